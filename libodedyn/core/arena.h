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
// than reserve_minimum bytes. huge_pages: a rebuilt block of
// DX_ARENA_HUGE_MIN bytes or more is asked for one huge page larger, and its
// usable bytes start at a huge page and are advised onto huge pages
// (huge_page.h), rounded up to whole ones: QuickStep reads its rows in a
// shuffled order all over the step's arena, and with 4 KB pages most of
// those reads miss the first-level TLB (a rebuilt block only: the blocks
// chained while a step outgrows the arena are short-lived, and huge pages
// would only add to the memory they hold at once). NULL: dAlloc/dFree, 1.2,
// 64 KiB and no huge pages.
typedef struct dxArenaPolicy {
    void *(*alloc)(void *context, size_t bytes);
    void (*release)(void *context, void *p, size_t bytes);
    void *context;
    float reserve_factor;
    size_t reserve_minimum;
    int huge_pages;
} dxArenaPolicy;

// The least rebuilt block put on huge pages (so that at least half of each
// huge page it takes is asked for).
#define DX_ARENA_HUGE_MIN ((size_t)1 << 20)

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
