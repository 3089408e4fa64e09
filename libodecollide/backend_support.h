// SPDX-License-Identifier: BSD-3-Clause
//
// backend_support.h -- what the collision library gives backend adapters
// (C, usable from the C++ adapters), so that the ODE bookkeeping exists once:
// a geom's shape and pose as plain numbers, its cache slot, and a contact
// sink that filters, merges, selects and writes contacts in ODE's convention
// (BACKENDS.md section 3).

#ifndef DX_BACKEND_SUPPORT_H
#define DX_BACKEND_SUPPORT_H

#include <ode/backend.h>

#ifdef __cplusplus
extern "C" {
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
void dxGeomDescribe(dGeomID g, dxShapeDesc *out);
// The world pose: position and rotation (row-major 3x4, as dGeomGetRotation).
void dxGeomPose(dGeomID g, dReal pos[3], dReal R[12]);

// One cache slot per geom for the backend's shape object. dxGeomCache
// returns it if `owner` made it, else NULL (another backend's object is freed
// first, through that backend's geom_changed): for collisions.
// dxGeomOwnedCache returns it if `owner` made it, else NULL, and frees
// nothing: for geom_changed and geom_destroyed. dxGeomSetCache stores one.
void *dxGeomCache(dGeomID g, const void *owner);
void *dxGeomOwnedCache(dGeomID g, const void *owner);
void dxGeomSetCache(dGeomID g, const void *owner, void *cache);

// Raw contacts from a backend, in ODE's sense for (o1, o2) as passed to it.
enum { DX_SINK_CAPACITY = 64 };   // raw contacts kept; more are ignored
typedef struct dxContactSink {
    int count;
    struct dxRawContact {
        dReal pos[3], normal[3], depth;
        int side1, side2;
    } c[DX_SINK_CAPACITY];
} dxContactSink;

void dxSinkInit(dxContactSink *s);
// Add one contact: the normal points into o1 (need not be unit length).
void dxSinkAdd(dxContactSink *s, const dReal pos[3], const dReal normal[3], dReal depth,
               int side1, int side2);
// Drop non-finite values, negative depths and zero normals; normalise normals;
// merge contacts closer than a relative 1e-6 (keeping the deeper); keep at
// most flags & 0xffff (the deepest first, then each farthest from those kept);
// write them with stride skip, g1 = o1, g2 = o2. Returns the number written;
// with 0, `out` is untouched.
int dxSinkFinish(dxContactSink *s, dGeomID o1, dGeomID o2, int flags, dContactGeom *out,
                 int skip);

// The adapters' tables (backends/fcl, backends/bullet), registered at start
// when meson built them in (DX_HAVE_FCL, DX_HAVE_BULLET). Each entry point
// catches every C++ exception and reports it with dMessage. Their
// geom_changed / geom_destroyed free the geom's cache only if they own it
// (dxGeomOwnedCache).
const dCollisionBackend *dxFclBackend(void);
const dCollisionBackend *dxBulletBackend(void);

#ifdef __cplusplus
}
#endif

#endif
