// SPDX-License-Identifier: BSD-3-Clause
//
// collide_convex.c -- the convex hull (ODE 0.16's dCreateConvex) against
// every class but the triangle mesh, boxes and hulls (whose colliders are
// in collide_convex_hull.c, with the separating axis test); planes take the hull's
// points below them; rays clip their line by the hull's planes; a sphere
// meets the hull's closest point (or its nearest face from inside); a
// capsule is its axis segment grown by the radius: the segment's distance
// to the hull, or, when it enters the hull, the separating axes of the
// segment (hull faces, hull edges across the axis). A cylinder has no such
// closed form: libccd's MPR tells whether it meets the hull and gives a
// first normal, and the least depth is searched from it and from the
// pair's feature directions. Where the normal is a face normal of the hull,
// the capsule's segment or the cylinder's resting side or cap is clipped to
// that face for a manifold. Everything inside is double.

#include "collide_convex.h"
#include "collide_math.h"
#include "mpr_bounded.h"

#include <math.h>
#include <string.h>

// A normal within this of a hull face's counts as that face's (manifold).
#define FACE_ALIGNED (1 - DX_HULL_EPS)
// The cylinder's cap and side rest on a face within this of it.
#define CYL_ALIGNED 1e-3
enum { RIM_POINTS = 16, MAX_EXTRA = 64 };

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

static int normalize3(double v[3])
{
    double l2 = dot3(v, v);
    if (!(l2 > 1e-30)) return 0;
    double inv = 1 / sqrt(l2);
    for (int i = 0; i < 3; i++) v[i] *= inv;
    return 1;
}

static void put(dContactGeom *out, int i, int skip, const double p[3], const double n[3],
                double depth, dxGeom *o1, dxGeom *o2)
{
    dReal pos[3], nn[3];
    for (int k = 0; k < 3; k++) {
        pos[k] = (dReal)p[k];
        nn[k] = (dReal)n[k];
    }
    dx_put_contact(out, i, skip, pos, nn, (dReal)depth, o1, o2);
}

static void geom_pos(const dxGeom *g, double c[3])
{
    for (int i = 0; i < 3; i++) c[i] = g->pos[i];
}

static void geom_axis(const dxGeom *g, int k, double z[3])
{
    for (int i = 0; i < 3; i++) z[i] = g->R[4 * i + k];
}

// ---- closest points ---------------------------------------------------------------

// The point of segment p0 p1 nearest q, into out.
static void nearest_on_segment(const double p0[3], const double p1[3], const double q[3],
                               double out[3])
{
    double d[3], w[3];
    for (int i = 0; i < 3; i++) {
        d[i] = p1[i] - p0[i];
        w[i] = q[i] - p0[i];
    }
    double l2 = dot3(d, d), t = l2 > 0 ? dot3(w, d) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (int i = 0; i < 3; i++) out[i] = p0[i] + t * d[i];
}

static double dist2(const double *a, const double *b)
{
    double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return dot3(d, d);
}

// The closest points pa on segment a0 a1 and pb on b0 b1.
static void segments_closest(const double a0[3], const double a1[3], const double b0[3],
                             const double b1[3], double pa[3], double pb[3])
{
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) {
        u[i] = a1[i] - a0[i];
        v[i] = b1[i] - b0[i];
        w[i] = a0[i] - b0[i];
    }
    double a = dot3(u, u), b = dot3(u, v), c = dot3(v, v), d = dot3(u, w), e = dot3(v, w);
    double den = a * c - b * b, s = 0, t;
    if (den > 1e-14 * a * c) {
        s = (b * e - c * d) / den;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
    }
    t = c > 0 ? (b * s + e) / c : 0;
    if (t < 0 || t > 1) {   // clamp t, then s again for it
        t = t < 0 ? 0 : 1;
        s = a > 0 ? (b * t - d) / a : 0;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
    }
    for (int i = 0; i < 3; i++) {
        pa[i] = a0[i] + s * u[i];
        pb[i] = b0[i] + t * v[i];
    }
}

