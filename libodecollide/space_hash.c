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
// The cells are kept from one collision to the next (space_hash_cells.c):
// when the space's bounding boxes were recomputed (something in it moved,
// came or went), each geom's level and cell range are compared with those it
// is recorded under, and only a geom whose range changed is moved to its new
// cells. A cell lists its geoms latest in space order first, so the pairs
// come in the same order as from a table built afresh from the geoms in space
// order: the order is a function of the geoms and their boxes, never of how
// they got there. The update is skipped while a collision of the space walks
// the cells; dSpaceCollide2 against the space reuses them geom after geom.
// Arrays grow geometrically: a steady state allocates nothing.

#include "geom_internal.h"
#include "space_hash_cells.h"
#include "space_pair.h"

#include "../libodedyn/core/dx_clones.h"

#include <float.h>
#include <math.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <ode/memory.h>
#include <stdint.h>
#include <string.h>

// |cell index| below this is exact in a double and fits an int64_t.
#define CELL_LIMIT 4503599627370496.0   // 2^52

#define ALL_AXES 7u
#define PER_GEOM DX_HASH_CELLS_PER_GEOM

// The same-level walk (same_level_pairs) in two versions, AVX2 and the
// baseline (dx_clones.h).
#ifdef DX_AVX2_CLONES
#define SAME_LEVEL_CLONES DX_AVX2_CLONES
#else
#define SAME_LEVEL_CLONES
#endif

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

// The geoms placed at one level are nodes[start .. start + count); 1 / (cell
// size) there is scale.
typedef struct hash_level {
    int level, start, count;
    double scale;
} hash_level;

// What a geom of the space is recorded as.
enum { SLOT_FREE, SLOT_NEW, SLOT_BIG, SLOT_PLACED };

// A geom of the space: its cells lo..hi at `level` (PLACED), recorded in
// its entries cells.entries[slot * PER_GEOM ..][0 .. n).
// What keeps it there without computing its cells afresh: the scale
// 2^-level, lo and hi as doubles, and the bounds of the longest side of its
// box at this level, (side_lo, side_hi] (NaN: never kept).
typedef struct hash_slot {
    dxGeom *g;
    int state;
    int level, n;
    int next_free;                // the next free slot (FREE)
    int64_t lo[3], hi[3];
    double scale, lo_d[3], hi_d[3], side_lo, side_hi;
} hash_slot;

// Where s->geoms[i] goes at the next update, when that differs from where
// it is: its level and cells, unless big.
typedef struct hash_place {
    int i;
    int placed, level;
    int64_t lo[3], hi[3];
} hash_place;

// A geom's box as its maxima and negated minima, q = (max x, y, z, -min x,
// y, z), the last two numbers 0: boxes a and b overlap exactly when p <= q
// in every number, p = (min, -max) of a (space_hash.c: boxes_meet), x <= y
// being -y <= -x for every pair of numbers, NaN and signed zeros included.
typedef struct hash_box {
    dReal q[8];
} hash_box;

// The hash_box of an AABB (minx maxx miny maxy minz maxz).
static inline hash_box box_of(const dReal *aabb)
{
    return (hash_box){ { aabb[1], aabb[3], aabb[5], -aabb[0], -aabb[2], -aabb[4], 0, 0 } };
}

