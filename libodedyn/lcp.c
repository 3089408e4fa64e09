// SPDX-License-Identifier: BSD-3-Clause
//
// lcp.c -- the mixed (boxed) LCP solver behind dWorldStep (see lcp.h for the problem).
//
// Algorithm: Dantzig-style principal pivoting (Baraff 1994; Cottle, Pang & Stone ch. 4).
// The unbounded rows are solved first as a linear system. The others are then added one at
// a time, friction rows last. The rows solved so far are split into a clamped set C (x free
// between its bounds, w = 0) and held rows N (x at a bound, w of the sign that bound allows).
// Adding row i "drives" it: x[i] moves in the direction that brings w[i] toward 0, x[C] moves
// with it so that w[C] stays 0, x[N] stays put. The step stops at the first event: w[i]
// reaches 0 (i joins C), x[i] reaches a bound (i joins N), some x[C] reaches a bound (it moves
// to N) or some w[N] reaches 0 (it joins C); then driving goes on in the new direction. As A
// is positive semi-definite, w[i] only moves toward 0.
//
// A[C][C] is kept as L D L^T, in the order the rows joined C. A joining row borders the
// factorisation (one forward substitution, O(|C|^2)); a leaving row is cut out and the rows
// after it get a rank-one update (O(|C|^2)). Each row of L records where its nonzeros start
// and each row of A its nonzero extent, so that banded or block-sparse problems cost far less
// than dense ones. x and w are updated step by step and each event sets its variable exactly
// to the bound or to 0, so x stays within its bounds up to rounding (clamped at the end); a
// final re-solve of A[C][C] would be no more accurate and, when it is ill-conditioned, would
// land past bounds.
//
// Singular A (redundant constraints): a row whose pivot would be rounding noise depends on C.
// It never joins C; it counts as solved if its w is zero within a loose tolerance, and is
// held with w = 0 until a change of C lets it join. Rounding can make degenerate rows flip
// between C and N in zero-length steps; such a row is kept out until C changes otherwise, and
// each drive has a step limit.

#include "lcp.h"

#include <float.h>
#include <math.h>
#include <string.h>

#ifdef dSINGLE
#define LCP_EPS FLT_EPSILON
#define DEP_TOL REAL(3.5e-4)   // about sqrt(FLT_EPSILON)
#else
#define LCP_EPS DBL_EPSILON
#define DEP_TOL REAL(1.5e-8)   // about sqrt(DBL_EPSILON)
#endif

// A pivot of A[C+j][C+j] below PIVOT_TOL * A[j][j] means row j depends on the rows in C. The
// computed pivot of an exactly dependent row is rounding noise, typically some LCP_EPS *
// A[j][j] (more when A[C][C] is ill-conditioned). A CFM of 1e-10 on a unit diagonal stays
// well above the threshold in double precision; in single precision it is below rounding.
#define PIVOT_TOL ((dReal)(256 * LCP_EPS))
// A row that depends on C is held as solved only if its |w| is within HOLD_FRACTION of the
// final tolerance (see row_residual), leaving room for the rounding that later steps add.
#define HOLD_FRACTION REAL(0.1)
// A drive gives up after 2 * (rows solved so far) + DRIVE_SLACK changes of C: far more than a
// drive takes, unless rounding makes it cycle.
#define DRIVE_SLACK 32

enum {
    ST_NEW,     // not processed yet: x at its starting value
    ST_C,       // clamped: w == 0, lo <= x <= hi
    ST_LO,      // x == lo, w >= 0
    ST_HI,      // x == hi, w <= 0
    ST_ZERO,    // lo < x < hi held, w == 0: a row that depends on C
    ST_FREE,    // held where it is, no condition on w: given up on
    ST_FIXED    // lo == hi
};

enum { EV_NONE, EV_DRIVEN_ZERO, EV_DRIVEN_BOUND, EV_C_LO, EV_C_HI, EV_N_ZERO };

