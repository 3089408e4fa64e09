// SPDX-License-Identifier: BSD-3-Clause
//
// lcp.h -- the mixed (boxed) linear complementarity solver used by the big-matrix stepper.

#ifndef DX_LCP_H
#define DX_LCP_H

#include <ode/common.h>

#include "arena.h"

// Problems of up to this many rows are solved on A in full, in the order given: elimination,
// reordering and sparsity cannot gain there (dxSolveLCP is then the cheaper entry).
#define DX_LCP_SMALL 16

// A sparse symmetric n x n matrix: row i has the columns cols[start[i] .. start[i + 1]) (in
// any order, each once, the diagonal included) with the values vals at the same places.
typedef struct dxLCPMatrix {
    const int *start;
    const int *cols;
    const dReal *vals;
} dxLCPMatrix;

// Solve the mixed LCP  A x = b + w  for x and w, where A is n x n, symmetric positive
// semi-definite, stored in full with row skip dPAD(n), such that for each i:
//   lo[i] <= x[i] <= hi[i], and  x[i] == lo[i] => w[i] >= 0,  x[i] == hi[i] => w[i] <= 0,
//   lo[i] < x[i] < hi[i] => w[i] == 0.
// A row with lo[i] == hi[i] has x[i] = lo[i] and any w[i]. lo[i] <= hi[i] is required; the
// bounds may be infinite and need not contain 0.
//
// The first nub indices are unbounded (their lo and hi are not read), as is any row with
// lo = -inf, hi = inf and no friction index. If findex[i] >= 0 (findex may be NULL: all -1),
// row i is a friction row: it gets the bounds hi = |hi[i] * x[findex[i]]|, lo = -hi, where
// x[findex[i]] is the normal force of the solution without friction (findex[i] < n must be a
// row that is not itself a friction row). All friction bounds are set before any friction
// row moves load between contacts, so a sliding body feels mu times its whole normal load.
// The normal forces can still change afterwards; the bounds are not revisited.
//
// On input only A, b, lo, hi, nub and findex are read (x and w need not be initialised).
// On return x is the solution and w = A x - b, recomputed from the final x. A and b are not
// modified. lo and hi are modified for friction rows only: they receive the
// bounds that were used, so the conditions above hold with the returned lo and hi.
//
// Time is O(n^3) for dense A and far less for sparse A; scratch (O(n^2) reals at most) comes
// from `arena` and is released before returning: the arena is left at the mark it had on
// entry.
//
// Returns 1 on success: the conditions hold, w[i] being compared with zero to a loose
// tolerance (sqrt(epsilon) times |b[i]| + sum |A[i][j] x[j]|). Returns 0 if they do not, or
// if a drive hit its pivot limit (rounding-induced cycling). With a singular A the former
// means a row that depends on others has a w[i] that no x can bring to zero: the system is
// inconsistent. x is then still finite and within its bounds, never NaN, and the other rows
// satisfy the conditions as far as the pivoting got.
int dxSolveLCP(dxArena *arena, int n, const dReal *A, dReal *x, const dReal *b, dReal *w,
               int nub, dReal *lo, dReal *hi, const int *findex);

// The same with A given by its nonzeros. (dxSolveLCP finds them in the lower triangle of A,
// and reads A in full only for small problems: A must be exactly symmetric.)
int dxSolveLCPSparse(dxArena *arena, int n, const dxLCPMatrix *A, dReal *x, const dReal *b,
                     dReal *w, int nub, dReal *lo, dReal *hi, const int *findex);

#endif
