// SPDX-License-Identifier: BSD-3-Clause
//
// collide_ccd.c -- cylinder against box, capsule and cylinder: convex pairs
// without a cheap closed form. libccd's MPR decides whether the pair
// intersects and gives a first contact normal. That normal is then
// improved: the depth along a unit direction n, the translation of o1 along
// n that parts the pair, is exactly s(n) = h_o2(n) + h_o1(-n) (h the
// support value), and the penetration depth is its least value over the
// unit sphere (libccd's EPA would find it too, but allocates on the heap
// each call; MPR's own depth is along the centre ray, not the least). It
// is evaluated at the candidate directions of the pair's features (face
// normals, axes, their cross products, radial and rim directions); up to
// 6 of the best (within 0.1 of the pair's size of the best, 11 degrees
// apart) start a local pattern search to 1e-3 radians, and the best result
// is refined to 1e-6. A negative depth there is a separating direction (a
// grazing pair MPR let through): no contact. The contact points follow
// from collide_ccd_manifold.c. Everything inside is double.

#include "collide_ccd.h"
#include "collide_math.h"
#include "mpr_bounded.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// Scales v to unit length; 0 (v unchanged) if it is too short to have a direction.
static int normalize3(double v[3])
{
    double l2 = dot3(v, v);
    if (!(l2 > 1e-24)) return 0;
    double inv = 1 / sqrt(l2);
    for (int i = 0; i < 3; i++) v[i] *= inv;
    return 1;
}

static double sign_of(double x)
{
    return x < 0 ? -1 : 1;
}

// ---- the shapes ------------------------------------------------------------

// dx_convex_extent, inlined in the search's inner loop.
static inline double extent(const dx_convex *s, const double m[3])
{
    double e = dot3(m, s->c);
    if (s->kind == DX_CONVEX_BOX) {
        for (int k = 0; k < 3; k++) e += s->half[k] * fabs(dot3(m, s->ax[k]));
        return e;
    }
    double mz = dot3(m, s->ax[2]), m2 = dot3(m, m);
    e += s->half[2] * fabs(mz);
    if (s->kind == DX_CONVEX_CAPSULE) return e + s->half[0] * sqrt(m2);
    double across2 = m2 - mz * mz;   // the radial part of m, squared
    return e + s->half[0] * sqrt(across2 > 0 ? across2 : 0);
}

double dx_convex_extent(const dx_convex *s, const double m[3])
{
    return extent(s, m);
}

void dx_convex_support(const dx_convex *s, const double m[3], double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = s->c[i];
    if (s->kind == DX_CONVEX_BOX) {
        for (int k = 0; k < 3; k++) {
            double h = s->half[k] * sign_of(dot3(m, s->ax[k]));
            for (int i = 0; i < 3; i++) out[i] += h * s->ax[k][i];
        }
        return;
    }
    const double *z = s->ax[2];
    double mz = dot3(m, z), h = s->half[2] * sign_of(mz), w[3];
    for (int i = 0; i < 3; i++) {
        out[i] += h * z[i];
        w[i] = s->kind == DX_CONVEX_CAPSULE ? m[i] : m[i] - mz * z[i];
    }
    if (!normalize3(w)) return;   // along the axis: the cap's centre is a support point
    for (int i = 0; i < 3; i++) out[i] += s->half[0] * w[i];
}

