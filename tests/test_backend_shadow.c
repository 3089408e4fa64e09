// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_shadow.c -- shadow mode (backend.h). meson runs it with
// ODE_COLLISION_BACKEND=native,native, which the first case checks. A scene
// stepped with native shadowing native agrees with itself on every call; a
// fake shadow whose answers are wrong in known ways gives exactly those
// disagreements, with poses and both results kept; the program always sees
// the first backend's contacts; FCL and Bullet (skipped when not built)
// shadowing a box resting on a plane report a reduced manifold exactly when
// that backend gives one contact there; FCL and Bullet, both caching
// shapes, keep their own under shadow mode; bad arguments are reported.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <ode/backend.h>
#include <stdio.h>
#include <string.h>

enum { MAXC = 8, NPAIRS = dGeomNumClasses * (dGeomNumClasses + 1) / 2 };

// The counts of one pair class (zeroed when it was never seen).
static dCollisionShadowStats stats_of(int c1, int c2)
{
    dCollisionShadowStats all[NPAIRS], none;
    memset(&none, 0, sizeof none);
    int n = dCollisionShadowGetStats(all, NPAIRS);
    for (int i = 0; i < n; i++)
        if (all[i].class1 == (c1 < c2 ? c1 : c2) && all[i].class2 == (c1 < c2 ? c2 : c1))
            return all[i];
    return none;
}

// ---- a scene stepped under shadow mode ---------------------------------------

typedef struct scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    unsigned long backend_calls;   // dCollide calls of two non-space geoms
} scene;

static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *s = data;
    dContactGeom c[MAXC];
    s->backend_calls++;
    int n = dCollide(a, b, MAXC, c, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        dContact k;
        memset(&k, 0, sizeof k);
        k.surface.mu = 0.5;
        k.geom = c[i];
        dJointAttach(dJointCreateContact(s->world, s->contacts, &k), dGeomGetBody(a),
                     dGeomGetBody(b));
    }
}

static dBodyID add_body(scene *s, dGeomID g, double x, double y, double z, double tilt)
{
    dBodyID b = dBodyCreate(s->world);
    dMass m;
    dMassSetSphere(&m, 1, 0.3);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 1, 0, tilt);
    dBodySetRotation(b, R);
    dGeomSetBody(g, b);
    return b;
}

static void scene_open(scene *s)
{
    memset(s, 0, sizeof *s);
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, -9.81);
    s->space = dSimpleSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    dCreatePlane(s->space, 0, 0, 1, 0);
}

static void scene_step(scene *s, int steps)
{
    for (int i = 0; i < steps; i++) {
        dSpaceCollide(s->space, s, near_callback);
        dWorldQuickStep(s->world, 0.01);
        dJointGroupEmpty(s->contacts);
    }
}

static void scene_close(scene *s)
{
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);
    dWorldDestroy(s->world);
}

static int test_the_environment_turns_shadow_mode_on(void)
{
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    const char *shadow = dCollisionGetShadowBackend();
    CHECK(shadow && strcmp(shadow, "native") == 0);
    return 0;
}

// Native against itself: every call compared, none disagrees, errors are zero.
static int test_native_shadowing_native_agrees(void)
{
    CHECK(dCollisionSetShadowBackend("native") == 1);
    dCollisionShadowReset();
    scene s;
    scene_open(&s);
    add_body(&s, dCreateBox(s.space, 1, 0.6, 0.4), 0, 0, 0.5, 0.3);
    add_body(&s, dCreateSphere(s.space, 0.3), 2, 0, 0.6, 0);
    add_body(&s, dCreateCapsule(s.space, 0.2, 0.8), 0, 2, 0.4, 1.5);
    add_body(&s, dCreateCylinder(s.space, 0.3, 0.5), 2, 2, 0.5, 0.7);
    add_body(&s, dCreateBox(s.space, 0.4, 0.4, 0.4), 0.2, 0.1, 1.4, 0.5);
    scene_step(&s, 150);
    dCollisionShadowStats all[NPAIRS];
    int n = dCollisionShadowGetStats(all, NPAIRS);
    CHECK(n >= 4);   // box, sphere, capsule, cylinder against the plane at least
    unsigned long calls = 0;
    for (int i = 0; i < n; i++) {
        CHECK(all[i].class1 <= all[i].class2);
        CHECK(all[i].disagreements == 0 && all[i].not_answered == 0);
        CHECK(all[i].worst_depth == 0 && all[i].worst_normal == 0);
        CHECK(all[i].worst_point_first == all[i].worst_point_shadow);
        calls += all[i].calls;
    }
    CHECK(calls == s.backend_calls);
    CHECK(stats_of(dBoxClass, dPlaneClass).calls > 0);
    scene_close(&s);
    return 0;
}

