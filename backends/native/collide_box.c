// SPDX-License-Identifier: BSD-3-Clause
//
// collide_box.c -- box-box (separating axes, then the contact polygon of the
// touching faces or the closest points of two edges) and box-plane (the
// corners below the plane).

#include <stdint.h>
#include <string.h>

#include "collide_math.h"
#include "../../libodedyn/core/dx_clones.h"

// The edge axes of (nearly) parallel edges are (nearly) zero vectors: their
// separation test allows this margin (relative to the box sizes) for rounding.
#define BOX_AXIS_SLACK ((dReal)1e-5)
// An edge axis wins only if its penetration is shorter than the best face
// axis' by this factor: face contacts give a stable polygon, so they are
// preferred when the two are about as deep.
#define BOX_EDGE_PREFERENCE ((dReal)1.05)
// box_keep_overlapping's shortcut trusts a bound when it clears the
// rounding by this much, relative to the sizes (for rotations: matrix
// entries of at most 1.25).
#ifdef dSINGLE
#define BOX_EXIT_MARGIN ((dReal)1e-4)
#else
#define BOX_EXIT_MARGIN ((dReal)1e-10)
#endif
// edges_lose's margin for rounding (relative), and the range of overlaps
// (BOX_SQUARE_RANGE to its inverse) whose squares it takes.
#ifdef dSINGLE
#define BOX_SQUARE_MARGIN ((dReal)1e-4)
#define BOX_SQUARE_RANGE ((dReal)1e-15)
#else
#define BOX_SQUARE_MARGIN ((dReal)1e-9)
#define BOX_SQUARE_RANGE ((dReal)1e-100)
#endif
// Boxes whose centres are farther apart than this times the sum of their
// half diagonals are apart without a look at their axes.
#define BOX_SPHERE_MARGIN ((dReal)1.001)

// Functions of the clipper and the axes, inlined with their constant
// arguments (a side, an axis pair) so that their indices fold away.
#define BOX_INLINE static inline __attribute__((always_inline))

// The collider's entry points (everything else inlined in them) are built
// twice where the compiler can pick a version when the library is loaded
// (GNU ifunc: x86-64, ELF, glibc): for AVX2 (one operation per four numbers
// below) and for the baseline.
// (-DBOX_CLONES= builds the baseline alone, to check it.) Clang (14)
// refuses the fours passed between the inlined functions of the baseline
// clone ("AVX vector argument ... changes the ABI", an error there), so it
// builds the baseline alone: the same numbers.
#if !defined(BOX_CLONES) && !defined(__clang__) && defined(DX_AVX2_CLONES)
#define BOX_CLONES DX_AVX2_CLONES
#endif
#ifndef BOX_CLONES
#define BOX_CLONES
#endif

// Fours of numbers (GNU vector extensions: one AVX operation in the AVX2
// build, two SSE2 ones for doubles in the baseline): a vector's lanes are
// computed with the same operations in the same order as the scalar
// formulas they stand for, so their results are the same to the bit. (The
// AVX2 build has no FMA, so no a * b + c is contracted to one rounding.)
typedef dReal box_v4 __attribute__((vector_size(4 * sizeof(dReal))));
#ifdef dSINGLE
typedef int32_t box_b4 __attribute__((vector_size(4 * sizeof(int32_t))));
#define BOX_SIGN_BIT ((int32_t)0x7fffffff)
#else
typedef int64_t box_b4 __attribute__((vector_size(4 * sizeof(int64_t))));
#define BOX_SIGN_BIT ((int64_t)0x7fffffffffffffff)
#endif

