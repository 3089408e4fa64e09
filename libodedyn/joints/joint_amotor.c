// SPDX-License-Identifier: BSD-3-Clause
//
// joint_amotor.c -- the angular motor (guide 7.3.x): up to three limit/motor
// rows on the relative rotation of two bodies. In user mode the axes and the
// angles (needed for stops) come from the user; in Euler mode the angles are
// the Euler angles of the relative orientation.
//
// Everything is in the user's body order (body 1 and body 2 of dJointAttach):
// rel 1 fixes an axis to body 1, rel 2 to body 2, whatever order the joint
// stores the bodies in. A rel naming the static world fixes the axis in the
// world. Angles, rates, motors and stops are those of body 1 against body 2,
// as for the other joints (a motor row is axis . (w1 - w2) = vel).
//
// Euler mode. At the reference (mode set, axis set) axis 0 = e0 and axis 2
// (made perpendicular to it) = e2 give a frame e0, e1 = e2 x e0, e2 that is
// fixed to body 1 (the e's) and, as f0, f1, f2, to body 2. Since then body 2
// turned relative to body 1 by D = Rot(e0, t0) Rot(e1, t1) Rot(e2, t2): first
// about axis 0 (fixed to body 1), last about axis 2 (fixed to body 2), and in
// between about axis 1 = Rot(e0, t0) e1, which is perpendicular to both, so
// along axis 2 x axis 0. In the e basis D is M = Rx(t0) Ry(t1) Rz(t2) with
// M_ij = e_i . f_j (world vectors now), hence
//     t1 = asin(M02),  t0 = atan2(-M12, M22),  t2 = atan2(-M01, M00),
// and the angles reported are -t (body 1 against body 2; ODE's sign).
// The relative angular velocity w2 - w1 = t0' a0 + t1' a1 + t2' a2, so with
// the reciprocal basis d0 = (a1 x a2) / V, d1 = (a2 x a0) / V = a1,
// d2 = (a0 x a1) / V, V = a0 . (a1 x a2) = cos t1, each rate is
// t_i' = d_i . (w2 - w1): the Euler rows along d_i move one angle each. (ODE
// uses the same crosses without 1/V, so its rows 0 and 2 and its rates 0 and
// 2 are scaled by cos t1; here rates are the derivatives of the angles.)
// At t1 = +-pi/2 (gimbal lock) t0 and t2 are not defined: 1/V is capped.

#include "joint_geometry.h"

// The smallest cos(t1) the Euler rates divide by.
#define GIMBAL_MIN_COS REAL(1e-6)

typedef struct dxJointAMotor {
    dxJoint base;
    int mode;                 // dAMotorUser or dAMotorEuler
    int num;                  // active axes, 0..3
    int rel[3];               // 0 world, 1 body 1, 2 body 2
    dVector3 axis[3];         // unit, in the frame rel names
    dReal angle[3];           // user mode: the angles the user set
    dVector3 eref1[3];        // Euler mode: e0 e1 e2 in body 1's frame
    dVector3 eref2[3];        // the same at the reference, in body 2's frame
    int axes_reversed;        // DX_JOINT_REVERSE when rel, axis and eref were stored
    dxLimot limot[3];
} dxJointAMotor;

// ---- the user's body order ------------------------------------------------

// User body k (0: body 1 of dJointAttach, 1: body 2), NULL for the static world.
static struct dxBody *user_body(const dxJoint *j, int k)
{
    return dxJointBody(j, (j->flags & DX_JOINT_REVERSE) ? 1 - k : k);
}

// World direction of v, fixed in the frame of user body k (k < 0: the world).
static void to_world(const dxJoint *j, int k, dVector3 out, const dVector3 v)
{
    const struct dxBody *b = k >= 0 ? user_body(j, k) : NULL;
    if (b) dMultiply0_331(out, b->R, v);
    else dCopyVector3(out, v);
    out[3] = 0;
}

// World direction v in the frame of user body k (k < 0: the world).
static void from_world(const dxJoint *j, int k, dVector3 out, const dVector3 v)
{
    const struct dxBody *b = k >= 0 ? user_body(j, k) : NULL;
    if (b) dMultiply1_331(out, b->R, v);
    else dCopyVector3(out, v);
    out[3] = 0;
}

