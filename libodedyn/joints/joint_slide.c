// SPDX-License-Identifier: BSD-3-Clause
//
// joint_slide.c -- the slide rows and position shared by the PR and piston
// joints (see joint_slide.h).

#include "joint_slide.h"

#include "joint_geometry.h"

#include <ode/rotation.h>

void dxJointSlideFrame(const dxJoint *j, const dVector3 offset1, const dVector3 anchor2,
                       dxSlideFrame *f)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    dVector3 a2, o1;
    if (b1) {
        dMultiply0_331(f->rel2, b1->R, anchor2);
        dAddVectors3(a2, b1->pos, f->rel2);
    } else {
        dZeroVector3(f->rel2);
        dCopyVector3(a2, anchor2);
    }
    dSubtractVectors3(f->dist, a2, b0->pos);
    dMultiply0_331(o1, b0->R, offset1);
    dSubtractVectors3(f->err, f->dist, o1);
}

// Each row is the velocity, along u, of body 0's material point at the anchor
// against body 1's: u . (v0 + w0 x dist) - u . (v1 + w1 x rel2).
void dxJointSlideLineRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 u0,
                          const dVector3 u1, const dxSlideFrame *f)
{
    const int s = rows->rowskip;
    const int has_b1 = dxJointBody(j, 1) != NULL;
    const dReal k = rows->fps * rows->erp;
    const dReal *u[2] = { u0, u1 };
    for (int i = 0; i < 2; i++) {
        const int r = (row + i) * s;
        dCopyVector3(rows->J1l + r, u[i]);
        dCalcVectorCross3(rows->J1a + r, f->dist, u[i]);
        if (has_b1) {
            dCopyNegatedVector3(rows->J2l + r, u[i]);
            dCalcVectorCross3(rows->J2a + r, u[i], f->rel2);
        }
        rows->c[row + i] = k * dCalcVectorDot3(u[i], f->err);
    }
}

void dxJointTwistRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 u0,
                      const dVector3 u1, const dVector3 misalign)
{
    const int s = rows->rowskip;
    const int has_b1 = dxJointBody(j, 1) != NULL;
    const dReal k = rows->fps * rows->erp;
    const dReal *u[2] = { u0, u1 };
    for (int i = 0; i < 2; i++) {
        dCopyVector3(rows->J1a + (row + i) * s, u[i]);
        if (has_b1) dCopyNegatedVector3(rows->J2a + (row + i) * s, u[i]);
        rows->c[row + i] = k * dCalcVectorDot3(misalign, u[i]);
    }
}

dReal dxJointSlidePosition(const dxJoint *j, const dVector3 offset1, const dVector3 anchor2,
                           const dVector3 axis)
{
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (!b0) return 0;
    dxSlideFrame f;
    dxJointSlideFrame(j, offset1, anchor2, &f);
    // err = anchor - point; the position is (point - anchor) . axis.
    const dReal pos = -dCalcVectorDot3(axis, f.err);
    return (j->flags & DX_JOINT_REVERSE) ? -pos : pos;
}

dReal dxQuaternionHingeAngle(const dQuaternion q, const dVector3 axis)
{
    const dReal s = dCalcVectorLength3(q + 1);
    dReal theta = 2 * dAtan2(s, dCalcVectorDot3(q + 1, axis) >= 0 ? q[0] : -q[0]);
    if (theta > M_PI) theta -= 2 * M_PI;
    return -theta;
}

dReal dxJointHingeAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0)
{
    dQuaternion now, change;
    dxJointRelativeQuaternion(j, now);
    dQMultiply2(change, now, qrel0);
    return dxQuaternionHingeAngle(change, axis);
}