// ---- a shadow that lies in known ways ----------------------------------------

enum { LIE_DEEPER, LIE_NONE, LIE_FAR_POINT, LIE_SINGLE };
static int lie;

static int liar_supports(int c1, int c2)
{
    return (c1 == dSphereClass && c2 == dSphereClass) || (c1 == dBoxClass && c2 == dPlaneClass) ||
           (c1 == dPlaneClass && c2 == dBoxClass);
}

// Sphere-sphere: the true contact, then the lie. Box (o1) on plane (o2): one
// contact below the box centre, as deep as its lowest corner.
static int liar_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    memset(c, 0, sizeof *c);
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = c->side2 = -1;
    const dReal *p1 = dGeomGetPosition(o1), *p2;
    if (dGeomGetClass(o1) == dBoxClass) {
        dVector3 side;
        dGeomBoxGetLengths(o1, side);
        c->depth = side[2] / 2 - p1[2];
        c->normal[2] = 1;
        c->pos[0] = p1[0];
        c->pos[1] = p1[1];
        return 1;
    }
    p2 = dGeomGetPosition(o2);
    double d[3] = { p1[0] - p2[0], p1[1] - p2[1], p1[2] - p2[2] };
    double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    c->depth = dGeomSphereGetRadius(o1) + dGeomSphereGetRadius(o2) - dist;
    for (int k = 0; k < 3; k++) {
        c->normal[k] = d[k] / dist;
        c->pos[k] = (p1[k] + p2[k]) / 2;
    }
    switch (lie) {
    case LIE_DEEPER: {   // 0.1 deeper, normal turned 30 degrees about z
        c->depth += 0.1;
        double x = c->normal[0], y = c->normal[1];
        c->normal[0] = cos(M_PI / 6) * x - sin(M_PI / 6) * y;
        c->normal[1] = sin(M_PI / 6) * x + cos(M_PI / 6) * y;
        break;
    }
    case LIE_NONE: return 0;
    case LIE_FAR_POINT: c->pos[1] += 1; break;
    default: break;
    }
    return 1;
}

static const dCollisionBackend liar = { "liar", liar_supports, liar_collide, 0, 0 };

// dCollide of spheres of radius 0.5 at x = 0 and x = gap, under the lie
// told; returns the program's contact count and checks it got native's.
static int collide_spheres(dGeomID a, dGeomID b, double gap, int told)
{
    lie = told;
    dGeomSetPosition(a, 0, 0, 0);
    dGeomSetPosition(b, gap, 0, 0);
    dContactGeom c[MAXC];
    int n = dCollide(a, b, MAXC, c, sizeof c[0]);
    if (n != 1 || fabs(c[0].depth - (1 - gap)) > TOL(1e-12, 1e-6) ||
        fabs(c[0].normal[0] + 1) > TOL(1e-12, 1e-6))
        return -1;
    return n;
}

