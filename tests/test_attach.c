// SPDX-License-Identifier: BSD-3-Clause
//
// test_attach.c -- what dJointAttach does to a joint's geometry (as ODE 0.16
// does): the anchor stays where the first body puts it, the axes stay fixed
// in the bodies, and the current pose becomes angle or position 0; and the
// signs of one-body joints attached in the second slot, dJointAttach(j, 0, b).
// Expected values are worked out by hand from the poses.

#include "test.h"

#define EPS TOL(1e-12, 1e-5)

typedef struct scene {
    dWorldID w;
    dBodyID a, b;
    dMatrix3 Ra, Rb;
} scene;

static void scene_make(scene *s)
{
    s->w = dWorldCreate();
    s->a = dBodyCreate(s->w);
    s->b = dBodyCreate(s->w);
    dBodySetPosition(s->a, -1, -2, -3);
    dBodySetPosition(s->b, 11, 22, 33);
    dRFromAxisAndAngle(s->Ra, 0.53, -0.71, 0.43, 0.47123);
    dRFromAxisAndAngle(s->Rb, 1.2, 0.87, -0.33, 0.47123);
    dBodySetRotation(s->a, s->Ra);
    dBodySetRotation(s->b, s->Rb);
}

// Column k of R: where body axis k points in the world.
static void column(const dMatrix3 R, int k, dVector3 out)
{
    for (int i = 0; i < 3; i++) out[i] = R[4 * i + k];
}

static int test_fresh_hinge_is_anchored_at_the_first_body_with_angle_zero(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateHinge(s.w, 0);

    dJointAttach(j, s.a, s.b);

    dVector3 p, p2, axis, x;
    dJointGetHingeAnchor(j, p);
    dJointGetHingeAnchor2(j, p2);
    dJointGetHingeAxis(j, axis);
    column(s.Ra, 0, x);   // the default axis, x of the first body
    CHECK_VEC(p, -1, -2, -3, EPS);
    CHECK_VEC(p2, -1, -2, -3, TOL(1e-12, 1e-4));
    CHECK_VEC(axis, x[0], x[1], x[2], EPS);
    CHECK_NEAR(dJointGetHingeAngle(j), 0, EPS);
    dWorldDestroy(s.w);
    return 0;
}

// After attaching, turning body 2 by 0.3 about the axis through the anchor
// reads as angle -0.3 (body 1 against body 2).
static int test_reattached_hinge_measures_from_the_pose_at_attach(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateHinge(s.w, 0);
    dJointAttach(j, s.a, s.b);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dBodySetPosition(s.b, 5, 0, 0);   // moved: the joint is broken now

    dJointAttach(j, s.a, s.b);

    dVector3 p2;
    dJointGetHingeAnchor2(j, p2);
    CHECK_VEC(p2, 0, 0, 0, TOL(1e-12, 1e-4));   // anchor 2 joins anchor 1 again
    CHECK_NEAR(dJointGetHingeAngle(j), 0, EPS);
    dMatrix3 turn, R;
    dRFromAxisAndAngle(turn, 0, 0, 1, 0.3);
    dMultiply0_333(R, turn, s.Rb);
    dBodySetRotation(s.b, R);
    CHECK_NEAR(dJointGetHingeAngle(j), -0.3, TOL(1e-9, 1e-4));
    dWorldDestroy(s.w);
    return 0;
}

static int test_fresh_slider_is_at_position_zero_and_measures_along_its_axis(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateSlider(s.w, 0);

    dJointAttach(j, s.a, s.b);

    CHECK_NEAR(dJointGetSliderPosition(j), 0, TOL(1e-12, 1e-4));
    dVector3 axis;
    dJointGetSliderAxis(j, axis);
    dBodySetPosition(s.a, -1 + 0.5 * axis[0], -2 + 0.5 * axis[1], -3 + 0.5 * axis[2]);
    CHECK_NEAR(dJointGetSliderPosition(j), 0.5, TOL(1e-12, 1e-4));
    dWorldDestroy(s.w);
    return 0;
}

