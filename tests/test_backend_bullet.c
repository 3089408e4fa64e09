// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_bullet.c -- the Bullet backend (backends/bullet) through
// dCollide: hand-worked pairs both ways round (depth, normal sign, contact
// count and places, the separation rule, points inside both shapes, agreement
// with native), known Bullet gaps tagged as TAP comments, shapes resized and
// geoms destroyed while Bullet objects are cached, switching backends with the
// same geoms, geometry transforms, the native fallback for rays, and resting
// scenes through dSpaceCollide, contact joints and dWorldQuickStep. Built a
// second time with ODE_COLLISION_BACKEND=bullet (tests/meson.build), where the
// first case checks that the variable selects Bullet. Every case skips (with
// a TAP comment) when the library was built without Bullet.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ode/backend.h>

enum { MAXC = 16 };

// Exact algorithms (spheres, planes, box-box, capsule-capsule, GJK distances
// between a point or segment core and a box): rounding of a few dozen
// operations on sizes ~1, far below 1e-9 in double; Bullet in float keeps
// ~1e-7 relative per operation, so 1e-5.
#define EXACT TOL(1e-9, 1e-5)
// GJK/EPA on curved or margin-0 shapes stop at a tolerance, not at the exact
// answer. Depths: up to 1.2e-6 off (a sphere against a cylinder's side, over
// a range of poses); 1e-5 leaves a factor 8, and float Bullet adds its
// rounding. Normals converge as the square root of that: 6.1e-4 off there,
// EPA_NORMAL allows 2e-3 (BACKENDS.md section 7 allows 1e-3 rad per GJK pair).
#define EPA TOL(1e-5, 3e-4)
#define EPA_NORMAL 2e-3
// Separation margin: moved apart by depth + SEP, at most SEP deep.
#define SEP TOL(1e-6, 1e-4)

// ---- helpers ----------------------------------------------------------------

// Every case starts here: skip (pass with a TAP comment) without Bullet, else
// select it.
#define USE_BULLET() \
    do { \
        if (!backend_built("bullet")) \
            return test_skip("this library was built without the bullet backend"); \
        CHECK(dCollisionSetBackend("bullet") == 1); \
    } while (0)

// A shape to create: class, parameters as dCreate* takes them, position and
// a rotation about an axis.
typedef struct shape {
    int cls;
    dReal p[4];
    dReal pos[3];
    dReal axis[3], angle;
} shape;

static dGeomID make_geom(const shape *s)
{
    dGeomID g;
    switch (s->cls) {
    case dSphereClass: g = dCreateSphere(0, s->p[0]); break;
    case dBoxClass: g = dCreateBox(0, s->p[0], s->p[1], s->p[2]); break;
    case dCapsuleClass: g = dCreateCapsule(0, s->p[0], s->p[1]); break;
    case dCylinderClass: g = dCreateCylinder(0, s->p[0], s->p[1]); break;
    default: return dCreatePlane(0, s->p[0], s->p[1], s->p[2], s->p[3]);
    }
    dGeomSetPosition(g, s->pos[0], s->pos[1], s->pos[2]);
    if (s->angle != 0) {
        dMatrix3 R;
        dRFromAxisAndAngle(R, s->axis[0], s->axis[1], s->axis[2], s->angle);
        dGeomSetRotation(g, R);
    }
    return g;
}

// dCollide(a, b) with the checks every contact gets: count within max, g1 =
// a, g2 = b, sides -1, finite, unit normal, depth >= 0, pos in both shapes
// (point depth between -tol and the deepest depth + tol: a point of the
// overlap is no deeper in either shape than the translation that separates
// them), with tolerance mtol for all but the deepest contact. Returns the
// count, or -1 after reporting a failure.
static int collide_checked(dGeomID a, dGeomID b, int max, dContactGeom *c, double tol,
                           double mtol)
{
    int n = dCollide(a, b, max, c, sizeof *c);
    if (n < 0 || n > max) {
        test_fail(__FILE__, __LINE__, "count %d, max %d", n, max);
        return -1;
    }
    int top = deepest(c, n);
    dReal most = n ? c[top].depth : 0;
    for (int i = 0; i < n; i++) {
        const dContactGeom *k = &c[i];
        double t = i == top ? tol : mtol;
        dReal da = point_depth(a, k->pos), db = point_depth(b, k->pos);
        int ok = k->g1 == a && k->g2 == b && k->side1 == -1 && k->side2 == -1 &&
                 isfinite(k->depth) && k->depth >= 0 &&
                 fabs(dCalcVectorLength3(k->normal) - 1) <= EXACT && da >= -t &&
                 da <= most + t && db >= -t && db <= most + t;
        if (!ok) {
            test_fail(__FILE__, __LINE__, "contact %d: depth %g, pos %g %g %g, %g and %g deep "
                      "in the shapes (deepest %g)", i, (double)k->depth, (double)k->pos[0],
                      (double)k->pos[1], (double)k->pos[2], (double)da, (double)db, (double)most);
            return -1;
        }
    }
    return n;
}

