// SPDX-License-Identifier: BSD-3-Clause
//
// test_backends.c -- every collision backend built besides native, compared
// with native (BACKENDS.md section 7): for each class pair both can collide,
// seeded random poses in three bands (apart, penetrating, grazing) check the
// touching verdict, the deepest depth and normal, the separation rule,
// contact points inside both shapes, the contact count, argument order and
// repeatability, with per-pair error statistics printed as TAP comments.
// Then, per backend: face-resting contact manifolds, the native fallback,
// resting scenes through dSpaceCollide and contact joints, resized and
// destroyed geoms with cached shapes, and switching backends.
// The backend_fcl_env test runs it again with ODE_COLLISION_BACKEND=fcl,
// which the first case checks. Without a backend besides native the cases
// are skipped.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAXC = 16, MAX_BACKENDS = 8, SAMPLES = 1500 };

static const unsigned char SENTINEL = 0xA5;

// ---- the tolerance table -----------------------------------------------------
//
// Depth and point tolerances are relative to the pair's scale (the larger
// bounding radius); angles are in radians. kind says how the backend
// computes the pair, which is what each tolerance rests on:
//   ANALYTIC  closed form in both backends: rounding only. Double 1e-9 covers
//             a few hundred roundings of numbers ~1 (native's contact distance
//             is bisected to 1e-15); single precision 2e-5 covers float's 6e-8
//             over the same (the adapters compute in double from float
//             inputs, native in float).
//   GJK       iterative (GJK/EPA): BACKENDS.md's 1e-3 relative, 1e-3 rad.
//   MPR       FCL 0.7 (libccd) answers these pairs by Minkowski portal
//             refinement: its depth is the distance to the portal met by the
//             line from the centre difference through the origin of the
//             Minkowski difference, and its normal points to the nearest point
//             of that portal. Where the portal lies on a flat part of the
//             difference that is the true depth and normal; elsewhere the
//             contact tends to "push apart along the centre line". So: native
//             depth <= depth <= the translation along the centre line that
//             parts the pair, and moving by the depth along the normal
//             separates. Both bounds are checked, to 1e-5 (libccd stops when
//             the portal moves less than FCL's absolute 1e-6, on sizes
//             0.2..1.5); the normal is only measured (a known gap).
//   BOXBOX    ODE's box-box (FCL's boxBoxIntersect is a port): an edge-edge
//             axis is taken only if 5% shallower than the best so far, so
//             native depth <= depth <= 1.05 native depth (to EXACT); where
//             the depths agree, so must the normals, else the normal is another
//             face's and only the separation rule applies to it.
// outside: FCL's and Bullet's box-box points are ODE's incident-face points
// moved by half their depth along the normal, which leaves the incident box by
// up to half the depth times the sine of its tilt; elsewhere points are in
// both shapes.
enum { ANALYTIC, GJK, MPR, BOXBOX };
static const char *const kind_name[] = { "analytic", "GJK/EPA", "MPR", "ODE box-box" };

typedef struct tolerance {
    const char *backend;   // NULL: any backend without its own row
    int c1, c2;            // class pair (c1 <= c2), ANY: any pair
    int kind;
    double depth, angle, point;   // relative to the scale; radians; relative
    double outside;               // fraction of the depth a point may lie outside a shape
} tolerance;

#define ANY (-1)
#define EXACT TOL(1e-9, 2e-5)
#define MPR_TOL TOL(1e-5, 3e-5)
#define BT_FLOAT_ANGLE TOL(1e-9, 5e-4)
#define BT_GJK_DEPTH TOL(1e-5, 5e-3)
#define BT_GJK_ANGLE TOL(5e-3, 0.15)
#define BT_EPA_DEPTH TOL(1e-3, 5e-3)
#define BT_EPA_ANGLE TOL(1e-2, 0.15)
static const tolerance tolerances[] = {
    // FCL 0.7: closed forms for sphere-{sphere, box, cylinder}, box-box (ODE's
    // own algorithm) and every primitive against a half-space; sphere-capsule
    // is not supported (its contact point is wrong); the rest is MPR.
    { "fcl", dSphereClass, dSphereClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dSphereClass, dBoxClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dSphereClass, dCylinderClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dSphereClass, dPlaneClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dBoxClass, dBoxClass, BOXBOX, EXACT, EXACT, EXACT, 0.5 },
    { "fcl", dBoxClass, dPlaneClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dCapsuleClass, dPlaneClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", dCylinderClass, dPlaneClass, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    { "fcl", ANY, ANY, MPR, MPR_TOL, MPR_TOL, MPR_TOL, 0 },
    // Bullet 3.24 (measured against its adapter as it stands; single
    // precision uses Debian's float Bullet). Spheres and capsules are a point
    // or segment plus a margin, and GJK's distance between such a core and a
    // sphere, box, capsule or plane is exact (the cores stay apart in the
    // band: depth <= 0.4 r); convex-plane takes the support vertex; box-box is
    // ODE's. In float one sphere-box normal in 200 was 2.1e-4 rad off (p99
    // 7.7e-7). Sphere-cylinder goes through GJK/EPA (margin 0): at most 7.6e-6
    // of the scale in depth and 2.2e-3 rad in normal (float: 3.1e-3 and 0.1
    // rad). Capsule-cylinder goes through GJK/EPA too: depths to
    // BACKENDS.md's 1e-3 of the scale, normals to 1e-2 rad (measured up to
    // 3.4e-3); box-cylinder and two cylinders go to native (the adapter
    // explains why).
    { "bullet", dSphereClass, dBoxClass, ANALYTIC, EXACT, BT_FLOAT_ANGLE, EXACT, 0 },
    { "bullet", dSphereClass, dCylinderClass, GJK, BT_GJK_DEPTH, BT_GJK_ANGLE, BT_GJK_DEPTH, 0 },
    { "bullet", dCapsuleClass, dCylinderClass, GJK, BT_EPA_DEPTH, BT_EPA_ANGLE, BT_EPA_DEPTH, 0 },
    { "bullet", dBoxClass, dBoxClass, BOXBOX, EXACT, EXACT, EXACT, 0.5 },
    { "bullet", ANY, ANY, ANALYTIC, EXACT, EXACT, EXACT, 0 },
    // Backends without their own rows: BACKENDS.md's GJK/EPA numbers.
    { NULL, ANY, ANY, GJK, 1e-3, 1e-3, 1e-3, 0 },
};

static const tolerance *tolerance_for(const char *backend, int c1, int c2)
{
    if (c1 > c2) return tolerance_for(backend, c2, c1);
    size_t n = sizeof tolerances / sizeof tolerances[0];
    for (size_t i = 0; i < n; i++) {
        const tolerance *t = &tolerances[i];
        if (t->backend && strcmp(t->backend, backend) != 0) continue;
        if (t->c1 == ANY || (t->c1 == c1 && t->c2 == c2)) return t;
    }
    return &tolerances[n - 1];
}

// ---- small helpers -----------------------------------------------------------

static const char *class_name(int cls)
{
    static const char *const names[] = { "sphere", "box", "capsule", "cylinder", "plane",
                                         "ray" };
    return cls >= 0 && cls <= dRayClass ? names[cls] : "?";
}

static void random_unit(dReal v[3])
{
    dReal len;
    do {
        for (int i = 0; i < 3; i++) v[i] = (dReal)rnd(-1, 1);
        len = dCalcVectorLength3(v);
    } while (len < 0.1 || len > 1);
    for (int i = 0; i < 3; i++) v[i] /= len;
}

static void random_rotation(dGeomID g)
{
    dReal axis[3];
    dMatrix3 R;
    random_unit(axis);
    dRFromAxisAndAngle(R, axis[0], axis[1], axis[2], (dReal)rnd(-M_PI, M_PI));
    dGeomSetRotation(g, R);
}

// Backends to compare: every registered one but native.
static int other_backends(const char **out)
{
    int n = 0;
    for (const char *const *b = dCollisionListBackends(); *b; b++)
        if (strcmp(*b, "native") != 0 && n < MAX_BACKENDS) out[n++] = *b;
    return n;
}

// No backend besides native: the case is skipped.
static int skip_without_backends(const char *what)
{
    printf("# %s needs a collision backend besides native\n", what);
    return test_skip("no collision backend besides native is built");
}

static double angle_between(const dReal *a, const dReal *b)
{
    double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2],
           cz = a[0] * b[1] - a[1] * b[0];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), dot);
}