// A box, cylinder or capsule geom as a dx_convex. The axes are made
// orthonormal (z kept, x square to it, y = z x x): a single precision
// rotation is only orthonormal to ~1e-7, and the manifold's line tests
// need the shape's own frame exact.
static void convex_from_geom(dx_convex *s, const dxGeom *g)
{
    for (int i = 0; i < 3; i++) {
        s->c[i] = g->pos[i];
        for (int k = 0; k < 3; k++) s->ax[k][i] = g->R[4 * i + k];
    }
    normalize3(s->ax[2]);
    double t = dot3(s->ax[0], s->ax[2]);
    for (int i = 0; i < 3; i++) s->ax[0][i] -= t * s->ax[2][i];
    normalize3(s->ax[0]);
    cross3(s->ax[2], s->ax[0], s->ax[1]);
    switch (g->ops->cls) {
    case dBoxClass:
        s->kind = DX_CONVEX_BOX;
        for (int k = 0; k < 3; k++) s->half[k] = ((const dxBox *)g)->side[k] / 2;
        break;
    case dCylinderClass:
        s->kind = DX_CONVEX_CYLINDER;
        s->half[0] = s->half[1] = ((const dxCylinder *)g)->radius;
        s->half[2] = ((const dxCylinder *)g)->length / 2;
        break;
    default:
        s->kind = DX_CONVEX_CAPSULE;
        s->half[0] = s->half[1] = ((const dxCapsule *)g)->radius;
        s->half[2] = ((const dxCapsule *)g)->length / 2;
        break;
    }
}

// A size of the shape: its largest half extent.
static double convex_size(const dx_convex *s)
{
    double m = s->half[0];
    for (int k = 1; k < 3; k++)
        if (s->half[k] > m) m = s->half[k];
    return s->kind == DX_CONVEX_CAPSULE ? m + s->half[0] : m;
}

// ---- libccd ----------------------------------------------------------------

// A dx_convex as MPR sees it.
static void mpr_support(const void *shape, const double dir[3], double out[3])
{
    dx_convex_support(shape, dir, out);
}

// What MPR (no allocation, unlike libccd's EPA) says of a pair; on
// DX_MPR_OVERLAP, n_out gets the unit normal it finds, into a (the opposite
// of libccd's direction, the one to move b along to part the pair).
static dx_mpr_verdict mpr_normal(const dx_convex *a, const dx_convex *b, double scale,
                                 double n_out[3])
{
    dx_mpr_shape sa = { a, mpr_support, { 0 } }, sb = { b, mpr_support, { 0 } };
    memcpy(sa.centre, a->c, sizeof sa.centre);
    memcpy(sb.centre, b->c, sizeof sb.centre);
    double dir[3];
    const dx_mpr_verdict v = dx_mpr_penetration(&sa, &sb, 1e-9 * scale, dir);
    if (v != DX_MPR_OVERLAP) return v;
    for (int i = 0; i < 3; i++) n_out[i] = -dir[i];
    if (!normalize3(n_out)) {   // touching at the centre ray's end: any direction will do
        for (int i = 0; i < 3; i++) n_out[i] = b->ax[2][i];
    }
    return DX_MPR_OVERLAP;
}

// ---- the least depth over directions -----------------------------------------

// The pair being collided and the directions across which its depth
// function has creases (|n . e| terms): box axes, cylinder and capsule axes.
typedef struct ccd_pair {
    const dx_convex *a, *b;
    double crease[4][3];
    int ncrease;
} ccd_pair;

// The best direction so far and its depth.
typedef struct ccd_best {
    double n[3], depth;
} ccd_best;

// The translation of a along the unit n that parts it from b.
static double depth_along(const ccd_pair *p, const double n[3])
{
    double m[3] = { -n[0], -n[1], -n[2] };
    return extent(p->b, n) + extent(p->a, m);
}

// The directions tried as starts, with their depths.
enum { MAX_CANDIDATES = 80 };
typedef struct ccd_candidates {
    ccd_best c[MAX_CANDIDATES];
    int n;
} ccd_candidates;

// Consider the direction d (any length) and its opposite.
static void try_direction(const ccd_pair *p, const double d[3], ccd_candidates *list)
{
    double n[3] = { d[0], d[1], d[2] };
    if (!normalize3(n)) return;
    for (int sgn = 0; sgn < 2 && list->n < MAX_CANDIDATES; sgn++) {
        ccd_best *c = &list->c[list->n++];
        for (int i = 0; i < 3; i++) c->n[i] = sgn ? -n[i] : n[i];
        c->depth = depth_along(p, c->n);
    }
}

// The part of v across the unit axis z.
static void across_axis(const double v[3], const double z[3], double out[3])
{
    double t = dot3(v, z);
    for (int i = 0; i < 3; i++) out[i] = v[i] - t * z[i];
}

