// SPDX-License-Identifier: BSD-3-Clause
//
// diff_joints_016a.c -- the prismatic-rotoide (PR), prismatic-universal (PU)
// and piston joints of ODE 0.16, run against this library and the reference:
// getters right after setting up (exact up to rounding), after re-attaching
// (the body-relative values are recomputed), and short dWorldStep
// trajectories with two bodies, one body, and one body attached as (0, b).
// Bodies are spheres (no gyroscopic term). Trajectory tolerances: 1e-6 after
// 100-200 steps of the same first-order method with a direct solver; the
// rows are built the same way, so both agree to rounding unless a pivot
// differs.
//
// Left out on purpose, where ODE 0.16 has bugs this library does not copy:
// a reversed PR or piston with the anchor off the body's centre (ODE flips
// the lever arm and the error term then: the body is flung away), a reversed
// PU whose body turns (ODE reads a body-frame axis as a world one), a
// reversed dJointAddPistonForce (ODE applies no force), and a two-body
// dJointAddPistonForce with the anchor off the line of centres.

#include "diff_print.h"

#define EXACT 1e-12
#define TRAJ 1e-6

static dBodyID sphere(dWorldID w, dReal mass, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, mass, 0.1);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

// A body turned about a unit axis, so body frames differ from the world's.
static void turn(dBodyID b, dReal x, dReal y, dReal z, dReal angle)
{
    dQuaternion q;
    dQFromAxisAndAngle(q, x, y, z, angle);
    dBodySetQuaternion(b, q);
}

static void print_body(const char *name, dBodyID b)
{
    char buf[96];
    snprintf(buf, sizeof buf, "%s_pos", name);
    diff_values(buf, TRAJ, dBodyGetPosition(b), 3);
    snprintf(buf, sizeof buf, "%s_quat", name);
    diff_values(buf, TRAJ, dBodyGetQuaternion(b), 4);
    snprintf(buf, sizeof buf, "%s_lvel", name);
    diff_values(buf, 1e-5, dBodyGetLinearVel(b), 3);
    snprintf(buf, sizeof buf, "%s_avel", name);
    diff_values(buf, 1e-5, dBodyGetAngularVel(b), 3);
}

// ---- PR --------------------------------------------------------------------

static void print_pr(const char *name, dJointID j, double tol)
{
    char buf[96];
    dVector3 v;
    dJointGetPRAnchor(j, v);
    snprintf(buf, sizeof buf, "%s_anchor", name);
    diff_values(buf, tol, v, 3);
    dJointGetPRAxis1(j, v);
    snprintf(buf, sizeof buf, "%s_axis1", name);
    diff_values(buf, tol, v, 3);
    dJointGetPRAxis2(j, v);
    snprintf(buf, sizeof buf, "%s_axis2", name);
    diff_values(buf, tol, v, 3);
    const dReal s[4] = { dJointGetPRPosition(j), dJointGetPRPositionRate(j),
                         dJointGetPRAngle(j), dJointGetPRAngleRate(j) };
    snprintf(buf, sizeof buf, "%s_pos_rate_angle_rate", name);
    diff_values(buf, tol * 10, s, 4);
}

static void pr_two_bodies(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID a = sphere(w, 2, 0, 0, 1), b = sphere(w, 1, 0, 1, 1);
    turn(a, 0, 0, 1, 0.3);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, a, b);
    dJointSetPRAnchor(j, 0, 0.5, 1);
    dJointSetPRAxis1(j, 0, 1, 0);
    dJointSetPRAxis2(j, 1, 0, 0);
    dBodySetLinearVel(b, 0.1, 0.4, 0.2);
    dBodySetAngularVel(b, 0.7, 0.1, 0);
    print_pr("pr2_set", j, EXACT);
    for (int i = 0; i < 150; i++) dWorldStep(w, 0.01);
    print_pr("pr2_end", j, TRAJ);
    print_body("pr2_a", a);
    print_body("pr2_b", b);
    // Re-attached the other way round: the values are recomputed from the
    // world ones.
    dJointAttach(j, b, a);
    print_pr("pr2_swapped", j, TRAJ);
    dWorldDestroy(w);
}

