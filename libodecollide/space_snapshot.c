// SPDX-License-Identifier: BSD-3-Clause
//
// space_snapshot.c -- dSpaceSnapshot / dSpaceRestore (ours, <ode/snapshot.h>):
// the geoms of a space and of the spaces inside it, in space order: enabled
// or not, category and collide bits, the pose of those not on a body (the
// others follow their bodies, whose snapshot is the world's), and the size
// of the primitive classes (sphere, box, capsule, cylinder, plane, ray with
// its flags). A restore finds exactly the same geoms (handle, generation,
// class, body) in the same order, or refuses and changes nothing. The
// header is the world snapshot's (snapshot_format.c) with its own magic.

#include "geom_internal.h"
#include "../libodedyn/io/snapshot_io.h"

#include <ode/snapshot.h>

#define SPACE_MAGIC "ODESPAC"   // with its terminating zero: 8 bytes
#define MAX_SHAPE 4

// The class's size parameters into x; returns how many.
static int shape_of(dxGeom *g, dReal *x)
{
    switch (g->ops->cls) {
    case dSphereClass:
        x[0] = dGeomSphereGetRadius(g);
        return 1;
    case dBoxClass: {
        dVector3 l;
        dGeomBoxGetLengths(g, l);
        x[0] = l[0];
        x[1] = l[1];
        x[2] = l[2];
        return 3;
    }
    case dCapsuleClass:
        dGeomCapsuleGetParams(g, &x[0], &x[1]);
        return 2;
    case dCylinderClass:
        dGeomCylinderGetParams(g, &x[0], &x[1]);
        return 2;
    case dPlaneClass: {
        dVector4 p;
        dGeomPlaneGetParams(g, p);
        for (int i = 0; i < 4; i++) x[i] = p[i];
        return 4;
    }
    case dRayClass:
        x[0] = dGeomRayGetLength(g);
        x[1] = (dReal)dGeomRayGetFirstContact(g);
        x[2] = (dReal)dGeomRayGetBackfaceCull(g);
        x[3] = (dReal)dGeomRayGetClosestHit(g);
        return 4;
    default:
        return 0;
    }
}

static void set_shape(dxGeom *g, const dReal *x)
{
    switch (g->ops->cls) {
    case dSphereClass: dGeomSphereSetRadius(g, x[0]); break;
    case dBoxClass: dGeomBoxSetLengths(g, x[0], x[1], x[2]); break;
    case dCapsuleClass: dGeomCapsuleSetParams(g, x[0], x[1]); break;
    case dCylinderClass: dGeomCylinderSetParams(g, x[0], x[1]); break;
    case dPlaneClass: dGeomPlaneSetParams(g, x[0], x[1], x[2], x[3]); break;
    case dRayClass:
        dGeomRaySetLength(g, x[0]);
        dGeomRaySetFirstContact(g, x[1] != 0);
        dGeomRaySetBackfaceCull(g, x[2] != 0);
        dGeomRaySetClosestHit(g, x[3] != 0);
        break;
    default: break;
    }
}

static int has_own_pose(const dxGeom *g) { return (g->flags & DX_GEOM_PLACEABLE) && !g->body; }

static void put_geoms(dxSnapWriter *o, const dxSpace *s)
{
    for (int i = 0; i < s->count; i++) {
        dxGeom *g = s->geoms[i];
        dxSnapPutU64(o, (uint64_t)(uintptr_t)g);
        dxSnapPutU32(o, g->generation);
        dxSnapPutU32(o, (uint32_t)g->ops->cls);
        dxSnapPutU64(o, (uint64_t)(uintptr_t)g->body);
        dxSnapPutU32(o, (g->flags & DX_GEOM_ENABLED) ? 1 : 0);
        dxSnapPutU64(o, g->category_bits);
        dxSnapPutU64(o, g->collide_bits);
        if (has_own_pose(g)) {
            dxSnapPutReals(o, g->own_pos, 4);
            dxSnapPutReals(o, g->own_R, 12);
        }
        dReal x[MAX_SHAPE];
        const int n = shape_of(g, x);
        dxSnapPutReals(o, x, (size_t)n);
        if (g->flags & DX_GEOM_IS_SPACE) {
            const dxSpace *inner = (const dxSpace *)g;
            dxSnapPutU32(o, (uint32_t)inner->count);
            put_geoms(o, inner);
        }
    }
}

