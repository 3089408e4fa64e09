// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_build.c -- setting up dWorldQuickStep's iteration, island by
// island and joint by joint, straight from each joint's rows: its equality
// rows as blocks with their inverses, its other rows on their own, each
// scaled by D = sor_w / A_ii with M^-1 J^T precomputed (quickstep.h); and
// the warm start of contacts (quickstep.c): the forces of the same contact
// in the last step (quickstep_warm.c) as the starting lambdas, fc to match,
// and D = 1 / A_ii for a warm contact's normal row. Plain contacts skip the
// joint rows: quickstep_contact.c makes their rows, the same way.

#include "quickstep.h"
#include "joint_contact.h"

#include <float.h>
#include <math.h>
#include <string.h>

// A pivot below this fraction of its diagonal entry makes a block singular.
#ifdef dSINGLE
#define PIVOT_EPS (64 * FLT_EPSILON)
#else
#define PIVOT_EPS (64 * DBL_EPSILON)
#endif

// The rows of one joint (joint-local indices, as dxJointRowsFill makes them).
typedef struct qs_jrows {
    int m;
    int direct;            // a contact made straight into its rows (quickstep_contact.c)
    int equality;          // an equality joint, tried straight into its block first
    dReal *J, *c, *cfm, *lo, *hi;
    int *findex;
    int b[2];              // island indices of its bodies, -1: static or kinematic
    // Its island bodies in the solver's order (the one body first if only
    // one): where their parts of a J row start, inverse mass and inertia,
    // unconstrained rates.
    int src[2];
    dReal im[2];
    const dReal *I[2], *rate[2];
    int o[2];              // their offsets in fc: a missing second body is the dummy
    // An equality joint's block made ahead (equality_rows, equality_factors):
    // its piece of arena (J first), whether its rows fit (else the joint
    // takes the generic way) and whether its matrix factored.
    qs_v2 *eq;
    int eq_fit, eq_ok;
    // A run joint's block made ahead of its turn (blocks_ahead), or NULL.
    struct qs_ahead *ahead;
} qs_jrows;

// The solver-order side data of jr's bodies.
QS_INLINE void joint_sides(const qs_input *in, qs_jrows *jr)
{
    const int swap = jr->b[0] < 0;
    for (int side = 0; side < 2; side++) {
        const int body = jr->b[side ^ swap];
        jr->src[side] = 6 * (side ^ swap);
        jr->im[side] = body >= 0 ? in->bd->inv_mass[body] : 0;
        jr->I[side] = body >= 0 ? in->bd->inv_inertia + 12 * body : NULL;
        jr->rate[side] = body >= 0 ? in->rates + 6 * body : NULL;
        jr->o[side] = 6 * (in->body0 + (body >= 0 ? body : in->nb));
    }
}

static int is_unbounded(const qs_jrows *jr, int i)
{
    return jr->findex[i] < 0 && jr->lo[i] == -dInfinity && jr->hi[i] == dInfinity;
}

static int is_two_body(const qs_jrows *jr)
{
    return jr->b[0] >= 0 && jr->b[1] >= 0;
}

// The sum of the products of the 6 pairs of a and b.
static dReal pair_dot(const qs_v2 *a, const qs_v2 *b)
{
    const qs_v2 s = qs_add(qs_add(qs_mul(a[0], b[0]), qs_mul(a[1], b[1])),
                           qs_add(qs_add(qs_mul(a[2], b[2]), qs_mul(a[3], b[3])),
                                  qs_add(qs_mul(a[4], b[4]), qs_mul(a[5], b[5]))));
    return qs_lane(s, 0) + qs_lane(s, 1);
}

// The set-up of blocks and of the rows coupled to them is done in double
// precision whatever dReal is: the Schur complement of a stiff block (a light
// body far from its joint) is a small difference of large numbers.
static double dot12(const qs_v2 *a, const qs_v2 *b)
{
#ifdef dSINGLE
    double s0 = 0, s1 = 0;
    for (int e = 0; e < 6; e++) {
        s0 += (double)qs_lane(a[e], 0) * qs_lane(b[e], 0);
        s1 += (double)qs_lane(a[e], 1) * qs_lane(b[e], 1);
    }
    return s0 + s1;
#else
    return pair_dot(a, b);
#endif
}

// The pair (a, b).
QS_INLINE qs_v2 pair_of(dReal a, dReal b)
{
#if defined(__GNUC__)
    const qs_v2 v = { a, b };
#else
    const qs_v2 v = { { a, b } };
#endif
    return v;
}

// One island body's part of a row (its 6 numbers of J at Js, inverse mass
// im and world inverse inertia I, unconstrained rates r): M^-1 J^T into Mo,
// J into Jo unless it is NULL, and the products of J and r as 3 pairs in p.
QS_INLINE void side_parts(const dReal *Js, dReal im, const dReal *I, const dReal *r, qs_v2 *Mo,
                          qs_v2 *Jo, qs_v2 *p)
{
    // Every load before the first store: the compiler need not fear overlaps.
    qs_v2 j0, j1, j2, r0, r1, r2;
    memcpy(&j0, Js, sizeof j0);
    memcpy(&j1, Js + 2, sizeof j1);
    memcpy(&j2, Js + 4, sizeof j2);
    memcpy(&r0, r, sizeof r0);
    memcpy(&r1, r + 2, sizeof r1);
    memcpy(&r2, r + 4, sizeof r2);
    const dReal a0 = Js[3], a1 = Js[4], a2 = Js[5];
    const dReal m3 = I[0] * a0 + I[1] * a1 + I[2] * a2;
    const dReal m4 = I[4] * a0 + I[5] * a1 + I[6] * a2;
    const dReal m5 = I[8] * a0 + I[9] * a1 + I[10] * a2;
    Mo[0] = qs_mul(qs_splat(im), j0);
    Mo[1] = pair_of(im * Js[2], m3);
    Mo[2] = pair_of(m4, m5);
    if (Jo) {
        Jo[0] = j0;
        Jo[1] = j1;
        Jo[2] = j2;
    }
    p[0] = qs_mul(j0, r0);
    p[1] = qs_mul(j1, r1);
    p[2] = qs_mul(j2, r2);
}

// Row i's M^-1 J^T into Mo and (unless Jo is NULL) its J, 6 pairs each, with
// its one island body first if it has only one (the other side, static or
// kinematic, is then zero); returns J times the bodies' unconstrained rates
// (the pairs' products summed as pair_dot sums them; a missing body's would
// add exact zeros).
static dReal row_full(const qs_jrows *jr, int i, qs_v2 *Jo, qs_v2 *Mo)
{
    const dReal *J = jr->J + i * DX_ROW_SKIP;
    qs_v2 p[6];
    if (!jr->I[0]) {   // no island body at all: an empty row
        for (int e = 0; e < 6; e++) {
            if (Jo) Jo[e] = qs_splat(0);
            Mo[e] = qs_splat(0);
        }
        return 0;
    }
    side_parts(J + jr->src[0], jr->im[0], jr->I[0], jr->rate[0], Mo, Jo, p);
    if (jr->I[1]) {
        side_parts(J + 6, jr->im[1], jr->I[1], jr->rate[1], Mo + 3, Jo ? Jo + 3 : NULL, p + 3);
        const qs_v2 s = qs_add(qs_add(p[0], p[1]), qs_add(qs_add(p[2], p[3]), qs_add(p[4], p[5])));
        return qs_lane(s, 0) + qs_lane(s, 1);
    }
    for (int e = 3; e < 6; e++) {
        if (Jo) Jo[e] = qs_splat(0);
        Mo[e] = qs_splat(0);
    }
    const qs_v2 s = qs_add(qs_add(p[0], p[1]), p[2]);
    return qs_lane(s, 0) + qs_lane(s, 1);
}

// ---- blocks --------------------------------------------------------------------

// Unroll the next loop completely: the block's sizes are constants after
// inlining, and without it GCC keeps the loops of the larger ones. (Clang's
// full unrolling with the sanitizers took over ten minutes on this file: it
// is left to clang's own judgement.)
#if defined(__GNUC__) && !defined(__clang__)
#define UNROLL _Pragma("GCC unroll 8")
#else
#define UNROLL
#endif

// The block's matrix B = J M^-1 J^T + cfm/h (n x n, row-major).
QS_INLINE void block_matrix(const qs_v2 *J, const qs_v2 *iMJ, const dReal *cfm, int n,
                             double *B)
{
    UNROLL for (int a = 0; a < n; a++) {
        UNROLL for (int c = 0; c < a; c++) B[a * n + c] = B[c * n + a] = dot12(J + 6 * a, iMJ + 6 * c);
        B[a * n + a] = dot12(J + 6 * a, iMJ + 6 * a) + cfm[a];
    }
}

