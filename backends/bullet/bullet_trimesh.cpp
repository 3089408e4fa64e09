// SPDX-License-Identifier: BSD-3-Clause
//
// bullet_trimesh.cpp -- triangle meshes in the Bullet adapter: one model
// per trimesh data object (a copy of its vertices and indices in btScalar,
// Bullet's mesh interface over them and a btBvhTriangleMeshShape), shared
// by the geoms on the same data through their cache slots. When the data
// changes (Build, Update, SetData) each geom on it drops its object
// (geom_changed) but hands the model to the registry (trimesh_adapter.h),
// which keeps it stale: the next collision rewrites the copied vertices in
// place and refits the shape's tree when the triangles are the same
// (Update: the vertices moved), and builds a new model only when they are
// not. Bullet collides the shape with a convex one triangle by triangle
// (btConvexConcaveCollisionAlgorithm); bullet_backend.cpp keeps each
// triangle's first point, on the triangle, with its index
// (btManifoldResult's m_index0 / m_index1) as side1 / side2.
//
// One shape for every mesh, moving or not: a collision query takes the
// mesh's pose at each call, so a btBvhTriangleMeshShape is right for a
// mesh on a body too. btGImpactMeshShape, Bullet's shape for moving meshes,
// was measured in its place (tests/test_backend_trimesh.c): against convex
// shapes it gives the same contacts as the BVH shape, and its one extra,
// mesh-mesh, breaks the contract (below), so it is not used.

#include "bullet_trimesh.h"

#include <vector>

