// SPDX-License-Identifier: BSD-3-Clause
//
// big_block.h -- memory for one large array (a mesh's tree, a build's
// temporaries): from dAlloc, at a cache line's start, and where it spans a
// transparent huge page or more (Linux, set to `madvise`), from a huge
// page's start with its whole huge pages advised before they are touched.
// A large array written once and then read all over costs its page faults
// (about one per 4 KB page, each far dearer than writing the page in a
// virtual machine) and its TLB misses; a 2 MB page is one fault and one
// TLB entry. Only advice: where it fails, the block is as dAlloc made it.

#ifndef DX_BIG_BLOCK_H
#define DX_BIG_BLOCK_H

#include <stddef.h>

typedef struct dxBigBlock {
    void *base;   // from dAlloc (NULL: none)
    size_t size;  // what was asked of dAlloc
} dxBigBlock;

// A block of at least size bytes (size > 0) into b; returns its start.
void *dxBigBlockAlloc(dxBigBlock *b, size_t size);

// Give b's block back (none: nothing) and leave b empty.
void dxBigBlockFree(dxBigBlock *b);

#endif
