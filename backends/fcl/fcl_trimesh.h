// SPDX-License-Identifier: BSD-3-Clause
//
// fcl_trimesh.h -- inside the FCL adapter only (C++): what fcl_backend.cpp
// and fcl_trimesh.cpp (triangle meshes) share.

#ifndef DX_FCL_TRIMESH_H
#define DX_FCL_TRIMESH_H

#include "../../libodecollide/backend_support.h"

#include <ode/collision.h>

#include <fcl/narrowphase/collision.h>

#include <memory>

namespace dxfcl {

using Geometry = fcl::CollisionGeometryd;

// fcl_backend.cpp: the geom's cached FCL shape (NULL for a mesh without
// triangles), its world pose, and the order FCL sees a pair in.
const Geometry *shape_of(dGeomID g);
fcl::Transform3d pose_of(dGeomID g);
bool in_fcl_order(dGeomID g1, dGeomID g2);

// fcl_trimesh.cpp: the BVH model of a trimesh geom's data, built once per
// data object and shared by the geoms on it (NULL without triangles),
// refit when the data's vertices moved.
std::shared_ptr<Geometry> mesh_model(dGeomID g);
// A trimesh geom's shape changed (geom_changed, its cache about to be
// freed): the model it held (or NULL) is kept for the refit.
void mesh_changed(dGeomID g, std::shared_ptr<Geometry> held);
// A trimesh geom is destroyed: the model kept for it goes.
void mesh_destroyed(dGeomID g);
// Whether the adapter answers a trimesh against a geom of class `other`.
bool mesh_pair_supported(int other);
// Contacts of a supported pair with a trimesh in it (either or both).
int collide_mesh_pair(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip);

} // namespace dxfcl

#endif
