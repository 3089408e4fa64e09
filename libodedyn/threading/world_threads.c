// SPDX-License-Identifier: BSD-3-Clause
//
// world_threads.c -- a world's stepping threads: the public functions that
// set the threading implementation and the islands limit, and the parallel
// run of a step's pieces (step_threads.h), each thread in its own arena.

#include "parallel_run.h"
#include "step_memory.h"
#include "step_threads.h"
#include "threading_internal.h"


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

int dxStepThreadCount(struct dxWorld *w, int count, const char *function)
{
    if (!w->threading || count < 2) return 1;
    if (w->threading == &dx_threading_functions && !dxThreadingIsLive(w->threading_impl)) {
        dxReportBadArgument(function, "the world's threading implementation was freed; "
                            "stepping on the caller's thread");
        return 1;
    }
    unsigned n = w->threading->retrieve_thread_count(w->threading_impl);
    if (w->islands_max_threads != 0 && n > w->islands_max_threads) n = w->islands_max_threads;
    if (n > (unsigned)count) n = (unsigned)count;
    return n < 2 ? 1 : (int)n;
}

// A step's piece on a thread's arena.
typedef struct step_run {
    dxStepPieceFunction *piece;
    void *context;
    dxArena *arenas;   // one per thread
} step_run;

static void step_piece(void *context, int item, int thread)
{
    step_run *run = context;
    run->piece(run->context, item, &run->arenas[thread]);
}

void dxStepRunParallel(struct dxWorld *w, int threads, int count, dxStepPieceFunction *piece,
                       void *context)
{
    step_run run = { piece, context, dxStepMemoryThreadArenas(w, threads) };
    if (!w->step_wait) w->step_wait = w->threading->alloc_call_wait(w->threading_impl);
    if (dxRunPieces(w->threading, w->threading_impl, w->step_wait, threads, count, step_piece,
                    &run)) {
        dxStepMemoryBalance(w, threads);
    } else {   // the implementation has no room: on this thread
        for (int k = 0; k < count; k++) piece(context, k, &run.arenas[0]);
    }
}
