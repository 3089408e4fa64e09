// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep.c -- dWorldQuickStep: the iterative stepper (guide 5.1). Per
// island it solves the same mixed LCP as dWorldStep,
//   A lambda = b + w,  A = J M^-1 J^T + cfm/h,  b = c/h - J (v/h + M^-1 f),
// but by projected successive over-relaxation (Gauss-Seidel with the factor
// sor_w = dWorldGetQuickStepW) instead of pivoting: O(m) memory and O(m N)
// time for m rows and N iterations. A is never formed: the vector
// fc = M^-1 J^T lambda (6 numbers per body) is kept up to date, so the
// residual of a row is b_i - cfm_i/h lambda_i - J_i fc, in O(1).
//
// Units of the iteration:
//  - each joint's unbounded (equality) rows form a block of up to 6 rows,
//    solved together with its exact inverse: the rows of one joint are
//    strongly coupled (a ball joint on a body with a small inertia has a
//    badly conditioned 3x3 block on which row-by-row iteration stalls);
//  - every other row (limits, motors, contacts) is updated on its own and
//    projected onto its bounds; friction rows last, with bounds
//    +-|hi * lambda_normal| from the current normal force.
// Rows and blocks on one body (the other side static or kinematic) skip the
// second body's numbers; they are iterated in loops of their own, so the
// inner loops do not test for it.

#include "step_internal.h"

#include <float.h>
#include <math.h>
#include <ode/matrix.h>
#include <stdint.h>

// The single rows (contacts, limits, motors) are shuffled every this many
// sweeps, as ODE does, so that no fixed order biases the unconverged
// solution. The joint blocks keep the order of the island walk, which carries
// forces along chains (shuffling them measured worse on hanging chains).
#define REORDER_PERIOD 8
#define MAX_BLOCK 6

// The updates are inlined into the sweep, once per block size and kind, so
// that the loops have constant bounds and the one-body tests disappear.
#if defined(__GNUC__)
#define QS_INLINE static inline __attribute__((always_inline))
#else
#define QS_INLINE static inline
#endif

// A pivot below this fraction of its diagonal entry makes a block singular.
#ifdef dSINGLE
#define PIVOT_EPS (64 * FLT_EPSILON)
#else
#define PIVOT_EPS (64 * DBL_EPSILON)
#endif

// A row updated on its own. With d = sor_w / A_ii the update is
//   delta = rhs - cfm lambda - J . fc,  lambda += delta (clamped),
//   fc += delta_actual * iMJ.
// A limit or motor row of a joint with a block moves the block along: its
// lambdas change by g * delta_actual so that the block's residuals stay as
// they were (iMJ and d then include the block's response: A_ii becomes its
// Schur complement). Without this the row would fight a much stiffer block
// and converge very slowly (a stop on a pendulum with a light bob).
typedef struct qs_row {
    dReal J[12];     // d * J_i, [lin0 ang0 lin1 ang1]
    dReal iMJ[12];   // M^-1 J_i^T (plus the block's response); zero for a static side
    dReal rhs;       // d * b_i
    dReal cfm;       // d * cfm_i / h
    dReal lo, hi;    // bounds; for friction rows hi is the coefficient
    const dReal *g;  // gn numbers: the block's lambda change per unit of delta
    int gn, gfirst;  // gfirst: the lambda position of the block's first row
    int o0, o1;      // offsets of the bodies in fc; a one-body row has its body first
    int findex;      // friction rows: the lambda position of the normal row, else -1
    int pos;         // the row's lambda position
} qs_row;

// n rows of one joint solved together: with the residuals res (as above,
// unscaled), delta = Ainv res (Ainv: the inverse of the block of A, times
// sor_w), lambda += delta, fc += M^-1 J^T delta.
// data: J (n x 12), iMJ (n x 12), Ainv (n x n), rhs (n), cfm/h (n).
typedef struct qs_block {
    int n;
    int two;         // acts on two bodies (else on o0 only)
    int o0, o1;
    int first;       // lambda position of its first row; the others follow
    dReal *data;
} qs_block;

// Kinds of single rows, in solve order: the bounds of friction rows need the
// current normal forces.
enum { KIND_ONE, KIND_TWO, KIND_FRICTION_ONE, KIND_FRICTION_TWO, NKINDS };

