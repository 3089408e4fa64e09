// SPDX-License-Identifier: BSD-3-Clause
//
// space_sap.c -- the sweep-and-prune space (ODE 0.16's
// dSweepAndPruneSpaceCreate).
//
// The geoms are kept sorted by the low end of their AABBs along the space's
// first axis. A collision sweeps that list once: each geom meets the geoms
// after it whose low end is not past its high end, and the pair is tested
// only if the boxes also overlap on the second and third axes. The order is kept from one collision to the next and repaired by
// insertion sort, which costs one comparison per geom and one move per swap:
// near-linear when most geoms are still, whatever their number. A list too
// disordered for that (many moved far, or a first sort) is sorted afresh.
// Geoms with an infinite AABB (planes) sort first and reach every geom, as
// their boxes say. The list is refreshed only when the space's bounding box
// was recomputed (something in it moved, came or went), so dSpaceCollide2
// against the space reuses it geom after geom; its array grows geometrically
// and a steady state allocates nothing.

#include "geom_internal.h"

#include <ode/memory.h>
#include <stdlib.h>
#include <string.h>

// A geom and its AABB in the space's axis order (lo, hi along the sweep axis
// first), kept in the entry so the sweep reads the list in order.
typedef struct sap_entry {
    dReal lo, hi, lo1, hi1, lo2, hi2;
    dxGeom *g;
} sap_entry;

typedef struct dxSapSpace {
    dxSpace s;
    int axis[3];                  // the axis order: sweep, prune, (the rest by the pair test)
    int stale;                    // the list's keys or order may be out of date
    int walking;                  // > 0 while a collision walks the list
    sap_entry *list;              // every geom of the space, sorted by lo
    int n, cap;
} dxSapSpace;

static void list_reserve(dxSapSpace *ss, int n)
{
    if (n <= ss->cap) return;
    int cap = ss->cap ? 2 * ss->cap : 64;
    while (cap < n) cap *= 2;
    ss->list = dRealloc(ss->list, (size_t)ss->cap * sizeof *ss->list, (size_t)cap * sizeof *ss->list);
    ss->cap = cap;
}

static void sap_added(dxSpace *s, dxGeom *g)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    list_reserve(ss, ss->n + 1);
    ss->list[ss->n].lo = -dInfinity;   // keys are refreshed before use
    ss->list[ss->n].hi = dInfinity;
    ss->list[ss->n++].g = g;
    ss->stale = 1;
}

static void sap_removed(dxSpace *s, dxGeom *g)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    for (int i = 0; i < ss->n; i++) {
        if (ss->list[i].g == g) {
            memmove(ss->list + i, ss->list + i + 1, (size_t)(ss->n - i - 1) * sizeof *ss->list);
            ss->n--;
            break;
        }
    }
    ss->stale = 1;
}

static int by_lo(const void *a, const void *b)
{
    const sap_entry *x = a, *y = b;
    return (x->lo > y->lo) - (x->lo < y->lo);
}

// Insertion sort by lo; gives up (returns 0) after `budget` moves.
static int insertion_sort(sap_entry *e, int n, long budget)
{
    for (int i = 1; i < n; i++) {
        sap_entry x = e[i];
        int j = i;
        while (j > 0 && e[j - 1].lo > x.lo) {
            e[j] = e[j - 1];
            j--;
            if (--budget < 0) {
                e[j] = x;
                return 0;
            }
        }
        e[j] = x;
    }
    return 1;
}

// Bring the keys up to date (AABBs are current: the caller updated them) and
// the order with them. A NaN bound (a geom at a non-finite place) sorts as
// -infinity for lo and +infinity for hi, so that the order stays a total one.
// Returns 0 if the list is stale while an outer collision of this space
// still walks it (a callback moved a geom): the caller then tests geoms one
// by one.
static int sap_refresh(dxSapSpace *ss)
{
    if (!ss->stale) return 1;
    if (ss->walking > 0) return 0;
    const int a = 2 * ss->axis[0], b = 2 * ss->axis[1], c = 2 * ss->axis[2];
    for (int i = 0; i < ss->n; i++) {
        sap_entry *e = &ss->list[i];
        const dReal *box = e->g->aabb;
        e->lo = box[a] == box[a] ? box[a] : -dInfinity;
        e->hi = box[a + 1] == box[a + 1] ? box[a + 1] : dInfinity;
        e->lo1 = box[b];
        e->hi1 = box[b + 1];
        e->lo2 = box[c];
        e->hi2 = box[c + 1];
    }
    if (!insertion_sort(ss->list, ss->n, 4L * ss->n + 64))
        qsort(ss->list, (size_t)ss->n, sizeof *ss->list, by_lo);
    ss->stale = 0;
    return 1;
}

