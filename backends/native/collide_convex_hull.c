// SPDX-License-Identifier: BSD-3-Clause
//
// collide_convex_hull.c -- convex hulls in the world, and hull against hull
// (the colliders of a convex geom against a convex geom or a box).
// A convex geom's hull is posed once per pose (kept on the geom); a box's
// on each call. The pair test is the separating axis test of
// collide_convex_sat.c. As for box-box (collide_box.c), an edge axis wins
// only if 1.05 times shallower than the best face. A face axis gives the
// contact polygon: the other hull's face most against the reference face,
// clipped to the reference face's side planes, each point below the
// reference face as deep as it is under it, placed in the middle of its
// line along the normal inside both hulls (the deepest carries the exact
// translation along the normal that parts the hulls, as box-box's does).
// An edge axis gives one point between the closest points of the two
// edges. Everything inside is double.

#include "collide_convex.h"
#include "collide_math.h"

#include <math.h>
#include <string.h>

// clip_line_along four planes at a time where the machine has AVX2 (chosen
// when called; -DDX_HULL_NO_AVX2 builds the baseline alone).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__) && !defined(DX_HULL_NO_AVX2)
#define DX_CLIP_AVX2 1
#include <immintrin.h>
#endif


// Polygon buffers: the clipped polygon has at most the incident polygon's
// count plus one per reference edge; larger polygons give one contact.
enum { MAXP = 256, MAXP_INCIDENT = 128 };

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

// What every box made into a hull shares: the faces' polygons (each
// counterclockwise seen from outside) and where they start; the edges, the
// one along axis k from the corner with bit k clear to the one with it set,
// between the faces of the other two axes' bits (i = k + 1, j = k + 2 mod 3:
// faces 2 i + bit i, 2 j + bit j); the edges by first and second face; and
// each face's neighbours (every face but its opposite).
static const unsigned box_polys[30] = { 4, 0, 4, 6, 2, 4, 1, 3, 7, 5, 4, 0, 1, 5, 4,
                                        4, 2, 6, 7, 3, 4, 0, 2, 3, 1, 4, 4, 5, 7, 6 };
static const unsigned box_poly_start[6] = { 0, 5, 10, 15, 20, 25 };
static const dxHullEdge box_edges[12] = {
    { 0, 1, 2, 4 }, { 2, 3, 3, 4 }, { 4, 5, 2, 5 }, { 6, 7, 3, 5 },
    { 0, 2, 4, 0 }, { 4, 6, 5, 0 }, { 1, 3, 4, 1 }, { 5, 7, 5, 1 },
    { 0, 4, 0, 2 }, { 1, 5, 1, 2 }, { 2, 6, 0, 3 }, { 3, 7, 1, 3 },
};
static const uint64_t box_by_f1[6] = { 0x500, 0xa00, 0x5, 0xa, 0x50, 0xa0 };
static const uint64_t box_by_f2[6] = { 0x30, 0xc0, 0x300, 0xc00, 0x3, 0xc };
static const uint64_t box_nbr[6] = { 0x3d, 0x3e, 0x37, 0x3b, 0x1f, 0x2f };
#define BOX_NO_EDGE 0x80, 0x80, 0x80, 0x80
static const uint8_t box_edge_faces[2][32] = {
    { 2, 3, 2, 3, 4, 5, 4, 5, 0, 1, 0, 1, BOX_NO_EDGE, BOX_NO_EDGE, BOX_NO_EDGE, BOX_NO_EDGE,
      BOX_NO_EDGE },
    { 4, 4, 5, 5, 0, 0, 1, 1, 2, 2, 3, 3, BOX_NO_EDGE, BOX_NO_EDGE, BOX_NO_EDGE, BOX_NO_EDGE,
      BOX_NO_EDGE },
};
#undef BOX_NO_EDGE

// A box as a hull in bx: corners by bits (x, y, z), faces -x +x -y +y -z +z.
static void box_hull(dx_hull *h, const dxBox *box, dx_hull_box *bx)
{
    const dReal *side = box->side;
    for (unsigned v = 0; v < 8; v++)
        for (int i = 0; i < 3; i++) bx->pts[3 * v + i] = (v >> i & 1 ? 1 : -1) * side[i] / 2;
    for (int f = 0; f < 6; f++) {
        int axis = f / 2;
        dReal sg = f & 1 ? 1 : -1;
        for (int i = 0; i < 3; i++) bx->planes[4 * f + i] = i == axis ? sg : 0;
        bx->planes[4 * f + 3] = side[axis] / 2;
    }
    h->by_f1 = box_by_f1;
    h->by_f2 = box_by_f2;
    h->lone = 0;
    h->nbr = box_nbr;
    h->edge_faces = box_edge_faces;
    h->pts = bx->pts;
    h->planes = bx->planes;
    h->polys = box_polys;
    h->poly_start = box_poly_start;
    h->edges = box_edges;
    h->vert_start = h->vert_edges = NULL;
    h->npts = 8;
    h->nplanes = 6;
    h->nedges = 12;
    h->convex = NULL;
    const dReal *p = bx->pts;   // every corner is as far from the centre
    h->size = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
    dxHullPoseBounds(h);
    dxHullPosePointsPlanes(h->R, h->c, bx->pts, 8, bx->planes, NULL, 6, bx->wp,
                           (double *const[3]){ bx->p_soa[0], bx->p_soa[1], bx->p_soa[2] }, bx->wn,
                           (double *const[3]){ bx->n_soa[0], bx->n_soa[1], bx->n_soa[2] }, bx->wd);
    h->px = bx->p_soa[0];
    h->py = bx->p_soa[1];
    h->pz = bx->p_soa[2];
    h->nx = bx->n_soa[0];
    h->ny = bx->n_soa[1];
    h->nz = bx->n_soa[2];
    h->ex = bx->e_soa[0];
    h->ey = bx->e_soa[1];
    h->ez = bx->e_soa[2];
    memcpy(h->centre, h->c, sizeof h->centre);
    h->wp = (const double (*)[3])bx->wp;
    h->wn = (const double (*)[3])bx->wn;
    h->wd = bx->wd;
    h->we = bx->we;
    h->face_low = bx->face_low;
    h->plane_dev = NULL;
    bx->edges_posed = 0;

    h->edges_posed = &bx->edges_posed;
}

