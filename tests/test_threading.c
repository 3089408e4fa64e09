// SPDX-License-Identifier: BSD-3-Clause
//
// test_threading.c -- the threading API of ODE 0.16: the task system behind
// the functions table (order, dependencies, sub-calls, waits, timeouts,
// faults), self- and multi-threaded implementations served by pools and by
// the program's own threads, clean shutdown; worlds stepped on 1 to 4 threads
// giving the single-threaded results to the bit (dWorldStep and
// dWorldQuickStep); the working-memory functions (memory manager,
// reservation policy, sharing, cleanup); bad input.
//
// Every wait here is bounded or on calls that can complete, so a broken
// implementation fails (or hits meson's timeout) instead of hanging forever.

#include "test.h"

#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

static const dThreadedWaitTime one_second = { 1, 0 };
static const dThreadedWaitTime zero_time = { 0, 0 };

// ---- the task system --------------------------------------------------

// A thread pool (the library must be initialised for its threads).
static dThreadingThreadPoolID new_pool(unsigned n, dsizeint stack, unsigned flags, void *reserved)
{
    dInitODE2(0);
    return dThreadingAllocateThreadPool(n, stack, flags, reserved);
}

#define LOG_MAX 64

typedef struct call_log {
    const dThreadingFunctionsInfo *f;
    dThreadingImplementationID impl;
    atomic_int n;
    int order[LOG_MAX];          // instance indices in the order they ran
    pthread_t thread[LOG_MAX];
    dMutexGroupID mutex;
    int counter;                 // incremented under mutex 0
} call_log;

static int record(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)self;
    call_log *log = context;
    int k = atomic_fetch_add(&log->n, 1);
    if (k < LOG_MAX) {
        log->order[k] = (int)index;
        log->thread[k] = pthread_self();
    }
    return 1;
}

static int fail(void *context, dcallindex_t index, dCallReleaseeID self)
{
    record(context, index, self);
    return 0;
}

static void log_init(call_log *log, dThreadingImplementationID impl)
{
    memset(log, 0, sizeof *log);
    log->impl = impl;
    log->f = dThreadingImplementationGetFunctions(impl);
}

// Self-threaded: nothing runs until the wait; then calls run on the waiting
// thread in the order they became ready, and a call posted with a
// dependency runs after the call that releases it.
static int test_self_threaded_runs_calls_in_order_on_the_waiter(void)
{
    dThreadingImplementationID impl = dThreadingAllocateSelfThreadedImplementation();
    call_log log;
    log_init(&log, impl);
    const dThreadingFunctionsInfo *f = log.f;
    dCallWaitID wait = f->alloc_call_wait(impl);
    dCallReleaseeID last;
    int fault = -1, status = -1;

    f->post_call(impl, &fault, &last, 1, NULL, wait, record, &log, 9, "last");
    for (int i = 0; i < 3; i++) f->post_call(impl, NULL, NULL, 0, NULL, NULL, record, &log, i, 0);
    f->post_call(impl, NULL, NULL, 0, last, NULL, record, &log, 3, "releases last");
    CHECK(atomic_load(&log.n) == 0);
    f->wait_call(impl, &status, wait, NULL, "test");

    CHECK(status == 1);
    CHECK(fault == 0);
    CHECK(atomic_load(&log.n) == 5);
    const int expect[5] = { 0, 1, 2, 3, 9 };
    for (int i = 0; i < 5; i++) CHECK(log.order[i] == expect[i]);
    CHECK(pthread_equal(log.thread[4], pthread_self()));
    CHECK(f->retrieve_thread_count(impl) == 0);
    f->free_call_wait(impl, wait);
    dThreadingFreeImplementation(impl);
    return 0;
}

// A call that posts sub-calls and waits for them through its own releasee:
// its wait is signalled only once they have completed too.
typedef struct fork_join {
    call_log *log;
    int subcalls;
} fork_join;