// Directions from the cylinder a to the point q: radial from its axis line
// (q against the side) and from the nearest point of the rim on q's side
// (q against the rim).
static void try_point(const ccd_pair *p, const double q[3], ccd_candidates *list)
{
    const dx_convex *a = p->a;
    const double *z = a->ax[2];
    double d[3], r[3];
    for (int i = 0; i < 3; i++) d[i] = q[i] - a->c[i];
    double along = dot3(d, z), cap = along < 0 ? -a->half[2] : a->half[2];
    across_axis(d, z, r);
    try_direction(p, r, list);
    if (!normalize3(r)) return;
    for (int i = 0; i < 3; i++) d[i] -= cap * z[i] + a->half[0] * r[i];
    try_direction(p, d, list);
}

// The box b's corners against the cylinder a.
static void try_box_corners(const ccd_pair *p, ccd_candidates *list)
{
    const dx_convex *b = p->b;
    for (int k = 0; k < 8; k++) {
        double q[3];
        for (int i = 0; i < 3; i++) {
            q[i] = b->c[i];
            for (int j = 0; j < 3; j++) q[i] += ((k >> j & 1) ? 1 : -1) * b->half[j] * b->ax[j][i];
        }
        try_point(p, q, list);
    }
}

// The axis segments of a and of a capsule or cylinder b: the direction
// between their closest points, as it is and across either axis; b's axis
// ends, and the points of b's axis nearest a's cap centres, against a.
static void try_axis_segments(const ccd_pair *p, ccd_candidates *list)
{
    const dx_convex *a = p->a, *b = p->b;
    dReal ca[3], za[3], cb[3], zb[3], s, t;
    for (int i = 0; i < 3; i++) {
        ca[i] = (dReal)a->c[i];
        za[i] = (dReal)a->ax[2][i];
        cb[i] = (dReal)b->c[i];
        zb[i] = (dReal)b->ax[2][i];
    }
    dx_closest_segments(ca, za, (dReal)a->half[2], cb, zb, (dReal)b->half[2], &s, &t);
    double d[3], r[3];
    for (int i = 0; i < 3; i++) d[i] = (a->c[i] + s * a->ax[2][i]) - (b->c[i] + t * b->ax[2][i]);
    try_direction(p, d, list);
    across_axis(d, a->ax[2], r);
    try_direction(p, r, list);
    across_axis(d, b->ax[2], r);
    try_direction(p, r, list);
    for (int e = -1; e <= 1; e += 2) {
        double end[3], near[3];
        for (int i = 0; i < 3; i++) {
            end[i] = b->c[i] + e * b->half[2] * b->ax[2][i];
            d[i] = a->c[i] + e * a->half[2] * a->ax[2][i] - b->c[i];
        }
        double u = dot3(d, b->ax[2]);
        u = u < -b->half[2] ? -b->half[2] : u > b->half[2] ? b->half[2] : u;
        for (int i = 0; i < 3; i++) near[i] = b->c[i] + u * b->ax[2][i];
        try_point(p, end, list);
        try_point(p, near, list);
    }
}

// The candidate directions: libccd's, the centre line, the crease axes,
// and for a's axis with each of b's: their cross product (edge against
// edge) and each projected across the other (a face against a side).
// Then the radial directions of curved sides.
static void try_candidates(const ccd_pair *p, const double mpr_n[3], ccd_candidates *list)
{
    double d[3];
    try_direction(p, mpr_n, list);
    for (int i = 0; i < 3; i++) d[i] = p->a->c[i] - p->b->c[i];
    try_direction(p, d, list);
    const double *za = p->crease[0];
    try_direction(p, za, list);
    for (int k = 1; k < p->ncrease; k++) {
        const double *e = p->crease[k];
        try_direction(p, e, list);
        cross3(za, e, d);
        try_direction(p, d, list);
        across_axis(za, e, d);
        try_direction(p, d, list);
        across_axis(e, za, d);
        try_direction(p, d, list);
    }
    if (p->b->kind == DX_CONVEX_BOX)
        try_box_corners(p, list);
    else
        try_axis_segments(p, list);
}

