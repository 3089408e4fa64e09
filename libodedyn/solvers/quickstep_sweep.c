// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_sweep.c -- one sweep of dWorldQuickStep's projected SOR over
// every block and every row of all islands (quickstep.h). This is where
// QuickStep spends its time: the updates work on fours and pairs of numbers
// (a body's 6 numbers as 4 + 2; a block's residuals, lambdas and Ainv res two
// rows at a time), the block updates (with their coupled rows, on the
// bodies' fc kept in registers) are inlined once per size and number of
// bodies so that the loops have constant bounds, and the row update branches
// only on one body or two.

#include "quickstep.h"
#include "quickstep_v4.h"
#include "dx_clones.h"

#include <string.h>

// The sweeps are built twice where the compiler can pick a version when the
// library is loaded (GNU ifunc: x86-64, ELF, glibc): for AVX2 and for the
// baseline. (-DQS_SWEEP_CLONES= builds the baseline alone, to compare the two.)
#if !defined(QS_SWEEP_CLONES) && defined(DX_AVX2_CLONES)
#define QS_SWEEP_CLONES DX_AVX2_CLONES
#endif
#ifndef QS_SWEEP_CLONES
#define QS_SWEEP_CLONES
#endif
// The same for dxQuickCoupledRows, called from quickstep_block_batch.c
// (dx_clones.h: clang builds such a function once).
#if defined(__clang__)
#define QS_SWEEP_EXTERN_CLONES
#else
#define QS_SWEEP_EXTERN_CLONES QS_SWEEP_CLONES
#endif

#if QS_FUSE
int dxQuickFused;

