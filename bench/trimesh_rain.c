// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_rain.c -- bench scene: spheres and boxes raining onto a triangle-mesh terrain.
//
// `trimesh_rain spheres=500 boxes=200 steps=300 cells=100 stepper=quick iterations=20`: a
// 100 x 100-cell terrain (20 000 triangles) over 20 m x 20 m, height
// 0.5 sin(0.6 x) cos(0.5 y) m, static; spheres of radius 15 cm and boxes of 30 x 20 x 15 cm,
// 1 kg each, dropped from a jittered grid (fixed seed) between 1 and 8 m above it. Hash
// space, 4 contacts per pair, mu 0.8 with dContactApprox1, dt 1/60, gravity 9.81.
// Quality: the deepest contact seen, how many bodies ended below the terrain (fell
// through: their centre more than their size under the surface) and the kinetic energy at
// the end. Memory: the peak resident size (bench_report) beside the reference's.

#include "bench_ode.h"

#define HALF 10.0   // half the terrain's side
#define RADIUS 0.15

static double terrain_height(double x, double y)
{
    return 0.5 * sin(0.6 * x) * cos(0.5 * y);
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int spheres = (int)bench_arg_int(&args, "spheres", 500);
    const int boxes = (int)bench_arg_int(&args, "boxes", 200);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int cells = (int)bench_arg_int(&args, "cells", 100);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    const int tc = strcmp(bench_arg_str(&args, "tc", "off"), "on") == 0;
    bench_args_check(&args, "[spheres=N] [boxes=N] [steps=N] [cells=N] "
                            "[stepper=quick|world|fast] [iterations=N] [tc=on|off]");
    const dReal dt = (dReal)(1.0 / 60.0);

    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    dSpaceID space = dHashSpaceCreate(0);

    // The terrain: (cells + 1)^2 vertices, 2 cells^2 triangles facing up.
    const int nt = 2 * cells * cells;
    double(*v)[3] = NULL;
    dTriIndex(*tri)[3] = NULL;
    const int terrain_ok = bench_grid_terrain(cells, HALF, terrain_height, &v, &tri);
    if (!terrain_ok) return 1;
    dTriMeshDataID data;
    bench_terrain_geom(space, cells, v, tri, tc, &data);

    const int count = spheres + boxes;
    dBodyID *body = (dBodyID *)malloc(sizeof(dBodyID) * (size_t)count);
    if (!body) return 1;
    bench_rng rng = bench_rng_init(11);
    const int per_row = 20;
    for (int i = 0; i < count; i++) {
        const int layer = i / (per_row * per_row), cell = i % (per_row * per_row);
        const double x = (cell % per_row - 0.5 * (per_row - 1)) * 0.8 + bench_rand(&rng, -0.2, 0.2);
        const double y = (cell / per_row - 0.5 * (per_row - 1)) * 0.8 + bench_rand(&rng, -0.2, 0.2);
        const double z = terrain_height(x, y) + 1 + layer * 1.5 + bench_rand(&rng, 0, 1);
        body[i] = dBodyCreate(world);
        dMass m;
        dGeomID g;
        if (i < spheres) {
            g = dCreateSphere(space, (dReal)RADIUS);
            dMassSetSphereTotal(&m, 1, (dReal)RADIUS);
        } else {
            g = dCreateBox(space, (dReal)0.3, (dReal)0.2, (dReal)0.15);
            dMassSetBoxTotal(&m, 1, (dReal)0.3, (dReal)0.2, (dReal)0.15);
        }
        dBodySetMass(body[i], &m);
        dGeomSetBody(g, body[i]);
        dBodySetPosition(body[i], (dReal)x, (dReal)y, (dReal)z);
        // One draw a statement (C leaves the order of a call's arguments open, and gcc and
        // clang differ): the angle, then the axis's y and x, the order gcc drew them in.
        const double angle = bench_rand(&rng, 0, 3);
        const double ay = bench_rand(&rng, -1, 1);
        const double ax = bench_rand(&rng, -1, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, (dReal)ax, (dReal)ay, 1, (dReal)angle);
        dBodySetRotation(body[i], R);
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    double coll_s = 0, step_s = 0;
    for (int s = 0; s < steps; s++)
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);

    int fell = 0;
    double ke = 0;
    for (int i = 0; i < count; i++) {
        const dReal *p = dBodyGetPosition(body[i]);
        if (fabs(p[0]) < HALF && fabs(p[1]) < HALF && p[2] < terrain_height(p[0], p[1]) - 0.2)
            fell++;
        ke += bench_body_ke(body[i]);
    }
    bench_report("trimesh_rain", BENCH_ENGINE, bench_stepper_name(stepper), count, steps,
                 coll_s, step_s, "triangles=%d iterations=%d max_pen=%.6f fell_through=%d "
                 "ke_end=%.6g contacts_per_step=%.1f",
                 nt, iterations, con.max_depth, fell, ke, (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    dGeomTriMeshDataDestroy(data);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    free(v);
    free(tri);
    return 0;
}
