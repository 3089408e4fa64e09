// SPDX-License-Identifier: BSD-3-Clause
//
// geom_convex.c -- the convex hull class of ODE 0.16: creation and
// dGeomSetConvex with their checks, and the bounding box of the points as
// posed. The arrays belong to the caller (as in ODE): they are not copied.
// The geom owns only what it derives from them: the edge list (each edge
// with its two faces), which the colliders use to skip edge pairs, where
// each polygon starts, and room for the hull posed in the world.

#include "geom_convex.h"

#include <ode/memory.h>

#include <float.h>
#include <math.h>
#include <string.h>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

// 1 if the hull data is usable by the colliders; else reports what is
// wrong (naming the calling function) and returns 0.
static int convex_valid(const char *fn, const dReal *planes, unsigned planecount,
                        const dReal *points, unsigned pointcount, const unsigned *polygons)
{
#define CONVEX_CHECK(cond, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(fn, __VA_ARGS__); \
            return 0; \
        } \
    } while (0)
    CONVEX_CHECK(planecount > 0, "planecount is 0: a convex needs planes");
    CONVEX_CHECK(pointcount > 0, "pointcount is 0: a convex needs points");
    CONVEX_CHECK(planes != NULL, "planes is NULL with planecount %u", planecount);
    CONVEX_CHECK(points != NULL, "points is NULL with pointcount %u", pointcount);
    CONVEX_CHECK(polygons != NULL, "polygons is NULL with planecount %u", planecount);
    for (unsigned i = 0; i < 3 * pointcount; i++)
        CONVEX_CHECK(dxIsFinite(points[i]), "points[%u] is not finite", i);
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++) {
        const dReal *p = planes + 4 * f;
        for (int k = 0; k < 4; k++)
            CONVEX_CHECK(dxIsFinite(p[k]), "planes[%u] is not finite", 4 * f + (unsigned)k);
        CONVEX_CHECK(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 0,
                     "plane %u has a zero normal", f);
        unsigned count = *poly++;
        CONVEX_CHECK(count >= 3, "polygon %u has %u points (at least 3 needed)", f, count);
        for (unsigned k = 0; k < count; k++, poly++)
            CONVEX_CHECK(*poly < pointcount, "polygon %u uses point %u, past pointcount %u", f,
                         *poly, pointcount);
    }
    return 1;
#undef CONVEX_CHECK
}

// Poses point v and plane f one at a time (dxHullPosePointsPlanes' way).
static void pose_point(const double R[9], const double c[3], const dReal *p, double wp[3],
                       double *const p3[3], unsigned v)
{
    for (int r = 0; r < 3; r++)
        p3[r][v] = wp[r] = c[r] + R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2];
}

static void pose_plane(const double R[9], const double c[3], const dReal *p, const double *len,
                       double wn[3], double *const n3[3], double *wd, unsigned f)
{
    double l = len ? len[f] : sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
    for (int r = 0; r < 3; r++)
        n3[r][f] = wn[r] = (R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2]) / l;
    *wd = p[3] / l + (wn[0] * c[0] + wn[1] * c[1] + wn[2] * c[2]);
}

#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__) && !defined(dSINGLE) && \
    !defined(DX_HULL_NO_AVX2)
#define DX_POSE_AVX2 1
#include <immintrin.h>

// Three rows of four (x0..x3, y0..y3, z0..z3) from four points' (x, y, z)
// in a row (12 numbers at p), and back.
__attribute__((target("avx2"))) static inline void rows_of_triples(const double *p, __m256d out[3])
{
    __m256d m0 = _mm256_loadu_pd(p), m1 = _mm256_loadu_pd(p + 4), m2 = _mm256_loadu_pd(p + 8);
    __m256d t0 = _mm256_permute2f128_pd(m0, m1, 0x30);   // x0 y0 x2 y2
    __m256d t1 = _mm256_permute2f128_pd(m0, m2, 0x21);   // z0 x1 z2 x3
    __m256d t2 = _mm256_permute2f128_pd(m1, m2, 0x30);   // y1 z1 y3 z3
    out[0] = _mm256_blend_pd(t0, t1, 0xa);
    out[1] = _mm256_shuffle_pd(t0, t2, 0x5);
    out[2] = _mm256_blend_pd(t1, t2, 0xa);
}

