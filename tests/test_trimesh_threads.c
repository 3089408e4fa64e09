// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_threads.c -- the trimesh colliders' scratch memory is per
// thread and per nesting level: two threads colliding one mesh with
// different geoms at once get the contacts they get alone, and a trimesh
// callback may itself collide meshes.

#include "test.h"
#include "collide_threads.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

enum { POSES = 40, ROUNDS = 60, KINDS = 4 };

static double wavy(double x, double y)
{
    return 0.3 * sin(1.3 * x) * cos(0.9 * y);
}

// Each thread has a sphere, a box, a capsule and a ray at its own poses.
static int test_two_threads_collide_one_mesh(void)
{
    dInitODE2(0);
    test_mesh m;
    mesh_grid(&m, 16, 2, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dReal aabb[6];
    dGeomGetAABB(mesh, aabb);   // the mesh's pose settled before the threads read it
    static ct_worker w[2];
    for (int i = 0; i < 2; i++) {
        w[i].target = mesh;
        w[i].kinds = KINDS;
        w[i].poses = POSES;
        w[i].rounds = ROUNDS;
        w[i].geom[0] = dCreateSphere(0, 0.3);
        w[i].geom[1] = dCreateBox(0, 0.5, 0.4, 0.3);
        w[i].geom[2] = dCreateCapsule(0, 0.2, 0.6);
        w[i].geom[3] = dCreateRay(0, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0.5 * i, 0.3, 0.7 + i);
        dGeomSetRotation(w[i].geom[1], R);
        dGeomSetRotation(w[i].geom[2], R);
        dRFromAxisAndAngle(R, 1, 0, 0, M_PI);   // the ray looks down
        dGeomSetRotation(w[i].geom[3], R);
        for (int p = 0; p < POSES; p++) {
            double x = -1.7 + 3.4 * ((p * 7 + 3 * i) % POSES) / POSES, y = 1.5 * sin(p + i);
            w[i].pose[p][0] = x;
            w[i].pose[p][1] = y;
            w[i].pose[p][2] = wavy(x, y) + 0.1 + 0.02 * (p % 5);
        }
        int touching[CT_KINDS];
        ct_record(&w[i], touching);
        CHECK(touching[0] + touching[1] + touching[2] + touching[3] >
              POSES * KINDS / 2);   // the poses do touch the mesh
    }

    CHECK(ct_run_pair(&w[0], &w[1]) == 0);
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < KINDS; k++) dGeomDestroy(w[i].geom[k]);
    dGeomDestroy(mesh);
    mesh_free(&m);
    dCloseODE();
    return 0;
}

// A per-triangle callback that collides another mesh (and, for the test of
// the limit, the same mesh again, deeper and deeper).
static dGeomID inner_mesh, inner_sphere;
static int inner_n, depth, max_depth;

static int nested_callback(dGeomID mesh, dGeomID other, int tri)
{
    (void)tri;
    dContactGeom c[4];
    if (inner_mesh) {
        inner_n = dCollide(inner_mesh, inner_sphere, 4, c, sizeof c[0]);
    } else if (depth < max_depth) {
        depth++;
        dCollide(mesh, other, 4, c, sizeof c[0]);
        depth--;
    }
    return 1;
}

static int test_a_callback_may_collide_meshes(void)
{
    test_mesh a, b;
    mesh_grid(&a, 4, 1, NULL);
    mesh_icosphere(&b, 1, 2);
    dGeomID ga = dCreateTriMesh(0, a.data, NULL, NULL, NULL);
    dGeomID gb = dCreateTriMesh(0, b.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.3), s2 = dCreateSphere(0, 0.5);
    dGeomSetPosition(s, 0.1, 0.2, 0.2);
    dGeomSetPosition(s2, 0, 0, 1.3);
    dContactGeom alone[4], outer[4], inner[4];
    int n_alone = dCollide(ga, s, 4, alone, sizeof alone[0]);
    int n_inner = dCollide(gb, s2, 4, inner, sizeof inner[0]);
    CHECK(n_alone >= 1 && n_inner >= 1);

    dGeomTriMeshSetCallback(ga, nested_callback);
    inner_mesh = gb;
    inner_sphere = s2;
    inner_n = -1;
    int n = dCollide(ga, s, 4, outer, sizeof outer[0]);

    CHECK(n == n_alone && inner_n == n_inner);
    for (int i = 0; i < n && i < n_alone; i++) {
        CHECK(memcmp(outer[i].pos, alone[i].pos, 3 * sizeof(dReal)) == 0);
        CHECK(outer[i].depth == alone[i].depth && outer[i].side1 == alone[i].side1);
    }
    // Deeper than the scratch sets go: the innermost call is refused and
    // reported, the outer ones still answer.
    test_capture_reports();
    inner_mesh = NULL;
    depth = 0;
    max_depth = 6;
    n = dCollide(ga, s, 4, outer, sizeof outer[0]);
    CHECK(n == n_alone);
    CHECK(test_captured_count() >= 1);
    CHECK(test_captured_contains("nested more than 4 deep"));
    test_release_reports();
    dGeomDestroy(s);
    dGeomDestroy(s2);
    dGeomDestroy(ga);
    dGeomDestroy(gb);
    mesh_free(&a);
    mesh_free(&b);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_two_threads_collide_one_mesh),
    TEST_CASE(test_a_callback_may_collide_meshes),
    TEST_END,
};