// The deepest contact of (a, b) through the named backend (count in *n).
static dContactGeom deepest_with(const char *backend, dGeomID a, dGeomID b, int *n)
{
    const char *was = dCollisionGetBackend();
    dCollisionSetBackend(backend);
    dContactGeom c[MAXC], none;
    memset(&none, 0, sizeof none);
    *n = dCollide(a, b, MAXC, c, sizeof c[0]);
    dCollisionSetBackend(was);
    return *n ? c[deepest(c, *n)] : none;
}

// ---- the environment variable -------------------------------------------------

// First case: nothing has selected a backend yet. Under
// ODE_COLLISION_BACKEND=bullet the variable has selected Bullet, which then
// sends a ray pair to native with its one-time message; otherwise native is
// the default.
static int test_environment_selects_bullet(void)
{
    const char *env = getenv("ODE_COLLISION_BACKEND");
    if (!env || strcmp(env, "bullet") != 0) {
        printf("# ODE_COLLISION_BACKEND is not \"bullet\": native is the default\n");
        CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
        return 0;
    }
    if (!backend_built("bullet"))
        return test_skip("this library was built without the bullet backend");
    CHECK(strcmp(dCollisionGetBackend(), "bullet") == 0);
    dGeomID ray = dCreateRay(0, 10), s = dCreateSphere(0, 1);
    dContactGeom c[1];
    test_capture_reports();
    dCollide(ray, s, 1, c, sizeof c[0]);
    CHECK(test_captured_contains("\"bullet\" cannot collide a ray"));
    dGeomDestroy(ray);
    dGeomDestroy(s);
    return 0;
}

// ---- which pairs Bullet takes -------------------------------------------------

// Strict mode makes a pair the backend does not support an error: every pair
// of solids goes to Bullet, rays and plane-plane do not.
static int test_supported_pairs(void)
{
    USE_BULLET();
    static const shape solids[] = {
        { dSphereClass, { 1 }, { 0 }, { 0 }, 0 },
        { dBoxClass, { 1, 1, 1 }, { 0 }, { 0 }, 0 },
        { dCapsuleClass, { 0.5, 1 }, { 0 }, { 0 }, 0 },
        { dCylinderClass, { 0.5, 1 }, { 0 }, { 0 }, 0 },
        { dPlaneClass, { 0, 0, 1, 0 }, { 0 }, { 0 }, 0 },
    };
    enum { N = sizeof solids / sizeof solids[0] };
    dGeomID g[N], g2[N], ray = dCreateRay(0, 5);
    for (int i = 0; i < N; i++) g[i] = make_geom(&solids[i]), g2[i] = make_geom(&solids[i]);
    dContactGeom c[MAXC];
    dCollisionSetStrict(1);
    test_capture_reports();
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            if (!(i == N - 1 && j == N - 1)) dCollide(g[i], g2[j], MAXC, c, sizeof c[0]);
    int solid_reports = test_captured_count();
    dCollide(g[N - 1], g2[N - 1], MAXC, c, sizeof c[0]);
    int plane_reports = test_captured_count() - solid_reports;
    int n = 0;
    for (int i = 0; i < N; i++) {
        n += dCollide(ray, g[i], MAXC, c, sizeof c[0]);
        n += dCollide(g[i], ray, MAXC, c, sizeof c[0]);
    }
    int ray_reports = test_captured_count() - solid_reports - plane_reports;
    dCollisionSetStrict(0);
    CHECK(solid_reports == 3);   // cylinder with box (both ways) and cylinder
    CHECK(test_captured_contains("cannot collide a cylinder with a box"));
    CHECK(test_captured_contains("cannot collide a cylinder with a cylinder"));
    CHECK(plane_reports == 1);
    CHECK(ray_reports == 2 * N && n == 0);
    CHECK(test_captured_contains("cannot collide a ray"));
    for (int i = 0; i < N; i++) dGeomDestroy(g[i]), dGeomDestroy(g2[i]);
    dGeomDestroy(ray);
    return 0;
}

