// SPDX-License-Identifier: BSD-3-Clause
//
// matrix_coop.c -- matrix.h's L D L^T factorisation and triangular solves
// computed cooperatively (matrix_coop.h): blocks of BLOCK rows are done in
// order on the calling thread, and what each block contributes to the rows
// after it (before it, for L^T) is spread over the threads, CHUNK rows a
// piece. Every number is formed by the same operations in the same order as
// in matrix.c (a sum over k is accumulated in increasing k, resumed where
// the previous block left it), so the results are those of dFactorLDLT,
// dSolveL1, dSolveL1T, dScaleVector and dSolveLDLT to the bit, whatever the
// number of threads.

#include "cooperative_internal.h"
#include "dx_check.h"

#include <ode/matrix_coop.h>

#define BLOCK 32u
#define CHUNK 32u

// Pieces of CHUNK rows in [first, n).
static int chunk_count(unsigned first, unsigned n)
{
    return first >= n ? 0 : (int)((n - first + CHUNK - 1) / CHUNK);
}

static unsigned min_u(unsigned a, unsigned b) { return a < b ? a : b; }

// The arguments of a call with a matrix M, a vector v, n rows and row skip.
static int args_ok(const char *function, dResourceContainerID rc, const void *M,
                   const char *mname, const void *v, const char *vname, unsigned n,
                   unsigned skip)
{
    if (!dxCoopContainerCovers(function, rc, n)) return 0;
    if (skip < n) {
        dxReportBadArgument(function, "rowSkip %u is smaller than rowCount %u", skip, n);
        return 0;
    }
    if (n > 0 && (!M || !v)) {
        dxReportBadArgument(function, "%s is NULL", !M ? mname : vname);
        return 0;
    }
    return 1;
}

// ---- L D L^T -------------------------------------------------------------

typedef struct factor_job {
    dReal *A, *d;
    unsigned n, skip;
    unsigned c0, c1;   // the block of columns being done
} factor_job;

// Row i's columns j in [c0, min(c1, i)) as dFactorLDLT's first pass leaves
// them: z_ij = A_ij - sum_{k<j} z_ik L_jk (rows j < c1 are final).
static void factor_columns(const factor_job *f, unsigned i)
{
    dReal *Ai = f->A + (size_t)i * f->skip;
    const unsigned end = min_u(f->c1, i);
    for (unsigned j = f->c0; j < end; j++) {
        const dReal *Aj = f->A + (size_t)j * f->skip;
        dReal sum = 0;
        for (unsigned k = 0; k < j; k++) sum += Ai[k] * Aj[k];
        Ai[j] -= sum;
    }
}

// Row i with all its z: L_ij = z_ij / D_j and d_i = 1 / (A_ii - sum_j z_ij L_ij).
static void factor_finish(const factor_job *f, unsigned i)
{
    dReal *Ai = f->A + (size_t)i * f->skip;
    dReal Dii = Ai[i];
    for (unsigned j = 0; j < i; j++) {
        const dReal z = Ai[j];
        Ai[j] = z * f->d[j];
        Dii -= z * Ai[j];
    }
    f->d[i] = dRecip(Dii);
}

static void factor_piece(void *context, int item)
{
    const factor_job *f = context;
    const unsigned first = f->c1 + (unsigned)item * CHUNK, end = min_u(first + CHUNK, f->n);
    for (unsigned i = first; i < end; i++) factor_columns(f, i);
}

void dEstimateCooperativelyFactorLDLTResourceRequirements(dResourceRequirementsID requirements,
                                                          unsigned maximalAllowedThreadCount,
                                                          unsigned maximalRowCount)
{
    dxCoopRequire(__func__, requirements, maximalAllowedThreadCount, maximalRowCount);
}

void dCooperativelyFactorLDLT(dResourceContainerID resources, unsigned allowedThreadCount,
                              dReal *A, dReal *d, unsigned rowCount, unsigned rowSkip)
{
    if (!args_ok(__func__, resources, A, "A", d, "d", rowCount, rowSkip)) return;
    factor_job f = { A, d, rowCount, rowSkip, 0, 0 };
    for (f.c0 = 0; f.c0 < rowCount; f.c0 = f.c1) {
        f.c1 = min_u(f.c0 + BLOCK, rowCount);
        for (unsigned i = f.c0; i < f.c1; i++) {
            factor_columns(&f, i);
            factor_finish(&f, i);
        }
        dxCoopRun(resources, allowedThreadCount, chunk_count(f.c1, rowCount), factor_piece, &f);
    }
}

// ---- L x = b ---------------------------------------------------------------

typedef struct solve_job {
    const dReal *L;
    dReal *b, *acc;    // acc: each row's sum so far (L1 straight)
    unsigned n, skip;
    unsigned r0, r1;   // the block of rows (of b) being done
} solve_job;

// acc_i += L_ik b_k for k in [r0, min(r1, i)).
static void straight_add(const solve_job *s, unsigned i)
{
    const dReal *Li = s->L + (size_t)i * s->skip;
    const unsigned end = min_u(s->r1, i);
    dReal sum = s->acc[i];
    for (unsigned k = s->r0; k < end; k++) sum += Li[k] * s->b[k];
    s->acc[i] = sum;
}

static void straight_piece(void *context, int item)
{
    const solve_job *s = context;
    const unsigned first = s->r1 + (unsigned)item * CHUNK, end = min_u(first + CHUNK, s->n);
    for (unsigned i = first; i < end; i++) straight_add(s, i);
}

