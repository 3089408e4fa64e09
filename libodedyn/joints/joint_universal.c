// SPDX-License-Identifier: BSD-3-Clause
//
// joint_universal.c -- the universal joint (guide 7.3.4): the ball rows, one
// row keeping axis 1 (on body 1) perpendicular to axis 2 (on body 2), and a
// limit/motor row about each axis.
//
// Axes, angles and limits are kept in the user's order (body 1 = first
// argument of dJointAttach, possibly the static world); only the anchors and
// the rows use the stored order (body 0 = the first non-static body).
//
// Angles: body 1 turns about axis 1 relative to the cross, and the cross
// turns with body 1 about axis 2 relative to body 2. With r = conj(q2) q1
// (body 1 seen from body 2) and r0 its value at zero angles,
//   r = Q(a2, theta2) r0 Q(a1, theta1)
// with a2 in body 2's frame and a1 in body 1's frame; so the change
// D = r conj(r0) = Q(a2, theta2) Q(a1', theta1), a1' = r0 a1 conj(r0).

#include "joint_geometry.h"

typedef struct dxJointUniversal {
    dxJoint base;
    dVector3 anchor1, anchor2;   // body 0 frame; body 1 frame (or world)
    dVector3 axis[2];            // axis k in the frame of user body k+1 (or world)
    int axes_reversed;           // DX_JOINT_REVERSE when the axes were stored
    dQuaternion qrel;            // r0 = conj(q2) q1 at zero angles (user bodies)
    dVector3 e1, n;              // the angles' frame (e1, axis 2, n) from qrel and the axes
    dxLimot limot[2];
} dxJointUniversal;

// User body k (0: first argument of dJointAttach, 1: second); NULL = world.
static struct dxBody *user_body(const dxJoint *j, int k)
{
    return dxJointBody(j, (j->flags & DX_JOINT_REVERSE) ? 1 - k : k);
}

// Axis k in world coordinates.
static void world_axis(const dxJointUniversal *u, int k, dVector3 result)
{
    const struct dxBody *b = user_body(&u->base, k);
    if (b) dMultiply0_331(result, b->R, u->axis[k]);
    else dCopyVector3(result, u->axis[k]);
}

// r = conj(q2) q1 of the user bodies (identity for the world).
static void user_relative_quaternion(const dxJoint *j, dQuaternion r)
{
    static const dQuaternion identity = { 1, 0, 0, 0 };
    const struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    dQMultiply1(r, b2 ? b2->q : identity, b1 ? b1->q : identity);
}

// Half angle of Q(a, theta) from two pairs proportional to (cos, sin) of
// it: c*(w, x) and s*(y, z) with c^2 + s^2 = 1; the larger pair is exact
// and the sign of c or s only adds 2 pi to theta, which the wrap removes.
static dReal angle_from_pairs(dReal w, dReal x, dReal y, dReal z)
{
    dReal theta = (w * w + x * x >= y * y + z * z) ? 2 * dAtan2(x, w) : 2 * dAtan2(z, y);
    if (theta > M_PI) theta -= 2 * M_PI;
    if (theta <= -M_PI) theta += 2 * M_PI;
    return theta;
}

// The frame the angles are measured in (body 2's): with a1' = r0 a1 conj(r0)
// and a2, n = a2 x a1' normalised and e1 = n x a2, orthonormal in case the
// axes were set not quite perpendicular. It depends only on qrel and the
// axes: made again whenever they change.
static void set_frame(dxJointUniversal *u)
{
    dMatrix3 R0;
    dVector3 a1;
    dRfromQ(R0, u->qrel);
    dMultiply0_331(a1, R0, u->axis[0]);   // a1' in body 2's frame
    dCalcVectorCross3(u->n, u->axis[1], a1);
    if (!dSafeNormalize3(u->n)) dPlaneSpace(u->axis[1], u->n, u->e1);
    dCalcVectorCross3(u->e1, u->n, u->axis[1]);
}

// The two angles (-pi..pi); see the file comment. With
// D = Q(a2, t2) Q(a1', t1) = c1c2 + c2 s1 a1' + c1 s2 a2 + s1 s2 (a2 x a1')
// for perpendicular unit a1', a2 (c = cos(t/2), s = sin(t/2)).
// The numbers w, x1, x2, xn the two angles are made of (universal_angles).
static void universal_pairs(const dxJointUniversal *u, dReal p[4])
{
    dQuaternion r, d;
    user_relative_quaternion(&u->base, r);
    dQMultiply2(d, r, u->qrel);
    p[0] = d[0];
    p[1] = dCalcVectorDot3(d + 1, u->e1);
    p[2] = dCalcVectorDot3(d + 1, u->axis[1]);
    p[3] = dCalcVectorDot3(d + 1, u->n);
}

