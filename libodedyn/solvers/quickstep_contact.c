// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_contact.c -- a contact's solver rows (quickstep.h's qs_row)
// straight from the contact's numbers (dxJointContactRows: directions, lever
// arms, targets, bounds), without the generic joint rows in between: most of
// a heap's rows are contacts, and the generic way copies each row's 12
// numbers of J into the joint-row layout and out again, with the defaults,
// the block search and the bookkeeping of joints with blocks.
//
// The arithmetic is the generic build's (quickstep_build.c: row_full,
// fill_row, warm_apply), operation for operation, so the rows and the
// results are the same to the bit (tests/test_contact_direct.c runs scenes
// both ways). One shortcut: a one-body row (a contact with the static world)
// leaves out its second body's products, which are exact zeros.
//
// A contact's rows (normal, t1, t2: up to three) share their bodies, arms
// and inverse inertias, so they are made together, one row per lane of a
// four (row i in lane i, the fourth lane and the missing rows zero): each
// scalar operation of the row's formula is one operation on the four, in
// the same order, so every lane gets the bits the row alone would. The
// lanes are then turned into rows four numbers at a time (a 4 x 4
// transpose per four consecutive numbers of qs_row).

#include "quickstep_v4.h"
#include "quickstep_warm_match.h"
#include "joint_contact.h"
#include "dx_clones.h"

#include <stddef.h>
#include <string.h>

int dxQuickContactDirect = 1;

// Built for AVX2 and for the baseline where the compiler can pick a version
// when the library is loaded (GNU ifunc: x86-64, ELF, glibc), as the sweeps
// (quickstep_sweep.c); the same numbers either way. -DQS_CONTACT_CLONES=
// builds the baseline alone. Clang (14) refuses the fours passed between the
// inlined functions of the baseline clone ("AVX vector argument ... changes
// the ABI", an error there), so it builds the baseline alone, as box-box does
// (collide_box.c).
#if !defined(QS_CONTACT_CLONES) && !defined(__clang__) && defined(DX_AVX2_CLONES)
#define QS_CONTACT_CLONES DX_AVX2_CLONES
#endif
#ifndef QS_CONTACT_CLONES
#define QS_CONTACT_CLONES
#endif

// D = sor_w / diag per lane, in double as fill_row makes it (diag =
// (double)ms + cfm), 0 where diag is not positive (an empty row without
// cfm leaves its force at 0; the absent rows' lanes).
QS_INLINE qs_v4 qc_factor(qs_v4 ms, qs_v4 cfm, qs_v4 sor_w)
{
#if defined(__GNUC__)
    typedef double d4 __attribute__((vector_size(4 * sizeof(double))));
    typedef long long m4 __attribute__((vector_size(4 * sizeof(double))));
    const d4 diag = __builtin_convertvector(ms, d4) + __builtin_convertvector(cfm, d4);
    const m4 pos = diag > 0;
    const d4 one = { 1, 1, 1, 1 };
    // Divide by 1 where diag is not used: no division by zero.
    const d4 safe = (d4)(((m4)diag & pos) | ((m4)one & ~pos));
    const d4 D = (d4)((m4)(__builtin_convertvector(sor_w, d4) / safe) & pos);
    return __builtin_convertvector(D, qs_v4);
#else
    qs_v4 D;
    for (int i = 0; i < 4; i++) {
        const double diag = (double)ms.e[i] + cfm.e[i];
        D.e[i] = diag > 0 ? (dReal)(sor_w.e[i] / diag) : 0;
    }
    return D;
#endif
}

// Lanes 0..2 of a, b, c, d as fours (a 4 x 4 transpose, its fourth row
// left out): out[i] = (a_i, b_i, c_i, d_i).
QS_INLINE void qc_transpose(qs_v4 a, qs_v4 b, qs_v4 c, qs_v4 d, qs_v4 out[3])
{
    qs_v4 t[4];
    v4_transpose(a, b, c, d, t);
    for (int i = 0; i < 3; i++) out[i] = t[i];
}

