// SPDX-License-Identifier: BSD-3-Clause
//
// test_export_dif.c -- dWorldExportDIF: the text is read back and its values
// compared with the world's, computed independently here (the layout itself
// is compared with the reference ODE's in tests/reference/diff_export_dif.c).

#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TEXT_MAX 65536

static char text[TEXT_MAX];

// Export w with prefix into `text`.
static void export_world(dWorldID w, const char *prefix)
{
    FILE *f = tmpfile();
    dWorldExportDIF(w, f, prefix);
    rewind(f);
    size_t n = fread(text, 1, TEXT_MAX - 1, f);
    text[n] = 0;
    fclose(f);
}

// How often s occurs in the text.
static int count(const char *s)
{
    int n = 0;
    for (const char *p = strstr(text, s); p; p = strstr(p + 1, s)) n++;
    return n;
}

// Read the k-th (from 0) `key = {a,b,c...}` or `key = a` after `from` in the
// text: up to n numbers into v; returns how many were read.
static int read_values(const char *from, const char *key, int k, double *v, int n)
{
    const char *p = strstr(text, from);
    char pattern[64];
    snprintf(pattern, sizeof pattern, "\t%s = ", key);
    for (int i = 0; p && i <= k; i++) {
        p = strstr(p, pattern);
        if (p && i < k) p++;
    }
    if (!p) return 0;
    p += strlen(pattern);
    if (*p == '{') p++;
    int got = 0;
    while (got < n) {
        char *end;
        double x = strtod(p, &end);
        if (end == p) break;
        v[got++] = x;
        p = end;
        if (*p != ',') break;
        p++;
    }
    return got;
}

// The largest difference between the k-th `key` after `from` and the n
// numbers expect; infinity if fewer were read.
static double deviation(const char *from, const char *key, int k, const dReal *expect, int n)
{
    double v[4], worst = 0;
    if (read_values(from, key, k, v, n) != n) return INFINITY;
    for (int i = 0; i < n; i++)
        if (!(fabs(v[i] - expect[i]) <= worst)) worst = fabs(v[i] - expect[i]);
    return worst;
}

#define VALUES_TOL TOL(1e-12, 2e-5)
#define CHECK_VALUES(from, key, k, expect, n) \
    CHECK_NEAR(deviation(from, key, k, expect, n), 0, VALUES_TOL)

static dBodyID make_body(dWorldID w, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 2, 3, 0.4 + x);
    dBodySetRotation(b, R);
    return b;
}

// Turn body b by angle about a world axis through a world point.
static void turn_body(dBodyID b, const dReal *point, const dReal *axis, dReal angle)
{
    dMatrix3 R, Rn;
    dRFromAxisAndAngle(R, axis[0], axis[1], axis[2], angle);
    dMultiply0(Rn, R, dBodyGetRotation(b), 3, 3, 3);
    for (int i = 0; i < 3; i++) Rn[i * 4 + 3] = 0;
    dVector3 d, nd;
    const dReal *p = dBodyGetPosition(b);
    for (int i = 0; i < 3; i++) d[i] = p[i] - point[i];
    dMultiply0_331(nd, R, d);
    dBodySetRotation(b, Rn);
    dBodySetPosition(b, point[0] + nd[0], point[1] + nd[1], point[2] + nd[2]);
}

// Move body b by d along world direction dir.
static void slide_body(dBodyID b, const dReal *dir, dReal d)
{
    const dReal *p = dBodyGetPosition(b);
    dBodySetPosition(b, p[0] + d * dir[0], p[1] + d * dir[1], p[2] + d * dir[2]);
}

