// SPDX-License-Identifier: BSD-3-Clause
//
// rows.c -- per-island data every stepper needs: world-frame inverse
// inertias, external forces (gravity, gyroscopic torque), the joints'
// constraint rows, and turning constraint forces back into body forces and
// velocity changes.

#include "step_internal.h"

#include <ode/matrix.h>

#include <float.h>
#include <math.h>
#include <string.h>

// Two numbers at a time (GCC/Clang vector extension: SSE2).
typedef dReal dxRealPair __attribute__((vector_size(2 * sizeof(dReal))));

static inline dxRealPair pair_of(dReal a, dReal b)
{
    const dxRealPair v = { a, b };
    return v;
}

// Are the off-diagonal entries of the 3x3 matrix M (dMatrix3 layout: 1, 2,
// 4, 6, 8, 9) all zero? (Three pairs compared at once.)
static inline int is_diagonal(const dReal *M)
{
    const dxRealPair zero = { 0, 0 };
    dxRealPair a, c;
    memcpy(&a, M + 1, sizeof a);
    memcpy(&c, M + 8, sizeof c);
    const __typeof__(a == zero) z = (a == zero) & (pair_of(M[4], M[6]) == zero) & (c == zero);
    return (z[0] & z[1]) != 0;
}

// out = R A R^T for a body-frame inverse inertia A that is not diagonal
// (out of line: the diagonal case's code stays short).
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void world_inverse_inertia_full(const dReal *A, const dReal *R, dReal *out)
{
    dMatrix3 tmp;
    dMultiply2_333(tmp, A, R);
    dMultiply0_333(out, R, tmp);
}

void dxBodyWorldInverseInertia(const struct dxBody *b, dReal *out)
{
    const dReal *A = b->inv_inertia, *R = b->R;
    if (is_diagonal(A)) {
        // A diagonal body-frame inverse (the usual case): tmp = A R^T is R^T
        // with row k scaled by A_kk, the products the general form adds to it
        // being exact zeros; then R tmp summed in dMultiply0_333's order.
        // Columns 0 and 1 of tmp and out as pairs, column 2 alone: each
        // number the same products and sums.
        const dxRealPair t0 = pair_of(R[0], R[4]) * A[0];
        const dxRealPair t1 = pair_of(R[1], R[5]) * A[5];
        const dxRealPair t2 = pair_of(R[2], R[6]) * A[10];
        const dReal u0 = A[0] * R[8], u1 = A[5] * R[9], u2 = A[10] * R[10];
        for (int i = 0; i < 3; i++) {
            const dReal *Ri = R + 4 * i;
            const dxRealPair o = t0 * Ri[0] + t1 * Ri[1] + t2 * Ri[2];
            out[4 * i] = o[0];
            out[4 * i + 1] = o[1];
            out[4 * i + 2] = u0 * Ri[0] + u1 * Ri[1] + u2 * Ri[2];
        }
        return;
    }
    world_inverse_inertia_full(A, R, out);
}

// Newton's method stops when its step is this small relative to the solution.
#ifdef dSINGLE
#define GYRO_TOL (16 * FLT_EPSILON)
#else
#define GYRO_TOL (16 * DBL_EPSILON)
#endif

// out = I v for the body-frame inertia I; diag (a constant after inlining):
// I is diagonal, and its zeros are left out (the products they would add
// are exact zeros).
static inline void inertia_times(const dReal *I, int diag, const dReal *v, dReal *out)
{
    if (!diag) {
        dMultiply0_331(out, I, v);
        return;
    }
    for (int k = 0; k < 3; k++) out[k] = I[5 * k] * v[k];
}

// The Newton Jacobian of gyroscopic_midpoint, I + h/2 ([m]x I - [I m]x),
// its diagonal zeros left out for a diagonal I as in inertia_times.
static inline void midpoint_jacobian(const dReal *I, int diag, const dReal *m, const dReal *Im,
                                     dReal h, dMatrix3 J)
{
    dMatrix3 mx, Imx, mxI;
    dZeroMatrix3(mx);
    dZeroMatrix3(Imx);
    dSetCrossMatrixPlus(mx, m, 4);
    dSetCrossMatrixPlus(Imx, Im, 4);
    if (!diag) {
        dMultiply0_333(mxI, mx, I);
        for (int k = 0; k < 12; k++) J[k] = I[k] + REAL(0.5) * h * (mxI[k] - Imx[k]);
        return;
    }
    // [m]x I scales column c of [m]x by I_c; its diagonal stays zero.
    J[3] = J[7] = J[11] = 0;
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            const int k = 4 * r + c;
            J[k] = r == c ? I[k] : REAL(0.5) * h * (mx[k] * I[5 * c] - Imx[k]);
        }
    }
}

