// SPDX-License-Identifier: BSD-3-Clause
//
// test_matrix.c -- the dense matrix functions: products, Cholesky and LDL^T
// factorisations and solves, the LDL^T updates and dRemoveRowCol.
//
// Tolerances: inputs are O(1) or O(n) and every quantity compared is a short
// sum of products, so errors are a small multiple of n * eps * magnitude with
// eps = 2.2e-16 (double) or 1.2e-7 (single); each check states its bound.

#include "test.h"

#define NMAX 12
#define SMAX (NMAX * NMAX + 4 * NMAX)   // room for NMAX rows of skip dPAD(NMAX) or more

// Largest |x| over an n-vector.
static double max_abs(const dReal *x, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs((double)x[i]));
    return m;
}

// A = B B^T + n I, a symmetric positive definite n x n matrix (skip dPAD(n)) whose
// eigenvalues lie in [n, n + n^2]: condition number at most n + 1.
static void make_spd(dReal *A, int n)
{
    dReal B[SMAX];
    dMakeRandomMatrix(B, n, n, 1);
    dMultiply2(A, B, B, n, n, n);
    for (int i = 0; i < n; i++) A[i * dPAD(n) + i] += n;
}

// Copy the n x n matrix A with skip sa into skip sb.
static void copy_matrix(dReal *dst, int sb, const dReal *src, int sa, int n)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) dst[i * sb + j] = src[i * sa + j];
}

// M = L D L^T (skip dPAD(n)) from the strict lower triangle of L (skip nskip) and d = 1/D.
static void ldlt_product(dReal *M, const dReal *L, const dReal *d, int n, int nskip)
{
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            double sum = 0;
            for (int k = 0; k <= (i < j ? i : j); k++) {
                double lik = k == i ? 1 : L[i * nskip + k], ljk = k == j ? 1 : L[j * nskip + k];
                sum += lik * ljk / d[k];
            }
            M[i * dPAD(n) + j] = (dReal)sum;
        }
    }
}

static int test_set_zero_set_value_and_dot(void)
{
    dReal a[5] = {1, 2, 3, 4, 5}, b[5] = {2, -1, 0.5, 4, 0};

    CHECK(dDot(a, b, 5) == REAL(2.0) - 2 + REAL(1.5) + 16);   // exact in binary
    CHECK(dDot(a, b, 0) == 0);
    dSetValue(a, 4, REAL(-2.5));
    CHECK(a[0] == REAL(-2.5) && a[3] == REAL(-2.5) && a[4] == 5);
    dSetZero(a, 3);
    CHECK(a[0] == 0 && a[2] == 0 && a[3] == REAL(-2.5));
    return 0;
}

static int test_multiply0_hand_computed(void)
{
    // [1 2 3; 4 5 6] (skip 4) times [1 0; 0 1; 2 -1] (skip 4: dPAD(2) == 4).
    const dReal B[8] = {1, 2, 3, 99, 4, 5, 6, 99};
    const dReal C[12] = {1, 0, 99, 99, 0, 1, 99, 99, 2, -1, 99, 99};
    dReal A[8] = {-7, -7, -7, -7, -7, -7, -7, -7};

    dMultiply0(A, B, C, 2, 3, 2);

    // Small integers: exact in either precision.
    CHECK(A[0] == 7 && A[1] == -1 && A[4] == 16 && A[5] == -1);
    CHECK(A[2] == -7 && A[3] == -7);   // padding of A is not written
    return 0;
}

