// SPDX-License-Identifier: BSD-3-Clause
//
// geom_convex.h -- the convex hull class (ODE 0.16's dCreateConvex): the
// caller's arrays, kept by pointer as ODE keeps them, for the geom's own
// file and the native convex colliders.

#ifndef DX_GEOM_CONVEX_H
#define DX_GEOM_CONVEX_H

#include "shapes.h"

#include <stdint.h>

// An edge of the hull, (a, b) with a < b, between faces f1 and f2 (f2 =
// f1 when the polygons give the edge only once).
typedef struct dxHullEdge {
    unsigned a, b, f1, f2;
} dxHullEdge;

// What a hull found against another geom last time (collide_convex_hull.c),
// tried first the next time the pair meets: the axis that parted them, so
// a pair that stays apart is rejected by one axis; or, if they touched, the
// face that gave the contact axis, the first guess that bounds the others
// (a pair resting on one another keeps it). Only a hint: `other` is never
// dereferenced (it may be destroyed and its address reused), an axis that
// no longer separates is simply not used, and any face is a valid guess.
enum { DX_CONVEX_AXIS_CACHE = 8 };
typedef struct dxHullAxisHint {
    double axis[3];               // in this hull's frame, if !touching
    int touching;                 // else: the face of this hull (side 0) or the other's,
    int side;                     // and a point of each that bounded the other axes
    unsigned face, own_point, other_point;
} dxHullAxisHint;

// The hull posed in the world (by dxConvexPose and the native colliders,
// collide_convex_hull.c), kept while the geom's pose stays what it was
// made for: a hull meets several partners a step and is posed once. The
// geom's own arrays are assumed unchanged between dGeomSetConvex calls (as
// the edge list already assumes). An edge's direction u = b - a with u . u,
// and the sum of its faces' normals n1 + n2 with its square.
typedef struct dxHullPosedEdge {
    double u[3], sum[3], uu, ss;
} dxHullPosedEdge;

typedef struct dxHullPose {
    dReal pos[3], R[12];          // the pose the arrays were made for
    double (*pts)[3];             // pointcount world points
    double (*normals)[3];         // planecount unit outward normals ...
    double *offsets;              // ... and offsets (n . x = d)
    dxHullPosedEdge *edges;       // edgecount
    double *face_low;             // per plane: a floor under n . x over its polygon
    // The same by coordinate, for loops over many at once: the points'
    // x, y, z, the normals' x, y, z; and with the edges, each edge's cross
    // product of its faces' normals n2 x n1 (the normal of its arc's circle).
    // The normals' and edges' rows hold a multiple of four, zero past the
    // planes and the edges.
    double *px, *py, *pz, *nx, *ny, *nz, *ex, *ey, *ez;
    double box[6];                // their bounding box (lo, hi by axis)
    int edges_valid;              // what else the pair test made for it (bits: the
                                  // faces' floors, the edges; only when needed)
    int valid;                    // points and planes hold that pose (last: next to the
                                  // hull's first fields, dxConvex)
} dxHullPose;

// A hull as the native colliders see it (backends/native/collide_convex*.c):
// the geom's arrays, its pose, and the same posed in the world (points,
// face planes, and the edges once the pair test needs them): a convex
// geom's is kept on the geom while its pose stays (dxConvexPose), a box's
// is made by the collider.
typedef struct dx_hull {
    // What a pair test reads first (the bounding spheres, the convex geom's
    // hints), together.
    double c[3];
    double radius;            // a bound on |x - c| over the points as posed
    struct dxConvex *convex;  // the convex geom (its axis hints), NULL for a box
    const dReal *pts;         // npts x (x, y, z), local
    const dReal *planes;      // nplanes x (a, b, c, d), local, outward
    const unsigned *polys;    // per plane: count, indices
    const unsigned *poly_start;   // per plane: where its polygon starts in polys
    const dxHullEdge *edges;  // each edge once, with its two faces
    const unsigned *vert_start, *vert_edges;   // per point v: the edges at it, in order,
                              // vert_edges[vert_start[v] .. vert_start[v + 1]) (NULL: none kept)
    unsigned npts, nplanes, nedges;
    double R[9];              // world = R local + c (row-major)
    double size;              // the largest distance of a point from the origin of the frame
    double rot_err;           // |R^T R - I| (Frobenius): how far R is from a rotation
    double centre[3];         // a point inside, in the world (for the colliders' first
                              // guesses only: no result depends on which)
    const double (*wp)[3];    // the points in the world
    const double (*wn)[3];    // the planes in the world: unit outward normals ...
    const double *wd;         // ... and offsets
    dxHullPosedEdge *we;      // the edges in the world, and per plane
    double *face_low;         // a floor under n . x over its polygon
    const double *plane_dev;  // per plane: how far its polygon dips under it (NULL: none)
    int *edges_posed;         // which of face_low and we (with ex, ey, ez) are made
                              // (bits, collide_convex_sat.c)
    // The edges by face as bit sets (dxConvex's by_f1, by_f2, lone, nbr; NULL
    // beyond 64 edges or planes).
    const uint64_t *by_f1, *by_f2;
    uint64_t lone;
    const uint64_t *nbr;      // per plane: it and the planes it shares an edge with
    // Each edge's first face (row 0) and second face (row 1) as bytes, 0x80
    // past the edges (NULL beyond 32 edges or 16 planes): by_f1 and by_f2
    // the other way round, for turning sets of faces into sets of edges.
    const uint8_t (*edge_faces)[32];
    // The points, normals and edges' n2 x n1 by coordinate (dxHullPose; the
    // normals and edges zero past their count up to a multiple of four).
    const double *px, *py, *pz, *nx, *ny, *nz;
    double *ex, *ey, *ez;     // (with the edges: n2 x n1)
} dx_hull;