typedef struct lcp_event {
    dReal t;    // step length
    int kind;   // EV_*
    int j;      // the index concerned
} lcp_event;

typedef struct lcp {
    int n, nub;
    ptrdiff_t ld;          // row skip of A and of L
    const dReal *A, *b;
    dReal *x, *w, *lo, *hi;
    const int *findex;
    int *order;            // the processing order; order[0..np) are processed
    signed char *state;    // ST_* of each index
    int *first, *end;      // nonzero extent [first, end) of each row of A

    // A[C][C] = L D L^T with C = cidx[0..m) in the order the rows joined. Row k of L holds
    // columns [lstart[k], k); the entries before lstart[k] are zero, the diagonal is 1.
    int m;
    dReal *L, *d, *dinv;
    int *cidx, *cpos, *lstart;   // cpos[j]: position of j in cidx, -1 if not in C

    dReal *y, *z;          // from c_forward: L y = A[C][j], z = D^-1 y (the new row of L)
    int yfirst;            // y[k] == 0 for k < yfirst
    dReal *u;              // the direction: x[cidx[k]] moves by t * u[k]
    dReal *dw;             // w[j] moves by t * dw[j] for the held rows
    dReal *dxf;            // the direction scattered to full length (zero between uses)
    dReal *p, *beta;       // rank-one update scratch
    unsigned *stamp;       // stamp[j] == version: j was found dependent on the current C
    unsigned version;      // changes whenever C changes
} lcp;

// Dot product with four partial sums: the four lanes let the compiler vectorise the loop
// body (at -O2 GCC only vectorises such straight-line groups, not loops needing an epilogue).
static dReal dot(const dReal *restrict a, const dReal *restrict b, int n)
{
    dReal s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    int k = 0;
    for (; k + 4 <= n; k += 4) {
        s0 += a[k] * b[k];
        s1 += a[k + 1] * b[k + 1];
        s2 += a[k + 2] * b[k + 2];
        s3 += a[k + 3] * b[k + 3];
    }
    for (; k < n; k++) s0 += a[k] * b[k];
    return (s0 + s1) + (s2 + s3);
}

// a . b, and in *size the sum of |a[k] b[k]| (the scale of the terms, for tolerances).
static dReal dot_size(const dReal *restrict a, const dReal *restrict b, int n, dReal *size)
{
    dReal s0 = 0, s1 = 0, a0 = 0, a1 = 0;
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        dReal t0 = a[k] * b[k], t1 = a[k + 1] * b[k + 1];
        s0 += t0;
        s1 += t1;
        a0 += dFabs(t0);
        a1 += dFabs(t1);
    }
    for (; k < n; k++) {
        dReal t0 = a[k] * b[k];
        s0 += t0;
        a0 += dFabs(t0);
    }
    *size = a0 + a1;
    return s0 + s1;
}

static const dReal *row_of(const lcp *s, int j) { return s->A + j * s->ld; }
static dReal *lrow(const lcp *s, int k) { return s->L + k * s->ld; }

// Row j of A times v, over the row's nonzero extent.
static dReal row_dot(const lcp *s, int j, const dReal *v)
{
    int f = s->first[j];
    return dot(row_of(s, j) + f, v + f, s->end[j] - f);
}

// A[j] x - b[j], and in *tol the tolerance DEP_TOL * (|b[j]| + sum |A[j][k] x[k]|) within
// which the final check counts it as zero.
static dReal row_residual(const lcp *s, int j, dReal *tol)
{
    dReal size;
    int f = s->first[j];
    dReal r = dot_size(row_of(s, j) + f, s->x + f, s->end[j] - f, &size) - s->b[j];
    *tol = DEP_TOL * (size + dFabs(s->b[j]));
    return r;
}

static dReal lower(const lcp *s, int j) { return j < s->nub ? -dInfinity : s->lo[j]; }
static dReal upper(const lcp *s, int j) { return j < s->nub ? dInfinity : s->hi[j]; }

