// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_dispatch.c -- dCollide's shortcut to the native colliders
// (collide.c, backend.c: dx_routes). For every pair of built-in classes, in
// both orders, dCollide answers exactly (bit for bit) what the native
// backend's own entry answers; what changes the path -- another backend
// selected, a shadow backend, an override -- takes effect at once, also
// after pairs went the short way; geoms of one body, a geom with itself and
// bad arguments are answered as before. White-box: the native backend's
// table is compared directly.

#include "test.h"
#include "backend_internal.h"

#include <math.h>
#include <ode/backend.h>
#include <stdio.h>
#include <string.h>

enum { MAXC = 8 };

// One geom of each built-in class except the transform, posed so that each
// overlaps the others near the origin.
static dGeomID make_geom(int cls)
{
    static dTriMeshDataID mesh;
    static const dReal verts[] = { -2, -2, 0.1, 2, -2, 0.1, 2, 2, 0.1, -2, 2, 0.1 };
    static const dTriIndex tris[] = { 0, 1, 2, 0, 2, 3 };
    static dReal planes[] = { 1, 0, 0, 0.4, -1, 0, 0, 0.4, 0, 1, 0, 0.4,
                              0, -1, 0, 0.4, 0, 0, 1, 0.4, 0, 0, -1, 0.4 };
    static dReal points[] = { 0.4, 0.4, 0.4, -0.4, 0.4, 0.4, 0.4, -0.4, 0.4, -0.4, -0.4, 0.4,
                              0.4, 0.4, -0.4, -0.4, 0.4, -0.4, 0.4, -0.4, -0.4, -0.4, -0.4, -0.4 };
    static unsigned polygons[] = { 4, 0, 2, 6, 4, 4, 1, 5, 7, 3, 4, 0, 4, 5, 1,
                                   4, 2, 3, 7, 6, 4, 0, 1, 3, 2, 4, 4, 6, 7, 5 };
    dGeomID g = NULL;
    switch (cls) {
    case dSphereClass: g = dCreateSphere(0, 0.5); break;
    case dBoxClass: g = dCreateBox(0, 0.8, 0.9, 1.0); break;
    case dCapsuleClass: g = dCreateCapsule(0, 0.3, 0.8); break;
    case dCylinderClass: g = dCreateCylinder(0, 0.4, 0.7); break;
    case dPlaneClass: g = dCreatePlane(0, 0, 0, 1, 0.05); break;
    case dRayClass:
        g = dCreateRay(0, 3);
        dGeomRaySet(g, 0.05, 0.02, 1.5, 0, 0, -1);
        return g;
    case dConvexClass: g = dCreateConvex(0, planes, 6, points, 8, polygons); break;
    case dTriMeshClass:
        if (!mesh) {
            mesh = dGeomTriMeshDataCreate();
            dGeomTriMeshDataBuildSingle(mesh, verts, 3 * sizeof(dReal), 4, tris, 6,
                                        3 * sizeof(dTriIndex));
        }
        g = dCreateTriMesh(0, mesh, NULL, NULL, NULL);
        break;
    case dHeightfieldClass: {
        static dHeightfieldDataID field;
        static const double heights[9] = { 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1 };
        if (!field) {
            field = dGeomHeightfieldDataCreate();
            dGeomHeightfieldDataBuildDouble(field, heights, 0, 4, 4, 3, 3, 1, 0, 1, 0);
        }
        g = dCreateHeightfield(0, field, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0, 0, M_PI / 2);   // the field's up (y) along z
        dGeomSetRotation(g, R);
        return g;
    }
    }
    if (cls != dPlaneClass) {
        dGeomSetPosition(g, 0.03 * cls, -0.02 * cls, 0.2 + 0.01 * cls);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 2, 3, 0.1 * cls);
        dGeomSetRotation(g, R);
    }
    return g;
}

// The contacts through the native backend's entry, and through dCollide.
static int native_contacts(dGeomID a, dGeomID b, dContactGeom *c)
{
    memset(c, 0, MAXC * sizeof *c);
    return dxNativeBackend()->collide(a, b, MAXC, c, sizeof *c);
}

static int dcollide_contacts(dGeomID a, dGeomID b, dContactGeom *c)
{
    memset(c, 0, MAXC * sizeof *c);
    return dCollide(a, b, MAXC, c, sizeof *c);
}

static const int classes[] = { dSphereClass, dBoxClass,     dCapsuleClass, dCylinderClass,
                               dPlaneClass,  dRayClass,     dConvexClass,  dTriMeshClass,
                               dHeightfieldClass };
enum { NCLASSES = sizeof classes / sizeof classes[0] };