static int test_fresh_ball_and_universal_join_at_the_first_body(void)
{
    scene s;
    scene_make(&s);
    dJointID ball = dJointCreateBall(s.w, 0), u = dJointCreateUniversal(s.w, 0);

    dJointAttach(ball, s.a, s.b);
    dJointAttach(u, s.a, s.b);

    dVector3 p, x, y, a1, a2;
    dJointGetBallAnchor2(ball, p);
    CHECK_VEC(p, -1, -2, -3, TOL(1e-12, 1e-4));
    dJointGetUniversalAnchor2(u, p);
    CHECK_VEC(p, -1, -2, -3, TOL(1e-12, 1e-4));
    column(s.Ra, 0, x);
    column(s.Rb, 1, y);
    dJointGetUniversalAxis1(u, a1);
    dJointGetUniversalAxis2(u, a2);
    CHECK_VEC(a1, x[0], x[1], x[2], EPS);   // axis 1 fixed in body 1, axis 2 in body 2
    CHECK_VEC(a2, y[0], y[1], y[2], EPS);
    CHECK_NEAR(dJointGetUniversalAngle1(u), 0, EPS);
    CHECK_NEAR(dJointGetUniversalAngle2(u), 0, EPS);
    dWorldDestroy(s.w);
    return 0;
}

static int test_fresh_hinge2_joins_its_anchors_at_angle_zero(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateHinge2(s.w, 0);

    dJointAttach(j, s.a, s.b);

    dVector3 p;
    dJointGetHinge2Anchor2(j, p);
    CHECK_VEC(p, -1, -2, -3, TOL(1e-12, 1e-4));
    CHECK_NEAR(dJointGetHinge2Angle1(j), 0, EPS);
    CHECK_NEAR(dJointGetHinge2Angle2(j), 0, EPS);
    dWorldDestroy(s.w);
    return 0;
}

// ---- attached in the second slot ------------------------------------------------

// dJointAttach(j, 0, b): the position is body 1 (the world) against body 2,
// so moving b along the axis makes it negative.
static int test_slider_in_the_second_slot_measures_the_world_against_the_body(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateSlider(s.w, 0);
    dJointAttach(j, 0, s.a);
    dVector3 x;
    column(s.Ra, 0, x);

    dBodySetPosition(s.a, -1 + 0.25 * x[0], -2 + 0.25 * x[1], -3 + 0.25 * x[2]);
    dBodySetLinearVel(s.a, 2 * x[0], 2 * x[1], 2 * x[2]);

    dVector3 axis;
    dJointGetSliderAxis(j, axis);
    CHECK_VEC(axis, x[0], x[1], x[2], EPS);   // the default axis, not reversed
    CHECK_NEAR(dJointGetSliderPosition(j), -0.25, TOL(1e-12, 1e-4));
    CHECK_NEAR(dJointGetSliderPositionRate(j), -2, TOL(1e-12, 1e-4));
    dWorldDestroy(s.w);
    return 0;
}

// ODE's unit test: a body pushed along +x by a slider in the second slot with
// stops [-1, 0.25] ends where a two-body slider's second body ends when its
// first body is held by a fixed joint; the stop holds it at x = 1 (position -1).
static int test_slider_stops_in_the_second_slot_act_as_on_a_second_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID one = dBodyCreate(w), held = dBodyCreate(w), pushed = dBodyCreate(w);
    dJointID single = dJointCreateSlider(w, 0), pair = dJointCreateSlider(w, 0);
    dJointID fixed = dJointCreateFixed(w, 0);
    dJointAttach(pair, held, pushed);
    dJointAttach(fixed, held, 0);
    dJointSetFixed(fixed);
    dJointAttach(single, 0, one);
    dJointID js[2] = { single, pair };
    for (int k = 0; k < 2; k++) {
        dJointSetSliderParam(js[k], dParamLoStop, -1);
        dJointSetSliderParam(js[k], dParamHiStop, 0.25);
    }

    for (int i = 0; i < 200; i++) {
        dBodyAddForce(one, 4, 0, 0);
        dBodyAddForce(pushed, 4, 0, 0);
        dWorldStep(w, 0.05);
    }

    const dReal *p1 = dBodyGetPosition(one), *p2 = dBodyGetPosition(pushed);
    CHECK_NEAR(p1[0], p2[0], 1e-3);
    CHECK_NEAR(p1[0], 1, 0.02);
    CHECK_NEAR(dJointGetSliderPosition(single), -1, 0.02);
    dWorldDestroy(w);
    return 0;
}

