// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_util.c -- the collision utilities of guide 10.10:
// dClosestLineSegmentPoints (hand-worked pairs, zero-length and parallel
// segments, random segments against a brute-force minimisation) and
// dBoxTouchesBox (touching and apart faces, a pair only an edge-edge axis
// separates, random boxes against the box-box collider).

#include "collide_check.h"
#include "test.h"

#include <math.h>

// Rounding of a few operations on coordinates ~1 (double 1e-12; single
// 1e-5 covers float's 6e-8 times a few dozen operations).
#define EPS TOL(1e-12, 1e-5)

static void vec(dVector3 v, dReal x, dReal y, dReal z)
{
    v[0] = x;
    v[1] = y;
    v[2] = z;
    v[3] = 0;
}

static double dist(const dReal *a, const dReal *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

// ---- dClosestLineSegmentPoints ---------------------------------------------------

// Closest points of a1-a2 and b1-b2 into c1, c2.
static void closest(const dReal *a1, const dReal *a2, const dReal *b1, const dReal *b2,
                    dVector3 c1, dVector3 c2)
{
    dClosestLineSegmentPoints(a1, a2, b1, b2, c1, c2);
}

static int test_crossing_segments(void)
{
    dVector3 a1, a2, b1, b2, c1, c2;
    // Perpendicular, skew by 1 along z, crossing over their middles.
    vec(a1, -1, 0, 0);
    vec(a2, 1, 0, 0);
    vec(b1, 0, -1, 1);
    vec(b2, 0, 1, 1);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 0, 0, 0, EPS);
    CHECK_VEC(c2, 0, 0, 1, EPS);
    // Intersecting: b is vertical through a's midpoint (1, 1, 0).
    vec(a1, 0, 0, 0);
    vec(a2, 2, 2, 0);
    vec(b1, 1, 1, -1);
    vec(b2, 1, 1, 3);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 1, 1, 0, EPS);
    CHECK_VEC(c2, 1, 1, 0, EPS);
    return 0;
}

static int test_clamped_segments(void)
{
    dVector3 a1, a2, b1, b2, c1, c2;
    // b lies beyond a's end a2: a2 and b's point nearest to it.
    vec(a1, 0, 0, 0);
    vec(a2, 1, 0, 0);
    vec(b1, 2, -1, 1);
    vec(b2, 2, 1, 1);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 1, 0, 0, EPS);
    CHECK_VEC(c2, 2, 0, 1, EPS);
    // Both clamped: b = (2,1,0)-(3,2,0) runs away from a; a2 and b1.
    vec(b1, 2, 1, 0);
    vec(b2, 3, 2, 0);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 1, 0, 0, EPS);
    CHECK_VEC(c2, 2, 1, 0, EPS);
    // The same with the segments given the other way round and reversed.
    closest(b2, b1, a2, a1, c1, c2);
    CHECK_VEC(c1, 2, 1, 0, EPS);
    CHECK_VEC(c2, 1, 0, 0, EPS);
    return 0;
}

static int test_zero_length_segments(void)
{
    dVector3 a1, a2, b1, b2, c1, c2;
    vec(a1, 1, 1, 1);   // a is a point above the middle of b
    vec(b1, 0, 0, 0);
    vec(b2, 2, 0, 0);
    closest(a1, a1, b1, b2, c1, c2);
    CHECK_VEC(c1, 1, 1, 1, 0);
    CHECK_VEC(c2, 1, 0, 0, EPS);
    closest(b1, b2, a1, a1, c1, c2);   // b a point
    CHECK_VEC(c1, 1, 0, 0, EPS);
    CHECK_VEC(c2, 1, 1, 1, 0);
    vec(a2, 5, 1, 1);   // a point beyond b's end: b2
    closest(a2, a2, b1, b2, c1, c2);
    CHECK_VEC(c2, 2, 0, 0, EPS);
    closest(b1, b1, a1, a1, c1, c2);   // two points
    CHECK_VEC(c1, 0, 0, 0, 0);
    CHECK_VEC(c2, 1, 1, 1, 0);
    return 0;
}

