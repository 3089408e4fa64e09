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

// The storage of a box made into a hull (dx_hull_posed's box case).
typedef struct dx_hull_box {
    dReal pts[24], planes[24];
    double wp[8][3], wn[6][3], wd[6];
    dxHullPosedEdge we[12];
    double p_soa[3][8], n_soa[3][8], e_soa[3][12], face_low[6];   // n_soa: zero past 6
    int edges_posed;
} dx_hull_box;

// The hull of a convex geom, posed, copied into h.
void dx_hull_of_geom(dx_hull *h, const dxGeom *g);
// The same without a copy (valid until the next call on this thread): a
// convex geom's kept hull, or a box geom's made or kept (collide_convex_hull.c).
dx_hull *dx_hull_posed(const dxGeom *g);

// Point i in world coordinates.
static inline void dx_hull_vertex(const dx_hull *h, unsigned i, double out[3])
{
    for (int k = 0; k < 3; k++) out[k] = h->wp[i][k];
}

// Plane f in world coordinates: unit outward normal n and offset (n . x = d).
static inline void dx_hull_plane(const dx_hull *h, unsigned f, double n[3], double *d)
{
    for (int k = 0; k < 3; k++) n[k] = h->wn[f][k];
    *d = h->wd[f];
}

// The polygon of plane f: its count and indices.
static inline const unsigned *dx_hull_polygon(const dx_hull *h, unsigned f, unsigned *count)
{
    const unsigned *p = h->polys + h->poly_start[f];
    *count = *p;
    return p + 1;
}

// max over the points of m . x, and (if idx) which point.
double dx_hull_extent(const dx_hull *h, const double m[3], unsigned *idx);
// min and max over the points of m . x.
void dx_hull_interval(const dx_hull *h, const double m[3], double *lo, double *hi);
// Whether the axis m (world) parts a and b.
int dx_hull_axis_separates(const dx_hull *a, const dx_hull *b, const double m[3]);
// Clips [*t0, *t1] to where o + t d (world) is inside h, with planes that d
// runs along (|n . d| below DX_HULL_EPS) kept if o is within tol of them; 0 if
// empty by more than tol (rounding can leave a point's span crossed).
int dx_hull_clip_line(const dx_hull *h, const double o[3], const double d[3], double tol,
                      double *t0, double *t1);

// ---- the separating axis test (collide_convex_sat.c) ----

// An edge pair's axis wins over the best face only if this many times shallower.
#define DX_HULL_EDGE_PREFERENCE 1.05

// The best axis found: its unit normal (into a), its depth, and what it is:
// a face of a (ref 0) or of b (ref 1) with its index, or an edge pair.
typedef struct sat_axis {
    double n[3], depth;
    int ref;            // 0: a's face, 1: b's face, 2: edges
    unsigned face;
    unsigned ea, eb;    // the edges (indices into a's and b's edge lists)
} sat_axis;

// What sat measured, for clearance: the depth along each face axis (if
// both hulls' faces fit), and the edge pairs whose axes may lower the
// clearance along the best face's normal (their edges' indices in a and
// b), unless there were more.
enum { MAX_EDGE_AXES = 1024, KEPT_FACES = 48 };
typedef struct edge_axes {
    double face_s[2][KEPT_FACES];   // for the faces in tested (the others are clearly
    uint64_t tested[2];             // deeper than the best: infinite)
    int faces_kept;
    double margin;   // for rounding, in the screens of depths: 1e-12 times the scale
                     // of the sizes and the coordinates
    unsigned pair[MAX_EDGE_AXES][2];
    int n, overflow;
} edge_axes;

// What a touching pair's last test leaves for its next (only ever a
// first guess: any face and any points give the same result): the face
// that gave the contact axis, of a (side 0) or b (1), and the points qa of
// a and qb of b that bounded the other axes (each hull's point furthest
// towards the other's centre, when they were found). side -1: none.
typedef struct sat_hint {
    int side;
    unsigned face, qa, qb;
} sat_hint;

// 0 if a separating axis parts a and b (into sep); else the face axis and
// the edge axis of least depth (edge->depth is infinite if no edge pair
// counts), and what the clearance needs into found. hint's face and
// points are tried first, and hint's points are set to those used.
int dx_hull_sat(dx_hull *a, dx_hull *b, sat_hint *hint, sat_axis *face, sat_axis *edge,
                edge_axes *found, double sep[3]);
// The exact translation of a along the unit n (the best face axis, of depth
// s_n) that parts it from b, from what dx_hull_sat kept in found.
double dx_hull_clearance(const dx_hull *a, const dx_hull *b, const double n[3], double s_n,
                         const edge_axes *found);

// Hull against hull (separating axes; face contacts clipped, or an edge
// pair's point), as dxCollideBoxBox does for boxes. Contacts name o1, o2.
int dx_hull_hull(dx_hull *a, dx_hull *b, dxGeom *o1, dxGeom *o2, int flags,
                 dContactGeom *out, int skip);

#endif