static int fork_calls(void *context, dcallindex_t index, dCallReleaseeID self)
{
    fork_join *fj = context;
    const dThreadingFunctionsInfo *f = fj->log->f;
    f->alter_call_dependencies_count(fj->log->impl, self, fj->subcalls);
    for (int i = 0; i < fj->subcalls; i++)
        f->post_call(fj->log->impl, NULL, NULL, 0, self, NULL, record, fj->log,
                     (dcallindex_t)(100 + i), "sub-call");
    return record(fj->log, index, self);
}

static int check_fork_join(dThreadingImplementationID impl)
{
    call_log log;
    log_init(&log, impl);
    fork_join fj = { &log, 8 };
    dCallWaitID wait = log.f->alloc_call_wait(impl);
    int status = 0, fault = -1;

    log.f->post_call(impl, &fault, NULL, 0, NULL, wait, fork_calls, &fj, 1, "fork");
    log.f->wait_call(impl, &status, wait, NULL, "join");

    CHECK(status == 1);
    CHECK(fault == 0);
    CHECK(atomic_load(&log.n) == 9);   // the fork and its 8 sub-calls, all done
    log.f->free_call_wait(impl, wait);
    return 0;
}

static int test_subcalls_complete_before_their_parent(void)
{
    dThreadingImplementationID self = dThreadingAllocateSelfThreadedImplementation();
    CHECK(check_fork_join(self) == 0);
    dThreadingFreeImplementation(self);

    dThreadingImplementationID multi = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = new_pool(3, 0, dAllocateFlagBasicData, 0);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, multi);
    for (int i = 0; i < 20; i++) CHECK(check_fork_join(multi) == 0);
    dThreadingImplementationShutdownProcessing(multi);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(multi);
    return 0;
}

// A call that returns 0 faults; the fault reaches the summary of the call it
// releases, and of that call's dependent in turn.
static int test_faults_reach_the_summary_of_dependents(void)
{
    dThreadingImplementationID impl = dThreadingAllocateSelfThreadedImplementation();
    call_log log;
    log_init(&log, impl);
    const dThreadingFunctionsInfo *f = log.f;
    dCallWaitID wait = f->alloc_call_wait(impl);
    dCallReleaseeID top, middle;
    int top_fault = -1, middle_fault = -1, ok_fault = -1, status = 0;

    f->post_call(impl, &top_fault, &top, 1, NULL, wait, record, &log, 0, "top");
    f->post_call(impl, &middle_fault, &middle, 2, top, NULL, record, &log, 1, "middle");
    f->post_call(impl, &ok_fault, NULL, 0, middle, NULL, record, &log, 2, "fine");
    f->post_call(impl, NULL, NULL, 0, middle, NULL, fail, &log, 3, "fails");
    f->wait_call(impl, &status, wait, NULL, "test");

    CHECK(status == 1);
    CHECK(ok_fault == 0);
    CHECK(middle_fault == 1);
    CHECK(top_fault == 1);
    CHECK(atomic_load(&log.n) == 4);

    // A new call on the reset wait starts clean.
    f->reset_call_wait(impl, wait);
    f->post_call(impl, &top_fault, NULL, 0, NULL, wait, record, &log, 4, "again");
    f->wait_call(impl, &status, wait, NULL, "test");
    CHECK(top_fault == 0);
    f->free_call_wait(impl, wait);
    dThreadingFreeImplementation(impl);
    return 0;
}

// A wait times out on a call whose dependency is not released, and succeeds
// once it is (multi-threaded: a pool thread runs it).
static int test_wait_times_out_until_the_dependency_is_released(void)
{
    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = new_pool(2, 0, dAllocateFlagBasicData, 0);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
    call_log log;
    log_init(&log, impl);
    const dThreadingFunctionsInfo *f = log.f;
    dCallWaitID wait = f->alloc_call_wait(impl);
    dCallReleaseeID held;
    const dThreadedWaitTime short_time = { 0, 20 * 1000 * 1000 };
    int status = -1;

    f->post_call(impl, NULL, &held, 1, NULL, wait, record, &log, 7, "held");
    f->wait_call(impl, &status, wait, &zero_time, "look");
    CHECK(status == 0);
    f->wait_call(impl, &status, wait, &short_time, "20 ms");
    CHECK(status == 0);
    CHECK(atomic_load(&log.n) == 0);

    f->alter_call_dependencies_count(impl, held, -1);
    f->wait_call(impl, &status, wait, &one_second, "released");
    CHECK(status == 1);
    CHECK(atomic_load(&log.n) == 1);
    CHECK(!pthread_equal(log.thread[0], pthread_self()));   // a pool thread ran it
    CHECK(f->retrieve_thread_count(impl) == 2);

    f->free_call_wait(impl, wait);
    dThreadingImplementationShutdownProcessing(impl);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(impl);
    return 0;
}