BOX_INLINE box_v4 v4_load(const dReal *p)
{
    box_v4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

BOX_INLINE void v4_store(dReal *p, box_v4 v)
{
    memcpy(p, &v, sizeof v);
}

// |v| lane by lane (the sign bits cleared, as fabs does).
BOX_INLINE box_v4 v4_abs(box_v4 v)
{
    box_b4 bits;
    memcpy(&bits, &v, sizeof v);
    bits &= BOX_SIGN_BIT;
    memcpy(&v, &bits, sizeof v);
    return v;
}

// v with its fourth lane 0: cleared with a mask, not inserted (GCC inserts
// a 0 with a vmovq between registers that Valgrind 3.19, the instruction
// counts' tool, cannot run).
BOX_INLINE box_v4 v4_clear3(box_v4 v)
{
    static const box_b4 keep3 = { -1, -1, -1, 0 };
    box_b4 bits;
    memcpy(&bits, &v, sizeof v);
    bits &= keep3;
    memcpy(&v, &bits, sizeof v);
    return v;
}

// (x, y, z, 0).
BOX_INLINE box_v4 v4_of3(dReal x, dReal y, dReal z)
{
    return v4_clear3((box_v4){ x, y, z, z });
}

// Lane by lane, a where mask (all bits set) else b.
BOX_INLINE box_v4 v4_select(box_b4 mask, box_v4 a, box_v4 b)
{
    box_b4 x, y;
    memcpy(&x, &a, sizeof a);
    memcpy(&y, &b, sizeof b);
    x = (x & mask) | (y & ~mask);
    memcpy(&a, &x, sizeof a);
    return a;
}

// (v1, v2, v0, v3) and (v2, v0, v1, v3): lane j gets lane j + 1 or j + 2
// (mod 3).
BOX_INLINE box_v4 v4_turn1(box_v4 v)
{
    return __builtin_shufflevector(v, v, 1, 2, 0, 3);
}

BOX_INLINE box_v4 v4_turn2(box_v4 v)
{
    return __builtin_shufflevector(v, v, 2, 0, 1, 3);
}

// A point of the clipped contact polygon in the reference face's frame, in
// four lanes: x, y, its depth under the reference face, and t (pos is this
// far from the incident point along nf).
typedef box_v4 clip_point;
enum { CP_X, CP_Y, CP_DEPTH, CP_T };

// The reference face's rectangle |x| <= h1, |y| <= h2 as four clipping
// lines, clipped against in this order: x <= h1, -x <= h1, y <= h2,
// -y <= h2. A point's offsets from them (> 0 outside) are the lanes of
// (x, x, y, y) sg - h, with sg = (1, -1, 1, -1) (exact signs) and
// h = (h1, h1, h2, h2).
typedef struct clip_rect {
    box_v4 sg, h;
} clip_rect;

BOX_INLINE box_v4 side_offsets(const clip_rect *r, clip_point p)
{
    return __builtin_shufflevector(p, p, CP_X, CP_X, CP_Y, CP_Y) * r->sg - r->h;
}

// The lines a point with offsets off is not inside of (all bits set), NaN
// counted as outside.
BOX_INLINE box_b4 outside_of(box_v4 off)
{
    box_v4 zero = { 0, 0, 0, 0 };
    return ~(off <= zero);
}

// The part of edge p-q (line offsets dp, dq) clip_side keeps, written at
// *o (offsets at *oo, their outside_of ored into *mask): p if inside, then
// the crossing if the edge crosses the line (with room for it: room is 0
// for none). Points on the line are kept once and not duplicated by the
// crossing test.
BOX_INLINE void clip_edge(const clip_rect *r, const clip_point *p, const clip_point *q,
                          const box_v4 *po, dReal dp, dReal dq, clip_point **o, box_v4 **oo,
                          box_b4 *mask, int room)
{
    int cross;
    if (dp <= 0) {
        *(*o)++ = *p;
        *(*oo)++ = *po;
        *mask |= outside_of(*po);
        cross = room > 1 && dp < 0 && dq > 0;
    } else {
        cross = room > 0 && dp > 0 && dq < 0;
    }
    if (cross) {
        dReal f = dp / (dp - dq);
        clip_point c = *p + f * (*q - *p);   // x, y, depth (t: unset)
        box_v4 co = side_offsets(r, c);
        *(*o)++ = c;
        *(*oo)++ = co;
        *mask |= outside_of(co);
    }
}

// Clip poly (n points, their offsets off) by line s into out and out_off;
// returns the new count (at most n + 1 for a convex polygon, capped at 16)
// and sets *outside to the new points' outside_of ored. Each point adds at
// most two, so up to 8 points need no cap. The closing edge comes last.
BOX_INLINE int clip_side(const clip_rect *r, const clip_point *poly, const box_v4 *off, int n,
                         int s, clip_point *out, box_v4 *out_off, box_b4 *outside)
{
    box_b4 mask = { 0, 0, 0, 0 };
    clip_point *o = out;
    box_v4 *oo = out_off;
    if (n <= 8) {
        for (int i = 0; i < n - 1; i++)
            clip_edge(r, &poly[i], &poly[i + 1], &off[i], off[i][s], off[i + 1][s], &o, &oo,
                      &mask, 2);
        clip_edge(r, &poly[n - 1], &poly[0], &off[n - 1], off[n - 1][s], off[0][s], &o, &oo,
                  &mask, 2);
    } else {
        for (int i = 0; i < n && o - out < 16; i++) {
            int j = i + 1 < n ? i + 1 : 0;
            clip_edge(r, &poly[i], &poly[j], &off[i], off[i][s], off[j][s], &o, &oo, &mask,
                      (int)(16 - (o - out)));
        }
    }
    *outside = mask;
    return (int)(o - out);
}

// Choose max of the n points (n > max, n <= 16) to keep, in place: the
// deepest, then each time the point farthest from those already chosen, so
// the kept points spread over the polygon. near[i] is point i's squared
// distance to the nearest chosen one, brought up to date with each choice.
BOX_INLINE void cull_points(clip_point *pts, int n, int max)
{
    dReal near[16];
    for (int i = 1; i < n; i++) near[i] = dInfinity;
    for (int k = 1; k < max; k++) {
        int best = k;
        dReal best_d = -1;
        for (int i = k; i < n; i++) {
            clip_point d = pts[i] - pts[k - 1];
            dReal d2 = d[CP_X] * d[CP_X] + d[CP_Y] * d[CP_Y];
            if (d2 < near[i]) near[i] = d2;
            if (near[i] > best_d) {
                best_d = near[i];
                best = i;
            }
        }
        clip_point t = pts[k];
        pts[k] = pts[best];
        pts[best] = t;
        dReal u = near[k];
        near[k] = near[best];
        near[best] = u;
    }
}

// Clip [*t0, *t1] to where p + t d lies in the box (pos, R, half sides h).
static void clip_line_to_box(const dReal p[3], const dReal d[3], const dReal *pos,
                             const dReal *R, const dReal h[3], dReal *t0, dReal *t1)
{
    dReal rel[3] = { p[0] - pos[0], p[1] - pos[1], p[2] - pos[2] }, q[3], v[3];
    dx_to_local(R, rel, q);
    dx_to_local(R, d, v);
    for (int i = 0; i < 3; i++) {
        if (v[i] == 0) {
            if (q[i] > h[i] || q[i] < -h[i]) *t1 = *t0 - 1;   // empty
            continue;
        }
        dReal a = (-h[i] - q[i]) / v[i], b = (h[i] - q[i]) / v[i];
        if (a > b) {
            dReal x = a;
            a = b;
            b = x;
        }
        if (a > *t0) *t0 = a;
        if (b < *t1) *t1 = b;
    }
}

// A point in both boxes, found the long way for deep overlaps where the
// contact features give none: when two convex solids overlap, an edge of
// one passes through the other, so the middle of such an edge's part inside
// the other box will do.
static void box_overlap_point(const dReal *p1, const dReal *R1, const dReal h1[3],
                              const dReal *p2, const dReal *R2, const dReal h2[3], dReal pos[3])
{
    for (int box = 0; box < 2; box++) {
        const dReal *p = box ? p2 : p1, *R = box ? R2 : R1, *h = box ? h2 : h1;
        const dReal *op = box ? p1 : p2, *oR = box ? R1 : R2, *oh = box ? h1 : h2;
        for (int e = 0; e < 12; e++) {
            int i = e / 4, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            dReal s1 = (e & 1) ? h[i1] : -h[i1], s2 = (e & 2) ? h[i2] : -h[i2], c[3], d[3];
            for (int q = 0; q < 3; q++) {
                c[q] = p[q] + s1 * R[4 * q + i1] + s2 * R[4 * q + i2];
                d[q] = R[4 * q + i];
            }
            dReal t0 = -h[i], t1 = h[i];
            clip_line_to_box(c, d, op, oR, oh, &t0, &t1);
            if (t0 <= t1) {
                for (int q = 0; q < 3; q++) pos[q] = c[q] + (t0 + t1) / 2 * d[q];
                return;
            }
        }
    }
    for (int q = 0; q < 3; q++) pos[q] = (p1[q] + p2[q]) / 2;   // only rounding gets here
}

// The face case: the reference box (pr, Rr, half sides hr) touches with its
// face of axis k whose outward normal nf points at the incident box (pi, Ri,
// hi, axes B_m); U1, U2 are the reference box's other axes, the frame of
// that face. box_box has most of the dot products already (its Rm and T):
// C[m] = (B_m . U1, B_m . U2, B_m . nf), c = (pi - pr) . (U1, U2, nf), and
// e[m], an estimate of B_m . (pr - pi) for box_keep_overlapping's test
// (made only for rotations); hk, h1, h2 are hr along nf, U1, U2.
typedef struct box_face {
    const dReal *pr, *Rr, *hr, *pi, *Ri, *hi;
    int rotations;
    dReal hk, h1, h2;
    box_v4 nf, U1, U2;   // fourth lanes 0
    box_v4 Cx, Cy, Cz, e;   // lanes m: C[m][0], C[m][1], C[m][2], e[m]
    dReal c[3];
} box_face;

// The incident box's face most against nf, clipped to the reference face's
// rectangle (in the frame U1, U2, relative to pr): the clipped polygon (at
// most 16 points) is left in a or b (room for 16 each), which is returned,
// its count in *count.
BOX_INLINE clip_point *box_clip_incident(const box_face *f, clip_point a[16], clip_point b[16],
                                         int *count)
{
    const dReal *hi = f->hi;
    box_v4 Cx = f->Cx, Cy = f->Cy, Cz = f->Cz;
    dReal d0 = dFabs(Cz[0]), d1 = dFabs(Cz[1]), d2 = dFabs(Cz[2]);
    int j = d1 > d0 ? 1 : 0;
    if (d2 > (j ? d1 : d0)) j = 2;
    int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    // The incident face's centre (rel + sgn hi_j B_j) and half edges
    // (hi B_j1, hi B_j2) in the reference face's frame (x, y, height); the
    // corners centre +- u +- v (exact signs), the height turned to a depth.
    dReal sgn = Cz[j] > 0 ? -hi[j] : hi[j];
    box_v4 cv = v4_of3(f->c[0] + sgn * Cx[j], f->c[1] + sgn * Cy[j], f->c[2] + sgn * Cz[j]);
    box_v4 u = v4_of3(hi[j1] * Cx[j1], hi[j1] * Cy[j1], hi[j1] * Cz[j1]);
    box_v4 v = v4_of3(hi[j2] * Cx[j2], hi[j2] * Cy[j2], hi[j2] * Cz[j2]);
    box_v4 cu = cv + u, cmu = cv - u;
    a[0] = cu + v;
    a[1] = cmu + v;
    a[2] = cmu - v;
    a[3] = cu - v;
    for (int k = 0; k < 4; k++) a[k][CP_DEPTH] = f->hk - a[k][CP_DEPTH];
    clip_rect r = { { 1, -1, 1, -1 }, { f->h1, f->h1, f->h2, f->h2 } };
    clip_point *cur = a, *spare = b;
    box_v4 off_a[16], off_b[16], *cur_off = off_a, *spare_off = off_b;
    box_b4 outside = { 0, 0, 0, 0 };
    for (int k = 0; k < 4; k++) {
        off_a[k] = side_offsets(&r, a[k]);
        outside |= outside_of(off_a[k]);
    }
    int n = 4;
#pragma GCC unroll 4
    for (int s = 0; s < 4; s++) {   // a line every point is inside of cuts nothing
        if (!outside[s]) continue;
        n = clip_side(&r, cur, cur_off, n, s, spare, spare_off, &outside);
        clip_point *t = cur;
        cur = spare;
        spare = t;
        box_v4 *u = cur_off;
        cur_off = spare_off;
        spare_off = u;
    }
    *count = n;
    return cur;
}

// Keep (in place) the clipped points below the reference face whose line
// P + t nf (P the incident point) runs inside both boxes: t in
// [depth - 2 hr_k, depth] for the reference box, [0, exit] for the incident
// one (rel = pr - pi); pos will be the middle of that stretch (t). Deep
// overlaps can clip points past the far side of a thin reference box: they
// are in neither box and dropped. The deepest is moved first.
BOX_INLINE int box_keep_overlapping(const box_face *f, clip_point *a, int n, box_v4 rel)
{
    const dReal *hr = f->hr, *hi = f->hi, *Ri = f->Ri;
    const dReal hk = f->hk;
    // The exit through the incident box's faces of axis m (t_m, where
    // B_m . (q + t nf) = +-hi_m) is >= depth exactly when the point over P
    // on the reference face lies inside them: g_m = hi_m - sg_m B_m . (rel
    // + x U1 + y U2 + hk nf) >= 0 (sg_m the sign of B_m . nf; the depth
    // cancels), linear in x, y. Where g_m clears the rounding of both
    // computations (margin, relative to the sizes involved) t_m cannot be
    // the least exit short of the depth and is not needed; the others are
    // computed as defined. Axes whose g_m clears twice the margin over the
    // whole reference face (|x| <= h1, |y| <= h2, with the margin for the
    // clipped points' rounding) are not looked at again (nor those
    // parallel to nf: no exit through their faces). The three axes' g_m and
    // t_m are lanes of fours; the least exit is taken in axis order.
    dReal scale = dFabs(rel[0]) + dFabs(rel[1]) + dFabs(rel[2]) + hr[0] + hr[1] + hr[2]
                  + 2 * (hi[0] + hi[1] + hi[2]);
    dReal margin = f->rotations ? BOX_EXIT_MARGIN * scale : dInfinity;   // else: as defined
    dReal X = f->h1 + margin, Y = f->h2 + margin;
    // Lanes of axes not looked at: t_m = (inf - from) / 1, never the least.
    box_v4 zero = { 0, 0, 0, 0 }, one = { 1, 1, 1, 1 };
    box_v4 inf = { dInfinity, dInfinity, dInfinity, dInfinity };
    box_v4 hiv = v4_load(hi), Cz = f->Cz, margins = { margin, margin, margin, margin };
    box_b4 up = Cz > zero, axes = { -1, -1, -1, 0 };
    box_v4 sg = v4_select(up, one, -one);
    box_v4 g0 = hiv - sg * (f->e + hk * Cz), gx = -sg * f->Cx, gy = -sg * f->Cy;
    box_b4 act = axes & (Cz != zero)
                 & ~(g0 - v4_abs(gx) * X - v4_abs(gy) * Y > 2 * margins);
    box_v4 face = v4_select(act, v4_select(up, hiv, -hiv), inf);
    box_v4 dot = v4_select(act, Cz, one);
    box_v4 ri0 = v4_load(Ri), ri1 = v4_load(Ri + 4), ri2 = v4_load(Ri + 8);
    int kept = 0, deepest = 0;
    for (int i = 0; i < n; i++) {
        clip_point p = a[i];
        dReal depth = p[CP_DEPTH];
        if (depth < 0) continue;
        dReal x = p[CP_X], y = p[CP_Y], exit = dInfinity;
        // t_m where g_m > margin replaced by inf; when that leaves no active
        // axis, every t_m is inf (the inactive ones' (inf - finite) / 1: a
        // finite margin means finite sizes) and none is computed.
        box_b4 far = g0 + x * gx + y * gy > margins, need = act & ~far;
        if (need[0] | need[1] | need[2]) {
            box_v4 q = rel + x * f->U1 + y * f->U2 + (hk - depth) * f->nf;
            box_v4 t = (face - (ri0 * q[0] + ri1 * q[1] + ri2 * q[2])) / dot;
            t = v4_select(far, inf, t);
            for (int m = 0; m < 3; m++)
                if (t[m] < exit) exit = t[m];
        }
        if (exit < 0) exit = 0;   // clipped points lie on the incident face: rounding
        dReal lo = depth - 2 * hk > 0 ? depth - 2 * hk : 0;
        dReal top = exit < depth ? exit : depth;
        if (top < lo) continue;
        p[CP_T] = (lo + top) / 2;
        a[kept] = p;
        if (depth > a[deepest][CP_DEPTH]) deepest = kept;
        kept++;
    }
    if (kept > 0) {
        clip_point t = a[0];
        a[0] = a[deepest];
        a[deepest] = t;
    }
    return kept;
}

// What box_clearance needs: the contact normal in box 1's frame (nl), and
// box_box's Rm, overlaps and projections (room for 16: fours are read).
typedef struct box_axes {
    dReal nl[4];   // the fourth lane not looked at
    const dReal (*Rm)[4];
    const dReal *over, *proj;
} box_axes;

// The ray's exit through the faces of axis x, whose direction has s = m . n
// (dInfinity if it runs along them).
BOX_INLINE dReal exit_along(const box_axes *ax, int x, dReal s)
{
    if (s == 0) return dInfinity;
    dReal radii = ax->over[x] + dFabs(ax->proj[x]);
    return ((s > 0 ? ax->proj[x] : -ax->proj[x]) + radii) / dFabs(s);
}

// m . n for face axis x (0-5).
BOX_INLINE dReal face_dot(const box_axes *ax, int x)
{
    const dReal *nl = ax->nl, (*Rm)[4] = ax->Rm;
    return x < 3 ? nl[x] : Rm[0][x - 3] * nl[0] + Rm[1][x - 3] * nl[1] + Rm[2][x - 3] * nl[2];
}

// exit_along for the axes of four lanes (their overlaps, projections and
// s = m . n), each lane the scalar formula's operations in their order.
BOX_INLINE box_v4 exits_along(box_v4 over, box_v4 proj, box_v4 s)
{
    box_v4 zero = { 0, 0, 0, 0 }, inf = { dInfinity, dInfinity, dInfinity, dInfinity };
    box_v4 t = (v4_select(s > zero, proj, -proj) + (over + v4_abs(proj))) / v4_abs(s);
    return v4_select(s == zero, inf, t);
}

// Lane by lane the lesser of t and best, best kept on ties and where t is
// NaN (as "if (t < best) best = t").
BOX_INLINE box_v4 v4_less(box_v4 t, box_v4 best)
{
    return v4_select(t < best, t, best);
}

// How far box 1 must move along the unit normal (nl, in box 1's frame) to
// clear box 2: box 1 moved by t n meets box 2 while t n lies in the
// Minkowski difference box 2 - box 1, whose faces are normal to the 15
// axes m; the ray t n leaves it at the least h(m) / (m . n) over the axes
// facing n, h(m) = m . (p2 - p1) + radius1(m) + radius2(m) its support. The
// ratio does not depend on the length of m, so axes stay unnormalised;
// edge axes of (nearly) parallel edges are left out.
//
// The 15 exits are lanes of five fours (axes 0-2, 3-5, 6-8, 9-11, 12-14:
// over and proj read four at a time, the fourth lane never looked at),
// each the scalar exit to the bit; the least is that of the axes taken in
// order, but for the sign of a zero, which the first zero in axis order
// gives.
BOX_INLINE dReal box_clearance(const box_axes *ax)
{
    const dReal *nl = ax->nl, (*Rm)[4] = ax->Rm, *over = ax->over, *proj = ax->proj;
    box_v4 r[3] = { v4_load(Rm[0]), v4_load(Rm[1]), v4_load(Rm[2]) };
    box_v4 eps = { DX_COLLIDE_EPS, DX_COLLIDE_EPS, DX_COLLIDE_EPS, DX_COLLIDE_EPS };
    box_v4 inf = { dInfinity, dInfinity, dInfinity, dInfinity };
    box_v4 t[5];
    t[0] = exits_along(v4_load(over), v4_load(proj), v4_load(nl));
    t[1] = exits_along(v4_load(over + 3), v4_load(proj + 3),
                       r[0] * nl[0] + r[1] * nl[1] + r[2] * nl[2]);
    box_v4 best = v4_less(t[1], t[0]);
#pragma GCC unroll 3
    for (int i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        box_v4 s = r[i1] * nl[i2] - r[i2] * nl[i1];   // (e_i x Rm[.][j]) . n
        box_v4 len2 = r[i1] * r[i1] + r[i2] * r[i2];
        t[2 + i] = v4_select(len2 <= eps, inf,
                             exits_along(v4_load(over + 6 + 3 * i), v4_load(proj + 6 + 3 * i), s));
        best = v4_less(t[2 + i], best);
    }
    dReal least = best[0];
    if (best[1] < least) least = best[1];
    if (best[2] < least) least = best[2];
    if (least == 0)
        for (int x = 0; x < 15; x++)
            if (t[x / 3][x % 3] == 0) return t[x / 3][x % 3];
    return least;
}

// The face case (see box_clip_incident): the kept points are the contacts,
// each with its depth under the reference face, pos in the middle of the
// stretch through it inside both boxes; at most max, spread (cull_points).
// The deepest carries the translation along the normal that separates the
// boxes (clear, box_clearance of ax): the clipped points reach it unless
// the incident box's highest part over the reference face is not on its
// incident face (deep or crossed overlaps). clear is at most the exit
// through the faces of the contact's own axis (code), so when the deepest
// point reaches that, the full clearance is not needed. normal is the
// contact normal (into o1).
BOX_INLINE int box_face_contacts(const box_face *f, const dReal normal[3], const box_axes *ax,
                             int code, dxGeom *o1, dxGeom *o2, int max, dContactGeom *out,
                             int skip)
{
    const dReal *pr = f->pr, *pi = f->pi;
    clip_point buf[2][16], *a;
    int n;
    a = box_clip_incident(f, buf[0], buf[1], &n);
    box_v4 prv = v4_of3(pr[0], pr[1], pr[2]);
    box_v4 rel = v4_of3(pr[0] - pi[0], pr[1] - pi[1], pr[2] - pi[2]);
    int kept = box_keep_overlapping(f, a, n, rel);
    if (kept == 0) {   // the separating axis says they overlap: find a point
        dReal pos[3];
        box_overlap_point(pr, f->Rr, f->hr, pi, f->Ri, f->hi, pos);
        dx_put_contact(out, 0, skip, pos, normal, box_clearance(ax), o1, o2);
        return 1;
    }
    dReal own = exit_along(ax, code, face_dot(ax, code));
    dReal deepest = a[0][CP_DEPTH];
    dReal clear = deepest < own ? box_clearance(ax) : deepest;
    if (kept > max) {
        cull_points(a, kept, max);
        kept = max;
    }
    // pos = pr + x U1 + y U2 + (hk - depth + t) nf, lane by lane; the fourth
    // lanes of pos and normal (dVector3's padding) get 0.
    box_v4 nv = v4_of3(normal[0], normal[1], normal[2]);
    dReal hk = f->hk;
    for (int c = 0; c < kept; c++) {
        clip_point p = a[c];
        dReal up = hk - p[CP_DEPTH] + p[CP_T];
        box_v4 pos = prv + p[CP_X] * f->U1 + p[CP_Y] * f->U2 + up * f->nf;
        dContactGeom *k = dxContactAt(out, c, skip);
        v4_store(k->pos, pos);
        v4_store(k->normal, nv);
        k->depth = p[CP_DEPTH];
        k->g1 = o1;
        k->g2 = o2;
        k->side1 = k->side2 = -1;
    }
    if (deepest < clear) out->depth = clear;   // contact 0, the deepest point
    return kept;
}

// The edge case: box 1's edge along A_i and box 2's along B_j (the edges of
// each box nearest the other along the normal) touch; one contact at the
// middle of the part of the segment between their closest points that lies
// in both boxes, or if there is none (deep overlaps), box_overlap_point.
static void box_edge_point(const dReal *p1, const dReal *R1, const dReal h1[3], int i,
                           const dReal *p2, const dReal *R2, const dReal h2[3], int j,
                           const dReal n[3], dReal pos[3])
{
    dReal pa[3], pb[3], u[3], v[3];
    for (int m = 0; m < 3; m++) {
        pa[m] = p1[m];
        pb[m] = p2[m];
    }
    for (int m = 0; m < 3; m++) {
        dReal ax[3];
        if (m != i) {   // box 1 towards box 2: against n
            dx_axis(R1, m, ax);
            dReal s = dx_dot(ax, n) > 0 ? -h1[m] : h1[m];
            for (int q = 0; q < 3; q++) pa[q] += s * ax[q];
        }
        if (m != j) {   // box 2 towards box 1: along n
            dx_axis(R2, m, ax);
            dReal s = dx_dot(ax, n) > 0 ? h2[m] : -h2[m];
            for (int q = 0; q < 3; q++) pb[q] += s * ax[q];
        }
    }
    dx_axis(R1, i, u);
    dx_axis(R2, j, v);
    dReal w[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
    dReal b = dx_dot(u, v), d = dx_dot(u, w), e = dx_dot(v, w), denom = 1 - b * b;
    dReal s = dx_clamp((b * e - d) / denom, -h1[i], h1[i]);
    dReal t = dx_clamp((e - b * d) / denom, -h2[j], h2[j]);
    dReal qb[3], dir[3];
    for (int q = 0; q < 3; q++) {
        qb[q] = pb[q] + t * v[q];
        dir[q] = pa[q] + s * u[q] - qb[q];
    }
    dReal t0 = 0, t1 = 1;
    clip_line_to_box(qb, dir, p1, R1, h1, &t0, &t1);
    clip_line_to_box(qb, dir, p2, R2, h2, &t0, &t1);
    if (t0 <= t1) {
        dReal f = (t0 + t1) / 2;
        for (int q = 0; q < 3; q++) pos[q] = qb[q] + f * dir[q];
        return;
    }
    box_overlap_point(p1, R1, h1, p2, R2, h2, pos);
}

// The axis box_box chose, for its callers.
static void report_axis(const dReal normal[3], dReal depth, int code, dReal normal_out[3],
                        dReal *depth_out, int *code_out)
{
    for (int q = 0; q < 3; q++) normal_out[q] = normal[q];
    *depth_out = depth;
    *code_out = code;
}

// An edge axis' length may vanish, so its overlap separates only below this
// margin beyond rounding (or below 0 where the axis is well defined).
BOX_INLINE dReal edge_slack(int i, int j, const dReal a[3], const dReal b[3])
{
    return -BOX_AXIS_SLACK * (a[(i + 1) % 3] + a[(i + 2) % 3] + b[(j + 1) % 3] + b[(j + 2) % 3]);
}

// Whether box_box's shortcuts may take R1 and R2 for rotations: every entry
// of theirs and of Rm (its absolute values Q) at most 1.25 in magnitude.
static int rotation_like(const dReal *R1, const dReal *R2, const dReal Q[3][4])
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            if (!(Q[i][j] <= 1.25 && dFabs(R1[4 * i + j]) <= 1.25 && dFabs(R2[4 * i + j]) <= 1.25))
                return 0;
        }
    }
    return 1;
}

