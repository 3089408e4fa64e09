// SPDX-License-Identifier: BSD-3-Clause
//
// space_quadtree.c -- the quadtree space (guide 10.6).
//
// The root block is Center +- Extents on two axes, the split axes: the two
// with the larger Extents, the third being "up" and never split (on ties the
// later axis is up, so equal extents split x and y; a landscape with z up
// splits x and y, one with y up splits x and z). Every block is split into
// four equal blocks, Depth times: levels 0 (the root) to Depth, 4^Depth
// smallest blocks. A geom belongs to the smallest block whose region contains
// its AABB strictly (on the split axes); one that no block contains belongs to
// the root. Blocks of one level have disjoint open regions, so two geoms can
// overlap only if one's block is the other's or an ancestor of it: pairs come
// from a block with itself and its descendants.
//
// Blocks are numbered in depth-first preorder, so a block's subtree is a
// range of numbers. Sorting the geoms by block number makes a block with its
// descendants a run of the sorted list. Each geom is tested against the geoms
// after it in its own block, then the walk goes down into the child blocks
// whose (closed) regions its AABB touches, finding their runs by binary
// search: a geom that straddles the root's middle lines meets the geoms along
// its way down, not the whole tree. Block boundaries are computed as
// lo + i (size 2^-level), which gives the same double for a boundary shared
// by blocks of different levels, so the disjointness holds exactly. The
// blocks themselves are never stored: the sorted list is rebuilt (radix sort,
// arrays kept in the space) when the space's bounding boxes were recomputed.

#include "geom_internal.h"

#include <math.h>
#include <ode/memory.h>
#include <stdint.h>

// Keys of a tree of depth 31 use all of 64 bits.
#define QUAD_MAX_DEPTH 31

// A geom in its block: the block's preorder number, level and indices along
// the two split axes within its level.
typedef struct quad_item {
    uint64_t key;
    dxGeom *g;
    int level;
    uint32_t index[2];
} quad_item;

// An AABB on the split axes: min and max.
typedef struct quad_box {
    double a[2], b[2];
} quad_box;

typedef struct dxQuadTreeSpace {
    dxSpace s;
    int depth;
    int axis[2];                              // the split axes
    double lo[2], size[2];                    // the root block along them
    uint64_t subtree[QUAD_MAX_DEPTH + 1];     // blocks in the subtree of a block of level l
    quad_item *items, *spare;                 // sorted by key; radix sort scratch
    int items_cap, spare_cap, n_items;
    int stale;                                // the list no longer describes the geoms
    int walking;                              // > 0 while a collision walks the list
} dxQuadTreeSpace;

// p with room for `need` items of `size` bytes; the capacity doubles.
static void *grow(void *p, int *cap, int need, size_t size)
{
    if (need <= *cap) return p;
    int c = *cap ? *cap : 16;
    while (c < need) c *= 2;
    p = dRealloc(p, (size_t)*cap * size, (size_t)c * size);
    *cap = c;
    return p;
}

static quad_box split_box(const dxQuadTreeSpace *qs, const dReal *aabb)
{
    quad_box q;
    for (int d = 0; d < 2; d++) {
        q.a[d] = aabb[2 * qs->axis[d]];
        q.b[d] = aabb[2 * qs->axis[d] + 1];
    }
    return q;
}

// Boundary i of the blocks of `level` along split axis d.
static double boundary(const dxQuadTreeSpace *qs, int d, int level, uint64_t i)
{
    return qs->lo[d] + (double)i * ldexp(qs->size[d], -level);
}

// Key of child c (x half + 2 y half) of the block `key` of `level`.
static uint64_t child_key(const dxQuadTreeSpace *qs, uint64_t key, int level, int c)
{
    return key + 1 + (uint64_t)c * qs->subtree[level + 1];
}

// The block of an AABB into it (key, level, indices), and the keys of its
// ancestors into path[0 .. level) if path is not NULL.
static void find_block(const dxQuadTreeSpace *qs, const dReal *aabb, quad_item *it,
                       uint64_t *path)
{
    const quad_box q = split_box(qs, aabb);
    uint64_t k = 0, index[2] = { 0, 0 };
    int level = 0, inside = 1;
    for (int d = 0; d < 2; d++)
        inside &= q.a[d] <= q.b[d] && q.a[d] > boundary(qs, d, 0, 0) &&
                  q.b[d] < boundary(qs, d, 0, 1);
    while (inside && level < qs->depth) {
        int child[2];
        for (int d = 0; d < 2; d++) {
            double mid = boundary(qs, d, level + 1, 2 * index[d] + 1);
            child[d] = q.b[d] < mid ? 0 : q.a[d] > mid ? 1 : -1;
        }
        if (child[0] < 0 || child[1] < 0) break;
        if (path) path[level] = k;
        k = child_key(qs, k, level, 2 * child[1] + child[0]);
        for (int d = 0; d < 2; d++) index[d] = 2 * index[d] + (uint64_t)child[d];
        level++;
    }
    it->key = k;
    it->level = level;
    it->index[0] = (uint32_t)index[0];
    it->index[1] = (uint32_t)index[1];
}

