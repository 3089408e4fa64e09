// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash.c -- the multi-resolution hash table space (guide 10.6).
//
// A geom lives at one level L: the smallest L >= minlevel with 2^L >= the
// largest side of its AABB. It is recorded in every cell of side 2^L its AABB
// touches (two per axis at most); cell (L, i, j, k) is
// [i 2^L, (i+1) 2^L) x [j 2^L, ...) x [k 2^L, ...). Geoms above maxlevel, with
// an infinite or empty AABB, or so far out that cell indices would not be
// exact are "big": they are tested against every geom.
//
// Two overlapping AABBs both contain q, the point whose coordinates are the
// larger of their two minima, so at the level of the larger geom both touch
// the cell holding q: geoms of one level meet in a cell list, and a geom meets
// those of coarser levels by looking up the cells of those levels that its
// AABB touches. A pair is tested only in the cell that holds q, so it is
// tested once without remembering the pairs seen. (On each axis q's cell is
// the larger of the two geoms' lowest cells, and a cell both touch is at
// least that: it holds q exactly when on every axis it is the lowest cell of
// one of the two. Each entry keeps that as three bits, so the test needs no
// arithmetic on the boxes.) Spread-out geoms meet only
// their neighbours: time near-linear in their number.
//
// The table is rebuilt when the space's bounding boxes were recomputed
// (something in it moved, came or went), so dSpaceCollide2 against the space
// reuses it geom after geom. Its arrays live in the space and grow
// geometrically: a steady state allocates nothing.

#include "geom_internal.h"

#include <float.h>
#include <math.h>
#include <ode/memory.h>
#include <stdint.h>
#include <string.h>

// |cell index| below this is exact in a double and fits an int64_t.
#define CELL_LIMIT 4503599627370496.0   // 2^52

typedef struct hash_entry {
    int64_t cell[3];
    int level;
    int next;          // next entry of the same bucket, -1 at the end
    dxGeom *g;
    unsigned lowest;   // bit k: cell[k] is the geom's lowest cell on axis k
} hash_entry;

#define ALL_AXES 7u

// Bit k set where cell c is the lowest of the range lo on axis k.
static unsigned lowest_bits(const int64_t c[3], const int64_t lo[3])
{
    return (unsigned)(c[0] == lo[0]) | (unsigned)(c[1] == lo[1]) << 1 |
           (unsigned)(c[2] == lo[2]) << 2;
}

typedef struct hash_node {
    dxGeom *g;
    int level;
} hash_node;

// The geoms placed at one level are nodes[start .. start + count).
typedef struct hash_level {
    int level, start, count;
} hash_level;

typedef struct dxHashSpace {
    dxSpace s;
    int minlevel, maxlevel;
    int stale;                    // the table no longer describes the geoms
    int walking;                  // > 0 while a collision walks the table
    hash_node *nodes, *placed;    // placed geoms by level / in space order
    int nodes_cap, placed_cap, n_nodes;
    dxGeom **big;
    int big_cap, n_big;
    hash_entry *entries;
    int entries_cap, n_entries;
    int *buckets;                 // first entry of each bucket, -1 if none
    int buckets_cap, mask;        // mask + 1 buckets in use (a power of two)
    hash_level *levels;           // in increasing level
    int levels_cap, n_levels;
} dxHashSpace;

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

// 1 / (cell size) = 2^-level (clamped: beyond 2^+-2000 a double is 0 or inf).
static double level_scale(int level)
{
    return ldexp(1.0, level < -2000 ? 2000 : level > 2000 ? -2000 : -level);
}

// The cells at 1 / (cell size) = scale that the AABB touches, lo..hi per
// axis; 0 if an index would not be exact (infinite, huge, NaN or empty box).
static int cell_range(const dReal *aabb, double scale, int64_t lo[3], int64_t hi[3])
{
    for (int k = 0; k < 3; k++) {
        double a = aabb[2 * k] * scale, b = aabb[2 * k + 1] * scale;
        if (!(a >= -CELL_LIMIT && b <= CELL_LIMIT && a <= b)) return 0;
        lo[k] = (int64_t)floor(a);
        hi[k] = (int64_t)floor(b);
    }
    return 1;
}

// Number of cells in the ranges lo..hi.
static double cell_count(const int64_t lo[3], const int64_t hi[3])
{
    return (double)(hi[0] - lo[0] + 1) * (double)(hi[1] - lo[1] + 1) * (double)(hi[2] - lo[2] + 1);
}

