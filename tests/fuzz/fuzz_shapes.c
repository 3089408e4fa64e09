// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_shapes.c -- geoms of every class from input bytes (fuzz_shapes.h).

#include "fuzz_shapes.h"

#include <string.h>

#define SCALE ((dReal)4)

static void *keep(fz_shapes *s, size_t bytes)
{
    if (s->nbuffers == (int)(sizeof s->buffers / sizeof s->buffers[0])) return NULL;
    void *p = calloc(1, bytes ? bytes : 1);
    if (p) s->buffers[s->nbuffers++] = p;
    return p;
}

void fz_pose_geom(fz_input *in, dGeomID g)
{
    // a plane has no pose; a non-placeable heightfield refuses one (reported)
    if (dGeomGetClass(g) == dPlaneClass) return;
    dVector3 p;
    fz_vec3(in, SCALE, p);
    dGeomSetPosition(g, p[0], p[1], p[2]);
    dMatrix3 R;
    fz_rotation(in, R);
    dGeomSetRotation(g, R);
}

// A mesh of up to 12 vertices and 16 triangles, indices in range, built by
// one of the build functions.
static dGeomID make_trimesh(fz_input *in, dSpaceID space, fz_shapes *s)
{
    if (s->nmeshes == FZ_MAX_DATA) return NULL;
    int nv = 3 + (int)fz_pick(in, 10), nt = 1 + (int)fz_pick(in, 16);
    dReal *v = keep(s, sizeof(dReal) * 4 * (size_t)nv);
    dTriIndex *idx = keep(s, sizeof(dTriIndex) * 3 * (size_t)nt);
    if (!v || !idx) return NULL;
    for (int i = 0; i < nv; i++) fz_vec3(in, SCALE, v + 4 * i);
    for (int i = 0; i < 3 * nt; i++) idx[i] = (dTriIndex)fz_pick(in, (unsigned)nv);
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    s->meshes[s->nmeshes++] = d;
    dGeomTriMeshDataBuildSimple(d, v, nv, idx, 3 * nt);
    if (fz_u8(in) & 1) dGeomTriMeshDataPreprocess2(d, 1u << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, NULL);
    return dCreateTriMesh(space, d, NULL, NULL, NULL);
}

