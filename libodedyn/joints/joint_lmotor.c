// SPDX-License-Identifier: BSD-3-Clause
//
// joint_lmotor.c -- the linear motor (ODE 0.16): up to three motor rows on
// the relative linear velocity of two bodies, each along an axis fixed in
// the world, to body 1 or to body 2 (rel 0, 1, 2). Each axis has the
// parameters of a limit/motor group (dParamVel, dParamVel2, dParamVel3 ...);
// as in ODE 0.16 only the motors act: there is no position to stop at, so
// dParamLoStop / dParamHiStop are kept but never engage.
//
// As for the angular motor, bodies are in the user's order (body 1 and body 2
// of dJointAttach): a motor row is axis . (v1 - v2) = vel, with the forces
// applied at the midpoint of the centres so the pair exerts no couple, and a
// rel naming a missing body fixes the axis in the world. (ODE 0.16 ignores a
// reversed attachment (0, b) here: it fixes a rel 1 axis to b and moves b at
// +vel; this library fixes it in the world and moves b at -vel, as body 2.)

#include "joint_geometry.h"
#include "joint_kept.h"

typedef struct dxJointLMotor {
    dxJoint base;
    int num;                 // active axes, 0..3
    int rel[3];              // 0 world, 1 body 1, 2 body 2
    dVector3 axis[3];        // unit (or zero until set), in the frame rel names
    dxLimot limot[3];
} dxJointLMotor;

// User body k (0: body 1 of dJointAttach, 1: body 2), NULL for the static world.
static struct dxBody *user_body(const dxJoint *j, int k)
{
    return dxJointBody(j, (j->flags & DX_JOINT_REVERSE) ? 1 - k : k);
}

// The frame axis i is fixed in: its body, or NULL for the world.
static const struct dxBody *axis_frame(const dxJointLMotor *m, int i)
{
    return m->rel[i] > 0 ? user_body(&m->base, m->rel[i] - 1) : NULL;
}

// World direction of axis i.
static void world_axis(const dxJointLMotor *m, int i, dVector3 out)
{
    const struct dxBody *b = axis_frame(m, i);
    if (b) dMultiply0_331(out, b->R, m->axis[i]);
    else dCopyVector3(out, m->axis[i]);
    out[3] = 0;
}

static void lmotor_init(dxJoint *j)
{
    dxJointLMotor *m = (dxJointLMotor *)j;
    for (int i = 0; i < 3; i++) dxLimotInit(&m->limot[i], j->world);
}

static void lmotor_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointLMotor *m = (dxJointLMotor *)j;
    count->m = 0;
    count->nub = 0;
    if (!dxJointBody(j, 0)) return;
    for (int i = 0; i < m->num; i++) count->m += m->limot[i].fmax > 0;
}

static void lmotor_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointLMotor *m = (dxJointLMotor *)j;
    // The limot rows are in stored order: reversed, the stored body 0 is user
    // body 2, so the direction flips.
    const dReal sign = (j->flags & DX_JOINT_REVERSE) ? -1 : 1;
    int row = 0;
    for (int i = 0; i < m->num; i++) {
        dVector3 dir;
        world_axis(m, i, dir);
        dScaleVector3(dir, sign);
        row += dxLimotAddRow(&m->limot[i], j, rows, row, dir, 0);
    }
}

static const dxJointClass lmotor_class = {
    dJointTypeLMotor, "linear motor", sizeof(dxJointLMotor), lmotor_init, lmotor_count_rows,
    lmotor_fill_rows, NULL
};

dJointID dJointCreateLMotor(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &lmotor_class);
}

#define LMOTOR(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeLMotor, on_fail)
#define CHECK_ANUM(anum, on_fail) \
    DX_CHECK_ARG((anum) >= 0 && (anum) <= 2, on_fail, "anum must be 0, 1 or 2, got %d", (anum))

void dJointSetLMotorNumAxes(dJointID j, int num)
{
    LMOTOR(j, return);
    DX_CHECK_ARG(num >= 0 && num <= 3, return, "num must be 0..3, got %d", num);
    ((dxJointLMotor *)j)->num = num;
}

int dJointGetLMotorNumAxes(dJointID j)
{
    LMOTOR(j, return 0);
    return ((dxJointLMotor *)j)->num;
}

// The axis is kept in the frame rel names, so it turns with that body. Set it
// after attaching: before, every frame is the world's.
void dJointSetLMotorAxis(dJointID j, int anum, int rel, dReal x, dReal y, dReal z)
{
    LMOTOR(j, return);
    CHECK_ANUM(anum, return);
    DX_CHECK_ARG(rel >= 0 && rel <= 2, return, "rel must be 0, 1 or 2, got %d", rel);
    dVector3 a = { x, y, z, 0 };
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dSafeNormalize3(a), return,
                 "axis (%g, %g, %g) has no direction", (double)x, (double)y, (double)z);
    dxJointLMotor *m = (dxJointLMotor *)j;
    m->rel[anum] = rel;
    const struct dxBody *b = axis_frame(m, anum);
    if (b) dMultiply1_331(m->axis[anum], b->R, a);
    else dCopyVector3(m->axis[anum], a);
    m->axis[anum][3] = 0;
}

// The axis in world coordinates now. (ODE 0.16 returns it in the frame rel
// names, which is the world direction only for rel 0 or an unturned body.)
void dJointGetLMotorAxis(dJointID j, int anum, dVector3 result)
{
    LMOTOR(j, return);
    CHECK_ANUM(anum, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    world_axis((dxJointLMotor *)j, anum, result);
}

int dxJointLMotorAxisRel(const dxJoint *j, int anum)
{
    if (j->cls->type != dJointTypeLMotor || anum < 0 || anum > 2) return 0;
    return ((const dxJointLMotor *)j)->rel[anum];
}

void dJointSetLMotorParam(dJointID j, int parameter, dReal value)
{
    LMOTOR(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    int group, param;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return;
    dxLimotSetParam(&((dxJointLMotor *)j)->limot[group], param, value);
}

dReal dJointGetLMotorParam(dJointID j, int parameter)
{
    LMOTOR(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 3, &group, &param)) return 0;
    dxLimotGetParam(&((dxJointLMotor *)j)->limot[group], param, &value);
    return value;
}