static void solve_straight(dResourceContainerID rc, unsigned threads, const dReal *L, dReal *b,
                           unsigned n, unsigned skip)
{
    solve_job s = { L, b, dxCoopScratch(rc), n, skip, 0, 0 };
    for (unsigned i = 0; i < n; i++) s.acc[i] = 0;
    for (s.r0 = 0; s.r0 < n; s.r0 = s.r1) {
        s.r1 = min_u(s.r0 + BLOCK, n);
        for (unsigned i = s.r0; i < s.r1; i++) {
            straight_add(&s, i);
            b[i] -= s.acc[i];
        }
        dxCoopRun(rc, threads, chunk_count(s.r1, n), straight_piece, &s);
    }
}

void dEstimateCooperativelySolveL1StraightResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount)
{
    dxCoopRequire(__func__, requirements, maximalAllowedThreadCount, maximalRowCount);
}

void dCooperativelySolveL1Straight(dResourceContainerID resources, unsigned allowedThreadCount,
                                   const dReal *L, dReal *b, unsigned rowCount, unsigned rowSkip)
{
    if (!args_ok(__func__, resources, L, "L", b, "b", rowCount, rowSkip)) return;
    solve_straight(resources, allowedThreadCount, L, b, rowCount, rowSkip);
}

// ---- L^T x = b -------------------------------------------------------------

// b_k -= L_ik b_i for i from r1 - 1 down to max(r0, k + 1): the block's
// part of dSolveL1T's updates of b_k, in its order.
static void transposed_sub(const solve_job *s, unsigned k)
{
    dReal bk = s->b[k];
    for (unsigned i = s->r1; i-- > s->r0 && i > k;) bk -= s->L[(size_t)i * s->skip + k] * s->b[i];
    s->b[k] = bk;
}

static void transposed_piece(void *context, int item)
{
    const solve_job *s = context;
    const unsigned first = (unsigned)item * CHUNK, end = min_u(first + CHUNK, s->r0);
    for (unsigned k = first; k < end; k++) transposed_sub(s, k);
}

static void solve_transposed(dResourceContainerID rc, unsigned threads, const dReal *L,
                             dReal *b, unsigned n, unsigned skip)
{
    solve_job s = { L, b, NULL, n, skip, n, n };
    for (s.r1 = n; s.r1 > 0; s.r1 = s.r0) {
        s.r0 = s.r1 > BLOCK ? s.r1 - BLOCK : 0;
        for (unsigned k = s.r1; k-- > s.r0;) transposed_sub(&s, k);   // in-block, b_k final
        dxCoopRun(rc, threads, chunk_count(0, s.r0), transposed_piece, &s);
    }
}

void dEstimateCooperativelySolveL1TransposedResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount)
{
    dxCoopRequire(__func__, requirements, maximalAllowedThreadCount, maximalRowCount);
}

void dCooperativelySolveL1Transposed(dResourceContainerID resources, unsigned allowedThreadCount,
                                     const dReal *L, dReal *b, unsigned rowCount,
                                     unsigned rowSkip)
{
    if (!args_ok(__func__, resources, L, "L", b, "b", rowCount, rowSkip)) return;
    solve_transposed(resources, allowedThreadCount, L, b, rowCount, rowSkip);
}

// ---- scaling and L D L^T x = b ------------------------------------------------

typedef struct scale_job {
    dReal *v;
    const dReal *s;
    unsigned n;
} scale_job;

static void scale_piece(void *context, int item)
{
    const scale_job *j = context;
    const unsigned first = (unsigned)item * CHUNK, end = min_u(first + CHUNK, j->n);
    for (unsigned i = first; i < end; i++) j->v[i] *= j->s[i];
}

static void scale(dResourceContainerID rc, unsigned threads, dReal *v, const dReal *s,
                  unsigned n)
{
    scale_job j = { v, s, n };
    dxCoopRun(rc, threads, chunk_count(0, n), scale_piece, &j);
}

void dEstimateCooperativelyScaleVectorResourceRequirements(dResourceRequirementsID requirements,
                                                           unsigned maximalAllowedThreadCount,
                                                           unsigned maximalElementCount)
{
    dxCoopRequire(__func__, requirements, maximalAllowedThreadCount, maximalElementCount);
}

void dCooperativelyScaleVector(dResourceContainerID resources, unsigned allowedThreadCount,
                               dReal *dataVector, const dReal *scaleVector, unsigned elementCount)
{
    if (!args_ok(__func__, resources, dataVector, "dataVector", scaleVector, "scaleVector",
                 elementCount, elementCount))
        return;
    scale(resources, allowedThreadCount, dataVector, scaleVector, elementCount);
}

void dEstimateCooperativelySolveLDLTResourceRequirements(dResourceRequirementsID requirements,
                                                         unsigned maximalAllowedThreadCount,
                                                         unsigned maximalRowCount)
{
    dxCoopRequire(__func__, requirements, maximalAllowedThreadCount, maximalRowCount);
}

void dCooperativelySolveLDLT(dResourceContainerID resources, unsigned allowedThreadCount,
                             const dReal *L, const dReal *d, dReal *b, unsigned rowCount,
                             unsigned rowSkip)
{
    if (!args_ok(__func__, resources, L, "L", b, "b", rowCount, rowSkip)) return;
    DX_CHECK_ARG(d != NULL || rowCount == 0, return, "d is NULL");
    solve_straight(resources, allowedThreadCount, L, b, rowCount, rowSkip);
    scale(resources, allowedThreadCount, b, d, rowCount);
    solve_transposed(resources, allowedThreadCount, L, b, rowCount, rowSkip);
}
