// SPDX-License-Identifier: BSD-3-Clause
//
// friction.c -- boxes on four ramps of 25 degrees with friction coefficients
// 0.1, 0.3, 0.6 and 1.0, and balls dropped from 2 m with restitution 0.3,
// 0.6 and 0.9. Key r puts everything back.
// Checks when the loop ends: the boxes with mu < tan 25 = 0.466 slid
// (after 1 s each has gone g (sin - mu cos) t^2 / 2 down its ramp, within
// 5 %), those with mu above it did not move (< 1 cm); each ball rebounded to
// e^2 times its drop height (within 10 %), so the bouncier ones higher.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define RAMPS 4
#define BALLS 3
#define SLIDE_STEPS EXU_RATE   // slides are measured after 1 s

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[256];
static long steps;

static const dReal slope = 0.436332;   // 25 degrees
static const dReal mus[RAMPS] = { 0.1, 0.3, 0.6, 1.0 };
static const dReal bounces[BALLS] = { 0.3, 0.6, 0.9 };
static const dReal drop_height = 2.0;   // of the balls' lowest point
static const dReal ball_radius = 0.2;
static const dReal cube = 0.3;

static dSurfaceParameters ramp_surface[RAMPS];
static dSurfaceParameters ball_surface[BALLS];
static dGeomID ramps[RAMPS];
static dBodyID boxes[RAMPS];
static dGeomID box_geoms[RAMPS];
static dVector3 box_start[RAMPS];
static dReal slid_at_1s[RAMPS];
static dBodyID balls[BALLS];
static dGeomID ball_geoms[BALLS];
static int ball_phase[BALLS];        // 0 falling, 1 rising after the first bounce, 2 done
static dReal rebound[BALLS];         // highest lowest-point after the first bounce
static long reset_at;

// Where box i starts on its ramp, and the ramp's rotation (its x axis down the slope).
static void box_pose(int i, dReal *pos, dReal *R)
{
    dRFromAxisAndAngle(R, 0, 1, 0, slope);
    const dReal *c = dGeomGetPosition(ramps[i]);
    const dReal n[3] = { R[2], R[6], R[10] };      // ramp's z axis: its normal
    const dReal down[3] = { R[0], R[4], R[8] };   // ramp's x axis: down the slope
    for (int k = 0; k < 3; k++) pos[k] = c[k] + n[k] * (0.05 + cube / 2) - down[k] * 1.4;
}

static void reset(void)
{
    for (int i = 0; i < RAMPS; i++) {
        dMatrix3 R;
        box_pose(i, box_start[i], R);
        dBodySetPosition(boxes[i], box_start[i][0], box_start[i][1], box_start[i][2]);
        dBodySetRotation(boxes[i], R);
        dBodySetLinearVel(boxes[i], 0, 0, 0);
        dBodySetAngularVel(boxes[i], 0, 0, 0);
    }
    for (int i = 0; i < BALLS; i++) {
        dBodySetPosition(balls[i], 3, -1 + i, drop_height + ball_radius);
        dBodySetLinearVel(balls[i], 0, 0, 0);
        dBodySetAngularVel(balls[i], 0, 0, 0);
        ball_phase[i] = 0;
        rebound[i] = 0;
    }
    reset_at = steps;
}

static void build(void)
{
    dMass m;
    for (int i = 0; i < RAMPS; i++) {
        ramp_surface[i] = (dSurfaceParameters){ .mode = dContactApprox1, .mu = mus[i] };
        ramps[i] = dCreateBox(space, 4, 0.8, 0.1);
        dGeomSetPosition(ramps[i], -2, -2.4 + 1.6 * i, 1.5);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 1, 0, slope);
        dGeomSetRotation(ramps[i], R);
        dGeomSetData(ramps[i], &ramp_surface[i]);
        boxes[i] = dBodyCreate(world);
        dMassSetBox(&m, 500, cube, cube, cube);
        dBodySetMass(boxes[i], &m);
        box_geoms[i] = dCreateBox(space, cube, cube, cube);
        dGeomSetBody(box_geoms[i], boxes[i]);
        dGeomSetData(box_geoms[i], &ramp_surface[i]);
    }
    for (int i = 0; i < BALLS; i++) {
        ball_surface[i] = (dSurfaceParameters){ .mode = dContactBounce | dContactApprox1,
                                                .mu = 0.5, .bounce = bounces[i],
                                                .bounce_vel = 0.05 };
        balls[i] = dBodyCreate(world);
        dMassSetSphere(&m, 500, ball_radius);
        dBodySetMass(balls[i], &m);
        ball_geoms[i] = dCreateSphere(space, ball_radius);
        dGeomSetBody(ball_geoms[i], balls[i]);
        dGeomSetData(ball_geoms[i], &ball_surface[i]);
    }
    reset();
}

