// SPDX-License-Identifier: BSD-3-Clause
//
// test_joints_016a.c -- the prismatic-rotoide (PR), prismatic-universal (PU)
// and piston joints of ODE 0.16: free degrees move as the free motion
// predicts, constrained ones hold over 10 s under gravity with both steppers,
// motors reach their speed in one dWorldStep, stops hold, getters and setters
// round-trip, parameter groups reach the right axis, the (0, b) order, the
// re-attach hook, and bad input.

#include "test.h"

#include <math.h>

static const dReal STEP = REAL(0.01);
#define SECONDS_10 1000

// Angles after free turning: the steppers' orientation update is first order,
// off by about (w dt)^3 / 12 per step, ~1e-5 rad over these runs.
#define TURN_TOL 1e-4
// Motor rows have the world's CFM (1e-10 in double, 1e-5 in single): a motor
// reaches its speed to about CFM * its force / step.
#define MOTOR_TOL TOL(1e-6, 1e-3)

typedef int (*stepper)(dWorldID, dReal);
static const stepper steppers[2] = { dWorldStep, dWorldQuickStep };

// A sphere-like body (equal principal moments: no gyroscopic term).
static dBodyID make_body(dWorldID w, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, 1, REAL(0.1));
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

static double dot3(const dReal *a, const dReal *b)
{
    return (double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2];
}

// |v - (v . u) u| for unit u: how far v is off the line along u.
static double off_line(const dReal *v, const dReal *u)
{
    double d = dot3(v, u), s = 0;
    for (int i = 0; i < 3; i++) s += (v[i] - d * u[i]) * (v[i] - d * u[i]);
    return sqrt(s);
}

// |a x b| for unit a, b: the sine of the angle between them.
static double misalignment(const dReal *a, const dReal *b)
{
    dVector3 c;
    dCalcVectorCross3(c, a, b);
    return dCalcVectorLength3(c);
}

// ---- PR --------------------------------------------------------------------

// A pendulum (body 0.5 below the anchor) that turns about x and slides along
// its own y axis: gravity pulls both ways.
static dJointID make_pr_pendulum(dWorldID w, dBodyID *b)
{
    *b = make_body(w, 0, 0, REAL(-0.5));
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, *b, 0);
    dJointSetPRAnchor(j, 0, 0, 0);
    dJointSetPRAxis1(j, 0, 1, 0);
    dJointSetPRAxis2(j, 1, 0, 0);
    return j;
}

// A body turning about the vertical axis 2 through the anchor while it slides
// along its horizontal axis 1, braked by a velocity-0 motor; the joint
// carries its weight.
static int test_pr_holds_its_line_and_axis_for_10s(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, REAL(-9.81));
        dBodyID b = make_body(w, 0, 0, 0);
        dJointID j = dJointCreatePR(w, 0);
        dJointAttach(j, b, 0);
        dJointSetPRAnchor(j, REAL(0.1), 0, 0);
        dJointSetPRAxis1(j, 1, 0, 0);
        dJointSetPRAxis2(j, 0, 0, 1);
        dJointSetPRParam(j, dParamFMax, REAL(0.5));
        dBodySetAngularVel(b, 0, 0, 1);
        dBodySetLinearVel(b, REAL(0.3), REAL(-0.1), 0);
        double worst_line = 0, worst_axis = 0;
        const dReal anchor[3] = { REAL(0.1), 0, 0 }, z[3] = { 0, 0, 1 };
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            // The anchor stays on the body's slide line, which passes through
            // the body point that was at the anchor; axis 2 stays vertical.
            dVector3 p, axp, ax2, d;
            dBodyGetRelPointPos(b, REAL(0.1), 0, 0, p);
            dJointGetPRAxis1(j, axp);
            dJointGetPRAxis2(j, ax2);
            dSubtractVectors3(d, anchor, p);
            if (off_line(d, axp) > worst_line) worst_line = off_line(d, axp);
            if (misalignment(ax2, z) > worst_axis) worst_axis = misalignment(ax2, z);
        }
        CHECK_NEAR(worst_line, 0, 1e-3);
        CHECK_NEAR(worst_axis, 0, 1e-3);
        CHECK(dJointGetPRPosition(j) > 0.05);   // it did slide
        CHECK(fabs(dJointGetPRAngleRate(j)) > 0.1);   // and turn
        dWorldDestroy(w);
    }
    return 0;
}

