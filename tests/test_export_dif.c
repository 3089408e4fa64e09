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

static dBodyID make_body(dWorldID w, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 2, 3, 0.4 + x);
    dBodySetRotation(b, R);
    return b;
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

// Every joint type of the library is named; the contact's surface cannot be
// read back, so it is written as ODE writes a type it has no printer for.
static int test_every_joint_type_is_named(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = make_body(w, 0, 0, 0);
    dBodyID b2 = make_body(w, 1, 0, 0);
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.normal[2] = 1;
    dJointID j[9] = { dJointCreateBall(w, 0), dJointCreateHinge(w, 0), dJointCreateSlider(w, 0),
                      dJointCreateContact(w, 0, &c), dJointCreateUniversal(w, 0),
                      dJointCreateHinge2(w, 0), dJointCreateFixed(w, 0), dJointCreateNull(w, 0),
                      dJointCreateAMotor(w, 0) };
    for (int i = 0; i < 9; i++) dJointAttach(j[i], b1, b2);

    export_world(w, "");

    const char *names[9] = { "ball", "hinge", "slider", "contact", "universal", "ODE_hinge2",
                             "fixed", "null", "ODE_angular_motor" };
    for (int i = 0; i < 9; i++) {
        char s[64];
        snprintf(s, sizeof s, "= dynamics.%s_joint {", names[i]);
        CHECK(count(s) == 1);
    }
    CHECK(count("\tbody = {body[1],body[0]}\n") == 9);
    CHECK(count("\tunknown joint\n") == 2);   // contact and null, as ODE
    CHECK(count("\tlimit1 = {") == 3);        // universal, hinge-2, angular motor
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
    for (int attach = 0; attach < 3; attach++) {
        dJointID j[9] = { dJointCreateBall(w, 0), dJointCreateHinge(w, 0),
                          dJointCreateSlider(w, 0), dJointCreateContact(w, 0, &c),
                          dJointCreateUniversal(w, 0), dJointCreateHinge2(w, 0),
                          dJointCreateFixed(w, 0), dJointCreateNull(w, 0),
                          dJointCreateAMotor(w, 0) };
        for (int i = 0; i < 9; i++) {
            if (attach == 1) dJointAttach(j[i], b, 0);
            if (attach == 2) dJointAttach(j[i], 0, b);
        }
    }
    dJointSetAMotorNumAxes(dJointCreateAMotor(w, 0), 2);

    export_world(w, "");

    CHECK(test_captured_count() == 0);
    CHECK(count("nan") == 0);
    CHECK(count(" = dynamics.") == 1 + 1 + 28);
    CHECK(count("\tbody = {}\n") == 10);
    CHECK(count("\tbody = {body[0]}\n") == 18);
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
    TEST_CASE(test_geoms_on_bodies_are_written_with_their_sizes),
    TEST_CASE(test_every_joint_type_is_named),
    TEST_CASE(test_joints_with_fewer_bodies_are_written_quietly),
    TEST_CASE(test_bad_arguments_are_reported_and_nothing_is_written),
    TEST_END
};
