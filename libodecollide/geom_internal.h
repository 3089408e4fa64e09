// SPDX-License-Identifier: BSD-3-Clause
//
// geom_internal.h -- the private structures of the collision library: the
// geom every class extends, the per-class operations, spaces, and the
// services the classes, spaces and backends share.

#ifndef DX_GEOM_INTERNAL_H
#define DX_GEOM_INTERNAL_H

#include <ode/collision.h>
#include <ode/objects.h>
#include <ode/odemath.h>
#include <stdint.h>

#include "../libodedyn/core/dx_check.h"

enum {
    DX_MAGIC_GEOM = 0x47656f6du,   // "Geom"
    DX_MAGIC_GEOM_DEAD = 0xdead6e0du
};

enum {
    DX_GEOM_PLACEABLE = 1 << 0,   // has a pose (planes and spaces do not)
    DX_GEOM_ENABLED = 1 << 1,
    DX_GEOM_AABB_BAD = 1 << 2,    // pose or size changed since the AABB was computed
    DX_GEOM_IS_SPACE = 1 << 3
};

typedef struct dxGeom dxGeom;
typedef struct dxSpace dxSpace;

// What differs between geometry classes (built-in and user).
typedef struct dxGeomClassOps {
    int cls;                      // dSphereClass, ...
    const char *name;             // "sphere", ... for messages
    // Bounding box from the current pose and size, into g->aabb.
    void (*compute_aabb)(dxGeom *g);
    // Release what the class owns (NULL if nothing).
    void (*destroy)(dxGeom *g);
} dxGeomClassOps;

struct dxGeom {
    uint32_t magic;
    uint32_t generation;
    // What a space's pair test reads, together in the first 96 bytes: the
    // box first (most pairs end at it), then the rest of the test.
    unsigned flags;               // DX_GEOM_...
    int space_index;              // its index in space->geoms
    dReal aabb[6];                // minx maxx miny maxy minz maxz, valid unless AABB_BAD
    dBodyID body;                 // attached body, or NULL
    const dxGeomClassOps *ops;
    unsigned long category_bits, collide_bits;
    size_t alloc_size;            // bytes of the whole class structure
    void *data;                   // user data
    dxGeom *body_next;            // next geom of the same body
    // The pose: pos and R point at the body's when attached, else at the
    // geom's own storage (own_pos, own_R). Only placeable geoms have one.
    const dReal *pos;
    const dReal *R;
    dVector3 own_pos;
    dMatrix3 own_R;
    dxSpace *space;               // the space that holds it, or NULL
    dxGeom *holder;               // the geometry transform that holds it, or NULL
    unsigned shape_version;       // bumped when size parameters change (backend caches)
    struct dxGeomOffset *offset;  // its pose relative to its body, or NULL
                                  // (then pos and R are own_pos, own_R: the
                                  // body's pose composed with it, geom_offset.c)
    void *backend_cache;          // a backend's shape object for this geom ...
    const void *backend_cache_owner;   // ... and which backend made it (it frees it)
    void *shadow_cache;           // the same for the shadow backend (backend_shadow.c),
    const void *shadow_cache_owner;    // swapped in around its calls
};

// ---- spaces ------------------------------------------------------------

typedef struct dxSpaceOps {
    // Called after a geom was appended to / is about to be removed from geoms[].
    void (*added)(dxSpace *s, dxGeom *g);
    void (*removed)(dxSpace *s, dxGeom *g);
    // Every pair of geoms of the space whose AABBs overlap, each once: call
    // dxSpaceTestPair for it (which applies bits, enabled and AABB tests).
    void (*collide)(dxSpace *s, void *data, dNearCallback *cb);
    // Every geom of s whose AABB may overlap that of the non-space geom g
    // (AABB already current): call dxSpaceTestPair(g, other) for each, g first.
    void (*collide_geom)(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb);
    // Free what the space type owns (the geoms[] array is freed by the caller).
    void (*destroy)(dxSpace *s);
} dxSpaceOps;

struct dxSpace {
    dxGeom geom;                  // a space is a geom (class dSimpleSpaceClass, ...)
    const dxSpaceOps *sops;
    dxGeom **geoms;               // the geoms, in insertion order (index = space_index)
    int count, capacity;
    int cleanup;                  // destroy the geoms with the space (default 1)
    int manual_cleanup;           // dSpaceSetManualCleanup's mark (default 0)
    int sublevel;
    int lock_count;               // > 0 while colliding: changes are refused
};