static void pr_one_body(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, -2, -9.81);
    dBodyID b = sphere(w, 1, 0, 0, -0.5);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPRAnchor(j, 0, 0, 0);
    dJointSetPRAxis1(j, 0, 1, 0);
    dJointSetPRAxis2(j, 1, 0, 0);
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 1, 0, 0);
    dJointSetPRParam(j, dParamLoStop, -0.2);
    dJointSetPRParam(j, dParamLoStop2, -0.5);
    dJointSetPRParam(j, dParamHiStop2, 0.5);
    print_pr("pr1_set", j, EXACT);
    dJointFeedback fb;
    dJointSetFeedback(j, &fb);
    for (int i = 0; i < 200; i++) dWorldStep(w, 0.01);
    print_pr("pr1_end", j, TRAJ);
    print_body("pr1_b", b);
    diff_values("pr1_feedback_f1", 1e-5, fb.f1, 3);
    diff_values("pr1_feedback_t1", 1e-5, fb.t1, 3);
    dWorldDestroy(w);
}

// Attached as (0, b), anchor at the body's centre: a motor on the slide and a
// torque on the rotation.
static void pr_reversed(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = sphere(w, 1, 0.2, 0.3, 0.4);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPRAnchor(j, 0.2, 0.3, 0.4);
    dJointSetPRAxis1(j, 0, 0, 1);
    dJointSetPRAxis2(j, 0, 1, 0);
    dJointSetPRParam(j, dParamVel, 0.5);
    dJointSetPRParam(j, dParamFMax, 10);
    print_pr("prr_set", j, EXACT);
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    print_pr("prr_end", j, TRAJ);
    print_body("prr_b", b);
    dJointAttach(j, b, 0);
    print_pr("prr_unreversed", j, TRAJ);
    dWorldDestroy(w);
}

// ---- piston ------------------------------------------------------------------

static void print_piston(const char *name, dJointID j, double tol)
{
    char buf[96];
    dVector3 v;
    dJointGetPistonAnchor(j, v);
    snprintf(buf, sizeof buf, "%s_anchor", name);
    diff_values(buf, tol, v, 3);
    dJointGetPistonAnchor2(j, v);
    snprintf(buf, sizeof buf, "%s_anchor2", name);
    diff_values(buf, tol, v, 3);
    dJointGetPistonAxis(j, v);
    snprintf(buf, sizeof buf, "%s_axis", name);
    diff_values(buf, tol, v, 3);
    const dReal s[4] = { dJointGetPistonPosition(j), dJointGetPistonPositionRate(j),
                         dJointGetPistonAngle(j), dJointGetPistonAngleRate(j) };
    snprintf(buf, sizeof buf, "%s_pos_rate_angle_rate", name);
    diff_values(buf, tol * 10, s, 4);
}

static void piston_two_bodies(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID a = sphere(w, 2, 0, 0, 1), b = sphere(w, 1, 1, 0, 1);
    turn(b, 0, 1, 0, 0.4);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, a, b);
    dJointSetPistonAnchor(j, 0.5, 0, 1);
    dJointSetPistonAxis(j, 1, 0, 0);
    dBodySetLinearVel(b, 0.3, 0.1, 0.2);
    dBodySetAngularVel(b, 0.8, 0.2, 0);
    print_piston("pi2_set", j, EXACT);
    dJointFeedback fb;
    dJointSetFeedback(j, &fb);
    for (int i = 0; i < 150; i++) dWorldStep(w, 0.01);
    print_piston("pi2_end", j, TRAJ);
    print_body("pi2_a", a);
    print_body("pi2_b", b);
    dJointAttach(j, b, a);
    print_piston("pi2_swapped", j, TRAJ);
    diff_values("pi2_feedback_f1", 1e-5, fb.f1, 3);
    diff_values("pi2_feedback_t1", 1e-5, fb.t1, 3);
    dWorldDestroy(w);
}

