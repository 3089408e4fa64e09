// SPDX-License-Identifier: BSD-3-Clause
//
// test_matrix_coop.c -- the cooperative matrix functions of ODE 0.16
// (matrix_coop.h, cooperative.h): on random symmetric positive definite
// matrices of sizes around the block size, with tight and loose row skips,
// they give matrix.h's dFactorLDLT, dSolveLDLT, dSolveL1, dSolveL1T and
// dScaleVector results to the bit, on no threads, a self-threaded
// implementation and pools of 2 and 3 threads; the solution satisfies
// A x = b; the requirements objects; bad input.

#include "test.h"

#include <stdlib.h>
#include <string.h>

#define MAXN 140

typedef struct setup {
    dThreadingImplementationID impl;
    dThreadingThreadPoolID pool;
    dCooperativeID coop;
    dResourceContainerID rc;
} setup;

// kind 0: no threading; 1: self-threaded; 2, 3: a pool of that many threads.
static void setup_make(setup *s, int kind, unsigned threads)
{
    memset(s, 0, sizeof *s);
    if (kind == 1) s->impl = dThreadingAllocateSelfThreadedImplementation();
    if (kind >= 2) {
        dInitODE2(0);
        s->impl = dThreadingAllocateMultiThreadedImplementation();
        s->pool = dThreadingAllocateThreadPool((unsigned)kind, 0, 0, NULL);
        dThreadingThreadPoolServeMultiThreadedImplementation(s->pool, s->impl);
    }
    s->coop = dCooperativeCreate(s->impl ? dThreadingImplementationGetFunctions(s->impl) : NULL,
                                 s->impl);
    dResourceRequirementsID a = dResourceRequirementsCreate(s->coop);
    dResourceRequirementsID b = dResourceRequirementsCreate(s->coop);
    dEstimateCooperativelyFactorLDLTResourceRequirements(a, threads, MAXN);
    dEstimateCooperativelySolveLDLTResourceRequirements(b, threads, MAXN);
    dEstimateCooperativelySolveL1StraightResourceRequirements(b, threads, MAXN);
    dEstimateCooperativelySolveL1TransposedResourceRequirements(b, threads, MAXN);
    dEstimateCooperativelyScaleVectorResourceRequirements(b, threads, MAXN);
    dResourceRequirementsMergeIn(a, b);
    dResourceRequirementsDestroy(b);
    s->rc = dResourceContainerAcquire(a);
    dResourceRequirementsDestroy(a);   // the container does not need them
}

static void setup_free(setup *s)
{
    dResourceContainerDestroy(s->rc);
    dCooperativeDestroy(s->coop);
    if (s->pool) {
        dThreadingImplementationShutdownProcessing(s->impl);
        dThreadingFreeThreadPool(s->pool);
    }
    if (s->impl) dThreadingFreeImplementation(s->impl);
}

// A = M M^T + n I (symmetric positive definite), row skip `skip`, the padding
// filled with a value that must not be read into results.
static void random_spd(dReal *A, int n, int skip)
{
    static dReal M[MAXN * MAXN];
    for (int i = 0; i < n * n; i++) M[i] = (dReal)(dRandReal() * 2 - 1);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < skip; j++) {
            dReal s = 0;
            if (j < n) {
                for (int k = 0; k < n; k++) s += M[i * n + k] * M[j * n + k];
                if (i == j) s += n;
            } else {
                s = 12345;
            }
            A[i * skip + j] = s;
        }
    }
}

static int same(const dReal *a, const dReal *b, int n)
{
    return memcmp(a, b, sizeof(dReal) * (size_t)n) == 0;
}

// Every function against matrix.h for one size and row skip, on one setup.
static int check_size(setup *s, unsigned threads, int n, int skip)
{
    static dReal A[MAXN * (MAXN + 8)], L[MAXN * (MAXN + 8)], L2[MAXN * (MAXN + 8)];
    static dReal d[MAXN], d2[MAXN], b[MAXN], x[MAXN], y[MAXN];
    random_spd(A, n, skip);
    for (int i = 0; i < n; i++) b[i] = (dReal)(dRandReal() * 2 - 1);
    memcpy(L, A, sizeof(dReal) * (size_t)(n * skip));
    memcpy(L2, A, sizeof(dReal) * (size_t)(n * skip));

    dFactorLDLT(L, d, n, skip);
    dCooperativelyFactorLDLT(s->rc, threads, L2, d2, (unsigned)n, (unsigned)skip);
    CHECK(same(L, L2, n * skip));
    CHECK(same(d, d2, n));

    memcpy(x, b, sizeof b);
    memcpy(y, b, sizeof b);
    dSolveLDLT(L, d, x, n, skip);
    dCooperativelySolveLDLT(s->rc, threads, L, d, y, (unsigned)n, (unsigned)skip);
    CHECK(same(x, y, n));
    for (int i = 0; i < n; i++) {   // A x = b, A from its lower triangle
        double r = b[i];
        for (int j = 0; j < n; j++) r -= (double)A[i >= j ? i * skip + j : j * skip + i] * x[j];
        CHECK_NEAR(r, 0, TOL(1e-10, 1e-3));
    }

    memcpy(x, b, sizeof b);
    memcpy(y, b, sizeof b);
    dSolveL1(L, x, n, skip);
    dCooperativelySolveL1Straight(s->rc, threads, L, y, (unsigned)n, (unsigned)skip);
    CHECK(same(x, y, n));
    dSolveL1T(L, x, n, skip);
    dCooperativelySolveL1Transposed(s->rc, threads, L, y, (unsigned)n, (unsigned)skip);
    CHECK(same(x, y, n));
    dScaleVector(x, d, n);
    dCooperativelyScaleVector(s->rc, threads, y, d, (unsigned)n);
    CHECK(same(x, y, n));
    return 0;
}

