// SPDX-License-Identifier: BSD-3-Clause
//
// fcl_backend.cpp -- the FCL 0.7 narrow phase behind dCollide (BACKENDS.md
// section 4): one FCL shape per geom, kept in the geom's backend cache slot
// and rebuilt when the geom's size changes; poses read on every call; FCL's
// contacts turned into ODE's convention through the contact sink.

#include "fcl_trimesh.h"

#include <ode/collision.h>
#include <ode/error.h>

#include <cstring>
#include <exception>
#include <functional>
#include <memory>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>

using dxfcl::Geometry;
using dxfcl::in_fcl_order;
using dxfcl::pose_of;
using dxfcl::shape_of;

namespace {

// FCL's shape for one geom, and the shape version it was built from (a
// mesh's model is shared by the geoms on its data: fcl_trimesh.cpp).
struct ShapeCache {
    std::shared_ptr<Geometry> shape;
    unsigned version;
};

// Raw contacts asked of FCL: the sink's capacity (it selects the max asked).
constexpr std::size_t RAW_CONTACTS = DX_SINK_CAPACITY;

int fcl_supports(int c1, int c2) noexcept;
int fcl_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip);
void fcl_geom_changed(dGeomID g);
void fcl_geom_destroyed(dGeomID g);

const dCollisionBackend table = { "fcl", fcl_supports, fcl_collide, fcl_geom_changed,
                                  fcl_geom_destroyed };

// Classes with an FCL shape here (rays are native only: FCL has no ray).
bool is_primitive(int cls)
{
    return cls == dSphereClass || cls == dBoxClass || cls == dCapsuleClass ||
           cls == dCylinderClass || cls == dPlaneClass;
}

// Primitive pairs, except those where FCL 0.7 cannot meet the contract
// (issue 14; they fall back to native, which dCollide reports once):
// - plane-plane: two FCL half-spaces intersect unless parallel and facing
//   apart, while ODE never collides two planes;
// - sphere-capsule: depth and normal are right, but the contact point is the
//   capsule's axis point moved by the depth towards the sphere, which can lie
//   well outside the sphere (sphereCapsuleIntersect);
// - a capsule or cylinder against a box, capsule or cylinder: fcl::collide
//   answers them by libccd's MPR, whose depth is where the line through the
//   centres leaves the Minkowski difference, not the least translation
//   (measured on random poses against tests' support-function truth: up to
//   0.28 off on box-cylinder, 2x on capsule-capsule). Its other solver,
//   GST_INDEP, reports no contact for these pairs, a smaller GJK tolerance
//   changes nothing, and the signed distance (GJK then EPA) aborts inside
//   libfcl on an assertion (isOutsidePolytopeFace) on some poses.
// Trimesh pairs: fcl_trimesh.cpp (dxfcl::mesh_pair_supported).
// (Nothing here can throw, hence no try/catch.)
int fcl_supports(int c1, int c2) noexcept
{
    if (c1 == dTriMeshClass) return dxfcl::mesh_pair_supported(c2);
    if (c2 == dTriMeshClass) return dxfcl::mesh_pair_supported(c1);
    if (!is_primitive(c1) || !is_primitive(c2)) return 0;
    const int lo = c1 < c2 ? c1 : c2, hi = c1 < c2 ? c2 : c1;
    if (lo == dPlaneClass && hi == dPlaneClass) return 0;
    if (lo == dSphereClass) return hi != dCapsuleClass;
    return hi != dCapsuleClass && hi != dCylinderClass;   // box-box, or anything-plane
}