// 1 if q (on the plane of face f, normal n) is inside the face's polygon.
static int inside_polygon(const dx_hull *h, unsigned f, const double n[3], const double q[3])
{
    unsigned count;
    const unsigned *idx = dx_hull_polygon(h, f, &count);
    int pos = 0, neg = 0;
    for (unsigned k = 0; k < count; k++) {
        double v0[3], v1[3], e[3], r[3], s[3];
        dx_hull_vertex(h, idx[k], v0);
        dx_hull_vertex(h, idx[(k + 1) % count], v1);
        for (int i = 0; i < 3; i++) {
            e[i] = v1[i] - v0[i];
            r[i] = q[i] - v0[i];
        }
        cross3(e, r, s);
        double side = dot3(s, n);
        pos += side > 0;
        neg += side < 0;
    }
    return pos == 0 || neg == 0;   // on one side of every edge, whatever the winding
}

// The point of face f's polygon nearest q, into out; returns the squared distance.
static double polygon_closest(const dx_hull *h, unsigned f, const double q[3], double out[3])
{
    double n[3], d;
    dx_hull_plane(h, f, n, &d);
    double above = dot3(n, q) - d, p[3];
    for (int i = 0; i < 3; i++) p[i] = q[i] - above * n[i];
    if (inside_polygon(h, f, n, p)) {
        memcpy(out, p, sizeof p);
        return above * above;
    }
    unsigned count;
    const unsigned *idx = dx_hull_polygon(h, f, &count);
    double best = INFINITY;
    for (unsigned k = 0; k < count; k++) {
        double v0[3], v1[3], c[3];
        dx_hull_vertex(h, idx[k], v0);
        dx_hull_vertex(h, idx[(k + 1) % count], v1);
        nearest_on_segment(v0, v1, q, c);
        double d2 = dist2(c, q);
        if (d2 < best) {
            best = d2;
            memcpy(out, c, sizeof c);
        }
    }
    return best;
}

// The closest points of the hull (ph) and the segment s0 s1 (ps), known
// not to meet the hull: over the faces, the segment's ends against the
// polygon and the segment against the polygon's edges. Returns the squared
// distance.
static double hull_segment_closest(const dx_hull *h, const double s0[3], const double s1[3],
                                   double ph[3], double ps[3])
{
    double best = INFINITY;
    for (unsigned f = 0; f < h->nplanes; f++) {
        double n[3], d;
        dx_hull_plane(h, f, n, &d);
        if (dot3(n, s0) < d && dot3(n, s1) < d) continue;   // the face looks away
        for (int e = 0; e < 2; e++) {
            const double *q = e ? s1 : s0;
            double c[3], d2 = polygon_closest(h, f, q, c);
            if (d2 < best) {
                best = d2;
                memcpy(ph, c, sizeof c);
                memcpy(ps, q, sizeof c);
            }
        }
        if (dist2(s0, s1) == 0) continue;
        unsigned count;
        const unsigned *idx = dx_hull_polygon(h, f, &count);
        for (unsigned k = 0; k < count; k++) {
            double v0[3], v1[3], pa[3], pb[3];
            dx_hull_vertex(h, idx[k], v0);
            dx_hull_vertex(h, idx[(k + 1) % count], v1);
            segments_closest(v0, v1, s0, s1, pa, pb);
            double d2 = dist2(pa, pb);
            if (d2 < best) {
                best = d2;
                memcpy(ph, pa, sizeof pa);
                memcpy(ps, pb, sizeof pb);
            }
        }
    }
    return best;
}

// The face of h whose outward normal is nearest -n (facing along the
// contact normal n into h, i.e. towards the other geom); its plane.
static unsigned facing_face(const dx_hull *h, const double n[3], double nf[3], double *df,
                            double *cosine)
{
    unsigned best = 0;
    *cosine = -INFINITY;
    *df = 0;   // set by the first face (a hull has one): for the compiler
    for (unsigned f = 0; f < h->nplanes; f++) {
        double m[3], d;
        dx_hull_plane(h, f, m, &d);
        double c = -dot3(m, n);
        if (c > *cosine) {
            *cosine = c;
            best = f;
            memcpy(nf, m, sizeof m);
            *df = d;
        }
    }
    return best;
}