// Cholesky factor L (lower, row-major) of the n x n matrix B, its diagonal
// stored as reciprocals (the solves then multiply). Returns 0 if B is not
// safely positive definite.
QS_INLINE int cholesky(const double *B, int n, double *L)
{
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int j = 0; j <= i; j++) {
            double s = B[i * n + j];
            UNROLL for (int k = 0; k < j; k++) s -= L[i * n + k] * L[j * n + k];
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
QS_INLINE void cholesky_solve(const double *L, int n, double *x)
{
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int k = 0; k < i; k++) x[i] -= L[i * n + k] * x[k];
        x[i] *= L[i * n + i];
    }
    UNROLL for (int i = n - 1; i >= 0; i--) {
        UNROLL for (int k = i + 1; k < n; k++) x[i] -= L[k * n + i] * x[k];
        x[i] *= L[i * n + i];
    }
}

// A block being built: its rows' J and M^-1 J^T (the block's own, n x 6
// pairs) and the Cholesky factor of its matrix (kept for coupling the
// joint's other rows to it).
typedef struct qs_jblock {
    int n;
    const qs_v2 *J, *iMJ;
    dReal *g;              // room for the next coupled row's g (n numbers)
    double L[QS_MAX_BLOCK * QS_MAX_BLOCK];
} qs_jblock;

// sor_w B^-1 into Ainv (n rows of QS_PAD(n), the padding zero) from the
// Cholesky factor L of B.
QS_INLINE void scaled_inverse(const double *L, int n, dReal sor_w, dReal *Ainv)
{
    const int w = QS_PAD(n);
    // Linv = L^-1 (lower).
    double Linv[QS_MAX_BLOCK * QS_MAX_BLOCK];
    UNROLL for (int j = 0; j < n; j++) {
        Linv[j * n + j] = L[j * n + j];
        UNROLL for (int i = j + 1; i < n; i++) {
            double s = 0;
            UNROLL for (int k = j; k < i; k++) s += L[i * n + k] * Linv[k * n + j];
            Linv[i * n + j] = -s * L[i * n + i];
        }
    }
    // sor_w B^-1 = sor_w Linv^T Linv.
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int j = 0; j <= i; j++) {
            double s = 0;
            UNROLL for (int k = i; k < n; k++) s += Linv[k * n + i] * Linv[k * n + j];
            Ainv[i * w + j] = Ainv[j * w + i] = (dReal)(sor_w * s);
        }
        UNROLL for (int j = n; j < w; j++) Ainv[i * w + j] = 0;
    }
}

// The block's matrix B = J M^-1 J^T + cfm/h, its Cholesky factor L and
// sor_w B^-1 (Ainv); n is a constant after inlining. Returns 0 if B is
// singular.
QS_INLINE int factor_n(const qs_v2 *J, const qs_v2 *iMJ, const dReal *cfm, int n, dReal sor_w,
                       double *L, dReal *Ainv)
{
    double B[QS_MAX_BLOCK * QS_MAX_BLOCK];
    block_matrix(J, iMJ, cfm, n, B);
    if (!cholesky(B, n, L)) return 0;
    scaled_inverse(L, n, sor_w, Ainv);
    return 1;
}

// (Always inline: out of line, its calls cost more than sharing its code saves.)
QS_INLINE int factor(const qs_v2 *J, const qs_v2 *iMJ, const dReal *cfm, int n, dReal sor_w,
                  double *L, dReal *Ainv)
{
#ifdef QS_ANY_SIZE
    return factor_n(J, iMJ, cfm, n, sor_w, L, Ainv);
#else
    switch (n) {   // constant sizes let the compiler unroll
    case 2: return factor_n(J, iMJ, cfm, 2, sor_w, L, Ainv);
    case 3: return factor_n(J, iMJ, cfm, 3, sor_w, L, Ainv);
    case 4: return factor_n(J, iMJ, cfm, 4, sor_w, L, Ainv);
    case 5: return factor_n(J, iMJ, cfm, 5, sor_w, L, Ainv);
    default: return factor_n(J, iMJ, cfm, QS_MAX_BLOCK, sor_w, L, Ainv);
    }
#endif
}

// Rows idx[0..n) of a joint as a block: its J, M^-1 J^T, rhs and cfm in a
// piece of arena (with room for its Ainv, then for the g of the rows that
// may be coupled to it: couple_n), pointed to by blk and jb; Ainv and jb's
// factor are left to the factor.
QS_INLINE void block_rows(dxArena *a, const qs_input *in, const qs_jrows *jr, const int *idx,
                          int n, qs_block *blk, qs_jblock *jb)
{
    // Rows that follow each other, their island body first, are already
    // the block's J in the joint's rows (the pairs of a row are J1 then J2).
    const int in_place = jr->src[0] == 0 && idx[n - 1] - idx[0] == n - 1;
    const size_t pairs = (size_t)(in_place ? 6 : 12) * n;
    const size_t reals = (size_t)n * (QS_PAD(n) + 2 + jr->m - n);
    qs_v2 *M = dxArenaAlloc(a, sizeof(qs_v2) * pairs + sizeof(dReal) * reals);
    qs_v2 *J = in_place ? (qs_v2 *)(jr->J + idx[0] * DX_ROW_SKIP) : M + 6 * n;
    dReal *Ainv = (dReal *)(M + pairs);
    dReal *rhs = Ainv + n * QS_PAD(n), *cfm = rhs + n;
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        const dReal rate = row_full(jr, i, in_place ? NULL : J + 6 * k, M + 6 * k);
        rhs[k] = jr->c[i] * in->fps - rate;
        cfm[k] = jr->cfm[i] * in->fps;
    }
    jb->n = n;
    jb->J = J;
    jb->iMJ = M;
    jb->g = cfm + n;
    blk->n = n;
    blk->two = is_two_body(jr);
    blk->o0 = jr->o[0];
    blk->o1 = jr->o[1];
    blk->J = J;
    blk->M = M;
    blk->Ainv = Ainv;
    blk->rhs = rhs;
    blk->cfm = cfm;
}

// Two blocks of the same size factored side by side (blocks_ahead): each
// number of the two blocks' factors and inverses in one lane of a pair,
// the same operations as factor_n's in the same order (square roots and
// divisions are correctly rounded, lane by lane as one by one), so the same
// numbers; two chains of dependent square roots and divisions in one, and
// about half the instructions. Returns a bit per block (1: a, 2: b) that
// factored; a singular block's lane goes on with numbers that are not used.
#if defined(__GNUC__)
typedef double qs_d2 __attribute__((vector_size(2 * sizeof(double))));

QS_INLINE int factor_pair_n(const qs_block *a, const qs_block *b, int n, dReal sor_w, double *La,
                            double *Lb)
{
    double Ba[QS_MAX_BLOCK * QS_MAX_BLOCK], Bb[QS_MAX_BLOCK * QS_MAX_BLOCK];
    block_matrix(a->J, a->M, a->cfm, n, Ba);
    block_matrix(b->J, b->M, b->cfm, n, Bb);
    // cholesky's L, lane by lane.
    qs_d2 L[QS_MAX_BLOCK * QS_MAX_BLOCK];
    int ok = 3;
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int j = 0; j <= i; j++) {
            qs_d2 s = { Ba[i * n + j], Bb[i * n + j] };
            UNROLL for (int k = 0; k < j; k++) s -= L[i * n + k] * L[j * n + k];
            if (i == j) {
                ok &= (s[0] > PIVOT_EPS * Ba[i * n + i]) | (s[1] > PIVOT_EPS * Bb[i * n + i]) << 1;
                const qs_d2 root = { sqrt(s[0]), sqrt(s[1]) };
                L[i * n + i] = 1 / root;
            } else {
                L[i * n + j] = s * L[j * n + j];
            }
        }
    }
    // scaled_inverse's Linv and sor_w Linv^T Linv, lane by lane.
    qs_d2 Linv[QS_MAX_BLOCK * QS_MAX_BLOCK];
    UNROLL for (int j = 0; j < n; j++) {
        Linv[j * n + j] = L[j * n + j];
        UNROLL for (int i = j + 1; i < n; i++) {
            qs_d2 s = { 0, 0 };
            UNROLL for (int k = j; k < i; k++) s += L[i * n + k] * Linv[k * n + j];
            Linv[i * n + j] = -s * L[i * n + i];
        }
    }
    const int w = QS_PAD(n);
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int j = 0; j <= i; j++) {
            qs_d2 s = { 0, 0 };
            UNROLL for (int k = i; k < n; k++) s += Linv[k * n + i] * Linv[k * n + j];
            const qs_d2 v = sor_w * s;
            a->Ainv[i * w + j] = a->Ainv[j * w + i] = (dReal)v[0];
            b->Ainv[i * w + j] = b->Ainv[j * w + i] = (dReal)v[1];
        }
        UNROLL for (int j = n; j < w; j++) a->Ainv[i * w + j] = b->Ainv[i * w + j] = 0;
    }
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int j = 0; j <= i; j++) {
            La[i * n + j] = L[i * n + j][0];
            Lb[i * n + j] = L[i * n + j][1];
        }
    }
    return ok;
}

