// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_block_batch.c -- QuickStep's joint blocks four at a time
// (quickstep.h: qs_batch). A block update is one long chain of dependent
// operations (its residuals wait for its dots, delta for the Ainv sums, fc
// for n multiply-adds), so a sweep over blocks one by one waits on it. But
// Gauss-Seidel's result depends only on the order of the updates that share
// a body: blocks of different bodies can go side by side. bseq interleaves
// the islands of each group (identical ragdolls or cars give the same joint
// kind at the same place in turn), so its blocks are packed once per step,
// group by group, in batches of four blocks of the same size and number of
// bodies, one block a SIMD lane.
//
// Each lane does exactly its block's operations in the order of the block
// update of quickstep_sweep.c (the same products, the same order of sums,
// multiply-adds fused at the same places in its fused version, quickstep.h:
// qs_madd), so the results are the same bits as there: fc's numbers e and
// e + 2 are summed first, then e + 4, a second body's sum is added to the
// first's, then lane 0's sum to lane 1's; delta is Ainv's column products
// summed in row order. The blocks' coupled rows (they touch only their
// block's bodies and lambdas) follow side by side when every lane has as
// many, else each lane's on their own.

#include "quickstep.h"
#include "quickstep_v4.h"
#include "dx_clones.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

int dxQuickBlockBatches = 1;

// Built for AVX2 and for the baseline, as the sweeps (quickstep_sweep.c);
// the same numbers either way. -DQS_BATCH_CLONES= builds the baseline
// alone. Clang builds the baseline alone, as quickstep_contact.c does (it
// refuses fours passed between the baseline clone's inlined functions).
#if !defined(QS_BATCH_CLONES) && !defined(__clang__) && defined(DX_AVX2_CLONES)
#define QS_BATCH_CLONES DX_AVX2_CLONES
#endif
#ifndef QS_BATCH_CLONES
#define QS_BATCH_CLONES
#endif

// ---- packing -------------------------------------------------------------------

// A batch's copy leaves out what the rows' structure makes known. Ainv is
// symmetric: its lower triangle is enough. A block of the ball form (the
// rows of ball, hinge, universal and fixed joints) has more: its first
// three rows' J_lin are the unit vectors e_0, e_1, e_2 (the second body's
// -e_0, -e_1, -e_2) and its other rows' zero, so its dots take fc's linear
// numbers as they are (x for 1 x, subtracted for -1 x), and, as M^-1 J^T's
// linear part is im J_lin (quickstep_build.c: side_parts; im the body's
// inverse mass), fc's linear numbers change by im delta of their own row
// alone; a lane holds per row J's and M^-1 J^T's angular parts (3 + 3 a
// body) and the bodies' inverse masses. Other blocks (the general form)
// keep J and M^-1 J^T in full.
// Every product and sum the ball form's update makes is the same number as
// the full form's but for the zero products it leaves out. Those change at
// most the sign of a zero in a dot or a delta, which no state can see: fc
// and a block's lambdas start at +0 or a nonzero number and only ever have
// numbers added, so they are never -0, and x + (+-0) is x.
enum { SOA_GENERAL = 0, SOA_BALL = 1 };
// Numbers a lane holds per row of J (je) and of M (me) and per block of
// inverse masses (mass), for a block of the given form on two + 1 bodies.
#define SOA_JE(form, two) ((form) ? ((two) ? 6 : 3) : ((two) ? 12 : 6))
#define SOA_ME(form, two) ((form) ? ((two) ? 6 : 3) : ((two) ? 12 : 6))
#define SOA_MASS(form, two) ((form) ? (two) + 1 : 0)
// Place of Ainv's (c, a) in its lower triangle (Ainv is symmetric).
#define SOA_TRI(c, a) ((c) >= (a) ? (c) * ((c) + 1) / 2 + (a) : (a) * ((a) + 1) / 2 + (c))

// The numbers of a full batch of blocks of n rows of a form on `two` + 1
// bodies: J and M (n rows of je and me numbers), the inverse masses,
// Ainv's lower triangle, rhs and cfm (n); then per coupled row (ncoupled
// of each lane) its J and M in full (ne = 6 or 12), rhs, keep, lo, hi and g
// (n). Each number QS_LANES times, one a lane.
static size_t soa_size(int n, int form, int two, int ncoupled)
{
    const size_t ne = two ? 12 : 6, nn = (size_t)n;
    return QS_LANES * (nn * (size_t)(SOA_JE(form, two) + SOA_ME(form, two)) +
                       (size_t)SOA_MASS(form, two) + nn * (nn + 1) / 2 + 2 * nn +
                       (size_t)ncoupled * (2 * ne + 4 + nn));
}

