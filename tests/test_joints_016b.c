// SPDX-License-Identifier: BSD-3-Clause
//
// test_joints_016b.c -- joints ODE 0.16 added: the linear motor, plane-2D,
// double ball, double hinge and transmission joints. Getters and setters,
// parameter groups, the constrained degrees held and the free ones free over
// 10 s with both dWorldStep and dWorldQuickStep, motors against their one-step
// and force-limited answers, transmission ratios and backlash, bad input.

#include "test.h"

#include <math.h>

static const dReal STEP = REAL(0.01);
#define STEPS_10S 1000

typedef int (*stepper)(dWorldID, dReal);
static const stepper steppers[2] = { dWorldStep, dWorldQuickStep };
static const char *const stepper_names[2] = { "dWorldStep", "dWorldQuickStep" };

// ---- helpers ------------------------------------------------------------------

static dWorldID make_world(dReal gravity_z)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, gravity_z);
    return w;
}

// A body at (x,y,z) with the given mass and principal moments along x, y, z.
static dBodyID make_body(dWorldID w, dReal x, dReal y, dReal z, dReal mass, dReal ixx, dReal iyy,
                         dReal izz)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetParameters(&m, mass, 0, 0, 0, ixx, iyy, izz, 0, 0, 0);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

// Turn b about the world direction (ax, ay, az) by angle (orientation only).
static void turn_body(dBodyID b, dReal ax, dReal ay, dReal az, dReal angle)
{
    dQuaternion r, q;
    dQFromAxisAndAngle(r, ax, ay, az, angle);
    dQMultiply0(q, r, dBodyGetQuaternion(b));
    dBodySetQuaternion(b, q);
}

static double dist3(const dReal *a, const dReal *b)
{
    return sqrt((double)((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                         (a[2] - b[2]) * (a[2] - b[2])));
}

static double dot3(const dReal *a, const dReal *b)
{
    return (double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2];
}

// Angle (rad) between two unit vectors, accurate for small angles.
static double angle_between(const dReal *a, const dReal *b)
{
    dVector3 c;
    dCalcVectorCross3(c, a, b);
    return atan2(sqrt(dot3(c, c)), dot3(a, b));
}

// World direction of the body's local vector (x, y, z).
static void body_dir(dBodyID b, dReal x, dReal y, dReal z, dVector3 out)
{
    dBodyVectorToWorld(b, x, y, z, out);
}

// A changing force and torque (deterministic), to shake a body about.
static void shake(dBodyID b, int step, dReal f, dReal t)
{
    const dReal s = (dReal)step * REAL(0.37);
    dBodyAddForce(b, f * dSin(s), f * dCos(REAL(1.3) * s), f * dSin(REAL(0.7) * s + 1));
    dBodyAddTorque(b, t * dCos(REAL(0.9) * s), t * dSin(REAL(1.1) * s), t * dCos(s + 2));
}

// ---- linear motor -----------------------------------------------------------------

static int test_lmotor_defaults_and_axes(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 1, 0, 0, 1, 1, 1, 1);
    turn_body(b1, 0, 0, 1, REAL(0.5));
    turn_body(b2, 1, 0, 0, REAL(-0.7));
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, b1, b2);
    dVector3 v;

    CHECK(dJointGetType(j) == dJointTypeLMotor);
    CHECK(dJointGetLMotorNumAxes(j) == 0);
    dJointGetLMotorAxis(j, 0, v);
    CHECK_VEC(v, 0, 0, 0, 0);
    CHECK(dJointGetLMotorParam(j, dParamFMax) == 0);
    CHECK(dJointGetLMotorParam(j, dParamVel3) == 0);
    CHECK(dJointGetLMotorParam(j, dParamLoStop2) == -dInfinity);
    CHECK(dJointGetLMotorParam(j, dParamCFM3) == dWorldGetCFM(w));

    dJointSetLMotorNumAxes(j, 3);
    dJointSetLMotorAxis(j, 0, 0, 0, 2, 0);
    dJointSetLMotorAxis(j, 1, 1, 1, 1, 0);
    dJointSetLMotorAxis(j, 2, 2, 0, 0, -3);
    CHECK(dJointGetLMotorNumAxes(j) == 3);
    const dReal s = (dReal)M_SQRT1_2, tol = TOL(1e-12, 1e-6);
    dJointGetLMotorAxis(j, 0, v);
    CHECK_VEC(v, 0, 1, 0, tol);
    dJointGetLMotorAxis(j, 1, v);
    CHECK_VEC(v, s, s, 0, tol);
    dJointGetLMotorAxis(j, 2, v);
    CHECK_VEC(v, 0, 0, -1, tol);

    // Axes 1 and 2 turn with their bodies, axis 0 stays in the world.
    turn_body(b1, 0, 0, 1, (dReal)(M_PI / 4));
    turn_body(b2, 0, 1, 0, (dReal)(M_PI / 2));
    dJointGetLMotorAxis(j, 0, v);
    CHECK_VEC(v, 0, 1, 0, tol);
    dJointGetLMotorAxis(j, 1, v);
    CHECK_VEC(v, 0, 1, 0, tol);
    dJointGetLMotorAxis(j, 2, v);
    CHECK_VEC(v, -1, 0, 0, tol);
    dWorldDestroy(w);
    return 0;
}

// Parameter group g (dParamVel + g * dParamGroup ...) is axis g's, and only
// that axis moves.
static int test_lmotor_param_groups_route_to_axes(void)
{
    for (int g = 0; g < 3; g++) {
        dWorldID w = make_world(0);
        dBodyID b = make_body(w, 0, 0, 0, 2, 1, 1, 1);
        dJointID j = dJointCreateLMotor(w, 0);
        dJointAttach(j, b, 0);
        dJointSetLMotorNumAxes(j, 3);
        dJointSetLMotorAxis(j, 0, 0, 1, 0, 0);
        dJointSetLMotorAxis(j, 1, 0, 0, 1, 0);
        dJointSetLMotorAxis(j, 2, 0, 0, 0, 1);
        dJointSetLMotorParam(j, dParamVel + g * dParamGroup, REAL(1.5));
        dJointSetLMotorParam(j, dParamFMax + g * dParamGroup, 1000);
        dJointSetLMotorParam(j, dParamCFM + g * dParamGroup, 0);
        for (int k = 0; k < 3; k++) {
            CHECK(dJointGetLMotorParam(j, dParamVel + k * dParamGroup) == (k == g ? REAL(1.5) : 0));
            CHECK(dJointGetLMotorParam(j, dParamFMax + k * dParamGroup) == (k == g ? 1000 : 0));
        }

        dWorldStep(w, STEP);

        const dReal *v = dBodyGetLinearVel(b);
        for (int k = 0; k < 3; k++) CHECK_NEAR(v[k], k == g ? 1.5 : 0, TOL(1e-9, 1e-5));
        dWorldDestroy(w);
    }
    return 0;
}