// Parallel segments have many closest pairs: the one ODE 0.16 gives (two
// endpoints if they are closest, else b1, b2, a1, a2 with its closest
// point on the other), which always involves an endpoint (guide 10.10).
static int test_parallel_segments(void)
{
    dVector3 a1, a2, b1, b2, c1, c2;
    vec(a1, 0, 0, 0);
    vec(a2, 2, 0, 0);
    vec(b1, 1, 1, 0);   // overlapping, 1 apart: b1 over a's point x = 1
    vec(b2, 3, 1, 0);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 1, 0, 0, EPS);
    CHECK_VEC(c2, 1, 1, 0, 0);
    closest(a1, a2, b2, b1, c1, c2);   // b reversed: b2 now at x = 1
    CHECK_VEC(c1, 1, 0, 0, EPS);
    CHECK_VEC(c2, 1, 1, 0, 0);
    closest(b1, b2, a1, a2, c1, c2);   // swapped: the new b1 is beyond the new a, the
    CHECK_VEC(c1, 2, 1, 0, EPS);       // new b2 (2, 0, 0) under it
    CHECK_VEC(c2, 2, 0, 0, 0);
    vec(b1, 0, 1, 0);   // equal extents: two endpoints, a1 and b1
    vec(b2, 2, 1, 0);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 0, 0, 0, 0);
    CHECK_VEC(c2, 0, 1, 0, 0);
    vec(b1, 3, 1, 0);   // apart along their line: a2 and b1
    vec(b2, 4, 1, 0);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_VEC(c1, 2, 0, 0, 0);
    CHECK_VEC(c2, 3, 1, 0, 0);
    vec(b1, 1, 0, 0);   // on one line, overlapping: a point of both
    vec(b2, 5, 0, 0);
    closest(a1, a2, b1, b2, c1, c2);
    CHECK_NEAR(dist(c1, c2), 0, EPS);
    CHECK_VEC(c2, 1, 0, 0, 0);
    return 0;
}

// The distance of the closest points of a1 + s da, b1 + t db (s, t in
// [0, 1]) by nested ternary searches: |.|^2 is convex in (s, t), and so is
// its minimum over t as a function of s.
static double brute_min_t(const double *r, const double *da, const double *db, double s)
{
    double lo = 0, hi = 1, best = INFINITY;
    for (int k = 0; k < 100; k++) {
        double t[2] = { lo + (hi - lo) / 3, hi - (hi - lo) / 3 }, f[2];
        for (int j = 0; j < 2; j++) {
            double d2 = 0;
            for (int i = 0; i < 3; i++) {
                double e = r[i] + s * da[i] - t[j] * db[i];
                d2 += e * e;
            }
            f[j] = d2;
        }
        if (f[0] < f[1])
            hi = t[1];
        else
            lo = t[0];
        best = fmin(best, fmin(f[0], f[1]));
    }
    return best;
}

static double brute_distance(const dReal *a1, const dReal *a2, const dReal *b1,
                             const dReal *b2)
{
    double r[3], da[3], db[3];
    for (int i = 0; i < 3; i++) {
        r[i] = a1[i] - b1[i];
        da[i] = a2[i] - a1[i];
        db[i] = b2[i] - b1[i];
    }
    double lo = 0, hi = 1, best = INFINITY;
    for (int k = 0; k < 100; k++) {
        double s1 = lo + (hi - lo) / 3, s2 = hi - (hi - lo) / 3;
        double f1 = brute_min_t(r, da, db, s1), f2 = brute_min_t(r, da, db, s2);
        if (f1 < f2)
            hi = s2;
        else
            lo = s1;
        best = fmin(best, fmin(f1, f2));
    }
    return sqrt(best);
}

// Distance of p from the segment a-b (0 if on it).
static double off_segment(const dReal *p, const dReal *a, const dReal *b)
{
    double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, r[3];
    double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], t = 0;
    for (int i = 0; i < 3; i++) r[i] = p[i] - a[i];
    if (dd > 0) t = fmin(1, fmax(0, (r[0] * d[0] + r[1] * d[1] + r[2] * d[2]) / dd));
    double e = 0;
    for (int i = 0; i < 3; i++) e += (r[i] - t * d[i]) * (r[i] - t * d[i]);
    return sqrt(e);
}