// x scaled back to w's energy if it has more (an iteration that did not
// converge, a huge spin for the step, or rounding), or set to w if it is not
// finite: the term never adds energy.
static inline void keep_energy(const dReal *I, int diag, const dReal *w, dReal *x)
{
    dVector3 Iw, Ix;
    inertia_times(I, diag, w, Iw);
    inertia_times(I, diag, x, Ix);
    const dReal e0 = dCalcVectorDot3(w, Iw), e1 = dCalcVectorDot3(x, Ix);
    if (!(e1 <= e0)) {
        if (e1 > 0 && dxIsFinite(e1)) dScaleVector3(x, dSqrt(e0 / e1));
        else dCopyVector3(x, w);
    }
}

// The torque-free motion of a body over one step, in the body frame: the
// implicit midpoint rule for Euler's equation,
//   I (x - w) + h m x (I m) = 0,   m = (w + x) / 2,
// solved by Newton's method from x = w (Jacobian I + h/2 ([m]x I - [I m]x)).
// Any solution keeps both quadratic invariants exactly: dotting the equation
// with m gives x.Ix = w.Iw (energy), with I m gives |Ix| = |Iw| (|L|).
// Because the position update then turns the body about x itself, these are
// also the energy and |L| measured after the step. An iteration that does
// not converge (a huge spin for the step) is scaled back to w's energy, so
// the term never adds energy. Writes x; see docs/design.md for the choice.
// diag: I is diagonal (the usual body frame: principal axes), whose zeros
// are left out.
static inline void gyroscopic_midpoint(const dReal *I, int diag, const dReal *w, dReal h,
                                       dReal *x)
{
    const dReal tol = GYRO_TOL;
    dReal last2 = 0;   // the last step's |step|^2
    dCopyVector3(x, w);
    for (int it = 0; it < 12; it++) {
        dVector3 m, Im, mIm, F, step;
        for (int k = 0; k < 3; k++) m[k] = REAL(0.5) * (w[k] + x[k]);
        inertia_times(I, diag, m, Im);
        dCalcVectorCross3(mIm, m, Im);
        dVector3 d;
        dSubtractVectors3(d, x, w);
        inertia_times(I, diag, d, F);
        dAddVectorScaledVector3(F, F, mIm, h);
        dMatrix3 J, Jinv;
        midpoint_jacobian(I, diag, m, Im, h, J);
        if (dInvertMatrix3(Jinv, J) == 0) break;
        dMultiply0_331(step, Jinv, F);
        dSubtractVectors3(x, x, step);
        // Converged when the step is below tol |x|, or when the next one
        // would be: Newton's steps shrink quadratically, |next| ~ K |step|^2
        // with K ~ |step| / |last|^2, so |step|^3 / |last|^2 <= tol |x| (in
        // squares) saves the step that would only confirm it.
        const dReal s2 = dCalcVectorLengthSquare3(step), x2 = dCalcVectorLengthSquare3(x);
        if (s2 <= tol * tol * x2 || s2 * s2 * s2 <= tol * tol * x2 * last2 * last2) break;
        last2 = s2;
    }
    keep_energy(I, diag, w, x);
}

// The symmetry axis s of a diagonal inertia with exactly two equal moments
// (I_p = I_q != I_s), or -1.
static int symmetry_axis(const dReal *I)
{
    if (I[0] == I[5]) return I[0] != I[10] ? 2 : -1;
    if (I[5] == I[10]) return 0;
    if (I[10] == I[0]) return 1;
    return -1;
}

