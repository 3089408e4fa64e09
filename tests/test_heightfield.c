// SPDX-License-Identifier: BSD-3-Clause
//
// test_heightfield.c -- heightfields (ODE 0.16): contacts equal to those of
// a triangle mesh of the same surface; a flat field behaves as a plane for
// rolling, sliding and resting bodies; every build form, the copy flag,
// bounds, wrap, thickness (the solid below), non-placeable fields, both
// argument orders and bad input.

#include "test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

// The test surface: 17 x 13 samples over 8 x 6 (cells 0.5 x 0.5).
enum { NX = 17, NZ = 13 };
#define WIDTH 8.0
#define DEPTH 6.0

static double surface(double x, double z)
{
    return 0.4 * sin(1.3 * x) * cos(0.9 * z) + 0.1 * x;
}

static double heights[NX * NZ];

static void fill_heights(void)
{
    for (int z = 0; z < NZ; z++)
        for (int x = 0; x < NX; x++)
            heights[x + z * NX] =
                surface(x * WIDTH / (NX - 1) - WIDTH / 2, z * DEPTH / (NZ - 1) - DEPTH / 2);
}

// The same surface as a trimesh in the heightfield's frame: the same
// vertices and diagonals (from (x + 1, z) to (x, z + 1)), facing +Y.
static double mesh_v[NX * NZ][3];
static dTriIndex mesh_t[2 * (NX - 1) * (NZ - 1)][3];

static dTriMeshDataID make_mesh_data(void)
{
    for (int z = 0; z < NZ; z++)
        for (int x = 0; x < NX; x++) {
            double *v = mesh_v[x + z * NX];
            v[0] = x * WIDTH / (NX - 1) - WIDTH / 2;
            v[1] = heights[x + z * NX];
            v[2] = z * DEPTH / (NZ - 1) - DEPTH / 2;
        }
    int t = 0;
    for (int z = 0; z + 1 < NZ; z++)
        for (int x = 0; x + 1 < NX; x++) {
            dTriIndex a = (dTriIndex)(x + z * NX), b = a + 1, c = a + NX, d = c + 1;
            mesh_t[t][0] = a, mesh_t[t][1] = c, mesh_t[t][2] = b, t++;
            mesh_t[t][0] = d, mesh_t[t][1] = b, mesh_t[t][2] = c, t++;
        }
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(data, mesh_v, sizeof mesh_v[0], NX * NZ, mesh_t, 3 * t,
                                sizeof mesh_t[0]);
    return data;
}

static dHeightfieldDataID make_field(int wrap, double thickness)
{
    fill_heights();
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, heights, 0, WIDTH, DEPTH, NX, NZ, 1, 0, thickness, wrap);
    return d;
}

static double urand(double lo, double hi)
{
    return lo + (hi - lo) * (rand() / (double)RAND_MAX);
}

static void random_rotation(dMatrix3 R)
{
    // One draw a statement: the order in which a call's arguments are
    // evaluated is unspecified (gcc's is right to left, clang's left to
    // right), and the poses must not depend on the compiler.
    double ax = urand(-1, 1), ay = urand(-1, 1), az = urand(-1, 1) + 0.01;
    dRFromAxisAndAngle(R, ax, ay, az, urand(-M_PI, M_PI));
}

// Whether every contact of a has one of b at the same point with the same
// normal and depth (within tol).
static int contacts_match(const dContactGeom *a, int na, const dContactGeom *b, int nb,
                          double tol)
{
    for (int i = 0; i < na; i++) {
        int found = 0;
        for (int j = 0; j < nb && !found; j++) {
            double dp = 0, dn = 0;
            for (int k = 0; k < 3; k++) {
                dp += fabs(a[i].pos[k] - b[j].pos[k]);
                dn += fabs(a[i].normal[k] - b[j].normal[k]);
            }
            found = dp < tol && dn < tol && fabs(a[i].depth - b[j].depth) < tol;
        }
        if (!found) return 0;
    }
    return 1;
}

// A random solid of class k (0 sphere, 1 box, 2 capsule, 3 cylinder) with
// its centre above the surface near a random point of the field (both
// geoms posed at P, R).
static dGeomID random_solid(int k, const dReal *P, const dReal *R)
{
    dGeomID g;
    double size, lx, ly, lz, len;
    // One draw a statement (see random_rotation).
    switch (k) {
    case 0: g = dCreateSphere(0, size = urand(0.1, 0.8)); break;
    case 1:
        lx = urand(0.2, 1.5), ly = urand(0.2, 1.5), lz = urand(0.2, 1.5);
        g = dCreateBox(0, lx, ly, lz);
        size = 0.5;
        break;
    case 2:
        size = urand(0.1, 0.5), len = urand(0.2, 1.5);
        g = dCreateCapsule(0, size, len);
        break;
    default:
        size = urand(0.1, 0.6), len = urand(0.2, 1.2);
        g = dCreateCylinder(0, size, len);
        break;
    }
    double x = urand(-3, 3), z = urand(-2.2, 2.2);
    // Centre above the triangulated surface (which lies up to 0.02 below
    // the curved one): a centre under it is the buried case, which a
    // one-sided trimesh does not have.
    double local[3] = { x, surface(x, z) + 0.03 + urand(0, 1) * size, z }, w[3];
    for (int i = 0; i < 3; i++)
        w[i] = P[i] + R[4 * i] * local[0] + R[4 * i + 1] * local[1] + R[4 * i + 2] * local[2];
    dGeomSetPosition(g, w[0], w[1], w[2]);
    dMatrix3 Rg;
    random_rotation(Rg);
    dGeomSetRotation(g, Rg);
    return g;
}

