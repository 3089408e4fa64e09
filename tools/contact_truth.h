// SPDX-License-Identifier: BSD-3-Clause
//
// contact_truth.h -- the ground truth the collision backends are held to
// (issue 14): for two convex geoms, from their support functions alone, the
// penetration depth (or, apart, the distance), the direction achieving it,
// and whether a point lies within a shape. It uses ODE's public API and maths
// only (no collider, no backend), so it can be built against any ODE.
//
// Classes: sphere, box, capsule, cylinder, plane (a half-space, solid below).
// Two planes are not a pair. Computed in double whatever dReal is.

#ifndef CONTACT_TRUTH_H
#define CONTACT_TRUTH_H

#include <ode/ode.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct contact_truth {
    int overlap;        // 1 when the shapes overlap (depth > 0)
    double depth;       // penetration depth; apart: minus the distance between them
    double normal[3];   // unit, ODE's sense: moving g1 by depth along it separates
                        // the pair (apart: moving g1 by depth brings it to touch)
} contact_truth;

// 1 if the class has a support function here (see above).
int contact_truth_supports(int geom_class);

// The point of g furthest along dir (need not be unit) into point, and
// dir . point. g must not be a plane.
double contact_truth_support(dGeomID g, const double dir[3], double point[3]);

// The truth for (g1, g2): returns 1, or 0 (out untouched) when a class is not
// supported or both are planes. The depth is the least, over unit directions
// u, of h2(u) + h1(-u) (h: support value), the overlap along u: a dense
// search on the sphere refined by local pattern searches from its best
// minima. Measured accuracy: tools/README.md (better than 1e-9 on unit
// sizes for sphere-sphere, sphere-box, box-plane and box-box).
int contact_truth_compute(dGeomID g1, dGeomID g2, contact_truth *out);

// Signed depth of point p in g: positive inside (distance to the surface),
// negative outside (minus the distance to the shape).
double contact_truth_point_depth(dGeomID g, const double p[3]);

// 1 if p lies within g up to tol (its point depth is at least -tol).
int contact_truth_point_inside(dGeomID g, const double p[3], double tol);

#ifdef __cplusplus
}
#endif

#endif