static void universal_angles(const dxJointUniversal *u, dReal *angle1, dReal *angle2)
{
    dReal p[4];
    universal_pairs(u, p);
    *angle1 = angle_from_pairs(p[0], p[1], p[2], p[3]);   // c2 (c1, s1) and s2 (c1, s1)
    *angle2 = angle_from_pairs(p[0], p[2], p[1], p[3]);   // c1 (c2, s2) and s1 (c2, s2)
}

// Whether angle_from_pairs(w, x, y, z) is certainly between lm's stops, away
// from both (dxLimotAngleClear, from the same pair).
static int pairs_clear(const dxLimot *lm, dReal w, dReal x, dReal y, dReal z)
{
    return (w * w + x * x >= y * y + z * z) ? dxLimotAngleClear(lm, x, w)
                                            : dxLimotAngleClear(lm, z, y);
}

// Rate of angle k: axis k (world) . (w1 - w2) of the user bodies, which is
// exactly d theta_k / dt while the axes are perpendicular.
static dReal universal_rate(const dxJointUniversal *u, int k)
{
    const struct dxBody *b1 = user_body(&u->base, 0), *b2 = user_body(&u->base, 1);
    dVector3 ax;
    world_axis(u, k, ax);
    dReal rate = 0;
    if (b1) rate += dCalcVectorDot3(ax, b1->avel);
    if (b2) rate -= dCalcVectorDot3(ax, b2->avel);
    return rate;
}

static void universal_init(dxJoint *j)
{
    dxJointUniversal *u = (dxJointUniversal *)j;
    u->axis[0][0] = 1;
    u->axis[1][1] = 1;
    dQSetIdentity(u->qrel);
    set_frame(u);
    dxLimotInit(&u->limot[0], j->world);
    dxLimotInit(&u->limot[1], j->world);
}

static int has_stops(const dxLimot *lm)
{
    return lm->lostop > -dInfinity || lm->histop < dInfinity;
}

static void universal_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointUniversal *u = (dxJointUniversal *)j;
    count->m = 4;
    count->nub = 4;
    dReal p[4] = { 0, 0, 0, 0 };
    if (has_stops(&u->limot[0]) || has_stops(&u->limot[1])) universal_pairs(u, p);
    for (int k = 0; k < 2; k++) {
        dxLimot *lm = &u->limot[k];
        // angle 1 from (w, x1, x2, xn), angle 2 from (w, x2, x1, xn)
        const dReal a = p[1 + k], b = p[2 - k];
        if (!has_stops(lm) || pairs_clear(lm, p[0], a, b, p[3])) lm->limit = 0;
        else dxLimotTestLimit(lm, angle_from_pairs(p[0], a, b, p[3]));
        if (dxLimotActive(lm)) count->m++;
    }
}

static void universal_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointUniversal *u = (dxJointUniversal *)j;
    const int s = rows->rowskip;
    dxJointBallRows(j, rows, 0, u->anchor1, u->anchor2, rows->erp);

    // Row 3: d/dt (a1 . a2) = (a1 x a2) . (w1 - w2) (user bodies); drive
    // a1 . a2 to 0. Body 0 is user body 2 when reversed: its term is -(a1 x a2).
    dVector3 ax[2], p;
    world_axis(u, 0, ax[0]);
    world_axis(u, 1, ax[1]);
    dCalcVectorCross3(p, ax[0], ax[1]);
    if (j->flags & DX_JOINT_REVERSE) dNegateVector3(p);   // body 0 is user body 2
    dCopyVector3(rows->J1a + 3 * s, p);
    if (dxJointBody(j, 1)) dCopyNegatedVector3(rows->J2a + 3 * s, p);
    rows->c[3] = -rows->fps * rows->erp * dCalcVectorDot3(ax[0], ax[1]);

    // The limit/motor rows measure body 0 against body 1: in user sense when
    // body 0 is user body 1, reversed otherwise.
    int row = 4;
    for (int k = 0; k < 2; k++) {
        if (j->flags & DX_JOINT_REVERSE) dNegateVector3(ax[k]);
        row += dxLimotAddRow(&u->limot[k], j, rows, row, ax[k], 1);
    }
}

