// SPDX-License-Identifier: BSD-3-Clause
//
// joint_slide.h -- what the prismatic-rotoide (PR) and piston joints share
// (ODE 0.16): a point of body 0 (an offset in its frame) that may only slide
// along a line through an anchor on body 1 (or fixed in the world), the rows
// that keep it on the line, the rows that leave one relative rotation free,
// the slide position, and ODE's hinge angle (also used by the PU joint).

#ifndef DX_JOINT_SLIDE_H
#define DX_JOINT_SLIDE_H

#include "objects_internal.h"

// The world vectors the slide rows are made of, from offset1 (body 0 frame:
// body 0's point, relative to its centre) and anchor2 (body 1 frame, or world
// without body 1).
typedef struct dxSlideFrame {
    dVector3 dist;    // anchor2 (world) - centre of body 0
    dVector3 rel2;    // anchor2 (world) - centre of body 1; zero without body 1
    dVector3 err;     // anchor2 (world) - body 0's point: its distance off the line
} dxSlideFrame;

void dxJointSlideFrame(const dxJoint *j, const dVector3 offset1, const dVector3 anchor2,
                       dxSlideFrame *f);

// Two rows at `row` stopping the relative motion of body 0's point at the
// anchor along directions u0 and u1 (world, across the slide axis), steering
// the error f->err back to the line.
void dxJointSlideLineRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 u0,
                          const dVector3 u1, const dxSlideFrame *f);

// Two rows at `row` stopping relative rotation about u0 and u1 (world);
// misalign is ax1 x ax2, the rotation (small angles) that would bring body
// 0's free axis onto body 1's.
void dxJointTwistRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 u0,
                      const dVector3 u1, const dVector3 misalign);

// ODE's hinge angle of a relative rotation q (-pi..pi): the whole rotation
// angle of q, signed by the side of the axis its rotation vector lies on,
// negated. Unlike dxJointRelativeAngle it counts turns about other axes too.
dReal dxQuaternionHingeAngle(const dQuaternion q, const dVector3 axis);
// That angle for the change of body 0 against body 1 (or the world) since
// their relative orientation was qrel0 (dxJointRelativeQuaternion); axis in
// body 0's frame. The PR and piston joints measure their rotation with it.
dReal dxJointHingeAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0);

// The slide position as ODE 0.16 defines it: axis (world) . (body 0's point -
// anchor2), negated when the joint was attached as (0, b).
dReal dxJointSlidePosition(const dxJoint *j, const dVector3 offset1, const dVector3 anchor2,
                           const dVector3 axis);

#endif
