// SPDX-License-Identifier: BSD-3-Clause
//
// diff_matrix.c -- the matrix functions and the random number generator,
// printed for comparison with the reference ODE (see diff_print.h). All
// inputs come from the seeded generator, so both builds see the same numbers.
//
// Tolerances: generator integers and seeds must match exactly; values derived
// from one draw by the same formula get 1e-15 of their magnitude; factors and
// solves of matrices with entries <= 2n and condition <= n + 1 (n <= 8) get
// 1e-12, well above the few hundred ulps by which summation orders may differ.

#include "diff_print.h"

#define N 7
#define S 8   // dPAD(N)

// The n-vector of integers v, as dReals (exact: all are below 2^32).
static void print_ulongs(const char *name, const unsigned long *v, int n)
{
    dReal x[32];
    for (int i = 0; i < n; i++) x[i] = (dReal)v[i];
    diff_values(name, 0, x, n);
}

static void generator(void)
{
    unsigned long raw[12];
    dRandSetSeed(0);
    for (int i = 0; i < 12; i++) raw[i] = dRand();
    print_ulongs("rand_from_seed_0", raw, 12);
    diff_value("seed_after_12", 0, (double)dRandGetSeed());
    dRandSetSeed(123456789);
    for (int i = 0; i < 4; i++) raw[i] = dRand();
    print_ulongs("rand_from_seed_123456789", raw, 4);
    dRandSetSeed(987654321);
    diff_value("test_rand", 0, dTestRand());
    diff_value("seed_kept_by_test_rand", 0, (double)dRandGetSeed());
}

static void rand_ints(void)
{
    static const int ns[] = {1, 2, 3, 4, 5, 10, 16, 17, 100, 256, 257, 1000,
                             65536, 65537, 1000000, 2147483647};
    char name[64];
    dRandSetSeed(2024);
    for (size_t t = 0; t < sizeof ns / sizeof ns[0]; t++) {
        dReal v[24];
        for (int i = 0; i < 24; i++) v[i] = (dReal)dRandInt(ns[t]);
        snprintf(name, sizeof name, "rand_int_%d", ns[t]);
        diff_values(name, 0, v, 24);
    }
}

static void rand_reals(void)
{
    dReal v[16], M[5 * 8];
    dRandSetSeed(31337);
    for (int i = 0; i < 16; i++) v[i] = dRandReal();
    diff_values("rand_real", 1e-16, v, 16);
    dMakeRandomVector(v, 9, REAL(2.5));
    diff_values("make_random_vector", 3e-15, v, 9);
    dMakeRandomMatrix(M, 5, 7, REAL(4.0));   // only the 7 used columns of each row
    for (int i = 0; i < 5; i++) diff_values("make_random_matrix_row", 5e-15, M + i * 8, 7);
}

static void basics(void)
{
    dReal a[N], b[N], A[N * S], B[N * S];
    dRandSetSeed(5);
    dMakeRandomVector(a, N, 1);
    dMakeRandomVector(b, N, 1);
    diff_value("dot", 1e-15, dDot(a, b, N));
    dScaleVector(a, b, N);
    diff_values("scale_vector", 1e-16, a, N);
    dMakeRandomMatrix(A, N, N, 1);
    dMakeRandomMatrix(B, N, N, 1);
    diff_value("max_difference", 1e-16, dMaxDifference(A, B, N, N));
    diff_value("max_difference_lower", 1e-16, dMaxDifferenceLowerTriangle(A, B, N));
    dClearUpperTriangle(A, N);
    for (int i = 0; i < N; i++) diff_values("clear_upper_triangle_row", 0, A + i * S, N);
}

static void products(void)
{
    // B 4 x 3 (skip 4), C 3 x 5 (skip 8); transposed copies for the other two forms.
    dReal B[4 * 4], C[3 * 8], Bt[3 * 4], Ct[5 * 4], A[4 * 8];
    dRandSetSeed(77);
    dMakeRandomMatrix(B, 4, 3, 2);
    dMakeRandomMatrix(C, 3, 5, 3);
    dMakeRandomMatrix(Bt, 3, 4, 2);
    dMakeRandomMatrix(Ct, 5, 3, 3);
    dMultiply0(A, B, C, 4, 3, 5);
    for (int i = 0; i < 4; i++) diff_values("multiply0_row", 1e-14, A + i * 8, 5);
    dMultiply1(A, Bt, C, 4, 3, 5);
    for (int i = 0; i < 4; i++) diff_values("multiply1_row", 1e-14, A + i * 8, 5);
    dMultiply2(A, B, Ct, 4, 3, 5);
    for (int i = 0; i < 4; i++) diff_values("multiply2_row", 1e-14, A + i * 8, 5);
}

// A = B B^T + n I from the generator: symmetric positive definite (skip dPAD(n)).
static void make_spd(dReal *A, int n)
{
    dReal B[8 * 8];   // n <= 8
    dMakeRandomMatrix(B, n, n, 1);
    dMultiply2(A, B, B, n, n, n);
    for (int i = 0; i < n; i++) A[i * dPAD(n) + i] += n;
}