// Body b's gyroscopic change x - w (body frame) over a step h (the term on,
// an inertia with three different moments or not diagonal); its body-frame
// rate w into w. diag: its inertia is diagonal.
static void gyroscopic_change(const struct dxBody *b, dReal h, int diag, dReal *d, dReal *w)
{
    const dReal *I = b->mass.I;
    dMultiply1_331(w, b->R, b->avel);   // body frame
    dVector3 x;
    if (diag) gyroscopic_midpoint(I, 1, w, h, x);
    else gyroscopic_midpoint(I, 0, w, h, x);
    dSubtractVectors3(d, x, w);
}

// The torque that gives back last step's gyroscopic work, -W / h along the
// momentum L (world frame; it turns the body about its own rate, so it is
// realised wherever the body may still turn as it turned): added to t.
// Limited to a tenth of the rate per step, so a stale or odd entry cannot
// throw the body.
static void add_work_correction(const struct dxBody *b, const dReal *L, dReal h, dReal *t)
{
    const dReal e2 = dCalcVectorDot3(b->avel, L);   // twice the rotational energy
    if (!(e2 > 0)) return;
    dReal k = -b->gyro_pending / e2;   // relative change of the rate, h * torque / L
    const dReal limit = REAL(0.1);
    if (k > limit) k = limit;
    if (k < -limit) k = -limit;
    dAddVectorScaledVector3(t, t, L, k / h);
}

// The gyroscopic torque of an axisymmetric body (diagonal I with I_p = I_q
// = a, I_s = c for the axes (p, q, s) in cyclic order) into t, worked in the
// world frame. Then w x I w = (c - a) w_s (w_q, -w_p, 0) in (p, q, s), so the
// implicit midpoint rule of gyroscopic_midpoint keeps w_s and is linear in
// the rest: x_p - w_p + k (w_q + x_q) = 0, x_q - w_q - k (w_p + x_p) = 0 with
// k = h (c - a) w_s / (2 a). Its solution turns w's part across the axis,
// v = w - w_s u (u: the axis, column s of R), about u by the Cayley rotation
// of angle 2 atan k (the exact precession rate (c - a) w_s / a, to second
// order in h): x_v = ((1 - k^2) v + 2 k u x w) / (1 + k^2), the same
// solution Newton's method converges to, up to rounding, without its
// iteration. x - w lies across u, where I acts as a, so the torque is
// a (x_v - v) / h: no turn into the body frame and back. A rounding that
// lengthens x_v is scaled away, so the term never adds energy.
static void axisymmetric_torque(const struct dxBody *b, int s, dReal h, dReal *t)
{
    const dReal *I = b->mass.I, *R = b->R, *w = b->avel;
    const dReal a = I[5 * ((s + 1) % 3)], c = I[5 * s];
    const dVector3 u = { R[s], R[4 + s], R[8 + s] };
    const dReal ws = dCalcVectorDot3(u, w);
    dVector3 v, uw, x;
    dAddVectorScaledVector3(v, w, u, -ws);
    dCalcVectorCross3(uw, u, w);
    const dReal k = REAL(0.5) * h * (c - a) * ws / a, k2 = k * k;
    const dReal r = dRecip(1 + k2), cv = (1 - k2) * r, cu = 2 * k * r;
    for (int i = 0; i < 3; i++) x[i] = cv * v[i] + cu * uw[i];
    const dReal e0 = dCalcVectorLengthSquare3(v), e1 = dCalcVectorLengthSquare3(x);
    if (!(e1 <= e0)) {
        if (e1 > 0 && dxIsFinite(e1)) dScaleVector3(x, dSqrt(e0 / e1));
        else dCopyVector3(x, v);
    }
    const dReal ah = a / h;
    for (int i = 0; i < 3; i++) t[i] = ah * (x[i] - v[i]);
    if (b->gyro_pending != 0) {
        dVector3 L;   // I w = a w + (c - a) w_s u
        for (int i = 0; i < 3; i++) L[i] = a * w[i] + (c - a) * ws * u[i];
        add_work_correction(b, L, h, t);
    }
}