// The start value of an unprocessed x: the point of [lo, hi] nearest 0.
static dReal clamp_zero(dReal lo, dReal hi) { return lo > 0 ? lo : hi < 0 ? hi : 0; }

// ---- the factorisation of A[C][C] ----

// Solve L v = v in place, given v[k] == 0 for k < f.
static void l_solve(const lcp *s, dReal *v, int f)
{
    for (int k = f; k < s->m; k++) {
        int st = s->lstart[k] > f ? s->lstart[k] : f;
        v[k] -= dot(lrow(s, k) + st, v + st, k - st);
    }
}

// y -= a x, unrolled like dot.
static void axpy_sub(dReal *restrict y, const dReal *restrict x, dReal a, int n)
{
    int k = 0;
    for (; k + 4 <= n; k += 4) {
        y[k] -= a * x[k];
        y[k + 1] -= a * x[k + 1];
        y[k + 2] -= a * x[k + 2];
        y[k + 3] -= a * x[k + 3];
    }
    for (; k < n; k++) y[k] -= a * x[k];
}

// Solve L^T v = v in place (column-oriented, so the inner loop runs along rows of L).
static void lt_solve(const lcp *s, dReal *v)
{
    for (int k = s->m - 1; k > 0; k--) {
        int st = s->lstart[k];
        if (v[k] != 0) axpy_sub(v + st, lrow(s, k) + st, v[k], k - st);
    }
}

// Gather a = A[C][j], solve L y = a and set z = D^-1 y. Returns A[j][j] - y.z: the pivot j
// would get on joining C (the Schur complement of A[C][C]; zero if j depends on C).
static dReal c_forward(lcp *s, int j)
{
    const dReal *aj = row_of(s, j);
    int m = s->m, f = m;
    for (int k = 0; k < m; k++) {
        s->y[k] = aj[s->cidx[k]];
        if (s->y[k] != 0 && f == m) f = k;
    }
    l_solve(s, s->y, f);
    for (int k = 0; k < f; k++) s->z[k] = 0;
    for (int k = f; k < m; k++) s->z[k] = s->y[k] * s->dinv[k];
    s->yfirst = f;
    return aj[j] - dot(s->y + f, s->z + f, m - f);
}

// Append j to C: the new row of L is z from the c_forward(s, j) just done, its pivot `pivot`.
static void c_add(lcp *s, int j, dReal pivot)
{
    int m = s->m, f = s->yfirst;
    memcpy(lrow(s, m) + f, s->z + f, (size_t)(m - f) * sizeof(dReal));
    s->lstart[m] = f;
    s->d[m] = pivot;
    s->dinv[m] = 1 / pivot;
    s->cidx[m] = j;
    s->cpos[j] = m;
    s->state[j] = ST_C;
    s->m = m + 1;
    s->version++;
}

// Remove position r from C. Cutting row and column r out of L D L^T leaves the rows below
// with L' D' L'^T = L3 D3 L3^T + d[r] v v^T, v = column r of L below r: a rank-one update,
// done row by row (Gill, Golub, Murray & Saunders 1974, method C1) while each row is moved
// up by one and its columns after r left by one.
static void c_remove(lcp *s, int r)
{
    int m = s->m;
    dReal alpha = s->d[r];
    s->cpos[s->cidx[r]] = -1;
    for (int q = r + 1; q < m; q++) {
        dReal *lq = lrow(s, q), *dst = lrow(s, q - 1);
        int st = s->lstart[q];
        dReal v = st <= r ? lq[r] : 0;
        int from = st > r ? st : r + 1;
        for (int c = from; c < q; c++) {
            v -= s->p[c] * lq[c];
            lq[c] += s->beta[c] * v;
        }
        dReal dq = s->d[q], dn = dq + alpha * v * v;
        s->p[q] = v;
        s->beta[q] = v * alpha / dn;
        alpha = alpha * dq / dn;
        if (st < r) memmove(dst + st, lq + st, (size_t)(r - st) * sizeof(dReal));
        memmove(dst + from - 1, lq + from, (size_t)(q - from) * sizeof(dReal));
        s->lstart[q - 1] = st <= r ? st : st - 1;
        s->d[q - 1] = dn;
        s->dinv[q - 1] = 1 / dn;
        s->cidx[q - 1] = s->cidx[q];
        s->cpos[s->cidx[q - 1]] = q - 1;
    }
    s->m = m - 1;
    s->version++;
}

