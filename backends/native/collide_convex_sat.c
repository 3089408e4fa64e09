// SPDX-License-Identifier: BSD-3-Clause
//
// collide_convex_sat.c -- the separating axis test of two convex hulls
// (for dx_hull_hull, collide_convex_hull.c): the least translation of a
// along a unit n that parts it from b, s(n) = h_b(n) + h_a(-n) (h the
// support value), is least over the face normals of either and the cross
// products of an edge of each whose arcs on the unit sphere cross (the
// faces of the Minkowski difference); a negative value there separates
// them. Axes that cheap lower bounds show clearly deeper than the best
// face are skipped (see docs/perf.md); the result is that of testing them
// all. Also the exact clearance along the chosen face's normal, and the
// hulls' support queries (extents) that all of it rests on.

#include "collide_convex.h"
#include "collide_math.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#ifdef __SSE2__
#include <emmintrin.h>
#endif
// dot_signs four at a time where the machine has AVX2 (chosen when called;
// -DDX_HULL_NO_AVX2 builds the baseline alone, to compare the two).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__) && !defined(DX_HULL_NO_AVX2)
#define DX_SIGNS_AVX2 1
#include <immintrin.h>
#endif

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

// The least and the largest of m . (x[k], y[k], z[k]) over k < n, each
// product made as dot3 makes it (two at a time where SSE2 is there; the
// same numbers either way).
static void dot_range(const double m[3], const double *x, const double *y, const double *z,
                      unsigned n, double *lo, double *hi)
{
    double mn = INFINITY, mx = -INFINITY;
    unsigned k = 0;
#ifdef __SSE2__
    __m128d m0 = _mm_set1_pd(m[0]), m1 = _mm_set1_pd(m[1]), m2 = _mm_set1_pd(m[2]);
    __m128d vlo = _mm_set1_pd(INFINITY), vhi = _mm_set1_pd(-INFINITY);
    for (; k + 2 <= n; k += 2) {
        __m128d e = _mm_add_pd(_mm_add_pd(_mm_mul_pd(m0, _mm_loadu_pd(x + k)),
                                          _mm_mul_pd(m1, _mm_loadu_pd(y + k))),
                               _mm_mul_pd(m2, _mm_loadu_pd(z + k)));
        vlo = _mm_min_pd(e, vlo);   // a NaN product is skipped, as below
        vhi = _mm_max_pd(e, vhi);
    }
    double l2[2], h2[2];
    _mm_storeu_pd(l2, vlo);
    _mm_storeu_pd(h2, vhi);
    mn = l2[0] < l2[1] ? l2[0] : l2[1];
    mx = h2[0] > h2[1] ? h2[0] : h2[1];
#endif
    for (; k < n; k++) {
        double e = m[0] * x[k] + m[1] * y[k] + m[2] * z[k];
        mn = e < mn ? e : mn;
        mx = e > mx ? e : mx;
    }
    *lo = mn;
    *hi = mx;
}

// The largest of m . (x[k], y[k], z[k]) over k < n (dot_range's way).
static double dot_max(const double m[3], const double *x, const double *y, const double *z,
                      unsigned n)
{
    double mx = -INFINITY;
    unsigned k = 0;
#ifdef __SSE2__
    __m128d m0 = _mm_set1_pd(m[0]), m1 = _mm_set1_pd(m[1]), m2 = _mm_set1_pd(m[2]);
    __m128d vhi = _mm_set1_pd(-INFINITY);
    for (; k + 2 <= n; k += 2) {
        __m128d e = _mm_add_pd(_mm_add_pd(_mm_mul_pd(m0, _mm_loadu_pd(x + k)),
                                          _mm_mul_pd(m1, _mm_loadu_pd(y + k))),
                               _mm_mul_pd(m2, _mm_loadu_pd(z + k)));
        vhi = _mm_max_pd(e, vhi);
    }
    double h2[2];
    _mm_storeu_pd(h2, vhi);
    mx = h2[0] > h2[1] ? h2[0] : h2[1];
#endif
    for (; k < n; k++) {
        double e = m[0] * x[k] + m[1] * y[k] + m[2] * z[k];
        mx = e > mx ? e : mx;
    }
    return mx;
}

#ifdef DX_SIGNS_AVX2
// base[i0], base[i1], base[i2], base[i3] in lanes 0-3: what a gather
// (_mm256_i32gather_pd) gives, by four loads, the indices read where they
// lie. On Intel processors with the microcode fix for Downfall (gather data
// sampling) a gather takes about 28 cycles (a loop of them on an Ice Lake
// Xeon: 10 ns each, four loads and an insert 3 ns); AMD's Zen was not
// measured. The hulls scene: 0.83x the time, 3 % more instructions
// (docs/perf.md, "Gathers on Intel").
__attribute__((target("avx2"))) static inline __m256d load4(const double *base, size_t i0,
                                                            size_t i1, size_t i2, size_t i3)
{
    const __m128d lo = _mm_loadh_pd(_mm_load_sd(base + i0), base + i1);
    const __m128d hi = _mm_loadh_pd(_mm_load_sd(base + i2), base + i3);
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(lo), hi, 1);
}

// load4 at four consecutive indices idx[0..3].
__attribute__((target("avx2"))) static inline __m256d load4_at(const double *base,
                                                               const unsigned *idx)
{
    return load4(base, idx[0], idx[1], idx[2], idx[3]);
}

// The columns c of the 4 x 4 matrix whose rows are r (lane l of c[e] is
// r[l]'s number e).
__attribute__((target("avx2"))) static inline void transpose4(const __m256d r[4], __m256d c[4])
{
    const __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]), t1 = _mm256_unpackhi_pd(r[0], r[1]);
    const __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]), t3 = _mm256_unpackhi_pd(r[2], r[3]);
    c[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    c[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    c[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    c[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

// m . x for h's points k to k + 3 (m broadcast in m0, m1, m2; made as
// dot3 makes them).
__attribute__((target("avx2"))) static inline __m256d products4(__m256d m0, __m256d m1, __m256d m2,
                                                                const dx_hull *h, unsigned k)
{
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(m0, _mm256_loadu_pd(h->px + k)),
                                       _mm256_mul_pd(m1, _mm256_loadu_pd(h->py + k))),
                         _mm256_mul_pd(m2, _mm256_loadu_pd(h->pz + k)));
}
#endif

// The first of h's points from v on with the largest m . x (over best,
// the largest before v, at bi), into *idx; returns that largest.
static double extent_index_from(const dx_hull *h, const double m[3], unsigned v, double best,
                                unsigned bi, unsigned *idx)
{
    for (; v < h->npts; v++) {
        double e = dot3(m, h->wp[v]);
        if (e > best) {
            best = e;
            bi = v;
        }
    }
    *idx = bi;
    return best;
}

#ifdef DX_SIGNS_AVX2
// dx_hull_extent with its index, four points at a time: the largest of the
// fours' products, then the first point that gives it (the same point).
__attribute__((target("avx2"))) static double extent_index4(const dx_hull *h, const double m[3],
                                                            unsigned *idx)
{
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    __m256d vhi = _mm256_set1_pd(-INFINITY);
    unsigned n = h->npts & ~3u;
    for (unsigned k = 0; k < n; k += 4)
        vhi = _mm256_max_pd(products4(m0, m1, m2, h, k), vhi);   // a NaN is passed over
    vhi = _mm256_max_pd(vhi, _mm256_permute2f128_pd(vhi, vhi, 1));
    double best = _mm256_cvtsd_f64(_mm256_max_pd(vhi, _mm256_permute_pd(vhi, 1)));
    unsigned bi = 0;
    if (best > -INFINITY) {
        __m256d bv = _mm256_set1_pd(best);
        for (unsigned k = 0;; k += 4) {
            int eq = _mm256_movemask_pd(_mm256_cmp_pd(products4(m0, m1, m2, h, k), bv, _CMP_EQ_OQ));
            if (eq) {
                bi = k + (unsigned)__builtin_ctz((unsigned)eq);
                break;
            }
        }
    }
    return extent_index_from(h, m, n, best, bi, idx);
}
#endif

double dx_hull_extent(const dx_hull *h, const double m[3], unsigned *idx)
{
    if (!idx) return dot_max(m, h->px, h->py, h->pz, h->npts);
#ifdef DX_SIGNS_AVX2
    if (__builtin_cpu_supports("avx2")) return extent_index4(h, m, idx);
#endif
    return extent_index_from(h, m, 0, -INFINITY, 0, idx);
}

void dx_hull_interval(const dx_hull *h, const double m[3], double *lo, double *hi)
{
    dot_range(m, h->px, h->py, h->pz, h->npts, lo, hi);
}

#ifdef DX_SIGNS_AVX2
// dot_range four at a time (the same products): the same least and
// largest numbers, but for which of +0 and -0 a tie between them gives.
__attribute__((target("avx2"))) static inline void dot_range4(const double m[3], const double *x,
                                                              const double *y, const double *z,
                                                              unsigned n, double *lo, double *hi)
{
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    __m256d vlo = _mm256_set1_pd(INFINITY), vhi = _mm256_set1_pd(-INFINITY);
    unsigned k = 0;
    for (; k + 4 <= n; k += 4) {
        __m256d e = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(m0, _mm256_loadu_pd(x + k)),
                                                _mm256_mul_pd(m1, _mm256_loadu_pd(y + k))),
                                  _mm256_mul_pd(m2, _mm256_loadu_pd(z + k)));
        vlo = _mm256_min_pd(e, vlo);   // a NaN product is skipped, as dot_range does
        vhi = _mm256_max_pd(e, vhi);
    }
    vlo = _mm256_min_pd(vlo, _mm256_permute2f128_pd(vlo, vlo, 1));
    vhi = _mm256_max_pd(vhi, _mm256_permute2f128_pd(vhi, vhi, 1));
    double mn = _mm256_cvtsd_f64(_mm256_min_pd(vlo, _mm256_permute_pd(vlo, 1)));
    double mx = _mm256_cvtsd_f64(_mm256_max_pd(vhi, _mm256_permute_pd(vhi, 1)));
    for (; k < n; k++) {
        double e = m[0] * x[k] + m[1] * y[k] + m[2] * z[k];
        mn = e < mn ? e : mn;
        mx = e > mx ? e : mx;
    }
    *lo = mn;
    *hi = mx;
}

