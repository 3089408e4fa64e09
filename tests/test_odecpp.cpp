// SPDX-License-Identifier: BSD-3-Clause
//
// test_odecpp.cpp -- the C++ wrappers (odecpp.h, odecpp_collision.h). Each
// wrapper method must do exactly what the C call it names does: most tests build
// two identical scenes, drive one through the wrappers and the other through the
// C API, and compare the results exactly (same library, same inputs, so the same
// bits). Then whole simulations through the wrappers against the same ones in C,
// and the wrappers' destructors destroying their objects.
//
// Built three times (C++98, C++11, C++17) with -Werror, so the headers compile
// cleanly in each. With TEST_ODECPP_INSTANTIATE_ALL it is instead compiled (not
// linked) with every wrapper template explicitly instantiated, so every method
// compiles, including those of joints whose C functions are not defined yet.

#include <ode/ode.h>   // before test.h: the wrappers must not be in extern "C"

#include <math.h>
#include <string.h>

#ifdef TEST_ODECPP_INSTANTIATE_ALL

#define JOINT_BASES dJointDynamicIDContainer, dWorldDynamicIDContainer, dBodyDynamicIDContainer
template class dWorldTemplate<dWorldDynamicIDContainer>;
template class dWorldTemplate<dWorldSimpleIDContainer>;
template class dBodyTemplate<dBodyDynamicIDContainer, dWorldDynamicIDContainer>;
template class dBodyTemplate<dBodySimpleIDContainer, dWorldSimpleIDContainer>;
template class dJointGroupTemplate<dJointGroupDynamicIDContainer>;
template class dJointGroupTemplate<dJointGroupSimpleIDContainer>;
template class dJointTemplate<JOINT_BASES>;
template class dBallJointTemplate<JOINT_BASES>;
template class dHingeJointTemplate<JOINT_BASES>;
template class dSliderJointTemplate<JOINT_BASES>;
template class dUniversalJointTemplate<JOINT_BASES>;
template class dHinge2JointTemplate<JOINT_BASES>;
template class dPRJointTemplate<JOINT_BASES>;
template class dPUJointTemplate<JOINT_BASES>;
template class dPistonJointTemplate<JOINT_BASES>;
template class dFixedJointTemplate<JOINT_BASES>;
template class dContactJointTemplate<JOINT_BASES>;
template class dNullJointTemplate<JOINT_BASES>;
template class dAMotorJointTemplate<JOINT_BASES>;
template class dLMotorJointTemplate<JOINT_BASES>;
template class dHingeJointTemplate<dJointSimpleIDContainer, dWorldSimpleIDContainer,
                                   dBodySimpleIDContainer>;

#else

extern "C" {
#include "test.h"
}

#if __cplusplus >= 201103L
#include <type_traits>
// Not copyable, but convertible to the C IDs (checked at compile time).
static_assert(!std::is_copy_constructible<dWorld>::value, "dWorld is copyable");
static_assert(!std::is_copy_assignable<dWorld>::value, "dWorld is assignable");
static_assert(!std::is_copy_constructible<dBody>::value, "dBody is copyable");
static_assert(!std::is_copy_constructible<dJointGroup>::value, "dJointGroup is copyable");
static_assert(!std::is_copy_constructible<dHingeJoint>::value, "dHingeJoint is copyable");
static_assert(!std::is_copy_assignable<dHingeJoint>::value, "dHingeJoint is assignable");
static_assert(!std::is_copy_constructible<dGeom>::value, "dGeom is copyable");
static_assert(!std::is_copy_constructible<dSphere>::value, "dSphere is copyable");
static_assert(!std::is_default_constructible<dJoint>::value, "dJoint is constructible");
static_assert(!std::is_default_constructible<dSpace>::value, "dSpace is constructible");
static_assert(std::is_convertible<dWorld &, dWorldID>::value, "no operator dWorldID");
static_assert(std::is_convertible<dBody &, dBodyID>::value, "no operator dBodyID");
static_assert(std::is_convertible<dJointGroup &, dJointGroupID>::value, "no dJointGroupID");
static_assert(std::is_convertible<dBallJoint &, dJointID>::value, "no operator dJointID");
static_assert(std::is_convertible<dBox &, dGeomID>::value, "no operator dGeomID");
static_assert(std::is_convertible<dHashSpace &, dSpaceID>::value, "no operator dSpaceID");
static_assert(std::has_virtual_destructor<dWorld>::value, "dWorld: not the dynamic base");
static_assert(!std::has_virtual_destructor<dGeom>::value, "dGeom: ODE's is not virtual");
#endif

// Exact equality of n numbers (copies and identical computations).
static int same(const dReal *a, const dReal *b, int n)
{
    for (int i = 0; i < n; i++)
        if (!(a[i] == b[i])) return 0;
    return 1;
}

// The whole dynamic state of two bodies is bit-for-bit the same.
static int same_body(dBodyID a, dBodyID b)
{
    return same(dBodyGetPosition(a), dBodyGetPosition(b), 3) &&
           same(dBodyGetRotation(a), dBodyGetRotation(b), 12) &&
           same(dBodyGetQuaternion(a), dBodyGetQuaternion(b), 4) &&
           same(dBodyGetLinearVel(a), dBodyGetLinearVel(b), 3) &&
           same(dBodyGetAngularVel(a), dBodyGetAngularVel(b), 3) &&
           same(dBodyGetForce(a), dBodyGetForce(b), 3) &&
           same(dBodyGetTorque(a), dBodyGetTorque(b), 3);
}

// A body posed off the identity, moving and spinning, with a box mass.
static void pose_body(dBodyID b, dReal x, dReal spin)
{
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 2, 3, 0.4 + spin);
    dBodySetPosition(b, x, 0.5, 1.5);
    dBodySetRotation(b, R);
    dBodySetLinearVel(b, 0.1, -0.2, 0.3);
    dBodySetAngularVel(b, spin, 0.7, -0.4);
    dMass m;
    dMassSetBox(&m, 2, 0.5, 1, 1.5);
    dBodySetMass(b, &m);
}

// ---- worlds ---------------------------------------------------------------

