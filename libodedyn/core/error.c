// SPDX-License-Identifier: BSD-3-Clause
//
// error.c -- the error, debug and message handlers (guide 9.4) and the
// library's own reporting of bad arguments.

#include <ode/error.h>

static dMessageFunction *error_handler;
static dMessageFunction *debug_handler;
static dMessageFunction *message_handler;

void dSetErrorHandler(dMessageFunction *fn) { error_handler = fn; }
void dSetDebugHandler(dMessageFunction *fn) { debug_handler = fn; }
void dSetMessageHandler(dMessageFunction *fn) { message_handler = fn; }
dMessageFunction *dGetErrorHandler(void) { return error_handler; }
dMessageFunction *dGetDebugHandler(void) { return debug_handler; }
dMessageFunction *dGetMessageHandler(void) { return message_handler; }

// The default action of every handler: one line on stderr.
static void print_message(const char *kind, int num, const char *msg, va_list ap)
{
    fprintf(stderr, "\n%s %d: ", kind, num);
    vfprintf(stderr, msg, ap);
    fprintf(stderr, "\n");
    fflush(stderr);
}

void dError(int num, const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    if (error_handler) error_handler(num, msg, ap);
    else print_message("ODE Error", num, msg, ap);
    va_end(ap);
    exit(1);
}

void dDebug(int num, const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    if (debug_handler) debug_handler(num, msg, ap);
    else print_message("ODE INTERNAL ERROR", num, msg, ap);
    va_end(ap);
    abort();
}

void dMessage(int num, const char *msg, ...)
{
    va_list ap;
    va_start(ap, msg);
    if (message_handler) message_handler(num, msg, ap);
    else print_message("ODE Message", num, msg, ap);
    va_end(ap);
}
