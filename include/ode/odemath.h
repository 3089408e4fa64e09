/* SPDX-License-Identifier: BSD-3-Clause */
/* odemath.h -- small vector and 3x3 matrix helpers (inline), the ODE 0.5
 * macro names for them, and vector normalisation (guide 9.3).
 *
 * Vectors are dReal[4] (padded), matrices 3x4 row-major. Helper suffixes name
 * the strides: dCalcVectorDot3_14(a, b) reads a with stride 1 and b with
 * stride 4 (a column of a dMatrix3). Multiply0 is A = B*C, Multiply1 is
 * A = B^T*C, Multiply2 is A = B*C^T; _331 means a 3x3 matrix times a 3x1
 * vector, and so on. No helper may be called with the result aliasing an
 * input unless it says so. */
#ifndef ODE_ODEMATH_H
#define ODE_ODEMATH_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

#define dACCESS33(A, i, j) ((A)[(i) * 4 + (j)])

#define dVALIDVEC3(v) (!(dIsNan((v)[0]) || dIsNan((v)[1]) || dIsNan((v)[2])))
#define dVALIDVEC4(v) (dVALIDVEC3(v) && !dIsNan((v)[3]))
#define dVALIDMAT3(m) \
    (dVALIDVEC4(m) && dVALIDVEC4((m) + 4) && dVALIDVEC4((m) + 8))
#define dVALIDMAT4(m) (dVALIDMAT3(m) && dVALIDVEC4((m) + 12))

ODE_PURE_INLINE void dZeroVector3(dVector3 res) { res[0] = res[1] = res[2] = 0; }
ODE_PURE_INLINE void dAssignVector3(dVector3 res, dReal x, dReal y, dReal z)
{
    res[0] = x; res[1] = y; res[2] = z;
}
ODE_PURE_INLINE void dZeroMatrix3(dMatrix3 res)
{
    int i;
    for (i = 0; i < 12; i++) res[i] = 0;
}
ODE_PURE_INLINE void dZeroMatrix4(dMatrix4 res)
{
    int i;
    for (i = 0; i < 16; i++) res[i] = 0;
}

ODE_PURE_INLINE void dAddVectors3(dReal *res, const dReal *a, const dReal *b)
{
    dReal r0 = a[0] + b[0], r1 = a[1] + b[1], r2 = a[2] + b[2];
    res[0] = r0; res[1] = r1; res[2] = r2;
}
ODE_PURE_INLINE void dSubtractVectors3(dReal *res, const dReal *a, const dReal *b)
{
    dReal r0 = a[0] - b[0], r1 = a[1] - b[1], r2 = a[2] - b[2];
    res[0] = r0; res[1] = r1; res[2] = r2;
}
ODE_PURE_INLINE void dAddVectorScaledVector3(dReal *res, const dReal *a, const dReal *b,
                                             dReal b_scale)
{
    dReal r0 = a[0] + b_scale * b[0], r1 = a[1] + b_scale * b[1], r2 = a[2] + b_scale * b[2];
    res[0] = r0; res[1] = r1; res[2] = r2;
}
ODE_PURE_INLINE void dAddScaledVectors3(dReal *res, const dReal *a, const dReal *b,
                                        dReal a_scale, dReal b_scale)
{
    dReal r0 = a_scale * a[0] + b_scale * b[0];
    dReal r1 = a_scale * a[1] + b_scale * b[1];
    dReal r2 = a_scale * a[2] + b_scale * b[2];
    res[0] = r0; res[1] = r1; res[2] = r2;
}
ODE_PURE_INLINE void dAddThreeScaledVectors3(dReal *res, const dReal *a, const dReal *b,
                                             const dReal *c, dReal a_scale, dReal b_scale,
                                             dReal c_scale)
{
    dReal r0 = a_scale * a[0] + b_scale * b[0] + c_scale * c[0];
    dReal r1 = a_scale * a[1] + b_scale * b[1] + c_scale * c[1];
    dReal r2 = a_scale * a[2] + b_scale * b[2] + c_scale * c[2];
    res[0] = r0; res[1] = r1; res[2] = r2;
}
ODE_PURE_INLINE void dScaleVector3(dReal *res, dReal scale)
{
    res[0] *= scale; res[1] *= scale; res[2] *= scale;
}
ODE_PURE_INLINE void dNegateVector3(dReal *res)
{
    res[0] = -res[0]; res[1] = -res[1]; res[2] = -res[2];
}
ODE_PURE_INLINE void dCopyVector3(dReal *res, const dReal *a)
{
    res[0] = a[0]; res[1] = a[1]; res[2] = a[2];
}
ODE_PURE_INLINE void dCopyScaledVector3(dReal *res, const dReal *a, dReal scale)
{
    res[0] = a[0] * scale; res[1] = a[1] * scale; res[2] = a[2] * scale;
}
ODE_PURE_INLINE void dCopyNegatedVector3(dReal *res, const dReal *a)
{
    res[0] = -a[0]; res[1] = -a[1]; res[2] = -a[2];
}
ODE_PURE_INLINE void dCopyVector4(dReal *res, const dReal *a)
{
    res[0] = a[0]; res[1] = a[1]; res[2] = a[2]; res[3] = a[3];
}
ODE_PURE_INLINE void dCopyMatrix4x4(dReal *res, const dReal *a)
{
    int i;
    for (i = 0; i < 16; i++) res[i] = a[i];
}
ODE_PURE_INLINE void dCopyMatrix4x3(dReal *res, const dReal *a)
{
    int i;
    for (i = 0; i < 12; i++) res[i] = a[i];
}
/* Column n of a dMatrix3. */
ODE_PURE_INLINE void dGetMatrixColumn3(dReal *res, const dReal *a, unsigned n)
{
    res[0] = a[n]; res[1] = a[n + 4]; res[2] = a[n + 8];
}