// Without gravity: sliding at 0.7 m/s for 1 s, then turning at 1.5 rad/s
// for 1 s about the anchor at the body's centre, are free motions.
static int test_pr_slides_and_turns_freely(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 1, 2, 3);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPRAnchor(j, 1, 2, 3);
    dJointSetPRAxis1(j, 0, 0, 1);
    dJointSetPRAxis2(j, 1, 0, 0);
    dBodySetLinearVel(b, 0, 0, REAL(0.7));

    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPRPosition(j), 0.7, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPRPositionRate(j), 0.7, TOL(1e-9, 1e-4));
    CHECK_VEC(dBodyGetPosition(b), 1, 2, 3.7, TOL(1e-9, 1e-4));

    dBodySetLinearVel(b, 0, 0, 0);
    dJointSetPRAnchor(j, 1, 2, REAL(3.7));
    dBodySetAngularVel(b, REAL(1.5), 0, 0);
    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPRAngle(j), 1.5, TURN_TOL);
    CHECK_NEAR(dJointGetPRAngleRate(j), 1.5, TOL(1e-9, 1e-4));
    CHECK_VEC(dBodyGetPosition(b), 1, 2, 3.7, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

static int test_pr_motors_reach_their_speed_in_one_step(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, -1, REAL(-9.81));
    dBodyID b;
    dJointID j = make_pr_pendulum(w, &b);
    dJointSetPRParam(j, dParamVel, REAL(0.5));
    dJointSetPRParam(j, dParamFMax, 100);

    dWorldStep(w, STEP);
    CHECK_NEAR(dJointGetPRPositionRate(j), 0.5, MOTOR_TOL);

    // Group 2 drives the rotation only (a turn also tilts the slide axis, so
    // the slide motor is off for this step).
    dJointSetPRParam(j, dParamFMax, 0);
    dJointSetPRParam(j, dParamVel2, REAL(-1.5));
    dJointSetPRParam(j, dParamFMax2, 100);
    dWorldStep(w, STEP);
    CHECK_NEAR(dJointGetPRAngleRate(j), -1.5, MOTOR_TOL);
    dWorldDestroy(w);
    return 0;
}

static int test_pr_stops_hold(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, -3, REAL(-9.81));
        dBodyID b;
        dJointID j = make_pr_pendulum(w, &b);
        dBodySetAngularVel(b, 3, 0, 0);
        dJointSetPRParam(j, dParamLoStop, REAL(-0.2));
        dJointSetPRParam(j, dParamLoStop2, REAL(-0.4));
        dJointSetPRParam(j, dParamHiStop2, REAL(0.4));
        double lowest = 0, widest = 0;
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            if (dJointGetPRPosition(j) < lowest) lowest = dJointGetPRPosition(j);
            if (fabs(dJointGetPRAngle(j)) > widest) widest = fabs(dJointGetPRAngle(j));
        }
        // A stop holds within what one step of motion passes it by.
        // A stop acts from the step after it is reached: it is passed by about
        // one step of the arrival speed (~3 m/s here, ~1 rad/s for the angle).
        CHECK_NEAR(lowest, -0.2, 0.04);
        CHECK_NEAR(widest, 0.4, 0.04);
        CHECK_NEAR(dJointGetPRPosition(j), -0.2, 2e-3);
        dWorldDestroy(w);
    }
    return 0;
}

