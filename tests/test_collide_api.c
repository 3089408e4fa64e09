// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_api.c -- the smaller collision calls of ODE 0.16:
// dGeomRaySetParams/GetParams, dSetColliderOverride, dGeomLowLevelControl
// (with a handler registered the way a class with codes registers it) and
// dSpaceSetManualCleanup/GetManualCleanup. White-box: linked with the
// internals, for dxGeomRegisterControl and the liveness of handles.

#include "test.h"
#include "geom_internal.h"

#include <string.h>

// dGeomRaySetParams and dGeomRayGetParams are deprecated, and tested here.
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

// ---- ray parameters ---------------------------------------------------------------

static int test_ray_params_set_both_flags_and_read_them_as_0_or_1(void)
{
    dGeomID r = dCreateRay(0, 1);
    int fc = 7, bc = 7;

    dGeomRayGetParams(r, &fc, &bc);
    CHECK(fc == 0 && bc == 0);
    dGeomRaySetParams(r, 5, 1);
    dGeomRayGetParams(r, &fc, &bc);
    CHECK(fc == 1 && bc == 1);
    CHECK(dGeomRayGetFirstContact(r) == 1 && dGeomRayGetBackfaceCull(r) == 1);
    dGeomRaySetParams(r, 0, 1);
    dGeomRayGetParams(r, &fc, &bc);
    CHECK(fc == 0 && bc == 1);
    CHECK(dGeomRayGetClosestHit(r) == 0);   // the third flag is not touched
    dGeomDestroy(r);
    return 0;
}

static int test_ray_params_of_a_non_ray_are_reported(void)
{
    test_capture_reports();
    dGeomID s = dCreateSphere(0, 1);
    dGeomID r = dCreateRay(0, 1);
    int fc = 7, bc = 7;

    dGeomRaySetParams(s, 1, 1);
    dGeomRayGetParams(s, &fc, &bc);
    dGeomRayGetParams(r, NULL, &bc);

    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("dGeomRaySetParams: geom is a sphere, not a ray"));
    CHECK(test_captured_contains("dGeomRayGetParams: FirstContact or BackfaceCull is NULL"));
    CHECK(fc == 7 && bc == 7);
    dGeomDestroy(s);
    dGeomDestroy(r);
    test_release_reports();
    return 0;
}

// ---- collider overrides -----------------------------------------------------------

static int calls;
static dGeomID called_o1, called_o2;

// A collider whose contact is recognisable: depth 0.5, normal +z, at (1,2,3).
static int marker_collider(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    calls++;
    called_o1 = o1;
    called_o2 = o2;
    memset(c, 0, sizeof *c);
    c->pos[0] = 1;
    c->pos[1] = 2;
    c->pos[2] = 3;
    c->normal[2] = 1;
    c->depth = 0.5;
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = 4;
    c->side2 = 9;
    return 1;
}

static int test_override_answers_in_place_of_the_backend(void)
{
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomID b = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(b, 100, 0, 0);   // far apart: the backend would say 0
    dSetColliderOverride(dSphereClass, dBoxClass, marker_collider);
    dContactGeom c;
    calls = 0;

    int n = dCollide(s, b, 1, &c, sizeof c);

    CHECK(n == 1 && calls == 1);
    CHECK(called_o1 == s && called_o2 == b);
    CHECK(c.g1 == s && c.g2 == b && c.depth == 0.5);
    CHECK_VEC(c.normal, 0, 0, 1, 0);
    dGeomDestroy(s);
    dGeomDestroy(b);
    return 0;
}

// (j, i) calls the same collider with the geoms in its order, and mirrors
// the contacts back: normal negated, g1/g2 and side1/side2 swapped.
static int test_override_serves_the_reversed_pair_mirrored(void)
{
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomID c = dCreateCapsule(0, 0.5, 1);
    dSetColliderOverride(dSphereClass, dCapsuleClass, marker_collider);
    dContactGeom k;
    calls = 0;

    int n = dCollide(c, s, 1, &k, sizeof k);

    CHECK(n == 1 && calls == 1);
    CHECK(called_o1 == s && called_o2 == c);
    CHECK(k.g1 == c && k.g2 == s);
    CHECK(k.side1 == 9 && k.side2 == 4);
    CHECK_VEC(k.normal, 0, 0, -1, 0);
    CHECK_VEC(k.pos, 1, 2, 3, 0);
    dGeomDestroy(s);
    dGeomDestroy(c);
    return 0;
}

