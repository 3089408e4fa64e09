// SPDX-License-Identifier: BSD-3-Clause
//
// test_convex.c -- the convex hull geom (ODE 0.16's dCreateConvex) through
// dCollide. A convex built as a box must behave as that box: on seeded
// random poses its contacts with a box, a plane and a sphere equal the box's
// own (box-box, box-plane, sphere-box: same count, each contact within
// 1e-9), its depths and normals with a capsule and a cylinder agree with
// the box's, and rays hit it where they hit the box; both argument orders.
// A convex cube rests on a plane under dWorldStep and dWorldQuickStep at the
// box's height with four contacts, and lies on a box with the face polygon.
// A non-box hull (an octahedron) gets the analytic sphere depth. Bad input
// is a named error, never a crash.

#include "collide_check.h"
#include "convex_depth.h"
#include "convex_hulls.h"
#include "test.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { MAXC = 16 };

#define EPS TOL(1e-9, 2e-4)

// ---- hull data --------------------------------------------------------------------

// ---- poses and comparisons ----------------------------------------------------------

static void random_rotation(dMatrix3 R)
{
    dReal q[4];
    double n = 0;
    do {
        n = 0;
        for (int i = 0; i < 4; i++) {
            q[i] = (dReal)rnd(-1, 1);
            n += (double)q[i] * q[i];
        }
    } while (n < 0.1 || n > 1);
    for (int i = 0; i < 4; i++) q[i] = (dReal)(q[i] / sqrt(n));
    dRfromQ(R, q);
}

static void place(dGeomID g, const dReal *p, const dMatrix3 R)
{
    dGeomSetPosition(g, p[0], p[1], p[2]);
    dGeomSetRotation(g, R);
}

// Contact a matches b: position, normal, depth within tol, and g1/g2 as given.
static int same_contact(const dContactGeom *a, const dContactGeom *b, double tol)
{
    for (int i = 0; i < 3; i++)
        if (fabs(a->pos[i] - b->pos[i]) > tol || fabs(a->normal[i] - b->normal[i]) > tol)
            return 0;
    return fabs(a->depth - b->depth) <= tol;
}

// Every contact of c (n) matches one of ref (m = n), each used once.
static inline int same_sets(const dContactGeom *c, int n, const dContactGeom *ref, int m, double tol)
{
    if (n != m) return 0;
    int used[MAXC] = { 0 };
    for (int i = 0; i < n; i++) {
        int found = 0;
        for (int j = 0; j < m && !found; j++)
            if (!used[j] && same_contact(&c[i], &ref[j], tol)) found = used[j] = 1;
        if (!found) return 0;
    }
    return 1;
}

#ifdef dSINGLE
// The deepest contacts match. In single precision box-box's float
// clipping of deep overlaps can keep or lose a clipped corner that the
// double computation of the hull drops or keeps: only the deepest is
// compared there (double compares the whole sets).
static inline int same_deepest(const dContactGeom *c, int n, const dContactGeom *ref, int m,
                               double tol)
{
    return n > 0 && m > 0 && same_contact(&c[deepest(c, n)], &ref[deepest(ref, m)], tol);
}
#define SAME_SETS same_deepest
#else
#define SAME_SETS same_sets
#endif

// g1 / g2 of every contact are (a, b).
static int names(const dContactGeom *c, int n, dGeomID a, dGeomID b)
{
    for (int i = 0; i < n; i++)
        if (c[i].g1 != a || c[i].g2 != b) return 0;
    return 1;
}

// ---- the convex cube as a box ----------------------------------------------------

// The convex (made from the box's sides) and the box both at (p, R), each
// collided with `other` in both orders: the same contacts (as sets), or
// only the same deepest depth and normal (deep_only, with tol). Counts the
// poses where they touch.
typedef struct pair_stats {
    int touching, checked;
} pair_stats;

static int compare_pair(dGeomID hull, dGeomID box, dGeomID other, int max, int deep_only,
                        double tol, pair_stats *st)
{
    dContactGeom ch[MAXC], cb[MAXC];
    for (int order = 0; order < 2; order++) {
        int nh = order ? dCollide(other, hull, max, ch, sizeof ch[0])
                       : dCollide(hull, other, max, ch, sizeof ch[0]);
        int nb = order ? dCollide(other, box, max, cb, sizeof cb[0])
                       : dCollide(box, other, max, cb, sizeof cb[0]);
        if ((nh > 0) != (nb > 0)) {
            // Only a grazing pose may disagree.
            const dContactGeom *k = nh ? &ch[deepest(ch, nh)] : &cb[deepest(cb, nb)];
            if (k->depth > tol) {
                fprintf(stderr, "# order %d: convex %d contacts, box %d (depth %g)\n", order,
                        nh, nb, (double)k->depth);
                return 1;
            }
            continue;
        }
        if (nh == 0) continue;
        st->touching++;
        CHECK(nh <= max);
        CHECK(order ? names(ch, nh, other, hull) : names(ch, nh, hull, other));
        if (!deep_only) {
            if (!SAME_SETS(ch, nh, cb, nb, tol)) {
                fprintf(stderr, "# order %d: sets differ (%d vs %d)\n", order, nh, nb);
                for (int i = 0; i < nh || i < nb; i++)
                    fprintf(stderr, "#  %s %s\n", i < nh ? "h" : " ", i < nb ? "b" : " ");
                for (int i = 0; i < nh; i++)
                    fprintf(stderr, "#  h pos %.12g %.12g %.12g n %.12g %.12g %.12g d %.12g\n",
                            (double)ch[i].pos[0], (double)ch[i].pos[1], (double)ch[i].pos[2],
                            (double)ch[i].normal[0], (double)ch[i].normal[1],
                            (double)ch[i].normal[2], (double)ch[i].depth);
                for (int i = 0; i < nb; i++)
                    fprintf(stderr, "#  b pos %.12g %.12g %.12g n %.12g %.12g %.12g d %.12g\n",
                            (double)cb[i].pos[0], (double)cb[i].pos[1], (double)cb[i].pos[2],
                            (double)cb[i].normal[0], (double)cb[i].normal[1],
                            (double)cb[i].normal[2], (double)cb[i].depth);
                return 1;
            }
        } else {
            // The deepest depths agree, and each normal is a direction
            // along which the pair parts by that depth (the box's support
            // functions): near-ties between directions make the normals
            // themselves differ.
            const dContactGeom *kh = &ch[deepest(ch, nh)], *kb = &cb[deepest(cb, nb)];
            CHECK_NEAR(kh->depth, kb->depth, tol);
            double n[3] = { kh->normal[0], kh->normal[1], kh->normal[2] };
            double along = order ? convex_depth_along(other, box, n)
                                 : convex_depth_along(box, other, n);
            CHECK_NEAR(along, kh->depth, tol);
        }
        st->checked++;
    }
    return 0;
}

// `poses` random poses of a convex box and a box of the same random sides
// against `other` (posed near them by pose_other); then the statistics.
static int random_against(dGeomID other, int max, int deep_only, double tol, int poses,
                          unsigned long long seed, int placeable_other, pair_stats *st)
{
    rng_state = seed;
    test_hull bh;
    dReal s[3] = { (dReal)rnd(0.3, 2), (dReal)rnd(0.3, 2), (dReal)rnd(0.3, 2) };
    test_hull_box(&bh, s[0], s[1], s[2]);
    dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    dGeomID box = dCreateBox(0, s[0], s[1], s[2]);
    CHECK(hull && dGeomGetClass(hull) == dConvexClass);
    for (int k = 0; k < poses; k++) {
        dMatrix3 R;
        dReal p[3];
        random_rotation(R);
        for (int i = 0; i < 3; i++) p[i] = (dReal)rnd(-1, 1);
        place(hull, p, R);
        place(box, p, R);
        if (placeable_other) {
            dMatrix3 Ro;
            dReal po[3];
            random_rotation(Ro);
            for (int i = 0; i < 3; i++) po[i] = (dReal)rnd(-1, 1);
            place(other, po, Ro);
        }
        if (compare_pair(hull, box, other, max, deep_only, tol, st)) {
            fprintf(stderr, "# pose %d\n", k);
            dGeomDestroy(hull);
            dGeomDestroy(box);
            return 1;
        }
    }
    dGeomDestroy(hull);
    dGeomDestroy(box);
    return 0;
}

static int test_box_equals_box_box(void)
{
    pair_stats st = { 0, 0 };
    for (int run = 0; run < 4; run++) {
        rng_state = 100 + (unsigned long long)run;
        dGeomID other = dCreateBox(0, (dReal)rnd(0.3, 2), (dReal)rnd(0.3, 2), (dReal)rnd(0.3, 2));
        int bad = random_against(other, MAXC, 0, EPS, 250, 7 + (unsigned long long)run, 1, &st);
        dGeomDestroy(other);
        CHECK(!bad);
    }
    printf("# convex-box: %d touching of %d compared, all as box-box\n", st.touching, st.checked);
    CHECK(st.touching > 300);
    return 0;
}

