// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_v4.h -- fours of numbers for QuickStep's SIMD paths, and the
// loads and stores of fours and of pairs (qs_v2, quickstep.h): a body's 6
// numbers as a four and a pair (quickstep_sweep.c), a contact's rows one a
// lane (quickstep_contact.c), a batch's blocks one a lane
// (quickstep_block_batch.c). GNU vector extensions: one AVX operation for
// doubles in the AVX2 clones, two SSE2 ones in the baseline; elsewhere four
// scalar operations. Every operation is lane by lane, so the results are the
// same bits whichever code runs (but for the fused multiply-adds of v4_madd,
// quickstep.h).

#ifndef QUICKSTEP_V4_H
#define QUICKSTEP_V4_H

#include "quickstep.h"
#include "dx_clones.h"   // (quiets -Wpsabi: fours pass between inlined functions)

#include <stdint.h>
#include <string.h>
#if QS_FUSE
#include <immintrin.h>
#endif

#if defined(__GNUC__)
typedef dReal qs_v4 __attribute__((vector_size(4 * sizeof(dReal))));
#if defined(dSINGLE)
typedef int32_t qs_m4 __attribute__((vector_size(4 * sizeof(dReal))));
#else
typedef int64_t qs_m4 __attribute__((vector_size(4 * sizeof(dReal))));
#endif
#define v4_lane(v, i) ((v)[i])
#define v4_add(x, y) ((x) + (y))
#define v4_sub(x, y) ((x) - (y))
#define v4_mul(x, y) ((x) * (y))
#define v4_neg(x) (-(x))
// Lane i of v in all four lanes (one vpermpd with AVX2).
#define v4_spread(v, i) __builtin_shufflevector(v, v, i, i, i, i)
QS_INLINE qs_v4 v4_make(dReal a, dReal b, dReal c, dReal d)
{
    const qs_v4 v = { a, b, c, d };
    return v;
}
QS_INLINE qs_v4 v4_splat(dReal a)
{
    const qs_v4 v = { a };   // (then spread: one vbroadcastsd with AVX2)
    return __builtin_shufflevector(v, v, 0, 0, 0, 0);
}
// l projected on lo..hi in each lane, as the scalar update does: hi where
// l > hi, then lo where l < lo (comparisons are masks of all ones).
QS_INLINE qs_v4 v4_clamp(qs_v4 l, qs_v4 lo, qs_v4 hi)
{
    qs_m4 m = l > hi;
    l = (qs_v4)(((qs_m4)hi & m) | ((qs_m4)l & ~m));
    m = l < lo;
    return (qs_v4)(((qs_m4)lo & m) | ((qs_m4)l & ~m));
}
// [a0 + a2, a1 + a3] (the halves taken as vectors)
QS_INLINE qs_v2 v4_fold(qs_v4 a)
{
    return __builtin_shufflevector(a, a, 0, 1) + __builtin_shufflevector(a, a, 2, 3);
}
#else
typedef struct qs_v4 {
    dReal e[4];
} qs_v4;
#define v4_lane(v, i) ((v).e[i])
static inline qs_v4 v4_make(dReal a, dReal b, dReal c, dReal d)
{
    const qs_v4 v = { { a, b, c, d } };
    return v;
}
static inline qs_v4 v4_add(qs_v4 x, qs_v4 y)
{
    return v4_make(x.e[0] + y.e[0], x.e[1] + y.e[1], x.e[2] + y.e[2], x.e[3] + y.e[3]);
}
static inline qs_v4 v4_sub(qs_v4 x, qs_v4 y)
{
    return v4_make(x.e[0] - y.e[0], x.e[1] - y.e[1], x.e[2] - y.e[2], x.e[3] - y.e[3]);
}
static inline qs_v4 v4_mul(qs_v4 x, qs_v4 y)
{
    return v4_make(x.e[0] * y.e[0], x.e[1] * y.e[1], x.e[2] * y.e[2], x.e[3] * y.e[3]);
}
static inline qs_v4 v4_neg(qs_v4 x)
{
    return v4_make(-x.e[0], -x.e[1], -x.e[2], -x.e[3]);
}
static inline qs_v4 v4_splat(dReal a)
{
    return v4_make(a, a, a, a);
}
#define v4_spread(v, i) v4_splat(v4_lane(v, i))
static inline qs_v4 v4_clamp(qs_v4 l, qs_v4 lo, qs_v4 hi)
{
    for (int i = 0; i < 4; i++) {
        l.e[i] = l.e[i] > hi.e[i] ? hi.e[i] : l.e[i];
        l.e[i] = l.e[i] < lo.e[i] ? lo.e[i] : l.e[i];
    }
    return l;
}
static inline qs_v2 v4_fold(qs_v4 a)
{
    qs_v2 v = { { a.e[0] + a.e[2], a.e[1] + a.e[3] } };
    return v;
}
#endif

#if QS_FUSE
// a * b + c lane by lane, rounded once: one vfmadd (the intrinsic: built
// lane by lane, a four whose addend is a product was taken apart into
// single lanes). Not always inlined: inlined into the fused versions, a
// call (never made) in the others.
QS_FUSED_VERSION static inline qs_v4 v4_fused(qs_v4 a, qs_v4 b, qs_v4 c)
{
#if defined(dSINGLE)
    return (qs_v4)_mm_fmadd_ps((__m128)a, (__m128)b, (__m128)c);
#else
    return (qs_v4)_mm256_fmadd_pd((__m256d)a, (__m256d)b, (__m256d)c);
#endif
}
#endif

// a * b + c lane by lane, rounded once if fu (quickstep.h: qs_madd).
QS_INLINE qs_v4 v4_madd(qs_v4 a, qs_v4 b, qs_v4 c, int fu)
{
#if QS_FUSE
    if (fu) return v4_fused(a, b, c);
#endif
    (void)fu;
    return v4_add(v4_mul(a, b), c);
}

QS_INLINE qs_v2 v2_load(const dReal *p)
{
    qs_v2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

QS_INLINE void v2_store(qs_v2 v, dReal *p)
{
    memcpy(p, &v, sizeof v);
}

QS_INLINE qs_v4 v4_load(const dReal *p)
{
    qs_v4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

QS_INLINE void v4_store(qs_v4 v, dReal *p)
{
    memcpy(p, &v, sizeof v);
}

// The 4 x 4 transpose of a, b, c, d: out[i] = (a_i, b_i, c_i, d_i).
QS_INLINE void v4_transpose(qs_v4 a, qs_v4 b, qs_v4 c, qs_v4 d, qs_v4 out[4])
{
#if defined(__GNUC__)
    const qs_v4 t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6);
    const qs_v4 t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
    const qs_v4 t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6);
    const qs_v4 t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
    out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
#else
    for (int i = 0; i < 4; i++) out[i] = v4_make(a.e[i], b.e[i], c.e[i], d.e[i]);
#endif
}

#endif