typedef struct qs_system {
    int nblocks, nrows;    // units: blocks (their rows come first in lambda), single rows
    int kind_end[NKINDS];  // the single rows of kind k end at kind_end[k]
    qs_block *blocks;
    qs_row *rows;
    int *row_order;        // a permutation of the rows within each kind
    int *orig;             // lambda position -> dxIslandRows index
    dReal *lambda;
    dReal *fc;             // 6 * nb: M^-1 J^T lambda per body
} qs_system;

// Everything the build needs about the island.
typedef struct qs_input {
    const dxIslandRows *r;
    const dxIslandBodies *bd;
    const dReal *rates;    // v/h + M^-1 f per body, 6 each
    dReal fps, sor_w;
} qs_input;

static int is_unbounded(const dxIslandRows *r, int i)
{
    return r->findex[i] < 0 && r->lo[i] == -dInfinity && r->hi[i] == dInfinity;
}

// Whether row i acts on two island bodies.
static int is_two_body(const dxIslandRows *r, int i)
{
    return r->body0[i] >= 0 && r->body1[i] >= 0;
}

static int row_kind(const dxIslandRows *r, int i)
{
    return (r->findex[i] >= 0 ? KIND_FRICTION_ONE : KIND_ONE) + is_two_body(r, i);
}

// Row i's J into Jout[12] and M^-1 J^T into out[12], with its one island body
// first if it has only one (the other side, static or kinematic, is then
// zero); its fc offsets; returns its b_i.
static dReal row_setup(const qs_input *in, int i, dReal *Jout, dReal *out, int *o0, int *o1)
{
    const dxIslandRows *r = in->r;
    const dReal *J = r->J + i * DX_ROW_SKIP;
    int b[2] = { r->body0[i], r->body1[i] };
    int swap = b[0] < 0;
    dReal rate = 0;
    for (int side = 0; side < 2; side++) {
        int body = b[side ^ swap];
        const dReal *Js = J + 6 * (side ^ swap);
        dReal *Jo = Jout + 6 * side, *o = out + 6 * side;
        if (body < 0) {
            dSetZero(Jo, 6);
            dSetZero(o, 6);
            continue;
        }
        for (int e = 0; e < 6; e++) Jo[e] = Js[e];
        dCopyScaledVector3(o, Js, in->bd->inv_mass[body]);
        dMultiply0_331(o + 3, in->bd->inv_inertia + 12 * body, Js + 3);
        const dReal *t = in->rates + 6 * body;
        for (int e = 0; e < 6; e++) rate += Js[e] * t[e];
    }
    *o0 = 6 * (b[swap] < 0 ? 0 : b[swap]);
    *o1 = 6 * (b[1 - swap] < 0 ? 0 : b[1 - swap]);   // unused by one-body rows
    return r->c[i] * in->fps - rate;
}

// The set-up of blocks and of the rows coupled to them is done in double
// precision whatever dReal is: the Schur complement of a stiff block
// (a light body far from its joint) is a small difference of large numbers.
static double dot12(const dReal *a, const dReal *b)
{
    double s[4] = { 0, 0, 0, 0 };   // four partial sums: a short dependency chain
    for (int e = 0; e < 12; e++) s[e & 3] += (double)a[e] * b[e];
    return (s[0] + s[1]) + (s[2] + s[3]);
}

// The block's matrix B = J M^-1 J^T + cfm/h (n x n, row-major).
static void block_matrix(const dReal *J, const dReal *iMJ, const dReal *cfm, int n, double *B)
{
    for (int a = 0; a < n; a++) {
        for (int c = 0; c < a; c++) B[a * n + c] = B[c * n + a] = dot12(J + 12 * a, iMJ + 12 * c);
        B[a * n + a] = dot12(J + 12 * a, iMJ + 12 * a) + cfm[a];
    }
}

// Cholesky factor L (lower, row-major) of the n x n matrix B, its diagonal
// stored as reciprocals (the solves then multiply). Returns 0 if B is not
// safely positive definite.
static int cholesky(const double *B, int n, double *L)
{
    for (int i = 0; i < n; i++) {
        for (int j = 0; j <= i; j++) {
            double s = B[i * n + j];
            for (int k = 0; k < j; k++) s -= L[i * n + k] * L[j * n + k];
            if (i == j) {
                if (!(s > PIVOT_EPS * B[i * n + i])) return 0;
                L[i * n + i] = 1 / sqrt(s);
            } else {
                L[i * n + j] = s * L[j * n + j];
            }
        }
    }
    return 1;
}

