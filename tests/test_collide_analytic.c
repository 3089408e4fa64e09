// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_analytic.c -- the native analytic colliders through dCollide:
// sphere against sphere, box, capsule, plane and cylinder; box-box,
// box-plane, capsule-capsule, capsule-box, capsule-plane, cylinder-plane.
// Hand-worked poses check depth, normal and position; every pair is also
// collided the other way round, contact points are checked to lie in both
// shapes, the separation rule (moving g1 by depth along the normal parts the
// pair) is checked, and seeded random poses repeat the general checks.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <string.h>

enum { MAXC = 16 };

// Rounding of a few operations on sizes ~1: double 1e-9 is far above it,
// single 1e-4 covers float's 6e-8 times the dozens of operations involved.
#define EPS TOL(1e-9, 1e-4)

static const unsigned char SENTINEL = 0xA5;

// ---- helpers ----------------------------------------------------------------

static int untouched(const void *p, size_t size)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < size; i++)
        if (b[i] != SENTINEL) return 0;
    return 1;
}

// dCollide(a, b) into c with the general checks: count within max, the
// entries past the count untouched, g1 = a, g2 = b, sides -1, finite values,
// unit normals, depth >= 0, pos in both shapes: point depth between -tol and
// the deepest contact's depth + tol (a point of the overlap is no deeper in
// either shape than the translation that separates them; with several
// contacts a point may lie deeper in one shape than its own contact's depth,
// e.g. a capsule's upper end ball point inside the capsule's lower part).
// Returns the count, or -1 after reporting a failure.
static int collide_checked(dGeomID a, dGeomID b, int max, dContactGeom *c, double tol)
{
    memset(c, SENTINEL, MAXC * sizeof *c);
    int n = dCollide(a, b, max, c, sizeof *c);
#define REQUIRE(cond) \
    do { \
        if (!(cond)) { \
            test_fail(__FILE__, __LINE__, "REQUIRE(%s), contact %d", #cond, i); \
            return -1; \
        } \
    } while (0)
    int i = -1;
    REQUIRE(n >= 0 && n <= max);
    REQUIRE(untouched(c + n, (MAXC - n) * sizeof *c));
    dReal most = n ? c[deepest(c, n)].depth : 0;
    for (i = 0; i < n; i++) {
        const dContactGeom *k = &c[i];
        REQUIRE(k->g1 == a && k->g2 == b && k->side1 == -1 && k->side2 == -1);
        REQUIRE(isfinite(k->depth) && k->depth >= 0);
        REQUIRE(isfinite(k->pos[0]) && isfinite(k->pos[1]) && isfinite(k->pos[2]));
        REQUIRE(fabs(dCalcVectorLength3(k->normal) - 1) <= EPS);
        dReal da = point_depth(a, k->pos), db = point_depth(b, k->pos);
        if (!(da >= -tol && da <= most + tol && db >= -tol && db <= most + tol)) {
            test_fail(__FILE__, __LINE__, "contact %d: pos %g, %g deep in the shapes (deepest %g)",
                      i, (double)da, (double)db, (double)most);
            return -1;
        }
    }
#undef REQUIRE
    return n;
}

// The checks every touching or apart pair gets, both ways round: same count
// (same_count: pairs of different classes and symmetric poses), the deepest
// depths equal and their normals opposite (within ntol); then the separation
// rule on (a, b): moved apart by depth + SEP, at most SEP deep (SEP: 1e-6,
// single 1e-4 as float positions near 1 are only good to ~1e-7 and the
// colliders compound a few dozen roundings). Returns the count of (a, b), or
// -1 after a failure.
#define SEP TOL(1e-6, 1e-4)
static int check_pair_ntol(dGeomID a, dGeomID b, int max, dContactGeom *ab, int same_count,
                           double tol, double ntol)
{
    dContactGeom ba[MAXC];
    int n = collide_checked(a, b, max, ab, tol);
    int m = collide_checked(b, a, max, ba, tol);
    if (n < 0 || m < 0) return -1;
    if (same_count && n != m) {
        test_fail(__FILE__, __LINE__, "count %d one way, %d the other", n, m);
        return -1;
    }
    if ((n == 0) != (m == 0)) {
        test_fail(__FILE__, __LINE__, "touching one way (%d), not the other (%d)", n, m);
        return -1;
    }
    if (n == 0) return 0;
    const dContactGeom *p = &ab[deepest(ab, n)], *q = &ba[deepest(ba, m)];
    if (fabs(p->depth - q->depth) > tol) {
        test_fail(__FILE__, __LINE__, "deepest depth %.17g one way, %.17g the other",
                  (double)p->depth, (double)q->depth);
        return -1;
    }
    for (int i = 0; i < 3; i++) {
        if (fabs(p->normal[i] + q->normal[i]) > ntol) {
            test_fail(__FILE__, __LINE__, "normals not opposite");
            return -1;
        }
    }
    dReal left = depth_after_separation(a, b, p, SEP);
    if (left > SEP) {
        test_fail(__FILE__, __LINE__, "still %.3g deep after moving by the depth %g", (double)left,
                  (double)p->depth);
        return -1;
    }
    return n;
}

static int check_pair(dGeomID a, dGeomID b, int max, dContactGeom *ab, int same_count,
                      double tol)
{
    return check_pair_ntol(a, b, max, ab, same_count, tol, tol);
}

// ---- sphere -----------------------------------------------------------------

static int test_sphere_sphere(void)
{
    dGeomID a = dCreateSphere(0, 1), b = dCreateSphere(0, 0.5);
    dContactGeom c[MAXC];
    dGeomSetPosition(b, 1.2, 0, 0);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.3, EPS);
    CHECK_VEC(c[0].normal, -1, 0, 0, EPS);   // from b into a
    CHECK_VEC(c[0].pos, 0.85, 0, 0, EPS);    // middle of [0.7, 1.0]
    dGeomSetPosition(b, 1.6, 0, 0);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 0);
    dGeomSetPosition(b, 0, 0, 0);            // coincident: some unit normal
    CHECK(collide_checked(a, b, 1, c, EPS) == 1);
    CHECK_NEAR(c[0].depth, 1.5, EPS);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_sphere_box(void)
{
    dGeomID s = dCreateSphere(0, 0.5), b = dCreateBox(0, 2, 2, 2);
    dContactGeom c[MAXC];
    dGeomSetPosition(s, 0.2, -0.3, 1.3);   // over the top face
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    CHECK_VEC(c[0].pos, 0.2, -0.3, 1, EPS);
    dGeomSetPosition(s, 1.2, 1.2, 1.2);    // off the corner: 0.5 - sqrt(3) 0.2
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.5 - sqrt(3) * 0.2, EPS);
    CHECK_VEC(c[0].normal, 1 / sqrt(3), 1 / sqrt(3), 1 / sqrt(3), EPS);
    CHECK_VEC(c[0].pos, 1, 1, 1, EPS);
    dGeomSetPosition(s, 0.7, 0, 0.2);      // centre inside, 0.3 from the +x face
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.8, EPS);
    CHECK_VEC(c[0].normal, 1, 0, 0, EPS);
    CHECK_VEC(c[0].pos, 0.7, 0, 0.2, EPS);
    dGeomSetPosition(s, 0, -0.1, -0.9);    // inside, nearest the -z face
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.6, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    // Box turned 45 degrees about z: its vertical edge is at x = sqrt(2).
    set_rot(b, 0, 0, 1, M_PI / 4);
    dGeomSetPosition(s, sqrt(2) + 0.4, 0, 0.3);
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, 1, 0, 0, EPS);
    CHECK_VEC(c[0].pos, sqrt(2), 0, 0.3, EPS);
    dGeomSetPosition(s, sqrt(2) + 0.6, 0, 0);
    CHECK(check_pair(s, b, 3, c, 1, EPS) == 0);
    dGeomDestroy(s);
    dGeomDestroy(b);
    return 0;
}