static int test_header_world_and_bodies_are_written_in_order(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.5);
    dWorldSetERP(w, 0.25);
    dBodyID b1 = make_body(w, 1, 2, 3);
    dBodyID b2 = make_body(w, -4, 5, 6);
    dBodySetLinearVel(b2, 0.5, 0, -1);

    export_world(w, "");

    static const char head[] = "-- Dynamics Interchange Format v0.1\n\nworld = dynamics.world {\n";
    CHECK(strncmp(text, head, strlen(head)) == 0);
    double v[4];
    CHECK(read_values("world =", "gravity", 0, v, 3) == 3);
    CHECK_VEC(v, 0, 0, -9.5, 1e-6);
    CHECK(read_values("world =", "ERP", 0, v, 1) == 1);
    CHECK_NEAR(v[0], 0.25, 1e-6);
    CHECK(count("= dynamics.body {") == 2);
    // Newest first, as ODE lists them.
    CHECK(read_values("body[0] =", "pos", 0, v, 3) == 3);
    CHECK_VEC(v, -4, 5, 6, 1e-6);
    CHECK(read_values("body[0] =", "lvel", 0, v, 3) == 3);
    CHECK_VEC(v, 0.5, 0, -1, 1e-6);
    CHECK(read_values("body[1] =", "q", 0, v, 4) == 4);
    const dReal *q = dBodyGetQuaternion(b1);
    for (int i = 0; i < 4; i++) CHECK_NEAR(v[i], q[i], TOL(1e-14, 1e-6));
    dWorldDestroy(w);
    return 0;
}

static int test_prefix_names_every_top_level_object(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 1);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);

    export_world(w, "my_");

    CHECK(strstr(text, "my_world = dynamics.world {") != NULL);
    CHECK(strstr(text, "my_body = {}\nmy_body[0] = dynamics.body {\n\tworld = my_world,") != NULL);
    CHECK(strstr(text, "my_joint[0] = dynamics.ball_joint {\n\tworld = my_world,\n"
                       "\tbody = {my_body[0]}\n") != NULL);
    dWorldDestroy(w);
    return 0;
}

// Anchors and axes are written in the frames of the bodies they are fixed to.
static int test_hinge_anchor_and_axis_are_written_in_body_frames(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 1, 0, 0);
    dBodyID b2 = make_body(w, 2, 0, 0);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetHingeAnchor(j, 1.5, 0.5, 0.25);
    dJointSetHingeAxis(j, 0, 0.6, 0.8);
    dJointSetHingeParam(j, dParamHiStop, 0.5);

    export_world(w, "");

    dVector3 a1, a2, ax;
    dBodyGetPosRelPoint(b1, 1.5, 0.5, 0.25, a1);
    dBodyGetPosRelPoint(b2, 1.5, 0.5, 0.25, a2);
    dBodyVectorFromWorld(b1, 0, 0.6, 0.8, ax);
    double v[4];
    CHECK(read_values("joint[0] =", "anchor1", 0, v, 3) == 3);
    CHECK_VEC(v, a1[0], a1[1], a1[2], TOL(1e-12, 1e-5));
    CHECK(read_values("joint[0] =", "anchor2", 0, v, 3) == 3);
    CHECK_VEC(v, a2[0], a2[1], a2[2], TOL(1e-12, 1e-5));
    CHECK(read_values("joint[0] =", "axis1", 0, v, 3) == 3);
    CHECK_VEC(v, ax[0], ax[1], ax[2], TOL(1e-12, 1e-5));
    CHECK(read_values("joint[0] =", "low_stop", 0, v, 1) == 1);
    CHECK(strstr(text, "low_stop = -inf,") != NULL);
    CHECK(read_values("joint[0] =", "high_stop", 0, v, 1) == 1);
    CHECK_NEAR(v[0], 0.5, 1e-6);
    dWorldDestroy(w);
    return 0;
}

