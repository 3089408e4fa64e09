// SPDX-License-Identifier: BSD-3-Clause
//
// heightfield_internal.h -- heightfield data (the user's heights, read in
// place or copied, or a callback) and the heightfield geom, for
// heightfield_*.c and the native colliders. Frames and sample layout as in
// <ode/collision_heightfield.h>.
//
// The colliders do not have a collider of their own per shape: for each
// query the cells under the other geom become a small triangle mesh (a
// patch, with a ring of one cell around them so that every tested triangle
// knows its neighbours), and the trimesh colliders run on it.

#ifndef DX_HEIGHTFIELD_INTERNAL_H
#define DX_HEIGHTFIELD_INTERNAL_H

#include "trimesh_internal.h"

#include <stdatomic.h>

enum {
    DX_MAGIC_HEIGHTFIELD_DATA = 0x48666c44u,   // "HflD"
    DX_MAGIC_HEIGHTFIELD_DATA_DEAD = 0xdead4fdau
};

// Where the heights come from (no source: the data was never built).
enum { DX_HF_NONE, DX_HF_CALLBACK, DX_HF_BYTE, DX_HF_SHORT, DX_HF_SINGLE, DX_HF_DOUBLE };

struct dxHeightfieldData {
    uint32_t magic;
    int source;                       // DX_HF_*
    const void *heights;              // the user's array, or `owned`
    void *owned;                      // the copy (bCopyHeightData), or NULL
    size_t owned_size;
    void *user_data;                  // for the callback
    dHeightfieldGetHeight *callback;
    dReal width, depth;               // extent along X and Z
    int width_samples, depth_samples; // >= 2 once built
    dReal scale, offset, thickness;
    int wrap;
    dReal min_height, max_height;     // scaled bounds; min_height includes -thickness
    int users;                        // heightfield geoms on the data
    int destroy_pending;              // destroyed while still used
};
typedef struct dxHeightfieldData dxHeightfieldData;

// The most cells one query takes: a geom whose box covers more of a field
// (a geom thousands of cells wide, or a long ray across fine cells) gets no
// contacts, and the first such query of a heightfield is reported through
// dMessage. It bounds a query's work and its patch (at most twice as many
// triangles, about 80 bytes each).
enum { DX_HEIGHTFIELD_MAX_CELLS = 1 << 16 };

typedef struct dxHeightfield {
    dxGeom g;
    dxHeightfieldData *data;
    atomic_int cap_reported;          // a query over DX_HEIGHTFIELD_MAX_CELLS was reported
} dxHeightfield;

// The cells of one query as a mesh (heightfield frame) and the trimesh geom
// the colliders see it through (posed by the collider); the arrays stay
// allocated between queries (heightfield_scratch.c).
typedef struct dxHeightfieldPatch {
    dxTriMesh mesh;
    dxTriMeshData data;
    dxTriMeshNode node;
    int vertex_cap, tri_cap, adj_cap;
} dxHeightfieldPatch;

// A free patch of the calling thread's (NULL, reported, if heightfield
// collisions nest too deep through callbacks); give it back with
// dxHeightfieldPatchRelease (NULL is ignored).
dxHeightfieldPatch *dxHeightfieldPatchAcquire(void);
void dxHeightfieldPatchRelease(dxHeightfieldPatch *p);

extern const dxGeomClassOps dx_heightfield_ops;

static inline int dxHeightfieldDataIsLive(const dxHeightfieldData *d)
{
    return d != NULL && d->magic == DX_MAGIC_HEIGHTFIELD_DATA;
}

// The scaled height of sample (x, z): wrapped (period samples - 1) or
// clamped to the field.
dReal dxHeightfieldSample(const dxHeightfieldData *d, int x, int z);

// Sample spacing along X and Z.
static inline dReal dxHeightfieldCellWidth(const dxHeightfieldData *d)
{
    return d->width / (dReal)(d->width_samples - 1);
}
static inline dReal dxHeightfieldCellDepth(const dxHeightfieldData *d)
{
    return d->depth / (dReal)(d->depth_samples - 1);
}

// The patch of cells [x0, x1) x [z0, z1) of d (sample coordinates, may lie
// outside the field when it wraps) into p, with a ring of one more cell each
// way (clamped to the field unless it wraps); only the asked cells'
// triangles are listed for testing. Returns 0 if a height is not finite
// (reported), else 1.
int dxHeightfieldBuildPatch(const dxHeightfieldData *d, dxHeightfieldPatch *p, int x0, int x1,
                            int z0, int z1);

#endif
