// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_sweep.c -- one sweep of dWorldQuickStep's projected SOR over
// every block and every row of all islands (quickstep.h). This is where
// QuickStep spends its time: the updates work on pairs of numbers (a block's
// residuals, lambdas and Ainv res two rows at a time), the block updates are
// inlined once per size so that the loops have constant bounds, and the row
// update branches only on one body or two.

#include "quickstep.h"

#include <string.h>

// The rows are read in a random order that hardware prefetchers cannot
// guess, and a big island's rows do not fit in the caches: the row this many
// places ahead is fetched while the current one is updated, when the rows
// take more than PREFETCH_BYTES (smaller ones stay in the caches).
#define PREFETCH_AHEAD 3
#define PREFETCH_BYTES ((size_t)256 * 1024)

// l projected on lo..hi (minsd, maxsd: no branches).
QS_INLINE dReal clamp(dReal l, dReal lo, dReal hi)
{
    l = l > hi ? hi : l;
    return l < lo ? lo : l;
}

QS_INLINE qs_v2 load2(const dReal *p)
{
    qs_v2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

QS_INLINE void store2(qs_v2 v, dReal *p)
{
    memcpy(p, &v, sizeof v);
}

// x += delta M for np pairs.
QS_INLINE void add_pairs(qs_v2 *x, dReal delta, const qs_v2 *M, int np)
{
    const qs_v2 k = qs_splat(delta);
    for (int e = 0; e < np; e++) x[e] = qs_add(x[e], qs_mul(k, M[e]));
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

// J . x for np pairs of J and x (3 or 6), the two lanes not yet summed.
QS_INLINE qs_v2 dot_lanes(const qs_v2 *J, const qs_v2 *x, int np)
{
    qs_v2 s = qs_add(qs_add(qs_mul(J[0], x[0]), qs_mul(J[1], x[1])), qs_mul(J[2], x[2]));
    if (np == 6)
        s = qs_add(s, qs_add(qs_add(qs_mul(J[3], x[3]), qs_mul(J[4], x[4])), qs_mul(J[5], x[5])));
    return s;
}

// One block update; n and np (3: one body, 6: two) are constants after
// inlining. The residuals, delta = Ainv res and the lambdas go two rows at a
// time (each lane computing exactly what a row alone would).
QS_INLINE void update_block(const qs_block *blk, int n, int np, dReal *lambda, dReal *fc)
{
    const int w = QS_PAD(n);
    const qs_v2 *J = blk->J, *M = blk->M;
    const qs_v2 *Ainv = (const qs_v2 *)blk->Ainv;   // rows of w / 2 pairs
    dReal *f0 = fc + blk->o0, *f1 = fc + blk->o1, *l = lambda + blk->first;
    qs_v2 x[6] = { load2(f0), load2(f0 + 2), load2(f0 + 4) };
    if (np == 6) {
        x[3] = load2(f1);
        x[4] = load2(f1 + 2);
        x[5] = load2(f1 + 4);
    }
    qs_v2 res[QS_MAX_BLOCK / 2];   // in pairs: res[a / 2] lane a % 2
    for (int a = 0; a < QS_MAX_BLOCK / 2; a++) res[a] = qs_splat(0);   // (for the compiler)
    for (int a = 0; a < n; a += 2) {
        const qs_v2 sa = dot_lanes(J + 6 * a, x, np);
        if (a + 1 < n) {
            const qs_v2 sb = dot_lanes(J + 6 * (a + 1), x, np);
            const qs_v2 r = qs_sub(load2(blk->rhs + a), qs_mul(load2(blk->cfm + a), load2(l + a)));
            res[a / 2] = qs_sub(r, hadd2(sa, sb));
        } else {
            res[a / 2] = qs_splat(blk->rhs[a] - blk->cfm[a] * l[a] -
                                  (qs_lane(sa, 0) + qs_lane(sa, 1)));
        }
    }
    dReal delta[QS_MAX_BLOCK];
    for (int a = 0; a < w; a += 2) {
        qs_v2 d = qs_mul(Ainv[a / 2], qs_splat(qs_lane(res[0], 0)));
        for (int c = 1; c < n; c++)
            d = qs_add(d, qs_mul(Ainv[(c * w + a) / 2], qs_splat(qs_lane(res[c / 2], c % 2))));
        delta[a] = qs_lane(d, 0);
        if (a + 1 < n) {
            delta[a + 1] = qs_lane(d, 1);
            store2(qs_add(load2(l + a), d), l + a);
        } else {
            l[a] += qs_lane(d, 0);
        }
    }
    for (int a = 0; a < n; a++) add_pairs(x, delta[a], M + 6 * a, np);
    for (int e = 0; e < 3; e++) {
        store2(x[e], f0 + 2 * e);
        if (np == 6) store2(x[3 + e], f1 + 2 * e);
    }
}

QS_INLINE void update_block_n(const qs_block *blk, int n, dReal *lambda, dReal *fc)
{
    if (blk->two) update_block(blk, n, 6, lambda, fc);
    else update_block(blk, n, 3, lambda, fc);
}

// One row: J . fc of its bodies, the projected update of its lambda,
// fc += delta M, and (coupled, a constant after inlining) the block it moves
// along. np: 6 for two bodies, 3 for one (the second body's numbers are
// zeros and would add exact zeros), a constant after inlining.
QS_INLINE void update_row(const qs_row *q, int coupled, int np, dReal *lambda, dReal *fc)
{
    dReal *f0 = fc + q->o0, *f1 = fc + q->o1;
    qs_v2 x[3] = { load2(f0), load2(f0 + 2), load2(f0 + 4) };
    qs_v2 y[3];
    const dReal s = dFabs(lambda[q->f]), old = lambda[q->pos];
    qs_v2 dot = qs_add(qs_add(qs_mul(q->J[0], x[0]), qs_mul(q->J[1], x[1])),
                       qs_mul(q->J[2], x[2]));
    if (np == 6) {
        y[0] = load2(f1);
        y[1] = load2(f1 + 2);
        y[2] = load2(f1 + 4);
        dot = qs_add(dot, qs_add(qs_add(qs_mul(q->J1[0], y[0]), qs_mul(q->J1[1], y[1])),
                                 qs_mul(q->J1[2], y[2])));
    }
    const dReal now = clamp(old + q->rhs - q->cfm * old - (qs_lane(dot, 0) + qs_lane(dot, 1)),
                            q->lo * s, q->hi * s);
    lambda[q->pos] = now;
    const dReal delta = now - old;
    add_pairs(x, delta, q->M, 3);
    for (int e = 0; e < 3; e++) store2(x[e], f0 + 2 * e);
    if (np == 6) {
        add_pairs(y, delta, q->M1, 3);
        for (int e = 0; e < 3; e++) store2(y[e], f1 + 2 * e);
    }
    if (coupled)
        for (int a = 0; a < q->gn; a++) lambda[q->gfirst + a] += delta * q->g[a];
}

// A free row: one body or two.
QS_INLINE void update_free_row(const qs_row *q, dReal *lambda, dReal *fc)
{
    if (q->two) update_row(q, 0, 6, lambda, fc);
    else update_row(q, 0, 3, lambda, fc);
}

// Ask for a row's 256 bytes: every other 64-byte line, the neighbouring
// line comes along.
QS_INLINE void prefetch_row(const qs_row *q)
{
#if defined(__GNUC__)
    __builtin_prefetch(q);
    __builtin_prefetch((const char *)q + 128);
#else
    (void)q;
#endif
}

// The blocks in bseq, each followed by its coupled rows.
static void sweep_blocks(const qs_system *sys)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    for (int k = 0; k < sys->nblocks; k++) {
        const qs_block *blk = sys->bseq[k];
        switch (blk->n) {   // constant sizes let the compiler unroll
        case 2: update_block_n(blk, 2, lambda, fc); break;
        case 3: update_block_n(blk, 3, lambda, fc); break;
        case 4: update_block_n(blk, 4, lambda, fc); break;
        case 5: update_block_n(blk, 5, lambda, fc); break;
        default: update_block_n(blk, QS_MAX_BLOCK, lambda, fc); break;
        }
        for (int c = 0; c < blk->ncoupled; c++)
            update_row(&sys->rows[blk->coupled + c], 1, 6, lambda, fc);
    }
}

// The rows in seq; those of a big system (beyond PREFETCH_BYTES) fetched
// ahead.
static void sweep_rows(const qs_system *sys)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    const qs_row *rows = sys->rows;
    const int *order = sys->seq, n = sys->norder;
    if ((size_t)n * sizeof(qs_row) < PREFETCH_BYTES) {
        for (int k = 0; k < n; k++) update_free_row(&rows[order[k]], lambda, fc);
        return;
    }
    for (int k = 0; k < n; k++) {
        if (k + PREFETCH_AHEAD < n) prefetch_row(&rows[order[k + PREFETCH_AHEAD]]);
        update_free_row(&rows[order[k]], lambda, fc);
    }
}

void dxQuickSweep(const qs_system *sys, int rows_first)
{
    if (rows_first) sweep_rows(sys);
    sweep_blocks(sys);
    if (!rows_first) sweep_rows(sys);
}
