// SPDX-License-Identifier: BSD-3-Clause
//
// joint_geometry.h -- helpers the joint types share: anchors and axes kept in
// body frames (so they move with the bodies), the ball-and-socket rows, the
// rows that keep two axes parallel, and relative angles.

#ifndef DX_JOINT_GEOMETRY_H
#define DX_JOINT_GEOMETRY_H

#include "joint_limot.h"
#include "objects_internal.h"

#include <ode/rotation.h>

// Store world point p as anchor1 (body 0 frame) and anchor2 (body 1 frame,
// or world if body 1 is the static world).
void dxJointSetAnchors(dxJoint *j, dReal x, dReal y, dReal z, dVector3 anchor1,
                       dVector3 anchor2);
// Store world direction (x,y,z), normalised, as axis1 (body 0 frame) and
// axis2 (body 1 frame or world). Reports a zero axis and returns 0.
int dxJointSetAxes(dxJoint *j, const char *function, dReal x, dReal y, dReal z, dVector3 axis1,
                   dVector3 axis2);
// World position of anchor1 / anchor2, and world direction of axis1 / axis2.
void dxJointGetAnchor1(const dxJoint *j, dVector3 result, const dVector3 anchor1);
void dxJointGetAnchor2(const dxJoint *j, dVector3 result, const dVector3 anchor2);
void dxJointGetAxis1(const dxJoint *j, dVector3 result, const dVector3 axis1);
void dxJointGetAxis2(const dxJoint *j, dVector3 result, const dVector3 axis2);

// Rows 0..2 of `rows` (from `row`): the anchors coincide (erp: row ERP).
void dxJointBallRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 anchor1,
                     const dVector3 anchor2, dReal erp);
// Two rows at `row` that stop relative rotation about the two directions
// perpendicular to world axis ax1; err is ax1 x ax2 (the misalignment).
void dxJointParallelAxesRows(const dxJoint *j, dxJointRows *rows, int row, const dVector3 ax1,
                             const dVector3 ax2, dReal erp);

// The relative orientation of the bodies now, to compare with later:
// conj(q0) q1 (or conj(q0) without body 1).
void dxJointRelativeQuaternion(const dxJoint *j, dQuaternion qrel);
// The rotation angle (-pi..pi) of body 0 relative to body 1 about axis
// (body 0 frame, unit) since the relative orientation was qrel0.
dReal dxJointRelativeAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0);
// That angle as two numbers y, x: the angle is -2 atan2(y, x), wrapped into
// (-pi, pi] (dxJointRelativeAngleOf), which a limit test may not need
// (dxLimotAngleClear takes -y, x).
void dxJointRelativeHalfAngle(const dxJoint *j, const dVector3 axis, const dQuaternion qrel0,
                              dReal *y, dReal *x);
dReal dxJointRelativeAngleOf(dReal y, dReal x);
// Rate of that angle: axis (world) . (w0 - w1).
dReal dxJointRelativeAngleRate(const dxJoint *j, const dVector3 axis_world);

// Report a joint of the wrong type; on_fail runs if the handler returns.
#define DX_CHECK_JOINT_TYPE(j, t, on_fail) \
    do { \
        DX_CHECK_ARG(dxJointIsLive(j), on_fail, "joint is NULL or was destroyed"); \
        DX_CHECK_ARG((j)->cls->type == (t), on_fail, "joint is a %s joint, not the right type", \
                     (j)->cls->name); \
    } while (0)

#endif
