// SPDX-License-Identifier: BSD-3-Clause
//
// test_main.c -- runs test_cases[] and prints TAP (one `ok`/`not ok` per case).

#include "test.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_REPORTS 64

static char reports[MAX_REPORTS][512];
static int report_count;

void test_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("# %s:%d: ", file, line);
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
}

static void capture(int num, const char *msg, va_list ap)
{
    (void)num;
    if (report_count < MAX_REPORTS) vsnprintf(reports[report_count], sizeof reports[0], msg, ap);
    report_count++;
}

void test_capture_reports(void)
{
    report_count = 0;
    dSetDebugHandler(capture);
    dSetMessageHandler(capture);
}

void test_release_reports(void)
{
    dSetDebugHandler(0);
    dSetMessageHandler(0);
}

int test_captured_count(void) { return report_count; }

int test_captured_contains(const char *text)
{
    for (int i = 0; i < report_count && i < MAX_REPORTS; i++)
        if (strstr(reports[i], text)) return 1;
    return 0;
}

const char *test_captured_last(void)
{
    if (report_count == 0) return "";
    return reports[(report_count <= MAX_REPORTS ? report_count : MAX_REPORTS) - 1];
}

static char skip_reason[256];

int test_skip(const char *reason)
{
    snprintf(skip_reason, sizeof skip_reason, "%s", reason);
    return TEST_SKIPPED;
}

int main(void)
{
    int n = 0, failed = 0;
    while (test_cases[n].fn) n++;
    printf("TAP version 13\n1..%d\n", n);
    for (int i = 0; i < n; i++) {
        int result = test_cases[i].fn();
        test_release_reports();
        if (result == TEST_SKIPPED) {
            printf("ok %d - %s # SKIP %s\n", i + 1, test_cases[i].name, skip_reason);
        } else {
            failed += result != 0;
            printf("%s %d - %s\n", result ? "not ok" : "ok", i + 1, test_cases[i].name);
        }
        fflush(stdout);
    }
    return failed ? 1 : 0;
}

static int allocations_counted;

static void *counting_alloc(dsizeint size)
{
    allocations_counted++;
    return malloc(size ? size : 1);
}

static void *counting_realloc(void *p, dsizeint old_size, dsizeint size)
{
    (void)old_size;
    allocations_counted++;
    return realloc(p, size ? size : 1);
}

void test_count_allocations(void)
{
    allocations_counted = 0;
    dSetAllocHandler(counting_alloc);
    dSetReallocHandler(counting_realloc);
}

int test_allocations_counted(void)
{
    dSetAllocHandler(0);
    dSetReallocHandler(0);
    return allocations_counted;
}