// Clips the segment p0 p1 to the prism over face f's polygon (its side
// planes); 0 if nothing is left.
static int clip_to_face_prism(const dx_hull *h, unsigned f, const double nf[3], double p0[3],
                              double p1[3])
{
    unsigned count;
    const unsigned *idx = dx_hull_polygon(h, f, &count);
    double centre[3] = { 0, 0, 0 };
    for (unsigned k = 0; k < count; k++) {
        double v[3];
        dx_hull_vertex(h, idx[k], v);
        for (int i = 0; i < 3; i++) centre[i] += v[i] / count;
    }
    double t0 = 0, t1 = 1, d[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    for (unsigned k = 0; k < count; k++) {
        double v0[3], v1[3], e[3], s[3];
        dx_hull_vertex(h, idx[k], v0);
        dx_hull_vertex(h, idx[(k + 1) % count], v1);
        for (int i = 0; i < 3; i++) e[i] = v1[i] - v0[i];
        cross3(e, nf, s);
        double off = dot3(s, v0);
        if (dot3(s, centre) > off) {
            for (int i = 0; i < 3; i++) s[i] = -s[i];
            off = -off;
        }
        double sd = dot3(s, d), gap = off - dot3(s, p0);
        if (sd == 0) {
            if (gap < 0) return 0;
        } else if (sd > 0) {
            t1 = fmin(t1, gap / sd);
        } else {
            t0 = fmax(t0, gap / sd);
        }
    }
    if (t0 > t1) return 0;
    double q0[3], q1[3];
    for (int i = 0; i < 3; i++) {
        q0[i] = p0[i] + t0 * d[i];
        q1[i] = p0[i] + t1 * d[i];
    }
    memcpy(p0, q0, sizeof q0);
    memcpy(p1, q1, sizeof q1);
    return 1;
}

// ---- pairs ------------------------------------------------------------------------

// The hull's points below the plane, deepest first, at most max.
int dxCollideConvexPlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    dx_hull h;
    dx_hull_of_geom(&h, o1);
    const dReal *pl = ((const dxPlane *)o2)->p;
    double n[3] = { pl[0], pl[1], pl[2] };
    int max = dx_max_contacts(flags), count = 0;
    for (unsigned v = 0; v < h.npts; v++) {
        double p[3];
        dx_hull_vertex(&h, v, p);
        double depth = pl[3] - dot3(n, p);
        if (depth < 0) continue;
        // Insert deepest first; once max are held, only deeper ones enter.
        int k = count < max ? count++ : max;
        for (; k > 0 && dxContactAt(out, k - 1, skip)->depth < depth; k--)
            if (k < max) *dxContactAt(out, k, skip) = *dxContactAt(out, k - 1, skip);
        if (k < max) put(out, k, skip, p, n, depth, o1, o2);
    }
    return count;
}

// The ball (centre c, radius r) against the hull: normal into the hull.
static int hull_ball(const dx_hull *h, const double c[3], double r, double n[3], double *depth,
                     double pos[3])
{
    double worst = -INFINITY, nf[3];
    for (unsigned f = 0; f < h->nplanes; f++) {
        double m[3], d;
        dx_hull_plane(h, f, m, &d);
        double above = dot3(m, c) - d;
        if (above > worst) {
            worst = above;
            memcpy(nf, m, sizeof m);
        }
    }
    if (worst <= 0) {   // the centre is inside: out through the nearest face
        for (int i = 0; i < 3; i++) {
            n[i] = -nf[i];
            pos[i] = c[i];
        }
        *depth = r - worst;
        return 1;
    }
    double best = INFINITY, q[3];
    for (unsigned f = 0; f < h->nplanes; f++) {
        double m[3], d, p[3];
        dx_hull_plane(h, f, m, &d);
        if (dot3(m, c) - d <= 0) continue;
        double d2 = polygon_closest(h, f, c, p);
        if (d2 < best) {
            best = d2;
            memcpy(q, p, sizeof p);
        }
    }
    double dist = sqrt(best);
    if (!(dist <= r)) return 0;
    for (int i = 0; i < 3; i++) {
        n[i] = q[i] - c[i];
        pos[i] = q[i];
    }
    if (!normalize3(n)) memcpy(n, nf, sizeof nf), n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
    *depth = r - dist;
    return 1;
}

int dxCollideConvexSphere(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    (void)flags;
    dx_hull h;
    dx_hull_of_geom(&h, o1);
    double c[3], n[3], pos[3], depth;
    geom_pos(o2, c);
    if (!hull_ball(&h, c, ((const dxSphere *)o2)->radius, n, &depth, pos)) return 0;
    put(out, 0, skip, pos, n, depth, o1, o2);
    return 1;
}

