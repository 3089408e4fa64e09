// SPDX-License-Identifier: BSD-3-Clause
//
// lcp_internal.h -- what the parts of the LCP solver share: sparse kernels, patterns,
// orderings and the bordered L D L^T factor (lcp_sparse.c), and the pivoting on the bounded
// rows (lcp_pivot.c); lcp.c puts them together (see there for the algorithm).

#ifndef DX_LCP_INTERNAL_H
#define DX_LCP_INTERNAL_H

#include "lcp.h"

#include <float.h>

#ifdef dSINGLE
#define DX_LCP_EPS FLT_EPSILON
#define DX_LCP_DEP_TOL REAL(3.5e-4)   // about sqrt(FLT_EPSILON)
#else
#define DX_LCP_EPS DBL_EPSILON
#define DX_LCP_DEP_TOL REAL(1.5e-8)   // about sqrt(DBL_EPSILON)
#endif

// A pivot below DX_LCP_PIVOT_TOL * A[j][j] means row j depends on the rows already factored.
// The computed pivot of an exactly dependent row is rounding noise, typically some epsilon
// times A[j][j] (more when the factored block is ill-conditioned). A CFM of 1e-10 on a unit
// diagonal stays well above the threshold in double precision; in single precision it is
// below rounding.
#define DX_LCP_PIVOT_TOL ((dReal)(256 * DX_LCP_EPS))

// ---- kernels and patterns (lcp_sparse.c) ----

// Dot product with four partial sums: the four lanes let the compiler vectorise the loop
// body (at -O2 GCC only vectorises such straight-line groups, not loops needing an epilogue).
static inline dReal dxLcpDot(const dReal *restrict a, const dReal *restrict b, int n)
{
    dReal s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    int k = 0;
    for (; k + 4 <= n; k += 4) {
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * b[k + 3];
    }
    for (; k < n; k++) s0 += a[k] * b[k];
    return (s0 + s1) + (s2 + s3);
}

// The same as dxLcpDot (the same products summed in the same lanes and order: the same
// result) with b[n - 1] given as last (n >= 1). A solve passes the value it has just
// computed in a register, so that only the final few operations wait for it.
static inline dReal dxLcpDotLast(const dReal *restrict a, const dReal *restrict b, int n,
                                 dReal last)
{
    dReal s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    int k = 0, whole = n % 4 == 0 ? n - 4 : n & ~3;   // the groups without the last entry
    for (; k < whole; k += 4) {
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * b[k + 3];
    }
    if (n % 4 == 0) {   // the last entry closes a group of four, in lane 3
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * last;
    } else {            // the last entry closes the tail, in lane 0
        for (; k < n - 1; k++) s0 += a[k] * b[k];
        s0 += a[n - 1] * last;
    }
    return (s0 + s1) + (s2 + s3);
}

// a . b, and in *size the sum of |a[k] b[k]| (the scale of the terms, for tolerances).
static inline dReal dxLcpDotSize(const dReal *restrict a, const dReal *restrict b, int n,
                                 dReal *size)
{
    dReal s0 = 0, s1 = 0, a0 = 0, a1 = 0;
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        dReal t0 = a[k] * b[k], t1 = a[k + 1] * b[k + 1];
        s0 += t0;
        s1 += t1;
        a0 += dFabs(t0);
        a1 += dFabs(t1);
    }
    for (; k < n; k++) {
        dReal t0 = a[k] * b[k];
        s0 += t0;
        a0 += dFabs(t0);
    }
    *size = a0 + a1;
    return s0 + s1;
}

// The nonzero columns of each row of a symmetric matrix, as in dxLCPMatrix.
typedef struct dxLcpPattern {
    const int *start;
    const int *cols;
} dxLcpPattern;

static inline dxLcpPattern dxLcpPatternOfMatrix(const dxLCPMatrix *A)
{
    dxLcpPattern pt = { A->start, A->cols };
    return pt;
}

// Building a pattern (and its values, allocated with_values) from its entries (i, j),
// i >= j, each given once: first count every entry, then allocate, then add every entry in
// the same way (dxLcpPatternAddValue with values).
typedef struct dxLcpPatternBuilder {
    int n;
    int *start, *cols, *fill;
    dReal *vals;
} dxLcpPatternBuilder;

void dxLcpPatternBegin(dxLcpPatternBuilder *pb, dxArena *arena, int n);
void dxLcpPatternAllocate(dxLcpPatternBuilder *pb, dxArena *arena, int with_values);

static inline void dxLcpPatternCount(dxLcpPatternBuilder *pb, int i, int j)
{
    pb->fill[i]++;
    if (j != i) pb->fill[j]++;
}

static inline void dxLcpPatternAdd(dxLcpPatternBuilder *pb, int i, int j)
{
    pb->cols[pb->fill[i]++] = j;
    if (j != i) pb->cols[pb->fill[j]++] = i;
}

static inline void dxLcpPatternAddValue(dxLcpPatternBuilder *pb, int i, int j, dReal v)
{
    pb->vals[pb->fill[i]] = v;
    pb->cols[pb->fill[i]++] = j;
    if (j == i) return;
    pb->vals[pb->fill[j]] = v;
    pb->cols[pb->fill[j]++] = i;
}

