// SPDX-License-Identifier: BSD-3-Clause
//
// drawstuff_program.c -- written the way ODE's demos are (callbacks with
// empty parameter lists, dsFunctions filled field by field, options passed
// through argv), for the install check: a box falls on the ground plane;
// stop() prints where it came to rest. Built as C and as C++.

#include <ode/ode.h>
#include <drawstuff/drawstuff.h>
#include <stdio.h>

// As ODE's demos: the drawing functions that take dReal arrays.
#ifdef dDOUBLE
#define dsDrawBox dsDrawBoxD
#endif

static dWorldID world;
static dSpaceID space;
static dJointGroupID contacts;
static dBodyID body;
static dGeomID box;

static void near_callback(void *data, dGeomID a, dGeomID b)
{
    dContact contact[4];
    (void)data;
    int n = dCollide(a, b, 4, &contact[0].geom, sizeof(dContact));
    for (int i = 0; i < n; i++) {
        contact[i].surface.mode = 0;
        contact[i].surface.mu = 1.0;
        dJointID j = dJointCreateContact(world, contacts, &contact[i]);
        dJointAttach(j, dGeomGetBody(a), dGeomGetBody(b));
    }
}

static void start()
{
    static float xyz[3] = { 3.0f, -3.0f, 2.0f };
    static float hpr[3] = { 135.0f, -20.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
}

static void step(int pause)
{
    if (!pause) {
        dSpaceCollide(space, 0, near_callback);
        dWorldStep(world, 0.01);
        dJointGroupEmpty(contacts);
    }
    dVector3 sides;
    dGeomBoxGetLengths(box, sides);
    dsSetColor(1, 0, 0);
    dsSetTexture(DS_WOOD);
    dsDrawBox(dBodyGetPosition(body), dBodyGetRotation(body), sides);
}

static void stop()
{
    const dReal *p = dBodyGetPosition(body);
    printf("rest %.2f %.2f %.2f\n", (double)p[0], (double)p[1], (double)p[2]);
}

int main(int argc, char **argv)
{
    dsFunctions fn;
    fn.version = DS_VERSION;
    fn.start = &start;
    fn.step = &step;
    fn.command = 0;
    fn.stop = &stop;
    fn.path_to_textures = "textures";

    dInitODE();
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    space = dHashSpaceCreate(0);
    contacts = dJointGroupCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    body = dBodyCreate(world);
    dMass m;
    dMassSetBox(&m, 1, 1, 1, 1);
    dBodySetMass(body, &m);
    dBodySetPosition(body, 0, 0, 1.5);
    box = dCreateBox(space, 1, 1, 1);
    dGeomSetBody(box, body);

    dsSimulationLoop(argc, argv, 320, 240, &fn);

    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return 0;
}
