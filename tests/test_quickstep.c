// SPDX-License-Identifier: BSD-3-Clause
//
// test_quickstep.c -- dWorldQuickStep (guide 5.1): the iterative stepper
// against analytic pendulum motion, against dWorldStep, limits, motors,
// contacts and friction, stacks and a pyramid of boxes, its parameters, bad
// input, large systems and allocation behaviour.

#include "test.h"

#include <math.h>
#include <stdio.h>

#define G 9.81
#define PI 3.14159265358979323846

// A body of mass m at (x, y, z): a sphere of radius r (small r: a point mass).
static dBodyID sphere_body(dWorldID w, double x, double y, double z, double m, double r)
{
    dBodyID b = dBodyCreate(w);
    dMass mass;
    dMassSetSphereTotal(&mass, m, r);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    return b;
}

static double distance(const dReal *a, const dReal *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double ball_separation(dJointID j)
{
    dVector3 a1, a2;
    dJointGetBallAnchor(j, a1);
    dJointGetBallAnchor2(j, a2);
    return distance(a1, a2);
}

// ---- no constraints ---------------------------------------------------------

// Without rows QuickStep is the same integration as dWorldStep: bit for bit.
static int test_free_fall_matches_world_step(void)
{
    dWorldID w[2];
    dBodyID b[2];
    for (int k = 0; k < 2; k++) {
        w[k] = dWorldCreate();
        dWorldSetGravity(w[k], 0.5, 0, -G);
        b[k] = dBodyCreate(w[k]);
        dMass m;
        dMassSetBoxTotal(&m, 2, 0.3, 0.5, 0.9);   // unequal inertia: gyroscopic torque
        dBodySetMass(b[k], &m);
        dBodySetLinearVel(b[k], 1, 2, 3);
        dBodySetAngularVel(b[k], 0.7, -2, 5);
    }
    for (int s = 0; s < 200; s++) {
        dBodyAddForce(b[0], 0.1 * s, 0, 0);
        dBodyAddForce(b[1], 0.1 * s, 0, 0);
        CHECK(dWorldStep(w[0], 0.01) == 1);
        CHECK(dWorldQuickStep(w[1], 0.01) == 1);
    }
    const dReal *p0 = dBodyGetPosition(b[0]), *p1 = dBodyGetPosition(b[1]);
    const dReal *q0 = dBodyGetQuaternion(b[0]), *q1 = dBodyGetQuaternion(b[1]);
    const dReal *v0 = dBodyGetLinearVel(b[0]), *v1 = dBodyGetLinearVel(b[1]);
    const dReal *a0 = dBodyGetAngularVel(b[0]), *a1 = dBodyGetAngularVel(b[1]);
    for (int i = 0; i < 3; i++) {
        CHECK(p0[i] == p1[i]);
        CHECK(v0[i] == v1[i]);
        CHECK(a0[i] == a1[i]);
    }
    for (int i = 0; i < 4; i++) CHECK(q0[i] == q1[i]);
    // And it is free fall: z(t) = z0 + v0 t - g t^2 / 2 up to the O(h) of
    // semi-implicit Euler (g h t / 2 = 0.098 m at t = 2 s, h = 0.01).
    CHECK_NEAR(p1[2], 3 * 2.0 - 0.5 * G * 4 - 0.5 * G * 0.01 * 2, TOL(1e-9, 1e-3));
    dWorldDestroy(w[0]);
    dWorldDestroy(w[1]);
    return 0;
}

// ---- pendulums ----------------------------------------------------------------

// Simulate a pendulum of length L released at angle theta0 from the vertical,
// swinging in the x-z plane about the origin, for `seconds` with step h.
// Returns the largest deviation of its length from L and the mean period,
// measured between upward zero crossings of x.
static int run_pendulum(dWorldID w, dBodyID b, double L, double seconds, double h,
                        double *max_length_error, double *period)
{
    const dVector3 origin = { 0, 0, 0, 0 };
    double prev_x = dBodyGetPosition(b)[0], first = -1, last = -1;
    int crossings = 0;
    *max_length_error = 0;
    int steps = (int)(seconds / h + 0.5);
    for (int s = 1; s <= steps; s++) {
        if (!dWorldQuickStep(w, h)) return 1;
        const dReal *p = dBodyGetPosition(b);
        double e = fabs(distance(p, origin) - L);
        if (e > *max_length_error) *max_length_error = e;
        double x = p[0];
        if (prev_x < 0 && x >= 0) {
            double t = h * (s - 1 + prev_x / (prev_x - x));
            if (crossings == 0) first = t;
            last = t;
            crossings++;
        }
        prev_x = x;
    }
    *period = crossings > 1 ? (last - first) / (crossings - 1) : 0;
    return 0;
}

// A small ball on a ball joint to the static world: length kept within 1 mm
// over 10 s with the default ERP/CFM and 20 iterations; small-angle period
// 2 pi sqrt(L/g) within 1 %. (Amplitude 0.1 rad: the finite-amplitude
// correction theta0^2/16 = 0.06 %; the sphere's own inertia adds 2e-5.)
// The ball's small inertia (radius 1 cm) makes the joint's 3x3 block badly
// conditioned: iterated row by row the length drifts by 3 mm (7 mm in ODE
// 0.16); QuickStep solves the block exactly.
static int test_ball_pendulum_length_and_period(void)
{
    const double L = 1, theta0 = 0.1;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    CHECK(dWorldGetQuickStepNumIterations(w) == 20);
    dBodyID b = sphere_body(w, L * sin(theta0), 0, -L * cos(theta0), 1, 0.01);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetBallAnchor(j, 0, 0, 0);
    double err, period;
    CHECK(run_pendulum(w, b, L, 10, 0.01, &err, &period) == 0);
    double expected = 2 * PI * sqrt(L / G);
    printf("# ball pendulum: length error %.3g m, period %.5g s (2 pi sqrt(L/g) = %.5g s)\n",
           err, period, expected);
    CHECK(err < 1e-3);
    CHECK_NEAR(period, expected, 0.01 * expected);
    dWorldDestroy(w);
    return 0;
}

// The same with a hinge about the horizontal y axis.
static int test_hinge_pendulum_length_and_period(void)
{
    const double L = 0.5, theta0 = 0.1;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID b = sphere_body(w, L * sin(theta0), 0, -L * cos(theta0), 2, 0.01);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 1, 0);
    double err, period;
    CHECK(run_pendulum(w, b, L, 10, 0.005, &err, &period) == 0);
    double expected = 2 * PI * sqrt(L / G);
    printf("# hinge pendulum: length error %.3g m, period %.5g s (2 pi sqrt(L/g) = %.5g s)\n",
           err, period, expected);
    CHECK(err < 1e-3);
    CHECK_NEAR(period, expected, 0.01 * expected);
    // The hinge keeps the motion in the x-z plane.
    CHECK_NEAR(dBodyGetPosition(b)[1], 0, 1e-6);
    dWorldDestroy(w);
    return 0;
}

// ---- chains ---------------------------------------------------------------------

