// SPDX-License-Identifier: BSD-3-Clause
//
// step.c -- dWorldStep: the "big matrix" stepper. Per island, with the
// constraint rows J, right-hand sides c and mixing terms cfm of every joint,
// it forms A = J M^-1 J^T + cfm/h (dense, O(m^2) memory) and solves the mixed
// LCP  A lambda = c/h - J (v/h + M^-1 f) + w  (lambda the constraint forces,
// bounded by lo/hi and friction indices) with the pivoting solver of lcp.c,
// then updates velocities with the external and constraint forces and
// integrates positions.

#include "lcp.h"
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

// A = J M^-1 J^T + cfm/h on the diagonal; row skip dPAD(m).
static dReal *form_A(dxArena *a, const dxIslandRows *r, const body_rows *br, int nb,
                     const dReal *iMJ, dReal fps)
{
    const int m = r->m, skip = dPAD(m);
    dReal *A = DX_ARENA_ARRAY(a, dReal, (size_t)m * skip);
    dSetZero(A, m * skip);
    for (int b = 0; b < nb; b++) {
        for (int p = br->start[b]; p < br->start[b + 1]; p++) {
            int i = br->entries[p] >> 1, si = br->entries[p] & 1;
            const dReal *Ji = r->J + i * DX_ROW_SKIP + 6 * si;
            dReal *Arow = A + (size_t)i * skip;
            for (int q = br->start[b]; q < br->start[b + 1]; q++) {
                int j = br->entries[q] >> 1, sj = br->entries[q] & 1;
                const dReal *Mj = iMJ + j * DX_ROW_SKIP + 6 * sj;
                Arow[j] += Ji[0] * Mj[0] + Ji[1] * Mj[1] + Ji[2] * Mj[2] + Ji[3] * Mj[3] +
                           Ji[4] * Mj[4] + Ji[5] * Mj[5];
            }
        }
    }
    for (int i = 0; i < m; i++) A[(size_t)i * skip + i] += r->cfm[i] * fps;
    return A;
}

// rhs = c/h - J (v/h + M^-1 f).
static dReal *form_rhs(dxArena *a, const dxIsland *is, const dxIslandBodies *bd,
                       const dxIslandRows *r, dReal fps)
{
    dReal *tmp = DX_ARENA_ARRAY(a, dReal, 6 * is->nb);
    for (int b = 0; b < is->nb; b++) {
        const struct dxBody *body = is->bodies[b];
        dReal *t = tmp + 6 * b;
        dAddScaledVectors3(t, body->lvel, body->force, fps, bd->inv_mass[b]);
        dMultiply0_331(t + 3, bd->inv_inertia + 12 * b, body->torque);
        dAddVectorScaledVector3(t + 3, t + 3, body->avel, fps);
    }
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
static void solve_big_matrix(struct dxWorld *w, const dxIsland *is, const dxIslandBodies *bd,
                             const dxIslandRows *r, dReal h, dReal *lambda)
{
    dxArena *a = &w->arena;
    const dReal fps = dRecip(h);
    body_rows br;
    index_rows_by_body(a, r, is->nb, &br);
    dReal *iMJ = inverse_mass_times_jt(a, r, bd);
    dReal *A = form_A(a, r, &br, is->nb, iMJ, fps);
    dReal *rhs = form_rhs(a, is, bd, r, fps);
    dReal *wout = DX_ARENA_ARRAY(a, dReal, r->m);
    if (!dxSolveLCP(a, r->m, A, lambda, rhs, wout, 0, r->lo, r->hi, r->findex))
        dMessage(d_ERR_LCP, "dWorldStep: the LCP solver did not converge (%d rows); "
                 "using its best approximation", r->m);
}

int dWorldStep(dWorldID w, dReal stepsize)
{
    return dxStepWorld(w, stepsize, __func__, solve_big_matrix);
}
