// SPDX-License-Identifier: BSD-3-Clause
//
// test_geom.c -- the geom layer of the collision library (guide 10.2, 10.4,
// 10.5.2, 10.7, 10.8, 10.11.2) through the public API: geoms on bodies, the
// cached AABB, class parameters and bad sizes, point depths, dCollide's
// rules, the geometry transform, user classes, the three hooks and the
// backend registry.

#include "test.h"

#include <ode/backend.h>
#include <string.h>

// Exact arithmetic on small numbers gives exact results; where a rotation
// or a square root is involved, a few ulps of dReal.
#define EPS TOL(1e-12, 1e-5)

static int vec3_near(const dReal *a, dReal x, dReal y, dReal z, double tol)
{
    return fabs(a[0] - x) <= tol && fabs(a[1] - y) <= tol && fabs(a[2] - z) <= tol;
}

static int aabb_near(const dReal *a, const double want[6], double tol)
{
    for (int i = 0; i < 6; i++)
        if (!(a[i] == (dReal)want[i] || fabs(a[i] - want[i]) <= tol)) return 0;
    return 1;
}

// ---- geoms on bodies --------------------------------------------------------

static int test_set_body_shares_the_pose_both_ways(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g = dCreateSphere(0, 0.5);
    dBodySetPosition(b, 1, 2, 3);

    dGeomSetBody(g, b);

    CHECK(dGeomGetBody(g) == b);
    CHECK(dGeomGetPosition(g) == dBodyGetPosition(b));   // the body's data itself
    CHECK(dGeomGetRotation(g) == dBodyGetRotation(b));
    CHECK(vec3_near(dGeomGetPosition(g), 1, 2, 3, 0));
    dGeomSetPosition(g, 4, 5, 6);
    CHECK(vec3_near(dBodyGetPosition(b), 4, 5, 6, 0));
    dBodySetPosition(b, 7, 8, 9);
    CHECK(vec3_near(dGeomGetPosition(g), 7, 8, 9, 0));
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);
    dGeomSetRotation(g, R);
    const dReal *BR = dBodyGetRotation(b);
    CHECK_NEAR(BR[1], -1, EPS);   // the body's x axis now points along world y
    CHECK_NEAR(BR[4], 1, EPS);
    dQuaternion q, gq;
    dQFromAxisAndAngle(q, 1, 0, 0, 0.3);
    dBodySetQuaternion(b, q);
    dGeomGetQuaternion(g, gq);
    for (int i = 0; i < 4; i++) CHECK_NEAR(gq[i], dBodyGetQuaternion(b)[i], 0);
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_detaching_keeps_the_last_pose(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g = dCreateBox(0, 1, 1, 1);
    dGeomSetBody(g, b);
    dBodySetPosition(b, 1, 2, 3);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, 0.7);
    dBodySetRotation(b, R);
    dMatrix3 before;
    dGeomCopyRotation(g, before);

    dGeomSetBody(g, 0);
    dBodySetPosition(b, -5, -5, -5);

    CHECK(dGeomGetBody(g) == 0);
    CHECK(dBodyGetFirstGeom(b) == 0);
    CHECK(dGeomGetPosition(g) != dBodyGetPosition(b));
    CHECK(vec3_near(dGeomGetPosition(g), 1, 2, 3, 0));
    for (int i = 0; i < 12; i++) CHECK_NEAR(dGeomGetRotation(g)[i], before[i], 0);
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// A sphere of radius 0.5 on a falling body, stepped with `step`: the geom's
// pose is the body's and its AABB follows (the step calls dGeomMoved).
static int follows_body_when_stepped(int (*step)(dWorldID, dReal))
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, 0, 0, 10);
    dGeomID g = dCreateSphere(0, 0.5);
    dGeomSetBody(g, b);
    dReal box[6];
    dGeomGetAABB(g, box);
    CHECK_NEAR(box[4], 9.5, EPS);

    for (int i = 0; i < 100; i++) step(w, 0.01);

    // Free fall for 1 s: 10 - g/2 = 5.095; explicit-implicit Euler differs by
    // g h t / 2 = 0.05 at most.
    const dReal *p = dBodyGetPosition(b);
    CHECK(vec3_near(dGeomGetPosition(g), p[0], p[1], p[2], 0));
    CHECK_NEAR(p[2], 10 - 9.81 / 2, 0.06);
    dGeomGetAABB(g, box);
    CHECK_NEAR(box[4], p[2] - 0.5, EPS);
    CHECK_NEAR(box[5], p[2] + 0.5, EPS);
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_geom_follows_its_body_through_dWorldStep(void)
{
    return follows_body_when_stepped(dWorldStep);
}

static int test_geom_follows_its_body_through_dWorldQuickStep(void)
{
    return follows_body_when_stepped(dWorldQuickStep);
}

static int test_body_destroy_detaches_its_geoms_which_keep_the_pose(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g1 = dCreateSphere(0, 1), g2 = dCreateBox(0, 1, 2, 3);
    dGeomSetBody(g1, b);
    dGeomSetBody(g2, b);
    dBodySetPosition(b, 3, -2, 1);

    dBodyDestroy(b);
    dBodyID other = dBodyCreate(w);   // may reuse the destroyed body's memory
    dBodySetPosition(other, 9, 9, 9);

    CHECK(dGeomGetBody(g1) == 0 && dGeomGetBody(g2) == 0);
    CHECK(vec3_near(dGeomGetPosition(g1), 3, -2, 1, 0));
    CHECK(vec3_near(dGeomGetPosition(g2), 3, -2, 1, 0));
    CHECK(dBodyGetFirstGeom(other) == 0);
    dGeomDestroy(g1);
    dGeomDestroy(g2);
    dWorldDestroy(w);
    return 0;
}

// ---- the AABB and the hooks -----------------------------------------------

static int test_aabb_is_cached_until_the_geom_moves(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g = dCreateSphere(0, 1);
    dReal a1[6], a2[6];

    dGeomSetPosition(g, 1, 2, 3);
    dGeomGetAABB(g, a1);
    dGeomGetAABB(g, a2);
    CHECK(memcmp(a1, a2, sizeof a1) == 0);
    CHECK(aabb_near(a1, (double[6]){ 0, 2, 1, 3, 2, 4 }, 0));
    dGeomSetPosition(g, 0, 0, 0);
    dGeomGetAABB(g, a2);
    CHECK(aabb_near(a2, (double[6]){ -1, 1, -1, 1, -1, 1 }, 0));

    dGeomSetBody(g, b);
    dBodySetPosition(b, 5, 0, 0);
    dGeomGetAABB(g, a1);
    CHECK(aabb_near(a1, (double[6]){ 4, 6, -1, 1, -1, 1 }, 0));

    // Changing the body's storage behind the library's back: the cached box
    // stays until dGeomMoved (the hook the dynamics calls) marks the geom.
    dReal *p = (dReal *)dBodyGetPosition(b);
    p[0] = 7;
    dGeomGetAABB(g, a2);
    CHECK(aabb_near(a2, (double[6]){ 4, 6, -1, 1, -1, 1 }, 0));
    dGeomMoved(g);
    dGeomGetAABB(g, a2);
    CHECK(aabb_near(a2, (double[6]){ 6, 8, -1, 1, -1, 1 }, 0));
    dGeomDestroy(g);
    dWorldDestroy(w);
    return 0;
}