// World direction of user axis i (user mode).
static void user_axis(const dxJointAMotor *m, int i, dVector3 out)
{
    to_world(&m->base, m->rel[i] - 1, out, m->axis[i]);
}

// ---- Euler mode -------------------------------------------------------------

typedef struct euler_frame {
    dVector3 ax[3];      // world: axis 0 (body 1), axis 1, axis 2 (body 2)
    dVector3 d[3];       // reciprocal basis: d_i . (w1 - w2) is the rate of angle i
    dReal angle[3];      // body 1 against body 2
} euler_frame;

// The current relative orientation becomes zero for all three angles.
static void euler_set_reference(dxJointAMotor *m)
{
    dVector3 e[3];
    user_axis(m, 0, e[0]);
    user_axis(m, 2, e[2]);
    dAddScaledVectors3(e[2], e[2], e[0], 1, -dCalcVectorDot3(e[2], e[0]));
    if (!dSafeNormalize3(e[2])) dPlaneSpace(e[0], e[2], e[1]);   // parallel axes
    dCalcVectorCross3(e[1], e[2], e[0]);
    for (int i = 0; i < 3; i++) {
        from_world(&m->base, 0, m->eref1[i], e[i]);
        from_world(&m->base, 1, m->eref2[i], e[i]);
    }
}

static void euler_compute(const dxJointAMotor *m, euler_frame *fr)
{
    dVector3 e[3], f[3];
    for (int i = 0; i < 3; i++) {
        to_world(&m->base, 0, e[i], m->eref1[i]);
        to_world(&m->base, 1, f[i], m->eref2[i]);
    }
    dReal m02 = dCalcVectorDot3(e[0], f[2]), m12 = dCalcVectorDot3(e[1], f[2]);
    dReal m22 = dCalcVectorDot3(e[2], f[2]), m00 = dCalcVectorDot3(e[0], f[0]);
    dReal m01 = dCalcVectorDot3(e[0], f[1]);
    dReal cos1 = dSqrt(m12 * m12 + m22 * m22);   // cos t1 >= 0
    dReal t0 = dAtan2(-m12, m22), t1 = dAtan2(m02, cos1), t2 = dAtan2(-m01, m00);
    fr->angle[0] = -t0;
    fr->angle[1] = -t1;
    fr->angle[2] = -t2;

    dCopyVector3(fr->ax[0], e[0]);
    dCopyVector3(fr->ax[2], f[2]);
    // axis 1 = Rot(e0, t0) e1, defined even at gimbal lock.
    dAddScaledVectors3(fr->ax[1], e[1], e[2], dCos(t0), dSin(t0));
    dReal inv_v = 1 / (cos1 > GIMBAL_MIN_COS ? cos1 : GIMBAL_MIN_COS);
    // d_i . (w1 - w2) = -t_i', the rate of the reported angle -t_i.
    dCalcVectorCross3(fr->d[0], fr->ax[1], fr->ax[2]);
    dScaleVector3(fr->d[0], inv_v);
    dCopyVector3(fr->d[1], fr->ax[1]);
    dCalcVectorCross3(fr->d[2], fr->ax[0], fr->ax[1]);
    dScaleVector3(fr->d[2], inv_v);
    for (int i = 0; i < 3; i++) fr->ax[i][3] = fr->d[i][3] = 0;
}

// ---- rows -----------------------------------------------------------------

static void amotor_init(dxJoint *j)
{
    dxJointAMotor *m = (dxJointAMotor *)j;
    m->mode = dAMotorUser;
    for (int i = 0; i < 3; i++) {
        m->axis[i][0] = 1;   // the guide's default axis, global
        m->eref1[i][i] = 1;
        m->eref2[i][i] = 1;
        dxLimotInit(&m->limot[i], j->world);
    }
}