static int test_known_lies_are_the_disagreements_recorded(void)
{
    static int registered;
    if (!registered) registered = dCollisionRegisterBackend(&liar);
    CHECK(registered);
    CHECK(dCollisionSetShadowBackend("liar") == 1);
    CHECK(strcmp(dCollisionGetShadowBackend(), "liar") == 0);
    dCollisionShadowReset();
    CHECK(dCollisionShadowGetStats(NULL, 0) == 0);

    dGeomID a = dCreateSphere(0, 0.5), b = dCreateSphere(0, 0.5);
    CHECK(collide_spheres(a, b, 0.8, LIE_DEEPER) == 1);
    dCollisionShadowStats s = stats_of(dSphereClass, dSphereClass);
    CHECK(s.calls == 1 && s.disagreements == 1 && s.not_answered == 0);
    CHECK(s.kinds[1] == 1 && s.kinds[2] == 1);   // depth, normal
    CHECK(s.kinds[0] == 0 && s.kinds[3] == 0 && s.kinds[4] == 0);
    CHECK_NEAR(s.worst_depth, 0.1, TOL(1e-12, 1e-6));
    CHECK_NEAR(s.worst_normal, 30, TOL(1e-9, 1e-3));

    dCollisionShadowRecord r[dCOLLISION_SHADOW_RECORDS];
    CHECK(dCollisionShadowGetRecords(dSphereClass, dSphereClass, r, 4) == 1);
    CHECK(r[0].class1 == dSphereClass && r[0].class2 == dSphereClass);
    CHECK(r[0].kinds == (dCOLLISION_SHADOW_DEPTH | dCOLLISION_SHADOW_NORMAL));
    CHECK(r[0].params1[0] == 0.5 && r[0].pos2[0] == (dReal)0.8 && r[0].R1[0] == 1);
    CHECK(r[0].flags == MAXC && r[0].n_first == 1 && r[0].n_shadow == 1);
    CHECK_NEAR(r[0].first[0].depth, 0.2, TOL(1e-12, 1e-6));
    CHECK_NEAR(r[0].shadow[0].depth, 0.3, TOL(1e-12, 1e-6));
    CHECK(r[0].first[0].g1 == NULL && r[0].shadow[0].g2 == NULL);

    // No contact where native is 0.2 deep: a contact disagreement; 4 mm deep
    // is inside the depth tolerance, so not one.
    CHECK(collide_spheres(a, b, 0.8, LIE_NONE) == 1);
    CHECK(collide_spheres(a, b, 0.996, LIE_NONE) == 1);
    s = stats_of(dSphereClass, dSphereClass);
    CHECK(s.calls == 3 && s.disagreements == 2 && s.kinds[0] == 1);

    // A point 1 m off the overlap: outside both spheres by sqrt(0.4^2 + 1) - 0.5.
    CHECK(collide_spheres(a, b, 0.8, LIE_FAR_POINT) == 1);
    s = stats_of(dSphereClass, dSphereClass);
    CHECK(s.kinds[3] == 1);
    CHECK_NEAR(s.worst_point_shadow, sqrt(0.16 + 1) - 0.5, TOL(1e-9, 1e-5));
    CHECK(s.worst_point_first == 0);

    // Two more: counted, but only the first four are kept.
    CHECK(collide_spheres(a, b, 0.8, LIE_DEEPER) == 1);
    CHECK(collide_spheres(a, b, 0.8, LIE_DEEPER) == 1);
    s = stats_of(dSphereClass, dSphereClass);
    CHECK(s.disagreements == 5);
    CHECK(dCollisionShadowGetRecords(dSphereClass, dSphereClass, r, 4) == 4);
    CHECK(r[1].kinds == dCOLLISION_SHADOW_CONTACT && r[1].n_shadow == 0);
    CHECK(r[2].kinds == dCOLLISION_SHADOW_POINT);

    // A pair the shadow does not support: not answered.
    dGeomID box = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(box, 0.9, 0, 0);
    dContactGeom c[MAXC];
    CHECK(dCollide(a, box, MAXC, c, sizeof c[0]) >= 1);
    s = stats_of(dBoxClass, dSphereClass);
    CHECK(s.calls == 1 && s.not_answered == 1 && s.disagreements == 0);

    // A box resting on a plane: native gives its four corners, the liar one
    // point: a reduced manifold, and nothing else.
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0);
    dGeomSetPosition(box, 3, 0, 0.499);
    lie = LIE_SINGLE;
    CHECK(dCollide(box, plane, MAXC, c, sizeof c[0]) == 4);
    s = stats_of(dBoxClass, dPlaneClass);
    CHECK(s.calls == 1 && s.disagreements == 1 && s.kinds[4] == 1);
    CHECK(s.worst_depth < 1e-6 && s.worst_normal < 1e-3);
    // With one contact asked for, both give one: no manifold to compare.
    CHECK(dCollide(box, plane, 1, c, sizeof c[0]) == 1);
    CHECK(stats_of(dBoxClass, dPlaneClass).disagreements == 1);

    // The printed report: the table and the first disagreement of a class.
    FILE *f = tmpfile();
    CHECK(f != NULL);
    dCollisionShadowReport(f);
    char text[8192];
    rewind(f);
    size_t len = fread(text, 1, sizeof text - 1, f);
    text[len] = 0;
    fclose(f);
    CHECK(strstr(text, "\"native\" answers, \"liar\" shadows") != NULL);
    CHECK(strstr(text, "sphere-sphere") != NULL && strstr(text, "box-plane") != NULL);
    CHECK(strstr(text, "first disagreement: depth normal") != NULL);
    CHECK(strstr(text, "first disagreement: manifold") != NULL);

    // Off: nothing more is counted; reset forgets.
    CHECK(dCollisionSetShadowBackend(NULL) == 1);
    CHECK(dCollisionGetShadowBackend() == NULL);
    CHECK(collide_spheres(a, b, 0.8, LIE_DEEPER) == 1);
    CHECK(stats_of(dSphereClass, dSphereClass).calls == 6);
    dCollisionShadowReset();
    CHECK(dCollisionShadowGetStats(NULL, 0) == 0);
    CHECK(dCollisionShadowGetRecords(dSphereClass, dSphereClass, r, 4) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomDestroy(box);
    dGeomDestroy(plane);
    return 0;
}