ODE_PURE_INLINE dReal dCalcVectorLengthSquare3(const dReal *a)
{
    return a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
}
ODE_PURE_INLINE dReal dCalcVectorLength3(const dReal *a)
{
    return dSqrt(dCalcVectorLengthSquare3(a));
}
/* Signed distance of test_p below the plane through plane_p with normal plane_n. */
ODE_PURE_INLINE dReal dCalcPointDepth3(const dReal *test_p, const dReal *plane_p,
                                       const dReal *plane_n)
{
    return (plane_p[0] - test_p[0]) * plane_n[0] + (plane_p[1] - test_p[1]) * plane_n[1] +
           (plane_p[2] - test_p[2]) * plane_n[2];
}

ODE_PURE_INLINE dReal dCalcVectorDot3Stride(const dReal *a, const dReal *b, unsigned sa, unsigned sb)
{
    return a[0] * b[0] + a[sa] * b[sb] + a[2 * sa] * b[2 * sb];
}
ODE_PURE_INLINE dReal dCalcVectorDot3(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 1, 1); }
ODE_PURE_INLINE dReal dCalcVectorDot3_13(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 1, 3); }
ODE_PURE_INLINE dReal dCalcVectorDot3_31(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 3, 1); }
ODE_PURE_INLINE dReal dCalcVectorDot3_33(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 3, 3); }
ODE_PURE_INLINE dReal dCalcVectorDot3_14(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 1, 4); }
ODE_PURE_INLINE dReal dCalcVectorDot3_41(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 4, 1); }
ODE_PURE_INLINE dReal dCalcVectorDot3_44(const dReal *a, const dReal *b) { return dCalcVectorDot3Stride(a, b, 4, 4); }

/* res = a x b with strides; safe when res aliases a or b. */
ODE_PURE_INLINE void dCalcVectorCross3Stride(dReal *res, const dReal *a, const dReal *b,
                                      unsigned sr, unsigned sa, unsigned sb)
{
    dReal r0 = a[sa] * b[2 * sb] - a[2 * sa] * b[sb];
    dReal r1 = a[2 * sa] * b[0] - a[0] * b[2 * sb];
    dReal r2 = a[0] * b[sb] - a[sa] * b[0];
    res[0] = r0; res[sr] = r1; res[2 * sr] = r2;
}
ODE_PURE_INLINE void dCalcVectorCross3(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 1, 1, 1); }
ODE_PURE_INLINE void dCalcVectorCross3_114(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 1, 1, 4); }
ODE_PURE_INLINE void dCalcVectorCross3_141(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 1, 4, 1); }
ODE_PURE_INLINE void dCalcVectorCross3_144(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 1, 4, 4); }
ODE_PURE_INLINE void dCalcVectorCross3_411(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 4, 1, 1); }
ODE_PURE_INLINE void dCalcVectorCross3_414(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 4, 1, 4); }
ODE_PURE_INLINE void dCalcVectorCross3_441(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 4, 4, 1); }
ODE_PURE_INLINE void dCalcVectorCross3_444(dReal *r, const dReal *a, const dReal *b) { dCalcVectorCross3Stride(r, a, b, 4, 4, 4); }

