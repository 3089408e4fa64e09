// SPDX-License-Identifier: BSD-3-Clause
//
// backend_shadow.h -- shadow mode inside the collision library (backend.h):
// running a second backend beside the selected one, comparing the two
// results with the contract's tolerances, and keeping what disagreed.

#ifndef DX_BACKEND_SHADOW_H
#define DX_BACKEND_SHADOW_H

#include <ode/backend.h>

#include "geom_internal.h"

// The contract's tolerances (include/ode/backend.h says them in words).
#define DX_SHADOW_DEPTH_ABS 0.005      // depth: 5 mm ...
#define DX_SHADOW_DEPTH_REL 0.05       // ... + 5 % of the depth
#define DX_SHADOW_NORMAL_DEG 10.0      // normals, where both are deeper than:
#define DX_SHADOW_NORMAL_MIN_DEPTH 1e-4
#define DX_SHADOW_POINT_ABS 0.01       // a point outside a shape: 1 cm ...
#define DX_SHADOW_POINT_REL 0.1        // ... + 10 % of its depth
#define DX_SHADOW_SPREAD 0.01          // a manifold spreads over more than 1 cm

// How two results of one pair compare.
typedef struct dxShadowVerdict {
    int kinds;                 // dCOLLISION_SHADOW_* bits
    double depth_error;        // |deepest depth difference| (0 when neither touches)
    double normal_error;       // degrees between the deepest normals (0 if not compared)
    double point_first;        // farthest a first-result point lies outside a shape
    double point_shadow;       // ... a shadow-result point
} dxShadowVerdict;

// Compare the selected backend's na contacts `a` (stride skip) with the
// shadow's nb contacts `b` (packed) for (o1, o2); max is the contact budget
// both were given.
void dxShadowCompare(dxGeom *o1, dxGeom *o2, int max, const dContactGeom *a, int na, int skip,
                     const dContactGeom *b, int nb, dxShadowVerdict *v);

// Signed depth of point p in g (positive inside); returns 0 when the class
// has no point depth here (rays, meshes, heightfields, user classes).
int dxShadowPointDepth(dxGeom *g, const dReal p[3], double *depth);

// dCollide through `first` (which answers) and `shadow` (compared, counted).
int dxShadowCollide(const dCollisionBackend *first, const dCollisionBackend *shadow,
                    dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip);

// Shadow mode was turned on: print the report at exit (registered once).
void dxShadowReportAtExit(void);
// Call notify (a backend cache notification) on g with its shadow cache
// slot in place, if that slot holds anything.
void dxShadowNotify(dxGeom *g, void (*notify)(dxGeom *g));
// The summary table and the first disagreement of each pair class, read
// through the public getters.
void dxShadowPrint(FILE *f);

#endif