typedef struct dxHashSpace {
    dxSpace s;
    int minlevel, maxlevel;
    int stale;                    // the cells may no longer describe the geoms
    int members_changed;          // geoms came or went since the last update
    int levels_changed;           // dHashSpaceSetLevels since the last update
    int afresh;                   // the last update linked every geom afresh (most moved:
                                  // the next checks no geom's cell bounds first)
    int walking;                  // > 0 while a collision walks the cells
    hash_slot *slots;
    int slots_cap, n_slots, free_slot;   // allocated, ever used, first free (-1 if none)
    int *slot_of;                 // the slot of s->geoms[i]
    int slot_of_cap;
    hash_place *next;             // the geoms that move, in space order (scratch of hash_update)
    int next_cap;
    dxHashCells cells;
    hash_node *nodes, *placed;    // placed geoms by level / in space order
    int nodes_cap, placed_cap, n_nodes;
    dxGeom **big;
    int big_cap, n_big;
    hash_level *levels;           // in increasing level
    int levels_cap, n_levels;
    int n_entries;                // entries in the cells (as of the last update)
    hash_box *box;                // the geoms' boxes by slot, as of the last update
                                  // (for same_level_pairs)
    int box_cap;
    int *meets;                   // a geom's partners whose boxes overlap its (the same;
    int meets_cap, meets_top;     // a nested collision's after those of the one it is in)
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

// 1 / (cell size) = 2^-level (clamped: beyond 2^+-2000 a double is 0 or inf),
// made from its bits where 2^-level is a normal double.
static double level_scale(int level)
{
    if (level >= -1022 && level <= 1022) {
        const uint64_t bits = (uint64_t)(1023 - level) << 52;
        double d;
        memcpy(&d, &bits, sizeof d);
        return d;
    }
    return ldexp(1.0, level < -2000 ? 2000 : level > 2000 ? -2000 : -level);
}

// floor(a) for |a| <= 2^52 (the conversion truncates toward zero).
static int64_t floor_index(double a)
{
    const int64_t t = (int64_t)a;
    return t - (a < (double)t);
}

// The cells at 1 / (cell size) = scale that the AABB touches, lo..hi per
// axis; 0 if an index would not be exact (infinite, huge, NaN or empty box).
static int cell_range(const dReal *aabb, double scale, int64_t lo[3], int64_t hi[3])
{
    for (int k = 0; k < 3; k++) {
        double a = aabb[2 * k] * scale, b = aabb[2 * k + 1] * scale;
        if (!(a >= -CELL_LIMIT && b <= CELL_LIMIT && a <= b)) return 0;
        lo[k] = floor_index(a);
        hi[k] = floor_index(b);
    }
    return 1;
}

// Number of cells in the ranges lo..hi.
static double cell_count(const int64_t lo[3], const int64_t hi[3])
{
    return (double)(hi[0] - lo[0] + 1) * (double)(hi[1] - lo[1] + 1) * (double)(hi[2] - lo[2] + 1);
}

// The smallest L with 2^L >= side > 0 (side finite): from the exponent's
// bits, one more when the mantissa is not exactly 1 (frexp for subnormals).
static int side_level(double side)
{
    uint64_t bits;
    memcpy(&bits, &side, sizeof bits);
    const int e = (int)(bits >> 52 & 0x7ff);
    if (e == 0) {
        int x;
        const double m = frexp(side, &x);   // side = m 2^x, 1/2 <= m < 1
        return m == 0.5 ? x - 1 : x;
    }
    return e - 1023 + ((bits & 0xfffffffffffffu) != 0);
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
        int need = side_level(side);
        if (need > L) L = need;
    }
    if (L > hs->maxlevel) return 0;
    if (!cell_range(aabb, level_scale(L), lo, hi)) return 0;
    // side is b - a rounded: a box a little longer than 2^L can have a side
    // of 2^L and reach a third cell on an axis (a = -2^-53, b = 1 at level
    // 0: cells -1, 0 and 1). One level up it touches at most two, all that
    // place records.
    if (hi[0] - lo[0] > 1 || hi[1] - lo[1] > 1 || hi[2] - lo[2] > 1) {
        if (++L > hs->maxlevel) return 0;
        if (!cell_range(aabb, level_scale(L), lo, hi)) return 0;
    }
    *level = L;
    return 1;
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
    hs->levels[lo] = (hash_level){ level, 0, 0, level_scale(level) };
    hs->n_levels++;
    return lo;
}

// level_index, trying the last answer first (neighbours in space order
// mostly share a level).
static int level_index_near(dxHashSpace *hs, int level, int *last)
{
    if (*last < hs->n_levels && hs->levels[*last].level == level) return *last;
    return *last = level_index(hs, level);
}

// The bounds of the longest side of a box that keeps the placed geom of sl
// at its level, (side_lo, side_hi]: they depend on minlevel (a geom at
// minlevel may be as small as it likes), so they are set again whenever the
// levels change.
static void side_bounds(const dxHashSpace *hs, hash_slot *sl)
{
    const int level = sl->level;
    const int exact = level > -1000 && level < 1000;   // 2^level, 2^(level-1) are doubles
    sl->side_lo = level == hs->minlevel ? -1.0 : level_scale(1 - level);
    sl->side_hi = exact ? level_scale(-level) : NAN;
}

