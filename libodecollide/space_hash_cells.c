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

static int same_cell(const dxHashCell *cell, int level, const int64_t c[3])
{
    return cell->level == level && cell->c[0] == c[0] && cell->c[1] == c[1] && cell->c[2] == c[2];
}

// Spread the cells in use over `n` buckets (a power of two).
static void rebucket(dxHashCells *hc, int n)
{
    if (n > hc->mask + 1) {
        const size_t old = hc->mask ? (size_t)(hc->mask + 1) * sizeof *hc->buckets : 0;
        hc->buckets = dRealloc(hc->buckets, old, (size_t)n * sizeof *hc->buckets);
        hc->mask = n - 1;
    }
    for (int b = 0; b <= hc->mask; b++) hc->buckets[b] = -1;
    for (int i = 0; i < hc->cells_used; i++) {
        dxHashCell *cell = &hc->cells[i];
        if (cell->head < 0) continue;
        unsigned b = cell_bucket(cell->level, cell->c, hc->mask);
        cell->next = hc->buckets[b];
        hc->buckets[b] = i;
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

int dxHashCellsFind(const dxHashCells *hc, int level, const int64_t c[3])
{
    if (!hc->mask) return -1;
    for (int i = hc->buckets[cell_bucket(level, c, hc->mask)]; i >= 0; i = hc->cells[i].next)
        if (same_cell(&hc->cells[i], level, c)) return hc->cells[i].head;
    return -1;
}

// The record of cell (level, c), made (empty) if there is none.
static int cell_record(dxHashCells *hc, int level, const int64_t c[3])
{
    if (!hc->mask) rebucket(hc, 64);
    unsigned b = cell_bucket(level, c, hc->mask);
    for (int i = hc->buckets[b]; i >= 0; i = hc->cells[i].next)
        if (same_cell(&hc->cells[i], level, c)) return i;
    int i = hc->free_cell;
    if (i >= 0) {
        hc->free_cell = hc->cells[i].next;
    } else {
        hc->cells = grow(hc->cells, &hc->cells_cap, hc->cells_used + 1, sizeof *hc->cells);
        i = hc->cells_used++;
    }
    hc->cells[i] = (dxHashCell){ { c[0], c[1], c[2] }, level, -1, hc->buckets[b] };
    hc->buckets[b] = i;
    hc->live++;
    return i;
}

void dxHashCellsLink(dxHashCells *hc, int e, int level, const int64_t c[3])
{
    int ci = cell_record(hc, level, c);
    dxHashEntry *en = hc->entries;
    const int order = en[e].g->space_index;
    int *p = &hc->cells[ci].head;
    while (*p >= 0 && en[*p].g->space_index > order) p = &en[*p].next;
    en[e].next = *p;
    en[e].cell = ci;
    *p = e;
    if (2 * hc->live > hc->mask + 1) rebucket(hc, 2 * (hc->mask + 1));
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
    int *q = &hc->buckets[cell_bucket(cell->level, cell->c, hc->mask)];
    while (*q != ci) q = &hc->cells[*q].next;
    *q = cell->next;
    cell->next = hc->free_cell;
    hc->free_cell = ci;
    hc->live--;
}

void dxHashCellsFree(dxHashCells *hc)
{
    dFree(hc->entries, (size_t)hc->entries_cap * sizeof *hc->entries);
    dFree(hc->cells, (size_t)hc->cells_cap * sizeof *hc->cells);
    if (hc->mask) dFree(hc->buckets, (size_t)(hc->mask + 1) * sizeof *hc->buckets);
    dxHashCellsInit(hc);
}