static int test_world_methods_set_and_read_the_c_world(void)
{
    dWorld world;
    dWorldID c = dWorldCreate();

    world.setGravity(0, -2, -9.5);
    dWorldSetGravity(c, 0, -2, -9.5);
    dVector3 g1, g2;
    world.getGravity(g1);
    dWorldGetGravity(c, g2);
    CHECK(same(g1, g2, 3));
    const dVector3 g3 = { 1, 2, 3, 0 };
    world.setGravity(g3);
    dWorldGetGravity(world, g1);   // operator dWorldID
    CHECK(same(g1, g3, 3));
    CHECK(world.id() == (dWorldID)world);

    world.setERP(0.3);
    world.setCFM(1e-4);
    world.setQuickStepNumIterations(33);
    world.setQuickStepW(1.2);
    world.setAutoDisableLinearThreshold(0.02);
    world.setAutoDisableAngularThreshold(0.03);
    world.setAutoDisableSteps(7);
    world.setAutoDisableTime(0.5);
    world.setAutoDisableFlag(1);
    world.setLinearDampingThreshold(0.04);
    world.setAngularDampingThreshold(0.05);
    world.setDamping(0.06, 0.07);
    world.setMaxAngularSpeed(50);
    world.setContactSurfaceLayer(0.001);
    dWorldSetERP(c, 0.3);
    dWorldSetCFM(c, 1e-4);
    dWorldSetQuickStepNumIterations(c, 33);
    dWorldSetQuickStepW(c, 1.2);
    dWorldSetAutoDisableLinearThreshold(c, 0.02);
    dWorldSetAutoDisableAngularThreshold(c, 0.03);
    dWorldSetAutoDisableSteps(c, 7);
    dWorldSetAutoDisableTime(c, 0.5);
    dWorldSetAutoDisableFlag(c, 1);
    dWorldSetLinearDampingThreshold(c, 0.04);
    dWorldSetAngularDampingThreshold(c, 0.05);
    dWorldSetDamping(c, 0.06, 0.07);
    dWorldSetMaxAngularSpeed(c, 50);
    dWorldSetContactSurfaceLayer(c, 0.001);

    CHECK(world.getERP() == dWorldGetERP(c));
    CHECK(world.getCFM() == dWorldGetCFM(c));
    CHECK(world.getQuickStepNumIterations() == 33);
    CHECK(world.getQuickStepW() == dWorldGetQuickStepW(c));
    CHECK(world.getAutoDisableLinearThreshold() == dWorldGetAutoDisableLinearThreshold(c));
    CHECK(world.getAutoDisableAngularThreshold() == dWorldGetAutoDisableAngularThreshold(c));
    CHECK(world.getAutoDisableSteps() == 7);
    CHECK(world.getAutoDisableTime() == dWorldGetAutoDisableTime(c));
    CHECK(world.getAutoDisableFlag() == 1);
    CHECK(world.getLinearDampingThreshold() == dWorldGetLinearDampingThreshold(c));
    CHECK(world.getAngularDampingThreshold() == dWorldGetAngularDampingThreshold(c));
    CHECK(world.getLinearDamping() == dWorldGetLinearDamping(c));
    CHECK(world.getAngularDamping() == dWorldGetAngularDamping(c));
    CHECK(world.getMaxAngularSpeed() == dWorldGetMaxAngularSpeed(c));
    CHECK(world.getContactSurfaceLayer() == dWorldGetContactSurfaceLayer(c));
    world.setLinearDamping(0.08);
    world.setAngularDamping(0.09);
    CHECK(dWorldGetLinearDamping(world) == (dReal)0.08);
    CHECK(dWorldGetAngularDamping(world) == (dReal)0.09);

    dVector3 f1, f2;
    world.impulseToForce(0.01, 1, 2, 3, f1);
    dWorldImpulseToForce(c, 0.01, 1, 2, 3, f2);
    CHECK(same(f1, f2, 3));
    dWorldDestroy(c);
    return 0;
}

// A program may pick the non-virtual ID containers: the same methods work.
static int test_world_template_over_the_simple_container(void)
{
    typedef dWorldTemplate<dWorldSimpleIDContainer> SimpleWorld;
    typedef dBodyTemplate<dBodySimpleIDContainer, dWorldSimpleIDContainer> SimpleBody;
    SimpleWorld world;
    SimpleBody body(world);

    world.setGravity(0, 0, -1);
    body.setPosition(1, 2, 3);
    world.step(0.5);

    CHECK(sizeof(SimpleWorld) == sizeof(dWorldID));   // no vtable: only the ID
    CHECK(dBodyGetWorld(body) == world.id());
    CHECK_VEC(body.getPosition(), 1, 2, 3 - 0.25, 0);   // v = -0.5, then x += 0.5 v
    return 0;
}

// ---- bodies ---------------------------------------------------------------

static int test_body_state_setters_match_c(void)
{
    dWorld world;
    dBody body(world);
    dBodyID c = dBodyCreate(world);
    dMatrix3 R;
    dRFromEulerAngles(R, 0.1, 0.2, 0.3);
    dQuaternion q;
    dQFromAxisAndAngle(q, 0, 1, 1, 0.5);
    const dVector3 p = { 1, 2, 3, 0 }, v = { -1, 0.5, 2, 0 }, w = { 0.3, 0.2, 0.1, 0 };
    dMass m;
    dMassSetCapsule(&m, 3, 2, 0.25, 1);
    int data = 0;

    body.setPosition(4, 5, 6);
    dBodySetPosition(c, 4, 5, 6);
    CHECK(same_body(body, c));
    body.setPosition(p);
    body.setRotation(R);
    body.setLinearVel(v);
    body.setAngularVel(w);
    dBodySetPosition(c, 1, 2, 3);
    dBodySetRotation(c, R);
    dBodySetLinearVel(c, -1, 0.5, 2);
    dBodySetAngularVel(c, 0.3, 0.2, 0.1);
    CHECK(same_body(body, c));
    body.setQuaternion(q);
    body.setLinearVel(7, 8, 9);
    body.setAngularVel(-7, -8, -9);
    dBodySetQuaternion(c, q);
    dBodySetLinearVel(c, 7, 8, 9);
    dBodySetAngularVel(c, -7, -8, -9);
    CHECK(same_body(body, c));
    CHECK(body.getPosition() == dBodyGetPosition(body));   // the body's own arrays
    CHECK(body.getRotation() == dBodyGetRotation(body));
    CHECK(body.getQuaternion() == dBodyGetQuaternion(body));
    CHECK(body.getLinearVel() == dBodyGetLinearVel(body));
    CHECK(body.getAngularVel() == dBodyGetAngularVel(body));

    body.setMass(&m);
    dMass got = body.getMass();
    CHECK(got.mass == m.mass && same(got.c, m.c, 3) && same(got.I, m.I, 12));
    dMassAdjust(&m, 5);
    body.setMass(m);
    dBodyGetMass(body, &got);
    CHECK(got.mass == 5);

    body.setData(&data);
    CHECK(body.getData() == &data && dBodyGetData(body) == &data);
    CHECK(body.id() == (dBodyID)body && dBodyGetWorld(body) == world.id());
    dBodyDestroy(c);
    return 0;
}

static int test_body_forces_match_c(void)
{
    dWorld world;
    dBody body(world);
    dBodyID c = dBodyCreate(world);
    pose_body(body, 0, 0.2);
    pose_body(c, 0, 0.2);
    const dVector3 f = { 1, -2, 3, 0 }, p = { 0.5, 0.25, -1, 0 };

    body.addForce(1, 2, 3);
    body.addForce(f);
    body.addTorque(4, 5, 6);
    body.addTorque(f);
    body.addRelForce(0.1, 0.2, 0.3);
    body.addRelForce(f);
    body.addRelTorque(0.4, 0.5, 0.6);
    body.addRelTorque(f);
    body.addForceAtPos(1, 0, 0, 0, 1, 0);
    body.addForceAtPos(f, p);
    body.addForceAtRelPos(0, 1, 0, 0, 0, 1);
    body.addForceAtRelPos(f, p);
    body.addRelForceAtPos(0, 0, 1, 1, 0, 0);
    body.addRelForceAtPos(f, p);
    body.addRelForceAtRelPos(1, 1, 0, 0, 1, 1);
    body.addRelForceAtRelPos(f, p);
    dBodyAddForce(c, 1, 2, 3);
    dBodyAddForce(c, 1, -2, 3);
    dBodyAddTorque(c, 4, 5, 6);
    dBodyAddTorque(c, 1, -2, 3);
    dBodyAddRelForce(c, 0.1, 0.2, 0.3);
    dBodyAddRelForce(c, 1, -2, 3);
    dBodyAddRelTorque(c, 0.4, 0.5, 0.6);
    dBodyAddRelTorque(c, 1, -2, 3);
    dBodyAddForceAtPos(c, 1, 0, 0, 0, 1, 0);
    dBodyAddForceAtPos(c, 1, -2, 3, 0.5, 0.25, -1);
    dBodyAddForceAtRelPos(c, 0, 1, 0, 0, 0, 1);
    dBodyAddForceAtRelPos(c, 1, -2, 3, 0.5, 0.25, -1);
    dBodyAddRelForceAtPos(c, 0, 0, 1, 1, 0, 0);
    dBodyAddRelForceAtPos(c, 1, -2, 3, 0.5, 0.25, -1);
    dBodyAddRelForceAtRelPos(c, 1, 1, 0, 0, 1, 1);
    dBodyAddRelForceAtRelPos(c, 1, -2, 3, 0.5, 0.25, -1);

    CHECK(same_body(body, c));
    CHECK(body.getForce() == dBodyGetForce(body) && body.getTorque() == dBodyGetTorque(body));
    body.setForce(1, 2, 3);
    body.setTorque(f);
    CHECK_VEC(dBodyGetForce(body), 1, 2, 3, 0);
    CHECK_VEC(dBodyGetTorque(body), 1, -2, 3, 0);
    body.setForce(f);
    body.setTorque(4, 5, 6);
    CHECK_VEC(dBodyGetForce(body), 1, -2, 3, 0);
    CHECK_VEC(dBodyGetTorque(body), 4, 5, 6, 0);
    dBodyDestroy(c);
    return 0;
}

