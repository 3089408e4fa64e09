// SPDX-License-Identifier: BSD-3-Clause
//
// unit_vector.h -- the arithmetic of dSafeNormalize3 and dPlaneSpace without
// their argument checks, for callers that have checked already (a contact's
// normal at dJointCreateContact): the same operations, so the same bits.

#ifndef DX_UNIT_VECTOR_H
#define DX_UNIT_VECTOR_H

#include <ode/common.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// The square root of x >= 0 (or NaN): dSqrt's correctly rounded result, as
// one instruction. GCC keeps sqrt's errno case as a library call, which it
// sometimes makes for every argument.
static inline dReal dxSqrtNonNeg(dReal x)
{
#if defined(__SSE2__) && defined(dSINGLE)
    return _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x)));
#elif defined(__SSE2__)
    return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(x)));
#else
    return dSqrt(x);
#endif
}

// Scale a finite, nonzero 3-vector to unit length. Dividing by the largest
// component first keeps the sum of squares in [1, 3], so tiny or huge
// vectors neither underflow nor overflow. Returns 0 (a untouched) for a zero
// vector.
static inline int dxUnitVector3(dReal *a)
{
    const dReal x = dFabs(a[0]), y = dFabs(a[1]), z = dFabs(a[2]);
    // max(x, y, z) as two steps of the form the processor's max takes (no
    // branch on which component is largest): the same value as nested
    // choices.
    const dReal mxy = x > y ? x : y, m = mxy > z ? mxy : z;
    if (!(m > 0)) return 0;
    const dReal s0 = a[0] / m, s1 = a[1] / m, s2 = a[2] / m;
    const dReal len = dxSqrtNonNeg(s0 * s0 + s1 * s1 + s2 * s2);
    a[0] = s0 / len;
    a[1] = s1 / len;
    a[2] = s2 / len;
    return 1;
}

// Two unit vectors p, q perpendicular to the unit vector n (q = n x p). p is
// built from the two components of n that are not both small, so 1/sqrt(a)
// is well conditioned: a >= 1/2 in either branch.
static inline void dxPlaneSpaceUnit(const dReal *n, dReal *p, dReal *q)
{
    dReal pp[3], qq[3];
    if (dFabs(n[2]) > M_SQRT1_2) {
        // p in the y-z plane
        const dReal a = n[1] * n[1] + n[2] * n[2], k = 1 / dxSqrtNonNeg(a);
        pp[0] = 0;
        pp[1] = -n[2] * k;
        pp[2] = n[1] * k;
        qq[0] = a * k;
        qq[1] = -n[0] * pp[2];
        qq[2] = n[0] * pp[1];
    } else {
        // p in the x-y plane
        const dReal a = n[0] * n[0] + n[1] * n[1], k = 1 / dxSqrtNonNeg(a);
        pp[0] = -n[1] * k;
        pp[1] = n[0] * k;
        pp[2] = 0;
        qq[0] = -n[2] * pp[1];
        qq[1] = n[2] * pp[0];
        qq[2] = a * k;
    }
    for (int i = 0; i < 3; i++) {
        p[i] = pp[i];
        q[i] = qq[i];
    }
}

#endif
