// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_ray_brute.c -- the trimesh-ray collider's walk of the tree
// against a loop over every triangle: for thousands of rays on a wavy
// terrain, turned and moved, each ray's hits (distances, triangles, the ray
// callback's barycentric u and v) must be the loop's, bit for bit: the
// nearest 16 or 3 (or only the nearest, ClosestHit), BackfaceCull off and on,
// and the same contacts flipped with the ray as the first geom.
// The rays: random ones starting above, below and inside the surface's
// boxes, ones along the mesh's axes (zero components in the mesh frame:
// the mesh is turned by an exact quarter turn for them), ones running in
// the planes of the grid's lines (grazing the triangles' boxes' sides),
// nearly along an axis, and of length 0. Each contact's normal must be its
// triangle's normal reversed (into the mesh), in the world, bit for bit;
// and rays along a degenerate triangle's line never name it.

#include "test.h"
#include "test_trimesh_meshes.h"
#include "../libodecollide/trimesh_internal.h"

#define RNG_SEED 0x9E3779B97F4A7C15ULL
#include "xorshift.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef dSINGLE
#define RAY_EPS ((dReal)1e-5)   // the collider's DX_COLLIDE_EPS
#else
#define RAY_EPS ((dReal)1e-9)
#endif

enum { GRID = 32, MAX_HITS = 16 };
static const double HALF = 8;   // grid lines at whole halves: exact

static double wavy(double x, double y)
{
    return 0.4 * sin(0.9 * x) * cos(0.7 * y) + 0.05 * x;
}

// The ray callback's u and v per triangle (the last call's).
static dReal seen_u[2 * GRID * GRID], seen_v[2 * GRID * GRID];

static int record_uv(dGeomID mesh, dGeomID ray, int tri, dReal u, dReal v)
{
    (void)mesh;
    (void)ray;
    seen_u[tri] = u;
    seen_v[tri] = v;
    return 1;
}

typedef struct hit {
    dReal dist, u, v;
    int tri;
} hit;

// The ray from s along v (mesh frame) over [0, len] against one triangle,
// with the collider's arithmetic (Moller-Trumbore, the same operations in
// the same order): 1 with h's distance and u, v if it crosses.
static int cross(const dReal s[3], const dReal v[3], dReal len, const dReal tri[3][3], int cull,
                 hit *h)
{
    dReal e1[3], e2[3], p[3], tv[3], qv[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = tri[1][i] - tri[0][i];
        e2[i] = tri[2][i] - tri[0][i];
        tv[i] = s[i] - tri[0][i];
    }
    p[0] = v[1] * e2[2] - v[2] * e2[1];
    p[1] = v[2] * e2[0] - v[0] * e2[2];
    p[2] = v[0] * e2[1] - v[1] * e2[0];
    dReal det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    dReal scale = (e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]) *
                  (e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
    if (cull ? det <= 0 : dFabs(det) * dFabs(det) <= scale * RAY_EPS * RAY_EPS) return 0;
    dReal inv = 1 / det;
    dReal u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) * inv;
    if (u < 0 || u > 1) return 0;
    qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
    qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
    qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
    dReal w = (v[0] * qv[0] + v[1] * qv[1] + v[2] * qv[2]) * inv;
    if (w < 0 || u + w > 1) return 0;
    dReal d = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
    if (d < 0 || d > len) return 0;
    h->dist = d;
    h->u = u;
    h->v = w;
    return 1;
}

static int by_dist_then_tri(const void *a, const void *b)
{
    const hit *x = a, *y = b;
    if (x->dist != y->dist) return x->dist < y->dist ? -1 : 1;
    return (x->tri > y->tri) - (x->tri < y->tri);
}

// The hits the collider must give: every triangle crossed, nearest first
// (ties by triangle), at most max. The ray's start and direction go to the
// mesh frame as the collider takes them (R^T (p - pos), R^T dir).
static int brute_hits(const test_mesh *tm, dGeomID mesh, dGeomID ray, int cull, int max,
                      hit *out)
{
    const dReal *R = dGeomGetRotation(mesh), *pos = dGeomGetPosition(mesh);
    const dReal *rp = dGeomGetPosition(ray), *rr = dGeomGetRotation(ray);
    dReal d[3] = { rp[0] - pos[0], rp[1] - pos[1], rp[2] - pos[2] };
    dReal dir[3] = { rr[2], rr[6], rr[10] }, s[3], v[3];
    for (int i = 0; i < 3; i++) {
        s[i] = R[i] * d[0] + R[4 + i] * d[1] + R[8 + i] * d[2];
        v[i] = R[i] * dir[0] + R[4 + i] * dir[1] + R[8 + i] * dir[2];
    }
    dReal len = dGeomRayGetLength(ray);
    static hit all[2 * GRID * GRID];
    int n = 0;
    for (int t = 0; t < tm->nt; t++) {
        dReal tri[3][3];
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) tri[k][i] = (dReal)tm->v[tm->tri[t][k]][i];
        if (cross(s, v, len, (const dReal(*)[3])tri, cull, &all[n])) all[n++].tri = t;
    }
    qsort(all, (size_t)n, sizeof all[0], by_dist_then_tri);
    if (n > max) n = max;
    memcpy(out, all, sizeof(hit) * (size_t)n);
    return n;
}

