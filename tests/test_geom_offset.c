// SPDX-License-Identifier: BSD-3-Clause
//
// test_geom_offset.c -- geom offsets (ODE 0.16): an offset geom's pose is its
// body's composed with the offset, also while the body moves in a world;
// setting the geom's pose moves the body; world-frame setters; clearing;
// detaching and re-attaching; the same contacts as the same shape placed by a
// geometry transform; offset geoms and transforms on one body; bad input.

#include "test.h"

#include <math.h>
#include <string.h>

static const double EPS = TOL(1e-12, 1e-5);

// A body at p, turned by angle about (ax, ay, az).
static dBodyID posed_body(dWorldID w, dReal x, dReal y, dReal z, dReal ax, dReal ay, dReal az,
                          dReal angle)
{
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, ax, ay, az, angle);
    dBodySetRotation(b, R);
    return b;
}

// The pose body (bp, bR) composed with the offset (op, oR), computed here.
static void compose(const dReal *bp, const dReal *bR, const dReal *op, const dReal *oR,
                    dVector3 p, dMatrix3 R)
{
    for (int i = 0; i < 3; i++) {
        p[i] = bp[i];
        for (int k = 0; k < 3; k++) p[i] += bR[4 * i + k] * op[k];
        for (int j = 0; j < 3; j++) {
            R[4 * i + j] = 0;
            for (int k = 0; k < 3; k++) R[4 * i + j] += bR[4 * i + k] * oR[4 * k + j];
        }
    }
}

static int check_pose(dGeomID g, const dReal *p, const dReal *R)
{
    const dReal *gp = dGeomGetPosition(g), *gR = dGeomGetRotation(g);
    CHECK_VEC(gp, p[0], p[1], p[2], EPS);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(gR[4 * i + j], R[4 * i + j], EPS);
    return 0;
}

// The offset geom is where body and offset put it, also after the body moved.
static int check_follows(dGeomID g)
{
    dBodyID b = dGeomGetBody(g);
    dVector3 p;
    dMatrix3 R;
    compose(dBodyGetPosition(b), dBodyGetRotation(b), dGeomGetOffsetPosition(g),
            dGeomGetOffsetRotation(g), p, R);
    return check_pose(g, p, R);
}