// Many calls on four threads, each incrementing a counter under a mutex of
// the implementation's mutex group: every call runs once.
static int count_under_mutex(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)index;
    (void)self;
    call_log *log = context;
    log->f->lock_group_mutex(log->impl, log->mutex, 1);
    log->counter++;
    log->f->unlock_group_mutex(log->impl, log->mutex, 1);
    return 1;
}

static int test_pool_threads_run_every_call_once(void)
{
    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = new_pool(4, 256 * 1024, 0, 0);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
    call_log log;
    log_init(&log, impl);
    const dThreadingFunctionsInfo *f = log.f;
    log.mutex = f->alloc_mutex_group(impl, 2, NULL);
    dCallWaitID wait = f->alloc_call_wait(impl);
    dCallReleaseeID done;
    const int n = 2000;
    int status = 0;

    CHECK(f->preallocate_resources_for_calls(impl, 64) == 1);
    f->post_call(impl, NULL, &done, (size_t)n, NULL, wait, record, &log, 0, "done");
    for (int i = 0; i < n; i++)
        f->post_call(impl, NULL, NULL, 0, done, NULL, count_under_mutex, &log, (size_t)i, 0);
    f->wait_call(impl, &status, wait, NULL, "all");

    CHECK(status == 1);
    CHECK(log.counter == n);
    f->free_call_wait(impl, wait);
    f->free_mutex_group(impl, log.mutex);
    dThreadingImplementationShutdownProcessing(impl);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(impl);
    return 0;
}

// The program's own thread serves an implementation until it is shut down.
typedef struct external {
    dThreadingImplementationID impl;
    atomic_int ready;
} external;

static void external_ready(void *context) { atomic_store(&((external *)context)->ready, 1); }

static void *external_main(void *context)
{
    external *e = context;
    dExternalThreadingServeMultiThreadedImplementation(e->impl, external_ready, e);
    return NULL;
}

static int test_external_thread_serves_until_shutdown(void)
{
    external e = { dThreadingAllocateMultiThreadedImplementation(), 0 };
    pthread_t thread;
    pthread_create(&thread, NULL, external_main, &e);
    while (!atomic_load(&e.ready)) sched_yield();
    call_log log;
    log_init(&log, e.impl);
    dCallWaitID wait = log.f->alloc_call_wait(e.impl);
    int status = 0;

    CHECK(log.f->retrieve_thread_count(e.impl) == 1);
    log.f->post_call(e.impl, NULL, NULL, 0, NULL, wait, record, &log, 5, "on the thread");
    log.f->wait_call(e.impl, &status, wait, &one_second, "test");
    CHECK(status == 1);
    CHECK(pthread_equal(log.thread[0], thread));

    dThreadingImplementationShutdownProcessing(e.impl);
    pthread_join(thread, NULL);   // it returned: no hang
    CHECK(log.f->retrieve_thread_count(e.impl) == 0);
    log.f->free_call_wait(e.impl, wait);
    dThreadingFreeImplementation(e.impl);
    return 0;
}

// A pool goes idle on shutdown, and serves again after a restart; freeing
// everything gives back every byte (counted through the allocation handlers).
static atomic_long bytes_out;

static void *counted_alloc(dsizeint size)
{
    atomic_fetch_add(&bytes_out, (long)size);
    return malloc(size ? size : 1);
}

static void counted_free(void *p, dsizeint size)
{
    atomic_fetch_sub(&bytes_out, (long)size);
    free(p);
}

