/* SPDX-License-Identifier: BSD-3-Clause */
/* collision_space.h -- spaces: containers of geoms that find the pairs whose
 * bounding boxes overlap (guide 10.3, 10.6). A space is itself a geom, so
 * spaces nest. */
#ifndef ODE_COLLISION_SPACE_H
#define ODE_COLLISION_SPACE_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dContactGeom;

/** Called by dSpaceCollide / dSpaceCollide2 with each potentially touching pair. */
typedef void dNearCallback(void *data, dGeomID o1, dGeomID o2);

/** Every pair of geoms tested: O(n^2), best for few geoms. space: a parent, or 0. */
ODE_API dSpaceID dSimpleSpaceCreate(dSpaceID space);
/** Multi-resolution hash table: O(n) for geoms spread out in space. */
ODE_API dSpaceID dHashSpaceCreate(dSpaceID space);

/* Sweep-and-prune space (ODE 0.16): the geoms sorted along the first axis of
 * axisorder, pruned on the second; best for many geoms that mostly stay put. */
#define dSAP_AXES_XYZ ((0) | (1 << 2) | (2 << 4))
#define dSAP_AXES_XZY ((0) | (2 << 2) | (1 << 4))
#define dSAP_AXES_YXZ ((1) | (0 << 2) | (2 << 4))
#define dSAP_AXES_YZX ((1) | (2 << 2) | (0 << 4))
#define dSAP_AXES_ZXY ((2) | (0 << 2) | (1 << 4))
#define dSAP_AXES_ZYX ((2) | (1 << 2) | (0 << 4))
ODE_API dSpaceID dSweepAndPruneSpaceCreate(dSpaceID space, int axisorder);
/** A quadtree over the box Center +- Extents (Extents are half-sizes), split
 *  on the two axes with the larger extents (x and y on ties), Depth >= 1
 *  levels below the root. */
ODE_API dSpaceID dQuadTreeSpaceCreate(dSpaceID space, const dVector3 Center,
                                      const dVector3 Extents, int Depth);
/** With cleanup on (default), destroys the geoms it contains. */
ODE_API void dSpaceDestroy(dSpaceID);

/** Cells of the hash space are 2^level wide, minlevel <= level <= maxlevel
 *  (defaults -3 and 10). */
ODE_API void dHashSpaceSetLevels(dSpaceID space, int minlevel, int maxlevel);
ODE_API void dHashSpaceGetLevels(dSpaceID space, int *minlevel, int *maxlevel);

/** 1 (default): destroying the space destroys its geoms; 0: they are only removed. */
ODE_API void dSpaceSetCleanup(dSpaceID space, int mode);
ODE_API int dSpaceGetCleanup(dSpaceID space);
/** The manual thread-data cleanup mark of ODE 0.16 (for programs started
 *  with dInitFlagManualThreadCleanup): 1 marks the space as released by
 *  dCleanupODEAllDataForThread, 0 (the default) as released when its thread
 *  ends. This library keeps no per-thread collision data, so the mark is
 *  kept and reported but frees nothing either way; it is independent of
 *  dSpaceSetCleanup and of the space's parent. */
ODE_API void dSpaceSetManualCleanup(dSpaceID space, int mode);
ODE_API int dSpaceGetManualCleanup(dSpaceID space);
/** Sublevel of a space (ODE 0.16): orders nested spaces for dSpaceCollide2. */
ODE_API void dSpaceSetSublevel(dSpaceID space, int sublevel);
ODE_API int dSpaceGetSublevel(dSpaceID space);

/** A geom is in at most one space; adding it to a second is an error. */
ODE_API void dSpaceAdd(dSpaceID, dGeomID);
ODE_API void dSpaceRemove(dSpaceID, dGeomID);
/** 1 if the geom is directly in the space. */
ODE_API int dSpaceQuery(dSpaceID, dGeomID);
/** Bring cached bounding boxes up to date. */
ODE_API void dSpaceClean(dSpaceID);
ODE_API int dSpaceGetNumGeoms(dSpaceID);
/** The i-th geom (0 <= i < dSpaceGetNumGeoms); fastest in increasing order. */
ODE_API dGeomID dSpaceGetGeom(dSpaceID, int i);
/** dSimpleSpaceClass, dHashSpaceClass or dQuadTreeSpaceClass. */
ODE_API int dSpaceGetClass(dSpaceID space);

#ifdef __cplusplus
}
#endif

#endif
