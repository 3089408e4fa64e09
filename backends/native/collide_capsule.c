// SPDX-License-Identifier: BSD-3-Clause
//
// collide_capsule.c -- the capsule's analytic colliders (against a capsule,
// a box and a plane) and the cylinder against a plane. A capsule is the set
// of points within its radius of its axis segment, so most of this is
// closest points to that segment.

#include "collide_math.h"

// A capsule's axis segment (around its position): unit axis and half length.
static void capsule_segment(const dxGeom *g, dReal z[3], dReal *half)
{
    dx_axis(g->R, 2, z);
    *half = ((const dxCapsule *)g)->length / 2;
}

// Sort contacts 0..n-1 (stride skip) deepest first (n is small).
static void sort_by_depth(dContactGeom *c, int n, int skip)
{
    for (int i = 1; i < n; i++) {
        for (int j = i; j > 0; j--) {
            dContactGeom *a = dxContactAt(c, j - 1, skip), *b = dxContactAt(c, j, skip);
            if (a->depth >= b->depth) break;
            dContactGeom t = *a;
            *a = *b;
            *b = t;
        }
    }
}

// ---- capsule-capsule ------------------------------------------------------

// Below this sin^2 of the angle between the axes (about 6 degrees) the
// capsules count as lying along each other and also touch at the ends of
// their overlap, so that a capsule lying on another rests on two points.
#define CAPSULE_PARALLEL_SIN2 ((dReal)0.01)

// The contact of the balls at A's axis point s and the nearest point of B's
// axis; returns 0 if they are apart.
static int capsule_ball_at(const dReal cA[3], const dReal uA[3], dReal rA, const dReal cB[3],
                           const dReal uB[3], dReal hB, dReal rB, dReal s, const dReal fallback[3],
                           dReal pos[3], dReal n[3], dReal *depth)
{
    dReal pa[3], pb[3], d[3];
    for (int i = 0; i < 3; i++) {
        pa[i] = cA[i] + s * uA[i];
        d[i] = pa[i] - cB[i];
    }
    dReal t = dx_clamp(dx_dot(d, uB), -hB, hB);
    for (int i = 0; i < 3; i++) pb[i] = cB[i] + t * uB[i];
    return dx_ball_contact(pa, rA, pb, rB, fallback, pos, n, depth);
}

// Capsule-capsule: the balls at the closest points of the axis segments
// (the deepest contact, first); nearly parallel capsules also touch at the
// two ends of the part of A's axis that lies alongside B's.
int dxCollideCapsuleCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    const dReal rA = ((dxCapsule *)o1)->radius, rB = ((dxCapsule *)o2)->radius;
    dReal uA[3], uB[3], hA, hB, s, t;
    capsule_segment(o1, uA, &hA);
    capsule_segment(o2, uB, &hB);
    dx_closest_segments(o1->pos, uA, hA, o2->pos, uB, hB, &s, &t);
    dReal pa[3], pb[3], d[3];
    for (int i = 0; i < 3; i++) {
        pa[i] = o1->pos[i] + s * uA[i];
        pb[i] = o2->pos[i] + t * uB[i];
        d[i] = pa[i] - pb[i];
    }
    if (dx_dot(d, d) > (rA + rB) * (rA + rB)) return 0;
    // Axes crossing: leave along their common perpendicular, else across A.
    dReal fallback[3] = { uA[1] * uB[2] - uA[2] * uB[1], uA[2] * uB[0] - uA[0] * uB[2],
                          uA[0] * uB[1] - uA[1] * uB[0] };
    dReal cross2 = dx_dot(fallback, fallback);
    if (cross2 > DX_COLLIDE_EPS) {
        dReal inv = 1 / dSqrt(cross2);
        for (int i = 0; i < 3; i++) fallback[i] *= inv;
    } else {
        dx_perpendicular(uA, fallback);
    }
    dReal pos[3], n[3], depth;
    if (!dx_ball_contact(pa, rA, pb, rB, fallback, pos, n, &depth)) return 0;
    dx_put_contact(c, 0, skip, pos, n, depth, o1, o2);
    int count = 1, max = dx_max_contacts(flags);
    if (max < 2 || cross2 >= CAPSULE_PARALLEL_SIN2) return count;

    // B's axis projected on A's: [mid - half, mid + half], clipped to A's.
    dReal rel[3] = { o2->pos[0] - o1->pos[0], o2->pos[1] - o1->pos[1], o2->pos[2] - o1->pos[2] };
    dReal mid = dx_dot(rel, uA), half = hB * dFabs(dx_dot(uA, uB));
    dReal lo = mid - half > -hA ? mid - half : -hA, hi = mid + half < hA ? mid + half : hA;
    dReal same = DX_COLLIDE_EPS * (hA + hB + rA + rB);
    if (hi - lo <= same) return count;
    const dReal ends[2] = { lo, hi };
    for (int e = 0; e < 2 && count < max; e++) {
        if (dFabs(ends[e] - s) <= same) continue;   // already the first contact
        if (capsule_ball_at(o1->pos, uA, rA, o2->pos, uB, hB, rB, ends[e], fallback, pos, n,
                            &depth))
            dx_put_contact(c, count++, skip, pos, n, depth, o1, o2);
    }
    sort_by_depth(c, count, skip);
    return count;
}