void dx_hull_of_geom(dx_hull *h, const dxGeom *g)
{
    *h = *dx_hull_posed(g);
}

// Boxes made into hulls, kept (a few per thread) with what they were made
// from: a box hull is a function of the box's position, rotation and sides
// alone, so a box met again with the same bits (the static boxes a scene's
// hulls rest on, met by many hulls a step) is not made again, and keeps the
// edges and floors a test posed. The geom is only the entry looked at
// first: its address may be reused, the bits decide.
enum { BOX_MEMOS = 4, BOX_KEY = 3 + 9 + 3 };
typedef struct box_memo {
    const dxGeom *g;
    dReal key[BOX_KEY];   // pos, R's nine entries (not its padding), sides
    dx_hull h;
    dx_hull_box bx;
} box_memo;
static _Thread_local box_memo box_memos[BOX_MEMOS];
static _Thread_local unsigned box_memo_next;

// The box geom g as a hull: its kept one if made from the same bits.
static dx_hull *box_posed(const dxGeom *g)
{
    dReal key[BOX_KEY];
    memcpy(key, g->pos, 3 * sizeof(dReal));
    for (int i = 0; i < 3; i++) memcpy(key + 3 + 3 * i, g->R + 4 * i, 3 * sizeof(dReal));
    memcpy(key + 12, ((const dxBox *)g)->side, 3 * sizeof(dReal));
    box_memo *m = NULL;
    for (int k = 0; k < BOX_MEMOS && !m; k++)
        if (box_memos[k].g == g) m = &box_memos[k];
    if (m && memcmp(m->key, key, sizeof key) == 0) return &m->h;
    if (!m) {
        m = &box_memos[box_memo_next];
        box_memo_next = (box_memo_next + 1) % BOX_MEMOS;
        m->g = g;
    }
    memcpy(m->key, key, sizeof key);
    dx_hull *h = &m->h;
    for (int i = 0; i < 3; i++) {
        h->c[i] = g->pos[i];
        for (int k = 0; k < 3; k++) h->R[3 * i + k] = g->R[4 * i + k];
    }
    box_hull(h, (const dxBox *)g, &m->bx);
    return h;
}

dx_hull *dx_hull_posed(const dxGeom *g)
{
    if (g->ops->cls == dConvexClass) {
        dxConvex *c = (dxConvex *)g;   // its kept pose changes, the geom does not
        dxConvexPoseIfMoved(c);
        return &c->hull;
    }
    return box_posed(g);
}

// Narrows [t0, t1] to where the line o + t d is inside one plane, given
// nd = n . d and gap = off - n . o (|d| = dl); 0 when a plane parallel to the
// line has it outside by more than tol.
static inline int narrow_to_plane(double nd, double gap, double dl, double tol, double *t0,
                                  double *t1)
{
    if (fabs(nd) <= DX_HULL_EPS * dl) return !(gap < -tol);
    double t = gap / nd;
    if (nd > 0) {
        if (t < *t1) *t1 = t;
    } else if (t > *t0) {
        *t0 = t;
    }
    return 1;
}

int dx_hull_clip_line(const dx_hull *h, const double o[3], const double d[3], double tol,
                      double *t0, double *t1)
{
    double dl = sqrt(dot3(d, d));
    for (unsigned f = 0; f < h->nplanes; f++) {
        double n[3], off;
        dx_hull_plane(h, f, n, &off);
        double nd = dot3(n, d), gap = off - dot3(n, o);   // n . (o + t d) <= off
        if (!narrow_to_plane(nd, gap, dl, tol, t0, t1)) return 0;
    }
    return *t0 <= *t1 + tol / dl;
}

// ---- contact points --------------------------------------------------------------

typedef struct hull_point {
    double p[3], depth;
} hull_point;

// The lines along one direction d, clipped to a hull many times (each
// point of a face contact): each plane's n . d, made once (dx_hull_clip_line
// makes the same numbers per call), for hulls of at most LINE_PLANES planes.
enum { LINE_PLANES = 64 };
typedef struct line_planes {
    double nd[LINE_PLANES], dl;
    int avx2;   // clip four planes at a time
} line_planes;

#ifdef DX_CLIP_AVX2
// m . n for h's plane normals n, four planes at a time from the first (as
// dot3 makes each), into out; returns how many it made.
__attribute__((target("avx2"))) static inline unsigned normal_products4(const dx_hull *h,
                                                                        const double m[3],
                                                                        double *out)
{
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    unsigned f = 0;
    for (; f + 4 <= h->nplanes; f += 4)
        _mm256_storeu_pd(out + f,
                         _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(h->nx + f), m0),
                                                     _mm256_mul_pd(_mm256_loadu_pd(h->ny + f), m1)),
                                       _mm256_mul_pd(_mm256_loadu_pd(h->nz + f), m2)));
    return f;
}

// normal_products4 over h's planes' count rounded up to a multiple of four
// (the rows are zero past the planes, and so are the products there).
__attribute__((target("avx2"))) static inline unsigned normal_products_padded4(const dx_hull *h,
                                                                               const double m[3],
                                                                               double *out)
{
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    unsigned f = 0;
    for (; f < h->nplanes; f += 4)
        _mm256_storeu_pd(out + f,
                         _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(h->nx + f), m0),
                                                     _mm256_mul_pd(_mm256_loadu_pd(h->ny + f), m1)),
                                       _mm256_mul_pd(_mm256_loadu_pd(h->nz + f), m2)));
    return f;
}
#endif

// line_planes for h along d; with AVX2 (avx2 1, in a function built for
// it) the products four at a time and the clipping too.
static inline __attribute__((always_inline)) int line_planes_with(const dx_hull *h,
                                                                  const double d[3],
                                                                  line_planes *lp, int avx2)
{
    if (h->nplanes > LINE_PLANES) return 0;
    lp->dl = sqrt(dot3(d, d));
    unsigned f = 0;
#ifdef DX_CLIP_AVX2
    if (avx2) f = normal_products_padded4(h, d, lp->nd);
#endif
    for (; f < h->nplanes; f++) lp->nd[f] = dot3(h->wn[f], d);
    lp->avx2 = avx2;
    return 1;
}