// Random segments in general position, nearly parallel (1e-4 apart in
// direction), exactly parallel and zero-length: the points lie on their
// segments and are as close as the brute force finds (its ternary searches
// reach the minimum to ~1e-15 in double; single: float inputs, 1e-5).
static int test_random_segments(void)
{
    rng_state = 12345;
    for (int k = 0; k < 2000; k++) {
        dVector3 p[4], c1, c2;
        for (int j = 0; j < 4; j++) vec(p[j], rnd(-2, 2), rnd(-2, 2), rnd(-2, 2));
        int kind = k % 5;
        for (int i = 0; i < 3; i++) {
            dReal da = p[1][i] - p[0][i];
            if (kind == 1) p[3][i] = p[2][i] + da + rnd(-1e-4, 1e-4);   // nearly parallel
            if (kind == 2) p[3][i] = p[2][i] - 0.5 * da;                // parallel, opposite
            if (kind == 3) p[1][i] = p[0][i];                           // a is a point
        }
        if (kind == 4) dCopyVector3(p[3], p[2]);   // b is a point
        closest(p[0], p[1], p[2], p[3], c1, c2);
        CHECK(off_segment(c1, p[0], p[1]) <= EPS);
        CHECK(off_segment(c2, p[2], p[3]) <= EPS);
        CHECK_NEAR(dist(c1, c2), brute_distance(p[0], p[1], p[2], p[3]), TOL(1e-9, 1e-5));
        if (kind == 2) {   // an endpoint of either segment
            double e = fmin(fmin(dist(c1, p[0]), dist(c1, p[1])),
                            fmin(dist(c2, p[2]), dist(c2, p[3])));
            CHECK(e <= EPS);
        }
    }
    return 0;
}

// ---- dBoxTouchesBox -------------------------------------------------------------

static const dMatrix3 identity = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };

static int test_boxes_touching_and_apart(void)
{
    dVector3 p1, p2, s1, s2;
    vec(p1, 0, 0, 0);
    vec(s1, 2, 2, 2);
    vec(s2, 1, 4, 2);
    vec(p2, 1.5, 0, 0);   // faces x = 1 touch exactly
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 1);
    CHECK(dBoxTouchesBox(p2, identity, s2, p1, identity, s1) == 1);
    const double gap = TOL(1e-6, 1e-3);   // well above the tests' margins (1e-12, 1e-5)
    vec(p2, 1.5 + gap, 0, 0);
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 0);
    CHECK(dBoxTouchesBox(p2, identity, s2, p1, identity, s1) == 0);
    vec(p2, 1.5, 3, 2);   // edge on edge: x = 1, y = 1 (b's y from 1 to 5), z = 1
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 1);
    vec(p2, 1.5, 3 + gap, 2);
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 0);
    vec(p2, 0.2, 0.1, -0.3);   // b's middle inside a
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 1);
    vec(s2, 0.1, 0.1, 0.1);   // a small box entirely inside
    CHECK(dBoxTouchesBox(p1, identity, s1, p2, identity, s2) == 1);
    CHECK(dBoxTouchesBox(p2, identity, s2, p1, identity, s1) == 1);
    return 0;
}

// Two unit-half-side cubes, b turned by Rz(45 deg) Rx(45 deg) and placed at
// (-2.625, 2.625, 0): the projections on all six face normals overlap (by
// at least 0.08), but along the cross product of an edge of each they are
// 0.88 apart (found by a search over placements; ODE 0.16 also says apart).
// Moved closer, to (-1.5, 1.5, 0), they overlap.
static int test_boxes_only_an_edge_axis_separates(void)
{
    const dReal c = (dReal)sqrt(0.5);
    const dMatrix3 R = { c, -0.5, 0.5, 0, c, 0.5, -0.5, 0, 0, c, c, 0 };
    dVector3 p1, p2, s;
    vec(p1, 0, 0, 0);
    vec(s, 2, 2, 2);
    vec(p2, -2.625, 2.625, 0);
    CHECK(dBoxTouchesBox(p1, identity, s, p2, R, s) == 0);
    CHECK(dBoxTouchesBox(p2, R, s, p1, identity, s) == 0);
    vec(p2, -1.5, 1.5, 0);
    CHECK(dBoxTouchesBox(p1, identity, s, p2, R, s) == 1);
    CHECK(dBoxTouchesBox(p2, R, s, p1, identity, s) == 1);
    return 0;
}

static void random_rotation(dMatrix3 R)
{
    dQuaternion q = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
    dNormalize4(q);
    dRfromQ(R, q);
}

