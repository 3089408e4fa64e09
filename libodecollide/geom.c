// SPDX-License-Identifier: BSD-3-Clause
//
// geom.c -- what all geoms share (guide 10.2, 10.4): creation and
// destruction, user data, the body link and the three hooks the dynamics
// library calls (10.11.2), pose, bounding box, class, category and collide
// bits, enabling, and point conversions.

#include "../libodedyn/core/objects_internal.h"
#include "backend_internal.h"
#include "geom_internal.h"

#include <ode/memory.h>
#include <ode/rotation.h>

#define CHECK_PLACEABLE(g, on_fail) \
    DX_CHECK_ARG((g)->flags & DX_GEOM_PLACEABLE, on_fail, \
                 "a %s geom is not placeable (it has no position or rotation)", (g)->ops->name)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

// ---- memory ----------------------------------------------------------------
//
// A destroyed geom's block is kept for the next geom of the same size, so that
// checking a stale handle reads a poisoned header, never freed memory (bodies
// are pooled the same way). One free list per size, linked through
// body_next; the classes give few sizes, and a block whose size finds no room
// in the table goes back to the system.

enum { POOL_SIZES = 32 };

static struct geom_pool {
    size_t size;
    dxGeom *free_list;
} pools[POOL_SIZES];

// The pool of blocks of `size` bytes; with `create`, a free slot becomes it.
static struct geom_pool *pool_for(size_t size, int create)
{
    for (int i = 0; i < POOL_SIZES; i++) {
        if (pools[i].size == size) return &pools[i];
        if (pools[i].size == 0) {
            if (!create) return NULL;
            pools[i].size = size;
            return &pools[i];
        }
    }
    return NULL;
}

static dxGeom *geom_alloc(size_t size)
{
    struct geom_pool *p = pool_for(size, 0);
    if (!p || !p->free_list) return dAlloc(size);
    dxGeom *g = p->free_list;
    p->free_list = g->body_next;
    return g;
}

// g's header is already poisoned.
static void geom_free(dxGeom *g)
{
    struct geom_pool *p = pool_for(g->alloc_size, 1);
    if (!p) {
        dFree(g, g->alloc_size);
        return;
    }
    g->body_next = p->free_list;
    p->free_list = g;
}

// ---- creation and destruction ------------------------------------------------

dxGeom *dxGeomCreate(size_t size, const dxGeomClassOps *ops, unsigned flags, dSpaceID space)
{
    dxGeom *g = geom_alloc(size);
    memset(g, 0, size);
    g->magic = DX_MAGIC_GEOM;
    g->alloc_size = size;
    g->ops = ops;
    g->flags = flags | DX_GEOM_ENABLED | DX_GEOM_AABB_BAD;
    g->pos = g->own_pos;
    g->R = g->own_R;
    dRSetIdentity(g->own_R);
    g->category_bits = ~0ul;
    g->collide_bits = ~0ul;
    g->space_index = -1;
    if (space) dSpaceAdd(space, g);
    return g;
}

void dxGeomMarkMoved(dxGeom *g)
{
    if (g->offset) dxGeomOffsetUpdate(g);   // its body moved: so did it
    // A geom held by a transform moves the transform (its own flag is set
    // and cleared by every collision of the transform, so it cannot stop the
    // walk). Otherwise stop at the first geom or space that already knows:
    // its parents know too.
    for (; g && g->holder; g = g->holder) g->flags |= DX_GEOM_AABB_BAD;
    for (; g && !(g->flags & DX_GEOM_AABB_BAD); g = (dxGeom *)g->space)
        g->flags |= DX_GEOM_AABB_BAD;
}

void dxGeomShapeChanged(dxGeom *g)
{
    g->shape_version++;
    g->flags &= ~(unsigned)DX_GEOM_AABB_BAD;   // force the walk up to the spaces
    dxGeomMarkMoved(g);
    dxBackendGeomChanged(g);
}

void dxGeomUpdateAABB(dxGeom *g)
{
    if (!(g->flags & DX_GEOM_AABB_BAD)) return;
    if (g->flags & DX_GEOM_IS_SPACE) dxSpaceUpdateAABBs((dxSpace *)g);
    else g->ops->compute_aabb(g);
    g->flags &= ~(unsigned)DX_GEOM_AABB_BAD;
}

