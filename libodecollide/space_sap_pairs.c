// SPDX-License-Identifier: BSD-3-Clause
//
// space_sap_pairs.c -- the set of overlapping pairs of the sweep-and-prune
// space (space_sap_pairs.h). The table is kept at most half full; removal
// shifts the following entries of the probe run back (no tombstones), so
// lookups stay short however many pairs come and go.

#include "space_sap_pairs.h"

#include <ode/memory.h>
#include <string.h>

// The key of an unordered pair: never 0 (0 marks an empty slot).
static uint64_t pair_key(int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    return (uint64_t)(uint32_t)(a + 1) << 32 | (uint32_t)b;
}

// Fibonacci hashing: the top bits of key times 2^64 / phi.
static int home_slot(const dxSapPairSet *ps, uint64_t key)
{
    return (int)(((key * 0x9E3779B97F4A7C15u) >> 32) & (uint64_t)(ps->tcap - 1));
}

// The table slot holding key, or the empty slot where it would go.
static int find_slot(const dxSapPairSet *ps, uint64_t key)
{
    int t = home_slot(ps, key);
    while (ps->key[t] != 0 && ps->key[t] != key) t = (t + 1) & (ps->tcap - 1);
    return t;
}

static void table_fill(dxSapPairSet *ps)
{
    memset(ps->key, 0, (size_t)ps->tcap * sizeof *ps->key);
    for (int i = 0; i < ps->count; i++) {
        uint64_t k = pair_key(ps->pair[i].a, ps->pair[i].b);
        int t = find_slot(ps, k);
        ps->key[t] = k;
        ps->at[t] = i;
    }
}

void dxSapPairReserve(dxSapPairSet *ps, int n)
{
    if (n > ps->cap) {
        int cap = ps->cap ? ps->cap : 256;
        while (cap < n) cap *= 2;
        ps->pair = dRealloc(ps->pair, (size_t)ps->cap * sizeof *ps->pair,
                            (size_t)cap * sizeof *ps->pair);
        ps->cap = cap;
    }
    if (2 * n > ps->tcap) {
        int tcap = ps->tcap ? ps->tcap : 512;
        while (tcap < 2 * n) tcap *= 2;
        dFree(ps->key, (size_t)ps->tcap * sizeof *ps->key);
        dFree(ps->at, (size_t)ps->tcap * sizeof *ps->at);
        ps->key = dAlloc((size_t)tcap * sizeof *ps->key);
        ps->at = dAlloc((size_t)tcap * sizeof *ps->at);
        ps->tcap = tcap;
        table_fill(ps);
        ps->unindexed = 0;
    }
}

static void index_pairs(dxSapPairSet *ps)
{
    if (!ps->unindexed) return;
    dxSapPairReserve(ps, ps->count);
    table_fill(ps);
    ps->unindexed = 0;
}

void dxSapPairAppend(dxSapPairSet *ps, int a, dxGeom *ga, int b, dxGeom *gb)
{
    if (ps->count + 1 > ps->cap) dxSapPairReserve(ps, 2 * (ps->count + 1));
    ps->pair[ps->count++] = a < b ? (dxSapPair){ ga, gb, a, b } : (dxSapPair){ gb, ga, b, a };
    ps->unindexed = 1;
}

void dxSapPairAdd(dxSapPairSet *ps, int a, dxGeom *ga, int b, dxGeom *gb)
{
    index_pairs(ps);
    if (ps->count + 1 > ps->cap || 2 * (ps->count + 1) > ps->tcap)
        dxSapPairReserve(ps, 2 * (ps->count + 1));
    uint64_t k = pair_key(a, b);
    int t = find_slot(ps, k);
    if (ps->key[t] != 0) return;
    ps->key[t] = k;
    ps->at[t] = ps->count;
    ps->pair[ps->count++] = a < b ? (dxSapPair){ ga, gb, a, b } : (dxSapPair){ gb, ga, b, a };
}

void dxSapPairRemove(dxSapPairSet *ps, int a, int b)
{
    if (ps->count == 0) return;
    index_pairs(ps);
    uint64_t k = pair_key(a, b);
    int t = find_slot(ps, k);
    if (ps->key[t] == 0) return;
    const int i = ps->at[t];

    // Empty slot t, then move back every later entry of the run that may sit
    // at t: one whose home is not cyclically in (t, j].
    const int mask = ps->tcap - 1;
    for (int j = (t + 1) & mask; ps->key[j] != 0; j = (j + 1) & mask) {
        int h = home_slot(ps, ps->key[j]);
        if (((j - h) & mask) >= ((j - t) & mask)) {
            ps->key[t] = ps->key[j];
            ps->at[t] = ps->at[j];
            t = j;
        }
    }
    ps->key[t] = 0;

    // The last pair fills the hole in the array.
    const int last = --ps->count;
    if (i != last) {
        ps->pair[i] = ps->pair[last];
        ps->at[find_slot(ps, pair_key(ps->pair[i].a, ps->pair[i].b))] = i;
    }
}

void dxSapPairFilter(dxSapPairSet *ps, int (*keep)(void *ctx, int a, int b), void *ctx)
{
    int n = 0;
    for (int i = 0; i < ps->count; i++)
        if (keep(ctx, ps->pair[i].a, ps->pair[i].b)) ps->pair[n++] = ps->pair[i];
    ps->count = n;
    if (ps->tcap && !ps->unindexed) table_fill(ps);
}

void dxSapPairClear(dxSapPairSet *ps)
{
    ps->count = 0;
    ps->unindexed = 1;   // filled (empty) when next needed
}

void dxSapPairFree(dxSapPairSet *ps)
{
    dFree(ps->pair, (size_t)ps->cap * sizeof *ps->pair);
    dFree(ps->key, (size_t)ps->tcap * sizeof *ps->key);
    dFree(ps->at, (size_t)ps->tcap * sizeof *ps->at);
    memset(ps, 0, sizeof *ps);
}