__attribute__((target("avx2"))) static inline void triples_of_rows(const __m256d in[3], double *p)
{
    __m256d t0 = _mm256_unpacklo_pd(in[0], in[1]);       // x0 y0 x2 y2
    __m256d t1 = _mm256_blend_pd(in[2], in[0], 0xa);     // z0 x1 z2 x3
    __m256d t2 = _mm256_unpackhi_pd(in[1], in[2]);       // y1 z1 y3 z3
    _mm256_storeu_pd(p, _mm256_permute2f128_pd(t0, t1, 0x20));
    _mm256_storeu_pd(p + 4, _mm256_permute2f128_pd(t2, t0, 0x30));
    _mm256_storeu_pd(p + 8, _mm256_permute2f128_pd(t1, t2, 0x31));
}

// dxHullPosePointsPlanes four points and four planes at a time: the same
// products, sums and quotients in the same order (no fused multiply-add),
// so the same numbers.
__attribute__((target("avx2"))) static void
pose_avx2(const double R[9], const double c[3], const dReal *pts, unsigned npts,
          const dReal *planes, const double *len, unsigned nplanes, double (*wp)[3],
          double *const p3[3], double (*wn)[3], double *const n3[3], double *wd)
{
    __m256d r[9], cc[3];
    for (int k = 0; k < 9; k++) r[k] = _mm256_set1_pd(R[k]);
    for (int k = 0; k < 3; k++) cc[k] = _mm256_set1_pd(c[k]);
    unsigned v = 0;
    for (; v + 4 <= npts; v += 4) {
        __m256d p[3], w[3];
        rows_of_triples(pts + 3 * v, p);
        for (int k = 0; k < 3; k++) {
            w[k] = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(cc[k], _mm256_mul_pd(r[3 * k], p[0])),
                                               _mm256_mul_pd(r[3 * k + 1], p[1])),
                                 _mm256_mul_pd(r[3 * k + 2], p[2]));
            _mm256_storeu_pd(p3[k] + v, w[k]);
        }
        triples_of_rows(w, wp[v]);
    }
    for (; v < npts; v++) pose_point(R, c, pts + 3 * v, wp[v], p3, v);
    unsigned f = 0;
    for (; f + 4 <= nplanes; f += 4) {
        const double *q = planes + 4 * f;
        __m256d q0 = _mm256_loadu_pd(q), q1 = _mm256_loadu_pd(q + 4);
        __m256d q2 = _mm256_loadu_pd(q + 8), q3 = _mm256_loadu_pd(q + 12);
        __m256d u0 = _mm256_unpacklo_pd(q0, q1), u1 = _mm256_unpackhi_pd(q0, q1);
        __m256d u2 = _mm256_unpacklo_pd(q2, q3), u3 = _mm256_unpackhi_pd(q2, q3);
        __m256d a = _mm256_permute2f128_pd(u0, u2, 0x20), b = _mm256_permute2f128_pd(u1, u3, 0x20);
        __m256d cz = _mm256_permute2f128_pd(u0, u2, 0x31), d = _mm256_permute2f128_pd(u1, u3, 0x31);
        __m256d l = len ? _mm256_loadu_pd(len + f)
                        : _mm256_sqrt_pd(_mm256_add_pd(
                              _mm256_add_pd(_mm256_mul_pd(a, a), _mm256_mul_pd(b, b)),
                              _mm256_mul_pd(cz, cz)));
        __m256d n[3];
        for (int k = 0; k < 3; k++) {
            n[k] = _mm256_div_pd(
                _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r[3 * k], a), _mm256_mul_pd(r[3 * k + 1], b)),
                              _mm256_mul_pd(r[3 * k + 2], cz)),
                l);
            _mm256_storeu_pd(n3[k] + f, n[k]);
        }
        __m256d nc = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(n[0], cc[0]), _mm256_mul_pd(n[1], cc[1])),
                                   _mm256_mul_pd(n[2], cc[2]));
        _mm256_storeu_pd(wd + f, _mm256_add_pd(_mm256_div_pd(d, l), nc));
        triples_of_rows(n, wn[f]);
    }
    for (; f < nplanes; f++) pose_plane(R, c, planes + 4 * f, len, wn[f], n3, wd + f, f);
}
#endif