// Collide the ray (start p, direction dir, both in the mesh frame: placed
// in the world through the mesh's pose) with the mesh, every way (the
// nearest 16, 3 or, by ClosestHit, 1: the collider keeps a few in a local
// array and many in its scratch; BackfaceCull off and on); each must match
// the loop. Counts the hits into *hits.
static int check_ray(const test_mesh *tm, dGeomID mesh, dGeomID ray, const double p[3],
                     const double dir[3], double len, long *hits)
{
    const dReal *R = dGeomGetRotation(mesh), *pos = dGeomGetPosition(mesh);
    dReal wp[3], wd[3];
    for (int i = 0; i < 3; i++) {
        wp[i] = pos[i] + R[4 * i] * p[0] + R[4 * i + 1] * p[1] + R[4 * i + 2] * p[2];
        wd[i] = R[4 * i] * dir[0] + R[4 * i + 1] * dir[1] + R[4 * i + 2] * dir[2];
    }
    dGeomRaySetLength(ray, (dReal)len);
    dGeomRaySet(ray, wp[0], wp[1], wp[2], wd[0], wd[1], wd[2]);
    static const int maxes[3] = { MAX_HITS, 1, 3 };
    for (int way = 0; way < 6; way++) {
        const int cull = way & 1, max = maxes[way >> 1];
        dGeomRaySetBackfaceCull(ray, cull);
        dGeomRaySetClosestHit(ray, max == 1);
        hit want[MAX_HITS];
        dContactGeom c[MAX_HITS];
        const int nw = brute_hits(tm, mesh, ray, cull, max, want);
        memset(seen_u, 0xff, sizeof seen_u);   // NaN: a hit without its call fails
        memset(seen_v, 0xff, sizeof seen_v);
        const int n = dCollide(mesh, ray, max == 1 ? MAX_HITS : max, c, sizeof c[0]);
        if (n != nw) {
            test_fail(__FILE__, __LINE__, "ray (%.17g %.17g %.17g) dir (%.17g %.17g %.17g): "
                      "%d hits, the loop %d", p[0], p[1], p[2], dir[0], dir[1], dir[2], n, nw);
            return 1;
        }
        const dReal *normal = ((const dxTriMeshData *)tm->data)->normal;
        for (int i = 0; i < n; i++) {
            CHECK(c[i].side1 == want[i].tri);
            CHECK(c[i].depth == want[i].dist);
            CHECK(seen_u[want[i].tri] == want[i].u && seen_v[want[i].tri] == want[i].v);
            // The triangle's normal turned into the world (the collider's
            // products, in its order) and reversed.
            const dReal *m = normal + 3 * want[i].tri;
            dReal into[3];
            for (int k = 0; k < 3; k++)
                into[k] = -(R[4 * k] * m[0] + R[4 * k + 1] * m[1] + R[4 * k + 2] * m[2]);
            CHECK(memcmp(c[i].normal, into, sizeof into) == 0);
        }
        // The ray first: the same contacts flipped, bit for bit.
        dContactGeom f[MAX_HITS];
        CHECK(dCollide(ray, mesh, max == 1 ? MAX_HITS : max, f, sizeof f[0]) == n);
        for (int i = 0; i < n; i++) {
            dReal flipped[3] = { -c[i].normal[0], -c[i].normal[1], -c[i].normal[2] };
            CHECK(memcmp(f[i].pos, c[i].pos, sizeof(dReal[3])) == 0);
            CHECK(memcmp(f[i].normal, flipped, sizeof(dReal[3])) == 0);
            CHECK(memcmp(&f[i].depth, &c[i].depth, sizeof(dReal)) == 0);
            CHECK(f[i].g1 == ray && f[i].g2 == mesh && f[i].side1 == -1 &&
                  f[i].side2 == c[i].side1);
        }
        *hits += n;
    }
    return 0;
}