// Block blk's form (above): the ball form if its rows have that
// structure. Equal as numbers is enough: a zero of the other sign only
// changes zero products' signs.
static int block_form(const qs_block *blk)
{
    if (blk->n < 3) return SOA_GENERAL;
    const dReal *J = (const dReal *)blk->J;
    for (int a = 0; a < blk->n; a++, J += 12)
        for (int e = 0; e < 3; e++) {
            const dReal unit = a == e ? 1 : 0;
            if (!(J[e] == unit && (!blk->two || J[6 + e] == -unit))) return SOA_GENERAL;
        }
    return SOA_BALL;
}

// dst[QS_LANES k + i] = src[i][k] for k < count: count numbers of each of
// the four lanes' sources, interleaved by lane; fours of them by 4 x 4
// transposes, then a pair by two (a constant count unrolls it).
QS_INLINE void lanes_copy(dReal *dst, const dReal *const src[QS_LANES], int count)
{
    int k = 0;
#if defined(__GNUC__)
    for (; k + 4 <= count; k += 4, dst += 4 * QS_LANES) {
        qs_v4 t[4];
        v4_transpose(v4_load(src[0] + k), v4_load(src[1] + k), v4_load(src[2] + k),
                     v4_load(src[3] + k), t);
        for (int e = 0; e < 4; e++) v4_store(t[e], dst + QS_LANES * e);
    }
    if (k + 2 <= count) {
        const qs_v4 c02 = __builtin_shufflevector(v2_load(src[0] + k), v2_load(src[2] + k), 0, 1, 2, 3);
        const qs_v4 c13 = __builtin_shufflevector(v2_load(src[1] + k), v2_load(src[3] + k), 0, 1, 2, 3);
        v4_store(__builtin_shufflevector(c02, c13, 0, 4, 2, 6), dst);
        v4_store(__builtin_shufflevector(c02, c13, 1, 5, 3, 7), dst + QS_LANES);
        k += 2;
        dst += 2 * QS_LANES;
    }
#endif
    for (; k < count; k++, dst += QS_LANES)
        for (int i = 0; i < QS_LANES; i++) dst[i] = src[i][k];
}

// The sources of lanes_copy: p[i] plus `at` numbers.
QS_INLINE void lanes_at(const dReal *src[QS_LANES], const dReal *const p[QS_LANES], int at)
{
    for (int i = 0; i < QS_LANES; i++) src[i] = p[i] + at;
}

