/* SPDX-License-Identifier: BSD-3-Clause */
/* collision.h -- geoms, collision detection, the geometry classes, user
 * classes and utilities (guide chapter 10), in the collision library.
 *
 * Bad arguments (a NULL or destroyed geom, a negative size, a non-placeable
 * geom given a position, skip smaller than sizeof(dContactGeom), ...) are
 * reported through the debug handler naming the function and the argument
 * (error.h); the call then has no effect. */
#ifndef ODE_COLLISION_H
#define ODE_COLLISION_H

#include <ode/common.h>
#include <ode/contact.h>
#include <ode/collision_space.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- geoms in general (10.2, 10.4) --------------------------------------- */

/** Removes the geom from its space and destroys it (a space with its geoms if
 *  its cleanup mode is on). */
ODE_API void dGeomDestroy(dGeomID geom);
ODE_API void dGeomSetData(dGeomID geom, void *data);
ODE_API void *dGeomGetData(dGeomID geom);
/** Attach to a body: geom and body then share position and rotation. body 0
 *  detaches; the geom keeps the body's last pose. Placeable geoms only. */
ODE_API void dGeomSetBody(dGeomID geom, dBodyID body);
ODE_API dBodyID dGeomGetBody(dGeomID geom);
/* Pose of a placeable geom (moves its body too, if attached). */
ODE_API void dGeomSetPosition(dGeomID geom, dReal x, dReal y, dReal z);
ODE_API void dGeomSetRotation(dGeomID geom, const dMatrix3 R);
ODE_API void dGeomSetQuaternion(dGeomID geom, const dQuaternion Q);
/** Pointers into the geom (or its body), valid until it changes. */
ODE_API const dReal *dGeomGetPosition(dGeomID geom);
ODE_API void dGeomCopyPosition(dGeomID geom, dVector3 pos);
ODE_API const dReal *dGeomGetRotation(dGeomID geom);
ODE_API void dGeomCopyRotation(dGeomID geom, dMatrix3 R);
ODE_API void dGeomGetQuaternion(dGeomID geom, dQuaternion result);
/** Axis-aligned bounding box (minx, maxx, miny, maxy, minz, maxz). */
ODE_API void dGeomGetAABB(dGeomID geom, dReal aabb[6]);
ODE_API int dGeomIsSpace(dGeomID geom);
/** The space that contains the geom, or 0. */
ODE_API dSpaceID dGeomGetSpace(dGeomID);
ODE_API int dGeomGetClass(dGeomID geom);
/** Two geoms may touch only if the category bits of one share a bit with the
 *  collide bits of the other, either way round. All bits set by default. */
ODE_API void dGeomSetCategoryBits(dGeomID geom, unsigned long bits);
ODE_API void dGeomSetCollideBits(dGeomID geom, unsigned long bits);
ODE_API unsigned long dGeomGetCategoryBits(dGeomID);
ODE_API unsigned long dGeomGetCollideBits(dGeomID);
/** Disabled geoms are skipped by dSpaceCollide and dSpaceCollide2. */
ODE_API void dGeomEnable(dGeomID geom);
ODE_API void dGeomDisable(dGeomID geom);
ODE_API int dGeomIsEnabled(dGeomID geom);

/* Low-level control (ODE 0.16): class-specific settings, each a control
 * class and code with an argument of a fixed size. */
enum {
    dGeomCommonControlClass = 0,
    dGeomColliderControlClass = 1
};
enum {
    dGeomCommonAnyControlCode = 0,
    dGeomColliderSetMergeSphereContactsControlCode = 1,
    dGeomColliderGetMergeSphereContactsControlCode = 2
};
enum {
    dGeomColliderMergeContactsValue__Default = 0,   /* with Set...: restore the default */
    dGeomColliderMergeContactsValue_None = 1,
    dGeomColliderMergeContactsValue_Normals = 2,
    dGeomColliderMergeContactsValue_Full = 3
};
/** Run control code controlCode of class controlClass on geom with the
 *  argument dataValue of *dataSize bytes. Returns 1 on success. If *dataSize
 *  is not the size the code expects, it is set to that size and 0 is returned
 *  (so NULL and 0 ask for the size); dGeomCommonAnyControlCode succeeds if
 *  the geom has any code in the class. The merge-sphere-contacts codes
 *  (an int, dGeomColliderMergeContactsValue_*) are understood by triangle
 *  meshes only. A geom that understands none of the class is reported
 *  through the debug handler, as ODE does; *dataSize is then set to 0 and 0
 *  returned. */