// ---- capsule-box ------------------------------------------------------------

// Squared distance from the point p to the box of half sides h (its frame).
static dReal point_box_dist2(const dReal p[3], const dReal h[3])
{
    dReal f = 0;
    for (int i = 0; i < 3; i++) {
        dReal e = p[i] > h[i] ? p[i] - h[i] : p[i] < -h[i] ? p[i] + h[i] : 0;
        f += e * e;
    }
    return f;
}

// The parameter t in [-hl, hl] of the segment point c + t z nearest to the
// box of half sides h (all in the box frame); its squared distance in *f.
// The squared distance is convex and piecewise quadratic in t, with breaks
// where a coordinate crosses a face plane: minimise exactly on each piece.
static dReal segment_box_closest(const dReal c[3], const dReal z[3], dReal hl, const dReal h[3],
                                 dReal *f)
{
    dReal bp[8];
    int nb = 0;
    bp[nb++] = -hl;
    for (int i = 0; i < 3; i++) {
        if (z[i] == 0) continue;
        for (int sg = -1; sg <= 1; sg += 2) {
            dReal t = (sg * h[i] - c[i]) / z[i];
            if (t > -hl && t < hl) {
                int j = nb++;
                for (; j > 1 && bp[j - 1] > t; j--) bp[j] = bp[j - 1];   // keep sorted
                bp[j] = t;
            }
        }
    }
    bp[nb++] = hl;
    dReal best_t = -hl, best_f = dInfinity;
    for (int k = 0; k + 1 < nb; k++) {
        dReal t0 = bp[k], t1 = bp[k + 1], tm = (t0 + t1) / 2, a = 0, b = 0;
        for (int i = 0; i < 3; i++) {
            dReal x = c[i] + tm * z[i];
            dReal e = x > h[i] ? c[i] - h[i] : x < -h[i] ? c[i] + h[i] : 0;
            if (e == 0 && x <= h[i] && x >= -h[i]) continue;
            a += z[i] * z[i];   // this piece's sum (e + t z)^2 has slope 2 (a t + b)
            b += z[i] * e;
        }
        dReal t = a > 0 ? dx_clamp(-b / a, t0, t1) : tm;   // a = 0: inside all the way
        dReal p[3] = { c[0] + t * z[0], c[1] + t * z[1], c[2] + t * z[2] };
        dReal fp = point_box_dist2(p, h);
        if (fp < best_f) {
            best_f = fp;
            best_t = t;
        }
    }
    *f = best_f;
    return best_t;
}

// Clip [*t0, *t1] to where c + t z satisfies |x_i| <= h_i for the axes i
// with use[i]; returns 0 if nothing is left.
static int clip_segment_to_slabs(const dReal c[3], const dReal z[3], const dReal h[3],
                                 const int use[3], dReal *t0, dReal *t1)
{
    for (int i = 0; i < 3; i++) {
        if (!use[i]) continue;
        if (z[i] == 0) {
            if (c[i] > h[i] || c[i] < -h[i]) return 0;
            continue;
        }
        dReal a = (-h[i] - c[i]) / z[i], b = (h[i] - c[i]) / z[i];
        if (a > b) {
            dReal x = a;
            a = b;
            b = x;
        }
        if (a > *t0) *t0 = a;
        if (b < *t1) *t1 = b;
    }
    return *t0 <= *t1;
}

