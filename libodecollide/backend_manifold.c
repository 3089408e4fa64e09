// SPDX-License-Identifier: BSD-3-Clause
//
// backend_manifold.c -- what the adapters add to a backend's raw contacts so
// that they meet the contract (issue 14, backend_support.h): the manifold of
// a shape on a plane where the backend gives one point, and contact points
// put back inside both shapes where a backend reports the middle of a
// segment that leaves one of them.

#include "backend_support.h"

#include <math.h>
#include <ode/collision.h>
#include <string.h>

enum { MAX_FEATURE_POINTS = 8 };

// World point of g at local offset l.
static void local_point(const dReal c[3], const dReal R[12], const dReal l[3], dReal out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = c[i] + R[4 * i] * l[0] + R[4 * i + 1] * l[1] + R[4 * i + 2] * l[2];
}

// The points of g that can touch a plane whose normal u points into g: a
// box's corners; the lowest points of a capsule's two end spheres; on each
// cap rim of a cylinder, the lowest point and those a quarter, a half and
// three quarters round (an upright cylinder: a square inscribed in its
// cap, as native gives). Returns the count (0 for other classes).
static int feature_points(dGeomID g, const dReal u[3], dReal out[MAX_FEATURE_POINTS][3])
{
    dxShapeDesc d;
    dReal c[3], R[12];
    dxGeomDescribe(g, &d);
    dxGeomPose(g, c, R);
    dReal ul[3];   // u in g's frame
    for (int k = 0; k < 3; k++) ul[k] = u[0] * R[k] + u[1] * R[4 + k] + u[2] * R[8 + k];
    switch (d.cls) {
    case dBoxClass:
        for (int i = 0; i < 8; i++) {
            dReal l[3] = { (i & 1 ? 0.5 : -0.5) * d.p[0], (i & 2 ? 0.5 : -0.5) * d.p[1],
                           (i & 4 ? 0.5 : -0.5) * d.p[2] };
            local_point(c, R, l, out[i]);
        }
        return 8;
    case dCapsuleClass:
        for (int i = 0; i < 2; i++) {
            dReal l[3] = { -d.p[0] * ul[0], -d.p[0] * ul[1],
                           (i ? 0.5 : -0.5) * d.p[1] - d.p[0] * ul[2] };
            local_point(c, R, l, out[i]);
        }
        return 2;
    case dCylinderClass: {
        dReal q = sqrt(ul[0] * ul[0] + ul[1] * ul[1]);
        dReal wx = q > 1e-9 ? -ul[0] / q : 1, wy = q > 1e-9 ? -ul[1] / q : 0;
        for (int i = 0; i < 8; i++) {
            // quarter turns of (wx, wy): (wx, wy), (-wy, wx), (-wx, -wy), (wy, -wx)
            int k = i & 3;
            dReal x = k == 0 ? wx : k == 1 ? -wy : k == 2 ? -wx : wy;
            dReal y = k == 0 ? wy : k == 1 ? wx : k == 2 ? -wy : -wx;
            dReal l[3] = { d.p[0] * x, d.p[0] * y, (i & 4 ? 0.5 : -0.5) * d.p[1] };
            local_point(c, R, l, out[i]);
        }
        return 8;
    }
    default: return 0;
    }
}