// The ray's line clipped by the hull's planes; the hit as the other rays
// report it (collide_ray.c): the entry, or the exit with the normal turned
// inward for a ray starting inside.
int dxCollideRayConvex(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    (void)flags;
    dx_hull h;
    dx_hull_of_geom(&h, o2);
    double s[3], dir[3], t_in = -INFINITY, t_out = INFINITY, n_in[3] = { 0 }, n_out[3] = { 0 };
    geom_pos(o1, s);
    geom_axis(o1, 2, dir);
    for (unsigned f = 0; f < h.nplanes; f++) {
        double m[3], d;
        dx_hull_plane(&h, f, m, &d);
        double nd = dot3(m, dir), gap = d - dot3(m, s);
        if (nd == 0) {
            if (gap < 0) return 0;
            continue;
        }
        double t = gap / nd;
        if (nd < 0 && t > t_in) {
            t_in = t;
            memcpy(n_in, m, sizeof m);
        } else if (nd > 0 && t < t_out) {
            t_out = t;
            memcpy(n_out, m, sizeof m);
        }
    }
    if (t_in > t_out) return 0;
    double t, n[3];
    if (t_in >= 0) {
        t = t_in;
        memcpy(n, n_in, sizeof n);
    } else if (t_out >= 0) {
        t = t_out;
        for (int i = 0; i < 3; i++) n[i] = -n_out[i];
    } else {
        return 0;
    }
    if (t > ((const dxRay *)o1)->length) return 0;
    t = t > 0 ? t : 0;
    double pos[3];
    for (int i = 0; i < 3; i++) pos[i] = s[i] + t * dir[i];
    put(out, 0, skip, pos, n, t, o1, o2);
    return 1;
}

// Extra contacts where a hull face rests on a capsule's or cylinder's
// straight side, grown by radius r: the segment p0 p1 (just under that
// side's surface by r) clipped to face f's prism, each end as deep as it is
// under the face plus r. Into pts; returns the count.
typedef struct extra_point {
    double p[3], depth;
} extra_point;

static int segment_on_face(const dx_hull *h, unsigned f, const double nf[3], double df,
                           double p0[3], double p1[3], double r, extra_point *pts)
{
    if (!clip_to_face_prism(h, f, nf, p0, p1)) return 0;
    int n = 0;
    for (int e = 0; e < 2; e++) {
        const double *q = e ? p1 : p0;
        double depth = r - (dot3(nf, q) - df);
        if (depth < 0 || (e == 1 && dist2(p0, p1) == 0)) continue;
        for (int i = 0; i < 3; i++) pts[n].p[i] = q[i] - (r - depth / 2) * nf[i];
        pts[n++].depth = depth;
    }
    return n;
}

// Writes pts (n > 0; the deepest carries at least `depth`, the pair's) as
// the contacts, at most max spread (deepest first, then furthest), or the
// single contact (pos, depth) if n is 0; all with normal nrm. The count.
static int write_points(extra_point *pts, int n, const double pos[3], const double nrm[3],
                        double depth, int max, dxGeom *o1, dxGeom *o2, dContactGeom *out,
                        int skip)
{
    if (n == 0) {
        put(out, 0, skip, pos, nrm, depth, o1, o2);
        return 1;
    }
    int deepest = 0;
    for (int i = 1; i < n; i++)
        if (pts[i].depth > pts[deepest].depth) deepest = i;
    extra_point t = pts[0];
    pts[0] = pts[deepest];
    pts[deepest] = t;
    if (pts[0].depth < depth) pts[0].depth = depth;
    for (int k = 1; k < max && k < n; k++) {   // the furthest from those taken
        int far = k;
        double far_d = -1;
        for (int i = k; i < n; i++) {
            double nearest = INFINITY;
            for (int j = 0; j < k; j++) nearest = fmin(nearest, dist2(pts[i].p, pts[j].p));
            if (nearest > far_d) {
                far_d = nearest;
                far = i;
            }
        }
        t = pts[k];
        pts[k] = pts[far];
        pts[far] = t;
    }
    if (n > max) n = max;
    for (int k = 0; k < n; k++) put(out, k, skip, pts[k].p, nrm, pts[k].depth, o1, o2);
    return n;
}