// A hull: a box of random half sizes (6 faces), possibly sheared by moving
// its points (planes then no longer match: data the colliders must survive).
static dGeomID make_convex(fz_input *in, dSpaceID space, fz_shapes *s)
{
    dReal *planes = keep(s, sizeof(dReal) * 24);
    dReal *points = keep(s, sizeof(dReal) * 24);
    unsigned *polys = keep(s, sizeof(unsigned) * 30);
    if (!planes || !points || !polys) return NULL;
    dReal h[3];
    for (int i = 0; i < 3; i++) h[i] = fz_size(in, 2);
    static const unsigned faces[6][4] = {
        {0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++) points[3 * k + i] = (k >> i & 1) ? h[i] : -h[i];
    if (fz_u8(in) < 32) points[3 * fz_pick(in, 8) + fz_pick(in, 3)] = fz_real(in, SCALE);
    for (int f = 0; f < 6; f++) {
        int axis = f / 2;
        dReal sign = (f & 1) ? 1 : -1;
        // faces 0/1 are x-/x+, 2/3 y-/y+, 4/5 z-/z+ (vertex bits select +)
        planes[4 * f + 0] = axis == 0 ? sign : 0;
        planes[4 * f + 1] = axis == 1 ? sign : 0;
        planes[4 * f + 2] = axis == 2 ? sign : 0;
        planes[4 * f + 3] = h[axis];
        polys[5 * f] = 4;
        for (int k = 0; k < 4; k++) polys[5 * f + 1 + k] = faces[f][k];
    }
    // a geom of an inconsistent hull makes every collision lenient
    if (!fz_hull_consistent(planes, 6, points, 8, polys)) fz_lenient = 1;
    return dCreateConvex(space, planes, 6, points, 8, polys);
}

// A heightfield of 2..7 samples a side, heights from the input.
static dGeomID make_heightfield(fz_input *in, dSpaceID space, fz_shapes *s)
{
    if (s->nfields == FZ_MAX_DATA) return NULL;
    int nw = 2 + (int)fz_pick(in, 6), nd = 2 + (int)fz_pick(in, 6);
    double heights[64];
    for (int i = 0; i < nw * nd; i++) heights[i] = (double)fz_real(in, 2);
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    s->fields[s->nfields++] = d;
    dReal width = fz_size(in, 8), depth = fz_size(in, 8);
    dReal scale = fz_real(in, 2), offset = fz_real(in, 2), thickness = fz_size(in, 2);
    dGeomHeightfieldDataBuildDouble(d, heights, 1, width, depth, nw, nd, scale, offset,
                                    thickness, fz_u8(in) & 1);
    s->field_cell[s->nfields - 1] = dMin(width / (dReal)(nw - 1), depth / (dReal)(nd - 1));
    if (fz_u8(in) < 64) dGeomHeightfieldDataSetBounds(d, fz_real(in, 4), fz_real(in, 4));
    return dCreateHeightfield(space, d, fz_u8(in) & 1);
}

static dGeomID make_class(fz_input *in, dSpaceID space, fz_shapes *s, unsigned which)
{
    dReal a, b, c;
    switch (which) {
    case 0: return dCreateSphere(space, fz_size(in, 2));
    case 1:
        a = fz_size(in, 2), b = fz_size(in, 2), c = fz_size(in, 2);
        return dCreateBox(space, a, b, c);
    case 2: a = fz_size(in, 2), b = fz_size(in, 3); return dCreateCapsule(space, a, b);
    case 3: a = fz_size(in, 2), b = fz_size(in, 3); return dCreateCylinder(space, a, b);
    case 4: {
        dVector3 n;
        fz_vec3(in, 1, n);
        return dCreatePlane(space, n[0], n[1], n[2], fz_real(in, 2));
    }
    case 5: {
        dGeomID r = dCreateRay(space, fz_size(in, 8));
        if (!r) return NULL;
        uint8_t f = fz_u8(in);
        dGeomRaySetFirstContact(r, f & 1);
        dGeomRaySetBackfaceCull(r, f >> 1 & 1);
        dGeomRaySetClosestHit(r, f >> 2 & 1);
        return r;
    }
    case 6: return make_convex(in, space, s);
    case 7: return make_trimesh(in, space, s);
    default: return make_heightfield(in, space, s);
    }
}

dGeomID fz_make_geom(fz_input *in, dSpaceID space, fz_shapes *s)
{
    unsigned which = fz_pick(in, 10);
    dGeomID g;
    if (which == 9) {
        // a transform holding a placeable geom of a basic class, offset in it
        g = dCreateGeomTransform(space);
        dGeomID inner = make_class(in, 0, s, fz_pick(in, 4));
        if (!g || !inner) {
            if (inner) dGeomDestroy(inner);
            return g;
        }
        fz_pose_geom(in, inner);
        dGeomTransformSetGeom(g, inner);
        dGeomTransformSetCleanup(g, 1);
        dGeomTransformSetInfo(g, fz_u8(in) & 1);
    } else {
        g = make_class(in, space, s, which);
    }
    if (g) fz_pose_geom(in, g);
    return g;
}

int fz_field_pair_cheap(dReal cell, dGeomID other)
{
    dReal b[6];
    dGeomGetAABB(other, b);
    double diag = sqrt((double)((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                (b[5] - b[4]) * (b[5] - b[4])));
    double side = diag / (double)cell + 2;
    // NaN (a refused field's cell) or an infinite AABB: leave it to the library
    return !(side * side > FZ_MAX_FIELD_CELLS) || !isfinite(side);
}

int fz_pair_cheap(const fz_shapes *s, dGeomID a, dGeomID b)
{
    for (int k = 0; k < 2; k++) {
        dGeomID f = k ? b : a, other = k ? a : b;
        if (dGeomGetClass(f) != dHeightfieldClass) continue;
        dHeightfieldDataID d = dGeomHeightfieldGetHeightfieldData(f);
        for (int i = 0; i < s->nfields; i++)
            if (s->fields[i] == d && !fz_field_pair_cheap(s->field_cell[i], other)) return 0;
    }
    return 1;
}

void fz_shapes_free(fz_shapes *s)
{
    fz_lenient = 0;
    for (int i = 0; i < s->nmeshes; i++) dGeomTriMeshDataDestroy(s->meshes[i]);
    for (int i = 0; i < s->nfields; i++) dGeomHeightfieldDataDestroy(s->fields[i]);
    for (int i = 0; i < s->nbuffers; i++) free(s->buffers[i]);
    memset(s, 0, sizeof *s);
}
