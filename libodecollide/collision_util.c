// SPDX-License-Identifier: BSD-3-Clause
//
// collision_util.c -- the collision utilities of guide 10.10: the closest
// points of two line segments, and whether two boxes touch (separating axis
// test).

#include <ode/collision.h>
#include <ode/odemath.h>

#include <float.h>

// Below this sin^2 of the angle between two segments they count as
// parallel, and a pair with an endpoint is preferred (guide 10.10) when it
// is as close as the general solution within rounding.
#ifdef dSINGLE
#define PARALLEL_SIN2 ((dReal)1e-6)
#define ROUNDING ((dReal)FLT_EPSILON)
#else
#define PARALLEL_SIN2 ((dReal)1e-13)
#define ROUNDING ((dReal)DBL_EPSILON)
#endif

// Added to |cos| between box axes in the separating axis test: with two
// nearly parallel edges their cross product is rounding noise and so is the
// test along it; the margin (a relative inflation of the boxes by as much)
// keeps the noise from reporting a separation that is not there.
#ifdef dSINGLE
#define AXIS_MARGIN ((dReal)1e-5)
#else
#define AXIS_MARGIN ((dReal)1e-12)
#endif

static dReal dot3(const dReal *a, const dReal *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static dReal clamp01(dReal x)
{
    return x < 0 ? 0 : x > 1 ? 1 : x;
}

// The point p + u (q - p) of segment p-q into out.
static void lerp3(const dReal *p, const dReal *q, dReal u, dReal *out)
{
    for (int i = 0; i < 3; i++) out[i] = p[i] + u * (q[i] - p[i]);
}

static dReal dist2(const dReal *a, const dReal *b)
{
    dReal d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return dot3(d, d);
}

static void cross3(const dReal *a, const dReal *b, dReal *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// The parameter of the point of segment p + u d (u in [0, 1], |d|^2 = dd > 0)
// closest to x.
static dReal project01(const dReal *p, const dReal *d, dReal dd, const dReal *x)
{
    dReal r[3] = { x[0] - p[0], x[1] - p[1], x[2] - p[2] };
    return clamp01(dot3(r, d) / dd);
}

// The two segments a1 + s da and b1 + t db (r = a1 - b1, both of nonzero
// length) with the quantities the solutions share.
typedef struct segment_pair {
    const dReal *a1, *a2, *b1, *b2;
    dReal da[3], db[3], r[3];
    dReal aa, bb, ab, ar, br;
} segment_pair;

// The minimum of |r + s da - t db|^2 over s, t in [0, 1] for segments that
// are not parallel (n = da x db != 0): the unconstrained s, clamped, then
// the best t for it, and if t had to be clamped the best s for that t (for a
// convex quadratic on a square this finds the minimum). The unconstrained s
// is n . (db x r) / |n|^2, which equals the textbook
// (ab br - bb ar) / (aa bb - ab^2) but loses only eps / sin to rounding
// instead of eps / sin^2.
static void closest_general(const segment_pair *q, const dReal *n, dReal nn, dReal *s_out,
                            dReal *t_out)
{
    dReal m[3];
    cross3(q->db, q->r, m);
    dReal s = clamp01(dot3(n, m) / nn);
    dReal t = (q->ab * s + q->br) / q->bb;
    if (t < 0 || t > 1) {
        t = clamp01(t);
        s = clamp01((q->ab * t - q->ar) / q->aa);
    }
    *s_out = s;
    *t_out = t;
}

// (Nearly) parallel segments have many closest pairs or a flat minimum. The
// candidates, in the order ODE 0.16 tries them where its arithmetic is
// exact: two endpoints (a1 b1, a1 b2, a2 b1, a2 b2), b1 and b2 with their
// closest points on A, a1 and a2 with theirs on B; last the general
// solution g (s_g, t_g) if there is one (has_g). The first candidate
// within rounding of the closest is returned.
static void closest_parallel(const segment_pair *q, int has_g, dReal s_g, dReal t_g,
                             dReal *cp1, dReal *cp2)
{
    const dReal *ends_a[2] = { q->a1, q->a2 }, *ends_b[2] = { q->b1, q->b2 };
    dReal pa[9][3], pb[9][3], d[9], best = dInfinity;
    for (int k = 0; k < 4; k++) {
        dCopyVector3(pa[k], ends_a[k / 2]);
        dCopyVector3(pb[k], ends_b[k % 2]);
    }
    for (int k = 0; k < 2; k++) {
        dCopyVector3(pb[4 + k], ends_b[k]);
        lerp3(q->a1, q->a2, project01(q->a1, q->da, q->aa, ends_b[k]), pa[4 + k]);
        dCopyVector3(pa[6 + k], ends_a[k]);
        lerp3(q->b1, q->b2, project01(q->b1, q->db, q->bb, ends_a[k]), pb[6 + k]);
    }
    int count = 8;
    if (has_g) {
        lerp3(q->a1, q->a2, s_g, pa[8]);
        lerp3(q->b1, q->b2, t_g, pb[8]);
        count = 9;
    }
    for (int k = 0; k < count; k++) {
        d[k] = dSqrt(dist2(pa[k], pb[k]));
        if (d[k] < best) best = d[k];
    }
    // Distances between points ~size apart are good to a few ulps of size.
    dReal size = dSqrt(q->aa) + dSqrt(q->bb) + dSqrt(dot3(q->r, q->r));
    int k = 0;
    while (k < count - 1 && d[k] > best + 4 * ROUNDING * size) k++;
    dCopyVector3(cp1, pa[k]);
    dCopyVector3(cp2, pb[k]);
}

// Zero-length segments fix their parameter at 0 (the other is then the
// projection of that point); parallel ones go to closest_parallel.
void dClosestLineSegmentPoints(const dVector3 a1, const dVector3 a2, const dVector3 b1,
                               const dVector3 b2, dVector3 cp1, dVector3 cp2)
{
    segment_pair q = { a1, a2, b1, b2, { 0 }, { 0 }, { 0 }, 0, 0, 0, 0, 0 };
    for (int i = 0; i < 3; i++) {
        q.da[i] = a2[i] - a1[i];
        q.db[i] = b2[i] - b1[i];
        q.r[i] = a1[i] - b1[i];
    }
    q.aa = dot3(q.da, q.da);
    q.bb = dot3(q.db, q.db);
    q.ab = dot3(q.da, q.db);
    q.ar = dot3(q.da, q.r);
    q.br = dot3(q.db, q.r);
    dReal s = 0, t = 0;
    if (q.aa > 0 && q.bb > 0) {
        dReal n[3];
        cross3(q.da, q.db, n);
        dReal nn = dot3(n, n);   // (|da| |db| sin)^2
        if (nn > 0) closest_general(&q, n, nn, &s, &t);
        if (nn <= PARALLEL_SIN2 * q.aa * q.bb) {
            closest_parallel(&q, nn > 0, s, t, cp1, cp2);
            return;
        }
    } else if (q.bb > 0) {
        t = project01(b1, q.db, q.bb, a1);
    } else if (q.aa > 0) {
        s = project01(a1, q.da, q.aa, b1);
    }
    lerp3(a1, a2, s, cp1);
    lerp3(b1, b2, t, cp2);
}

// Separating axis test in box 1's frame: the 3 face normals of each box and
// the 9 cross products of an edge of each. Touching counts (1).
int dBoxTouchesBox(const dVector3 _p1, const dMatrix3 R1, const dVector3 side1,
                   const dVector3 _p2, const dMatrix3 R2, const dVector3 side2)
{
    dReal d[3], t[3], h1[3], h2[3], C[3][3], A[3][3];
    for (int i = 0; i < 3; i++) {
        d[i] = _p2[i] - _p1[i];
        h1[i] = side1[i] / 2;
        h2[i] = side2[i] / 2;
    }
    for (int i = 0; i < 3; i++) {
        t[i] = R1[i] * d[0] + R1[4 + i] * d[1] + R1[8 + i] * d[2];
        for (int j = 0; j < 3; j++) {   // cos between axis i of box 1 and j of box 2
            C[i][j] = R1[i] * R2[j] + R1[4 + i] * R2[4 + j] + R1[8 + i] * R2[8 + j];
            A[i][j] = dFabs(C[i][j]) + AXIS_MARGIN;
        }
    }
    for (int i = 0; i < 3; i++)   // box 1's faces
        if (dFabs(t[i]) > h1[i] + h2[0] * A[i][0] + h2[1] * A[i][1] + h2[2] * A[i][2])
            return 0;
    for (int j = 0; j < 3; j++) {   // box 2's faces
        dReal tj = t[0] * C[0][j] + t[1] * C[1][j] + t[2] * C[2][j];
        if (dFabs(tj) > h2[j] + h1[0] * A[0][j] + h1[1] * A[1][j] + h1[2] * A[2][j])
            return 0;
    }
    for (int i = 0; i < 3; i++) {   // edge i of box 1 x edge j of box 2
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; j++) {
            int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            dReal dist = dFabs(t[i2] * C[i1][j] - t[i1] * C[i2][j]);
            dReal r1 = h1[i1] * A[i2][j] + h1[i2] * A[i1][j];
            dReal r2 = h2[j1] * A[i][j2] + h2[j2] * A[i][j1];
            if (dist > r1 + r2) return 0;
        }
    }
    return 1;
}
