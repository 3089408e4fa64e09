// SPDX-License-Identifier: BSD-3-Clause
//
// step.c -- dWorldStep: the "big matrix" stepper. Per island, with the constraint rows J,
// right-hand sides c and mixing terms cfm of every joint, it forms A = J M^-1 J^T + cfm/h
// (its nonzeros, from the rows that share a body; in full for a small island) and solves
// the mixed LCP  A lambda = c/h - J (v/h + M^-1 f) + w  (lambda the constraint forces,
// bounded by lo/hi and friction indices) with the solver of lcp.c, then updates velocities
// with the external and constraint forces and integrates positions.

#include "lcp_internal.h"
#include "step_internal.h"

#include <ode/matrix.h>

// For each body, the rows that act on it and on which side (0/1) of the row
// it is: rows_of[start[b] .. start[b+1]-1] in CSR form, side in the low bit.
typedef struct body_rows {
    int *start;
    int *entries;   // row * 2 + side
} body_rows;

static void index_rows_by_body(dxArena *a, const dxIslandRows *r, int nb, body_rows *out)
{
    out->start = DX_ARENA_ARRAY(a, int, nb + 1);
    out->entries = DX_ARENA_ARRAY(a, int, 2 * r->m + 1);
    int *fill = DX_ARENA_ARRAY(a, int, nb + 1);
    for (int b = 0; b <= nb; b++) out->start[b] = 0;
    for (int i = 0; i < r->m; i++) {
        if (r->body0[i] >= 0) out->start[r->body0[i] + 1]++;
        if (r->body1[i] >= 0) out->start[r->body1[i] + 1]++;
    }
    for (int b = 0; b < nb; b++) out->start[b + 1] += out->start[b];
    for (int b = 0; b < nb; b++) fill[b] = out->start[b];
    for (int i = 0; i < r->m; i++) {
        if (r->body0[i] >= 0) out->entries[fill[r->body0[i]]++] = 2 * i;
        if (r->body1[i] >= 0) out->entries[fill[r->body1[i]]++] = 2 * i + 1;
    }
}

// iMJ = M^-1 J^T, row by row, in the same [lin0 ang0 lin1 ang1] layout as J.
static dReal *inverse_mass_times_jt(dxArena *a, const dxIslandRows *r,
                                    const dxIslandBodies *bd)
{
    dReal *iMJ = DX_ARENA_ARRAY(a, dReal, (size_t)r->m * DX_ROW_SKIP);
    for (int i = 0; i < r->m; i++) {
        const dReal *J = r->J + i * DX_ROW_SKIP;
        dReal *out = iMJ + i * DX_ROW_SKIP;
        for (int side = 0; side < 2; side++) {
            int b = side ? r->body1[i] : r->body0[i];
            dReal *o = out + 6 * side;
            if (b < 0) {
                dSetZero(o, 6);
                continue;
            }
            dCopyScaledVector3(o, J + 6 * side, bd->inv_mass[b]);
            dMultiply0_331(o + 3, bd->inv_inertia + 12 * b, J + 6 * side + 3);
        }
    }
    return iMJ;
}

// Row i of J M^-1 J^T up to the diagonal (iMJ = M^-1 J^T): the rows j <= i that share a body
// with it go to `touched` (returned: their count; mark[j] == i), and acc[j] receives the sum
// over the shared bodies of J_i M^-1 J_j^T for that body. The rows of a body are listed in
// increasing order.
static int a_row(const dxIslandRows *r, const body_rows *br, const dReal *iMJ, int i,
                 int *mark, int *touched, dReal *acc)
{
    int count = 0;
    for (int si = 0; si < 2; si++) {
        int b = si ? r->body1[i] : r->body0[i];
        if (b < 0) continue;
        const dReal *Ji = r->J + i * DX_ROW_SKIP + 6 * si;
        for (int p = br->start[b]; p < br->start[b + 1]; p++) {
            int j = br->entries[p] >> 1;
            if (j > i) break;
            if (mark[j] != i) {
                mark[j] = i;
                touched[count++] = j;
                acc[j] = 0;
            }
            const dReal *Mj = iMJ + j * DX_ROW_SKIP + 6 * (br->entries[p] & 1);
            acc[j] += Ji[0] * Mj[0] + Ji[1] * Mj[1] + Ji[2] * Mj[2] + Ji[3] * Mj[3] +
                      Ji[4] * Mj[4] + Ji[5] * Mj[5];
        }
    }
    if (mark[i] != i) {   // a row without bodies still has its diagonal
        mark[i] = i;
        touched[count++] = i;
        acc[i] = 0;
    }
    return count;
}

