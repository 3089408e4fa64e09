// SPDX-License-Identifier: BSD-3-Clause
//
// test_odemath.c -- the vector and 3x3 helpers of odemath.h (inline functions
// and the ODE 0.5 macros), normalisation, dPlaneSpace and dOrthogonalizeR.
//
// The inline helpers are fed small integers, so every product and sum is
// exact in both precisions and they are compared with tolerance 0.

#include "test.h"

// Deterministic pseudo-random numbers in [-1, 1] (independent of dRand).
static unsigned long long rng_state = 12345;
static double rnd(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) / (double)(1ULL << 53) * 2 - 1;
}

// Rounding tolerance of a few operations on numbers of order 1.
#define EPS_TOL TOL(1e-14, 1e-6)

// ---------------------------------------------------------------- inline helpers

static int test_dot_with_strides(void)
{
    dReal a[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    dReal b[12] = {2, -1, 3, 0, 5, 7, -2, 1, 4, 6, 8, -3};

    CHECK(dCalcVectorDot3(a, b) == 1 * 2 + 2 * -1 + 3 * 3);
    CHECK(dCalcVectorDot3_13(a, b) == 1 * 2 + 2 * 0 + 3 * -2);
    CHECK(dCalcVectorDot3_31(a, b) == 1 * 2 + 4 * -1 + 7 * 3);
    CHECK(dCalcVectorDot3_33(a, b) == 1 * 2 + 4 * 0 + 7 * -2);
    CHECK(dCalcVectorDot3_14(a, b) == 1 * 2 + 2 * 5 + 3 * 4);   // b's column 0
    CHECK(dCalcVectorDot3_41(a, b) == 1 * 2 + 5 * -1 + 9 * 3);   // a's column 0
    CHECK(dCalcVectorDot3_44(a + 1, b + 2) == 2 * 3 + 6 * -2 + 10 * 8);
    CHECK(dDOT(a, b) == dCalcVectorDot3(a, b));
    CHECK(dDOT13(a, b) == dCalcVectorDot3_13(a, b));
    CHECK(dDOT31(a, b) == dCalcVectorDot3_31(a, b));
    CHECK(dDOT33(a, b) == dCalcVectorDot3_33(a, b));
    CHECK(dDOT14(a, b) == dCalcVectorDot3_14(a, b));
    CHECK(dDOT41(a, b) == dCalcVectorDot3_41(a, b));
    CHECK(dDOT44(a, b) == dCalcVectorDot3_44(a, b));
    return 0;
}

// Reference cross product of contiguous vectors.
static void cross(dReal *r, const dReal *a, const dReal *b)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static int test_cross_is_perpendicular_and_right_handed(void)
{
    dVector3 x = {1, 0, 0, 0}, y = {0, 1, 0, 0}, r;
    dCalcVectorCross3(r, x, y);
    CHECK(r[0] == 0 && r[1] == 0 && r[2] == 1);   // x cross y = z

    dVector3 a = {2, -3, 5, 0}, b = {-1, 4, 2, 0};
    dCalcVectorCross3(r, a, b);
    CHECK(dCalcVectorDot3(r, a) == 0);
    CHECK(dCalcVectorDot3(r, b) == 0);
    dCalcVectorCross3(a, a, b);   // aliasing the result is allowed
    CHECK(a[0] == r[0] && a[1] == r[1] && a[2] == r[2]);
    return 0;
}

static int test_cross_with_strides(void)
{
    // a as column 1 of A (stride 4), b as column 2 of B; results written
    // contiguously or into a column
    dReal A[12] = {0, 2, 0, 0, 0, -3, 0, 0, 0, 5, 0, 0};
    dReal B[12] = {0, 0, -1, 0, 0, 0, 4, 0, 0, 0, 2, 0};
    dReal a[3] = {2, -3, 5}, b[3] = {-1, 4, 2}, want[3], r[12];
    cross(want, a, b);

    dCalcVectorCross3_144(r, A + 1, B + 2);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);
    dCalcVectorCross3_114(r, a, B + 2);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);
    dCalcVectorCross3_141(r, A + 1, b);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);
    dCalcVectorCross3_411(r, a, b);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);
    dCalcVectorCross3_414(r, a, B + 2);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);
    dCalcVectorCross3_441(r, A + 1, b);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);
    dCalcVectorCross3_444(r, A + 1, B + 2);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);

    dVector3 acc = {1, 1, 1, 0};
    dAddVectorCross3(acc, a, b);
    CHECK(acc[0] == 1 + want[0] && acc[1] == 1 + want[1] && acc[2] == 1 + want[2]);
    dSubtractVectorCross3(acc, a, b);
    CHECK(acc[0] == 1 && acc[1] == 1 && acc[2] == 1);
    return 0;
}