// narrow_to_plane over h's planes from f on, in order.
static int narrow_from(const dx_hull *h, const line_planes *lp, unsigned f, const double o[3],
                       double tol, double *t0, double *t1)
{
    for (; f < h->nplanes; f++) {
        double nd = lp->nd[f], gap = h->wd[f] - dot3(h->wn[f], o);
        if (!narrow_to_plane(nd, gap, lp->dl, tol, t0, t1)) return 0;
    }
    return 1;
}

#ifdef DX_CLIP_AVX2
// The zero a bound narrowed to a zero ends as: from, if that is a zero
// (a later equal t does not replace it), else the first t (of n) that is
// a zero among those whose mask (all bits set) says it narrows the bound.
static double first_zero(const double *ts, const double *mask, unsigned n, double from)
{
    if (from == 0) return from;
    unsigned f = 0;
    while (f < n && !(ts[f] == 0 && mask[f] != 0)) f++;   // a set mask is a NaN, != 0
    return ts[f];
}

// narrow_from(h, lp, 0, ...) four planes at a time: each lane keeps the
// least exit (largest entry) of its planes as narrow_to_plane does (t
// first: a NaN is passed over, and of equal values the earlier stays),
// then the least (largest) of the lanes: the same numbers, but for which
// of +0 and -0 wins a tie, so a result of zero is taken as narrow_from
// would take it: the bound it started from if that is a zero, else the
// first plane's zero (each plane's t and side are kept for that). Returns
// how many planes it went over (the rest are left to narrow_from), or -1
// if a plane along the line has it outside by more than tol.
__attribute__((target("avx2"))) static int narrow4(const dx_hull *h, const line_planes *lp,
                                                   const double o[3], double tol, double *t0,
                                                   double *t1)
{
    const __m256d sign = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd();
    __m256d o0 = _mm256_set1_pd(o[0]), o1 = _mm256_set1_pd(o[1]), o2 = _mm256_set1_pd(o[2]);
    __m256d par_lim = _mm256_set1_pd(DX_HULL_EPS * lp->dl), low = _mm256_set1_pd(-tol);
    __m256d lo = _mm256_set1_pd(*t0), hi = _mm256_set1_pd(*t1), out = zero;
    double ts[LINE_PLANES], ups[LINE_PLANES], downs[LINE_PLANES];   // t, and which bound it narrows
    unsigned f = 0;
    for (; f + 4 <= h->nplanes; f += 4) {
        __m256d nd = _mm256_loadu_pd(lp->nd + f);
        __m256d no = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(h->nx + f), o0),
                                                 _mm256_mul_pd(_mm256_loadu_pd(h->ny + f), o1)),
                                   _mm256_mul_pd(_mm256_loadu_pd(h->nz + f), o2));
        __m256d gap = _mm256_sub_pd(_mm256_loadu_pd(h->wd + f), no);
        __m256d par = _mm256_cmp_pd(_mm256_andnot_pd(sign, nd), par_lim, _CMP_LE_OQ);
        out = _mm256_or_pd(out, _mm256_and_pd(par, _mm256_cmp_pd(gap, low, _CMP_LT_OQ)));
        __m256d t = _mm256_div_pd(gap, nd);
        __m256d up = _mm256_andnot_pd(par, _mm256_cmp_pd(nd, zero, _CMP_GT_OQ));
        __m256d down = _mm256_andnot_pd(par, _mm256_cmp_pd(nd, zero, _CMP_NGT_UQ));
        hi = _mm256_blendv_pd(hi, _mm256_min_pd(t, hi), up);
        lo = _mm256_blendv_pd(lo, _mm256_max_pd(t, lo), down);
        _mm256_storeu_pd(ts + f, t);
        _mm256_storeu_pd(ups + f, up);
        _mm256_storeu_pd(downs + f, down);
    }
    if (_mm256_movemask_pd(out)) return -1;
    lo = _mm256_max_pd(lo, _mm256_permute2f128_pd(lo, lo, 1));
    hi = _mm256_min_pd(hi, _mm256_permute2f128_pd(hi, hi, 1));
    double a = _mm256_cvtsd_f64(_mm256_max_pd(lo, _mm256_permute_pd(lo, 1)));
    double b = _mm256_cvtsd_f64(_mm256_min_pd(hi, _mm256_permute_pd(hi, 1)));
    if (a == 0) a = first_zero(ts, downs, f, *t0);
    if (b == 0) b = first_zero(ts, ups, f, *t1);
    *t0 = a;
    *t1 = b;
    return (int)f;
}
#endif

// dx_hull_clip_line for the line o + t d whose planes' products lp holds.
static int clip_line_along(const dx_hull *h, const line_planes *lp, const double o[3],
                           double tol, double *t0, double *t1)
{
    unsigned f = 0;
#ifdef DX_CLIP_AVX2
    if (lp->avx2) {
        int done = narrow4(h, lp, o, tol, t0, t1);
        if (done < 0) return 0;
        f = (unsigned)done;
    }
#endif
    if (!narrow_from(h, lp, f, o, tol, t0, t1)) return 0;
    return *t0 <= *t1 + tol / lp->dl;
}

// middle_inside with both hulls' plane products along n made (la for a,
// lb for b).
static int middle_inside_along(const dx_hull *a, const line_planes *la, const dx_hull *b,
                               const line_planes *lb, const double q[3], const double n[3],
                               double t0, double t1, double pos[3])
{
    double tol = DX_HULL_EPS * (a->size + b->size);
    if (!clip_line_along(a, la, q, tol, &t0, &t1) || !clip_line_along(b, lb, q, tol, &t0, &t1))
        return 0;
    double t = (t0 + t1) / 2;
    for (int i = 0; i < 3; i++) pos[i] = q[i] + t * n[i];
    return 1;
}