// The level of an AABB and its cells there; 0 if the geom is big.
static int geom_level(const dxHashSpace *hs, const dReal *aabb, int *level, int64_t lo[3],
                      int64_t hi[3])
{
    double side = 0;
    for (int k = 0; k < 3; k++) {
        double d = (double)aabb[2 * k + 1] - (double)aabb[2 * k];
        if (!(d >= 0 && d <= DBL_MAX)) return 0;
        if (d > side) side = d;
    }
    int L = hs->minlevel;
    if (side > 0) {
        int e;
        double m = frexp(side, &e);   // side = m 2^e, 1/2 <= m < 1
        int need = m == 0.5 ? e - 1 : e;
        if (need > L) L = need;
    }
    if (L > hs->maxlevel) return 0;
    *level = L;
    return cell_range(aabb, level_scale(L), lo, hi);
}

// Multiply-xor hash of a cell, mixed so that neighbouring cells spread.
static unsigned cell_bucket(int level, const int64_t c[3], int mask)
{
    uint64_t h = (uint64_t)c[0] * 0x9E3779B97F4A7C15u ^ (uint64_t)c[1] * 0xC2B2AE3D27D4EB4Fu ^
                 (uint64_t)c[2] * 0x165667B19E3779F9u ^
                 (uint64_t)(int64_t)level * 0x27D4EB2F165667C5u;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9u;
    h ^= h >> 29;
    return (unsigned)h & (unsigned)mask;
}

static int same_cell(const hash_entry *e, int level, const int64_t c[3])
{
    return e->level == level && e->cell[0] == c[0] && e->cell[1] == c[1] && e->cell[2] == c[2];
}

// The index of `level` in the sorted level list, inserted if new.
static int level_index(dxHashSpace *hs, int level)
{
    int lo = 0, hi = hs->n_levels;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (hs->levels[mid].level < level) lo = mid + 1;
        else hi = mid;
    }
    if (lo < hs->n_levels && hs->levels[lo].level == level) return lo;
    hs->levels = grow(hs->levels, &hs->levels_cap, hs->n_levels + 1, sizeof *hs->levels);
    memmove(&hs->levels[lo + 1], &hs->levels[lo], (size_t)(hs->n_levels - lo) * sizeof *hs->levels);
    hs->levels[lo] = (hash_level){ level, 0, 0 };
    hs->n_levels++;
    return lo;
}

// Record geom g in the cells lo..hi of `level`.
static void add_entries(dxHashSpace *hs, dxGeom *g, int level, const int64_t lo[3],
                        const int64_t hi[3])
{
    int n = (int)cell_count(lo, hi);
    hs->entries = grow(hs->entries, &hs->entries_cap, hs->n_entries + n, sizeof *hs->entries);
    for (int64_t i = lo[0]; i <= hi[0]; i++)
        for (int64_t j = lo[1]; j <= hi[1]; j++)
            for (int64_t k = lo[2]; k <= hi[2]; k++)
                hs->entries[hs->n_entries++] = (hash_entry){
                    { i, j, k }, level, -1, g, lowest_bits((const int64_t[3]){ i, j, k }, lo)
                };
}

// Chain the entries into mask + 1 buckets, at least twice as many as entries.
static void fill_buckets(dxHashSpace *hs)
{
    int n = 16;
    while (n < 2 * hs->n_entries) n *= 2;
    hs->buckets = grow(hs->buckets, &hs->buckets_cap, n, sizeof *hs->buckets);
    hs->mask = n - 1;
    for (int b = 0; b < n; b++) hs->buckets[b] = -1;
    for (int e = 0; e < hs->n_entries; e++) {
        hash_entry *h = &hs->entries[e];
        unsigned b = cell_bucket(h->level, h->cell, hs->mask);
        h->next = hs->buckets[b];
        hs->buckets[b] = e;
    }
}

// Sort the placed geoms into nodes by level (counting sort over the levels).
static void sort_nodes(dxHashSpace *hs)
{
    int start = 0;
    for (int li = 0; li < hs->n_levels; li++) {
        hs->levels[li].start = start;
        start += hs->levels[li].count;
        hs->levels[li].count = 0;
    }
    hs->nodes = grow(hs->nodes, &hs->nodes_cap, hs->n_nodes, sizeof *hs->nodes);
    for (int i = 0; i < hs->n_nodes; i++) {
        int li = level_index(hs, hs->placed[i].level);
        hash_level *lv = &hs->levels[li];
        hs->nodes[lv->start + lv->count++] = hs->placed[i];
    }
}