static int check_kind(int kind)
{
    static const int sizes[] = { 0, 1, 5, 31, 32, 33, 64, 70, 97, MAXN };
    setup s;
    setup_make(&s, kind, 4);
    dRandSetSeed(17);
    for (unsigned k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        const int n = sizes[k];
        for (unsigned threads = 1; threads <= 4; threads += 3) {
            if (check_size(&s, threads, n, dPAD(n)) || check_size(&s, threads, n, n + 5)) {
                test_fail(__FILE__, __LINE__, "n %d, threads %u, setup %d", n, threads, kind);
                setup_free(&s);
                return 1;
            }
        }
    }
    setup_free(&s);
    return 0;
}

static int test_without_threading_results_are_matrix_h_results(void) { return check_kind(0); }
static int test_self_threaded_results_are_matrix_h_results(void) { return check_kind(1); }
static int test_two_pool_threads_give_matrix_h_results(void) { return check_kind(2); }
static int test_three_pool_threads_give_matrix_h_results(void) { return check_kind(3); }

// Requirements: a clone is a copy; merging takes the larger estimates; a
// container covers the rows estimated, and a call beyond them is reported.
static int test_requirements_cover_what_was_estimated(void)
{
    test_capture_reports();
    dCooperativeID coop = dCooperativeCreate(NULL, NULL);
    dResourceRequirementsID small = dResourceRequirementsCreate(coop);
    dEstimateCooperativelyScaleVectorResourceRequirements(small, 1, 10);
    dResourceRequirementsID big = dResourceRequirementsClone(small);
    dEstimateCooperativelyFactorLDLTResourceRequirements(big, 2, 40);
    dEstimateCooperativelyFactorLDLTResourceRequirements(big, 1, 20);   // never lowers
    dResourceContainerID rc_small = dResourceContainerAcquire(small);
    dResourceRequirementsMergeIn(small, big);
    dResourceContainerID rc_merged = dResourceContainerAcquire(small);
    dReal v[40], sc[40];
    for (int i = 0; i < 40; i++) v[i] = sc[i] = 2;

    dCooperativelyScaleVector(rc_small, 1, v, sc, 10);
    CHECK(v[0] == 4 && v[9] == 4 && v[10] == 2);
    CHECK(test_captured_count() == 0);
    dCooperativelyScaleVector(rc_small, 1, v, sc, 11);
    CHECK(test_captured_count() == 1 && test_captured_contains("estimated for 10"));
    CHECK(v[0] == 4);   // no effect
    dCooperativelyScaleVector(rc_merged, 1, v, sc, 40);
    CHECK(test_captured_count() == 1);
    CHECK(v[39] == 4);

    dCooperativeDestroy(coop);   // still used
    CHECK(test_captured_count() == 2 && test_captured_contains("still use it"));
    dResourceContainerDestroy(rc_small);
    dResourceContainerDestroy(rc_merged);
    dResourceRequirementsDestroy(small);
    dResourceRequirementsDestroy(big);
    dResourceRequirementsDestroy(NULL);
    dResourceContainerDestroy(NULL);
    dCooperativeDestroy(coop);
    dCooperativeDestroy(NULL);
    CHECK(test_captured_count() == 2);
    return 0;
}

static int test_bad_input_is_reported(void)
{
    test_capture_reports();
    dCooperativeID coop = dCooperativeCreate(NULL, NULL);
    dResourceRequirementsID rq = dResourceRequirementsCreate(coop);
    dEstimateCooperativelyFactorLDLTResourceRequirements(rq, 1, 8);
    dResourceContainerID rc = dResourceContainerAcquire(rq);
    dReal A[8 * 8] = { 0 }, d[8];

    dCooperativelyFactorLDLT(rc, 1, A, d, 8, 7);
    CHECK(test_captured_count() == 1 && test_captured_contains("rowSkip"));
    dCooperativelyFactorLDLT(rc, 1, NULL, d, 8, 8);
    CHECK(test_captured_count() == 2 && test_captured_contains("A is NULL"));
    dCooperativelyFactorLDLT(NULL, 1, A, d, 8, 8);
    CHECK(test_captured_count() == 3);
    CHECK(dResourceRequirementsCreate(NULL) == NULL);
    CHECK(test_captured_count() == 4);
    dThreadingImplementationID impl = dThreadingAllocateSelfThreadedImplementation();
    const dThreadingFunctionsInfo *f = dThreadingImplementationGetFunctions(impl);
    dThreadingFreeImplementation(impl);
    CHECK(dCooperativeCreate(f, impl) == NULL);
    CHECK(test_captured_count() == 5 && test_captured_contains("was freed"));
    dResourceContainerDestroy(rc);
    dResourceRequirementsDestroy(rq);
    dCooperativeDestroy(coop);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_without_threading_results_are_matrix_h_results),
    TEST_CASE(test_self_threaded_results_are_matrix_h_results),
    TEST_CASE(test_two_pool_threads_give_matrix_h_results),
    TEST_CASE(test_three_pool_threads_give_matrix_h_results),
    TEST_CASE(test_requirements_cover_what_was_estimated),
    TEST_CASE(test_bad_input_is_reported),
    TEST_END
};
