// SPDX-License-Identifier: BSD-3-Clause
//
// rows.c -- per-island data every stepper needs: world-frame inverse
// inertias, external forces (gravity, gyroscopic torque), the joints'
// constraint rows, and turning constraint forces back into body forces and
// velocity changes.

#include "step_internal.h"

#include <ode/matrix.h>

void dxBodyWorldInverseInertia(const struct dxBody *b, dReal *out)
{
    dMatrix3 tmp;
    dMultiply2_333(tmp, b->inv_inertia, b->R);
    dMultiply0_333(out, b->R, tmp);
}

// The gyroscopic effect, integrated implicitly so that a spinning body's
// energy cannot grow: one Newton step of backward Euler for the torque-free
// Euler equation in the body frame, I (w' - w) + h w' x (I w') = 0, starting
// at w:  w' = w - J^-1 (h w x I w),  J = I + h ([w]x I - [I w]x).
// The velocity change is handed to the stepper as the equivalent torque.
static void add_gyroscopic_torque(struct dxBody *b, dReal h)
{
    const dReal *I = b->mass.I;
    // An isotropic inertia (a sphere, a cube) has w x I w = 0: nothing to add.
    if (I[1] == 0 && I[2] == 0 && I[6] == 0 && I[4] == 0 && I[8] == 0 && I[9] == 0 &&
        I[0] == I[5] && I[0] == I[10])
        return;
    dVector3 w, L, f, dw;
    dMultiply1_331(w, b->R, b->avel);   // body frame
    dMultiply0_331(L, I, w);
    dCalcVectorCross3(f, w, L);
    dScaleVector3(f, h);
    dMatrix3 J, wx, Lx, wxI, Jinv;
    dZeroMatrix3(wx);
    dZeroMatrix3(Lx);
    dSetCrossMatrixPlus(wx, w, 4);
    dSetCrossMatrixPlus(Lx, L, 4);
    dMultiply0_333(wxI, wx, I);
    for (int i = 0; i < 12; i++) J[i] = I[i] + h * (wxI[i] - Lx[i]);
    if (dInvertMatrix3(Jinv, J) == 0) return;
    dMultiply0_331(dw, Jinv, f);         // w' = w - dw
    // torque = I_world * (-dw_world) / h, with I_world R = R I
    dVector3 Idw, t;
    dMultiply0_331(Idw, I, dw);
    dMultiply0_331(t, b->R, Idw);
    dAddVectorScaledVector3(b->torque, b->torque, t, -dRecip(h));
}

void dxIslandPrepare(struct dxWorld *w, dxArena *a, const dxIsland *is, dReal h,
                     dxIslandBodies *out)
{
    out->inv_mass = DX_ARENA_ARRAY(a, dReal, is->nb);
    out->inv_inertia = DX_ARENA_ARRAY(a, dReal, 12 * is->nb);
    for (int i = 0; i < is->nb; i++) {
        struct dxBody *b = is->bodies[i];
        b->tag = i;
        out->inv_mass[i] = b->inv_mass;
        dxBodyWorldInverseInertia(b, out->inv_inertia + 12 * i);
        if (!(b->flags & DX_BODY_NO_GRAVITY))
            dAddVectorScaledVector3(b->force, b->force, w->gravity, b->mass.mass);
        if (!(b->flags & DX_BODY_NO_GYROSCOPIC)) add_gyroscopic_torque(b, h);
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
    for (int i = 0; i < m * DX_ROW_SKIP; i++) J[i] = 0;
    for (int i = 0; i < m; i++) {
        c[i] = 0;
        cfm[i] = w->cfm;
        lo[i] = -dInfinity;
        hi[i] = dInfinity;
        findex[i] = -1;
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
