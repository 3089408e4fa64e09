// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_ray.c -- trimesh-ray, as ODE 0.16 with OPCODE: one
// contact per triangle the ray crosses within its length (nearest first, at
// most the flags' count; only the nearest with the ray's ClosestHit or
// FirstContact set), backfaces skipped with BackfaceCull. Each hit that
// could be kept (not beyond the farthest of the hits kept once there are as
// many as wanted) goes through the ray callback (with its barycentric u, v)
// and the per-triangle callback. pos is the hit point, depth its distance
// from the ray's start, normal the triangle's normal reversed (into the
// mesh, g1); side1 the triangle.

#include "collide_trimesh.h"

#include <ode/memory.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#if defined(__SSE__)
#include <emmintrin.h>
#endif

// The ray (start s, unit direction v, mesh frame) against the triangle of
// vertices tri (Moller-Trumbore): 1 with the distance and the barycentric u (of v1) and
// v (of v2) if it crosses within [0, len].
static int ray_triangle(const dReal s[3], const dReal v[3], dReal len, const dReal tri[3][3],
                        int cull, dReal *dist, dReal *bu, dReal *bv)
{
    const dReal *a = tri[0];
    dReal e1[3], e2[3], p[3], tv[3], qv[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = tri[1][i] - a[i];
        e2[i] = tri[2][i] - a[i];
        tv[i] = s[i] - a[i];
    }
    p[0] = v[1] * e2[2] - v[2] * e2[1];
    p[1] = v[2] * e2[0] - v[0] * e2[2];
    p[2] = v[0] * e2[1] - v[1] * e2[0];
    dReal det = dx_dot(e1, p);   // > 0: the ray meets the front face
    dReal scale = dx_dot(e1, e1) * dx_dot(e2, e2);
    if (cull ? det <= 0 : dFabs(det) * dFabs(det) <= scale * DX_COLLIDE_EPS * DX_COLLIDE_EPS)
        return 0;
    dReal inv = 1 / det;
    dReal u = dx_dot(tv, p) * inv;
    if (u < 0 || u > 1) return 0;
    qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
    qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
    qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
    dReal w = dx_dot(v, qv) * inv;
    if (w < 0 || u + w > 1) return 0;
    dReal d = dx_dot(e2, qv) * inv;
    if (d < 0 || d > len) return 0;
    *dist = d;
    *bu = u;
    *bv = w;
    return 1;
}

#if defined(__SSE2__) && !defined(dSINGLE)
// ray_triangle for two triangles at once (9 numbers each, t0 in lane 0 and
// t1 in lane 1): the same operations in the same order, so the same bits
// (no fused operations: SSE2), each test passing as the scalar one does
// (also for a NaN). Bit l of the result is set if triangle l is crossed,
// with dist[l], bu[l], bv[l].
static inline unsigned ray_triangle_pair(const dReal s[3], const dReal v[3], dReal len,
                                         const dReal *t0, const dReal *t1, int cull,
                                         dReal dist[2], dReal bu[2], dReal bv[2])
{
    __m128d e1[3], e2[3], tv[3], vv[3];
    for (int i = 0; i < 3; i++) {
        __m128d a = _mm_set_pd(t1[i], t0[i]);
        e1[i] = _mm_sub_pd(_mm_set_pd(t1[3 + i], t0[3 + i]), a);
        e2[i] = _mm_sub_pd(_mm_set_pd(t1[6 + i], t0[6 + i]), a);
        tv[i] = _mm_sub_pd(_mm_set1_pd(s[i]), a);
        vv[i] = _mm_set1_pd(v[i]);
    }
#define MUL _mm_mul_pd
#define SUB _mm_sub_pd
#define DOT(a, b) _mm_add_pd(_mm_add_pd(MUL(a[0], b[0]), MUL(a[1], b[1])), MUL(a[2], b[2]))
    __m128d p[3] = { SUB(MUL(vv[1], e2[2]), MUL(vv[2], e2[1])),
                     SUB(MUL(vv[2], e2[0]), MUL(vv[0], e2[2])),
                     SUB(MUL(vv[0], e2[1]), MUL(vv[1], e2[0])) };
    __m128d det = DOT(e1, p), zero = _mm_setzero_pd(), one = _mm_set1_pd(1);
    __m128d ok;
    if (cull) {
        ok = _mm_cmpnle_pd(det, zero);
    } else {
        __m128d abs = _mm_andnot_pd(_mm_set1_pd(-0.0), det);
        __m128d eps = _mm_set1_pd(DX_COLLIDE_EPS);
        __m128d scale = MUL(DOT(e1, e1), DOT(e2, e2));
        ok = _mm_cmpnle_pd(MUL(abs, abs), MUL(MUL(scale, eps), eps));
    }
    __m128d inv = _mm_div_pd(one, det);
    __m128d u = MUL(DOT(tv, p), inv);
    ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpnlt_pd(u, zero), _mm_cmpngt_pd(u, one)));
    __m128d qv[3] = { SUB(MUL(tv[1], e1[2]), MUL(tv[2], e1[1])),
                      SUB(MUL(tv[2], e1[0]), MUL(tv[0], e1[2])),
                      SUB(MUL(tv[0], e1[1]), MUL(tv[1], e1[0])) };
    __m128d w = MUL(DOT(vv, qv), inv);
    ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpnlt_pd(w, zero),
                                   _mm_cmpngt_pd(_mm_add_pd(u, w), one)));
    __m128d dd = MUL(DOT(e2, qv), inv);
    ok = _mm_and_pd(ok, _mm_and_pd(_mm_cmpnlt_pd(dd, zero), _mm_cmpngt_pd(dd, _mm_set1_pd(len))));
#undef MUL
#undef SUB
#undef DOT
    _mm_storeu_pd(dist, dd);
    _mm_storeu_pd(bu, u);
    _mm_storeu_pd(bv, w);
    return (unsigned)_mm_movemask_pd(ok);
}
#endif