// dCollide through the named backend into c (entries past the count keep
// the sentinel bytes).
static int collide_with(const char *backend, dGeomID a, dGeomID b, int max, dContactGeom *c)
{
    dCollisionSetBackend(backend);
    memset(c, SENTINEL, MAXC * sizeof *c);
    return dCollide(a, b, max, c, sizeof *c);
}

static dReal depth_with(const char *backend, dGeomID a, dGeomID b)
{
    dContactGeom c[MAXC];
    int n = collide_with(backend, a, b, MAXC, c);
    return n ? c[deepest(c, n)].depth : 0;
}

static int untouched(const void *p, size_t size)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < size; i++)
        if (b[i] != SENTINEL) return 0;
    return 1;
}

// ---- shapes --------------------------------------------------------------------

// A geom of the class with random sizes (planes: a random unit normal and
// offset; the others at the origin, randomly turned).
static dGeomID random_geom(int cls)
{
    dGeomID g;
    switch (cls) {
    case dSphereClass: g = dCreateSphere(0, (dReal)rnd(0.2, 0.8)); break;
    case dBoxClass:
        g = dCreateBox(0, (dReal)rnd(0.3, 1.5), (dReal)rnd(0.3, 1.5), (dReal)rnd(0.3, 1.5));
        break;
    case dCapsuleClass: g = dCreateCapsule(0, (dReal)rnd(0.15, 0.5), (dReal)rnd(0.2, 1.2)); break;
    case dCylinderClass: g = dCreateCylinder(0, (dReal)rnd(0.2, 0.6), (dReal)rnd(0.3, 1.2)); break;
    case dRayClass: g = dCreateRay(0, 1); break;
    default: {
        dReal n[3];
        random_unit(n);
        return dCreatePlane(0, n[0], n[1], n[2], (dReal)rnd(-1, 1));
    }
    }
    random_rotation(g);
    return g;
}