// Body 1 moves relative to body 2 along an axis fixed to a turned body 2 at
// exactly vel after one dWorldStep (momentum conserved: equal masses share
// it), across the axis nothing changes. The bodies sit on the axis, so the
// pair of forces (acting at the midpoint of the centres) makes no couple.
static int test_lmotor_reaches_velocity_in_one_step(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    turn_body(b2, 1, 1, 0, REAL(0.8));
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetLMotorNumAxes(j, 1);
    dJointSetLMotorAxis(j, 0, 2, 1, 2, 2);
    dJointSetLMotorParam(j, dParamVel, 3);
    dJointSetLMotorParam(j, dParamFMax, 1000);
    dJointSetLMotorParam(j, dParamCFM, 0);
    dVector3 ax;
    dJointGetLMotorAxis(j, 0, ax);
    dBodySetPosition(b2, 2 * ax[0], 2 * ax[1], 2 * ax[2]);

    dWorldStep(w, STEP);

    const dReal *v1 = dBodyGetLinearVel(b1), *v2 = dBodyGetLinearVel(b2);
    const dReal tol = TOL(1e-9, 1e-5);
    dVector3 rel;
    dSubtractVectors3(rel, v1, v2);
    CHECK_NEAR(dot3(rel, ax), 3, tol);
    CHECK_NEAR(dist3(rel, (dReal[3]){ 3 * ax[0], 3 * ax[1], 3 * ax[2] }), 0, tol);
    CHECK_NEAR(v1[0] + v2[0], 0, tol);
    CHECK_NEAR(v1[1] + v2[1], 0, tol);
    CHECK_NEAR(v1[2] + v2[2], 0, tol);
    // The pair of forces acts at the midpoint: no couple, no spin.
    CHECK_NEAR(dist3(dBodyGetAngularVel(b1), dBodyGetAngularVel(b2)), 0, tol);
    dWorldDestroy(w);
    return 0;
}

// Too little FMax: the speed grows by FMax h / m per step, with either stepper.
static int test_lmotor_limited_by_fmax(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = make_world(0);
        dBodyID b = make_body(w, 0, 0, 0, 2, 1, 1, 1);
        dJointID j = dJointCreateLMotor(w, 0);
        dJointAttach(j, b, 0);
        dJointSetLMotorNumAxes(j, 1);
        dJointSetLMotorAxis(j, 0, 0, 0, 0, 1);
        dJointSetLMotorParam(j, dParamVel, 10);
        dJointSetLMotorParam(j, dParamFMax, REAL(0.5));
        for (int i = 0; i < 20; i++) steppers[s](w, STEP);
        CHECK_NEAR(dBodyGetLinearVel(b)[2], 20 * 0.5 * STEP / 2, TOL(1e-9, 1e-5));
        // Then it reaches and keeps the target with enough force.
        dJointSetLMotorParam(j, dParamFMax, 1000);
        for (int i = 0; i < 50; i++) steppers[s](w, STEP);
        if (fabs(dBodyGetLinearVel(b)[2] - 10) > 1e-3) {
            test_fail(__FILE__, __LINE__, "%s: vz %g", stepper_names[s],
                      (double)dBodyGetLinearVel(b)[2]);
            return 1;
        }
        dWorldDestroy(w);
    }
    return 0;
}

// A motor along x (holding vx = 0) leaves y, z and rotation free: a force along
// y accelerates the body as if there were no joint, over 10 s.
static int test_lmotor_other_directions_are_free(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = make_world(0);
        dBodyID b = make_body(w, 0, 0, 0, 2, 1, 1, 1);
        dJointID j = dJointCreateLMotor(w, 0);
        dJointAttach(j, b, 0);
        dJointSetLMotorNumAxes(j, 1);
        dJointSetLMotorAxis(j, 0, 1, 1, 0, 0);   // turns with the body, which does not turn
        dJointSetLMotorParam(j, dParamFMax, 1000);
        for (int i = 0; i < STEPS_10S; i++) {
            dBodyAddForce(b, 5, 1, -2);
            steppers[s](w, STEP);
        }
        const dReal *v = dBodyGetLinearVel(b);
        CHECK_NEAR(v[0], 0, 1e-3);
        CHECK_NEAR(v[1], 1 * 10.0 / 2, TOL(1e-9, 1e-3));
        CHECK_NEAR(v[2], -2 * 10.0 / 2, TOL(1e-9, 1e-3));
        CHECK_NEAR(dBodyGetPosition(b)[0], 0, 1e-3);
        dWorldDestroy(w);
    }
    return 0;
}

