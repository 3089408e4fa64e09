// SPDX-License-Identifier: BSD-3-Clause
//
// chain_bullet.cpp -- the chain scene (chain.c) for Bullet: the same capsules (with ODE's
// capsule inertia), point-to-point constraints at the same anchors, dt 1/100, gravity 9.81.
//
// `chain_bullet links=100 steps=300 stepper=quick|world iterations=20 seed=N`: stepper=quick is the
// sequential-impulse solver with the given iterations, stepper=world the direct MLCP solver
// with the Dantzig LCP (Bullet's counterpart of dWorldStep); seed=N tilts the release down as
// chain.c does. Prints the same key=value line.

#include "bench_bullet.h"

#include <cstring>

static const double LINK = 0.1, RADIUS = 0.025, MASS = 0.1;

// Principal moments of a capsule along x, as ODE's dMassSetCapsuleTotal computes them.
static btVector3 capsule_inertia(double mass, double r, double len)
{
    const double m1 = M_PI * r * r * len, m2 = 4.0 / 3.0 * M_PI * r * r * r;
    const double scale = mass / (m1 + m2);
    const double ia = m1 * (0.25 * r * r + len * len / 12.0) +
                      m2 * (0.4 * r * r + 0.375 * r * len + 0.25 * len * len);
    const double iz = (0.5 * m1 + 0.4 * m2) * r * r;
    return btVector3(btScalar(iz * scale), btScalar(ia * scale), btScalar(ia * scale));
}

static double separation(const btPoint2PointConstraint *c)
{
    const btVector3 a = c->getRigidBodyA().getCenterOfMassTransform() * c->getPivotInA();
    const btVector3 b = c->getRigidBodyB().getCenterOfMassTransform() * c->getPivotInB();
    return (a - b).length();
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int links = (int)bench_arg_int(&args, "links", 100);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const char *stepper = bench_arg_str(&args, "stepper", "world");
    const long seed = bench_arg_int(&args, "seed", 0);   // 0: not given, horizontal
    bench_args_check(&args, "[links=N] [steps=N] [stepper=world|quick] [iterations=N] [seed=N]");
    const bool direct = strcmp(stepper, "world") == 0;
    if (!direct && strcmp(stepper, "quick") != 0) {
        fprintf(stderr, "%s: stepper is world or quick, not '%s'\n", argv[0], stepper);
        return 2;
    }
    const btScalar dt = btScalar(1.0 / 100.0);

    BenchWorld w(0.8, iterations, direct);
    btCollisionShape *capsule = w.shape(new btCapsuleShapeX(btScalar(RADIUS),
                                                            btScalar(LINK - 2 * RADIUS)));
    const btVector3 inertia = capsule_inertia(MASS, RADIUS, LINK - 2 * RADIUS);
    const btVector3 half(btScalar(LINK / 2), 0, 0);
    std::vector<btPoint2PointConstraint *> joints;
    // The links along x, or turned about y so that x points down by `tilt` (chain.c's draw).
    bench_rng rng = bench_rng_init((unsigned long long)seed);
    const double tilt = seed ? bench_rand(&rng, 0, 2 * M_PI / 180) : 0;
    const double dx = cos(tilt), dz = seed ? -sin(tilt) : 0;
    btTransform at;
    at.setIdentity();
    at.setRotation(btQuaternion(btVector3(0, 1, 0), btScalar(tilt)));
    for (int i = 0; i < links; i++) {
        const double along = (i + 0.5) * LINK;
        at.setOrigin(btVector3(btScalar(along * dx), 0, btScalar(along * dz)));
        btRigidBody *b = w.body(capsule, MASS, at, inertia);
        btPoint2PointConstraint *c;
        if (i == 0)
            c = new btPoint2PointConstraint(*b, -half);
        else
            c = new btPoint2PointConstraint(*b, *w.bodies[(size_t)i - 1], -half, half);
        w.constraint(c);
        joints.push_back(c);
    }

    double total_s = 0, max_pen = 0, sep_max = 0, sep_end = 0, sep_sum = 0;
    long contacts = 0;
    for (int s = 0; s < steps; s++) {
        bench_count_on();
        double t0 = bench_now();
        w.world->stepSimulation(dt, 0);
        total_s += bench_now() - t0;
        bench_count_off();
        double pen = w.penetration(&contacts);
        if (pen > max_pen) max_pen = pen;
        sep_end = 0;
        for (const btPoint2PointConstraint *c : joints)
            if (separation(c) > sep_end) sep_end = separation(c);
        if (sep_end > sep_max) sep_max = sep_end;
        sep_sum += sep_end;
    }

    double ke = 0;
    for (const btRigidBody *b : w.bodies) ke += bench_bullet_ke(b);
    const double tip_z = w.bodies.back()->getCenterOfMassPosition().z();
    bench_report("chain", BENCH_ENGINE, direct ? "world" : "quick", links, steps,
                 w.world->coll_s, total_s - w.world->coll_s,
                 "iterations=%d max_pen=%.6f joint_sep=%.6f joint_sep_end=%.6f joint_sep_mean=%.6f "
                 "ke_end=%.6g tip_z=%.4f contacts_per_step=%.1f",
                 iterations, max_pen, sep_max, sep_end, sep_sum / steps, ke, tip_z,
                 (double)contacts / steps);
    return 0;
}