static int test_pool_restarts_and_everything_is_freed(void)
{
    dInitODE2(0);   // (runs first of the pool tests: nothing else keeps the library open)
    dCloseODE();    // gives back the pooled blocks of earlier tests
    dInitODE2(0);
    atomic_store(&bytes_out, 0);
    dSetAllocHandler(counted_alloc);
    dSetFreeHandler(counted_free);
    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = dThreadingAllocateThreadPool(2, 0, dAllocateMaskAll, 0);
    call_log log;
    log_init(&log, impl);
    dCallWaitID wait = log.f->alloc_call_wait(impl);
    int status = 0;

    for (int round = 0; round < 3; round++) {
        dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
        CHECK(log.f->retrieve_thread_count(impl) == 2);
        log.f->reset_call_wait(impl, wait);
        log.f->post_call(impl, NULL, NULL, 0, NULL, wait, record, &log, (size_t)round, 0);
        log.f->wait_call(impl, &status, wait, &one_second, "round");
        CHECK(status == 1);
        dThreadingImplementationShutdownProcessing(impl);
        dThreadingThreadPoolWaitIdleState(pool);
        CHECK(log.f->retrieve_thread_count(impl) == 0);
        dThreadingImplementationCleanupForRestart(impl);
    }
    CHECK(atomic_load(&log.n) == 3);
    log.f->free_call_wait(impl, wait);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(impl);
    dCloseODE();   // the pooled handles go back too

    dSetAllocHandler(NULL);
    dSetFreeHandler(NULL);
    if (atomic_load(&bytes_out) != 0)
        test_fail(__FILE__, __LINE__, "%ld bytes not freed", (long)atomic_load(&bytes_out));
    CHECK(atomic_load(&bytes_out) == 0);
    return 0;
}

// ---- bad input ---------------------------------------------------------

static int test_bad_handles_are_reported(void)
{
    test_capture_reports();
    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    const dThreadingFunctionsInfo *f = dThreadingImplementationGetFunctions(impl);
    dThreadingFreeImplementation(impl);
    dWorldID w = dWorldCreate();

    dThreadingImplementationShutdownProcessing(impl);
    CHECK(test_captured_count() == 1 && test_captured_contains("was freed"));
    f->post_call(impl, NULL, NULL, 0, NULL, NULL, record, NULL, 0, 0);
    CHECK(test_captured_count() == 2);
    CHECK(dThreadingImplementationGetFunctions(NULL) == NULL);
    CHECK(test_captured_count() == 3);
    dWorldSetStepThreadingImplementation(w, f, NULL);
    CHECK(test_captured_count() == 4 && test_captured_contains("threading_impl is NULL"));
    dWorldSetStepThreadingImplementation(w, f, impl);
    CHECK(test_captured_count() == 5);
    dThreadingFreeImplementation(impl);
    CHECK(test_captured_count() == 6);
    CHECK(dThreadingAllocateThreadPool(0, 0, 0, NULL) == NULL);
    CHECK(test_captured_count() == 7 && test_captured_contains("thread_count"));
    dThreadingFreeThreadPool(NULL);
    CHECK(test_captured_count() == 8);

    // A self-threaded implementation cannot be served by threads, and a wait
    // for a call that nothing can release is reported instead of hanging.
    dThreadingImplementationID self = dThreadingAllocateSelfThreadedImplementation();
    dExternalThreadingServeMultiThreadedImplementation(self, NULL, NULL);
    CHECK(test_captured_count() == 9 && test_captured_contains("self-threaded"));
    dCallWaitID wait = f->alloc_call_wait(self);
    int status = -1;
    f->post_call(self, NULL, NULL, 1, NULL, wait, record, NULL, 0, "never released");
    f->wait_call(self, &status, wait, NULL, "forever");
    CHECK(status == 0);
    CHECK(test_captured_count() == 10 && test_captured_contains("nothing left to run"));
    f->free_call_wait(self, wait);
    dThreadingFreeImplementation(self);
    dWorldDestroy(w);
    return 0;
}