__attribute__((target("avx2"))) static int axis_separates_avx2(const dx_hull *a, const dx_hull *b,
                                                               const double n[3])
{
    double alo, ahi, blo, bhi;
    dot_range4(n, a->px, a->py, a->pz, a->npts, &alo, &ahi);
    dot_range4(n, b->px, b->py, b->pz, b->npts, &blo, &bhi);
    return bhi - alo < 0 || ahi - blo < 0;
}
#endif

// Whether the axis n (world) parts a and b: their intervals along it are
// apart (which of +0 and -0 an end is cannot change that).
int dx_hull_axis_separates(const dx_hull *a, const dx_hull *b, const double n[3])
{
#ifdef DX_SIGNS_AVX2
    if (__builtin_cpu_supports("avx2")) return axis_separates_avx2(a, b, n);
#endif
    double alo, ahi, blo, bhi;
    dx_hull_interval(a, n, &alo, &ahi);
    dx_hull_interval(b, n, &blo, &bhi);
    return bhi - alo < 0 || ahi - blo < 0;
}

// What of a hull's pose the pair test has made (bits of *edges_posed):
// its faces' floors, its edges.
enum { POSED_FLOORS = 1, POSED_EDGES = 2 };

#ifdef DX_SIGNS_AVX2
// pose_floors' first faces four at a time; returns how many it made.
__attribute__((target("avx2"))) static inline unsigned floors4(dx_hull *h, double slack)
{
    const __m256d sl = _mm256_set1_pd(slack);
    unsigned f = 0;
    for (; f + 4 <= h->nplanes; f += 4) {
        __m256d dev = h->plane_dev ? _mm256_loadu_pd(h->plane_dev + f) : _mm256_setzero_pd();
        _mm256_storeu_pd(h->face_low + f,
                         _mm256_sub_pd(_mm256_sub_pd(_mm256_loadu_pd(h->wd + f), dev), sl));
    }
    return f;
}
#endif

// Poses h's faces' floors (once per pose): a floor under n . x over face
// f's polygon, without visiting it: the plane's offset less how far the
// polygon dips under the plane in the hull's frame (plane_dev), less what
// R's departure from a rotation can add (n . x = (n' R^T R x' + ...) /
// |n'|: |E| size, E = R^T R - I), less rounding (the products' sizes
// times 8 units in the last place). With AVX2 (avx2 1, in a function
// built for it) four faces at a time (the same differences).
static inline __attribute__((always_inline)) void pose_floors(dx_hull *h, int avx2)
{
    if (*h->edges_posed & POSED_FLOORS) return;
    double reach = h->size + fabs(h->c[0]) + fabs(h->c[1]) + fabs(h->c[2]);
    double slack = h->rot_err * h->size + 8 * DBL_EPSILON * reach;
    unsigned f = 0;
#ifdef DX_SIGNS_AVX2
    if (avx2) f = floors4(h, slack);
#else
    (void)avx2;
#endif
    for (; f < h->nplanes; f++)
        h->face_low[f] = h->wd[f] - (h->plane_dev ? h->plane_dev[f] : 0) - slack;
    *h->edges_posed |= POSED_FLOORS;
}

// Poses h's edge k: its direction u, its faces' normals' sum, their
// squares, and its circle's normal n2 x n1 (by coordinate).
static inline void pose_edge(dx_hull *h, unsigned k)
{
    const dxHullEdge *e = &h->edges[k];
    dxHullPosedEdge *out = &h->we[k];
    double c[3];
    for (int i = 0; i < 3; i++) {
        out->u[i] = h->wp[e->b][i] - h->wp[e->a][i];
        out->sum[i] = h->wn[e->f1][i] + h->wn[e->f2][i];
    }
    out->uu = dot3(out->u, out->u);
    out->ss = dot3(out->sum, out->sum);
    cross3(h->wn[e->f2], h->wn[e->f1], c);
    h->ex[k] = c[0];
    h->ey[k] = c[1];
    h->ez[k] = c[2];
}

#ifdef DX_SIGNS_AVX2
// pose_edge for edges k to k + 3 at once, their points and normals
// gathered by coordinate (the same differences, sums, products in the
// same order: the same numbers).
_Static_assert(sizeof(dxHullPosedEdge) == 8 * sizeof(double), "a posed edge is eight doubles");
__attribute__((target("avx2"))) static inline void pose_edges4(dx_hull *h, unsigned k)
{
    const dxHullEdge *e = &h->edges[k];
    const double *p[3] = { h->px, h->py, h->pz }, *n[3] = { h->nx, h->ny, h->nz };
    __m256d u[3], s[3], n1[3], n2[3];
    for (int i = 0; i < 3; i++) {
        u[i] = _mm256_sub_pd(load4(p[i], e[0].b, e[1].b, e[2].b, e[3].b),
                             load4(p[i], e[0].a, e[1].a, e[2].a, e[3].a));
        n1[i] = load4(n[i], e[0].f1, e[1].f1, e[2].f1, e[3].f1);
        n2[i] = load4(n[i], e[0].f2, e[1].f2, e[2].f2, e[3].f2);
        s[i] = _mm256_add_pd(n1[i], n2[i]);
    }
    __m256d uu = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(u[0], u[0]), _mm256_mul_pd(u[1], u[1])),
                               _mm256_mul_pd(u[2], u[2]));
    __m256d ss = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(s[0], s[0]), _mm256_mul_pd(s[1], s[1])),
                               _mm256_mul_pd(s[2], s[2]));
    _mm256_storeu_pd(h->ex + k, _mm256_sub_pd(_mm256_mul_pd(n2[1], n1[2]), _mm256_mul_pd(n2[2], n1[1])));
    _mm256_storeu_pd(h->ey + k, _mm256_sub_pd(_mm256_mul_pd(n2[2], n1[0]), _mm256_mul_pd(n2[0], n1[2])));
    _mm256_storeu_pd(h->ez + k, _mm256_sub_pd(_mm256_mul_pd(n2[0], n1[1]), _mm256_mul_pd(n2[1], n1[0])));
    // Each edge's (u, sum, uu, ss): two 4 x 4 transposes.
    __m256d rows[2][4] = { { u[0], u[1], u[2], s[0] }, { s[1], s[2], uu, ss } };
    for (int half = 0; half < 2; half++) {
        __m256d c[4];
        transpose4(rows[half], c);
        for (int l = 0; l < 4; l++)
            _mm256_storeu_pd(half ? &h->we[k + l].sum[1] : h->we[k + l].u, c[l]);
    }
}
#endif

// Poses h's edges (once per pose, when a test first reaches the edge
// pairs: not for pairs that a face axis parts); with AVX2 (avx2 1) four
// at a time.
static inline __attribute__((always_inline)) void pose_edges(dx_hull *h, int avx2)
{
    if (*h->edges_posed & POSED_EDGES) return;
    unsigned k = 0;
#ifdef DX_SIGNS_AVX2
    if (avx2)
        for (; k + 4 <= h->nedges; k += 4) pose_edges4(h, k);
#else
    (void)avx2;
#endif
    for (; k < h->nedges; k++) pose_edge(h, k);
    *h->edges_posed |= POSED_EDGES;
}

// The normal of h's edge k's circle (n2 x n1), as pose_edges made it.
static void edge_circle(const dx_hull *h, unsigned k, double c[3])
{
    c[0] = h->ex[k];
    c[1] = h->ey[k];
    c[2] = h->ez[k];
}

// The signs of c . (x[k], y[k], z[k]) for k >= k0, k < n, made as dot3
// makes them, added to *pos (bit k where above 0) and *neg (below).
static inline void dot_signs_from(const double c[3], const double *x, const double *y,
                                  const double *z, unsigned k0, unsigned n, uint64_t *pos,
                                  uint64_t *neg)
{
    uint64_t p = *pos, q = *neg;
    unsigned k = k0;
#ifdef __SSE2__
    __m128d c0 = _mm_set1_pd(c[0]), c1 = _mm_set1_pd(c[1]), c2 = _mm_set1_pd(c[2]);
    __m128d zero = _mm_setzero_pd();
    for (; k + 2 <= n; k += 2) {
        __m128d d = _mm_add_pd(_mm_add_pd(_mm_mul_pd(c0, _mm_loadu_pd(x + k)),
                                          _mm_mul_pd(c1, _mm_loadu_pd(y + k))),
                               _mm_mul_pd(c2, _mm_loadu_pd(z + k)));
        p |= (uint64_t)_mm_movemask_pd(_mm_cmpgt_pd(d, zero)) << k;
        q |= (uint64_t)_mm_movemask_pd(_mm_cmplt_pd(d, zero)) << k;
    }
#endif
    for (; k < n; k++) {
        double d = c[0] * x[k] + c[1] * y[k] + c[2] * z[k];
        p |= (uint64_t)(d > 0) << k;
        q |= (uint64_t)(d < 0) << k;
    }
    *pos = p;
    *neg = q;
}

