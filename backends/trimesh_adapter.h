// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_adapter.h -- what the FCL and Bullet adapters (C++, header only,
// never installed) share for triangle meshes: asking the per-triangle
// callback about the triangles their engine reports, per-call contact
// buffers that allocate nothing once warm and survive a callback that
// collides again, and the registry of mesh models (one per data object,
// refit when Update moved the vertices).

#ifndef DX_TRIMESH_ADAPTER_H
#define DX_TRIMESH_ADAPTER_H

#include "../libodecollide/backend_support.h"

#include <ode/error.h>

#include <cstdlib>
#include <deque>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace dxadapter {

// ODE_BACKEND_MEASURE_TRIMESH set (to anything): the adapters answer the
// trimesh pairs they leave to native too, so that tests/test_backend_trimesh
// can measure them against the contract (never for simulations: those pairs
// break it). Read once.
inline bool measuring_every_mesh_pair()
{
    static const bool on = std::getenv("ODE_BACKEND_MEASURE_TRIMESH") != nullptr;
    return on;
}

// Whether triangle t of a mesh may give contacts with `other`
// (dxTriMeshTriangleAllowed): the per-triangle callback is asked once per
// triangle for the first MEMO triangles of a call, then again each time.
class TriangleFilter {
public:
    TriangleFilter(dGeomID mesh, dGeomID other) : mesh_(mesh), other_(other) {}
    dGeomID mesh() const { return mesh_; }
    bool allowed(int t)
    {
        for (int i = 0; i < count_; i++)
            if (tri_[i] == t) return ok_[i];
        const bool ok = dxTriMeshTriangleAllowed(mesh_, other_, t) != 0;
        if (count_ < MEMO) {
            tri_[count_] = t;
            ok_[count_++] = ok;
        }
        return ok;
    }

private:
    static constexpr int MEMO = 64;
    dGeomID mesh_, other_;
    int tri_[MEMO];
    bool ok_[MEMO];
    int count_ = 0;
};

// A raw-contact buffer for one collision of this thread, emptied; given
// back at scope exit. A callback colliding inside a collision gets the next
// buffer, so nesting never clears a buffer in use.
class RawContacts {
public:
    RawContacts() : buffer_(acquire()) { buffer_.clear(); }
    ~RawContacts() { depth()--; }
    RawContacts(const RawContacts &) = delete;
    RawContacts &operator=(const RawContacts &) = delete;
    std::vector<dxRawContact> &get() { return buffer_; }

private:
    static int &depth()
    {
        thread_local int d = 0;
        return d;
    }
    static std::vector<dxRawContact> &acquire()
    {
        thread_local std::deque<std::vector<dxRawContact>> pool;   // stable references
        const std::size_t level = static_cast<std::size_t>(depth()++);
        if (pool.size() <= level) pool.resize(level + 1);
        return pool[level];
    }
    std::vector<dxRawContact> &buffer_;
};

// ODE_BACKEND_TRACE_TRIMESH set (to anything): the adapters say through
// dMessage each mesh model they build or refit, so that tests can count
// them (tests/test_backend_trimesh_refit.c). Read once.
inline bool tracing_mesh_models()
{
    static const bool on = std::getenv("ODE_BACKEND_TRACE_TRIMESH") != nullptr;
    return on;
}

// Says (when tracing) that `engine` built or refit a model of `count` triangles.
inline void trace_mesh_model(const char *engine, const char *what, int count)
{
    if (tracing_mesh_models())
        dMessage(d_ERR_UNKNOWN, "%s backend: trimesh model %s (%d triangles)", engine, what,
                 count);
}

