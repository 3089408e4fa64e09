// SPDX-License-Identifier: BSD-3-Clause
//
// report.c -- how the library reports bad arguments: "function: message"
// through the user's debug handler (the call then returns without effect),
// or through dDebug (print and abort) when there is none. Only the public
// error API is used, so both libraries compile this file in.

#include "dx_check.h"

#include <ode/error.h>

// Format "function: fmt..." into text.
static void format_report(char *text, size_t size, const char *function, const char *fmt,
                          va_list ap)
{
    int used = snprintf(text, size, "%s: ", function);
    if (used >= 0 && (size_t)used < size) vsnprintf(text + used, size - (size_t)used, fmt, ap);
}

// Hand an already formatted text to a handler, which takes a format and a va_list.
static void call_with_text(dMessageFunction *fn, int num, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fn(num, fmt, ap);
    va_end(ap);
}

void dxReportBadArgument(const char *function, const char *fmt, ...)
{
    char text[512];
    va_list ap;
    va_start(ap, fmt);
    format_report(text, sizeof text, function, fmt, ap);
    va_end(ap);
    dMessageFunction *handler = dGetDebugHandler();
    if (handler) {
        call_with_text(handler, d_ERR_UASSERT, "%s", text);
        return;   // the handler chose to continue: the caller makes its call a no-op
    }
    dDebug(d_ERR_UASSERT, "%s", text);
}

void dxReportMessage(const char *function, const char *fmt, ...)
{
    char text[512];
    va_list ap;
    va_start(ap, fmt);
    format_report(text, sizeof text, function, fmt, ap);
    va_end(ap);
    dMessage(d_ERR_UASSERT, "%s", text);
}