// The four numbers a, b, c, d of each of the first m rows (lanes), stored
// at byte offset off of rows[0..m).
QS_INLINE void qc_store(qs_row *rows, int m, size_t off, qs_v4 a, qs_v4 b, qs_v4 c, qs_v4 d)
{
    qs_v4 out[3];
    qc_transpose(a, b, c, d, out);
    memcpy((char *)&rows[0] + off, &out[0], sizeof out[0]);
    if (m > 1) memcpy((char *)&rows[1] + off, &out[1], sizeof out[1]);
    if (m > 2) memcpy((char *)&rows[2] + off, &out[2], sizeof out[2]);
}

// The two numbers a, b of each of the first m rows (lanes), stored at byte
// offset off of rows[0..m): the pairs that qc_store's fours leave between
// them, so that each body's M (four numbers and a pair) is written by the
// very stores the warm start (start_row) reads it back with. A load that
// spans two stores waits until both reach the cache; one within a store
// takes its numbers from the store.
QS_INLINE void qc_store2(qs_row *rows, int m, size_t off, qs_v4 a, qs_v4 b)
{
#if defined(__GNUC__)
    const qs_v4 t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6);   // a0 b0 a2 b2
    const qs_v4 t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);   // a1 b1 a3 b3
    const qs_v2 p0 = __builtin_shufflevector(t0, t0, 0, 1), p1 = __builtin_shufflevector(t1, t1, 0, 1),
                p2 = __builtin_shufflevector(t0, t0, 2, 3);
#else
    const qs_v2 p0 = { { a.e[0], b.e[0] } }, p1 = { { a.e[1], b.e[1] } },
                p2 = { { a.e[2], b.e[2] } };
#endif
    memcpy((char *)&rows[0] + off, &p0, sizeof p0);
    if (m > 1) memcpy((char *)&rows[1] + off, &p1, sizeof p1);
    if (m > 2) memcpy((char *)&rows[2] + off, &p2, sizeof p2);
}

// The numbers qc_store and qc_store2 write: rhs, keep, lo, hi together, and
// J, M, J1, M1 (24 numbers) together.
_Static_assert(offsetof(qs_row, keep) == sizeof(dReal) &&
                   offsetof(qs_row, lo) == 2 * sizeof(dReal) &&
                   offsetof(qs_row, hi) == 3 * sizeof(dReal),
               "qs_row: rhs, keep, lo, hi are consecutive");
_Static_assert(offsetof(qs_row, M) == offsetof(qs_row, J) + 6 * sizeof(dReal) &&
                   offsetof(qs_row, J1) == offsetof(qs_row, J) + 12 * sizeof(dReal) &&
                   offsetof(qs_row, M1) == offsetof(qs_row, J) + 18 * sizeof(dReal),
               "qs_row: J, M, J1, M1 are consecutive");

// A contact's bodies as the solver sees them: inverse mass and world inverse
// inertia, unconstrained rates, offsets in fc (the island's dummy for a
// missing second body).
typedef struct qs_cbodies {
    dReal im0, im1;
    const dReal *I0, *I1;
    const dReal *R0, *R1;
    int o0, o1;
} qs_cbodies;

// x = I a for the lanes' a (I: a world inverse inertia, dMatrix3), each
// entry of I spread once: I0 a0 + I1 a1 + I2 a2, in that order.
QS_INLINE void inertia_lanes(const dReal *I, qs_v4 ax, qs_v4 ay, qs_v4 az, qs_v4 x[3])
{
    for (int i = 0; i < 3; i++) {
        const qs_v4 row = v4_load(I + 4 * i);
        const qs_v4 c0 = v4_spread(row, 0), c1 = v4_spread(row, 1), c2 = v4_spread(row, 2);
        x[i] = v4_add(v4_add(v4_mul(c0, ax), v4_mul(c1, ay)), v4_mul(c2, az));
    }
}