// Copy the numbers of the four blocks blk (n rows, form, two: on two
// bodies, nc coupled rows: constants after inlining) into their lanes of a
// full batch's soa, in the layout of soa_size.
QS_INLINE void soa_fill(dReal *s, const qs_block *const blk[QS_LANES], const qs_row *rows,
                        const dReal *inv_mass, int n, int form, int two, int nc)
{
    const int w = QS_PAD(n), je = SOA_JE(form, two), me = SOA_ME(form, two);
    const int ne = two ? 12 : 6, e0 = form == SOA_BALL ? 3 : 0;
    const dReal *J[QS_LANES], *M[QS_LANES], *src[QS_LANES];
    for (int i = 0; i < QS_LANES; i++) {
        J[i] = (const dReal *)blk[i]->J;
        M[i] = (const dReal *)blk[i]->M;
    }
    if (form == SOA_GENERAL && two) {   // rows of 12 numbers (quickstep.h), all kept
        lanes_copy(s, J, 12 * n);
        s += QS_LANES * 12 * n;
        lanes_copy(s, M, 12 * n);
        s += QS_LANES * 12 * n;
    } else {
        // A ball form's first body's three angular numbers are copied as a
        // four (the row's next number along): the slot that fourth one fills
        // is the second body's, the next row's or the next part's (M after
        // J, the masses after M), copied after it.
        const int first = form == SOA_BALL ? 4 : 6 - e0;
        for (int m = 0; m < 2; m++) {   // J, then M
            const dReal *const *from = m ? M : J;
            for (int a = 0; a < n; a++, s += QS_LANES * (m ? me : je)) {
                lanes_at(src, from, 12 * a + e0);
                lanes_copy(s, src, first);
                if (two) {
                    lanes_at(src, from, 12 * a + 6 + e0);
                    lanes_copy(s + QS_LANES * (6 - e0), src, 6 - e0);
                }
            }
        }
    }
    if (form == SOA_BALL)
        for (int i = 0; i < QS_LANES; i++) {
            s[i] = inv_mass[blk[i]->o0 / 6];
            if (two) s[QS_LANES + i] = inv_mass[blk[i]->o1 / 6];
        }
    s += QS_LANES * SOA_MASS(form, two);
    for (int c = 0; c < n; c++) {   // Ainv's row c up to its diagonal
        for (int i = 0; i < QS_LANES; i++) src[i] = blk[i]->Ainv + c * w;
        lanes_copy(s + QS_LANES * SOA_TRI(c, 0), src, c + 1);
    }
    s += QS_LANES * n * (n + 1) / 2;
    for (int i = 0; i < QS_LANES; i++) src[i] = blk[i]->rhs;
    lanes_copy(s, src, n);
    for (int i = 0; i < QS_LANES; i++) src[i] = blk[i]->cfm;
    lanes_copy(s + QS_LANES * n, src, n);
    s += QS_LANES * 2 * n;
    for (int c = 0; c < nc; c++) {
        const qs_row *q[QS_LANES];
        for (int i = 0; i < QS_LANES; i++) q[i] = rows + blk[i]->coupled + c;
        // J, J1, M, M1 (6 numbers each) to soa's J, J1, M, M1; a one-body
        // row's J1 and M1 (zero) are left out.
        static const size_t from[4] = { offsetof(qs_row, J), offsetof(qs_row, J1),
                                        offsetof(qs_row, M), offsetof(qs_row, M1) };
        const int to[4] = { 0, 6, ne, ne + 6 };
        for (int part = 0; part < 4; part += two ? 1 : 2) {
            for (int i = 0; i < QS_LANES; i++)
                src[i] = (const dReal *)((const char *)q[i] + from[part]);
            lanes_copy(s + QS_LANES * to[part], src, 6);
        }
        s += QS_LANES * 2 * ne;
        for (int i = 0; i < QS_LANES; i++) src[i] = &q[i]->rhs;   // rhs, keep, lo, hi
        lanes_copy(s, src, 4);
        s += 4 * QS_LANES;
        for (int i = 0; i < QS_LANES; i++) src[i] = q[i]->g;
        lanes_copy(s, src, n);
        s += QS_LANES * n;
    }
}

QS_INLINE void soa_fill_n(dReal *soa, const qs_block *const blk[QS_LANES], const qs_row *rows,
                          const dReal *inv_mass, int n, int form, int nc)
{
    if (form == SOA_BALL) {
        if (blk[0]->two) soa_fill(soa, blk, rows, inv_mass, n, SOA_BALL, 1, nc);
        else soa_fill(soa, blk, rows, inv_mass, n, SOA_BALL, 0, nc);
    } else {
        if (blk[0]->two) soa_fill(soa, blk, rows, inv_mass, n, SOA_GENERAL, 1, nc);
        else soa_fill(soa, blk, rows, inv_mass, n, SOA_GENERAL, 0, nc);
    }
}

// Full batch b's numbers into its soa in the batch's form, with nc coupled
// rows' (nc: the batch's ncoupled, or 0 when its lanes differ).
QS_INLINE void soa_copy(const qs_batch *b, const qs_row *rows, const dReal *inv_mass, int nc)
{
    dReal *soa = (dReal *)b->soa;
#ifdef QS_ANY_SIZE
    soa_fill(soa, b->blk, rows, inv_mass, b->n, b->form, b->blk[0]->two != 0, nc);
#else
    switch (b->n) {   // constant sizes let the compiler unroll
    case 2: soa_fill_n(soa, b->blk, rows, inv_mass, 2, b->form, nc); break;
    case 3: soa_fill_n(soa, b->blk, rows, inv_mass, 3, b->form, nc); break;
    case 4: soa_fill_n(soa, b->blk, rows, inv_mass, 4, b->form, nc); break;
    case 5: soa_fill_n(soa, b->blk, rows, inv_mass, 5, b->form, nc); break;
    default: soa_fill_n(soa, b->blk, rows, inv_mass, QS_MAX_BLOCK, b->form, nc); break;
    }
#endif
}

