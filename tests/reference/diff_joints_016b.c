// SPDX-License-Identifier: BSD-3-Clause
//
// diff_joints_016b.c -- the linear motor, plane-2D, double ball, double hinge
// and transmission joints against the reference ODE 0.16: getters exactly
// (to rounding), short dWorldStep trajectories tightly. Bodies are spheres (no
// gyroscopic term, integrated differently on purpose). Where this library
// differs from ODE 0.16 on purpose (the LMotor axis getter of a turned body,
// a reversed LMotor, bevel gears ODE mis-signs, chain sprockets out of the
// world's planes; see the joint files) the scenes stay where both agree.

#include "diff_print.h"

static dBodyID sphere_body(dWorldID w, dReal mass, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, mass, 0.1);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

static void body_state(const char *name, dBodyID b, double tol)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s_pos", name);
    diff_values(buf, tol, dBodyGetPosition(b), 3);
    snprintf(buf, sizeof buf, "%s_quat", name);
    diff_values(buf, tol, dBodyGetQuaternion(b), 4);
    snprintf(buf, sizeof buf, "%s_lvel", name);
    diff_values(buf, 10 * tol, dBodyGetLinearVel(b), 3);
    snprintf(buf, sizeof buf, "%s_avel", name);
    diff_values(buf, 10 * tol, dBodyGetAngularVel(b), 3);
}

// A body driven by a three-axis motor against gravity (one axis too weak),
// and two bodies driven apart along an axis fixed to the first.
static void lmotor(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere_body(w, 2, 0, 0, 1);
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, b, 0);
    dJointSetLMotorNumAxes(j, 3);
    dJointSetLMotorAxis(j, 0, 0, 1, 1, 0);
    dJointSetLMotorAxis(j, 1, 1, 0, 0, 2);   // body 1, not turned: also the world axis
    dJointSetLMotorAxis(j, 2, 0, 1, -1, 0);
    dJointSetLMotorParam(j, dParamVel, 1);
    dJointSetLMotorParam(j, dParamFMax, 100);
    dJointSetLMotorParam(j, dParamVel2, 2);
    dJointSetLMotorParam(j, dParamFMax2, 100);
    dJointSetLMotorParam(j, dParamVel3, -3);
    dJointSetLMotorParam(j, dParamFMax3, 2);
    diff_value("lmotor_num_axes", 0, dJointGetLMotorNumAxes(j));
    dVector3 v;
    dJointGetLMotorAxis(j, 0, v);
    diff_values("lmotor_axis0", 1e-15, v, 3);
    dJointGetLMotorAxis(j, 1, v);
    diff_values("lmotor_axis1", 1e-15, v, 3);
    diff_value("lmotor_vel2", 0, dJointGetLMotorParam(j, dParamVel2));
    diff_value("lmotor_fmax3", 0, dJointGetLMotorParam(j, dParamFMax3));
    diff_value("lmotor_cfm", 0, dJointGetLMotorParam(j, dParamCFM));
    diff_value("lmotor_lostop3", 0, dJointGetLMotorParam(j, dParamLoStop3));
    for (int i = 0; i < 50; i++) dWorldStep(w, 0.01);
    body_state("lmotor_one", b, 1e-9);

    dBodyID b1 = sphere_body(w, 1, 5, 0, 0), b2 = sphere_body(w, 3, 5, 1, 0.5);
    dJointID k = dJointCreateLMotor(w, 0);
    dJointAttach(k, b1, b2);
    dJointSetLMotorNumAxes(k, 1);
    dJointSetLMotorAxis(k, 0, 1, 1, 1, 0);
    dJointSetLMotorParam(k, dParamVel, 0.5);
    dJointSetLMotorParam(k, dParamFMax, 10);
    for (int i = 0; i < 50; i++) dWorldStep(w, 0.01);
    body_state("lmotor_pair1", b1, 1e-9);
    body_state("lmotor_pair2", b2, 1e-9);
    dWorldDestroy(w);
}

// A body in the plane pushed about, with its x and angle motors on.
static void plane2d(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, -9.81, -2);
    dBodyID b = sphere_body(w, 1, 0.5, 0, 0.1);
    dJointID j = dJointCreatePlane2D(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPlane2DXParam(j, dParamVel, 1);
    dJointSetPlane2DXParam(j, dParamFMax, 0.5);
    dJointSetPlane2DAngleParam(j, dParamVel, -2);
    dJointSetPlane2DAngleParam(j, dParamFMax, 1);
    for (int i = 0; i < 100; i++) {
        dBodyAddForce(b, 0.3, 0, 5 * (i % 7) - 12);
        dBodyAddTorque(b, 0.2, -0.1, 0.05);
        dWorldStep(w, 0.01);
    }
    body_state("plane2d", b, 1e-9);
    dWorldDestroy(w);
}

