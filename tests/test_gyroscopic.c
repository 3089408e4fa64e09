// SPDX-License-Identifier: BSD-3-Clause
//
// test_gyroscopic.c -- the gyroscopic term under every stepper: a torque-free
// box keeps its energy and |L| and flips with the period of the Euler top
// (complete elliptic integral, computed here by the AGM), about every kind of
// axis; a spinning wheel on a hinge keeps its spin; a gyroscope on a ball
// joint precesses at m g r / (I w); a symmetric top's rate turns at the Euler
// top's rate about its axis; a body with the term off moves as before.

#include "test.h"

#include <math.h>
#include <stdio.h>

enum stepper { STEP, QUICK, FAST1 };
static const char *const stepper_name[] = { "dWorldStep", "QuickStep", "StepFast1" };

static void step_world(dWorldID w, enum stepper s, dReal h)
{
    if (s == STEP) dWorldStep(w, h);
    else if (s == QUICK) dWorldQuickStep(w, h);
    else dWorldStepFast1(w, h, 5);
}

// The box of issue 15: 1 kg, 0.2 x 0.6 x 1.4 m. Principal moments
// I1 > I2 > I3 along x, y, z.
static const dReal box_side[3] = { 0.2, 0.6, 1.4 };

static void box_moments(double I[3])
{
    const double a = box_side[0], b = box_side[1], c = box_side[2];
    I[0] = (b * b + c * c) / 12;
    I[1] = (a * a + c * c) / 12;
    I[2] = (a * a + b * b) / 12;
}

// The arithmetic-geometric mean; K(k) = pi / (2 agm(1, sqrt(1 - k^2))).
static double agm(double a, double b)
{
    for (int i = 0; i < 64 && fabs(a - b) > 1e-15 * a; i++) {
        double m = (a + b) / 2;
        b = sqrt(a * b);
        a = m;
    }
    return a;
}

// Torque-free Euler top (I1 > I2 > I3) started at body rates w: the time
// between sign changes of the intermediate-axis rate w2, which is an sn
// function of its motion, 2 K(k) / lambda (Landau & Lifshitz, section 37).
// For L^2 > 2 E I2 the body turns about axis 1, else about axis 3.
static double euler_top_half_period(const double I[3], const double w[3])
{
    const double L2 = I[0] * I[0] * w[0] * w[0] + I[1] * I[1] * w[1] * w[1] +
                      I[2] * I[2] * w[2] * w[2];
    const double E2 = I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2];
    const double I123 = I[0] * I[1] * I[2];
    double lambda, k2;
    if (L2 > E2 * I[1]) {
        lambda = sqrt((I[0] - I[1]) * (L2 - E2 * I[2]) / I123);
        k2 = (I[1] - I[2]) * (E2 * I[0] - L2) / ((I[0] - I[1]) * (L2 - E2 * I[2]));
    } else {
        lambda = sqrt((I[1] - I[2]) * (E2 * I[0] - L2) / I123);
        k2 = (I[0] - I[1]) * (L2 - E2 * I[2]) / ((I[1] - I[2]) * (E2 * I[0] - L2));
    }
    const double K = M_PI / (2 * agm(1, sqrt(1 - k2)));
    return 2 * K / lambda;
}

// How far the motion from body rates w is from the separatrix, |L^2 - 2 E I2| / L^2:
// near it the flip period grows as the logarithm of this, so a change of the energy
// by rounding moves the period.
static double separatrix_distance(const double I[3], const double w[3])
{
    const double L2 = I[0] * I[0] * w[0] * w[0] + I[1] * I[1] * w[1] * w[1] +
                      I[2] * I[2] * w[2] * w[2];
    const double E2 = I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2];
    return fabs(L2 - E2 * I[1]) / L2;
}

typedef struct spin_result {
    double energy_gain, energy_loss;   // largest relative rise and fall of the energy
    double momentum_change;            // largest relative change of |L|
    double half_period;                // mean time between sign changes of w2, 0 if none
    int flips;
} spin_result;

