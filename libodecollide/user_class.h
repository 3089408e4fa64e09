// SPDX-License-Identifier: BSD-3-Clause
//
// user_class.h -- user-defined geometry classes, for dCollide and spaces.

#ifndef DX_USER_CLASS_H
#define DX_USER_CLASS_H

#include "geom_internal.h"

typedef struct dxUserClass {
    dGeomClass info;
    char name[32];
    // info.collider's answers, by the other class, once asked.
    dColliderFn *collider[dGeomNumClasses];
    unsigned char asked[dGeomNumClasses];
} dxUserClass;

// The class of a user geom, or NULL for a built-in class.
const dxUserClass *dxUserClassOf(const dxGeom *g);
// The collider of user geom g's class for another class (or NULL).
dColliderFn *dxUserColliderFor(const dxGeom *g, int other_class);
// 0 if the box test of a's or b's user class rules the pair out, else 1: for
// the spaces' pair test, after the AABBs were found to overlap.
int dxUserAABBTest(dxGeom *a, dxGeom *b);

#endif