// Take the geom of slot si out of its cells.
static void unplace(dxHashSpace *hs, int si)
{
    hash_slot *sl = &hs->slots[si];
    for (int k = 0; k < sl->n; k++) dxHashCellsUnlink(&hs->cells, si * PER_GEOM + k);
    sl->n = 0;
}

// Record the geom of slot si in the cells lo..hi of `level` (at most two per
// axis: its AABB is no longer than the cells' side); `latest`: the cells are
// being filled in space order, so it goes first in each.
static void place(dxHashSpace *hs, int si, int level, const int64_t lo[3], const int64_t hi[3],
                  int latest)
{
    unplace(hs, si);
    hash_slot *sl = &hs->slots[si];
    sl->state = SLOT_PLACED;
    sl->level = level;
    memcpy(sl->lo, lo, sizeof sl->lo);
    memcpy(sl->hi, hi, sizeof sl->hi);
    sl->scale = level_scale(level);
    for (int k = 0; k < 3; k++) {
        sl->lo_d[k] = (double)lo[k];
        sl->hi_d[k] = (double)hi[k];
    }
    side_bounds(hs, sl);
    for (int64_t i = lo[0]; i <= hi[0]; i++)
        for (int64_t j = lo[1]; j <= hi[1]; j++)
            for (int64_t k = lo[2]; k <= hi[2]; k++) {
                const int64_t c[3] = { i, j, k };
                const int e = si * PER_GEOM + sl->n++;
                hs->cells.entries[e].g = sl->g;
                hs->cells.entries[e].lowest = lowest_bits(c, lo);
                if (latest) dxHashCellsPushFresh(&hs->cells, e, level, c);
                else dxHashCellsLink(&hs->cells, e, level, c);
            }
}

// 1 if the box b gives the placed geom of slot sl the level and cells it
// has: what geom_level would find (the same products, compared with the
// cells' bounds instead of floored), at less cost.
static int keeps_place(const hash_slot *sl, const dReal *b)
{
    double side = 0;
    for (int k = 0; k < 3; k++) {
        const double d = (double)b[2 * k + 1] - (double)b[2 * k];
        if (!(d >= 0)) return 0;
        if (d > side) side = d;
        const double lo = b[2 * k] * sl->scale, hi = b[2 * k + 1] * sl->scale;
        if (!(lo >= sl->lo_d[k] && lo < sl->lo_d[k] + 1)) return 0;
        if (!(hi >= sl->hi_d[k] && hi < sl->hi_d[k] + 1)) return 0;
    }
    return side > sl->side_lo && side <= sl->side_hi;
}

static int same_place(const hash_slot *sl, const hash_place *p)
{
    return sl->state == SLOT_PLACED && sl->level == p->level && sl->lo[0] == p->lo[0] &&
           sl->lo[1] == p->lo[1] && sl->lo[2] == p->lo[2] && sl->hi[0] == p->hi[0] &&
           sl->hi[1] == p->hi[1] && sl->hi[2] == p->hi[2];
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
    int last = 0;
    for (int i = 0; i < hs->n_nodes; i++) {
        const int li = level_index_near(hs, hs->placed[i].level, &last);
        hash_level *lv = &hs->levels[li];
        hs->nodes[lv->start + lv->count++] = hs->placed[i];
    }
}

// List the big geoms in space order, and the placed ones by level.
static void list_geoms(dxHashSpace *hs)
{
    const dxSpace *s = &hs->s;
    hs->placed = grow(hs->placed, &hs->placed_cap, s->count, sizeof *hs->placed);
    hs->big = grow(hs->big, &hs->big_cap, s->count, sizeof *hs->big);
    hs->n_nodes = hs->n_big = hs->n_levels = 0;
    int last = 0;
    for (int i = 0; i < s->count; i++) {
        const hash_slot *sl = &hs->slots[hs->slot_of[i]];
        if (sl->state == SLOT_BIG) {
            hs->big[hs->n_big++] = sl->g;
            continue;
        }
        hs->placed[hs->n_nodes++] = (hash_node){ sl->g, sl->level };
        const int li = level_index_near(hs, sl->level, &last);   // may move hs->levels
        hs->levels[li].count++;
    }
    sort_nodes(hs);
}