// x = B^-1 x with B = L L^T.
static void cholesky_solve(const double *L, int n, double *x)
{
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < i; k++) x[i] -= L[i * n + k] * x[k];
        x[i] *= L[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        for (int k = i + 1; k < n; k++) x[i] -= L[k * n + i] * x[k];
        x[i] *= L[i * n + i];
    }
}

// Couple row q (diagonal *diag) to the block of its joint: with the block's
// matrix B and its column c = J_B M^-1 J_q^T, g = -B^-1 c, the diagonal
// becomes the Schur complement diag - c^T B^-1 c and iMJ gains M^-1 J_B^T g.
// g goes to *pool. Not done if the row depends on the block's rows.
static void couple_to_block(const qs_block *blk, qs_row *q, double *diag, dReal **pool)
{
    const int n = blk->n;
    const dReal *JB = blk->data, *iMJB = JB + 12 * n, *cfm = iMJB + 12 * n + n * n + n;
    double B[MAX_BLOCK * MAX_BLOCK], L[MAX_BLOCK * MAX_BLOCK], c[MAX_BLOCK], t[MAX_BLOCK];
    block_matrix(JB, iMJB, cfm, n, B);
    if (!cholesky(B, n, L)) return;
    for (int a = 0; a < n; a++) t[a] = c[a] = dot12(JB + 12 * a, q->iMJ);
    cholesky_solve(L, n, t);
    double schur = *diag;
    for (int a = 0; a < n; a++) schur -= c[a] * t[a];
    if (!(schur > PIVOT_EPS * *diag)) return;
    dReal *g = *pool;
    *pool += n;
    for (int a = 0; a < n; a++) {
        g[a] = (dReal)-t[a];
        for (int e = 0; e < 12; e++) q->iMJ[e] += g[a] * iMJB[12 * a + e];
    }
    q->g = g;
    q->gn = n;
    q->gfirst = blk->first;
    *diag = schur;
}

// Single row i at lambda position pos; blk: its joint's block, or NULL.
static void fill_row(const qs_input *in, int i, int pos, const qs_block *blk, dReal **pool,
                     qs_row *q)
{
    const dxIslandRows *r = in->r;
    dReal b = row_setup(in, i, q->J, q->iMJ, &q->o0, &q->o1);
    dReal cfm = r->cfm[i] * in->fps;
    double diag = dot12(q->J, q->iMJ) + cfm;
    q->g = NULL;
    q->gn = 0;
    q->gfirst = 0;
    if (blk && diag > 0) couple_to_block(blk, q, &diag, pool);
    // A zero diagonal (an empty row without cfm) leaves the row's force at 0.
    dReal d = diag > 0 ? (dReal)(in->sor_w / diag) : 0;
    for (int e = 0; e < 12; e++) q->J[e] *= d;
    q->rhs = b * d;
    q->cfm = cfm * d;
    q->lo = r->lo[i];
    q->hi = r->hi[i];
    q->pos = pos;
}

// Try to make rows idx[0..n) (of one joint) a block with its data at `data`.
// Returns 0 if their matrix is singular (they are then iterated one by one).
static int fill_block(const qs_input *in, const int *idx, int n, qs_block *blk, dReal *data)
{
    const dxIslandRows *r = in->r;
    dReal *J = data, *iMJ = J + 12 * n, *Ainv = iMJ + 12 * n, *rhs = Ainv + n * n,
          *cfm = rhs + n;
    for (int a = 0; a < n; a++) {
        rhs[a] = row_setup(in, idx[a], J + 12 * a, iMJ + 12 * a, &blk->o0, &blk->o1);
        cfm[a] = r->cfm[idx[a]] * in->fps;
    }
    double B[MAX_BLOCK * MAX_BLOCK], L[MAX_BLOCK * MAX_BLOCK];
    block_matrix(J, iMJ, cfm, n, B);
    if (!cholesky(B, n, L)) return 0;
    // Linv = L^-1 (lower, in B's storage), then sor_w B^-1 = sor_w Linv^T Linv.
    double *Linv = B;
    for (int j = 0; j < n; j++) {
        Linv[j * n + j] = L[j * n + j];
        for (int i = j + 1; i < n; i++) {
            double s = 0;
            for (int k = j; k < i; k++) s += L[i * n + k] * Linv[k * n + j];
            Linv[i * n + j] = -s * L[i * n + i];
        }
    }
    for (int i = 0; i < n; i++) {
        for (int j = 0; j <= i; j++) {
            double s = 0;
            for (int k = i; k < n; k++) s += Linv[k * n + i] * Linv[k * n + j];
            Ainv[i * n + j] = Ainv[j * n + i] = (dReal)(in->sor_w * s);
        }
    }
    blk->n = n;
    blk->two = is_two_body(r, idx[0]);
    blk->data = data;
    return 1;
}