static int test_contacts_match_a_trimesh_of_the_surface(void)
{
    dHeightfieldDataID hd = make_field(0, 0);
    dTriMeshDataID md = make_mesh_data();
    dGeomID hf = dCreateHeightfield(0, hd, 1), mesh = dCreateTriMesh(0, md, NULL, NULL, NULL);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0.3, 1, -0.4, 0.7);
    const dReal P[3] = { 1, -2, 0.5 };
    dGeomSetPosition(hf, P[0], P[1], P[2]);
    dGeomSetPosition(mesh, P[0], P[1], P[2]);
    dGeomSetRotation(hf, R);
    dGeomSetRotation(mesh, R);
    srand(7);
    int touching[4] = { 0 }, differing = 0;
    for (int i = 0; i < 800; i++) {
        int k = i % 4;
        dGeomID g = random_solid(k, P, R);
        // Room for every contact: the pick among more than the maximum
        // depends on the triangles' order, which differs.
        static dContactGeom a[512], b[512];
        int na = dCollide(hf, g, 512, a, sizeof a[0]);
        int nb = dCollide(mesh, g, 512, b, sizeof b[0]);
        CHECK(na < 512);
        // In single precision near-duplicates are merged in the order the
        // triangles come, which differs: about 1 pose in 80 differs there.
        // A sphere's contacts on the mesh are not merged (ODE's default
        // there): the same set, with repeats.
        if ((k != 0 && na != nb) || !contacts_match(a, na, b, nb, TOL(1e-9, 2e-4)) ||
            !contacts_match(b, nb, a, na, TOL(1e-9, 2e-4)))
            differing++;
        for (int j = 0; j < na; j++) {
            CHECK(a[j].g1 == hf && a[j].g2 == g);
            CHECK(a[j].side1 == -1);
        }
        touching[k] += na > 0;
        dGeomDestroy(g);
    }
    printf("# differing %d\n", differing);
    CHECK(differing <= TOL(0, 16));
    for (int k = 0; k < 4; k++) CHECK(touching[k] > 40);   // the pairs did touch
    dGeomDestroy(hf);
    dGeomDestroy(mesh);
    dGeomHeightfieldDataDestroy(hd);
    dGeomTriMeshDataDestroy(md);
    return 0;
}

static int test_both_argument_orders_mirror(void)
{
    dHeightfieldDataID hd = make_field(0, 0);
    dGeomID hf = dCreateHeightfield(0, hd, 1);
    const dReal P[3] = { 0, 0, 0 };
    dMatrix3 I;
    dRSetIdentity(I);
    srand(11);
    for (int i = 0; i < 200; i++) {
        dGeomID g = random_solid(i % 4, P, I);
        dContactGeom a[16], b[16];
        int na = dCollide(hf, g, 16, a, sizeof a[0]);
        int nb = dCollide(g, hf, 16, b, sizeof b[0]);
        CHECK(na == nb);
        for (int j = 0; j < na && j < nb; j++) {
            CHECK(b[j].g1 == g && b[j].g2 == hf);
            CHECK_VEC(b[j].normal, -a[j].normal[0], -a[j].normal[1], -a[j].normal[2], 0);
            CHECK(b[j].depth == a[j].depth);
        }
        dGeomDestroy(g);
    }
    // A ray straight down: the hit on the surface, the normal facing the ray
    // when it is g1 (BACKENDS.md), negated when it is g2.
    dGeomID ray = dCreateRay(0, 10);
    dGeomRaySet(ray, 0.7, 5, -0.3, 0, -1, 0);
    dContactGeom a, b;
    CHECK(dCollide(ray, hf, 1, &a, sizeof a) == 1 && dCollide(hf, ray, 1, &b, sizeof b) == 1);
    CHECK_NEAR(a.pos[1], 5 - a.depth, TOL(1e-12, 1e-5));
    CHECK(a.normal[1] > 0.5 && a.g1 == ray && b.g1 == hf);
    CHECK_VEC(b.normal, -a.normal[0], -a.normal[1], -a.normal[2], 0);
    CHECK_VEC(b.pos, a.pos[0], a.pos[1], a.pos[2], 0);
    dGeomDestroy(ray);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(hd);
    return 0;
}