// Record the geom of slot si afresh where it already is (after
// dxHashCellsRestart, in space order).
static void place_again(dxHashSpace *hs, int si)
{
    hash_slot *sl = &hs->slots[si];
    sl->n = 0;   // (the cells forgot its entries)
    if (sl->state != SLOT_PLACED) return;
    int64_t lo[3], hi[3];
    memcpy(lo, sl->lo, sizeof lo);
    memcpy(hi, sl->hi, sizeof hi);
    place(hs, si, sl->level, lo, hi, 1);
}

// Put the geom of slot si where p says.
static void move_to(dxHashSpace *hs, int si, const hash_place *p, int afresh)
{
    hash_slot *sl = &hs->slots[si];
    if (afresh) sl->n = 0;   // (the cells forgot its entries)
    if (p->placed) {
        place(hs, si, p->level, p->lo, p->hi, afresh);
    } else {
        unplace(hs, si);
        sl->state = SLOT_BIG;
    }
}

// Bring the cells up to date with the geoms' boxes. Only geoms whose level
// or cells changed are moved (an unlink and a link per cell: a hash lookup
// each); when that is more than a third of them (a scene in motion), the
// cells are emptied and every geom is linked afresh in space order instead
// (each entry first in its cell: nothing to unlink, no list to walk).
// Either way the cells list the same geoms in the same order. The lists of
// geoms by level change only when a level or the membership did.
static void hash_update(dxHashSpace *hs)
{
    const dxSpace *s = &hs->s;
    hs->next = grow(hs->next, &hs->next_cap, s->count, sizeof *hs->next);
    hs->box = grow(hs->box, &hs->box_cap, hs->n_slots, sizeof *hs->box);
    int n_placed = 0, n_entries = 0, moved = 0, relevelled = hs->members_changed;
    const int check_kept = !hs->levels_changed && !hs->afresh;
    for (int i = 0; i < s->count; i++) {
        hash_slot *sl = &hs->slots[hs->slot_of[i]];
        hs->box[hs->slot_of[i]] = box_of(sl->g->aabb);
        if (check_kept && sl->state == SLOT_PLACED && keeps_place(sl, sl->g->aabb)) {
            n_placed++;
            n_entries += sl->n;
            continue;
        }
        hash_place *p = &hs->next[moved];
        p->i = i;
        p->placed = geom_level(hs, sl->g->aabb, &p->level, p->lo, p->hi);
        int changed, new_level;
        if (p->placed) {
            n_placed++;
            n_entries += (int)cell_count(p->lo, p->hi);
            changed = !same_place(sl, p);
            if (!changed) side_bounds(hs, sl);   // (minlevel may have changed)
            new_level = sl->state != SLOT_PLACED || sl->level != p->level;
        } else {
            changed = new_level = sl->state != SLOT_BIG;
        }
        moved += changed;   // (p is kept only if it moves)
        relevelled += new_level;
    }
    hs->stale = hs->levels_changed = hs->afresh = 0;
    hs->n_entries = n_entries;
    if (!moved && !relevelled) return;
    const int afresh = hs->afresh = 3 * moved > n_placed;
    if (afresh) {
        dxHashCellsRestart(&hs->cells, n_entries);
        const hash_place *p = hs->next, *end = hs->next + moved;
        for (int i = 0; i < s->count; i++) {
            if (p < end && p->i == i) move_to(hs, hs->slot_of[i], p++, 1);
            else place_again(hs, hs->slot_of[i]);
        }
    } else {
        for (int m = 0; m < moved; m++) move_to(hs, hs->slot_of[hs->next[m].i], &hs->next[m], 0);
    }
    if (relevelled) list_geoms(hs);
    hs->members_changed = 0;
}

// Make the cells current; 0 if they are stale but an outer collision of
// this space still walks them (a callback moved a geom): the caller then
// tests geoms one by one.
static int hash_ready(dxHashSpace *hs)
{
    if (!hs->stale) return 1;
    if (hs->walking > 0) return 0;
    hash_update(hs);
    return 1;
}

// dxSpaceTestPair, inline (most pairs of neighbouring cells have their
// boxes apart), counted in *tests (space_pair.h: the caller adds its count
// to dx_aabb_tests at its end).
static inline __attribute__((always_inline)) void test_pair(dxGeom *a, dxGeom *b, void *data,
                                                           dNearCallback *cb,
                                                           unsigned long *tests)
{
    ++*tests;
    dxSpaceTestPairUncounted(a, b, data, cb);
}

