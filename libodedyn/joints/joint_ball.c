// SPDX-License-Identifier: BSD-3-Clause
//
// joint_ball.c -- the ball-and-socket joint (guide 7.3.1): three rows that
// keep one anchor point of the two bodies together. Its ERP and CFM can be
// set per joint (dParamERP, dParamCFM; ODE 0.16).

#include "joint_geometry.h"

typedef struct dxJointBall {
    dxJoint base;
    dVector3 anchor1, anchor2;   // body 0 frame; body 1 frame (or world)
    dReal erp, cfm;
} dxJointBall;

static void ball_init(dxJoint *j)
{
    dxJointBall *b = (dxJointBall *)j;
    b->erp = j->world->erp;
    b->cfm = j->world->cfm;
}

static void ball_count_rows(dxJoint *j, dxJointRowCount *count)
{
    (void)j;
    count->m = 3;
    count->nub = 3;
}

static void ball_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointBall *b = (dxJointBall *)j;
    dxJointBallRows(j, rows, 0, b->anchor1, b->anchor2, b->erp);
    for (int i = 0; i < 3; i++) rows->cfm[i] = b->cfm;
}

// After dJointAttach: the anchor stays where the getter now puts it (from the
// first body's side) and is stored again for the new bodies (ODE 0.16).
static void ball_attached(dxJoint *j)
{
    dxJointBall *b = (dxJointBall *)j;
    dVector3 p;
    if (!dxJointBody(j, 0)) return;
    dJointGetBallAnchor(j, p);
    dxJointSetAnchors(j, p[0], p[1], p[2], b->anchor1, b->anchor2);
}

static const dxJointClass ball_class = {
    dJointTypeBall, "ball", sizeof(dxJointBall), ball_init, ball_count_rows, ball_fill_rows,
    ball_attached
};

dJointID dJointCreateBall(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &ball_class);
}

#define BALL(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeBall, on_fail)

void dJointSetBallAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    BALL(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointBall *b = (dxJointBall *)j;
    dxJointSetAnchors(j, x, y, z, b->anchor1, b->anchor2);
}

void dJointSetBallAnchor2(dJointID j, dReal x, dReal y, dReal z)
{
    BALL(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointBall *b = (dxJointBall *)j;
    const struct dxBody *b1 = dxJointBody(j, 1);
    dVector3 p = { x, y, z, 0 };
    if (b1) {
        dVector3 r;
        dSubtractVectors3(r, p, b1->pos);
        dMultiply1_331(b->anchor2, b1->R, r);
    } else {
        dCopyVector3(b->anchor2, p);
    }
}

void dJointGetBallAnchor(dJointID j, dVector3 result)
{
    BALL(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dxJointBall *b = (dxJointBall *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor2(j, result, b->anchor2);
    else dxJointGetAnchor1(j, result, b->anchor1);
}

void dJointGetBallAnchor2(dJointID j, dVector3 result)
{
    BALL(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dxJointBall *b = (dxJointBall *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor1(j, result, b->anchor1);
    else dxJointGetAnchor2(j, result, b->anchor2);
}

void dJointSetBallParam(dJointID j, int parameter, dReal value)
{
    BALL(j, return);
    dxJointBall *b = (dxJointBall *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    if (param == dParamERP) b->erp = value;
    else if (param == dParamCFM) b->cfm = value;
}

dReal dJointGetBallParam(dJointID j, int parameter)
{
    BALL(j, return 0);
    dxJointBall *b = (dxJointBall *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    if (param == dParamERP) return b->erp;
    if (param == dParamCFM) return b->cfm;
    return 0;
}