QS_INLINE int factor_pair(const qs_block *a, const qs_block *b, int n, dReal sor_w, double *La,
                          double *Lb)
{
#ifdef QS_ANY_SIZE
    return factor_pair_n(a, b, n, sor_w, La, Lb);
#else
    switch (n) {   // constant sizes let the compiler unroll
    case 2: return factor_pair_n(a, b, 2, sor_w, La, Lb);
    case 3: return factor_pair_n(a, b, 3, sor_w, La, Lb);
    case 4: return factor_pair_n(a, b, 4, sor_w, La, Lb);
    case 5: return factor_pair_n(a, b, 5, sor_w, La, Lb);
    default: return factor_pair_n(a, b, QS_MAX_BLOCK, sor_w, La, Lb);
    }
#endif
}
#else
QS_INLINE int factor_pair(const qs_block *a, const qs_block *b, int n, dReal sor_w, double *La,
                          double *Lb)
{
    return factor(a->J, a->M, a->cfm, n, sor_w, La, a->Ainv) |
           factor(b->J, b->M, b->cfm, n, sor_w, Lb, b->Ainv) << 1;
}
#endif

// Try to make rows idx[0..n) of a joint a block (its data from the arena,
// its build data in *jb). Returns 0 if their matrix is singular (they are
// then iterated one by one).
static int fill_block(dxArena *a, const qs_input *in, const qs_jrows *jr, const int *idx, int n,
                      qs_block *blk, qs_jblock *jb)
{
    const dxArenaMark mark = dxArenaSave(a);
    block_rows(a, in, jr, idx, n, blk, jb);
    if (!factor(blk->J, blk->M, blk->cfm, n, in->sor_w, jb->L, blk->Ainv)) {
        dxArenaRestore(a, mark);
        return 0;
    }
    return 1;
}

// Block blk of a joint, its rows idx[0..n), appended to the system with
// their lambda positions (pos) from *next on.
static void add_block(qs_system *sys, qs_block *blk, const int *idx, int n, int *pos, int *next)
{
    const int first = *next;
    blk->first = first;
    blk->coupled = blk->ncoupled = 0;
    for (int k = 0; k < n; k++) pos[idx[k]] = first + k;
    *next = first + n;
    sys->nblocks++;
}

// The blocks of a joint: its unbounded rows in groups of up to QS_MAX_BLOCK.
// Rows that end up in a block get their lambda position in pos[] (counting
// on from *next); the others keep -1. Returns the joint's block if it has
// exactly one (its build data then in *jb), else NULL.
static qs_block *make_blocks(dxArena *a, const qs_input *in, const qs_jrows *jr, qs_system *sys,
                             int *pos, int *next, qs_jblock *jb)
{
    const int first_block = sys->nblocks;
    int idx[QS_MAX_BLOCK], n = 0;
    for (int i = 0; i <= jr->m; i++) {
        const int last = i == jr->m;
        if (!last && is_unbounded(jr, i)) idx[n++] = i;
        if (n < QS_MAX_BLOCK && !last) continue;
        qs_block *blk = &sys->blocks[sys->nblocks];
        if (n >= 2 && fill_block(a, in, jr, idx, n, blk, jb)) add_block(sys, blk, idx, n, pos, next);
        n = 0;
    }
    return sys->nblocks == first_block + 1 ? &sys->blocks[first_block] : NULL;
}

// ---- joints of equality rows only ---------------------------------------------

// Is j a joint whose rows (counted this step) may all be equalities made
// straight into one block (equality_block): 2..QS_MAX_BLOCK rows, all of them
// unbounded by its count, not a contact, body 0 in the island and no
// kinematic body (whose motion dxJointRowsFill folds into the rows).
static int is_equality_joint(const dxJoint *j)
{
    const int m = j->rows.m;
    if (m < 2 || m > QS_MAX_BLOCK || j->rows.nub != m || j->cls->type == dJointTypeContact)
        return 0;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    return b0 && !(b0->flags & DX_BODY_KINEMATIC) && !(b1 && (b1->flags & DX_BODY_KINEMATIC));
}

// Are the joint's n rows numbers a solver can take (J, c and cfm finite: a
// sum of finite numbers is finite unless it overflows, which the generic
// check then settles) and all of them unbounded?
static int equality_rows_fit(int n, const dReal *J, const dReal *c, const dReal *cfm,
                             const dReal *lo, const dReal *hi, const int *findex)
{
    qs_v2 sum = qs_splat(0);
    dReal sum1 = 0;
    int unbounded = 1;
    for (int i = 0; i < n; i++) {
        for (int e = 0; e < 12; e += 2) {
            qs_v2 x;
            memcpy(&x, J + i * DX_ROW_SKIP + e, sizeof x);
            sum = qs_add(sum, x);
        }
        sum1 += c[i] + cfm[i];
        unbounded &= (findex[i] < 0) & (lo[i] == -dInfinity) & (hi[i] == dInfinity);
    }
    const dReal total = qs_lane(sum, 0) + qs_lane(sum, 1) + sum1;
    return unbounded && total - total == 0;
}

// The parts of an equality joint's piece of arena (equality_rows): J and M
// (n x 6 pairs each), Ainv, rhs, cfm.
static size_t equality_piece_bytes(int n)
{
    return sizeof(qs_v2) * 12 * (size_t)n + sizeof(dReal) * (size_t)n * (QS_PAD(n) + 2);
}

// The parts of that piece, found from its start.
typedef struct qs_equality_piece {
    qs_v2 *J, *M;
    dReal *Ainv, *rhs, *cfm;
} qs_equality_piece;

static qs_equality_piece equality_piece(qs_v2 *piece, int n)
{
    dReal *Ainv = (dReal *)(piece + 12 * n), *rhs = Ainv + n * QS_PAD(n);
    return (qs_equality_piece){ piece, piece + 6 * n, Ainv, rhs, rhs + n };
}

// An equality joint's blocks are made in three passes over the island, so
// that the long chains of their factors (a square root, then a division that
// the next pivot waits for, and the inverse after them: about a quarter of
// the joints' set-up time on a chain) overlap from joint to joint instead of
// waiting each between two joints' rows (docs/perf.md). equality_rows makes
// the rows, equality_factors makes and factors the matrices of the whole
// island, and equality_append appends a block that factored in the
// joint's place in the island's order: the same numbers, blocks and rows in
// the same order as made joint by joint.

// The rows of an equality joint (is_equality_joint; its island bodies in
// jr->b, joint_sides done) written by the joint straight into its block's J
// (its piece of arena in jr->eq), M^-1 J^T, rhs and cfm as make_blocks
// makes them from the generic rows (the same numbers). jr->eq_fit is 0 if
// the rows are not finite or not all unbounded: the joint then takes the
// generic way (its piece stays unused until the step ends). (Out of line:
// inlined, it made GCC move more of the generic way out of line.)
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void equality_rows(struct dxWorld *w, dxJoint *j, const qs_input *in, qs_jrows *jr)
{
    const int n = jr->m;
    const qs_equality_piece p =
        equality_piece(dxArenaAlloc(w->arena, equality_piece_bytes(n)), n);
    qs_v2 *J = p.J, *M = p.M;
    dReal *rhs = p.rhs, *cfm = p.cfm;
    dReal c[QS_MAX_BLOCK], jcfm[QS_MAX_BLOCK], lo[QS_MAX_BLOCK], hi[QS_MAX_BLOCK];
    int findex[QS_MAX_BLOCK];
    for (int e = 0; e < 6 * n; e++) J[e] = qs_splat(0);
    dxJointRowsDefaults(w, n, c, jcfm, lo, hi, findex);
    dReal *Jr = (dReal *)J;
    dxJointRows info = { in->fps, w->erp, DX_ROW_SKIP, Jr, Jr + 3, Jr + 6, Jr + 9,
                         c, jcfm, lo, hi, findex };
    j->cls->fill_rows(j, &info);
    jr->eq = J;
    jr->eq_ok = 0;
    jr->eq_fit = equality_rows_fit(n, Jr, c, jcfm, lo, hi, findex);
    if (!jr->eq_fit) return;
    jr->J = Jr;
    for (int k = 0; k < n; k++) {
        const dReal rate = row_full(jr, k, NULL, M + 6 * k);
        rhs[k] = c[k] * in->fps - rate;
        cfm[k] = jcfm[k] * in->fps;
    }
}