static int test_pr_getters_and_params_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = make_body(w, 0, 0, 0), b = make_body(w, 0, 1, 0);
    dQuaternion q;
    dQFromAxisAndAngle(q, 0, 0, 1, REAL(0.7));
    dBodySetQuaternion(a, q);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, a, b);
    dJointSetPRAnchor(j, 0, REAL(0.5), 0);
    dJointSetPRAxis1(j, 0, 2, 0);
    dJointSetPRAxis2(j, 0, 0, 3);
    dVector3 v;
    dJointGetPRAnchor(j, v);
    CHECK_VEC(v, 0, 0.5, 0, TOL(1e-12, 1e-6));
    dJointGetPRAxis1(j, v);
    CHECK_VEC(v, 0, 1, 0, TOL(1e-12, 1e-6));
    dJointGetPRAxis2(j, v);
    CHECK_VEC(v, 0, 0, 1, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPRPosition(j), 0, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPRAngle(j), 0, TOL(1e-12, 1e-6));
    CHECK(dJointGetType(j) == dJointTypePR);

    const int params[] = { dParamLoStop, dParamHiStop, dParamVel, dParamFMax, dParamFudgeFactor,
                           dParamBounce, dParamCFM, dParamStopERP, dParamStopCFM };
    for (int k = 0; k < 9; k++) {
        dJointSetPRParam(j, params[k], REAL(0.25));
        dJointSetPRParam(j, params[k] + dParamGroup2, REAL(0.75));
        CHECK(dJointGetPRParam(j, params[k]) == REAL(0.25));
        CHECK(dJointGetPRParam(j, params[k] + dParamGroup2) == REAL(0.75));
    }
    dWorldDestroy(w);
    return 0;
}

// Attached as (0, b): position and rates are body 1 (the world) against
// body 2, so they change sign; the axes do not.
static int test_pr_reversed_measures_the_world_against_the_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPRAnchor(j, 0, 0, 0);
    dJointSetPRAxis1(j, 0, 1, 0);
    dJointSetPRAxis2(j, 1, 0, 0);
    dBodySetLinearVel(b, 0, REAL(0.3), 0);
    dVector3 v;
    dJointGetPRAxis1(j, v);
    CHECK_VEC(v, 0, 1, 0, 1e-12);

    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPRPosition(j), -0.3, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPRPositionRate(j), -0.3, TOL(1e-9, 1e-4));
    dBodySetAngularVel(b, REAL(0.2), 0, 0);
    CHECK_NEAR(dJointGetPRAngleRate(j), -0.2, TOL(1e-12, 1e-6));
    dQuaternion q;
    dQFromAxisAndAngle(q, 1, 0, 0, REAL(0.2));
    dBodySetQuaternion(b, q);
    CHECK_NEAR(dJointGetPRAngle(j), -0.2, TOL(1e-12, 1e-6));
    // A torque on body 1 (the world) turns body 2 the other way.
    dBodySetAngularVel(b, 0, 0, 0);
    dJointAddPRTorque(j, 1);
    CHECK_VEC(dBodyGetTorque(b), -1, 0, 0, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// ---- piston ------------------------------------------------------------------

// A body hanging on a vertical piston through its centre, off the origin.
static dJointID make_piston(dWorldID w, dBodyID *b, int reversed)
{
    *b = make_body(w, REAL(0.3), 0, REAL(-0.5));
    dJointID j = dJointCreatePiston(w, 0);
    if (reversed) dJointAttach(j, 0, *b);
    else dJointAttach(j, *b, 0);
    dJointSetPistonAnchor(j, REAL(0.3), 0, 0);
    dJointSetPistonAxis(j, 0, 0, 1);
    return j;
}

// A body on a tilted piston, its anchor off its centre: gravity slides it
// down the axis and a spin about the axis stays free.
static int test_piston_holds_its_line_and_axis_for_10s(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, REAL(-9.81));
        dBodyID b = make_body(w, 0, 0, 0);
        dJointID j = dJointCreatePiston(w, 0);
        dJointAttach(j, b, 0);
        dJointSetPistonAnchor(j, 0, 0, REAL(0.2));
        const dReal axis[3] = { REAL(0.6), REAL(0.8), 0 };
        dJointSetPistonAxis(j, axis[0], axis[1], axis[2]);
        dBodySetAngularVel(b, REAL(0.6), REAL(0.8), 0);
        dBodySetLinearVel(b, REAL(0.06), REAL(0.08), 0);
        double worst_line = 0, worst_axis = 0;
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            dVector3 a1, a2, ax, d;
            dJointGetPistonAnchor(j, a1);
            dJointGetPistonAnchor2(j, a2);
            dJointGetPistonAxis(j, ax);
            dSubtractVectors3(d, a1, a2);
            if (off_line(d, axis) > worst_line) worst_line = off_line(d, axis);
            if (misalignment(ax, axis) > worst_axis) worst_axis = misalignment(ax, axis);
        }
        CHECK_NEAR(worst_line, 0, 1e-3);
        CHECK_NEAR(worst_axis, 0, 1e-3);
        CHECK_NEAR(dJointGetPistonPosition(j), 1, 1e-3);   // slid freely at 0.1 m/s
        dWorldDestroy(w);
    }
    return 0;
}

