// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_leaf_cache.c -- the native trimesh colliders' always-on cache
// of a pair's tree leaves (collide_trimesh_tc.c, white box): every query it
// answers is the tree walk's own list (dxTriMeshQueryLeavesF), the same
// leaves in the same order, for boxes at rest, moving, teleported, growing
// and shrinking, huge, empty or NaN, for many partners at once (sets full,
// entries taken over), across dGeomTriMeshDataUpdate, other data set on the
// geom, ClearTCCache, mesh and partner geoms destroyed and made again, and
// in two threads at once; and the contacts of a mesh that moves are the same
// bits with the cache warm and with it cleared before every collision.

#include "test.h"
#include "test_trimesh_meshes.h"
#include "collide_trimesh.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

#define RNG_SEED 0x9b1f3c5d7e2a4861ull
#include "xorshift.h"

static double wavy(double x, double y)
{
    return 0.5 * sin(0.6 * x) * cos(0.5 * y);
}

enum { PARTNERS = 64, MAX_LEAVES = 256 };

// A partner's box in the mesh frame: centre, half extents, velocity.
typedef struct partner {
    double c[3], h[3], v[3];
    int kind;   // 0 rests (jitters), 1 moves, 2 teleports, 3 grows and shrinks
} partner;

static void partner_start(partner *p, int kind)
{
    for (int k = 0; k < 2; k++) p->c[k] = rnd(-9, 9);
    p->c[2] = rnd(-0.6, 0.6);
    for (int k = 0; k < 3; k++) {
        p->h[k] = rnd(0.05, 0.4);
        p->v[k] = kind == 1 ? rnd(-0.08, 0.08) : 0;
    }
    p->kind = kind;
}

// One step of the partner's motion.
static void partner_step(partner *p)
{
    switch (p->kind) {
    case 0:
        for (int k = 0; k < 3; k++) p->c[k] += rnd(-1e-4, 1e-4);
        break;
    case 1:
        for (int k = 0; k < 3; k++) p->c[k] += p->v[k];
        for (int k = 0; k < 2; k++)
            if (fabs(p->c[k]) > 10) p->v[k] = -p->v[k];
        break;
    case 2:
        if (rnd(0, 1) < 0.2) partner_start(p, 2);
        break;
    default:
        for (int k = 0; k < 3; k++) p->h[k] = fmin(3, fmax(0.01, p->h[k] * rnd(0.7, 1.4)));
        break;
    }
}

// The cached leaves of (mesh, other) for the box [lo, hi] against the
// walk's; counts mismatches.
static int compare_query(dxTriScratch *s, dGeomID mesh, const void *other, const dReal lo[3],
                         const dReal hi[3], int max)
{
    const dxTriMesh *m = (const dxTriMesh *)mesh;
    float lo_f[4], hi_f[4];
    dxFloatBox(lo, hi, lo_f, hi_f);
    int want[MAX_LEAVES], got[MAX_LEAVES];
    const int nw = dxTriMeshQueryLeavesF(m->data, lo_f, hi_f, want, max);
    dxTriLeafEntry *e = dxTriMeshLeafEntry(s, m, other);
    const int ng = dxTriMeshQueryLeavesCached(m->data, e, lo_f, hi_f, got, max);
    return nw != ng || (nw > 0 && memcmp(want, got, (size_t)nw * sizeof *want) != 0);
}

static int compare_partner(dxTriScratch *s, dGeomID mesh, const void *other, const partner *p)
{
    dReal lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = (dReal)(p->c[k] - p->h[k]);
        hi[k] = (dReal)(p->c[k] + p->h[k]);
    }
    return compare_query(s, mesh, other, lo, hi, MAX_LEAVES);
}

// Every partner queried `steps` times as it moves; returns the mismatches.
static int run_partners(dxTriScratch *s, dGeomID mesh, partner *p, int n, int steps)
{
    static char other[PARTNERS];   // the partners' addresses (never followed)
    int bad = 0;
    for (int step = 0; step < steps; step++) {
        for (int i = 0; i < n; i++) {
            partner_step(&p[i]);
            bad += compare_partner(s, mesh, &other[i], &p[i]);
        }
    }
    return bad;
}

