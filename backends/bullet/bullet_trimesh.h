// SPDX-License-Identifier: BSD-3-Clause
//
// bullet_trimesh.h -- inside the Bullet adapter only (C++): the triangle
// meshes of bullet_trimesh.cpp, for bullet_backend.cpp.

#ifndef DX_BULLET_TRIMESH_H
#define DX_BULLET_TRIMESH_H

#include "../trimesh_adapter.h"

#include <btBulletCollisionCommon.h>
#include <ode/collision.h>

#include <memory>

namespace dxbullet {

// The btBvhTriangleMeshShape of a trimesh geom's data, built once per data
// object and shared by the geoms on it (NULL without triangles), refit
// when the data's vertices moved; the pointer keeps the data's model alive.
std::shared_ptr<btCollisionShape> mesh_shape(dGeomID g);
// A trimesh geom's shape changed (geom_changed, its object about to be
// freed): the shape it held (or NULL) is kept for the refit.
void mesh_changed(dGeomID g, std::shared_ptr<btCollisionShape> held);
// A trimesh geom is destroyed: the model kept for it goes.
void mesh_destroyed(dGeomID g);
// Whether the adapter answers a trimesh against a geom of class `other`.
bool mesh_pair_supported(int other);

} // namespace dxbullet

#endif