// Body rates and L (world) of body b.
static void body_state(dBodyID b, const double I[3], double wb[3], double *E, double *L)
{
    const dReal *R = dBodyGetRotation(b), *w = dBodyGetAngularVel(b);
    for (int i = 0; i < 3; i++) wb[i] = R[i] * w[0] + R[4 + i] * w[1] + R[8 + i] * w[2];
    double Lb[3] = { I[0] * wb[0], I[1] * wb[1], I[2] * wb[2] };
    *E = 0.5 * (Lb[0] * wb[0] + Lb[1] * wb[1] + Lb[2] * wb[2]);
    *L = sqrt(Lb[0] * Lb[0] + Lb[1] * Lb[1] + Lb[2] * Lb[2]);
}

// The box spun at body rates w0, no gravity, stepped for t seconds.
static spin_result spin_box(const double w0[3], enum stepper s, dReal h, double t, int finite)
{
    double I[3];
    box_moments(I);
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 1, box_side[0], box_side[1], box_side[2]);
    dBodySetMass(b, &m);
    dBodySetFiniteRotationMode(b, finite);
    dBodySetAngularVel(b, w0[0], w0[1], w0[2]);
    spin_result r = { 0, 0, 0, 0, 0 };
    double wb[3], E0, L0, E, L;
    body_state(b, I, wb, &E0, &L0);
    double prev = wb[1], last_flip = -1, sum = 0;
    const int n = (int)lround(t / h);
    for (int k = 1; k <= n; k++) {
        step_world(w, s, h);
        body_state(b, I, wb, &E, &L);
        r.energy_gain = fmax(r.energy_gain, E / E0 - 1);
        r.energy_loss = fmax(r.energy_loss, 1 - E / E0);
        r.momentum_change = fmax(r.momentum_change, fabs(L / L0 - 1));
        if ((prev < 0) != (wb[1] < 0)) {
            double tc = k * h - h * wb[1] / (wb[1] - prev);   // linear interpolation
            if (last_flip >= 0) {
                sum += tc - last_flip;
                r.flips++;
            }
            last_flip = tc;
        }
        prev = wb[1];
    }
    if (r.flips) r.half_period = sum / r.flips;
    dWorldDestroy(w);
    return r;
}

// A wheel (a disc, axis z in its frame) on a hinge to the static world whose
// axis is tilted by `tilt` from the wheel's symmetry axis, spinning at `spin`
// about the hinge axis, no gravity, for t seconds: returns the final rate
// about the hinge axis over the first. The hinge must carry the gyroscopic
// torque of the tilted wheel; an ideal hinge does no work, so the rate stays.
static double hinged_wheel_spin_ratio(enum stepper s, dReal h, double t, double tilt,
                                      double spin, int gyroscopic)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetCylinderTotal(&m, 2, 3, 0.3, 0.05);
    dBodySetMass(b, &m);
    dBodySetGyroscopicMode(b, gyroscopic);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, tilt);
    dBodySetRotation(b, R);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dBodySetAngularVel(b, 0, 0, spin);
    const int n = (int)lround(t / h);
    for (int k = 0; k < n; k++) step_world(w, s, h);
    const double rate = dJointGetHingeAngleRate(j);
    dWorldDestroy(w);
    return rate / spin;
}

// A gyroscope: a disc (mass 1, radius 0.3, 4 cm thick) on a ball joint at
// the origin, its axis horizontal along x with the centre at x = r, spinning
// at w3 about its axis, gravity g. Started in steady precession (rate
// Omega = m g r / (I3 w3) about z, exact for a horizontal axis), stepped for
// t seconds: returns the mean precession rate (the centre's azimuth over t)
// and the largest height of the centre above the pivot in *rise.
static double gyroscope_precession(enum stepper s, dReal h, double t, double r, double w3,
                                   double *rise, double *omega_expected)
{
    const double g = 9.81, radius = 0.3;
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -g);
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetCylinderTotal(&m, 1, 1, radius, 0.04);   // axis x
    dBodySetMass(b, &m);
    const double I3 = radius * radius / 2;
    const double omega = g * r / (I3 * w3);
    *omega_expected = omega;
    dBodySetPosition(b, r, 0, 0);
    dBodySetAngularVel(b, w3, 0, omega);
    dBodySetLinearVel(b, 0, omega * r, 0);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetBallAnchor(j, 0, 0, 0);
    const int n = (int)lround(t / h);
    double azimuth = 0, prev = 0;
    *rise = 0;
    for (int k = 0; k < n; k++) {
        step_world(w, s, h);
        const dReal *p = dBodyGetPosition(b);
        double a = atan2(p[1], p[0]), d = a - prev;
        if (d > M_PI) d -= 2 * M_PI;
        if (d < -M_PI) d += 2 * M_PI;
        azimuth += d;
        prev = a;
        *rise = fmax(*rise, fabs(p[2]));
    }
    dWorldDestroy(w);
    return azimuth / t;
}

