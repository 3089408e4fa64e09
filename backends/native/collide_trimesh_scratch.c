// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_scratch.c -- the scratch memory of the native trimesh
// colliders (triangle lists, contacts before the reduction), per thread:
// two threads may collide one mesh with different geoms at once. Each
// thread has a few sets, one per nested collision (a trimesh callback may
// itself call dCollide); they grow when needed and are reused, so a warm
// collision allocates nothing. The thread's temporal-coherence cache
// (collide_trimesh_tc.c) lives here too. A thread's memory is freed when it
// exits.

#include "collide_trimesh.h"

#include <ode/memory.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

enum { NESTING = 4 };

typedef struct thread_scratch {
    dxTriScratch set[NESTING];
    int depth;   // sets in use
    void *tc;    // the temporal-coherence cache's block (tc_size bytes) or NULL
    size_t tc_size;
    void *tc_line;   // the cache itself: where the block's first cache line starts
} thread_scratch;

static _Thread_local thread_scratch *mine;
static pthread_key_t exit_key;
static pthread_once_t exit_key_once = PTHREAD_ONCE_INIT;

static void free_thread_scratch(void *p)
{
    thread_scratch *t = (thread_scratch *)p;
    for (int i = 0; i < NESTING; i++) {
        dxTriScratch *s = &t->set[i];
        for (int k = 0; k < 2; k++) {
            dFree(s->cand[k], (size_t)s->cand_cap[k] * sizeof(int));
            dFree(s->hits[k], (size_t)s->hits_cap[k] * sizeof(int));
        }
        dFree(s->raw, (size_t)s->raw_cap * sizeof(dxTriMeshRaw));
        dxTriGridFree(&s->grid);
        dFree(s->score, (size_t)s->score_cap * sizeof(dReal));
    }
    if (t->tc) dFree(t->tc, t->tc_size);
    dFree(t, sizeof *t);
}

static void make_exit_key(void)
{
    pthread_key_create(&exit_key, free_thread_scratch);
}

// The calling thread's scratch, made on first use.
static thread_scratch *thread_mine(void)
{
    if (!mine) {
        pthread_once(&exit_key_once, make_exit_key);
        mine = (thread_scratch *)dAlloc(sizeof *mine);
        memset(mine, 0, sizeof *mine);
        for (int i = 0; i < NESTING; i++) mine->set[i].in_use = &mine->depth;
        pthread_setspecific(exit_key, mine);
    }
    return mine;
}

void *dxTriScratchThreadTC(size_t size)
{
    thread_scratch *t = thread_mine();
    if (!t->tc) {
        t->tc_size = size + 64;
        t->tc = dAlloc(t->tc_size);
        memset(t->tc, 0, t->tc_size);
        t->tc_line = (char *)t->tc + (64 - (uintptr_t)t->tc % 64) % 64;
    }
    return t->tc_line;
}

dxTriScratch *dxTriScratchAcquire(void)
{
    thread_mine();
    DX_CHECK_ARG(mine->depth < NESTING, return NULL,
                 "trimesh collisions nested more than %d deep (dCollide called from a trimesh "
                 "callback): no contacts", NESTING);
    dxTriScratch *s = &mine->set[mine->depth++];
    s->raw_count = 0;
    return s;
}

void dxTriScratchRelease(dxTriScratch *s)
{
    if (s) (*s->in_use)--;   // (the thread's count, without its thread-local lookup)
}

void dxTriScratchAddRaw(dxTriScratch *s, int extra)
{
    if (s->raw_count + extra <= s->raw_cap) return;
    int ncap = s->raw_cap ? 2 * s->raw_cap : 32;
    while (ncap < s->raw_count + extra) ncap *= 2;
    s->raw = (dxTriMeshRaw *)dRealloc(s->raw, (size_t)s->raw_cap * sizeof *s->raw,
                                      (size_t)ncap * sizeof *s->raw);
    s->raw_cap = ncap;
}