static int test_cross_macros(void)
{
    dReal a[3] = {2, -3, 5}, b[3] = {-1, 4, 2}, want[3], r[12];
    cross(want, a, b);

    dCROSS(r, =, a, b);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);
    dCROSS(r, +=, a, b);
    CHECK(r[0] == 2 * want[0] && r[1] == 2 * want[1] && r[2] == 2 * want[2]);
    dCROSS(r, -=, a, b);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);

    dReal B[12] = {0, 0, -1, 0, 0, 0, 4, 0, 0, 0, 2, 0};
    dCROSS114(r, =, a, B + 2);
    CHECK(r[0] == want[0] && r[1] == want[1] && r[2] == want[2]);
    dCROSS414(r, =, a, B + 2);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);
    dCROSS411(r, =, a, b);
    CHECK(r[0] == want[0] && r[4] == want[1] && r[8] == want[2]);

    // dCROSSMAT(+,-) gives M with M*b = a x b
    dMatrix3 M = {0};
    dCROSSMAT(M, a, 4, +, -);
    dReal mb[3];
    dMultiply0_331(mb, M, b);
    CHECK(mb[0] == want[0] && mb[1] == want[1] && mb[2] == want[2]);
    CHECK(M[0] == 0 && M[5] == 0 && M[10] == 0);
    return 0;
}

static int test_cross_matrix_helpers(void)
{
    dReal a[3] = {2, -3, 5}, b[3] = {-1, 4, 2}, want[3], mb[3];
    cross(want, a, b);
    dMatrix3 P = {0}, N = {0};
    dSetCrossMatrixPlus(P, a, 4);
    dSetCrossMatrixMinus(N, a, 4);
    dMultiply0_331(mb, P, b);
    CHECK(mb[0] == want[0] && mb[1] == want[1] && mb[2] == want[2]);
    dMultiply0_331(mb, N, b);
    CHECK(mb[0] == -want[0] && mb[1] == -want[1] && mb[2] == -want[2]);
    return 0;
}

// Reference products of 3x3 blocks (row skip 4).
static dReal el(const dReal *M, int i, int j) { return M[4 * i + j]; }

static int test_matrix_vector_products(void)
{
    dMatrix3 A = {1, 2, 3, 0, -4, 5, 6, 0, 7, -8, 9, 0};
    dReal b[3] = {2, -1, 3}, r[3];

    dMultiply0_331(r, A, b);
    for (int i = 0; i < 3; i++)
        CHECK(r[i] == el(A, i, 0) * b[0] + el(A, i, 1) * b[1] + el(A, i, 2) * b[2]);
    dMultiply1_331(r, A, b);
    for (int i = 0; i < 3; i++)
        CHECK(r[i] == el(A, 0, i) * b[0] + el(A, 1, i) * b[1] + el(A, 2, i) * b[2]);
    dReal r2[3];
    dMultiply0_133(r2, b, A);   // b^T A as a row is A^T b
    CHECK(r2[0] == r[0] && r2[1] == r[1] && r2[2] == r[2]);

    dReal acc[3] = {1, 2, 3};
    dMultiplyAdd0_331(acc, A, b);
    dMultiply0_331(r, A, b);
    CHECK(acc[0] == 1 + r[0] && acc[1] == 2 + r[1] && acc[2] == 3 + r[2]);
    dReal acc1[3] = {1, 2, 3}, acc2[3] = {1, 2, 3};
    dMultiplyAdd1_331(acc1, A, b);
    dMultiplyAdd0_133(acc2, b, A);
    dMultiply1_331(r, A, b);
    CHECK(acc1[0] == 1 + r[0] && acc1[1] == 2 + r[1] && acc1[2] == 3 + r[2]);
    CHECK(acc2[0] == acc1[0] && acc2[1] == acc1[1] && acc2[2] == acc1[2]);

    dMULTIPLY0_331(r2, A, b);
    dMultiply0_331(r, A, b);
    CHECK(r2[0] == r[0] && r2[1] == r[1] && r2[2] == r[2]);
    dMULTIPLY1_331(r2, A, b);
    dMultiply1_331(r, A, b);
    CHECK(r2[0] == r[0] && r2[1] == r[1] && r2[2] == r[2]);
    dMULTIPLY0_133(r2, b, A);
    CHECK(r2[0] == r[0] && r2[1] == r[1] && r2[2] == r[2]);
    dMultiply0_331(b, A, b);   // in place: the result is computed before writing
    dMultiply0_331(r, A, (dReal[3]){2, -1, 3});
    CHECK(b[0] == r[0] && b[1] == r[1] && b[2] == r[2]);
    return 0;
}

