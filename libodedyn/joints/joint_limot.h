// SPDX-License-Identifier: BSD-3-Clause
//
// joint_limot.h -- the limit and motor of one joint axis (guide 7.5), shared
// by the hinge, slider, universal, hinge-2 and angular motor joints. A motor
// is a velocity constraint with a force limit; a stop is a one-sided position
// constraint with its own ERP and CFM, optionally bouncy.

#ifndef DX_JOINT_LIMOT_H
#define DX_JOINT_LIMOT_H

#include "objects_internal.h"

typedef struct dxLimot {
    dReal vel, fmax;           // motor: target velocity, force limit (0 = off)
    dReal lostop, histop;      // stops (-inf / +inf = none)
    dReal fudge_factor;        // scale of motor force when powering away from a stop
    dReal normal_cfm;          // dParamCFM: CFM of the motor row
    dReal stop_erp, stop_cfm;
    dReal bounce;
    int limit;                 // 0 free, 1 at the low stop, 2 at the high stop
    dReal limit_err;           // how far past the stop (position - stop)
} dxLimot;

// Defaults: no motor, no stops, ERP and CFM from the world.
void dxLimotInit(dxLimot *lm, const struct dxWorld *w);
// Set or get one parameter of the group (param & 0xff, without dParamGroup
// bits). Returns 0 (and reports) if the number is not a limit/motor one.
int dxLimotSetParam(dxLimot *lm, int param, dReal value);
int dxLimotGetParam(const dxLimot *lm, int param, dReal *value);
// Decide whether position (an angle or distance) is at a stop; 1 if it is.
int dxLimotTestLimit(dxLimot *lm, dReal position);
// 1 if the angle 2 atan2(y, x), wrapped into (-pi, pi], is certainly between
// the stops, away from both: dxLimotTestLimit would then find no limit, and
// the caller may set lm->limit = 0 without the angle; 0 if unsure (the
// angle must be measured). Judged without atan2 (docs/perf.md).
int dxLimotAngleClear(const dxLimot *lm, dReal y, dReal x);
// The same for the angle atan2(y, x) itself (not doubled; in (-pi, pi]).
int dxLimotAtan2Clear(const dxLimot *lm, dReal y, dReal x);
// 1 if this axis needs a row this step (after dxLimotTestLimit).
int dxLimotActive(const dxLimot *lm);
// Write the row for this axis at `row`: axis is a world unit vector,
// rotational selects a torque (else a force) row. Returns rows added (0/1).
int dxLimotAddRow(dxLimot *lm, dxJoint *j, dxJointRows *rows, int row, const dReal axis[3],
                  int rotational);
// The rest of such a row once its Jacobian is written (for rows that act
// elsewhere than dxLimotAddRow puts them): motor bounds and velocity, or the
// stop's bounds, correction and bounce (velocity: the row's, J v), and a motor
// powering against its stop pushing along the row's Jacobian.
void dxLimotSetRow(dxLimot *lm, dxJoint *j, dxJointRows *rows, int row, dReal velocity);

// Split a parameter number into group (0..2) and parameter in the group;
// reports and returns 0 if the group exceeds max_groups or the number is not
// a parameter at all.
int dxParamSplit(const char *function, int parameter, int max_groups, int *group, int *param);

#endif
