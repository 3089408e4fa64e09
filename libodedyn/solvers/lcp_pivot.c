// SPDX-License-Identifier: BSD-3-Clause
//
// lcp_pivot.c -- Dantzig-style principal pivoting on the bounded rows of the LCP (see lcp.c
// for the whole algorithm and lcp_internal.h for the interface).
//
// The rows processed so far are split into a clamped set C (x free between its bounds,
// w = 0) and held rows N (x at a bound, w of the sign that bound allows). Driving a new row
// i: x[i] moves in the direction that brings w[i] toward 0, x[C] moves with it so that w[C]
// stays 0, x[N] stays put. The step stops at the first event: w[i] reaches 0 (i joins C),
// x[i] reaches a bound (i joins N), some x[C] reaches a bound (it moves to N) or some w[N]
// reaches 0 (it joins C); then driving goes on in the new direction. As A is positive
// semi-definite, w[i] only moves toward 0.
//
// A[C][C] is kept as L D L^T, in the order the rows joined C. A joining row borders the
// factorisation (one forward substitution within the profile); a leaving row is cut out and
// the rows after it get a rank-one update. x and w are updated step by step and each event
// sets its variable exactly to the bound or to 0, so x stays within its bounds up to rounding
// (clamped at the end); a final re-solve of A[C][C] would be no more accurate and, when it is
// ill-conditioned, would land past bounds.
//
// Singular A (redundant constraints): a row whose pivot would be rounding noise depends on C.
// It never joins C; it counts as solved if its w is zero within a loose tolerance, and is
// held with w = 0 until a change of C lets it join. Rounding can make degenerate rows flip
// between C and N in zero-length steps; such a row is kept out until C changes otherwise, and
// each drive has a step limit.

#include "lcp_internal.h"

#include <math.h>
#include <string.h>

// A row that depends on C is held as solved only if its |w| is within HOLD_FRACTION of the
// final tolerance (see row_residual), leaving room for the rounding that later steps add.
#define HOLD_FRACTION REAL(0.1)
// A drive gives up after 2 * (rows processed so far) + DRIVE_SLACK changes of C: far more
// than a drive takes, unless rounding makes it cycle.
#define DRIVE_SLACK 32
// A row of C whose bound is within CANDIDATE times the shortest step so far (compared by
// multiplying) may end the step: only then is its step length divided out.
#define CANDIDATE REAL(1.001)

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

static const dReal *row_of(const dxLcpPivot *s, int j) { return s->A + j * s->lda; }

static int is_held(int st) { return st == ST_LO || st == ST_HI || st == ST_ZERO; }

// Set the state of j, keeping the list of held rows.
static void set_state(dxLcpPivot *s, int j, int st)
{
    if (is_held(st) && s->hpos[j] < 0) {
        s->hpos[j] = s->nheld;
        s->held[s->nheld++] = j;
    } else if (!is_held(st) && s->hpos[j] >= 0) {
        int last = s->held[--s->nheld];
        s->held[s->hpos[j]] = last;
        s->hpos[last] = s->hpos[j];
        s->hpos[j] = -1;
    }
    s->state[j] = (signed char)st;
}

// A[j] x - b[j], and in *tol the tolerance DX_LCP_DEP_TOL * (|b[j]| + sum |A[j][k] x[k]|)
// within which the final check counts it as zero (b before elimination).
static dReal row_residual(const dxLcpPivot *s, int j, dReal *tol)
{
    int f = s->first[j];
    dReal size, r = dxLcpDotSize(row_of(s, j) + f, s->x + f, s->end[j] - f, &size);
    *tol = DX_LCP_DEP_TOL * (size + s->base[j]);
    return r - s->b[j];
}

// ---- the factor of A[C][C] ----

// The border of row j (see dxLcpBorder) into z; returns its pivot. y is left all zero.
static dReal c_forward(dxLcpPivot *s, int j)
{
    if (s->fwd_row == j && s->fwd_version == s->version) return s->fwd_pivot;
    const dReal *a = row_of(s, j);
    int m = s->f.m, first = m;
    if (s->pa.start) {   // scatter the row's nonzeros that are in C
        // Columns outside C go to y[m], cleared after: no branch on whether a column is in
        // C, which is unpredictable. (y has room: j is not in C, so m < n.)
        for (int k = s->pa.start[j]; k < s->pa.start[j + 1]; k++) {
            int c = s->pa.cols[k], q = s->cpos[c], out = -(q < 0);   // out: all ones or 0
            q = (q & ~out) | (m & out);
            s->y[q] = a[c];
            first = q < first ? q : first;
        }
        s->y[m] = 0;
    } else {   // dense: gather A[j][C]
        for (int k = m - 1; k >= 0; k--) {
            s->y[k] = a[s->f.cidx[k]];
            if (s->y[k] != 0) first = k;
        }
    }
    s->fwd_pivot = dxLcpBorder(&s->f, a[j], s->y, s->z, first, &s->yend);
    s->yfirst = first;
    for (int k = first; k < s->yend; k++) s->y[k] = 0;
    s->fwd_row = j;
    s->fwd_version = s->version;
    return s->fwd_pivot;
}

