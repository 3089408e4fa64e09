// SPDX-License-Identifier: BSD-3-Clause
//
// huge_page.h -- transparent huge pages (Linux, set to `madvise`) for the
// large blocks of both libraries (the step arena here, arena.c; the mesh
// trees' big_block.c in libodecollide): whether the system takes such
// advice (DX_HUGE_PAGES), the size of a huge page, and the advice itself. A
// source file that includes it defines _DEFAULT_SOURCE before any header
// (madvise's MADV_HUGEPAGE).

#ifndef DX_HUGE_PAGE_H
#define DX_HUGE_PAGE_H

#include <stddef.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define DX_HUGE_PAGES 1
#else
#define DX_HUGE_PAGES 0
#endif
#define DX_HUGE_PAGE ((size_t)2 << 20)

// Ask for huge pages for the bytes from p (a huge page's start; bytes a
// multiple of one), before they are touched. Only advice: a failure leaves
// the pages as they were.
static inline void dxAdviseHugePages(void *p, size_t bytes)
{
#if DX_HUGE_PAGES
    (void)madvise(p, bytes, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

#endif
