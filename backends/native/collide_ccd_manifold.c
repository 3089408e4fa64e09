// SPDX-License-Identifier: BSD-3-Clause
//
// collide_ccd_manifold.c -- the contact points of the libccd pairs once the
// normal n (into a) and the depth are known. Each shape's contact feature
// is the part of its surface that faces the other along n: a box's face,
// edge or corner; a cylinder's cap disc (a 16-gon on its rim), side line or
// rim point; a capsule's side line or end. A feature counts as a face or a
// line when n is within 5 degrees of being square to it, so that resting
// contacts keep their polygon while the solver tilts them a little. The
// two features are projected on the plane across n and intersected
// (convex clipping, or the overlap of two lines); each point of the
// intersection gets its own depth, the gap along n between the features
// there, and the ones deeper than 0 (but for rounding) are kept. When the features are points
// or do not overlap, one contact at their closest points with the pair's
// depth. Only fixed-size arrays on the stack.

#include "collide_ccd.h"

#include <math.h>
#include <string.h>

enum { DISC_SIDES = 16, MAXP = DX_CCD_MAX_POINTS };
#define FEATURE_SIN 0.087155742747658174   // sin 5 degrees
#define FEATURE_COS 0.99619469809174553    // cos 5 degrees
#define TWO_PI 6.283185307179586477

// A contact feature: its vertices in world coordinates, and projected on
// the frame's plane (xy) with their heights along the normal (h).
typedef struct feature {
    int n;                       // 1 a point, 2 a segment, more a convex polygon in order
    double p[DISC_SIDES][3];
    double plane[3], offset;     // a polygon's plane: plane . x = offset
    double xy[DISC_SIDES][2], h[DISC_SIDES];
} feature;

// The contact frame: the unit normal n and two unit vectors u, v across it.
typedef struct frame {
    double n[3], u[3], v[3];
} frame;

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double cross2(const double *a, const double *b)
{
    return a[0] * b[1] - a[1] * b[0];
}

static double sign_of(double x)
{
    return x < 0 ? -1 : 1;
}

// ---- features ----------------------------------------------------------------

