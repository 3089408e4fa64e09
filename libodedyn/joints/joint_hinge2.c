// SPDX-License-Identifier: BSD-3-Clause
//
// joint_hinge2.c -- the hinge-2 joint (guide 7.3.5): two hinges in series, a
// steering axis 1 fixed to body 1 and a wheel axis 2 fixed to body 2, with a
// suspension along axis 1. Rows: the anchors held together (softly along
// axis 1, with the suspension ERP and CFM), one row keeping the angle between
// the axes, and a limit/motor row for each axis.
//
// Everything here is kept in the user's body order (body 1 and body 2 of
// dJointAttach), whatever order the joint stores them in: anchors and axes
// live in the frame of the user body they belong to, and the rows are written
// for the user bodies. ODE 0.16 refuses to attach a hinge-2 to one body; here
// the static world may take the place of either body (its frame is the world
// frame), which gives a suspended universal joint to the environment.
//
// Angles and rates are those of body 1 relative to body 2, about axis 1 and
// axis 2. For axes that are not perpendicular, the rates and the motor/stop
// rows use the reciprocal basis d1 = (a1 - c a2) / s^2, d2 = (a2 - c a1) / s^2
// (c, s: cosine and sine of the angle between the axes): with a relative
// angular velocity w = alpha a1 + beta a2, d1 . w = alpha and d2 . w = beta,
// so each rate is the derivative of its angle and a steering motor does no
// work on the wheel. For perpendicular axes d1 = a1 and d2 = a2, as in ODE.

#include "joint_geometry.h"

// Below this sine of the angle between them, the axes count as parallel.
#define PARALLEL_SIN REAL(1e-4)

typedef struct dxJointHinge2 {
    dxJoint base;
    dVector3 anchor[2];      // frame of user body 1 / user body 2 (world if static)
    dVector3 axis1, axis2;   // axis 1 in body 1's frame, axis 2 in body 2's frame
    dVector3 ref1[2];        // body 1 frame: axis 2 at zero angle 1 (made perpendicular
                             // to axis 1), and axis 1 x that
    dVector3 ref2[2];        // body 2 frame: axis 1 at zero angle 2 (made perpendicular
                             // to axis 2), and axis 2 x that
    dReal c0, s0;            // cosine and sine of the angle between the axes at set time
    dReal susp_erp, susp_cfm;
    dxLimot limot[2];        // axis 1 (steering), axis 2 (wheel)
} dxJointHinge2;

// ---- the user's body order ------------------------------------------------

// User body k (0: body 1 of dJointAttach, 1: body 2), NULL for the static world.
static struct dxBody *user_body(const dxJoint *j, int k)
{
    return dxJointBody(j, (j->flags & DX_JOINT_REVERSE) ? 1 - k : k);
}

// World direction of v, which is fixed in the frame of user body k.
static void to_world(const dxJoint *j, int k, dVector3 out, const dVector3 v)
{
    const struct dxBody *b = user_body(j, k);
    if (b) dMultiply0_331(out, b->R, v);
    else dCopyVector3(out, v);
    out[3] = 0;
}

// World direction v in the frame of user body k.
static void from_world(const dxJoint *j, int k, dVector3 out, const dVector3 v)
{
    const struct dxBody *b = user_body(j, k);
    if (b) dMultiply1_331(out, b->R, v);
    else dCopyVector3(out, v);
    out[3] = 0;
}

// Row `row` of the Jacobian block of user body k (linear or angular part),
// or NULL when that body is the static world.
static dReal *user_jacobian(const dxJoint *j, const dxJointRows *rows, int k, int angular,
                            int row)
{
    int slot = (j->flags & DX_JOINT_REVERSE) ? 1 - k : k;
    if (!dxJointBody(j, slot)) return NULL;
    dReal *J = slot ? (angular ? rows->J2a : rows->J2l) : (angular ? rows->J1a : rows->J1l);
    return J + row * rows->rowskip;
}

// ---- geometry -------------------------------------------------------------

// The joint's geometry now, in world coordinates.
typedef struct hinge2_pose {
    dVector3 a1, a2;     // the axes
    dVector3 r[2];       // anchor k relative to the centre of user body k
    dVector3 p[2];       // anchor k
} hinge2_pose;

// World directions of axis 1 and axis 2.
static void get_axes(const dxJointHinge2 *h, dVector3 a1, dVector3 a2)
{
    to_world(&h->base, 0, a1, h->axis1);
    to_world(&h->base, 1, a2, h->axis2);
}

