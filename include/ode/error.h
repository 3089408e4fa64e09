/* SPDX-License-Identifier: BSD-3-Clause */
/* error.h -- error, debug and message reporting (guide 9.4).
 *
 * dError reports a fatal error, dDebug a programming error (a broken
 * precondition), dMessage information. Each goes to its handler; with no
 * handler the message is printed to stderr, and dError/dDebug then abort.
 * The library reports bad arguments through the debug handler; if a user's
 * debug handler returns, the offending call has no effect. */
#ifndef ODE_ERROR_H
#define ODE_ERROR_H

#include <ode/odeconfig.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A handler receives the error number (d_ERR_...), a printf format and its arguments. */
typedef void dMessageFunction(int errnum, const char *msg, va_list ap);

ODE_API void dSetErrorHandler(dMessageFunction *fn);
ODE_API void dSetDebugHandler(dMessageFunction *fn);
ODE_API void dSetMessageHandler(dMessageFunction *fn);
ODE_API dMessageFunction *dGetErrorHandler(void);
ODE_API dMessageFunction *dGetDebugHandler(void);
ODE_API dMessageFunction *dGetMessageHandler(void);

/** Report a fatal error; does not return (exits after a handler that returns). */
ODE_API void ODE_NORETURN dError(int num, const char *msg, ...);
/** Report a programming error; does not return (aborts after a handler that returns). */
ODE_API void ODE_NORETURN dDebug(int num, const char *msg, ...);
/** Report a message; returns. */
ODE_API void dMessage(int num, const char *msg, ...);

#ifdef __cplusplus
}
#endif

#endif