void dxHullPosePointsPlanes(const double R[9], const double c[3], const dReal *pts, unsigned npts,
                            const dReal *planes, const double *len, unsigned nplanes,
                            double (*wp)[3], double *const p3[3], double (*wn)[3],
                            double *const n3[3], double *wd)
{
#ifdef DX_POSE_AVX2
    if (__builtin_cpu_supports("avx2")) {
        pose_avx2(R, c, pts, npts, planes, len, nplanes, wp, p3, wn, n3, wd);
        return;
    }
#endif
    for (unsigned v = 0; v < npts; v++) pose_point(R, c, pts + 3 * v, wp[v], p3, v);
    for (unsigned f = 0; f < nplanes; f++)
        pose_plane(R, c, planes + 4 * f, len, wn[f], n3, wd + f, f);
}

void dxHullPoseBounds(dx_hull *h)
{
    double e2 = 0;
    for (int i = 0; i < 3; i++) {
        for (int k = i; k < 3; k++) {
            double d = h->R[i] * h->R[k] + h->R[3 + i] * h->R[3 + k] + h->R[6 + i] * h->R[6 + k] -
                       (i == k);
            e2 += (i == k ? 1 : 2) * d * d;
        }
    }
    h->rot_err = sqrt(e2);
    double reach = h->size + fabs(h->c[0]) + fabs(h->c[1]) + fabs(h->c[2]);
    h->radius = h->size * (1 + h->rot_err) * (1 + 1e-12) + 16 * DBL_EPSILON * reach;
}

// Whether the n numbers at a and b are the same bits (memcmp's answer,
// without its call: this runs for every pair a hull meets), 16 bytes at a
// time where SSE2 is there.
static int same_bits(const dReal *a, const dReal *b, int n)
{
    const char *x = (const char *)a, *y = (const char *)b;
    size_t bytes = (size_t)n * sizeof(dReal), k = 0;
#ifdef __SSE2__
    __m128i diff = _mm_setzero_si128();
    for (; k + 16 <= bytes; k += 16)
        diff = _mm_or_si128(diff, _mm_xor_si128(_mm_loadu_si128((const __m128i *)(x + k)),
                                                _mm_loadu_si128((const __m128i *)(y + k))));
    if (_mm_movemask_epi8(_mm_cmpeq_epi8(diff, _mm_setzero_si128())) != 0xffff) return 0;
#endif
    uint32_t d = 0, u, v;
    for (; k < bytes; k += sizeof u) {
        memcpy(&u, x + k, sizeof u);
        memcpy(&v, y + k, sizeof v);
        d |= u ^ v;
    }
    return d == 0;
}

// The bounding box of the posed points (lo, hi by axis) into box.
static void points_box(const dxHullPose *pose, unsigned n, double box[6])
{
    const double *p3[3] = { pose->px, pose->py, pose->pz };
    for (int i = 0; i < 3; i++) {
        const double *x = p3[i];
        double lo = x[0], hi = x[0];
        unsigned v = 1;
#ifdef __SSE2__
        __m128d vlo = _mm_set1_pd(lo), vhi = vlo;
        for (; v + 2 <= n; v += 2) {
            __m128d e = _mm_loadu_pd(x + v);
            vlo = _mm_min_pd(e, vlo);
            vhi = _mm_max_pd(e, vhi);
        }
        double l2[2], h2[2];
        _mm_storeu_pd(l2, vlo);
        _mm_storeu_pd(h2, vhi);
        lo = l2[0] < l2[1] ? l2[0] : l2[1];
        hi = h2[0] > h2[1] ? h2[0] : h2[1];
#endif
        for (; v < n; v++) {
            lo = x[v] < lo ? x[v] : lo;
            hi = x[v] > hi ? x[v] : hi;
        }
        box[2 * i] = lo;
        box[2 * i + 1] = hi;
    }
}

#ifdef DX_POSE_AVX2
// points_box four points at a time (the same least and largest numbers,
// but for which of +0 and -0 a tie between them gives).
__attribute__((target("avx2"))) static void points_box_avx2(const dxHullPose *pose, unsigned n,
                                                            double box[6])
{
    const double *p3[3] = { pose->px, pose->py, pose->pz };
    __m256d lo[3], hi[3];
    for (int i = 0; i < 3; i++) {
        lo[i] = _mm256_set1_pd(p3[i][0]);
        hi[i] = lo[i];
    }
    unsigned v = 0;
    for (; v + 4 <= n; v += 4) {
        for (int i = 0; i < 3; i++) {
            __m256d e = _mm256_loadu_pd(p3[i] + v);
            lo[i] = _mm256_min_pd(e, lo[i]);
            hi[i] = _mm256_max_pd(e, hi[i]);
        }
    }
    for (int i = 0; i < 3; i++) {
        __m256d l = _mm256_min_pd(lo[i], _mm256_permute2f128_pd(lo[i], lo[i], 1));
        __m256d h = _mm256_max_pd(hi[i], _mm256_permute2f128_pd(hi[i], hi[i], 1));
        double a = _mm256_cvtsd_f64(_mm256_min_pd(l, _mm256_permute_pd(l, 1)));
        double b = _mm256_cvtsd_f64(_mm256_max_pd(h, _mm256_permute_pd(h, 1)));
        for (unsigned k = v; k < n; k++) {
            a = p3[i][k] < a ? p3[i][k] : a;
            b = p3[i][k] > b ? p3[i][k] : b;
        }
        box[2 * i] = a;
        box[2 * i + 1] = b;
    }
}
#endif

