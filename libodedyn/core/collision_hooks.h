// SPDX-License-Identifier: BSD-3-Clause
//
// collision_hooks.h -- the only collision functions the dynamics library
// calls (guide 10.11.2). They are defined by libodecollide, or by a program
// that brings its own collision library. The references are weak so that a
// dynamics-only program without geoms links as well: the hooks are only
// called for a body that has geoms, and only a collision library attaches
// geoms to bodies.

#ifndef DX_COLLISION_HOOKS_H
#define DX_COLLISION_HOOKS_H

#include <ode/common.h>

void dGeomSetBody(dGeomID geom, dBodyID body);

#if defined(__GNUC__)
#pragma weak dGeomMoved
#pragma weak dGeomGetBodyNext
#pragma weak dGeomSetBody
#endif

#endif
