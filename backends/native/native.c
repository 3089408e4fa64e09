// SPDX-License-Identifier: BSD-3-Clause
//
// native.c -- the native backend: a table of pair colliders by class, used
// for either argument order (the reversed call's contacts are flipped).

#include "../../libodecollide/backend_internal.h"
#include "native_colliders.h"

enum { NATIVE_CLASSES = dHeightfieldClass + 1 };   // sphere ... ray, ..., trimesh, heightfield

// table[a][b] collides (class a, class b) in that order; NULL if no collider.
static dxCollider *const table[NATIVE_CLASSES][NATIVE_CLASSES] = {
    [dSphereClass] = { [dSphereClass] = dxCollideSphereSphere, [dBoxClass] = dxCollideSphereBox,
                       [dCapsuleClass] = dxCollideSphereCapsule,
                       [dCylinderClass] = dxCollideSphereCylinder,
                       [dPlaneClass] = dxCollideSpherePlane },
    [dBoxClass] = { [dBoxClass] = dxCollideBoxBox, [dPlaneClass] = dxCollideBoxPlane },
    [dCapsuleClass] = { [dBoxClass] = dxCollideCapsuleBox,
                        [dCapsuleClass] = dxCollideCapsuleCapsule,
                        [dPlaneClass] = dxCollideCapsulePlane },
    [dCylinderClass] = { [dBoxClass] = dxCollideCylinderBox,
                         [dCapsuleClass] = dxCollideCylinderCapsule,
                         [dCylinderClass] = dxCollideCylinderCylinder,
                         [dPlaneClass] = dxCollideCylinderPlane },
    [dRayClass] = { [dSphereClass] = dxCollideRaySphere, [dBoxClass] = dxCollideRayBox,
                    [dCapsuleClass] = dxCollideRayCapsule,
                    [dCylinderClass] = dxCollideRayCylinder, [dPlaneClass] = dxCollideRayPlane,
                    [dConvexClass] = dxCollideRayConvex, [dTriMeshClass] = dxCollideRayTriMesh },
    [dConvexClass] = { [dSphereClass] = dxCollideConvexSphere, [dBoxClass] = dxCollideConvexBox,
                       [dCapsuleClass] = dxCollideConvexCapsule,
                       [dCylinderClass] = dxCollideConvexCylinder,
                       [dPlaneClass] = dxCollideConvexPlane, [dConvexClass] = dxCollideConvexConvex },
    [dTriMeshClass] = { [dSphereClass] = dxCollideTriMeshSphere, [dBoxClass] = dxCollideTriMeshBox,
                        [dCapsuleClass] = dxCollideTriMeshCapsule,
                        [dCylinderClass] = dxCollideTriMeshCylinder,
                        [dPlaneClass] = dxCollideTriMeshPlane, [dRayClass] = dxCollideTriMeshRay,
                        [dTriMeshClass] = dxCollideTriMeshTriMesh,
                        [dConvexClass] = dxCollideTriMeshConvex },
    [dHeightfieldClass] = { [dSphereClass] = dxCollideHeightfieldSphere,
                            [dBoxClass] = dxCollideHeightfieldBox,
                            [dCapsuleClass] = dxCollideHeightfieldCapsule,
                            [dCylinderClass] = dxCollideHeightfieldCylinder,
                            [dRayClass] = dxCollideHeightfieldRay,
                            [dTriMeshClass] = dxCollideHeightfieldTriMesh,
                            [dConvexClass] = dxCollideHeightfieldConvex },
};

static int native_supports(int c1, int c2)
{
    if (c1 < 0 || c2 < 0 || c1 >= NATIVE_CLASSES || c2 >= NATIVE_CLASSES) return 0;
    return table[c1][c2] != NULL || table[c2][c1] != NULL;
}

static int native_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip)
{
    int c1 = o1->ops->cls, c2 = o2->ops->cls;
    if (!native_supports(c1, c2)) return 0;
    if (table[c1][c2]) return table[c1][c2](o1, o2, flags, contact, skip);
    int n = table[c2][c1](o2, o1, flags, contact, skip);
    dxFlipContacts(contact, n, skip);
    return n;
}

static const dCollisionBackend native_backend = { "native", native_supports, native_collide,
                                                  NULL, NULL };

const dCollisionBackend *dxNativeBackend(void) { return &native_backend; }

// The route of every pair of classes, each written once (a pointer to one
// of these is what dCollide's table publishes, so a reader never sees half
// of one).
static dxRoute routes[NATIVE_CLASSES][NATIVE_CLASSES];
static int routes_made;

const dxRoute *dxNativeRoute(int c1, int c2)
{
    if (c1 < 0 || c2 < 0 || c1 >= NATIVE_CLASSES || c2 >= NATIVE_CLASSES) return NULL;
    if (!routes_made) {
        for (int a = 0; a < NATIVE_CLASSES; a++)
            for (int b = 0; b < NATIVE_CLASSES; b++)
                routes[a][b] = table[a][b] ? (dxRoute){ table[a][b], 0 }
                                           : (dxRoute){ table[b][a], 1 };
        routes_made = 1;
    }
    return routes[c1][c2].fn ? &routes[c1][c2] : NULL;
}