// The translation of the hull along the unit n that parts it from the
// segment s0 s1 grown by r.
static double segment_depth(const dx_hull *h, const double s0[3], const double s1[3], double r,
                            const double n[3])
{
    double m[3] = { -n[0], -n[1], -n[2] };
    return fmax(dot3(n, s0), dot3(n, s1)) + r + dx_hull_extent(h, m, NULL);
}

int dxCollideConvexCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    dx_hull h;
    dx_hull_of_geom(&h, o1);
    const dxCapsule *cap = (const dxCapsule *)o2;
    double c[3], z[3], s0[3], s1[3], r = cap->radius;
    geom_pos(o2, c);
    geom_axis(o2, 2, z);
    for (int i = 0; i < 3; i++) {
        s0[i] = c[i] - z[i] * cap->length / 2;
        s1[i] = c[i] + z[i] * cap->length / 2;
    }
    double n[3], depth, pos[3], t0 = 0, t1 = 1, d[3] = { s1[0] - s0[0], s1[1] - s0[1], s1[2] - s0[2] };
    if (dx_hull_clip_line(&h, s0, d, 0, &t0, &t1)) {
        // The segment enters the hull: its separating axes (hull faces, and
        // hull edges across the axis).
        depth = INFINITY;
        for (unsigned f = 0; f < h.nplanes; f++) {
            double m[3], off;
            dx_hull_plane(&h, f, m, &off);
            for (int i = 0; i < 3; i++) m[i] = -m[i];
            double s = segment_depth(&h, s0, s1, r, m);
            if (s < depth) {
                depth = s;
                memcpy(n, m, sizeof m);
            }
        }
        for (unsigned f = 0; f < h.nplanes; f++) {
            unsigned count;
            const unsigned *idx = dx_hull_polygon(&h, f, &count);
            for (unsigned k = 0; k < count; k++) {
                double v0[3], v1[3], e[3], m[3];
                dx_hull_vertex(&h, idx[k], v0);
                dx_hull_vertex(&h, idx[(k + 1) % count], v1);
                for (int i = 0; i < 3; i++) e[i] = v1[i] - v0[i];
                cross3(e, z, m);
                if (!normalize3(m)) continue;
                for (int sg = 0; sg < 2; sg++) {
                    if (sg)
                        for (int i = 0; i < 3; i++) m[i] = -m[i];
                    double s = segment_depth(&h, s0, s1, r, m);
                    if (s < depth) {
                        depth = s;
                        memcpy(n, m, sizeof m);
                    }
                }
            }
        }
        // The segment enters the hull, so the depth is at least 0 (a touch
        // may round below). The contact: at the end of the segment's part
        // inside the hull (t0 .. t1; rounding may cross them) deepest along
        // n, half the depth back from the capsule's surface, so midway
        // between the two along n. (The whole segment's deeper end, with the
        // hull's deepest corner, put the contact of a capsule 1e6 long
        // touching a flat hull's edge 250 km from the hull.)
        if (depth < 0) depth = 0;
        double ta = t0, tb = t1, q0[3], q1[3];
        if (ta > tb) ta = tb = (t0 + t1) / 2;
        for (int i = 0; i < 3; i++) {
            q0[i] = s0[i] + ta * d[i];
            q1[i] = s0[i] + tb * d[i];
        }
        const double *sp = dot3(n, q0) > dot3(n, q1) ? q0 : q1;
        for (int i = 0; i < 3; i++) pos[i] = sp[i] + (r - depth / 2) * n[i];
    } else {
        double ph[3], ps[3];
        double dist = sqrt(hull_segment_closest(&h, s0, s1, ph, ps));
        if (!(dist <= r)) return 0;
        for (int i = 0; i < 3; i++) n[i] = ph[i] - ps[i];
        if (!normalize3(n)) return 0;   // touching at distance 0: the other branch's case
        depth = r - dist;
        for (int i = 0; i < 3; i++) pos[i] = ph[i];
    }
    double nf[3], df, cosine;
    unsigned f = facing_face(&h, n, nf, &df, &cosine);
    extra_point pts[2];
    int np = 0;
    if (cosine >= FACE_ALIGNED) np = segment_on_face(&h, f, nf, df, s0, s1, r, pts);
    return write_points(pts, np, pos, n, depth, dx_max_contacts(flags), o1, o2, out, skip);
}

// ---- cylinder ------------------------------------------------------------------------

