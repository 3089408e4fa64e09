// SPDX-License-Identifier: BSD-3-Clause
//
// joint_piston.c -- the piston joint (ODE 0.16): the bodies may slide along,
// and turn about, one axis through the anchor. Four rows: two stop relative
// rotation across the axis, two keep body 1's anchor on the line of body 2's;
// a limit/motor row for the slide (parameter group 1) and one for the
// rotation (group 2).
//
// As in ODE, position, angle and rates are measured body 1 against body 2;
// attached as (0, b) they change sign but the axis does not, and the
// rotation's stops and motor act in the stored sense (body b against the
// world), as ODE's do.

#include "joint_geometry.h"
#include "joint_kept.h"
#include "joint_slide.h"

typedef struct dxJointPiston {
    dxJoint base;
    dVector3 anchor1, anchor2;   // body 0 frame; body 1 frame or world
    dVector3 axis1, axis2;       // body 0 frame; body 1 frame or world
    dQuaternion qrel;            // relative orientation at zero angle
    dxLimot limot_p, limot_r;
} dxJointPiston;

static void piston_init(dxJoint *j)
{
    dxJointPiston *p = (dxJointPiston *)j;
    p->axis1[0] = 1;
    p->axis2[0] = 1;
    dQSetIdentity(p->qrel);
    dxLimotInit(&p->limot_p, j->world);
    dxLimotInit(&p->limot_r, j->world);
}

static dReal piston_position(const dxJoint *j)
{
    const dxJointPiston *p = (const dxJointPiston *)j;
    dVector3 ax;
    dxJointGetAxis1(j, ax, p->axis1);
    return dxJointSlidePosition(j, p->anchor1, p->anchor2, ax);
}

static int has_stops(const dxLimot *lm)
{
    return (lm->lostop > -dInfinity || lm->histop < dInfinity) && lm->lostop <= lm->histop;
}

static void piston_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointPiston *p = (dxJointPiston *)j;
    count->m = 4;
    count->nub = 4;
    p->limot_p.limit = 0;
    if (has_stops(&p->limot_p)) dxLimotTestLimit(&p->limot_p, piston_position(j));
    if (dxLimotActive(&p->limot_p)) count->m++;
    p->limot_r.limit = 0;
    if (has_stops(&p->limot_r))
        dxLimotTestLimit(&p->limot_r, dxJointHingeAngle(j, p->axis1, p->qrel));
    if (dxLimotActive(&p->limot_r)) count->m++;
}

static void piston_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointPiston *p = (dxJointPiston *)j;
    dVector3 ax1, ax2, u, v, misalign;
    dxJointGetAxis1(j, ax1, p->axis1);
    dxJointGetAxis2(j, ax2, p->axis2);
    dPlaneSpace(ax1, u, v);

    dCalcVectorCross3(misalign, ax1, ax2);
    dxJointTwistRows(j, rows, 0, u, v, misalign);

    dxSlideFrame f;
    dxJointSlideFrame(j, p->anchor1, p->anchor2, &f);
    dxJointSlideLineRows(j, rows, 2, u, v, &f);

    // The position changes sign when reversed: so does the slide row's axis.
    dVector3 axp;
    dCopyVector3(axp, ax1);
    if (j->flags & DX_JOINT_REVERSE) dNegateVector3(axp);
    int row = 4 + dxLimotAddRow(&p->limot_p, j, rows, 4, axp, 0);
    dxLimotAddRow(&p->limot_r, j, rows, row, ax1, 1);
}

// Recompute the body-relative values after dJointAttach from the world
// anchor and axis the getters report (ODE's setRelativeValues).
static void piston_attached(dxJoint *j)
{
    dxJointPiston *p = (dxJointPiston *)j;
    dVector3 anchor, axis;
    dJointGetPistonAnchor(j, anchor);
    dJointGetPistonAxis(j, axis);
    dxJointSetAnchors(j, anchor[0], anchor[1], anchor[2], p->anchor1, p->anchor2);
    dxJointSetAxes(j, "dJointAttach", axis[0], axis[1], axis[2], p->axis1, p->axis2);
    dxJointRelativeQuaternion(j, p->qrel);
}

void dxJointPistonRest(const dxJoint *j, dQuaternion qrel)
{
    if (j->cls->type == dJointTypePiston) dCopyVector4(qrel, ((const dxJointPiston *)j)->qrel);
}

static const dxJointClass piston_class = {
    dJointTypePiston, "piston", sizeof(dxJointPiston), piston_init, piston_count_rows,
    piston_fill_rows, piston_attached
};

dJointID dJointCreatePiston(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &piston_class);
}

#define PISTON(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypePiston, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

void dJointSetPistonAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    PISTON(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointPiston *p = (dxJointPiston *)j;
    dxJointSetAnchors(j, x, y, z, p->anchor1, p->anchor2);
    dxJointRelativeQuaternion(j, p->qrel);
}

// The anchor at (x,y,z), with body 1 taken as displaced by -delta at zero
// position, so the position is now axis . delta (ODE 0.16's meaning; the
// delta is the user's, body 1 against body 2, also when reversed).
void dJointSetPistonAnchorOffset(dJointID j, dReal x, dReal y, dReal z, dReal dx, dReal dy,
                                 dReal dz)
{
    PISTON(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dxIsFinite3(dx, dy, dz), return,
                 "anchor or offset is not finite");
    dxJointPiston *p = (dxJointPiston *)j;
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (!b0) return;
    const dReal sign = (j->flags & DX_JOINT_REVERSE) ? -1 : 1;
    dxJointSetAnchors(j, x, y, z, p->anchor1, p->anchor2);
    // anchor1 as if body 0 were at pos - delta: R0^T (x - pos + delta).
    const dVector3 d = { sign * dx, sign * dy, sign * dz, 0 };
    dVector3 shift;
    dMultiply1_331(shift, b0->R, d);
    dAddVectors3(p->anchor1, p->anchor1, shift);
    dxJointRelativeQuaternion(j, p->qrel);
}

