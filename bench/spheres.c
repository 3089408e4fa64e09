// SPDX-License-Identifier: BSD-3-Clause
//
// spheres.c -- bench scene: spheres poured into a box-shaped container.
//
// `spheres count=2000 steps=300 stepper=quick iterations=20 seed=5`: spheres of radius 10 cm
// and 1 kg, dropped from a jittered grid (12 x 12 per layer, 24 cm apart, the jitter drawn
// from `seed`) into a container 3 m x 3 m inside and 4 m high made of five static boxes
// (floor and four walls, 50 cm thick). Hash space, 4 contacts per pair, mu 0.8 with
// dContactApprox1, dt 1/60, gravity 9.81, world ERP and CFM left at their defaults.
// Quality: the deepest contact seen (max_pen: a falling sphere's first touch of another, as
// deep as it got in the step before the collision saw it), how many spheres ended outside the
// container (escaped), the height of the highest sphere, the kinetic energy and the largest
// speed at the end, and how many spheres moved faster than 0.1 m/s per step over the last 60
// steps (moving_end).

#include "bench_ode.h"

#define RADIUS 0.1
#define MASS 1.0
#define HALF 1.5    // half the inside width of the container
#define WALL 0.5    // wall thickness
#define HEIGHT 4.0  // wall height
#define PITCH 0.24  // spawn grid spacing
#define PER_ROW 12
#define LAST 60      // the steps (1 s) over which moving_end counts
#define MOVING 0.1   // m/s: a sphere faster than this is still moving

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int count = (int)bench_arg_int(&args, "count", 2000);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    const long seed = bench_arg_int(&args, "seed", 5);
    bench_threads threads;
    const dReal dt = (dReal)(1.0 / 60.0);

    dInitODE2(0);
    dWorldID world = dWorldCreate();
    bench_threads_start(&threads, &args, world, bench_stepper_name(stepper));
    bench_args_check(&args,
                     "[count=N] [steps=N] [stepper=quick|world|fast] [iterations=N] [threads=N] "
                     "[seed=N]");
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    dSpaceID space = dHashSpaceCreate(0);

    // The container: floor (top face at z = 0) and four walls, static geoms.
    const dReal outer = (dReal)(2 * (HALF + WALL)), inner = (dReal)(2 * HALF);
    dGeomID floor_box = dCreateBox(space, outer, outer, (dReal)WALL);
    dGeomSetPosition(floor_box, 0, 0, (dReal)(-WALL / 2));
    for (int side = -1; side <= 1; side += 2) {
        dGeomID wx = dCreateBox(space, (dReal)WALL, outer, (dReal)HEIGHT);
        dGeomSetPosition(wx, (dReal)(side * (HALF + WALL / 2)), 0, (dReal)(HEIGHT / 2));
        dGeomID wy = dCreateBox(space, inner, (dReal)WALL, (dReal)HEIGHT);
        dGeomSetPosition(wy, 0, (dReal)(side * (HALF + WALL / 2)), (dReal)(HEIGHT / 2));
    }

    dBodyID *body = (dBodyID *)malloc(sizeof(dBodyID) * (size_t)count);
    if (!body) return 1;
    dMass m;
    dMassSetSphereTotal(&m, (dReal)MASS, (dReal)RADIUS);
    bench_rng rng = bench_rng_init((unsigned long long)seed);
    for (int i = 0; i < count; i++) {
        const int layer = i / (PER_ROW * PER_ROW), cell = i % (PER_ROW * PER_ROW);
        const double x = (cell % PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.02, 0.02);
        const double y = (cell / PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.02, 0.02);
        const double z = RADIUS + 0.05 + layer * PITCH;
        body[i] = dBodyCreate(world);
        dBodySetMass(body[i], &m);
        dBodySetPosition(body[i], (dReal)x, (dReal)y, (dReal)z);
        dGeomID g = dCreateSphere(space, (dReal)RADIUS);
        dGeomSetBody(g, body[i]);
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    double coll_s = 0, step_s = 0;
    long moving = 0;   // spheres faster than MOVING, summed over the last LAST steps
    for (int s = 0; s < steps; s++) {
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);
        if (s < steps - LAST) continue;
        for (int i = 0; i < count; i++) {
            const dReal *v = dBodyGetLinearVel(body[i]);
            moving += (double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2] >
                      MOVING * MOVING;
        }
    }
    const int last = steps < LAST ? steps : LAST;

    int escaped = 0;
    double ke = 0, top = 0, vmax = 0;
    for (int i = 0; i < count; i++) {
        const dReal *p = dBodyGetPosition(body[i]);
        vmax = fmax(vmax, bench_body_speed(body[i]));
        if (fabs(p[0]) > HALF || fabs(p[1]) > HALF || p[2] < 0 || p[2] > HEIGHT) escaped++;
        if (p[2] > top) top = p[2];
        ke += bench_body_ke(body[i]);
    }
    bench_report("spheres", BENCH_ENGINE, threads.variant, count, steps, coll_s,
                 step_s, "iterations=%d max_pen=%.6f escaped=%d top_z=%.4f ke_end=%.6g "
                 "vmax_end=%.6g ke_per_kg_end=%.6g moving_end=%.2f contacts_per_step=%.1f",
                 iterations, con.max_depth, escaped, top, ke, vmax, ke / count,
                 (double)moving / last, (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    bench_threads_stop(&threads, world);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    return 0;
}
