// SPDX-License-Identifier: BSD-3-Clause
//
// test_step.c -- dWorldStep against physics: free fall, torques, angular
// momentum, a pendulum's period, chain joint error, hinged boxes resting on
// contacts, joint feedback, motors, stops, soft joints as springs, auto-disable
// and waking, kinematic bodies.

#include "test.h"

static const dReal g = 9.81;

// A world with gravity -g along z.
static dWorldID world_with_gravity(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -g);
    return w;
}

static int test_free_fall_follows_semi_implicit_euler(void)
{
    dWorldID w = world_with_gravity();
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, 0, 0, 10);
    const dReal h = 0.01;
    const int n = 100;

    for (int i = 0; i < n; i++) dWorldStep(w, h);

    // v_k = -g k h, z_n = z0 - g h^2 n (n+1) / 2: exact for this integrator,
    // and within g h t / 2 of the continuous 10 - g t^2 / 2.
    const dReal t = n * h;
    CHECK_NEAR(dBodyGetLinearVel(b)[2], -g * t, TOL(1e-9, 1e-4));
    CHECK_NEAR(dBodyGetPosition(b)[2], 10 - g * h * h * n * (n + 1) / 2, TOL(1e-9, 1e-4));
    CHECK_NEAR(dBodyGetPosition(b)[2], 10 - g * t * t / 2, g * h * t / 2 + TOL(1e-9, 1e-4));
    CHECK(dBodyGetForce(b)[2] == 0);   // accumulators are zeroed after the step
    dWorldDestroy(w);
    return 0;
}

static int test_force_at_offset_spins_the_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 2, 1, 2, 3);   // Izz = 2 (1 + 4) / 12
    dBodySetMass(b, &m);
    const dReal h = 0.001;

    dBodyAddForceAtRelPos(b, 0, 4, 0, 0.5, 0, 0);   // torque 0.5 * 4 = 2 about z
    dWorldStep(w, h);

    CHECK_NEAR(dBodyGetLinearVel(b)[1], 4 / 2.0 * h, 1e-12);
    CHECK_NEAR(dBodyGetAngularVel(b)[2], 2 / (2.0 * 5 / 12) * h, TOL(1e-12, 1e-6));
    dWorldDestroy(w);
    return 0;
}

// A torque-free asymmetric box spinning fast about z (its axis of least
// inertia) with a little wobble, for 10 s at h = 0.01: returns the relative
// change of its angular momentum L and sets the ratio of final to initial
// kinetic energy.
static double angular_momentum_drift(int finite, double *energy_ratio)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 1, 1, 2, 3);
    dBodySetMass(b, &m);
    dBodySetFiniteRotationMode(b, finite);
    dBodySetAngularVel(b, 0.1, 0.1, 20);
    dVector3 L0 = { 0 }, L = { 0 };
    double E0 = 0, E = 0;

    for (int step = 0; step <= 1000; step++) {
        const dReal *R = dBodyGetRotation(b), *wv = dBodyGetAngularVel(b);
        dMatrix3 tmp, I;
        dMultiply2_333(tmp, m.I, R);
        dMultiply0_333(I, R, tmp);
        dMultiply0_331(L, I, wv);
        E = 0.5 * dCalcVectorDot3(wv, L);
        if (step == 0) {
            dCopyVector3(L0, L);
            E0 = E;
        }
        if (step < 1000) dWorldStep(w, 0.01);
    }
    dWorldDestroy(w);
    dVector3 d;
    dSubtractVectors3(d, L, L0);
    *energy_ratio = E / E0;
    return dCalcVectorLength3(d) / dCalcVectorLength3(L0);
}

static int test_torque_free_body_keeps_angular_momentum(void)
{
    double e_inf, e_fin;
    double infinitesimal = angular_momentum_drift(0, &e_inf);
    double finite = angular_momentum_drift(1, &e_fin);

    // (The reference ODE 0.16 loses a third of this body's energy in these 10 s.)
    printf("# |dL|/|L| over 10 s: infinitesimal %.3g, finite %.3g; energy ratio %.9f, %.9f\n",
           infinitesimal, finite, e_inf, e_fin);
    // (The world vector L is measured with the rate the step ends on, which
    // leads the mean rate of the step's turn: a bounded offset of order h w,
    // in either rotation mode. Its length and the energy are kept to
    // rounding: test_gyroscopic.c.)
    CHECK(finite < TOL(0.01, 0.02));
    CHECK(infinitesimal < TOL(0.01, 0.02));
    // (No energy gain beyond rounding: 1000 steps of 6e-8 in single precision.)
    CHECK(e_inf <= 1.0 + TOL(1e-9, 2e-5) && e_inf > 1.0 - TOL(1e-9, 2e-5));
    CHECK(e_fin <= 1.0 + TOL(1e-9, 2e-5) && e_fin > 1.0 - TOL(1e-9, 2e-5));
    return 0;
}

