// SPDX-License-Identifier: BSD-3-Clause
//
// pyramid_bullet.cpp -- the pyramid scene (pyramid.c) for Bullet: same boxes, gaps, plane,
// dt 1/60, 20 solver iterations (sequential impulses), friction 0.8, gravity 9.81.
//
// `pyramid_bullet layers=20 steps=600 iterations=20`; prints the same key=value line.
// Bullet's broad phase is its dynamic AABB tree (it has no hash space); its contact manifolds
// keep up to 4 points per pair, like the 4 contacts per pair of the ODE scene.

#include "bench_bullet.h"

static const double BOX = 1.0, GAP = 0.01, MASS = 1.0;

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int layers = (int)bench_arg_int(&args, "layers", 20);
    const int steps = (int)bench_arg_int(&args, "steps", 600);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    bench_args_check(&args, "[layers=N] [steps=N] [iterations=N]");
    const btScalar dt = btScalar(1.0 / 60.0);

    BenchWorld w(0.8, iterations, false);
    btTransform at;
    at.setIdentity();
    w.body(w.shape(new btStaticPlaneShape(btVector3(0, 0, 1), 0)), 0, at);
    btCollisionShape *box = w.shape(new btBoxShape(btVector3(0.5, 0.5, 0.5) * btScalar(BOX)));
    std::vector<btVector3> start;
    for (int l = 0; l < layers; l++) {
        const int row = layers - l;
        for (int i = 0; i < row; i++) {
            btVector3 p(btScalar((i - 0.5 * (row - 1)) * (BOX + GAP)), 0,
                        btScalar(0.5 * BOX + l * BOX));
            at.setOrigin(p);
            w.body(box, MASS, at);
            start.push_back(p);
        }
    }

    double total_s = 0, max_pen = 0;
    long contacts = 0;
    for (int s = 0; s < steps; s++) {
        bench_count_on();
        double t0 = bench_now();
        w.world->stepSimulation(dt, 0);
        total_s += bench_now() - t0;
        bench_count_off();
        double pen = w.penetration(&contacts);
        if (pen > max_pen) max_pen = pen;
    }

    int fallen = 0;
    double ke = 0, top_drift = 0;
    const int n = (int)start.size();
    for (int i = 0; i < n; i++) {
        const btRigidBody *b = w.bodies[(size_t)i + 1];
        const double d = (b->getCenterOfMassPosition() - start[(size_t)i]).length();
        if (d > 0.5 * BOX) fallen++;
        if (i == n - 1) top_drift = d;
        ke += bench_bullet_ke(b);
    }
    bench_report("pyramid", BENCH_ENGINE, "quick", n, steps, w.world->coll_s,
                 total_s - w.world->coll_s,
                 "iterations=%d max_pen=%.6f top_drift=%.6f fallen=%d stands=%d ke_end=%.6g "
                 "contacts_per_step=%.1f",
                 iterations, max_pen, top_drift, fallen, fallen == 0, ke,
                 (double)contacts / steps);
    return 0;
}
