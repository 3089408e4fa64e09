// SPDX-License-Identifier: BSD-3-Clause
//
// space_pairs.h -- what the space tests share: geoms numbered through their
// user data, the pairs a space calls back with (recorded in order), compared
// as sets of unordered pairs, and what a space must report for two geoms.

#ifndef TESTS_SPACE_PAIRS_H
#define TESTS_SPACE_PAIRS_H

#include <ode/ode.h>

#include <stdint.h>

// A geom's number (its user data: 1, 2, ...).
static inline int idx(dGeomID g) { return (int)(intptr_t)dGeomGetData(g); }

typedef struct pairs {
    int n, cap;
    int (*p)[2];   // (number of o1, number of o2) in callback order
} pairs;

void pairs_add(pairs *l, int a, int b);
void pairs_free(pairs *l);
// A near callback recording the pair into the `pairs` passed as data.
void record(void *data, dGeomID a, dGeomID b);
// 1 if no unordered pair appears twice.
int pairs_unique(const pairs *l);
// 1 if the two lists hold the same unordered pairs.
int pairs_same(const pairs *x, const pairs *y);
// 1 if (a, b) was recorded in that order.
int pairs_has(const pairs *l, int a, int b);
// What a space must report for a and b, written out from the guide (10.5):
// both enabled, not on one body, bits matching, AABBs overlapping as closed
// boxes.
int expect_touch(dGeomID a, dGeomID b);

#endif
