// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_tc.c -- temporal coherence of trimesh collisions
// (dGeomTriMeshEnableTC) never changes a contact: a rain of spheres, boxes,
// capsules and cylinders on a wavy terrain collides every mesh pair with the
// cache off and on and gets the same bits (contacts, and the triangles the
// per-triangle callback is asked about, in order), through a cleared cache,
// moved vertices (Update), other data set on the geom, partners destroyed
// and new ones made, a second geom on the same data, and two threads at
// once. Also the flags as ODE 0.16 has them, bad input, no allocation once
// warm, and rays reading the leaf-order copy of the vertices.

#include "test.h"
#include "collide_threads.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

static double wavy(double x, double y)
{
    return 0.4 * sin(0.9 * x) * cos(0.7 * y);
}

static double wavy2(double x, double y)
{
    return 0.3 * cos(0.8 * x + 0.3) * sin(0.6 * y) + 0.05;
}

static void set_tc(dGeomID mesh, int on)
{
    dGeomTriMeshEnableTC(mesh, dSphereClass, on);
    dGeomTriMeshEnableTC(mesh, dBoxClass, on);
    dGeomTriMeshEnableTC(mesh, dCapsuleClass, on);
}

// ---- the flags -----------------------------------------------------------------

static int test_flags_as_ode(void)
{
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    for (int c = 0; c < dGeomNumClasses; c++) CHECK(!dGeomTriMeshIsTCEnabled(g, c));
    set_tc(g, 1);
    CHECK(dGeomTriMeshIsTCEnabled(g, dSphereClass) && dGeomTriMeshIsTCEnabled(g, dBoxClass) &&
          dGeomTriMeshIsTCEnabled(g, dCapsuleClass));
    // Other classes have no flag in ODE 0.16: accepted, and stay off.
    const int others[] = { dCylinderClass, dRayClass, dConvexClass, dTriMeshClass,
                           dHeightfieldClass, dPlaneClass };
    for (size_t i = 0; i < sizeof others / sizeof others[0]; i++) {
        dGeomTriMeshEnableTC(g, others[i], 1);
        CHECK(!dGeomTriMeshIsTCEnabled(g, others[i]));
    }
    dGeomTriMeshEnableTC(g, dBoxClass, 0);
    CHECK(!dGeomTriMeshIsTCEnabled(g, dBoxClass) && dGeomTriMeshIsTCEnabled(g, dSphereClass));
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

static int test_bad_input(void)
{
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 1);
    test_capture_reports();
    dGeomTriMeshEnableTC(g, -1, 1);
    CHECK(test_captured_contains("dGeomTriMeshEnableTC") && test_captured_contains("geomClass"));
    CHECK(dGeomTriMeshIsTCEnabled(g, 99) == 0);
    CHECK(test_captured_contains("dGeomTriMeshIsTCEnabled"));
    int before = test_captured_count();
    dGeomTriMeshEnableTC(s, dSphereClass, 1);
    CHECK(test_captured_count() == before + 1 && test_captured_contains("not a trimesh"));
    CHECK(dGeomTriMeshIsTCEnabled(s, dSphereClass) == 0);
    dGeomTriMeshClearTCCache(s);
    dGeomTriMeshClearTCCache(NULL);
    CHECK(test_captured_count() == before + 4);
    test_release_reports();
    for (int c = 0; c < dGeomNumClasses; c++) CHECK(!dGeomTriMeshIsTCEnabled(g, c));
    dGeomDestroy(s);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// ---- the rain ------------------------------------------------------------------

enum { BODIES = 48, STEPS = 240, MAXC = 16, LOG = 4096 };

// The triangles the per-triangle callback was asked about, in order.
typedef struct tri_log {
    int tri[LOG];
    int n;
} tri_log;

static tri_log *current_log;

static int log_triangle(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    if (current_log->n < LOG) current_log->tri[current_log->n] = tri;
    current_log->n++;
    return 1;
}

typedef struct rain {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    dGeomID mesh[2];     // two geoms on one data
    dBodyID body[BODIES];
    dGeomID geom[BODIES];
    int pairs, touching, mismatches;
} rain;

// A mesh pair collided with the cache off, then on (in either argument
// order): the same contacts and the same callback sequence, or a mismatch.
static int collide_both_ways(rain *r, dGeomID a, dGeomID b, dContactGeom *out)
{
    dGeomID mesh = dGeomGetClass(a) == dTriMeshClass ? a : b;
    static tri_log off_log, on_log;
    dContactGeom off[MAXC];
    off_log.n = on_log.n = 0;
    current_log = &off_log;
    set_tc(mesh, 0);
    int n_off = dCollide(a, b, MAXC, off, sizeof off[0]);
    current_log = &on_log;
    set_tc(mesh, 1);
    int n = dCollide(a, b, MAXC, out, sizeof out[0]);
    r->pairs++;
    r->touching += n > 0;
    if (n != n_off || !ct_same_contacts(out, off, n) || on_log.n != off_log.n ||
        memcmp(on_log.tri, off_log.tri, sizeof(int) * (size_t)(on_log.n < LOG ? on_log.n : LOG)))
        r->mismatches++;
    return n;
}

static void near_callback(void *data, dGeomID a, dGeomID b)
{
    rain *r = (rain *)data;
    dContactGeom c[MAXC];
    int mesh_pair = dGeomGetClass(a) == dTriMeshClass || dGeomGetClass(b) == dTriMeshClass;
    int n = mesh_pair ? collide_both_ways(r, a, b, c) : dCollide(a, b, MAXC, c, sizeof c[0]);
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    for (int i = 0; i < n; i++) {
        dContact ct;
        memset(&ct, 0, sizeof ct);
        ct.surface.mode = dContactApprox1;
        ct.surface.mu = 0.6;
        ct.geom = c[i];
        dJointAttach(dJointCreateContact(r->world, r->contacts, &ct), ba, bb);
    }
}

// Body i: a sphere, box, capsule or cylinder over the terrain, turned.
static void make_body(rain *r, int i, int round)
{
    dBodyID b = dBodyCreate(r->world);
    dGeomID g;
    switch ((i + round) % 4) {
    case 0: g = dCreateSphere(r->space, 0.2); break;
    case 1: g = dCreateBox(r->space, 0.4, 0.3, 0.2); break;
    case 2: g = dCreateCapsule(r->space, 0.12, 0.3); break;
    default: g = dCreateCylinder(r->space, 0.15, 0.3); break;
    }
    dMass mass;
    dMassSetSphereTotal(&mass, 1, 0.2);
    dBodySetMass(b, &mass);
    dGeomSetBody(g, b);
    double x = -3.5 + 7.0 * (i % 7) / 6 + 0.13 * round, y = -3.5 + 7.0 * (i / 7 % 7) / 6;
    dBodySetPosition(b, x, y, 0.8 + 0.25 * (i % 5) + 0.3 * round);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0.3 + i % 3, 1, 0.2 * i, 0.4 + 0.1 * i);
    dBodySetRotation(b, R);
    dBodySetLinearVel(b, 0.3 * sin(i), 0.3 * cos(i), 0);
    r->body[i] = b;
    r->geom[i] = g;
}