#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__) && !defined(dSINGLE)
#define DX_RAY_AVX2 1
#include <immintrin.h>

// ray_triangle for a leaf's triangles four at once (1 <= count <= 4, the
// triangles at t, 9 numbers each; lanes past the last repeat it and are
// masked off): the same operations in the same order per lane as
// ray_triangle_pair (no fused operations: the target has no FMA), so the
// same bits. Bit l of the result is set if triangle l is crossed, with
// dist[l], bu[l], bv[l].
__attribute__((target("avx2"))) static inline unsigned
ray_triangle_quad(const dReal s[3], const dReal v[3], dReal len, const dReal *t, int count,
                  int cull, dReal dist[4], dReal bu[4], dReal bv[4])
{
    const int l1 = count > 1 ? 9 : 0, l2 = count > 2 ? 18 : l1, l3 = count > 3 ? 27 : l2;
    const dReal *const row[4] = { t, t + l1, t + l2, t + l3 };
    // c[i]: number i of the four triangles, lane l triangle l's; numbers
    // 0-7 as two 4 x 4 transposes of the triangles' rows, 8 gathered.
    __m256d c[9];
    for (int h = 0; h < 8; h += 4) {
        const __m256d r0 = _mm256_loadu_pd(row[0] + h), r1 = _mm256_loadu_pd(row[1] + h);
        const __m256d r2 = _mm256_loadu_pd(row[2] + h), r3 = _mm256_loadu_pd(row[3] + h);
        const __m256d e01 = _mm256_unpacklo_pd(r0, r1), o01 = _mm256_unpackhi_pd(r0, r1);
        const __m256d e23 = _mm256_unpacklo_pd(r2, r3), o23 = _mm256_unpackhi_pd(r2, r3);
        c[h] = _mm256_permute2f128_pd(e01, e23, 0x20);
        c[h + 1] = _mm256_permute2f128_pd(o01, o23, 0x20);
        c[h + 2] = _mm256_permute2f128_pd(e01, e23, 0x31);
        c[h + 3] = _mm256_permute2f128_pd(o01, o23, 0x31);
    }
    c[8] = _mm256_set_pd(row[3][8], row[2][8], row[1][8], row[0][8]);
    __m256d e1[3], e2[3], tv[3], vv[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = _mm256_sub_pd(c[3 + i], c[i]);
        e2[i] = _mm256_sub_pd(c[6 + i], c[i]);
        tv[i] = _mm256_sub_pd(_mm256_set1_pd(s[i]), c[i]);
        vv[i] = _mm256_set1_pd(v[i]);
    }
#define MUL _mm256_mul_pd
#define SUB _mm256_sub_pd
#define DOT(a, b) _mm256_add_pd(_mm256_add_pd(MUL(a[0], b[0]), MUL(a[1], b[1])), MUL(a[2], b[2]))
    __m256d p[3] = { SUB(MUL(vv[1], e2[2]), MUL(vv[2], e2[1])),
                     SUB(MUL(vv[2], e2[0]), MUL(vv[0], e2[2])),
                     SUB(MUL(vv[0], e2[1]), MUL(vv[1], e2[0])) };
    __m256d det = DOT(e1, p), zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1);
    __m256d ok;
    if (cull) {
        ok = _mm256_cmp_pd(det, zero, _CMP_NLE_UQ);
    } else {
        __m256d abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), det);
        __m256d eps = _mm256_set1_pd(DX_COLLIDE_EPS);
        __m256d scale = MUL(DOT(e1, e1), DOT(e2, e2));
        ok = _mm256_cmp_pd(MUL(abs, abs), MUL(MUL(scale, eps), eps), _CMP_NLE_UQ);
    }
    __m256d inv = _mm256_div_pd(one, det);
    __m256d u = MUL(DOT(tv, p), inv);
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(u, zero, _CMP_NLT_UQ),
                                         _mm256_cmp_pd(u, one, _CMP_NGT_UQ)));
    __m256d qv[3] = { SUB(MUL(tv[1], e1[2]), MUL(tv[2], e1[1])),
                      SUB(MUL(tv[2], e1[0]), MUL(tv[0], e1[2])),
                      SUB(MUL(tv[0], e1[1]), MUL(tv[1], e1[0])) };
    __m256d w = MUL(DOT(vv, qv), inv);
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(w, zero, _CMP_NLT_UQ),
                                         _mm256_cmp_pd(_mm256_add_pd(u, w), one, _CMP_NGT_UQ)));
    __m256d dd = MUL(DOT(e2, qv), inv);
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(dd, zero, _CMP_NLT_UQ),
                                         _mm256_cmp_pd(dd, _mm256_set1_pd(len), _CMP_NGT_UQ)));
#undef MUL
#undef SUB
#undef DOT
    _mm256_storeu_pd(dist, dd);
    _mm256_storeu_pd(bu, u);
    _mm256_storeu_pd(bv, w);
    return (unsigned)_mm256_movemask_pd(ok) & ((1u << count) - 1);
}
#endif

// The ray as the general slot test takes it (mesh frame, in float): its
// start s, the inverses of its direction's components, and per axis a slack
// that covers every rounding of a crossing computed in float (the start's,
// the difference's, the inverse's and the product's: together under
// 8 2^-24 m |inv|, m the largest coordinate in play, the box's or the
// start's; the slack is 64 2^-24 m |inv|), so that each slab's [near, far]
// holds the exact one. The tests can only keep a box an exact test would
// drop, never drop one it would keep: the walk finds the hits of an exact
// walk. An axis the ray runs along (|v| under 1e-30, or 0) is tested as a
// slab the start must lie in, [s_lo, s_hi]: the start widened by how far
// the ray moves along that axis and by the slack in length (64 2^-24 m:
// the triangle test's rounding, see ray_setup_lanes), and a float step
// more each side. Each
// number is there four times, as the four slots take it (one load, not a
// load and a shuffle per node). This test serves the rays the plane test
// (ray_planes) cannot take: along an axis, or so far out that a product
// could overflow.
typedef struct ray_lanes {
    float s[3][4], inv[3][4], slack[3][4], s_lo[3][4], s_hi[3][4];
    int along[3];
} ray_lanes;

