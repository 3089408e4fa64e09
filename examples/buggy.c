// SPDX-License-Identifier: BSD-3-Clause
//
// buggy.c -- a four-wheeled car on hinge-2 joints: axis 1 steers (front
// wheels; the rear ones are held straight by zero stops), axis 2 drives, with
// suspension along axis 1. Keys a/z change the throttle, comma and period
// steer. Headless (-headless or DS_HEADLESS) it drives itself straight ahead.
// Checks when the loop ends: finite state, the chassis upright and, when it
// drove itself for two seconds or more, moved forward (+x) more than 1 m.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define WHEELS 4
#define CONES 6

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[256];
static long steps;
static long driven_steps;   // steps with a forward throttle

static const dReal length = 1.0, width = 0.6, height = 0.2, radius = 0.2, start_z = 0.5;
static dBodyID chassis;
static dGeomID chassis_geom;
static dBodyID wheels[WHEELS];
static dGeomID wheel_geoms[WHEELS];
static dJointID axles[WHEELS];
static dGeomID cones[CONES];
static dReal throttle;   // wheel spin wanted, rad/s
static dReal steer;      // front wheel angle wanted, rad
static int autopilot;

static void build(void)
{
    dMass m;
    chassis = dBodyCreate(world);
    dBodySetPosition(chassis, 0, 0, start_z);
    dMassSetBoxTotal(&m, 4, length, width, height);
    dBodySetMass(chassis, &m);
    chassis_geom = dCreateBox(space, length, width, height);
    dGeomSetBody(chassis_geom, chassis);

    for (int i = 0; i < WHEELS; i++) {
        const dReal x = (i < 2 ? 0.5 : -0.5) * length;
        const dReal y = (i % 2 ? 0.5 : -0.5) * (width + 0.1);
        wheels[i] = dBodyCreate(world);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0, 0, (dReal)M_PI / 2);
        dBodySetRotation(wheels[i], R);
        dBodySetPosition(wheels[i], x, y, start_z - height / 2);
        dMassSetSphereTotal(&m, 0.4, radius);
        dBodySetMass(wheels[i], &m);
        wheel_geoms[i] = dCreateSphere(space, radius);
        dGeomSetBody(wheel_geoms[i], wheels[i]);

        axles[i] = dJointCreateHinge2(world, 0);
        dJointAttach(axles[i], chassis, wheels[i]);
        dJointSetHinge2Anchor(axles[i], x, y, start_z - height / 2);
        const dReal steer_axis[3] = { 0, 0, 1 }, spin_axis[3] = { 0, 1, 0 };
        dJointSetHinge2Axes(axles[i], steer_axis, spin_axis);
        dJointSetHinge2Param(axles[i], dParamSuspensionERP, 0.4);
        dJointSetHinge2Param(axles[i], dParamSuspensionCFM, 0.8);
        const dReal lock = i < 2 ? 0.5 : 0;
        dJointSetHinge2Param(axles[i], dParamLoStop, -lock);
        dJointSetHinge2Param(axles[i], dParamHiStop, lock);
    }
}

static void start(void)
{
    static const float xyz[3] = { -3.0f, -3.5f, 1.8f };
    static const float hpr[3] = { 45.0f, -18.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("buggy", "  a / z: throttle up / down\n  , / .: steer left / right\n"
             "  space: stop\n");
}

static void command(int key)
{
    switch (key) {
    case 'a': throttle += 2; break;
    case 'z': throttle -= 2; break;
    case ',': steer = fmin(steer + 0.1, 0.5); break;
    case '.': steer = fmax(steer - 0.1, -0.5); break;
    case ' ': throttle = 0; steer = 0; break;
    default: break;
    }
}

static void drive(void)
{
    if (autopilot && steps == 30) throttle = 10;   // after the suspension settled
    for (int i = 0; i < WHEELS; i++) {
        // Body 1 is the chassis: the wheel turns forward at a negative rate of axis 2.
        dJointSetHinge2Param(axles[i], dParamVel2, -throttle);
        dJointSetHinge2Param(axles[i], dParamFMax2, 2.0);
        if (i < 2) {   // steer by a proportional motor on axis 1
            const dReal error = steer - dJointGetHinge2Angle1(axles[i]);
            dJointSetHinge2Param(axles[i], dParamVel, 10 * error);
            dJointSetHinge2Param(axles[i], dParamFMax, 2.0);
        }
    }
    if (throttle > 0) driven_steps++;
}

static void step(int pause)
{
    if (!pause) {
        drive();
        exu_collide(&contacts, space);
        dWorldStep(world, EXU_DT);
        steps++;
    }
    dsSetTexture(DS_WOOD);
    dsSetColor(0.9f, 0.8f, 0.1f);
    exu_draw_geom(chassis_geom);
    dsSetColor(0.15f, 0.15f, 0.15f);
    for (int i = 0; i < WHEELS; i++) exu_draw_geom(wheel_geoms[i]);
    dsSetColor(1.0f, 0.45f, 0.1f);
    for (int i = 0; i < CONES; i++) exu_draw_geom(cones[i]);
}

static int check(void)
{
    int finite = exu_body_finite(chassis);
    for (int i = 0; i < WHEELS; i++) finite = finite && exu_body_finite(wheels[i]);
    if (!finite) return exu_report("buggy", 0, "state not finite");
    const dReal *p = dBodyGetPosition(chassis);
    const dReal up = dBodyGetRotation(chassis)[10];   // z component of the body's z axis
    const int upright = up > 0.8;
    if (!autopilot || driven_steps < 2 * EXU_RATE)
        return exu_report("buggy", upright, "upright (z axis %.3f > 0.8); at (%.2f, %.2f); "
                          "the distance is checked when it drives itself", (double)up,
                          (double)p[0], (double)p[1]);
    return exu_report("buggy", upright && p[0] > 1,
                      "upright (z axis %.3f > 0.8); driven %ld steps, moved %.2f m forward (> 1)",
                      (double)up, driven_steps, (double)p[0]);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    autopilot = exu_headless(argc, argv);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetAutoDisableFlag(world, 0);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactSlip1 | dContactSlip2 |
                                                    dContactSoftERP | dContactSoftCFM |
                                                    dContactApprox1,
                                            .mu = dInfinity, .slip1 = 0.05, .slip2 = 0.05,
                                            .soft_erp = 0.5, .soft_cfm = 0.003 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 256 };
    build();
    // Static cones to drive between.
    for (int i = 0; i < CONES; i++) {
        cones[i] = dCreateCylinder(space, 0.12, 0.5);
        dGeomSetPosition(cones[i], 2.0 + 2.0 * (i / 2), i % 2 ? 1.2 : -1.2, 0.25);
    }

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
