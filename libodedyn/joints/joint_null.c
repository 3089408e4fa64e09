// SPDX-License-Identifier: BSD-3-Clause
//
// joint_null.c -- the null joint (dJointTypeNull): it connects two bodies
// (for the connectivity queries and islands) but adds no constraint rows.

#include "joint_geometry.h"

static void null_count_rows(dxJoint *j, dxJointRowCount *count)
{
    (void)j;
    count->m = 0;
    count->nub = 0;
}

// Never called by the steppers (no rows), present so every class is complete.
static void null_fill_rows(dxJoint *j, dxJointRows *rows)
{
    (void)j;
    (void)rows;
}

static const dxJointClass null_class = {
    dJointTypeNull, "null", sizeof(dxJoint), NULL, null_count_rows, null_fill_rows,
    NULL
};

dJointID dJointCreateNull(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &null_class);
}
