// SPDX-License-Identifier: BSD-3-Clause
//
// calls.c -- the task system behind the functions table of threading.h, for
// both of the library's implementations: posted calls with dependency
// counts, releasees, call waits, timeouts and fault summaries.
//
// A job is posted with a dependency count; at zero it joins the ready queue
// (oldest first). Running it holds one more dependency, so sub-calls posted
// from inside it (after it added dependencies for them) keep it from
// completing until they complete. On completion its fault goes to
// *fault_out, its wait is signalled, and its dependent loses a dependency
// (inheriting the fault): a dependent that has not started becomes ready, one
// that has already returned completes in turn.
//
// Who runs ready jobs: the threads serving a multi-threaded implementation
// (dxCallsServe), or, for a self-threaded one, the thread that waits.

#include "threading_internal.h"

#include <errno.h>
#include <ode/memory.h>
#include <time.h>

#define CHECK_IMPL(impl, on_fail) \
    DX_CHECK_ARG(dxThreadingIsLive(impl), on_fail, \
                 "threading implementation is NULL or was freed")

static int is_multi(const struct dxThreadingImplementation *impl)
{
    return impl->magic == DX_MAGIC_THREADING_MULTI;
}

void dxCallsInit(struct dxThreadingImplementation *impl)
{
    pthread_mutex_init(&impl->lock, NULL);
    pthread_cond_init(&impl->work, NULL);
    pthread_cond_init(&impl->done, NULL);
    impl->ready_head = impl->ready_tail = NULL;
    impl->free_jobs = impl->all_jobs = NULL;
    impl->free_count = 0;
    impl->serving = 0;
    impl->shutdown = 0;
}

void dxCallsFree(struct dxThreadingImplementation *impl)
{
    while (impl->all_jobs) {
        dxJob *j = impl->all_jobs;
        impl->all_jobs = j->all_next;
        dFree(j, sizeof *j);
    }
    impl->free_jobs = NULL;
    impl->free_count = 0;
    pthread_cond_destroy(&impl->done);
    pthread_cond_destroy(&impl->work);
    pthread_mutex_destroy(&impl->lock);
}

// ---- jobs (lock held) ----------------------------------------------------

// Put one more job on the free list.
static void add_free_job(struct dxThreadingImplementation *impl)
{
    dxJob *j = dAlloc(sizeof *j);
    j->magic = DX_MAGIC_THREADING_DEAD;
    j->all_next = impl->all_jobs;
    impl->all_jobs = j;
    j->next = impl->free_jobs;
    impl->free_jobs = j;
    impl->free_count++;
}

static dxJob *take_job(struct dxThreadingImplementation *impl)
{
    if (!impl->free_jobs) add_free_job(impl);
    dxJob *j = impl->free_jobs;
    impl->free_jobs = j->next;
    impl->free_count--;
    return j;
}

static void give_job(struct dxThreadingImplementation *impl, dxJob *j)
{
    j->magic = DX_MAGIC_THREADING_DEAD;
    j->next = impl->free_jobs;
    impl->free_jobs = j;
    impl->free_count++;
}

static void make_ready(struct dxThreadingImplementation *impl, dxJob *j)
{
    j->next = NULL;
    if (impl->ready_tail) impl->ready_tail->next = j;
    else impl->ready_head = j;
    impl->ready_tail = j;
    pthread_cond_signal(&impl->work);
}

static dxJob *pop_ready(struct dxThreadingImplementation *impl)
{
    dxJob *j = impl->ready_head;
    if (j) {
        impl->ready_head = j->next;
        if (!impl->ready_head) impl->ready_tail = NULL;
    }
    return j;
}

// A job whose dependencies (its own run included) are all released: report,
// signal, and release its dependent, completing the chain as far as it goes.
static void complete(struct dxThreadingImplementation *impl, dxJob *j)
{
    while (j) {
        const int fault = j->fault;
        if (j->fault_out) *j->fault_out = fault;
        if (j->wait) {
            j->wait->signalled = 1;
            pthread_cond_broadcast(&impl->done);
        }
        dxJob *dep = j->dependent;
        give_job(impl, j);
        j = NULL;
        if (!dep) break;
        if (fault) dep->fault = 1;
        if (--dep->deps != 0) break;
        if (dep->started) j = dep;   // it returned and waited for this one
        else make_ready(impl, dep);
    }
}

// Run a ready job: unlocked while its function runs.
static void run(struct dxThreadingImplementation *impl, dxJob *j)
{
    j->started = 1;
    j->deps = 1;
    pthread_mutex_unlock(&impl->lock);
    const int ok = j->fn(j->context, j->index, (dCallReleaseeID)j);
    pthread_mutex_lock(&impl->lock);
    if (!ok) j->fault = 1;
    if (--j->deps == 0) complete(impl, j);
}

