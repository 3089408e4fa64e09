// SPDX-License-Identifier: BSD-3-Clause
//
// lcp.c -- the mixed (boxed) LCP solver behind dWorldStep (see lcp.h for the problem).
//
// Algorithm: Dantzig-style principal pivoting (Baraff 1994; Cottle, Pang & Stone ch. 4;
// lcp_pivot.c) on the bounded rows, after the unbounded ones are eliminated, all of it
// exploiting the sparsity of A (lcp_sparse.c).
//
// Elimination: the unbounded rows U (the first nub, and any row with infinite bounds and no
// friction index) always have w = 0, so x[U] = A[U][U]^-1 (b[U] - A[U][B] x[B]) and the other
// rows B form the LCP of the Schur complement S = A[B][B] - A[B][U] A[U][U]^-1 A[U][B] with
// right-hand side b[B] - A[B][U] A[U][U]^-1 b[U]. A[U][U] is factored once as L D L^T in
// reverse breadth-first order, which keeps each connected part of it (the joint rows of one
// articulated body) together and its factor within a narrow profile. With
// Q = D^-1/2 L^-1 A[U][B], S = A[B][B] - Q^T Q, where two rows of Q only meet within the
// parts both touch. The pivoting then works on S alone, far smaller than A when most rows
// are joint rows. An unbounded row that depends on the others (a pivot that is rounding
// noise) is left out of the elimination and treated as a bounded row with infinite bounds.
//
// Pivoting: the rows of B in interaction order (reverse breadth-first on the pattern of S:
// rows that interact close together), so that the factor of S[C][C] that the pivoting grows
// (in the order rows join C) stays sparse within its profile. First the rows without
// friction alone, for the normal forces all friction bounds come from; then every row, from
// an empty C and x where the first pass left it. (Small problems skip the reordering and
// append the friction rows to the first pass instead: it cannot gain there.)
//
// Finally x[U] from x[B], then w = A x - b and a check of the conditions over the whole
// problem.

#include "lcp_internal.h"

#include <math.h>
#include <string.h>

// Up to this many rows of B are pivoted in their given order, the friction rows appended to
// the first pass: the interaction order would not pay for itself.
#define ORDER_MIN_ROWS 48

// The start value of an unprocessed x: the point of [lo, hi] nearest 0.
static dReal clamp_zero(dReal lo, dReal hi) { return lo > 0 ? lo : hi < 0 ? hi : 0; }

// ---- the whole problem ----

// The problem as given, and its split into eliminated rows U and pivoted rows B.
typedef struct problem {
    int n, nub;
    const dReal *dense;    // A in full (row skip dPAD(n)) if given so, else NULL
    dxLCPMatrix A;         // the nonzeros of A, unless it is small and given in full
    dxLcpPattern pa;
    const dReal *b;
    dReal *x, *w, *lo, *hi;
    const int *findex;
    dReal *diag;           // the diagonal of A

    dxLcpFactor fu;        // A[U][U], fu.cidx: the rows of U in elimination order
    int *upos;             // position of each row in fu.cidx, -1 for a row of B
    int *fpart;            // connected part of A[U][U] of each position of fu: each part is
    int *part_end;         // a run of positions, ending at part_end[part]
    int nparts;
    int nb;
    const int *brow;       // the rows of B (original index) in pivoting order
    const int *normals;    // the places in brow of the rows without friction, in the
    int nnormal;           // order they are pivoted in first
} problem;

static int is_friction(const problem *p, int i)
{
    return i >= p->nub && p->findex && p->findex[i] >= 0;
}

static int is_unbounded(const problem *p, int i)
{
    return i < p->nub || (p->lo[i] == -dInfinity && p->hi[i] == dInfinity && !is_friction(p, i));
}

static dReal lower(const problem *p, int j) { return j < p->nub ? -dInfinity : p->lo[j]; }
static dReal upper(const problem *p, int j) { return j < p->nub ? dInfinity : p->hi[j]; }

// Place the entries of row i of A whose columns c have pos[c] >= 0 at y[pos[c]]. Returns the
// smallest place written (m if none); *last receives the largest (-1 if none).
static int scatter_row(const problem *p, int i, const int *pos, dReal *y, int m, int *last)
{
    int first = m, end = -1;
    for (int k = p->A.start[i]; k < p->A.start[i + 1]; k++) {
        int q = pos[p->A.cols[k]];
        if (q < 0) continue;
        y[q] = p->A.vals[k];
        if (q < first) first = q;
        if (q > end) end = q;
    }
    *last = end;
    return first;
}