// The common ray as the plane test takes it. Per axis the node's plane it
// enters by is known from the direction's sign (lo for a positive
// component, hi for a negative one: byte offsets at[k] and at[3 + k] in
// a node, a row of planes_at), and the crossing (P - s) / v of a plane P is taken as
// P inv + c with inv = (float)(1 / v) and the start folded into
// c_near = below(-s inv - slack), c_far = above(-s inv + slack) (in double,
// then rounded outwards to float), the slack as ray_lanes' (64 2^-24 m |inv|
// + FLT_MIN). Conservative: against the exact crossing T = (P - s) / v the
// float inverse moves (P - s) inv by at most 2^-24 |P - s| |inv| <=
// 2^-23 m |inv|, the product P inv's rounding by 2^-24 m |inv|, the sum's
// rounding by 2^-24 (2 m |inv| + slack), the double arithmetic of c by
// far less; c itself is rounded away from the slab. Together under
// 6 2^-24 m |inv| + 2^-24 slack + FLT_MIN's share for underflow, which the
// slack covers: near <= T <= far for every used slot, so the test may keep
// a box the exact test drops, never drop one it keeps. Taken only when
// every |v| >= 1e-30 and m |inv| <= 2^64 (no product or constant near
// overflow). Unused slots (lo = +inf, hi = -inf) give near = +inf or
// far = -inf and fail without their count's mask (inv is finite and not 0,
// so no NaN). Each number four times, 16-byte aligned, as the lanes take it.
typedef struct ray_planes {
    _Alignas(16) float inv[3][4];
    _Alignas(16) float c_near[3][4];
    _Alignas(16) float c_far[3][4];
    const int *at;
} ray_planes;

// Per direction's signs (bit k set for a positive component k) the byte
// offsets in a node of the planes a ray enters by on each axis (lo's for
// a positive component, hi's otherwise), then of those it leaves by: a
// ray's row is chosen once, nothing is stored per axis.
#define RAY_LO_AT(k) ((int)(offsetof(dxTriMeshNode, lo) + sizeof(float[4]) * (k)))
#define RAY_HI_AT(k) ((int)(offsetof(dxTriMeshNode, hi) + sizeof(float[4]) * (k)))
#define RAY_NEAR_AT(p, k) ((p) >> (k) & 1 ? RAY_LO_AT(k) : RAY_HI_AT(k))
#define RAY_FAR_AT(p, k) ((p) >> (k) & 1 ? RAY_HI_AT(k) : RAY_LO_AT(k))
#define RAY_PLANES_AT(p)                                                                       \
    { RAY_NEAR_AT(p, 0), RAY_NEAR_AT(p, 1), RAY_NEAR_AT(p, 2),                                 \
      RAY_FAR_AT(p, 0),  RAY_FAR_AT(p, 1),  RAY_FAR_AT(p, 2) }
static const int planes_at[8][6] = { RAY_PLANES_AT(0), RAY_PLANES_AT(1), RAY_PLANES_AT(2),
                                     RAY_PLANES_AT(3), RAY_PLANES_AT(4), RAY_PLANES_AT(5),
                                     RAY_PLANES_AT(6), RAY_PLANES_AT(7) };
#undef RAY_PLANES_AT
#undef RAY_FAR_AT
#undef RAY_NEAR_AT
#undef RAY_HI_AT
#undef RAY_LO_AT

// Set the four lanes of a ray_lanes or ray_planes number.
static inline void set_lanes(float lanes[4], float f)
{
#if defined(__SSE__)
    _mm_storeu_ps(lanes, _mm_set1_ps(f));
#else
    for (int j = 0; j < 4; j++) lanes[j] = f;
#endif
}

// The general test's numbers (ray_lanes) for the ray from s along v over len.
static void ray_setup_lanes(ray_lanes *r, const dxTriMeshData *d, const dReal s[3],
                            const dReal v[3], dReal len)
{
    for (int k = 0; k < 3; k++) {
        set_lanes(r->s[k], (float)s[k]);
        r->along[k] = !(dFabs(v[k]) >= (dReal)1e-30);
        set_lanes(r->inv[k], 0);
        set_lanes(r->slack[k], 0);
        set_lanes(r->s_lo[k], 0);
        set_lanes(r->s_hi[k], 0);
        dReal m = dMax(dFabs(s[k]), dMax(dFabs(d->lo[k]), dFabs(d->hi[k])));
        if (r->along[k]) {
            // Widened, beyond how far the ray moves along the axis, by the
            // other axes' slack in length (64 2^-24 m): the triangle test's
            // rounding can take a crossing that far outside a triangle's
            // box (in single, a ray along y at x = -0.49999994 crosses, by
            // the test, a triangle whose x ends at -0.5), and the walk must
            // not drop a triangle the test would take.
            dReal reach = dFabs(v[k]) * len + 32 * (dReal)FLT_EPSILON * m;
            set_lanes(r->s_lo[k], nextafterf(dxFloatBelow(s[k] - reach), -INFINITY));
            set_lanes(r->s_hi[k], nextafterf(dxFloatAbove(s[k] + reach), INFINITY));
            continue;
        }
        dReal inv = 1 / v[k], slack = 32 * (dReal)FLT_EPSILON * m * dFabs(inv) + FLT_MIN;
        set_lanes(r->inv[k], (float)inv);
        set_lanes(r->slack[k], slack < FLT_MAX ? (float)slack : FLT_MAX);
    }
}