// x[C] = A[C][C]^-1 (b[C] - A[C][rest] x[rest]): the clamped values for the current sets.
static void c_resolve(lcp *s)
{
    int m = s->m;
    for (int k = 0; k < m; k++) s->x[s->cidx[k]] = 0;
    for (int k = 0; k < m; k++) {
        int j = s->cidx[k];
        s->u[k] = s->b[j] - row_dot(s, j, s->x);
    }
    l_solve(s, s->u, 0);
    for (int k = 0; k < m; k++) s->u[k] *= s->dinv[k];
    lt_solve(s, s->u);
    for (int k = 0; k < m; k++) s->x[s->cidx[k]] = s->u[k];
}

// ---- driving one index ----

// The direction for driving i by sgn: dx[i] = sgn and dx[C] = -sgn A[C][C]^-1 A[C][i] (from
// the z of the c_forward(s, i) just done), into u by position in C; and the rates dw[j] =
// A[j] dx of the held rows, whose w must keep its sign (or stay 0).
static void set_direction(lcp *s, int i, int np, dReal sgn)
{
    int m = s->m, jmin = i, jmax = i;   // dx is zero outside [jmin, jmax]
    dReal *u = s->u;
    memcpy(u, s->z, (size_t)m * sizeof(dReal));
    lt_solve(s, u);
    for (int k = 0; k < m; k++) {
        int j = s->cidx[k];
        u[k] *= -sgn;
        s->dxf[j] = u[k];
        if (j < jmin) jmin = j;
        if (j > jmax) jmax = j;
    }
    s->dxf[i] = sgn;
    for (int q = 0; q < np - 1; q++) {
        int j = s->order[q], st = s->state[j];
        if (st != ST_LO && st != ST_HI && st != ST_ZERO) continue;
        int f = s->first[j] > jmin ? s->first[j] : jmin;
        int e = s->end[j] < jmax + 1 ? s->end[j] : jmax + 1;
        s->dw[j] = e > f ? dot(row_of(s, j) + f, s->dxf + f, e - f) : 0;
    }
    for (int k = 0; k < m; k++) s->dxf[s->cidx[k]] = 0;
    s->dxf[i] = 0;
}

static void consider(lcp_event *ev, dReal t, int kind, int j)
{
    if (t < ev->t) {
        ev->t = t;
        ev->kind = kind;
        ev->j = j;
    }
}

// The first event along the current direction (dwi: the rate of w[i]). The driven index is
// considered first, so it wins ties.
static lcp_event next_event(const lcp *s, int i, int np, dReal sgn, dReal dwi)
{
    const dReal *x = s->x, *w = s->w;
    lcp_event ev = { dInfinity, EV_NONE, i };
    if (dwi != 0) consider(&ev, -w[i] / dwi, EV_DRIVEN_ZERO, i);
    consider(&ev, sgn > 0 ? s->hi[i] - x[i] : x[i] - s->lo[i], EV_DRIVEN_BOUND, i);
    for (int k = 0; k < s->m; k++) {
        int j = s->cidx[k];
        dReal dx = s->u[k];
        if (dx < 0) consider(&ev, (lower(s, j) - x[j]) / dx, EV_C_LO, j);
        else if (dx > 0) consider(&ev, (upper(s, j) - x[j]) / dx, EV_C_HI, j);
    }
    for (int q = 0; q < np - 1; q++) {
        int j = s->order[q], st = s->state[j];
        if (st != ST_LO && st != ST_HI && st != ST_ZERO) continue;
        dReal dw = s->dw[j];
        int wrong = st == ST_LO ? dw < 0 : st == ST_HI ? dw > 0 : dw != 0;
        if (wrong && s->stamp[j] != s->version) consider(&ev, -w[j] / dw, EV_N_ZERO, j);
    }
    if (ev.t < 0) ev.t = 0;   // a value a rounding error past its limit: a zero step
    return ev;
}

