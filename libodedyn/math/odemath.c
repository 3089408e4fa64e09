// SPDX-License-Identifier: BSD-3-Clause
//
// odemath.c -- the non-inline part of odemath.h: vector normalisation,
// dPlaneSpace and dOrthogonalizeR.

#include "dx_check.h"
#include "unit_vector.h"

#include <ode/odemath.h>

#ifdef dSINGLE
#define DX_EPS FLT_EPSILON
#else
#define DX_EPS DBL_EPSILON
#endif

// What is left of a vector with largest component 1 after removing its part
// along a unit vector is only rounding noise (a few eps) when the two were
// parallel; below this length the pair counts as degenerate.
#define PARALLEL_TOL (32 * DX_EPS)

// Largest |a[i]| of the n components, or -1 if one is not finite.
static dReal max_abs(const dReal *a, int n)
{
    dReal m = 0;
    for (int i = 0; i < n; i++) {
        if (!dxIsFinite(a[i])) return -1;
        if (dFabs(a[i]) > m) m = dFabs(a[i]);
    }
    return m;
}

// Scale the n-vector a (n <= 4) to unit length; 0 (a untouched) if it is zero
// or not finite. Dividing by the largest component first keeps the sum of
// squares in [1, n], so tiny or huge vectors neither underflow nor overflow.
static int normalize_n(dReal *a, int n)
{
    dReal m = max_abs(a, n);
    if (!(m > 0)) return 0;
    dReal s[4], len2 = 0;
    for (int i = 0; i < n; i++) {
        s[i] = a[i] / m;
        len2 += s[i] * s[i];
    }
    dReal len = dSqrt(len2);
    for (int i = 0; i < n; i++) a[i] = s[i] / len;
    return 1;
}

// Unit vector along a; 0 and (1,0,0[,0]) without a report if a has no direction.
int dSafeNormalize3(dVector3 a)
{
    DX_CHECK_ARG(a != NULL, return 0, "a is NULL");
    if (dxIsFinite3(a[0], a[1], a[2]) && dxUnitVector3(a)) return 1;
    a[0] = 1;
    a[1] = a[2] = 0;
    return 0;
}

int dSafeNormalize4(dVector4 a)
{
    DX_CHECK_ARG(a != NULL, return 0, "a is NULL");
    if (normalize_n(a, 4)) return 1;
    a[0] = 1;
    a[1] = a[2] = a[3] = 0;
    return 0;
}

// The same, but a vector without direction is also reported (as a warning:
// the program goes on with the fallback, as with ODE's release builds).
void dNormalize3(dVector3 a)
{
    DX_CHECK_ARG(a != NULL, return, "a is NULL");
    DX_WARN_ARG(dSafeNormalize3(a), return,
                "the vector has zero length (or is not finite); set to (1,0,0)");
}

void dNormalize4(dVector4 a)
{
    DX_CHECK_ARG(a != NULL, return, "a is NULL");
    DX_WARN_ARG(dSafeNormalize4(a), return,
                "the vector has zero length (or is not finite); set to (1,0,0,0)");
}

// Two unit vectors p, q perpendicular to n (q = n x p): unit_vector.h.
void dPlaneSpace(const dVector3 n, dVector3 p, dVector3 q)
{
    DX_CHECK_ARG(n != NULL && p != NULL && q != NULL, return, "n, p or q is NULL");
    DX_CHECK_ARG(dxIsFinite3(n[0], n[1], n[2]), return, "n (%g, %g, %g) is not finite",
                 (double)n[0], (double)n[1], (double)n[2]);
    DX_CHECK_ARG(dFabs(n[2]) > M_SQRT1_2 || n[0] * n[0] + n[1] * n[1] > 0, return,
                 "n (%g, %g, %g) has no direction", (double)n[0], (double)n[1], (double)n[2]);
    dxPlaneSpaceUnit(n, p, q);
}

// Remove from v its part along the unit vector u, and normalise the rest.
// Returns 0 if v is zero, not finite or (nearly) parallel to u.
static int unit_perpendicular(dReal v[3], const dReal u[3])
{
    dReal s = max_abs(v, 3);
    if (!(s > 0)) return 0;
    for (int i = 0; i < 3; i++) v[i] /= s;   // largest component now 1
    dAddVectorScaledVector3(v, v, u, -dCalcVectorDot3(u, v));
    if (dCalcVectorLength3(v) <= PARALLEL_TOL) return 0;
    // a second projection removes what rounding left along u when v was
    // nearly parallel to it ("twice is enough" Gram-Schmidt)
    dAddVectorScaledVector3(v, v, u, -dCalcVectorDot3(u, v));
    return normalize_n(v, 3);
}

// Gram-Schmidt on the rows: row 0 normalised, row 1 made perpendicular to it
// and normalised, row 2 = row 0 x row 1 (so the result is a proper rotation).
int dOrthogonalizeR(dMatrix3 m)
{
    DX_CHECK_ARG(m != NULL, return 0, "m is NULL");
    dReal r0[3] = {m[0], m[1], m[2]}, r1[3] = {m[4], m[5], m[6]}, r2[3];
    if (!normalize_n(r0, 3) || !unit_perpendicular(r1, r0)) return 0;
    dCalcVectorCross3(r2, r0, r1);
    for (int j = 0; j < 3; j++) {
        m[j] = r0[j];
        m[4 + j] = r1[j];
        m[8 + j] = r2[j];
    }
    m[3] = m[7] = m[11] = 0;
    return 1;
}
