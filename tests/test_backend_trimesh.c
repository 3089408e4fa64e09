// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_trimesh.c -- triangle-mesh pairs under the FCL and Bullet
// adapters, against the contract (issue 14, tests/test_backend_contract.c)
// and against native, on the generated meshes of test_trimesh_meshes.h.
//
// Each mesh (grid terrain, icosphere, closed box, torus, thin sheet; posed
// off the origin and turned) meets a sphere, box, capsule, cylinder, convex
// box and a small closed box mesh at seeded random poses, both argument
// orders. Where the mesh's solid has a convex stand-in (the flat terrain a
// plane, the icosphere a sphere, the box mesh a box, the convex and the
// small mesh a box), tools/contact_truth.c gives the truth and each call is
// held to the contract: verdict, deepest depth, separation along its normal,
// every point within both shapes (tolerances widened by the tessellation);
// the torus and the sheet are held to native's deepest depth and to their
// own signed distances. Every call must also mirror its reversed call. A
// table per backend prints each pair's failures and worst errors, native's
// alongside; a pair a backend answers itself must pass, a pair it leaves to
// native is listed as such.
//
// Then, under each backend: the per-triangle callback vetoes triangles, an
// array callback or a merge setting sends the mesh to native (saying so
// once) with native's contacts, side1/side2 name touching triangles, Update
// moves the contacts with the vertices, and a box and a sphere dropped on a
// grid mesh come to rest at native's height.

#include "collide_check.h"
#include "contact_truth.h"
#include "convex_hulls.h"
#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

enum { MAXC = 32, POSES = 40, NMESHES = 5, NOTHERS = 6 };

#define NEAR_MISS 0.02    // no pose closer than this (+ the tessellation) to touching

static double depth_tol(double true_depth)
{
    return 0.005 + 0.05 * fabs(true_depth);
}

static double point_tol(double true_depth)
{
    return 0.01 + 0.1 * fabs(true_depth);
}

// ---- the meshes and their stand-ins -----------------------------------------------

typedef struct mesh_case {
    const char *name;
    test_mesh m;
    int kind;          // 0 flat terrain, 1 icosphere, 2 box, 3 torus, 4 sheet
    double a, b, c;    // sizes
    double tess;       // how far the mesh lies inside the solid it stands for
    dGeomID geom, proxy;   // the mesh posed, and its convex stand-in (or 0)
} mesh_case;

static mesh_case meshes[NMESHES] = {
    { "terrain", { 0 }, 0, 2.0, 0, 0, 0, 0, 0 },
    { "icosphere", { 0 }, 1, 1.2, 0, 0, 1.2 * 0.01, 0, 0 },
    { "box", { 0 }, 2, 2.0, 1.6, 1.2, 0, 0, 0 },
    { "torus", { 0 }, 3, 1.0, 0.4, 0, 0.4 * 0.02, 0, 0 },
    { "sheet", { 0 }, 4, 1.5, 0, 0, 0, 0, 0 },
};

// Where every mesh is: off the origin and turned, so that the adapters'
// transforms are exercised.
static const dReal MESH_POS[3] = { 0.3, -0.2, 0.1 };
static const dReal MESH_AXIS[3] = { 0.2, -0.3, 1 };
#define MESH_ANGLE 0.35

static void pose_mesh(dGeomID g)
{
    dGeomSetPosition(g, MESH_POS[0], MESH_POS[1], MESH_POS[2]);
    set_rot(g, MESH_AXIS[0], MESH_AXIS[1], MESH_AXIS[2], (dReal)MESH_ANGLE);
}

// A point of the mesh frame in the world.
static void mesh_to_world(dGeomID mesh, const double l[3], double w[3])
{
    dVector3 out;
    dGeomGetRelPointPos(mesh, (dReal)l[0], (dReal)l[1], (dReal)l[2], out);
    for (int i = 0; i < 3; i++) w[i] = out[i];
}