// Stable LSD radix sort of the items by key, a byte at a time, for as many
// bytes as the largest key has.
static void sort_items(dxQuadTreeSpace *qs)
{
    const int n = qs->n_items;
    const uint64_t max_key = qs->subtree[0] - 1;
    qs->spare = grow(qs->spare, &qs->spare_cap, n, sizeof *qs->spare);
    for (int shift = 0; shift < 64 && (max_key >> shift) != 0; shift += 8) {
        int start[257] = { 0 };
        for (int i = 0; i < n; i++) start[((qs->items[i].key >> shift) & 255) + 1]++;
        for (int b = 0; b < 256; b++) start[b + 1] += start[b];
        for (int i = 0; i < n; i++)
            qs->spare[start[(qs->items[i].key >> shift) & 255]++] = qs->items[i];
        quad_item *t = qs->items;
        qs->items = qs->spare;
        qs->spare = t;
        int c = qs->items_cap;
        qs->items_cap = qs->spare_cap;
        qs->spare_cap = c;
    }
}

static void quad_rebuild(dxQuadTreeSpace *qs)
{
    const dxSpace *s = &qs->s;
    qs->items = grow(qs->items, &qs->items_cap, s->count, sizeof *qs->items);
    qs->n_items = s->count;
    for (int i = 0; i < s->count; i++) {
        quad_item *it = &qs->items[i];
        it->g = s->geoms[i];
        find_block(qs, it->g->aabb, it, NULL);
    }
    sort_items(qs);
    qs->stale = 0;
}

// Make the list current; 0 if it is stale but an outer collision of this
// space still walks it (a callback moved a geom): the caller then tests
// geoms one by one.
static int quad_ready(dxQuadTreeSpace *qs)
{
    if (!qs->stale) return 1;
    if (qs->walking > 0) return 0;
    quad_rebuild(qs);
    return 1;
}

// The first item of [lo, hi) with key >= k.
static int lower_bound(const dxQuadTreeSpace *qs, int lo, int hi, uint64_t k)
{
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (qs->items[mid].key < k) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

// 1 if the box touches the closed region of block (level, index).
static int touches_block(const dxQuadTreeSpace *qs, const quad_box *q, int level,
                         const uint64_t index[2])
{
    for (int d = 0; d < 2; d++)
        if (!(q->a[d] <= boundary(qs, d, level, index[d] + 1) &&
              q->b[d] >= boundary(qs, d, level, index[d])))
            return 0;
    return 1;
}

static void test_items(const dxQuadTreeSpace *qs, dxGeom *g, int from, int to, void *data,
                       dNearCallback *cb)
{
    for (int j = from; j < to; j++) dxSpaceTestPair(g, qs->items[j].g, data, cb);
}

// g (box q) against the geoms below the block (key, level, index), whose
// items are [from, to) without the block's own: the children whose regions
// q touches, with their own geoms and recursively theirs.
static void test_below(const dxQuadTreeSpace *qs, dxGeom *g, const quad_box *q, uint64_t key,
                       int level, const uint64_t index[2], int from, int to, void *data,
                       dNearCallback *cb)
{
    if (from >= to) return;
    for (int c = 0; c < 4; c++) {
        uint64_t ck = child_key(qs, key, level, c);
        uint64_t ci[2] = { 2 * index[0] + (uint64_t)(c & 1), 2 * index[1] + (uint64_t)(c >> 1) };
        if (!touches_block(qs, q, level + 1, ci)) continue;
        int begin = lower_bound(qs, from, to, ck);
        int end = lower_bound(qs, begin, to, ck + qs->subtree[level + 1]);
        int own = lower_bound(qs, begin, end, ck + 1);
        test_items(qs, g, begin, own, data, cb);
        test_below(qs, g, q, ck, level + 1, ci, own, end, data, cb);
    }
}

static void quad_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    dxQuadTreeSpace *qs = (dxQuadTreeSpace *)s;
    if (!quad_ready(qs)) {
        for (int i = 0; i < s->count; i++)
            for (int j = i + 1; j < s->count; j++)
                dxSpaceTestPair(s->geoms[i], s->geoms[j], data, cb);
        return;
    }
    const int n = qs->n_items;
    qs->walking++;
    int own = 0, below = 0;   // the ends of the current block's own geoms and of its subtree
    for (int i = 0; i < n; i++) {
        const quad_item *it = &qs->items[i];
        if (i == own) {
            while (own < n && qs->items[own].key == it->key) own++;
            below = lower_bound(qs, own, n, it->key + qs->subtree[it->level]);
        }
        if (!(it->g->flags & DX_GEOM_ENABLED)) continue;
        const quad_box q = split_box(qs, it->g->aabb);
        const uint64_t index[2] = { it->index[0], it->index[1] };
        test_items(qs, it->g, i + 1, own, data, cb);
        test_below(qs, it->g, &q, it->key, it->level, index, own, below, data, cb);
    }
    qs->walking--;
}

