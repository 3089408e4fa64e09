// SPDX-License-Identifier: BSD-3-Clause
//
// joint_dhinge.c -- the double hinge joint (ODE 0.16): a double ball joint
// whose bodies also keep an axis parallel (two rows, as in the hinge) and
// whose anchors stay in one plane across that axis (one row, acting at the
// midpoint of the centres so it exerts no couple). Four rows, all with the
// joint's ERP (dParamERP); dParamCFM applies to the distance row. The
// anchors, distance and parameters are the double ball's.

#include "joint_dball.h"

typedef struct dxJointDHinge {
    dxJointDBall ball;
    dVector3 axis1, axis2;   // stored body 0 frame; stored body 1 frame (or world)
} dxJointDHinge;

// Until an axis is set (it starts as zero, as in ODE) only the distance row acts.
static void dhinge_count_rows(dxJoint *j, dxJointRowCount *count)
{
    const dxJointDHinge *h = (const dxJointDHinge *)j;
    const int has_axis = h->axis1[0] != 0 || h->axis1[1] != 0 || h->axis1[2] != 0;
    count->m = count->nub = dxJointBody(j, 0) ? (has_axis ? 4 : 1) : 0;
}

static void dhinge_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointDHinge *h = (dxJointDHinge *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const dReal erp = h->ball.erp;
    dxDBallDistanceRow(j, rows);

    dVector3 ax1, ax2;
    dxJointGetAxis1(j, ax1, h->axis1);
    dxJointGetAxis2(j, ax2, h->axis2);
    dxJointParallelAxesRows(j, rows, 1, ax1, ax2, erp);

    // Row 3: the anchors' separation along the axis stays zero.
    const int r = 3 * rows->rowskip;
    dCopyVector3(rows->J1l + r, ax1);
    if (b1) {
        dVector3 half;
        dSubtractVectors3(half, b1->pos, b0->pos);
        dScaleVector3(half, REAL(0.5));
        dCalcVectorCross3(rows->J1a + r, half, ax1);
        dCopyNegatedVector3(rows->J2l + r, ax1);
        dCopyVector3(rows->J2a + r, rows->J1a + r);
    }
    dVector3 p1, p2, sep;
    dxDBallWorldAnchors(j, p1, p2);
    dSubtractVectors3(sep, p1, p2);
    rows->c[3] = -rows->fps * erp * dCalcVectorDot3(ax1, sep);
}

static const dxJointClass dhinge_class = {
    dJointTypeDHinge, "double hinge", sizeof(dxJointDHinge), dxDBallInit, dhinge_count_rows,
    dhinge_fill_rows, dxDBallUpdateDistance
};

dJointID dJointCreateDHinge(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &dhinge_class);
}

#define DHINGE(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeDHinge, on_fail)

// The axis (world) is kept in both bodies' frames, so a misalignment after
// this call is corrected. Set it after attaching: before, both are the world's.
void dJointSetDHingeAxis(dJointID j, dReal x, dReal y, dReal z)
{
    DHINGE(j, return);
    dxJointDHinge *h = (dxJointDHinge *)j;
    dVector3 a = { x, y, z, 0 };
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dSafeNormalize3(a), return,
                 "axis (%g, %g, %g) has no direction", (double)x, (double)y, (double)z);
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (b0) dMultiply1_331(h->axis1, b0->R, a);
    else dCopyVector3(h->axis1, a);
    if (b1) dMultiply1_331(h->axis2, b1->R, a);
    else dCopyVector3(h->axis2, a);
    h->axis1[3] = h->axis2[3] = 0;
}

void dJointGetDHingeAxis(dJointID j, dVector3 result)
{
    DHINGE(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dxJointGetAxis1(j, result, ((dxJointDHinge *)j)->axis1);
}

// The rest is the double ball's (checked there: a double hinge is one).
void dJointSetDHingeAnchor1(dJointID j, dReal x, dReal y, dReal z)
{
    DHINGE(j, return);
    dJointSetDBallAnchor1(j, x, y, z);
}

void dJointSetDHingeAnchor2(dJointID j, dReal x, dReal y, dReal z)
{
    DHINGE(j, return);
    dJointSetDBallAnchor2(j, x, y, z);
}

void dJointGetDHingeAnchor1(dJointID j, dVector3 result)
{
    DHINGE(j, return);
    dJointGetDBallAnchor1(j, result);
}

void dJointGetDHingeAnchor2(dJointID j, dVector3 result)
{
    DHINGE(j, return);
    dJointGetDBallAnchor2(j, result);
}

dReal dJointGetDHingeDistance(dJointID j)
{
    DHINGE(j, return 0);
    return dJointGetDBallDistance(j);
}

void dJointSetDHingeParam(dJointID j, int parameter, dReal value)
{
    DHINGE(j, return);
    dJointSetDBallParam(j, parameter, value);
}

dReal dJointGetDHingeParam(dJointID j, int parameter)
{
    DHINGE(j, return 0);
    return dJointGetDBallParam(j, parameter);
}