static int test_piston_turns_freely(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b;
    dJointID j = make_piston(w, &b, 0);
    dBodySetAngularVel(b, 0, 0, 2);

    for (int i = 0; i < 50; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPistonAngle(j), 1.0, TURN_TOL);
    CHECK_NEAR(dJointGetPistonAngleRate(j), 2.0, TOL(1e-9, 1e-4));
    CHECK_VEC(dBodyGetPosition(b), 0.3, 0, -0.5, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

static int test_piston_motors_reach_their_speed_in_one_step(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, REAL(-9.81));
    dBodyID b;
    dJointID j = make_piston(w, &b, 0);
    dJointSetPistonParam(j, dParamVel, REAL(0.4));
    dJointSetPistonParam(j, dParamFMax, 100);
    dJointSetPistonParam(j, dParamVel2, 3);
    dJointSetPistonParam(j, dParamFMax2, 100);

    dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPistonPositionRate(j), 0.4, MOTOR_TOL);
    CHECK_NEAR(dJointGetPistonAngleRate(j), 3, MOTOR_TOL);
    dWorldDestroy(w);
    return 0;
}

static int test_piston_stops_hold(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, REAL(-9.81));
        dBodyID b;
        dJointID j = make_piston(w, &b, 0);
        dBodySetAngularVel(b, 0, 0, 4);
        dJointSetPistonParam(j, dParamLoStop, REAL(-0.3));
        dJointSetPistonParam(j, dParamLoStop2, REAL(-1.0));
        dJointSetPistonParam(j, dParamHiStop2, REAL(1.0));
        double lowest = 0, highest = 0;
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            if (dJointGetPistonPosition(j) < lowest) lowest = dJointGetPistonPosition(j);
            if (fabs(dJointGetPistonAngle(j)) > highest) highest = fabs(dJointGetPistonAngle(j));
        }
        // Passed by about one step of the arrival speed (~2.4 m/s, 4 rad/s).
        CHECK_NEAR(lowest, -0.3, 0.03);
        CHECK_NEAR(highest, 1.0, 0.05);
        CHECK_NEAR(dJointGetPistonPosition(j), -0.3, 2e-3);
        dWorldDestroy(w);
    }
    return 0;
}

static int test_piston_offsets_set_the_position(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = make_body(w, 0, 0, 0), b = make_body(w, 0, 0, 1);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, a, b);
    dJointSetPistonAxis(j, 0, 0, 1);
    dJointSetPistonAnchorOffset(j, 0, 0, REAL(0.5), 0, 0, REAL(0.25));
    CHECK_NEAR(dJointGetPistonPosition(j), 0.25, TOL(1e-12, 1e-6));
    dVector3 v;
    dJointGetPistonAnchor2(j, v);
    CHECK_VEC(v, 0, 0, 0.5, TOL(1e-12, 1e-6));
    // Reversed, the offset keeps the user's sense.
    dJointAttach(j, 0, a);
    dJointSetPistonAnchorOffset(j, 0, 0, REAL(0.5), 0, 0, REAL(0.25));
    CHECK_NEAR(dJointGetPistonPosition(j), 0.25, TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// A force along the axis: +force on body 1, -force on body 2 (user order).
static int test_piston_force_acts_in_the_users_sense(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = make_body(w, 0, 0, 0), b = make_body(w, 0, 0, 1);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, a, b);
    dJointSetPistonAnchor(j, 0, 0, REAL(0.5));
    dJointSetPistonAxis(j, 0, 0, 1);
    dJointAddPistonForce(j, 2);
    CHECK_VEC(dBodyGetForce(a), 0, 0, 2, 1e-12);
    CHECK_VEC(dBodyGetForce(b), 0, 0, -2, 1e-12);
    dJointAttach(j, 0, b);
    dJointAddPistonForce(j, 2);   // the world pushed +z: b is pushed -z
    CHECK_VEC(dBodyGetForce(b), 0, 0, -4, 1e-12);
    dWorldStep(w, STEP);
    CHECK(dJointGetPistonPositionRate(j) > 0);
    dWorldDestroy(w);
    return 0;
}

