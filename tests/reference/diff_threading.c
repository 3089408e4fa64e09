// SPDX-License-Identifier: BSD-3-Clause
//
// diff_threading.c -- ODE 0.16's threading API against this library and the
// reference: thread counts of the implementations, the islands limit, fault
// summaries and wait statuses of posted calls, and three separate pendulums
// stepped with dWorldStep on a pool of 2 threads (they must move as without
// threads: 1e-6 after 300 steps, as diff_dynamics); the cooperative L D L^T
// factorisation and solve of a 70 x 70 matrix on the pool.

#include "diff_print.h"

static int ok_call(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)context;
    (void)index;
    (void)self;
    return 1;
}

static int failing_call(void *context, dcallindex_t index, dCallReleaseeID self)
{
    (void)context;
    (void)index;
    (void)self;
    return 0;
}

// (A self-threaded implementation of ODE 0.16 cannot wait with a timeout for
// a call that is not done: only `multi` looks before the release.)
static void calls(dThreadingImplementationID impl, const char *name, int multi)
{
    const dThreadingFunctionsInfo *f = dThreadingImplementationGetFunctions(impl);
    dCallWaitID wait = f->alloc_call_wait(impl);
    dCallReleaseeID top, held;
    int top_fault = -1, ok_fault = -1, status = -1, look = -1;
    const dThreadedWaitTime zero = { 0, 0 };
    f->post_call(impl, &top_fault, &top, 2, NULL, wait, ok_call, NULL, 0, "top");
    f->post_call(impl, &ok_fault, NULL, 0, top, NULL, ok_call, NULL, 1, "fine");
    f->post_call(impl, NULL, &held, 1, top, NULL, failing_call, NULL, 2, "fails, held");
    if (multi) f->wait_call(impl, &look, wait, &zero, "look");
    f->alter_call_dependencies_count(impl, held, -1);
    f->wait_call(impl, &status, wait, NULL, "all");
    printf("%s_faults 0 %d %d %d %d\n", name, top_fault, ok_fault, look, status);
    f->free_call_wait(impl, wait);
}

static void pendulums(dThreadingImplementationID impl)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b[3];
    for (int i = 0; i < 3; i++) {
        b[i] = dBodyCreate(w);
        dMass m;
        dMassSetSphereTotal(&m, 1 + i, 0.05);
        dBodySetMass(b[i], &m);
        dBodySetPosition(b[i], 2.0 * i + 0.5 + 0.1 * i, 0, -0.6);
        dJointID j = dJointCreateBall(w, 0);
        dJointAttach(j, b[i], 0);
        dJointSetBallAnchor(j, 2.0 * i, 0, 0);
        dBodySetLinearVel(b[i], 0, 0.3 * i, 0);
    }
    dWorldSetStepThreadingImplementation(w, dThreadingImplementationGetFunctions(impl), impl);
    printf("islands_max_threads 0 %u", dWorldGetStepIslandsProcessingMaxThreadCount(w));
    dWorldSetStepIslandsProcessingMaxThreadCount(w, 2);
    printf(" %u\n", dWorldGetStepIslandsProcessingMaxThreadCount(w));
    for (int s = 0; s < 300; s++) dWorldStep(w, 0.005);
    for (int i = 0; i < 3; i++)
        diff_values("threaded_pendulum_pos", 1e-6, dBodyGetPosition(b[i]), 3);
    dWorldSetStepThreadingImplementation(w, NULL, NULL);
    dWorldDestroy(w);
}

static void cooperative_ldlt(dThreadingImplementationID impl)
{
    enum { N = 70, SKIP = 72 };
    static dReal A[N * SKIP], d[N], b[N];
    for (int i = 0; i < N; i++) {
        b[i] = (dReal)((i % 7) - 3);
        for (int j = 0; j < N; j++)
            A[i * SKIP + j] = (dReal)(i == j ? N : 1.0 / (1 + i + j));   // diagonally dominant
    }
    dCooperativeID coop = dCooperativeCreate(dThreadingImplementationGetFunctions(impl), impl);
    dResourceRequirementsID rq = dResourceRequirementsCreate(coop);
    dEstimateCooperativelyFactorLDLTResourceRequirements(rq, 2, N);
    dEstimateCooperativelySolveLDLTResourceRequirements(rq, 2, N);
    dResourceContainerID rc = dResourceContainerAcquire(rq);
    dCooperativelyFactorLDLT(rc, 2, A, d, N, SKIP);
    dCooperativelySolveLDLT(rc, 2, A, d, b, N, SKIP);
    diff_values("coop_ldlt_d", 1e-12, d, N);
    diff_values("coop_ldlt_x", 1e-12, b, N);
    dResourceContainerDestroy(rc);
    dResourceRequirementsDestroy(rq);
    dCooperativeDestroy(coop);
}

int main(void)
{
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    dThreadingImplementationID self = dThreadingAllocateSelfThreadedImplementation();
    const dThreadingFunctionsInfo *f = dThreadingImplementationGetFunctions(self);
    printf("self_threaded_threads 0 %u\n", f->retrieve_thread_count(self));
    calls(self, "self_threaded", 0);
    dThreadingFreeImplementation(self);

    dThreadingImplementationID multi = dThreadingAllocateMultiThreadedImplementation();
    dThreadingThreadPoolID pool = dThreadingAllocateThreadPool(2, 0, dAllocateFlagBasicData, NULL);
    dThreadingThreadPoolServeMultiThreadedImplementation(pool, multi);
    printf("pool_threads 0 %u\n", f->retrieve_thread_count(multi));
    calls(multi, "multi_threaded", 1);
    pendulums(multi);
    cooperative_ldlt(multi);
    dThreadingImplementationShutdownProcessing(multi);
    dThreadingThreadPoolWaitIdleState(pool);
    printf("after_shutdown_threads 0 %u\n", f->retrieve_thread_count(multi));
    dThreadingFreeThreadPool(pool);
    dThreadingFreeImplementation(multi);
    dCloseODE();
    return 0;
}