// pos: the middle of the part of the line q + t n, t0 <= t <= t1, inside
// both hulls; 0 if there is none.
static int middle_inside(const dx_hull *a, const dx_hull *b, const double q[3], const double n[3],
                         double t0, double t1, double pos[3])
{
    line_planes la, lb;
#ifdef DX_CLIP_AVX2
    int avx2 = __builtin_cpu_supports("avx2");
#else
    int avx2 = 0;
#endif
    if (line_planes_with(a, n, &la, avx2) && line_planes_with(b, n, &lb, avx2))
        return middle_inside_along(a, &la, b, &lb, q, n, t0, t1, pos);
    double tol = DX_HULL_EPS * (a->size + b->size);
    if (!dx_hull_clip_line(a, q, n, tol, &t0, &t1) || !dx_hull_clip_line(b, q, n, tol, &t0, &t1))
        return 0;
    double t = (t0 + t1) / 2;
    for (int i = 0; i < 3; i++) pos[i] = q[i] + t * n[i];
    return 1;
}

// plane_sides for poly's points from i on.
static int plane_sides_from(const hull_point *poly, int i, int n, const double s[3], double off,
                            double *side)
{
    int inside = 1;
    for (; i < n; i++) {
        side[i] = dot3(s, poly[i].p) - off;
        inside &= side[i] <= 0;
    }
    return inside;
}

#ifdef DX_CLIP_AVX2
_Static_assert(sizeof(hull_point) == 4 * sizeof(double), "a hull point is four doubles");
// plane_sides' first points four at a time (their coordinates gathered by
// a 4 x 4 transpose: the same products and sums); returns how many it
// measured, *inside cleared if one of them is not inside.
__attribute__((target("avx2"))) static inline int plane_sides4(const hull_point *poly, int n,
                                                               const double s[3], double off,
                                                               double *side, int *inside)
{
    __m256d s0 = _mm256_set1_pd(s[0]), s1 = _mm256_set1_pd(s[1]), s2 = _mm256_set1_pd(s[2]);
    __m256d vo = _mm256_set1_pd(off), zero = _mm256_setzero_pd();
    int i = 0, out = 0;
    for (; i + 4 <= n; i += 4) {
        __m256d p0 = _mm256_loadu_pd(poly[i].p), p1 = _mm256_loadu_pd(poly[i + 1].p);
        __m256d p2 = _mm256_loadu_pd(poly[i + 2].p), p3 = _mm256_loadu_pd(poly[i + 3].p);
        __m256d t0 = _mm256_unpacklo_pd(p0, p1), t1 = _mm256_unpackhi_pd(p0, p1);   // x z, y -
        __m256d t2 = _mm256_unpacklo_pd(p2, p3), t3 = _mm256_unpackhi_pd(p2, p3);
        __m256d x = _mm256_permute2f128_pd(t0, t2, 0x20), z = _mm256_permute2f128_pd(t0, t2, 0x31);
        __m256d y = _mm256_permute2f128_pd(t1, t3, 0x20);
        __m256d d = _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(s0, x), _mm256_mul_pd(s1, y)),
                                                _mm256_mul_pd(s2, z)),
                                  vo);
        _mm256_storeu_pd(side + i, d);
        out |= _mm256_movemask_pd(_mm256_cmp_pd(d, zero, _CMP_NLE_UQ));
    }
    *inside = !out;
    return i;
}
#endif

// The sides of poly's n points against the plane s . x = off (s . x - off)
// into side; 1 if every point is inside (not above 0), where clipping
// keeps poly as it is. With AVX2 (avx2 1) four points at a time.
static inline __attribute__((always_inline)) int plane_sides(const hull_point *poly, int n,
                                                             const double s[3], double off,
                                                             double *side, int avx2)
{
    int i = 0, inside = 1;
#ifdef DX_CLIP_AVX2
    if (avx2) i = plane_sides4(poly, n, s, off, side, &inside);
#else
    (void)avx2;
#endif
    return plane_sides_from(poly, i, n, s, off, side) & inside;
}

// Whether the edge between points on sides dp and dq crosses the plane.
static inline int crosses(double dp, double dq)
{
    return (dp < 0 && dq > 0) || (dp > 0 && dq < 0);
}

// The point where the edge p -> q (sides dp, dq) crosses the plane, into o.
static inline __attribute__((always_inline)) void crossing(const hull_point *p, const hull_point *q,
                                                           double dp, double dq, hull_point *o)
{
    double f = dp / (dp - dq);
    for (int k = 0; k < 3; k++) o->p[k] = p->p[k] + f * (q->p[k] - p->p[k]);
}

// Keeps the part of poly (n points, on the sides plane_sides gives) with
// s . x <= off in out, checking out's room at every point; the new count.
static int clip_plane_bounded(const hull_point *poly, int n, const double *side, hull_point *out)
{
    int m = 0;
    for (int i = 0; i < n && m < MAXP; i++) {
        int j = i + 1 < n ? i + 1 : 0;
        const hull_point *p = &poly[i], *q = &poly[j];
        double dp = side[i], dq = side[j];
        if (dp <= 0) out[m++] = *p;
        if (m < MAXP && crosses(dp, dq)) crossing(p, q, dp, dq, &out[m++]);
    }
    return m;
}

// One edge p -> q (sides dp, dq) of clip_plane into out from m: p if it is
// inside, then the crossing if the edge crosses the plane; the new count.
static inline __attribute__((always_inline)) int clip_edge(const hull_point *p, const hull_point *q,
                                                           double dp, double dq, hull_point *out,
                                                           int m)
{
    if (dp <= 0) out[m++] = *p;
    if (crosses(dp, dq)) crossing(p, q, dp, dq, &out[m++]);
    return m;
}

// Keeps the part of poly (n > 0 points, on the sides plane_sides gives)
// with s . x <= off in out; the new count. An edge adds at most two points,
// so with 2n <= MAXP out has room for all of them and the edges go without
// room checks, the closing edge (back to point 0) after the loop. Inlined
// into face_points (its call alone cost about 11 K instructions a step).
static inline __attribute__((always_inline)) int clip_plane(const hull_point *poly, int n,
                                                            const double *side, hull_point *out)
{
    if (2 * n > MAXP) return clip_plane_bounded(poly, n, side, out);
    int m = 0;
    for (int i = 0; i + 1 < n; i++)
        m = clip_edge(&poly[i], &poly[i + 1], side[i], side[i + 1], out, m);
    return clip_edge(&poly[n - 1], &poly[0], side[n - 1], side[0], out, m);
}