// A capsule against the box face of axis k on side sg: contacts at both ends
// of the stretch of the axis within the face's other two slabs (a lying
// capsule rests on two points), or when the axis passes through the box
// (`through`) within the box; pos in the middle of the overlap of the ball
// there and the box along the normal. Depth r - height above the face of that
// end; when through, of the lower of it and the axis end beyond it, so that
// the deepest contact carries the separating translation even if the axis'
// lowest point is off the face. t_near (a point of the stretch) stands in if
// rounding empties it.
static int capsule_box_face(dxGeom *o1, dxGeom *o2, const dReal c[3], const dReal z[3],
                            dReal hl, dReal r, const dReal h[3], int k, dReal sg, dReal t_near,
                            int through, int max, dContactGeom *out, int skip)
{
    const int use[3] = { k != 0 || through, k != 1 || through, k != 2 || through };
    dReal t0 = -hl, t1 = hl;
    if (!clip_segment_to_slabs(c, z, h, use, &t0, &t1)) t0 = t1 = t_near;
    dReal same = DX_COLLIDE_EPS * (hl + r + h[0] + h[1] + h[2]);
    int ends = t1 - t0 > same ? 2 : 1;
    dReal nl[3] = { 0, 0, 0 }, n[3];
    nl[k] = sg;
    dx_to_world(o2->R, nl, n);
    // Heights above the face: of the stretch's ends and of the axis' ends.
    dReal h0 = sg * (c[k] + t0 * z[k]) - h[k], h1 = sg * (c[k] + t1 * z[k]) - h[k];
    dReal e0 = sg * (c[k] - hl * z[k]) - h[k], e1 = sg * (c[k] + hl * z[k]) - h[k];
    dReal low[2] = { h0, h1 };
    if (through) {
        if (e0 < low[0]) low[0] = e0;
        if (e1 < low[1]) low[1] = e1;
        if (ends == 1 && low[1] < low[0]) low[0] = low[1];
    }
    const dReal at[2] = { t0, t1 }, height[2] = { h0, h1 };
    int order[2] = { 0, 1 };   // deepest first
    if (ends == 2 && low[1] < low[0]) {
        order[0] = 1;
        order[1] = 0;
    }
    int count = 0;
    for (int o = 0; o < ends && count < max; o++) {
        int e = order[o];
        dReal depth = r - low[e];
        if (depth < 0) break;
        dReal p[3];
        for (int i = 0; i < 3; i++) p[i] = c[i] + at[e] * z[i];
        // The line through p along the normal: the ball at p covers [-r, r]
        // of it, the box [-height - 2 h_k, -height]; pos in the middle of both.
        dReal lo = -height[e] - 2 * h[k] > -r ? -height[e] - 2 * h[k] : -r;
        dReal hi = -height[e] < r ? -height[e] : r;
        if (lo <= hi) p[k] += sg * (lo + hi) / 2;
        for (int i = 0; i < 3; i++) p[i] = dx_clamp(p[i], -h[i], h[i]);
        dReal pos[3];
        dx_point_to_world(o2->R, o2->pos, p, pos);
        dx_put_contact(out, count++, skip, pos, n, depth, o1, o2);
    }
    return count;
}

