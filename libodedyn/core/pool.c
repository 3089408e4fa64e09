// SPDX-License-Identifier: BSD-3-Clause
//
// pool.c -- free lists of fixed-size blocks (see pool.h).

#include "pool.h"

#include <ode/memory.h>
#include <string.h>

dxPool dx_world_pool;
dxPool dx_body_pool;

// The free-list link lives after the 8-byte object header, so a pooled
// block still reads as a dead object.
#define LINK_OFFSET 8

static void **link_of(void *block) { return (void **)((char *)block + LINK_OFFSET); }

void *dxPoolTake(dxPool *pool, size_t size)
{
    if (pool->block_size == 0) pool->block_size = size;
    if (pool->free_list) {
        void *block = pool->free_list;
        pool->free_list = *link_of(block);
        return block;
    }
    void *block = dAlloc(pool->block_size);
    memset(block, 0, pool->block_size);
    return block;
}

void dxPoolGive(dxPool *pool, void *block)
{
    *link_of(block) = pool->free_list;
    pool->free_list = block;
}

void dxPoolDrain(dxPool *pool)
{
    while (pool->free_list) {
        void *block = pool->free_list;
        pool->free_list = *link_of(block);
        dFree(block, pool->block_size);
    }
}
