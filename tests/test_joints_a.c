// SPDX-License-Identifier: BSD-3-Clause
//
// test_joints_a.c -- the slider, fixed, null and universal joints (guide 7.3):
// positions and angles against motions made by hand, rates against finite
// differences, the user's body order when attached as (0, b), motors and
// stops against one-step analytic results, joint error under load, and bad
// input reported without effect.

#include "test.h"

#include <math.h>

static const dReal g = 9.81;

// A body of mass m (a sphere of radius 0.1) at (x, y, z).
static dBodyID body_at(dWorldID w, dReal m, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass mass;
    dMassSetSphereTotal(&mass, m, 0.1);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    return b;
}

// Turn a body by angle about the world axis (x, y, z) (about its origin).
static void turn(dBodyID b, dReal x, dReal y, dReal z, dReal angle)
{
    dQuaternion t, q;
    dQFromAxisAndAngle(t, x, y, z, angle);
    dQMultiply0(q, t, dBodyGetQuaternion(b));
    dBodySetQuaternion(b, q);
}

static void move(dBodyID b, dReal dx, dReal dy, dReal dz)
{
    const dReal *p = dBodyGetPosition(b);
    dBodySetPosition(b, p[0] + dx, p[1] + dy, p[2] + dz);
}

static double distance3(const dReal *a, const dReal *b)
{
    return sqrt((double)((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                         (a[2] - b[2]) * (a[2] - b[2])));
}

// The angle of the rotation between two orientations.
static double rotation_between(const dReal *qa, const dReal *qb)
{
    dQuaternion d;
    dQMultiply1(d, qa, qb);
    double s = sqrt((double)(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]));
    return 2 * atan2(s, fabs((double)d[0]));
}

// ---- slider: geometry ------------------------------------------------------

static int test_slider_position_follows_displacement(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 2, 1, 0);
    turn(a, 1, 2, 3, 0.7);   // the bodies' own orientations do not matter
    turn(b, -1, 0, 2, 1.1);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, a, b);
    dJointSetSliderAxis(j, 0, 3, 4);   // normalised to (0, 0.6, 0.8)
    dVector3 ax;
    dJointGetSliderAxis(j, ax);
    CHECK_NEAR(ax[0], 0, TOL(1e-15, 1e-7));
    CHECK_NEAR(ax[1], 0.6, TOL(1e-15, 1e-7));
    CHECK_NEAR(ax[2], 0.8, TOL(1e-15, 1e-7));
    CHECK_NEAR(dJointGetSliderPosition(j), 0, TOL(1e-15, 1e-7));

    move(a, 0, 0.3, 0.4);   // body 1 along +axis by 0.5
    CHECK_NEAR(dJointGetSliderPosition(j), 0.5, TOL(1e-12, 1e-6));
    move(b, 0, 0.6, 0.8);   // body 2 along +axis by 1: body 1 is now 0.5 behind
    CHECK_NEAR(dJointGetSliderPosition(j), -0.5, TOL(1e-12, 1e-6));
    move(a, 5, 0.8, -0.6);  // across the axis: no change
    CHECK_NEAR(dJointGetSliderPosition(j), -0.5, TOL(1e-12, 1e-5));

    // Turning the whole pair rigidly (about body 2's origin) keeps the position.
    dQuaternion q;
    dQFromAxisAndAngle(q, 1, -1, 2, 0.9);
    dMatrix3 R;
    dRfromQ(R, q);
    dVector3 r, rr;
    const dReal *pa = dBodyGetPosition(a), *pb = dBodyGetPosition(b);
    dSubtractVectors3(r, pa, pb);
    dMultiply0_331(rr, R, r);
    dBodySetPosition(a, pb[0] + rr[0], pb[1] + rr[1], pb[2] + rr[2]);
    turn(a, 1, -1, 2, 0.9);
    turn(b, 1, -1, 2, 0.9);
    CHECK_NEAR(dJointGetSliderPosition(j), -0.5, TOL(1e-12, 1e-5));
    dWorldDestroy(w);
    return 0;
}