// n rods of length l (boxes, mass 0.1 kg) joined end to end by ball joints,
// the first to the static world at the origin, lying straight at `angle`
// below the +x axis in the x-z plane (so they fall and swing). joints[k]
// joins rod k-1 (or the world) and rod k.
static void make_chain(dWorldID w, int n, double l, double angle, dBodyID *rods,
                       dJointID *joints)
{
    const double ux = cos(angle), uz = -sin(angle);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, angle);
    for (int k = 0; k < n; k++) {
        rods[k] = dBodyCreate(w);
        dMass m;
        dMassSetBoxTotal(&m, 0.1, l, 0.02, 0.02);
        dBodySetMass(rods[k], &m);
        dBodySetPosition(rods[k], (k + 0.5) * l * ux, 0, (k + 0.5) * l * uz);
        dBodySetRotation(rods[k], R);
        joints[k] = dJointCreateBall(w, 0);
        dJointAttach(joints[k], rods[k], k > 0 ? rods[k - 1] : 0);
        dJointSetBallAnchor(joints[k], k * l * ux, 0, k * l * uz);
    }
}

// Largest separation of any joint of a 20-link chain (2 m) released at
// `angle` over 10 s, stepped with h = 0.01 by QuickStep with `iterations`
// (or by dWorldStep if iterations is 0).
static double chain_max_separation(double angle, int iterations)
{
    enum { N = 20 };
    dBodyID rods[N];
    dJointID joints[N];
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    if (iterations > 0) dWorldSetQuickStepNumIterations(w, iterations);
    make_chain(w, N, 0.1, angle, rods, joints);
    double worst = 0;
    for (int s = 0; s < 1000; s++) {
        if (iterations > 0) dWorldQuickStep(w, 0.01);
        else dWorldStep(w, 0.01);
        for (int k = 0; k < N; k++) {
            double e = ball_separation(joints[k]);
            if (!(e <= worst)) worst = e;   // NaN propagates
        }
    }
    dWorldDestroy(w);
    return worst;
}

// A 20-link chain released at 45 degrees: the joints stay together within
// 1 cm over 10 s with the default 20 iterations. What remains is mostly the
// step's own drift (ERP corrects position errors 20 % per step): dWorldStep,
// exact each step, does about as well.
static int test_chain_joint_separation(void)
{
    double sep20 = chain_max_separation(PI / 4, 20);
    double sep100 = chain_max_separation(PI / 4, 100);
    double exact = chain_max_separation(PI / 4, 0);
    printf("# 20-link chain at 45 deg, max joint separation over 10 s: %.3g m (20 iterations), "
           "%.3g m (100 iterations), %.3g m (dWorldStep)\n", sep20, sep100, exact);
    CHECK(sep20 < 1e-2);
    CHECK(sep100 < 1e-2);
    CHECK(sep20 < 1.5 * exact);
    return 0;
}

// Released 10 degrees from hanging, the chain's tension must cross 20 links
// and iterations matter: 100 iterations come close to dWorldStep.
static int test_hanging_chain_converges_with_iterations(void)
{
    const double angle = PI / 2 - PI / 18;
    double sep20 = chain_max_separation(angle, 20);
    double sep100 = chain_max_separation(angle, 100);
    double exact = chain_max_separation(angle, 0);
    printf("# 20-link chain at 80 deg: %.3g m (20 iterations), %.3g m (100 iterations), "
           "%.3g m (dWorldStep)\n", sep20, sep100, exact);
    CHECK(sep20 < 1e-2);
    CHECK(sep100 < sep20);
    CHECK(sep100 < 2 * exact);
    return 0;
}

// 1000 bodies in one island: no recursion or stack arrays, so no overflow;
// the hanging chain stays finite and attached at the top.
static int test_thousand_body_chain(void)
{
    enum { N = 1000 };
    static dBodyID rods[N];
    static dJointID joints[N];
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    make_chain(w, N, 0.05, PI / 2, rods, joints);
    for (int s = 0; s < 20; s++) CHECK(dWorldQuickStep(w, 0.01) == 1);
    for (int k = 0; k < N; k++) {
        const dReal *p = dBodyGetPosition(rods[k]);
        CHECK(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]));
    }
    // In 0.2 s the top of the chain falls 0.2 m freely at most; the joint to
    // the world holds it far better than that.
    CHECK(ball_separation(joints[0]) < 0.01);
    dWorldDestroy(w);
    return 0;
}

// A kinematic body is not part of the island: the rows on it act on the bob
// alone (the solver puts the island body first; the support is attached as
// the joint's first body here) and its velocity enters the rows. A bob
// hanging from a kinematic support moving at constant velocity ends up moving
// with it.
static int test_pendulum_on_moving_kinematic_support(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID support = dBodyCreate(w);
    dBodySetKinematic(support);
    dBodySetLinearVel(support, 1, 0, 0);
    dBodyID bob = sphere_body(w, 0, 0, -1, 1, 0.1);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, support, bob);
    dJointSetBallAnchor(j, 0, 0, 0);
    // The bob starts at rest and swings behind; a viscous drag relative to
    // the support (time constant 0.5 s) settles it within 10 s.
    double worst = 0;
    for (int s = 0; s < 1000; s++) {
        const dReal *v = dBodyGetLinearVel(bob);
        dBodyAddForce(bob, -2 * (v[0] - 1), -2 * v[1], -2 * v[2]);
        CHECK(dWorldQuickStep(w, 0.01) == 1);
        worst = fmax(worst, ball_separation(j));
    }
    CHECK(worst < 1e-3);
    CHECK_NEAR(dBodyGetPosition(support)[0], 10, TOL(1e-9, 1e-3));   // 1000 sums of 0.01
    CHECK_NEAR(dBodyGetLinearVel(bob)[0], 1, 0.01);
    CHECK_NEAR(dBodyGetPosition(bob)[0], 10, 0.01);
    dWorldDestroy(w);
    return 0;
}

// ---- motors, limits, feedback ----------------------------------------------------

// A velocity motor with ample force reaches its target speed in a few steps.
static int test_hinge_motor_reaches_speed(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetCylinderTotal(&m, 5, 3, 0.3, 0.05);   // a wheel about z
    dBodySetMass(b, &m);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dJointSetHingeParam(j, dParamVel, 10);
    dJointSetHingeParam(j, dParamFMax, 1e4);
    for (int s = 0; s < 3; s++) CHECK(dWorldQuickStep(w, 0.01) == 1);
    CHECK_NEAR(dJointGetHingeAngleRate(j), 10, 0.1);
    // Negative target, weak motor: the speed changes by at most FMax h / I per step.
    dJointSetHingeParam(j, dParamVel, -10);
    dJointSetHingeParam(j, dParamFMax, 0.1);
    double before = dJointGetHingeAngleRate(j);
    CHECK(dWorldQuickStep(w, 0.01) == 1);
    double limit = 0.1 * 0.01 / m.I[2 * 4 + 2];
    CHECK_NEAR(dJointGetHingeAngleRate(j), before - limit, 1e-3 * limit);
    dWorldDestroy(w);
    return 0;
}