#ifdef DX_SIGNS_AVX2
// dot_signs' first products four at a time (the same products and sums,
// no fused multiply-add: the same numbers); returns how many it made.
__attribute__((target("avx2"))) static inline unsigned dot_signs4(const double c[3], const double *x,
                                                          const double *y, const double *z,
                                                          unsigned n, uint64_t *pos,
                                                          uint64_t *neg)
{
    uint64_t p = 0, q = 0;
    unsigned k = 0;
    __m256d c0 = _mm256_set1_pd(c[0]), c1 = _mm256_set1_pd(c[1]), c2 = _mm256_set1_pd(c[2]);
    __m256d zero = _mm256_setzero_pd();
    for (; k + 4 <= n; k += 4) {
        __m256d d = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, _mm256_loadu_pd(x + k)),
                                                _mm256_mul_pd(c1, _mm256_loadu_pd(y + k))),
                                  _mm256_mul_pd(c2, _mm256_loadu_pd(z + k)));
        p |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(d, zero, _CMP_GT_OQ)) << k;
        q |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(d, zero, _CMP_LT_OQ)) << k;
    }
    *pos = p;
    *neg = q;
    return k;
}
#endif

// The signs of c . (x[k], y[k], z[k]) for k < n (made as dot3 makes them):
// bit k of *pos where above 0, of *neg where below; with AVX2 (avx2 is
// then 1, in a function built for it) four at a time.
static inline __attribute__((always_inline)) void dot_signs(const double c[3], const double *x,
                                                             const double *y, const double *z,
                                                             unsigned n, uint64_t *pos,
                                                             uint64_t *neg, int avx2)
{
    unsigned k = 0;
    *pos = *neg = 0;
#ifdef DX_SIGNS_AVX2
    if (avx2) k = dot_signs4(c, x, y, z, n, pos, neg);
#else
    (void)avx2;
#endif
    dot_signs_from(c, x, y, z, k, n, pos, neg);
}

#ifdef DX_SIGNS_AVX2
// dot_signs4 for n = 8 (the same products), without a loop.
__attribute__((target("avx2"))) static inline void dot_signs8(const double c[3], const double *x,
                                                              const double *y, const double *z,
                                                              uint64_t *pos, uint64_t *neg)
{
    __m256d c0 = _mm256_set1_pd(c[0]), c1 = _mm256_set1_pd(c[1]), c2 = _mm256_set1_pd(c[2]);
    __m256d zero = _mm256_setzero_pd();
    __m256d d0 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, _mm256_loadu_pd(x)),
                                             _mm256_mul_pd(c1, _mm256_loadu_pd(y))),
                               _mm256_mul_pd(c2, _mm256_loadu_pd(z)));
    __m256d d1 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, _mm256_loadu_pd(x + 4)),
                                             _mm256_mul_pd(c1, _mm256_loadu_pd(y + 4))),
                               _mm256_mul_pd(c2, _mm256_loadu_pd(z + 4)));
    *pos = (uint64_t)(_mm256_movemask_pd(_mm256_cmp_pd(d0, zero, _CMP_GT_OQ)) |
                      _mm256_movemask_pd(_mm256_cmp_pd(d1, zero, _CMP_GT_OQ)) << 4);
    *neg = (uint64_t)(_mm256_movemask_pd(_mm256_cmp_pd(d0, zero, _CMP_LT_OQ)) |
                      _mm256_movemask_pd(_mm256_cmp_pd(d1, zero, _CMP_LT_OQ)) << 4);
}
#endif

// dot_signs for n a multiple of four (rows padded with zeros: see
// up_to_four): no tail after the fours; eight (a prism's or a box's
// planes, padded) without a loop.
static inline __attribute__((always_inline)) void dot_signs_padded(const double c[3],
                                                                    const double *x,
                                                                    const double *y,
                                                                    const double *z, unsigned n,
                                                                    uint64_t *pos, uint64_t *neg,
                                                                    int avx2)
{
#ifdef DX_SIGNS_AVX2
    if (avx2) {
        if (n == 8)
            dot_signs8(c, x, y, z, pos, neg);
        else
            dot_signs4(c, x, y, z, n, pos, neg);
        return;
    }
#else
    (void)avx2;
#endif
    dot_signs(c, x, y, z, n, pos, neg, 0);
}

// The translation of a along the unit n that parts it from b.
static double depth_along(const dx_hull *a, const dx_hull *b, const double n[3])
{
    double m[3] = { -n[0], -n[1], -n[2] };
    return dx_hull_extent(b, n, NULL) + dx_hull_extent(a, m, NULL);
}

// max over the points of h's face f's polygon of m . x: the hull's extent
// along that face's own normal m (its other points lie below the face).
static double face_extent(const dx_hull *h, unsigned f, const double m[3])
{
    unsigned count;
    const unsigned *idx = dx_hull_polygon(h, f, &count);
    double best = -INFINITY;
    for (unsigned k = 0; k < count; k++) {
        double e = dot3(m, h->wp[idx[k]]);
        best = e > best ? e : best;
    }
    return best;
}

#ifdef DX_SIGNS_AVX2
// dot_max four at a time (the same products; the largest is the same
// number, the order it is found in aside).
__attribute__((target("avx2"))) static inline double dot_max4(const double m[3], const double *x,
                                                             const double *y, const double *z,
                                                             unsigned n)
{
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    __m256d vhi = _mm256_set1_pd(-INFINITY);
    unsigned k = 0;
    for (; k + 4 <= n; k += 4) {
        __m256d e = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(m0, _mm256_loadu_pd(x + k)),
                                                _mm256_mul_pd(m1, _mm256_loadu_pd(y + k))),
                                  _mm256_mul_pd(m2, _mm256_loadu_pd(z + k)));
        vhi = _mm256_max_pd(e, vhi);
    }
    double h4[4];
    _mm256_storeu_pd(h4, vhi);
    double mx = h4[0] > h4[1] ? h4[0] : h4[1];
    mx = h4[2] > mx ? h4[2] : mx;
    mx = h4[3] > mx ? h4[3] : mx;
    for (; k < n; k++) {
        double e = m[0] * x[k] + m[1] * y[k] + m[2] * z[k];
        mx = e > mx ? e : mx;
    }
    return mx;
}
#endif

// dx_hull_extent without the index, four at a time with AVX2 (avx2 1, in
// a function built for it).
static inline __attribute__((always_inline)) double extent_with(const dx_hull *h,
                                                                const double m[3], int avx2)
{
#ifdef DX_SIGNS_AVX2
    if (avx2) return dot_max4(m, h->px, h->py, h->pz, h->npts);
#else
    (void)avx2;
#endif
    return dot_max(m, h->px, h->py, h->pz, h->npts);
}

#ifdef DX_SIGNS_AVX2
// face_extent four polygon points at a time (gathered by coordinate; the
// same products, the largest the same number, the order it is found in
// aside).
__attribute__((target("avx2"))) static inline double face_extent4(const dx_hull *h, unsigned f,
                                                                  const double m[3])
{
    unsigned count;
    const unsigned *idx = dx_hull_polygon(h, f, &count);
    __m256d m0 = _mm256_set1_pd(m[0]), m1 = _mm256_set1_pd(m[1]), m2 = _mm256_set1_pd(m[2]);
    __m256d vhi = _mm256_set1_pd(-INFINITY);
    unsigned k = 0;
    for (; k + 4 <= count; k += 4) {
        __m256d e = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(m0, load4_at(h->px, idx + k)),
                          _mm256_mul_pd(m1, load4_at(h->py, idx + k))),
            _mm256_mul_pd(m2, load4_at(h->pz, idx + k)));
        vhi = _mm256_max_pd(e, vhi);
    }
    vhi = _mm256_max_pd(vhi, _mm256_permute2f128_pd(vhi, vhi, 1));
    double best = _mm256_cvtsd_f64(_mm256_max_pd(vhi, _mm256_permute_pd(vhi, 1)));
    for (; k < count; k++) {
        double e = dot3(m, h->wp[idx[k]]);
        best = e > best ? e : best;
    }
    return best;
}
#endif

// face_extent, with AVX2 (avx2 1, in a function built for it) four points
// at a time where the polygon's indices fit gathers.
static inline __attribute__((always_inline)) double face_extent_with(const dx_hull *h, unsigned f,
                                                                     const double m[3], int avx2)
{
#ifdef DX_SIGNS_AVX2
    if (avx2 && h->npts <= INT32_MAX) return face_extent4(h, f, m);
#else
    (void)avx2;
#endif
    return face_extent(h, f, m);
}

// depth_along for the face axis n of a's face f (side 0: n its inward
// normal) or b's (side 1: its outward normal), the face's own hull's
// extent taken over the face's polygon.
static inline __attribute__((always_inline)) double
face_depth(const dx_hull *a, const dx_hull *b, int side, unsigned f, const double n[3], int avx2)
{
    double m[3] = { -n[0], -n[1], -n[2] };
    return side ? face_extent_with(b, f, n, avx2) + extent_with(a, m, avx2)
                : extent_with(b, n, avx2) + face_extent_with(a, f, m, avx2);
}

// The axis of a's face f (side 0: its inward normal, along which a's face
// pushes a back) or b's (side 1: its outward normal) into n.
static void face_axis(const dx_hull *a, const dx_hull *b, int side, unsigned f, double n[3])
{
    const double *m = side ? b->wn[f] : a->wn[f];
    for (int i = 0; i < 3; i++) n[i] = side ? m[i] : -m[i];
}

// face_gaps for h's faces from f on.
static void face_gaps_from(const dx_hull *h, const double q[3], unsigned f, double *gap)
{
    for (; f < h->nplanes; f++)
        gap[f] = h->face_low[f] - (h->nx[f] * q[0] + h->ny[f] * q[1] + h->nz[f] * q[2]);
}

