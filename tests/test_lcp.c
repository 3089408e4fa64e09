// SPDX-License-Identifier: BSD-3-Clause
//
// test_lcp.c -- the mixed LCP solver (libodedyn/solvers/lcp.c): the LCP conditions themselves
// (w = A x - b, bounds, complementarity) on linear systems, 1-D cases, problems with a planted
// solution, brute-force enumeration of active sets, friction, redundant (nearly singular)
// constraints, large dense and banded problems, articulated bodies with contacts as the
// stepper builds them (with redundant joints, and given sparse), and the scratch arena being
// released.

#include "test.h"
#include "arena.h"
#include "lcp.h"

#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define INF dInfinity

// ---- a small deterministic generator (independent of the library's) ----

#include "xorshift.h"

static void rng_seed(uint64_t s) { rng_state = s * 0x9E3779B97F4A7C15u + 1; }

static int rnd_int(int n) { return (int)rnd(0, n); }   // uniform in 0 .. n - 1

// ---- problems ----

typedef struct problem {
    int n, nub, ld;
    dReal *A, *b, *lo, *hi, *x, *w;
    int *findex;      // NULL unless friction is used
    double *xp;       // a planted solution, when there is one
} problem;

static problem problem_make(int n)
{
    problem p = { .n = n, .ld = dPAD(n) };
    size_t nn = (size_t)n * (size_t)p.ld + 1, n1 = (size_t)n + 1;
    p.A = calloc(nn, sizeof(dReal));
    p.b = calloc(n1, sizeof(dReal));
    p.lo = calloc(n1, sizeof(dReal));
    p.hi = calloc(n1, sizeof(dReal));
    p.x = calloc(n1, sizeof(dReal));
    p.w = calloc(n1, sizeof(dReal));
    p.xp = calloc(n1, sizeof(double));
    return p;
}

static void problem_free(problem *p)
{
    free(p->A);
    free(p->b);
    free(p->lo);
    free(p->hi);
    free(p->x);
    free(p->w);
    free(p->xp);
    free(p->findex);
}

static dReal *at(const problem *p, int i, int j) { return p->A + (size_t)i * p->ld + j; }

// Solve with a fresh arena; x and w are filled with garbage first to show they are outputs.
static int solve(problem *p)
{
    dxArena arena;
    dxArenaInit(&arena);
    for (int i = 0; i < p->n; i++) p->x[i] = p->w[i] = (dReal)12345.0;
    int ok = dxSolveLCP(&arena, p->n, p->A, p->x, p->b, p->w, p->nub, p->lo, p->hi, p->findex);
    dxArenaFree(&arena);
    return ok;
}

// A = B B^T / k + shift I with B n x k uniform in [-1, 1]: symmetric positive definite for
// shift > 0, eigenvalues in [shift, shift + about n/3 + ...].
static void make_spd(problem *p, int k, double shift)
{
    int n = p->n;
    double *B = malloc(sizeof(double) * (size_t)n * (size_t)k);
    for (int i = 0; i < n * k; i++) B[i] = rnd(-1, 1);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j <= i; j++) {
            double s = 0;
            for (int c = 0; c < k; c++) s += B[i * k + c] * B[j * k + c];
            s /= k;
            if (i == j) s += shift;
            *at(p, i, j) = *at(p, j, i) = (dReal)s;
        }
    }
    free(B);
}

// Row i of A x - b in double, and in *size the scale |b[i]| + sum |A[i][j] x[j]|.
static double residual(const problem *p, const dReal *x, int i, double *size)
{
    double s = -(double)p->b[i], a = fabs((double)p->b[i]);
    for (int j = 0; j < p->n; j++) {
        double t = (double)*at(p, i, j) * (double)x[j];
        s += t;
        a += fabs(t);
    }
    *size = a;
    return s;
}

// The LCP conditions, with the bounds in p (for friction rows: the ones the solver returned):
// x finite and within its bounds (exactly: the solver clamps), w equal to A x - b up to
// rounding (rel * size), and complementarity: w may exceed tol * (1 + size) only where x is
// at lo, and be below -tol * (1 + size) only where x is at hi (within tol * (1 + |x|)).
static int check_lcp(const problem *p, double tol)
{
    double rel = 64 * TOL(DBL_EPSILON, FLT_EPSILON) * (p->n + 1);
    for (int i = 0; i < p->n; i++) {
        double x = p->x[i], w = p->w[i], size, r = residual(p, p->x, i, &size);
        if (!isfinite(x) || !isfinite(w)) {
            test_fail(__FILE__, __LINE__, "row %d: x = %g, w = %g", i, x, w);
            return 1;
        }
        if (fabs(w - r) > rel * (1 + size)) {
            test_fail(__FILE__, __LINE__, "row %d: w = %.10g but A x - b = %.10g", i, w, r);
            return 1;
        }
        double lo = i < p->nub ? -INF : p->lo[i], hi = i < p->nub ? INF : p->hi[i];
        if (x < lo || x > hi) {
            test_fail(__FILE__, __LINE__, "row %d: x = %.10g outside [%g, %g]", i, x, lo, hi);
            return 1;
        }
        if (lo == hi) continue;
        double wt = tol * (1 + size), xt = tol * (1 + fabs(x));
        if ((w > wt && x > lo + xt) || (w < -wt && x < hi - xt)) {
            test_fail(__FILE__, __LINE__, "row %d: x = %.10g in [%g, %g] with w = %.10g", i, x,
                      lo, hi, w);
            return 1;
        }
    }
    return 0;
}

static double max_x_error(const problem *p)
{
    double e = 0;
    for (int i = 0; i < p->n; i++) {
        double d = fabs((double)p->x[i] - p->xp[i]) / (1 + fabs(p->xp[i]));
        if (!(d <= e)) e = d;   // NaN wins
    }
    return e;
}

// Choose x and w satisfying the conditions, then set b = A x - w. Categories: unbounded rows
// (w = 0), at lo with w > 0, at hi with w < 0, interior, degenerate (at a bound with w = 0),
// fixed (lo == hi, any w). Bounds are random, sometimes infinite, sometimes not containing 0.
static void plant(problem *p, int nub)
{
    int n = p->n;
    double *w = malloc(sizeof(double) * (size_t)n);
    p->nub = nub;
    for (int i = 0; i < n; i++) {
        double lo = -INF, hi = INF, x, wi = 0;
        if (i < nub) {
            x = rnd(-2, 2);
        } else {
            lo = rnd(-2, -0.1);
            hi = rnd(0.1, 2);
            double shift = rnd(0, 1);
            if (shift < 0.1) hi = lo + rnd(0.1, 1);    // both below 0
            else if (shift < 0.2) lo = hi - rnd(0.1, 1);  // both above 0
            if (rnd(0, 1) < 0.1) lo = -INF;
            if (rnd(0, 1) < 0.1) hi = INF;
            lo = (dReal)lo;
            hi = (dReal)hi;
            int c = rnd_int(6);
            if (c == 0 && lo == -INF) c = 2;
            if (c == 1 && hi == INF) c = 2;
            if (c == 0) x = lo, wi = rnd(0.1, 1);
            else if (c == 1) x = hi, wi = -rnd(0.1, 1);
            else if (c == 3) x = lo != -INF ? lo : hi != INF ? hi : 0;
            else if (c == 4) lo = hi = x = (dReal)rnd(-1, 1), wi = rnd(-1, 1);
            else if (lo == -INF && hi == INF) x = rnd(-1, 1);
            else if (lo == -INF) x = hi - rnd(0.1, 1);
            else if (hi == INF) x = lo + rnd(0.1, 1);
            else x = lo + (hi - lo) * rnd(0.1, 0.9);
        }
        p->lo[i] = (dReal)lo;
        p->hi[i] = (dReal)hi;
        p->xp[i] = (dReal)x;
        w[i] = wi;
    }
    for (int i = 0; i < n; i++) {
        double s = -w[i];
        for (int j = 0; j < n; j++) s += (double)*at(p, i, j) * p->xp[j];
        p->b[i] = (dReal)s;
    }
    free(w);
}

