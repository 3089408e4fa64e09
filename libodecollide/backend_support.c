// SPDX-License-Identifier: BSD-3-Clause
//
// backend_support.c -- shapes, poses, cache slots and the contact sink for
// backend adapters (backend_support.h).

#include "backend_support.h"

#include <math.h>
#include <string.h>

#include "backend_internal.h"
#include "shapes.h"
#include "trimesh_internal.h"

void dxGeomDescribe(dGeomID g, dxShapeDesc *out)
{
    memset(out, 0, sizeof *out);
    out->cls = g->ops->cls;
    out->version = g->shape_version;
    switch (out->cls) {
    case dSphereClass: out->p[0] = ((const dxSphere *)g)->radius; break;
    case dBoxClass: memcpy(out->p, ((const dxBox *)g)->side, 3 * sizeof(dReal)); break;
    case dCapsuleClass:
        out->p[0] = ((const dxCapsule *)g)->radius;
        out->p[1] = ((const dxCapsule *)g)->length;
        break;
    case dCylinderClass:
        out->p[0] = ((const dxCylinder *)g)->radius;
        out->p[1] = ((const dxCylinder *)g)->length;
        break;
    case dPlaneClass: memcpy(out->p, ((const dxPlane *)g)->p, 4 * sizeof(dReal)); break;
    case dRayClass: out->p[0] = ((const dxRay *)g)->length; break;
    default: break;
    }
}

void dxGeomPose(dGeomID g, dReal pos[3], dReal R[12])
{
    if (!(g->flags & DX_GEOM_PLACEABLE)) {
        memset(pos, 0, 3 * sizeof(dReal));
        memset(R, 0, 12 * sizeof(dReal));
        R[0] = R[5] = R[10] = 1;
        return;
    }
    memcpy(pos, g->pos, 3 * sizeof(dReal));
    memcpy(R, g->R, 12 * sizeof(dReal));
}

void *dxGeomCache(dGeomID g, const void *owner)
{
    if (g->backend_cache && g->backend_cache_owner != owner) {
        dxBackendGeomChanged(g);   // the owner frees its object and clears the slot
        g->backend_cache = NULL;
        g->backend_cache_owner = NULL;
    }
    return g->backend_cache;
}

void *dxGeomOwnedCache(dGeomID g, const void *owner)
{
    return g->backend_cache_owner == owner ? g->backend_cache : NULL;
}

void dxGeomSetCache(dGeomID g, const void *owner, void *cache)
{
    g->backend_cache = cache;
    g->backend_cache_owner = cache ? owner : NULL;
}

void dxSinkInit(dxContactSink *s) { s->count = 0; }

void dxSinkAdd(dxContactSink *s, const dReal pos[3], const dReal normal[3], dReal depth,
               int side1, int side2)
{
    if (s->count >= DX_SINK_CAPACITY) return;
    struct dxRawContact *c = &s->c[s->count++];
    memcpy(c->pos, pos, sizeof c->pos);
    memcpy(c->normal, normal, sizeof c->normal);
    c->depth = depth;
    c->side1 = side1;
    c->side2 = side2;
}

