// SPDX-License-Identifier: BSD-3-Clause
//
// test_stepfast.c -- dWorldStepFast1 (guide chapter 8): free motion against
// dWorldStep and the sub-stepped integrator, a pendulum's length and period,
// motors, a box on contacts, chain error against the iteration count, joint
// feedback, kinematic bodies, the StepFast1 auto-disable and waking depth,
// bad input, and allocation in steady state.

#include "test.h"

#include <math.h>
#include <stdio.h>

#define G 9.81
#define PI 3.14159265358979323846

static dWorldID world_with_gravity(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    return w;
}

// A sphere of mass m and radius r at (x, y, z) (small r: a point mass).
static dBodyID sphere_body(dWorldID w, double x, double y, double z, double m, double r)
{
    dBodyID b = dBodyCreate(w);
    dMass mass;
    dMassSetSphereTotal(&mass, m, r);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    return b;
}

static double ball_separation(dJointID j)
{
    dVector3 a1, a2;
    dJointGetBallAnchor(j, a1);
    dJointGetBallAnchor2(j, a2);
    return dCalcPointsDistance3(a1, a2);
}

// A spinning, pushed asymmetric box under gravity.
static dBodyID tumbling_box(dWorldID w)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 2, 1, 2, 3);
    dBodySetMass(b, &m);
    dBodySetPosition(b, 1, 2, 3);
    dBodySetLinearVel(b, 0.5, -1, 2);
    dBodySetAngularVel(b, 0.3, 2, -1);
    return b;
}

static int same3(const dReal *a, const dReal *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static int test_one_iteration_is_dWorldStep_for_free_bodies(void)
{
    dWorldID w1 = world_with_gravity(), w2 = world_with_gravity();
    dBodyID b1 = tumbling_box(w1), b2 = tumbling_box(w2);

    for (int i = 0; i < 50; i++) {
        dBodyAddForce(b1, 1, 0, 0);
        dBodyAddTorque(b1, 0, 0.5, 0);
        dBodyAddForce(b2, 1, 0, 0);
        dBodyAddTorque(b2, 0, 0.5, 0);
        dWorldStep(w1, 0.01);
        dWorldStepFast1(w2, 0.01, 1);
    }

    // One sub-step is the same integrator with the same operations: bitwise equal.
    CHECK(same3(dBodyGetPosition(b1), dBodyGetPosition(b2)));
    CHECK(same3(dBodyGetLinearVel(b1), dBodyGetLinearVel(b2)));
    CHECK(same3(dBodyGetAngularVel(b1), dBodyGetAngularVel(b2)));
    const dReal *q1 = dBodyGetQuaternion(b1), *q2 = dBodyGetQuaternion(b2);
    CHECK(q1[0] == q2[0] && same3(q1 + 1, q2 + 1));
    dWorldDestroy(w1);
    dWorldDestroy(w2);
    return 0;
}

static int test_free_fall_follows_the_sub_stepped_integrator(void)
{
    dWorldID w = world_with_gravity();
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, 0, 0, 10);
    const double h = 0.01;
    const int n = 100, iters = 10;

    for (int i = 0; i < n; i++) dWorldStepFast1(w, h, iters);

    // Semi-implicit Euler over K = n * iters sub-steps of s = h / iters:
    // v_k = -g k s, z_K = z0 - g s^2 K (K + 1) / 2 = z0 - g h^2 n (n + 1/iters) / 2.
    // dWorldStep (one sub-step per step) gives z0 - g h^2 n (n + 1) / 2, lower by
    // g h^2 n (1 - 1/iters) / 2 = 0.0441 m here.
    const double s = h / iters, K = (double)n * iters;
    CHECK_NEAR(dBodyGetLinearVel(b)[2], -G * n * h, TOL(1e-10, 1e-4));
    CHECK_NEAR(dBodyGetPosition(b)[2], 10 - G * s * s * K * (K + 1) / 2, TOL(1e-10, 1e-4));
    CHECK_NEAR(dBodyGetPosition(b)[2] - (10 - G * h * h * n * (n + 1) / 2),
               G * h * h * n * (1 - 1.0 / iters) / 2, TOL(1e-10, 1e-4));
    CHECK(dBodyGetForce(b)[2] == 0);   // the accumulator is cleared after the step
    dWorldDestroy(w);
    return 0;
}