// A ray pair (not strict) goes to native, saying so once, with native's
// answer whatever that is.
static int test_rays_fall_back_to_native(void)
{
    USE_BULLET();
    dGeomID ray = dCreateRay(0, 10), s = dCreateSphere(0, 1);
    dGeomSetPosition(ray, 0.2, 0.1, 5);
    dMatrix3 down;
    dRFromAxisAndAngle(down, 1, 0, 0, M_PI);   // local z along world -z
    dGeomSetRotation(ray, down);
    int nn;
    dContactGeom native = deepest_with("native", ray, s, &nn), c[MAXC];
    test_capture_reports();
    int n = dCollide(ray, s, MAXC, c, sizeof c[0]);
    CHECK(dCollide(s, ray, MAXC, c + n, sizeof c[0]) == n);
    CHECK(test_captured_count() == 1 && test_captured_contains("using native for such pairs"));
    CHECK(n == nn && (n == 0 || c[0].depth == native.depth));
    dGeomDestroy(ray);
    dGeomDestroy(s);
    return 0;
}

// ---- hand-worked pairs ------------------------------------------------------

typedef struct pair_case {
    const char *name;
    shape a, b;
    dReal depth, normal[3];   // the deepest contact: depth and normal into a
    int count;                // Bullet's contacts (max 16)
    int kind;                 // how Bullet computes it (below)
    const char *gap;          // a known Bullet gap, or NULL
} pair_case;

// EXACT_PAIR: closed forms and GJK distances, every contact within EXACT.
// EPA_PAIR: the deepest contact's depth within EPA, its normal within EPA_NORMAL.
// GJK/EPA pairs keep Bullet's first point only: its multipoint extras come
// from a shape turned by 0.02 / its bounding radius and mapped back, and lie
// off the shapes (a reduced manifold, tagged). Cylinders against boxes,
// capsules and cylinders go to native (test_supported_pairs).
enum { EXACT_PAIR, EPA_PAIR };
#define ONE_POINT_GAP "reduced manifold: GJK/EPA pairs keep Bullet's first point only"

#define NONE { 0 }, 0
#define ROT_Y90 { 0, 1, 0 }, M_PI / 2   // local z along world x
#define ROT_X90 { 1, 0, 0 }, M_PI / 2   // local z along world -y
#define PLANE_Z0 { dPlaneClass, { 0, 0, 1, 0 }, { 0 }, NONE }