typedef struct cyl {
    double c[3], z[3], r, hl;
} cyl;

typedef struct hull_cyl {
    const dx_hull *h;
    const cyl *cy;
} hull_cyl;

static double cyl_extent(const cyl *cy, const double m[3])
{
    double mz = dot3(m, cy->z), across = dot3(m, m) - mz * mz;
    return dot3(m, cy->c) + cy->hl * fabs(mz) + cy->r * sqrt(across > 0 ? across : 0);
}

static void cyl_support(const cyl *cy, const double m[3], double out[3])
{
    double mz = dot3(m, cy->z), w[3];
    for (int i = 0; i < 3; i++) {
        out[i] = cy->c[i] + (mz < 0 ? -cy->hl : cy->hl) * cy->z[i];
        w[i] = m[i] - mz * cy->z[i];
    }
    if (!normalize3(w)) return;
    for (int i = 0; i < 3; i++) out[i] += cy->r * w[i];
}

static void mpr_support_hull(const void *shape, const double dir[3], double out[3])
{
    unsigned v;
    dx_hull_extent(shape, dir, &v);
    dx_hull_vertex(shape, v, out);
}

static void mpr_support_cyl(const void *shape, const double dir[3], double out[3])
{
    cyl_support(shape, dir, out);
}

// The mean of the hull's points: a point inside it for MPR.
static void hull_centre(const dx_hull *h, double out[3])
{
    double sum[3] = { 0, 0, 0 };
    for (unsigned v = 0; v < h->npts; v++) {
        double p[3];
        dx_hull_vertex(h, v, p);
        for (int i = 0; i < 3; i++) sum[i] += p[i] / h->npts;
    }
    memcpy(out, sum, sizeof sum);
}

// The translation of the hull along the unit n that parts it from the cylinder.
static double cyl_depth(const hull_cyl *p, const double n[3])
{
    double m[3] = { -n[0], -n[1], -n[2] };
    return cyl_extent(p->cy, n) + dx_hull_extent(p->h, m, NULL);
}

// Considers the direction d (any length) for the least depth: best_n and
// *best keep the least so far.
static void consider(const hull_cyl *p, const double d[3], double best_n[3], double *best)
{
    double n[3] = { d[0], d[1], d[2] };
    if (!normalize3(n)) return;
    double s = cyl_depth(p, n);
    if (s < *best) {
        *best = s;
        memcpy(best_n, n, sizeof n);
    }
}

// The starting directions of the search, with their depths.
enum { MAX_STARTS = 512, SEARCH_STARTS = 6 };
typedef struct starts {
    double n[MAX_STARTS][3], depth[MAX_STARTS];
    int count;
} starts;

static void add_start(const hull_cyl *p, const double d[3], starts *st)
{
    if (st->count == MAX_STARTS) return;
    double depth = INFINITY;
    consider(p, d, st->n[st->count], &depth);
    if (depth < INFINITY) st->depth[st->count++] = depth;
}

// Pattern search for the least depth near n (unit): steps in 12
// directions across it, the pattern turned by 0.7 radians each time (so a
// valley along a crease of the depth is followed whatever its heading),
// the step shrinking by 2 after two failures running, down to 1e-9 radians.
static void refine(const hull_cyl *p, double n[3], double *depth)
{
    double step = 0.05, turn = 0;
    int failed = 0;
    for (int it = 0; it < 600 && step > 1e-9; it++) {
        double u[3], v[3], e[3] = { 0, 0, 0 };
        int k = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0
                : fabs(n[1]) <= fabs(n[2])                        ? 1
                                                                  : 2;
        e[k] = 1;
        cross3(n, e, u);
        normalize3(u);
        cross3(n, u, v);
        double best = *depth, bn[3] = { n[0], n[1], n[2] };
        for (int d = 0; d < 12; d++) {
            double a = turn + d * 0.52359877559829887, m[3];
            for (int i = 0; i < 3; i++) m[i] = n[i] + step * (cos(a) * u[i] + sin(a) * v[i]);
            consider(p, m, bn, &best);
        }
        turn += 0.7;
        if (best < *depth) {
            *depth = best;
            memcpy(n, bn, sizeof bn);
            failed = 0;
        } else if (++failed == 2) {
            step /= 2;
            failed = 0;
        }
    }
}

