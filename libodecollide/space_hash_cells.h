// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash_cells.h -- the cells of a hash space (space_hash.c), kept from
// one collision to the next: a table from a cell (level, i, j, k) to the list
// of the geoms recorded in it, latest in space order first. A geom owns
// DX_HASH_CELLS_PER_GEOM entries (one per cell it touches) at a fixed place,
// so moving it relinks only its own entries. A cell that empties leaves the
// table; the arrays grow geometrically and never shrink: a steady state
// allocates nothing. The lookups every collision makes are inline here.

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
    int cell;          // the cell's slot
    unsigned lowest;   // bit k: the cell is the geom's lowest on axis k
} dxHashEntry;

// A cell in use, a slot of the table: its key and the first entry of its
// list (latest in space order); head < 0 for an empty slot. 32 bytes, so
// that a lookup finds the key and the list in one cache line.
typedef struct dxHashCell {
    int64_t c[3];
    int level;
    int head;
} dxHashCell;

// The cells are an open-addressed table (linear probing, at most half full):
// a lookup reads the slots from the cell's hash on, with no bucket array to
// wait on first. A slot's index changes only when the table grows or a
// removal shifts a later slot back into it; the entries' `cell` follow.
typedef struct dxHashCells {
    dxHashEntry *entries;         // DX_HASH_CELLS_PER_GEOM per geom slot
    int entries_cap;
    dxHashCell *cells;            // mask + 1 slots, aligned to 64 bytes (before first
    void *cells_mem;              // use, one empty slot not allocated); their allocation
    int mask;                     // a power of two less one
    int live;                     // slots in use
    int *used;                    // the slots made live since the table was last emptied or
    int used_cap, n_used;         // rebuilt (some may be empty again): mask + 1 at most
    int used_all;                 // 1 while every slot in use is in `used`
} dxHashCells;

// An empty table.
void dxHashCellsInit(dxHashCells *hc);
// Room for the entries of geom slots 0 .. slots - 1.
void dxHashCellsReserve(dxHashCells *hc, int slots);
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
// through the carries) picks the slot; neighbouring cells spread.
static inline unsigned dxHashCellBucket(int level, const int64_t c[3], int mask)
{
    const uint64_t h = (uint64_t)c[0] * 0x9E3779B97F4A7C15u + (uint64_t)c[1] * 0xC2B2AE3D27D4EB4Fu +
                       (uint64_t)c[2] * 0x165667B19E3779F9u +
                       (uint64_t)(int64_t)level * 0x27D4EB2F165667C5u;
    return (unsigned)(h >> 32) & (unsigned)mask;
}

// 1 if the slot holds cell (level, c) (its key; the slot may be empty).
static inline int dxHashCellIs(const dxHashCell *cell, int level, const int64_t c[3])
{
    return cell->c[0] == c[0] && cell->c[1] == c[1] && cell->c[2] == c[2] && cell->level == level;
}

// The slot of cell (level, c), or -1 if it has none.
static inline int dxHashCellsLookup(const dxHashCells *hc, int level, const int64_t c[3])
{
    for (unsigned i = dxHashCellBucket(level, c, hc->mask);; i = (i + 1) & (unsigned)hc->mask) {
        const dxHashCell *cell = &hc->cells[i];
        if (cell->head < 0) return -1;
        if (dxHashCellIs(cell, level, c)) return (int)i;
    }
}

// The first entry of cell (level, c), or -1 if no geom is recorded there.
static inline int dxHashCellsFind(const dxHashCells *hc, int level, const int64_t c[3])
{
    for (unsigned i = dxHashCellBucket(level, c, hc->mask);; i = (i + 1) & (unsigned)hc->mask) {
        const dxHashCell *cell = &hc->cells[i];
        if (cell->head < 0 || dxHashCellIs(cell, level, c)) return cell->head;
    }
}

// Record entry e (its g and lowest set) first in cell (level, c), after
// dxHashCellsRestart: the cells are being filled in space order, so its geom
// is the latest of the cell's, and there is room.
static inline void dxHashCellsPushFresh(dxHashCells *hc, int e, int level, const int64_t c[3])
{
    unsigned i = dxHashCellBucket(level, c, hc->mask);
    dxHashCell *cell = &hc->cells[i];
    while (cell->head >= 0 && !dxHashCellIs(cell, level, c)) {
        i = (i + 1) & (unsigned)hc->mask;
        cell = &hc->cells[i];
    }
    if (cell->head < 0) {
        *cell = (dxHashCell){ { c[0], c[1], c[2] }, level, -1 };
        hc->live++;
        hc->used[hc->n_used++] = (int)i;
    }
    hc->entries[e].next = cell->head;
    hc->entries[e].cell = (int)i;
    cell->head = e;
}

#endif