static void piston_one_body(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere(w, 1, 0.3, 0, -0.5);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPistonAnchor(j, 0.3, 0, 0);
    dJointSetPistonAxis(j, 0, 0, 1);
    dBodySetAngularVel(b, 0, 0, 2);
    dJointSetPistonParam(j, dParamLoStop, -0.3);
    dJointSetPistonParam(j, dParamVel2, 1);
    dJointSetPistonParam(j, dParamFMax2, 0.001);
    print_piston("pi1_set", j, EXACT);
    for (int i = 0; i < 200; i++) dWorldStep(w, 0.01);
    print_piston("pi1_end", j, TRAJ);
    print_body("pi1_b", b);
    dWorldDestroy(w);
}

static void piston_reversed(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -1);
    dBodyID b = sphere(w, 1, 0.1, 0.2, 0.3);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPistonAnchor(j, 0.1, 0.2, 0.3);
    dJointSetPistonAxis(j, 0, 0, 1);
    dJointSetPistonParam(j, dParamHiStop, 0.05);
    dBodySetAngularVel(b, 0, 0, 1);
    print_piston("pir_set", j, EXACT);
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    print_piston("pir_end", j, TRAJ);
    print_body("pir_b", b);
    dJointAttach(j, b, 0);
    print_piston("pir_unreversed", j, TRAJ);
    dWorldDestroy(w);
}

static void piston_offsets(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = sphere(w, 1, 0, 0, 0), b = sphere(w, 1, 0, 0, 1);
    turn(a, 1, 0, 0, 0.2);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, a, b);
    dJointSetPistonAxis(j, 0, 0, 1);
    dJointSetPistonAnchorOffset(j, 0, 0, 0.5, 0, 0, 0.25);
    print_piston("pi_offset", j, EXACT);
    #if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    dJointSetPistonAxisDelta(j, 0, 0, 1, 0.1, 0, 0.3);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
    print_piston("pi_axisdelta", j, EXACT);
    dJointAttach(j, 0, a);
    dJointSetPistonAnchorOffset(j, 0, 0, 0.5, 0, 0, 0.25);
    print_piston("pi_offset_reversed", j, EXACT);
    dWorldDestroy(w);
}

// A torque on a reversed PR whose body does not slide.
static void pr_reversed_torque(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = sphere(w, 1, 0.2, 0.3, 0.4);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPRAnchor(j, 0.2, 0.3, 0.4);
    dJointSetPRAxis1(j, 0, 0, 1);
    dJointSetPRAxis2(j, 0, 1, 0);
    for (int i = 0; i < 50; i++) {
        dJointAddPRTorque(j, 0.01);
        dWorldStep(w, 0.01);
    }
    print_pr("prr_torque", j, TRAJ);
    print_body("prr_torque_b", b);
    dWorldDestroy(w);
}

// dJointAddPistonForce between two bodies on the axis through the anchor.
static void piston_force(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = sphere(w, 2, 0, 0, 1), b = sphere(w, 1, 1, 0, 1);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, a, b);
    dJointSetPistonAnchor(j, 0.5, 0, 1);
    dJointSetPistonAxis(j, 1, 0, 0);
    for (int i = 0; i < 50; i++) {
        dJointAddPistonForce(j, 0.2);
        dWorldStep(w, 0.01);
    }
    print_piston("pi_force", j, TRAJ);
    print_body("pi_force_a", a);
    print_body("pi_force_b", b);
    dWorldDestroy(w);
}

// ---- PU --------------------------------------------------------------------

