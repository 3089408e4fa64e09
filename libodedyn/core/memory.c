// SPDX-License-Identifier: BSD-3-Clause
//
// memory.c -- the allocation handlers (guide 9.4). Every allocation of the
// library goes through dAlloc/dRealloc/dFree so a program can count or pool it.

#include <ode/memory.h>
#include <ode/error.h>
#include <ode/common.h>

static dAllocFunction *alloc_handler;
static dReallocFunction *realloc_handler;
static dFreeFunction *free_handler;

void dSetAllocHandler(dAllocFunction *fn) { alloc_handler = fn; }
void dSetReallocHandler(dReallocFunction *fn) { realloc_handler = fn; }
void dSetFreeHandler(dFreeFunction *fn) { free_handler = fn; }
dAllocFunction *dGetAllocHandler(void) { return alloc_handler; }
dReallocFunction *dGetReallocHandler(void) { return realloc_handler; }
dFreeFunction *dGetFreeHandler(void) { return free_handler; }

void *dAlloc(dsizeint size)
{
    void *p = alloc_handler ? alloc_handler(size) : malloc(size ? size : 1);
    if (!p) dError(d_ERR_UNKNOWN, "dAlloc: out of memory (%zu bytes)", (size_t)size);
    return p;
}

void *dRealloc(void *ptr, dsizeint oldsize, dsizeint newsize)
{
    void *p = realloc_handler ? realloc_handler(ptr, oldsize, newsize)
                              : realloc(ptr, newsize ? newsize : 1);
    if (!p) dError(d_ERR_UNKNOWN, "dRealloc: out of memory (%zu bytes)", (size_t)newsize);
    return p;
}

void dFree(void *ptr, dsizeint size)
{
    if (!ptr) return;
    if (free_handler) free_handler(ptr, size);
    else free(ptr);
}