static int test_class_aabbs(void)
{
    dMatrix3 Rz, Rx;
    dRFromAxisAndAngle(Rz, 0, 0, 1, M_PI / 2);
    dRFromAxisAndAngle(Rx, 1, 0, 0, M_PI / 2);
    dGeomID box = dCreateBox(0, 2, 4, 6), cap = dCreateCapsule(0, 1, 2);
    dGeomID cyl = dCreateCylinder(0, 1, 4), ray = dCreateRay(0, 5);
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 2);
    dReal a[6];

    dGeomSetRotation(box, Rz);   // x and y extents swap
    dGeomGetAABB(box, a);
    CHECK(aabb_near(a, (double[6]){ -2, 2, -1, 1, -3, 3 }, EPS));
    dGeomGetAABB(cap, a);   // caps add the radius along the axis
    CHECK(aabb_near(a, (double[6]){ -1, 1, -1, 1, -2, 2 }, EPS));
    dGeomSetRotation(cyl, Rx);   // axis along world y
    dGeomGetAABB(cyl, a);
    CHECK(aabb_near(a, (double[6]){ -1, 1, -2, 2, -1, 1 }, EPS));
    dGeomRaySet(ray, 1, 2, 3, 0, 0, -1);
    dGeomGetAABB(ray, a);
    CHECK(aabb_near(a, (double[6]){ 1, 1, 2, 2, -2, 3 }, EPS));
    dGeomGetAABB(plane, a);   // solid below z = 2, unbounded elsewhere
    CHECK(aabb_near(a, (double[6]){ -dInfinity, dInfinity, -dInfinity, dInfinity, -dInfinity, 2 },
                    0));
    dGeomDestroy(box);
    dGeomDestroy(cap);
    dGeomDestroy(cyl);
    dGeomDestroy(ray);
    dGeomDestroy(plane);
    return 0;
}

static int test_size_change_updates_the_aabb(void)
{
    dGeomID g = dCreateSphere(0, 1);
    dReal a[6];
    dGeomGetAABB(g, a);

    dGeomSphereSetRadius(g, 2);
    dGeomGetAABB(g, a);

    CHECK(aabb_near(a, (double[6]){ -2, 2, -2, 2, -2, 2 }, 0));
    dGeomDestroy(g);
    return 0;
}

static int test_body_geom_list_walk_and_unlink(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g[3] = { dCreateSphere(0, 1), dCreateBox(0, 1, 1, 1), dCreateCapsule(0, 1, 1) };
    for (int i = 0; i < 3; i++) dGeomSetBody(g[i], b);

    int seen[3] = { 0 }, n = 0;
    for (dGeomID x = dBodyGetFirstGeom(b); x; x = dBodyGetNextGeom(x), n++)
        for (int i = 0; i < 3; i++) seen[i] += x == g[i];
    CHECK(n == 3 && seen[0] == 1 && seen[1] == 1 && seen[2] == 1);
    CHECK(dGeomGetBodyNext(dBodyGetFirstGeom(b)) == dBodyGetNextGeom(dBodyGetFirstGeom(b)));

    for (int k = 0; k < 3; k++) {
        // Unlink the middle geom first, then whatever is first.
        dGeomID victim = k == 0 ? dGeomGetBodyNext(dBodyGetFirstGeom(b)) : dBodyGetFirstGeom(b);
        dGeomSetBody(victim, 0);
        CHECK(dGeomGetBody(victim) == 0 && dGeomGetBodyNext(victim) == 0);
        n = 0;
        for (dGeomID x = dBodyGetFirstGeom(b); x; x = dGeomGetBodyNext(x), n++)
            CHECK(x != victim && dGeomGetBody(x) == b);
        CHECK(n == 2 - k);
    }
    for (int i = 0; i < 3; i++) dGeomDestroy(g[i]);
    dWorldDestroy(w);
    return 0;
}

static int test_moving_a_body_with_three_geoms_moves_all(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID g[3] = { dCreateSphere(0, 1), dCreateSphere(0, 2), dCreateSphere(0, 3) };
    dReal a[6];
    for (int i = 0; i < 3; i++) {
        dGeomSetBody(g[i], b);
        dGeomGetAABB(g[i], a);
    }

    dBodySetPosition(b, 10, 0, 0);

    for (int i = 0; i < 3; i++) {
        dGeomGetAABB(g[i], a);
        CHECK_NEAR(a[0], 10 - (i + 1), 0);
        dGeomDestroy(g[i]);
    }
    dWorldDestroy(w);
    return 0;
}

// ---- placeability, parameters and bad input ----------------------------------

static int test_placeable_only_calls_on_plane_and_space_are_reported(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0);
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID targets[2] = { plane, (dGeomID)space };
    test_capture_reports();

    for (int i = 0; i < 2; i++) {
        int before = test_captured_count();
        dGeomSetPosition(targets[i], 1, 2, 3);
        CHECK(dGeomGetPosition(targets[i]) == 0);
        dGeomSetBody(targets[i], b);
        CHECK(test_captured_count() == before + 3);
        CHECK(dGeomGetBody(targets[i]) == 0);
    }

    CHECK(test_captured_contains("dGeomSetPosition") && test_captured_contains("placeable"));
    CHECK(test_captured_contains("dGeomGetPosition") && test_captured_contains("dGeomSetBody"));
    CHECK(dBodyGetFirstGeom(b) == 0);
    dVector4 p;
    dGeomPlaneGetParams(plane, p);
    CHECK(p[0] == 0 && p[1] == 0 && p[2] == 1 && p[3] == 0);
    dGeomDestroy(plane);
    dSpaceDestroy(space);
    dWorldDestroy(w);
    return 0;
}

static int test_class_parameters_round_trip(void)
{
    dGeomID s = dCreateSphere(0, 1), b = dCreateBox(0, 1, 2, 3), c = dCreateCapsule(0, 1, 2);
    dGeomID y = dCreateCylinder(0, 1, 2), p = dCreatePlane(0, 1, 0, 0, 1), r = dCreateRay(0, 1);
    dVector3 v;
    dVector4 q;
    dReal r1, l1;

    dGeomSphereSetRadius(s, 2.5);
    dGeomBoxSetLengths(b, 4, 5, 6);
    dGeomCapsuleSetParams(c, 0.25, 3);
    dGeomCylinderSetParams(y, 0.75, 1.5);
    dGeomPlaneSetParams(p, 0, 1, 0, -2);
    dGeomRaySetLength(r, 7);
    dGeomRaySetFirstContact(r, 1);
    dGeomRaySetBackfaceCull(r, 1);
    dGeomRaySetClosestHit(r, 1);

    CHECK(dGeomSphereGetRadius(s) == 2.5);
    dGeomBoxGetLengths(b, v);
    CHECK(v[0] == 4 && v[1] == 5 && v[2] == 6);
    dGeomCapsuleGetParams(c, &r1, &l1);
    CHECK(r1 == 0.25 && l1 == 3);
    dGeomCylinderGetParams(y, &r1, &l1);
    CHECK(r1 == 0.75 && l1 == 1.5);
    dGeomPlaneGetParams(p, q);
    CHECK(q[0] == 0 && q[1] == 1 && q[2] == 0 && q[3] == -2);
    CHECK(dGeomRayGetLength(r) == 7);
    CHECK(dGeomRayGetFirstContact(r) == 1 && dGeomRayGetBackfaceCull(r) == 1);
    CHECK(dGeomRayGetClosestHit(r) == 1);
    dGeomID all[6] = { s, b, c, y, p, r };
    for (int i = 0; i < 6; i++) dGeomDestroy(all[i]);
    return 0;
}