// rate_ok: body 2 does not turn (ODE 0.16's position rate counts its turn
// with the wrong sign).
static void print_pu(const char *name, dJointID j, double tol, int rate_ok)
{
    char buf[96];
    dVector3 v;
    dJointGetPUAnchor(j, v);
    snprintf(buf, sizeof buf, "%s_anchor", name);
    diff_values(buf, tol, v, 3);
    dJointGetPUAxis1(j, v);
    snprintf(buf, sizeof buf, "%s_axis1", name);
    diff_values(buf, tol, v, 3);
    dJointGetPUAxis2(j, v);
    snprintf(buf, sizeof buf, "%s_axis2", name);
    diff_values(buf, tol, v, 3);
    dJointGetPUAxis3(j, v);
    snprintf(buf, sizeof buf, "%s_axis3", name);
    diff_values(buf, tol, v, 3);
    dReal a1, a2;
    dJointGetPUAngles(j, &a1, &a2);
    const dReal s[6] = { dJointGetPUPosition(j), rate_ok ? dJointGetPUPositionRate(j) : 0, a1, a2,
                         dJointGetPUAngle1Rate(j), dJointGetPUAngle2Rate(j) };
    snprintf(buf, sizeof buf, "%s_pos_rate_angles_rates", name);
    diff_values(buf, tol * 10, s, 6);
    const dReal t[2] = { dJointGetPUAngle1(j), dJointGetPUAngle2(j) };
    snprintf(buf, sizeof buf, "%s_angle1_angle2", name);
    diff_values(buf, tol * 10, t, 2);
}

static void pu_two_bodies(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID a = sphere(w, 2, 0, 0, 1), b = sphere(w, 1, 1, 0, 1);
    turn(a, 0, 0, 1, 0.25);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, a, b);
    dJointSetPUAnchor(j, 0.5, 0, 1);
    dJointSetPUAxis1(j, 0, 1, 0);
    dJointSetPUAxis2(j, 0, 0, 1);
    dJointSetPUAxisP(j, 1, 0, 0);
    dBodySetLinearVel(b, 0.2, 0, 0.1);
    dBodySetAngularVel(b, 0, 0.3, 0.4);
    print_pu("pu2_set", j, EXACT, 1);
    for (int i = 0; i < 150; i++) dWorldStep(w, 0.01);
    print_pu("pu2_end", j, TRAJ, 0);
    print_body("pu2_a", a);
    print_body("pu2_b", b);
    dJointAttach(j, b, a);
    print_pu("pu2_swapped", j, TRAJ, 0);
    dWorldDestroy(w);
}

// A pendulum of variable length: the body slides along axis P (towards the
// anchor) and swings about axes 1 and 2 at the anchor; stops on the slide and
// on axis 1.
static void pu_one_body(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere(w, 1, 0, 0, -1);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, b, 0);
    dJointSetPUAnchor(j, 0, 0, 0);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxis3(j, 0, 0, 1);
    dJointSetPUParam(j, dParamLoStop3, -0.2);
    dJointSetPUParam(j, dParamHiStop, 0.3);
    dBodySetLinearVel(b, 0.5, 1.0, 0);
    print_pu("pu1_set", j, EXACT, 1);
    dJointFeedback fb;
    dJointSetFeedback(j, &fb);
    for (int i = 0; i < 150; i++) dWorldStep(w, 0.01);
    print_pu("pu1_end", j, TRAJ, 1);
    print_body("pu1_b", b);
    diff_values("pu1_feedback_f1", 1e-5, fb.f1, 3);
    diff_values("pu1_feedback_t1", 1e-5, fb.t1, 3);
    dWorldDestroy(w);
}

// Attached as (0, b), the body not turning: a motor on the slide against
// gravity along it.
static void pu_reversed(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -2);
    dBodyID b = sphere(w, 1, 0, 0, 0);
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, 0, b);
    dJointSetPUAnchor(j, 0, 0, 0.5);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxisP(j, 0, 0, 1);
    dJointSetPUParam(j, dParamVel3, 0.4);
    dJointSetPUParam(j, dParamFMax3, 5);
    print_pu("pur_set", j, EXACT, 1);
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    print_pu("pur_end", j, TRAJ, 1);
    print_body("pur_b", b);
    dJointSetPUAnchorOffset(j, 0, 0, 0.5, 0, 0, 0.2);
    print_pu("pur_offset", j, EXACT, 1);
    dJointAttach(j, b, 0);
    print_pu("pur_unreversed", j, EXACT, 1);
    dJointSetPUAnchorOffset(j, 0, 0, 0.5, 0, 0, 0.2);
    print_pu("pu_offset", j, EXACT, 1);
    dWorldDestroy(w);
}