static void setup_meshes(void)
{
    mesh_grid(&meshes[0].m, 16, meshes[0].a, NULL);
    mesh_icosphere(&meshes[1].m, meshes[1].a, 3);
    mesh_box(&meshes[2].m, meshes[2].a, meshes[2].b, meshes[2].c, 2);
    mesh_torus(&meshes[3].m, meshes[3].a, meshes[3].b, 48, 24);
    mesh_sheet(&meshes[4].m, meshes[4].a);
    for (int i = 0; i < NMESHES; i++) {
        mesh_case *mc = &meshes[i];
        mc->geom = dCreateTriMesh(0, mc->m.data, NULL, NULL, NULL);
        pose_mesh(mc->geom);
        mc->proxy = 0;
        if (mc->kind == 0) {
            double o[3] = { 0, 0, 0 }, up[3] = { 0, 0, 1 }, wo[3], wu[3];
            mesh_to_world(mc->geom, o, wo);
            mesh_to_world(mc->geom, up, wu);
            double n[3] = { wu[0] - wo[0], wu[1] - wo[1], wu[2] - wo[2] };
            mc->proxy = dCreatePlane(0, (dReal)n[0], (dReal)n[1], (dReal)n[2],
                                     (dReal)(n[0] * wo[0] + n[1] * wo[1] + n[2] * wo[2]));
        } else if (mc->kind == 1) {
            mc->proxy = dCreateSphere(0, (dReal)mc->a);
        } else if (mc->kind == 2) {
            mc->proxy = dCreateBox(0, (dReal)mc->a, (dReal)mc->b, (dReal)mc->c);
        }
        if (mc->proxy && mc->kind != 0) {
            pose_mesh(mc->proxy);
        }
    }
}

static void free_meshes(void)
{
    for (int i = 0; i < NMESHES; i++) {
        dGeomDestroy(meshes[i].geom);
        if (meshes[i].proxy) dGeomDestroy(meshes[i].proxy);
        mesh_free(&meshes[i].m);
    }
}

// ---- the other geoms ------------------------------------------------------------------

static const char *const other_names[NOTHERS] = { "sphere", "box", "capsule", "cylinder",
                                                  "convex", "trimesh" };
static dGeomID others[NOTHERS], other_proxy[NOTHERS];
// The distance from each other geom's centre to its farthest point.
static const double other_reach[NOTHERS] = { 0.35, 0.39, 0.45, 0.32, 0.39, 0.39 };
static test_hull hull;
static test_mesh small;   // the small closed box mesh

// Sides of the box, the convex box and the small box mesh.
#define BX 0.6
#define BY 0.4
#define BZ 0.3

static void setup_others(void)
{
    others[0] = dCreateSphere(0, 0.35);
    others[1] = dCreateBox(0, BX, BY, BZ);
    others[2] = dCreateCapsule(0, 0.2, 0.5);
    others[3] = dCreateCylinder(0, 0.25, 0.4);
    test_hull_box(&hull, BX, BY, BZ);
    others[4] = dCreateConvex(0, hull.planes, hull.nplanes, hull.points, hull.npoints,
                              hull.polygons);
    mesh_box(&small, BX, BY, BZ, 2);
    others[5] = dCreateTriMesh(0, small.data, NULL, NULL, NULL);
    for (int i = 0; i < NOTHERS; i++) other_proxy[i] = i >= 4 ? dCreateBox(0, BX, BY, BZ) : others[i];
}

static void free_others(void)
{
    for (int i = 0; i < NOTHERS; i++) {
        if (other_proxy[i] != others[i]) dGeomDestroy(other_proxy[i]);
        dGeomDestroy(others[i]);
    }
    mesh_free(&small);
}

// The other geom at a world position, turned by a random rotation (its
// stand-in too).
static void place_other(int o, const double p[3], const dReal axis[3], dReal angle)
{
    dGeomID gs[2] = { others[o], other_proxy[o] };
    for (int k = 0; k < 2; k++) {
        dGeomSetPosition(gs[k], (dReal)p[0], (dReal)p[1], (dReal)p[2]);
        set_rot(gs[k], axis[0], axis[1], axis[2], angle);
    }
}

// ---- one pair, one pose ----------------------------------------------------------

// The stand-in of either geom of a pair (0: none).
static dGeomID proxy_of(const mesh_case *mc, int o, dGeomID g)
{
    return g == mc->geom ? mc->proxy : other_proxy[o];
}

typedef struct pair_stats {
    int calls, verdict, depth, separation, points, mirror;   // failures of each rule
    double depth_err, sep_err, point_err;                    // worst (absolute)
} pair_stats;

