// SPDX-License-Identifier: BSD-3-Clause
//
// test_arena.c -- the per-world scratch arena: alignment, marks, growth by
// chaining, and the promise that a steady workload allocates nothing after
// the first reset.

#include "test.h"
#include "arena.h"

#include <stdint.h>
#include <string.h>

static int test_allocations_are_aligned_and_distinct(void)
{
    dxArena a;
    dxArenaInit(&a);

    char *p = dxArenaAlloc(&a, 10);
    char *q = dxArenaAlloc(&a, 100);
    memset(p, 1, 10);
    memset(q, 2, 100);

    CHECK((uintptr_t)p % 64 == 0);
    CHECK((uintptr_t)q % 64 == 0);
    CHECK(q >= p + 10);
    CHECK(p[9] == 1);
    dxArenaFree(&a);
    return 0;
}

static int test_restore_returns_to_mark(void)
{
    dxArena a;
    dxArenaInit(&a);
    dxArenaAlloc(&a, 100);

    dxArenaMark m = dxArenaSave(&a);
    void *first = dxArenaAlloc(&a, 1000);
    dxArenaRestore(&a, m);
    void *again = dxArenaAlloc(&a, 1000);

    CHECK(first == again);
    dxArenaFree(&a);
    return 0;
}

static int test_growth_keeps_earlier_pointers_valid(void)
{
    dxArena a;
    dxArenaInit(&a);

    int *small = DX_ARENA_ARRAY(&a, int, 16);
    for (int i = 0; i < 16; i++) small[i] = i;
    double *big = DX_ARENA_ARRAY(&a, double, 1 << 20);   // 8 MB: forces a new block
    big[(1 << 20) - 1] = 3.5;

    for (int i = 0; i < 16; i++) CHECK(small[i] == i);
    CHECK(big[(1 << 20) - 1] == 3.5);
    dxArenaFree(&a);
    return 0;
}

static int test_steady_workload_allocates_nothing_after_first_reset(void)
{
    dxArena a;
    dxArenaInit(&a);
    for (int step = 0; step < 5; step++) {
        dxArenaReset(&a);
        if (step == 2) test_count_allocations();   // steps 0 and 1 size the arena
        for (int k = 0; k < 50; k++) dxArenaAlloc(&a, 40000);   // 2 MB in pieces
    }

    CHECK(test_allocations_counted() == 0);
    dxArenaFree(&a);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_allocations_are_aligned_and_distinct),
    TEST_CASE(test_restore_returns_to_mark),
    TEST_CASE(test_growth_keeps_earlier_pointers_valid),
    TEST_CASE(test_steady_workload_allocates_nothing_after_first_reset),
    TEST_END
};
