// SPDX-License-Identifier: BSD-3-Clause
//
// test_arena.c -- the per-world scratch arena: alignment, marks, growth by
// chaining, the promise that a steady workload allocates nothing after
// the first reset, and the rebuilt block on huge pages.

#include "test.h"
#include "arena.h"

#include <stdint.h>
#include <stdlib.h>
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

// A policy's record of its blocks: how many are out, their bytes, and the
// largest request.
typedef struct block_record {
    long out, bytes;
    size_t largest;
} block_record;

static void *recording_alloc(void *context, size_t bytes)
{
    block_record *r = context;
    r->out++;
    r->bytes += (long)bytes;
    if (bytes > r->largest) r->largest = bytes;
    return malloc(bytes);
}

static void recording_release(void *context, void *p, size_t bytes)
{
    block_record *r = context;
    r->out--;
    r->bytes -= (long)bytes;
    free(p);
}

// An empty arena a whose blocks r records, through policy (filled here; it
// must outlive a), with huge pages or not.
static void recording_arena(dxArena *a, dxArenaPolicy *policy, block_record *r, int huge)
{
    *r = (block_record){ 0, 0, 0 };
    *policy = (dxArenaPolicy){ recording_alloc, recording_release, r, 1.2f, 64 * 1024, huge };
    dxArenaInitPolicy(a, policy);
}

// A step of 1.5 MB in pieces, then the reset that rebuilds one block.
static char *grow_and_rebuild(dxArena *a)
{
    for (int k = 0; k < 30; k++) memset(dxArenaAlloc(a, 50000), k, 50000);
    dxArenaReset(a);
    return dxArenaAlloc(a, 1);
}

static int test_rebuilt_block_starts_at_a_huge_page(void)
{
    block_record r;
    dxArenaPolicy policy;
    dxArena a;
    recording_arena(&a, &policy, &r, 1);
    char *p = grow_and_rebuild(&a);
#if defined(__linux__)
    CHECK((uintptr_t)p % ((uintptr_t)2 << 20) == 0);
    // The rebuilt block: 1.8 MB rounded up to a huge page, and one more
    // for the alignment (the chained ones stop at 1 MB).
    CHECK(r.largest >= ((size_t)4 << 20));
#endif
    CHECK(r.out == 1);
    // Every byte of the peak (and the reserve) is there, from the first on.
    const size_t peak = 30 * 50048;
    memset(p, 0x5a, peak * 6 / 5);
    dxArenaReset(&a);
    CHECK(dxArenaAlloc(&a, 1) == p);   // a steady step keeps the block
    dxArenaFree(&a);
    CHECK(r.out == 0 && r.bytes == 0);
    return 0;
}

static int test_without_huge_pages_blocks_are_as_asked(void)
{
    block_record r;
    dxArenaPolicy policy;
    dxArena a;
    recording_arena(&a, &policy, &r, 0);
    grow_and_rebuild(&a);
    // The chained blocks double up to 1 MB; the rebuilt one is 1.2 times
    // the 1.5 MB peak, without a huge page's room more.
    CHECK(r.largest < ((size_t)5 << 19));
    CHECK(r.out == 1);
    dxArenaFree(&a);
    CHECK(r.out == 0 && r.bytes == 0);
    return 0;
}

static int test_small_rebuilt_block_stays_off_huge_pages(void)
{
    block_record r;
    dxArenaPolicy policy;
    dxArena a;
    recording_arena(&a, &policy, &r, 1);
    for (int step = 0; step < 2; step++) {
        for (int k = 0; k < 10; k++) dxArenaAlloc(&a, 50000);   // 0.5 MB
        dxArenaReset(&a);
    }
    CHECK(r.largest < DX_ARENA_HUGE_MIN);
    dxArenaFree(&a);
    CHECK(r.out == 0 && r.bytes == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_allocations_are_aligned_and_distinct),
    TEST_CASE(test_restore_returns_to_mark),
    TEST_CASE(test_growth_keeps_earlier_pointers_valid),
    TEST_CASE(test_steady_workload_allocates_nothing_after_first_reset),
    TEST_CASE(test_rebuilt_block_starts_at_a_huge_page),
    TEST_CASE(test_without_huge_pages_blocks_are_as_asked),
    TEST_CASE(test_small_rebuilt_block_stays_off_huge_pages),
    TEST_END
};