static int test_box_equals_box_plane(void)
{
    pair_stats st = { 0, 0 };
    dGeomID plane = dCreatePlane(0, (dReal)0.3, (dReal)0.2, 1, (dReal)0.1);
    // Box-plane keeps at most 4 corners.
    CHECK(!random_against(plane, 4, 0, EPS, 400, 21, 0, &st));
    dGeomDestroy(plane);
    CHECK(st.touching > 200);
    return 0;
}

static int test_box_equals_sphere_box(void)
{
    pair_stats st = { 0, 0 };
    dGeomID s = dCreateSphere(0, (dReal)0.6);
    CHECK(!random_against(s, 1, 0, EPS, 400, 31, 1, &st));
    dGeomDestroy(s);
    CHECK(st.touching > 200);
    return 0;
}

static int test_box_like_capsule_box(void)
{
    pair_stats st = { 0, 0 };
    dGeomID c = dCreateCapsule(0, (dReal)0.3, (dReal)0.8);
    CHECK(!random_against(c, MAXC, 1, TOL(1e-6, 1e-3), 400, 41, 1, &st));
    dGeomDestroy(c);
    CHECK(st.touching > 200);
    return 0;
}

static int test_box_like_cylinder_box(void)
{
    pair_stats st = { 0, 0 };
    dGeomID c = dCreateCylinder(0, (dReal)0.4, (dReal)0.9);
    CHECK(!random_against(c, MAXC, 1, TOL(1e-3, 2e-3), 300, 51, 1, &st));
    dGeomDestroy(c);
    CHECK(st.touching > 150);
    return 0;
}

// Convex against convex: two convex boxes as the two boxes.
static int test_convex_convex_equals_box_box(void)
{
    rng_state = 61;
    int touching = 0;
    for (int k = 0; k < 600; k++) {
        test_hull ha, hb;
        dReal sa[3], sb[3];
        for (int i = 0; i < 3; i++) {
            sa[i] = (dReal)rnd(0.3, 2);
            sb[i] = (dReal)rnd(0.3, 2);
        }
        test_hull_box(&ha, sa[0], sa[1], sa[2]);
        test_hull_box(&hb, sb[0], sb[1], sb[2]);
        dGeomID a = dCreateConvex(0, ha.planes, 6, ha.points, 8, ha.polygons);
        dGeomID b = dCreateConvex(0, hb.planes, 6, hb.points, 8, hb.polygons);
        dGeomID ba = dCreateBox(0, sa[0], sa[1], sa[2]), bb = dCreateBox(0, sb[0], sb[1], sb[2]);
        dMatrix3 Ra, Rb;
        dReal pa[3], pb[3];
        random_rotation(Ra);
        random_rotation(Rb);
        for (int i = 0; i < 3; i++) {
            pa[i] = (dReal)rnd(-1, 1);
            pb[i] = (dReal)rnd(-1, 1);
        }
        place(a, pa, Ra);
        place(ba, pa, Ra);
        place(b, pb, Rb);
        place(bb, pb, Rb);
        dContactGeom c[MAXC], r[MAXC];
        int n = dCollide(a, b, MAXC, c, sizeof c[0]), m = dCollide(ba, bb, MAXC, r, sizeof r[0]);
        int ok = (n > 0) == (m > 0) || (n ? c[deepest(c, n)].depth : r[deepest(r, m)].depth) < EPS;
        if (ok && n > 0 && m > 0) {
            touching++;
            ok = SAME_SETS(c, n, r, m, EPS) && names(c, n, a, b);
        }
        dGeomDestroy(a);
        dGeomDestroy(b);
        dGeomDestroy(ba);
        dGeomDestroy(bb);
        if (!ok) {
            fprintf(stderr, "# pose %d: %d vs %d contacts\n", k, n, m);
            for (int i = 0; i < n || i < m; i++)
                fprintf(stderr, "#  %g %g %g %g | %g %g %g %g\n", i < n ? c[i].pos[0] : 0,
                        i < n ? c[i].pos[1] : 0, i < n ? c[i].pos[2] : 0, i < n ? c[i].depth : 0,
                        i < m ? r[i].pos[0] : 0, i < m ? r[i].pos[1] : 0, i < m ? r[i].pos[2] : 0,
                        i < m ? r[i].depth : 0);
        }
        CHECK(ok);
    }
    CHECK(touching > 150);
    return 0;
}

// Rays from random starts towards the box: the same hit as the box's.
static int test_rays_as_box(void)
{
    rng_state = 71;
    test_hull bh;
    test_hull_box(&bh, 1, (dReal)0.6, (dReal)1.4);
    dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    dGeomID box = dCreateBox(0, 1, (dReal)0.6, (dReal)1.4);
    dGeomID ray = dCreateRay(0, 3);
    int hits = 0, inside = 0;
    for (int k = 0; k < 500; k++) {
        dMatrix3 R;
        dReal p[3] = { (dReal)rnd(-.2, .2), (dReal)rnd(-.2, .2), (dReal)rnd(-.2, .2) };
        random_rotation(R);
        place(hull, p, R);
        place(box, p, R);
        dReal s[3], d[3];
        for (int i = 0; i < 3; i++) {
            s[i] = (dReal)rnd(-1.5, 1.5);
            d[i] = (dReal)rnd(-1, 1) - s[i] * (dReal)0.5;
        }
        dGeomRaySet(ray, s[0], s[1], s[2], d[0], d[1], d[2]);
        for (int order = 0; order < 2; order++) {
            dContactGeom c[2], r[2];
            int n = order ? dCollide(hull, ray, 2, c, sizeof c[0]) : dCollide(ray, hull, 2, c, sizeof c[0]);
            int m = order ? dCollide(box, ray, 2, r, sizeof r[0]) : dCollide(ray, box, 2, r, sizeof r[0]);
            CHECK(n == m && n <= 1);
            if (!n) continue;
            hits += !order;
            inside += !order && dGeomBoxPointDepth(box, s[0], s[1], s[2]) > 0;
            CHECK(same_contact(&c[0], &r[0], EPS));
            CHECK(order ? names(c, 1, hull, ray) : names(c, 1, ray, hull));
        }
    }
    CHECK(hits > 100 && inside > 10);
    dGeomDestroy(hull);
    dGeomDestroy(box);
    dGeomDestroy(ray);
    return 0;
}

// ---- a hull that is not a box ----------------------------------------------------

// The octahedron |x| + |y| + |z| <= 1: 6 points, 8 triangles.
static dReal octa_points[18] = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
static dReal octa_planes[32];
static unsigned octa_polygons[32];

static dGeomID make_octahedron(void)
{
    for (int f = 0; f < 8; f++) {
        dReal sx = f & 1 ? -1 : 1, sy = f & 2 ? -1 : 1, sz = f & 4 ? -1 : 1;
        dReal k = 1 / dSqrt(3);
        octa_planes[4 * f] = sx * k;
        octa_planes[4 * f + 1] = sy * k;
        octa_planes[4 * f + 2] = sz * k;
        octa_planes[4 * f + 3] = k;
        unsigned px = sx > 0 ? 0 : 1, py = sy > 0 ? 2 : 3, pz = sz > 0 ? 4 : 5;
        octa_polygons[4 * f] = 3;
        // Counterclockwise seen from outside: x, y, z when the signs' product is +.
        int even = sx * sy * sz > 0;
        octa_polygons[4 * f + 1] = px;
        octa_polygons[4 * f + 2] = even ? py : pz;
        octa_polygons[4 * f + 3] = even ? pz : py;
    }
    return dCreateConvex(0, octa_planes, 8, octa_points, 6, octa_polygons);
}