static dReal dist2(const dReal *a, const dReal *b)
{
    dReal d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

// Drop unusable contacts, normalise normals; returns the scale of the
// positions (for the relative merge distance).
static dReal sink_clean(dxContactSink *s)
{
    int n = 0;
    dReal scale = 1;
    for (int i = 0; i < s->count; i++) {
        struct dxRawContact *c = &s->c[i];
        dReal len = sqrt(c->normal[0] * c->normal[0] + c->normal[1] * c->normal[1] +
                         c->normal[2] * c->normal[2]);
        int finite = isfinite(c->depth) && isfinite(len) && isfinite(c->pos[0]) &&
                     isfinite(c->pos[1]) && isfinite(c->pos[2]);
        if (!finite || c->depth < 0 || !(len > 0)) continue;
        for (int k = 0; k < 3; k++) {
            c->normal[k] /= len;
            if (fabs(c->pos[k]) > scale) scale = fabs(c->pos[k]);
        }
        s->c[n++] = *c;
    }
    s->count = n;
    return scale;
}

// Merge contacts closer than tol to an earlier one, keeping the deeper.
static void sink_merge(dxContactSink *s, dReal tol)
{
    int n = 0;
    for (int i = 0; i < s->count; i++) {
        int j = 0;
        while (j < n && dist2(s->c[j].pos, s->c[i].pos) > tol * tol) j++;
        if (j == n) s->c[n++] = s->c[i];
        else if (s->c[i].depth > s->c[j].depth) s->c[j] = s->c[i];
    }
    s->count = n;
}

// The deepest, then repeatedly the one farthest from those already kept
// (spreading the support polygon).
int dxContactsSelect(dxRawContact *c, int n, int max)
{
    if (n <= max) return n;
    int deepest = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[deepest].depth) deepest = i;
    dxRawContact t = c[0];
    c[0] = c[deepest];
    c[deepest] = t;
    for (int k = 1; k < max; k++) {
        int best = k;
        dReal best_d = -1;
        for (int i = k; i < n; i++) {
            dReal d = INFINITY;
            for (int j = 0; j < k; j++) {
                dReal dj = dist2(c[i].pos, c[j].pos);
                if (dj < d) d = dj;
            }
            if (d > best_d) best_d = d, best = i;
        }
        t = c[k];
        c[k] = c[best];
        c[best] = t;
    }
    return max;
}

int dxSinkFinish(dxContactSink *s, dGeomID o1, dGeomID o2, int flags, dContactGeom *out,
                 int skip)
{
    int max = flags & 0xffff;
    if (max < 1) max = 1;
    dReal scale = sink_clean(s);
    sink_merge(s, (dReal)1e-6 * scale);
    s->count = dxContactsSelect(s->c, s->count, max);
    for (int i = 0; i < s->count; i++) {
        const struct dxRawContact *c = &s->c[i];
        dContactGeom *k = dxContactAt(out, i, skip);
        memcpy(k->pos, c->pos, sizeof c->pos);
        k->pos[3] = 0;
        memcpy(k->normal, c->normal, sizeof c->normal);
        k->normal[3] = 0;
        k->depth = c->depth;
        k->g1 = o1;
        k->g2 = o2;
        k->side1 = c->side1;
        k->side2 = c->side2;
    }
    return s->count;
}

// ---- triangle meshes ----------------------------------------------------------

static const dxTriMesh *as_trimesh(dGeomID g)
{
    return g->ops->cls == dTriMeshClass ? (const dxTriMesh *)g : NULL;
}

void dxTriMeshGetInfo(dGeomID g, dxTriMeshInfo *out)
{
    const dxTriMesh *m = as_trimesh(g);
    const dxTriMeshData *d = m ? m->data : NULL;
    out->data = d;
    out->vertex_count = d ? d->vertex_count : 0;
    out->tri_count = d ? d->tri_count : 0;
}

void dxTriMeshGetVertex(dGeomID g, int i, dReal out[3])
{
    dxTriMeshVertex(as_trimesh(g)->data, i, out);
}

void dxTriMeshGetTriangle(dGeomID g, int t, int idx[3])
{
    dxTriMeshIndices(as_trimesh(g)->data, t, idx);
}

int dxTriMeshTriangleAllowed(dGeomID g, dGeomID other, int t)
{
    const dxTriMesh *m = as_trimesh(g);
    if (!m || !m->data || t < 0 || t >= m->data->tri_count) return 0;
    if (dxTriMeshIsDegenerate(m->data, t)) return 0;
    return !m->callback || m->callback(g, other, t);
}

int dxTriMeshFrontSide(dGeomID g, int t, const dReal leave[3])
{
    const dxTriMesh *m = as_trimesh(g);
    if (!m || !m->data || t < 0 || t >= m->data->tri_count) return 0;
    dReal local[3];
    dxTriMeshDirToLocal(g, leave, local);
    const dReal *n = m->data->normal + 3 * t;
    return n[0] * local[0] + n[1] * local[1] + n[2] * local[2] >= 0;
}

const char *dxTriMeshNeedsNative(dGeomID g)
{
    const dxTriMesh *m = as_trimesh(g);
    if (!m) return NULL;
    if (m->array_callback) return "a trimesh's array callback";
    if (m->merge_callback) return "a trimesh's merge callback";
    if (m->sphere_merge != dGeomColliderMergeContactsValue_None)
        return "a trimesh's contact merge setting";
    return NULL;
}
