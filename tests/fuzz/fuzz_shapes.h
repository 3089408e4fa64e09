// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_shapes.h -- a geom of any class made from input bytes: its sizes, pose
// and flags, a small random (valid-index) mesh, hull or heightfield. The data
// objects live in an fz_shapes store, freed with it after the geoms.

#ifndef FUZZ_SHAPES_H
#define FUZZ_SHAPES_H

#include "fuzz_input.h"

#define FZ_MAX_DATA 16

typedef struct fz_shapes {
    dTriMeshDataID meshes[FZ_MAX_DATA];
    dHeightfieldDataID fields[FZ_MAX_DATA];
    dReal field_cell[FZ_MAX_DATA];   // the smaller cell side of each field
    void *buffers[4 * FZ_MAX_DATA];   // vertex, index, plane, point, polygon arrays
    int nmeshes, nfields, nbuffers;
} fz_shapes;

// A new geom in space (0: none) of a class the input picks, posed by it when
// placeable; a transform wraps a geom of another class. NULL when the library
// refused the input (reported) or the store is full.
dGeomID fz_make_geom(fz_input *in, dSpaceID space, fz_shapes *store);
// Pose g from the input (position and rotation; a plane or a non-placeable
// geom is left alone).
void fz_pose_geom(fz_input *in, dGeomID g);
// 0 if a or b is a heightfield of the store and the other geom's AABB may
// cover more than FZ_MAX_FIELD_CELLS of its cells: such a pair is not
// collided (the collider's cost grows with the cells, its contact merge
// quadratically: tests/fuzz/known).
#define FZ_MAX_FIELD_CELLS 4096
int fz_pair_cheap(const fz_shapes *store, dGeomID a, dGeomID b);
// The same for a field of cells of side `cell` (at least) against other.
int fz_field_pair_cheap(dReal cell, dGeomID other);
// Free the data objects (after every geom using them is destroyed).
void fz_shapes_free(fz_shapes *store);

#endif