// The island's equality joints' rows (equality_rows).
QS_INLINE void equality_island_rows(struct dxWorld *w, const dxIsland *is, const qs_input *in,
                                    qs_jrows *jrows)
{
    for (int k = 0; k < is->nj; k++) {
        qs_jrows *jr = &jrows[k];
        if (!jr->equality) continue;
        joint_sides(in, jr);
        equality_rows(w, is->joints[k], in, jr);
    }
}

// The matrices and factors of the island's equality blocks whose rows fit,
// one after the other with nothing else between them (jr->eq_ok: it
// factored).
QS_INLINE void equality_factors(const dxIsland *is, dReal sor_w, qs_jrows *jrows)
{
    for (int k = 0; k < is->nj; k++) {
        qs_jrows *jr = &jrows[k];
        if (!jr->equality || !jr->eq_fit) continue;
        const int n = jr->m;
        double L[QS_MAX_BLOCK * QS_MAX_BLOCK];
        const qs_equality_piece p = equality_piece(jr->eq, n);
        jr->eq_ok = factor(p.J, p.M, p.cfm, n, sor_w, L, p.Ainv);
    }
}

// The block of an equality joint that factored (jr->eq_ok), appended to the
// system with its lambda positions.
QS_INLINE void equality_append(const qs_jrows *jr, qs_system *sys)
{
    const int n = jr->m;
    const qs_equality_piece p = equality_piece(jr->eq, n);
    qs_block *blk = &sys->blocks[sys->nblocks++];
    blk->n = n;
    blk->two = is_two_body(jr);
    blk->o0 = jr->o[0];
    blk->o1 = jr->o[1];
    blk->first = sys->next;
    blk->J = p.J;
    blk->M = p.M;
    blk->Ainv = p.Ainv;
    blk->rhs = p.rhs;
    blk->cfm = p.cfm;
    blk->coupled = blk->ncoupled = 0;
    sys->next += n;
}

// ---- rows --------------------------------------------------------------------

// A coupled row's response to its block (build data jb, n its size), from
// its solve t = B^-1 c: g = -t into the block's room, and iMJ gains
// M^-1 J_B^T g. Returns g.
QS_INLINE const dReal *block_response(qs_jblock *jb, int n, const double *t, qs_v2 *iMJ)
{
    dReal *g = jb->g;
    jb->g += n;
    UNROLL for (int k = 0; k < n; k++) {
        g[k] = (dReal)-t[k];
        const qs_v2 gk = qs_splat(g[k]);
        UNROLL for (int e = 0; e < 6; e++) iMJ[e] = qs_add(iMJ[e], qs_mul(gk, jb->iMJ[6 * k + e]));
    }
    return g;
}

// Couple a row (J, iMJ, diagonal *diag) to the block of its joint (build
// data jb, n its size: a constant after inlining): with the block's matrix B
// and its column c = J_B M^-1 J^T, g = -B^-1 c, the diagonal becomes the
// Schur complement diag - c^T B^-1 c and iMJ gains M^-1 J_B^T g. Returns g
// (arena), or NULL if the row depends on the block's rows.
QS_INLINE const dReal *couple_n(qs_jblock *jb, int n, qs_v2 *iMJ, double *diag)
{
    double c[QS_MAX_BLOCK], t[QS_MAX_BLOCK];
    UNROLL for (int k = 0; k < n; k++) t[k] = c[k] = dot12(jb->J + 6 * k, iMJ);
    cholesky_solve(jb->L, n, t);
    double schur = *diag;
    UNROLL for (int k = 0; k < n; k++) schur -= c[k] * t[k];
    if (!(schur > PIVOT_EPS * *diag)) return NULL;
    *diag = schur;
    return block_response(jb, n, t, iMJ);
}

static const dReal *couple_to_block(qs_jblock *jb, qs_v2 *iMJ, double *diag)
{
#ifdef QS_ANY_SIZE
    return couple_n(jb, jb->n, iMJ, diag);
#else
    switch (jb->n) {   // constant sizes let the compiler unroll
    case 2: return couple_n(jb, 2, iMJ, diag);
    case 3: return couple_n(jb, 3, iMJ, diag);
    case 4: return couple_n(jb, 4, iMJ, diag);
    case 5: return couple_n(jb, 5, iMJ, diag);
    default: return couple_n(jb, QS_MAX_BLOCK, iMJ, diag);
    }
#endif
}

// A row's diagonal J M^-1 J^T + cfm/h (Jp, Mp: its J and M^-1 J^T); in
// double when it is to be coupled to a block (coupling) and positive.
QS_INLINE double row_diag(const qs_v2 *Jp, const qs_v2 *Mp, dReal cfm, int coupling)
{
#ifdef dSINGLE
    double diag = (double)pair_dot(Jp, Mp) + cfm;
    if (coupling && diag > 0) diag = dot12(Jp, Mp) + cfm;   // in double
    return diag;
#else
    (void)coupling;   // dot12 is pair_dot
    return pair_dot(Jp, Mp) + cfm;
#endif
}

// Row i of the joint once its J and M^-1 J^T (Jp, Mp, as pairs), J times
// the rates, cfm/h and its scale D are known (lambda positions of the
// joint's rows in pos, the constant 1 at position one): all of q but its
// coupling (g, gn, gfirst).
QS_INLINE void row_out(const qs_input *in, const qs_jrows *jr, int i, const int *pos, int one,
                       const qs_v2 *Jp, const qs_v2 *Mp, dReal rate, dReal cfm, dReal D,
                       qs_row *q)
{
    const qs_v2 d = qs_splat(D);
    for (int e = 0; e < 3; e++) {
        q->J[e] = qs_mul(d, Jp[e]);
        q->M[e] = Mp[e];
        q->J1[e] = qs_mul(d, Jp[3 + e]);
        q->M1[e] = Mp[3 + e];
    }
    q->two = (short)is_two_body(jr);
    q->rhs = (jr->c[i] * in->fps - rate) * D;
    q->keep = 1 - cfm * D;
    q->pos = pos[i];
    q->o0 = jr->o[0];
    q->o1 = jr->o[1];
    const int f = jr->findex[i];
    if (f >= 0) {
        // Friction: -+|hi| times the normal force (as ODE: lo is not used).
        q->hi = dFabs(jr->hi[i]) < QS_BIG ? dFabs(jr->hi[i]) : QS_BIG;
        q->lo = -q->hi;
        q->f = pos[f];
    } else {
        q->lo = jr->lo[i];
        q->hi = jr->hi[i];
        q->f = one;
    }
}

// Row i of the joint (lambda positions of the joint's rows in pos, the
// constant 1 at position one): D J and M^-1 J^T as pairs, the scaled rhs and
// cfm, the bounds. blk, jb: the joint's block to couple to and its build
// data, or NULL.
static void fill_row(const qs_input *in, const qs_jrows *jr, int i, const int *pos, int one,
                     const qs_block *blk, qs_jblock *jb, qs_row *q)
{
    qs_v2 Jp[6], Mp[6];
    const dReal rate = row_full(jr, i, Jp, Mp), cfm = jr->cfm[i] * in->fps;
    double diag = row_diag(Jp, Mp, cfm, jb != NULL);
    q->g = NULL;
    if (jb && diag > 0) q->g = couple_to_block(jb, Mp, &diag);
    q->gn = (short)(q->g ? blk->n : 0);
    q->gfirst = q->g ? blk->first : 0;
    // A zero diagonal (an empty row without cfm) leaves the row's force at 0.
    const dReal sor_w = in->warm && i == 0 ? 1 : in->sor_w;
    const dReal D = diag > 0 ? (dReal)(sor_w / diag) : 0;
    row_out(in, jr, i, pos, one, Jp, Mp, rate, cfm, D, q);
}

// The joint's rows outside its blocks (pos[i] < 0 after make_blocks): their
// lambda positions from *next on, then their rows: first those coupled to
// the joint's block (blk, if it has one), then the others, which go into
// sys->order, each with its normal row (sys->normal: the row of its findex
// if that one went into order before it). done, row: scratch for the
// joint's rows.
static void make_rows(const qs_input *in, const qs_jrows *jr, qs_block *blk, qs_jblock *jb,
                      qs_system *sys, int *pos, int *next, char *done, unsigned *row)
{
    int nx = *next;
    for (int i = 0; i < jr->m; i++) {
        done[i] = pos[i] >= 0;   // in a block
        if (pos[i] < 0) pos[i] = nx++;
    }
    *next = nx;
    if (blk) {
        blk->coupled = sys->nrows;
        for (int i = 0; i < jr->m; i++) {
            if (done[i]) continue;
            qs_row *q = &sys->rows[sys->nrows];
            fill_row(in, jr, i, pos, sys->m, blk, jb, q);
            done[i] = q->g != NULL;
            sys->nrows += done[i];
        }
        blk->ncoupled = sys->nrows - blk->coupled;
    }
    for (int i = 0; i < jr->m; i++) row[i] = QS_NO_ROW;
    for (int i = 0; i < jr->m; i++) {
        if (done[i]) continue;
        fill_row(in, jr, i, pos, sys->m, NULL, NULL, &sys->rows[sys->nrows]);
        const int f = jr->findex[i];
        row[i] = (unsigned)sys->nrows;
        sys->normal[sys->nrows] = f >= 0 && f <= i ? row[f] : QS_NO_ROW;
        sys->order[sys->norder++] = sys->nrows++;
    }
}