enum { SEARCH_ITERATIONS = 120, SEARCH_DIRECTIONS = 6 };
#define SEARCH_FIRST_STEP 0.05   // radians
#define SEARCH_COARSE_STEP 1e-3   // the starts' searches stop here, the best's goes on
#define SEARCH_LAST_STEP 1e-6
#define SEARCH_SHRINK 3
// The pattern: 6 directions 60 degrees apart, all turned by 0.7 radians
// (about 40 degrees) from one iteration to the next.
#define COS_60 0.5
#define SIN_60 0.86602540378443865
#define COS_TURN 0.76484218728448842
#define SIN_TURN 0.64421768723769105

// Two unit vectors completing the unit n to an orthonormal frame.
static void complete_frame(const double n[3], double u[3], double v[3])
{
    int k = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0
            : fabs(n[1]) <= fabs(n[2])                        ? 1
                                                              : 2;
    double e[3] = { 0, 0, 0 };
    e[k] = 1;
    cross3(n, e, u);
    normalize3(u);
    cross3(n, u, v);
}

// Consider the direction of n + step t, for unit n and t square to it: its
// length is sqrt(1 + step^2), and the depth scales with the length.
static void try_step(const ccd_pair *p, const double n[3], const double t[3], double step,
                     ccd_best *best)
{
    double m[3], inv = 1 / sqrt(1 + step * step);
    for (int i = 0; i < 3; i++) m[i] = n[i] + step * t[i];
    double f = depth_along(p, m) * inv;
    if (f < best->depth) {
        best->depth = f;
        for (int i = 0; i < 3; i++) best->n[i] = m[i] * inv;
    }
}

// Moves along the crease of the axis e near n (the unit directions across
// e): the depth is not smooth across it, and the pattern's steps, which
// leave it, can stall there while going down along it is still possible.
static void try_crease(const ccd_pair *p, const double n[3], const double e[3], double step,
                       ccd_best *best)
{
    double q[3], t[3];
    across_axis(n, e, q);
    if (!normalize3(q)) return;
    cross3(e, q, t);
    try_step(p, q, t, 0, best);
    try_step(p, q, t, step, best);
    try_step(p, q, t, -step, best);
}

// Local pattern search for the least depth from best: steps around the
// current direction in turning patterns, plus moves along nearby creases;
// the step halves whenever none is better.
static void refine(const ccd_pair *p, double first_step, double last_step, ccd_best *best)
{
    double step = first_step, c0 = 1, s0 = 0;   // the pattern's first direction
    for (int it = 0; it < SEARCH_ITERATIONS && step > last_step; it++) {
        ccd_best next = *best;
        double u[3], v[3], t[3], c = c0, s = s0;
        complete_frame(best->n, u, v);
        for (int k = 0; k < SEARCH_DIRECTIONS; k++) {
            for (int i = 0; i < 3; i++) t[i] = c * u[i] + s * v[i];
            try_step(p, best->n, t, step, &next);
            double c1 = c * COS_60 - s * SIN_60;
            s = s * COS_60 + c * SIN_60;
            c = c1;
        }
        double c1 = c0 * COS_TURN - s0 * SIN_TURN;
        s0 = s0 * COS_TURN + c0 * SIN_TURN;
        c0 = c1;
        for (int k = 0; k < p->ncrease; k++)
            if (fabs(dot3(best->n, p->crease[k])) < step)
                try_crease(p, best->n, p->crease[k], step, &next);
        if (next.depth < best->depth)
            *best = next;
        else
            step /= SEARCH_SHRINK;
    }
}

enum { SEARCH_STARTS = 6 };
#define SEARCH_START_COS 0.98   // starts differ by more than 11 degrees
#define SEARCH_START_MARGIN 0.1   // of the pair's size