// The capsule's axis passes through the box: the minimum translation is
// r + the axis' least overlap over the separating axes of a segment and a
// box (the 3 face normals and the axis crossed with each box edge). A face
// gives the face contacts; a cross axis one contact in the middle of the
// part of the axis inside the box.
static int capsule_box_penetrating(dxGeom *o1, dxGeom *o2, const dReal c[3], const dReal z[3],
                                   dReal hl, dReal r, const dReal h[3], dReal t_in, int max,
                                   dContactGeom *out, int skip)
{
    int face = 0;
    dReal best = dInfinity;
    for (int i = 0; i < 3; i++) {
        dReal overlap = h[i] + hl * dFabs(z[i]) - dFabs(c[i]);
        if (overlap < best) {
            best = overlap;
            face = i;
        }
    }
    dReal best_u[3] = { 0, 0, 0 };
    int cross = 0;
    for (int j = 0; j < 3; j++) {
        // u = z x e_j
        dReal u[3] = { j == 0 ? 0 : j == 1 ? -z[2] : z[1], j == 0 ? z[2] : j == 1 ? 0 : -z[0],
                       j == 0 ? -z[1] : j == 1 ? z[0] : 0 };
        dReal len2 = dx_dot(u, u);
        if (len2 <= DX_COLLIDE_EPS) continue;   // axis along e_j: the faces cover it
        dReal inv = 1 / dSqrt(len2);
        for (int i = 0; i < 3; i++) u[i] *= inv;
        dReal overlap = h[0] * dFabs(u[0]) + h[1] * dFabs(u[1]) + h[2] * dFabs(u[2])
                        - dFabs(dx_dot(c, u));
        if (overlap < best * (1 - DX_COLLIDE_EPS)) {   // ties go to the faces
            best = overlap;
            cross = 1;
            for (int i = 0; i < 3; i++) best_u[i] = dx_dot(c, u) < 0 ? -u[i] : u[i];
        }
    }
    if (!cross)
        return capsule_box_face(o1, o2, c, z, hl, r, h, face, c[face] < 0 ? -1 : 1, t_in, 1,
                                max, out, skip);
    const int all[3] = { 1, 1, 1 };
    dReal t0 = -hl, t1 = hl;
    if (!clip_segment_to_slabs(c, z, h, all, &t0, &t1)) t0 = t1 = t_in;
    dReal tm = (t0 + t1) / 2, p[3], pos[3], n[3];
    for (int i = 0; i < 3; i++) p[i] = c[i] + tm * z[i];
    dx_point_to_world(o2->R, o2->pos, p, pos);
    dx_to_world(o2->R, best_u, n);
    dx_put_contact(out, 0, skip, pos, n, r + best, o1, o2);
    return 1;
}

// Capsule-box, in the box frame: the point of the axis segment nearest to
// the box. Apart by less than r: a contact at the nearest box point, or the
// face contacts when that point is off a face (not an edge or corner).
// Axis through the box: capsule_box_penetrating.
int dxCollideCapsuleBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *out, int skip)
{
    const dReal r = ((dxCapsule *)o1)->radius;
    const dReal *side = ((dxBox *)o2)->side;
    const dReal h[3] = { side[0] / 2, side[1] / 2, side[2] / 2 };
    dReal zw[3], hl, d[3], c[3], z[3];
    capsule_segment(o1, zw, &hl);
    for (int i = 0; i < 3; i++) d[i] = o1->pos[i] - o2->pos[i];
    dx_to_local(o2->R, d, c);
    dx_to_local(o2->R, zw, z);
    for (int i = 0; i < 3; i++)   // apart along a face normal
        if (dFabs(c[i]) > h[i] + hl * dFabs(z[i]) + r) return 0;
    dReal f, t = segment_box_closest(c, z, hl, h, &f);
    if (f > r * r) return 0;
    int max = dx_max_contacts(flags);
    if (f == 0) return capsule_box_penetrating(o1, o2, c, z, hl, r, h, t, max, out, skip);

    dReal p[3], q[3];
    int outside = 0, k = 0;
    for (int i = 0; i < 3; i++) {
        p[i] = c[i] + t * z[i];
        q[i] = dx_clamp(p[i], -h[i], h[i]);
        if (q[i] != p[i]) {
            outside++;
            k = i;
        }
    }
    if (outside == 1)
        return capsule_box_face(o1, o2, c, z, hl, r, h, k, p[k] < 0 ? -1 : 1, t, 0, max,
                                out, skip);
    dReal dist = dSqrt(f), nl[3], n[3], pos[3];
    for (int i = 0; i < 3; i++) nl[i] = (p[i] - q[i]) / dist;
    dx_to_world(o2->R, nl, n);
    dx_point_to_world(o2->R, o2->pos, q, pos);
    dx_put_contact(out, 0, skip, pos, n, r - dist, o1, o2);
    return 1;
}