// Dense Gaussian elimination with partial pivoting (double): solve M x = r, M m x m with
// row skip m, both destroyed. Returns 0 if M is singular.
static int gauss_solve(double *M, double *r, int m)
{
    for (int c = 0; c < m; c++) {
        int piv = c;
        for (int i = c + 1; i < m; i++)
            if (fabs(M[i * m + c]) > fabs(M[piv * m + c])) piv = i;
        if (fabs(M[piv * m + c]) < 1e-300) return 0;
        for (int j = 0; j < m; j++) {
            double t = M[c * m + j];
            M[c * m + j] = M[piv * m + j];
            M[piv * m + j] = t;
        }
        double t = r[c];
        r[c] = r[piv];
        r[piv] = t;
        for (int i = c + 1; i < m; i++) {
            double f = M[i * m + c] / M[c * m + c];
            for (int j = c; j < m; j++) M[i * m + j] -= f * M[c * m + j];
            r[i] -= f * r[c];
        }
    }
    for (int c = m - 1; c >= 0; c--) {
        for (int j = c + 1; j < m; j++) r[c] -= M[c * m + j] * r[j];
        r[c] /= M[c * m + c];
    }
    return 1;
}

static double elapsed_ms(struct timespec t0)
{
    struct timespec t1;
    timespec_get(&t1, TIME_UTC);
    return (double)(t1.tv_sec - t0.tv_sec) * 1e3 + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-6;
}

// ---- tests ----

static int test_all_unbounded_equals_linear_solve(void)
{
    rng_seed(1);
    for (int n = 1; n <= 20; n += 3) {
        problem p = problem_make(n);
        make_spd(&p, n, 0.5);
        double *M = malloc(sizeof(double) * (size_t)(n * n)), *r = malloc(sizeof(double) * n);
        for (int i = 0; i < n; i++) {
            p.b[i] = (dReal)rnd(-3, 3);
            r[i] = p.b[i];
            for (int j = 0; j < n; j++) M[i * n + j] = *at(&p, i, j);
        }
        p.nub = n;
        int ok = solve(&p);
        int solved = gauss_solve(M, r, n);
        // cond(A) <= about (n/3 + 1) / 0.5 < 20: the error is a few eps times that
        // (measured: 2e-15 and 1.1e-6).
        double err = 0;
        for (int i = 0; i < n; i++) err = fmax(err, fabs((double)p.x[i] - r[i]));
        free(M);
        free(r);
        CHECK(ok == 1);
        CHECK(solved);
        CHECK_NEAR(err, 0, TOL(1e-12, 5e-5));
        CHECK(check_lcp(&p, TOL(1e-12, 1e-5)) == 0);
        problem_free(&p);
    }
    return 0;
}

static int test_one_dimensional_bounds_from_each_side(void)
{
    // A = 2, lo = -1, hi = 1: the unconstrained answer is b / 2.
    static const struct { double b, x, w; } cases[] = {
        { 4, 1, -2 },       // pushed past hi: x = hi, w = 2 - 4 < 0
        { -4, -1, 2 },      // pushed past lo: x = lo, w = -2 + 4 > 0
        { 1, 0.5, 0 },      // interior
        { 2, 1, 0 },        // exactly at hi: degenerate, w = 0
        { 0, 0, 0 },
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        problem p = problem_make(1);
        p.A[0] = 2;
        p.b[0] = (dReal)cases[c].b;
        p.lo[0] = -1;
        p.hi[0] = 1;
        CHECK(solve(&p) == 1);
        CHECK(p.x[0] == (dReal)cases[c].x);   // exact: bounds are set exactly, 1/2 is exact
        CHECK(p.w[0] == (dReal)cases[c].w);
        problem_free(&p);
    }
    // One-sided and shifted bounds: lo = 0, hi = inf (a contact); [1, 3] (0 outside).
    problem p = problem_make(1);
    p.A[0] = 2;
    p.b[0] = -1;
    p.lo[0] = 0;
    p.hi[0] = INF;
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == 0 && p.w[0] == 1);
    p.b[0] = 3;
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == (dReal)1.5 && p.w[0] == 0);
    p.lo[0] = 1;
    p.hi[0] = 3;
    p.b[0] = 0;
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == 1 && p.w[0] == 2);
    p.b[0] = 10;
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == 3 && p.w[0] == -4);
    p.lo[0] = p.hi[0] = (dReal)0.25;   // fixed: x = 0.25 whatever w
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == (dReal)0.25 && p.w[0] == (dReal)-9.5);
    problem_free(&p);
    return 0;
}

static int test_planted_solutions_are_found(void)
{
    rng_seed(2);
    for (int trial = 0; trial < 400; trial++) {
        int n = 1 + rnd_int(40);
        problem p = problem_make(n);
        make_spd(&p, n, rnd(0, 1) < 0.5 ? 0.05 : 0.5);
        plant(&p, rnd(0, 1) < 0.3 ? rnd_int(n / 2 + 1) : 0);
        int ok = solve(&p);
        // A positive definite: the solution is unique. cond(A) <= (n/3 + 2) / 0.05 < 300, so
        // x is accurate to a few hundred eps (measured: 2e-15 and 6e-7 relative).
        double err = max_x_error(&p);
        if (!(ok == 1 && err <= TOL(1e-12, 5e-5)))
            printf("# trial %d n %d: ok %d, x error %g\n", trial, n, ok, err);
        CHECK(ok == 1);
        CHECK(err <= TOL(1e-12, 5e-5));
        CHECK(check_lcp(&p, TOL(1e-12, 1e-5)) == 0);   // measured 3e-16, 2e-7
        problem_free(&p);
    }
    return 0;
}

