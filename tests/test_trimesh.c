// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh.c -- the trimesh API (guide 10.7.6): data builds in every
// form (float, double, simple, strided with user data per vertex and per
// triangle), bad input, triangles in world coordinates, extra data and
// preprocessing, Update, the geom's settings and callbacks' accessors,
// data destroyed while in use, and dMassSetTrimesh against analytic masses.

#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

// Rounding of a few operations on sizes ~1 in the precision built.
#define EPS TOL(1e-9, 2e-5)

// ---- builds ------------------------------------------------------------------

// A unit right triangle in z = 0 and a sphere of radius 0.5 at height z:
// the depth of their contact (0 if none).
static dReal sphere_depth_on(dTriMeshDataID data, dReal z)
{
    dGeomID mesh = dCreateTriMesh(0, data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomSetPosition(s, 0.25, 0.25, z);
    dContactGeom c[4];
    int n = dCollide(mesh, s, 4, c, sizeof c[0]);
    dGeomDestroy(s);
    dGeomDestroy(mesh);
    return n ? c[0].depth : 0;
}

static int test_build_forms(void)
{
    float vf[3][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    double vd[3][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    dReal vs[3][4] = { { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 } };
    dTriIndex idx[3] = { 0, 1, 2 };
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    CHECK(d != NULL);
    dGeomTriMeshDataBuildSingle(d, vf, sizeof vf[0], 3, idx, 3, sizeof idx);
    CHECK_NEAR(sphere_depth_on(d, 0.25), 0.25, EPS);
    dGeomTriMeshDataBuildDouble(d, vd, sizeof vd[0], 3, idx, 3, sizeof idx);
    CHECK_NEAR(sphere_depth_on(d, 0.25), 0.25, EPS);
    dGeomTriMeshDataBuildSimple(d, &vs[0][0], 3, idx, 3);
    CHECK_NEAR(sphere_depth_on(d, 0.25), 0.25, EPS);
    dReal normals[3] = { 0, 0, 1 };
    dGeomTriMeshDataBuildDouble1(d, vd, sizeof vd[0], 3, idx, 3, sizeof idx, normals);
    CHECK(dGeomTriMeshDataGet(d, dTRIMESHDATA_FACE_NORMALS) == normals);
    CHECK_NEAR(sphere_depth_on(d, 0.25), 0.25, EPS);
    dGeomTriMeshDataBuildSingle1(d, vf, sizeof vf[0], 3, idx, 3, sizeof idx, NULL);
    dGeomTriMeshDataBuildSimple1(d, &vs[0][0], 3, idx, 3, NULL);
    CHECK_NEAR(sphere_depth_on(d, 0.4), 0.1, EPS);
    CHECK(sphere_depth_on(d, 0.6) == 0);
    CHECK(sphere_depth_on(d, -0.1) == 0);   // behind the one-sided triangle
    dGeomTriMeshDataDestroy(d);
    return 0;
}

// Vertices and triangles with user data between them (the guide's strided
// layout): the same contacts as packed arrays.
static int test_strides(void)
{
    struct vertex {
        float p[3];
        int id;
        double extra[2];
    } v[4];
    struct triangle {
        dTriIndex i[3];
        char tag[13];
    } t[2];
    test_mesh packed;
    mesh_sheet(&packed, 1);
    for (int i = 0; i < 4; i++) {
        for (int k = 0; k < 3; k++) v[i].p[k] = (float)packed.v[i][k];
        v[i].id = 1000 + i;
        v[i].extra[0] = v[i].extra[1] = NAN;   // never read as coordinates
    }
    for (int j = 0; j < 2; j++) {
        memcpy(t[j].i, packed.tri[j], sizeof t[j].i);
        memset(t[j].tag, 0xff, sizeof t[j].tag);   // nor as indices
    }
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildSingle(d, v, sizeof v[0], 4, t, 6, sizeof t[0]);
    dGeomID a = dCreateTriMesh(0, d, NULL, NULL, NULL);
    dGeomID b = dCreateTriMesh(0, packed.data, NULL, NULL, NULL);
    CHECK(dGeomTriMeshGetTriangleCount(a) == 2);
    dGeomID s = dCreateSphere(0, 0.3);
    for (int i = 0; i < 20; i++) {
        dGeomSetPosition(s, -0.9 + 0.09 * i, 0.7 - 0.07 * i, 0.1 + 0.01 * i);
        dContactGeom ca[4], cb[4];
        int na = dCollide(a, s, 4, ca, sizeof ca[0]), nb = dCollide(b, s, 4, cb, sizeof cb[0]);
        CHECK(na == nb && na >= 1);
        for (int j = 0; j < na && j < nb; j++) {
            CHECK_NEAR(ca[j].depth, cb[j].depth, 1e-6);
            CHECK_VEC(ca[j].normal, cb[j].normal[0], cb[j].normal[1], cb[j].normal[2], 1e-6);
            CHECK(ca[j].side1 == cb[j].side1);
        }
    }
    dVector3 p0, p1, p2;
    dGeomTriMeshGetTriangle(a, 1, &p0, &p1, &p2);
    CHECK_VEC(p2, -1, 1, 0, 0);
    dGeomDestroy(s);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomTriMeshDataDestroy(d);
    mesh_free(&packed);
    return 0;
}

// Each bad input is reported naming the function and leaves an empty mesh.
static int test_bad_input(void)
{
    double v[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
    dTriIndex good[3] = { 0, 1, 2 }, past[3] = { 0, 1, 4 };
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    dGeomID mesh = dCreateTriMesh(0, d, NULL, NULL, NULL);
    test_capture_reports();
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, past, 3, sizeof past);
    CHECK(test_captured_contains("dGeomTriMeshDataBuildDouble"));
    CHECK(test_captured_contains("past the vertex count"));
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 0);
    v[1][2] = NAN;
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, good, 3, sizeof good);
    CHECK(test_captured_contains("vertex 1 is not finite"));
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 0);
    v[1][2] = 0;
    // A vertex no triangle names is never read, as in ODE (whose own
    // demo_trimesh_collision passes a VertexCount past its array): not
    // finite, it is no error, at the build or at an Update.
    v[3][0] = NAN;
    int reports = test_captured_count();
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, good, 3, sizeof good);
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 1);
    v[2][2] = 0.5;
    dGeomTriMeshDataUpdate(d);
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 1);
    CHECK(test_captured_count() == reports);
    dVector3 q0, q1, q2;
    dGeomTriMeshGetTriangle(mesh, 0, &q0, &q1, &q2);
    CHECK(q2[2] == 0.5);
    v[3][0] = 1;
    v[2][2] = 0;
    dGeomTriMeshDataBuildDouble(d, v, 2 * sizeof(double), 4, good, 3, sizeof good);
    CHECK(test_captured_contains("VertexStride"));
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, good, 3, 2 * sizeof(dTriIndex));
    CHECK(test_captured_contains("TriStride"));
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, good, 2, sizeof good);
    CHECK(test_captured_contains("multiple of 3"));
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 0);
    int before = test_captured_count();
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 4, good, 0, sizeof good);   // no triangles
    CHECK(test_captured_count() == before + 1 && test_captured_contains("no triangles"));
    dGeomID s = dCreateSphere(0, 1);
    dContactGeom c[4];
    CHECK(dCollide(mesh, s, 4, c, sizeof c[0]) == 0);
    dGeomTriMeshGetTriangle(mesh, 0, NULL, NULL, NULL);
    CHECK(test_captured_contains("Index 0 is not a triangle"));
    dGeomTriMeshDataDestroy(NULL);
    CHECK(test_captured_contains("trimesh data is NULL"));
    test_release_reports();

    // A degenerate triangle (three points on a line) is kept in the
    // numbering and never collides; its neighbour still does.
    double w[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
    dTriIndex tris[6] = { 0, 1, 2, 0, 1, 3 };
    dGeomTriMeshDataBuildDouble(d, w, sizeof w[0], 5, tris, 6, 3 * sizeof(dTriIndex));
    CHECK(dGeomTriMeshGetTriangleCount(mesh) == 2);
    dGeomSetPosition(s, 0.3, 0.1, 0.5);
    int n = dCollide(mesh, s, 4, c, sizeof c[0]);
    CHECK(n == 1 && c[0].side1 == 1);
    CHECK_NEAR(c[0].depth, 0.5, EPS);
    dGeomDestroy(s);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(d);
    return 0;
}