// After dJointAttach, as ODE 0.16 does: the anchor stays where the getter now
// puts it (from user body 1's side, the world's when attached as (0, b)) and
// is stored again for the new bodies; each axis stays fixed in the frame of
// the stored body it was fixed in (ODE keeps its axes by stored body, so
// when the attachment turns round, axis 1 and axis 2 change places); the
// current pose becomes angle 0 for both.
static void universal_attached(dxJoint *j)
{
    dxJointUniversal *u = (dxJointUniversal *)j;
    if (!dxJointBody(j, 0)) return;
    const int reversed = (j->flags & DX_JOINT_REVERSE) != 0;
    if (reversed != u->axes_reversed) {
        dVector3 t;
        dCopyVector4(t, u->axis[0]);
        dCopyVector4(u->axis[0], u->axis[1]);
        dCopyVector4(u->axis[1], t);
        u->axes_reversed = reversed;
    }
    dVector3 p;
    dJointGetUniversalAnchor(j, p);
    dxJointSetAnchors(j, p[0], p[1], p[2], u->anchor1, u->anchor2);
    user_relative_quaternion(j, u->qrel);
    set_frame(u);
}

static const dxJointClass universal_class = {
    dJointTypeUniversal, "universal", sizeof(dxJointUniversal), universal_init,
    universal_count_rows, universal_fill_rows, universal_attached
};

dJointID dJointCreateUniversal(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &universal_class);
}

#define UNIVERSAL(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeUniversal, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

void dJointSetUniversalAnchor(dJointID j, dReal x, dReal y, dReal z)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointUniversal *u = (dxJointUniversal *)j;
    if (!dxJointBody(j, 0)) return;
    dxJointSetAnchors(j, x, y, z, u->anchor1, u->anchor2);
    user_relative_quaternion(j, u->qrel);
    set_frame(u);
}

// Store world direction (x,y,z) as axis k in the frame of user body k+1.
// Returns 0 if it was reported or the joint is not attached.
static int set_axis(dxJoint *j, const char *function, int k, dReal x, dReal y, dReal z)
{
    dxJointUniversal *u = (dxJointUniversal *)j;
    dVector3 unused;
    // dxJointSetAxes writes its first axis in body 0's frame and its second in
    // body 1's (or the world): user body k+1 is stored body k unless reversed.
    const int stored = (j->flags & DX_JOINT_REVERSE) ? 1 - k : k;
    int ok = stored == 0 ? dxJointSetAxes(j, function, x, y, z, u->axis[k], NULL)
                         : dxJointSetAxes(j, function, x, y, z, unused, u->axis[k]);
    if (!ok || !dxJointBody(j, 0)) return 0;
    user_relative_quaternion(j, u->qrel);
    set_frame(u);
    return 1;
}

void dJointSetUniversalAxis1(dJointID j, dReal x, dReal y, dReal z)
{
    UNIVERSAL(j, return);
    set_axis(j, __func__, 0, x, y, z);
}

void dJointSetUniversalAxis2(dJointID j, dReal x, dReal y, dReal z)
{
    UNIVERSAL(j, return);
    set_axis(j, __func__, 1, x, y, z);
}

// Make the current angles (offset1, offset2): from r = Q(a2, o2) r0 Q(a1, o1),
// r0 = Q(a2, -o2) r Q(a1, -o1).
static void set_offsets(dxJointUniversal *u, dReal offset1, dReal offset2)
{
    dQuaternion turn1, turn2, t;
    const dReal *a1 = u->axis[0], *a2 = u->axis[1];
    dQFromAxisAndAngle(turn1, a1[0], a1[1], a1[2], -offset1);
    dQFromAxisAndAngle(turn2, a2[0], a2[1], a2[2], -offset2);
    dQMultiply0(t, u->qrel, turn1);
    dQMultiply0(u->qrel, turn2, t);
    set_frame(u);
}

void dJointSetUniversalAxis1Offset(dJointID j, dReal x, dReal y, dReal z, dReal offset1,
                                   dReal offset2)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(dxIsFinite(offset1) && dxIsFinite(offset2), return, "offset is not finite");
    if (set_axis(j, __func__, 0, x, y, z)) set_offsets((dxJointUniversal *)j, offset1, offset2);
}