// The solution of a small problem by trying every assignment of each row to lo / hi / free:
// solve the free rows with the others at their bounds and keep the first assignment meeting
// every condition (with A positive definite there is exactly one solution).
static int brute_force(const problem *p, double *xs)
{
    int n = p->n, total = 1;
    for (int i = 0; i < n; i++) total *= 3;
    double M[36], r[6];
    for (int code = 0; code < total; code++) {
        int st[6], c = code, fr[6], m = 0, valid = 1;
        for (int i = 0; i < n; i++, c /= 3) {
            st[i] = i < p->nub ? 2 : c % 3;   // 0: lo, 1: hi, 2: free
            if (i < p->nub && c % 3 != 2) valid = 0;
            double bound = st[i] == 0 ? p->lo[i] : p->hi[i];
            if (st[i] != 2 && !isfinite(bound)) valid = 0;
            if (st[i] != 2) xs[i] = bound;
            else fr[m++] = i;
        }
        if (!valid) continue;
        for (int a = 0; a < m; a++) {
            r[a] = p->b[fr[a]];
            for (int j = 0; j < n; j++)
                if (st[j] != 2) r[a] -= (double)*at(p, fr[a], j) * xs[j];
            for (int q = 0; q < m; q++) M[a * m + q] = *at(p, fr[a], fr[q]);
        }
        if (!gauss_solve(M, r, m)) continue;
        for (int a = 0; a < m; a++) xs[fr[a]] = r[a];
        for (int i = 0; i < n && valid; i++) {
            double w = -(double)p->b[i];
            for (int j = 0; j < n; j++) w += (double)*at(p, i, j) * xs[j];
            double lo = i < p->nub ? -INF : p->lo[i], hi = i < p->nub ? INF : p->hi[i];
            if (st[i] == 2) valid = xs[i] >= lo - 1e-9 && xs[i] <= hi + 1e-9;
            else if (lo != hi) valid = st[i] == 0 ? w >= -1e-9 : w <= 1e-9;
        }
        if (valid) return 1;
    }
    return 0;
}

static int test_agrees_with_brute_force_enumeration(void)
{
    rng_seed(3);
    for (int trial = 0; trial < 600; trial++) {
        int n = 1 + rnd_int(6);
        problem p = problem_make(n);
        make_spd(&p, 1 + rnd_int(n), 0.1);   // low rank + 0.1 I: strongly coupled rows
        p.nub = rnd(0, 1) < 0.3 ? rnd_int(n + 1) : 0;
        for (int i = 0; i < n; i++) {
            p.b[i] = (dReal)rnd(-2, 2);
            p.lo[i] = rnd(0, 1) < 0.15 ? -INF : (dReal)rnd(-1.5, 0.2);
            p.hi[i] = rnd(0, 1) < 0.15 ? INF : (dReal)rnd(-0.2, 1.5);
            if (p.hi[i] < p.lo[i]) p.hi[i] = p.lo[i];
        }
        double xs[6];
        CHECK(brute_force(&p, xs));
        int ok = solve(&p);
        CHECK(ok == 1);
        // cond(A) <= (6 + 0.1) / 0.1 = 61: errors of a few hundred eps at most (measured:
        // 1.4e-14, and 7e-6 where A and b are rounded to float but xs is solved in double).
        for (int i = 0; i < n; i++) CHECK_NEAR(p.x[i], xs[i], TOL(1e-12, 2e-4));
        CHECK(check_lcp(&p, TOL(1e-12, 1e-5)) == 0);
        problem_free(&p);
    }
    return 0;
}

// One contact on a particle of mass 2: A = I / 2 over (normal, tangent 1, tangent 2), so the
// rows only interact through the friction bounds, and the answer is known exactly.
static int friction_particle(problem *p, double bn, double bt1, double bt2, double mu)
{
    *p = problem_make(3);
    p->findex = malloc(3 * sizeof(int));
    static const int fi[3] = { -1, 0, 0 };
    memcpy(p->findex, fi, sizeof fi);
    for (int i = 0; i < 3; i++) *at(p, i, i) = (dReal)0.5;
    p->b[0] = (dReal)bn;
    p->b[1] = (dReal)bt1;
    p->b[2] = (dReal)bt2;
    p->lo[0] = 0;
    p->hi[0] = INF;
    p->lo[1] = p->lo[2] = (dReal)-mu;
    p->hi[1] = p->hi[2] = (dReal)mu;
    return solve(p);
}

static int test_friction_sticks_below_and_slides_above_mu_normal(void)
{
    problem p;
    // Pressed: x_n = 2 / 0.5 = 4, friction bound mu x_n = 2. Tangent 1 asks for 0.6 (sticks,
    // w = 0); tangent 2 asks for -6 and saturates at -2, where w = 0.5 * -2 + 3 = 2 >= 0.
    CHECK(friction_particle(&p, 2, 0.3, -3, 0.5) == 1);
    CHECK(p.x[0] == 4 && p.w[0] == 0);
    CHECK(p.lo[1] == -2 && p.hi[1] == 2 && p.lo[2] == -2 && p.hi[2] == 2);
    CHECK(p.x[1] == (dReal)0.6 && p.w[1] == 0);
    CHECK(p.x[2] == -2 && p.w[2] == 2);
    CHECK(check_lcp(&p, 0) == 0);
    problem_free(&p);
    // Pushed the other way past the bound: saturates at +2 with w = 1 - 5 < 0.
    CHECK(friction_particle(&p, 2, 5, 0, 0.5) == 1);
    CHECK(p.x[1] == 2 && p.w[1] == -4);
    CHECK(p.x[2] == 0 && p.w[2] == 0);
    problem_free(&p);
    // Separating (b_n < 0): no normal force, so no friction: x_t = 0 and w_t = -b_t.
    CHECK(friction_particle(&p, -1, 0.3, -3, 0.5) == 1);
    CHECK(p.x[0] == 0 && p.w[0] == 1);
    CHECK(p.lo[1] == 0 && p.hi[1] == 0);
    CHECK(p.x[1] == 0 && p.w[1] == (dReal)-0.3);
    CHECK(p.x[2] == 0 && p.w[2] == 3);
    problem_free(&p);
    // mu = infinity: friction never saturates (and 0 * inf never appears as a NaN bound).
    CHECK(friction_particle(&p, 2, 0.3, -300, INF) == 1);
    CHECK(p.hi[1] == INF && p.x[2] == -600 && p.w[2] == 0);
    problem_free(&p);
    CHECK(friction_particle(&p, -1, 0.3, -300, INF) == 1);
    CHECK(p.hi[1] == 0 && p.x[2] == 0);
    problem_free(&p);
    return 0;
}

static int test_friction_row_before_its_normal_is_processed_after_it(void)
{
    // Rows (tangent, normal): the tangent row comes first but must use the solved normal.
    problem p = problem_make(2);
    p.findex = malloc(2 * sizeof(int));
    p.findex[0] = 1;
    p.findex[1] = -1;
    *at(&p, 0, 0) = *at(&p, 1, 1) = 1;
    p.b[0] = 5;
    p.b[1] = 3;
    p.lo[0] = (dReal)-0.5;
    p.hi[0] = (dReal)0.5;
    p.lo[1] = 0;
    p.hi[1] = INF;
    CHECK(solve(&p) == 1);
    CHECK(p.x[1] == 3);
    CHECK(p.hi[0] == (dReal)1.5 && p.lo[0] == (dReal)-1.5);
    CHECK(p.x[0] == (dReal)1.5 && p.w[0] == (dReal)-3.5);
    problem_free(&p);
    return 0;
}

// A box (mass 1, half-size 0.5) on the plane z = 0 with contacts at its bottom corners, each
// contact three rows (normal z, tangents x and y) with findex -> normal, as the stepper builds
// them: A = J M^-1 J^T + cfm I, b = -J v0 so that w = J v_after is the velocity along each
// row after the impulse x. `copies` repeats each corner (redundant contacts).
#define BOX_ROWS_MAX 48

