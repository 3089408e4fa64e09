// SPDX-License-Identifier: BSD-3-Clause
//
// test_heightfield_threads.c -- the heightfield colliders' patches are per
// thread and per nesting level: two threads colliding one heightfield with
// different geoms at once get the contacts they get alone, and a height
// callback may itself collide heightfields.

#include "test.h"
#include "collide_threads.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

enum { NX = 33, NZ = 25, POSES = 40, ROUNDS = 40, KINDS = 6 };
#define WIDTH 16.0
#define DEPTH 12.0

static double surface(double x, double z)
{
    return 0.4 * sin(1.3 * x) * cos(0.9 * z) + 0.05 * x;
}

static double heights[NX * NZ];

static dHeightfieldDataID make_field(void)
{
    for (int z = 0; z < NZ; z++)
        for (int x = 0; x < NX; x++)
            heights[x + z * NX] =
                surface(x * WIDTH / (NX - 1) - WIDTH / 2, z * DEPTH / (NZ - 1) - DEPTH / 2);
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, heights, 0, WIDTH, DEPTH, NX, NZ, 1, 0, 1, 0);
    return d;
}

// One thread's geoms (a sphere, a box, a capsule, a cylinder, a ray, a
// closed trimesh on its own data) and poses.
typedef struct worker {
    ct_worker ct;
    test_mesh ball;
} worker;

static void make_worker(worker *w, dGeomID field, int i)
{
    ct_worker *c = &w->ct;
    c->target = field;
    c->kinds = KINDS;
    c->poses = POSES;
    c->rounds = ROUNDS;
    c->geom[0] = dCreateSphere(0, 0.3);
    c->geom[1] = dCreateBox(0, 0.5, 0.4, 0.3);
    c->geom[2] = dCreateCapsule(0, 0.2, 0.6);
    c->geom[3] = dCreateCylinder(0, 0.25, 0.5);
    c->geom[4] = dCreateRay(0, 1);
    mesh_icosphere(&w->ball, 0.35, 1);
    c->geom[5] = dCreateTriMesh(0, w->ball.data, NULL, NULL, NULL);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0.5 * i, 0.3, 0.7 + i);
    for (int k = 1; k < 4; k++) dGeomSetRotation(c->geom[k], R);
    dGeomSetRotation(c->geom[5], R);
    dRFromAxisAndAngle(R, 1, 0, 0, M_PI / 2);   // the ray looks down (-Y)
    dGeomSetRotation(c->geom[4], R);
    for (int p = 0; p < POSES; p++) {
        double x = -6 + 12.0 * ((p * 7 + 3 * i) % POSES) / POSES, z = 4 * sin(p + i);
        c->pose[p][0] = x;
        c->pose[p][1] = surface(x, z) + 0.1 + 0.03 * (p % 5);
        c->pose[p][2] = z;
    }
}

static void free_worker(worker *w)
{
    for (int k = 0; k < KINDS; k++) dGeomDestroy(w->ct.geom[k]);
    mesh_free(&w->ball);
}

static int test_two_threads_collide_one_heightfield(void)
{
    dInitODE2(0);
    dHeightfieldDataID d = make_field();
    dGeomID field = dCreateHeightfield(0, d, 1);
    dReal aabb[6];
    dGeomGetAABB(field, aabb);   // the field's pose settled before the threads read it
    static worker w[2];
    for (int i = 0; i < 2; i++) {
        make_worker(&w[i], field, i);
        int touching[CT_KINDS];
        ct_record(&w[i].ct, touching);
        for (int k = 0; k < KINDS; k++) CHECK(touching[k] > POSES / 2);   // the poses touch
    }
    CHECK(ct_run_pair(&w[0].ct, &w[1].ct) == 0);
    for (int i = 0; i < 2; i++) free_worker(&w[i]);
    dGeomDestroy(field);
    dGeomHeightfieldDataDestroy(d);
    dCloseODE();
    return 0;
}

// A height callback that collides another heightfield (or, for the test of
// the limit, its own field again, deeper and deeper) while its field's
// patch is being built.
static dGeomID inner_field, inner_ball, outer_field, outer_ball;
static int inner_n, depth, max_depth;

static dReal nesting_height(void *user, int x, int z)
{
    (void)user;
    if (x == 2 && z == 2) {
        dContactGeom c[4];
        if (inner_field) {
            inner_n = dCollide(inner_field, inner_ball, 4, c, sizeof c[0]);
        } else if (outer_field && depth < max_depth) {
            depth++;
            dCollide(outer_field, outer_ball, 4, c, sizeof c[0]);
            depth--;
        }
    }
    return (dReal)(0.1 * x - 0.05 * z);
}

static int test_a_height_callback_may_collide_heightfields(void)
{
    dHeightfieldDataID da = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildCallback(da, NULL, nesting_height, 4, 4, 5, 5, 1, 0, 1, 0);
    dHeightfieldDataID db = make_field();
    dGeomID fa = dCreateHeightfield(0, da, 1), fb = dCreateHeightfield(0, db, 1);
    dGeomID s = dCreateSphere(0, 0.3), s2 = dCreateSphere(0, 0.4);
    dGeomSetPosition(s, 0.1, 0.2, 0.1);
    dGeomSetPosition(s2, 1, surface(1, 0.5) + 0.2, 0.5);
    dContactGeom alone[4], outer[4], inner[4];
    inner_field = outer_field = NULL;
    int n_alone = dCollide(fa, s, 4, alone, sizeof alone[0]);
    int n_inner = dCollide(fb, s2, 4, inner, sizeof inner[0]);
    CHECK(n_alone >= 1 && n_inner >= 1);

    inner_field = fb;
    inner_ball = s2;
    inner_n = -1;
    int n = dCollide(fa, s, 4, outer, sizeof outer[0]);

    CHECK(n == n_alone && inner_n == n_inner);
    for (int i = 0; i < n; i++) {
        CHECK(memcmp(outer[i].pos, alone[i].pos, 3 * sizeof(dReal)) == 0);
        CHECK(outer[i].depth == alone[i].depth);
    }
    // Deeper than the patches go: the innermost call is refused and
    // reported, the outer ones still answer.
    test_capture_reports();
    inner_field = NULL;
    outer_field = fa;
    outer_ball = s;
    depth = 0;
    max_depth = 6;
    n = dCollide(fa, s, 4, outer, sizeof outer[0]);
    CHECK(n == n_alone);
    CHECK(test_captured_count() >= 1);
    CHECK(test_captured_contains("dCollide: heightfield collisions nested more than 4 deep"));
    test_release_reports();
    outer_field = NULL;
    dGeomDestroy(s);
    dGeomDestroy(s2);
    dGeomDestroy(fa);
    dGeomDestroy(fb);
    dGeomHeightfieldDataDestroy(da);
    dGeomHeightfieldDataDestroy(db);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_two_threads_collide_one_heightfield),
    TEST_CASE(test_a_height_callback_may_collide_heightfields),
    TEST_END,
};