static int test_piston_reversed_measures_the_world_against_the_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b;
    dJointID j = make_piston(w, &b, 1);
    dBodySetLinearVel(b, 0, 0, REAL(0.5));
    dBodySetAngularVel(b, 0, 0, 1);

    for (int i = 0; i < 20; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPistonPosition(j), -0.1, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPistonPositionRate(j), -0.5, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPistonAngle(j), -0.2, TURN_TOL);
    CHECK_NEAR(dJointGetPistonAngleRate(j), -1, TOL(1e-9, 1e-4));
    dVector3 a1, a2;
    dJointGetPistonAnchor(j, a1);    // body 1's: the world point
    dJointGetPistonAnchor2(j, a2);   // body 2's: moved with the body
    CHECK_VEC(a1, 0.3, 0, 0, TOL(1e-12, 1e-6));
    CHECK_VEC(a2, 0.3, 0, 0.1, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// ---- PU --------------------------------------------------------------------

// A pendulum of variable length: the body 1 below the anchor, slide axis
// along the rod, universal axes x and y at the anchor.
static dJointID make_pu_pendulum(dWorldID w, dBodyID *b)
{
    *b = make_body(w, 0, 0, -1);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, *b, 0);
    dJointSetPUAnchor(j, 0, 0, 0);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxisP(j, 0, 0, 1);
    return j;
}

static int test_pu_holds_its_anchor_line_and_cross_for_10s(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, REAL(-9.81));
        dBodyID b;
        dJointID j = make_pu_pendulum(w, &b);
        // The rod's length is held by its stops (gravity pulls it out).
        dJointSetPUParam(j, dParamLoStop3, 0);
        dJointSetPUParam(j, dParamHiStop3, REAL(0.3));
        dBodySetLinearVel(b, REAL(0.4), REAL(0.3), 0);
        double worst_line = 0, worst_cross = 0;
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            // The world anchor stays on the body's slide line through the
            // body point that was at the anchor; axes 1 and 2 stay perpendicular.
            dVector3 p, axp, ax1, ax2, d;
            const dReal origin[3] = { 0, 0, 0 };
            dBodyGetRelPointPos(b, 0, 0, 1, p);
            dJointGetPUAxisP(j, axp);
            dJointGetPUAxis1(j, ax1);
            dJointGetPUAxis2(j, ax2);
            dSubtractVectors3(d, origin, p);
            if (off_line(d, axp) > worst_line) worst_line = off_line(d, axp);
            if (fabs(dot3(ax1, ax2)) > worst_cross) worst_cross = fabs(dot3(ax1, ax2));
        }
        CHECK_NEAR(worst_line, 0, 1e-3);
        CHECK_NEAR(worst_cross, 0, 1e-3);
        dWorldDestroy(w);
    }
    return 0;
}

