// SPDX-License-Identifier: BSD-3-Clause
//
// test_joints_b.c -- the hinge-2 joint and the angular motor (guide 7.3.5 and
// the AMotor section): geometry getters, angles against known rotations,
// rates against finite differences, suspension, stops and motors in the
// stepper, the user's body order, and bad input.

#include "test.h"

#include <math.h>

static const dReal STEP = REAL(0.01);

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

static void turn_body_v(dBodyID b, const dReal *axis, dReal angle)
{
    turn_body(b, axis[0], axis[1], axis[2], angle);
}

// Turn b by its angular velocity over dt (an exact rotation).
static void spin_body(dBodyID b, dReal dt)
{
    const dReal *w = dBodyGetAngularVel(b);
    dReal n = dSqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (n > 0) turn_body(b, w[0], w[1], w[2], n * dt);
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

// An angle of joint j: a getter, with the axis number for the angular motor.
typedef struct angle_getter {
    dReal (*hinge2)(dJointID);
    int anum;
} angle_getter;

static dReal get_angle(dJointID j, angle_getter g)
{
    return g.hinge2 ? g.hinge2(j) : dJointGetAMotorAngle(j, g.anum);
}

// d(angle)/dt by a central difference: both bodies turned by their angular
// velocities over -dt and +dt, then put back.
static double central_difference(dJointID j, dBodyID b1, dBodyID b2, angle_getter g, dReal dt)
{
    dQuaternion q1, q2;
    dCopyVector4(q1, dBodyGetQuaternion(b1));
    dCopyVector4(q2, dBodyGetQuaternion(b2));
    spin_body(b1, dt);
    spin_body(b2, dt);
    double plus = get_angle(j, g);
    dBodySetQuaternion(b1, q1);
    dBodySetQuaternion(b2, q2);
    spin_body(b1, -dt);
    spin_body(b2, -dt);
    double minus = get_angle(j, g);
    dBodySetQuaternion(b1, q1);
    dBodySetQuaternion(b2, q2);
    return (plus - minus) / (2 * (double)dt);
}

// Finite-difference step and tolerance: truncation error dt^2/6 |angle'''|
// (angular speeds ~1 rad/s: ~1e-13 / ~2e-6) plus rounding eps / dt
// (~1e-10 in double, ~3e-5 in single).
#define FD_DT TOL(1e-6, 3e-3)
#define FD_TOL TOL(1e-7, 1e-3)

// ---- hinge-2: geometry ---------------------------------------------------------

// A chassis (body 1) and a wheel (body 2), anchor at the wheel centre,
// steering axis z, wheel axis y. The chassis is kinematic if asked.
typedef struct car_wheel {
    dWorldID w;
    dBodyID chassis, wheel;
    dJointID j;
} car_wheel;

static void make_car_wheel(car_wheel *c, dReal gravity_z, int kinematic_chassis)
{
    c->w = make_world(gravity_z);
    c->chassis = make_body(c->w, 0, 0, 0, 5, 1, 1, 1);
    c->wheel = make_body(c->w, 0, REAL(0.6), 0, 1, REAL(0.2), REAL(0.4), REAL(0.2));
    if (kinematic_chassis) dBodySetKinematic(c->chassis);
    c->j = dJointCreateHinge2(c->w, 0);
    dJointAttach(c->j, c->chassis, c->wheel);
    dJointSetHinge2Anchor(c->j, 0, REAL(0.6), 0);
    const dReal a1[3] = { 0, 0, 1 }, a2[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(c->j, a1, a2);
}

static int test_hinge2_defaults_and_getters(void)
{
    dWorldID w = make_world(0);
    dWorldSetERP(w, REAL(0.3));
    dWorldSetCFM(w, REAL(1e-6));
    dBodyID b1 = make_body(w, 1, 2, 3, 1, 1, 1, 1), b2 = make_body(w, 1, 2, 2, 1, 1, 1, 1);
    dJointID j = dJointCreateHinge2(w, 0);
    dVector3 v;

    CHECK(dJointGetType(j) == dJointTypeHinge2);
    // ODE 0.16's default axes: x on body 1, y on body 2; suspension from the world.
    dJointAttach(j, b1, b2);
    dJointGetHinge2Axis1(j, v);
    CHECK(v[0] == 1 && v[1] == 0 && v[2] == 0);
    dJointGetHinge2Axis2(j, v);
    CHECK(v[0] == 0 && v[1] == 1 && v[2] == 0);
    CHECK_NEAR(dJointGetHinge2Param(j, dParamSuspensionERP), 0.3, TOL(1e-15, 1e-7));
    CHECK_NEAR(dJointGetHinge2Param(j, dParamSuspensionCFM), 1e-6, TOL(1e-20, 1e-12));
    CHECK(dJointGetHinge2Param(j, dParamLoStop) == -dInfinity);
    CHECK(dJointGetHinge2Param(j, dParamHiStop2) == dInfinity);
    CHECK(dJointGetHinge2Param(j, dParamFMax2) == 0);

    dJointSetHinge2Anchor(j, 1, 2, REAL(2.5));
    dJointSetHinge2Axis1(j, 0, 0, 3);   // normalised
    dJointSetHinge2Axis2(j, 2, 0, 0);
    dJointGetHinge2Anchor(j, v);
    CHECK(dist3(v, (dReal[3]){ 1, 2, 2.5 }) < 1e-12);
    dJointGetHinge2Anchor2(j, v);
    CHECK(dist3(v, (dReal[3]){ 1, 2, 2.5 }) < 1e-12);
    dJointGetHinge2Axis1(j, v);
    CHECK(dist3(v, (dReal[3]){ 0, 0, 1 }) < 1e-12);
    dJointGetHinge2Axis2(j, v);
    CHECK(dist3(v, (dReal[3]){ 1, 0, 0 }) < 1e-12);
    CHECK(dJointGetHinge2Angle1(j) == 0);
    CHECK(dJointGetHinge2Angle2(j) == 0);

    // Anchors and axes move with their bodies: axis 1 and anchor 1 with body 1.
    turn_body(b1, 1, 0, 0, (dReal)(M_PI / 2));   // z -> -y, and (0,0,-0.5) -> (0,0.5,0)
    dJointGetHinge2Axis1(j, v);
    CHECK(dist3(v, (dReal[3]){ 0, -1, 0 }) < TOL(1e-12, 1e-6));
    dJointGetHinge2Anchor(j, v);
    CHECK(dist3(v, (dReal[3]){ 1, 2.5, 3 }) < TOL(1e-12, 1e-6));
    dJointGetHinge2Axis2(j, v);
    CHECK(dist3(v, (dReal[3]){ 1, 0, 0 }) < 1e-12);

    // Parameters of both groups; a known parameter the joint does not use
    // (suspension of group 2) has no effect and is not an error.
    test_capture_reports();
    dJointSetHinge2Param(j, dParamSuspensionERP, REAL(0.5));
    dJointSetHinge2Param(j, dParamSuspensionCFM, REAL(0.01));
    dJointSetHinge2Param(j, dParamVel2, 4);
    dJointSetHinge2Param(j, dParamLoStop2, -1);
    dJointSetHinge2Param(j, dParamSuspensionERP2, REAL(0.9));
    CHECK(test_captured_count() == 0);
    CHECK(dJointGetHinge2Param(j, dParamSuspensionERP) == REAL(0.5));
    CHECK(dJointGetHinge2Param(j, dParamSuspensionCFM) == REAL(0.01));
    CHECK(dJointGetHinge2Param(j, dParamVel2) == 4);
    CHECK(dJointGetHinge2Param(j, dParamVel) == 0);
    CHECK(dJointGetHinge2Param(j, dParamLoStop2) == -1);
    CHECK(dJointGetHinge2Param(j, dParamSuspensionERP2) == 0);

    // Unattached: setters do nothing, getters answer without bodies.
    dJointID u = dJointCreateHinge2(w, 0);
    dJointSetHinge2Anchor(u, 5, 5, 5);
    dJointGetHinge2Anchor(u, v);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == 0);
    CHECK(dJointGetHinge2Angle1(u) == 0 && dJointGetHinge2Angle2Rate(u) == 0);
    dWorldDestroy(w);
    return 0;
}

// Body 2 steered by -phi about axis 1 and spun by -psi about axis 2 (body 1
// held) is body 1 turned by +phi about axis 1 and +psi about axis 2 relative
// to body 2: Angle1 = phi, Angle2 = psi, with any axes and body frames.
static int test_hinge2_angles_follow_known_rotations(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 0, 0, -1, 1, 1, 1, 1);
    turn_body(b1, 1, 2, 3, REAL(0.7));
    turn_body(b2, -2, 1, REAL(0.5), REAL(1.1));
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetHinge2Anchor(j, 0, 0, REAL(-0.5));
    const dReal axis1[3] = { 0, REAL(0.5), 1 }, axis2[3] = { 1, REAL(0.2), 0 };   // 85 degrees
    dJointSetHinge2Axes(j, axis1, axis2);
    dVector3 a1, a2;
    dJointGetHinge2Axis1(j, a1);
    dJointGetHinge2Axis2(j, a2);
    dQuaternion q2;
    dCopyVector4(q2, dBodyGetQuaternion(b2));

    const dReal cases[][2] = { { REAL(0.3), 0 },  { 0, REAL(-0.4) },   { REAL(1.2), REAL(2.5) },
                               { -2, -3 },  { REAL(-0.1), 3 } };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        dReal phi = cases[k][0], psi = cases[k][1];
        dBodySetQuaternion(b2, q2);
        turn_body_v(b2, a2, -psi);   // wheel spin first, about the set-time wheel axis
        turn_body_v(b2, a1, -phi);   // then steering
        CHECK_NEAR(dJointGetHinge2Angle1(j), phi, TOL(1e-12, 2e-6));
        CHECK_NEAR(dJointGetHinge2Angle2(j), psi, TOL(1e-12, 2e-6));
        // The same relative pose anywhere: turn both bodies together.
        turn_body(b1, 3, -1, 2, REAL(0.9));
        turn_body(b2, 3, -1, 2, REAL(0.9));
        CHECK_NEAR(dJointGetHinge2Angle1(j), phi, TOL(1e-12, 2e-6));
        CHECK_NEAR(dJointGetHinge2Angle2(j), psi, TOL(1e-12, 2e-6));
        turn_body(b1, 3, -1, 2, REAL(-0.9));
    }
    dWorldDestroy(w);
    return 0;
}