// ---- a flat field behaves as a plane ------------------------------------------

static dWorldID world;
static dJointGroupID group;
static dReal max_tilt, friction;

static void near_cb(void *data, dGeomID a, dGeomID b)
{
    (void)data;
    dContact c[16];
    int n = dCollide(a, b, 16, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        dReal up = fabs(c[i].geom.normal[2]);
        dReal tilt = acos(up > 1 ? 1 : up);
        if (tilt > max_tilt) max_tilt = tilt;
        c[i].surface.mode = dContactSoftERP | dContactSoftCFM;
        c[i].surface.mu = friction;
        c[i].surface.soft_erp = 0.2;
        c[i].surface.soft_cfm = 1e-6;
        dJointID j = dJointCreateContact(world, group, &c[i]);
        dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
}

// A flat field (heights 0, 97 x 49 samples over 24 x 12: cells of 0.25 m)
// turned so that its Y is the world's Z.
static unsigned char flat[97 * 49];

static dGeomID make_flat_field(dSpaceID space, dHeightfieldDataID *d)
{
    memset(flat, 0, sizeof flat);
    *d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildByte(*d, flat, 0, 24, 12, 97, 49, 1, 0, 1, 0);
    dGeomID g = dCreateHeightfield(space, *d, 1);
    // A quarter turn about X, exactly (in single precision a computed one
    // tilts the field by 4e-8 rad, a slope the plane does not have).
    const dMatrix3 R = { 1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0 };
    dGeomSetRotation(g, R);
    return g;
}

typedef struct path {
    dReal pos[3], max_vz;
} path;

static void run(int on_field, int ball, dReal z, dReal vx, dReal vy, dReal wx, dReal wy,
                int steps, path *out)
{
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    group = dJointGroupCreate(0);
    dSpaceID space = dHashSpaceCreate(0);
    dHeightfieldDataID d = NULL;
    if (on_field) make_flat_field(space, &d);
    else dCreatePlane(space, 0, 0, 1, 0);
    dBodyID body = dBodyCreate(world);
    dGeomID g = ball ? dCreateSphere(space, 0.3) : dCreateBox(space, 0.6, 0.4, 0.3);
    dGeomSetBody(g, body);
    dMass mass;
    if (ball) dMassSetSphere(&mass, 1, 0.3);
    else dMassSetBox(&mass, 1, 0.6, 0.4, 0.3);
    dBodySetMass(body, &mass);
    dBodySetPosition(body, -4, -2, z);
    dBodySetLinearVel(body, vx, vy, 0);
    dBodySetAngularVel(body, wx, wy, 0);
    out->max_vz = 0;
    for (int s = 0; s < steps; s++) {
        dSpaceCollide(space, NULL, near_cb);
        dWorldStep(world, 0.01);
        dJointGroupEmpty(group);
        dReal vz = fabs(dBodyGetLinearVel(body)[2]);
        if (s >= 20 && vz > out->max_vz) out->max_vz = vz;   // after settling
    }
    dCopyVector3(out->pos, dBodyGetPosition(body));
    dSpaceDestroy(space);
    if (d) dGeomHeightfieldDataDestroy(d);
    dJointGroupDestroy(group);
    dWorldDestroy(world);
}

static int test_ball_rolls_as_on_plane(void)
{
    path field, plane;
    friction = dInfinity;
    max_tilt = 0;
    run(1, 1, 0.3, 3, 1.5, -1.5 / 0.3, 3 / 0.3, 250, &field);
    CHECK(max_tilt < M_PI / 180);
    run(0, 1, 0.3, 3, 1.5, -1.5 / 0.3, 3 / 0.3, 250, &plane);
    CHECK(field.max_vz < 1e-3);
    CHECK(field.pos[0] > 2);   // it crossed many cells
    CHECK_VEC(field.pos, plane.pos[0], plane.pos[1], plane.pos[2], TOL(1e-6, 1e-3));
    return 0;
}

static int test_box_slides_as_on_plane(void)
{
    path field, plane;
    friction = 0.02;
    max_tilt = 0;
    run(1, 0, 0.15, 4, 2, 0, 0, 250, &field);
    CHECK(max_tilt < M_PI / 180);
    run(0, 0, 0.15, 4, 2, 0, 0, 250, &plane);
    CHECK(field.max_vz < 1e-3);
    CHECK(field.pos[0] > 0);
    CHECK_VEC(field.pos, plane.pos[0], plane.pos[1], plane.pos[2], TOL(1e-6, 1e-3));
    return 0;
}

static int test_resting_box_gets_four_contacts(void)
{
    dHeightfieldDataID d;
    dGeomID hf = make_flat_field(0, &d);
    dGeomID box = dCreateBox(0, 0.6, 0.4, 0.3);
    dGeomSetPosition(box, 0.37, 0.11, 0.149);   // 1 mm into the field, across cell lines
    dContactGeom c[16];
    int n = dCollide(hf, box, 16, c, sizeof c[0]);
    CHECK(n == 4);
    for (int i = 0; i < n; i++) {
        CHECK_NEAR(c[i].depth, 1e-3, TOL(1e-9, 1e-5));
        CHECK_VEC(c[i].normal, 0, 0, -1, TOL(1e-9, 1e-6));
        CHECK(fabs(fabs(c[i].pos[0] - 0.37) - 0.3) < TOL(1e-9, 1e-5));
        CHECK(fabs(fabs(c[i].pos[1] - 0.11) - 0.2) < TOL(1e-9, 1e-5));
    }
    dGeomDestroy(box);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

// A closed box mesh (full sides 0.8 x 0.5 x 0.6, 12 triangles wound outwards).
static double box_v[8][3];
static dTriIndex box_i[12][3] = { { 0, 2, 3 }, { 0, 3, 1 }, { 4, 5, 7 }, { 4, 7, 6 },
                                  { 0, 1, 5 }, { 0, 5, 4 }, { 2, 6, 7 }, { 2, 7, 3 },
                                  { 0, 4, 6 }, { 0, 6, 2 }, { 1, 3, 7 }, { 1, 7, 5 } };

// Heightfield-trimesh: a closed box mesh lying flat 1 mm deep in a flat
// field gets its four bottom corners, straight up, 1 mm deep, at any place
// and yaw; turned at random near a curved field, both orders mirror and
// every contact is as deep as the box's corner below the surface at most.
static int test_trimesh_rests_on_a_flat_field_and_orders_mirror(void)
{
    for (int v = 0; v < 8; v++) {
        box_v[v][0] = v & 1 ? 0.4 : -0.4;
        box_v[v][1] = v & 2 ? 0.25 : -0.25;
        box_v[v][2] = v & 4 ? 0.3 : -0.3;
    }
    dTriMeshDataID bd = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(bd, box_v, sizeof box_v[0], 8, box_i, 36, sizeof box_i[0]);
    dGeomID box = dCreateTriMesh(0, bd, NULL, NULL, NULL);
    dHeightfieldDataID fd;
    dGeomID flat_hf = make_flat_field(0, &fd);   // its Y is the world's Z
    srand(13);
    static dContactGeom a[64], r[64];
    for (int i = 0; i < 20; i++) {
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 0, 1, urand(0, M_PI));
        dGeomSetRotation(box, R);
        double x = urand(-5, 5), y = urand(-3, 3);   // one draw a statement
        dGeomSetPosition(box, x, y, 0.3 - 1e-3);
        int n = dCollide(flat_hf, box, 64, a, sizeof a[0]);
        CHECK(n == 4);
        for (int j = 0; j < n; j++) {
            CHECK_NEAR(a[j].depth, 1e-3, TOL(1e-9, 1e-5));
            CHECK_VEC(a[j].normal, 0, 0, -1, TOL(1e-9, 1e-6));
            CHECK(a[j].g1 == flat_hf && a[j].g2 == box);
        }
    }
    dHeightfieldDataID hd = make_field(0, 0);
    dGeomID hf = dCreateHeightfield(0, hd, 1);
    const dReal P[3] = { 0, 0, 0 };
    dMatrix3 I;
    dRSetIdentity(I);
    int touching = 0;
    for (int i = 0; i < 100; i++) {
        dGeomID g = random_solid(1, P, I);   // a pose near the surface
        const dReal *p = dGeomGetPosition(g);
        dGeomSetPosition(box, p[0], p[1], p[2]);
        dGeomSetRotation(box, dGeomGetRotation(g));
        dGeomDestroy(g);
        int na = dCollide(hf, box, 64, a, sizeof a[0]);
        int nr = dCollide(box, hf, 64, r, sizeof r[0]);
        CHECK(nr == na);
        for (int j = 0; j < nr; j++) {
            CHECK(r[j].g1 == box && r[j].g2 == hf && a[j].depth >= 0 && a[j].depth < 0.75);
            CHECK_VEC(r[j].normal, -a[j].normal[0], -a[j].normal[1], -a[j].normal[2], 0);
        }
        touching += na > 0;
    }
    CHECK(touching > 20);
    dGeomDestroy(box);
    dGeomDestroy(hf);
    dGeomDestroy(flat_hf);
    dGeomHeightfieldDataDestroy(hd);
    dGeomHeightfieldDataDestroy(fd);
    dGeomTriMeshDataDestroy(bd);
    return 0;
}

// ---- data: build forms, copy, bounds, wrap, thickness -------------------------------

// The height the field shows at local (x, z): a ray straight down.
static double field_height(dGeomID hf, double x, double z)
{
    dGeomID ray = dCreateRay(0, 100);
    dGeomRaySet(ray, x, 50, z, 0, -1, 0);
    dContactGeom c;
    int n = dCollide(ray, hf, 1, &c, sizeof c);
    dGeomDestroy(ray);
    return n ? c.pos[1] : NAN;
}

static dReal callback_height(void *user, int x, int z)
{
    CHECK(user == (void *)heights);
    return (dReal)(x + 2 * z);
}

static int test_every_build_form_gives_the_same_surface(void)
{
    // Heights x + 2 z (3 x 4 samples), scale 0.5, offset -1, over 4 x 6.
    unsigned char hb[12];
    short hs[12];
    float hf32[12];
    double hd[12];
    for (int z = 0; z < 4; z++)
        for (int x = 0; x < 3; x++) {
            int v = x + 2 * z;
            hb[x + 3 * z] = (unsigned char)v;
            hs[x + 3 * z] = (short)v;
            hf32[x + 3 * z] = (float)v;
            hd[x + 3 * z] = v;
        }
    for (int form = 0; form < 5; form++) {
        dHeightfieldDataID d = dGeomHeightfieldDataCreate();
        switch (form) {
        case 0: dGeomHeightfieldDataBuildByte(d, hb, 0, 4, 6, 3, 4, 0.5, -1, 0, 0); break;
        case 1: dGeomHeightfieldDataBuildShort(d, hs, 1, 4, 6, 3, 4, 0.5, -1, 0, 0); break;
        case 2: dGeomHeightfieldDataBuildSingle(d, hf32, 0, 4, 6, 3, 4, 0.5, -1, 0, 0); break;
        case 3: dGeomHeightfieldDataBuildDouble(d, hd, 1, 4, 6, 3, 4, 0.5, -1, 0, 0); break;
        default:
            dGeomHeightfieldDataBuildCallback(d, heights, callback_height, 4, 6, 3, 4, 0.5, -1,
                                              0, 0);
        }
        dGeomID g = dCreateHeightfield(0, d, 1);
        CHECK(dGeomGetClass(g) == dHeightfieldClass);
        CHECK(dGeomHeightfieldGetHeightfieldData(g) == d);
        // Sample (x, z) at X = 2 x - 2, Z = 2 z - 3; the surface is planar:
        // h = 0.5 (x + 2 z) - 1 = 0.25 X + 0.5 Z + 1.
        for (double X = -1.7; X < 2; X += 0.55)
            for (double Z = -2.6; Z < 3; Z += 0.7)
                CHECK_NEAR(field_height(g, X, Z), 0.25 * X + 0.5 * Z + 1, TOL(1e-9, 1e-4));
        dGeomDestroy(g);
        dGeomHeightfieldDataDestroy(d);
    }
    return 0;
}

static int test_copy_flag_decides_whether_heights_are_read_in_place(void)
{
    double h[4] = { 1, 1, 1, 1 };
    dHeightfieldDataID in_place = dGeomHeightfieldDataCreate();
    dHeightfieldDataID copied = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(in_place, h, 0, 2, 2, 2, 2, 1, 0, 0, 0);
    dGeomHeightfieldDataBuildDouble(copied, h, 1, 2, 2, 2, 2, 1, 0, 0, 0);
    dGeomID a = dCreateHeightfield(0, in_place, 1), b = dCreateHeightfield(0, copied, 1);
    for (int i = 0; i < 4; i++) h[i] = 3;
    CHECK_NEAR(field_height(a, 0.1, 0.2), 3, TOL(1e-12, 1e-5));
    CHECK_NEAR(field_height(b, 0.1, 0.2), 1, TOL(1e-12, 1e-5));
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomHeightfieldDataDestroy(in_place);
    dGeomHeightfieldDataDestroy(copied);
    return 0;
}

static int test_bounds_make_the_bounding_box(void)
{
    short h[6] = { -2, 0, 5, 1, 3, 4 };
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildShort(d, h, 0, 4, 2, 3, 2, 0.5, 1, 0.25, 0);
    dGeomID g = dCreateHeightfield(0, d, 1);
    dGeomSetPosition(g, 10, 20, 30);
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    // Heights -2..5 scaled by 0.5 plus 1: 0..3.5, thickness 0.25 below.
    CHECK_NEAR(aabb[0], 8, 1e-6);
    CHECK_NEAR(aabb[1], 12, 1e-6);
    CHECK_NEAR(aabb[2], 20 - 0.25, 1e-6);
    CHECK_NEAR(aabb[3], 23.5, 1e-6);
    CHECK_NEAR(aabb[4], 29, 1e-6);
    CHECK_NEAR(aabb[5], 31, 1e-6);
    // A callback field is unbounded in height until its bounds are set.
    dGeomHeightfieldDataBuildCallback(d, heights, callback_height, 4, 2, 3, 2, 0.5, 1, 0.25, 0);
    dGeomHeightfieldSetHeightfieldData(g, d);
    dGeomGetAABB(g, aabb);
    CHECK(isinf(aabb[2]) && aabb[2] < 0 && isinf(aabb[3]) && aabb[3] > 0);
    dGeomHeightfieldDataSetBounds(d, 0, 4);
    dGeomHeightfieldSetHeightfieldData(g, d);
    dGeomGetAABB(g, aabb);
    CHECK_NEAR(aabb[2], 20 + 1 - 0.25, 1e-6);
    CHECK_NEAR(aabb[3], 20 + 3, 1e-6);
    dGeomDestroy(g);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

static int test_wrapped_field_repeats(void)
{
    dHeightfieldDataID wd = make_field(1, 0), fd = make_field(0, 0);
    dGeomID wrapped = dCreateHeightfield(0, wd, 1), finite = dCreateHeightfield(0, fd, 1);
    dGeomID ball = dCreateSphere(0, 0.4);
    srand(3);
    for (int i = 0; i < 50; i++) {
        // Away from the finite field's border cells (and their ring), and
        // from the last samples, which the wrapped field replaces by the
        // first ones (the period is width samples - 1).
        double x = urand(-2.5, 2.5), z = urand(-1.5, 1.5);
        double y = field_height(finite, x, z) + urand(0.1, 0.35);
        int kx = (int)urand(-3, 3), kz = (int)urand(-3, 3);
        if (i == 0 && sizeof(dReal) == sizeof(double)) kx = 5000;   // 40 km away
        dContactGeom a[8], b[8];
        dGeomSetPosition(ball, x, y, z);
        int na = dCollide(finite, ball, 8, a, sizeof a[0]);
        dGeomSetPosition(ball, x + kx * WIDTH, y, z + kz * DEPTH);
        int nb = dCollide(wrapped, ball, 8, b, sizeof b[0]);
        CHECK(na >= 1 && na == nb);
        for (int j = 0; j < nb; j++) {
            b[j].pos[0] -= kx * WIDTH;
            b[j].pos[2] -= kz * DEPTH;
        }
        CHECK(contacts_match(a, na, b, nb, TOL(1e-9, 1e-4)));
        // The finite field has nothing out there.
        CHECK(dCollide(finite, ball, 8, a, sizeof a[0]) == 0 || (kx == 0 && kz == 0));
    }
    dGeomDestroy(ball);
    dGeomDestroy(wrapped);
    dGeomDestroy(finite);
    dGeomHeightfieldDataDestroy(wd);
    dGeomHeightfieldDataDestroy(fd);
    return 0;
}

// A capsule lying along X over cells [x0, x0 + n) of row 0 of a field of
// 4 m cells (its box 0.5 m inside the cells' ends), its lowest point at y.
static void lay_capsule(dGeomID capsule, double x0, int n, double y)
{
    const double r = 1.5, length = 4.0 * n - 1 - 2 * r;
    dGeomCapsuleSetParams(capsule, r, length);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);
    dGeomSetRotation(capsule, R);
    dGeomSetPosition(capsule, x0 * 4 - 8 + 0.5 + (length + 2 * r) / 2, y + r, 2);
}

// A query takes at most 65536 cells (2^16): a geom whose box covers more
// gets no contacts, reported once per heightfield (a 10^6 m capsule on a
// wrapping field once built 1.2 million triangles for one dCollide).
static int test_a_geom_over_too_many_cells_is_refused_and_reported_once(void)
{
    static double flat[5 * 5];
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, flat, 0, 16, 16, 5, 5, 1, 0, 1, 1);   // wraps
    dGeomHeightfieldDataSetBounds(d, -1, 1);   // a geom up to 1 m above is a query
    dGeomID hf = dCreateHeightfield(0, d, 1), hf2 = dCreateHeightfield(0, d, 1);
    dGeomID capsule = dCreateCapsule(0, 1, 1);
    dContactGeom c[8];
    test_capture_reports();

    // 10^6 m long, resting on the surface, far out along the wrap.
    dGeomCapsuleSetParams(capsule, 1.5, 1e6);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);
    dGeomSetRotation(capsule, R);
    dGeomSetPosition(capsule, 3e5, 1.4, 2);
    CHECK(dCollide(hf, capsule, 8, c, sizeof c[0]) == 0);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("a capsule covers more than 65536 cells of a heightfield"));
    CHECK(dCollide(capsule, hf, 8, c, sizeof c[0]) == 0);
    CHECK(test_captured_count() == 1);   // once per heightfield ...
    CHECK(dCollide(hf2, capsule, 8, c, sizeof c[0]) == 0);
    CHECK(test_captured_count() == 2);   // ... each

    // The bound is exact: 65536 cells taken (no contacts: the capsule is
    // above the surface, inside the bounds), 65537 refused.
    test_release_reports();
    test_capture_reports();
    dGeomID hf3 = dCreateHeightfield(0, d, 1);
    lay_capsule(capsule, 1000, 65536, 0.5);
    CHECK(dCollide(hf3, capsule, 8, c, sizeof c[0]) == 0);
    CHECK(test_captured_count() == 0);
    lay_capsule(capsule, 1000, 65537, 0.5);
    CHECK(dCollide(hf3, capsule, 8, c, sizeof c[0]) == 0);
    CHECK(test_captured_count() == 1);
    test_release_reports();
    test_capture_reports();

    // A capsule of 10 cells resting on the field still gets its contacts.
    lay_capsule(capsule, 1000, 10, -0.1);
    int n = dCollide(hf, capsule, 8, c, sizeof c[0]);
    CHECK(n >= 2);
    for (int i = 0; i < n; i++) CHECK_NEAR(c[i].depth, 0.1, TOL(1e-9, 1e-3));
    CHECK(test_captured_count() == 0);
    test_release_reports();
    dGeomDestroy(capsule);
    dGeomDestroy(hf);
    dGeomDestroy(hf2);
    dGeomDestroy(hf3);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