// The nonzeros of the symmetric n x n matrix A (row skip ld), from its lower triangle.
dxLCPMatrix dxLcpSparseOf(dxArena *arena, const dReal *A, ptrdiff_t ld, int n);

// Reverse breadth-first order of the rows nodes[0..count) on the graph of the pattern
// restricted to them (in[i] >= 0 for the rows in nodes, -1 for the others; all -1 on return),
// in place: a part at a time, from its first row in the given order (Cuthill-McKee without
// its degree sort). Rows that interact end up close together, and a factor in this order has its
// nonzeros near the diagonal. Returns the number of connected parts; part (if not NULL)
// receives the part of each place in the new order, numbered along it (each part is a run
// of places).
int dxLcpBfsOrder(dxArena *arena, const dxLcpPattern *pt, int *nodes, int count, int *in,
                  int *part);

// ---- L D L^T of a principal block, grown by bordering (lcp_sparse.c) ----

// The factored block is A[C][C] with C = cidx[0..m) in the order the rows joined. Row k of L
// holds columns [lstart[k], k) at L + k * ld; the entries before lstart[k] are zero, the
// diagonal is 1.
typedef struct dxLcpFactor {
    int m;
    ptrdiff_t ld;
    dReal *L, *d, *dinv;
    int *cidx, *lstart;
} dxLcpFactor;

void dxLcpFactorInit(dxLcpFactor *f, dxArena *arena, int n);

static inline dReal *dxLcpRow(const dxLcpFactor *f, int k) { return f->L + k * f->ld; }

// Solve L v = v in place, given v[k] == 0 for k < first. Returns e with v[k] == 0 for k >= e.
int dxLcpSolveL(const dxLcpFactor *f, dReal *v, int first);
// Solve L^T v = v in place, given v[k] == 0 for k >= end.
void dxLcpSolveLT(const dxLcpFactor *f, dReal *v, int end);

// The border of a row a with a[C] in y (m entries, zero before `first`): y = L^-1 a[C] and
// z = D^-1 y, both nonzero only in [first, *end); z is not written outside it. Returns
// diag - y.z, the pivot the row would get on joining (zero if it depends on C).
dReal dxLcpBorder(const dxLcpFactor *f, dReal diag, dReal *y, dReal *z, int first, int *end);

// Append row j with the border z (nonzero in [first, end)) and pivot `pivot`.
void dxLcpAppend(dxLcpFactor *f, int j, dReal pivot, const dReal *z, int first, int end);

// ---- pivoting on the bounded rows (lcp_pivot.c) ----

typedef struct dxLcpPivot {
    int n;                 // rows of the pivoted problem
    ptrdiff_t lda;         // row skip of A
    const dReal *A, *b;    // the pivoted problem and its right-hand side
    dxLcpPattern pa;       // the nonzeros of A; pa.start NULL: A is dense
    const dReal *diag;     // per row: the diagonal it had before elimination (pivot tolerance)
    const dReal *base;     // per row: scale of b before elimination, for tolerances
    dReal *x, *w, *lo, *hi;
    signed char *state;    // state of each row (see lcp_pivot.c)
    int *first, *end;      // nonzero extent [first, end) of each row of A
    int *held, nheld;      // the rows held at a bound or at w == 0, not in C
    int *hpos;             // place of each row in held, -1 if not there

    dxLcpFactor f;         // A[C][C], C the clamped rows
    int *cpos;             // position of each row in f.cidx, -1 if not in C

    dReal *y, *z;          // the border of row fwd_row: L y = A[C][j], z = D^-1 y
    int yfirst, yend;      // z is zero outside [yfirst, yend); y is kept all zero
    int fwd_row;           // the row y and z belong to, while fwd_version == version
    unsigned fwd_version;
    dReal fwd_pivot;
    dReal *u;              // the direction: x[cidx[k]] moves by t * u[k]
    dReal *dw;             // w[j] moves by t * dw[j] for the held rows
    dReal *dxf;            // the direction scattered to full length (zero between uses)
    dReal *p, *beta;       // rank-one update scratch
    unsigned *stamp;       // stamp[j] == version: j was found dependent on the current C
    unsigned version;      // changes whenever C changes
} dxLcpPivot;

// Scratch for pivoting on an n-row problem whose A, lda, pa, b, diag, base, x, lo and hi
// are set; x holds the start values. Every row starts unprocessed.
void dxLcpPivotSetup(dxLcpPivot *s, dxArena *arena, int n);
// Forget every row processed so far (C empty, nothing held); x keeps its values.
void dxLcpPivotRestart(dxLcpPivot *s);
// Solve for row i, the np-th row processed since the setup or restart, keeping the rows
// processed before it solved. Returns 0 if it hit the pivot limit.
int dxLcpPivotDrive(dxLcpPivot *s, int i, int np);
// Whether row i was processed since the setup or restart.
int dxLcpPivotProcessed(const dxLcpPivot *s, int i);

#endif