void dxConvexPose(dxConvex *c)
{
    const dxGeom *g = &c->g;
    dxHullPose *pose = &c->pose;
    if (pose->valid && same_bits(pose->pos, g->pos, 3) && same_bits(pose->R, g->R, 12)) return;
    dx_hull *h = &c->hull;
    for (int i = 0; i < 3; i++) {
        h->c[i] = g->pos[i];
        for (int k = 0; k < 3; k++) h->R[3 * i + k] = g->R[4 * i + k];
    }
    dxHullPoseBounds(h);
    dxHullPosePointsPlanes(h->R, h->c, c->points, c->pointcount, c->planes, c->plane_len,
                           c->planecount, pose->pts, (double *const[3]){ pose->px, pose->py, pose->pz },
                           pose->normals, (double *const[3]){ pose->nx, pose->ny, pose->nz },
                           pose->offsets);
#ifdef DX_POSE_AVX2
    if (__builtin_cpu_supports("avx2"))
        points_box_avx2(pose, c->pointcount, pose->box);
    else
#endif
        points_box(pose, c->pointcount, pose->box);
    for (int i = 0; i < 3; i++)
        h->centre[i] = h->c[i] + h->R[3 * i] * c->mean[0] + h->R[3 * i + 1] * c->mean[1] +
                       h->R[3 * i + 2] * c->mean[2];
    memcpy(pose->pos, g->pos, sizeof pose->pos);
    memcpy(pose->R, g->R, sizeof pose->R);
    pose->valid = 1;
    pose->edges_valid = 0;
}

// The bounding box of the points as posed (the pose is kept for the
// colliders: a hull that meets others this step is posed once; the box is
// made with it).
static void convex_aabb(dxGeom *g)
{
    dxConvex *c = (dxConvex *)g;
    dxConvexPose(c);
    for (int k = 0; k < 6; k++) g->aabb[k] = (dReal)c->pose.box[k];
}

// The edges of the polygons, each once, with the faces on either side,
// into e (room for one per polygon side); returns their count.
static unsigned convex_edges(const unsigned *polygons, unsigned planecount, dxHullEdge *e)
{
    unsigned n = 0;
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++, poly += 1 + *poly) {
        for (unsigned k = 0; k < poly[0]; k++) {
            unsigned i = poly[1 + k], j = poly[1 + (k + 1) % poly[0]];
            unsigned a = i < j ? i : j, b = i < j ? j : i, m = 0;
            while (m < n && !(e[m].a == a && e[m].b == b)) m++;
            if (m < n) {   // the same edge from its other face
                if (e[m].f2 == e[m].f1 && e[m].f1 != f) e[m].f2 = f;
                continue;
            }
            e[n++] = (dxHullEdge){ a, b, f, f };
        }
    }
    return n;
}

// The sets of edges by face and of neighbouring faces (dxConvex's by_f1,
// by_f2, lone, nbr) into masks (room for three per plane), for hulls that
// fit 64-bit sets.
static void convex_edge_sets(dxConvex *c, uint64_t *masks)
{
    c->lone = 0;
    if (c->edgecount > 64 || c->planecount > 64) {
        c->by_f1 = c->by_f2 = c->nbr = NULL;
        return;
    }
    c->by_f1 = masks;
    c->by_f2 = masks + c->planecount;
    c->nbr = masks + 2 * (size_t)c->planecount;
    for (unsigned f = 0; f < c->planecount; f++) {
        c->by_f1[f] = c->by_f2[f] = 0;
        c->nbr[f] = (uint64_t)1 << f;
    }
    for (unsigned k = 0; k < c->edgecount; k++) {
        const dxHullEdge *e = &c->edges[k];
        uint64_t bit = (uint64_t)1 << k;
        c->by_f1[e->f1] |= bit;
        c->by_f2[e->f2] |= bit;
        c->nbr[e->f1] |= (uint64_t)1 << e->f2;
        c->nbr[e->f2] |= (uint64_t)1 << e->f1;
        if (e->f1 == e->f2) c->lone |= bit;
    }
    memset(c->edge_faces, 0x80, sizeof c->edge_faces);
    if (c->edgecount > 32 || c->planecount > 16) return;
    for (unsigned k = 0; k < c->edgecount; k++) {
        c->edge_faces[0][k] = (uint8_t)c->edges[k].f1;
        c->edge_faces[1][k] = (uint8_t)c->edges[k].f2;
    }
}