// dxQuickFused set when the library is loaded.
__attribute__((constructor)) static void find_fused_multiply_add(void)
{
    __builtin_cpu_init();
    dxQuickFused = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#else
int dxQuickFused = 0;
#endif

// The rows are read in a random order that hardware prefetchers cannot
// guess, and a big island's rows do not fit in the caches: the row this many
// places ahead is fetched while the current one is updated, when the rows
// take more than PREFETCH_BYTES (smaller ones stay in the caches). 8 rows
// (about 200 cycles of updates) cover a row's fetch from the last-level
// cache or memory; 3 did not (docs/perf.md: pyramid-40's sweeps).
#define PREFETCH_AHEAD 8
#define PREFETCH_BYTES ((size_t)256 * 1024)

// l projected on lo..hi (minsd, maxsd: no branches).
QS_INLINE dReal clamp(dReal l, dReal lo, dReal hi)
{
    l = l > hi ? hi : l;
    return l < lo ? lo : l;
}

// A body's 6 numbers of J, M or fc are a four and a pair (4 + 2;
// quickstep_v4.h), so that an update takes half the arithmetic of pairs
// alone where the machine has 4-wide vectors; sums are made in the same order
// either way.

// A body's 6 numbers of fc, in registers.
typedef struct qs_b6 {
    qs_v4 a;   // numbers 0-3
    qs_v2 b;   // numbers 4-5
} qs_b6;

QS_INLINE qs_b6 b6_load(const dReal *p)
{
    qs_b6 x = { v4_load(p), v2_load(p + 4) };
    return x;
}

QS_INLINE void b6_store(qs_b6 x, dReal *p)
{
    v4_store(x.a, p);
    v2_store(x.b, p + 4);
}

// One body's part of J . x (J: its 6 numbers), the two lanes not yet
// summed: lane k is (J_k x_k + J_k+2 x_k+2) + J_k+4 x_k+4, the last product
// fused into the sum if fu.
QS_INLINE qs_v2 b6_dot(const dReal *J, qs_b6 x, int fu)
{
    return qs_madd(v2_load(J + 4), x.b, v4_fold(v4_mul(v4_load(J), x.a)), fu);
}

// x + delta M for one body's 6 numbers of M (d4, d2: delta splat; fu:
// fused, quickstep.h).
QS_INLINE qs_b6 b6_add(qs_b6 x, qs_v4 d4, qs_v2 d2, const dReal *M, int fu)
{
    qs_b6 y = { v4_madd(d4, v4_load(M), x.a, fu), qs_madd(d2, v2_load(M + 4), x.b, fu) };
    return y;
}

// [sum of a's lanes, sum of b's lanes].
QS_INLINE qs_v2 hadd2(qs_v2 a, qs_v2 b)
{
#if defined(__GNUC__)
    const qs_v2 lo = { a[0], b[0] }, hi = { a[1], b[1] };
    return lo + hi;
#else
    qs_v2 v = { { a.e[0] + a.e[1], b.e[0] + b.e[1] } };
    return v;
#endif
}

// a's two lanes summed (lane 0 + lane 1: the same sum either way round),
// without moving lane 0 out first.
QS_INLINE dReal lane_sum(qs_v2 a)
{
#if defined(__GNUC__)
    return (a + __builtin_shufflevector(a, a, 1, 0))[0];
#else
    return a.e[0] + a.e[1];
#endif
}

// Row a's J . fc of a block (12 numbers a row: its first body's 6, then its
// second's), the two lanes not yet summed; np 3: one body.
QS_INLINE qs_v2 block_dot(const qs_v2 *J, int a, qs_b6 x0, qs_b6 x1, int np, int fu)
{
    const dReal *Ja = (const dReal *)(J + 6 * a);
    qs_v2 s = b6_dot(Ja, x0, fu);
    if (np == 6) s = qs_add(s, b6_dot(Ja + 6, x1, fu));
    return s;
}

// A block's delta (rows of Ainv in pairs, QS_PAD(n) wide): the residuals,
// delta = Ainv res and the lambdas two rows at a time, each lane computing
// exactly what its row alone would (fu: fused, quickstep.h).
QS_INLINE void block_delta(const qs_block *blk, int n, int np, qs_b6 x0, qs_b6 x1, dReal *l,
                           dReal *delta, int fu)
{
    const int w = QS_PAD(n);
    const qs_v2 *J = blk->J, *Ainv = (const qs_v2 *)blk->Ainv;
    qs_v2 res[QS_MAX_BLOCK / 2];   // in pairs: res[a / 2] lane a % 2
    for (int a = 0; a < QS_MAX_BLOCK / 2; a++) res[a] = qs_splat(0);   // (for the compiler)
    for (int a = 0; a < n; a += 2) {
        const qs_v2 sa = block_dot(J, a, x0, x1, np, fu);
        if (a + 1 < n) {
            const qs_v2 sb = block_dot(J, a + 1, x0, x1, np, fu);
            const qs_v2 cfm = v2_load(blk->cfm + a);   // r = rhs - cfm l
            const qs_v2 r = qs_madd(qs_neg(cfm), v2_load(l + a), v2_load(blk->rhs + a), fu);
            res[a / 2] = qs_sub(r, hadd2(sa, sb));
        } else {
            res[a / 2] = qs_splat(qs_madd1(-blk->cfm[a], l[a], blk->rhs[a], fu) - lane_sum(sa));
        }
    }
    for (int a = 0; a < w; a += 2) {
        qs_v2 d = qs_mul(Ainv[a / 2], qs_splat(qs_lane(res[0], 0)));
        for (int c = 1; c < n; c++)
            d = qs_madd(Ainv[(c * w + a) / 2], qs_splat(qs_lane(res[c / 2], c % 2)), d, fu);
        delta[a] = qs_lane(d, 0);
        if (a + 1 < n) {
            delta[a + 1] = qs_lane(d, 1);
            v2_store(qs_add(v2_load(l + a), d), l + a);
        } else {
            l[a] += qs_lane(d, 0);
        }
    }
}

// A row's J . fc for its bodies' fc x0 and x1 (np as below), the two lanes
// not yet summed: with p the products of the first body's 6 numbers and q
// the second's, lane k is ((p_k + q_k) + (p_k+2 + q_k+2)) + (p_k+4 + q_k+4)
// (one body: b6_dot), so that the bodies' fours and pairs are added before
// they are folded (two instructions fewer than folding each); if fu, each
// q fused into its sum with p.
QS_INLINE qs_v2 row_dot(const qs_row *q, int np, qs_b6 x0, qs_b6 x1, int fu)
{
    const dReal *J = (const dReal *)q->J, *J1 = (const dReal *)q->J1;
    if (np == 3) return b6_dot(J, x0, fu);
    const qs_v4 a = v4_madd(v4_load(J1), x1.a, v4_mul(v4_load(J), x0.a), fu);
    const qs_v2 b = qs_madd(v2_load(J1 + 4), x1.b, qs_mul(v2_load(J + 4), x0.b), fu);
    return qs_add(v4_fold(a), b);
}

// One row's update on its bodies' fc in registers x0 and x1 (np: 6 for two
// bodies, 3 for one, the second body's numbers being zeros that would add
// exact zeros; a constant after inlining): J . fc, the projected update of
// its lambda and fc += delta M. Returns delta. fu: fused (quickstep.h).
QS_INLINE dReal row_in_registers(const qs_row *q, int np, dReal *lambda, qs_b6 *x0, qs_b6 *x1,
                                 int fu)
{
    const dReal s = dFabs(lambda[q->f]), old = lambda[q->pos];
    const qs_v2 dot = row_dot(q, np, *x0, *x1, fu);
    const dReal now = clamp(qs_madd1(q->keep, old, q->rhs, fu) - lane_sum(dot), q->lo * s,
                            q->hi * s);
    lambda[q->pos] = now;
    const dReal delta = now - old;
    const qs_v4 d4 = v4_splat(delta);
    const qs_v2 d2 = qs_splat(delta);
    *x0 = b6_add(*x0, d4, d2, (const dReal *)q->M, fu);
    if (np == 6) *x1 = b6_add(*x1, d4, d2, (const dReal *)q->M1, fu);
    return delta;
}

// One coupled row of a block of n rows (quickstep.h), its bodies' fc in x0
// and x1 (np as for the block): the row update, and the block's lambdas
// moved by g delta.
QS_INLINE void coupled_row(const qs_row *q, int n, int np, dReal *lambda, qs_b6 *x0, qs_b6 *x1,
                           int fu)
{
    const dReal delta = row_in_registers(q, np, lambda, x0, x1, fu);
    const qs_v4 d4 = v4_splat(delta);
    dReal *lb = lambda + q->gfirst;
    int a = 0;
    for (; a + 4 <= n; a += 4)
        v4_store(v4_madd(d4, v4_load(q->g + a), v4_load(lb + a), fu), lb + a);
    for (; a < n; a++) lb[a] = qs_madd1(delta, q->g[a], lb[a], fu);
}

// One block update and its coupled rows; n and np (3: one body, 6: two) are
// constants after inlining. The fc of the bodies stays in registers until
// the coupled rows are done.
QS_INLINE void update_block(const qs_block *blk, const qs_row *coupled, int n, int np,
                            dReal *lambda, dReal *fc, int fu)
{
    dReal *f0 = fc + blk->o0, *f1 = fc + blk->o1, *l = lambda + blk->first;
    qs_b6 x0 = b6_load(f0), x1 = x0;
    if (np == 6) x1 = b6_load(f1);
    dReal delta[QS_MAX_BLOCK];
    block_delta(blk, n, np, x0, x1, l, delta, fu);
    for (int a = 0; a < n; a++) {
        const qs_v4 d4 = v4_splat(delta[a]);
        const qs_v2 d2 = qs_splat(delta[a]);
        const dReal *Ma = (const dReal *)(blk->M + 6 * a);
        x0 = b6_add(x0, d4, d2, Ma, fu);
        if (np == 6) x1 = b6_add(x1, d4, d2, Ma + 6, fu);
    }
    for (int c = 0; c < blk->ncoupled; c++) coupled_row(&coupled[c], n, np, lambda, &x0, &x1, fu);
    b6_store(x0, f0);
    if (np == 6) b6_store(x1, f1);
}

QS_INLINE void update_block_n(const qs_block *blk, const qs_row *coupled, int n, dReal *lambda,
                              dReal *fc, int fu)
{
    if (blk->two) update_block(blk, coupled, n, 6, lambda, fc, fu);
    else update_block(blk, coupled, n, 3, lambda, fc, fu);
}

// One free row, its bodies' fc loaded and stored back.
QS_INLINE void update_row(const qs_row *q, int np, dReal *lambda, dReal *fc, int fu)
{
    dReal *f0 = fc + q->o0, *f1 = fc + q->o1;
    qs_b6 x0 = b6_load(f0), x1 = x0;
    if (np == 6) x1 = b6_load(f1);
    row_in_registers(q, np, lambda, &x0, &x1, fu);
    b6_store(x0, f0);
    if (np == 6) b6_store(x1, f1);
}

// A free row: one body or two.
QS_INLINE void update_free_row(const qs_row *q, dReal *lambda, dReal *fc, int fu)
{
    if (q->two) update_row(q, 6, lambda, fc, fu);
    else update_row(q, 3, lambda, fc, fu);
}

// Ask for every 64-byte line of a row (four in double). Every other line
// was enough on AMD's Zen, where the neighbouring line came along in time
// (all four: 1.6 % slower there); Intel's spatial prefetcher brings it only
// as far as the second-level cache, and the row's J then waited on it: all
// four make pyramid-40 10-17 % and spheres 13-15 % faster on an Ice Lake
// Xeon (docs/perf.md, "The row sweep on Intel").
QS_INLINE void prefetch_row(const qs_row *q)
{
    const char *p = (const char *)q;
    for (size_t at = 0; at < sizeof *q; at += 64) qs_prefetch(p + at);
}

// One block of any size and its coupled rows.
QS_INLINE void update_any_block(const qs_block *blk, const qs_row *rows, dReal *lambda,
                                dReal *fc, int fu)
{
    const qs_row *coupled = rows + blk->coupled;
#ifdef QS_ANY_SIZE
    update_block_n(blk, coupled, blk->n, lambda, fc, fu);
#else
    switch (blk->n) {   // constant sizes let the compiler unroll
    case 2: update_block_n(blk, coupled, 2, lambda, fc, fu); break;
    case 3: update_block_n(blk, coupled, 3, lambda, fc, fu); break;
    case 4: update_block_n(blk, coupled, 4, lambda, fc, fu); break;
    case 5: update_block_n(blk, coupled, 5, lambda, fc, fu); break;
    default: update_block_n(blk, coupled, QS_MAX_BLOCK, lambda, fc, fu); break;
    }
#endif
}

// The coupled rows of one block of n rows (np as for the block), its
// bodies' fc loaded and stored back.
QS_INLINE void coupled_rows(const qs_block *blk, const qs_row *coupled, int n, int np,
                            dReal *lambda, dReal *fc, int fu)
{
    dReal *f0 = fc + blk->o0, *f1 = fc + blk->o1;
    qs_b6 x0 = b6_load(f0), x1 = x0;
    if (np == 6) x1 = b6_load(f1);
    for (int c = 0; c < blk->ncoupled; c++) coupled_row(&coupled[c], n, np, lambda, &x0, &x1, fu);
    b6_store(x0, f0);
    if (np == 6) b6_store(x1, f1);
}

QS_INLINE void coupled_rows_n(const qs_block *blk, const qs_row *coupled, int n, dReal *lambda,
                              dReal *fc, int fu)
{
    if (blk->two) coupled_rows(blk, coupled, n, 6, lambda, fc, fu);
    else coupled_rows(blk, coupled, n, 3, lambda, fc, fu);
}

QS_INLINE void coupled_rows_with(const qs_block *blk, const qs_row *rows, dReal *lambda,
                                 dReal *fc, int fu)
{
    const qs_row *coupled = rows + blk->coupled;
#ifdef QS_ANY_SIZE
    coupled_rows_n(blk, coupled, blk->n, lambda, fc, fu);
#else
    switch (blk->n) {
    case 2: coupled_rows_n(blk, coupled, 2, lambda, fc, fu); break;
    case 3: coupled_rows_n(blk, coupled, 3, lambda, fc, fu); break;
    case 4: coupled_rows_n(blk, coupled, 4, lambda, fc, fu); break;
    case 5: coupled_rows_n(blk, coupled, 5, lambda, fc, fu); break;
    default: coupled_rows_n(blk, coupled, QS_MAX_BLOCK, lambda, fc, fu); break;
    }
#endif
}

QS_SWEEP_CLONES static void coupled_rows_plain(const qs_block *blk, const qs_row *rows,
                                                      dReal *lambda, dReal *fc)
{
    coupled_rows_with(blk, rows, lambda, fc, 0);
}

#if QS_FUSE
QS_FUSED_VERSION static void coupled_rows_fused(const qs_block *blk, const qs_row *rows,
                                                dReal *lambda, dReal *fc)
{
    coupled_rows_with(blk, rows, lambda, fc, 1);
}
#endif

void dxQuickCoupledRows(const qs_block *blk, const qs_row *rows, dReal *lambda, dReal *fc)
{
#if QS_FUSE
    if (dxQuickFused) {
        coupled_rows_fused(blk, rows, lambda, fc);
        return;
    }
#endif
    coupled_rows_plain(blk, rows, lambda, fc);
}

// The blocks in bseq, each followed by its coupled rows; or their batches.
QS_INLINE void sweep_blocks_with(const qs_system *sys, int fu)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    if (sys->batches) {
        for (int k = 0; k < sys->nbatches; k++) {
            const qs_batch *b = &sys->batches[k];
            if (b->soa) dxQuickBatchUpdate(b, sys->rows, lambda, fc);
            else update_any_block(b->blk[0], sys->rows, lambda, fc, fu);
        }
        return;
    }
    for (int k = 0; k < sys->nblocks; k++)
        update_any_block(sys->bseq[k], sys->rows, lambda, fc, fu);
}

