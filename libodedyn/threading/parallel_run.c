// SPDX-License-Identifier: BSD-3-Clause
//
// parallel_run.c -- independent pieces on a threading implementation's
// threads (parallel_run.h).

#include "parallel_run.h"

#include <stdatomic.h>

typedef struct pieces {
    dxPieceFunction *piece;
    void *context;
    int count;
    atomic_int next;   // the next piece nobody has taken
} pieces;

// One thread's call (instance_index: its number): pieces until none is left.
static int run_pieces(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)self;
    pieces *run = context;
    for (int k; (k = atomic_fetch_add_explicit(&run->next, 1, memory_order_relaxed)) < run->count;)
        run->piece(run->context, k, (int)index);
    return 1;
}

static int all_done(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)context;
    (void)index;
    (void)self;
    return 1;
}

int dxRunPieces(const dThreadingFunctionsInfo *f, dThreadingImplementationID impl,
                dCallWaitID wait, int threads, int count, dxPieceFunction *piece, void *context)
{
    if (!wait || !f->preallocate_resources_for_calls(impl, (size_t)threads + 1)) return 0;
    pieces run = { piece, context, count, 0 };
    f->reset_call_wait(impl, wait);
    dCallReleaseeID done;
    f->post_call(impl, NULL, &done, (size_t)threads, NULL, wait, all_done, NULL, 0, "pieces done");
    for (int t = 0; t < threads; t++)
        f->post_call(impl, NULL, NULL, 0, done, NULL, run_pieces, &run, (dcallindex_t)t, "pieces");
    f->wait_call(impl, NULL, wait, NULL, "pieces");
    return 1;
}