// The smallest extent of a shape (planes: unbounded) and its bounding radius.
static double smallest_size(dGeomID g)
{
    dReal r, len;
    dVector3 s;
    switch (dGeomGetClass(g)) {
    case dSphereClass: return 2 * dGeomSphereGetRadius(g);
    case dBoxClass:
        dGeomBoxGetLengths(g, s);
        return fmin(s[0], fmin(s[1], s[2]));
    case dCapsuleClass: dGeomCapsuleGetParams(g, &r, &len); return 2 * r;
    case dCylinderClass: dGeomCylinderGetParams(g, &r, &len); return fmin(2 * r, len);
    default: return INFINITY;
    }
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

// ---- the random comparison (section 7) ------------------------------------------

// A random pair (classes c1 <= c2, so only b can be a plane) and a line along
// which one of them moves: b from a's centre outwards in a random direction,
// or, against a plane, a along the plane's normal. t_contact is where native
// stops reporting contacts along it.
typedef struct trial {
    dGeomID a, b, mover;
    dVector3 base;
    dReal dir[3];
    double t_contact, size, scale;   // smaller extent, larger bounding radius
} trial;

static void place(const trial *t, double s)
{
    dGeomSetPosition(t->mover, t->base[0] + (dReal)s * t->dir[0],
                     t->base[1] + (dReal)s * t->dir[1], t->base[2] + (dReal)s * t->dir[2]);
}

static int count_with(const char *backend, dGeomID a, dGeomID b)
{
    dContactGeom c[MAXC];
    return collide_with(backend, a, b, MAXC, c);
}

// Set up a trial; t_contact by bisection on native's verdict (the set of
// touching offsets along a line is an interval, as the Minkowski difference
// is convex). Returns 1 if native reports nothing even with the centres
// together (a collider still missing), else 0.
static int setup_trial(trial *t, int c1, int c2)
{
    t->a = random_geom(c1);
    t->b = random_geom(c2);
    double lo, hi;
    if (c2 == dPlaneClass) {
        dVector4 p;
        dGeomPlaneGetParams(t->b, p);
        t->mover = t->a;
        for (int i = 0; i < 3; i++) t->base[i] = p[i] * p[3], t->dir[i] = p[i];
        lo = -bounding_radius(t->a) - 0.1;
        hi = bounding_radius(t->a) + 0.1;
    } else {
        dGeomSetPosition(t->a, (dReal)rnd(-1, 1), (dReal)rnd(-1, 1), (dReal)rnd(-1, 1));
        t->mover = t->b;
        dGeomCopyPosition(t->a, t->base);
        random_unit(t->dir);
        lo = 0;
        hi = bounding_radius(t->a) + bounding_radius(t->b) + 0.1;
    }
    t->size = fmin(smallest_size(t->a), smallest_size(t->b));
    t->scale = fmax(bounding_radius(t->a), bounding_radius(t->b));
    place(t, lo);
    if (count_with("native", t->a, t->b) == 0) return 1;
    for (int i = 0; i < 60; i++) {
        double mid = (lo + hi) / 2;
        place(t, mid);
        if (count_with("native", t->a, t->b)) lo = mid;
        else hi = mid;
    }
    t->t_contact = hi;
    return 0;
}

static void end_trial(trial *t)
{
    dGeomDestroy(t->a);
    dGeomDestroy(t->b);
}

// What a contact array must be whatever the pose (section 1): count within
// max, entries past it untouched, g1 = a, g2 = b, sides -1, finite values,
// unit normals, depth >= 0.
static int check_contract(dGeomID a, dGeomID b, int max, const dContactGeom *c, int n)
{
    if (n < 0 || n > max || !untouched(c + n, (MAXC - n) * sizeof *c)) return 0;
    for (int i = 0; i < n; i++) {
        const dContactGeom *k = &c[i];
        if (k->g1 != a || k->g2 != b || k->side1 != -1 || k->side2 != -1) return 0;
        if (!isfinite(k->depth) || k->depth < 0) return 0;
        for (int j = 0; j < 3; j++)
            if (!isfinite(k->pos[j]) || !isfinite(k->normal[j])) return 0;
        if (fabs(dCalcVectorLength3(k->normal) - 1) > TOL(1e-9, 1e-5)) return 0;
    }
    return 1;
}

// Native's deepest normal is stable: the same (within 1e-2 rad) with the
// mover shifted by 1e-4 of the scale along each axis (a curved surface turns
// its normal by ~1e-3 rad there; a switch between features by far more). An
// unstable one (two faces about equally deep, parallel edges) is ambiguous:
// backends may pick either.
static int native_normal_stable(const trial *t, double s, const dReal *normal)
{
    dVector3 p;
    dGeomCopyPosition(t->mover, p);
    int stable = 1;
    for (int k = 0; k < 6 && stable; k++) {
        dReal q[3] = { p[0], p[1], p[2] };
        q[k / 2] += (dReal)((k % 2 ? 1e-4 : -1e-4) * t->scale);
        dGeomSetPosition(t->mover, q[0], q[1], q[2]);
        dContactGeom c[MAXC];
        int n = collide_with("native", t->a, t->b, MAXC, c);
        stable = n > 0 && angle_between(c[deepest(c, n)].normal, normal) <= 1e-2;
    }
    place(t, s);
    return stable;
}

// Each contact of ab has its mirror in ba: same position and depth, opposite
// normal (within the pair's tolerances).
static int mirrored(const dContactGeom *ab, const dContactGeom *ba, int n, const tolerance *tol,
                    double scale)
{
    for (int i = 0; i < n; i++) {
        int found = 0;
        for (int j = 0; j < n && !found; j++) {
            dReal flipped[3] = { -ba[j].normal[0], -ba[j].normal[1], -ba[j].normal[2] };
            found = fabs(ab[i].depth - ba[j].depth) <= tol->depth * scale &&
                    dCalcPointsDistance3(ab[i].pos, ba[j].pos) <= tol->point * scale &&
                    angle_between(ab[i].normal, flipped) <= tol->angle;
        }
        if (!found) return 0;
    }
    return 1;
}

// Per pair and backend: errors of the penetrating samples, contact counts.
typedef struct stats {
    double depth_err[SAMPLES], angle_err[SAMPLES];
    int depths, angles, ambiguous, other_axis, native_not_least, apart, grazing;
    int min_contacts, max_contacts, native_max_contacts;
} stats;

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

// Largest and 99th-percentile value (sorts v).
static void max_p99(double *v, int n, double *max, double *p99)
{
    *max = *p99 = 0;
    if (n == 0) return;
    qsort(v, (size_t)n, sizeof *v, compare_double);
    *max = v[n - 1];
    *p99 = v[(int)ceil(0.99 * n) - 1];
}

#define FAIL_IF(cond, ...) \
    do { \
        if (cond) { \
            test_fail(__FILE__, __LINE__, __VA_ARGS__); \
            return 1; \
        } \
    } while (0)

// Separation: a moved by the contact's depth (+ tolerance) along its normal
// no longer touches b, in native's judgement.
static int check_separation(const tolerance *tol, const trial *t, const dContactGeom *k)
{
    const double dtol = tol->depth * t->scale;
    dVector3 p;
    dGeomCopyPosition(t->a, p);
    dReal m = k->depth + (dReal)dtol;
    dGeomSetPosition(t->a, p[0] + m * k->normal[0], p[1] + m * k->normal[1],
                     p[2] + m * k->normal[2]);
    dReal left = depth_with("native", t->a, t->b);
    dGeomSetPosition(t->a, p[0], p[1], p[2]);
    FAIL_IF(left > dtol, "still %g deep after moving by depth %g along the normal",
            (double)left, (double)k->depth);
    return 0;
}

// Deepest depth kb against native's kn: equal within the tolerance, or
// within the bounds of the table's kind (the upper one for MPR is
// line_depth, the translation along the centre line that parts the pair).
// Shallower than native is right only if it separates: then native's depth
// was not the least, which is noted, not failed (native has its own tests).
static int check_depth(const tolerance *tol, const trial *t, double line_depth,
                       const dContactGeom *kb, const dContactGeom *kn, stats *st)
{
    const double dtol = tol->depth * t->scale, err = kb->depth - kn->depth;
    st->depth_err[st->depths++] = fabs(err) / t->scale;
    if (err < -dtol) {
        FAIL_IF(check_separation(tol, t, kb), "depth %.12g below native %.12g",
                (double)kb->depth, (double)kn->depth);
        st->native_not_least++;
        return 0;
    }
    double high = kn->depth + dtol;
    if (tol->kind == MPR) high = line_depth + dtol;
    if (tol->kind == BOXBOX) high = 1.05 * kn->depth + dtol;
    FAIL_IF(kb->depth > high, "depth %.12g above %.12g (native %.12g)", (double)kb->depth,
            high - dtol, (double)kn->depth);
    return 0;
}

// Deepest normals, unless native's is ambiguous, not the least, or the
// backend took another axis (ODE's box-box, by depth); MPR normals only
// measured.
static int check_normal(const tolerance *tol, const trial *t, double s, const dContactGeom *kb,
                        const dContactGeom *kn, stats *st)
{
    if (kb->depth < kn->depth - tol->depth * t->scale) return 0;   // native not the least
    if (tol->kind == BOXBOX && kb->depth > kn->depth + tol->depth * t->scale) {
        st->other_axis++;
        return 0;
    }
    if (!native_normal_stable(t, s, kn->normal)) {
        st->ambiguous++;
        return 0;
    }
    double err = angle_between(kb->normal, kn->normal);
    st->angle_err[st->angles++] = err;
    FAIL_IF(tol->kind != MPR && err > tol->angle, "normal %.3g rad from native's", err);
    return 0;
}

// Every point in both shapes, no deeper than the deepest contact (section 7
// item 6), with the table's allowance outside.
static int check_points(const tolerance *tol, dGeomID a, dGeomID b, double scale,
                        const dContactGeom *c, int n)
{
    const double ptol = tol->point * scale;
    const dReal most = c[deepest(c, n)].depth;
    for (int i = 0; i < n; i++) {
        double da = point_depth(a, c[i].pos), db = point_depth(b, c[i].pos);
        double low = -ptol - tol->outside * c[i].depth, high = most + ptol;
        FAIL_IF(!(da >= low && da <= high && db >= low && db <= high),
                "contact %d lies %g, %g deep in the shapes (deepest %g)", i, da, db, (double)most);
    }
    return 0;
}

// dCollide(b, a) mirrors dCollide(a, b); a repeated call is bit-identical.
static int check_order_and_repeat(const char *backend, const tolerance *tol, const trial *t,
                                  int max, const dContactGeom *c, int n)
{
    dContactGeom ba[MAXC], again[MAXC];
    int nr = collide_with(backend, t->b, t->a, max, ba);
    FAIL_IF(nr != n || !mirrored(c, ba, n, tol, t->scale), "dCollide(b, a) is no mirror");
    int na = collide_with(backend, t->a, t->b, max, again);
    FAIL_IF(na != n || memcmp(again, c, (size_t)n * sizeof *c) != 0, "a repeated call differs");
    return 0;
}

// The penetrating band at offset s along the trial's line: the backend's
// contacts against native's (section 7 items 2 to 8).
static int check_penetrating(const char *backend, const tolerance *tol, const trial *t, double s,
                             int max, stats *st)
{
    dContactGeom cn[MAXC], cb[MAXC];
    int nn = collide_with("native", t->a, t->b, MAXC, cn);
    int nb = collide_with(backend, t->a, t->b, max, cb);
    FAIL_IF(nn == 0, "native reports no contact inside its own contact distance");
    FAIL_IF(!check_contract(t->a, t->b, max, cb, nb), "contact array breaks the contract");
    const dContactGeom *kn = &cn[deepest(cn, nn)];
    if (nn > st->native_max_contacts) st->native_max_contacts = nn;
    if (nb == 0) {
        FAIL_IF(kn->depth > tol->depth * t->scale, "no contact, native depth %g",
                (double)kn->depth);
        return 0;
    }
    const dContactGeom *kb = &cb[deepest(cb, nb)];
    if (nb < st->min_contacts) st->min_contacts = nb;
    if (nb > st->max_contacts) st->max_contacts = nb;
    return check_depth(tol, t, t->t_contact - s, kb, kn, st) ||
           check_normal(tol, t, s, kb, kn, st) || check_points(tol, t->a, t->b, t->scale, cb, nb) ||
           check_separation(tol, t, kb) || check_order_and_repeat(backend, tol, t, max, cb, nb);
}

// The apart band: nothing (or nothing deeper than the tolerance), both ways.
static int check_apart(const char *backend, const tolerance *tol, const trial *t, int max)
{
    dContactGeom c[MAXC];
    for (int order = 0; order < 2; order++) {
        dGeomID g1 = order ? t->b : t->a, g2 = order ? t->a : t->b;
        int n = collide_with(backend, g1, g2, max, c);
        FAIL_IF(!check_contract(g1, g2, max, c, n), "contact array breaks the contract");
        FAIL_IF(n && c[deepest(c, n)].depth > tol->depth * t->scale,
                "apart by %g along the line, yet %g deep", t->size, (double)c[0].depth);
    }
    return 0;
}

// The grazing band: only that the call survives and keeps the contract.
static int check_grazing(const char *backend, const trial *t, int max)
{
    dContactGeom c[MAXC];
    int n = collide_with(backend, t->a, t->b, max, c);
    FAIL_IF(!check_contract(t->a, t->b, max, c, n), "contact array breaks the contract");
    return 0;
}

static void print_stats(const char *backend, int c1, int c2, const tolerance *tol, stats *st)
{
    double dmax, dp99, amax, ap99;
    int depths = st->depths, angles = st->angles;
    max_p99(st->depth_err, depths, &dmax, &dp99);
    max_p99(st->angle_err, angles, &amax, &ap99);
    printf("# %s %s-%s [%s]: %d penetrating (normals: %d ambiguous, %d of another face; "
           "%d where native is not the least depth), %d apart, %d grazing; "
           "|depth - native| / scale max %.2g p99 %.2g; normal angle max %.2g p99 %.2g rad; "
           "contacts %d..%d (native up to %d)%s\n",
           backend, class_name(c1), class_name(c2), kind_name[tol->kind], depths, st->ambiguous,
           st->other_axis, st->native_not_least, st->apart, st->grazing, dmax, dp99, amax, ap99,
           st->min_contacts, st->max_contacts, st->native_max_contacts,
           st->max_contacts < st->native_max_contacts ? ", reduced manifold" : "");
}

// SAMPLES random trials of one pair for one backend, the band by turns, the
// maximum contact count asked by turns (1, 2, 4, MAXC).
static int compare_backend(const char *backend, int c1, int c2)
{
    static stats st;
    memset(&st, 0, sizeof st);
    st.min_contacts = MAXC;
    const tolerance *tol = tolerance_for(backend, c1, c2);
    rng_state = 0x5eed0000ULL + (unsigned long long)(c1 * 16 + c2);
    for (int i = 0; i < SAMPLES; i++) {
        trial t;
        if (setup_trial(&t, c1, c2)) {
            end_trial(&t);
            printf("# native has no %s-%s collider yet: comparison skipped\n", class_name(c1),
                   class_name(c2));
            return 0;
        }
        const int maxes[4] = { 1, 2, 4, MAXC }, max = maxes[(i / 3) % 4];
        int bad;
        double s;
        switch (i % 3) {
        case 0:
            s = t.t_contact - rnd(0.01, 0.2) * t.size;
            place(&t, s);
            bad = check_penetrating(backend, tol, &t, s, max, &st);
            break;
        case 1:
            place(&t, t.t_contact + rnd(0.01, 0.2) * t.size);
            bad = check_apart(backend, tol, &t, max);
            st.apart++;
            break;
        default:
            place(&t, t.t_contact + rnd(-0.01, 0.01) * t.size);
            bad = check_grazing(backend, &t, max);
            st.grazing++;
            break;
        }
        end_trial(&t);
        if (bad) {
            printf("# %s %s-%s, sample %d\n", backend, class_name(c1), class_name(c2), i);
            return 1;
        }
    }
    print_stats(backend, c1, c2, tol, &st);
    return 0;
}

// Whether the backend collides the pair itself: in strict mode an
// unsupported pair is reported instead of going to native.
static int backend_supports(const char *backend, int c1, int c2)
{
    dGeomID a = random_geom(c1), b = random_geom(c2);
    dContactGeom c[MAXC];
    test_capture_reports();
    dCollisionSetStrict(1);
    collide_with(backend, a, b, MAXC, c);
    dCollisionSetStrict(0);
    int supported = !test_captured_contains("cannot collide");
    test_release_reports();
    dGeomDestroy(a);
    dGeomDestroy(b);
    return supported;
}

static int compare_pair(int c1, int c2)
{
    const char *backends[MAX_BACKENDS];
    int n = other_backends(backends);
    if (n == 0) return skip_without_backends("comparison");
    for (int i = 0; i < n; i++) {
        if (!backend_supports(backends[i], c1, c2)) {
            printf("# %s %s-%s: not supported (native fallback)\n", backends[i],
                   class_name(c1), class_name(c2));
            continue;
        }
        if (compare_backend(backends[i], c1, c2)) return 1;
    }
    dCollisionSetBackend("native");
    return 0;
}

// One case per class pair (plane-plane never touches: see the fallback case).
#define PAIR_TEST(a, b, class_a, class_b) \
    static int test_compare_##a##_##b(void) { return compare_pair(class_a, class_b); }
PAIR_TEST(sphere, sphere, dSphereClass, dSphereClass)
PAIR_TEST(sphere, box, dSphereClass, dBoxClass)
PAIR_TEST(sphere, capsule, dSphereClass, dCapsuleClass)
PAIR_TEST(sphere, cylinder, dSphereClass, dCylinderClass)
PAIR_TEST(sphere, plane, dSphereClass, dPlaneClass)
PAIR_TEST(box, box, dBoxClass, dBoxClass)
PAIR_TEST(box, capsule, dBoxClass, dCapsuleClass)
PAIR_TEST(box, cylinder, dBoxClass, dCylinderClass)
PAIR_TEST(box, plane, dBoxClass, dPlaneClass)
PAIR_TEST(capsule, capsule, dCapsuleClass, dCapsuleClass)
PAIR_TEST(capsule, cylinder, dCapsuleClass, dCylinderClass)
PAIR_TEST(capsule, plane, dCapsuleClass, dPlaneClass)
PAIR_TEST(cylinder, cylinder, dCylinderClass, dCylinderClass)
PAIR_TEST(cylinder, plane, dCylinderClass, dPlaneClass)


// ---- hand-worked contacts --------------------------------------------------------

// Spheres of radius 1 at the origin and 0.5 at (1.2, 0, 0) overlap by 0.3
// along x. Moving g1 along the normal by the depth separates them, so with
// the big sphere as g1 the normal is -x; the point lies in the lens between
// x = 0.7 and x = 1. The other order flips the normal only.
static int test_sphere_sphere_by_hand(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("hand-worked spheres");
    dGeomID a = dCreateSphere(0, 1), b = dCreateSphere(0, 0.5);
    dGeomSetPosition(b, 1.2, 0, 0);
    for (int i = 0; i < nb; i++) {
        dContactGeom c[MAXC];
        CHECK(collide_with(backends[i], a, b, MAXC, c) == 1);
        CHECK_NEAR(c[0].depth, 0.3, TOL(1e-12, 1e-6));
        CHECK_NEAR(c[0].normal[0], -1, TOL(1e-12, 1e-6));
        CHECK(fabs(c[0].normal[1]) < 1e-12 && fabs(c[0].normal[2]) < 1e-12);
        CHECK(c[0].pos[0] >= 0.7 - 1e-6 && c[0].pos[0] <= 1 + 1e-6);
        CHECK(c[0].g1 == a && c[0].g2 == b);
        CHECK(collide_with(backends[i], b, a, MAXC, c) == 1);
        CHECK_NEAR(c[0].normal[0], 1, TOL(1e-12, 1e-6));
        CHECK(c[0].g1 == b && c[0].g2 == a);
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    dCollisionSetBackend("native");
    return 0;
}

// ---- face-resting manifolds (section 7 item 7) ----------------------------------

// Points projected on the xy plane (the resting poses below have normal z).
typedef struct xy {
    double x, y;
} xy;

static double cross_xy(xy o, xy a, xy b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int compare_xy(const void *pa, const void *pb)
{
    const xy *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    return (a->y > b->y) - (a->y < b->y);
}

// Convex hull (counter-clockwise, Andrew's monotone chain) of the contacts'
// xy positions into hull; returns its vertex count.
static int hull_xy(const dContactGeom *c, int n, xy *hull)
{
    xy p[MAXC];
    for (int i = 0; i < n; i++) p[i] = (xy){ c[i].pos[0], c[i].pos[1] };
    qsort(p, (size_t)n, sizeof p[0], compare_xy);
    int k = 0;
    for (int pass = 0; pass < 2; pass++) {
        int start = k;
        for (int j = 0; j < n; j++) {
            xy q = p[pass ? n - 1 - j : j];
            while (k >= start + 2 && cross_xy(hull[k - 2], hull[k - 1], q) <= 1e-12) k--;
            hull[k++] = q;
        }
        k--;   // the last point starts the other chain
    }
    return k < 1 ? 1 : k;
}

static double hull_area(const dContactGeom *c, int n)
{
    xy h[2 * MAXC];
    int k = hull_xy(c, n, h);
    double area = 0;
    for (int i = 0; i < k; i++) area += cross_xy((xy){ 0, 0 }, h[i], h[(i + 1) % k]) / 2;
    return area;
}

// The longest xy distance between two contacts.
static double longest_span(const dContactGeom *c, int n)
{
    double longest = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            longest = fmax(longest, hypot(c[i].pos[0] - c[j].pos[0], c[i].pos[1] - c[j].pos[1]));
    return longest;
}

// The extent of a support region: its area, or for a segment (native's
// contacts of a lying capsule or cylinder are collinear) its length.
static double support_extent(const dContactGeom *c, int n, int as_area)
{
    return as_area ? hull_area(c, n) : longest_span(c, n);
}

// Distance from q to the segment ab.
static double segment_distance(xy q, xy a, xy b)
{
    double ux = b.x - a.x, uy = b.y - a.y, len2 = ux * ux + uy * uy;
    double t = len2 > 0 ? ((q.x - a.x) * ux + (q.y - a.y) * uy) / len2 : 0;
    t = fmin(1, fmax(0, t));
    return hypot(a.x + t * ux - q.x, a.y + t * uy - q.y);
}

// Whether (x, y) lies in the hull of the contacts (or on their segment), within tol.
static int inside_support(const dContactGeom *c, int n, double x, double y, double tol)
{
    xy h[2 * MAXC], q = { x, y };
    int k = hull_xy(c, n, h);
    if (hull_area(c, n) > 1e-9) {
        for (int i = 0; i < k; i++) {
            xy a = h[i], b = h[(i + 1) % k];
            if (cross_xy(a, b, q) < -tol * hypot(b.x - a.x, b.y - a.y)) return 0;
        }
        return 1;
    }
    for (int i = 0; i < n; i++)   // collinear: within tol of a segment between two contacts
        for (int j = 0; j < n; j++) {
            xy a = { c[i].pos[0], c[i].pos[1] }, b = { c[j].pos[0], c[j].pos[1] };
            if (segment_distance(q, a, b) <= tol) return 1;
        }
    return 0;
}

typedef struct resting_pose {
    const char *name;
    int upper_class;
    dReal size[3];     // box sides, or radius and length
    dReal quarter_turn;   // about x, to lay a capsule or cylinder down (radians)
    int on_box;        // on the top face of a 4 x 4 x 1 box, else on the plane z = 0
} resting_pose;

// Shapes resting 0.01 deep on the plane z = 0 or on a box's top face at z = 0.
static const resting_pose resting_poses[] = {
    { "box face-down on a plane", dBoxClass, { 1, 1, 0.5 }, 0, 0 },
    { "box face-down on a box", dBoxClass, { 0.5, 0.5, 0.5 }, 0, 1 },
    { "capsule lying on a plane", dCapsuleClass, { 0.2, 1, 0 }, (dReal)(M_PI / 2), 0 },
    { "capsule lying on a box", dCapsuleClass, { 0.2, 1, 0 }, (dReal)(M_PI / 2), 1 },
    { "cylinder upright on a plane", dCylinderClass, { 0.3, 0.8, 0 }, 0, 0 },
    { "cylinder lying on a plane", dCylinderClass, { 0.3, 0.8, 0 }, (dReal)(M_PI / 2), 0 },
    { "cylinder upright on a box", dCylinderClass, { 0.3, 0.8, 0 }, 0, 1 },
};

static dGeomID make_resting(const resting_pose *p)
{
    dGeomID g;
    double half;   // half height along z once placed
    if (p->upper_class == dBoxClass) {
        g = dCreateBox(0, p->size[0], p->size[1], p->size[2]);
        half = p->size[2] / 2;
    } else {
        g = p->upper_class == dCapsuleClass ? dCreateCapsule(0, p->size[0], p->size[1])
                                            : dCreateCylinder(0, p->size[0], p->size[1]);
        half = p->quarter_turn != 0 ? p->size[0]
               : p->size[1] / 2 + (p->upper_class == dCapsuleClass ? p->size[0] : 0);
    }
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, p->quarter_turn);
    dGeomSetRotation(g, R);
    dGeomSetPosition(g, 0.1, -0.05, (dReal)(half - 0.01));
    return g;
}

// One pose for one backend: contacts in both shapes, the deepest at 0.01,
// all in native's support region (within the depth: a curved surface sunk
// by d touches over a width sqrt(2 r d) > d around native's segment). Fewer
// contacts than native's are a reduced manifold (tagged, not failed); as
// many or more must span at least 90% of native's region.
static int check_resting(const char *backend, const resting_pose *p, dGeomID upper,
                         dGeomID lower)
{
    dContactGeom cn[MAXC], cb[MAXC];
    int nn = collide_with("native", upper, lower, MAXC, cn);
    int nb = collide_with(backend, upper, lower, MAXC, cb);
    const tolerance *tol = tolerance_for(backend, dGeomGetClass(upper), dGeomGetClass(lower));
    CHECK(nn >= 1 && nb >= 1);
    CHECK(check_points(tol, upper, lower, 1, cb, nb) == 0);
    CHECK_NEAR(cb[deepest(cb, nb)].depth, 0.01, tol->depth);
    int as_area = hull_area(cn, nn) > 1e-9;
    double native_extent = support_extent(cn, nn, as_area), extent = 0;
    if (nb > 1) extent = support_extent(cb, nb, as_area);
    printf("# %s, %s: %d contacts (native %d), support %.3g of native's %.3g%s\n", backend,
           p->name, nb, nn, extent, native_extent, nb < nn ? " -- reduced manifold" : "");
    for (int i = 0; i < nb; i++) CHECK(inside_support(cn, nn, cb[i].pos[0], cb[i].pos[1], 0.01));
    if (nb >= nn) CHECK(extent >= 0.9 * native_extent);
    return 0;
}

static int test_face_resting_manifolds(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("resting manifolds");
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 4, 4, 1);
    dGeomSetPosition(box, 0, 0, -0.5);
    for (size_t k = 0; k < sizeof resting_poses / sizeof resting_poses[0]; k++) {
        const resting_pose *p = &resting_poses[k];
        dGeomID upper = make_resting(p), lower = p->on_box ? box : plane;
        for (int i = 0; i < nb; i++) {
            if (!backend_supports(backends[i], p->upper_class, dGeomGetClass(lower))) continue;
            if (check_resting(backends[i], p, upper, lower)) return 1;
        }
        dGeomDestroy(upper);
    }
    dGeomDestroy(plane);
    dGeomDestroy(box);
    dCollisionSetBackend("native");
    return 0;
}

// ---- native fallback ----------------------------------------------------------------

// The backend does not collide (a, b) itself: dCollide gives native's
// contacts, saying so once per selection of the backend.
static int check_fallback(const char *backend, dGeomID a, dGeomID b)
{
    dContactGeom cn[MAXC], cb[MAXC];
    int nn = collide_with("native", a, b, MAXC, cn);
    test_capture_reports();
    int n1 = collide_with(backend, a, b, MAXC, cb);
    int n2 = collide_with(backend, a, b, MAXC, cb);   // selected again: one more message
    dCollide(a, b, MAXC, cb, sizeof cb[0]);           // same selection: none
    int messages = test_captured_count(), said = test_captured_contains("using native");
    test_release_reports();
    CHECK(messages == 2 && said);
    CHECK(n1 == nn && n2 == nn && memcmp(cb, cn, (size_t)nn * sizeof cn[0]) == 0);
    return 0;
}

// Pairs a backend does not do go to native. FCL has no rays, and its
// sphere-capsule is routed to native (fcl_backend.cpp); two planes never
// touch, whoever answers.
static int test_unsupported_pairs_fall_back(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("fallback");
    dGeomID ray = dCreateRay(0, 5), sphere = dCreateSphere(0, 1), capsule = dCreateCapsule(0, 1, 1);
    dGeomID p1 = dCreatePlane(0, 0, 0, 1, 0), p2 = dCreatePlane(0, 0, 1, 0, 0);
    dGeomRaySet(ray, 0, 0, -3, 0, 0, 1);      // hits the sphere's bottom at z = -1
    dGeomSetPosition(capsule, 0, 1.8, 0);     // 0.2 into the sphere
    for (int i = 0; i < nb; i++) {
        if (strcmp(backends[i], "fcl") == 0) {
            CHECK(!backend_supports("fcl", dRayClass, dSphereClass));
            CHECK(!backend_supports("fcl", dSphereClass, dCapsuleClass));
        }
        if (!backend_supports(backends[i], dRayClass, dSphereClass))
            CHECK(check_fallback(backends[i], ray, sphere) == 0);
        if (!backend_supports(backends[i], dSphereClass, dCapsuleClass))
            CHECK(check_fallback(backends[i], sphere, capsule) == 0);
        dContactGeom c[MAXC];
        if (!backend_supports(backends[i], dPlaneClass, dPlaneClass))
            CHECK(check_fallback(backends[i], p1, p2) == 0);
        else
            CHECK(collide_with(backends[i], p1, p2, MAXC, c) == 0);
    }
    dGeomDestroy(ray);
    dGeomDestroy(sphere);
    dGeomDestroy(capsule);
    dGeomDestroy(p1);
    dGeomDestroy(p2);
    dCollisionSetBackend("native");
    return 0;
}

// ---- resting scenes through dSpaceCollide and contact joints --------------------------

enum { SCENE_CONTACTS = 8 };

typedef struct scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID group;
    dBodyID body;
    dGeomID geom;
} scene;

