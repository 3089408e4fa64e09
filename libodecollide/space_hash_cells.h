// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash_cells.h -- the cells of a hash space (space_hash.c), kept from
// one collision to the next: a table from a cell (level, i, j, k) to the list
// of the geoms recorded in it, latest in space order first. A geom owns
// DX_HASH_CELLS_PER_GEOM entries (one per cell it touches) at a fixed place,
// so moving it relinks only its own entries. Cells that empty are recycled;
// the arrays grow geometrically and never shrink: a steady state allocates
// nothing.

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
// The first entry of cell (level, c), or -1 if no geom is recorded there.
int dxHashCellsFind(const dxHashCells *hc, int level, const int64_t c[3]);
// Record entry e (its g and lowest set) in cell (level, c), keeping the
// cell's list in decreasing space order of the geoms.
void dxHashCellsLink(dxHashCells *hc, int e, int level, const int64_t c[3]);
// Take entry e out of its cell (freeing the cell if it empties).
void dxHashCellsUnlink(dxHashCells *hc, int e);
void dxHashCellsFree(dxHashCells *hc);

#endif
