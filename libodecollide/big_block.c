// SPDX-License-Identifier: BSD-3-Clause
//
// big_block.c -- large arrays on huge pages where they can be (big_block.h).

#define _DEFAULT_SOURCE   // madvise's MADV_HUGEPAGE (Linux)

#include "big_block.h"

#include <ode/memory.h>
#include <stdint.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define HUGE_PAGE ((size_t)2 << 20)
#else
#define HUGE_PAGE ((size_t)0)
#endif

void *dxBigBlockAlloc(dxBigBlock *b, size_t size)
{
    const int huge = HUGE_PAGE && size >= HUGE_PAGE;
    b->size = size + (huge ? HUGE_PAGE : 64);
    b->base = dAlloc(b->size);
    char *p = (char *)b->base + (64 - (uintptr_t)b->base % 64) % 64;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge) {
        p = (char *)b->base + (HUGE_PAGE - (uintptr_t)b->base % HUGE_PAGE) % HUGE_PAGE;
        const size_t whole = ((char *)b->base + b->size - p) / HUGE_PAGE * HUGE_PAGE;
        (void)madvise(p, whole, MADV_HUGEPAGE);
    }
#endif
    return p;
}

void dxBigBlockFree(dxBigBlock *b)
{
    if (b->base) dFree(b->base, b->size);
    b->base = NULL;
    b->size = 0;
}