// Stops are one-sided bounded rows: a pendulum released from the horizontal
// with a stop at 1 rad below it comes to rest on the stop.
static int test_hinge_stop_holds(void)
{
    const double L = 0.5;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID b = sphere_body(w, L, 0, 0, 1, 0.01);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 1, 0);   // falling turns about +y: the angle grows
    dJointSetHingeParam(j, dParamHiStop, 1.0);
    double most = 0;
    for (int s = 0; s < 400; s++) {
        CHECK(dWorldQuickStep(w, 0.005) == 1);
        if (dJointGetHingeAngle(j) > most) most = dJointGetHingeAngle(j);
    }
    // Free it would swing to pi; the stop (ERP 0.2, bounce 0) lets it
    // overshoot by at most a few hundredths of a radian and then holds it.
    CHECK(most < 1.05);
    CHECK_NEAR(dJointGetHingeAngle(j), 1.0, 0.01);
    CHECK(fabs(dJointGetHingeAngleRate(j)) < 0.01);
    dWorldDestroy(w);
    return 0;
}

// A pendulum at rest: the joint's force on the bob balances its weight.
static int test_feedback_of_static_pendulum(void)
{
    const double mass = 3;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID b = sphere_body(w, 0, 0, -0.8, mass, 0.05);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetBallAnchor(j, 0, 0, 0);
    dJointFeedback fb;
    dJointSetFeedback(j, &fb);
    for (int s = 0; s < 5; s++) CHECK(dWorldQuickStep(w, 0.01) == 1);
    // The vertical row is decoupled from the others (the anchor is straight
    // above the centre), so SOR converges to it by a factor 0.3 per iteration.
    CHECK_NEAR(fb.f1[0], 0, TOL(1e-9, 1e-4));
    CHECK_NEAR(fb.f1[1], 0, TOL(1e-9, 1e-4));
    CHECK_NEAR(fb.f1[2], mass * G, TOL(1e-7, 1e-3) * mass * G);
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(fb.t1[i], 0, TOL(1e-9, 1e-4));
        CHECK(fb.f2[i] == 0 && fb.t2[i] == 0);   // the static world gets nothing
    }
    CHECK_NEAR(dBodyGetPosition(b)[2], -0.8, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// A wheel on a hinge-2 joint to a free chassis, no gravity (as in the vehicle
// bench): the wheel motor (axis 2, vel2 -8 rad/s, FMax2 1 N m) is a row
// coupled to the joint's block, and so is the steering motor of a front
// wheel (stops at -+0.75 rad, vel 0.5 rad/s, FMax 0.2 N m); a rear wheel's
// steering stops both at 0 make its steering row an equality, in a block of 5.
// Only internal forces act: the total momentum stays zero (its angular part
// up to the joint's position error, a lever of 0.1 mm, and the gyroscopic
// term's split between bodies), the wheel turns at the motor's speed, a rear
// wheel does not steer (the equality row is held to within 0.7 mrad while
// the motor row coupled to its block pushes it), a front one steers at its
// motor's speed until its stop holds it.
static int hinge2_wheel(int front)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, 0);
    dBodyID chassis = dBodyCreate(w), wheel = sphere_body(w, 0.35, 0.25, -0.1, 0.2, 0.18);
    dMass m;
    dMassSetBoxTotal(&m, 1, 0.7, 0.5, 0.2);
    dBodySetMass(chassis, &m);
    dJointID j = dJointCreateHinge2(w, 0);
    dJointAttach(j, chassis, wheel);
    dJointSetHinge2Anchor(j, 0.35, 0.25, -0.1);
    const dReal up[3] = { 0, 0, 1 }, across[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(j, up, across);
    dJointSetHinge2Param(j, dParamSuspensionERP, 0.4);
    dJointSetHinge2Param(j, dParamSuspensionCFM, 0.01);
    dJointSetHinge2Param(j, dParamLoStop, front ? -0.75 : 0);
    dJointSetHinge2Param(j, dParamHiStop, front ? 0.75 : 0);
    if (front) {
        dJointSetHinge2Param(j, dParamVel, 0.5);
        dJointSetHinge2Param(j, dParamFMax, 0.2);
    }
    dJointSetHinge2Param(j, dParamVel2, -8);
    dJointSetHinge2Param(j, dParamFMax2, 1);
    double worst_p = 0, worst_l = 0, worst_sep = 0, worst_steer = 0;
    for (int s = 0; s < 120; s++) {
        CHECK(dWorldQuickStep(w, 1.0 / 60) == 1);
        double p[3] = { 0, 0, 0 }, l[3] = { 0, 0, 0 };
        const dBodyID b[2] = { chassis, wheel };
        for (int k = 0; k < 2; k++) {
            dMass bm;
            dBodyGetMass(b[k], &bm);
            const dReal *x = dBodyGetPosition(b[k]), *v = dBodyGetLinearVel(b[k]);
            const dReal *R = dBodyGetRotation(b[k]), *om = dBodyGetAngularVel(b[k]);
            dVector3 wb, Lb, L;   // R I R^T omega
            dMultiply1_331(wb, R, om);
            dMultiply0_331(Lb, bm.I, wb);
            dMultiply0_331(L, R, Lb);
            for (int e = 0; e < 3; e++) p[e] += bm.mass * v[e];
            // about the origin: total linear momentum is zero, so any point will do
            l[0] += L[0] + bm.mass * (x[1] * v[2] - x[2] * v[1]);
            l[1] += L[1] + bm.mass * (x[2] * v[0] - x[0] * v[2]);
            l[2] += L[2] + bm.mass * (x[0] * v[1] - x[1] * v[0]);
        }
        worst_p = fmax(worst_p, sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
        worst_l = fmax(worst_l, sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]));
        dVector3 a1, a2;
        dJointGetHinge2Anchor(j, a1);
        dJointGetHinge2Anchor2(j, a2);
        worst_sep = fmax(worst_sep, distance(a1, a2));
        if (!front) worst_steer = fmax(worst_steer, fabs(dJointGetHinge2Angle1(j)));
        if (front && s == 59) CHECK_NEAR(dJointGetHinge2Angle1(j), 0.5, 0.02);
    }
    printf("# %s wheel: |p| %.3g, |L| %.3g, anchor gap %.3g, steering %.3g, angle1 %.6g, "
           "rate2 %.6g\n", front ? "front" : "rear", worst_p, worst_l, worst_sep, worst_steer,
           (double)dJointGetHinge2Angle1(j), (double)dJointGetHinge2Angle2Rate(j));
    CHECK(worst_p < 1e-5);
    CHECK(worst_l < 2e-4);   // 1 % of the wheel's spin momentum, I w = 0.021 N m s
    CHECK(worst_sep < 1e-3);
    CHECK_NEAR(dJointGetHinge2Angle2Rate(j), -8, 0.08);
    if (front) CHECK_NEAR(dJointGetHinge2Angle1(j), 0.75, 0.02);
    else CHECK(worst_steer < 3e-3);
    dWorldDestroy(w);
    return 0;
}

static int test_hinge2_wheels_on_free_chassis(void)
{
    CHECK(hinge2_wheel(0) == 0);
    CHECK(hinge2_wheel(1) == 0);
    return 0;
}

// ---- against dWorldStep ----------------------------------------------------------