static void amotor_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointAMotor *m = (dxJointAMotor *)j;
    count->m = 0;
    count->nub = 0;
    if (!dxJointBody(j, 0) || m->num == 0) return;
    euler_frame fr;
    if (m->mode == dAMotorEuler) euler_compute(m, &fr);
    for (int i = 0; i < m->num; i++) {
        dxLimot *lm = &m->limot[i];
        if (lm->lostop > -dInfinity || lm->histop < dInfinity)
            dxLimotTestLimit(lm, m->mode == dAMotorEuler ? fr.angle[i] : m->angle[i]);
        else
            lm->limit = 0;
        count->m += dxLimotActive(lm);
    }
}

static void amotor_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointAMotor *m = (dxJointAMotor *)j;
    euler_frame fr;
    if (m->mode == dAMotorEuler) euler_compute(m, &fr);
    // The limot code works in stored order: reversed, the stored body 0 is
    // user body 2, so the direction flips.
    dReal sign = (j->flags & DX_JOINT_REVERSE) ? -1 : 1;
    int row = 0;
    for (int i = 0; i < m->num; i++) {
        dVector3 dir;
        if (m->mode == dAMotorEuler) dCopyVector3(dir, fr.d[i]);
        else user_axis(m, i, dir);
        dScaleVector3(dir, sign);
        row += dxLimotAddRow(&m->limot[i], j, rows, row, dir, 1);
    }
}

// After dJointAttach. ODE 0.16 recomputes nothing, and keeps its axes by
// stored body: when the attachment turns round, an axis fixed to body 1
// becomes one fixed to body 2 and the other way round, in the same frame.
static void amotor_attached(dxJoint *j)
{
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (!dxJointBody(j, 0)) return;
    const int reversed = (j->flags & DX_JOINT_REVERSE) != 0;
    if (reversed == m->axes_reversed) return;
    m->axes_reversed = reversed;
    for (int i = 0; i < 3; i++) {
        if (m->rel[i]) m->rel[i] = 3 - m->rel[i];
        dVector3 t;
        dCopyVector4(t, m->eref1[i]);
        dCopyVector4(m->eref1[i], m->eref2[i]);
        dCopyVector4(m->eref2[i], t);
    }
}

static const dxJointClass amotor_class = {
    dJointTypeAMotor, "angular motor", sizeof(dxJointAMotor), amotor_init, amotor_count_rows,
    amotor_fill_rows, amotor_attached
};

// ---- public API -------------------------------------------------------------

dJointID dJointCreateAMotor(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &amotor_class);
}

#define AMOTOR(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeAMotor, on_fail)
#define CHECK_ANUM(anum, on_fail) \
    DX_CHECK_ARG((anum) >= 0 && (anum) <= 2, on_fail, "anum must be 0, 1 or 2, got %d", (anum))

void dJointSetAMotorMode(dJointID j, int mode)
{
    AMOTOR(j, return);
    DX_CHECK_ARG(mode == dAMotorUser || mode == dAMotorEuler, return,
                 "mode must be dAMotorUser (0) or dAMotorEuler (1), got %d", mode);
    dxJointAMotor *m = (dxJointAMotor *)j;
    m->mode = mode;
    if (mode == dAMotorEuler) {
        m->num = 3;
        if (dxJointBody(j, 0)) euler_set_reference(m);
    }
}

int dJointGetAMotorMode(dJointID j)
{
    AMOTOR(j, return dAMotorUser);
    return ((dxJointAMotor *)j)->mode;
}

void dJointSetAMotorNumAxes(dJointID j, int num)
{
    AMOTOR(j, return);
    DX_CHECK_ARG(num >= 0 && num <= 3, return, "num must be 0..3, got %d", num);
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (m->mode == dAMotorUser) m->num = num;   // Euler mode always has 3
}

int dJointGetAMotorNumAxes(dJointID j)
{
    AMOTOR(j, return 0);
    return ((dxJointAMotor *)j)->num;
}