static void hash_rebuild(dxHashSpace *hs)
{
    const dxSpace *s = &hs->s;
    hs->placed = grow(hs->placed, &hs->placed_cap, s->count, sizeof *hs->placed);
    hs->big = grow(hs->big, &hs->big_cap, s->count, sizeof *hs->big);
    hs->n_nodes = hs->n_big = hs->n_entries = hs->n_levels = 0;
    for (int i = 0; i < s->count; i++) {
        dxGeom *g = s->geoms[i];
        int level;
        int64_t lo[3], hi[3];
        if (!geom_level(hs, g->aabb, &level, lo, hi)) {
            hs->big[hs->n_big++] = g;
            continue;
        }
        hs->placed[hs->n_nodes++] = (hash_node){ g, level };
        int li = level_index(hs, level);   // may move hs->levels
        hs->levels[li].count++;
        add_entries(hs, g, level, lo, hi);
    }
    sort_nodes(hs);
    fill_buckets(hs);
    hs->stale = 0;
}

// Make the table current; 0 if it is stale but an outer collision of this
// space still walks it (a callback moved a geom): the caller then tests
// geoms one by one.
static int hash_ready(dxHashSpace *hs)
{
    if (!hs->stale) return 1;
    if (hs->walking > 0) return 0;
    hash_rebuild(hs);
    return 1;
}

// g against the geoms of `level` recorded in cell c (g's lowest-cell bits
// there: lowest).
static void query_cell(const dxHashSpace *hs, dxGeom *g, int level, const int64_t c[3],
                       unsigned lowest, void *data, dNearCallback *cb)
{
    for (int e = hs->buckets[cell_bucket(level, c, hs->mask)]; e >= 0; e = hs->entries[e].next) {
        const hash_entry *h = &hs->entries[e];
        if ((h->lowest | lowest) == ALL_AXES && same_cell(h, level, c))
            dxSpaceTestPair(g, h->g, data, cb);
    }
}

// g against the placed geoms of levels[first ..]: through the cells of each
// level that g's AABB touches, or one by one when those cells outnumber the
// level's geoms (a big g against small geoms).
static void query_levels(const dxHashSpace *hs, dxGeom *g, int first, void *data,
                         dNearCallback *cb)
{
    for (int li = first; li < hs->n_levels; li++) {
        const hash_level *lv = &hs->levels[li];
        int64_t lo[3], hi[3];
        if (cell_range(g->aabb, level_scale(lv->level), lo, hi) &&
            cell_count(lo, hi) <= lv->count) {
            for (int64_t i = lo[0]; i <= hi[0]; i++)
                for (int64_t j = lo[1]; j <= hi[1]; j++)
                    for (int64_t k = lo[2]; k <= hi[2]; k++) {
                        const int64_t c[3] = { i, j, k };
                        query_cell(hs, g, lv->level, c, lowest_bits(c, lo), data, cb);
                    }
        } else {
            for (int n = lv->start; n < lv->start + lv->count; n++)
                dxSpaceTestPair(g, hs->nodes[n].g, data, cb);
        }
    }
}

static int enabled(const dxGeom *g) { return (g->flags & DX_GEOM_ENABLED) != 0; }

static void brute_collide(const dxSpace *s, void *data, dNearCallback *cb)
{
    for (int i = 0; i < s->count; i++)
        for (int j = i + 1; j < s->count; j++) dxSpaceTestPair(s->geoms[i], s->geoms[j], data, cb);
}