// A sphere over a face, over an edge, over a corner, and inside: the exact
// depths and normals.
static int test_octahedron_sphere(void)
{
    dGeomID o = make_octahedron(), s = dCreateSphere(0, (dReal)0.5);
    CHECK(o);
    dContactGeom c[4];
    dReal k = 1 / dSqrt(3);
    // Over the face (+,+,+) at distance 0.4 from it.
    dReal f = k + (dReal)0.4;
    dGeomSetPosition(s, f * k, f * k, f * k);
    CHECK(dCollide(o, s, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].normal, -k, -k, -k, EPS);
    CHECK_VEC(c[0].pos, k * k, k * k, k * k, EPS);
    // Over the corner (0, 0, 1) along z, 0.3 above it.
    dGeomSetPosition(s, 0, 0, (dReal)1.3);
    CHECK(dCollide(s, o, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.2, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    CHECK_VEC(c[0].pos, 0, 0, 1, EPS);
    // Over the edge from (1,0,0) to (0,1,0), 0.45 out.
    dReal e = (dReal)(0.5 + 0.45 / sqrt(2));
    dGeomSetPosition(s, e, e, 0);
    CHECK(dCollide(s, o, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.05, EPS);
    CHECK_VEC(c[0].normal, 1 / sqrt(2), 1 / sqrt(2), 0, EPS);
    // Centre inside, 0.2 from the face (+,+,+): out through it.
    f = k - (dReal)0.2;
    dGeomSetPosition(s, f * k, f * k, f * k);
    CHECK(dCollide(s, o, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.7, EPS);
    CHECK_VEC(c[0].normal, k, k, k, EPS);
    // Apart.
    dGeomSetPosition(s, 0, 0, (dReal)1.6);
    CHECK(dCollide(s, o, 4, c, sizeof c[0]) == 0);
    // The AABB is the points', posed.
    dReal aabb[6];
    dGeomSetPosition(o, 1, 2, 3);
    dGeomGetAABB(o, aabb);
    CHECK_NEAR(aabb[0], 0, EPS);
    CHECK_NEAR(aabb[1], 2, EPS);
    CHECK_NEAR(aabb[4], 2, EPS);
    CHECK_NEAR(aabb[5], 4, EPS);
    dGeomDestroy(o);
    dGeomDestroy(s);
    return 0;
}

// An octahedron on a plane, point down: one contact at the tip; a capsule
// lying across its top corner: one contact; a capsule lying on a face: two.
static int test_octahedron_capsule_plane(void)
{
    dGeomID o = make_octahedron(), p = dCreatePlane(0, 0, 0, 1, -(dReal)0.9);
    dContactGeom c[MAXC];
    CHECK(dCollide(o, p, MAXC, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.1, EPS);
    CHECK_VEC(c[0].pos, 0, 0, -1, EPS);
    CHECK_VEC(c[0].normal, 0, 0, 1, EPS);
    dGeomID cap = dCreateCapsule(0, (dReal)0.2, 1);
    set_rot(cap, 1, 0, 0, (dReal)(M_PI / 2));   // along y
    dGeomSetPosition(cap, 0, 0, (dReal)1.15);
    CHECK(dCollide(o, cap, MAXC, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.05, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    // Lying on the face (+,+,+), along the face's direction (1,-1,0)/sqrt 2,
    // 0.15 over it: both ends sink 0.05.
    dReal k = 1 / dSqrt(3), f = k + (dReal)0.15, s2 = dSqrt(2);
    dMatrix3 R;
    dRFromZAxis(R, 1 / s2, -1 / s2, 0);
    dGeomSetRotation(cap, R);
    dGeomSetPosition(cap, f * k, f * k, f * k);
    int n = dCollide(o, cap, MAXC, c, sizeof c[0]);
    CHECK(n == 2);
    for (int i = 0; i < 2; i++) {
        CHECK_NEAR(c[i].depth, 0.05, EPS);
        CHECK_VEC(c[i].normal, -k, -k, -k, EPS);
        CHECK(point_depth(cap, c[i].pos) >= -EPS);
    }
    dGeomDestroy(o);
    dGeomDestroy(p);
    dGeomDestroy(cap);
    return 0;
}

// A cylinder standing on a convex box's top: its rim points over the face
// (a polygon around the axis), all 0.02 deep; lying: its two line ends.
static int test_cylinder_on_convex(void)
{
    test_hull bh;
    test_hull_box(&bh, 4, 4, 1);
    dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    dGeomID cyl = dCreateCylinder(0, (dReal)0.5, 1);
    dGeomSetPosition(cyl, (dReal)0.2, (dReal)0.1, (dReal)0.98);
    dContactGeom c[MAXC];
    int n = dCollide(cyl, hull, MAXC, c, sizeof c[0]);
    CHECK(n >= 8);
    double cx = 0, cy = 0;
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 0.02, TOL(1e-7, 1e-4));
        CHECK_VEC(c[i].normal, 0, 0, 1, TOL(1e-7, 1e-4));
        CHECK(point_depth(cyl, c[i].pos) >= -TOL(1e-7, 1e-4));
        cx += c[i].pos[0] / n;
        cy += c[i].pos[1] / n;
    }
    CHECK_NEAR(cx, 0.2, 1e-6);
    CHECK_NEAR(cy, 0.1, 1e-6);
    set_rot(cyl, 1, 0, 0, (dReal)(M_PI / 2));
    dGeomSetPosition(cyl, 0, 0, (dReal)0.99);
    n = dCollide(hull, cyl, MAXC, c, sizeof c[0]);
    CHECK(n == 2);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 0.01, TOL(1e-7, 1e-4));
        CHECK_VEC(c[i].normal, 0, 0, -1, TOL(1e-7, 1e-4));
    }
    CHECK_NEAR(fabs(c[0].pos[1] - c[1].pos[1]), 1, TOL(1e-7, 1e-4));
    dGeomDestroy(hull);
    dGeomDestroy(cyl);
    return 0;
}

// Thin or point-like hulls against zero-radius cylinders 1e6 long: poses on
// which libccd's MPR never ended (found by a search over degenerate sizes
// after a fuzz_space timeout; the last one still looped when the bound
// only collapsed the support points to the shapes' centres). The call
// returns, both ways round, with at most the contacts asked for, each finite
// with a unit normal and a depth no more than the two shapes' widths.
static int test_mpr_without_end_is_cut_short(void)
{
    static const struct {
        double h[3], r, len, pos[3], axis[3], angle;
    } cases[] = {
        { { 0.5, 1e-6, 1e-6 }, 0, 1e6, { 0.5, 0, 0 }, { 1, 0, 1 }, M_PI / 2 },
        { { 1e-30, 0, 1e-6 }, 1e-30, 1e6, { -1e-6, 1e-6, -1e-30 }, { 1, 1, 1 }, M_PI / 2 },
        { { 1e-30, 1e-6, 1e-6 }, 1e-30, 1e6, { 1e-30, 0, 1e-6 }, { 1, 0, 1 }, M_PI / 2 },
        { { 1e-6, 1e-30, 1e-30 }, 1e-30, 1e6, { 0, 0, 1 }, { 1, 1, 1 }, 2.65016 },
        { { 0.5, 1e-6, 1e-30 }, 1e-30, 1e6, { -1e-30, 0, 1e-6 }, { 1, 1, 1 }, 5.56408 },
        { { 1e-30, 1e-30, 1e-30 }, 1e-30, 1e6, { 1, -1, -1e-6 }, { 1, 0, 1 }, 1.99076 },
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        test_hull bh;
        const double *h = cases[k].h;
        test_hull_box(&bh, 2 * h[0], 2 * h[1], 2 * h[2]);
        dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
        dGeomID cyl = dCreateCylinder(0, (dReal)cases[k].r, (dReal)cases[k].len);
        dGeomSetPosition(cyl, (dReal)cases[k].pos[0], (dReal)cases[k].pos[1],
                         (dReal)cases[k].pos[2]);
        set_rot(cyl, (dReal)cases[k].axis[0], (dReal)cases[k].axis[1], (dReal)cases[k].axis[2],
                (dReal)cases[k].angle);
        const double widths = 2 * sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]) + 2 * cases[k].r;
        dContactGeom c[MAXC];
        for (int order = 0; order < 2; order++) {
            const int n = order ? dCollide(cyl, hull, MAXC, c, sizeof c[0])
                                : dCollide(hull, cyl, MAXC, c, sizeof c[0]);
            CHECK(n >= 0 && n <= MAXC);
            for (int i = 0; i < n; i++) {
                CHECK(isfinite(c[i].pos[0]) && isfinite(c[i].pos[1]) && isfinite(c[i].pos[2]));
                CHECK_NEAR(dCalcVectorLength3(c[i].normal), 1, EPS);
                CHECK(c[i].depth >= 0 && c[i].depth <= widths + TOL(1e-6, 1));
            }
        }
        dGeomDestroy(hull);
        dGeomDestroy(cyl);
    }
    return 0;
}

// A zero-radius capsule 1e6 long through a flat square hull's edge (found by
// test_collide_degenerate.c): the contact was put at the segment's far half
// (250 km out) with a depth of -4e-12. It lies on the edge now, 0 deep
// within rounding, both ways round.
static int test_needle_capsule_on_flat_hull_edge(void)
{
    test_hull bh;
    test_hull_box(&bh, 2, 2, 2e-30);
    dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    dGeomID cap = dCreateCapsule(0, (dReal)1e-30, (dReal)1e6);
    set_rot(cap, 1, 1, 1, (dReal)(M_PI / 2));
    dGeomSetPosition(cap, 0, 1, 0);   // its axis meets the edge y = 1 at x = 0
    dContactGeom c[MAXC];
    for (int order = 0; order < 2; order++) {
        const int n = order ? dCollide(cap, hull, MAXC, c, sizeof c[0])
                            : dCollide(hull, cap, MAXC, c, sizeof c[0]);
        CHECK(n >= 1);
        for (int i = 0; i < n; i++) {
            CHECK(c[i].depth >= 0 && c[i].depth <= TOL(1e-9, 1e-1));
            CHECK_VEC(c[i].pos, 0, 1, 0, TOL(1e-6, 1e-1));
        }
    }
    dGeomDestroy(hull);
    dGeomDestroy(cap);
    return 0;
}

// A prism over a regular 40-gon (120 edges: more than the colliders keep
// posed), radius 1 to the corners, height 1 (into p, which the geom keeps).
enum { SIDES = 40 };
typedef struct prism {
    dReal points[6 * SIDES], planes[4 * (SIDES + 2)];
    unsigned polygons[2 * (SIDES + 1) + 5 * SIDES];
} prism;

static dGeomID make_prism(prism *p)
{
    unsigned *q = p->polygons;
    for (int i = 0; i < SIDES; i++) {
        double a = 2 * M_PI * i / SIDES, b = a + M_PI / SIDES;
        for (int top = 0; top < 2; top++) {
            dReal *v = p->points + 3 * (SIDES * top + i);
            v[0] = (dReal)cos(a);
            v[1] = (dReal)sin(a);
            v[2] = top ? (dReal)0.5 : (dReal)-0.5;
        }
        dReal *pl = p->planes + 4 * (2 + i);
        pl[0] = (dReal)cos(b);
        pl[1] = (dReal)sin(b);
        pl[2] = 0;
        pl[3] = (dReal)cos(M_PI / SIDES);
    }
    const dReal caps[8] = { 0, 0, 1, (dReal)0.5, 0, 0, -1, (dReal)0.5 };
    memcpy(p->planes, caps, sizeof caps);
    *q++ = SIDES;
    for (int i = 0; i < SIDES; i++) *q++ = (unsigned)(SIDES + i);
    *q++ = SIDES;
    for (int i = SIDES - 1; i >= 0; i--) *q++ = (unsigned)i;
    for (int i = 0; i < SIDES; i++) {
        unsigned j = (unsigned)(i + 1) % SIDES;
        *q++ = 4;
        *q++ = (unsigned)i;
        *q++ = j;
        *q++ = SIDES + j;
        *q++ = (unsigned)(SIDES + i);
    }
    return dCreateConvex(0, p->planes, SIDES + 2, p->points, 2 * SIDES, p->polygons);
}

// The prism standing on a box and on another prism (turned about z): the
// bottom polygon, MAXC of its corners spread, each as deep as it sinks.
static int test_large_prism(void)
{
    static prism pa, pb;
    dGeomID a = make_prism(&pa), b = make_prism(&pb), box = dCreateBox(0, 5, 5, 1);
    CHECK(a && b);
    dGeomSetPosition(a, (dReal)0.1, 0, (dReal)0.99);
    dContactGeom c[MAXC];
    int n = dCollide(a, box, MAXC, c, sizeof c[0]);
    CHECK(n == MAXC);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 0.01, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
        double r = hypot(c[i].pos[0] - 0.1, c[i].pos[1]);
        CHECK_NEAR(r, 1, 1e-3 + EPS);   // corners (pos within the 2.5 mm sagitta)
    }
    set_rot(b, 0, 0, 1, (dReal)0.05);
    dGeomSetPosition(b, 0, 0, (dReal)-0.98);
    dGeomSetPosition(a, 0, 0, 0);
    n = dCollide(a, b, MAXC, c, sizeof c[0]);
    CHECK(n == MAXC);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 0.02, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomDestroy(box);
    return 0;
}