// dxBodyGyroscopicTorque for a body that has the term (out of line: the
// bodies without it, as spheres, take a short way).
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void gyroscopic_torque(struct dxBody *b, dReal h, int diag, dReal *t)
{
    const int s = diag ? symmetry_axis(b->mass.I) : -1;
    if (s >= 0) {
        axisymmetric_torque(b, s, h, t);
    } else {
        dVector3 d, w, Id;
        gyroscopic_change(b, h, diag, d, w);
        inertia_times(b->mass.I, diag, d, Id);
        dMultiply0_331(t, b->R, Id);
        dScaleVector3(t, dRecip(h));
        if (b->gyro_pending != 0) {
            dVector3 Lb, L;
            inertia_times(b->mass.I, diag, w, Lb);
            dMultiply0_331(L, b->R, Lb);
            add_work_correction(b, L, h, t);
        }
    }
    dCopyVector3(b->gyro_torque, t);
    b->gyro_work = REAL(0.5) * h * dCalcVectorDot3(t, b->avel);
}

int dxBodyGyroscopicTorque(struct dxBody *b, dReal h, dReal *t)
{
    const dReal *I = b->mass.I;
    dZeroVector3(b->gyro_torque);
    b->gyro_work = 0;
    // None with the term off, or for an isotropic inertia (w x I w = 0).
    const int diag = is_diagonal(I);
    if ((b->flags & DX_BODY_NO_GYROSCOPIC) || (diag && I[0] == I[5] && I[0] == I[10])) {
        b->gyro_pending = 0;
        return 0;
    }
    gyroscopic_torque(b, h, diag, t);
    return 1;
}

void dxBodyGyroscopicEnd(struct dxBody *b, dReal h)
{
    b->gyro_pending += b->gyro_work + REAL(0.5) * h * dCalcVectorDot3(b->gyro_torque, b->avel);
    dZeroVector3(b->gyro_torque);
    b->gyro_work = 0;
}

void dxIslandPrepare(struct dxWorld *w, dxArena *a, const dxIsland *is, dReal gyro_h,
                     dxIslandBodies *out)
{
    dReal *inv_mass = DX_ARENA_ARRAY(a, dReal, is->nb);
    dxIslandPrepareAt(w, is, gyro_h, inv_mass, DX_ARENA_ARRAY(a, dReal, 12 * is->nb), out);
}

// dxIslandPrepareAt asks for the lines of the body this many places ahead in
// the island while it works on the current one: the bodies lie far apart, in
// an order the hardware prefetchers cannot follow, and since the island walk
// only their first line is in the cache (two thirds of the pass's time waited
// on the first read of each body's mass in ragdolls).
#define PREPARE_AHEAD 4

// Ask for the lines of body b that the pass reads: from its mass to its
// gyroscopic fields.
static inline void prefetch_prepared_body(const struct dxBody *b)
{
#if defined(__GNUC__)
    const char *p = (const char *)&b->mass, *end = (const char *)(&b->gyro_pending + 1);
    for (; p < end; p += 64) __builtin_prefetch(p);
    __builtin_prefetch(end - 1);
#else
    (void)b;
#endif
}

void dxIslandPrepareAt(struct dxWorld *w, const dxIsland *is, dReal gyro_h, dReal *inv_mass,
                       dReal *inv_inertia, dxIslandBodies *out)
{
    out->inv_mass = inv_mass;
    out->inv_inertia = inv_inertia;
    for (int i = 0; i < is->nb; i++) {
        if (i + PREPARE_AHEAD < is->nb) prefetch_prepared_body(is->bodies[i + PREPARE_AHEAD]);
        struct dxBody *b = is->bodies[i];
        b->tag = i;
        out->inv_mass[i] = b->inv_mass;
        dxBodyWorldInverseInertia(b, out->inv_inertia + 12 * i);
        if (!(b->flags & DX_BODY_NO_GRAVITY))
            dAddVectorScaledVector3(b->force, b->force, w->gravity, b->mass.mass);
        dVector3 t;
        if (gyro_h > 0 && dxBodyGyroscopicTorque(b, gyro_h, t))
            dAddVectors3(b->torque, b->torque, t);
    }
}

void dxIslandBodyRates(const dxIsland *is, const dxIslandBodies *bd, dReal fps, dReal *rates)
{
    for (int b = 0; b < is->nb; b++) {
        const struct dxBody *body = is->bodies[b];
        dReal *t = rates + 6 * b;
        dAddScaledVectors3(t, body->lvel, body->force, fps, bd->inv_mass[b]);
        dMultiply0_331(t + 3, bd->inv_inertia + 12 * b, body->torque);
        dAddVectorScaledVector3(t + 3, t + 3, body->avel, fps);
    }
}

