// SPDX-License-Identifier: BSD-3-Clause
//
// step_threads.h -- running a step's independent pieces (islands) on the
// threads of the world's threading implementation (world_threads.c).
//
// Each thread takes the next piece not yet taken and works it in its own
// arena (step_memory.h), so which thread runs which piece, and in what order,
// changes nothing in any piece's numbers: a piece must read and write only its
// own data (and data no piece writes).

#ifndef DX_STEP_THREADS_H
#define DX_STEP_THREADS_H

#include "objects_internal.h"

// How many threads to run `count` pieces on: the implementation's thread
// count, at most the world's islands limit and count; 1 means the caller
// alone (no implementation, or one without threads, or a freed one: reported
// naming `function`).
int dxStepThreadCount(struct dxWorld *w, int count, const char *function);

// One piece: number `item`, with scratch from `arena` (reset between steps,
// not between pieces: restore what you take).
typedef void dxStepPieceFunction(void *context, int item, dxArena *arena);

// piece(context, k, arena) for every k in [0, count), on `threads` (> 1)
// threads of the world's implementation; returns when all are done.
void dxStepRunParallel(struct dxWorld *w, int threads, int count, dxStepPieceFunction *piece,
                       void *context);

#endif