// Depth of world point p in the mesh's solid (its stand-in's, or for the
// torus its signed distance; the sheet: minus the distance off its plane).
static double mesh_point_depth(const mesh_case *mc, const double p[3])
{
    if (mc->proxy) return contact_truth_point_depth(mc->proxy, p);
    dVector3 l;
    dGeomGetPosRelPoint(mc->geom, (dReal)p[0], (dReal)p[1], (dReal)p[2], l);
    double q[3] = { l[0], l[1], l[2] };
    if (mc->kind == 3) return sdf_torus(mc->a, mc->b, q);
    return -fabs(q[2]);
}

static double geom_point_depth(const mesh_case *mc, int o, dGeomID g, const double p[3])
{
    return g == mc->geom ? mesh_point_depth(mc, p) : contact_truth_point_depth(other_proxy[o], p);
}

// Overlap of the stand-ins left after g1 is moved by the contact's depth
// along its normal (the other way round when g1's stand-in is a plane).
static double overlap_after_moving(dGeomID p1, dGeomID p2, const dContactGeom *k)
{
    int plane1 = dGeomGetClass(p1) == dPlaneClass;
    dGeomID m = plane1 ? p2 : p1;
    double s = plane1 ? -k->depth : k->depth;
    dVector3 p0;
    dGeomCopyPosition(m, p0);
    dGeomSetPosition(m, p0[0] + (dReal)(s * k->normal[0]), p0[1] + (dReal)(s * k->normal[1]),
                     p0[2] + (dReal)(s * k->normal[2]));
    contact_truth t;
    contact_truth_compute(p1, p2, &t);
    dGeomSetPosition(m, p0[0], p0[1], p0[2]);
    return t.depth;
}

// dCollide(g1, g2) and its mirror under the backend, checked against the
// truth t for (g1, g2) (has_truth) or native's deepest depth `want`
// (native_n contacts). Failures counted in st.
static void check_call(const char *backend, const mesh_case *mc, int o, dGeomID g1, dGeomID g2,
                       int has_truth, const contact_truth *t, int native_n, double want,
                       pair_stats *st)
{
    dContactGeom c[MAXC], r[MAXC];
    dCollisionSetBackend(backend);
    int n = dCollide(g1, g2, MAXC, c, sizeof c[0]);
    int m = dCollide(g2, g1, MAXC, r, sizeof r[0]);
    st->calls++;
    int k = n > 0 ? deepest(c, n) : 0;
    if (m != n || (n > 0 && fabs(r[deepest(r, m)].depth - c[k].depth) > 1e-9 + 1e-6 * c[k].depth))
        st->mirror++;
    double truth_depth = has_truth ? t->depth : want, tess = mc->tess;
    if (has_truth) {
        if ((n > 0) != t->overlap) {
            st->verdict++;
            return;
        }
    } else if ((n > 0) != (native_n > 0)) {
        double d = n > 0 ? c[k].depth : want;   // the one that sees contact
        if (d > NEAR_MISS + tess) st->verdict++;
        return;
    }
    if (n == 0) return;
    double err = fabs(c[k].depth - truth_depth);
    st->depth_err = fmax(st->depth_err, err);
    if (err > depth_tol(truth_depth) + tess) st->depth++;
    if (has_truth) {
        double left = overlap_after_moving(proxy_of(mc, o, g1), proxy_of(mc, o, g2), &c[k]);
        st->sep_err = fmax(st->sep_err, left);
        if (left > depth_tol(truth_depth) + tess) st->separation++;
    }
    int outside = 0;
    for (int i = 0; i < n; i++) {
        double p[3] = { c[i].pos[0], c[i].pos[1], c[i].pos[2] };
        double d1 = geom_point_depth(mc, o, g1, p), d2 = geom_point_depth(mc, o, g2, p);
        // The sheet has no inside: its points lie within the depth of its plane.
        if (mc->kind == 4) {
            if (g1 == mc->geom) d1 += c[k].depth;
            else d2 += c[k].depth;
        }
        double d = fmin(d1, d2);
        st->point_err = fmax(st->point_err, -d);
        if (d < -point_tol(truth_depth) - tess) outside = 1;
    }
    if (outside) st->points++;
}