// Below the surface is solid: a ball whose centre is under it is pushed up
// along the normal of the triangle under it (down to the lowest height
// minus the thickness; below that, nothing).
static int test_solid_below_the_surface(void)
{
    dHeightfieldDataID d = make_field(0, 2);
    dGeomID hf = dCreateHeightfield(0, d, 0);   // not placeable: the world frame
    dGeomID ball = dCreateSphere(0, 0.2);
    double x = 0.3, z = -0.4, h = field_height(hf, x, z);
    dGeomSetPosition(ball, x, h - 1, z);
    dContactGeom c[4];
    int n = dCollide(hf, ball, 4, c, sizeof c[0]);
    CHECK(n == 1);
    CHECK(c[0].normal[1] < -0.8);   // into the field: the ball leaves upwards
    // Depth: the distance to the triangle's plane plus the radius.
    dReal nrm[3] = { -c[0].normal[0], -c[0].normal[1], -c[0].normal[2] };
    CHECK_NEAR(c[0].depth, nrm[1] * 1 + 0.2, TOL(1e-9, 1e-4));
    double lowest = heights[0];
    for (int i = 0; i < NX * NZ; i++) lowest = fmin(lowest, heights[i]);
    dGeomSetPosition(ball, x, lowest - 2 - 0.5, z);
    CHECK(dCollide(hf, ball, 4, c, sizeof c[0]) == 0);
    dGeomDestroy(ball);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

static int test_placeable_and_non_placeable_agree_at_the_identity(void)
{
    dHeightfieldDataID d = make_field(0, 0);
    dGeomID a = dCreateHeightfield(0, d, 0), b = dCreateHeightfield(0, d, 1);
    const dReal P[3] = { 0, 0, 0 };
    dMatrix3 I;
    dRSetIdentity(I);
    srand(5);
    for (int i = 0; i < 100; i++) {
        dGeomID g = random_solid(i % 4, P, I);
        dContactGeom ca[16], cb[16];
        int na = dCollide(a, g, 16, ca, sizeof ca[0]), nb = dCollide(b, g, 16, cb, sizeof cb[0]);
        CHECK(na == nb);
        CHECK(contacts_match(ca, na, cb, nb, 1e-12));
        dGeomDestroy(g);
    }
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

static int test_warm_collisions_allocate_nothing(void)
{
    dHeightfieldDataID d = make_field(0, 0);
    dGeomID hf = dCreateHeightfield(0, d, 1);
    dGeomID box = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(box, 0, surface(0, 0) + 0.3, 0);
    dContactGeom c[16];
    for (int pass = 0; pass < 2; pass++) {   // the first warms the scratch arrays
        if (pass == 1) test_count_allocations();
        for (int i = 0; i < 10; i++) {
            dGeomSetPosition(box, 0.1 * i, surface(0.1 * i, 0) + 0.3, 0);
            CHECK(dCollide(hf, box, 16, c, sizeof c[0]) > 0);
        }
    }
    CHECK(test_allocations_counted() == 0);
    dGeomDestroy(box);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
    return 0;
}

// ---- bad input ----------------------------------------------------------------

static int test_bad_input_is_reported(void)
{
    test_capture_reports();
    double h[6] = { 0, 1, 2, 3, 4, 5 };
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();

    dGeomHeightfieldDataBuildDouble(d, h, 0, 1, 1, 1, 6, 1, 0, 0, 0);
    CHECK(test_captured_contains("dGeomHeightfieldDataBuildDouble"));
    CHECK(test_captured_contains("widthSamples"));
    dGeomHeightfieldDataBuildDouble(d, h, 0, 1, 1, 6, 0, 1, 0, 0, 0);
    dGeomHeightfieldDataBuildDouble(d, NULL, 0, 1, 1, 2, 3, 1, 0, 0, 0);
    CHECK(test_captured_contains("pHeightData is NULL"));
    dGeomHeightfieldDataBuildDouble(d, h, 0, -1, 1, 2, 3, 1, 0, 0, 0);
    CHECK(test_captured_contains("width and depth"));
    dGeomHeightfieldDataBuildDouble(d, h, 0, 1, 1, 2, 3, 1, 0, -0.5, 0);
    CHECK(test_captured_contains("thickness"));
    h[4] = NAN;
    dGeomHeightfieldDataBuildDouble(d, h, 0, 1, 1, 2, 3, 1, 0, 0, 0);
    CHECK(test_captured_contains("height 4 (x 0, z 2) is not finite"));
    dGeomHeightfieldDataBuildCallback(d, NULL, NULL, 1, 1, 2, 3, 1, 0, 0, 0);
    CHECK(test_captured_contains("pCallback is NULL"));
    dGeomHeightfieldDataBuildSingle(NULL, NULL, 0, 1, 1, 2, 3, 1, 0, 0, 0);
    CHECK(test_captured_contains("heightfield data is NULL"));
    dGeomHeightfieldDataSetBounds(d, 2, 1);
    CHECK(test_captured_contains("minHeight is above maxHeight"));
    int reports = test_captured_count();
    CHECK(reports == 9);

    // Never built: no contacts, no crash.
    dGeomID g = dCreateHeightfield(0, d, 1), ball = dCreateSphere(0, 1);
    dContactGeom c[4];
    CHECK(dCollide(g, ball, 4, c, sizeof c[0]) == 0);
    dGeomID empty = dCreateHeightfield(0, NULL, 1);
    CHECK(dCollide(empty, ball, 4, c, sizeof c[0]) == 0);
    CHECK(dGeomHeightfieldGetHeightfieldData(empty) == NULL);

    CHECK(dGeomHeightfieldGetHeightfieldData(ball) == NULL);
    CHECK(test_captured_contains("not a heightfield"));
    dGeomHeightfieldSetHeightfieldData(ball, d);

    // Data destroyed while a geom uses it lives until the geom goes, and
    // takes no new geoms.
    dGeomDestroy(empty);
    dGeomHeightfieldDataDestroy(d);
    CHECK(dGeomHeightfieldGetHeightfieldData(g) == d);
    CHECK(dCreateHeightfield(0, d, 1) == NULL);
    CHECK(test_captured_contains("was destroyed"));
    dGeomDestroy(g);
    dGeomDestroy(ball);
    test_release_reports();
    return 0;
}

static dReal nan_height(void *user, int x, int z)
{
    (void)user;
    return x == 1 && z == 1 ? NAN : 0;
}

static int test_non_finite_callback_height_is_reported(void)
{
    test_capture_reports();
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildCallback(d, NULL, nan_height, 4, 4, 5, 5, 1, 0, 0, 0);
    dGeomID g = dCreateHeightfield(0, d, 1), ball = dCreateSphere(0, 0.5);
    dGeomSetPosition(ball, -1, 0.3, -1);
    dContactGeom c[4];
    CHECK(dCollide(g, ball, 4, c, sizeof c[0]) == 0);
    CHECK(test_captured_contains("sample (1, 1) is not finite"));
    dGeomSetPosition(ball, 1.5, 0.3, 1.5);   // far from the bad sample
    CHECK(dCollide(g, ball, 4, c, sizeof c[0]) == 1);
    dGeomDestroy(ball);
    dGeomDestroy(g);
    dGeomHeightfieldDataDestroy(d);
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_contacts_match_a_trimesh_of_the_surface),
    TEST_CASE(test_both_argument_orders_mirror),
    TEST_CASE(test_ball_rolls_as_on_plane),
    TEST_CASE(test_box_slides_as_on_plane),
    TEST_CASE(test_resting_box_gets_four_contacts),
    TEST_CASE(test_trimesh_rests_on_a_flat_field_and_orders_mirror),
    TEST_CASE(test_every_build_form_gives_the_same_surface),
    TEST_CASE(test_copy_flag_decides_whether_heights_are_read_in_place),
    TEST_CASE(test_bounds_make_the_bounding_box),
    TEST_CASE(test_wrapped_field_repeats),
    TEST_CASE(test_a_geom_over_too_many_cells_is_refused_and_reported_once),
    TEST_CASE(test_solid_below_the_surface),
    TEST_CASE(test_placeable_and_non_placeable_agree_at_the_identity),
    TEST_CASE(test_warm_collisions_allocate_nothing),
    TEST_CASE(test_bad_input_is_reported),
    TEST_CASE(test_non_finite_callback_height_is_reported),
    TEST_END,
};