// 1 if R (skip 4) equals op(B)*op(C) where t says which are transposed.
static int product_matches(const dReal *R, const dReal *B, const dReal *C, int tb, int tc)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            dReal s = 0;
            for (int k = 0; k < 3; k++)
                s += (tb ? el(B, k, i) : el(B, i, k)) * (tc ? el(C, j, k) : el(C, k, j));
            if (el(R, i, j) != s) return 0;
        }
    return 1;
}

static int test_matrix_matrix_products(void)
{
    dMatrix3 B = {1, 2, 3, 0, -4, 5, 6, 0, 7, -8, 9, 0};
    dMatrix3 C = {2, 0, -1, 0, 3, 1, 4, 0, -2, 5, 1, 0};
    dMatrix3 R, S;

    dMultiply0_333(R, B, C);
    CHECK(product_matches(R, B, C, 0, 0));
    dMultiply1_333(R, B, C);
    CHECK(product_matches(R, B, C, 1, 0));
    dMultiply2_333(R, B, C);
    CHECK(product_matches(R, B, C, 0, 1));

    // the Add forms accumulate: start from R = B*C and add B*C again
    dMultiply0_333(R, B, C);
    dMultiplyAdd0_333(R, B, C);
    dMultiply0_333(S, B, C);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK(el(R, i, j) == 2 * el(S, i, j));
    dMultiply1_333(R, B, C);
    dMultiplyAdd1_333(R, B, C);
    dMultiply1_333(S, B, C);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK(el(R, i, j) == 2 * el(S, i, j));
    dMultiply2_333(R, B, C);
    dMultiplyAdd2_333(R, B, C);
    dMultiply2_333(S, B, C);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK(el(R, i, j) == 2 * el(S, i, j));

    // the 0.5 macros are the same functions
    dMULTIPLY0_333(R, B, C);
    CHECK(product_matches(R, B, C, 0, 0));
    dMULTIPLY1_333(R, B, C);
    CHECK(product_matches(R, B, C, 1, 0));
    dMULTIPLY2_333(R, B, C);
    CHECK(product_matches(R, B, C, 0, 1));
    dMULTIPLYADD0_333(R, B, C);   // R = B C^T + B C
    dMultiply2_333(S, B, C);
    dMultiplyAdd0_333(S, B, C);
    for (int i = 0; i < 12; i++)
        if (i % 4 != 3) CHECK(R[i] == S[i]);
    return 0;
}

static int test_determinant_and_inverse(void)
{
    dMatrix3 A = {2, 1, 0, 0, 1, 3, 1, 0, 0, 1, 4, 0};
    CHECK(dCalcMatrix3Det(A) == 2 * (12 - 1) - 1 * (4 - 0) + 0);   // 18

    dMatrix3 inv, P;
    CHECK(dInvertMatrix3(inv, A) == 18);
    dMultiply0_333(P, A, inv);
    // inv has entries k/18, so A*inv = E only up to rounding
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(el(P, i, j), i == j ? 1 : 0, EPS_TOL);

    dMatrix3 S = {1, 2, 3, 0, 2, 4, 6, 0, 1, 0, 1, 0};   // row 1 = 2 * row 0
    dMatrix3 keep = {7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7};
    CHECK(dInvertMatrix3(keep, S) == 0);
    for (int i = 0; i < 12; i++) CHECK(keep[i] == 7);   // untouched
    return 0;
}

