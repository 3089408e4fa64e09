// SPDX-License-Identifier: BSD-3-Clause
//
// bullet_backend.cpp -- the Bullet 3.24 narrow phase behind dCollide
// (BACKENDS.md section 5). A collision world without dynamics is made at the
// first collision; each geom gets one btCollisionObject (its shape built once,
// rebuilt when the geom's size changes, freed with the geom), posed from the
// geom on every call; the pair's algorithm from Bullet's dispatcher reports
// its points, which become contacts in ODE's convention through the sink of
// backend_support.h. Rays are not supported (native handles them): measured
// on unit-sized shapes, Bullet's ray casts hit spheres up to 3e-5 off with
// normals up to 7e-3 rad off, capsules up to 2.5 off, and report nothing for
// a ray starting inside a shape.

#include "bullet_trimesh.h"

#include <btBulletCollisionCommon.h>
#include <ode/collision.h>
#include <ode/error.h>

#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace {

// Multipoint perturbation: without it a face-on-face pair gets one point.
// Convex-plane pairs perturb 5 times, 72 degrees apart around the normal, so
// that every 90-degree corner cone of a rectangular face is hit: a box
// face-down on a plane gets its 4 corners (with 3 or 4 it gets 3). The second
// number is the manifold size below which Bullet perturbs; the points never
// reach a manifold here, so it only needs to be positive.
constexpr int PLANE_PERTURBATIONS = 5;
constexpr int CONVEX_PERTURBATIONS = 3;

// Bullet's default configuration with multipoint contacts.
struct MultipointConfiguration : btDefaultCollisionConfiguration {
    MultipointConfiguration()
    {
        setConvexConvexMultipointIterations(CONVEX_PERTURBATIONS, CONVEX_PERTURBATIONS);
        setPlaneConvexMultipointIterations(PLANE_PERTURBATIONS, PLANE_PERTURBATIONS);
    }
};

// A collision world (no dynamics), one a thread (the_world).
struct World {
    MultipointConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btCollisionWorld world{&dispatcher, &broadphase, &config};
};

// This thread's world, made at its first call (freed when the thread ends):
// Bullet's dispatcher takes each pair's algorithm from its own pool, which
// is not safe to share, so threads colliding at once each have their own.
World &the_world()
{
    static thread_local World w;
    return w;
}

// A geom's Bullet object, its shape as of the geom's shape `version` (a
// mesh's is shared with the other geoms on its data).
struct GeomObject {
    unsigned version = 0;
    std::shared_ptr<btCollisionShape> shape;
    btCollisionObject object;
};

// The Bullet shape of an ODE shape (BACKENDS.md section 5 table). Boxes and
// cylinders get margin 0: Bullet's default margin would round their edges.
// A mesh's shape is its data's (bullet_trimesh.cpp).
std::shared_ptr<btCollisionShape> make_shape(dGeomID g, const dxShapeDesc &d)
{
    switch (d.cls) {
    case dSphereClass: return std::make_shared<btSphereShape>(d.p[0]);
    case dBoxClass: {
        auto box = std::make_shared<btBoxShape>(btVector3(d.p[0], d.p[1], d.p[2]) / 2);
        box->setMargin(0);
        return box;
    }
    case dCapsuleClass: return std::make_shared<btCapsuleShapeZ>(d.p[0], d.p[1]);
    case dCylinderClass: {
        auto cyl = std::make_shared<btCylinderShapeZ>(btVector3(d.p[0], d.p[0], d.p[1] / 2));
        cyl->setMargin(0);
        return cyl;
    }
    case dTriMeshClass: return dxbullet::mesh_shape(g);
    default:   // dPlaneClass (supports() admits nothing else): solid where n.x < d, as ODE
        return std::make_shared<btStaticPlaneShape>(btVector3(d.p[0], d.p[1], d.p[2]), d.p[3]);
    }
}

// The world pose of a geom as a Bullet transform (R is row-major 3x4).
btTransform pose_of(dGeomID g)
{
    dReal p[3], R[12];
    dxGeomPose(g, p, R);
    return btTransform(btMatrix3x3(R[0], R[1], R[2], R[4], R[5], R[6], R[8], R[9], R[10]),
                       btVector3(p[0], p[1], p[2]));
}

extern const dCollisionBackend bullet_backend;
const void *const OWNER = &bullet_backend;   // marks the cache slots this backend fills