static int test_accumulated_force_acts_over_the_whole_step(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = sphere_body(w, 0, 0, 0, 2, 0.5);   // I = 2/5 m r^2 = 0.2
    const double h = 0.02;

    dBodyAddForce(b, 4, 0, 0);
    dBodyAddTorque(b, 0, 0, 1);
    dWorldStepFast1(w, h, 7);

    // Seven shares of h/7 add up to the full impulse: v = F h / m, w = T h / I.
    CHECK_NEAR(dBodyGetLinearVel(b)[0], 4 * h / 2, TOL(1e-14, 1e-6));
    CHECK_NEAR(dBodyGetAngularVel(b)[2], 1 * h / 0.2, TOL(1e-14, 1e-6));
    CHECK(dBodyGetForce(b)[0] == 0 && dBodyGetTorque(b)[2] == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_ball_pendulum_keeps_length_and_period(void)
{
    dWorldID w = world_with_gravity();
    const double L = 1, a0 = 0.05, h = 0.01;
    dBodyID bob = sphere_body(w, L * sin(a0), 0, -L * cos(a0), 1, 0.001);
    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, bob, 0);
    dJointSetBallAnchor(ball, 0, 0, 0);
    double worst = 0, first = -1, last = -1, max_x = 0;
    int crossings = 0;
    dReal prev = dBodyGetPosition(bob)[0];

    for (int i = 1; i <= 500; i++) {   // 5 s
        dWorldStepFast1(w, h, 10);
        const dReal *p = dBodyGetPosition(bob);
        double e = fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - L);
        if (e > worst) worst = e;
        if (i > 250 && fabs(p[0]) > max_x) max_x = fabs(p[0]);
        if ((prev < 0) != (p[0] < 0)) {
            double t = (i - 1 + prev / (prev - p[0])) * h;   // interpolated crossing
            if (first < 0) first = t;
            last = t;
            crossings++;
        }
        prev = p[0];
    }

    double period = 2 * (last - first) / (crossings - 1), expected = 2 * PI * sqrt(L / G);
    printf("# length error %.3g m; period %.5f s vs 2 pi sqrt(L/g) = %.5f s; "
           "amplitude after 2.5 s %.4f of %.4f m\n", worst, period, expected, max_x, L * sin(a0));
    CHECK(worst < 1e-3);
    CHECK(crossings >= 4);
    CHECK_NEAR(period, expected, 0.02 * expected);
    CHECK(max_x > 0.5 * L * sin(a0));   // not damped away
    dWorldDestroy(w);
    return 0;
}

static dJointID wheel_on_hinge(dWorldID w, dBodyID *wheel)
{
    *wheel = dBodyCreate(w);
    dMass m;
    dMassSetCylinderTotal(&m, 2, 3, 0.5, 0.1);   // axis z: Izz = 2 * 0.25 / 2 = 0.25
    dBodySetMass(*wheel, &m);
    dJointID hinge = dJointCreateHinge(w, 0);
    dJointAttach(hinge, *wheel, 0);
    dJointSetHingeAnchor(hinge, 0, 0, 0);
    dJointSetHingeAxis(hinge, 0, 0, 1);
    return hinge;
}

static int test_hinge_motor_reaches_its_speed(void)
{
    dWorldID w = dWorldCreate();
    dBodyID wheel;
    dJointID hinge = wheel_on_hinge(w, &wheel);
    dJointSetHingeParam(hinge, dParamVel, 5);
    dJointSetHingeParam(hinge, dParamFMax, 1000);

    dWorldStepFast1(w, 0.01, 10);

    // The motor row is solved with the hinge's other rows in each sub-step.
    CHECK_NEAR(dJointGetHingeAngleRate(hinge), 5, TOL(1e-6, 1e-3));
    CHECK_NEAR(dBodyGetAngularVel(wheel)[2], 5, TOL(1e-6, 1e-3));
    for (int i = 0; i < 100; i++) dWorldStepFast1(w, 0.01, 10);
    CHECK_NEAR(dJointGetHingeAngleRate(hinge), 5, TOL(1e-6, 1e-3));
    const dReal *p = dBodyGetPosition(wheel);
    CHECK(fabs(p[0]) < 1e-9 && fabs(p[1]) < 1e-9 && fabs(p[2]) < 1e-9);
    dWorldDestroy(w);
    return 0;
}