QS_SWEEP_CLONES static void sweep_blocks_plain(const qs_system *sys)
{
    sweep_blocks_with(sys, 0);
}

#if QS_FUSE
QS_FUSED_VERSION static void sweep_blocks_fused(const qs_system *sys)
{
    sweep_blocks_with(sys, 1);
}
#endif

QS_INLINE void overlapped_with(const qs_system *sys, const qs_block *blk, int n, int lag,
                               int iterations, int fu)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    const int end = n + (iterations - 1) * lag;   // the last time, plus one
    for (int t = 0; t < end; t++) {
        // Sweeps s0 to s1 have a block at time t: t - s lag in [0, n).
        const int s0 = t < n ? 0 : (t - n) / lag + 1;
        const int s1 = t / lag < iterations ? t / lag : iterations - 1;
        const qs_block *b = blk + (t - s0 * lag);
        for (int s = s0; s <= s1; s++, b -= lag) update_any_block(b, sys->rows, lambda, fc, fu);
    }
}

QS_SWEEP_CLONES static void overlapped_plain(const qs_system *sys, const qs_block *blk,
                                                    int n, int lag, int iterations)
{
    overlapped_with(sys, blk, n, lag, iterations, 0);
}

#if QS_FUSE
QS_FUSED_VERSION static void overlapped_fused(const qs_system *sys, const qs_block *blk, int n,
                                              int lag, int iterations)
{
    overlapped_with(sys, blk, n, lag, iterations, 1);
}
#endif

