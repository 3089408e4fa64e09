// SPDX-License-Identifier: BSD-3-Clause
//
// misc.c -- the random number generator and the matrix helpers for tests and
// demos. The generator is the 32-bit linear congruential one
// x' = (1664525 x + 1013904223) mod 2^32 starting from x = 0, so that a seeded
// program draws exactly the numbers it would draw with ODE.

#include "dx_check.h"

#include <ode/misc.h>

static unsigned long seed;

unsigned long dRand(void)
{
    seed = (1664525UL * seed + 1013904223UL) & 0xffffffffUL;
    return seed;
}

unsigned long dRandGetSeed(void) { return seed; }

// The state is 32 bits wide: higher bits of s are dropped.
void dRandSetSeed(unsigned long s) { seed = s & 0xffffffffUL; }

// The low bits of an LCG are its weakest (bit 0 just alternates), so for n <= 2^16 the high
// half is xor-folded onto the low 16 bits, then for n <= 2^8 onto the low 8, and so on down
// to 1 bit for n <= 2. The last fold leaves b = 32, 16, 8, 4, 2 or 1 useful low bits, and
// the result is floor(low_b * n / 2^b), which lies in 0..n-1 and hits each value since
// n <= 2^b. (ODE 0.16 computes exactly this; the differential test compares the numbers.)
int dRandInt(int n)
{
    DX_CHECK_ARG(n > 0, return 0, "n must be positive, got %d", n);
    static const struct { duint32 limit; int shift; } folds[] = {
        {0x10000u, 16}, {0x100u, 8}, {0x10u, 4}, {4u, 2}, {2u, 1},
    };
    const duint32 un = (duint32)n;
    duint32 r = (duint32)dRand();
    int bits = 32;
    for (size_t i = 0; i < sizeof folds / sizeof folds[0] && un <= folds[i].limit; i++) {
        r ^= r >> folds[i].shift;
        bits = folds[i].shift;
    }
    const duint64 low = bits == 32 ? r : r & ((1u << bits) - 1u);
    return (int)((low * un) >> bits);
}

dReal dRandReal(void) { return (dReal)((double)dRand() / (double)0xffffffffUL); }

// Restart the generator from 0 and compare with the first iterates of the formula,
// worked out independently of this code; the caller's seed is restored.
int dTestRand(void)
{
    static const unsigned long expected[] = {
        0x3c6ef35fUL, 0x47502932UL, 0xd1ccf6e9UL, 0xaaf95334UL, 0x6252e503UL,
    };
    const unsigned long saved = seed;
    int ok = 1;
    seed = 0;
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; i++)
        if (dRand() != expected[i]) ok = 0;
    seed = saved;
    return ok;
}

void dPrintMatrix(const dReal *A, int n, int m, const char *fmt, FILE *f)
{
    DX_CHECK_ARG(n >= 0 && m >= 0, return, "n and m must be >= 0, got %d, %d", n, m);
    DX_CHECK_ARG(fmt != NULL && f != NULL, return, "%s is NULL", fmt ? "f" : "fmt");
    DX_CHECK_ARG(A != NULL || n == 0 || m == 0, return, "A is NULL");
    const int s = dPAD(m);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < m; j++) fprintf(f, fmt, (double)A[i * s + j]);
        fputc('\n', f);
    }
}

// One uniform number in [-range, range].
static dReal random_in_range(dReal range) { return (dRandReal() * REAL(2.0) - REAL(1.0)) * range; }

void dMakeRandomVector(dReal *A, int n, dReal range)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(A != NULL || n == 0, return, "A is NULL");
    for (int i = 0; i < n; i++) A[i] = random_in_range(range);
}

// Row-major draw order; the padding at the end of each row is set to 0.
void dMakeRandomMatrix(dReal *A, int n, int m, dReal range)
{
    DX_CHECK_ARG(n >= 0 && m >= 0, return, "n and m must be >= 0, got %d, %d", n, m);
    DX_CHECK_ARG(A != NULL || n == 0 || m == 0, return, "A is NULL");
    const int s = dPAD(m);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < m; j++) A[i * s + j] = random_in_range(range);
        for (int j = m; j < s; j++) A[i * s + j] = 0;
    }
}

void dClearUpperTriangle(dReal *A, int n)
{
    DX_CHECK_ARG(n >= 0, return, "n must be >= 0, got %d", n);
    DX_CHECK_ARG(A != NULL || n == 0, return, "A is NULL");
    const int s = dPAD(n);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) A[i * s + j] = 0;
}

// Like ODE, a NaN difference never becomes the maximum (diff > max is false for it).
static dReal max_difference(const dReal *A, const dReal *B, int n, int m, int lower)
{
    const int s = dPAD(m);
    dReal max = 0;
    for (int i = 0; i < n; i++) {
        const int end = lower ? i + 1 : m;
        for (int j = 0; j < end; j++) {
            const dReal diff = dFabs(A[i * s + j] - B[i * s + j]);
            if (diff > max) max = diff;
        }
    }
    return max;
}

dReal dMaxDifference(const dReal *A, const dReal *B, int n, int m)
{
    DX_CHECK_ARG(n >= 0 && m >= 0, return 0, "n and m must be >= 0, got %d, %d", n, m);
    DX_CHECK_ARG((A != NULL && B != NULL) || n == 0 || m == 0, return 0, "%s is NULL",
                 A ? "B" : "A");
    return max_difference(A, B, n, m, 0);
}

dReal dMaxDifferenceLowerTriangle(const dReal *A, const dReal *B, int n)
{
    DX_CHECK_ARG(n >= 0, return 0, "n must be >= 0, got %d", n);
    DX_CHECK_ARG((A != NULL && B != NULL) || n == 0, return 0, "%s is NULL", A ? "B" : "A");
    return max_difference(A, B, n, n, 1);
}