// g against the geoms of `level` recorded in cell c (g's lowest-cell bits
// there: lowest).
static inline __attribute__((always_inline)) void query_cell(const dxHashSpace *hs, dxGeom *g,
                                                            int level, const int64_t c[3],
                                                            unsigned lowest, void *data,
                                                            dNearCallback *cb,
                                                            unsigned long *tests)
{
    const dxHashEntry *en = hs->cells.entries;
    for (int e = dxHashCellsFind(&hs->cells, level, c); e >= 0; e = en[e].next)
        if ((en[e].lowest | lowest) == ALL_AXES) test_pair(g, en[e].g, data, cb, tests);
}

int dxHashFewGeoms = 8;   // (geom_internal.h)

// 1 if the box of a geom of level lv overlaps g's: box tests alone (no
// callback), counted in *tests, up to the first that overlaps.
static inline __attribute__((always_inline)) int level_meets(const dxHashSpace *hs,
                                                            const dxGeom *g,
                                                            const hash_level *lv,
                                                            unsigned long *tests)
{
    const hash_node *n = hs->nodes + lv->start, *end = n + lv->count;
    for (; n < end; n++) {
        ++*tests;
        if (dxAABBsOverlap(g->aabb, n->g->aabb)) return 1;
    }
    return 0;
}

// g against the placed geoms of levels[first ..]: through the cells of each
// level that g's AABB touches, or one by one when those cells outnumber the
// level's geoms (a big g against small geoms). One cell never outnumbers
// them (a level lists at least one geom).
//
// Levels of at most dxHashFewGeoms geoms (at least 1) are tested without
// their cells first. A level of one geom (a terrain above everything else)
// is tested one by one: the cells would test the pair once if the boxes
// overlap (in the cell holding q) and maybe not at all if not, so the
// callbacks are the same. A level of a few more (the walls of a container)
// is tested box by box and passed over when no box overlaps g's (most geoms
// touch no wall), which costs less than finding g's cells there and looking
// them up. The callbacks are the same: whatever cells g's box touches, and
// whether or not they still describe the boxes (a callback of this
// collision may have moved geoms), a cell lists only geoms of its level,
// all among the level's nodes, and test_pair neither calls back nor asks a
// user class's box test when the two boxes, as they are, do not overlap; so
// that level would have made no callback, and nothing else happens between
// the box tests. Otherwise the level is walked as before.
static void query_levels(const dxHashSpace *hs, dxGeom *g, int first, void *data,
                         dNearCallback *cb)
{
    unsigned long tests = 0;
    for (int li = first; li < hs->n_levels; li++) {
        const hash_level *lv = &hs->levels[li];
        if (lv->count <= dxHashFewGeoms) {
            if (lv->count == 1) {
                test_pair(g, hs->nodes[lv->start].g, data, cb, &tests);
                continue;
            }
            if (!level_meets(hs, g, lv, &tests)) continue;
        }
        int64_t lo[3], hi[3];
        const int inside = cell_range(g->aabb, lv->scale, lo, hi);
        if (inside && lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) {   // the common case
            query_cell(hs, g, lv->level, lo, ALL_AXES, data, cb, &tests);
            continue;
        }
        if (inside && cell_count(lo, hi) <= lv->count) {
            for (int64_t i = lo[0]; i <= hi[0]; i++)
                for (int64_t j = lo[1]; j <= hi[1]; j++)
                    for (int64_t k = lo[2]; k <= hi[2]; k++) {
                        const int64_t c[3] = { i, j, k };
                        query_cell(hs, g, lv->level, c, lowest_bits(c, lo), data, cb,
                                   &tests);
                    }
        } else {
            for (int n = lv->start; n < lv->start + lv->count; n++)
                test_pair(g, hs->nodes[n].g, data, cb, &tests);
        }
    }
    dx_aabb_tests += tests;
}

static int enabled(const dxGeom *g) { return (g->flags & DX_GEOM_ENABLED) != 0; }

static void brute_collide(const dxSpace *s, void *data, dNearCallback *cb)
{
    for (int i = 0; i < s->count; i++)
        for (int j = i + 1; j < s->count; j++) dxSpaceTestPair(s->geoms[i], s->geoms[j], data, cb);
}