// The three products of one random B (p x q) and C (q x r), B and C transposed by hand.
static int check_product_forms(int p, int q, int r)
{
    dReal B[8 * 8], C[8 * 8], Bt[8 * 8], Ct[8 * 8], A0[8 * 8], A1[8 * 8], A2[8 * 8];
    dMakeRandomMatrix(B, p, q, 1);
    dMakeRandomMatrix(C, q, r, 1);
    for (int i = 0; i < p; i++)
        for (int k = 0; k < q; k++) Bt[k * dPAD(p) + i] = B[i * dPAD(q) + k];
    for (int k = 0; k < q; k++)
        for (int j = 0; j < r; j++) Ct[j * dPAD(q) + k] = C[k * dPAD(r) + j];

    dMultiply0(A0, B, C, p, q, r);
    dMultiply1(A1, Bt, C, p, q, r);
    dMultiply2(A2, B, Ct, p, q, r);

    // At most 8 products of numbers in [-1,1] summed: a few ulps of 8 apart.
    CHECK(dMaxDifference(A0, A1, p, r) <= TOL(1e-14, 5e-6));
    CHECK(dMaxDifference(A0, A2, p, r) <= TOL(1e-14, 5e-6));
    for (int i = 0; i < p; i++) {
        for (int j = 0; j < r; j++) {
            double sum = 0;   // the element by its definition
            for (int k = 0; k < q; k++) sum += (double)B[i * dPAD(q) + k] * C[k * dPAD(r) + j];
            CHECK_NEAR(A0[i * dPAD(r) + j], sum, TOL(1e-14, 5e-6));
        }
    }
    return 0;
}

static int test_multiply_forms_agree_through_transposes(void)
{
    static const int shapes[][3] = {{3, 5, 6}, {1, 1, 1}, {2, 3, 1}, {4, 4, 3}, {5, 2, 7},
                                     {1, 8, 2}, {8, 1, 8}, {3, 3, 3}};
    dRandSetSeed(11);
    for (size_t t = 0; t < sizeof shapes / sizeof shapes[0]; t++)
        CHECK(check_product_forms(shapes[t][0], shapes[t][1], shapes[t][2]) == 0);
    return 0;
}

static int test_multiply_vectors_use_skip_one(void)
{
    // 1 x 3 row times 3 x 1 column: skips dPAD(3) == 4 for B, dPAD(1) == 1 for C and A.
    const dReal B[4] = {1, 2, 3, 0}, C[3] = {4, 5, 6};
    dReal A[1];
    dMultiply0(A, B, C, 1, 3, 1);
    CHECK(A[0] == 32);
    // Outer product 3 x 1 times 1 x 3 through dMultiply2 (C^T of a 3 x 1 is 1 x 3).
    dReal O[12];
    dMultiply2(O, C, B, 3, 1, 3);   // B is 3 x 1 with skip 1: its elements are B[0..2]
    CHECK(O[0] == 4 && O[1] == 8 && O[2] == 12 && O[4] == 5 && O[10] == 18);
    // B^T C with B and C both 3 x 1 (skip 1) is their dot product.
    dMultiply1(A, C, C, 1, 3, 1);
    CHECK(A[0] == 77);
    return 0;
}

static int test_cholesky_of_known_matrix(void)
{
    dReal A[12] = {4, 90, 91, 0, 2, 5, 92, 0, 1, 3, 6, 0};

    CHECK(dFactorCholesky(A, 3) == 1);

    // L = [2; 1 2; 0.5 1.25 sqrt(6 - 0.25 - 1.5625)], all but the last exact.
    CHECK(A[0] == 2 && A[4] == 1 && A[5] == 2 && A[8] == REAL(0.5) && A[9] == REAL(1.25));
    CHECK_NEAR(A[10], sqrt(4.1875), TOL(1e-15, 1e-6));   // one rounding of a number near 2
    CHECK(A[1] == 90 && A[2] == 91 && A[6] == 92);      // strict upper triangle untouched
    return 0;
}

static int test_cholesky_solves_random_spd_systems(void)
{
    static const int sizes[] = {1, 2, 3, 4, 5, 8, 12};
    dRandSetSeed(1);
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; t++) {
        const int n = sizes[t];
        dReal A[SMAX], L[SMAX], b[NMAX], x[NMAX], Ax[NMAX];
        make_spd(A, n);
        memcpy(L, A, sizeof L);
        dMakeRandomVector(b, n, 1);
        memcpy(x, b, sizeof x);

        CHECK(dFactorCholesky(L, n) == 1);
        dSolveCholesky(L, x, n);

        // Backward stable solve with condition number <= n + 1 <= 13.
        dMultiply0(Ax, A, x, n, n, 1);
        for (int i = 0; i < n; i++) CHECK_NEAR(Ax[i], b[i], TOL(1e-10, 1e-3) * max_abs(b, n));
        // L L^T reproduces A (lower triangle; the upper holds A's own values).
        dClearUpperTriangle(L, n);
        dReal LLt[SMAX];
        dMultiply2(LLt, L, L, n, n, n);
        CHECK(dMaxDifference(LLt, A, n, n) <= TOL(1e-12, 1e-4) * 2 * n);
    }
    return 0;
}

