// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_build.c -- building shape data from the input: triangle-mesh data by
// every build function (random strides, counts and indices, out of range
// included), heightfield data by every build function (random sample counts,
// sizes, scale, offset, thickness, wrap, bounds), convex hulls from random
// planes, points and polygons. The library must report what it refuses; what
// it accepts is then collided with a sphere, a box, a capsule and a ray, and
// the contacts must pass fz_check_contacts.

#include "fuzz_shapes.h"

#include <string.h>

// The buffers of one input (read in place by the data objects until the end).
#define MAX_BUFFERS 8
static void *buffers[MAX_BUFFERS];
static int nbuffers;

static void *buffer(size_t bytes)
{
    if (nbuffers == MAX_BUFFERS) return NULL;
    void *p = calloc(1, bytes ? bytes : 1);
    if (p) buffers[nbuffers++] = p;
    return p;
}

// Collide g with a geom of each basic class posed from the input (a pair of
// a heightfield of cells of side `cell` and a probe covering too many of them
// is left out: fz_field_pair_cheap).
static void collide_probes(fz_input *in, dGeomID g, dReal cell)
{
    dGeomID probes[4] = {dCreateSphere(0, fz_size(in, 2)), dCreateBox(0, 1, 2, (dReal)0.5),
                         dCreateCapsule(0, (dReal)0.5, 1), dCreateRay(0, fz_size(in, 8))};
    for (int i = 0; i < 4; i++) {
        if (!probes[i]) continue;
        fz_pose_geom(in, probes[i]);
        if (dGeomGetClass(g) == dHeightfieldClass && !fz_field_pair_cheap(cell, probes[i])) {
            dGeomDestroy(probes[i]);
            continue;
        }
        dContactGeom c[32];
        int flags = 1 + (int)fz_pick(in, 32);
        int n = dCollide(g, probes[i], flags, c, sizeof c[0]);
        fz_check_contacts(g, probes[i], flags, c, sizeof c[0], n);
        n = dCollide(probes[i], g, flags, c, sizeof c[0]);
        fz_check_contacts(probes[i], g, flags, c, sizeof c[0], n);
        dGeomDestroy(probes[i]);
    }
}

// A count that is usually small and valid, sometimes zero or negative.
static int fz_count(fz_input *in, int max)
{
    uint8_t k = fz_u8(in);
    if (k < 8) return -(int)k;
    return k % (max + 1);
}

