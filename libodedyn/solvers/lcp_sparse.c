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

// y = (y - a x) - b z: two axpy_sub in one pass, the same operations in the same order.
static void axpy2_sub(dReal *restrict y, const dReal *restrict x, dReal a,
                      const dReal *restrict z, dReal b, int n)
{
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        y[k] = (y[k] - a * x[k]) - b * z[k];
        y[k + 1] = (y[k + 1] - a * x[k + 1]) - b * z[k + 1];
    }
    for (; k < n; k++) y[k] = (y[k] - a * x[k]) - b * z[k];
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
    dReal prev = 0;   // v[k - 1] as just computed, while e == k
    for (int k = first; k < f->m; k++) {
        int st = f->lstart[k] > first ? f->lstart[k] : first;
        dReal vk = v[k];
        if (st < e) {
            const dReal *l = dxLcpRow(f, k) + st;
            vk -= e == k ? dxLcpDotLast(l, v + st, e - st, prev) : dxLcpDot(l, v + st, e - st);
            v[k] = vk;
        }
        if (vk != 0) e = k + 1;
        prev = vk;
    }
    return e;
}

// v[j] -= a L[k][j] for j in [from, to) and then, where both apply, v[j] -= b L[k2][j] for j
// in [from2, to): two columns of L^T in one pass over v (a column with a zero multiplier
// or nothing in the range is left out: from == to).
static void sub_columns(const dxLcpFactor *f, dReal *v, int k, dReal a, int from, int k2,
                        dReal b, int from2, int to)
{
    const dReal *l = dxLcpRow(f, k), *l2 = dxLcpRow(f, k2);
    if (from >= to) {
        if (from2 < to) axpy_sub(v + from2, l2 + from2, b, to - from2);
        return;
    }
    if (from2 >= to) {
        axpy_sub(v + from, l + from, a, to - from);
        return;
    }
    if (from < from2) axpy_sub(v + from, l + from, a, from2 - from);
    if (from2 < from) axpy_sub(v + from2, l2 + from2, b, from - from2);
    int both = from > from2 ? from : from2;
    axpy2_sub(v + both, l + both, a, l2 + both, b, to - both);
}

// Column-oriented, so that the inner loop runs along rows of L, two columns k and k - 1 at
// a time (one pass over v instead of two). Their two entries k - 1 and k - 2, which the
// next columns need first, are updated apart and carried in registers.
void dxLcpSolveLT(const dxLcpFactor *f, dReal *v, int end)
{
    int k = end - 1;
    dReal vk = end > 0 ? v[end - 1] : 0;
    for (; k > 1; k -= 2) {
        const dReal *l = dxLcpRow(f, k), *l1 = dxLcpRow(f, k - 1);
        int st = f->lstart[k], st1 = f->lstart[k - 1];
        int use = vk != 0 && st < k;   // column k applies, over [st, k)
        dReal v1 = v[k - 1], v2 = v[k - 2];
        if (use) v1 -= vk * l[k - 1];
        int use1 = v1 != 0 && st1 < k - 1;   // column k - 1 applies, over [st1, k - 1)
        if (use && st < k - 1) v2 -= vk * l[k - 2];
        if (use1) v2 -= v1 * l1[k - 2];
        sub_columns(f, v, k, vk, use ? st : k - 2, k - 1, v1, use1 ? st1 : k - 2, k - 2);
        v[k - 1] = v1;
        v[k - 2] = v2;
        vk = v2;
    }
    if (k == 1 && vk != 0 && f->lstart[1] < 1) v[0] -= vk * dxLcpRow(f, 1)[0];
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