static int test_invert_pd_matrix_times_a_is_identity(void)
{
    const int n = 7, s = dPAD(n);
    dReal A[SMAX], A0[SMAX], Ainv[SMAX], I[SMAX];
    dRandSetSeed(2);
    make_spd(A, n);
    memcpy(A0, A, sizeof A);
    dSetValue(Ainv, SMAX, 55);

    CHECK(dInvertPDMatrix(A, Ainv, n) == 1);

    dMultiply0(I, Ainv, A, n, n, n);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            CHECK_NEAR(I[i * s + j], i == j, TOL(1e-12, 1e-5));   // cond <= 8, |A| <= 14
    CHECK(dMaxDifference(A, A0, n, n) == 0);                       // A not modified
    for (int i = 0; i < n; i++) CHECK(Ainv[i * s + n] == 0);       // padding zeroed
    return 0;
}

static int test_non_pd_matrices_are_detected(void)
{
    // Eigenvalues 3 and -1; then a zero pivot; then a negative diagonal.
    dReal A[8] = {1, 2, 0, 0, 2, 1, 0, 0}, Ainv[8] = {5, 5, 5, 5, 5, 5, 5, 5};
    dReal S[8] = {1, 1, 0, 0, 1, 1, 0, 0}, N[1] = {-1};
    const dReal A0[8] = {1, 2, 0, 0, 2, 1, 0, 0};

    CHECK(dIsPositiveDefinite(A, 2) == 0);
    CHECK(dIsPositiveDefinite(S, 2) == 0);
    CHECK(dIsPositiveDefinite(N, 1) == 0);
    CHECK(dInvertPDMatrix(A, Ainv, 2) == 0);
    CHECK(Ainv[0] == 5 && Ainv[5] == 5);            // untouched on failure
    CHECK(dMaxDifference(A, A0, 2, 2) == 0);        // A untouched
    CHECK(dFactorCholesky(A, 2) == 0);
    A[0] = 2;
    A[4] = A[1] = 1;
    CHECK(dIsPositiveDefinite(A, 2) == 1);          // [2 1; 1 1]: det 1 > 0
    return 0;
}

static int test_large_matrices_use_the_heap(void)
{
    // 1100 x 1104 dReals are 9.7 MB in double: more than a default 8 MB stack.
    const int n = 1100, s = dPAD(n);
    dReal *A = calloc((size_t)n * s, sizeof *A);
    CHECK(A != NULL);
    for (int i = 0; i < n; i++) {
        A[i * s + i] = 4;
        if (i > 0) A[i * s + i - 1] = A[(i - 1) * s + i] = 1;   // tridiagonal, dominant
    }
    int pd = dIsPositiveDefinite(A, n);
    A[(n - 1) * s + n - 1] = -1;
    int not_pd = dIsPositiveDefinite(A, n);
    free(A);
    CHECK(pd == 1);
    CHECK(not_pd == 0);
    return 0;
}

static int test_ldlt_of_known_matrix(void)
{
    dReal A[12] = {4, 90, 91, 0, 2, 5, 92, 0, 1, 3, 6, 0}, d[3];

    dFactorLDLT(A, d, 3, 4);

    // L = [1; 0.5 1; 0.25 0.625 1], D = (4, 4, 4.1875): all exact but 1/4.1875.
    CHECK(A[4] == REAL(0.5) && A[8] == REAL(0.25) && A[9] == REAL(0.625));
    CHECK(d[0] == REAL(0.25) && d[1] == REAL(0.25));
    CHECK_NEAR(d[2], 1 / 4.1875, TOL(1e-16, 2e-8));   // one rounding near 0.24
    CHECK(A[0] == 4 && A[5] == 5 && A[10] == 6);      // diagonal left as it was
    CHECK(A[1] == 90 && A[2] == 91 && A[6] == 92);    // upper triangle too
    return 0;
}