// A random pose of other geom o near mesh mc (mesh frame sampling, see
// below) with its truth for (mesh, other) when the mesh has a stand-in;
// returns 0 if the pose is too close to touching.
static int random_pose(mesh_case *mc, int o, contact_truth *t)
{
    double l[3], w[3];
    switch (mc->kind) {
    case 0:
        l[0] = rnd(-1.2, 1.2), l[1] = rnd(-1.2, 1.2), l[2] = rnd(-0.45, 0.5);
        break;
    case 1: {
        double d[3], len, s = rnd(0.9, 1.8);
        do {
            for (int i = 0; i < 3; i++) d[i] = rnd(-1, 1);
            len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        } while (len < 0.1 || len > 1);
        for (int i = 0; i < 3; i++) l[i] = d[i] / len * s;
        break;
    }
    case 2:
        l[0] = rnd(-1.5, 1.5), l[1] = rnd(-1.3, 1.3), l[2] = rnd(-1.1, 1.1);
        break;
    case 3:
        for (int i = 0; i < 2; i++) l[i] = rnd(-1.6, 1.6);
        l[2] = rnd(-0.7, 0.7);
        break;
    default:
        l[0] = rnd(-1.4, 1.4), l[1] = rnd(-1.4, 1.4), l[2] = rnd(-0.4, 0.5);
        break;
    }
    mesh_to_world(mc->geom, l, w);
    dReal axis[3] = { (dReal)rnd(-1, 1), (dReal)rnd(-1, 1), (dReal)rnd(-1, 1) + (dReal)0.01 };
    place_other(o, w, axis, (dReal)rnd(0, 3.1));
    if (mc->kind == 3) {
        // Outside the torus, no farther than the other's reach.
        double out = -sdf_torus(mc->a, mc->b, l);
        return out >= 0.05 && out <= other_reach[o] + 0.25;
    }
    if (mc->kind == 4) return l[2] >= 0.05;   // on the sheet's front side
    contact_truth_compute(mc->proxy, other_proxy[o], t);
    // Shallow to moderately deep, as a contact of a simulation is: a shape
    // sunk far into a mesh has no meaningful per-triangle answer.
    return fabs(t->depth) >= NEAR_MISS + mc->tess && t->depth <= 0.1 && t->depth >= -0.3;
}

// Every pose of one (mesh, other) pair under one backend; 1 if the backend
// answers the pair, 0 if it leaves it to native.
static int run_pair(const char *backend, mesh_case *mc, int o, pair_stats *st)
{
    memset(st, 0, sizeof *st);
    rng_state = 5000 + 31 * (unsigned)mc->kind + (unsigned)o;
    int done = 0, tries = 0;
    while (done < POSES && tries < 40 * POSES) {
        tries++;
        contact_truth t = { 0, 0, { 0, 0, 0 } }, r;
        if (!random_pose(mc, o, &t)) continue;
        if (done == 0 && strcmp(backend, "native") != 0 &&
            !backend_answers(backend, mc->geom, others[o]))
            return 0;
        done++;
        dContactGeom c[MAXC];
        dCollisionSetBackend("native");
        int nn = dCollide(mc->geom, others[o], MAXC, c, sizeof c[0]);
        double want = nn > 0 ? c[deepest(c, nn)].depth : 0;
        r = t;
        for (int i = 0; i < 3; i++) r.normal[i] = -t.normal[i];
        int has_truth = mc->proxy != 0;
        check_call(backend, mc, o, mc->geom, others[o], has_truth, &t, nn, want, st);
        check_call(backend, mc, o, others[o], mc->geom, has_truth, &r, nn, want, st);
    }
    dCollisionSetBackend("native");
    return 1;
}

static int failures(const pair_stats *st)
{
    return st->verdict + st->depth + st->separation + st->points + st->mirror;
}