static int test_non_unit_plane_normal_is_normalised(void)
{
    dGeomID p = dCreatePlane(0, 0, 0, 2, 4);
    dVector4 q;

    dGeomPlaneGetParams(p, q);
    CHECK(q[0] == 0 && q[1] == 0 && q[2] == 1 && q[3] == 2);   // z = 2, same plane
    dGeomPlaneSetParams(p, 3, 4, 0, 10);
    dGeomPlaneGetParams(p, q);
    CHECK_NEAR(q[0], 0.6, EPS);
    CHECK_NEAR(q[1], 0.8, EPS);
    CHECK_NEAR(q[3], 2, EPS);
    dGeomDestroy(p);
    return 0;
}

static int test_bad_sizes_are_reported_and_change_nothing(void)
{
    dGeomID s = dCreateSphere(0, 1), b = dCreateBox(0, 1, 1, 1), c = dCreateCapsule(0, 1, 1);
    dGeomID y = dCreateCylinder(0, 1, 1), p = dCreatePlane(0, 0, 0, 1, 0), r = dCreateRay(0, 1);
    dGeomRaySet(r, 1, 2, 3, 1, 0, 0);
    test_capture_reports();

    CHECK(dCreateSphere(0, -1) == 0 && dCreateSphere(0, -0.5) == 0 && dCreateSphere(0, NAN) == 0);
    CHECK(dCreateBox(0, 1, -1, 1) == 0 && dCreatePlane(0, 0, 0, 0, 1) == 0);
    CHECK(dCreateCapsule(0, -1, 1) == 0 && dCreateCylinder(0, 1, -1) == 0);
    CHECK(dCreateRay(0, -1) == 0);
    dGeomSphereSetRadius(s, -2);
    dGeomSphereSetRadius(s, INFINITY);
    dGeomSphereSetRadius(s, NAN);
    dGeomBoxSetLengths(b, 1, -1, 1);
    dGeomCapsuleSetParams(c, 1, -1);
    dGeomCylinderSetParams(y, INFINITY, 1);
    dGeomPlaneSetParams(p, 0, 0, 0, 5);
    dGeomRaySet(r, 0, 0, 0, 0, 0, 0);
    dGeomRaySetLength(r, NAN);

    CHECK(test_captured_count() == 17);
    CHECK(test_captured_contains("dCreateSphere: radius must be >= 0"));
    CHECK(test_captured_contains("dGeomPlaneSetParams"));
    CHECK(test_captured_contains("dGeomRaySet: direction"));
    CHECK(dGeomSphereGetRadius(s) == 1);
    dVector3 v, start, dir;
    dGeomBoxGetLengths(b, v);
    CHECK(v[0] == 1 && v[1] == 1 && v[2] == 1);
    dReal r1, l1;
    dGeomCapsuleGetParams(c, &r1, &l1);
    CHECK(r1 == 1 && l1 == 1);
    dGeomCylinderGetParams(y, &r1, &l1);
    CHECK(r1 == 1 && l1 == 1);
    dVector4 q;
    dGeomPlaneGetParams(p, q);
    CHECK(q[2] == 1 && q[3] == 0);
    dGeomRayGet(r, start, dir);
    CHECK(vec3_near(start, 1, 2, 3, 0) && vec3_near(dir, 1, 0, 0, EPS));
    CHECK(dGeomRayGetLength(r) == 1);
    dGeomID all[6] = { s, b, c, y, p, r };
    for (int i = 0; i < 6; i++) dGeomDestroy(all[i]);
    return 0;
}

static int test_class_getter_on_wrong_class_is_reported(void)
{
    dGeomID b = dCreateBox(0, 1, 1, 1);
    test_capture_reports();

    CHECK(dGeomSphereGetRadius(b) == 0);
    dGeomSphereSetRadius(b, 3);

    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("geom is a box, not a sphere"));
    dGeomDestroy(b);
    return 0;
}

static int test_ray_set_and_get_round_trip_with_unit_direction(void)
{
    dGeomID r = dCreateRay(0, 2);
    dVector3 start, dir;

    dGeomRaySet(r, 1, 2, 3, 0, 0, -3);
    dGeomRayGet(r, start, dir);
    CHECK(vec3_near(start, 1, 2, 3, 0) && vec3_near(dir, 0, 0, -1, EPS));
    dGeomRaySet(r, -1, 0, 4, 1, 2, 2);
    dGeomRayGet(r, start, dir);
    CHECK(vec3_near(start, -1, 0, 4, 0));
    CHECK(vec3_near(dir, 1.0 / 3, 2.0 / 3, 2.0 / 3, EPS));
    // The direction is the z column of the geom's rotation.
    const dReal *R = dGeomGetRotation(r);
    CHECK(vec3_near((dReal[3]){ R[2], R[6], R[10] }, 1.0 / 3, 2.0 / 3, 2.0 / 3, EPS));
    dGeomDestroy(r);
    return 0;
}

static int test_bits_enable_data_class_and_space_queries(void)
{
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID g = dCreateSphere(space, 1);
    int data;

    CHECK(dGeomGetCategoryBits(g) == ~0ul && dGeomGetCollideBits(g) == ~0ul);
    dGeomSetCategoryBits(g, 0x5);
    dGeomSetCollideBits(g, 0xa0);
    CHECK(dGeomGetCategoryBits(g) == 0x5 && dGeomGetCollideBits(g) == 0xa0);
    CHECK(dGeomIsEnabled(g) == 1);
    dGeomDisable(g);
    CHECK(dGeomIsEnabled(g) == 0);
    dGeomEnable(g);
    CHECK(dGeomIsEnabled(g) == 1);
    CHECK(dGeomGetData(g) == 0);
    dGeomSetData(g, &data);
    CHECK(dGeomGetData(g) == &data);
    CHECK(dGeomGetSpace(g) == space && dGeomGetSpace((dGeomID)space) == 0);
    CHECK(dGeomIsSpace(g) == 0 && dGeomIsSpace((dGeomID)space) == 1);
    dSpaceDestroy(space);
    return 0;
}

