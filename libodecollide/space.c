// SPDX-License-Identifier: BSD-3-Clause
//
// space.c -- what all spaces share (guide 10.3, 10.6): creation and
// destruction with cleanup, adding and removing geoms, queries, bounding
// boxes, dSpaceCollide and dSpaceCollide2 (10.5.2). The pair search itself is
// each space type's (space_simple.c, space_hash.c, space_quadtree.c).
//
// Locking: while a space is being collided (lock_count > 0) its membership
// may not change (adding, removing, destroying its geoms or the space itself
// is reported and does nothing); reading it, e.g. dSpaceCollide2 on it from
// the callback, is allowed. Space types rebuild their search structure only
// when the space's bounding boxes were recomputed (the space's class
// compute_aabb, which a type may wrap, runs exactly then).

#include "geom_internal.h"
#include "space_pair.h"

#include <ode/memory.h>

#define CHECK_SPACE(s, on_fail) \
    DX_CHECK_ARG(dxGeomIsLive((dxGeom *)(s)) && ((dxGeom *)(s))->flags & DX_GEOM_IS_SPACE, \
                 on_fail, "space is NULL, was destroyed, or is not a space")
#define CHECK_UNLOCKED(s, on_fail) \
    DX_CHECK_ARG((s)->lock_count == 0, on_fail, \
                 "the space is being collided: a dSpaceCollide callback may not change it")

// A space's box is the union of its geoms' boxes (empty when it has none).
static void space_aabb(dxGeom *g)
{
    dxSpace *s = (dxSpace *)g;
    for (int i = 0; i < 6; i += 2) {
        g->aabb[i] = dInfinity;
        g->aabb[i + 1] = -dInfinity;
    }
    for (int k = 0; k < s->count; k++) {
        const dReal *b = s->geoms[k]->aabb;
        for (int i = 0; i < 6; i += 2) {
            if (b[i] < g->aabb[i]) g->aabb[i] = b[i];
            if (b[i + 1] > g->aabb[i + 1]) g->aabb[i + 1] = b[i + 1];
        }
    }
}

// Take g out of s (no checks), keeping the others in insertion order.
static void space_remove(dxSpace *s, dxGeom *g)
{
    if (s->sops->removed) s->sops->removed(s, g);
    for (int i = g->space_index; i < s->count - 1; i++) {
        s->geoms[i] = s->geoms[i + 1];
        s->geoms[i]->space_index = i;
    }
    s->count--;
    g->space = NULL;
    g->space_index = -1;
    s->geom.flags &= ~(unsigned)DX_GEOM_AABB_BAD;   // mark again so the parents hear of it
    dxGeomMarkMoved(&s->geom);
}

// The geoms are taken out first, so destroying them cannot fail on the
// space's lock (dSpaceDestroy refuses a locked space before getting here).
static void space_destroy(dxGeom *g)
{
    dxSpace *s = (dxSpace *)g;
    while (s->count > 0) {
        dxGeom *last = s->geoms[s->count - 1];
        space_remove(s, last);
        if (s->cleanup) dGeomDestroy(last);
    }
    if (s->sops->destroy) s->sops->destroy(s);
    dFree(s->geoms, (size_t)s->capacity * sizeof *s->geoms);
}

static const char *space_name(int cls)
{
    switch (cls) {
    case dSimpleSpaceClass: return "simple space";
    case dHashSpaceClass: return "hash space";
    case dSweepAndPruneSpaceClass: return "sweep-and-prune space";
    case dQuadTreeSpaceClass: return "quadtree space";
    default: return "space";
    }
}

static dxGeomClassOps space_ops[4];

dxSpace *dxSpaceCreate(size_t size, int cls, const dxSpaceOps *sops, dSpaceID parent)
{
    DX_CHECK_ARG(parent == NULL || (dxGeomIsLive((dxGeom *)parent) &&
                                    ((dxGeom *)parent)->flags & DX_GEOM_IS_SPACE),
                 return NULL, "space (the parent) is not a live space");
    dxGeomClassOps *ops = &space_ops[cls - dFirstSpaceClass];
    ops->cls = cls;
    ops->name = space_name(cls);
    ops->compute_aabb = space_aabb;
    ops->destroy = space_destroy;
    dxSpace *s = (dxSpace *)dxGeomCreate(size, ops, DX_GEOM_IS_SPACE, parent);
    s->sops = sops;
    s->cleanup = 1;
    return s;
}

