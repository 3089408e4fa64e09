// SPDX-License-Identifier: BSD-3-Clause
//
// boxbox_slow.h -- a straightforward box-box collider for test_boxbox_fast:
// the loops over the 15 axes, the general polygon clipper and the full
// clearance pass written plainly (the collider as it was before the fast
// paths of backends/native/collide_box.c), so that the fast one can be
// checked against it contact for contact.

#ifndef BOXBOX_SLOW_H
#define BOXBOX_SLOW_H

#include <ode/ode.h>
#include <math.h>
#include <string.h>

#ifdef dSINGLE
#define SLOW_EPS ((dReal)1e-5)
#else
#define SLOW_EPS ((dReal)1e-9)
#endif

static inline dReal slow_dot(const dReal *a, const dReal *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline dReal slow_clamp(dReal x, dReal lo, dReal hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

// Column i of R (ODE's 3x4 layout): the box's axis i in the world frame.
static inline void slow_axis(const dReal *R, int i, dReal out[3])
{
    out[0] = R[i];
    out[1] = R[4 + i];
    out[2] = R[8 + i];
}

// R^T v.
static inline void slow_to_local(const dReal *R, const dReal *v, dReal out[3])
{
    for (int i = 0; i < 3; i++) out[i] = R[i] * v[0] + R[4 + i] * v[1] + R[8 + i] * v[2];
}

// One contact, stored at index i of an array of stride skip.
static inline void slow_put_contact(dContactGeom *c, int i, int skip, const dReal pos[3],
                                    const dReal normal[3], dReal depth, dGeomID o1, dGeomID o2)
{
    dContactGeom *k = (dContactGeom *)((char *)c + (size_t)i * (size_t)skip);
    for (int j = 0; j < 3; j++) {
        k->pos[j] = pos[j];
        k->normal[j] = normal[j];
    }
    k->depth = depth;
    k->g1 = o1;
    k->g2 = o2;
    k->side1 = k->side2 = -1;
}


// The edge axes of (nearly) parallel edges are (nearly) zero vectors: their
// separation test allows this margin (relative to the box sizes) for rounding.
#define BOX_AXIS_SLACK ((dReal)1e-5)
// An edge axis wins only if its penetration is shorter than the best face
// axis' by this factor: face contacts give a stable polygon, so they are
// preferred when the two are about as deep.
#define BOX_EDGE_PREFERENCE ((dReal)1.05)
// Boxes whose centres are farther apart than this times the sum of their
// half diagonals are apart without a look at their axes.
#define BOX_SPHERE_MARGIN ((dReal)1.001)
// A point of the clipped contact polygon in the reference face's frame.
typedef struct clip_point {
    dReal x, y, depth;
    dReal t;   // pos is this far from the incident point along nf
} clip_point;

// Keep the part of poly (n points) with sg * coordinate(axis) <= h in out;
// returns the new count (at most n + 1 for a convex polygon, capped at 16).
// Points on the line are kept once and not duplicated by the crossing test.
static int clip_half(const clip_point *poly, int n, int axis, dReal sg, dReal h, clip_point *out)
{
    int m = 0;
    for (int i = 0; i < n && m < 16; i++) {
        const clip_point *p = &poly[i], *q = &poly[(i + 1) % n];
        dReal dp = sg * (axis ? p->y : p->x) - h, dq = sg * (axis ? q->y : q->x) - h;
        if (dp <= 0) out[m++] = *p;
        if (m < 16 && ((dp < 0 && dq > 0) || (dp > 0 && dq < 0))) {
            dReal f = dp / (dp - dq);
            out[m].x = p->x + f * (q->x - p->x);
            out[m].y = p->y + f * (q->y - p->y);
            out[m].depth = p->depth + f * (q->depth - p->depth);
            m++;
        }
    }
    return m;
}

// Whether every point of poly (n points) has sg * coordinate(axis) <= h,
// the test clip_half keeps a point by.
static int all_inside(const clip_point *poly, int n, int axis, dReal sg, dReal h)
{
    for (int i = 0; i < n; i++)
        if (!(sg * (axis ? poly[i].y : poly[i].x) - h <= 0)) return 0;
    return 1;
}

// Choose max of the n points (n > max) to keep, in place: the deepest, then
// each time the point farthest from those already chosen, so the kept
// points spread over the polygon.
static void cull_points(clip_point *pts, int n, int max)
{
    for (int k = 1; k < max; k++) {
        int best = k;
        dReal best_d = -1;
        for (int i = k; i < n; i++) {
            dReal nearest = dInfinity;
            for (int j = 0; j < k; j++) {
                dReal dx = pts[i].x - pts[j].x, dy = pts[i].y - pts[j].y;
                dReal d2 = dx * dx + dy * dy;
                if (d2 < nearest) nearest = d2;
            }
            if (nearest > best_d) {
                best_d = nearest;
                best = i;
            }
        }
        clip_point t = pts[k];
        pts[k] = pts[best];
        pts[best] = t;
    }
}

// Clip [*t0, *t1] to where p + t d lies in the box (pos, R, half sides h).
static void clip_line_to_box(const dReal p[3], const dReal d[3], const dReal *pos,
                             const dReal *R, const dReal h[3], dReal *t0, dReal *t1)
{
    dReal rel[3] = { p[0] - pos[0], p[1] - pos[1], p[2] - pos[2] }, q[3], v[3];
    slow_to_local(R, rel, q);
    slow_to_local(R, d, v);
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
// hi). The incident box's face most against nf is clipped to the reference
// face's rectangle (in the frame U1, U2 of that face, relative to pr); the
// clipped polygon is written to a (at most 16 points), its count returned.
// dots gets the incident axes' cosines with nf.
static int box_clip_incident(const dReal hr[3], int k, const dReal nf[3], const dReal U1[3],
                             const dReal U2[3], const dReal rel[3], const dReal *Ri,
                             const dReal hi[3], dReal dots[3], clip_point a[16])
{
    dReal B[3][3];
    int j = 0;
    for (int m = 0; m < 3; m++) {
        slow_axis(Ri, m, B[m]);
        dots[m] = slow_dot(B[m], nf);
        if (dFabs(dots[m]) > dFabs(dots[j])) j = m;
    }
    int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    // The incident face's centre (rel + sgn hi_j B_j) and half edges
    // (hi B_j1, hi B_j2) in the reference face's frame (x, y, height).
    dReal sgn = dots[j] > 0 ? -hi[j] : hi[j];
    dReal cx = slow_dot(rel, U1) + sgn * slow_dot(B[j], U1);
    dReal cy = slow_dot(rel, U2) + sgn * slow_dot(B[j], U2);
    dReal cz = slow_dot(rel, nf) + sgn * dots[j];
    dReal ux = hi[j1] * slow_dot(B[j1], U1), uy = hi[j1] * slow_dot(B[j1], U2);
    dReal uz = hi[j1] * dots[j1];
    dReal vx = hi[j2] * slow_dot(B[j2], U1), vy = hi[j2] * slow_dot(B[j2], U2);
    dReal vz = hi[j2] * dots[j2];
    static const dReal corner[4][2] = { { 1, 1 }, { -1, 1 }, { -1, -1 }, { 1, -1 } };
    for (int v = 0; v < 4; v++) {
        dReal s = corner[v][0], t = corner[v][1];
        a[v].x = cx + s * ux + t * vx;
        a[v].y = cy + s * uy + t * vy;
        a[v].depth = hr[k] - (cz + s * uz + t * vz);
    }
    clip_point b[16], *cur = a, *spare = b;
    int n = 4;
    for (int side = 0; side < 4; side++) {
        int axis = side / 2;
        dReal sg = side % 2 ? -1 : 1, h = hr[(k + 1 + axis) % 3];
        if (all_inside(cur, n, axis, sg, h)) continue;   // clip_half would copy
        n = clip_half(cur, n, axis, sg, h, spare);
        clip_point *t = cur;
        cur = spare;
        spare = t;
    }
    if (cur != a) memcpy(a, cur, (size_t)n * sizeof *a);
    return n;
}

// Keep (in place) the clipped points below the reference face whose line
// P + t nf (P the incident point) runs inside both boxes: t in
// [depth - 2 hr_k, depth] for the reference box, [0, exit] for the incident
// one (rel = pr - pi); pos will be the middle of that stretch (t). Deep
// overlaps can clip points past the far side of a thin reference box: they
// are in neither box and dropped. The deepest is moved first.
static int box_keep_overlapping(clip_point *a, int n, const dReal hr[3], int k,
                                const dReal nf[3], const dReal U1[3], const dReal U2[3],
                                const dReal rel[3], const dReal *Ri, const dReal hi[3],
                                const dReal dots[3])
{
    int kept = 0, deepest = 0;
    for (int i = 0; i < n; i++) {
        dReal depth = a[i].depth;
        if (depth < 0) continue;
        dReal q[3], up = hr[k] - depth, exit = dInfinity;
        for (int m = 0; m < 3; m++) q[m] = rel[m] + a[i].x * U1[m] + a[i].y * U2[m] + up * nf[m];
        for (int m = 0; m < 3; m++) {
            if (dots[m] == 0) continue;
            dReal from = Ri[m] * q[0] + Ri[4 + m] * q[1] + Ri[8 + m] * q[2];
            dReal t = ((dots[m] > 0 ? hi[m] : -hi[m]) - from) / dots[m];
            if (t < exit) exit = t;
        }
        if (exit < 0) exit = 0;   // clipped points lie on the incident face: rounding
        dReal lo = depth - 2 * hr[k] > 0 ? depth - 2 * hr[k] : 0;
        dReal top = exit < depth ? exit : depth;
        if (top < lo) continue;
        a[kept] = a[i];
        a[kept].t = (lo + top) / 2;
        if (a[kept].depth > a[deepest].depth) deepest = kept;
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
// box_box's Rm, overlaps and projections.
typedef struct box_axes {
    dReal nl[3];
    const dReal (*Rm)[3];
    const dReal *over, *proj;
} box_axes;

// The ray's exit through the faces of axis x, whose direction has s = m . n
// (dInfinity if it runs along them).
static inline dReal exit_along(const box_axes *ax, int x, dReal s)
{
    if (s == 0) return dInfinity;
    dReal radii = ax->over[x] + dFabs(ax->proj[x]);
    return ((s > 0 ? ax->proj[x] : -ax->proj[x]) + radii) / dFabs(s);
}

// m . n for face axis x (0-5).
static inline dReal face_dot(const box_axes *ax, int x)
{
    const dReal *nl = ax->nl, (*Rm)[3] = ax->Rm;
    return x < 3 ? nl[x] : Rm[0][x - 3] * nl[0] + Rm[1][x - 3] * nl[1] + Rm[2][x - 3] * nl[2];
}

// How far box 1 must move along the unit normal (nl, in box 1's frame) to
// clear box 2: box 1 moved by t n meets box 2 while t n lies in the
// Minkowski difference box 2 - box 1, whose faces are normal to the 15
// axes m; the ray t n leaves it at the least h(m) / (m . n) over the axes
// facing n, h(m) = m . (p2 - p1) + radius1(m) + radius2(m) its support. The
// ratio does not depend on the length of m, so axes stay unnormalised.
static dReal box_clearance(const box_axes *ax)
{
    const dReal *nl = ax->nl, (*Rm)[3] = ax->Rm;
    dReal best = dInfinity;
    for (int x = 0; x < 6; x++) {
        dReal t = exit_along(ax, x, face_dot(ax, x));
        if (t < best) best = t;
    }
    for (int i = 0; i < 3; i++) {
        int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; j++) {
            if (Rm[i1][j] * Rm[i1][j] + Rm[i2][j] * Rm[i2][j] <= SLOW_EPS) continue;
            dReal s = Rm[i1][j] * nl[i2] - Rm[i2][j] * nl[i1];   // (e_i x Rm[.][j]) . n
            dReal t = exit_along(ax, 6 + 3 * i + j, s);
            if (t < best) best = t;
        }
    }
    return best;
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
static int box_face_contacts(const dReal *pr, const dReal *Rr, const dReal hr[3], int k,
                             const dReal nf[3], const dReal *pi, const dReal *Ri,
                             const dReal hi[3], const dReal normal[3], const box_axes *ax,
                             int code, dGeomID o1, dGeomID o2, int max, dContactGeom *out,
                             int skip)
{
    dReal U1[3], U2[3], dots[3], rel[3] = { pi[0] - pr[0], pi[1] - pr[1], pi[2] - pr[2] };
    slow_axis(Rr, (k + 1) % 3, U1);
    slow_axis(Rr, (k + 2) % 3, U2);
    clip_point a[16];
    int n = box_clip_incident(hr, k, nf, U1, U2, rel, Ri, hi, dots, a);
    for (int i = 0; i < 3; i++) rel[i] = -rel[i];
    int kept = box_keep_overlapping(a, n, hr, k, nf, U1, U2, rel, Ri, hi, dots);
    if (kept == 0) {   // the separating axis says they overlap: find a point
        dReal pos[3];
        box_overlap_point(pr, Rr, hr, pi, Ri, hi, pos);
        slow_put_contact(out, 0, skip, pos, normal, box_clearance(ax), o1, o2);
        return 1;
    }
    dReal clear = a[0].depth < exit_along(ax, code, face_dot(ax, code)) ? box_clearance(ax)
                                                                       : a[0].depth;
    if (kept > max) {
        cull_points(a, kept, max);
        kept = max;
    }
    for (int c = 0; c < kept; c++) {
        dReal pos[3], up = hr[k] - a[c].depth + a[c].t;
        for (int i = 0; i < 3; i++) pos[i] = pr[i] + a[c].x * U1[i] + a[c].y * U2[i] + up * nf[i];
        dReal depth = c == 0 && a[0].depth < clear ? clear : a[c].depth;
        slow_put_contact(out, c, skip, pos, normal, depth, o1, o2);
    }
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
            slow_axis(R1, m, ax);
            dReal s = slow_dot(ax, n) > 0 ? -h1[m] : h1[m];
            for (int q = 0; q < 3; q++) pa[q] += s * ax[q];
        }
        if (m != j) {   // box 2 towards box 1: along n
            slow_axis(R2, m, ax);
            dReal s = slow_dot(ax, n) > 0 ? h2[m] : -h2[m];
            for (int q = 0; q < 3; q++) pb[q] += s * ax[q];
        }
    }
    slow_axis(R1, i, u);
    slow_axis(R2, j, v);
    dReal w[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
    dReal b = slow_dot(u, v), d = slow_dot(u, w), e = slow_dot(v, w), denom = 1 - b * b;
    dReal s = slow_clamp((b * e - d) / denom, -h1[i], h1[i]);
    dReal t = slow_clamp((e - b * d) / denom, -h2[j], h2[j]);
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

// Overlap of the boxes along face axis x (0-2: A_x, 3-5: B_(x-3)), and
// box 2's offset along it (proj); box_box's names.
static inline dReal face_overlap(int x, const dReal a[3], const dReal b[3], const dReal T[3],
                                 const dReal Rm[3][3], const dReal Q[3][3], dReal *proj)
{
    if (x < 3) {
        *proj = T[x];
        return a[x] + b[0] * Q[x][0] + b[1] * Q[x][1] + b[2] * Q[x][2] - dFabs(T[x]);
    }
    int j = x - 3;
    *proj = T[0] * Rm[0][j] + T[1] * Rm[1][j] + T[2] * Rm[2][j];
    return a[0] * Q[0][j] + a[1] * Q[1][j] + a[2] * Q[2][j] + b[j] - dFabs(*proj);
}

// The same, unnormalised, along edge axis 6 + 3 i + j (A_i x B_j, in box
// 1's frame e_i x Rm[.][j]).
static inline dReal edge_overlap(int i, int j, const dReal a[3], const dReal b[3],
                                 const dReal T[3], const dReal Rm[3][3], const dReal Q[3][3],
                                 dReal *proj)
{
    int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    *proj = T[i2] * Rm[i1][j] - T[i1] * Rm[i2][j];
    dReal radii = a[i1] * Q[i2][j] + a[i2] * Q[i1][j] + b[j1] * Q[i][j2] + b[j2] * Q[i][j1];
    return radii - dFabs(*proj);
}

// An edge axis' length may vanish, so its overlap separates only below this
// margin beyond rounding (or below 0 where the axis is well defined).
static inline dReal edge_slack(int i, int j, const dReal a[3], const dReal b[3])
{
    return -BOX_AXIS_SLACK * (a[(i + 1) % 3] + a[(i + 2) % 3] + b[(j + 1) % 3] + b[(j + 2) % 3]);
}

// Box-box, every step taken in full: the 15 axes' overlaps (any negative one
// parts the boxes), the axis of least overlap (an edge axis only if shorter
// than the best face axis by BOX_EDGE_PREFERENCE), then the face contacts or
// the one edge contact. Returns the contact count; the contacts' normal,
// the depth along it and the axis (0-14, as box_box numbers them) go to
// normal_out, *depth_out and *code_out.
static int slow_box_box(const dReal *p1, const dReal *R1, const dReal *s1, const dReal *p2,
                        const dReal *R2, const dReal *s2, dGeomID o1, dGeomID o2, int flags,
                        dContactGeom *out, int skip, dReal normal_out[3], dReal *depth_out,
                        int *code_out)
{
    const dReal a[3] = { s1[0] / 2, s1[1] / 2, s1[2] / 2 };
    const dReal b[3] = { s2[0] / 2, s2[1] / 2, s2[2] / 2 };
    dReal d[3] = { p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2] }, T[3];
    dReal ra = dSqrt(slow_dot(a, a)), rb = dSqrt(slow_dot(b, b));
    dReal reach = (ra + rb) * BOX_SPHERE_MARGIN;
    if (slow_dot(d, d) > reach * reach) return 0;
    slow_to_local(R1, d, T);
    dReal Rm[3][3], Q[3][3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            Rm[i][j] = R1[i] * R2[j] + R1[4 + i] * R2[4 + j] + R1[8 + i] * R2[8 + j];
            Q[i][j] = dFabs(Rm[i][j]);
        }
    }
    dReal over[15], proj[15];
    for (int x = 0; x < 6; x++) {
        over[x] = face_overlap(x, a, b, T, Rm, Q, &proj[x]);
        if (over[x] < 0) return 0;
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            int x = 6 + 3 * i + j;
            over[x] = edge_overlap(i, j, a, b, T, Rm, Q, &proj[x]);
            if (over[x] < edge_slack(i, j, a, b)) return 0;
        }
    }
    int code = 0, edge = -1;
    for (int x = 1; x < 6; x++)
        if (over[x] < over[code]) code = x;
    dReal best_edge = dInfinity, edge_len = 1;
    for (int x = 6; x < 15; x++) {
        int i = (x - 6) / 3, j = (x - 6) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        dReal len2 = Rm[i1][j] * Rm[i1][j] + Rm[i2][j] * Rm[i2][j];
        if (len2 <= SLOW_EPS) continue;
        dReal len = dSqrt(len2), o = over[x] / len;
        if (o < 0) return 0;
        if (o < best_edge) {
            best_edge = o;
            edge = x;
            edge_len = len;
        }
    }
    dReal best = over[code];
    if (edge >= 0 && best_edge * BOX_EDGE_PREFERENCE < best) {
        best = best_edge;
        code = edge;
    }
    int max = flags & 0xffff;
    dReal normal[3], nf[3];
    if (code < 6) {
        int k = code < 3 ? code : code - 3;
        const dReal *R = code < 3 ? R1 : R2;
        dReal sg = proj[code] < 0 ? 1 : -1;
        for (int q = 0; q < 3; q++) {
            normal[q] = sg * R[4 * q + k];
            nf[q] = code < 3 ? -normal[q] : normal[q];
        }
        box_axes ax = { .Rm = Rm, .over = over, .proj = proj };
        slow_to_local(R1, normal, ax.nl);
        report_axis(normal, best, code, normal_out, depth_out, code_out);
        if (code < 3)
            return box_face_contacts(p1, R1, a, k, nf, p2, R2, b, normal, &ax, code, o1, o2, max,
                                     out, skip);
        return box_face_contacts(p2, R2, b, k, nf, p1, R1, a, normal, &ax, code, o1, o2, max,
                                 out, skip);
    }
    int i = (code - 6) / 3, j = (code - 6) % 3;
    dReal Ai[3], Bj[3];
    slow_axis(R1, i, Ai);
    slow_axis(R2, j, Bj);
    dReal sg = proj[code] < 0 ? 1 : -1;
    normal[0] = sg * (Ai[1] * Bj[2] - Ai[2] * Bj[1]) / edge_len;
    normal[1] = sg * (Ai[2] * Bj[0] - Ai[0] * Bj[2]) / edge_len;
    normal[2] = sg * (Ai[0] * Bj[1] - Ai[1] * Bj[0]) / edge_len;
    dReal pos[3];
    box_edge_point(p1, R1, a, i, p2, R2, b, j, normal, pos);
    slow_put_contact(out, 0, skip, pos, normal, best, o1, o2);
    report_axis(normal, best, code, normal_out, depth_out, code_out);
    return 1;
}

#endif
