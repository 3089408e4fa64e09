// SPDX-License-Identifier: BSD-3-Clause
//
// thread_pool.c -- the library's thread pools (threading_impl.h): threads
// that idle until told to serve a multi-threaded implementation, serve it
// until it shuts down, and idle again; freed by joining them. Pools come from
// a free list, so a freed handle reads as dead.

#include "pool.h"
#include "threading_internal.h"

#include <limits.h>
#include <ode/error.h>
#include <ode/memory.h>
#include <ode/odeinit.h>
#include <signal.h>

struct dxThreadingThreadPool {
    uint32_t magic;
    uint32_t generation;
    pthread_mutex_t lock;
    pthread_cond_t command;      // a new implementation to serve, or exit
    pthread_cond_t state;        // a thread registered or went idle
    pthread_t *threads;
    unsigned count, started;
    unsigned round;              // bumped for each implementation to serve
    dThreadingImplementationID impl;
    unsigned busy;               // threads not yet back from serving
    unsigned registered;         // threads registered in this round's implementation
    int exit;
};

static dxPool thread_pool_pool;

#define CHECK_POOL(pool, on_fail) \
    DX_CHECK_ARG(pool && pool->magic == DX_MAGIC_THREAD_POOL, on_fail, \
                 "thread pool is NULL or was freed")

static void registered(void *context)
{
    struct dxThreadingThreadPool *pool = context;
    pthread_mutex_lock(&pool->lock);
    pool->registered++;
    pthread_cond_broadcast(&pool->state);
    pthread_mutex_unlock(&pool->lock);
}

static void *thread_main(void *context)
{
    struct dxThreadingThreadPool *pool = context;
    unsigned seen = 0;
    pthread_mutex_lock(&pool->lock);
    for (;;) {
        while (!pool->exit && pool->round == seen) pthread_cond_wait(&pool->command, &pool->lock);
        if (pool->exit) break;
        seen = pool->round;
        dThreadingImplementationID impl = pool->impl;
        pthread_mutex_unlock(&pool->lock);
        dExternalThreadingServeMultiThreadedImplementation(impl, registered, pool);
        pthread_mutex_lock(&pool->lock);
        pool->busy--;
        pthread_cond_broadcast(&pool->state);
    }
    pthread_mutex_unlock(&pool->lock);
    return NULL;
}

static size_t threads_size(unsigned count) { return sizeof(pthread_t) * (size_t)count; }

// End and join the started threads, and free the pool (idle).
static void destroy(struct dxThreadingThreadPool *pool)
{
    pthread_mutex_lock(&pool->lock);
    pool->exit = 1;
    pthread_cond_broadcast(&pool->command);
    pthread_mutex_unlock(&pool->lock);
    for (unsigned i = 0; i < pool->started; i++) pthread_join(pool->threads[i], NULL);
    dFree(pool->threads, threads_size(pool->count));
    pthread_cond_destroy(&pool->state);
    pthread_cond_destroy(&pool->command);
    pthread_mutex_destroy(&pool->lock);
    pool->magic = DX_MAGIC_THREADING_DEAD;
    dxPoolGive(&thread_pool_pool, pool);
}

dThreadingThreadPoolID dThreadingAllocateThreadPool(unsigned thread_count, dsizeint stack_size,
                                                    unsigned int ode_data_allocate_flags,
                                                    void *reserved)
{
    (void)reserved;
    DX_CHECK_ARG(thread_count > 0, return NULL, "thread_count must be positive");
    // Nothing is kept per thread here: the threads would only repeat this check.
    if (!dAllocateODEDataForThread(ode_data_allocate_flags)) return NULL;
    struct dxThreadingThreadPool *pool = dxPoolTake(&thread_pool_pool, sizeof *pool);
    pool->generation++;
    pthread_mutex_init(&pool->lock, NULL);
    pthread_cond_init(&pool->command, NULL);
    pthread_cond_init(&pool->state, NULL);
    pool->threads = dAlloc(threads_size(thread_count));
    pool->count = thread_count;
    pool->started = 0;
    pool->round = 0;
    pool->impl = NULL;
    pool->busy = pool->registered = 0;
    pool->exit = 0;
    pool->magic = DX_MAGIC_THREAD_POOL;

    pthread_attr_t attr;
    pthread_attr_init(&attr);
    if (stack_size > 0)
        pthread_attr_setstacksize(&attr, stack_size < PTHREAD_STACK_MIN ? PTHREAD_STACK_MIN
                                                                        : stack_size);
    // The threads start with every signal blocked (they inherit the mask).
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    while (pool->started < thread_count &&
           pthread_create(&pool->threads[pool->started], &attr, thread_main, pool) == 0)
        pool->started++;
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    pthread_attr_destroy(&attr);
    if (pool->started < thread_count) {
        dMessage(d_ERR_UNKNOWN, "dThreadingAllocateThreadPool: could start only %u of %u threads",
                 pool->started, thread_count);
        destroy(pool);
        return NULL;
    }
    return pool;
}

void dThreadingThreadPoolServeMultiThreadedImplementation(dThreadingThreadPoolID pool,
                                                          dThreadingImplementationID impl)
{
    CHECK_POOL(pool, return);
    DX_CHECK_ARG(dxThreadingIsLive(impl), return,
                 "threading implementation is NULL or was freed");
    DX_CHECK_ARG(impl->magic == DX_MAGIC_THREADING_MULTI, return,
                 "a self-threaded implementation is not served by threads");
    pthread_mutex_lock(&pool->lock);
    const unsigned busy = pool->busy;
    if (busy == 0) {
        pool->impl = impl;
        pool->busy = pool->count;
        pool->registered = 0;
        pool->round++;
        pthread_cond_broadcast(&pool->command);
        while (pool->registered < pool->count) pthread_cond_wait(&pool->state, &pool->lock);
    }
    pthread_mutex_unlock(&pool->lock);
    DX_CHECK_ARG(busy == 0, return,
                 "the pool still serves an implementation (shut it down and wait for the "
                 "pool's idle state first)");
}

void dThreadingThreadPoolWaitIdleState(dThreadingThreadPoolID pool)
{
    CHECK_POOL(pool, return);
    pthread_mutex_lock(&pool->lock);
    while (pool->busy > 0) pthread_cond_wait(&pool->state, &pool->lock);
    pthread_mutex_unlock(&pool->lock);
}

void dThreadingFreeThreadPool(dThreadingThreadPoolID pool)
{
    CHECK_POOL(pool, return);
    dThreadingThreadPoolWaitIdleState(pool);
    destroy(pool);
}

void dxThreadPoolsDrain(void) { dxPoolDrain(&thread_pool_pool); }