// The plane test's numbers (ray_planes) for the ray from s along v: 0 if
// the ray needs the general test (an axis it runs along, or coordinates
// and inverses whose products could come near a float's range).
static int ray_setup_planes(ray_planes *r, const dxTriMeshData *d, const dReal s[3],
                            const dReal v[3])
{
    double c_near[3], c_far[3];
    int positive = 0;
    for (int k = 0; k < 3; k++) {
        const double vk = (double)v[k], sk = (double)s[k];
        if (!(fabs(vk) >= 1e-30)) return 0;
        const double lo = fabs((double)d->lo[k]), hi = fabs((double)d->hi[k]);
        const double box = lo > hi ? lo : hi, m = fabs(sk) > box ? fabs(sk) : box;
        const float inv = (float)(1 / vk);
        const double reach = m * fabs((double)inv);
        if (!(reach <= 0x1p64)) return 0;
        const double slack = 32 * (double)FLT_EPSILON * reach + FLT_MIN, c = -sk * inv;
        set_lanes(r->inv[k], inv);
        c_near[k] = c - slack;
        c_far[k] = c + slack;
        positive |= (vk > 0) << k;
    }
    r->at = planes_at[positive];
    // Rounded outwards to float, the three axes at once where SSE2 allows
    // (the rounding's side follows the data: as branches, a predictor's
    // misses).
#if defined(__SSE2__) && !defined(dSINGLE)
    const __m128 below = dxFloatStep3(c_near, 0), above = dxFloatStep3(c_far, 1);
    _mm_store_ps(r->c_near[0], _mm_shuffle_ps(below, below, 0x00));
    _mm_store_ps(r->c_near[1], _mm_shuffle_ps(below, below, 0x55));
    _mm_store_ps(r->c_near[2], _mm_shuffle_ps(below, below, 0xaa));
    _mm_store_ps(r->c_far[0], _mm_shuffle_ps(above, above, 0x00));
    _mm_store_ps(r->c_far[1], _mm_shuffle_ps(above, above, 0x55));
    _mm_store_ps(r->c_far[2], _mm_shuffle_ps(above, above, 0xaa));
#else
    for (int k = 0; k < 3; k++) {
        set_lanes(r->c_near[k], dxFloatBelow(c_near[k]));
        set_lanes(r->c_far[k], dxFloatAbove(c_far[k]));
    }
#endif
    return 1;
}

#if defined(DX_RAY_AVX2)
// dxFloatStep3 for the four lanes of x (in 256 bits): each float below
// (up = 0) or above x, the same conversion, comparison and step per lane.
__attribute__((target("avx2"))) static inline __m128 float_step4(__m256d x, int up)
{
    const __m128 f = _mm256_cvtpd_ps(x);
    const __m256d g = _mm256_cvtps_pd(f);
    const __m256d w = up ? _mm256_cmp_pd(g, x, _CMP_LT_OS) : _mm256_cmp_pd(g, x, _CMP_GT_OS);
    // The lanes whose float is on the wrong side of x, as 32-bit masks.
    const __m128i wrong = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(
        _mm256_castpd_si256(w), _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
    // Up: +1 for a positive float, -1 for a negative one (down: the opposite).
    const __m128i bits = _mm_castps_si128(f);
    const __m128i step = _mm_and_si128(wrong, _mm_or_si128(_mm_srai_epi32(bits, 31),
                                                           _mm_set1_epi32(1)));
    return _mm_castsi128_ps(up ? _mm_add_epi32(bits, step) : _mm_sub_epi32(bits, step));
}

// x[0], x[1], x[2] and a zero in the lanes of 256 bits.
__attribute__((target("avx2"))) static inline __m256d load3(const double x[3])
{
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(x)), _mm_load_sd(x + 2), 1);
}

// ray_setup_planes with the three axes in the lanes of 256-bit registers
// (lane 3 a zero start and direction, unused): the same operations per
// axis, so the same numbers, with one division, no branch per axis and
// one test of the failing cases. The direction's components too small for
// the plane test are divided as 1 (their results unused) so that no lane
// divides by zero where the scalar set-up returns first.
__attribute__((target("avx2"))) static inline int
ray_setup_planes_avx2(ray_planes *r, const dxTriMeshData *d, const dReal s[3], const dReal v[3])
{
    const __m256d sign = _mm256_set1_pd(-0.0), one = _mm256_set1_pd(1);
    const __m256d vv = load3(v), sv = load3(s);
    const __m256d lo = _mm256_andnot_pd(sign, load3(d->lo));
    const __m256d hi = _mm256_andnot_pd(sign, load3(d->hi));
    const __m256d m = _mm256_max_pd(_mm256_andnot_pd(sign, sv), _mm256_max_pd(lo, hi));
    const __m256d tiny = _mm256_cmp_pd(_mm256_andnot_pd(sign, vv), _mm256_set1_pd(1e-30),
                                       _CMP_NGE_UQ);
    const __m128 invf = _mm256_cvtpd_ps(_mm256_div_pd(one, _mm256_blendv_pd(vv, one, tiny)));
    const __m256d inv = _mm256_cvtps_pd(invf);
    const __m256d reach = _mm256_mul_pd(m, _mm256_andnot_pd(sign, inv));
    const __m256d far_out = _mm256_cmp_pd(reach, _mm256_set1_pd(0x1p64), _CMP_NLE_UQ);
    if (_mm256_movemask_pd(_mm256_or_pd(tiny, far_out)) & 7) return 0;
    const __m256d slack = _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(32 * (double)FLT_EPSILON),
                                                      reach),
                                        _mm256_set1_pd(FLT_MIN));
    const __m256d c = _mm256_mul_pd(_mm256_xor_pd(sv, sign), inv);
    const __m128 below = float_step4(_mm256_sub_pd(c, slack), 0);
    const __m128 above = float_step4(_mm256_add_pd(c, slack), 1);
    _mm_store_ps(r->inv[0], _mm_permute_ps(invf, 0x00));
    _mm_store_ps(r->inv[1], _mm_permute_ps(invf, 0x55));
    _mm_store_ps(r->inv[2], _mm_permute_ps(invf, 0xaa));
    _mm_store_ps(r->c_near[0], _mm_permute_ps(below, 0x00));
    _mm_store_ps(r->c_near[1], _mm_permute_ps(below, 0x55));
    _mm_store_ps(r->c_near[2], _mm_permute_ps(below, 0xaa));
    _mm_store_ps(r->c_far[0], _mm_permute_ps(above, 0x00));
    _mm_store_ps(r->c_far[1], _mm_permute_ps(above, 0x55));
    _mm_store_ps(r->c_far[2], _mm_permute_ps(above, 0xaa));
    const __m256d positive = _mm256_cmp_pd(vv, _mm256_setzero_pd(), _CMP_GT_OQ);
    r->at = planes_at[_mm256_movemask_pd(positive) & 7];
    return 1;
}
#endif