static const pair_case cases[] = {
    // Centres 1.4 apart, radii 1 + 0.5.
    { "sphere-sphere", { dSphereClass, { 1 }, { 0 }, NONE },
      { dSphereClass, { 0.5 }, { 1.4, 0, 0 }, NONE }, 0.1, { -1, 0, 0 }, 1, EXACT_PAIR, NULL },
    { "sphere-plane", { dSphereClass, { 1 }, { 0.3, -0.2, 0.7 }, NONE }, PLANE_Z0,
      0.3, { 0, 0, 1 }, 1, EXACT_PAIR, NULL },
    // Box 2 x 2 x 1 at the origin: top face z = 0.5.
    { "sphere-box above", { dSphereClass, { 0.5 }, { 0.2, 0.1, 0.99 }, NONE },
      { dBoxClass, { 2, 2, 1 }, { 0 }, NONE }, 0.01, { 0, 0, 1 }, 1, EXACT_PAIR, NULL },
    // Centre 0.1 under the top face (sides 1 away): out through the top.
    { "sphere-box centre inside", { dSphereClass, { 0.5 }, { 0, 0, 0.4 }, NONE },
      { dBoxClass, { 2, 2, 1 }, { 0 }, NONE }, 0.6, { 0, 0, 1 }, 1, EPA_PAIR, NULL },
    // Axis distance 0.9, radii 0.5 + 0.5.
    { "sphere-capsule", { dSphereClass, { 0.5 }, { 0.9, 0, 0.3 }, NONE },
      { dCapsuleClass, { 0.5, 2 }, { 0 }, NONE }, 0.1, { 1, 0, 0 }, 1, EXACT_PAIR, NULL },
    // Cylinder r 1, length 2: top face z = 1, side x = 1.
    { "sphere-cylinder top", { dSphereClass, { 0.5 }, { 0.1, 0, 1.45 }, NONE },
      { dCylinderClass, { 1, 2 }, { 0 }, NONE }, 0.05, { 0, 0, 1 }, 1, EPA_PAIR, NULL },
    { "sphere-cylinder side", { dSphereClass, { 0.5 }, { 1.4, 0, 0 }, NONE },
      { dCylinderClass, { 1, 2 }, { 0 }, NONE }, 0.1, { 1, 0, 0 }, 1, EPA_PAIR, NULL },
    // Bottom face 0.01 under the plane: its 4 corners.
    { "box-plane face-down", { dBoxClass, { 2, 1, 0.5 }, { 0, 0, 0.24 }, NONE }, PLANE_Z0,
      0.01, { 0, 0, 1 }, 4, EXACT_PAIR, NULL },
    // Deep under the plane (a half-space): bottom corners 3.5 deep.
    { "box-plane deep", { dBoxClass, { 1, 1, 1 }, { 0, 0, -3 }, NONE }, PLANE_Z0,
      3.5, { 0, 0, 1 }, 4, EXACT_PAIR, NULL },
    // Turned 45 degrees about x: the lowest edge (x from -0.5 to 0.5) 0.01 deep.
    { "box-plane on an edge", { dBoxClass, { 1, 1, 1 }, { 0, 0, 0.70710678118654752 - 0.01 },
      { 1, 0, 0 }, M_PI / 4 }, PLANE_Z0, 0.01, { 0, 0, 1 }, 2, EXACT_PAIR, NULL },
    // Unit box on a 2 x 2 x 1 box, offset: its 4 bottom corners.
    { "box-box offset", { dBoxClass, { 1, 1, 1 }, { 0.3, 0.2, 0.99 }, NONE },
      { dBoxClass, { 2, 2, 1 }, { 0 }, NONE }, 0.01, { 0, 0, 1 }, 4, EXACT_PAIR, NULL },
    // Equal boxes stacked: the pose where GJK/EPA picks a diagonal normal.
    { "box-box concentric", { dBoxClass, { 1, 1, 1 }, { 0, 0, 0.99 }, NONE },
      { dBoxClass, { 1, 1, 1 }, { 0 }, NONE }, 0.01, { 0, 0, 1 }, 4, EXACT_PAIR, NULL },
    // Capsule r 0.5, length 1 lying along x on the box top.
    { "capsule-box lying", { dCapsuleClass, { 0.5, 1 }, { 0, 0, 0.99 }, ROT_Y90 },
      { dBoxClass, { 2, 2, 1 }, { 0 }, NONE }, 0.01, { 0, 0, 1 }, 1, EPA_PAIR, ONE_POINT_GAP },
    // Along x over along y, axes 0.95 apart, radii 0.5 + 0.5.
    { "capsule-capsule crossed", { dCapsuleClass, { 0.5, 1 }, { 0, 0, 0.95 }, ROT_Y90 },
      { dCapsuleClass, { 0.5, 1 }, { 0 }, ROT_X90 }, 0.05, { 0, 0, 1 }, 1, EXACT_PAIR, NULL },
    { "capsule-plane upright", { dCapsuleClass, { 0.5, 2 }, { 0, 0, 1.49 }, NONE }, PLANE_Z0,
      0.01, { 0, 0, 1 }, 1, EXACT_PAIR, NULL },
    // Bullet gives one point for these; the adapter builds the manifold
    // (both ends; a square on the rim; each cap's lowest rim point).
    { "capsule-plane lying", { dCapsuleClass, { 0.5, 2 }, { 0, 0, 0.49 }, ROT_Y90 }, PLANE_Z0,
      0.01, { 0, 0, 1 }, 2, EXACT_PAIR, NULL },
    { "cylinder-plane upright", { dCylinderClass, { 0.5, 1 }, { 0, 0, 0.49 }, NONE }, PLANE_Z0,
      0.01, { 0, 0, 1 }, 4, EXACT_PAIR, NULL },
    { "cylinder-plane lying", { dCylinderClass, { 0.5, 1 }, { 0, 0, 0.49 }, ROT_Y90 }, PLANE_Z0,
      0.01, { 0, 0, 1 }, 2, EXACT_PAIR, NULL },
};
enum { NCASES = sizeof cases / sizeof cases[0] };

// Every contact's normal within tol of n (within mtol but the deepest).
static int normals_near(const dContactGeom *c, int n, const dReal *want, dReal sign, double tol,
                        double mtol)
{
    int top = deepest(c, n);
    for (int i = 0; i < n; i++) {
        double t = i == top ? tol : mtol;
        for (int k = 0; k < 3; k++)
            if (!(fabs(c[i].normal[k] - sign * want[k]) <= t)) return 0;
    }
    return 1;
}