static int test_sphere_capsule(void)
{
    dGeomID s = dCreateSphere(0, 0.5), k = dCreateCapsule(0, 0.5, 2);   // axis z, |z| <= 1
    dContactGeom c[MAXC];
    dGeomSetPosition(s, 0.8, 0, 0.5);      // beside the cylindrical part
    CHECK(check_pair(s, k, 2, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EPS);
    CHECK_VEC(c[0].normal, 1, 0, 0, EPS);
    CHECK_VEC(c[0].pos, 0.4, 0, 0.5, EPS);  // middle of [0.3, 0.5]
    dGeomSetPosition(s, 0, 0.6, 1.8);      // over the cap: distance 1 from (0,0,1)
    CHECK(check_pair(s, k, 2, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0, EPS);
    dGeomSetPosition(s, 0, 0, 1.8);
    CHECK(check_pair(s, k, 2, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    CHECK_VEC(c[0].pos, 0, 0, 1.4, EPS);
    dGeomSetPosition(s, 0, 0, 0.3);        // centre on the axis: out sideways
    CHECK(check_pair(s, k, 2, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 1, EPS);
    CHECK_NEAR(c[0].normal[2], 0, EPS);
    dGeomSetPosition(s, 1.1, 0, 0);
    CHECK(check_pair(s, k, 2, c, 1, EPS) == 0);
    dGeomDestroy(s);
    dGeomDestroy(k);
    return 0;
}

static int test_sphere_plane(void)
{
    dGeomID s = dCreateSphere(0, 1), p = dCreatePlane(0, 0, 0, 1, 0);
    dContactGeom c[MAXC];
    dGeomSetPosition(s, 3, 4, 0.7);
    CHECK(check_pair(s, p, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.3, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    CHECK_VEC(c[0].pos, 3, 4, -0.3, EPS);   // the sphere's deepest point
    dGeomSetPosition(s, 0, 0, -5);         // a plane is a half-space
    CHECK(check_pair(s, p, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 6, EPS);
    dGeomSetPosition(s, 0, 0, 1.01);
    CHECK(check_pair(s, p, 1, c, 1, EPS) == 0);
    dGeomDestroy(p);
    // Tilted plane (0, 1, 1) / sqrt 2 . x = 1: the centre is 1 below it.
    p = dCreatePlane(0, 0, 1 / sqrt(2), 1 / sqrt(2), 1);
    dGeomSetPosition(s, 0, 0, 0);
    CHECK(check_pair(s, p, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 2, EPS);
    CHECK_VEC(c[0].pos, 0, -1 / sqrt(2), -1 / sqrt(2), EPS);
    dGeomDestroy(s);
    dGeomDestroy(p);
    return 0;
}

static int test_sphere_cylinder(void)
{
    dGeomID s = dCreateSphere(0, 0.5), y = dCreateCylinder(0, 1, 2);   // |z| <= 1, radius 1
    dContactGeom c[MAXC];
    dGeomSetPosition(s, 0, 1.3, 0.2);      // side
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EPS);
    CHECK_VEC(c[0].normal, 0, 1, 0, EPS);
    CHECK_VEC(c[0].pos, 0, 1, 0.2, EPS);
    dGeomSetPosition(s, 0.3, 0, 1.4);      // cap
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    CHECK_VEC(c[0].pos, 0.3, 0, 1, EPS);
    dGeomSetPosition(s, 1.2, 0, -1.2);     // rim: distance sqrt(0.08) from (1, 0, -1)
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.5 - sqrt(0.08), EPS);
    CHECK_VEC(c[0].normal, 1 / sqrt(2), 0, -1 / sqrt(2), EPS);
    CHECK_VEC(c[0].pos, 1, 0, -1, EPS);
    dGeomSetPosition(s, 1.36, 0, 1.36);    // beyond the rim, within the box around it
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 0);
    dGeomSetPosition(s, 0.8, 0, 0);        // inside, nearest the side
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.7, EPS);
    CHECK_VEC(c[0].normal, 1, 0, 0, EPS);
    dGeomSetPosition(s, 0.1, 0, -0.9);     // inside, nearest the bottom cap
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.6, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    // Cylinder lying along x: the sphere above its side.
    set_rot(y, 0, 1, 0, M_PI / 2);
    dGeomSetPosition(s, 0.7, 0, 1.4);
    CHECK(check_pair(s, y, 1, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    dGeomDestroy(s);
    dGeomDestroy(y);
    return 0;
}

// ---- box --------------------------------------------------------------------

static int contains_point(const dContactGeom *c, int n, double x, double y, double z, double tol)
{
    for (int i = 0; i < n; i++)
        if (fabs(c[i].pos[0] - x) <= tol && fabs(c[i].pos[1] - y) <= tol
            && fabs(c[i].pos[2] - z) <= tol)
            return 1;
    return 0;
}

static int test_box_resting_on_box_gives_its_face(void)
{
    // A unit cube 0.1 deep into the top of a 2-cube: box 1's top face is the
    // reference (the first of two equally deep face axes), the cube's bottom
    // face clipped to it is the whole bottom: its 4 corners, 0.1 deep (pos
    // midway between the faces).
    dGeomID a = dCreateBox(0, 2, 2, 2), b = dCreateBox(0, 1, 1, 1);
    dContactGeom c[MAXC];
    dGeomSetPosition(b, 0.3, -0.2, 1.4);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 4);
    for (int i = 0; i < 4; i++) {
        CHECK_NEAR(c[i].depth, 0.1, EPS);
        CHECK_VEC(c[i].normal, 0, 0, -1, EPS);
    }
    for (int sx = -1; sx <= 1; sx += 2)
        for (int sy = -1; sy <= 1; sy += 2)
            CHECK(contains_point(c, 4, 0.3 + sx * 0.5, -0.2 + sy * 0.5, 0.95, EPS));
    // The other way round the cube's face is the reference: the same points
    // (midway between the faces), same depths.
    CHECK(collide_checked(b, a, 8, c, EPS) == 4);
    for (int i = 0; i < 4; i++) CHECK_NEAR(c[i].pos[2], 0.95, EPS);
    // Hanging over the edge: the part of the face over the top, 4 points.
    dGeomSetPosition(b, 1.2, 0, 1.4);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 4);
    CHECK(contains_point(c, 4, 1, 0.5, 0.95, EPS) && contains_point(c, 4, 0.7, -0.5, 0.95, EPS));
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_equal_boxes(void)
{
    // Two equal boxes face to face: the incident face equals the reference
    // rectangle, so its 4 corners (each once) are the contacts.
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateBox(0, 1, 1, 1);
    dContactGeom c[MAXC];
    dGeomSetPosition(b, 0, 0, 0.9);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 4);
    // Turned 45 degrees about the normal: square clipped by square is an
    // octagon, 8 contacts, each 0.1 deep; fewer asked keeps the deepest and
    // spread ones.
    set_rot(b, 0, 0, 1, M_PI / 4);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 8);
    for (int i = 0; i < 8; i++) {
        CHECK_NEAR(c[i].depth, 0.1, EPS);
        CHECK_NEAR(c[i].pos[2], 0.45, EPS);   // midway between the faces
        // on the octagon: the square |x|, |y| <= 0.5 meets |x| + |y| <= sqrt(1/2)
        CHECK_NEAR(fmax(fmax(fabs(c[i].pos[0]), fabs(c[i].pos[1])),
                        (fabs(c[i].pos[0]) + fabs(c[i].pos[1])) / sqrt(2)), 0.5, EPS);
    }
    for (int max = 1; max <= 8; max++) {
        int n = check_pair(a, b, max, c, 1, EPS);
        CHECK(n == max);
        if (max >= 2 && max < 8) {   // culled: the second is the far side of the octagon
            double dx = c[0].pos[0] - c[1].pos[0], dy = c[0].pos[1] - c[1].pos[1];
            CHECK(sqrt(dx * dx + dy * dy) > 0.9);
        }
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_box_edge_on_edge(void)
{
    // Two unit cubes turned 45 degrees about x and about y: a's top edge
    // (along x, at z = sqrt(1/2)) crosses b's bottom edge (along y) 0.1 deep.
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateBox(0, 1, 1, 1);
    dContactGeom c[MAXC];
    set_rot(a, 1, 0, 0, M_PI / 4);
    set_rot(b, 0, 1, 0, M_PI / 4);
    double h = sqrt(0.5);
    dGeomSetPosition(b, 0, 0, 2 * h - 0.1);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    CHECK_VEC(c[0].pos, 0, 0, h - 0.05, EPS);
    dGeomSetPosition(b, 0, 0, 2 * h + 0.01);
    CHECK(check_pair(a, b, 8, c, 1, EPS) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_box_plane(void)
{
    dGeomID b = dCreateBox(0, 1, 1, 1), p = dCreatePlane(0, 0, 0, 1, 0);
    dContactGeom c[MAXC];
    dGeomSetPosition(b, 2, 3, 0.45);       // face down: its 4 bottom corners
    CHECK(check_pair(b, p, 8, c, 1, EPS) == 4);
    for (int i = 0; i < 4; i++) {
        CHECK_NEAR(c[i].depth, 0.05, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
        CHECK_NEAR(c[i].pos[2], -0.05, EPS);
    }
    CHECK(contains_point(c, 4, 1.5, 2.5, -0.05, EPS) && contains_point(c, 4, 2.5, 3.5, -0.05, EPS));
    for (int max = 1; max <= 4; max++) CHECK(check_pair(b, p, max, c, 1, EPS) == max);
    // On an edge (turned 45 degrees about x): 2 corners, 0.1 deep.
    set_rot(b, 1, 0, 0, M_PI / 4);
    dGeomSetPosition(b, 0, 0, sqrt(0.5) - 0.1);
    CHECK(check_pair(b, p, 8, c, 1, EPS) == 2);
    CHECK(contains_point(c, 2, 0.5, 0, -0.1, EPS) && contains_point(c, 2, -0.5, 0, -0.1, EPS));
    // Tilted onto one corner, then pushed in: deepest first.
    set_rot(b, 1, 1, 0, 0.3);
    dGeomSetPosition(b, 0, 0, 0.2);
    int n = check_pair(b, p, 4, c, 1, EPS);
    CHECK(n >= 2 && n <= 4);
    for (int i = 1; i < n; i++) CHECK(c[i - 1].depth >= c[i].depth);
    // Sunk: 8 corners below, the 4 deepest kept (the bottom face).
    dGeomSetRotation(b, (dMatrix3){ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 });
    dGeomSetPosition(b, 0, 0, -5);
    CHECK(check_pair(b, p, 8, c, 1, EPS) == 4);
    for (int i = 0; i < 4; i++) CHECK_NEAR(c[i].depth, 5.5, EPS);
    dGeomSetPosition(b, 0, 0, 0.51);
    CHECK(check_pair(b, p, 8, c, 1, EPS) == 0);
    dGeomDestroy(b);
    dGeomDestroy(p);
    return 0;
}

// ---- capsule ----------------------------------------------------------------

static int test_capsule_capsule(void)
{
    // Both along x (radius 0.5): a of length 2 at the origin, b of length 1
    // above it. The part of a's axis alongside b's is x in [0, 1]: two
    // contacts at its ends, 0.1 deep, pos in the middle of [0.4, 0.5].
    dGeomID a = dCreateCapsule(0, 0.5, 2), b = dCreateCapsule(0, 0.5, 1);
    dContactGeom c[MAXC];
    set_rot(a, 0, 1, 0, M_PI / 2);
    set_rot(b, 0, 1, 0, M_PI / 2);
    dGeomSetPosition(b, 0.5, 0, 0.9);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 2);
    for (int i = 0; i < 2; i++) {
        CHECK_NEAR(c[i].depth, 0.1, EPS);
        CHECK_VEC(c[i].normal, 0, 0, -1, EPS);
    }
    CHECK(contains_point(c, 2, 0, 0, 0.45, EPS) && contains_point(c, 2, 1, 0, 0.45, EPS));
    CHECK(check_pair(a, b, 1, c, 1, EPS) == 1);
    // Crossed (b along y): one contact.
    set_rot(b, 1, 0, 0, M_PI / 2);
    dGeomSetPosition(b, 0.3, 0.2, 0.9);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    CHECK_VEC(c[0].pos, 0.3, 0, 0.45, EPS);
    // End to end along x: one contact between the caps.
    set_rot(b, 0, 1, 0, M_PI / 2);
    dGeomSetPosition(b, 2.4, 0, 0);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, -1, 0, 0, EPS);
    // Same axis: out sideways (some direction, not tied to the order), 1
    // deep, at both ends of the overlap.
    dGeomSetPosition(b, 0.5, 0, 0);
    CHECK(collide_checked(b, a, 4, c, EPS) == 2);
    CHECK(collide_checked(a, b, 4, c, EPS) == 2);
    CHECK_NEAR(c[0].depth, 1, EPS);
    CHECK_NEAR(c[0].normal[0], 0, EPS);
    dGeomSetPosition(b, 0.5, 0, 1.01);
    CHECK(check_pair(a, b, 4, c, 1, EPS) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_capsule_box(void)
{
    dGeomID k = dCreateCapsule(0, 0.25, 1), b = dCreateBox(0, 2, 2, 2);
    dContactGeom c[MAXC];
    set_rot(k, 0, 1, 0, M_PI / 2);         // lying along x over the top face
    dGeomSetPosition(k, 0.1, 0.2, 1.2);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 2);
    for (int i = 0; i < 2; i++) {
        CHECK_NEAR(c[i].depth, 0.05, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
    }
    // pos: halfway between the capsule's bottom (0.95) and the face (1)
    CHECK(contains_point(c, 2, -0.4, 0.2, 0.975, EPS));
    CHECK(contains_point(c, 2, 0.6, 0.2, 0.975, EPS));
    CHECK(check_pair(k, b, 1, c, 1, EPS) == 1);
    // Half over the edge: the ends of the part over the face, x = 1 and 0.5.
    dGeomSetPosition(k, 1.0, 0.2, 1.2);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 2);
    CHECK(contains_point(c, 2, 1, 0.2, 0.975, EPS) && contains_point(c, 2, 0.5, 0.2, 0.975, EPS));
    // Sunk into the face (axis 0.1 below it): 0.35 deep, still 2 points.
    dGeomSetPosition(k, 0.1, 0.2, 0.9);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 2);
    for (int i = 0; i < 2; i++) {
        CHECK_NEAR(c[i].depth, 0.35, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
    }
    // Standing on the face: one contact under its lower end.
    set_rot(k, 0, 1, 0, 0);
    dGeomSetPosition(k, 0.3, 0.1, 1.7);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.05, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    // Along y past the edge x = z = 1: distance sqrt(0.08) from it.
    set_rot(k, 1, 0, 0, M_PI / 2);
    dGeomSetPosition(k, 1.2, 0, 1.2);
    dGeomCapsuleSetParams(k, 0.3, 1);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.3 - sqrt(0.08), EPS);
    CHECK_VEC(c[0].normal, 1 / sqrt(2), 0, 1 / sqrt(2), EPS);
    CHECK_NEAR(c[0].pos[0], 1, EPS);       // on the edge (anywhere along it)
    CHECK_NEAR(c[0].pos[2], 1, EPS);
    dGeomSetPosition(k, 1.22, 0, 1.22);
    CHECK(check_pair(k, b, 4, c, 1, EPS) == 0);
    dGeomDestroy(k);
    dGeomDestroy(b);
    return 0;
}

static int test_capsule_plane(void)
{
    dGeomID k = dCreateCapsule(0, 0.5, 2), p = dCreatePlane(0, 0, 0, 1, 0);
    dContactGeom c[MAXC];
    set_rot(k, 0, 1, 0, M_PI / 2);         // lying: both cap balls touch
    dGeomSetPosition(k, 0, 0, 0.4);
    CHECK(check_pair(k, p, 4, c, 1, EPS) == 2);
    CHECK(contains_point(c, 2, 1, 0, -0.1, EPS) && contains_point(c, 2, -1, 0, -0.1, EPS));
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_NEAR(c[1].depth, 0.1, EPS);
    CHECK(check_pair(k, p, 1, c, 1, EPS) == 1);
    set_rot(k, 0, 1, 0, M_PI / 2 - 0.05);  // almost lying: both, the lower end first
    CHECK(check_pair(k, p, 4, c, 1, EPS) == 2);
    CHECK_NEAR(c[0].depth, 0.1 + sin(0.05), EPS);
    CHECK_NEAR(c[1].depth, 0.1 - sin(0.05), EPS);
    CHECK_VEC(c[0].pos, -cos(0.05), 0, -0.1 - sin(0.05), EPS);
    set_rot(k, 0, 1, 0, 0.3);              // tilted: only the lower end
    dGeomSetPosition(k, 0, 0, 1.4);
    CHECK(check_pair(k, p, 4, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.5 - 1.4 + cos(0.3), EPS);
    CHECK_VEC(c[0].pos, -sin(0.3), 0, 1.4 - cos(0.3) - 0.5, EPS);
    dGeomSetPosition(k, 0, 0, 2);
    CHECK(check_pair(k, p, 4, c, 1, EPS) == 0);
    dGeomDestroy(k);
    dGeomDestroy(p);
    return 0;
}

static int test_cylinder_plane(void)
{
    dGeomID y = dCreateCylinder(0, 1, 2), p = dCreatePlane(0, 0, 0, 1, 0);
    dContactGeom c[MAXC];
    dGeomSetPosition(y, 0, 0, 0.9);        // upright: 4 points of the bottom rim
    CHECK(check_pair(y, p, 8, c, 1, EPS) == 4);
    for (int i = 0; i < 4; i++) {
        CHECK_NEAR(c[i].depth, 0.1, EPS);
        CHECK_NEAR(c[i].pos[0] * c[i].pos[0] + c[i].pos[1] * c[i].pos[1], 1, EPS);
    }
    // spread: they average to the axis
    CHECK_NEAR(c[0].pos[0] + c[1].pos[0] + c[2].pos[0] + c[3].pos[0], 0, EPS);
    for (int max = 1; max <= 4; max++) CHECK(check_pair(y, p, max, c, 1, EPS) == max);
    set_rot(y, 1, 0, 0, M_PI / 2);         // on its side: the 2 ends of the bottom line
    dGeomSetPosition(y, 0, 0, 0.9);
    CHECK(check_pair(y, p, 8, c, 1, EPS) == 2);
    CHECK(contains_point(c, 2, 0, 1, -0.1, EPS) && contains_point(c, 2, 0, -1, -0.1, EPS));
    // Tilted 30 degrees about x: the lowest rim point, 0.1 deep.
    set_rot(y, 1, 0, 0, M_PI / 6);
    dGeomSetPosition(y, 0, 0, cos(M_PI / 6) + sin(M_PI / 6) - 0.1);
    CHECK(check_pair(y, p, 8, c, 1, EPS) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_NEAR(c[0].pos[2], -0.1, EPS);
    dGeomSetPosition(y, 0, 0, cos(M_PI / 6) + sin(M_PI / 6) + 0.01);
    CHECK(check_pair(y, p, 8, c, 1, EPS) == 0);
    dGeomDestroy(y);
    dGeomDestroy(p);
    return 0;
}

// ---- contract details -------------------------------------------------------

static int test_skip_is_honoured(void)
{
    typedef struct {
        dContactGeom g;
        double extra[3];
    } wide;
    wide w[6];
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(b, 0, 0, 0.9);
    set_rot(b, 0, 0, 1, M_PI / 4);
    memset(w, SENTINEL, sizeof w);
    int n = dCollide(a, b, 5, &w[0].g, sizeof w[0]);
    CHECK(n == 5);
    for (int i = 0; i < 5; i++) {
        CHECK(untouched(w[i].extra, sizeof w[i].extra));
        CHECK(w[i].g.g1 == a && w[i].g.g2 == b);
        CHECK_NEAR(w[i].g.depth, 0.1, EPS);
    }
    CHECK(untouched(&w[5], sizeof w[5]));
    // Flag bits above the count (CONTACTS_UNIMPORTANT) do not change it.
    CHECK(dCollide(a, b, CONTACTS_UNIMPORTANT | 3, &w[0].g, sizeof w[0]) == 3);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_geoms_on_bodies_take_the_body_pose(void)
{
    // A capsule on a body turned to lie along y, over a plane, and a box on
    // a body turned 90 degrees about x resting on a box.
    dWorldID w = dWorldCreate();
    dBodyID bk = dBodyCreate(w), bb = dBodyCreate(w);
    dGeomID k = dCreateCapsule(0, 0.5, 2), p = dCreatePlane(0, 0, 0, 1, 0);
    dGeomID box = dCreateBox(0, 1, 2, 0.5), ground = dCreateBox(0, 10, 10, 1);
    dGeomSetBody(k, bk);
    dGeomSetBody(box, bb);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, M_PI / 2);
    dBodySetRotation(bk, R);
    dBodySetPosition(bk, 1, 2, 0.45);
    dBodySetRotation(bb, R);               // the box's 2-long y side is now vertical
    dBodySetPosition(bb, 0, 0, 0.5 + 1 - 0.02);
    dContactGeom c[MAXC];
    CHECK(check_pair(k, p, 4, c, 1, EPS) == 2);
    CHECK(contains_point(c, 2, 1, 1, -0.05, EPS) && contains_point(c, 2, 1, 3, -0.05, EPS));
    CHECK(check_pair(box, ground, 8, c, 1, EPS) == 4);
    for (int i = 0; i < 4; i++) {
        CHECK_NEAR(c[i].depth, 0.02, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
        CHECK_NEAR(fabs(c[i].pos[0]), 0.5, EPS);   // the 1 x 0.5 bottom face
        CHECK_NEAR(fabs(c[i].pos[1]), 0.25, EPS);
    }
    dGeomDestroy(k);
    dGeomDestroy(p);
    dGeomDestroy(box);
    dGeomDestroy(ground);
    dWorldDestroy(w);
    return 0;
}

// ---- random poses -----------------------------------------------------------

static void random_pose(dGeomID g)
{
    dGeomSetPosition(g, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
    dQuaternion q = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
    dReal l = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (l < 1e-3) return;
    for (int i = 0; i < 4; i++) q[i] /= l;
    dGeomSetQuaternion(g, q);
}

static dGeomID random_geom(int cls)
{
    dGeomID g;
    switch (cls) {
    case dSphereClass: g = dCreateSphere(0, rnd(0.1, 1)); break;
    case dBoxClass: g = dCreateBox(0, rnd(0.2, 2), rnd(0.2, 2), rnd(0.2, 2)); break;
    case dCapsuleClass: g = dCreateCapsule(0, rnd(0.1, 0.6), rnd(0, 2)); break;
    case dCylinderClass: g = dCreateCylinder(0, rnd(0.2, 1), rnd(0.2, 2)); break;
    default: {
        double n[3] = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + 1e-9;
        return dCreatePlane(0, n[0] / l, n[1] / l, n[2] / l, rnd(-0.5, 0.5));
    }
    }
    random_pose(g);
    return g;
}

// Thousands of seeded random poses of the pair (c1, c2), both ways round,
// with every max from 1 to 8, and each touching pose again moved to a
// shallow contact: the general checks, the separation rule and agreement of
// the two orders. Same-class pairs are computed from either
// geom's side, so their counts may differ (not their deepest contact).
static int random_pair(int c1, int c2, unsigned long long seed, int *touching)
{
    rng_state = seed;
    *touching = 0;
    for (int it = 0; it < 10000; it++) {
        dGeomID a = random_geom(c1), b = random_geom(c2);
        int max = 1 + it % 8;
        dContactGeom c[MAXC];
        // Points may stray from the shapes by rounding only: 1e-9 / 1e-4.
        // The normal of two balls whose centres are d apart (sphere and
        // capsule pairs) is only known to about eps / d, and random poses
        // give d down to 1e-5: 1e-6 / 1e-2.
        int n = check_pair_ntol(a, b, max, c, c1 != c2, EPS, TOL(1e-6, 1e-2));
        if (n < 0) {
            test_fail(__FILE__, __LINE__, "pair %d-%d, iteration %d", c1, c2, it);
            return 1;
        }
        if (n > 0) {
            ++*touching;
            // The same pair moved to a shallow contact (up to 0.02 deep) along
            // the normal of its deepest contact: the checks again.
            const dContactGeom *k = &c[deepest(c, n)];
            int move_a = dGeomGetClass(a) != dPlaneClass;
            dGeomID g = move_a ? a : b;
            dReal s = (move_a ? 1 : -1) * (k->depth - rnd(0, 0.02));
            const dReal *p = dGeomGetPosition(g);
            dGeomSetPosition(g, p[0] + s * k->normal[0], p[1] + s * k->normal[1],
                             p[2] + s * k->normal[2]);
            if (check_pair_ntol(a, b, max, c, c1 != c2, EPS, TOL(1e-6, 1e-2)) < 0) {
                test_fail(__FILE__, __LINE__, "pair %d-%d, iteration %d, shallow", c1, c2, it);
                return 1;
            }
        }
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    return 0;
}

#define RANDOM_TEST(name, c1, c2, seed) \
    static int name(void) \
    { \
        int touching; \
        CHECK(random_pair(c1, c2, seed, &touching) == 0); \
        CHECK(touching > 1000);   /* the poses do test contacts */ \
        return 0; \
    }

RANDOM_TEST(test_random_sphere_sphere, dSphereClass, dSphereClass, 1)
RANDOM_TEST(test_random_sphere_box, dSphereClass, dBoxClass, 2)
RANDOM_TEST(test_random_sphere_capsule, dSphereClass, dCapsuleClass, 3)
RANDOM_TEST(test_random_sphere_plane, dSphereClass, dPlaneClass, 4)
RANDOM_TEST(test_random_sphere_cylinder, dSphereClass, dCylinderClass, 5)
RANDOM_TEST(test_random_box_box, dBoxClass, dBoxClass, 6)
RANDOM_TEST(test_random_box_plane, dBoxClass, dPlaneClass, 7)
RANDOM_TEST(test_random_capsule_capsule, dCapsuleClass, dCapsuleClass, 8)
RANDOM_TEST(test_random_capsule_box, dCapsuleClass, dBoxClass, 9)
RANDOM_TEST(test_random_capsule_plane, dCapsuleClass, dPlaneClass, 10)
RANDOM_TEST(test_random_cylinder_plane, dCylinderClass, dPlaneClass, 11)

const test_case test_cases[] = {
    TEST_CASE(test_sphere_sphere),
    TEST_CASE(test_sphere_box),
    TEST_CASE(test_sphere_capsule),
    TEST_CASE(test_sphere_plane),
    TEST_CASE(test_sphere_cylinder),
    TEST_CASE(test_box_resting_on_box_gives_its_face),
    TEST_CASE(test_equal_boxes),
    TEST_CASE(test_box_edge_on_edge),
    TEST_CASE(test_box_plane),
    TEST_CASE(test_capsule_capsule),
    TEST_CASE(test_capsule_box),
    TEST_CASE(test_capsule_plane),
    TEST_CASE(test_cylinder_plane),
    TEST_CASE(test_skip_is_honoured),
    TEST_CASE(test_geoms_on_bodies_take_the_body_pose),
    TEST_CASE(test_random_sphere_sphere),
    TEST_CASE(test_random_sphere_box),
    TEST_CASE(test_random_sphere_capsule),
    TEST_CASE(test_random_sphere_plane),
    TEST_CASE(test_random_sphere_cylinder),
    TEST_CASE(test_random_box_box),
    TEST_CASE(test_random_box_plane),
    TEST_CASE(test_random_capsule_capsule),
    TEST_CASE(test_random_capsule_box),
    TEST_CASE(test_random_capsule_plane),
    TEST_CASE(test_random_cylinder_plane),
    TEST_END
};