ODE_PURE_INLINE void dAddVectorCross3(dReal *res, const dReal *a, const dReal *b)
{
    dVector3 t;
    dCalcVectorCross3(t, a, b);
    dAddVectors3(res, res, t);
}
ODE_PURE_INLINE void dSubtractVectorCross3(dReal *res, const dReal *a, const dReal *b)
{
    dVector3 t;
    dCalcVectorCross3(t, a, b);
    dSubtractVectors3(res, res, t);
}

/* Write into a zeroed 3x3 block (row skip `skip`) the matrix M with M*b = a x b
 * (Plus) or M*b = -(a x b) (Minus). The diagonal is not written. */
ODE_PURE_INLINE void dSetCrossMatrixPlus(dReal *res, const dReal *a, unsigned skip)
{
    res[1] = -a[2]; res[2] = a[1];
    res[skip + 0] = a[2]; res[skip + 2] = -a[0];
    res[2 * skip + 0] = -a[1]; res[2 * skip + 1] = a[0];
}
ODE_PURE_INLINE void dSetCrossMatrixMinus(dReal *res, const dReal *a, unsigned skip)
{
    res[1] = a[2]; res[2] = -a[1];
    res[skip + 0] = -a[2]; res[skip + 2] = a[0];
    res[2 * skip + 0] = a[1]; res[2 * skip + 1] = -a[0];
}

ODE_PURE_INLINE dReal dCalcPointsDistance3(const dReal *a, const dReal *b)
{
    dVector3 d;
    dSubtractVectors3(d, a, b);
    return dCalcVectorLength3(d);
}

/* res = A*b for a dMatrix3 A. */
ODE_PURE_INLINE void dMultiply0_331(dReal *res, const dReal *A, const dReal *b)
{
    dReal r0 = dCalcVectorDot3(A, b), r1 = dCalcVectorDot3(A + 4, b);
    dReal r2 = dCalcVectorDot3(A + 8, b);
    res[0] = r0; res[1] = r1; res[2] = r2;
}
/* res = A^T*b. */
ODE_PURE_INLINE void dMultiply1_331(dReal *res, const dReal *A, const dReal *b)
{
    dReal r0 = dCalcVectorDot3_41(A, b), r1 = dCalcVectorDot3_41(A + 1, b);
    dReal r2 = dCalcVectorDot3_41(A + 2, b);
    res[0] = r0; res[1] = r1; res[2] = r2;
}
/* res = b^T*A (a row vector), the same as A^T*b. */
ODE_PURE_INLINE void dMultiply0_133(dReal *res, const dReal *b, const dReal *A)
{
    dMultiply1_331(res, A, b);
}
/* res = B*C for dMatrix3s; res must not alias B or C. */
ODE_PURE_INLINE void dMultiply0_333(dReal *res, const dReal *B, const dReal *C)
{
    int i;
    for (i = 0; i < 3; i++) dMultiply0_133(res + 4 * i, B + 4 * i, C);
}
/* res = B^T*C. */
ODE_PURE_INLINE void dMultiply1_333(dReal *res, const dReal *B, const dReal *C)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) res[4 * i + j] = dCalcVectorDot3_44(B + i, C + j);
}
/* res = B*C^T. */
ODE_PURE_INLINE void dMultiply2_333(dReal *res, const dReal *B, const dReal *C)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) res[4 * i + j] = dCalcVectorDot3(B + 4 * i, C + 4 * j);
}
ODE_PURE_INLINE void dMultiplyAdd0_331(dReal *res, const dReal *A, const dReal *b)
{
    dVector3 t;
    dMultiply0_331(t, A, b);
    dAddVectors3(res, res, t);
}
ODE_PURE_INLINE void dMultiplyAdd1_331(dReal *res, const dReal *A, const dReal *b)
{
    dVector3 t;
    dMultiply1_331(t, A, b);
    dAddVectors3(res, res, t);
}
ODE_PURE_INLINE void dMultiplyAdd0_133(dReal *res, const dReal *b, const dReal *A)
{
    dMultiplyAdd1_331(res, A, b);
}
ODE_PURE_INLINE void dMultiplyAdd0_333(dReal *res, const dReal *B, const dReal *C)
{
    int i;
    for (i = 0; i < 3; i++) dMultiplyAdd0_133(res + 4 * i, B + 4 * i, C);
}
ODE_PURE_INLINE void dMultiplyAdd1_333(dReal *res, const dReal *B, const dReal *C)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) res[4 * i + j] += dCalcVectorDot3_44(B + i, C + j);
}
ODE_PURE_INLINE void dMultiplyAdd2_333(dReal *res, const dReal *B, const dReal *C)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) res[4 * i + j] += dCalcVectorDot3(B + 4 * i, C + 4 * j);
}

