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

// Where an arena's blocks come from and how big they are made: blocks from
// alloc(context, bytes) (never NULL) and back to release(context, p, bytes);
// a rebuilt block has reserve_factor times the peak, and no block has fewer
// than reserve_minimum bytes. NULL: dAlloc/dFree, 1.2 and 64 KiB.
typedef struct dxArenaPolicy {
    void *(*alloc)(void *context, size_t bytes);
    void (*release)(void *context, void *p, size_t bytes);
    void *context;
    float reserve_factor;
    size_t reserve_minimum;
} dxArenaPolicy;

typedef struct dxArena {
    dxArenaBlock *block;   // current block (the head of the chain)
    size_t peak;           // most bytes in use at once (or reserved) since the last free
    size_t in_use;         // bytes handed out since the last reset, all blocks
    const dxArenaPolicy *policy;
} dxArena;

// A position to roll back to with dxArenaRestore (nested scratch use).
typedef struct dxArenaMark {
    dxArenaBlock *block;
    size_t used;
    size_t in_use;
} dxArenaMark;

// An empty arena with the default policy, or with `policy` (which must
// outlive it; NULL: the defaults).
void dxArenaInit(dxArena *arena);
void dxArenaInitPolicy(dxArena *arena, const dxArenaPolicy *policy);
// Give every block back (the arena stays usable, with its policy).
void dxArenaFree(dxArena *arena);
// Release everything; a chain of blocks, or a block smaller than the peak,
// is replaced by one block of the peak size times the reserve factor.
void dxArenaReset(dxArena *arena);
// Make the next reset provide at least `bytes` in one block.
void dxArenaReserve(dxArena *arena, size_t bytes);
// bytes of scratch, aligned to 64 bytes; never returns NULL (dAlloc reports
// exhaustion through dError).
void *dxArenaAlloc(dxArena *arena, size_t bytes);
dxArenaMark dxArenaSave(const dxArena *arena);
void dxArenaRestore(dxArena *arena, dxArenaMark mark);

// Typed helpers.
#define DX_ARENA_ARRAY(arena, type, count) \
    ((type *)dxArenaAlloc((arena), sizeof(type) * (size_t)(count)))

#endif