static int test_vector_helpers(void)
{
    dVector3 a = {1, 2, 3, 0}, b = {4, -5, 6, 0}, c = {-1, 0, 2, 0}, r;

    dAddVectors3(r, a, b);
    CHECK(r[0] == 5 && r[1] == -3 && r[2] == 9);
    dSubtractVectors3(r, a, b);
    CHECK(r[0] == -3 && r[1] == 7 && r[2] == -3);
    dAddVectorScaledVector3(r, a, b, 2);
    CHECK(r[0] == 9 && r[1] == -8 && r[2] == 15);
    dAddScaledVectors3(r, a, b, 3, -1);
    CHECK(r[0] == -1 && r[1] == 11 && r[2] == 3);
    dAddThreeScaledVectors3(r, a, b, c, 1, 1, 2);
    CHECK(r[0] == 3 && r[1] == -3 && r[2] == 13);
    dCopyScaledVector3(r, a, -2);
    CHECK(r[0] == -2 && r[1] == -4 && r[2] == -6);
    dScaleVector3(r, 0.5);
    CHECK(r[0] == -1 && r[1] == -2 && r[2] == -3);
    dNegateVector3(r);
    CHECK(r[0] == 1 && r[1] == 2 && r[2] == 3);
    dCopyNegatedVector3(r, b);
    CHECK(r[0] == -4 && r[1] == 5 && r[2] == -6);
    dCopyVector3(r, c);
    CHECK(r[0] == -1 && r[1] == 0 && r[2] == 2);
    dAssignVector3(r, 7, 8, 9);
    CHECK(r[0] == 7 && r[1] == 8 && r[2] == 9);
    dZeroVector3(r);
    CHECK(r[0] == 0 && r[1] == 0 && r[2] == 0);

    dVector3 p = {3, 4, 12, 0}, o = {0, 0, 0, 0};
    CHECK(dCalcVectorLengthSquare3(p) == 169);
    CHECK(dCalcVectorLength3(p) == 13);
    CHECK(dCalcPointsDistance3(p, o) == 13);
    CHECK(dLENGTHSQUARED(p) == 169 && dLENGTH(p) == 13 && dDISTANCE(p, o) == 13);

    // depth of a point below the plane z = 1 (normal +z): 1 - z
    dVector3 plane_p = {5, 5, 1, 0}, n = {0, 0, 1, 0}, below = {2, 3, -2, 0};
    CHECK(dCalcPointDepth3(below, plane_p, n) == 3);
    return 0;
}

static int test_copy_zero_and_column_helpers(void)
{
    dReal src[16], dst[16];
    for (int i = 0; i < 16; i++) src[i] = (dReal)(i + 1);

    dCopyMatrix4x4(dst, src);
    for (int i = 0; i < 16; i++) CHECK(dst[i] == src[i]);
    dZeroMatrix4(dst);
    for (int i = 0; i < 16; i++) CHECK(dst[i] == 0);
    dCopyMatrix4x3(dst, src);
    for (int i = 0; i < 12; i++) CHECK(dst[i] == src[i]);
    CHECK(dst[12] == 0);
    dZeroMatrix3(dst);
    for (int i = 0; i < 12; i++) CHECK(dst[i] == 0);
    dCopyVector4(dst, src);
    CHECK(dst[0] == 1 && dst[3] == 4);

    dReal col[3];
    dGetMatrixColumn3(col, src, 2);
    CHECK(col[0] == 3 && col[1] == 7 && col[2] == 11);
    CHECK(dACCESS33(src, 2, 1) == 10);
    return 0;
}

static int test_op_macros(void)
{
    dReal a[3], b[3] = {1, 2, 3}, c[3] = {4, 5, 6};
    dOP(a, +, b, c);
    CHECK(a[0] == 5 && a[1] == 7 && a[2] == 9);
    dOPC(a, *, b, 2);
    CHECK(a[0] == 2 && a[1] == 4 && a[2] == 6);
    dOPE(a, +=, c);
    CHECK(a[0] == 6 && a[1] == 9 && a[2] == 12);
    dOPEC(a, -=, 1);
    CHECK(a[0] == 5 && a[1] == 8 && a[2] == 11);
    dOPE2(a, =, b, -, c);
    CHECK(a[0] == -3 && a[1] == -3 && a[2] == -3);
    return 0;
}

static int test_valid_macros(void)
{
    dMatrix3 M = {0};
    CHECK(dVALIDVEC3(M) && dVALIDVEC4(M) && dVALIDMAT3(M));
    M[9] = NAN;
    CHECK(!dVALIDMAT3(M));
    CHECK(dVALIDVEC4(M));
    dMatrix4 M4 = {0};
    CHECK(dVALIDMAT4(M4));
    M4[15] = NAN;
    CHECK(!dVALIDMAT4(M4));
    return 0;
}

