// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash_cells.c -- the persistent cells of a hash space
// (space_hash_cells.h). Cells are records chained into buckets, at least
// twice as many buckets as cells in use; a cell's record stays where it is
// while the cell holds geoms, so entries refer to it by index.

#include "space_hash_cells.h"

#include <ode/memory.h>
#include <string.h>

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

// Spread the cells in use over `n` buckets (a power of two).
static void rebucket(dxHashCells *hc, int n)
{
    if (n > hc->mask + 1) {
        const size_t old = hc->mask ? (size_t)(hc->mask + 1) * sizeof *hc->buckets : 0;
        hc->buckets = dRealloc(hc->buckets, old, (size_t)n * sizeof *hc->buckets);
        hc->mask = n - 1;
    }
    memset(hc->buckets, 0xff, (size_t)n * sizeof *hc->buckets);   // all -1
    for (int i = 0; i < hc->cells_used; i++) {
        dxHashCell *cell = &hc->cells[i];
        if (cell->head < 0) continue;
        cell->bucket = (int)dxHashCellBucket(cell->level, cell->c, hc->mask);
        cell->next = hc->buckets[cell->bucket];
        hc->buckets[cell->bucket] = i;
    }
}

void dxHashCellsInit(dxHashCells *hc)
{
    memset(hc, 0, sizeof *hc);
    hc->free_cell = -1;
}

void dxHashCellsReserve(dxHashCells *hc, int slots)
{
    hc->entries = grow(hc->entries, &hc->entries_cap, slots * DX_HASH_CELLS_PER_GEOM,
                       sizeof *hc->entries);
}

int dxHashCellsAdd(dxHashCells *hc, int level, const int64_t c[3])
{
    if (2 * (hc->live + 1) > hc->mask + 1) rebucket(hc, hc->mask ? 2 * (hc->mask + 1) : 64);
    int i = hc->free_cell;
    if (i >= 0) {
        hc->free_cell = hc->cells[i].next;
    } else {
        hc->cells = grow(hc->cells, &hc->cells_cap, hc->cells_used + 1, sizeof *hc->cells);
        i = hc->cells_used++;
    }
    const unsigned b = dxHashCellBucket(level, c, hc->mask);
    hc->cells[i] = (dxHashCell){ { c[0], c[1], c[2] }, level, -1, hc->buckets[b], (int)b };
    hc->buckets[b] = i;
    hc->live++;
    return i;
}

void dxHashCellsLink(dxHashCells *hc, int e, int level, const int64_t c[3])
{
    int ci = dxHashCellsLookup(hc, level, c);
    if (ci < 0) ci = dxHashCellsAdd(hc, level, c);
    dxHashEntry *en = hc->entries;
    const int order = en[e].g->space_index;
    int *p = &hc->cells[ci].head;
    while (*p >= 0 && en[*p].g->space_index > order) p = &en[*p].next;
    en[e].next = *p;
    en[e].cell = ci;
    *p = e;
}

void dxHashCellsUnlink(dxHashCells *hc, int e)
{
    dxHashEntry *en = hc->entries;
    const int ci = en[e].cell;
    dxHashCell *cell = &hc->cells[ci];
    int *p = &cell->head;
    while (*p != e) p = &en[*p].next;
    *p = en[e].next;
    if (cell->head >= 0) return;
    int *q = &hc->buckets[cell->bucket];
    while (*q != ci) q = &hc->cells[*q].next;
    *q = cell->next;
    cell->next = hc->free_cell;
    hc->free_cell = ci;
    hc->live--;
}

void dxHashCellsRestart(dxHashCells *hc, int entries)
{
    int n = hc->mask ? hc->mask + 1 : 64;
    while (n < 2 * entries) n *= 2;
    if (n > hc->mask + 1) {
        hc->cells_used = 0;
        rebucket(hc, n);   // (no cell in use: all buckets empty)
    } else {
        // Empty only the buckets in use.
        for (int i = 0; i < hc->cells_used; i++)
            if (hc->cells[i].head >= 0) hc->buckets[hc->cells[i].bucket] = -1;
        hc->cells_used = 0;
    }
    hc->live = 0;
    hc->free_cell = -1;
    hc->cells = grow(hc->cells, &hc->cells_cap, entries, sizeof *hc->cells);
}

void dxHashCellsFree(dxHashCells *hc)
{
    dFree(hc->entries, (size_t)hc->entries_cap * sizeof *hc->entries);
    dFree(hc->cells, (size_t)hc->cells_cap * sizeof *hc->cells);
    if (hc->mask) dFree(hc->buckets, (size_t)(hc->mask + 1) * sizeof *hc->buckets);
    dxHashCellsInit(hc);
}