// The set of faces f, k0 <= f < n (bit f), whose gap[f] is not above x,
// two at a time where SSE2 is there.
static inline uint64_t faces_within_from(const double *gap, unsigned k0, unsigned n, double x)
{
    uint64_t m = 0;
    unsigned f = k0;
#ifdef __SSE2__
    __m128d vx = _mm_set1_pd(x);
    for (; f + 2 <= n; f += 2)
        m |= (uint64_t)_mm_movemask_pd(_mm_cmpngt_pd(_mm_loadu_pd(gap + f), vx)) << f;
#endif
    for (; f < n; f++) m |= (uint64_t)!(gap[f] > x) << f;
    return m;
}

#ifdef DX_SIGNS_AVX2
// face_gaps' first faces four at a time (the same products and sums);
// returns how many it made.
__attribute__((target("avx2"))) static inline unsigned face_gaps4(const dx_hull *h, const double q[3],
                                                                  double *gap)
{
    __m256d q0 = _mm256_set1_pd(q[0]), q1 = _mm256_set1_pd(q[1]), q2 = _mm256_set1_pd(q[2]);
    unsigned f = 0;
    for (; f + 4 <= h->nplanes; f += 4)
        _mm256_storeu_pd(
            gap + f,
            _mm256_sub_pd(_mm256_loadu_pd(h->face_low + f),
                          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(h->nx + f), q0),
                                                      _mm256_mul_pd(_mm256_loadu_pd(h->ny + f), q1)),
                                        _mm256_mul_pd(_mm256_loadu_pd(h->nz + f), q2))));
    return f;
}

// faces_within's first faces four at a time; *k set to how many it went over.
__attribute__((target("avx2"))) static inline uint64_t faces_within4(const double *gap, unsigned n,
                                                                     double x, unsigned *k)
{
    __m256d vx = _mm256_set1_pd(x);
    uint64_t m = 0;
    unsigned f = 0;
    for (; f + 4 <= n; f += 4)
        m |= (uint64_t)_mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(gap + f), vx, _CMP_NGT_UQ))
             << f;
    *k = f;
    return m;
}
#endif

// The gaps of h's faces against q, a point of the other hull: gap[f] =
// low - n . q for the face's unit normal n and a floor under n . x over
// its polygon, low (pose_floors). A floor under the face axis' depth (h's extent along n is
// at least low, the other's along -n at least -n . q), and under the
// depth of every edge pair with an edge of that face over the edge's arc
// (see masked_edge_pairs). With AVX2 (avx2 1, in a function built for it)
// four at a time.
static inline __attribute__((always_inline)) void face_gaps(const dx_hull *h, const double q[3],
                                                            double *gap, int avx2)
{
    unsigned f = 0;
#ifdef DX_SIGNS_AVX2
    if (avx2) f = face_gaps4(h, q, gap);
#else
    (void)avx2;
#endif
    face_gaps_from(h, q, f, gap);
}

// The set of faces f < n (bit f) whose gap[f] is not above x; with AVX2
// (avx2 1) four at a time.
static inline __attribute__((always_inline)) uint64_t faces_within(const double *gap, unsigned n,
                                                                   double x, int avx2)
{
    unsigned k = 0;
    uint64_t m = 0;
#ifdef DX_SIGNS_AVX2
    if (avx2) m = faces_within4(gap, n, x, &k);
#else
    (void)avx2;
#endif
    return m | faces_within_from(gap, k, n, x);
}

// Whether a's arc (from n1 to n2) and b's negated arc (for the difference,
// from -n1 to -n2) cross on the unit sphere: each arc's ends lie on
// opposite sides of the other's great circle, on the same side. cba, dba:
// b's -n1, -n2 against a's circle (n2 x n1); adc, bdc: a's n1, n2
// against b's.
static int arcs_cross(double cba, double dba, double adc, double bdc)
{
    return cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0;
}

// The unit cross product of the posed edges' directions into m; 0 if they
// are parallel.
static int unit_cross(const dxHullPosedEdge *xa, const dxHullPosedEdge *xb, double m[3])
{
    cross3(xa->u, xb->u, m);
    double l2 = dot3(m, m);
    if (l2 <= DX_COLLIDE_EPS * xa->uu * xb->uu) return 0;   // parallel
    double inv = 1 / sqrt(l2);
    for (int k = 0; k < 3; k++) m[k] *= inv;
    return 1;
}

// The unit axis of the edge pair (a's edge i, b's edge j), into m (either
// sign); 0 if the pair can give no face of the Minkowski difference a - b
// (the arcs of the two edges on the unit sphere, between their faces'
// normals, do not cross: the least depth is never there) or the edges are
// parallel. An edge without a second face is always tried. The edges are
// posed.
static int edge_axis(const dx_hull *a, unsigned i, const dx_hull *b, unsigned j, double m[3])
{
    const dxHullEdge *ea = &a->edges[i], *eb = &b->edges[j];
    double ca[3], cb[3];
    edge_circle(a, i, ca);
    edge_circle(b, j, cb);
    if (ea->f1 != ea->f2 && eb->f1 != eb->f2 &&
        !arcs_cross(-dot3(b->wn[eb->f1], ca), -dot3(b->wn[eb->f2], ca),
                    dot3(a->wn[ea->f1], cb), dot3(a->wn[ea->f2], cb)))
        return 0;
    return unit_cross(&a->we[i], &b->we[j], m);
}

// The depths of a along +m (s[0]) and -m (s[1]) against b, from one pass
// over each hull's points.
static void depths_both_ways(const dx_hull *a, const dx_hull *b, const double m[3], double s[2])
{
    double alo, ahi, blo, bhi;
    dx_hull_interval(a, m, &alo, &ahi);
    dx_hull_interval(b, m, &blo, &bhi);
    s[0] = bhi - alo;
    s[1] = ahi - blo;
}

// The depths of a along +m (s[0]) and -m (s[1]) for the axis m of the
// edge pair (a's edge i, b's edge j) that edge_axis accepted. With two
// faces at each edge the pair is a face of the Minkowski difference, whose
// outward normal d is the sign of m between a's faces' normals: the edges
// are then the hulls' supports (a's along d, b's along -d), so a's depth
// along -d is d . (pa - pb) for any points of them. The other sign is no
// face: it bounds neither the depth nor the clearance (infinite).
static void pair_depths(const dx_hull *a, unsigned i, const dx_hull *b, unsigned j,
                        const double m[3], double s[2])
{
    const dxHullEdge *ea = &a->edges[i], *eb = &b->edges[j];
    if (ea->f1 == ea->f2 || eb->f1 == eb->f2) {
        depths_both_ways(a, b, m, s);
        return;
    }
    double n1[3], n2[3], d, pa[3], pb[3];
    dx_hull_plane(a, ea->f1, n1, &d);
    dx_hull_plane(a, ea->f2, n2, &d);
    dx_hull_vertex(a, ea->a, pa);
    dx_hull_vertex(b, eb->a, pb);
    double gap = m[0] * (pa[0] - pb[0]) + m[1] * (pa[1] - pb[1]) + m[2] * (pa[2] - pb[2]);
    if (dot3(m, n1) + dot3(m, n2) > 0) {   // d = m
        s[0] = INFINITY;
        s[1] = gap;
    } else {   // d = -m
        s[0] = -gap;
        s[1] = INFINITY;
    }
}

// Takes the axis n of the edge pair (a's edge i, b's edge j) that
// edge_axis accepted: 0 (n into sep) if it parts the hulls, else the least
// depth kept in edge.
static int edge_pair(const dx_hull *a, unsigned i, const dx_hull *b, unsigned j, double n[3],
                     sat_axis *edge, double sep[3])
{
    double both[2];
    pair_depths(a, i, b, j, n, both);
    if (both[0] < 0 || both[1] < 0) {
        memcpy(sep, n, 3 * sizeof n[0]);
        return 0;
    }
    for (int sg = 0; sg < 2; sg++) {
        if (sg)
            for (int k = 0; k < 3; k++) n[k] = -n[k];
        double s = both[sg];
        if (s < edge->depth) {
            edge->depth = s;
            memcpy(edge->n, n, sizeof edge->n);
            edge->ref = 2;
            edge->ea = i;
            edge->eb = j;
        }
    }
    return 1;
}

// What the edge pairs of sat update: the least edge axis, the pairs kept
// for clearance, the separating axis if one is found, and the depth
// (times the cross product's length) beyond which a pair cannot matter.
typedef struct edge_search {
    sat_axis *edge;
    edge_axes *found;
    double *sep;
    const sat_axis *face;   // the best face axis (final: the edge pairs come after)
    double bound;   // face depth / DX_HULL_EDGE_PREFERENCE: an edge pair deeper never wins
    double thr;     // the least of bound and edge->depth, with a margin for rounding
    double margin;  // a depth's margin for rounding (edge_axes' margin)
} edge_search;

static void update_threshold(edge_search *es)
{
    double least = es->edge->depth < es->bound ? es->edge->depth : es->bound;
    es->thr = least * (1 + 1e-9) + es->margin;
}

// Whether the sign of the unnormalised product x (of the cross product
// c, with c . c = cc, and a vector of square vv) is clear of rounding.
static int clear_sign(double x, double cc, double vv)
{
    return x * x > 1e-12 * cc * vv;
}

// Keeps the pair (a's edge i, b's edge j) for clearance.
static void keep_pair(edge_axes *found, unsigned i, unsigned j)
{
    if (found->n < MAX_EDGE_AXES) {
        found->pair[found->n][0] = i;
        found->pair[found->n++][1] = j;
    } else {
        found->overflow = 1;
    }
}