// One engine's live mesh models by trimesh data object, weakly held: the
// geoms' cache slots own them. shared(g, key, build, refit) gives mesh geom
// g the live model of the data object `key`, or makes one with build() (a
// std::unique_ptr). A data object that changes (Build, Update, SetData)
// drops every geom's cache (geom_changed); a geom that held the data's
// model hands it to park() first, which keeps it (for that geom, until its
// next shared() or forget()) and marks it stale, so that the next shared()
// on the data brings the same model up to date with refit(model) -- true
// when it could (the same triangles: the vertices refit in place, or
// nothing moved), false when the triangles differ, and a new model is
// built. The last owner's release removes the entry, unless a newer model
// of the same data took it. One registry per model type, never destroyed,
// so a model released during the program's exit still finds it.
//
// Threads: every call locks the registry; a refit runs under that lock, so
// the first collision after a change refits once and the others wait for
// it. A refit writes the model that other collisions read: Build, Update
// and SetData must not run while a collision uses the data (ODE's rule too:
// they are called between steps), after which collisions on any threads
// are safe.
template <class Model>
class ModelRegistry {
public:
    static ModelRegistry &instance()
    {
        static ModelRegistry *r = new ModelRegistry;
        return *r;
    }

    template <class Build, class Refit>
    std::shared_ptr<Model> shared(dGeomID g, const void *key, Build build, Refit refit)
    {
        std::shared_ptr<Model> replaced;   // these released after the lock (deleters lock)
        std::shared_ptr<const void> kept;
        std::lock_guard<std::mutex> lock(mutex_);
        Entry &e = live_[key];
        std::shared_ptr<Model> model = e.model.lock();
        if (model && e.stale && !refit(*model)) replaced = std::move(model);
        if (!model) {
            model = std::shared_ptr<Model>(build().release(), [this, key](Model *m) {
                forget_model(key);
                delete m;
            });
            e.model = model;
        }
        e.stale = false;
        kept = take_parked(g);
        return model;
    }

    // Mesh geom g's data changed (geom_changed), g holding `held` (or NULL:
    // a pointer that owns a model, or part of one): if held owns the model
    // of g's data as it is now (with triangles), it is kept for g and the
    // model marked stale.
    void park(dGeomID g, std::shared_ptr<const void> held)
    {
        dxTriMeshInfo info;
        dxTriMeshGetInfo(g, &info);
        const void *key = info.tri_count > 0 ? info.data : nullptr;
        std::shared_ptr<const void> released = std::move(held), kept;   // after the lock
        std::lock_guard<std::mutex> lock(mutex_);
        kept = take_parked(g);
        auto it = key ? live_.find(key) : live_.end();
        if (!released || it == live_.end()) return;
        const std::weak_ptr<Model> &live = it->second.model;
        if (released.owner_before(live) || live.owner_before(released)) return;   // another
        it->second.stale = true;
        parked_[g] = std::move(released);
    }

    // Geom g is destroyed: what it kept goes.
    void forget(dGeomID g)
    {
        std::shared_ptr<const void> kept;   // released after the lock
        std::lock_guard<std::mutex> lock(mutex_);
        kept = take_parked(g);
    }

private:
    struct Entry {
        std::weak_ptr<Model> model;
        bool stale = false;   // the data changed since the model was made or refit
    };

    ModelRegistry() = default;

    // What g kept (NULL if nothing), no longer kept: the caller releases it
    // after the lock.
    std::shared_ptr<const void> take_parked(dGeomID g)
    {
        auto it = parked_.find(g);
        if (it == parked_.end()) return nullptr;
        std::shared_ptr<const void> kept = std::move(it->second);
        parked_.erase(it);
        return kept;
    }

    void forget_model(const void *key)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = live_.find(key);
        if (it != live_.end() && it->second.model.expired()) live_.erase(it);
    }

    std::mutex mutex_;
    std::unordered_map<const void *, Entry> live_;
    std::unordered_map<dGeomID, std::shared_ptr<const void>> parked_;
};

// The contacts gathered (more than a sink holds, for a mesh) into the sink:
// at most DX_SINK_CAPACITY, the deepest then spread (dxContactsSelect).
inline void fill_sink(std::vector<dxRawContact> &raw, dxContactSink *sink)
{
    const int n = dxContactsSelect(raw.data(), static_cast<int>(raw.size()), DX_SINK_CAPACITY);
    for (int i = 0; i < n; i++) {
        const dxRawContact &r = raw[static_cast<std::size_t>(i)];
        dxSinkAdd(sink, r.pos, r.normal, r.depth, r.side1, r.side2);
    }
}

} // namespace dxadapter

#endif