static void box_on_plane(problem *p, int copies, double cfm, double mu, const double v0[6])
{
    static const double corner[4][2] = { { 1, 1 }, { 1, -1 }, { -1, 1 }, { -1, -1 } };
    int nc = 4 * copies, n = 3 * nc;
    double J[BOX_ROWS_MAX][6];
    double inv_i = 1 / (1.0 / 6.0);   // solid unit cube of mass 1: I = m (2 h)^2 / 6 = 1/6
    *p = problem_make(n);
    p->findex = malloc(sizeof(int) * (size_t)n);
    for (int c = 0; c < nc; c++) {
        double r[3] = { 0.5 * corner[c % 4][0], 0.5 * corner[c % 4][1], -0.5 };
        for (int k = 0; k < 3; k++) {
            double d[3] = { k == 1, k == 2, k == 0 };   // normal z, then x and y
            double *row = J[3 * c + k];
            row[0] = d[0];
            row[1] = d[1];
            row[2] = d[2];
            row[3] = r[1] * d[2] - r[2] * d[1];   // r x d
            row[4] = r[2] * d[0] - r[0] * d[2];
            row[5] = r[0] * d[1] - r[1] * d[0];
            int i = 3 * c + k;
            p->findex[i] = k == 0 ? -1 : 3 * c;
            p->lo[i] = k == 0 ? 0 : (dReal)-mu;
            p->hi[i] = k == 0 ? INF : (dReal)mu;
        }
    }
    for (int i = 0; i < n; i++) {
        double bi = 0;
        for (int k = 0; k < 6; k++) bi -= J[i][k] * v0[k];
        p->b[i] = (dReal)bi;
        for (int j = 0; j < n; j++) {
            double a = i == j ? cfm : 0;
            for (int k = 0; k < 6; k++) a += J[i][k] * J[j][k] * (k < 3 ? 1 : inv_i);
            *at(p, i, j) = (dReal)a;
        }
    }
}

// The box's velocity after the impulses x: v0 + M^-1 J^T x; vz must come out 0 when the box
// rests, which needs sum of normal impulses = -vz0 (unit mass).
static double sum_normal(const problem *p)
{
    double s = 0;
    for (int i = 0; i < p->n; i += 3) s += p->x[i];
    return s;
}

static int test_friction_on_a_box_sliding_and_sticking(void)
{
    // Falling at 0.1 and sliding at 1 along x, mu = 0.5: the box cannot stop in one step
    // (needs 1 > 0.5 * 0.1), so every tangent-x row sits at its lower bound -mu x_n. (Four
    // normal rows for three degrees of freedom: how the load is shared is not unique, and in
    // single precision, where the CFM vanishes, one corner may carry none.)
    const double sliding[6] = { 1, 0, -0.1, 0, 0, 0 };
    problem p;
    box_on_plane(&p, 1, 1e-9, 0.5, sliding);
    CHECK(solve(&p) == 1);
    CHECK(check_lcp(&p, TOL(1e-12, 1e-6)) == 0);   // measured 2e-17, 5e-9
    CHECK_NEAR(sum_normal(&p), 0.1, TOL(1e-9, 1e-6));   // cfm 1e-9 shifts it by ~3e-11
    double fx = 0;
    for (int c = 0; c < 4; c++) {
        CHECK(p.hi[3 * c + 1] == -p.lo[3 * c + 1]);
        CHECK(p.x[3 * c + 1] == p.lo[3 * c + 1]);
        CHECK(p.w[3 * c + 1] > 0);   // still sliding forward
        fx += p.x[3 * c + 1];
    }
    CHECK(fx < -0.01);   // friction does act
    problem_free(&p);
    // Sliding at 0.01 only: friction can stop it (0.01 < 0.5 * 0.1); all tangential
    // velocities come out 0 and the tangent-x impulses add up to -0.01.
    const double slow[6] = { 0.01, 0, -0.1, 0, 0, 0 };
    box_on_plane(&p, 1, 1e-9, 0.5, slow);
    CHECK(solve(&p) == 1);
    CHECK(check_lcp(&p, TOL(1e-12, 1e-6)) == 0);
    fx = 0;
    for (int c = 0; c < 4; c++) {
        fx += p.x[3 * c + 1];
        CHECK_NEAR(p.w[3 * c + 1], 0, TOL(1e-12, 1e-6));   // measured 1e-17, 7e-9
        CHECK_NEAR(p.w[3 * c + 2], 0, TOL(1e-12, 1e-6));
    }
    CHECK_NEAR(fx, -0.01, TOL(1e-9, 1e-6));   // cfm: 5e-12
    CHECK_NEAR(sum_normal(&p), 0.1, TOL(1e-9, 1e-6));
    problem_free(&p);
    return 0;
}

static int test_redundant_contacts_with_tiny_cfm(void)
{
    // Each corner once, twice or three times (12 to 36 rows, rank 6): with CFM 1e-10 A is
    // barely positive definite in double and singular to rounding in single precision. How
    // the load is shared is not unique, but the velocity after the impulses is. Without
    // friction: the box falls at 0.1 and spins at 0.5 about x, so the corners at y = -0.5
    // approach at -0.35 and the others separate; an impulse P shared by those two corners
    // (I = 1/6) changes their normal velocity by 2.5 P, so P = 0.14 exactly. With friction
    // the answer also depends on when each friction bound is taken: only the conditions are
    // checked (violations measured: 5e-17 in double, 2e-8 in single precision).
    const double falling[6] = { 0.3, -0.2, -0.1, 0.5, 0, 0.2 };
    for (int copies = 1; copies <= 3; copies++) {
        for (int friction = 0; friction < 2; friction++) {
            problem p;
            box_on_plane(&p, copies, 1e-10, friction ? 0.7 : 0, falling);
            CHECK(solve(&p) == 1);
            CHECK(check_lcp(&p, TOL(1e-12, 1e-6)) == 0);
            if (!friction) CHECK_NEAR(sum_normal(&p), 0.14, TOL(1e-9, 1e-6));
            problem_free(&p);
        }
    }
    return 0;
}