// The box test of hash_collide's walk without branches: 1 if p <= b->q in
// every number, p = (min, -max) made by box_p_of from a's q (hash_box: a's
// box and b's overlap, closed, as dxAABBsOverlap), two or four numbers at a
// time where SSE2 is.
#if defined(__SSE2__) && !defined(dSINGLE)
typedef __m128d box_p[3];
static inline __attribute__((always_inline)) void box_p_of(box_p p, const hash_box *a)
{
    const dReal *q = a->q;
    p[0] = _mm_set_pd(-q[4], -q[3]);
    p[1] = _mm_set_pd(-q[0], -q[5]);
    p[2] = _mm_set_pd(-q[2], -q[1]);
}
static inline __attribute__((always_inline)) int boxes_meet(const box_p p, const hash_box *b)
{
    const __m128d m = _mm_and_pd(_mm_and_pd(_mm_cmple_pd(p[0], _mm_loadu_pd(b->q)),
                                            _mm_cmple_pd(p[1], _mm_loadu_pd(b->q + 2))),
                                 _mm_cmple_pd(p[2], _mm_loadu_pd(b->q + 4)));
    return _mm_movemask_pd(m) == 3;
}
#elif defined(__SSE2__)
typedef __m128 box_p[2];
static inline __attribute__((always_inline)) void box_p_of(box_p p, const hash_box *a)
{
    const dReal *q = a->q;
    p[0] = _mm_set_ps(-q[0], -q[5], -q[4], -q[3]);
    p[1] = _mm_set_ps(0, 0, -q[2], -q[1]);
}
static inline __attribute__((always_inline)) int boxes_meet(const box_p p, const hash_box *b)
{
    const __m128 m = _mm_and_ps(_mm_cmple_ps(p[0], _mm_loadu_ps(b->q)),
                                _mm_cmple_ps(p[1], _mm_loadu_ps(b->q + 4)));
    return _mm_movemask_ps(m) == 15;
}
#else
typedef dReal box_p[6];
static inline void box_p_of(box_p p, const hash_box *a)
{
    for (int k = 0; k < 6; k++) p[k] = -a->q[(k + 3) % 6];
}
static inline int boxes_meet(const box_p p, const hash_box *b)
{
    return (p[0] <= b->q[0]) & (p[1] <= b->q[1]) & (p[2] <= b->q[2]) & (p[3] <= b->q[3]) &
           (p[4] <= b->q[4]) & (p[5] <= b->q[5]);
}
#endif

// The pairs of geoms of one level that share a cell: each geom's entries in
// space order, against the entries after it in the cell's list (earlier
// geoms). A geom's partners whose boxes overlap its are listed without a
// branch on the box test (most pairs in a cell are apart, unpredictably),
// then called back in that order. The number of box tests made.
SAME_LEVEL_CLONES static unsigned long same_level_pairs(dxHashSpace *hs, void *data,
                                                        dNearCallback *cb)
{
    const dxSpace *s = &hs->s;
    const dxHashEntry *en = hs->cells.entries;
    const hash_box *box = hs->box;
    // The partners' list, after those of a collision this one is nested in
    // (a geom has fewer partners than the cells have entries).
    const int base = hs->meets_top;
    hs->meets = grow(hs->meets, &hs->meets_cap, base + hs->n_entries, sizeof *hs->meets);
    hs->meets_top = base + hs->n_entries;
    unsigned long tests = 0;
    for (int i = 0; i < s->count; i++) {
        const int si = hs->slot_of[i];
        const hash_slot *sl = &hs->slots[si];
        dxGeom *a = sl->g;
        if (sl->state != SLOT_PLACED || !enabled(a)) continue;   // (only placed geoms have cells)
        int *meets = hs->meets + base, n = 0;
        box_p p;
        box_p_of(p, &box[si]);
        for (int e = si * PER_GEOM; e < si * PER_GEOM + sl->n; e++) {
            const unsigned lowest = en[e].lowest;
            for (int f = en[e].next; f >= 0; f = en[f].next) {
                if ((en[f].lowest | lowest) != ALL_AXES) continue;   // not the pair's cell
                const unsigned b = (unsigned)f / PER_GEOM;              // its geom's slot
                tests++;
                meets[n] = (int)b;
                n += boxes_meet(p, &box[b]);
            }
        }
        for (int k = 0; k < n; k++) {   // (a nested collision may move hs->meets)
            dxGeom *b = hs->slots[hs->meets[base + k]].g;
            if (dxGeomsMayTouchOverlapping(a, b)) cb(data, a, b);
        }
    }
    hs->meets_top = base;
    return tests;
}