static int test_weak_hinge_motor_is_torque_limited(void)
{
    dWorldID w = dWorldCreate();
    dBodyID wheel;
    dJointID hinge = wheel_on_hinge(w, &wheel);
    dJointSetHingeParam(hinge, dParamVel, 5);
    dJointSetHingeParam(hinge, dParamFMax, 1);
    const double h = 0.01;

    dWorldStepFast1(w, h, 10);

    // Each sub-step adds FMax s / I; the step adds FMax h / I = 0.04 rad/s.
    CHECK_NEAR(dJointGetHingeAngleRate(hinge), 1 * h / 0.25, TOL(1e-9, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// Contacts under a unit box at its four bottom corners, with the penetration
// of each corner below the plane z = 0 as depth (0 if above: the contacts
// stay, so nothing but the solver keeps the box from creeping upwards).
static void box_corner_contacts(dWorldID w, dJointGroupID g, dBodyID box, dJointFeedback fb[4])
{
    for (int k = 0; k < 4; k++) {
        dVector3 c;
        dBodyGetRelPointPos(box, k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, -0.5, c);
        dContact ct = { 0 };
        ct.surface.mode = dContactApprox1;
        ct.surface.mu = 1;
        ct.geom.pos[0] = c[0];
        ct.geom.pos[1] = c[1];
        ct.geom.normal[2] = 1;
        ct.geom.depth = c[2] < 0 ? -c[2] : 0;
        dJointID j = dJointCreateContact(w, g, &ct);
        dJointAttach(j, box, 0);
        dJointSetFeedback(j, &fb[k]);
    }
}

static int test_box_on_four_contacts_stays_put(void)
{
    dWorldID w = world_with_gravity();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID box = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 1, 1, 1, 1);
    dBodySetMass(box, &m);
    dBodySetPosition(box, 0, 0, 0.5);
    dJointFeedback fb[4];
    double worst_z = 0, worst_xy = 0, worst_tilt = 0;

    for (int i = 0; i < 500; i++) {   // 5 s
        box_corner_contacts(w, g, box, fb);
        dWorldStepFast1(w, 0.01, 10);
        dJointGroupEmpty(g);
        const dReal *p = dBodyGetPosition(box), *R = dBodyGetRotation(box);
        worst_z = fmax(worst_z, fabs(p[2] - 0.5));
        worst_xy = fmax(worst_xy, hypot(p[0], p[1]));
        worst_tilt = fmax(worst_tilt, hypot(R[2], R[6]));   // the body z axis off vertical
    }

    // The four contact forces (each statically indeterminate) carry the
    // weight and add up to no sideways force. They are the last sub-step's:
    // a residual speed jitter dv ~ 1e-7 m/s over s = 1e-3 s is m dv / s ~ 1e-4 N.
    double fx = 0, fy = 0, fz = 0;
    for (int k = 0; k < 4; k++) {
        fx += fb[k].f1[0];
        fy += fb[k].f1[1];
        fz += fb[k].f1[2];
    }
    printf("# box on 4 contacts over 5 s: |z - 0.5| <= %.3g m, drift %.3g m, tilt %.3g; "
           "contact force (%.3g, %.3g, %.6f) N (m g = %.6f N)\n", worst_z, worst_xy, worst_tilt,
           fx, fy, fz, G);
    CHECK(worst_z < TOL(1e-5, 1e-3));
    CHECK(worst_xy < TOL(1e-5, 1e-3));
    CHECK(worst_tilt < TOL(1e-5, 1e-3));
    CHECK_NEAR(fz, G, TOL(1e-3, 1e-2));
    CHECK(fabs(fx) < TOL(1e-3, 1e-2) && fabs(fy) < TOL(1e-3, 1e-2));
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Worst ball-joint separation of a 10-link chain released horizontally, over
// 2 s of h = 0.01 with `iters` iterations.
static double chain_error(int iters)
{
    enum { LINKS = 10 };
    dWorldID w = world_with_gravity();
    dJointID joint[LINKS];
    const double len = 0.1;
    dMass m;
    dMassSetCapsuleTotal(&m, 0.1, 1, 0.01, len);
    dBodyID prev = 0;
    for (int i = 0; i < LINKS; i++) {
        dBodyID b = dBodyCreate(w);
        dBodySetMass(b, &m);
        dBodySetPosition(b, (i + 0.5) * len, 0, 0);
        joint[i] = dJointCreateBall(w, 0);
        dJointAttach(joint[i], b, prev);
        dJointSetBallAnchor(joint[i], i * len, 0, 0);
        prev = b;
    }
    double worst = 0;
    for (int step = 0; step < 200; step++) {
        dWorldStepFast1(w, 0.01, iters);
        for (int i = 0; i < LINKS; i++) worst = fmax(worst, ball_separation(joint[i]));
    }
    dWorldDestroy(w);
    return worst;
}

static int test_more_iterations_reduce_chain_error(void)
{
    const int iters[] = { 1, 2, 5, 10, 20, 40 };
    double err[6];
    printf("# 10-link chain, worst joint error over 2 s:");
    for (int k = 0; k < 6; k++) {
        err[k] = chain_error(iters[k]);
        printf(" %d it: %.3g m%s", iters[k], err[k], k < 5 ? ";" : "\n");
    }
    for (int k = 1; k < 6; k++) CHECK(err[k] < err[k - 1]);
    CHECK(err[5] < 0.1 * err[0]);
    return 0;
}

static int test_feedback_of_static_pendulum_is_its_weight(void)
{
    dWorldID w = world_with_gravity();
    dBodyID bob = sphere_body(w, 0, 0, -1, 3, 0.1);
    dJointID hinge = dJointCreateHinge(w, 0);
    dJointAttach(hinge, bob, 0);
    dJointSetHingeAnchor(hinge, 0, 0, 0);
    dJointSetHingeAxis(hinge, 1, 0, 0);
    dJointFeedback fb;
    dJointSetFeedback(hinge, &fb);

    for (int i = 0; i < 10; i++) dWorldStepFast1(w, 0.01, 5);

    // The joint holds the bob up. In single precision a position rounding
    // error e ~ 1e-6 m is corrected by a force ~ m ERP e / h^2 ~ 6e-3 N.
    CHECK_NEAR(fb.f1[2], 3 * G, TOL(1e-6, 1e-2));
    CHECK_NEAR(fb.f1[0], 0, TOL(1e-6, 1e-2));
    CHECK_NEAR(fb.t1[0], 0, TOL(1e-6, 1e-2));
    // The world CFM makes the joint soft: it sags towards h CFM m g / ERP
    // (1.5e-10 m in double, 1.5e-5 m in single precision).
    const double sag = 0.01 * dWorldGetCFM(w) * 3 * G / dWorldGetERP(w);
    CHECK_NEAR(dBodyGetPosition(bob)[2], -1, sag + TOL(1e-9, 1e-6));
    dWorldDestroy(w);
    return 0;
}

static int test_kinematic_body_drags_a_joined_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID kin = dBodyCreate(w), dyn = sphere_body(w, 0, 0, -1, 1, 0.1);
    dBodySetKinematic(kin);
    dBodySetLinearVel(kin, 1, 0, 0);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, dyn, kin);
    dJointSetBallAnchor(j, 0, 0, 0);
    double worst = 0;

    for (int i = 0; i < 100; i++) {
        dWorldStepFast1(w, 0.01, 10);
        worst = fmax(worst, ball_separation(j));
    }

    // Seen from the kinematic body the free body starts moving at -1 m/s
    // on a circle of radius 1: after 1 s it has turned 1 rad, to
    // (1 - sin 1, 0, -cos 1) in the world. The kinematic body moves every
    // sub-step, so the joint never lags it.
    const dReal *p = dBodyGetPosition(dyn);
    printf("# kinematic drag: worst joint error %.3g m; x %.4f (1 - sin 1 = %.4f), "
           "z %.4f (-cos 1 = %.4f)\n", worst, p[0], 1 - sin(1.0), p[2], -cos(1.0));
    CHECK_NEAR(dBodyGetPosition(kin)[0], 1, TOL(1e-9, 1e-5));
    CHECK_NEAR(p[0], 1 - sin(1.0), 0.01);
    CHECK_NEAR(p[2], -cos(1.0), 0.01);
    CHECK(worst < 1e-3);
    dWorldDestroy(w);
    return 0;
}

static int test_soft_ball_joint_is_the_same_spring_as_under_dWorldStep(void)
{
    // ERP and CFM from kp, kd for the step h (guide 3.8): the rows see
    // c = ERP error / h, so the spring is kp = ERP / (h CFM) whatever the
    // number of iterations, and a hanging mass m sags m g / kp.
    dWorldID w = world_with_gravity();
    dBodyID b = sphere_body(w, 0, 0, 0, 2, 0.1);
    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, b, 0);
    dJointSetBallAnchor(ball, 0, 0, 0);
    const double h = 0.01, kp = 2000, kd = 40;
    dJointSetBallParam(ball, dParamERP, h * kp / (h * kp + kd));
    dJointSetBallParam(ball, dParamCFM, 1 / (h * kp + kd));

    for (int i = 0; i < 2000; i++) dWorldStepFast1(w, h, 10);

    CHECK_NEAR(dBodyGetPosition(b)[2], -2 * G / kp, 0.01 * 2 * G / kp);
    dWorldDestroy(w);
    return 0;
}

