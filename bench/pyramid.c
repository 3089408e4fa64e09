// SPDX-License-Identifier: BSD-3-Clause
//
// pyramid.c -- bench scene: a 2-D pyramid of unit boxes standing on a plane.
//
// `pyramid layers=20 steps=600 stepper=quick|world|fast iterations=20`: layers=20 is 210 boxes,
// layers=40 is 820. Hash space, 4 contacts per pair, mu 0.8 with dContactApprox1, dt 1/60,
// gravity 9.81, world ERP and CFM left at their defaults. Boxes of a layer are 1 cm apart; each
// layer rests on the one below. stepper=fast is reported as scene "stepfast".
// Quality: the deepest contact seen, the drift of the top box from where it started, how many
// boxes moved by more than half their size (fallen), and the kinetic energy at the end.

#include "bench_ode.h"

#define BOX 1.0
#define GAP 0.01
#define MASS 1.0

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int layers = (int)bench_arg_int(&args, "layers", 20);
    const int steps = (int)bench_arg_int(&args, "steps", 600);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    bench_args_check(&args, "[layers=N] [steps=N] [stepper=quick|world|fast] [iterations=N]");
    const dReal dt = (dReal)(1.0 / 60.0);

    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    dSpaceID space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);

    const int n = layers * (layers + 1) / 2;
    dBodyID *body = (dBodyID *)malloc(sizeof(dBodyID) * (size_t)n);
    double(*start)[3] = malloc(sizeof(double[3]) * (size_t)n);
    if (!body || !start) return 1;
    dMass m;
    dMassSetBoxTotal(&m, (dReal)MASS, (dReal)BOX, (dReal)BOX, (dReal)BOX);
    int k = 0;
    for (int l = 0; l < layers; l++) {
        const int row = layers - l;
        for (int i = 0; i < row; i++, k++) {
            body[k] = dBodyCreate(world);
            dBodySetMass(body[k], &m);
            start[k][0] = (i - 0.5 * (row - 1)) * (BOX + GAP);
            start[k][1] = 0;
            start[k][2] = 0.5 * BOX + l * BOX;
            dBodySetPosition(body[k], (dReal)start[k][0], (dReal)start[k][1], (dReal)start[k][2]);
            dGeomID g = dCreateBox(space, (dReal)BOX, (dReal)BOX, (dReal)BOX);
            dGeomSetBody(g, body[k]);
        }
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    double coll_s = 0, step_s = 0;
    for (int s = 0; s < steps; s++) {
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);
    }

    int fallen = 0;
    double ke = 0, top_drift = 0, v_end = 0;
    for (int i = 0; i < n; i++) {
        v_end = fmax(v_end, bench_body_speed(body[i]));
        const dReal *p = dBodyGetPosition(body[i]);
        double dx = p[0] - start[i][0], dy = p[1] - start[i][1], dz = p[2] - start[i][2];
        double d = sqrt(dx * dx + dy * dy + dz * dz);
        if (d > 0.5 * BOX) fallen++;
        if (i == n - 1) top_drift = d;
        ke += bench_body_ke(body[i]);
    }
    bench_report(stepper == BENCH_FAST ? "stepfast" : "pyramid", BENCH_ENGINE,
                 bench_stepper_name(stepper), n, steps, coll_s, step_s,
                 "iterations=%d max_pen=%.6f top_drift=%.6f fallen=%d stands=%d ke_end=%.6g "
                 "v_end=%.3g contacts_per_step=%.1f",
                 iterations, con.max_depth, top_drift, fallen, fallen == 0, ke, v_end,
                 (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    free(start);
    return 0;
}