typedef struct dxConvex {
    dxGeom g;
    const dReal *planes;          // planecount x (a, b, c, d): a x + b y + c z = d, outward
    const dReal *points;          // pointcount x (x, y, z), in the geom's frame
    const unsigned *polygons;     // per plane: count, then count point indices
    unsigned planecount, pointcount;
    dxHullEdge *edges;            // derived from the polygons, owned by the geom
    unsigned edgecount;
    unsigned *poly_start;         // per plane: where its polygon starts in polygons
    unsigned *vert_start, *vert_edges;   // per point: the edges at it (dx_hull's)
    // For hulls of at most 64 edges and 64 planes (else NULL): per plane, the
    // set of edges (bit k: edge k) whose first face it is, and whose second
    // face; the edges with one face only.
    uint64_t *by_f1, *by_f2;
    uint64_t lone;
    uint64_t *nbr;                // per plane: it and the planes it shares an edge with
    uint8_t edge_faces[2][32];    // dx_hull's, if the hull has at most 32 edges, 16 planes
    double size;                  // the largest distance of a point from the frame's origin
    double mean[3];               // the points' mean (the hull's centre, posed)
    double *plane_len;            // per plane: the length of its normal as given ...
    double *plane_dev;            // ... and how far below it its polygon's points reach
    // The axis hints, hints[k] against the geom hint_other[k] (together in
    // one cache line: a pair test looks its partner up among them first).
    const void *hint_other[DX_CONVEX_AXIS_CACHE];
    dxHullAxisHint hints[DX_CONVEX_AXIS_CACHE];
    unsigned next_hint;           // the entry replaced next
    dxHullPose pose;
    dx_hull hull;                 // the pose as the native colliders see it (pose.valid and
                                  // the hull's first fields: what a pair test reads first)
    void *derived;                // one block: edges, poly_start, the pose's arrays
    size_t derived_size;
} dxConvex;

extern const dxGeomClassOps dx_convex_ops;

// Points and planes of a hull's local arrays posed by R (row-major) and c
// (world = R local + c) into wp and by coordinate p3[3], and into unit
// outward normals wn (p3's way: n3[3]) and offsets wd; len: the planes'
// normal lengths, or NULL to take them here.
void dxHullPosePointsPlanes(const double R[9], const double c[3], const dReal *pts, unsigned npts,
                            const dReal *planes, const double *len, unsigned nplanes,
                            double (*wp)[3], double *const p3[3], double (*wn)[3],
                            double *const n3[3], double *wd);

// How far the row-major R is from a rotation, |R^T R - I| (Frobenius), into
// h->rot_err, and from it (with h->size and h->c) a bound on how far from
// c the posed points lie, into h->radius: |R p| <= sqrt(1 + rot_err) |p|,
// plus the rounding of R p + c.
void dxHullPoseBounds(struct dx_hull *h);

// The convex geom's hull posed in the world for its position and rotation
// (c->pose, c->hull), unless it already is (compared bit for bit).
void dxConvexPose(dxConvex *c);

// dxConvexPose where the geom may have moved: a valid pose is current while
// the geom's AABB_BAD flag is clear (the flag is cleared only right after
// compute_aabb, which poses it, and set by every move), so the bits are
// compared only when the flag is set (the colliders meet a hull several
// times a step).
static inline void dxConvexPoseIfMoved(dxConvex *c)
{
    if (!c->pose.valid || (c->g.flags & DX_GEOM_AABB_BAD)) dxConvexPose(c);
}

#endif
