// SPDX-License-Identifier: BSD-3-Clause
//
// matrix.c -- dense row-major matrix functions (guide 9.3): products, the
// Cholesky and LDL^T factorisations with their solvers, and the LDL^T updates
// (add a top-left cross, remove a row and column) that an LCP solver needs.
//
// Conventions: a p x q matrix without an explicit nskip has row skip dPAD(q);
// an LDL^T factorisation keeps the unit lower triangular L in the strict lower
// triangle (its diagonal of ones is not stored) and d[i] = 1 / D(i).

#include "dx_check.h"

#include <ode/matrix.h>
#include <ode/memory.h>

// Sum of a[k] * b[k] for k < n (no argument checks: for use inside this file).
static dReal dot(const dReal *a, const dReal *b, int n)
{
    dReal sum = 0;
    for (int k = 0; k < n; k++) sum += a[k] * b[k];
    return sum;
}

// Scratch of n dReals through the library's allocator (never on the stack).
static dReal *scratch(int n) { return dAlloc(sizeof(dReal) * (size_t)(n > 0 ? n : 1)); }
static void scratch_free(dReal *p, int n) { dFree(p, sizeof(dReal) * (size_t)(n > 0 ? n : 1)); }

void dSetZero(dReal *a, int n)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(a != NULL || n == 0, return, "a is NULL");
    for (int i = 0; i < n; i++) a[i] = 0;
}

void dSetValue(dReal *a, int n, dReal value)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(a != NULL || n == 0, return, "a is NULL");
    for (int i = 0; i < n; i++) a[i] = value;
}

dReal dDot(const dReal *a, const dReal *b, int n)
{
    DX_CHECK_ARG(n >= 0, return 0, "n must be >= 0, got %d", n);
    DX_CHECK_ARG((a != NULL && b != NULL) || n == 0, return 0, "%s is NULL", a ? "b" : "a");
    return dot(a, b, n);
}

// Argument checks shared by the three products, reported under the caller's name.
static int product_args_ok(const char *fn, const dReal *A, const dReal *B, const dReal *C,
                           int p, int q, int r)
{
    if (p < 0 || q < 0 || r < 0) {
        dxReportBadArgument(fn, "sizes p, q, r must be >= 0, got %d, %d, %d", p, q, r);
        return 0;
    }
    if (!A || !B || !C) {
        dxReportBadArgument(fn, "%s is NULL", !A ? "A" : !B ? "B" : "C");
        return 0;
    }
    return 1;
}

void dMultiply0(dReal *A, const dReal *B, const dReal *C, int p, int q, int r)
{
    if (!product_args_ok(__func__, A, B, C, p, q, r)) return;
    const int qs = dPAD(q), rs = dPAD(r);
    for (int i = 0; i < p; i++) {
        for (int j = 0; j < r; j++) {
            dReal sum = 0;
            for (int k = 0; k < q; k++) sum += B[i * qs + k] * C[k * rs + j];
            A[i * rs + j] = sum;
        }
    }
}

void dMultiply1(dReal *A, const dReal *B, const dReal *C, int p, int q, int r)
{
    if (!product_args_ok(__func__, A, B, C, p, q, r)) return;
    const int ps = dPAD(p), rs = dPAD(r);   // B is stored q x p
    for (int i = 0; i < p; i++) {
        for (int j = 0; j < r; j++) {
            dReal sum = 0;
            for (int k = 0; k < q; k++) sum += B[k * ps + i] * C[k * rs + j];
            A[i * rs + j] = sum;
        }
    }
}

void dMultiply2(dReal *A, const dReal *B, const dReal *C, int p, int q, int r)
{
    if (!product_args_ok(__func__, A, B, C, p, q, r)) return;
    const int qs = dPAD(q), rs = dPAD(r);   // C is stored r x q
    for (int i = 0; i < p; i++) {
        for (int j = 0; j < r; j++) A[i * rs + j] = dot(B + i * qs, C + j * qs, q);
    }
}

