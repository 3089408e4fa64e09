// SPDX-License-Identifier: BSD-3-Clause
//
// geom_transform.c -- the geometry transform class (guide 10.7.7): a geom that
// holds one other geom whose position and rotation are taken relative to the
// transform. The held geom is in no space and on no body.

#include "shapes.h"

#define CHECK_TRANSFORM(g, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->ops->cls == dGeomTransformClass, on_fail, \
                     "geom is a %s, not a geometry transform", (g)->ops->name); \
    } while (0)

dxGeom *dxTransformPoseObject(dxGeomTransform *t, const dReal **saved_pos, const dReal **saved_R)
{
    dxGeom *obj = t->obj;
    dMultiply0_331(t->world_pos, t->g.R, obj->own_pos);
    dAddVectors3(t->world_pos, t->world_pos, t->g.pos);
    dMultiply0_333(t->world_R, t->g.R, obj->own_R);
    *saved_pos = obj->pos;
    *saved_R = obj->R;
    obj->pos = t->world_pos;
    obj->R = t->world_R;
    obj->flags |= DX_GEOM_AABB_BAD;
    return obj;
}

void dxTransformRestore(dxGeomTransform *t, const dReal *saved_pos, const dReal *saved_R)
{
    t->obj->pos = saved_pos;
    t->obj->R = saved_R;
    t->obj->flags |= DX_GEOM_AABB_BAD;
}

// The held geom's box in its world pose; an empty box (touching nothing)
// when the transform holds nothing.
static void transform_aabb(dxGeom *g)
{
    dxGeomTransform *t = (dxGeomTransform *)g;
    if (!t->obj) {
        for (int i = 0; i < 6; i += 2) {
            g->aabb[i] = dInfinity;
            g->aabb[i + 1] = -dInfinity;
        }
        return;
    }
    const dReal *pos, *R;
    dxGeom *obj = dxTransformPoseObject(t, &pos, &R);
    dxGeomUpdateAABB(obj);
    memcpy(g->aabb, obj->aabb, sizeof g->aabb);
    dxTransformRestore(t, pos, R);
}

// With cleanup on, the held geom goes with the transform.
static void release_object(dxGeomTransform *t)
{
    dxGeom *obj = t->obj;
    if (!obj) return;
    t->obj = NULL;
    obj->holder = NULL;
    if (t->cleanup) dGeomDestroy(obj);
}

static void transform_destroy(dxGeom *g) { release_object((dxGeomTransform *)g); }

const dxGeomClassOps dx_transform_ops = { dGeomTransformClass, "geometry transform",
                                          transform_aabb, transform_destroy };

// 1 if t is obj or is held, directly or through other transforms, by obj:
// holding obj would then make a cycle.
static int holds_chain_to(const dxGeom *obj, const dxGeom *t)
{
    while (obj && obj != t && obj->ops->cls == dGeomTransformClass)
        obj = ((const dxGeomTransform *)obj)->obj;
    return obj == t;
}

dGeomID dCreateGeomTransform(dSpaceID space)
{
    dxGeomTransform *t = (dxGeomTransform *)dxGeomCreate(sizeof *t, &dx_transform_ops,
                                                         DX_GEOM_PLACEABLE, space);
    return &t->g;
}

// With cleanup on, a geom held before is destroyed (guide 10.7.7).
void dGeomTransformSetGeom(dGeomID g, dGeomID obj)
{
    CHECK_TRANSFORM(g, return);
    DX_CHECK_ARG(obj == NULL || dxGeomIsLive(obj), return, "obj was destroyed");
    dxGeomTransform *t = (dxGeomTransform *)g;
    if (t->obj == obj) return;
    if (obj) {
        DX_CHECK_ARG(!holds_chain_to(obj, g), return,
                     "obj is the transform itself or holds it (a cycle)");
        DX_CHECK_ARG(!(obj->flags & DX_GEOM_IS_SPACE), return, "obj is a space");
        DX_CHECK_ARG(obj->space == NULL, return, "obj is in a space (it must not be)");
        DX_CHECK_ARG(obj->body == NULL, return, "obj is attached to a body (it must not be)");
        DX_CHECK_ARG(!obj->holder, return,
                     "obj is already held by a geometry transform");
        DX_CHECK_ARG(obj->flags & DX_GEOM_PLACEABLE, return, "obj (a %s) is not placeable",
                     obj->ops->name);
    }
    release_object(t);
    t->obj = obj;
    if (obj) obj->holder = g;
    dxGeomShapeChanged(g);
}

dGeomID dGeomTransformGetGeom(dGeomID g)
{
    CHECK_TRANSFORM(g, return NULL);
    return ((dxGeomTransform *)g)->obj;
}

void dGeomTransformSetCleanup(dGeomID g, int mode)
{
    CHECK_TRANSFORM(g, return);
    ((dxGeomTransform *)g)->cleanup = mode != 0;
}

int dGeomTransformGetCleanup(dGeomID g)
{
    CHECK_TRANSFORM(g, return 0);
    return ((dxGeomTransform *)g)->cleanup;
}

void dGeomTransformSetInfo(dGeomID g, int mode)
{
    CHECK_TRANSFORM(g, return);
    DX_CHECK_ARG(mode == 0 || mode == 1, return, "mode must be 0 or 1, got %d", mode);
    ((dxGeomTransform *)g)->info = mode;
}

int dGeomTransformGetInfo(dGeomID g)
{
    CHECK_TRANSFORM(g, return 0);
    return ((dxGeomTransform *)g)->info;
}
