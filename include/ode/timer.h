/* SPDX-License-Identifier: BSD-3-Clause */
/* timer.h -- stopwatches and a code timer for profiling, on the monotonic
 * clock (nanosecond ticks). */
#ifndef ODE_TIMER_H
#define ODE_TIMER_H

#include <ode/odeconfig.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A stopwatch: time is the accumulated clock count (ticks), cc the clock
 *  count at the last dStopwatchStart (here cc[1] seconds, cc[0] nanoseconds). */
typedef struct dStopwatch {
    double time;
    unsigned long cc[2];
} dStopwatch;

/** Zero the accumulated time. */
ODE_API void dStopwatchReset(dStopwatch *);
ODE_API void dStopwatchStart(dStopwatch *);
/** Add the time since the last dStopwatchStart. */
ODE_API void dStopwatchStop(dStopwatch *);
/** The accumulated time in seconds. */
ODE_API double dStopwatchTime(dStopwatch *);

/* The code timer: dTimerStart opens a run of slots, each dTimerNow ends the
 * last slot and opens a new one, dTimerEnd closes the run (at most 100
 * slots). Descriptions are kept as pointers: pass static strings. */
ODE_API void dTimerStart(const char *description);
ODE_API void dTimerNow(const char *description);
ODE_API void dTimerEnd(void);

/** Print each slot of the last run with its time and share of the total;
 *  with average nonzero, also each slot's average over all reports so far. */
ODE_API void dTimerReport(FILE *fout, int average);

/** Clock ticks per second (1e9: the clock counts nanoseconds). */
ODE_API double dTimerTicksPerSecond(void);
/** The clock's actual resolution in seconds (clock_getres). */
ODE_API double dTimerResolution(void);

#ifdef __cplusplus
}
#endif

#endif