// Anchor k in the world (p), and its offset from user body k's centre (r).
static void get_anchor(const dxJointHinge2 *h, int k, dVector3 r, dVector3 p)
{
    const struct dxBody *b = user_body(&h->base, k);
    if (b) {
        dMultiply0_331(r, b->R, h->anchor[k]);
        dAddVectors3(p, b->pos, r);
    } else {
        dZeroVector3(r);
        dCopyVector3(p, h->anchor[k]);
    }
}

static void get_pose(const dxJointHinge2 *h, hinge2_pose *pose)
{
    get_axes(h, pose->a1, pose->a2);
    for (int k = 0; k < 2; k++) get_anchor(h, k, pose->r[k], pose->p[k]);
}

// Unit vector along the part of v perpendicular to unit n (some unit
// vector if the axes were parallel, which the setters do not allow).
static void perpendicular_part(dVector3 out, const dVector3 v, const dVector3 n)
{
    dAddScaledVectors3(out, v, n, 1, -dCalcVectorDot3(v, n));
    dSafeNormalize3(out);
}

// 1 unless the axes (world) are parallel, which is reported for `function`.
static int check_not_parallel(const char *function, const dVector3 a1, const dVector3 a2)
{
    dVector3 cross;
    dCalcVectorCross3(cross, a1, a2);
    if (dCalcVectorLength3(cross) > PARALLEL_SIN) return 1;
    dxReportBadArgument(function, "axis1 (%g, %g, %g) and axis2 (%g, %g, %g) are parallel",
                        (double)a1[0], (double)a1[1], (double)a1[2], (double)a2[0],
                        (double)a2[1], (double)a2[2]);
    return 0;
}

// Take the current pose as zero for both angles, and the current angle
// between the axes (not parallel) as the one the joint keeps.
static void set_reference(dxJointHinge2 *h)
{
    dVector3 a1, a2, v, w;
    get_axes(h, a1, a2);
    dCalcVectorCross3(v, a1, a2);
    h->c0 = dCalcVectorDot3(a1, a2);
    h->s0 = dCalcVectorLength3(v);
    perpendicular_part(v, a2, a1);
    from_world(&h->base, 0, h->ref1[0], v);
    dCalcVectorCross3(w, a1, v);
    from_world(&h->base, 0, h->ref1[1], w);
    perpendicular_part(v, a1, a2);
    from_world(&h->base, 1, h->ref2[0], v);
    dCalcVectorCross3(w, a2, v);
    from_world(&h->base, 1, h->ref2[1], w);
}

// The sides (y, x) of angle k's arctangent: how far body 1 turned about
// axis k + 1 relative to body 2 since the reference is -atan2(y, x) for
// angle 1 (seen from body 1, axis 2 turns the other way about axis 1) and
// atan2(y, x) for angle 2 (seen from body 2, axis 1 turns the same way
// about axis 2).
static void angle_sides(const dxJointHinge2 *h, int k, dReal *y, dReal *x)
{
    dVector3 a1, a2, q;
    get_axes(h, a1, a2);
    from_world(&h->base, k, q, k ? a1 : a2);
    const dVector3 *ref = k ? h->ref2 : h->ref1;
    *y = dCalcVectorDot3(ref[1], q);
    *x = dCalcVectorDot3(ref[0], q);
}

// Angle k (0: angle 1, 1: angle 2).
static dReal angle_of(const dxJointHinge2 *h, int k)
{
    dReal y, x;
    angle_sides(h, k, &y, &x);
    return k ? dAtan2(y, x) : -dAtan2(y, x);
}

// The reciprocal basis of the axes in their plane: d1 . a1 = 1, d1 . a2 = 0,
// d2 . a1 = 0, d2 . a2 = 1 (see the file comment).
static void reciprocal_axes(const dVector3 a1, const dVector3 a2, dVector3 d1, dVector3 d2)
{
    dReal c = dCalcVectorDot3(a1, a2), s2 = 1 - c * c;
    if (s2 < PARALLEL_SIN * PARALLEL_SIN) s2 = PARALLEL_SIN * PARALLEL_SIN;
    dAddScaledVectors3(d1, a1, a2, 1 / s2, -c / s2);
    dAddScaledVectors3(d2, a2, a1, 1 / s2, -c / s2);
}

// Relative angular velocity of body 1 against body 2.
static void relative_angular_velocity(const dxJoint *j, dVector3 w)
{
    const struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    dZeroVector3(w);
    if (b1) dAddVectors3(w, w, b1->avel);
    if (b2) dSubtractVectors3(w, w, b2->avel);
}