static int test_class_numbers(void)
{
    dVector3 c = { 0, 0, 0 }, e = { 10, 10, 10 };
    dGeomID g[] = { dCreateSphere(0, 1), dCreateBox(0, 1, 1, 1), dCreateCapsule(0, 1, 1),
                    dCreateCylinder(0, 1, 1), dCreatePlane(0, 0, 0, 1, 0), dCreateRay(0, 1),
                    dCreateGeomTransform(0), (dGeomID)dSimpleSpaceCreate(0),
                    (dGeomID)dHashSpaceCreate(0), (dGeomID)dQuadTreeSpaceCreate(0, c, e, 3) };
    const int want[] = { 0, 1, 2, 3, 4, 5, 7, 10, 11, 13 };

    for (int i = 0; i < 10; i++) CHECK(dGeomGetClass(g[i]) == want[i]);

    CHECK(dSphereClass == 0 && dCCylinderClass == dCapsuleClass && dGeomTransformClass == 7);
    CHECK(dFirstUserClass == 14 && dGeomNumClasses == 18);
    for (int i = 0; i < 10; i++) dGeomDestroy(g[i]);
    return 0;
}

// ---- point depths --------------------------------------------------------------

static int test_sphere_point_depth(void)
{
    dGeomID s = dCreateSphere(0, 1);
    dGeomSetPosition(s, 1, 2, 3);

    CHECK_NEAR(dGeomSpherePointDepth(s, 1, 2, 3), 1, 0);         // centre
    CHECK_NEAR(dGeomSpherePointDepth(s, 1, 2.25, 3), 0.75, EPS);  // inside
    CHECK_NEAR(dGeomSpherePointDepth(s, 1, 2, 4), 0, EPS);        // surface
    CHECK_NEAR(dGeomSpherePointDepth(s, 4, 6, 3), -4, EPS);       // 5 away (3-4-5)
    dGeomDestroy(s);
    return 0;
}

// Inside: distance to the nearest face. Outside: minus the distance to the
// box (ODE 0.16 returns other negative numbers there; only the sign is ODE's).
static int test_box_point_depth(void)
{
    dGeomID b = dCreateBox(0, 2, 4, 6);   // half extents 1, 2, 3
    dGeomSetPosition(b, 0, 0, 1);

    CHECK_NEAR(dGeomBoxPointDepth(b, 0, 0, 1), 1, 0);
    CHECK_NEAR(dGeomBoxPointDepth(b, 0.5, 0, 1), 0.5, EPS);
    CHECK_NEAR(dGeomBoxPointDepth(b, 0, 1.75, 1), 0.25, EPS);
    CHECK_NEAR(dGeomBoxPointDepth(b, 3, 0, 1), -2, EPS);                // off a face
    CHECK_NEAR(dGeomBoxPointDepth(b, 2, 3, 5), -dSqrt(3), EPS);         // off a corner
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);   // local x along world y
    dGeomSetRotation(b, R);
    CHECK_NEAR(dGeomBoxPointDepth(b, 0, 0.75, 1), 0.25, EPS);
    CHECK_NEAR(dGeomBoxPointDepth(b, 1.75, 0, 1), 0.25, EPS);
    CHECK(dGeomBoxPointDepth(b, 0, 1.5, 1) < 0);
    dGeomDestroy(b);
    return 0;
}

static int test_capsule_point_depth(void)
{
    dGeomID c = dCreateCapsule(0, 1, 2);   // axis z from -1 to 1, radius 1

    CHECK_NEAR(dGeomCapsulePointDepth(c, 0, 0.5, 0), 0.5, EPS);
    CHECK_NEAR(dGeomCapsulePointDepth(c, 0, 0, 1.5), 0.5, EPS);    // in the cap
    CHECK_NEAR(dGeomCapsulePointDepth(c, 0, 0, 2.5), -0.5, EPS);   // beyond the cap
    CHECK_NEAR(dGeomCapsulePointDepth(c, 3, 0, 0), -2, EPS);
    CHECK_NEAR(dGeomCapsulePointDepth(c, 3, 0, 5), -4, EPS);       // 3-4-5 from (0,0,1)
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);   // axis along world x
    dGeomSetRotation(c, R);
    CHECK_NEAR(dGeomCapsulePointDepth(c, 2.5, 0, 0), -0.5, EPS);
    CHECK_NEAR(dGeomCapsulePointDepth(c, 1, 0, 0.5), 0.5, EPS);
    dGeomDestroy(c);
    return 0;
}

static int test_plane_point_depth(void)
{
    dGeomID p = dCreatePlane(0, 0, 0, 2, 4);   // z = 2, solid below

    CHECK_NEAR(dGeomPlanePointDepth(p, 0, 0, 0), 2, 0);
    CHECK_NEAR(dGeomPlanePointDepth(p, 5, -7, 2), 0, 0);
    CHECK_NEAR(dGeomPlanePointDepth(p, 0, 0, 5), -3, 0);
    dGeomDestroy(p);
    return 0;
}

// ---- dCollide ----------------------------------------------------------------------

// Two unit spheres 1.5 apart on x: they overlap by 0.5.
static void overlapping_spheres(dGeomID *a, dGeomID *b)
{
    *a = dCreateSphere(0, 1);
    *b = dCreateSphere(0, 1);
    dGeomSetPosition(*b, 1.5, 0, 0);
}