void dGeomDestroy(dGeomID g)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(!g->space || g->space->lock_count == 0, return,
                 "the geom's space is being collided (dSpaceCollide callback)");
    DX_CHECK_ARG(!(g->flags & DX_GEOM_IS_SPACE) || ((dxSpace *)g)->lock_count == 0, return,
                 "the space is being collided (dSpaceCollide callback)");
    DX_CHECK_ARG(!g->holder, return,
                 "the geom is held by a geometry transform; destroy or empty that first");
    if (g->space) dSpaceRemove(g->space, g);
    if (g->body) dGeomSetBody(g, 0);
    if (g->ops->destroy) g->ops->destroy(g);
    dxBackendGeomDestroyed(g);
    g->magic = DX_MAGIC_GEOM_DEAD;
    geom_free(g);
}

void dGeomSetData(dGeomID g, void *data)
{
    DX_CHECK_GEOM(g, return);
    g->data = data;
}

void *dGeomGetData(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->data;
}

// ---- the body link and the hooks of guide 10.11.2 ------------------------

// Remove g from its body's geom list (kept by the body: dBodyGetFirstGeom).
static void unlink_from_body(dxGeom *g)
{
    dxGeom *first = dBodyGetFirstGeom(g->body);
    if (first == g) {
        dBodySetFirstGeom(g->body, g->body_next);
    } else {
        dxGeom *p = first;
        while (p && p->body_next != g) p = p->body_next;
        if (p) p->body_next = g->body_next;
    }
    g->body_next = NULL;
}

// Attaching shares the body's pose (pos and R point at the body's) and puts g
// at the head of the body's list; detaching copies the last pose into the
// geom. The pose does not change on detaching, so the AABB stays valid. An
// offset is dropped either way (as in ODE 0.16).
void dGeomSetBody(dGeomID g, dBodyID b)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    DX_CHECK_ARG(b == NULL || dxBodyIsLive(b), return, "body was destroyed");
    DX_CHECK_ARG(b == NULL || !g->holder, return,
                 "the geom is held by a geometry transform (attach the transform instead)");
    if (g->body == b) return;
    dxGeomOffsetFree(g);   // detached, it stays where it is; on another body, at its pose
    if (g->body) {
        // Keep the body's last pose as the geom's own.
        dCopyVector3(g->own_pos, g->pos);
        dCopyMatrix4x3(g->own_R, g->R);
        unlink_from_body(g);
        g->pos = g->own_pos;
        g->R = g->own_R;
        g->body = NULL;
    }
    if (b) {
        dxGeomRegisterDifWriter();   // a world with geoms on bodies may be exported
        g->body = b;
        g->body_next = dBodyGetFirstGeom(b);
        dBodySetFirstGeom(b, g);
        g->pos = dBodyGetPosition(b);
        g->R = dBodyGetRotation(b);
        dxGeomMarkMoved(g);
    }
}

dBodyID dGeomGetBody(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->body;
}

void dGeomMoved(dGeomID g)
{
    DX_CHECK_GEOM(g, return);
    dxGeomMarkMoved(g);
}

dGeomID dGeomGetBodyNext(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->body_next;
}

// ---- pose -------------------------------------------------------------------

void dGeomSetPosition(dGeomID g, dReal x, dReal y, dReal z)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "position is not finite");
    if (g->offset) {   // move the body so that the geom gets there
        dVector3 d;
        dMultiply0_331(d, dBodyGetRotation(g->body), g->offset->pos);
        dBodySetPosition(g->body, x - d[0], y - d[1], z - d[2]);
    } else if (g->body) {
        dBodySetPosition(g->body, x, y, z);   // tells every geom of the body
    } else {
        dAssignVector3(g->own_pos, x, y, z);
        dxGeomMarkMoved(g);
    }
}

void dGeomSetRotation(dGeomID g, const dMatrix3 R)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    if (g->offset) {   // turn the body so that the geom turns about its position
        dMatrix3 clean;
        DX_CHECK_ARG(dxCleanRotation(R, clean), return, "R is not a finite rotation");
        const dVector3 pos = { g->pos[0], g->pos[1], g->pos[2], 0 };
        dxGeomOffsetMoveBody(g, pos, clean);
    } else if (g->body) {
        dBodySetRotation(g->body, R);
    } else {
        dMatrix3 clean;   // without the padding, which may be uninitialised
        DX_CHECK_ARG(dxCleanRotation(R, clean), return, "R is not a finite rotation");
        dCopyMatrix4x3(g->own_R, clean);
        dxGeomMarkMoved(g);
    }
}