// Attached as (0, b) with the anchor at b's centre: the rotation motors of PR
// (group 2) and piston (group 2), and PU's group-1 motor (on the stored axis
// 1: the user's axis 2), each turning the body; stop and motor senses as
// ODE's. The PU's axis P getters are left out (ODE's turns with the body).
static void reversed_rotation_motors(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b[3];
    for (int k = 0; k < 3; k++) b[k] = sphere(w, 1, k, 0, 0);
    dJointID pr = dJointCreatePR(w, 0), pi = dJointCreatePiston(w, 0), pu = dJointCreatePU(w, 0);
    dJointAttach(pr, 0, b[0]);
    dJointSetPRAnchor(pr, 0, 0, 0);
    dJointSetPRAxis1(pr, 0, 1, 0);
    dJointSetPRAxis2(pr, 1, 0, 0);
    dJointSetPRParam(pr, dParamVel2, 0.5);
    dJointSetPRParam(pr, dParamFMax2, 10);
    dJointSetPRParam(pr, dParamHiStop2, 0.3);
    dJointAttach(pi, 0, b[1]);
    dJointSetPistonAnchor(pi, 1, 0, 0);
    dJointSetPistonAxis(pi, 0, 0, 1);
    dJointSetPistonParam(pi, dParamVel2, -0.5);
    dJointSetPistonParam(pi, dParamFMax2, 10);
    dJointSetPistonParam(pi, dParamLoStop2, -0.3);
    dJointAttach(pu, 0, b[2]);
    dJointSetPUAnchor(pu, 2, 0, 0);
    dJointSetPUAxis1(pu, 1, 0, 0);
    dJointSetPUAxis2(pu, 0, 1, 0);
    dJointSetPUAxisP(pu, 0, 0, 1);
    dJointSetPUParam(pu, dParamVel, 0.5);
    dJointSetPUParam(pu, dParamFMax, 10);
    dJointSetPUParam(pu, dParamHiStop, 0.3);
    for (int i = 0; i < 100; i++) dWorldStep(w, 0.01);
    const dReal v[4] = { dJointGetPRAngle(pr), dJointGetPRAngleRate(pr), dJointGetPistonAngle(pi),
                         dJointGetPistonAngleRate(pi) };
    diff_values("reversed_motors_pr_piston_angles", TRAJ, v, 4);
    dReal a1, a2;
    dJointGetPUAngles(pu, &a1, &a2);
    const dReal u[4] = { a1, a2, dJointGetPUAngle1Rate(pu), dJointGetPUAngle2Rate(pu) };
    diff_values("reversed_motors_pu_angles", TRAJ, u, 4);
    print_body("reversed_motors_pr", b[0]);
    print_body("reversed_motors_piston", b[1]);
    print_body("reversed_motors_pu", b[2]);
    dWorldDestroy(w);
}

// Getters against known poses: the joints set up between turned bodies (and
// with one body, both orders), then the bodies moved and turned by hand and
// given velocities. Exact up to rounding. A reversed PU's axis P and position
// are printed only before the move (ODE's axis P turns with the body there).
static void move_bodies(dBodyID a, dBodyID b)
{
    dQuaternion q;
    dQFromAxisAndAngle(q, 0.3, -0.5, 0.8, 0.4);
    dBodySetQuaternion(a, q);
    dBodySetPosition(a, 0.1, 0.25, -0.2);
    dBodySetLinearVel(a, 0.3, -0.2, 0.1);
    dBodySetAngularVel(a, -0.4, 0.6, 0.2);
    if (b) {
        dQFromAxisAndAngle(q, -0.6, 0.2, 0.3, 0.7);
        dBodySetQuaternion(b, q);
        dBodySetPosition(b, 0.9, 1.1, 0.3);
        dBodySetLinearVel(b, -0.1, 0.5, 0.2);
        dBodySetAngularVel(b, 0.3, -0.1, 0.5);
    }
}

