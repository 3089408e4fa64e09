// SPDX-License-Identifier: BSD-3-Clause
//
// joint_pr.c -- the prismatic-rotoide joint (ODE 0.16): body 1 slides along
// axis 1 (fixed in body 1), and body 2 turns about axis 2 (perpendicular to
// it) at the anchor that rides on the slide. Four rows: two keep axis 2 of
// both bodies parallel (across axis 1 and across axis 2 x axis 1), two keep
// the anchor on the slide line; a limit/motor row for the slide (parameter
// group 1) and one for the rotation (group 2).
//
// As in ODE, the slide position, rate and the rotation angle and rate are
// measured body 1 against body 2; attached as (0, b) the position and rates
// change sign but the axes do not. The rotation's stops and motor act in the
// stored sense (body b against the world) in that case, as ODE's do.

#include "joint_geometry.h"
#include "joint_kept.h"
#include "joint_slide.h"

typedef struct dxJointPR {
    dxJoint base;
    dVector3 offset;           // the anchor in body 0's frame (at set time)
    dVector3 anchor2;          // the anchor in body 1's frame, or world
    dVector3 axis_p;           // slide axis, body 0 frame
    dVector3 axis_r1, axis_r2; // rotation axis: body 0 frame; body 1 frame or world
    dQuaternion qrel;          // relative orientation at zero angle
    dxLimot limot_p, limot_r;
} dxJointPR;

static void pr_init(dxJoint *j)
{
    dxJointPR *pr = (dxJointPR *)j;
    pr->axis_r1[0] = 1;
    pr->axis_r2[0] = 1;
    pr->axis_p[1] = 1;
    dQSetIdentity(pr->qrel);
    dxLimotInit(&pr->limot_p, j->world);
    dxLimotInit(&pr->limot_r, j->world);
}

static dReal pr_position(const dxJoint *j)
{
    const dxJointPR *pr = (const dxJointPR *)j;
    dVector3 ax;
    dxJointGetAxis1(j, ax, pr->axis_p);
    return dxJointSlidePosition(j, pr->offset, pr->anchor2, ax);
}

static void pr_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointPR *pr = (dxJointPR *)j;
    dxLimot *p = &pr->limot_p, *r = &pr->limot_r;
    count->m = 4;
    count->nub = 4;
    // The slide's stops are tested when one is finite, the rotation's when
    // one is within -pi..pi (ODE's conditions), both only when consistent.
    p->limit = 0;
    if ((p->lostop > -dInfinity || p->histop < dInfinity) && p->lostop <= p->histop)
        dxLimotTestLimit(p, pr_position(j));
    if (dxLimotActive(p)) count->m++;
    r->limit = 0;
    if ((r->lostop >= -M_PI || r->histop <= M_PI) && r->lostop <= r->histop)
        dxLimotTestLimit(r, dxJointHingeAngle(j, pr->axis_r1, pr->qrel));
    if (dxLimotActive(r)) count->m++;
}

static void pr_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointPR *pr = (dxJointPR *)j;
    dVector3 axp, ax1, ax2, q, misalign;
    dxJointGetAxis1(j, axp, pr->axis_p);
    dxJointGetAxis1(j, ax1, pr->axis_r1);
    dxJointGetAxis2(j, ax2, pr->axis_r2);
    dCalcVectorCross3(q, ax1, axp);

    // Rows 0, 1: no relative rotation except about the rotation axis.
    dCalcVectorCross3(misalign, ax1, ax2);
    dxJointTwistRows(j, rows, 0, axp, q, misalign);

    // Rows 2, 3: the anchor stays on the slide line (across axp).
    dxSlideFrame f;
    dxJointSlideFrame(j, pr->offset, pr->anchor2, &f);
    dxJointSlideLineRows(j, rows, 2, ax1, q, &f);

    // The slide position changes sign when reversed: so does its row's axis.
    if (j->flags & DX_JOINT_REVERSE) dNegateVector3(axp);
    int row = 4 + dxLimotAddRow(&pr->limot_p, j, rows, 4, axp, 0);
    dxLimotAddRow(&pr->limot_r, j, rows, row, ax1, 1);
}

// Recompute the body-relative values after dJointAttach from the world
// anchor and axes the getters report (ODE's setRelativeValues).
static void pr_attached(dxJoint *j)
{
    dxJointPR *pr = (dxJointPR *)j;
    dVector3 anchor, axp, axr;
    dJointGetPRAnchor(j, anchor);
    dJointGetPRAxis1(j, axp);
    dJointGetPRAxis2(j, axr);
    dxJointSetAnchors(j, anchor[0], anchor[1], anchor[2], pr->offset, pr->anchor2);
    dxJointSetAxes(j, "dJointAttach", axp[0], axp[1], axp[2], pr->axis_p, NULL);
    dxJointSetAxes(j, "dJointAttach", axr[0], axr[1], axr[2], pr->axis_r1, pr->axis_r2);
    dxJointRelativeQuaternion(j, pr->qrel);
}

