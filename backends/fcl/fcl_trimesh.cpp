// SPDX-License-Identifier: BSD-3-Clause
//
// fcl_trimesh.cpp -- triangle meshes in the FCL adapter: one
// BVHModel<OBBRSS> per trimesh data object (BACKENDS.md section 4), built at
// the first collision of a geom on it and shared by every geom on the same
// data through their cache slots. When the data changes (Build, Update,
// SetData) each geom on it drops its cache (geom_changed) but hands the
// model to the registry (trimesh_adapter.h), which keeps it stale: the next
// collision refits it in place when the triangles are the same (Update:
// the vertices moved), and builds a new one only when they are not. FCL
// reports one contact per triangle (Contact::b1 / b2 its index), which
// become the pair's contacts with side1 / side2 = that index, the
// per-triangle callback vetoing a triangle's contacts; meshes with an array
// or merge callback or a merge setting go to native (backend_support.h:
// dxTriMeshNeedsNative).

#include "fcl_trimesh.h"

#include "../trimesh_adapter.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>

#include <cmath>
#include <vector>

namespace dxfcl {

namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

// Raw contacts asked of FCL for a pair with a mesh: one per triangle, so
// enough for a shape resting on a few hundred small triangles (FCL stops
// at this many); the adapter keeps DX_SINK_CAPACITY of them, spread.
constexpr std::size_t MESH_CONTACTS = 1024;

// A new model of the data of g (info: its counts).
std::unique_ptr<Model> build_model(dGeomID g, const dxTriMeshInfo &info)
{
    std::vector<fcl::Vector3d> vertices(static_cast<std::size_t>(info.vertex_count));
    for (int i = 0; i < info.vertex_count; i++) {
        dReal v[3];
        dxTriMeshGetVertex(g, i, v);
        vertices[static_cast<std::size_t>(i)] = fcl::Vector3d(v[0], v[1], v[2]);
    }
    std::vector<fcl::Triangle> triangles(static_cast<std::size_t>(info.tri_count));
    for (int t = 0; t < info.tri_count; t++) {
        int idx[3];
        dxTriMeshGetTriangle(g, t, idx);
        triangles[static_cast<std::size_t>(t)].set(static_cast<std::size_t>(idx[0]),
                                                   static_cast<std::size_t>(idx[1]),
                                                   static_cast<std::size_t>(idx[2]));
    }
    std::unique_ptr<Model> model(new Model);
    model->beginModel(info.tri_count, info.vertex_count);
    model->addSubModel(vertices, triangles);
    model->endModel();
    model->computeLocalAABB();
    dxadapter::trace_mesh_model("fcl", "built", info.tri_count);
    return model;
}

// Brings `model` up to the data of g (info: its counts) if the data has the
// model's triangles: the vertices replaced and the tree refit, keeping its
// structure (nothing done if no vertex moved). False if the triangles
// differ: the model must be rebuilt. FCL's replace (not its update, which
// keeps the previous vertices for continuous collision and fits each leaf
// round both frames) with a bottom-up refit: each leaf's box fit to its
// triangle, each parent's the merge of its children's.
bool refit_model(Model &model, dGeomID g, const dxTriMeshInfo &info)
{
    if (model.num_vertices != info.vertex_count || model.num_tris != info.tri_count) return false;
    for (int t = 0; t < info.tri_count; t++) {
        int idx[3];
        dxTriMeshGetTriangle(g, t, idx);
        const fcl::Triangle &tri = model.tri_indices[t];
        for (int k = 0; k < 3; k++)
            if (tri[static_cast<std::size_t>(k)] != static_cast<std::size_t>(idx[k])) return false;
    }
    bool moved = false;
    for (int i = 0; i < info.vertex_count; i++) {
        dReal v[3];
        dxTriMeshGetVertex(g, i, v);
        const fcl::Vector3d p(v[0], v[1], v[2]);
        if (!moved && p == model.vertices[i]) continue;
        if (!moved) {   // the first vertex that moved: the ones before it stay
            moved = true;
            model.beginReplaceModel();
            for (int j = 0; j < i; j++) model.replaceVertex(fcl::Vector3d(model.vertices[j]));
        }
        model.replaceVertex(p);
    }
    if (!moved) return true;
    model.endReplaceModel(true, true);
    model.computeLocalAABB();
    dxadapter::trace_mesh_model("fcl", "refit", info.tri_count);
    return true;
}

const fcl::CollisionRequestd &mesh_request()
{
    static const fcl::CollisionRequestd req(MESH_CONTACTS, true);
    return req;
}

bool is_mesh(dGeomID g) { return dGeomGetClass(g) == dTriMeshClass; }

} // namespace

std::shared_ptr<Geometry> mesh_model(dGeomID g)
{
    dxTriMeshInfo info;
    dxTriMeshGetInfo(g, &info);
    if (!info.data || info.tri_count == 0) return nullptr;
    return dxadapter::ModelRegistry<Model>::instance().shared(
        g, info.data, [&] { return build_model(g, info); },
        [&](Model &model) { return refit_model(model, g, info); });
}

