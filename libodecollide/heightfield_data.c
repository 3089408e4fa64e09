// SPDX-License-Identifier: BSD-3-Clause
//
// heightfield_data.c -- heightfield data objects: the build forms (callback,
// byte, short, float and double arrays, read in place or copied), the height
// bounds, and one sample's height.

#include <ode/memory.h>
#include <string.h>

#include "heightfield_internal.h"

#define CHECK_DATA(d, on_fail) \
    DX_CHECK_ARG(dxHeightfieldDataIsLive(d) && !(d)->destroy_pending, on_fail, \
                 "heightfield data is NULL or was destroyed")

dHeightfieldDataID dGeomHeightfieldDataCreate(void)
{
    dxHeightfieldData *d = (dxHeightfieldData *)dAlloc(sizeof *d);
    memset(d, 0, sizeof *d);
    d->magic = DX_MAGIC_HEIGHTFIELD_DATA;
    return d;
}

static void drop_copy(dxHeightfieldData *d)
{
    if (d->owned) dFree(d->owned, d->owned_size);
    d->owned = NULL;
    d->owned_size = 0;
}

// Free the data (the last geom let go of it, or nobody used it).
void dxHeightfieldDataFree(dxHeightfieldData *d)
{
    drop_copy(d);
    d->magic = DX_MAGIC_HEIGHTFIELD_DATA_DEAD;
    dFree(d, sizeof *d);
}

void dGeomHeightfieldDataDestroy(dHeightfieldDataID d)
{
    CHECK_DATA(d, return);
    if (d->users > 0) d->destroy_pending = 1;   // freed when the last geom lets go
    else dxHeightfieldDataFree(d);
}

// The raw (unscaled) value of array element i.
static dReal raw_height(const dxHeightfieldData *d, size_t i)
{
    switch (d->source) {
    case DX_HF_BYTE: return (dReal)((const unsigned char *)d->heights)[i];
    case DX_HF_SHORT: return (dReal)((const short *)d->heights)[i];
    case DX_HF_SINGLE: return (dReal)((const float *)d->heights)[i];
    case DX_HF_DOUBLE: return (dReal)((const double *)d->heights)[i];
    default: return 0;
    }
}

dReal dxHeightfieldSample(const dxHeightfieldData *d, int x, int z)
{
    int nx = d->width_samples, nz = d->depth_samples;
    if (d->wrap) {
        x %= nx - 1;
        z %= nz - 1;
        if (x < 0) x += nx - 1;
        if (z < 0) z += nz - 1;
    } else {
        x = x < 0 ? 0 : x > nx - 1 ? nx - 1 : x;
        z = z < 0 ? 0 : z > nz - 1 ? nz - 1 : z;
    }
    dReal h = d->source == DX_HF_CALLBACK ? d->callback(d->user_data, x, z)
                                          : raw_height(d, (size_t)x + (size_t)z * (size_t)nx);
    return h * d->scale + d->offset;
}

// The checks every build form shares; 1 if the arguments are good.
static int layout_ok(const char *fn, dxHeightfieldData *d, dReal width, dReal depth,
                     int width_samples, int depth_samples, dReal scale, dReal offset,
                     dReal thickness)
{
    if (!dxHeightfieldDataIsLive(d) || d->destroy_pending) {
        dxReportBadArgument(fn, "heightfield data is NULL or was destroyed");
        return 0;
    }
    if (width_samples < 2 || depth_samples < 2) {
        dxReportBadArgument(fn, "widthSamples and depthSamples must be at least 2 (got %d, %d)",
                            width_samples, depth_samples);
        return 0;
    }
    if (!(width > 0 && depth > 0 && dxIsFinite(width) && dxIsFinite(depth))) {
        dxReportBadArgument(fn, "width and depth must be positive and finite");
        return 0;
    }
    if (!dxIsFinite3(scale, offset, thickness) || thickness < 0) {
        dxReportBadArgument(fn, "scale, offset and thickness must be finite, thickness >= 0");
        return 0;
    }
    return 1;
}

static void set_layout(dxHeightfieldData *d, dReal width, dReal depth, int width_samples,
                       int depth_samples, dReal scale, dReal offset, dReal thickness, int wrap)
{
    d->width = width;
    d->depth = depth;
    d->width_samples = width_samples;
    d->depth_samples = depth_samples;
    d->scale = scale;
    d->offset = offset;
    d->thickness = thickness;
    d->wrap = wrap != 0;
}