// nc contacts among nb free bodies (unit mass, inertia 0.2 I) and the static world, each
// contact three rows (normal, two tangents; findex -> normal) at random points and normals:
// A = J M^-1 J^T + cfm I, b = -J v0 for a random velocity v0. Up to 8 contacts per body
// make most systems redundant (more rows than degrees of freedom); mu is random, sometimes
// 0 or infinite.
static void random_contacts(problem *p, int nb, int nc, double cfm)
{
    int n = 3 * nc, dof = 6 * nb;
    double *J = calloc((size_t)n * (size_t)dof, sizeof(double)), v0[6 * 8];
    for (int k = 0; k < dof; k++) v0[k] = rnd(-1, 1);
    *p = problem_make(n);
    p->findex = malloc(sizeof(int) * (size_t)n);
    for (int c = 0; c < nc; c++) {
        int body[2] = { rnd_int(nb), rnd(0, 1) < 0.3 ? -1 : rnd_int(nb) };
        if (body[1] == body[0]) body[1] = -1;   // -1: the world
        double d[3][3], r[2][3];
        for (int k = 0; k < 3; k++) {
            d[0][k] = rnd(-1, 1);
            r[0][k] = rnd(-0.5, 0.5);
            r[1][k] = rnd(-0.5, 0.5);
        }
        double len = sqrt(d[0][0] * d[0][0] + d[0][1] * d[0][1] + d[0][2] * d[0][2]);
        for (int k = 0; k < 3; k++) d[0][k] /= len;
        // tangents: any unit vector orthogonal to the normal, and normal x that
        int a = fabs(d[0][0]) < 0.6 ? 0 : 1;
        double e[3] = { a == 0, a == 1, 0 }, dn = d[0][a];
        for (int k = 0; k < 3; k++) d[1][k] = e[k] - dn * d[0][k];
        len = sqrt(d[1][0] * d[1][0] + d[1][1] * d[1][1] + d[1][2] * d[1][2]);
        for (int k = 0; k < 3; k++) d[1][k] /= len;
        for (int k = 0; k < 3; k++)
            d[2][k] = d[0][(k + 1) % 3] * d[1][(k + 2) % 3] - d[0][(k + 2) % 3] * d[1][(k + 1) % 3];
        double mu = rnd(0, 1) < 0.2 ? 0 : rnd(0, 1) < 0.1 ? INF : rnd(0.1, 1.5);
        for (int k = 0; k < 3; k++) {
            double *row = J + (size_t)(3 * c + k) * (size_t)dof;
            for (int side = 0; side < 2; side++) {
                if (body[side] < 0) continue;
                double *bj = row + 6 * body[side], sg = side ? -1 : 1;
                const double *rr = r[side], *dd = d[k];
                for (int q = 0; q < 3; q++) {
                    bj[q] += sg * dd[q];
                    bj[3 + q] += sg * (rr[(q + 1) % 3] * dd[(q + 2) % 3] -
                                       rr[(q + 2) % 3] * dd[(q + 1) % 3]);
                }
            }
            int i = 3 * c + k;
            p->findex[i] = k == 0 ? -1 : 3 * c;
            p->lo[i] = k == 0 ? 0 : (dReal)-mu;
            p->hi[i] = k == 0 ? INF : (dReal)mu;
        }
    }
    for (int i = 0; i < n; i++) {
        const double *ji = J + (size_t)i * (size_t)dof;
        double bi = 0;
        for (int k = 0; k < dof; k++) bi -= ji[k] * v0[k];
        p->b[i] = (dReal)bi;
        for (int j = 0; j <= i; j++) {
            const double *jj = J + (size_t)j * (size_t)dof;
            double s = i == j ? cfm : 0;
            for (int k = 0; k < dof; k++) s += ji[k] * jj[k] * (k % 6 < 3 ? 1 : 5);
            *at(p, i, j) = *at(p, j, i) = (dReal)s;
        }
    }
    free(J);
}

static int test_random_contact_systems(void)
{
    // Violations measured over these systems: 3e-12 in double, 5e-5 in single precision
    // (where redundant contacts are singular to rounding).
    rng_seed(8);
    for (int trial = 0; trial < 400; trial++) {
        int nb = 1 + rnd_int(8), nc = 1 + rnd_int(8 * nb);
        problem p;
        random_contacts(&p, nb, nc, trial % 3 == 0 ? 0 : trial % 3 == 1 ? 1e-10 : 1e-5);
        int ok = solve(&p);
        if (!ok) printf("# trial %d (%d bodies, %d contacts) gave up\n", trial, nb, nc);
        CHECK(ok == 1);
        CHECK(check_lcp(&p, TOL(1e-10, 2e-3)) == 0);
        for (int i = 0; i < p.n; i++) {
            if (p.findex[i] < 0) CHECK(p.lo[i] == 0 && p.hi[i] == INF);   // not touched
            else CHECK(p.hi[i] >= 0 && p.lo[i] == -p.hi[i]);
        }
        problem_free(&p);
    }
    return 0;
}

static int test_coincident_joints_share_the_load(void)
{
    // Two identical 3-row joints on a unit-mass particle (6 unbounded rows, A = [[I, I], [I,
    // I]] + cfm I) must together stop the velocity v0: x_a + x_b = -v0 and w = 0.
    static const double cfms[] = { 1e-10, 0 };
    for (int k = 0; k < 2; k++) {
        problem p = problem_make(6);
        for (int i = 0; i < 6; i++) {
            for (int j = 0; j < 6; j++)
                *at(&p, i, j) = (dReal)((i % 3 == j % 3) + (i == j) * cfms[k]);
            p.b[i] = (dReal)(-(1.0 + i % 3));   // v0 = (1, 2, 3)
        }
        p.nub = 6;
        CHECK(solve(&p) == 1);
        for (int i = 0; i < 3; i++) {
            // The CFM changes the sum by a relative 1e-10 (x_a = x_b = -v0 / (2 + cfm)).
            CHECK_NEAR(p.x[i] + p.x[i + 3], -(1.0 + i), TOL(1e-9, 1e-5));
            CHECK_NEAR(p.w[i], 0, TOL(1e-12, 1e-6));
            CHECK_NEAR(p.w[i + 3], 0, TOL(1e-12, 1e-6));
        }
        problem_free(&p);
    }
    return 0;
}

static int test_redundant_bounded_rows_redistribute(void)
{
    // Two identical contact rows (A = [[1, 1], [1, 1]], no CFM) with b = (1, 2): after the
    // first row takes x = 1, the second can only get w = 0 by taking the whole load from it.
    problem p = problem_make(2);
    for (int i = 0; i < 4; i++) p.A[(i / 2) * p.ld + i % 2] = 1;
    p.b[0] = 1;
    p.b[1] = 2;
    p.lo[0] = p.lo[1] = 0;
    p.hi[0] = p.hi[1] = INF;
    CHECK(solve(&p) == 1);
    CHECK(p.x[0] == 0 && p.w[0] == 1);
    CHECK(p.x[1] == 2 && p.w[1] == 0);
    problem_free(&p);
    return 0;
}

static int test_inconsistent_singular_system_gives_up_finite(void)
{
    // Two identical unbounded rows asking for different values: no solution. It must say so
    // and still return finite x.
    problem p = problem_make(2);
    for (int i = 0; i < 4; i++) p.A[(i / 2) * p.ld + i % 2] = 1;
    p.b[0] = 1;
    p.b[1] = 2;
    p.nub = 2;
    CHECK(solve(&p) == 0);
    CHECK(isfinite(p.x[0]) && isfinite(p.x[1]));
    problem_free(&p);
    // The same as free bounded rows (lo = -inf, hi = inf): x could move without bound.
    p = problem_make(2);
    for (int i = 0; i < 4; i++) p.A[(i / 2) * p.ld + i % 2] = 1;
    p.b[0] = 1;
    p.b[1] = 2;
    p.lo[0] = p.lo[1] = -INF;
    p.hi[0] = p.hi[1] = INF;
    CHECK(solve(&p) == 0);
    CHECK(isfinite(p.x[0]) && isfinite(p.x[1]));
    problem_free(&p);
    return 0;
}

// A = B B^T / k + cfm I with B n x k: positive semi-definite for cfm = 0, of rank <= k. With
// `duplicates`, about that fraction of the rows of B copy (a multiple of) an earlier row:
// exactly redundant constraints, as several contacts at one point or coincident joints.
static void make_redundant(problem *p, int k, double cfm, double duplicates)
{
    int n = p->n;
    double *B = malloc(sizeof(double) * (size_t)n * (size_t)k);
    for (int i = 0; i < n; i++) {
        int src = i > 0 && rnd(0, 1) < duplicates ? rnd_int(i) : -1;
        double scale = rnd(0, 1) < 0.5 ? 1 : rnd(-2, 2);
        for (int c = 0; c < k; c++)
            B[i * k + c] = src >= 0 ? scale * B[src * k + c] : rnd(-1, 1);
    }
    for (int i = 0; i < n; i++) {
        for (int j = 0; j <= i; j++) {
            double s = 0;
            for (int c = 0; c < k; c++) s += B[i * k + c] * B[j * k + c];
            s = s / k + (i == j ? cfm : 0);
            *at(p, i, j) = *at(p, j, i) = (dReal)s;
        }
    }
    free(B);
}