// Append j to C: the new row of L is z from the c_forward(s, j) just done, its pivot `pivot`.
static void c_add(dxLcpPivot *s, int j, dReal pivot)
{
    s->cpos[j] = s->f.m;
    dxLcpAppend(&s->f, j, pivot, s->z, s->yfirst, s->yend);
    set_state(s, j, ST_C);
    s->version++;
}

// Remove position r from C. Cutting row and column r out of L D L^T leaves the rows below
// with L' D' L'^T = L3 D3 L3^T + d[r] v v^T, v = column r of L below r: a rank-one update,
// done row by row (Gill, Golub, Murray & Saunders 1974, method C1) while each row is moved
// up by one and its columns after r left by one.
static void c_remove(dxLcpPivot *s, int r)
{
    dxLcpFactor *f = &s->f;
    int m = f->m;
    dReal alpha = f->d[r];
    s->cpos[f->cidx[r]] = -1;
    for (int q = r + 1; q < m; q++) {
        dReal *lq = dxLcpRow(f, q), *dst = dxLcpRow(f, q - 1);
        int st = f->lstart[q];
        dReal v = st <= r ? lq[r] : 0;
        int from = st > r ? st : r + 1;
        for (int c = from; c < q; c++) {
            v -= s->p[c] * lq[c];
            lq[c] += s->beta[c] * v;
        }
        dReal dq = f->d[q], dn = dq + alpha * v * v;
        s->p[q] = v;
        s->beta[q] = v * alpha / dn;
        alpha = alpha * dq / dn;
        if (st < r) memmove(dst + st, lq + st, (size_t)(r - st) * sizeof(dReal));
        memmove(dst + from - 1, lq + from, (size_t)(q - from) * sizeof(dReal));
        f->lstart[q - 1] = st <= r ? st : st - 1;
        f->d[q - 1] = dn;
        f->dinv[q - 1] = 1 / dn;
        f->cidx[q - 1] = f->cidx[q];
        s->cpos[f->cidx[q - 1]] = q - 1;
    }
    f->m = m - 1;
    s->version++;
}

// ---- driving one index ----