void mesh_changed(dGeomID g, std::shared_ptr<Geometry> held)
{
    dxadapter::ModelRegistry<Model>::instance().park(g, std::move(held));
}

void mesh_destroyed(dGeomID g) { dxadapter::ModelRegistry<Model>::instance().forget(g); }

// Measured against the contract and native (tests/test_backend_trimesh.c,
// 40 poses per pair and mesh, both orders; the grid terrain, icosphere,
// closed box, torus and sheet): the sphere meets it on every mesh once its
// depth's sign is mended (collide_mesh_pair). The others stay native (worst
// errors; ODE_BACKEND_MEASURE_TRIMESH=1 answers them to measure again):
// FCL answers each triangle with libccd's MPR, whose depth and normal
// follow the line between the centres (BACKENDS.md section 4), not the
// least translation:
// - box: depths 0.046 off at 0.1, normals 36 degrees off the face, 0.054
//   overlap left along them (terrain); 0.62 off native's depth (sheet);
// - capsule: 0.067 (terrain) to 0.71 (sheet) off;
// - cylinder: 0.05 (terrain) to 1.09 (sheet) off, 0.056 overlap left;
// - trimesh: depth and normal per triangle pair (fcl#491): points 0.22
//   outside the meshes, 0.14 off native's depth (torus);
// - convex: the adapter has no convex shape.
// The other solver, GST_INDEP, reports no contact for a third of the poses.
bool mesh_pair_supported(int other)
{
    if (other == dSphereClass) return true;
    return dxadapter::measuring_every_mesh_pair() &&
           (other == dBoxClass || other == dCapsuleClass || other == dCylinderClass ||
            other == dTriMeshClass);
}

int collide_mesh_pair(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip)
{
    for (dGeomID g : { o1, o2 })
        if (const char *why = dxTriMeshNeedsNative(g))
            return dxBackendNativeFallback("fcl", o1, o2, flags, out, skip, why);
    const Geometry *s1 = shape_of(o1), *s2 = shape_of(o2);
    if (!s1 || !s2) return 0;   // a mesh without triangles
    const bool keep = in_fcl_order(o1, o2);
    fcl::CollisionResultd res;   // (its contact vector grows per call: FCL's API)
    if (keep) fcl::collide(s1, pose_of(o1), s2, pose_of(o2), mesh_request(), res);
    else fcl::collide(s2, pose_of(o2), s1, pose_of(o1), mesh_request(), res);
    const bool mesh1 = is_mesh(o1), mesh2 = is_mesh(o2);
    const bool sphere = dGeomGetClass(o1) == dSphereClass || dGeomGetClass(o2) == dSphereClass;
    dxadapter::TriangleFilter filter1(o1, o2), filter2(o2, o1);
    dxadapter::RawContacts buffer;
    std::vector<dxRawContact> &raw = buffer.get();
    for (std::size_t i = 0; i < res.numContacts(); i++) {
        const fcl::Contactd &c = res.getContact(i);
        // Which of FCL's objects is o1's: FCL puts a mesh first against a
        // shape; two meshes on one model keep the order they were given in.
        const bool first_is_o1 = s1 == s2 ? keep : c.o1 == s1;
        const int side1 = mesh1 ? static_cast<int>(first_is_o1 ? c.b1 : c.b2) : -1;
        const int side2 = mesh2 ? static_cast<int>(first_is_o1 ? c.b2 : c.b1) : -1;
        if ((mesh1 && !filter1.allowed(side1)) || (mesh2 && !filter2.allowed(side2))) continue;
        const double sign = first_is_o1 ? -1 : 1;   // FCL's normal: from its o1 to its o2
        dxRawContact r;
        for (int k = 0; k < 3; k++) {
            r.pos[k] = static_cast<dReal>(c.pos(k));
            r.normal[k] = static_cast<dReal>(sign * c.normal(k));
        }
        // FCL 0.7's sphere-triangle test (sphereTriangleIntersect) returns
        // minus the depth (fixed upstream later: either sign is the depth).
        r.depth = static_cast<dReal>(sphere ? std::fabs(c.penetration_depth)
                                            : c.penetration_depth);
        if (!(r.depth >= 0)) continue;
        // Triangles are one-sided (as native's): FCL's sphere-triangle test
        // faces each triangle towards the sphere's centre, even behind it.
        const dReal leave2[3] = { r.normal[0], r.normal[1], r.normal[2] },
                    leave1[3] = { -r.normal[0], -r.normal[1], -r.normal[2] };
        if ((mesh1 && !dxTriMeshFrontSide(o1, side1, leave1)) ||
            (mesh2 && !dxTriMeshFrontSide(o2, side2, leave2)))
            continue;
        r.side1 = side1;
        r.side2 = side2;
        raw.push_back(r);
    }
    dxContactSink sink;
    dxSinkInit(&sink);
    dxadapter::fill_sink(raw, &sink);
    return dxSinkFinish(&sink, o1, o2, flags, out, skip);
}

} // namespace dxfcl