// Worst joint error of a ball pendulum (length 1) released level, over 2 s
// of h = 0.01: stepper 0 dWorldStep, 1 dWorldStepFast1, 2 alternating.
static double swing_error(int stepper)
{
    dWorldID w = world_with_gravity();
    dBodyID bob = sphere_body(w, 1, 0, 0, 1, 0.01);
    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, bob, 0);
    dJointSetBallAnchor(ball, 0, 0, 0);
    double worst = 0;
    for (int i = 0; i < 200; i++) {
        if (stepper == 0 || (stepper == 2 && i % 2)) dWorldStep(w, 0.01);
        else dWorldStepFast1(w, 0.01, 10);
        worst = fmax(worst, ball_separation(ball));
    }
    dWorldDestroy(w);
    return worst;
}

static int test_steppers_can_be_switched_at_will(void)
{
    // Guide 8.2: StepFast1 uses the world and bodies as dWorldStep does, so
    // alternating them is as good as the worse of the two.
    double step = swing_error(0), fast = swing_error(1), mixed = swing_error(2);

    printf("# level release, worst joint error over 2 s: dWorldStep %.3g m, "
           "StepFast1 (10 it) %.3g m, alternating %.3g m\n", step, fast, mixed);
    CHECK(mixed <= fmax(step, fast));
    CHECK(mixed < 0.01);
    return 0;
}