// The table of one backend; 1 if a pair it answers fails (native's own
// row is printed for comparison, not asserted: its colliders have their
// own tests).
static int check_backend(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    setup_meshes();
    setup_others();
    printf("# %s: mesh-other, calls (both orders), failures (verdict depth separation points "
           "mirror), worst errors (depth, overlap left, point outside)\n", backend);
    // ODE_BACKEND_MEASURE_TRIMESH (trimesh_adapter.h): the adapters answer
    // the pairs they leave to native too; the table measures, not asserts.
    const int measuring = getenv("ODE_BACKEND_MEASURE_TRIMESH") != NULL;
    int failed = 0;
    for (int i = 0; i < NMESHES; i++)
        for (int o = 0; o < NOTHERS; o++) {
            pair_stats st;
            char name[40];
            snprintf(name, sizeof name, "%s-%s", meshes[i].name, other_names[o]);
            if (!run_pair(backend, &meshes[i], o, &st)) {
                printf("#   %-18s native fallback\n", name);
                continue;
            }
            int bad = failures(&st) > 0;
            printf("#   %-18s %4d  %s %3d %3d %3d %3d %3d   %.4f %.4f %.4f\n", name, st.calls,
                   bad ? "FAIL" : "ok  ", st.verdict, st.depth, st.separation, st.points,
                   st.mirror, st.depth_err, st.sep_err, st.point_err);
            if (bad && strcmp(backend, "native") != 0 && !measuring) failed = 1;
        }
    free_others();
    free_meshes();
    return failed;
}

static int test_native_table(void)
{
    return check_backend("native");
}

static int test_fcl_meets_the_contract(void)
{
    return check_backend("fcl");
}

static int test_bullet_meets_the_contract(void)
{
    return check_backend("bullet");
}

// ---- callbacks, sides, Update, empty meshes -----------------------------------------

static dGeomID seen_mesh, seen_other;
static int filter_calls, vetoed = -1;

// The per-triangle callback: vetoes `vetoed` (every triangle if -2).
static int veto(dGeomID mesh, dGeomID other, int tri)
{
    seen_mesh = mesh;
    seen_other = other;
    filter_calls++;
    return vetoed != -2 && tri != vetoed;
}

static int array_calls;

static void array_cb(dGeomID mesh, dGeomID other, const int *tris, int count)
{
    (void)mesh, (void)other, (void)tris, (void)count;
    array_calls++;
}

static int merge_cb(dGeomID mesh, int a, int b)
{
    (void)mesh, (void)b;
    return a;
}

// Distance from p to triangle t of mesh g (world), sampled on its plane
// through barycentric clamping: the exact closest point is not needed, a
// contact on the triangle gives 0.
static double distance_to_triangle(dGeomID g, int t, const dReal p[3])
{
    dVector3 v[3];
    dGeomTriMeshGetTriangle(g, t, &v[0], &v[1], &v[2]);
    double best = INFINITY;
    for (int i = 0; i <= 200; i++)
        for (int j = 0; i + j <= 200; j++) {
            double u = i / 200.0, w = j / 200.0, d2 = 0;
            for (int k = 0; k < 3; k++) {
                double q = (1 - u - w) * v[0][k] + u * v[1][k] + w * v[2][k] - p[k];
                d2 += q * q;
            }
            best = fmin(best, sqrt(d2));
        }
    return best;
}

// Both orders give the same contacts, the mesh's side the triangle.
static int same_contacts(const dContactGeom *a, int na, const dContactGeom *b, int nb)
{
    if (na != nb) return 0;
    for (int i = 0; i < na; i++) {
        if (a[i].depth != b[i].depth || a[i].side1 != b[i].side1 || a[i].side2 != b[i].side2)
            return 0;
        for (int k = 0; k < 3; k++)
            if (a[i].pos[k] != b[i].pos[k] || a[i].normal[k] != b[i].normal[k]) return 0;
    }
    return 1;
}

