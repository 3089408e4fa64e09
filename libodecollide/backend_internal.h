// SPDX-License-Identifier: BSD-3-Clause
//
// backend_internal.h -- the backend registry inside the collision library:
// which backend dCollide uses for a pair, and the cache notifications.

#ifndef DX_BACKEND_INTERNAL_H
#define DX_BACKEND_INTERNAL_H

#include <ode/backend.h>

#include "geom_internal.h"

// The native backend (backends/native), always present (the adapter
// modules' entry point is declared in backend_support.h).
const dCollisionBackend *dxNativeBackend(void);

// Contacts of two non-space geoms through the selected backend, or native
// for a pair it does not support. Flags and skip are already checked.
int dxBackendCollide(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip);
// dCollide's shortcut to a native collider for a pair of built-in classes:
// fn(o1, o2), or, with reverse, fn(o2, o1) and the contacts flipped.
typedef struct dxRoute {
    int (*fn)(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip);
    int reverse;
} dxRoute;
enum { DX_ROUTE_CLASSES = dFirstSpaceClass };   // the built-in non-space classes
// The route of each pair of classes while the general path would end in
// that native collider anyway (native selected, no shadow, no backend
// request pending, no override for the pair); NULL where dCollide must take
// the general path (backend.c keeps it current).
extern const dxRoute *dx_routes[DX_ROUTE_CLASSES][DX_ROUTE_CLASSES];
// Recompute dx_routes after the selection, shadow, pending requests or
// overrides changed.
void dxBackendRoutesUpdate(void);
// The native backend's route for (c1, c2), NULL if it has no collider
// (native.c).
const dxRoute *dxNativeRoute(int c1, int c2);
// 1 if dSetColliderOverride was called for (c1, c2) (collider_override.c).
int dxCollideOverrideIsSet(int c1, int c2);

// Tell every registered backend (each frees g->backend_cache only if it made
// it: g->backend_cache_owner).
void dxBackendGeomChanged(dxGeom *g);
void dxBackendGeomDestroyed(dxGeom *g);

#endif