// 0 if an edge pair (c its unnormalised cross product, c . c = cc, facing
// = c . (n1 + n2) of a's edge, depth its positive depth times |c|) clearly
// cannot lower the clearance along the best face's normal below the face's
// own depth, where clearance starts (see edge_may_clear).
static int may_clear(const edge_search *es, const double c[3], double cc, double facing,
                     double depth)
{
    double cn = dot3(c, es->face->n);
    if (!clear_sign(cn, cc, 1)) return 1;
    if ((facing > 0) == (cn > 0)) return 0;
    return depth <= (es->face->depth * (1 + 1e-9) + es->margin) * fabs(cn);
}

// The edge pair (a's edge i, b's edge j) whose arcs cross: 0 (the axis
// into sep) if its axis parts the hulls; else kept in found if it may
// matter to clearance, and its depth in edge if least. The exact test (edge_axis's
// unit axis, pair_depths, edge_pair) runs only where it can matter: where
// the pair's depth, from the unnormalised cross product c of the edges,
// is not clearly positive or not clearly above the threshold (beyond which
// the pair can be neither the least depth nor win over the best face); a
// pair it skips would not have changed edge. Edges without a second face
// always take the exact test.
static inline int edge_candidate(const dx_hull *a, unsigned i, const dx_hull *b, unsigned j,
                                 edge_search *es)
{
    const dxHullPosedEdge *xa = &a->we[i], *xb = &b->we[j];
    double c[3];
    cross3(xa->u, xb->u, c);
    double cc = dot3(c, c);
    if (cc <= DX_COLLIDE_EPS * xa->uu * xb->uu) return 1;   // parallel: unit_cross's test
    const dxHullEdge *ea = &a->edges[i], *eb = &b->edges[j];
    if (ea->f1 != ea->f2 && eb->f1 != eb->f2) {
        const double *pa = a->wp[ea->a], *pb = b->wp[eb->a];
        double d[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
        double facing = dot3(c, xa->sum), gap = dot3(c, d);
        double depth = facing > 0 ? gap : -gap;   // times |c|
        int sure = clear_sign(facing, cc, xa->ss);
        if (!sure || depth <= 0 || may_clear(es, c, cc, facing, depth)) keep_pair(es->found, i, j);
        if (sure && depth > 0 && depth * depth > es->thr * es->thr * cc) return 1;
    } else {
        keep_pair(es->found, i, j);
    }
    double n[3];
    unit_cross(xa, xb, n);
    if (!edge_pair(a, i, b, j, n, es->edge, es->sep)) return 0;
    update_threshold(es);
    return 1;
}

#ifdef DX_SIGNS_AVX2
// The edge pairs gathered for edge_candidate, in its order, screened four
// at a time first (screen_pairs).
enum { PAIR_BATCH = 64 };
typedef struct pair_batch {
    int32_t i[PAIR_BATCH + 3], j[PAIR_BATCH + 3];   // room for a four's padding (and
                                                      // add_pairs' two past a full batch)
    unsigned n;
} pair_batch;

// Which of the batch's pairs (a's edges pb->i[k], b's edges pb->j[k], k <
// pb->n, the last four padded) edge_candidate would leave alone (bit k):
// no pair kept, no exact test, as it finds them with the threshold
// es->thr or any lower one (the threshold only falls): parallel edges, or
// a depth clearly positive and clearly above the threshold that may_clear
// does not keep. Four pairs at a time, with the same products, sums and
// comparisons as edge_candidate's (no fused multiply-add: the same
// numbers; a NaN compares false there as here). Lone edges are not looked
// at here (the caller keeps their pairs).
__attribute__((target("avx2"), always_inline)) static inline uint64_t
screen_pairs(const dx_hull *a, const dx_hull *b, const pair_batch *pb, const edge_search *es)
{
    const double *pa[3] = { a->px, a->py, a->pz }, *pb3[3] = { b->px, b->py, b->pz };
    const __m256d zero = _mm256_setzero_pd(), sign = _mm256_set1_pd(-0.0);
    const __m256d tiny = _mm256_set1_pd(1e-12), one = _mm256_set1_pd(1);
    const __m256d eps = _mm256_set1_pd((double)DX_COLLIDE_EPS), thr = _mm256_set1_pd(es->thr);
    const __m256d n0 = _mm256_set1_pd(es->face->n[0]), n1 = _mm256_set1_pd(es->face->n[1]);
    const __m256d n2 = _mm256_set1_pd(es->face->n[2]);
    const __m256d reach = _mm256_set1_pd(es->face->depth * (1 + 1e-9) + es->margin);
    uint64_t alone = 0;
    for (unsigned k = 0; k < pb->n; k += 4) {
        // Each lane's posed edges (u, sum, uu, ss: eight doubles) by rows,
        // transposed into numbers by lane; its edges' first points (index a).
        const dxHullPosedEdge *ea[4], *eb[4];
        size_t va[4], vb[4];
        for (int l = 0; l < 4; l++) {
            ea[l] = &a->we[pb->i[k + l]];
            eb[l] = &b->we[pb->j[k + l]];
            va[l] = a->edges[pb->i[k + l]].a;
            vb[l] = b->edges[pb->j[k + l]].a;
        }
        __m256d r[4], lo[4], hi[4], bl[4];
        for (int l = 0; l < 4; l++) r[l] = _mm256_loadu_pd(ea[l]->u);   // u, sum[0]
        transpose4(r, lo);
        for (int l = 0; l < 4; l++) r[l] = _mm256_loadu_pd(&ea[l]->sum[1]);   // sum[1, 2], uu, ss
        transpose4(r, hi);
        for (int l = 0; l < 4; l++) r[l] = _mm256_loadu_pd(eb[l]->u);
        transpose4(r, bl);
        __m256d ua[3] = { lo[0], lo[1], lo[2] }, sa[3] = { lo[3], hi[0], hi[1] };
        __m256d ub[3] = { bl[0], bl[1], bl[2] }, d[3];
        const __m256d uua = hi[2], ssa = hi[3];
        const __m256d uub = _mm256_setr_pd(eb[0]->uu, eb[1]->uu, eb[2]->uu, eb[3]->uu);
        for (int q = 0; q < 3; q++)
            d[q] = _mm256_sub_pd(load4(pa[q], va[0], va[1], va[2], va[3]),
                                 load4(pb3[q], vb[0], vb[1], vb[2], vb[3]));
        __m256d c0 = _mm256_sub_pd(_mm256_mul_pd(ua[1], ub[2]), _mm256_mul_pd(ua[2], ub[1]));
        __m256d c1 = _mm256_sub_pd(_mm256_mul_pd(ua[2], ub[0]), _mm256_mul_pd(ua[0], ub[2]));
        __m256d c2 = _mm256_sub_pd(_mm256_mul_pd(ua[0], ub[1]), _mm256_mul_pd(ua[1], ub[0]));
#define DOT4(x0, x1, x2) \
    _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, x0), _mm256_mul_pd(c1, x1)), _mm256_mul_pd(c2, x2))
        __m256d cc = DOT4(c0, c1, c2), facing = DOT4(sa[0], sa[1], sa[2]);
        __m256d gap = DOT4(d[0], d[1], d[2]), cn = DOT4(n0, n1, n2);
#undef DOT4
        __m256d parallel = _mm256_cmp_pd(cc, _mm256_mul_pd(_mm256_mul_pd(eps, uua), uub), _CMP_LE_OQ);
        __m256d faces_up = _mm256_cmp_pd(facing, zero, _CMP_GT_OQ);
        __m256d depth = _mm256_blendv_pd(_mm256_xor_pd(gap, sign), gap, faces_up);
        __m256d tiny_cc = _mm256_mul_pd(tiny, cc);
        __m256d sure = _mm256_cmp_pd(_mm256_mul_pd(facing, facing), _mm256_mul_pd(tiny_cc, ssa),
                                     _CMP_GT_OQ);
        __m256d positive = _mm256_cmp_pd(depth, zero, _CMP_GT_OQ);
        // may_clear keeps the pair unless cn's sign is clear and either
        // faces the pair's way or leaves the depth beyond reach times |cn|.
        __m256d cn_sure = _mm256_cmp_pd(_mm256_mul_pd(cn, cn), _mm256_mul_pd(tiny_cc, one),
                                        _CMP_GT_OQ);
        __m256d against = _mm256_xor_pd(faces_up, _mm256_cmp_pd(cn, zero, _CMP_GT_OQ));
        __m256d within = _mm256_cmp_pd(depth, _mm256_mul_pd(reach, _mm256_andnot_pd(sign, cn)),
                                       _CMP_LE_OQ);
        __m256d cleared = _mm256_andnot_pd(_mm256_and_pd(against, within), cn_sure);
        __m256d beyond = _mm256_cmp_pd(_mm256_mul_pd(depth, depth),
                                       _mm256_mul_pd(_mm256_mul_pd(thr, thr), cc), _CMP_GT_OQ);
        __m256d skipped = _mm256_and_pd(_mm256_and_pd(cleared, sure), _mm256_and_pd(positive, beyond));
        alone |= (uint64_t)_mm256_movemask_pd(_mm256_or_pd(parallel, skipped)) << k;
    }
    return alone;
}