void dJointSetAMotorAxis(dJointID j, int anum, int rel, dReal x, dReal y, dReal z)
{
    AMOTOR(j, return);
    CHECK_ANUM(anum, return);
    DX_CHECK_ARG(rel >= 0 && rel <= 2, return, "rel must be 0, 1 or 2, got %d", rel);
    dVector3 a = { x, y, z, 0 };
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dSafeNormalize3(a), return,
                 "axis (%g, %g, %g) has no direction", (double)x, (double)y, (double)z);
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (!dxJointBody(j, 0)) return;   // not attached: setters do nothing
    m->rel[anum] = rel;
    from_world(j, rel - 1, m->axis[anum], a);
    if (m->mode == dAMotorEuler) euler_set_reference(m);
}

void dJointGetAMotorAxis(dJointID j, int anum, dVector3 result)
{
    AMOTOR(j, return);
    CHECK_ANUM(anum, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (m->mode == dAMotorEuler && dxJointBody(j, 0)) {
        euler_frame fr;
        euler_compute(m, &fr);
        dCopyVector3(result, fr.ax[anum]);
    } else {
        user_axis(m, anum, result);
    }
}

int dJointGetAMotorAxisRel(dJointID j, int anum)
{
    AMOTOR(j, return 0);
    CHECK_ANUM(anum, return 0);
    return ((dxJointAMotor *)j)->rel[anum];
}

void dJointSetAMotorAngle(dJointID j, int anum, dReal angle)
{
    AMOTOR(j, return);
    CHECK_ANUM(anum, return);
    DX_CHECK_ARG(dxIsFinite(angle), return, "angle is not finite");
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (m->mode != dAMotorUser) {
        dxReportMessage(__func__, "has no effect in Euler mode (the angles are measured)");
        return;
    }
    m->angle[anum] = angle;
}

dReal dJointGetAMotorAngle(dJointID j, int anum)
{
    AMOTOR(j, return 0);
    CHECK_ANUM(anum, return 0);
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (m->mode == dAMotorUser) return m->angle[anum];
    if (!dxJointBody(j, 0)) return 0;
    euler_frame fr;
    euler_compute(m, &fr);
    return fr.angle[anum];
}

dReal dJointGetAMotorAngleRate(dJointID j, int anum)
{
    AMOTOR(j, return 0);
    CHECK_ANUM(anum, return 0);
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (m->mode == dAMotorUser || !dxJointBody(j, 0)) return 0;   // guide: 0 in user mode
    euler_frame fr;
    euler_compute(m, &fr);
    const struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    dReal rate = 0;
    if (b1) rate += dCalcVectorDot3(fr.d[anum], b1->avel);
    if (b2) rate -= dCalcVectorDot3(fr.d[anum], b2->avel);
    return rate;
}

void dJointSetAMotorParam(dJointID j, int parameter, dReal value)
{
    AMOTOR(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    int group, param;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return;
    dxLimotSetParam(&((dxJointAMotor *)j)->limot[group], param, value);
}

dReal dJointGetAMotorParam(dJointID j, int parameter)
{
    AMOTOR(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return 0;
    dxLimotGetParam(&((dxJointAMotor *)j)->limot[group], param, &value);
    return value;
}

void dJointAddAMotorTorques(dJointID j, dReal torque1, dReal torque2, dReal torque3)
{
    AMOTOR(j, return);
    DX_CHECK_ARG(dxIsFinite3(torque1, torque2, torque3), return, "torque is not finite");
    dxJointAMotor *m = (dxJointAMotor *)j;
    if (!dxJointBody(j, 0)) return;
    const dReal torque[3] = { torque1, torque2, torque3 };
    euler_frame fr;
    if (m->mode == dAMotorEuler) euler_compute(m, &fr);
    dVector3 t = { 0, 0, 0, 0 }, a;
    for (int i = 0; i < m->num; i++) {   // torques beyond num are ignored (guide)
        if (m->mode == dAMotorEuler) dCopyVector3(a, fr.ax[i]);
        else user_axis(m, i, a);
        dAddVectorScaledVector3(t, t, a, torque[i]);
    }
    struct dxBody *b1 = user_body(j, 0), *b2 = user_body(j, 1);
    if (b1) dAddVectors3(b1->torque, b1->torque, t);
    if (b2) dSubtractVectors3(b2->torque, b2->torque, t);
}