// ---------------------------------------------------------------- normalisation

static int test_normalize_gives_unit_vector_along_input(void)
{
    dVector3 a = {3, 4, 0, 0};
    CHECK(dSafeNormalize3(a) == 1);
    CHECK_NEAR(a[0], 0.6, EPS_TOL);
    CHECK_NEAR(a[1], 0.8, EPS_TOL);
    CHECK(a[2] == 0);

    for (int k = 0; k < 100; k++) {
        dVector3 v = {(dReal)rnd(), (dReal)rnd(), (dReal)rnd(), 0}, u, c;
        dCopyVector3(u, v);
        dNormalize3(u);
        CHECK_NEAR(dCalcVectorLength3(u), 1, EPS_TOL);
        // same direction: u x v = 0 and u . v = |v| > 0
        dCalcVectorCross3(c, u, v);
        CHECK_NEAR(dCalcVectorLength3(c), 0, EPS_TOL);
        CHECK_NEAR(dCalcVectorDot3(u, v), dCalcVectorLength3(v), EPS_TOL);
    }
    return 0;
}

static int test_normalize4(void)
{
    dVector4 a = {1, -1, 1, -1};
    CHECK(dSafeNormalize4(a) == 1);
    for (int i = 0; i < 4; i++) CHECK_NEAR(a[i], (i % 2 ? -0.5 : 0.5), EPS_TOL);
    dVector4 b = {0, 0, 0, 2};
    dNormalize4(b);
    CHECK(b[0] == 0 && b[1] == 0 && b[2] == 0 && b[3] == 1);
    return 0;
}

static int test_normalize_tiny_and_huge_vectors(void)
{
    // squares of these under/overflow dReal; the result must still be exact
    // to rounding: (1, 2, 2)/3
    const dReal tiny = TOL(1e-300, 1e-30f), huge = TOL(1e300, 1e37f);
    dVector3 t = {tiny, 2 * tiny, 2 * tiny, 0}, h = {huge, 2 * huge, -2 * huge, 0};
    CHECK(dSafeNormalize3(t) == 1);
    CHECK(dSafeNormalize3(h) == 1);
    CHECK_NEAR(t[0], 1.0 / 3, EPS_TOL);
    CHECK_NEAR(t[1], 2.0 / 3, EPS_TOL);
    CHECK_NEAR(t[2], 2.0 / 3, EPS_TOL);
    CHECK_NEAR(h[0], 1.0 / 3, EPS_TOL);
    CHECK_NEAR(h[2], -2.0 / 3, EPS_TOL);

    dVector4 q = {huge, huge, huge, huge};
    CHECK(dSafeNormalize4(q) == 1);
    for (int i = 0; i < 4; i++) CHECK_NEAR(q[i], 0.5, EPS_TOL);
    return 0;
}

static int test_safe_normalize_of_zero_is_silent(void)
{
    test_capture_reports();
    dVector3 z = {0, 0, 0, 0};
    dVector4 z4 = {0, 0, 0, 0};
    dVector3 bad = {NAN, 1, 0, 0};
    dVector3 inf = {INFINITY, 1, 0, 0};

    CHECK(dSafeNormalize3(z) == 0);
    CHECK(dSafeNormalize4(z4) == 0);
    CHECK(dSafeNormalize3(bad) == 0);
    CHECK(dSafeNormalize3(inf) == 0);

    CHECK(z[0] == 1 && z[1] == 0 && z[2] == 0);
    CHECK(z4[0] == 1 && z4[1] == 0 && z4[2] == 0 && z4[3] == 0);
    CHECK(bad[0] == 1 && bad[1] == 0 && bad[2] == 0);
    CHECK(inf[0] == 1 && inf[1] == 0 && inf[2] == 0);
    CHECK(test_captured_count() == 0);
    return 0;
}

static int test_normalize_of_zero_is_reported(void)
{
    test_capture_reports();
    dVector3 z = {0, 0, 0, 0};
    dNormalize3(z);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dNormalize3"));
    CHECK(test_captured_contains("zero length"));
    CHECK(z[0] == 1 && z[1] == 0 && z[2] == 0);

    dVector4 z4 = {0, 0, 0, 0};
    dNormalize4(z4);
    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("dNormalize4"));
    CHECK(z4[0] == 1 && z4[1] == 0 && z4[2] == 0 && z4[3] == 0);

    dVector3 nan = {NAN, NAN, NAN, 0};
    dNormalize3(nan);
    CHECK(test_captured_count() == 3);
    CHECK(nan[0] == 1 && nan[1] == 0 && nan[2] == 0);
    return 0;
}