static int moved_calls;
static void count_moved(dBodyID b)
{
    (void)b;
    moved_calls++;
}

static int test_bodies_are_reported_moved_once_per_step(void)
{
    dWorldID w = world_with_gravity();
    dBodyID b = sphere_body(w, 0, 0, 0, 1, 0.1);
    dBodySetMovedCallback(b, count_moved);
    moved_calls = 0;

    for (int i = 0; i < 3; i++) dWorldStepFast1(w, 0.01, 10);

    CHECK(moved_calls == 3);
    dWorldDestroy(w);
    return 0;
}

// A world without gravity and a body with StepFast1 auto-disable moving at speed v.
static dBodyID sf1_body(dWorldID w, double x, double v)
{
    dBodyID b = sphere_body(w, x, 0, 0, 1, 0.1);
    dBodySetAutoDisableSF1(b, 1);
    dBodySetLinearVel(b, v, 0, 0);
    return b;
}

static int test_idle_body_is_disabled_after_sf1_steps(void)
{
    dWorldID w = dWorldCreate();
    dBodyID still = sf1_body(w, 0, 0);
    dBodyID slow = sf1_body(w, 1, 0.05);    // |v|^2 = 0.0025 <= 0.003 (it is the square)
    dBodyID fast = sf1_body(w, 2, 0.06);    // |v|^2 = 0.0036 > 0.003
    dBodyID plain = sphere_body(w, 3, 0, 0, 1, 0.1);   // auto-disable off
    dBodyID quick = sf1_body(w, 4, 0);
    dBodySetAutoDisableStepsSF1(quick, 3);
    CHECK(dBodyGetAutoDisableThresholdSF1(still) == (dReal)0.003);
    CHECK(dBodyGetAutoDisableStepsSF1(still) == 10);

    for (int i = 0; i < 3; i++) dWorldStepFast1(w, 0.01, 4);
    CHECK(!dBodyIsEnabled(quick));
    for (int i = 3; i < 9; i++) dWorldStepFast1(w, 0.01, 4);
    CHECK(dBodyIsEnabled(still) && dBodyIsEnabled(slow));
    dWorldStepFast1(w, 0.01, 4);   // the 10th idle step
    CHECK(!dBodyIsEnabled(still) && !dBodyIsEnabled(slow));
    CHECK(dBodyGetLinearVel(slow)[0] == 0);   // stopped when disabled

    const dReal x = dBodyGetPosition(slow)[0];
    for (int i = 0; i < 20; i++) dWorldStepFast1(w, 0.01, 4);
    CHECK(dBodyGetPosition(slow)[0] == x);   // disabled: not stepped
    CHECK(dBodyIsEnabled(fast) && dBodyIsEnabled(plain));
    dWorldDestroy(w);
    return 0;
}