// Adds the pairs of a's edge i with b's edges in the set cand (count of
// them, room for them in the batch) in order: the first two written
// whether there are two or not (past the count: not read), the rest (rare)
// one by one, so that how many there are is not a branch.
static inline void add_pairs(pair_batch *pb, unsigned i, uint64_t cand, unsigned count)
{
    const uint64_t stop = (uint64_t)1 << 63;   // what a missing pair's edge reads as
    unsigned n = pb->n;
    uint64_t rest = cand & (cand - 1);
    pb->i[n] = pb->i[n + 1] = (int32_t)i;
    pb->j[n] = (int32_t)__builtin_ctzll(cand | stop);
    pb->j[n + 1] = (int32_t)__builtin_ctzll(rest | stop);
    for (rest &= rest - 1, n += 2; rest; rest &= rest - 1, n++) {
        pb->i[n] = (int32_t)i;
        pb->j[n] = (int32_t)__builtin_ctzll(rest);
    }
    pb->n += count;
}

// edge_candidate for the batch's pairs in order, but for those the screen
// leaves alone (that would do nothing there); 0 (the axis into es->sep) as
// soon as one parts the hulls. Empties the batch.
__attribute__((target("avx2"))) static int flush_pairs(const dx_hull *a, const dx_hull *b,
                                                       pair_batch *pb, edge_search *es)
{
    unsigned n = pb->n, first = (n - 1) & ~3u;   // n > 0: the last four's first pair
    for (unsigned k = n; k < n + 3; k++) {   // that four padded with it (past it: unread)
        pb->i[k] = pb->i[first];
        pb->j[k] = pb->j[first];
    }
    uint64_t to_test = ~screen_pairs(a, b, pb, es);
    if (n < 64) to_test &= ((uint64_t)1 << n) - 1;
    if (a->lone || b->lone)
        for (unsigned k = 0; k < n; k++)
            to_test |= (uint64_t)((a->lone >> pb->i[k] | b->lone >> pb->j[k]) & 1) << k;
    pb->n = 0;
    for (; to_test; to_test &= to_test - 1) {
        unsigned k = (unsigned)__builtin_ctzll(to_test);
        if (!edge_candidate(a, (unsigned)pb->i[k], b, (unsigned)pb->j[k], es)) return 0;
    }
    return 1;
}
#endif

// The edge pairs of sat for hulls whose edges and faces fit 64-bit masks.
// edge_axis's arc test asks, of a's edge i (faces f1, f2) and b's edge j
// (faces g1, g2), for the signs of the products of each edge's circle
// normal (n2 x n1) with the other hull's face normals: b's g1, g2 on
// opposite sides of i's circle (S), a's f1, f2 on opposite sides of j's
// (U), and g1 below i's circle where f2 is above j's or the reverse (W).
// Each product is made once, into masks: for a's edge i the sets of b's
// faces above and below its circle, turned into sets of b's edges by their
// first and second face; for a's face f the sets of b's edges whose
// circle it is above and below. Then the pairs that pass are, for each i,
// the set bits of S & U & W, visited in edge_axis's order. An edge
// without a second face meets every edge. Edges whose every pair is
// clearly deeper than the best face are left out: such a pair can neither
// part the hulls, nor win, nor lower the clearance. Where an edge pair is
// a face of the Minkowski difference its normal d lies on the edge's arc
// (between its faces' outward normals) and its depth is the hull's extent
// along d, d . p for p on the edge, plus the other's along -d, at least
// -d . q for the other's point q: at least the least of d . (p - q) over
// the arc, which (the arc shorter than a half circle) is at one of its
// ends when both are positive, each end at least its face's gap (gap_a
// for a's faces against b's point, gap_b for b's against a's).
enum { MASK_BITS = 64 };

// n rounded up to a multiple of four: a hull's normals and edge circles by
// coordinate hold that many, zero past n (no sign: no bit in dot_signs).
static inline unsigned up_to_four(unsigned n)
{
    return (n + 3) & ~3u;
}

#ifdef DX_SIGNS_AVX2
// The edges of h whose first face is in the set faces (of h's faces: as
// the union of by_f1 over them) into *first, and whose second face is
// into *second, from h->edge_faces: a byte per face (all set if the face
// is in the set) looked up by each edge's face index, thirty-two edges at
// once (an index of 0x80 past the edges looks up zero).
__attribute__((target("avx2"))) static inline void edges_of_faces(const dx_hull *h,
                                                                  uint64_t faces,
                                                                  uint64_t *first,
                                                                  uint64_t *second)
{
    const __m128i pick = _mm_setr_epi8(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
    const __m128i bit = _mm_setr_epi8(1, 2, 4, 8, 16, 32, 64, -128, 1, 2, 4, 8, 16, 32, 64, -128);
    __m128i spread = _mm_shuffle_epi8(_mm_cvtsi32_si128((int)faces), pick);
    __m256i in = _mm256_broadcastsi128_si256(_mm_cmpeq_epi8(_mm_and_si128(spread, bit), bit));
    const __m256i *row = (const __m256i *)h->edge_faces;
    *first = (uint32_t)_mm256_movemask_epi8(_mm256_shuffle_epi8(in, _mm256_loadu_si256(row)));
    *second = (uint32_t)_mm256_movemask_epi8(_mm256_shuffle_epi8(in, _mm256_loadu_si256(row + 1)));
}
#endif

#ifdef DX_SIGNS_AVX2
// The circles' normals (n2 x n1) of b's edges in the set edges, in order,
// by coordinate into x, y, z, zero past them up to a multiple of four (no
// sign: no bit in dot_signs4); returns that multiple.
static inline unsigned pack_circles(const dx_hull *b, uint64_t edges, double *x, double *y,
                                    double *z)
{
    unsigned n = 0;
    for (; edges; edges &= edges - 1, n++) {
        unsigned j = (unsigned)__builtin_ctzll(edges);
        x[n] = b->ex[j];
        y[n] = b->ey[j];
        z[n] = b->ez[j];
    }
    for (unsigned k = n; k % 4; k++) x[k] = y[k] = z[k] = 0;
    return up_to_four(n);
}

// face_signs_near for at most eight near edges: their circles gathered
// into registers (lanes past them zero), each face's products with them
// made as dot_signs4 makes them.
__attribute__((target("avx2,bmi2"))) static inline void
face_signs_near8(const dx_hull *a, const dx_hull *b, uint64_t faces, uint64_t near,
                 uint64_t *above, uint64_t *below)
{
    unsigned idx[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    int n = 0;
    for (uint64_t e = near; e; e &= e - 1) idx[n++] = (unsigned)__builtin_ctzll(e);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(n), lane);
    __m256d m0 = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm256_castsi256_si128(live)));
    __m256d m1 = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm256_extracti128_si256(live, 1)));
    const __m256d zero = _mm256_setzero_pd();
    // Lanes past n read edge 0 (their index), then are masked to +0.
    __m256d x0 = _mm256_and_pd(load4_at(b->ex, idx), m0);
    __m256d y0 = _mm256_and_pd(load4_at(b->ey, idx), m0);
    __m256d z0 = _mm256_and_pd(load4_at(b->ez, idx), m0);
    __m256d x1 = _mm256_and_pd(load4_at(b->ex, idx + 4), m1);
    __m256d y1 = _mm256_and_pd(load4_at(b->ey, idx + 4), m1);
    __m256d z1 = _mm256_and_pd(load4_at(b->ez, idx + 4), m1);
    for (; faces; faces &= faces - 1) {
        unsigned f = (unsigned)__builtin_ctzll(faces);
        __m256d c0 = _mm256_set1_pd(a->wn[f][0]), c1 = _mm256_set1_pd(a->wn[f][1]);
        __m256d c2 = _mm256_set1_pd(a->wn[f][2]);
        __m256d d0 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, x0), _mm256_mul_pd(c1, y0)),
                                   _mm256_mul_pd(c2, z0));
        __m256d d1 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c0, x1), _mm256_mul_pd(c1, y1)),
                                   _mm256_mul_pd(c2, z1));
        uint64_t p = (uint64_t)(_mm256_movemask_pd(_mm256_cmp_pd(d0, zero, _CMP_GT_OQ)) |
                                _mm256_movemask_pd(_mm256_cmp_pd(d1, zero, _CMP_GT_OQ)) << 4);
        uint64_t q = (uint64_t)(_mm256_movemask_pd(_mm256_cmp_pd(d0, zero, _CMP_LT_OQ)) |
                                _mm256_movemask_pd(_mm256_cmp_pd(d1, zero, _CMP_LT_OQ)) << 4);
        above[f] = _pdep_u64(p, near);
        below[f] = _pdep_u64(q, near);
    }
}

// For each of a's faces f in the set faces, the sets of b's edges in
// near (at most 64) whose circle f's normal is above (above[f]) and
// below (below[f]): the products of the near edges' circles alone, packed
// (pack_circles), their bits put back in place by pdep; no bit for the
// other edges.
__attribute__((target("avx2,bmi2"))) static inline void
face_signs_near(const dx_hull *a, const dx_hull *b, uint64_t faces, uint64_t near,
                uint64_t *above, uint64_t *below)
{
    if (__builtin_popcountll(near) <= 8) {
        face_signs_near8(a, b, faces, near, above, below);
        return;
    }
    double x[MASK_BITS], y[MASK_BITS], z[MASK_BITS];
    unsigned n = pack_circles(b, near, x, y, z);
    for (; faces; faces &= faces - 1) {
        unsigned f = (unsigned)__builtin_ctzll(faces);
        uint64_t p, q;
        dot_signs4(a->wn[f], x, y, z, n, &p, &q);
        above[f] = _pdep_u64(p, near);
        below[f] = _pdep_u64(q, near);
    }
}
#endif

