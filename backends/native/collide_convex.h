// SPDX-License-Identifier: BSD-3-Clause
//
// collide_convex.h -- what the convex hull colliders' files share: a hull
// (a convex geom, or a box made into one) posed in the world, evaluated in
// double precision whatever dReal is.

#ifndef DX_COLLIDE_CONVEX_H
#define DX_COLLIDE_CONVEX_H

#include "native_colliders.h"
#include "../../libodecollide/geom_convex.h"

// Relative tolerance of the hulls' geometry: directions this close to
// parallel, points this close (times the sizes) to a plane. Single
// precision poses are orthonormal only to ~1e-7.
#ifdef dSINGLE
#define DX_HULL_EPS 1e-5
#else
#define DX_HULL_EPS 1e-9
#endif

// An edge posed in the world: its direction (b - a), its faces' unit
// normals, and their cross product n2 x n1 (the edge pair test's).
typedef struct dx_hull_edge {
    double u[3], n1[3], n2[3], n2xn1[3];
} dx_hull_edge;

// Hulls with at most this many edges (faces, points) keep them posed in
// the world.
enum { DX_HULL_POSED_EDGES = 64, DX_HULL_POSED_FACES = 48, DX_HULL_POSED_POINTS = 64 };

typedef struct dx_hull {
    const dReal *pts;         // npts x (x, y, z), local
    const dReal *planes;      // nplanes x (a, b, c, d), local, outward
    const unsigned *polys;    // per plane: count, indices
    const dxHullEdge *edges;  // each edge once, with its two faces
    unsigned npts, nplanes, nedges;
    double R[9];              // world = R local + c (row-major)
    double c[3];
    double size;              // the largest distance of a point from the origin of the frame
    int posed;                // 1 once posed_edges holds the edges (if nedges <= ..._EDGES)
    dx_hull_edge posed_edges[DX_HULL_POSED_EDGES];
    int faces_posed;          // 1 if face_n, face_d hold the planes (nplanes <= ..._FACES)
    double face_n[DX_HULL_POSED_FACES][3], face_d[DX_HULL_POSED_FACES];
    int points_posed;         // 1 once posed_pts holds the points (dx_hull_pose_points)
    double posed_pts[DX_HULL_POSED_POINTS][3];
    dxConvex *convex;         // the convex geom (its axis hints), NULL for a box
} dx_hull;

// The storage of a box made into a hull (dx_hull_of_geom's box case).
typedef struct dx_hull_box {
    dReal pts[24], planes[24];
    unsigned polys[30];
    dxHullEdge edges[12];
} dx_hull_box;

// The hull of a convex geom or (into the storage bx) of a box geom.
void dx_hull_of_geom(dx_hull *h, const dxGeom *g, dx_hull_box *bx);

// Poses the points in the world (if they fit), for the many extents of a
// separating axis test.
void dx_hull_pose_points(dx_hull *h);
// Point i in world coordinates.
void dx_hull_vertex(const dx_hull *h, unsigned i, double out[3]);
// Plane f in world coordinates: unit outward normal n and offset (n . x = d).
void dx_hull_plane(const dx_hull *h, unsigned f, double n[3], double *d);
// max over the points of m . x, and (if idx) which point.
double dx_hull_extent(const dx_hull *h, const double m[3], unsigned *idx);
// min and max over the points of m . x.
void dx_hull_interval(const dx_hull *h, const double m[3], double *lo, double *hi);
// The polygon of plane f: its count and indices (walks the polygon list).
const unsigned *dx_hull_polygon(const dx_hull *h, unsigned f, unsigned *count);
// Clips [*t0, *t1] to where o + t d (world) is inside h, with planes that d
// runs along (|n . d| below DX_HULL_EPS) kept if o is within tol of them; 0 if
// empty by more than tol (rounding can leave a point's span crossed).
int dx_hull_clip_line(const dx_hull *h, const double o[3], const double d[3], double tol,
                      double *t0, double *t1);

// Hull against hull (separating axes; face contacts clipped, or an edge
// pair's point), as dxCollideBoxBox does for boxes. Contacts name o1, o2.
int dx_hull_hull(dx_hull *a, dx_hull *b, dxGeom *o1, dxGeom *o2, int flags,
                 dContactGeom *out, int skip);

#endif
