// SPDX-License-Identifier: BSD-3-Clause
//
// parallel_run.h -- independent pieces of work run on the threads of a
// threading implementation (any implementation, through its functions
// table): one call per thread, each taking the next piece nobody has taken,
// all released into a last call that the caller waits for.

#ifndef DX_PARALLEL_RUN_H
#define DX_PARALLEL_RUN_H

#include <ode/threading.h>

// Piece `item`, run on the thread numbered `thread` (0 .. threads - 1; at
// most one piece at a time per number).
typedef void dxPieceFunction(void *context, int item, int thread);

// piece(context, k, t) for every k in [0, count) on `threads` threads of impl,
// waiting with `wait` (a call wait of impl). Returns 1 when all are done, or
// 0 (nothing ran) if the implementation could not take the calls.
int dxRunPieces(const dThreadingFunctionsInfo *f, dThreadingImplementationID impl,
                dCallWaitID wait, int threads, int count, dxPieceFunction *piece, void *context);

#endif