static int test_ldlt_factor_and_solve_random(void)
{
    static const int sizes[] = {1, 2, 3, 6, 9, 12};
    dRandSetSeed(3);
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; t++) {
        const int n = sizes[t], nskip = n + 3;   // any nskip >= n is allowed
        dReal A[SMAX], L[NMAX * (NMAX + 3)], d[NMAX], M[SMAX], b[NMAX], x[NMAX], Ax[NMAX];
        make_spd(A, n);
        copy_matrix(L, nskip, A, dPAD(n), n);

        dFactorLDLT(L, d, n, nskip);
        ldlt_product(M, L, d, n, nskip);
        // Entries of A are <= 2n; the product sums n terms of that size.
        CHECK(dMaxDifference(M, A, n, n) <= TOL(1e-13, 1e-5) * 2 * n);

        dMakeRandomVector(b, n, 1);
        memcpy(x, b, sizeof x);
        dSolveLDLT(L, d, x, n, nskip);
        dMultiply0(Ax, A, x, n, n, 1);
        for (int i = 0; i < n; i++) CHECK_NEAR(Ax[i], b[i], TOL(1e-10, 1e-3) * max_abs(b, n));
    }
    return 0;
}

static int test_triangular_solves_and_scale(void)
{
    // L = [1; 2 1; -1 3 1] stored with skip 5 (strict lower only; the rest is noise).
    const dReal L[15] = {9, 9, 9, 9, 9, 2, 9, 9, 9, 9, -1, 3, 9, 9, 9};
    dReal b[3] = {1, 4, 0}, c[3] = {1, 4, 0};

    dSolveL1(L, b, 3, 5);    // x0 = 1, x1 = 4 - 2 = 2, x2 = 0 + 1 - 6 = -5
    CHECK(b[0] == 1 && b[1] == 2 && b[2] == -5);
    dSolveL1T(L, c, 3, 5);   // x2 = 0, x1 = 4 - 3*0 = 4, x0 = 1 - 2*4 + 1*0 = -7
    CHECK(c[0] == -7 && c[1] == 4 && c[2] == 0);

    const dReal s[3] = {2, REAL(0.5), -1};
    dScaleVector(b, s, 3);
    CHECK(b[0] == 2 && b[1] == 1 && b[2] == 5);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    dVectorScale(b, s, 2);   // the deprecated alias does the same
#pragma GCC diagnostic pop
    CHECK(b[0] == 4 && b[1] == REAL(0.5) && b[2] == 5);
    return 0;
}

// Factor A, add the top-left cross a through dLDLTAddTL, and compare with factoring A + T.
static int check_add_tl(int n, dReal scale, dReal corner)
{
    const int s = dPAD(n);
    dReal A[SMAX], L[SMAX], d[NMAX], L2[SMAX], d2[NMAX], a[NMAX];
    make_spd(A, n);
    dMakeRandomVector(a, n, scale);
    a[0] = corner;
    memcpy(L, A, sizeof L);
    dFactorLDLT(L, d, n, s);
    memcpy(L2, A, sizeof L2);
    L2[0] += a[0];
    for (int i = 1; i < n; i++) {
        L2[i * s] += a[i];
        L2[i] += a[i];
    }
    dFactorLDLT(L2, d2, n, s);

    dLDLTAddTL(L, d, a, n, s);

    // The factors of a matrix with entries <= 2n and condition <= ~2n: a rank-two update
    // and a refactorisation agree to a few hundred eps.
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(d[i], d2[i], TOL(1e-13, 1e-4) * fabs((double)d2[i]));
        for (int j = 0; j < i; j++) CHECK_NEAR(L[i * s + j], L2[i * s + j], TOL(1e-12, 1e-4));
    }
    return 0;
}

static int test_ldlt_add_tl_matches_refactorisation(void)
{
    dRandSetSeed(4);
    // A's eigenvalues are >= n and |T| <= |a0| + sqrt(n - 1) * scale, so A + T stays PD.
    for (int n = 1; n <= NMAX; n++) CHECK(check_add_tl(n, REAL(0.9), REAL(0.7)) == 0);
    for (int n = 2; n <= NMAX; n++) CHECK(check_add_tl(n, REAL(0.5), REAL(-0.8)) == 0);
    for (int n = 3; n <= NMAX; n++) CHECK(check_add_tl(n, REAL(0.001), REAL(20.0)) == 0);
    CHECK(check_add_tl(4, 0, 0) == 0);   // T = 0 changes nothing
    return 0;
}

