// SPDX-License-Identifier: BSD-3-Clause
//
// test.h -- the project's minimal test harness. Each test executable defines
// `const test_case test_cases[]`; test_main.c runs them and prints TAP.

#ifndef TEST_H
#define TEST_H

#include <ode/ode.h>

typedef struct test_case {
    const char *name;
    int (*fn)(void);   // 0 = pass, TEST_SKIPPED = skipped (see test_skip)
} test_case;

// A case that cannot run here (a library not built in): `return test_skip(
// "why")` reports it as skipped (TAP "# SKIP why"), neither passed nor failed.
#define TEST_SKIPPED 77
int test_skip(const char *reason);

#define TEST_CASE(f) { #f, f }
#define TEST_END { 0, 0 }

extern const test_case test_cases[];

void test_fail(const char *file, int line, const char *fmt, ...);

#define CHECK(cond) \
    do { \
        if (!(cond)) { \
            test_fail(__FILE__, __LINE__, "CHECK(%s)", #cond); \
            return 1; \
        } \
    } while (0)

// |a - b| <= tol, NaN fails.
#define CHECK_NEAR(a, b, tol) \
    do { \
        double a_ = (double)(a), b_ = (double)(b), t_ = (double)(tol); \
        if (!(fabs(a_ - b_) <= t_)) { \
            test_fail(__FILE__, __LINE__, "CHECK_NEAR(%s, %s, %s): %.17g vs %.17g (diff %.3g)", \
                      #a, #b, #tol, a_, b_, fabs(a_ - b_)); \
            return 1; \
        } \
    } while (0)
// CHECK_NEAR on each component of a 3-vector.
#define CHECK_VEC(v, x, y, z, tol) \
    do { \
        CHECK_NEAR((v)[0], x, tol); \
        CHECK_NEAR((v)[1], y, tol); \
        CHECK_NEAR((v)[2], z, tol); \
    } while (0)

// A tolerance that depends on the precision the library was built with.
#ifdef dSINGLE
#define TOL(double_tol, single_tol) (single_tol)
#else
#define TOL(double_tol, single_tol) (double_tol)
#endif

// Capture reports to the debug / message handlers instead of aborting.
void test_capture_reports(void);
void test_release_reports(void);
int test_captured_count(void);
int test_captured_contains(const char *text);   // in any captured report
const char *test_captured_last(void);

// Count the allocations made through ODE's alloc and realloc handlers from
// now on; test_allocations_counted puts the default handlers back and
// returns the count.
void test_count_allocations(void);
int test_allocations_counted(void);

#endif
