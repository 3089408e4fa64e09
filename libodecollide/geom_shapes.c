// SPDX-License-Identifier: BSD-3-Clause
//
// geom_shapes.c -- the sphere, box, capsule and cylinder classes (guide
// 10.7.1, 10.7.2, 10.7.4, and the flat-ended cylinder): creation, size
// setters and getters, bounding boxes, and the point-depth functions.

#include "shapes.h"

#define CHECK_CLASS(g, c, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->ops->cls == (c), on_fail, "geom is a %s, not a %s", (g)->ops->name, \
                     (c) == dSphereClass ? "sphere" : (c) == dBoxClass ? "box" \
                     : (c) == dCapsuleClass ? "capsule" : "cylinder"); \
    } while (0)
// Sizes may be zero (ODE creates shapes that are sized later); colliders
// take a zero size as a point, a segment or a flat box.
#define CHECK_NON_NEGATIVE(v, what, on_fail) \
    DX_CHECK_ARG((v) >= 0 && dxIsFinite(v), on_fail, what " must be >= 0 and finite, got %g", \
                 (double)(v))

void dxAABBOfBox(dReal aabb[6], const dReal *pos, const dReal *R, const dReal h[3])
{
    for (int i = 0; i < 3; i++) {
        dReal e = dFabs(R[4 * i]) * h[0] + dFabs(R[4 * i + 1]) * h[1] + dFabs(R[4 * i + 2]) * h[2];
        aabb[2 * i] = pos[i] - e;
        aabb[2 * i + 1] = pos[i] + e;
    }
}

// A point in the geom's frame.
static void to_local(const dxGeom *g, dReal x, dReal y, dReal z, dVector3 out)
{
    dVector3 d = { x - g->pos[0], y - g->pos[1], z - g->pos[2], 0 };
    dMultiply1_331(out, g->R, d);
}

// ---- sphere -----------------------------------------------------------------

static void sphere_aabb(dxGeom *g)
{
    dReal r = ((dxSphere *)g)->radius;
    for (int i = 0; i < 3; i++) {
        g->aabb[2 * i] = g->pos[i] - r;
        g->aabb[2 * i + 1] = g->pos[i] + r;
    }
}

const dxGeomClassOps dx_sphere_ops = { dSphereClass, "sphere", sphere_aabb, NULL };

dGeomID dCreateSphere(dSpaceID space, dReal radius)
{
    CHECK_NON_NEGATIVE(radius, "radius", return NULL);
    dxSphere *s = (dxSphere *)dxGeomCreate(sizeof *s, &dx_sphere_ops, DX_GEOM_PLACEABLE, space);
    s->radius = radius;
    return &s->g;
}

void dGeomSphereSetRadius(dGeomID g, dReal radius)
{
    CHECK_CLASS(g, dSphereClass, return);
    CHECK_NON_NEGATIVE(radius, "radius", return);
    ((dxSphere *)g)->radius = radius;
    dxGeomShapeChanged(g);
}

dReal dGeomSphereGetRadius(dGeomID g)
{
    CHECK_CLASS(g, dSphereClass, return 0);
    return ((dxSphere *)g)->radius;
}

dReal dGeomSpherePointDepth(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_CLASS(g, dSphereClass, return 0);
    dVector3 p = { x, y, z, 0 };
    return ((dxSphere *)g)->radius - dCalcPointsDistance3(p, g->pos);
}

// ---- box ----------------------------------------------------------------------

static void box_aabb(dxGeom *g)
{
    const dReal *s = ((dxBox *)g)->side;
    dReal h[3] = { s[0] / 2, s[1] / 2, s[2] / 2 };
    dxAABBOfBox(g->aabb, g->pos, g->R, h);
}

const dxGeomClassOps dx_box_ops = { dBoxClass, "box", box_aabb, NULL };

dGeomID dCreateBox(dSpaceID space, dReal lx, dReal ly, dReal lz)
{
    CHECK_NON_NEGATIVE(lx, "lx", return NULL);
    CHECK_NON_NEGATIVE(ly, "ly", return NULL);
    CHECK_NON_NEGATIVE(lz, "lz", return NULL);
    dxBox *b = (dxBox *)dxGeomCreate(sizeof *b, &dx_box_ops, DX_GEOM_PLACEABLE, space);
    dAssignVector3(b->side, lx, ly, lz);
    return &b->g;
}

void dGeomBoxSetLengths(dGeomID g, dReal lx, dReal ly, dReal lz)
{
    CHECK_CLASS(g, dBoxClass, return);
    CHECK_NON_NEGATIVE(lx, "lx", return);
    CHECK_NON_NEGATIVE(ly, "ly", return);
    CHECK_NON_NEGATIVE(lz, "lz", return);
    dAssignVector3(((dxBox *)g)->side, lx, ly, lz);
    dxGeomShapeChanged(g);
}