// ---- rows -----------------------------------------------------------------

// Rows 0..2: the anchors do not separate along the unit directions n[i]
// (row i, its ERP erp[i]). Row i's velocity is n . (v1 + w1 x r1 - v2 - w2 x
// r2), and n . (w x r) = w . (r x n). The three are made together: each
// body's Jacobian found once, the anchors' gap once.
static void anchor_rows(const dxJoint *j, dxJointRows *rows, const hinge2_pose *pose,
                        const dReal *const n[3], const dReal erp[3])
{
    const int s = rows->rowskip;
    for (int k = 0; k < 2; k++) {
        dReal *Jl = user_jacobian(j, rows, k, 0, 0), *Ja = user_jacobian(j, rows, k, 1, 0);
        if (!Jl) continue;
        const dReal sign = k ? -1 : 1;
        for (int i = 0; i < 3; i++) {
            dVector3 rn;
            dCalcVectorCross3(rn, pose->r[k], n[i]);
            dCopyScaledVector3(Jl + i * s, n[i], sign);
            dCopyScaledVector3(Ja + i * s, rn, sign);
        }
    }
    dVector3 gap;
    dSubtractVectors3(gap, pose->p[1], pose->p[0]);
    for (int i = 0; i < 3; i++) rows->c[i] = rows->fps * erp[i] * dCalcVectorDot3(n[i], gap);
}

// Row `row`: no relative rotation about u = a1 x a2, which keeps the angle
// theta between the axes. Turning body 1 about u brings a1 towards a2, so
// u . (w1 - w2) = -d(theta)/dt; the correction drives theta back to theta0
// through sin(theta - theta0) = s c0 - c s0.
static void axes_angle_row(const dxJointHinge2 *h, dxJointRows *rows, int row,
                           const hinge2_pose *pose)
{
    dVector3 u, unused;
    dCalcVectorCross3(u, pose->a1, pose->a2);
    dReal s = dCalcVectorLength3(u), c = dCalcVectorDot3(pose->a1, pose->a2);
    if (s > PARALLEL_SIN) {
        dScaleVector3(u, 1 / s);
        rows->c[row] = rows->fps * rows->erp * (s * h->c0 - c * h->s0);
    } else {
        dPlaneSpace(pose->a1, u, unused);   // broken joint: just block some rotation
    }
    for (int k = 0; k < 2; k++) {
        dReal *Ja = user_jacobian(&h->base, rows, k, 1, row);
        if (Ja) dCopyScaledVector3(Ja, u, k ? -1 : 1);
    }
}

// The limit/motor row of axis k along direction d (user sense: body 1
// against body 2). The limot code works in stored order: reversed, the
// stored body 0 is user body 2, so the direction flips.
static int limot_row(dxJointHinge2 *h, int k, dxJointRows *rows, int row, const dVector3 d)
{
    dVector3 dir;
    dCopyScaledVector3(dir, d, (h->base.flags & DX_JOINT_REVERSE) ? -1 : 1);
    return dxLimotAddRow(&h->limot[k], &h->base, rows, row, dir, 1);
}

static void hinge2_init(dxJoint *j)
{
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    // ODE's defaults: axis 1 = x in body 1, axis 2 = y in body 2.
    h->axis1[0] = 1;
    h->axis2[1] = 1;
    h->c0 = 0;
    h->s0 = 1;
    h->ref1[0][1] = 1;    // y
    h->ref1[1][2] = 1;    // x cross y = z
    h->ref2[0][0] = 1;    // x
    h->ref2[1][2] = -1;   // y cross x = -z
    h->susp_erp = j->world->erp;
    h->susp_cfm = j->world->cfm;
    for (int k = 0; k < 2; k++) dxLimotInit(&h->limot[k], j->world);
}

// Test axis k against its stops (without atan2 when the angle is clearly
// between them); 1 if it needs a row.
static int test_axis(dxJointHinge2 *h, int k)
{
    dxLimot *lm = &h->limot[k];
    if (lm->lostop > -dInfinity || lm->histop < dInfinity) {
        dReal y, x;
        angle_sides(h, k, &y, &x);
        if (k ? dxLimotAtan2Clear(lm, y, x) : dxLimotAtan2Clear(lm, -y, x)) lm->limit = 0;
        else dxLimotTestLimit(lm, k ? dAtan2(y, x) : -dAtan2(y, x));
    } else {
        lm->limit = 0;
    }
    return dxLimotActive(lm);
}