// ---- resting ------------------------------------------------------------------

// A 0.5 cube (as convex, or as a box) dropped on a plane at z = 0: its
// height after `steps`, and the contact count then.
static int rest_on_plane(int as_convex, int quick, double *height, int *contacts)
{
    static test_hull bh;
    test_hull_box(&bh, (dReal)0.5, (dReal)0.5, (dReal)0.5);
    dWorldID w = dWorldCreate();
    dSpaceID space = dSimpleSpaceCreate(0);
    dJointGroupID group = dJointGroupCreate(0);
    dWorldSetGravity(w, 0, 0, (dReal)-9.81);
    dGeomID plane = dCreatePlane(space, 0, 0, 1, 0);
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBox(&m, 1, (dReal)0.5, (dReal)0.5, (dReal)0.5);
    dBodySetMass(b, &m);
    dBodySetPosition(b, 0, 0, (dReal)0.3);
    dGeomID g = as_convex ? dCreateConvex(space, bh.planes, 6, bh.points, 8, bh.polygons)
                          : dCreateBox(space, (dReal)0.5, (dReal)0.5, (dReal)0.5);
    dGeomSetBody(g, b);
    int n = 0;
    for (int step = 0; step < 300; step++) {
        dContactGeom cg[8];
        n = dCollide(g, plane, 8, cg, sizeof cg[0]);
        for (int i = 0; i < n; i++) {
            dContact ct;
            memset(&ct, 0, sizeof ct);
            ct.surface.mode = dContactSoftERP | dContactSoftCFM;
            ct.surface.mu = 1;
            ct.surface.soft_erp = (dReal)0.2;
            ct.surface.soft_cfm = (dReal)1e-5;
            ct.geom = cg[i];
            dJointAttach(dJointCreateContact(w, group, &ct), b, 0);
        }
        if (quick)
            dWorldQuickStep(w, (dReal)0.01);
        else
            dWorldStep(w, (dReal)0.01);
        dJointGroupEmpty(group);
    }
    *height = dBodyGetPosition(b)[2];
    *contacts = n;
    dJointGroupDestroy(group);
    dSpaceDestroy(space);
    dWorldDestroy(w);
    return 0;
}

static int test_resting_on_plane(void)
{
    for (int quick = 0; quick < 2; quick++) {
        double hc, hb;
        int nc, nb;
        rest_on_plane(1, quick, &hc, &nc);
        rest_on_plane(0, quick, &hb, &nb);
        CHECK(nc == 4 && nb == 4);
        CHECK_NEAR(hc, hb, 1e-3);
        CHECK_NEAR(hc, 0.25, 2e-3);
    }
    return 0;
}

// A convex cube lying on a larger box: the face polygon (its 4 corners).
static int test_cube_on_box_polygon(void)
{
    test_hull bh;
    test_hull_box(&bh, 1, 1, 1);
    dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    dGeomID box = dCreateBox(0, 4, 4, 1);
    dGeomSetPosition(hull, (dReal)0.3, (dReal)-0.2, (dReal)0.99);
    set_rot(hull, 0, 0, 1, (dReal)0.4);
    dContactGeom c[MAXC];
    int n = dCollide(hull, box, MAXC, c, sizeof c[0]);
    CHECK(n == 4);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 0.01, EPS);
        CHECK_VEC(c[i].normal, 0, 0, 1, EPS);
        CHECK_NEAR(c[i].pos[2], 0.495, EPS);
    }
    // Asking for fewer keeps that many, the deepest first.
    CHECK(dCollide(box, hull, 2, c, sizeof c[0]) == 2);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    dGeomDestroy(hull);
    dGeomDestroy(box);
    return 0;
}

// ---- remembered separating axes ---------------------------------------------------

// Whether a pair's contacts are the same bit for bit.
static int identical(const dContactGeom *a, int na, const dContactGeom *b, int nb)
{
    if (na != nb) return 0;
    for (int i = 0; i < na; i++) {
        if (a[i].depth != b[i].depth) return 0;
        for (int k = 0; k < 3; k++)
            if (a[i].pos[k] != b[i].pos[k] || a[i].normal[k] != b[i].normal[k]) return 0;
    }
    return 1;
}

// Partner k of the walk below, placed on a circle (the same calls for the
// fresh copy, so the same bits).
static void pose_other(dGeomID g, int k)
{
    dGeomSetPosition(g, (dReal)(1.2 * cos(k * M_PI / 6)), (dReal)(1.2 * sin(k * M_PI / 6)), 0);
    set_rot(g, 1, 1, 0, (dReal)(0.3 * k));
}

// The geoms of a walk: the walker (k < 0) or partner k.
typedef dGeomID (*walk_geom)(int k);