// Removing row and column r of the n2 x n2 matrix M(i,j) = A[p[i]][p[j]].
static int check_remove(dReal **rows, const int *p, int n1, int n2, int r)
{
    const int nskip = 9;
    dReal L[NMAX * 9], d[NMAX], M[SMAX], sub[SMAX];
    for (int i = 0; i < n2; i++)
        for (int j = 0; j < n2; j++) L[i * nskip + j] = rows[p[i]][p[j]];
    dFactorLDLT(L, d, n2, nskip);

    dLDLTRemove(rows, p, L, d, n1, n2, r, nskip);

    const int m = n2 - 1, s = dPAD(m);
    for (int i = 0; i < m; i++) {
        const dReal *row = rows[p[i < r ? i : i + 1]];
        for (int j = 0; j < m; j++) sub[i * s + j] = row[p[j < r ? j : j + 1]];
    }
    ldlt_product(M, L, d, m, nskip);
    // Entries <= 2 n1 = 18, condition <= 10: a few hundred eps of 18.
    CHECK(dMaxDifference(M, sub, m, m) <= TOL(1e-12, 1e-4));
    return 0;
}

static int test_ldlt_remove_every_row(void)
{
    const int n1 = 9, n2 = 7, s = dPAD(n1);
    const int p[7] = {5, 2, 8, 0, 3, 7, 1};   // a non-trivial selection and order
    dReal A[9 * 12], *rows[9];
    dRandSetSeed(5);
    make_spd(A, n1);
    for (int i = 0; i < n1; i++) rows[i] = A + i * s;
    for (int r = 0; r < n2; r++) CHECK(check_remove(rows, p, n1, n2, r) == 0);
    // From 2 x 2 down to 1 x 1, both ways.
    CHECK(check_remove(rows, p, n1, 2, 0) == 0);
    CHECK(check_remove(rows, p, n1, 2, 1) == 0);
    return 0;
}

static int test_ldlt_remove_repeatedly(void)
{
    // Shrink a factorisation one row at a time, as an LCP solver does, and compare at the end.
    const int n = 8, s = dPAD(n), nskip = 8;
    int p[8] = {3, 6, 0, 7, 1, 4, 2, 5};
    dReal A[8 * 8], L[8 * 8], d[8], M[8 * 8], sub[8 * 8], *rows[8];
    dRandSetSeed(6);
    make_spd(A, n);
    for (int i = 0; i < n; i++) rows[i] = A + i * s;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) L[i * nskip + j] = rows[p[i]][p[j]];
    dFactorLDLT(L, d, n, nskip);

    static const int removals[] = {2, 0, 4, 1, 0};
    int m = n;
    for (int k = 0; k < 5; k++, m--) {
        dLDLTRemove(rows, p, L, d, n, m, removals[k], nskip);
        for (int i = removals[k]; i < m - 1; i++) p[i] = p[i + 1];
    }
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) sub[i * dPAD(m) + j] = rows[p[i]][p[j]];
    ldlt_product(M, L, d, m, nskip);
    CHECK(dMaxDifference(M, sub, m, m) <= TOL(1e-12, 1e-4));   // as above, five updates
    return 0;
}

static int test_remove_row_col_on_numbered_matrix(void)
{
    // A(i,j) = 10 i + j in a 5 x 5 matrix with skip 6.
    dReal A[30];
    for (int r = 0; r < 5; r++) {
        for (int i = 0; i < 30; i++) A[i] = 10 * (i / 6) + i % 6;

        dRemoveRowCol(A, 5, 6, r);

        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                CHECK(A[i * 6 + j] == 10 * (i < r ? i : i + 1) + (j < r ? j : j + 1));
        for (int j = 0; j < 6; j++) CHECK(A[4 * 6 + j] == 40 + j);   // last row untouched
        for (int i = 0; i < 4; i++) CHECK(A[i * 6 + 5] == 10 * i + 5);   // skip padding too
    }
    return 0;
}

