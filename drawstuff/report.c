// SPDX-License-Identifier: BSD-3-Clause
//
// report.c -- dsError, dsDebug and dsPrint: drawstuff's messages.

#include "ds_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

// Prints "\n<kind>: <message>\n" on stderr, after flushing what came before.
static void report(const char *kind, const char *msg, va_list ap)
{
    fflush(stdout);
    fprintf(stderr, "\n%s: ", kind);
    vfprintf(stderr, msg, ap);
    fprintf(stderr, "\n");
    fflush(stderr);
}

// A misuse the program cannot continue after: message, exit status 1.
void dsError(const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    report("Error", msg, ap);
    va_end(ap);
    exit(1);
}

// An inconsistency (as ODE, a version mismatch): message, then abort so a
// debugger or core dump shows where.
void dsDebug(const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    report("INTERNAL ERROR", msg, ap);
    va_end(ap);
    abort();
}

void dsPrint(const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    vprintf(msg, ap);
    va_end(ap);
}

// A bad argument that is ignored (the call keeps the previous setting):
// "drawstuff: <message>" on stderr; the program continues.
void dxDsWarn(const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    fflush(stdout);
    fprintf(stderr, "drawstuff: ");
    vfprintf(stderr, msg, ap);
    fprintf(stderr, "\n");
    fflush(stderr);
    va_end(ap);
}
