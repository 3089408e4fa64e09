// SPDX-License-Identifier: BSD-3-Clause
//
// joint_pu.c -- the prismatic-universal joint (ODE 0.16): body 1 slides
// along axis P (fixed in body 1) and a universal joint (axis 1 on the
// slider, axis 2 on body 2) sits at the anchor. Three rows: one keeps axes
// 1 and 2 perpendicular, two keep the anchors of both bodies on the line
// along P; limit/motor rows for axis 1 (dParamX), axis 2 (dParamX2) and the
// slide (dParamX3).
//
// Storage follows ODE: anchor1 and axis1 in body 0's frame, anchor2 and axis2
// in body 1's (or the world); attached as (0, b) the user's axis 1 is stored
// as axis2 and axis 2 as axis1, the getters swap them back, and the angle
// stops and motors (dParamX on the stored axis 1) are not swapped, as ODE's.
// Axis P belongs to the user's first body: attached as (0, b) it is kept in
// world coordinates (ODE keeps it in b's frame but uses it as a world axis in
// the constraint rows, which agree while b is not turned).

#include "joint_geometry.h"
#include "joint_kept.h"
#include "joint_slide.h"

typedef struct dxJointPU {
    dxJoint base;
    dVector3 anchor1, anchor2;   // body 0 frame; body 1 frame or world
    dVector3 axis1, axis2;       // universal axes: body 0 frame; body 1 frame or world
    dVector3 axis_p;             // slide axis: body 0 frame (reversed: world)
    dQuaternion qrel1, qrel2;    // each body against the cross at zero angles
    dxLimot limot1, limot2, limot_p;
} dxJointPU;

static int reversed(const dxJoint *j) { return (j->flags & DX_JOINT_REVERSE) != 0; }

static void pu_init(dxJoint *j)
{
    dxJointPU *pu = (dxJointPU *)j;
    pu->axis1[1] = 1;
    pu->axis2[2] = 1;
    pu->axis_p[0] = 1;
    dQSetIdentity(pu->qrel1);
    dQSetIdentity(pu->qrel2);
    dxLimotInit(&pu->limot1, j->world);
    dxLimotInit(&pu->limot2, j->world);
    dxLimotInit(&pu->limot_p, j->world);
}

// The world axes: universal axis 1 (stored), axis 2 (stored), and P.
static void world_axes(const dxJointPU *pu, dVector3 ax1, dVector3 ax2, dVector3 axp)
{
    const dxJoint *j = &pu->base;
    if (ax1) dxJointGetAxis1(j, ax1, pu->axis1);
    if (ax2) dxJointGetAxis2(j, ax2, pu->axis2);
    if (axp) {
        if (reversed(j)) dxJointGetAxis2(j, axp, pu->axis_p);
        else dxJointGetAxis1(j, axp, pu->axis_p);
    }
}

// The orientation of the cross as a quaternion: its first axis along a, its
// second along b made perpendicular (as dRFrom2Axes builds it), any
// perpendicular while the axes are parallel (only while they are being set).
static void cross_quaternion(const dVector3 a, const dVector3 b, dQuaternion q)
{
    dVector3 u, v, w;
    dCopyVector3(u, a);
    dSafeNormalize3(u);   // unit already, up to rounding
    dAddScaledVectors3(v, b, u, 1, -dCalcVectorDot3(b, u));
    if (!dSafeNormalize3(v)) dPlaneSpace(u, v, w);
    dCalcVectorCross3(w, u, v);
    dMatrix3 R;
    for (int i = 0; i < 3; i++) {
        R[i * 4 + 0] = u[i];
        R[i * 4 + 1] = v[i];
        R[i * 4 + 2] = w[i];
        R[i * 4 + 3] = 0;
    }
    dQfromR(q, R);
}

// Body 0 (or body 1, or the world) against the cross now, times the inverse
// of the same at zero angles: the turn about the axis on that body.
static void compute_rest_rotations(dxJointPU *pu)
{
    const struct dxBody *b0 = dxJointBody(&pu->base, 0), *b1 = dxJointBody(&pu->base, 1);
    if (!b0) return;
    dVector3 ax1, ax2;
    dQuaternion qc;
    world_axes(pu, ax1, ax2, NULL);
    cross_quaternion(ax1, ax2, qc);
    dQMultiply1(pu->qrel1, b0->q, qc);
    cross_quaternion(ax2, ax1, qc);
    if (b1) dQMultiply1(pu->qrel2, b1->q, qc);
    else dCopyVector4(pu->qrel2, qc);
}

