// SPDX-License-Identifier: BSD-3-Clause
//
// space_sap_pairs.h -- the sweep-and-prune space's set of overlapping pairs:
// the pairs in a dense array (walked by dSpaceCollide) with an open-addressing
// hash table (linear probing) from the pair's key to its place in the array.
// Both grow geometrically and never shrink: a steady state allocates nothing.

#ifndef SPACE_SAP_PAIRS_H
#define SPACE_SAP_PAIRS_H

#include "geom_internal.h"

#include <stdint.h>

// A pair of geoms, by their proxies' numbers (a < b) and themselves.
typedef struct dxSapPair {
    dxGeom *ga, *gb;
    int a, b;
} dxSapPair;

typedef struct dxSapPairSet {
    dxSapPair *pair;              // the pairs, in no particular order
    int count, cap;
    uint64_t *key;                // the hash table: 0 for an empty slot ...
    int *at;                      // ... else the pair's index in pair[]
    int tcap;                     // table size, a power of two (0 before the first use)
    int unindexed;                // pairs were appended since the table was filled
} dxSapPairSet;

// Add the pair of proxies a != b (geoms ga, gb) unless it is there.
void dxSapPairAdd(dxSapPairSet *ps, int a, dxGeom *ga, int b, dxGeom *gb);
// Append the pair of proxies a != b, known not to be there, leaving the
// table to be filled at the next add or remove (a fresh sweep finds each pair
// once, and a sweep at every refresh never needs the table).
void dxSapPairAppend(dxSapPairSet *ps, int a, dxGeom *ga, int b, dxGeom *gb);
// Remove the pair of proxies a, b if it is there.
void dxSapPairRemove(dxSapPairSet *ps, int a, int b);
// Keep only the pairs for which keep(ctx, a, b) is 1 (rebuilding the table).
void dxSapPairFilter(dxSapPairSet *ps, int (*keep)(void *ctx, int a, int b), void *ctx);
// Room for n pairs without allocating.
void dxSapPairReserve(dxSapPairSet *ps, int n);
// Empty the set (keeping its memory).
void dxSapPairClear(dxSapPairSet *ps);
void dxSapPairFree(dxSapPairSet *ps);

#endif
