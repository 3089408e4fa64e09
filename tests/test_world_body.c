// SPDX-License-Identifier: BSD-3-Clause
//
// test_world_body.c -- world and body API semantics (guide chapters 5 and 6)
// and their handling of bad input. Stepping physics is in test_step.c.

#include "test.h"

static int test_world_defaults_are_the_guides(void)
{
    dWorldID w = dWorldCreate();
    dVector3 g;

    dWorldGetGravity(w, g);

    CHECK(g[0] == 0 && g[1] == 0 && g[2] == 0);
    CHECK_NEAR(dWorldGetERP(w), 0.2, 1e-7);
    CHECK_NEAR(dWorldGetCFM(w), TOL(1e-10, 1e-5), TOL(1e-20, 1e-12));
    CHECK(dWorldGetQuickStepNumIterations(w) == 20);
    CHECK(dWorldGetContactMaxCorrectingVel(w) == dInfinity);
    CHECK(dWorldGetContactSurfaceLayer(w) == 0);
    CHECK(dWorldGetAutoDisableFlag(w) == 0);
    CHECK_NEAR(dWorldGetAutoDisableLinearThreshold(w), 0.01, 1e-7);
    CHECK_NEAR(dWorldGetAutoDisableAngularThreshold(w), 0.01, 1e-7);
    CHECK(dWorldGetAutoDisableSteps(w) == 10);
    CHECK(dWorldGetAutoDisableTime(w) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_world_setters_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dVector3 g;
    int data;

    dWorldSetGravity(w, 1, -2, -9.81);
    dWorldSetERP(w, 0.5);
    dWorldSetCFM(w, 1e-3);
    dWorldSetQuickStepNumIterations(w, 7);
    dWorldSetQuickStepW(w, 1.1);
    dWorldSetContactMaxCorrectingVel(w, 3);
    dWorldSetContactSurfaceLayer(w, 0.001);
    dWorldSetAutoDisableFlag(w, 1);
    dWorldSetAutoDisableSteps(w, 4);
    dWorldSetAutoDisableTime(w, 0.5);
    dWorldSetData(w, &data);

    dWorldGetGravity(w, g);
    CHECK(g[0] == 1 && g[1] == -2 && g[2] == (dReal)-9.81);
    CHECK_NEAR(dWorldGetERP(w), 0.5, 0);
    CHECK_NEAR(dWorldGetCFM(w), 1e-3, 1e-9);
    CHECK(dWorldGetQuickStepNumIterations(w) == 7);
    CHECK_NEAR(dWorldGetQuickStepW(w), 1.1, 1e-6);
    CHECK_NEAR(dWorldGetContactMaxCorrectingVel(w), 3, 0);
    CHECK_NEAR(dWorldGetContactSurfaceLayer(w), 0.001, 1e-9);
    CHECK(dWorldGetAutoDisableFlag(w) == 1);
    CHECK(dWorldGetAutoDisableSteps(w) == 4);
    CHECK_NEAR(dWorldGetAutoDisableTime(w), 0.5, 0);
    CHECK(dWorldGetData(w) == &data);
    dWorldDestroy(w);
    return 0;
}

static int test_impulse_to_force_divides_by_step(void)
{
    dWorldID w = dWorldCreate();
    dVector3 f;

    dWorldImpulseToForce(w, 0.01, 1, 2, -3, f);

    CHECK_NEAR(f[0], 100, 1e-4);
    CHECK_NEAR(f[1], 200, 1e-4);
    CHECK_NEAR(f[2], -300, 1e-4);
    dWorldDestroy(w);
    return 0;
}

static int test_new_body_is_at_origin_with_unit_mass(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;

    dBodyGetMass(b, &m);
    const dReal *p = dBodyGetPosition(b), *q = dBodyGetQuaternion(b), *R = dBodyGetRotation(b);

    CHECK(p[0] == 0 && p[1] == 0 && p[2] == 0);
    CHECK(q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0);
    CHECK(R[0] == 1 && R[5] == 1 && R[10] == 1 && R[1] == 0);
    CHECK(m.mass == 1 && m.I[0] == 1 && m.I[5] == 1 && m.I[10] == 1);
    CHECK(dBodyIsEnabled(b));
    CHECK(dBodyGetGravityMode(b) == 1);
    CHECK(dBodyGetWorld(b) == w);
    CHECK(dBodyGetNumJoints(b) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_rotation_and_quaternion_stay_consistent(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMatrix3 R;
    dQuaternion q;
    dRFromAxisAndAngle(R, 1, 1, 0, 0.7);

    dBodySetRotation(b, R);
    dBodyCopyQuaternion(b, q);
    dMatrix3 Rq;
    dRfromQ(Rq, q);

    for (int i = 0; i < 12; i++) CHECK_NEAR(Rq[i], R[i], TOL(1e-12, 1e-6));
    dQFromAxisAndAngle(q, 0, 0, 2, M_PI / 2);   // not normalised on purpose: length matters not
    q[0] *= 3; q[1] *= 3; q[2] *= 3; q[3] *= 3;
    dBodySetQuaternion(b, q);
    const dReal *Rb = dBodyGetRotation(b);
    CHECK_NEAR(Rb[4], 1, TOL(1e-12, 1e-6));   // x maps to y
    dWorldDestroy(w);
    return 0;
}

static int test_point_conversions_are_inverse(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);
    dBodySetRotation(b, R);
    dBodySetPosition(b, 1, 2, 3);
    dBodySetLinearVel(b, 1, 0, 0);
    dBodySetAngularVel(b, 0, 0, 2);
    dVector3 p, back, v, dir;

    dBodyGetRelPointPos(b, 1, 0, 0, p);   // body x is world y
    dBodyGetPosRelPoint(b, p[0], p[1], p[2], back);
    dBodyGetRelPointVel(b, 1, 0, 0, v);   // v + w x r = (1,0,0) + (0,0,2) x (0,1,0)
    dBodyVectorToWorld(b, 1, 0, 0, dir);

    CHECK_NEAR(p[0], 1, 1e-6); CHECK_NEAR(p[1], 3, 1e-6); CHECK_NEAR(p[2], 3, 1e-6);
    CHECK_NEAR(back[0], 1, 1e-6); CHECK_NEAR(back[1], 0, 1e-6); CHECK_NEAR(back[2], 0, 1e-6);
    CHECK_NEAR(v[0], -1, 1e-6); CHECK_NEAR(v[1], 0, 1e-6); CHECK_NEAR(v[2], 0, 1e-6);
    CHECK_NEAR(dir[1], 1, 1e-6);
    dBodyGetPointVel(b, p[0], p[1], p[2], back);
    CHECK_NEAR(back[0], -1, 1e-6);
    dBodyVectorFromWorld(b, 0, 1, 0, dir);
    CHECK_NEAR(dir[0], 1, 1e-6);
    dWorldDestroy(w);
    return 0;
}

static int test_force_at_offset_adds_torque(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, 1, 0, 0);

    dBodyAddForceAtPos(b, 0, 10, 0, 3, 0, 0);   // lever arm (2,0,0)
    dBodyAddRelForceAtRelPos(b, 0, 0, 1, 0, 1, 0);   // arm (0,1,0), force z: torque (1,0,0)

    const dReal *f = dBodyGetForce(b), *t = dBodyGetTorque(b);
    CHECK_NEAR(f[1], 10, 1e-9);
    CHECK_NEAR(f[2], 1, 1e-9);
    CHECK_NEAR(t[2], 20, 1e-9);
    CHECK_NEAR(t[0], 1, 1e-9);
    dBodySetForce(b, 0, 0, 0);
    dBodySetTorque(b, 1, 2, 3);
    CHECK(dBodyGetForce(b)[1] == 0 && dBodyGetTorque(b)[2] == 3);
    dWorldDestroy(w);
    return 0;
}

static int test_set_mass_requires_centre_at_origin(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m, got;
    dMassSetBox(&m, 1, 1, 1, 1);
    dMassTranslate(&m, 0.5, 0, 0);

    dBodySetMass(b, &m);

    CHECK(test_captured_contains("dBodySetMass"));
    CHECK(test_captured_contains("centre of mass"));
    dBodyGetMass(b, &got);
    CHECK(got.mass == 1 && got.I[0] == 1);   // unchanged
    dWorldDestroy(w);
    return 0;
}

static int test_destroyed_body_is_reported_not_touched(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dBodyDestroy(b);

    dBodySetPosition(b, 1, 2, 3);
    const dReal *p = dBodyGetPosition(b);

    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("dBodySetPosition: body is NULL or was destroyed"));
    CHECK(p == NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_non_finite_input_is_refused(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);

    dBodySetPosition(b, NAN, 0, 0);
    dBodyAddForce(b, INFINITY, 0, 0);
    dBodySetLinearVel(b, 0, NAN, 0);
    dWorldSetGravity(w, 0, 0, NAN);
    dWorldSetERP(w, 1.5);
    dWorldSetCFM(w, -1);

    CHECK(test_captured_count() == 6);
    CHECK(test_captured_contains("dBodySetPosition: position is not finite"));
    CHECK(test_captured_contains("dWorldSetERP: erp must be in 0..1"));
    CHECK(dBodyGetPosition(b)[0] == 0);
    CHECK(dBodyGetForce(b)[0] == 0);
    CHECK(dWorldGetERP(w) == (dReal)0.2);
    dWorldDestroy(w);
    return 0;
}

static int test_null_handles_are_reported(void)
{
    test_capture_reports();

    dWorldSetGravity(NULL, 0, 0, 0);
    CHECK(dBodyCreate(NULL) == NULL);
    CHECK(dBodyGetWorld(NULL) == NULL);
    CHECK(dWorldStep(NULL, 0.01) == 0);

    CHECK(test_captured_count() == 4);
    CHECK(test_captured_contains("dWorldStep: world is NULL"));
    return 0;
}

static int test_destroying_body_puts_its_joints_in_limbo(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, a, b);

    dBodyDestroy(a);

    CHECK(dJointGetBody(j, 0) == NULL);
    CHECK(dJointGetBody(j, 1) == b);
    CHECK(dBodyGetNumJoints(b) == 1);
    dBodyDestroy(b);
    CHECK(dJointGetBody(j, 0) == NULL && dJointGetBody(j, 1) == NULL);
    CHECK(dJointGetType(j) == dJointTypeBall);   // the joint itself survives
    dJointDestroy(j);
    dWorldDestroy(w);
    return 0;
}