// The geom's object, made on first use, its shape rebuilt if the geom's size
// changed, posed where the geom is now. Its shape is NULL for a mesh
// without triangles.
GeomObject &posed_object(dGeomID g)
{
    dxShapeDesc d;
    dxGeomDescribe(g, &d);
    auto *obj = static_cast<GeomObject *>(dxGeomCache(g, OWNER));
    if (!obj) {
        auto fresh = std::make_unique<GeomObject>();
        fresh->shape = make_shape(g, d);
        obj = fresh.release();
        obj->object.setCollisionShape(obj->shape.get());
        obj->version = d.version;
        dxGeomSetCache(g, OWNER, obj);
    } else if (obj->version != d.version) {
        obj->shape = make_shape(g, d);
        obj->object.setCollisionShape(obj->shape.get());
        obj->version = d.version;
    }
    obj->object.setWorldTransform(pose_of(g));
    return *obj;
}

// What to keep of the points Bullet's pair algorithm reports. Its first
// point is the pair's own answer; with multipoint perturbation the others
// come from one shape turned slightly and mapped back: measured against the
// shapes, they lie outside them by up to several times the depth (0.086 for
// a box against a cylinder 0.057 deep) and can be deeper than the pair.
enum class Points {
    ALL,       // exact algorithms: box-box (ODE's), convex-plane (depths recomputed)
    FIRST,     // GJK/EPA pairs: the first point only (a reduced manifold)
    PER_TRIANGLE   // a shape against a mesh: the first point of each triangle
};

// Takes the points of Bullet's pair algorithm (instead of keeping them in a
// manifold, which would merge and cap them) and adds the touching ones to the
// sink in ODE's sense for (o1, o2). A point comes as Bullet's manifold orders
// the pair (A, B), which may be either way round: the normal lies on B and
// points towards A, the point is on B, A's point is `distance` along the
// normal from it (negative: they overlap). The contact position is the middle
// of the two, except against a plane (always B): there B's point is on the
// plane's surface, outside an A sunk deeper than its height, so A's point
// (its deepest, as native puts it) is used. Against a mesh B is the
// triangle, and B's point (on it, inside the shape) is used: the middle can
// leave a curved mesh's solid. A mesh is always the second of the pair
// (w2, classes in order): its triangle is the result's m_index1, the
// contact's side on the mesh's side, and `mesh` (the mesh's filter, else
// NULL) drops the triangles the per-triangle callback vetoes.
class SinkResult : public btManifoldResult {
public:
    SinkResult(const btCollisionObjectWrapper *w1, const btCollisionObjectWrapper *w2,
               const btCollisionObject *o1, Points keep, bool plane_pair,
               dxadapter::TriangleFilter *mesh, bool mesh_is_o1,
               std::vector<dxRawContact> &out)
        : btManifoldResult(w1, w2), o1_(o1), keep_(keep),
          a_fraction_(plane_pair ? 1 : mesh ? 0 : 0.5), mesh_(mesh), mesh_is_o1_(mesh_is_o1),
          out_(out)
    {
    }

    void addContactPoint(const btVector3 &normal_on_b, const btVector3 &point_on_b,
                         btScalar distance) override
    {
        if (keep_ == Points::PER_TRIANGLE) {
            if (points_++ > 0 && m_index1 == last_triangle_) return;
            last_triangle_ = m_index1;
        } else if (points_++ > 0 && keep_ == Points::FIRST) {
            return;
        }
        if (distance > 0) return;   // a near miss, not a contact
        const int triangle = mesh_ ? m_index1 : -1;
        if (mesh_ && !mesh_->allowed(triangle)) return;
        bool o1_is_a = !m_manifoldPtr || m_manifoldPtr->getBody0() == o1_;
        btVector3 n = o1_is_a ? normal_on_b : -normal_on_b;
        btVector3 p = point_on_b + normal_on_b * (distance * a_fraction_);
        dxRawContact r = { { p.x(), p.y(), p.z() }, { n.x(), n.y(), n.z() }, -distance,
                           mesh_is_o1_ ? triangle : -1, mesh_is_o1_ ? -1 : triangle };
        // Triangles are one-sided (as native's): Bullet's sphere-triangle
        // test faces each triangle towards the sphere's centre, even behind it.
        const dReal s = mesh_is_o1_ ? -1 : 1;   // the other leaves along -n if the mesh is o1
        const dReal leave[3] = { s * r.normal[0], s * r.normal[1], s * r.normal[2] };
        if (mesh_ && !dxTriMeshFrontSide(mesh_->mesh(), triangle, leave)) return;
        out_.push_back(r);
    }

private:
    const btCollisionObject *o1_;   // the object of the dCollide call's o1
    Points keep_;
    btScalar a_fraction_;           // where pos lies from B's point (0) to A's (1)
    int points_ = 0;
    int last_triangle_ = -1;        // the triangle of the last point (PER_TRIANGLE)
    dxadapter::TriangleFilter *mesh_;
    bool mesh_is_o1_;
    std::vector<dxRawContact> &out_;
};

