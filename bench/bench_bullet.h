// SPDX-License-Identifier: BSD-3-Clause
//
// bench_bullet.h -- what the Bullet equivalents of the bench scenes share: a dynamics world
// that times its collision phase, friction combined as ODE's mu, kinetic energy, penetration.
//
// Bullet multiplies the two objects' friction coefficients; every object gets sqrt(mu) so each
// pair has ODE's mu. Restitution stays 0. Bodies never deactivate (ODE's auto-disable is off
// in the ODE scenes too). One stepSimulation(dt, 0) call is one step of exactly dt.

#ifndef BENCH_BULLET_H
#define BENCH_BULLET_H

#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>
#include <cmath>
#include <vector>

#include "bench_common.h"

#ifndef BENCH_ENGINE
#define BENCH_ENGINE "bullet"
#endif

// A discrete dynamics world that adds the time of each collision phase to coll_s.
class TimedWorld : public btDiscreteDynamicsWorld {
public:
    double coll_s = 0;
    TimedWorld(btDispatcher *d, btBroadphaseInterface *b, btConstraintSolver *s,
               btCollisionConfiguration *c)
        : btDiscreteDynamicsWorld(d, b, s, c)
    {
    }
    void performDiscreteCollisionDetection() override
    {
        double t0 = bench_now();
        btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
        coll_s += bench_now() - t0;
    }
};

// Everything a scene's world is made of, owned here. direct selects btMLCPSolver with the
// Dantzig LCP (Bullet's counterpart of dWorldStep) instead of sequential impulses.
struct BenchWorld {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btDantzigSolver dantzig;
    btConstraintSolver *solver;
    TimedWorld *world;
    std::vector<btCollisionShape *> shapes;
    std::vector<btRigidBody *> bodies;
    std::vector<btTypedConstraint *> constraints;
    btScalar friction;

    BenchWorld(double mu, int iterations, bool direct)
    {
        if (direct)
            solver = new btMLCPSolver(&dantzig);
        else
            solver = new btSequentialImpulseConstraintSolver();
        world = new TimedWorld(&dispatcher, &broadphase, solver, &config);
        world->setGravity(btVector3(0, 0, btScalar(-9.81)));
        world->getSolverInfo().m_numIterations = iterations;
        if (direct) world->getSolverInfo().m_minimumSolverBatchSize = 1;
        friction = btScalar(std::sqrt(mu));
    }

    ~BenchWorld()
    {
        for (btTypedConstraint *c : constraints) {
            world->removeConstraint(c);
            delete c;
        }
        for (btRigidBody *b : bodies) {
            world->removeRigidBody(b);
            delete b->getMotionState();
            delete b;
        }
        for (btCollisionShape *s : shapes) delete s;
        delete world;
        delete solver;
    }

    // The shape is owned by the world once added here.
    btCollisionShape *shape(btCollisionShape *s)
    {
        shapes.push_back(s);
        return s;
    }

    // mass 0 makes a static object. inertia 0 asks Bullet for the shape's own.
    btRigidBody *body(btCollisionShape *s, double mass, const btTransform &at,
                      btVector3 inertia = btVector3(0, 0, 0))
    {
        if (mass > 0 && inertia.isZero()) s->calculateLocalInertia(btScalar(mass), inertia);
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), new btDefaultMotionState(at),
                                                      s, inertia);
        info.m_friction = friction;
        info.m_restitution = 0;
        btRigidBody *b = new btRigidBody(info);
        b->setActivationState(DISABLE_DEACTIVATION);
        world->addRigidBody(b);
        bodies.push_back(b);
        return b;
    }

    // Connected bodies do not collide with each other.
    void constraint(btTypedConstraint *c)
    {
        world->addConstraint(c, true);
        constraints.push_back(c);
    }

    // Deepest penetration among the current contact points (0 if none), and their count.
    double penetration(long *count) const
    {
        double deepest = 0;
        const int n = world->getDispatcher()->getNumManifolds();
        for (int i = 0; i < n; i++) {
            const btPersistentManifold *m = world->getDispatcher()->getManifoldByIndexInternal(i);
            *count += m->getNumContacts();
            for (int k = 0; k < m->getNumContacts(); k++)
                if (-m->getContactPoint(k).getDistance() > deepest)
                    deepest = -m->getContactPoint(k).getDistance();
        }
        return deepest;
    }
};

// Linear plus rotational kinetic energy of a body.
static inline double bench_bullet_ke(const btRigidBody *b)
{
    if (b->getInvMass() == 0) return 0;
    const btVector3 v = b->getLinearVelocity();
    const btVector3 wl = b->getWorldTransform().getBasis().transpose() * b->getAngularVelocity();
    const btVector3 I = b->getLocalInertia();
    return 0.5 * (1.0 / b->getInvMass()) * v.length2() +
           0.5 * (I.x() * wl.x() * wl.x() + I.y() * wl.y() * wl.y() + I.z() * wl.z() * wl.z());
}

#endif