static int test_world_destroy_deactivates_grouped_joints(void)
{
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID b = dBodyCreate(w);
    dJointID grouped = dJointCreateBall(w, g);
    dJointAttach(grouped, b, 0);

    dWorldDestroy(w);

    CHECK(dJointGetBody(grouped, 0) == NULL);   // still readable until the group is emptied
    dJointGroupEmpty(g);
    dJointGroupDestroy(g);
    return 0;
}

static int test_joint_queries_follow_attach(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w), c = dBodyCreate(w);
    dJointID hinge = dJointCreateHinge(w, 0), ball = dJointCreateBall(w, 0);
    dJointAttach(hinge, a, b);
    dJointAttach(ball, 0, c);

    CHECK(dAreConnected(a, b) && dAreConnected(b, a));
    CHECK(!dAreConnected(a, c));
    CHECK(!dAreConnectedExcluding(a, b, dJointTypeHinge));
    CHECK(dAreConnectedExcluding(a, b, dJointTypeContact));
    CHECK(dJointGetBody(ball, 0) == NULL && dJointGetBody(ball, 1) == c);
    CHECK(dJointGetNumBodies(ball) == 1);
    CHECK(dConnectingJoint(a, b) == hinge);
    CHECK(dBodyGetJoint(a, 0) == hinge);
    CHECK(dBodyGetNumJoints(c) == 1);
    dJointAttach(hinge, 0, 0);   // limbo
    CHECK(!dAreConnected(a, b));
    CHECK(dBodyGetNumJoints(a) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_attach_to_same_body_is_reported(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID a = dBodyCreate(w);
    dJointID j = dJointCreateBall(w, 0);

    dJointAttach(j, a, a);

    CHECK(test_captured_contains("dJointAttach: body1 and body2 are the same body"));
    CHECK(dBodyGetNumJoints(a) == 0);
    dWorldDestroy(w);
    return 0;
}

static int test_grouped_joint_is_destroyed_only_by_its_group(void)
{
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = dBodyCreate(w);
    dJointID j = dJointCreateBall(w, g);
    dJointAttach(j, a, 0);

    dJointDestroy(j);   // no effect (guide 7.1)
    CHECK(dBodyGetNumJoints(a) == 1);
    dJointGroupEmpty(g);

    CHECK(dBodyGetNumJoints(a) == 0);
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_emptying_a_large_group_detaches_everything(void)
{
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = dBodyCreate(w);

    for (int round = 0; round < 3; round++) {
        for (int i = 0; i < 5000; i++) dJointAttach(dJointCreateBall(w, g), a, 0);
        CHECK(dBodyGetNumJoints(a) == 5000);
        dJointGroupEmpty(g);
        CHECK(dBodyGetNumJoints(a) == 0);
    }
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_body_parameters_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetAutoDisableFlag(w, 1);
    dWorldSetAutoDisableSteps(w, 3);
    dBodyID b = dBodyCreate(w);
    dVector3 axis;

    CHECK(dBodyGetAutoDisableFlag(b) == 1);   // defaults copied at creation
    CHECK(dBodyGetAutoDisableSteps(b) == 3);
    dBodySetAutoDisableLinearThreshold(b, 0.5);
    dBodySetFiniteRotationMode(b, 1);
    dBodySetFiniteRotationAxis(b, 0, 0, 2);
    dBodySetGravityMode(b, 0);
    dBodySetAutoDisableSF1(b, 1);
    dBodySetAutoDisableStepsSF1(b, 7);

    dBodyGetFiniteRotationAxis(b, axis);
    CHECK_NEAR(dBodyGetAutoDisableLinearThreshold(b), 0.5, 0);
    CHECK(dBodyGetFiniteRotationMode(b) == 1);
    CHECK_NEAR(axis[2], 1, 1e-12);   // normalised
    CHECK(dBodyGetGravityMode(b) == 0);
    CHECK(dBodyGetAutoDisableSF1(b) == 1 && dBodyGetAutoDisableStepsSF1(b) == 7);
    dBodyDisable(b);
    CHECK(!dBodyIsEnabled(b));
    dBodyEnable(b);
    CHECK(dBodyIsEnabled(b));
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_world_defaults_are_the_guides),
    TEST_CASE(test_world_setters_round_trip),
    TEST_CASE(test_impulse_to_force_divides_by_step),
    TEST_CASE(test_new_body_is_at_origin_with_unit_mass),
    TEST_CASE(test_rotation_and_quaternion_stay_consistent),
    TEST_CASE(test_point_conversions_are_inverse),
    TEST_CASE(test_force_at_offset_adds_torque),
    TEST_CASE(test_set_mass_requires_centre_at_origin),
    TEST_CASE(test_destroyed_body_is_reported_not_touched),
    TEST_CASE(test_non_finite_input_is_refused),
    TEST_CASE(test_null_handles_are_reported),
    TEST_CASE(test_destroying_body_puts_its_joints_in_limbo),
    TEST_CASE(test_world_destroy_deactivates_grouped_joints),
    TEST_CASE(test_joint_queries_follow_attach),
    TEST_CASE(test_attach_to_same_body_is_reported),
    TEST_CASE(test_grouped_joint_is_destroyed_only_by_its_group),
    TEST_CASE(test_emptying_a_large_group_detaches_everything),
    TEST_CASE(test_body_parameters_round_trip),
    TEST_END
};
