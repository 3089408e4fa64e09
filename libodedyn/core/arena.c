// SPDX-License-Identifier: BSD-3-Clause
//
// arena.c -- the per-world scratch arena (see arena.h).

#define _DEFAULT_SOURCE   // madvise's MADV_HUGEPAGE (huge_page.h)

#include "arena.h"
#include "huge_page.h"

#include <ode/memory.h>

#define ARENA_ALIGN 64

struct dxArenaBlock {
    dxArenaBlock *prev;   // older block in the chain, freed at reset
    size_t size;          // usable bytes after the header
    size_t used;
    size_t alloc_size;    // what the policy's alloc was asked for
    char *data;           // aligned start of the usable bytes
};

static void *default_alloc(void *context, size_t bytes)
{
    (void)context;
    return dAlloc(bytes);
}

static void default_release(void *context, void *p, size_t bytes)
{
    (void)context;
    dFree(p, bytes);
}

static const dxArenaPolicy default_policy = { default_alloc, default_release, NULL, 1.2f,
                                              64 * 1024, 0 };

static size_t round_up(size_t n, size_t a) { return (n + a - 1) / a * a; }

// The size of a block that holds `bytes` with the policy's reserve.
static size_t reserve_size(const dxArenaPolicy *p, size_t bytes)
{
    size_t size = (size_t)((double)bytes * (double)p->reserve_factor);
    if (size < bytes) size = bytes;
    if (size < p->reserve_minimum) size = p->reserve_minimum;
    return round_up(size ? size : 1, ARENA_ALIGN);
}

// A block of size usable bytes after prev in the chain; on huge pages if
// huge and the policy and the size allow (arena.h).
static dxArenaBlock *block_create(const dxArenaPolicy *p, size_t size, dxArenaBlock *prev,
                                  int huge)
{
    huge = huge && DX_HUGE_PAGES && p->huge_pages && size >= DX_ARENA_HUGE_MIN;
    if (huge) size = round_up(size, DX_HUGE_PAGE);
    const size_t align = huge ? DX_HUGE_PAGE : ARENA_ALIGN;
    size_t alloc_size = sizeof(dxArenaBlock) + align + size;
    dxArenaBlock *b = p->alloc(p->context, alloc_size);
    b->prev = prev;
    b->size = size;
    b->used = 0;
    b->alloc_size = alloc_size;
    b->data = (char *)round_up((size_t)(b + 1), align);
    if (huge) dxAdviseHugePages(b->data, size);
    return b;
}

static void chain_free(const dxArenaPolicy *p, dxArenaBlock *b)
{
    while (b) {
        dxArenaBlock *prev = b->prev;
        p->release(p->context, b, b->alloc_size);
        b = prev;
    }
}

void dxArenaInit(dxArena *arena) { dxArenaInitPolicy(arena, NULL); }

void dxArenaInitPolicy(dxArena *arena, const dxArenaPolicy *policy)
{
    arena->block = NULL;
    arena->peak = 0;
    arena->in_use = 0;
    arena->policy = policy ? policy : &default_policy;
}

void dxArenaFree(dxArena *arena)
{
    chain_free(arena->policy, arena->block);
    dxArenaInitPolicy(arena, arena->policy);
}

void dxArenaReset(dxArena *arena)
{
    dxArenaBlock *b = arena->block;
    if (b ? b->prev || b->size < arena->peak : arena->peak > 0) {   // make one block that fits
        chain_free(arena->policy, b);
        arena->block =
            block_create(arena->policy, reserve_size(arena->policy, arena->peak), NULL, 1);
    } else if (b) {
        b->used = 0;
    }
    arena->in_use = 0;
}

void dxArenaReserve(dxArena *arena, size_t bytes)
{
    if (bytes > arena->peak) arena->peak = bytes;
}

void *dxArenaAlloc(dxArena *arena, size_t bytes)
{
    bytes = round_up(bytes ? bytes : 1, ARENA_ALIGN);
    dxArenaBlock *b = arena->block;
    if (!b || b->size - b->used < bytes) {
        size_t size = reserve_size(arena->policy, b ? 0 : arena->peak);
        if (size < bytes) size = bytes;
        if (b && size < b->size * 2) size = b->size * 2;
        b = block_create(arena->policy, size, b, 0);
        arena->block = b;
    }
    void *p = b->data + b->used;
    b->used += bytes;
    arena->in_use += bytes;
    if (arena->in_use > arena->peak) arena->peak = arena->in_use;
    return p;
}

dxArenaMark dxArenaSave(const dxArena *arena)
{
    dxArenaMark m = { arena->block, arena->block ? arena->block->used : 0, arena->in_use };
    return m;
}

void dxArenaRestore(dxArena *arena, dxArenaMark mark)
{
    // Blocks chained after the mark stay allocated (freed or merged at reset);
    // only the marked block's fill level rolls back.
    for (dxArenaBlock *b = arena->block; b && b != mark.block; b = b->prev) b->used = 0;
    if (mark.block) mark.block->used = mark.used;
    arena->in_use = mark.in_use;
}