// The scaled numbers of the contact's m rows into rows[0..m) (lane i: row
// i along r->d[i], its cfm lane i of cfm; sor_w the lanes' relaxation
// factors; lanes from m on are made but not stored): D J and M^-1 J^T,
// rhs = (c fps - J rates) D, keep = 1 - cfm fps D, the bounds (friction: -k..k),
// as fill_row makes them from row_full's J and M^-1 J^T. two: a second
// body (else its numbers are zero, and its J1 and M1 are not written: the
// sweep reads them only for a two-body row). The sums are pair_dot's: with p the
// products of body 0's 6 numbers and q body 1's, the pair
// (p0 + p2 | p1 + p3) + ((p4 + q0) + (q2 + q4) | (p5 + q1) + (q3 + q5)),
// (one body: + (p4 | p5)), its two lanes added last. d: the directions'
// x, y, z as lanes (the missing rows' zero). m and two are constants where
// the caller makes them so (the usual three rows).
QS_INLINE void lanes_rows(const qs_input *in, const qs_cbodies *cb, const dxContactRows *r,
                          const qs_v4 d[3], qs_v4 cfm_rows, qs_v4 sor_w, const int m,
                          const int two, qs_row *rows)
{
    const size_t J = offsetof(qs_row, J), n = sizeof(dReal);
    const qs_v4 dx = d[0], dy = d[1], dz = d[2];
    // Body 0: J = [d, arm0 x d], M^-1 J^T = [im0 d, I0 (arm0 x d)].
    const qs_v4 A = v4_load(r->arm[0]);   // (a dVector3: four numbers)
    const qs_v4 A0 = v4_spread(A, 0), A1 = v4_spread(A, 1), A2 = v4_spread(A, 2);
    const qs_v4 ax = v4_sub(v4_mul(A1, dz), v4_mul(A2, dy));
    const qs_v4 ay = v4_sub(v4_mul(A2, dx), v4_mul(A0, dz));
    const qs_v4 az = v4_sub(v4_mul(A0, dy), v4_mul(A1, dx));
    const qs_v4 im = v4_splat(cb->im0);
    const qs_v4 m0 = v4_mul(im, dx), m1 = v4_mul(im, dy), m2 = v4_mul(im, dz);
    qs_v4 ia[3];
    inertia_lanes(cb->I0, ax, ay, az, ia);
    const qs_v4 m3 = ia[0], m4 = ia[1], m5 = ia[2];
    qc_store(rows, m, J + 6 * n, m0, m1, m2, m3);
    qc_store2(rows, m, J + 10 * n, m4, m5);
    // The rates: R[0..3] and R[2..5] as fours (a body's six numbers).
    const qs_v4 R = v4_load(cb->R0), R2 = v4_load(cb->R0 + 2);
    const qs_v4 ra = v4_add(v4_mul(dx, v4_spread(R, 0)), v4_mul(dz, v4_spread(R, 2)));
    const qs_v4 rb = v4_add(v4_mul(dy, v4_spread(R, 1)), v4_mul(ax, v4_spread(R, 3)));
    const qs_v4 ma = v4_add(v4_mul(dx, m0), v4_mul(dz, m2));
    const qs_v4 mb = v4_add(v4_mul(dy, m1), v4_mul(ax, m3));
    qs_v4 rc = v4_mul(ay, v4_spread(R2, 2)), rd = v4_mul(az, v4_spread(R2, 3));
    qs_v4 mc = v4_mul(ay, m4), md = v4_mul(az, m5);
    // Body 1: J = [-d, d x arm1], M^-1 J^T = [im1 (-d), I1 (d x arm1)].
    qs_v4 lx, ly, lz, bx, by, bz;
    if (two) {
        lx = v4_neg(dx);
        ly = v4_neg(dy);
        lz = v4_neg(dz);
        const qs_v4 B = v4_load(r->arm[1]);
        const qs_v4 B0 = v4_spread(B, 0), B1 = v4_spread(B, 1), B2 = v4_spread(B, 2);
        bx = v4_sub(v4_mul(dy, B2), v4_mul(dz, B1));
        by = v4_sub(v4_mul(dz, B0), v4_mul(dx, B2));
        bz = v4_sub(v4_mul(dx, B1), v4_mul(dy, B0));
        const qs_v4 im1 = v4_splat(cb->im1);
        const qs_v4 n0 = v4_mul(im1, lx), n1 = v4_mul(im1, ly);
        const qs_v4 n2 = v4_mul(im1, lz);
        qs_v4 ib[3];
        inertia_lanes(cb->I1, bx, by, bz, ib);
        const qs_v4 n3 = ib[0], n4 = ib[1], n5 = ib[2];
        qc_store(rows, m, J + 18 * n, n0, n1, n2, n3);
        qc_store2(rows, m, J + 22 * n, n4, n5);
        const qs_v4 S = v4_load(cb->R1), S2 = v4_load(cb->R1 + 2);
        rc = v4_add(v4_add(rc, v4_mul(lx, v4_spread(S, 0))),
                    v4_add(v4_mul(lz, v4_spread(S, 2)), v4_mul(by, v4_spread(S2, 2))));
        rd = v4_add(v4_add(rd, v4_mul(ly, v4_spread(S, 1))),
                    v4_add(v4_mul(bx, v4_spread(S, 3)), v4_mul(bz, v4_spread(S2, 3))));
        mc = v4_add(v4_add(mc, v4_mul(lx, n0)), v4_add(v4_mul(lz, n2), v4_mul(by, n4)));
        md = v4_add(v4_add(md, v4_mul(ly, n1)), v4_add(v4_mul(bx, n3), v4_mul(bz, n5)));
    } else {
        lx = ly = lz = bx = by = bz = v4_splat(0);
    }
    const qs_v4 rate = v4_add(v4_add(ra, rc), v4_add(rb, rd));
    const qs_v4 ms = v4_add(v4_add(ma, mc), v4_add(mb, md));
    const qs_v4 fps = v4_splat(in->fps);
    const qs_v4 cfm = v4_mul(cfm_rows, fps);
    const qs_v4 D = qc_factor(ms, cfm, sor_w);
    qc_store(rows, m, 0, v4_mul(v4_sub(v4_mul(v4_load(r->c), fps), rate), D),
             v4_sub(v4_splat(1), v4_mul(cfm, D)), v4_load(r->lo), v4_load(r->hi));
    qc_store(rows, m, J, v4_mul(D, dx), v4_mul(D, dy), v4_mul(D, dz), v4_mul(D, ax));
    qc_store2(rows, m, J + 4 * n, v4_mul(D, ay), v4_mul(D, az));
    if (two) {
        qc_store(rows, m, J + 12 * n, v4_mul(D, lx), v4_mul(D, ly), v4_mul(D, lz), v4_mul(D, bx));
        qc_store2(rows, m, J + 16 * n, v4_mul(D, by), v4_mul(D, bz));
    }
}