// Four rods of unequal mass, all moving: a ball joint to the world, then
// hinge, ball, hinge; the last hinge has a motor too weak for its target
// speed, so its row ends at its bound (a true LCP). Compared after one step:
// QuickStep's velocities against the exact solution of dWorldStep.
static void build_small_system(dWorldID w, dBodyID *rods)
{
    const double l = 0.3;
    dWorldSetGravity(w, 0, 0, -G);
    for (int k = 0; k < 4; k++) {
        rods[k] = dBodyCreate(w);
        dMass m;
        dMassSetBoxTotal(&m, k % 2 ? 2.0 : 0.1, l, 0.05, 0.05);
        dBodySetMass(rods[k], &m);
        dBodySetPosition(rods[k], (k + 0.5) * l, 0, 0);
        dBodySetLinearVel(rods[k], 0.1 * k, 0.5, -0.2 * k);
        dBodySetAngularVel(rods[k], 1 - k, 0.3 * k, 2);
    }
    for (int k = 0; k < 4; k++) {
        dBodyID prev = k > 0 ? rods[k - 1] : 0;
        if (k % 2 == 0) {
            dJointID j = dJointCreateBall(w, 0);
            dJointAttach(j, rods[k], prev);
            dJointSetBallAnchor(j, k * l, 0, 0);
        } else {
            dJointID j = dJointCreateHinge(w, 0);
            dJointAttach(j, rods[k], prev);
            dJointSetHingeAnchor(j, k * l, 0, 0);
            dJointSetHingeAxis(j, 0, k == 1 ? 1 : 0, 1);
            if (k == 3) {
                dJointSetHingeParam(j, dParamVel, 50);
                dJointSetHingeParam(j, dParamFMax, 0.5);
            }
        }
    }
}

static double quickstep_error(int iterations, const dBodyID *exact)
{
    dBodyID rods[4];
    dWorldID w = dWorldCreate();
    build_small_system(w, rods);
    dWorldSetQuickStepNumIterations(w, iterations);
    dWorldQuickStep(w, 0.01);
    double err = 0;
    for (int k = 0; k < 4; k++) {
        const dReal *v = dBodyGetLinearVel(rods[k]), *ve = dBodyGetLinearVel(exact[k]);
        const dReal *a = dBodyGetAngularVel(rods[k]), *ae = dBodyGetAngularVel(exact[k]);
        for (int i = 0; i < 3; i++) {
            err = fmax(err, fabs(v[i] - ve[i]));
            err = fmax(err, fabs(a[i] - ae[i]));
        }
    }
    dWorldDestroy(w);
    return err;
}

static int test_converges_to_world_step(void)
{
    dBodyID exact[4];
    dWorldID w = dWorldCreate();
    build_small_system(w, exact);
    CHECK(dWorldStep(w, 0.01) == 1);
    double e5 = quickstep_error(5, exact);
    double e50 = quickstep_error(50, exact);
    double e500 = quickstep_error(500, exact);
    printf("# max velocity error vs dWorldStep: %.3g (5 it), %.3g (50 it), %.3g (500 it)\n",
           e5, e50, e500);
    CHECK(e50 < e5);
    CHECK(e500 < e50);
    // SOR converges to the LCP solution (the mass ratio 20 makes it slow).
    CHECK(e500 < TOL(1e-6, 1e-2));
    dWorldDestroy(w);
    return 0;
}

// Joints whose equality rows make blocks of every size QuickStep has (2 to
// 6, even and odd, one body and two): a fixed joint to the world (6, one
// body), universal (4), slider (5), ball (3), hinge (5), ball and an
// angular motor of two axes with unlimited force (2).
static void build_block_sizes(dWorldID w, dBodyID *b)
{
    const double size[3] = { 0.3, 0.1, 0.1 };
    dWorldSetGravity(w, 0, 0, -G);
    for (int k = 0; k < 6; k++) {
        b[k] = dBodyCreate(w);
        dMass m;
        dMassSetBoxTotal(&m, 0.5 + 0.3 * k, size[0], size[1], size[2]);
        dBodySetMass(b[k], &m);
        dBodySetPosition(b[k], 0.3 * k, 0.05 * k, 0);
        dBodySetLinearVel(b[k], 0.1 * k, 0.3 - 0.1 * k, -0.2 * k);
        dBodySetAngularVel(b[k], 0.5 - 0.2 * k, 0.3 * k, 1 - 0.1 * k);
    }
    dJointID j = dJointCreateFixed(w, 0);
    dJointAttach(j, b[0], 0);
    dJointSetFixed(j);
    j = dJointCreateUniversal(w, 0);
    dJointAttach(j, b[1], b[0]);
    dJointSetUniversalAnchor(j, 0.15, 0.025, 0);
    dJointSetUniversalAxis1(j, 0, 1, 0);
    dJointSetUniversalAxis2(j, 0, 0, 1);
    j = dJointCreateSlider(w, 0);
    dJointAttach(j, b[2], b[1]);
    dJointSetSliderAxis(j, 1, 0.2, 0);
    j = dJointCreateBall(w, 0);
    dJointAttach(j, b[3], b[2]);
    dJointSetBallAnchor(j, 0.75, 0.125, 0);
    j = dJointCreateHinge(w, 0);
    dJointAttach(j, b[4], b[3]);
    dJointSetHingeAnchor(j, 1.05, 0.175, 0);
    dJointSetHingeAxis(j, 0, 1, 1);
    j = dJointCreateBall(w, 0);
    dJointAttach(j, b[5], b[4]);
    dJointSetBallAnchor(j, 1.35, 0.225, 0);
    j = dJointCreateAMotor(w, 0);
    dJointAttach(j, b[5], b[4]);
    dJointSetAMotorNumAxes(j, 2);
    dJointSetAMotorAxis(j, 0, 1, 1, 0, 0);
    dJointSetAMotorAxis(j, 1, 1, 0, 0, 1);
    dJointSetAMotorParam(j, dParamVel, 0.5);
    dJointSetAMotorParam(j, dParamFMax, dInfinity);
    dJointSetAMotorParam(j, dParamVel2, -0.3);
    dJointSetAMotorParam(j, dParamFMax2, dInfinity);
}

static double block_sizes_error(int iterations, const dBodyID *exact)
{
    dBodyID b[6];
    dWorldID w = dWorldCreate();
    build_block_sizes(w, b);
    dWorldSetQuickStepNumIterations(w, iterations);
    dWorldQuickStep(w, 0.01);
    double err = 0;
    for (int k = 0; k < 6; k++) {
        const dReal *v = dBodyGetLinearVel(b[k]), *ve = dBodyGetLinearVel(exact[k]);
        const dReal *a = dBodyGetAngularVel(b[k]), *ae = dBodyGetAngularVel(exact[k]);
        for (int i = 0; i < 3; i++) {
            err = fmax(err, fabs(v[i] - ve[i]));
            err = fmax(err, fabs(a[i] - ae[i]));
        }
    }
    dWorldDestroy(w);
    return err;
}