void dSpaceDestroy(dSpaceID s)
{
    CHECK_SPACE(s, return);
    CHECK_UNLOCKED(s, return);
    dGeomDestroy(&s->geom);
}

void dSpaceSetCleanup(dSpaceID s, int mode)
{
    CHECK_SPACE(s, return);
    s->cleanup = mode != 0;
}

int dSpaceGetCleanup(dSpaceID s)
{
    CHECK_SPACE(s, return 0);
    return s->cleanup;
}

// Only kept: no per-thread collision data exists to release (collision_space.h).
void dSpaceSetManualCleanup(dSpaceID s, int mode)
{
    CHECK_SPACE(s, return);
    s->manual_cleanup = mode != 0;
}

int dSpaceGetManualCleanup(dSpaceID s)
{
    CHECK_SPACE(s, return 0);
    return s->manual_cleanup;
}

void dSpaceSetSublevel(dSpaceID s, int sublevel)
{
    CHECK_SPACE(s, return);
    s->sublevel = sublevel;
}

int dSpaceGetSublevel(dSpaceID s)
{
    CHECK_SPACE(s, return 0);
    return s->sublevel;
}

int dSpaceGetClass(dSpaceID s)
{
    CHECK_SPACE(s, return -1);
    return s->geom.ops->cls;
}

// 1 if `inner` is `outer` or lies somewhere inside it.
static int space_contains(const dxSpace *outer, const dxGeom *inner)
{
    for (const dxGeom *g = inner; g; g = (const dxGeom *)g->space)
        if (g == &outer->geom) return 1;
    return 0;
}

void dSpaceAdd(dSpaceID s, dGeomID g)
{
    CHECK_SPACE(s, return);
    DX_CHECK_GEOM(g, return);
    CHECK_UNLOCKED(s, return);
    DX_CHECK_ARG(g->space != s, return, "the geom is already in this space");
    DX_CHECK_ARG(g->space == NULL, return, "the geom is already in another space (a geom can "
                 "be in only one; remove it first)");
    DX_CHECK_ARG(!g->holder, return,
                 "the geom is held by a geometry transform");
    DX_CHECK_ARG(!(g->flags & DX_GEOM_IS_SPACE) || !space_contains((dxSpace *)g, &s->geom),
                 return, "adding the space to itself or to a space inside it");
    if (s->count == s->capacity) {
        int cap = s->capacity ? 2 * s->capacity : 16;
        s->geoms = dRealloc(s->geoms, (size_t)s->capacity * sizeof *s->geoms,
                            (size_t)cap * sizeof *s->geoms);
        s->capacity = cap;
    }
    g->space = s;
    g->space_index = s->count;
    s->geoms[s->count++] = g;
    if (s->sops->added) s->sops->added(s, g);
    g->flags &= ~(unsigned)DX_GEOM_AABB_BAD;   // mark again so the new parents hear of it
    dxGeomMarkMoved(g);
}

void dSpaceRemove(dSpaceID s, dGeomID g)
{
    CHECK_SPACE(s, return);
    DX_CHECK_GEOM(g, return);
    CHECK_UNLOCKED(s, return);
    DX_CHECK_ARG(g->space == s, return, "the geom is not in this space");
    space_remove(s, g);
}

int dSpaceQuery(dSpaceID s, dGeomID g)
{
    CHECK_SPACE(s, return 0);
    DX_CHECK_GEOM(g, return 0);
    return g->space == s;
}

int dSpaceGetNumGeoms(dSpaceID s)
{
    CHECK_SPACE(s, return 0);
    return s->count;
}

dGeomID dSpaceGetGeom(dSpaceID s, int i)
{
    CHECK_SPACE(s, return NULL);
    DX_CHECK_ARG(i >= 0 && i < s->count, return NULL, "i = %d is out of range (0..%d)", i,
                 s->count - 1);
    return s->geoms[i];
}