static int test_bad_arguments_are_reported(void)
{
    test_capture_reports();
    int ok = dCollisionSetShadowBackend("nosuch") == 0 &&
             test_captured_contains("dCollisionSetShadowBackend") &&
             test_captured_contains("\"nosuch\"");
    dCollisionShadowStats s;
    dCollisionShadowRecord r;
    ok = ok && dCollisionShadowGetStats(&s, -1) == 0 && test_captured_contains("max");
    ok = ok && dCollisionShadowGetStats(NULL, 3) == 0 && test_captured_contains("out is NULL");
    ok = ok && dCollisionShadowGetRecords(-1, 0, &r, 1) == 0 && test_captured_contains("class1");
    ok = ok && dCollisionShadowGetRecords(0, dGeomNumClasses, &r, 1) == 0 &&
         test_captured_contains("class2");
    int before = test_captured_count();
    dCollisionShadowReport(NULL);
    ok = ok && test_captured_count() == before + 1 &&
         test_captured_contains("dCollisionShadowReport");
    ok = ok && dCollisionBackendSupports("nosuch", 0, 0) == 0 &&
         test_captured_contains("dCollisionBackendSupports");
    test_release_reports();
    CHECK(ok);
    CHECK(dCollisionBackendSupports("native", dBoxClass, dPlaneClass) == 1);
    return 0;
}

// ---- FCL and Bullet shadowing a resting box -----------------------------------

// How many contacts the backend gives for a box resting flat on a plane.
static int resting_box_contacts(const char *name)
{
    CHECK(dCollisionSetBackend(name) == 1);
    dGeomID box = dCreateBox(0, 1, 1, 1), plane = dCreatePlane(0, 0, 0, 1, 0);
    dGeomSetPosition(box, 0, 0, 0.499);
    dContactGeom c[MAXC];
    int n = dCollide(box, plane, MAXC, c, sizeof c[0]);
    dGeomDestroy(box);
    dGeomDestroy(plane);
    CHECK(dCollisionSetBackend("native") == 1);
    return n;
}

