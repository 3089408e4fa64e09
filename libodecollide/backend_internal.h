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
// Tell every registered backend (each frees g->backend_cache only if it made
// it: g->backend_cache_owner).
void dxBackendGeomChanged(dxGeom *g);
void dxBackendGeomDestroyed(dxGeom *g);

#endif