// Through the class's compute_aabb, which the hash and quadtree spaces wrap
// to learn that their search structure is stale.
void dxSpaceUpdateAABBs(dxSpace *s)
{
    for (int i = 0; i < s->count; i++) dxGeomUpdateAABB(s->geoms[i]);
    s->geom.ops->compute_aabb(&s->geom);
}

void dSpaceClean(dSpaceID s)
{
    CHECK_SPACE(s, return);
    dxGeomUpdateAABB(&s->geom);
}

// ---- pair tests -------------------------------------------------------------

unsigned long dx_aabb_tests;

// a == b happens only in dSpaceCollide2(space, X) with X in the space: the
// guide (10.5.2) reports the pair (X, X) then, so a geom touches itself.
int dxGeomsMayTouch(dxGeom *a, dxGeom *b)
{
    return dxAABBsOverlap(a->aabb, b->aabb) && dxGeomsMayTouchOverlapping(a, b);
}

void dxSpaceTestPair(dxGeom *a, dxGeom *b, void *data, dNearCallback *cb)
{
    dxSpaceTestPairInline(a, b, data, cb);
}

// ---- dSpaceCollide, dSpaceCollide2 --------------------------------------------

void dSpaceCollide(dSpaceID s, void *data, dNearCallback *cb)
{
    CHECK_SPACE(s, return);
    DX_CHECK_ARG(cb != NULL, return, "callback is NULL");
    dxGeomUpdateAABB(&s->geom);
    s->lock_count++;
    s->sops->collide(s, data, cb);
    s->lock_count--;
}

// The callback gets (geom of o1, geom of o2) whatever order the search uses.
typedef struct swapped_call {
    void *data;
    dNearCallback *cb;
} swapped_call;

static void call_swapped(void *p, dGeomID a, dGeomID b)
{
    swapped_call *sc = p;
    sc->cb(sc->data, b, a);
}

// Pairs of the geom g (not recursed into if it is a space) with the geoms of
// space s, with the callback's first geom from o1.
static void collide_geom_with_space(dxSpace *s, dxGeom *g, int space_first, void *data,
                                    dNearCallback *cb)
{
    s->lock_count++;
    if (space_first) {
        swapped_call sc = { data, cb };
        s->sops->collide_geom(s, g, &sc, call_swapped);
    } else {
        s->sops->collide_geom(s, g, data, cb);
    }
    s->lock_count--;
}

// Every geom of `each` (one by one) against the space `against` (guide
// 10.5.2: the space with fewer geoms is walked).
static void collide_each_with_space(dxSpace *each, dxSpace *against, int each_first, void *data,
                                    dNearCallback *cb)
{
    each->lock_count++;
    for (int i = 0; i < each->count; i++) {
        dxGeom *g = each->geoms[i];
        if (!(g->flags & DX_GEOM_ENABLED)) continue;
        collide_geom_with_space(against, g, !each_first, data, cb);
    }
    each->lock_count--;
}

void dSpaceCollide2(dGeomID o1, dGeomID o2, void *data, dNearCallback *cb)
{
    DX_CHECK_ARG(dxGeomIsLive(o1), return, "space1 is NULL or was destroyed");
    DX_CHECK_ARG(dxGeomIsLive(o2), return, "space2 is NULL or was destroyed");
    DX_CHECK_ARG(cb != NULL, return, "callback is NULL");
    int s1 = (o1->flags & DX_GEOM_IS_SPACE) != 0, s2 = (o2->flags & DX_GEOM_IS_SPACE) != 0;
    dxGeomUpdateAABB(o1);
    dxGeomUpdateAABB(o2);
    if (s1 && o1 == o2) {
        dSpaceCollide((dxSpace *)o1, data, cb);
    } else if (s1 && s2) {
        // The space with fewer geoms is walked; each of its geoms is tested
        // against the other space's search structure.
        dxSpace *a = (dxSpace *)o1, *b = (dxSpace *)o2;
        if (a->count <= b->count) collide_each_with_space(a, b, 1, data, cb);
        else collide_each_with_space(b, a, 0, data, cb);
    } else if (s1) {
        collide_geom_with_space((dxSpace *)o1, o2, 1, data, cb);
    } else if (s2) {
        collide_geom_with_space((dxSpace *)o2, o1, 0, data, cb);
    } else if (dxGeomsMayTouch(o1, o2)) {
        cb(data, o1, o2);
    }
}