void dxCallsServe(struct dxThreadingImplementation *impl)
{
    for (;;) {
        while (!impl->shutdown && !impl->ready_head) pthread_cond_wait(&impl->work, &impl->lock);
        if (impl->shutdown) return;
        run(impl, pop_ready(impl));
    }
}

static dxJob *live_job(dCallReleaseeID releasee)
{
    dxJob *j = (dxJob *)releasee;
    return j && j->magic == DX_MAGIC_CALL_JOB ? j : NULL;
}

// ---- the functions table ---------------------------------------------------

typedef struct dxMutexGroup {
    uint32_t magic;
    dmutexindex_t count;
    pthread_mutex_t mutex[];
} dxMutexGroup;

static size_t mutex_group_size(dmutexindex_t count)
{
    return sizeof(dxMutexGroup) + sizeof(pthread_mutex_t) * (size_t)count;
}

static dMutexGroupID alloc_mutex_group(dThreadingImplementationID impl, dmutexindex_t count,
                                       const char *const *names)
{
    (void)names;
    CHECK_IMPL(impl, return NULL);
    DX_CHECK_ARG(count > 0, return NULL, "Mutex_count must be positive");
    dxMutexGroup *g = dAlloc(mutex_group_size(count));
    g->magic = DX_MAGIC_MUTEX_GROUP;
    g->count = count;
    for (dmutexindex_t i = 0; i < count; i++) pthread_mutex_init(&g->mutex[i], NULL);
    return g;
}

static void free_mutex_group(dThreadingImplementationID impl, dMutexGroupID g)
{
    CHECK_IMPL(impl, return);
    DX_CHECK_ARG(g && g->magic == DX_MAGIC_MUTEX_GROUP, return,
                 "mutex_group is NULL or was freed");
    for (dmutexindex_t i = 0; i < g->count; i++) pthread_mutex_destroy(&g->mutex[i]);
    g->magic = DX_MAGIC_THREADING_DEAD;
    dFree(g, mutex_group_size(g->count));
}

#define CHECK_MUTEX(g, i) \
    DX_CHECK_ARG(g && g->magic == DX_MAGIC_MUTEX_GROUP, return, \
                 "mutex_group is NULL or was freed"); \
    DX_CHECK_ARG(i < g->count, return, "mutex_index %u is not below the group's %u", i, \
                 g->count)

static void lock_group_mutex(dThreadingImplementationID impl, dMutexGroupID g, dmutexindex_t i)
{
    CHECK_IMPL(impl, return);
    CHECK_MUTEX(g, i);
    pthread_mutex_lock(&g->mutex[i]);
}

static void unlock_group_mutex(dThreadingImplementationID impl, dMutexGroupID g,
                               dmutexindex_t i)
{
    CHECK_IMPL(impl, return);
    CHECK_MUTEX(g, i);
    pthread_mutex_unlock(&g->mutex[i]);
}

static dCallWaitID alloc_call_wait(dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return NULL);
    struct dxCallWait *w = dAlloc(sizeof *w);
    w->magic = DX_MAGIC_CALL_WAIT;
    w->signalled = 0;
    return w;
}

#define CHECK_WAIT(w, on_fail) \
    DX_CHECK_ARG(w && w->magic == DX_MAGIC_CALL_WAIT, on_fail, "call_wait is NULL or was freed")

static void reset_call_wait(dThreadingImplementationID impl, dCallWaitID w)
{
    CHECK_IMPL(impl, return);
    CHECK_WAIT(w, return);
    pthread_mutex_lock(&impl->lock);
    w->signalled = 0;
    pthread_mutex_unlock(&impl->lock);
}

// (A wait does not depend on the implementation's memory: it may be freed
// after the implementation.)
static void free_call_wait(dThreadingImplementationID impl, dCallWaitID w)
{
    (void)impl;
    CHECK_WAIT(w, return);
    w->magic = DX_MAGIC_THREADING_DEAD;
    dFree(w, sizeof *w);
}