// g first in each pair (the contract of dxSpaceOps.collide_geom): the geoms
// of g's ancestors, of its block, and those below that it may touch.
static void quad_collide_geom(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb)
{
    dxQuadTreeSpace *qs = (dxQuadTreeSpace *)s;
    if (!quad_ready(qs)) {
        for (int i = 0; i < s->count; i++) dxSpaceTestPair(g, s->geoms[i], data, cb);
        return;
    }
    const int n = qs->n_items;
    qs->walking++;
    uint64_t path[QUAD_MAX_DEPTH];
    quad_item block;
    find_block(qs, g->aabb, &block, path);
    for (int l = 0; l < block.level; l++) {
        int begin = lower_bound(qs, 0, n, path[l]);
        test_items(qs, g, begin, lower_bound(qs, begin, n, path[l] + 1), data, cb);
    }
    int begin = lower_bound(qs, 0, n, block.key);
    int own = lower_bound(qs, begin, n, block.key + 1);
    int below = lower_bound(qs, own, n, block.key + qs->subtree[block.level]);
    const quad_box q = split_box(qs, g->aabb);
    const uint64_t index[2] = { block.index[0], block.index[1] };
    test_items(qs, g, begin, own, data, cb);
    test_below(qs, g, &q, block.key, block.level, index, own, below, data, cb);
    qs->walking--;
}

static void quad_destroy(dxSpace *s)
{
    dxQuadTreeSpace *qs = (dxQuadTreeSpace *)s;
    dFree(qs->items, (size_t)qs->items_cap * sizeof *qs->items);
    dFree(qs->spare, (size_t)qs->spare_cap * sizeof *qs->spare);
}

static const dxSpaceOps quad_ops = { NULL, NULL, quad_collide, quad_collide_geom, quad_destroy };

// The class operations of all spaces, with compute_aabb wrapped: the space's
// box is recomputed exactly when something in it changed, which makes the
// sorted list stale.
static dxGeomClassOps quad_class_ops;
static void (*union_aabb)(dxGeom *g);

static void quad_aabb(dxGeom *g)
{
    union_aabb(g);
    ((dxQuadTreeSpace *)g)->stale = 1;
}

// The axis that is not split: the smallest extent, the later axis on ties.
static int up_axis(const dVector3 extents)
{
    int up = 2;
    if (extents[1] < extents[up]) up = 1;
    if (extents[0] < extents[up]) up = 0;
    return up;
}

dSpaceID dQuadTreeSpaceCreate(dSpaceID parent, const dVector3 Center, const dVector3 Extents,
                              int Depth)
{
    DX_CHECK_ARG(Center != NULL && dxIsFinite3(Center[0], Center[1], Center[2]), return NULL,
                 "Center is NULL or not finite");
    DX_CHECK_ARG(Extents != NULL && dxIsFinite3(Extents[0], Extents[1], Extents[2]) &&
                     Extents[0] >= 0 && Extents[1] >= 0 && Extents[2] >= 0,
                 return NULL, "Extents is NULL, not finite or negative");
    DX_CHECK_ARG(Depth >= 1, return NULL, "Depth (%d) is less than 1", Depth);
    DX_WARN_ARG(Depth <= QUAD_MAX_DEPTH, Depth = QUAD_MAX_DEPTH,
                "Depth %d is more than %d, which is used instead", Depth, QUAD_MAX_DEPTH);
    dxSpace *s = dxSpaceCreate(sizeof(dxQuadTreeSpace), dQuadTreeSpaceClass, &quad_ops, parent);
    if (!s) return NULL;
    if (!union_aabb) {
        quad_class_ops = *s->geom.ops;
        union_aabb = quad_class_ops.compute_aabb;
        quad_class_ops.compute_aabb = quad_aabb;
    }
    s->geom.ops = &quad_class_ops;
    dxQuadTreeSpace *qs = (dxQuadTreeSpace *)s;
    qs->depth = Depth;
    int up = up_axis(Extents);
    qs->axis[0] = up == 0 ? 1 : 0;
    qs->axis[1] = up == 2 ? 1 : 2;
    for (int d = 0; d < 2; d++) {
        qs->lo[d] = (double)Center[qs->axis[d]] - (double)Extents[qs->axis[d]];
        qs->size[d] = 2.0 * (double)Extents[qs->axis[d]];
    }
    qs->subtree[Depth] = 1;
    for (int l = Depth - 1; l >= 0; l--) qs->subtree[l] = 1 + 4 * qs->subtree[l + 1];
    qs->stale = 1;
    return s;
}