// Can block blk's coupled rows go side by side with other lanes': none reads
// its bound from the block's own lambdas (the block's lambdas stay in
// registers while its coupled rows are updated)?
static int coupled_apart(const qs_block *blk, const qs_row *rows)
{
    for (int c = 0; c < blk->ncoupled; c++) {
        const int f = rows[blk->coupled + c].f;
        if (f >= blk->first && f < blk->first + blk->n) return 0;
    }
    return 1;
}

QS_BATCH_CLONES void dxQuickBatchBlocks(dxArena *a, qs_system *sys, qs_group *groups, int ngroups)
{
    sys->batches = NULL;
    sys->nbatches = 0;
    // The groups' blocks (islands swept on their own are in none).
    const int nb = ngroups > 0 ? groups[ngroups - 1].block0 + groups[ngroups - 1].nblocks : 0;
    int several = 0;   // a group of two islands or more
    for (int g = 0; g < ngroups; g++) several |= groups[g].islands >= 2;
    if (!dxQuickBlockBatches || nb < QS_LANES || !several) return;
    // Each block's batch (slot) by bseq's order: the latest batch of its kind
    // (size, bodies, form) in its group if that has a free lane and comes after
    // every batch holding an earlier block on one of its bodies (last), else
    // a new one. Per batch: its blocks (count) and their common number of
    // coupled rows (nc; -1: they differ), their form. Per group: its first
    // batch.
    int *last = DX_ARENA_ARRAY(a, int, sys->nbodies);
    int *slot = DX_ARENA_ARRAY(a, int, nb);
    int *count = DX_ARENA_ARRAY(a, int, nb), *nc = DX_ARENA_ARRAY(a, int, nb);
    int *first = DX_ARENA_ARRAY(a, int, ngroups + 1);
    int *forms = DX_ARENA_ARRAY(a, int, nb);
    int open[4 * (QS_MAX_BLOCK + 1)];   // per kind: its latest batch
    for (int b = 0; b < sys->nbodies; b++) last[b] = -1;
    int nbatch = 0, full = 0;
    for (int g = 0; g < ngroups; g++) {
        first[g] = nbatch;
        for (int k = 0; k < 4 * (QS_MAX_BLOCK + 1); k++) open[k] = -1;
        const int apart = groups[g].islands < 2;   // each block a batch of its own
        for (int k = groups[g].block0; k < groups[g].block0 + groups[g].nblocks; k++) {
            const qs_block *blk = sys->bseq[k];
            const int b0 = blk->o0 / 6, b1 = blk->o1 / 6;
            int after = last[b0];
            if (blk->two && last[b1] > after) after = last[b1];
            const int ncoupled = coupled_apart(blk, sys->rows) ? blk->ncoupled : -1;
            const int form = block_form(blk);
            const int kind = 2 * (2 * blk->n + blk->two) + form;
            int t = open[kind];
            if (apart || t < 0 || t <= after || count[t] == QS_LANES) {
                t = open[kind] = nbatch++;
                count[t] = 0;
                nc[t] = ncoupled;
                forms[t] = form;
            }
            if (nc[t] != ncoupled) nc[t] = -1;
            if (++count[t] == QS_LANES) full++;
            slot[k] = t;
            last[b0] = t;
            if (blk->two) last[b1] = t;
        }
    }
    first[ngroups] = nbatch;
    if (full == 0) return;
    // The sweep's entries: a full batch is one, a partial one's blocks are
    // one each (start: each batch's first entry; fill: its blocks so far).
    int *start = DX_ARENA_ARRAY(a, int, nbatch + 1), *fill = DX_ARENA_ARRAY(a, int, nbatch);
    sys->nbatches = 0;
    for (int t = 0; t < nbatch; t++) {
        start[t] = sys->nbatches;
        sys->nbatches += count[t] == QS_LANES ? 1 : count[t];
        fill[t] = 0;
    }
    start[nbatch] = sys->nbatches;
    for (int g = 0; g < ngroups; g++) {
        groups[g].batch0 = start[first[g]];
        groups[g].nbatches = start[first[g + 1]] - groups[g].batch0;
    }
    qs_batch *out = DX_ARENA_ARRAY(a, qs_batch, sys->nbatches);
    for (int k = 0; k < nb; k++) {
        const qs_block *blk = sys->bseq[k];
        const int t = slot[k];
        if (count[t] < QS_LANES) {
            qs_batch *one = &out[start[t] + fill[t]++];
            memset(one, 0, sizeof *one);
            one->blk[0] = blk;
            continue;
        }
        qs_batch *b = &out[start[t]];
        const int i = fill[t]++, c = nc[t] > 0 ? nc[t] : 0;
        if (i == 0) {
            b->soa = DX_ARENA_ARRAY(a, dReal, soa_size(blk->n, forms[t], blk->two, c));
            b->ncoupled = nc[t];
            b->form = forms[t];
            b->n = blk->n;
            b->two = blk->two;
            b->cpos = c > 0 ? DX_ARENA_ARRAY(a, int, 2 * QS_LANES * c) : NULL;
        }
        b->blk[i] = blk;
        b->o0[i] = blk->o0;
        b->o1[i] = blk->o1;
        b->first[i] = blk->first;
        for (int r = 0; r < c; r++) {
            int *cpos = (int *)b->cpos + 2 * QS_LANES * r;
            cpos[i] = sys->rows[blk->coupled + r].pos;
            cpos[QS_LANES + i] = sys->rows[blk->coupled + r].f;
        }
        if (i == QS_LANES - 1) soa_copy(b, sys->rows, sys->inv_mass, c);
    }
    sys->batches = out;
}

