// SPDX-License-Identifier: BSD-3-Clause
//
// joint_geometry.c -- anchors, axes, ball rows, parallel-axes rows and
// relative angles shared by the joint types (see joint_geometry.h).

#include "joint_geometry.h"

#include <ode/rotation.h>

void dxJointSetAnchors(dxJoint *j, dReal x, dReal y, dReal z, dVector3 anchor1,
                       dVector3 anchor2)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;   // not attached: the guide says setters do nothing
    dVector3 p = { x, y, z, 0 }, r;
    dSubtractVectors3(r, p, b0->pos);
    dMultiply1_331(anchor1, b0->R, r);
    anchor1[3] = 0;
    if (b1) {
        dSubtractVectors3(r, p, b1->pos);
        dMultiply1_331(anchor2, b1->R, r);
    } else {
        dCopyVector3(anchor2, p);
    }
    anchor2[3] = 0;
}

int dxJointSetAxes(dxJoint *j, const char *function, dReal x, dReal y, dReal z, dVector3 axis1,
                   dVector3 axis2)
{
    dVector3 a = { x, y, z, 0 };
    if (!dxIsFinite3(x, y, z) || !dSafeNormalize3(a)) {
        dxReportBadArgument(function, "axis (%g, %g, %g) has no direction", (double)x,
                            (double)y, (double)z);
        return 0;
    }
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 1;
    dMultiply1_331(axis1, b0->R, a);
    axis1[3] = 0;
    if (axis2) {
        if (b1) dMultiply1_331(axis2, b1->R, a);
        else dCopyVector3(axis2, a);
        axis2[3] = 0;
    }
    return 1;
}

void dxJointGetAnchor1(const dxJoint *j, dVector3 result, const dVector3 anchor1)
{
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (!b0) {
        dZeroVector3(result);
        return;
    }
    dMultiply0_331(result, b0->R, anchor1);
    dAddVectors3(result, result, b0->pos);
}

void dxJointGetAnchor2(const dxJoint *j, dVector3 result, const dVector3 anchor2)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (b1) {
        dMultiply0_331(result, b1->R, anchor2);
        dAddVectors3(result, result, b1->pos);
    } else if (b0) {
        dCopyVector3(result, anchor2);
    } else {
        dZeroVector3(result);
    }
}

void dxJointGetAxis1(const dxJoint *j, dVector3 result, const dVector3 axis1)
{
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (b0) dMultiply0_331(result, b0->R, axis1);
    else dCopyVector3(result, axis1);
}

void dxJointGetAxis2(const dxJoint *j, dVector3 result, const dVector3 axis2)
{
    const struct dxBody *b1 = dxJointBody(j, 1);
    if (b1) dMultiply0_331(result, b1->R, axis2);
    else dCopyVector3(result, axis2);
}

void dxJointBallRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 anchor1,
                     const dVector3 anchor2, dReal erp)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int s = rows->rowskip, r0 = row * s;
    dVector3 a1, a2, p1, p2;
    // Velocity of the anchor on body 0: v0 + w0 x a1 = v0 - a1 x w0.
    dMultiply0_331(a1, b0->R, anchor1);
    dAddVectors3(p1, b0->pos, a1);
    for (int k = 0; k < 3; k++) rows->J1l[r0 + k * s + k] = 1;
    dSetCrossMatrixMinus(rows->J1a + r0, a1, (unsigned)s);
    if (b1) {
        dMultiply0_331(a2, b1->R, anchor2);
        dAddVectors3(p2, b1->pos, a2);
        for (int k = 0; k < 3; k++) rows->J2l[r0 + k * s + k] = -1;
        dSetCrossMatrixPlus(rows->J2a + r0, a2, (unsigned)s);
    } else {
        dCopyVector3(p2, anchor2);
    }
    const dReal k = rows->fps * erp;
    for (int i = 0; i < 3; i++) rows->c[row + i] = k * (p2[i] - p1[i]);
}

void dxJointParallelAxesRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 ax1,
                             const dVector3 ax2, dReal erp)
{
    const int s = rows->rowskip;
    dVector3 p, q, err;
    dPlaneSpace(ax1, p, q);
    dCopyVector3(rows->J1a + row * s, p);
    dCopyVector3(rows->J1a + (row + 1) * s, q);
    if (dxJointBody(j, 1)) {
        dCopyNegatedVector3(rows->J2a + row * s, p);
        dCopyNegatedVector3(rows->J2a + (row + 1) * s, q);
    }
    // ax1 x ax2 is the rotation vector (small angles) that would bring ax1
    // onto ax2: body 0 must turn that way.
    dCalcVectorCross3(err, ax1, ax2);
    const dReal k = rows->fps * erp;
    rows->c[row] = k * dCalcVectorDot3(err, p);
    rows->c[row + 1] = k * dCalcVectorDot3(err, q);
}

void dxJointRelativeQuaternion(const dxJoint *j, dQuaternion qrel)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) {
        dQSetIdentity(qrel);
        return;
    }
    if (b1) {
        dQMultiply1(qrel, b0->q, b1->q);
    } else {
        dQuaternion identity = { 1, 0, 0, 0 };
        dQMultiply1(qrel, b0->q, identity);
    }
}

void dxJointRelativeHalfAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0,
                              dReal *y, dReal *x)
{
    dQuaternion now, delta;
    dxJointRelativeQuaternion(j, now);
    dQMultiply2(delta, now, qrel0);   // change of body 1 relative to body 0 since then
    // delta = (cos(phi/2), sin(phi/2) u): body 1 turned by phi about u (body 0
    // frame); project on the axis (dxJointRelativeAngleOf measures body 0
    // against body 1, -phi).
    *y = dCalcVectorDot3(delta + 1, axis);
    *x = delta[0];
}

dReal dxJointRelativeAngleOf(dReal y, dReal x)
{
    dReal phi = 2 * dAtan2(y, x);
    if (phi > M_PI) phi -= 2 * M_PI;
    if (phi <= -M_PI) phi += 2 * M_PI;
    return -phi;
}

dReal dxJointRelativeAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0)
{
    dReal y, x;
    dxJointRelativeHalfAngle(j, axis, qrel0, &y, &x);
    return dxJointRelativeAngleOf(y, x);
}

dReal dxJointRelativeAngleRate(const dxJoint *j, const dVector3 axis_world)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 0;
    dReal rate = dCalcVectorDot3(axis_world, b0->avel);
    if (b1) rate -= dCalcVectorDot3(axis_world, b1->avel);
    return rate;
}
