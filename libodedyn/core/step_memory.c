// SPDX-License-Identifier: BSD-3-Clause
//
// step_memory.c -- a world's working memory (step_memory.h) and its public
// functions: the reservation policy, the memory manager, sharing between
// worlds, and freeing it.

#include "objects_internal.h"
#include "step_memory.h"

#include <ode/error.h>
#include <ode/memory.h>

#define CHECK_WORLD(w, on_fail) \
    DX_CHECK_ARG(dxWorldIsLive(w), on_fail, "world is NULL or was destroyed")

static void *default_alloc_block(dsizeint size) { return dAlloc(size); }
static void default_free_block(void *p, dsizeint size) { dFree(p, size); }

static const dWorldStepMemoryFunctionsInfo default_manager = {
    sizeof(dWorldStepMemoryFunctionsInfo), default_alloc_block, NULL, default_free_block
};

// The arenas' block functions: the manager's, one call at a time (the
// island-stepping threads' arenas may grow at once).
static void *manager_alloc(void *context, size_t bytes)
{
    dxStepMemory *m = context;
    pthread_mutex_lock(&m->lock);
    void *p = m->manager.alloc_block(bytes);
    pthread_mutex_unlock(&m->lock);
    if (!p) dError(d_ERR_UNKNOWN, "world step: the memory manager's alloc_block failed "
                   "(%zu bytes)", bytes);
    return p;
}

static void manager_release(void *context, void *p, size_t bytes)
{
    dxStepMemory *m = context;
    pthread_mutex_lock(&m->lock);
    m->manager.free_block(p, bytes);
    pthread_mutex_unlock(&m->lock);
}

static void set_default_policy(dxStepMemory *m)
{
    m->policy.reserve_factor = dWORLDSTEP_RESERVEFACTOR_DEFAULT;
    m->policy.reserve_minimum = dWORLDSTEP_RESERVESIZE_DEFAULT;
}

// The world's memory, created (not shared) if it has none.
static dxStepMemory *memory_of(struct dxWorld *w)
{
    if (!w->memory) {
        dxStepMemory *m = dAlloc(sizeof *m);
        m->refs = 1;
        m->manager = default_manager;
        m->policy.alloc = manager_alloc;
        m->policy.release = manager_release;
        m->policy.context = m;
        m->policy.huge_pages = 1;   // the default manager's blocks only (dAlloc's)
        set_default_policy(m);
        pthread_mutex_init(&m->lock, NULL);
        dxArenaInitPolicy(&m->main, &m->policy);
        m->threads = NULL;
        m->nthreads = 0;
        w->memory = m;
    }
    w->arena = &w->memory->main;
    return w->memory;
}

// Give every block back (through the manager that allocated it).
static void memory_cleanup(dxStepMemory *m)
{
    dxArenaFree(&m->main);
    for (int i = 0; i < m->nthreads; i++) dxArenaFree(&m->threads[i]);
    dFree(m->threads, sizeof(dxArena) * (size_t)m->nthreads);
    m->threads = NULL;
    m->nthreads = 0;
}

void dxStepMemoryRelease(struct dxWorld *w)
{
    dxStepMemory *m = w->memory;
    w->memory = NULL;
    w->arena = NULL;
    if (!m || --m->refs > 0) return;
    memory_cleanup(m);
    pthread_mutex_destroy(&m->lock);
    dFree(m, sizeof *m);
}

void dxStepMemoryBegin(struct dxWorld *w)
{
    dxArenaReset(&memory_of(w)->main);
}

dxArena *dxStepMemoryThreadArenas(struct dxWorld *w, int n)
{
    dxStepMemory *m = memory_of(w);
    if (n > m->nthreads) {
        dxArena *grown = dAlloc(sizeof(dxArena) * (size_t)n);
        for (int i = 0; i < n; i++) {
            if (i < m->nthreads) grown[i] = m->threads[i];
            else dxArenaInitPolicy(&grown[i], &m->policy);
        }
        dFree(m->threads, sizeof(dxArena) * (size_t)m->nthreads);
        m->threads = grown;
        m->nthreads = n;
    }
    for (int i = 0; i < n; i++) dxArenaReset(&m->threads[i]);
    return m->threads;
}

void dxStepMemoryBalance(struct dxWorld *w, int n)
{
    dxStepMemory *m = w->memory;
    size_t peak = 0;
    for (int i = 0; i < n; i++)
        if (m->threads[i].peak > peak) peak = m->threads[i].peak;
    for (int i = 0; i < n; i++) dxArenaReserve(&m->threads[i], peak);
}

int dWorldSetStepMemoryReservationPolicy(dWorldID w, const dWorldStepReserveInfo *policyinfo)
{
    CHECK_WORLD(w, return 0);
    if (!policyinfo) {
        if (w->memory) set_default_policy(w->memory);
        return 1;
    }
    DX_CHECK_ARG(policyinfo->struct_size >= sizeof *policyinfo, return 0,
                 "policyinfo->struct_size is %u, smaller than the structure",
                 policyinfo->struct_size);
    DX_CHECK_ARG(policyinfo->reserve_factor >= 1.0f && dxIsFinite(policyinfo->reserve_factor),
                 return 0, "policyinfo->reserve_factor must be finite and >= 1, got %g",
                 (double)policyinfo->reserve_factor);
    dxStepMemory *m = memory_of(w);
    m->policy.reserve_factor = policyinfo->reserve_factor;
    m->policy.reserve_minimum = policyinfo->reserve_minimum;
    return 1;
}

int dWorldSetStepMemoryManager(dWorldID w, const dWorldStepMemoryFunctionsInfo *memfuncs)
{
    CHECK_WORLD(w, return 0);
    if (memfuncs) {
        DX_CHECK_ARG(memfuncs->struct_size >= sizeof *memfuncs, return 0,
                     "memfuncs->struct_size is %u, smaller than the structure",
                     memfuncs->struct_size);
        DX_CHECK_ARG(memfuncs->alloc_block && memfuncs->free_block, return 0,
                     "memfuncs->alloc_block and free_block must not be NULL");
    } else if (!w->memory) {
        return 1;
    }
    dxStepMemory *m = memory_of(w);
    memory_cleanup(m);   // with the functions that allocated it
    m->manager = memfuncs ? *memfuncs : default_manager;
    // A user's manager gets blocks of the sizes the arena needs, nothing
    // more (a huge page's alignment costs up to one more huge page).
    m->policy.huge_pages = memfuncs == NULL;
    return 1;
}

int dWorldUseSharedWorkingMemory(dWorldID w, dWorldID from_world)
{
    CHECK_WORLD(w, return 0);
    if (!from_world) {
        dxStepMemoryRelease(w);
        return 1;
    }
    DX_CHECK_ARG(dxWorldIsLive(from_world), return 0, "from_world was destroyed");
    DX_CHECK_ARG(from_world != w, return 0, "from_world is the world itself");
    DX_CHECK_ARG(w->memory == NULL || w->memory == from_world->memory, return 0,
                 "the world has working memory of its own (detach it with from_world NULL "
                 "first)");
    if (w->memory) return 1;   // already shared with from_world
    dxStepMemory *m = memory_of(from_world);
    m->refs++;
    w->memory = m;
    w->arena = &m->main;
    return 1;
}

void dWorldCleanupWorkingMemory(dWorldID w)
{
    CHECK_WORLD(w, return);
    if (w->memory) memory_cleanup(w->memory);
}