// ---- triangles, extra data, preprocessing ----------------------------------

static int test_triangles_world(void)
{
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    CHECK(dGeomGetClass(g) == dTriMeshClass);
    CHECK(dGeomTriMeshGetData(g) == m.data && dGeomTriMeshGetTriMeshDataID(g) == m.data);
    dGeomSetPosition(g, 1, 2, 3);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);   // x -> y, y -> -x
    dGeomSetRotation(g, R);
    dVector3 a, b, c;
    dGeomTriMeshGetTriangle(g, 0, &a, &b, &c);
    CHECK_VEC(a, 1 + 1, 2 - 1, 3, EPS);
    CHECK_VEC(b, 1 + 1, 2 + 1, 3, EPS);
    CHECK_VEC(c, 1 - 1, 2 + 1, 3, EPS);
    dGeomTriMeshGetTriangle(g, 1, NULL, &b, NULL);
    CHECK_VEC(b, 0, 3, 3, EPS);
    dVector3 p;
    dGeomTriMeshGetPoint(g, 0, 0.25, 0.5, p);   // 0.25 a + 0.25 b + 0.5 c
    CHECK_VEC(p, 0.25 * 2 + 0.25 * 2 + 0.5 * 0, 0.25 * 1 + 0.25 * 3 + 0.5 * 3, 3, EPS);
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    CHECK_NEAR(aabb[0], 0, EPS);
    CHECK_NEAR(aabb[1], 2, EPS);
    CHECK_NEAR(aabb[2], 1, EPS);
    CHECK_NEAR(aabb[3], 3, EPS);
    CHECK_NEAR(aabb[4], 3, EPS);
    CHECK_NEAR(aabb[5], 3, EPS);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// GetBuffer / SetBuffer are ODE's deprecated forms of Get2 / Set.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