ODE_PURE_INLINE dReal dCalcMatrix3Det(const dReal *m)
{
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
           m[2] * (m[4] * m[9] - m[5] * m[8]);
}
/* dst = inverse of the 3x3 part of ma; returns the determinant, and leaves dst
 * untouched when it is 0. */
ODE_PURE_INLINE dReal dInvertMatrix3(dReal *dst, const dReal *ma)
{
    dReal det = dCalcMatrix3Det(ma), r;
    if (det == 0) return 0;
    r = dRecip(det);
    dst[0] = (ma[5] * ma[10] - ma[6] * ma[9]) * r;
    dst[1] = (ma[2] * ma[9] - ma[1] * ma[10]) * r;
    dst[2] = (ma[1] * ma[6] - ma[2] * ma[5]) * r;
    dst[4] = (ma[6] * ma[8] - ma[4] * ma[10]) * r;
    dst[5] = (ma[0] * ma[10] - ma[2] * ma[8]) * r;
    dst[6] = (ma[2] * ma[4] - ma[0] * ma[6]) * r;
    dst[8] = (ma[4] * ma[9] - ma[5] * ma[8]) * r;
    dst[9] = (ma[1] * ma[8] - ma[0] * ma[9]) * r;
    dst[10] = (ma[0] * ma[5] - ma[1] * ma[4]) * r;
    return det;
}

/* Scale a to unit length. The Safe forms return 0 and set a to (1,0,0[,0])
 * when a has no direction; the others also report that through dDebug. */
ODE_API int dSafeNormalize3(dVector3 a);
ODE_API int dSafeNormalize4(dVector4 a);
ODE_API void dNormalize3(dVector3 a);
ODE_API void dNormalize4(dVector4 a);

/* Given a unit vector n, make p and q such that n, p, q are mutually
 * perpendicular and p is unit length (q = n x p). */
ODE_API void dPlaneSpace(const dVector3 n, dVector3 p, dVector3 q);

/* Make m an exact rotation (orthonormal, right-handed) close to what it was.
 * Returns 0 and leaves m unchanged if its rows are degenerate. */
ODE_API int dOrthogonalizeR(dMatrix3 m);

#ifdef __cplusplus
}
#endif

/* ODE 0.5 macro names, kept so old programs build. `op` is an assignment
 * operator (=, +=, -=); the argument macros evaluate their arguments more
 * than once. */
#define dOP(a, op, b, c) do { \
    (a)[0] = ((b)[0])op((c)[0]); (a)[1] = ((b)[1])op((c)[1]); \
    (a)[2] = ((b)[2])op((c)[2]); } while (0)
#define dOPC(a, op, b, c) do { \
    (a)[0] = ((b)[0])op(c); (a)[1] = ((b)[1])op(c); (a)[2] = ((b)[2])op(c); } while (0)