static void post_call(dThreadingImplementationID impl, int *out_summary_fault,
                      dCallReleaseeID *out_post_releasee, ddependencycount_t dependencies_count,
                      dCallReleaseeID dependent_releasee, dCallWaitID call_wait,
                      dThreadedCallFunction *call_func, void *call_context,
                      dcallindex_t instance_index, const char *call_name)
{
    (void)call_name;
    CHECK_IMPL(impl, return);
    DX_CHECK_ARG(call_func != NULL, return, "call_func is NULL");
    if (call_wait) CHECK_WAIT(call_wait, return);
    pthread_mutex_lock(&impl->lock);
    dxJob *dep = NULL;
    if (dependent_releasee) {
        dep = live_job(dependent_releasee);
        if (!dep) {
            pthread_mutex_unlock(&impl->lock);
            dxReportBadArgument(__func__, "dependent_releasee is not a pending call");
            return;
        }
    }
    dxJob *j = take_job(impl);
    j->magic = DX_MAGIC_CALL_JOB;
    j->dependent = dep;
    j->wait = call_wait;
    j->fault_out = out_summary_fault;
    j->fn = call_func;
    j->context = call_context;
    j->index = instance_index;
    j->deps = dependencies_count;
    j->started = 0;
    j->fault = 0;
    if (out_post_releasee) *out_post_releasee = (dCallReleaseeID)j;
    if (dependencies_count == 0) make_ready(impl, j);
    pthread_mutex_unlock(&impl->lock);
}

static void alter_call_dependencies_count(dThreadingImplementationID impl,
                                          dCallReleaseeID target, ddependencychange_t change)
{
    CHECK_IMPL(impl, return);
    pthread_mutex_lock(&impl->lock);
    dxJob *j = live_job(target);
    const char *bad = !j ? "target_releasee is not a pending call"
                      : change < 0 && (size_t)-change > j->deps
                          ? "dependencies_count_change takes the count below zero"
                          : NULL;
    if (bad) {
        pthread_mutex_unlock(&impl->lock);
        dxReportBadArgument(__func__, "%s", bad);
        return;
    }
    j->deps = (size_t)((ddependencychange_t)j->deps + change);
    if (j->deps == 0 && change != 0) {
        if (j->started) complete(impl, j);
        else make_ready(impl, j);
    }
    pthread_mutex_unlock(&impl->lock);
}

// The absolute time `timeout` from now (CLOCK_REALTIME, as pthread_cond_timedwait).
static struct timespec deadline_after(const dThreadedWaitTime *timeout)
{
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    t.tv_sec += timeout->wait_sec + (time_t)(timeout->wait_nsec / 1000000000ul);
    t.tv_nsec += (long)(timeout->wait_nsec % 1000000000ul);
    if (t.tv_nsec >= 1000000000l) {
        t.tv_sec++;
        t.tv_nsec -= 1000000000l;
    }
    return t;
}

static void wait_call(dThreadingImplementationID impl, int *out_wait_status, dCallWaitID w,
                      const dThreadedWaitTime *timeout, const char *wait_name)
{
    (void)wait_name;
    CHECK_IMPL(impl, return);
    CHECK_WAIT(w, return);
    struct timespec deadline;
    if (timeout) deadline = deadline_after(timeout);
    int status = 0, stuck = 0, timed_out = 0;
    pthread_mutex_lock(&impl->lock);
    for (;;) {
        if (w->signalled) {
            status = 1;
            break;
        }
        if (!is_multi(impl) && impl->ready_head) {   // self-threaded: the waiter runs calls
            run(impl, pop_ready(impl));
            continue;
        }
        if (timed_out) break;
        if (!is_multi(impl) && !timeout) {   // nothing left to run, and nobody else runs it
            stuck = 1;
            break;
        }
        if (timeout) timed_out = pthread_cond_timedwait(&impl->done, &impl->lock, &deadline) ==
                                 ETIMEDOUT;
        else pthread_cond_wait(&impl->done, &impl->lock);
    }
    pthread_mutex_unlock(&impl->lock);
    if (out_wait_status) *out_wait_status = status;
    if (stuck)
        dxReportBadArgument(__func__, "the call waited for has unreleased dependencies and the "
                            "self-threaded implementation has nothing left to run");
}

static unsigned retrieve_thread_count(dThreadingImplementationID impl)
{
    CHECK_IMPL(impl, return 0);
    if (!is_multi(impl)) return 0;
    pthread_mutex_lock(&impl->lock);
    const unsigned n = impl->serving;
    pthread_mutex_unlock(&impl->lock);
    return n;
}

static int preallocate_resources_for_calls(dThreadingImplementationID impl,
                                           ddependencycount_t estimate)
{
    CHECK_IMPL(impl, return 0);
    pthread_mutex_lock(&impl->lock);
    while (impl->free_count < estimate) add_free_job(impl);
    pthread_mutex_unlock(&impl->lock);
    return 1;
}

const dThreadingFunctionsInfo dx_threading_functions = {
    sizeof(dThreadingFunctionsInfo),
    alloc_mutex_group,
    free_mutex_group,
    lock_group_mutex,
    unlock_group_mutex,
    alloc_call_wait,
    reset_call_wait,
    free_call_wait,
    post_call,
    alter_call_dependencies_count,
    wait_call,
    retrieve_thread_count,
    preallocate_resources_for_calls,
};
