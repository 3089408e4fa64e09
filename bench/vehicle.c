// SPDX-License-Identifier: BSD-3-Clause
//
// vehicle.c -- bench scene: four-wheeled cars (as ODE's demo_buggy, with a fourth wheel)
// driving in circles on a hilly triangle-mesh terrain.
//
// `vehicle cars=16 steps=600 cells=64 stepper=quick iterations=20`: a 64 x 64-cell terrain
// (8192 triangles) over 40 m x 40 m, height 0.8 sin(0.25 x) cos(0.2 y) + 0.3 sin(0.7 x + 0.4 y)
// m, static; cars on a 4-wide grid 8 m apart, each a 0.7 x 0.5 x 0.2 m box chassis of 1 kg and
// four sphere wheels (r 0.18 m, 0.2 kg) on hinge-2 joints (steering axis up, axle across,
// suspension ERP 0.4 CFM 0.01); the front wheels steer towards 0.3 rad, the four driven at
// 8 rad/s (torque at most 1 N m). Contacts only with the terrain (or between different cars),
// 4 per pair, demo_buggy's surface (slip 0.1, soft ERP 0.5, soft CFM 0.001, mu infinite,
// dContactApprox1); hash space, dt 1/60, gravity 9.81.
// Quality: the deepest contact, how many cars ended on their roof or under the terrain, and
// the mean distance each chassis travelled.

#include "bench_ode.h"

#define HALF 20.0   // half the terrain's side
#define LENGTH 0.7
#define WIDTH 0.5
#define HEIGHT 0.2
#define RADIUS 0.18
#define CMASS 1.0
#define WMASS 0.2

static double terrain_height(double x, double y)
{
    return 0.8 * sin(0.25 * x) * cos(0.2 * y) + 0.3 * sin(0.7 * x + 0.4 * y);
}

typedef struct car {
    dBodyID chassis, wheel[4];   // wheels: front left, front right, rear left, rear right
    dJointID axle[4];
} car;

// A car with its chassis centre at (x, y, z), facing +x turned by yaw about z.
static void car_create(car *c, dWorldID world, dSpaceID space, double x, double y, double z,
                       double yaw)
{
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, (dReal)yaw);
    const dReal at[3] = { (dReal)x, (dReal)y, (dReal)z };
    dMass m;
    c->chassis = dBodyCreate(world);
    dBodySetPosition(c->chassis, at[0], at[1], at[2]);
    dBodySetRotation(c->chassis, R);
    dMassSetBox(&m, 1, (dReal)LENGTH, (dReal)WIDTH, (dReal)HEIGHT);
    dMassAdjust(&m, (dReal)CMASS);
    dBodySetMass(c->chassis, &m);
    dGeomSetBody(dCreateBox(space, (dReal)LENGTH, (dReal)WIDTH, (dReal)HEIGHT), c->chassis);
    dVector3 up, across;
    bench_xform(up, R, NULL, 0, 0, 1);
    bench_xform(across, R, NULL, 0, 1, 0);
    for (int i = 0; i < 4; i++) {
        const double lx = (i < 2 ? 0.5 : -0.5) * LENGTH, ly = (i % 2 ? -0.5 : 0.5) * WIDTH;
        dVector3 p;
        bench_xform(p, R, at, lx, ly, -0.5 * HEIGHT);
        dBodyID w = c->wheel[i] = dBodyCreate(world);
        dMatrix3 Rx, Rw;
        dRFromAxisAndAngle(Rx, 1, 0, 0, (dReal)(M_PI / 2));
        bench_rmul(Rw, R, Rx);
        dBodySetRotation(w, Rw);
        dBodySetPosition(w, p[0], p[1], p[2]);
        dMassSetSphere(&m, 1, (dReal)RADIUS);
        dMassAdjust(&m, (dReal)WMASS);
        dBodySetMass(w, &m);
        dGeomSetBody(dCreateSphere(space, (dReal)RADIUS), w);
        dJointID j = c->axle[i] = dJointCreateHinge2(world, 0);
        dJointAttach(j, c->chassis, w);
        dJointSetHinge2Anchor(j, p[0], p[1], p[2]);
        dJointSetHinge2Axes(j, up, across);
        dJointSetHinge2Param(j, dParamSuspensionERP, (dReal)0.4);
        dJointSetHinge2Param(j, dParamSuspensionCFM, (dReal)0.01);
        if (i >= 2) {   // rear wheels do not steer
            dJointSetHinge2Param(j, dParamLoStop, 0);
            dJointSetHinge2Param(j, dParamHiStop, 0);
        } else {
            dJointSetHinge2Param(j, dParamLoStop, (dReal)-0.75);
            dJointSetHinge2Param(j, dParamHiStop, (dReal)0.75);
            dJointSetHinge2Param(j, dParamFudgeFactor, (dReal)0.1);
        }
        dJointSetHinge2Param(j, dParamVel2, (dReal)-8);
        dJointSetHinge2Param(j, dParamFMax2, 1);
    }
}