static int test_collide_flags_zero_means_one(void)
{
    dGeomID a, b;
    overlapping_spheres(&a, &b);
    dContactGeom c[2];

    int n = dCollide(a, b, 0, c, sizeof c[0]);

    CHECK(n == 1);
    CHECK(c[0].g1 == a && c[0].g2 == b);
    CHECK_NEAR(c[0].depth, 0.5, EPS);
    CHECK(vec3_near(c[0].normal, -1, 0, 0, EPS));   // into o1
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_collide_small_skip_is_reported(void)
{
    dGeomID a, b;
    overlapping_spheres(&a, &b);
    dContactGeom c[2];
    test_capture_reports();

    int n = dCollide(a, b, 1, c, sizeof c[0] - 1);

    CHECK(n == 0);
    CHECK(test_captured_count() == 1 && test_captured_contains("dCollide: skip"));
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_collide_self_same_body_and_separated_touch_nothing(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body = dBodyCreate(w);
    dGeomID a, b, far = dCreateSphere(0, 1);
    overlapping_spheres(&a, &b);
    dGeomSetPosition(far, 10, 0, 0);
    dContactGeom c[4], sentinel[4];
    memset(c, 0xab, sizeof c);
    memset(sentinel, 0xab, sizeof sentinel);

    CHECK(dCollide(a, a, 4, c, sizeof c[0]) == 0);
    CHECK(dCollide(a, far, 4, c, sizeof c[0]) == 0);
    CHECK(dCollide(far, b, 4, c, sizeof c[0]) == 0);
    dGeomSetBody(a, body);
    dGeomSetBody(b, body);   // b moves to the body's pose: a and b coincide
    CHECK(dCollide(a, b, 4, c, sizeof c[0]) == 0);

    CHECK(memcmp(c, sentinel, sizeof c) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomDestroy(far);
    dWorldDestroy(w);
    return 0;
}

// Contacts embedded in larger records: each is written at its stride and
// nothing else of the record is touched.
static int test_collide_writes_with_the_stride(void)
{
    struct record {
        dContactGeom g;
        double tag;
    } r[8];
    dGeomID box = dCreateBox(0, 1, 1, 1), plane = dCreatePlane(0, 0, 0, 1, 0);
    dGeomSetPosition(box, 0, 0, 0.49);
    for (int i = 0; i < 8; i++) r[i].tag = i;

    int n = dCollide(box, plane, 8, &r[0].g, sizeof r[0]);

    CHECK(n >= 1 && n <= 8);
    for (int i = 0; i < 8; i++) CHECK(r[i].tag == i);
    for (int i = 0; i < n; i++) {
        CHECK(r[i].g.g1 == box && r[i].g.g2 == plane);
        CHECK_NEAR(r[i].g.depth, 0.01, TOL(1e-9, 1e-5));
        CHECK(vec3_near(r[i].g.normal, 0, 0, 1, EPS));
    }
    dGeomDestroy(box);
    dGeomDestroy(plane);
    return 0;
}

static int test_collide_with_a_space_collides_its_contents(void)
{
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID in1 = dCreateSphere(space, 1), in2 = dCreateSphere(space, 1);
    dGeomID probe = dCreateSphere(0, 1);
    dGeomSetPosition(in1, 0, 0, 0);
    dGeomSetPosition(in2, 10, 0, 0);
    dGeomSetPosition(probe, 1.5, 0, 0);   // touches in1 only
    dContactGeom c[4];

    int n = dCollide((dGeomID)space, probe, 4, c, sizeof c[0]);
    CHECK(n == 1 && c[0].g1 == in1 && c[0].g2 == probe);
    CHECK(vec3_near(c[0].normal, -1, 0, 0, EPS));
    n = dCollide(probe, (dGeomID)space, 4, c, sizeof c[0]);
    CHECK(n == 1 && c[0].g1 == probe && c[0].g2 == in1);
    CHECK(vec3_near(c[0].normal, 1, 0, 0, EPS));
    dGeomSetPosition(probe, 8.5, 0, 0);   // now in2 only
    n = dCollide((dGeomID)space, probe, 4, c, sizeof c[0]);
    CHECK(n == 1 && c[0].g1 == in2);
    // A geom against its own space meets itself (0) and the others.
    dGeomSetPosition(in2, 1.5, 0, 0);
    n = dCollide(in1, (dGeomID)space, 4, c, sizeof c[0]);
    CHECK(n == 1 && c[0].g1 == in1 && c[0].g2 == in2);
    dGeomDestroy(probe);
    dSpaceDestroy(space);
    return 0;
}

static int test_destroying_a_geom_removes_it_from_its_space(void)
{
    dSpaceID space = dHashSpaceCreate(0);
    dGeomID a = dCreateSphere(space, 1), b = dCreateBox(space, 1, 1, 1);

    dGeomDestroy(a);

    CHECK(dSpaceGetNumGeoms(space) == 1);
    CHECK(dSpaceGetGeom(space, 0) == b && dSpaceQuery(space, b) == 1);
    dSpaceDestroy(space);
    return 0;
}

static int test_bad_handles_are_reported(void)
{
    dWorldID w = dWorldCreate();
    dBodyID dead_body = dBodyCreate(w);
    dBodyDestroy(dead_body);
    dGeomID live = dCreateSphere(0, 1), dead = dCreateSphere(0, 1);
    dGeomDestroy(dead);   // its memory is pooled: reading the handle is safe
    dContactGeom c[1];
    dReal a[6];
    test_capture_reports();

    dGeomSetData(0, 0);
    CHECK(dGeomGetPosition(dead) == 0);
    CHECK(dCollide(dead, live, 1, c, sizeof c[0]) == 0);
    CHECK(dCollide(live, 0, 1, c, sizeof c[0]) == 0);
    dGeomDestroy(dead);
    dGeomGetAABB(0, a);
    CHECK(dGeomGetClass(dead) == -1);
    dGeomSetBody(live, dead_body);
    CHECK(dGeomGetBody(live) == 0);

    CHECK(test_captured_count() == 8);
    CHECK(test_captured_contains("dGeomSetData: geom is NULL or was destroyed"));
    CHECK(test_captured_contains("dCollide: o1 is NULL or was destroyed"));
    CHECK(test_captured_contains("dCollide: o2"));
    CHECK(test_captured_contains("dGeomSetBody: body was destroyed"));
    dGeomDestroy(live);
    dWorldDestroy(w);
    return 0;
}

// ---- user classes (10.8) ----------------------------------------------------------------

// A "ball" class: class data is the radius; it collides with spheres only.
typedef struct ball_data {
    dReal radius;
    unsigned char pad[40];   // writable class data beyond the radius
} ball_data;

static int ball_class = -1;
static int ball_dtor_calls, ball_aabb_tests, ball_aabb_test_answer = 1;

static dReal ball_radius(dGeomID g) { return ((ball_data *)dGeomGetClassData(g))->radius; }

static void ball_aabb(dGeomID g, dReal aabb[6])
{
    const dReal *p = dGeomGetPosition(g);
    for (int i = 0; i < 3; i++) {
        aabb[2 * i] = p[i] - ball_radius(g);
        aabb[2 * i + 1] = p[i] + ball_radius(g);
    }
}

// Ball (o1) against sphere (o2): one contact, normal into the ball.
static int ball_sphere(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    const dReal *p1 = dGeomGetPosition(o1), *p2 = dGeomGetPosition(o2);
    dReal r1 = ball_radius(o1), r2 = dGeomSphereGetRadius(o2);
    dVector3 d = { p1[0] - p2[0], p1[1] - p2[1], p1[2] - p2[2] };
    dReal dist = dSqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (dist >= r1 + r2 || dist == 0) return 0;
    c->depth = r1 + r2 - dist;
    for (int i = 0; i < 3; i++) {
        c->normal[i] = d[i] / dist;
        c->pos[i] = p2[i] + c->normal[i] * (r2 - c->depth / 2);
    }
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = c->side2 = -1;
    return 1;
}

static dColliderFn *ball_collider(int num) { return num == dSphereClass ? ball_sphere : 0; }

static void ball_dtor(dGeomID g)
{
    (void)g;
    ball_dtor_calls++;
}

static int ball_aabb_test(dGeomID o1, dGeomID o2, dReal aabb[6])
{
    (void)o1;
    (void)o2;
    (void)aabb;
    ball_aabb_tests++;
    return ball_aabb_test_answer;
}

static dGeomID create_ball(dSpaceID space, dReal radius)
{
    if (ball_class < 0) {
        dGeomClass cls = { sizeof(ball_data), ball_collider, ball_aabb, ball_aabb_test,
                           ball_dtor };
        ball_class = dCreateGeomClass(&cls);
    }
    dGeomID g = dCreateGeom(ball_class);
    ((ball_data *)dGeomGetClassData(g))->radius = radius;
    if (space) dSpaceAdd(space, g);
    return g;
}

static int test_user_class_geom_and_class_data(void)
{
    dGeomID g = create_ball(0, 1);

    CHECK(ball_class >= dFirstUserClass && ball_class <= dLastUserClass);
    CHECK(dGeomGetClass(g) == ball_class);
    ball_data *d = dGeomGetClassData(g);
    for (size_t i = 0; i < sizeof d->pad; i++) CHECK(d->pad[i] == 0);   // zeroed
    memset(d->pad, 0x5a, sizeof d->pad);
    CHECK(d->radius == 1 && d->pad[sizeof d->pad - 1] == 0x5a);
    dGeomSetPosition(g, 1, 2, 3);
    dReal a[6];
    dGeomGetAABB(g, a);
    CHECK(aabb_near(a, (double[6]){ 0, 2, 1, 3, 2, 4 }, 0));
    test_capture_reports();
    dGeomID s = dCreateSphere(0, 1);
    CHECK(dGeomGetClassData(s) == 0);
    CHECK(test_captured_contains("not of a user class"));
    dGeomDestroy(s);
    dGeomDestroy(g);
    return 0;
}

static int test_user_class_collides_both_ways_round(void)
{
    dGeomID u = create_ball(0, 1), s = dCreateSphere(0, 0.5);
    dGeomSetPosition(s, 0, 0, 1.25);   // overlap 0.25 along z
    dContactGeom c[2];

    CHECK(dCollide(u, s, 2, c, sizeof c[0]) == 1);
    CHECK(c[0].g1 == u && c[0].g2 == s);
    CHECK(vec3_near(c[0].normal, 0, 0, -1, EPS));
    CHECK_NEAR(c[0].depth, 0.25, EPS);
    CHECK(dCollide(s, u, 2, c, sizeof c[0]) == 1);   // the ball's collider, flipped
    CHECK(c[0].g1 == s && c[0].g2 == u);
    CHECK(vec3_near(c[0].normal, 0, 0, 1, EPS));
    CHECK_NEAR(c[0].depth, 0.25, EPS);
    dGeomID box = dCreateBox(0, 5, 5, 5);   // no collider for boxes: no contact
    CHECK(dCollide(u, box, 2, c, sizeof c[0]) == 0 && dCollide(box, u, 2, c, sizeof c[0]) == 0);
    dGeomDestroy(box);
    dGeomDestroy(u);
    dGeomDestroy(s);
    return 0;
}

static int test_user_class_dtor_runs_on_destroy(void)
{
    dGeomID u = create_ball(0, 1);
    int before = ball_dtor_calls;

    dGeomDestroy(u);

    CHECK(ball_dtor_calls == before + 1);
    return 0;
}

typedef struct pair_log {
    int count;
    dGeomID a, b;
} pair_log;

static void log_pair(void *data, dGeomID a, dGeomID b)
{
    pair_log *log = data;
    log->count++;
    log->a = a;
    log->b = b;
}

static int test_user_geom_in_a_space_is_found(void)
{
    dSpaceID space = dHashSpaceCreate(0);
    dGeomID u = create_ball(space, 1), s = dCreateSphere(space, 0.5);
    dGeomSetPosition(u, 5, 5, 5);
    dGeomSetPosition(s, 5, 5, 6.25);
    pair_log log = { 0, 0, 0 };

    dSpaceCollide(space, &log, log_pair);

    CHECK(log.count == 1);
    CHECK((log.a == u && log.b == s) || (log.a == s && log.b == u));
    dSpaceDestroy(space);
    return 0;
}

// Guide 10.8: the class's aabb_test is the space's early exit for a pair
// whose AABBs overlap.
static int test_user_aabb_test_can_veto_a_pair(void)
{
    dSpaceID space = dSimpleSpaceCreate(0);
    create_ball(space, 1);
    dGeomID s = dCreateSphere(space, 0.5);
    dGeomSetPosition(s, 0, 0, 1.25);
    pair_log log = { 0, 0, 0 };
    ball_aabb_tests = 0;
    ball_aabb_test_answer = 0;

    dSpaceCollide(space, &log, log_pair);
    int vetoed_tests = ball_aabb_tests, vetoed_pairs = log.count;
    ball_aabb_test_answer = 1;
    dSpaceCollide(space, &log, log_pair);
    dSpaceDestroy(space);

    CHECK(vetoed_tests == 1 && vetoed_pairs == 0);
    CHECK(ball_aabb_tests == 2 && log.count == 1);
    return 0;
}

// Classes are registered for the life of the process: this runs after the
// other user class tests and fills the remaining slots.
static int test_fifth_user_class_is_reported(void)
{
    dGeomID g = create_ball(0, 1);   // make sure the ball class exists
    dGeomDestroy(g);
    dGeomClass cls = { 0, ball_collider, dInfiniteAABB, 0, 0 };
    int last = ball_class;
    while (last < dLastUserClass) {
        int n = dCreateGeomClass(&cls);
        CHECK(n == last + 1);
        last = n;
    }
    test_capture_reports();

    CHECK(dCreateGeomClass(&cls) == -1);
    CHECK(dCreateGeom(dLastUserClass + 1) == 0);
    CHECK(dCreateGeom(dSphereClass) == 0);

    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("too many user classes"));
    return 0;
}

// ---- geometry transform (10.7.7) ---------------------------------------------------------

static int test_transform_collides_where_the_offset_puts_the_geom(void)
{
    dGeomID t = dCreateGeomTransform(0), held = dCreateSphere(0, 0.5);
    dGeomID other = dCreateSphere(0, 0.5);
    dGeomTransformSetGeom(t, held);
    dGeomSetPosition(held, 2, 0, 0);   // relative to the transform
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);
    dGeomSetPosition(t, 1, 0, 0);
    dGeomSetRotation(t, R);            // the held sphere is at (1, 2, 0)
    dContactGeom c[2];

    dGeomSetPosition(other, 3, 0, 0);   // where it would be unrotated
    CHECK(dCollide(t, other, 2, c, sizeof c[0]) == 0);
    dGeomSetPosition(other, 1, 2.9, 0);
    CHECK(dCollide(t, other, 2, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK(vec3_near(c[0].normal, 0, -1, 0, EPS));
    CHECK(c[0].pos[1] >= 2.4 - EPS && c[0].pos[1] <= 2.5 + EPS);   // in the overlap
    dReal a[6];
    dGeomGetAABB(t, a);
    CHECK(aabb_near(a, (double[6]){ 0.5, 1.5, 1.5, 2.5, -0.5, 0.5 }, EPS));
    CHECK(vec3_near(dGeomGetPosition(held), 2, 0, 0, 0));   // its own pose is untouched
    dGeomDestroy(t);
    dGeomDestroy(held);
    dGeomDestroy(other);
    return 0;
}

// Guide 10.7.7: info 0 (the default) puts the held geom in g1 (or g2), info 1
// the transform (which has the body and the world pose). ODE 0.16 agrees.
static int test_transform_info_mode_names_the_geom_or_the_transform(void)
{
    dGeomID t = dCreateGeomTransform(0), held = dCreateSphere(0, 1), other = dCreateSphere(0, 1);
    dGeomTransformSetGeom(t, held);
    dGeomSetPosition(other, 1.5, 0, 0);
    dContactGeom c[1];

    CHECK(dGeomTransformGetInfo(t) == 0);
    CHECK(dCollide(t, other, 1, c, sizeof c[0]) == 1 && c[0].g1 == held && c[0].g2 == other);
    CHECK(dCollide(other, t, 1, c, sizeof c[0]) == 1 && c[0].g1 == other && c[0].g2 == held);
    dGeomTransformSetInfo(t, 1);
    CHECK(dGeomTransformGetInfo(t) == 1);
    CHECK(dCollide(t, other, 1, c, sizeof c[0]) == 1 && c[0].g1 == t && c[0].g2 == other);
    CHECK(dCollide(other, t, 1, c, sizeof c[0]) == 1 && c[0].g1 == other && c[0].g2 == t);
    CHECK(vec3_near(c[0].normal, 1, 0, 0, EPS));
    dGeomDestroy(t);
    dGeomDestroy(held);
    dGeomDestroy(other);
    return 0;
}

// Moving or resizing the held geom moves the transform's box, also through
// a space that had already cached it, and nested transforms pass it on.
static int test_transform_box_follows_the_held_geom(void)
{
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID outer = dCreateGeomTransform(space), inner = dCreateGeomTransform(0);
    dGeomID held = dCreateSphere(0, 0.5), probe = dCreateSphere(space, 0.5);
    dGeomTransformSetGeom(outer, inner);
    dGeomTransformSetGeom(inner, held);
    dGeomSetPosition(probe, 5, 0, 0);
    pair_log log = { 0, 0, 0 };
    dSpaceCollide(space, &log, log_pair);   // caches both boxes: apart
    CHECK(log.count == 0);
    dReal a[6];

    dGeomSetPosition(held, 4.5, 0, 0);      // relative to inner, itself at outer's origin
    dSpaceCollide(space, &log, log_pair);

    CHECK(log.count == 1);
    dGeomGetAABB(outer, a);
    CHECK(aabb_near(a, (double[6]){ 4, 5, -0.5, 0.5, -0.5, 0.5 }, EPS));
    dGeomSphereSetRadius(held, 1);
    dGeomGetAABB(outer, a);
    CHECK(aabb_near(a, (double[6]){ 3.5, 5.5, -1, 1, -1, 1 }, EPS));
    dGeomTransformSetCleanup(outer, 1);
    dGeomTransformSetCleanup(inner, 1);
    dSpaceDestroy(space);
    return 0;
}

static int test_transform_cleanup_destroys_the_held_geom(void)
{
    dGeomID t = dCreateGeomTransform(0), u = create_ball(0, 1);
    CHECK(dGeomTransformGetCleanup(t) == 0);
    dGeomTransformSetGeom(t, u);
    CHECK(dGeomTransformGetGeom(t) == u);
    int before = ball_dtor_calls;

    dGeomTransformSetCleanup(t, 1);
    dGeomDestroy(t);

    CHECK(ball_dtor_calls == before + 1);
    // Cleanup 0: the held geom survives its transform.
    t = dCreateGeomTransform(0);
    u = create_ball(0, 1);
    dGeomTransformSetGeom(t, u);
    dGeomDestroy(t);
    CHECK(ball_dtor_calls == before + 1 && dGeomGetClass(u) == ball_class);
    dGeomDestroy(u);
    return 0;
}

static int test_transform_on_a_body_in_a_space(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dSpaceID space = dHashSpaceCreate(0);
    dGeomID t = dCreateGeomTransform(space), held = dCreateBox(0, 1, 1, 1);
    dGeomID probe = dCreateSphere(space, 0.5);
    dGeomTransformSetGeom(t, held);
    dGeomTransformSetCleanup(t, 1);
    dGeomSetPosition(held, 0, 0, 3);
    dGeomSetBody(t, b);
    dBodySetPosition(b, 10, 0, 0);   // the box is at (10, 0, 3)
    dGeomSetPosition(probe, 10, 0, 3.9);
    pair_log log = { 0, 0, 0 };

    dSpaceCollide(space, &log, log_pair);

    CHECK(log.count == 1);
    dContactGeom c[4];
    dGeomTransformSetInfo(t, 1);
    int n = dCollide(t, probe, 4, c, sizeof c[0]);
    CHECK(n >= 1 && c[0].g1 == t && dGeomGetBody(c[0].g1) == b);
    CHECK_NEAR(c[0].depth, 0.1, TOL(1e-9, 1e-5));
    dSpaceDestroy(space);
    dWorldDestroy(w);
    return 0;
}

static int test_transform_refuses_geoms_in_a_space_or_on_a_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID t = dCreateGeomTransform(0), t2 = dCreateGeomTransform(0);
    dGeomID in_space = dCreateSphere(space, 1), on_body = dCreateSphere(0, 1);
    dGeomID held = dCreateSphere(0, 1);
    dGeomSetBody(on_body, b);
    dGeomTransformSetGeom(t2, held);
    test_capture_reports();

    dGeomTransformSetGeom(t, in_space);
    dGeomTransformSetGeom(t, on_body);
    dGeomTransformSetGeom(t, held);        // already held by t2
    dGeomTransformSetGeom(t, (dGeomID)space);
    dGeomTransformSetGeom(t, t);
    dGeomTransformSetGeom(t, t2);          // fine: t holds t2 ...
    dGeomTransformSetGeom(t2, t);          // ... but t2 cannot hold t (a cycle)
    dGeomSetBody(held, b);
    dSpaceAdd(space, held);
    dGeomDestroy(held);

    CHECK(test_captured_count() == 9);
    CHECK(test_captured_contains("in a space") && test_captured_contains("to a body"));
    CHECK(test_captured_contains("cycle") && test_captured_contains("already held"));
    CHECK(test_captured_contains("obj is a space") && test_captured_contains("dSpaceAdd"));
    CHECK(test_captured_contains("dGeomSetBody") && test_captured_contains("dGeomDestroy"));
    CHECK(dGeomTransformGetGeom(t) == t2 && dGeomTransformGetGeom(t2) == held);
    CHECK(dGeomGetBody(held) == 0 && dGeomGetSpace(held) == 0);
    dGeomTransformSetGeom(t2, 0);   // held is free again
    dGeomDestroy(held);
    dGeomDestroy(on_body);
    dGeomDestroy(t);
    dGeomDestroy(t2);
    dSpaceDestroy(space);
    dWorldDestroy(w);
    return 0;
}

// ---- backends -----------------------------------------------------------------------------

// A fake backend: sphere-sphere only, one contact with a marker depth.
#define MARKER_DEPTH 1234.5
static int fake_changed, fake_destroyed;

static int fake_supports(int c1, int c2) { return c1 == dSphereClass && c2 == dSphereClass; }

static int fake_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    const dReal *p = dGeomGetPosition(o1);
    c->pos[0] = p[0];
    c->pos[1] = p[1];
    c->pos[2] = p[2];
    c->normal[0] = c->normal[1] = 0;
    c->normal[2] = 1;
    c->depth = MARKER_DEPTH;
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = c->side2 = -1;
    return 1;
}

static void fake_geom_changed(dGeomID g)
{
    (void)g;
    fake_changed++;
}

static void fake_geom_destroyed(dGeomID g)
{
    (void)g;
    fake_destroyed++;
}

static const dCollisionBackend fake_backend = { "fake", fake_supports, fake_collide,
                                                fake_geom_changed, fake_geom_destroyed };

static int test_native_is_the_default_backend(void)
{
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    const char *const *names = dCollisionListBackends();
    int found = 0, n = 0;
    for (; names[n]; n++) found += strcmp(names[n], "native") == 0;
    CHECK(found == 1 && n >= 1);
    test_capture_reports();
    CHECK(dCollisionSetBackend("nope") == 0);
    CHECK(test_captured_count() == 1 && test_captured_contains("no collision backend named"));
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    return 0;
}

static int test_registered_backend_gets_its_pairs_and_native_the_rest(void)
{
    CHECK(dCollisionRegisterBackend(&fake_backend) == 1);
    CHECK(dCollisionRegisterBackend(&fake_backend) == 0);   // the name is taken
    dGeomID s1, s2;
    overlapping_spheres(&s1, &s2);
    dGeomID b1 = dCreateBox(0, 1, 1, 1), b2 = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(b2, 0, 0, 0.9);
    dContactGeom c[8];
    CHECK(dCollisionSetBackend("fake") == 1);
    CHECK(strcmp(dCollisionGetBackend(), "fake") == 0);
    test_capture_reports();

    CHECK(dCollide(s1, s2, 8, c, sizeof c[0]) == 1 && c[0].depth == MARKER_DEPTH);
    int n = dCollide(b1, b2, 8, c, sizeof c[0]);   // native, with one message
    CHECK(n >= 1 && c[0].depth < 1);
    CHECK_NEAR(c[0].depth, 0.1, TOL(1e-9, 1e-5));
    CHECK(dCollide(b2, b1, 8, c, sizeof c[0]) >= 1 && dCollide(s1, b1, 8, c, sizeof c[0]) >= 1);

    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("fake") && test_captured_contains("native"));
    // Geoms of user classes and transforms still go their own ways.
    dGeomID u = create_ball(0, 1), t = dCreateGeomTransform(0), held = dCreateSphere(0, 1);
    dGeomSetPosition(s2, 0, 0, 1.5);
    CHECK(dCollide(u, s2, 1, c, sizeof c[0]) == 1 && c[0].depth == (dReal)0.5);
    dGeomTransformSetGeom(t, held);
    CHECK(dCollide(t, s2, 1, c, sizeof c[0]) == 1 && c[0].depth == MARKER_DEPTH);
    dGeomDestroy(u);
    dGeomDestroy(t);
    dGeomDestroy(held);
    dGeomID all[4] = { s1, s2, b1, b2 };
    for (int i = 0; i < 4; i++) dGeomDestroy(all[i]);
    dCollisionSetBackend("native");
    return 0;
}

