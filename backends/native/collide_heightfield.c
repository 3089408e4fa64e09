// SPDX-License-Identifier: BSD-3-Clause
//
// collide_heightfield.c -- the native heightfield colliders: the cells under
// the other geom's box become a patch of triangles (heightfield_patch.c) and
// the trimesh colliders run on it, so a heightfield has a trimesh's contacts
// and its no-internal-edge rules (a ball rolls across flat cells as on a
// plane). Below the surface is solid: a geom whose centre is under the
// surface (and above the field's lowest height minus its thickness) gets one
// contact pushing it up along the normal of the triangle under its centre.

#include "../../libodecollide/geom_convex.h"
#include "../../libodecollide/heightfield_internal.h"
#include "../../libodecollide/shapes.h"
#include "collide_math.h"
#include "native_colliders.h"

// The surface under local point p (inside the field, or wrapping): the
// point on it straight above or below p, and the triangle's upward unit
// normal n.
static void surface_at(const dxHeightfieldData *d, const dReal p[3], dReal s[3], dReal n[3])
{
    dReal sw = dxHeightfieldCellWidth(d), sd = dxHeightfieldCellDepth(d);
    dReal fx = (p[0] + d->width / 2) / sw, fz = (p[2] + d->depth / 2) / sd;
    dReal cx = dFloor(fx), cz = dFloor(fz);
    if (!d->wrap) {
        cx = dMin(dMax(cx, 0), (dReal)(d->width_samples - 2));
        cz = dMin(dMax(cz, 0), (dReal)(d->depth_samples - 2));
    }
    int x = (int)cx, z = (int)cz;
    dReal u = fx - cx, v = fz - cz;
    // Triangle (A, C, B) when u + v <= 1, else (D, B, C): heights and slopes.
    dReal a = dxHeightfieldSample(d, x, z), b = dxHeightfieldSample(d, x + 1, z);
    dReal c = dxHeightfieldSample(d, x, z + 1), e = dxHeightfieldSample(d, x + 1, z + 1);
    dReal hx, hz, y;
    if (u + v <= 1) {
        hx = b - a;
        hz = c - a;
        y = a + hx * u + hz * v;
    } else {
        hx = e - c;
        hz = e - b;
        y = e - hx * (1 - u) - hz * (1 - v);
    }
    s[0] = p[0];
    s[1] = y;
    s[2] = p[2];
    // The plane y = y0 + (hx / sw) X + (hz / sd) Z: normal (-hx/sw, 1, -hz/sd).
    n[0] = -hx / sw;
    n[1] = 1;
    n[2] = -hz / sd;
    dReal len = dSqrt(dx_dot(n, n));
    for (int k = 0; k < 3; k++) n[k] /= len;
}

// How far the solid g reaches from its centre along unit direction w (world).
static dReal support(const dxGeom *g, const dReal w[3])
{
    const dReal *R = g->R;
    dReal a[3];   // w in g's frame
    for (int i = 0; i < 3; i++) a[i] = R[i] * w[0] + R[4 + i] * w[1] + R[8 + i] * w[2];
    switch (g->ops->cls) {
    case dSphereClass: return ((const dxSphere *)g)->radius;
    case dBoxClass: {
        const dReal *s = ((const dxBox *)g)->side;
        return (dFabs(a[0]) * s[0] + dFabs(a[1]) * s[1] + dFabs(a[2]) * s[2]) / 2;
    }
    case dCapsuleClass: {
        const dxCapsule *c = (const dxCapsule *)g;
        return c->radius + dFabs(a[2]) * c->length / 2;
    }
    case dCylinderClass: {
        const dxCylinder *c = (const dxCylinder *)g;
        return c->radius * dSqrt(dMax(0, 1 - a[2] * a[2])) + dFabs(a[2]) * c->length / 2;
    }
    case dConvexClass: {
        const dxConvex *h = (const dxConvex *)g;
        dReal best = 0;   // the origin counts: the reach is from the centre
        for (unsigned v = 0; v < h->pointcount; v++) {
            const dReal *p = h->points + 3 * v;
            best = dMax(best, a[0] * p[0] + a[1] * p[1] + a[2] * p[2]);
        }
        return best;
    }
    default: return 0;
    }
}

// The one contact of a geom whose centre is inside the solid below the
// surface; 0 if its centre is not there.
static int buried_contact(dxHeightfield *h, const dxGeom *patch, dxGeom *o2, dContactGeom *c,
                          int skip)
{
    const dxHeightfieldData *d = h->data;
    dReal p[3], s[3], n[3];
    dxTriMeshToLocal(patch, o2->pos, p);   // the patch's frame (wrap: shifted)
    if (!d->wrap && (dFabs(p[0]) > d->width / 2 || dFabs(p[2]) > d->depth / 2)) return 0;
    if (p[1] < d->min_height) return 0;
    surface_at(d, p, s, n);
    dReal sp[3] = { s[0] - p[0], s[1] - p[1], s[2] - p[2] };
    dReal dist = dx_dot(n, sp);   // > 0: the centre is below the surface
    if (!(dist > 0) || !dxIsFinite(dist)) return 0;
    dReal nw[3], down[3];
    dx_to_world(h->g.R, n, nw);
    for (int k = 0; k < 3; k++) down[k] = -nw[k];
    dx_put_contact(c, 0, skip, o2->pos, down, dist + support(o2, down), &h->g, o2);
    return 1;
}