static int test_body_point_conversions_match_c(void)
{
    dWorld world;
    dBody body(world);
    pose_body(body, 1, 0.3);
    const dVector3 p = { 0.5, -0.25, 2, 0 };
    dVector3 a, b, r;

    body.getRelPointPos(0.5, -0.25, 2, a);
    body.getRelPointPos(p, b);
    dBodyGetRelPointPos(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    body.getRelPointVel(0.5, -0.25, 2, a);
    body.getRelPointVel(p, b);
    dBodyGetRelPointVel(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    body.getPointVel(0.5, -0.25, 2, a);
    body.getPointVel(p, b);
    dBodyGetPointVel(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    body.getPosRelPoint(0.5, -0.25, 2, a);
    body.getPosRelPoint(p, b);
    dBodyGetPosRelPoint(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    body.vectorToWorld(0.5, -0.25, 2, a);
    body.vectorToWorld(p, b);
    dBodyVectorToWorld(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    body.vectorFromWorld(0.5, -0.25, 2, a);
    body.vectorFromWorld(p, b);
    dBodyVectorFromWorld(body, 0.5, -0.25, 2, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    return 0;
}

static int test_body_modes_match_c(void)
{
    dWorld world;
    dBody body(world);
    dBodyID c = dBodyCreate(world);
    const dVector3 axis = { 0, 0.6, 0.8, 0 };
    dVector3 a, r;

    body.setFiniteRotationMode(true);
    body.setFiniteRotationAxis(1, 0, 0);
    body.getFiniteRotationAxis(a);
    CHECK(body.getFiniteRotationMode() && dBodyGetFiniteRotationMode(body) == 1);
    CHECK_VEC(a, 1, 0, 0, 0);
    body.setFiniteRotationAxis(axis);
    dBodySetFiniteRotationAxis(c, 0, 0.6, 0.8);
    body.getFiniteRotationAxis(a);
    dBodyGetFiniteRotationAxis(c, r);
    CHECK(same(a, r, 3));

    body.setGravityMode(false);
    CHECK(!body.getGravityMode() && dBodyGetGravityMode(body) == 0);
    body.setKinematic();
    CHECK(body.isKinematic() && dBodyIsKinematic(body));
    body.setDynamic();
    CHECK(!body.isKinematic() && !dBodyIsKinematic(body));
    body.disable();
    CHECK(!body.isEnabled() && !dBodyIsEnabled(body));
    body.enable();
    CHECK(body.isEnabled() && dBodyIsEnabled(body));

    body.setAutoDisableLinearThreshold(0.1);
    body.setAutoDisableAngularThreshold(0.2);
    body.setAutoDisableSteps(12);
    body.setAutoDisableTime(1.5);
    body.setAutoDisableFlag(true);
    dBodySetAutoDisableLinearThreshold(c, 0.1);
    dBodySetAutoDisableAngularThreshold(c, 0.2);
    dBodySetAutoDisableTime(c, 1.5);
    CHECK(body.getAutoDisableLinearThreshold() == dBodyGetAutoDisableLinearThreshold(c));
    CHECK(body.getAutoDisableAngularThreshold() == dBodyGetAutoDisableAngularThreshold(c));
    CHECK(body.getAutoDisableSteps() == 12 && dBodyGetAutoDisableSteps(body) == 12);
    CHECK(body.getAutoDisableTime() == dBodyGetAutoDisableTime(c));
    CHECK(body.getAutoDisableFlag() && dBodyGetAutoDisableFlag(body) == 1);

    body.setDamping(0.1, 0.2);
    dBodySetDamping(c, 0.1, 0.2);
    CHECK(body.getLinearDamping() == dBodyGetLinearDamping(c));
    CHECK(body.getAngularDamping() == dBodyGetAngularDamping(c));
    body.setLinearDamping(0.3);
    body.setAngularDamping(0.4);
    body.setLinearDampingThreshold(0.5);
    body.setAngularDampingThreshold(0.6);
    dBodySetLinearDamping(c, 0.3);
    dBodySetAngularDamping(c, 0.4);
    dBodySetLinearDampingThreshold(c, 0.5);
    dBodySetAngularDampingThreshold(c, 0.6);
    CHECK(body.getLinearDamping() == dBodyGetLinearDamping(c));
    CHECK(body.getAngularDamping() == dBodyGetAngularDamping(c));
    CHECK(body.getLinearDampingThreshold() == dBodyGetLinearDampingThreshold(c));
    CHECK(body.getAngularDampingThreshold() == dBodyGetAngularDampingThreshold(c));
    world.setDamping(0.01, 0.02);
    body.setDampingDefaults();
    CHECK(dBodyGetLinearDamping(body) == world.getLinearDamping());
    CHECK(dBodyGetAngularDamping(body) == world.getAngularDamping());

    body.setMaxAngularSpeed(12);
    CHECK(body.getMaxAngularSpeed() == 12 && dBodyGetMaxAngularSpeed(body) == 12);
    body.setGyroscopicMode(false);
    CHECK(!body.getGyroscopicMode() && dBodyGetGyroscopicMode(body) == 0);
    body.setGyroscopicMode(true);
    CHECK(body.getGyroscopicMode() && dBodyGetGyroscopicMode(body) == 1);
    dBodyDestroy(c);
    return 0;
}

static int test_body_joints_and_connection_match_c(void)
{
    dWorld world;
    dBody b1(world), b2(world), b3;
    dBallJoint ball(world);

    ball.attach(b1, b2);

    CHECK(b1.getNumJoints() == 1 && dBodyGetNumJoints(b1) == 1);
    CHECK(b1.getJoint(0) == ball.id() && b2.getJoint(0) == dBodyGetJoint(b2, 0));
    CHECK(b1.isConnectedTo(b2) && b2.isConnectedTo(b1));
    CHECK(b3.id() == 0);   // default-constructed: no body until create()
    b3.create(world);
    CHECK(b3.id() != 0 && dBodyGetWorld(b3) == world.id());
    CHECK(!b3.isConnectedTo(b1));
    return 0;
}

// ---- joint groups and joints ---------------------------------------------

static int test_joint_base_methods_match_c(void)
{
    dWorld world;
    dBody b1(world), b2(world);
    dJointGroup group;
    dHingeJoint hinge(world, group);
    int data = 0;
    dJointFeedback fb;

    hinge.attach(b1.id(), b2.id());
    hinge.setData(&data);
    hinge.setFeedback(&fb);

    CHECK(hinge.getNumBodies() == 2 && dJointGetNumBodies(hinge) == 2);
    CHECK(hinge.getBody(0) == b1.id() && hinge.getBody(1) == dJointGetBody(hinge, 1));
    CHECK(hinge.getData() == &data && dJointGetData(hinge) == &data);
    CHECK(hinge.getFeedback() == &fb && dJointGetFeedback(hinge) == &fb);
    CHECK(hinge.getType() == dJointTypeHinge && dJointGetType(hinge) == dJointTypeHinge);
    hinge.disable();
    CHECK(!hinge.isEnabled() && !dJointIsEnabled(hinge));
    hinge.enable();
    CHECK(hinge.isEnabled() && dJointIsEnabled(hinge));
    hinge.attach(b2, b1);   // the dBody overload
    CHECK(dJointGetBody(hinge, 0) == b2.id());
    CHECK(group.id() == (dJointGroupID)group);
    return 0;   // the hinge's wrapper leaves it to the group, which destroys it
}

// setParam/getParam are virtual: a dJoint& reaches the joint type's C call,
// and the types without parameters ignore them as ODE's wrappers do.
static int test_params_dispatch_through_a_joint_reference(void)
{
    dWorld world;
    dHingeJoint hinge(world);
    dSliderJoint slider(world);
    dNullJoint null_joint(world);
    dJoint *joints[3] = { &hinge, &slider, &null_joint };

    for (int i = 0; i < 3; i++) joints[i]->setParam(dParamLoStop, -0.5 - i);

    CHECK(dJointGetHingeParam(hinge, dParamLoStop) == (dReal)-0.5);
    CHECK(dJointGetSliderParam(slider, dParamLoStop) == (dReal)-1.5);
    CHECK(joints[0]->getParam(dParamLoStop) == (dReal)-0.5);
    CHECK(joints[1]->getParam(dParamLoStop) == (dReal)-1.5);
    CHECK(joints[2]->getParam(dParamLoStop) == 0);
    CHECK(null_joint.getType() == dJointTypeNull);
    return 0;
}

// Two worlds, each with two posed bodies; `jw` (wrapped) and `jc` (C) are the
// same kind of joint attached to them.
struct twin {
    dWorldID w[2];
    dBodyID b[2][2];

    twin()
    {
        for (int k = 0; k < 2; k++) {
            w[k] = dWorldCreate();
            for (int i = 0; i < 2; i++) {
                b[k][i] = dBodyCreate(w[k]);
                pose_body(b[k][i], i ? 1.0 : -0.5, i ? 0.9 : -0.3);
            }
        }
    }
    ~twin()
    {
        dWorldDestroy(w[0]);
        dWorldDestroy(w[1]);
    }
    // Both pairs of bodies are in the same state.
    bool same_bodies() const
    {
        return same_body(b[0][0], b[1][0]) && same_body(b[0][1], b[1][1]);
    }
};

static int test_ball_joint_matches_c(void)
{
    twin t;
    dBallJoint ball(t.w[0]);
    dJointID c = dJointCreateBall(t.w[1], 0);
    ball.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 anchor = { 0.25, 0.5, 1, 0 };
    dVector3 a, r;

    ball.setAnchor(0.1, 0.2, 0.3);
    dJointSetBallAnchor(c, 0.1, 0.2, 0.3);
    ball.getAnchor(a);
    dJointGetBallAnchor(c, r);
    CHECK(same(a, r, 3));
    ball.setAnchor(anchor);
    dJointSetBallAnchor(c, 0.25, 0.5, 1);
    ball.getAnchor(a);
    dJointGetBallAnchor(c, r);
    CHECK(same(a, r, 3));
    dBodySetPosition(t.b[0][1], 2, 0, 0);   // pull the bodies apart: anchor 2 moves
    dBodySetPosition(t.b[1][1], 2, 0, 0);
    ball.getAnchor2(a);
    dJointGetBallAnchor2(c, r);
    CHECK(same(a, r, 3));
    ball.setParam(dParamCFM, 0.01);
    dJointSetBallParam(c, dParamCFM, 0.01);
    CHECK(ball.getParam(dParamCFM) == dJointGetBallParam(c, dParamCFM));
    CHECK(ball.getType() == dJointTypeBall);
    return 0;
}

static int test_hinge_joint_matches_c(void)
{
    twin t;
    dHingeJoint hinge(t.w[0]);
    dJointID c = dJointCreateHinge(t.w[1], 0);
    hinge.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 anchor = { 0.25, 0.5, 1, 0 }, axis = { 0, 0.6, 0.8, 0 };
    dVector3 a, r;

    hinge.setAnchor(0.1, 0.2, 0.3);
    hinge.setAxis(1, 1, 0);
    dJointSetHingeAnchor(c, 0.1, 0.2, 0.3);
    dJointSetHingeAxis(c, 1, 1, 0);
    hinge.getAxis(a);
    dJointGetHingeAxis(c, r);
    CHECK(same(a, r, 3));
    hinge.setAnchor(anchor);
    hinge.setAxis(axis);
    dJointSetHingeAnchor(c, 0.25, 0.5, 1);
    dJointSetHingeAxis(c, 0, 0.6, 0.8);
    hinge.getAnchor(a);
    dJointGetHingeAnchor(c, r);
    CHECK(same(a, r, 3));
    hinge.getAxis(a);
    dJointGetHingeAxis(c, r);
    CHECK(same(a, r, 3));
    dBodySetPosition(t.b[0][1], 2, 0, 0);
    dBodySetPosition(t.b[1][1], 2, 0, 0);
    dBodySetAngularVel(t.b[0][1], 0, 3, 4);   // turning about the axis
    dBodySetAngularVel(t.b[1][1], 0, 3, 4);
    hinge.getAnchor2(a);
    dJointGetHingeAnchor2(c, r);
    CHECK(same(a, r, 3));
    CHECK(hinge.getAngle() == dJointGetHingeAngle(c));
    CHECK(hinge.getAngleRate() == dJointGetHingeAngleRate(c) && hinge.getAngleRate() != 0);
    hinge.setParam(dParamHiStop, 0.5);
    dJointSetHingeParam(c, dParamHiStop, 0.5);
    CHECK(hinge.getParam(dParamHiStop) == dJointGetHingeParam(c, dParamHiStop));
    hinge.addTorque(2.5);
    dJointAddHingeTorque(c, 2.5);
    CHECK(t.same_bodies());
    return 0;
}

static int test_slider_joint_matches_c(void)
{
    twin t;
    dSliderJoint slider(t.w[0]);
    dJointID c = dJointCreateSlider(t.w[1], 0);
    slider.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 axis = { 0.6, 0, 0.8, 0 };
    dVector3 a, r;

    slider.setAxis(0, 1, 0);
    dJointSetSliderAxis(c, 0, 1, 0);
    slider.getAxis(a);
    dJointGetSliderAxis(c, r);
    CHECK(same(a, r, 3));
    slider.setAxis(axis);
    dJointSetSliderAxis(c, 0.6, 0, 0.8);
    slider.getAxis(a);
    dJointGetSliderAxis(c, r);
    CHECK(same(a, r, 3));
    dBodySetPosition(t.b[0][1], 2, 0, 1);
    dBodySetPosition(t.b[1][1], 2, 0, 1);
    CHECK(slider.getPosition() == dJointGetSliderPosition(c) && slider.getPosition() != 0);
    CHECK(slider.getPositionRate() == dJointGetSliderPositionRate(c));
    slider.setParam(dParamFMax, 3);
    dJointSetSliderParam(c, dParamFMax, 3);
    CHECK(slider.getParam(dParamFMax) == dJointGetSliderParam(c, dParamFMax));
    slider.addForce(1.5);
    dJointAddSliderForce(c, 1.5);
    CHECK(t.same_bodies());
    return 0;
}

static int test_universal_joint_matches_c(void)
{
    twin t;
    dUniversalJoint uj(t.w[0]);
    dJointID c = dJointCreateUniversal(t.w[1], 0);
    uj.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 anchor = { 0.5, 0, 0.5, 0 }, x = { 1, 0, 0, 0 }, y = { 0, 1, 0, 0 };
    dVector3 a, r;
    dReal a1, a2;

    uj.setAnchor(0.1, 0.2, 0.3);
    uj.setAxis1(0, 0, 1);
    uj.setAxis2(0, 1, 0);
    dJointSetUniversalAnchor(c, 0.1, 0.2, 0.3);
    dJointSetUniversalAxis1(c, 0, 0, 1);
    dJointSetUniversalAxis2(c, 0, 1, 0);
    uj.getAxis1(a);
    dJointGetUniversalAxis1(c, r);
    CHECK(same(a, r, 3));
    uj.setAnchor(anchor);
    uj.setAxis1(x);
    uj.setAxis2(y);
    dJointSetUniversalAnchor(c, 0.5, 0, 0.5);
    dJointSetUniversalAxis1(c, 1, 0, 0);
    dJointSetUniversalAxis2(c, 0, 1, 0);
    uj.getAnchor(a);
    dJointGetUniversalAnchor(c, r);
    CHECK(same(a, r, 3));
    uj.getAxis1(a);
    dJointGetUniversalAxis1(c, r);
    CHECK(same(a, r, 3));
    uj.getAxis2(a);
    dJointGetUniversalAxis2(c, r);
    CHECK(same(a, r, 3));
    for (int k = 0; k < 2; k++) {   // turn body 2 about both axes, and spin it
        dMatrix3 R;
        dRFromEulerAngles(R, 0.3, 0.2, 0);
        dBodySetRotation(t.b[k][1], R);
        dBodySetAngularVel(t.b[k][1], 0.5, -0.7, 0);
    }
    uj.getAnchor2(a);
    dJointGetUniversalAnchor2(c, r);
    CHECK(same(a, r, 3));
    CHECK(uj.getAngle1() == dJointGetUniversalAngle1(c));
    CHECK(uj.getAngle2() == dJointGetUniversalAngle2(c));
    CHECK(uj.getAngle1() != uj.getAngle2());
    CHECK(uj.getAngle1Rate() == dJointGetUniversalAngle1Rate(c));
    CHECK(uj.getAngle2Rate() == dJointGetUniversalAngle2Rate(c));
    CHECK(uj.getAngle1Rate() != uj.getAngle2Rate());
    uj.getAngles(&a1, &a2);
    CHECK(a1 == dJointGetUniversalAngle1(c) && a2 == dJointGetUniversalAngle2(c));
    uj.setParam(dParamLoStop2, -0.25);
    dJointSetUniversalParam(c, dParamLoStop2, -0.25);
    CHECK(uj.getParam(dParamLoStop2) == dJointGetUniversalParam(c, dParamLoStop2));
    uj.addTorques(1, -2);
    dJointAddUniversalTorques(c, 1, -2);
    CHECK(t.same_bodies());
    return 0;
}

static int test_hinge2_joint_matches_c(void)
{
    twin t;
    dHinge2Joint h2(t.w[0]);
    dJointID c = dJointCreateHinge2(t.w[1], 0);
    h2.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 anchor = { 0.5, 0, 0.5, 0 }, z = { 0, 0, 1, 0 }, y = { 0, 1, 0, 0 };
    dVector3 a, r;

    h2.setAnchor(0.1, 0.2, 0.3);
    dJointSetHinge2Anchor(c, 0.1, 0.2, 0.3);
    h2.getAnchor(a);
    dJointGetHinge2Anchor(c, r);
    CHECK(same(a, r, 3));
    h2.setAnchor(anchor);
    h2.setAxes(z, y);
    dJointSetHinge2Anchor(c, 0.5, 0, 0.5);
    dJointSetHinge2Axes(c, z, y);
    h2.getAxis1(a);
    dJointGetHinge2Axis1(c, r);
    CHECK(same(a, r, 3));
    h2.getAxis2(a);
    dJointGetHinge2Axis2(c, r);
    CHECK(same(a, r, 3));
    h2.setAxes(0, y);   // a null axis is left as it is
    dJointSetHinge2Axes(c, 0, y);
    h2.getAxis1(a);
    dJointGetHinge2Axis1(c, r);
    CHECK(same(a, r, 3) && a[2] != 0);
    for (int k = 0; k < 2; k++) {
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 0, 1, 0.3);
        dBodySetRotation(t.b[k][1], R);
        dBodySetAngularVel(t.b[k][1], 0, 0.5, -0.7);
    }
    h2.getAnchor2(a);
    dJointGetHinge2Anchor2(c, r);
    CHECK(same(a, r, 3));
    CHECK(h2.getAngle1() == dJointGetHinge2Angle1(c));
    CHECK(h2.getAngle1Rate() == dJointGetHinge2Angle1Rate(c));
    CHECK(h2.getAngle2Rate() == dJointGetHinge2Angle2Rate(c));
    CHECK(h2.getAngle1Rate() != h2.getAngle2Rate());
    h2.setParam(dParamSuspensionERP, 0.4);
    dJointSetHinge2Param(c, dParamSuspensionERP, 0.4);
    CHECK(h2.getParam(dParamSuspensionERP) == dJointGetHinge2Param(c, dParamSuspensionERP));
    h2.addTorques(0.5, 0.25);
    dJointAddHinge2Torques(c, 0.5, 0.25);
    CHECK(t.same_bodies());
    return 0;
}

// The deprecated one-axis setters are setAxes with the other axis null.
static int test_hinge2_deprecated_axis_setters_set_one_axis(void)
{
    dWorld world;
    dBody b1(world), b2(world);
    dHinge2Joint h2(world);
    h2.attach(b1, b2);
    const dVector3 x = { 1, 0, 0, 0 }, y = { 0, 1, 0, 0 };
    dVector3 a;

#ifdef __GNUC__
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    h2.setAxis1(0, 0, 1);
    h2.setAxis2(x);
    h2.getAxis1(a);
    CHECK_VEC(a, 0, 0, 1, 0);
    h2.getAxis2(a);
    CHECK_VEC(a, 1, 0, 0, 0);
    h2.setAxis1(y);
    h2.setAxis2(0, 0, 1);
#ifdef __GNUC__
#pragma GCC diagnostic pop
#endif
    h2.getAxis1(a);
    CHECK_VEC(a, 0, 1, 0, 0);
    h2.getAxis2(a);
    CHECK_VEC(a, 0, 0, 1, 0);
    return 0;
}

static int test_fixed_joint_matches_c(void)
{
    twin t;
    dFixedJoint fixed(t.w[0]);
    dJointID c = dJointCreateFixed(t.w[1], 0);
    fixed.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);

    fixed.set();
    dJointSetFixed(c);
    fixed.setParam(dParamERP, 0.7);
    dJointSetFixedParam(c, dParamERP, 0.7);
    dWorldStep(t.w[0], 0.01);
    dWorldStep(t.w[1], 0.01);

    CHECK(fixed.getParam(dParamERP) == dJointGetFixedParam(c, dParamERP));
    CHECK(t.same_bodies());   // same fixed offsets, so the same step
    CHECK(fixed.getType() == dJointTypeFixed);
    return 0;
}

static int test_amotor_joint_matches_c(void)
{
    twin t;
    dAMotorJoint motor(t.w[0]);
    dJointID c = dJointCreateAMotor(t.w[1], 0);
    motor.attach(t.b[0][0], t.b[0][1]);
    dJointAttach(c, t.b[1][0], t.b[1][1]);
    const dVector3 y = { 0, 1, 0, 0 };
    dVector3 a, r;

    motor.setMode(dAMotorUser);
    motor.setNumAxes(3);
    motor.setAxis(0, 1, 1, 0, 0);
    motor.setAxis(1, 0, y);
    motor.setAxis(2, 2, 0, 0, 1);
    motor.setAngle(1, 0.25);
    dJointSetAMotorMode(c, dAMotorUser);
    dJointSetAMotorNumAxes(c, 3);
    dJointSetAMotorAxis(c, 0, 1, 1, 0, 0);
    dJointSetAMotorAxis(c, 1, 0, 0, 1, 0);
    dJointSetAMotorAxis(c, 2, 2, 0, 0, 1);
    dJointSetAMotorAngle(c, 1, 0.25);

    CHECK(motor.getMode() == dAMotorUser && dJointGetAMotorMode(motor) == dAMotorUser);
    CHECK(motor.getNumAxes() == 3 && dJointGetAMotorNumAxes(motor) == 3);
    for (int i = 0; i < 3; i++) {
        motor.getAxis(i, a);
        dJointGetAMotorAxis(c, i, r);
        CHECK(same(a, r, 3));
        CHECK(motor.getAxisRel(i) == dJointGetAMotorAxisRel(c, i));
        CHECK(motor.getAngle(i) == dJointGetAMotorAngle(c, i));
        CHECK(motor.getAngleRate(i) == dJointGetAMotorAngleRate(c, i));
    }
    CHECK(motor.getAxisRel(2) == 2 && motor.getAngle(1) == (dReal)0.25);
    motor.setParam(dParamVel3, 1.5);
    dJointSetAMotorParam(c, dParamVel3, 1.5);
    CHECK(motor.getParam(dParamVel3) == dJointGetAMotorParam(c, dParamVel3));
    motor.addTorques(1, 2, 3);
    dJointAddAMotorTorques(c, 1, 2, 3);
    CHECK(t.same_bodies());
    return 0;
}

static int test_joint_create_replaces_the_joint(void)
{
    dWorld world;
    dBody b1(world), b2(world);
    dJointGroup group;
    dHingeJoint hinge;
    dContactJoint contact;

    CHECK(hinge.id() == 0 && contact.id() == 0);   // nothing held yet
    hinge.create(world);
    hinge.attach(b1, b2);
    CHECK(b1.getNumJoints() == 1);
    hinge.create(world.id());   // the first hinge is destroyed
    CHECK(b1.getNumJoints() == 0 && hinge.getType() == dJointTypeHinge);

    dContact c;
    memset(&c, 0, sizeof c);
    c.surface.mode = dContactBounce;
    c.geom.normal[2] = 1;
    contact.create(world, group, &c);
    CHECK(contact.getType() == dJointTypeContact);
    contact.attach(b1, b2);
    CHECK(b1.getNumJoints() == 1);
    return 0;   // the contact's wrapper goes first, leaving the joint to the group
}

// ---- destructors ----------------------------------------------------------

// `call` uses a destroyed object: with the reports captured, it must be reported.
#define CHECK_DESTROYED(call)                 \
    do {                                      \
        test_capture_reports();               \
        call;                                 \
        CHECK(test_captured_count() >= 1);    \
        CHECK(test_captured_contains("destroyed")); \
        test_release_reports();               \
    } while (0)

static int test_wrappers_destroy_their_objects(void)
{
    dWorldID world_id;
    dBodyID body_id;
    dJointID joint_id;
    dJointGroupID group_id;
    dGeomID geom_id;
    dSpaceID space_id;
    dBodyID survivor;
    {
        dWorld world;
        dBody body(world);
        survivor = dBodyCreate(world);
        dHingeJoint hinge(world);
        dJointGroup group;
        dHashSpace space;
        dSphere sphere(0.5);
        hinge.attach(body, survivor);
        world_id = world;
        body_id = body;
        joint_id = hinge;
        group_id = group;
        space_id = space;
        geom_id = sphere;
    }   // destroyed in reverse order: sphere, space, group, hinge, body, world

    CHECK_DESTROYED(dWorldGetERP(world_id));
    CHECK_DESTROYED(dBodyGetPosition(body_id));
    CHECK_DESTROYED(dBodyGetPosition(survivor));   // went with its world
    CHECK_DESTROYED(dJointGetType(joint_id));
    CHECK_DESTROYED(dJointGroupEmpty(group_id));
    CHECK_DESTROYED(dGeomGetClass(geom_id));
    CHECK_DESTROYED(dSpaceGetNumGeoms(space_id));
    return 0;
}

static int test_joint_wrapper_leaves_a_group_joint_to_its_group(void)
{
    dWorld world;
    dBody b1(world), b2(world);
    dJointGroup group;
    dJointID id;
    {
        dBallJoint ball(world, group);
        ball.attach(b1, b2);
        id = ball;
    }

    CHECK(dJointGetType(id) == dJointTypeBall);   // still there: the group owns it
    CHECK(b1.getNumJoints() == 1);
    group.empty();
    CHECK(b1.getNumJoints() == 0);
    return 0;
}

// ---- geoms and spaces -----------------------------------------------------

static int test_geom_methods_match_c(void)
{
    dWorld world;
    dBody body(world);
    dSimpleSpace space;
    dBox box(space, 1, 2, 3);
    dGeomID c = dCreateBox(0, 1, 2, 3);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 1, 0, 0.7);
    dQuaternion q, q1, q2;
    dQFromAxisAndAngle(q, 0, 0, 1, 0.2);
    const dVector3 p = { 0.5, -0.5, 1, 0 };
    dVector3 a, b, r;
    dReal aabb1[6], aabb2[6];
    int data = 0;

    box.setPosition(1, 2, 3);
    box.setRotation(R);
    dGeomSetPosition(c, 1, 2, 3);
    dGeomSetRotation(c, R);
    CHECK(same(box.getPosition(), dGeomGetPosition(c), 3));
    CHECK(same(box.getRotation(), dGeomGetRotation(c), 12));
    CHECK(box.getPosition() == dGeomGetPosition(box));
    box.getAABB(aabb1);
    dGeomGetAABB(c, aabb2);
    CHECK(same(aabb1, aabb2, 6));
    box.getRelPointPos(0.5, -0.5, 1, a);
    box.getRelPointPos(p, b);
    dGeomGetRelPointPos(c, 0.5, -0.5, 1, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    box.getPosRelPoint(0.5, -0.5, 1, a);
    box.getPosRelPoint(p, b);
    dGeomGetPosRelPoint(c, 0.5, -0.5, 1, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    box.vectorToWorld(0.5, -0.5, 1, a);
    box.vectorToWorld(p, b);
    dGeomVectorToWorld(c, 0.5, -0.5, 1, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    box.vectorFromWorld(0.5, -0.5, 1, a);
    box.vectorFromWorld(p, b);
    dGeomVectorFromWorld(c, 0.5, -0.5, 1, r);
    CHECK(same(a, r, 3) && same(b, r, 3));
    box.setQuaternion(q);
    dGeomSetQuaternion(c, q);
    box.getQuaternion(q1);
    dGeomGetQuaternion(c, q2);
    CHECK(same(q1, q2, 4));

    CHECK(box.getClass() == dBoxClass && box.getSpace() == space.id());
    CHECK(!box.isSpace() && space.isSpace());
    box.setData(&data);
    CHECK(box.getData() == &data && dGeomGetData(box) == &data);
    box.setCategoryBits(6);
    box.setCollideBits(5);
    CHECK(box.getCategoryBits() == 6 && dGeomGetCollideBits(box) == 5);
    CHECK(box.getCollideBits() == 5);
    box.disable();
    CHECK(!box.isEnabled() && !dGeomIsEnabled(box));
    box.enable();
    CHECK(box.isEnabled());
    box.setBody(body);
    CHECK(box.getBody() == body.id() && box.getPosition() == body.getPosition());
    box.setBody(0);
    CHECK(box.id() == (dGeomID)box);
    box.destroy();
    CHECK(box.id() == 0 && space.getNumGeoms() == 0);
    dGeomDestroy(c);
    return 0;
}

static int test_geom_classes_match_c(void)
{
    dSimpleSpace space;
    dSphere sphere(space, 0.5);
    dBox box(1, 2, 3);
    dPlane plane(space.id(), 0, 0, 1, 0.25);
    dCapsule capsule(space, 0.5, 2);
    dCylinder cylinder(0.25, 1);
    dRay ray(space, 10);
    dVector3 v, start, dir;
    dVector4 plane_params;
    dReal radius, length;

    sphere.setRadius(0.75);
    CHECK(sphere.getRadius() == dGeomSphereGetRadius(sphere) && sphere.getRadius() == 0.75);
    CHECK(sphere.getClass() == dSphereClass);
    box.setLengths(4, 5, 6);
    box.getLengths(v);
    CHECK_VEC(v, 4, 5, 6, 0);
    dGeomBoxGetLengths(box, v);
    CHECK_VEC(v, 4, 5, 6, 0);
    CHECK(box.getSpace() == 0);
    plane.getParams(plane_params);
    dVector4 c_params;
    dGeomPlaneGetParams(plane, c_params);
    CHECK(same(plane_params, c_params, 4) && plane_params[3] == (dReal)0.25);
    plane.setParams(0, 1, 0, -1);
    plane.getParams(plane_params);
    CHECK(plane_params[1] == 1 && plane_params[3] == -1);
    capsule.setParams(0.25, 3);
    capsule.getParams(&radius, &length);
    CHECK(radius == (dReal)0.25 && length == 3 && capsule.getClass() == dCapsuleClass);
    cylinder.setParams(0.5, 1.5);
    cylinder.getParams(&radius, &length);
    CHECK(radius == (dReal)0.5 && length == (dReal)1.5 && cylinder.getClass() == dCylinderClass);

    ray.setLength(5);
    CHECK(ray.getLength() == 5 && dGeomRayGetLength(ray) == 5);
    ray.set(1, 2, 3, 0, 0, -2);
    ray.get(start, dir);
    CHECK_VEC(start, 1, 2, 3, 0);
    CHECK_VEC(dir, 0, 0, -1, 0);
    ray.setBackfaceCull(1);
    ray.setFirstContact(1);
    ray.setClosestHit(1);
    CHECK(ray.getBackfaceCull() == 1 && dGeomRayGetBackfaceCull(ray) == 1);
    CHECK(ray.getFirstContact() == 1 && dGeomRayGetFirstContact(ray) == 1);
    CHECK(ray.getClosestHit() == 1 && dGeomRayGetClosestHit(ray) == 1);
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    int first = -1, cull = -1;
    ray.setParams(0, 1);
    ray.getParams(&first, &cull);
    CHECK(first == 0 && cull == 1 && dGeomRayGetFirstContact(ray) == 0);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
    CHECK(space.getNumGeoms() == 4);

    sphere.create(0, 2);   // replaces the sphere: the old one leaves the space
    CHECK(sphere.getRadius() == 2 && sphere.getSpace() == 0 && space.getNumGeoms() == 3);
    dBox later;
    later.create(space, 1, 1, 1);
    CHECK(later.getClass() == dBoxClass && space.getNumGeoms() == 4);
    return 0;
}

static int test_geom_transform_matches_c(void)
{
#ifdef __GNUC__
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    dSimpleSpace space;
    dGeomTransform transform(space);
    dGeomTransform later;
#ifdef __GNUC__
#pragma GCC diagnostic pop
#endif
    dGeomID inner = dCreateSphere(0, 0.5);

    transform.setGeom(inner);
    transform.setCleanup(1);
    transform.setInfo(1);

    CHECK(transform.getGeom() == inner && dGeomTransformGetGeom(transform) == inner);
    CHECK(transform.getCleanup() == 1 && dGeomTransformGetCleanup(transform) == 1);
    CHECK(transform.getInfo() == 1 && dGeomTransformGetInfo(transform) == 1);
    CHECK(transform.getClass() == dGeomTransformClass);
    later.create();
    CHECK(later.getClass() == dGeomTransformClass && later.getSpace() == 0);
    return 0;   // the transform's cleanup destroys `inner` (ASan: no leak)
}

static int test_spaces_match_c(void)
{
    dHashSpace top;
    dSimpleSpace simple(top);
    dHashSpace hash(top.id());
    const dVector3 center = { 0, 0, 0, 0 }, extents = { 10, 10, 10, 0 };
    dQuadTreeSpace quad(top, center, extents, 3);
    dQuadTreeSpace quad2(center, extents, 2);
    dSphere a(0.5), b(0.5);
    int lo, hi;

    CHECK(top.getNumGeoms() == 3 && dSpaceGetNumGeoms(top) == 3);
    CHECK(top.query(simple) && top.query(hash) && top.query(quad));
    CHECK(top.getGeom(0) == dSpaceGetGeom(top, 0));
    CHECK(top.id() == (dSpaceID)top && dSpaceGetClass(quad) == dQuadTreeSpaceClass);
    CHECK(quad.getSpace() == top.id() && quad2.getSpace() == 0);
    CHECK(dSpaceGetClass(simple) == dSimpleSpaceClass && hash.getClass() == dHashSpaceClass);
    hash.setLevels(-2, 5);
    dHashSpaceGetLevels(hash, &lo, &hi);
    CHECK(lo == -2 && hi == 5);
    simple.add(a);
    simple.add(b.id());
    CHECK(simple.getNumGeoms() == 2 && simple.query(a) && a.getSpace() == simple.id());
    simple.remove(a);
    CHECK(simple.getNumGeoms() == 1 && !simple.query(a) && a.getSpace() == 0);
    simple.setCleanup(0);
    CHECK(simple.getCleanup() == 0 && dSpaceGetCleanup(simple) == 0);
    quad.add(a);
    CHECK(quad.getNumGeoms() == 1);
    quad.remove(a);
    return 0;   // the wrappers go in reverse order: geoms, child spaces, then top
}

// Counts the pairs the near callback sees.
static void count_pair(void *data, dGeomID, dGeomID) { ++*(int *)data; }

static int test_space_collide_and_collide2_match_c(void)
{
    dSimpleSpace space;
    dSphere s1(space, 1), s2(space, 1), s3(space, 1);
    dSphere probe(0.5);
    s2.setPosition(1.5, 0, 0);
    s3.setPosition(10, 0, 0);
    probe.setPosition(0, 1, 0);
    int wrapped = 0, c = 0;

    space.collide(&wrapped, count_pair);
    dSpaceCollide(space, &c, count_pair);
    CHECK(wrapped == c && c == 1);   // only s1-s2 overlap
    wrapped = c = 0;
    probe.collide2(space, &wrapped, count_pair);
    dSpaceCollide2(probe, (dGeomID)space.id(), &c, count_pair);
    CHECK(wrapped == c && c >= 1);
    return 0;
}

// ---- simulations: through the wrappers and through C, bit for bit ---------

static const int STEPS = 200;
static const dReal DT = 0.01;

// A pendulum: a sphere on a rod of length 1, hinged to the world about y.
static int test_pendulum_through_wrappers_matches_c(void)
{
    dReal wrapped[STEPS][3], c[STEPS][3];
    dMass m;
    dMassSetSphere(&m, 1, 0.1);
    {
        dWorld world;
        world.setGravity(0, 0, -9.81);
        dBody bob(world);
        bob.setPosition(1, 0, 1);
        bob.setMass(m);
        dHingeJoint hinge(world);
        hinge.attach(bob.id(), 0);
        hinge.setAnchor(0, 0, 1);
        hinge.setAxis(0, 1, 0);
        for (int i = 0; i < STEPS; i++) {
            world.step(DT);
            memcpy(wrapped[i], bob.getPosition(), sizeof wrapped[i]);
        }
        CHECK(hinge.getAngle() != 0);
    }
    {
        dWorldID world = dWorldCreate();
        dWorldSetGravity(world, 0, 0, -9.81);
        dBodyID bob = dBodyCreate(world);
        dBodySetPosition(bob, 1, 0, 1);
        dBodySetMass(bob, &m);
        dJointID hinge = dJointCreateHinge(world, 0);
        dJointAttach(hinge, bob, 0);
        dJointSetHingeAnchor(hinge, 0, 0, 1);
        dJointSetHingeAxis(hinge, 0, 1, 0);
        for (int i = 0; i < STEPS; i++) {
            dWorldStep(world, DT);
            memcpy(c[i], dBodyGetPosition(bob), sizeof c[i]);
        }
        dWorldDestroy(world);
    }

    for (int i = 0; i < STEPS; i++) CHECK(same(wrapped[i], c[i], 3));
    // And it is a pendulum: it swung down, on its rod, in the x-z plane.
    const dReal *end = wrapped[STEPS / 4];
    CHECK(end[2] < 0.5);
    // The rod stretches by about v^2 dt^2 / (2 ERP L) = 4e-3 at v = 4 m/s: the
    // step moves the bob along its tangent and ERP 0.2 pulls it back.
    CHECK_NEAR(end[0] * end[0] + (end[2] - 1) * (end[2] - 1), 1, 0.02);
    CHECK_NEAR(end[1], 0, TOL(1e-9, 1e-4));
    return 0;
}

// What the near callbacks need.
struct contact_scene {
    dWorldID world;
    dJointGroupID group;
};

static void fill_contact(dContact *c, const dContactGeom *g)
{
    memset(c, 0, sizeof *c);
    c->surface.mode = dContactBounce;
    c->surface.mu = 1;
    c->surface.bounce = 0.3;
    c->geom = *g;
}

// The wrappers' callback: a dContactJoint for each contact, left to the group.
static void near_wrapped(void *data, dGeomID o1, dGeomID o2)
{
    contact_scene *s = (contact_scene *)data;
    dContactGeom g[4];
    const int n = dCollide(o1, o2, 4, g, sizeof g[0]);
    for (int i = 0; i < n; i++) {
        dContact c;
        fill_contact(&c, &g[i]);
        dContactJoint joint(s->world, s->group, &c);
        joint.attach(dGeomGetBody(o1), dGeomGetBody(o2));
    }
}

static void near_c(void *data, dGeomID o1, dGeomID o2)
{
    contact_scene *s = (contact_scene *)data;
    dContactGeom g[4];
    const int n = dCollide(o1, o2, 4, g, sizeof g[0]);
    for (int i = 0; i < n; i++) {
        dContact c;
        fill_contact(&c, &g[i]);
        dJointID joint = dJointCreateContact(s->world, s->group, &c);
        dJointAttach(joint, dGeomGetBody(o1), dGeomGetBody(o2));
    }
}

// A sphere dropped on a plane, with quickStep and contacts from dSpace::collide.
static int test_sphere_on_plane_through_wrappers_matches_c(void)
{
    static dReal wrapped[STEPS][3], c[STEPS][3];
    dMass m;
    dMassSetSphere(&m, 1, 0.5);
    {
        dWorld world;
        dHashSpace space;
        dJointGroup contacts;
        world.setGravity(0, 0, -9.81);
        dBody ball(world);
        ball.setPosition(0, 0, 2);
        ball.setLinearVel(0.5, 0, 0);
        ball.setMass(m);
        dSphere sphere(space, 0.5);
        sphere.setBody(ball);
        dPlane ground(space, 0, 0, 1, 0);
        contact_scene s = { world, contacts };
        for (int i = 0; i < STEPS; i++) {
            space.collide(&s, near_wrapped);
            world.quickStep(DT);
            contacts.empty();
            memcpy(wrapped[i], ball.getPosition(), sizeof wrapped[i]);
        }
    }
    {
        dWorldID world = dWorldCreate();
        dSpaceID space = dHashSpaceCreate(0);
        dJointGroupID contacts = dJointGroupCreate(0);
        dWorldSetGravity(world, 0, 0, -9.81);
        dBodyID ball = dBodyCreate(world);
        dBodySetPosition(ball, 0, 0, 2);
        dBodySetLinearVel(ball, 0.5, 0, 0);
        dBodySetMass(ball, &m);
        dGeomID sphere = dCreateSphere(space, 0.5);
        dGeomSetBody(sphere, ball);
        dCreatePlane(space, 0, 0, 1, 0);
        contact_scene s = { world, contacts };
        for (int i = 0; i < STEPS; i++) {
            dSpaceCollide(space, &s, near_c);
            dWorldQuickStep(world, DT);
            dJointGroupEmpty(contacts);
            memcpy(c[i], dBodyGetPosition(ball), sizeof c[i]);
        }
        dJointGroupDestroy(contacts);
        dSpaceDestroy(space);   // cleanup on: the geoms go with it
        dWorldDestroy(world);
    }

    for (int i = 0; i < STEPS; i++) CHECK(same(wrapped[i], c[i], 3));
    // It fell, bounced and came to rest on the plane.
    CHECK_NEAR(wrapped[STEPS - 1][2], 0.5, 0.01);
    CHECK(wrapped[STEPS - 1][0] > 0.5);
    return 0;
}

extern "C" const test_case test_cases[] = {
    TEST_CASE(test_world_methods_set_and_read_the_c_world),
    TEST_CASE(test_world_template_over_the_simple_container),
    TEST_CASE(test_body_state_setters_match_c),
    TEST_CASE(test_body_forces_match_c),
    TEST_CASE(test_body_point_conversions_match_c),
    TEST_CASE(test_body_modes_match_c),
    TEST_CASE(test_body_joints_and_connection_match_c),
    TEST_CASE(test_joint_base_methods_match_c),
    TEST_CASE(test_params_dispatch_through_a_joint_reference),
    TEST_CASE(test_ball_joint_matches_c),
    TEST_CASE(test_hinge_joint_matches_c),
    TEST_CASE(test_slider_joint_matches_c),
    TEST_CASE(test_universal_joint_matches_c),
    TEST_CASE(test_hinge2_joint_matches_c),
    TEST_CASE(test_hinge2_deprecated_axis_setters_set_one_axis),
    TEST_CASE(test_fixed_joint_matches_c),
    TEST_CASE(test_amotor_joint_matches_c),
    TEST_CASE(test_joint_create_replaces_the_joint),
    TEST_CASE(test_wrappers_destroy_their_objects),
    TEST_CASE(test_joint_wrapper_leaves_a_group_joint_to_its_group),
    TEST_CASE(test_geom_methods_match_c),
    TEST_CASE(test_geom_classes_match_c),
    TEST_CASE(test_geom_transform_matches_c),
    TEST_CASE(test_spaces_match_c),
    TEST_CASE(test_space_collide_and_collide2_match_c),
    TEST_CASE(test_pendulum_through_wrappers_matches_c),
    TEST_CASE(test_sphere_on_plane_through_wrappers_matches_c),
    TEST_END
};

#endif   // TEST_ODECPP_INSTANTIATE_ALL