// A random unit vector, a component set to 0 when zero_mask's bit says so
// (not all of them).
static void random_dir(double d[3], int zero_mask)
{
    double l;
    do {
        for (int i = 0; i < 3; i++) d[i] = zero_mask >> i & 1 ? 0 : rnd(-1, 1);
        l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (l < 0.1);
    for (int i = 0; i < 3; i++) d[i] /= l;
}

// The rays of the header on a mesh at pose (R, pos): per kind `count` rays.
static int rays_match_loop(const dMatrix3 R, const dReal pos[3], int count, long *hits)
{
    test_mesh tm;
    mesh_grid(&tm, GRID, HALF, wavy);
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID mesh = dCreateTriMesh(space, tm.data, NULL, NULL, NULL);
    dGeomSetRotation(mesh, R);
    dGeomSetPosition(mesh, pos[0], pos[1], pos[2]);
    dGeomTriMeshSetRayCallback(mesh, record_uv);
    dGeomID ray = dCreateRay(space, 1);
    int fail = 0;
    for (int i = 0; i < count && !fail; i++) {
        double p[3], d[3];
        // Random: from above, below or among the surface's boxes.
        p[0] = rnd(-HALF - 1, HALF + 1);
        p[1] = rnd(-HALF - 1, HALF + 1);
        p[2] = rnd(-2, 2);
        random_dir(d, 0);
        fail |= check_ray(&tm, mesh, ray, p, d, rnd(0.5, 20), hits);
        // Along one or two of the mesh's axes (zero components).
        random_dir(d, 1 + (i % 6));
        fail |= check_ray(&tm, mesh, ray, p, d, rnd(0.5, 20), hits);
        // In a grid line's plane (x or y a whole half: the sides of the
        // triangles' boxes), running in it or crossing it.
        p[i & 1] = -HALF + 0.5 * (double)(i % (4 * (int)HALF + 1));
        random_dir(d, i & 2 ? 1 << (i & 1) : 0);
        fail |= check_ray(&tm, mesh, ray, p, d, rnd(0.5, 20), hits);
        // Nearly along an axis, and of length 0 from a grid point.
        d[0] = rnd(-1e-12, 1e-12);
        d[1] = i & 4 ? 1e-35 : 0;
        d[2] = i & 8 ? 1 : -1;
        fail |= check_ray(&tm, mesh, ray, p, d, rnd(0.5, 5), hits);
        p[2] = wavy(p[0], p[1]);
        fail |= check_ray(&tm, mesh, ray, p, d, 0, hits);
    }
    dGeomDestroy(ray);
    dGeomDestroy(mesh);
    dSpaceDestroy(space);
    mesh_free(&tm);
    return fail;
}

static int test_turned_mesh(void)
{
    dMatrix3 R;
    dRFromEulerAngles(R, 0.3, -0.7, 1.9);
    const dReal pos[3] = { 0.7, -1.3, 2.1 };
    long hits = 0;
    CHECK(rays_match_loop(R, pos, 1500, &hits) == 0);
    CHECK(hits > 4000);   // about one collision in six has a hit
    return 0;
}

// A quarter turn about z and a half turn about x, exactly (entries 0 and
// +-1): the mesh frame's zero components stay zero.
static int test_quarter_turned_mesh(void)
{
    const dMatrix3 R = { 0, -1, 0, 0, -1, 0, 0, 0, 0, 0, -1, 0 };
    const dReal pos[3] = { 1.5, -2.25, 0.75 };
    long hits = 0;
    CHECK(rays_match_loop(R, pos, 1500, &hits) == 0);
    CHECK(hits > 4000);
    return 0;
}

// A degenerate triangle (a sliver of height 1e-14 over a side of 2: too
// thin for a normal, so its normal is 0) beside a real one sharing its
// first edge: rays through points of the sliver and near it, both ways
// round and culled or not, may hit the real triangle and never name the
// degenerate one (which the triangle test takes, culled, from above).
static int test_degenerate_triangle(void)
{
    const double h = 1e-14;
    double w[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, h, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
    dTriIndex tris[6] = { 0, 1, 2, 0, 1, 3 };
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(data, w, sizeof w[0], 5, tris, 6, 3 * sizeof(dTriIndex));
    const dxTriMeshData *d = (const dxTriMeshData *)data;
    CHECK(d->leaf_faces != NULL);   // the walk with the leaf copy
    CHECK(d->normal[0] == 0 && d->normal[1] == 0 && d->normal[2] == 0);
    dGeomID mesh = dCreateTriMesh(0, data, NULL, NULL, NULL);
    dGeomID ray = dCreateRay(0, 4);
    long hits = 0;
    for (int i = 0; i < 4000; i++) {
        const double x = rnd(-0.5, 2.5), tilt = rnd(-1, 1) * (i & 1 ? 1e-9 : 0.5);
        const double dz = i & 2 ? 1 : -1;
        dGeomRaySet(ray, x - tilt, -tilt, -2 * dz, tilt, tilt, dz);
        if (i % 3 == 0) {   // straight through the sliver, between its long sides
            const double xs = rnd(1.05, 1.95);
            dGeomRaySet(ray, xs, h * ((xs - 1) + xs / 2) / 2, -2 * dz, 0, 0, dz);
        }
        dGeomRaySetBackfaceCull(ray, i >> 2 & 1);
        dGeomRaySetClosestHit(ray, i >> 3 & 1);
        dContactGeom c[4];
        const int n = dCollide(mesh, ray, 4, c, sizeof c[0]);
        for (int k = 0; k < n; k++) CHECK(c[k].side1 == 1);
        hits += n;
    }
    CHECK(hits > 100);
    dGeomDestroy(ray);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(data);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_turned_mesh),
    TEST_CASE(test_quarter_turned_mesh),
    TEST_CASE(test_degenerate_triangle),
    TEST_END,
};