// The rates are the time derivatives of the angles, for any angular
// velocities and for axes that are not perpendicular.
static int test_hinge2_rates_match_finite_differences(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 0, 0, -1, 1, 1, 1, 1);
    turn_body(b1, 1, -1, 2, REAL(0.4));
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, b1, b2);
    const dReal axis1[3] = { REAL(0.3), 0, 1 }, axis2[3] = { 0, 1, REAL(0.4) };
    dJointSetHinge2Axes(j, axis1, axis2);
    turn_body(b2, 1, 2, 3, REAL(0.8));   // away from zero

    const dReal vel[][6] = { { REAL(0.3), REAL(-0.5), REAL(0.8), REAL(-0.7), REAL(0.2), REAL(0.4) },
                             { 0, 0, 0, REAL(0.1), REAL(0.9), REAL(-0.3) },
                             { -1, REAL(0.5), 0, 0, 0, 0 } };
    for (size_t k = 0; k < sizeof vel / sizeof vel[0]; k++) {
        dBodySetAngularVel(b1, vel[k][0], vel[k][1], vel[k][2]);
        dBodySetAngularVel(b2, vel[k][3], vel[k][4], vel[k][5]);
        angle_getter g1 = { dJointGetHinge2Angle1, 0 }, g2 = { dJointGetHinge2Angle2, 0 };
        CHECK_NEAR(dJointGetHinge2Angle1Rate(j), central_difference(j, b1, b2, g1, FD_DT), FD_TOL);
        CHECK_NEAR(dJointGetHinge2Angle2Rate(j), central_difference(j, b1, b2, g2, FD_DT), FD_TOL);
    }
    // A wheel spinning about a slanted wheel axis does not steer.
    dBodySetAngularVel(b1, 0, 0, 0);
    dVector3 a2;
    dJointGetHinge2Axis2(j, a2);
    dBodySetAngularVel(b2, 2 * a2[0], 2 * a2[1], 2 * a2[2]);
    CHECK_NEAR(dJointGetHinge2Angle1Rate(j), 0, TOL(1e-14, 1e-6));
    CHECK_NEAR(dJointGetHinge2Angle2Rate(j), -2, TOL(1e-14, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// ---- hinge-2: stepping ----------------------------------------------------------

// Suspension ERP and CFM from a spring kp and damper kd (guide 3.8.2):
// ERP = h kp / (h kp + kd), CFM = 1 / (h kp + kd). A mass m resting on the
// suspension sags by m g / kp: at rest the row gives fps ERP err = CFM f with
// f = m g, so err = f h CFM / ERP = f / kp.
static int test_hinge2_suspension_sags_by_mg_over_kp(void)
{
    const dReal kp = 1000, kd = 50, mass = 2, g = REAL(9.81);
    const dReal erp = STEP * kp / (STEP * kp + kd), cfm = 1 / (STEP * kp + kd);
    // 0: on a kinematic wheel; 1: hanging from the static world as body 2;
    // 2: the static world as body 1 (dJointAttach(j, 0, b), stored reversed).
    for (int config = 0; config < 3; config++) {
        dWorldID w = make_world(-g);
        dBodyID chassis = make_body(w, 0, 0, 1, mass, REAL(0.1), REAL(0.2), REAL(0.3));
        dBodyID wheel = NULL;
        dJointID j = dJointCreateHinge2(w, 0);
        if (config == 0) {
            wheel = make_body(w, 0, 0, 0, 1, 1, 1, 1);
            dBodySetKinematic(wheel);
            dJointAttach(j, chassis, wheel);
        } else if (config == 1) {
            dJointAttach(j, chassis, 0);
        } else {
            dJointAttach(j, 0, chassis);
        }
        dJointSetHinge2Anchor(j, 0, 0, 1);   // at the chassis centre: no lever
        const dReal a1[3] = { 0, 0, 1 }, a2[3] = { 0, 1, 0 };
        dJointSetHinge2Axes(j, a1, a2);
        dJointSetHinge2Param(j, dParamSuspensionERP, erp);
        dJointSetHinge2Param(j, dParamSuspensionCFM, cfm);
        // Damping ratio kd / (2 sqrt(kp m)) = 0.56: 2000 steps leave e^-250 of the transient.
        for (int i = 0; i < 2000; i++) dWorldStep(w, STEP);
        const dReal *p = dBodyGetPosition(chassis);
        double sag = mass * g / kp;   // 0.01962 m
        CHECK_NEAR(p[2], 1 - sag, TOL(1e-10, 2e-6));
        CHECK_NEAR(p[0], 0, TOL(1e-12, 1e-6));
        CHECK_NEAR(p[1], 0, TOL(1e-12, 1e-6));
        CHECK_NEAR(dBodyGetLinearVel(chassis)[2], 0, TOL(1e-10, 1e-5));
        dVector3 anchor1, anchor2;
        dJointGetHinge2Anchor(j, anchor1);
        dJointGetHinge2Anchor2(j, anchor2);
        // The user's body 1 is the one that sags, unless it is the world.
        CHECK_NEAR(anchor1[2] - anchor2[2], config == 2 ? sag : -sag, TOL(1e-10, 2e-6));
        dWorldDestroy(w);
    }
    return 0;
}

// The rows across the suspension axis are rigid: a heavy wheel hanging from
// a kinematic chassis (suspension axis horizontal, gravity across it) keeps
// its anchor on the chassis anchor while spinning.
static int test_hinge2_anchors_coincide_under_load(void)
{
    dWorldID w = make_world(REAL(-9.81));
    dBodyID chassis = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dBodySetKinematic(chassis);
    dBodyID wheel = make_body(w, 0, 0, REAL(-0.5), 20, 2, 4, 2);
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, chassis, wheel);
    dJointSetHinge2Anchor(j, 0, 0, REAL(-0.5));
    const dReal a1[3] = { 1, 0, 0 }, a2[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(j, a1, a2);
    dJointSetHinge2Param(j, dParamVel2, -20);
    dJointSetHinge2Param(j, dParamFMax2, 50);
    double worst = 0;
    for (int i = 0; i < 300; i++) {
        dWorldStep(w, STEP);
        dVector3 p1, p2;
        dJointGetHinge2Anchor(j, p1);
        dJointGetHinge2Anchor2(j, p2);
        double d = dist3(p1, p2);
        if (d > worst) worst = d;
    }
    // Static load 196 N, world CFM 1e-10: the gap is f h CFM / ERP = 1e-9 m.
    CHECK(worst < TOL(1e-7, 1e-4));
    CHECK_NEAR(dJointGetHinge2Angle2Rate(j), -20, TOL(1e-6, 1e-3));
    CHECK_NEAR(dJointGetHinge2Angle1(j), 0, TOL(1e-7, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// Steering stops: a wheel pushed about the steering axis stops at the stop.
static int test_hinge2_steering_stops_hold(void)
{
    car_wheel c;
    make_car_wheel(&c, 0, 1);
    dJointSetHinge2Param(c.j, dParamLoStop, REAL(-0.3));
    dJointSetHinge2Param(c.j, dParamHiStop, REAL(0.3));
    // Torque +z on the wheel turns it +z: the chassis turns -z relative to it.
    double low = 0, high = 0;
    for (int i = 0; i < 300; i++) {
        dBodyAddTorque(c.wheel, 0, 0, 1);
        dWorldStep(c.w, STEP);
        double a = dJointGetHinge2Angle1(c.j);
        if (a < low) low = a;
    }
    // Reached with 10 rad/s^2 after ~0.25 s at ~2.4 rad/s: one step of 0.024 rad
    // overshoot at most, then the stop's ERP pulls it back.
    CHECK(low > -0.3 - 0.03);
    CHECK_NEAR(dJointGetHinge2Angle1(c.j), -0.3, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetHinge2Angle1Rate(c.j), 0, TOL(1e-6, 1e-4));
    for (int i = 0; i < 400; i++) {
        dBodyAddTorque(c.wheel, 0, 0, -1);
        dWorldStep(c.w, STEP);
        double a = dJointGetHinge2Angle1(c.j);
        if (a > high) high = a;
    }
    CHECK(high < 0.3 + 0.03);
    CHECK_NEAR(dJointGetHinge2Angle1(c.j), 0.3, TOL(1e-6, 1e-4));
    dWorldDestroy(c.w);
    return 0;
}

// Motors reach their target in one step when FMax suffices; otherwise the
// speed changes by FMax h / I (the rows do not couple: anchor at the wheel
// centre, principal axes along the joint axes, kinematic chassis).
static int test_hinge2_motors_one_step_and_force_limit(void)
{
    for (int axis = 0; axis < 2; axis++) {
        int vel = axis ? dParamVel2 : dParamVel, fmax = axis ? dParamFMax2 : dParamFMax;
        dReal (*rate)(dJointID) = axis ? dJointGetHinge2Angle2Rate : dJointGetHinge2Angle1Rate;
        dReal inertia = axis ? REAL(0.4) : REAL(0.2);   // wheel about y / about z
        int component = axis ? 1 : 2;

        car_wheel c;
        make_car_wheel(&c, 0, 1);
        dJointSetHinge2Param(c.j, vel, -5);
        dJointSetHinge2Param(c.j, fmax, 1000);
        dJointSetHinge2Param(c.j, dParamCFM + axis * dParamGroup, 0);   // else off by CFM f
        dWorldStep(c.w, STEP);
        CHECK_NEAR(rate(c.j), -5, TOL(1e-9, 1e-4));
        // rate = axis . (w_chassis - w_wheel): the wheel turns at +5.
        CHECK_NEAR(dBodyGetAngularVel(c.wheel)[component], 5, TOL(1e-9, 1e-4));
        dWorldDestroy(c.w);

        make_car_wheel(&c, 0, 1);
        dJointSetHinge2Param(c.j, vel, -5);
        dJointSetHinge2Param(c.j, fmax, REAL(0.8));
        dWorldStep(c.w, STEP);
        CHECK_NEAR(dBodyGetAngularVel(c.wheel)[component], 0.8 * STEP / inertia,
                   TOL(1e-12, 1e-7));
        dWorldDestroy(c.w);
    }
    return 0;
}

// The angular row keeps the set-time angle theta0 between the axes: a wheel
// turned by delta about u = a1 x a2 (which opens the angle) is pulled back
// by ERP sin(delta) in one step, and the angle converges to theta0.
static int test_hinge2_axes_angle_restored(void)
{
    dWorldID w = make_world(0);
    dBodyID chassis = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dBodySetKinematic(chassis);
    dBodyID wheel = make_body(w, 0, 1, 0, 1, REAL(0.5), REAL(0.5), REAL(0.5));
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, chassis, wheel);
    dJointSetHinge2Anchor(j, 0, 1, 0);
    const dReal a1[3] = { 0, 0, 1 }, a2[3] = { 0, 1, REAL(0.5773502691896257) };   // 60 deg
    dJointSetHinge2Axes(j, a1, a2);
    const double theta0 = M_PI / 3, delta = 0.05;
    dVector3 u, x1, x2;
    dCalcVectorCross3(u, a1, a2);
    turn_body_v(wheel, u, (dReal)delta);
    for (int step = 0; step < 100; step++) {
        dJointGetHinge2Axis1(j, x1);
        dJointGetHinge2Axis2(j, x2);
        dCalcVectorCross3(u, x1, x2);
        double theta = atan2(sqrt(dot3(u, u)), dot3(x1, x2));
        if (step == 0) CHECK_NEAR(theta - theta0, delta, TOL(1e-12, 1e-6));
        // One step: delta - ERP sin(delta), up to the O((w h)^3) error of the
        // stepper's first-order rotation update (w h = 0.01 rad here); in
        // single precision the world's default CFM 1e-5 also softens the row
        // by CFM f h = 1e-5 * 50 N m * 0.01 s = 5e-6 rad.
        if (step == 1) CHECK_NEAR(theta - theta0, delta - 0.2 * sin(delta), TOL(1e-7, 1e-5));
        if (step == 99) CHECK_NEAR(theta - theta0, 0, TOL(1e-9, 1e-5));
        dWorldStep(w, STEP);
    }
    dWorldDestroy(w);
    return 0;
}

// With a slanted steering axis (caster), a steering motor holding the
// steering still and a wheel motor driving the wheel do not fight: the rows
// use the reciprocal axes, so holding Angle1 costs the wheel nothing.
static int test_hinge2_caster_steering_held_while_wheel_driven(void)
{
    dWorldID w = make_world(REAL(-9.81));
    dBodyID chassis = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dBodySetKinematic(chassis);
    dBodyID wheel = make_body(w, 0, REAL(0.6), 0, 1, REAL(0.2), REAL(0.4), REAL(0.2));
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, chassis, wheel);
    dJointSetHinge2Anchor(j, 0, REAL(0.6), 0);
    const dReal a1[3] = { 0, REAL(0.34), REAL(0.94) }, a2[3] = { 0, 1, 0 };   // 20 deg caster
    dJointSetHinge2Axes(j, a1, a2);
    dJointSetHinge2Param(j, dParamFMax, 1000);
    dJointSetHinge2Param(j, dParamCFM, 0);
    dJointSetHinge2Param(j, dParamVel2, -10);
    dJointSetHinge2Param(j, dParamFMax2, 1000);
    dJointSetHinge2Param(j, dParamCFM2, 0);
    for (int step = 0; step < 100; step++) dWorldStep(w, STEP);
    CHECK_NEAR(dJointGetHinge2Angle1(j), 0, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetHinge2Angle1Rate(j), 0, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetHinge2Angle2Rate(j), -10, TOL(1e-6, 1e-3));
    dWorldDestroy(w);
    return 0;
}

static int test_hinge2_torques(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 1, 0, 0, 1, 1, 1, 1);
    turn_body(b1, 0, 1, 0, REAL(0.5));
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, b1, b2);
    const dReal a1[3] = { 0, 0, 1 }, a2[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(j, a1, a2);
    dJointAddHinge2Torques(j, 2, 3);
    const dReal *t1 = dBodyGetTorque(b1), *t2 = dBodyGetTorque(b2);
    CHECK(dist3(t1, (dReal[3]){ 0, 3, 2 }) < TOL(1e-12, 1e-6));
    CHECK(dist3(t2, (dReal[3]){ 0, -3, -2 }) < TOL(1e-12, 1e-6));

    // The static world as body 1: body 2 still gets minus the torque.
    dJointID r = dJointCreateHinge2(w, 0);
    dJointAttach(r, 0, b2);
    dJointSetHinge2Axes(r, a1, a2);
    dJointAddHinge2Torques(r, 1, 0);
    CHECK(dist3(t2, (dReal[3]){ 0, -3, -3 }) < TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// ---- the user's body order --------------------------------------------------------

// The static world behaves like a kinematic body at rest at the origin: a
// joint attached as (0, b) -- stored reversed -- must move b exactly as a
// joint attached as (k, b) with such a body k, and present the same values.
// Likewise (b, 0) against (b, k).
typedef struct twin {
    dWorldID w[2];
    dBodyID b[2], k;
    dJointID j[2];
} twin;

static void make_twin(twin *t, int world_is_body1, dJointID (*create)(dWorldID, dJointGroupID))
{
    for (int i = 0; i < 2; i++) {
        t->w[i] = make_world(REAL(-9.81));
        t->b[i] = make_body(t->w[i], REAL(0.1), REAL(0.2), REAL(-0.6), 2, REAL(0.1), REAL(0.3),
                            REAL(0.2));
        turn_body(t->b[i], 1, 1, 0, REAL(0.3));
        dBodySetAngularVel(t->b[i], REAL(0.5), -1, 2);
        t->j[i] = create(t->w[i], 0);
    }
    t->k = make_body(t->w[0], 0, 0, 0, 1, 1, 1, 1);
    dBodySetKinematic(t->k);
    if (world_is_body1) {
        dJointAttach(t->j[0], t->k, t->b[0]);
        dJointAttach(t->j[1], 0, t->b[1]);
    } else {
        dJointAttach(t->j[0], t->b[0], t->k);
        dJointAttach(t->j[1], t->b[1], 0);
    }
}

static int twin_bodies_agree(const twin *t, double tol)
{
    CHECK(dist3(dBodyGetPosition(t->b[0]), dBodyGetPosition(t->b[1])) <= tol);
    CHECK(dist3(dBodyGetLinearVel(t->b[0]), dBodyGetLinearVel(t->b[1])) <= tol);
    CHECK(dist3(dBodyGetAngularVel(t->b[0]), dBodyGetAngularVel(t->b[1])) <= tol);
    const dReal *q0 = dBodyGetQuaternion(t->b[0]), *q1 = dBodyGetQuaternion(t->b[1]);
    for (int i = 0; i < 4; i++) CHECK_NEAR(q0[i], q1[i], tol);
    return 0;
}

static void destroy_twin(twin *t)
{
    dWorldDestroy(t->w[0]);
    dWorldDestroy(t->w[1]);
}

static int test_hinge2_reversed_attach_keeps_user_order(void)
{
    for (int world_is_body1 = 0; world_is_body1 < 2; world_is_body1++) {
        twin t;
        make_twin(&t, world_is_body1, dJointCreateHinge2);
        for (int i = 0; i < 2; i++) {
            dJointSetHinge2Anchor(t.j[i], 0, 0, REAL(-0.5));
            const dReal a1[3] = { 0, REAL(0.2), 1 }, a2[3] = { 1, 0, 0 };
            dJointSetHinge2Axes(t.j[i], a1, a2);
            dJointSetHinge2Param(t.j[i], dParamLoStop, REAL(-0.2));
            dJointSetHinge2Param(t.j[i], dParamHiStop, REAL(0.2));
            dJointSetHinge2Param(t.j[i], dParamVel2, 3);
            dJointSetHinge2Param(t.j[i], dParamFMax2, REAL(0.05));
            dJointSetHinge2Param(t.j[i], dParamSuspensionCFM, REAL(0.01));
            dJointSetHinge2Param(t.j[i], dParamSuspensionERP, REAL(0.3));
        }
        for (int s = 0; s < 200; s++) {
            for (int i = 0; i < 2; i++) {
                dJointAddHinge2Torques(t.j[i], REAL(0.05), REAL(0.02));
                dWorldStep(t.w[i], STEP);
            }
        }
        // Rounding differs only in the kinematic body's (exact) identity terms.
        if (twin_bodies_agree(&t, TOL(1e-9, 1e-4))) return 1;
        // The stop held and the motor spun, in the user's sense, in both.
        CHECK(fabs(dJointGetHinge2Angle1(t.j[1])) < 0.2 + 0.02);
        CHECK(fabs(dJointGetHinge2Angle1(t.j[1])) > 0.05);
        dVector3 v0, v1;
        dJointGetHinge2Anchor(t.j[0], v0);
        dJointGetHinge2Anchor(t.j[1], v1);
        CHECK(dist3(v0, v1) < TOL(1e-9, 1e-4));
        dJointGetHinge2Anchor2(t.j[0], v0);
        dJointGetHinge2Anchor2(t.j[1], v1);
        CHECK(dist3(v0, v1) < TOL(1e-9, 1e-4));
        dJointGetHinge2Axis1(t.j[0], v0);
        dJointGetHinge2Axis1(t.j[1], v1);
        CHECK(dist3(v0, v1) < TOL(1e-9, 1e-4));
        dJointGetHinge2Axis2(t.j[0], v0);
        dJointGetHinge2Axis2(t.j[1], v1);
        CHECK(dist3(v0, v1) < TOL(1e-9, 1e-4));
        CHECK_NEAR(dJointGetHinge2Angle1(t.j[0]), dJointGetHinge2Angle1(t.j[1]), TOL(1e-9, 1e-4));
        CHECK_NEAR(dJointGetHinge2Angle2(t.j[0]), dJointGetHinge2Angle2(t.j[1]), TOL(1e-9, 1e-4));
        CHECK_NEAR(dJointGetHinge2Angle1Rate(t.j[0]), dJointGetHinge2Angle1Rate(t.j[1]),
                   TOL(1e-9, 1e-4));
        CHECK_NEAR(dJointGetHinge2Angle2Rate(t.j[0]), dJointGetHinge2Angle2Rate(t.j[1]),
                   TOL(1e-9, 1e-4));
        destroy_twin(&t);
    }
    return 0;
}

// ---- hinge-2: bad input -------------------------------------------------------------

static int test_hinge2_bad_input(void)
{
    car_wheel c;
    make_car_wheel(&c, 0, 0);
    dVector3 v;
    test_capture_reports();

    const dReal z[3] = { 0, 0, 1 }, down[3] = { 0, 0, -2 }, y[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(c.j, z, down);
    CHECK(test_captured_count() == 1 && test_captured_contains("parallel"));
    CHECK(test_captured_contains("dJointSetHinge2Axes"));
    dJointSetHinge2Axis1(c.j, 0, -3, 0);   // parallel to axis 2 (y)
    CHECK(test_captured_count() == 2 && test_captured_contains("dJointSetHinge2Axis1"));
    dJointSetHinge2Axes(c.j, NULL, z);           // axis 2 onto axis 1
    CHECK(test_captured_count() == 3);
    dJointGetHinge2Axis1(c.j, v);
    CHECK(dist3(v, z) == 0);
    dJointGetHinge2Axis2(c.j, v);
    CHECK(dist3(v, y) == 0);

    dJointSetHinge2Axis2(c.j, 0, 0, 0);
    CHECK(test_captured_count() == 4 && test_captured_contains("no direction"));
    dJointSetHinge2Axis1(c.j, NAN, 0, 1);
    CHECK(test_captured_count() == 5);
    dJointSetHinge2Axes(c.j, NULL, NULL);
    CHECK(test_captured_count() == 6);
    dJointGetHinge2Axis2(c.j, v);
    CHECK(dist3(v, y) == 0);

    dJointSetHinge2Anchor(c.j, 0, INFINITY, 0);
    CHECK(test_captured_count() == 7 && test_captured_contains("anchor"));
    dJointGetHinge2Anchor(c.j, v);
    CHECK(dist3(v, (dReal[3]){ 0, 0.6, 0 }) < 1e-12);

    dJointSetHinge2Param(c.j, dParamVel, NAN);
    CHECK(test_captured_count() == 8);
    dJointSetHinge2Param(c.j, dParamFMax3, 1);   // no third axis
    CHECK(test_captured_count() == 9);
    CHECK(dJointGetHinge2Param(c.j, dParamFMax3) == 0);
    CHECK(test_captured_count() == 10);
    dJointSetHinge2Param(c.j, dParamFMax2, -1);
    CHECK(test_captured_count() == 11);
    CHECK(dJointGetHinge2Param(c.j, dParamVel) == 0 && dJointGetHinge2Param(c.j, dParamFMax2) == 0);

    dJointAddHinge2Torques(c.j, NAN, 0);
    CHECK(test_captured_count() == 12);
    CHECK(dBodyGetTorque(c.wheel)[0] == 0);
    dJointGetHinge2Anchor(c.j, NULL);
    CHECK(test_captured_count() == 13);

    // Wrong joint type and no joint.
    dJointID hinge = dJointCreateHinge(c.w, 0);
    dJointSetHinge2Anchor(hinge, 0, 0, 0);
    CHECK(test_captured_count() == 14 && test_captured_contains("hinge joint"));
    CHECK(dJointGetHinge2Angle1(hinge) == 0);
    CHECK(dJointGetHinge2Param(NULL, dParamVel) == 0);
    CHECK(test_captured_count() == 16);

    // The default axes (x on body 1, y on body 2) made parallel by the
    // bodies' orientations: setting the anchor reports it (the anchor is kept).
    dJointID k = dJointCreateHinge2(c.w, 0);
    turn_body(c.wheel, 0, 0, 1, (dReal)(M_PI / 2));   // the wheel's y is now -x
    dJointAttach(k, c.chassis, c.wheel);
    dJointSetHinge2Anchor(k, 1, 2, 3);
    CHECK(test_captured_count() == 17 && test_captured_contains("parallel"));
    dJointGetHinge2Anchor2(k, v);
    CHECK(dist3(v, (dReal[3]){ 1, 2, 3 }) < TOL(1e-12, 1e-6));
    dWorldDestroy(c.w);
    return 0;
}

// ---- angular motor: API -----------------------------------------------------------------

static int test_amotor_defaults_and_axes(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 1, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateAMotor(w, 0);
    dVector3 v;
    CHECK(dJointGetType(j) == dJointTypeAMotor);
    CHECK(dJointGetAMotorMode(j) == dAMotorUser);
    CHECK(dJointGetAMotorNumAxes(j) == 0);
    dJointGetAMotorAxis(j, 2, v);   // the guide's default axis
    CHECK(v[0] == 1 && v[1] == 0 && v[2] == 0);
    CHECK(dJointGetAMotorAxisRel(j, 1) == 0);
    CHECK(dJointGetAMotorParam(j, dParamLoStop3) == -dInfinity);
    CHECK(dJointGetAMotorParam(j, dParamFMax2) == 0);

    dJointAttach(j, b1, b2);
    dJointSetAMotorNumAxes(j, 3);
    CHECK(dJointGetAMotorNumAxes(j) == 3);
    dJointSetAMotorAxis(j, 0, 0, 0, 0, 2);   // global
    dJointSetAMotorAxis(j, 1, 1, 0, 3, 0);   // fixed to body 1
    dJointSetAMotorAxis(j, 2, 2, 4, 0, 0);   // fixed to body 2
    CHECK(dJointGetAMotorAxisRel(j, 0) == 0);
    CHECK(dJointGetAMotorAxisRel(j, 1) == 1);
    CHECK(dJointGetAMotorAxisRel(j, 2) == 2);
    turn_body(b1, 1, 0, 0, (dReal)(M_PI / 2));   // y -> z
    turn_body(b2, 0, 0, 1, (dReal)(M_PI / 2));   // x -> y
    dJointGetAMotorAxis(j, 0, v);
    CHECK(dist3(v, (dReal[3]){ 0, 0, 1 }) < 1e-12);
    dJointGetAMotorAxis(j, 1, v);
    CHECK(dist3(v, (dReal[3]){ 0, 0, 1 }) < TOL(1e-12, 1e-6));
    dJointGetAMotorAxis(j, 2, v);
    CHECK(dist3(v, (dReal[3]){ 0, 1, 0 }) < TOL(1e-12, 1e-6));

    // User mode: the angle is what the user said, the rate is 0 (guide).
    dJointSetAMotorAngle(j, 1, REAL(0.7));
    CHECK(dJointGetAMotorAngle(j, 1) == REAL(0.7));
    dBodySetAngularVel(b1, 1, 2, 3);
    CHECK(dJointGetAMotorAngleRate(j, 1) == 0);

    dJointSetAMotorParam(j, dParamVel3, 2);
    dJointSetAMotorParam(j, dParamHiStop2, 1);
    CHECK(dJointGetAMotorParam(j, dParamVel3) == 2);
    CHECK(dJointGetAMotorParam(j, dParamHiStop2) == 1);
    CHECK(dJointGetAMotorParam(j, dParamVel) == 0);

    // Euler mode forces three axes; setting the count then has no effect.
    dJointSetAMotorNumAxes(j, 1);
    CHECK(dJointGetAMotorNumAxes(j) == 1);
    dJointSetAMotorMode(j, dAMotorEuler);
    CHECK(dJointGetAMotorMode(j) == dAMotorEuler);
    CHECK(dJointGetAMotorNumAxes(j) == 3);
    dJointSetAMotorNumAxes(j, 2);
    CHECK(dJointGetAMotorNumAxes(j) == 3);
    dWorldDestroy(w);
    return 0;
}

// ---- angular motor: Euler mode ---------------------------------------------------------

// Bodies in any orientation, axis 0 (on body 1) and axis 2 (on body 2)
// perpendicular. Turning body 2 by Rot(a0, t0) Rot(a1, t1) Rot(a2, t2) (world
// rotations with the set-time axes) is the Euler sequence t of body 2
// relative to body 1: the angles (body 1 against body 2, ODE's sign) are -t.
typedef struct euler_rig {
    dWorldID w;
    dBodyID b1, b2;
    dJointID j;
    dVector3 e[3];   // the axes at the reference
} euler_rig;

static void make_euler_rig(euler_rig *r)
{
    r->w = make_world(0);
    r->b1 = make_body(r->w, 0, 0, 0, 1, 1, 1, 1);
    r->b2 = make_body(r->w, 0, 0, -1, 1, 1, 1, 1);
    turn_body(r->b1, 1, 2, 3, REAL(0.7));
    turn_body(r->b2, -2, 1, REAL(0.5), REAL(1.1));
    r->j = dJointCreateAMotor(r->w, 0);
    dJointAttach(r->j, r->b1, r->b2);
    dJointSetAMotorMode(r->j, dAMotorEuler);
    dReal s = 1 / sqrt(3.0), t = 1 / sqrt(2.0);
    dJointSetAMotorAxis(r->j, 0, 1, s, s, s);
    dJointSetAMotorAxis(r->j, 2, 2, t, -t, 0);
    for (int i = 0; i < 3; i++) dJointGetAMotorAxis(r->j, i, r->e[i]);
}

static void euler_turn(euler_rig *r, const dReal t[3])
{
    turn_body_v(r->b2, r->e[2], t[2]);
    turn_body_v(r->b2, r->e[1], t[1]);
    turn_body_v(r->b2, r->e[0], t[0]);
}

static int test_amotor_euler_angles_follow_known_rotation(void)
{
    euler_rig r;
    make_euler_rig(&r);
    // The reference axes: a0, a2 as set, a1 = a2 x a0.
    CHECK(fabs(dot3(r.e[0], r.e[2])) < TOL(1e-12, 1e-6));
    dVector3 c;
    dCalcVectorCross3(c, r.e[2], r.e[0]);
    CHECK(dist3(c, r.e[1]) < TOL(1e-12, 1e-6));
    for (int i = 0; i < 3; i++) CHECK_NEAR(dJointGetAMotorAngle(r.j, i), 0, TOL(1e-14, 1e-6));

    dQuaternion q2;
    dCopyVector4(q2, dBodyGetQuaternion(r.b2));
    const dReal cases[][3] = { { REAL(0.3), REAL(-0.5), REAL(1.2) },
                               { REAL(-2.5), REAL(1.4), REAL(3.0) },
                               { 0, REAL(0.2), 0 },
                               { 1, REAL(-1.5), -2 } };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        dBodySetQuaternion(r.b2, q2);
        euler_turn(&r, cases[k]);
        for (int i = 0; i < 3; i++)
            CHECK_NEAR(dJointGetAMotorAngle(r.j, i), -cases[k][i], TOL(1e-9, 1e-4));
        // The axes now: a0 stays with body 1, a2 moved with body 2, a1 = Rot(a0, t0) e1.
        dVector3 a[3];
        for (int i = 0; i < 3; i++) dJointGetAMotorAxis(r.j, i, a[i]);
        CHECK(dist3(a[0], r.e[0]) < TOL(1e-12, 1e-6));
        CHECK(fabs(dot3(a[1], a[0])) < TOL(1e-12, 1e-6));
        CHECK(fabs(dot3(a[1], a[2])) < TOL(1e-12, 1e-6));
        CHECK_NEAR(dot3(a[0], a[2]), sin(cases[k][1]), TOL(1e-12, 1e-6));
        // Turning both bodies together changes nothing.
        turn_body(r.b1, 1, -3, 2, REAL(2.1));
        turn_body(r.b2, 1, -3, 2, REAL(2.1));
        for (int i = 0; i < 3; i++)
            CHECK_NEAR(dJointGetAMotorAngle(r.j, i), -cases[k][i], TOL(1e-9, 1e-4));
        turn_body(r.b1, 1, -3, 2, REAL(-2.1));
    }
    // Setting an axis again makes the current orientation the zero.
    dJointSetAMotorAxis(r.j, 0, 1, r.e[0][0], r.e[0][1], r.e[0][2]);
    for (int i = 0; i < 3; i++) CHECK_NEAR(dJointGetAMotorAngle(r.j, i), 0, TOL(1e-12, 1e-6));
    dWorldDestroy(r.w);
    return 0;
}

static int test_amotor_euler_rates_match_finite_differences(void)
{
    euler_rig r;
    make_euler_rig(&r);
    const dReal t[3] = { REAL(0.4), REAL(-0.6), REAL(2.0) };
    euler_turn(&r, t);
    const dReal vel[][6] = { { REAL(0.3), REAL(-0.5), REAL(0.8), REAL(-0.7), REAL(0.2), REAL(0.4) },
                             { 0, 0, 0, REAL(0.1), REAL(0.9), REAL(-0.3) },
                             { -1, REAL(0.5), 0, 0, 0, 0 } };
    for (size_t k = 0; k < sizeof vel / sizeof vel[0]; k++) {
        dBodySetAngularVel(r.b1, vel[k][0], vel[k][1], vel[k][2]);
        dBodySetAngularVel(r.b2, vel[k][3], vel[k][4], vel[k][5]);
        for (int i = 0; i < 3; i++) {
            angle_getter g = { NULL, i };
            CHECK_NEAR(dJointGetAMotorAngleRate(r.j, i),
                       central_difference(r.j, r.b1, r.b2, g, FD_DT), FD_TOL);
        }
    }
    dWorldDestroy(r.w);
    return 0;
}

// Euler stops hold: torques through dJointAddAMotorTorques (-a0 + a2 on body
// 1, the opposite on body 2) drive angle 0 down and angle 2 up into the stops.
static int test_amotor_euler_stops_hold(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 0, 0, -1, 1, 1, 1, 1);
    dBodySetKinematic(b1);
    dJointID j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetAMotorMode(j, dAMotorEuler);
    dJointSetAMotorAxis(j, 0, 1, 1, 0, 0);
    dJointSetAMotorAxis(j, 2, 2, 0, 0, 1);
    dJointSetAMotorParam(j, dParamLoStop, REAL(-0.4));
    dJointSetAMotorParam(j, dParamHiStop, REAL(0.4));
    dJointSetAMotorParam(j, dParamLoStop3, REAL(-0.6));
    dJointSetAMotorParam(j, dParamHiStop3, REAL(0.6));
    double low0 = 0, high2 = 0;
    for (int i = 0; i < 400; i++) {
        dJointAddAMotorTorques(j, -1, 0, 1);
        dWorldStep(w, STEP);
        double a0 = dJointGetAMotorAngle(j, 0), a2 = dJointGetAMotorAngle(j, 2);
        if (a0 < low0) low0 = a0;
        if (a2 > high2) high2 = a2;
    }
    // ~1 rad/s^2 reaches the stops at under 1.2 rad/s: overshoot < 0.012 rad.
    CHECK(low0 > -0.4 - 0.02);
    CHECK(high2 < 0.6 + 0.02);
    CHECK_NEAR(dJointGetAMotorAngle(j, 0), -0.4, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetAMotorAngle(j, 2), 0.6, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetAMotorAngleRate(j, 0), 0, TOL(1e-6, 1e-4));
    CHECK_NEAR(dJointGetAMotorAngleRate(j, 2), 0, TOL(1e-6, 1e-4));
    // Angle 1 is free; it picks up speed although no torque acts along a1:
    // a1 turns with angle 0, so a1 . w changes while the stops engage (the
    // Euler coordinates' velocity-dependent coupling). It then keeps turning.
    CHECK(fabs(dJointGetAMotorAngleRate(j, 1)) > 0.01);
    dWorldDestroy(w);
    return 0;
}

// Euler velocity motor: one step to the target rate, whatever the pose. The
// rows hold the rates in the frame at the start of the step, so the rates
// are read with the new velocities in the old orientation.
static int test_amotor_euler_motor_reaches_rate(void)
{
    euler_rig r;
    make_euler_rig(&r);
    const dReal t[3] = { REAL(0.4), REAL(-0.6), REAL(2.0) };
    euler_turn(&r, t);
    dBodySetKinematic(r.b1);
    const dReal target[3] = { REAL(0.5), REAL(-1.0), REAL(1.5) };
    for (int i = 0; i < 3; i++) {
        dJointSetAMotorParam(r.j, dParamVel + i * dParamGroup, target[i]);
        dJointSetAMotorParam(r.j, dParamFMax + i * dParamGroup, 1e6);
        dJointSetAMotorParam(r.j, dParamCFM + i * dParamGroup, 0);
    }
    dQuaternion q2;
    dCopyVector4(q2, dBodyGetQuaternion(r.b2));
    dWorldStep(r.w, STEP);
    dBodySetQuaternion(r.b2, q2);
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(dJointGetAMotorAngleRate(r.j, i), target[i], TOL(1e-9, 1e-4));
    dWorldDestroy(r.w);
    return 0;
}

// ---- angular motor: user mode ------------------------------------------------------------

// Three axes (one fixed to the body), velocity 0 and a large force: a spinning
// asymmetric body stops in one step.
static int test_amotor_user_holds_spinning_body(void)
{
    for (int reversed = 0; reversed < 2; reversed++) {
        dWorldID w = make_world(REAL(-9.81));
        dBodyID b = make_body(w, 0, 0, 0, 1, REAL(0.1), REAL(0.2), REAL(0.3));
        turn_body(b, 1, 2, 0, REAL(0.4));
        dBodySetAngularVel(b, 1, -2, 3);
        dJointID j = dJointCreateAMotor(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetAMotorNumAxes(j, 3);
        dJointSetAMotorAxis(j, 0, 0, 1, 0, 0);
        dJointSetAMotorAxis(j, 1, reversed ? 2 : 1, 0, 1, 0);   // fixed to b
        dJointSetAMotorAxis(j, 2, 0, 0, 0, 1);
        for (int i = 0; i < 3; i++) {
            dJointSetAMotorParam(j, dParamFMax + i * dParamGroup, 1e9);
            dJointSetAMotorParam(j, dParamCFM + i * dParamGroup, 0);
        }
        dWorldStep(w, STEP);
        const dReal *av = dBodyGetAngularVel(b);
        CHECK(sqrt(dot3(av, av)) < TOL(1e-9, 1e-4));
        CHECK_NEAR(dBodyGetLinearVel(b)[2], -9.81 * STEP, TOL(1e-12, 1e-6));   // linear is free
        dWorldDestroy(w);
    }
    return 0;
}

// A velocity motor about a principal axis reaches its target in one step if
// FMax allows; otherwise the speed changes by FMax h / I. The rate is that of
// body 1 against body 2: with the world as body 1 the body turns the other way.
static int test_amotor_user_velocity_motor_and_force_limit(void)
{
    for (int reversed = 0; reversed < 2; reversed++) {
        dReal sign = reversed ? -1 : 1;
        dWorldID w = make_world(0);
        dBodyID b = make_body(w, 0, 0, 0, 1, 1, 2, 3);
        dJointID j = dJointCreateAMotor(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetAMotorNumAxes(j, 2);
        dJointSetAMotorAxis(j, 0, 0, 0, 0, 1);   // I = 3
        dJointSetAMotorAxis(j, 1, 0, 1, 0, 0);   // I = 1
        dJointSetAMotorParam(j, dParamVel, 2);
        dJointSetAMotorParam(j, dParamFMax, 1000);
        dJointSetAMotorParam(j, dParamCFM, 0);
        dJointSetAMotorParam(j, dParamVel2, -1);
        dJointSetAMotorParam(j, dParamFMax2, 2);   // needs 100, gets 2
        dWorldStep(w, STEP);
        const dReal *av = dBodyGetAngularVel(b);
        CHECK_NEAR(av[2], sign * 2, TOL(1e-9, 1e-5));
        CHECK_NEAR(av[0], sign * -2 * STEP / 1, TOL(1e-12, 1e-7));
        CHECK_NEAR(av[1], 0, TOL(1e-12, 1e-7));
        dWorldDestroy(w);
    }
    return 0;
}

// User-mode stops use the angle the user reports.
static int test_amotor_user_stop_uses_set_angle(void)
{
    dWorldID w = make_world(0);
    dBodyID b = make_body(w, 0, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b, 0);
    dJointSetAMotorNumAxes(j, 1);
    dJointSetAMotorAxis(j, 0, 0, 0, 0, 1);
    dJointSetAMotorParam(j, dParamHiStop, REAL(0.5));
    dJointSetAMotorParam(j, dParamStopCFM, 0);
    dBodySetAngularVel(b, 0, 0, 2);
    dJointSetAMotorAngle(j, 0, REAL(0.4));   // below the stop: free
    dWorldStep(w, STEP);
    CHECK_NEAR(dBodyGetAngularVel(b)[2], 2, 1e-12);
    dJointSetAMotorAngle(j, 0, REAL(0.5));   // at the stop: the row allows no further motion
    dWorldStep(w, STEP);
    CHECK_NEAR(dBodyGetAngularVel(b)[2], 0, TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

static int test_amotor_zero_axes_adds_nothing(void)
{
    dWorldID w = make_world(REAL(-9.81));
    dBodyID b[2];
    for (int i = 0; i < 2; i++) {
        b[i] = make_body(w, 3 * (dReal)i, 0, 0, 1, REAL(0.1), REAL(0.2), REAL(0.3));
        dBodySetAngularVel(b[i], 1, -2, 3);
    }
    dJointID j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b[0], 0);
    dJointSetAMotorAxis(j, 0, 0, 0, 0, 1);
    dJointSetAMotorParam(j, dParamFMax, 100);   // inert: no axis is active
    dJointSetAMotorParam(j, dParamLoStop, 0);
    dJointSetAMotorParam(j, dParamHiStop, 0);
    dJointFeedback fb = { { 0 }, { 0 }, { 0 }, { 0 } };
    dJointSetFeedback(j, &fb);
    for (int s = 0; s < 10; s++) dWorldStep(w, STEP);
    CHECK(dot3(fb.t1, fb.t1) == 0 && dot3(fb.f1, fb.f1) == 0);
    CHECK(dist3(dBodyGetAngularVel(b[0]), dBodyGetAngularVel(b[1])) == 0);
    CHECK(dist3(dBodyGetLinearVel(b[0]), dBodyGetLinearVel(b[1])) == 0);
    dJointAddAMotorTorques(j, 5, 5, 5);   // torques beyond the axis count are ignored
    CHECK(dot3(dBodyGetTorque(b[0]), dBodyGetTorque(b[0])) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_amotor_torques(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 1, 0, 0, 1, 1, 1, 1);
    turn_body(b1, 0, 0, 1, (dReal)(M_PI / 2));
    dJointID j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetAMotorNumAxes(j, 2);
    dJointSetAMotorAxis(j, 0, 0, 1, 0, 0);
    dJointSetAMotorAxis(j, 1, 1, 0, 1, 0);
    turn_body(b1, 0, 0, 1, (dReal)(M_PI / 2));   // axis 1 follows body 1: y -> -x
    dJointAddAMotorTorques(j, 1, 2, 3);        // the third torque is ignored
    CHECK(dist3(dBodyGetTorque(b1), (dReal[3]){ -1, 0, 0 }) < TOL(1e-12, 1e-6));
    CHECK(dist3(dBodyGetTorque(b2), (dReal[3]){ 1, 0, 0 }) < TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// The AMotor attached as (0, b) and (b, 0) against a kinematic stand-in for
// the world (see make_twin), in Euler and user modes.
static int test_amotor_reversed_attach_keeps_user_order(void)
{
    for (int mode = 0; mode < 2; mode++) {
        for (int world_is_body1 = 0; world_is_body1 < 2; world_is_body1++) {
            twin t;
            make_twin(&t, world_is_body1, dJointCreateAMotor);
            for (int i = 0; i < 2; i++) {
                dJointID j = t.j[i];
                dJointSetAMotorMode(j, mode);
                dJointSetAMotorNumAxes(j, 3);
                dJointSetAMotorAxis(j, 0, 1, 1, 0, 0);
                dJointSetAMotorAxis(j, 1, 0, 0, 1, 0);
                dJointSetAMotorAxis(j, 2, 2, 0, 0, 1);
                dJointSetAMotorParam(j, dParamLoStop, REAL(-0.3));
                dJointSetAMotorParam(j, dParamHiStop, REAL(0.3));
                dJointSetAMotorParam(j, dParamVel3, 2);
                dJointSetAMotorParam(j, dParamFMax3, REAL(0.05));
                dJointSetAMotorParam(j, dParamVel2, REAL(-0.5));
                dJointSetAMotorParam(j, dParamFMax2, REAL(0.02));
            }
            for (int s = 0; s < 200; s++) {
                for (int i = 0; i < 2; i++) {
                    if (mode == dAMotorUser) dJointSetAMotorAngle(t.j[i], 0, (dReal)s / 400);
                    dJointAddAMotorTorques(t.j[i], REAL(0.05), 0, REAL(-0.02));
                    dWorldStep(t.w[i], STEP);
                }
            }
            if (twin_bodies_agree(&t, TOL(1e-9, 1e-4))) return 1;
            for (int i = 0; i < 3; i++) {
                dVector3 v0, v1;
                dJointGetAMotorAxis(t.j[0], i, v0);
                dJointGetAMotorAxis(t.j[1], i, v1);
                CHECK(dist3(v0, v1) < TOL(1e-9, 1e-4));
                CHECK_NEAR(dJointGetAMotorAngle(t.j[0], i), dJointGetAMotorAngle(t.j[1], i),
                           TOL(1e-9, 1e-4));
                CHECK_NEAR(dJointGetAMotorAngleRate(t.j[0], i),
                           dJointGetAMotorAngleRate(t.j[1], i), TOL(1e-9, 1e-4));
            }
            if (mode == dAMotorEuler) CHECK(fabs(dJointGetAMotorAngle(t.j[1], 0)) < 0.3 + 0.02);
            destroy_twin(&t);
        }
    }
    return 0;
}

// ---- angular motor: bad input ------------------------------------------------------------

static int test_amotor_bad_input(void)
{
    dWorldID w = make_world(0);
    dBodyID b1 = make_body(w, 0, 0, 0, 1, 1, 1, 1), b2 = make_body(w, 1, 0, 0, 1, 1, 1, 1);
    dJointID j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetAMotorNumAxes(j, 2);
    dJointSetAMotorAxis(j, 0, 1, 0, 0, 1);
    dVector3 v;
    test_capture_reports();
    int n = 0;

    dJointSetAMotorAxis(j, -1, 0, 1, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("anum"));
    dJointSetAMotorAxis(j, 3, 0, 1, 0, 0);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorAxis(j, 0, 3, 1, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("rel"));
    dJointSetAMotorAxis(j, 0, -1, 1, 0, 0);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorAxis(j, 0, 0, 0, 0, 0);
    CHECK(test_captured_count() == ++n && test_captured_contains("no direction"));
    dJointSetAMotorAxis(j, 0, 0, NAN, 0, 1);
    CHECK(test_captured_count() == ++n);
    dJointGetAMotorAxis(j, 0, v);
    CHECK(dist3(v, (dReal[3]){ 0, 0, 1 }) == 0);
    CHECK(dJointGetAMotorAxisRel(j, 0) == 1);

    dJointGetAMotorAxis(j, 3, v);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorAxisRel(j, -1) == 0);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorAngle(j, 3) == 0);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorAngleRate(j, -1) == 0);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorAngle(j, 3, 1);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorAngle(j, 0, NAN);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorAngle(j, 0) == 0);

    dJointSetAMotorMode(j, 2);
    CHECK(test_captured_count() == ++n && test_captured_contains("mode"));
    CHECK(dJointGetAMotorMode(j) == dAMotorUser);
    dJointSetAMotorNumAxes(j, 4);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorNumAxes(j, -1);
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorNumAxes(j) == 2);

    dJointSetAMotorParam(j, dParamVel, NAN);
    CHECK(test_captured_count() == ++n);
    dJointSetAMotorParam(j, dParamGroup3 + dParamGroup, 1);   // a fourth group
    CHECK(test_captured_count() == ++n);
    CHECK(dJointGetAMotorParam(j, dParamVel) == 0);
    dJointAddAMotorTorques(j, 1, INFINITY, 0);
    CHECK(test_captured_count() == ++n);
    CHECK(dot3(dBodyGetTorque(b1), dBodyGetTorque(b1)) == 0);

    // Wrong type, no joint.
    dJointID hinge2 = dJointCreateHinge2(w, 0);
    dJointSetAMotorNumAxes(hinge2, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("hinge-2 joint"));
    CHECK(dJointGetAMotorNumAxes(NULL) == 0);
    CHECK(test_captured_count() == ++n);

    // In Euler mode the angles are measured: setting one is reported (as a
    // message) and ignored.
    dJointSetAMotorMode(j, dAMotorEuler);
    dJointSetAMotorAngle(j, 0, 1);
    CHECK(test_captured_count() == ++n && test_captured_contains("Euler"));
    CHECK(dJointGetAMotorAngle(j, 0) == 0);
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_hinge2_defaults_and_getters),
    TEST_CASE(test_hinge2_angles_follow_known_rotations),
    TEST_CASE(test_hinge2_rates_match_finite_differences),
    TEST_CASE(test_hinge2_suspension_sags_by_mg_over_kp),
    TEST_CASE(test_hinge2_anchors_coincide_under_load),
    TEST_CASE(test_hinge2_steering_stops_hold),
    TEST_CASE(test_hinge2_motors_one_step_and_force_limit),
    TEST_CASE(test_hinge2_axes_angle_restored),
    TEST_CASE(test_hinge2_caster_steering_held_while_wheel_driven),
    TEST_CASE(test_hinge2_torques),
    TEST_CASE(test_hinge2_reversed_attach_keeps_user_order),
    TEST_CASE(test_hinge2_bad_input),
    TEST_CASE(test_amotor_defaults_and_axes),
    TEST_CASE(test_amotor_euler_angles_follow_known_rotation),
    TEST_CASE(test_amotor_euler_rates_match_finite_differences),
    TEST_CASE(test_amotor_euler_stops_hold),
    TEST_CASE(test_amotor_euler_motor_reaches_rate),
    TEST_CASE(test_amotor_user_holds_spinning_body),
    TEST_CASE(test_amotor_user_velocity_motor_and_force_limit),
    TEST_CASE(test_amotor_user_stop_uses_set_angle),
    TEST_CASE(test_amotor_zero_axes_adds_nothing),
    TEST_CASE(test_amotor_torques),
    TEST_CASE(test_amotor_reversed_attach_keeps_user_order),
    TEST_CASE(test_amotor_bad_input),
    TEST_END
};