// The body of every heightfield collider: the cells under o2's box, the
// trimesh collider `mesh` on them, then the contacts named after the
// heightfield (side1 -1: the triangles are the patch's, not stable).
static int collide(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip,
                   dxCollider *mesh)
{
    dxHeightfield *h = (dxHeightfield *)o1;
    const dxHeightfieldData *d = h->data;
    if (!d || d->source == DX_HF_NONE) return 0;
    // o2's box in the heightfield frame.
    dxGeomUpdateAABB(o2);
    dReal cw[3], hw[3], cl[3], lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        cw[k] = (o2->aabb[2 * k] + o2->aabb[2 * k + 1]) / 2;
        hw[k] = (o2->aabb[2 * k + 1] - o2->aabb[2 * k]) / 2;
    }
    dxTriMeshToLocal(o1, cw, cl);
    const dReal *R = o1->R;
    for (int i = 0; i < 3; i++) {
        dReal e = dFabs(R[i]) * hw[0] + dFabs(R[4 + i]) * hw[1] + dFabs(R[8 + i]) * hw[2];
        lo[i] = cl[i] - e;
        hi[i] = cl[i] + e;
    }
    if (lo[1] > d->max_height || hi[1] < d->min_height) return 0;
    dReal sw = dxHeightfieldCellWidth(d), sd = dxHeightfieldCellDepth(d);
    dReal fx0 = dFloor((lo[0] + d->width / 2) / sw), fx1 = dCeil((hi[0] + d->width / 2) / sw);
    dReal fz0 = dFloor((lo[2] + d->depth / 2) / sd), fz1 = dCeil((hi[2] + d->depth / 2) / sd);
    // A wrapping field: whole periods off the first are taken out of the
    // cell indices and put into the patch's origin (shift, field frame).
    dReal shift[3] = { 0, 0, 0 };
    if (d->wrap) {
        dReal px = (dReal)(d->width_samples - 1), pz = (dReal)(d->depth_samples - 1);
        dReal kx = dFloor(fx0 / px) * px, kz = dFloor(fz0 / pz) * pz;
        fx0 -= kx;
        fx1 -= kx;
        fz0 -= kz;
        fz1 -= kz;
        shift[0] = kx * sw;
        shift[2] = kz * sd;
    } else {
        fx0 = dMax(fx0, 0);
        fz0 = dMax(fz0, 0);
        fx1 = dMin(fx1, (dReal)(d->width_samples - 1));
        fz1 = dMin(fz1, (dReal)(d->depth_samples - 1));
    }
    if (!(fx0 < fx1 && fz0 < fz1)) return 0;   // outside the field (or NaN)
    if ((fx1 - fx0) * (fz1 - fz0) > (dReal)DX_HEIGHTFIELD_MAX_CELLS) {
        if (!atomic_exchange(&h->cap_reported, 1))
            dxReportMessage("dCollide", "a %s covers more than %d cells of a heightfield: no "
                            "contacts (reported once per heightfield)", o2->ops->name,
                            DX_HEIGHTFIELD_MAX_CELLS);
        return 0;
    }
    dxHeightfieldPatch *patch = dxHeightfieldPatchAcquire();
    if (!patch) return 0;
    int n = 0;
    if (dxHeightfieldBuildPatch(d, patch, (int)fx0, (int)fx1, (int)fz0, (int)fz1)) {
        // The patch's pose: the heightfield's (a body's, if it has one), moved
        // by the whole periods taken out.
        dxGeom *s = &patch->mesh.g;
        s->R = o1->R;
        s->pos = o1->pos;
        if (shift[0] != 0 || shift[2] != 0) {
            dx_point_to_world(o1->R, o1->pos, shift, s->own_pos);
            s->pos = s->own_pos;
        }
        int solid = o2->ops->cls != dRayClass && o2->ops->cls != dTriMeshClass;
        n = solid && buried_contact(h, s, o2, c, skip) ? 1 : mesh(s, o2, flags, c, skip);
    }
    dxHeightfieldPatchRelease(patch);
    for (int i = 0; i < n; i++) {
        dContactGeom *k = dxContactAt(c, i, skip);
        k->g1 = o1;
        k->side1 = -1;
    }
    return n;
}

int dxCollideHeightfieldSphere(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshSphere);
}

int dxCollideHeightfieldBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshBox);
}

int dxCollideHeightfieldCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshCapsule);
}

int dxCollideHeightfieldCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshCylinder);
}

int dxCollideHeightfieldConvex(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshConvex);
}

int dxCollideHeightfieldTriMesh(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    // The patch first whatever the addresses (the patch is the thread's), so
    // every thread gets the same contacts.
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshTriMeshInOrder);
}

int dxCollideHeightfieldRay(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return collide(o1, o2, flags, c, skip, dxCollideTriMeshRay);
}