// The array builds' shared body: check the heights (every one finite),
// then point at them or copy them, and take their bounds.
static void build_array(const char *fn, dxHeightfieldData *d, int source, const void *heights,
                        size_t elem, int copy, dReal width, dReal depth, int width_samples,
                        int depth_samples, dReal scale, dReal offset, dReal thickness, int wrap)
{
    if (!layout_ok(fn, d, width, depth, width_samples, depth_samples, scale, offset, thickness))
        return;
    if (!heights) {
        dxReportBadArgument(fn, "pHeightData is NULL");
        return;
    }
    size_t n = (size_t)width_samples * (size_t)depth_samples;
    dxHeightfieldData probe = *d;
    probe.source = source;
    probe.heights = heights;
    dReal lo = dInfinity, hi = -dInfinity;
    for (size_t i = 0; i < n; i++) {
        dReal h = raw_height(&probe, i);
        if (!dxIsFinite(h)) {
            dxReportBadArgument(fn, "height %zu (x %zu, z %zu) is not finite", i,
                                i % (size_t)width_samples, i / (size_t)width_samples);
            return;
        }
        lo = dMin(lo, h);
        hi = dMax(hi, h);
    }
    drop_copy(d);
    d->source = source;
    d->heights = heights;
    if (copy) {
        d->owned_size = n * elem;
        d->owned = dAlloc(d->owned_size);
        memcpy(d->owned, heights, d->owned_size);
        d->heights = d->owned;
    }
    d->callback = NULL;
    d->user_data = NULL;
    set_layout(d, width, depth, width_samples, depth_samples, scale, offset, thickness, wrap);
    // As ODE: the bounds are the scaled extremes (a negative scale swaps them).
    dReal a = lo * scale + offset, b = hi * scale + offset;
    d->min_height = dMin(a, b) - thickness;
    d->max_height = dMax(a, b);
}

void dGeomHeightfieldDataBuildCallback(dHeightfieldDataID d, void *pUserData,
                                       dHeightfieldGetHeight *pCallback, dReal width, dReal depth,
                                       int widthSamples, int depthSamples, dReal scale,
                                       dReal offset, dReal thickness, int bWrap)
{
    if (!layout_ok(__func__, d, width, depth, widthSamples, depthSamples, scale, offset,
                   thickness))
        return;
    DX_CHECK_ARG(pCallback != NULL, return, "pCallback is NULL");
    drop_copy(d);
    d->source = DX_HF_CALLBACK;
    d->heights = NULL;
    d->callback = pCallback;
    d->user_data = pUserData;
    set_layout(d, width, depth, widthSamples, depthSamples, scale, offset, thickness, bWrap);
    d->min_height = -dInfinity;   // until dGeomHeightfieldDataSetBounds
    d->max_height = dInfinity;
}

void dGeomHeightfieldDataBuildByte(dHeightfieldDataID d, const unsigned char *pHeightData,
                                   int bCopyHeightData, dReal width, dReal depth,
                                   int widthSamples, int depthSamples, dReal scale, dReal offset,
                                   dReal thickness, int bWrap)
{
    build_array(__func__, d, DX_HF_BYTE, pHeightData, sizeof *pHeightData, bCopyHeightData,
                width, depth, widthSamples, depthSamples, scale, offset, thickness, bWrap);
}

void dGeomHeightfieldDataBuildShort(dHeightfieldDataID d, const short *pHeightData,
                                    int bCopyHeightData, dReal width, dReal depth,
                                    int widthSamples, int depthSamples, dReal scale, dReal offset,
                                    dReal thickness, int bWrap)
{
    build_array(__func__, d, DX_HF_SHORT, pHeightData, sizeof *pHeightData, bCopyHeightData,
                width, depth, widthSamples, depthSamples, scale, offset, thickness, bWrap);
}

void dGeomHeightfieldDataBuildSingle(dHeightfieldDataID d, const float *pHeightData,
                                     int bCopyHeightData, dReal width, dReal depth,
                                     int widthSamples, int depthSamples, dReal scale,
                                     dReal offset, dReal thickness, int bWrap)
{
    build_array(__func__, d, DX_HF_SINGLE, pHeightData, sizeof *pHeightData, bCopyHeightData,
                width, depth, widthSamples, depthSamples, scale, offset, thickness, bWrap);
}

void dGeomHeightfieldDataBuildDouble(dHeightfieldDataID d, const double *pHeightData,
                                     int bCopyHeightData, dReal width, dReal depth,
                                     int widthSamples, int depthSamples, dReal scale,
                                     dReal offset, dReal thickness, int bWrap)
{
    build_array(__func__, d, DX_HF_DOUBLE, pHeightData, sizeof *pHeightData, bCopyHeightData,
                width, depth, widthSamples, depthSamples, scale, offset, thickness, bWrap);
}

void dGeomHeightfieldDataSetBounds(dHeightfieldDataID d, dReal minHeight, dReal maxHeight)
{
    CHECK_DATA(d, return);
    DX_CHECK_ARG(!dIsNan(minHeight) && !dIsNan(maxHeight), return, "a bound is NaN");
    DX_CHECK_ARG(minHeight <= maxHeight, return, "minHeight is above maxHeight");
    // As ODE: scaled and offset (before any build: scale 0, offset 0); a
    // negative scale swaps them.
    dReal a = minHeight * d->scale + d->offset, b = maxHeight * d->scale + d->offset;
    if (dIsNan(a)) a = -dInfinity;   // an infinite bound times scale 0
    if (dIsNan(b)) b = dInfinity;
    d->min_height = dMin(a, b) - d->thickness;
    d->max_height = dMax(a, b);
}
