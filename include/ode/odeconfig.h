/* SPDX-License-Identifier: BSD-3-Clause */
/* odeconfig.h -- platform configuration: standard headers every ODE program
 * expects to be pulled in, export macros, fixed-width integer names and
 * dInfinity. */
#ifndef ODE_ODECONFIG_H
#define ODE_ODECONFIG_H

#include <stddef.h>
#include <stdint.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdarg.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include <ode/precision.h>

#if defined(dSINGLE) && defined(dDOUBLE)
#error "define only one of dSINGLE and dDOUBLE"
#endif

#if defined(__GNUC__) && !defined(_WIN32)
#define ODE_API __attribute__((visibility("default")))
#else
#define ODE_API
#endif

#if defined(__GNUC__)
#define ODE_API_DEPRECATED __attribute__((__deprecated__))
#define ODE_NORETURN __attribute__((noreturn))
#else
#define ODE_API_DEPRECATED
#define ODE_NORETURN
#endif

#define ODE_PURE_INLINE static inline
#define ODE_INLINE inline

#if defined(__cplusplus)
#define ODE_EXTERN_C extern "C"
#else
#define ODE_EXTERN_C
#endif

typedef int64_t dint64;
typedef uint64_t duint64;
typedef int32_t dint32;
typedef uint32_t duint32;
typedef int16_t dint16;
typedef uint16_t duint16;
typedef int8_t dint8;
typedef uint8_t duint8;
typedef intptr_t dintptr;
typedef uintptr_t duintptr;
typedef ptrdiff_t ddiffint;
typedef size_t dsizeint;

#ifdef dSINGLE
#define dInfinity ((float)INFINITY)
#else
#define dInfinity ((double)INFINITY)
#endif

#endif