int dxQuickRunJoints = 1;

// A run joint: at most QS_MAX_BLOCK rows without friction indices whose
// unbounded rows are one run of two or more (hinge-2's, or a contact's two
// infinite friction rows). Returns the run's length and its first row in
// *first, or 0 for any other joint.
QS_INLINE int run_of(const qs_jrows *jr, int *first)
{
    const int m = jr->m;
    if (m > QS_MAX_BLOCK || !dxQuickRunJoints) return 0;
    int f = 0, n = 0, broken = 0;
    for (int i = 0; i < m; i++) {
        const int u = is_unbounded(jr, i);
        broken |= (jr->findex[i] >= 0) | (u & (n > 0) & (f + n != i));
        f = n ? f : i;
        n += u;
    }
    if (n < 2 || broken) return 0;
    *first = f;
    return n;
}

// A run joint's row outside its run, coupled to its block ahead of its
// turn (blocks_ahead): its J and M^-1 J^T (the block's response added),
// J times the rates, cfm/h, its diagonal (the Schur complement once
// coupled) and D = sor_w / diag, and g, or NULL if it was not coupled (it
// is then made on its own at its turn, as fill_row leaves such a row).
typedef struct qs_coupled {
    qs_v2 J[6], M[6];
    double diag;
    dReal rate, cfm, D;
    const dReal *g;
} qs_coupled;

// A run joint's block made ahead of its turn (blocks_ahead): its block but
// the lambda positions, its build data, whether it factored, its run's
// first row, its other rows (in row order) coupled to it if it factored.
typedef struct qs_ahead {
    qs_block blk;
    qs_jblock jb;
    int ok, first;
    int ncoupled;
    qs_coupled *rows;
} qs_ahead;

// Row i of a run joint as a row to couple, before its coupling: fill_row's
// first part.
QS_INLINE void coupled_start(const qs_jrows *jr, int i, dReal fps, qs_coupled *r)
{
    r->rate = row_full(jr, i, r->J, r->M);
    r->cfm = jr->cfm[i] * fps;
    r->diag = row_diag(r->J, r->M, r->cfm, 1);
}

// Row r coupled to its block alone (fill_row's coupling and D).
QS_INLINE void couple_alone(qs_jblock *jb, dReal sor_w, qs_coupled *r)
{
    r->g = r->diag > 0 ? couple_to_block(jb, r->M, &r->diag) : NULL;
    if (r->g) r->D = (dReal)(sor_w / r->diag);
}

#if defined(__GNUC__)
// Rows ra and rb of two blocks of the same size n (build data ja, jb)
// coupled side by side: couple_n's dot products, solves and Schur
// complement and fill_row's D with each number of the two rows in one lane
// of a pair, the same operations in the same order, so the same numbers;
// the two chains of dependent products and the division in one.
QS_INLINE void couple_pair_n(qs_jblock *ja, qs_coupled *ra, qs_jblock *jb, qs_coupled *rb,
                             int n, dReal sor_w)
{
    qs_d2 c[QS_MAX_BLOCK], t[QS_MAX_BLOCK], L[QS_MAX_BLOCK * QS_MAX_BLOCK];
    UNROLL for (int k = 0; k < n; k++) {
        c[k] = (qs_d2){ dot12(ja->J + 6 * k, ra->M), dot12(jb->J + 6 * k, rb->M) };
        t[k] = c[k];
    }
    UNROLL for (int k = 0; k < n * n; k++) L[k] = (qs_d2){ ja->L[k], jb->L[k] };
    // cholesky_solve, lane by lane.
    UNROLL for (int i = 0; i < n; i++) {
        UNROLL for (int k = 0; k < i; k++) t[i] -= L[i * n + k] * t[k];
        t[i] *= L[i * n + i];
    }
    UNROLL for (int i = n - 1; i >= 0; i--) {
        UNROLL for (int k = i + 1; k < n; k++) t[i] -= L[k * n + i] * t[k];
        t[i] *= L[i * n + i];
    }
    qs_d2 schur = { ra->diag, rb->diag };
    UNROLL for (int k = 0; k < n; k++) schur -= c[k] * t[k];
    const qs_d2 w = { sor_w, sor_w };
    const qs_d2 D = w / schur;
    qs_coupled *r[2] = { ra, rb };
    qs_jblock *blk[2] = { ja, jb };
    for (int lane = 0; lane < 2; lane++) {
        qs_coupled *x = r[lane];
        x->g = NULL;
        if (!(x->diag > 0) || !(schur[lane] > PIVOT_EPS * x->diag)) continue;
        double tl[QS_MAX_BLOCK];
        UNROLL for (int k = 0; k < n; k++) tl[k] = t[k][lane];
        x->g = block_response(blk[lane], n, tl, x->M);
        x->diag = schur[lane];
        x->D = (dReal)D[lane];
    }
}

QS_INLINE void couple_pair(qs_jblock *ja, qs_coupled *ra, qs_jblock *jb, qs_coupled *rb,
                           dReal sor_w)
{
#ifdef QS_ANY_SIZE
    couple_pair_n(ja, ra, jb, rb, ja->n, sor_w);
#else
    switch (ja->n) {   // constant sizes let the compiler unroll
    case 2: couple_pair_n(ja, ra, jb, rb, 2, sor_w); break;
    case 3: couple_pair_n(ja, ra, jb, rb, 3, sor_w); break;
    case 4: couple_pair_n(ja, ra, jb, rb, 4, sor_w); break;
    case 5: couple_pair_n(ja, ra, jb, rb, 5, sor_w); break;
    default: couple_pair_n(ja, ra, jb, rb, QS_MAX_BLOCK, sor_w); break;
    }
#endif
}
#else
QS_INLINE void couple_pair(qs_jblock *ja, qs_coupled *ra, qs_jblock *jb, qs_coupled *rb,
                           dReal sor_w)
{
    couple_alone(ja, sor_w, ra);
    couple_alone(jb, sor_w, rb);
}
#endif

// The other rows of run joints x and y (blocks of the same size; y may be
// NULL) coupled to their blocks: a row of each side by side while both
// have one, then those left alone. (x's and y's rows each in their order:
// each block's room for g fills as fill_row fills it.)
static void couple_ahead(qs_ahead *x, qs_ahead *y, dReal sor_w)
{
    const int both = y ? (x->ncoupled < y->ncoupled ? x->ncoupled : y->ncoupled) : 0;
    for (int k = 0; k < both; k++) couple_pair(&x->jb, &x->rows[k], &y->jb, &y->rows[k], sor_w);
    for (int k = both; k < x->ncoupled; k++) couple_alone(&x->jb, sor_w, &x->rows[k]);
    for (int k = both; y && k < y->ncoupled; k++) couple_alone(&y->jb, sor_w, &y->rows[k]);
}

// Row i of a run joint coupled ahead (r) appended as q: fill_row's row,
// its D now that the joint is known to be a warm contact or not.
QS_INLINE void append_coupled(const qs_input *in, const qs_jrows *jr, int i, const int *pos,
                              int one, const qs_block *blk, const qs_coupled *r, qs_row *q)
{
    const dReal D = in->warm && i == 0 ? (dReal)(1 / r->diag) : r->D;
    q->g = r->g;
    q->gn = (short)blk->n;
    q->gfirst = blk->first;
    row_out(in, jr, i, pos, one, r->J, r->M, r->rate, r->cfm, D, q);
}

