// SPDX-License-Identifier: BSD-3-Clause
//
// terrain.c -- the same bumpy slope twice: on the left a triangle mesh, on
// the right a heightfield (its Y axis turned to world z), with balls,
// capsules and a box rolling and sliding down each. Key d drops a ball on
// each. Checks when the loop ends: finite state, nothing sank into or fell
// through its terrain (each centre above the surface under it), and the
// balls rolled downhill (their mean distance along the slope grew by 0.5 m).

#include "example_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SAMPLES 25          // per side of each patch
#define PATCH 6.0           // m, side of each patch
#define MAX_THINGS 24
#define ROLL_STEPS 180

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[1024];
static long steps;

static const dReal centre_x[2] = { -3.6, 3.6 };   // mesh, heightfield
static float mesh_vertices[SAMPLES * SAMPLES][3];
static dTriIndex mesh_indices[(SAMPLES - 1) * (SAMPLES - 1) * 6];
static dTriMeshDataID mesh_data;
static dHeightfieldDataID field_data;
static dGeomID terrain[2];

static struct thing {
    dBodyID body;
    dGeomID geom;
    int patch;
    dReal start_u;   // along the slope, from the patch centre
} things[MAX_THINGS];
static int thing_count;

// The surface over a patch, at (u, v) from its centre: a slope down to +u with bumps
// (downhill along +u everywhere: d/du <= -0.2 + 0.15).
static dReal height(dReal u, dReal v)
{
    return (dReal)(0.8 - 0.2 * u + 0.1 * sin(1.5 * u) * cos(1.2 * v));
}

static dReal field_sample(void *data, int x, int z)
{
    (void)data;
    const dReal step = PATCH / (SAMPLES - 1);
    // Heightfield frame: sample (x, z) at X, Z; turned so X is world x and Z is world -y.
    return height(x * step - PATCH / 2, -(z * step - PATCH / 2));
}

static void build_terrain(void)
{
    const dReal step = PATCH / (SAMPLES - 1);
    for (int j = 0; j < SAMPLES; j++)
        for (int i = 0; i < SAMPLES; i++) {
            const dReal u = i * step - PATCH / 2, v = j * step - PATCH / 2;
            float *p = mesh_vertices[j * SAMPLES + i];
            p[0] = (float)(centre_x[0] + u);
            p[1] = (float)v;
            p[2] = (float)height(u, v);
        }
    int n = 0;
    for (int j = 0; j + 1 < SAMPLES; j++)
        for (int i = 0; i + 1 < SAMPLES; i++) {   // counter-clockwise from above
            const dTriIndex a = j * SAMPLES + i, b = a + 1, c = a + SAMPLES + 1, d = a + SAMPLES;
            const dTriIndex tri[6] = { a, b, c, a, c, d };
            for (int k = 0; k < 6; k++) mesh_indices[n++] = tri[k];
        }
    mesh_data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildSingle(mesh_data, mesh_vertices, 3 * sizeof(float),
                                SAMPLES * SAMPLES, mesh_indices, n, 3 * sizeof(dTriIndex));
    terrain[0] = dCreateTriMesh(space, mesh_data, NULL, NULL, NULL);

    field_data = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildCallback(field_data, NULL, field_sample, PATCH, PATCH, SAMPLES,
                                      SAMPLES, 1, 0, 1, 0);
    dGeomHeightfieldDataSetBounds(field_data, 0, 1.6);
    terrain[1] = dCreateHeightfield(space, field_data, 1);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, (dReal)M_PI / 2);
    dGeomSetRotation(terrain[1], R);
    dGeomSetPosition(terrain[1], centre_x[1], 0, 0);
}

static void add(int patch, int kind, dReal u, dReal v)
{
    if (thing_count == MAX_THINGS) return;
    struct thing *t = &things[thing_count++];
    dMass m;
    t->body = dBodyCreate(world);
    dReal lift;
    if (kind == 0) {
        t->geom = dCreateSphere(space, 0.2);
        dMassSetSphere(&m, 500, 0.2);
        lift = 0.25;
    } else if (kind == 1) {   // lying across the slope so it rolls down
        t->geom = dCreateCapsule(space, 0.12, 0.6);
        dMassSetCapsule(&m, 500, 3, 0.12, 0.6);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0, 0, (dReal)M_PI / 2);
        dBodySetRotation(t->body, R);
        lift = 0.2;
    } else {
        t->geom = dCreateBox(space, 0.4, 0.4, 0.3);
        dMassSetBox(&m, 500, 0.4, 0.4, 0.3);
        lift = 0.3;
    }
    dBodySetMass(t->body, &m);
    dBodySetPosition(t->body, centre_x[patch] + u, v, height(u, v) + lift);
    dGeomSetBody(t->geom, t->body);
    t->patch = patch;
    t->start_u = u;
}

