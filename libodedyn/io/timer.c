// SPDX-License-Identifier: BSD-3-Clause
//
// timer.c -- <ode/timer.h>: stopwatches and the code timer, on
// CLOCK_MONOTONIC with nanosecond ticks. dTimerReport prints the table ODE
// prints: each slot's time in ms and share of the run, and optionally each
// slot's average over every report so far (meaningful when the same
// start-now-end sequence repeats).

#define _POSIX_C_SOURCE 200809L   // clock_gettime

#include <ode/timer.h>

#include <string.h>
#include <time.h>

#include "dx_check.h"

#define MAX_SLOTS 100

// A clock reading as two counts, the layout of dStopwatch.cc: [0] nanoseconds,
// [1] seconds.
static void read_clock(unsigned long cc[2])
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    cc[0] = (unsigned long)t.tv_nsec;
    cc[1] = (unsigned long)t.tv_sec;
}

// A reading in ticks (nanoseconds).
static double ticks(const unsigned long cc[2])
{
    return (double)cc[1] * 1e9 + (double)cc[0];
}

double dTimerTicksPerSecond(void)
{
    return 1e9;
}

double dTimerResolution(void)
{
    struct timespec r;
    if (clock_getres(CLOCK_MONOTONIC, &r) != 0) return 1.0 / dTimerTicksPerSecond();
    return (double)r.tv_sec + (double)r.tv_nsec * 1e-9;
}

// ---- stopwatches --------------------------------------------------------------

void dStopwatchReset(dStopwatch *s)
{
    DX_CHECK_ARG(s != NULL, return, "stopwatch is NULL");
    s->time = 0;
    s->cc[0] = 0;
    s->cc[1] = 0;
}

void dStopwatchStart(dStopwatch *s)
{
    DX_CHECK_ARG(s != NULL, return, "stopwatch is NULL");
    read_clock(s->cc);
}

void dStopwatchStop(dStopwatch *s)
{
    DX_CHECK_ARG(s != NULL, return, "stopwatch is NULL");
    unsigned long now[2];
    read_clock(now);
    s->time += ticks(now) - ticks(s->cc);
}

double dStopwatchTime(dStopwatch *s)
{
    DX_CHECK_ARG(s != NULL, return 0, "stopwatch is NULL");
    return s->time / dTimerTicksPerSecond();
}

// ---- the code timer -------------------------------------------------------------

// Slot i runs from reading i to reading i + 1; the last reading ("TOTAL",
// from dTimerEnd) closes the run. The totals and counts add up over reports.
static struct {
    unsigned long cc[2];
    const char *description;
    double total_ticks;     // over all reports
    double total_percent;
    int reports;
} slots[MAX_SLOTS];
static int slot_count;

void dTimerStart(const char *description)
{
    DX_CHECK_ARG(description != NULL, return, "description is NULL");
    slots[0].description = description;
    slot_count = 1;
    read_clock(slots[0].cc);
}

void dTimerNow(const char *description)
{
    DX_CHECK_ARG(description != NULL, return, "description is NULL");
    if (slot_count == 0 || slot_count >= MAX_SLOTS) return;   // not started, or full
    read_clock(slots[slot_count].cc);
    slots[slot_count].description = description;
    slot_count++;
}

void dTimerEnd(void)
{
    if (slot_count == 0 || slot_count >= MAX_SLOTS) return;
    read_clock(slots[slot_count].cc);
    slots[slot_count].description = "TOTAL";
    slot_count++;
}

// a seconds with an SI prefix (a >= ~1: none, then m, u, n).
static void print_with_prefix(FILE *f, double a)
{
    static const char *const prefix[] = { "", "m", "u", "n" };
    int k = 0;
    while (k < 3 && a < 0.999999) {
        a *= 1000.0;
        k++;
    }
    fprintf(f, "%.2f %s", a, prefix[k]);
}

void dTimerReport(FILE *fout, int average)
{
    DX_CHECK_ARG(fout != NULL, return, "fout is NULL");
    const double seconds_per_tick = 1.0 / dTimerTicksPerSecond();
    fprintf(fout, "\nTimer Report (");
    print_with_prefix(fout, seconds_per_tick);
    fprintf(fout, "s resolution)\n------------\n");
    if (slot_count < 1) return;

    int width = 0;
    for (int i = 0; i < slot_count; i++) {
        const int l = (int)strlen(slots[i].description);
        if (l > width) width = l;
    }
    double total = ticks(slots[slot_count - 1].cc) - ticks(slots[0].cc);
    if (total <= 0) total = 1;   // a run shorter than a tick: shares of nothing

    for (int i = 0; i < slot_count; i++) {
        double t = total, percent = 100.0;
        if (i < slot_count - 1) {
            t = ticks(slots[i + 1].cc) - ticks(slots[i].cc);
            percent = t / total * 100.0;
            slots[i].reports++;
            slots[i].total_ticks += t;
            slots[i].total_percent += percent;
        }
        fprintf(fout, "%-*s %7.2fms %6.2f%%", width, slots[i].description,
                t * seconds_per_tick * 1000.0, percent);
        if (average && i < slot_count - 1) {
            fprintf(fout, "  (avg %7.2fms %6.2f%%)",
                    slots[i].total_ticks / slots[i].reports * seconds_per_tick * 1000.0,
                    slots[i].total_percent / slots[i].reports);
        }
        fprintf(fout, "\n");
    }
    fprintf(fout, "\n");
}