#define dOPE(a, op, b) do { (a)[0] op((b)[0]); (a)[1] op((b)[1]); (a)[2] op((b)[2]); } while (0)
#define dOPEC(a, op, c) do { (a)[0] op(c); (a)[1] op(c); (a)[2] op(c); } while (0)
#define dOPE2(a, op1, b, op2, c) do { \
    (a)[0] op1((b)[0])op2((c)[0]); (a)[1] op1((b)[1])op2((c)[1]); \
    (a)[2] op1((b)[2])op2((c)[2]); } while (0)

#define dLENGTHSQUARED(a) dCalcVectorLengthSquare3(a)
#define dLENGTH(a) dCalcVectorLength3(a)
#define dDISTANCE(a, b) dCalcPointsDistance3(a, b)
#define dDOT(a, b) dCalcVectorDot3(a, b)
#define dDOT13(a, b) dCalcVectorDot3_13(a, b)
#define dDOT31(a, b) dCalcVectorDot3_31(a, b)
#define dDOT33(a, b) dCalcVectorDot3_33(a, b)
#define dDOT14(a, b) dCalcVectorDot3_14(a, b)
#define dDOT41(a, b) dCalcVectorDot3_41(a, b)
#define dDOT44(a, b) dCalcVectorDot3_44(a, b)

/* a op b x c, where b and c are read with strides q and r and a written with p. */
#define dCROSSpqr(a, op, b, c, p, q, r) do { \
    (a)[0] op((b)[q] * (c)[2 * (r)] - (b)[2 * (q)] * (c)[r]); \
    (a)[p] op((b)[2 * (q)] * (c)[0] - (b)[0] * (c)[2 * (r)]); \
    (a)[2 * (p)] op((b)[0] * (c)[r] - (b)[q] * (c)[0]); } while (0)
#define dCROSS(a, op, b, c) dCROSSpqr(a, op, b, c, 1, 1, 1)
#define dCROSS114(a, op, b, c) dCROSSpqr(a, op, b, c, 1, 1, 4)
#define dCROSS141(a, op, b, c) dCROSSpqr(a, op, b, c, 1, 4, 1)
#define dCROSS144(a, op, b, c) dCROSSpqr(a, op, b, c, 1, 4, 4)
#define dCROSS411(a, op, b, c) dCROSSpqr(a, op, b, c, 4, 1, 1)
#define dCROSS414(a, op, b, c) dCROSSpqr(a, op, b, c, 4, 1, 4)
#define dCROSS441(a, op, b, c) dCROSSpqr(a, op, b, c, 4, 4, 1)
#define dCROSS444(a, op, b, c) dCROSSpqr(a, op, b, c, 4, 4, 4)

/* Write the cross-product matrix of a into a zeroed 3x3 block: pass (+,-) for
 * M*b = a x b, (-,+) for its negative. */
#define dCROSSMAT(A, a, skip, plus, minus) do { \
    (A)[1] = minus(a)[2]; (A)[2] = plus(a)[1]; \
    (A)[(skip) + 0] = plus(a)[2]; (A)[(skip) + 2] = minus(a)[0]; \
    (A)[2 * (skip) + 0] = minus(a)[1]; (A)[2 * (skip) + 1] = plus(a)[0]; } while (0)

#define dMULTIPLY0_331(A, B, C) dMultiply0_331(A, B, C)
#define dMULTIPLY1_331(A, B, C) dMultiply1_331(A, B, C)
#define dMULTIPLY0_133(A, B, C) dMultiply0_133(A, B, C)
#define dMULTIPLY0_333(A, B, C) dMultiply0_333(A, B, C)
#define dMULTIPLY1_333(A, B, C) dMultiply1_333(A, B, C)
#define dMULTIPLY2_333(A, B, C) dMultiply2_333(A, B, C)
#define dMULTIPLYADD0_331(A, B, C) dMultiplyAdd0_331(A, B, C)
#define dMULTIPLYADD1_331(A, B, C) dMultiplyAdd1_331(A, B, C)
#define dMULTIPLYADD0_133(A, B, C) dMultiplyAdd0_133(A, B, C)
#define dMULTIPLYADD0_333(A, B, C) dMultiplyAdd0_333(A, B, C)
#define dMULTIPLYADD1_333(A, B, C) dMultiplyAdd1_333(A, B, C)
#define dMULTIPLYADD2_333(A, B, C) dMultiplyAdd2_333(A, B, C)

#endif