// Each point's edges, in the edge list's order (c->vert_start, vert_edges).
static void convex_vertex_edges(dxConvex *c)
{
    unsigned *start = c->vert_start;
    for (unsigned v = 0; v <= c->pointcount; v++) start[v] = 0;
    for (unsigned k = 0; k < c->edgecount; k++) {
        start[c->edges[k].a + 1]++;
        start[c->edges[k].b + 1]++;
    }
    for (unsigned v = 0; v < c->pointcount; v++) start[v + 1] += start[v];
    for (unsigned k = 0; k < c->edgecount; k++) {   // start[v] runs ahead, then is put back
        c->vert_edges[start[c->edges[k].a]++] = k;
        c->vert_edges[start[c->edges[k].b]++] = k;
    }
    for (unsigned v = c->pointcount; v > 0; v--) start[v] = start[v - 1];
    start[0] = 0;
}

// The parts of c->hull that stay from one pose to the next.
static void convex_view(dxConvex *c)
{
    dx_hull *h = &c->hull;
    dxHullPose *pose = &c->pose;
    h->pts = c->points;
    h->planes = c->planes;
    h->polys = c->polygons;
    h->poly_start = c->poly_start;
    h->edges = c->edges;
    h->vert_start = c->vert_start;
    h->vert_edges = c->vert_edges;
    h->npts = c->pointcount;
    h->nplanes = c->planecount;
    h->nedges = c->edgecount;
    h->wp = (const double (*)[3])pose->pts;
    h->wn = (const double (*)[3])pose->normals;
    h->wd = pose->offsets;
    h->we = pose->edges;
    h->face_low = pose->face_low;
    h->plane_dev = c->plane_dev;
    h->edges_posed = &pose->edges_valid;
    h->by_f1 = c->by_f1;
    h->by_f2 = c->by_f2;
    h->lone = c->lone;
    h->nbr = c->nbr;
    h->edge_faces = c->by_f1 && c->edgecount <= 32 && c->planecount <= 16
                        ? (const uint8_t (*)[32])c->edge_faces
                        : NULL;
    h->px = pose->px;
    h->py = pose->py;
    h->pz = pose->pz;
    h->nx = pose->nx;
    h->ny = pose->ny;
    h->nz = pose->nz;
    h->ex = pose->ex;
    h->ey = pose->ey;
    h->ez = pose->ez;
    h->convex = c;
}

static void free_derived(dxConvex *c)
{
    if (c->derived) dFree(c->derived, c->derived_size);
    c->derived = NULL;
    c->edges = NULL;
    c->poly_start = c->vert_start = c->vert_edges = NULL;
    c->by_f1 = c->by_f2 = c->nbr = NULL;
    c->plane_len = c->plane_dev = NULL;
}

static void convex_destroy(dxGeom *g)
{
    free_derived((dxConvex *)g);
}

const dxGeomClassOps dx_convex_ops = { dConvexClass, "convex", convex_aabb, convex_destroy };

