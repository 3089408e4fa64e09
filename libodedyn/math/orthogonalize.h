// SPDX-License-Identifier: BSD-3-Clause
//
// orthogonalize.h -- the arithmetic of dOrthogonalizeR (and of the vector
// normalisation it shares with dSafeNormalize4), inline: dGeomRaySet makes
// a ray's rotation with it per call, and the call's checks and jumps were a
// third of its work. The same operations in the same order, so the same bits.

#ifndef DX_ORTHOGONALIZE_H
#define DX_ORTHOGONALIZE_H

#include <ode/odemath.h>

#include "../core/dx_check.h"
#include "unit_vector.h"

#ifdef dSINGLE
#define DX_ORTHO_EPS FLT_EPSILON
#else
#define DX_ORTHO_EPS DBL_EPSILON
#endif

// What is left of a vector with largest component 1 after removing its part
// along a unit vector is only rounding noise (a few eps) when the two were
// parallel; below this length the pair counts as degenerate.
#define DX_ORTHO_PARALLEL_TOL (32 * DX_ORTHO_EPS)

// Largest |a[i]| of the n components, or -1 if one is not finite (not
// looked at if the caller knows them finite: finite set).
static inline dReal dxMaxAbs(const dReal *a, int n, int finite)
{
    dReal m = 0;
    for (int i = 0; i < n; i++) {
        if (!finite && !dxIsFinite(a[i])) return -1;
        if (dFabs(a[i]) > m) m = dFabs(a[i]);
    }
    return m;
}

// Scale the n-vector a (n <= 4) to unit length; 0 (a untouched) if it is zero
// or not finite. Dividing by the largest component first keeps the sum of
// squares in [1, n], so tiny or huge vectors neither underflow nor overflow.
// finite: as dxMaxAbs.
static inline int dxNormalizeN(dReal *a, int n, int finite)
{
    dReal m = dxMaxAbs(a, n, finite);
    if (!(m > 0)) return 0;
    dReal s[4], len2 = 0;
    for (int i = 0; i < n; i++) {
        s[i] = a[i] / m;
        len2 += s[i] * s[i];
    }
    dReal len = dxSqrtNonNeg(len2);
    for (int i = 0; i < n; i++) a[i] = s[i] / len;
    return 1;
}

// Remove from v its part along the unit vector u, and normalise the rest.
// Returns 0 if v is zero, not finite or (nearly) parallel to u.
static inline int dxUnitPerpendicular(dReal v[3], const dReal u[3], int finite)
{
    dReal s = dxMaxAbs(v, 3, finite);
    if (!(s > 0)) return 0;
    for (int i = 0; i < 3; i++) v[i] /= s;   // largest component now 1
    dAddVectorScaledVector3(v, v, u, -dCalcVectorDot3(u, v));
    if (dxSqrtNonNeg(dCalcVectorLengthSquare3(v)) <= DX_ORTHO_PARALLEL_TOL) return 0;
    // a second projection removes what rounding left along u when v was
    // nearly parallel to it ("twice is enough" Gram-Schmidt)
    dAddVectorScaledVector3(v, v, u, -dCalcVectorDot3(u, v));
    return dxNormalizeN(v, 3, finite);
}

// Gram-Schmidt on the rows of m: row 0 normalised, row 1 made perpendicular
// to it and normalised, row 2 = row 0 x row 1 (so the result is a proper
// rotation). 0 (m untouched) if the first two rows are degenerate or not
// finite (finite set: the caller knows them finite).
static inline int dxOrthogonalizeR(dMatrix3 m, int finite)
{
    dReal r0[3] = { m[0], m[1], m[2] }, r1[3] = { m[4], m[5], m[6] }, r2[3];
    if (!dxNormalizeN(r0, 3, finite) || !dxUnitPerpendicular(r1, r0, finite)) return 0;
    dCalcVectorCross3(r2, r0, r1);
    for (int j = 0; j < 3; j++) {
        m[j] = r0[j];
        m[4 + j] = r1[j];
        m[8 + j] = r2[j];
    }
    m[3] = m[7] = m[11] = 0;
    return 1;
}

#endif
