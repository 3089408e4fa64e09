// SPDX-License-Identifier: BSD-3-Clause
//
// pool.h -- free lists for worlds, bodies and joints. A destroyed object's
// memory is kept (with its header poisoned) and handed out again to the next
// object of that kind, so checking a stale handle never reads freed memory.
// dCloseODE returns all pooled memory to the system.

#ifndef DX_POOL_H
#define DX_POOL_H

#include <stddef.h>

typedef struct dxPool {
    void *free_list;      // pooled blocks, linked through their second word
    size_t block_size;    // size of every block handed out (0 until first use)
} dxPool;

extern dxPool dx_world_pool;
extern dxPool dx_body_pool;

// A block of at least `size` bytes (the pool's size is fixed at first use).
// Its header (first 8 bytes) keeps what the previous owner left there.
void *dxPoolTake(dxPool *pool, size_t size);
// Return a block whose header is already poisoned.
void dxPoolGive(dxPool *pool, void *block);
// Free every pooled block.
void dxPoolDrain(dxPool *pool);
// Free the pooled blocks of every joint type and of joint groups (joint.c).
void dxJointPoolsDrain(void);
// Free the pooled blocks of threading implementations and thread pools.
void dxThreadingPoolsDrain(void);

#endif