// ---- eliminating the unbounded rows ----

// The rows of U in interaction order, and the connected part of each (upart).
static int order_unbounded(problem *p, dxArena *arena, int *u, int *upart)
{
    int n = p->n, nu = 0;
    dxArenaMark mark = dxArenaSave(arena);
    int *in = DX_ARENA_ARRAY(arena, int, n);
    for (int i = 0; i < n; i++) {
        in[i] = -1;
        if (is_unbounded(p, i)) in[i] = 0, u[nu++] = i;
    }
    if (nu > DX_LCP_SMALL) {
        p->nparts = dxLcpBfsOrder(arena, &p->pa, u, nu, in, upart);
    } else {   // one part: coarser than needed, but right
        p->nparts = nu > 0;
        for (int k = 0; k < nu; k++) upart[k] = 0;
    }
    dxArenaRestore(arena, mark);
    return nu;
}

// Factor A[U][U] in interaction order; a row that depends on those before it goes to B
// instead. Fills fu, upos, fpart and part_end.
static void factor_unbounded(problem *p, dxArena *arena)
{
    int n = p->n;
    int *u = DX_ARENA_ARRAY(arena, int, n), *upart = DX_ARENA_ARRAY(arena, int, n);
    int nu = order_unbounded(p, arena, u, upart);
    dxLcpFactorInit(&p->fu, arena, nu);
    p->upos = DX_ARENA_ARRAY(arena, int, n);
    p->fpart = DX_ARENA_ARRAY(arena, int, nu);
    p->part_end = DX_ARENA_ARRAY(arena, int, p->nparts);
    for (int i = 0; i < n; i++) p->upos[i] = -1;
    if (nu == 0) return;
    dxArenaMark mark = dxArenaSave(arena);
    dReal *y = DX_ARENA_ARRAY(arena, dReal, nu), *z = DX_ARENA_ARRAY(arena, dReal, nu);
    memset(y, 0, (size_t)nu * sizeof(dReal));
    for (int k = 0; k < nu; k++) {
        int i = u[k], last, f = scatter_row(p, i, p->upos, y, p->fu.m, &last), e;
        dReal pivot = dxLcpBorder(&p->fu, p->diag[i], y, z, f, &e);
        memset(y + f, 0, (size_t)(e - f) * sizeof(dReal));
        if (pivot > DX_LCP_PIVOT_TOL * dFabs(p->diag[i])) {
            p->upos[i] = p->fu.m;
            p->fpart[p->fu.m] = upart[k];
            dxLcpAppend(&p->fu, i, pivot, z, f, e);
        }
    }
    dxArenaRestore(arena, mark);
    for (int c = 0; c < p->nparts; c++) p->part_end[c] = 0;
    for (int k = 0; k < p->fu.m; k++) p->part_end[p->fpart[k]] = k + 1;
}

// Two segments of Q in one part that overlap: rows lo <= hi of Q (places in bidx), whose
// nonzeros meet within [f, e).
typedef struct q_overlap {
    int lo, hi, f, e;
} q_overlap;

// The rows of B in their original order and Q = D^-1/2 L^-1 A[U][B], so that S = A[B][B] -
// Q^T Q. Row j of Q is nonzero in [qf[j], qe[j]), and only within the parts of A[U][U] it
// touches: there its nonzeros lie in a segment. Two rows of S interact through Q only where
// their segments in a part overlap.
typedef struct reduction {
    int *bidx;             // the rows of B, increasing
    int *bplace;           // place of each row in bidx, -1 for a row of U
    dReal *q;
    ptrdiff_t ldq;
    int *qf, *qe;
    int *seg_row, *seg_part, *seg_f, *seg_e;   // segment: row of Q, part, nonzero range
    int *row_seg;          // the segments of row j: row_seg[j] .. row_seg[j + 1]
    int *part_seg;         // the segments in part c, by increasing row: part_seg[part_start[c]
    int *part_start;       // .. part_start[c + 1])
    q_overlap *overlaps;   // where two segments in a part overlap (see s_entries)
    int noverlaps;
} reduction;