// A pair's algorithm from the dispatcher's pool, given back on scope exit.
class PairAlgorithm {
public:
    PairAlgorithm(btCollisionDispatcher &d, const btCollisionObjectWrapper *w1,
                  const btCollisionObjectWrapper *w2)
        : dispatcher_(d), algorithm_(d.findAlgorithm(w1, w2, nullptr,
                                                     BT_CONTACT_POINT_ALGORITHMS))
    {
    }
    ~PairAlgorithm()
    {
        if (!algorithm_) return;
        algorithm_->~btCollisionAlgorithm();
        dispatcher_.freeCollisionAlgorithm(algorithm_);
    }
    PairAlgorithm(const PairAlgorithm &) = delete;
    PairAlgorithm &operator=(const PairAlgorithm &) = delete;
    btCollisionAlgorithm *get() const { return algorithm_; }

private:
    btCollisionDispatcher &dispatcher_;
    btCollisionAlgorithm *algorithm_;
};

// A failure inside an entry point, through ODE's message handler.
void report(const char *entry, const char *what)
{
    dMessage(d_ERR_UNKNOWN, "bullet backend: %s failed: %s", entry, what);
}

// The classes with a Bullet shape.
bool is_solid(int cls)
{
    return cls == dSphereClass || cls == dBoxClass || cls == dCapsuleClass ||
           cls == dCylinderClass || cls == dPlaneClass;
}

// A cylinder against a box or a cylinder: Bullet's EPA fails on some such
// poses. Against the support-function truth (500 random poses, both
// orders), two cylinders got depths 0.22 off in 4 of 1000 calls, along
// normals that leave them overlapped by 0.27; in tests/test_backends.c's
// poses a box-cylinder contact lay 0.086 and 0.072 outside the two shapes
// for a depth of 0.057. Bullet's other penetration solver,
// btMinkowskiPenetrationDepthSolver, is worse (a third of the cylinder
// pairs, and sphere-cylinder, box-capsule and capsule-cylinder fail).
// Capsule-cylinder meets the contract once its points are moved into both
// shapes (complete_contacts).
bool epa_cylinder_pair(int c1, int c2)
{
    bool cyl1 = c1 == dCylinderClass, cyl2 = c2 == dCylinderClass;
    auto epa_partner = [](int c) { return c == dBoxClass || c == dCylinderClass; };
    return (cyl1 && epa_partner(c2)) || (cyl2 && epa_partner(c1));
}

// Every pair of solids except two planes (never in contact: native's answer)
// and the cylinder pairs Bullet's EPA gets wrong (native does them); the
// trimesh pairs of bullet_trimesh.cpp (dxbullet::mesh_pair_supported).
int bullet_supports(int c1, int c2) noexcept
{
    if (c1 == dTriMeshClass) return dxbullet::mesh_pair_supported(c2);
    if (c2 == dTriMeshClass) return dxbullet::mesh_pair_supported(c1);
    return is_solid(c1) && is_solid(c2) && !(c1 == dPlaneClass && c2 == dPlaneClass) &&
           !epa_cylinder_pair(c1, c2);
}

// Which points of a class pair to keep (c1 <= c2).
Points points_to_keep(int c1, int c2)
{
    if (c2 == dPlaneClass || (c1 == dBoxClass && c2 == dBoxClass)) return Points::ALL;
    return Points::FIRST;
}

// Whether (g1, g2) comes before (g2, g1): by class, then by pose, then by
// address. Bullet always gets a pair in that order (GJK's answer depends on
// it), so that dCollide(b, a) mirrors dCollide(a, b) exactly.
bool in_order(dGeomID g1, dGeomID g2)
{
    int c1 = dGeomGetClass(g1), c2 = dGeomGetClass(g2);
    if (c1 != c2) return c1 < c2;
    dReal p1[15], p2[15];
    dxGeomPose(g1, p1, p1 + 3);
    dxGeomPose(g2, p2, p2 + 3);
    for (int i = 0; i < 15; i++)
        if (p1[i] != p2[i]) return p1[i] < p2[i];
    return std::less<const void *>()(g1, g2);
}