void dJointSetPistonAxis(dJointID j, dReal x, dReal y, dReal z)
{
    PISTON(j, return);
    dxJointPiston *p = (dxJointPiston *)j;
    if (!dxJointSetAxes(j, __func__, x, y, z, p->axis1, p->axis2)) return;
    dxJointRelativeQuaternion(j, p->qrel);
}

// ODE 0.16's deprecated form: the axis, and body 0's anchor put at the
// separation of the centres minus delta (body 0's frame), so the position
// reads as if body 0 were displaced by delta from the anchor on body 1.
void dJointSetPistonAxisDelta(dJointID j, dReal x, dReal y, dReal z, dReal ax, dReal ay,
                              dReal az)
{
    PISTON(j, return);
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az), return, "delta is not finite");
    dxJointPiston *p = (dxJointPiston *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!dxJointSetAxes(j, __func__, x, y, z, p->axis1, p->axis2) || !b0) return;
    dxJointRelativeQuaternion(j, p->qrel);
    const dVector3 delta = { ax, ay, az, 0 };
    dVector3 c;
    dSubtractVectors3(c, b0->pos, delta);
    if (b1) dSubtractVectors3(c, c, b1->pos);
    dMultiply1_331(p->anchor1, b0->R, c);
    p->anchor1[3] = 0;
}

void dJointSetPistonParam(dJointID j, int parameter, dReal value)
{
    PISTON(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    dxJointPiston *p = (dxJointPiston *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return;
    dxLimotSetParam(group ? &p->limot_r : &p->limot_p, param, value);
}

dReal dJointGetPistonParam(dJointID j, int parameter)
{
    PISTON(j, return 0);
    dxJointPiston *p = (dxJointPiston *)j;
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return 0;
    dxLimotGetParam(group ? &p->limot_r : &p->limot_p, param, &value);
    return value;
}

void dJointGetPistonAnchor(dJointID j, dVector3 result)
{
    PISTON(j, return);
    CHECK_RESULT(result, return);
    dxJointPiston *p = (dxJointPiston *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor2(j, result, p->anchor2);
    else dxJointGetAnchor1(j, result, p->anchor1);
}

void dJointGetPistonAnchor2(dJointID j, dVector3 result)
{
    PISTON(j, return);
    CHECK_RESULT(result, return);
    dxJointPiston *p = (dxJointPiston *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor1(j, result, p->anchor1);
    else dxJointGetAnchor2(j, result, p->anchor2);
}

void dJointGetPistonAxis(dJointID j, dVector3 result)
{
    PISTON(j, return);
    CHECK_RESULT(result, return);
    dxJointGetAxis1(j, result, ((dxJointPiston *)j)->axis1);
}

dReal dJointGetPistonPosition(dJointID j)
{
    PISTON(j, return 0);
    return piston_position(j);
}

// axis . (v0 - v1): turning about the axis moves nothing along it.
dReal dJointGetPistonPositionRate(dJointID j)
{
    PISTON(j, return 0);
    dxJointPiston *p = (dxJointPiston *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 0;
    dVector3 ax;
    dxJointGetAxis1(j, ax, p->axis1);
    dReal rate = dCalcVectorDot3(ax, b0->lvel);
    if (b1) return rate - dCalcVectorDot3(ax, b1->lvel);
    return (j->flags & DX_JOINT_REVERSE) ? -rate : rate;
}

dReal dJointGetPistonAngle(dJointID j)
{
    PISTON(j, return 0);
    dxJointPiston *p = (dxJointPiston *)j;
    if (!dxJointBody(j, 0)) return 0;
    const dReal angle = dxJointHingeAngle(j, p->axis1, p->qrel);
    return (j->flags & DX_JOINT_REVERSE) ? -angle : angle;
}

dReal dJointGetPistonAngleRate(dJointID j)
{
    PISTON(j, return 0);
    dxJointPiston *p = (dxJointPiston *)j;
    if (!dxJointBody(j, 0)) return 0;
    dVector3 ax;
    dxJointGetAxis1(j, ax, p->axis1);
    const dReal rate = dxJointRelativeAngleRate(j, ax);
    return (j->flags & DX_JOINT_REVERSE) ? -rate : rate;
}

// force along the axis on body 1, the opposite on body 2, both acting at the
// anchor: each body also gets the couple (anchor - centre) x its force.
// Attached as (0, b) the force on b is -force along the axis, keeping the
// sense of dJointGetPistonPosition (ODE 0.16 applies no force at all then).
void dJointAddPistonForce(dJointID j, dReal force)
{
    PISTON(j, return);
    DX_CHECK_ARG(dxIsFinite(force), return, "force is not finite");
    dxJointPiston *p = (dxJointPiston *)j;
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;
    if (j->flags & DX_JOINT_REVERSE) force = -force;
    dVector3 f, r, t;
    dxJointGetAxis1(j, f, p->axis1);
    dScaleVector3(f, force);
    dAddVectors3(b0->force, b0->force, f);
    if (!b1) return;
    dSubtractVectors3(b1->force, b1->force, f);
    dMultiply0_331(r, b0->R, p->anchor1);
    dCalcVectorCross3(t, r, f);
    dAddVectors3(b0->torque, b0->torque, t);
    dMultiply0_331(r, b1->R, p->anchor2);
    dCalcVectorCross3(t, r, f);
    dSubtractVectors3(b1->torque, b1->torque, t);
}