static void hash_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    if (!hash_ready(hs)) {
        brute_collide(s, data, cb);
        return;
    }
    hs->walking++;
    unsigned long tests = 0;
    // Big geoms against every geom.
    for (int i = 0; i < hs->n_big; i++) {
        dxGeom *a = hs->big[i];
        if (!enabled(a)) continue;
        for (int j = i + 1; j < hs->n_big; j++) test_pair(a, hs->big[j], data, cb, &tests);
        for (int j = 0; j < hs->n_nodes; j++) test_pair(a, hs->nodes[j].g, data, cb, &tests);
    }
    dx_aabb_tests += tests + same_level_pairs(hs, data, cb);
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
    unsigned long tests = 0;
    for (int i = 0; i < hs->n_big; i++) test_pair(g, hs->big[i], data, cb, &tests);
    dx_aabb_tests += tests;
    query_levels(hs, g, 0, data, cb);
    hs->walking--;
}

// A geom joined the space (last in space order): it gets a slot, placed at
// the next update.
static void hash_added(dxSpace *s, dxGeom *g)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    int si = hs->free_slot;
    if (si >= 0) {
        hs->free_slot = hs->slots[si].next_free;
    } else {
        hs->slots = grow(hs->slots, &hs->slots_cap, hs->n_slots + 1, sizeof *hs->slots);
        si = hs->n_slots++;
        dxHashCellsReserve(&hs->cells, hs->n_slots);
    }
    hs->slots[si] = (hash_slot){ .g = g, .state = SLOT_NEW, .next_free = -1 };
    hs->slot_of = grow(hs->slot_of, &hs->slot_of_cap, s->count, sizeof *hs->slot_of);
    hs->slot_of[g->space_index] = si;
    hs->stale = hs->members_changed = 1;
}

// A geom is leaving the space: out of its cells, its slot freed, the later
// geoms' slots moved down with them in space order.
static void hash_removed(dxSpace *s, dxGeom *g)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    const int at = g->space_index, si = hs->slot_of[at];
    unplace(hs, si);
    hs->slots[si] = (hash_slot){ .state = SLOT_FREE, .next_free = hs->free_slot };
    hs->free_slot = si;
    memmove(&hs->slot_of[at], &hs->slot_of[at + 1],
            (size_t)(s->count - 1 - at) * sizeof *hs->slot_of);
    hs->stale = hs->members_changed = 1;
}

static void hash_destroy(dxSpace *s)
{
    dxHashSpace *hs = (dxHashSpace *)s;
    dFree(hs->slots, (size_t)hs->slots_cap * sizeof *hs->slots);
    dFree(hs->slot_of, (size_t)hs->slot_of_cap * sizeof *hs->slot_of);
    dFree(hs->next, (size_t)hs->next_cap * sizeof *hs->next);
    dxHashCellsFree(&hs->cells);
    dFree(hs->nodes, (size_t)hs->nodes_cap * sizeof *hs->nodes);
    dFree(hs->placed, (size_t)hs->placed_cap * sizeof *hs->placed);
    dFree(hs->big, (size_t)hs->big_cap * sizeof *hs->big);
    dFree(hs->levels, (size_t)hs->levels_cap * sizeof *hs->levels);
    dFree(hs->box, (size_t)hs->box_cap * sizeof *hs->box);
    dFree(hs->meets, (size_t)hs->meets_cap * sizeof *hs->meets);
}

static const dxSpaceOps hash_ops = { hash_added, hash_removed, hash_collide, hash_collide_geom,
                                     hash_destroy };

// The class operations of all spaces, with compute_aabb wrapped: the space's
// box is recomputed exactly when something in it changed, which makes the
// cells stale.
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
    hs->free_slot = -1;
    dxHashCellsInit(&hs->cells);
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
    hs->stale = hs->levels_changed = 1;
}

void dHashSpaceGetLevels(dSpaceID s, int *minlevel, int *maxlevel)
{
    CHECK_HASH_SPACE(s, return);
    const dxHashSpace *hs = (const dxHashSpace *)s;
    if (minlevel) *minlevel = hs->minlevel;
    if (maxlevel) *maxlevel = hs->maxlevel;
}
