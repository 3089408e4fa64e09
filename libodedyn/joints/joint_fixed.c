// SPDX-License-Identifier: BSD-3-Clause
//
// joint_fixed.c -- the fixed joint (guide 7.3.6): three rows keep the origin
// of body 0 at its place in body 1's frame and three keep the relative
// orientation. Its ERP and CFM can be set per joint (dParamERP, dParamCFM;
// ODE 0.16). Also the orientation-lock rows the slider shares.

#include "joint_fixed.h"
#include "joint_geometry.h"

typedef struct dxJointFixed {
    dxJoint base;
    dVector3 anchor1;   // body 0 frame: always its origin
    dVector3 anchor2;   // where body 0's origin belongs, in body 1's frame (or world)
    dQuaternion qrel;   // the relative orientation to keep
    dReal erp, cfm;
} dxJointFixed;

// The rotation vector (world) by which body 0 must turn, relative to body 1,
// to bring the relative orientation back to qrel0. With r = conj(q0) q1 the
// kept relation is q1 = q0 qrel0; turning body 0 by e (q0 -> exp(e) q0)
// restores it when exp(e) = q1 conj(q0 qrel0).
static void orientation_error(const dxJoint *j, const dQuaternion qrel0, dVector3 e)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    dQuaternion target, qe;
    dQMultiply0(target, b0->q, qrel0);   // where body 1 should be
    if (b1) {
        dQMultiply2(qe, b1->q, target);
    } else {
        dQuaternion identity = { 1, 0, 0, 0 };
        dQMultiply2(qe, identity, target);
    }
    // qe = (cos(a/2), sin(a/2) u): e = a u (2 * vector part for small a);
    // qe and -qe are the same rotation, the one with qe[0] >= 0 is the short way.
    dReal s = dCalcVectorLength3(qe + 1);
    dReal scale = s > 0 ? 2 * dAtan2(s, dFabs(qe[0])) / s : 2;
    if (qe[0] < 0) scale = -scale;
    for (int i = 0; i < 3; i++) e[i] = qe[1 + i] * scale;
}

void dxJointOrientationRows(const dxJoint *j, dxJointRows *rows, int row, const dQuaternion qrel0,
                            dReal erp)
{
    const int s = rows->rowskip;
    const int has_b1 = dxJointBody(j, 1) != NULL;
    dVector3 e;
    orientation_error(j, qrel0, e);
    const dReal k = rows->fps * erp;
    for (int i = 0; i < 3; i++) {
        rows->J1a[(row + i) * s + i] = 1;
        if (has_b1) rows->J2a[(row + i) * s + i] = -1;
        rows->c[row + i] = k * e[i];
    }
}

static void fixed_init(dxJoint *j)
{
    dxJointFixed *f = (dxJointFixed *)j;
    f->erp = j->world->erp;
    f->cfm = j->world->cfm;
    dQSetIdentity(f->qrel);
}

static void fixed_count_rows(dxJoint *j, dxJointRowCount *count)
{
    (void)j;
    count->m = 6;
    count->nub = 6;
}

static void fixed_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointFixed *f = (dxJointFixed *)j;
    dxJointBallRows(j, rows, 0, f->anchor1, f->anchor2, f->erp);
    dxJointOrientationRows(j, rows, 3, f->qrel, f->erp);
    for (int i = 0; i < 6; i++) rows->cfm[i] = f->cfm;
}

static const dxJointClass fixed_class = {
    dJointTypeFixed, "fixed", sizeof(dxJointFixed), fixed_init, fixed_count_rows,
    fixed_fill_rows, NULL   // ODE 0.16 recomputes nothing: dJointSetFixed does
};

dJointID dJointCreateFixed(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &fixed_class);
}

#define FIXED(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeFixed, on_fail)

void dJointSetFixed(dJointID j)
{
    FIXED(j, return);
    dxJointFixed *f = (dxJointFixed *)j;
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (!b0) return;
    dxJointSetAnchors(j, b0->pos[0], b0->pos[1], b0->pos[2], f->anchor1, f->anchor2);
    dxJointRelativeQuaternion(j, f->qrel);
}

void dJointSetFixedParam(dJointID j, int parameter, dReal value)
{
    FIXED(j, return);
    DX_CHECK_ARG(dxIsFinite(value), return, "value is not finite");
    dxJointFixed *f = (dxJointFixed *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    if (param == dParamERP) f->erp = value;
    else if (param == dParamCFM) f->cfm = value;
}

dReal dJointGetFixedParam(dJointID j, int parameter)
{
    FIXED(j, return 0);
    dxJointFixed *f = (dxJointFixed *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    if (param == dParamERP) return f->erp;
    if (param == dParamCFM) return f->cfm;
    return 0;
}