static int test_rain_same_contacts(void)
{
    dInitODE2(0);
    test_mesh m, m2;
    mesh_grid(&m, 40, 5, wavy);
    mesh_grid(&m2, 30, 5, wavy2);
    static rain r;
    memset(&r, 0, sizeof r);
    r.world = dWorldCreate();
    dWorldSetGravity(r.world, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(r.world, 10);
    r.space = dHashSpaceCreate(0);
    r.contacts = dJointGroupCreate(0);
    for (int k = 0; k < 2; k++) {
        r.mesh[k] = dCreateTriMesh(r.space, m.data, log_triangle, NULL, NULL);
        dGeomSetPosition(r.mesh[k], 0.01 * k, 0, -0.05 * k);   // both touched by the rain
    }
    for (int i = 0; i < BODIES; i++) make_body(&r, i, 0);
    int touching_before_events = 0;
    for (int step = 0; step < STEPS; step++) {
        if (step == 60) touching_before_events = r.touching;
        if (step == 80) dGeomTriMeshClearTCCache(r.mesh[0]);
        if (step == 110) {   // the terrain rises and waves more: a refit
            for (int v = 0; v < m.nv; v++) m.v[v][2] += 0.03 + 0.05 * sin(m.v[v][0]);
            dGeomTriMeshDataUpdate(m.data);
        }
        if (step == 140) {   // a quarter of the partners replaced (addresses may be reused)
            for (int i = 0; i < BODIES; i += 4) {
                dGeomDestroy(r.geom[i]);
                dBodyDestroy(r.body[i]);
                make_body(&r, i, 1);
            }
        }
        if (step == 170) dGeomTriMeshSetData(r.mesh[1], m2.data);
        if (step == 200) {   // everything moved far at once
            for (int i = 0; i < BODIES; i++) {
                const dReal *p = dBodyGetPosition(r.body[i]);
                dBodySetPosition(r.body[i], -p[1], p[0], p[2] + 0.2);
            }
        }
        dSpaceCollide(r.space, &r, near_callback);
        dWorldQuickStep(r.world, 1.0 / 60);
        dJointGroupEmpty(r.contacts);
    }
    CHECK(r.mismatches == 0);
    CHECK(touching_before_events > 0);
    CHECK(r.touching > STEPS * BODIES / 2);   // the bodies rest on the terrain most of the run
    dJointGroupDestroy(r.contacts);
    dSpaceDestroy(r.space);
    dWorldDestroy(r.world);
    mesh_free(&m);
    mesh_free(&m2);
    dCloseODE();
    return 0;
}

// ---- warm queries allocate nothing -------------------------------------------

static int test_warm_queries_allocate_nothing(void)
{
    test_mesh m;
    mesh_grid(&m, 20, 3, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    set_tc(mesh, 1);
    dGeomID g[3] = { dCreateSphere(0, 0.3), dCreateBox(0, 0.5, 0.4, 0.3),
                     dCreateCapsule(0, 0.2, 0.5) };
    dContactGeom c[MAXC];
    int total = 0;
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) test_count_allocations();
        for (int p = 0; p < 50; p++) {
            double x = -2 + 0.08 * p, y = sin(0.3 * p);
            for (int k = 0; k < 3; k++) {
                dGeomSetPosition(g[k], x, y, wavy(x, y) + 0.1);
                total += dCollide(mesh, g[k], MAXC, c, sizeof c[0]);
            }
        }
        if (pass == 1) CHECK(test_allocations_counted() == 0);
    }
    CHECK(total > 0);
    for (int k = 0; k < 3; k++) dGeomDestroy(g[k]);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

// ---- two threads -------------------------------------------------------------------

enum { POSES = 60, ROUNDS = 20, KINDS = 3 };

static int test_two_threads(void)
{
    dInitODE2(0);
    test_mesh m;
    mesh_grid(&m, 24, 3, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dReal aabb[6];
    dGeomGetAABB(mesh, aabb);   // the mesh's pose settled before the threads read it
    static ct_worker w[2];
    for (int i = 0; i < 2; i++) {
        w[i].target = mesh;
        w[i].kinds = KINDS;
        w[i].poses = POSES;
        w[i].rounds = ROUNDS;
        w[i].geom[0] = dCreateSphere(0, 0.25);
        w[i].geom[1] = dCreateBox(0, 0.5, 0.4, 0.3);
        w[i].geom[2] = dCreateCapsule(0, 0.2, 0.6);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0.5 * i, 0.3, 0.7 + i);
        dGeomSetRotation(w[i].geom[1], R);
        dGeomSetRotation(w[i].geom[2], R);
        // A path in small steps (the cache is used) with jumps (it is made again).
        for (int p = 0; p < POSES; p++) {
            double x = -2.5 + 0.06 * p + (p % 20 == 19 ? 1.0 : 0), y = (i ? 1 : -1) * sin(0.1 * p);
            w[i].pose[p][0] = x;
            w[i].pose[p][1] = y;
            w[i].pose[p][2] = wavy(x, y) + 0.12 + 0.01 * (p % 3);
        }
        int touching[CT_KINDS];
        ct_record(&w[i], touching);   // expected: the cache off
        CHECK(touching[0] + touching[1] + touching[2] > POSES * KINDS / 2);
    }
    set_tc(mesh, 1);
    CHECK(ct_run_pair(&w[0], &w[1]) == 0);
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < KINDS; k++) dGeomDestroy(w[i].geom[k]);
    dGeomDestroy(mesh);
    mesh_free(&m);
    dCloseODE();
    return 0;
}