// Rotation angle about z after spinning at 20 rad/s for 1 s at h = 0.01.
static double spin_angle_error(int finite)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dBodySetFiniteRotationMode(b, finite);
    dBodySetAngularVel(b, 0, 0, 20);

    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);

    const dReal *q = dBodyGetQuaternion(b);
    double angle = 2 * atan2(q[3], q[0]);
    double err = fmod(fabs(angle - 20.0), 2 * M_PI);
    dWorldDestroy(w);
    return err < M_PI ? err : 2 * M_PI - err;
}

static int test_finite_rotation_mode_integrates_spin_exactly(void)
{
    double finite = spin_angle_error(1), infinitesimal = spin_angle_error(0);

    // An infinitesimal update turns by 2 atan(w h / 2) instead of w h per step.
    CHECK_NEAR(finite, 0, TOL(1e-9, 1e-4));
    CHECK_NEAR(infinitesimal, 100 * (0.2 - 2 * atan(0.1)), TOL(1e-6, 1e-3));
    return 0;
}

// Hinge pendulum of length L (point-like bob) released at `angle`; returns
// the measured period from zero crossings of the hinge angle.
static double pendulum_period(dReal L, dReal angle, int *crossings_out)
{
    dWorldID w = world_with_gravity();
    dBodyID bob = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, 1, 0.001);
    dBodySetMass(bob, &m);
    dBodySetPosition(bob, L * dSin(angle), 0, -L * dCos(angle));
    dJointID hinge = dJointCreateHinge(w, 0);
    dJointAttach(hinge, bob, 0);
    dJointSetHingeAnchor(hinge, 0, 0, 0);
    dJointSetHingeAxis(hinge, 0, 1, 0);
    const dReal h = 0.001;
    double first = -1, last = -1;
    int crossings = 0;
    dReal prev = dBodyGetPosition(bob)[0];

    for (int i = 1; i <= 20000; i++) {
        dWorldStep(w, h);
        dReal x = dBodyGetPosition(bob)[0];
        if ((prev < 0) != (x < 0)) {
            double t = (i - 1 + prev / (prev - x)) * h;   // interpolated crossing time
            if (first < 0) first = t;
            last = t;
            crossings++;
        }
        prev = x;
    }
    dWorldDestroy(w);
    *crossings_out = crossings;
    return 2 * (last - first) / (crossings - 1);
}

static int test_hinge_pendulum_has_small_angle_period(void)
{
    int crossings;
    const dReal L = 1;

    double period = pendulum_period(L, 0.05, &crossings);

    double expected = 2 * M_PI * sqrt(L / g);
    printf("# period %.5f s, 2 pi sqrt(L/g) = %.5f s\n", period, expected);
    CHECK(crossings >= 20);
    CHECK_NEAR(period, expected, 0.01 * expected);
    return 0;
}

static int test_chain_joint_error_stays_small(void)
{
    enum { LINKS = 20 };
    dWorldID w = world_with_gravity();
    dBodyID body[LINKS];
    dJointID joint[LINKS];
    const dReal len = 0.1;
    dMass m;
    dMassSetCapsuleTotal(&m, 0.1, 1, 0.01, len);
    // Straight, released 15 degrees from hanging vertically. (Released
    // horizontally, the whip of the free end makes first-order integration
    // drift by ~8 cm at h = 0.01: the reference ODE 0.16 gives the same
    // 0.0777 m as this library.)
    const dReal angle = 75 * M_PI / 180, dx = dCos(angle), dz = -dSin(angle);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, angle);
    for (int i = 0; i < LINKS; i++) {
        body[i] = dBodyCreate(w);
        dBodySetMass(body[i], &m);
        dBodySetRotation(body[i], R);
        dBodySetPosition(body[i], (i + 0.5) * len * dx, 0, (i + 0.5) * len * dz);
        joint[i] = dJointCreateBall(w, 0);
        dJointAttach(joint[i], body[i], i ? body[i - 1] : 0);
        dJointSetBallAnchor(joint[i], i * len * dx, 0, i * len * dz);
    }
    double worst = 0;

    for (int step = 0; step < 1000; step++) {   // 10 s at h = 0.01
        dWorldStep(w, 0.01);
        for (int i = 0; i < LINKS; i++) {
            dVector3 a1, a2;
            dJointGetBallAnchor(joint[i], a1);
            dJointGetBallAnchor2(joint[i], a2);
            double e = dCalcPointsDistance3(a1, a2);
            if (e > worst) worst = e;
        }
    }
    printf("# worst joint error over 10 s: %.3g m\n", worst);
    CHECK(worst < 1e-3);
    dWorldDestroy(w);
    return 0;
}