// Which of the node's slots the ray enters within [0, limit]: bit j set,
// and enter[j], at most where it enters. Per axis the slab's crossings
// (lo - s) inv and (hi - s) inv, the nearer less the slack and the farther
// plus it; the latest near against the earliest far. The four slots side
// by side: one SSE operation each, or a loop the compiler may make one.
#if defined(__SSE__)
static inline unsigned ray_slots(const ray_lanes *r, const dxTriMeshNode *node, float limit,
                                 float enter[4])
{
    __m128 t0 = _mm_setzero_ps(), t1 = _mm_set1_ps(limit);
    __m128i count = _mm_loadu_si128((const __m128i *)node->count);
    __m128 ok = _mm_castsi128_ps(_mm_cmpgt_epi32(count, _mm_set1_epi32(-1)));
    for (int k = 0; k < 3; k++) {
        __m128 lo = _mm_loadu_ps(node->lo[k]), hi = _mm_loadu_ps(node->hi[k]);
        if (r->along[k]) {
            ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmple_ps(lo, _mm_loadu_ps(r->s_hi[k])),
                                           _mm_cmpge_ps(hi, _mm_loadu_ps(r->s_lo[k]))));
            continue;
        }
        __m128 sk = _mm_loadu_ps(r->s[k]), ik = _mm_loadu_ps(r->inv[k]);
        __m128 slack = _mm_loadu_ps(r->slack[k]);
        __m128 a = _mm_mul_ps(_mm_sub_ps(lo, sk), ik), b = _mm_mul_ps(_mm_sub_ps(hi, sk), ik);
        t0 = _mm_max_ps(t0, _mm_sub_ps(_mm_min_ps(a, b), slack));
        t1 = _mm_min_ps(t1, _mm_add_ps(_mm_max_ps(a, b), slack));
    }
    _mm_storeu_ps(enter, t0);
    return (unsigned)_mm_movemask_ps(_mm_and_ps(ok, _mm_cmple_ps(t0, t1)));
}

// ray_slots for a ray_planes ray: per axis the entry plane's crossing
// P inv + c_near and the exit plane's P inv + c_far, no minimum, maximum or
// branch per axis, no count mask (see ray_planes).
static inline unsigned ray_slots_planes(const ray_planes *r, const dxTriMeshNode *node,
                                        float limit, float enter[4])
{
    const char *b = (const char *)node;
    __m128 t0 = _mm_setzero_ps(), t1 = _mm_set1_ps(limit);
    for (int k = 0; k < 3; k++) {
        const __m128 inv = _mm_load_ps(r->inv[k]);
        const __m128 near = _mm_mul_ps(_mm_load_ps((const float *)(b + r->at[k])), inv);
        const __m128 far = _mm_mul_ps(_mm_load_ps((const float *)(b + r->at[3 + k])), inv);
        t0 = _mm_max_ps(t0, _mm_add_ps(near, _mm_load_ps(r->c_near[k])));
        t1 = _mm_min_ps(t1, _mm_add_ps(far, _mm_load_ps(r->c_far[k])));
    }
    _mm_storeu_ps(enter, t0);
    return (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1));
}
#else
static inline unsigned ray_slots(const ray_lanes *r, const dxTriMeshNode *node, float limit,
                                 float enter[4])
{
    float t0[4] = { 0, 0, 0, 0 }, t1[4] = { limit, limit, limit, limit };
    int ok[4];
    for (int j = 0; j < 4; j++) ok[j] = node->count[j] >= 0;
    for (int k = 0; k < 3; k++) {
        if (r->along[k]) {
            for (int j = 0; j < 4; j++)
                ok[j] &= node->lo[k][j] <= r->s_hi[k][j] && node->hi[k][j] >= r->s_lo[k][j];
            continue;
        }
        for (int j = 0; j < 4; j++) {
            float a = (node->lo[k][j] - r->s[k][j]) * r->inv[k][j];
            float b = (node->hi[k][j] - r->s[k][j]) * r->inv[k][j];
            float near = (a < b ? a : b) - r->slack[k][j], far = (a < b ? b : a) + r->slack[k][j];
            t0[j] = near > t0[j] ? near : t0[j];
            t1[j] = far < t1[j] ? far : t1[j];
        }
    }
    unsigned m = 0;
    for (int j = 0; j < 4; j++) {
        enter[j] = t0[j];
        if (ok[j] && t0[j] <= t1[j]) m |= 1u << j;
    }
    return m;
}

static inline unsigned ray_slots_planes(const ray_planes *r, const dxTriMeshNode *node,
                                        float limit, float enter[4])
{
    const char *b = (const char *)node;
    float t0[4] = { 0, 0, 0, 0 }, t1[4] = { limit, limit, limit, limit };
    for (int k = 0; k < 3; k++) {
        const float *pn = (const float *)(b + r->at[k]), *pf = (const float *)(b + r->at[3 + k]);
        for (int j = 0; j < 4; j++) {
            float near = pn[j] * r->inv[k][j] + r->c_near[k][j];
            float far = pf[j] * r->inv[k][j] + r->c_far[k][j];
            t0[j] = near > t0[j] ? near : t0[j];
            t1[j] = far < t1[j] ? far : t1[j];
        }
    }
    unsigned m = 0;
    for (int j = 0; j < 4; j++) {
        enter[j] = t0[j];
        if (t0[j] <= t1[j]) m |= 1u << j;
    }
    return m;
}
#endif