// The first `end` rows of f. L is block diagonal by part, so a forward solve of a vector that
// is zero past the part ending at `end` stays zero there: it can stop at `end`.
static dxLcpFactor factor_head(const dxLcpFactor *f, int end)
{
    dxLcpFactor head = *f;
    head.m = end;
    return head;
}

static const dReal *q_row(const reduction *r, int j) { return r->q + j * r->ldq; }

// Rows of Q: y = L^-1 A[U][j] scaled by D^-1/2, the solve within the parts A[U][j] touches.
static void reduce_rows(const problem *p, dxArena *arena, reduction *r, int nb)
{
    const dxLcpFactor *fu = &p->fu;
    int n = p->n, nu = fu->m;
    r->bidx = DX_ARENA_ARRAY(arena, int, nb);
    r->bplace = DX_ARENA_ARRAY(arena, int, n);
    for (int i = 0, k = 0; i < n; i++) {
        r->bplace[i] = -1;
        if (p->upos[i] < 0) r->bplace[i] = k, r->bidx[k++] = i;
    }
    r->ldq = dPAD(nu);
    r->q = DX_ARENA_ARRAY(arena, dReal, (size_t)nb * (size_t)r->ldq);
    r->qf = DX_ARENA_ARRAY(arena, int, nb);
    r->qe = DX_ARENA_ARRAY(arena, int, nb);
    dxArenaMark mark = dxArenaSave(arena);
    dReal *sd = DX_ARENA_ARRAY(arena, dReal, nu);
    for (int k = 0; k < nu; k++) sd[k] = dSqrt(fu->dinv[k]);
    for (int j = 0; j < nb; j++) {
        dReal *qj = r->q + j * r->ldq;
        r->qf[j] = r->qe[j] = 0;
        if (nu == 0) continue;
        memset(qj, 0, (size_t)nu * sizeof(dReal));
        int last, f = scatter_row(p, r->bidx[j], p->upos, qj, nu, &last);
        r->qf[j] = r->qe[j] = f;
        if (last < 0) continue;
        dxLcpFactor head = factor_head(fu, p->part_end[p->fpart[last]]);
        r->qe[j] = dxLcpSolveL(&head, qj, f);
        for (int k = r->qf[j]; k < r->qe[j]; k++) qj[k] *= sd[k];
    }
    dxArenaRestore(arena, mark);
}

// Split each row of Q into its segments, one per part it touches, and list them by part.
static void reduce_segments(const problem *p, dxArena *arena, reduction *r, int nb)
{
    int most = 0;   // parts are runs numbered along fu: a row spans at most this many
    for (int j = 0; j < nb; j++)
        if (r->qe[j] > r->qf[j]) most += p->fpart[r->qe[j] - 1] - p->fpart[r->qf[j]] + 1;
    r->seg_row = DX_ARENA_ARRAY(arena, int, most + 1);
    r->seg_part = DX_ARENA_ARRAY(arena, int, most + 1);
    r->seg_f = DX_ARENA_ARRAY(arena, int, most + 1);
    r->seg_e = DX_ARENA_ARRAY(arena, int, most + 1);
    r->row_seg = DX_ARENA_ARRAY(arena, int, nb + 1);
    int ns = 0;
    for (int j = 0; j < nb; j++) {
        const dReal *qj = q_row(r, j);
        r->row_seg[j] = ns;
        for (int k = r->qf[j]; k < r->qe[j];) {
            int c = p->fpart[k], pe = p->part_end[c] < r->qe[j] ? p->part_end[c] : r->qe[j];
            int f = k, e = pe;
            while (f < pe && qj[f] == 0) f++;
            while (e > f && qj[e - 1] == 0) e--;
            if (e > f) {
                r->seg_row[ns] = j;
                r->seg_part[ns] = c;
                r->seg_f[ns] = f;
                r->seg_e[ns++] = e;
            }
            k = pe;
        }
    }
    r->row_seg[nb] = ns;
    r->part_start = DX_ARENA_ARRAY(arena, int, p->nparts + 1);
    r->part_seg = DX_ARENA_ARRAY(arena, int, ns + 1);
    for (int c = 0; c <= p->nparts; c++) r->part_start[c] = 0;
    for (int t = 0; t < ns; t++) r->part_start[r->seg_part[t] + 1]++;
    for (int c = 0; c < p->nparts; c++) r->part_start[c + 1] += r->part_start[c];
    int *fill = DX_ARENA_ARRAY(arena, int, p->nparts + 1);
    for (int c = 0; c < p->nparts; c++) fill[c] = r->part_start[c];
    for (int t = 0; t < ns; t++) r->part_seg[fill[r->seg_part[t]]++] = t;
}

