// SPDX-License-Identifier: BSD-3-Clause
//
// collide_ccd.h -- what the libccd colliders' two files share: the convex
// shapes (box, cylinder, capsule) in world coordinates and in double
// precision whatever dReal is, their support functions, and the contact
// manifold built once the normal and depth are known.

#ifndef DX_COLLIDE_CCD_H
#define DX_COLLIDE_CCD_H

#include "native_colliders.h"

typedef enum dx_convex_kind {
    DX_CONVEX_BOX,
    DX_CONVEX_CYLINDER,
    DX_CONVEX_CAPSULE
} dx_convex_kind;

typedef struct dx_convex {
    dx_convex_kind kind;
    double c[3];        // centre
    double ax[3][3];    // the local axes x, y, z in world coordinates
    double half[3];     // box: half sides; cylinder, capsule: radius, radius, half length
} dx_convex;

// The support value max over x in s of m . x (m of any length).
double dx_convex_extent(const dx_convex *s, const double m[3]);
// A point of s where m . x is largest.
void dx_convex_support(const dx_convex *s, const double m[3], double out[3]);

typedef struct dx_ccd_point {
    double pos[3], depth;
} dx_ccd_point;

// The most contact points a manifold holds (two 16-gons clipped, and spare).
enum { DX_CCD_MAX_POINTS = 48 };

// The contact points of a (moved along the unit normal n by `depth`, a and
// b touch) into out: the clipped contact features where they are flat, else
// one point; at most `max` (the deepest and a spread), at least one.
int dx_ccd_manifold(const dx_convex *a, const dx_convex *b, const double n[3], double depth,
                    dx_ccd_point *out, int max);

#endif
