// SPDX-License-Identifier: BSD-3-Clause
//
// native_colliders.h -- the native backend's pair colliders. Each takes o1 of
// the first class and o2 of the second (as named), writes at most
// flags & 0xffff contacts (at least 1 is asked) with stride skip, and fills
// every field in ODE's convention: normal pointing into o1 (moving o1 by depth
// along it separates the pair), depth >= 0, pos in the overlap, g1 = o1,
// g2 = o2, side1 = side2 = -1. Returns the count; writes nothing if 0.

#ifndef DX_NATIVE_COLLIDERS_H
#define DX_NATIVE_COLLIDERS_H

#include "../../libodecollide/shapes.h"

typedef int dxCollider(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip);

// Analytic colliders (collide_sphere.c, collide_box.c, collide_capsule.c).
dxCollider dxCollideSphereSphere, dxCollideSphereBox, dxCollideSphereCapsule,
    dxCollideSpherePlane, dxCollideSphereCylinder, dxCollideBoxBox, dxCollideBoxPlane,
    dxCollideCapsuleCapsule, dxCollideCapsuleBox, dxCollideCapsulePlane,
    dxCollideCylinderPlane;

// Rays (collide_ray.c): at most one contact, as BACKENDS.md section 1 defines.
dxCollider dxCollideRaySphere, dxCollideRayBox, dxCollideRayCapsule, dxCollideRayCylinder,
    dxCollideRayPlane;

// Convex pairs without a closed form, through libccd (collide_ccd.c).
dxCollider dxCollideCylinderBox, dxCollideCylinderCapsule, dxCollideCylinderCylinder;

// Trimeshes (collide_trimesh*.c): side1 is the triangle of each contact.
dxCollider dxCollideTriMeshSphere, dxCollideTriMeshBox, dxCollideTriMeshCapsule,
    dxCollideTriMeshCylinder, dxCollideTriMeshPlane, dxCollideTriMeshRay,
    dxCollideTriMeshTriMesh, dxCollideTriMeshConvex;
// Ray-trimesh with the ray first: dxCollideTriMeshRay's contacts flipped,
// made so directly.
dxCollider dxCollideRayTriMesh;
// Trimesh-trimesh computed with o1 as the first mesh, whatever the addresses
// (dxCollideTriMeshTriMesh orders the pair by address so that it mirrors).
dxCollider dxCollideTriMeshTriMeshInOrder;
// The convex hull (collide_convex.c); its triangle mesh pair is
// dxCollideTriMeshConvex (collide_trimesh_convex.c).
dxCollider dxCollideConvexConvex, dxCollideConvexBox, dxCollideConvexPlane, dxCollideConvexSphere,
    dxCollideConvexCapsule, dxCollideConvexCylinder, dxCollideRayConvex;

// Heightfields (collide_heightfield.c): the trimesh colliders on the cells
// under the other geom; side1 is -1.
dxCollider dxCollideHeightfieldSphere, dxCollideHeightfieldBox, dxCollideHeightfieldCapsule,
    dxCollideHeightfieldCylinder, dxCollideHeightfieldRay, dxCollideHeightfieldTriMesh,
    dxCollideHeightfieldConvex;

#endif
