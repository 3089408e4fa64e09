// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_adapter.h -- what the FCL and Bullet adapters (C++, header only,
// never installed) share for triangle meshes: asking the per-triangle
// callback about the triangles their engine reports, and per-call contact
// buffers that allocate nothing once warm and survive a callback that
// collides again.

#ifndef DX_TRIMESH_ADAPTER_H
#define DX_TRIMESH_ADAPTER_H

#include "../libodecollide/backend_support.h"

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

// One engine's live mesh models by trimesh data object, weakly held: the
// geoms' cache slots own them. shared(key, build) gives the live model of
// the data object `key`, or makes one with build() (a std::unique_ptr);
// the last owner's release removes the entry, unless a newer model of the
// same data took it. One registry per model type, never destroyed, so a
// model released during the program's exit still finds it.
template <class Model>
class ModelRegistry {
public:
    static ModelRegistry &instance()
    {
        static ModelRegistry *r = new ModelRegistry;
        return *r;
    }

    template <class Build>
    std::shared_ptr<Model> shared(const void *key, Build build)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        std::weak_ptr<Model> &slot = live_[key];
        std::shared_ptr<Model> model = slot.lock();
        if (!model) {
            model = std::shared_ptr<Model>(build().release(), [this, key](Model *m) {
                forget(key);
                delete m;
            });
            slot = model;
        }
        return model;
    }

private:
    ModelRegistry() = default;
    void forget(const void *key)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = live_.find(key);
        if (it != live_.end() && it->second.expired()) live_.erase(it);
    }

    std::mutex mutex_;
    std::unordered_map<const void *, std::weak_ptr<Model>> live_;
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