// What Bullet leaves out of the contract (issue 14): a capsule or cylinder
// on a plane gets one point even with multipoint perturbation, which becomes
// the manifold of its end or rim points under the plane Bullet's answer
// defines; a contact point of two solids is the middle of the witness
// segment, which leaves one of them when deep (box-box, sphere-cylinder:
// 0.09 and 0.06 outside), so it is moved to the middle or an end of that
// segment, whichever lies deepest in both.
void complete_contacts(dGeomID o1, dGeomID o2, dxContactSink *sink)
{
    const int c1 = dGeomGetClass(o1), c2 = dGeomGetClass(o2);
    auto curved = [](int c) { return c == dCapsuleClass || c == dCylinderClass; };
    if (c2 == dPlaneClass && curved(c1)) dxSinkPlaneManifold(sink, o1, 1);
    if (c1 == dPlaneClass && curved(c2)) dxSinkPlaneManifold(sink, o2, 0);
    if (c1 != dPlaneClass && c2 != dPlaneClass) dxSinkPointsInBoth(sink, o1, o2);
}

// The contacts of two solids, Bullet seeing them as (first, second). A mesh
// that needs what only native does (dxTriMeshNeedsNative) goes there.
int collide_pair(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip)
{
    if (!bullet_supports(dGeomGetClass(o1), dGeomGetClass(o2))) return 0;
    for (dGeomID g : { o1, o2 })
        if (const char *why = dxTriMeshNeedsNative(g))
            return dxBackendNativeFallback("bullet", o1, o2, flags, out, skip, why);
    bool keep_order = in_order(o1, o2);
    dGeomID first = keep_order ? o1 : o2, second = keep_order ? o2 : o1;
    int c1 = dGeomGetClass(first), c2 = dGeomGetClass(second);
    World &w = the_world();
    GeomObject &a = posed_object(first), &b = posed_object(second);
    if (!a.shape || !b.shape) return 0;   // a mesh without triangles
    btCollisionObjectWrapper wa(nullptr, a.shape.get(), &a.object, a.object.getWorldTransform(),
                                -1, -1);
    btCollisionObjectWrapper wb(nullptr, b.shape.get(), &b.object, b.object.getWorldTransform(),
                                -1, -1);
    PairAlgorithm algorithm(w.dispatcher, &wa, &wb);
    if (!algorithm.get()) return 0;
    const bool mesh = c2 == dTriMeshClass;   // (a mesh comes last in class order)
    dxadapter::TriangleFilter filter(second, first);
    dxadapter::RawContacts raw;
    SinkResult result(&wa, &wb, keep_order ? &a.object : &b.object,
                      mesh ? Points::PER_TRIANGLE : points_to_keep(c1, c2), c2 == dPlaneClass,
                      mesh ? &filter : nullptr, second == o1, raw.get());
    algorithm.get()->processCollision(&wa, &wb, w.world.getDispatchInfo(), &result);
    dxContactSink sink;
    dxSinkInit(&sink);
    dxadapter::fill_sink(raw.get(), &sink);
    if (!mesh) complete_contacts(o1, o2, &sink);
    return dxSinkFinish(&sink, o1, o2, flags, out, skip);
}

// dCollide's narrow phase (backend table entry): no exception leaves it.
int bullet_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *out, int skip)
{
    try {
        return collide_pair(o1, o2, flags, out, skip);
    } catch (const std::exception &e) {
        report("dCollide", e.what());
    } catch (...) {
        report("dCollide", "unknown exception");
    }
    return 0;
}

// Frees the geom's object if this backend made it; a changed mesh's shape
// goes to the registry first, to be refit (bullet_trimesh.cpp).
void drop_object(dGeomID g, bool changed)
{
    std::unique_ptr<GeomObject> obj(static_cast<GeomObject *>(dxGeomOwnedCache(g, OWNER)));
    if (obj) dxGeomSetCache(g, OWNER, nullptr);
    if (dGeomGetClass(g) != dTriMeshClass) return;
    if (changed) dxbullet::mesh_changed(g, obj ? std::move(obj->shape) : nullptr);
    else dxbullet::mesh_destroyed(g);
}

// The geom's size changed: its object goes (rebuilt at the next collision).
void bullet_geom_changed(dGeomID g)
{
    try {
        drop_object(g, true);
    } catch (...) {
        report("geom_changed", "unknown exception");
    }
}

// The geom is being destroyed: its object goes with it.
void bullet_geom_destroyed(dGeomID g)
{
    try {
        drop_object(g, false);
    } catch (...) {
        report("geom_destroyed", "unknown exception");
    }
}

const dCollisionBackend bullet_backend = { "bullet", bullet_supports, bullet_collide,
                                           bullet_geom_changed, bullet_geom_destroyed };

}   // namespace

// The module's entry point (backend_support.h).
const dCollisionBackend *dxBackendModule(const char *abi)
{
    return std::strcmp(abi, DX_BACKEND_ABI) == 0 ? &bullet_backend : nullptr;
}
