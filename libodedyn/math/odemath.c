// SPDX-License-Identifier: BSD-3-Clause
//
// odemath.c -- the non-inline part of odemath.h: vector normalisation,
// dPlaneSpace and dOrthogonalizeR.

#include "dx_check.h"
#include "orthogonalize.h"
#include "unit_vector.h"

#include <ode/odemath.h>

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
    if (dxNormalizeN(a, 4, 0)) return 1;
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

// Gram-Schmidt on the rows: row 0 normalised, row 1 made perpendicular to it
// and normalised, row 2 = row 0 x row 1 (so the result is a proper rotation).
int dOrthogonalizeR(dMatrix3 m)
{
    DX_CHECK_ARG(m != NULL, return 0, "m is NULL");
    return dxOrthogonalizeR(m, 0);
}
