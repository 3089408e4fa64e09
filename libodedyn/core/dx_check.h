// SPDX-License-Identifier: BSD-3-Clause
//
// dx_check.h -- argument checks at the public entry points. They are on in
// every build: a broken precondition is reported through the debug handler
// (default: print and abort); if a user handler returns, the call does
// nothing instead of touching bad data.

#ifndef DX_CHECK_H
#define DX_CHECK_H

#include <ode/common.h>

#if defined(__GNUC__)
#define DX_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define DX_PRINTF(f, a)
#endif

/* Report "function: message" as d_ERR_UASSERT through the debug handler.
 * Returns only if a user handler returned. */
void dxReportBadArgument(const char *function, const char *fmt, ...) DX_PRINTF(2, 3);
/* Report "function: message" through the message handler (not an error). */
void dxReportMessage(const char *function, const char *fmt, ...) DX_PRINTF(2, 3);

/* If cond is false: report msg (printf-style) naming the calling function,
 * then run on_fail (typically `return` or `return 0`). */
#define DX_CHECK_ARG(cond, on_fail, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(__func__, __VA_ARGS__); \
            on_fail; \
        } \
    } while (0)

/* A recoverable oddity that ODE accepts with a documented fallback (a zero
 * rotation axis gives the identity): report it through the message handler,
 * which prints and continues, and run fallback. */
#define DX_WARN_ARG(cond, fallback, ...) \
    do { \
        if (!(cond)) { \
            dxReportMessage(__func__, __VA_ARGS__); \
            fallback; \
        } \
    } while (0)

static inline int dxIsFinite(dReal x) { return isfinite(x); }
static inline int dxIsFinite3(dReal x, dReal y, dReal z)
{
    return isfinite(x) && isfinite(y) && isfinite(z);
}

/* The 9 elements of a dMatrix3 that hold the matrix; R[3], R[7] and R[11] are
 * padding, which ODE programs often leave uninitialised: never read them. */
static inline int dxIsFiniteMatrix3(const dReal *R)
{
    return dxIsFinite3(R[0], R[1], R[2]) && dxIsFinite3(R[4], R[5], R[6]) &&
           dxIsFinite3(R[8], R[9], R[10]);
}

/* Copy the 9 elements of a dMatrix3 and zero the padding of the copy. */
static inline void dxCopyMatrix3(dReal *dst, const dReal *R)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) dst[4 * i + j] = R[4 * i + j];
        dst[4 * i + 3] = 0;
    }
}

#endif