// The FCL shape of a description (sizes mean the same in both libraries,
// section 4: full box sides, capsule length without caps, z axes). An ODE
// plane is a half-space, solid where n.x < d, which is FCL's Halfspace.
std::shared_ptr<Geometry> make_shape(dGeomID g, const dxShapeDesc &d)
{
    switch (d.cls) {
    case dSphereClass: return std::make_shared<fcl::Sphered>(d.p[0]);
    case dBoxClass: return std::make_shared<fcl::Boxd>(d.p[0], d.p[1], d.p[2]);
    case dCapsuleClass: return std::make_shared<fcl::Capsuled>(d.p[0], d.p[1]);
    case dCylinderClass: return std::make_shared<fcl::Cylinderd>(d.p[0], d.p[1]);
    case dTriMeshClass: return dxfcl::mesh_model(g);
    default:
        return std::make_shared<fcl::Halfspaced>(fcl::Vector3d(d.p[0], d.p[1], d.p[2]), d.p[3]);
    }
}

} // namespace

namespace dxfcl {

// The geom's FCL shape: the cached one, or a new one when there is none or
// the geom's size changed since it was built.
const Geometry *shape_of(dGeomID g)
{
    dxShapeDesc d;
    dxGeomDescribe(g, &d);
    auto *c = static_cast<ShapeCache *>(dxGeomCache(g, &table));
    if (c && c->version == d.version) return c->shape.get();
    std::shared_ptr<Geometry> shape = make_shape(g, d);
    if (!c) {
        c = new ShapeCache;
        dxGeomSetCache(g, &table, c);
    }
    c->shape = std::move(shape);
    c->version = d.version;
    return c->shape.get();
}

// The geom's world pose as an FCL transform (R is row-major 3x4).
fcl::Transform3d pose_of(dGeomID g)
{
    dReal pos[3], R[12];
    dxGeomPose(g, pos, R);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) tf.linear()(i, j) = R[i * 4 + j];
        tf.translation()(i) = pos[i];
    }
    return tf;
}

} // namespace dxfcl

namespace {

const fcl::CollisionRequestd &request()
{
    static const fcl::CollisionRequestd req(RAW_CONTACTS, true);
    return req;
}

// Each contact into the sink. FCL's normal points from its o1 to its o2;
// ODE's points into g1, so it is negated when FCL's o1 is g1's shape.
void add_contacts(const fcl::CollisionResultd &res, const Geometry *s1, dxContactSink *sink)
{
    for (std::size_t i = 0; i < res.numContacts(); i++) {
        const fcl::Contactd &c = res.getContact(i);
        const double sign = c.o1 == s1 ? -1 : 1;
        dReal pos[3], n[3];
        for (int k = 0; k < 3; k++) {
            pos[k] = static_cast<dReal>(c.pos(k));
            n[k] = static_cast<dReal>(sign * c.normal(k));
        }
        dxSinkAdd(sink, pos, n, static_cast<dReal>(c.penetration_depth), -1, -1);
    }
}

// What FCL leaves out of the contract (issue 14): a box, capsule or
// cylinder on a half-space gets one contact, which becomes the manifold of
// the shape's features under the plane FCL's answer defines; a contact point
// of two solids can lie outside one (box-box: the middle of the witness
// segment, ODE's box-box as ported, leaves a thin box when deep; sphere-
// cylinder: 0.06 outside on 1 pose in 400), so it is moved along its normal
// to the middle or an end of that segment, whichever lies deepest in both.
void complete_contacts(dGeomID o1, dGeomID o2, dxContactSink *sink)
{
    const int c1 = dGeomGetClass(o1), c2 = dGeomGetClass(o2);
    auto faces = [](int c) { return c == dBoxClass || c == dCapsuleClass || c == dCylinderClass; };
    if (c2 == dPlaneClass && faces(c1)) dxSinkPlaneManifold(sink, o1, 1);
    if (c1 == dPlaneClass && faces(c2)) dxSinkPlaneManifold(sink, o2, 0);
    if (c1 != dPlaneClass && c2 != dPlaneClass) dxSinkPointsInBoth(sink, o1, o2);
}

void report(const char *what, const char *why)
{
    dMessage(d_ERR_UNKNOWN, "fcl backend: %s failed: %s", what, why);
}

} // namespace