// A double pendulum of rods with ball ends (the body rotates about its anchor).
static void dball(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b1 = sphere_body(w, 1, 0.2, 0, 2), b2 = sphere_body(w, 1, 0.2, 0.3, 0);
    dJointID j1 = dJointCreateDBall(w, 0), j2 = dJointCreateDBall(w, 0);
    dJointAttach(j1, b1, 0);
    dJointSetDBallAnchor1(j1, 0.2, 0, 2.5);
    dJointSetDBallAnchor2(j1, 0, 0, 3.5);
    dJointAttach(j2, b1, b2);
    dJointSetDBallAnchor1(j2, 0.2, 0, 1.5);
    dJointSetDBallAnchor2(j2, 0.2, 0.3, 0.5);
    dJointSetDBallParam(j2, dParamERP, 0.5);
    dVector3 v;
    diff_value("dball_distance1", 1e-15, dJointGetDBallDistance(j1));
    diff_value("dball_distance2", 1e-15, dJointGetDBallDistance(j2));
    dJointGetDBallAnchor1(j2, v);
    diff_values("dball_anchor1", 1e-15, v, 3);
    dJointGetDBallAnchor2(j2, v);
    diff_values("dball_anchor2", 1e-15, v, 3);
    diff_value("dball_erp", 0, dJointGetDBallParam(j2, dParamERP));
    diff_value("dball_cfm", 0, dJointGetDBallParam(j1, dParamCFM));
    for (int i = 0; i < 300; i++) dWorldStep(w, 0.01);
    body_state("dball_b1", b1, 1e-6);
    body_state("dball_b2", b2, 1e-6);
    dJointGetDBallAnchor1(j1, v);
    diff_values("dball_anchor1_after", 1e-6, v, 3);
    dJointSetDBallDistance(j1, 1.5);
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    diff_value("dball_set_distance", 0, dJointGetDBallDistance(j1));
    body_state("dball_b1_longer", b1, 1e-6);
    // Attached again: the distance is the anchors' distance now (as ODE 0.16).
    dJointAttach(j2, b1, b2);
    diff_value("dball_reattached_distance", 1e-9, dJointGetDBallDistance(j2));
    dWorldDestroy(w);
}

// ODE's demo_dhinge: a body hung from the world by a double hinge about y,
// a second from it by one about x (and a double ball), pushed sideways.
static void dhinge(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b1 = sphere_body(w, 1, 0, 0, 3), b2 = sphere_body(w, 1, 0, 0, 1);
    dBodySetLinearVel(b1, 1, 0, 0);
    dBodySetLinearVel(b2, 0, 1, 0);
    dJointID j1 = dJointCreateDHinge(w, 0), j2 = dJointCreateDHinge(w, 0);
    dJointAttach(j1, b1, 0);
    dJointSetDHingeAxis(j1, 0, 1, 0);
    dJointSetDHingeAnchor1(j1, 0, 0, 3.5);
    dJointSetDHingeAnchor2(j1, 0, 0, 4.5);
    dJointAttach(j2, b1, b2);
    dJointSetDHingeAxis(j2, 1, 0, 0);
    dJointSetDHingeAnchor1(j2, 0, 0, 2.5);
    dJointSetDHingeAnchor2(j2, 0, 0, 1.5);
    dVector3 v;
    dJointGetDHingeAxis(j2, v);
    diff_values("dhinge_axis", 1e-15, v, 3);
    diff_value("dhinge_distance", 1e-15, dJointGetDHingeDistance(j1));
    dJointGetDHingeAnchor2(j1, v);
    diff_values("dhinge_anchor2", 1e-15, v, 3);
    diff_value("dhinge_erp", 0, dJointGetDHingeParam(j1, dParamERP));
    for (int i = 0; i < 300; i++) dWorldStep(w, 0.01);
    body_state("dhinge_b1", b1, 1e-6);
    body_state("dhinge_b2", b2, 1e-6);
    dJointGetDHingeAxis(j2, v);
    diff_values("dhinge_axis_after", 1e-6, v, 3);
    dWorldDestroy(w);
}