static int check_callbacks(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    test_mesh m;
    mesh_grid(&m, 8, 2, NULL);   // cells of 0.5
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL), s = dCreateSphere(0, 0.4);
    // Near a vertex of the grid: several triangles touch.
    dGeomSetPosition(s, 0.02, 0.03, 0.35);
    dContactGeom c[MAXC], r[MAXC], want[MAXC];
    dCollisionSetBackend(backend);
    CHECK(backend_answers(backend, g, s));
    dCollisionSetBackend(backend);
    int n = dCollide(g, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 2);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.05, TOL(1e-6, 1e-4));
    // side1 names a triangle the contact lies on; reversed, side2 does.
    int m2 = dCollide(s, g, MAXC, r, sizeof r[0]);
    CHECK(m2 == n);
    for (int i = 0; i < n; i++) {
        CHECK(c[i].side1 >= 0 && c[i].side1 < m.nt && c[i].side2 == -1);
        CHECK(r[i].side2 == c[i].side1 && r[i].side1 == -1);
        CHECK(distance_to_triangle(g, c[i].side1, c[i].pos) < 0.012);   // the sampling's step
    }
    // The per-triangle callback: its arguments, vetoing one triangle, all.
    int deep = c[deepest(c, n)].side1;
    dGeomTriMeshSetCallback(g, veto);
    vetoed = deep;
    filter_calls = 0;
    int nv = dCollide(g, s, MAXC, c, sizeof c[0]);
    CHECK(filter_calls > 0 && seen_mesh == g && seen_other == s);
    CHECK(nv >= 1 && nv < n);
    for (int i = 0; i < nv; i++) CHECK(c[i].side1 != deep);
    nv = dCollide(s, g, MAXC, c, sizeof c[0]);
    for (int i = 0; i < nv; i++) CHECK(c[i].side2 != deep);
    vetoed = -2;
    CHECK(dCollide(g, s, MAXC, c, sizeof c[0]) == 0);
    CHECK(dCollide(s, g, MAXC, c, sizeof c[0]) == 0);
    dGeomTriMeshSetCallback(g, NULL);
    // An array callback, a merge callback, a merge setting: native answers
    // (its contacts exactly), which is said once per reason.
    for (int reason = 0; reason < 3; reason++) {
        if (reason == 0) dGeomTriMeshSetArrayCallback(g, array_cb);
        if (reason == 1) dGeomTriMeshSetTriMergeCallback(g, merge_cb);
        int value = reason == 2 ? dGeomColliderMergeContactsValue_Normals
                                : dGeomColliderMergeContactsValue_None;
        int size = sizeof value;
        dGeomLowLevelControl(g, dGeomColliderControlClass,
                             dGeomColliderSetMergeSphereContactsControlCode, &value, &size);
        dCollisionSetBackend("native");
        array_calls = 0;
        int nw = dCollide(g, s, MAXC, want, sizeof want[0]);
        CHECK(reason != 0 || array_calls == 1);
        dCollisionSetBackend(backend);
        test_capture_reports();
        array_calls = 0;
        int got = dCollide(g, s, MAXC, c, sizeof c[0]);
        CHECK(reason != 0 || array_calls == 1);
        CHECK(same_contacts(c, got, want, nw));
        dCollide(s, g, MAXC, c, sizeof c[0]);
        static const char *const why[3] = { "array callback", "merge callback", "merge setting" };
        CHECK(test_captured_count() == 1 && test_captured_contains(why[reason]));
        test_release_reports();
        // Strict mode makes it an error.
        test_capture_reports();
        dCollisionSetStrict(1);
        CHECK(dCollide(g, s, MAXC, c, sizeof c[0]) == 0);
        dCollisionSetStrict(0);
        CHECK(test_captured_contains("cannot collide") && test_captured_contains(why[reason]));
        test_release_reports();
        dGeomTriMeshSetArrayCallback(g, NULL);
        dGeomTriMeshSetTriMergeCallback(g, NULL);
        value = dGeomColliderMergeContactsValue__Default;
        dGeomLowLevelControl(g, dGeomColliderControlClass,
                             dGeomColliderSetMergeSphereContactsControlCode, &value, &size);
    }
    dCollisionSetBackend("native");
    dGeomDestroy(s);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

static int test_fcl_callbacks(void)
{
    return check_callbacks("fcl");
}

static int test_bullet_callbacks(void)
{
    return check_callbacks("bullet");
}

