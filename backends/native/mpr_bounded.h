// SPDX-License-Identifier: BSD-3-Clause
//
// mpr_bounded.h -- libccd's MPR (minkowski portal refinement) with an end.
//
// MPR's portal loops have no iteration bound of their own, and on a
// Minkowski difference of (nearly) no volume or of extreme proportions (a
// zero-radius capsule against a point-like cylinder; a hull 1e-6 thick
// against a zero-radius cylinder 1e6 long) they may never end. The query
// here counts the support calls of both shapes; the call past
// DX_MPR_MAX_SUPPORTS (the tests' and the fuzz corpora's queries make at
// most ~100) leaves MPR at once (longjmp: MPR holds nothing but its stack),
// and the query is undecided: the caller decides the pair another way (both
// callers: the least depth over directions). Collapsing the support points
// to the shapes' centres instead, as this did first, ends the zero-radius
// capsule's case but not the thin hull's: MPR kept asking.

#ifndef DX_MPR_BOUNDED_H
#define DX_MPR_BOUNDED_H

enum { DX_MPR_MAX_SUPPORTS = 1000 };

// A shape as MPR sees it: its support point in direction dir (not unit) and
// a point inside it.
typedef void dx_mpr_support_fn(const void *shape, const double dir[3], double out[3]);
typedef struct dx_mpr_shape {
    const void *shape;
    dx_mpr_support_fn *support;
    double centre[3];
} dx_mpr_shape;

typedef enum dx_mpr_verdict {
    DX_MPR_APART,
    DX_MPR_OVERLAP,     // dir: libccd's direction (to move b along to part the pair)
    DX_MPR_UNDECIDED    // no answer within DX_MPR_MAX_SUPPORTS support calls
} dx_mpr_verdict;

// ccdMPRPenetration on a and b with the given tolerance (libccd's
// mpr_tolerance), bounded as above; dir is set on DX_MPR_OVERLAP only.
dx_mpr_verdict dx_mpr_penetration(const dx_mpr_shape *a, const dx_mpr_shape *b, double tolerance,
                                  double dir[3]);

#endif