static void posed_getters(void)
{
    for (int order = 0; order < 3; order++) {   // (a, b), (a, 0), (0, a)
        dWorldID w = dWorldCreate();
        dBodyID a = sphere(w, 1, 0, 0, 0), b = order ? 0 : sphere(w, 1, 1, 1, 0);
        turn(a, 1, 0, 0, 0.5);
        if (b) turn(b, 0, 1, 0, -0.3);
        dJointID pr = dJointCreatePR(w, 0), pi = dJointCreatePiston(w, 0), pu = dJointCreatePU(w, 0);
        dJointID js[3] = { pr, pi, pu };
        for (int k = 0; k < 3; k++) {
            if (order == 2) dJointAttach(js[k], 0, a);
            else dJointAttach(js[k], a, b);
        }
        dJointSetPRAnchor(pr, 0.5, 0.5, 0);
        dJointSetPRAxis1(pr, 1, 1, 0);
        dJointSetPRAxis2(pr, 0, 0, 1);
        dJointSetPistonAnchor(pi, 0.5, 0.5, 0);
        dJointSetPistonAxis(pi, 1, 1, 0);
        dJointSetPUAnchor(pu, 0.5, 0.5, 0);
        dJointSetPUAxis1(pu, 0, 0, 1);
        // A unit axis: ODE keeps a world-frame axis unnormalised, this library not.
        dJointSetPUAxis2(pu, 0.70710678118654752, -0.70710678118654752, 0);
        dJointSetPUAxisP(pu, 1, 1, 0);
        char name[64];
        snprintf(name, sizeof name, "posed%d_pr_set", order);
        print_pr(name, pr, EXACT);
        snprintf(name, sizeof name, "posed%d_piston_set", order);
        print_piston(name, pi, EXACT);
        snprintf(name, sizeof name, "posed%d_pu_set", order);
        print_pu(name, pu, EXACT, 1);
        move_bodies(a, b);
        snprintf(name, sizeof name, "posed%d_pr_moved", order);
        print_pr(name, pr, EXACT);
        snprintf(name, sizeof name, "posed%d_piston_moved", order);
        print_piston(name, pi, EXACT);
        if (order < 2) {
            snprintf(name, sizeof name, "posed%d_pu_moved", order);
            print_pu(name, pu, EXACT, b == 0);
        } else {
            dReal a1, a2;
            dJointGetPUAngles(pu, &a1, &a2);
            const dReal v[6] = { a1, a2, dJointGetPUAngle1(pu), dJointGetPUAngle2(pu),
                                 dJointGetPUAngle1Rate(pu), dJointGetPUAngle2Rate(pu) };
            diff_values("posed2_pu_moved_angles", EXACT * 10, v, 6);
        }
        dWorldDestroy(w);
    }
}

static void params(void)
{
    dWorldID w = dWorldCreate();
    dJointID pr = dJointCreatePR(w, 0), pu = dJointCreatePU(w, 0), pi = dJointCreatePiston(w, 0);
    dJointSetPRParam(pr, dParamVel2, 3);
    dJointSetPRParam(pr, dParamLoStop, -1);
    dJointSetPUParam(pu, dParamVel, 1);
    dJointSetPUParam(pu, dParamVel2, 2);
    dJointSetPUParam(pu, dParamVel3, 3);
    dJointSetPistonParam(pi, dParamHiStop2, 0.5);
    dJointSetPistonParam(pi, dParamFMax, 4);
    const dReal v[9] = { dJointGetPRParam(pr, dParamVel), dJointGetPRParam(pr, dParamVel2),
                         dJointGetPRParam(pr, dParamLoStop), dJointGetPUParam(pu, dParamVel),
                         dJointGetPUParam(pu, dParamVel2), dJointGetPUParam(pu, dParamVel3),
                         dJointGetPistonParam(pi, dParamHiStop2),
                         dJointGetPistonParam(pi, dParamFMax),
                         dJointGetPistonParam(pi, dParamCFM2) };
    diff_values("params_routed", EXACT, v, 9);
    dWorldDestroy(w);
}

int main(void)
{
    dInitODE();
    pr_two_bodies();
    pr_one_body();
    pr_reversed();
    pr_reversed_torque();
    piston_two_bodies();
    piston_one_body();
    piston_reversed();
    piston_offsets();
    piston_force();
    pu_two_bodies();
    pu_one_body();
    pu_reversed();
    reversed_rotation_motors();
    posed_getters();
    params();
    dCloseODE();
    return 0;
}
