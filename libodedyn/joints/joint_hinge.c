// SPDX-License-Identifier: BSD-3-Clause
//
// joint_hinge.c -- the hinge joint (guide 7.3.2): the ball rows plus two rows
// keeping the axes parallel, and a limit/motor row about the axis.
//
// Attached as (0, b), b is stored as body 0 and the axis is kept as the user
// gave it; as in ODE 0.16 the angle, its rate and dJointAddHingeTorque then
// take the user's sense (body 1 against body 2: the world against b) while
// the stops and the motor act on b against the world, the opposite sense.

#include "joint_geometry.h"
#include "joint_kept.h"

typedef struct dxJointHinge {
    dxJoint base;
    dVector3 anchor1, anchor2;
    dVector3 axis1, axis2;      // body 0 frame; body 1 frame (or world)
    dQuaternion qrel;           // relative orientation at zero angle
    dxLimot limot;
} dxJointHinge;

static void hinge_init(dxJoint *j)
{
    dxJointHinge *h = (dxJointHinge *)j;
    h->axis1[0] = 1;
    h->axis2[0] = 1;
    dQSetIdentity(h->qrel);
    dxLimotInit(&h->limot, j->world);
}

static void hinge_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointHinge *h = (dxJointHinge *)j;
    count->m = 5;
    count->nub = 5;
    if (h->limot.lostop > -dInfinity || h->limot.histop < dInfinity) {
        dReal y, x;
        dxJointRelativeHalfAngle(j, h->axis1, h->qrel, &y, &x);
        if (dxLimotAngleClear(&h->limot, -y, x)) h->limot.limit = 0;   // far from the stops
        else dxLimotTestLimit(&h->limot, dxJointRelativeAngleOf(y, x));
    } else {
        h->limot.limit = 0;
    }
    if (dxLimotActive(&h->limot)) count->m = 6;
}

static void hinge_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointHinge *h = (dxJointHinge *)j;
    dVector3 ax1, ax2;
    dxJointBallRows(j, rows, 0, h->anchor1, h->anchor2, rows->erp);
    dxJointGetAxis1(j, ax1, h->axis1);
    dxJointGetAxis2(j, ax2, h->axis2);
    dxJointParallelAxesRows(j, rows, 3, ax1, ax2, rows->erp);
    dxLimotAddRow(&h->limot, j, rows, 5, ax1, 1);
}

// After dJointAttach: anchor and axis stay where the getters now put them
// (from the first body's side), stored again for the new bodies, and the
// current pose becomes angle 0 (ODE 0.16).
static void hinge_attached(dxJoint *j)
{
    dxJointHinge *h = (dxJointHinge *)j;
    dVector3 v;
    if (!dxJointBody(j, 0)) return;
    dJointGetHingeAnchor(j, v);
    dxJointSetAnchors(j, v[0], v[1], v[2], h->anchor1, h->anchor2);
    dJointGetHingeAxis(j, v);
    dxJointSetAxes(j, __func__, v[0], v[1], v[2], h->axis1, h->axis2);
    dxJointRelativeQuaternion(j, h->qrel);
}

void dxJointHingeRest(const dxJoint *j, dQuaternion qrel)
{
    if (j->cls->type == dJointTypeHinge) dCopyVector4(qrel, ((const dxJointHinge *)j)->qrel);
}

static const dxJointClass hinge_class = {
    dJointTypeHinge, "hinge", sizeof(dxJointHinge), hinge_init, hinge_count_rows,
    hinge_fill_rows, hinge_attached
};

// The sign turning an angle, rate or torque of the stored bodies (body 0
// against body 1) into the user's (body 1 against body 2 of dJointAttach).
static dReal stored_sign(const dxJoint *j)
{
    return (j->flags & DX_JOINT_REVERSE) ? -1 : 1;
}

dJointID dJointCreateHinge(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &hinge_class);
}

#define HINGE(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeHinge, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

void dJointSetHingeAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    HINGE(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointHinge *h = (dxJointHinge *)j;
    dxJointSetAnchors(j, x, y, z, h->anchor1, h->anchor2);
    dxJointRelativeQuaternion(j, h->qrel);
}