// Box 1's frame (axes A_i, half sides a) for box_box: box 2's centre T,
// Rm_ij = A_i . B_j and Q = |Rm| (rows of four, the fourth unused), and
// along each of the 15 axes (0-2 A_i, 3-5 B_j, 6 + 3 i + j A_i x B_j,
// unnormalised) the overlap of the boxes (over) and box 2's offset (proj).
// Each is computed as the plain formulas say, term for term in the same
// order, four lanes at a time (the same numbers to the bit): T_i = A_i . d;
// over = a_i + sum_j b_j Q_ij - |T_i| and proj = T_i along A_i;
// proj = sum_i T_i Rm_ij, over = sum_i a_i Q_ij + b_j - |proj| along B_j;
// along A_i x B_j, proj = T_i2 Rm_i1j - T_i1 Rm_i2j and over = a_i1 Q_i2j
// + a_i2 Q_i1j + b_j1 Q_ij2 + b_j2 Q_ij1 - |proj| (i1, i2 and j1, j2 the
// next indices mod 3). over and proj have room for 16.
BOX_INLINE void box_frame(const dReal *R1, const dReal *R2, const dReal d[3], const dReal a[3],
                          const dReal b[3], dReal T[4], dReal Rm[3][4], dReal Rc[3][4],
                          dReal Q[3][4], dReal over[16], dReal proj[16])
{
    box_v4 r1[3], r2[3], row[3], qrow[3], qcol[3];
    for (int q = 0; q < 3; q++) {
        r1[q] = v4_load(R1 + 4 * q);
        r2[q] = v4_load(R2 + 4 * q);
    }
    box_v4 t = r1[0] * d[0] + r1[1] * d[1] + r1[2] * d[2];
    for (int i = 0; i < 3; i++) {
        row[i] = R1[i] * r2[0] + R1[4 + i] * r2[1] + R1[8 + i] * r2[2];   // Rm_i.
        qrow[i] = v4_abs(row[i]);
        v4_store(Rm[i], row[i]);
        v4_store(Q[i], qrow[i]);
    }
    // Rm's columns: its rows turned (column i's lane j, B_i . A_j, is the sum
    // of the same products in the same order as row j's lane i).
    box_v4 lo = __builtin_shufflevector(row[0], row[1], 0, 4, 2, 6);   // Rm00 Rm10 Rm02 Rm12
    box_v4 hi = __builtin_shufflevector(row[0], row[1], 1, 5, 3, 7);   // Rm01 Rm11 Rm03 Rm13
    box_v4 col[3] = { __builtin_shufflevector(lo, row[2], 0, 1, 4, 4),
                      __builtin_shufflevector(hi, row[2], 0, 1, 5, 5),
                      __builtin_shufflevector(lo, row[2], 2, 3, 6, 6) };
    for (int i = 0; i < 3; i++) {
        qcol[i] = v4_abs(col[i]);
        v4_store(Rc[i], col[i]);
    }
    v4_store(T, t);
    box_v4 av = v4_load(a), bv = v4_load(b);
    v4_store(proj, t);
    v4_store(over, av + b[0] * qcol[0] + b[1] * qcol[1] + b[2] * qcol[2] - v4_abs(t));
    box_v4 pb = T[0] * row[0] + T[1] * row[1] + T[2] * row[2];
    v4_store(proj + 3, pb);
    v4_store(over + 3, a[0] * qrow[0] + a[1] * qrow[1] + a[2] * qrow[2] + bv - v4_abs(pb));
    box_v4 b1 = v4_of3(b[1], b[2], b[0]), b2 = v4_of3(b[2], b[0], b[1]);
    for (int i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        box_v4 pe = T[i2] * row[i1] - T[i1] * row[i2];
        box_v4 radii = a[i1] * qrow[i2] + a[i2] * qrow[i1] + b1 * v4_turn2(qrow[i])
                       + b2 * v4_turn1(qrow[i]);
        v4_store(proj + 6 + 3 * i, pe);
        v4_store(over + 6 + 3 * i, radii - v4_abs(pe));
    }
}