// The index of the point of pts (n) furthest, across the normal nf, from
// the nearest of the first k.
static int furthest_from_taken(const hull_point *pts, int n, int k, const double nf[3])
{
    int best = k;
    double best_d = -1;
    for (int i = k; i < n; i++) {
        double nearest = INFINITY;
        for (int j = 0; j < k; j++) {
            double d[3];
            for (int q = 0; q < 3; q++) d[q] = pts[i].p[q] - pts[j].p[q];
            double along = dot3(d, nf), d2 = dot3(d, d) - along * along;
            if (d2 < nearest) nearest = d2;
        }
        if (nearest > best_d) {
            best_d = nearest;
            best = i;
        }
    }
    return best;
}

// The first of inc's faces whose normal is most against nf (least n . nf,
// made as dot3 makes it; face 0 if none is below infinity).
static unsigned incident_face_from(const dx_hull *inc, const double nf[3], unsigned g,
                                   double lowest, unsigned best)
{
    for (; g < inc->nplanes; g++) {
        double c = dot3(inc->wn[g], nf);
        if (c < lowest) {
            lowest = c;
            best = g;
        }
    }
    return best;
}

#ifdef DX_CLIP_AVX2
// incident_face four faces at a time: the least product, then the first
// face that gives it (the same face).
__attribute__((target("avx2"))) static inline unsigned incident_face4(const dx_hull *inc,
                                                                      const double nf[3])
{
    double prod[LINE_PLANES];
    unsigned g = normal_products4(inc, nf, prod);
    __m256d vmin = _mm256_set1_pd(INFINITY);
    for (unsigned k = 0; k + 4 <= g; k += 4)
        vmin = _mm256_min_pd(_mm256_loadu_pd(prod + k), vmin);   // a NaN is passed over
    vmin = _mm256_min_pd(vmin, _mm256_permute2f128_pd(vmin, vmin, 1));
    double lowest = _mm256_cvtsd_f64(_mm256_min_pd(vmin, _mm256_permute_pd(vmin, 1)));
    unsigned best = 0;
    if (lowest < INFINITY) {   // the first of the fours' faces with it
        __m256d lv = _mm256_set1_pd(lowest);
        for (unsigned k = 0;; k += 4) {
            int eq = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(prod + k), lv, _CMP_EQ_OQ));
            if (eq) {
                best = k + (unsigned)__builtin_ctz((unsigned)eq);
                break;
            }
        }
    }
    return incident_face_from(inc, nf, g, lowest, best);
}
#endif

// The incident face of a face contact: inc's face most against the
// reference face's normal nf; with AVX2 (avx2 1) for hulls of at most
// LINE_PLANES planes four at a time.
static inline __attribute__((always_inline)) unsigned incident_face(const dx_hull *inc,
                                                                    const double nf[3], int avx2)
{
#ifdef DX_CLIP_AVX2
    if (avx2 && inc->nplanes <= LINE_PLANES) return incident_face4(inc, nf);
#else
    (void)avx2;
#endif
    return incident_face_from(inc, nf, 0, INFINITY, 0);
}

// Keeps a face contact's point p (of depth depth, the middle of its line
// inside both hulls at pos) in pts, after the kept ones; *deepest: the
// first of the deepest.
static inline void keep_point(hull_point *pts, int *kept, int *deepest, const double pos[3],
                              double depth)
{
    if (*kept == 0 || depth > pts[*deepest].depth) *deepest = *kept;
    hull_point *q = &pts[(*kept)++];
    memcpy(q->p, pos, sizeof q->p);
    q->depth = depth;
}

#ifdef DX_CLIP_AVX2
// h's planes (at least one, at most LINE_PLANES) by how they narrow a line along lp's
// direction, as narrow_to_plane takes them: along it (|n . d| not above
// its limit), its exit (n . d > 0), or its entry (the rest, a NaN too).
typedef struct plane_kinds {
    uint64_t along, exits, entries;
} plane_kinds;

__attribute__((target("avx2"))) static inline plane_kinds kinds_of_planes(const dx_hull *h,
                                                                         const line_planes *lp)
{
    const __m256d sign = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd();
    const __m256d lim = _mm256_set1_pd(DX_HULL_EPS * lp->dl);
    uint64_t along = 0, up = 0;
    for (unsigned f = 0; f < h->nplanes; f += 4) {   // lp->nd padded (line_planes_with)
        __m256d nd = _mm256_loadu_pd(lp->nd + f);
        along |= (uint64_t)_mm256_movemask_pd(
                     _mm256_cmp_pd(_mm256_andnot_pd(sign, nd), lim, _CMP_LE_OQ))
                 << f;
        up |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(nd, zero, _CMP_GT_OQ)) << f;
    }
    uint64_t all = ((uint64_t)2 << (h->nplanes - 1)) - 1;   // a face contact's hulls have planes
    along &= all;
    plane_kinds k = { along, up & ~along, all & ~along & ~up };   // no padded plane is up
    return k;
}

// wd - n . x of h's plane f for four points, one a lane.
__attribute__((target("avx2"))) static inline __m256d gap_lanes(const dx_hull *h, unsigned f,
                                                                __m256d x, __m256d y, __m256d z)
{
    __m256d no = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(h->nx[f]), x),
                                             _mm256_mul_pd(_mm256_set1_pd(h->ny[f]), y)),
                               _mm256_mul_pd(_mm256_set1_pd(h->nz[f]), z));
    return _mm256_sub_pd(_mm256_set1_pd(h->wd[f]), no);
}

// narrow_from(h, lp, 0, ...) for four lines at once, one a lane (their
// points' x, y, z; the same direction; kinds: h's planes by kind): the
// planes of each kind in order, with the same products, sums and
// quotients, each lane's exit kept where less (the earlier of equal values
// stays, a NaN is passed over: min(t, hi) is t < hi ? t : hi) and its
// entry where larger, so each lane ends with the numbers narrow_from gives
// its line alone (exits and entries narrow apart). Lanes that a plane
// along the lines has outside by more than tol are set in *bad.
__attribute__((target("avx2"))) static inline void
narrow_lanes(const dx_hull *h, const line_planes *lp, const plane_kinds *kinds, __m256d x,
             __m256d y, __m256d z, double tol, __m256d *lo, __m256d *hi, __m256d *bad)
{
    const __m256d low = _mm256_set1_pd(-tol);
    for (uint64_t m = kinds->along; m; m &= m - 1)
        *bad = _mm256_or_pd(*bad, _mm256_cmp_pd(gap_lanes(h, (unsigned)__builtin_ctzll(m), x, y, z),
                                                low, _CMP_LT_OQ));
    for (uint64_t m = kinds->exits; m; m &= m - 1) {
        unsigned f = (unsigned)__builtin_ctzll(m);
        *hi = _mm256_min_pd(_mm256_div_pd(gap_lanes(h, f, x, y, z), _mm256_set1_pd(lp->nd[f])), *hi);
    }
    for (uint64_t m = kinds->entries; m; m &= m - 1) {
        unsigned f = (unsigned)__builtin_ctzll(m);
        *lo = _mm256_max_pd(_mm256_div_pd(gap_lanes(h, f, x, y, z), _mm256_set1_pd(lp->nd[f])), *lo);
    }
}