namespace dxbullet {

namespace {

// Bullet's BVH mesh shape, refit to bounds its caller found (the shape's
// own refitTree would find its box by six walks over every triangle).
ATTRIBUTE_ALIGNED16(struct) MeshShape : btBvhTriangleMeshShape {
    using btBvhTriangleMeshShape::btBvhTriangleMeshShape;
    // The tree's boxes refit to the mesh's vertices, quantised within
    // [lo, hi] (the box of every triangle's vertices, as a build takes).
    void refit(const btVector3 &lo, const btVector3 &hi)
    {
        getOptimizedBvh()->refit(m_meshInterface, lo, hi);
        m_localAabbMin = lo;   // (the margin is 0)
        m_localAabbMax = hi;
    }
};

// A data object's arrays and shape (Bullet's shape points into the arrays).
struct Model {
    std::vector<btScalar> vertices;   // 3 per vertex
    std::vector<int> indices;         // 3 per triangle
    btTriangleIndexVertexArray arrays;
    std::unique_ptr<MeshShape> shape;
};

// A new model of the data of g (info: its counts). Margin 0: Bullet would
// otherwise thicken every triangle.
std::unique_ptr<Model> build_model(dGeomID g, const dxTriMeshInfo &info)
{
    std::unique_ptr<Model> m(new Model);
    const std::size_t nv = static_cast<std::size_t>(info.vertex_count);
    const std::size_t nt = static_cast<std::size_t>(info.tri_count);
    m->vertices.resize(3 * nv);
    for (std::size_t i = 0; i < nv; i++) {
        dReal v[3];
        dxTriMeshGetVertex(g, static_cast<int>(i), v);
        for (std::size_t k = 0; k < 3; k++) m->vertices[3 * i + k] = v[k];
    }
    m->indices.resize(3 * nt);
    for (std::size_t t = 0; t < nt; t++)
        dxTriMeshGetTriangle(g, static_cast<int>(t), &m->indices[3 * t]);
    btIndexedMesh part;
    part.m_numTriangles = info.tri_count;
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char *>(m->indices.data());
    part.m_triangleIndexStride = 3 * sizeof(int);
    part.m_numVertices = info.vertex_count;
    part.m_vertexBase = reinterpret_cast<const unsigned char *>(m->vertices.data());
    part.m_vertexStride = 3 * sizeof(btScalar);
    m->arrays.addIndexedMesh(part, PHY_INTEGER);
    m->shape = std::make_unique<MeshShape>(&m->arrays, true);
    m->shape->setMargin(0);
    dxadapter::trace_mesh_model("bullet", "built", info.tri_count);
    return m;
}

// Brings the model up to the data of g (info: its counts) if the data has
// the model's triangles: the copied vertices rewritten in place and the
// tree's boxes refit, keeping its structure (nothing done if no vertex
// moved). False if the triangles differ: the model must be rebuilt.
bool refit_model(Model &m, dGeomID g, const dxTriMeshInfo &info)
{
    const std::size_t nv = static_cast<std::size_t>(info.vertex_count);
    const std::size_t nt = static_cast<std::size_t>(info.tri_count);
    if (m.vertices.size() != 3 * nv || m.indices.size() != 3 * nt) return false;
    for (std::size_t t = 0; t < nt; t++) {
        int idx[3];
        dxTriMeshGetTriangle(g, static_cast<int>(t), idx);
        for (std::size_t k = 0; k < 3; k++)
            if (m.indices[3 * t + k] != idx[k]) return false;
    }
    bool moved = false;
    for (std::size_t i = 0; i < nv; i++) {
        dReal v[3];
        dxTriMeshGetVertex(g, static_cast<int>(i), v);
        for (std::size_t k = 0; k < 3; k++) {
            const btScalar x = static_cast<btScalar>(v[k]);
            moved = moved || x != m.vertices[3 * i + k];
            m.vertices[3 * i + k] = x;
        }
    }
    if (!moved) return true;
    btVector3 lo(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT), hi = -lo;
    for (int i : m.indices) {
        const btScalar *p = &m.vertices[3 * static_cast<std::size_t>(i)];
        const btVector3 point(p[0], p[1], p[2]);
        lo.setMin(point);
        hi.setMax(point);
    }
    m.shape->refit(lo, hi);
    dxadapter::trace_mesh_model("bullet", "refit", info.tri_count);
    return true;
}

} // namespace

std::shared_ptr<btCollisionShape> mesh_shape(dGeomID g)
{
    dxTriMeshInfo info;
    dxTriMeshGetInfo(g, &info);
    if (!info.data || info.tri_count == 0) return nullptr;
    std::shared_ptr<Model> model = dxadapter::ModelRegistry<Model>::instance().shared(
        g, info.data, [&] { return build_model(g, info); },
        [&](Model &m) { return refit_model(m, g, info); });
    return std::shared_ptr<btCollisionShape>(model, model->shape.get());   // owns the model
}

void mesh_changed(dGeomID g, std::shared_ptr<btCollisionShape> held)
{
    dxadapter::ModelRegistry<Model>::instance().park(g, std::move(held));
}

void mesh_destroyed(dGeomID g) { dxadapter::ModelRegistry<Model>::instance().forget(g); }

// Measured against the contract and native (tests/test_backend_trimesh.c,
// 40 poses per pair and mesh, both orders; the grid terrain, icosphere,
// closed box, torus and sheet): the sphere meets it on every mesh. The
// others stay native (worst errors; ODE_BACKEND_MEASURE_TRIMESH=1 answers
// them to measure again):
// - box: on the terrain the deepest depth 0.011 off at 0.097 (per-triangle
//   EPA normals up to 70 degrees off the face), 0.015 overlap left along it;
//   on the torus 0.087 off native's depth;
// - capsule: 0.036 off native's depth on the torus, 0.046 on the sheet;
// - cylinder: 0.023 to 0.032 overlap left along the normal (terrain,
//   icosphere, box), 0.21 outside the shapes and 0.07 off native's depth
//   (torus);
// - trimesh (GImpact on both): 0.037 to 0.074 off the depth (box, torus,
//   sheet), 0.022 overlap left; btBvhTriangleMeshShape has no mesh-mesh;
// - convex: the adapter has no convex shape.
bool mesh_pair_supported(int other)
{
    if (other == dSphereClass) return true;
    return dxadapter::measuring_every_mesh_pair() &&
           (other == dBoxClass || other == dCapsuleClass || other == dCylinderClass);
}

} // namespace dxbullet