// One hand-worked pair: both ways round through Bullet, the general checks,
// the deepest contact's depth and normal, the count, every normal, the
// separation rule and native's deepest depth.
static int check_case(const pair_case *k)
{
    dGeomID a = make_geom(&k->a), b = make_geom(&k->b);
    double tol = k->kind == EXACT_PAIR ? EXACT : EPA;
    double ntol = k->kind == EXACT_PAIR ? EXACT : EPA_NORMAL;
    double mtol = ntol;
    dContactGeom ab[MAXC], ba[MAXC];
    int n = collide_checked(a, b, MAXC, ab, tol, mtol);
    int m = collide_checked(b, a, MAXC, ba, tol, mtol);
    CHECK(n >= 0 && m >= 0);
    int nn;
    dContactGeom native = deepest_with("native", a, b, &nn);
    printf("# %s: %d and %d contact(s) (native %d)\n", k->name, n, m, nn);
    if (k->gap) printf("# gap: %s\n", k->gap);
    CHECK(n == k->count && m == k->count);
    const dContactGeom *p = &ab[deepest(ab, n)], *q = &ba[deepest(ba, m)];
    printf("#   deepest %.2g off the hand value (native %.2g off)\n", fabs(p->depth - k->depth),
           fabs(native.depth - k->depth));
    CHECK_NEAR(p->depth, k->depth, tol);
    CHECK_NEAR(q->depth, k->depth, tol);
    CHECK(normals_near(ab, n, k->normal, 1, ntol, mtol));
    CHECK(normals_near(ba, m, k->normal, -1, ntol, mtol));
    CHECK(depth_after_separation(a, b, p, SEP) <= SEP);
    CHECK_NEAR(native.depth, k->depth, EPA);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_hand_worked_pairs(void)
{
    USE_BULLET();
    int failed = 0;
    for (int i = 0; i < NCASES; i++) {
        if (check_case(&cases[i])) {
            printf("# ... in case \"%s\"\n", cases[i].name);
            failed = 1;
        }
    }
    return failed;
}

// Where the contacts of resting poses are: the corners of a face-down box
// and of a box resting on a larger box, and what is left when fewer contacts
// are asked for.
static int has_point(const dContactGeom *c, int n, dReal x, dReal y, dReal z, dReal tol)
{
    for (int i = 0; i < n; i++)
        if (fabs(c[i].pos[0] - x) <= tol && fabs(c[i].pos[1] - y) <= tol &&
            fabs(c[i].pos[2] - z) <= tol)
            return 1;
    return 0;
}

static int test_resting_contact_places(void)
{
    USE_BULLET();
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 2, 1, 0.5);
    dGeomID big = dCreateBox(0, 2, 2, 1), top = dCreateBox(0, 1, 1, 1);
    dContactGeom c[MAXC];
    // Face-down, turned 0.3 rad about z: the bottom corners (z = -0.01; against
    // a plane the contact is the solid's deepest point, as in native).
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, 0.3);
    dGeomSetRotation(box, R);
    dGeomSetPosition(box, 0.5, -0.25, 0.24);
    CHECK(dCollide(box, plane, MAXC, c, sizeof c[0]) == 4);
    for (int i = 0; i < 4; i++) {
        dReal sx = i & 1 ? 1 : -1, sy = i & 2 ? 0.5 : -0.5;
        dReal x = 0.5 + cos(0.3) * sx - sin(0.3) * sy, y = -0.25 + sin(0.3) * sx + cos(0.3) * sy;
        CHECK(has_point(c, 4, x, y, -0.01, EXACT));
    }
    // One contact asked: one of them (all equally deep).
    CHECK(dCollide(box, plane, 1, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.01, EXACT);
    // Unit box on the 2 x 2 x 1 box, offset (0.3, 0.2): its bottom corners,
    // halfway between z = 0.49 and the top face z = 0.5.
    dGeomSetPosition(top, 0.3, 0.2, 0.99);
    CHECK(dCollide(top, big, MAXC, c, sizeof c[0]) == 4);
    for (int i = 0; i < 4; i++)
        CHECK(has_point(c, 4, 0.3 + (i & 1 ? 0.5 : -0.5), 0.2 + (i & 2 ? 0.5 : -0.5), 0.495,
                        EXACT));
    // Two contacts asked: two of the four, kept apart.
    CHECK(dCollide(top, big, 2, c, sizeof c[0]) == 2);
    CHECK(dCalcPointsDistance3(c[0].pos, c[1].pos) >= 1 - EXACT);
    dGeomDestroy(plane);
    dGeomDestroy(box);
    dGeomDestroy(big);
    dGeomDestroy(top);
    return 0;
}

