// SPDX-License-Identifier: BSD-3-Clause
//
// collide_sphere.c -- the sphere's analytic colliders: against a sphere, a
// box, a capsule, a plane and a cylinder. Each gives one contact: the
// nearest point of the other shape, or, with the centre inside it, the
// shortest way out.

#include "collide_math.h"

static const dReal x_axis[3] = { 1, 0, 0 };

// Sphere-sphere: normal from o2's centre to o1's, pos in the middle of the
// overlap along the centre line.
int dxCollideSphereSphere(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    dReal pos[3], n[3], depth;
    if (!dx_ball_contact(o1->pos, ((dxSphere *)o1)->radius, o2->pos, ((dxSphere *)o2)->radius,
                         x_axis, pos, n, &depth))
        return 0;
    dx_put_contact(c, 0, skip, pos, n, depth, o1, o2);
    return 1;
}

// The length of the nonzero v (n numbers) and v over it into unit, from v
// scaled by its largest part first: for a v whose squares underflow to 0
// (a sphere 1e-30 off a face in single precision), where the usual
// sqrt(v . v) gives 0 and the normal 0 * inf.
static dReal scaled_length(const dReal *v, int n, dReal *unit)
{
    dReal big = 0, e2 = 0;
    for (int i = 0; i < n; i++) big = dMax(big, dFabs(v[i]));
    for (int i = 0; i < n; i++) {
        unit[i] = v[i] / big;
        e2 += unit[i] * unit[i];
    }
    const dReal e = dSqrt(e2);
    for (int i = 0; i < n; i++) unit[i] /= e;
    return big * e;
}

// Sphere-box: with the centre outside the box, the nearest box point q
// (centre clamped to the box in its frame): normal (centre - q) / |..|,
// depth r - |centre - q|, pos q. With the centre inside, out through the
// nearest face: depth r + distance to it, pos the centre.
int dxCollideSphereBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dReal r = ((dxSphere *)o1)->radius;
    const dReal *side = ((dxBox *)o2)->side;
    const dReal *R = o2->R;
    dReal d[3] = { o1->pos[0] - o2->pos[0], o1->pos[1] - o2->pos[1], o1->pos[2] - o2->pos[2] };
    dReal q[3], out[3], out2 = 0;
    dx_to_local(R, d, q);
    int inside = 1;
    for (int i = 0; i < 3; i++) {
        dReal h = side[i] / 2;
        out[i] = q[i] > h ? q[i] - h : q[i] < -h ? q[i] + h : 0;
        if (out[i] != 0) inside = 0;
        out2 += out[i] * out[i];
    }
    if (out2 > r * r) return 0;
    dReal n[3], pos[3], depth;
    if (!inside) {
        dReal dist, nl[3], ql[3];
        if (out2 > 0) {
            dist = dSqrt(out2);
            const dReal inv = 1 / dist;
            for (int i = 0; i < 3; i++) nl[i] = out[i] * inv;
        } else {   // just off the box by less than the squares resolve
            dist = scaled_length(out, 3, nl);
            if (dist > r) return 0;
        }
        for (int i = 0; i < 3; i++) ql[i] = q[i] - out[i];
        dx_to_world(R, nl, n);
        dx_point_to_world(R, o2->pos, ql, pos);
        depth = r - dist;
    } else {
        int k = 0;
        dReal best = side[0] / 2 - dFabs(q[0]);
        for (int i = 1; i < 3; i++) {
            dReal gap = side[i] / 2 - dFabs(q[i]);
            if (gap < best) {
                best = gap;
                k = i;
            }
        }
        dReal sign = q[k] < 0 ? -1 : 1;
        n[0] = sign * R[k];
        n[1] = sign * R[4 + k];
        n[2] = sign * R[8 + k];
        for (int i = 0; i < 3; i++) pos[i] = o1->pos[i];
        depth = r + best;
    }
    dx_put_contact(c, 0, skip, pos, n, depth, o1, o2);
    return 1;
}