// A walker wanders among 12 partners placed on a circle (more than a geom
// remembers), in and out of contact, 3000 steps from the seed. At each step
// its contacts with partner step % 12, in both orders, must be exactly those
// of fresh geoms made by the same function at the same poses (nothing
// remembered).
static int wander_among_partners(walk_geom make, unsigned long long seed)
{
    dGeomID walker = make(-1);
    dGeomID others[12];
    for (int k = 0; k < 12; k++) {
        others[k] = make(k);
        pose_other(others[k], k);
    }
    rng_state = seed;
    double p[3] = { 0, 0, 0 };
    int touching = 0, apart = 0;
    for (int step = 0; step < 3000; step++) {
        for (int k = 0; k < 3; k++) p[k] = fmax(-1.5, fmin(1.5, p[k] + rnd(-0.05, 0.05)));
        p[2] = fmax(-0.4, fmin(0.4, p[2]));
        dMatrix3 R;
        random_rotation(R);
        place(walker, (dReal[3]){ (dReal)p[0], (dReal)p[1], (dReal)p[2] }, R);
        int k = step % 12;
        dContactGeom a[MAXC], b[MAXC];
        int na = dCollide(walker, others[k], MAXC, a, sizeof a[0]);
        dGeomID w2 = make(-1), o2 = make(k);
        place(w2, (dReal[3]){ (dReal)p[0], (dReal)p[1], (dReal)p[2] }, R);
        pose_other(o2, k);
        int nb = dCollide(w2, o2, MAXC, b, sizeof b[0]);
        CHECK(identical(a, na, b, nb));
        // The other order, from the other's memory.
        na = dCollide(others[k], walker, MAXC, a, sizeof a[0]);
        nb = dCollide(o2, w2, MAXC, b, sizeof b[0]);
        CHECK(identical(a, na, b, nb));
        touching += na > 0;
        apart += na == 0;
        dGeomDestroy(w2);
        dGeomDestroy(o2);
    }
    CHECK(touching > 200 && apart > 200);
    for (int k = 0; k < 12; k++) dGeomDestroy(others[k]);
    dGeomDestroy(walker);
    return 0;
}

// A hull walker among boxes, octahedra and prisms.
static dGeomID hull_walk_geom(int k)
{
    static test_hull bh;
    static prism pr;
    if (k < 0) {
        test_hull_box(&bh, (dReal)0.6, (dReal)0.4, (dReal)0.3);
        return dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    }
    return k % 3 == 0 ? dCreateBox(0, (dReal)0.5, (dReal)0.5, (dReal)0.5)
         : k % 3 == 1 ? make_octahedron()
                      : make_prism(&pr);
}

// A hull remembers the axis that parted it from each of its last few
// partners and tries it first. That is only a shortcut: a hull wandering
// among 12 others gets exactly the contacts that fresh geoms at the same
// poses get.
static int test_remembered_axis_never_hides_contacts(void)
{
    return wander_among_partners(hull_walk_geom, 77);
}

// ---- kept state against fresh geoms ----------------------------------------------

// Geom k of the drift below: prism hulls, box hulls, tall prism hulls and
// real boxes in turn (arrays shared, as ODE keeps them).
static dGeomID drift_geom(int k)
{
    static test_hull pr, bh, tall;
    static int made;
    if (!made) {
        test_hull_prism(&pr, 0.15, 0.1);
        test_hull_box(&bh, 0.3, 0.2, 0.25);
        test_hull_prism(&tall, 0.1, 0.3);
        made = 1;
    }
    const test_hull *h = k % 4 == 0 ? &pr : k % 4 == 1 ? &bh : &tall;
    if (k % 4 == 3) return dCreateBox(0, (dReal)0.3, (dReal)0.25, (dReal)0.2);
    return dCreateConvex(0, h->planes, h->nplanes, h->points, h->npoints, h->polygons);
}

// Places g at p, q (the same calls for a fresh copy: the same bits).
static void place_q(dGeomID g, const dReal p[3], const dQuaternion q)
{
    dGeomSetPosition(g, p[0], p[1], p[2]);
    dGeomSetQuaternion(g, q);
}

// What a convex geom keeps between calls (its posed hull, with or without
// its edges; per partner the separating axis, or the contact face and
// points; the faces measured for the clearance) changes no contact. Eight
// hulls and boxes drift slowly into and through one another, each step
// turning a little (resting and sliding pairs, pairs coming apart), and
// some stay put for a few steps; every pair, in both orders, with every
// contact count from 1 to 8, must give the contacts of fresh geoms at the
// same poses bit for bit.
static int test_kept_state_as_fresh_geoms(void)
{
    enum { N = 8 };
    dGeomID g[N];
    dReal pos[N][3];
    dQuaternion quat[N];
    double v[N][3], w[N][3];
    rng_state = 2024;
    for (int i = 0; i < N; i++) {
        g[i] = drift_geom(i);
        for (int k = 0; k < 3; k++) {
            pos[i][k] = (dReal)rnd(-0.25, 0.25);
            v[i][k] = rnd(-1, 1) * 0.003;
            w[i][k] = rnd(-1, 1) * 0.02;
        }
        dQSetIdentity(quat[i]);
        place_q(g[i], pos[i], quat[i]);
    }
    int touching = 0, apart = 0, counts[9] = { 0 };
    for (int step = 0; step < 300; step++) {
        for (int i = 0; i < N; i++) {
            if (i % 3 == 1 && step % 4) continue;   // left unmoved: its kept pose is reused
            for (int k = 0; k < 3; k++) {
                pos[i][k] = (dReal)(pos[i][k] + v[i][k]);
                if (fabs(pos[i][k]) > 0.25) v[i][k] = -v[i][k];
            }
            dQuaternion dq = { 1, (dReal)w[i][0], (dReal)w[i][1], (dReal)w[i][2] }, r;
            dQMultiply0(r, dq, quat[i]);
            dNormalize4(r);
            memcpy(quat[i], r, sizeof r);
            place_q(g[i], pos[i], quat[i]);
        }
        for (int i = 0; i < N; i++) {
            for (int j = 0; j < N; j++) {
                if (i == j || (i % 4 == 3 && j % 4 == 3)) continue;   // box-box is not a hull pair
                int max = 1 + (i + j + step) % 8;
                dContactGeom a[8], b[8];
                int na = dCollide(g[i], g[j], max, a, sizeof a[0]);
                dGeomID fi = drift_geom(i), fj = drift_geom(j);
                place_q(fi, pos[i], quat[i]);
                place_q(fj, pos[j], quat[j]);
                int nb = dCollide(fi, fj, max, b, sizeof b[0]);
                dGeomDestroy(fi);
                dGeomDestroy(fj);
                CHECK(identical(a, na, b, nb));
                CHECK(na <= max);
                touching += na > 0;
                apart += na == 0;
                counts[na]++;
            }
        }
    }
    printf("# drift: %d touching, %d apart; pairs with 1-8 contacts: %d %d %d %d %d %d %d %d\n",
           touching, apart, counts[1], counts[2], counts[3], counts[4], counts[5], counts[6],
           counts[7], counts[8]);
    CHECK(touching > 2000 && apart > 2000);
    for (int k = 1; k <= 4; k++) CHECK(counts[k] > 100);
    for (int i = 0; i < N; i++) dGeomDestroy(g[i]);
    return 0;
}

// A drifting geom of the test below and its fresh copy: on a body (k even),
// moved through the body's setters, or placed by the geom's own.
typedef struct kept_geom {
    dGeomID g;
    dBodyID b;
} kept_geom;

static kept_geom kept_make(dWorldID w, int k)
{
    kept_geom m = { drift_geom(k), NULL };
    if (k % 2 == 0) {
        m.b = dBodyCreate(w);
        dGeomSetBody(m.g, m.b);
    }
    return m;
}

static void kept_place(kept_geom m, const dReal p[3], const dQuaternion q)
{
    if (m.b) {
        dBodySetPosition(m.b, p[0], p[1], p[2]);
        dBodySetQuaternion(m.b, q);
    } else {
        place_q(m.g, p, q);
    }
}

static void kept_destroy(kept_geom m)
{
    dGeomDestroy(m.g);
    if (m.b) dBodyDestroy(m.b);
}

typedef struct kept_scene {
    dWorldID w;
    kept_geom geom[6];
    dReal pos[6][3];
    dQuaternion quat[6];
    int touching, failed;
} kept_scene;

// Geoms i and j (both orders) against fresh copies at the same poses.
static void kept_compare(kept_scene *sc, int i, int j)
{
    for (int order = 0; order < 2; order++) {
        int a = order ? j : i, b = order ? i : j;
        if (a % 4 == 3 && b % 4 == 3) continue;   // box-box is not a hull pair
        dContactGeom x[4], y[4];
        int nx = dCollide(sc->geom[a].g, sc->geom[b].g, 4, x, sizeof x[0]);
        kept_geom fa = kept_make(sc->w, a), fb = kept_make(sc->w, b);
        kept_place(fa, sc->pos[a], sc->quat[a]);
        kept_place(fb, sc->pos[b], sc->quat[b]);
        int ny = dCollide(fa.g, fb.g, 4, y, sizeof y[0]);
        kept_destroy(fa);
        kept_destroy(fb);
        sc->failed |= !identical(x, nx, y, ny);
        sc->touching += nx > 0;
    }
}

static void kept_near(void *data, dGeomID o1, dGeomID o2)
{
    kept_compare(data, (int)(intptr_t)dGeomGetData(o1), (int)(intptr_t)dGeomGetData(o2));
}