// A run joint made without make_blocks' and make_rows' general search: its
// run as its block (made here, or ahead: jr->ahead), its other rows' lambda
// positions after it in row order, then those rows coupled to the block in
// row order (coupled ahead too if the block was), then those that could
// not be coupled as free rows (no normal row): the same blocks, rows and
// positions (pos, all set) as make_blocks and make_rows give such a joint.
// Returns its block, or NULL (nothing done) for any other joint and a
// singular block.
QS_INLINE qs_block *run_joint(dxArena *a, const qs_input *in, const qs_jrows *jr,
                              qs_system *sys, int *pos)
{
    const int m = jr->m;
    qs_block *blk = &sys->blocks[sys->nblocks];
    qs_jblock made, *jb = &made;
    int first = 0, n;
    if (jr->ahead) {
        if (!jr->ahead->ok) return NULL;
        *blk = jr->ahead->blk;
        jb = &jr->ahead->jb;
        n = blk->n;
        first = jr->ahead->first;
    } else {
        n = run_of(jr, &first);
        if (n == 0) return NULL;
    }
    int idx[QS_MAX_BLOCK];
    for (int k = 0; k < n; k++) idx[k] = first + k;
    if (!jr->ahead && !fill_block(a, in, jr, idx, n, blk, jb)) return NULL;
    add_block(sys, blk, idx, n, pos, &sys->next);
    const unsigned rest = ((1u << m) - 1) & ~(((1u << n) - 1) << first);
    int nx = sys->next;
    for (int i = 0; i < m; i++)
        if (rest >> i & 1) pos[i] = nx++;
    sys->next = nx;
    blk->coupled = sys->nrows;
    unsigned loose = 0;
    for (int i = 0, k = 0; i < m; i++) {
        if (!(rest >> i & 1)) continue;
        qs_row *q = &sys->rows[sys->nrows];
        if (jr->ahead) {
            const qs_coupled *r = &jr->ahead->rows[k++];
            if (r->g) append_coupled(in, jr, i, pos, sys->m, blk, r, q);
            else q->g = NULL;
        } else {
            fill_row(in, jr, i, pos, sys->m, blk, jb, q);
        }
        if (q->g) sys->nrows++;
        else loose |= 1u << i;
    }
    blk->ncoupled = sys->nrows - blk->coupled;
    for (int i = 0; i < m; i++) {
        if (!(loose >> i & 1)) continue;
        fill_row(in, jr, i, pos, sys->m, NULL, NULL, &sys->rows[sys->nrows]);
        sys->normal[sys->nrows] = QS_NO_ROW;
        sys->order[sys->norder++] = sys->nrows++;
    }
    return blk;
}

// ---- the warm start ------------------------------------------------------------

// A contact's start: its normal and friction rows (joint-local: r[0] = 0,
// r[1], r[2] or -1) and their directions, its entry in the world's cache,
// and (found) the forces of the same contact in the last step, normal force
// ln and friction force f (world frame).
typedef struct qs_warm {
    int r[3];
    const dReal *t[3];
    qs_warm_entry *entry;
    int found;
    dReal ln, f[3];
} qs_warm;

// Enter a contact in the cache (for the next step) and look it up in the
// last step's (quickstep_warm.c). Returns ws->found (0 for other joints).
QS_INLINE int warm_lookup(dxJoint *j, const qs_jrows *jr, qs_system *sys, qs_warm *ws)
{
    ws->entry = NULL;
    ws->found = 0;
    if (j->cls->type != dJointTypeContact) return 0;
    dVector3 point;
    const int friction = dxJointContactWarmInfo(j, point);
    if (friction < 0) return 0;
    static const dReal zero[3] = { 0, 0, 0 };
    ws->r[0] = 0;
    ws->r[1] = (friction & 1) ? 1 : -1;
    ws->r[2] = (friction & 2) ? 1 + (friction & 1) : -1;
    for (int k = 0; k < 3; k++) ws->t[k] = ws->r[k] >= 0 ? jr->J + ws->r[k] * DX_ROW_SKIP : zero;
    ws->entry = dxQuickWarmContact(sys->warm, dxJointBody(j, 0), dxJointBody(j, 1), point,
                                   ws->t[0], ws->t[1], ws->t[2], &ws->found, &ws->ln, ws->f);
    return ws->found;
}

// lambda[pos] = l and fc += M^-1 J^T l for row i of the joint; q: its row
// as made (its M^-1 J^T), or NULL; blk: the joint's block, whose rows keep
// their M^-1 J^T (a row coupled to it has the block's response in its M),
// or NULL; else M^-1 J^T is worked out again (the same numbers).
QS_INLINE void start_row(const qs_jrows *jr, int i, const qs_row *q, const qs_block *blk,
                         int pos, dReal l, qs_system *sys)
{
    if (l == 0) return;
    sys->lambda[pos] = l;
    qs_v2 Mf[6];
    const qs_v2 *M0 = Mf, *M1 = Mf + 3;
    if (q) {
        M0 = q->M;
        M1 = q->M1;
    } else if (blk && pos >= blk->first && pos < blk->first + blk->n) {
        M0 = blk->M + 6 * (pos - blk->first);
        M1 = M0 + 3;
    } else {
        row_full(jr, i, NULL, Mf);
    }
    const qs_v2 k = qs_splat(l);
    dReal *f0 = sys->fc + jr->o[0], *f1 = sys->fc + jr->o[1];
    for (int e = 0; e < 3; e++) {
        qs_v2 x, y;
        memcpy(&x, f0 + 2 * e, sizeof x);
        memcpy(&y, f1 + 2 * e, sizeof y);
        x = qs_add(x, qs_mul(k, M0[e]));
        y = qs_add(y, qs_mul(k, M1[e]));
        memcpy(f0 + 2 * e, &x, sizeof x);
        memcpy(f1 + 2 * e, &y, sizeof y);
    }
}

// After the contact's rows are made (lambda positions in pos; rows: its
// rows in order in sys->rows, or NULL if some went into a block; blk: its
// one block, or NULL): the cache entry learns where its forces will be; a
// contact found in the last step starts from those forces, scaled by
// WARM_SCALE and projected on the rows' bounds (the friction pyramid's with
// the scaled normal force), the friction force projected on this step's
// friction directions; fc gets their M^-1 J^T.
QS_INLINE void warm_apply(const qs_jrows *jr, const int *pos, const qs_row *rows,
                          const qs_block *blk, const qs_warm *ws, qs_system *sys)
{
    if (!ws->entry) return;
    int p[3];
    for (int k = 0; k < 3; k++) p[k] = ws->r[k] >= 0 ? pos[ws->r[k]] : -1;
    dxQuickWarmPositions(ws->entry, p);
    if (!ws->found) return;
    const dReal ln = WARM_SCALE * (ws->ln > 0 ? ws->ln : 0);
    start_row(jr, 0, rows, blk, p[0], ln, sys);
    for (int k = 1; k < 3; k++) {
        const int i = ws->r[k];
        if (i < 0) continue;
        dReal lo = jr->lo[i], hi = jr->hi[i];
        if (jr->findex[i] >= 0) {
            hi = dFabs(hi) * ln;
            lo = -hi;
        }
        dReal l = WARM_SCALE * dCalcVectorDot3(ws->f, ws->t[k]);
        l = l > hi ? hi : l < lo ? lo : l;
        start_row(jr, i, rows ? rows + i : NULL, blk, p[k], l, sys);
    }
}

// ---- the islands ----------------------------------------------------------------

// An island whose build waits in the queue (dxQuickBuild): its bodies'
// mass data, its part of the system, its joints' rows in the scratch.
typedef struct qs_queued {
    const dxIsland *is;
    const dxIslandBodies *bd;
    qs_island *part;
    qs_jrows *jrows;
} qs_queued;

// Scratch for the build, allocated once a step: the joint rows of the
// queued islands (room for dxQuickBuildJoints joints, or the largest
// island's), one joint's rows' lambda positions.
struct qs_scratch {
    struct qs_jrows *jrows;
    int *pos;
    char *done;
    unsigned *row;       // per row of the joint: its row in order, or QS_NO_ROW
    qs_queued *queue;
    int nqueued;         // islands queued
    int queued_joints;   // their joints (their rows from jrows on)
    int room;            // jrows' room, in joints
    int next, count;     // the step's islands: how many came, how many there are
    int phased;          // 1: islands queued and built in phases; 0: each right away
};

// Keep what the joint's feedback needs: its J and lambda positions.
static void keep_feedback(dxArena *a, dxJoint *j, const qs_jrows *jr, const int *pos,
                          qs_system *sys)
{
    qs_feedback *fb = &sys->feedback[sys->nfeedback++];
    int *p = DX_ARENA_ARRAY(a, int, jr->m);
    memcpy(p, pos, sizeof(int) * (size_t)jr->m);
    fb->joint = j;
    fb->J = jr->J;   // the island's rows live until the step ends
    fb->pos = p;
    fb->m = jr->m;
}

// Joint j's rows by dxJointRowsFill into jr, its numbers from one piece of
// arena memory that lives until the step ends (J at *J, c, cfm, lo, hi at
// *num, findex at *findex), the pointers moved past them.
static void fill_joint_rows(struct dxWorld *w, dxJoint *j, dReal h, qs_jrows *jr, dReal **J,
                            dReal **num, int **findex)
{
    const size_t jm = (size_t)jr->m;
    jr->J = *J;
    jr->c = *num;
    jr->cfm = *num + jm;
    jr->lo = *num + 2 * jm;
    jr->hi = *num + 3 * jm;
    jr->findex = *findex;
    jr->ahead = NULL;
    dxJointRowsFill(w, j, h, jr->J, jr->c, jr->cfm, jr->lo, jr->hi, jr->findex, jr->b);
    *J += jm * DX_ROW_SKIP;
    *num += 4 * jm;
    *findex += jm;
}

