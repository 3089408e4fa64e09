// SPDX-License-Identifier: BSD-3-Clause
//
// space_pairs.c -- recorded space pairs (space_pairs.h).

#include "space_pairs.h"

#include <stdlib.h>
#include <string.h>

void pairs_add(pairs *l, int a, int b)
{
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 256;
        l->p = realloc(l->p, (size_t)l->cap * sizeof *l->p);
    }
    l->p[l->n][0] = a;
    l->p[l->n][1] = b;
    l->n++;
}

void pairs_free(pairs *l)
{
    free(l->p);
    *l = (pairs){ 0, 0, NULL };
}

void record(void *data, dGeomID a, dGeomID b) { pairs_add(data, idx(a), idx(b)); }

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

// The pairs as sorted unordered keys (smaller number high); caller frees.
static uint64_t *pair_keys(const pairs *l)
{
    uint64_t *k = malloc((size_t)(l->n + 1) * sizeof *k);
    for (int i = 0; i < l->n; i++) {
        uint64_t a = (uint64_t)l->p[i][0], b = (uint64_t)l->p[i][1];
        k[i] = a < b ? a << 32 | b : b << 32 | a;
    }
    qsort(k, (size_t)l->n, sizeof *k, cmp_u64);
    return k;
}

int pairs_unique(const pairs *l)
{
    uint64_t *k = pair_keys(l);
    int ok = 1;
    for (int i = 1; i < l->n; i++) ok &= k[i] != k[i - 1];
    free(k);
    return ok;
}

int pairs_same(const pairs *x, const pairs *y)
{
    if (x->n != y->n) return 0;
    uint64_t *a = pair_keys(x), *b = pair_keys(y);
    int same = memcmp(a, b, (size_t)x->n * sizeof *a) == 0;
    free(a);
    free(b);
    return same;
}

int pairs_has(const pairs *l, int a, int b)
{
    for (int i = 0; i < l->n; i++)
        if (l->p[i][0] == a && l->p[i][1] == b) return 1;
    return 0;
}

int expect_touch(dGeomID a, dGeomID b)
{
    if (!dGeomIsEnabled(a) || !dGeomIsEnabled(b)) return 0;
    if (dGeomGetBody(a) && dGeomGetBody(a) == dGeomGetBody(b)) return 0;
    if (!(dGeomGetCategoryBits(a) & dGeomGetCollideBits(b)) &&
        !(dGeomGetCategoryBits(b) & dGeomGetCollideBits(a)))
        return 0;
    dReal p[6], q[6];
    dGeomGetAABB(a, p);
    dGeomGetAABB(b, q);
    for (int k = 0; k < 6; k += 2)
        if (!(p[k] <= q[k + 1] && q[k] <= p[k + 1])) return 0;
    return 1;
}