// Whether every edge axis (of overlap >= 0, R1 and R2 rotations) loses to
// the best face axis, of overlap best, in box_box's choice: those of
// length len <= sqrt(DX_COLLIDE_EPS) are left out there, and the others
// have o = over / len with o BOX_EDGE_PREFERENCE >= best when (over
// BOX_EDGE_PREFERENCE)^2 >= best^2 len^2 with a margin (BOX_SQUARE_MARGIN,
// relative) for the rounding of both sides and of o (a few units in the
// last place, far less): o >= 0 is not apart either, so box_box's loop
// over the edges would change nothing. Squares of best between
// BOX_SQUARE_RANGE and its inverse stay clear of underflow and overflow.
BOX_INLINE int edges_lose(const dReal over[16], const dReal Rm[3][4], dReal best)
{
    if (!(best > BOX_SQUARE_RANGE && best < 1 / BOX_SQUARE_RANGE)) return 0;
    box_v4 r[3] = { v4_load(Rm[0]), v4_load(Rm[1]), v4_load(Rm[2]) };
    dReal b2 = best * best * (1 + BOX_SQUARE_MARGIN);
    box_v4 eps = { DX_COLLIDE_EPS, DX_COLLIDE_EPS, DX_COLLIDE_EPS, DX_COLLIDE_EPS };
    box_b4 lose = { -1, -1, -1, -1 };
    for (int i = 0; i < 3; i++) {
        box_v4 l2 = r[(i + 1) % 3] * r[(i + 1) % 3] + r[(i + 2) % 3] * r[(i + 2) % 3];
        box_v4 o = v4_load(over + 6 + 3 * i) * BOX_EDGE_PREFERENCE;
        lose &= (l2 <= eps) | (o * o >= b2 * l2);
    }
    return lose[0] & lose[1] & lose[2] & 1;
}