// Body rates (x, y, z along I1 > I2 > I3) of the spins tested: both stable
// axes, the intermediate axis (issue 15's box), near the separatrix, and a
// general tumble.
static const double spins[][3] = {
    { 0.3, 12, 0.2 },     // mostly about the intermediate axis: flips
    { 1e-3, 12, 1e-3 },   // nearly on the separatrix: long flips
    { 0.02, 12, 0.5 },    // near the separatrix, on the other side
    { 12, 0.3, 0.2 },     // about the largest moment: stable
    { 0.2, 0.3, 12 },     // about the smallest moment: stable
    { 3, 4, 5 },          // a general tumble
};

static int test_torque_free_box_keeps_energy_momentum_and_flip_period(void)
{
    double I[3];
    box_moments(I);
    for (size_t k = 0; k < sizeof spins / sizeof spins[0]; k++) {
        const double period = euler_top_half_period(I, spins[k]);
        // In single precision (rounding 6e-8 a step) the motion started within
        // 1e-5 of the separatrix may end on either side of it: its period is
        // not checked there (energy and |L| are).
        const int period_resolved = separatrix_distance(I, spins[k]) > TOL(0, 1e-5);
        for (int s = STEP; s <= FAST1; s++) {
            for (int fine = 0; fine < 2; fine++) {
                const dReal h = fine ? 0.001 : 0.01;
                // 1 % at 0.01 and 0.1 % at 0.001, as issue 15 asks; the
                // scheme keeps both to rounding: about 1e-12 in double; in
                // single precision each of up to 50000 (sub-)steps rounds at
                // 6e-8, some 5e-5 in all, either way.
                const double tol = fine ? TOL(1e-3, 1e-3) : TOL(1e-2, 1e-2);
                for (int finite = 0; finite < 2; finite++) {
                    spin_result r = spin_box(spins[k], s, h, 10, finite);
                    if (finite == 0 && s == STEP)
                        printf("# w (%g, %g, %g) h %g: energy -%.1e +%.1e, |L| %.1e, "
                               "half period %.4f s (analytic %.4f)\n", spins[k][0],
                               spins[k][1], spins[k][2], (double)h, r.energy_loss,
                               r.energy_gain, r.momentum_change, r.half_period, period);
                    CHECK(r.energy_loss < tol);
                    CHECK(r.momentum_change < tol);
                    CHECK(r.energy_gain < TOL(1e-9, 1e-4));   // never gains, up to rounding
                    if (!period_resolved) continue;
                    CHECK(r.flips >= 2);
                    CHECK_NEAR(r.half_period / period, 1, 0.02);
                }
            }
        }
    }
    return 0;
}

static int test_wheel_on_hinge_keeps_its_spin(void)
{
    for (int s = STEP; s <= FAST1; s++) {
        for (int fine = 0; fine < 2; fine++) {
            const dReal h = fine ? 0.001 : 0.01;
            const double tilted = hinged_wheel_spin_ratio(s, h, 10, 0.2, 20, 1);
            const double straight = hinged_wheel_spin_ratio(s, h, 10, 0, 20, 1);
            const double off = hinged_wheel_spin_ratio(s, h, 10, 0.2, 20, 0);
            printf("# %s h %g: spin after 10 s / before: tilted wheel %.6f, straight %.6f, "
                   "term off %.6f\n", stepper_name[s], (double)h, tilted, straight, off);
            // Single precision: the wheel's rate changes by a few 1e-6 a step,
            // which float rounding at 20 rad/s (2e-6) quantises; over the 50000
            // sub-steps of StepFast1 at 0.001 that leaves 0.2 %.
            CHECK_NEAR(tilted, 1, TOL(1e-3, 5e-3));
            CHECK_NEAR(straight, 1, TOL(1e-9, 1e-4));
            CHECK_NEAR(off, 1, TOL(1e-9, 1e-4));
        }
    }
    return 0;
}