// A NULL override makes the pair give no contacts (ODE's table entry empty).
static int test_null_override_makes_the_pair_collide_nothing(void)
{
    dGeomID a = dCreateCylinder(0, 0.5, 1);
    dGeomID b = dCreateCylinder(0, 0.5, 1);
    dContactGeom c;
    CHECK(dCollide(a, b, 1, &c, sizeof c) == 1);   // overlapping

    dSetColliderOverride(dCylinderClass, dCylinderClass, NULL);

    CHECK(dCollide(a, b, 1, &c, sizeof c) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

// Geoms of one body still never touch; the override is not asked.
static int test_override_is_not_asked_for_geoms_of_one_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body = dBodyCreate(w);
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomID p = dCreatePlane(0, 0, 0, 1, 0);
    dGeomID r = dCreateRay(0, 2);
    dGeomSetBody(s, body);
    dGeomSetBody(r, body);
    dSetColliderOverride(dSphereClass, dRayClass, marker_collider);
    dContactGeom c;
    calls = 0;

    CHECK(dCollide(s, r, 1, &c, sizeof c) == 0);
    CHECK(dCollide(s, s, 1, &c, sizeof c) == 0);
    CHECK(calls == 0);
    dGeomDestroy(s);
    dGeomDestroy(p);
    dGeomDestroy(r);
    dWorldDestroy(w);
    return 0;
}

// The override also wins over a geometry transform's unwrapping, and
// applies inside it (the held geom's class pair) and inside spaces.
static int test_override_applies_at_every_level_of_dcollide(void)
{
    dGeomID t = dCreateGeomTransform(0);
    dGeomID held = dCreateBox(0, 1, 1, 1);
    dGeomTransformSetGeom(t, held);
    dGeomTransformSetCleanup(t, 1);
    dGeomID s = dCreateSphere(0, 0.5);   // sphere-box is overridden above
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID in_space = dCreateSphere(space, 0.5);
    dGeomSetPosition(in_space, 50, 0, 0);
    dGeomID far_box = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(far_box, -50, 0, 0);
    dSetColliderOverride(dSphereClass, dBoxClass, marker_collider);
    dContactGeom c;

    calls = 0;
    CHECK(dCollide(t, s, 1, &c, sizeof c) == 1);
    CHECK(calls == 1 && called_o1 == s && called_o2 == held);
    calls = 0;
    CHECK(dCollide((dGeomID)space, far_box, 1, &c, sizeof c) == 1);
    CHECK(calls == 1 && called_o1 == in_space && called_o2 == far_box);

    dSetColliderOverride(dGeomTransformClass, dSphereClass, NULL);
    calls = 0;
    CHECK(dCollide(s, t, 1, &c, sizeof c) == 0);
    CHECK(calls == 0);
    dGeomDestroy(t);
    dGeomDestroy(s);
    dSpaceDestroy(space);
    dGeomDestroy(far_box);
    return 0;
}

static int test_override_of_a_bad_class_number_is_reported(void)
{
    test_capture_reports();

    dSetColliderOverride(-1, dBoxClass, marker_collider);
    dSetColliderOverride(dBoxClass, dGeomNumClasses, marker_collider);

    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("dSetColliderOverride: class i (-1) is not a class number"));
    test_release_reports();
    return 0;
}

// ---- low-level control --------------------------------------------------------------

static int test_control_of_a_geom_without_codes_fails_and_is_reported(void)
{
    test_capture_reports();
    dGeomID s = dCreateSphere(0, 1);
    int size = 4, value = 1;

    int ok = dGeomLowLevelControl(s, dGeomColliderControlClass,
                                  dGeomColliderSetMergeSphereContactsControlCode, &value, &size);

    CHECK(ok == 0 && size == 0);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dGeomLowLevelControl: a sphere has no control codes"));
    size = 0;
    ok = dGeomLowLevelControl(s, dGeomCommonControlClass, dGeomCommonAnyControlCode, NULL, &size);
    CHECK(ok == 0 && test_captured_count() == 2);
    ok = dGeomLowLevelControl(s, dGeomCommonControlClass, dGeomCommonAnyControlCode, NULL, NULL);
    CHECK(ok == 0 && test_captured_contains("dataSize is NULL"));
    dGeomDestroy(s);
    test_release_reports();
    return 0;
}

// A class with codes (as a triangle mesh would register them): the collider
// class's merge setting, an int, with ODE's size protocol.
static int merge_setting = dGeomColliderMergeContactsValue_Normals;

static int merge_control(dxGeom *g, int cls, int code, void *data, int *size)
{
    (void)g;
    if (cls != dGeomColliderControlClass) return 0;
    if (code == dGeomCommonAnyControlCode) return dxGeomControlSizeValid(data, size, 0);
    if (!dxGeomControlSizeValid(data, size, (int)sizeof(int))) return 0;
    if (code == dGeomColliderSetMergeSphereContactsControlCode) {
        merge_setting = *(int *)data;
        return 1;
    }
    if (code == dGeomColliderGetMergeSphereContactsControlCode) {
        *(int *)data = merge_setting;
        return 1;
    }
    return 0;
}