static int enabled(const dxGeom *g) { return (g->flags & DX_GEOM_ENABLED) != 0; }

// The boxes overlap on the other two axes (prune axis first).
static int prune_overlap(const sap_entry *a, const sap_entry *b)
{
    return a->lo1 <= b->hi1 && b->lo1 <= a->hi1 && a->lo2 <= b->hi2 && b->lo2 <= a->hi2;
}

static void sap_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    if (!sap_refresh(ss)) {
        for (int i = 0; i < s->count; i++)
            for (int j = i + 1; j < s->count; j++)
                dxSpaceTestPair(s->geoms[i], s->geoms[j], data, cb);
        return;
    }
    ss->walking++;
    for (int i = 0; i < ss->n; i++) {
        const sap_entry *e = &ss->list[i];
        if (!enabled(e->g)) continue;
        for (int j = i + 1; j < ss->n && ss->list[j].lo <= e->hi; j++)
            if (prune_overlap(e, &ss->list[j])) dxSpaceTestPair(e->g, ss->list[j].g, data, cb);
    }
    ss->walking--;
}

// g (not in the space) against the geoms whose low end is not past g's high
// end: the sorted prefix found by bisection. g first in each pair.
static void sap_collide_geom(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    if (!sap_refresh(ss)) {
        for (int i = 0; i < s->count; i++) dxSpaceTestPair(g, s->geoms[i], data, cb);
        return;
    }
    ss->walking++;
    const int a = 2 * ss->axis[0], b = 2 * ss->axis[1], c = 2 * ss->axis[2];
    const sap_entry ge = { g->aabb[a], g->aabb[a + 1], g->aabb[b], g->aabb[b + 1], g->aabb[c],
                           g->aabb[c + 1], g };
    const dReal glo = ge.lo, ghi = ge.hi;
    int end = ss->n;
    if (ghi == ghi) {   // the first entry with lo > ghi
        int lo = 0, hi = ss->n;
        while (lo < hi) {
            int mid = lo + (hi - lo) / 2;
            if (ss->list[mid].lo <= ghi) lo = mid + 1;
            else hi = mid;
        }
        end = lo;
    }
    for (int i = 0; i < end; i++) {
        if ((ss->list[i].hi >= glo || glo != glo) && prune_overlap(&ge, &ss->list[i]))
            dxSpaceTestPair(g, ss->list[i].g, data, cb);
    }
    ss->walking--;
}

static void sap_destroy(dxSpace *s)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    dFree(ss->list, (size_t)ss->cap * sizeof *ss->list);
}

static const dxSpaceOps sap_ops = { sap_added, sap_removed, sap_collide, sap_collide_geom,
                                    sap_destroy };

// The class operations of all spaces, with compute_aabb wrapped: the space's
// box is recomputed exactly when something in it changed, which makes the
// list stale.
static dxGeomClassOps sap_class_ops;
static void (*union_aabb)(dxGeom *g);

static void sap_aabb(dxGeom *g)
{
    union_aabb(g);
    ((dxSapSpace *)g)->stale = 1;
}

dSpaceID dSweepAndPruneSpaceCreate(dSpaceID parent, int axisorder)
{
    const int a0 = axisorder & 3, a1 = (axisorder >> 2) & 3, a2 = (axisorder >> 4) & 3;
    DX_CHECK_ARG(a0 < 3 && a1 < 3 && a2 < 3 && a0 != a1 && a1 != a2 && a0 != a2 &&
                     (axisorder & ~63) == 0,
                 return NULL, "axisorder %d is not one of the dSAP_AXES_* orders", axisorder);
    dxSpace *s = dxSpaceCreate(sizeof(dxSapSpace), dSweepAndPruneSpaceClass, &sap_ops, parent);
    if (!s) return NULL;
    if (!union_aabb) {
        sap_class_ops = *s->geom.ops;
        union_aabb = sap_class_ops.compute_aabb;
        sap_class_ops.compute_aabb = sap_aabb;
    }
    s->geom.ops = &sap_class_ops;
    dxSapSpace *ss = (dxSapSpace *)s;
    ss->axis[0] = a0;
    ss->axis[1] = a1;
    ss->axis[2] = a2;
    ss->stale = 1;
    return s;
}