// The blocks of joint k: its unbounded rows in groups of up to MAX_BLOCK.
// Rows that end up in a block get their lambda position in pos[] (counting
// on from *next); the others keep pos -1. If the joint has exactly one block,
// block_of[] names it for all the joint's rows (else -1).
static void make_blocks(const qs_input *in, int k, qs_system *sys, dReal **pool, int *pos,
                        int *block_of, int *next)
{
    const dxIslandRows *r = in->r;
    const int first_block = sys->nblocks;
    int idx[MAX_BLOCK], n = 0;
    for (int i = r->joint_row[k]; i <= r->joint_row[k + 1]; i++) {
        int last = i == r->joint_row[k + 1];
        if (!last && is_unbounded(r, i)) idx[n++] = i;
        if (n < MAX_BLOCK && !last) continue;
        qs_block *blk = &sys->blocks[sys->nblocks];
        if (n >= 2 && fill_block(in, idx, n, blk, *pool)) {
            *pool += n * (26 + n);
            blk->first = *next;
            for (int a = 0; a < n; a++) {
                pos[idx[a]] = *next;
                sys->orig[(*next)++] = idx[a];
            }
            sys->nblocks++;
        }
        n = 0;
    }
    int only = sys->nblocks == first_block + 1 ? first_block : -1;
    for (int i = r->joint_row[k]; i < r->joint_row[k + 1]; i++) block_of[i] = only;
}

// Build the system of an island (arena scratch).
static void build_system(dxArena *a, const dxIsland *is, const dxIslandBodies *bd,
                         const dxIslandRows *r, dReal h, dReal sor_w, qs_system *sys)
{
    const int m = r->m, nb = is->nb;
    sys->nblocks = 0;
    sys->blocks = DX_ARENA_ARRAY(a, qs_block, m / 2 + 1);
    sys->orig = DX_ARENA_ARRAY(a, int, m);
    sys->lambda = DX_ARENA_ARRAY(a, dReal, m);
    sys->fc = DX_ARENA_ARRAY(a, dReal, 6 * nb);
    int *pos = DX_ARENA_ARRAY(a, int, m);
    int *block_of = DX_ARENA_ARRAY(a, int, m);
    // A block of n rows takes n (26 + n) <= 32 n numbers, a single row's g <= 6.
    dReal *pool = DX_ARENA_ARRAY(a, dReal, 32 * (size_t)m);

    // fc serves as the scratch for the unconstrained rates before it is zeroed.
    dReal *rates = sys->fc;
    const dReal fps = dRecip(h);
    for (int b = 0; b < nb; b++) {
        const struct dxBody *body = is->bodies[b];
        dReal *t = rates + 6 * b;
        dAddScaledVectors3(t, body->lvel, body->force, fps, bd->inv_mass[b]);
        dMultiply0_331(t + 3, bd->inv_inertia + 12 * b, body->torque);
        dAddVectorScaledVector3(t + 3, t + 3, body->avel, fps);
    }
    const qs_input in = { r, bd, rates, fps, sor_w };

    for (int i = 0; i < m; i++) pos[i] = -1;
    int next = 0;
    for (int k = 0; k < is->nj; k++) make_blocks(&in, k, sys, &pool, pos, block_of, &next);

    // The single rows, kind by kind.
    sys->nrows = m - next;
    sys->rows = DX_ARENA_ARRAY(a, qs_row, sys->nrows);
    sys->row_order = DX_ARENA_ARRAY(a, int, sys->nrows);
    int first_single = next;
    for (int kind = 0; kind < NKINDS; kind++) {
        for (int i = 0; i < m; i++) {
            if (pos[i] >= 0 || row_kind(r, i) != kind) continue;
            pos[i] = next;
            sys->orig[next] = i;
            const qs_block *blk = block_of[i] >= 0 ? &sys->blocks[block_of[i]] : NULL;
            fill_row(&in, i, next, blk, &pool, &sys->rows[next - first_single]);
            next++;
        }
        sys->kind_end[kind] = next - first_single;
    }
    for (int k = 0; k < sys->nrows; k++) {
        qs_row *q = &sys->rows[k];
        int f = r->findex[sys->orig[q->pos]];
        q->findex = f < 0 ? -1 : pos[f];
    }
    for (int k = 0; k < sys->nrows; k++) sys->row_order[k] = k;
    dSetZero(sys->fc, 6 * nb);
    dSetZero(sys->lambda, m);
}