static int test_offset_geom_follows_its_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, 1, 2, 3, 1, 1, 0, REAL(0.7));
    dGeomID g = dCreateBox(0, 1, 2, 3);
    dGeomSetBody(g, b);
    CHECK(!dGeomIsOffset(g));
    dGeomSetOffsetPosition(g, REAL(0.5), -1, REAL(0.25));
    CHECK(dGeomIsOffset(g));
    dMatrix3 oR;
    dRFromAxisAndAngle(oR, 0, 1, 1, REAL(-1.1));
    dGeomSetOffsetRotation(g, oR);
    if (check_follows(g)) return 1;
    // A spinning, flying body: the geom follows every step.
    dBodySetLinearVel(b, 1, -2, REAL(0.5));
    dBodySetAngularVel(b, REAL(0.3), 2, -1);
    for (int i = 0; i < 50; i++) {
        dWorldStep(w, REAL(0.01));
        if (check_follows(g)) return 1;
    }
    // Its bounding box follows too: it is the box's at the composed pose.
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    const dReal *gp = dGeomGetPosition(g), *gR = dGeomGetRotation(g);
    const dReal half[3] = { REAL(0.5), 1, REAL(1.5) };
    for (int i = 0; i < 3; i++) {
        dReal r = 0;
        for (int k = 0; k < 3; k++) r += fabs(gR[4 * i + k]) * half[k];
        CHECK_NEAR(aabb[2 * i], gp[i] - r, TOL(1e-9, 1e-4));
        CHECK_NEAR(aabb[2 * i + 1], gp[i] + r, TOL(1e-9, 1e-4));
    }
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_quaternion_offset_and_getters(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, 0, 0, 1, 0, 0, 1, REAL(0.4));
    dGeomID g = dCreateSphere(0, 1);
    dGeomSetBody(g, b);
    // Without an offset: zero position and identity.
    dVector3 p;
    dMatrix3 R;
    dQuaternion q;
    dGeomCopyOffsetPosition(g, p);
    CHECK_VEC(p, 0, 0, 0, 0);
    dGeomCopyOffsetRotation(g, R);
    CHECK(R[0] == 1 && R[5] == 1 && R[10] == 1 && R[1] == 0 && R[4] == 0);
    dGeomGetOffsetQuaternion(g, q);
    CHECK(q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0);
    // A quaternion offset reads back as itself and as its matrix.
    dQuaternion set;
    dQFromAxisAndAngle(set, 1, -2, REAL(0.5), REAL(2.2));
    dGeomSetOffsetQuaternion(g, set);
    dGeomGetOffsetQuaternion(g, q);
    double sign = q[0] * set[0] < 0 ? -1 : 1;
    for (int i = 0; i < 4; i++) CHECK_NEAR(sign * q[i], set[i], EPS);
    dMatrix3 expect;
    dRfromQ(expect, set);
    dGeomCopyOffsetRotation(g, R);
    for (int i = 0; i < 12; i++) CHECK_NEAR(R[i], expect[i], EPS);
    if (check_follows(g)) return 1;
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// dGeomSetPosition/Rotation/Quaternion on an offset geom move the body.
static int test_setting_the_geom_pose_moves_the_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, 1, 1, 1, 1, 0, 0, REAL(0.3));
    dGeomID g = dCreateCapsule(0, REAL(0.2), 1);
    dGeomSetBody(g, b);
    dGeomSetOffsetPosition(g, 0, 0, 2);
    dGeomSetPosition(g, 5, 6, 7);
    CHECK_VEC(dGeomGetPosition(g), 5, 6, 7, EPS);
    if (check_follows(g)) return 1;
    // A rotation keeps the geom's position and turns the body about it.
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, REAL(1.3));
    R[3] = R[7] = R[11] = NAN;   // the padding is not read
    dGeomSetRotation(g, R);
    CHECK_VEC(dGeomGetPosition(g), 5, 6, 7, EPS);
    const dReal *gR = dGeomGetRotation(g);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(gR[4 * i + j], R[4 * i + j], EPS);
    if (check_follows(g)) return 1;
    dQuaternion q;
    dQFromAxisAndAngle(q, 1, 1, 1, REAL(-0.8));
    dGeomSetQuaternion(g, q);
    CHECK_VEC(dGeomGetPosition(g), 5, 6, 7, EPS);
    dQuaternion got;
    dGeomGetQuaternion(g, got);
    double sign = got[0] * q[0] < 0 ? -1 : 1;
    for (int i = 0; i < 4; i++) CHECK_NEAR(sign * got[i], q[i], EPS);
    if (check_follows(g)) return 1;
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// The world setters choose the offset that puts the geom at a world pose
// without moving the body.
static int test_world_offset_setters(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, -1, 2, REAL(0.5), 2, 1, -1, REAL(0.9));
    dVector3 bp;
    dCopyVector3(bp, dBodyGetPosition(b));
    dGeomID g = dCreateCylinder(0, REAL(0.3), 1);
    dGeomSetBody(g, b);
    dGeomSetOffsetWorldPosition(g, 3, -4, 5);
    CHECK_VEC(dGeomGetPosition(g), 3, -4, 5, EPS);
    CHECK_VEC(dBodyGetPosition(b), bp[0], bp[1], bp[2], 0);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 1, REAL(-2.1));
    dGeomSetOffsetWorldRotation(g, R);
    const dReal *gR = dGeomGetRotation(g);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(gR[4 * i + j], R[4 * i + j], EPS);
    CHECK_VEC(dGeomGetPosition(g), 3, -4, 5, EPS);
    dQuaternion q;
    dQFromAxisAndAngle(q, 0, 1, 0, REAL(0.6));
    dGeomSetOffsetWorldQuaternion(g, q);
    dMatrix3 qR;
    dRfromQ(qR, q);
    gR = dGeomGetRotation(g);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(gR[4 * i + j], qR[4 * i + j], EPS);
    if (check_follows(g)) return 1;
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_clear_detach_and_reattach(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b1 = posed_body(w, 1, 0, 0, 0, 0, 1, REAL(0.5));
    dBodyID b2 = posed_body(w, 0, 4, 0, 1, 0, 0, REAL(-0.5));
    dGeomID g = dCreateBox(0, 1, 1, 1);
    dGeomSetBody(g, b1);
    dGeomSetOffsetPosition(g, 2, 0, 0);
    // Cleared: the geom is at its body's pose again.
    dGeomClearOffset(g);
    CHECK(!dGeomIsOffset(g));
    if (check_pose(g, dBodyGetPosition(b1), dBodyGetRotation(b1))) return 1;
    dGeomClearOffset(g);   // nothing to clear: no effect
    // Detached: the geom stays where the offset put it, without an offset.
    dGeomSetOffsetPosition(g, 2, 0, 0);
    dVector3 p;
    dMatrix3 R;
    dGeomCopyPosition(g, p);
    dGeomCopyRotation(g, R);
    dGeomSetBody(g, 0);
    CHECK(!dGeomIsOffset(g));
    if (check_pose(g, p, R)) return 1;
    dBodySetPosition(b1, 9, 9, 9);
    if (check_pose(g, p, R)) return 1;
    // On another body: at that body's pose, without an offset.
    dGeomSetBody(g, b1);
    dGeomSetOffsetPosition(g, 0, 1, 0);
    dGeomSetBody(g, b2);
    CHECK(!dGeomIsOffset(g));
    if (check_pose(g, dBodyGetPosition(b2), dBodyGetRotation(b2))) return 1;
    dGeomDestroy(g);
    // A destroyed body takes its geoms off; an offset geom keeps its pose.
    g = dCreateSphere(0, 1);
    dGeomSetBody(g, b2);
    dGeomSetOffsetPosition(g, 0, 0, 3);
    dGeomCopyPosition(g, p);
    dBodyDestroy(b2);
    CHECK(dGeomGetBody(g) == 0 && !dGeomIsOffset(g));
    CHECK_VEC(dGeomGetPosition(g), p[0], p[1], p[2], 0);
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Contacts of a shape placed by an offset and the same shape placed by a
// geometry transform on the same body agree exactly (position, normal,
// depth), against a plane, a sphere and a box, both ways round.
static int test_same_contacts_as_a_geometry_transform(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, REAL(0.2), REAL(-0.1), REAL(0.9), 1, 2, 3, REAL(0.4));
    dGeomID offset_box = dCreateBox(0, REAL(0.8), REAL(0.5), REAL(1.2));
    dGeomSetBody(offset_box, b);
    dGeomSetOffsetPosition(offset_box, REAL(0.3), 0, REAL(-0.4));
    dMatrix3 oR;
    dRFromAxisAndAngle(oR, 1, 0, 0, REAL(0.7));
    dGeomSetOffsetRotation(offset_box, oR);

    dGeomID held = dCreateBox(0, REAL(0.8), REAL(0.5), REAL(1.2));
    dGeomSetPosition(held, REAL(0.3), 0, REAL(-0.4));
    dGeomSetRotation(held, oR);
    dGeomID transform = dCreateGeomTransform(0);
    dGeomTransformSetInfo(transform, 1);   // contacts name the held geom
    dGeomTransformSetCleanup(transform, 1);   // and it goes with the transform
    dGeomTransformSetGeom(transform, held);
    dGeomSetBody(transform, b);

    dGeomID others[3] = { dCreatePlane(0, 0, 0, 1, 0), dCreateSphere(0, REAL(0.6)),
                          dCreateBox(0, 2, 2, REAL(0.3)) };
    dGeomSetPosition(others[1], REAL(0.6), 0, REAL(0.1));
    dGeomSetPosition(others[2], 0, REAL(0.2), REAL(0.2));
    for (int k = 0; k < 3; k++) {
        for (int order = 0; order < 2; order++) {
            dContactGeom a[8], t[8];
            int na = order ? dCollide(others[k], offset_box, 8, a, sizeof a[0])
                           : dCollide(offset_box, others[k], 8, a, sizeof a[0]);
            int nt = order ? dCollide(others[k], transform, 8, t, sizeof t[0])
                           : dCollide(transform, others[k], 8, t, sizeof t[0]);
            CHECK(na > 0);
            CHECK(na == nt);
            for (int i = 0; i < na; i++) {
                CHECK_VEC(a[i].pos, t[i].pos[0], t[i].pos[1], t[i].pos[2], EPS);
                CHECK_VEC(a[i].normal, t[i].normal[0], t[i].normal[1], t[i].normal[2], EPS);
                CHECK_NEAR(a[i].depth, t[i].depth, EPS);
            }
        }
    }
    for (int k = 0; k < 3; k++) dGeomDestroy(others[k]);
    dGeomDestroy(transform);
    dGeomDestroy(offset_box);
    dWorldDestroy(w);
    return 0;
}

