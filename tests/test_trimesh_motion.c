// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_motion.c -- objects moving on a flat area of many triangles
// behave as on a plane (no internal-edge bumps): a ball rolling and a box
// sliding diagonally across a grid mesh keep their vertical speed under
// 1 mm/s, every contact normal within 1 degree of the face normal, and
// follow the same path as on a plane; a mesh body comes to rest on a plane
// and on meshes.

#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>

static dWorldID world;
static dJointGroupID contacts;
static dReal max_tilt;   // largest angle of a contact normal from vertical

static dReal friction;

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
        dJointID j = dJointCreateContact(world, contacts, &c[i]);
        dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
}

typedef struct path {
    dReal pos[3];
    dReal max_vz;
} path;

// Run `steps` steps of a body with geom `shape` (created here by make) on
// either the grid mesh or a plane; the body starts at height z with
// velocity (vx, vy) and spin (wx, wy).
static void run(int on_mesh, dGeomID (*make)(dSpaceID), dReal z, dReal vx, dReal vy, dReal wx,
                dReal wy, int steps, path *out)
{
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    contacts = dJointGroupCreate(0);
    dSpaceID space = dHashSpaceCreate(0);
    test_mesh m = { 0 };
    if (on_mesh) {
        mesh_grid(&m, 48, 6, NULL);   // 4608 triangles of 0.25 m
        dCreateTriMesh(space, m.data, NULL, NULL, NULL);
    } else {
        dCreatePlane(space, 0, 0, 1, 0);
    }
    dBodyID body = dBodyCreate(world);
    dGeomID g = make(space);
    dGeomSetBody(g, body);
    dMass mass;
    if (dGeomGetClass(g) == dSphereClass) dMassSetSphere(&mass, 1, dGeomSphereGetRadius(g));
    else {
        dVector3 s;
        dGeomBoxGetLengths(g, s);
        dMassSetBox(&mass, 1, s[0], s[1], s[2]);
    }
    dBodySetMass(body, &mass);
    dBodySetPosition(body, -4, -2, z);
    dBodySetLinearVel(body, vx, vy, 0);
    dBodySetAngularVel(body, wx, wy, 0);
    out->max_vz = 0;
    for (int s = 0; s < steps; s++) {
        dSpaceCollide(space, NULL, near_cb);
        dWorldStep(world, 0.01);
        dJointGroupEmpty(contacts);
        dReal vz = fabs(dBodyGetLinearVel(body)[2]);
        if (s >= 20 && vz > out->max_vz) out->max_vz = vz;   // after settling
    }
    dCopyVector3(out->pos, dBodyGetPosition(body));
    dSpaceDestroy(space);
    dJointGroupDestroy(contacts);
    dWorldDestroy(world);
    mesh_free(&m);
}

static dGeomID make_ball(dSpaceID s)
{
    return dCreateSphere(s, 0.3);
}

static dGeomID make_box(dSpaceID s)
{
    return dCreateBox(s, 0.6, 0.4, 0.3);
}

static int test_ball_rolls_as_on_plane(void)
{
    path mesh, plane;
    friction = dInfinity;
    max_tilt = 0;
    // Rolling without slipping: w = v / r about the axis across the motion.
    run(1, make_ball, 0.3, 3, 1.5, -1.5 / 0.3, 3 / 0.3, 250, &mesh);
    CHECK(max_tilt < M_PI / 180);
    run(0, make_ball, 0.3, 3, 1.5, -1.5 / 0.3, 3 / 0.3, 250, &plane);
    CHECK(mesh.max_vz < 1e-3);
    CHECK(mesh.pos[0] > 2);   // it crossed many triangles
    CHECK_VEC(mesh.pos, plane.pos[0], plane.pos[1], plane.pos[2], TOL(1e-6, 1e-3));
    return 0;
}

static int test_box_slides_as_on_plane(void)
{
    path mesh, plane;
    friction = 0.02;   // a force limit per contact (no dContactApprox1)
    max_tilt = 0;
    run(1, make_box, 0.15, 4, 2, 0, 0, 250, &mesh);
    CHECK(max_tilt < M_PI / 180);
    run(0, make_box, 0.15, 4, 2, 0, 0, 250, &plane);
    CHECK(mesh.max_vz < 1e-3);
    CHECK(mesh.pos[0] > 0);   // it slid over 4 m
    CHECK_VEC(mesh.pos, plane.pos[0], plane.pos[1], plane.pos[2], TOL(1e-6, 1e-3));
    return 0;
}

// A closed box mesh (1 x 0.8 x 0.6, mass from dMassSetTrimesh) dropped
// tilted onto a floor: on a plane, a grid mesh and a closed box mesh it
// comes to rest flat on a face, its centre half that face's height up.
static int test_mesh_body_settles(void)
{
    for (int floor_kind = 0; floor_kind < 3; floor_kind++) {
        world = dWorldCreate();
        dWorldSetGravity(world, 0, 0, -9.81);
        contacts = dJointGroupCreate(0);
        dSpaceID space = dHashSpaceCreate(0);
        test_mesh fl = { 0 }, m;
        if (floor_kind == 0) {
            dCreatePlane(space, 0, 0, 1, 0);
        } else if (floor_kind == 1) {
            mesh_grid(&fl, 16, 5, NULL);
            dCreateTriMesh(space, fl.data, NULL, NULL, NULL);
        } else {
            mesh_box(&fl, 10, 10, 1, 8);
            dGeomSetPosition(dCreateTriMesh(space, fl.data, NULL, NULL, NULL), 0, 0, -0.5);
        }
        mesh_box(&m, 1, 0.8, 0.6, 2);
        dGeomID g = dCreateTriMesh(space, m.data, NULL, NULL, NULL);
        dBodyID b = dBodyCreate(world);
        dGeomSetBody(g, b);
        dMass mass;
        dMassSetTrimesh(&mass, 1, g);
        CHECK_NEAR(mass.mass, 0.48, TOL(1e-9, 1e-5));
        dBodySetMass(b, &mass);
        dBodySetPosition(b, 0.3, 0.2, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0.5, 0.2, 0.4);
        dBodySetRotation(b, R);
        friction = 0.8;
        for (int s = 0; s < 600; s++) {
            dSpaceCollide(space, NULL, near_cb);
            dWorldQuickStep(world, 0.01);
            dJointGroupEmpty(contacts);
        }
        // Resting on a face: one body axis vertical, the centre its half side up.
        const dReal *p = dBodyGetPosition(b), *Rb = dBodyGetRotation(b);
        const double half[3] = { 0.5, 0.4, 0.3 };
        int k = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(Rb[8 + i]) > fabs(Rb[8 + k])) k = i;
        CHECK(fabs(Rb[8 + k]) > 0.999);
        CHECK_NEAR(p[2], half[k], 2e-3);
        CHECK(dCalcVectorLength3(dBodyGetLinearVel(b)) < 1e-2);
        dSpaceDestroy(space);
        dJointGroupDestroy(contacts);
        dWorldDestroy(world);
        mesh_free(&m);
        mesh_free(&fl);
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_ball_rolls_as_on_plane),
    TEST_CASE(test_box_slides_as_on_plane),
    TEST_CASE(test_mesh_body_settles),
    TEST_END,
};