void dGeomBoxGetLengths(dGeomID g, dVector3 result)
{
    CHECK_CLASS(g, dBoxClass, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dCopyVector3(result, ((dxBox *)g)->side);
}

// Inside: distance to the nearest face (> 0). Outside: minus the distance to
// the box (< 0).
dReal dGeomBoxPointDepth(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_CLASS(g, dBoxClass, return 0);
    const dReal *side = ((dxBox *)g)->side;
    dVector3 p;
    to_local(g, x, y, z, p);
    dReal inside = dInfinity, outside2 = 0;
    for (int i = 0; i < 3; i++) {
        dReal d = side[i] / 2 - dFabs(p[i]);   // > 0 within the slab
        if (d < inside) inside = d;
        if (d < 0) outside2 += d * d;
    }
    return outside2 > 0 ? -dSqrt(outside2) : inside;
}

// ---- capsule --------------------------------------------------------------------

static void capsule_aabb(dxGeom *g)
{
    const dxCapsule *c = (const dxCapsule *)g;
    for (int i = 0; i < 3; i++) {
        dReal e = dFabs(g->R[4 * i + 2]) * c->length / 2 + c->radius;
        g->aabb[2 * i] = g->pos[i] - e;
        g->aabb[2 * i + 1] = g->pos[i] + e;
    }
}

const dxGeomClassOps dx_capsule_ops = { dCapsuleClass, "capsule", capsule_aabb, NULL };

dGeomID dCreateCapsule(dSpaceID space, dReal radius, dReal length)
{
    CHECK_NON_NEGATIVE(radius, "radius", return NULL);
    CHECK_NON_NEGATIVE(length, "length", return NULL);
    dxCapsule *c = (dxCapsule *)dxGeomCreate(sizeof *c, &dx_capsule_ops, DX_GEOM_PLACEABLE,
                                             space);
    c->radius = radius;
    c->length = length;
    return &c->g;
}

void dGeomCapsuleSetParams(dGeomID g, dReal radius, dReal length)
{
    CHECK_CLASS(g, dCapsuleClass, return);
    CHECK_NON_NEGATIVE(radius, "radius", return);
    CHECK_NON_NEGATIVE(length, "length", return);
    ((dxCapsule *)g)->radius = radius;
    ((dxCapsule *)g)->length = length;
    dxGeomShapeChanged(g);
}

void dGeomCapsuleGetParams(dGeomID g, dReal *radius, dReal *length)
{
    CHECK_CLASS(g, dCapsuleClass, return);
    DX_CHECK_ARG(radius != NULL && length != NULL, return, "radius or length is NULL");
    *radius = ((dxCapsule *)g)->radius;
    *length = ((dxCapsule *)g)->length;
}

dReal dGeomCapsulePointDepth(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_CLASS(g, dCapsuleClass, return 0);
    const dxCapsule *c = (const dxCapsule *)g;
    dVector3 p;
    to_local(g, x, y, z, p);
    dReal half = c->length / 2;
    dReal zc = p[2] < -half ? -half : p[2] > half ? half : p[2];   // nearest axis point
    dVector3 d = { p[0], p[1], p[2] - zc, 0 };
    return c->radius - dCalcVectorLength3(d);
}

// ---- cylinder -------------------------------------------------------------------

static void cylinder_aabb(dxGeom *g)
{
    const dxCylinder *c = (const dxCylinder *)g;
    for (int i = 0; i < 3; i++) {
        // The disc of radius r perpendicular to the axis a extends r sqrt(1 - a_i^2).
        dReal a = g->R[4 * i + 2];
        dReal disc = 1 - a * a;
        dReal e = dFabs(a) * c->length / 2 + c->radius * dSqrt(disc > 0 ? disc : 0);
        g->aabb[2 * i] = g->pos[i] - e;
        g->aabb[2 * i + 1] = g->pos[i] + e;
    }
}

const dxGeomClassOps dx_cylinder_ops = { dCylinderClass, "cylinder", cylinder_aabb, NULL };

dGeomID dCreateCylinder(dSpaceID space, dReal radius, dReal length)
{
    CHECK_NON_NEGATIVE(radius, "radius", return NULL);
    CHECK_NON_NEGATIVE(length, "length", return NULL);
    dxCylinder *c = (dxCylinder *)dxGeomCreate(sizeof *c, &dx_cylinder_ops, DX_GEOM_PLACEABLE,
                                               space);
    c->radius = radius;
    c->length = length;
    return &c->g;
}

void dGeomCylinderSetParams(dGeomID g, dReal radius, dReal length)
{
    CHECK_CLASS(g, dCylinderClass, return);
    CHECK_NON_NEGATIVE(radius, "radius", return);
    CHECK_NON_NEGATIVE(length, "length", return);
    ((dxCylinder *)g)->radius = radius;
    ((dxCylinder *)g)->length = length;
    dxGeomShapeChanged(g);
}

void dGeomCylinderGetParams(dGeomID g, dReal *radius, dReal *length)
{
    CHECK_CLASS(g, dCylinderClass, return);
    DX_CHECK_ARG(radius != NULL && length != NULL, return, "radius or length is NULL");
    *radius = ((dxCylinder *)g)->radius;
    *length = ((dxCylinder *)g)->length;
}