// The largest gap of the boxes' projections over the 15 axes, normalised
// (positive: apart by at least that much; near 0: touching).
static double box_gap(const dReal *p1, const dReal *R1, const dReal *s1, const dReal *p2,
                      const dReal *R2, const dReal *s2)
{
    double ax[15][3];
    int n = 0;
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            ax[n][k] = R1[4 * k + i];
            ax[n + 1][k] = R2[4 * k + i];
        }
        n += 2;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double u[3] = { R1[i], R1[4 + i], R1[8 + i] }, v[3] = { R2[j], R2[4 + j], R2[8 + j] };
            double m[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                            u[0] * v[1] - u[1] * v[0] };
            double l = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            if (l < 1e-6) continue;
            for (int k = 0; k < 3; k++) ax[n][k] = m[k] / l;
            n++;
        }
    double gap = -INFINITY;
    for (int a = 0; a < n; a++) {
        double r = 0, d = 0;
        for (int i = 0; i < 3; i++) {
            double u1 = R1[i] * ax[a][0] + R1[4 + i] * ax[a][1] + R1[8 + i] * ax[a][2];
            double u2 = R2[i] * ax[a][0] + R2[4 + i] * ax[a][1] + R2[8 + i] * ax[a][2];
            r += s1[i] / 2 * fabs(u1) + s2[i] / 2 * fabs(u2);
            d += (p2[i] - p1[i]) * ax[a][i];
        }
        gap = fmax(gap, fabs(d) - r);
    }
    return gap;
}