// ---- shared services ---------------------------------------------------

static inline int dxGeomIsLive(const dxGeom *g)
{
    return g != NULL && g->magic == DX_MAGIC_GEOM;
}

// Allocate a geom of `size` bytes (the class struct that begins with dxGeom),
// initialise the common part, and add it to `space` (may be NULL).
dxGeom *dxGeomCreate(size_t size, const dxGeomClassOps *ops, unsigned flags, dSpaceID space);
// Mark the AABB stale (pose or size changed) and tell the containing spaces.
void dxGeomMarkMoved(dxGeom *g);
// Size parameters changed: as dxGeomMarkMoved, plus backend caches.
void dxGeomShapeChanged(dxGeom *g);
// Bring g->aabb up to date.
void dxGeomUpdateAABB(dxGeom *g);

// 1 if a and b may collide: different, enabled, not on the same body, their
// category and collide bits match, and their AABBs overlap.
int dxGeomsMayTouch(dxGeom *a, dxGeom *b);
// Call cb(data, a, b) if dxGeomsMayTouch (the shared inner test of spaces).
void dxSpaceTestPair(dxGeom *a, dxGeom *b, void *data, dNearCallback *cb);
// Number of dxSpaceTestPair calls so far: the broad phase's work, which tests
// count (instead of timing) to check how a space scales.
extern unsigned long dx_aabb_tests;
// The hash space passes over a coarser level of at most this many geoms
// when a box test of each finds none meeting a geom's box, without finding
// the geom's cells there (space_hash.c: query_levels). At least 1 (a level
// of one geom is always tested directly); 1 for the cells whenever a level
// has more (for tests that compare the two: the same callbacks in the same
// order).
extern int dxHashFewGeoms;
// Initialise a space's common part (spaces are created by their types).
dxSpace *dxSpaceCreate(size_t size, int cls, const dxSpaceOps *sops, dSpaceID parent);
// Bring every AABB in the space (recursively) up to date.
void dxSpaceUpdateAABBs(dxSpace *s);

// Geom offsets (geom_offset.c). The pose relative to the body:
typedef struct dxGeomOffset {
    dVector3 pos;
    dMatrix3 R;
} dxGeomOffset;
// Recompute an offset geom's world pose (own_pos, own_R) from its body's.
void dxGeomOffsetUpdate(dxGeom *g);
// Forget the offset (the geom keeps pointing at own_pos, own_R, its pose now).
void dxGeomOffsetFree(dxGeom *g);
// Move the body of the offset geom g so that g is at (pos, R).
void dxGeomOffsetMoveBody(dxGeom *g, const dReal *pos, const dReal *R);
// R's nine used entries (padding ignored) made orthonormal into out; 0 if
// they are not finite or not a rotation.
int dxCleanRotation(const dReal *R, dMatrix3 out);
// q normalised into out; 0 if it is not finite or has zero length.
int dxCleanQuaternion(const dReal *q, dQuaternion out);

// A class's handler of dGeomLowLevelControl codes (geom_control.c): returns
// 1 on success; keeps ODE's size protocol with dxGeomControlSizeValid.
typedef int dxGeomControlFn(dxGeom *g, int controlClass, int controlCode, void *dataValue,
                            int *dataSize);
void dxGeomRegisterControl(int cls, dxGeomControlFn *fn);
// 1 if *dataSize is `required` (and dataValue is given when required > 0);
// else sets *dataSize to `required` and returns 0.
int dxGeomControlSizeValid(const void *dataValue, int *dataSize, int required);

// The contacts of a pair whose classes have a dSetColliderOverride
// (collider_override.c); *handled is 0 when they have none.
int dxCollideOverride(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip, int *handled);

// Give dWorldExportDIF (libodedyn) the writer of geom lines (geom_export_dif.c).
void dxGeomRegisterDifWriter(void);

// Contacts produced for (b, a) made into contacts for (a, b): normals
// negated, g1/g2 and side1/side2 swapped (collide.c).
void dxFlipContacts(dContactGeom *c, int n, int skip);

// Contact i of an array written with stride skip.
static inline dContactGeom *dxContactAt(dContactGeom *c, int i, int skip)
{
    return (dContactGeom *)((char *)c + (size_t)i * (size_t)skip);
}

#define DX_CHECK_GEOM(g, on_fail) \
    DX_CHECK_ARG(dxGeomIsLive(g), on_fail, "geom is NULL or was destroyed")

#endif