// Arena memory for the generic rows of m rows (J, then c, cfm, lo, hi, then findex).
static dReal *rows_piece(dxArena *a, size_t m)
{
    return dxArenaAlloc(a, sizeof(dReal) * 16 * m + sizeof(int) * m);
}

// The rows of every joint of the island (count_rows done) into the step's
// jrows scratch, their numbers in arena memory that lives until the step
// ends (one piece, none when every joint is a direct contact or an equality
// joint); contacts that go straight to the solver's rows and equality
// joints, whose rows go straight into their block, are only marked (their
// rows are made in dxQuickBuild). Returns the number of equality joints.
QS_INLINE int fill_island_rows(struct dxWorld *w, const dxIsland *is, dReal h, qs_jrows *jrows)
{
    size_t m = 0;
    int equality = 0;
    for (int k = 0; k < is->nj; k++) {
        dxJoint *j = is->joints[k];
        qs_jrows *jr = &jrows[k];
        jr->m = j->rows.m;
        jr->direct = j->rows.m > 0 && j->cls->type == dJointTypeContact &&
                     dxQuickContactIsDirect(j);
        jr->equality = is_equality_joint(j);
        equality += jr->equality;
        if (jr->equality) {
            const struct dxBody *b1 = dxJointBody(j, 1);
            jr->b[0] = dxJointBody(j, 0)->tag;
            jr->b[1] = b1 ? b1->tag : -1;
        } else if (!jr->direct) {
            m += (size_t)j->rows.m;
        }
    }
    if (m == 0) return equality;
    dReal *J = rows_piece(w->arena, m);
    dReal *num = J + m * DX_ROW_SKIP;
    int *findex = (int *)(num + 4 * m);
    for (int k = 0; k < is->nj; k++) {
        qs_jrows *jr = &jrows[k];
        if (!jr->direct && !jr->equality) fill_joint_rows(w, is->joints[k], h, jr, &J, &num, &findex);
    }
    return equality;
}

// x[0, n) = 0, a body's six numbers at a time in vector stores (memset of
// a few thousand numbers is `rep stosb`, which counts as an instruction a
// byte), then one by one.
static void zero_numbers(dReal *x, int n)
{
    int k = 0;
    for (; k + 6 <= n; k += 6) memset(x + k, 0, 6 * sizeof(dReal));
    for (; k < n; k++) x[k] = 0;
}

// Islands are built in phases (dxQuickBuild) when those with joints other
// than contacts have at most this many of them on average: then each island
// runs its joints' code paths a few times only, and island by island they
// did not stay in the caches (a vehicle's cars: 4 hinge-2 joints each). A
// larger island runs them many times in a row anyway, and keeps its data in
// the cache from its rows to its blocks (ragdolls of 10 joints took 1 to 2 %
// more time in phases; docs/perf.md).
#define PHASED_JOINTS 6

void dxQuickSetup(struct dxWorld *w, const dxIsland *islands, int count, qs_system *sys)
{
    dxArena *a = w->arena;
    int m = 0, max_m = 0, max_nj = 0, nfeedback = 0, nbodies = 0, ncontacts = 0;
    int others = 0, joint_islands = 0;   // joints other than contacts, islands with them
    for (int i = 0; i < count; i++) {
        const dxIsland *is = &islands[i];
        const int others_before = others;
        nbodies += is->nb + 1;   // and the island's dummy
        if (is->nj > max_nj) max_nj = is->nj;
        for (int k = 0; k < is->nj; k++) {
            dxJoint *j = is->joints[k];
            // A contact's count is fixed at its creation and kept in
            // j->rows there (joint_contact.c): no call for it.
            if (j->cls->type == dJointTypeContact) {
                ncontacts++;
            } else {
                j->cls->count_rows(j, &j->rows);
                others++;
            }
            m += j->rows.m;
            if (j->rows.m > max_m) max_m = j->rows.m;
            nfeedback += j->feedback != NULL;
        }
        joint_islands += others > others_before;
    }
    sys->warm = dxQuickWarmBegin(w, ncontacts);
    sys->m = m;
    sys->nbodies = sys->nblocks = sys->nrows = sys->norder = sys->nfeedback = sys->next = 0;
    sys->lambda = DX_ARENA_ARRAY(a, dReal, m + 1);   // zeros or warm: the build
    sys->fc = DX_ARENA_ARRAY(a, dReal, 6 * (size_t)nbodies);   // zeros: dxQuickBuild
    sys->rates = DX_ARENA_ARRAY(a, dReal, 6 * (size_t)nbodies);
    sys->inv_mass = DX_ARENA_ARRAY(a, dReal, nbodies);
    sys->inv_inertia = DX_ARENA_ARRAY(a, dReal, 12 * (size_t)nbodies);
    sys->blocks = DX_ARENA_ARRAY(a, qs_block, m / 2 + 1);
    sys->bseq = DX_ARENA_ARRAY(a, const qs_block *, m / 2 + 1);
    sys->rows = DX_ARENA_ARRAY(a, qs_row, m + 1);
    sys->order = DX_ARENA_ARRAY(a, int, m + 1);
    sys->seq = DX_ARENA_ARRAY(a, const qs_row *, m + 1);
    sys->normal = DX_ARENA_ARRAY(a, unsigned, m + 1);
    sys->feedback = DX_ARENA_ARRAY(a, qs_feedback, nfeedback + 1);
    sys->lambda[m] = 1;

    qs_scratch *s = DX_ARENA_ARRAY(a, qs_scratch, 1);
    s->room = max_nj > dxQuickBuildJoints ? max_nj : dxQuickBuildJoints;
    s->jrows = DX_ARENA_ARRAY(a, qs_jrows, s->room + 1);
    s->queue = DX_ARENA_ARRAY(a, qs_queued, count + 1);
    s->nqueued = s->queued_joints = s->next = 0;
    s->count = count;
    // Contacts alone are built right away, without the queue's own
    // instructions.
    s->phased = others > 0 && others <= PHASED_JOINTS * joint_islands && dxQuickBuildJoints > 0;
    s->pos = DX_ARENA_ARRAY(a, int, max_m + 1);
    s->done = DX_ARENA_ARRAY(a, char, max_m + 1);
    s->row = DX_ARENA_ARRAY(a, unsigned, max_m + 1);
    sys->scratch = s;
}

// The joints' loop asks for the lines of the contact this many joints ahead
// (prefetch_contact).
#define CONTACT_AHEAD 2

// Ask for the lines of a direct contact that dxQuickContact reads beyond the
// joint's first two (read when the island's rows were counted): they were
// written in collision and have left the first-level cache (docs/perf.md).
// Every line: with every other one (the second-level prefetcher brings the
// neighbouring line of a pair, but only into the second level), the rain's
// contacts waited on the line of their flag and warm-start fields.
QS_INLINE void prefetch_contact(const dxJoint *j)
{
#if defined(__GNUC__)
#pragma GCC unroll 16
#endif
    for (size_t at = 128; at < sizeof(dxJointContact); at += 64)
        qs_prefetch((const char *)j + at);
}

// The islands are built in phases over a queue of them (up to
// dxQuickBuildJoints joints, or one larger island): every queued island's
// joint rows and rates, then the run joints' blocks (blocks_ahead: two
// factored side by side), then every queued island's blocks and rows
// appended to the system, island after island in the order they came, each
// in its joints' order (the same system as island by island). Each phase's
// code then runs for many islands in a row: island by island, the joints'
// rows (hinge-2's, the limit motors', the contacts'), the blocks' factors
// of each size, the couplings and the warm start (some 70 KB of code) took
// turns, and a vehicle of 16 cars spent about 6 % more time in its step
// (docs/perf.md). Steps whose joints are all contacts, or whose islands
// have many joints (PHASED_JOINTS), build each island right away.
int dxQuickBuildJoints = 256;   // about 40 KB of jrows

// The first phase of a queued island's build: its fc zeroed, its joints'
// rows, its bodies' rates (after the rows: a limit motor that powers
// against its stop adds its force to the bodies while its rows are filled,
// joint_limot.c, and the rates must include that force), its equality
// joints' blocks.
QS_INLINE void island_rows(struct dxWorld *w, const qs_queued *q, dReal h, dReal fps,
                           qs_system *sys)
{
    const dxIsland *is = q->is;
    const int body0 = q->part->body0;
    zero_numbers(sys->fc + 6 * (size_t)body0, 6 * (is->nb + 1));
    if (is->nj == 0) return;
    const int equality = fill_island_rows(w, is, h, q->jrows);
    dReal *rates = sys->rates + 6 * body0;
    dxIslandBodyRates(is, q->bd, fps, rates);
    if (equality > 0) {
        const qs_input in = { q->bd, rates, fps, w->erp, w->qs_w, body0, is->nb, 0 };
        equality_island_rows(w, is, &in, q->jrows);
        equality_factors(is, in.sor_w, q->jrows);
    }
}