// Bullet's GJK answer depends on the order it sees a pair in; the adapter
// always gives it one order, so dCollide(b, a) is dCollide(a, b) with
// normals negated, bit for bit, and a repeated call is bit-identical. Poses:
// b turned, a turned and moved along a fixed direction to 3% of the smaller
// size inside native's touching distance (found by bisection).
static int test_argument_order_mirrors_exactly(void)
{
    USE_BULLET();
    static const shape pairs[][2] = {
        { { dBoxClass, { 0.7, 0.5, 0.3 }, { 0 }, NONE },
          { dCapsuleClass, { 0.2, 0.6 }, { 0 }, NONE } },
        { { dCapsuleClass, { 0.2, 0.6 }, { 0 }, NONE },
          { dCapsuleClass, { 0.3, 0.8 }, { 0 }, NONE } },
        { { dBoxClass, { 0.7, 0.5, 0.3 }, { 0 }, NONE },
          { dBoxClass, { 0.4, 0.9, 0.6 }, { 0 }, NONE } },
        { { dSphereClass, { 0.35 }, { 0 }, NONE },
          { dCylinderClass, { 0.3, 0.8 }, { 0 }, NONE } },
    };
    const dReal dir[3] = { 0.48, 0.6, 0.64 };   // unit
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; k++) {
        shape sa = pairs[k][0], sb = pairs[k][1];
        sa.axis[0] = 1, sa.axis[1] = 2, sa.axis[2] = 3, sa.angle = 0.7;
        sb.axis[0] = -1, sb.axis[1] = 1, sb.axis[2] = 0.5, sb.angle = 1.1;
        dGeomID a = make_geom(&sa), b = make_geom(&sb);
        dContactGeom ab[MAXC], ba[MAXC], again[MAXC];
        CHECK(dCollisionSetBackend("native") == 1);
        dReal lo = 0, hi = 4;   // touching at lo, apart at hi
        for (int i = 0; i < 60; i++) {
            dReal t = (lo + hi) / 2;
            dGeomSetPosition(a, t * dir[0], t * dir[1], t * dir[2]);
            if (dCollide(a, b, MAXC, ab, sizeof ab[0])) lo = t;
            else hi = t;
        }
        dReal t = lo - 0.03 * 0.2;
        dGeomSetPosition(a, t * dir[0], t * dir[1], t * dir[2]);
        CHECK(dCollisionSetBackend("bullet") == 1);
        // Zeroed first: single precision dContactGeom has padding, not written.
        memset(ab, 0, sizeof ab);
        memset(again, 0, sizeof again);
        int n = dCollide(a, b, MAXC, ab, sizeof ab[0]);
        CHECK(n >= 1 && dCollide(b, a, MAXC, ba, sizeof ba[0]) == n);
        CHECK(dCollide(a, b, MAXC, again, sizeof again[0]) == n);
        CHECK(memcmp(ab, again, n * sizeof ab[0]) == 0);
        for (int i = 0; i < n; i++) {
            CHECK(memcmp(ab[i].pos, ba[i].pos, 3 * sizeof(dReal)) == 0);
            CHECK(ab[i].depth == ba[i].depth && ba[i].g1 == b && ba[i].g2 == a);
            for (int j = 0; j < 3; j++) CHECK(ab[i].normal[j] == -ba[i].normal[j]);
        }
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    return 0;
}

// ---- cached shapes ----------------------------------------------------------

// The deepest depth of (a, b) through the selected backend (0 if apart).
static dReal deepest_depth(dGeomID a, dGeomID b)
{
    dContactGeom c[MAXC];
    int n = dCollide(a, b, MAXC, c, sizeof c[0]);
    return n ? c[deepest(c, n)].depth : 0;
}

// Every class resized (and moved) after its Bullet object was made: the next
// collision sees the new size.
static int test_resized_shapes_are_rebuilt(void)
{
    USE_BULLET();
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0);
    dGeomID s = dCreateSphere(0, 1), b = dCreateBox(0, 1, 1, 1);
    dGeomID cap = dCreateCapsule(0, 0.5, 1), cyl = dCreateCylinder(0, 0.5, 1);
    dGeomSetPosition(s, 0, 0, 0.9);      // 0.1 deep
    dGeomSetPosition(b, 5, 0, 0.45);     // 0.05 deep
    dGeomSetPosition(cap, 10, 0, 0.98);  // 0.02 deep
    dGeomSetPosition(cyl, 15, 0, 0.47);  // 0.03 deep
    CHECK_NEAR(deepest_depth(s, plane), 0.1, EXACT);
    CHECK_NEAR(deepest_depth(b, plane), 0.05, EXACT);
    CHECK_NEAR(deepest_depth(cap, plane), 0.02, EXACT);
    CHECK_NEAR(deepest_depth(cyl, plane), 0.03, EXACT);
    dGeomSphereSetRadius(s, 1.2);
    dGeomBoxSetLengths(b, 1, 1, 1.2);
    dGeomCapsuleSetParams(cap, 0.6, 1);
    dGeomCylinderSetParams(cyl, 0.5, 1.4);
    CHECK_NEAR(deepest_depth(s, plane), 0.3, EXACT);
    CHECK_NEAR(deepest_depth(b, plane), 0.15, EXACT);
    CHECK_NEAR(deepest_depth(cap, plane), 0.12, EXACT);
    CHECK_NEAR(deepest_depth(cyl, plane), 0.23, EXACT);
    // The plane itself raised to z = 0.05; the sphere moved up by 0.2.
    dGeomPlaneSetParams(plane, 0, 0, 1, 0.05);
    dGeomSetPosition(s, 0, 0, 1.1);
    CHECK_NEAR(deepest_depth(s, plane), 0.15, EXACT);
    CHECK_NEAR(deepest_depth(b, plane), 0.2, EXACT);
    dGeomDestroy(plane);
    dGeomDestroy(s);
    dGeomDestroy(b);
    dGeomDestroy(cap);
    dGeomDestroy(cyl);
    return 0;
}