static int test_rank_deficient_planted_problems(void)
{
    // Singular A (CFM 0) or nearly so (CFM 1e-10, below rounding in single precision), low
    // rank or with duplicated rows. A planted solution makes the problem solvable; x is not
    // unique, so the conditions are checked, to a tolerance loose enough for the error
    // amplification of the ill-conditioned pivots (measured: 3e-13 and 2e-5).
    rng_seed(4);
    for (int trial = 0; trial < 600; trial++) {
        int n = 2 + rnd_int(40), k = 1 + rnd_int(trial % 3 ? n : n / 3 + 1);
        problem p = problem_make(n);
        make_redundant(&p, k, trial % 2 ? 1e-10 : 0, trial % 3 ? 0.4 : 0);
        plant(&p, rnd(0, 1) < 0.3 ? rnd_int(n / 2 + 1) : 0);
        int ok = solve(&p);
        if (!ok) printf("# trial %d (n %d, k %d) gave up\n", trial, n, k);
        CHECK(ok == 1);
        CHECK(check_lcp(&p, TOL(1e-10, 2e-3)) == 0);
        problem_free(&p);
    }
    return 0;
}

static int test_large_dense_planted_n300(void)
{
    rng_seed(5);
    problem p = problem_make(300);
    make_spd(&p, 300, 0.2);
    plant(&p, 30);
    size_t bytes = sizeof(dReal) * (size_t)p.n * (size_t)p.ld;
    dReal *A0 = malloc(bytes), *b0 = malloc(sizeof(dReal) * 300);
    memcpy(A0, p.A, bytes);
    memcpy(b0, p.b, sizeof(dReal) * 300);
    struct timespec t0;
    timespec_get(&t0, TIME_UTC);
    int ok = solve(&p);
    printf("# n = 300 dense: %.1f ms\n", elapsed_ms(t0));
    int unchanged = !memcmp(A0, p.A, bytes) && !memcmp(b0, p.b, sizeof(dReal) * 300);
    free(A0);
    free(b0);
    CHECK(unchanged);   // A and b are only read
    CHECK(ok == 1);
    // cond(A) <= (100 + 2) / 0.2 ~ 500 (x error measured: 3e-15 and 8e-7).
    CHECK(max_x_error(&p) <= TOL(1e-12, 5e-5));
    CHECK(check_lcp(&p, TOL(1e-12, 1e-5)) == 0);
    problem_free(&p);
    return 0;
}

static int test_large_banded_n2000_terminates(void)
{
    // A pentadiagonal, diagonally dominant matrix: positive definite, well conditioned.
    rng_seed(6);
    int n = 2000;
    problem p = problem_make(n);
    for (int i = 0; i < n; i++) {
        for (int j = i + 1; j <= i + 2 && j < n; j++)
            *at(&p, i, j) = *at(&p, j, i) = (dReal)rnd(-1, 1);
    }
    for (int i = 0; i < n; i++) {
        double s = 0.5;
        for (int j = i - 2; j <= i + 2; j++)
            if (j >= 0 && j < n && j != i) s += fabs((double)*at(&p, i, j));
        *at(&p, i, i) = (dReal)s;
    }
    plant(&p, 100);
    struct timespec t0;
    timespec_get(&t0, TIME_UTC);
    int ok = solve(&p);
    printf("# n = 2000 banded: %.1f ms\n", elapsed_ms(t0));
    CHECK(ok == 1);
    CHECK(max_x_error(&p) <= TOL(1e-12, 5e-5));   // measured 4e-16 and 1.4e-7
    CHECK(check_lcp(&p, TOL(1e-12, 1e-5)) == 0);
    problem_free(&p);
    return 0;
}

// Articulated bodies as the big-matrix stepper sees them: `figures` chains of `links` bodies
// (unit mass, random diagonal inertia) on ball joints (three unbounded rows each; the first
// link of some chains hangs from the world), a few joint limits (one angular row bounded
// below by 0) and nc contacts between a body and the world or two bodies of different
// chains (a normal row bounded below by 0 and two friction rows naming it). The rows come in
// a shuffled order, and the unbounded ones are found by their infinite bounds (nub 0) or,
// with `nub_first`, moved to the front and counted in nub. A = J M^-1 J^T + cfm I and
// b = -J v0 for a random v0, as the stepper forms them (without the constraint error terms).
// `twins`: each ball joint also gets an identical copy (redundant unbounded rows).
typedef struct articulated {
    int figures, links, nc, limits, twins, nub_first;
    double cfm;
} articulated;