// out = c + sum_k w[k] axis[k].
static void combine(const double c[3], const double (*axis)[3], const double w[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = c[i] + w[0] * axis[0][i] + w[1] * axis[1][i] + w[2] * axis[2][i];
}

// A box's feature facing the unit direction m: its axes within 5 degrees
// of square to m are flat (both signs), the others take m's sign.
static void box_feature(const dx_convex *s, const double m[3], feature *f)
{
    double w[3];
    int flat[3], nflat = 0;
    for (int k = 0; k < 3; k++) {
        double t = dot3(m, s->ax[k]);
        flat[k] = fabs(t) < FEATURE_SIN;
        nflat += flat[k];
        w[k] = flat[k] ? 0 : sign_of(t) * s->half[k];
    }
    if (nflat == 0) {
        f->n = 1;
        combine(s->c, s->ax, w, f->p[0]);
    } else if (nflat == 1) {
        int k = flat[0] ? 0 : flat[1] ? 1 : 2;
        f->n = 2;
        for (int e = 0; e < 2; e++) {
            w[k] = (e ? 1 : -1) * s->half[k];
            combine(s->c, s->ax, w, f->p[e]);
        }
    } else {   // a face: the corners in turn around it
        int k = !flat[0] ? 0 : !flat[1] ? 1 : 2, i = (k + 1) % 3, j = (k + 2) % 3;
        static const double si[4] = { 1, -1, -1, 1 }, sj[4] = { 1, 1, -1, -1 };
        f->n = 4;
        for (int e = 0; e < 4; e++) {
            w[i] = si[e] * s->half[i];
            w[j] = sj[e] * s->half[j];
            combine(s->c, s->ax, w, f->p[e]);
        }
        for (int d = 0; d < 3; d++) f->plane[d] = s->ax[k][d];
        f->offset = dot3(f->plane, f->p[0]);
    }
}

// A cylinder's or capsule's feature facing the unit direction m: a
// cylinder's cap disc within 5 degrees of the axis, the side line within 5
// degrees of square to it, else the point of the rim (cylinder) or end
// (capsule) furthest along m. The points furthest along m are corners, so
// that the deepest contact has the pair's depth. A capsule's line is its
// axis moved by r m: on the surface at the deeper end, a little inside
// elsewhere when m is not square to the axis (which errs on the shallow
// side); a cylinder's side line is on its surface.
static void round_feature(const dx_convex *s, const double m[3], feature *f)
{
    const double *z = s->ax[2];
    double t = dot3(m, z), r = s->half[0], hl = s->half[2], end = sign_of(t) * hl;
    if (s->kind == DX_CONVEX_CYLINDER && fabs(t) >= FEATURE_COS) {
        // The 16-gon turned to have a corner at the rim point furthest along
        // m, or (m along the axis but for rounding) at the local x axis.
        double mx = dot3(m, s->ax[0]), my = dot3(m, s->ax[1]);
        double w[3] = { 0, 0, end }, turn = fabs(mx) + fabs(my) > 1e-12 ? atan2(my, mx) : 0;
        for (int e = 0; e < DISC_SIDES; e++) {
            double angle = turn + TWO_PI * e / DISC_SIDES;
            w[0] = r * cos(angle);
            w[1] = r * sin(angle);
            combine(s->c, s->ax, w, f->p[e]);
        }
        f->n = DISC_SIDES;
        for (int d = 0; d < 3; d++) f->plane[d] = z[d];
        f->offset = dot3(z, f->p[0]);
        return;
    }
    // The radial direction of m scaled to the radius (m along a capsule's
    // axis has none: its end's point is then r m).
    double w[3], l2 = 0;
    for (int i = 0; i < 3; i++) {
        w[i] = m[i] - t * z[i];
        l2 += w[i] * w[i];
    }
    double scale = l2 > 0 ? r / sqrt(l2) : 0;
    for (int i = 0; i < 3; i++) w[i] = s->kind == DX_CONVEX_CAPSULE ? r * m[i] : scale * w[i];
    if (fabs(t) < FEATURE_SIN) {   // from the other end to the end furthest along m
        f->n = 2;
        for (int i = 0; i < 3; i++) {
            f->p[0][i] = s->c[i] - end * z[i] + w[i];
            f->p[1][i] = s->c[i] + end * z[i] + w[i];
        }
        return;
    }
    f->n = 1;
    for (int i = 0; i < 3; i++) f->p[0][i] = s->c[i] + end * z[i] + w[i];
}

// The feature of s facing m, projected on the frame.
static void make_feature(const dx_convex *s, const double m[3], const frame *fr, feature *f)
{
    if (s->kind == DX_CONVEX_BOX)
        box_feature(s, m, f);
    else
        round_feature(s, m, f);
    for (int e = 0; e < f->n; e++) {
        f->xy[e][0] = dot3(f->p[e], fr->u);
        f->xy[e][1] = dot3(f->p[e], fr->v);
        f->h[e] = dot3(f->p[e], fr->n);
    }
}

// The parameter in [0, 1] of the point of segment feature f nearest to q
// (across the normal).
static double segment_param(const feature *f, const double q[2])
{
    double d[2] = { f->xy[1][0] - f->xy[0][0], f->xy[1][1] - f->xy[0][1] };
    double l2 = d[0] * d[0] + d[1] * d[1];
    if (!(l2 > 0)) return 0;
    double t = ((q[0] - f->xy[0][0]) * d[0] + (q[1] - f->xy[0][1]) * d[1]) / l2;
    return t < 0 ? 0 : t > 1 ? 1 : t;
}

// The height along the normal of feature f at q across it: on a
// polygon's plane, along a segment, or the point's.
static double feature_height(const feature *f, const frame *fr, const double q[2])
{
    if (f->n >= 3) {   // plane . (q0 u + q1 v + h n) = offset; plane . n ~ 1 for facing features
        return (f->offset - q[0] * dot3(f->plane, fr->u) - q[1] * dot3(f->plane, fr->v)) /
               dot3(f->plane, fr->n);
    }
    if (f->n == 1) return f->h[0];
    double t = segment_param(f, q);
    return f->h[0] + t * (f->h[1] - f->h[0]);
}

// ---- intersecting the projected features -----------------------------------------

// Twice the signed area of a projected polygon (positive counterclockwise).
static double polygon_area2(const feature *f)
{
    double a = 0;
    for (int e = 0; e < f->n; e++) a += cross2(f->xy[e], f->xy[(e + 1) % f->n]);
    return a;
}

// Sutherland-Hodgman: the projected feature subj (any count; a segment
// comes out as its clipped part, its ends repeated) clipped by the convex
// projected polygon clip, into out; returns the count.
static int clip_convex(const feature *subj, const feature *clip, double out[][2])
{
    double buf[2][MAXP][2];
    int cur = 0, count = subj->n;
    memcpy(buf[0], subj->xy, sizeof(double[2]) * (size_t)count);
    double orient = polygon_area2(clip) < 0 ? -1 : 1;
    for (int e = 0; e < clip->n && count > 0; e++) {
        const double *a = clip->xy[e], *b = clip->xy[(e + 1) % clip->n];
        double edge[2] = { b[0] - a[0], b[1] - a[1] };
        double(*in)[2] = buf[cur], (*res)[2] = buf[cur ^ 1];
        int next = 0;
        for (int j = 0; j < count; j++) {
            const double *p = in[j], *q = in[(j + 1) % count];
            double rp[2] = { p[0] - a[0], p[1] - a[1] }, rq[2] = { q[0] - a[0], q[1] - a[1] };
            double dp = orient * cross2(edge, rp), dq = orient * cross2(edge, rq);
            if (dp >= 0 && next < MAXP) {
                res[next][0] = p[0];
                res[next++][1] = p[1];
            }
            if ((dp >= 0) != (dq >= 0) && next < MAXP) {
                double t = dp / (dp - dq);
                res[next][0] = p[0] + t * (q[0] - p[0]);
                res[next++][1] = p[1] + t * (q[1] - p[1]);
            }
        }
        count = next;
        cur ^= 1;
    }
    memcpy(out, buf[cur], sizeof(double[2]) * (size_t)count);
    return count;
}

// Two projected segments: their common part when they are within 5
// degrees of parallel (on a's line), else their crossing point.
static int segments_overlap(const feature *a, const feature *b, double out[][2])
{
    const double *a0 = a->xy[0], *b0 = b->xy[0];
    double da[2] = { a->xy[1][0] - a0[0], a->xy[1][1] - a0[1] };
    double db[2] = { b->xy[1][0] - b0[0], b->xy[1][1] - b0[1] };
    double w[2] = { b0[0] - a0[0], b0[1] - a0[1] };
    double la2 = da[0] * da[0] + da[1] * da[1], lb2 = db[0] * db[0] + db[1] * db[1];
    if (!(la2 > 0) || !(lb2 > 0)) return 0;
    double cr = cross2(da, db);
    if (fabs(cr) <= FEATURE_SIN * sqrt(la2 * lb2)) {
        double t0 = (w[0] * da[0] + w[1] * da[1]) / la2;
        double t1 = t0 + (db[0] * da[0] + db[1] * da[1]) / la2;
        double lo = fmax(0, fmin(t0, t1)), hi = fmin(1, fmax(t0, t1));
        if (lo > hi) return 0;
        for (int i = 0; i < 2; i++) {
            out[0][i] = a0[i] + lo * da[i];
            out[1][i] = a0[i] + hi * da[i];
        }
        return 2;
    }
    double s = cross2(w, db) / cr, t = cross2(w, da) / cr;
    if (s < 0 || s > 1 || t < 0 || t > 1) return 0;
    for (int i = 0; i < 2; i++) out[0][i] = a0[i] + s * da[i];
    return 1;
}

// The projected features' common points, for polygons with anything and
// two segments; 0 for the rest (points), which the fallback handles.
static int overlap(const feature *fa, const feature *fb, double out[][2])
{
    if (fb->n >= 3) return clip_convex(fa, fb, out);
    if (fa->n >= 3) return clip_convex(fb, fa, out);
    if (fa->n == 2 && fb->n == 2) return segments_overlap(fa, fb, out);
    return 0;
}

// ---- the fallback: one point at the closest points ---------------------------------

// The point of segment p0 p1 nearest to q.
static void nearest_on_segment(const double p0[2], const double p1[2], const double q[2],
                               double out[2])
{
    double d[2] = { p1[0] - p0[0], p1[1] - p0[1] }, l2 = d[0] * d[0] + d[1] * d[1];
    double t = l2 > 0 ? ((q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1]) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    out[0] = p0[0] + t * d[0];
    out[1] = p0[1] + t * d[1];
}

// The point of projected feature f nearest to q.
static void nearest_on_feature(const feature *f, const double q[2], double out[2])
{
    out[0] = f->xy[0][0];
    out[1] = f->xy[0][1];
    if (f->n == 1) return;
    if (f->n >= 3) {   // inside the polygon: q itself
        double orient = polygon_area2(f) < 0 ? -1 : 1;
        int inside = 1;
        for (int e = 0; e < f->n && inside; e++) {
            const double *a = f->xy[e], *b = f->xy[(e + 1) % f->n];
            double edge[2] = { b[0] - a[0], b[1] - a[1] }, r[2] = { q[0] - a[0], q[1] - a[1] };
            inside = orient * cross2(edge, r) >= 0;
        }
        if (inside) {
            out[0] = q[0];
            out[1] = q[1];
            return;
        }
    }
    double best = INFINITY;
    int edges = f->n == 2 ? 1 : f->n;
    for (int e = 0; e < edges; e++) {
        double c[2];
        nearest_on_segment(f->xy[e], f->xy[(e + 1) % f->n], q, c);
        double d2 = (c[0] - q[0]) * (c[0] - q[0]) + (c[1] - q[1]) * (c[1] - q[1]);
        if (d2 < best) {
            best = d2;
            out[0] = c[0];
            out[1] = c[1];
        }
    }
}

// The closest points qa, qb of the projected features (one of them at a
// vertex, as for any two convex sets apart; the first vertex found when
// they overlap).
static void closest_pair(const feature *fa, const feature *fb, double qa[2], double qb[2])
{
    double best = INFINITY;
    for (int side = 0; side < 2; side++) {
        const feature *f = side ? fb : fa, *g = side ? fa : fb;
        for (int e = 0; e < f->n; e++) {
            double c[2];
            nearest_on_feature(g, f->xy[e], c);
            double d2 = (c[0] - f->xy[e][0]) * (c[0] - f->xy[e][0]) +
                        (c[1] - f->xy[e][1]) * (c[1] - f->xy[e][1]);
            if (d2 < best) {
                best = d2;
                double *mine = side ? qb : qa, *other = side ? qa : qb;
                mine[0] = f->xy[e][0];
                mine[1] = f->xy[e][1];
                other[0] = c[0];
                other[1] = c[1];
            }
        }
    }
}

// The world point at q across the frame and height h along it.
static void lift(const frame *fr, const double q[2], double h, double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = q[0] * fr->u[i] + q[1] * fr->v[i] + h * fr->n[i];
}

// ---- the overlap along the normal ---------------------------------------------------

// Intersect [*t0, *t1] with the t where -hi <= o + t d <= hi (one
// coordinate); 0 if the line runs along the slab outside it.
static int clip_slab(double o, double d, double hi, double *t0, double *t1)
{
    if (fabs(d) < 1e-12) return fabs(o) <= hi;
    double a = (-hi - o) / d, b = (hi - o) / d;
    *t0 = fmax(*t0, fmin(a, b));
    *t1 = fmin(*t1, fmax(a, b));
    return 1;
}

// Intersect [*t0, *t1] with the t where |o + t d| <= r, over the first
// `dims` coordinates (2: a cylinder's round side, 3: a ball); 0 if the
// line misses.
static int clip_round(const double o[3], const double d[3], int dims, double r, double *t0,
                      double *t1)
{
    double a = 0, b = 0, c = -r * r;
    for (int i = 0; i < dims; i++) {
        a += d[i] * d[i];
        b += o[i] * d[i];
        c += o[i] * o[i];
    }
    if (a < 1e-24) return c <= 0;
    double disc = b * b - a * c;
    if (disc < 0) return 0;
    double root = sqrt(disc);
    *t0 = fmax(*t0, (-b - root) / a);
    *t1 = fmin(*t1, (-b + root) / a);
    return 1;
}

// An interval [t0, t1] that rounding left empty by less than tol is the
// point between; 0 if it is empty by more.
static int settle(double *t0, double *t1, double tol)
{
    if (*t0 <= *t1) return 1;
    if (*t0 - *t1 > tol) return 0;
    *t0 = *t1 = (*t0 + *t1) / 2;
    return 1;
}

// The part [*t0, *t1] of the line o + t d (world, d unit) inside s grown
// by 1e-12 of its size (a thousand times the rounding), so that lines
// through an edge or a rim (as from the features' corners) keep their
// point; 0 if it misses. A capsule is convex: its part spans the parts in its round side
// (between the end planes) and in its end balls.
static int line_interval(const dx_convex *s, const double ow[3], const double dw[3], double *t0,
                         double *t1)
{
    double o[3], d[3];
    for (int k = 0; k < 3; k++) {
        o[k] = dot3(ow, s->ax[k]) - dot3(s->c, s->ax[k]);
        d[k] = dot3(dw, s->ax[k]);
    }
    double tol = 1e-12 * (s->half[0] + s->half[1] + s->half[2]);
    double r = s->half[0] + tol, hl = s->half[2] + tol;
    *t0 = -INFINITY;
    *t1 = INFINITY;
    if (s->kind == DX_CONVEX_BOX) {
        for (int k = 0; k < 3; k++)
            if (!clip_slab(o[k], d[k], s->half[k] + tol, t0, t1)) return 0;
        return settle(t0, t1, tol);
    }
    int hit = clip_slab(o[2], d[2], hl, t0, t1) && clip_round(o, d, 2, r, t0, t1) &&
              settle(t0, t1, tol);
    if (s->kind == DX_CONVEX_CYLINDER) return hit;
    if (!hit) {
        *t0 = INFINITY;
        *t1 = -INFINITY;
    }
    for (int e = -1; e <= 1; e += 2) {
        double oe[3] = { o[0], o[1], o[2] - e * s->half[2] }, b0 = -INFINITY, b1 = INFINITY;
        if (!clip_round(oe, d, 3, r, &b0, &b1)) continue;
        *t0 = fmin(*t0, b0);
        *t1 = fmax(*t1, b1);
    }
    return *t0 <= *t1;
}

// The contact at q across the frame: depth b's top over a's bottom along
// the normal there, pos the middle of the part of that line inside both; 0
// if the line misses either, or they do not overlap on it (by more than
// tol).
static int contact_at(const dx_convex *a, const dx_convex *b, const frame *fr, const double q[2],
                      double tol, dx_ccd_point *p)
{
    double o[3], a0, a1, b0, b1;
    lift(fr, q, 0, o);
    if (!line_interval(a, o, fr->n, &a0, &a1) || !line_interval(b, o, fr->n, &b0, &b1)) return 0;
    double lo = fmax(a0, b0), hi = fmin(a1, b1);
    if (!settle(&lo, &hi, tol)) return 0;
    lift(fr, q, (lo + hi) / 2, p->pos);
    p->depth = b1 - a0;
    return 1;
}

// ---- choosing the points -------------------------------------------------------------

static double dist2_3(const double *a, const double *b)
{
    double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return dot3(d, d);
}

// At most max of the n points into out: the deepest first, then each time
// the one furthest from those taken (a spread over the contact region).
static int select_points(dx_ccd_point *pts, int n, dx_ccd_point *out, int max)
{
    int deepest = 0;
    for (int i = 1; i < n; i++)
        if (pts[i].depth > pts[deepest].depth) deepest = i;
    dx_ccd_point t = pts[0];
    pts[0] = pts[deepest];
    pts[deepest] = t;
    if (n <= max) {
        memcpy(out, pts, sizeof *pts * (size_t)n);
        return n;
    }
    double gap[MAXP];   // squared distance to the nearest point taken
    out[0] = pts[0];
    for (int i = 1; i < n; i++) gap[i] = dist2_3(pts[i].pos, pts[0].pos);
    gap[0] = -1;
    for (int k = 1; k < max; k++) {
        int far = 0;
        for (int i = 1; i < n; i++)
            if (gap[i] > gap[far]) far = i;
        out[k] = pts[far];
        gap[far] = -1;
        for (int i = 1; i < n; i++) {
            double d2 = dist2_3(pts[i].pos, pts[far].pos);
            if (gap[i] >= 0 && d2 < gap[i]) gap[i] = d2;
        }
    }
    return max;
}

int dx_ccd_manifold(const dx_convex *a, const dx_convex *b, const double n[3], double depth,
                    dx_ccd_point *out, int max)
{
    frame fr;
    for (int i = 0; i < 3; i++) fr.n[i] = n[i];
    // u across n (crossing n with the world axis it is least along), v = n x u.
    int k = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0
            : fabs(n[1]) <= fabs(n[2])                        ? 1
                                                              : 2;
    double e[3] = { 0, 0, 0 };
    e[k] = 1;
    fr.u[0] = n[1] * e[2] - n[2] * e[1];
    fr.u[1] = n[2] * e[0] - n[0] * e[2];
    fr.u[2] = n[0] * e[1] - n[1] * e[0];
    double ul = sqrt(dot3(fr.u, fr.u));
    for (int i = 0; i < 3; i++) fr.u[i] /= ul;
    fr.v[0] = n[1] * fr.u[2] - n[2] * fr.u[1];
    fr.v[1] = n[2] * fr.u[0] - n[0] * fr.u[2];
    fr.v[2] = n[0] * fr.u[1] - n[1] * fr.u[0];

    // a's feature faces -n (towards b), b's faces n.
    feature fa, fb;
    double down[3] = { -n[0], -n[1], -n[2] };
    make_feature(a, down, &fr, &fa);
    make_feature(b, n, &fr, &fb);

    double common[MAXP][2], size = 0;
    for (int i = 0; i < 3; i++) size = fmax(size, fmax(a->half[i], b->half[i]));
    double same2 = 1e-14 * size * size;   // closer than 1e-7 sizes: the same point
    int count = overlap(&fa, &fb, common), found = 0;
    dx_ccd_point pts[MAXP];
    // Points shallower than 0 by less than 1e-7 sizes (rounding, as of a
    // single precision rotation: a lying cylinder's ends differ by ~1e-7)
    // count at depth 0, so that a resting pair keeps its whole polygon.
    double margin = 1e-7 * size;
    for (int i = 0; i < count; i++) {
        dx_ccd_point p;
        if (!contact_at(a, b, &fr, common[i], margin, &p) || !(p.depth > -margin)) continue;
        // Not past the exact depth (the grown shapes' rounding), nor below 0.
        p.depth = fmax(0, fmin(p.depth, depth));
        int dup = 0;
        for (int j = 0; j < found && !dup; j++) dup = dist2_3(p.pos, pts[j].pos) < same2;
        if (!dup) pts[found++] = p;
    }
    if (found == 0) {   // at the features' closest points, with the pair's depth
        double qa[2], qb[2], mid[2];
        closest_pair(&fa, &fb, qa, qb);
        mid[0] = (qa[0] + qb[0]) / 2;
        mid[1] = (qa[1] + qb[1]) / 2;
        if (!contact_at(a, b, &fr, mid, margin, &pts[0]))
            lift(&fr, mid, (feature_height(&fa, &fr, qa) + feature_height(&fb, &fr, qb)) / 2,
                 pts[0].pos);
        pts[0].depth = depth;
        found = 1;
    }
    return select_points(pts, found, out, max);
}