// Geoms destroyed while their Bullet objects are cached (alone and with
// their space), and new geoms made in their place, which may reuse the
// memory: the new ones collide as themselves (ASan builds check the frees).
static int test_destroyed_geoms_free_their_objects(void)
{
    USE_BULLET();
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0);
    for (int round = 0; round < 3; round++) {
        dGeomID s = dCreateSphere(0, 1);
        dGeomSetPosition(s, 0, 0, 0.9);
        CHECK_NEAR(deepest_depth(s, plane), 0.1, EXACT);
        dGeomDestroy(s);
        dGeomID b = dCreateBox(0, 1, 1, 1);
        dGeomSetPosition(b, 0, 0, 0.4);
        CHECK_NEAR(deepest_depth(b, plane), 0.1, EXACT);
        dGeomDestroy(b);
    }
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID in[3] = { dCreateSphere(space, 0.5), dCreateBox(space, 1, 1, 1),
                      dCreateCylinder(space, 0.5, 1) };
    for (int i = 0; i < 3; i++) {
        dGeomSetPosition(in[i], 2.0 * i, 0, 0.45);
        CHECK_NEAR(deepest_depth(in[i], plane), 0.05, EXACT);
    }
    dSpaceDestroy(space);   // destroys the three geoms
    dGeomDestroy(plane);
    return 0;
}

// The same geoms through native, Bullet, native, Bullet (and FCL in between
// when it is built: the cache slot changes hands, and a resize while FCL
// holds it): the answers stay right.
static int test_switching_backends(void)
{
    USE_BULLET();
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), b = dCreateBox(0, 2, 1, 0.5);
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomSetPosition(b, 0, 0, 0.24);
    dGeomSetPosition(s, 0, 0, 0.74);   // on the box top (z = 0.49): 0.25 deep
    const char *order[] = { "native", "bullet", "native", "bullet", "fcl", "bullet" };
    dContactGeom c[MAXC];
    for (int i = 0; i < 6; i++) {
        if (i == 4) dGeomSphereSetRadius(s, 0.6);   // 0.35 deep from now on
        if (!backend_built(order[i])) continue;
        CHECK(dCollisionSetBackend(order[i]) == 1);
        dReal want = i >= 4 ? 0.35 : 0.25;
        int n = dCollide(b, plane, MAXC, c, sizeof c[0]);
        CHECK(n >= 1);
        CHECK_NEAR(c[deepest(c, n)].depth, 0.01, EPA);
        n = dCollide(s, b, MAXC, c, sizeof c[0]);
        CHECK(n >= 1);
        CHECK_NEAR(c[deepest(c, n)].depth, want, EPA);
        CHECK_VEC(c[deepest(c, n)].normal, 0, 0, 1, EPA);
    }
    dGeomDestroy(plane);
    dGeomDestroy(b);
    dGeomDestroy(s);
    return 0;
}

// A geometry transform's geom collides posed in the world, read again after
// the transform moves: sphere r 0.5 held 1 above a transform at z = -0.4
// (so at z = 0.6, 0.1 above the plane), then the transform lowered by 0.3.
static int test_transformed_geom(void)
{
    USE_BULLET();
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), t = dCreateGeomTransform(0);
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomTransformSetGeom(t, s);
    dGeomTransformSetCleanup(t, 1);
    dGeomSetPosition(s, 0, 0, 1);
    dGeomSetPosition(t, 0, 0, -0.4);
    dContactGeom c[MAXC];
    CHECK(dCollide(t, plane, MAXC, c, sizeof c[0]) == 0);
    dGeomSetPosition(t, 0, 0, -0.7);
    CHECK(dCollide(t, plane, MAXC, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EXACT);
    CHECK_VEC(c[0].normal, 0, 0, 1, EXACT);
    CHECK(c[0].g1 == s && c[0].g2 == plane);
    dGeomDestroy(t);
    dGeomDestroy(plane);
    return 0;
}