// Offset geoms, a plain geom and a transform on one body: the body's geom
// list holds them all, and each is where it should be after the body moves.
static int test_offsets_and_transforms_on_one_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = posed_body(w, 0, 0, 0, 0, 1, 0, REAL(0.2));
    dGeomID plain = dCreateSphere(0, 1), off1 = dCreateBox(0, 1, 1, 1),
            off2 = dCreateCapsule(0, REAL(0.1), 1), transform = dCreateGeomTransform(0);
    dGeomID held = dCreateSphere(0, REAL(0.5));
    dGeomSetPosition(held, 0, 0, 1);
    dGeomTransformSetGeom(transform, held);
    dGeomTransformSetCleanup(transform, 1);
    dGeomID all[4] = { plain, off1, off2, transform };
    for (int i = 0; i < 4; i++) dGeomSetBody(all[i], b);
    dGeomSetOffsetPosition(off1, 1, 0, 0);
    dGeomSetOffsetPosition(off2, 0, -1, 0);
    int seen[4] = { 0 }, count = 0;
    for (dGeomID g = dBodyGetFirstGeom(b); g; g = dGeomGetBodyNext(g)) {
        for (int i = 0; i < 4; i++) seen[i] += g == all[i];
        count++;
    }
    CHECK(count == 4 && seen[0] == 1 && seen[1] == 1 && seen[2] == 1 && seen[3] == 1);
    dBodySetPosition(b, 3, 2, 1);
    dBodySetAngularVel(b, 1, 1, 0);
    dWorldStep(w, REAL(0.1));
    if (check_pose(plain, dBodyGetPosition(b), dBodyGetRotation(b))) return 1;
    if (check_pose(transform, dBodyGetPosition(b), dBodyGetRotation(b))) return 1;
    if (check_follows(off1) || check_follows(off2)) return 1;
    // The held sphere, seen through the transform, sits one unit along the body's z.
    dContactGeom c;
    dGeomID probe = dCreateSphere(0, REAL(0.1));
    const dReal *bp = dBodyGetPosition(b), *bR = dBodyGetRotation(b);
    dGeomSetPosition(probe, bp[0] + bR[2] * REAL(1.5), bp[1] + bR[6] * REAL(1.5),
                     bp[2] + bR[10] * REAL(1.5));
    CHECK(dCollide(probe, transform, 1, &c, sizeof c) == 1);
    CHECK_NEAR(c.depth, 0.1, TOL(1e-9, 1e-4));
    for (int i = 0; i < 4; i++) dGeomDestroy(all[i]);
    dGeomDestroy(probe);
    dWorldDestroy(w);
    return 0;
}