// The 6 numbers of fc of one body, copied to locals so the compiler need not
// assume they alias the row's data. The helpers are written out element by
// element so the values stay in registers.
typedef struct qs_f6 {
    dReal v0, v1, v2, v3, v4, v5;
} qs_f6;

QS_INLINE qs_f6 load6(const dReal *f)
{
    qs_f6 x = { f[0], f[1], f[2], f[3], f[4], f[5] };
    return x;
}

QS_INLINE void store6(qs_f6 x, dReal *f)
{
    f[0] = x.v0;
    f[1] = x.v1;
    f[2] = x.v2;
    f[3] = x.v3;
    f[4] = x.v4;
    f[5] = x.v5;
}

// J . x for 6 numbers of J; pairwise sums keep the dependency chain short.
QS_INLINE dReal dot6(const dReal *J, qs_f6 x)
{
    return (J[0] * x.v0 + J[1] * x.v1 + J[2] * x.v2) + (J[3] * x.v3 + J[4] * x.v4 + J[5] * x.v5);
}

// x += k * M for 6 numbers of M.
QS_INLINE void add6(qs_f6 *x, dReal k, const dReal *M)
{
    x->v0 += k * M[0];
    x->v1 += k * M[1];
    x->v2 += k * M[2];
    x->v3 += k * M[3];
    x->v4 += k * M[4];
    x->v5 += k * M[5];
}

// One block update; n and two are constants after inlining.
QS_INLINE void update_block(const qs_block *blk, int n, int two, dReal *lambda, dReal *fc)
{
    const dReal *J = blk->data, *iMJ = J + 12 * n, *Ainv = iMJ + 12 * n, *rhs = Ainv + n * n,
                *cfm = rhs + n;
    dReal *f0 = fc + blk->o0, *f1 = fc + blk->o1, *l = lambda + blk->first;
    qs_f6 x0 = load6(f0), x1 = { 0, 0, 0, 0, 0, 0 };
    if (two) x1 = load6(f1);
    dReal res[MAX_BLOCK];
    for (int a = 0; a < n; a++) {
        const dReal *Ja = J + 12 * a;
        res[a] = rhs[a] - cfm[a] * l[a] - (two ? dot6(Ja, x0) + dot6(Ja + 6, x1) : dot6(Ja, x0));
    }
    for (int a = 0; a < n; a++) {
        dReal delta = 0;
        for (int c = 0; c < n; c++) delta += Ainv[a * n + c] * res[c];
        l[a] += delta;
        add6(&x0, delta, iMJ + 12 * a);
        if (two) add6(&x1, delta, iMJ + 12 * a + 6);
    }
    store6(x0, f0);
    if (two) store6(x1, f1);
}

// One projected update of a single row; two and friction are constants
// after inlining. (Plain locals here measured faster than the qs_f6 helpers.)
QS_INLINE void update_row(const qs_row *q, int two, int friction, dReal *lambda, dReal *fc)
{
    dReal *f0 = fc + q->o0, *f1 = fc + q->o1;
    const dReal *J = q->J, *M = q->iMJ;
    dReal lo = q->lo, hi = q->hi;
    if (friction) {
        dReal normal = lambda[q->findex];
        hi = normal == 0 ? 0 : dFabs(hi * normal);   // no 0 * inf
        lo = -hi;
    }
    dReal old = lambda[q->pos];
    dReal a0 = f0[0], a1 = f0[1], a2 = f0[2], a3 = f0[3], a4 = f0[4], a5 = f0[5];
    dReal l = old + q->rhs - q->cfm * old -
              ((J[0] * a0 + J[1] * a1 + J[2] * a2) + (J[3] * a3 + J[4] * a4 + J[5] * a5));
    dReal b0 = 0, b1 = 0, b2 = 0, b3 = 0, b4 = 0, b5 = 0;
    if (two) {
        b0 = f1[0], b1 = f1[1], b2 = f1[2], b3 = f1[3], b4 = f1[4], b5 = f1[5];
        l -= (J[6] * b0 + J[7] * b1 + J[8] * b2) + (J[9] * b3 + J[10] * b4 + J[11] * b5);
    }
    // Mostly within bounds: predictable branches, off the dependency chain.
    if (l < lo) l = lo;
    else if (l > hi) l = hi;
    lambda[q->pos] = l;
    dReal delta = l - old;
    f0[0] = a0 + delta * M[0];
    f0[1] = a1 + delta * M[1];
    f0[2] = a2 + delta * M[2];
    f0[3] = a3 + delta * M[3];
    f0[4] = a4 + delta * M[4];
    f0[5] = a5 + delta * M[5];
    if (two) {
        f1[0] = b0 + delta * M[6];
        f1[1] = b1 + delta * M[7];
        f1[2] = b2 + delta * M[8];
        f1[3] = b3 + delta * M[9];
        f1[4] = b4 + delta * M[10];
        f1[5] = b5 + delta * M[11];
    }
    for (int a = 0; a < q->gn; a++) lambda[q->gfirst + a] += delta * q->g[a];
}

