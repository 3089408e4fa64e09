// SPDX-License-Identifier: BSD-3-Clause
//
// joint_fixed.h -- the rows that lock the relative orientation of a joint's
// bodies, shared by the fixed and slider joints.

#ifndef DX_JOINT_FIXED_H
#define DX_JOINT_FIXED_H

#include "objects_internal.h"

// Three rows at `row` that stop all relative rotation and steer the relative
// orientation back to qrel0 (as kept by dxJointRelativeQuaternion).
void dxJointOrientationRows(const dxJoint *j, dxJointRows *rows, int row, const dQuaternion qrel0,
                            dReal erp);

#endif
