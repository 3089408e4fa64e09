// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash_cells.h -- the cells of a hash space (space_hash.c), kept from
// one collision to the next: a table from a cell (level, i, j, k) to the list
// of the geoms recorded in it, latest in space order first. A geom owns
// DX_HASH_CELLS_PER_GEOM entries (one per cell it touches) at a fixed place,
// so moving it relinks only its own entries. Cells that empty are recycled;
// the arrays grow geometrically and never shrink: a steady state allocates
// nothing. The lookups every collision makes are inline here.

#ifndef SPACE_HASH_CELLS_H
#define SPACE_HASH_CELLS_H

#include "geom_internal.h"

#include <stdint.h>

// A geom at its level touches at most two cells per axis.
#define DX_HASH_CELLS_PER_GEOM 8

// One geom in one cell.
typedef struct dxHashEntry {
    dxGeom *g;
    int next;          // the next entry of the cell (earlier in space order), -1 at the end
    int cell;          // the cell's record
    unsigned lowest;   // bit k: the cell is the geom's lowest on axis k
} dxHashEntry;

typedef struct dxHashCell {
    int64_t c[3];
    int level;
    int head;          // first entry (latest in space order); -1 for a free record
    int next;          // next cell of the same bucket, or next free record
    int bucket;        // its bucket
} dxHashCell;

typedef struct dxHashCells {
    dxHashEntry *entries;         // DX_HASH_CELLS_PER_GEOM per geom slot
    int entries_cap;
    dxHashCell *cells;
    int cells_cap, cells_used;    // records allocated / ever used (high water)
    int free_cell, live;          // first free record (-1 if none), records in use
    int *buckets;                 // first cell of each bucket, -1 if none
    int mask;                     // mask + 1 buckets (a power of two, 0 before first use)
} dxHashCells;

// An empty table (a zeroed one is not: its free list must end at -1).
void dxHashCellsInit(dxHashCells *hc);
// Room for the entries of geom slots 0 .. slots - 1.
void dxHashCellsReserve(dxHashCells *hc, int slots);
// A new record for cell (level, c), known to have none, in its bucket.
int dxHashCellsAdd(dxHashCells *hc, int level, const int64_t c[3]);
// Record entry e (its g and lowest set) in cell (level, c), keeping the
// cell's list in decreasing space order of the geoms.
void dxHashCellsLink(dxHashCells *hc, int e, int level, const int64_t c[3]);
// Take entry e out of its cell (freeing the cell if it empties).
void dxHashCellsUnlink(dxHashCells *hc, int e);
// Forget every cell, with room for `entries` entries to be pushed next
// (dxHashCellsPushFresh) without growing anything.
void dxHashCellsRestart(dxHashCells *hc, int entries);
void dxHashCellsFree(dxHashCells *hc);

// Multiplicative hash of a cell: a sum of the coordinates times odd
// constants, whose high half (which every bit of the coordinates reaches
// through the carries) picks the bucket; neighbouring cells spread.
static inline unsigned dxHashCellBucket(int level, const int64_t c[3], int mask)
{
    const uint64_t h = (uint64_t)c[0] * 0x9E3779B97F4A7C15u + (uint64_t)c[1] * 0xC2B2AE3D27D4EB4Fu +
                       (uint64_t)c[2] * 0x165667B19E3779F9u +
                       (uint64_t)(int64_t)level * 0x27D4EB2F165667C5u;
    return (unsigned)(h >> 32) & (unsigned)mask;
}

// The record of cell (level, c), or -1 if it has none.
static inline int dxHashCellsLookup(const dxHashCells *hc, int level, const int64_t c[3])
{
    if (!hc->mask) return -1;
    for (int i = hc->buckets[dxHashCellBucket(level, c, hc->mask)]; i >= 0; i = hc->cells[i].next) {
        const dxHashCell *cell = &hc->cells[i];
        if (cell->c[0] == c[0] && cell->c[1] == c[1] && cell->c[2] == c[2] && cell->level == level)
            return i;
    }
    return -1;
}

// The first entry of cell (level, c), or -1 if no geom is recorded there.
static inline int dxHashCellsFind(const dxHashCells *hc, int level, const int64_t c[3])
{
    const int i = dxHashCellsLookup(hc, level, c);
    return i < 0 ? -1 : hc->cells[i].head;
}

// Record entry e (its g and lowest set) first in cell (level, c), after
// dxHashCellsRestart: the cells are being filled in space order, so its geom
// is the latest of the cell's, and there is room.
static inline void dxHashCellsPushFresh(dxHashCells *hc, int e, int level, const int64_t c[3])
{
    const unsigned b = dxHashCellBucket(level, c, hc->mask);
    int ci = hc->buckets[b];
    dxHashCell *cell = NULL;
    for (; ci >= 0; ci = cell->next) {
        cell = &hc->cells[ci];
        if (cell->c[0] == c[0] && cell->c[1] == c[1] && cell->c[2] == c[2] && cell->level == level)
            break;
    }
    if (ci < 0) {
        ci = hc->cells_used++;
        hc->live++;
        cell = &hc->cells[ci];
        *cell = (dxHashCell){ { c[0], c[1], c[2] }, level, -1, hc->buckets[b], (int)b };
        hc->buckets[b] = ci;
    }
    hc->entries[e].next = cell->head;
    hc->entries[e].cell = ci;
    cell->head = e;
}

#endif