// The kept points of a face contact (face_points_with's last loop) four
// lines at a time: the points of poly (n) not above the reference face
// (depth df - nf . p not below 0) whose line p + t nf has a part inside r
// and inc (their planes' products with nf in lr, li), at the middle of
// that part, into pts in poly's order (middle_inside_along's numbers);
// returns how many, *deepest the first of the deepest.
__attribute__((target("avx2"))) static int kept_points4(const dx_hull *r, const line_planes *lr,
                                                        const dx_hull *inc, const line_planes *li,
                                                        const hull_point *poly, int n,
                                                        const double nf[3], double df,
                                                        hull_point *pts, int *deepest)
{
    const hull_point *below[MAXP + 3];
    double depth[MAXP];
    int nb = 0, kept = 0;
    for (int k = 0; k < n; k++) {
        double d = df - dot3(nf, poly[k].p);
        if (d < 0) continue;
        depth[nb] = d;
        below[nb++] = &poly[k];
    }
    double tol = DX_HULL_EPS * (r->size + inc->size);
    const __m256d reach_r = _mm256_set1_pd(tol / lr->dl), reach_i = _mm256_set1_pd(tol / li->dl);
    if (nb) below[nb] = below[nb + 1] = below[nb + 2] = below[nb - 1];   // the last four padded
    plane_kinds kr = kinds_of_planes(r, lr), ki = kinds_of_planes(inc, li);
    for (int k = 0; k < nb; k += 4) {
        __m256d p0 = _mm256_loadu_pd(below[k]->p), p1 = _mm256_loadu_pd(below[k + 1]->p);
        __m256d p2 = _mm256_loadu_pd(below[k + 2]->p), p3 = _mm256_loadu_pd(below[k + 3]->p);
        __m256d t0 = _mm256_unpacklo_pd(p0, p1), t1 = _mm256_unpackhi_pd(p0, p1);   // x z, y -
        __m256d t2 = _mm256_unpacklo_pd(p2, p3), t3 = _mm256_unpackhi_pd(p2, p3);
        __m256d x = _mm256_permute2f128_pd(t0, t2, 0x20), z = _mm256_permute2f128_pd(t0, t2, 0x31);
        __m256d y = _mm256_permute2f128_pd(t1, t3, 0x20);
        __m256d lo = _mm256_set1_pd(-INFINITY), hi = _mm256_set1_pd(INFINITY);
        __m256d bad = _mm256_setzero_pd();
        narrow_lanes(r, lr, &kr, x, y, z, tol, &lo, &hi, &bad);
        bad = _mm256_or_pd(bad, _mm256_cmp_pd(lo, _mm256_add_pd(hi, reach_r), _CMP_NLE_UQ));
        narrow_lanes(inc, li, &ki, x, y, z, tol, &lo, &hi, &bad);
        bad = _mm256_or_pd(bad, _mm256_cmp_pd(lo, _mm256_add_pd(hi, reach_i), _CMP_NLE_UQ));
        int ok = ~_mm256_movemask_pd(bad);
        double los[4], his[4];
        _mm256_storeu_pd(los, lo);
        _mm256_storeu_pd(his, hi);
        for (int q = 0; q < 4 && k + q < nb; q++) {
            if (!(ok >> q & 1)) continue;
            double t = (los[q] + his[q]) / 2, pos[3];
            for (int i = 0; i < 3; i++) pos[i] = below[k + q]->p[i] + t * nf[i];
            keep_point(pts, &kept, deepest, pos, depth[k + q]);
        }
    }
    return kept;
}
#endif

// The face contacts: the reference hull r's face f (outward unit nf at
// offset df, facing the incident hull i). Writes the points, deepest first,
// at most max (spread), into pts; returns the count (0 if none was found).
static inline __attribute__((always_inline)) int
face_points_with(const dx_hull *r, unsigned f, const double nf[3], double df, const dx_hull *inc,
                 int max, hull_point *pts, int avx2)
{
    unsigned best = incident_face(inc, nf, avx2), count;
    const unsigned *idx = dx_hull_polygon(inc, best, &count);
    if (count > MAXP_INCIDENT) return 0;
    hull_point buf[2][MAXP];
    int cur = 0, n = (int)count;
    for (int k = 0; k < n; k++) dx_hull_vertex(inc, idx[k], buf[0][k].p);
    // The side planes of the reference polygon, oriented away from its centre.
    const unsigned *ref = dx_hull_polygon(r, f, &count);
    double centre[3] = { 0, 0, 0 };
    for (unsigned k = 0; k < count; k++) {
        double v[3];
        dx_hull_vertex(r, ref[k], v);
        for (int q = 0; q < 3; q++) centre[q] += v[q] / count;
    }
    for (unsigned k = 0; k < count && n > 0; k++) {
        double v0[3], v1[3], e[3], s[3];
        dx_hull_vertex(r, ref[k], v0);
        dx_hull_vertex(r, ref[(k + 1) % count], v1);
        for (int q = 0; q < 3; q++) e[q] = v1[q] - v0[q];
        cross3(e, nf, s);
        double off = dot3(s, v0);
        if (dot3(s, centre) > off) {
            for (int q = 0; q < 3; q++) s[q] = -s[q];
            off = -off;
        }
        double side[MAXP];
        if (plane_sides(buf[cur], n, s, off, side, avx2)) continue;
        n = clip_plane(buf[cur], n, side, buf[cur ^ 1]);
        cur ^= 1;
    }
    // Points below the reference face, lying inside both hulls along nf.
    int kept = 0, deepest = 0;
    line_planes lr, li;
    int along = line_planes_with(r, nf, &lr, avx2) && line_planes_with(inc, nf, &li, avx2);
#ifdef DX_CLIP_AVX2
    if (along && avx2)
        kept = kept_points4(r, &lr, inc, &li, buf[cur], n, nf, df, pts, &deepest);
    else
#endif
        for (int k = 0; k < n; k++) {
            const hull_point *p = &buf[cur][k];
            double depth = df - dot3(nf, p->p), pos[3];
            if (depth < 0) continue;
            if (along ? !middle_inside_along(r, &lr, inc, &li, p->p, nf, -INFINITY, INFINITY, pos)
                      : !middle_inside(r, inc, p->p, nf, -INFINITY, INFINITY, pos))
                continue;
            keep_point(pts, &kept, &deepest, pos, depth);
        }
    if (kept == 0) return 0;
    hull_point t = pts[0];
    pts[0] = pts[deepest];
    pts[deepest] = t;
    if (kept > max) {
        for (int k = 1; k < max; k++) {
            int far = furthest_from_taken(pts, kept, k, nf);
            t = pts[k];
            pts[k] = pts[far];
            pts[far] = t;
        }
        kept = max;
    }
    return kept;
}

