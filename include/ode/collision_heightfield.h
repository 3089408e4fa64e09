/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * collision_heightfield.h -- heightfields (ODE 0.16): a grid of heights over
 * the geom's X-Z plane, Y up in the geom's frame, centred on its origin.
 * Sample (x, z), 0 <= x < widthSamples, 0 <= z < depthSamples, stands at
 * X = x * width / (widthSamples - 1) - width / 2, Z likewise with depth, and
 * height Y = h * scale + offset (array index x + z * widthSamples). Each cell
 * is two triangles split along the diagonal from (x + 1, z) to (x, z + 1).
 * Everything below the surface is solid (the bounding box reaches down to
 * the lowest height minus thickness). With wrap set the field repeats with
 * period width by depth (the last row and column of samples stand for the
 * first). Included by <ode/collision.h>.
 */

#ifndef ODE_COLLISION_HEIGHTFIELD_H
#define ODE_COLLISION_HEIGHTFIELD_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dxHeightfieldData;
typedef struct dxHeightfieldData *dHeightfieldDataID;

/** The height (before scale and offset) of sample (x, z), for
 *  dGeomHeightfieldDataBuildCallback. */
typedef dReal dHeightfieldGetHeight(void *p_user_data, int x, int z);

/** A heightfield geom on data (which may be built later, and is not copied:
 *  destroy the geom before the data). Not placeable: its frame is the world's. */
ODE_API dGeomID dCreateHeightfield(dSpaceID space, dHeightfieldDataID data, int bPlaceable);

/** A new empty data object; destroy with dGeomHeightfieldDataDestroy. */
ODE_API dHeightfieldDataID dGeomHeightfieldDataCreate(void);
ODE_API void dGeomHeightfieldDataDestroy(dHeightfieldDataID d);

/** Heights from a callback, asked for at each collision. The bounds are
 *  infinite until dGeomHeightfieldDataSetBounds. widthSamples and
 *  depthSamples >= 2, width and depth > 0, thickness >= 0; bad input is
 *  reported and leaves the data unchanged. */
ODE_API void dGeomHeightfieldDataBuildCallback(dHeightfieldDataID d, void *pUserData,
                                               dHeightfieldGetHeight *pCallback, dReal width,
                                               dReal depth, int widthSamples, int depthSamples,
                                               dReal scale, dReal offset, dReal thickness,
                                               int bWrap);
/** Heights from an array of widthSamples * depthSamples values, read in
 *  place (keep it alive) unless bCopyHeightData, then copied. */
ODE_API void dGeomHeightfieldDataBuildByte(dHeightfieldDataID d, const unsigned char *pHeightData,
                                           int bCopyHeightData, dReal width, dReal depth,
                                           int widthSamples, int depthSamples, dReal scale,
                                           dReal offset, dReal thickness, int bWrap);
ODE_API void dGeomHeightfieldDataBuildShort(dHeightfieldDataID d, const short *pHeightData,
                                            int bCopyHeightData, dReal width, dReal depth,
                                            int widthSamples, int depthSamples, dReal scale,
                                            dReal offset, dReal thickness, int bWrap);
ODE_API void dGeomHeightfieldDataBuildSingle(dHeightfieldDataID d, const float *pHeightData,
                                             int bCopyHeightData, dReal width, dReal depth,
                                             int widthSamples, int depthSamples, dReal scale,
                                             dReal offset, dReal thickness, int bWrap);
ODE_API void dGeomHeightfieldDataBuildDouble(dHeightfieldDataID d, const double *pHeightData,
                                             int bCopyHeightData, dReal width, dReal depth,
                                             int widthSamples, int depthSamples, dReal scale,
                                             dReal offset, dReal thickness, int bWrap);

/** The heights' range (before scale and offset) for the bounding box. */
ODE_API void dGeomHeightfieldDataSetBounds(dHeightfieldDataID d, dReal minHeight,
                                           dReal maxHeight);

ODE_API void dGeomHeightfieldSetHeightfieldData(dGeomID g, dHeightfieldDataID d);
ODE_API dHeightfieldDataID dGeomHeightfieldGetHeightfieldData(dGeomID g);

#ifdef __cplusplus
}
#endif

#endif