// Contacts under a unit box at its four bottom corners, with the penetration of each corner
// below the plane z = 0 as depth (0 if above: the contacts stay).
static void box_corner_contacts(dWorldID w, dJointGroupID g, dBodyID box)
{
    for (int k = 0; k < 4; k++) {
        dVector3 c;
        dBodyGetRelPointPos(box, k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, -0.5, c);
        dContact ct = { 0 };
        ct.surface.mode = dContactApprox1;
        ct.surface.mu = 0.8;
        ct.geom.pos[0] = c[0];
        ct.geom.pos[1] = c[1];
        ct.geom.normal[2] = 1;
        ct.geom.depth = c[2] < 0 ? -c[2] : 0;
        dJointID j = dJointCreateContact(w, g, &ct);
        dJointAttach(j, box, 0);
    }
}

static int test_hinged_boxes_rest_on_their_contacts(void)
{
    // Eight unit boxes in a row, hinged edge to edge (hinge stops at +-0.3 rad), thrown onto
    // the plane with some spin: one island of 35 joint rows, stop rows and 96 contact rows
    // with friction. They must come to rest flat, the hinges closed.
    enum { BOXES = 8 };
    dWorldID w = world_with_gravity();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID box[BOXES];
    dJointID hinge[BOXES - 1];
    dMass m;
    dMassSetBoxTotal(&m, 1, 1, 1, 1);
    for (int i = 0; i < BOXES; i++) {
        box[i] = dBodyCreate(w);
        dBodySetMass(box[i], &m);
        dBodySetPosition(box[i], 1.01 * i, 0, 0.5);
        dBodySetLinearVel(box[i], 0.1, 0, -0.2);
        dBodySetAngularVel(box[i], 0.1 * (i % 3), 0.2, -0.1);
        if (i == 0) continue;
        hinge[i - 1] = dJointCreateHinge(w, 0);
        dJointAttach(hinge[i - 1], box[i - 1], box[i]);
        dJointSetHingeAnchor(hinge[i - 1], 1.01 * i - 0.505, 0, 0.5);
        dJointSetHingeAxis(hinge[i - 1], 0, 1, 0);
        dJointSetHingeParam(hinge[i - 1], dParamLoStop, -0.3);
        dJointSetHingeParam(hinge[i - 1], dParamHiStop, 0.3);
    }
    for (int step = 0; step < 300; step++) {   // 3 s
        for (int i = 0; i < BOXES; i++) box_corner_contacts(w, g, box[i]);
        dWorldStep(w, 0.01);
        dJointGroupEmpty(g);
    }
    double worst_z = 0, speed = 0, sep = 0;
    for (int i = 0; i < BOXES; i++) {
        worst_z = fmax(worst_z, fabs(dBodyGetPosition(box[i])[2] - 0.5));
        speed = fmax(speed, dCalcVectorLength3(dBodyGetLinearVel(box[i])));
        speed = fmax(speed, dCalcVectorLength3(dBodyGetAngularVel(box[i])));
        if (i == 0) continue;
        dVector3 a1, a2;
        dJointGetHingeAnchor(hinge[i - 1], a1);
        dJointGetHingeAnchor2(hinge[i - 1], a2);
        sep = fmax(sep, dCalcPointsDistance3(a1, a2));
    }
    printf("# hinged boxes after 3 s: |z - 0.5| <= %.3g m, speed <= %.3g, hinge gap %.3g m\n",
           worst_z, speed, sep);
    CHECK(worst_z < 1e-4);
    CHECK(speed < 1e-4);
    CHECK(sep < 1e-4);
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_feedback_of_static_pendulum_is_its_weight(void)
{
    dWorldID w = world_with_gravity();
    dBodyID bob = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, 3, 0.1);
    dBodySetMass(bob, &m);
    dBodySetPosition(bob, 0, 0, -1);
    dJointID hinge = dJointCreateHinge(w, 0);
    dJointAttach(hinge, bob, 0);
    dJointSetHingeAnchor(hinge, 0, 0, 0);
    dJointSetHingeAxis(hinge, 1, 0, 0);
    dJointFeedback fb;
    dJointSetFeedback(hinge, &fb);

    for (int i = 0; i < 10; i++) dWorldStep(w, 0.01);

    CHECK(dJointGetFeedback(hinge) == &fb);
    CHECK_NEAR(fb.f1[2], 3 * g, TOL(1e-6, 1e-2));   // the joint holds the bob up
    CHECK_NEAR(fb.f1[0], 0, TOL(1e-6, 1e-3));
    CHECK_NEAR(fb.t1[0], 0, TOL(1e-6, 1e-3));
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

static int test_motor_reaches_speed_in_one_step(void)
{
    dWorldID w = dWorldCreate();
    dBodyID wheel;
    dJointID hinge = wheel_on_hinge(w, &wheel);
    dJointSetHingeParam(hinge, dParamVel, 5);
    dJointSetHingeParam(hinge, dParamFMax, 1000);

    dWorldStep(w, 0.01);

    // (single precision: the default CFM 1e-5 lets the motor row give 0.03 %)
    CHECK_NEAR(dJointGetHingeAngleRate(hinge), 5, TOL(1e-6, 3e-3));
    CHECK_NEAR(dBodyGetAngularVel(wheel)[2], 5, TOL(1e-6, 3e-3));
    dWorldDestroy(w);
    return 0;
}

static int test_weak_motor_is_torque_limited(void)
{
    dWorldID w = dWorldCreate();
    dBodyID wheel;
    dJointID hinge = wheel_on_hinge(w, &wheel);
    dJointSetHingeParam(hinge, dParamVel, 5);
    dJointSetHingeParam(hinge, dParamFMax, 1);
    const dReal h = 0.01;

    dWorldStep(w, h);

    CHECK_NEAR(dJointGetHingeAngleRate(hinge), 1 * h / 0.25, TOL(1e-6, 1e-4));
    dWorldDestroy(w);
    return 0;
}

static int test_hinge_stop_holds_and_bounces(void)
{
    dWorldID w = dWorldCreate();
    dBodyID wheel;
    dJointID hinge = wheel_on_hinge(w, &wheel);
    dJointSetHingeParam(hinge, dParamHiStop, 0.5);
    dJointSetHingeParam(hinge, dParamBounce, 1);
    dJointSetHingeParam(hinge, dParamStopERP, 0);   // pure restitution, no position push
    dBodySetAngularVel(wheel, 0, 0, 2);
    dReal max_angle = -1, rate_after = 0;

    for (int i = 0; i < 100; i++) {
        dWorldStep(w, 0.01);
        dReal a = dJointGetHingeAngle(hinge);
        if (a > max_angle) max_angle = a;
        if (i == 99) rate_after = dJointGetHingeAngleRate(hinge);
    }

    CHECK(max_angle < 0.5 + 2 * 0.01 + 1e-9);   // at most one step past the stop
    CHECK_NEAR(rate_after, -2, 0.05);           // bounced back at the same speed
    dWorldDestroy(w);
    return 0;
}

static int test_soft_ball_joint_is_a_spring(void)
{
    // ERP and CFM as a spring: kp = ERP / (h CFM); hanging mass m sags m g / kp.
    dWorldID w = world_with_gravity();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, 2, 0.1);
    dBodySetMass(b, &m);
    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, b, 0);
    dJointSetBallAnchor(ball, 0, 0, 0);
    const dReal h = 0.01, kp = 2000, kd = 40;
    dJointSetBallParam(ball, dParamERP, h * kp / (h * kp + kd));
    dJointSetBallParam(ball, dParamCFM, 1 / (h * kp + kd));

    for (int i = 0; i < 2000; i++) dWorldStep(w, h);

    CHECK_NEAR(dBodyGetPosition(b)[2], -2 * g / kp, 0.01 * 2 * g / kp);
    dWorldDestroy(w);
    return 0;
}

