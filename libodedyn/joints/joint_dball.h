// SPDX-License-Identifier: BSD-3-Clause
//
// joint_dball.h -- the double ball joint's data and distance row, which the
// double hinge joint extends (joint_dball.c, joint_dhinge.c).

#ifndef DX_JOINT_DBALL_H
#define DX_JOINT_DBALL_H

#include "joint_geometry.h"

typedef struct dxJointDBall {
    dxJoint base;
    dVector3 anchor1, anchor2;   // stored body 0 frame; stored body 1 frame (or world)
    dReal erp, cfm;              // of the distance row (dParamERP, dParamCFM)
    dReal distance;              // the distance kept between the anchors
} dxJointDBall;

// Defaults: anchors at the origin, distance 0, ERP and CFM from the world.
void dxDBallInit(dxJoint *j);
// The anchors in world coordinates (stored order).
void dxDBallWorldAnchors(const dxJoint *j, dVector3 p1, dVector3 p2);
// Make the distance the anchors' current distance (after an anchor or the
// bodies changed: dJointSetDBallAnchor*, dJointAttach).
void dxDBallUpdateDistance(dxJoint *j);
// Row 0 of `rows`: the anchors stay at the distance.
void dxDBallDistanceRow(const dxJoint *j, dxJointRows *rows);

// A double ball or double hinge (which is one too, as in ODE).
static inline int dxJointIsDBall(const dxJoint *j)
{
    return dxJointIsLive(j) &&
           (j->cls->type == dJointTypeDBall || j->cls->type == dJointTypeDHinge);
}

#endif