static int test_every_pair_of_classes_gets_the_native_answer_bit_for_bit(void)
{
    dGeomID g[NCLASSES], h[NCLASSES];   // h: a second geom of each class, moved a little
    for (int i = 0; i < NCLASSES; i++) {
        g[i] = make_geom(classes[i]);
        h[i] = make_geom(classes[i]);
        if (classes[i] == dPlaneClass) continue;
        const dReal *p = dGeomGetPosition(h[i]);
        dGeomSetPosition(h[i], p[0] + 0.05, p[1] - 0.04, p[2] + (classes[i] == dRayClass ? 0 : 0.1));
    }
    int pairs_with_contacts = 0;

    for (int i = 0; i < NCLASSES; i++)
        for (int j = 0; j < NCLASSES; j++) {
            dContactGeom want[MAXC], got[MAXC];
            const int nw = native_contacts(g[i], h[j], want);
            const int ng = dcollide_contacts(g[i], h[j], got);
            if (ng != nw || memcmp(want, got, sizeof want) != 0)
                printf("# classes %d, %d: %d contacts natively, %d by dCollide\n", classes[i],
                       classes[j], nw, ng);
            CHECK(ng == nw);
            CHECK(memcmp(want, got, sizeof want) == 0);
            pairs_with_contacts += ng > 0;
        }

    CHECK(pairs_with_contacts > 40);   // the scene does exercise the colliders
    for (int i = 0; i < NCLASSES; i++) {
        dGeomDestroy(g[i]);
        dGeomDestroy(h[i]);
    }
    return 0;
}

// A reversed pair: the contacts of (b, a) mirrored.
static int test_reversed_pair_is_mirrored(void)
{
    dGeomID s = make_geom(dSphereClass), b = make_geom(dBoxClass);
    dContactGeom sb[MAXC], bs[MAXC];

    const int n = dcollide_contacts(s, b, sb);
    CHECK(n == 1 && dcollide_contacts(b, s, bs) == 1);

    CHECK(bs[0].g1 == b && bs[0].g2 == s && bs[0].depth == sb[0].depth);
    CHECK(bs[0].normal[0] == -sb[0].normal[0] && bs[0].normal[1] == -sb[0].normal[1] &&
          bs[0].normal[2] == -sb[0].normal[2]);
    dGeomDestroy(s);
    dGeomDestroy(b);
    return 0;
}

static int test_geoms_of_one_body_and_a_geom_with_itself_do_not_touch(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body = dBodyCreate(w);
    dGeomID a = make_geom(dSphereClass), b = make_geom(dSphereClass);
    dContactGeom c[MAXC];
    CHECK(dcollide_contacts(a, b, c) == 1);

    dGeomSetBody(a, body);
    dGeomSetBody(b, body);

    CHECK(dcollide_contacts(a, b, c) == 0);
    CHECK(dcollide_contacts(a, a, c) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dWorldDestroy(w);
    return 0;
}

static int test_bad_arguments_are_still_reported(void)
{
    dGeomID a = make_geom(dSphereClass), b = make_geom(dSphereClass);
    dContactGeom c[MAXC];
    test_capture_reports();

    CHECK(dCollide(a, NULL, 1, c, sizeof c[0]) == 0);
    CHECK(dCollide(a, b, 1, c, sizeof c[0] - 1) == 0);
    CHECK(dCollide(a, b, 1, NULL, sizeof c[0]) == 0);

    CHECK(test_captured_count() == 3);
    CHECK(test_captured_contains("o2 is NULL"));
    CHECK(test_captured_contains("skip"));
    CHECK(test_captured_contains("contact is NULL"));
    test_release_reports();
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

// A backend that counts its calls and answers one fixed contact.
static int counted;
static int counting_supports(int c1, int c2)
{
    (void)c1;
    (void)c2;
    return 1;
}
static int counting_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    counted++;
    memset(c, 0, sizeof *c);
    c->depth = 0.25;
    c->normal[2] = 1;
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = c->side2 = -1;
    return 1;
}
static const dCollisionBackend counting = { "counting", counting_supports, counting_collide,
                                            NULL, NULL };

// Pairs went the short way; then the selection and the shadow change.
static int test_selecting_another_backend_or_a_shadow_takes_effect_at_once(void)
{
    dGeomID a = make_geom(dSphereClass), b = make_geom(dBoxClass);
    dContactGeom c[MAXC];
    CHECK(dcollide_contacts(a, b, c) == 1 && c[0].depth != 0.25);
    CHECK(dCollisionRegisterBackend(&counting) == 1);
    counted = 0;

    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 0);   // native still selected
    CHECK(dCollisionSetBackend("counting") == 1);
    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 1 && c[0].depth == 0.25);
    CHECK(dCollisionSetBackend("native") == 1);
    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 1 && c[0].depth != 0.25);
    CHECK(dCollisionSetShadowBackend("counting") == 1);
    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 2 && c[0].depth != 0.25);
    CHECK(dCollisionSetShadowBackend(NULL) == 1);
    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 2);

    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int marker(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    return counting_collide(o1, o2, flags, c, skip);
}

static int test_an_override_set_after_pairs_went_the_short_way_is_used(void)
{
    dGeomID a = make_geom(dCapsuleClass), b = make_geom(dCapsuleClass);
    dContactGeom c[MAXC];
    CHECK(dcollide_contacts(a, b, c) >= 1 && c[0].depth != 0.25);
    counted = 0;

    dSetColliderOverride(dCapsuleClass, dCapsuleClass, marker);

    CHECK(dcollide_contacts(a, b, c) == 1 && counted == 1 && c[0].depth == 0.25);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_every_pair_of_classes_gets_the_native_answer_bit_for_bit),
    TEST_CASE(test_reversed_pair_is_mirrored),
    TEST_CASE(test_geoms_of_one_body_and_a_geom_with_itself_do_not_touch),
    TEST_CASE(test_bad_arguments_are_still_reported),
    TEST_CASE(test_selecting_another_backend_or_a_shadow_takes_effect_at_once),
    TEST_CASE(test_an_override_set_after_pairs_went_the_short_way_is_used),
    TEST_END
};