// ---- the update ----------------------------------------------------------------

// p[0][e], p[1][e], p[2][e], p[3][e].
QS_INLINE qs_v4 qb_gather(dReal *const *p, int e)
{
    qs_v4 v;
    for (int i = 0; i < QS_LANES; i++) v4_lane(v, i) = p[i][e];
    return v;
}

QS_INLINE void qb_scatter(qs_v4 v, dReal *const *p, int e)
{
    for (int i = 0; i < QS_LANES; i++) p[i][e] = v4_lane(v, i);
}

// The 6 numbers of fc of the four bodies p[0..3] by lane: x[e] =
// qb_gather(p, e). Read as each body's four and pair (the loads and
// stores of the sweeps' b6_load and b6_store) and transposed in registers:
// a wide load of numbers just written one by one (qb_scatter) waits until
// those stores are done, as it cannot take them from the store buffer.
QS_INLINE void qb_gather6(dReal *const *p, qs_v4 *x)
{
#if defined(__GNUC__)
    v4_transpose(v4_load(p[0]), v4_load(p[1]), v4_load(p[2]), v4_load(p[3]), x);
    const qs_v2 b0 = v2_load(p[0] + 4), b1 = v2_load(p[1] + 4);
    const qs_v2 b2 = v2_load(p[2] + 4), b3 = v2_load(p[3] + 4);
    const qs_v4 c02 = __builtin_shufflevector(b0, b2, 0, 1, 2, 3);
    const qs_v4 c13 = __builtin_shufflevector(b1, b3, 0, 1, 2, 3);
    x[4] = __builtin_shufflevector(c02, c13, 0, 4, 2, 6);
    x[5] = __builtin_shufflevector(c02, c13, 1, 5, 3, 7);
#else
    for (int e = 0; e < 6; e++) x[e] = qb_gather(p, e);
#endif
}

// qb_scatter(x[e], p, e) for the 6 numbers, stored as each body's four
// and pair (qb_gather6), which the next update of a body (here or in the
// sweeps) loads as they are stored.
QS_INLINE void qb_scatter6(const qs_v4 *x, dReal *const *p)
{
#if defined(__GNUC__)
    qs_v4 t[4];
    v4_transpose(x[0], x[1], x[2], x[3], t);
    for (int i = 0; i < 4; i++) v4_store(t[i], p[i]);
    const qs_v4 c02 = __builtin_shufflevector(x[4], x[5], 0, 4, 2, 6);
    const qs_v4 c13 = __builtin_shufflevector(x[4], x[5], 1, 5, 3, 7);
    v2_store(__builtin_shufflevector(c02, c02, 0, 1), p[0] + 4);
    v2_store(__builtin_shufflevector(c13, c13, 0, 1), p[1] + 4);
    v2_store(__builtin_shufflevector(c02, c02, 2, 3), p[2] + 4);
    v2_store(__builtin_shufflevector(c13, c13, 2, 3), p[3] + 4);
#else
    for (int e = 0; e < 6; e++) qb_scatter(x[e], p, e);
#endif
}

