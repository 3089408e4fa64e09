// SPDX-License-Identifier: BSD-3-Clause
//
// big_block.c -- large arrays on huge pages where they can be (big_block.h).

#define _DEFAULT_SOURCE   // madvise's MADV_HUGEPAGE (huge_page.h)

#include "big_block.h"
#include "../libodedyn/core/huge_page.h"

#include <ode/memory.h>
#include <stdint.h>

void *dxBigBlockAlloc(dxBigBlock *b, size_t size)
{
    const int huge = DX_HUGE_PAGES && size >= DX_HUGE_PAGE;
    b->size = size + (huge ? DX_HUGE_PAGE : 64);
    b->base = dAlloc(b->size);
    char *p = (char *)b->base + (64 - (uintptr_t)b->base % 64) % 64;
    if (huge) {
        p = (char *)b->base + (DX_HUGE_PAGE - (uintptr_t)b->base % DX_HUGE_PAGE) % DX_HUGE_PAGE;
        const size_t whole = ((char *)b->base + b->size - p) / DX_HUGE_PAGE * DX_HUGE_PAGE;
        dxAdviseHugePages(p, whole);
    }
    return p;
}

void dxBigBlockFree(dxBigBlock *b)
{
    if (b->base) dFree(b->base, b->size);
    b->base = NULL;
    b->size = 0;
}
