// SPDX-License-Identifier: BSD-3-Clause
//
// backend_shadow_compare.c -- shadow mode's verdict on two results of one
// pair (backend.h lists the kinds of disagreement): deepest depths, deepest
// normals, contact points against both shapes, and manifold sizes.

#include "backend_shadow.h"

#include <math.h>

#include "geom_convex.h"
#include "shapes.h"

// Depth of a world point in a cylinder: inside, the distance to the nearer of
// its side and caps; outside, minus the distance to the solid.
static double cylinder_depth(dxGeom *g, const dReal p[3])
{
    const dxCylinder *c = (const dxCylinder *)g;
    double d[3], l[3];
    for (int k = 0; k < 3; k++) d[k] = p[k] - g->pos[k];
    for (int k = 0; k < 3; k++) l[k] = d[0] * g->R[k] + d[1] * g->R[4 + k] + d[2] * g->R[8 + k];
    double radial = c->radius - sqrt(l[0] * l[0] + l[1] * l[1]);
    double axial = c->length / 2 - fabs(l[2]);
    if (radial < 0 && axial < 0) return -sqrt(radial * radial + axial * axial);
    return radial < axial ? radial : axial;
}

// Depth of a world point in a convex hull, from its farthest face plane
// (outside, a lower bound of the distance: it flags no point wrongly).
static double convex_depth(dxGeom *g, const dReal p[3])
{
    const dxConvex *c = (const dxConvex *)g;
    double d[3], l[3], worst = -INFINITY;
    for (int k = 0; k < 3; k++) d[k] = p[k] - g->pos[k];
    for (int k = 0; k < 3; k++) l[k] = d[0] * g->R[k] + d[1] * g->R[4 + k] + d[2] * g->R[8 + k];
    for (unsigned i = 0; i < c->planecount; i++) {
        const dReal *pl = c->planes + 4 * i;
        double s = pl[0] * l[0] + pl[1] * l[1] + pl[2] * l[2] - pl[3];
        if (s > worst) worst = s;
    }
    return c->planecount ? -worst : 0;
}

int dxShadowPointDepth(dxGeom *g, const dReal p[3], double *depth)
{
    switch (g->ops->cls) {
    case dSphereClass: *depth = dGeomSpherePointDepth(g, p[0], p[1], p[2]); return 1;
    case dBoxClass: *depth = dGeomBoxPointDepth(g, p[0], p[1], p[2]); return 1;
    case dCapsuleClass: *depth = dGeomCapsulePointDepth(g, p[0], p[1], p[2]); return 1;
    case dPlaneClass: *depth = dGeomPlanePointDepth(g, p[0], p[1], p[2]); return 1;
    case dCylinderClass: *depth = cylinder_depth(g, p); return 1;
    case dConvexClass: *depth = convex_depth(g, p); return 1;
    default: return 0;
    }
}

static const dContactGeom *at(const dContactGeom *c, int i, int skip)
{
    return (const dContactGeom *)((const char *)c + (size_t)i * (size_t)skip);
}

// The deepest of n contacts (NULL when n is 0).
static const dContactGeom *deepest(const dContactGeom *c, int n, int skip)
{
    const dContactGeom *best = NULL;
    for (int i = 0; i < n; i++)
        if (!best || at(c, i, skip)->depth > best->depth) best = at(c, i, skip);
    return best;
}

// How far the farthest of n contact points lies outside o1 or o2 (0 when all
// are inside); sets *bad when one is farther out than the point tolerance.
static double points_outside(dxGeom *o1, dxGeom *o2, const dContactGeom *c, int n, int skip,
                             int *bad)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        const dContactGeom *k = at(c, i, skip);
        double tol = DX_SHADOW_POINT_ABS + DX_SHADOW_POINT_REL * fabs((double)k->depth);
        dxGeom *g[2] = { o1, o2 };
        for (int j = 0; j < 2; j++) {
            double d;
            if (!dxShadowPointDepth(g[j], k->pos, &d)) continue;
            double out = -d;
            if (out > worst) worst = out;
            if (out > tol) *bad = 1;
        }
    }
    return worst;
}

// The largest distance between two of n contact points.
static double spread(const dContactGeom *c, int n, int skip)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            const dReal *p = at(c, i, skip)->pos, *q = at(c, j, skip)->pos;
            double d = sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                            (p[2] - q[2]) * (p[2] - q[2]));
            if (d > s) s = d;
        }
    return s;
}

void dxShadowCompare(dxGeom *o1, dxGeom *o2, int max, const dContactGeom *a, int na, int skip,
                     const dContactGeom *b, int nb, dxShadowVerdict *v)
{
    v->kinds = 0;
    v->normal_error = 0;
    const dContactGeom *da = deepest(a, na, skip), *db = deepest(b, nb, sizeof *b);
    double depth_a = da ? da->depth : 0, depth_b = db ? db->depth : 0;
    v->depth_error = fabs(depth_a - depth_b);
    double larger = depth_a > depth_b ? depth_a : depth_b;
    if (v->depth_error > DX_SHADOW_DEPTH_ABS + DX_SHADOW_DEPTH_REL * larger)
        v->kinds |= (na && nb) ? dCOLLISION_SHADOW_DEPTH : dCOLLISION_SHADOW_CONTACT;

    double smaller = depth_a < depth_b ? depth_a : depth_b;
    if (da && db && smaller >= DX_SHADOW_NORMAL_MIN_DEPTH) {
        double dot = 0, la = 0, lb = 0;
        for (int k = 0; k < 3; k++) {
            dot += da->normal[k] * db->normal[k];
            la += da->normal[k] * da->normal[k];
            lb += db->normal[k] * db->normal[k];
        }
        double cosine = (la > 0 && lb > 0) ? dot / sqrt(la * lb) : -1;
        if (cosine > 1) cosine = 1;
        if (cosine < -1) cosine = -1;
        v->normal_error = acos(cosine) * 180 / M_PI;
        if (v->normal_error > DX_SHADOW_NORMAL_DEG) v->kinds |= dCOLLISION_SHADOW_NORMAL;
    }

    int bad = 0;
    v->point_first = points_outside(o1, o2, a, na, skip, &bad);
    v->point_shadow = points_outside(o1, o2, b, nb, sizeof *b, &bad);
    if (bad) v->kinds |= dCOLLISION_SHADOW_POINT;

    if (max >= 2 && ((na == 1 && nb >= 2 && spread(b, nb, sizeof *b) > DX_SHADOW_SPREAD) ||
                     (nb == 1 && na >= 2 && spread(a, na, skip) > DX_SHADOW_SPREAD)))
        v->kinds |= dCOLLISION_SHADOW_MANIFOLD;
}