static void take_step(lcp *s, int i, int np, dReal t, dReal sgn, dReal dwi)
{
    for (int k = 0; k < s->m; k++) s->x[s->cidx[k]] += t * s->u[k];
    s->x[i] += t * sgn;
    s->w[i] += t * dwi;
    for (int q = 0; q < np - 1; q++) {
        int j = s->order[q], st = s->state[j];
        if (st == ST_LO || st == ST_HI || st == ST_ZERO) s->w[j] += t * s->dw[j];
    }
}

// A held row whose w reached 0 (or, for ST_ZERO, would move) joins C, unless it depends on C:
// then it stays (w == 0) and is not considered again until C changes.
static void n_to_c(lcp *s, int j)
{
    s->w[j] = 0;
    dReal pivot = c_forward(s, j);
    if (pivot > PIVOT_TOL * dFabs(row_of(s, j)[j])) c_add(s, j, pivot);
    else s->stamp[j] = s->version;
}

// Hold i, which depends on C and has |w[i]| within tolerance: w[i] counts as zero, x[i] stays
// where it is. Should a change of C make w[i] move, the event test lets i join C then.
static void hold_dependent(lcp *s, int i)
{
    s->w[i] = 0;
    s->state[i] = s->x[i] == lower(s, i) ? ST_LO : s->x[i] == upper(s, i) ? ST_HI : ST_ZERO;
}

// Handle an event after the step of the drive of i in direction sgn. Returns 1 if the drive
// is over.
static int apply_event(lcp *s, int i, lcp_event ev, dReal sgn)
{
    int j = ev.j;
    switch (ev.kind) {
    case EV_DRIVEN_ZERO:
        s->w[i] = 0;
        c_add(s, i, c_forward(s, i));   // again: n_to_c may have used y and z since
        return 1;
    case EV_DRIVEN_BOUND:
        s->x[i] = sgn > 0 ? s->hi[i] : s->lo[i];
        s->state[i] = sgn > 0 ? ST_HI : ST_LO;
        return 1;
    case EV_C_LO:
    case EV_C_HI:
        s->x[j] = ev.kind == EV_C_LO ? s->lo[j] : s->hi[j];
        s->w[j] = 0;
        c_remove(s, s->cpos[j]);
        s->state[j] = ev.kind == EV_C_LO ? ST_LO : ST_HI;
        return 0;
    default:
        n_to_c(s, j);
        return 0;
    }
}

// Follow the direction set up for driving i through the events that leave C as it is (a
// dependent row reaching w == 0), until the drive ends (returns 1), C changes (returns 0,
// the event in *last, the distance moved in *moved) or nothing stops it (returns -1).
static int follow_direction(lcp *s, int i, int np, dReal sgn, dReal dwi, lcp_event *last,
                            dReal *moved)
{
    unsigned version = s->version;
    *moved = 0;
    do {
        *last = next_event(s, i, np, sgn, dwi);
        if (last->kind == EV_NONE) return -1;
        take_step(s, i, np, last->t, sgn, dwi);
        *moved += last->t;
        if (apply_event(s, i, *last, sgn)) return 1;
    } while (s->version == version);
    return 0;
}

