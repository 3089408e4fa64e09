// SPDX-License-Identifier: BSD-3-Clause
//
// collide_math.h -- small vector helpers shared by the analytic colliders
// (collide_sphere.c, collide_box.c, collide_capsule.c): frames, contact
// writing, sphere-pair contacts and segment closest points. All static
// inline: they sit in the colliders' inner loops.

#ifndef DX_COLLIDE_MATH_H
#define DX_COLLIDE_MATH_H

#include "native_colliders.h"

// A relative tolerance for "the same point" / "parallel" tests.
#ifdef dSINGLE
#define DX_COLLIDE_EPS ((dReal)1e-5)
#else
#define DX_COLLIDE_EPS ((dReal)1e-9)
#endif

static inline dReal dx_dot(const dReal *a, const dReal *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline dReal dx_clamp(dReal x, dReal lo, dReal hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

// Column i of a rotation (the geom's local axis i in world coordinates).
static inline void dx_axis(const dReal *R, int i, dReal out[3])
{
    out[0] = R[i];
    out[1] = R[4 + i];
    out[2] = R[8 + i];
}

// R^T v: a world direction in the geom's frame.
static inline void dx_to_local(const dReal *R, const dReal *v, dReal out[3])
{
    for (int i = 0; i < 3; i++) out[i] = R[i] * v[0] + R[4 + i] * v[1] + R[8 + i] * v[2];
}

// R v: a local direction in world coordinates.
static inline void dx_to_world(const dReal *R, const dReal *v, dReal out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = R[4 * i] * v[0] + R[4 * i + 1] * v[1] + R[4 * i + 2] * v[2];
}

// origin + R v: a point given in a geom's frame (origin its position) in
// world coordinates.
static inline void dx_point_to_world(const dReal *R, const dReal *origin, const dReal *v,
                                     dReal out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = origin[i] + R[4 * i] * v[0] + R[4 * i + 1] * v[1] + R[4 * i + 2] * v[2];
}

static inline int dx_max_contacts(int flags)
{
    return flags & 0xffff;
}

// Write contact i (stride skip) of the pair (o1, o2).
static inline void dx_put_contact(dContactGeom *c, int i, int skip, const dReal pos[3],
                                  const dReal normal[3], dReal depth, dxGeom *o1, dxGeom *o2)
{
    dContactGeom *k = dxContactAt(c, i, skip);
    for (int j = 0; j < 3; j++) {
        k->pos[j] = pos[j];
        k->normal[j] = normal[j];
    }
    k->depth = depth;
    k->g1 = o1;
    k->g2 = o2;
    k->side1 = k->side2 = -1;
}

// The contact of a ball (p1, r1) with a ball (p2, r2): normal n from p2 to
// p1 (`fallback` if the centres (nearly) coincide), pos in the middle of the
// part of the centre line inside both balls: at distances [-r2, r2] and
// [dist - r1, dist + r1] from p2 along n. Returns 0 (writes nothing) when
// they are apart.
static inline int dx_ball_contact(const dReal p1[3], dReal r1, const dReal p2[3], dReal r2,
                                  const dReal fallback[3], dReal pos[3], dReal normal[3],
                                  dReal *depth)
{
    dReal d[3] = { p1[0] - p2[0], p1[1] - p2[1], p1[2] - p2[2] };
    dReal dist2 = dx_dot(d, d), rsum = r1 + r2;
    if (dist2 > rsum * rsum) return 0;
    dReal dist = dSqrt(dist2);
    if (dist > DX_COLLIDE_EPS * rsum) {   // else the direction would be rounding noise
        dReal inv = 1 / dist;
        for (int i = 0; i < 3; i++) normal[i] = d[i] * inv;
    } else {
        for (int i = 0; i < 3; i++) normal[i] = fallback[i];
    }
    dReal lo = dist - r1 > -r2 ? dist - r1 : -r2, hi = dist + r1 < r2 ? dist + r1 : r2;
    dReal mid = (lo + hi) / 2;
    for (int i = 0; i < 3; i++) pos[i] = p2[i] + mid * normal[i];
    *depth = rsum - dist;
    return 1;
}

// Closest points of the segments cA + s uA (|s| <= hA) and cB + t uB
// (|t| <= hB), u unit: the convex quadratic |cA - cB + s uA - t uB|^2 is
// minimised in s on the lines, then each parameter clamped and the other
// re-optimised. Parallel segments give an end of their overlap.
static inline void dx_closest_segments(const dReal cA[3], const dReal uA[3], dReal hA,
                                       const dReal cB[3], const dReal uB[3], dReal hB,
                                       dReal *s_out, dReal *t_out)
{
    dReal r[3] = { cA[0] - cB[0], cA[1] - cB[1], cA[2] - cB[2] };
    dReal b = dx_dot(uA, uB), c = dx_dot(uA, r), f = dx_dot(uB, r);
    dReal denom = 1 - b * b;
    dReal s = denom > DX_COLLIDE_EPS ? dx_clamp((b * f - c) / denom, -hA, hA) : -hA;
    dReal t = f + s * b;   // the best t for this s
    if (t < -hB || t > hB) {
        t = t < -hB ? -hB : hB;
        s = dx_clamp(t * b - c, -hA, hA);   // the best s for this t
    }
    *s_out = s;
    *t_out = t;
}

// A unit vector perpendicular to the unit vector u.
static inline void dx_perpendicular(const dReal u[3], dReal out[3])
{
    // Cross u with the world axis it is least aligned with.
    dReal a0 = dFabs(u[0]), a1 = dFabs(u[1]), a2 = dFabs(u[2]);
    dReal e[3] = { 0, 0, 0 };
    e[(a0 <= a1 && a0 <= a2) ? 0 : (a1 <= a2 ? 1 : 2)] = 1;
    dReal v[3] = { u[1] * e[2] - u[2] * e[1], u[2] * e[0] - u[0] * e[2],
                   u[0] * e[1] - u[1] * e[0] };
    dReal inv = 1 / dSqrt(dx_dot(v, v));
    for (int i = 0; i < 3; i++) out[i] = v[i] * inv;
}

#endif