// Update after moving the vertices, SetData to other data, two geoms on one
// data, a mesh without data or triangles: the adapter's model follows.
static int check_data_changes(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    test_mesh a, b;
    mesh_grid(&a, 8, 2, NULL);
    mesh_grid(&b, 8, 2, NULL);
    for (int i = 0; i < b.nv; i++) b.v[i][2] = 0.2;   // b: 0.2 higher
    dGeomTriMeshDataUpdate(b.data);
    dGeomID g1 = dCreateTriMesh(0, a.data, NULL, NULL, NULL);
    dGeomID g2 = dCreateTriMesh(0, a.data, NULL, NULL, NULL);
    dGeomSetPosition(g2, 10, 0, 0);
    dGeomID s = dCreateSphere(0, 0.4);
    dContactGeom c[MAXC];
    const double tol = TOL(1e-6, 1e-4);
    dCollisionSetBackend(backend);
    dGeomSetPosition(s, 0.1, 0.2, 0.35);
    int n = dCollide(g1, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.05, tol);
    dGeomSetPosition(s, 10.1, 0.2, 0.35);
    n = dCollide(g2, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.05, tol);
    // The vertices move up 0.1: both geoms see it.
    for (int i = 0; i < a.nv; i++) a.v[i][2] = 0.1;
    dGeomTriMeshDataUpdate(a.data);
    n = dCollide(g2, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.15, tol);
    dGeomSetPosition(s, 0.1, 0.2, 0.35);
    n = dCollide(g1, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.15, tol);
    // g1 onto b (0.2 high), g2 stays on a.
    dGeomTriMeshSetData(g1, b.data);
    n = dCollide(g1, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.25, tol);
    dGeomSetPosition(s, 10.1, 0.2, 0.35);
    n = dCollide(g2, s, MAXC, c, sizeof c[0]);
    CHECK(n >= 1);
    CHECK_NEAR(c[deepest(c, n)].depth, 0.15, tol);
    // A rebuild with no triangles, and a mesh without data: no contact.
    test_capture_reports();   // (the build warns of the empty mesh)
    dGeomTriMeshDataBuildDouble(a.data, a.v, 3 * sizeof(double), a.nv, a.tri, 0,
                                3 * sizeof(dTriIndex));
    CHECK(test_captured_contains("no triangles"));
    test_release_reports();
    CHECK(dCollide(g2, s, MAXC, c, sizeof c[0]) == 0);
    dGeomID none = dCreateTriMesh(0, NULL, NULL, NULL, NULL);
    CHECK(dCollide(none, s, MAXC, c, sizeof c[0]) == 0);
    dCollisionSetBackend("native");
    dGeomDestroy(none);
    dGeomDestroy(s);
    dGeomDestroy(g1);
    dGeomDestroy(g2);
    mesh_free(&a);
    mesh_free(&b);
    return 0;
}

static int test_fcl_data_changes(void)
{
    return check_data_changes("fcl");
}

static int test_bullet_data_changes(void)
{
    return check_data_changes("bullet");
}

// Triangles are one-sided under every backend, as native's: a ball behind
// the sheet, or sunk past its centre into the terrain, has no contact (FCL
// and Bullet would face each triangle towards its centre and push it
// through); in front, it has.
static int check_one_sided(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    test_mesh sheet, grid;
    mesh_sheet(&sheet, 1.5);
    mesh_grid(&grid, 8, 2, NULL);
    dGeomID gs = dCreateTriMesh(0, sheet.data, NULL, NULL, NULL);
    dGeomID gg = dCreateTriMesh(0, grid.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.35);
    dContactGeom c[MAXC];
    const dReal z[3] = { -0.2, -0.05, 0.3 };   // behind, past the centre, in front
    for (int k = 0; k < 3; k++) {
        dGeomSetPosition(s, 0.1, 0.2, z[k]);
        for (int m = 0; m < 2; m++) {
            dGeomID g = m ? gg : gs;
            dCollisionSetBackend("native");
            int nn = dCollide(g, s, MAXC, c, sizeof c[0]);
            dCollisionSetBackend(backend);
            int nb = dCollide(g, s, MAXC, c, sizeof c[0]), nr = dCollide(s, g, MAXC, c, sizeof c[0]);
            CHECK(nb == nr);
            CHECK((nb > 0) == (k == 2) && (nn > 0) == (k == 2));
        }
    }
    dCollisionSetBackend("native");
    dGeomDestroy(s);
    dGeomDestroy(gs);
    dGeomDestroy(gg);
    mesh_free(&sheet);
    mesh_free(&grid);
    return 0;
}

static int test_fcl_one_sided(void)
{
    return check_one_sided("fcl");
}

static int test_bullet_one_sided(void)
{
    return check_one_sided("bullet");
}

// ---- resting on a grid mesh ----------------------------------------------------------

typedef struct rest_scene {
    dWorldID world;
    dJointGroupID contacts;
    dGeomID mesh, ball, box;
} rest_scene;

