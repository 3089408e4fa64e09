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

// A row that shares a body with a run of rows (see lower_triangle) and its M^-1 J^T at the
// run's first and second body (NULL where it is not on that body).
typedef struct run_neighbour {
    int row;
    const dReal *at[2];
} run_neighbour;

// Row i's entry of J M^-1 J^T with row j (Ji: row i's J; Mj[s]: row j's M^-1 J^T at the body
// of row i's side s, NULL if j is not on it): the sum from 0 of the shared bodies' products,
// side by side.
static inline dReal a_entry(const dReal *Ji, const dReal *const Mj[2])
{
    dReal v = 0;
    for (int s = 0; s < 2; s++) {
        const dReal *J = Ji + 6 * s, *M = Mj[s];
        if (M)
            v += J[0] * M[0] + J[1] * M[1] + J[2] * M[2] + J[3] * M[3] + J[4] * M[4] +
                 J[5] * M[5];
    }
    return v;
}

// The rows before i0 that share a body with row i0 (and its run), into nbr (returned: their
// count; mark[j] == i0, slot[j] their place): those of its first body (the first of body0,
// body1 that is one; *nfirst of them) in the order of that body's list, then those only on
// the second body. The rows of a body are listed in increasing order.
static int run_neighbours(const dxIslandRows *r, const body_rows *br, const dReal *iMJ, int i0,
                          int *mark, int *slot, run_neighbour *nbr, int *nfirst)
{
    int count = 0;
    *nfirst = -1;
    for (int s = 0; s < 2; s++) {
        int b = s ? r->body1[i0] : r->body0[i0];
        if (b < 0) continue;
        for (int p = br->start[b]; p < br->start[b + 1]; p++) {
            const int j = br->entries[p] >> 1;
            if (j >= i0) break;
            if (mark[j] != i0) {
                mark[j] = i0;
                slot[j] = count;
                nbr[count++] = (run_neighbour){ j, { NULL, NULL } };
            }
            nbr[slot[j]].at[s] = iMJ + j * DX_ROW_SKIP + 6 * (br->entries[p] & 1);
        }
        if (*nfirst < 0) *nfirst = count;   // the first body's walk, even if it met none
    }
    if (*nfirst < 0) *nfirst = 0;
    return count;
}

// The lower triangle of A = J M^-1 J^T + cfm/h on the diagonal, row after row: row i's
// columns and values at lower_cols and lower_vals [lower_start[i], lower_start[i + 1]), in
// the order a walk of its bodies' lists meets the rows j <= i that share a body with it (its
// first body's, then those only on its second). The rows of a joint (or of a contact) come
// one after the other on the same bodies: such a run of rows shares its neighbours before
// it, found once, and each row adds the run's rows up to itself after the first body's.
// If upper is not NULL, upper[j] receives the number of entries of row j above the diagonal
// (the later rows that share a body with it), counted run by run.
static void lower_triangle(dxArena *a, const dxIslandRows *r, const body_rows *br,
                           const dReal *iMJ, dReal fps, int *restrict lower_start,
                           int *restrict lower_cols, dReal *restrict lower_vals,
                           int *restrict upper)
{
    const int m = r->m;
    int *mark = DX_ARENA_ARRAY(a, int, m), *slot = DX_ARENA_ARRAY(a, int, m);
    run_neighbour *nbr = DX_ARENA_ARRAY(a, run_neighbour, m);
    for (int i = 0; i < m; i++) mark[i] = -1;
    int pos = 0;
    for (int i0 = 0, i1; i0 < m; i0 = i1) {
        const int b0 = r->body0[i0], b1 = r->body1[i0];
        i1 = i0 + 1;   // a row without bodies is a run of its own: just its diagonal
        if (b0 >= 0 || b1 >= 0)
            while (i1 < m && r->body0[i1] == b0 && r->body1[i1] == b1) i1++;
        int nfirst, count = run_neighbours(r, br, iMJ, i0, mark, slot, nbr, &nfirst);
        if (upper) {   // a row is first counted by its own run (later runs add to it)
            for (int j = i0; j < i1; j++) upper[j] = i1 - 1 - j;
            for (int t = 0; t < count; t++) upper[nbr[t].row] += i1 - i0;
        }
        for (int i = i0; i < i1; i++) {
            const dReal *Ji = r->J + i * DX_ROW_SKIP;
            lower_start[i] = pos;
            for (int t = 0; t < nfirst; t++) {
                lower_cols[pos] = nbr[t].row;
                lower_vals[pos++] = a_entry(Ji, nbr[t].at);
            }
            for (int j = i0; j <= i; j++) {
                const dReal *Mj = iMJ + j * DX_ROW_SKIP;
                const dReal *own[2] = { b0 >= 0 ? Mj : NULL, b1 >= 0 ? Mj + 6 : NULL };
                lower_cols[pos] = j;
                lower_vals[pos++] = a_entry(Ji, own);
            }
            lower_vals[pos - 1] += r->cfm[i] * fps;
            for (int t = nfirst; t < count; t++) {
                lower_cols[pos] = nbr[t].row;
                lower_vals[pos++] = a_entry(Ji, nbr[t].at);
            }
        }
    }
    lower_start[m] = pos;
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

// A = J M^-1 J^T + cfm/h on the diagonal in full (row skip dPAD(m)), exactly symmetric: for
// a small island.
static dReal *form_A_full(dxArena *a, const dxIslandRows *r, const body_rows *br, int nb,
                          const dReal *iMJ, dReal fps)
{
    const int m = r->m, skip = dPAD(m);
    const size_t bound = lower_entries_bound(br, nb, m);
    dReal *A = DX_ARENA_ARRAY(a, dReal, (size_t)m * skip);
    int *lower_start = DX_ARENA_ARRAY(a, int, m + 1);
    int *lower_cols = DX_ARENA_ARRAY(a, int, bound);
    dReal *lower_vals = DX_ARENA_ARRAY(a, dReal, bound);
    lower_triangle(a, r, br, iMJ, fps, lower_start, lower_cols, lower_vals, NULL);
    dSetZero(A, m * skip);
    for (int i = 0; i < m; i++) {
        dReal *Ai = A + (size_t)i * skip;
        for (int p = lower_start[i]; p < lower_start[i + 1]; p++)
            Ai[lower_cols[p]] = lower_vals[p];
        for (int j = 0; j < i; j++) A[(size_t)j * skip + i] = Ai[j];
    }
    return A;
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
// of rows that share a body. The lower triangle goes to scratch (with each row's count of
// entries above the diagonal, so that the pattern is sized without a walk of its own), then
// into the pattern as rows i and columns j in its order, so that every row of A lists its
// columns as lower_triangle met them (j <= i) and then the later rows in increasing order.
static dxLCPMatrix form_A(dxArena *a, const dxIslandRows *r, const body_rows *br, int nb,
                          const dReal *iMJ, dReal fps)
{
    const int m = r->m;
    const size_t bound = lower_entries_bound(br, nb, m);
    int *lower_start = DX_ARENA_ARRAY(a, int, m + 1);
    int *lower_cols = DX_ARENA_ARRAY(a, int, bound);
    dReal *lower_vals = DX_ARENA_ARRAY(a, dReal, bound);
    dxLcpPatternBuilder pb;
    dxLcpPatternBegin(&pb, a, m);
    lower_triangle(a, r, br, iMJ, fps, lower_start, lower_cols, lower_vals, pb.fill);
    for (int i = 0; i < m; i++) pb.fill[i] += lower_start[i + 1] - lower_start[i];
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
        dReal *A = form_A_full(a, r, &br, is->nb, iMJ, fps);
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