static void hinge2_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    count->m = 0;
    count->nub = 0;
    if (!dxJointBody(j, 0)) return;
    count->m = 4 + test_axis(h, 0) + test_axis(h, 1);
    count->nub = 4;
}

static void hinge2_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    hinge2_pose pose;
    get_pose(h, &pose);
    // The anchor along axis 1 is the suspension: a spring kp = ERP / (h CFM)
    // with damping kd = (1 - ERP) / CFM (guide 3.8.2); across it, rigid.
    dVector3 p, q, d1, d2;
    dPlaneSpace(pose.a1, p, q);
    const dReal *const n[3] = { pose.a1, p, q };
    const dReal erp[3] = { h->susp_erp, rows->erp, rows->erp };
    anchor_rows(j, rows, &pose, n, erp);
    rows->cfm[0] = h->susp_cfm;
    axes_angle_row(h, rows, 3, &pose);
    reciprocal_axes(pose.a1, pose.a2, d1, d2);
    int row = 4 + limot_row(h, 0, rows, 4, d1);
    limot_row(h, 1, rows, row, d2);
}

// Store world point p as the anchor on both user bodies.
static void set_anchor(dxJointHinge2 *h, const dVector3 p)
{
    for (int k = 0; k < 2; k++) {
        const struct dxBody *b = user_body(&h->base, k);
        dVector3 r;
        if (b) dSubtractVectors3(r, p, b->pos);
        else dCopyVector3(r, p);
        from_world(&h->base, k, h->anchor[k], r);
    }
}

// After dJointAttach, as ODE 0.16 does: the anchor stays where body 1 now
// puts it and is stored again for body 2, the axes stay fixed in their
// bodies, and the current pose becomes angle 0 with the current angle
// between the axes kept (unless the new poses make the axes parallel).
static void hinge2_attached(dxJoint *j)
{
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    if (!dxJointBody(j, 0)) return;
    dVector3 r, p, a1, a2, cross;
    get_anchor(h, 0, r, p);
    set_anchor(h, p);
    get_axes(h, a1, a2);
    dCalcVectorCross3(cross, a1, a2);
    if (dCalcVectorLength3(cross) > PARALLEL_SIN) set_reference(h);
}

static const dxJointClass hinge2_class = {
    dJointTypeHinge2, "hinge-2", sizeof(dxJointHinge2), hinge2_init, hinge2_count_rows,
    hinge2_fill_rows, hinge2_attached
};

// ---- public API -------------------------------------------------------------

dJointID dJointCreateHinge2(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &hinge2_class);
}

#define HINGE2(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeHinge2, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