static int test_bad_arguments_are_reported(void)
{
    test_capture_reports();
    dReal A[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, d[4] = {7, 7, 7, 7};

    CHECK(dFactorCholesky(NULL, 3) == 0);
    CHECK(test_captured_contains("dFactorCholesky") && test_captured_contains("A is NULL"));
    dFactorLDLT(A, d, 4, 3);
    CHECK(test_captured_contains("dFactorLDLT") && test_captured_contains("nskip"));
    CHECK(d[0] == 7);   // the call did nothing
    dRemoveRowCol(A, 4, 4, 4);
    CHECK(test_captured_contains("dRemoveRowCol") && test_captured_contains("r must be"));
    CHECK(A[15] == 1 && A[10] == 1);
    dMultiply0(A, A, A, 2, -1, 2);
    CHECK(test_captured_contains("dMultiply0") && test_captured_contains("-1"));
    dSetZero(A, -2);
    CHECK(test_captured_contains("dSetZero") && test_captured_contains("n must be"));
    int p[2] = {0, 1};
    dReal *rows[2] = {A, A + 4};
    dLDLTRemove(rows, p, A, d, 2, 2, 2, 4);
    CHECK(test_captured_contains("dLDLTRemove"));
    CHECK(test_captured_count() == 6);
    return 0;
}

static int test_empty_sizes_do_nothing(void)
{
    test_capture_reports();
    dReal A[4] = {3, 3, 3, 3}, d[1] = {3};

    CHECK(dFactorCholesky(A, 0) == 1);
    CHECK(dIsPositiveDefinite(A, 0) == 1);
    CHECK(dInvertPDMatrix(A, A, 0) == 1);
    dFactorLDLT(A, d, 0, 0);
    dSolveLDLT(A, d, A, 0, 0);
    dLDLTAddTL(A, d, A, 0, 0);
    dMultiply0(A, A, A, 0, 0, 0);
    dMultiply1(A, A, A, 1, 0, 1);   // an empty sum: A = 0
    CHECK(A[0] == 0 && A[1] == 3 && d[0] == 3);
    CHECK(test_captured_count() == 0);
    return 0;
}

static int test_add_tl_on_one_by_one(void)
{
    // A 1 x 1 factorisation is just D; adding a[0] gives D + a[0].
    dReal L[1] = {0}, d[1] = {REAL(0.5)}, a[1] = {3};
    dLDLTAddTL(L, d, a, 1, 1);
    CHECK_NEAR(d[0], 0.2, TOL(1e-15, 1e-7));   // 1 / (2 + 3), a few roundings
    a[0] = -4;
    dLDLTAddTL(L, d, a, 1, 1);
    CHECK_NEAR(d[0], 1.0, TOL(1e-15, 1e-6));   // 1 / (5 - 4)
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_set_zero_set_value_and_dot),
    TEST_CASE(test_multiply0_hand_computed),
    TEST_CASE(test_multiply_forms_agree_through_transposes),
    TEST_CASE(test_multiply_vectors_use_skip_one),
    TEST_CASE(test_cholesky_of_known_matrix),
    TEST_CASE(test_cholesky_solves_random_spd_systems),
    TEST_CASE(test_invert_pd_matrix_times_a_is_identity),
    TEST_CASE(test_non_pd_matrices_are_detected),
    TEST_CASE(test_large_matrices_use_the_heap),
    TEST_CASE(test_ldlt_of_known_matrix),
    TEST_CASE(test_ldlt_factor_and_solve_random),
    TEST_CASE(test_triangular_solves_and_scale),
    TEST_CASE(test_ldlt_add_tl_matches_refactorisation),
    TEST_CASE(test_ldlt_remove_every_row),
    TEST_CASE(test_ldlt_remove_repeatedly),
    TEST_CASE(test_remove_row_col_on_numbered_matrix),
    TEST_CASE(test_bad_arguments_are_reported),
    TEST_CASE(test_empty_sizes_do_nothing),
    TEST_CASE(test_add_tl_on_one_by_one),
    TEST_END
};
