// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_walks.c -- the native trimesh colliders list a pair's
// triangles three ways: the tree's leaves in place (no per-triangle
// callback), the same leaves through the callback's path, and the
// temporal-coherence cache's list (each candidate's vertices copied from
// the user's arrays). Each way leaves out the triangles off the other
// geom's box and those whose plane its position is below (or, for a
// sphere, more than its radius above) before the shape's own test. All
// three must give the same contacts to the bit, and the same triangles to
// the array callback, for spheres, boxes, capsules, cylinders and a hull on
// a turned wavy terrain and for shapes whose boxes' sides lie within float
// roundings of a flat grid's lines; and a sphere over a flat grid touches
// it exactly when its centre is within [0, r] of the plane, at depth
// r - height.

#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

#define RNG_SEED 0x2545F4914F6CDD1DULL
#include "xorshift.h"

static double wavy(double x, double y)
{
    return 0.4 * sin(0.9 * x) * cos(0.7 * y);
}

static int accept_all(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    (void)tri;
    return 1;
}

// The array callback's triangles, summed with their places (a list's
// fingerprint).
static long array_sum;
static void array_seen(dGeomID mesh, dGeomID other, const int *tri, int n)
{
    (void)mesh;
    (void)other;
    for (int i = 0; i < n; i++) array_sum += (long)tri[i] * (i + 1) + 7;
}

enum { WAYS = 3, MAXC = 16 };

// Set the mesh up for walk `way`: 0 the leaves in place, 1 the leaves with a
// per-triangle callback, 2 the temporal-coherence list.
static void set_way(dGeomID mesh, int way)
{
    dGeomTriMeshSetCallback(mesh, way == 1 ? accept_all : NULL);
    const int classes[] = { dSphereClass, dBoxClass, dCapsuleClass };
    for (int i = 0; i < 3; i++) dGeomTriMeshEnableTC(mesh, classes[i], way == 2);
    dGeomTriMeshClearTCCache(mesh);
}

// Collide a with b (one of them the mesh) by each walk; the walks must give
// the same contacts, bit for bit, and the same array-callback triangles.
// *count: how many contacts.
static int walks_agree(dGeomID mesh, dGeomID a, dGeomID b, int *count)
{
    static dContactGeom c[WAYS][MAXC];
    int n[WAYS];
    long sum[WAYS];
    for (int way = 0; way < WAYS; way++) {
        set_way(mesh, way);
        array_sum = 0;
        memset(c[way], 0, sizeof c[way]);
        n[way] = dCollide(a, b, MAXC, c[way], sizeof c[way][0]);
        sum[way] = array_sum;
    }
    for (int way = 1; way < WAYS; way++) {
        CHECK(n[way] == n[0]);
        CHECK(sum[way] == sum[0]);
        CHECK(memcmp(c[way], c[0], (size_t)n[0] * sizeof c[0][0]) == 0);
    }
    *count = n[0];
    return 0;
}