static int test_world_auto_disable_applies_too(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetAutoDisableFlag(w, 1);
    dWorldSetAutoDisableSteps(w, 5);
    dBodyID b = sphere_body(w, 0, 0, 0, 1, 0.1);

    for (int i = 0; i < 4; i++) dWorldStepFast1(w, 0.01, 3);
    CHECK(dBodyIsEnabled(b));
    dWorldStepFast1(w, 0.01, 3);
    CHECK(!dBodyIsEnabled(b));
    dWorldDestroy(w);
    return 0;
}

// Three bodies in a row (x = 0, 1, 2) joined by ball joints: a moves along y,
// b and c are disabled.
static void three_body_chain(dWorldID w, dBodyID body[3])
{
    for (int i = 0; i < 3; i++) body[i] = sphere_body(w, i, 0, 0, 1, 0.1);
    for (int i = 0; i < 2; i++) {
        dJointID j = dJointCreateBall(w, 0);
        dJointAttach(j, body[i], body[i + 1]);
        dJointSetBallAnchor(j, i + 0.5, 0, 0);
    }
    dBodySetLinearVel(body[0], 0, 1, 0);
    dBodyDisable(body[1]);
    dBodyDisable(body[2]);
}

static int test_enabled_body_wakes_its_jointed_neighbours(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body[3];
    three_body_chain(w, body);
    CHECK(dWorldGetAutoEnableDepthSF1(w) >= 1000);   // guide 8.4: a large default

    dWorldStepFast1(w, 0.01, 5);

    CHECK(dBodyIsEnabled(body[1]) && dBodyIsEnabled(body[2]));
    // All three took part: the joints only exchange momentum (total 1 along y),
    // and the woken bodies were set moving (mostly spinning: they are small).
    double py = 0;
    for (int i = 0; i < 3; i++) py += dBodyGetLinearVel(body[i])[1];
    CHECK_NEAR(py, 1, TOL(1e-12, 1e-5));
    CHECK(fabs(dBodyGetAngularVel(body[1])[2]) > 0.1 && fabs(dBodyGetAngularVel(body[2])[2]) > 0.1);
    dWorldDestroy(w);
    return 0;
}

static int test_auto_enable_depth_zero_never_wakes(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body[3];
    three_body_chain(w, body);
    dWorldSetAutoEnableDepthSF1(w, 0);
    const dReal y1 = dBodyGetPosition(body[1])[1];

    for (int i = 0; i < 50; i++) dWorldStepFast1(w, 0.01, 5);

    CHECK(!dBodyIsEnabled(body[1]) && !dBodyIsEnabled(body[2]));
    CHECK(dBodyGetPosition(body[1])[1] == y1);
    // The sleeping body holds its joint like static geometry: body 0 swings
    // about the anchor at x = 0.5 instead of flying off along y.
    dVector3 anchor = { 0.5, 0, 0, 0 };
    CHECK_NEAR(dCalcPointsDistance3(dBodyGetPosition(body[0]), anchor), 0.5, 1e-3);
    dWorldDestroy(w);
    return 0;
}

static int test_auto_enable_depth_one_wakes_one_hop_per_step(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body[3];
    three_body_chain(w, body);
    dWorldSetAutoEnableDepthSF1(w, 1);

    dWorldStepFast1(w, 0.01, 5);
    CHECK(dBodyIsEnabled(body[1]));
    CHECK(!dBodyIsEnabled(body[2]));

    dWorldStepFast1(w, 0.01, 5);   // body 1 is enabled now: its neighbour wakes
    CHECK(dBodyIsEnabled(body[2]));
    dWorldDestroy(w);
    return 0;
}