// A hinge turned by 0.3 about its axis: qrel is still the rest orientation,
// conj(q1) q2 as it was when the axis was set.
static int test_hinge_rest_orientation_survives_a_turn(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 1, 0, 0);
    dBodyID b2 = make_body(w, 1, 0, 0);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetHingeAnchor(j, 1, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dQuaternion rest;
    dQMultiply1(rest, dBodyGetQuaternion(b1), dBodyGetQuaternion(b2));
    dMatrix3 R, R2;
    dRFromAxisAndAngle(R, 0, 0, 1, 0.3);
    dMultiply0(R2, R, dBodyGetRotation(b2), 3, 3, 3);
    for (int i = 0; i < 3; i++) R2[i * 4 + 3] = 0;
    dBodySetRotation(b2, R2);
    CHECK_NEAR(fabs(dJointGetHingeAngle(j)), 0.3, TOL(1e-12, 1e-5));

    export_world(w, "");

    double v[4];
    CHECK(read_values("joint[0] =", "qrel", 0, v, 4) == 4);
    const double sign = v[0] * rest[0] < 0 ? -1 : 1;
    for (int i = 0; i < 4; i++) CHECK_NEAR(sign * v[i], rest[i], TOL(1e-12, 1e-5));
    dWorldDestroy(w);
    return 0;
}

// The body-frame values a PR joint keeps are those of the pose it was set
// in: sliding body 1 and turning body 2 about the rotation axis at the
// anchor change none of them.
static int test_pr_is_written_as_it_was_set(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 1, 0, 0), b2 = make_body(w, 2, 0.5, 0);
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, b1, b2);
    const dReal anchor[3] = { 1.5, 0.25, 0.5 }, axp[3] = { 0, 0.6, 0.8 }, axr[3] = { 1, 0, 0 };
    dJointSetPRAnchor(j, anchor[0], anchor[1], anchor[2]);
    dJointSetPRAxis1(j, axp[0], axp[1], axp[2]);
    dJointSetPRAxis2(j, axr[0], axr[1], axr[2]);
    dJointSetPRParam(j, dParamHiStop2, 0.5);
    dVector3 offset, anchor2, axr1, axr2, axp1;
    dBodyGetPosRelPoint(b1, anchor[0], anchor[1], anchor[2], offset);
    dBodyGetPosRelPoint(b2, anchor[0], anchor[1], anchor[2], anchor2);
    dBodyVectorFromWorld(b1, axr[0], axr[1], axr[2], axr1);
    dBodyVectorFromWorld(b2, axr[0], axr[1], axr[2], axr2);
    dBodyVectorFromWorld(b1, axp[0], axp[1], axp[2], axp1);
    dQuaternion qrel;
    dQMultiply1(qrel, dBodyGetQuaternion(b1), dBodyGetQuaternion(b2));
    slide_body(b1, axp, 0.3);
    turn_body(b2, anchor, axr, 0.4);
    CHECK_NEAR(dJointGetPRPosition(j), 0.3, TOL(1e-12, 1e-5));
    CHECK_NEAR(fabs(dJointGetPRAngle(j)), 0.4, TOL(1e-12, 1e-5));

    export_world(w, "");

    CHECK(strstr(text, "joint[0] = dynamics.PR_joint {\n\tworld = world,\n"
                       "\tbody = {body[1],body[0]}\n") != NULL);
    CHECK_VALUES("joint[0] =", "anchor2", 0, anchor2, 3);
    CHECK_VALUES("joint[0] =", "axisR1", 0, axr1, 3);
    CHECK_VALUES("joint[0] =", "axisR2", 0, axr2, 3);
    CHECK_VALUES("joint[0] =", "axisP1", 0, axp1, 3);
    CHECK_VALUES("joint[0] =", "qrel", 0, qrel, 4);
    CHECK_VALUES("joint[0] =", "offset", 0, offset, 3);
    // limit1 is the slide's, limit2 the rotation's.
    CHECK(strstr(text, "\tlimit1 = {\n\t\tlow_stop = -inf,\n\t\thigh_stop = inf,\n") != NULL);
    CHECK(strstr(text, "\tlimit2 = {\n\t\tlow_stop = -inf,\n\t\thigh_stop = 0.5,\n") != NULL);
    dWorldDestroy(w);
    return 0;
}

