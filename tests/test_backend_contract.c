// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_contract.c -- the contract every contact of every backend
// meets (issue 14 section 1), held to the ground truth of
// tools/contact_truth.c rather than to another backend. For each backend
// built (native, fcl, bullet) and each convex pair it answers itself, seeded
// random poses at least 2 cm from touching, both argument orders:
//   verdict     contacts exactly when the shapes overlap;
//   depth       the deepest depth within 5 mm + 5 % of the true depth;
//   separation  g1 moved by that depth along its normal overlaps g2 by at
//               most the same tolerance;
//   points      every contact point within both shapes to 1 cm + 10 % of
//               the true depth.
// A per-backend, per-pair table of failures and worst errors is printed.
// Then face-resting manifolds: box-plane 4 points at the corners, box-box 4
// to 8 covering the face, capsule-plane and a lying cylinder 2 spanning the
// line, an upright cylinder on a plane 3 or 4 spanning its cap.

#include "collide_check.h"
#include "contact_truth.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { MAXC = 16, POSES = 100 };

static const int classes[] = { dSphereClass, dBoxClass, dCapsuleClass, dCylinderClass,
                               dPlaneClass };
enum { NCLASSES = 5 };

static const char *class_name(int cls)
{
    static const char *const names[] = { "sphere", "box", "capsule", "cylinder", "plane" };
    return names[cls];
}

// ---- the contract's tolerances ---------------------------------------------------

#define NEAR_MISS 0.02    // no pose closer than this to touching (either way)

static double depth_tol(double true_depth)
{
    return 0.005 + 0.05 * true_depth;
}

static double point_tol(double true_depth)
{
    return 0.01 + 0.1 * true_depth;
}

// ---- random poses -----------------------------------------------------------------

static void random_unit(double v[3])
{
    double len;
    do {
        for (int i = 0; i < 3; i++) v[i] = rnd(-1, 1);
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    } while (len < 0.1 || len > 1);
    for (int i = 0; i < 3; i++) v[i] /= len;
}

static dGeomID random_shape(int cls)
{
    dGeomID g;
    switch (cls) {
    case dSphereClass: g = dCreateSphere(0, (dReal)rnd(0.1, 0.5)); break;
    case dBoxClass:
        g = dCreateBox(0, (dReal)rnd(0.15, 1), (dReal)rnd(0.15, 1), (dReal)rnd(0.15, 1));
        break;
    case dCapsuleClass: g = dCreateCapsule(0, (dReal)rnd(0.08, 0.3), (dReal)rnd(0.1, 1)); break;
    case dCylinderClass: g = dCreateCylinder(0, (dReal)rnd(0.1, 0.4), (dReal)rnd(0.15, 1)); break;
    default: {
        double n[3] = { rnd(-0.4, 0.4), rnd(-0.4, 0.4), 1 };
        return dCreatePlane(0, (dReal)n[0], (dReal)n[1], (dReal)n[2], (dReal)rnd(-0.2, 0.2));
    }
    }
    double axis[3];
    random_unit(axis);
    set_rot(g, (dReal)axis[0], (dReal)axis[1], (dReal)axis[2], (dReal)rnd(-3.14, 3.14));
    return g;
}

static double bounding_radius(dGeomID g)
{
    dReal r, len;
    dVector3 s;
    switch (dGeomGetClass(g)) {
    case dSphereClass: return dGeomSphereGetRadius(g);
    case dBoxClass:
        dGeomBoxGetLengths(g, s);
        return 0.5 * sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    case dCapsuleClass: dGeomCapsuleGetParams(g, &r, &len); return r + len / 2;
    case dCylinderClass: dGeomCylinderGetParams(g, &r, &len); return sqrt(r * r + len * len / 4);
    default: return 0;
    }
}

