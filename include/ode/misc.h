/* SPDX-License-Identifier: BSD-3-Clause */
/* misc.h -- the library's random number generator and matrix utilities for
 * tests and demos. The generator is ODE's 32-bit linear congruential one, so
 * a seeded program draws the same numbers as with ODE. */
#ifndef ODE_MISC_H
#define ODE_MISC_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/** 1 if the random number generator produces its documented sequence. */
ODE_API int dTestRand(void);
/** The next raw 32-bit random number. */
ODE_API unsigned long dRand(void);
ODE_API unsigned long dRandGetSeed(void);
ODE_API void dRandSetSeed(unsigned long s);
/** A random integer in 0..n-1 (n > 0). */
ODE_API int dRandInt(int n);
/** A random number in [0, 1]. */
ODE_API dReal dRandReal(void);

/** Print the n x m matrix A (row skip dPAD(m)) with the printf format fmt. */
ODE_API void dPrintMatrix(const dReal *A, int n, int m, const char *fmt, FILE *f);
/** Fill with random numbers in [-range, range]. */
ODE_API void dMakeRandomVector(dReal *A, int n, dReal range);
ODE_API void dMakeRandomMatrix(dReal *A, int n, int m, dReal range);
/** Zero the strict upper triangle of the n x n matrix A. */
ODE_API void dClearUpperTriangle(dReal *A, int n);
/** Largest |A(i,j) - B(i,j)| over two n x m matrices. */
ODE_API dReal dMaxDifference(const dReal *A, const dReal *B, int n, int m);
/** The same over the lower triangle (diagonal included) of n x n matrices. */
ODE_API dReal dMaxDifferenceLowerTriangle(const dReal *A, const dReal *B, int n);

#ifdef __cplusplus
}
#endif

#endif