// A = J M^-1 J^T + cfm/h on the diagonal in full (row skip dPAD(m)), exactly symmetric: for
// a small island.
static dReal *form_A_full(dxArena *a, const dxIslandRows *r, const body_rows *br,
                          const dReal *iMJ, dReal fps)
{
    const int m = r->m, skip = dPAD(m);
    dReal *A = DX_ARENA_ARRAY(a, dReal, (size_t)m * skip);
    int *mark = DX_ARENA_ARRAY(a, int, m), *touched = DX_ARENA_ARRAY(a, int, m);
    dSetZero(A, m * skip);
    for (int i = 0; i < m; i++) mark[i] = -1;
    for (int i = 0; i < m; i++) {
        dReal *Ai = A + (size_t)i * skip;
        a_row(r, br, iMJ, i, mark, touched, Ai);
        Ai[i] += r->cfm[i] * fps;
        for (int j = 0; j < i; j++) A[(size_t)j * skip + i] = Ai[j];
    }
    return A;
}

// An upper bound on the entries of the lower triangle of J M^-1 J^T (with the diagonal): each
// comes from a pair j <= i of rows on one body, or is the diagonal of a row without bodies.
static size_t lower_entries_bound(const body_rows *br, int nb, int m)
{
    size_t bound = (size_t)m;
    for (int b = 0; b < nb; b++) {
        size_t deg = (size_t)(br->start[b + 1] - br->start[b]);
        bound += deg * (deg + 1) / 2;
    }
    return bound;
}

// The lower triangle (row i: columns lower_cols and values lower_vals at [lower_start[i],
// lower_start[i + 1])) into the allocated pattern pb, both halves, as dxLcpPatternAddValue
// would put them entry by entry in that order: row i's own entries first (nothing reached
// row i before it), with its running place in a register, then (i, j) to each earlier row j.
static void scatter_lower(dxLcpPatternBuilder *pb, const int *lower_start,
                          const int *lower_cols, const dReal *lower_vals)
{
    int *restrict fill = pb->fill, *restrict cols = pb->cols;
    dReal *restrict vals = pb->vals;
    for (int i = 0; i < pb->n; i++) {
        int at = fill[i];
        for (int p = lower_start[i]; p < lower_start[i + 1]; p++) {
            const int j = lower_cols[p];
            const dReal v = lower_vals[p];
            cols[at] = j;
            vals[at++] = v;
            if (j == i) continue;
            const int up = fill[j]++;
            cols[up] = i;
            vals[up] = v;
        }
        fill[i] = at;
    }
}

