// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_tc.c -- temporal coherence of the native trimesh colliders
// (dGeomTriMeshEnableTC): per thread, a cache with an entry per (mesh geom,
// other geom) pair holding the tree's leaves that an enlarged ("fat") box
// around the other geom's box meets. While the other's box stays inside the
// fat box, a query filters those leaves instead of walking the tree, which
// gives the same triangles in the same order (dxTriMeshFilterLeaves): the
// contacts never change, only the time.
//
// An entry is found by the mesh's tc_id (unique; ClearTCCache renews it)
// and the other geom's address, which is compared, never followed: after
// the other geom is destroyed, its entry can only be found by a new geom at
// the same address, and is still exact for it. An entry is used only with
// the tree stamp it was made with (a new build or Update, or other data set
// on the geom, changes it; a heightfield's patch has stamp 0 and is never
// cached) and while the query box lies in its fat box; otherwise it is made
// again. The cache has a fixed size (SETS x WAYS entries, allocated when the
// thread first uses it): a pair that finds no room takes the entry used
// least recently in its set. An entry whose fat box meets more than LEAVES
// leaves records only that, and its pair walks the tree (a large geom gains
// nothing from the cache).

#include "collide_trimesh.h"

#include <stdint.h>

enum { SETS = 512, WAYS = 4, LEAVES = 24 };

// Each side of the fat box is this fraction of the box's largest half
// extent out from the query box.
#define FAT ((dReal)0.5)

typedef struct tc_entry {
    uint64_t mesh_id;      // the mesh's tc_id; 0: empty
    const void *other;     // the other geom (never followed)
    uint64_t stamp;        // the tree stamp the leaves are from
    uint64_t used;         // the table's clock when last used
    dReal lo[3], hi[3];    // the fat box
    int n;                 // leaves, or -1: more than LEAVES
    int leaf[LEAVES];
} tc_entry;

typedef struct tc_table {
    uint64_t clock;
    tc_entry set[SETS][WAYS];
} tc_table;

// The entry of the pair, or the one of its set to take over (emptied).
static tc_entry *find_entry(tc_table *t, uint64_t mesh_id, const void *other)
{
    uint64_t h = mesh_id * 0x9e3779b97f4a7c15u ^ (uint64_t)(uintptr_t)other * 0xc2b2ae3d27d4eb4fu;
    tc_entry *set = t->set[(h >> 32) % SETS], *oldest = &set[0];
    t->clock++;
    for (int w = 0; w < WAYS; w++) {
        if (set[w].mesh_id == mesh_id && set[w].other == other) {
            set[w].used = t->clock;
            return &set[w];
        }
        if (set[w].used < oldest->used) oldest = &set[w];
    }
    oldest->mesh_id = mesh_id;
    oldest->other = other;
    oldest->stamp = 0;
    oldest->used = t->clock;
    return oldest;
}

static int inside(const dReal lo[3], const dReal hi[3], const dReal flo[3], const dReal fhi[3])
{
    return lo[0] >= flo[0] && lo[1] >= flo[1] && lo[2] >= flo[2] && hi[0] <= fhi[0] &&
           hi[1] <= fhi[1] && hi[2] <= fhi[2];
}

// Make the entry for the query box [lo, hi] of data d.
static void fill_entry(tc_entry *e, const dxTriMeshData *d, const dReal lo[3], const dReal hi[3])
{
    dReal half = 0;
    for (int k = 0; k < 3; k++) half = dMax(half, (hi[k] - lo[k]) / 2);
    for (int k = 0; k < 3; k++) {
        e->lo[k] = lo[k] - FAT * half;
        e->hi[k] = hi[k] + FAT * half;
    }
    e->stamp = d->tree_stamp;
    e->n = dxTriMeshQueryLeaves(d, e->lo, e->hi, e->leaf, LEAVES);
}

int dxTriMeshQueryTC(dxTriScratch *s, const dxTriMesh *m, const dxGeom *other,
                     const dReal lo[3], const dReal hi[3])
{
    const dxTriMeshData *d = m->data;
    if (d->tree_stamp == 0 || !dxTriMeshTCOn(m, other->ops->cls))
        return dxTriMeshQueryBox(d, lo, hi, &s->cand[0], &s->cand_cap[0]);
    tc_table *t = (tc_table *)dxTriScratchThreadTC(sizeof *t);
    tc_entry *e = find_entry(t, m->tc_id, other);
    if (e->stamp != d->tree_stamp || !inside(lo, hi, e->lo, e->hi)) fill_entry(e, d, lo, hi);
    if (e->n < 0) return dxTriMeshQueryBox(d, lo, hi, &s->cand[0], &s->cand_cap[0]);
    return dxTriMeshFilterLeaves(d, e->leaf, e->n, lo, hi, &s->cand[0], &s->cand_cap[0]);
}