// A convex geom's posed hull is kept while its AABB flag says it has not
// moved: geoms in a space (whose collision clears the flag) moved through
// their bodies or their own setters, some left unmoved, collided through
// the space and then, a step on, directly (the flag set again by the move),
// give the contacts of fresh geoms at the same poses bit for bit.
static int test_kept_pose_through_space_and_bodies(void)
{
    kept_scene sc;
    memset(&sc, 0, sizeof sc);
    sc.w = dWorldCreate();
    dSpaceID space = dSimpleSpaceCreate(0);
    double v[6][3], spin[6][3];
    rng_state = 77;
    for (int i = 0; i < 6; i++) {
        sc.geom[i] = kept_make(sc.w, i);
        dSpaceAdd(space, sc.geom[i].g);
        dGeomSetData(sc.geom[i].g, (void *)(intptr_t)i);
        for (int k = 0; k < 3; k++) {
            sc.pos[i][k] = (dReal)rnd(-0.2, 0.2);
            v[i][k] = rnd(-1, 1) * 0.004;
            spin[i][k] = rnd(-1, 1) * 0.03;
        }
        dQSetIdentity(sc.quat[i]);
        kept_place(sc.geom[i], sc.pos[i], sc.quat[i]);
    }
    for (int step = 0; step < 200; step++) {
        for (int i = 0; i < 6; i++) {
            if (i % 3 == 1 && step % 3) continue;   // unmoved: the flag stays clear
            for (int k = 0; k < 3; k++) {
                sc.pos[i][k] = (dReal)(sc.pos[i][k] + v[i][k]);
                if (fabs(sc.pos[i][k]) > 0.2) v[i][k] = -v[i][k];
            }
            dQuaternion dq = { 1, (dReal)spin[i][0], (dReal)spin[i][1], (dReal)spin[i][2] }, r;
            dQMultiply0(r, dq, sc.quat[i]);
            dNormalize4(r);
            memcpy(sc.quat[i], r, sizeof r);
            kept_place(sc.geom[i], sc.pos[i], sc.quat[i]);
        }
        if (step % 2) {
            dSpaceCollide(space, &sc, kept_near);
        } else {
            for (int i = 0; i < 6; i++)
                for (int j = i + 1; j < 6; j++) kept_compare(&sc, i, j);
        }
        CHECK(!sc.failed);
    }
    printf("# kept poses: %d touching pairs\n", sc.touching);
    CHECK(sc.touching > 500);
    for (int i = 0; i < 6; i++) kept_destroy(sc.geom[i]);
    dSpaceDestroy(space);
    dWorldDestroy(sc.w);
    return 0;
}

// The deepest of a hull's n contacts.
static double deepest_of(const dContactGeom *c, int n)
{
    double d = -INFINITY;
    for (int i = 0; i < n; i++) d = c[i].depth > d ? c[i].depth : d;
    return d;
}