// The guide's near callback: contacts become joints between the geoms' bodies.
static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *s = data;
    dContact c[SCENE_CONTACTS];
    memset(c, 0, sizeof c);
    int n = dCollide(a, b, SCENE_CONTACTS, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = 0;
        c[i].surface.mu = 1;
        dJointID j = dJointCreateContact(s->world, s->group, &c[i]);
        dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
}

// Gravity -9.81 z, a simple space holding the static ground geom, and the
// falling geom on a body of mass 1 released at height z, turned by angle
// about the axis (ax, ay, az).
static void scene_init(scene *s, dGeomID ground, dGeomID falling, dReal z, dReal ax, dReal ay,
                       dReal az, dReal angle)
{
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, (dReal)-9.81);
    s->space = dSimpleSpaceCreate(0);
    s->group = dJointGroupCreate(0);
    dSpaceAdd(s->space, ground);
    dSpaceAdd(s->space, falling);
    s->body = dBodyCreate(s->world);
    dMass m;
    if (dGeomGetClass(falling) == dSphereClass) {
        dMassSetSphereTotal(&m, 1, dGeomSphereGetRadius(falling));
    } else {
        dVector3 side;
        dGeomBoxGetLengths(falling, side);
        dMassSetBoxTotal(&m, 1, side[0], side[1], side[2]);
    }
    dBodySetMass(s->body, &m);
    dMatrix3 R;
    dRFromAxisAndAngle(R, ax, ay, az, angle);
    dBodySetRotation(s->body, R);
    dBodySetPosition(s->body, 0.05, -0.02, z);
    dGeomSetBody(falling, s->body);
    s->geom = falling;
}