// ---------------------------------------------------------------- dPlaneSpace

// p, q unit, and n, p, q mutually perpendicular with q = n x p.
static int check_plane_space(const dVector3 n)
{
    dVector3 p, q, nxp;
    dPlaneSpace(n, p, q);
    CHECK_NEAR(dCalcVectorLength3(p), 1, EPS_TOL);
    CHECK_NEAR(dCalcVectorLength3(q), 1, EPS_TOL);
    CHECK_NEAR(dCalcVectorDot3(n, p), 0, EPS_TOL);
    CHECK_NEAR(dCalcVectorDot3(n, q), 0, EPS_TOL);
    CHECK_NEAR(dCalcVectorDot3(p, q), 0, EPS_TOL);
    dCalcVectorCross3(nxp, n, p);
    for (int i = 0; i < 3; i++) CHECK_NEAR(q[i], nxp[i], EPS_TOL);
    return 0;
}

static int test_plane_space_is_orthonormal_for_many_directions(void)
{
    // the axes, directions at the branch switch |n_z| = sqrt(1/2), and a
    // spiral of 500 points covering the sphere
    const dReal s = (dReal)M_SQRT1_2;
    dVector3 special[] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, 0, 0, 0},
                          {0, -1, 0, 0}, {0, 0, -1, 0}, {s, 0, s, 0}, {0, s, -s, 0},
                          {-s, 0, s, 0}};
    for (size_t k = 0; k < sizeof special / sizeof special[0]; k++)
        if (check_plane_space(special[k])) return 1;
    const int N = 500;
    for (int k = 0; k < N; k++) {
        double z = 1 - (2.0 * k + 1) / N, r = sqrt(1 - z * z), phi = k * 2.399963229728653;
        dVector3 n = {(dReal)(r * cos(phi)), (dReal)(r * sin(phi)), (dReal)z, 0};
        dNormalize3(n);
        if (check_plane_space(n)) return 1;
    }
    return 0;
}

static int test_plane_space_of_zero_is_reported(void)
{
    test_capture_reports();
    dVector3 n = {0, 0, 0, 0}, p = {5, 5, 5, 5}, q = {6, 6, 6, 6};
    dPlaneSpace(n, p, q);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dPlaneSpace"));
    CHECK(p[0] == 5 && q[0] == 6);   // left unchanged
    dVector3 nan = {NAN, 0, 1, 0};
    dPlaneSpace(nan, p, q);
    CHECK(test_captured_count() == 2);
    CHECK(p[0] == 5 && q[0] == 6);
    return 0;
}

// ---------------------------------------------------------------- dOrthogonalizeR