// A = J M^-1 J^T + cfm/h on the diagonal, as its nonzeros (exactly symmetric): the entries
// of rows that share a body. One walk of the body lists: the lower triangle goes row after
// row to scratch (its entries counted for the pattern as they come), then into the pattern
// in the same order as rows i and columns j, so that every row of A lists its columns as
// the walk met them (j <= i) and then the later rows in increasing order.
static dxLCPMatrix form_A(dxArena *a, const dxIslandRows *r, const body_rows *br, int nb,
                          const dReal *iMJ, dReal fps)
{
    const int m = r->m;
    const size_t bound = lower_entries_bound(br, nb, m);
    int *mark = DX_ARENA_ARRAY(a, int, m), *lower_start = DX_ARENA_ARRAY(a, int, m + 1);
    int *lower_cols = DX_ARENA_ARRAY(a, int, bound);
    dReal *acc = DX_ARENA_ARRAY(a, dReal, m), *lower_vals = DX_ARENA_ARRAY(a, dReal, bound);
    dxLcpPatternBuilder pb;
    dxLcpPatternBegin(&pb, a, m);
    for (int i = 0; i < m; i++) mark[i] = -1;
    int pos = 0;
    for (int i = 0; i < m; i++) {
        lower_start[i] = pos;
        int *cols = lower_cols + pos;
        int count = a_row(r, br, iMJ, i, mark, cols, acc);
        acc[i] += r->cfm[i] * fps;
        for (int t = 0; t < count; t++) {
            dxLcpPatternCount(&pb, i, cols[t]);
            lower_vals[pos + t] = acc[cols[t]];
        }
        pos += count;
    }
    lower_start[m] = pos;
    dxLcpPatternAllocate(&pb, a, 1);
    scatter_lower(&pb, lower_start, lower_cols, lower_vals);
    dxLCPMatrix A = { pb.start, pb.cols, pb.vals };
    return A;
}

// rhs = c/h - J (v/h + M^-1 f).
static dReal *form_rhs(dxArena *a, const dxIsland *is, const dxIslandBodies *bd,
                       const dxIslandRows *r, dReal fps)
{
    dReal *tmp = DX_ARENA_ARRAY(a, dReal, 6 * is->nb);
    dxIslandBodyRates(is, bd, fps, tmp);
    dReal *rhs = DX_ARENA_ARRAY(a, dReal, r->m);
    for (int i = 0; i < r->m; i++) {
        const dReal *J = r->J + i * DX_ROW_SKIP;
        dReal s = 0;
        for (int side = 0; side < 2; side++) {
            int b = side ? r->body1[i] : r->body0[i];
            if (b < 0) continue;
            const dReal *t = tmp + 6 * b, *Js = J + 6 * side;
            s += Js[0] * t[0] + Js[1] * t[1] + Js[2] * t[2] + Js[3] * t[3] + Js[4] * t[4] +
                 Js[5] * t[5];
        }
        rhs[i] = r->c[i] * fps - s;
    }
    return rhs;
}

// The big-matrix solve: A lambda = rhs + w as a mixed LCP.
static void solve_big_matrix(struct dxWorld *w, dxArena *a, const dxIsland *is,
                             const dxIslandBodies *bd, const dxIslandRows *r, dReal h,
                             dReal *lambda)
{
    (void)w;
    const dReal fps = dRecip(h);
    body_rows br;
    index_rows_by_body(a, r, is->nb, &br);
    dReal *iMJ = inverse_mass_times_jt(a, r, bd);
    dReal *rhs = form_rhs(a, is, bd, r, fps);
    dReal *wout = DX_ARENA_ARRAY(a, dReal, r->m);
    int ok;
    if (r->m <= DX_LCP_SMALL) {
        dReal *A = form_A_full(a, r, &br, iMJ, fps);
        ok = dxSolveLCP(a, r->m, A, lambda, rhs, wout, 0, r->lo, r->hi, r->findex);
    } else {
        dxLCPMatrix A = form_A(a, r, &br, is->nb, iMJ, fps);
        ok = dxSolveLCPSparse(a, r->m, &A, lambda, rhs, wout, 0, r->lo, r->hi, r->findex);
    }
    if (!ok)
        dMessage(d_ERR_LCP, "dWorldStep: the LCP solver did not converge (%d rows); "
                 "using its best approximation", r->m);
}

int dWorldStep(dWorldID w, dReal stepsize)
{
    if (dxWatchdogWants(w)) return dxWatchdogStep(w, stepsize, DX_STEP_WORLD, 0);
    return dxStepWorld(w, stepsize, __func__, solve_big_matrix);
}