// Solve for index i = order[np - 1]. Returns 0 if it hit the step limit. i is then held
// (ST_FREE) at a value within its bounds, as when it depends on C and w[i] cannot be brought
// to 0 by moving x[i]; finish() checks how far from complementary it is.
static int drive(lcp *s, int i, int np)
{
    dReal *x = s->x, *w = s->w, lo = s->lo[i], hi = s->hi[i];
    if (lo == hi) {
        x[i] = lo;
        s->state[i] = ST_FIXED;
        return 1;
    }
    dReal wtol, ptol = PIVOT_TOL * dFabs(row_of(s, i)[i]);
    w[i] = row_residual(s, i, &wtol);
    wtol *= HOLD_FRACTION;
    int joined = -1;   // the row that joined C at the end of the last round
    for (int round = 0; round <= 2 * np + DRIVE_SLACK; round++) {
        if (x[i] <= lo && w[i] >= 0) {
            s->state[i] = ST_LO;
            return 1;
        }
        if (x[i] >= hi && w[i] <= 0) {
            s->state[i] = ST_HI;
            return 1;
        }
        dReal pivot = c_forward(s, i);
        int independent = pivot > ptol;
        if (w[i] == 0 || (!independent && dFabs(w[i]) <= wtol)) {
            if (independent) c_add(s, i, pivot);
            else hold_dependent(s, i);
            return 1;
        }
        // While i depends on C, w[i] cannot change; moving x[i] can still free a row of C.
        dReal sgn = w[i] < 0 ? 1 : -1;
        dReal dwi = independent ? sgn * pivot : 0;
        set_direction(s, i, np, sgn);
        lcp_event ev;
        dReal moved;
        int r = follow_direction(s, i, np, sgn, dwi, &ev, &moved);
        if (r > 0) return 1;
        if (r < 0) {   // i depends on C, x[i] could move without bound: leave it to finish()
            s->state[i] = ST_FREE;
            return 1;
        }
        // A row at a bound with w == 0 that just joined C may leave it again without any
        // movement: in exact arithmetic it would move off its bound, so its numbers are
        // rounding noise. Keep it in N until C changes again, or it would flip forever.
        if (moved == 0 && ev.j == joined && (ev.kind == EV_C_LO || ev.kind == EV_C_HI))
            s->stamp[ev.j] = s->version;
        joined = ev.kind == EV_N_ZERO ? ev.j : -1;
    }
    s->state[i] = ST_FREE;
    return 0;
}

// ---- setup and the driver ----

static void setup(lcp *s, dxArena *arena, int n, int nub)
{
    s->n = n;
    s->nub = nub;
    s->ld = dPAD(n);
    s->order = DX_ARENA_ARRAY(arena, int, n);
    s->state = DX_ARENA_ARRAY(arena, signed char, n);
    s->first = DX_ARENA_ARRAY(arena, int, n);
    s->end = DX_ARENA_ARRAY(arena, int, n);
    s->m = 0;
    s->L = DX_ARENA_ARRAY(arena, dReal, (size_t)n * (size_t)s->ld);
    s->d = DX_ARENA_ARRAY(arena, dReal, n);
    s->dinv = DX_ARENA_ARRAY(arena, dReal, n);
    s->cidx = DX_ARENA_ARRAY(arena, int, n);
    s->cpos = DX_ARENA_ARRAY(arena, int, n);
    s->lstart = DX_ARENA_ARRAY(arena, int, n);
    s->y = DX_ARENA_ARRAY(arena, dReal, n);
    s->z = DX_ARENA_ARRAY(arena, dReal, n);
    s->u = DX_ARENA_ARRAY(arena, dReal, n);
    s->p = DX_ARENA_ARRAY(arena, dReal, n);
    s->beta = DX_ARENA_ARRAY(arena, dReal, n);
    s->dxf = DX_ARENA_ARRAY(arena, dReal, n);
    s->dw = DX_ARENA_ARRAY(arena, dReal, n);
    s->stamp = DX_ARENA_ARRAY(arena, unsigned, n);
    s->version = 1;
    for (int j = 0; j < n; j++) {
        const dReal *a = row_of(s, j);
        int f = 0, e = n;
        while (f < n && a[f] == 0) f++;
        while (e > f && a[e - 1] == 0) e--;
        s->first[j] = f;
        s->end[j] = e;
        int friction = j >= nub && s->findex && s->findex[j] >= 0;
        s->x[j] = j < nub || friction ? 0 : clamp_zero(s->lo[j], s->hi[j]);
        s->state[j] = ST_NEW;
        s->cpos[j] = -1;
        s->dxf[j] = 0;
        s->stamp[j] = 0;
    }
}

