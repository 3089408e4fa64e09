// SPDX-License-Identifier: BSD-3-Clause
//
// collide_ray.c -- the ray against a sphere, a box, a capsule, a cylinder and
// a plane (BACKENDS.md section 1, guide 10.7.5). Each shape gives the span
// of the ray's line inside it, [t_in, t_out] in distance along the ray, with
// the outward surface normal at both ends. A ray starting outside hits where
// it enters (t_in >= 0); one starting inside hits where it leaves (t_in < 0
// <= t_out). The contact is that point on the shape's surface, depth its
// distance from the start (at most the ray's length: a ray ending exactly
// on the surface hits), and the normal the surface normal turned to face
// the ray's side: outward at an entry, inward at an exit. Both ends count as
// inside, so a ray grazing a shape tangentially hits at the touching point,
// as in ODE 0.16.

#include "collide_math.h"

#include <string.h>

// Where the ray's line is inside a shape: entry and exit distances along the
// ray (t_in <= t_out, either may be infinite) and the outward unit normals
// there, in the shape's frame.
typedef struct ray_span {
    dReal t_in, t_out;
    dReal n_in[3], n_out[3];
} ray_span;

// The ray in a shape's frame: start s and unit direction v.
typedef struct ray_local {
    dReal s[3], v[3];
} ray_local;

static void ray_to_local(const dxGeom *ray, const dxGeom *shape, ray_local *r)
{
    dReal d[3], dir[3];
    for (int i = 0; i < 3; i++) d[i] = ray->pos[i] - shape->pos[i];
    dx_axis(ray->R, 2, dir);
    dx_to_local(shape->R, d, r->s);
    dx_to_local(shape->R, dir, r->v);
}

static void set3(dReal out[3], dReal x, dReal y, dReal z)
{
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

// The roots t0 <= t1 of a t^2 + 2 b t + c = 0 (a > 0), computed without the
// cancellation of -b +- sqrt(b^2 - a c): the larger-magnitude root first,
// the other from the product of the roots c / a. 0 if there are none.
static int quadratic_roots(dReal a, dReal b, dReal c, dReal *t0, dReal *t1)
{
    dReal disc = b * b - a * c;
    if (disc < 0) return 0;
    dReal root = dSqrt(disc);
    dReal q = b < 0 ? root - b : -root - b;   // -(b + sign(b) root)
    if (q == 0) {                             // b = 0 and disc = 0, so c = 0
        *t0 = *t1 = 0;
        return 1;
    }
    dReal x = q / a, y = c / q;
    *t0 = x < y ? x : y;
    *t1 = x < y ? y : x;
    return 1;
}

// The span inside the ball of radius r >= 0 centred at c (shape frame); the
// normals point from c to the entry and exit points (for a point ball hit
// through its centre: against the ray at entry, along it at exit). 0 if the
// line misses.
static int ball_span(const ray_local *r, const dReal c[3], dReal radius, ray_span *sp)
{
    dReal q[3] = { r->s[0] - c[0], r->s[1] - c[1], r->s[2] - c[2] };
    if (!quadratic_roots(dx_dot(r->v, r->v), dx_dot(q, r->v), dx_dot(q, q) - radius * radius,
                         &sp->t_in, &sp->t_out))
        return 0;
    dReal t[2] = { sp->t_in, sp->t_out };
    dReal *n[2] = { sp->n_in, sp->n_out };
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < 3; i++) n[k][i] = q[i] + t[k] * r->v[i];
        dReal len = dSqrt(dx_dot(n[k], n[k]));   // ~radius: the point is on the sphere
        if (len > 0) {
            for (int i = 0; i < 3; i++) n[k][i] /= len;
        } else {
            const dReal along = (k ? 1 : -1) / dSqrt(dx_dot(r->v, r->v));
            for (int i = 0; i < 3; i++) n[k][i] = along * r->v[i];
        }
    }
    return 1;
}

