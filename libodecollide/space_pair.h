// SPDX-License-Identifier: BSD-3-Clause
//
// space_pair.h -- the spaces' pair test (dxGeomsMayTouch, dxSpaceTestPair in
// space.c), split so that a space's inner loop can decide the common case --
// the boxes are apart -- inline, and the rest without testing the boxes twice.

#ifndef DX_SPACE_PAIR_H
#define DX_SPACE_PAIR_H

#include "user_class.h"

// 1 if the closed boxes a and b (minx maxx miny maxy minz maxz) overlap.
static inline int dxAABBsOverlap(const dReal *a, const dReal *b)
{
    return a[0] <= b[1] && b[0] <= a[1] && a[2] <= b[3] && b[2] <= a[3] && a[4] <= b[5] &&
           b[4] <= a[5];
}

// dxGeomsMayTouch for geoms whose boxes are known to overlap: both enabled,
// not two geoms of one body (a == b is the guide's (X, X) of dSpaceCollide2),
// category and collide bits matching, and a user class's box test, if any,
// agreeing.
static inline int dxGeomsMayTouchOverlapping(dxGeom *a, dxGeom *b)
{
    if (!(a->flags & b->flags & DX_GEOM_ENABLED)) return 0;
    if (a != b && a->body && a->body == b->body) return 0;
    if (!(a->category_bits & b->collide_bits) && !(b->category_bits & a->collide_bits)) return 0;
    return (a->ops->cls < dFirstUserClass && b->ops->cls < dFirstUserClass) || dxUserAABBTest(a, b);
}

// dxSpaceTestPair inline, not counted: the callback called when the pair
// may touch. A loop over many pairs counts them in a local and adds that to
// dx_aabb_tests once (a global incremented per pair is a store that the
// next pair's increment waits on).
static inline void dxSpaceTestPairUncounted(dxGeom *a, dxGeom *b, void *data, dNearCallback *cb)
{
    if (dxAABBsOverlap(a->aabb, b->aabb) && dxGeomsMayTouchOverlapping(a, b)) cb(data, a, b);
}

// dxSpaceTestPair inline: one AABB test counted in dx_aabb_tests, the
// callback called when the pair may touch.
static inline void dxSpaceTestPairInline(dxGeom *a, dxGeom *b, void *data, dNearCallback *cb)
{
    dx_aabb_tests++;
    dxSpaceTestPairUncounted(a, b, data, cb);
}

#endif