static int test_gyroscope_on_ball_joint_precesses_at_analytic_rate(void)
{
    for (int s = STEP; s <= FAST1; s++) {
        double rise, expected;
        const double rate = gyroscope_precession(s, 0.001, 5, 0.2, 60, &rise, &expected);
        printf("# %s h 0.001: precession %.5f rad/s, m g r / (I3 w) = %.5f; the centre "
               "moved %.4f m off the pivot's plane\n", stepper_name[s], rate, expected, rise);
        CHECK_NEAR(rate / expected, 1, 0.02);
        CHECK(rise < 0.05);
    }
    return 0;
}

// A torque-free symmetric top (a capsule along each body axis in turn, the
// moments a, a about the others and c about it) spun at body rates w_s = 10
// about its axis and w_p = 1 across it: w_s stays, and (w_p, w_q) turns at
// Omega = (c - a) w_s / a (Euler's equations). Measured over 2 s from the
// body-frame rate's angle, with energy and |L| kept.
static int test_symmetric_top_precesses_at_analytic_rate(void)
{
    const double radius = 0.1, length = 0.6;
    for (int axis = 0; axis < 3; axis++) {
        const int p = (axis + 1) % 3, q = (axis + 2) % 3;
        for (int s = STEP; s <= FAST1; s++) {
            dWorldID w = dWorldCreate();
            dWorldSetGravity(w, 0, 0, 0);
            dBodyID b = dBodyCreate(w);
            dMass m;
            dMassSetCapsuleTotal(&m, 1, axis + 1, radius, length);
            dBodySetMass(b, &m);
            const double I[3] = { m.I[0], m.I[5], m.I[10] };
            const double a = I[p], c = I[axis];
            double w0[3] = { 0, 0, 0 };
            w0[axis] = 10;
            w0[p] = 1;
            dBodySetAngularVel(b, w0[0], w0[1], w0[2]);
            double wb[3], E0, L0, E, L, turned = 0, last = 0, drift = 0;
            body_state(b, I, wb, &E0, &L0);
            const dReal h = 0.01;
            for (int k = 0; k < 200; k++) {
                step_world(w, s, h);
                body_state(b, I, wb, &E, &L);
                const double angle = atan2(wb[q], wb[p]);
                double d = angle - last;
                if (d > M_PI) d -= 2 * M_PI;
                if (d < -M_PI) d += 2 * M_PI;
                turned += d;
                last = angle;
                drift = fmax(drift, fmax(fabs(E / E0 - 1), fabs(L / L0 - 1)));
            }
            const double expected = (c - a) * w0[axis] / a * 2;
            if (s == STEP)
                printf("# capsule axis %d: turned %.5f rad in 2 s (analytic %.5f), "
                       "energy and |L| within %.1e\n", axis, turned, expected, drift);
            CHECK_NEAR(turned / expected, 1, 0.01);
            CHECK_NEAR(wb[axis], w0[axis], TOL(1e-9, 1e-4));
            CHECK(drift < TOL(1e-9, 1e-4));
            dWorldDestroy(w);
        }
    }
    return 0;
}

// With the term off a torque-free body keeps its angular velocity exactly
// (ODE's behaviour, which the differential tests compare).
static int test_body_with_term_off_keeps_its_angular_velocity(void)
{
    for (int s = STEP; s <= FAST1; s++) {
        dWorldID w = dWorldCreate();
        dBodyID b = dBodyCreate(w);
        dMass m;
        dMassSetBoxTotal(&m, 1, box_side[0], box_side[1], box_side[2]);
        dBodySetMass(b, &m);
        dBodySetGyroscopicMode(b, 0);
        dBodySetAngularVel(b, 0.3, 12, 0.2);

        for (int k = 0; k < 100; k++) step_world(w, s, 0.01);

        const dReal *v = dBodyGetAngularVel(b);
        CHECK(v[0] == (dReal)0.3 && v[1] == (dReal)12 && v[2] == (dReal)0.2);
        CHECK(dBodyGetGyroscopicMode(b) == 0);
        dWorldDestroy(w);
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_torque_free_box_keeps_energy_momentum_and_flip_period),
    TEST_CASE(test_wheel_on_hinge_keeps_its_spin),
    TEST_CASE(test_gyroscope_on_ball_joint_precesses_at_analytic_rate),
    TEST_CASE(test_symmetric_top_precesses_at_analytic_rate),
    TEST_CASE(test_body_with_term_off_keeps_its_angular_velocity),
    TEST_END
};
