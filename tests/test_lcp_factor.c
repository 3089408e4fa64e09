// SPDX-License-Identifier: BSD-3-Clause
//
// test_lcp_factor.c -- the triangular solves of the LCP solver's L D L^T factor
// (libodedyn/solvers/lcp_sparse.c). They are tuned for latency: dxLcpSolveL hands each
// row's result to the next row's dot in a register (dxLcpDotLast), dxLcpSolveLT applies two
// columns of L^T in one pass and carries the entries the next columns need in registers.
// Each must do the same operations in the same order as the plain loops (a row's dot in
// dxLcpDot's four lanes; one column after another), so that a simulation gives the same
// bits: compared here bit for bit with those plain loops on random factors of random
// profiles (rows empty, full or in between, zeros inside, vectors with zeros), and checked
// against the products L v and L^T v computed in long double.

#include "test.h"
#include "arena.h"
#include "lcp_internal.h"

#include <math.h>
#include <string.h>

#include "xorshift.h"

enum { MAX_M = 48, FACTORS = 400 };

static dReal rnd_real(void) { return (dReal)rnd(-1, 1); }
static int rnd_below(int n) { return (int)rnd(0, n); }   // 0 .. n - 1

// A random unit lower triangular factor of m rows: row k starts at a random lstart[k] <= k
// (k: empty), with about one entry in six of its profile zero.
static void random_factor(dxLcpFactor *f, int m)
{
    f->m = m;
    for (int k = 0; k < m; k++) {
        int kind = rnd_below(4);
        f->lstart[k] = kind == 0 ? k : kind == 1 ? 0 : rnd_below(k + 1);
        dReal *l = dxLcpRow(f, k);
        for (int c = 0; c < k; c++)
            l[c] = c < f->lstart[k] || rnd_below(6) == 0 ? 0 : rnd_real();
        f->d[k] = REAL(0.5) + dFabs(rnd_real());
        f->dinv[k] = 1 / f->d[k];
        f->cidx[k] = k;
    }
}

// v zero outside [first, end), about one entry in five zero inside.
static void random_vector(dReal *v, int m, int first, int end)
{
    for (int k = 0; k < m; k++)
        v[k] = k < first || k >= end || rnd_below(5) == 0 ? 0 : rnd_real();
}

// The plain forward solve: each row's dot over the nonzero extent of v so far.
static int plain_solve_l(const dxLcpFactor *f, dReal *v, int first)
{
    int e = first;
    for (int k = first; k < f->m; k++) {
        int st = f->lstart[k] > first ? f->lstart[k] : first;
        if (st < e) v[k] -= dxLcpDot(dxLcpRow(f, k) + st, v + st, e - st);
        if (v[k] != 0) e = k + 1;
    }
    return e;
}

// The plain backward solve: one column of L^T after another.
static void plain_solve_lt(const dxLcpFactor *f, dReal *v, int end)
{
    for (int k = end - 1; k > 0; k--) {
        const dReal *l = dxLcpRow(f, k);
        if (v[k] != 0)
            for (int c = f->lstart[k]; c < k; c++) v[c] -= v[k] * l[c];
    }
}

// max |(L x)[k] - b[k]| (transposed: L^T), in long double, relative to the terms' size.
static double product_error(const dxLcpFactor *f, const dReal *x, const dReal *b, int transposed)
{
    double worst = 0;
    for (int k = 0; k < f->m; k++) {
        long double s = x[k], size = fabsl((long double)x[k]);
        if (!transposed) {
            for (int c = f->lstart[k]; c < k; c++) {
                s += (long double)dxLcpRow(f, k)[c] * x[c];
                size += fabsl((long double)dxLcpRow(f, k)[c] * x[c]);
            }
        } else {
            for (int q = k + 1; q < f->m; q++) {
                if (f->lstart[q] > k) continue;
                s += (long double)dxLcpRow(f, q)[k] * x[q];
                size += fabsl((long double)dxLcpRow(f, q)[k] * x[q]);
            }
        }
        double err = (double)(fabsl(s - b[k]) / (size + 1));
        if (err > worst) worst = err;
    }
    return worst;
}

static int test_dot_with_last_given_apart_equals_the_dot(void)
{
    rng_state = 11;
    dReal a[24], b[24];
    for (int n = 1; n <= 24; n++) {
        for (int t = 0; t < 20; t++) {
            for (int k = 0; k < n; k++) {
                a[k] = rnd_real();
                b[k] = rnd_real() * (dReal)(1 << rnd_below(20));
            }
            dReal whole = dxLcpDot(a, b, n), apart = dxLcpDotLast(a, b, n, b[n - 1]);
            CHECK(memcmp(&whole, &apart, sizeof whole) == 0);
        }
    }
    return 0;
}

static int test_forward_solve_same_bits_as_the_plain_loop(void)
{
    dxArena arena;
    dxArenaInit(&arena);
    dxLcpFactor f;
    dxLcpFactorInit(&f, &arena, MAX_M);
    rng_state = 12345;
    dReal v[MAX_M], w[MAX_M], b[MAX_M];
    int failed = 0;
    for (int t = 0; t < FACTORS && !failed; t++) {
        int m = 1 + rnd_below(MAX_M);
        random_factor(&f, m);
        for (int first = 0; first <= m && !failed; first += 1 + rnd_below(4)) {
            random_vector(b, m, first, m);
            memcpy(v, b, sizeof v);
            memcpy(w, b, sizeof w);
            int e = dxLcpSolveL(&f, v, first), pe = plain_solve_l(&f, w, first);
            failed = e != pe || memcmp(v, w, (size_t)m * sizeof(dReal)) != 0 ||
                     product_error(&f, v, b, 0) > TOL(1e-13, 1e-4);
            for (int k = e; k < m && !failed; k++) failed = v[k] != 0;
        }
    }
    dxArenaFree(&arena);
    CHECK(!failed);
    return 0;
}

static int test_backward_solve_same_bits_as_the_plain_loop(void)
{
    dxArena arena;
    dxArenaInit(&arena);
    dxLcpFactor f;
    dxLcpFactorInit(&f, &arena, MAX_M);
    rng_state = 54321;
    dReal v[MAX_M], w[MAX_M], b[MAX_M];
    int failed = 0;
    for (int t = 0; t < FACTORS && !failed; t++) {
        int m = 1 + rnd_below(MAX_M);
        random_factor(&f, m);
        for (int end = 0; end <= m && !failed; end += 1 + rnd_below(4)) {
            random_vector(b, m, 0, end);
            memcpy(v, b, sizeof v);
            memcpy(w, b, sizeof w);
            dxLcpSolveLT(&f, v, end);
            plain_solve_lt(&f, w, end);
            // L^T v = b holds over the whole factor: b is zero past end
            failed = memcmp(v, w, (size_t)m * sizeof(dReal)) != 0 ||
                     product_error(&f, v, b, 1) > TOL(1e-13, 1e-4);
        }
    }
    dxArenaFree(&arena);
    CHECK(!failed);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_dot_with_last_given_apart_equals_the_dot),
    TEST_CASE(test_forward_solve_same_bits_as_the_plain_loop),
    TEST_CASE(test_backward_solve_same_bits_as_the_plain_loop),
    TEST_END,
};