// Use flags: on a flat grid only the border edges and the vertices on the
// border are features; on a closed box every edge between two faces of the
// box is one, and none inside a face.
static int test_preprocess(void)
{
    test_mesh grid;
    mesh_grid(&grid, 4, 1, NULL);
    CHECK(dGeomTriMeshDataGet(grid.data, dTRIMESHDATA_USE_FLAGS) == NULL);
    CHECK(dGeomTriMeshDataPreprocess(grid.data) == 1);
    dsizeint size = 0;
    unsigned char *flags = dGeomTriMeshDataGet2(grid.data, dTRIMESHDATA_USE_FLAGS, &size);
    CHECK(flags != NULL && size == (dsizeint)grid.nt);
    for (int t = 0; t < grid.nt; t++)
        for (int k = 0; k < 3; k++) {
            const double *a = grid.v[grid.tri[t][k]], *b = grid.v[grid.tri[t][(k + 1) % 3]];
            int border = (a[0] == b[0] && fabs(a[0]) == 1) || (a[1] == b[1] && fabs(a[1]) == 1);
            CHECK(((flags[t] >> k) & 1) == border);
            int on_border = fabs(a[0]) == 1 || fabs(a[1]) == 1;
            CHECK(((flags[t] >> (3 + k)) & 1) == on_border);
        }
    unsigned char *buf;
    int len;
    dGeomTriMeshDataGetBuffer(grid.data, &buf, &len);
    CHECK(buf == flags && len == grid.nt);
    dintptr extra[dTRIDATAPREPROCESS_BUILD__MAX] = {
        0, dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_WORD_ALL };
    CHECK(dGeomTriMeshDataPreprocess2(grid.data, 1u << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES,
                                      extra) == 1);
    test_capture_reports();
    CHECK(dGeomTriMeshDataPreprocess2(grid.data, 1u << 5, NULL) == 0);
    CHECK(test_captured_contains("buildRequestFlags"));
    test_release_reports();
    // The user's own flags replace the computed ones.
    unsigned char mine[32] = { 0 };
    dGeomTriMeshDataSetBuffer(grid.data, mine);
    CHECK(dGeomTriMeshDataGet(grid.data, dTRIMESHDATA_USE_FLAGS) == mine);
    mesh_free(&grid);

    test_mesh box;
    mesh_box(&box, 2, 2, 2, 2);
    dGeomTriMeshDataPreprocess(box.data);
    flags = dGeomTriMeshDataGet(box.data, dTRIMESHDATA_USE_FLAGS);
    for (int t = 0; t < box.nt; t++)
        for (int k = 0; k < 3; k++) {
            const double *a = box.v[box.tri[t][k]], *b = box.v[box.tri[t][(k + 1) % 3]];
            // Both ends on one edge line of the box (the faces share no
            // vertices, so that is a border of the mesh too).
            int on_box_edge = 0;
            for (int i = 0; i < 3; i++)
                for (int j = i + 1; j < 3; j++)
                    if (fabs(a[i]) == 1 && fabs(a[j]) == 1 && a[i] == b[i] && a[j] == b[j])
                        on_box_edge = 1;
            CHECK(((flags[t] >> k) & 1) == on_box_edge);
        }
    mesh_free(&box);
    return 0;
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

static int test_geom_settings(void)
{
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    CHECK(dGeomTriMeshGetCallback(g) == NULL && dGeomTriMeshGetArrayCallback(g) == NULL);
    CHECK(dGeomTriMeshGetRayCallback(g) == NULL && dGeomTriMeshGetTriMergeCallback(g) == NULL);
    CHECK(!dGeomTriMeshIsTCEnabled(g, dSphereClass));
    dGeomTriMeshEnableTC(g, dSphereClass, 1);
    dGeomTriMeshEnableTC(g, dBoxClass, 1);
    dGeomTriMeshEnableTC(g, dBoxClass, 0);
    CHECK(dGeomTriMeshIsTCEnabled(g, dSphereClass) && !dGeomTriMeshIsTCEnabled(g, dBoxClass));
    dGeomTriMeshClearTCCache(g);
    const dReal *last = dGeomTriMeshGetLastTransform(g);
    for (int i = 0; i < 16; i++) CHECK(last[i] == (i % 5 == 0 ? 1 : 0));
    dMatrix4 t;
    for (int i = 0; i < 16; i++) t[i] = (dReal)i;
    dGeomTriMeshSetLastTransform(g, t);
    last = dGeomTriMeshGetLastTransform(g);
    for (int i = 0; i < 16; i++) CHECK(last[i] == i);
    test_capture_reports();
    dGeomID s = dCreateSphere(0, 1);
    dGeomTriMeshSetData(s, m.data);
    CHECK(test_captured_contains("not a trimesh"));
    dGeomDestroy(s);
    test_release_reports();
    dGeomTriMeshSetData(g, NULL);
    CHECK(dGeomTriMeshGetTriangleCount(g) == 0);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// Data destroyed before its geoms: the geoms keep working, the data goes
// with the last of them (AddressSanitizer watches the memory).
static int test_destroy_data_first(void)
{
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID a = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID b = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomTriMeshDataDestroy(m.data);
    m.data = NULL;
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomSetPosition(s, 0.2, 0.2, 0.4);
    dContactGeom c[4];
    CHECK(dCollide(a, s, 4, c, sizeof c[0]) >= 1);
    dGeomDestroy(a);
    CHECK(dCollide(b, s, 4, c, sizeof c[0]) >= 1);
    // Destroyed is destroyed: it cannot be given to a geom or destroyed again.
    dTriMeshDataID gone = dGeomTriMeshGetData(b);
    test_capture_reports();
    CHECK(dCreateTriMesh(0, gone, NULL, NULL, NULL) == NULL);
    dGeomTriMeshSetData(b, gone);
    dGeomTriMeshDataDestroy(gone);
    CHECK(test_captured_count() == 3 && test_captured_contains("destroyed"));
    test_release_reports();
    dGeomDestroy(b);
    dGeomDestroy(s);
    mesh_free(&m);
    return 0;
}

// Update after the vertices moved: the tree, normals and the geoms' boxes
// follow.
static int test_update(void)
{
    test_mesh m;
    mesh_grid(&m, 8, 2, NULL);
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID g = dCreateTriMesh(space, m.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(space, 0.25);
    dGeomSetPosition(s, 0.3, -0.4, 1.1);
    dContactGeom c[4];
    CHECK(dCollide(g, s, 4, c, sizeof c[0]) == 0);
    for (int i = 0; i < m.nv; i++) m.v[i][2] += 1;   // raise the terrain by 1
    dGeomTriMeshDataUpdate(m.data);
    int n = dCollide(g, s, 4, c, sizeof c[0]);
    CHECK(n == 1);
    CHECK_NEAR(c[0].depth, 0.15, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    CHECK_NEAR(aabb[4], 1, EPS);
    // Tilt it: z = 1 + x / 2 (1.15 below the sphere).
    for (int i = 0; i < m.nv; i++) m.v[i][2] = 1 + m.v[i][0] / 2;
    dGeomTriMeshDataUpdate(m.data);
    dGeomSetPosition(s, 0.3, -0.4, 1.3);
    n = dCollide(g, s, 4, c, sizeof c[0]);
    double nz = 1 / sqrt(1.25);
    CHECK(n == 1);
    CHECK_VEC(c[0].normal, 0.5 * nz, 0, -nz, EPS);
    CHECK_NEAR(c[0].depth, 0.25 - (1.3 - 1.15) * nz, EPS);
    // A non-finite vertex empties the mesh, reported.
    m.v[3][1] = INFINITY;
    test_capture_reports();
    dGeomTriMeshDataUpdate(m.data);
    CHECK(test_captured_contains("vertex 3 is not finite"));
    test_release_reports();
    CHECK(dCollide(g, s, 4, c, sizeof c[0]) == 0);
    dSpaceDestroy(space);
    mesh_free(&m);
    return 0;
}

// ---- mass ------------------------------------------------------------------------

static int test_mass_box(void)
{
    test_mesh m;
    mesh_box(&m, 1, 2, 3, 3);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dMass mm, ref;
    dMassSetTrimesh(&mm, 2.5, g);
    dMassSetBox(&ref, 2.5, 1, 2, 3);
    CHECK_NEAR(mm.mass, ref.mass, EPS * ref.mass);
    for (int i = 0; i < 3; i++) CHECK_NEAR(mm.c[i], 0, EPS);
    for (int i = 0; i < 12; i++) CHECK_NEAR(mm.I[i], ref.I[i], EPS * ref.I[0]);
    dMassSetTrimeshTotal(&mm, 7, g);
    CHECK_NEAR(mm.mass, 7, 7 * EPS);
    CHECK_NEAR(mm.I[0], 7 * (4 + 9) / 12.0, 10 * EPS);
    // Off the origin: the centre follows the geom (world coordinates).
    dGeomSetPosition(g, 1, -2, 0.5);
    dMassSetTrimesh(&mm, 1, g);
    CHECK_NEAR(mm.mass, 6, 6 * EPS);
    CHECK_VEC(mm.c, 1, -2, 0.5, EPS);
    // A rotated box: the inertia rotates with it.
    dGeomSetPosition(g, 0, 0, 0);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 1, 0, 0.7);
    dGeomSetRotation(g, R);
    dMassSetTrimesh(&mm, 1, g);
    dMassSetBox(&ref, 1, 1, 2, 3);
    dMassRotate(&ref, R);
    for (int i = 0; i < 12; i++) CHECK_NEAR(mm.I[i], ref.I[i], EPS * ref.I[0]);
    test_capture_reports();
    dMassSetTrimesh(&mm, -1, g);
    CHECK(test_captured_contains("density"));
    test_mesh sheet;
    mesh_sheet(&sheet, 1);
    dGeomTriMeshSetData(g, sheet.data);
    dMass before = mm;
    dMassSetTrimesh(&mm, 1, g);
    CHECK(test_captured_contains("no volume"));
    CHECK(memcmp(&before, &mm, sizeof mm) == 0);
    test_release_reports();
    dGeomDestroy(g);
    mesh_free(&sheet);
    mesh_free(&m);
    return 0;
}

// An icosphere: its exact polyhedron volume (sum of the tetrahedra from the
// centre, computed here by the pyramid formula on each face) and a
// sphere's inertia within the tessellation's error.
static int test_mass_sphere(void)
{
    test_mesh m;
    mesh_icosphere(&m, 0.8, 3);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    double volume = 0;
    for (int t = 0; t < m.nt; t++) {
        const double *a = m.v[m.tri[t][0]], *b = m.v[m.tri[t][1]], *c = m.v[m.tri[t][2]];
        double e1[3], e2[3], n[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = b[k] - a[k];
            e2[k] = c[k] - a[k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double h = (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / area2;   // face distance
        volume += area2 / 2 * h / 3;
    }
    dMass mm, ref;
    dMassSetTrimesh(&mm, 3, g);
    CHECK_NEAR(mm.mass, 3 * volume, 3 * volume * EPS);
    dMassSetSphere(&ref, 3, 0.8);
    CHECK_NEAR(mm.mass, ref.mass, 0.02 * ref.mass);
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(mm.I[5 * i], ref.I[5 * i], 0.04 * ref.I[0]);
        CHECK_NEAR(mm.c[i], 0, EPS);
    }
    CHECK_NEAR(mm.I[1], 0, 1e-6);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// The torus: volume 2 pi^2 R r^2 within the tessellation's error.
static int test_mass_torus(void)
{
    test_mesh m;
    mesh_torus(&m, 1, 0.25, 64, 32);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dMass mm;
    dMassSetTrimesh(&mm, 1, g);
    double v = 2 * M_PI * M_PI * 1 * 0.25 * 0.25;
    CHECK_NEAR(mm.mass, v, 0.01 * v);
    CHECK(mm.I[10] > mm.I[0]);   // the axis of the ring has the most inertia
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_build_forms),
    TEST_CASE(test_strides),
    TEST_CASE(test_bad_input),
    TEST_CASE(test_triangles_world),
    TEST_CASE(test_preprocess),
    TEST_CASE(test_geom_settings),
    TEST_CASE(test_destroy_data_first),
    TEST_CASE(test_update),
    TEST_CASE(test_mass_box),
    TEST_CASE(test_mass_sphere),
    TEST_CASE(test_mass_torus),
    TEST_END,
};