// Box-box. In box 1's frame (axes A_i, half sides a), with box 2's centre T
// and Rm_ij = A_i . B_j, the 15 candidate axes are A_i, B_j and A_i x B_j;
// along each the boxes overlap by (radius1 + radius2 - |T . axis|) / |axis|.
// Any negative overlap separates them (return at once); otherwise the axis
// of least overlap gives the normal: a face axis the face contacts, an edge
// axis one contact between the two edges, as deep as that overlap.
//
// Boxes given by centre, rotation and sides; contacts name o1 and o2 (which
// may be NULL). The contact normal goes to normal_out, the depth along it to
// *depth_out and the axis to *code_out, numbered as ODE 0.16's dBoxBox does:
// 1-3 box 1's faces, 4-6 box 2's, 7 + 3 i + j the edge pair A_i x B_j.
// trusted says that the sides are >= 0 and R1, R2 rotations (orthonormal to
// rounding), as box geoms keep them; dBoxBox's callers may pass anything,
// and its shortcuts check what they need. Inlined in its two callers (no 17
// arguments to pass per pair).
BOX_INLINE int box_box(const dReal *p1, const dReal *R1, const dReal *s1, const dReal *p2,
                       const dReal *R2, const dReal *s2, int trusted, dxGeom *o1, dxGeom *o2,
                       int flags, dContactGeom *out, int skip, dReal normal_out[3],
                       dReal *depth_out, int *code_out)
{
    dReal a[4], b[4];   // s / 2 as s * 0.5 (the same number), fourth lanes 0
    v4_store(a, v4_clear3(v4_load(s1) * (dReal)0.5));
    v4_store(b, v4_clear3(v4_load(s2) * (dReal)0.5));
    dReal d[3] = { p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2] }, T[4];
    // Bounding spheres apart by more than the edge axes' slack: no axis can
    // say the boxes touch.
    dReal ra = dSqrt(dx_dot(a, a)), rb = dSqrt(dx_dot(b, b));
    dReal reach = (ra + rb) * BOX_SPHERE_MARGIN;
    if (dx_dot(d, d) > reach * reach) return 0;
    dReal Rm[3][4], Rc[3][4], Q[3][4], over[16], proj[16];
    box_frame(R1, R2, d, a, b, T, Rm, Rc, Q, over, proj);
    // Any negative overlap parts the boxes, the first in axis order found. An
    // edge axis' slack is <= 0 for boxes of sides >= 0: a pair apart along it
    // has an edge overlap < 0, and only then are the edges tested in turn.
    // (Touching pairs, most of them, find no negative overlap among the 15
    // in four fours first.)
    box_v4 zero = { 0, 0, 0, 0 };
    box_b4 neg = (v4_load(over) < zero) | (v4_load(over + 4) < zero)
                 | (v4_load(over + 8) < zero) | (v4_load(over + 11) < zero);
    dReal lowest = 0;
    if ((neg[0] | neg[1] | neg[2] | neg[3]) & 1) {
        for (int x = 0; x < 6; x++)
            if (over[x] < 0) return 0;
        for (int x = 6; x < 15; x++)
            if (over[x] < lowest) lowest = over[x];
    }
    if (lowest < 0 || (!trusted && !(a[0] >= 0 && a[1] >= 0 && a[2] >= 0 && b[0] >= 0
                                       && b[1] >= 0 && b[2] >= 0))) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                int x = 6 + 3 * i + j;
                if (over[x] < edge_slack(i, j, a, b)) return 0;
            }
        }
    }

    int code = 0, edge = -1;
    for (int x = 1; x < 6; x++)
        if (over[x] < over[code]) code = x;
    // An edge axis of overlap o (>= 0) and length len <= sqrt(2 * 1.25^2)
    // (when every |Rm_ij| <= 1.25, as for rotations) has
    // o / len >= o / 1.77 (to rounding), so with o >= 2 over[code] it
    // cannot win against the faces (its o / len * BOX_EDGE_PREFERENCE stays
    // >= over[code]), nor be apart: it is left out unnormalised.
    dReal best_edge = dInfinity, edge_len = 1;
    int rotations = trusted || rotation_like(R1, R2, Q);
    dReal bound = rotations ? 2 * over[code] : dInfinity;
    int edges = !(rotations && lowest >= 0 && edges_lose(over, Rm, over[code]));
