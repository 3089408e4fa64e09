// SPDX-License-Identifier: BSD-3-Clause
//
// geom_convex.h -- the convex hull class (ODE 0.16's dCreateConvex): the
// caller's arrays, kept by pointer as ODE keeps them, for the geom's own
// file and the native convex colliders.

#ifndef DX_GEOM_CONVEX_H
#define DX_GEOM_CONVEX_H

#include "shapes.h"

// An edge of the hull, (a, b) with a < b, between faces f1 and f2 (f2 =
// f1 when the polygons give the edge only once).
typedef struct dxHullEdge {
    unsigned a, b, f1, f2;
} dxHullEdge;

// A separating axis found against another geom (collide_convex_hull.c):
// tried first the next time the pair meets, so a pair that stays apart is
// rejected by one axis. Only a hint: `other` is never dereferenced (it may
// be destroyed and its address reused), and an axis that no longer
// separates is simply not used.
enum { DX_CONVEX_AXIS_CACHE = 8 };
typedef struct dxHullAxisHint {
    const void *other;
    double axis[3];               // in this hull's frame
} dxHullAxisHint;

typedef struct dxConvex {
    dxGeom g;
    const dReal *planes;          // planecount x (a, b, c, d): a x + b y + c z = d, outward
    const dReal *points;          // pointcount x (x, y, z), in the geom's frame
    const unsigned *polygons;     // per plane: count, then count point indices
    unsigned planecount, pointcount;
    dxHullEdge *edges;            // derived from the polygons, owned by the geom
    unsigned edgecount;
    size_t edgecap;               // the entries allocated (one per polygon side)
    dxHullAxisHint hints[DX_CONVEX_AXIS_CACHE];
    unsigned next_hint;           // the entry replaced next
} dxConvex;

extern const dxGeomClassOps dx_convex_ops;

#endif