static int seg_overlap(const reduction *r, int s, int t, int *f, int *e)
{
    *f = r->seg_f[s] > r->seg_f[t] ? r->seg_f[s] : r->seg_f[t];
    *e = r->seg_e[s] < r->seg_e[t] ? r->seg_e[s] : r->seg_e[t];
    return *e > *f;
}

// The most overlaps of segments there can be: every pair of segments in a part, and each
// segment with itself.
static size_t most_overlaps(const problem *p, const reduction *r)
{
    size_t most = 0;
    for (int c = 0; c < p->nparts; c++) {
        size_t count = (size_t)(r->part_start[c + 1] - r->part_start[c]);
        most += count * (count + 1) / 2;
    }
    return most;
}

// The entries (i, j), j <= i, of the pattern of S over B (places in bidx), each once, as
// counted into pb and listed in `lower` (row i's from lower_start[i]): where A[B][B] is
// nonzero or segments of Q overlap. Every overlap of segments goes to r->overlaps, the
// overlaps of one pair of rows by increasing part.
static void s_entries(const problem *p, reduction *r, int nb, int *mark, int *lower,
                      int *lower_start, dxLcpPatternBuilder *pb)
{
    int count = 0;
    r->noverlaps = 0;
    for (int i = 0; i < nb; i++) mark[i] = -1;
    for (int i = 0; i < nb; i++) {
        int bi = r->bidx[i];
        lower_start[i] = count;
        for (int k = p->pa.start[bi]; k < p->pa.start[bi + 1]; k++) {
            int j = r->bplace[p->pa.cols[k]];
            if (j < 0 || j > i || mark[j] == i) continue;
            mark[j] = i;
            lower[count++] = j;
            dxLcpPatternCount(pb, i, j);
        }
        for (int s = r->row_seg[i]; s < r->row_seg[i + 1]; s++) {
            int c = r->seg_part[s], f, e;
            for (int k = r->part_start[c]; k < r->part_start[c + 1]; k++) {
                int t = r->part_seg[k], j = r->seg_row[t];
                if (j > i) break;
                if (!seg_overlap(r, s, t, &f, &e)) continue;
                r->overlaps[r->noverlaps++] = (q_overlap){ j, i, f, e };
                if (mark[j] == i) continue;
                mark[j] = i;
                lower[count++] = j;
                dxLcpPatternCount(pb, i, j);
            }
        }
    }
    lower_start[nb] = count;
}

// The pattern of S over B, and the overlaps of segments of Q in r.
static dxLcpPattern pattern_of_s(const problem *p, reduction *r, dxArena *arena, int nb)
{
    r->overlaps = DX_ARENA_ARRAY(arena, q_overlap, most_overlaps(p, r) + 1);
    r->noverlaps = 0;
    if (nb == p->n) return p->pa;   // nothing eliminated
    dxLcpPatternBuilder pb;
    dxLcpPatternBegin(&pb, arena, nb);
    int *mark = DX_ARENA_ARRAY(arena, int, nb), *lower_start = DX_ARENA_ARRAY(arena, int, nb + 1);
    int *lower = DX_ARENA_ARRAY(arena, int, (size_t)nb * (size_t)(nb + 1) / 2);
    s_entries(p, r, nb, mark, lower, lower_start, &pb);
    dxLcpPatternAllocate(&pb, arena, 0);
    for (int i = 0; i < nb; i++)
        for (int k = lower_start[i]; k < lower_start[i + 1]; k++) dxLcpPatternAdd(&pb, i, lower[k]);
    dxLcpPattern pt = { pb.start, pb.cols };
    return pt;
}

// ---- the pivoted problem ----

