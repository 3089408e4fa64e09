// SPDX-License-Identifier: BSD-3-Clause
//
// space_hash_cells.c -- the persistent cells of a hash space
// (space_hash_cells.h): an open-addressed table of cells, at least twice as
// many slots as cells in use, probed linearly. A removal shifts the later
// slots of its run back (no tombstones), and a slot that moves takes its
// entries' `cell` with it, so entries always name their cell's slot. A shift
// moves a cell only into a slot that was in use, so the list of the slots
// made live since the table was emptied (`used`) covers every slot in use,
// and emptying the table again needs to clear only those.

#include "space_hash_cells.h"

#include <ode/memory.h>
#include <stdint.h>
#include <string.h>

#define LINE 64

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

// The allocation size of a table of mask + 1 slots (one line more, to align).
static size_t table_bytes(int mask)
{
    return (size_t)(mask + 1) * sizeof(dxHashCell) + LINE;
}

// A table of n slots (a power of two), all empty, in place of the current
// one (freed, its cells forgotten).
static void new_table(dxHashCells *hc, int n)
{
    if (hc->mask) dFree(hc->cells_mem, table_bytes(hc->mask));
    hc->mask = n - 1;
    hc->cells_mem = dAlloc(table_bytes(hc->mask));
    hc->cells = (dxHashCell *)(((uintptr_t)hc->cells_mem + LINE - 1) & ~(uintptr_t)(LINE - 1));
    memset(hc->cells, 0xff, (size_t)n * sizeof *hc->cells);   // every head -1
    hc->live = 0;
    hc->used = grow(hc->used, &hc->used_cap, n, sizeof *hc->used);
    hc->n_used = 0;
    hc->used_all = 1;
}

// Note that slot i has become live (or, when the list is full, that it no
// longer covers every slot in use).
static void note_used(dxHashCells *hc, int i)
{
    if (hc->n_used < hc->used_cap) hc->used[hc->n_used++] = i;
    else hc->used_all = 0;
}

// Point the entries of the cell in slot i at it (it has just moved there).
static void follow(dxHashCells *hc, int i)
{
    for (int e = hc->cells[i].head; e >= 0; e = hc->entries[e].next) hc->entries[e].cell = i;
}

// An empty slot for cell (level, c), which has none; the table has room.
static int empty_slot(const dxHashCells *hc, int level, const int64_t c[3])
{
    unsigned i = dxHashCellBucket(level, c, hc->mask);
    while (hc->cells[i].head >= 0) i = (i + 1) & (unsigned)hc->mask;
    return (int)i;
}

// The same cells in a table of n slots (a power of two).
static void rehash(dxHashCells *hc, int n)
{
    const dxHashCell *old = hc->cells;
    void *old_mem = hc->cells_mem;
    const int old_mask = hc->mask, live = hc->live;
    hc->mask = 0;   // (new_table must not free the old table yet)
    new_table(hc, n);
    for (int k = 0; k <= old_mask; k++) {
        if (old[k].head < 0) continue;
        const int i = empty_slot(hc, old[k].level, old[k].c);
        hc->cells[i] = old[k];
        follow(hc, i);
        note_used(hc, i);
    }
    hc->live = live;
    if (old_mask) dFree(old_mem, table_bytes(old_mask));
}

// The table of every space before its first cell: one empty slot, never
// written (a lookup needs no test for a missing table).
static dxHashCell no_cells = { { 0, 0, 0 }, 0, -1 };

void dxHashCellsInit(dxHashCells *hc)
{
    memset(hc, 0, sizeof *hc);
    hc->cells = &no_cells;
}

void dxHashCellsReserve(dxHashCells *hc, int slots)
{
    hc->entries = grow(hc->entries, &hc->entries_cap, slots * DX_HASH_CELLS_PER_GEOM,
                       sizeof *hc->entries);
}

// Cell (level, c) in empty slot i, the first empty slot of its probe (the
// slot a lookup of the cell ended at), growing the table if it would be more
// than half full (the cell then gets the slot its probe reaches in the new
// table); its slot. Not inlined: the link's probe would then load the key
// as the record is made, two of its coordinates at once from the caller's
// stores still on their way (a store-forwarding stall on every link).
static __attribute__((noinline)) int add_at(dxHashCells *hc, unsigned i, int level,
                                            const int64_t c[3])
{
    if (2 * (hc->live + 1) > hc->mask + 1) {
        rehash(hc, hc->mask ? 2 * (hc->mask + 1) : 64);
        i = (unsigned)empty_slot(hc, level, c);
    }
    hc->cells[i] = (dxHashCell){ { c[0], c[1], c[2] }, level, -1 };
    hc->live++;
    note_used(hc, (int)i);
    return (int)i;
}

void dxHashCellsLink(dxHashCells *hc, int e, int level, const int64_t c[3])
{
    const unsigned mask = (unsigned)hc->mask;
    unsigned i = dxHashCellBucket(level, c, hc->mask);
    while (hc->cells[i].head >= 0 && !dxHashCellIs(&hc->cells[i], level, c)) i = (i + 1) & mask;
    const int ci = hc->cells[i].head >= 0 ? (int)i : add_at(hc, i, level, c);
    dxHashEntry *en = hc->entries;
    const int order = en[e].g->space_index;
    int *p = &hc->cells[ci].head;
    while (*p >= 0 && en[*p].g->space_index > order) p = &en[*p].next;
    en[e].next = *p;
    en[e].cell = ci;
    *p = e;
}

// Empty slot `hole`: each later slot of its run whose probe from its hash
// passes the hole moves back into it, and leaves its own slot as the hole,
// so that every lookup still reaches its cell before an empty slot.
static void remove_slot(dxHashCells *hc, unsigned hole)
{
    const unsigned mask = (unsigned)hc->mask;
    for (unsigned j = (hole + 1) & mask; hc->cells[j].head >= 0; j = (j + 1) & mask) {
        const unsigned home = dxHashCellBucket(hc->cells[j].level, hc->cells[j].c, hc->mask);
        if (((j - home) & mask) < ((j - hole) & mask)) continue;   // its probe starts past the hole
        hc->cells[hole] = hc->cells[j];
        follow(hc, (int)hole);
        hole = j;
    }
    hc->cells[hole].head = -1;
    hc->live--;
}

void dxHashCellsUnlink(dxHashCells *hc, int e)
{
    dxHashEntry *en = hc->entries;
    const int ci = en[e].cell;
    int *p = &hc->cells[ci].head;
    while (*p != e) p = &en[*p].next;
    *p = en[e].next;
    if (hc->cells[ci].head < 0) remove_slot(hc, (unsigned)ci);
}

void dxHashCellsRestart(dxHashCells *hc, int entries)
{
    int n = hc->mask ? hc->mask + 1 : 64;
    while (n < 2 * entries) n *= 2;
    if (n > hc->mask + 1) {
        new_table(hc, n);
    } else if (hc->used_all) {
        // Empty only the slots that may be in use.
        for (int k = 0; k < hc->n_used; k++) hc->cells[hc->used[k]].head = -1;
    } else {
        memset(hc->cells, 0xff, (size_t)n * sizeof *hc->cells);
    }
    hc->live = 0;
    hc->n_used = 0;
    hc->used_all = 1;
}

void dxHashCellsFree(dxHashCells *hc)
{
    dFree(hc->entries, (size_t)hc->entries_cap * sizeof *hc->entries);
    if (hc->mask) dFree(hc->cells_mem, table_bytes(hc->mask));
    dFree(hc->used, (size_t)hc->used_cap * sizeof *hc->used);
    dxHashCellsInit(hc);
}