// Cholesky-Banachiewicz, row by row: L(i,j) = (A(i,j) - L(i,:j).L(j,:j)) / L(j,j) and
// L(i,i) = sqrt(A(i,i) - |L(i,:i)|^2); a pivot that is not > 0 means A is not PD.
int dFactorCholesky(dReal *A, int n)
{
    DX_CHECK_ARG(n >= 0, return 0, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(A != NULL || n == 0, return 0, "A is NULL");
    const int s = dPAD(n);
    for (int i = 0; i < n; i++) {
        dReal *Li = A + i * s;
        for (int j = 0; j < i; j++) {
            const dReal *Lj = A + j * s;
            Li[j] = (Li[j] - dot(Li, Lj, j)) / Lj[j];
        }
        const dReal pivot = Li[i] - dot(Li, Li, i);
        if (!(pivot > 0)) return 0;   // also catches NaN
        Li[i] = dSqrt(pivot);
    }
    return 1;
}

// Forward substitution L y = b, then back substitution L^T x = y (by columns of L^T,
// i.e. rows of L, so that the inner loop runs along memory).
void dSolveCholesky(const dReal *L, dReal *b, int n)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG((L != NULL && b != NULL) || n == 0, return, "%s is NULL", L ? "b" : "L");
    const int s = dPAD(n);
    for (int i = 0; i < n; i++) b[i] = (b[i] - dot(L + i * s, b, i)) / L[i * s + i];
    for (int i = n - 1; i >= 0; i--) {
        const dReal *Li = L + i * s;
        b[i] /= Li[i];
        for (int k = 0; k < i; k++) b[k] -= Li[k] * b[i];
    }
}

// Copy of the n x n matrix A (skip dPAD(n)) into dAlloc'ed scratch, factored by Cholesky.
// Returns the scratch (size n * dPAD(n) + extra) or NULL, having freed it, if A is not PD.
static dReal *cholesky_copy(const dReal *A, int n, int extra)
{
    const int size = n * dPAD(n);
    dReal *L = scratch(size + extra);
    memcpy(L, A, sizeof(dReal) * (size_t)size);
    if (dFactorCholesky(L, n)) return L;
    scratch_free(L, size + extra);
    return NULL;
}

// Column c of A^-1 solves A x = e_c; every padding element of Ainv is set to 0.
int dInvertPDMatrix(const dReal *A, dReal *Ainv, int n)
{
    DX_CHECK_ARG(n >= 0, return 0, "n must be >= 0, got %d", n);
    DX_CHECK_ARG((A != NULL && Ainv != NULL) || n == 0, return 0, "%s is NULL",
                 A ? "Ainv" : "A");
    if (n == 0) return 1;
    const int s = dPAD(n), size = n * s;
    dReal *L = cholesky_copy(A, n, n);
    if (!L) return 0;
    dReal *x = L + size;
    dSetZero(Ainv, size);
    for (int c = 0; c < n; c++) {
        dSetZero(x, n);
        x[c] = 1;
        dSolveCholesky(L, x, n);
        for (int i = 0; i < n; i++) Ainv[i * s + c] = x[i];
    }
    scratch_free(L, size + n);
    return 1;
}