// A world whose implementation was freed (without unassigning it) reports
// it and steps on the caller's thread.
static int test_a_freed_implementation_is_reported_by_the_step(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dBodyID first = NULL;
    for (int i = 0; i < 2; i++) {
        dBodyID b = dBodyCreate(w);
        dBodySetPosition(b, i, 0, 0);
        dBodySetLinearVel(b, 1, 0, 0);
        if (!first) first = b;
    }
    dThreadingImplementationID impl = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(w, dThreadingImplementationGetFunctions(impl), impl);
    dThreadingFreeImplementation(impl);

    CHECK(dWorldStep(w, 0.1) == 1);
    CHECK(test_captured_count() == 1 && test_captured_contains("dWorldStep: the world's"));
    CHECK_NEAR(dBodyGetPosition(first)[0], 0.1, TOL(1e-12, 1e-6));
    CHECK(dWorldQuickStep(w, 0.1) == 1);
    CHECK(test_captured_count() == 2 && test_captured_contains("dWorldQuickStep: the world's"));
    CHECK_NEAR(dBodyGetPosition(first)[0], 0.2, TOL(1e-12, 1e-6));
    dWorldSetStepThreadingImplementation(w, NULL, NULL);
    dWorldDestroy(w);
    return 0;
}

// ---- worlds stepped on threads -------------------------------------------

#define CHAINS 20
#define LINKS 5

typedef struct scene {
    dWorldID w;
    dJointGroupID contacts;
    dBodyID body[CHAINS][LINKS];
} scene;