static void start(void)
{
    static const float xyz[3] = { 0.0f, -10.0f, 5.0f };
    static const float hpr[3] = { 90.0f, -25.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("terrain", "  d: drop a ball on each terrain\n"
             "  left: a triangle mesh; right: a heightfield of the same surface\n");
}

static void command(int key)
{
    if (key == 'd') {
        const dReal v = dRandReal() * 3 - 1.5;
        add(0, 0, -2.5, v);
        add(1, 0, -2.5, v);
    }
}

// The heightfield drawn as its cells' two triangles, split as the geom splits them,
// in one call (the field never moves: its triangles are listed once).
static void draw_field(void)
{
    static const dReal origin[3] = { 0, 0, 0 };
    static const dReal identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    static dReal tri[2 * (SAMPLES - 1) * (SAMPLES - 1)][9];
    static int listed;
    const dReal step = PATCH / (SAMPLES - 1);
    for (int z = 0; !listed && z + 1 < SAMPLES; z++)
        for (int x = 0; x + 1 < SAMPLES; x++) {
            dReal p[4][3];   // samples (x, z), (x + 1, z), (x, z + 1), (x + 1, z + 1)
            for (int k = 0; k < 4; k++) {
                const int sx = x + (k & 1), sz = z + (k >> 1);
                p[k][0] = centre_x[1] + sx * step - PATCH / 2;
                p[k][1] = -(sz * step - PATCH / 2);
                p[k][2] = field_sample(NULL, sx, sz);
            }
            static const int corners[2][3] = { { 0, 2, 1 }, { 1, 2, 3 } };
            for (int t = 0; t < 2; t++)
                for (int k = 0; k < 3; k++)
                    memcpy(&tri[2 * (z * (SAMPLES - 1) + x) + t][3 * k], p[corners[t][k]],
                           sizeof p[0]);
        }
    listed = 1;
    dsDrawTriangles(origin, identity, &tri[0][0], 2 * (SAMPLES - 1) * (SAMPLES - 1), 1);
}

static void step(int pause)
{
    if (!pause) {
        exu_collide(&contacts, space);
        dWorldQuickStep(world, EXU_DT);
        steps++;
    }
    dsSetTexture(DS_GROUND);
    dsSetColor(0.45f, 0.7f, 0.4f);
    exu_draw_geom(terrain[0]);
    dsSetColor(0.7f, 0.6f, 0.4f);
    draw_field();
    dsSetTexture(DS_WOOD);
    for (int i = 0; i < thing_count; i++) {
        const int cls = dGeomGetClass(things[i].geom);
        dsSetColor(cls == dSphereClass ? 0.9f : 0.3f, 0.4f, cls == dBoxClass ? 0.9f : 0.3f);
        exu_draw_geom(things[i].geom);
    }
}

static int check(void)
{
    dReal worst = 1e9;   // least height of a centre over the surface under it
    double rolled = 0;
    int balls = 0;
    for (int i = 0; i < thing_count; i++) {
        const struct thing *t = &things[i];
        if (!exu_body_finite(t->body)) return exu_report("terrain", 0, "state not finite");
        const dReal *p = dBodyGetPosition(t->body);
        const dReal u = p[0] - centre_x[t->patch];
        const int over = fabs((double)u) < PATCH / 2 && fabs((double)p[1]) < PATCH / 2;
        worst = fmin(worst, p[2] - (over ? height(u, p[1]) : 0));
        if (dGeomGetClass(t->geom) == dSphereClass && t->start_u < -2) {
            rolled += u - t->start_u;
            balls++;
        }
    }
    const int above = worst > 0;
    if (steps < ROLL_STEPS || balls == 0)
        return exu_report("terrain", above, "%d bodies, centres at least %.3f m above the "
                          "surface (> 0); stopped before they could roll far", thing_count,
                          (double)worst);
    rolled /= balls;
    return exu_report("terrain", above && rolled > 0.5,
                      "%d bodies, centres at least %.3f m above the surface (> 0); "
                      "%d balls rolled %.2f m downhill on average (> 0.5)",
                      thing_count, (double)worst, balls, rolled);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(world, 30);
    dWorldSetAutoDisableFlag(world, 0);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactApprox1, .mu = 0.9 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 1024 };
    build_terrain();
    for (int patch = 0; patch < 2; patch++) {
        for (int k = 0; k < 4; k++) add(patch, 0, -2.5, -1.8 + 1.2 * k);
        add(patch, 1, -1.2, -1.0);
        add(patch, 1, -1.2, 1.0);
        add(patch, 2, 0.5, 0);
    }

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dGeomTriMeshDataDestroy(mesh_data);
    dGeomHeightfieldDataDestroy(field_data);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