// Takes the caller's arrays and derives, in one block made once per
// dGeomSetConvex: the edge list, where each polygon starts, the size, and
// room for the hull posed in the world (filled by the colliders).
static void convex_set(dxConvex *c, const dReal *planes, unsigned planecount,
                       const dReal *points, unsigned pointcount, const unsigned *polygons)
{
    free_derived(c);
    c->planes = planes;
    c->planecount = planecount;
    c->points = points;
    c->pointcount = pointcount;
    c->polygons = polygons;
    size_t sides = 0;
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++) {
        sides += *poly;
        poly += 1 + *poly;
    }
    // The normals and the edges' n2 x n1 by coordinate get room for a
    // multiple of four (sides is at least the edge count), zero past the
    // planes and edges: the loops over them go four at a time without a
    // tail (zeros give no sign).
    size_t planes4 = (planecount + 3) & ~(size_t)3, sides4 = (sides + 3) & ~(size_t)3;
    size_t doubles = 6 * (size_t)pointcount + 7 * (size_t)planecount + 3 * planes4 + 3 * sides4;
    c->derived_size = sizeof(uint64_t) * 3 * (size_t)planecount + sizeof(double) * doubles +
                      sizeof(dxHullPosedEdge) * sides + sizeof(dxHullEdge) * sides +
                      sizeof(unsigned) * (planecount + (size_t)pointcount + 1 + 2 * sides);
    char *block = dAlloc(c->derived_size);
    c->derived = block;
    dxHullPose *pose = &c->pose;
    uint64_t *masks = (uint64_t *)block;
    pose->pts = (double (*)[3])(masks + 3 * (size_t)planecount);
    pose->normals = pose->pts + pointcount;
    pose->offsets = (double *)(pose->normals + planecount);
    pose->px = pose->offsets + planecount;
    pose->py = pose->px + pointcount;
    pose->pz = pose->py + pointcount;
    pose->nx = pose->pz + pointcount;
    pose->ny = pose->nx + planes4;
    pose->nz = pose->ny + planes4;
    pose->ex = pose->nz + planes4;
    pose->ey = pose->ex + sides4;
    pose->ez = pose->ey + sides4;
    pose->face_low = pose->ez + sides4;
    memset(pose->nx, 0, (3 * planes4 + 3 * sides4) * sizeof(double));
    c->plane_len = pose->face_low + planecount;
    c->plane_dev = c->plane_len + planecount;
    pose->edges = (dxHullPosedEdge *)(c->plane_dev + planecount);
    pose->valid = pose->edges_valid = 0;
    c->edges = (dxHullEdge *)(pose->edges + sides);
    c->poly_start = (unsigned *)(c->edges + sides);
    c->vert_start = c->poly_start + planecount;
    c->vert_edges = c->vert_start + pointcount + 1;
    c->edgecount = convex_edges(polygons, planecount, c->edges);
    convex_vertex_edges(c);
    convex_edge_sets(c, masks);
    unsigned at = 0;
    for (unsigned f = 0; f < planecount; f++) {
        c->poly_start[f] = at;
        at += 1 + polygons[at];
    }
    for (unsigned f = 0; f < planecount; f++) {
        const dReal *p = planes + 4 * f;
        c->plane_len[f] = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
        // (d - n . x) / |n| at the polygon's points: the most is how far
        // under the plane the polygon reaches (0 for a flat one).
        const unsigned *idx = polygons + c->poly_start[f];
        double dev = 0;
        for (unsigned k = 1; k <= idx[0]; k++) {
            const dReal *q = points + 3 * idx[k];
            double under = ((double)p[3] - ((double)p[0] * q[0] + (double)p[1] * q[1] +
                                            (double)p[2] * q[2])) / c->plane_len[f];
            dev = under > dev ? under : dev;
        }
        c->plane_dev[f] = dev;
    }
    convex_view(c);
    double r2 = 0;
    for (int i = 0; i < 3; i++) c->mean[i] = 0;
    for (unsigned v = 0; v < pointcount; v++) {
        const dReal *p = points + 3 * v;
        for (int i = 0; i < 3; i++) c->mean[i] += (double)p[i] / pointcount;
        double d2 = (double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2];
        if (d2 > r2) r2 = d2;
    }
    c->size = c->hull.size = sqrt(r2);
}

dGeomID dCreateConvex(dSpaceID space, const dReal *planes, unsigned int planecount,
                      const dReal *points, unsigned int pointcount, const unsigned int *polygons)
{
    if (!convex_valid(__func__, planes, planecount, points, pointcount, polygons)) return NULL;
    dxConvex *c = (dxConvex *)dxGeomCreate(sizeof *c, &dx_convex_ops, DX_GEOM_PLACEABLE, space);
    convex_set(c, planes, planecount, points, pointcount, polygons);
    return &c->g;
}

void dGeomSetConvex(dGeomID g, const dReal *planes, unsigned int planecount,
                    const dReal *points, unsigned int pointcount, const unsigned int *polygons)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(g->ops->cls == dConvexClass, return, "geom is a %s, not a convex",
                 g->ops->name);
    if (!convex_valid(__func__, planes, planecount, points, pointcount, polygons)) return;
    convex_set((dxConvex *)g, planes, planecount, points, pointcount, polygons);
    dxGeomShapeChanged(g);
}
