// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_collide.c -- the native trimesh colliders through dCollide,
// on meshes generated here (grid terrain, icosphere, closed box, torus,
// thin sheet): hand-worked poses (depth, normal, position), every pair both
// ways with each contact checked against the solids' own signed distances,
// rays with the barycentric callback, the plane, trimesh-trimesh (with the
// last transforms), the per-triangle, array and merge callbacks, the other
// backends' fallback, and no per-query allocation once warm.

#include "collide_check.h"
#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <string.h>

enum { MAXC = 64 };
#define EPS TOL(1e-9, 2e-4)

static const dReal DOWN[3] = { 0, 0, -1 };

// dCollide(a, b) and the checks every contact must pass: count within max,
// g1 = a, g2 = b, the trimesh's side a triangle index (or -1), the other's
// -1, finite values, unit normal, depth >= 0; and dCollide(b, a) gives the
// same contacts flipped. Returns the count, -1 after a failure.
static int collide_both(dGeomID a, dGeomID b, int max, dContactGeom *c)
{
    int n = dCollide(a, b, max, c, sizeof *c);
    dContactGeom r[MAXC];
    int m = dCollide(b, a, max, r, sizeof *r);
#define REQUIRE(cond) \
    do { \
        if (!(cond)) { \
            test_fail(__FILE__, __LINE__, "REQUIRE(%s), contact %d of %d", #cond, i, n); \
            return -1; \
        } \
    } while (0)
    int i = -1;
    REQUIRE(n >= 0 && n <= max && m == n);
    for (i = 0; i < n; i++) {
        const dContactGeom *k = &c[i];
        REQUIRE(k->g1 == a && k->g2 == b);
        int ta = dGeomGetClass(a) == dTriMeshClass ? dGeomTriMeshGetTriangleCount(a) : 0;
        int tb = dGeomGetClass(b) == dTriMeshClass ? dGeomTriMeshGetTriangleCount(b) : 0;
        REQUIRE(k->side1 >= -1 && k->side1 < ta && (ta > 0 || k->side1 == -1));
        REQUIRE(k->side2 >= -1 && k->side2 < tb && (tb > 0 || k->side2 == -1));
        REQUIRE(isfinite(k->depth) && k->depth >= 0);
        REQUIRE(fabs(dCalcVectorLength3(k->normal) - 1) < EPS);
        REQUIRE(r[i].g1 == b && r[i].g2 == a && r[i].side1 == k->side2 &&
                r[i].side2 == k->side1 && r[i].depth == k->depth);
        for (int j = 0; j < 3; j++) REQUIRE(r[i].pos[j] == k->pos[j] && r[i].normal[j] == -k->normal[j]);
    }
#undef REQUIRE
    return n;
}

static double flat(double x, double y)
{
    (void)x;
    (void)y;
    return 0;
}

static double wavy(double x, double y)
{
    return 0.3 * sin(1.3 * x) * cos(0.9 * y);
}

// ---- hand-worked poses on a flat grid ----------------------------------------

// A ball anywhere over a flat area of many triangles (over faces, edges,
// vertices) meets one plane: one contact, straight down, depth r - z.
static int test_sphere_on_flat_grid(void)
{
    test_mesh m;
    mesh_grid(&m, 10, 2, flat);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.3);
    dContactGeom c[MAXC];
    rng_state = 11;
    for (int i = 0; i < 400; i++) {
        // Every 4th pose exactly over a vertex, every 4th over an edge.
        double x = rnd(-1.5, 1.5), y = rnd(-1.5, 1.5), z = rnd(0.05, 0.29);
        if (i % 4 == 0) x = 0.4 * floor(x / 0.4), y = 0.4 * floor(y / 0.4);
        if (i % 4 == 1) x = 0.4 * floor(x / 0.4);
        dGeomSetPosition(s, x, y, z);
        // One contact per triangle touched (ODE's default: not merged),
        // all the same: the plane's.
        int n = collide_both(g, s, 8, c);
        CHECK(n >= 1 && n <= 8);
        for (int j = 0; j < n; j++) {
            CHECK_VEC(c[j].normal, DOWN[0], DOWN[1], DOWN[2], EPS);
            CHECK_NEAR(c[j].depth, 0.3 - z, EPS);
            CHECK_VEC(c[j].pos, x, y, z - 0.3, EPS);
        }
        CHECK(i % 4 != 0 || n == 4 || n == 8);   // the triangles at the vertex
    }
    // Out of reach, and behind the (one-sided) surface.
    dGeomSetPosition(s, 0.1, 0.2, 0.31);
    CHECK(dCollide(g, s, 8, c, sizeof c[0]) == 0);
    dGeomSetPosition(s, 0.1, 0.2, -0.1);
    CHECK(dCollide(g, s, 8, c, sizeof c[0]) == 0);
    // Past the middle of a border edge (x = 2, y in [0, 0.4]), out of reach
    // of its ends: the edge pushes outwards and up.
    dGeomSphereSetRadius(s, 0.15);
    dGeomSetPosition(s, 2.05, 0.2, 0.05);
    CHECK(collide_both(g, s, 8, c) == 1);
    double d = sqrt(0.05 * 0.05 + 0.05 * 0.05);
    CHECK_NEAR(c[0].depth, 0.15 - d, EPS);
    CHECK_VEC(c[0].normal, -0.05 / d, 0, -0.05 / d, EPS);
    dGeomDestroy(s);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// A box lying on a flat grid with any yaw: every contact points straight
// down with the box's sinking as depth, and the four kept are the corners
// of its footprint.
static int test_box_on_flat_grid(void)
{
    test_mesh m;
    mesh_grid(&m, 12, 3, flat);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID b = dCreateBox(0, 0.8, 0.5, 0.4);
    dContactGeom c[MAXC];
    rng_state = 12;
    for (int i = 0; i < 100; i++) {
        double x = rnd(-1.5, 1.5), y = rnd(-1.5, 1.5), yaw = rnd(0, 2 * M_PI), sink = rnd(0.001, 0.05);
        dGeomSetPosition(b, x, y, 0.2 - sink);
        set_rot(b, 0, 0, 1, yaw);
        int n = collide_both(g, b, 4, c);
        CHECK(n == 4);
        for (int k = 0; k < 4; k++) {
            CHECK_VEC(c[k].normal, 0, 0, -1, EPS);
            CHECK_NEAR(c[k].depth, sink, EPS);
        }
        for (int corner = 0; corner < 4; corner++) {
            dVector3 p;
            dGeomBoxGetLengths(b, p);
            dGeomGetRelPointPos(b, (corner & 1 ? 0.4 : -0.4), (corner & 2 ? 0.25 : -0.25), -0.2, p);
            int found = 0;
            for (int k = 0; k < 4; k++)
                if (dCalcPointsDistance3(p, c[k].pos) < 1e4 * EPS) found = 1;
            CHECK(found);
        }
        n = collide_both(g, b, MAXC, c);
        CHECK(n >= 4);
        for (int k = 0; k < n; k++) CHECK_VEC(c[k].normal, 0, 0, -1, EPS);
    }
    // Tilted onto one bottom edge: contacts only along that edge.
    dGeomSetPosition(b, 0.3, 0.2, 0.25);
    set_rot(b, 0, 1, 0, 0.3);
    int n = collide_both(g, b, 8, c);
    CHECK(n >= 2);
    for (int k = 0; k < n; k++) {
        CHECK(point_depth(b, c[k].pos) > -EPS);
        CHECK_NEAR(-c[k].pos[2], c[k].depth, EPS);
    }
    dGeomDestroy(b);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// A capsule lying on a flat grid: two contacts under the end balls; upright,
// one under the lower ball.
static int test_capsule_on_flat_grid(void)
{
    test_mesh m;
    mesh_grid(&m, 9, 2, flat);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID cap = dCreateCapsule(0, 0.2, 1.0);
    dContactGeom c[MAXC];
    rng_state = 13;
    for (int i = 0; i < 100; i++) {
        double x = rnd(-1, 1), y = rnd(-1, 1), yaw = rnd(0, 2 * M_PI), z = rnd(0.1, 0.199);
        dGeomSetPosition(cap, x, y, z);
        dMatrix3 R1, R2, R;
        dRFromAxisAndAngle(R1, 1, 0, 0, M_PI / 2);
        dRFromAxisAndAngle(R2, 0, 0, 1, yaw);
        dMultiply0_333(R, R2, R1);
        dGeomSetRotation(cap, R);
        int n = collide_both(g, cap, 8, c);
        CHECK(n == 2);
        dVector3 ends[2];
        dGeomGetRelPointPos(cap, 0, 0, -0.5, ends[0]);
        dGeomGetRelPointPos(cap, 0, 0, 0.5, ends[1]);
        for (int k = 0; k < 2; k++) {
            CHECK_VEC(c[k].normal, 0, 0, -1, EPS);
            CHECK_NEAR(c[k].depth, 0.2 - z, EPS);
            double dx0 = c[k].pos[0] - ends[0][0], dy0 = c[k].pos[1] - ends[0][1];
            double dx1 = c[k].pos[0] - ends[1][0], dy1 = c[k].pos[1] - ends[1][1];
            CHECK(fmin(dx0 * dx0 + dy0 * dy0, dx1 * dx1 + dy1 * dy1) < 1e4 * EPS);
        }
    }
    dGeomSetRotation(cap, (dReal[12]){ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 });
    dGeomSetPosition(cap, 0.33, -0.21, 0.65);
    int n = collide_both(g, cap, 8, c);
    CHECK(n == 1);
    CHECK_NEAR(c[0].depth, 0.05, EPS);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    dGeomDestroy(cap);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// A cylinder on a flat grid: lying, its lowest line (exact depth) gives
// the two ends; standing, its cap gives points around the rim, spread; tilted,
// the lowest rim point is the deepest, exactly.
static int test_cylinder_on_flat_grid(void)
{
    test_mesh m;
    mesh_grid(&m, 9, 2, flat);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID cyl = dCreateCylinder(0, 0.3, 0.8);
    dContactGeom c[MAXC];
    rng_state = 18;
    for (int i = 0; i < 100; i++) {
        // Sinking less than the prism's next side line rises (5.8 mm).
        double x = rnd(-1, 1), y = rnd(-1, 1), yaw = rnd(0, 2 * M_PI), sink = rnd(0, 0.005);
        dMatrix3 R1, R2, R;
        dRFromAxisAndAngle(R1, 1, 0, 0, M_PI / 2);
        dRFromAxisAndAngle(R2, 0, 0, 1, yaw);
        dMultiply0_333(R, R2, R1);
        dGeomSetRotation(cyl, R);
        dGeomSetPosition(cyl, x, y, 0.3 - sink);
        int n = collide_both(g, cyl, 8, c);
        // The ends of the lowest line, and maybe a shallower point where a
        // mesh vertex meets the prism's neighbouring side.
        CHECK(n >= 2);
        double apart = 0;   // the farthest two at the full depth
        for (int k = 0; k < n; k++) {
            CHECK_VEC(c[k].normal, 0, 0, -1, EPS);
            CHECK(c[k].depth <= sink + EPS);
            for (int j = 0; j < k; j++)
                if (fabs(c[k].depth - sink) < EPS && fabs(c[j].depth - sink) < EPS)
                    apart = fmax(apart, dCalcPointsDistance3(c[k].pos, c[j].pos));
        }
        CHECK_NEAR(apart, 0.8, EPS);
        // Deeper: a band of contacts, the deepest exact.
        dGeomSetPosition(cyl, x, y, 0.3 - 10 * sink);
        n = collide_both(g, cyl, 8, c);
        CHECK(n >= 2);
        CHECK_NEAR(c[deepest(c, n)].depth, 10 * sink, EPS);
        // Standing on its cap.
        dGeomSetRotation(cyl, R2);
        dGeomSetPosition(cyl, x, y, 0.4 - sink);
        n = collide_both(g, cyl, 4, c);
        CHECK(n == 4);
        for (int k = 0; k < 4; k++) {
            CHECK_NEAR(c[k].depth, sink, EPS);
            double dx = c[k].pos[0] - x, dy = c[k].pos[1] - y;
            // On the inscribed 32-gon: within its sagitta of the rim.
            CHECK_NEAR(sqrt(dx * dx + dy * dy), 0.3, 0.3 * (1 - cos(M_PI / 32)) + EPS);
        }
        CHECK(dCalcPointsDistance3(c[0].pos, c[1].pos) > 0.59);   // across the rim
        // Tilted by 0.4 rad about a horizontal axis.
        set_rot(cyl, cos(yaw), sin(yaw), 0, 0.4);
        dGeomSetPosition(cyl, x, y, 0.3);
        n = collide_both(g, cyl, 4, c);
        double lowest = 0.3 - 0.4 * cos(0.4) - 0.3 * sin(0.4);   // the lowest rim point
        CHECK(n >= 1);
        CHECK_NEAR(c[deepest(c, n)].depth, -lowest, EPS);
    }
    dGeomDestroy(cyl);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// ---- every pair, random poses, signed distances --------------------------------

typedef struct solid {
    const char *name;
    test_mesh mesh;
    int kind;                 // 0 terrain (z below height), 1 sphere, 2 box, 3 torus, 4 sheet
    double a, b, c;           // sizes
    double tess;              // how far the mesh may be inside the solid it stands for
} solid;

static double solid_depth(const solid *s, const double p[3])
{
    switch (s->kind) {
    case 0: return wavy(p[0], p[1]) - p[2];   // vertical: >= the distance
    case 1: return sdf_sphere(s->a, p);
    case 2: return sdf_box(s->a, s->b, s->c, p);
    case 3: return sdf_torus(s->a, s->b, p);
    default: return -fabs(p[2]) * 0;   // a sheet: only the plane z = 0 (checked apart)
    }
}

// Contacts of `mesh` (at the origin, identity) and a primitive at random
// poses near its surface: each contact's point lies in the primitive (point
// depth >= -tol) and in the mesh's solid up to the tessellation; on the
// sheet, no farther from its plane than the deepest contact. (A point may
// lie deeper in the primitive than its depth: a triangle sees only the part
// of the primitive over itself.)
static int sweep(solid *s, dGeomID prim, int max)
{
    dGeomID g = dCreateTriMesh(0, s->mesh.data, NULL, NULL, NULL);
    dContactGeom c[MAXC];
    int touching = 0;
    for (int i = 0; i < 300; i++) {
        double p[3];
        for (int k = 0; k < 3; k++) p[k] = rnd(-1.6, 1.6);
        if (s->kind == 0 || s->kind == 4) p[2] = rnd(-0.2, 0.6);
        dGeomSetPosition(prim, p[0], p[1], p[2]);
        set_rot(prim, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) + 0.01, rnd(0, M_PI));
        int n = collide_both(g, prim, max, c);
        if (n < 0) return 1;
        if (n == 0) continue;
        touching++;
        dReal most = c[deepest(c, n)].depth;
        for (int k = 0; k < n; k++) {
            double q[3] = { c[k].pos[0], c[k].pos[1], c[k].pos[2] };
            double dp = point_depth(prim, c[k].pos), dm = solid_depth(s, q);
            if (!(dp > -1e3 * EPS) || !(dm > -s->tess - 1e3 * EPS)) {
                test_fail(__FILE__, __LINE__, "%s vs %s pose %d contact %d: depth in shape %g, in mesh %g, deepest %g",
                          s->name, dGeomGetClass(prim) == dSphereClass ? "sphere" :
                          dGeomGetClass(prim) == dBoxClass ? "box" :
                          dGeomGetClass(prim) == dCapsuleClass ? "capsule" : "cylinder",
                          i, k, dp, dm, (double)most);
                return 1;
            }
            if (s->kind == 4) CHECK(fabs(q[2]) <= most + 1e3 * EPS);
        }
    }
    CHECK(touching > 10);
    dGeomDestroy(g);
    return 0;
}

static int test_every_pair_sdf(void)
{
    solid solids[5] = {
        { "terrain", { 0 }, 0, 0, 0, 0, 0.3 * 0.25 * 0.25 },   // curvature x cell^2 bound
        { "icosphere", { 0 }, 1, 1.2, 0, 0, 1.2 * 0.01 },
        { "box", { 0 }, 2, 2.0, 1.6, 1.2, 0 },
        { "torus", { 0 }, 3, 1.0, 0.4, 0, 0.4 * 0.02 },
        { "sheet", { 0 }, 4, 1.5, 0, 0, 0 },
    };
    mesh_grid(&solids[0].mesh, 16, 2, wavy);
    mesh_icosphere(&solids[1].mesh, 1.2, 3);
    mesh_box(&solids[2].mesh, 2.0, 1.6, 1.2, 2);
    mesh_torus(&solids[3].mesh, 1.0, 0.4, 48, 24);
    mesh_sheet(&solids[4].mesh, 1.5);
    dGeomID prims[4] = { dCreateSphere(0, 0.35), dCreateBox(0, 0.6, 0.4, 0.3),
                         dCreateCapsule(0, 0.2, 0.5), dCreateCylinder(0, 0.25, 0.4) };
    rng_state = 14;
    int fail = 0;
    for (int s = 0; s < 5 && !fail; s++)
        for (int p = 0; p < 4 && !fail; p++) fail = sweep(&solids[s], prims[p], p == 0 ? 4 : 8);
    for (int p = 0; p < 4; p++) dGeomDestroy(prims[p]);
    for (int s = 0; s < 5; s++) mesh_free(&solids[s].mesh);
    return fail;
}

// A small closed box mesh against each mesh at random poses: every contact
// lies on or in the box and in the other mesh's solid (up to its
// tessellation); both orders mirror.
static int test_trimesh_trimesh_sdf(void)
{
    solid solids[4] = {
        { "terrain", { 0 }, 0, 0, 0, 0, 0.3 * 0.25 * 0.25 },
        { "icosphere", { 0 }, 1, 1.2, 0, 0, 1.2 * 0.01 },
        { "box", { 0 }, 2, 2.0, 1.6, 1.2, 0 },
        { "torus", { 0 }, 3, 1.0, 0.4, 0, 0.4 * 0.02 },
    };
    mesh_grid(&solids[0].mesh, 16, 2, wavy);
    mesh_icosphere(&solids[1].mesh, 1.2, 3);
    mesh_box(&solids[2].mesh, 2.0, 1.6, 1.2, 2);
    mesh_torus(&solids[3].mesh, 1.0, 0.4, 48, 24);
    test_mesh small;
    mesh_box(&small, 0.6, 0.4, 0.3, 2);
    dGeomID b = dCreateTriMesh(0, small.data, NULL, NULL, NULL);
    dContactGeom c[MAXC];
    rng_state = 19;
    int fail = 0, touching = 0;
    for (int s = 0; s < 4 && !fail; s++) {
        dGeomID a = dCreateTriMesh(0, solids[s].mesh.data, NULL, NULL, NULL);
        for (int i = 0; i < 200 && !fail; i++) {
            double p[3] = { rnd(-1.6, 1.6), rnd(-1.6, 1.6), rnd(-1.6, 1.6) };
            if (s == 0) p[2] = rnd(-0.2, 0.5);
            dGeomSetPosition(b, p[0], p[1], p[2]);
            set_rot(b, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) + 0.01, rnd(0, M_PI));
            int n = collide_both(a, b, 8, c);
            if (n < 0) fail = 1;
            touching += n > 0;
            for (int k = 0; k < n && !fail; k++) {
                dVector3 local;
                dGeomGetPosRelPoint(b, c[k].pos[0], c[k].pos[1], c[k].pos[2], local);
                double lb[3] = { local[0], local[1], local[2] };
                double q[3] = { c[k].pos[0], c[k].pos[1], c[k].pos[2] };
                double db = sdf_box(0.6, 0.4, 0.3, lb), da = solid_depth(&solids[s], q);
                if (!(db > -1e3 * EPS) || !(da > -solids[s].tess - 1e3 * EPS)) {
                    test_fail(__FILE__, __LINE__, "%s pose %d contact %d: in box %g, in mesh %g",
                              solids[s].name, i, k, db, da);
                    fail = 1;
                }
            }
        }
        dGeomDestroy(a);
    }
    CHECK(fail || touching > 40);
    dGeomDestroy(b);
    mesh_free(&small);
    for (int s = 0; s < 4; s++) mesh_free(&solids[s].mesh);
    return fail;
}

// A ball against the icosphere: the polyhedron's exact penetration (the
// deepest contact separates the pair) and a radial normal within the
// tessellation's angle.
static int test_sphere_icosphere_depth(void)
{
    test_mesh m;
    mesh_icosphere(&m, 1, 3);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID s = dCreateSphere(0, 0.3);
    dContactGeom c[MAXC];
    rng_state = 15;
    for (int i = 0; i < 200; i++) {
        dReal d[3] = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), dist = rnd(1.05, 1.29);
        for (int k = 0; k < 3; k++) d[k] /= len;
        dGeomSetPosition(s, dist * d[0], dist * d[1], dist * d[2]);
        int n = collide_both(s, g, 8, c);
        CHECK(n >= 1);
        const dContactGeom *k = &c[deepest(c, n)];
        CHECK_NEAR(k->depth, 1.3 - dist, 0.01);
        CHECK(dCalcVectorDot3(k->normal, d) > cos(0.15));
        CHECK(depth_after_separation(s, g, k, 1e-6) < 1e3 * EPS);
    }
    dGeomDestroy(s);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// ---- plane, ray --------------------------------------------------------------------

// A closed box mesh through the plane z = 0: its vertices below are the
// contacts, the plane's normal pointing into the mesh.
static int test_plane(void)
{
    test_mesh m;
    mesh_box(&m, 2, 2, 2, 2);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID p = dCreatePlane(0, 0, 0, 1, 0);
    dGeomSetPosition(g, 0.5, 0.5, 0.9);
    dContactGeom c[MAXC];
    int n = collide_both(g, p, MAXC, c);
    CHECK(n == 4);   // of the bottom face's 3 x 3 vertices, the corners
    for (int k = 0; k < n; k++) {
        CHECK_VEC(c[k].normal, 0, 0, 1, EPS);
        CHECK_NEAR(c[k].depth, 0.1, EPS);
        CHECK_NEAR(c[k].pos[2], -0.1, EPS);
    }
    n = collide_both(g, p, 3, c);
    CHECK(n == 3);   // three of them
    for (int k = 0; k < n; k++) {
        CHECK_NEAR(fabs(c[k].pos[0] - 0.5), 1, EPS);
        CHECK_NEAR(fabs(c[k].pos[1] - 0.5), 1, EPS);
    }
    dGeomSetPosition(g, 0, 0, 1.01);
    CHECK(dCollide(g, p, 4, c, sizeof c[0]) == 0);
    dGeomDestroy(p);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

static dGeomID seen_ray;
static int ray_calls;
static dReal seen_u, seen_v;
static int seen_tri;

static int ray_cb(dGeomID mesh, dGeomID ray, int tri, dReal u, dReal v)
{
    (void)mesh;
    seen_ray = ray;
    ray_calls++;
    seen_u = u;
    seen_v = v;
    seen_tri = tri;
    return 1;
}

// Vertical rays onto the wavy terrain: the hit lies on the triangle the
// callback names, at the barycentric point it gives; ray first the normal
// faces the ray (up), mesh first it points into the mesh.
static int test_ray_terrain(void)
{
    test_mesh m;
    mesh_grid(&m, 16, 2, wavy);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, ray_cb);
    CHECK(dGeomTriMeshGetRayCallback(g) == ray_cb);
    dGeomSetPosition(g, 0.1, 0.2, 0.3);
    dGeomID r = dCreateRay(0, 5);
    dContactGeom c[MAXC];
    rng_state = 16;
    for (int i = 0; i < 200; i++) {
        double x = rnd(-1.8, 1.8), y = rnd(-1.8, 1.8);
        dGeomRaySet(r, x + 0.1, y + 0.2, 3, 0, 0, -1);
        ray_calls = 0;
        int n = collide_both(r, g, 4, c);
        CHECK(n == 1 && ray_calls == 2 && seen_ray == r);   // once per order
        CHECK(c[0].side2 == seen_tri);
        dVector3 p;
        dGeomTriMeshGetPoint(g, seen_tri, seen_u, seen_v, p);
        CHECK_VEC(c[0].pos, p[0], p[1], p[2], 1e3 * EPS);
        CHECK_NEAR(c[0].depth, 3 - p[2], 1e3 * EPS);
        CHECK(c[0].normal[2] > 0.5);
        CHECK(fabs(p[2] - 0.3 - wavy(x, y)) < 0.3 * 0.25 * 0.25);   // on the surface
    }
    // Pointing up from below: only backfaces, hit unless culled; the normal
    // is the face's (up) whichever side the ray comes from, as in ODE.
    dGeomRaySet(r, 0.3, 0.3, -2, 0, 0, 1);
    CHECK(dCollide(r, g, 4, c, sizeof c[0]) == 1 && c[0].normal[2] > 0.5);
    dGeomRaySetBackfaceCull(r, 1);
    CHECK(dCollide(r, g, 4, c, sizeof c[0]) == 0);
    dGeomDestroy(r);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// A ray through a closed box mesh crosses two faces: both, nearest first;
// ClosestHit keeps the entry; a short ray only the entry.
static int test_ray_closed_box(void)
{
    test_mesh m;
    mesh_box(&m, 2, 2, 2, 3);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID r = dCreateRay(0, 10);
    dGeomRaySet(r, -5, 0.1, 0.2, 1, 0, 0);
    dContactGeom c[MAXC];
    int n = collide_both(g, r, 8, c);
    CHECK(n == 2);
    CHECK_NEAR(c[0].depth, 4, EPS);
    CHECK_NEAR(c[1].depth, 6, EPS);
    CHECK_VEC(c[0].normal, 1, 0, 0, EPS);   // into the mesh (g1) at the entry
    CHECK_VEC(c[1].normal, -1, 0, 0, EPS);
    CHECK_VEC(c[1].pos, 1, 0.1, 0.2, EPS);
    dGeomRaySetClosestHit(r, 1);
    n = collide_both(g, r, 8, c);
    CHECK(n == 1);
    CHECK_NEAR(c[0].depth, 4, EPS);
    dGeomRaySetClosestHit(r, 0);
    dGeomRaySetLength(r, 5);
    CHECK(collide_both(g, r, 8, c) == 1);
    dGeomRaySetLength(r, 3.9);
    CHECK(dCollide(g, r, 8, c, sizeof c[0]) == 0);
    dGeomDestroy(r);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// ---- trimesh-trimesh ----------------------------------------------------------------

static int veto_all(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    (void)tri;
    return 0;
}

// Two closed boxes, one resting 0.1 into the other's top (turned 0.3 rad):
// contacts straight down at the overlap's depth, in both boxes; mirrored;
// the other mesh's per-triangle callback vetoes.
static int test_trimesh_trimesh_stack(void)
{
    test_mesh ma, mb;
    mesh_box(&ma, 2, 2, 2, 2);
    mesh_box(&mb, 1, 1, 1, 3);
    dGeomID a = dCreateTriMesh(0, ma.data, NULL, NULL, NULL);
    dGeomID b = dCreateTriMesh(0, mb.data, NULL, NULL, NULL);
    dGeomSetPosition(b, 0.2, -0.1, 1.4);
    set_rot(b, 0, 0, 1, 0.3);
    dContactGeom c[MAXC];
    int n = collide_both(a, b, 8, c);
    CHECK(n >= 3);
    for (int k = 0; k < n; k++) {
        CHECK_VEC(c[k].normal, 0, 0, -1, EPS);
        double p[3] = { c[k].pos[0], c[k].pos[1], c[k].pos[2] }, lb[3];
        dVector3 local;
        dGeomGetPosRelPoint(b, p[0], p[1], p[2], local);
        for (int i = 0; i < 3; i++) lb[i] = local[i];
        CHECK(sdf_box(2, 2, 2, p) > -1e3 * EPS && sdf_box(1, 1, 1, lb) > -1e3 * EPS);
    }
    CHECK_NEAR(c[deepest(c, n)].depth, 0.1, 1e3 * EPS);
    // Apart.
    dGeomSetPosition(b, 0.2, -0.1, 1.51);
    CHECK(dCollide(a, b, 8, c, sizeof c[0]) == 0);
    dGeomSetPosition(b, 0.2, -0.1, 1.4);
    dGeomTriMeshSetCallback(b, veto_all);
    CHECK(dCollide(a, b, 8, c, sizeof c[0]) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    mesh_free(&ma);
    mesh_free(&mb);
    return 0;
}

static void set_last_transform_at(dGeomID g, double x, double y, double z)
{
    const dReal *R = dGeomGetRotation(g);
    dMatrix4 T = { R[0], R[4], R[8], 0, R[1], R[5], R[9], 0, R[2], R[6], R[10], 0,
                   (dReal)x, (dReal)y, (dReal)z, 1 };
    dGeomTriMeshSetLastTransform(g, T);
}

// Two single triangles crossing tip to tip: a's (z = 0, up) pokes 0.05
// through b's (x = 0, facing -x) and b's pokes 0.05 down through a's, a tie.
// Without last transforms either face may be taken; with them, the face b
// moved into.
static int test_trimesh_trimesh_last_transform(void)
{
    dReal va[3][4] = { { -2, -1, 0, 0 }, { 0.05, 0, 0, 0 }, { -2, 1, 0, 0 } };
    dReal vb[3][4] = { { 0, -1, 2, 0 }, { 0, 1, 2, 0 }, { 0, 0, -0.05, 0 } };
    dTriIndex idx[3] = { 0, 1, 2 };
    dTriMeshDataID da = dGeomTriMeshDataCreate(), db = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildSimple(da, &va[0][0], 3, idx, 3);
    dGeomTriMeshDataBuildSimple(db, &vb[0][0], 3, idx, 3);
    dGeomID a = dCreateTriMesh(0, da, NULL, NULL, NULL);
    dGeomID b = dCreateTriMesh(0, db, NULL, NULL, NULL);
    dContactGeom c[MAXC];
    int n = collide_both(a, b, 8, c);
    CHECK(n == 1);
    CHECK_NEAR(c[0].depth, 0.05, 1e3 * EPS);
    CHECK(fabs(c[0].normal[2] + 1) < 1e3 * EPS || fabs(c[0].normal[0] + 1) < 1e3 * EPS);
    set_last_transform_at(a, 0, 0, 0);
    set_last_transform_at(b, 0, 0, 0.5);   // b came down
    n = collide_both(a, b, 8, c);
    CHECK(n == 1);
    CHECK_VEC(c[0].normal, 0, 0, -1, 1e3 * EPS);
    set_last_transform_at(b, 0.5, 0, 0);   // b came from +x
    n = collide_both(a, b, 8, c);
    CHECK(n == 1);
    CHECK_VEC(c[0].normal, -1, 0, 0, 1e3 * EPS);
    CHECK_NEAR(c[0].depth, 0.05, 1e3 * EPS);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomTriMeshDataDestroy(da);
    dGeomTriMeshDataDestroy(db);
    return 0;
}

// ---- callbacks -----------------------------------------------------------------------

static int veto_odd(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    return tri % 2 == 0;
}

static int vetoed;

static int veto_one(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    return tri != vetoed;
}

static int array_seen[256], array_count, array_calls;

static void array_cb(dGeomID mesh, dGeomID other, const int *tris, int count)
{
    (void)mesh;
    (void)other;
    array_calls++;
    array_count = count;
    for (int i = 0; i < count && i < 256; i++) array_seen[i] = tris[i];
}

static int merges;

static int merge_cb(dGeomID mesh, int a, int b)
{
    (void)mesh;
    merges++;
    return 1000 + (a < b ? a : b);
}

static int test_callbacks(void)
{
    test_mesh m;
    mesh_grid(&m, 4, 1, flat);
    dGeomID g = dCreateTriMesh(0, m.data, veto_odd, array_cb, NULL);
    CHECK(dGeomTriMeshGetCallback(g) == veto_odd && dGeomTriMeshGetArrayCallback(g) == array_cb);
    dGeomID s = dCreateSphere(0, 0.2);
    dContactGeom c[MAXC];
    // Over the grid's centre vertex (0, 0): the triangles around it touch;
    // the array callback sees the even ones, each with its contact.
    dGeomSetPosition(s, 0, 0, 0.1);
    array_calls = 0;
    int n = dCollide(g, s, 8, c, sizeof c[0]);
    CHECK(n >= 1 && array_calls == 1);
    CHECK(array_count == n);
    for (int i = 0; i < array_count; i++) CHECK(array_seen[i] % 2 == 0);
    for (int i = 0; i < n; i++) CHECK(c[i].side1 % 2 == 0);
    // Without the veto: every triangle around the vertex, and, merging
    // fully, the merge callback names the merged contact.
    dGeomTriMeshSetCallback(g, NULL);
    dGeomTriMeshSetTriMergeCallback(g, merge_cb);
    int full = dGeomColliderMergeContactsValue_Full, size = sizeof full;
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass,
                               dGeomColliderSetMergeSphereContactsControlCode, &full, &size));
    merges = 0;
    n = dCollide(g, s, 8, c, sizeof c[0]);
    CHECK(n == 1 && merges == array_count - 1 && c[0].side1 >= 1000);
    int around = 0;
    for (int t = 0; t < m.nt; t++)
        for (int k = 0; k < 3; k++)
            if (m.v[m.tri[t][k]][0] == 0 && m.v[m.tri[t][k]][1] == 0) around++;
    CHECK(array_count == around);
    // Over the inside of one triangle: vetoing it leaves nothing, and the
    // array callback is not called.
    dGeomTriMeshSetCallback(g, NULL);
    dGeomTriMeshSetTriMergeCallback(g, NULL);
    dGeomSetPosition(s, 0.3, 0.1, 0.195);
    n = dCollide(g, s, 8, c, sizeof c[0]);
    CHECK(n == 1 && c[0].side1 >= 0 && array_count == 1 && array_seen[0] == c[0].side1);
    vetoed = c[0].side1;
    dGeomTriMeshSetCallback(g, veto_one);
    array_calls = 0;
    CHECK(dCollide(g, s, 8, c, sizeof c[0]) == 0 && array_calls == 0);
    dGeomDestroy(s);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

// ---- merging a sphere's contacts (dGeomLowLevelControl) ----------------------------

static int merge_control(dGeomID g, int code, int *value)
{
    int size = sizeof *value;
    return dGeomLowLevelControl(g, dGeomColliderControlClass, code, value, &size);
}

// ODE's own case: a sphere exactly touching the diagonal shared by the two
// triangles of a square gets one contact from each, of depth 0, along the
// face normal (the default: contacts not merged).
static int test_sphere_on_a_shared_edge_touches_both_triangles(void)
{
    static const float v[4][3] = { { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } };
    static const dTriIndex t[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildSingle(d, v, sizeof v[0], 4, t, 6, sizeof t[0]);
    dGeomID g = dCreateTriMesh(0, d, NULL, NULL, NULL), s = dCreateSphere(0, 4);
    dContactGeom c[4];
    const dReal shift[3] = { 10, 30, 40 };

    for (int pass = 0; pass < 2; pass++) {
        const dReal *o = pass ? shift : (const dReal[3]){ 0, 0, 0 };
        dGeomSetPosition(g, o[0], o[1], o[2]);
        dGeomSetPosition(s, o[0], o[1], o[2] + 4);
        int n = dCollide(g, s, 4, c, sizeof c[0]);

        CHECK(n == 2);
        for (int i = 0; i < n; i++) {
            CHECK(c[i].depth == 0);
            CHECK_VEC(c[i].normal, 0, 0, -1, 0);
            CHECK(c[i].side1 == i || c[i].side1 == 1 - i);
        }
        CHECK(n == 2 && c[0].side1 != c[1].side1);
    }
    dGeomDestroy(s);
    dGeomDestroy(g);
    dGeomTriMeshDataDestroy(d);
    return 0;
}

// A ball in a concave V (faces at 45 degrees either side of x = 0) touches
// both faces: each setting as ODE defines it.
static int test_sphere_merge_settings(void)
{
    static const double v[6][3] = { { 0, -2, 0 }, { 0, 2, 0 }, { -1, 0, 1 },
                                    { 0, 2, 0 }, { 0, -2, 0 }, { 1, 0, 1 } };
    static const dTriIndex t[2][3] = { { 0, 1, 2 }, { 3, 4, 5 } };
    dTriMeshDataID d = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(d, v, sizeof v[0], 6, t, 6, sizeof t[0]);
    dGeomID g = dCreateTriMesh(0, d, NULL, NULL, NULL), s = dCreateSphere(0, 0.5);
    dGeomSetPosition(s, 0, 0, 0.6);
    const double h = sqrt(0.5), depth = 0.5 - 0.6 * h;
    dContactGeom c[4];
    int value = -1;

    // Default: not merged, each face's own normal.
    CHECK(merge_control(g, dGeomColliderGetMergeSphereContactsControlCode, &value));
    CHECK(value == dGeomColliderMergeContactsValue_None);
    int n = dCollide(g, s, 4, c, sizeof c[0]);
    CHECK(n == 2);
    for (int i = 0; i < n; i++) {
        double sx = c[i].pos[0] < 0 ? 1 : -1;   // the left face pushes +x
        CHECK_VEC(c[i].normal, -sx * h, 0, -h, EPS);
        CHECK_NEAR(c[i].depth, depth, EPS);
        CHECK_VEC(c[i].pos, -sx * 0.5 * h, 0, 0.6 - 0.5 * h, EPS);   // the ball's deepest
    }
    // Normals: both take the mean normal, depths and points unchanged.
    value = dGeomColliderMergeContactsValue_Normals;
    CHECK(merge_control(g, dGeomColliderSetMergeSphereContactsControlCode, &value));
    n = dCollide(g, s, 4, c, sizeof c[0]);
    CHECK(n == 2);
    for (int i = 0; i < n; i++) {
        CHECK_VEC(c[i].normal, 0, 0, -1, EPS);
        CHECK_NEAR(c[i].depth, depth, EPS);
        CHECK_NEAR(fabs(c[i].pos[0]), 0.5 * h, EPS);
    }
    // Full: one contact at the mean point, deep enough along the mean
    // normal (depth / cos 45); no merge callback: no triangle.
    value = dGeomColliderMergeContactsValue_Full;
    CHECK(merge_control(g, dGeomColliderSetMergeSphereContactsControlCode, &value));
    n = dCollide(g, s, 4, c, sizeof c[0]);
    CHECK(n == 1);
    CHECK_VEC(c[0].normal, 0, 0, -1, EPS);
    CHECK_NEAR(c[0].depth, depth / h, EPS);
    CHECK_VEC(c[0].pos, 0, 0, 0.6 - 0.5 * h, EPS);
    CHECK(c[0].side1 == -1);
    // Unimportant contacts are not merged: the first one alone.
    n = dCollide(g, s, 4 | CONTACTS_UNIMPORTANT, c, sizeof c[0]);
    CHECK(n == 1);
    CHECK_NEAR(fabs(c[0].normal[0]), h, EPS);
    // __Default restores the default.
    value = dGeomColliderMergeContactsValue__Default;
    CHECK(merge_control(g, dGeomColliderSetMergeSphereContactsControlCode, &value));
    CHECK(merge_control(g, dGeomColliderGetMergeSphereContactsControlCode, &value));
    CHECK(value == dGeomColliderMergeContactsValue_None);
    CHECK(dCollide(g, s, 4, c, sizeof c[0]) == 2);
    dGeomDestroy(s);
    dGeomDestroy(g);
    dGeomTriMeshDataDestroy(d);
    return 0;
}

static int test_merge_control_bad_input_is_reported(void)
{
    test_capture_reports();
    test_mesh m;
    mesh_sheet(&m, 1);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    int value = 7, size = 2;

    // A wrong size: refused, the size wanted given back, nothing reported.
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass,
                               dGeomColliderSetMergeSphereContactsControlCode, &value,
                               &size) == 0);
    CHECK(size == (int)sizeof(int) && test_captured_count() == 0);
    CHECK(dGeomLowLevelControl(g, dGeomColliderControlClass, dGeomCommonAnyControlCode, NULL,
                               &(int){ 0 }) == 1);
    // Not a merge value, another class, another code: refused and named.
    CHECK(merge_control(g, dGeomColliderSetMergeSphereContactsControlCode, &value) == 0);
    CHECK(test_captured_contains("7 is not a dGeomColliderMergeContactsValue"));
    CHECK(merge_control(g, dGeomColliderGetMergeSphereContactsControlCode, &value) == 1);
    CHECK(value == dGeomColliderMergeContactsValue_None);
    size = sizeof value;
    CHECK(dGeomLowLevelControl(g, dGeomCommonControlClass,
                               dGeomColliderSetMergeSphereContactsControlCode, &value,
                               &size) == 0);
    CHECK(size == 0 && test_captured_contains("no codes in control class 0"));
    CHECK(merge_control(g, 9, &value) == 0);
    CHECK(test_captured_contains("no control code 9"));
    CHECK(test_captured_count() == 3);
    dGeomDestroy(g);
    mesh_free(&m);
    test_release_reports();
    return 0;
}

// The FCL and Bullet adapters take only trimesh-sphere pairs
// (tests/test_backend_trimesh.c): selected, they leave the others to native
// (the same contacts), saying so once.
static int test_other_backends_fall_back(void)
{
    const char *const *names = dCollisionListBackends();
    int others = 0;
    test_mesh m;
    mesh_grid(&m, 6, 2, wavy);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID prims[2] = { dCreateCapsule(0, 0.4, 0.3), dCreateBox(0, 0.5, 0.6, 0.7) };
    dGeomSetPosition(prims[0], 0.3, 0.2, 0.2);
    dGeomSetPosition(prims[1], -0.4, 0.5, 0.1);
    dContactGeom want[2][MAXC], got[MAXC];
    int nwant[2];
    for (int p = 0; p < 2; p++) nwant[p] = dCollide(g, prims[p], MAXC, want[p], sizeof got[0]);
    for (int i = 0; names[i]; i++) {
        if (strcmp(names[i], "native") == 0) continue;
        others++;
        test_capture_reports();
        CHECK(dCollisionSetBackend(names[i]));
        for (int p = 0; p < 2; p++) {
            CHECK(nwant[p] > 0);
            CHECK(dCollide(g, prims[p], MAXC, got, sizeof got[0]) == nwant[p]);
            for (int k = 0; k < nwant[p]; k++) {
                const dContactGeom *a = &got[k], *b = &want[p][k];
                CHECK(a->depth == b->depth && a->side1 == b->side1 && a->g2 == b->g2);
                for (int j = 0; j < 3; j++)
                    CHECK(a->pos[j] == b->pos[j] && a->normal[j] == b->normal[j]);
            }
        }
        CHECK(test_captured_contains("trimesh"));
        test_release_reports();
        dCollisionSetBackend("native");
    }
    for (int p = 0; p < 2; p++) dGeomDestroy(prims[p]);
    dGeomDestroy(g);
    mesh_free(&m);
    return others ? 0 : test_skip("no other backend built");
}

// Once the scratch has grown, collisions allocate nothing.
static int test_no_allocation_when_warm(void)
{
    test_mesh m;
    mesh_grid(&m, 20, 3, wavy);
    dGeomID g = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    test_mesh small;
    mesh_box(&small, 0.6, 0.5, 0.4, 2);
    dGeomID prims[6] = { dCreateSphere(0, 0.4), dCreateBox(0, 0.7, 0.5, 0.4),
                         dCreateCapsule(0, 0.2, 0.8), dCreateRay(0, 3),
                         dCreateCylinder(0, 0.3, 0.5),
                         dCreateTriMesh(0, small.data, NULL, NULL, NULL) };
    dContactGeom c[MAXC];
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) test_count_allocations();
        rng_state = 17;
        for (int i = 0; i < 100; i++)
            for (int p = 0; p < 6; p++) {
                dGeomSetPosition(prims[p], rnd(-2, 2), rnd(-2, 2), rnd(-0.3, 0.5));
                set_rot(prims[p], rnd(-1, 1), rnd(-1, 1), 1, rnd(0, 3));
                dCollide(g, prims[p], MAXC, c, sizeof c[0]);
            }
    }
    CHECK(test_allocations_counted() == 0);
    for (int p = 0; p < 6; p++) dGeomDestroy(prims[p]);
    mesh_free(&small);
    dGeomDestroy(g);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_sphere_on_flat_grid),
    TEST_CASE(test_box_on_flat_grid),
    TEST_CASE(test_capsule_on_flat_grid),
    TEST_CASE(test_cylinder_on_flat_grid),
    TEST_CASE(test_every_pair_sdf),
    TEST_CASE(test_sphere_icosphere_depth),
    TEST_CASE(test_plane),
    TEST_CASE(test_ray_terrain),
    TEST_CASE(test_ray_closed_box),
    TEST_CASE(test_trimesh_trimesh_stack),
    TEST_CASE(test_trimesh_trimesh_last_transform),
    TEST_CASE(test_trimesh_trimesh_sdf),
    TEST_CASE(test_callbacks),
    TEST_CASE(test_sphere_on_a_shared_edge_touches_both_triangles),
    TEST_CASE(test_sphere_merge_settings),
    TEST_CASE(test_merge_control_bad_input_is_reported),
    TEST_CASE(test_other_backends_fall_back),
    TEST_CASE(test_no_allocation_when_warm),
    TEST_END,
};