// ---- rays read the leaf-order copy of the vertices ---------------------------------

// The ray (start s, unit direction d) against every triangle of the geom
// (only triangle `only` if >= 0), by its own arithmetic: the nearest hit's
// distance and triangle (-1: none).
static int nearest_hit(dGeomID mesh, const double s[3], const double d[3], double len, int only,
                       double *best)
{
    int tri = -1;
    *best = len;
    for (int t = 0; t < dGeomTriMeshGetTriangleCount(mesh); t++) {
        if (only >= 0 && t != only) continue;
        dVector3 v[3];
        dGeomTriMeshGetTriangle(mesh, t, &v[0], &v[1], &v[2]);
        double e1[3], e2[3], n[3], w[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = v[1][k] - v[0][k];
            e2[k] = v[2][k] - v[0][k];
            w[k] = s[k] - v[0][k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double den = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        if (den == 0) continue;
        double dist = -(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / den;
        if (dist < 0 || dist > *best) continue;
        double p[3], c[3];
        for (int k = 0; k < 3; k++) p[k] = s[k] + dist * d[k];
        int inside = 1;
        for (int k = 0; k < 3 && inside; k++) {   // p on the inner side of each edge
            const dReal *a = v[k], *b = v[(k + 1) % 3];
            double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
            double q[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
            c[0] = e[1] * q[2] - e[2] * q[1];
            c[1] = e[2] * q[0] - e[0] * q[2];
            c[2] = e[0] * q[1] - e[1] * q[0];
            inside = c[0] * n[0] + c[1] * n[1] + c[2] * n[2] >= -1e-12;
        }
        if (!inside) continue;
        *best = dist;
        tri = t;
    }
    return tri;
}

// Rays from above onto the geom: the closest hit is the nearest triangle
// found by brute force, at its distance.
static int check_rays(dGeomID mesh, dGeomID ray, int *hits)
{
    for (int i = 0; i < 200; i++) {
        // (Off the grid's lines: a ray in the plane of an edge may slip
        // between its two triangles.)
        double s[3] = { -2.6 + 0.026 * i + 0.0037, 2.5 * sin(0.37 * i) + 0.0071, 2 };
        double d[3] = { 0.3 * cos(0.11 * i), 0.3 * sin(0.23 * i), -1 };
        double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; k++) d[k] /= l;
        dGeomRaySet(ray, s[0], s[1], s[2], d[0], d[1], d[2]);
        dContactGeom c;
        int n = dCollide(ray, mesh, 1, &c, sizeof c);
        double best;
        int tri = nearest_hit(mesh, s, d, 5, -1, &best);
        CHECK(n == (tri >= 0));
        if (!n) continue;
        (*hits)++;
        CHECK_NEAR(c.depth, best, TOL(1e-9, 1e-4));
        // Ties (a hit on a shared edge) may name either triangle: the one
        // named is hit there too.
        if (c.side2 != tri) {
            double own;
            CHECK(nearest_hit(mesh, s, d, 5, c.side2, &own) == c.side2);
            CHECK_NEAR(own, best, TOL(1e-9, 1e-4));
        }
    }
    return 0;
}

static int test_rays_after_update(void)
{
    test_mesh m;
    mesh_grid(&m, 30, 3, wavy);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomSetPosition(mesh, 0.1, -0.2, 0.05);
    dGeomID ray = dCreateRay(0, 5);
    dGeomRaySetClosestHit(ray, 1);
    int hits = 0;
    CHECK(check_rays(mesh, ray, &hits) == 0);
    for (int v = 0; v < m.nv; v++) m.v[v][2] = 0.5 * wavy2(m.v[v][1], m.v[v][0]);
    dGeomTriMeshDataUpdate(m.data);
    CHECK(check_rays(mesh, ray, &hits) == 0);
    CHECK(hits > 300);
    dGeomDestroy(ray);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_flags_as_ode),
    TEST_CASE(test_bad_input),
    TEST_CASE(test_rain_same_contacts),
    TEST_CASE(test_warm_queries_allocate_nothing),
    TEST_CASE(test_two_threads),
    TEST_CASE(test_rays_after_update),
    TEST_END,
};