static int test_leaves_as_walk(void)
{
    test_mesh m;
    mesh_grid(&m, 60, 10, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dxTriScratch *s = dxTriScratchAcquire();
    partner p[PARTNERS];
    for (int i = 0; i < PARTNERS; i++) partner_start(&p[i], i % 4);
    CHECK(run_partners(s, mesh, p, PARTNERS, 60) == 0);

    // The vertices move (Update): the kept leaves are from the old tree.
    for (int i = 0; i < m.nv; i++) m.v[i][2] = 0.8 * m.v[i][2] + 0.1 * sin(m.v[i][0]);
    dGeomTriMeshDataUpdate(m.data);
    CHECK(run_partners(s, mesh, p, PARTNERS, 10) == 0);
    // Other data on the geom, then the first again.
    test_mesh m2;
    mesh_icosphere(&m2, 3, 3);
    dGeomTriMeshSetData(mesh, m2.data);
    CHECK(run_partners(s, mesh, p, PARTNERS, 10) == 0);
    dGeomTriMeshSetData(mesh, m.data);
    CHECK(run_partners(s, mesh, p, PARTNERS, 10) == 0);
    dGeomTriMeshClearTCCache(mesh);
    CHECK(run_partners(s, mesh, p, PARTNERS, 10) == 0);

    // A mesh geom destroyed and made again (maybe at the same address) on
    // the same data: a new tc_id.
    const uint64_t old_id = ((dxTriMesh *)mesh)->tc_id;
    dGeomDestroy(mesh);
    mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    CHECK(((dxTriMesh *)mesh)->tc_id != old_id);
    CHECK(run_partners(s, mesh, p, PARTNERS, 10) == 0);

    // Huge, empty and NaN boxes, and fewer leaves allowed than there are.
    static char odd;
    const dReal big_lo[3] = { -20, -20, -5 }, big_hi[3] = { 20, 20, 5 };
    const dReal empty_lo[3] = { 1, 1, 1 }, empty_hi[3] = { -1, -1, -1 };
    const dReal nan_lo[3] = { 0, NAN, 0 }, nan_hi[3] = { 1, 1, 1 };
    const dReal far_lo[3] = { 50, 50, 50 }, far_hi[3] = { 51, 51, 51 };
    const dReal inf_lo[3] = { -INFINITY, -INFINITY, -INFINITY };
    const dReal inf_hi[3] = { INFINITY, INFINITY, INFINITY };
    const dReal small_lo[3] = { 0, 0, -1 }, small_hi[3] = { 0.5, 0.5, 1 };
    for (int r = 0; r < 2; r++) {
        CHECK(compare_query(s, mesh, &odd, big_lo, big_hi, MAX_LEAVES) == 0);
        CHECK(compare_query(s, mesh, &odd, empty_lo, empty_hi, MAX_LEAVES) == 0);
        CHECK(compare_query(s, mesh, &odd, nan_lo, nan_hi, MAX_LEAVES) == 0);
        CHECK(compare_query(s, mesh, &odd, far_lo, far_hi, MAX_LEAVES) == 0);
        CHECK(compare_query(s, mesh, &odd, inf_lo, inf_hi, MAX_LEAVES) == 0);
        for (int max = 0; max < 8; max++)
            CHECK(compare_query(s, mesh, &odd, small_lo, small_hi, max) == 0);
    }

    dxTriScratchRelease(s);
    dGeomDestroy(mesh);
    mesh_free(&m2);
    mesh_free(&m);
    return 0;
}

// Many more pairs than the cache holds: entries are taken over, and every
// answer is still the walk's.
static int test_leaves_many_pairs(void)
{
    test_mesh m;
    mesh_grid(&m, 40, 10, wavy);
    enum { MESHES = 40 };
    dGeomID mesh[MESHES];
    for (int i = 0; i < MESHES; i++) mesh[i] = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dxTriScratch *s = dxTriScratchAcquire();
    partner p[PARTNERS];
    for (int i = 0; i < PARTNERS; i++) partner_start(&p[i], i % 4);
    int bad = 0;
    for (int step = 0; step < 6; step++)
        for (int i = 0; i < MESHES; i++) bad += run_partners(s, mesh[i], p, PARTNERS, 1);
    CHECK(bad == 0);
    dxTriScratchRelease(s);
    for (int i = 0; i < MESHES; i++) dGeomDestroy(mesh[i]);
    mesh_free(&m);
    return 0;
}

// Two threads query the same pairs (the same mesh geom and partner
// addresses) with their own boxes, each through its own cache.
typedef struct thread_job {
    dGeomID mesh;
    uint64_t seed;
    int bad;
} thread_job;

static void *thread_queries(void *arg)
{
    thread_job *job = (thread_job *)arg;
    dxTriScratch *s = dxTriScratchAcquire();
    static char other[PARTNERS];
    const dxTriMesh *m = (const dxTriMesh *)job->mesh;
    uint64_t x = job->seed;
    for (int step = 0; step < 4000; step++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        const double cx = (double)(x % 1000) / 50 - 10, cy = (double)(x / 1000 % 1000) / 50 - 10;
        const dReal lo[3] = { (dReal)cx, (dReal)cy, -1 }, hi[3] = { (dReal)cx + 0.3f,
                                                                    (dReal)cy + 0.3f, 1 };
        float lo_f[4], hi_f[4];
        dxFloatBox(lo, hi, lo_f, hi_f);
        int want[MAX_LEAVES], got[MAX_LEAVES];
        const int nw = dxTriMeshQueryLeavesF(m->data, lo_f, hi_f, want, MAX_LEAVES);
        dxTriLeafEntry *e = dxTriMeshLeafEntry(s, m, &other[step % 8]);
        const int ng = dxTriMeshQueryLeavesCached(m->data, e, lo_f, hi_f, got, MAX_LEAVES);
        job->bad += nw != ng || (nw > 0 && memcmp(want, got, (size_t)nw * sizeof *want) != 0);
    }
    dxTriScratchRelease(s);
    return NULL;
}

static int test_leaves_two_threads(void)
{
    test_mesh m;
    mesh_grid(&m, 60, 10, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    thread_job job[2] = { { mesh, 0x1234567u, 0 }, { mesh, 0x89abcdefu, 0 } };
    pthread_t t[2];
    for (int i = 0; i < 2; i++) CHECK(pthread_create(&t[i], NULL, thread_queries, &job[i]) == 0);
    for (int i = 0; i < 2; i++) pthread_join(t[i], NULL);
    CHECK(job[0].bad == 0 && job[1].bad == 0);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

// Whether two sets of n contacts are the same bits (the vectors' padding
// left out). Not collide_threads.c's ct_same_contacts: the two sets come
// from two mesh geoms (warm and cleared), so their g1 differ.
static int same_contacts(const dContactGeom *a, const dContactGeom *b, int n)
{
    for (int i = 0; i < n; i++) {
        if (memcmp(a[i].pos, b[i].pos, 3 * sizeof(dReal)) != 0 ||
            memcmp(a[i].normal, b[i].normal, 3 * sizeof(dReal)) != 0 ||
            memcmp(&a[i].depth, &b[i].depth, sizeof a[i].depth) != 0 || a[i].side1 != b[i].side1)
            return 0;
    }
    return 1;
}

// A new partner geom of kind i (sphere, box, capsule).
static dGeomID make_partner(int i)
{
    return i % 3 == 0   ? dCreateSphere(0, (dReal)0.3)
           : i % 3 == 1 ? dCreateBox(0, (dReal)0.4, (dReal)0.3, (dReal)0.2)
                        : dCreateCapsule(0, (dReal)0.15, (dReal)0.4);
}

// A moving, turning mesh and partners resting on it, moving over it and
// teleported, destroyed half way and made again as other kinds (most at the
// same addresses): the contacts of a geom whose cache stays warm are those
// of a geom on the same data whose cache is cleared before each collision.
static int test_contacts_moving_mesh(void)
{
    test_mesh m;
    mesh_grid(&m, 40, 10, wavy);
    dGeomID warm = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID cold = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    enum { GEOMS = 24 };
    dGeomID g[GEOMS];
    partner p[GEOMS];
    for (int i = 0; i < GEOMS; i++) {
        g[i] = make_partner(i);
        partner_start(&p[i], i % 3);
        p[i].c[2] = wavy(p[i].c[0], p[i].c[1]) + 0.1;
    }
    int touched = 0, bad = 0;
    for (int step = 0; step < 120; step++) {
        if (step == 60) {
            for (int i = 0; i < GEOMS; i++) dGeomDestroy(g[i]);
            for (int i = 0; i < GEOMS; i++) g[i] = make_partner(i + 1);
        }
        // The mesh slides and turns about z; the partners are placed in its
        // frame, so they stay over it.
        const double a = 0.01 * step;
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 0, 1, (dReal)a);
        const dReal mx = (dReal)(0.02 * step), my = (dReal)(-0.01 * step);
        for (int k = 0; k < 2; k++) {
            dGeomSetPosition(k ? cold : warm, mx, my, 0);
            dGeomSetRotation(k ? cold : warm, R);
        }
        for (int i = 0; i < GEOMS; i++) {
            partner_step(&p[i]);
            p[i].c[0] = fmax(-9, fmin(9, p[i].c[0]));
            p[i].c[1] = fmax(-9, fmin(9, p[i].c[1]));
            p[i].c[2] = wavy(p[i].c[0], p[i].c[1]) + 0.1;
            const double x = p[i].c[0], y = p[i].c[1];
            dGeomSetPosition(g[i], (dReal)(mx + cos(a) * x - sin(a) * y),
                             (dReal)(my + sin(a) * x + cos(a) * y), (dReal)p[i].c[2]);
            dContactGeom cw[16], cc[16];
            const int nw = dCollide(warm, g[i], 16, cw, sizeof cw[0]);
            dGeomTriMeshClearTCCache(cold);
            const int nc = dCollide(cold, g[i], 16, cc, sizeof cc[0]);
            touched += nw > 0;
            bad += nw != nc || !same_contacts(cw, cc, nw);
        }
    }
    CHECK(bad == 0);
    CHECK(touched > 1000);
    for (int i = 0; i < GEOMS; i++) dGeomDestroy(g[i]);
    dGeomDestroy(warm);
    dGeomDestroy(cold);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_leaves_as_walk),
    TEST_CASE(test_leaves_many_pairs),
    TEST_CASE(test_leaves_two_threads),
    TEST_CASE(test_contacts_moving_mesh),
    TEST_END,
};
