// SPDX-License-Identifier: BSD-3-Clause
//
// joint_kept.h -- values joints keep that no public getter reports, for
// dWorldExportDIF (io/export_dif.c), which writes them as ODE does. Each is
// defined in its joint's file.

#ifndef DX_JOINT_KEPT_H
#define DX_JOINT_KEPT_H

#include "objects_internal.h"

#include <ode/contact.h>

// The dContact a contact joint was made from, as dJointCreateContact kept it
// (its out-of-range surface numbers replaced, as reported then): its point,
// normal, depth, surface mode and mu, the surface numbers its mode uses and
// fdir1 with dContactFDir1 (the rest is not kept: geom.g1, g2, side1, side2
// are not set); NULL if j is not a contact joint.
const dContact *dxJointContactGet(const dxJoint *j);

// The rel dJointSetLMotorAxis was given for axis anum (0..2): 0 world, 1 the
// user's body 1, 2 body 2; 0 for an axis never set or another joint type.
int dxJointLMotorAxisRel(const dxJoint *j, int anum);

// The rest orientations (relative orientation at zero angle) of the hinge,
// PR and piston joints, and the PU joint's two (each body against the cross of the
// axes), as kept. Only a quaternion's rotation follows from the angle
// getters, not its sign, which ODE's file shows. Left unchanged for another
// joint type.
void dxJointHingeRest(const dxJoint *j, dQuaternion qrel);
void dxJointPRRest(const dxJoint *j, dQuaternion qrel);
void dxJointPistonRest(const dxJoint *j, dQuaternion qrel);
void dxJointPURest(const dxJoint *j, dQuaternion qrel1, dQuaternion qrel2);

#endif
