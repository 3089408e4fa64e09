// SPDX-License-Identifier: BSD-3-Clause
//
// diff_trimesh.c -- triangle meshes against the reference ODE 0.16 (OPCODE).
//
// Temporal coherence flags: off for every class at creation; after enabling
// each class only sphere, box and capsule have one; then box off again.
//
// Getters: triangle count, triangles and barycentric points in world
// coordinates of a posed mesh (1e-6: the reference transforms them in
// float), and dMassSetTrimesh on a closed box mesh at a pose (mass, centre,
// inertia of size ~10, 1e-5: the same solid, integrated by the reference
// from those float triangles; ours moves the inertia to the centre with
// dMassTranslate as the reference does).
//
// Contacts (counts differ between the libraries and are not printed): on
// faces, where the answer is unique, the deepest contact's depth and
// normal, tolerance 1e-6 (the reference's tree works in float, its
// colliders in dReal):
// - a sphere, a box (any yaw, flat) and a capsule (lying) sunk into a large
//   flat two-triangle floor, well inside it, both argument orders;
// - a closed box mesh through a plane (flat and tilted);
// - rays straight down onto a wavy terrain and through a closed box mesh
//   (closest hit): depth, position and normal, 1e-5 (OPCODE's ray test is
//   in float).

#include "diff_print.h"
#include "diff_random.h"

#include <math.h>

enum { SCENES = 60 };

static double floor_v[4][3] = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 } };
static dTriIndex floor_i[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };

// A closed box of full sides 2 x 1.6 x 1.2, 12 triangles wound outwards.
static double box_v[8][3];
static dTriIndex box_i[12][3] = { { 0, 2, 3 }, { 0, 3, 1 }, { 4, 5, 7 }, { 4, 7, 6 },
                                  { 0, 1, 5 }, { 0, 5, 4 }, { 2, 6, 7 }, { 2, 7, 3 },
                                  { 0, 4, 6 }, { 0, 6, 2 }, { 1, 3, 7 }, { 1, 7, 5 } };

static void make_box(void)
{
    for (int v = 0; v < 8; v++) {
        box_v[v][0] = v & 1 ? 1 : -1;
        box_v[v][1] = v & 2 ? 0.8 : -0.8;
        box_v[v][2] = v & 4 ? 0.6 : -0.6;
    }
}

// A 12 x 12 terrain over [-3, 3]^2, z = 0.3 sin(x) cos(0.7 y).
static double terrain_v[13 * 13][3];
static dTriIndex terrain_i[2 * 12 * 12][3];

static void make_terrain(void)
{
    for (int j = 0; j <= 12; j++)
        for (int i = 0; i <= 12; i++) {
            double *p = terrain_v[j * 13 + i];
            p[0] = -3 + 0.5 * i;
            p[1] = -3 + 0.5 * j;
            p[2] = 0.3 * sin(p[0]) * cos(0.7 * p[1]);
        }
    int t = 0;
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 12; i++) {
            dTriIndex a = (dTriIndex)(j * 13 + i), b = a + 1, c = a + 13, d = c + 1;
            terrain_i[t][0] = a, terrain_i[t][1] = b, terrain_i[t][2] = d, t++;
            terrain_i[t][0] = a, terrain_i[t][1] = d, terrain_i[t][2] = c, t++;
        }
}

static dTriMeshDataID build(double (*v)[3], int nv, dTriIndex (*idx)[3], int nt)
{
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(d, v, 3 * sizeof(double), nv, idx, 3 * nt,
                                3 * sizeof(dTriIndex));
    return d;
}

// The deepest contact of dCollide(a, b): depth and normal (zeros if none).
static void print_deepest(const char *name, dGeomID a, dGeomID b)
{
    dContactGeom c[32];
    int n = dCollide(a, b, 32, c, sizeof c[0]);
    int k = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[k].depth) k = i;
    dReal v[4] = { 0, 0, 0, 0 };
    if (n > 0) {
        v[0] = c[k].depth;
        for (int i = 0; i < 3; i++) v[1 + i] = c[k].normal[i];
    }
    diff_values(name, 1e-6, v, 4);
}

static void getters_and_mass(void)
{
    dTriMeshDataID d = build(box_v, 8, box_i, 12);
    dGeomID g = dCreateTriMesh(0, d, NULL, NULL, NULL);
    dGeomSetPosition(g, 0.3, -0.2, 0.5);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 2, 3, 0.7);
    dGeomSetRotation(g, R);
    diff_value("trimesh_triangle_count", 0, dGeomTriMeshGetTriangleCount(g));
    for (int t = 0; t < 12; t += 5) {
        dVector3 v0, v1, v2, p;
        dGeomTriMeshGetTriangle(g, t, &v0, &v1, &v2);
        dReal v[9] = { v0[0], v0[1], v0[2], v1[0], v1[1], v1[2], v2[0], v2[1], v2[2] };
        diff_values("trimesh_get_triangle", 1e-6, v, 9);
        dGeomTriMeshGetPoint(g, t, 0.2, 0.3, p);
        diff_values("trimesh_get_point", 1e-6, p, 3);
    }
    dMass m;
    dMassSetTrimesh(&m, 2.5, g);
    diff_value("trimesh_mass", 1e-5, m.mass);
    diff_values("trimesh_mass_centre", 1e-6, m.c, 3);
    diff_matrix3("trimesh_mass_inertia", 1e-5, m.I);
    dGeomDestroy(g);
    dGeomTriMeshDataDestroy(d);
}

