/* SPDX-License-Identifier: BSD-3-Clause */
/* threading.h -- the interface between the library and a threading
 * implementation (ODE 0.16): a table of functions that allocate mutexes and
 * call waits, post calls with dependencies, and wait for them. The library's
 * own implementations are in threading_impl.h; a program may supply its own
 * table instead (dWorldSetStepThreadingImplementation).
 *
 * The call model: a posted call runs once its dependency count is zero. When
 * it has run (and any dependencies added from inside it have completed) it
 * completes: its fault state goes to *out_summary_fault (1 if it or a call
 * it depended on returned 0), its call wait is signalled, and the call named
 * as its dependent_releasee loses one dependency. */
#ifndef ODE_THREADING_H
#define ODE_THREADING_H

#include <ode/odeconfig.h>
#include <time.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dxThreadingImplementation;
typedef struct dxThreadingImplementation *dThreadingImplementationID;

typedef unsigned dmutexindex_t;
struct dxMutexGroup;
typedef struct dxMutexGroup *dMutexGroupID;

#define dTHREADING_THREAD_COUNT_UNLIMITED 0U

/** A group of Mutex_count non-recursive mutexes (names optional, for
 *  debugging); NULL on failure. */
typedef dMutexGroupID dMutexGroupAllocFunction(dThreadingImplementationID impl,
                                               dmutexindex_t Mutex_count,
                                               const char *const *Mutex_names_ptr);
typedef void dMutexGroupFreeFunction(dThreadingImplementationID impl, dMutexGroupID mutex_group);
/** Blocks until mutex mutex_index (0 .. count - 1) of the group is locked. */
typedef void dMutexGroupMutexLockFunction(dThreadingImplementationID impl,
                                          dMutexGroupID mutex_group, dmutexindex_t mutex_index);
typedef void dMutexGroupMutexUnlockFunction(dThreadingImplementationID impl,
                                            dMutexGroupID mutex_group,
                                            dmutexindex_t mutex_index);

struct dxCallReleasee;
typedef struct dxCallReleasee *dCallReleaseeID;

struct dxCallWait;
typedef struct dxCallWait *dCallWaitID;

typedef dsizeint ddependencycount_t;
typedef ddiffint ddependencychange_t;
typedef dsizeint dcallindex_t;
/** A posted call: returns nonzero on success, 0 on failure (a fault).
 *  this_releasee names the call itself, for sub-calls it waits for. */
typedef int dThreadedCallFunction(void *call_context, dcallindex_t instance_index,
                                  dCallReleaseeID this_releasee);

/** A duration: seconds and nanoseconds. */
typedef struct dxThreadedWaitTime {
    time_t wait_sec;
    unsigned long wait_nsec;
} dThreadedWaitTime;

/** A wait object for one posted call at a time; NULL on failure. */
typedef dCallWaitID dThreadedCallWaitAllocFunction(dThreadingImplementationID impl);
/** Make a signalled wait usable for another call. */
typedef void dThreadedCallWaitResetFunction(dThreadingImplementationID impl,
                                            dCallWaitID call_wait);
typedef void dThreadedCallWaitFreeFunction(dThreadingImplementationID impl,
                                           dCallWaitID call_wait);

/** Post call_func(call_context, instance_index, releasee) to run once
 *  dependencies_count dependencies have been released. out_post_releasee
 *  (optional) receives the call's releasee, for sub-calls that name it as
 *  their dependent_releasee. On completion: *out_summary_fault (optional)
 *  gets 1 if the call or a call it depended on failed, else 0; call_wait
 *  (optional) is signalled; dependent_releasee (optional) loses one
 *  dependency. call_name must stay valid until the call completes. */
typedef void dThreadedCallPostFunction(dThreadingImplementationID impl, int *out_summary_fault,
                                       dCallReleaseeID *out_post_releasee,
                                       ddependencycount_t dependencies_count,
                                       dCallReleaseeID dependent_releasee, dCallWaitID call_wait,
                                       dThreadedCallFunction *call_func, void *call_context,
                                       dcallindex_t instance_index, const char *call_name);

/** Add (or remove) dependencies of a posted call; from inside the call once it
 *  has started. A call whose count reaches zero may start. */
typedef void dThreadedCallDependenciesCountAlterFunction(
    dThreadingImplementationID impl, dCallReleaseeID target_releasee,
    ddependencychange_t dependencies_count_change);

/** Block until the call posted with call_wait completes, or the timeout
 *  (a duration; NULL: none; zero: only look) passes. *out_wait_status
 *  (optional): 1 if it completed, 0 on timeout. Never from inside a call. */
typedef void dThreadedCallWaitFunction(dThreadingImplementationID impl, int *out_wait_status,
                                       dCallWaitID call_wait,
                                       const dThreadedWaitTime *timeout_time_ptr,
                                       const char *wait_name);

/** The number of threads serving the implementation (0 for self-threaded). */
typedef unsigned dThreadingImplThreadCountRetrieveFunction(dThreadingImplementationID impl);

/** Make room for max_simultaneous_calls_estimate calls posted at once; 1 on
 *  success. */
typedef int dThreadingImplResourcesForCallsPreallocateFunction(
    dThreadingImplementationID impl, ddependencycount_t max_simultaneous_calls_estimate);

/** The functions of a threading implementation; struct_size = sizeof. */
typedef struct dxThreadingFunctionsInfo {
    unsigned struct_size;

    dMutexGroupAllocFunction *alloc_mutex_group;
    dMutexGroupFreeFunction *free_mutex_group;
    dMutexGroupMutexLockFunction *lock_group_mutex;
    dMutexGroupMutexUnlockFunction *unlock_group_mutex;

    dThreadedCallWaitAllocFunction *alloc_call_wait;
    dThreadedCallWaitResetFunction *reset_call_wait;
    dThreadedCallWaitFreeFunction *free_call_wait;

    dThreadedCallPostFunction *post_call;
    dThreadedCallDependenciesCountAlterFunction *alter_call_dependencies_count;
    dThreadedCallWaitFunction *wait_call;

    dThreadingImplThreadCountRetrieveFunction *retrieve_thread_count;
    dThreadingImplResourcesForCallsPreallocateFunction *preallocate_resources_for_calls;
} dThreadingFunctionsInfo;

#ifdef __cplusplus
}
#endif

#endif