// Every line the bytes [p, p + size) touch (size > 0): they need not start
// a line, so the last byte's line too (a loop from p's line would run a
// count of times that varies with the alignment, which a predictor misses).
// Two lines a turn (the second may be the line after the last: a prefetch
// does not fault), half the loop's counting.
static inline __attribute__((always_inline)) void prefetch_bytes(const void *p, size_t size)
{
    for (size_t k = 0; k < size; k += 128) {
        __builtin_prefetch((const char *)p + k);
        __builtin_prefetch((const char *)p + k + 64);
    }
    __builtin_prefetch((const char *)p + size - 1);
}

// The faces of a leaf's triangles (1 <= count <= DX_TRI_LEAF_MAX: a leaf
// of the built tree, the only kind with a leaf copy), asked for when the
// walk comes to the leaf: a hit reads its index and normal there, one line
// a triangle in leaf order, addressed without order[] (through order[] the
// normal was two misses in turn). Without a loop: a triangle past the
// leaf's last is clamped to its last, which asks for a line again (the
// loop's count, 3 or 4, was a branch a predictor missed).
static inline __attribute__((always_inline)) void prefetch_faces(const dxTriMeshData *d,
                                                                 int first, int count)
{
    for (int t = 0; t < DX_TRI_LEAF_MAX; t++)
        __builtin_prefetch(&d->leaf_faces[first + (t < count ? t : count - 1)]);
}

// A subtree of at most this many triangles (a node over four leaves) has
// its vertices asked for with its node.
enum { SPAN_AHEAD = 16 };

// Ask for the vertices of the triangles under nodes[i] if they are few
// (node_span), when the walk comes to the node: they arrive
// while the node and its leaves' nodes are read and tested (the leaves
// under it read nothing else before a hit). The span's address needs only
// i, so the request leaves with the node's own. `built` (a constant of
// each inlined walk): the tree is known to have its leaf copy and spans
// (made together), not looked at per node. Inlined always: GCC finds a
// function that only prefetches free of side effects and drops the calls.
static inline __attribute__((always_inline)) void prefetch_span(const dxTriMeshData *d, int i,
                                                                const int built)
{
    if (!built && !d->node_span) return;
    const int *span = d->node_span + 2 * i;
    if (span[1] > SPAN_AHEAD) return;
    prefetch_bytes(d->leaf_vertices + 9 * span[0], 9 * sizeof(dReal) * (size_t)span[1]);
}

// Ask for the first two lines a stacked slot's visit reads, while the
// slots before it are walked: an inner slot's node (its two lines from a
// line's start), a leaf's first vertices (its others came with its
// parent's span when the parent's subtree was small) or, without a leaf
// copy, its indices. The address is chosen without a branch (inner or
// leaf follows the data).
static inline __attribute__((always_inline)) void
prefetch_slot(const dxTriMeshData *d, const dxTriMeshNode *node, int j, const int built)
{
    const int first = node->first[j];
    const char *inner = (const char *)&d->nodes[first];
    const char *leaf = built || d->leaf_vertices ? (const char *)(d->leaf_vertices + 9 * first)
                                                 : (const char *)(d->order + first);
    const char *p = node->count[j] == 0 ? inner : leaf;
    __builtin_prefetch(p);
    __builtin_prefetch(p + 64);
}

// The hits kept so far, nearest first: in a local array when few are
// wanted (a ray's usual one), else in the scratch set's raw array. Only
// depth, tri and n (the triangle's normal) are set.
typedef struct ray_hits {
    dxTriMeshRaw *raw;
    int count;
} ray_hits;

// Hits kept in a local array (no scratch set, so no nesting limit) for
// rays wanting at most this many.
enum { RAY_LOCAL_HITS = 4 };

// Keep the nearest `max` hits in h sorted by distance (then triangle):
// insert this one at its place, the farthest dropping out when full.
static void keep_hit(ray_hits *h, int max, dReal dist, int tri, const dReal n[3])
{
    int k = h->count;
    if (k == max) {
        const dxTriMeshRaw *last = &h->raw[max - 1];
        if (dist > last->depth || (dist == last->depth && tri > last->tri)) return;
    } else {
        h->count++;
    }
    while (k > 0 && (h->raw[k - 1].depth > dist ||
                     (h->raw[k - 1].depth == dist && h->raw[k - 1].tri > tri))) {
        if (k < max) h->raw[k] = h->raw[k - 1];
        k--;
    }
    h->raw[k].depth = dist;
    h->raw[k].tri = tri;
    for (int i = 0; i < 3; i++) h->raw[k].n[i] = n[i];
}

// A slot the walk visits: the inner node at nodes[first] (count 0) or the
// leaf of count triangles from leaf-order first; count -1: none.
typedef struct ray_slot {
    int first, count;
} ray_slot;

// What visit_node leaves for the walk: the slot to visit at once (the
// nearest one the ray enters, or none) and the stack's new top.
typedef struct ray_next {
    ray_slot slot;
    int top;
} ray_next;