// The edges of b whose first face is in the set faces, and whose second
// face is, into *first and *second (by_f1 and by_f2 over the set's faces);
// with AVX2 (avx2 1) by edges_of_faces where b has its edges' faces as
// bytes.
static inline __attribute__((always_inline)) void
edge_sets(const dx_hull *b, uint64_t faces, uint64_t *first, uint64_t *second, int avx2)
{
#ifdef DX_SIGNS_AVX2
    if (avx2 && b->edge_faces) {
        edges_of_faces(b, faces, first, second);
        return;
    }
#else
    (void)avx2;
#endif
    uint64_t f1 = 0, f2 = 0;
    for (; faces; faces &= faces - 1) {
        unsigned f = (unsigned)__builtin_ctzll(faces);
        f1 |= b->by_f1[f];
        f2 |= b->by_f2[f];
    }
    *first = f1;
    *second = f2;
}

static inline __attribute__((always_inline)) int
masked_edge_pairs_with(const dx_hull *a, const dx_hull *b, edge_search *es, const double *gap_a,
                       const double *gap_b, int avx2)
{
    uint64_t above[MASK_BITS], below[MASK_BITS];   // by a's face: b's edges
    const uint64_t *first = b->by_f1, *second = b->by_f2, lone = b->lone;
    uint64_t all = b->nedges == MASK_BITS ? ~(uint64_t)0 : ((uint64_t)1 << b->nedges) - 1;
    uint64_t b_planes = b->nplanes == MASK_BITS ? ~(uint64_t)0 : ((uint64_t)1 << b->nplanes) - 1;
    double far = es->face->depth * (1 + 1e-9) + 2 * es->margin;
    // The near edges (and lone ones), and the faces of a's near faces' edges.
    uint64_t near_a = a->lone, near_b = lone, faces = 0;
    for (uint64_t m = faces_within(gap_a, a->nplanes, far, avx2); m; m &= m - 1) {
        unsigned f = (unsigned)__builtin_ctzll(m);
        near_a |= a->by_f1[f] | a->by_f2[f];
        faces |= a->nbr[f];   // the faces of f's edges
    }
    for (uint64_t m = faces_within(gap_b, b->nplanes, far, avx2); m; m &= m - 1) {
        unsigned f = (unsigned)__builtin_ctzll(m);
        near_b |= first[f] | second[f];
    }
#ifdef DX_SIGNS_AVX2
    if (avx2) {   // only the near edges' signs count (cand is within near_b)
        face_signs_near(a, b, faces, near_b, above, below);
        faces = 0;
    }
#endif
    for (; faces; faces &= faces - 1) {
        unsigned f = (unsigned)__builtin_ctzll(faces);
        dot_signs_padded(a->wn[f], b->ex, b->ey, b->ez, up_to_four(b->nedges), &above[f],
                         &below[f], avx2);
    }
    // a's edges that can have candidates: the near ones, or all if b has
    // lone edges (which meet every edge).
    uint64_t visit = !lone ? near_a
                     : a->nedges == MASK_BITS ? ~(uint64_t)0
                                              : ((uint64_t)1 << a->nedges) - 1;
#ifdef DX_SIGNS_AVX2
    // With AVX2, hulls with their edges' faces as bytes (at most 32 edges)
    // screen their pairs four at a time.
    int screened = avx2 && a->edge_faces && b->edge_faces;
    pair_batch batch;
    batch.n = 0;
#endif
    for (; visit; visit &= visit - 1) {
        unsigned i = (unsigned)__builtin_ctzll(visit);
        const dxHullEdge *ea = &a->edges[i];
        uint64_t cand = all;
        if (!(near_a >> i & 1)) {
            cand = lone;
        } else if (ea->f1 != ea->f2) {
            uint64_t first_pos, first_neg, second_pos, second_neg, pos, neg;
            double circle[3];
            edge_circle(a, i, circle);
            dot_signs_padded(circle, b->nx, b->ny, b->nz, up_to_four(b->nplanes), &pos, &neg,
                             avx2);
            edge_sets(b, pos, &first_pos, &second_pos, avx2);
            if ((pos | neg) == b_planes) {   // each edge has one first and one second face
                first_neg = all & ~first_pos;
                second_neg = all & ~second_pos;
            } else {
                edge_sets(b, neg, &first_neg, &second_neg, avx2);
            }
            uint64_t s = (first_pos & second_neg) | (first_neg & second_pos);
            uint64_t u = (above[ea->f1] & below[ea->f2]) | (below[ea->f1] & above[ea->f2]);
            uint64_t w = (first_neg & above[ea->f2]) | (first_pos & below[ea->f2]);
            cand = (s & u & w & near_b) | lone;
        }
#ifdef DX_SIGNS_AVX2
        if (screened) {
            unsigned count = (unsigned)__builtin_popcountll(cand);   // at most 32: b's edges
            if (batch.n + count > PAIR_BATCH && !flush_pairs(a, b, &batch, es)) return 0;
            add_pairs(&batch, i, cand, count);
            continue;
        }
#endif
        for (; cand; cand &= cand - 1) {
            unsigned j = (unsigned)__builtin_ctzll(cand);
            if (!edge_candidate(a, i, b, j, es)) return 0;
        }
    }
#ifdef DX_SIGNS_AVX2
    if (screened && batch.n) return flush_pairs(a, b, &batch, es);
#endif
    return 1;
}

// The point of the box h (a box made into a hull, collide_convex_hull.c:
// its corner 7 is its half sides) nearest p, into q: p taken into the box's
// frame, clamped to a hair inside its sides (so that the rounding of the
// pose back leaves it in the box, well within the screens' margins), posed
// back.
static void box_point_near(const dx_hull *h, const double p[3], double q[3])
{
    const dReal *half = h->pts + 21;
    double d[3] = { p[0] - h->c[0], p[1] - h->c[1], p[2] - h->c[2] }, l[3];
    for (int k = 0; k < 3; k++) {
        double x = h->R[k] * d[0] + h->R[3 + k] * d[1] + h->R[6 + k] * d[2];
        double lim = half[k] * (1 - 1e-12);
        l[k] = x > lim ? lim : x < -lim ? -lim : x;
    }
    for (int i = 0; i < 3; i++)
        q[i] = h->c[i] + h->R[3 * i] * l[0] + h->R[3 * i + 1] * l[1] + h->R[3 * i + 2] * l[2];
}

// Points of each hull (qa of a, qb of b), for the gaps (any point of the
// hull bounds them; the nearer the other hull, the tighter): the hint's,
// else each hull's point furthest towards the other's centre (into the
// hint); for a box, its point nearest the other's centre instead (a large
// box's corners are far from where it meets the other hull), into the
// room at qa_box, qb_box.
static void facing_points(const dx_hull *a, const dx_hull *b, sat_hint *hint,
                          const double **qa, const double **qb, double qa_box[3],
                          double qb_box[3])
{
    if (hint->side < 0 || hint->qa >= a->npts || hint->qb >= b->npts) {
        double ab[3] = { b->centre[0] - a->centre[0], b->centre[1] - a->centre[1],
                         b->centre[2] - a->centre[2] };
        double ba[3] = { -ab[0], -ab[1], -ab[2] };
        dx_hull_extent(a, ab, &hint->qa);
        dx_hull_extent(b, ba, &hint->qb);
    }
    *qa = a->wp[hint->qa];
    *qb = b->wp[hint->qb];
    if (!a->convex) {
        box_point_near(a, b->centre, qa_box);
        *qa = qa_box;
    }
    if (!b->convex) {
        box_point_near(b, a->centre, qb_box);
        *qb = qb_box;
    }
}

// The face axis of a's face f (side 0) or b's (side 1), of depth *known
// if that is given (else measured here): 0 (the axis into sep) if it parts
// the hulls; else its depth kept in found (if it keeps faces), and in face
// if least.
static inline __attribute__((always_inline)) int
face_test(const dx_hull *a, const dx_hull *b, int side, unsigned f, const double *known,
          sat_axis *face, edge_axes *found, double sep[3], int avx2)
{
    double n[3];
    face_axis(a, b, side, f, n);
    double s = known ? *known : face_depth(a, b, side, f, n, avx2);
    if (s < 0) {
        memcpy(sep, n, 3 * sizeof n[0]);
        return 0;
    }
    if (found->faces_kept) found->face_s[side][f] = s;
    if (s < face->depth) {
        face->depth = s;
        memcpy(face->n, n, sizeof face->n);
        face->ref = side;
        face->face = f;
    }
    return 1;
}