void dGeomSetQuaternion(dGeomID g, const dQuaternion q)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    if (g->offset) {   // turn the body so that the geom turns about its position
        dQuaternion n;
        DX_CHECK_ARG(dxCleanQuaternion(q, n), return, "q is not finite or has zero length");
        dMatrix3 R;
        dRfromQ(R, n);
        const dVector3 pos = { g->pos[0], g->pos[1], g->pos[2], 0 };
        dxGeomOffsetMoveBody(g, pos, R);
    } else if (g->body) {
        dBodySetQuaternion(g->body, q);
    } else {
        dQuaternion n;
        DX_CHECK_ARG(dxCleanQuaternion(q, n), return, "q is not finite or has zero length");
        dRfromQ(g->own_R, n);
        dxGeomMarkMoved(g);
    }
}

const dReal *dGeomGetPosition(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    CHECK_PLACEABLE(g, return NULL);
    return g->pos;
}

void dGeomCopyPosition(dGeomID g, dVector3 pos)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(pos, return);
    dCopyVector3(pos, g->pos);
}

const dReal *dGeomGetRotation(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    CHECK_PLACEABLE(g, return NULL);
    return g->R;
}

void dGeomCopyRotation(dGeomID g, dMatrix3 R)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(R, return);
    dCopyMatrix4x3(R, g->R);
}

void dGeomGetQuaternion(dGeomID g, dQuaternion result)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(result, return);
    if (g->body) dCopyVector4(result, dBodyGetQuaternion(g->body));
    else dQfromR(result, g->R);
}

void dGeomGetAABB(dGeomID g, dReal aabb[6])
{
    DX_CHECK_GEOM(g, return);
    CHECK_RESULT(aabb, return);
    dxGeomUpdateAABB(g);
    memcpy(aabb, g->aabb, sizeof g->aabb);
}

int dGeomIsSpace(dGeomID g)
{
    DX_CHECK_GEOM(g, return 0);
    return (g->flags & DX_GEOM_IS_SPACE) != 0;
}

dSpaceID dGeomGetSpace(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    return g->space;
}

int dGeomGetClass(dGeomID g)
{
    DX_CHECK_GEOM(g, return -1);
    return g->ops->cls;
}

void dGeomSetCategoryBits(dGeomID g, unsigned long bits)
{
    DX_CHECK_GEOM(g, return);
    g->category_bits = bits;
}

void dGeomSetCollideBits(dGeomID g, unsigned long bits)
{
    DX_CHECK_GEOM(g, return);
    g->collide_bits = bits;
}

unsigned long dGeomGetCategoryBits(dGeomID g)
{
    DX_CHECK_GEOM(g, return 0);
    return g->category_bits;
}

unsigned long dGeomGetCollideBits(dGeomID g)
{
    DX_CHECK_GEOM(g, return 0);
    return g->collide_bits;
}

void dGeomEnable(dGeomID g)
{
    DX_CHECK_GEOM(g, return);
    g->flags |= DX_GEOM_ENABLED;
}

void dGeomDisable(dGeomID g)
{
    DX_CHECK_GEOM(g, return);
    g->flags &= ~(unsigned)DX_GEOM_ENABLED;
}

int dGeomIsEnabled(dGeomID g)
{
    DX_CHECK_GEOM(g, return 0);
    return (g->flags & DX_GEOM_ENABLED) != 0;
}

// ---- point conversions ------------------------------------------------------

void dGeomGetRelPointPos(dGeomID g, dReal px, dReal py, dReal pz, dVector3 result)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(result, return);
    dVector3 p = { px, py, pz, 0 };
    dMultiply0_331(result, g->R, p);
    dAddVectors3(result, result, g->pos);
}

void dGeomGetPosRelPoint(dGeomID g, dReal px, dReal py, dReal pz, dVector3 result)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(result, return);
    dVector3 d = { px - g->pos[0], py - g->pos[1], pz - g->pos[2], 0 };
    dMultiply1_331(result, g->R, d);
}

void dGeomVectorToWorld(dGeomID g, dReal px, dReal py, dReal pz, dVector3 result)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(result, return);
    dVector3 v = { px, py, pz, 0 };
    dMultiply0_331(result, g->R, v);
}

void dGeomVectorFromWorld(dGeomID g, dReal px, dReal py, dReal pz, dVector3 result)
{
    DX_CHECK_GEOM(g, return);
    CHECK_PLACEABLE(g, return);
    CHECK_RESULT(result, return);
    dVector3 v = { px, py, pz, 0 };
    dMultiply1_331(result, g->R, v);
}

void dInfiniteAABB(dGeomID g, dReal aabb[6])
{
    (void)g;
    CHECK_RESULT(aabb, return);
    for (int i = 0; i < 6; i += 2) {
        aabb[i] = -dInfinity;
        aabb[i + 1] = dInfinity;
    }
}