// Steps of 0.01 s with dWorldStep for the given time.
static void scene_run(scene *s, double seconds)
{
    for (int i = 0; i < (int)(seconds / 0.01 + 0.5); i++) {
        dSpaceCollide(s->space, s, near_callback);
        dWorldStep(s->world, (dReal)0.01);
        dJointGroupEmpty(s->group);
    }
}

static void scene_end(scene *s)
{
    dJointGroupDestroy(s->group);
    dSpaceDestroy(s->space);   // destroys the geoms too
    dWorldDestroy(s->world);
}

// A sphere of radius 0.5 dropped from 1 m onto the plane z = 0 comes to rest
// with its centre at 0.5: the contact's ERP (0.2) removes the penetration
// geometrically step after step, so what remains is far below 1e-3 (a step's
// fall, g h^2, is 1e-3); it is at rest (speed < 1e-3 m/s).
static int test_sphere_rests_on_plane(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("sphere on a plane");
    for (int i = 0; i < nb; i++) {
        CHECK(dCollisionSetBackend(backends[i]));
        scene s;
        scene_init(&s, dCreatePlane(0, 0, 0, 1, 0), dCreateSphere(0, 0.5), 1, 0, 0, 1, 0);
        scene_run(&s, 3);
        const dReal *p = dBodyGetPosition(s.body), *v = dBodyGetLinearVel(s.body);
        printf("# %s: sphere at rest at z = %.6f\n", backends[i], (double)p[2]);
        CHECK_NEAR(p[2], 0.5, 1e-3);
        CHECK(dCalcVectorLength3(v) < 1e-3);
        scene_end(&s);
    }
    dCollisionSetBackend("native");
    return 0;
}

