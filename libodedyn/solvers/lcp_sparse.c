// SPDX-License-Identifier: BSD-3-Clause
//
// lcp_sparse.c -- the building blocks of the LCP solver (see lcp_internal.h): sparsity
// patterns, a reverse breadth-first ordering and an L D L^T factor that grows by bordering,
// with each row of L kept within its profile.

#include "lcp_internal.h"

// ---- dense kernels ----

// y -= a x, unrolled like dxLcpDot.
static void axpy_sub(dReal *restrict y, const dReal *restrict x, dReal a, int n)
{
    int k = 0;
    for (; k + 4 <= n; k += 4) {
        y[k] -= a * x[k];
        y[k + 1] -= a * x[k + 1];
        y[k + 2] -= a * x[k + 2];
        y[k + 3] -= a * x[k + 3];
    }
    for (; k < n; k++) y[k] -= a * x[k];
}

// ---- patterns ----

void dxLcpPatternBegin(dxLcpPatternBuilder *pb, dxArena *arena, int n)
{
    pb->n = n;
    pb->start = DX_ARENA_ARRAY(arena, int, n + 1);
    pb->fill = DX_ARENA_ARRAY(arena, int, n + 1);
    pb->cols = NULL;
    pb->vals = NULL;
    for (int i = 0; i <= n; i++) pb->fill[i] = 0;
}

void dxLcpPatternAllocate(dxLcpPatternBuilder *pb, dxArena *arena, int with_values)
{
    pb->start[0] = 0;
    for (int i = 0; i < pb->n; i++) {
        pb->start[i + 1] = pb->start[i] + pb->fill[i];
        pb->fill[i] = pb->start[i];
    }
    pb->cols = DX_ARENA_ARRAY(arena, int, pb->start[pb->n] + 1);
    if (with_values) pb->vals = DX_ARENA_ARRAY(arena, dReal, pb->start[pb->n] + 1);
}

dxLCPMatrix dxLcpSparseOf(dxArena *arena, const dReal *A, ptrdiff_t ld, int n)
{
    dxLcpPatternBuilder pb;
    dxLcpPatternBegin(&pb, arena, n);
    for (int i = 0; i < n; i++) {
        const dReal *a = A + i * ld;
        for (int j = 0; j <= i; j++)
            if (a[j] != 0) dxLcpPatternCount(&pb, i, j);
    }
    dxLcpPatternAllocate(&pb, arena, 1);
    for (int i = 0; i < n; i++) {
        const dReal *a = A + i * ld;
        for (int j = 0; j <= i; j++)
            if (a[j] != 0) dxLcpPatternAddValue(&pb, i, j, a[j]);
    }
    dxLCPMatrix m = { pb.start, pb.cols, pb.vals };
    return m;
}

// ---- ordering ----

int dxLcpBfsOrder(dxArena *arena, const dxLcpPattern *pt, int *nodes, int count, int *in,
                  int *part)
{
    dxArenaMark mark = dxArenaSave(arena);
    int *out = DX_ARENA_ARRAY(arena, int, count), *out_part = DX_ARENA_ARRAY(arena, int, count);
    int head = 0, tail = 0, next_seed = 0, parts = 0;
    while (tail < count) {   // one connected part per seed; a row reached leaves `in`
        while (in[nodes[next_seed]] < 0) next_seed++;
        in[nodes[next_seed]] = -1;
        out_part[tail] = parts;
        out[tail++] = nodes[next_seed];
        while (head < tail) {
            int a = out[head++];
            for (int k = pt->start[a]; k < pt->start[a + 1]; k++) {
                int c = pt->cols[k];
                if (in[c] < 0) continue;
                in[c] = -1;
                out_part[tail] = parts;
                out[tail++] = c;
            }
        }
        parts++;
    }
    for (int k = 0; k < count; k++) nodes[k] = out[count - 1 - k];
    if (part)
        for (int k = 0; k < count; k++) part[k] = parts - 1 - out_part[count - 1 - k];
    dxArenaRestore(arena, mark);
    return parts;
}

// ---- the bordered L D L^T factor ----

void dxLcpFactorInit(dxLcpFactor *f, dxArena *arena, int n)
{
    f->m = 0;
    f->ld = dPAD(n);
    f->L = DX_ARENA_ARRAY(arena, dReal, (size_t)n * (size_t)f->ld);
    f->d = DX_ARENA_ARRAY(arena, dReal, n);
    f->dinv = DX_ARENA_ARRAY(arena, dReal, n);
    f->cidx = DX_ARENA_ARRAY(arena, int, n);
    f->lstart = DX_ARENA_ARRAY(arena, int, n);
}

// Rows of L that start at or after the last nonzero of v so far cannot bring in anything
// new, and the entries of v past it are zero: each dot stops there.
int dxLcpSolveL(const dxLcpFactor *f, dReal *v, int first)
{
    int e = first;
    for (int k = first; k < f->m; k++) {
        int st = f->lstart[k] > first ? f->lstart[k] : first;
        if (st < e) v[k] -= dxLcpDot(dxLcpRow(f, k) + st, v + st, e - st);
        if (v[k] != 0) e = k + 1;
    }
    return e;
}

// Column-oriented, so that the inner loop runs along rows of L.
void dxLcpSolveLT(const dxLcpFactor *f, dReal *v, int end)
{
    for (int k = end - 1; k > 0; k--) {
        int st = f->lstart[k];
        if (v[k] != 0) axpy_sub(v + st, dxLcpRow(f, k) + st, v[k], k - st);
    }
}

dReal dxLcpBorder(const dxLcpFactor *f, dReal diag, dReal *y, dReal *z, int first, int *end)
{
    int e = dxLcpSolveL(f, y, first);
    for (int k = first; k < e; k++) z[k] = y[k] * f->dinv[k];
    *end = e;
    return diag - dxLcpDot(y + first, z + first, e - first);
}

void dxLcpAppend(dxLcpFactor *f, int j, dReal pivot, const dReal *z, int first, int end)
{
    int m = f->m;
    dReal *l = dxLcpRow(f, m);
    for (int k = first; k < end; k++) l[k] = z[k];
    for (int k = end; k < m; k++) l[k] = 0;
    f->lstart[m] = first;
    f->d[m] = pivot;
    f->dinv[m] = 1 / pivot;
    f->cidx[m] = j;
    f->m = m + 1;
}