// ---- bad input -------------------------------------------------------------------

static int errors;
static char last_error[512];

static void count_error(int num, const char *msg, va_list ap)
{
    (void)num;
    vsnprintf(last_error, sizeof last_error, msg, ap);
    errors++;
}

static int expect_error(const char *function)
{
    CHECK(errors == 1);
    CHECK(strstr(last_error, function) != NULL);
    errors = 0;
    return 0;
}

static int test_bad_input_is_reported(void)
{
    dSetDebugHandler(count_error);
    dWorldID w = dWorldCreate();
    dGeomID loose = dCreateSphere(0, 1), plane = dCreatePlane(0, 0, 0, 1, 0);
    dGeomSetOffsetPosition(loose, 1, 0, 0);
    if (expect_error("dGeomSetOffsetPosition")) return 1;
    CHECK(strstr(last_error, "") && !dGeomIsOffset(loose));
    dGeomSetOffsetWorldRotation(plane, dBodyGetRotation(dBodyCreate(w)));
    if (expect_error("dGeomSetOffsetWorldRotation")) return 1;
    dBodyID b = dBodyCreate(w);
    dGeomSetBody(loose, b);
    dGeomSetOffsetPosition(loose, NAN, 0, 0);
    if (expect_error("dGeomSetOffsetPosition")) return 1;
    CHECK(!dGeomIsOffset(loose));
    dMatrix3 zero = { 0 };
    dGeomSetOffsetRotation(loose, zero);
    if (expect_error("dGeomSetOffsetRotation")) return 1;
    dGeomSetOffsetRotation(loose, NULL);
    if (expect_error("dGeomSetOffsetRotation")) return 1;
    const dQuaternion nan_q = { NAN, 0, 0, 0 };
    dGeomSetOffsetWorldQuaternion(loose, nan_q);
    if (expect_error("dGeomSetOffsetWorldQuaternion")) return 1;
    CHECK(!dGeomIsOffset(loose));
    dGeomCopyOffsetPosition(loose, NULL);
    if (expect_error("dGeomCopyOffsetPosition")) return 1;
    dGeomDestroy(loose);
    CHECK(dGeomIsOffset(loose) == 0);
    if (expect_error("dGeomIsOffset")) return 1;
    dGeomDestroy(plane);
    dWorldDestroy(w);
    dSetDebugHandler(NULL);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_offset_geom_follows_its_body),
    TEST_CASE(test_quaternion_offset_and_getters),
    TEST_CASE(test_setting_the_geom_pose_moves_the_body),
    TEST_CASE(test_world_offset_setters),
    TEST_CASE(test_clear_detach_and_reattach),
    TEST_CASE(test_same_contacts_as_a_geometry_transform),
    TEST_CASE(test_offsets_and_transforms_on_one_body),
    TEST_CASE(test_bad_input_is_reported),
    TEST_END
};