// A box met by a hull is made into a hull once and kept with the bits it
// was made from: a cube hull resting in a box's top sees the box's new
// sides, its move, its replacement by a new box (which may take its
// address), also after more boxes than are kept were met.
static int test_box_kept_by_its_bits(void)
{
    test_hull cube;
    test_hull_box(&cube, 1, 1, 1);
    dGeomID h = dCreateConvex(0, cube.planes, cube.nplanes, cube.points, cube.npoints,
                              cube.polygons);
    dGeomSetPosition(h, 0, 0, (dReal)0.9);   // its bottom at 0.4
    dGeomID b = dCreateBox(0, 2, 2, 1), others[6];
    for (int k = 0; k < 6; k++) {
        others[k] = dCreateBox(0, 1, 1, 1);
        dGeomSetPosition(others[k], (dReal)(1.5 * k - 4), 0, (dReal)-0.2);
    }
    dContactGeom c[4];
    int n = dCollide(h, b, 4, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK_NEAR(deepest_of(c, n), 0.1, EPS);
    dGeomBoxSetLengths(b, 2, 2, (dReal)1.4);   // top at 0.7
    n = dCollide(h, b, 4, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK_NEAR(deepest_of(c, n), 0.3, EPS);
    dGeomSetPosition(b, 0, 0, (dReal)-0.1);   // top at 0.6
    n = dCollide(h, b, 4, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK_NEAR(deepest_of(c, n), 0.2, EPS);
    CHECK_NEAR(fabs(c[0].normal[2]), 1, EPS);
    for (int k = 0; k < 6; k++) dCollide(h, others[k], 4, c, sizeof c[0]);
    n = dCollide(b, h, 4, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK_NEAR(deepest_of(c, n), 0.2, EPS);
    dGeomDestroy(b);
    b = dCreateBox(0, 2, 2, (dReal)0.6);   // top at 0.3: clear of the hull
    CHECK(dCollide(h, b, 4, c, sizeof c[0]) == 0);
    dGeomDestroy(b);
    b = dCreateBox(0, 2, 2, (dReal)1.2);   // top at 0.6
    n = dCollide(h, b, 4, c, sizeof c[0]);
    CHECK(n == 4);
    CHECK_NEAR(deepest_of(c, n), 0.2, EPS);
    dGeomDestroy(b);
    for (int k = 0; k < 6; k++) dGeomDestroy(others[k]);
    dGeomDestroy(h);
    return 0;
}

// ---- bad input ------------------------------------------------------------------

static char last_error[512];
static int errors;

static void record(int num, const char *msg, va_list ap)
{
    (void)num;
    vsnprintf(last_error, sizeof last_error, msg, ap);
    errors++;
}

// The call reports an error naming fn and mentioning what.
static int reported(const char *fn, const char *what)
{
    if (errors != 1 || !strstr(last_error, fn) || !strstr(last_error, what)) {
        fprintf(stderr, "# errors %d, last \"%s\" (wanted %s, %s)\n", errors, last_error, fn,
                what);
        return 0;
    }
    errors = 0;
    last_error[0] = 0;
    return 1;
}

static int test_bad_input(void)
{
    test_hull bh;
    test_hull_box(&bh, 1, 1, 1);
    dSetDebugHandler(record);
    errors = 0;
    CHECK(dCreateConvex(0, NULL, 6, bh.points, 8, bh.polygons) == NULL);
    CHECK(reported("dCreateConvex", "planes"));
    CHECK(dCreateConvex(0, bh.planes, 0, bh.points, 8, bh.polygons) == NULL);
    CHECK(reported("dCreateConvex", "planecount"));
    CHECK(dCreateConvex(0, bh.planes, 6, NULL, 8, bh.polygons) == NULL);
    CHECK(reported("dCreateConvex", "points"));
    CHECK(dCreateConvex(0, bh.planes, 6, bh.points, 0, bh.polygons) == NULL);
    CHECK(reported("dCreateConvex", "pointcount"));
    CHECK(dCreateConvex(0, bh.planes, 6, bh.points, 8, NULL) == NULL);
    CHECK(reported("dCreateConvex", "polygons"));
    test_hull bad = bh;
    bad.points[5] = (dReal)NAN;
    CHECK(dCreateConvex(0, bad.planes, 6, bad.points, 8, bad.polygons) == NULL);
    CHECK(reported("dCreateConvex", "points[5]"));
    bad = bh;
    bad.planes[7] = (dReal)INFINITY;
    CHECK(dCreateConvex(0, bad.planes, 6, bad.points, 8, bad.polygons) == NULL);
    CHECK(reported("dCreateConvex", "planes[7]"));
    bad = bh;
    bad.polygons[13] = 8;
    CHECK(dCreateConvex(0, bad.planes, 6, bad.points, 8, bad.polygons) == NULL);
    CHECK(reported("dCreateConvex", "past pointcount"));
    // A valid convex keeps its data when set with bad data.
    dGeomID g = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
    CHECK(g && errors == 0);
    dGeomSetConvex(g, bh.planes, 6, bh.points, 3, bh.polygons);
    CHECK(reported("dGeomSetConvex", "past pointcount"));
    dGeomID s = dCreateSphere(0, 1);
    dGeomSetConvex(s, bh.planes, 6, bh.points, 8, bh.polygons);
    CHECK(reported("dGeomSetConvex", "not a convex"));
    dSetDebugHandler(0);
    dContactGeom c[4];
    dGeomSetPosition(s, 0, 0, (dReal)1.2);
    CHECK(dCollide(g, s, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.3, EPS);
    // dGeomSetConvex takes new data (not copied): a taller box.
    test_hull tall;
    test_hull_box(&tall, 1, 1, 3);
    dGeomSetConvex(g, tall.planes, 6, tall.points, 8, tall.polygons);
    dGeomSetPosition(s, 0, 0, (dReal)2.2);
    CHECK(dCollide(g, s, 4, c, sizeof c[0]) == 1);
    CHECK_NEAR(c[0].depth, 0.3, EPS);
    dGeomDestroy(g);
    dGeomDestroy(s);
    return 0;
}

// ---- the least depth, by brute force ------------------------------------------------

// A hull's arrays, for the brute-force test below.
typedef struct hull_arrays {
    const dReal *points;
    const unsigned *polygons;
    unsigned npoints, nplanes;
} hull_arrays;

// max over g's points (posed) of m . x.
static double brute_support(dGeomID g, const hull_arrays *h, const double m[3])
{
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    double best = -INFINITY;
    for (unsigned v = 0; v < h->npoints; v++) {
        const dReal *p = h->points + 3 * v;
        double e = 0;
        for (int i = 0; i < 3; i++)
            e += m[i] * (c[i] + R[4 * i] * p[0] + R[4 * i + 1] * p[1] + R[4 * i + 2] * p[2]);
        best = fmax(best, e);
    }
    return best;
}

// The world directions of g's polygon sides (each edge twice) into d; their count.
static int brute_edges(dGeomID g, const hull_arrays *h, double (*d)[3])
{
    const dReal *R = dGeomGetRotation(g);
    const unsigned *poly = h->polygons;
    int n = 0;
    for (unsigned f = 0; f < h->nplanes; f++, poly += 1 + *poly) {
        for (unsigned k = 0; k < poly[0]; k++) {
            const dReal *p = h->points + 3 * poly[1 + k];
            const dReal *q = h->points + 3 * poly[1 + (k + 1) % poly[0]];
            double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
            for (int i = 0; i < 3; i++)
                d[n][i] = R[4 * i] * u[0] + R[4 * i + 1] * u[1] + R[4 * i + 2] * u[2];
            n++;
        }
    }
    return n;
}

// The least translation of a, over every unit direction n, that parts it
// from b (negative if they are apart): min over candidate axes of
// h_b(n) + h_a(-n). The candidates (every face normal of either, computed
// from the points, and the cross product of every pair of edges, both
// signs) hold the faces of the Minkowski difference, where the least is.
static double brute_least_depth(dGeomID a, const hull_arrays *ha, dGeomID b,
                                const hull_arrays *hb)
{
    static double ea[64][3], eb[64][3];
    int na = brute_edges(a, ha, ea), nb = brute_edges(b, hb, eb);
    double least = INFINITY;
    for (int i = 0; i < na + nb; i++) {
        for (int j = 0; j < na + nb; j++) {
            const double *u = i < na ? ea[i] : eb[i - na], *v = j < na ? ea[j] : eb[j - na];
            double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                            u[0] * v[1] - u[1] * v[0] };
            double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (l < 1e-6) continue;
            for (int sg = -1; sg <= 1; sg += 2) {
                double m[3], mm[3];
                for (int k = 0; k < 3; k++) {
                    m[k] = sg * n[k] / l;
                    mm[k] = -m[k];
                }
                least = fmin(least, brute_support(b, hb, m) + brute_support(a, ha, mm));
            }
        }
    }
    return least;
}

// a's n contacts c against b judged by the brute-force least depth: none
// when it says apart (*verdict -1), some when it says overlapping (*verdict
// 1), the first normal's separating translation then within [least, 1.05
// least]; a least depth within rounding of 0 is not judged (*verdict 0).
static int judge_by_least_depth(dGeomID a, const hull_arrays *ha, dGeomID b, const hull_arrays *hb,
                                double least, const dContactGeom *c, int n, int *verdict)
{
    const double tol = TOL(1e-9, 1e-4);
    *verdict = 0;
    if (least < -tol) {
        CHECK(n == 0);
        *verdict = -1;
    } else if (least > tol) {
        CHECK(n > 0);
        double m[3], mm[3];
        for (int k = 0; k < 3; k++) {
            m[k] = c[0].normal[k];
            mm[k] = -m[k];
        }
        double along = brute_support(b, hb, m) + brute_support(a, ha, mm);
        CHECK(along >= least - tol && along <= 1.05 * least + tol);
        *verdict = 1;
    }
    return 0;
}

// The pair test keeps only what can matter: edge pairs whose arcs cross,
// and of those, faces and edges that are not clearly deeper than the best
// face. Against a brute-force least depth over every face and edge pair
// of random hull pairs near contact: the pair touches exactly when that
// depth is positive, and the contact normal's depth is that least depth,
// or (a face preferred over a shallower edge pair) at most 1.05 times it.
static int test_least_depth_as_brute_force(void)
{
    static test_hull pr, bh;
    test_hull_prism(&pr, 0.15, 0.1);
    test_hull_box(&bh, 0.3, 0.2, 0.25);
    dGeomDestroy(make_octahedron());   // its arrays (the geom itself not needed), shrunk to the others' size
    static dReal small_points[18], small_planes[32];
    const dReal k = (dReal)0.15;
    for (int i = 0; i < 18; i++) small_points[i] = octa_points[i] * k;
    for (int f = 0; f < 8; f++) {
        for (int i = 0; i < 3; i++) small_planes[4 * f + i] = octa_planes[4 * f + i];
        small_planes[4 * f + 3] = octa_planes[4 * f + 3] * k;
    }
    const hull_arrays shapes[3] = { { pr.points, pr.polygons, 12, 8 },
                                    { bh.points, bh.polygons, 8, 6 },
                                    { small_points, octa_polygons, 6, 8 } };
    dGeomID g[4] = { dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons),
                     dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons),
                     dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons),
                     dCreateConvex(0, small_planes, 8, small_points, 6, octa_polygons) };
    const hull_arrays *of[4] = { &shapes[0], &shapes[0], &shapes[1], &shapes[2] };
    static const int pairs[][2] = { { 0, 1 }, { 0, 2 }, { 2, 0 }, { 1, 3 }, { 3, 2 } };
    rng_state = 4242;
    int touching = 0, apart = 0;
    for (int it = 0; it < 1500; it++) {
        const int *pq = pairs[it % 5];
        dGeomID a = g[pq[0]], b = g[pq[1]];
        dMatrix3 R;
        random_rotation(R);
        place(a, (dReal[3]){ 0, 0, 0 }, R);
        random_rotation(R);
        double dir[3] = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) }, r = rnd(0.1, 0.45);
        double l = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        place(b, (dReal[3]){ (dReal)(r * dir[0] / l), (dReal)(r * dir[1] / l),
                             (dReal)(r * dir[2] / l) },
              R);
        double least = brute_least_depth(a, of[pq[0]], b, of[pq[1]]);
        dContactGeom c[MAXC];
        int n = dCollide(a, b, MAXC, c, sizeof c[0]);
        int verdict;
        CHECK(judge_by_least_depth(a, of[pq[0]], b, of[pq[1]], least, c, n, &verdict) == 0);
        apart += verdict < 0;
        touching += verdict > 0;
    }
    printf("# least depth: %d touching, %d apart, as the brute force\n", touching, apart);
    CHECK(touching > 300 && apart > 300);
    for (int k = 0; k < 4; k++) dGeomDestroy(g[k]);
    return 0;
}

// The pair test's floors under the faces' depths stand on the planes'
// offsets, less how far each polygon dips under its plane. Hulls whose
// planes sit 1 mm to 3 mm above their polygons: the same least depth as
// the brute force, and the same contacts as fresh geoms (which have no
// remembered axes, faces or points: the ones reused here come from the
// previous, unrelated poses of the same pair).
static int test_floors_of_loose_planes(void)
{
    static test_hull pr, bh;
    test_hull_prism(&pr, 0.15, 0.1);
    test_hull_box(&bh, 0.3, 0.2, 0.25);
    for (unsigned f = 0; f < pr.nplanes; f++) pr.planes[4 * f + 3] += (dReal)(0.001 * (1 + f % 3));
    for (unsigned f = 0; f < bh.nplanes; f++) bh.planes[4 * f + 3] += (dReal)0.002;
    const hull_arrays shapes[2] = { { pr.points, pr.polygons, 12, 8 },
                                    { bh.points, bh.polygons, 8, 6 } };
    dGeomID g[3] = { dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons),
                     dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons),
                     dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons) };
    const hull_arrays *of[3] = { &shapes[0], &shapes[0], &shapes[1] };
    static const int pairs[][2] = { { 0, 1 }, { 0, 2 }, { 2, 1 } };
    rng_state = 777;
    int touching = 0, same = 0;
    for (int it = 0; it < 900; it++) {
        const int *pq = pairs[it % 3];
        dGeomID a = g[pq[0]], b = g[pq[1]];
        dMatrix3 Ra, R;
        random_rotation(Ra);
        place(a, (dReal[3]){ 0, 0, 0 }, Ra);
        random_rotation(R);
        double dir[3] = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) }, r = rnd(0.1, 0.4);
        double l = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        place(b, (dReal[3]){ (dReal)(r * dir[0] / l), (dReal)(r * dir[1] / l),
                             (dReal)(r * dir[2] / l) },
              R);
        double least = brute_least_depth(a, of[pq[0]], b, of[pq[1]]);
        dContactGeom c[MAXC], fc[MAXC];
        int n = dCollide(a, b, MAXC, c, sizeof c[0]);
        const test_hull *ta = pq[0] == 2 ? &bh : &pr;
        dGeomID fresh = dCreateConvex(0, ta->planes, ta->nplanes, ta->points, ta->npoints,
                                      ta->polygons);
        place(fresh, (dReal[3]){ 0, 0, 0 }, Ra);   // the same calls: the same bits
        int fn = dCollide(fresh, b, MAXC, fc, sizeof fc[0]);
        dGeomDestroy(fresh);
        CHECK(identical(c, n, fc, fn));
        same++;
        int verdict;
        CHECK(judge_by_least_depth(a, of[pq[0]], b, of[pq[1]], least, c, n, &verdict) == 0);
        touching += verdict > 0;
    }
    printf("# loose planes: %d touching as the brute force, %d as fresh geoms\n", touching,
           same);
    CHECK(touching > 200);
    for (int k = 0; k < 3; k++) dGeomDestroy(g[k]);
    return 0;
}

