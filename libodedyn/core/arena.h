// SPDX-License-Identifier: BSD-3-Clause
//
// arena.h -- per-world scratch memory for stepping. Allocation is a pointer
// bump; everything is released at once. When a step needs more than the
// arena holds, extra blocks are chained (earlier pointers stay valid) and at
// the next reset the arena is rebuilt as one block of the peak size, so a
// steady simulation allocates nothing per step.

#ifndef DX_ARENA_H
#define DX_ARENA_H

#include <stddef.h>

typedef struct dxArenaBlock dxArenaBlock;

typedef struct dxArena {
    dxArenaBlock *block;   // current block (the head of the chain)
    size_t peak;           // most bytes in use at once since the last reset
    size_t in_use;         // bytes handed out since the last reset, all blocks
} dxArena;

// A position to roll back to with dxArenaRestore (nested scratch use).
typedef struct dxArenaMark {
    dxArenaBlock *block;
    size_t used;
    size_t in_use;
} dxArenaMark;

void dxArenaInit(dxArena *arena);
void dxArenaFree(dxArena *arena);
// Release everything; merge a chain of blocks into one of the peak size.
void dxArenaReset(dxArena *arena);
// bytes of scratch, aligned to 64 bytes; never returns NULL (dAlloc reports
// exhaustion through dError).
void *dxArenaAlloc(dxArena *arena, size_t bytes);
dxArenaMark dxArenaSave(const dxArena *arena);
void dxArenaRestore(dxArena *arena, dxArenaMark mark);

// Typed helpers.
#define DX_ARENA_ARRAY(arena, type, count) \
    ((type *)dxArenaAlloc((arena), sizeof(type) * (size_t)(count)))

#endif
