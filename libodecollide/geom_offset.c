// SPDX-License-Identifier: BSD-3-Clause
//
// geom_offset.c -- geom offsets (ODE 0.16): a geom on a body at a fixed pose
// relative to the body. The geom keeps its world pose in own_pos / own_R,
// recomputed whenever the body tells it that it moved (dGeomMoved), so every
// reader of the pose (colliders, bounding boxes, backends) sees the final
// pose without knowing about offsets.

#include "geom_internal.h"

#include <ode/memory.h>
#include <ode/rotation.h>

#define CHECK_OFFSET_GEOM(g, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->flags & DX_GEOM_PLACEABLE, on_fail, \
                     "a %s geom is not placeable (it has no position or rotation)", \
                     (g)->ops->name); \
        DX_CHECK_ARG((g)->body != NULL, on_fail, "the geom is not on a body"); \
    } while (0)

void dxGeomOffsetUpdate(dxGeom *g)
{
    const dReal *bp = dBodyGetPosition(g->body), *bR = dBodyGetRotation(g->body);
    dMultiply0_331(g->own_pos, bR, g->offset->pos);
    dAddVectors3(g->own_pos, g->own_pos, bp);
    dMultiply0_333(g->own_R, bR, g->offset->R);
}

void dxGeomOffsetFree(dxGeom *g)
{
    if (!g->offset) return;
    dFree(g->offset, sizeof *g->offset);
    g->offset = NULL;
}

// Put the body where it must be for the offset geom g to be at (pos, R):
// body_R = R offset_R^T, body_pos = pos - body_R offset_pos.
void dxGeomOffsetMoveBody(dxGeom *g, const dReal *pos, const dReal *R)
{
    dMatrix3 body_R;
    dVector3 d;
    dMultiply2_333(body_R, R, g->offset->R);
    dMultiply0_331(d, body_R, g->offset->pos);
    const dReal x = pos[0] - d[0], y = pos[1] - d[1], z = pos[2] - d[2];
    dBodySetRotation(g->body, body_R);   // moves g, and with it pos if it is g's
    dBodySetPosition(g->body, x, y, z);
}

// g's offset, made (identity) if it has none: its pose then lives in own_*.
static dxGeomOffset *offset_of(dxGeom *g)
{
    if (!g->offset) {
        g->offset = dAlloc(sizeof *g->offset);
        dZeroVector3(g->offset->pos);
        g->offset->pos[3] = 0;
        dRSetIdentity(g->offset->R);
        g->pos = g->own_pos;
        g->R = g->own_R;
    }
    return g->offset;
}

// The offset changed: the geom's world pose and bounding box follow.
static void offset_changed(dxGeom *g)
{
    dxGeomOffsetUpdate(g);
    dxGeomMarkMoved(g);
}

// R's nine used entries (the padding of a dMatrix3 is ignored) made exactly
// orthonormal into out; 0 if they are not finite or not a rotation.
int dxCleanRotation(const dReal *R, dMatrix3 out)
{
    if (!dxIsFiniteMatrix3(R)) return 0;
    dxCopyMatrix3(out, R);
    return dOrthogonalizeR(out);
}

// q normalised into out; 0 if it is not finite or has zero length.
int dxCleanQuaternion(const dReal *q, dQuaternion out)
{
    for (int i = 0; i < 4; i++) out[i] = q[i];
    return dxIsFinite(out[0]) && dxIsFinite3(out[1], out[2], out[3]) && dSafeNormalize4(out);
}

void dGeomSetOffsetPosition(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "position is not finite");
    dAssignVector3(offset_of(g)->pos, x, y, z);
    offset_changed(g);
}

void dGeomSetOffsetRotation(dGeomID g, const dMatrix3 R)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    dMatrix3 clean;
    DX_CHECK_ARG(dxCleanRotation(R, clean), return, "R is not a finite rotation");
    dCopyMatrix4x3(offset_of(g)->R, clean);
    offset_changed(g);
}

void dGeomSetOffsetQuaternion(dGeomID g, const dQuaternion q)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    dQuaternion n;
    DX_CHECK_ARG(dxCleanQuaternion(q, n), return, "q is not finite or has zero length");
    dRfromQ(offset_of(g)->R, n);
    offset_changed(g);
}

// offset_pos = body_R^T (p - body_pos).
void dGeomSetOffsetWorldPosition(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "position is not finite");
    const dReal *bp = dBodyGetPosition(g->body), *bR = dBodyGetRotation(g->body);
    const dVector3 d = { x - bp[0], y - bp[1], z - bp[2], 0 };
    dMultiply1_331(offset_of(g)->pos, bR, d);
    offset_changed(g);
}

// offset_R = body_R^T R.
static void set_offset_world_rotation(dxGeom *g, const dMatrix3 R)
{
    dMultiply1_333(offset_of(g)->R, dBodyGetRotation(g->body), R);
    offset_changed(g);
}

void dGeomSetOffsetWorldRotation(dGeomID g, const dMatrix3 R)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    dMatrix3 clean;
    DX_CHECK_ARG(dxCleanRotation(R, clean), return, "R is not a finite rotation");
    set_offset_world_rotation(g, clean);
}

void dGeomSetOffsetWorldQuaternion(dGeomID g, const dQuaternion q)
{
    CHECK_OFFSET_GEOM(g, return);
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    dQuaternion n;
    DX_CHECK_ARG(dxCleanQuaternion(q, n), return, "q is not finite or has zero length");
    dMatrix3 R;
    dRfromQ(R, n);
    set_offset_world_rotation(g, R);
}

void dGeomClearOffset(dGeomID g)
{
    DX_CHECK_GEOM(g, return);
    if (!g->offset) return;
    dxGeomOffsetFree(g);
    g->pos = dBodyGetPosition(g->body);
    g->R = dBodyGetRotation(g->body);
    dxGeomMarkMoved(g);
}

int dGeomIsOffset(dGeomID g)
{
    DX_CHECK_GEOM(g, return 0);
    return g->offset != NULL;
}

static const dReal zero_position[4] = { 0, 0, 0, 0 };
static const dReal identity_rotation[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };

const dReal *dGeomGetOffsetPosition(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->offset ? g->offset->pos : zero_position;
}

void dGeomCopyOffsetPosition(dGeomID g, dVector3 pos)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(pos != NULL, return, "pos is NULL");
    dCopyVector3(pos, g->offset ? g->offset->pos : zero_position);
}

const dReal *dGeomGetOffsetRotation(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->offset ? g->offset->R : identity_rotation;
}

void dGeomCopyOffsetRotation(dGeomID g, dMatrix3 R)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    dCopyMatrix4x3(R, g->offset ? g->offset->R : identity_rotation);
}

void dGeomGetOffsetQuaternion(dGeomID g, dQuaternion result)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    if (g->offset) dQfromR(result, g->offset->R);
    else dQSetIdentity(result);
}