static void hash_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    if (!hash_ready(hs)) {
        brute_collide(s, data, cb);
        return;
    }
    hs->walking++;
    // Big geoms against every geom.
    for (int i = 0; i < hs->n_big; i++) {
        dxGeom *a = hs->big[i];
        if (!enabled(a)) continue;
        for (int j = i + 1; j < hs->n_big; j++) dxSpaceTestPair(a, hs->big[j], data, cb);
        for (int j = 0; j < hs->n_nodes; j++) dxSpaceTestPair(a, hs->nodes[j].g, data, cb);
    }
    // Geoms of one level that share a cell: the entries of a bucket after
    // this one in its chain.
    for (int e = 0; e < hs->n_entries; e++) {
        const hash_entry *h = &hs->entries[e];
        if (!enabled(h->g)) continue;
        for (int f = h->next; f >= 0; f = hs->entries[f].next) {
            const hash_entry *o = &hs->entries[f];
            if ((o->lowest | h->lowest) == ALL_AXES && same_cell(o, h->level, h->cell))
                dxSpaceTestPair(h->g, o->g, data, cb);
        }
    }
    // Each geom against the coarser levels.
    for (int li = 0; li < hs->n_levels; li++) {
        const hash_level *lv = &hs->levels[li];
        for (int n = lv->start; n < lv->start + lv->count; n++)
            if (enabled(hs->nodes[n].g)) query_levels(hs, hs->nodes[n].g, li + 1, data, cb);
    }
    hs->walking--;
}

// g first in each pair (the contract of dxSpaceOps.collide_geom).
static void hash_collide_geom(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    if (!hash_ready(hs)) {
        for (int i = 0; i < s->count; i++) dxSpaceTestPair(g, s->geoms[i], data, cb);
        return;
    }
    hs->walking++;
    for (int i = 0; i < hs->n_big; i++) dxSpaceTestPair(g, hs->big[i], data, cb);
    query_levels(hs, g, 0, data, cb);
    hs->walking--;
}

static void hash_destroy(dxSpace *s)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    dFree(hs->nodes, (size_t)hs->nodes_cap * sizeof *hs->nodes);
    dFree(hs->placed, (size_t)hs->placed_cap * sizeof *hs->placed);
    dFree(hs->big, (size_t)hs->big_cap * sizeof *hs->big);
    dFree(hs->entries, (size_t)hs->entries_cap * sizeof *hs->entries);
    dFree(hs->buckets, (size_t)hs->buckets_cap * sizeof *hs->buckets);
    dFree(hs->levels, (size_t)hs->levels_cap * sizeof *hs->levels);
}

static const dxSpaceOps hash_ops = { NULL, NULL, hash_collide, hash_collide_geom, hash_destroy };

// The class operations of all spaces, with compute_aabb wrapped: the space's
// box is recomputed exactly when something in it changed, which makes the
// table stale.
static dxGeomClassOps hash_class_ops;
static void (*union_aabb)(dxGeom *g);

static void hash_aabb(dxGeom *g)
{
    union_aabb(g);
    ((dxHashSpace *)g)->stale = 1;
}

dSpaceID dHashSpaceCreate(dSpaceID parent)
{
    dxSpace *s = dxSpaceCreate(sizeof(dxHashSpace), dHashSpaceClass, &hash_ops, parent);
    if (!s) return NULL;
    if (!union_aabb) {
        hash_class_ops = *s->geom.ops;
        union_aabb = hash_class_ops.compute_aabb;
        hash_class_ops.compute_aabb = hash_aabb;
    }
    s->geom.ops = &hash_class_ops;
    dxHashSpace *hs = (dxHashSpace *)s;
    hs->minlevel = -3;
    hs->maxlevel = 10;
    hs->stale = 1;
    return s;
}

#define CHECK_HASH_SPACE(s, on_fail) \
    DX_CHECK_ARG(dxGeomIsLive((dxGeom *)(s)) && ((dxGeom *)(s))->flags & DX_GEOM_IS_SPACE && \
                     ((dxGeom *)(s))->ops->cls == dHashSpaceClass, \
                 on_fail, "space is NULL, was destroyed, or is not a hash space")

void dHashSpaceSetLevels(dSpaceID s, int minlevel, int maxlevel)
{
    CHECK_HASH_SPACE(s, return);
    DX_CHECK_ARG(minlevel <= maxlevel, return, "minlevel (%d) is greater than maxlevel (%d)",
                 minlevel, maxlevel);
    dxHashSpace *hs = (dxHashSpace *)s;
    hs->minlevel = minlevel;
    hs->maxlevel = maxlevel;
    hs->stale = 1;
}

void dHashSpaceGetLevels(dSpaceID s, int *minlevel, int *maxlevel)
{
    CHECK_HASH_SPACE(s, return);
    const dxHashSpace *hs = (const dxHashSpace *)s;
    if (minlevel) *minlevel = hs->minlevel;
    if (maxlevel) *maxlevel = hs->maxlevel;
}