void dJointSetUniversalAxis2Offset(dJointID j, dReal x, dReal y, dReal z, dReal offset1,
                                   dReal offset2)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(dxIsFinite(offset1) && dxIsFinite(offset2), return, "offset is not finite");
    if (set_axis(j, __func__, 1, x, y, z)) set_offsets((dxJointUniversal *)j, offset1, offset2);
}

void dJointGetUniversalAnchor(dJointID j, dVector3 result)
{
    UNIVERSAL(j, return);
    CHECK_RESULT(result, return);
    dxJointUniversal *u = (dxJointUniversal *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor2(j, result, u->anchor2);
    else dxJointGetAnchor1(j, result, u->anchor1);
}

void dJointGetUniversalAnchor2(dJointID j, dVector3 result)
{
    UNIVERSAL(j, return);
    CHECK_RESULT(result, return);
    dxJointUniversal *u = (dxJointUniversal *)j;
    if (j->flags & DX_JOINT_REVERSE) dxJointGetAnchor1(j, result, u->anchor1);
    else dxJointGetAnchor2(j, result, u->anchor2);
}

void dJointGetUniversalAxis1(dJointID j, dVector3 result)
{
    UNIVERSAL(j, return);
    CHECK_RESULT(result, return);
    world_axis((dxJointUniversal *)j, 0, result);
}

void dJointGetUniversalAxis2(dJointID j, dVector3 result)
{
    UNIVERSAL(j, return);
    CHECK_RESULT(result, return);
    world_axis((dxJointUniversal *)j, 1, result);
}

void dJointSetUniversalParam(dJointID j, int parameter, dReal value)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    int group, param;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return;
    dxLimotSetParam(&((dxJointUniversal *)j)->limot[group], param, value);
}

dReal dJointGetUniversalParam(dJointID j, int parameter)
{
    UNIVERSAL(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return 0;
    dxLimotGetParam(&((dxJointUniversal *)j)->limot[group], param, &value);
    return value;
}

void dJointGetUniversalAngles(dJointID j, dReal *angle1, dReal *angle2)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(angle1 != NULL && angle2 != NULL, return, "angle1 or angle2 is NULL");
    *angle1 = *angle2 = 0;
    if (dxJointBody(j, 0)) universal_angles((dxJointUniversal *)j, angle1, angle2);
}

dReal dJointGetUniversalAngle1(dJointID j)
{
    UNIVERSAL(j, return 0);
    dReal a1 = 0, a2 = 0;
    if (dxJointBody(j, 0)) universal_angles((dxJointUniversal *)j, &a1, &a2);
    return a1;
}

dReal dJointGetUniversalAngle2(dJointID j)
{
    UNIVERSAL(j, return 0);
    dReal a1 = 0, a2 = 0;
    if (dxJointBody(j, 0)) universal_angles((dxJointUniversal *)j, &a1, &a2);
    return a2;
}

dReal dJointGetUniversalAngle1Rate(dJointID j)
{
    UNIVERSAL(j, return 0);
    return universal_rate((dxJointUniversal *)j, 0);
}

dReal dJointGetUniversalAngle2Rate(dJointID j)
{
    UNIVERSAL(j, return 0);
    return universal_rate((dxJointUniversal *)j, 1);
}

// The names the ODE 0.5 guide's index gives the two rates.
dReal dJointGetUniversalAngleRate1(dJointID j)
{
    UNIVERSAL(j, return 0);
    return universal_rate((dxJointUniversal *)j, 0);
}

dReal dJointGetUniversalAngleRate2(dJointID j)
{
    UNIVERSAL(j, return 0);
    return universal_rate((dxJointUniversal *)j, 1);
}

// torque1 about axis 1 and torque2 about axis 2 on body 1, the opposite on body 2.
void dJointAddUniversalTorques(dJointID j, dReal torque1, dReal torque2)
{
    UNIVERSAL(j, return);
    DX_CHECK_ARG(dxIsFinite(torque1) && dxIsFinite(torque2), return, "torque is not finite");
    dxJointUniversal *u = (dxJointUniversal *)j;
    struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    dVector3 ax1, ax2, t;
    world_axis(u, 0, ax1);
    world_axis(u, 1, ax2);
    dAddScaledVectors3(t, ax1, ax2, torque1, torque2);
    if (b1) dAddVectors3(b1->torque, b1->torque, t);
    if (b2) dSubtractVectors3(b2->torque, b2->torque, t);
}