void dJointSetHinge2Anchor(dJointID j, dReal x, dReal y, dReal z)
{
    HINGE2(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    if (!dxJointBody(j, 0)) return;   // not attached: setters do nothing
    const dVector3 p = { x, y, z, 0 };
    set_anchor(h, p);
    // The anchor is kept; the zero angles need axes that are not parallel,
    // which the bodies' orientations can make of the default axes.
    dVector3 a1, a2;
    get_axes(h, a1, a2);
    if (check_not_parallel(__func__, a1, a2)) set_reference(h);
}

// Copy axis (world) to out, normalised; reports and returns 0 if it is
// not a direction.
static int unit_axis(const char *function, const char *name, const dReal *axis, dVector3 out)
{
    dCopyVector3(out, axis);
    out[3] = 0;
    if (dxIsFinite3(out[0], out[1], out[2]) && dSafeNormalize3(out)) return 1;
    dxReportBadArgument(function, "%s (%g, %g, %g) has no direction", name, (double)axis[0],
                        (double)axis[1], (double)axis[2]);
    return 0;
}

// Set either or both axes (world directions, NULL = keep). Nothing changes
// if an axis is bad or the resulting axes are parallel.
static void set_axes(dxJoint *j, const char *function, const dReal *axis1, const dReal *axis2)
{
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    dVector3 a1, a2;
    get_axes(h, a1, a2);
    if (axis1 && !unit_axis(function, "axis1", axis1, a1)) return;
    if (axis2 && !unit_axis(function, "axis2", axis2, a2)) return;
    if (!dxJointBody(j, 0) || !check_not_parallel(function, a1, a2)) return;
    from_world(j, 0, h->axis1, a1);
    from_world(j, 1, h->axis2, a2);
    set_reference(h);
}

void dJointSetHinge2Axes(dJointID j, const dReal *axis1, const dReal *axis2)
{
    HINGE2(j, return);
    DX_CHECK_ARG(axis1 || axis2, return, "axis1 and axis2 are both NULL");
    set_axes(j, __func__, axis1, axis2);
}

void dJointSetHinge2Axis1(dJointID j, dReal x, dReal y, dReal z)
{
    HINGE2(j, return);
    const dReal axis[3] = { x, y, z };
    set_axes(j, __func__, axis, NULL);
}

void dJointSetHinge2Axis2(dJointID j, dReal x, dReal y, dReal z)
{
    HINGE2(j, return);
    const dReal axis[3] = { x, y, z };
    set_axes(j, __func__, NULL, axis);
}

void dJointGetHinge2Anchor(dJointID j, dVector3 result)
{
    HINGE2(j, return);
    CHECK_RESULT(result, return);
    dVector3 r;
    get_anchor((dxJointHinge2 *)j, 0, r, result);
}

void dJointGetHinge2Anchor2(dJointID j, dVector3 result)
{
    HINGE2(j, return);
    CHECK_RESULT(result, return);
    dVector3 r;
    get_anchor((dxJointHinge2 *)j, 1, r, result);
}

void dJointGetHinge2Axis1(dJointID j, dVector3 result)
{
    HINGE2(j, return);
    CHECK_RESULT(result, return);
    to_world(j, 0, result, ((dxJointHinge2 *)j)->axis1);
}

void dJointGetHinge2Axis2(dJointID j, dVector3 result)
{
    HINGE2(j, return);
    CHECK_RESULT(result, return);
    to_world(j, 1, result, ((dxJointHinge2 *)j)->axis2);
}

void dJointSetHinge2Param(dJointID j, int parameter, dReal value)
{
    HINGE2(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return;
    if (group == 0 && param == dParamSuspensionERP) h->susp_erp = value;
    else if (group == 0 && param == dParamSuspensionCFM) h->susp_cfm = value;
    else dxLimotSetParam(&h->limot[group], param, value);
}

dReal dJointGetHinge2Param(dJointID j, int parameter)
{
    HINGE2(j, return 0);
    dxJointHinge2 *h = (dxJointHinge2 *)j;
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 2, &group, &param)) return 0;
    if (group == 0 && param == dParamSuspensionERP) return h->susp_erp;
    if (group == 0 && param == dParamSuspensionCFM) return h->susp_cfm;
    dxLimotGetParam(&h->limot[group], param, &value);
    return value;
}

dReal dJointGetHinge2Angle1(dJointID j)
{
    HINGE2(j, return 0);
    if (!dxJointBody(j, 0)) return 0;
    return angle_of((dxJointHinge2 *)j, 0);
}

dReal dJointGetHinge2Angle2(dJointID j)
{
    HINGE2(j, return 0);
    if (!dxJointBody(j, 0)) return 0;
    return angle_of((dxJointHinge2 *)j, 1);
}

// The rate about axis k: d_k . (w1 - w2) with the reciprocal axes.
static dReal angle_rate(const dxJointHinge2 *h, int k)
{
    dVector3 a1, a2, d1, d2, w;
    get_axes(h, a1, a2);
    reciprocal_axes(a1, a2, d1, d2);
    relative_angular_velocity(&h->base, w);
    return dCalcVectorDot3(k ? d2 : d1, w);
}

dReal dJointGetHinge2Angle1Rate(dJointID j)
{
    HINGE2(j, return 0);
    if (!dxJointBody(j, 0)) return 0;
    return angle_rate((dxJointHinge2 *)j, 0);
}

dReal dJointGetHinge2Angle2Rate(dJointID j)
{
    HINGE2(j, return 0);
    if (!dxJointBody(j, 0)) return 0;
    return angle_rate((dxJointHinge2 *)j, 1);
}

void dJointAddHinge2Torques(dJointID j, dReal torque1, dReal torque2)
{
    HINGE2(j, return);
    DX_CHECK_ARG(dxIsFinite(torque1) && dxIsFinite(torque2), return, "torque is not finite");
    if (!dxJointBody(j, 0)) return;
    dVector3 a1, a2, t;
    get_axes((dxJointHinge2 *)j, a1, a2);
    dAddScaledVectors3(t, a1, a2, torque1, torque2);
    struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    if (b1) dAddVectors3(b1->torque, b1->torque, t);
    if (b2) dSubtractVectors3(b2->torque, b2->torque, t);
}
