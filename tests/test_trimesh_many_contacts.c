// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_many_contacts.c -- one dCollide whose triangles give tens of
// thousands of contacts before the reduction (merging near-duplicates,
// keeping the corners of flat groups, picking the spread): the fuzz
// finding tests/fuzz/known/collide-heightfield-quadratic-merge (a wrapped
// heightfield of 1e-6 m cells under a geom covering tens of thousands of
// them) and a box pressed onto a bed of separate triangles. The reduction
// used to compare each contact with every one kept (minutes for these);
// the tests assert the contacts, not the time.

#include "test.h"

#include <math.h>
#include <stdlib.h>

// A wrapped field of S x S samples, cells of CELL m, heights up to BUMP m,
// and one spike SPIKE m high at sample (SX, SZ).
enum { S = 64, SX = 20, SZ = 37 };
#define CELL 1e-6
#define BUMP 1e-7
#define SPIKE 1e-5

static double field_heights[S * S];

// A sphere of 1.2e-4 m (240 cells across) centred half its radius above
// the spike's base, one period or more away from the field's origin (the
// wrap): about 45 000 triangles touch it; the deepest contact is at the
// spike's tip, along the line from the tip to the centre, as deep as the
// radius less that distance.
static int test_sphere_on_a_wrapped_field_of_micro_cells(void)
{
    srand(3);
    for (int i = 0; i < S * S; i++) field_heights[i] = BUMP * (rand() / (double)RAND_MAX);
    field_heights[SX + SZ * S] = SPIKE;
    dHeightfieldDataID hd = dGeomHeightfieldDataCreate();
    const double size = (S - 1) * CELL;
    dGeomHeightfieldDataBuildDouble(hd, field_heights, 0, size, size, S, S, 1, 0, 0, 1);
    dGeomID hf = dCreateHeightfield(0, hd, 1);
    const double r = 1.2e-4;
    // The spike's sample in the field frame (centred), shifted by whole periods.
    const double tip[3] = { SX * CELL - size / 2 + 3 * size, SPIKE, SZ * CELL - size / 2 - 2 * size };
    dGeomID s = dCreateSphere(0, r);
    dGeomSetPosition(s, tip[0] + 1e-7, r / 2, tip[2] - 2e-7);
    const dReal *c = dGeomGetPosition(s);
    double d[3] = { c[0] - tip[0], c[1] - tip[1], c[2] - tip[2] };
    double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);

    enum { MAX = 8 };
    dContactGeom k[MAX];
    int n = dCollide(hf, s, MAX, k, sizeof k[0]);

    CHECK(n == MAX);
    CHECK_NEAR(k[0].depth, r - dist, TOL(1e-12, 1e-9));
    for (int j = 0; j < 3; j++) CHECK_NEAR(k[0].normal[j], -d[j] / dist, TOL(1e-9, 1e-4));
    for (int i = 0; i < n; i++) {
        CHECK(k[i].g1 == hf && k[i].g2 == s);
        CHECK(k[i].depth >= 0 && k[i].depth <= k[0].depth);
        CHECK_NEAR(dCalcVectorLength3(k[i].normal), 1, TOL(1e-9, 1e-5));
        // On the sphere, pushed in by the depth along the normal.
        dReal p[3];
        for (int j = 0; j < 3; j++) p[j] = k[i].pos[j] - c[j];
        CHECK(dCalcVectorLength3(p) <= r * (1 + TOL(1e-9, 1e-5)));
    }
    dGeomDestroy(s);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(hd);
    return 0;
}

// N x N cells over [-1, 1]^2, each holding its own small right triangle
// (legs LEG of the cell, no shared vertices: every edge a border) at z = 0
// facing up; a 3 x 3 m box pressed SINK into them from above: under each
// triangle's three corners a contact, 3 N^2 distinct points with one
// normal. Merging finds no duplicates among them; the flat group
// keeps its hull's corners alone: the bed's five.
enum { N = 120 };
#define LEG 0.6
#define SINK 0.01

static int test_box_on_a_bed_of_separate_triangles(void)
{
    static double v[3 * N * N][3];
    static dTriIndex t[N * N][3];
    const double w = 2.0 / N, a = LEG * w;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            int c = i + N * j;
            double x = -1 + i * w, y = -1 + j * w;
            double corner[3][2] = { { x, y }, { x + a, y }, { x, y + a } };
            for (int k = 0; k < 3; k++) {
                v[3 * c + k][0] = corner[k][0];
                v[3 * c + k][1] = corner[k][1];
                v[3 * c + k][2] = 0;
                t[c][k] = (dTriIndex)(3 * c + k);
            }
        }
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(data, v, sizeof v[0], 3 * N * N, t, 3 * N * N, sizeof t[0]);
    dGeomID mesh = dCreateTriMesh(0, data, NULL, NULL, NULL);
    dGeomID box = dCreateBox(0, 3, 3, 0.5);
    dGeomSetPosition(box, 0, 0, 0.25 - SINK);
    const double far = -1 + (N - 1) * w, top = far + a;
    const double hull[5][2] = { { -1, -1 }, { top, -1 }, { top, far }, { far, top }, { -1, top } };

    enum { MAX = 16 };
    dContactGeom k[MAX];
    int n = dCollide(mesh, box, MAX, k, sizeof k[0]);
    int n4 = dCollide(box, mesh, 4, k + 8, sizeof k[0]);

    // (The prisms' sides are widened by 1e-9 of the box's size for rounding.)
    const double near = TOL(1e-8, 1e-4);
    CHECK(n == 5);
    for (int c = 0; c < 5; c++) {
        int found = 0;
        for (int i = 0; i < n; i++)
            found += fabs(k[i].pos[0] - hull[c][0]) < near && fabs(k[i].pos[1] - hull[c][1]) < near;
        CHECK(found == 1);
    }
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(k[i].pos[2], -SINK, TOL(1e-12, 1e-6));
        CHECK_NEAR(k[i].depth, SINK, TOL(1e-12, 1e-6));
        CHECK(k[i].normal[0] == 0 && k[i].normal[1] == 0 && k[i].normal[2] == -1);
        CHECK(k[i].side1 >= 0 && k[i].side1 < N * N);
    }
    // Four asked for: four of the five corners, the normal flipped.
    CHECK(n4 == 4);
    for (int i = 8; i < 12; i++) {
        int found = 0;
        for (int j = 0; j < n; j++)
            found += k[i].pos[0] == k[j].pos[0] && k[i].pos[1] == k[j].pos[1];
        CHECK(found == 1);
        CHECK(k[i].normal[2] == 1 && k[i].g1 == box && k[i].side2 >= 0);
    }
    dGeomDestroy(box);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(data);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_sphere_on_a_wrapped_field_of_micro_cells),
    TEST_CASE(test_box_on_a_bed_of_separate_triangles),
    TEST_END,
};