// A pose of a (class c1) and b (class c2, the plane if there is one) at
// least NEAR_MISS from touching, and its truth for (a, b).
static void random_pose(int c1, int c2, dGeomID *pa, dGeomID *pb, contact_truth *t)
{
    for (;;) {
        dGeomID a = random_shape(c1), b = random_shape(c2);
        if (c2 == dPlaneClass) {
            dVector4 p;
            dGeomPlaneGetParams(b, p);
            double h = rnd(-0.6, 1.2) * bounding_radius(a), x = rnd(-1, 1), y = rnd(-1, 1);
            dGeomSetPosition(a, (dReal)(x + p[0] * (p[3] + h)), (dReal)(y + p[1] * (p[3] + h)),
                             (dReal)(p[2] * (p[3] + h) - (p[0] * x + p[1] * y) / p[2]));
        } else {
            double d[3], s = rnd(0.2, 1.1) * (bounding_radius(a) + bounding_radius(b));
            random_unit(d);
            dGeomSetPosition(a, (dReal)rnd(-1, 1), (dReal)rnd(-1, 1), (dReal)rnd(-1, 1));
            const dReal *o = dGeomGetPosition(a);
            dGeomSetPosition(b, (dReal)(o[0] + s * d[0]), (dReal)(o[1] + s * d[1]),
                             (dReal)(o[2] + s * d[2]));
        }
        contact_truth_compute(a, b, t);
        if (fabs(t->depth) >= NEAR_MISS) {
            *pa = a;
            *pb = b;
            return;
        }
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
}

// ---- one call against the truth ---------------------------------------------------

typedef struct pair_stats {
    int calls, verdict, depth, separation, points;   // failures of each rule
    double depth_err, sep_err, point_err;            // worst excess over 0 (absolute)
    int min_n, max_n;
} pair_stats;

// Overlap left after g1 is moved by depth along the normal (g2 moved the
// other way if g1 is a plane, which has no position).
static double overlap_after_moving(dGeomID g1, dGeomID g2, const dContactGeom *k)
{
    int plane1 = dGeomGetClass(g1) == dPlaneClass;
    dGeomID m = plane1 ? g2 : g1;
    double s = plane1 ? -k->depth : k->depth;
    dVector3 p0;
    dGeomCopyPosition(m, p0);
    dGeomSetPosition(m, p0[0] + (dReal)(s * k->normal[0]), p0[1] + (dReal)(s * k->normal[1]),
                     p0[2] + (dReal)(s * k->normal[2]));
    contact_truth t;
    contact_truth_compute(g1, g2, &t);
    dGeomSetPosition(m, p0[0], p0[1], p0[2]);
    return t.depth;
}

// dCollide(g1, g2) under the backend, checked against the truth t for
// (g1, g2); failures counted in st. Returns 1 if any rule failed.
static int check_call(const char *backend, dGeomID g1, dGeomID g2, const contact_truth *t,
                      pair_stats *st)
{
    dContactGeom c[MAXC];
    dCollisionSetBackend(backend);
    int n = dCollide(g1, g2, MAXC, c, sizeof c[0]), bad = 0;
    st->calls++;
    if ((n > 0) != t->overlap) {
        st->verdict++;
        return 1;
    }
    if (n == 0) return 0;
    if (n < st->min_n) st->min_n = n;
    if (n > st->max_n) st->max_n = n;
    const dContactGeom *k = &c[deepest(c, n)];
    double err = fabs(k->depth - t->depth);
    st->depth_err = fmax(st->depth_err, err);
    if (err > depth_tol(t->depth)) st->depth++, bad = 1;
    double left = overlap_after_moving(g1, g2, k);
    st->sep_err = fmax(st->sep_err, left);
    if (left > depth_tol(t->depth)) st->separation++, bad = 1;
    int outside = 0;
    for (int i = 0; i < n; i++) {
        double p[3] = { c[i].pos[0], c[i].pos[1], c[i].pos[2] };
        double d = fmin(contact_truth_point_depth(g1, p), contact_truth_point_depth(g2, p));
        st->point_err = fmax(st->point_err, -d);
        if (d < -point_tol(t->depth)) outside = 1;
    }
    if (outside) st->points++, bad = 1;
    return bad;
}

static int failures(const pair_stats *st)
{
    return st->verdict + st->depth + st->separation + st->points;
}

// One backend on every pair it answers: prints its table; 1 if any failed.
static int check_backend(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    printf("# %s: pair, calls, failures (verdict depth separation points), worst errors "
           "(depth, overlap left, point outside), contacts\n", backend);
    int failed = 0;
    for (int i = 0; i < NCLASSES; i++)
        for (int j = i; j < NCLASSES; j++) {
            int c1 = classes[i], c2 = classes[j];
            if (c1 == dPlaneClass && c2 == dPlaneClass) continue;
            pair_stats st = { 0, 0, 0, 0, 0, 0, 0, 0, MAXC + 1, 0 };
            int answered = 1;
            char name[40];
            snprintf(name, sizeof name, "%s-%s", class_name(c1), class_name(c2));
            rng_state = 1000 + 17 * (unsigned)c1 + (unsigned)c2;
            for (int pose = 0; pose < POSES && answered; pose++) {
                dGeomID a, b;
                contact_truth t, r;
                random_pose(c1, c2, &a, &b, &t);
                answered = backend_answers(backend, a, b);
                if (answered) {
                    r = t;
                    for (int k = 0; k < 3; k++) r.normal[k] = -t.normal[k];
                    check_call(backend, a, b, &t, &st);
                    check_call(backend, b, a, &r, &st);
                }
                dGeomDestroy(a);
                dGeomDestroy(b);
            }
            if (!answered) {
                printf("#   %-17s native fallback\n", name);
                continue;
            }
            printf("#   %-17s %4d  %s %3d %3d %3d %3d   %.4f %.4f %.4f   %d..%d\n", name,
                   st.calls, failures(&st) ? "FAIL" : "ok  ", st.verdict, st.depth,
                   st.separation, st.points, st.depth_err, st.sep_err, st.point_err,
                   st.max_n ? st.min_n : 0, st.max_n);
            if (failures(&st)) failed = 1;
        }
    dCollisionSetBackend("native");
    return failed;
}

static int test_native_meets_the_contract(void)
{
    return check_backend("native");
}

static int test_fcl_meets_the_contract(void)
{
    return check_backend("fcl");
}

static int test_bullet_meets_the_contract(void)
{
    return check_backend("bullet");
}

// ---- face-resting manifolds ----------------------------------------------------------

// Area of the convex hull of the contacts' xy positions (gift wrapping; a
// handful of points).
static double hull_area_xy(const dContactGeom *c, int n)
{
    int hull[MAXC + 1], h = 0, start = 0;
    if (n < 3) return 0;
    for (int i = 1; i < n; i++)
        if (c[i].pos[0] < c[start].pos[0]) start = i;
    int p = start;
    do {
        hull[h++] = p;
        int q = (p + 1) % n;
        for (int r = 0; r < n; r++) {
            double cr = (c[q].pos[0] - c[p].pos[0]) * (c[r].pos[1] - c[p].pos[1]) -
                        (c[q].pos[1] - c[p].pos[1]) * (c[r].pos[0] - c[p].pos[0]);
            if (cr < 0) q = r;
        }
        p = q;
    } while (p != start && h <= n);
    double area = 0;
    for (int i = 0; i < h; i++) {
        const dReal *a = c[hull[i]].pos, *b = c[hull[(i + 1) % h]].pos;
        area += (a[0] * b[1] - a[1] * b[0]) / 2;
    }
    return fabs(area);
}

static double span_xy(const dContactGeom *c, int n)
{
    double longest = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            longest = fmax(longest, hypot(c[i].pos[0] - c[j].pos[0], c[i].pos[1] - c[j].pos[1]));
    return longest;
}

typedef struct resting {
    const char *name;
    int cls;
    dReal size[3];        // box sides, or radius and length
    int lying, on_box;    // turned a quarter about x; on a 4 x 4 x 1 box, else the plane z = 0
    int min_n, max_n;     // the manifold's count
    double extent;        // the least hull area (or span if lying) of the contacts
} resting;

// 0.01 deep on z = 0, turned 0.3 rad about z. An upright cylinder's cap is
// covered by 3 or 4 points spanning at least a triangle inscribed in it.
static const resting restings[] = {
    { "box face-down on a plane", dBoxClass, { 1, 0.8, 0.5 }, 0, 0, 4, 4, 0.95 * 0.8 },
    { "box face-down on a box", dBoxClass, { 0.5, 0.4, 0.5 }, 0, 1, 4, 8, 0.95 * 0.2 },
    { "capsule lying on a plane", dCapsuleClass, { 0.2, 1, 0 }, 1, 0, 2, 2, 0.95 },
    { "cylinder lying on a plane", dCylinderClass, { 0.3, 0.8, 0 }, 1, 0, 2, 2, 0.95 * 0.8 },
    { "cylinder upright on a plane", dCylinderClass, { 0.3, 0.8, 0 }, 0, 0, 3, 4,
      0.41 * 3.14159 * 0.09 },
};

static dGeomID make_resting(const resting *p)
{
    dGeomID g;
    double half;
    if (p->cls == dBoxClass) {
        g = dCreateBox(0, p->size[0], p->size[1], p->size[2]);
        half = p->size[2] / 2;
    } else {
        g = p->cls == dCapsuleClass ? dCreateCapsule(0, p->size[0], p->size[1])
                                    : dCreateCylinder(0, p->size[0], p->size[1]);
        half = p->lying ? p->size[0] : p->size[1] / 2;
    }
    dQuaternion qx, qz, q;
    dQFromAxisAndAngle(qx, 1, 0, 0, p->lying ? (dReal)1.5707963267948966 : 0);
    dQFromAxisAndAngle(qz, 0, 0, 1, (dReal)0.3);
    dQMultiply0(q, qz, qx);
    dGeomSetQuaternion(g, q);
    dGeomSetPosition(g, 0.1, -0.05, (dReal)(half - 0.01));
    return g;
}

static int check_manifolds(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 4, 4, 1);
    dGeomSetPosition(box, 0, 0, -0.5);
    int failed = 0;
    for (size_t k = 0; k < sizeof restings / sizeof restings[0]; k++) {
        const resting *p = &restings[k];
        dGeomID g = make_resting(p), ground = p->on_box ? box : plane;
        if (!backend_answers(backend, g, ground)) {
            printf("# %s, %s: native fallback\n", backend, p->name);
            dGeomDestroy(g);
            continue;
        }
        dContactGeom c[MAXC];
        dCollisionSetBackend(backend);
        int n = dCollide(g, ground, MAXC, c, sizeof c[0]);
        double extent = p->lying ? span_xy(c, n) : hull_area_xy(c, n), worst_out = 0;
        for (int i = 0; i < n; i++) {
            double q[3] = { c[i].pos[0], c[i].pos[1], c[i].pos[2] };
            worst_out = fmax(worst_out, -fmin(contact_truth_point_depth(g, q),
                                              contact_truth_point_depth(ground, q)));
        }
        int ok = n >= p->min_n && n <= p->max_n && extent >= p->extent &&
                 worst_out <= point_tol(0.01) &&
                 fabs(c[deepest(c, n)].depth - 0.01) <= depth_tol(0.01);
        printf("# %s, %s: %d contacts (want %d..%d), %s %.3f (want >= %.3f), deepest %.4f%s\n",
               backend, p->name, n, p->min_n, p->max_n, p->lying ? "span" : "area", extent,
               p->extent, n ? c[deepest(c, n)].depth : 0.0, ok ? "" : " -- FAIL");
        if (!ok) failed = 1;
        dGeomDestroy(g);
    }
    dGeomDestroy(plane);
    dGeomDestroy(box);
    dCollisionSetBackend("native");
    return failed;
}

static int test_native_resting_manifolds(void)
{
    return check_manifolds("native");
}

static int test_fcl_resting_manifolds(void)
{
    return check_manifolds("fcl");
}

static int test_bullet_resting_manifolds(void)
{
    return check_manifolds("bullet");
}

const test_case test_cases[] = {
    TEST_CASE(test_native_meets_the_contract),
    TEST_CASE(test_fcl_meets_the_contract),
    TEST_CASE(test_bullet_meets_the_contract),
    TEST_CASE(test_native_resting_manifolds),
    TEST_CASE(test_fcl_resting_manifolds),
    TEST_CASE(test_bullet_resting_manifolds),
    TEST_END
};