namespace dxfcl {

// Whether FCL should see the pair as (g1, g2) rather than (g2, g1): by
// class, then by pose and size, then by address. FCL's iterative answers
// depend a little on the order: a fixed one makes dCollide(b, a) exactly
// dCollide(a, b) mirrored, and (unlike addresses alone) the same from run
// to run.
bool in_fcl_order(dGeomID g1, dGeomID g2)
{
    const int c1 = dGeomGetClass(g1), c2 = dGeomGetClass(g2);
    if (c1 != c2) return c1 < c2;
    dReal k1[19], k2[19];   // position, rotation, size
    dxShapeDesc d1, d2;
    dxGeomPose(g1, k1, k1 + 3);
    dxGeomPose(g2, k2, k2 + 3);
    dxGeomDescribe(g1, &d1);
    dxGeomDescribe(g2, &d2);
    for (int i = 0; i < 4; i++) k1[15 + i] = d1.p[i], k2[15 + i] = d2.p[i];
    for (int i = 0; i < 19; i++)
        if (k1[i] != k2[i]) return k1[i] < k2[i];
    return std::less<dGeomID>()(g1, g2);
}

} // namespace dxfcl

namespace {

// Contacts of two geoms through fcl::collide on the cached shapes
// (the geometry-and-transform form: no CollisionObject is needed), the pair
// in FCL's order. The result's contact vector is reused from call to call.
int fcl_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip)
{
    try {
        if (!fcl_supports(dGeomGetClass(o1), dGeomGetClass(o2))) return 0;
        if (dGeomGetClass(o1) == dTriMeshClass || dGeomGetClass(o2) == dTriMeshClass)
            return dxfcl::collide_mesh_pair(o1, o2, flags, out, skip);
        const bool keep = in_fcl_order(o1, o2);
        const dGeomID f1 = keep ? o1 : o2, f2 = keep ? o2 : o1;
        const Geometry *s1 = shape_of(o1), *s2 = shape_of(o2);
        thread_local fcl::CollisionResultd res;
        res.clear();
        fcl::collide(keep ? s1 : s2, pose_of(f1), keep ? s2 : s1, pose_of(f2), request(), res);
        dxContactSink sink;
        dxSinkInit(&sink);
        add_contacts(res, s1, &sink);
        complete_contacts(o1, o2, &sink);
        return dxSinkFinish(&sink, o1, o2, flags, out, skip);
    } catch (const std::exception &e) {
        report("collide", e.what());
    } catch (...) {
        report("collide", "unknown exception");
    }
    return 0;
}

// Frees the geom's shape if this backend made it (a changed geom gets a new
// one at its next collision); a changed mesh's model goes to the registry
// first, to be refit (fcl_trimesh.cpp).
void drop_cache(dGeomID g, bool changed)
{
    std::unique_ptr<ShapeCache> c(static_cast<ShapeCache *>(dxGeomOwnedCache(g, &table)));
    if (c) dxGeomSetCache(g, &table, nullptr);
    if (dGeomGetClass(g) != dTriMeshClass) return;
    if (changed) dxfcl::mesh_changed(g, c ? std::move(c->shape) : nullptr);
    else dxfcl::mesh_destroyed(g);
}

void fcl_geom_changed(dGeomID g)
{
    try {
        drop_cache(g, true);
    } catch (...) {
        report("dropping a changed shape", "unknown exception");
    }
}

void fcl_geom_destroyed(dGeomID g)
{
    try {
        drop_cache(g, false);
    } catch (...) {
        report("dropping a destroyed geom's shape", "unknown exception");
    }
}

} // namespace

// The module's entry point (backend_support.h).
const dCollisionBackend *dxBackendModule(const char *abi)
{
    return std::strcmp(abi, DX_BACKEND_ABI) == 0 ? &table : nullptr;
}