// The span inside the infinite cylinder x^2 + y^2 <= radius^2 (radius >= 0,
// shape frame), with radial normals (through the axis of a zero radius:
// against the ray's radial part at entry, along it at exit); infinite both
// ways for a line parallel to the axis inside it. 0 if the line misses.
static int tube_span(const ray_local *r, dReal radius, ray_span *sp)
{
    const dReal *s = r->s, *v = r->v;
    dReal a = v[0] * v[0] + v[1] * v[1], c = s[0] * s[0] + s[1] * s[1] - radius * radius;
    if (a == 0) {
        if (c > 0) return 0;
        sp->t_in = -dInfinity;
        sp->t_out = dInfinity;
        set3(sp->n_in, 0, 0, 0);   // never used: an infinite end is never hit
        set3(sp->n_out, 0, 0, 0);
        return 1;
    }
    if (!quadratic_roots(a, s[0] * v[0] + s[1] * v[1], c, &sp->t_in, &sp->t_out)) return 0;
    dReal t[2] = { sp->t_in, sp->t_out };
    dReal *n[2] = { sp->n_in, sp->n_out };
    for (int k = 0; k < 2; k++) {
        dReal x = s[0] + t[k] * v[0], y = s[1] + t[k] * v[1], len = dSqrt(x * x + y * y);
        if (len > 0) {
            set3(n[k], x / len, y / len, 0);   // len ~ radius
        } else {
            const dReal along = (k ? 1 : -1) / dSqrt(a);
            set3(n[k], along * v[0], along * v[1], 0);
        }
    }
    return 1;
}

// The span between the planes x_i = -h and x_i = h (shape frame), with the
// normals +-e_i; infinite both ways for a line parallel to them between
// them. 0 if the line misses. The line meets the face x_i = -sign(v_i) h
// first.
static int slab_span(const ray_local *r, int i, dReal h, ray_span *sp)
{
    dReal s = r->s[i], v = r->v[i];
    set3(sp->n_in, 0, 0, 0);
    set3(sp->n_out, 0, 0, 0);
    if (v == 0) {
        if (s < -h || s > h) return 0;
        sp->t_in = -dInfinity;
        sp->t_out = dInfinity;
        return 1;
    }
    dReal ta = (-h - s) / v, tb = (h - s) / v, sign = v > 0 ? 1 : -1;
    sp->t_in = ta < tb ? ta : tb;
    sp->t_out = ta < tb ? tb : ta;
    sp->n_in[i] = -sign;
    sp->n_out[i] = sign;
    return 1;
}

// sp = sp intersected with other; 0 if that is empty. A tie keeps other's
// normal when prefer_other (the cylinder's rim counts as cap) and sp's if
// not (the box's edges count as the lower-numbered face, as in ODE 0.16).
static int span_clip(ray_span *sp, const ray_span *other, int prefer_other)
{
    if (other->t_in > sp->t_in || (prefer_other && other->t_in == sp->t_in)) {
        sp->t_in = other->t_in;
        memcpy(sp->n_in, other->n_in, sizeof sp->n_in);
    }
    if (other->t_out < sp->t_out || (prefer_other && other->t_out == sp->t_out)) {
        sp->t_out = other->t_out;
        memcpy(sp->n_out, other->n_out, sizeof sp->n_out);
    }
    return sp->t_in <= sp->t_out;
}

// sp = the union of sp and other, two spans known to overlap (parts of one
// convex shape); has tells whether sp holds a span yet.
static void span_join(ray_span *sp, const ray_span *other, int *has)
{
    if (!*has || other->t_in < sp->t_in) {
        sp->t_in = other->t_in;
        memcpy(sp->n_in, other->n_in, sizeof sp->n_in);
    }
    if (!*has || other->t_out > sp->t_out) {
        sp->t_out = other->t_out;
        memcpy(sp->n_out, other->n_out, sizeof sp->n_out);
    }
    *has = 1;
}

// The contact of a ray with a shape whose line span is sp, normals in the
// frame R (NULL: world). Writes nothing and returns 0 when the ray does not
// reach the surface within its length.
static int ray_hit(dxGeom *ray, dxGeom *shape, const dReal *R, const ray_span *sp,
                   dContactGeom *c, int skip)
{
    dReal t, nl[3];
    if (sp->t_in >= 0) {   // starts outside (or on the surface): the entry
        t = sp->t_in;
        for (int i = 0; i < 3; i++) nl[i] = sp->n_in[i];
    } else if (sp->t_out >= 0) {   // starts inside: the exit, normal inward
        t = sp->t_out;
        for (int i = 0; i < 3; i++) nl[i] = -sp->n_out[i];
    } else {
        return 0;
    }
    if (t > ((dxRay *)ray)->length) return 0;
    t = t > 0 ? t : 0;   // not -0 for a ray starting on the surface
    dReal n[3], dir[3], pos[3];
    if (R)
        dx_to_world(R, nl, n);
    else
        for (int i = 0; i < 3; i++) n[i] = nl[i];
    dx_axis(ray->R, 2, dir);
    for (int i = 0; i < 3; i++) pos[i] = ray->pos[i] + t * dir[i];
    dx_put_contact(c, 0, skip, pos, n, t, ray, shape);
    return 1;
}

