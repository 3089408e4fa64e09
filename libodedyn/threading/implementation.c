// SPDX-License-Identifier: BSD-3-Clause
//
// implementation.c -- the public life cycle of the library's threading
// implementations (threading_impl.h): allocation of either kind, its
// functions table, serving by external threads, shutdown, restart, free.
// Implementations come from a free list, so a freed handle reads as dead.

#include "pool.h"
#include "threading_internal.h"

static dxPool implementation_pool;

static dThreadingImplementationID allocate(uint32_t magic)
{
    struct dxThreadingImplementation *impl = dxPoolTake(&implementation_pool, sizeof *impl);
    impl->generation++;
    dxCallsInit(impl);
    impl->magic = magic;
    return impl;
}

dThreadingImplementationID dThreadingAllocateSelfThreadedImplementation(void)
{
    return allocate(DX_MAGIC_THREADING_SELF);
}

dThreadingImplementationID dThreadingAllocateMultiThreadedImplementation(void)
{
    return allocate(DX_MAGIC_THREADING_MULTI);
}

#define CHECK_IMPL(impl, on_fail) \
    DX_CHECK_ARG(dxThreadingIsLive(impl), on_fail, \
                 "threading implementation is NULL or was freed")

const dThreadingFunctionsInfo *dThreadingImplementationGetFunctions(
    dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return NULL);
    return &dx_threading_functions;
}

void dThreadingImplementationShutdownProcessing(dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return);
    pthread_mutex_lock(&impl->lock);
    impl->shutdown = impl->magic == DX_MAGIC_THREADING_MULTI;
    pthread_cond_broadcast(&impl->work);
    pthread_mutex_unlock(&impl->lock);
}

void dThreadingImplementationCleanupForRestart(dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return);
    pthread_mutex_lock(&impl->lock);
    const unsigned serving = impl->serving;
    if (serving == 0) impl->shutdown = 0;
    pthread_mutex_unlock(&impl->lock);
    DX_CHECK_ARG(serving == 0, return,
                 "%u threads still serve the implementation (shut it down and let them leave "
                 "first)", serving);
}

void dThreadingFreeImplementation(dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return);
    pthread_mutex_lock(&impl->lock);
    const unsigned serving = impl->serving;
    pthread_mutex_unlock(&impl->lock);
    DX_CHECK_ARG(serving == 0, return,
                 "%u threads still serve the implementation (shut it down and let them leave "
                 "first)", serving);
    dxCallsFree(impl);
    impl->magic = DX_MAGIC_THREADING_DEAD;
    dxPoolGive(&implementation_pool, impl);
}

void dExternalThreadingServeMultiThreadedImplementation(dThreadingImplementationID impl,
                                                        dThreadReadyToServeCallback *ready,
                                                        void *context)
{
    CHECK_IMPL(impl, return);
    DX_CHECK_ARG(impl->magic == DX_MAGIC_THREADING_MULTI, return,
                 "a self-threaded implementation is not served by threads");
    pthread_mutex_lock(&impl->lock);
    impl->serving++;
    pthread_mutex_unlock(&impl->lock);
    if (ready) ready(context);
    pthread_mutex_lock(&impl->lock);
    dxCallsServe(impl);
    impl->serving--;
    pthread_cond_broadcast(&impl->done);
    pthread_mutex_unlock(&impl->lock);
}

void dxThreadingPoolsDrain(void)
{
    dxPoolDrain(&implementation_pool);
    dxThreadPoolsDrain();
}