void dJointSetHingeAnchorDelta(dJointID j, dReal x, dReal y, dReal z, dReal ax, dReal ay,
                               dReal az)
{
    HINGE(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dxIsFinite3(ax, ay, az), return,
                 "anchor or delta is not finite");
    dxJointHinge *h = (dxJointHinge *)j;
    // anchor1 at (x,y,z); anchor2 displaced by the delta (a deliberate error).
    dxJointSetAnchors(j, x, y, z, h->anchor1, h->anchor2);
    dVector3 unused;
    dxJointSetAnchors(j, x + ax, y + ay, z + az, unused, h->anchor2);
    dxJointRelativeQuaternion(j, h->qrel);
}

void dJointSetHingeAxis(dJointID j, dReal x, dReal y, dReal z)
{
    HINGE(j, return);
    dxJointHinge *h = (dxJointHinge *)j;
    if (!dxJointSetAxes(j, __func__, x, y, z, h->axis1, h->axis2)) return;
    dxJointRelativeQuaternion(j, h->qrel);
}

void dJointSetHingeAxisOffset(dJointID j, dReal x, dReal y, dReal z, dReal angle)
{
    HINGE(j, return);
    DX_CHECK_ARG(dxIsFinite(angle), return, "angle is not finite");
    dxJointHinge *h = (dxJointHinge *)j;
    dJointSetHingeAxis(j, x, y, z);
    // The current position is at `angle` (user's sense): the zero was that
    // angle earlier about the axis, measured on the stored bodies.
    dQuaternion turn, q;
    dQFromAxisAndAngle(turn, h->axis1[0], h->axis1[1], h->axis1[2], stored_sign(j) * angle);
    dQMultiply0(q, turn, h->qrel);
    dCopyVector4(h->qrel, q);
}

void dJointGetHingeAnchor(dJointID j, dVector3 result)
{
    HINGE(j, return);
    CHECK_RESULT(result, return);
    dxJointHinge *h = (dxJointHinge *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor2(j, result, h->anchor2);
    else dxJointGetAnchor1(j, result, h->anchor1);
}

void dJointGetHingeAnchor2(dJointID j, dVector3 result)
{
    HINGE(j, return);
    CHECK_RESULT(result, return);
    dxJointHinge *h = (dxJointHinge *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor1(j, result, h->anchor1);
    else dxJointGetAnchor2(j, result, h->anchor2);
}

void dJointGetHingeAxis(dJointID j, dVector3 result)
{
    HINGE(j, return);
    CHECK_RESULT(result, return);
    dxJointHinge *h = (dxJointHinge *)j;
    dxJointGetAxis1(j, result, h->axis1);
}

void dJointSetHingeParam(dJointID j, int parameter, dReal value)
{
    HINGE(j, return);
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    dxLimotSetParam(&((dxJointHinge *)j)->limot, param, value);
}

dReal dJointGetHingeParam(dJointID j, int parameter)
{
    HINGE(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    dxLimotGetParam(&((dxJointHinge *)j)->limot, param, &value);
    return value;
}

dReal dJointGetHingeAngle(dJointID j)
{
    HINGE(j, return 0);
    dxJointHinge *h = (dxJointHinge *)j;
    if (!dxJointBody(j, 0)) return 0;
    return stored_sign(j) * dxJointRelativeAngle(j, h->axis1, h->qrel);
}

dReal dJointGetHingeAngleRate(dJointID j)
{
    HINGE(j, return 0);
    dxJointHinge *h = (dxJointHinge *)j;
    if (!dxJointBody(j, 0)) return 0;
    dVector3 axis;
    dxJointGetAxis1(j, axis, h->axis1);
    return stored_sign(j) * dxJointRelativeAngleRate(j, axis);
}

void dJointAddHingeTorque(dJointID j, dReal torque)
{
    HINGE(j, return);
    DX_CHECK_ARG(dxIsFinite(torque), return, "torque is not finite");
    dxJointHinge *h = (dxJointHinge *)j;
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;
    dVector3 axis;
    dxJointGetAxis1(j, axis, h->axis1);
    torque *= stored_sign(j);
    dAddVectorScaledVector3(b0->torque, b0->torque, axis, torque);
    if (b1) dAddVectorScaledVector3(b1->torque, b1->torque, axis, -torque);
}