// Attached as (0, b): b is body 2, so axis . (v_world - v_b) = vel moves b at -vel.
static int test_lmotor_reversed_attach_keeps_user_order(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, 0, b);
    dJointSetLMotorNumAxes(j, 1);
    dJointSetLMotorAxis(j, 0, 0, 1, 0, 0);
    dJointSetLMotorParam(j, dParamVel, 2);
    dJointSetLMotorParam(j, dParamFMax, 1000);
    dJointSetLMotorParam(j, dParamCFM, 0);

    dWorldStep(w, STEP);

    CHECK_NEAR(dBodyGetLinearVel(b)[0], -2, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

static int test_lmotor_bad_input(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateLMotor(w, 0), h = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetLMotorNumAxes(j, 1);
    dJointSetLMotorAxis(j, 0, 0, 0, 0, 1);
    dVector3 v;
    test_capture_reports();
    int n = 0;

    dJointSetLMotorNumAxes(h, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("not the right type"));
    CHECK(dJointGetLMotorNumAxes(h) == 0 && test_captured_count() == ++n);
    dJointSetLMotorNumAxes(j, 4);
    CHECK(test_captured_count() == ++n && test_captured_contains("num"));
    dJointSetLMotorNumAxes(j, -1);
    CHECK(test_captured_count() == ++n && dJointGetLMotorNumAxes(j) == 1);
    dJointSetLMotorAxis(j, 3, 0, 1, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("anum"));
    dJointSetLMotorAxis(j, -1, 0, 1, 0, 0);
    CHECK(test_captured_count() == ++n);
    dJointSetLMotorAxis(j, 0, 3, 1, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("rel"));
    dJointSetLMotorAxis(j, 0, 0, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("no direction"));
    dJointSetLMotorAxis(j, 0, 0, NAN, 0, 1);
    CHECK(test_captured_count() == ++n);
    dJointGetLMotorAxis(j, 0, v);
    CHECK_VEC(v, 0, 0, 1, 0);   // unchanged
    dJointGetLMotorAxis(j, 3, v);
    CHECK(test_captured_count() == ++n);
    dJointGetLMotorAxis(j, 0, NULL);
    CHECK(test_captured_count() == ++n && test_captured_contains("result"));
    dJointSetLMotorParam(j, dParamVel, NAN);
    CHECK(test_captured_count() == ++n && test_captured_contains("NaN"));
    dJointSetLMotorParam(j, dParamVel + 3 * dParamGroup, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("parameter"));
    CHECK(dJointGetLMotorParam(j, dParamVel + 3 * dParamGroup) == 0);
    CHECK(test_captured_count() == ++n);
    dJointSetLMotorParam(j, dParamFMax, -1);
    CHECK(test_captured_count() == ++n && dJointGetLMotorParam(j, dParamFMax) == 0);
    CHECK(dJointCreateLMotor(NULL, 0) == NULL && test_captured_count() == ++n);
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

// ---- plane-2D ---------------------------------------------------------------------

// A box in the plane z = 0 under gravity along -z, off-plane forces and
// torques and in-plane pushes: z and the tilt stay 0 for 10 s while x, y and
// the turn about z follow the in-plane forces as for a free body.
static int test_plane2d_holds_plane_frees_the_rest(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = make_world(REAL(-9.81));
        dBodyID b = make_body(w, 0, 0, 0, 2, REAL(0.3), REAL(0.5), REAL(0.4));
        dJointID j = dJointCreatePlane2D(w, 0);
        dJointAttach(j, b, 0);
        double max_z = 0, max_tilt = 0;
        for (int i = 0; i < STEPS_10S; i++) {
            shake(b, i, 0, 3);   // torques only: their z part turns the box
            dBodyAddForce(b, 1, -REAL(0.5), 40 * dSin(REAL(0.1) * (dReal)i));
            steppers[s](w, STEP);
            dVector3 bz;
            body_dir(b, 0, 0, 1, bz);
            max_z = fmax(max_z, fabs((double)dBodyGetPosition(b)[2]));
            max_tilt = fmax(max_tilt, angle_between(bz, (dReal[3]){ 0, 0, 1 }));
        }
        if (!(max_z <= 1e-3 && max_tilt <= 1e-3)) {
            test_fail(__FILE__, __LINE__, "%s: max |z| %g, max tilt %g", stepper_names[s], max_z,
                      max_tilt);
            return 1;
        }
        // x = F t^2 / 2m exactly up to integration order (symplectic Euler: t (t + h) / 2).
        const double t = 10, x = 1 * t * (t + STEP) / 2 / 2;
        CHECK_NEAR(dBodyGetPosition(b)[0], x, TOL(1e-6, 1e-2));
        CHECK_NEAR(dBodyGetPosition(b)[1], -x / 2, TOL(1e-6, 1e-2));
        CHECK_NEAR(dBodyGetLinearVel(b)[0], 1 * t / 2, TOL(1e-9, 1e-3));
        // The turn about z is free: the torques about z spun the box.
        CHECK(fabs((double)dBodyGetAngularVel(b)[2]) > 0.01);
        dWorldDestroy(w);
    }
    return 0;
}

// A height error decays by the ERP.
static int test_plane2d_pulls_back_to_the_plane(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, REAL(0.5), 1, 1, 1, 1);
    dJointID j = dJointCreatePlane2D(w, 0);
    dJointAttach(j, b, 0);
    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);
    // z shrinks by (1 - ERP) per step.
    CHECK_NEAR(dBodyGetPosition(b)[2], 0.5 * pow(0.8, 100), TOL(1e-9, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// The x, y and angle motors reach their targets in one dWorldStep, and each
// is force-limited.
static int test_plane2d_motors(void)
{
    void (*set[3])(dJointID, int, dReal) = { dJointSetPlane2DXParam, dJointSetPlane2DYParam,
                                             dJointSetPlane2DAngleParam };
    for (int k = 0; k < 3; k++) {
        for (int limited = 0; limited < 2; limited++) {
            dWorldID w = make_world(0);
            dBodyID b = make_body(w, 0, 0, 0, 2, REAL(0.3), REAL(0.5), REAL(0.4));
            dJointID j = dJointCreatePlane2D(w, 0);
            dJointAttach(j, b, 0);
            set[k](j, dParamVel, REAL(1.5));
            set[k](j, dParamFMax, limited ? REAL(0.2) : 1000);
            set[k](j, dParamCFM, 0);

            dWorldStep(w, STEP);

            const dReal *v = dBodyGetLinearVel(b), *om = dBodyGetAngularVel(b);
            const double inertia = k < 2 ? 2 : 0.4;
            const double want = limited ? 0.2 * STEP / inertia : 1.5;
            const dReal tol = TOL(1e-9, 1e-5);
            CHECK_NEAR(k < 2 ? v[k] : om[2], want, tol);
            CHECK_NEAR(k == 0 ? 0 : v[0], 0, tol);
            CHECK_NEAR(k == 1 ? 0 : v[1], 0, tol);
            CHECK_NEAR(k == 2 ? 0 : om[2], 0, tol);
            dWorldDestroy(w);
        }
    }
    return 0;
}

static int test_plane2d_bad_input(void)
{
    dWorldID w = make_world(0);
    dJointID j = dJointCreatePlane2D(w, 0), h = dJointCreateHinge(w, 0);
    test_capture_reports();
    int n = 0;

    CHECK(dJointGetType(j) == dJointTypePlane2D);
    dJointSetPlane2DXParam(h, dParamVel, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("not the right type"));
    dJointSetPlane2DYParam(j, dParamVel2, 1);   // one group per motor
    CHECK(test_captured_count() == ++n && test_captured_contains("dJointSetPlane2DYParam"));
    dJointSetPlane2DAngleParam(j, dParamVel, NAN);
    CHECK(test_captured_count() == ++n && test_captured_contains("NaN"));
    dJointSetPlane2DXParam(NULL, dParamVel, 1);
    CHECK(test_captured_count() == ++n);
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

// ---- double ball ----------------------------------------------------------------

static int test_dball_getters_and_setters(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 3, 0, 1, 1, 1, 1, 1);
    turn_body(b1, 0, 1, 0, REAL(0.4));
    dJointID j = dJointCreateDBall(w, 0);
    dJointAttach(j, b1, b2);
    const dReal tol = TOL(1e-12, 1e-6);
    dVector3 v;

    CHECK(dJointGetType(j) == dJointTypeDBall);
    CHECK(dJointGetDBallParam(j, dParamERP) == dWorldGetERP(w));
    CHECK(dJointGetDBallParam(j, dParamCFM) == dWorldGetCFM(w));
    dJointSetDBallAnchor1(j, 1, 0, 0);
    CHECK_NEAR(dJointGetDBallDistance(j), dSqrt(5), tol);   // anchor 2 at the origin
    dJointSetDBallAnchor2(j, 2, 2, 0);
    CHECK_NEAR(dJointGetDBallDistance(j), dSqrt(5), tol);
    dJointSetDBallAnchor2(j, 1, 3, 0);
    CHECK_NEAR(dJointGetDBallDistance(j), 3, tol);
    dJointGetDBallAnchor1(j, v);
    CHECK_VEC(v, 1, 0, 0, tol);
    dJointGetDBallAnchor2(j, v);
    CHECK_VEC(v, 1, 3, 0, tol);
    dJointSetDBallDistance(j, REAL(2.5));
    CHECK(dJointGetDBallDistance(j) == REAL(2.5));
    dJointSetDBallParam(j, dParamERP, REAL(0.5));
    dJointSetDBallParam(j, dParamCFM, REAL(0.01));
    CHECK(dJointGetDBallParam(j, dParamERP) == REAL(0.5));
    CHECK(dJointGetDBallParam(j, dParamCFM) == REAL(0.01));
    CHECK(dJointGetDBallParam(j, dParamVel) == 0);

    // The anchors move with their bodies.
    dBodySetPosition(b2, 4, 0, 1);
    dJointGetDBallAnchor2(j, v);
    CHECK_VEC(v, 2, 3, 0, tol);
    dJointGetDBallAnchor1(j, v);
    CHECK_VEC(v, 1, 0, 0, tol);
    // Attaching again makes the distance the anchors' distance (as ODE does).
    dJointAttach(j, b1, b2);
    CHECK_NEAR(dJointGetDBallDistance(j), dSqrt(10), tol);

    // Attached as (0, b): anchor 2 is on b, anchor 1 in the world.
    dJointAttach(j, 0, b2);
    dJointSetDBallAnchor1(j, 0, 0, 5);
    dJointSetDBallAnchor2(j, 4, 0, 2);
    CHECK_NEAR(dJointGetDBallDistance(j), 5, tol);
    dBodySetPosition(b2, 4, 0, 0);
    dJointGetDBallAnchor1(j, v);
    CHECK_VEC(v, 0, 0, 5, tol);
    dJointGetDBallAnchor2(j, v);
    CHECK_VEC(v, 4, 0, 1, tol);
    dWorldDestroy(w);
    return 0;
}

// A chain: body 1 hangs from a world point by a rod of length 1 (anchors on
// the body 0.5 above its centre), body 2 from body 1 by a rod of length 1.5.
// Shaken under gravity for 10 s the rod lengths hold; the bodies swing and
// turn freely (the rods do not stop rotation about the anchors).
static int test_dball_keeps_distance(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = make_world(REAL(-9.81));
        dBodyID b1 = make_body(w, REAL(0.1), 0, 2, 1, REAL(0.1), REAL(0.1), REAL(0.1));
        dBodyID b2 = make_body(w, REAL(0.1), REAL(0.15), 0, 1, REAL(0.1), REAL(0.1), REAL(0.1));
        dJointID j1 = dJointCreateDBall(w, 0), j2 = dJointCreateDBall(w, 0);
        dJointAttach(j1, b1, 0);
        dJointSetDBallAnchor1(j1, REAL(0.1), 0, REAL(2.5));
        dJointSetDBallAnchor2(j1, 0, 0, REAL(3.5));
        dJointAttach(j2, b1, b2);
        dJointSetDBallAnchor1(j2, REAL(0.1), 0, REAL(1.5));
        dJointSetDBallAnchor2(j2, REAL(0.1), REAL(0.15), REAL(0.5));
        const double d1 = dJointGetDBallDistance(j1), d2 = dJointGetDBallDistance(j2);
        CHECK_NEAR(d1, sqrt(0.01 + 1), TOL(1e-12, 1e-6));
        CHECK_NEAR(d2, sqrt(0.0225 + 1), TOL(1e-12, 1e-6));
        double worst = 0, swing = 0;
        for (int i = 0; i < STEPS_10S; i++) {
            shake(b2, i, 1, REAL(0.1));
            steppers[s](w, STEP);
            dVector3 p, q;
            dJointGetDBallAnchor1(j1, p);
            dJointGetDBallAnchor2(j1, q);
            worst = fmax(worst, fabs(dist3(p, q) - d1));
            dJointGetDBallAnchor1(j2, p);
            dJointGetDBallAnchor2(j2, q);
            worst = fmax(worst, fabs(dist3(p, q) - d2));
            const dReal start[3] = { REAL(0.1), REAL(0.15), 0 };
            swing = fmax(swing, dist3(dBodyGetPosition(b2), start));
        }
        if (!(worst <= 1e-3)) {
            test_fail(__FILE__, __LINE__, "%s: distance error %g", stepper_names[s], worst);
            return 1;
        }
        // It swung: body 2 went far from where it started.
        CHECK(swing > 0.1);
        dWorldDestroy(w);
    }
    return 0;
}

// A body spinning about its own anchor point is not slowed: the row only
// acts along the rod.
static int test_dball_leaves_rotation_free(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateDBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetDBallAnchor1(j, 0, 0, 0);
    dJointSetDBallAnchor2(j, 0, 0, 2);
    dBodySetAngularVel(b, 1, 2, 3);
    for (int i = 0; i < 100; i++) dWorldStep(w, STEP);
    CHECK_VEC(dBodyGetAngularVel(b), 1, 2, 3, TOL(1e-9, 1e-5));
    CHECK_VEC(dBodyGetPosition(b), 0, 0, 0, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// A set distance is reached: the anchors move apart at ERP per step.
static int test_dball_set_distance_is_reached(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 1, 1, 1, 1, 1);
    dJointID j = dJointCreateDBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetDBallAnchor1(j, 0, 0, 1);
    dJointSetDBallAnchor2(j, 0, 0, 0);
    dJointSetDBallDistance(j, 2);
    dJointSetDBallParam(j, dParamERP, REAL(0.5));
    for (int i = 0; i < 60; i++) {
        dWorldStep(w, STEP);
        dBodySetLinearVel(b, 0, 0, 0);   // no overshoot from the velocity left over
    }
    CHECK_NEAR(dBodyGetPosition(b)[2], 2, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

static int test_dball_bad_input(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateDBall(w, 0), h = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetDBallAnchor2(j, 0, 0, 1);
    test_capture_reports();
    int n = 0;

    dJointSetDBallAnchor1(h, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("double ball"));
    CHECK(dJointGetDBallDistance(h) == 0 && test_captured_count() == ++n);
    dJointSetDBallAnchor1(j, NAN, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("anchor"));
    dJointSetDBallDistance(j, -1);
    CHECK(test_captured_count() == ++n && test_captured_contains("distance"));
    dJointSetDBallDistance(j, NAN);
    CHECK(test_captured_count() == ++n);
    CHECK_NEAR(dJointGetDBallDistance(j), 1, TOL(1e-12, 1e-6));
    dJointSetDBallParam(j, dParamERP + dParamGroup, REAL(0.5));
    CHECK(test_captured_count() == ++n && test_captured_contains("parameter"));
    dJointSetDBallParam(j, dParamERP, NAN);
    CHECK(test_captured_count() == ++n && test_captured_contains("NaN"));
    dJointGetDBallAnchor1(j, NULL);
    CHECK(test_captured_count() == ++n && test_captured_contains("result"));
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

// ---- double hinge ---------------------------------------------------------------

static int test_dhinge_getters_and_setters(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 0, 0, 2, 1, 1, 1, 1);
    turn_body(b1, 1, 0, 0, REAL(0.3));
    dJointID j = dJointCreateDHinge(w, 0);
    dJointAttach(j, b1, b2);
    const dReal tol = TOL(1e-12, 1e-6);
    dVector3 v;

    CHECK(dJointGetType(j) == dJointTypeDHinge);
    dJointGetDHingeAxis(j, v);
    CHECK_VEC(v, 0, 0, 0, 0);   // unset, as in ODE
    dJointSetDHingeAxis(j, 0, 2, 0);
    dJointGetDHingeAxis(j, v);
    CHECK_VEC(v, 0, 1, 0, tol);
    dJointSetDHingeAnchor1(j, 0, 0, REAL(0.5));
    dJointSetDHingeAnchor2(j, 0, 0, REAL(1.5));
    CHECK_NEAR(dJointGetDHingeDistance(j), 1, tol);
    dJointGetDHingeAnchor1(j, v);
    CHECK_VEC(v, 0, 0, 0.5, tol);
    dJointGetDHingeAnchor2(j, v);
    CHECK_VEC(v, 0, 0, 1.5, tol);
    // The double ball functions accept a double hinge (it is one).
    CHECK_NEAR(dJointGetDBallDistance(j), 1, tol);
    dJointSetDHingeParam(j, dParamERP, REAL(0.3));
    CHECK(dJointGetDHingeParam(j, dParamERP) == REAL(0.3));
    CHECK(dJointGetDBallParam(j, dParamERP) == REAL(0.3));
    // The axis turns with body 1.
    turn_body(b1, 0, 0, 1, (dReal)(M_PI / 2));
    dJointGetDHingeAxis(j, v);
    CHECK_VEC(v, -1, 0, 0, tol);
    dWorldDestroy(w);
    return 0;
}

// Body 1 hangs from the world by a double hinge with axis y (anchors 1 apart
// along z), body 2 from body 1 by one with axis x. Shaken under gravity for
// 10 s: the distances, the axes and the anchors' planes across the axes
// hold; the swings about the axes are free.
static int test_dhinge_keeps_distance_and_axis(void)
{
    for (int s = 0; s < 2; s++) {
        dWorldID w = make_world(REAL(-9.81));
        dBodyID b1 = make_body(w, 0, 0, 3, 1, REAL(0.1), REAL(0.1), REAL(0.1));
        dBodyID b2 = make_body(w, 0, 0, 1, 1, REAL(0.1), REAL(0.1), REAL(0.1));
        dBodySetLinearVel(b1, 1, 0, 0);
        dBodySetLinearVel(b2, 0, 1, 0);
        dJointID j1 = dJointCreateDHinge(w, 0), j2 = dJointCreateDHinge(w, 0);
        dJointAttach(j1, b1, 0);
        dJointSetDHingeAxis(j1, 0, 1, 0);
        dJointSetDHingeAnchor1(j1, 0, 0, REAL(3.5));
        dJointSetDHingeAnchor2(j1, 0, 0, REAL(4.5));
        dJointAttach(j2, b1, b2);
        dJointSetDHingeAxis(j2, 1, 0, 0);
        dJointSetDHingeAnchor1(j2, 0, 0, REAL(2.5));
        dJointSetDHingeAnchor2(j2, 0, 0, REAL(1.5));
        const dJointID js[2] = { j1, j2 };
        const dBodyID other[2] = { NULL, b1 };
        const dBodyID self[2] = { b1, b2 };
        const dReal local_axis[2][3] = { { 0, 1, 0 }, { 1, 0, 0 } };
        double worst_d = 0, worst_axis = 0, worst_plane = 0, swing = 0;
        for (int i = 0; i < STEPS_10S; i++) {
            shake(b2, i, 1, REAL(0.05));
            steppers[s](w, STEP);
            for (int k = 0; k < 2; k++) {
                dVector3 p, q, ax, ax2, sep;
                dJointGetDHingeAnchor1(js[k], p);
                dJointGetDHingeAnchor2(js[k], q);
                worst_d = fmax(worst_d, fabs(dist3(p, q) - 1));
                dJointGetDHingeAxis(js[k], ax);
                // The axis fixed in the other body (or the world) at set time.
                if (other[k])
                    dBodyVectorToWorld(other[k], local_axis[k][0], local_axis[k][1],
                                       local_axis[k][2], ax2);
                else
                    dCopyVector3(ax2, local_axis[k]);
                worst_axis = fmax(worst_axis, angle_between(ax, ax2));
                dSubtractVectors3(sep, p, q);
                worst_plane = fmax(worst_plane, fabs(dot3(sep, ax)));
            }
            dVector3 down;
            body_dir(self[0], 0, 0, 1, down);
            swing = fmax(swing, angle_between(down, (dReal[3]){ 0, 0, 1 }));
        }
        if (!(worst_d <= 1e-3 && worst_axis <= 1e-3 && worst_plane <= 1e-3)) {
            test_fail(__FILE__, __LINE__, "%s: distance %g, axis %g, plane %g",
                      stepper_names[s], worst_d, worst_axis, worst_plane);
            return 1;
        }
        CHECK(swing > 0.1);
        dWorldDestroy(w);
    }
    return 0;
}

static int test_dhinge_bad_input(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateDHinge(w, 0), d = dJointCreateDBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetDHingeAxis(j, 0, 0, 1);
    dVector3 v;
    test_capture_reports();
    int n = 0;

    dJointSetDHingeAxis(d, 0, 0, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("not the right type"));
    dJointSetDHingeAnchor1(d, 0, 0, 1);
    CHECK(test_captured_count() == ++n);
    dJointSetDHingeAxis(j, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("no direction"));
    dJointSetDHingeAxis(j, NAN, 0, 1);
    CHECK(test_captured_count() == ++n);
    dJointGetDHingeAxis(j, v);
    CHECK_VEC(v, 0, 0, 1, 0);
    dJointGetDHingeAxis(j, NULL);
    CHECK(test_captured_count() == ++n && test_captured_contains("result"));
    dJointSetDHingeParam(j, dParamCFM2, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("parameter"));
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

// ---- transmission ---------------------------------------------------------------

// Two wheels, each on a hinge to the world at its anchor about its axis;
// wheel 1 is driven by its hinge motor at `rate` (rad/s about its axis).
typedef struct gearbox {
    dWorldID w;
    dBodyID wheel[2];
    dJointID hinge[2], t;
} gearbox;

static void make_gearbox(gearbox *g, int mode, const dReal a[2][3], const dReal n[2][3],
                         dReal rate)
{
    g->w = make_world(0);
    g->t = dJointCreateTransmission(g->w, 0);
    for (int i = 0; i < 2; i++) {
        g->wheel[i] = make_body(g->w, a[i][0], a[i][1], a[i][2], 1, REAL(0.2), REAL(0.2),
                                REAL(0.2));
        g->hinge[i] = dJointCreateHinge(g->w, 0);
        dJointAttach(g->hinge[i], g->wheel[i], 0);
        dJointSetHingeAnchor(g->hinge[i], a[i][0], a[i][1], a[i][2]);
        dJointSetHingeAxis(g->hinge[i], n[i][0], n[i][1], n[i][2]);
    }
    dJointSetHingeParam(g->hinge[0], dParamVel, rate);
    dJointSetHingeParam(g->hinge[0], dParamFMax, 1000);
    dJointAttach(g->t, g->wheel[0], g->wheel[1]);
    dJointSetTransmissionMode(g->t, mode);
    dJointSetTransmissionAnchor1(g->t, a[0][0], a[0][1], a[0][2]);
    dJointSetTransmissionAnchor2(g->t, a[1][0], a[1][1], a[1][2]);
    if (mode == dTransmissionIntersectingAxes) {
        dJointSetTransmissionAxis1(g->t, n[0][0], n[0][1], n[0][2]);
        dJointSetTransmissionAxis2(g->t, n[1][0], n[1][1], n[1][2]);
    } else {
        dJointSetTransmissionAxis(g->t, n[0][0], n[0][1], n[0][2]);
    }
}

// The difference of the wheels' arc lengths, r1 phase1 - sense r2 phase2,
// where sense is +1 if the wheels turn the same way about their axes (a
// chain; the bevel gears below), -1 if opposite ways (parallel gears); zero
// when the drive holds.
static double arc_difference(dJointID t, double sense)
{
    double a = dJointGetTransmissionRadius1(t) * dJointGetTransmissionAngle1(t);
    double b = dJointGetTransmissionRadius2(t) * dJointGetTransmissionAngle2(t);
    return a - sense * b;
}

// Each mode, each stepper: wheel 1 driven at 1 rad/s for 10 s; wheel 2 turns
// at -ratio (parallel gears) or +ratio (bevel gears, chain) times its rate, and the phases keep
// the arc lengths equal. The wheels start at those rates (an impulsive start
// is a different test: QuickStep's 20 iterations take a few steps there).
static int test_transmission_keeps_ratio_in_every_mode(void)
{
    const dReal par_a[2][3] = { { 1, 0, 1 }, { -1, 0, 1 } };
    const dReal par_n[2][3] = { { 0, 0, 1 }, { 0, 0, 1 } };
    // Planes z = 0 and x = 1: turning +1 about z, wheel 1 moves the contact
    // point (1, 0, 0) along +y, as wheel 2 does turning +1/2 about x.
    const dReal bev_a[2][3] = { { 0, 0, 0 }, { 1, 0, 2 } };
    const dReal bev_n[2][3] = { { 0, 0, 1 }, { 1, 0, 0 } };
    const dReal chain_a[2][3] = { { 2, 0, 1 }, { -2, 0, 1 } };
    const dReal chain_n[2][3] = { { 0, 0, 1 }, { 0, 0, 1 } };
    for (int mode = 0; mode < 3; mode++) {
        for (int s = 0; s < 2; s++) {
            gearbox g;
            const dReal(*a)[3] = mode == 0 ? par_a : mode == 1 ? bev_a : chain_a;
            const dReal(*n)[3] = mode == 0 ? par_n : mode == 1 ? bev_n : chain_n;
            make_gearbox(&g, mode, a, n, 1);
            double ratio, r1, r2;
            if (mode == dTransmissionParallelAxes) {
                dJointSetTransmissionRatio(g.t, 2);
                ratio = 2, r1 = 4.0 / 3, r2 = 2.0 / 3;
            } else if (mode == dTransmissionIntersectingAxes) {
                ratio = 0.5, r1 = 1, r2 = 2;   // contact at (1, 0, 0)
            } else {
                dJointSetTransmissionRadius1(g.t, REAL(0.5));
                dJointSetTransmissionRadius2(g.t, 1);
                ratio = 0.5, r1 = 0.5, r2 = 1;
            }
            const double sense = mode == dTransmissionParallelAxes ? -1 : 1;
            dBodySetAngularVel(g.wheel[0], n[0][0], n[0][1], n[0][2]);
            const dReal w2 = (dReal)(sense * ratio);
            dBodySetAngularVel(g.wheel[1], w2 * n[1][0], w2 * n[1][1], w2 * n[1][2]);
            double worst_arc = 0, worst_rate = 0;
            for (int i = 0; i < STEPS_10S; i++) {
                steppers[s](g.w, STEP);
                worst_arc = fmax(worst_arc, fabs(arc_difference(g.t, sense)));
                const double w1 = dot3(dBodyGetAngularVel(g.wheel[0]), n[0]);
                const double w2 = dot3(dBodyGetAngularVel(g.wheel[1]), n[1]);
                worst_rate = fmax(worst_rate, fabs(w2 - sense * ratio * w1));
            }
            CHECK_NEAR(dJointGetTransmissionRatio(g.t), ratio, TOL(1e-12, 1e-6));
            CHECK_NEAR(dJointGetTransmissionRadius1(g.t), r1, TOL(1e-12, 1e-6));
            CHECK_NEAR(dJointGetTransmissionRadius2(g.t), r2, TOL(1e-12, 1e-6));
            // Wheel 1 turned 10 rad positively: its phase went down by as much.
            // (Phases are tracked as a step starts: they lag by one step.)
            CHECK_NEAR(dJointGetTransmissionAngle1(g.t), -(10 - STEP), 2e-3);
            if (!(worst_arc <= 1e-3 && worst_rate <= 1e-3)) {
                test_fail(__FILE__, __LINE__, "mode %d, %s: arc %g, rate %g", mode,
                          stepper_names[s], worst_arc, worst_rate);
                return 1;
            }
            dWorldDestroy(g.w);
        }
    }
    return 0;
}

// Parallel gears (ratio 1, radii 1) with backlash b: wheel 2, braked by a
// little friction, stays still until wheel 1 has turned through the arc b,
// then follows at the arc difference b. Reversed, wheel 2 turns back only
// once the arc difference has crossed the play to -b... +b on the other side.
static int test_transmission_backlash_is_free_play(void)
{
    const dReal a[2][3] = { { 1, 0, 0 }, { -1, 0, 0 } };
    const dReal n[2][3] = { { 0, 0, 1 }, { 0, 0, 1 } };
    const dReal b = REAL(0.1), rate = REAL(0.05);
    for (int s = 0; s < 2; s++) {
        gearbox g;
        make_gearbox(&g, dTransmissionParallelAxes, a, n, rate);
        dJointSetHingeParam(g.hinge[1], dParamFMax, REAL(0.1));   // friction: a motor at 0
        dJointSetTransmissionBacklash(g.t, b);
        int engaged_at = -1;
        for (int i = 0; i < 400; i++) {
            const double arc = arc_difference(g.t, -1);
            steppers[s](g.w, STEP);
            const double w2 = dBodyGetAngularVel(g.wheel[1])[2];
            if (engaged_at < 0 && fabs(w2) > 1e-6) {
                engaged_at = i;
                CHECK_NEAR(arc, -b, 1e-3);
            }
        }
        // Wheel 1 turns 0.0005 rad per step: the arc b takes 200 steps.
        if (!(engaged_at >= 199 && engaged_at <= 202)) {
            test_fail(__FILE__, __LINE__, "%s: engaged at step %d", stepper_names[s],
                      engaged_at);
            return 1;
        }
        CHECK_NEAR(arc_difference(g.t, -1), -b, 1e-3);
        CHECK_NEAR(dBodyGetAngularVel(g.wheel[1])[2], -rate, 1e-3);

        // Back the other way: wheel 2 stops, and turns back once the play is crossed.
        dJointSetHingeParam(g.hinge[0], dParamVel, -rate);
        engaged_at = -1;
        for (int i = 0; i < 600; i++) {
            const double arc = arc_difference(g.t, -1);
            steppers[s](g.w, STEP);
            const double w2 = dBodyGetAngularVel(g.wheel[1])[2];
            if (engaged_at < 0 && w2 > 1e-6) {
                engaged_at = i;
                CHECK_NEAR(arc, b, 1e-3);
            }
        }
        // About the whole play 2 b (400 steps) was crossed.
        if (!(engaged_at >= 390)) {
            test_fail(__FILE__, __LINE__, "%s: engaged back at step %d", stepper_names[s],
                      engaged_at);
            return 1;
        }
        CHECK_NEAR(arc_difference(g.t, -1), b, 1e-3);
        CHECK_NEAR(dBodyGetAngularVel(g.wheel[1])[2], rate, 1e-3);
        dWorldDestroy(g.w);
    }
    return 0;
}

static int test_transmission_getters_and_setters(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 1, 0, 0, 1, 1, 1, 1), b2 = make_body(w, -1, 0, 0, 1, 1, 1, 1);
    turn_body(b1, 0, 1, 0, REAL(0.3));
    dJointID t = dJointCreateTransmission(w, 0);
    const dReal tol = TOL(1e-12, 1e-6);
    dVector3 v;

    CHECK(dJointGetType(t) == dJointTypeTransmission);
    CHECK(dJointGetTransmissionMode(t) == dTransmissionParallelAxes);
    CHECK(dJointGetTransmissionRatio(t) == 1);
    CHECK(dJointGetTransmissionBacklash(t) == 0);
    CHECK(dJointGetTransmissionRadius1(t) == 0 && dJointGetTransmissionRadius2(t) == 0);
    CHECK(dJointGetTransmissionAngle1(t) == 0 && dJointGetTransmissionAngle2(t) == 0);
    CHECK(dJointGetTransmissionParam(t, dParamERP) == dWorldGetERP(w));
    CHECK(dJointGetTransmissionParam(t, dParamCFM) == dWorldGetCFM(w));
    dJointAttach(t, b1, b2);
    dJointSetTransmissionAnchor1(t, 1, 1, 0);
    dJointSetTransmissionAnchor2(t, -1, 1, 0);
    dJointSetTransmissionAxis(t, 0, 0, 3);
    dJointSetTransmissionRatio(t, 3);
    dJointSetTransmissionBacklash(t, REAL(0.25));
    dJointSetTransmissionParam(t, dParamERP, REAL(0.4));
    dJointSetTransmissionParam(t, dParamCFM, REAL(0.001));
    dJointGetTransmissionAnchor1(t, v);
    CHECK_VEC(v, 1, 1, 0, tol);
    dJointGetTransmissionAnchor2(t, v);
    CHECK_VEC(v, -1, 1, 0, tol);
    dJointGetTransmissionAxis(t, v);
    CHECK_VEC(v, 0, 0, 1, tol);
    dJointGetTransmissionAxis1(t, v);
    CHECK_VEC(v, 0, 0, 1, tol);
    dJointGetTransmissionAxis2(t, v);
    CHECK_VEC(v, 0, 0, 1, tol);
    CHECK(dJointGetTransmissionRatio(t) == 3);
    CHECK(dJointGetTransmissionBacklash(t) == REAL(0.25));
    CHECK(dJointGetTransmissionParam(t, dParamERP) == REAL(0.4));
    CHECK(dJointGetTransmissionParam(t, dParamCFM) == REAL(0.001));
    CHECK(dJointGetTransmissionParam(t, dParamVel) == 0);

    // The first step places the contact point at 3/4 of the way to anchor 2.
    dWorldStep(w, STEP);
    dJointGetTransmissionContactPoint1(t, v);
    CHECK_VEC(v, -0.5, 1, 0, tol);
    dJointGetTransmissionContactPoint2(t, v);
    CHECK_VEC(v, -0.5, 1, 0, tol);
    CHECK_NEAR(dJointGetTransmissionRadius1(t), 1.5, tol);
    CHECK_NEAR(dJointGetTransmissionRadius2(t), 0.5, tol);
    CHECK_NEAR(dJointGetTransmissionRatio(t), 3, tol);

    dJointSetTransmissionMode(t, dTransmissionChainDrive);
    dJointSetTransmissionRadius1(t, REAL(0.7));
    dJointSetTransmissionRadius2(t, REAL(0.2));
    CHECK(dJointGetTransmissionRadius1(t) == REAL(0.7));
    CHECK(dJointGetTransmissionRadius2(t) == REAL(0.2));
    dJointSetTransmissionMode(t, dTransmissionIntersectingAxes);
    CHECK(dJointGetTransmissionMode(t) == dTransmissionIntersectingAxes);
    dJointSetTransmissionAxis1(t, 0, 0, 1);
    dJointSetTransmissionAxis2(t, 0, 1, 0);
    dJointGetTransmissionAxis1(t, v);
    CHECK_VEC(v, 0, 0, 1, tol);
    dJointGetTransmissionAxis2(t, v);
    CHECK_VEC(v, 0, 1, 0, tol);
    dWorldDestroy(w);
    return 0;
}

static int test_transmission_bad_input(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 1, 0, 0, 1, 1, 1, 1), b2 = make_body(w, -1, 0, 0, 1, 1, 1, 1);
    dJointID t = dJointCreateTransmission(w, 0), h = dJointCreateHinge(w, 0);
    dJointAttach(t, b1, b2);
    dVector3 v;
    test_capture_reports();
    int n = 0;

    dJointSetTransmissionRatio(h, 2);
    CHECK(test_captured_count() == ++n && test_captured_contains("not the right type"));
    dJointSetTransmissionMode(t, 3);
    CHECK(test_captured_count() == ++n && test_captured_contains("mode"));
    CHECK(dJointGetTransmissionMode(t) == dTransmissionParallelAxes);
    dJointSetTransmissionRatio(t, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("ratio"));
    dJointSetTransmissionRatio(t, NAN);
    CHECK(test_captured_count() == ++n);
    dJointSetTransmissionRadius1(t, 1);   // not in chain mode
    CHECK(test_captured_count() == ++n && test_captured_contains("geometry"));
    dJointSetTransmissionAxis1(t, 0, 0, 1);   // not in intersecting mode
    CHECK(test_captured_count() == ++n && test_captured_contains("one by one"));
    dJointSetTransmissionAxis(t, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("no direction"));
    dJointSetTransmissionAnchor1(t, 0, NAN, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("anchor"));
    dJointSetTransmissionBacklash(t, -1);
    CHECK(test_captured_count() == ++n && test_captured_contains("backlash"));
    dJointSetTransmissionParam(t, dParamERP2, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("parameter"));
    dJointSetTransmissionParam(t, dParamERP, NAN);
    CHECK(test_captured_count() == ++n);
    dJointSetTransmissionMode(t, dTransmissionChainDrive);
    dJointSetTransmissionRadius1(t, -1);
    CHECK(test_captured_count() == ++n && test_captured_contains("radius"));
    dJointSetTransmissionRadius2(t, 0);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetTransmissionRadius1(t) == 0);
    dJointGetTransmissionAxis(t, v);   // parallel mode only
    CHECK(test_captured_count() == ++n);
    dJointGetTransmissionContactPoint1(t, NULL);
    CHECK(test_captured_count() == ++n && test_captured_contains("result"));
    dJointAttach(t, b1, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("two bodies"));
    test_release_reports();
    // Attached to one body, or with a degenerate geometry (chain radii
    // unset), it adds no rows and the step goes on.
    dWorldStep(w, STEP);
    dJointAttach(t, b1, b2);
    dWorldStep(w, STEP);
    dWorldQuickStep(w, STEP);
    CHECK(isfinite(dBodyGetPosition(b1)[0]) && isfinite(dBodyGetAngularVel(b2)[2]));
    dWorldDestroy(w);
    return 0;
}

// Bevel gears whose axes are parallel to within rounding (as a tumbling
// pair may turn them) have no line where their planes meet: the joint gives
// no row and the wheels keep their rates, under every stepper. (The planes'
// meeting point came out NaN, which a fuzzed world spread to both bodies.)
static int test_transmission_bevel_gears_turned_parallel_act_no_more(void)
{
    for (int stepper = 0; stepper < 3; stepper++) {
        test_capture_reports();
        dWorldID w = make_world(0);
        dBodyID a = make_body(w, 0, 0, 0, 1, REAL(0.2), REAL(0.2), REAL(0.2));
        dBodyID b = make_body(w, 0, 1, REAL(0.5), 1, REAL(0.2), REAL(0.2), REAL(0.2));
        dBodySetAngularVel(a, REAL(0.3), 0, 0);   // about its axis: the axes stay parallel
        dJointID t = dJointCreateTransmission(w, 0);
        dJointAttach(t, a, b);
        dJointSetTransmissionMode(t, dTransmissionIntersectingAxes);
        dJointSetTransmissionAnchor1(t, 0, 0, 0);
        dJointSetTransmissionAnchor2(t, 0, 1, REAL(0.5));
        dJointSetTransmissionAxis1(t, 1, 0, 0);
        dJointSetTransmissionAxis2(t, 1, REAL(1e-9), 0);
        for (int i = 0; i < 10; i++) {
            if (stepper == 0) dWorldStep(w, STEP);
            else if (stepper == 1) dWorldQuickStep(w, STEP);
            else dWorldStepFast1(w, STEP, 5);
        }
        const dReal *wa = dBodyGetAngularVel(a), *wb = dBodyGetAngularVel(b);
        CHECK_VEC(wa, 0.3, 0, 0, TOL(1e-12, 1e-6));
        CHECK_VEC(wb, 0, 0, 0, 1e-12);
        CHECK(test_captured_count() == 0);
        test_release_reports();
        dWorldDestroy(w);
    }
    return 0;
}

// The five joints under dWorldStepFast1 (rows filled once per sub-step):
// a gear pair, a double pendulum of a double ball and a double hinge, a
// body on a plane-2D joint with a linear motor; 2 s, the constraints hold
// to the looser accuracy of that stepper.
static int test_all_joints_under_stepfast1(void)
{
    const dReal a[2][3] = { { 1, 0, 1 }, { -1, 0, 1 } };
    const dReal n[2][3] = { { 0, 0, 1 }, { 0, 0, 1 } };
    gearbox g;
    make_gearbox(&g, dTransmissionParallelAxes, a, n, 1);
    dWorldSetGravity(g.w, 0, 0, REAL(-9.81));
    dBodyID p1 = make_body(g.w, 5, 0, 2, 1, REAL(0.1), REAL(0.1), REAL(0.1));
    dBodyID p2 = make_body(g.w, REAL(5.1), 0, 1, 1, REAL(0.1), REAL(0.1), REAL(0.1));
    dJointID db = dJointCreateDBall(g.w, 0), dh = dJointCreateDHinge(g.w, 0);
    dJointAttach(db, p1, 0);
    dJointSetDBallAnchor1(db, 5, 0, 2);
    dJointSetDBallAnchor2(db, REAL(5.2), 0, 3);
    dJointAttach(dh, p2, p1);
    dJointSetDHingeAxis(dh, 0, 1, 0);
    dJointSetDHingeAnchor1(dh, REAL(5.1), 0, 1);
    dJointSetDHingeAnchor2(dh, 5, 0, 2);
    dBodyID slab = make_body(g.w, -5, 0, 0, 1, REAL(0.1), REAL(0.1), REAL(0.1));
    dJointID pl = dJointCreatePlane2D(g.w, 0), lm = dJointCreateLMotor(g.w, 0);
    dJointAttach(pl, slab, 0);
    dJointAttach(lm, slab, 0);
    dJointSetLMotorNumAxes(lm, 1);
    dJointSetLMotorAxis(lm, 0, 0, 1, 1, 0);
    dJointSetLMotorParam(lm, dParamVel, 1);
    dJointSetLMotorParam(lm, dParamFMax, 100);
    for (int i = 0; i < 200; i++) dWorldStepFast1(g.w, STEP, 20);
    dVector3 p, q;
    dJointGetDBallAnchor1(db, p);
    dJointGetDBallAnchor2(db, q);
    CHECK_NEAR(dist3(p, q), dJointGetDBallDistance(db), 1e-2);
    dJointGetDHingeAnchor1(dh, p);
    dJointGetDHingeAnchor2(dh, q);
    CHECK_NEAR(dist3(p, q), dJointGetDHingeDistance(dh), 1e-2);
    CHECK_NEAR(dBodyGetPosition(slab)[2], 0, 1e-2);
    CHECK_NEAR(dot3(dBodyGetLinearVel(slab), (dReal[3]){ 1, 1, 0 }) / sqrt(2.0), 1, 1e-2);
    CHECK_NEAR(dBodyGetAngularVel(g.wheel[1])[2], -1, 1e-2);
    dWorldDestroy(g.w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_lmotor_defaults_and_axes),
    TEST_CASE(test_lmotor_param_groups_route_to_axes),
    TEST_CASE(test_lmotor_reaches_velocity_in_one_step),
    TEST_CASE(test_lmotor_limited_by_fmax),
    TEST_CASE(test_lmotor_other_directions_are_free),
    TEST_CASE(test_lmotor_reversed_attach_keeps_user_order),
    TEST_CASE(test_lmotor_bad_input),
    TEST_CASE(test_plane2d_holds_plane_frees_the_rest),
    TEST_CASE(test_plane2d_pulls_back_to_the_plane),
    TEST_CASE(test_plane2d_motors),
    TEST_CASE(test_plane2d_bad_input),
    TEST_CASE(test_dball_getters_and_setters),
    TEST_CASE(test_dball_keeps_distance),
    TEST_CASE(test_dball_leaves_rotation_free),
    TEST_CASE(test_dball_set_distance_is_reached),
    TEST_CASE(test_dball_bad_input),
    TEST_CASE(test_dhinge_getters_and_setters),
    TEST_CASE(test_dhinge_keeps_distance_and_axis),
    TEST_CASE(test_dhinge_bad_input),
    TEST_CASE(test_transmission_getters_and_setters),
    TEST_CASE(test_transmission_keeps_ratio_in_every_mode),
    TEST_CASE(test_transmission_backlash_is_free_play),
    TEST_CASE(test_transmission_bad_input),
    TEST_CASE(test_transmission_bevel_gears_turned_parallel_act_no_more),
    TEST_CASE(test_all_joints_under_stepfast1),
    TEST_END
};
