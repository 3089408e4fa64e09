// SPDX-License-Identifier: BSD-3-Clause
//
// backend_support.h -- what the collision library gives backend adapters
// (C, usable from the C++ adapters), so that the ODE bookkeeping exists once:
// a geom's shape and pose as plain numbers, its cache slot, and a contact
// sink that filters, merges, selects and writes contacts in ODE's convention
// (BACKENDS.md section 3). The adapters are loadable modules linked against
// libodecollide.so, so these functions are exported from it
// (DX_INTERNAL_EXPORT) while staying out of the public headers.

#ifndef DX_BACKEND_SUPPORT_H
#define DX_BACKEND_SUPPORT_H

#include <ode/backend.h>

#include "backend_config.h"

#ifdef __cplusplus
extern "C" {
#endif

// Exported from libodecollide.so (whose other internals are hidden) for the
// backend modules, and the modules' entry point exported from them.
#if defined(__GNUC__)
#define DX_INTERNAL_EXPORT __attribute__((visibility("default")))
#else
#define DX_INTERNAL_EXPORT
#endif

// A geom's shape: class and size parameters.
typedef struct dxShapeDesc {
    int cls;          // dSphereClass, dBoxClass, ...
    dReal p[4];       // sphere: radius; box: full sides; capsule, cylinder:
                      // radius, length (capsule: without caps; both along
                      // local z); plane: a, b, c, d (unit normal); ray: length
    unsigned version; // changes whenever the parameters change
} dxShapeDesc;

// The shape of a non-space geom (for a class without parameters, p is zero).
DX_INTERNAL_EXPORT void dxGeomDescribe(dGeomID g, dxShapeDesc *out);
// The world pose: position and rotation (row-major 3x4, as dGeomGetRotation).
DX_INTERNAL_EXPORT void dxGeomPose(dGeomID g, dReal pos[3], dReal R[12]);

// One cache slot per geom for the backend's shape object. dxGeomCache
// returns it if `owner` made it, else NULL (another backend's object is freed
// first, through that backend's geom_changed): for collisions.
// dxGeomOwnedCache returns it if `owner` made it, else NULL, and frees
// nothing: for geom_changed and geom_destroyed. dxGeomSetCache stores one.
DX_INTERNAL_EXPORT void *dxGeomCache(dGeomID g, const void *owner);
DX_INTERNAL_EXPORT void *dxGeomOwnedCache(dGeomID g, const void *owner);
DX_INTERNAL_EXPORT void dxGeomSetCache(dGeomID g, const void *owner, void *cache);

// Raw contacts from a backend, in ODE's sense for (o1, o2) as passed to it.
enum { DX_SINK_CAPACITY = 64 };   // raw contacts kept; more are ignored
typedef struct dxRawContact {
    dReal pos[3], normal[3], depth;
    int side1, side2;
} dxRawContact;
typedef struct dxContactSink {
    int count;
    dxRawContact c[DX_SINK_CAPACITY];
} dxContactSink;

// For a backend with more raw contacts than a sink holds (a mesh's
// triangles): moves the `keep` of c[0 .. n) to keep to the front (the
// deepest, then each the farthest from those kept, as dxSinkFinish selects)
// and returns how many that is (n if n <= keep).
DX_INTERNAL_EXPORT int dxContactsSelect(dxRawContact *c, int n, int keep);

DX_INTERNAL_EXPORT void dxSinkInit(dxContactSink *s);
// Add one contact: the normal points into o1 (need not be unit length).
DX_INTERNAL_EXPORT void dxSinkAdd(dxContactSink *s, const dReal pos[3], const dReal normal[3],
                                  dReal depth, int side1, int side2);
// Drop non-finite values, negative depths and zero normals; normalise normals;
// merge contacts closer than a relative 1e-6 (keeping the deeper); keep at
// most flags & 0xffff (the deepest first, then each farthest from those kept);
// write them with stride skip, g1 = o1, g2 = o2. Returns the number written;
// with 0, `out` is untouched.
DX_INTERNAL_EXPORT int dxSinkFinish(dxContactSink *s, dGeomID o1, dGeomID o2, int flags,
                                    dContactGeom *out, int skip);

// Face contacts (backend_manifold.c). For a box, capsule or cylinder
// `shape` against a plane, where the backend gave one point: the sink's
// deepest contact (its normal and depth) is kept as the backend's answer and
// the sink is refilled with the shape's features under the plane that
// answer defines (corners, end points, cap rim points), each as deep as it
// lies below it. shape_is_o1: the shape is the o1 of the sink's sense.
DX_INTERNAL_EXPORT void dxSinkPlaneManifold(dxContactSink *s, dGeomID shape, int shape_is_o1);
// For a backend whose contact point is the middle of the segment between
// the two shapes' witness points (pos -+ normal * depth / 2), which can
// leave one shape when they are deep: each point moved to the middle or an
// end of that segment, whichever lies deepest in both (sphere, box, capsule,
// cylinder, plane).
DX_INTERNAL_EXPORT void dxSinkPointsInBoth(dxContactSink *s, dGeomID o1, dGeomID o2);

// Triangle meshes, for adapters that build their own model of a mesh's
// data (once per data object: geoms may share one).
typedef struct dxTriMeshInfo {
    const void *data;   // the data object (its identity; NULL: no data)
    int vertex_count, tri_count;
} dxTriMeshInfo;
// The data of trimesh geom g (zero / NULL when it has none). A data object
// whose triangles or vertices change (Build, Update, SetData) tells each
// geom on it through geom_changed, so a model shared through the geoms'
// caches is never older than its data while any geom still holds it.
DX_INTERNAL_EXPORT void dxTriMeshGetInfo(dGeomID g, dxTriMeshInfo *out);
// Vertex i of the data (mesh frame), as the native colliders read it.
DX_INTERNAL_EXPORT void dxTriMeshGetVertex(dGeomID g, int i, dReal out[3]);
// The three vertex indices of triangle t.
DX_INTERNAL_EXPORT void dxTriMeshGetTriangle(dGeomID g, int t, int idx[3]);
// 1 if triangle t of mesh g may give contacts with `other`: it has an area
// (native skips degenerate ones) and the per-triangle callback, if set,
// accepts it (dGeomTriMeshSetCallback).
DX_INTERNAL_EXPORT int dxTriMeshTriangleAllowed(dGeomID g, dGeomID other, int t);
// 1 if `leave`, the world direction in which the other geom of a contact
// leaves the mesh, does not point behind triangle t (into the solid:
// triangles are one-sided, as native's).
DX_INTERNAL_EXPORT int dxTriMeshFrontSide(dGeomID g, int t, const dReal leave[3]);
// Why an adapter cannot answer mesh g as native would, or NULL: an array
// callback (it must see every intersecting triangle), a merge callback or a
// contact merge setting other than the default (dGeomLowLevelControl).
DX_INTERNAL_EXPORT const char *dxTriMeshNeedsNative(dGeomID g);
// The pair through native instead, for a reason only the geoms (not their
// classes) show: `why` is said once per backend and reason string through
// dMessage, or, in strict mode, reported as an error (returning 0).
DX_INTERNAL_EXPORT int dxBackendNativeFallback(const char *backend, dGeomID o1, dGeomID o2,
                                               int flags, dContactGeom *out, int skip,
                                               const char *why);

// A backend module (libodecollide-NAME.so: backends/fcl, backends/bullet)
// defines this entry point, which libodecollide calls once after dlopen: it
// returns the module's table if `abi` is the DX_BACKEND_ABI the module was
// built with, else NULL. Each entry point of the table catches every C++
// exception and reports it with dMessage; geom_changed / geom_destroyed free
// the geom's cache only if they own it (dxGeomOwnedCache).
#define DX_BACKEND_MODULE_ENTRY "dxBackendModule"
DX_INTERNAL_EXPORT const dCollisionBackend *dxBackendModule(const char *abi);

#ifdef __cplusplus
}
#endif

#endif
