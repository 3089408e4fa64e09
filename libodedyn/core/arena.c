// SPDX-License-Identifier: BSD-3-Clause
//
// arena.c -- the per-world scratch arena (see arena.h).

#include "arena.h"

#include <ode/memory.h>

#define ARENA_ALIGN 64
#define ARENA_MIN_BLOCK (64 * 1024)

struct dxArenaBlock {
    dxArenaBlock *prev;   // older block in the chain, freed at reset
    size_t size;          // usable bytes after the header
    size_t used;
    size_t alloc_size;    // what dAlloc was asked for, for dFree
    char *data;           // aligned start of the usable bytes
};

static size_t round_up(size_t n, size_t a) { return (n + a - 1) / a * a; }

static dxArenaBlock *block_create(size_t size, dxArenaBlock *prev)
{
    size_t alloc_size = sizeof(dxArenaBlock) + ARENA_ALIGN + size;
    dxArenaBlock *b = dAlloc(alloc_size);
    b->prev = prev;
    b->size = size;
    b->used = 0;
    b->alloc_size = alloc_size;
    b->data = (char *)round_up((size_t)(b + 1), ARENA_ALIGN);
    return b;
}

static void chain_free(dxArenaBlock *b)
{
    while (b) {
        dxArenaBlock *prev = b->prev;
        dFree(b, b->alloc_size);
        b = prev;
    }
}

void dxArenaInit(dxArena *arena)
{
    arena->block = NULL;
    arena->peak = 0;
    arena->in_use = 0;
}

void dxArenaFree(dxArena *arena)
{
    chain_free(arena->block);
    dxArenaInit(arena);
}

void dxArenaReset(dxArena *arena)
{
    dxArenaBlock *b = arena->block;
    if (b && b->prev) {   // the last steps needed a chain: make one block that fits
        size_t size = round_up(arena->peak + arena->peak / 4, ARENA_ALIGN);
        chain_free(b);
        arena->block = block_create(size, NULL);
    } else if (b) {
        b->used = 0;
    }
    arena->in_use = 0;
}

void *dxArenaAlloc(dxArena *arena, size_t bytes)
{
    bytes = round_up(bytes ? bytes : 1, ARENA_ALIGN);
    dxArenaBlock *b = arena->block;
    if (!b || b->size - b->used < bytes) {
        size_t size = bytes > ARENA_MIN_BLOCK ? bytes : ARENA_MIN_BLOCK;
        if (b && size < b->size * 2) size = b->size * 2;
        b = block_create(size, b);
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