// Row a's J . fc in every lane (x: the bodies' numbers by lane), summed as
// the block update does (quickstep_sweep.c: block_dot, then its two lanes;
// fu as there), for a block of the general form or a coupled row (J in
// full: ne numbers).
QS_INLINE qs_v4 general_dot(const dReal *J, const qs_v4 *x, int two, int fu)
{
#define JL(k) v4_load(J + QS_LANES * (k))
#define JX(k, e) v4_mul(JL(k), x[e])
    qs_v4 s0 = v4_madd(JL(4), x[4], v4_add(JX(0, 0), JX(2, 2)), fu);
    qs_v4 s1 = v4_madd(JL(5), x[5], v4_add(JX(1, 1), JX(3, 3)), fu);
    if (two) {
        s0 = v4_add(s0, v4_madd(JL(10), x[10], v4_add(JX(6, 6), JX(8, 8)), fu));
        s1 = v4_add(s1, v4_madd(JL(11), x[11], v4_add(JX(7, 7), JX(9, 9)), fu));
    }
    return v4_add(s0, s1);
}

// A coupled row's J . fc in every lane, summed as the row update does
// (quickstep_sweep.c: row_dot, then its two lanes): with two bodies, each
// of the first body's products added to the second's first (the second's
// fused into it if fu).
QS_INLINE qs_v4 row_dot(const dReal *J, const qs_v4 *x, int two, int fu)
{
    if (!two) return general_dot(J, x, 0, fu);
#define PQ(k) v4_madd(JL(k + 6), x[k + 6], JX(k, k), fu)
    const qs_v4 s0 = v4_add(v4_add(PQ(0), PQ(2)), PQ(4));
    const qs_v4 s1 = v4_add(v4_add(PQ(1), PQ(3)), PQ(5));
#undef PQ
    return v4_add(s0, s1);
}

// The same for row a (a constant after inlining) of a block of the ball
// form (J: the row's angular numbers): J_lin is e_a (a < 3) or zero, and
// the second body's -e_a. Where the full form's first two products of a
// lane are x and a zero, the third (fused if fu) is added to x alone.
QS_INLINE qs_v4 ball_dot(const dReal *J, const qs_v4 *x, int two, int a, int fu)
{
    qs_v4 s0 = JX(1, 4), s1 = JX(0, 3);
    if (a == 0 || a == 2) s0 = v4_madd(JL(1), x[4], x[a], fu);
    if (a == 1) s1 = v4_add(x[1], s1);
    s1 = v4_madd(JL(2), x[5], s1, fu);
    if (two) {
        qs_v4 t0 = JX(4, 10), t1 = JX(3, 9);
        if (a == 0 || a == 2) t0 = v4_madd(JL(4), x[10], v4_neg(x[6 + a]), fu);
        if (a == 1) t1 = v4_sub(t1, x[7]);
        s0 = v4_add(s0, t0);
        s1 = v4_add(s1, v4_madd(JL(5), x[11], t1, fu));
    }
#undef JX
#undef JL
    return v4_add(s0, s1);
}

// The coupled rows of a full batch whose lanes have nc each (the block
// part done: x its bodies' numbers, L its lambdas, by lane), side by side:
// each lane coupled_row of quickstep_sweep.c. cs: their numbers (soa);
// their lambda positions and bounds' from b->cpos.
QS_INLINE void batch_coupled(const qs_batch *b, int n, int two, int nc, const dReal *cs,
                             dReal *lambda, qs_v4 *x, qs_v4 *L, int fu)
{
    const int ne = two ? 12 : 6;
    for (int c = 0; c < nc; c++) {
        dReal *pos[QS_LANES];
        qs_v4 s, old;
        const int *cpos = b->cpos + 2 * QS_LANES * c;
        for (int i = 0; i < QS_LANES; i++) {
            pos[i] = lambda + cpos[i];
            v4_lane(s, i) = dFabs(lambda[cpos[QS_LANES + i]]);
            v4_lane(old, i) = *pos[i];
        }
        const dReal *M = cs + QS_LANES * ne, *k = M + QS_LANES * ne, *g = k + 4 * QS_LANES;
        const qs_v4 r = v4_madd(v4_load(k + QS_LANES), old, v4_load(k), fu);
        const qs_v4 now = v4_clamp(v4_sub(r, row_dot(cs, x, two, fu)),
                                   v4_mul(v4_load(k + 2 * QS_LANES), s),
                                   v4_mul(v4_load(k + 3 * QS_LANES), s));
        for (int i = 0; i < QS_LANES; i++) *pos[i] = v4_lane(now, i);
        const qs_v4 delta = v4_sub(now, old);
        for (int e = 0; e < ne; e++) x[e] = v4_madd(delta, v4_load(M + QS_LANES * e), x[e], fu);
        for (int a = 0; a < n; a++) L[a] = v4_madd(delta, v4_load(g + QS_LANES * a), L[a], fu);
        cs = g + QS_LANES * n;
    }
}