int dxCollideRaySphere(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    static const dReal centre[3] = { 0, 0, 0 };
    ray_local r;
    ray_span sp;
    ray_to_local(o1, o2, &r);
    if (!ball_span(&r, centre, ((dxSphere *)o2)->radius, &sp)) return 0;
    return ray_hit(o1, o2, o2->R, &sp, c, skip);
}

// Ray-box: the intersection of the three slabs (Kay and Kajiya).
int dxCollideRayBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dReal *side = ((dxBox *)o2)->side;
    ray_local r;
    ray_span sp, slab;
    ray_to_local(o1, o2, &r);
    if (!slab_span(&r, 0, side[0] / 2, &sp)) return 0;
    for (int i = 1; i < 3; i++)
        if (!slab_span(&r, i, side[i] / 2, &slab) || !span_clip(&sp, &slab, 0)) return 0;
    return ray_hit(o1, o2, o2->R, &sp, c, skip);
}

// Ray-capsule: the capsule is the union of its two end balls and the part of
// its tube between the caps, so the span is the union of their spans. An end
// of the tube's span beyond a cap does not count: the line crosses the cap's
// disc there, inside the cap's ball, whose span reaches further. (A line
// parallel to the axis inside the tube goes through both balls.)
int dxCollideRayCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dxCapsule *cap = (const dxCapsule *)o2;
    const dReal h = cap->length / 2;
    ray_local r;
    ray_span sp, part;
    int has = 0;
    ray_to_local(o1, o2, &r);
    for (int k = -1; k <= 1; k += 2) {
        const dReal centre[3] = { 0, 0, k * h };
        if (ball_span(&r, centre, cap->radius, &part)) span_join(&sp, &part, &has);
    }
    if (tube_span(&r, cap->radius, &part) && dxIsFinite(part.t_in)) {
        int in_ok = dFabs(r.s[2] + part.t_in * r.v[2]) <= h;
        int out_ok = dFabs(r.s[2] + part.t_out * r.v[2]) <= h;
        if (!in_ok) {   // keep only the exit
            part.t_in = part.t_out;
            memcpy(part.n_in, part.n_out, sizeof part.n_in);
        }
        if (!out_ok) {   // keep only the entry
            part.t_out = part.t_in;
            memcpy(part.n_out, part.n_in, sizeof part.n_out);
        }
        if (in_ok || out_ok) span_join(&sp, &part, &has);
    }
    if (!has) return 0;
    return ray_hit(o1, o2, o2->R, &sp, c, skip);
}

// Ray-cylinder (flat caps): the tube's span clipped to the slab between the
// caps. A ray through the rim gets the cap's normal, as in ODE 0.16.
int dxCollideRayCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dxCylinder *cyl = (const dxCylinder *)o2;
    ray_local r;
    ray_span sp, slab;
    ray_to_local(o1, o2, &r);
    if (!tube_span(&r, cyl->radius, &sp) || !slab_span(&r, 2, cyl->length / 2, &slab) ||
        !span_clip(&sp, &slab, 1))
        return 0;
    return ray_hit(o1, o2, o2->R, &sp, c, skip);
}

// Ray-plane: the half-space n . x <= d; the line crosses its boundary once
// unless parallel to it (then no contact, as in ODE 0.16, even inside).
int dxCollideRayPlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dReal *p = ((dxPlane *)o2)->p;
    dReal dir[3];
    dx_axis(o1->R, 2, dir);
    dReal rate = dx_dot(p, dir);   // d/dt of n . x along the ray
    if (rate == 0) return 0;
    ray_span sp;
    dReal t = (p[3] - dx_dot(p, o1->pos)) / rate;
    if (rate < 0) {   // going down into the solid: t is the entry
        sp.t_in = t;
        sp.t_out = dInfinity;
    } else {          // coming up out of it: t is the exit
        sp.t_in = -dInfinity;
        sp.t_out = t;
    }
    for (int i = 0; i < 3; i++) sp.n_in[i] = sp.n_out[i] = p[i];
    return ray_hit(o1, o2, NULL, &sp, c, skip);
}