static void make_articulated(problem *p, const articulated *a)
{
    int nbody = a->figures * a->links, dof = 6 * nbody;
    int nball = a->figures * a->links * (a->twins ? 2 : 1);
    int n = 3 * nball + a->limits + 3 * a->nc;
    double *J = calloc((size_t)n * (size_t)dof, sizeof(double));
    double *inv_i = malloc(sizeof(double) * dof);
    double *v0 = malloc(sizeof(double) * dof), *lo = malloc(sizeof(double) * n);
    double *hi = malloc(sizeof(double) * n);
    int *fi = malloc(sizeof(int) * n), *order = malloc(sizeof(int) * n), r = 0;
    for (int k = 0; k < dof; k++) {
        inv_i[k] = k % 6 < 3 ? 1 : 1 / rnd(0.05, 0.5);
        v0[k] = rnd(-1, 1);
    }
    // A point constraint between body b0 (or the world, -1) and b1 along direction d at
    // offsets r0, r1 from their centres: J = [d, r0 x d] for b0 and the negative for b1.
    for (int f = 0; f < a->figures; f++) {
        for (int l = 0; l < a->links; l++) {
            int b1 = f * a->links + l, b0 = l > 0 ? b1 - 1 : (f % 2 ? -1 : -2);
            if (b0 == -2) continue;   // a free chain: no joint to the world
            for (int copy = 0; copy <= a->twins; copy++) {
                for (int k = 0; k < 3; k++, r++) {
                    double *row = J + (size_t)r * dof;
                    row[6 * b1 + k] = -1;
                    row[6 * b1 + 3 + (k + 1) % 3] = 0.25 * (k == 2 ? 1 : 0);
                    row[6 * b1 + 3 + (k + 2) % 3] = -0.25 * (k == 1 ? 1 : 0);
                    if (b0 >= 0) {
                        row[6 * b0 + k] = 1;
                        row[6 * b0 + 3 + (k + 1) % 3] = 0.25 * (k == 2 ? 1 : 0);
                        row[6 * b0 + 3 + (k + 2) % 3] = -0.25 * (k == 1 ? 1 : 0);
                    }
                    lo[r] = -INF;
                    hi[r] = INF;
                    fi[r] = -1;
                }
            }
        }
    }
    for (int t = 0; t < a->limits; t++, r++) {
        int b = rnd_int(nbody), axis = rnd_int(3);
        double *row = J + (size_t)r * dof;
        row[6 * b + 3 + axis] = 1;
        if (b % a->links) row[6 * (b - 1) + 3 + axis] = -1;
        lo[r] = 0;
        hi[r] = INF;
        fi[r] = -1;
    }
    for (int c = 0; c < a->nc; c++) {
        int body[2] = { rnd_int(nbody), -1 };
        if (rnd(0, 1) < 0.4 && a->figures > 1) {
            body[1] = rnd_int(nbody);
            if (body[1] / a->links == body[0] / a->links) body[1] = -1;
        }
        double d[3][3], off[2][3];
        for (int k = 0; k < 3; k++) {
            d[0][k] = rnd(-1, 1);
            off[0][k] = rnd(-0.3, 0.3);
            off[1][k] = rnd(-0.3, 0.3);
        }
        double len = sqrt(d[0][0] * d[0][0] + d[0][1] * d[0][1] + d[0][2] * d[0][2]);
        for (int k = 0; k < 3; k++) d[0][k] /= len;
        int ax = fabs(d[0][0]) < 0.6 ? 0 : 1;
        double e[3] = { ax == 0, ax == 1, 0 }, dn = d[0][ax];
        for (int k = 0; k < 3; k++) d[1][k] = e[k] - dn * d[0][k];
        len = sqrt(d[1][0] * d[1][0] + d[1][1] * d[1][1] + d[1][2] * d[1][2]);
        for (int k = 0; k < 3; k++) d[1][k] /= len;
        for (int k = 0; k < 3; k++)
            d[2][k] = d[0][(k + 1) % 3] * d[1][(k + 2) % 3] - d[0][(k + 2) % 3] * d[1][(k + 1) % 3];
        double mu = rnd(0, 1) < 0.1 ? 0 : rnd(0.2, 1.2);
        for (int k = 0; k < 3; k++, r++) {
            double *row = J + (size_t)r * dof;
            for (int side = 0; side < 2; side++) {
                if (body[side] < 0) continue;
                double *bj = row + 6 * body[side], sg = side ? -1 : 1;
                const double *o = off[side], *dd = d[k];
                for (int q = 0; q < 3; q++) {
                    bj[q] += sg * dd[q];
                    bj[3 + q] += sg * (o[(q + 1) % 3] * dd[(q + 2) % 3] -
                                       o[(q + 2) % 3] * dd[(q + 1) % 3]);
                }
            }
            lo[r] = k == 0 ? 0 : -mu;
            hi[r] = k == 0 ? INF : mu;
            fi[r] = k == 0 ? -1 : r - k;   // the source row of the normal, renumbered below
        }
    }
    n = r;
    // The order: unbounded rows first when counted in nub, else shuffled.
    int nu = 0;
    for (int i = 0; i < n; i++) order[i] = i;
    for (int i = n - 1; i > 0; i--) {
        int k = rnd_int(i + 1), t = order[i];
        order[i] = order[k];
        order[k] = t;
    }
    if (a->nub_first) {
        int *tmp = malloc(sizeof(int) * n), c = 0;
        for (int i = 0; i < n; i++)
            if (lo[order[i]] == -INF && fi[order[i]] < 0) tmp[c++] = order[i];
        nu = c;
        for (int i = 0; i < n; i++)
            if (!(lo[order[i]] == -INF && fi[order[i]] < 0)) tmp[c++] = order[i];
        memcpy(order, tmp, sizeof(int) * n);
        free(tmp);
    }
    int *place = malloc(sizeof(int) * n);
    for (int i = 0; i < n; i++) place[order[i]] = i;
    *p = problem_make(n);
    p->nub = nu;
    p->findex = malloc(sizeof(int) * n);
    for (int i = 0; i < n; i++) {
        int src = order[i];
        const double *ji = J + (size_t)src * dof;
        double bi = 0;
        for (int k = 0; k < dof; k++) bi -= ji[k] * v0[k];
        p->b[i] = (dReal)bi;
        p->lo[i] = (dReal)lo[src];
        p->hi[i] = (dReal)hi[src];
        p->findex[i] = fi[src] >= 0 ? place[fi[src]] : -1;
        for (int j = 0; j <= i; j++) {
            const double *jj = J + (size_t)order[j] * dof;
            double sum = i == j ? a->cfm : 0;
            for (int k = 0; k < dof; k++) sum += ji[k] * jj[k] * inv_i[k];
            *at(p, i, j) = *at(p, j, i) = (dReal)sum;
        }
    }
    free(J);
    free(inv_i);
    free(v0);
    free(lo);
    free(hi);
    free(fi);
    free(order);
    free(place);
}

// The friction bounds the solver returned must be mu times the normal forces of the
// frictionless problem (the friction rows held at 0), solved on its own.
static int check_friction_bounds(const problem *p, const dReal *mu, double tol)
{
    problem q = problem_make(p->n);
    memcpy(q.A, p->A, sizeof(dReal) * (size_t)p->n * (size_t)p->ld);
    memcpy(q.b, p->b, sizeof(dReal) * (size_t)p->n);
    q.nub = p->nub;
    for (int i = 0; i < p->n; i++) {
        int friction = i >= p->nub && p->findex[i] >= 0;
        q.lo[i] = friction ? 0 : p->lo[i];
        q.hi[i] = friction ? 0 : p->hi[i];
    }
    int ok = solve(&q);
    for (int i = 0; i < p->n && ok; i++) {
        if (i < p->nub || p->findex[i] < 0) continue;
        double expect = fabs((double)mu[i] * q.x[p->findex[i]]);
        if (fabs(p->hi[i] - expect) > tol * (1 + expect) || p->lo[i] != -p->hi[i]) {
            test_fail(__FILE__, __LINE__, "row %d: bounds [%g, %g], mu x_n = %g", i, p->lo[i],
                      p->hi[i], expect);
            ok = 0;
        }
    }
    problem_free(&q);
    return ok ? 0 : 1;
}

static int test_articulated_systems_with_contacts(void)
{
    // Sizes from 20 to a few hundred rows: the unbounded rows are eliminated and the rest
    // pivoted in interaction order. Positive definite (cfm > 0), so the solution is unique:
    // checking the conditions (and the friction bounds) checks the answer. Violations
    // measured: 1e-13 in double, 4e-5 in single precision.
    rng_seed(9);
    for (int trial = 0; trial < 120; trial++) {
        articulated a = { .figures = 1 + rnd_int(6), .links = 2 + rnd_int(8),
                          .limits = rnd_int(6), .twins = 0, .nub_first = trial % 2,
                          .cfm = trial % 3 == 0 ? 1e-6 : 1e-3 };
        a.nc = 1 + rnd_int(4 * a.figures + 4);
        problem p;
        make_articulated(&p, &a);
        dReal *mu = malloc(sizeof(dReal) * (size_t)p.n);
        memcpy(mu, p.hi, sizeof(dReal) * (size_t)p.n);
        int ok = solve(&p);
        if (!ok) printf("# trial %d (n %d) gave up\n", trial, p.n);
        CHECK(ok == 1);
        CHECK(check_lcp(&p, TOL(1e-9, 2e-3)) == 0);
        CHECK(check_friction_bounds(&p, mu, TOL(1e-6, 1e-2)) == 0);
        free(mu);
        problem_free(&p);
    }
    return 0;
}