// The direction for driving i by sgn: dx[i] = sgn and dx[C] = -sgn A[C][C]^-1 A[C][i] (from
// the z of the c_forward(s, i) just done), into u by position in C; and the rates dw[j] =
// A[j] dx of the held rows, whose w must keep its sign (or stay 0).
static void set_direction(dxLcpPivot *s, int i, dReal sgn)
{
    int m = s->f.m, jmin = i, jmax = i;   // dx is zero outside [jmin, jmax]
    dReal *u = s->u;
    for (int k = 0; k < m; k++) u[k] = k >= s->yfirst && k < s->yend ? s->z[k] : 0;
    dxLcpSolveLT(&s->f, u, s->yend);
    for (int k = 0; k < m; k++) {
        int j = s->f.cidx[k];
        u[k] *= -sgn;
        s->dxf[j] = u[k];
        if (u[k] != 0 && j < jmin) jmin = j;
        if (u[k] != 0 && j > jmax) jmax = j;
    }
    s->dxf[i] = sgn;
    for (int q = 0; q < s->nheld; q++) {
        int j = s->held[q];
        int f = s->first[j] > jmin ? s->first[j] : jmin;
        int e = s->end[j] < jmax + 1 ? s->end[j] : jmax + 1;
        s->dw[j] = e > f ? dxLcpDot(row_of(s, j) + f, s->dxf + f, e - f) : 0;
    }
    for (int k = 0; k < m; k++) s->dxf[s->f.cidx[k]] = 0;
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
static lcp_event next_event(const dxLcpPivot *s, int i, dReal sgn, dReal dwi)
{
    const dReal *x = s->x, *w = s->w;
    lcp_event ev = { dInfinity, EV_NONE, i };
    if (dwi != 0) consider(&ev, -w[i] / dwi, EV_DRIVEN_ZERO, i);
    consider(&ev, sgn > 0 ? s->hi[i] - x[i] : x[i] - s->lo[i], EV_DRIVEN_BOUND, i);
    // Divide only where the step may be shorter: where the distance to the bound x[j] moves
    // toward (room, negated exactly when dx < 0) is below t |dx| CANDIDATE. The bound and the
    // sign are picked by indexing, not by a branch: the sign of dx is unpredictable, while
    // the test is rarely passed.
    const dReal *bound[2] = { s->hi, s->lo };
    static const dReal toward[2] = { 1, -1 };
    for (int k = 0; k < s->f.m; k++) {
        int j = s->f.cidx[k];
        dReal dx = s->u[k];
        int down = dx < 0;
        dReal room = bound[down][j] - x[j];
        if ((dx != 0) & (room * toward[down] < ev.t * dFabs(dx) * CANDIDATE))
            consider(&ev, room / dx, EV_C_HI - down, j);
    }
    for (int q = 0; q < s->nheld; q++) {
        int j = s->held[q], st = s->state[j];
        dReal dw = s->dw[j];
        int wrong = st == ST_LO ? dw < 0 : st == ST_HI ? dw > 0 : dw != 0;
        if (wrong && s->stamp[j] != s->version) consider(&ev, -w[j] / dw, EV_N_ZERO, j);
    }
    if (ev.t < 0) ev.t = 0;   // a value a rounding error past its limit: a zero step
    return ev;
}

static void take_step(dxLcpPivot *s, int i, dReal t, dReal sgn, dReal dwi)
{
    for (int k = 0; k < s->f.m; k++) s->x[s->f.cidx[k]] += t * s->u[k];
    s->x[i] += t * sgn;
    s->w[i] += t * dwi;
    for (int q = 0; q < s->nheld; q++) s->w[s->held[q]] += t * s->dw[s->held[q]];
}

static int independent(const dxLcpPivot *s, int j, dReal pivot)
{
    return pivot > DX_LCP_PIVOT_TOL * dFabs(s->diag[j]);
}

// A held row whose w reached 0 (or, for ST_ZERO, would move) joins C, unless it depends on C:
// then it stays (w == 0) and is not considered again until C changes.
static void n_to_c(dxLcpPivot *s, int j)
{
    s->w[j] = 0;
    dReal pivot = c_forward(s, j);
    if (independent(s, j, pivot)) c_add(s, j, pivot);
    else s->stamp[j] = s->version;
}

// Hold i, which depends on C and has |w[i]| within tolerance: w[i] counts as zero, x[i] stays
// where it is. Should a change of C make w[i] move, the event test lets i join C then.
static void hold_dependent(dxLcpPivot *s, int i)
{
    s->w[i] = 0;
    set_state(s, i, s->x[i] == s->lo[i] ? ST_LO : s->x[i] == s->hi[i] ? ST_HI : ST_ZERO);
}

// Handle an event after the step of the drive of i in direction sgn. Returns 1 if the drive
// is over.
static int apply_event(dxLcpPivot *s, int i, lcp_event ev, dReal sgn)
{
    int j = ev.j;
    switch (ev.kind) {
    case EV_DRIVEN_ZERO:
        s->w[i] = 0;
        c_add(s, i, c_forward(s, i));   // recomputed only if n_to_c used y and z since
        return 1;
    case EV_DRIVEN_BOUND:
        s->x[i] = sgn > 0 ? s->hi[i] : s->lo[i];
        set_state(s, i, sgn > 0 ? ST_HI : ST_LO);
        return 1;
    case EV_C_LO:
    case EV_C_HI:
        s->x[j] = ev.kind == EV_C_LO ? s->lo[j] : s->hi[j];
        s->w[j] = 0;
        c_remove(s, s->cpos[j]);
        set_state(s, j, ev.kind == EV_C_LO ? ST_LO : ST_HI);
        return 0;
    default:
        n_to_c(s, j);
        return 0;
    }
}

// Follow the direction set up for driving i through the events that leave C as it is (a
// dependent row reaching w == 0), until the drive ends (returns 1), C changes (returns 0,
// the event in *last, the distance moved in *moved) or nothing stops it (returns -1).
static int follow_direction(dxLcpPivot *s, int i, dReal sgn, dReal dwi, lcp_event *last,
                            dReal *moved)
{
    unsigned version = s->version;
    *moved = 0;
    do {
        *last = next_event(s, i, sgn, dwi);
        if (last->kind == EV_NONE) return -1;
        take_step(s, i, last->t, sgn, dwi);
        *moved += last->t;
        if (apply_event(s, i, *last, sgn)) return 1;
    } while (s->version == version);
    return 0;
}

// Solve for index i, the np-th row processed. Returns 0 if it hit the step limit. i is then
// held (ST_FREE) at a value within its bounds, as when it depends on C and w[i] cannot be
// brought to 0 by moving x[i]; the final check tells how far from complementary it is.
int dxLcpPivotDrive(dxLcpPivot *s, int i, int np)
{
    dReal *x = s->x, *w = s->w, lo = s->lo[i], hi = s->hi[i];
    if (lo == hi) {
        x[i] = lo;
        set_state(s, i, ST_FIXED);
        return 1;
    }
    dReal wtol;
    w[i] = row_residual(s, i, &wtol);
    wtol *= HOLD_FRACTION;
    int joined = -1;   // the row that joined C at the end of the last round
    for (int round = 0; round <= 2 * np + DRIVE_SLACK; round++) {
        if (x[i] <= lo && w[i] >= 0) {
            set_state(s, i, ST_LO);
            return 1;
        }
        if (x[i] >= hi && w[i] <= 0) {
            set_state(s, i, ST_HI);
            return 1;
        }
        dReal pivot = c_forward(s, i);
        int indep = independent(s, i, pivot);
        if (w[i] == 0 || (!indep && dFabs(w[i]) <= wtol)) {
            if (indep) c_add(s, i, pivot);
            else hold_dependent(s, i);
            return 1;
        }
        // While i depends on C, w[i] cannot change; moving x[i] can still free a row of C.
        dReal sgn = w[i] < 0 ? 1 : -1;
        dReal dwi = indep ? sgn * pivot : 0;
        set_direction(s, i, sgn);
        lcp_event ev;
        dReal moved;
        int r = follow_direction(s, i, sgn, dwi, &ev, &moved);
        if (r > 0) return 1;
        if (r < 0) {   // i depends on C, x[i] could move without bound: left to the check
            set_state(s, i, ST_FREE);
            return 1;
        }
        // A row at a bound with w == 0 that just joined C may leave it again without any
        // movement: in exact arithmetic it would move off its bound, so its numbers are
        // rounding noise. Keep it in N until C changes again, or it would flip forever.
        if (moved == 0 && ev.j == joined && (ev.kind == EV_C_LO || ev.kind == EV_C_HI))
            s->stamp[ev.j] = s->version;
        joined = ev.kind == EV_N_ZERO ? ev.j : -1;
    }
    set_state(s, i, ST_FREE);
    return 0;
}

int dxLcpPivotProcessed(const dxLcpPivot *s, int i) { return s->state[i] != ST_NEW; }

void dxLcpPivotRestart(dxLcpPivot *s)
{
    s->f.m = 0;
    s->nheld = 0;
    s->version++;
    for (int j = 0; j < s->n; j++) {
        s->state[j] = ST_NEW;
        s->cpos[j] = -1;
        s->hpos[j] = -1;
    }
}

void dxLcpPivotSetup(dxLcpPivot *s, dxArena *arena, int n)
{
    s->n = n;
    ptrdiff_t ld = dPAD(n);
    // One allocation: the reals (L, then nine vectors), the ints (seven), the stamps, the states.
    size_t reals = (size_t)n * (size_t)ld + 9 * (size_t)n, ints = 7 * (size_t)n;
    dReal *r = dxArenaAlloc(arena, reals * sizeof(dReal) + ints * sizeof(int) +
                                       (size_t)n * (sizeof(unsigned) + 1));
    int *v = (int *)(void *)(r + reals);
    s->f.L = r;
    r += (size_t)n * (size_t)ld;
    s->y = r;
    s->z = r + n;
    s->u = r + 2 * n;
    s->p = r + 3 * n;
    s->beta = r + 4 * n;
    s->dxf = r + 5 * n;
    s->dw = r + 6 * n;
    s->f.d = r + 7 * n;
    s->f.dinv = r + 8 * n;
    s->first = v;
    s->end = v + n;
    s->held = v + 2 * n;
    s->hpos = v + 3 * n;
    s->cpos = v + 4 * n;
    s->f.cidx = v + 5 * n;
    s->f.lstart = v + 6 * n;
    s->stamp = (unsigned *)(void *)(v + ints);
    s->state = (signed char *)(s->stamp + n);
    s->f.m = 0;
    s->f.ld = ld;
    s->version = 1;
    s->fwd_row = -1;
    for (int j = 0; j < n; j++) {
        int f = 0, e = n;
        if (s->pa.start) {
            f = n;
            e = 0;
            for (int k = s->pa.start[j]; k < s->pa.start[j + 1]; k++) {
                int c = s->pa.cols[k];
                if (c < f) f = c;
                if (c + 1 > e) e = c + 1;
            }
        }
        s->first[j] = f < e ? f : 0;
        s->end[j] = e;
        s->y[j] = 0;
        s->dxf[j] = 0;
        s->stamp[j] = 0;
    }
    dxLcpPivotRestart(s);
}