// 20 separate chains of 5 spheres (radius 0.25) joined by ball and hinge
// joints, some hanging from the static world, thrown at different speeds
// onto the ground z = 0, with one chain joined to its neighbour at a
// distance.
static void scene_build(scene *s)
{
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, -9.81);
    s->contacts = dJointGroupCreate(0);
    for (int c = 0; c < CHAINS; c++) {
        for (int k = 0; k < LINKS; k++) {
            dBodyID b = dBodyCreate(s->w);
            dMass m;
            dMassSetSphere(&m, 1 + 0.1 * k, 0.25);
            dBodySetMass(b, &m);
            dBodySetPosition(b, 3.0 * c + 0.45 * k, 0.1 * k, 1.0 + 0.2 * (c % 3) + 0.05 * k);
            dBodySetLinearVel(b, 0.3 * (c % 4) - 0.5, 0.2 * (c % 5) - 0.4, 0.5 * (c % 2));
            dBodySetAngularVel(b, 0.1 * c, -0.2 * k, 0.3);
            s->body[c][k] = b;
            if (k == 0) {
                if (c % 4 == 0) {   // hangs from the world
                    dJointID j = dJointCreateBall(s->w, 0);
                    dJointAttach(j, b, 0);
                    dJointSetBallAnchor(j, 3.0 * c - 0.3, 0, 1.6);
                }
                continue;
            }
            dBodyID prev = s->body[c][k - 1];
            const dReal *p = dBodyGetPosition(prev), *q = dBodyGetPosition(b);
            dJointID j;
            if (k % 2) {
                j = dJointCreateBall(s->w, 0);
                dJointAttach(j, prev, b);
                dJointSetBallAnchor(j, (p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2);
            } else {
                j = dJointCreateHinge(s->w, 0);
                dJointAttach(j, prev, b);
                dJointSetHingeAnchor(j, (p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2);
                dJointSetHingeAxis(j, 0, 1, 0);
                dJointSetHingeParam(j, dParamLoStop, -0.5);
                dJointSetHingeParam(j, dParamHiStop, 0.5);
            }
        }
    }
    dJointID far = dJointCreateBall(s->w, 0);   // chains 6 and 7 make one island
    dJointAttach(far, s->body[6][LINKS - 1], s->body[7][0]);
    dJointSetBallAnchor(far, 3.0 * 6 + 2.5, 0, 1.2);
}

// Contacts of every sphere with the ground, from the bodies' state only.
static void scene_contacts(scene *s)
{
    dJointGroupEmpty(s->contacts);
    for (int c = 0; c < CHAINS; c++) {
        for (int k = 0; k < LINKS; k++) {
            const dReal *p = dBodyGetPosition(s->body[c][k]);
            if (p[2] > 0.25) continue;
            dContact ct;
            memset(&ct, 0, sizeof ct);
            ct.surface.mode = dContactApprox1 | dContactBounce;
            ct.surface.mu = 0.6;
            ct.surface.bounce = 0.2;
            ct.geom.pos[0] = p[0];
            ct.geom.pos[1] = p[1];
            ct.geom.normal[2] = 1;
            ct.geom.depth = 0.25 - p[2];
            dJointAttach(dJointCreateContact(s->w, s->contacts, &ct), s->body[c][k], 0);
        }
    }
}

// The state of every body, as bytes.
typedef struct state {
    dReal v[CHAINS * LINKS][13];
} state;

static void scene_state(const scene *s, state *out)
{
    memset(out, 0, sizeof *out);
    for (int c = 0; c < CHAINS; c++) {
        for (int k = 0; k < LINKS; k++) {
            dBodyID b = s->body[c][k];
            dReal *v = out->v[c * LINKS + k];
            memcpy(v, dBodyGetPosition(b), 3 * sizeof(dReal));
            memcpy(v + 3, dBodyGetQuaternion(b), 4 * sizeof(dReal));
            memcpy(v + 7, dBodyGetLinearVel(b), 3 * sizeof(dReal));
            memcpy(v + 10, dBodyGetAngularVel(b), 3 * sizeof(dReal));
        }
    }
}

static void scene_run(scene *s, int quick, int steps)
{
    for (int i = 0; i < steps; i++) {
        scene_contacts(s);
        if (quick) dWorldQuickStep(s->w, 0.01);
        else dWorldStep(s->w, 0.01);
    }
}

static void scene_destroy(scene *s)
{
    dJointGroupDestroy(s->contacts);
    dWorldDestroy(s->w);
}

// The scene stepped `steps` times with no implementation, then with pools of
// 1 to 4 threads (and a self-threaded implementation, and a limit of 2
// island threads on a pool of 4): the same bits every time.
static int check_bit_identical(int quick, int steps)
{
    static state reference, threaded;
    scene s;
    scene_build(&s);
    scene_run(&s, quick, steps);
    scene_state(&s, &reference);
    const dReal z = reference.v[LINKS * 3 + 2][2];
    scene_destroy(&s);
    CHECK(z < 0.3 && z > 0.15);   // chain 3 lies on the ground

    for (int threads = 0; threads <= 5; threads++) {
        dThreadingImplementationID impl =
            threads == 0 ? dThreadingAllocateSelfThreadedImplementation()
                         : dThreadingAllocateMultiThreadedImplementation();
        const int pool_threads = threads == 5 ? 4 : threads;
        dThreadingThreadPoolID pool = NULL;
        if (threads > 0) {
            pool = new_pool((unsigned)pool_threads, 0, 0, NULL);
            dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
        }
        scene_build(&s);
        dWorldSetStepThreadingImplementation(s.w, dThreadingImplementationGetFunctions(impl),
                                             impl);
        if (threads == 5) dWorldSetStepIslandsProcessingMaxThreadCount(s.w, 2);
        scene_run(&s, quick, steps);
        scene_state(&s, &threaded);
        dWorldSetStepThreadingImplementation(s.w, NULL, NULL);
        scene_destroy(&s);
        if (pool) {
            dThreadingImplementationShutdownProcessing(impl);
            dThreadingFreeThreadPool(pool);
        }
        dThreadingFreeImplementation(impl);
        if (memcmp(&reference, &threaded, sizeof reference) != 0) {
            test_fail(__FILE__, __LINE__, "%s with %d threads differs",
                      quick ? "QuickStep" : "Step", threads);
            return 1;
        }
    }
    return 0;
}

static int test_step_on_threads_is_bit_identical(void) { return check_bit_identical(0, 150); }

static int test_quickstep_on_threads_is_bit_identical(void)
{
    return check_bit_identical(1, 150);
}

// After warming up, a threaded step allocates nothing, whichever thread
// takes which island.
static int test_warm_threaded_step_allocates_nothing(void)
{
    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = new_pool(3, 0, 0, NULL);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
    scene s;
    scene_build(&s);
    dWorldSetStepThreadingImplementation(s.w, dThreadingImplementationGetFunctions(impl), impl);
    for (int i = 0; i < 3; i++) dWorldStep(s.w, 0.01), dWorldQuickStep(s.w, 0.01);

    test_count_allocations();
    for (int i = 0; i < 5; i++) dWorldStep(s.w, 0.01), dWorldQuickStep(s.w, 0.01);
    const int n = test_allocations_counted();

    CHECK(n == 0);
    dWorldSetStepThreadingImplementation(s.w, NULL, NULL);
    scene_destroy(&s);
    dThreadingImplementationShutdownProcessing(impl);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(impl);
    return 0;
}

static int test_islands_thread_limit_is_kept(void)
{
    dWorldID w = dWorldCreate();
    CHECK(dWorldGetStepIslandsProcessingMaxThreadCount(w) == dWORLDSTEP_THREADCOUNT_UNLIMITED);
    dWorldSetStepIslandsProcessingMaxThreadCount(w, 3);
    CHECK(dWorldGetStepIslandsProcessingMaxThreadCount(w) == 3);
    dWorldDestroy(w);
    return 0;
}

// ---- working memory ------------------------------------------------------

static atomic_int blocks_allocated, blocks_freed;
static atomic_long block_bytes, largest_block;

static void *manager_alloc(dsizeint size)
{
    atomic_fetch_add(&blocks_allocated, 1);
    atomic_fetch_add(&block_bytes, (long)size);
    if ((long)size > atomic_load(&largest_block)) atomic_store(&largest_block, (long)size);
    return malloc(size);
}

static void *manager_shrink(void *p, dsizeint size, dsizeint smaller)
{
    (void)size;
    (void)smaller;
    return p;
}

static void manager_free(void *p, dsizeint size)
{
    atomic_fetch_add(&blocks_freed, 1);
    atomic_fetch_sub(&block_bytes, (long)size);
    free(p);
}

static const dWorldStepMemoryFunctionsInfo manager = {
    sizeof(dWorldStepMemoryFunctionsInfo), manager_alloc, manager_shrink, manager_free
};

static void reset_manager_counts(void)
{
    atomic_store(&blocks_allocated, 0);
    atomic_store(&blocks_freed, 0);
    atomic_store(&block_bytes, 0);
    atomic_store(&largest_block, 0);
}

// The step's memory comes from the manager (also on threads), with the
// reservation policy's minimum; cleanup and destroy give it all back.
static int test_memory_manager_and_policy_are_used(void)
{
    reset_manager_counts();
    scene s;
    scene_build(&s);
    const dWorldStepReserveInfo policy = { sizeof policy, 1.5f, 1 << 20 };
    CHECK(dWorldSetStepMemoryManager(s.w, &manager) == 1);
    CHECK(dWorldSetStepMemoryReservationPolicy(s.w, &policy) == 1);

    scene_run(&s, 0, 3);
    CHECK(atomic_load(&blocks_allocated) >= 1);
    CHECK(atomic_load(&largest_block) >= 1 << 20);

    dThreadingImplementationID impl = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = new_pool(2, 0, 0, NULL);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, impl);
    dWorldSetStepThreadingImplementation(s.w, dThreadingImplementationGetFunctions(impl), impl);
    const int before = atomic_load(&blocks_allocated);
    scene_run(&s, 0, 3);
    CHECK(atomic_load(&blocks_allocated) >= before + 2);   // the two threads' arenas

    dWorldCleanupWorkingMemory(s.w);
    CHECK(atomic_load(&block_bytes) == 0);
    CHECK(atomic_load(&blocks_freed) == atomic_load(&blocks_allocated));
    scene_run(&s, 0, 2);   // and it steps again
    CHECK(atomic_load(&block_bytes) > 0);
    dWorldSetStepThreadingImplementation(s.w, NULL, NULL);
    scene_destroy(&s);
    CHECK(atomic_load(&block_bytes) == 0);
    dThreadingImplementationShutdownProcessing(impl);
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(impl);
    return 0;
}