static void infinite_aabb(dGeomID g, dReal aabb[6])
{
    dInfiniteAABB(g, aabb);
}

static dColliderFn *no_collider(int other_class)
{
    (void)other_class;
    return NULL;
}

static int test_control_reaches_the_handler_of_the_geoms_class(void)
{
    dGeomClass info = { 0, no_collider, infinite_aabb, NULL, NULL };
    const int cls = dCreateGeomClass(&info);
    dGeomID g = dCreateGeom(cls);
    dxGeomRegisterControl(cls, merge_control);
    int size = 0, value = 0;

    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass, dGeomCommonAnyControlCode, NULL,
                               &size) == 1);
    // Asking with no data gives the size wanted.
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass,
                               dGeomColliderGetMergeSphereContactsControlCode, NULL, &size) == 0);
    CHECK(size == (int)sizeof(int));
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass,
                               dGeomColliderGetMergeSphereContactsControlCode, &value, &size) == 1);
    CHECK(value == dGeomColliderMergeContactsValue_Normals);
    value = dGeomColliderMergeContactsValue_Full;
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass,
                               dGeomColliderSetMergeSphereContactsControlCode, &value, &size) == 1);
    CHECK(merge_setting == dGeomColliderMergeContactsValue_Full);
    dGeomDestroy(g);
    return 0;
}

// ---- manual cleanup mark --------------------------------------------------------------

static int test_manual_cleanup_mark_is_kept_per_space(void)
{
    dSpaceID parent = dHashSpaceCreate(0);
    dSpaceID child = dSimpleSpaceCreate(0);

    CHECK(dSpaceGetManualCleanup(parent) == 0);
    dSpaceSetManualCleanup(child, 5);
    CHECK(dSpaceGetManualCleanup(child) == 1);
    dSpaceAdd(parent, (dGeomID)child);   // inserting changes neither mark
    CHECK(dSpaceGetManualCleanup(child) == 1);
    CHECK(dSpaceGetManualCleanup(parent) == 0);
    CHECK(dSpaceGetCleanup(child) == 1);   // independent of the cleanup flag
    dSpaceSetManualCleanup(child, 0);
    CHECK(dSpaceGetManualCleanup(child) == 0);
    dSpaceDestroy(parent);
    return 0;
}

// Destroying is governed by dSpaceSetCleanup alone, whatever the mark.
static int test_manual_cleanup_mark_does_not_change_destruction(void)
{
    dSpaceID parent = dSimpleSpaceCreate(0);
    dSpaceID kept_parent = dSimpleSpaceCreate(0);
    dSpaceSetCleanup(kept_parent, 0);
    dSpaceSetManualCleanup(parent, 1);
    dSpaceSetManualCleanup(kept_parent, 1);
    dGeomID a = dCreateSphere(parent, 1);
    dGeomID b = dCreateSphere(kept_parent, 1);

    dSpaceDestroy(parent);
    dSpaceDestroy(kept_parent);

    CHECK(!dxGeomIsLive(a));
    CHECK(dxGeomIsLive(b) && dGeomGetSpace(b) == NULL);
    dGeomDestroy(b);
    return 0;
}

static int test_manual_cleanup_of_a_non_space_is_reported(void)
{
    test_capture_reports();
    dGeomID s = dCreateSphere(0, 1);

    dSpaceSetManualCleanup((dSpaceID)s, 1);
    int m = dSpaceGetManualCleanup((dSpaceID)s);

    CHECK(m == 0);
    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("dSpaceSetManualCleanup: space is NULL, was destroyed"));
    dGeomDestroy(s);
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_ray_params_set_both_flags_and_read_them_as_0_or_1),
    TEST_CASE(test_ray_params_of_a_non_ray_are_reported),
    TEST_CASE(test_override_answers_in_place_of_the_backend),
    TEST_CASE(test_override_serves_the_reversed_pair_mirrored),
    TEST_CASE(test_null_override_makes_the_pair_collide_nothing),
    TEST_CASE(test_override_is_not_asked_for_geoms_of_one_body),
    TEST_CASE(test_override_applies_at_every_level_of_dcollide),
    TEST_CASE(test_override_of_a_bad_class_number_is_reported),
    TEST_CASE(test_control_of_a_geom_without_codes_fails_and_is_reported),
    TEST_CASE(test_control_reaches_the_handler_of_the_geoms_class),
    TEST_CASE(test_manual_cleanup_mark_is_kept_per_space),
    TEST_CASE(test_manual_cleanup_mark_does_not_change_destruction),
    TEST_CASE(test_manual_cleanup_of_a_non_space_is_reported),
    TEST_END
};