// A 0.5 m cube dropped from 1 m, turned 30 degrees about z, onto the top of a
// static 4 x 4 x 1 box (at z = 0): with its face's four corners as contacts
// (FCL's box-box gives them) it stands, its centre at 0.25 (as above,
// within 1e-3), upright (its z axis within 1e-3 rad of the world's), at rest.
static int test_box_stands_on_box(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("box on a box");
    for (int i = 0; i < nb; i++) {
        CHECK(dCollisionSetBackend(backends[i]));
        scene s;
        dGeomID ground = dCreateBox(0, 4, 4, 1);
        dGeomSetPosition(ground, 0, 0, -0.5);
        scene_init(&s, ground, dCreateBox(0, 0.5, 0.5, 0.5), 1, 0, 0, 1, (dReal)(M_PI / 6));
        scene_run(&s, 3);
        const dReal *p = dBodyGetPosition(s.body), *R = dBodyGetRotation(s.body);
        printf("# %s: box at rest at z = %.6f, tilt %.2g rad\n", backends[i], (double)p[2],
               acos(fmin(1, (double)R[10])));
        CHECK_NEAR(p[2], 0.25, 1e-3);
        CHECK(R[10] > cos(1e-3));
        CHECK(dCalcVectorLength3(dBodyGetLinearVel(s.body)) < 1e-3);
        CHECK(dCalcVectorLength3(dBodyGetAngularVel(s.body)) < 1e-3);
        scene_end(&s);
    }
    dCollisionSetBackend("native");
    return 0;
}