static int test_three_walks_agree(void)
{
    test_mesh m;
    mesh_grid(&m, 24, 5, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dMatrix3 R;
    dRFromEulerAngles(R, 0.2, -0.3, 0.4);
    dGeomSetRotation(mesh, R);
    dGeomSetPosition(mesh, 0.3, -0.1, 0.2);
    dGeomTriMeshSetArrayCallback(mesh, array_seen);
    dGeomID shapes[5] = { dCreateSphere(0, 0.25), dCreateBox(0, 0.5, 0.3, 0.2),
                          dCreateCapsule(0, 0.15, 0.4), dCreateCylinder(0, 0.2, 0.3), NULL };
    // The hull: a box as a convex (its own box's contacts).
    static const dReal box_planes[24] = { 1, 0, 0, 0.2, -1, 0, 0, 0.2, 0, 1, 0, 0.15, 0, -1, 0, 0.15,
                                          0, 0, 1, 0.1, 0, 0, -1, 0.1 };
    static dReal box_pts[24];
    for (int v = 0; v < 8; v++) {
        box_pts[3 * v] = v & 1 ? 0.2 : -0.2;
        box_pts[3 * v + 1] = v & 2 ? 0.15 : -0.15;
        box_pts[3 * v + 2] = v & 4 ? 0.1 : -0.1;
    }
    static const unsigned box_polys[30] = { 4, 1, 3, 7, 5, 4, 0, 4, 6, 2, 4, 2, 6, 7, 3,
                                            4, 0, 1, 5, 4, 4, 4, 5, 7, 6, 4, 0, 2, 3, 1 };
    shapes[4] = dCreateConvex(0, box_planes, 6, box_pts, 8, box_polys);
    int total = 0;
    for (int i = 0; i < 2500; i++) {
        dGeomID o = shapes[i % 5];
        double x = rnd(-4, 4), y = rnd(-4, 4), z = wavy(x, y) + rnd(-0.3, 0.25);
        dVector3 p = { x, y, z }, w;
        dMultiply0_331(w, R, p);
        dGeomSetPosition(o, w[0] + 0.3, w[1] - 0.1, w[2] + 0.2);
        dMatrix3 Ro;
        dRFromEulerAngles(Ro, rnd(0, 6.3), rnd(0, 6.3), rnd(0, 6.3));
        dGeomSetRotation(o, Ro);
        for (int order = 0; order < 2; order++) {
            int n;
            if (walks_agree(mesh, order ? o : mesh, order ? mesh : o, &n)) return 1;
            total += n;
        }
    }
    CHECK(total > 1000);   // the poses do touch
    for (int k = 0; k < 5; k++) dGeomDestroy(shapes[k]);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

// The walk in place drops a triangle off the other geom's box by the
// triangle's float box first, and asks the exact test only where a side of
// that box equals the query's side in float. On a grid of whole and half
// coordinates (its triangles' float boxes are exact), shapes set so that
// their boxes' sides fall within a few float roundings of grid lines, on
// either side, meet both cases: the three walks must still agree to the
// bit, with the array callback's triangles.
static int test_walks_agree_at_box_sides(void)
{
    test_mesh m;
    mesh_grid(&m, 16, 4, NULL);   // cells of 0.5
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomTriMeshSetArrayCallback(mesh, array_seen);
    const dReal r = 0.25;
    dGeomID shapes[2] = { dCreateSphere(0, r), dCreateBox(0, 2 * r, 2 * r, 2 * r) };
    int total = 0;
    for (int i = 0; i < 1200; i++) {
        dGeomID o = shapes[i % 2];
        // a side of the shape's box on a grid line, moved by a few float
        // roundings (at 1: 1.2e-7) either way, or by far less
        const double shift = (i % 7 - 3) * (i % 3 ? 3e-8 : 1e-13);
        double x = round(rnd(-3, 3) * 2) / 2 + r + shift;
        double y = round(rnd(-3, 3) * 2) / 2 - r - (i % 5 - 2) * 4e-8;
        double z = (i % 4 ? r : 0.1) + (i % 11 - 5) * 2e-8;
        dGeomSetPosition(o, x, y, z);
        for (int order = 0; order < 2; order++) {
            int n;
            if (walks_agree(mesh, order ? o : mesh, order ? mesh : o, &n)) return 1;
            total += n;
        }
    }
    CHECK(total > 1000);   // the poses do touch
    for (int k = 0; k < 2; k++) dGeomDestroy(shapes[k]);
    dGeomDestroy(mesh);
    mesh_free(&m);
    // Heights that are not floats: a sphere over the wavy grid's highest
    // vertex, its box's lower side swept across the vertex's height in
    // steps far below a float's rounding there, so that for some it lies
    // above the vertex but at the same float (the exact test says off).
    mesh_grid(&m, 24, 5, wavy);
    mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomTriMeshSetArrayCallback(mesh, array_seen);
    int top = 0;
    for (int i = 1; i < m.nv; i++)
        if (m.v[i][2] > m.v[top][2]) top = i;
    dGeomID ball = dCreateSphere(0, r);
    for (int i = -400; i <= 400; i++) {
        dGeomSetPosition(ball, m.v[top][0] + 0.01, m.v[top][1] - 0.02, m.v[top][2] + r + i * 2e-10);
        int n;
        if (walks_agree(mesh, mesh, ball, &n)) return 1;
    }
    dGeomDestroy(ball);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

// A sphere over a flat grid (facing up): contacts exactly when its centre
// is on or above the plane by at most r (one a triangle it is over: ODE's
// sphere contacts are not merged by default), each at depth r - height,
// normal along z; none below the plane (the mesh is one-sided) or above r.
// Heights from just below to just above both ends, over edges and faces.
static int test_sphere_height_window(void)
{
    test_mesh m;
    mesh_grid(&m, 10, 2, NULL);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    const dReal r = 0.3;
    dGeomID ball = dCreateSphere(0, r);
    const double tol = sizeof(dReal) == sizeof(double) ? 1e-12 : 1e-6;
    const double heights[] = { -1e-9, 0, 1e-9, 0.1, 0.2999999, 0.3, 0.3000001, 0.5 };
    dContactGeom c[8];
    for (int i = 0; i < 300; i++) {
        double x = rnd(-1.5, 1.5), y = rnd(-1.5, 1.5);
        if (i % 3 == 0) x = round(x / 0.4) * 0.4;   // over a grid line
        for (size_t k = 0; k < sizeof heights / sizeof heights[0]; k++) {
            double z = heights[k];
            dGeomSetPosition(ball, x, y, z);
            z = dGeomGetPosition(ball)[2];   // as the precision keeps it
            int n = dCollide(mesh, ball, 8, c, sizeof c[0]);
            CHECK((n > 0) == (z >= 0 && z <= r));
            for (int j = 0; j < n; j++) {
                CHECK_NEAR(c[j].depth, r - z, tol);
                CHECK_NEAR(fabs(c[j].normal[2]), 1, tol);
            }
        }
    }
    dGeomDestroy(ball);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_three_walks_agree),
    TEST_CASE(test_walks_agree_at_box_sides),
    TEST_CASE(test_sphere_height_window),
    TEST_END,
};
