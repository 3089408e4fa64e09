// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_tc.c -- temporal coherence of the native trimesh colliders,
// always on (dGeomTriMeshEnableTC's flags change nothing: the cache is
// invisible): per thread, a cache with an entry per (mesh geom, other geom)
// pair holding the tree's leaves that an enlarged ("fat") box around an
// earlier query box meets. While the query box stays inside the fat box, the
// leaves the tree walk would list are picked from the kept ones by the walk's
// own test of their boxes, which gives the same leaves in the same order
// (see dxTriMeshQueryLeavesCached): the contacts never change, only the time.
//
// An entry is found by the mesh's tc_id (unique; ClearTCCache renews it)
// and the other geom's address, which is compared, never followed: after
// the other geom is destroyed, its entry can only be found by a new geom at
// the same address, and is still exact for it (an entry says which leaves
// its fat box meets, whoever asks). An entry is used only with the tree
// stamp it was made with (a new build or Update, or other data set on the
// geom, changes it; a heightfield's patch has stamp 0 and is never cached)
// and while the query box lies in its fat box; otherwise it is made again.
// Boxes are in the mesh's frame, so a moving mesh needs nothing more. The
// cache has a fixed size (SETS x WAYS entries, allocated when the thread
// first uses it): a pair that finds no room takes the entry used least
// recently in its set. An entry keeps its leaves as runs of one node's
// (a node's box test picks a run's leaves at once); one whose fat box meets
// leaves that make more than RUNS runs records only that, and its pair
// walks the tree (a large geom gains nothing from the cache).

#include "collide_trimesh.h"

#include <stdint.h>
#include <string.h>

// A set: WAYS entries of two cache lines each, a pair's key, fat box,
// stamp and clock in the first line with the first of its RUNS runs of
// leaves.
enum { SETS = 512, WAYS = 4, RUNS = 17 };

// The fat box: each side this fraction of the query box's largest half
// extent out from the query box, and on the side the box moves to (from
// the centre of the pair's last fat box, when it is from the same tree)
// MOVE times as far as it moved.
#define FAT 0.25f
#define MOVE 1.5f

typedef struct dxTriLeafEntry {
    uint64_t mesh_id;     // the mesh's tc_id; 0: empty
    const void *other;    // the other geom (never followed)
    uint64_t stamp;       // the tree stamp the leaves are from; 0: none
    float lo[3], hi[3];   // the fat box as floats
    uint32_t used;        // the table's clock when last used (wraps: only
                          // the choice of a way to take over suffers)
    uint32_t next;        // the entry found after this one, last time
    int n;                // runs, or -1: more than RUNS
    int run[RUNS];        // node * 16 + a bit per kept slot: the kept
                          // leaves, in leaf order, by runs of one node's
} leaf_entry;

_Static_assert(sizeof(leaf_entry) == 128, "an entry is two cache lines");

// The entries, set after set; the last entry found, and the one expected
// next (the pairs of a step come in the order of the step before).
typedef struct leaf_table {
    uint32_t clock, last, expected;
    _Alignas(64) leaf_entry entry[SETS * WAYS];
} leaf_table;

// The first way of the pair's set.
static inline leaf_entry *pair_set(leaf_table *t, uint64_t mesh_id, const void *other)
{
    const uint64_t h =
        mesh_id * 0x9e3779b97f4a7c15u ^ (uint64_t)(uintptr_t)other * 0xc2b2ae3d27d4eb4fu;
    return &t->entry[(h >> 32) % SETS * WAYS];
}

// The entry of the pair (the expected one, else one of its set), or the one
// of its set to take over (its stamp 0).
static leaf_entry *find_entry(leaf_table *t, uint64_t mesh_id, const void *other)
{
    const uint32_t now = ++t->clock;
    leaf_entry *e = &t->entry[t->expected];
    if (e->mesh_id == mesh_id && e->other == other) {
        e->used = now;
        return e;
    }
    leaf_entry *set = pair_set(t, mesh_id, other);
    for (int w = 0; w < WAYS; w++) {
        if (set[w].mesh_id == mesh_id && set[w].other == other) {
            set[w].used = now;
            return &set[w];
        }
    }
    e = &set[0];
    for (int w = 1; w < WAYS; w++)
        if (now - set[w].used > now - e->used) e = &set[w];
    e->mesh_id = mesh_id;
    e->other = other;
    e->stamp = 0;
    e->used = now;
    return e;
}

dxTriLeafEntry *dxTriMeshLeafEntry(dxTriScratch *s, const dxTriMesh *m, const void *other)
{
    const dxTriMeshData *d = m->data;
    if (d->tree_stamp == 0) return NULL;
    if (!s->tc) s->tc = dxTriScratchThreadTC(sizeof(leaf_table));
    leaf_table *t = (leaf_table *)s->tc;
    leaf_entry *e = find_entry(t, m->tc_id, other);
    const uint32_t i = (uint32_t)(e - t->entry);
    t->entry[t->last].next = i;
    t->last = i;
    t->expected = e->next;
    const char *next = (const char *)&t->entry[e->next];
    __builtin_prefetch(next);
    __builtin_prefetch(next + 64);
    __builtin_prefetch(&e->run[RUNS - 1]);
    if (e->stamp == d->tree_stamp) {
        for (int r = 0; r < e->n; r++) {
            const char *node = (const char *)&d->nodes[e->run[r] >> 4];
            __builtin_prefetch(node);
            __builtin_prefetch(node + 64);
        }
    }
    return e;
}