// Sphere-capsule: the sphere against the ball at the nearest point of the
// capsule's axis segment.
int dxCollideSphereCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dxCapsule *cap = (const dxCapsule *)o2;
    dReal z[3], d[3], q[3];
    dx_axis(o2->R, 2, z);
    for (int i = 0; i < 3; i++) d[i] = o1->pos[i] - o2->pos[i];
    dReal t = dx_clamp(dx_dot(d, z), -cap->length / 2, cap->length / 2);
    for (int i = 0; i < 3; i++) q[i] = o2->pos[i] + t * z[i];
    dReal across[3], pos[3], n[3], depth;
    dx_axis(o2->R, 0, across);   // centre on the axis: leave sideways
    if (!dx_ball_contact(o1->pos, ((dxSphere *)o1)->radius, q, cap->radius, across, pos, n,
                         &depth))
        return 0;
    dx_put_contact(c, 0, skip, pos, n, depth, o1, o2);
    return 1;
}

// Sphere-plane: depth r - (n . centre - d), pos the sphere's deepest point.
int dxCollideSpherePlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dReal *p = ((dxPlane *)o2)->p;
    const dReal r = ((dxSphere *)o1)->radius;
    dReal depth = p[3] - dx_dot(p, o1->pos) + r;
    if (depth < 0) return 0;
    dReal pos[3];
    for (int i = 0; i < 3; i++) pos[i] = o1->pos[i] - r * p[i];
    dx_put_contact(c, 0, skip, pos, p, depth, o1, o2);
    return 1;
}

// Sphere-cylinder, in the cylinder's frame (axial a, radial s): outside,
// the nearest point clamps a to the caps and the radial part to the radius
// (side, cap or rim); inside, out through the side or the nearer cap,
// whichever is closer.
int dxCollideSphereCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    const dReal r = ((dxSphere *)o1)->radius;
    const dxCylinder *cyl = (const dxCylinder *)o2;
    const dReal R = cyl->radius, H = cyl->length / 2;
    const dReal *rot = o2->R;
    dReal d[3] = { o1->pos[0] - o2->pos[0], o1->pos[1] - o2->pos[1], o1->pos[2] - o2->pos[2] };
    dReal q[3];
    dx_to_local(rot, d, q);
    dReal s2 = q[0] * q[0] + q[1] * q[1];
    dReal out_a = q[2] > H ? q[2] - H : q[2] < -H ? q[2] + H : 0;
    if (dFabs(out_a) > r) return 0;
    dReal reach = R + r;
    if (s2 > reach * reach) return 0;
    dReal s = dSqrt(s2);
    dReal out_s = s > R ? s - R : 0;
    dReal nl[3], pl[3], depth;
    if (out_a != 0 || out_s != 0) {
        dReal dist2 = out_a * out_a + out_s * out_s;
        if (dist2 > r * r) return 0;
        // Radial unit direction (s > R > 0 whenever out_s != 0).
        dReal ux = out_s != 0 ? q[0] / s : 0, uy = out_s != 0 ? q[1] / s : 0, dist;
        if (dist2 > 0) {
            dist = dSqrt(dist2);
            const dReal inv = 1 / dist;
            nl[0] = out_s * ux * inv;
            nl[1] = out_s * uy * inv;
            nl[2] = out_a * inv;
        } else {   // just off the cylinder by less than the squares resolve
            const dReal v[2] = { out_s, out_a };
            dReal u[2];
            dist = scaled_length(v, 2, u);
            if (dist > r) return 0;
            nl[0] = u[0] * ux;
            nl[1] = u[0] * uy;
            nl[2] = u[1];
        }
        pl[0] = q[0] - out_s * ux;
        pl[1] = q[1] - out_s * uy;
        pl[2] = q[2] - out_a;
        depth = r - dist;
    } else {
        dReal side_gap = R - s, cap_gap = H - dFabs(q[2]);
        if (side_gap < cap_gap) {
            if (s > 0) {
                nl[0] = q[0] / s;
                nl[1] = q[1] / s;
            } else {
                nl[0] = 1;
                nl[1] = 0;
            }
            nl[2] = 0;
            depth = r + side_gap;
        } else {
            nl[0] = nl[1] = 0;
            nl[2] = q[2] < 0 ? -1 : 1;
            depth = r + cap_gap;
        }
        for (int i = 0; i < 3; i++) pl[i] = q[i];
    }
    dReal n[3], pos[3];
    dx_to_world(rot, nl, n);
    dx_point_to_world(rot, o2->pos, pl, pos);
    dx_put_contact(c, 0, skip, pos, n, depth, o1, o2);
    return 1;
}