// The angles about the stored axes 1 and 2 (ODE's universal joint angles).
static void stored_angles(const dxJointPU *pu, dReal *angle1, dReal *angle2)
{
    const struct dxBody *b0 = dxJointBody(&pu->base, 0), *b1 = dxJointBody(&pu->base, 1);
    *angle1 = *angle2 = 0;
    if (!b0) return;
    dVector3 ax1, ax2;
    dQuaternion qc, qq, qrel;
    world_axes(pu, ax1, ax2, NULL);
    cross_quaternion(ax1, ax2, qc);
    dQMultiply1(qq, b0->q, qc);
    dQMultiply2(qrel, qq, pu->qrel1);
    *angle1 = dxQuaternionHingeAngle(qrel, pu->axis1);
    cross_quaternion(ax2, ax1, qc);
    if (b1) dQMultiply1(qq, b1->q, qc);
    else dCopyVector4(qq, qc);
    dQMultiply2(qrel, qq, pu->qrel2);
    *angle2 = -dxQuaternionHingeAngle(qrel, pu->axis2);
}

// The anchors in world coordinates.
static void world_anchors(const dxJointPU *pu, dVector3 an1, dVector3 an2)
{
    dxJointGetAnchor1(&pu->base, an1, pu->anchor1);
    dxJointGetAnchor2(&pu->base, an2, pu->anchor2);
}

// The slide position: axis P . (anchor on body 1 - anchor on body 2), negated
// when reversed (body 1 is then the world).
static dReal pu_position(const dxJointPU *pu)
{
    if (!dxJointBody(&pu->base, 0)) return 0;
    dVector3 an1, an2, axp, d;
    world_anchors(pu, an1, an2);
    world_axes(pu, NULL, NULL, axp);
    dSubtractVectors3(d, an1, an2);
    const dReal pos = dCalcVectorDot3(axp, d);
    return reversed(&pu->base) ? -pos : pos;
}

static int has_stops(const dxLimot *lm, dReal range)
{
    return (lm->lostop >= -range || lm->histop <= range) && lm->lostop <= lm->histop;
}

static void pu_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointPU *pu = (dxJointPU *)j;
    count->m = 3;
    count->nub = 3;
    // ODE's conditions: the slide's stops count when one is finite, the
    // angles' when one is within -pi..pi.
    pu->limot_p.limit = 0;
    if ((pu->limot_p.lostop > -dInfinity || pu->limot_p.histop < dInfinity) &&
        pu->limot_p.lostop <= pu->limot_p.histop)
        dxLimotTestLimit(&pu->limot_p, pu_position(pu));
    if (dxLimotActive(&pu->limot_p)) count->m++;
    const int stops1 = has_stops(&pu->limot1, M_PI), stops2 = has_stops(&pu->limot2, M_PI);
    pu->limot1.limit = pu->limot2.limit = 0;
    if (stops1 || stops2) {
        dReal angle1, angle2;
        stored_angles(pu, &angle1, &angle2);
        if (stops1) dxLimotTestLimit(&pu->limot1, angle1);
        if (stops2) dxLimotTestLimit(&pu->limot2, angle2);
    }
    if (dxLimotActive(&pu->limot1)) count->m++;
    if (dxLimotActive(&pu->limot2)) count->m++;
}

// The slide's limit/motor row at `row`, acting at the anchors: along axis
// (world) on body 0's anchor (pt1 from its centre) against body 1's (pt2).
// Returns the rows added (0 or 1).
static int slide_limot_row(dxLimot *lm, dxJoint *j, dxJointRows *rows, int row,
                           const dVector3 axis, const dVector3 pt1, const dVector3 pt2)
{
    if (!dxLimotActive(lm)) return 0;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int s = row * rows->rowskip;
    dCopyVector3(rows->J1l + s, axis);
    dCalcVectorCross3(rows->J1a + s, pt1, axis);
    if (b1) {
        dCopyNegatedVector3(rows->J2l + s, axis);
        dCalcVectorCross3(rows->J2a + s, pt2, rows->J2l + s);
    }
    dReal v = 0;   // the row's velocity J v, for a bounce
    if (lm->limit && lm->bounce > 0) {
        v = dCalcVectorDot3(b0->lvel, rows->J1l + s) + dCalcVectorDot3(b0->avel, rows->J1a + s);
        if (b1)
            v += dCalcVectorDot3(b1->lvel, rows->J2l + s) + dCalcVectorDot3(b1->avel, rows->J2a + s);
    }
    dxLimotSetRow(lm, j, rows, row, v);
    return 1;
}