// Without gravity: sliding along P, and turning about axes 1 and 2 at the
// anchor at the body's centre, are free.
static int test_pu_slides_and_turns_freely(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPUAnchor(j, 0, 0, 0);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxis3(j, 0, 0, 1);
    dBodySetLinearVel(b, 0, 0, REAL(0.6));

    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPUPosition(j), 0.6, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPUPositionRate(j), 0.6, TOL(1e-9, 1e-4));

    dBodySetLinearVel(b, 0, 0, 0);
    dJointSetPUAnchor(j, 0, 0, REAL(0.6));
    dBodySetAngularVel(b, REAL(0.5), 0, 0);
    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPUAngle1(j), 0.5, TURN_TOL);
    CHECK_NEAR(dJointGetPUAngle1Rate(j), 0.5, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPUAngle2(j), 0, TOL(1e-9, 1e-4));
    dReal a1, a2;
    dJointGetPUAngles(j, &a1, &a2);
    CHECK_NEAR(a1, 0.5, TURN_TOL);
    CHECK_NEAR(a2, 0, TOL(1e-9, 1e-4));
    CHECK_VEC(dBodyGetPosition(b), 0, 0, 0.6, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

static int test_pu_motors_reach_their_speed_in_one_step(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, REAL(-9.81));
    dBodyID b;
    dJointID j = make_pu_pendulum(w, &b);
    dJointSetPUParam(j, dParamVel3, REAL(0.3));
    dJointSetPUParam(j, dParamFMax3, 100);
    dWorldStep(w, STEP);
    CHECK_NEAR(dJointGetPUPositionRate(j), 0.3, MOTOR_TOL);

    // Groups 1 and 2 drive the universal axes (the slide motor is off: a turn
    // tilts the slide axis).
    dJointSetPUParam(j, dParamFMax3, 0);
    dJointSetPUParam(j, dParamVel, REAL(0.7));
    dJointSetPUParam(j, dParamFMax, 100);
    dJointSetPUParam(j, dParamVel2, REAL(-0.4));
    dJointSetPUParam(j, dParamFMax2, 100);
    dWorldStep(w, STEP);
    CHECK_NEAR(dJointGetPUAngle1Rate(j), 0.7, MOTOR_TOL);
    CHECK_NEAR(dJointGetPUAngle2Rate(j), -0.4, MOTOR_TOL);
    dWorldDestroy(w);
    return 0;
}

static int test_pu_stops_hold(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, REAL(-9.81));
        dBodyID b;
        dJointID j = make_pu_pendulum(w, &b);
        dJointSetPUParam(j, dParamLoStop3, REAL(-0.2));
        dJointSetPUParam(j, dParamHiStop, REAL(0.3));
        dJointSetPUParam(j, dParamLoStop2, REAL(-0.2));
        dBodySetLinearVel(b, REAL(-1.5), REAL(1.5), 0);
        double lowest = 0, highest1 = 0, lowest2 = 0;
        for (int i = 0; i < SECONDS_10; i++) {
            steppers[s](w, STEP);
            if (dJointGetPUPosition(j) < lowest) lowest = dJointGetPUPosition(j);
            if (dJointGetPUAngle1(j) > highest1) highest1 = dJointGetPUAngle1(j);
            if (dJointGetPUAngle2(j) < lowest2) lowest2 = dJointGetPUAngle2(j);
        }
        // Passed by about one step of the arrival speed.
        CHECK_NEAR(lowest, -0.2, 0.03);
        CHECK_NEAR(highest1, 0.3, 0.05);
        CHECK_NEAR(lowest2, -0.2, 0.05);
        CHECK(highest1 > 0.25);   // it reached the stops
        CHECK(lowest2 < -0.15);
        dWorldDestroy(w);
    }
    return 0;
}