#pragma GCC unroll 3
    for (int i = 0; i < 3 && edges; i++) {
#pragma GCC unroll 3
        for (int j = 0; j < 3; j++) {
            int x = 6 + 3 * i + j, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            if (over[x] >= bound) continue;
            dReal len2 = Rm[i1][j] * Rm[i1][j] + Rm[i2][j] * Rm[i2][j];
            if (len2 <= DX_COLLIDE_EPS) continue;   // parallel edges: the faces cover them
            dReal len = dSqrt(len2), o = over[x] / len;
            if (o < 0) return 0;   // apart after all: a well-defined edge axis
            if (o < best_edge) {
                best_edge = o;
                edge = x;
                edge_len = len;
            }
        }
    }
    dReal best = over[code];
    if (edge >= 0 && best_edge * BOX_EDGE_PREFERENCE < best) {
        best = best_edge;
        code = edge;
    }
    int max = dx_max_contacts(flags);
    dReal normal[3];
    if (code < 6) {
        box_face f;
        f.nf[3] = f.U1[3] = f.U2[3] = 0;
        box_axes ax = { .Rm = Rm, .over = over, .proj = proj };
        dReal sg = proj[code] < 0 ? 1 : -1;
        if (code < 3) {   // face of box 1: normal -sign(T_k) A_k; C, c from Rm and T
            int k = code, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            f.pr = p1, f.Rr = R1, f.hr = a, f.pi = p2, f.Ri = R2, f.hi = b;
            f.rotations = rotations;
            f.hk = a[k], f.h1 = a[k1], f.h2 = a[k2];
            for (int q = 0; q < 3; q++) {
                normal[q] = sg * R1[4 * q + k];
                f.nf[q] = -normal[q];
                f.U1[q] = R1[4 * q + k1];
                f.U2[q] = R1[4 * q + k2];
            }
            f.Cx = v4_load(Rm[k1]);
            f.Cy = v4_load(Rm[k2]);
            f.Cz = -sg * v4_load(Rm[k]);
            // B_m . (p1 - p2): T . Rm[.][m] is it for orthonormal R1
            f.e = trusted ? -v4_load(proj + 3)
                          : -(d[0] * v4_load(R2) + d[1] * v4_load(R2 + 4) + d[2] * v4_load(R2 + 8));
            f.c[0] = T[k1];
            f.c[1] = T[k2];
            f.c[2] = -sg * T[k];
        } else {   // face of box 2: normal sign(B_k . T) B_k; C from Rm
            int k = code - 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            f.pr = p2, f.Rr = R2, f.hr = b, f.pi = p1, f.Ri = R1, f.hi = a;
            f.rotations = rotations;
            f.hk = b[k], f.h1 = b[k1], f.h2 = b[k2];
            for (int q = 0; q < 3; q++) {
                normal[q] = f.nf[q] = sg * R2[4 * q + k];
                f.U1[q] = R2[4 * q + k1];
                f.U2[q] = R2[4 * q + k2];
            }
            f.Cx = v4_load(Rc[k1]);
            f.Cy = v4_load(Rc[k2]);
            f.Cz = sg * v4_load(Rc[k]);
            f.e = v4_load(T);
            f.c[0] = -(d[0] * f.U1[0] + d[1] * f.U1[1] + d[2] * f.U1[2]);
            f.c[1] = -(d[0] * f.U2[0] + d[1] * f.U2[1] + d[2] * f.U2[2]);
            f.c[2] = -(d[0] * f.nf[0] + d[1] * f.nf[1] + d[2] * f.nf[2]);
        }
        // R1^T normal, lane i R1[i] n0 + R1[4 + i] n1 + R1[8 + i] n2 as dx_to_local
        v4_store(ax.nl, v4_load(R1) * normal[0] + v4_load(R1 + 4) * normal[1]
                            + v4_load(R1 + 8) * normal[2]);
        report_axis(normal, best, code, normal_out, depth_out, code_out);
        return box_face_contacts(&f, normal, &ax, code, o1, o2, max, out, skip);
    }
    int i = (code - 6) / 3, j = (code - 6) % 3;
    dReal Ai[3], Bj[3];
    dx_axis(R1, i, Ai);
    dx_axis(R2, j, Bj);
    dReal sg = proj[code] < 0 ? 1 : -1;   // against box 2's offset along A_i x B_j
    normal[0] = sg * (Ai[1] * Bj[2] - Ai[2] * Bj[1]) / edge_len;
    normal[1] = sg * (Ai[2] * Bj[0] - Ai[0] * Bj[2]) / edge_len;
    normal[2] = sg * (Ai[0] * Bj[1] - Ai[1] * Bj[0]) / edge_len;
    dReal pos[3];
    box_edge_point(p1, R1, a, i, p2, R2, b, j, normal, pos);
    dx_put_contact(out, 0, skip, pos, normal, best, o1, o2);
    report_axis(normal, best, code, normal_out, depth_out, code_out);
    return 1;
}