// a, b += li M (M: a row's six numbers for one body, li spread to the four).
QS_INLINE void start_row(qs_v4 *a, qs_v2 *b, const qs_row *row, size_t off, qs_v4 li)
{
    const dReal *M = (const dReal *)((const char *)row + off);
#if defined(__GNUC__)
    const qs_v2 li2 = __builtin_shufflevector(li, li, 0, 1);
#else
    const qs_v2 li2 = qs_splat(v4_lane(li, 0));
#endif
    *a = v4_add(*a, v4_mul(li, v4_load(M)));
    *b = qs_add(*b, qs_mul(li2, v2_load(M + 4)));
}

// fc += M^-1 J^T l of body 0 (at fc0, the rows' M) and with two of body 1
// (at fc1, M1) for the m rows with l[i] nonzero, in row order (warm_apply's
// start_row, row by row: the same sums; the bodies' numbers are apart), fc
// as a four and a pair; l as a four, each spread from it.
QS_INLINE void start_bodies(dReal *fc0, dReal *fc1, const qs_row *rows, const int m,
                            const int two, qs_v4 l)
{
    const size_t M = offsetof(qs_row, M), M1 = offsetof(qs_row, M1);
    qs_v4 a0 = v4_load(fc0), a1 = two ? v4_load(fc1) : v4_splat(0);
    qs_v2 b0 = v2_load(fc0 + 4), b1 = two ? v2_load(fc1 + 4) : qs_splat(0);
    if (v4_lane(l, 0) != 0) {
        start_row(&a0, &b0, &rows[0], M, v4_spread(l, 0));
        if (two) start_row(&a1, &b1, &rows[0], M1, v4_spread(l, 0));
    }
    if (m > 1 && v4_lane(l, 1) != 0) {
        start_row(&a0, &b0, &rows[1], M, v4_spread(l, 1));
        if (two) start_row(&a1, &b1, &rows[1], M1, v4_spread(l, 1));
    }
    if (m > 2 && v4_lane(l, 2) != 0) {
        start_row(&a0, &b0, &rows[2], M, v4_spread(l, 2));
        if (two) start_row(&a1, &b1, &rows[2], M1, v4_spread(l, 2));
    }
    memcpy(fc0, &a0, sizeof a0);
    memcpy(fc0 + 4, &b0, sizeof b0);
    if (!two) return;
    memcpy(fc1, &a1, sizeof a1);
    memcpy(fc1 + 4, &b1, sizeof b1);
}