// Island index of a joint's body k, or -1 for the static world or a
// kinematic body (which is not part of the island).
static int island_index(const dxJoint *j, int k)
{
    const struct dxBody *b = dxJointBody(j, k);
    return (b && !(b->flags & DX_BODY_KINEMATIC)) ? b->tag : -1;
}

// A kinematic body moves whatever the constraint does: its velocity is a
// known term of the row, J_k v_k, moved into c (m rows).
static void fold_kinematic(const dxJoint *j, const dReal *J, dReal *c, int m)
{
    for (int k = 0; k < 2; k++) {
        const struct dxBody *b = dxJointBody(j, k);
        if (!b || !(b->flags & DX_BODY_KINEMATIC)) continue;
        for (int i = 0; i < m; i++) {
            const dReal *Jk = J + i * DX_ROW_SKIP + 6 * k;
            c[i] -= dCalcVectorDot3(Jk, b->lvel) + dCalcVectorDot3(Jk + 3, b->avel);
        }
    }
}

void dxJointRowsFill(struct dxWorld *w, dxJoint *j, dReal h, dReal *J, dReal *c, dReal *cfm,
                     dReal *lo, dReal *hi, int *findex, int *b)
{
    const int m = j->rows.m;
    b[0] = island_index(j, 0);
    b[1] = island_index(j, 1);
    if (m == 0) return;
    if (j->cls->type != dJointTypeContact) {   // it writes every entry itself
        for (int i = 0; i < m * DX_ROW_SKIP; i++) J[i] = 0;
        dxJointRowsDefaults(w, m, c, cfm, lo, hi, findex);
    }
    dxJointRows info;
    info.fps = dRecip(h);
    info.erp = w->erp;
    info.rowskip = DX_ROW_SKIP;
    info.J1l = J;
    info.J1a = J + 3;
    info.J2l = J + 6;
    info.J2a = J + 9;
    info.c = c;
    info.cfm = cfm;
    info.lo = lo;
    info.hi = hi;
    info.findex = findex;
    j->cls->fill_rows(j, &info);
    fold_kinematic(j, J, c, m);
    if (!dxJointRowsKeepFinite(j, m, J, DX_ROW_SKIP, c, cfm, lo, hi, findex))
        dxReportMessage("step", "a %s joint's rows are not finite (its pose or parameters have "
                        "no answer): it acts with no force this step", j->cls->name);
}


static inline dxRealPair load_pair(const dReal *x)
{
    dxRealPair v;
    memcpy(&v, x, sizeof v);
    return v;
}

// Are the m rows' J (row skip `skip`), c and cfm finite and their bounds not
// NaN? x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so the
// sums of the products stay 0 exactly when every number is finite (a
// multiply and an add a pair, no branch).
static int rows_finite(int m, const dReal *J, int skip, const dReal *c, const dReal *cfm,
                       const dReal *lo, const dReal *hi)
{
    const dxRealPair zero = { 0, 0 };
    dxRealPair sum = zero;
    dReal sum1 = 0;
    int nan_bound = 0;
    for (int i = 0; i < m; i++) {
        const dReal *Ji = J + i * skip;
        for (int e = 0; e < 12; e += 2) sum += load_pair(Ji + e) * zero;
        sum1 += c[i] * zero[0] + cfm[i] * zero[0];
        nan_bound |= (lo[i] != lo[i]) | (hi[i] != hi[i]);   // infinite bounds are fine
    }
    return sum[0] + sum[1] + sum1 == 0 && !nan_bound;
}

int dxJointRowsKeepFinite(const dxJoint *j, int m, dReal *J, int skip, dReal *c, dReal *cfm,
                          dReal *lo, dReal *hi, int *findex)
{
    // First the plain sums (an add a pair): finite numbers have a finite sum
    // unless it overflows, so a finite sum settles it; otherwise (a number
    // is not finite, or the sum overflowed) rows_finite decides.
    dxRealPair sum = { 0, 0 };
    dReal sum1 = 0;
    int nan_bound = 0;
    for (int i = 0; i < m; i++) {
        const dReal *Ji = J + i * skip;
        for (int e = 0; e < 12; e += 2) sum += load_pair(Ji + e);
        sum1 += c[i] + cfm[i];
        nan_bound |= (lo[i] != lo[i]) | (hi[i] != hi[i]);
    }
    const dReal total = sum[0] + sum[1] + sum1;
    if (total - total == 0 && !nan_bound) return 1;   // finite: x - x is 0, else NaN
    if (!nan_bound && rows_finite(m, J, skip, c, cfm, lo, hi)) return 1;
    for (int i = 0; i < m; i++) {
        for (int e = 0; e < 12; e++) J[i * skip + e] = 0;
        c[i] = lo[i] = hi[i] = 0;
        cfm[i] = j->world->cfm;
        findex[i] = -1;
    }
    return 0;
}

