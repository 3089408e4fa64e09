// SPDX-License-Identifier: BSD-3-Clause
//
// test_selftest.c -- the self-tests ODE exports without a public declaration
// (declared here as ODE's demo_ode.cpp declares them): they pass on this
// library, print what ODE prints, and report nothing.

#define _POSIX_C_SOURCE 200809L   // fileno, dup

#include "test.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

int dTestSolveLCP(void);
void dTestDataStructures(void);

#define OUT_MAX (1 << 20)
static char out[OUT_MAX];

// Run fn with stdout going to a file, then read that into `out`.
static void capture_stdout(void (*fn)(void))
{
    fflush(stdout);
    FILE *f = tmpfile();
    const int saved = dup(1);
    dup2(fileno(f), 1);
    fn();
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    rewind(f);
    size_t n = fread(out, 1, OUT_MAX - 1, f);
    out[n] = 0;
    fclose(f);
}

static int count_lines_starting(const char *prefix)
{
    int n = 0;
    for (const char *p = out; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL)
        n += strncmp(p, prefix, strlen(prefix)) == 0;
    return n;
}

static int lcp_result;
static void run_lcp(void) { lcp_result = dTestSolveLCP(); }

static int test_solve_lcp_passes_every_problem(void)
{
    test_capture_reports();

    capture_stdout(run_lcp);

    CHECK(lcp_result == 1);
    CHECK(test_captured_count() == 0);
    CHECK(strncmp(out, "dTestSolveLCP()\n", 16) == 0);
    CHECK(count_lines_starting("passed: NL=") == 1000);
    CHECK(count_lines_starting("FAILED") == 0);
    // Every row is classified: NL + NH + C = 100 on a line.
    int nl, nh, c;
    CHECK(sscanf(strchr(out, '\n') + 1, "passed: NL=%d NH=%d C=%d", &nl, &nh, &c) == 3);
    CHECK(nl + nh + c == 100);
    CHECK(c >= 50);   // the 50 unbounded rows
    test_release_reports();
    return 0;
}

static int test_data_structures_keep_their_links(void)
{
    test_capture_reports();

    capture_stdout(dTestDataStructures);

    CHECK(test_captured_count() == 0);
    CHECK(strncmp(out, "dTestDataStructures()\n", 22) == 0);
    CHECK(strstr(out, "20000 operations on bodies and joints, 0 broken rules: passed\n") != NULL);
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_solve_lcp_passes_every_problem),
    TEST_CASE(test_data_structures_keep_their_links),
    TEST_END
};