void dxJointPRRest(const dxJoint *j, dQuaternion qrel)
{
    if (j->cls->type == dJointTypePR) dCopyVector4(qrel, ((const dxJointPR *)j)->qrel);
}

static const dxJointClass pr_class = {
    dJointTypePR, "PR", sizeof(dxJointPR), pr_init, pr_count_rows, pr_fill_rows, pr_attached
};

dJointID dJointCreatePR(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &pr_class);
}

#define PR(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypePR, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

void dJointSetPRAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    PR(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointPR *pr = (dxJointPR *)j;
    dxJointSetAnchors(j, x, y, z, pr->offset, pr->anchor2);
}

void dJointSetPRAxis1(dJointID j, dReal x, dReal y, dReal z)
{
    PR(j, return);
    dxJointPR *pr = (dxJointPR *)j;
    if (!dxJointSetAxes(j, __func__, x, y, z, pr->axis_p, NULL)) return;
    dxJointRelativeQuaternion(j, pr->qrel);
}

void dJointSetPRAxis2(dJointID j, dReal x, dReal y, dReal z)
{
    PR(j, return);
    dxJointPR *pr = (dxJointPR *)j;
    if (!dxJointSetAxes(j, __func__, x, y, z, pr->axis_r1, pr->axis_r2)) return;
    dxJointRelativeQuaternion(j, pr->qrel);
}

void dJointSetPRParam(dJointID j, int parameter, dReal value)
{
    PR(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    dxJointPR *pr = (dxJointPR *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return;
    dxLimotSetParam(group ? &pr->limot_r : &pr->limot_p, param, value);
}

dReal dJointGetPRParam(dJointID j, int parameter)
{
    PR(j, return 0);
    dxJointPR *pr = (dxJointPR *)j;
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return 0;
    dxLimotGetParam(group ? &pr->limot_r : &pr->limot_p, param, &value);
    return value;
}

// The anchor as it rides on body 2 (the world point without body 2).
void dJointGetPRAnchor(dJointID j, dVector3 result)
{
    PR(j, return);
    CHECK_RESULT(result, return);
    dxJointGetAnchor2(j, result, ((dxJointPR *)j)->anchor2);
}

void dJointGetPRAxis1(dJointID j, dVector3 result)
{
    PR(j, return);
    CHECK_RESULT(result, return);
    dxJointGetAxis1(j, result, ((dxJointPR *)j)->axis_p);
}

void dJointGetPRAxis2(dJointID j, dVector3 result)
{
    PR(j, return);
    CHECK_RESULT(result, return);
    dxJointGetAxis1(j, result, ((dxJointPR *)j)->axis_r1);
}

dReal dJointGetPRPosition(dJointID j)
{
    PR(j, return 0);
    return pr_position(j);
}

// axis . (v0 - velocity of body 1's point at the anchor); the anchor's own
// turn with body 0 is not counted (ODE's definition).
dReal dJointGetPRPositionRate(dJointID j)
{
    PR(j, return 0);
    dxJointPR *pr = (dxJointPR *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 0;
    dVector3 ax;
    dxJointGetAxis1(j, ax, pr->axis_p);
    dReal rate = dCalcVectorDot3(ax, b0->lvel);
    if (b1) {
        dVector3 r, v1;
        dMultiply0_331(r, b1->R, pr->anchor2);
        dCalcVectorCross3(v1, b1->avel, r);
        dAddVectors3(v1, v1, b1->lvel);
        return rate - dCalcVectorDot3(ax, v1);
    }
    return (j->flags & DX_JOINT_REVERSE) ? -rate : rate;
}

dReal dJointGetPRAngle(dJointID j)
{
    PR(j, return 0);
    dxJointPR *pr = (dxJointPR *)j;
    if (!dxJointBody(j, 0)) return 0;
    const dReal angle = dxJointHingeAngle(j, pr->axis_r1, pr->qrel);
    return (j->flags & DX_JOINT_REVERSE) ? -angle : angle;
}

dReal dJointGetPRAngleRate(dJointID j)
{
    PR(j, return 0);
    dxJointPR *pr = (dxJointPR *)j;
    if (!dxJointBody(j, 0)) return 0;
    dVector3 ax;
    dxJointGetAxis1(j, ax, pr->axis_r1);
    const dReal rate = dxJointRelativeAngleRate(j, ax);
    return (j->flags & DX_JOINT_REVERSE) ? -rate : rate;
}

// torque about the rotation axis on body 1, the opposite on body 2.
void dJointAddPRTorque(dJointID j, dReal torque)
{
    PR(j, return);
    DX_CHECK_ARG(dxIsFinite(torque), return, "torque is not finite");
    dxJointPR *pr = (dxJointPR *)j;
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;
    if (j->flags & DX_JOINT_REVERSE) torque = -torque;
    dVector3 ax;
    dxJointGetAxis1(j, ax, pr->axis_r1);
    dAddVectorScaledVector3(b0->torque, b0->torque, ax, torque);
    if (b1) dAddVectorScaledVector3(b1->torque, b1->torque, ax, -torque);
}