// demo_buggy's steering: the front wheels turn towards `steer` at most 1 rad/s.
static void car_drive(car *c, double steer)
{
    for (int i = 0; i < 2; i++) {
        double v = steer - dJointGetHinge2Angle1(c->axle[i]);
        v = 10 * (v > 0.1 ? 0.1 : v < -0.1 ? -0.1 : v);
        dJointSetHinge2Param(c->axle[i], dParamVel, (dReal)v);
        dJointSetHinge2Param(c->axle[i], dParamFMax, (dReal)0.2);
    }
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int cars = (int)bench_arg_int(&args, "cars", 16);
    const int steps = (int)bench_arg_int(&args, "steps", 600);
    const int cells = (int)bench_arg_int(&args, "cells", 64);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    const int tc = strcmp(bench_arg_str(&args, "tc", "off"), "on") == 0;
    bench_args_check(&args, "[cars=N] [steps=N] [cells=N] [stepper=quick|world|fast] "
                            "[iterations=N] [tc=on|off]");
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
    car *car_of = (car *)malloc(sizeof(car) * (size_t)(cars > 0 ? cars : 1));
    double *travel = (double *)calloc((size_t)(cars > 0 ? cars : 1), sizeof(double));
    double *last = (double *)malloc(2 * sizeof(double) * (size_t)(cars > 0 ? cars : 1));
    if (!terrain_ok || !car_of || !travel || !last) return 1;
    dTriMeshDataID data;
    bench_terrain_geom(space, cells, v, tri, tc, &data);

    bench_rng rng = bench_rng_init(5);
    const int per_row = 4;
    for (int i = 0; i < cars; i++) {
        const double x = (i % per_row - 0.5 * (per_row - 1)) * 8 + bench_rand(&rng, -1, 1);
        const double y = (i / per_row % per_row - 0.5 * (per_row - 1)) * 8 +
                         bench_rand(&rng, -1, 1);
        const double z = terrain_height(x, y) + 0.5 + 2 * (i / (per_row * per_row));
        car_create(&car_of[i], world, space, x, y, z, bench_rand(&rng, 0, 2 * M_PI));
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    con.skip_connected = 1;   // a car's wheels and chassis
    con.surface.mode = dContactSlip1 | dContactSlip2 | dContactSoftERP | dContactSoftCFM |
                       dContactApprox1;
    con.surface.mu = dInfinity;
    con.surface.slip1 = con.surface.slip2 = (dReal)0.1;
    con.surface.soft_erp = (dReal)0.5;
    con.surface.soft_cfm = (dReal)0.001;
    double coll_s = 0, step_s = 0;
    for (int s = 0; s < steps; s++) {
        for (int i = 0; i < cars; i++) {
            const dReal *p = dBodyGetPosition(car_of[i].chassis);
            last[2 * i] = p[0];
            last[2 * i + 1] = p[1];
            car_drive(&car_of[i], i % 2 ? 0.3 : -0.3);
        }
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);
        for (int i = 0; i < cars; i++) {
            const dReal *p = dBodyGetPosition(car_of[i].chassis);
            travel[i] += hypot(p[0] - last[2 * i], p[1] - last[2 * i + 1]);
        }
    }

    int flipped = 0, under = 0;
    double mean_travel = 0;
    for (int i = 0; i < cars; i++) {
        const dReal *p = dBodyGetPosition(car_of[i].chassis);
        const dReal *R = dBodyGetRotation(car_of[i].chassis);
        if (R[10] < 0) flipped++;   // the chassis' up axis points down
        if (fabs(p[0]) < HALF && fabs(p[1]) < HALF && p[2] < terrain_height(p[0], p[1]) - 0.1)
            under++;
        mean_travel += travel[i] / cars;
    }
    bench_report("vehicle", BENCH_ENGINE, bench_stepper_name(stepper), 5 * cars, steps, coll_s,
                 step_s, "triangles=%d cars=%d iterations=%d max_pen=%.6f flipped=%d under=%d "
                 "travel=%.3f contacts_per_step=%.1f",
                 nt, cars, iterations, con.max_depth, flipped, under, mean_travel,
                 (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    dGeomTriMeshDataDestroy(data);
    dWorldDestroy(world);
    dCloseODE();
    free(last);
    free(travel);
    free(car_of);
    free(v);
    free(tri);
    return 0;
}