static int test_pu_getters_offsets_and_params_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = make_body(w, 0, 0, 0), b = make_body(w, 1, 0, 0);
    dQuaternion q;
    dQFromAxisAndAngle(q, 1, 1, 0, REAL(0.5));
    dBodySetQuaternion(b, q);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, a, b);
    dJointSetPUAnchor(j, REAL(0.5), 0, 0);
    dJointSetPUAxis1(j, 0, 3, 0);
    dJointSetPUAxis2(j, 0, 0, 1);
    dJointSetPUAxis3(j, 2, 0, 0);
    dVector3 v;
    dJointGetPUAnchor(j, v);
    CHECK_VEC(v, 0.5, 0, 0, TOL(1e-12, 1e-6));
    dJointGetPUAxis1(j, v);
    CHECK_VEC(v, 0, 1, 0, TOL(1e-12, 1e-6));
    dJointGetPUAxis2(j, v);
    CHECK_VEC(v, 0, 0, 1, TOL(1e-12, 1e-6));
    dJointGetPUAxis3(j, v);
    CHECK_VEC(v, 1, 0, 0, TOL(1e-12, 1e-6));
    dJointGetPUAxisP(j, v);
    CHECK_VEC(v, 1, 0, 0, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPUAngle1(j), 0, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPUAngle2(j), 0, TOL(1e-12, 1e-6));
    dJointSetPUAnchorOffset(j, REAL(0.5), 0, 0, REAL(0.2), 0, 0);
    CHECK_NEAR(dJointGetPUPosition(j), 0.2, TOL(1e-12, 1e-6));
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    // The deprecated form: body 1 taken as displaced by delta at zero.
    dJointSetPUAnchorDelta(j, REAL(0.5), 0, 0, REAL(0.2), 0, 0);
    CHECK_NEAR(dJointGetPUPosition(j), -0.2, TOL(1e-12, 1e-6));
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

    for (int g = 0; g < 3; g++) {
        dJointSetPUParam(j, dParamVel + g * dParamGroup, (dReal)(g + 1));
        dJointSetPUParam(j, dParamStopERP + g * dParamGroup, REAL(0.1) * (g + 1));
    }
    for (int g = 0; g < 3; g++) {
        CHECK(dJointGetPUParam(j, dParamVel + g * dParamGroup) == (dReal)(g + 1));
        CHECK(dJointGetPUParam(j, dParamStopERP + g * dParamGroup) == REAL(0.1) * (g + 1));
    }
    dWorldDestroy(w);
    return 0;
}