// A full batch of blocks of n rows of a form on two + 1 bodies (constants
// after inlining): each lane the update_block of its block, then its
// coupled rows (side by side when the lanes have as many, nc >= 0; else
// each lane's on its own).
QS_INLINE void batch_update(const qs_batch *b, int n, int form, int two, int nc,
                            const qs_row *rows, dReal *lambda, dReal *fc, int fu)
{
    dReal *f0[QS_LANES], *f1[QS_LANES], *l[QS_LANES];
    for (int i = 0; i < QS_LANES; i++) {
        f0[i] = fc + b->o0[i];
        f1[i] = fc + b->o1[i];
        l[i] = lambda + b->first[i];
    }
    qs_v4 x[12], res[QS_MAX_BLOCK], L[QS_MAX_BLOCK];
    qb_gather6(f0, x);
    if (two) qb_gather6(f1, x + 6);
    const int je = SOA_JE(form, two), me = SOA_ME(form, two);
    const dReal *J = b->soa, *M = J + QS_LANES * n * je, *im = M + QS_LANES * n * me;
    const dReal *A = im + QS_LANES * SOA_MASS(form, two);
    const dReal *rhs = A + QS_LANES * n * (n + 1) / 2, *cfm = rhs + QS_LANES * n;
    for (int a = 0; a < n; a++) {
        L[a] = qb_gather(l, a);
        const qs_v4 ca = v4_load(cfm + QS_LANES * a);   // r = rhs - cfm L
        const qs_v4 r = v4_madd(v4_neg(ca), L[a], v4_load(rhs + QS_LANES * a), fu);
        const dReal *Ja = J + QS_LANES * je * a;
        res[a] = v4_sub(r, form == SOA_BALL ? ball_dot(Ja, x, two, a, fu)
                                            : general_dot(Ja, x, two, fu));
    }
    // delta = Ainv res, column products summed in row order; lambda +=
    // delta; fc += M^-1 J^T delta, row by row.
    qs_v4 d[QS_MAX_BLOCK];
    for (int a = 0; a < n; a++) {
        d[a] = v4_mul(v4_load(A + QS_LANES * SOA_TRI(0, a)), res[0]);
        for (int c = 1; c < n; c++)
            d[a] = v4_madd(v4_load(A + QS_LANES * SOA_TRI(c, a)), res[c], d[a], fu);
        L[a] = v4_add(L[a], d[a]);
    }
    if (form == SOA_BALL) {
        // Linear numbers: row e's alone, M^-1 J^T im (first body) and -im.
        const qs_v4 im0 = v4_load(im);
        for (int e = 0; e < 3; e++) x[e] = v4_madd(d[e], im0, x[e], fu);
        if (two) {
            const qs_v4 im1 = v4_neg(v4_load(im + QS_LANES));   // M^-1 J^T's -im
            for (int e = 0; e < 3; e++) x[6 + e] = v4_madd(d[e], im1, x[6 + e], fu);
        }
        for (int a = 0; a < n; a++)
            for (int e = 0; e < me; e++) {
                const int k = e < 3 ? 3 + e : 6 + e;   // angular numbers
                x[k] = v4_madd(d[a], v4_load(M + QS_LANES * (a * me + e)), x[k], fu);
            }
    } else {
        for (int a = 0; a < n; a++)
            for (int e = 0; e < me; e++)
                x[e] = v4_madd(d[a], v4_load(M + QS_LANES * (a * me + e)), x[e], fu);
    }
    if (nc > 0) batch_coupled(b, n, two, nc, cfm + QS_LANES * n, lambda, x, L, fu);
    for (int a = 0; a < n; a++) qb_scatter(L[a], l, a);
    qb_scatter6(x, f0);
    if (two) qb_scatter6(x + 6, f1);
    if (nc < 0)
        for (int i = 0; i < QS_LANES; i++)
            if (b->blk[i]->ncoupled) dxQuickCoupledRows(b->blk[i], rows, lambda, fc);
}