static void fuzz_trimesh(fz_input *in)
{
    unsigned form = fz_pick(in, 5);   // single, double, single1, double1, simple
    int dbl = form == 1 || form == 3 || (form == 4 && sizeof(dReal) == sizeof(double));
    size_t elem = dbl ? sizeof(double) : sizeof(float);
    int vcount = fz_count(in, 24), icount = fz_count(in, 72);
    int vstride = form == 4 ? (int)(4 * sizeof(dReal)) : (int)(3 * elem) + (int)fz_pick(in, 24) - 4;
    int tstride = form == 4 ? (int)(3 * sizeof(dTriIndex))
                            : (int)(3 * sizeof(dTriIndex)) + (int)fz_pick(in, 16) - 2;
    size_t vbytes = vcount > 0 && vstride > 0 ? (size_t)vcount * (size_t)vstride + 32 : 0;
    size_t tris = icount > 0 ? (size_t)icount / 3 + 1 : 0;
    size_t ibytes = tris && tstride > 0 ? tris * (size_t)tstride + 16 : 0;
    unsigned char *v = buffer(vbytes), *idx = buffer(ibytes);
    unsigned char *normals = buffer(tris * 3 * elem);
    if (!v || !idx || !normals) return;
    for (int i = 0; i < vcount && vstride > 0; i++)
        for (int k = 0; k < 3; k++) {
            dReal x = fz_real(in, 4);
            if (dbl) {
                double d = (double)x;
                memcpy(v + (size_t)i * (size_t)vstride + (size_t)k * elem, &d, sizeof d);
            } else {
                float f = (float)x;
                memcpy(v + (size_t)i * (size_t)vstride + (size_t)k * elem, &f, sizeof f);
            }
        }
    for (size_t t = 0; t < tris && tstride > 0; t++)
        for (int k = 0; k < 3; k++) {
            dTriIndex i = (dTriIndex)(fz_u8(in) < 250 ? fz_pick(in, (unsigned)(vcount > 0 ? vcount : 1))
                                                      : fz_u16(in) * 65599u);
            memcpy(idx + t * (size_t)tstride + (size_t)k * sizeof i, &i, sizeof i);
        }
    for (size_t i = 0; i < tris * 3; i++) {
        if (dbl) ((double *)(void *)normals)[i] = (double)fz_real(in, 1);
        else ((float *)(void *)normals)[i] = (float)fz_real(in, 1);
    }
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    switch (form) {
    case 0: dGeomTriMeshDataBuildSingle(d, v, vstride, vcount, idx, icount, tstride); break;
    case 1: dGeomTriMeshDataBuildDouble(d, v, vstride, vcount, idx, icount, tstride); break;
    case 2: dGeomTriMeshDataBuildSingle1(d, v, vstride, vcount, idx, icount, tstride, normals); break;
    case 3: dGeomTriMeshDataBuildDouble1(d, v, vstride, vcount, idx, icount, tstride, normals); break;
    default:
        dGeomTriMeshDataBuildSimple(d, (const dReal *)(void *)v, vcount, (const dTriIndex *)(void *)idx,
                                    icount);
        break;
    }
    if (fz_u8(in) & 1) dGeomTriMeshDataPreprocess2(d, fz_u8(in) & 3, NULL);
    dGeomID g = dCreateTriMesh(0, d, NULL, NULL, NULL);
    if (g) {
        fz_pose_geom(in, g);
        int nt = dGeomTriMeshGetTriangleCount(g);
        if (nt < 0 || (nt > 0 && nt != icount / 3)) fz_fail("triangle count %d for %d indices", nt, icount);
        dVector3 a, b, c;
        dGeomTriMeshGetTriangle(g, (int)fz_pick(in, 64) - 8, &a, &b, &c);
        collide_probes(in, g, 0);
        if (fz_u8(in) & 1) {
            dGeomTriMeshDataUpdate(d);
            collide_probes(in, g, 0);
        }
        dGeomDestroy(g);
    }
    dGeomTriMeshDataDestroy(d);
}

// The callback build's heights: a function of the cell from a seed.
static dReal height_at(void *user, int x, int z)
{
    unsigned seed = *(const unsigned *)user;
    unsigned h = seed * 2654435761u ^ (unsigned)x * 40503u ^ (unsigned)z * 9973u;
    return (dReal)(h % 1000) / 250 - 2;
}

