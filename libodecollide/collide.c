// SPDX-License-Identifier: BSD-3-Clause
//
// collide.c -- dCollide (guide 10.5.2): argument checks, colliders the
// program set for a pair of classes, spaces passed as arguments (their
// contents are collided), geometry transforms, user classes, and otherwise
// the selected backend's narrow phase. A pair of built-in classes that this
// would hand to a native collider goes there straight (dx_routes).

#include "backend_internal.h"
#include "shapes.h"
#include "user_class.h"

// Contacts produced for (b, a) made into contacts for (a, b).
void dxFlipContacts(dContactGeom *c, int n, int skip)
{
    for (int i = 0; i < n; i++) {
        dContactGeom *k = dxContactAt(c, i, skip);
        dNegateVector3(k->normal);
        dGeomID g = k->g1;
        k->g1 = k->g2;
        k->g2 = g;
        int s = k->side1;
        k->side1 = k->side2;
        k->side2 = s;
    }
}

static int collide_any(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip);

// A transform collides through the geom it holds, posed in the world. The
// held geom's collider names that geom in g1/g2, which info mode 0 (the
// guide's default) keeps; mode 1 names the transform instead, which has the
// body and the world pose (guide 10.7.7).
static int collide_transform(dxGeomTransform *t, dxGeom *other, int transform_first, int flags,
                             dContactGeom *c, int skip)
{
    if (!t->obj) return 0;
    const dReal *pos, *R;
    dxGeom *obj = dxTransformPoseObject(t, &pos, &R);
    int n = transform_first ? collide_any(obj, other, flags, c, skip)
                            : collide_any(other, obj, flags, c, skip);
    dxTransformRestore(t, pos, R);
    if (t->info == 1) {
        for (int i = 0; i < n; i++) {
            dContactGeom *k = dxContactAt(c, i, skip);
            if (k->g1 == obj) k->g1 = &t->g;
            if (k->g2 == obj) k->g2 = &t->g;
        }
    }
    return n;
}

// User classes collide through the collider their class gives for the other
// class (tried both ways round); without one they do not touch. Sets
// *handled when a user class was involved.
static int collide_user(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip,
                        int *handled)
{
    const dxUserClass *u1 = dxUserClassOf(o1), *u2 = dxUserClassOf(o2);
    *handled = u1 || u2;
    dColliderFn *fn;
    if (u1 && (fn = dxUserColliderFor(o1, o2->ops->cls))) return fn(o1, o2, flags, c, skip);
    if (u2 && (fn = dxUserColliderFor(o2, o1->ops->cls))) {
        int n = fn(o2, o1, flags, c, skip);
        dxFlipContacts(c, n, skip);
        return n;
    }
    return 0;
}

// Every geom of space s against other (s first or second), until the
// contact budget in flags is spent.
static int collide_space_contents(dxSpace *s, dxGeom *other, int space_first, int flags,
                                  dContactGeom *c, int skip)
{
    const int max = flags & 0xffff, rest = flags & ~0xffff;
    int n = 0;
    for (int i = 0; i < s->count && n < max; i++) {
        dxGeom *g = s->geoms[i];
        dContactGeom *out = dxContactAt(c, n, skip);
        int budget = rest | (max - n);
        n += space_first ? collide_any(g, other, budget, out, skip)
                         : collide_any(other, g, budget, out, skip);
    }
    return n;
}

// dCollide after its checks, in this order: a geom never touches itself,
// geoms of one body never touch, a program's override for the pair of
// classes (dSetColliderOverride) answers, spaces are opened, transforms are
// unwrapped, user classes use their colliders, the rest goes to the backend.
static int collide_any(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    if (o1 == o2) return 0;
    if (o1->body && o1->body == o2->body) return 0;   // parts of one rigid body
    int handled, n = dxCollideOverride(o1, o2, flags, c, skip, &handled);
    if (handled) return n;
    if (o1->flags & DX_GEOM_IS_SPACE)
        return collide_space_contents((dxSpace *)o1, o2, 1, flags, c, skip);
    if (o2->flags & DX_GEOM_IS_SPACE)
        return collide_space_contents((dxSpace *)o2, o1, 0, flags, c, skip);
    if (o1->ops->cls == dGeomTransformClass)
        return collide_transform((dxGeomTransform *)o1, o2, 1, flags, c, skip);
    if (o2->ops->cls == dGeomTransformClass)
        return collide_transform((dxGeomTransform *)o2, o1, 0, flags, c, skip);
    n = collide_user(o1, o2, flags, c, skip, &handled);
    if (handled) return n;
    return dxBackendCollide(o1, o2, flags, c, skip);
}

int dCollide(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip)
{
    DX_CHECK_ARG(dxGeomIsLive(o1), return 0, "o1 is NULL or was destroyed");
    DX_CHECK_ARG(dxGeomIsLive(o2), return 0, "o2 is NULL or was destroyed");
    DX_CHECK_ARG(skip >= (int)sizeof(dContactGeom), return 0,
                 "skip (%d) is smaller than sizeof(dContactGeom) (%d)", skip,
                 (int)sizeof(dContactGeom));
    DX_CHECK_ARG(contact != NULL, return 0, "contact is NULL");
    if ((flags & 0xffff) == 0) flags |= 1;   // guide 10.5.2: zero contacts means one
    // Two built-in geoms whose pair ends in a native collider: collide_any's
    // first two answers, then that collider, without the way there.
    const unsigned c1 = (unsigned)o1->ops->cls, c2 = (unsigned)o2->ops->cls;
    if (c1 < DX_ROUTE_CLASSES && c2 < DX_ROUTE_CLASSES) {
        const dxRoute *r = dx_routes[c1][c2];
        if (r) {
            if (o1 == o2 || (o1->body && o1->body == o2->body)) return 0;
            if (!r->reverse) return r->fn(o1, o2, flags, contact, skip);
            const int n = r->fn(o2, o1, flags, contact, skip);
            dxFlipContacts(contact, n, skip);
            return n;
        }
    }
    return collide_any(o1, o2, flags, contact, skip);
}
