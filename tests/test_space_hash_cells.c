// SPDX-License-Identifier: BSD-3-Clause
//
// test_space_hash_cells.c -- the hash space's table of cells
// (space_hash_cells.c, open addressing): through long random sequences of
// links, unlinks (whose removals shift later slots back), growth and
// restarts (emptied through the list of slots made live, then filled by
// fresh pushes), every cell lists exactly the entries a plain model puts in
// it, in decreasing space order, each entry names its cell's slot, and a
// restart leaves no cell behind. White-box: needs space_hash_cells.h.

#include "test.h"

#include "space_hash_cells.h"

#include <stdlib.h>
#include <string.h>
#include "xorshift.h"

enum { N_GEOMS = 300, N_KEYS = 2 * 64 };

static dxGeom geoms[N_GEOMS];
static int key_of[N_GEOMS];   // the model: the cell of geom i's entry, -1 if none

// Cell (level, c) of key k: levels 0 and 1, coordinates -2 .. 1.
static void key_cell(int k, int *level, int64_t c[3])
{
    *level = k / 64;
    c[0] = k % 4 - 2;
    c[1] = k / 4 % 4 - 2;
    c[2] = k / 16 % 4 - 2;
}

// Geom i's entry (the first of its slot).
static int entry(int i) { return i * DX_HASH_CELLS_PER_GEOM; }

// The table holds what the model says: each key's list, its slot in every
// entry, and no other cell.
static int check_table(const dxHashCells *hc)
{
    int keys_used = 0;
    for (int k = 0; k < N_KEYS; k++) {
        int level;
        int64_t c[3];
        key_cell(k, &level, c);
        const int slot = dxHashCellsLookup(hc, level, c);
        int e = dxHashCellsFind(hc, level, c);
        CHECK((slot < 0) == (e < 0));
        keys_used += slot >= 0;
        for (int i = N_GEOMS - 1; i >= 0; i--) {   // latest in space order first
            if (key_of[i] != k) continue;
            CHECK(e == entry(i));
            CHECK(hc->entries[e].cell == slot);
            e = hc->entries[e].next;
        }
        CHECK(e == -1);
    }
    CHECK(hc->live == keys_used);
    return 0;
}

// Link a random geom's entry with probability p_link if it is out, unlink
// it with probability 1 - p_link if it is in.
static void random_edit(dxHashCells *hc, double p_link)
{
    const int i = (int)rnd(0, N_GEOMS);
    if ((rnd(0, 1) < p_link) == (key_of[i] >= 0)) return;
    if (key_of[i] >= 0) {
        dxHashCellsUnlink(hc, entry(i));
        key_of[i] = -1;
        return;
    }
    const int k = (int)rnd(0, N_KEYS);
    int level;
    int64_t c[3];
    key_cell(k, &level, c);
    dxHashCellsLink(hc, entry(i), level, c);
    key_of[i] = k;
}

// Empty the table and push every linked entry again, in space order.
static int restart(dxHashCells *hc)
{
    int n = 0;
    for (int i = 0; i < N_GEOMS; i++) n += key_of[i] >= 0;
    dxHashCellsRestart(hc, n);
    for (int i = 0; i < N_GEOMS; i++) {
        if (key_of[i] < 0) continue;
        int level;
        int64_t c[3];
        key_cell(key_of[i], &level, c);
        CHECK(dxHashCellsLookup(hc, level, c) == -1);
    }
    for (int i = 0; i < N_GEOMS; i++) {
        if (key_of[i] < 0) continue;
        int level;
        int64_t c[3];
        key_cell(key_of[i], &level, c);
        dxHashCellsPushFresh(hc, entry(i), level, c);
    }
    return 0;
}

static int test_random_links_unlinks_and_restarts_match_the_model(void)
{
    rng_state = 0x9E3779B97F4A7C15u;
    dxHashCells hc;
    dxHashCellsInit(&hc);
    dxHashCellsReserve(&hc, N_GEOMS);
    for (int i = 0; i < N_GEOMS; i++) {
        memset(&geoms[i], 0, sizeof geoms[i]);
        geoms[i].space_index = i;
        hc.entries[entry(i)].g = &geoms[i];
        hc.entries[entry(i)].lowest = 0;
        key_of[i] = -1;
    }
    CHECK(check_table(&hc) == 0);
    for (int round = 0; round < 60; round++) {
        // Rounds that fill most cells and rounds that empty most, so that
        // cells come and go and the runs of slots grow and shrink.
        const double p_link = round % 2 ? 0.2 : 0.9;
        for (int m = 0; m < 400; m++) {
            random_edit(&hc, p_link);
            if (m % 16 == 0) CHECK(check_table(&hc) == 0);
        }
        CHECK(check_table(&hc) == 0);
        if (round % 3 == 2) {
            CHECK(restart(&hc) == 0);
            CHECK(check_table(&hc) == 0);
        }
    }
    dxHashCellsFree(&hc);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_random_links_unlinks_and_restarts_match_the_model),
    TEST_END,
};