// The same cube dropped onto the plane z = 0, tilted 0.3 rad about a
// horizontal axis so that it lands on an edge. Backends with the four face
// corners as contacts land it flat at 0.25 like the box above. FCL's single
// contact (at the deepest point, then the face centre; BACKENDS.md section 4)
// lets it rock, creep and sink: measured after 5 s 5.3 mm low, 0.004 rad
// tilted, 14 cm slid and still creeping. Asserted for all: it neither falls
// through nor tips over (centre within 2.5 cm, a tenth of its side, of 0.25;
// tilt < 0.05 rad); the rest is printed, tagged for a reduced manifold.
static int test_box_lands_on_plane(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("box on a plane");
    for (int i = 0; i < nb; i++) {
        CHECK(dCollisionSetBackend(backends[i]));
        scene s;
        scene_init(&s, dCreatePlane(0, 0, 0, 1, 0), dCreateBox(0, 0.5, 0.5, 0.5), 1, 1, 1, 0,
                   (dReal)0.3);
        scene_run(&s, 5);
        dContactGeom c[MAXC];
        int face_down = dCollide(s.geom, dSpaceGetGeom(s.space, 0), MAXC, c, sizeof c[0]);
        const dReal *p = dBodyGetPosition(s.body), *R = dBodyGetRotation(s.body);
        double tilt = acos(fmin(1, (double)R[10])), slid = hypot(p[0] - 0.05, p[1] + 0.02);
        printf("# %s: box on a plane at z = %.5f, tilt %.2g rad, slid %.3g m, speed %.2g m/s%s\n",
               backends[i], (double)p[2], tilt, slid,
               (double)dCalcVectorLength3(dBodyGetLinearVel(s.body)),
               face_down == 1 ? " -- reduced manifold" : "");
        CHECK_NEAR(p[2], 0.25, 0.025);
        CHECK(tilt < 0.05);
        scene_end(&s);
    }
    dCollisionSetBackend("native");
    return 0;
}

// ---- cached shapes: resized, destroyed, switched ------------------------------------