// A block of n rows on one or two bodies.
QS_INLINE void update_block_n(const qs_block *blk, int n, dReal *lambda, dReal *fc)
{
    if (blk->two) update_block(blk, n, 1, lambda, fc);
    else update_block(blk, n, 0, lambda, fc);
}

// One sweep: the blocks, then the single rows kind by kind.
static void sweep(qs_system *sys)
{
    dReal *lambda = sys->lambda, *fc = sys->fc;
    for (int k = 0; k < sys->nblocks; k++) {
        const qs_block *blk = &sys->blocks[k];
        switch (blk->n) {   // constant sizes let the compiler unroll
        case 2: update_block_n(blk, 2, lambda, fc); break;
        case 3: update_block_n(blk, 3, lambda, fc); break;
        case 4: update_block_n(blk, 4, lambda, fc); break;
        case 5: update_block_n(blk, 5, lambda, fc); break;
        default: update_block_n(blk, MAX_BLOCK, lambda, fc); break;
        }
    }
    const qs_row *rows = sys->rows;
    const int *order = sys->row_order, *end = sys->kind_end;
    int k = 0;
    for (; k < end[KIND_ONE]; k++) update_row(&rows[order[k]], 0, 0, lambda, fc);
    for (; k < end[KIND_TWO]; k++) update_row(&rows[order[k]], 1, 0, lambda, fc);
    for (; k < end[KIND_FRICTION_ONE]; k++) update_row(&rows[order[k]], 0, 1, lambda, fc);
    for (; k < end[KIND_FRICTION_TWO]; k++) update_row(&rows[order[k]], 1, 1, lambda, fc);
}

// xorshift32: a cheap deterministic generator; the state must not be 0.
static uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

// Fisher-Yates shuffle of order[first, last).
static void shuffle(int *order, int first, int last, uint32_t *state)
{
    for (int k = last - 1; k > first; k--) {
        // A uniform index in [first, k] by multiply-shift.
        int j = first + (int)(((uint64_t)next_random(state) * (uint64_t)(k - first + 1)) >> 32);
        int t = order[k];
        order[k] = order[j];
        order[j] = t;
    }
}

// `iterations` sweeps, reshuffling the single rows of each kind every
// REORDER_PERIOD. The generator restarts for each
// island, so a step is reproducible and independent of the other islands.
static void solve(qs_system *sys, int iterations)
{
    uint32_t state = 0x9e3779b9u;
    for (int it = 0; it < iterations; it++) {
        if (it > 0 && it % REORDER_PERIOD == 0)
            for (int k = 0; k < NKINDS; k++)
                shuffle(sys->row_order, k ? sys->kind_end[k - 1] : 0, sys->kind_end[k], &state);
        sweep(sys);
    }
}

// The iterative solve; lambda comes back in the rows' original order.
static void solve_sor(struct dxWorld *w, const dxIsland *is, const dxIslandBodies *bd,
                      const dxIslandRows *r, dReal h, dReal *lambda)
{
    qs_system sys;
    build_system(&w->arena, is, bd, r, h, w->qs_w, &sys);
    solve(&sys, w->qs_iterations);
    for (int k = 0; k < r->m; k++) lambda[sys.orig[k]] = sys.lambda[k];
}

int dWorldQuickStep(dWorldID w, dReal stepsize)
{
    return dxStepWorld(w, stepsize, __func__, solve_sor);
}