static void print_tc(const char *name, dGeomID g)
{
    dReal on[dGeomNumClasses];
    for (int c = 0; c < dGeomNumClasses; c++) on[c] = dGeomTriMeshIsTCEnabled(g, c);
    diff_values(name, 0, on, dGeomNumClasses);
}

static void tc_flags(void)
{
    dTriMeshDataID d = build(box_v, 8, box_i, 12);
    dGeomID g = dCreateTriMesh(0, d, NULL, NULL, NULL);
    print_tc("trimesh_tc_default", g);
    for (int c = 0; c < dGeomNumClasses; c++) dGeomTriMeshEnableTC(g, c, 1);
    print_tc("trimesh_tc_all_enabled", g);
    dGeomTriMeshEnableTC(g, dBoxClass, 0);
    dGeomTriMeshClearTCCache(g);
    print_tc("trimesh_tc_box_off", g);
    dGeomDestroy(g);
    dGeomTriMeshDataDestroy(d);
}

static void primitives_on_floor(void)
{
    dTriMeshDataID d = build(floor_v, 4, floor_i, 2);
    dGeomID mesh = dCreateTriMesh(0, d, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.5), b = dCreateBox(0, 0.8, 0.6, 0.4);
    dGeomID cap = dCreateCapsule(0, 0.3, 1.0);
    rng_state = 101;
    for (int i = 0; i < SCENES; i++) {
        double x = rnd(-5, 5), y = rnd(-5, 5), sink = rnd(0.01, 0.2);
        // Away from the diagonal edge x = y (both sides are faces of one plane).
        if (fabs(x - y) < 1.5) x += 3;
        dGeomSetPosition(s, x, y, 0.5 - sink);
        print_deepest("trimesh_sphere", mesh, s);
        print_deepest("sphere_trimesh", s, mesh);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 0, 1, rnd(0, 3));
        dGeomSetRotation(b, R);
        dGeomSetPosition(b, x, y, 0.2 - sink);
        print_deepest("trimesh_box", mesh, b);
        print_deepest("box_trimesh", b, mesh);
        dMatrix3 R1, R2;
        dRFromAxisAndAngle(R1, 1, 0, 0, M_PI / 2);
        dMultiply0_333(R2, R, R1);
        dGeomSetRotation(cap, R2);
        dGeomSetPosition(cap, x, y, 0.3 - sink);
        print_deepest("trimesh_capsule", mesh, cap);
        print_deepest("capsule_trimesh", cap, mesh);
    }
    dGeomDestroy(s);
    dGeomDestroy(b);
    dGeomDestroy(cap);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(d);
}

static void box_mesh_on_plane(void)
{
    dTriMeshDataID d = build(box_v, 8, box_i, 12);
    dGeomID mesh = dCreateTriMesh(0, d, NULL, NULL, NULL);
    dGeomID plane = dCreatePlane(0, 0, 0, 1, 0);
    rng_state = 102;
    for (int i = 0; i < SCENES; i++) {
        dMatrix3 R;
        dRFromAxisAndAngle(R, rnd(-1, 1), rnd(-1, 1), 1,
                           i % 2 ? rnd(0, 1) : 0);
        dGeomSetRotation(mesh, R);
        dGeomSetPosition(mesh, rnd(-2, 2), rnd(-2, 2), rnd(0.2, 1));
        print_deepest("trimesh_plane", mesh, plane);
        print_deepest("plane_trimesh", plane, mesh);
    }
    dGeomDestroy(plane);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(d);
}

// The closest hit of a ray: hit, depth, pos, normal.
static void print_ray(const char *name, dGeomID a, dGeomID b)
{
    dContactGeom c[4];
    int n = dCollide(a, b, 4, c, sizeof c[0]);
    dReal v[8] = { (dReal)n, 0, 0, 0, 0, 0, 0, 0 };
    if (n > 0) {
        v[1] = c[0].depth;
        for (int i = 0; i < 3; i++) {
            v[2 + i] = c[0].pos[i];
            v[5 + i] = c[0].normal[i];
        }
    }
    diff_values(name, 1e-5, v, 8);
}

static void rays(void)
{
    dTriMeshDataID dt = build(terrain_v, 13 * 13, terrain_i, 2 * 12 * 12);
    dTriMeshDataID db = build(box_v, 8, box_i, 12);
    dGeomID terrain = dCreateTriMesh(0, dt, NULL, NULL, NULL);
    dGeomID box = dCreateTriMesh(0, db, NULL, NULL, NULL);
    dGeomSetPosition(box, 5, 0, 0);
    dGeomID ray = dCreateRay(0, 4);
    dGeomRaySetClosestHit(ray, 1);
    rng_state = 103;
    for (int i = 0; i < SCENES; i++) {
        dGeomRaySet(ray, rnd(-2.8, 2.8), rnd(-2.8, 2.8), 2, 0, 0, -1);
        print_ray("ray_terrain", ray, terrain);
        print_ray("terrain_ray", terrain, ray);
        // Through the box from the side, away from its edges.
        dGeomRaySet(ray, 2, rnd(-0.6, 0.6), rnd(-0.4, 0.4), 1, 0, 0);
        print_ray("ray_box_mesh", ray, box);
    }
    dGeomDestroy(ray);
    dGeomDestroy(terrain);
    dGeomDestroy(box);
    dGeomTriMeshDataDestroy(dt);
    dGeomTriMeshDataDestroy(db);
}

int main(void)
{
    dInitODE2(0);
    make_box();
    make_terrain();
    getters_and_mass();
    tc_flags();
    primitives_on_floor();
    box_mesh_on_plane();
    rays();
    dCloseODE();
    return 0;
}