// A PU joint keeps anchor1 on body 1 where it was set, off the anchor on body
// 2 by the slide, and axis P in body 1's frame; attached as (0, b) ODE keeps
// axis P in b's frame as b was when it was set, though b turned since.
static int test_pu_is_written_as_it_was_set(void)
{
    dWorldID w = dWorldCreate();
    const dReal anchor[3] = { 1.5, 0.25, 0.5 }, x[3] = { 1, 0, 0 }, y[3] = { 0, 0.6, 0.8 },
                p[3] = { 0.8, 0, 0.6 };
    for (int rev = 0; rev < 2; rev++) {
        dBodyID b1 = make_body(w, 1, 0, 0), b2 = make_body(w, 2, 0.5, 0);
        dBodyID b = rev ? b2 : b1;
        dJointID j = dJointCreatePU(w, 0);
        if (rev) dJointAttach(j, 0, b2);
        else dJointAttach(j, b1, b2);
        dJointSetPUAnchor(j, anchor[0], anchor[1], anchor[2]);
        dJointSetPUAxis1(j, x[0], x[1], x[2]);
        dJointSetPUAxis2(j, y[0], y[1], y[2]);
        dJointSetPUAxisP(j, p[0], p[1], p[2]);
        dVector3 anchor1, axisp;
        dBodyGetPosRelPoint(b, anchor[0], anchor[1], anchor[2], anchor1);
        dBodyVectorFromWorld(b, p[0], p[1], p[2], axisp);
        // Turn b about the axis fixed to it (axis 1, or axis 2 as (0, b)),
        // then slide it.
        turn_body(b, anchor, rev ? y : x, 0.3);
        dVector3 axw;
        dJointGetPUAxisP(j, axw);
        slide_body(b, rev ? p : axw, 0.2);
        CHECK_NEAR(dJointGetPUPosition(j), rev ? -0.2 : 0.2, TOL(1e-12, 1e-5));

        export_world(w, "");

        CHECK(count("dynamics.PU_joint {") == rev + 1);
        CHECK_VALUES("joint[0] =", "anchor1", 0, anchor1, 3);
        CHECK_VALUES("joint[0] =", "axisP", 0, axisp, 3);
        CHECK(strstr(text, "\tlimit3 = {\n") != NULL);   // the slide's
    }
    dWorldDestroy(w);
    return 0;
}

// A piston keeps each body's anchor, the axis in both frames and the rest
// orientation as set, however far the bodies slid and turned along the axis.
static int test_piston_is_written_as_it_was_set(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 1, 0, 0), b2 = make_body(w, 2, 0.5, 0);
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, b1, b2);
    const dReal anchor[3] = { 1.5, 0.25, 0.5 }, axis[3] = { 0.48, 0.6, 0.64 };
    dJointSetPistonAnchor(j, anchor[0], anchor[1], anchor[2]);
    dJointSetPistonAxis(j, axis[0], axis[1], axis[2]);
    dVector3 a1, a2, ax1, ax2;
    dBodyGetPosRelPoint(b1, anchor[0], anchor[1], anchor[2], a1);
    dBodyGetPosRelPoint(b2, anchor[0], anchor[1], anchor[2], a2);
    dBodyVectorFromWorld(b1, axis[0], axis[1], axis[2], ax1);
    dBodyVectorFromWorld(b2, axis[0], axis[1], axis[2], ax2);
    dQuaternion qrel;
    dQMultiply1(qrel, dBodyGetQuaternion(b1), dBodyGetQuaternion(b2));
    // Full turns: the rest orientation keeps its sign, which no angle tells.
    turn_body(b1, anchor, axis, 2 * M_PI + 0.5);
    slide_body(b2, axis, -0.25);

    export_world(w, "");

    CHECK_VALUES("joint[0] =", "anchor1", 0, a1, 3);
    CHECK_VALUES("joint[0] =", "anchor2", 0, a2, 3);
    CHECK_VALUES("joint[0] =", "axis1", 0, ax1, 3);
    CHECK_VALUES("joint[0] =", "axis2", 0, ax2, 3);
    CHECK_VALUES("joint[0] =", "qrel", 0, qrel, 4);
    dWorldDestroy(w);
    return 0;
}