// The warm start's forces of the rows as a four (lane i: row i; lanes from
// m on unused) from the last step's friction force f[0..3) (world frame)
// and normal force f[3], as one row at a time makes them: the normal row
// WARM_SCALE max(fn, 0) = l0, a friction row WARM_SCALE (f . d_i) clamped
// to its bounds, times l0 where pyramid (each lane the same operations in
// the same order). d: the directions' x, y, z as lanes.
QS_INLINE qs_v4 warm_forces(const dxContactRows *r, const dReal *f, const qs_v4 d[3])
{
    const dReal fn = f[3];
    const dReal l0 = WARM_SCALE * (fn > 0 ? fn : 0);
#if defined(__GNUC__)
    typedef dxRealMask mask __attribute__((vector_size(4 * sizeof(dxRealMask))));
    const qs_v4 F = v4_load(f);
    const qs_v4 dot = v4_add(v4_add(v4_mul(v4_spread(F, 0), d[0]), v4_mul(v4_spread(F, 1), d[1])),
                             v4_mul(v4_spread(F, 2), d[2]));
    const qs_v4 li = v4_mul(v4_splat(WARM_SCALE), dot);
    const qs_v4 hi4 = v4_load(r->hi), lo4 = v4_load(r->lo), scaled = v4_mul(hi4, v4_splat(l0));
    mask pyr;
    memcpy(&pyr, r->pyramid, sizeof pyr);
    const mask hi = ((mask)scaled & pyr) | ((mask)hi4 & ~pyr);
    const mask lo = ((mask)v4_neg(scaled) & pyr) | ((mask)lo4 & ~pyr);
    const mask gt = li > (qs_v4)hi, lt = li < (qs_v4)lo;
    // li > hi ? hi : li < lo ? lo : li (not a number: li)
    qs_v4 l = (qs_v4)((hi & gt) | (~gt & ((lo & lt) | ((mask)li & ~lt))));
    l[0] = l0;
    return l;
#else
    qs_v4 l = v4_splat(0);
    v4_lane(l, 0) = l0;
    for (int i = 1; i < 3; i++) {
        dReal lo = r->lo[i], hi = r->hi[i];
        if (r->pyramid[i]) {
            hi = r->hi[i] * l0;
            lo = -hi;
        }
        const dReal li = WARM_SCALE * (f[0] * v4_lane(d[0], i) + f[1] * v4_lane(d[1], i) +
                                       f[2] * v4_lane(d[2], i));
        v4_lane(l, i) = li > hi ? hi : li < lo ? lo : li;
    }
    return l;
#endif
}

// A contact row's numbers from g to two (no block; one body or two), copied
// from constant memory: a template made on the stack field by field was read
// back in one load that spanned its stores, which waits until they reach the
// cache.
#define QS_ROW_TAIL offsetof(qs_row, g)
#define QS_ROW_TAIL_SIZE (offsetof(qs_row, J) - offsetof(qs_row, g))
static const qs_row contact_row_tail[2] = { { .g = NULL, .two = 0 }, { .g = NULL, .two = 1 } };

