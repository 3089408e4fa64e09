// SPDX-License-Identifier: BSD-3-Clause
//
// shapes.h -- the built-in geometry classes' data, for their own files and
// for the native colliders. Sizes are validated by the public setters.

#ifndef DX_SHAPES_H
#define DX_SHAPES_H

#include "geom_internal.h"

typedef struct dxSphere {
    dxGeom g;
    dReal radius;
} dxSphere;

typedef struct dxBox {
    dxGeom g;
    dVector3 side;                // full side lengths
} dxBox;

typedef struct dxCapsule {        // along local z; length excludes the caps
    dxGeom g;
    dReal radius, length;
} dxCapsule;

typedef struct dxCylinder {       // along local z; full length
    dxGeom g;
    dReal radius, length;
} dxCylinder;

typedef struct dxPlane {          // n . x = d with |n| = 1; solid where n . x < d
    dxGeom g;
    dReal p[4];
} dxPlane;

typedef struct dxRay {            // from pos along R's z column, length long
    dxGeom g;
    dReal length;
    int first_contact, backface_cull, closest_hit;
} dxRay;

typedef struct dxGeomTransform {
    dxGeom g;
    dxGeom *obj;                  // the held geom (pose relative to the transform)
    int cleanup;                  // destroy obj with the transform
    int info;                     // 0: contacts name obj; 1: the transform (guide 10.7.7)
    dVector3 world_pos;           // obj's world pose, computed for collisions
    dMatrix3 world_R;
} dxGeomTransform;

// The world pose of a transform's geom (into world_pos / world_R); returns obj
// temporarily posed there (restore with dxTransformRestore).
dxGeom *dxTransformPoseObject(dxGeomTransform *t, const dReal **saved_pos,
                              const dReal **saved_R);
void dxTransformRestore(dxGeomTransform *t, const dReal *saved_pos, const dReal *saved_R);

// The class operations of the built-in classes (geom_*.c).
extern const dxGeomClassOps dx_sphere_ops, dx_box_ops, dx_capsule_ops, dx_cylinder_ops,
    dx_plane_ops, dx_ray_ops, dx_transform_ops;

// An AABB around a local box of half extents h placed at pos with rotation R.
void dxAABBOfBox(dReal aabb[6], const dReal *pos, const dReal *R, const dReal h[3]);

#endif