// The linear motor writes each axis's rel as given and the axis in that
// frame, except that a body-2 axis without body 2 is written as ODE keeps it:
// rel 1, in body 1's frame.
static int test_lmotor_axes_are_written_in_the_frames_rel_names(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 1, 0, 0), b2 = make_body(w, 2, 0.5, 0);
    const dReal y[3] = { 0, 1, 0 }, z[3] = { 0, 0, 1 };
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetLMotorNumAxes(j, 3);
    dJointSetLMotorAxis(j, 0, 2, 0, 0, 2);
    dJointSetLMotorAxis(j, 1, 0, 0, 3, 0);
    dJointSetLMotorAxis(j, 2, 1, 1, 0, 0);
    dJointSetLMotorParam(j, dParamVel3, 1.5);
    dVector3 ax0, ax2;
    dBodyVectorFromWorld(b2, 0, 0, 1, ax0);
    dBodyVectorFromWorld(b1, 1, 0, 0, ax2);
    turn_body(b1, dBodyGetPosition(b1), z, 0.7);   // the axes turn with their bodies
    dJointID one = dJointCreateLMotor(w, 0);
    dJointAttach(one, b1, 0);
    dJointSetLMotorNumAxes(one, 1);
    dJointSetLMotorAxis(one, 0, 2, 0, 0, 1);
    dVector3 ax_one;
    dBodyVectorFromWorld(b1, 0, 0, 1, ax_one);

    export_world(w, "");

    CHECK(count("= dynamics.ODE_linear_motor_joint {") == 2);
    CHECK(strstr(text, "joint[1] = dynamics.ODE_linear_motor_joint {\n\tworld = world,\n"
                       "\tbody = {body[1],body[0]}\n\tnum = 3,\n\trel = {2,0,1},\n") != NULL);
    CHECK_VALUES("joint[1] =", "axis1", 0, ax0, 3);
    CHECK_VALUES("joint[1] =", "axis2", 0, y, 3);
    CHECK_VALUES("joint[1] =", "axis3", 0, ax2, 3);
    const dReal vel = 1.5;
    CHECK_VALUES("joint[1] =", "vel", 0, &vel, 1);
    CHECK(strstr(text, "\tmotor3 = {\n\t\tvel = 1.5,\n") != NULL);
    CHECK(strstr(text, "joint[0] = dynamics.ODE_linear_motor_joint {\n\tworld = world,\n"
                       "\tbody = {body[1]}\n\tnum = 1,\n\trel = {1,0,0},\n") != NULL);
    CHECK_VALUES("joint[0] =", "axis1", 0, ax_one, 3);
    dWorldDestroy(w);
    return 0;
}