// Attached as (0, b) the user's axis 1 is on the world: the getters keep the
// user's axes, the angles swap back, position and its rate change sign.
static int test_pu_reversed_keeps_the_users_axes(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPUAnchor(j, 0, 0, 0);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxis3(j, 0, 0, 1);
    dBodySetLinearVel(b, 0, 0, REAL(0.2));
    dBodySetAngularVel(b, 0, REAL(0.3), 0);
    dVector3 v;
    dJointGetPUAxis1(j, v);
    CHECK_VEC(v, 1, 0, 0, 1e-12);
    dJointGetPUAxis2(j, v);
    CHECK_VEC(v, 0, 1, 0, 1e-12);

    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);

    CHECK_NEAR(dJointGetPUPosition(j), -0.2, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetPUPositionRate(j), -0.2, TOL(1e-9, 1e-4));
    dReal a1, a2;
    dJointGetPUAngles(j, &a1, &a2);
    CHECK_NEAR(a1, 0, TOL(1e-9, 1e-4));
    CHECK(fabs(a2) > 0.29 && fabs(a2) < 0.31);
    CHECK_NEAR(dJointGetPUAngle2(j), a2, 1e-12);
    CHECK_NEAR(dJointGetPUAngle2Rate(j), 0.3, TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// ---- all three -----------------------------------------------------------------

// Re-attaching recomputes the body-relative values from the world ones: the
// bodies, at rest and with no gravity, do not move, and the positions are 0.
static int test_reattaching_starts_without_error(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = make_body(w, 0, 0, 0), b = make_body(w, REAL(0.4), REAL(0.3), 0);
    dJointID j[3] = { dJointCreatePR(w, 0), dJointCreatePU(w, 0), dJointCreatePiston(w, 0) };
    for (int k = 0; k < 3; k++) dJointAttach(j[k], a, b);
    dJointSetPRAnchor(j[0], REAL(0.2), 0, 0);
    dJointSetPUAnchor(j[1], REAL(0.2), 0, 0);
    dJointSetPistonAnchor(j[2], REAL(0.2), 0, 0);
    dBodySetPosition(b, REAL(0.5), REAL(0.1), REAL(0.2));   // away from where set
    for (int k = 0; k < 3; k++) dJointAttach(j[k], b, a);
    CHECK_NEAR(dJointGetPRPosition(j[0]), 0, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPUPosition(j[1]), 0, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetPistonPosition(j[2]), 0, TOL(1e-12, 1e-6));

    for (int i = 0; i < 10; i++) dWorldStep(w, STEP);

    CHECK_VEC(dBodyGetPosition(a), 0, 0, 0, TOL(1e-9, 1e-5));
    CHECK_VEC(dBodyGetPosition(b), 0.5, 0.1, 0.2, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

static int test_bad_input_is_reported(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dJointID hinge = dJointCreateHinge(w, 0);
    dJointID pr = dJointCreatePR(w, 0), pu = dJointCreatePU(w, 0), pi = dJointCreatePiston(w, 0);
    dJointAttach(pr, b, 0);
    dJointAttach(pu, b, 0);
    dJointAttach(pi, b, 0);

    int n = test_captured_count();
    dJointGetPRPosition(hinge);
    CHECK(test_captured_count() == ++n && test_captured_contains("not the right type"));
    dJointSetPUAxis1(pi, 1, 0, 0);
    CHECK(test_captured_count() == ++n);
    dJointAddPistonForce(pr, 1);
    CHECK(test_captured_count() == ++n);

    dJointSetPRAxis1(pr, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("no direction"));
    dJointSetPUAxis3(pu, 0, 0, 0);
    CHECK(test_captured_count() == ++n);
    dJointSetPistonAxis(pi, NAN, 0, 1);
    CHECK(test_captured_count() == ++n);
    dVector3 v;
    dJointGetPistonAxis(pi, v);
    CHECK_VEC(v, 1, 0, 0, 1e-12);   // unchanged

    dJointSetPRParam(pr, dParamVel, NAN);
    CHECK(test_captured_count() == ++n && test_captured_contains("NaN"));
    dJointSetPRParam(pr, dParamVel3, 1);   // PR has two groups
    CHECK(test_captured_count() == ++n);
    dJointSetPistonParam(pi, dParamFMax, -1);
    CHECK(test_captured_count() == ++n);
    dJointSetPUAnchor(pu, 0, INFINITY, 0);
    CHECK(test_captured_count() == ++n);
    dJointGetPUAngles(pu, NULL, NULL);
    CHECK(test_captured_count() == ++n);
    dJointGetPRAnchor(pr, NULL);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointCreatePiston(NULL, 0) == NULL);
    CHECK(test_captured_count() == ++n);
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_pr_holds_its_line_and_axis_for_10s),
    TEST_CASE(test_pr_slides_and_turns_freely),
    TEST_CASE(test_pr_motors_reach_their_speed_in_one_step),
    TEST_CASE(test_pr_stops_hold),
    TEST_CASE(test_pr_getters_and_params_round_trip),
    TEST_CASE(test_pr_reversed_measures_the_world_against_the_body),
    TEST_CASE(test_piston_holds_its_line_and_axis_for_10s),
    TEST_CASE(test_piston_turns_freely),
    TEST_CASE(test_piston_motors_reach_their_speed_in_one_step),
    TEST_CASE(test_piston_stops_hold),
    TEST_CASE(test_piston_offsets_set_the_position),
    TEST_CASE(test_piston_force_acts_in_the_users_sense),
    TEST_CASE(test_piston_reversed_measures_the_world_against_the_body),
    TEST_CASE(test_pu_holds_its_anchor_line_and_cross_for_10s),
    TEST_CASE(test_pu_slides_and_turns_freely),
    TEST_CASE(test_pu_motors_reach_their_speed_in_one_step),
    TEST_CASE(test_pu_stops_hold),
    TEST_CASE(test_pu_getters_offsets_and_params_round_trip),
    TEST_CASE(test_pu_reversed_keeps_the_users_axes),
    TEST_CASE(test_reattaching_starts_without_error),
    TEST_CASE(test_bad_input_is_reported),
    TEST_END
};