// Box-box of two geoms.
// Static: GCC 12 exports a target_clones function whatever -fvisibility
// says, so dxCollideBoxBox below is a plain call into it.
BOX_CLONES static int box_box_geoms(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out,
                                    int skip)
{
    dReal normal[3], depth;
    int code;
    return box_box(o1->pos, o1->R, ((dxBox *)o1)->side, o2->pos, o2->R, ((dxBox *)o2)->side, 1,
                   o1, o2, flags, out, skip, normal, &depth, &code);
}

int dxCollideBoxBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    return box_box_geoms(o1, o2, flags, out, skip);
}

// ODE 0.16's public box-box test. As there, normal is the direction from box
// 1 into box 2 (the contacts' normal negated) and return_code the axis
// (1-15, 0 if apart); the contacts get positions, depths and normals, with
// g1 and g2 left 0.
// dBoxBox's collider: box_box on anything, no geoms.
BOX_CLONES static int box_box_any(const dReal *p1, const dReal *R1, const dReal *s1,
                                  const dReal *p2, const dReal *R2, const dReal *s2, int flags,
                                  dContactGeom *out, int skip, dReal normal[3], dReal *depth,
                                  int *code)
{
    return box_box(p1, R1, s1, p2, R2, s2, 0, NULL, NULL, flags, out, skip, normal, depth, code);
}