// A contact joint writes its dContact: the point, then mu and the surface
// coefficients its mode uses, the pyramid bits as friction_approximation,
// and fdir1.
static int test_contact_is_written_with_its_surface(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 1, 0, 0);
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.pos[0] = 1;
    c.geom.pos[1] = 2;
    c.geom.pos[2] = 3;
    c.geom.normal[2] = 1;
    c.geom.depth = 0.125;
    c.surface.mu = 0.5;
    c.surface.mu2 = 0.25;
    c.surface.bounce = 0.75;
    c.surface.bounce_vel = 0.1;
    c.surface.soft_erp = 0.2;
    c.surface.soft_cfm = 0.001;
    c.surface.motion1 = 1.5;
    c.surface.motion2 = -2.5;
    c.surface.slip1 = 0.01;
    c.surface.slip2 = 0.02;
    c.fdir1[0] = 1;
    dJointAttach(dJointCreateContact(w, 0, &c), b, 0);
    c.surface.mode = dContactMu2 | dContactFDir1 | dContactBounce | dContactSoftERP |
                     dContactSoftCFM | dContactMotion1 | dContactMotion2 | dContactSlip1 |
                     dContactSlip2 | dContactApprox1;
    dJointAttach(dJointCreateContact(w, 0, &c), 0, b);
    c.surface.mode = dContactApprox1_2;
    dJointAttach(dJointCreateContact(w, 0, &c), b, 0);

    export_world(w, "");

    CHECK(count("= dynamics.contact_joint {") == 3);
    CHECK(count("unknown joint") == 0);
    // Newest first: the Approx1_2 contact, the full one, the plain one.
    CHECK(strstr(text, "joint[0] = dynamics.contact_joint {\n\tworld = world,\n"
                       "\tbody = {body[0]}\n\tpos = {1,2,3},\n\tnormal = {0,0,1},\n"
                       "\tdepth = 0.125,\n\tmu = 0.5,\n\tfriction_approximation = 2,\n}\n") !=
          NULL);
    CHECK(strstr(text, "\tmu = 0.5,\n\tmu2 = 0.25,\n\tbounce = 0.75,\n\tbounce_vel = 0.1,\n"
                       "\tsoft_ERP = 0.2,\n\tsoft_CFM = 0.001,\n\tmotion1 = 1.5,\n"
                       "\tmotion2 = -2.5,\n\tslip1 = 0.01,\n\tslip2 = 0.02,\n"
                       "\tfriction_approximation = 3,\n\tfdir1 = {1,0,0},\n}\n") != NULL);
    CHECK(strstr(text, "joint[2] = dynamics.contact_joint {\n\tworld = world,\n"
                       "\tbody = {body[0]}\n\tpos = {1,2,3},\n\tnormal = {0,0,1},\n"
                       "\tdepth = 0.125,\n\tmu = 0.5,\n}\n") != NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_geoms_on_bodies_are_written_with_their_sizes(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dGeomID s = dCreateSphere(0, 0.75);
    dGeomSetBody(s, b);
    dGeomID x = dCreateBox(0, 1, 2, 3);
    dGeomSetBody(x, b);
    dGeomSetCategoryBits(x, 4);

    export_world(w, "");

    CHECK(strstr(text, "\tgeometry = {\n") != NULL);
    CHECK(strstr(text, "type = \"sphere\",\n\t\t\tradius = 0.75,\n") != NULL);
    CHECK(strstr(text, "category_bits = 4\n\t\t\ttype = \"box\",\n"
                       "\t\t\tsides = {1,2,3},\n") != NULL);
    dGeomDestroy(s);
    dGeomDestroy(x);
    dWorldDestroy(w);
    return 0;
}

// Every joint type of ODE 0.16 is named as ODE names it; the null joint and
// the types ODE has no printer for are written as `unknown joint`.
static int test_every_joint_type_is_named(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 0, 0, 0);
    dBodyID b2 = make_body(w, 1, 0, 0);
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.normal[2] = 1;
    enum { N = 17 };
    dJointID j[N] = { dJointCreateBall(w, 0), dJointCreateHinge(w, 0),
                      dJointCreateSlider(w, 0), dJointCreateContact(w, 0, &c),
                      dJointCreateUniversal(w, 0), dJointCreateHinge2(w, 0),
                      dJointCreateFixed(w, 0), dJointCreateNull(w, 0),
                      dJointCreateAMotor(w, 0), dJointCreateLMotor(w, 0),
                      dJointCreatePR(w, 0), dJointCreatePU(w, 0),
                      dJointCreatePiston(w, 0), dJointCreatePlane2D(w, 0),
                      dJointCreateDBall(w, 0), dJointCreateDHinge(w, 0),
                      dJointCreateTransmission(w, 0) };
    for (int i = 0; i < N; i++) dJointAttach(j[i], b1, b2);

    export_world(w, "");

    const char *names[N] = { "ball", "hinge", "slider", "contact", "universal", "ODE_hinge2",
                             "fixed", "null", "ODE_angular_motor", "ODE_linear_motor", "PR",
                             "PU", "piston", "unknown", "unknown", "unknown", "unknown" };
    for (int i = 0; i < N; i++) {
        char s[64];
        snprintf(s, sizeof s, "= dynamics.%s_joint {", names[i]);
        CHECK(count(s) == (i < 13 ? 1 : 4));
    }
    CHECK(count("\tbody = {body[1],body[0]}\n") == N);
    CHECK(count("\tunknown joint\n") == 5);   // null and the four ODE has no printer for
    // universal, hinge-2, angular and linear motor, PR, PU, piston
    CHECK(count("\tlimit1 = {") == 7);
    CHECK(count("\tlimit3 = {") == 3);        // angular and linear motor, PU
    CHECK(count("\tlimit = {") == 2);         // hinge, slider
    dWorldDestroy(w);
    return 0;
}

