// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_ray.c -- trimesh-ray, as ODE 0.16 with OPCODE: one
// contact per triangle the ray crosses within its length (nearest first, at
// most the flags' count; only the nearest with the ray's ClosestHit or
// FirstContact set), backfaces skipped with BackfaceCull. Each hit goes
// through the ray callback (with its barycentric u, v) and the per-triangle
// callback. pos is the hit point, depth its distance from the ray's start,
// normal the triangle's normal reversed (into the mesh, g1); side1 the
// triangle.

#include "collide_trimesh.h"

#include <ode/memory.h>

// The ray (start s, unit direction v, mesh frame) against the triangle of
// vertices tri (Moller-Trumbore): 1 with the distance and the barycentric u (of v1) and
// v (of v2) if it crosses within [0, len].
static int ray_triangle(const dReal s[3], const dReal v[3], dReal len, const dReal tri[3][3],
                        int cull, dReal *dist, dReal *bu, dReal *bv)
{
    const dReal *a = tri[0];
    dReal e1[3], e2[3], p[3], tv[3], qv[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = tri[1][i] - a[i];
        e2[i] = tri[2][i] - a[i];
        tv[i] = s[i] - a[i];
    }
    p[0] = v[1] * e2[2] - v[2] * e2[1];
    p[1] = v[2] * e2[0] - v[0] * e2[2];
    p[2] = v[0] * e2[1] - v[1] * e2[0];
    dReal det = dx_dot(e1, p);   // > 0: the ray meets the front face
    dReal scale = dx_dot(e1, e1) * dx_dot(e2, e2);
    if (cull ? det <= 0 : dFabs(det) * dFabs(det) <= scale * DX_COLLIDE_EPS * DX_COLLIDE_EPS)
        return 0;
    dReal inv = 1 / det;
    dReal u = dx_dot(tv, p) * inv;
    if (u < 0 || u > 1) return 0;
    qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
    qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
    qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
    dReal w = dx_dot(v, qv) * inv;
    if (w < 0 || u + w > 1) return 0;
    dReal d = dx_dot(e2, qv) * inv;
    if (d < 0 || d > len) return 0;
    *dist = d;
    *bu = u;
    *bv = w;
    return 1;
}