// After a first collision (shape cached), each size change shows in the next
// depth: sphere radius, box sides, capsule and cylinder length, plane offset.
static int test_resized_geoms_are_rebuilt(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("resize");
    const double eps = TOL(1e-9, 1e-5);
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), big = dCreateSphere(0, 1);
    dGeomID sphere = dCreateSphere(0, 0.5), box = dCreateBox(0, 1, 1, 1);
    dGeomID capsule = dCreateCapsule(0, 0.2, 1), cylinder = dCreateCylinder(0, 0.3, 1);
    dGeomSetPosition(sphere, 1.2, 0, 0);        // 0.3 into the big sphere
    dGeomSetPosition(box, 0, 0, 0.45);          // 0.05 below the plane
    dGeomSetPosition(capsule, 3, 0, 0.65);      // 0.05
    dGeomSetPosition(cylinder, -3, 0, 0.45);    // 0.05
    for (int i = 0; i < nb; i++) {
        const char *b = backends[i];
        dGeomSphereSetRadius(sphere, 0.5);
        dGeomBoxSetLengths(box, 1, 1, 1);
        dGeomCapsuleSetParams(capsule, 0.2, 1);
        dGeomCylinderSetParams(cylinder, 0.3, 1);
        dGeomPlaneSetParams(plane, 0, 0, 1, 0);
        CHECK_NEAR(depth_with(b, big, sphere), 0.3, eps);
        CHECK_NEAR(depth_with(b, box, plane), 0.05, eps);
        CHECK_NEAR(depth_with(b, capsule, plane), 0.05, eps);
        CHECK_NEAR(depth_with(b, cylinder, plane), 0.05, eps);
        dGeomSphereSetRadius(sphere, 0.7);
        dGeomBoxSetLengths(box, 1, 1, 1.2);
        dGeomCapsuleSetParams(capsule, 0.2, 1.2);
        dGeomCylinderSetParams(cylinder, 0.3, 1.3);
        CHECK_NEAR(depth_with(b, big, sphere), 0.5, eps);
        CHECK_NEAR(depth_with(b, box, plane), 0.15, eps);
        CHECK_NEAR(depth_with(b, capsule, plane), 0.15, eps);
        CHECK_NEAR(depth_with(b, cylinder, plane), 0.2, eps);
        dGeomPlaneSetParams(plane, 0, 0, 1, 0.1);
        CHECK_NEAR(depth_with(b, box, plane), 0.25, eps);
    }
    dGeomDestroy(plane);
    dGeomDestroy(big);
    dGeomDestroy(sphere);
    dGeomDestroy(box);
    dGeomDestroy(capsule);
    dGeomDestroy(cylinder);
    dCollisionSetBackend("native");
    return 0;
}

// Geoms destroyed while a backend holds their shapes: directly, with another
// backend selected, and by their space's cleanup (an ASan build reports any
// shape not freed as a leak).
static int test_destroyed_geoms_free_their_shapes(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("destroy");
    for (int i = 0; i < nb; i++) {
        dSpaceID space = dSimpleSpaceCreate(0);
        dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateSphere(0, 0.5);
        dGeomID c = dCreateCylinder(space, 0.3, 1), d = dCreateBox(space, 1, 1, 1);
        dGeomSetPosition(b, 0.9, 0, 0);
        dGeomSetPosition(d, 0, 0, 0.9);
        CHECK(depth_with(backends[i], a, b) > 0 && depth_with(backends[i], c, d) > 0);
        dGeomDestroy(a);
        dCollisionSetBackend("native");
        dGeomDestroy(b);
        dSpaceDestroy(space);
    }
    return 0;
}

// One pair collided by every backend in turn, twice round, resized in
// between: each backend drops the others' shapes from the geoms' cache slots
// (the slot's owner is told through geom_changed) and builds its own.
static int test_switching_backends_keeps_shapes_right(void)
{
    const char *backends[MAX_BACKENDS];
    int nb = other_backends(backends);
    if (nb == 0) return skip_without_backends("switching");
    dGeomID a = dCreateBox(0, 1, 1, 1), b = dCreateSphere(0, 0.5);
    dGeomSetPosition(b, 0, 0, 0.9);   // 0.1 deep
    for (int round = 0; round < 2; round++) {
        for (int i = 0; i < nb; i++)
            CHECK_NEAR(depth_with(backends[i], a, b), 0.1 + 0.2 * round, TOL(1e-9, 1e-5));
        dGeomSphereSetRadius(b, 0.7);
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    dCollisionSetBackend("native");
    return 0;
}

// ---- selection by the environment ---------------------------------------------------

// ODE_COLLISION_BACKEND, read when the library starts, selects a built
// backend before any call (the backend_fcl_env test runs this program with
// it set to fcl); without it native is selected. Under FCL a box face-down on
// a plane gets FCL's single contact (native gives the four corners). First
// in the table: the other cases select backends themselves.
static int test_environment_selects_the_backend(void)
{
    const char *env = getenv("ODE_COLLISION_BACKEND");
    if (!env) {
        CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
        return 0;
    }
    const char *backends[MAX_BACKENDS];
    int n = other_backends(backends), built = 0;
    for (int i = 0; i < n; i++) built |= strcmp(backends[i], env) == 0;
    if (!built) return test_skip("no backend named by ODE_COLLISION_BACKEND is built");
    CHECK(strcmp(dCollisionGetBackend(), env) == 0);
    if (strcmp(env, "fcl") != 0) return 0;
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(box, 0, 0, 0.49);
    dContactGeom c[MAXC];
    CHECK(dCollide(box, plane, MAXC, c, sizeof c[0]) == 4);   // FCL's one, made a face
    CHECK_NEAR(c[0].depth, 0.01, TOL(1e-12, 1e-6));
    dGeomDestroy(plane);
    dGeomDestroy(box);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_environment_selects_the_backend),
    TEST_CASE(test_sphere_sphere_by_hand),
    TEST_CASE(test_compare_sphere_sphere),
    TEST_CASE(test_compare_sphere_box),
    TEST_CASE(test_compare_sphere_capsule),
    TEST_CASE(test_compare_sphere_cylinder),
    TEST_CASE(test_compare_sphere_plane),
    TEST_CASE(test_compare_box_box),
    TEST_CASE(test_compare_box_capsule),
    TEST_CASE(test_compare_box_cylinder),
    TEST_CASE(test_compare_box_plane),
    TEST_CASE(test_compare_capsule_capsule),
    TEST_CASE(test_compare_capsule_cylinder),
    TEST_CASE(test_compare_capsule_plane),
    TEST_CASE(test_compare_cylinder_cylinder),
    TEST_CASE(test_compare_cylinder_plane),
    TEST_CASE(test_face_resting_manifolds),
    TEST_CASE(test_unsupported_pairs_fall_back),
    TEST_CASE(test_sphere_rests_on_plane),
    TEST_CASE(test_box_stands_on_box),
    TEST_CASE(test_box_lands_on_plane),
    TEST_CASE(test_resized_geoms_are_rebuilt),
    TEST_CASE(test_destroyed_geoms_free_their_shapes),
    TEST_CASE(test_switching_backends_keeps_shapes_right),
    TEST_END
};