// Joints attached to nothing, or to one body, are written without any
// complaint from the getters the exporter uses.
static int test_joints_with_fewer_bodies_are_written_quietly(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID b = make_body(w, 0, 0, 0);
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.normal[2] = 1;
    enum { N = 13 };
    for (int attach = 0; attach < 3; attach++) {
        dJointID j[N] = { dJointCreateBall(w, 0), dJointCreateHinge(w, 0),
                          dJointCreateSlider(w, 0), dJointCreateContact(w, 0, &c),
                          dJointCreateUniversal(w, 0), dJointCreateHinge2(w, 0),
                          dJointCreateFixed(w, 0), dJointCreateNull(w, 0),
                          dJointCreateAMotor(w, 0), dJointCreateLMotor(w, 0),
                          dJointCreatePR(w, 0), dJointCreatePU(w, 0),
                          dJointCreatePiston(w, 0) };
        for (int i = 0; i < N; i++) {
            if (attach == 1) dJointAttach(j[i], b, 0);
            if (attach == 2) dJointAttach(j[i], 0, b);
        }
    }
    dJointSetAMotorNumAxes(dJointCreateAMotor(w, 0), 2);
    dJointSetLMotorNumAxes(dJointCreateLMotor(w, 0), 3);

    export_world(w, "");

    CHECK(test_captured_count() == 0);
    CHECK(count("nan") == 0);
    CHECK(count(" = dynamics.") == 1 + 1 + 3 * N + 2);
    CHECK(count("\tbody = {}\n") == N + 2);
    CHECK(count("\tbody = {body[0]}\n") == 2 * N);
    dWorldDestroy(w);
    test_release_reports();
    return 0;
}

static int test_bad_arguments_are_reported_and_nothing_is_written(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    FILE *f = tmpfile();

    dWorldExportDIF(NULL, f, "");
    dWorldExportDIF(w, NULL, "");
    dWorldExportDIF(w, f, NULL);

    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("dWorldExportDIF: world"));
    CHECK(test_captured_contains("dWorldExportDIF: file"));
    CHECK(ftell(f) == 0);
    fclose(f);
    dWorldDestroy(w);
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_header_world_and_bodies_are_written_in_order),
    TEST_CASE(test_prefix_names_every_top_level_object),
    TEST_CASE(test_hinge_anchor_and_axis_are_written_in_body_frames),
    TEST_CASE(test_hinge_rest_orientation_survives_a_turn),
    TEST_CASE(test_pr_is_written_as_it_was_set),
    TEST_CASE(test_pu_is_written_as_it_was_set),
    TEST_CASE(test_piston_is_written_as_it_was_set),
    TEST_CASE(test_lmotor_axes_are_written_in_the_frames_rel_names),
    TEST_CASE(test_contact_is_written_with_its_surface),
    TEST_CASE(test_geoms_on_bodies_are_written_with_their_sizes),
    TEST_CASE(test_every_joint_type_is_named),
    TEST_CASE(test_joints_with_fewer_bodies_are_written_quietly),
    TEST_CASE(test_bad_arguments_are_reported_and_nothing_is_written),
    TEST_END
};