// The unbounded rows: factor A[nub][nub] by bordering, then solve. A dependent row is held at
// 0; it is only right if that leaves its w at zero (the system is consistent).
static void solve_unbounded(lcp *s)
{
    for (int j = 0; j < s->nub; j++) {
        s->order[j] = j;
        dReal pivot = c_forward(s, j);
        if (pivot > PIVOT_TOL * dFabs(row_of(s, j)[j])) c_add(s, j, pivot);
        else s->state[j] = ST_FREE;
    }
    c_resolve(s);
    for (int j = 0; j < s->nub; j++) {
        dReal tol;
        if (s->state[j] != ST_FREE) continue;
        if (dFabs(row_residual(s, j, &tol)) <= HOLD_FRACTION * tol) hold_dependent(s, j);
    }
}

static void set_friction_bounds(lcp *s, int i)
{
    dReal xn = s->x[s->findex[i]];
    dReal h = xn == 0 ? 0 : dFabs(s->hi[i] * xn);   // no 0 * inf
    s->lo[i] = -h;
    s->hi[i] = h;
}

// Clamp x to its bounds (a clamped x may have rounded past one), replace anything not finite,
// set w = A x - b, and check the conditions to the loose tolerance of row_residual.
// Returns 0 if something had to be replaced or a condition does not hold.
static int finish(lcp *s)
{
    int ok = 1;
    for (int j = 0; j < s->n; j++) {
        dReal lo = lower(s, j), hi = upper(s, j), v = s->x[j];
        if (v < lo) v = lo;
        if (v > hi) v = hi;
        if (!isfinite(v)) {
            v = clamp_zero(lo, hi);
            ok = 0;
        }
        s->x[j] = v;
    }
    // A row whose own terms are tiny (x and b near 0) still carries the rounding
    // of the whole solve: its tolerance has a floor relative to the largest row.
    dReal largest = 0;
    for (int j = 0; j < s->n; j++) {
        dReal tol;
        s->w[j] = row_residual(s, j, &tol);
        if (tol > largest) largest = tol;
    }
    const dReal floor_tol = largest * REAL(1e-3);
    for (int j = 0; j < s->n; j++) {
        dReal tol, w = row_residual(s, j, &tol), x = s->x[j];
        tol += floor_tol;
        int off_lo = x > lower(s, j), off_hi = x < upper(s, j);
        if (s->state[j] != ST_FIXED && ((w > tol && off_lo) || (w < -tol && off_hi))) ok = 0;
    }
    return ok;
}

int dxSolveLCP(dxArena *arena, int n, dReal *A, dReal *x, dReal *b, dReal *w, int nub,
               dReal *lo, dReal *hi, const int *findex)
{
    if (n <= 0) return 1;
    if (nub > n) nub = n;
    if (nub < 0) nub = 0;
    dxArenaMark mark = dxArenaSave(arena);
    lcp s = { .A = A, .b = b, .x = x, .w = w, .lo = lo, .hi = hi, .findex = findex };
    setup(&s, arena, n, nub);
    solve_unbounded(&s);
    int ok = 1, np = nub;
    for (int pass = 0; pass < 2; pass++) {   // rows without friction, then friction rows
        // Every friction bound comes from the normal forces of the frictionless
        // solution, before any friction row moves load between contacts: the
        // friction of a sliding body is then mu times its whole normal load.
        if (pass == 1 && findex)
            for (int i = nub; i < n; i++)
                if (findex[i] >= 0) set_friction_bounds(&s, i);
        for (int i = nub; i < n; i++) {
            int friction = findex && findex[i] >= 0;
            if (friction != pass) continue;
            s.order[np++] = i;
            ok &= drive(&s, i, np);
        }
    }
    ok &= finish(&s);
    dxArenaRestore(arena, mark);
    return ok;
}