static dReal slid(int i)
{
    const dReal *p = dBodyGetPosition(boxes[i]);
    const dReal d[3] = { p[0] - box_start[i][0], p[1] - box_start[i][1], p[2] - box_start[i][2] };
    return (dReal)sqrt((double)(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
}

// Follow each ball: after its first bounce, the top of its flight.
static void watch(void)
{
    if (steps - reset_at == SLIDE_STEPS)
        for (int i = 0; i < RAMPS; i++) slid_at_1s[i] = slid(i);
    for (int i = 0; i < BALLS; i++) {
        const dReal vz = dBodyGetLinearVel(balls[i])[2];
        const dReal bottom = dBodyGetPosition(balls[i])[2] - ball_radius;
        if (ball_phase[i] == 0 && vz > 0) ball_phase[i] = 1;
        if (ball_phase[i] == 1) {
            rebound[i] = fmax(rebound[i], bottom);
            if (vz < 0) ball_phase[i] = 2;
        }
    }
}

static void start(void)
{
    static const float xyz[3] = { 6.5f, -5.0f, 3.0f };
    static const float hpr[3] = { 140.0f, -17.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("friction", "  r: put the boxes and balls back\n");
}

static void command(int key)
{
    if (key == 'r') reset();
}

static void step(int pause)
{
    if (!pause) {
        exu_collide(&contacts, space);
        dWorldStep(world, EXU_DT);
        steps++;
        watch();
    }
    dsSetTexture(DS_WOOD);
    for (int i = 0; i < RAMPS; i++) {
        const float grip = (float)(mus[i] / mus[RAMPS - 1]);
        dsSetColor(0.5f, 0.5f + 0.4f * grip, 0.9f - 0.5f * grip);
        exu_draw_geom(ramps[i]);
        dsSetColor(0.9f, 0.6f, 0.2f);
        exu_draw_geom(box_geoms[i]);
    }
    for (int i = 0; i < BALLS; i++) {
        dsSetColor(0.3f + 0.25f * (float)i, 0.2f, 0.2f);
        exu_draw_geom(ball_geoms[i]);
    }
}

static int check(void)
{
    for (int i = 0; i < RAMPS; i++)
        if (!exu_body_finite(boxes[i])) return exu_report("friction", 0, "state not finite");
    for (int i = 0; i < BALLS; i++)
        if (!exu_body_finite(balls[i])) return exu_report("friction", 0, "state not finite");
    if (steps - reset_at < 2 * EXU_RATE)
        return exu_report("friction", 1, "state finite; stopped before the slides and "
                          "bounces could be measured");
    int ok = 1;
    for (int i = 0; i < RAMPS; i++) {
        const double t = SLIDE_STEPS * (double)EXU_DT;
        const double a = 9.81 * (sin(slope) - mus[i] * cos(slope));
        const double expected = a > 0 ? a * t * t / 2 : 0;
        const double got = a > 0 ? slid_at_1s[i] : slid(i);
        const int good = a > 0 ? fabs(got - expected) < 0.05 * expected : got < 0.01;
        printf("  ramp mu %.1f: %s %.3f m, expected %.3f\n", (double)mus[i],
               a > 0 ? "slid in 1 s" : "moved in all", got, expected);
        ok = ok && good;
    }
    for (int i = 0; i < BALLS; i++) {
        const double expected = bounces[i] * bounces[i] * drop_height;
        printf("  ball e %.1f: rebounded to %.3f m, expected %.3f\n", (double)bounces[i],
               (double)rebound[i], expected);
        ok = ok && fabs(rebound[i] - expected) < 0.1 * expected;
        if (i > 0) ok = ok && rebound[i] > rebound[i - 1];
    }
    return exu_report("friction", ok, "boxes slide as g (sin - mu cos) t^2 / 2 (5 %%) or hold "
                      "(< 1 cm); balls rebound to e^2 h (10 %%), bouncier ones higher");
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    // Stiff contacts in both precisions (single's default CFM, 1e-5, soaks up bounce).
    dWorldSetCFM(world, 1e-10);
    dWorldSetAutoDisableFlag(world, 0);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactApprox1, .mu = 0.5 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 256 };
    build();

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