static int test_slider_rate_matches_finite_difference(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0.2, 0.1, 0), b = body_at(w, 1, 1, -1, 0.5);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, a, b);
    dJointSetSliderAxis(j, 1, 1, 0);
    const dReal va[3] = { 0.3, -0.2, 0.7 }, vb[3] = { -0.1, 0.4, 0.2 };
    const dReal wa[3] = { 0.5, -0.3, 0.8 };
    dBodySetLinearVel(a, va[0], va[1], va[2]);
    dBodySetLinearVel(b, vb[0], vb[1], vb[2]);
    dBodySetAngularVel(a, wa[0], wa[1], wa[2]);   // the axis turns with body 1
    dReal rate = dJointGetSliderPositionRate(j);

    // Move the bodies along that motion by +-dt and difference the positions:
    // the central difference is exact to O(dt^2) (|d2x/dt2| < 2 here).
    const dReal dt = 1e-4;
    const double wn = sqrt((double)(wa[0] * wa[0] + wa[1] * wa[1] + wa[2] * wa[2]));
    dReal pos[2];
    for (int s = 0; s < 2; s++) {
        dReal sign = s ? -1 : 1;
        move(a, sign * dt * va[0], sign * dt * va[1], sign * dt * va[2]);
        move(b, sign * dt * vb[0], sign * dt * vb[1], sign * dt * vb[2]);
        turn(a, wa[0], wa[1], wa[2], sign * dt * (dReal)wn);
        pos[s] = dJointGetSliderPosition(j);
        turn(a, wa[0], wa[1], wa[2], -sign * dt * (dReal)wn);
        move(a, -sign * dt * va[0], -sign * dt * va[1], -sign * dt * va[2]);
        move(b, -sign * dt * vb[0], -sign * dt * vb[1], -sign * dt * vb[2]);
    }
    CHECK_NEAR((pos[0] - pos[1]) / (2 * dt), rate, TOL(1e-7, 2e-2));
    // Without rotation it is the relative velocity along the axis.
    dBodySetAngularVel(a, 0, 0, 0);
    CHECK_NEAR(dJointGetSliderPositionRate(j), ((va[0] - vb[0]) + (va[1] - vb[1])) / sqrt(2.0),
               TOL(1e-15, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// Attached as (b, 0) body 1 is b; as (0, b) body 1 is the static world and b
// is body 2, so moving b along +axis is a negative position.
static int test_slider_user_order_when_attached_to_world(void)
{
    dWorldID w = dWorldCreate();
    for (int reversed = 0; reversed < 2; reversed++) {
        dBodyID b = body_at(w, 2, 1, 2, 3);
        dJointID j = dJointCreateSlider(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetSliderAxis(j, 0, 0, 2);
        const dReal sign = reversed ? -1 : 1;
        CHECK(dJointGetBody(j, reversed) == b);

        dVector3 ax;
        dJointGetSliderAxis(j, ax);
        CHECK(ax[0] == 0 && ax[1] == 0 && ax[2] == 1);   // the user's axis either way
        move(b, 0, 0, 0.25);
        CHECK_NEAR(dJointGetSliderPosition(j), sign * 0.25, TOL(1e-15, 1e-6));
        dBodySetLinearVel(b, 0, 0, 3);
        CHECK_NEAR(dJointGetSliderPositionRate(j), sign * 3, TOL(1e-15, 1e-6));

        // The force acts on body 1 along +axis: on b it is +F, or -F when b is body 2.
        dJointAddSliderForce(j, 4);
        CHECK_NEAR(dBodyGetForce(b)[2], sign * 4, 0);
        CHECK(dBodyGetForce(b)[0] == 0 && dBodyGetForce(b)[1] == 0);
        dJointDestroy(j);
        dBodyDestroy(b);
    }
    dWorldDestroy(w);
    return 0;
}

// The force pair acts at the midpoint of the centres: equal and opposite
// forces, and the added torques cancel the pair's couple.
static int test_slider_force_is_equal_and_opposite_without_couple(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 1, 2, 0.5);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, a, b);
    dJointSetSliderAxis(j, 1, 0, 0);
    dJointAddSliderForce(j, 5);
    const dReal *fa = dBodyGetForce(a), *fb = dBodyGetForce(b);
    const dReal *ta = dBodyGetTorque(a), *tb = dBodyGetTorque(b);
    CHECK(fa[0] == 5 && fa[1] == 0 && fa[2] == 0);
    CHECK(fb[0] == -5 && fb[1] == 0 && fb[2] == 0);
    // Net torque about the origin: pa x fa + pb x fb + ta + tb = 0.
    dVector3 net;
    dCalcVectorCross3(net, dBodyGetPosition(b), fb);
    dAddVectors3(net, net, ta);
    dAddVectors3(net, net, tb);
    for (int i = 0; i < 3; i++) CHECK_NEAR(net[i], 0, TOL(1e-15, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// As in ODE 0.16 (checked against it): for a body attached to the world the
// delta moves its zero to where the body would be displaced by delta, so the
// position now is -axis . delta as body 1 and +axis . delta as body 2;
// between two bodies the delta is not used.
static int test_slider_axis_delta_shifts_zero(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 0, 0, 1);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, a, 0);
    dJointSetSliderAxisDelta(j, 1, 0, 0, 0.25, 0, 0);
    CHECK_NEAR(dJointGetSliderPosition(j), -0.25, TOL(1e-15, 1e-7));
    move(a, 0.25, 0, 0);
    CHECK_NEAR(dJointGetSliderPosition(j), 0, TOL(1e-15, 1e-7));
    dJointAttach(j, 0, a);
    dJointSetSliderAxisDelta(j, 1, 0, 0, 0.25, 0, 0);
    CHECK_NEAR(dJointGetSliderPosition(j), 0.25, TOL(1e-15, 1e-7));
    dJointAttach(j, a, b);
    dJointSetSliderAxisDelta(j, 0, 0, 1, 0.5, 0, 0.125);
    CHECK(dJointGetSliderPosition(j) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_slider_params_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dJointID j = dJointCreateSlider(w, 0);
    // Defaults (guide 7.5): no stops, no motor, world ERP/CFM for the stops.
    CHECK(dJointGetSliderParam(j, dParamLoStop) == -dInfinity);
    CHECK(dJointGetSliderParam(j, dParamHiStop) == dInfinity);
    CHECK(dJointGetSliderParam(j, dParamFMax) == 0);
    CHECK(dJointGetSliderParam(j, dParamStopERP) == dWorldGetERP(w));
    CHECK(dJointGetSliderParam(j, dParamStopCFM) == dWorldGetCFM(w));
    const int params[] = { dParamLoStop, dParamHiStop, dParamVel, dParamFMax,
                           dParamFudgeFactor, dParamBounce, dParamCFM, dParamStopERP,
                           dParamStopCFM };
    for (unsigned i = 0; i < sizeof params / sizeof params[0]; i++) {
        dReal v = (dReal)(0.125 * (i + 1)) / 2;
        dJointSetSliderParam(j, params[i], v);
        CHECK(dJointGetSliderParam(j, params[i]) == v);
    }
    // A parameter the slider does not have: no effect, no report.
    test_capture_reports();
    dJointSetSliderParam(j, dParamSuspensionERP, 0.5);
    CHECK(dJointGetSliderParam(j, dParamSuspensionERP) == 0);
    CHECK(test_captured_count() == 0);
    dWorldDestroy(w);
    return 0;
}

// ---- slider: dynamics --------------------------------------------------------

// A motor is a velocity constraint (guide 7.5.1): with enough force it
// reaches its speed in one step, otherwise it accelerates at fmax / m. Its
// dParamCFM is 0 here: with the default (the world's 1e-10) the row gives way
// by cfm * force = 1e-10 * 300 = 3e-8.
static int test_slider_motor_reaches_velocity_in_one_step(void)
{
    const dReal h = 0.01, m = 2, v = 1.5;
    for (int reversed = 0; reversed < 2; reversed++) {
        dWorldID w = dWorldCreate();
        dBodyID b = body_at(w, m, 0, 0, 0);
        dJointID j = dJointCreateSlider(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetSliderAxis(j, 1, 2, 2);
        dJointSetSliderParam(j, dParamVel, v);
        dJointSetSliderParam(j, dParamFMax, 1000);   // m v / h = 300 is needed
        dJointSetSliderParam(j, dParamCFM, 0);
        dWorldStep(w, h);
        CHECK_NEAR(dJointGetSliderPositionRate(j), v, TOL(1e-9, 1e-5) * v);
        // b moves along +axis as body 1, along -axis as body 2.
        const dReal s = reversed ? -1 : 1;
        const dReal *lv = dBodyGetLinearVel(b);
        CHECK_NEAR(lv[0], s * v / 3, TOL(1e-9, 1e-5));
        CHECK_NEAR(lv[1], s * 2 * v / 3, TOL(1e-9, 1e-5));
        CHECK_NEAR(lv[2], s * 2 * v / 3, TOL(1e-9, 1e-5));
        dWorldDestroy(w);
    }
    return 0;
}

static int test_slider_motor_is_force_limited(void)
{
    const dReal h = 0.01, m = 2, fmax = 50;
    dWorldID w = dWorldCreate();
    dBodyID b = body_at(w, m, 0, 0, 0);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, b, 0);
    dJointSetSliderAxis(j, 0, 1, 0);
    dJointSetSliderParam(j, dParamVel, 10);
    dJointSetSliderParam(j, dParamFMax, fmax);
    dWorldStep(w, h);
    CHECK_NEAR(dJointGetSliderPositionRate(j), fmax * h / m, TOL(1e-9, 1e-6));
    dJointSetSliderParam(j, dParamVel, -10);   // the limit holds both ways
    dWorldStep(w, h);
    CHECK_NEAR(dJointGetSliderPositionRate(j), 0, TOL(1e-9, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// A motor between two bodies that are not on the axis. The relative sliding
// carries angular momentum (the bodies are off the axis line), so the pair
// starts to turn to keep the total zero; the forces act at the midpoint, so
// momentum and angular momentum stay zero. The motor row holds its speed in
// the geometry at the start of each step:
//   ax . (va - vb) + ((pb - pa) / 2 x ax) . (wa + wb) = vel.
static int test_slider_motor_between_bodies_conserves_momentum(void)
{
    const dReal h = 0.01, ma = 1, mb = 3;
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, ma, 0, 0, 0), b = body_at(w, mb, 1, 0.5, -0.3);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, a, b);
    dJointSetSliderAxis(j, 1, 0, 0);
    dJointSetSliderParam(j, dParamVel, 1);
    dJointSetSliderParam(j, dParamFMax, 1e4);
    dJointSetSliderParam(j, dParamCFM, 0);
    for (int i = 0; i < 10; i++) {
        dVector3 ax, half, ltd, dv, ws;
        dJointGetSliderAxis(j, ax);
        dSubtractVectors3(half, dBodyGetPosition(b), dBodyGetPosition(a));
        dScaleVector3(half, 0.5);
        dCalcVectorCross3(ltd, half, ax);
        dWorldStep(w, h);
        dSubtractVectors3(dv, dBodyGetLinearVel(a), dBodyGetLinearVel(b));
        dAddVectors3(ws, dBodyGetAngularVel(a), dBodyGetAngularVel(b));
        CHECK_NEAR(dCalcVectorDot3(ax, dv) + dCalcVectorDot3(ltd, ws), 1, TOL(1e-9, 1e-5));
    }
    CHECK(dCalcVectorLength3(dBodyGetAngularVel(a)) > 0.1);   // it does turn
    dVector3 p, L = { 0, 0, 0, 0 };
    dBodyID bodies[2] = { a, b };
    const dReal masses[2] = { ma, mb };
    for (int i = 0; i < 3; i++)
        p[i] = ma * dBodyGetLinearVel(a)[i] + mb * dBodyGetLinearVel(b)[i];
    for (int k = 0; k < 2; k++) {
        dVector3 mv, rxmv, Iw;
        dMass mass;
        dBodyGetMass(bodies[k], &mass);
        dCopyScaledVector3(mv, dBodyGetLinearVel(bodies[k]), masses[k]);
        dCalcVectorCross3(rxmv, dBodyGetPosition(bodies[k]), mv);
        dMultiply0_331(Iw, mass.I, dBodyGetAngularVel(bodies[k]));   // spheres: I is scalar
        dAddVectors3(L, L, rxmv);
        dAddVectors3(L, L, Iw);
    }
    for (int i = 0; i < 3; i++) CHECK_NEAR(p[i], 0, TOL(1e-9, 1e-5));
    for (int i = 0; i < 3; i++) CHECK_NEAR(L[i], 0, TOL(1e-9, 1e-5));
    // No relative turning either.
    CHECK_NEAR(rotation_between(dBodyGetQuaternion(a), dBodyGetQuaternion(b)), 0,
               TOL(1e-9, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// A body sliding down a vertical axis under gravity rests at the stop. The
// stop acts only once passed, so each step the body can fall g h^2 before
// the stop (ERP 0.2) pushes back: the error stays within g h^2 / erp.
static int test_slider_stop_holds_against_gravity(void)
{
    const dReal h = 0.001;
    for (int reversed = 0; reversed < 2; reversed++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, -g);
        dBodyID b = body_at(w, 1, 0, 0, 0);
        dJointID j = dJointCreateSlider(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetSliderAxis(j, 0, 0, 1);
        // b falls: position decreases as body 1, increases as body 2.
        dJointSetSliderParam(j, reversed ? dParamHiStop : dParamLoStop, reversed ? 0.3 : -0.3);
        for (int i = 0; i < 2000; i++) dWorldStep(w, h);
        CHECK_NEAR(dBodyGetPosition(b)[2], -0.3, g * h * h / 0.2 + TOL(1e-9, 1e-5));
        CHECK_NEAR(dJointGetSliderPosition(j), reversed ? 0.3 : -0.3, g * h * h / 0.2 + 1e-5);
        CHECK_NEAR(dBodyGetLinearVel(b)[2], 0, g * h + TOL(1e-9, 1e-5));
        dWorldDestroy(w);
    }
    return 0;
}

// dParamBounce 1: the body leaves the stop as fast as it came; 0.5: half.
static int test_slider_stop_bounces(void)
{
    const dReal h = 0.001, v0 = 1;
    const dReal bounces[2] = { 1, 0.5 };
    for (int k = 0; k < 2; k++) {
        dWorldID w = dWorldCreate();
        dBodyID b = body_at(w, 1, 0, 0, 0);
        dJointID j = dJointCreateSlider(w, 0);
        dJointAttach(j, b, 0);
        dJointSetSliderAxis(j, 1, 0, 0);
        dJointSetSliderParam(j, dParamHiStop, 0.1);
        dJointSetSliderParam(j, dParamBounce, bounces[k]);
        dJointSetSliderParam(j, dParamStopCFM, 0);   // else it gives way by cfm * force
        dBodySetLinearVel(b, v0, 0, 0);
        int steps = 0;
        while (dJointGetSliderPositionRate(j) > 0 && steps < 1000) {
            dWorldStep(w, h);
            steps++;
        }
        CHECK(steps < 200);   // it reached the stop (0.1 m at 1 m/s: 100 steps)
        // The restitution target -bounce * v exceeds the position correction
        // (fps * erp * overshoot <= 200 * 0.001 = 0.2), so it is met exactly.
        CHECK_NEAR(dJointGetSliderPositionRate(j), -bounces[k] * v0, TOL(1e-9, 1e-5));
        CHECK(dJointGetSliderPosition(j) <= 0.1 + v0 * h);
        dWorldDestroy(w);
    }
    return 0;
}

// Sideways forces and torques do not move the body off the axis or turn it;
// along the axis it accelerates freely (x_n = a h^2 n (n+1) / 2).
static int test_slider_blocks_perpendicular_motion(void)
{
    const dReal h = 0.01, m = 2;
    dWorldID w = dWorldCreate();
    dBodyID b = body_at(w, m, 0, 0, 0);
    dJointID j = dJointCreateSlider(w, 0);
    dJointAttach(j, b, 0);
    dJointSetSliderAxis(j, 1, 0, 0);
    const int n = 100;
    for (int i = 0; i < n; i++) {
        dBodyAddForce(b, 3, 10, -5);
        dBodyAddTorque(b, 1, 2, 3);
        dWorldStep(w, h);
    }
    // Steady error under force F: cfm F h / erp (5e-11 double, 5e-6 single).
    const dReal *p = dBodyGetPosition(b);
    CHECK_NEAR(p[1], 0, TOL(1e-6, 2e-5));
    CHECK_NEAR(p[2], 0, TOL(1e-6, 2e-5));
    CHECK_NEAR(p[0], 3 / m * h * h * n * (n + 1) / 2, TOL(1e-9, 1e-4));
    dQuaternion identity = { 1, 0, 0, 0 };
    CHECK_NEAR(rotation_between(dBodyGetQuaternion(b), identity), 0, TOL(1e-6, 1e-4));
    dWorldDestroy(w);
    return 0;
}

// ---- fixed -----------------------------------------------------------------

static int test_fixed_holds_bodies_against_gravity(void)
{
    const dReal h = 0.01;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -g);
    dBodyID a = body_at(w, 1, 0, 0, 1), b = body_at(w, 2, 0.5, 0.2, 0.8);
    turn(a, 1, 1, 0, 0.4);
    turn(b, 0, 1, 2, -0.9);
    dJointID ja = dJointCreateFixed(w, 0), jb = dJointCreateFixed(w, 0);
    dJointAttach(ja, a, 0);
    dJointSetFixed(ja);
    dJointAttach(jb, a, b);
    dJointSetFixed(jb);
    dVector3 pa0, pb0;
    dQuaternion qa0, qb0;
    dCopyVector3(pa0, dBodyGetPosition(a));
    dCopyVector3(pb0, dBodyGetPosition(b));
    dCopyVector4(qa0, dBodyGetQuaternion(a));
    dCopyVector4(qb0, dBodyGetQuaternion(b));
    for (int i = 0; i < 100; i++) dWorldStep(w, h);
    // Steady error cfm * force * h / erp: 1e-10 double, 1e-5 * 30 * 0.05 single.
    CHECK(distance3(dBodyGetPosition(a), pa0) < TOL(1e-6, 2e-5));
    CHECK(distance3(dBodyGetPosition(b), pb0) < TOL(1e-6, 5e-5));
    CHECK(rotation_between(dBodyGetQuaternion(a), qa0) < TOL(1e-6, 5e-5));
    CHECK(rotation_between(dBodyGetQuaternion(b), qb0) < TOL(1e-6, 5e-5));
    dWorldDestroy(w);
    return 0;
}

// Perturb the pose after dJointSetFixed: the error decays by (1 - erp) per
// step, from either attach order and between two free bodies. Two free bodies
// leave the correction slowly turning (the correcting forces act at anchors
// that are apart); then each step drifts off the pose by about w^2 r h^2 / 2
// (chord, not arc), of which ERP removes 0.2: the error settles there.
static int test_fixed_perturbed_returns_to_pose(void)
{
    const dReal h = 0.01;
    for (int mode = 0; mode < 3; mode++) {   // (b, 0), (0, b), (a, b)
        dWorldID w = dWorldCreate();
        dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1.5, 0.4, -0.3, 0.2);
        turn(a, 0, 0, 1, 0.3);
        turn(b, 1, 0, 0, 0.5);
        dJointID j = dJointCreateFixed(w, 0);
        if (mode == 0) dJointAttach(j, b, 0);
        else if (mode == 1) dJointAttach(j, 0, b);
        else dJointAttach(j, a, b);
        dJointSetFixed(j);
        // The pose to return to: b's position and orientation in a's frame.
        dVector3 r0, d;
        dQuaternion q0;
        dSubtractVectors3(d, dBodyGetPosition(b), dBodyGetPosition(a));
        dMultiply1_331(r0, dBodyGetRotation(a), d);
        dQMultiply1(q0, dBodyGetQuaternion(a), dBodyGetQuaternion(b));

        turn(b, 1, 2, -1, 0.4);
        move(b, 0.05, -0.02, 0.03);
        for (int i = 0; i < 200; i++) dWorldStep(w, h);
        dVector3 r;
        dQuaternion q;
        dSubtractVectors3(d, dBodyGetPosition(b), dBodyGetPosition(a));
        dMultiply1_331(r, dBodyGetRotation(a), d);
        dQMultiply1(q, dBodyGetQuaternion(a), dBodyGetQuaternion(b));
        // 0.8^200 ~ 4e-20: only rounding and the drift of a turning pair remain.
        const dReal *wa = dBodyGetAngularVel(a);
        double drift = dCalcVectorDot3(wa, wa) * dCalcVectorLength3(r0) * h * h / 2 / 0.2;
        CHECK(distance3(r, r0) < drift + TOL(1e-9, 1e-4));
        CHECK(rotation_between(q, q0) < TOL(1e-6, 1e-4));
        dWorldDestroy(w);
    }
    return 0;
}

// dParamERP 0 (per joint): the constraint holds the velocity but no longer
// corrects a position error, which then stays as it was.
static int test_fixed_param_erp_zero_keeps_error(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = body_at(w, 1, 0, 0, 0);
    dJointID j = dJointCreateFixed(w, 0);
    CHECK(dJointGetFixedParam(j, dParamERP) == dWorldGetERP(w));
    CHECK(dJointGetFixedParam(j, dParamCFM) == dWorldGetCFM(w));
    dJointSetFixedParam(j, dParamERP, 0);
    dJointSetFixedParam(j, dParamCFM, 1e-9);
    CHECK(dJointGetFixedParam(j, dParamERP) == 0);
    CHECK(dJointGetFixedParam(j, dParamCFM) == (dReal)1e-9);
    dJointAttach(j, b, 0);
    dJointSetFixed(j);
    move(b, 0.1, 0, 0);
    turn(b, 0, 0, 1, 0.2);
    for (int i = 0; i < 50; i++) dWorldStep(w, 0.01);
    CHECK_NEAR(dBodyGetPosition(b)[0], 0.1, TOL(1e-12, 1e-6));
    dQuaternion identity = { 1, 0, 0, 0 };
    CHECK_NEAR(rotation_between(dBodyGetQuaternion(b), identity), 0.2, TOL(1e-12, 1e-5));
    dJointSetFixedParam(j, dParamERP, 0.5);   // now it returns
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    CHECK_NEAR(dBodyGetPosition(b)[0], 0, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// ---- null ------------------------------------------------------------------

static int test_null_joint_adds_nothing(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -g);
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 0, 0, 0), c = body_at(w, 1, 3, 0, 0);
    dBodySetAngularVel(a, 1, 2, 3);
    dBodySetAngularVel(b, 1, 2, 3);
    dBodySetLinearVel(a, 0.5, 0, 2);
    dBodySetLinearVel(b, 0.5, 0, 2);
    dJointID j = dJointCreateNull(w, 0), k = dJointCreateNull(w, 0);
    dJointAttach(j, a, 0);
    dJointAttach(k, a, c);
    CHECK(dJointGetType(j) == dJointTypeNull);
    CHECK(dAreConnected(a, c));
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    // a follows exactly the path of the free body b.
    for (int i = 0; i < 3; i++) {
        CHECK(dBodyGetPosition(a)[i] == dBodyGetPosition(b)[i]);
        CHECK(dBodyGetAngularVel(a)[i] == dBodyGetAngularVel(b)[i]);
    }
    CHECK(dBodyGetPosition(c)[0] == 3);
    dWorldDestroy(w);
    return 0;
}

// ---- universal: geometry ----------------------------------------------------

static int test_universal_anchor_and_axes(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 1, 0, 0);
    turn(a, 1, 1, 1, 0.5);
    dJointID j = dJointCreateUniversal(w, 0);
    dVector3 v;
    dJointGetUniversalAxis1(j, v);   // defaults: axis 1 x, axis 2 y
    CHECK(v[0] == 1 && v[1] == 0 && v[2] == 0);
    dJointGetUniversalAxis2(j, v);
    CHECK(v[0] == 0 && v[1] == 1 && v[2] == 0);

    dJointAttach(j, a, b);
    dJointSetUniversalAnchor(j, 0.5, 0.25, 0);
    dJointSetUniversalAxis1(j, 0, 0, 3);
    dJointSetUniversalAxis2(j, 0, -2, 0);
    dJointGetUniversalAxis1(j, v);
    CHECK_NEAR(v[2], 1, TOL(1e-15, 1e-6));
    dJointGetUniversalAxis2(j, v);
    CHECK_NEAR(v[1], -1, TOL(1e-15, 1e-6));
    // Axis 1 turns with body 1, axis 2 with body 2; each anchor with its body.
    turn(a, 1, 0, 0, M_PI / 2);
    dJointGetUniversalAxis1(j, v);
    CHECK_NEAR(v[1], -1, TOL(1e-12, 1e-6));
    move(b, 0, 0, 1);
    dVector3 p1, p2;
    dJointGetUniversalAnchor(j, p1);
    dJointGetUniversalAnchor2(j, p2);
    CHECK_NEAR(p1[0], 0.5, TOL(1e-12, 1e-6));
    CHECK_NEAR(p1[2], 0.25, TOL(1e-12, 1e-6));   // turned about x with a
    CHECK_NEAR(p2[2], 1, TOL(1e-12, 1e-6));

    // Attached as (0, b): anchor 1 belongs to the world, axis 2 to b.
    dJointAttach(j, 0, b);
    dJointSetUniversalAnchor(j, 1, 2, 3);
    dJointSetUniversalAxis1(j, 1, 0, 0);
    dJointSetUniversalAxis2(j, 0, 0, 1);
    turn(b, 1, 0, 0, M_PI / 2);   // b is at (1, 0, 1): the anchor is (0, 2, 2) from it
    move(b, 0, 0, 1);
    dJointGetUniversalAnchor(j, p1);
    dJointGetUniversalAnchor2(j, p2);
    CHECK(p1[0] == 1 && p1[1] == 2 && p1[2] == 3);
    const dReal expect[3] = { 1, -2, 4 };   // (1, 0, 2) + (0, -2, 2)
    CHECK(distance3(p2, expect) < TOL(1e-12, 1e-5));
    dJointGetUniversalAxis1(j, v);
    CHECK(v[0] == 1);
    dJointGetUniversalAxis2(j, v);
    CHECK_NEAR(v[1], -1, TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// Set body 1's orientation to Q(a2, t2) Q(a1, t1) q1(0) (a1, a2 the world axes
// at zero) with body 2 at rest: the angles read (t1, t2). Turning body 2
// instead reads the opposite angle; turning both rigidly changes nothing.
static int test_universal_angles_follow_known_rotations(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 1, 1, 0);
    turn(a, 1, 2, 3, 0.7);
    turn(b, -2, 1, 0.5, 1.1);
    dQuaternion qa0, qb0;
    dCopyVector4(qa0, dBodyGetQuaternion(a));
    dCopyVector4(qb0, dBodyGetQuaternion(b));
    const dReal u[3] = { 1 / sqrt(2.0), 1 / sqrt(2.0), 0 }, v[3] = { 0, 0, 1 };
    dJointID j = dJointCreateUniversal(w, 0);
    dJointAttach(j, a, b);
    dJointSetUniversalAnchor(j, 0.5, 0.5, 0);
    dJointSetUniversalAxis1(j, u[0], u[1], u[2]);
    dJointSetUniversalAxis2(j, v[0], v[1], v[2]);
    CHECK_NEAR(dJointGetUniversalAngle1(j), 0, TOL(1e-15, 1e-6));
    CHECK_NEAR(dJointGetUniversalAngle2(j), 0, TOL(1e-15, 1e-6));

    const dReal cases[][2] = { { 0.5, 0 }, { 0, 0.5 }, { -2.9, 1.3 }, { 1, -3 }, { 3.1, 3.1 },
                               { -1.5, 2.0 } };
    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        dBodySetQuaternion(a, qa0);
        turn(a, u[0], u[1], u[2], cases[i][0]);
        turn(a, v[0], v[1], v[2], cases[i][1]);
        dReal t1, t2;
        dJointGetUniversalAngles(j, &t1, &t2);
        CHECK_NEAR(t1, cases[i][0], TOL(1e-12, 1e-5));
        CHECK_NEAR(t2, cases[i][1], TOL(1e-12, 1e-5));
        CHECK(dJointGetUniversalAngle1(j) == t1 && dJointGetUniversalAngle2(j) == t2);
        // A rigid turn of the pair keeps the angles.
        turn(a, 3, -1, 2, 2.2);
        turn(b, 3, -1, 2, 2.2);
        CHECK_NEAR(dJointGetUniversalAngle1(j), cases[i][0], TOL(1e-12, 1e-5));
        CHECK_NEAR(dJointGetUniversalAngle2(j), cases[i][1], TOL(1e-12, 1e-5));
        dBodySetQuaternion(b, qb0);
    }
    // Body 2 turning about either axis: body 1 turns the opposite way relative to it.
    dBodySetQuaternion(a, qa0);
    turn(b, u[0], u[1], u[2], 0.8);
    CHECK_NEAR(dJointGetUniversalAngle1(j), -0.8, TOL(1e-12, 1e-5));
    CHECK_NEAR(dJointGetUniversalAngle2(j), 0, TOL(1e-12, 1e-5));
    dBodySetQuaternion(b, qb0);
    turn(b, v[0], v[1], v[2], 0.6);
    CHECK_NEAR(dJointGetUniversalAngle1(j), 0, TOL(1e-12, 1e-5));
    CHECK_NEAR(dJointGetUniversalAngle2(j), -0.6, TOL(1e-12, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// Attached as (0, b), body 1 is the world: b turning by t about an axis reads -t.
static int test_universal_angles_when_attached_to_world(void)
{
    dWorldID w = dWorldCreate();
    for (int reversed = 0; reversed < 2; reversed++) {
        dBodyID b = body_at(w, 1, 0, 0, -1);
        dJointID j = dJointCreateUniversal(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetUniversalAnchor(j, 0, 0, 0);
        dJointSetUniversalAxis1(j, 1, 0, 0);
        dJointSetUniversalAxis2(j, 0, 1, 0);
        const dReal s = reversed ? -1 : 1;
        // Body 1 relative to body 2: q = Q(y, t2) Q(x, t1). As body 1, b turns
        // by that (about x first); as body 2, b turns by its inverse
        // Q(x, -t1) Q(y, -t2) (about y first).
        if (reversed) {
            turn(b, 0, 1, 0, -0.5);
            turn(b, 1, 0, 0, -0.3);
        } else {
            turn(b, 1, 0, 0, 0.3);
            turn(b, 0, 1, 0, 0.5);
        }
        dVector3 a1, a2;
        dJointGetUniversalAxis1(j, a1);
        dJointGetUniversalAxis2(j, a2);
        CHECK_NEAR(dCalcVectorDot3(a1, a2), 0, TOL(1e-15, 1e-7));   // a pose the joint allows
        CHECK_NEAR(dJointGetUniversalAngle1(j), 0.3, TOL(1e-12, 1e-6));
        CHECK_NEAR(dJointGetUniversalAngle2(j), 0.5, TOL(1e-12, 1e-6));
        // b turning about axis 2 (now): +rate as body 1, -rate as body 2.
        dBodySetAngularVel(b, 2 * a2[0], 2 * a2[1], 2 * a2[2]);
        CHECK_NEAR(dJointGetUniversalAngle2Rate(j), s * 2, TOL(1e-15, 1e-6));
        CHECK_NEAR(dJointGetUniversalAngle1Rate(j), 0, TOL(1e-15, 1e-6));
        dJointDestroy(j);
        dBodyDestroy(b);
    }
    dWorldDestroy(w);
    return 0;
}

// Along a motion the joint allows, body 2 turning at wb and the angles
// changing at (r1, r2), the rates read (r1, r2) and equal the central
// differences of the angles.
static int test_universal_rates_match_finite_differences(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 0, 0, 1);
    turn(a, 2, 1, 0, 0.4);
    turn(b, 0, 1, 1, -0.6);
    dQuaternion qa0, qb0;
    dCopyVector4(qa0, dBodyGetQuaternion(a));
    dCopyVector4(qb0, dBodyGetQuaternion(b));
    const dReal u[3] = { 0, 0.6, 0.8 }, v[3] = { 1, 0, 0 }, wb[3] = { 0.3, -0.5, 0.4 };
    const dReal t10 = 0.7, t20 = -1.1, r1 = 0.9, r2 = -0.4;
    dJointID j = dJointCreateUniversal(w, 0);
    dJointAttach(j, a, b);
    dJointSetUniversalAnchor(j, 0, 0, 0.5);
    dJointSetUniversalAxis1(j, u[0], u[1], u[2]);
    dJointSetUniversalAxis2(j, v[0], v[1], v[2]);

    // Pose at time t: q1 = Q(wb t) Q(v, t2) Q(u, t1) qa0, q2 = Q(wb t) qb0.
    const dReal wn = dCalcVectorLength3(wb);
    dReal angle1[2], angle2[2];
    const dReal dt = TOL(1e-4, 1e-2);
    for (int k = 0; k < 3; k++) {
        const int s = k == 2 ? 0 : 2 * k - 1;   // -1, +1, then 0 to stay there
        dBodySetQuaternion(a, qa0);
        dBodySetQuaternion(b, qb0);
        turn(a, u[0], u[1], u[2], t10 + r1 * s * dt);
        turn(a, v[0], v[1], v[2], t20 + r2 * s * dt);
        turn(a, wb[0], wb[1], wb[2], wn * s * dt);
        turn(b, wb[0], wb[1], wb[2], wn * s * dt);
        if (s != 0) {
            angle1[s > 0] = dJointGetUniversalAngle1(j);
            angle2[s > 0] = dJointGetUniversalAngle2(j);
        }
    }
    // At t = 0: w1 = wb + r2 v + r1 (axis 1 now) = wb + r2 v + r1 Q(v, t20) u.
    dVector3 ax1, w1;
    dJointGetUniversalAxis1(j, ax1);
    for (int i = 0; i < 3; i++) w1[i] = wb[i] + r2 * v[i] + r1 * ax1[i];
    dBodySetAngularVel(a, w1[0], w1[1], w1[2]);
    dBodySetAngularVel(b, wb[0], wb[1], wb[2]);
    CHECK_NEAR(dJointGetUniversalAngle1(j), t10, TOL(1e-12, 1e-5));
    CHECK_NEAR(dJointGetUniversalAngle2(j), t20, TOL(1e-12, 1e-5));
    CHECK_NEAR(dJointGetUniversalAngle1Rate(j), r1, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetUniversalAngle2Rate(j), r2, TOL(1e-12, 1e-6));
    // The angles are linear in t along this motion: only rounding / dt remains.
    CHECK_NEAR((angle1[1] - angle1[0]) / (2 * dt), r1, TOL(1e-9, 1e-3));
    CHECK_NEAR((angle2[1] - angle2[0]) / (2 * dt), r2, TOL(1e-9, 1e-3));
    dWorldDestroy(w);
    return 0;
}

// The offsets name the current angles (like dJointSetHingeAxisOffset).
static int test_universal_axis_offsets_set_current_angles(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 0, 0, 1);
    turn(a, 1, 0, 1, 0.3);
    dJointID j = dJointCreateUniversal(w, 0);
    dJointAttach(j, a, b);
    dJointSetUniversalAnchor(j, 0, 0, 0.5);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    dJointSetUniversalAxis1Offset(j, 1, 0, 0, 0.4, -0.25);
    CHECK_NEAR(dJointGetUniversalAngle1(j), 0.4, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetUniversalAngle2(j), -0.25, TOL(1e-12, 1e-6));
    turn(a, 1, 0, 0, 0.1);   // axis 1 (on a) is still x in the world
    CHECK_NEAR(dJointGetUniversalAngle1(j), 0.5, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetUniversalAngle2(j), -0.25, TOL(1e-12, 1e-6));
    dJointSetUniversalAxis2Offset(j, 0, 1, 0, -1, 2);
    CHECK_NEAR(dJointGetUniversalAngle1(j), -1, TOL(1e-12, 1e-6));
    CHECK_NEAR(dJointGetUniversalAngle2(j), 2, TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

static int test_universal_torques_are_equal_and_opposite(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = body_at(w, 1, 0, 0, 0), b = body_at(w, 1, 1, 0, 0);
    dJointID j = dJointCreateUniversal(w, 0);
    dJointAttach(j, a, b);
    dJointSetUniversalAxis1(j, 0, 0, 1);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    dJointAddUniversalTorques(j, 2, 3);
    const dReal *ta = dBodyGetTorque(a), *tb = dBodyGetTorque(b);
    CHECK(ta[0] == 0 && ta[1] == 3 && ta[2] == 2);
    CHECK(tb[0] == 0 && tb[1] == -3 && tb[2] == -2);
    CHECK(dBodyGetForce(a)[0] == 0 && dBodyGetForce(b)[0] == 0);
    // As (0, b), b is body 2 and receives the opposite torque.
    dJointAttach(j, 0, b);
    dJointSetUniversalAxis1(j, 0, 0, 1);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    dJointAddUniversalTorques(j, 1, 1);
    CHECK(tb[0] == 0 && tb[1] == -4 && tb[2] == -3);
    dWorldDestroy(w);
    return 0;
}

// ---- universal: dynamics -----------------------------------------------------

// A pendulum hanging from the world by a universal joint, released off-centre
// (default ERP): the anchors stay together and the axes perpendicular. The
// position update drifts off the joint by about w^2 r h^2 / 2 per step (a
// chord, not an arc) and ERP removes 0.2 of the error per step: with
// w^2 r < 2.1 here and h 0.001 that is about 5e-6.
static int test_universal_pendulum_keeps_anchor_and_axes(void)
{
    const dReal h = 0.001;
    for (int reversed = 0; reversed < 2; reversed++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, -g);
        dBodyID b = body_at(w, 1, 0.4, 0.3, -1);
        dJointID j = dJointCreateUniversal(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetUniversalAnchor(j, 0, 0, 0);
        dJointSetUniversalAxis1(j, 1, 0, 0);
        dJointSetUniversalAxis2(j, 0, 1, 0);
        double gap = 0, dot = 0, swing = 0;
        for (int i = 0; i < 5000; i++) {
            dWorldStep(w, h);
            dVector3 p1, p2, a1, a2;
            dJointGetUniversalAnchor(j, p1);
            dJointGetUniversalAnchor2(j, p2);
            dJointGetUniversalAxis1(j, a1);
            dJointGetUniversalAxis2(j, a2);
            gap = fmax(gap, distance3(p1, p2));
            dot = fmax(dot, fabs((double)dCalcVectorDot3(a1, a2)));
            swing = fmax(swing, fabs((double)dJointGetUniversalAngle1(j)));
        }
        CHECK(gap < 1e-4);
        CHECK(dot < 1e-4);
        CHECK(swing > 0.2);   // it did swing
        dWorldDestroy(w);
    }
    return 0;
}

// A motor on either axis reaches its speed in one step; with the anchor at the
// body's centre nothing else turns it. Axis 1 on b stays put as b turns about
// it, axis 2 on the world stays put: the rates after the step are exact.
static int test_universal_motors_reach_velocity(void)
{
    const dReal h = 0.01;
    for (int reversed = 0; reversed < 2; reversed++) {
        for (int axis = 0; axis < 2; axis++) {
            dWorldID w = dWorldCreate();
            dBodyID b = body_at(w, 1, 0, 0, 0);
            dJointID j = dJointCreateUniversal(w, 0);
            if (reversed) dJointAttach(j, 0, b);
            else dJointAttach(j, b, 0);
            dJointSetUniversalAnchor(j, 0, 0, 0);
            dJointSetUniversalAxis1(j, 1, 0, 0);
            dJointSetUniversalAxis2(j, 0, 0, 1);
            const int group = axis ? dParamGroup2 : dParamGroup1;
            dJointSetUniversalParam(j, group + dParamVel, axis ? -1.5 : 2);
            dJointSetUniversalParam(j, group + dParamFMax, 100);
            CHECK(dJointGetUniversalParam(j, group + dParamFMax) == 100);
            CHECK(dJointGetUniversalParam(j, (dParamGroup2 - group) + dParamFMax) == 0);
            dWorldStep(w, h);
            const dReal r1 = dJointGetUniversalAngle1Rate(j), r2 = dJointGetUniversalAngle2Rate(j);
            CHECK_NEAR(r1, axis ? 0 : 2, TOL(1e-9, 1e-5));
            CHECK_NEAR(r2, axis ? -1.5 : 0, TOL(1e-9, 1e-5));
            // b as body 2 turns the opposite way.
            const dReal *wv = dBodyGetAngularVel(b);
            CHECK_NEAR(wv[axis ? 2 : 0], (reversed ? -1 : 1) * (axis ? -1.5 : 2), TOL(1e-9, 1e-5));
            dWorldDestroy(w);
        }
    }
    return 0;
}

// A constant torque about each axis drives the joint into its stops; the
// angles settle there (StopERP 0.2; residual cfm torque h / erp, tiny).
static int test_universal_stops_hold(void)
{
    const dReal h = 0.01;
    for (int reversed = 0; reversed < 2; reversed++) {
        dWorldID w = dWorldCreate();
        dBodyID b = body_at(w, 1, 0, 0, 0);
        dJointID j = dJointCreateUniversal(w, 0);
        if (reversed) dJointAttach(j, 0, b);
        else dJointAttach(j, b, 0);
        dJointSetUniversalAnchor(j, 0, 0, 0);
        dJointSetUniversalAxis1(j, 1, 0, 0);
        dJointSetUniversalAxis2(j, 0, 1, 0);
        dJointSetUniversalParam(j, dParamHiStop, 0.5);
        dJointSetUniversalParam(j, dParamLoStop2, -0.4);
        for (int i = 0; i < 300; i++) {
            dJointAddUniversalTorques(j, 0.05, -0.05);   // toward +angle1 and -angle2
            dWorldStep(w, h);
        }
        // Each step the torque turns the joint by at most tau h^2 / I past the
        // stop (tau 0.05, I 0.004) before the stop row corrects it.
        const dReal slack = 0.05 * h * h / 0.004 / 0.2 + 1e-3;
        CHECK_NEAR(dJointGetUniversalAngle1(j), 0.5, slack);
        CHECK_NEAR(dJointGetUniversalAngle2(j), -0.4, slack);
        dWorldDestroy(w);
    }
    return 0;
}

// ---- bad input ---------------------------------------------------------------

static int test_bad_input_is_reported_without_effect(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = body_at(w, 1, 0, 0, 0);
    dJointID hinge = dJointCreateHinge(w, 0), s = dJointCreateSlider(w, 0);
    dJointID u = dJointCreateUniversal(w, 0), f = dJointCreateFixed(w, 0);
    dJointAttach(hinge, b, 0);
    dJointAttach(s, b, 0);
    dJointAttach(u, b, 0);
    dJointAttach(f, b, 0);
    dJointSetSliderAxis(s, 0, 1, 0);
    dJointSetUniversalAnchor(u, 1, 2, 3);
    dJointSetUniversalAxis1(u, 0, 0, 1);
    dJointSetHingeAxis(hinge, 0, 0, 1);
    test_capture_reports();

    dJointSetSliderAxis(hinge, 1, 0, 0);   // wrong joint type
    CHECK(test_captured_contains("dJointSetSliderAxis"));
    CHECK(test_captured_contains("hinge"));
    dVector3 v;
    dJointGetHingeAxis(hinge, v);
    CHECK(v[2] == 1);
    int n = test_captured_count();
    CHECK(dJointGetUniversalAngle1(s) == 0);
    CHECK(dJointGetSliderPosition(u) == 0);
    dJointSetFixed(s);
    dJointSetFixedParam(u, dParamERP, 0.5);
    CHECK(test_captured_count() == n + 4);

    dJointSetSliderAxis(s, 0, 0, 0);   // zero axis
    CHECK(test_captured_contains("dJointSetSliderAxis"));
    dJointSetSliderAxis(s, NAN, 0, 1);   // NaN
    dJointSetSliderAxisDelta(s, 1, 0, 0, 0, INFINITY, 0);
    dJointGetSliderAxis(s, v);
    CHECK(v[0] == 0 && v[1] == 1 && v[2] == 0);
    dJointSetSliderParam(s, dParamVel, NAN);
    CHECK(dJointGetSliderParam(s, dParamVel) == 0);
    dJointSetSliderParam(s, 0x100 + dParamVel, 1);   // the slider has one group
    CHECK(test_captured_contains("dJointSetSliderParam"));
    CHECK(dJointGetSliderParam(s, dParamVel) == 0);
    dJointAddSliderForce(s, NAN);
    CHECK(dBodyGetForce(b)[0] == 0 && dBodyGetForce(b)[1] == 0);

    n = test_captured_count();
    dJointSetUniversalParam(u, 0x300, 1);   // no third group
    CHECK(test_captured_contains("dJointSetUniversalParam"));
    CHECK(dJointGetUniversalParam(u, 0x300) == 0);
    CHECK(test_captured_contains("dJointGetUniversalParam"));
    dJointSetUniversalAnchor(u, 0, NAN, 0);
    dJointSetUniversalAxis2(u, 0, 0, 0);
    dJointSetUniversalAxis1Offset(u, 1, 0, 0, NAN, 0);
    dJointAddUniversalTorques(u, INFINITY, 0);
    dJointGetUniversalAnchor(u, NULL);
    dReal a1;
    dJointGetUniversalAngles(u, &a1, NULL);
    CHECK(test_captured_count() == n + 8);
    dJointGetUniversalAnchor(u, v);
    CHECK(v[0] == 1 && v[1] == 2 && v[2] == 3);
    dJointGetUniversalAxis1(u, v);
    CHECK(v[2] == 1);
    dJointGetUniversalAxis2(u, v);
    CHECK(v[1] == 1);   // the default, unchanged
    CHECK(dBodyGetTorque(b)[0] == 0);

    n = test_captured_count();
    dJointSetFixedParam(f, dParamCFM, NAN);
    CHECK(dJointGetFixedParam(f, dParamCFM) == dWorldGetCFM(w));
    CHECK(dJointGetFixedParam(f, 0x100 + dParamERP) == 0);
    CHECK(dJointCreateNull(0, 0) == NULL);
    CHECK(dJointCreateSlider(0, 0) == NULL);
    CHECK(test_captured_count() == n + 4);
    dWorldDestroy(w);
    return 0;
}

// Setters on an unattached joint do nothing (guide 7.4) and report nothing.
static int test_setters_on_unattached_joints_do_nothing(void)
{
    dWorldID w = dWorldCreate();
    dJointID s = dJointCreateSlider(w, 0), u = dJointCreateUniversal(w, 0);
    dJointID f = dJointCreateFixed(w, 0);
    test_capture_reports();
    dJointSetSliderAxis(s, 0, 1, 0);
    dJointSetUniversalAnchor(u, 1, 2, 3);
    dJointSetUniversalAxis1Offset(u, 0, 0, 1, 0.5, 0.5);
    dJointSetFixed(f);
    CHECK(test_captured_count() == 0);
    dVector3 v;
    dJointGetSliderAxis(s, v);
    CHECK(v[0] == 1 && v[1] == 0);
    CHECK(dJointGetSliderPosition(s) == 0 && dJointGetSliderPositionRate(s) == 0);
    dJointGetUniversalAnchor(u, v);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == 0);
    CHECK(dJointGetUniversalAngle1(u) == 0 && dJointGetUniversalAngle2Rate(u) == 0);
    dWorldStep(w, 0.01);   // joints in limbo are harmless
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_slider_position_follows_displacement),
    TEST_CASE(test_slider_rate_matches_finite_difference),
    TEST_CASE(test_slider_user_order_when_attached_to_world),
    TEST_CASE(test_slider_force_is_equal_and_opposite_without_couple),
    TEST_CASE(test_slider_axis_delta_shifts_zero),
    TEST_CASE(test_slider_params_round_trip),
    TEST_CASE(test_slider_motor_reaches_velocity_in_one_step),
    TEST_CASE(test_slider_motor_is_force_limited),
    TEST_CASE(test_slider_motor_between_bodies_conserves_momentum),
    TEST_CASE(test_slider_stop_holds_against_gravity),
    TEST_CASE(test_slider_stop_bounces),
    TEST_CASE(test_slider_blocks_perpendicular_motion),
    TEST_CASE(test_fixed_holds_bodies_against_gravity),
    TEST_CASE(test_fixed_perturbed_returns_to_pose),
    TEST_CASE(test_fixed_param_erp_zero_keeps_error),
    TEST_CASE(test_null_joint_adds_nothing),
    TEST_CASE(test_universal_anchor_and_axes),
    TEST_CASE(test_universal_angles_follow_known_rotations),
    TEST_CASE(test_universal_angles_when_attached_to_world),
    TEST_CASE(test_universal_rates_match_finite_differences),
    TEST_CASE(test_universal_axis_offsets_set_current_angles),
    TEST_CASE(test_universal_torques_are_equal_and_opposite),
    TEST_CASE(test_universal_pendulum_keeps_anchor_and_axes),
    TEST_CASE(test_universal_motors_reach_velocity),
    TEST_CASE(test_universal_stops_hold),
    TEST_CASE(test_bad_input_is_reported_without_effect),
    TEST_CASE(test_setters_on_unattached_joints_do_nothing),
    TEST_END
};
