// SPDX-License-Identifier: BSD-3-Clause
//
// spheres_bullet.cpp -- the spheres scene (spheres.c) for Bullet: the same spheres, spawn grid
// and seed, the same five static boxes as the container, dt 1/60, 20 solver iterations
// (sequential impulses), friction 0.8, gravity 9.81.
//
// `spheres_bullet count=2000 steps=300 iterations=20`; prints the same key=value line.

#include "bench_bullet.h"

static const double RADIUS = 0.1, MASS = 1.0, HALF = 1.5, WALL = 0.5, HEIGHT = 4.0;
static const double PITCH = 0.24;
static const int PER_ROW = 12;
static const int LAST = 60;          // the steps (1 s) over which moving_end counts
static const double MOVING = 0.1;    // m/s: a sphere faster than this is still moving

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int count = (int)bench_arg_int(&args, "count", 2000);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const long seed = bench_arg_int(&args, "seed", 5);
    bench_args_check(&args, "[count=N] [steps=N] [iterations=N] [seed=N]");
    const btScalar dt = btScalar(1.0 / 60.0);

    BenchWorld w(0.8, iterations, false);
    btTransform at;
    at.setIdentity();
    const double outer = 2 * (HALF + WALL), inner = 2 * HALF;
    at.setOrigin(btVector3(0, 0, btScalar(-WALL / 2)));
    w.body(w.shape(new btBoxShape(btVector3(btScalar(outer / 2), btScalar(outer / 2),
                                            btScalar(WALL / 2)))), 0, at);
    btCollisionShape *wx = w.shape(new btBoxShape(btVector3(btScalar(WALL / 2),
                                                            btScalar(outer / 2),
                                                            btScalar(HEIGHT / 2))));
    btCollisionShape *wy = w.shape(new btBoxShape(btVector3(btScalar(inner / 2),
                                                            btScalar(WALL / 2),
                                                            btScalar(HEIGHT / 2))));
    for (int side = -1; side <= 1; side += 2) {
        at.setOrigin(btVector3(btScalar(side * (HALF + WALL / 2)), 0, btScalar(HEIGHT / 2)));
        w.body(wx, 0, at);
        at.setOrigin(btVector3(0, btScalar(side * (HALF + WALL / 2)), btScalar(HEIGHT / 2)));
        w.body(wy, 0, at);
    }
    const size_t first = w.bodies.size();

    btCollisionShape *sphere = w.shape(new btSphereShape(btScalar(RADIUS)));
    bench_rng rng = bench_rng_init((unsigned long long)seed);
    for (int i = 0; i < count; i++) {
        const int layer = i / (PER_ROW * PER_ROW), cell = i % (PER_ROW * PER_ROW);
        const double x = (cell % PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.02, 0.02);
        const double y = (cell / PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.02, 0.02);
        const double z = RADIUS + 0.05 + layer * PITCH;
        at.setOrigin(btVector3(btScalar(x), btScalar(y), btScalar(z)));
        w.body(sphere, MASS, at);
    }

    double total_s = 0, max_pen = 0;
    long contacts = 0, moving = 0;   // as in spheres.c: spheres faster than MOVING
    for (int s = 0; s < steps; s++) {
        bench_count_on();
        double t0 = bench_now();
        w.world->stepSimulation(dt, 0);
        total_s += bench_now() - t0;
        bench_count_off();
        double pen = w.penetration(&contacts);
        if (pen > max_pen) max_pen = pen;
        if (s < steps - LAST) continue;
        for (size_t i = first; i < w.bodies.size(); i++)
            moving += w.bodies[i]->getLinearVelocity().length() > MOVING;
    }
    const int last = steps < LAST ? steps : LAST;

    int escaped = 0;
    double ke = 0, top = 0, vmax = 0;
    for (size_t i = first; i < w.bodies.size(); i++) {
        const btVector3 p = w.bodies[i]->getCenterOfMassPosition();
        double speed = w.bodies[i]->getLinearVelocity().length();
        if (speed > vmax) vmax = speed;
        if (std::fabs(p.x()) > HALF || std::fabs(p.y()) > HALF || p.z() < 0 || p.z() > HEIGHT)
            escaped++;
        if (p.z() > top) top = p.z();
        ke += bench_bullet_ke(w.bodies[i]);
    }
    bench_report("spheres", BENCH_ENGINE, "quick", count, steps, w.world->coll_s,
                 total_s - w.world->coll_s,
                 "iterations=%d max_pen=%.6f escaped=%d top_z=%.4f ke_end=%.6g "
                 "vmax_end=%.6g ke_per_kg_end=%.6g moving_end=%.2f contacts_per_step=%.1f",
                 iterations, max_pen, escaped, top, ke, vmax, ke / count,
                 (double)moving / last, (double)contacts / steps);
    return 0;
}