// Where the ray s + t v (inv: 1 / v per axis, infinite for 0) enters the
// node's box within [0, limit]: 1 and *enter, or 0 if it misses it.
static int ray_enters(const dReal s[3], const dReal v[3], const dReal inv[3],
                      const dxTriMeshNode *node, dReal limit, dReal *enter)
{
    dReal t0 = 0, t1 = limit;
    for (int k = 0; k < 3; k++) {
        if (v[k] == 0) {
            if (s[k] < node->lo[k] || s[k] > node->hi[k]) return 0;
            continue;
        }
        dReal a = (node->lo[k] - s[k]) * inv[k], b = (node->hi[k] - s[k]) * inv[k];
        if (a > b) {
            dReal t = a;
            a = b;
            b = t;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return 0;
    }
    *enter = t0;
    return 1;
}

// Ask for what a node pushed on the stack will read when popped (its
// children, or its triangles' vertices) while other nodes are tested.
// Inlined always: GCC finds a function that only prefetches free of side
// effects and drops the calls.
static inline __attribute__((always_inline)) void prefetch_below(const dxTriMeshData *d, int i)
{
    const dxTriMeshNode *node = &d->nodes[i];
    if (node->count == 0) {
        __builtin_prefetch(&d->nodes[node->first]);
    } else if (d->leaf_vertices) {
        const char *p = (const char *)(d->leaf_vertices + 9 * node->first);
        size_t size = 9 * sizeof(dReal) * (size_t)node->count;
        for (size_t k = 0; k < size; k += 64) __builtin_prefetch(p + k);
    }
}

// Keep the nearest `max` hits in m->raw (a scratch set) sorted by distance (then triangle):
// insert this one at its place, the farthest dropping out when full.
static void keep_hit(dxTriScratch *m, int max, dReal dist, int tri, const dReal n[3])
{
    int k = m->raw_count;
    if (k == max) {
        const dxTriMeshRaw *last = &m->raw[max - 1];
        if (dist > last->depth || (dist == last->depth && tri > last->tri)) return;
    } else {
        m->raw_count++;
    }
    while (k > 0 && (m->raw[k - 1].depth > dist ||
                     (m->raw[k - 1].depth == dist && m->raw[k - 1].tri > tri))) {
        if (k < max) m->raw[k] = m->raw[k - 1];
        k--;
    }
    dxTriMeshRaw *r = &m->raw[k];
    r->depth = dist;
    r->tri = tri;
    r->tri2 = -1;
    for (int j = 0; j < 3; j++) r->n[j] = n[j];
}

// The tree is walked along the ray, nearer child first; once `max` hits
// are kept, boxes the ray enters beyond the farthest of them are skipped.
int dxCollideTriMeshRay(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    dxTriMesh *m = (dxTriMesh *)o1;
    const dxRay *ray = (const dxRay *)o2;
    const dxTriMeshData *d = m->data;
    if (!d || d->node_count == 0) return 0;
    dReal s[3], v[3], dir[3], inv[3];
    dx_axis(o2->R, 2, dir);
    dxTriMeshToLocal(o1, o2->pos, s);
    dxTriMeshDirToLocal(o1, dir, v);
    for (int i = 0; i < 3; i++) inv[i] = v[i] != 0 ? 1 / v[i] : 0;
    int single = ray->closest_hit || ray->first_contact;
    int max = single ? 1 : dx_max_contacts(flags);
    dxTriScratch *h = dxTriScratchAcquire();
    if (!h) return 0;
    dxTriScratchAddRaw(h, max);
    // Each node on the stack with the distance at which the ray enters it:
    // popped beyond the farthest hit kept, it is skipped untested.
    int stack[64], top = 0;
    dReal entry[64];
    if (ray_enters(s, v, inv, &d->nodes[0], ray->length, &entry[0])) stack[top++] = 0;
    while (top > 0) {
        top--;
        dReal limit = h->raw_count == max ? h->raw[max - 1].depth : ray->length;
        if (entry[top] > limit) continue;
        const dxTriMeshNode *node = &d->nodes[stack[top]];
        if (node->count == 0) {
            // Push the farther child first: the nearer is walked first.
            int a = node->first, b = node->first + 1;
            dReal ea = 0, eb = 0;   // set by ray_enters when it returns 1
            int ha = ray_enters(s, v, inv, &d->nodes[a], limit, &ea);
            int hb = ray_enters(s, v, inv, &d->nodes[b], limit, &eb);
            if (ha) prefetch_below(d, a);
            if (hb) prefetch_below(d, b);
            if (ha && hb && ea < eb) {
                entry[top] = eb;
                stack[top++] = b;
                entry[top] = ea;
                stack[top++] = a;
            } else {
                if (ha) entry[top] = ea, stack[top++] = a;
                if (hb) entry[top] = eb, stack[top++] = b;
            }
            continue;
        }
        // Only the vertices are read until a hit (memory traffic is what a
        // ray costs), from the leaf-order copy (a heightfield's patch has
        // none: its arrays): the triangle's index and normal, after.
        for (int j = node->first; j < node->first + node->count; j++) {
            dReal load[3][3], dist, bu, bv;
            const dReal(*tv)[3] = (const dReal(*)[3])load;
            if (d->leaf_vertices) tv = (const dReal(*)[3])(d->leaf_vertices + 9 * j);
            else dxTriMeshTriangle(d, d->order[j], load);
            if (!ray_triangle(s, v, ray->length, tv, ray->backface_cull, &dist, &bu, &bv))
                continue;
            int ti = d->order[j];
            if (dxTriMeshIsDegenerate(d, ti)) continue;
            if (m->ray_callback && !m->ray_callback(o1, o2, ti, bu, bv)) continue;
            if (m->callback && !m->callback(o1, o2, ti)) continue;
            keep_hit(h, max, dist, ti, d->normal + 3 * ti);
        }
    }
    int count = h->raw_count;
    for (int i = 0; i < count; i++) {
        const dxTriMeshRaw *r = &h->raw[i];
        dReal pos[3], n[3];
        for (int j = 0; j < 3; j++) pos[j] = o2->pos[j] + dir[j] * r->depth;
        dx_to_world(o1->R, r->n, n);
        for (int j = 0; j < 3; j++) n[j] = -n[j];
        dx_put_contact(c, i, skip, pos, n, r->depth, o1, o2);
        dxContactAt(c, i, skip)->side1 = r->tri;
    }
    dxTriScratchRelease(h);
    return count;
}