#ifdef DX_CLIP_AVX2
__attribute__((target("avx2"))) static int face_points_avx2(const dx_hull *r, unsigned f,
                                                            const double nf[3], double df,
                                                            const dx_hull *inc, int max,
                                                            hull_point *pts)
{
    return face_points_with(r, f, nf, df, inc, max, pts, 1);
}
#endif

// face_points_with, with AVX2 where the machine has it (chosen when called).
static int face_points(const dx_hull *r, unsigned f, const double nf[3], double df,
                       const dx_hull *inc, int max, hull_point *pts)
{
#ifdef DX_CLIP_AVX2
    if (__builtin_cpu_supports("avx2")) return face_points_avx2(r, f, nf, df, inc, max, pts);
#endif
    return face_points_with(r, f, nf, df, inc, max, pts, 0);
}

// The edge of h through its point v parallel to h's edge ei (the copy of
// that edge on the side facing the other hull), or ei itself: its ends.
// The edges are posed (an edge axis won): each direction and its square
// are the posed edge's, the same numbers as from its ends.
static void supporting_edge(const dx_hull *h, unsigned v, unsigned ei, double p0[3],
                            double p1[3])
{
    const dxHullEdge *e = &h->edges[ei];
    const double *u = h->we[ei].u;
    dx_hull_vertex(h, e->a, p0);
    dx_hull_vertex(h, e->b, p1);
    double lu = sqrt(h->we[ei].uu), best = 0;
    // The edges at v: from the point's list where the hull keeps one.
    unsigned k = h->vert_start ? h->vert_start[v] : 0;
    unsigned end = h->vert_start ? h->vert_start[v + 1] : h->nedges;
    for (; k < end; k++) {
        unsigned fk = h->vert_start ? h->vert_edges[k] : k;
        const dxHullEdge *f = &h->edges[fk];
        if (f->a != v && f->b != v) continue;
        const dxHullPosedEdge *d = &h->we[fk];
        double c = fabs(dot3(d->u, u)) / (sqrt(d->uu) * lu);
        if (c > best && c > 1 - DX_HULL_EPS) {
            best = c;
            dx_hull_vertex(h, f->a, p0);
            dx_hull_vertex(h, f->b, p1);
        }
    }
}

// The edge case: one point between the closest points of a's and b's
// supporting edges (the lines' closest parameters clamped to each edge),
// in the middle of the part of the segment between them inside both hulls.
static void edge_point(const dx_hull *a, const dx_hull *b, const sat_axis *ax, double pos[3])
{
    unsigned va, vb;
    double m[3] = { -ax->n[0], -ax->n[1], -ax->n[2] };
    dx_hull_extent(a, m, &va);
    dx_hull_extent(b, ax->n, &vb);
    double a0[3], a1[3], b0[3], b1[3], u[3], v[3], w[3];
    supporting_edge(a, va, ax->ea, a0, a1);
    supporting_edge(b, vb, ax->eb, b0, b1);
    for (int i = 0; i < 3; i++) {
        u[i] = a1[i] - a0[i];
        v[i] = b1[i] - b0[i];
    }
    double lu = sqrt(dot3(u, u)), lv = sqrt(dot3(v, v));
    double iu = lu > 0 ? 1 / lu : 0, iv = lv > 0 ? 1 / lv : 0;   // 0: a point edge
    double ca[3], cb[3];   // the edges' middles
    for (int i = 0; i < 3; i++) {
        u[i] *= iu;
        v[i] *= iv;
        ca[i] = (a0[i] + a1[i]) / 2;
        cb[i] = (b0[i] + b1[i]) / 2;
        w[i] = ca[i] - cb[i];
    }
    double bb = dot3(u, v), d = dot3(u, w), e = dot3(v, w), denom = 1 - bb * bb;
    double s = 0, t = 0;   // parallel supporting edges: their middles
    if (denom > DX_HULL_EPS) {
        s = (bb * e - d) / denom;
        t = (e - bb * d) / denom;
    }
    s = s < -lu / 2 ? -lu / 2 : s > lu / 2 ? lu / 2 : s;
    t = t < -lv / 2 ? -lv / 2 : t > lv / 2 ? lv / 2 : t;
    double qb[3], dir[3];
    for (int i = 0; i < 3; i++) {
        qb[i] = cb[i] + t * v[i];
        dir[i] = ca[i] + s * u[i] - qb[i];
    }
    if (middle_inside(a, b, qb, dir, 0, 1, pos)) return;
    for (int i = 0; i < 3; i++) pos[i] = qb[i] + dir[i] / 2;
}