// Random boxes: dBoxTouchesBox agrees with the box-box collider (another
// separating axis implementation, in collide_box.c) on touching or not, and
// with the sign of the largest projection gap, outside a grazing band of
// 1e-6 (single 1e-3). Also symmetric in its arguments.
static int test_random_boxes(void)
{
    rng_state = 12345;
    dInitODE();
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateBox(0, 1, 1, 1);
    int touching = 0, checked = 0;
    for (int k = 0; k < 3000; k++) {
        dVector3 p1, p2, s1, s2;
        dMatrix3 R1, R2;
        vec(p1, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        vec(p2, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        vec(s1, rnd(0.1, 2), rnd(0.1, 2), rnd(0.1, 2));
        vec(s2, rnd(0.1, 2), rnd(0.1, 2), rnd(0.1, 2));
        random_rotation(R1);
        random_rotation(R2);
        if (fabs(box_gap(p1, R1, s1, p2, R2, s2)) < TOL(1e-6, 1e-3)) continue;
        int t = dBoxTouchesBox(p1, R1, s1, p2, R2, s2);
        CHECK(t == dBoxTouchesBox(p2, R2, s2, p1, R1, s1));
        CHECK(t == (box_gap(p1, R1, s1, p2, R2, s2) < 0));
        dGeomBoxSetLengths(a, s1[0], s1[1], s1[2]);
        dGeomBoxSetLengths(b, s2[0], s2[1], s2[2]);
        dGeomSetPosition(a, p1[0], p1[1], p1[2]);
        dGeomSetPosition(b, p2[0], p2[1], p2[2]);
        dGeomSetRotation(a, R1);
        dGeomSetRotation(b, R2);
        dContactGeom c[8];
        CHECK(t == (dCollide(a, b, 8, c, sizeof c[0]) > 0));
        touching += t;
        checked++;
    }
    CHECK(checked > 2900 && touching > 300 && touching < checked - 300);   // both kinds seen
    dGeomDestroy(a);
    dGeomDestroy(b);
    dCloseODE();
    return 0;
}

// dBoxBox on random overlapping boxes gives the contacts dCollide gives for
// the same boxes (positions, depths; normals the same, g1 g2 left 0), its
// normal is the contacts' normal negated, its depth the deepest contact's,
// and its code names an axis the normal lies along: a face normal of box 1
// (1-3) or box 2 (4-6), or perpendicular to both edges of the pair (7-15).
static int test_dboxbox_matches_the_collider(void)
{
    rng_state = 777;
    dInitODE();
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateBox(0, 1, 1, 1);
    int seen_face1 = 0, seen_face2 = 0, seen_edge = 0;
    for (int k = 0; k < 2000; k++) {
        dVector3 p1, p2, s1, s2;
        dMatrix3 R1, R2;
        vec(p1, rnd(-0.5, 0.5), rnd(-0.5, 0.5), rnd(-0.5, 0.5));
        vec(p2, rnd(-0.5, 0.5), rnd(-0.5, 0.5), rnd(-0.5, 0.5));
        vec(s1, rnd(0.1, 2), rnd(0.1, 2), rnd(0.1, 2));
        vec(s2, rnd(0.1, 2), rnd(0.1, 2), rnd(0.1, 2));
        random_rotation(R1);
        random_rotation(R2);
        dGeomBoxSetLengths(a, s1[0], s1[1], s1[2]);
        dGeomBoxSetLengths(b, s2[0], s2[1], s2[2]);
        dGeomSetPosition(a, p1[0], p1[1], p1[2]);
        dGeomSetPosition(b, p2[0], p2[1], p2[2]);
        dGeomSetRotation(a, R1);
        dGeomSetRotation(b, R2);
        dContactGeom c[8], d[8];
        int n = dCollide(a, b, 8, c, sizeof c[0]);
        dVector3 normal;
        dReal depth = -1;
        int code = -1;
        int m = dBoxBox(p1, R1, s1, p2, R2, s2, normal, &depth, &code, 8, d, sizeof d[0]);
        CHECK(m == n);
        if (n == 0) {
            CHECK(code == 0);
            continue;
        }
        CHECK(code >= 1 && code <= 15);
        dReal deepest = 0;
        for (int i = 0; i < n; i++) {
            // (the geoms hold R1, R2 re-orthonormalised: rounding apart)
            const double tol = TOL(1e-12, 1e-4);
            CHECK_VEC(d[i].pos, c[i].pos[0], c[i].pos[1], c[i].pos[2], tol);
            CHECK_VEC(d[i].normal, c[i].normal[0], c[i].normal[1], c[i].normal[2], tol);
            CHECK_VEC(normal, -c[i].normal[0], -c[i].normal[1], -c[i].normal[2], tol);
            CHECK_NEAR(d[i].depth, c[i].depth, tol);
            CHECK(d[i].g1 == 0 && d[i].g2 == 0);
            if (c[i].depth > deepest) deepest = c[i].depth;
        }
        CHECK(depth >= deepest - EPS);
        if (code <= 6) {   // along a face normal: |normal . axis| = 1
            const dReal *R = code <= 3 ? R1 : R2;
            int col = (code - 1) % 3;
            CHECK_NEAR(fabs(normal[0] * R[col] + normal[1] * R[4 + col] + normal[2] * R[8 + col]),
                       1, EPS);
            if (code <= 3) seen_face1++;
            else seen_face2++;
        } else {   // perpendicular to both edges
            int i = (code - 7) / 3, j = (code - 7) % 3;
            CHECK_NEAR(normal[0] * R1[i] + normal[1] * R1[4 + i] + normal[2] * R1[8 + i], 0, EPS);
            CHECK_NEAR(normal[0] * R2[j] + normal[1] * R2[4 + j] + normal[2] * R2[8 + j], 0, EPS);
            seen_edge++;
        }
    }
    CHECK(seen_face1 > 50 && seen_face2 > 50 && seen_edge > 10);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dCloseODE();
    return 0;
}

// A box resting on a wider box: the normal from box 1 into box 2 is -z, the
// depth its overlap, and four contacts at box 1's bottom corners.
static int test_dboxbox_resting_box(void)
{
    dVector3 p1, p2, s1, s2, normal;
    dMatrix3 R;
    dRSetIdentity(R);
    vec(p1, 0, 0, REAL(0.49));
    vec(s1, 1, 1, 1);
    vec(p2, 0, 0, -REAL(0.5));
    vec(s2, 4, 4, 1);
    dContactGeom c[8];
    dReal depth;
    int code;
    int n = dBoxBox(p1, R, s1, p2, R, s2, normal, &depth, &code, 8, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK(code == 6 || code == 3);   // box 2's top face or box 1's bottom face
    CHECK_VEC(normal, 0, 0, -1, EPS);
    CHECK_NEAR(depth, 0.01, EPS);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(fabs(c[i].pos[0]), 0.5, EPS);
        CHECK_NEAR(fabs(c[i].pos[1]), 0.5, EPS);
        CHECK_NEAR(c[i].depth, 0.01, EPS);
    }
    vec(p1, 0, 0, 2);   // apart
    CHECK(dBoxBox(p1, R, s1, p2, R, s2, normal, &depth, &code, 8, c, sizeof c[0]) == 0);
    CHECK(code == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_crossing_segments),
    TEST_CASE(test_clamped_segments),
    TEST_CASE(test_zero_length_segments),
    TEST_CASE(test_parallel_segments),
    TEST_CASE(test_random_segments),
    TEST_CASE(test_boxes_touching_and_apart),
    TEST_CASE(test_boxes_only_an_edge_axis_separates),
    TEST_CASE(test_random_boxes),
    TEST_CASE(test_dboxbox_matches_the_collider),
    TEST_CASE(test_dboxbox_resting_box),
    TEST_END,
};