// ODE's demo_transmission, each mode (wheels as spheres): wheel 2 driven by
// its hinge motor, wheel 1 following through the transmission.
static void transmission(int mode, double backlash)
{
    const double s = sqrt(0.5);
    static const double anchors[3][2][3] = { { { 1, 0, 1 }, { -1, 0, 1 } },
                                             { { 1, 0, 1 }, { -1, 0, 2 } },
                                             { { 2, 0, 1 }, { -2, 0, 1 } } };
    const double axis2[3] = { mode == 1 ? s : 0, 0, mode == 1 ? s : 1 };
    const double(*a)[3] = anchors[mode];
    dWorldID w = dWorldCreate();
    dBodyID b1 = sphere_body(w, 1, a[0][0], a[0][1], a[0][2]);
    dBodyID b2 = sphere_body(w, 1, a[1][0], a[1][1], a[1][2]);
    dJointID h1 = dJointCreateHinge(w, 0), h2 = dJointCreateHinge(w, 0);
    dJointAttach(h1, b1, 0);
    dJointSetHingeAnchor(h1, a[0][0], a[0][1], a[0][2]);
    dJointSetHingeAxis(h1, 0, 0, 1);
    dJointAttach(h2, b2, 0);
    dJointSetHingeAnchor(h2, a[1][0], a[1][1], a[1][2]);
    dJointSetHingeAxis(h2, axis2[0], axis2[1], axis2[2]);
    dJointSetHingeParam(h2, dParamVel, 5);
    dJointSetHingeParam(h2, dParamFMax, 50);
    dJointID t = dJointCreateTransmission(w, 0);
    dJointAttach(t, b1, b2);
    dJointSetTransmissionMode(t, mode);
    dJointSetTransmissionAnchor1(t, a[0][0], a[0][1], a[0][2]);
    dJointSetTransmissionAnchor2(t, a[1][0], a[1][1], a[1][2]);
    if (mode == dTransmissionIntersectingAxes) {
        dJointSetTransmissionAxis1(t, 0, 0, -1);
        dJointSetTransmissionAxis2(t, axis2[0], axis2[1], axis2[2]);
    } else {
        dJointSetTransmissionAxis(t, 0, 0, 1);
    }
    if (mode == dTransmissionParallelAxes) dJointSetTransmissionRatio(t, 2);
    if (mode == dTransmissionChainDrive) {
        dJointSetTransmissionRadius1(t, 0.5);
        dJointSetTransmissionRadius2(t, 1);
    }
    dJointSetTransmissionBacklash(t, backlash);
    dJointSetTransmissionParam(t, dParamERP, 0.3);
    char name[64];
#define NAME(what) (snprintf(name, sizeof name, "transmission%d_%s%s", mode, what, \
                             backlash > 0 ? "_backlash" : ""), name)
    diff_value(NAME("mode"), 0, dJointGetTransmissionMode(t));
    diff_value(NAME("ratio"), 0, dJointGetTransmissionRatio(t));
    diff_value(NAME("backlash"), 0, dJointGetTransmissionBacklash(t));
    diff_value(NAME("erp"), 0, dJointGetTransmissionParam(t, dParamERP));
    dVector3 v;
    dJointGetTransmissionAnchor2(t, v);
    diff_values(NAME("anchor2"), 1e-15, v, 3);
    dJointGetTransmissionAxis2(t, v);
    diff_values(NAME("axis2"), 1e-15, v, 3);
    for (int i = 0; i < 200; i++) dWorldStep(w, 0.01);
    diff_value(NAME("ratio_after"), 1e-12, dJointGetTransmissionRatio(t));
    diff_value(NAME("radius1"), 1e-12, dJointGetTransmissionRadius1(t));
    diff_value(NAME("radius2"), 1e-12, dJointGetTransmissionRadius2(t));
    // Bevel gears at 45 degrees: ODE's tangent is sin 45 long, not 1, which
    // makes its phase correction 1.4 times as strong (1e-5 rad apart after 2 s).
    const double phase_tol = mode == dTransmissionIntersectingAxes ? 1e-4 : 1e-6;
    diff_value(NAME("angle1"), phase_tol, dJointGetTransmissionAngle1(t));
    diff_value(NAME("angle2"), phase_tol, dJointGetTransmissionAngle2(t));
    dJointGetTransmissionContactPoint1(t, v);
    diff_values(NAME("contact1"), 1e-9, v, 3);
    dJointGetTransmissionContactPoint2(t, v);
    diff_values(NAME("contact2"), 1e-9, v, 3);
    dJointGetTransmissionAxis1(t, v);
    diff_values(NAME("axis1_after"), 1e-6, v, 3);
    diff_values(NAME("wheel1_avel"), 1e-6, dBodyGetAngularVel(b1), 3);
    diff_values(NAME("wheel2_avel"), 1e-6, dBodyGetAngularVel(b2), 3);
#undef NAME
    dWorldDestroy(w);
}

int main(void)
{
    dInitODE();
    lmotor();
    plane2d();
    dball();
    dhinge();
    for (int mode = 0; mode < 3; mode++) transmission(mode, 0);
    transmission(dTransmissionParallelAxes, 0.1);
    transmission(dTransmissionChainDrive, 0.1);
    dCloseODE();
    return 0;
}