// One contact where no polygon point was found: between the deepest points.
static void deepest_pair_point(const dx_hull *a, const dx_hull *b, const double n[3],
                               double pos[3])
{
    unsigned va, vb;
    double m[3] = { -n[0], -n[1], -n[2] }, pa[3], pb[3];
    dx_hull_extent(a, m, &va);
    dx_hull_extent(b, n, &vb);
    dx_hull_vertex(a, va, pa);
    dx_hull_vertex(b, vb, pb);
    for (int i = 0; i < 3; i++) pos[i] = (pa[i] + pb[i]) / 2;
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

// The hint of the pair (h's convex against the geom other): h's entry for
// other, or NULL.
static dxHullAxisHint *find_hint(dx_hull *h, const void *other)
{
    for (int k = 0; k < DX_CONVEX_AXIS_CACHE; k++)
        if (h->convex->hint_other[k] == other) return &h->convex->hints[k];
    return NULL;
}

// h's hint against the geom other: e (find_hint's answer), or made if
// there is none (replacing the oldest entry).
static dxHullAxisHint *hint_entry(dx_hull *h, dxHullAxisHint *e, const void *other)
{
    if (!e) {
        const unsigned k = h->convex->next_hint;
        e = &h->convex->hints[k];
        h->convex->hint_other[k] = other;
        h->convex->next_hint = (k + 1) % DX_CONVEX_AXIS_CACHE;
    }
    return e;
}

// Keeps the separating axis n (world) as h's hint against the geom other
// (found: its entry, or NULL).
static void keep_axis(dx_hull *h, dxHullAxisHint *found, const void *other, const double n[3])
{
    dxHullAxisHint *e = hint_entry(h, found, other);
    e->touching = 0;
    for (int k = 0; k < 3; k++)
        e->axis[k] = h->R[k] * n[0] + h->R[3 + k] * n[1] + h->R[6 + k] * n[2];
}

// Keeps the contact's face and the bounding points (side 0, own_point:
// h's own) as h's hint against other (found: its entry, or NULL).
static void keep_face(dx_hull *h, dxHullAxisHint *found, const void *other, int side,
                      unsigned face, unsigned own_point, unsigned other_point)
{
    dxHullAxisHint *e = hint_entry(h, found, other);
    e->touching = 1;
    e->side = side;
    e->face = face;
    e->own_point = own_point;
    e->other_point = other_point;
}

// dx_hull_hull, built into each caller (the colliders below call it
// with nothing left to do after it).
static inline __attribute__((always_inline)) int hull_hull(dx_hull *a, dx_hull *b, dxGeom *o1,
                                                           dxGeom *o2, int flags,
                                                           dContactGeom *out, int skip)
{
    // Bounding spheres apart part the hulls (a margin over the radii'
    // bounds for the rounding here).
    double d2 = 0;
    for (int i = 0; i < 3; i++) d2 += (a->c[i] - b->c[i]) * (a->c[i] - b->c[i]);
    double reach = (a->radius + b->radius) * (1 + 1e-9);
    if (d2 > reach * reach) return 0;
    // The axis that parted the pair last time, if it still does; or the
    // face that gave their contact (sides as the holder sees them).
    dx_hull *holder = a->convex ? a : b->convex ? b : NULL;
    const void *other = holder == a ? (const void *)o2 : (const void *)o1;
    sat_hint hint = { -1, 0, 0, 0 };
    dxHullAxisHint *e = holder ? find_hint(holder, other) : NULL;
    if (holder) {
        if (e && e->touching) {
            hint.side = holder == a ? e->side : 1 - e->side;
            hint.face = e->face;
            hint.qa = holder == a ? e->own_point : e->other_point;
            hint.qb = holder == a ? e->other_point : e->own_point;
        } else if (e) {
            double n[3];
            for (int r = 0; r < 3; r++)
                n[r] = holder->R[3 * r] * e->axis[0] + holder->R[3 * r + 1] * e->axis[1] +
                       holder->R[3 * r + 2] * e->axis[2];
            if (dx_hull_axis_separates(a, b, n)) return 0;
        }
    }
    sat_axis face, edge;
    edge_axes found;
    double sep[3];
    if (!dx_hull_sat(a, b, &hint, &face, &edge, &found, sep)) {
        if (holder) keep_axis(holder, e, other, sep);
        return 0;
    }
    if (holder) {
        int own = holder == a;
        keep_face(holder, e, other, own ? face.ref : 1 - face.ref, face.face,
                  own ? hint.qa : hint.qb, own ? hint.qb : hint.qa);
    }
    int max = dx_max_contacts(flags);
    if (edge.depth * DX_HULL_EDGE_PREFERENCE < face.depth) {
        double pos[3];
        edge_point(a, b, &edge, pos);
        put(out, 0, skip, pos, edge.n, edge.depth, o1, o2);
        return 1;
    }
    const dx_hull *r = face.ref ? b : a, *inc = face.ref ? a : b;
    double nf[3], df;
    dx_hull_plane(r, face.face, nf, &df);
    hull_point pts[MAXP];
    int n = face_points(r, face.face, nf, df, inc, max, pts);
    // The exact translation that parts them, at most face.depth: needed
    // only where the deepest point is short of that.
    double clear = face.depth;
    if (n == 0 || pts[0].depth < face.depth)
        clear = dx_hull_clearance(a, b, face.n, face.depth, &found);
    if (n == 0) {
        double pos[3];
        deepest_pair_point(a, b, face.n, pos);
        put(out, 0, skip, pos, face.n, clear, o1, o2);
        return 1;
    }
    for (int k = 0; k < n; k++) {
        double depth = k == 0 && pts[0].depth < clear ? clear : pts[k].depth;
        put(out, k, skip, pts[k].p, face.n, depth, o1, o2);
    }
    return n;
}

int dx_hull_hull(dx_hull *a, dx_hull *b, dxGeom *o1, dxGeom *o2, int flags,
                 dContactGeom *out, int skip)
{
    return hull_hull(a, b, o1, o2, flags, out, skip);
}

// The convex geom g's kept hull, posed (dx_hull_posed's convex case, here
// where the class is known).
static dx_hull *convex_posed(dxGeom *g)
{
    dxConvex *c = (dxConvex *)g;
    dxConvexPoseIfMoved(c);
    return &c->hull;
}

int dxCollideConvexConvex(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    return hull_hull(convex_posed(o1), convex_posed(o2), o1, o2, flags, out, skip);
}

int dxCollideConvexBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    return hull_hull(convex_posed(o1), box_posed(o2), o1, o2, flags, out, skip);
}