// The local search from the best candidates (the depth has local minima:
// one per face of the pair's Minkowski difference, roughly), each start
// more than 11 degrees from the previous ones and within 0.1 of the
// pair's size of the best so far; the least result into best.
static void search_from_starts(const ccd_pair *p, ccd_candidates *list, double scale,
                               ccd_best *best)
{
    double starts[SEARCH_STARTS][3];
    for (int k = 0; k < SEARCH_STARTS; k++) {
        int pick = -1;
        for (int i = 0; i < list->n; i++) {
            int near = 0;
            for (int j = 0; j < k && !near; j++)
                near = dot3(list->c[i].n, starts[j]) > SEARCH_START_COS;
            if (!near && (pick < 0 || list->c[i].depth < list->c[pick].depth)) pick = i;
        }
        if (pick < 0 || list->c[pick].depth > best->depth + SEARCH_START_MARGIN * scale) return;
        ccd_best local = list->c[pick];
        for (int i = 0; i < 3; i++) starts[k][i] = local.n[i];
        refine(p, SEARCH_FIRST_STEP, SEARCH_COARSE_STEP, &local);
        if (local.depth < best->depth) *best = local;
    }
}

// The pair's penetration: 0 if apart, else 1 with the unit normal n (into
// a) and the depth along it.
static int penetration(const dx_convex *a, const dx_convex *b, double n[3], double *depth)
{
    double scale = convex_size(a) + convex_size(b), mpr_n[3];
    const dx_mpr_verdict v = mpr_normal(a, b, scale, mpr_n);
    if (v == DX_MPR_APART) return 0;
    // Undecided: the search below decides alone (from the centre line and
    // the features' directions); a negative least depth still means apart.
    if (v == DX_MPR_UNDECIDED)
        for (int i = 0; i < 3; i++) mpr_n[i] = a->c[i] - b->c[i];
    ccd_pair p = { a, b, { { 0 } }, 0 };
    for (int i = 0; i < 3; i++) p.crease[p.ncrease][i] = a->ax[2][i];
    p.ncrease++;
    for (int k = b->kind == DX_CONVEX_BOX ? 0 : 2; k < 3; k++, p.ncrease++)
        for (int i = 0; i < 3; i++) p.crease[p.ncrease][i] = b->ax[k][i];
    ccd_candidates list = { .n = 0 };
    try_candidates(&p, mpr_n, &list);
    ccd_best best = { { 0, 0, 1 }, INFINITY };
    search_from_starts(&p, &list, scale, &best);
    refine(&p, SEARCH_COARSE_STEP, SEARCH_LAST_STEP, &best);
    // A direction of negative depth separates: MPR's tolerance let a
    // grazing pair through.
    if (!(best.depth >= 0)) return 0;
    for (int i = 0; i < 3; i++) n[i] = best.n[i];
    *depth = best.depth;
    return 1;
}

// ---- the colliders ---------------------------------------------------------

static int collide_convex(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    dx_convex a, b;
    convex_from_geom(&a, o1);
    convex_from_geom(&b, o2);
    double n[3], depth;
    if (!penetration(&a, &b, n, &depth)) return 0;
    dx_ccd_point pts[DX_CCD_MAX_POINTS];
    int count = dx_ccd_manifold(&a, &b, n, depth, pts, dx_max_contacts(flags));
    dReal normal[3] = { (dReal)n[0], (dReal)n[1], (dReal)n[2] };
    for (int k = 0; k < count; k++) {
        dReal pos[3] = { (dReal)pts[k].pos[0], (dReal)pts[k].pos[1], (dReal)pts[k].pos[2] };
        dx_put_contact(c, k, skip, pos, normal, (dReal)pts[k].depth, o1, o2);
    }
    return count;
}

int dxCollideCylinderBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide_convex(o1, o2, flags, c, skip);
}

int dxCollideCylinderCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide_convex(o1, o2, flags, c, skip);
}

// Cylinder-cylinder in one order for either (the first geom in memory as
// a, the other's contacts flipped): dCollide(b, a) is then the exact mirror
// image of dCollide(a, b), as for the pairs of different classes.
int dxCollideCylinderCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    if ((uintptr_t)o1 <= (uintptr_t)o2) return collide_convex(o1, o2, flags, c, skip);
    int n = collide_convex(o2, o1, flags, c, skip);
    dxFlipContacts(c, n, skip);
    return n;
}