// ---- resting scenes -----------------------------------------------------------

typedef struct scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    int last_contacts;   // contacts made in the last step
} scene;

static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *s = data;
    dContactGeom c[8];
    int n = dCollide(a, b, 8, c, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        dContact k;
        memset(&k, 0, sizeof k);
        k.surface.mu = 1;
        k.geom = c[i];
        dJointAttach(dJointCreateContact(s->world, s->contacts, &k), dGeomGetBody(a),
                     dGeomGetBody(b));
    }
    s->last_contacts += n;
}

static void scene_init(scene *s)
{
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, -9.81);
    s->space = dSimpleSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    dCreatePlane(s->space, 0, 0, 1, 0);
}

static void scene_run(scene *s, int steps)
{
    for (int i = 0; i < steps; i++) {
        s->last_contacts = 0;
        dSpaceCollide(s->space, s, near_callback);
        dWorldQuickStep(s->world, 0.01);
        dJointGroupEmpty(s->contacts);
    }
}

static void scene_free(scene *s)
{
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);
    dWorldDestroy(s->world);
}

// A ball dropped from 1 m comes to rest on the plane at its radius. At rest
// the error correction (ERP) takes the remaining depth towards zero; a step
// without contact lets it fall g h^2 = 1e-3 into the plane before the next
// contact catches it: REST allows twice that. Still: slower than STILL, half
// the speed one step of free fall gives (g h = 0.098 m/s).
#define REST 2e-3
#define STILL 0.05
static int test_dropped_sphere_rests_at_its_radius(void)
{
    USE_BULLET();
    scene s;
    scene_init(&s);
    dBodyID ball = dBodyCreate(s.world);
    dMass m;
    dMassSetSphereTotal(&m, 1, 0.5);
    dBodySetMass(ball, &m);
    dBodySetPosition(ball, 0, 0, 1.5);
    dGeomSetBody(dCreateSphere(s.space, 0.5), ball);
    scene_run(&s, 300);
    printf("# ball at rest: z %.6f\n", dBodyGetPosition(ball)[2]);
    CHECK_NEAR(dBodyGetPosition(ball)[2], 0.5, REST);
    CHECK(dCalcVectorLength3(dBodyGetLinearVel(ball)) < STILL);
    CHECK(s.last_contacts == 1);
    scene_free(&s);
    return 0;
}

// A 0.6 x 0.4 x 0.2 box dropped flat (turned 0.3 rad about z) from 2 cm
// stands on its 4 bottom corners: after 2 s its centre is at its half
// height (within REST, as the ball), its top face still up (tilt below
// 0.01 rad) and it is still (STILL, in m/s and rad/s).
static int test_box_stands_on_the_plane(void)
{
    USE_BULLET();
    scene s;
    scene_init(&s);
    dBodyID body = dBodyCreate(s.world);
    dMass m;
    dMassSetBoxTotal(&m, 1, 0.6, 0.4, 0.2);
    dBodySetMass(body, &m);
    dBodySetPosition(body, 0.2, 0.1, 0.12);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, 0.3);
    dBodySetRotation(body, R);
    dGeomSetBody(dCreateBox(s.space, 0.6, 0.4, 0.2), body);
    scene_run(&s, 200);
    printf("# box at rest: %d contacts, z %.6f\n", s.last_contacts, dBodyGetPosition(body)[2]);
    CHECK(s.last_contacts == 4);
    CHECK_NEAR(dBodyGetPosition(body)[2], 0.1, REST);
    CHECK(dBodyGetRotation(body)[10] > cos(0.01));
    CHECK(dCalcVectorLength3(dBodyGetLinearVel(body)) < STILL);
    CHECK(dCalcVectorLength3(dBodyGetAngularVel(body)) < STILL);
    scene_free(&s);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_environment_selects_bullet),
    TEST_CASE(test_supported_pairs),
    TEST_CASE(test_rays_fall_back_to_native),
    TEST_CASE(test_hand_worked_pairs),
    TEST_CASE(test_resting_contact_places),
    TEST_CASE(test_argument_order_mirrors_exactly),
    TEST_CASE(test_resized_shapes_are_rebuilt),
    TEST_CASE(test_destroyed_geoms_free_their_objects),
    TEST_CASE(test_switching_backends),
    TEST_CASE(test_transformed_geom),
    TEST_CASE(test_dropped_sphere_rests_at_its_radius),
    TEST_CASE(test_box_stands_on_the_plane),
    TEST_END
};