// The extra contacts of a cylinder resting on face f (normal nf at df):
// its cap's rim points over the face and the face's corners inside the
// cap, or its side line clipped to the face.
static int cylinder_on_face(const dx_hull *h, unsigned f, const double nf[3], double df,
                            const cyl *cy, extra_point *pts)
{
    double cz = dot3(cy->z, nf);
    int n = 0;
    if (fabs(cz) >= 1 - CYL_ALIGNED) {   // a cap: the one against the face
        double capc[3], u[3], v[3], e[3] = { 0, 0, 0 }, zc[3];
        double sg = cz > 0 ? -1 : 1;   // zc: the cap's outward normal, towards the face
        for (int i = 0; i < 3; i++) {
            zc[i] = sg * cy->z[i];
            capc[i] = cy->c[i] + cy->hl * zc[i];
        }
        int k = fabs(zc[0]) <= fabs(zc[1]) && fabs(zc[0]) <= fabs(zc[2]) ? 0
                : fabs(zc[1]) <= fabs(zc[2])                           ? 1
                                                                        : 2;
        e[k] = 1;
        cross3(zc, e, u);
        normalize3(u);
        cross3(zc, u, v);
        for (int j = 0; j < RIM_POINTS; j++) {
            double a = 2 * 3.14159265358979324 * j / RIM_POINTS, q[3], q1[3];
            for (int i = 0; i < 3; i++) q[i] = q1[i] = capc[i] + cy->r * (cos(a) * u[i] + sin(a) * v[i]);
            double depth = df - dot3(nf, q);
            if (depth < 0 || !clip_to_face_prism(h, f, nf, q, q1)) continue;
            for (int i = 0; i < 3; i++) pts[n].p[i] = q[i] + depth / 2 * nf[i];
            pts[n++].depth = depth;
        }
        unsigned count;
        const unsigned *idx = dx_hull_polygon(h, f, &count);
        for (unsigned k2 = 0; k2 < count && n < MAX_EXTRA; k2++) {
            double q[3], rel[3];
            dx_hull_vertex(h, idx[k2], q);
            for (int i = 0; i < 3; i++) rel[i] = q[i] - capc[i];
            double along = dot3(rel, zc), across2 = dot3(rel, rel) - along * along;
            if (along > 0 || along < -2 * cy->hl || across2 > cy->r * cy->r) continue;
            for (int i = 0; i < 3; i++) pts[n].p[i] = q[i] - along / 2 * zc[i];
            pts[n++].depth = -along;
        }
        return n;
    }
    if (fabs(cz) > CYL_ALIGNED) return 0;
    double w[3], p0[3], p1[3];   // the side line nearest the face
    for (int i = 0; i < 3; i++) w[i] = cz * cy->z[i] - nf[i];   // towards the face
    if (!normalize3(w)) return 0;
    for (int i = 0; i < 3; i++) {
        p0[i] = cy->c[i] + cy->r * w[i] - cy->hl * cy->z[i];
        p1[i] = cy->c[i] + cy->r * w[i] + cy->hl * cy->z[i];
    }
    return segment_on_face(h, f, nf, df, p0, p1, 0, pts);
}

int dxCollideConvexCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    dx_hull h;
    dx_hull_of_geom(&h, o1);
    const dxCylinder *cg = (const dxCylinder *)o2;
    cyl cy = { .r = cg->radius, .hl = cg->length / 2 };
    geom_pos(o2, cy.c);
    geom_axis(o2, 2, cy.z);
    dx_mpr_shape mh = { &h, mpr_support_hull, { 0 } }, mc = { &cy, mpr_support_cyl, { 0 } };
    hull_centre(&h, mh.centre);
    memcpy(mc.centre, cy.c, sizeof mc.centre);
    double dir[3];
    const dx_mpr_verdict verdict =
        dx_mpr_penetration(&mh, &mc, 1e-12 * (h.size + cy.r + cy.hl), dir);
    if (verdict == DX_MPR_APART) return 0;
    hull_cyl p = { &h, &cy };
    // Starts: MPR's normal, the axis, the hull's faces, the axis across the
    // hull's edges, and for each hull point the direction to it from the
    // axis (against the side) and from the nearest rim point (against the rim).
    starts st;
    st.count = 0;
    // (Undecided, MPR's normal is no start: the others decide alone, and a
    // negative least depth still means apart.)
    double m[3];
    if (verdict == DX_MPR_OVERLAP) {
        for (int i = 0; i < 3; i++) m[i] = -dir[i];
        add_start(&p, m, &st);
    }
    add_start(&p, cy.z, &st);
    for (int i = 0; i < 3; i++) m[i] = -cy.z[i];
    add_start(&p, m, &st);
    for (unsigned f = 0; f < h.nplanes; f++) {
        double off;
        dx_hull_plane(&h, f, m, &off);
        for (int i = 0; i < 3; i++) m[i] = -m[i];
        add_start(&p, m, &st);
        unsigned count;
        const unsigned *idx = dx_hull_polygon(&h, f, &count);
        for (unsigned k = 0; k < count; k++) {
            double v0[3], v1[3], e[3];
            dx_hull_vertex(&h, idx[k], v0);
            dx_hull_vertex(&h, idx[(k + 1) % count], v1);
            for (int i = 0; i < 3; i++) e[i] = v1[i] - v0[i];
            cross3(e, cy.z, m);
            add_start(&p, m, &st);
            for (int i = 0; i < 3; i++) m[i] = -m[i];
            add_start(&p, m, &st);
            // The axis square to the edge (a rim on the edge), the edge
            // square to the axis (the side along it): both signs.
            double ee = dot3(e, e), ez = dot3(e, cy.z);
            if (!(ee > 0)) continue;
            for (int sg = -1; sg <= 1; sg += 2) {
                for (int i = 0; i < 3; i++) m[i] = sg * (cy.z[i] - ez / ee * e[i]);
                add_start(&p, m, &st);
                for (int i = 0; i < 3; i++) m[i] = sg * (e[i] - ez * cy.z[i]);
                add_start(&p, m, &st);
            }
        }
    }
    for (unsigned v = 0; v < h.npts; v++) {
        double q[3], d[3], w[3];
        dx_hull_vertex(&h, v, q);
        for (int i = 0; i < 3; i++) d[i] = cy.c[i] - q[i];   // from the point into the cylinder
        double along = dot3(d, cy.z);
        for (int i = 0; i < 3; i++) w[i] = along * cy.z[i] - d[i];   // from the axis to q
        add_start(&p, w, &st);
        if (!normalize3(w)) continue;
        double cap = -along < 0 ? -cy.hl : cy.hl;   // q's side of the middle
        for (int i = 0; i < 3; i++) m[i] = q[i] - (cy.c[i] + cap * cy.z[i] + cy.r * w[i]);
        add_start(&p, m, &st);
    }
    // Refine the best few starts at least 10 degrees apart; keep the least.
    double n[3] = { 0, 0, 1 }, depth = INFINITY;
    int chosen[SEARCH_STARTS], nchosen = 0;
    while (nchosen < SEARCH_STARTS) {
        int best = -1;
        for (int k = 0; k < st.count; k++) {
            int near = 0;
            for (int j = 0; j < nchosen && !near; j++) near = dot3(st.n[k], st.n[chosen[j]]) > 0.985;
            if (!near && (best < 0 || st.depth[k] < st.depth[best])) best = k;
        }
        if (best < 0) break;
        chosen[nchosen++] = best;
        double nk[3], dk = st.depth[best];
        memcpy(nk, st.n[best], sizeof nk);
        refine(&p, nk, &dk);
        if (dk < depth) {
            depth = dk;
            memcpy(n, nk, sizeof nk);
        }
    }
    if (depth < 0) return 0;   // a separating direction: MPR let a grazing pair through
    double pa[3], pc[3], pos[3];
    unsigned va;
    for (int i = 0; i < 3; i++) m[i] = -n[i];
    dx_hull_extent(&h, m, &va);
    dx_hull_vertex(&h, va, pa);
    cyl_support(&cy, n, pc);
    for (int i = 0; i < 3; i++) pos[i] = (pa[i] + pc[i]) / 2;
    double nf[3], df, cosine;
    unsigned f = facing_face(&h, n, nf, &df, &cosine);
    extra_point pts[MAX_EXTRA];
    int np = 0;
    if (cosine >= FACE_ALIGNED) np = cylinder_on_face(&h, f, nf, df, &cy, pts);
    return write_points(pts, np, pos, n, depth, dx_max_contacts(flags), o1, o2, out, skip);
}