static void pu_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointPU *pu = (dxJointPU *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int s = rows->rowskip;
    const dReal k = rows->fps * rows->erp;
    dVector3 ax1, ax2, axp, perp, other;
    world_axes(pu, ax1, ax2, axp);

    // Row 0: d/dt (ax1 . ax2) = (ax1 x ax2) . (w0 - w1); drive ax1 . ax2 to 0.
    dCalcVectorCross3(perp, ax1, ax2);
    if (!dSafeNormalize3(perp)) dPlaneSpace(ax1, perp, other);
    dCopyVector3(rows->J1a, perp);
    if (b1) dCopyNegatedVector3(rows->J2a, perp);
    rows->c[0] = -k * dCalcVectorDot3(ax1, ax2);

    // Rows 1, 2: the anchors meet across axis P (velocities of each body's
    // anchor point along p and q).
    dVector3 an1, an2, sep, pt1, pt2 = { 0, 0, 0, 0 }, u[2];
    world_anchors(pu, an1, an2);
    dSubtractVectors3(sep, an2, an1);
    dSubtractVectors3(pt1, an1, b0->pos);
    if (b1) dSubtractVectors3(pt2, an2, b1->pos);
    dPlaneSpace(axp, u[0], u[1]);
    for (int i = 0; i < 2; i++) {
        const int r = (1 + i) * s;
        dCopyVector3(rows->J1l + r, u[i]);
        dCalcVectorCross3(rows->J1a + r, pt1, u[i]);
        if (b1) {
            dCopyNegatedVector3(rows->J2l + r, u[i]);
            dCalcVectorCross3(rows->J2a + r, u[i], pt2);
        }
        rows->c[1 + i] = k * dCalcVectorDot3(u[i], sep);
    }

    int row = 3;
    row += dxLimotAddRow(&pu->limot1, j, rows, row, ax1, 1);
    row += dxLimotAddRow(&pu->limot2, j, rows, row, ax2, 1);
    // The position changes sign when reversed: so does the slide row's axis.
    if (reversed(j)) dNegateVector3(axp);
    slide_limot_row(&pu->limot_p, j, rows, row, axp, pt1, pt2);
}

// Store world direction (x,y,z) in body 0's frame (slot 0) or in body 1's
// frame or the world (slot 1). Returns 0 if it was reported.
static int store_axis(dxJoint *j, const char *function, int slot, dReal x, dReal y, dReal z,
                      dVector3 axis)
{
    dVector3 unused;
    return slot == 0 ? dxJointSetAxes(j, function, x, y, z, axis, NULL)
                     : dxJointSetAxes(j, function, x, y, z, unused, axis);
}

// Set the user's axis k (0, 1: universal axes 1, 2; 2: axis P) to world
// direction (x,y,z), then take the current angles as zero.
static void set_user_axis(dxJoint *j, const char *function, int k, dReal x, dReal y, dReal z)
{
    dxJointPU *pu = (dxJointPU *)j;
    const int rev = reversed(j);
    int ok;
    if (k == 2) ok = store_axis(j, function, rev, x, y, z, pu->axis_p);
    else if ((k == 0) != rev) ok = store_axis(j, function, 0, x, y, z, pu->axis1);
    else ok = store_axis(j, function, 1, x, y, z, pu->axis2);
    if (ok) compute_rest_rotations(pu);
}

// Recompute the body-relative values after dJointAttach from the world
// anchor and axes the getters report (ODE's setRelativeValues).
static void pu_attached(dxJoint *j)
{
    dxJointPU *pu = (dxJointPU *)j;
    dVector3 anchor, ax[3];
    dJointGetPUAnchor(j, anchor);
    dJointGetPUAxis1(j, ax[0]);
    dJointGetPUAxis2(j, ax[1]);
    dJointGetPUAxis3(j, ax[2]);
    dxJointSetAnchors(j, anchor[0], anchor[1], anchor[2], pu->anchor1, pu->anchor2);
    for (int k = 0; k < 3; k++) set_user_axis(j, "dJointAttach", k, ax[k][0], ax[k][1], ax[k][2]);
}