void dxSinkPlaneManifold(dxContactSink *s, dGeomID shape, int shape_is_o1)
{
    int deepest = -1;
    for (int i = 0; i < s->count; i++)
        if (isfinite(s->c[i].depth) && (deepest < 0 || s->c[i].depth > s->c[deepest].depth))
            deepest = i;
    if (deepest < 0) return;
    dReal n[3], depth = s->c[deepest].depth;
    memcpy(n, s->c[deepest].normal, sizeof n);
    dReal len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !(depth >= 0)) return;
    dReal u[3];   // the plane's normal, into the shape
    for (int k = 0; k < 3; k++) {
        n[k] /= len;
        u[k] = shape_is_o1 ? n[k] : -n[k];
    }
    dReal p[MAX_FEATURE_POINTS][3], h[MAX_FEATURE_POINTS], low = INFINITY;
    int np = feature_points(shape, u, p);
    if (np == 0) return;
    for (int i = 0; i < np; i++) {
        h[i] = u[0] * p[i][0] + u[1] * p[i][1] + u[2] * p[i][2];
        if (h[i] < low) low = h[i];
    }
    // The lowest feature point is the backend's deepest; the others are as
    // deep as they are lower than the plane the backend's depth puts there.
    dxSinkInit(s);
    for (int i = 0; i < np; i++) {
        dReal di = depth - (h[i] - low);
        if (di > 0) dxSinkAdd(s, p[i], n, di, -1, -1);
    }
}

// Signed depth of p in a cylinder g: positive inside (distance to the
// surface), minus the distance outside.
static dReal cylinder_point_depth(dGeomID g, const dReal p[3])
{
    dxShapeDesc d;
    dReal c[3], R[12], l[3];
    dxGeomDescribe(g, &d);
    dxGeomPose(g, c, R);
    for (int k = 0; k < 3; k++)
        l[k] = (p[0] - c[0]) * R[k] + (p[1] - c[1]) * R[4 + k] + (p[2] - c[2]) * R[8 + k];
    dReal radial = d.p[0] - sqrt(l[0] * l[0] + l[1] * l[1]), axial = d.p[1] / 2 - fabs(l[2]);
    if (radial >= 0 && axial >= 0) return radial < axial ? radial : axial;
    dReal or = radial < 0 ? -radial : 0, oa = axial < 0 ? -axial : 0;
    return -sqrt(or * or + oa * oa);
}

// Signed depth of p in g (positive inside); 0 (no preference) for classes
// without a closed form here.
static dReal point_depth(dGeomID g, const dReal p[3])
{
    switch (dGeomGetClass(g)) {
    case dCylinderClass: return cylinder_point_depth(g, p);
    case dSphereClass: return dGeomSpherePointDepth(g, p[0], p[1], p[2]);
    case dBoxClass: return dGeomBoxPointDepth(g, p[0], p[1], p[2]);
    case dCapsuleClass: return dGeomCapsulePointDepth(g, p[0], p[1], p[2]);
    case dPlaneClass: return dGeomPlanePointDepth(g, p[0], p[1], p[2]);
    default: return 0;
    }
}

void dxSinkPointsInBoth(dxContactSink *s, dGeomID o1, dGeomID o2)
{
    for (int i = 0; i < s->count; i++) {
        struct dxRawContact *c = &s->c[i];
        dReal len = sqrt(c->normal[0] * c->normal[0] + c->normal[1] * c->normal[1] +
                         c->normal[2] * c->normal[2]);
        if (!(len > 0) || !(c->depth > 0)) continue;
        // How deep the middle (j = 0) and each end lie in both shapes. An end
        // replaces the middle only if clearly deeper (points on an edge of a
        // shape tie at 0 up to rounding); between two such ends, the one
        // deeper in the two together wins, so that the choice mirrors.
        dReal q[3][3], lo[3], sum[3];
        for (int j = 0; j < 3; j++) {
            for (int k = 0; k < 3; k++)
                q[j][k] = c->pos[k] + (j - 1) * c->normal[k] / len * c->depth / 2;
            dReal d1 = point_depth(o1, q[j]), d2 = point_depth(o2, q[j]);
            lo[j] = d1 < d2 ? d1 : d2;
            sum[j] = d1 + d2;
        }
        dReal margin = lo[1] + 1e-6 * c->depth;
        int best = 1;
        for (int j = 0; j < 3; j += 2)
            if (lo[j] > margin && (best == 1 || lo[j] > lo[best] ||
                                   (lo[j] == lo[best] && sum[j] > sum[best])))
                best = j;
        memcpy(c->pos, q[best], sizeof c->pos);
    }
}