// The slots of nodes[i] that the ray enters within limit_up (the limit
// rounded up to a float): the nearest is visited at once, unless it lies
// beyond limit (as a popped slot would be skipped), and the others are
// stacked above stack[top - 1], the farthest first, with where the ray
// enters them. This is the order of pushing every slot and popping the top
// at once, without the push and the pop. One slot or two (most nodes deep
// in the tree) without branches on their number or order (j1 is j0 when
// one, and the slot stored above the top is not counted); ties in slot
// order. The test is the plane test when `planes` (a constant of each
// inlined walk), the general one otherwise; `built` as prefetch_slot's.
// (The top is a value, not a pointer: through a pointer each store to the
// stack would reload it.)
static inline __attribute__((always_inline)) ray_next
visit_node(const dxTriMeshData *d, int i, const ray_lanes *r, const ray_planes *rp,
           const int planes, const int built, dReal limit, float limit_up, ray_slot *stack,
           float *entry, int top)
{
    const dxTriMeshNode *node = &d->nodes[i];
    prefetch_span(d, i, built);
    float enter[4];
    const unsigned m = planes ? ray_slots_planes(rp, node, limit_up, enter)
                              : ray_slots(r, node, limit_up, enter);
    ray_next next = { { 0, -1 }, top };
    if (!m) return next;
    const int j0 = __builtin_ctz(m);
    const unsigned rest = m & (m - 1);
    int near;
    if (!(rest & (rest - 1))) {
        const int j1 = 31 - __builtin_clz(m);
        near = enter[j1] < enter[j0] ? j1 : j0;
        const int far = j0 + j1 - near;
        prefetch_slot(d, node, far, built);
        stack[top] = (ray_slot){ node->first[far], node->count[far] };
        entry[top] = enter[far];
        next.top = top + (rest != 0);
    } else {
        int sorted[4], n = 0;
        for (unsigned b = m; b; b &= b - 1) {
            int j = __builtin_ctz(b), k = n++;   // insertion by entry, ties in slot order
            while (k > 0 && enter[sorted[k - 1]] > enter[j]) {
                sorted[k] = sorted[k - 1];
                k--;
            }
            sorted[k] = j;
        }
        while (n > 1) {
            const int j = sorted[--n];
            prefetch_slot(d, node, j, built);
            stack[top] = (ray_slot){ node->first[j], node->count[j] };
            entry[top++] = enter[j];
        }
        near = sorted[0];
        next.top = top;
    }
    if (!(enter[near] > limit)) next.slot = (ray_slot){ node->first[near], node->count[near] };
    return next;
}

// dxFloatAbove(x) with the step's side taken by a mask, not a choice: at a
// hit the side follows the data, and GCC made the choice a branch that a
// predictor missed every other ray.
static inline float float_above(dReal x)
{
    float f = (float)x;
    int32_t bits;
    memcpy(&bits, &f, sizeof bits);
    bits += ((bits >> 31) | 1) & -(int32_t)(f < x);
    memcpy(&f, &bits, sizeof f);
    return f;
}

// A crossing of the leaf-order triangle j at dist (barycentric bu, bv):
// kept among the nearest `max` in h if not beyond the limit, not
// degenerate and not refused by the callbacks; once `max` are kept, the
// limit (and its float above) is the farthest kept. `built` as
// prefetch_slot's.
static inline __attribute__((always_inline)) void
take_hit(dxGeom *o1, dxGeom *o2, ray_hits *h, int max, int j, dReal dist, dReal bu, dReal bv,
         const int built, dReal *limit, float *limit_up)
{
    const dxTriMesh *m = (const dxTriMesh *)o1;
    const dxTriMeshData *d = m->data;
    if (dist > *limit) return;
    int ti;
    const dReal *n;
    if (built || d->leaf_faces) {   // the index and normal in one line, no order[] first
        ti = d->leaf_faces[j].index;
        n = d->leaf_faces[j].n;
    } else {
        ti = d->order[j];
        n = d->normal + 3 * ti;
    }
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) return;   // degenerate: never a hit
    if (m->ray_callback && !m->ray_callback(o1, o2, ti, bu, bv)) return;
    if (m->callback && !m->callback(o1, o2, ti)) return;
    keep_hit(h, max, dist, ti, n);
    if (h->count == max) {
        *limit = h->raw[max - 1].depth;
        *limit_up = float_above(*limit);
    }
}