static int test_articulated_systems_with_redundant_rows(void)
{
    // Every ball joint twice (identical unbounded rows: half of them depend on the others)
    // and CFM 0 or 1e-10: singular or nearly so. The load is shared in some way; the
    // conditions must hold.
    rng_seed(10);
    for (int trial = 0; trial < 60; trial++) {
        articulated a = { .figures = 1 + rnd_int(4), .links = 2 + rnd_int(6),
                          .limits = rnd_int(4), .twins = 1, .nub_first = trial % 2,
                          .cfm = trial % 3 == 0 ? 0 : 1e-10 };
        a.nc = 1 + rnd_int(3 * a.figures + 2);
        problem p;
        make_articulated(&p, &a);
        int ok = solve(&p);
        if (!ok) printf("# trial %d (n %d) gave up\n", trial, p.n);
        CHECK(ok == 1);
        CHECK(check_lcp(&p, TOL(1e-7, 2e-2)) == 0);
        problem_free(&p);
    }
    return 0;
}

static int test_sparse_input_gives_the_dense_answer(void)
{
    // The same problems through dxSolveLCPSparse (the nonzeros only, in increasing column
    // order, as the solver lists them for a full A) and dxSolveLCP (A in full): the same
    // arithmetic, so the same x to the last bit.
    rng_seed(11);
    for (int trial = 0; trial < 40; trial++) {
        articulated a = { .figures = 1 + rnd_int(4), .links = 1 + rnd_int(6),
                          .limits = rnd_int(3), .nub_first = trial % 2, .cfm = 1e-4 };
        a.nc = 1 + rnd_int(8);
        problem p;
        make_articulated(&p, &a);
        int n = p.n, *start = malloc(sizeof(int) * (size_t)(n + 1));
        int *cols = malloc(sizeof(int) * (size_t)n * (size_t)n);
        dReal *vals = malloc(sizeof(dReal) * (size_t)n * (size_t)n);
        dReal *lo = malloc(sizeof(dReal) * (size_t)n), *hi = malloc(sizeof(dReal) * (size_t)n);
        dReal *x = malloc(sizeof(dReal) * (size_t)n), *w = malloc(sizeof(dReal) * (size_t)n);
        memcpy(lo, p.lo, sizeof(dReal) * (size_t)n);
        memcpy(hi, p.hi, sizeof(dReal) * (size_t)n);
        start[0] = 0;
        for (int i = 0; i < n; i++) {
            start[i + 1] = start[i];
            for (int j = 0; j < n; j++) {
                if (*at(&p, i, j) == 0) continue;
                cols[start[i + 1]] = j;
                vals[start[i + 1]++] = *at(&p, i, j);
            }
        }
        dxLCPMatrix m = { start, cols, vals };
        dxArena arena;
        dxArenaInit(&arena);
        CHECK(dxSolveLCPSparse(&arena, n, &m, x, p.b, w, p.nub, lo, hi, p.findex) == 1);
        dxArenaFree(&arena);
        CHECK(solve(&p) == 1);
        for (int i = 0; i < n; i++) {
            CHECK(x[i] == p.x[i]);
            CHECK(w[i] == p.w[i]);
            CHECK(lo[i] == p.lo[i] && hi[i] == p.hi[i]);
        }
        free(start);
        free(cols);
        free(vals);
        free(lo);
        free(hi);
        free(x);
        free(w);
        problem_free(&p);
    }
    return 0;
}

static int test_friction_from_an_unbounded_normal(void)
{
    // A friction row may name an unbounded row as its normal (it is then eliminated): its
    // bound comes from that row's recovered value. Rows: 20 independent unbounded rows
    // (A = I, x = b), then a friction row on row 3 with mu 0.5, pushed hard: it saturates.
    problem p = problem_make(21);
    p.findex = malloc(21 * sizeof(int));
    for (int i = 0; i < 21; i++) {
        *at(&p, i, i) = 1;
        p.b[i] = (dReal)(i + 1);
        p.findex[i] = -1;
        p.lo[i] = -INF;
        p.hi[i] = INF;
    }
    p.findex[20] = 3;
    p.lo[20] = (dReal)-0.5;
    p.hi[20] = (dReal)0.5;
    p.b[20] = 100;
    CHECK(solve(&p) == 1);
    CHECK(p.x[3] == 4);
    CHECK(p.hi[20] == 2 && p.lo[20] == -2);
    CHECK(p.x[20] == 2 && p.w[20] == -98);
    CHECK(check_lcp(&p, 0) == 0);
    problem_free(&p);
    return 0;
}

static int test_arena_is_left_at_its_mark(void)
{
    rng_seed(7);
    problem p = problem_make(50);
    make_spd(&p, 50, 0.1);
    plant(&p, 5);
    dxArena arena;
    dxArenaInit(&arena);
    dxArenaAlloc(&arena, 1000);   // the caller's own scratch, below the mark
    dxArenaMark before = dxArenaSave(&arena);
    CHECK(dxSolveLCP(&arena, p.n, p.A, p.x, p.b, p.w, p.nub, p.lo, p.hi, NULL) == 1);
    dxArenaMark after = dxArenaSave(&arena);
    CHECK(after.in_use == before.in_use);
    size_t peak = arena.peak;
    dxArenaReset(&arena);   // merges the grown chain into one block of the peak size
    dxArenaAlloc(&arena, 1000);
    dxArenaBlock *block = arena.block;
    CHECK(dxSolveLCP(&arena, p.n, p.A, p.x, p.b, p.w, p.nub, p.lo, p.hi, NULL) == 1);
    CHECK(arena.block == block);   // a second solve fits: nothing new allocated
    CHECK(arena.peak == peak);
    CHECK(dxArenaSave(&arena).in_use == before.in_use);
    dxArenaFree(&arena);
    problem_free(&p);
    return 0;
}

static int test_empty_problem(void)
{
    dxArena arena;
    dxArenaInit(&arena);
    CHECK(dxSolveLCP(&arena, 0, NULL, NULL, NULL, NULL, 0, NULL, NULL, NULL) == 1);
    CHECK(arena.in_use == 0);
    dxArenaFree(&arena);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_all_unbounded_equals_linear_solve),
    TEST_CASE(test_one_dimensional_bounds_from_each_side),
    TEST_CASE(test_planted_solutions_are_found),
    TEST_CASE(test_agrees_with_brute_force_enumeration),
    TEST_CASE(test_friction_sticks_below_and_slides_above_mu_normal),
    TEST_CASE(test_friction_row_before_its_normal_is_processed_after_it),
    TEST_CASE(test_friction_on_a_box_sliding_and_sticking),
    TEST_CASE(test_redundant_contacts_with_tiny_cfm),
    TEST_CASE(test_random_contact_systems),
    TEST_CASE(test_coincident_joints_share_the_load),
    TEST_CASE(test_redundant_bounded_rows_redistribute),
    TEST_CASE(test_inconsistent_singular_system_gives_up_finite),
    TEST_CASE(test_rank_deficient_planted_problems),
    TEST_CASE(test_large_dense_planted_n300),
    TEST_CASE(test_large_banded_n2000_terminates),
    TEST_CASE(test_articulated_systems_with_contacts),
    TEST_CASE(test_articulated_systems_with_redundant_rows),
    TEST_CASE(test_sparse_input_gives_the_dense_answer),
    TEST_CASE(test_friction_from_an_unbounded_normal),
    TEST_CASE(test_arena_is_left_at_its_mark),
    TEST_CASE(test_empty_problem),
    TEST_END
};