void dxJointPURest(const dxJoint *j, dQuaternion qrel1, dQuaternion qrel2)
{
    if (j->cls->type != dJointTypePU) return;
    dCopyVector4(qrel1, ((const dxJointPU *)j)->qrel1);
    dCopyVector4(qrel2, ((const dxJointPU *)j)->qrel2);
}

static const dxJointClass pu_class = {
    dJointTypePU, "PU", sizeof(dxJointPU), pu_init, pu_count_rows, pu_fill_rows, pu_attached
};

dJointID dJointCreatePU(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &pu_class);
}

#define PU(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypePU, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

// Set the anchors at (x,y,z), body 0's as if body 0 were displaced by
// shift (world), and take the current angles as zero.
static void set_anchor_shifted(dxJoint *j, dReal x, dReal y, dReal z, const dVector3 shift)
{
    dxJointPU *pu = (dxJointPU *)j;
    const struct dxBody *b0 = dxJointBody(j, 0);
    if (!b0) return;
    dxJointSetAnchors(j, x, y, z, pu->anchor1, pu->anchor2);
    dVector3 local;
    dMultiply1_331(local, b0->R, shift);
    dSubtractVectors3(pu->anchor1, pu->anchor1, local);
    compute_rest_rotations(pu);
}

void dJointSetPUAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    PU(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    const dVector3 none = { 0, 0, 0, 0 };
    set_anchor_shifted(j, x, y, z, none);
}

// Deprecated in ODE 0.16: the anchor, with body 1 taken as displaced by delta
// when it was set, so the position reads -axis . delta (not reversed).
void dJointSetPUAnchorDelta(dJointID j, dReal x, dReal y, dReal z, dReal dx, dReal dy, dReal dz)
{
    PU(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dxIsFinite3(dx, dy, dz), return,
                 "anchor or delta is not finite");
    const dVector3 shift = { dx, dy, dz, 0 };
    set_anchor_shifted(j, x, y, z, shift);
}

// The anchor, with the position now axis . delta (body 1 against body 2, also
// when reversed).
void dJointSetPUAnchorOffset(dJointID j, dReal x, dReal y, dReal z, dReal dx, dReal dy,
                             dReal dz)
{
    PU(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dxIsFinite3(dx, dy, dz), return,
                 "anchor or offset is not finite");
    const dReal sign = reversed(j) ? 1 : -1;
    const dVector3 shift = { sign * dx, sign * dy, sign * dz, 0 };
    set_anchor_shifted(j, x, y, z, shift);
}

void dJointSetPUAxis1(dJointID j, dReal x, dReal y, dReal z)
{
    PU(j, return);
    set_user_axis(j, __func__, 0, x, y, z);
}

void dJointSetPUAxis2(dJointID j, dReal x, dReal y, dReal z)
{
    PU(j, return);
    set_user_axis(j, __func__, 1, x, y, z);
}

void dJointSetPUAxis3(dJointID j, dReal x, dReal y, dReal z)
{
    PU(j, return);
    set_user_axis(j, __func__, 2, x, y, z);
}

void dJointSetPUAxisP(dJointID j, dReal x, dReal y, dReal z)
{
    PU(j, return);
    set_user_axis(j, __func__, 2, x, y, z);
}

// Parameter groups: 1 (dParamX) the stored axis 1, 2 (dParamX2) the stored
// axis 2, 3 (dParamX3) the slide.
static dxLimot *pu_limot(dxJointPU *pu, int group)
{
    return group == 0 ? &pu->limot1 : group == 1 ? &pu->limot2 : &pu->limot_p;
}

