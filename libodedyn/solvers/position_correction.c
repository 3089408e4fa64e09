// SPDX-License-Identifier: BSD-3-Clause
//
// position_correction.c -- the opt-in position sweeps at the end of a step
// (dWorldSetPositionIterations, <ode/position_correction.h>): nonlinear
// Gauss-Seidel on the joints' position errors. In each sweep every joint of
// the island in turn evaluates its equality rows at the bodies' current
// poses, with fps and ERP chosen so that the right-hand side is the position
// error e itself, and moves its two bodies by the smallest change in the mass
// metric that removes it to first order:
//   (J M^-1 J^T + cfm / h^2) mu = e,   dx = M^-1 J^T mu
// (translation and a small rotation; velocities are left alone, so nothing
// is added to the motion: Box2D's position relaxation, Bullet's split
// impulse). The next joint sees the moved poses. A joint's cfm softens its
// correction as it softens its velocity rows.

#include "step_internal.h"

#include <ode/position_correction.h>
#include <ode/rotation.h>

// Rows a joint may have here (the types that take part have at most 6).
#define MAX_ROWS 8

void dWorldSetPositionIterations(dWorldID w, int n)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return, "world is NULL or was destroyed");
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    w->position_iterations = n;
}

int dWorldGetPositionIterations(dWorldID w)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return 0, "world is NULL or was destroyed");
    return w->position_iterations;
}

// The fps that makes the joint's rows, filled with ERP 1, give its position
// error as c: 1, or 1 / its own ERP for the ball and fixed joints, which keep
// one (c = fps * ERP * error). 0 for a joint that does not take part (other
// types, or an ERP of 0: the user asked for no correction).
static dReal error_fps(dxJoint *j)
{
    dReal erp = 1;
    switch (j->cls->type) {
    case dJointTypeBall: erp = dJointGetBallParam(j, dParamERP); break;
    case dJointTypeFixed: erp = dJointGetFixedParam(j, dParamERP); break;
    case dJointTypeHinge:
    case dJointTypeSlider:
    case dJointTypeUniversal: break;
    default: return 0;
    }
    return erp > 0 ? dRecip(erp) : 0;
}

// Solve the symmetric positive semidefinite n x n system A x = b in place
// (b becomes x), by elimination without pivoting; a pivot that vanishes
// (redundant rows) leaves its component 0.
static void solve_small(dReal *A, dReal *b, int n)
{
    for (int k = 0; k < n; k++) {
        const dReal p = A[k * MAX_ROWS + k];
        if (!(p > 0)) continue;
        for (int i = k + 1; i < n; i++) {
            const dReal f = A[i * MAX_ROWS + k] / p;
            for (int c = k; c < n; c++) A[i * MAX_ROWS + c] -= f * A[k * MAX_ROWS + c];
            b[i] -= f * b[k];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        const dReal p = A[k * MAX_ROWS + k];
        if (!(p > 0)) {
            b[k] = 0;
            continue;
        }
        dReal s = b[k];
        for (int c = k + 1; c < n; c++) s -= A[k * MAX_ROWS + c] * b[c];
        b[k] = s / p;
    }
}

// Move body b by dp and turn it by the small rotation vector dth (first
// order in dth, then normalised).
static void move_body(struct dxBody *b, const dVector3 dp, const dVector3 dth)
{
    dAddVectors3(b->pos, b->pos, dp);
    dReal dq[4];
    dDQfromW(dq, dth, b->q);   // (0, dth) q / 2
    for (int i = 0; i < 4; i++) b->q[i] += dq[i];
    dNormalize4(b->q);
    dxBodyUpdateRotation(b);
}

// One joint's correction: its equality rows at the current poses, solved for
// the move of its dynamic bodies (a kinematic body or the world stays).
static void correct_joint(const struct dxWorld *w, dxJoint *j, dReal h)
{
    const dReal fps = error_fps(j);
    if (fps == 0) return;
    j->cls->count_rows(j, &j->rows);
    const int m = j->rows.m, n = j->rows.nub;
    if (n <= 0 || m > MAX_ROWS) return;
    dReal J[MAX_ROWS * 12] = { 0 }, c[MAX_ROWS] = { 0 }, cfm[MAX_ROWS], lo[MAX_ROWS],
          hi[MAX_ROWS];
    int findex[MAX_ROWS];
    for (int i = 0; i < m; i++) {
        cfm[i] = w->cfm;
        lo[i] = -dInfinity;
        hi[i] = dInfinity;
        findex[i] = -1;
    }
    dxJointRows info = { .fps = fps, .erp = 1, .rowskip = 12, .J1l = J, .J1a = J + 3,
                         .J2l = J + 6, .J2a = J + 9, .c = c, .cfm = cfm, .lo = lo, .hi = hi,
                         .findex = findex };
    j->cls->fill_rows(j, &info);
    // Rows that are not finite: no correction (the step's rows reported it).
    if (!dxJointRowsKeepFinite(j, m, J, 12, c, cfm, lo, hi, findex)) return;

    // iMJ = M^-1 J^T row by row, zero for a side that does not move.
    struct dxBody *body[2];
    dReal iMJ[MAX_ROWS * 12] = { 0 };
    for (int k = 0; k < 2; k++) {
        body[k] = dxJointBody(j, k);
        if (body[k] && (body[k]->flags & DX_BODY_KINEMATIC)) body[k] = NULL;
        if (!body[k]) continue;
        dMatrix3 inv_inertia;
        dxBodyWorldInverseInertia(body[k], inv_inertia);
        for (int i = 0; i < n; i++) {
            const dReal *Jk = J + 12 * i + 6 * k;
            dReal *o = iMJ + 12 * i + 6 * k;
            dCopyScaledVector3(o, Jk, body[k]->inv_mass);
            dMultiply0_331(o + 3, inv_inertia, Jk + 3);
        }
    }
    dReal A[MAX_ROWS * MAX_ROWS];
    for (int i = 0; i < n; i++) {
        for (int r = 0; r <= i; r++) {
            dReal s = 0;
            for (int e = 0; e < 12; e++) s += J[12 * i + e] * iMJ[12 * r + e];
            A[i * MAX_ROWS + r] = A[r * MAX_ROWS + i] = s;
        }
        A[i * MAX_ROWS + i] += cfm[i] / (h * h);
    }
    solve_small(A, c, n);
    for (int k = 0; k < 2; k++) {
        if (!body[k]) continue;
        dVector3 dp = { 0, 0, 0 }, dth = { 0, 0, 0 };
        for (int i = 0; i < n; i++) {
            const dReal *o = iMJ + 12 * i + 6 * k;
            dAddVectorScaledVector3(dp, dp, o, c[i]);
            dAddVectorScaledVector3(dth, dth, o + 3, c[i]);
        }
        move_body(body[k], dp, dth);
    }
}

void dxIslandCorrectPositions(const dxIsland *is, dReal h)
{
    if (is->nb == 0) return;
    const struct dxWorld *w = is->bodies[0]->world;
    // Sweeps alternate direction (symmetric Gauss-Seidel): a correction then
    // travels the whole length of a chain in two sweeps instead of one link
    // per sweep against the order.
    for (int sweep = 0; sweep < w->position_iterations; sweep++)
        for (int k = 0; k < is->nj; k++)
            correct_joint(w, is->joints[sweep & 1 ? is->nj - 1 - k : k], h);
}