// Two worlds sharing one working memory, stepped alternately, move exactly
// as two worlds with their own; the second uses the first's manager.
static int test_shared_working_memory_steps_alternately(void)
{
    static state alone[2], shared[2];
    scene s[2];
    for (int k = 0; k < 2; k++) {
        scene_build(&s[k]);
        scene_run(&s[k], k, 60);
        scene_state(&s[k], &alone[k]);
        scene_destroy(&s[k]);
    }
    reset_manager_counts();
    scene_build(&s[0]);
    scene_build(&s[1]);
    CHECK(dWorldSetStepMemoryManager(s[0].w, &manager) == 1);
    CHECK(dWorldUseSharedWorkingMemory(s[1].w, s[0].w) == 1);
    for (int i = 0; i < 60; i++) {
        scene_run(&s[1], 1, 1);   // the second world first: it brings the memory in
        scene_run(&s[0], 0, 1);
    }
    const int allocated = atomic_load(&blocks_allocated);
    for (int k = 0; k < 2; k++) scene_state(&s[k], &shared[k]);

    CHECK(allocated >= 1);
    CHECK(memcmp(&alone[0], &shared[0], sizeof alone[0]) == 0);
    CHECK(memcmp(&alone[1], &shared[1], sizeof alone[1]) == 0);
    scene_destroy(&s[0]);   // the second world keeps the memory
    CHECK(atomic_load(&block_bytes) > 0);
    scene_run(&s[1], 0, 1);
    CHECK(dWorldUseSharedWorkingMemory(s[1].w, NULL) == 1);   // leaves: memory freed
    CHECK(atomic_load(&block_bytes) == 0);
    scene_destroy(&s[1]);
    return 0;
}