// R R^T = E and det R = 1.
static int check_rotation(const dMatrix3 R, double tol)
{
    dMatrix3 P;
    dMultiply2_333(P, R, R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(el(P, i, j), i == j ? 1 : 0, tol);
    CHECK_NEAR(dCalcMatrix3Det(R), 1, tol);
    return 0;
}

static int test_orthogonalize_repairs_a_perturbed_rotation(void)
{
    for (int k = 0; k < 50; k++) {
        // a rotation about a random axis, disturbed by up to 1e-3 per entry
        dMatrix3 R, M;
        dRFromAxisAndAngle(R, (dReal)rnd(), (dReal)rnd(), (dReal)rnd() + 2, (dReal)(3 * rnd()));
        for (int i = 0; i < 12; i++) M[i] = R[i] + (dReal)(1e-3 * rnd());
        dMatrix3 orig;
        dCopyMatrix4x3(orig, M);

        CHECK(dOrthogonalizeR(M) == 1);
        if (check_rotation(M, EPS_TOL)) return 1;
        // row 0 keeps its direction; row 1 stays in the plane of rows 0 and 1
        dReal c[3];
        dCalcVectorCross3(c, M, orig);
        CHECK_NEAR(dCalcVectorLength3(c), 0, EPS_TOL);
        CHECK(dCalcVectorDot3(M, orig) > 0);
        dReal n[3];
        dCalcVectorCross3(n, orig, orig + 4);
        CHECK_NEAR(dCalcVectorDot3(n, M + 4) / dCalcVectorLength3(n), 0, EPS_TOL);
        CHECK(dCalcVectorDot3(M + 4, orig + 4) > 0);
        // and the repair moved nothing by more than the disturbance allows
        for (int i = 0; i < 12; i++)
            if (i % 4 != 3) CHECK_NEAR(M[i], R[i], 1e-2);
        CHECK(M[3] == 0 && M[7] == 0 && M[11] == 0);
    }
    return 0;
}

static int test_orthogonalize_makes_a_right_handed_frame(void)
{
    // a reflection: row 2 is replaced by row 0 x row 1
    dMatrix3 M = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, -1, 0};
    CHECK(dOrthogonalizeR(M) == 1);
    CHECK(M[0] == 1 && M[5] == 1 && M[10] == 1);
    CHECK(M[1] == 0 && M[2] == 0 && M[4] == 0 && M[6] == 0 && M[8] == 0 && M[9] == 0);

    // a row 1 nearly parallel to row 0 still gives an exact rotation
    dMatrix3 N = {1, 1, 0, 0, 1, TOL(1 + 1e-9, 1 + 1e-3f), 0, 0, 0, 0, 1, 0};
    CHECK(dOrthogonalizeR(N) == 1);
    return check_rotation(N, EPS_TOL);
}

static int test_orthogonalize_rejects_degenerate_rows(void)
{
    test_capture_reports();
    dMatrix3 zero_row = {0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    dMatrix3 parallel = {1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0};
    dMatrix3 nan = {1, 0, 0, 0, 0, NAN, 0, 0, 0, 0, 1, 0};
    dMatrix3 copy;

    dCopyMatrix4x3(copy, zero_row);
    CHECK(dOrthogonalizeR(zero_row) == 0);
    CHECK(memcmp(copy, zero_row, sizeof copy) == 0);
    dCopyMatrix4x3(copy, parallel);
    CHECK(dOrthogonalizeR(parallel) == 0);
    CHECK(memcmp(copy, parallel, sizeof copy) == 0);
    CHECK(dOrthogonalizeR(nan) == 0);
    CHECK(dIsNan(nan[5]) && nan[0] == 1);
    CHECK(test_captured_count() == 0);   // a degenerate matrix is an answer, not an error
    return 0;
}

static int test_null_pointers_are_reported(void)
{
    test_capture_reports();
    dVector3 v = {1, 0, 0, 0};
    CHECK(dSafeNormalize3(NULL) == 0);
    CHECK(dSafeNormalize4(NULL) == 0);
    dNormalize3(NULL);
    dNormalize4(NULL);
    dPlaneSpace(v, NULL, v);
    CHECK(dOrthogonalizeR(NULL) == 0);
    CHECK(test_captured_count() == 6);
    CHECK(test_captured_contains("NULL"));
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_dot_with_strides),
    TEST_CASE(test_cross_is_perpendicular_and_right_handed),
    TEST_CASE(test_cross_with_strides),
    TEST_CASE(test_cross_macros),
    TEST_CASE(test_cross_matrix_helpers),
    TEST_CASE(test_matrix_vector_products),
    TEST_CASE(test_matrix_matrix_products),
    TEST_CASE(test_determinant_and_inverse),
    TEST_CASE(test_vector_helpers),
    TEST_CASE(test_copy_zero_and_column_helpers),
    TEST_CASE(test_op_macros),
    TEST_CASE(test_valid_macros),
    TEST_CASE(test_normalize_gives_unit_vector_along_input),
    TEST_CASE(test_normalize4),
    TEST_CASE(test_normalize_tiny_and_huge_vectors),
    TEST_CASE(test_safe_normalize_of_zero_is_silent),
    TEST_CASE(test_normalize_of_zero_is_reported),
    TEST_CASE(test_plane_space_is_orthonormal_for_many_directions),
    TEST_CASE(test_plane_space_of_zero_is_reported),
    TEST_CASE(test_orthogonalize_repairs_a_perturbed_rotation),
    TEST_CASE(test_orthogonalize_makes_a_right_handed_frame),
    TEST_CASE(test_orthogonalize_rejects_degenerate_rows),
    TEST_CASE(test_null_pointers_are_reported),
    TEST_END
};