// ---- against a plane --------------------------------------------------------

// Capsule-plane: the balls at the two ends of the axis, each touching if it
// reaches below the plane (1 or 2 contacts, deepest first); pos the ball's
// lowest point.
int dxCollideCapsulePlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    const dReal *pl = ((dxPlane *)o2)->p;
    const dReal r = ((dxCapsule *)o1)->radius;
    dReal z[3], hl;
    capsule_segment(o1, z, &hl);
    dReal centre = pl[3] - dx_dot(pl, o1->pos) + r, along = hl * dx_dot(pl, z);
    // The end against the plane's normal is the deeper.
    dReal sg = along > 0 ? -1 : 1;
    dReal depth[2] = { centre + dFabs(along), centre - dFabs(along) };
    int count = 0, max = dx_max_contacts(flags);
    for (int e = 0; e < 2 && count < max; e++) {
        if (depth[e] < 0) break;
        dReal end = e == 0 ? sg * hl : -sg * hl, pos[3];
        for (int i = 0; i < 3; i++) pos[i] = o1->pos[i] + end * z[i] - r * pl[i];
        dx_put_contact(c, count++, skip, pos, pl, depth[e], o1, o2);
    }
    return count;
}

// Cylinder-plane: the deepest points are on the rims. With u the unit
// direction across the axis that goes most into the plane (any one if the
// axis is along the normal) and w = z x u, each rim is sampled at +-u and
// +-w: a cylinder on its side rests on 2 rim points, an upright one on 4,
// a tilted one on its lowest rim point. Up to 4 of the points below the
// plane, deepest first.
int dxCollideCylinderPlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    const dReal *pl = ((dxPlane *)o2)->p;
    const dxCylinder *cyl = (const dxCylinder *)o1;
    const dReal R = cyl->radius, H = cyl->length / 2;
    dReal z[3];
    dx_axis(o1->R, 2, z);
    dReal nz = dx_dot(pl, z), centre = pl[3] - dx_dot(pl, o1->pos);
    if (centre + H * dFabs(nz) + R < 0) return 0;   // even the widest rim reach misses
    dReal u[3] = { nz * z[0] - pl[0], nz * z[1] - pl[1], nz * z[2] - pl[2] };
    dReal across2 = dx_dot(u, u);
    dReal across = across2 > 0 ? dSqrt(across2) : 0;   // |n - (n.z) z|
    if (centre + H * dFabs(nz) + R * across < 0) return 0;
    if (across > 0) {
        for (int i = 0; i < 3; i++) u[i] /= across;
    } else {
        dx_axis(o1->R, 0, u);
    }
    dReal w[3] = { z[1] * u[2] - z[2] * u[1], z[2] * u[0] - z[0] * u[2],
                   z[0] * u[1] - z[1] * u[0] };
    int max = dx_max_contacts(flags);
    if (max > 4) max = 4;
    dReal pts[8][3], dep[8];
    int n = 0;
    for (int e = -1; e <= 1; e += 2) {
        dReal rim = centre - e * H * nz;
        const dReal *dir[4] = { u, w, u, w };
        const dReal dsg[4] = { R, R, -R, -R };
        const dReal dd[4] = { R * across, 0, -R * across, 0 };
        for (int k = 0; k < 4; k++) {
            if (rim + dd[k] < 0) continue;
            for (int i = 0; i < 3; i++) pts[n][i] = o1->pos[i] + e * H * z[i] + dsg[k] * dir[k][i];
            dep[n++] = rim + dd[k];
        }
    }
    int count = 0;
    for (; count < max && count < n; count++) {   // selection of the deepest
        int best = count;
        for (int j = count + 1; j < n; j++)
            if (dep[j] > dep[best]) best = j;
        dx_put_contact(c, count, skip, pts[best], pl, dep[best], o1, o2);
        dep[best] = dep[count];
        for (int i = 0; i < 3; i++) pts[best][i] = pts[count][i];
    }
    return count;
}