// The walk of dxCollideTriMeshRay with the plane test (`planes`, a
// constant: one copy of the walk each) or the general one, a leaf's
// triangles four at once (`avx2`, in an AVX2 copy, for a tree with its
// leaf copy and spans only) or two: the tree along the ray, nearer slot
// first; once `max` hits are kept, boxes the ray
// enters beyond the farthest of them are skipped. The hits go to h.
static inline __attribute__((always_inline)) void
walk(dxGeom *o1, dxGeom *o2, const dReal s[3], const dReal v[3], const ray_lanes *r,
     const ray_planes *rp, const int planes, const int avx2, int max, ray_hits *h)
{
    const dxTriMesh *m = (const dxTriMesh *)o1;
    const dxRay *ray = (const dxRay *)o2;
    const dxTriMeshData *d = m->data;
    // The slots stacked to visit later with the distance at which the ray
    // enters each: popped beyond the farthest hit kept, one is skipped
    // untested. A node stacks at most 3 and the four-way depth is under 17.
    ray_slot stack[128];
    float entry[128];
    dReal limit = ray->length;   // the farthest hit kept once `max` are
    float limit_up = dxFloatAbove(limit);
    ray_next next = visit_node(d, 0, r, rp, planes, avx2, limit, limit_up, stack, entry, 0);
    ray_slot cur = next.slot;
    int top = next.top;
    for (;;) {
        if (cur.count < 0) {
            do {
                if (top == 0) return;
                top--;
            } while (entry[top] > limit);
            cur = stack[top];
        }
        const int first = cur.first;
        if (cur.count == 0) {
            next = visit_node(d, first, r, rp, planes, avx2, limit, limit_up, stack, entry, top);
            cur = next.slot;
            top = next.top;
            continue;
        }
        // Only the vertices are read until a hit (memory traffic is what a
        // ray costs), from the leaf-order copy (a heightfield's patch has
        // none: its arrays), two triangles at a time where SSE2 allows: the
        // triangle's index and normal, after. A hit beyond the limit could
        // not be kept.
        const int end = first + cur.count;
        cur.count = -1;
        if (avx2 || d->leaf_vertices) prefetch_faces(d, first, end - first);
#if defined(DX_RAY_AVX2)
        if (avx2) {   // a leaf of the leaf copy: at most 4
            dReal dist[4], bu[4], bv[4];
            unsigned crossed = ray_triangle_quad(s, v, limit, d->leaf_vertices + 9 * first,
                                                 end - first, ray->backface_cull, dist, bu, bv);
            for (; crossed; crossed &= crossed - 1) {
                const int l = __builtin_ctz(crossed);
                take_hit(o1, o2, h, max, first + l, dist[l], bu[l], bv[l], 1, &limit,
                         &limit_up);
            }
            continue;
        }
#endif
        for (int j = first; j < end; j += 2) {
            dReal dist[2], bu[2], bv[2];
            unsigned crossed = 0;
#if defined(__SSE2__) && !defined(dSINGLE)
            if (d->leaf_vertices) {
                const dReal *t0 = d->leaf_vertices + 9 * j, *t1 = j + 1 < end ? t0 + 9 : t0;
                crossed = ray_triangle_pair(s, v, limit, t0, t1, ray->backface_cull, dist, bu,
                                            bv);
                if (j + 1 == end) crossed &= 1;
            } else
#endif
            {
                for (int l = 0; l < 2 && j + l < end; l++) {
                    dReal load[3][3];
                    const dReal(*tv)[3] = (const dReal(*)[3])load;
                    if (d->leaf_vertices)
                        tv = (const dReal(*)[3])(d->leaf_vertices + 9 * (j + l));
                    else
                        dxTriMeshTriangle(d, d->order[j + l], load);
                    if (ray_triangle(s, v, limit, tv, ray->backface_cull, &dist[l], &bu[l],
                                     &bv[l]))
                        crossed |= 1u << l;
                }
            }
            for (; crossed; crossed &= crossed - 1) {
                const int l = __builtin_ctz(crossed);
                take_hit(o1, o2, h, max, j + l, dist[l], bu[l], bv[l], 0, &limit, &limit_up);
            }
        }
    }
}

#if defined(DX_RAY_AVX2)
// The walk with the plane test and a leaf's four triangles at once, its
// set-up included, all of it in AVX2 code (no FMA: the same bits), for a
// tree with its leaf copy: 0 if the ray needs the general test.
__attribute__((target("avx2"))) static int
walk_planes_avx2(dxGeom *o1, dxGeom *o2, const dReal s[3], const dReal v[3], int max,
                 ray_hits *h)
{
    ray_planes planes;
    if (!ray_setup_planes_avx2(&planes, ((const dxTriMesh *)o1)->data, s, v)) return 0;
    walk(o1, o2, s, v, NULL, &planes, 1, 1, max, h);
    return 1;
}
#endif

// The ray's hits on the mesh m as contacts, nearest first: for the pair
// (m, ray) when not ray_first (a constant of each copy), for (ray, m)
// otherwise, with the contacts dxFlipContacts would make of the first's
// (the normal the triangle's, g1 the ray, side2 the triangle), written
// directly.
static inline __attribute__((always_inline)) int
collide_ray(dxGeom *o1, dxGeom *o2, const int ray_first, int flags, dContactGeom *c, int skip)
{
    dxTriMesh *m = (dxTriMesh *)o1;
    const dxRay *ray = (const dxRay *)o2;
    const dxTriMeshData *d = m->data;
    if (!d || d->node_count == 0) return 0;
    dReal s[3], v[3], dir[3];
    dx_axis(o2->R, 2, dir);
    dxTriMeshToLocal(o1, o2->pos, s);
    dxTriMeshDirToLocal(o1, dir, v);
    int single = ray->closest_hit || ray->first_contact;
    int max = single ? 1 : dx_max_contacts(flags);
    dxTriMeshRaw local[RAY_LOCAL_HITS];
    ray_hits hits = { local, 0 }, *h = &hits;
    dxTriScratch *scratch = NULL;
    if (max > RAY_LOCAL_HITS) {
        scratch = dxTriScratchAcquire();
        if (!scratch) return 0;
        dxTriScratchAddRaw(scratch, max);
        hits.raw = scratch->raw;
    }
    int walked = 0;
#if defined(DX_RAY_AVX2)
    if (d->leaf_vertices && __builtin_cpu_supports("avx2"))
        walked = walk_planes_avx2(o1, o2, s, v, max, h);
    else
#endif
    {
        ray_planes planes;
        if (ray_setup_planes(&planes, d, s, v)) {
            walk(o1, o2, s, v, NULL, &planes, 1, 0, max, h);
            walked = 1;
        }
    }
    if (!walked) {
        ray_lanes lanes;
        ray_setup_lanes(&lanes, d, s, v, ray->length);
        walk(o1, o2, s, v, &lanes, NULL, 0, 0, max, h);
    }
    const int count = hits.count;
    for (int i = 0; i < count; i++) {
        const dxTriMeshRaw *r = &hits.raw[i];
        dReal pos[3], n[3];
        for (int j = 0; j < 3; j++) pos[j] = o2->pos[j] + dir[j] * r->depth;
        dx_to_world(o1->R, r->n, n);
        if (ray_first) {
            dx_put_contact(c, i, skip, pos, n, r->depth, o2, o1);
            dxContactAt(c, i, skip)->side2 = r->tri;
        } else {
            for (int j = 0; j < 3; j++) n[j] = -n[j];
            dx_put_contact(c, i, skip, pos, n, r->depth, o1, o2);
            dxContactAt(c, i, skip)->side1 = r->tri;
        }
    }
    dxTriScratchRelease(scratch);
    return count;
}

int dxCollideTriMeshRay(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide_ray(o1, o2, 0, flags, c, skip);
}

int dxCollideRayTriMesh(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide_ray(o2, o1, 1, flags, c, skip);
}