static int test_bad_working_memory_input_is_reported(void)
{
    test_capture_reports();
    dWorldID a = dWorldCreate(), b = dWorldCreate();
    const dWorldStepReserveInfo bad_factor = { sizeof bad_factor, 0.5f, 0 };
    dWorldStepMemoryFunctionsInfo no_free = manager;
    no_free.free_block = NULL;

    CHECK(dWorldSetStepMemoryReservationPolicy(a, &bad_factor) == 0);
    CHECK(test_captured_count() == 1 && test_captured_contains("reserve_factor"));
    CHECK(dWorldSetStepMemoryManager(a, &no_free) == 0);
    CHECK(test_captured_count() == 2);
    dWorldStep(b, 0.01);   // b has memory of its own now
    CHECK(dWorldUseSharedWorkingMemory(b, a) == 0);
    CHECK(test_captured_count() == 3 && test_captured_contains("of its own"));
    CHECK(dWorldUseSharedWorkingMemory(b, NULL) == 1);   // after leaving it, b may share
    CHECK(dWorldUseSharedWorkingMemory(b, a) == 1);
    CHECK(dWorldUseSharedWorkingMemory(a, a) == 0);
    CHECK(test_captured_count() == 4);
    CHECK(dWorldSetStepMemoryReservationPolicy(a, NULL) == 1);
    CHECK(dWorldSetStepMemoryManager(a, NULL) == 1);
    dWorldDestroy(a);
    dWorldDestroy(b);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_self_threaded_runs_calls_in_order_on_the_waiter),
    TEST_CASE(test_pool_restarts_and_everything_is_freed),
    TEST_CASE(test_subcalls_complete_before_their_parent),
    TEST_CASE(test_faults_reach_the_summary_of_dependents),
    TEST_CASE(test_wait_times_out_until_the_dependency_is_released),
    TEST_CASE(test_pool_threads_run_every_call_once),
    TEST_CASE(test_external_thread_serves_until_shutdown),
    TEST_CASE(test_bad_handles_are_reported),
    TEST_CASE(test_a_freed_implementation_is_reported_by_the_step),
    TEST_CASE(test_step_on_threads_is_bit_identical),
    TEST_CASE(test_quickstep_on_threads_is_bit_identical),
    TEST_CASE(test_warm_threaded_step_allocates_nothing),
    TEST_CASE(test_islands_thread_limit_is_kept),
    TEST_CASE(test_memory_manager_and_policy_are_used),
    TEST_CASE(test_shared_working_memory_steps_alternately),
    TEST_CASE(test_bad_working_memory_input_is_reported),
    TEST_END
};
