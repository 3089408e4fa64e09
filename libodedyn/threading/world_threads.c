// SPDX-License-Identifier: BSD-3-Clause
//
// world_threads.c -- a world's stepping threads: the public functions that
// set the threading implementation and the islands limit, and the parallel
// run of a step's pieces (step_threads.h) through the implementation's
// functions: one call per thread, all of them released into a last call
// that the stepping thread waits for.

#include "step_memory.h"
#include "step_threads.h"
#include "threading_internal.h"

#include <stdatomic.h>

#define CHECK_WORLD(w, on_fail) \
    DX_CHECK_ARG(dxWorldIsLive(w), on_fail, "world is NULL or was destroyed")

// Free the world's call wait (with the implementation that made it).
static void drop_wait(struct dxWorld *w)
{
    if (w->step_wait) w->threading->free_call_wait(w->threading_impl, w->step_wait);
    w->step_wait = NULL;
}

void dxWorldThreadingRelease(struct dxWorld *w)
{
    drop_wait(w);
    w->threading = NULL;
    w->threading_impl = NULL;
}

void dWorldSetStepThreadingImplementation(dWorldID w,
                                          const dThreadingFunctionsInfo *functions_info,
                                          dThreadingImplementationID threading_impl)
{
    CHECK_WORLD(w, return);
    if (functions_info) {
        DX_CHECK_ARG(functions_info->struct_size >= sizeof *functions_info, return,
                     "functions_info->struct_size is %u, smaller than the structure",
                     functions_info->struct_size);
        const dThreadingFunctionsInfo *f = functions_info;
        DX_CHECK_ARG(f->alloc_call_wait && f->reset_call_wait && f->free_call_wait &&
                         f->post_call && f->wait_call && f->retrieve_thread_count &&
                         f->preallocate_resources_for_calls,
                     return, "functions_info lacks a call or wait function");
        DX_CHECK_ARG(f != &dx_threading_functions || dxThreadingIsLive(threading_impl), return,
                     "threading_impl is NULL or was freed");
    }
    drop_wait(w);
    w->threading = functions_info;
    w->threading_impl = functions_info ? threading_impl : NULL;
}

void dWorldSetStepIslandsProcessingMaxThreadCount(dWorldID w, unsigned count)
{
    CHECK_WORLD(w, return);
    w->islands_max_threads = count;
}

unsigned dWorldGetStepIslandsProcessingMaxThreadCount(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->islands_max_threads;
}

int dxStepThreadCount(struct dxWorld *w, int count)
{
    if (!w->threading || count < 2) return 1;
    if (w->threading == &dx_threading_functions && !dxThreadingIsLive(w->threading_impl)) {
        dxReportBadArgument("dWorldStep", "the world's threading implementation was freed; "
                            "stepping on the caller's thread");
        return 1;
    }
    unsigned n = w->threading->retrieve_thread_count(w->threading_impl);
    if (w->islands_max_threads != 0 && n > w->islands_max_threads) n = w->islands_max_threads;
    if (n > (unsigned)count) n = (unsigned)count;
    return n < 2 ? 1 : (int)n;
}

typedef struct parallel_run {
    dxStepPieceFunction *piece;
    void *context;
    int count;
    atomic_int next;              // the next piece nobody has taken
    dxArena *arenas;              // one per thread: instance_index
} parallel_run;

// One thread's call: pieces until none is left.
static int run_pieces(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)self;
    parallel_run *run = context;
    dxArena *arena = &run->arenas[index];
    for (int k; (k = atomic_fetch_add_explicit(&run->next, 1, memory_order_relaxed)) < run->count;)
        run->piece(run->context, k, arena);
    return 1;
}

static int all_done(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)context;
    (void)index;
    (void)self;
    return 1;
}

void dxStepRunParallel(struct dxWorld *w, int threads, int count, dxStepPieceFunction *piece,
                       void *context)
{
    const dThreadingFunctionsInfo *f = w->threading;
    dThreadingImplementationID impl = w->threading_impl;
    parallel_run run = { piece, context, count, 0, dxStepMemoryThreadArenas(w, threads) };
    if (!w->step_wait) w->step_wait = f->alloc_call_wait(impl);
    if (!w->step_wait || !f->preallocate_resources_for_calls(impl, (size_t)threads + 1)) {
        run_pieces(&run, 0, NULL);   // the implementation has no room: on this thread
        return;
    }
    f->reset_call_wait(impl, w->step_wait);
    dCallReleaseeID done;
    f->post_call(impl, NULL, &done, (size_t)threads, NULL, w->step_wait, all_done, NULL, 0,
                 "step pieces done");
    for (int t = 0; t < threads; t++)
        f->post_call(impl, NULL, NULL, 0, done, NULL, run_pieces, &run, (dcallindex_t)t,
                     "step pieces");
    f->wait_call(impl, NULL, w->step_wait, NULL, "step");
    dxStepMemoryBalance(w, threads);
}