static int test_idle_body_is_auto_disabled_and_woken_by_neighbour(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetAutoDisableFlag(w, 1);
    dWorldSetAutoDisableSteps(w, 5);
    dBodyID idle = dBodyCreate(w), mover = dBodyCreate(w);
    dBodySetAutoDisableFlag(mover, 0);
    dBodySetPosition(mover, 1, 0, 0);
    dBodySetLinearVel(idle, 0.001, 0, 0);   // below the 0.01 threshold

    for (int i = 0; i < 4; i++) dWorldStep(w, 0.01);
    CHECK(dBodyIsEnabled(idle));
    dWorldStep(w, 0.01);
    CHECK(!dBodyIsEnabled(idle));
    const dReal x = dBodyGetPosition(idle)[0];
    for (int i = 0; i < 10; i++) dWorldStep(w, 0.01);
    CHECK(dBodyGetPosition(idle)[0] == x);   // disabled: not stepped

    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, idle, mover);
    dJointSetBallAnchor(j, 0.5, 0, 0);
    dBodySetLinearVel(mover, 0, 1, 0);
    dWorldStep(w, 0.01);

    CHECK(dBodyIsEnabled(idle));
    CHECK(dBodyGetLinearVel(idle)[1] > 0.1);   // dragged along by the joint
    dWorldDestroy(w);
    return 0;
}