void dJointSetPUParam(dJointID j, int parameter, dReal value)
{
    PU(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    int group, param;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return;
    dxLimotSetParam(pu_limot((dxJointPU *)j, group), param, value);
}

dReal dJointGetPUParam(dJointID j, int parameter)
{
    PU(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return 0;
    dxLimotGetParam(pu_limot((dxJointPU *)j, group), param, &value);
    return value;
}

// The anchor on body 2 (the world point without body 2).
void dJointGetPUAnchor(dJointID j, dVector3 result)
{
    PU(j, return);
    CHECK_RESULT(result, return);
    dxJointGetAnchor2(j, result, ((dxJointPU *)j)->anchor2);
}

void dJointGetPUAxis1(dJointID j, dVector3 result)
{
    PU(j, return);
    CHECK_RESULT(result, return);
    dxJointPU *pu = (dxJointPU *)j;
    if (reversed(j)) dxJointGetAxis2(j, result, pu->axis2);
    else dxJointGetAxis1(j, result, pu->axis1);
}

void dJointGetPUAxis2(dJointID j, dVector3 result)
{
    PU(j, return);
    CHECK_RESULT(result, return);
    dxJointPU *pu = (dxJointPU *)j;
    if (reversed(j)) dxJointGetAxis1(j, result, pu->axis1);
    else dxJointGetAxis2(j, result, pu->axis2);
}

void dJointGetPUAxis3(dJointID j, dVector3 result)
{
    PU(j, return);
    CHECK_RESULT(result, return);
    world_axes((dxJointPU *)j, NULL, NULL, result);
}

void dJointGetPUAxisP(dJointID j, dVector3 result)
{
    PU(j, return);
    CHECK_RESULT(result, return);
    world_axes((dxJointPU *)j, NULL, NULL, result);
}

dReal dJointGetPUPosition(dJointID j)
{
    PU(j, return 0);
    return pu_position((dxJointPU *)j);
}

// axis P . (velocity of body 0's point at the anchor on body 1 - velocity of
// body 1's point there); negated when reversed. (ODE 0.16 counts body 2's
// turn with the wrong sign here; both agree while body 2 does not turn.)
dReal dJointGetPUPositionRate(dJointID j)
{
    PU(j, return 0);
    dxJointPU *pu = (dxJointPU *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 0;
    dVector3 an1, an2, axp, r, v0, v1;
    world_anchors(pu, an1, an2);
    world_axes(pu, NULL, NULL, axp);
    dSubtractVectors3(r, an2, b0->pos);
    dCalcVectorCross3(v0, b0->avel, r);
    dAddVectors3(v0, v0, b0->lvel);
    dReal rate = dCalcVectorDot3(axp, v0);
    if (b1) {
        dSubtractVectors3(r, an2, b1->pos);
        dCalcVectorCross3(v1, b1->avel, r);
        dAddVectors3(v1, v1, b1->lvel);
        return rate - dCalcVectorDot3(axp, v1);
    }
    return reversed(j) ? -rate : rate;
}

void dJointGetPUAngles(dJointID j, dReal *angle1, dReal *angle2)
{
    PU(j, return);
    DX_CHECK_ARG(angle1 != NULL && angle2 != NULL, return, "angle1 or angle2 is NULL");
    if (reversed(j)) stored_angles((dxJointPU *)j, angle2, angle1);
    else stored_angles((dxJointPU *)j, angle1, angle2);
}

dReal dJointGetPUAngle1(dJointID j)
{
    PU(j, return 0);
    dReal a1, a2;
    stored_angles((dxJointPU *)j, &a1, &a2);
    return reversed(j) ? a2 : a1;
}

dReal dJointGetPUAngle2(dJointID j)
{
    PU(j, return 0);
    dReal a1, a2;
    stored_angles((dxJointPU *)j, &a1, &a2);
    return reversed(j) ? a1 : a2;
}

// Rate about the user's axis k: axis . (w0 - w1) of the stored bodies.
static dReal user_angle_rate(dxJoint *j, int k)
{
    dxJointPU *pu = (dxJointPU *)j;
    if (!dxJointBody(j, 0)) return 0;
    dVector3 ax1, ax2;
    world_axes(pu, ax1, ax2, NULL);
    return dxJointRelativeAngleRate(j, (k == 0) != reversed(j) ? ax1 : ax2);
}

dReal dJointGetPUAngle1Rate(dJointID j)
{
    PU(j, return 0);
    return user_angle_rate(j, 0);
}

dReal dJointGetPUAngle2Rate(dJointID j)
{
    PU(j, return 0);
    return user_angle_rate(j, 1);
}