size_t dSpaceSnapshot(dSpaceID space, void *buffer, size_t capacity)
{
    const dxSpace *s = (const dxSpace *)space;
    DX_CHECK_ARG(dxGeomIsLive((dxGeom *)space) && (s->geom.flags & DX_GEOM_IS_SPACE), return 0,
                 "space is NULL, destroyed or not a space");
    dxSnapWriter count = { NULL, 0, 0 };
    dxSnapPutU32(&count, (uint32_t)s->count);
    put_geoms(&count, s);
    const size_t total = DX_SNAP_HEADER + count.n;
    if (!buffer || capacity < total) return total;
    unsigned char *out = buffer;
    dxSnapWriter o = { out + DX_SNAP_HEADER, 0, count.n };
    dxSnapPutU32(&o, (uint32_t)s->count);
    put_geoms(&o, s);
    dxSnapWriteHeader(out, SPACE_MAGIC, count.n);
    return total;
}

// Read the records of s's geoms (a count was read and matched); check them
// against the geoms and, if apply, write them. Returns NULL or what is wrong.
static const char *get_geoms(dxSnapReader *r, dxSpace *s, int apply)
{
    for (int i = 0; i < s->count; i++) {
        dxGeom *g = s->geoms[i];
        const uint64_t handle = dxSnapGetU64(r);
        const uint32_t generation = dxSnapGetU32(r), cls = dxSnapGetU32(r);
        const uint64_t body = dxSnapGetU64(r);
        const uint32_t enabled = dxSnapGetU32(r);
        const uint64_t category = dxSnapGetU64(r), collide = dxSnapGetU64(r);
        if (r->bad) return "it is truncated";
        if (handle != (uint64_t)(uintptr_t)g || generation != g->generation ||
            cls != (uint32_t)g->ops->cls)
            return "the space's geoms are not those of the snapshot";
        if (body != (uint64_t)(uintptr_t)g->body)
            return "a geom was moved to another body since the snapshot";
        dVector3 pos;
        dMatrix3 R;
        const int own = has_own_pose(g);
        if (own) {
            dxSnapGetReals(r, pos, 4);
            dxSnapGetReals(r, R, 12);
        }
        dReal x[MAX_SHAPE];
        dReal now[MAX_SHAPE];
        const int n = shape_of(g, now);
        dxSnapGetReals(r, x, (size_t)n);
        if (r->bad) return "it is truncated";
        if (apply) {
            if (enabled) dGeomEnable(g);
            else dGeomDisable(g);
            g->category_bits = (unsigned long)category;
            g->collide_bits = (unsigned long)collide;
            if (n) set_shape(g, x);
            if (own) {
                memcpy(g->own_pos, pos, sizeof pos);
                memcpy(g->own_R, R, sizeof R);
                dxGeomMarkMoved(g);
            }
        }
        if (g->flags & DX_GEOM_IS_SPACE) {
            dxSpace *inner = (dxSpace *)g;
            const uint32_t count = dxSnapGetU32(r);
            if (r->bad) return "it is truncated";
            if (count != (uint32_t)inner->count)
                return "the space's geoms are not those of the snapshot";
            const char *e = get_geoms(r, inner, apply);
            if (e) return e;
        }
    }
    return NULL;
}

static const char *get_space(const unsigned char *payload, size_t n, dxSpace *s, int apply)
{
    dxSnapReader r = { payload, n, 0, 0 };
    const uint32_t count = dxSnapGetU32(&r);
    if (r.bad) return "it is truncated";
    if (count != (uint32_t)s->count) return "the space's geoms are not those of the snapshot";
    const char *e = get_geoms(&r, s, apply);
    if (!e && r.at != r.n) e = "it has bytes after its end";
    return e;
}

int dSpaceRestore(dSpaceID space, const void *buffer, size_t size)
{
    dxSpace *s = (dxSpace *)space;
    DX_CHECK_ARG(dxGeomIsLive((dxGeom *)space) && (s->geom.flags & DX_GEOM_IS_SPACE), return 0,
                 "space is NULL, destroyed or not a space");
    DX_CHECK_ARG(s->lock_count == 0, return 0, "the space is being collided");
    DX_CHECK_ARG(buffer != NULL, return 0, "buffer is NULL");
    const unsigned char *payload = NULL;
    size_t n = 0;
    const char *e = dxSnapCheckHeader(buffer, size, SPACE_MAGIC, &payload, &n);
    DX_CHECK_ARG(e == NULL, return 0, "bad snapshot: %s", e);
    e = get_space(payload, n, s, 0);
    DX_CHECK_ARG(e == NULL, return 0, "bad snapshot: %s", e);
    get_space(payload, n, s, 1);
    return 1;
}
