// SPDX-License-Identifier: BSD-3-Clause
//
// falling.c -- boxes, spheres, capsules and cylinders dropped on a plane.
// Keys drop more. When the loop ends it checks that every object settled on
// the ground: finite state, lowest point at z = 0 (within 3 cm), no longer
// falling or bouncing.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define MAX_OBJECTS 64
#define SETTLE_STEPS 180   // 3 s: long enough for a drop from 3 m to come to rest

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[1024];

static struct object {
    dBodyID body;
    dGeomID geom;
    int kind;
    long dropped_at;   // step number
} objects[MAX_OBJECTS];
static int object_count;
static long steps;

// A shape of kind 0..3 (box, sphere, capsule, cylinder) at (x, y, z), turned by angle.
static void drop(int kind, dReal x, dReal y, dReal z, dReal angle)
{
    if (object_count == MAX_OBJECTS) return;
    const dReal density = 500;
    dMass m;
    dGeomID g;
    switch (kind) {
    case 0:
        g = dCreateBox(space, 0.5, 0.35, 0.25);
        dMassSetBox(&m, density, 0.5, 0.35, 0.25);
        break;
    case 1:
        g = dCreateSphere(space, 0.22);
        dMassSetSphere(&m, density, 0.22);
        break;
    case 2:
        g = dCreateCapsule(space, 0.12, 0.4);
        dMassSetCapsule(&m, density, 3, 0.12, 0.4);
        break;
    default:
        g = dCreateCylinder(space, 0.18, 0.3);
        dMassSetCylinder(&m, density, 3, 0.18, 0.3);
        break;
    }
    dBodyID b = dBodyCreate(world);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0.5, 0.2, angle);
    dBodySetRotation(b, R);
    dGeomSetBody(g, b);
    objects[object_count++] = (struct object){ b, g, kind, steps };
}

static void start(void)
{
    static const float xyz[3] = { 5.5f, -4.0f, 2.6f };
    static const float hpr[3] = { 144.0f, -20.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("falling", "  b s c y: drop a box, sphere, capsule, cylinder\n");
}

static void command(int key)
{
    const dReal x = dRandReal() * 2 - 1;
    const dReal y = dRandReal() * 2 - 1;
    const dReal angle = dRandReal() * 3;
    switch (key) {
    case 'b': drop(0, x, y, 3, angle); break;
    case 's': drop(1, x, y, 3, angle); break;
    case 'c': drop(2, x, y, 3, angle); break;
    case 'y': drop(3, x, y, 3, angle); break;
    default: break;
    }
}

static void step(int pause)
{
    if (!pause) {
        exu_collide(&contacts, space);
        dWorldQuickStep(world, EXU_DT);
        steps++;
    }
    static const float colours[4][3] = {
        { 0.9f, 0.6f, 0.2f }, { 0.3f, 0.5f, 0.9f }, { 0.4f, 0.8f, 0.3f }, { 0.8f, 0.3f, 0.6f }
    };
    dsSetTexture(DS_WOOD);
    for (int i = 0; i < object_count; i++) {
        const int kind = objects[i].kind;
        dsSetColor(colours[kind][0], colours[kind][1], colours[kind][2]);
        exu_draw_geom(objects[i].geom);
    }
}

// Every object dropped long enough ago rests on the ground.
static int check(void)
{
    int checked = 0;
    int finite = 1;
    int resting = 1;
    dReal worst_bottom = 0;
    dReal worst_vz = 0;
    for (int i = 0; i < object_count; i++) {
        if (!exu_body_finite(objects[i].body)) finite = 0;
        if (steps - objects[i].dropped_at < SETTLE_STEPS) continue;
        checked++;
        const dReal bottom = exu_geom_bottom(objects[i].geom);
        const dReal vz = dBodyGetLinearVel(objects[i].body)[2];
        if (fabs((double)bottom) > fabs((double)worst_bottom)) worst_bottom = bottom;
        if (fabs((double)vz) > fabs((double)worst_vz)) worst_vz = vz;
        if (fabs((double)bottom) > 0.03 || fabs((double)vz) > 0.05) resting = 0;
    }
    if (!finite) return exu_report("falling", 0, "a body's state is not finite");
    if (checked == 0)
        return exu_report("falling", 1, "state finite; stopped before anything could settle");
    return exu_report("falling", resting,
                      "%d objects on the ground after %ld steps: lowest point %+.4f m "
                      "(|z| <= 0.03), vertical speed %+.4f m/s (|vz| <= 0.05)",
                      checked, steps, (double)worst_bottom, (double)worst_vz);
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
                               .surface = { .mode = dContactSoftCFM | dContactApprox1,
                                            .mu = 0.8, .soft_cfm = 1e-5 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 1024 };

    // A 4 x 4 grid, each kind in turn, at different heights and angles.
    for (int i = 0; i < 16; i++)
        drop(i % 4, (i % 4) * 1.2 - 1.8, (i / 4) * 1.2 - 1.8, 0.8 + 0.15 * i, 0.4 * i);

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