// The pivoting orders over B (places in bidx): `all` for every row (interaction order on S),
// `normals` for the rows without friction (the same order).
static void pivot_orders(const problem *p, const reduction *r, dxArena *arena, int nb,
                         const dxLcpPattern *sp, int *all, int *normals, int *nnormal)
{
    dxArenaMark mark = dxArenaSave(arena);
    int *in = DX_ARENA_ARRAY(arena, int, nb);
    int count = 0;
    for (int k = 0; k < nb; k++) {
        all[k] = in[k] = k;
        if (!is_friction(p, r->bidx[k])) normals[count++] = k;
    }
    *nnormal = count;
    if (nb > ORDER_MIN_ROWS) {   // the rows without friction: in the same order
        dxLcpBfsOrder(arena, sp, all, nb, in, NULL);
        count = 0;
        for (int k = 0; k < nb; k++)
            if (!is_friction(p, r->bidx[all[k]])) normals[count++] = all[k];
    }
    dxArenaRestore(arena, mark);
}

// The pattern sp of S over B in pivoting order (order: place in bidx of each place in brow;
// inv: the reverse).
static dxLcpPattern permuted_pattern(dxArena *arena, const dxLcpPattern *sp, int nb,
                                     const int *order, const int *inv)
{
    int *start = DX_ARENA_ARRAY(arena, int, nb + 1);
    int *cols = DX_ARENA_ARRAY(arena, int, sp->start[nb] + 1);
    start[0] = 0;
    for (int k = 0; k < nb; k++) {
        int o = order[k], len = sp->start[o + 1] - sp->start[o];
        for (int e = 0; e < len; e++) cols[start[k] + e] = inv[sp->cols[sp->start[o] + e]];
        start[k + 1] = start[k] + len;
    }
    dxLcpPattern pt = { start, cols };
    return pt;
}

// S = A[B][B] - Q^T Q in pivoting order, from the nonzeros of A and the overlaps of segments
// (r->overlaps); zero elsewhere (the pivoting reads each row over the extent of its pattern:
// one memset of all of S costs less time than finding each row's extent).
static void schur_complement(const problem *p, const reduction *r, dxArena *arena,
                             const int *inv, dxLcpPivot *s)
{
    int nb = p->nb;
    ptrdiff_t ld = s->lda = dPAD(nb);
    dReal *S = DX_ARENA_ARRAY(arena, dReal, (size_t)nb * (size_t)ld);
    memset(S, 0, (size_t)nb * (size_t)ld * sizeof(dReal));
    for (int i = 0; i < nb; i++) {
        int bi = r->bidx[i];
        dReal *si = S + inv[i] * ld;
        for (int k = p->A.start[bi]; k < p->A.start[bi + 1]; k++) {
            int j = r->bplace[p->A.cols[k]];
            if (j >= 0) si[inv[j]] = p->A.vals[k];
        }
    }
    for (int k = 0; k < r->noverlaps; k++) {
        const q_overlap *o = &r->overlaps[k];
        int ia = inv[o->lo], ib = inv[o->hi];
        dReal v = dxLcpDot(q_row(r, o->lo) + o->f, q_row(r, o->hi) + o->f, o->e - o->f);
        S[ia * ld + ib] -= v;
        if (ib != ia) S[ib * ld + ia] -= v;
    }
    s->A = S;
}

// The right-hand side of the pivoted problem, b[B] - Q^T g with g = D^-1/2 L^-1 b[U], the
// scale |b| + sum |q g| of what the elimination subtracted (tolerances), the diagonal of A,
// the bounds and the start values, in pivoting order (order: place in r's bidx).
static void right_hand_side(const problem *p, const reduction *r, dxArena *arena,
                            const int *order, dxLcpPivot *s)
{
    const dxLcpFactor *fu = &p->fu;
    int nu = fu->m, nb = p->nb;
    dReal *b = DX_ARENA_ARRAY(arena, dReal, nb), *base = DX_ARENA_ARRAY(arena, dReal, nb);
    dReal *diag = DX_ARENA_ARRAY(arena, dReal, nb);
    s->x = DX_ARENA_ARRAY(arena, dReal, nb);
    s->w = DX_ARENA_ARRAY(arena, dReal, nb);
    s->lo = DX_ARENA_ARRAY(arena, dReal, nb);
    s->hi = DX_ARENA_ARRAY(arena, dReal, nb);
    dxArenaMark mark = dxArenaSave(arena);
    dReal *g = DX_ARENA_ARRAY(arena, dReal, nu);
    int gf = nu;
    for (int k = 0; k < nu; k++) {
        g[k] = p->b[fu->cidx[k]];
        if (g[k] != 0 && gf == nu) gf = k;
    }
    int ge = dxLcpSolveL(fu, g, gf);
    for (int k = gf; k < ge; k++) g[k] *= dSqrt(fu->dinv[k]);
    for (int k = 0; k < nb; k++) {
        int o = order[k], i = p->brow[k];
        int f = r->qf[o] > gf ? r->qf[o] : gf, e = r->qe[o] < ge ? r->qe[o] : ge;
        dReal size = 0, c = e > f ? dxLcpDotSize(q_row(r, o) + f, g + f, e - f, &size) : 0;
        b[k] = p->b[i] - c;
        base[k] = dFabs(p->b[i]) + size;
        diag[k] = p->diag[i];
        s->lo[k] = lower(p, i);
        s->hi[k] = upper(p, i);
        s->x[k] = is_friction(p, i) ? 0 : clamp_zero(s->lo[k], s->hi[k]);
    }
    dxArenaRestore(arena, mark);
    s->b = b;
    s->base = base;
    s->diag = diag;
}

