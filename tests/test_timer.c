// SPDX-License-Identifier: BSD-3-Clause
//
// test_timer.c -- <ode/timer.h>: the semantics of stopwatches and the code
// timer's report. No absolute time is asserted: only order, accumulation and
// the report's structure.

#include "test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// Burn a little time so that two clock readings differ.
static double spin(int n)
{
    volatile double x = 0;
    for (int i = 0; i < n; i++) x += (double)i * 1e-9;
    return x;
}

static int test_clock_constants_are_sane(void)
{
    CHECK(dTimerTicksPerSecond() == 1e9);
    const double r = dTimerResolution();
    CHECK(r > 0 && r < 1);
    return 0;
}

static int test_reset_stopwatch_reads_zero(void)
{
    dStopwatch s;
    memset(&s, 0x55, sizeof s);

    dStopwatchReset(&s);

    CHECK(dStopwatchTime(&s) == 0);
    return 0;
}

// Each start-stop interval is added; time between a stop and the next start
// is not: the total stays within a stopwatch that ran throughout.
static int test_stopwatch_accumulates_intervals(void)
{
    dStopwatch s, wall;
    dStopwatchReset(&s);
    dStopwatchReset(&wall);

    dStopwatchStart(&wall);
    dStopwatchStart(&s);
    spin(200000);
    dStopwatchStop(&s);
    const double t1 = dStopwatchTime(&s);
    spin(200000);   // not timed by s
    dStopwatchStart(&s);
    spin(200000);
    dStopwatchStop(&s);
    dStopwatchStop(&wall);
    const double t2 = dStopwatchTime(&s);

    CHECK(t1 > 0);
    CHECK(t2 > t1);
    CHECK(dStopwatchTime(&wall) >= t2);
    return 0;
}

// Readings of the monotonic clock never go back.
static int test_stopwatch_readings_are_monotonic(void)
{
    for (int i = 0; i < 1000; i++) {
        dStopwatch s;
        dStopwatchReset(&s);
        dStopwatchStart(&s);
        dStopwatchStop(&s);
        CHECK(dStopwatchTime(&s) >= 0);
    }
    return 0;
}

// Parse the report: every slot listed once in order, with its percentage;
// the slot percentages add up to the TOTAL line's 100 (to the printed 0.01).
static int test_report_lists_every_slot_with_shares_summing_to_100(void)
{
    static const char *const names[] = { "collide", "step", "a longer description" };
    dTimerStart(names[0]);
    spin(100000);
    dTimerNow(names[1]);
    spin(300000);
    dTimerNow(names[2]);
    spin(100000);
    dTimerEnd();
    FILE *f = tmpfile();

    dTimerReport(f, 1);

    rewind(f);
    char line[256];
    CHECK(fgets(line, sizeof line, f) && strcmp(line, "\n") == 0);
    CHECK(fgets(line, sizeof line, f) && strcmp(line, "Timer Report (1.00 ns resolution)\n") == 0);
    CHECK(fgets(line, sizeof line, f) && strcmp(line, "------------\n") == 0);
    double sum = 0;
    for (int i = 0; i < 3; i++) {
        CHECK(fgets(line, sizeof line, f));
        CHECK(strncmp(line, names[i], strlen(names[i])) == 0);
        const char *p = line + strlen("a longer description");   // the width of the longest
        double ms, percent, avg_ms, avg_percent;
        CHECK(sscanf(p, " %lfms %lf%% (avg %lfms %lf%%)", &ms, &percent, &avg_ms,
                     &avg_percent) == 4);
        CHECK(ms >= 0 && percent >= 0 && percent <= 100);
        sum += percent;
    }
    CHECK_NEAR(sum, 100, 0.03);
    CHECK(fgets(line, sizeof line, f));
    double total_ms, total_percent;
    CHECK(sscanf(line, "TOTAL %lfms %lf%%", &total_ms, &total_percent) == 2);
    CHECK(total_percent == 100);
    CHECK(fgets(line, sizeof line, f) && strcmp(line, "\n") == 0);
    CHECK(!fgets(line, sizeof line, f));
    fclose(f);
    return 0;
}

// Without averages the slot lines end after the percentage.
static int test_report_without_average_has_no_avg_column(void)
{
    dTimerStart("one");
    dTimerNow("two");
    dTimerEnd();
    char buf[1024];
    FILE *f = tmpfile();

    dTimerReport(f, 0);

    rewind(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    static const char head[] = "\nTimer Report (1.00 ns resolution)\n------------\n";
    CHECK(strstr(buf, "one  ") == buf + strlen(head));
    CHECK(strstr(buf, "avg") == NULL);
    CHECK(strstr(buf, "\nTOTAL") != NULL);
    return 0;
}

static int test_null_arguments_are_reported(void)
{
    test_capture_reports();

    dStopwatchReset(NULL);
    dTimerReport(NULL, 0);

    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("dStopwatchReset: stopwatch is NULL"));
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_clock_constants_are_sane),
    TEST_CASE(test_reset_stopwatch_reads_zero),
    TEST_CASE(test_stopwatch_accumulates_intervals),
    TEST_CASE(test_stopwatch_readings_are_monotonic),
    TEST_CASE(test_report_lists_every_slot_with_shares_summing_to_100),
    TEST_CASE(test_report_without_average_has_no_avg_column),
    TEST_CASE(test_null_arguments_are_reported),
    TEST_END
};