// ODE 0.16's hinge in the second slot: angle and rate are the world against
// the body (negated), and so is dJointAddHingeTorque, but the motor drives
// the body against the world: a motor at +1 turns the body at +1 about the
// axis, which reads as rate -1.
static int test_hinge_in_the_second_slot_signs_as_ode(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, 0, b);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dJointSetHingeParam(j, dParamVel, 1);
    dJointSetHingeParam(j, dParamFMax, 100);
    dJointSetHingeParam(j, dParamCFM, 0);   // a rigid motor: it reaches its speed

    dWorldStep(w, 0.01);

    CHECK_NEAR(dBodyGetAngularVel(b)[2], 1, TOL(1e-9, 1e-4));
    CHECK_NEAR(dJointGetHingeAngleRate(j), -1, TOL(1e-9, 1e-4));
    // (the infinitesimal rotation update is exact to O(h^3): 8e-8 here)
    CHECK_NEAR(dJointGetHingeAngle(j), -0.01, TOL(1e-6, 1e-4));
    dJointSetHingeParam(j, dParamFMax, 0);
    dBodySetAngularVel(b, 0, 0, 0);
    dJointAddHingeTorque(j, 2);
    CHECK_NEAR(dBodyGetTorque(b)[2], -2, EPS);
    dWorldDestroy(w);
    return 0;
}

// A one-body universal joint moved to the other slot keeps each axis fixed
// to what it was fixed to (as ODE 0.16, which keeps its axes by stored body):
// axis 1 (on the body) becomes axis 2, axis 2 (on the world) becomes axis 1.
static int test_universal_moved_to_the_other_slot_swaps_its_axes(void)
{
    scene s;
    scene_make(&s);
    dJointID j = dJointCreateUniversal(s.w, 0);
    dJointAttach(j, s.a, 0);
    dJointSetUniversalAxis1(j, 1, 0, 0);
    dJointSetUniversalAxis2(j, 0, 1, 0);

    dJointAttach(j, 0, s.a);

    dVector3 a1, a2;
    dJointGetUniversalAxis1(j, a1);
    dJointGetUniversalAxis2(j, a2);
    CHECK_VEC(a1, 0, 1, 0, EPS);
    CHECK_VEC(a2, 1, 0, 0, EPS);
    dWorldDestroy(s.w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_fresh_hinge_is_anchored_at_the_first_body_with_angle_zero),
    TEST_CASE(test_reattached_hinge_measures_from_the_pose_at_attach),
    TEST_CASE(test_fresh_slider_is_at_position_zero_and_measures_along_its_axis),
    TEST_CASE(test_fresh_ball_and_universal_join_at_the_first_body),
    TEST_CASE(test_fresh_hinge2_joins_its_anchors_at_angle_zero),
    TEST_CASE(test_slider_in_the_second_slot_measures_the_world_against_the_body),
    TEST_CASE(test_slider_stops_in_the_second_slot_act_as_on_a_second_body),
    TEST_CASE(test_hinge_in_the_second_slot_signs_as_ode),
    TEST_CASE(test_universal_moved_to_the_other_slot_swaps_its_axes),
    TEST_END
};