// The pivoted problem in pivoting order (row k is row brow[k] of A): S, its pattern, its
// right-hand side and bounds.
static void pivoted_problem(problem *p, dxArena *arena, dxLcpPivot *s)
{
    int n = p->n, nb = n - p->fu.m;
    reduction r;
    reduce_rows(p, arena, &r, nb);
    reduce_segments(p, arena, &r, nb);
    dxLcpPattern sp = pattern_of_s(p, &r, arena, nb);
    int *order = DX_ARENA_ARRAY(arena, int, nb), *normals = DX_ARENA_ARRAY(arena, int, nb);
    pivot_orders(p, &r, arena, nb, &sp, order, normals, &p->nnormal);
    p->nb = nb;
    int *brow = DX_ARENA_ARRAY(arena, int, nb);
    int *inv = DX_ARENA_ARRAY(arena, int, nb);   // place in bidx -> place in brow
    for (int k = 0; k < nb; k++) {
        brow[k] = r.bidx[order[k]];
        inv[order[k]] = k;
    }
    for (int k = 0; k < p->nnormal; k++) normals[k] = inv[normals[k]];
    p->brow = brow;
    p->normals = normals;
    s->pa = nb > ORDER_MIN_ROWS ? permuted_pattern(arena, &sp, nb, order, inv) : sp;
    schur_complement(p, &r, arena, inv, s);
    right_hand_side(p, &r, arena, order, s);
}

// A small problem: every row pivoted, in the given order, on A in full (elimination,
// reordering and sparsity cannot gain there; the unbounded rows are driven like the others).
static void small_problem(problem *p, dxArena *arena, dxLcpPivot *s)
{
    int n = p->n;
    size_t ld = (size_t)dPAD(n), full = p->dense ? 0 : (size_t)n * ld;
    dReal *r = dxArenaAlloc(arena, (full + 5 * (size_t)n) * sizeof(dReal) +
                                       2 * (size_t)n * sizeof(int));
    int *rows = (int *)(void *)(r + full + 5 * (size_t)n), *normals = rows + n;
    if (!p->dense) {
        memset(r, 0, full * sizeof(dReal));
        for (int i = 0; i < n; i++)
            for (int k = p->A.start[i]; k < p->A.start[i + 1]; k++)
                r[i * ld + (size_t)p->A.cols[k]] = p->A.vals[k];
    }
    s->A = p->dense ? p->dense : r;
    s->lda = (ptrdiff_t)ld;
    r += full;
    dReal *base = r;
    s->x = r + n;
    s->w = r + 2 * n;
    s->lo = r + 3 * n;
    s->hi = r + 4 * n;
    p->nnormal = 0;
    for (int i = 0; i < n; i++) {
        rows[i] = i;
        base[i] = dFabs(p->b[i]);
        s->lo[i] = lower(p, i);
        s->hi[i] = upper(p, i);
        s->x[i] = is_friction(p, i) ? 0 : clamp_zero(s->lo[i], s->hi[i]);
        if (!is_friction(p, i)) normals[p->nnormal++] = i;
    }
    p->nb = n;
    p->brow = rows;
    p->normals = normals;
    s->pa.start = s->pa.cols = NULL;
    s->b = p->b;
    s->base = base;
    s->diag = p->diag;
}