// The rows of a contact (r: m rows, lambda positions from sys->next on)
// appended to the system, in its order, with their bounds' f: friction rows
// bounded by the normal force (pyramid) take the normal row's lambda, the
// others the constant 1. f: the last step's forces (dxQuickWarmContactRows;
// lambda and fc then start from them, and the normal row is relaxed with
// 1), or NULL. cfm, m and two as in lanes_rows.
QS_INLINE void append_rows(const qs_input *in, const qs_cbodies *cb, const dxContactRows *r,
                           qs_v4 cfm, const dReal *f, qs_system *sys, const int m,
                           const int two)
{
    const int first = sys->next, one = sys->m, nrows = sys->nrows;
    qs_row *rows = sys->rows + nrows;
    qs_v4 d[3];   // the directions' x, y, z (the missing rows' are zero)
    qc_transpose(v4_load(r->d[0]), v4_load(r->d[1]), v4_load(r->d[2]), v4_splat(0), d);
    const qs_v4 l = f ? warm_forces(r, f, d) : v4_splat(0);
    const dReal w = in->sor_w;
    lanes_rows(in, cb, r, d, cfm, v4_make(f ? 1 : w, w, w, w), m, two, rows);
    // The integers: the bodies' offsets, the row's lambda position and its
    // bound's, and the template's rest.
    unsigned *normal = sys->normal + nrows;
    int *order = sys->order + sys->norder;
#if defined(__GNUC__)
#pragma GCC unroll 4
#endif
    for (int i = 0; i < m; i++) {
        qs_row *q = &rows[i];
        const int pyramid = r->pyramid[i] != 0;
        q->o0 = cb->o0;
        q->o1 = cb->o1;
        q->pos = first + i;
        q->f = pyramid ? first : one;
        memcpy((char *)q + QS_ROW_TAIL, (const char *)&contact_row_tail[two] + QS_ROW_TAIL,
               QS_ROW_TAIL_SIZE);
        normal[i] = pyramid ? (unsigned)nrows : QS_NO_ROW;
        order[i] = nrows + i;
    }
    sys->nrows = nrows + m;
    sys->norder += m;
    sys->next = first + m;
    // The lambdas start at zero, or warm: there a zero force (+-0) starts
    // at +0, the others as they are (x + 0 is x but for -0).
    dReal *lambda = sys->lambda + first;
    const qs_v4 l0 = f ? v4_add(l, v4_splat(0)) : v4_splat(0);
    lambda[0] = v4_lane(l0, 0);
    if (m > 1) lambda[1] = v4_lane(l0, 1);
    if (m > 2) lambda[2] = v4_lane(l0, 2);
    if (f) start_bodies(sys->fc + cb->o0, sys->fc + cb->o1, rows, m, two, l);
}

QS_CONTACT_CLONES void dxQuickContact(const qs_input *in, dxJoint *j, qs_system *sys)
{
    const struct dxBody *const b[2] = { dxJointBody(j, 0), dxJointBody(j, 1) };
    const struct dxBody *b0 = b[0], *b1 = b[1];
    dxJointContact *c = (dxJointContact *)j;
    const dxContactRows *r = dxJointContactStep(c, b, in->fps, in->erp);
    // The rows' cfm: the world's (the lanes from r->m on are not stored),
    // unless a mode gives a row its own (dxJointContactRows' numbers).
    qs_v4 cfm;
    if (c->own_numbers) {
        dxJointContactCfm(c);
        cfm = v4_load(r->cfm);
    } else {
        cfm = v4_splat(c->base.world->cfm);
    }
    const dxIslandBodies *bd = in->bd;
    qs_cbodies cb;
    cb.im0 = bd->inv_mass[b0->tag];
    cb.I0 = bd->inv_inertia + 12 * b0->tag;
    cb.R0 = in->rates + 6 * b0->tag;
    cb.o0 = 6 * (in->body0 + b0->tag);
    // A one-body contact's second body is the island's dummy: its numbers
    // are never read (its rows' J1 and M1 are left as they are: the sweep
    // and the warm start skip them).
    if (b1) {
        cb.im1 = bd->inv_mass[b1->tag];
        cb.I1 = bd->inv_inertia + 12 * b1->tag;
        cb.R1 = in->rates + 6 * b1->tag;
        cb.o1 = 6 * (in->body0 + b1->tag);
    } else {
        cb.im1 = 0;   // (GCC cannot tell it is unread)
        cb.o1 = 6 * (in->body0 + in->nb);
    }
    // The warm start's lookup first: a warm normal row is relaxed with 1.
    dReal fw[4];   // the friction force, then the normal force
    const dReal *f = warm_contact_rows(sys->warm, b0, b1, r, sys->next, fw) ? fw : NULL;
    // The usual three rows made with constants (no loop, no test of m).
    if (r->m == 3) {
        if (b1) append_rows(in, &cb, r, cfm, f, sys, 3, 1);
        else append_rows(in, &cb, r, cfm, f, sys, 3, 0);
    } else {
        if (b1) append_rows(in, &cb, r, cfm, f, sys, r->m, 1);
        else append_rows(in, &cb, r, cfm, f, sys, r->m, 0);
    }
}