// A box's point for the pair test's screens is its point nearest the
// hull's centre (a large box's corners are far from the hull on it). A
// prism and a box hull over and into each face of a large box (3 m x 3 m x
// 0.5 m, turned at random), near its middle, edges and corners, in both
// argument orders: touching exactly when the brute-force least depth is
// positive, along a normal of that depth (or at most 1.05 times it).
static int test_large_box_as_brute_force(void)
{
    static test_hull pr, bh, big;
    test_hull_prism(&pr, 0.15, 0.1);
    test_hull_box(&bh, 0.3, 0.2, 0.25);
    test_hull_box(&big, 3, 3, 0.5);
    const hull_arrays of_pr = { pr.points, pr.polygons, 12, 8 }, of_bh = { bh.points, bh.polygons, 8, 6 },
                      of_big = { big.points, big.polygons, 8, 6 };
    dGeomID floor_box = dCreateBox(0, 3, 3, (dReal)0.5);
    dGeomID mover[2] = { dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons),
                         dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons) };
    const hull_arrays *of_mover[2] = { &of_pr, &of_bh };
    rng_state = 5150;
    int touching = 0, apart = 0;
    for (int it = 0; it < 1200; it++) {
        dMatrix3 R;
        const dReal zero[3] = { 0, 0, 0 };
        random_rotation(R);
        place(floor_box, zero, R);
        // A point over face f of the box (its frame), up to 1.1 times its
        // half sides across, 0.35 m out to 0.15 m in.
        const double half[3] = { 1.5, 1.5, 0.25 };
        int f = it % 6, axis = f / 2;
        double l[3];
        for (int k = 0; k < 3; k++) l[k] = rnd(-1.1, 1.1) * half[k];
        l[axis] = (f & 1 ? 1 : -1) * (half[axis] + rnd(-0.15, 0.35));
        dReal p[3];
        for (int i = 0; i < 3; i++)
            p[i] = (dReal)(R[4 * i] * l[0] + R[4 * i + 1] * l[1] + R[4 * i + 2] * l[2]);
        dGeomID m = mover[it / 6 % 2];
        const hull_arrays *hm = of_mover[it / 6 % 2];
        random_rotation(R);
        place(m, p, R);
        int flip = it / 12 % 2;
        dGeomID a = flip ? floor_box : m, b = flip ? m : floor_box;
        const hull_arrays *ha = flip ? &of_big : hm, *hb = flip ? hm : &of_big;
        double least = brute_least_depth(a, ha, b, hb);
        dContactGeom c[MAXC];
        int n = dCollide(a, b, MAXC, c, sizeof c[0]);
        int verdict;
        CHECK(judge_by_least_depth(a, ha, b, hb, least, c, n, &verdict) == 0);
        apart += verdict < 0;
        touching += verdict > 0;
    }
    printf("# large box: %d touching, %d apart, as the brute force\n", touching, apart);
    CHECK(touching > 300 && apart > 300);
    dGeomDestroy(floor_box);
    for (int k = 0; k < 2; k++) dGeomDestroy(mover[k]);
    return 0;
}

// Hulls whose bounding spheres are apart are parted before any axis: the
// spheres hold every point. Two cube hulls (turned alike at random), corner
// towards corner along their diagonal, their centres a hair (0.1 % of the
// corners' reach) nearer than the two reaches: they touch, as deep as the
// brute force says; a hair further: apart.
static int test_corner_to_corner_spheres(void)
{
    static test_hull cube;
    test_hull_box(&cube, 0.2, 0.2, 0.2);
    const hull_arrays of_cube = { cube.points, cube.polygons, 8, 6 };
    dGeomID a = dCreateConvex(0, cube.planes, 6, cube.points, 8, cube.polygons);
    dGeomID b = dCreateConvex(0, cube.planes, 6, cube.points, 8, cube.polygons);
    const double reach = sqrt(3.0) * 0.1;
    rng_state = 77;
    for (int it = 0; it < 200; it++) {
        dMatrix3 R;
        random_rotation(R);
        const dReal zero[3] = { 0, 0, 0 };
        place(a, zero, R);
        double apart_by = it % 2 ? 1e-3 : -1e-3, d = 2 * reach * (1 + apart_by) / sqrt(3.0);
        dReal p[3];
        for (int i = 0; i < 3; i++) p[i] = (dReal)(d * (R[4 * i] + R[4 * i + 1] + R[4 * i + 2]));
        place(b, p, R);
        double least = brute_least_depth(a, &of_cube, b, &of_cube);
        dContactGeom c[MAXC];
        int n = dCollide(it % 4 < 2 ? a : b, it % 4 < 2 ? b : a, MAXC, c, sizeof c[0]);
        CHECK((n > 0) == (apart_by < 0));
        CHECK((least > 0) == (apart_by < 0));
        if (n > 0) CHECK_NEAR(c[0].depth, least, TOL(1e-9, 1e-5));
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

// The hull is posed (four points at a time where the machine allows) to
// the same numbers as c + R p made one point at a time, in this order: its
// bounding box, taken from those points, is theirs to the bit.
static int test_posed_points_exact(void)
{
    static test_hull pr;
    test_hull_prism(&pr, 0.15, 0.1);
    dGeomID g = dCreateConvex(0, pr.planes, 8, pr.points, 12, pr.polygons);
    rng_state = 31;
    for (int it = 0; it < 200; it++) {
        dMatrix3 R;
        random_rotation(R);
        dReal c[3] = { (dReal)rnd(-50, 50), (dReal)rnd(-50, 50), (dReal)rnd(-50, 50) };
        place(g, c, R);
        const dReal *gc = dGeomGetPosition(g), *gR = dGeomGetRotation(g);
        double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
        for (int v = 0; v < 12; v++) {
            const dReal *p = pr.points + 3 * v;
            for (int r = 0; r < 3; r++) {
                double x = (double)gc[r] + (double)gR[4 * r] * p[0] +
                           (double)gR[4 * r + 1] * p[1] + (double)gR[4 * r + 2] * p[2];
                lo[r] = fmin(lo[r], x);
                hi[r] = fmax(hi[r], x);
            }
        }
        dReal box[6];
        dGeomGetAABB(g, box);
        for (int r = 0; r < 3; r++) {
            CHECK(box[2 * r] == (dReal)lo[r]);
            CHECK(box[2 * r + 1] == (dReal)hi[r]);
        }
    }
    dGeomDestroy(g);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_box_equals_box_box),
    TEST_CASE(test_convex_convex_equals_box_box),
    TEST_CASE(test_floors_of_loose_planes),
    TEST_CASE(test_box_equals_box_plane),
    TEST_CASE(test_box_equals_sphere_box),
    TEST_CASE(test_box_like_capsule_box),
    TEST_CASE(test_box_like_cylinder_box),
    TEST_CASE(test_rays_as_box),
    TEST_CASE(test_octahedron_sphere),
    TEST_CASE(test_octahedron_capsule_plane),
    TEST_CASE(test_cube_on_box_polygon),
    TEST_CASE(test_cylinder_on_convex),
    TEST_CASE(test_mpr_without_end_is_cut_short),
    TEST_CASE(test_needle_capsule_on_flat_hull_edge),
    TEST_CASE(test_large_prism),
    TEST_CASE(test_resting_on_plane),
    TEST_CASE(test_remembered_axis_never_hides_contacts),
    TEST_CASE(test_kept_state_as_fresh_geoms),
    TEST_CASE(test_kept_pose_through_space_and_bodies),
    TEST_CASE(test_box_kept_by_its_bits),
    TEST_CASE(test_least_depth_as_brute_force),
    TEST_CASE(test_large_box_as_brute_force),
    TEST_CASE(test_corner_to_corner_spheres),
    TEST_CASE(test_posed_points_exact),
    TEST_CASE(test_bad_input),
    TEST_END,
};