// An equality joint whose block factored (jr->eq_ok): its block appended
// to the system.
QS_INLINE void append_equality(struct dxWorld *w, dxJoint *j, const qs_jrows *jr,
                               qs_system *sys)
{
    qs_scratch *s = sys->scratch;
    const int first = sys->next;
    zero_numbers(sys->lambda + first, jr->m);   // its lambda positions
    equality_append(jr, sys);
    if (j->feedback) {
        for (int i = 0; i < jr->m; i++) s->pos[i] = first + i;
        keep_feedback(w->arena, j, jr, s->pos, sys);
    }
}

// Any other joint but a direct contact: its blocks and rows appended to the
// system. (Out of line: the islands' loop over their contacts and equality
// joints stays short.)
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void build_joint(struct dxWorld *w, dxJoint *j, qs_jrows *jr, const qs_input *in, dReal h,
                        qs_system *sys)
{
    dxArena *a = w->arena;
    qs_scratch *s = sys->scratch;
    // (equality_island_rows or blocks_ahead did)
    if (!jr->equality && !jr->ahead) joint_sides(in, jr);
    zero_numbers(sys->lambda + sys->next, jr->m);   // its lambda positions
    if (jr->equality) {
        // Not finite, not all unbounded or singular: the generic way.
        dReal *J = rows_piece(a, (size_t)jr->m);
        dReal *num = J + jr->m * DX_ROW_SKIP;
        int *findex = (int *)(num + 4 * jr->m);
        fill_joint_rows(w, j, h, jr, &J, &num, &findex);
    }
    qs_warm ws;
    qs_input in_warm;
    const qs_input *jin = in;
    if (warm_lookup(j, jr, sys, &ws)) {
        in_warm = *in;
        in_warm.warm = 1;
        jin = &in_warm;
    }
    const int nblocks = sys->nblocks, nrows = sys->nrows;
    qs_block *blk = run_joint(a, jin, jr, sys, s->pos);
    if (!blk) {
        for (int i = 0; i < jr->m; i++) s->pos[i] = -1;
        qs_jblock jb;
        blk = make_blocks(a, jin, jr, sys, s->pos, &sys->next, &jb);
        make_rows(jin, jr, blk, blk ? &jb : NULL, sys, s->pos, &sys->next, s->done, s->row);
    }
    if (j->feedback) keep_feedback(a, j, jr, s->pos, sys);
    // Without blocks the joint's rows are in order and alone (not coupled).
    const int alone = sys->nblocks == nblocks && sys->nrows - nrows == jr->m;
    warm_apply(jr, s->pos, alone ? sys->rows + nrows : NULL, blk, &ws, sys);
}

// The second phase: the island's blocks and rows appended to the system in
// its joints' order; its part gets their ranges.
QS_INLINE void island_joints(struct dxWorld *w, const qs_queued *q, dReal h, dReal fps,
                             qs_system *sys)
{
    const dxIsland *is = q->is;
    qs_island *part = q->part;
    part->block0 = sys->nblocks;
    part->order0 = sys->norder;
    part->nblocks = part->norder = 0;
    if (is->nj == 0) return;
    const dReal *rates = sys->rates + 6 * part->body0;
    const qs_input in = { q->bd, rates, fps, w->erp, w->qs_w, part->body0, is->nb, 0 };
    qs_jrows *jrows = q->jrows;
    for (int k = 0; k < is->nj; k++) {
        if (k + CONTACT_AHEAD < is->nj && jrows[k + CONTACT_AHEAD].direct)
            prefetch_contact(is->joints[k + CONTACT_AHEAD]);
        dxJoint *j = is->joints[k];
        qs_jrows *jr = &jrows[k];
        if (jr->m == 0) continue;
        if (jr->direct) dxQuickContact(&in, j, sys);
        else if (jr->equality && jr->eq_ok) append_equality(w, j, jr, sys);
        else build_joint(w, j, jr, &in, h, sys);
    }
    part->nblocks = sys->nblocks - part->block0;
    part->norder = sys->norder - part->order0;
}

// The blocks of the queued islands' run joints, made ahead of their turn in
// island_joints (which appends them), each with the next one of its size
// factored side by side (factor_pair), the last one of a size alone. (Made
// one by one between the joints' other work, each block's factor was a
// chain of square roots and divisions that the next joint's waited for:
// docs/perf.md.)
static void blocks_ahead(struct dxWorld *w, dReal fps, qs_system *sys)
{
    qs_scratch *s = sys->scratch;
    qs_ahead *ahead = DX_ARENA_ARRAY(w->arena, qs_ahead, s->queued_joints + 1);
    qs_ahead *waiting[QS_MAX_BLOCK + 1] = { NULL };   // a block of each size without its pair
    for (int i = 0; i < s->nqueued; i++) {
        const qs_queued *q = &s->queue[i];
        const dxIsland *is = q->is;
        const int body0 = q->part->body0;
        const qs_input in = { q->bd, sys->rates + 6 * body0, fps, w->erp, w->qs_w, body0,
                              is->nb, 0 };
        for (int k = 0; k < is->nj; k++) {
            qs_jrows *jr = &q->jrows[k];
            if (jr->m == 0 || jr->direct || jr->equality) continue;
            joint_sides(&in, jr);
            int first = 0;
            const int n = run_of(jr, &first);
            if (n == 0) continue;
            int idx[QS_MAX_BLOCK];
            for (int e = 0; e < n; e++) idx[e] = first + e;
            qs_ahead *x = jr->ahead = ahead++;
            x->first = first;
            block_rows(w->arena, &in, jr, idx, n, &x->blk, &x->jb);
            x->ncoupled = jr->m - n;
            x->rows = DX_ARENA_ARRAY(w->arena, qs_coupled, x->ncoupled);
            for (int e = 0; e < x->ncoupled; e++)
                coupled_start(jr, e < first ? e : e + n, fps, &x->rows[e]);
            qs_ahead *y = waiting[n];
            if (!y) {
                waiting[n] = x;
                continue;
            }
            const int ok = factor_pair(&y->blk, &x->blk, n, w->qs_w, y->jb.L, x->jb.L);
            y->ok = ok & 1;
            x->ok = ok >> 1;
            if (y->ok && x->ok) couple_ahead(y, x, w->qs_w);
            else if (y->ok || x->ok) couple_ahead(y->ok ? y : x, NULL, w->qs_w);
            waiting[n] = NULL;
        }
    }
    for (int n = 2; n <= QS_MAX_BLOCK; n++) {
        qs_ahead *x = waiting[n];
        if (!x) continue;
        x->ok = factor(x->blk.J, x->blk.M, x->blk.cfm, n, w->qs_w, x->jb.L, x->blk.Ainv);
        if (x->ok) couple_ahead(x, NULL, w->qs_w);
    }
}

// The queued islands built in their order, phase by phase: every island's
// rows, the run joints' blocks (blocks_ahead), then every island's blocks
// and rows in the system.
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void build_queued(struct dxWorld *w, dReal h, qs_system *sys)
{
    qs_scratch *s = sys->scratch;
    const dReal fps = dRecip(h);
    for (int i = 0; i < s->nqueued; i++) island_rows(w, &s->queue[i], h, fps, sys);
    blocks_ahead(w, fps, sys);
    for (int i = 0; i < s->nqueued; i++) island_joints(w, &s->queue[i], h, fps, sys);
    s->nqueued = s->queued_joints = 0;
}

void dxQuickBuild(struct dxWorld *w, const dxIsland *is, const dxIslandBodies *bd, dReal h,
                  qs_system *sys, qs_island *part)
{
    qs_scratch *s = sys->scratch;
    part->body0 = sys->nbodies;
    sys->nbodies += is->nb + 1;
    if (!s->phased) {
        const qs_queued q = { is, bd, part, s->jrows };
        const dReal fps = dRecip(h);
        island_rows(w, &q, h, fps, sys);
        island_joints(w, &q, h, fps, sys);
        return;
    }
    if (s->queued_joints + is->nj > s->room) build_queued(w, h, sys);
    s->queue[s->nqueued++] = (qs_queued){ is, bd, part, s->jrows + s->queued_joints };
    s->queued_joints += is->nj;
    if (++s->next == s->count) build_queued(w, h, sys);
}
