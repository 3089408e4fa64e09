// SPDX-License-Identifier: BSD-3-Clause
//
// threading_internal.h -- the library's threading implementations
// (threading_impl.h): one task system (calls.c) behind the functions table
// of threading.h, run by the thread that waits (self-threaded) or by the
// threads that serve it (multi-threaded: implementation.c, thread_pool.c).
//
// Everything of an implementation is guarded by its one mutex: posting,
// releasing and waiting are a few pointer operations, and the calls
// themselves run unlocked.

#ifndef DX_THREADING_INTERNAL_H
#define DX_THREADING_INTERNAL_H

#include <ode/threading_impl.h>
#include <pthread.h>
#include <stdint.h>

#include "dx_check.h"

enum {
    DX_MAGIC_THREADING_SELF = 0x54536c66u,    // "TSlf"
    DX_MAGIC_THREADING_MULTI = 0x544d6c74u,   // "TMlt"
    DX_MAGIC_THREAD_POOL = 0x54506f6cu,       // "TPol"
    DX_MAGIC_CALL_JOB = 0x546a6f62u,          // "Tjob"
    DX_MAGIC_CALL_WAIT = 0x54776169u,         // "Twai"
    DX_MAGIC_MUTEX_GROUP = 0x546d7478u,       // "Tmtx"
    DX_MAGIC_THREADING_DEAD = 0xdeadbeefu
};

// A posted call. Its releasee ID is its address; jobs are recycled through
// the implementation's free list and freed only with it, so a stale
// releasee reads as a dead job.
typedef struct dxJob dxJob;
struct dxJob {
    uint32_t magic;              // DX_MAGIC_CALL_JOB while posted, else dead
    dxJob *next;                 // in the ready queue or the free list
    dxJob *all_next;             // every job of the implementation
    dxJob *dependent;            // loses a dependency when this completes
    struct dxCallWait *wait;     // signalled when this completes
    int *fault_out;
    dThreadedCallFunction *fn;
    void *context;
    dcallindex_t index;
    size_t deps;                 // unreleased dependencies (+1 while it runs)
    int started;                 // fn has been called
    int fault;                   // fn, or a call this one depended on, failed
};

struct dxCallWait {
    uint32_t magic;
    int signalled;               // the call completed (until reset)
};

struct dxThreadingImplementation {
    uint32_t magic;              // DX_MAGIC_THREADING_SELF or _MULTI, dead when freed
    uint32_t generation;
    pthread_mutex_t lock;
    pthread_cond_t work;         // a job became ready, or shutdown
    pthread_cond_t done;         // a wait was signalled, or a serving thread left
    dxJob *ready_head, *ready_tail;   // ready jobs, oldest first
    dxJob *free_jobs;
    size_t free_count;
    dxJob *all_jobs;
    unsigned serving;            // threads serving (multi-threaded)
    int shutdown;                // serving threads are to leave
};

// Check a handle of a live implementation (either kind).
static inline int dxThreadingIsLive(const struct dxThreadingImplementation *impl)
{
    return impl != NULL && (impl->magic == DX_MAGIC_THREADING_SELF ||
                            impl->magic == DX_MAGIC_THREADING_MULTI);
}

// The functions table of both kinds (calls.c).
extern const dThreadingFunctionsInfo dx_threading_functions;

// Set up and tear down the task system of an implementation (calls.c).
void dxCallsInit(struct dxThreadingImplementation *impl);
void dxCallsFree(struct dxThreadingImplementation *impl);
// Run ready jobs until shutdown (lock held): the loop of a serving thread.
void dxCallsServe(struct dxThreadingImplementation *impl);
// Free the pooled blocks of thread pools (thread_pool.c).
void dxThreadPoolsDrain(void);

#endif