void dxRowsBuild(struct dxWorld *w, dxArena *a, const dxIsland *is, dReal h, dxIslandRows *r)
{
    r->joint_row = DX_ARENA_ARRAY(a, int, is->nj + 1);
    int m = 0;
    for (int k = 0; k < is->nj; k++) {
        dxJoint *j = is->joints[k];
        j->cls->count_rows(j, &j->rows);
        r->joint_row[k] = m;
        m += j->rows.m;
    }
    r->joint_row[is->nj] = m;
    r->m = m;
    r->J = DX_ARENA_ARRAY(a, dReal, (size_t)m * DX_ROW_SKIP);
    r->c = DX_ARENA_ARRAY(a, dReal, m);
    r->cfm = DX_ARENA_ARRAY(a, dReal, m);
    r->lo = DX_ARENA_ARRAY(a, dReal, m);
    r->hi = DX_ARENA_ARRAY(a, dReal, m);
    r->findex = DX_ARENA_ARRAY(a, int, m);
    r->body0 = DX_ARENA_ARRAY(a, int, m);
    r->body1 = DX_ARENA_ARRAY(a, int, m);
    for (int k = 0; k < is->nj; k++) {
        const int first = r->joint_row[k], count = is->joints[k]->rows.m;
        int b[2];
        dxJointRowsFill(w, is->joints[k], h, r->J + first * DX_ROW_SKIP, r->c + first,
                        r->cfm + first, r->lo + first, r->hi + first, r->findex + first, b);
        for (int i = first; i < first + count; i++) {
            if (r->findex[i] >= 0) r->findex[i] += first;
            r->body0[i] = b[0];
            r->body1[i] = b[1];
        }
    }
}

void dxRowsApplyForces(const dxIsland *is, const dxIslandRows *r, const dReal *lambda,
                       dReal *bf)
{
    for (int k = 0; k < is->nj; k++) {
        dxJoint *j = is->joints[k];
        dJointFeedback *fb = j->feedback;
        dReal f[12] = { 0 };   // [force0 torque0 force1 torque1] of this joint
        for (int i = r->joint_row[k]; i < r->joint_row[k + 1]; i++) {
            const dReal *J = r->J + i * DX_ROW_SKIP;
            for (int e = 0; e < 12; e++) f[e] += J[e] * lambda[i];
        }
        int b0 = dxJointBody(j, 0) ? island_index(j, 0) : -1;
        int b1 = dxJointBody(j, 1) ? island_index(j, 1) : -1;
        if (b0 >= 0)
            for (int e = 0; e < 6; e++) bf[6 * b0 + e] += f[e];
        if (b1 >= 0)
            for (int e = 0; e < 6; e++) bf[6 * b1 + e] += f[6 + e];
        if (fb) {
            dCopyVector3(fb->f1, f);
            dCopyVector3(fb->t1, f + 3);
            dCopyVector3(fb->f2, f + 6);
            dCopyVector3(fb->t2, f + 9);
        }
    }
}

void dxIslandUpdateVelocities(const dxIsland *is, const dxIslandBodies *bd,
                              const dReal *cf, dReal h)
{
    for (int i = 0; i < is->nb; i++) {
        struct dxBody *b = is->bodies[i];
        dVector3 f, t, dw;
        dAddVectors3(f, b->force, cf + 6 * i);
        dAddVectors3(t, b->torque, cf + 6 * i + 3);
        dAddVectorScaledVector3(b->lvel, b->lvel, f, h * bd->inv_mass[i]);
        dMultiply0_331(dw, bd->inv_inertia + 12 * i, t);
        dAddVectorScaledVector3(b->avel, b->avel, dw, h);
    }
}