// Row i of the lower triangle (diagonal included if diag) of L with skip s.
static void print_lower(const char *name, const dReal *L, int n, int s, int diag)
{
    for (int i = diag ? 0 : 1; i < n; i++) diff_values(name, 1e-12, L + i * s, diag ? i + 1 : i);
}

static void cholesky(void)
{
    dReal A[N * S], L[N * S], Ainv[N * S], b[N];
    dRandSetSeed(123);
    make_spd(A, N);
    memcpy(L, A, sizeof L);
    diff_value("factor_cholesky_ok", 0, dFactorCholesky(L, N));
    print_lower("cholesky_row", L, N, S, 1);
    dMakeRandomVector(b, N, 1);
    dSolveCholesky(L, b, N);
    diff_values("solve_cholesky", 1e-12, b, N);
    diff_value("invert_pd_ok", 0, dInvertPDMatrix(A, Ainv, N));
    for (int i = 0; i < N; i++) diff_values("invert_pd_row", 1e-12, Ainv + i * S, N);
    diff_value("is_pd", 0, dIsPositiveDefinite(A, N));
    A[3 * S + 3] = -1;
    diff_value("is_pd_negative_diagonal", 0, dIsPositiveDefinite(A, N));
    const dReal indefinite[8] = {1, 2, 0, 0, 2, 1, 0, 0};
    diff_value("is_pd_indefinite", 0, dIsPositiveDefinite(indefinite, 2));
}

static void ldlt(void)
{
    dReal A[N * S], L[N * S], d[N], b[N], x[N];
    dRandSetSeed(456);
    make_spd(A, N);
    memcpy(L, A, sizeof L);
    dFactorLDLT(L, d, N, S);
    print_lower("ldlt_row", L, N, S, 0);
    diff_values("ldlt_d", 1e-13, d, N);
    dMakeRandomVector(b, N, 1);
    memcpy(x, b, sizeof x);
    dSolveL1(L, x, N, S);
    diff_values("solve_l1", 1e-12, x, N);
    memcpy(x, b, sizeof x);
    dSolveL1T(L, x, N, S);
    diff_values("solve_l1t", 1e-12, x, N);
    memcpy(x, b, sizeof x);
    dSolveLDLT(L, d, x, N, S);
    diff_values("solve_ldlt", 1e-12, x, N);
}

// dLDLTAddTL: the reference leaves column 0 of L and d[0] as they were, so only the
// trailing block (rows and columns 1..n-1) is compared.
static void add_tl(void)
{
    dReal A[N * S], L[N * S], d[N], a[N];
    dRandSetSeed(789);
    make_spd(A, N);
    memcpy(L, A, sizeof L);
    dFactorLDLT(L, d, N, S);
    dMakeRandomVector(a, N, REAL(0.8));
    dLDLTAddTL(L, d, a, N, S);
    for (int i = 2; i < N; i++) diff_values("add_tl_row", 1e-12, L + i * S + 1, i - 1);
    diff_values("add_tl_d", 1e-13, d + 1, N - 1);
}

// dLDLTRemove of every row r of a 6 x 6 matrix picked from an 8 x 8 one through p.
static void ldlt_remove(void)
{
    enum { N1 = 8, N2 = 6, SKIP = 8 };
    static const int p[N2] = {6, 1, 4, 0, 7, 3};
    dReal A[N1 * 8], L[N2 * SKIP], d[N2], *rows[N1];
    dRandSetSeed(1011);
    make_spd(A, N1);
    for (int i = 0; i < N1; i++) rows[i] = A + i * 8;
    for (int r = 0; r < N2; r++) {
        for (int i = 0; i < N2; i++)
            for (int j = 0; j < N2; j++) L[i * SKIP + j] = A[p[i] * 8 + p[j]];
        dFactorLDLT(L, d, N2, SKIP);
        dLDLTRemove(rows, p, L, d, N1, N2, r, SKIP);
        char name[32];
        snprintf(name, sizeof name, "ldlt_remove_%d_row", r);
        print_lower(name, L, N2 - 1, SKIP, 0);
        snprintf(name, sizeof name, "ldlt_remove_%d_d", r);
        diff_values(name, 1e-13, d, N2 - 1);
    }
}

static void remove_row_col(void)
{
    dReal A[5 * 6];
    for (int r = 0; r < 5; r++) {
        for (int i = 0; i < 30; i++) A[i] = (dReal)i;
        dRemoveRowCol(A, 5, 6, r);
        diff_values("remove_row_col", 0, A, 30);
    }
}

int main(void)
{
    generator();
    rand_ints();
    rand_reals();
    basics();
    products();
    cholesky();
    ldlt();
    add_tl();
    ldlt_remove();
    remove_row_col();
    return 0;
}