static void fuzz_heightfield(fz_input *in)
{
    int nw = fz_count(in, 9), nd = fz_count(in, 9);
    size_t n = nw > 0 && nd > 0 ? (size_t)nw * (size_t)nd : 0;
    unsigned form = fz_pick(in, 5);
    static const size_t elem[5] = {1, sizeof(short), sizeof(float), sizeof(double), 0};
    unsigned char *h = buffer(n * elem[form]);
    static unsigned seed;
    if (!h) return;
    for (size_t i = 0; i < n; i++) {
        dReal x = fz_real(in, 100);
        switch (form) {
        case 0: h[i] = fz_u8(in); break;
        case 1: ((short *)(void *)h)[i] = (short)fz_u16(in); break;
        case 2: ((float *)(void *)h)[i] = (float)x; break;
        case 3: ((double *)(void *)h)[i] = (double)x; break;
        default: break;
        }
    }
    seed = fz_u16(in);
    dReal width = fz_real(in, 16), depth = fz_real(in, 16);
    dReal scale = fz_real(in, 2), offset = fz_real(in, 4), thickness = fz_real(in, 2);
    int copy = fz_u8(in) & 1, wrap = fz_u8(in) & 1;
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    switch (form) {
    case 0: dGeomHeightfieldDataBuildByte(d, h, copy, width, depth, nw, nd, scale, offset, thickness, wrap); break;
    case 1: dGeomHeightfieldDataBuildShort(d, (short *)(void *)h, copy, width, depth, nw, nd, scale, offset, thickness, wrap); break;
    case 2: dGeomHeightfieldDataBuildSingle(d, (float *)(void *)h, copy, width, depth, nw, nd, scale, offset, thickness, wrap); break;
    case 3: dGeomHeightfieldDataBuildDouble(d, (double *)(void *)h, copy, width, depth, nw, nd, scale, offset, thickness, wrap); break;
    default: dGeomHeightfieldDataBuildCallback(d, &seed, height_at, width, depth, nw, nd, scale, offset, thickness, wrap); break;
    }
    if (fz_u8(in) < 64) dGeomHeightfieldDataSetBounds(d, fz_real(in, 200), fz_real(in, 200));
    dGeomID g = dCreateHeightfield(0, d, fz_u8(in) & 1);
    if (g) {
        fz_pose_geom(in, g);
        collide_probes(in, g, dMin(width / (dReal)(nw > 1 ? nw - 1 : 1),
                                   depth / (dReal)(nd > 1 ? nd - 1 : 1)));
        dGeomDestroy(g);
    }
    dGeomHeightfieldDataDestroy(d);
}

static void fuzz_convex(fz_input *in)
{
    unsigned np = (unsigned)fz_count(in, 8), nv = (unsigned)fz_count(in, 12);
    np = np > 8 ? 0 : np;
    nv = nv > 12 ? 0 : nv;
    dReal *planes = buffer(sizeof(dReal) * 4 * np), *points = buffer(sizeof(dReal) * 3 * nv);
    unsigned *polys = buffer(sizeof(unsigned) * 8 * np);
    if (!planes || !points || !polys) return;
    for (unsigned i = 0; i < 3 * nv; i++) points[i] = fz_real(in, 2);
    unsigned *p = polys;
    for (unsigned f = 0; f < np; f++) {
        dReal *pl = planes + 4 * f;
        fz_vec3(in, 1, pl);
        dReal len = (dReal)sqrt((double)(pl[0] * pl[0] + pl[1] * pl[1] + pl[2] * pl[2]));
        // the documented contract is unit normals: keep those the input allows
        if (isfinite(len) && len > (dReal)1e-3 && fz_u8(in) < 250)
            for (int k = 0; k < 3; k++) pl[k] /= len;
        pl[3] = fz_real(in, 2);
        unsigned count = 2 + fz_pick(in, 6);   // 2..7, 7 values fit the 8 per face
        *p++ = count;
        for (unsigned k = 0; k < count; k++)
            *p++ = fz_u8(in) < 250 ? fz_pick(in, nv ? nv : 1) : nv + fz_u8(in);
    }
    dGeomID g = dCreateConvex(0, planes, np, points, nv, polys);
    if (g) {
        fz_lenient = !fz_hull_consistent(planes, np, points, nv, polys);
        fz_pose_geom(in, g);
        collide_probes(in, g, 0);
        dGeomDestroy(g);
        fz_lenient = 0;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        dInitODE2(0);
        fz_install_handlers();
        ready = 1;
    }
    fz_input in = {data, size, 0};
    switch (fz_pick(&in, 3)) {
    case 0: fuzz_trimesh(&in); break;
    case 1: fuzz_heightfield(&in); break;
    default: fuzz_convex(&in); break;
    }
    for (int i = 0; i < nbuffers; i++) free(buffers[i]);
    nbuffers = 0;
    return 0;
}