// Whether the float box [lo, hi] lies in e's fat box (false for a NaN).
static inline int inside(const leaf_entry *e, const float lo[3], const float hi[3])
{
    int in = 1;
    for (int k = 0; k < 3; k++) in &= (lo[k] >= e->lo[k]) & (hi[k] <= e->hi[k]);
    return in;
}

// The n leaves (node * 4 + slot, in leaf order) as runs of one node's into
// e; -1 if they make more than RUNS.
static int make_runs(leaf_entry *e, const int *leaf, int n)
{
    int runs = 0;
    for (int i = 0; i < n; i++) {
        const int node = leaf[i] >> 2, bit = 1 << (leaf[i] & 3);
        if (runs > 0 && e->run[runs - 1] >> 4 == node) {
            e->run[runs - 1] |= bit;
        } else {
            if (runs == RUNS) return -1;
            e->run[runs++] = node << 4 | bit;
        }
    }
    return runs;
}

// Make e for the query box [lo, hi] (floats) of data d: the fat box and the
// leaves it meets. A fat box stretched along the motion whose leaves make
// more than RUNS runs is made again without the stretch.
static void fill_entry(leaf_entry *e, const dxTriMeshData *d, const float lo[3],
                       const float hi[3])
{
    float half = 0, move[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; k++) half = fmaxf(half, (hi[k] - lo[k]) / 2);
    if (e->stamp == d->tree_stamp)
        for (int k = 0; k < 3; k++) move[k] = MOVE * ((lo[k] + hi[k]) - (e->lo[k] + e->hi[k])) / 2;
    for (int stretch = 1; stretch >= 0; stretch--) {
        for (int k = 0; k < 3; k++) {
            e->lo[k] = lo[k] - FAT * half + (stretch ? fminf(move[k], 0) : 0);
            e->hi[k] = hi[k] + FAT * half + (stretch ? fmaxf(move[k], 0) : 0);
        }
        int leaf[4 * RUNS];
        const int n = dxTriMeshQueryLeavesF(d, e->lo, e->hi, leaf, 4 * RUNS);
        e->n = n < 0 ? -1 : make_runs(e, leaf, n);
        if (e->n >= 0 || (move[0] == 0 && move[1] == 0 && move[2] == 0)) break;
    }
    e->stamp = d->tree_stamp;
}

// Bit s set for each slot of node whose box overlaps the query box, its
// sides each in four lanes (qlo, qhi): dxTriNodeOverlaps's comparisons,
// the slots' use left out.
static inline unsigned slots_meeting(const dxTriMeshNode *node, const dxTriF4 qlo[3],
                                     const dxTriF4 qhi[3])
{
    dxTriI4 m = { -1, -1, -1, -1 };
    for (int k = 0; k < 3; k++) {
        dxTriF4 slo, shi;
        memcpy(&slo, node->lo[k], sizeof slo);
        memcpy(&shi, node->hi[k], sizeof shi);
        m &= (slo <= qhi[k]) & (shi >= qlo[k]);
    }
#if defined(__SSE__)
    return (unsigned)_mm_movemask_ps((__m128)m);
#else
    return (unsigned)((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
}

// Those of e's leaves whose boxes overlap [lo, hi] (floats), as the walk
// tests them (one node's four slots at once), into leaf[] (room for 4 RUNS);
// returns the count.
static int pick_leaves(const dxTriMeshData *d, const leaf_entry *e, const float lo[3],
                       const float hi[3], int *leaf)
{
    dxTriF4 qlo[3], qhi[3];
    for (int k = 0; k < 3; k++) {
        qlo[k] = (dxTriF4){ lo[k], lo[k], lo[k], lo[k] };
        qhi[k] = (dxTriF4){ hi[k], hi[k], hi[k], hi[k] };
    }
    int n = 0;
    for (int i = 0; i < e->n; i++) {
        const int node = e->run[i] >> 4;
        const unsigned meets = slots_meeting(&d->nodes[node], qlo, qhi) & (unsigned)e->run[i];
        for (int slot = 0; slot < 4; slot++) {
            leaf[n] = 4 * node + slot;
            n += meets >> slot & 1;
        }
    }
    return n;
}

// A leaf whose box overlaps the query box is listed by the walk: each of
// its parents' boxes holds its box, so overlaps too. A leaf kept for a fat
// box holding the query box is one of the fat box's, which the walk lists
// in leaf order as it lists the query's: picking the kept leaves that
// overlap gives the walk's list, in its order.
int dxTriMeshQueryLeavesCached(const dxTriMeshData *d, dxTriLeafEntry *e, const float lo_f[4],
                               const float hi_f[4], int *leaf, int max)
{
    if (!e || max <= 4 * RUNS) return dxTriMeshQueryLeavesF(d, lo_f, hi_f, leaf, max);
    if (e->stamp != d->tree_stamp || !inside(e, lo_f, hi_f)) {
        fill_entry(e, d, lo_f, hi_f);
        if (!inside(e, lo_f, hi_f)) return dxTriMeshQueryLeavesF(d, lo_f, hi_f, leaf, max);
    }
    if (e->n < 0) return dxTriMeshQueryLeavesF(d, lo_f, hi_f, leaf, max);
    return pick_leaves(d, e, lo_f, hi_f, leaf);
}
