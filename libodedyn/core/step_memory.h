// SPDX-License-Identifier: BSD-3-Clause
//
// step_memory.h -- a world's working memory for stepping (ODE 0.16's
// "working memory"): the main arena of a step, one arena per thread that
// steps islands, the reservation policy and the memory manager that all of
// them use. Created on demand, shared by worlds that
// dWorldUseSharedWorkingMemory (counted references).

#ifndef DX_STEP_MEMORY_H
#define DX_STEP_MEMORY_H

#include <ode/objects.h>
#include <pthread.h>

#include "arena.h"

typedef struct dxStepMemory {
    int refs;                         // worlds using it
    dxArenaPolicy policy;             // the arenas' blocks: through `manager`
    dWorldStepMemoryFunctionsInfo manager;
    pthread_mutex_t lock;             // block allocation (thread arenas grow in parallel)
    dxArena main;                     // the step's scratch (islands, QuickStep's system)
    dxArena *threads;                 // the island-stepping threads' arenas
    int nthreads;
} dxStepMemory;

struct dxWorld;

// Start a step: the world's memory (created if needed) with its main arena
// reset; w->arena points at it.
void dxStepMemoryBegin(struct dxWorld *w);
// The arenas of n island-stepping threads, reset.
dxArena *dxStepMemoryThreadArenas(struct dxWorld *w, int n);
// After a step on n thread arenas: every one of them keeps room for the
// largest, so that whichever thread steps whichever island next time, a
// repeated step allocates nothing.
void dxStepMemoryBalance(struct dxWorld *w, int n);
// The world lets go of its memory (dWorldDestroy).
void dxStepMemoryRelease(struct dxWorld *w);

#endif
