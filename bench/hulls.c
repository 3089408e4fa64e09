// SPDX-License-Identifier: BSD-3-Clause
//
// hulls.c -- bench scene: convex hulls (dCreateConvex) poured into a container.
//
// `hulls count=400 steps=300 stepper=quick iterations=20 seed=9`: hexagonal prisms (12
// points, 8 faces; 15 cm to the corners, 20 cm high, 1 kg) dropped from a jittered grid (6 x 6
// per layer, 40 cm apart, random turns drawn from the seed) into the container of the spheres
// scene (3 m x 3 m inside, five static boxes), so that the pairs are hull-hull and hull-box.
// Hash space, 4 contacts per pair, mu 0.8 with dContactApprox1, dt 1/60, gravity 9.81.
// Quality: the deepest contact seen, how many hulls ended outside the container, the
// height of the highest one and the kinetic energy at the end.

#include "bench_ode.h"

#define RADIUS 0.15  // centre to a corner
#define HALF_H 0.1   // half the height
#define MASS 1.0
#define HALF 1.5     // half the inside width of the container
#define WALL 0.5
#define HEIGHT 4.0
#define PITCH 0.4
#define PER_ROW 6

// The prism's arrays, shared by every hull (ODE keeps the pointers).
static dReal points[36], planes[32];
static unsigned polygons[2 * 7 + 6 * 5];

static void make_prism(void)
{
    const double pi = 3.14159265358979324;
    for (int i = 0; i < 6; i++) {
        double a = pi / 3 * i, b = a + pi / 6;
        for (int top = 0; top < 2; top++) {
            dReal *p = points + 3 * (6 * top + i);
            p[0] = (dReal)(RADIUS * cos(a));
            p[1] = (dReal)(RADIUS * sin(a));
            p[2] = (dReal)(top ? HALF_H : -HALF_H);
        }
        dReal *pl = planes + 4 * (2 + i);   // side i, between corners i and i + 1
        pl[0] = (dReal)cos(b);
        pl[1] = (dReal)sin(b);
        pl[2] = 0;
        pl[3] = (dReal)(RADIUS * cos(pi / 6));
    }
    const dReal caps[8] = { 0, 0, 1, (dReal)HALF_H, 0, 0, -1, (dReal)HALF_H };
    memcpy(planes, caps, sizeof caps);
    unsigned *q = polygons;
    *q++ = 6;   // top, counterclockwise seen from above
    for (int i = 0; i < 6; i++) *q++ = (unsigned)(6 + i);
    *q++ = 6;   // bottom, counterclockwise seen from below
    for (int i = 5; i >= 0; i--) *q++ = (unsigned)i;
    for (int i = 0; i < 6; i++) {
        unsigned j = (unsigned)(i + 1) % 6;
        *q++ = 4;
        *q++ = (unsigned)i;
        *q++ = j;
        *q++ = 6 + j;
        *q++ = (unsigned)(6 + i);
    }
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int count = (int)bench_arg_int(&args, "count", 400);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const unsigned long long seed = (unsigned long long)bench_arg_int(&args, "seed", 9);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    bench_args_check(&args, "[count=N] [steps=N] [stepper=quick|world|fast] [iterations=N] "
                            "[seed=N]");
    const dReal dt = (dReal)(1.0 / 60.0);

    dInitODE2(0);
    make_prism();
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    dSpaceID space = dHashSpaceCreate(0);

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
    dMass m;   // the prism's mass as a cylinder of its inscribed radius (close enough here)
    dMassSetCylinderTotal(&m, (dReal)MASS, 3, (dReal)(RADIUS * 0.93), (dReal)(2 * HALF_H));
    bench_rng rng = bench_rng_init(seed);
    for (int i = 0; i < count; i++) {
        const int layer = i / (PER_ROW * PER_ROW), cell = i % (PER_ROW * PER_ROW);
        const double x = (cell % PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.03, 0.03);
        const double y = (cell / PER_ROW - 0.5 * (PER_ROW - 1)) * PITCH +
                         bench_rand(&rng, -0.03, 0.03);
        const double z = 0.3 + layer * PITCH;
        body[i] = dBodyCreate(world);
        dBodySetMass(body[i], &m);
        dBodySetPosition(body[i], (dReal)x, (dReal)y, (dReal)z);
        // One draw a statement (C leaves the order of a call's arguments open, and gcc and
        // clang differ): the angle, then the axis's z, y and x, the order gcc drew them in.
        const double angle = bench_rand(&rng, 0, 3);
        const double az = bench_rand(&rng, -1, 1);
        const double ay = bench_rand(&rng, -1, 1);
        const double ax = bench_rand(&rng, -1, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, (dReal)ax, (dReal)ay, (dReal)az, (dReal)angle);
        dBodySetRotation(body[i], R);
        dGeomID g = dCreateConvex(space, planes, 8, points, 12, polygons);
        dGeomSetBody(g, body[i]);
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    double coll_s = 0, step_s = 0;
    for (int s = 0; s < steps; s++) bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);

    int escaped = 0;
    double ke = 0, top = 0;
    for (int i = 0; i < count; i++) {
        const dReal *p = dBodyGetPosition(body[i]);
        if (fabs(p[0]) > HALF || fabs(p[1]) > HALF || p[2] < 0 || p[2] > HEIGHT) escaped++;
        if (p[2] > top) top = p[2];
        ke += bench_body_ke(body[i]);
    }
    bench_report("hulls", BENCH_ENGINE, bench_stepper_name(stepper), count, steps, coll_s,
                 step_s, "iterations=%d max_pen=%.6f escaped=%d top_z=%.4f ke_end=%.6g "
                 "contacts_per_step=%.1f",
                 iterations, con.max_depth, escaped, top, ke, (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    return 0;
}