// A box dropped flat on a plane under native, with the backend shadowing:
// its only disagreement, if any, is the reduced manifold, on every resting
// call, exactly when it answers a resting box with one contact.
static int shadow_resting_box(const char *name)
{
    if (!backend_built(name)) return test_skip("backend not built");
    int resting = resting_box_contacts(name);
    CHECK(resting >= 1);
    CHECK(dCollisionSetShadowBackend(name) == 1);
    dCollisionShadowReset();
    scene s;
    scene_open(&s);
    add_body(&s, dCreateBox(s.space, 1, 1, 1), 0, 0, 0.52, 0);
    scene_step(&s, 100);
    dCollisionShadowStats b = stats_of(dBoxClass, dPlaneClass);
    printf("# %s shadowing native, box on plane: %lu calls, %lu disagreements "
           "(manifold %lu), worst depth %.3g, normal %.3g deg, point %.3g\n", name, b.calls,
           b.disagreements, b.kinds[4], b.worst_depth, b.worst_normal, b.worst_point_shadow);
    CHECK(b.calls == s.backend_calls && b.not_answered == 0);
    CHECK(b.kinds[0] == 0 && b.kinds[1] == 0 && b.kinds[2] == 0 && b.kinds[3] == 0);
    if (resting == 1) CHECK(b.kinds[4] > b.calls / 2);
    else CHECK(b.disagreements == 0);
    scene_close(&s);
    CHECK(dCollisionSetShadowBackend(NULL) == 1);
    return 0;
}

static int test_fcl_shadowing_a_resting_box(void) { return shadow_resting_box("fcl"); }
static int test_bullet_shadowing_a_resting_box(void) { return shadow_resting_box("bullet"); }

// FCL answering with Bullet shadowing: each keeps its own cached shapes
// (both use the geom's cache), so FCL's contacts are those it gives alone,
// also after a resize, and destroying the geoms frees both (the sanitizer
// build finds leaks).
static int test_two_caching_backends_keep_their_own_shapes(void)
{
    if (!backend_built("fcl") || !backend_built("bullet"))
        return test_skip("fcl and bullet are not both built");
    // Box-sphere: a pair both FCL and Bullet answer themselves.
    dGeomID box = dCreateBox(0, 1, 0.6, 0.4), ball = dCreateSphere(0, 0.3);
    dGeomSetPosition(ball, 0.5, 0.2, 0.3);
    dContactGeom alone[MAXC], shadowed[MAXC];
    CHECK(dCollisionSetBackend("fcl") == 1);
    for (int round = 0; round < 2; round++) {
        if (round == 1) dGeomBoxSetLengths(box, 1.2, 0.8, 0.5);
        CHECK(dCollisionSetShadowBackend("bullet") == 1);
        int n1 = dCollide(box, ball, MAXC, shadowed, sizeof shadowed[0]);
        CHECK(dCollisionSetShadowBackend(NULL) == 1);
        int n0 = dCollide(box, ball, MAXC, alone, sizeof alone[0]);
        CHECK(n0 >= 1 && n1 == n0);
        for (int i = 0; i < n0; i++) {
            CHECK(alone[i].depth == shadowed[i].depth);
            CHECK(memcmp(alone[i].pos, shadowed[i].pos, 3 * sizeof(dReal)) == 0);   // not the pad
            CHECK(memcmp(alone[i].normal, shadowed[i].normal, 3 * sizeof(dReal)) == 0);
        }
    }
    CHECK(dCollisionSetShadowBackend("bullet") == 1);
    dCollisionShadowReset();
    CHECK(dCollide(box, ball, MAXC, shadowed, sizeof shadowed[0]) >= 1);
    dCollisionShadowStats s = stats_of(dSphereClass, dBoxClass);
    CHECK(s.calls == 1 && s.not_answered == 0);
    dGeomDestroy(box);
    dGeomDestroy(ball);
    CHECK(dCollisionSetShadowBackend(NULL) == 1);
    CHECK(dCollisionSetBackend("native") == 1);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_the_environment_turns_shadow_mode_on),
    TEST_CASE(test_native_shadowing_native_agrees),
    TEST_CASE(test_known_lies_are_the_disagreements_recorded),
    TEST_CASE(test_bad_arguments_are_reported),
    TEST_CASE(test_fcl_shadowing_a_resting_box),
    TEST_CASE(test_bullet_shadowing_a_resting_box),
    TEST_CASE(test_two_caching_backends_keep_their_own_shapes),
    TEST_END
};