int dIsPositiveDefinite(const dReal *A, int n)
{
    DX_CHECK_ARG(n >= 0, return 0, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(A != NULL || n == 0, return 0, "A is NULL");
    if (n == 0) return 1;
    dReal *L = cholesky_copy(A, n, 0);
    if (!L) return 0;
    scratch_free(L, n * dPAD(n));
    return 1;
}

// Checks shared by the functions taking an n x n matrix with row skip nskip.
static int square_args_ok(const char *fn, const void *M, const char *mname, const void *v,
                          const char *vname, int n, int nskip)
{
    if (n < 0) {
        dxReportBadArgument(fn, "n must be >= 0, got %d", n);
        return 0;
    }
    if (nskip < n) {
        dxReportBadArgument(fn, "nskip must be >= n, got nskip %d for n %d", nskip, n);
        return 0;
    }
    if (n > 0 && (!M || !v)) {
        dxReportBadArgument(fn, "%s is NULL", !M ? mname : vname);
        return 0;
    }
    return 1;
}

// Row by row. Row i first receives Z(i,j) = L(i,j) D(j) for j < i, by forward substitution
// on A(i,j) = Z(i,j) + sum_{k<j} Z(i,k) L(j,k); then D(i) = A(i,i) - sum_j Z(i,j) L(i,j)
// and L(i,j) = Z(i,j) / D(j). Only the lower triangle of A is read; the diagonal and the
// strict upper triangle are left as they were.
void dFactorLDLT(dReal *A, dReal *d, int n, int nskip)
{
    if (!square_args_ok(__func__, A, "A", d, "d", n, nskip)) return;
    for (int i = 0; i < n; i++) {
        dReal *Ai = A + i * nskip;
        for (int j = 0; j < i; j++) Ai[j] -= dot(Ai, A + j * nskip, j);
        dReal Dii = Ai[i];
        for (int j = 0; j < i; j++) {
            const dReal z = Ai[j];
            Ai[j] = z * d[j];
            Dii -= z * Ai[j];
        }
        d[i] = dRecip(Dii);
    }
}

void dSolveL1(const dReal *L, dReal *b, int n, int nskip)
{
    if (!square_args_ok(__func__, L, "L", b, "b", n, nskip)) return;
    for (int i = 0; i < n; i++) b[i] -= dot(L + i * nskip, b, i);
}

// Back substitution on L^T, sweeping the columns of L^T (rows of L) from the last.
void dSolveL1T(const dReal *L, dReal *b, int n, int nskip)
{
    if (!square_args_ok(__func__, L, "L", b, "b", n, nskip)) return;
    for (int i = n - 1; i > 0; i--) {
        const dReal *Li = L + i * nskip;
        for (int k = 0; k < i; k++) b[k] -= Li[k] * b[i];
    }
}

void dScaleVector(dReal *a, const dReal *d, int n)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG((a != NULL && d != NULL) || n == 0, return, "%s is NULL", a ? "d" : "a");
    for (int i = 0; i < n; i++) a[i] *= d[i];
}

// The deprecated name of dScaleVector.
void dVectorScale(dReal *a, const dReal *d, int n) { dScaleVector(a, d, n); }

// L D L^T x = b: solve L y = b, then D z = y (d holds 1/D), then L^T x = z.
void dSolveLDLT(const dReal *L, const dReal *d, dReal *b, int n, int nskip)
{
    if (!square_args_ok(__func__, L, "L", b, "b", n, nskip)) return;
    DX_CHECK_ARG(d != NULL || n == 0, return, "d is NULL");
    dSolveL1(L, b, n, nskip);
    dScaleVector(b, d, n);
    dSolveL1T(L, b, n, nskip);
}

// Rank-one update L D L^T + sigma w w^T -> L' D' L'^T in place (d = 1/D), consuming w
// (Gill, Golub, Murray & Saunders 1974, "method C1"). Step j eliminates w[j] = (L^-1 w)[j]:
// D'(j) = D(j) + sigma w_j^2, the rest of w is reduced by w_j L(:,j), column j of L gains
// beta times that reduced w with beta = sigma w_j / D'(j), and sigma shrinks by D(j)/D'(j).
// sigma < 0 is a downdate; the result must stay positive definite for it to make sense.
static void ldlt_rank_one(dReal *L, dReal *d, dReal *w, dReal sigma, int n, int nskip)
{
    for (int j = 0; j < n; j++) {
        const dReal wj = w[j];
        if (wj == 0) continue;   // this step would change nothing
        const dReal Dj = dRecip(d[j]), Dnew = Dj + sigma * wj * wj;
        const dReal beta = sigma * wj / Dnew;
        sigma *= Dj / Dnew;
        d[j] = dRecip(Dnew);
        for (int i = j + 1; i < n; i++) {
            dReal *Lij = L + i * nskip + j;
            w[i] -= wj * *Lij;
            *Lij += beta * w[i];
        }
    }
}