int dBoxBox(const dVector3 p1, const dMatrix3 R1, const dVector3 side1, const dVector3 p2,
            const dMatrix3 R2, const dVector3 side2, dVector3 normal, dReal *depth,
            int *return_code, int flags, dContactGeom *contact, int skip)
{
    DX_CHECK_ARG(p1 && R1 && side1 && p2 && R2 && side2, return 0, "a box argument is NULL");
    DX_CHECK_ARG(normal && depth && return_code, return 0, "an output is NULL");
    DX_CHECK_ARG(contact != NULL, return 0, "contact is NULL");
    DX_CHECK_ARG(skip >= (int)sizeof(dContactGeom), return 0,
                 "skip %d is smaller than sizeof(dContactGeom)", skip);
    dReal n[3] = { 0, 0, 0 }, d = 0;
    int code = -1;
    int count = box_box_any(p1, R1, side1, p2, R2, side2, flags, contact, skip, n, &d, &code);
    *return_code = count > 0 ? code + 1 : 0;
    *depth = count > 0 ? d : 0;
    for (int q = 0; q < 3; q++) normal[q] = -n[q];
    return count;
}

// Box-plane: corner c is below the plane by d - n . c; with the normal in
// the box frame (m), that is the centre's depth - sum +-h_i m_i, deepest
// with the signs against m. Up to 4 corners below the plane, deepest first.
int dxCollideBoxPlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    const dReal *pl = ((dxPlane *)o2)->p, *side = ((dxBox *)o1)->side;
    dReal m[3], e[3];
    dx_to_local(o1->R, pl, m);
    dReal centre = pl[3] - dx_dot(pl, o1->pos);
    for (int i = 0; i < 3; i++) e[i] = side[i] / 2 * m[i];   // corner offsets along n
    if (centre + dFabs(e[0]) + dFabs(e[1]) + dFabs(e[2]) < 0) return 0;
    int max = dx_max_contacts(flags);
    if (max > 4) max = 4;
    dReal dep[8];
    int idx[8], n = 0;
    for (int v = 0; v < 8; v++) {
        dReal dv = centre - ((v & 1) ? e[0] : -e[0]) - ((v & 2) ? e[1] : -e[1])
                   - ((v & 4) ? e[2] : -e[2]);
        if (dv < 0) continue;
        int k = n++;   // insertion, deepest first
        for (; k > 0 && dep[k - 1] < dv; k--) {
            dep[k] = dep[k - 1];
            idx[k] = idx[k - 1];
        }
        dep[k] = dv;
        idx[k] = v;
    }
    if (n > max) n = max;
    for (int k = 0; k < n; k++) {
        dReal local[3], pos[3];
        for (int i = 0; i < 3; i++) local[i] = (idx[k] >> i & 1) ? side[i] / 2 : -side[i] / 2;
        dx_point_to_world(o1->R, o1->pos, local, pos);
        dx_put_contact(c, k, skip, pos, pl, dep[k], o1, o2);
    }
    return n;
}
