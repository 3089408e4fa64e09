// SPDX-License-Identifier: BSD-3-Clause
//
// joint_plane2d.c -- the plane-2D joint (ODE 0.16): keeps its first body in
// the world plane z = 0 with its own z axis along the world's. Three rows:
// no velocity along z (with error correction of the height), no angular
// velocity about x or y (without correction: the tilt is held where it is, as
// in ODE, which leaves tilt correction to the application). Three optional
// motor rows drive the velocity along x, along y and about z, each with the
// parameters of a limit/motor group set through dJointSetPlane2DXParam,
// ...YParam and ...AngleParam. As in ODE 0.16 the stops are kept but never
// engage (there is no reference to measure x, y or the angle from); a second
// body takes part only in the motor rows.

#include "joint_geometry.h"

typedef struct dxJointPlane2D {
    dxJoint base;
    dxLimot motor[3];        // x, y, angle
} dxJointPlane2D;

static const dReal world_axes[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };

static void plane2d_init(dxJoint *j)
{
    dxJointPlane2D *p = (dxJointPlane2D *)j;
    for (int i = 0; i < 3; i++) dxLimotInit(&p->motor[i], j->world);
}

static void plane2d_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointPlane2D *p = (dxJointPlane2D *)j;
    count->m = 0;
    count->nub = 0;
    if (!dxJointBody(j, 0)) return;
    count->m = 3;
    count->nub = 3;
    for (int i = 0; i < 3; i++) count->m += p->motor[i].fmax > 0;
}

static void plane2d_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointPlane2D *p = (dxJointPlane2D *)j;
    const struct dxBody *b0 = dxJointBody(j, 0);
    const int s = rows->rowskip;
    rows->J1l[2] = 1;            // vz = 0, pulled back to z = 0
    rows->J1a[s] = 1;            // wx = 0
    rows->J1a[2 * s + 1] = 1;    // wy = 0
    rows->c[0] = -rows->fps * rows->erp * b0->pos[2];
    int row = 3;
    for (int i = 0; i < 3; i++)
        row += dxLimotAddRow(&p->motor[i], j, rows, row, world_axes[i], i == 2);
}

static const dxJointClass plane2d_class = {
    dJointTypePlane2D, "plane-2D", sizeof(dxJointPlane2D), plane2d_init, plane2d_count_rows,
    plane2d_fill_rows, NULL
};

dJointID dJointCreatePlane2D(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &plane2d_class);
}

#define PLANE2D(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypePlane2D, on_fail)
#define CHECK_VALUE(v, on_fail) DX_CHECK_ARG(!isnan(v), on_fail, "value is NaN")

// Set one parameter of motor i; the number has no group bits (one group each).
static void set_param(dxJoint *j, const char *function, int i, int parameter, dReal value)
{
    int group, param;
    if (!dxParamSplit(function, parameter, 1, &group, &param)) return;
    dxLimotSetParam(&((dxJointPlane2D *)j)->motor[i], param, value);
}

void dJointSetPlane2DXParam(dJointID j, int parameter, dReal value)
{
    PLANE2D(j, return);
    CHECK_VALUE(value, return);
    set_param(j, __func__, 0, parameter, value);
}

void dJointSetPlane2DYParam(dJointID j, int parameter, dReal value)
{
    PLANE2D(j, return);
    CHECK_VALUE(value, return);
    set_param(j, __func__, 1, parameter, value);
}

void dJointSetPlane2DAngleParam(dJointID j, int parameter, dReal value)
{
    PLANE2D(j, return);
    CHECK_VALUE(value, return);
    set_param(j, __func__, 2, parameter, value);
}