static int test_strict_mode_makes_the_fallback_an_error(void)
{
    dGeomID b1 = dCreateBox(0, 1, 1, 1), b2 = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(b2, 0, 0, 0.9);
    dContactGeom c[8];
    memset(c, 0, sizeof c);
    CHECK(dCollisionSetBackend("fake") == 1);
    dCollisionSetStrict(1);
    test_capture_reports();

    int n = dCollide(b1, b2, 8, c, sizeof c[0]);
    dCollisionSetStrict(0);
    dCollisionSetBackend("native");

    CHECK(n == 0 && c[0].g1 == 0);
    CHECK(test_captured_count() == 1 && test_captured_contains("strict"));
    dGeomDestroy(b1);
    dGeomDestroy(b2);
    return 0;
}

static int test_backends_hear_of_shape_changes_and_destruction(void)
{
    dGeomID s = dCreateSphere(0, 1);
    int changed = fake_changed, destroyed = fake_destroyed;

    dGeomSphereSetRadius(s, 2);
    dGeomDestroy(s);

    CHECK(fake_changed == changed + 1 && fake_destroyed == destroyed + 1);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_set_body_shares_the_pose_both_ways),
    TEST_CASE(test_detaching_keeps_the_last_pose),
    TEST_CASE(test_geom_follows_its_body_through_dWorldStep),
    TEST_CASE(test_geom_follows_its_body_through_dWorldQuickStep),
    TEST_CASE(test_body_destroy_detaches_its_geoms_which_keep_the_pose),
    TEST_CASE(test_aabb_is_cached_until_the_geom_moves),
    TEST_CASE(test_class_aabbs),
    TEST_CASE(test_size_change_updates_the_aabb),
    TEST_CASE(test_body_geom_list_walk_and_unlink),
    TEST_CASE(test_moving_a_body_with_three_geoms_moves_all),
    TEST_CASE(test_placeable_only_calls_on_plane_and_space_are_reported),
    TEST_CASE(test_class_parameters_round_trip),
    TEST_CASE(test_non_unit_plane_normal_is_normalised),
    TEST_CASE(test_bad_sizes_are_reported_and_change_nothing),
    TEST_CASE(test_class_getter_on_wrong_class_is_reported),
    TEST_CASE(test_ray_set_and_get_round_trip_with_unit_direction),
    TEST_CASE(test_bits_enable_data_class_and_space_queries),
    TEST_CASE(test_class_numbers),
    TEST_CASE(test_sphere_point_depth),
    TEST_CASE(test_box_point_depth),
    TEST_CASE(test_capsule_point_depth),
    TEST_CASE(test_plane_point_depth),
    TEST_CASE(test_collide_flags_zero_means_one),
    TEST_CASE(test_collide_small_skip_is_reported),
    TEST_CASE(test_collide_self_same_body_and_separated_touch_nothing),
    TEST_CASE(test_collide_writes_with_the_stride),
    TEST_CASE(test_collide_with_a_space_collides_its_contents),
    TEST_CASE(test_destroying_a_geom_removes_it_from_its_space),
    TEST_CASE(test_bad_handles_are_reported),
    TEST_CASE(test_user_class_geom_and_class_data),
    TEST_CASE(test_user_class_collides_both_ways_round),
    TEST_CASE(test_user_class_dtor_runs_on_destroy),
    TEST_CASE(test_user_geom_in_a_space_is_found),
    TEST_CASE(test_user_aabb_test_can_veto_a_pair),
    TEST_CASE(test_transform_collides_where_the_offset_puts_the_geom),
    TEST_CASE(test_transform_info_mode_names_the_geom_or_the_transform),
    TEST_CASE(test_transform_box_follows_the_held_geom),
    TEST_CASE(test_transform_cleanup_destroys_the_held_geom),
    TEST_CASE(test_transform_on_a_body_in_a_space),
    TEST_CASE(test_transform_refuses_geoms_in_a_space_or_on_a_body),
    TEST_CASE(test_native_is_the_default_backend),
    TEST_CASE(test_registered_backend_gets_its_pairs_and_native_the_rest),
    TEST_CASE(test_strict_mode_makes_the_fallback_an_error),
    TEST_CASE(test_backends_hear_of_shape_changes_and_destruction),
    TEST_CASE(test_fifth_user_class_is_reported),
    TEST_END
};