// x[U] = A[U][U]^-1 (b[U] - A[U][B] x[B]), with x[B] already in place.
static void recover_unbounded(problem *p, dxArena *arena)
{
    const dxLcpFactor *fu = &p->fu;
    int nu = fu->m;
    if (nu == 0) return;
    dxArenaMark mark = dxArenaSave(arena);
    dReal *v = DX_ARENA_ARRAY(arena, dReal, nu);
    int first = nu;
    for (int k = 0; k < nu; k++) {
        int i = fu->cidx[k];
        dReal r = p->b[i];
        for (int e = p->A.start[i]; e < p->A.start[i + 1]; e++) {
            int c = p->A.cols[e];
            if (p->upos[c] < 0) r -= p->A.vals[e] * p->x[c];
        }
        v[k] = r;
        if (r != 0 && first == nu) first = k;
    }
    int e = dxLcpSolveL(fu, v, first);
    for (int k = first; k < e; k++) v[k] *= fu->dinv[k];
    dxLcpSolveLT(fu, v, e);
    for (int k = 0; k < nu; k++) p->x[fu->cidx[k]] = v[k];
    dxArenaRestore(arena, mark);
}

// ---- the driver ----

// x of the pivoted rows into the caller's x.
static void publish(problem *p, const dxLcpPivot *s)
{
    for (int k = 0; k < p->nb; k++) p->x[p->brow[k]] = s->x[k];
}

// Before the friction rows: their bounds from the normal forces, with the unbounded rows
// recovered first if a friction row takes its bound from one of them.
static void set_friction_bounds(problem *p, dxLcpPivot *s, dxArena *arena)
{
    publish(p, s);
    int need_u = 0;
    for (int k = 0; k < p->nb; k++) {
        int i = p->brow[k];
        if (is_friction(p, i) && p->fu.m > 0 && p->upos[p->findex[i]] >= 0) need_u = 1;
    }
    if (need_u) recover_unbounded(p, arena);
    for (int k = 0; k < p->nb; k++) {
        int i = p->brow[k];
        if (!is_friction(p, i)) continue;
        dReal xn = p->x[p->findex[i]];
        dReal h = xn == 0 ? 0 : dFabs(p->hi[i] * xn);   // no 0 * inf
        p->lo[i] = s->lo[k] = -h;
        p->hi[i] = s->hi[k] = h;
    }
}

// Drive the rows rows[0..count) (NULL: 0..count) that are not processed yet, in turn,
// counting on from np processed rows. Returns 0 if a drive gave up.
static int drive_rows(dxLcpPivot *s, const int *rows, int count, int np)
{
    int ok = 1;
    for (int c = 0; c < count; c++) {
        int i = rows ? rows[c] : c;
        if (!dxLcpPivotProcessed(s, i)) ok &= dxLcpPivotDrive(s, i, ++np);
    }
    return ok;
}

// Pivot on the rows of B. First the rows without friction, for the frictionless solution
// that all friction bounds come from, before any friction row moves load between contacts
// (the friction of a sliding body is then mu times its whole normal load). Then every row,
// again from an empty C with x where the first pass left it: adding the friction rows to the
// end of that pass's factor would spread its nonzeros over whole rows, while in one
// interaction order of all rows it stays sparse within its profile. A small problem just
// goes on with the friction rows. Returns 0 if a drive gave up.
static int pivot_all(problem *p, dxLcpPivot *s, dxArena *arena)
{
    int ok = drive_rows(s, p->normals, p->nnormal, 0), np = p->nnormal;
    if (np == p->nb) return ok;
    set_friction_bounds(p, s, arena);
    if (p->nb > ORDER_MIN_ROWS) {
        dxLcpPivotRestart(s);
        np = 0;
    }
    return ok & drive_rows(s, NULL, p->nb, np);
}

