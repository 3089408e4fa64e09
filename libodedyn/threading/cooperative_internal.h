// SPDX-License-Identifier: BSD-3-Clause
//
// cooperative_internal.h -- the objects of cooperative.h (cooperative.c) as
// the cooperative computations (matrix_coop.c) use them.

#ifndef DX_COOPERATIVE_INTERNAL_H
#define DX_COOPERATIVE_INTERNAL_H

#include <ode/cooperative.h>

// Check a container for a call with rowCount rows (or elements): reports
// (naming `function`) and returns 0 if it is not a live container, or its
// estimates do not cover that many.
int dxCoopContainerCovers(const char *function, dResourceContainerID rc, unsigned rows);

// The container's scratch: as many numbers as its estimated rows.
dReal *dxCoopScratch(dResourceContainerID rc);

// piece(context, k) for every k in [0, count) on up to `threads` threads of
// the container's Cooperative (fewer if it has fewer, or none: the caller's
// thread); returns when all are done.
typedef void dxCoopPieceFunction(void *context, int item);
void dxCoopRun(dResourceContainerID rc, unsigned threads, int count, dxCoopPieceFunction *piece,
               void *context);

// Requirements grow to cover a computation on `threads` threads and `rows`
// rows (reports and does nothing for a bad handle, naming `function`).
void dxCoopRequire(const char *function, dResourceRequirementsID rq, unsigned threads,
                   unsigned rows);

#endif