// dx_hull_sat, built once for AVX2 (avx2 1) and once for any machine.
static inline __attribute__((always_inline)) int
sat_with(dx_hull *a, dx_hull *b, sat_hint *hint, sat_axis *face, sat_axis *edge,
         edge_axes *found, double sep[3], int avx2)
{
    found->n = found->overflow = 0;
    found->faces_kept = a->nplanes <= KEPT_FACES && b->nplanes <= KEPT_FACES;
    double scale = a->size + b->size;
    for (int i = 0; i < 3; i++) scale += fabs(a->c[i]) + fabs(b->c[i]);
    found->margin = 1e-12 * scale;
    face->depth = edge->depth = INFINITY;
    pose_floors(a, avx2);
    pose_floors(b, avx2);
    // A face's depth is at least its gap: faces clearly deeper than a first
    // guess (the hinted face, else the face of least gap) are skipped.
    double gaps[2][MASK_BITS], guess = INFINITY;
    int gapped = a->nplanes <= MASK_BITS && b->nplanes <= MASK_BITS, gside = -1;
    unsigned gface = 0;
    if (gapped) {
        const double *qa, *qb;
        double qa_box[3], qb_box[3];
        facing_points(a, b, hint, &qa, &qb, qa_box, qb_box);
        face_gaps(a, qb, gaps[0], avx2);
        face_gaps(b, qa, gaps[1], avx2);
        if (hint->side >= 0 && hint->face < (hint->side ? b : a)->nplanes) {
            gside = hint->side;
            gface = hint->face;
        } else {
            gside = 0;
            for (int side = 0; side < 2; side++) {
                const dx_hull *h = side ? b : a;
                for (unsigned f = 0; f < h->nplanes; f++) {
                    if (gaps[side][f] < guess) {
                        guess = gaps[side][f];
                        gside = side;
                        gface = f;
                    }
                }
            }
        }
        double n[3];
        face_axis(a, b, gside, gface, n);
        guess = face_depth(a, b, gside, gface, n, avx2);
        if (guess < 0) {
            memcpy(sep, n, sizeof n);
            return 0;
        }
        // The faces to measure: those not clearly deeper than the guess
        // (found->tested; face_s is set for them only).
        double limit = guess * (1 + 1e-9) + 2 * found->margin;
        for (int side = 0; side < 2; side++) {
            const dx_hull *h = side ? b : a;
            uint64_t near = faces_within(gaps[side], h->nplanes, limit, avx2);
            found->tested[side] = near;
            for (; near; near &= near - 1) {
                unsigned f = (unsigned)__builtin_ctzll(near);
                const double *known = side == gside && f == gface ? &guess : NULL;
                if (!face_test(a, b, side, f, known, face, found, sep, avx2)) return 0;
            }
        }
    } else {
        for (int side = 0; side < 2; side++) {
            const dx_hull *h = side ? b : a;
            for (unsigned f = 0; f < h->nplanes; f++)
                if (!face_test(a, b, side, f, NULL, face, found, sep, avx2)) return 0;
        }
    }
    pose_edges(a, avx2);
    pose_edges(b, avx2);
    edge_search es = { edge, found, sep, face, face->depth / DX_HULL_EDGE_PREFERENCE, 0,
                       found->margin };
    update_threshold(&es);
    if (gapped && a->by_f1 && b->by_f1)
        return masked_edge_pairs_with(a, b, &es, gaps[0], gaps[1], avx2);
    for (unsigned i = 0; i < a->nedges; i++) {
        for (unsigned j = 0; j < b->nedges; j++) {
            double n[3];
            if (edge_axis(a, i, b, j, n) && !edge_candidate(a, i, b, j, &es)) return 0;
        }
    }
    return 1;
}

#ifdef DX_SIGNS_AVX2
__attribute__((target("avx2,bmi2"))) static int sat_avx2(dx_hull *a, dx_hull *b, sat_hint *hint,
                                                    sat_axis *face, sat_axis *edge,
                                                    edge_axes *found, double sep[3])
{
    return sat_with(a, b, hint, face, edge, found, sep, 1);
}
#endif

int dx_hull_sat(dx_hull *a, dx_hull *b, sat_hint *hint, sat_axis *face, sat_axis *edge,
                edge_axes *found, double sep[3])
{
#ifdef DX_SIGNS_AVX2
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2"))
        return sat_avx2(a, b, hint, face, edge, found, sep);
#endif
    return sat_with(a, b, hint, face, edge, found, sep, 0);
}

// What the edge pair axis m (either sign; s its depths along +m and -m)
// allows a to move along n before parting from b: s(m) / (m . n) with m
// turned to face n; infinite if m is square to n.
static double edge_clearance(const double n[3], const double m[3], const double s[2])
{
    double mn = dot3(m, n);
    if (mn == 0) return INFINITY;
    return mn > 0 ? s[0] / mn : s[1] / -mn;
}

// 0 if the kept edge pair (a's edge i, b's edge j) clearly cannot lower
// the clearance best along n: its face of the Minkowski difference faces
// away from n (edge_clearance infinite), or its ratio, from the
// unnormalised cross product, is clearly above best. Edges without a
// second face always count.
static int edge_may_clear(const dx_hull *a, unsigned i, const dx_hull *b, unsigned j,
                          const double n[3], double best, double margin)
{
    const dxHullEdge *ea = &a->edges[i], *eb = &b->edges[j];
    if (ea->f1 == ea->f2 || eb->f1 == eb->f2) return 1;
    const dxHullPosedEdge *xa = &a->we[i], *xb = &b->we[j];
    double c[3];
    cross3(xa->u, xb->u, c);
    double cc = dot3(c, c), facing = dot3(c, xa->sum), cn = dot3(c, n);
    if (!clear_sign(facing, cc, xa->ss) || !clear_sign(cn, cc, 1)) return 1;
    if ((facing > 0) == (cn > 0)) return 0;
    const double *pa = a->wp[ea->a], *pb = b->wp[eb->a];
    double d[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
    double gap = dot3(c, d), depth = facing > 0 ? gap : -gap;
    return depth <= (best * (1 + 1e-9) + margin) * fabs(cn);
}

// fmin(a, b) without the library's call (the clearance takes one per
// face): the other where one is a NaN, else a < b ? a : b, so that of a
// +0 and a -0 b is kept, as the library's minsd keeps it.
static inline double least(double a, double b)
{
    return b != b ? a : a < b ? a : b;
}

#ifdef DX_SIGNS_AVX2
// The face axes' part of dx_hull_clearance where found keeps the faces'
// depths, without a branch per face: each face's m . n made four at a time
// (as dot3 makes it, from the padded normal rows; a's axes are its normals
// turned, m . n = -(n_f . n) but for the sign of a zero, which m . n > 0
// leaves out either way), its s / m . n (s infinite for a face not tested;
// no number for a face not facing n, which least passes over), then
// least taken over the faces in dx_hull_clearance's order (best is never
// a NaN: it starts at a depth that is one).
__attribute__((target("avx2"))) static double faces_clearance4(const dx_hull *a, const dx_hull *b,
                                                               const double n[3], double best,
                                                               const edge_axes *found)
{
    const __m256d n0 = _mm256_set1_pd(n[0]), n1 = _mm256_set1_pd(n[1]), n2 = _mm256_set1_pd(n[2]);
    const __m256d inf = _mm256_set1_pd(INFINITY), nan = _mm256_set1_pd(NAN);
    const __m256d zero = _mm256_setzero_pd();
    const __m256i lane_bit = _mm256_setr_epi64x(1, 2, 4, 8);
    __m128d least_so_far = _mm_set_sd(best);
    for (int side = 0; side < 2; side++) {
        const dx_hull *h = side ? b : a;
        const __m256d turn = _mm256_set1_pd(side ? 0.0 : -0.0);
        double ratio[KEPT_FACES];
        for (unsigned f = 0; f < h->nplanes; f += 4) {
            __m256d mn = _mm256_xor_pd(
                _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(h->nx + f), n0),
                                            _mm256_mul_pd(_mm256_loadu_pd(h->ny + f), n1)),
                              _mm256_mul_pd(_mm256_loadu_pd(h->nz + f), n2)),
                turn);
            __m256i bits = _mm256_set1_epi64x((long long)(found->tested[side] >> f & 15));
            __m256i tested = _mm256_cmpeq_epi64(_mm256_and_si256(bits, lane_bit), lane_bit);
            __m256d s = _mm256_blendv_pd(
                inf, _mm256_maskload_pd(found->face_s[side] + f, tested), _mm256_castsi256_pd(tested));
            __m256d facing = _mm256_cmp_pd(mn, zero, _CMP_GT_OQ);
            _mm256_storeu_pd(ratio + f, _mm256_blendv_pd(nan, _mm256_div_pd(s, mn), facing));
        }
        for (unsigned f = 0; f < h->nplanes; f++) {   // least(best, ratio): no NaN taken
            __m128d r = _mm_load_sd(ratio + f);
            least_so_far = _mm_blendv_pd(least_so_far, r, _mm_cmple_sd(r, least_so_far));
        }
    }
    return _mm_cvtsd_f64(least_so_far);
}
#endif

// The exact translation of a along the unit n that parts it from b (as
// box_clearance in collide_box.c): a moved by t n is clear of b along a
// candidate axis m once t (m . n) > s(m); the least such t over the axes
// facing n. The candidates hold every face normal of the Minkowski
// difference, so this is exact; it is at most s_n, the depth along n.
double dx_hull_clearance(const dx_hull *a, const dx_hull *b, const double n[3], double s_n,
                         const edge_axes *found)
{
    double best = s_n;
#ifdef DX_SIGNS_AVX2
    if (found->faces_kept && __builtin_cpu_supports("avx2")) {
        best = faces_clearance4(a, b, n, best, found);
    } else
#endif
    for (int side = 0; side < 2; side++) {
        const dx_hull *h = side ? b : a;
        for (unsigned f = 0; f < h->nplanes; f++) {
            double m[3], d;
            dx_hull_plane(h, f, m, &d);
            if (!side)
                for (int i = 0; i < 3; i++) m[i] = -m[i];
            double mn = dot3(m, n);
            if (mn > 0) {
                double s = !found->faces_kept              ? depth_along(a, b, m)
                           : found->tested[side] >> f & 1 ? found->face_s[side][f]
                                                          : INFINITY;
                best = least(best, s / mn);
            }
        }
    }
    for (int k = 0; !found->overflow && k < found->n; k++) {
        unsigned i = found->pair[k][0], j = found->pair[k][1];
        if (!edge_may_clear(a, i, b, j, n, best, found->margin)) continue;
        double m[3], both[2];
        unit_cross(&a->we[i], &b->we[j], m);
        pair_depths(a, i, b, j, m, both);
        best = least(best, edge_clearance(n, m, both));
    }
    for (unsigned i = 0; found->overflow && i < a->nedges; i++) {
        for (unsigned j = 0; j < b->nedges; j++) {
            double m[3], both[2];
            if (!edge_axis(a, i, b, j, m)) continue;
            pair_depths(a, i, b, j, m, both);
            best = least(best, edge_clearance(n, m, both));
        }
    }
    return best;
}
