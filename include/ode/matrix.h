/* SPDX-License-Identifier: BSD-3-Clause */
/* matrix.h -- dense matrix functions (guide 9.3).
 *
 * Matrices are row-major. Unless a function takes an explicit nskip, a
 * p x q matrix is stored with a row skip of dPAD(q). An LDL^T factorisation
 * keeps L (unit lower triangular, diagonal not stored) in the lower triangle
 * and the reciprocals 1/D(i) of the diagonal in d. */
#ifndef ODE_MATRIX_H
#define ODE_MATRIX_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Set the n elements of a to 0 / to value. */
ODE_API void dSetZero(dReal *a, int n);
ODE_API void dSetValue(dReal *a, int n, dReal value);
/** Dot product of two n-vectors. */
ODE_API dReal dDot(const dReal *a, const dReal *b, int n);

/** A (p x r) = B (p x q) * C (q x r). */
ODE_API void dMultiply0(dReal *A, const dReal *B, const dReal *C, int p, int q, int r);
/** A (p x r) = B^T * C with B (q x p) and C (q x r). */
ODE_API void dMultiply1(dReal *A, const dReal *B, const dReal *C, int p, int q, int r);
/** A (p x r) = B * C^T with B (p x q) and C (r x q). */
ODE_API void dMultiply2(dReal *A, const dReal *B, const dReal *C, int p, int q, int r);

/** Cholesky-factor the n x n matrix A in place (A = L L^T, L in the lower
 *  triangle, the upper triangle untouched). Returns 1, or 0 if A is not
 *  positive definite. */
ODE_API int dFactorCholesky(dReal *A, int n);
/** Solve L L^T x = b in place, L from dFactorCholesky. */
ODE_API void dSolveCholesky(const dReal *L, dReal *b, int n);
/** Ainv = A^-1 for a positive definite A; returns 1, or 0 (Ainv untouched) if
 *  A is not positive definite. */
ODE_API int dInvertPDMatrix(const dReal *A, dReal *Ainv, int n);
/** 1 if the symmetric n x n matrix A is positive definite, else 0. */
ODE_API int dIsPositiveDefinite(const dReal *A, int n);

/** Factor the symmetric n x n matrix A (row skip nskip) as L D L^T in place;
 *  d receives 1/D. */
ODE_API void dFactorLDLT(dReal *A, dReal *d, int n, int nskip);
/** Solve L x = b in place (L unit lower triangular). */
ODE_API void dSolveL1(const dReal *L, dReal *b, int n, int nskip);
/** Solve L^T x = b in place. */
ODE_API void dSolveL1T(const dReal *L, dReal *b, int n, int nskip);
/** a[i] *= d[i]. */
ODE_API void dScaleVector(dReal *a, const dReal *d, int n);
ODE_API_DEPRECATED ODE_API void dVectorScale(dReal *a, const dReal *d, int n);
/** Solve L D L^T x = b in place, with d = 1/D from dFactorLDLT. */
ODE_API void dSolveLDLT(const dReal *L, const dReal *d, dReal *b, int n, int nskip);

/** Given the factorisation L D L^T of an n x n matrix A, replace it with the
 *  factorisation of A + the matrix whose first row and first column are a
 *  (a[0] added once, to the top-left element) and which is zero elsewhere. */
ODE_API void dLDLTAddTL(dReal *L, dReal *d, const dReal *a, int n, int nskip);
/** Given L D L^T (n2 x n2, skip nskip) of the permuted matrix whose element
 *  (i,j) is A[p[i]][p[j]] (A: n1 row pointers), make L and d the
 *  factorisation of that matrix with row and column r removed (size n2-1). */
ODE_API void dLDLTRemove(dReal **A, const int *p, dReal *L, dReal *d, int n1, int n2, int r,
                         int nskip);
/** Remove row and column r of the n x n matrix A (row skip nskip), moving the
 *  later rows and columns up and left. */
ODE_API void dRemoveRowCol(dReal *A, int n, int nskip, int r);

#ifdef __cplusplus
}
#endif

#endif