static int test_every_block_size_converges_to_world_step(void)
{
    dBodyID exact[6];
    dWorldID w = dWorldCreate();
    build_block_sizes(w, exact);
    CHECK(dWorldStep(w, 0.01) == 1);
    double e5 = block_sizes_error(5, exact);
    double e50 = block_sizes_error(50, exact);
    double e2000 = block_sizes_error(2000, exact);
    printf("# blocks of 2 to 6 rows, max velocity error vs dWorldStep: %.3g (5 it), %.3g (50 it), "
           "%.3g (2000 it)\n", e5, e50, e2000);
    CHECK(e50 < e5);
    CHECK(e2000 < e50);
    CHECK(e2000 < TOL(1e-6, 1e-2));
    dWorldDestroy(w);
    return 0;
}

// ---- contacts --------------------------------------------------------------------

// A box of the given size and mass at (x, y, z), unrotated.
static dBodyID box_body(dWorldID w, double x, double y, double z, const double *size, double m)
{
    dBodyID b = dBodyCreate(w);
    dMass mass;
    dMassSetBoxTotal(&mass, m, size[0], size[1], size[2]);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    return b;
}

// Contacts at the four bottom corners of `top` (a box of the given size)
// against `bottom` (another box below it, or the ground z = 0 if NULL), with
// normal +z and the depth of each corner below the supporting face, for the
// corners that touch: what a box-box collider reports for a flat stack. A
// corner that rounding alone lifts (by 1e-6 m or less) still touches:
// dropping it would leave a box on two corners, to tip over their edge.
static void box_contacts(dWorldID w, dJointGroupID g, dBodyID top, dBodyID bottom,
                         const double *size, int mode, double mu)
{
    double face = bottom ? dBodyGetPosition(bottom)[2] + 0.5 * size[2] : 0;
    for (int k = 0; k < 4; k++) {
        dVector3 p;
        dBodyGetRelPointPos(top, (k & 1 ? 0.5 : -0.5) * size[0], (k & 2 ? 0.5 : -0.5) * size[1],
                            -0.5 * size[2], p);
        dContact c = { 0 };
        c.surface.mode = mode;
        c.surface.mu = mu;
        dCopyVector3(c.geom.pos, p);
        c.geom.normal[2] = 1;
        c.geom.depth = face - p[2];
        c.geom.side1 = c.geom.side2 = -1;
        if (c.geom.depth < -1e-6) continue;
        dJointID j = dJointCreateContact(w, g, &c);
        dJointAttach(j, top, bottom);
    }
}

// A box resting on four contacts stays put: no drift, no rotation. With mu
// 0.5 the friction rows are bounded; with infinite mu they are equality rows
// (solved as a block) and the normal row is coupled to them.
static int test_box_rests_on_contacts(void)
{
    const double size[3] = { 1, 0.6, 0.4 }, mus[2] = { 0.5, dInfinity };
    for (int k = 0; k < 2; k++) {
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, 0, 0, -G);
        dJointGroupID g = dJointGroupCreate(0);
        dBodyID b = box_body(w, 0, 0, 0.2, size, 3);
        double worst = 0;
        for (int s = 0; s < 500; s++) {
            box_contacts(w, g, b, 0, size, 0, mus[k]);
            CHECK(dWorldQuickStep(w, 0.01) == 1);
            dJointGroupEmpty(g);
            const dReal *p = dBodyGetPosition(b);
            worst = fmax(worst, sqrt(p[0] * p[0] + p[1] * p[1] + (p[2] - 0.2) * (p[2] - 0.2)));
        }
        printf("# box on 4 contacts (mu %g), max displacement over 5 s: %.3g m\n", mus[k],
               worst);
        // The contacts hold the box at the velocity level and what sinks
        // within a step is corrected by ERP: in double nothing moves beyond
        // rounding. In single, rounding in the redundant system (12 rows for
        // 6 degrees of freedom) leaves a creep of about 1e-4 m/s.
        CHECK(worst < TOL(1e-6, 3e-3));
        const dReal *q = dBodyGetQuaternion(b);
        CHECK_NEAR(q[0], 1, TOL(1e-9, 1e-6));
        CHECK(dCalcVectorLength3(dBodyGetLinearVel(b)) < TOL(1e-6, 1e-3));
        CHECK(dCalcVectorLength3(dBodyGetAngularVel(b)) < TOL(1e-6, 1e-3));
        dJointGroupDestroy(g);
        dWorldDestroy(w);
    }
    return 0;
}