static int test_kinematic_body_moves_and_drags_a_joined_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID kin = dBodyCreate(w), dyn = dBodyCreate(w);
    dBodySetKinematic(kin);
    dBodySetLinearVel(kin, 1, 0, 0);
    dJointID j = dJointCreateBall(w, 0);   // joined at both centres
    dJointAttach(j, dyn, kin);
    dJointSetBallAnchor(j, 0, 0, 0);
    dBodyAddForce(kin, 100, 0, 0);   // ignored by a kinematic body

    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);

    CHECK_NEAR(dBodyGetPosition(kin)[0], 1, TOL(1e-9, 1e-5));
    CHECK_NEAR(dBodyGetLinearVel(kin)[0], 1, 1e-12);
    CHECK_NEAR(dBodyGetPosition(dyn)[0], 1, 1e-3);   // carried along
    dWorldDestroy(w);
    return 0;
}

// A chain of ball joints (LINKS of them: more rows than an island keeps dense) hanging from
// `anchor` (NULL: the world) at the origin, released 15 degrees from vertical; the joints
// attached parent first (`parent_first`) or child first. The links in body.
enum { HUNG_LINKS = 10 };
static void hung_chain(dBodyID anchor_body, dWorldID w, int parent_first, dBodyID *body)
{
    const dReal len = 0.1, angle = 75 * M_PI / 180, dx = dCos(angle), dz = -dSin(angle);
    dMass m;
    dMassSetCapsuleTotal(&m, 0.1, 1, 0.01, len);
    for (int i = 0; i < HUNG_LINKS; i++) {
        body[i] = dBodyCreate(w);
        dBodySetMass(body[i], &m);
        dBodySetPosition(body[i], (i + 0.5) * len * dx, 0, (i + 0.5) * len * dz);
        dJointID j = dJointCreateBall(w, 0);
        dBodyID parent = i ? body[i - 1] : anchor_body;
        if (parent_first) dJointAttach(j, parent, body[i]);
        else dJointAttach(j, body[i], parent);
        dJointSetBallAnchor(j, i * len * dx, 0, i * len * dz);
    }
}

// The big matrix has the same entries whichever side of a joint the static world or a
// kinematic body takes (rows with only a second body, runs of rows on the same bodies):
// chains hung from the world and from a kinematic body at rest, joints attached either way,
// swing alike.
static int test_chain_swings_alike_whichever_side_its_anchor_is(void)
{
    dBodyID body[4][HUNG_LINKS];
    dWorldID w[4];
    for (int k = 0; k < 4; k++) {
        w[k] = world_with_gravity();
        dBodyID anchor_body = NULL;
        if (k >= 2) {
            anchor_body = dBodyCreate(w[k]);
            dBodySetKinematic(anchor_body);
        }
        hung_chain(anchor_body, w[k], k & 1, body[k]);
    }
    for (int step = 0; step < 200; step++)
        for (int k = 0; k < 4; k++) dWorldStep(w[k], 0.01);
    const dReal *end = dBodyGetPosition(body[0][HUNG_LINKS - 1]);
    CHECK(end[2] < -0.3);   // still hanging, and swinging: off the start
    for (int k = 1; k < 4; k++)
        for (int i = 0; i < HUNG_LINKS; i++)
            for (int c = 0; c < 3; c++)
                CHECK_NEAR(dBodyGetPosition(body[k][i])[c], dBodyGetPosition(body[0][i])[c],
                           TOL(1e-6, 1e-3));
    for (int k = 0; k < 4; k++) dWorldDestroy(w[k]);
    return 0;
}