// Clamp x to its bounds (a clamped x may have rounded past one), replace anything not finite,
// set w = A x - b, and check the conditions to a loose tolerance: DX_LCP_DEP_TOL * (|b[j]| +
// sum |A[j][k] x[k]|), plus a floor. Returns 0 if something had to be replaced or a
// condition does not hold.
static int finish(problem *p, dReal *tol)
{
    int ok = 1, n = p->n;
    for (int j = 0; j < n; j++) {
        dReal lo = lower(p, j), hi = upper(p, j), v = p->x[j];
        if (v < lo) v = lo;
        if (v > hi) v = hi;
        if (!isfinite(v)) {
            v = clamp_zero(lo, hi);
            ok = 0;
        }
        p->x[j] = v;
    }
    // A row whose own terms are tiny (x and b near 0) still carries the rounding
    // of the whole solve: its tolerance has a floor relative to the largest row.
    dReal largest = 0;
    for (int j = 0; j < n; j++) {
        dReal r = 0, size = 0;
        if (p->dense) {
            for (int k = 0; k < n; k++) {
                dReal t = p->dense[j * dPAD(n) + k] * p->x[k];
                r += t;
                size += dFabs(t);
            }
        } else {
            for (int k = p->A.start[j]; k < p->A.start[j + 1]; k++) {
                dReal t = p->A.vals[k] * p->x[p->A.cols[k]];
                r += t;
                size += dFabs(t);
            }
        }
        p->w[j] = r - p->b[j];
        tol[j] = DX_LCP_DEP_TOL * (size + dFabs(p->b[j]));
        if (tol[j] > largest) largest = tol[j];
    }
    const dReal floor_tol = largest * REAL(1e-3);
    for (int j = 0; j < n; j++) {
        dReal t = tol[j] + floor_tol, w = p->w[j], x = p->x[j];
        int off_lo = x > lower(p, j), off_hi = x < upper(p, j);
        if (lower(p, j) != upper(p, j) && ((w > t && off_lo) || (w < -t && off_hi))) ok = 0;
    }
    return ok;
}

// The problem as set up by the two entry points.
static int solve(problem *p, dxArena *arena)
{
    int n = p->n;
    p->diag = DX_ARENA_ARRAY(arena, dReal, 2 * (size_t)n);   // and the tolerances of finish
    for (int i = 0; i < n; i++) {
        if (p->dense) {
            p->diag[i] = p->dense[i * dPAD(n) + i];
            continue;
        }
        p->diag[i] = 0;
        for (int k = p->A.start[i]; k < p->A.start[i + 1]; k++) {
            if (p->A.cols[k] != i) continue;
            p->diag[i] = p->A.vals[k];
            break;
        }
    }
    int ok = 1;
    p->fu.m = 0;
    if (n > DX_LCP_SMALL) factor_unbounded(p, arena);
    if (p->fu.m < n) {
        dxLcpPivot s;
        if (n <= DX_LCP_SMALL) small_problem(p, arena, &s);
        else pivoted_problem(p, arena, &s);
        dxLcpPivotSetup(&s, arena, p->nb);
        ok = pivot_all(p, &s, arena);
        publish(p, &s);
    }
    recover_unbounded(p, arena);
    return ok & finish(p, p->diag + n);
}

int dxSolveLCPSparse(dxArena *arena, int n, const dxLCPMatrix *A, dReal *x, const dReal *b,
                     dReal *w, int nub, dReal *lo, dReal *hi, const int *findex)
{
    if (n <= 0) return 1;
    dxArenaMark mark = dxArenaSave(arena);
    problem p = { .n = n, .nub = nub < 0 ? 0 : nub > n ? n : nub, .A = *A,
                  .pa = dxLcpPatternOfMatrix(A), .b = b, .x = x, .w = w, .lo = lo, .hi = hi,
                  .findex = findex };
    int ok = solve(&p, arena);
    dxArenaRestore(arena, mark);
    return ok;
}

int dxSolveLCP(dxArena *arena, int n, const dReal *A, dReal *x, const dReal *b, dReal *w,
               int nub, dReal *lo, dReal *hi, const int *findex)
{
    if (n <= 0) return 1;
    dxArenaMark mark = dxArenaSave(arena);
    problem p = { .n = n, .nub = nub < 0 ? 0 : nub > n ? n : nub, .b = b, .x = x, .w = w,
                  .lo = lo, .hi = hi, .findex = findex };
    if (n <= DX_LCP_SMALL) {
        p.dense = A;
    } else {
        p.A = dxLcpSparseOf(arena, A, dPAD(n), n);
        p.pa = dxLcpPatternOfMatrix(&p.A);
    }
    int ok = solve(&p, arena);
    dxArenaRestore(arena, mark);
    return ok;
}