// Sliding on the friction pyramid (dContactApprox1, mu 0.5): the friction
// force is mu times the normal force, so the box decelerates at mu g.
static int test_sliding_box_decelerates_at_mu_g(void)
{
    const double size[3] = { 1, 0.6, 0.4 }, mu = 0.5, h = 0.01;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID b = box_body(w, 0, 0, 0.2, size, 3);
    dBodySetLinearVel(b, 5, 0, 0);
    double v_start = 0;
    for (int s = 1; s <= 60; s++) {
        box_contacts(w, g, b, 0, size, dContactApprox1, mu);
        CHECK(dWorldQuickStep(w, h) == 1);
        dJointGroupEmpty(g);
        if (s == 10) v_start = dBodyGetLinearVel(b)[0];
    }
    double decel = (v_start - dBodyGetLinearVel(b)[0]) / (50 * h);
    printf("# sliding box: deceleration %.5g m/s^2 (mu g = %.5g)\n", decel, mu * G);
    CHECK_NEAR(decel, mu * G, 0.02 * mu * G);
    CHECK(fabs(dBodyGetLinearVel(b)[1]) < TOL(1e-6, 1e-4));   // no sideways drift
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Friction on a slope (gravity tilted by atan 0.3 about y, the ground flat):
// a box on its four corner contacts below the friction angle (mu 0.5) stays
// put with every way a contact's rows are made and swept together: both
// friction directions on the pyramid, one on the pyramid and one a fixed
// force (dContactApprox1_1), friction along the slope only (mu2 0: a
// contact of two rows), fixed friction forces, rolling friction (six rows).
// Above it (tilt atan 0.7) it slides down at g (sin - mu cos).
static int test_box_holds_on_slope_and_slides_beyond(void)
{
    const double size[3] = { 1, 0.6, 0.4 }, mu = 0.5, h = 0.01;
    const int modes[5] = { dContactApprox1, dContactApprox1_1, dContactApprox1 | dContactMu2,
                           0, dContactApprox1 | dContactRolling };
    for (int k = 0; k < 6; k++) {
        const int slide = k == 5, mode = slide ? dContactApprox1 : modes[k];
        const double t = slide ? 0.7 : 0.3, c = 1 / sqrt(1 + t * t), sn = t * c;
        dWorldID w = dWorldCreate();
        dWorldSetGravity(w, G * sn, 0, -G * c);
        dJointGroupID g = dJointGroupCreate(0);
        // Box friction is a force: about mu times this box's share of weight.
        const double m = 3, mu_k = mode == 0 ? mu * m * G * c / 4 : mu;
        dBodyID b = box_body(w, 0, 0, 0.2, size, m);
        double v_start = 0, worst = 0;
        for (int s = 1; s <= 300; s++) {
            for (int e = 0; e < 4; e++) {
                dVector3 p;
                dBodyGetRelPointPos(b, (e & 1 ? 0.5 : -0.5) * size[0],
                                    (e & 2 ? 0.5 : -0.5) * size[1], -0.5 * size[2], p);
                dContact ct = { 0 };
                ct.surface.mode = mode | dContactFDir1;
                ct.surface.mu = mu_k;
                ct.surface.mu2 = 0;   // used with dContactMu2 only
                ct.surface.rho = ct.surface.rho2 = ct.surface.rhoN = 0.1;
                ct.fdir1[0] = 1;
                dCopyVector3(ct.geom.pos, p);
                ct.geom.normal[2] = 1;
                ct.geom.depth = -p[2];
                ct.geom.side1 = ct.geom.side2 = -1;
                if (ct.geom.depth < -1e-6) continue;
                dJointAttach(dJointCreateContact(w, g, &ct), b, NULL);
            }
            CHECK(dWorldQuickStep(w, h) == 1);
            dJointGroupEmpty(g);
            if (s == 100) v_start = dBodyGetLinearVel(b)[0];
            const dReal *p = dBodyGetPosition(b);
            worst = fmax(worst, sqrt(p[0] * p[0] + p[1] * p[1]));
        }
        if (slide) {
            const double a = (dBodyGetLinearVel(b)[0] - v_start) / (200 * h);
            printf("# slope 0.7, mu %g: slides at %.5g m/s^2 (g (sin - mu cos) = %.5g)\n", mu, a,
                   G * (sn - mu * c));
            CHECK_NEAR(a, G * (sn - mu * c), 0.02 * G * (sn - mu * c));
        } else {
            printf("# slope 0.3, mode %#x: moved %.3g m in 3 s\n", mode, worst);
            CHECK(worst < TOL(1e-6, 3e-3));
        }
        CHECK(fabs(dBodyGetLinearVel(b)[1]) < TOL(1e-6, 1e-4));   // nothing sideways
        dJointGroupDestroy(g);
        dWorldDestroy(w);
    }
    return 0;
}

// Contacts of a box resting on another, as a box-box collider reports them
// for two boxes of the given size stacked flat or nearly: the corners of the
// overlap of the upper box's bottom face with the lower box's top face
// (worked out in the lower box's frame), normal the lower box's up axis,
// depth how far the upper face is below the lower one at each corner. On the
// ground z = 0 the upper box's four bottom corners.
typedef struct face_set {
    dWorldID w;
    dJointGroupID g;
    double size[3];
    double deepest;   // the deepest contact made so far
    double mu;        // friction coefficient (the friction pyramid)
} face_set;

static void face_contact(face_set *fs, dBodyID top, dBodyID bottom, const dVector3 p,
                         const dReal *n, double depth)
{
    if (depth < 0) return;
    dContact c = { 0 };
    c.surface.mode = dContactApprox1;
    c.surface.mu = fs->mu;
    dCopyVector3(c.geom.pos, p);
    dCopyVector3(c.geom.normal, n);
    c.geom.depth = depth;
    c.geom.side1 = c.geom.side2 = -1;
    fs->deepest = fmax(fs->deepest, depth);
    dJointID j = dJointCreateContact(fs->w, fs->g, &c);
    dJointAttach(j, top, bottom);
}

static void face_contacts(face_set *fs, dBodyID top, dBodyID bottom)
{
    const double hx = 0.5 * fs->size[0], hy = 0.5 * fs->size[1], hz = 0.5 * fs->size[2];
    static const dReal up[3] = { 0, 0, 1 };
    if (!bottom) {
        for (int k = 0; k < 4; k++) {
            dVector3 p;
            dBodyGetRelPointPos(top, (k & 1 ? hx : -hx), (k & 2 ? hy : -hy), -hz, p);
            face_contact(fs, top, NULL, p, up, -p[2]);
        }
        return;
    }
    // The upper box's bottom face in the lower box's frame: centre c, axes
    // u, v, normal m (all near the lower box's own axes).
    dVector3 p, c, u, v, m, ax;
    dBodyGetRelPointPos(top, 0, 0, -hz, p);
    dBodyGetPosRelPoint(bottom, p[0], p[1], p[2], c);
    dBodyVectorToWorld(top, 1, 0, 0, ax);
    dBodyVectorFromWorld(bottom, ax[0], ax[1], ax[2], u);
    dBodyVectorToWorld(top, 0, 1, 0, ax);
    dBodyVectorFromWorld(bottom, ax[0], ax[1], ax[2], v);
    dBodyVectorToWorld(top, 0, 0, 1, ax);
    dBodyVectorFromWorld(bottom, ax[0], ax[1], ax[2], m);
    // Its extent in x and y, clipped to the lower face.
    const double ex = hx * fabs(u[0]) + hy * fabs(v[0]), ey = hx * fabs(u[1]) + hy * fabs(v[1]);
    const double x0 = fmax(c[0] - ex, -hx), x1 = fmin(c[0] + ex, hx);
    const double y0 = fmax(c[1] - ey, -hy), y1 = fmin(c[1] + ey, hy);
    if (x0 > x1 || y0 > y1) return;
    dVector3 n;
    dBodyVectorToWorld(bottom, 0, 0, 1, n);
    for (int k = 0; k < 4; k++) {
        const double x = k & 1 ? x1 : x0, y = k & 2 ? y1 : y0;
        // The upper face's height over (x, y): on its plane through c, normal m.
        const double z = c[2] - (m[0] * (x - c[0]) + m[1] * (y - c[1])) / m[2];
        dBodyGetRelPointPos(bottom, x, y, hz, p);
        face_contact(fs, top, bottom, p, n, hz - z);
    }
}

// A stack of boxes on the ground (four contacts per interface, where a
// box-box collider puts them) stays standing with the default 20 iterations.
static int test_box_stack_stands(void)
{
    enum { N = 8 };
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    face_set fs = { w, dJointGroupCreate(0), { 0.5, 0.5, 0.25 }, 0, 0.5 };
    dBodyID boxes[N];
    for (int k = 0; k < N; k++) boxes[k] = box_body(w, 0, 0, (k + 0.5) * fs.size[2], fs.size, 1);
    double worst = 0;
    for (int s = 0; s < 500; s++) {
        for (int k = 0; k < N; k++) face_contacts(&fs, boxes[k], k ? boxes[k - 1] : 0);
        CHECK(dWorldQuickStep(w, 0.01) == 1);
        dJointGroupEmpty(fs.g);
        for (int k = 0; k < N; k++) {
            const dReal *p = dBodyGetPosition(boxes[k]);
            double z0 = (k + 0.5) * fs.size[2];
            worst = fmax(worst, sqrt(p[0] * p[0] + p[1] * p[1] + (p[2] - z0) * (p[2] - z0)));
        }
    }
    printf("# stack of %d boxes, max displacement over 5 s: %.3g m\n", N, worst);
    // 20 iterations do not converge a stack of 8 (dWorldStep holds it to
    // 1e-9 m): it settles and sways by about a centimetre, but stands (a
    // box that slid off or toppled would move by its size, 0.25 m or more).
    CHECK(worst < 0.05);
    dJointGroupDestroy(fs.g);
    dWorldDestroy(w);
    return 0;
}

// The bench's 2-D pyramid of unit boxes (1 kg, 1 cm apart in a layer, each
// box on two below it; mu 0.8 with the friction pyramid, dt 1/60, 20
// iterations, world ERP and CFM at their defaults), 10 layers for 10 s. It
// stands with small penetration and drift. Sweeping all normal rows before
// all friction rows made the contacts sink 2 cm, the top box drift 10 cm and
// the boxes of the lower layers slide apart by 55 cm (and a 20-layer
// pyramid fall); a contact's rows always next to each other let them slide
// apart by 25 cm at 20 layers.
static int test_box_pyramid_stands(void)
{
    enum { LAYERS = 10, N = LAYERS * (LAYERS + 1) / 2 };
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    face_set fs = { w, dJointGroupCreate(0), { 1, 1, 1 }, 0, 0.8 };
    dBodyID box[N];
    dVector3 start[N];
    int layer_of[N], k = 0;
    for (int l = 0; l < LAYERS; l++) {
        for (int i = 0; i < LAYERS - l; i++, k++) {
            start[k][0] = (i - 0.5 * (LAYERS - l - 1)) * 1.01;
            start[k][1] = 0;
            start[k][2] = 0.5 + l;
            box[k] = box_body(w, start[k][0], start[k][1], start[k][2], fs.size, 1);
            layer_of[k] = l;
        }
    }
    double worst = 0;
    for (int s = 0; s < 600; s++) {
        for (int a = 0; a < N; a++) {
            if (layer_of[a] == 0) face_contacts(&fs, box[a], NULL);
            for (int b = 0; b < N; b++) {
                const dReal *pa = dBodyGetPosition(box[a]), *pb = dBodyGetPosition(box[b]);
                if (layer_of[b] == layer_of[a] - 1 && fabs(pa[0] - pb[0]) < 1)
                    face_contacts(&fs, box[a], box[b]);
            }
        }
        CHECK(dWorldQuickStep(w, 1.0 / 60) == 1);
        dJointGroupEmpty(fs.g);
        for (int a = 0; a < N; a++)
            worst = fmax(worst, distance(dBodyGetPosition(box[a]), start[a]));
    }
    const double top = distance(dBodyGetPosition(box[N - 1]), start[N - 1]);
    printf("# %d-layer pyramid, 10 s: deepest contact %.3g m, top box drift %.3g m, "
           "largest displacement %.3g m\n", LAYERS, fs.deepest, top, worst);
    CHECK(fs.deepest < 0.005);
    CHECK(top < 0.02);
    CHECK(worst < 0.03);
    dJointGroupDestroy(fs.g);
    dWorldDestroy(w);
    return 0;
}

// ---- determinism -------------------------------------------------------------------

// Islands are solved independently: a pendulum moves the same whether or not
// another island is in the world, and two identical worlds agree exactly.
static int test_islands_are_independent_and_reproducible(void)
{
    dWorldID w[3];
    dBodyID rods[3][20];
    dJointID joints[3][20];
    for (int k = 0; k < 3; k++) {
        w[k] = dWorldCreate();
        dWorldSetGravity(w[k], 0, 0, -G);
        if (k == 2) {   // an extra island, created first so it is stepped first
            dBodyID other = sphere_body(w[k], 5, 5, 5, 1, 0.1);
            dJointID j = dJointCreateBall(w[k], 0);
            dJointAttach(j, other, 0);
            dJointSetBallAnchor(j, 5, 5, 6);
        }
        make_chain(w[k], 20, 0.1, PI / 4, rods[k], joints[k]);
    }
    for (int s = 0; s < 50; s++)
        for (int k = 0; k < 3; k++) CHECK(dWorldQuickStep(w[k], 0.01) == 1);
    for (int n = 0; n < 20; n++) {
        for (int k = 1; k < 3; k++) {
            const dReal *p0 = dBodyGetPosition(rods[0][n]), *pk = dBodyGetPosition(rods[k][n]);
            CHECK(p0[0] == pk[0] && p0[1] == pk[1] && p0[2] == pk[2]);
        }
    }
    for (int k = 0; k < 3; k++) dWorldDestroy(w[k]);
    return 0;
}

// A body without joints and with isotropic inertia (no gyroscopic term) moves
// by the guide's first-order update, to the bit, among many islands of every
// kind (free ones, boxes on their ground contacts): x += h v, q += h dq/dt
// (dDQfromW) normalised (dNormalize4), R from q (dRfromQ).
static int test_free_body_moves_by_the_first_order_update(void)
{
    const double size[3] = { 0.4, 0.3, 0.2 };
    const dReal h = 0.01;
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID boxes[12], spins[20];
    for (int i = 0; i < 12; i++) boxes[i] = box_body(w, 2.0 * i, 5, 0.1, size, 1);
    for (int i = 0; i < 20; i++) {
        spins[i] = sphere_body(w, i, 0, 3, 1 + 0.1 * i, 0.1);
        dBodySetLinearVel(spins[i], 0.5, -0.25 * i, 1);
        dBodySetAngularVel(spins[i], 3 - 0.4 * i, 0.7 * i, 5);
        dQuaternion q0 = { 1, 0.1 * i, -0.2, 0.05 * i };
        dBodySetQuaternion(spins[i], q0);
    }
    for (int s = 0; s < 20; s++) {
        for (int i = 0; i < 12; i++) box_contacts(w, g, boxes[i], 0, size, dContactApprox1, 0.5);
        dVector3 x[20];
        dQuaternion q[20];
        for (int i = 0; i < 20; i++) {
            const dReal *p = dBodyGetPosition(spins[i]), *v = dBodyGetLinearVel(spins[i]);
            const dReal *qi = dBodyGetQuaternion(spins[i]);
            dReal dq[4];
            dDQfromW(dq, dBodyGetAngularVel(spins[i]), qi);
            for (int e = 0; e < 3; e++) x[i][e] = p[e] + h * v[e];
            for (int e = 0; e < 4; e++) q[i][e] = qi[e] + h * dq[e];
            dNormalize4(q[i]);
        }

        CHECK(dWorldQuickStep(w, h) == 1);
        dJointGroupEmpty(g);

        for (int i = 0; i < 20; i++) {
            const dReal *p = dBodyGetPosition(spins[i]), *qi = dBodyGetQuaternion(spins[i]);
            const dReal *R = dBodyGetRotation(spins[i]);
            dMatrix3 Rq;
            dRfromQ(Rq, q[i]);
            CHECK(p[0] == x[i][0] && p[1] == x[i][1] && p[2] == x[i][2]);
            CHECK(qi[0] == q[i][0] && qi[1] == q[i][1] && qi[2] == q[i][2] && qi[3] == q[i][3]);
            for (int e = 0; e < 12; e++) CHECK(e % 4 == 3 || R[e] == Rq[e]);
        }
    }
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Many small islands with rows (stacks of one to three boxes sliding on
// their contacts: the islands are ordered by their number of rows and their
// rows interleaved) step exactly as each would alone, and a warm step of
// them allocates nothing.
static int test_many_small_islands_step_as_alone(void)
{
    enum { N = 40, H = 3 };
    const double size[3] = { 0.4, 0.3, 0.2 };
    dWorldID all = dWorldCreate(), one = dWorldCreate();
    dWorldSetGravity(all, 0, 0, -G);
    dWorldSetGravity(one, 0, 0, -G);
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID b[N][H] = { { 0 } }, alone[H] = { 0 };
    const int k = 17;   // a stack of k % H + 1 = 3 boxes, also in `one`
    for (int i = 0; i < N; i++) {
        for (int l = 0; l <= i % H; l++) {
            b[i][l] = box_body(all, 2.0 * i, 0, 0.1 + 0.2 * l, size, 1);
            dBodySetLinearVel(b[i][l], 0.2 + 0.01 * i, 0, 0);   // the friction rows work
            if (i != k) continue;
            alone[l] = box_body(one, 2.0 * i, 0, 0.1 + 0.2 * l, size, 1);
            dBodySetLinearVel(alone[l], 0.2 + 0.01 * i, 0, 0);
        }
    }
    int counted = -1;
    for (int s = 0; s < 30; s++) {
        for (int i = 0; i < N; i++)
            for (int l = 0; l <= i % H; l++)
                box_contacts(all, g, b[i][l], l ? b[i][l - 1] : 0, size, dContactApprox1, 0.5);
        for (int l = 0; l < H; l++)
            box_contacts(one, g, alone[l], l ? alone[l - 1] : 0, size, dContactApprox1, 0.5);

        if (s == 20) test_count_allocations();
        CHECK(dWorldQuickStep(all, 0.01) == 1);
        if (s == 20) counted = test_allocations_counted();
        CHECK(dWorldQuickStep(one, 0.01) == 1);
        dJointGroupEmpty(g);

        for (int l = 0; l < H; l++) {
            const dReal *p = dBodyGetPosition(b[k][l]), *q = dBodyGetPosition(alone[l]);
            CHECK(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
        }
    }
    CHECK(counted == 0);
    dJointGroupDestroy(g);
    dWorldDestroy(all);
    dWorldDestroy(one);
    return 0;
}

// ---- parameters and bad input ----------------------------------------------------

static int test_parameters_round_trip_and_bad_values(void)
{
    dWorldID w = dWorldCreate();
    CHECK(dWorldGetQuickStepNumIterations(w) == 20);
    CHECK_NEAR(dWorldGetQuickStepW(w), 1.3, 1e-6);
    dWorldSetQuickStepNumIterations(w, 37);
    dWorldSetQuickStepW(w, 0.9);
    CHECK(dWorldGetQuickStepNumIterations(w) == 37);
    CHECK_NEAR(dWorldGetQuickStepW(w), 0.9, 1e-6);

    test_capture_reports();
    dWorldSetQuickStepNumIterations(w, 0);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dWorldSetQuickStepNumIterations"));
    dWorldSetQuickStepNumIterations(w, -3);
    CHECK(test_captured_count() == 2);
    dWorldSetQuickStepW(w, 2.5);
    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("dWorldSetQuickStepW"));
    dWorldSetQuickStepW(w, 0);
    CHECK(test_captured_count() == 4);
    dWorldSetQuickStepW(w, NAN);
    CHECK(test_captured_count() == 5);
    CHECK(dWorldQuickStep(0, 0.01) == 0);
    CHECK(test_captured_count() == 6);
    CHECK(test_captured_contains("dWorldQuickStep"));
    test_release_reports();
    // Rejected values change nothing.
    CHECK(dWorldGetQuickStepNumIterations(w) == 37);
    CHECK_NEAR(dWorldGetQuickStepW(w), 0.9, 1e-6);
    dWorldDestroy(w);
    return 0;
}

// A bad step size is reported and leaves every body (and its accumulated
// force) as it was.
static int test_bad_step_size_changes_nothing(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    dBodyID b = sphere_body(w, 0.3, 0, -1, 1, 0.05);
    dBodySetLinearVel(b, 1, 2, 3);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetBallAnchor(j, 0, 0, 0);
    dBodyAddForce(b, 4, 5, 6);
    const dReal bad[] = { 0, -0.01, NAN, INFINITY };
    test_capture_reports();
    for (int i = 0; i < 4; i++) {
        int before = test_captured_count();
        CHECK(dWorldQuickStep(w, bad[i]) == 0);
        CHECK(test_captured_count() == before + 1);
        CHECK(test_captured_contains("stepsize"));
    }
    test_release_reports();
    const dReal *p = dBodyGetPosition(b), *v = dBodyGetLinearVel(b), *f = dBodyGetForce(b);
    CHECK(p[0] == (dReal)0.3 && p[1] == 0 && p[2] == -1);
    CHECK(v[0] == 1 && v[1] == 2 && v[2] == 3);
    CHECK(f[0] == 4 && f[1] == 5 && f[2] == 6);
    dWorldDestroy(w);
    return 0;
}

// ---- memory ------------------------------------------------------------------------

// After two warm-up steps a step allocates nothing: all scratch comes from
// the world's arena, which has grown to its peak size.
static int test_warm_step_allocates_nothing(void)
{
    enum { N = 30 };
    dBodyID rods[N];
    dJointID joints[N];
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    make_chain(w, N, 0.1, PI / 4, rods, joints);
    dBodyID lone = sphere_body(w, 9, 9, 9, 1, 0.1);   // a second island
    (void)lone;
    dJointFeedback fb;
    dJointSetFeedback(joints[0], &fb);
    dWorldQuickStep(w, 0.01);
    dWorldQuickStep(w, 0.01);
    test_count_allocations();
    for (int s = 0; s < 10; s++) dWorldQuickStep(w, 0.01);
    int counted = test_allocations_counted();
    dWorldDestroy(w);
    CHECK(counted == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_free_fall_matches_world_step),
    TEST_CASE(test_ball_pendulum_length_and_period),
    TEST_CASE(test_hinge_pendulum_length_and_period),
    TEST_CASE(test_chain_joint_separation),
    TEST_CASE(test_hanging_chain_converges_with_iterations),
    TEST_CASE(test_thousand_body_chain),
    TEST_CASE(test_pendulum_on_moving_kinematic_support),
    TEST_CASE(test_hinge_motor_reaches_speed),
    TEST_CASE(test_hinge_stop_holds),
    TEST_CASE(test_feedback_of_static_pendulum),
    TEST_CASE(test_hinge2_wheels_on_free_chassis),
    TEST_CASE(test_converges_to_world_step),
    TEST_CASE(test_every_block_size_converges_to_world_step),
    TEST_CASE(test_box_rests_on_contacts),
    TEST_CASE(test_sliding_box_decelerates_at_mu_g),
    TEST_CASE(test_box_holds_on_slope_and_slides_beyond),
    TEST_CASE(test_box_stack_stands),
    TEST_CASE(test_box_pyramid_stands),
    TEST_CASE(test_islands_are_independent_and_reproducible),
    TEST_CASE(test_free_body_moves_by_the_first_order_update),
    TEST_CASE(test_many_small_islands_step_as_alone),
    TEST_CASE(test_parameters_round_trip_and_bad_values),
    TEST_CASE(test_bad_step_size_changes_nothing),
    TEST_CASE(test_warm_step_allocates_nothing),
    TEST_END
};