static int test_bad_input_is_reported_and_changes_nothing(void)
{
    test_capture_reports();
    dWorldID w = world_with_gravity();
    dBodyID b = sphere_body(w, 0, 0, 0, 1, 0.1), sleeper = sphere_body(w, 1, 0, 0, 1, 0.1);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, sleeper);
    dJointSetBallAnchor(j, 0.5, 0, 0);
    dBodyDisable(sleeper);
    dBodyAddForce(b, 1, 2, 3);

    dWorldStepFast1(w, 0.01, 0);
    dWorldStepFast1(w, 0.01, -3);
    dWorldStepFast1(w, 0, 10);
    dWorldStepFast1(w, -0.01, 10);
    dWorldStepFast1(w, NAN, 10);
    dWorldStepFast1(w, INFINITY, 10);
    dWorldStepFast1(0, 0.01, 10);

    CHECK(test_captured_count() == 7);
    CHECK(test_captured_contains("dWorldStepFast1: maxiterations must be >= 1, got 0"));
    CHECK(test_captured_contains("dWorldStepFast1: maxiterations must be >= 1, got -3"));
    CHECK(test_captured_contains("dWorldStepFast1: stepsize must be positive and finite"));
    CHECK(test_captured_contains("dWorldStepFast1: world is NULL"));
    CHECK(dBodyGetPosition(b)[2] == 0 && dBodyGetLinearVel(b)[2] == 0);
    CHECK(dBodyGetForce(b)[2] == 3);   // the accumulator is kept for the next real step
    CHECK(!dBodyIsEnabled(sleeper));   // not woken
    dWorldDestroy(w);
    return 0;
}

static int test_steady_state_allocates_nothing(void)
{
    enum { LINKS = 30 };
    dWorldID w = world_with_gravity();
    dBodyID prev = 0;
    for (int i = 0; i < LINKS; i++) {
        dBodyID b = sphere_body(w, 0.1 * (i + 1), 0, 0, 1, 0.05);
        dJointID j = i % 2 ? dJointCreateHinge(w, 0) : dJointCreateBall(w, 0);
        dJointAttach(j, b, prev);
        if (i % 2) {
            dJointSetHingeAnchor(j, 0.1 * i, 0, 0);
            dJointSetHingeAxis(j, 0, 1, 0);
        } else {
            dJointSetBallAnchor(j, 0.1 * i, 0, 0);
        }
        prev = b;
    }
    dWorldStepFast1(w, 0.01, 10);   // warm up: the arena grows to its peak
    dWorldStepFast1(w, 0.01, 10);
    test_count_allocations();
    for (int i = 0; i < 20; i++) dWorldStepFast1(w, 0.01, 10);
    CHECK(test_allocations_counted() == 0);
    CHECK(isfinite(dBodyGetPosition(prev)[2]));
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_one_iteration_is_dWorldStep_for_free_bodies),
    TEST_CASE(test_free_fall_follows_the_sub_stepped_integrator),
    TEST_CASE(test_accumulated_force_acts_over_the_whole_step),
    TEST_CASE(test_ball_pendulum_keeps_length_and_period),
    TEST_CASE(test_hinge_motor_reaches_its_speed),
    TEST_CASE(test_weak_hinge_motor_is_torque_limited),
    TEST_CASE(test_box_on_four_contacts_stays_put),
    TEST_CASE(test_more_iterations_reduce_chain_error),
    TEST_CASE(test_feedback_of_static_pendulum_is_its_weight),
    TEST_CASE(test_soft_ball_joint_is_the_same_spring_as_under_dWorldStep),
    TEST_CASE(test_steppers_can_be_switched_at_will),
    TEST_CASE(test_kinematic_body_drags_a_joined_body),
    TEST_CASE(test_bodies_are_reported_moved_once_per_step),
    TEST_CASE(test_idle_body_is_disabled_after_sf1_steps),
    TEST_CASE(test_world_auto_disable_applies_too),
    TEST_CASE(test_enabled_body_wakes_its_jointed_neighbours),
    TEST_CASE(test_auto_enable_depth_zero_never_wakes),
    TEST_CASE(test_auto_enable_depth_one_wakes_one_hop_per_step),
    TEST_CASE(test_bad_input_is_reported_and_changes_nothing),
    TEST_CASE(test_steady_state_allocates_nothing),
    TEST_END
};