static int test_bad_step_size_is_reported_and_changes_nothing(void)
{
    test_capture_reports();
    dWorldID w = world_with_gravity();
    dBodyID b = dBodyCreate(w);

    CHECK(dWorldStep(w, 0) == 0);
    CHECK(dWorldStep(w, -0.01) == 0);
    CHECK(dWorldStep(w, NAN) == 0);

    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("dWorldStep: stepsize must be positive"));
    CHECK(dBodyGetPosition(b)[2] == 0 && dBodyGetLinearVel(b)[2] == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_long_chain_steps_without_overflowing_the_stack(void)
{
    enum { LINKS = 200 };
    dWorldID w = world_with_gravity();
    dBodyID prev = 0;
    for (int i = 0; i < LINKS; i++) {
        dBodyID b = dBodyCreate(w);
        dBodySetPosition(b, 0, 0, -0.1 * (i + 1));
        dJointID j = dJointCreateBall(w, 0);
        dJointAttach(j, b, prev);
        dJointSetBallAnchor(j, 0, 0, -0.1 * i);
        prev = b;
    }

    for (int i = 0; i < 3; i++) CHECK(dWorldStep(w, 0.01) == 1);

    CHECK(isfinite(dBodyGetPosition(prev)[2]));
    CHECK_NEAR(dBodyGetPosition(prev)[2], -0.1 * LINKS, TOL(1e-3, 1e-2));   // hanging still
    dWorldDestroy(w);
    return 0;
}

static int test_warm_step_allocates_nothing(void)
{
    dWorldID w = world_with_gravity();
    dBodyID prev = 0;
    for (int i = 0; i < 30; i++) {   // a chain with a motor and a stop
        dBodyID b = dBodyCreate(w);
        dBodySetPosition(b, 0.1 * (i + 1), 0, 0);
        dJointID j = dJointCreateHinge(w, 0);
        dJointAttach(j, b, prev);
        dJointSetHingeAnchor(j, 0.1 * i, 0, 0);
        dJointSetHingeAxis(j, 0, 1, 0);
        dJointSetHingeParam(j, dParamHiStop, 0.2);
        dJointSetHingeParam(j, dParamFMax, 1);
        prev = b;
    }
    for (int i = 0; i < 3; i++) dWorldStep(w, 0.01);   // the arena finds its size

    test_count_allocations();
    for (int i = 0; i < 5; i++) dWorldStep(w, 0.01);
    CHECK(test_allocations_counted() == 0);
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_free_fall_follows_semi_implicit_euler),
    TEST_CASE(test_force_at_offset_spins_the_body),
    TEST_CASE(test_torque_free_body_keeps_angular_momentum),
    TEST_CASE(test_finite_rotation_mode_integrates_spin_exactly),
    TEST_CASE(test_hinge_pendulum_has_small_angle_period),
    TEST_CASE(test_chain_joint_error_stays_small),
    TEST_CASE(test_hinged_boxes_rest_on_their_contacts),
    TEST_CASE(test_feedback_of_static_pendulum_is_its_weight),
    TEST_CASE(test_motor_reaches_speed_in_one_step),
    TEST_CASE(test_weak_motor_is_torque_limited),
    TEST_CASE(test_hinge_stop_holds_and_bounces),
    TEST_CASE(test_soft_ball_joint_is_a_spring),
    TEST_CASE(test_idle_body_is_auto_disabled_and_woken_by_neighbour),
    TEST_CASE(test_kinematic_body_moves_and_drags_a_joined_body),
    TEST_CASE(test_chain_swings_alike_whichever_side_its_anchor_is),
    TEST_CASE(test_bad_step_size_is_reported_and_changes_nothing),
    TEST_CASE(test_long_chain_steps_without_overflowing_the_stack),
    TEST_CASE(test_warm_step_allocates_nothing),
    TEST_END
};
