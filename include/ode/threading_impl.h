/* SPDX-License-Identifier: BSD-3-Clause */
/* threading_impl.h -- the library's threading implementations (ODE 0.16):
 * self-threaded (posted calls run on the thread that waits for them, in the
 * order they became ready) and multi-threaded (posted calls run on the
 * threads that serve the implementation: a thread pool of this library, or
 * the program's own threads), and thread pools.
 *
 * A typical program:
 *   impl = dThreadingAllocateMultiThreadedImplementation();
 *   pool = dThreadingAllocateThreadPool(4, 0, dAllocateFlagBasicData, NULL);
 *   dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
 *   dWorldSetStepThreadingImplementation(world,
 *       dThreadingImplementationGetFunctions(impl), impl);
 *   ... steps ...
 *   dThreadingImplementationShutdownProcessing(impl);
 *   dThreadingFreeThreadPool(pool);
 *   dWorldSetStepThreadingImplementation(world, NULL, NULL);
 *   dThreadingFreeImplementation(impl);
 * A NULL, freed or wrong kind of handle is reported through the debug
 * handler naming the function; the call then has no effect. */
#ifndef ODE_THREADING_IMPL_H
#define ODE_THREADING_IMPL_H

#include <ode/odeconfig.h>
#include <ode/threading.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dxThreadingThreadPool;
typedef struct dxThreadingThreadPool *dThreadingThreadPoolID;

/** An implementation whose calls run on the caller's thread while it waits
 *  for them; reports 0 threads. NULL on failure. */
ODE_API dThreadingImplementationID dThreadingAllocateSelfThreadedImplementation(void);
/** An implementation served by threads (a pool, or threads that call
 *  dExternalThreadingServeMultiThreadedImplementation). NULL on failure. */
ODE_API dThreadingImplementationID dThreadingAllocateMultiThreadedImplementation(void);
/** The functions table of an implementation allocated above. */
ODE_API const dThreadingFunctionsInfo *dThreadingImplementationGetFunctions(
    dThreadingImplementationID impl);
/** Release the threads serving impl (they return once their current call is
 *  done); no effect on a self-threaded implementation. */
ODE_API void dThreadingImplementationShutdownProcessing(dThreadingImplementationID impl);
/** Make a shut down implementation servable again (after its threads left). */
ODE_API void dThreadingImplementationCleanupForRestart(dThreadingImplementationID impl);
/** Free an implementation no world uses and no thread serves. */
ODE_API void dThreadingFreeImplementation(dThreadingImplementationID impl);

typedef void(dThreadReadyToServeCallback)(void *callback_context);

/** The calling thread serves impl until dThreadingImplementationShutdownProcessing;
 *  readiness_callback (optional) is called once it has registered. */
ODE_API void dExternalThreadingServeMultiThreadedImplementation(
    dThreadingImplementationID impl, dThreadReadyToServeCallback *readiness_callback,
    void *callback_context);

/** A pool of thread_count threads (stack_size bytes each, 0: the system's
 *  default); ode_data_allocate_flags as for dAllocateODEDataForThread;
 *  reserved is ignored. NULL on failure. */
ODE_API dThreadingThreadPoolID dThreadingAllocateThreadPool(unsigned thread_count,
                                                            dsizeint stack_size,
                                                            unsigned int ode_data_allocate_flags,
                                                            void *reserved);
/** All the pool's threads serve impl; returns once they have registered.
 *  A pool serves one implementation at a time. */
ODE_API void dThreadingThreadPoolServeMultiThreadedImplementation(dThreadingThreadPoolID pool,
                                                                  dThreadingImplementationID impl);
/** Wait until no thread of the pool serves an implementation. */
ODE_API void dThreadingThreadPoolWaitIdleState(dThreadingThreadPoolID pool);
/** Wait until idle, end the threads and free the pool. */
ODE_API void dThreadingFreeThreadPool(dThreadingThreadPoolID pool);

#ifdef __cplusplus
}
#endif

#endif