void dxQuickSweepOverlapped(const qs_system *sys, const qs_block *blk, int n, int lag,
                            int iterations)
{
#if QS_FUSE
    if (dxQuickFused) {
        overlapped_fused(sys, blk, n, lag, iterations);
        return;
    }
#endif
    overlapped_plain(sys, blk, n, lag, iterations);
}

// (quickstep.h)
QS_SWEEP_EXTERN_CLONES void dxQuickRowsOf(const qs_row **to, const qs_row *rows, const int *from,
                                          int n)
{
    for (int k = 0; k < n; k++) to[k] = rows + from[k];
}

// The rows in seq; those of a big system (beyond PREFETCH_BYTES) fetched
// ahead.
QS_INLINE void sweep_rows_with(const qs_system *sys, int fu)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    const qs_row *const *seq = sys->seq;
    const int n = sys->norder;
    if ((size_t)n * sizeof(qs_row) < PREFETCH_BYTES) {
        for (int k = 0; k < n; k++) update_free_row(seq[k], lambda, fc, fu);
        return;
    }
    int k = 0;
    for (; k + PREFETCH_AHEAD < n; k++) {
        prefetch_row(seq[k + PREFETCH_AHEAD]);
        update_free_row(seq[k], lambda, fc, fu);
    }
    for (; k < n; k++) update_free_row(seq[k], lambda, fc, fu);
}

QS_SWEEP_CLONES static void sweep_rows_plain(const qs_system *sys)
{
    sweep_rows_with(sys, 0);
}

#if QS_FUSE
QS_FUSED_VERSION static void sweep_rows_fused(const qs_system *sys)
{
    sweep_rows_with(sys, 1);
}
#endif

void dxQuickSweep(const qs_system *sys, int rows_first)
{
#if QS_FUSE
    if (dxQuickFused) {
        if (rows_first) sweep_rows_fused(sys);
        sweep_blocks_fused(sys);
        if (!rows_first) sweep_rows_fused(sys);
        return;
    }
#endif
    if (rows_first) sweep_rows_plain(sys);
    sweep_blocks_plain(sys);
    if (!rows_first) sweep_rows_plain(sys);
}