// nc: the batch's coupled rows a lane, a constant for the common cases.
QS_INLINE void batch_update_c(const qs_batch *b, int n, int form, int two, const qs_row *rows,
                              dReal *lambda, dReal *fc, int fu)
{
    switch (b->ncoupled) {
    case 0: batch_update(b, n, form, two, 0, rows, lambda, fc, fu); break;
    case 1: batch_update(b, n, form, two, 1, rows, lambda, fc, fu); break;
    case 2: batch_update(b, n, form, two, 2, rows, lambda, fc, fu); break;
    case -1: batch_update(b, n, form, two, -1, rows, lambda, fc, fu); break;
    default: batch_update(b, n, form, two, b->ncoupled, rows, lambda, fc, fu); break;
    }
}

QS_INLINE void batch_update_f(const qs_batch *b, int n, int form, const qs_row *rows,
                              dReal *lambda, dReal *fc, int fu)
{
    if (b->two) batch_update_c(b, n, form, 1, rows, lambda, fc, fu);
    else batch_update_c(b, n, form, 0, rows, lambda, fc, fu);
}

// The ball form has three rows or more. With QS_ANY_SIZE the form, the
// bodies and the coupled rows are read at run time too.
QS_INLINE void batch_update_n(const qs_batch *b, int n, const qs_row *rows, dReal *lambda,
                              dReal *fc, int fu)
{
    const int ball = n >= 3 && b->form == SOA_BALL;
#ifdef QS_ANY_SIZE
    batch_update(b, n, ball ? SOA_BALL : SOA_GENERAL, b->two != 0, b->ncoupled, rows, lambda, fc,
                 fu);
#else
    if (ball) batch_update_f(b, n, SOA_BALL, rows, lambda, fc, fu);
    else batch_update_f(b, n, SOA_GENERAL, rows, lambda, fc, fu);
#endif
}

// One function per block size and version, each with its size's update
// inlined: GCC's time on a function grows faster than the function, and one
// function with every size inlined took minutes to build. With QS_ANY_SIZE
// (quickstep.h) one function takes every size, read at run time.
#if QS_FUSE
#define BATCH_FUSED(NAME, N)                                                                       \
    QS_FUSED_VERSION static void batch_fused_##NAME(const qs_batch *b, const qs_row *rows,       \
                                                    dReal *lambda, dReal *fc)                    \
    {                                                                                            \
        batch_update_n(b, N, rows, lambda, fc, 1);                                               \
    }
#else
#define BATCH_FUSED(NAME, N)
#endif
#define BATCH_FUNCTIONS(NAME, N)                                                                   \
    QS_BATCH_CLONES static void batch_plain_##NAME(const qs_batch *b, const qs_row *rows,        \
                                                   dReal *lambda, dReal *fc)                     \
    {                                                                                            \
        batch_update_n(b, N, rows, lambda, fc, 0);                                               \
    }                                                                                            \
    BATCH_FUSED(NAME, N)

typedef void batch_fn(const qs_batch *b, const qs_row *rows, dReal *lambda, dReal *fc);

#ifdef QS_ANY_SIZE
BATCH_FUNCTIONS(any, b->n)

// The update of b, in the fused version where it runs.
static batch_fn *batch_update_for(const qs_batch *b)
{
    (void)b;
#if QS_FUSE
    if (dxQuickFused) return batch_fused_any;
#endif
    return batch_plain_any;
}
#else
BATCH_FUNCTIONS(2, 2)
BATCH_FUNCTIONS(3, 3)
BATCH_FUNCTIONS(4, 4)
BATCH_FUNCTIONS(5, 5)
_Static_assert(QS_MAX_BLOCK == 6, "a batch function for each block size");
BATCH_FUNCTIONS(6, 6)

// The update of batches of b's size, in the fused version where it runs.
static batch_fn *batch_update_for(const qs_batch *b)
{
#if QS_FUSE
    if (dxQuickFused) {
        switch (b->n) {
        case 2: return batch_fused_2;
        case 3: return batch_fused_3;
        case 4: return batch_fused_4;
        case 5: return batch_fused_5;
        default: return batch_fused_6;
        }
    }
#endif
    switch (b->n) {
    case 2: return batch_plain_2;
    case 3: return batch_plain_3;
    case 4: return batch_plain_4;
    case 5: return batch_plain_5;
    default: return batch_plain_6;
    }
}
#endif

void dxQuickBatchUpdate(const qs_batch *b, const qs_row *rows, dReal *lambda, dReal *fc)
{
    batch_update_for(b)(b, rows, lambda, fc);
}