ODE_API int dGeomLowLevelControl(dGeomID geom, int controlClass, int controlCode,
                                 void *dataValue, int *dataSize);

/* Point and vector conversions in the geom's frame (ODE 0.16). */
ODE_API void dGeomGetRelPointPos(dGeomID geom, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dGeomGetPosRelPoint(dGeomID geom, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dGeomVectorToWorld(dGeomID geom, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dGeomVectorFromWorld(dGeomID geom, dReal px, dReal py, dReal pz, dVector3 result);

/** Box-box test on boxes given by centre, rotation and side lengths (ODE 0.16):
 *  returns the contacts written (flags and skip as dCollide; g1, g2 left 0),
 *  normal = the direction from box 1 into box 2, depth = the penetration along
 *  it, return_code = the separating axis: 1-3 box 1's faces, 4-6 box 2's,
 *  7-15 the edge pairs; 0 if the boxes are apart. */
ODE_API int dBoxBox(const dVector3 p1, const dMatrix3 R1, const dVector3 side1,
                    const dVector3 p2, const dMatrix3 R2, const dVector3 side2,
                    dVector3 normal, dReal *depth, int *return_code, int flags,
                    dContactGeom *contact, int skip);

/* ---- geom offsets (ODE 0.16) --------------------------------------------
 * A geom on a body may sit at a fixed pose relative to the body (the modern
 * replacement for a geometry transform). Setting an offset needs a body; the
 * geom's position and rotation are then the body's pose composed with the
 * offset. dGeomSetPosition/Rotation/Quaternion on an offset geom move the body
 * so that the geom gets there. dGeomSetBody to another body clears the offset;
 * to 0 keeps the geom where it is. Without an offset the getters give a zero
 * position and the identity. */
ODE_API void dGeomSetOffsetPosition(dGeomID geom, dReal x, dReal y, dReal z);
ODE_API void dGeomSetOffsetRotation(dGeomID geom, const dMatrix3 R);
ODE_API void dGeomSetOffsetQuaternion(dGeomID geom, const dQuaternion Q);
/** The offset that puts the geom at this world pose, the body staying put. */
ODE_API void dGeomSetOffsetWorldPosition(dGeomID geom, dReal x, dReal y, dReal z);
ODE_API void dGeomSetOffsetWorldRotation(dGeomID geom, const dMatrix3 R);
ODE_API void dGeomSetOffsetWorldQuaternion(dGeomID geom, const dQuaternion);
ODE_API void dGeomClearOffset(dGeomID geom);
ODE_API int dGeomIsOffset(dGeomID geom);
ODE_API const dReal *dGeomGetOffsetPosition(dGeomID geom);
ODE_API void dGeomCopyOffsetPosition(dGeomID geom, dVector3 pos);
ODE_API const dReal *dGeomGetOffsetRotation(dGeomID geom);
ODE_API void dGeomCopyOffsetRotation(dGeomID geom, dMatrix3 R);
ODE_API void dGeomGetOffsetQuaternion(dGeomID geom, dQuaternion result);

/* ---- collision detection (10.5) ---------------------------------------- */

/** Ask only for some contacts, not the best ones (ODE 0.16; accepted). */
#define CONTACTS_UNIMPORTANT 0x80000000

/** Contacts between o1 and o2: at most flags & 0xffff (0 counts as 1), the
 *  i-th written at (char *)contact + i * skip. Returns how many; with 0 the
 *  array is untouched. A space given as o1 or o2 has its geoms tested. */
ODE_API int dCollide(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip);
/** Call callback for every pair of geoms in the space whose boxes overlap
 *  (never a pair twice; nested spaces are passed as geoms). */
ODE_API void dSpaceCollide(dSpaceID space, void *data, dNearCallback *callback);
/** Call callback for pairs of one geom of o1 and one of o2 (each a geom or a
 *  space, the four cases of guide 10.5.2). */
ODE_API void dSpaceCollide2(dGeomID space1, dGeomID space2, void *data,
                            dNearCallback *callback);

/* ---- classes (10.7) ------------------------------------------------------ */

enum { dMaxUserClasses = 4 };

enum {
    dSphereClass = 0,
    dBoxClass,
    dCapsuleClass,
    dCylinderClass,
    dPlaneClass,
    dRayClass,
    dConvexClass,
    dGeomTransformClass,
    dTriMeshClass,
    dHeightfieldClass,
    dFirstSpaceClass,
    dSimpleSpaceClass = dFirstSpaceClass,
    dHashSpaceClass,
    dSweepAndPruneSpaceClass,
    dQuadTreeSpaceClass,
    dLastSpaceClass = dQuadTreeSpaceClass,
    dFirstUserClass,
    dLastUserClass = dFirstUserClass + dMaxUserClasses - 1,
    dGeomNumClasses
};

/** Sphere (10.7.1). Radius > 0. PointDepth: > 0 inside, < 0 outside. */
ODE_API dGeomID dCreateSphere(dSpaceID space, dReal radius);
ODE_API void dGeomSphereSetRadius(dGeomID sphere, dReal radius);
ODE_API dReal dGeomSphereGetRadius(dGeomID sphere);
ODE_API dReal dGeomSpherePointDepth(dGeomID sphere, dReal x, dReal y, dReal z);

/** Box (10.7.2) with side lengths lx, ly, lz (> 0). */
ODE_API dGeomID dCreateBox(dSpaceID space, dReal lx, dReal ly, dReal lz);
ODE_API void dGeomBoxSetLengths(dGeomID box, dReal lx, dReal ly, dReal lz);
ODE_API void dGeomBoxGetLengths(dGeomID box, dVector3 result);
ODE_API dReal dGeomBoxPointDepth(dGeomID box, dReal x, dReal y, dReal z);

/** Plane a x + b y + c z = d (10.7.3), not placeable; the solid is below it.
 *  (a, b, c) must have a length: it is normalised (and d with it). */
ODE_API dGeomID dCreatePlane(dSpaceID space, dReal a, dReal b, dReal c, dReal d);
ODE_API void dGeomPlaneSetParams(dGeomID plane, dReal a, dReal b, dReal c, dReal d);
ODE_API void dGeomPlaneGetParams(dGeomID plane, dVector4 result);
ODE_API dReal dGeomPlanePointDepth(dGeomID plane, dReal x, dReal y, dReal z);

/** Capsule, the guide's capped cylinder (10.7.4): along local z, length of
 *  the cylindrical part (without the caps), radius of both. */
ODE_API dGeomID dCreateCapsule(dSpaceID space, dReal radius, dReal length);
ODE_API void dGeomCapsuleSetParams(dGeomID ccylinder, dReal radius, dReal length);
ODE_API void dGeomCapsuleGetParams(dGeomID ccylinder, dReal *radius, dReal *length);
ODE_API dReal dGeomCapsulePointDepth(dGeomID ccylinder, dReal x, dReal y, dReal z);
#define dCreateCCylinder dCreateCapsule
#define dGeomCCylinderSetParams dGeomCapsuleSetParams
#define dGeomCCylinderGetParams dGeomCapsuleGetParams
#define dGeomCCylinderPointDepth dGeomCapsulePointDepth
#define dCCylinderClass dCapsuleClass

/** Flat-ended cylinder along local z, full length. */
ODE_API dGeomID dCreateCylinder(dSpaceID space, dReal radius, dReal length);
ODE_API void dGeomCylinderSetParams(dGeomID cylinder, dReal radius, dReal length);
ODE_API void dGeomCylinderGetParams(dGeomID cylinder, dReal *radius, dReal *length);

/** Convex hull (ODE 0.16): planecount planes (a, b, c, d) with unit normals
 *  (a, b, c) pointing out, pointcount points (x, y, z), and for each plane
 *  in order its polygon as [count, i0, i1, ...] (point indices, counter-
 *  clockwise seen from outside). The arrays are not copied: they must
 *  outlive the geom (or the next dGeomSetConvex). */
ODE_API dGeomID dCreateConvex(dSpaceID space, const dReal *planes, unsigned int planecount,
                              const dReal *points, unsigned int pointcount,
                              const unsigned int *polygons);
ODE_API void dGeomSetConvex(dGeomID g, const dReal *planes, unsigned int planecount,
                            const dReal *points, unsigned int pointcount,
                            const unsigned int *polygons);

/** Ray (10.7.5): from the geom position along local +z, length >= 0. Its
 *  contacts are the hit points on the other geom: depth = distance from the
 *  start, normal = the surface normal there (facing the ray when the ray is o1). */
ODE_API dGeomID dCreateRay(dSpaceID space, dReal length);
ODE_API void dGeomRaySetLength(dGeomID ray, dReal length);
ODE_API dReal dGeomRayGetLength(dGeomID ray);
/** Start point and direction (normalised; zero is an error). */
ODE_API void dGeomRaySet(dGeomID ray, dReal px, dReal py, dReal pz, dReal dx, dReal dy, dReal dz);
ODE_API void dGeomRayGet(dGeomID ray, dVector3 start, dVector3 dir);
/* Hit selection flags (ODE 0.16; they matter for triangle meshes). */
ODE_API void dGeomRaySetFirstContact(dGeomID g, int firstContact);
ODE_API int dGeomRayGetFirstContact(dGeomID g);
ODE_API void dGeomRaySetBackfaceCull(dGeomID g, int backfaceCull);
ODE_API int dGeomRayGetBackfaceCull(dGeomID g);
ODE_API void dGeomRaySetClosestHit(dGeomID g, int closestHit);
ODE_API int dGeomRayGetClosestHit(dGeomID g);
/** FirstContact and BackfaceCull at once (deprecated: use the calls above).
 *  The getter writes 0 or 1 to each. */
ODE_API_DEPRECATED ODE_API void dGeomRaySetParams(dGeomID g, int FirstContact, int BackfaceCull);
ODE_API_DEPRECATED ODE_API void dGeomRayGetParams(dGeomID g, int *FirstContact,
                                                  int *BackfaceCull);

/** Geometry transform (10.7.7): holds one geom (in no space) with a pose
 *  relative to the transform. Cleanup 1: destroying the transform destroys
 *  the geom (default 0). Info 0 (default, as the guide): contacts report the
 *  encapsulated geom as g1/g2; info 1: they report the transform. */
ODE_API dGeomID dCreateGeomTransform(dSpaceID space);
ODE_API void dGeomTransformSetGeom(dGeomID g, dGeomID obj);
ODE_API dGeomID dGeomTransformGetGeom(dGeomID g);
ODE_API void dGeomTransformSetCleanup(dGeomID g, int mode);
ODE_API int dGeomTransformGetCleanup(dGeomID g);
ODE_API void dGeomTransformSetInfo(dGeomID g, int mode);
ODE_API int dGeomTransformGetInfo(dGeomID g);

/* ---- utilities (10.10) --------------------------------------------------- */

/** An AABB that covers everything: for geoms that are never culled. */
ODE_API void dInfiniteAABB(dGeomID geom, dReal aabb[6]);
/** The closest points cp1 on segment a1-a2 and cp2 on segment b1-b2; zero-length
 *  segments work, parallel ones give a pair involving an endpoint of one. */
ODE_API void dClosestLineSegmentPoints(const dVector3 a1, const dVector3 a2, const dVector3 b1,
                                       const dVector3 b2, dVector3 cp1, dVector3 cp2);
/** 1 if the boxes (centre p, rotation R, full side lengths) touch or overlap. */
ODE_API int dBoxTouchesBox(const dVector3 _p1, const dMatrix3 R1, const dVector3 side1,
                           const dVector3 _p2, const dMatrix3 R2, const dVector3 side2);

/* ---- user classes (10.8) -------------------------------------------------- */

typedef void dGetAABBFn(dGeomID, dReal aabb[6]);
typedef int dColliderFn(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip);
typedef dColliderFn *dGetColliderFnFn(int num);
typedef void dGeomDtorFn(dGeomID o);
typedef int dAABBTestFn(dGeomID o1, dGeomID o2, dReal aabb[6]);

typedef struct dGeomClass {
    int bytes;                    /* bytes of class data per geom */
    dGetColliderFnFn *collider;   /* collider for another class number, or 0 */
    dGetAABBFn *aabb;
    dAABBTestFn *aabb_test;       /* finer test against a box, or 0 */
    dGeomDtorFn *dtor;            /* or 0 */
} dGeomClass;

/** Register a class (at most dMaxUserClasses); returns its class number. */
ODE_API int dCreateGeomClass(const dGeomClass *classptr);

/** From now on dCollide of a geom of class i with one of class j (either
 *  order: the contacts of (j, i) are fn's for (i, j) mirrored) calls fn, in
 *  place of the selected backend, a transform's unwrapping or a user class's
 *  collider. As in ODE there is no call that removes it, and a NULL fn makes
 *  the pair produce no contacts. Geoms of one body, or a geom with itself, still
 *  give none; i and j are class numbers below dGeomNumClasses. */
ODE_API void dSetColliderOverride(int i, int j, dColliderFn *fn);
ODE_API void *dGeomGetClassData(dGeomID);
/** A placeable geom of a user class, in no space. */
ODE_API dGeomID dCreateGeom(int classnum);

#ifdef __cplusplus
}
#endif

#include <ode/collision_trimesh.h>
#include <ode/collision_heightfield.h>

#endif