// T = [a0 c^T; c 0] with c = a[1..n-1] is written as u u^T - v v^T, u = p e0 + q c and
// v = r e0 + q c: the c c^T terms cancel, the cross terms need q (p - r) = 1 and the corner
// p^2 - r^2 = a0, so p, r = (a0 q +- 1/q) / 2. Taking q = 1/sqrt(max|a|) keeps u and v of
// the size of sqrt|T|, so the update and the downdate add no error beyond T's own scale.
// Column 0 of L and d[0] are updated too, so L, d is the complete factorisation of A + T.
void dLDLTAddTL(dReal *L, dReal *d, const dReal *a, int n, int nskip)
{
    if (!square_args_ok(__func__, L, "L", d, "d", n, nskip)) return;
    DX_CHECK_ARG(a != NULL || n == 0, return, "a is NULL");
    dReal amax = 0;
    for (int i = 0; i < n; i++) amax = dMax(amax, dFabs(a[i]));
    if (amax == 0) return;   // T = 0 (also covers n == 0)
    const dReal root = dSqrt(amax), q = dRecip(root);
    dReal *w = scratch(n);
    for (int i = 1; i < n; i++) w[i] = q * a[i];
    w[0] = (a[0] * q + root) / 2;
    ldlt_rank_one(L, d, w, 1, n, nskip);
    for (int i = 1; i < n; i++) w[i] = q * a[i];
    w[0] = (a[0] * q - root) / 2;
    ldlt_rank_one(L, d, w, -1, n, nskip);
    scratch_free(w, n);
}

// Write M = [M11 . .; m21 m22 .; M31 m32 M33] with r the middle row, and L, D alike. Then
// M33 = L31 D1 L31^T + D(r) l32 l32^T + L33 D3 L33^T, while the matrix without row and
// column r keeps L11, D1, L31 and needs L33' D3' L33'^T = L33 D3 L33^T + D(r) l32 l32^T:
// a positive rank-one update of the trailing block (for r = 0 the leading block is empty).
// So L and d alone determine the result; A and p, which describe the same matrix, are only
// validated. Removing the last row just drops it.
void dLDLTRemove(dReal **A, const int *p, dReal *L, dReal *d, int n1, int n2, int r, int nskip)
{
    DX_CHECK_ARG(A != NULL && p != NULL, return, "%s is NULL", A ? "p" : "A");
    DX_CHECK_ARG(L != NULL && d != NULL, return, "%s is NULL", L ? "d" : "L");
    DX_CHECK_ARG(n2 >= 1 && n2 <= n1, return, "n2 must be in 1..n1 (%d), got %d", n1, n2);
    DX_CHECK_ARG(nskip >= n2, return, "nskip must be >= n2, got nskip %d for n2 %d", nskip, n2);
    DX_CHECK_ARG(r >= 0 && r < n2, return, "r must be in 0..%d, got %d", n2 - 1, r);
    if (r == n2 - 1) return;
    const int m = n2 - r - 1;
    dReal *w = scratch(m);
    for (int i = 0; i < m; i++) w[i] = L[(r + 1 + i) * nskip + r];
    ldlt_rank_one(L + (r + 1) * nskip + r + 1, d + r + 1, w, dRecip(d[r]), m, nskip);
    scratch_free(w, m);
    dRemoveRowCol(L, n2, nskip, r);
    for (int i = r; i < n2 - 1; i++) d[i] = d[i + 1];
}

// Element (i,j) of the result comes from (i or i+1, j or j+1), never from an earlier position
// in row-major order, so one forward pass moves everything in place. The last row and column
// are left untouched.
void dRemoveRowCol(dReal *A, int n, int nskip, int r)
{
    DX_CHECK_ARG(A != NULL, return, "A is NULL");
    DX_CHECK_ARG(n >= 1 && nskip >= n, return, "need 1 <= n <= nskip, got n %d nskip %d", n,
                 nskip);
    DX_CHECK_ARG(r >= 0 && r < n, return, "r must be in 0..%d, got %d", n - 1, r);
    for (int i = 0; i < n - 1; i++) {
        const dReal *src = A + (i < r ? i : i + 1) * nskip;
        dReal *dst = A + i * nskip;
        for (int j = 0; j < n - 1; j++) dst[j] = src[j < r ? j : j + 1];
    }
}