static void near_cb(void *data, dGeomID a, dGeomID b)
{
    rest_scene *sc = (rest_scene *)data;
    dContact c[8];
    int n = dCollide(a, b, 8, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = dContactSoftERP | dContactSoftCFM;
        c[i].surface.mu = 1;
        c[i].surface.soft_erp = 0.2;
        c[i].surface.soft_cfm = 1e-5;
        dJointAttach(dJointCreateContact(sc->world, sc->contacts, &c[i]), dGeomGetBody(a),
                     dGeomGetBody(b));
    }
}

// A ball (r 0.3) and a box (0.5 x 0.4 x 0.3) dropped on a flat grid mesh
// (cells of 0.5) under the backend: their heights after 2 s, and the
// largest speed left.
static void rest(const char *backend, const test_mesh *m, double z[2], double *speed)
{
    rest_scene sc;
    dCollisionSetBackend(backend);
    sc.world = dWorldCreate();
    dWorldSetGravity(sc.world, 0, 0, -9.81);
    sc.contacts = dJointGroupCreate(0);
    dSpaceID space = dHashSpaceCreate(0);
    sc.mesh = dCreateTriMesh(space, m->data, NULL, NULL, NULL);
    sc.ball = dCreateSphere(space, 0.3);
    sc.box = dCreateBox(space, 0.5, 0.4, 0.3);
    dGeomID geoms[2] = { sc.ball, sc.box };
    const dReal at[2][3] = { { 0.13, -0.27, 0.6 }, { 1.1, 0.6, 0.5 } };
    for (int i = 0; i < 2; i++) {
        dBodyID body = dBodyCreate(sc.world);
        dMass mass;
        if (i == 0) dMassSetSphereTotal(&mass, 1, 0.3);
        else dMassSetBoxTotal(&mass, 1, 0.5, 0.4, 0.3);
        dBodySetMass(body, &mass);
        dGeomSetBody(geoms[i], body);
        dBodySetPosition(body, at[i][0], at[i][1], at[i][2]);
    }
    for (int step = 0; step < 200; step++) {
        dSpaceCollide(space, &sc, near_cb);
        dWorldQuickStep(sc.world, 0.01);
        dJointGroupEmpty(sc.contacts);
    }
    *speed = 0;
    for (int i = 0; i < 2; i++) {
        dBodyID body = dGeomGetBody(geoms[i]);
        z[i] = dBodyGetPosition(body)[2];
        const dReal *v = dBodyGetLinearVel(body);
        *speed = fmax(*speed, sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    dJointGroupDestroy(sc.contacts);
    dSpaceDestroy(space);   // (destroys the geoms)
    dWorldDestroy(sc.world);
    dCollisionSetBackend("native");
}

// Resting heights within 1 mm of native's (the ball rests on the backend's
// contacts, the box on native's), both at rest.
static int check_resting(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    test_mesh m;
    mesh_grid(&m, 16, 4, NULL);
    double zn[2], zb[2], vn, vb;
    rest("native", &m, zn, &vn);
    test_capture_reports();   // (box-trimesh: native, said once)
    rest(backend, &m, zb, &vb);
    test_release_reports();
    printf("# %s: ball at %.6f (native %.6f), box at %.6f (native %.6f), speeds %.2g %.2g\n",
           backend, zb[0], zn[0], zb[1], zn[1], vb, vn);
    CHECK_NEAR(zn[0], 0.3, 0.002);
    CHECK_NEAR(zn[1], 0.15, 0.002);
    CHECK_NEAR(zb[0], zn[0], 0.001);
    CHECK_NEAR(zb[1], zn[1], 0.001);
    CHECK(vb < 0.01 && vn < 0.01);
    mesh_free(&m);
    return 0;
}

static int test_fcl_resting(void)
{
    return check_resting("fcl");
}

static int test_bullet_resting(void)
{
    return check_resting("bullet");
}

const test_case test_cases[] = {
    TEST_CASE(test_native_table),
    TEST_CASE(test_fcl_meets_the_contract),
    TEST_CASE(test_bullet_meets_the_contract),
    TEST_CASE(test_fcl_callbacks),
    TEST_CASE(test_bullet_callbacks),
    TEST_CASE(test_fcl_data_changes),
    TEST_CASE(test_bullet_data_changes),
    TEST_CASE(test_fcl_one_sided),
    TEST_CASE(test_bullet_one_sided),
    TEST_CASE(test_fcl_resting),
    TEST_CASE(test_bullet_resting),
    TEST_END
};
