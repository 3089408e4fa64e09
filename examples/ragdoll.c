// SPDX-License-Identifier: BSD-3-Clause
//
// ragdoll.c -- a figure of capsules, a box and a sphere on universal and
// hinge joints with stops, pushed over. Key k kicks it. When the loop ends it
// checks: finite state; the figure lies on the ground (no part below
// z = -3 cm, its lowest part touching, its torso below 0.5 m, every part
// slower than 0.3 m/s); every knee and elbow within its stops (0.1 rad slack).

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define MAX_PARTS 16
#define MAX_JOINTS 16
#define REST_STEPS 240   // 4 s: long enough to fall and come to rest

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[512];
static long steps;

static dBodyID parts[MAX_PARTS];
static dGeomID part_geoms[MAX_PARTS];
static int part_count;
static dJointID hinges[MAX_JOINTS];   // knees and elbows, checked against their stops
static int hinge_count;
static dBodyID torso;

static dBodyID add_part(dGeomID g, const dMass *m, const dReal *pos)
{
    dBodyID b = dBodyCreate(world);
    dBodySetMass(b, m);
    dBodySetPosition(b, pos[0], pos[1], pos[2]);
    dGeomSetBody(g, b);
    parts[part_count] = b;
    part_geoms[part_count++] = g;
    return b;
}

// A capsule limb from a to b (its z axis along b - a).
static dBodyID limb(const dReal *a, const dReal *b, dReal radius)
{
    const dReal d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const dReal len = (dReal)sqrt((double)(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    const dReal mid[3] = { (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 };
    dMass m;
    dMassSetCapsule(&m, 1000, 3, radius, len - 2 * radius);
    dBodyID body = add_part(dCreateCapsule(space, radius, len - 2 * radius), &m, mid);
    dMatrix3 R;
    dRFromZAxis(R, d[0], d[1], d[2]);
    dBodySetRotation(body, R);
    return body;
}

static void universal(dBodyID b1, dBodyID b2, const dReal *at, dReal limit)
{
    dJointID j = dJointCreateUniversal(world, 0);
    dJointAttach(j, b1, b2);
    dJointSetUniversalAnchor(j, at[0], at[1], at[2]);
    dJointSetUniversalAxis1(j, 0, 1, 0);
    dJointSetUniversalAxis2(j, 1, 0, 0);
    dJointSetUniversalParam(j, dParamLoStop, -limit);
    dJointSetUniversalParam(j, dParamHiStop, limit);
    dJointSetUniversalParam(j, dParamLoStop2, -limit);
    dJointSetUniversalParam(j, dParamHiStop2, limit);
}

static void hinge(dBodyID b1, dBodyID b2, const dReal *at, dReal lo, dReal hi, int checked)
{
    dJointID j = dJointCreateHinge(world, 0);
    dJointAttach(j, b1, b2);
    dJointSetHingeAnchor(j, at[0], at[1], at[2]);
    dJointSetHingeAxis(j, 0, 1, 0);
    dJointSetHingeParam(j, dParamLoStop, lo);
    dJointSetHingeParam(j, dParamHiStop, hi);
    if (checked) hinges[hinge_count++] = j;
}

// Standing, facing +x, feet at z = lift.
static void build(dReal lift)
{
    dMass m;
    const dReal pelvis_at[3] = { 0, 0, lift + 0.95 };
    dMassSetBoxTotal(&m, 8, 0.18, 0.32, 0.16);
    dBodyID pelvis = add_part(dCreateBox(space, 0.18, 0.32, 0.16), &m, pelvis_at);

    const dReal waist[3] = { 0, 0, lift + 1.03 }, neck[3] = { 0, 0, lift + 1.5 };
    torso = limb(waist, neck, 0.13);
    universal(torso, pelvis, waist, 0.6);

    const dReal head_at[3] = { 0, 0, lift + 1.63 };
    dMassSetSphere(&m, 1000, 0.11);
    dBodyID head = add_part(dCreateSphere(space, 0.11), &m, head_at);
    hinge(head, torso, neck, -0.6, 0.6, 0);

    for (int side = -1; side <= 1; side += 2) {
        const dReal shoulder[3] = { 0, side * 0.2, lift + 1.42 };
        const dReal elbow[3] = { 0, side * 0.24, lift + 1.14 };
        const dReal hand[3] = { 0, side * 0.26, lift + 0.88 };
        dBodyID upper = limb(shoulder, elbow, 0.05);
        universal(upper, torso, shoulder, 1.2);
        dBodyID fore = limb(elbow, hand, 0.045);
        hinge(fore, upper, elbow, -2.3, 0, 1);

        const dReal hip[3] = { 0, side * 0.1, lift + 0.9 };
        const dReal knee[3] = { 0, side * 0.1, lift + 0.48 };
        const dReal foot[3] = { 0, side * 0.1, lift + 0.02 };
        dBodyID thigh = limb(hip, knee, 0.07);
        universal(thigh, pelvis, hip, 1.0);
        dBodyID shin = limb(knee, foot, 0.06);
        hinge(shin, thigh, knee, 0, 2.3, 1);
    }
}

static void start(void)
{
    static const float xyz[3] = { 0.8f, -3.4f, 1.4f };
    static const float hpr[3] = { 90.0f, -15.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("ragdoll", "  k: kick the torso\n");
}

static void command(int key)
{
    if (key == 'k') dBodyAddForce(torso, 0, 4000, 3000);
}

static void step(int pause)
{
    if (!pause) {
        exu_collide(&contacts, space);
        dWorldStep(world, EXU_DT);
        steps++;
    }
    dsSetTexture(DS_WOOD);
    dsSetColor(0.85f, 0.65f, 0.5f);
    for (int i = 0; i < part_count; i++) exu_draw_geom(part_geoms[i]);
}

static int check(void)
{
    dReal lowest = 1e9, fastest = 0;
    for (int i = 0; i < part_count; i++) {
        if (!exu_body_finite(parts[i])) return exu_report("ragdoll", 0, "state not finite");
        lowest = fmin(lowest, exu_geom_bottom(part_geoms[i]));
        fastest = fmax(fastest, exu_speed(parts[i]));
    }
    dReal worst_stop = 0;   // how far a hinge went past a stop, rad
    for (int i = 0; i < hinge_count; i++) {
        const dReal a = dJointGetHingeAngle(hinges[i]);
        const dReal lo = dJointGetHingeParam(hinges[i], dParamLoStop);
        const dReal hi = dJointGetHingeParam(hinges[i], dParamHiStop);
        worst_stop = fmax(worst_stop, fmax(lo - a, a - hi));
    }
    const dReal torso_z = dBodyGetPosition(torso)[2];
    const int stops_ok = worst_stop < 0.1;
    if (steps < REST_STEPS)
        return exu_report("ragdoll", stops_ok, "hinges at most %.3f rad past a stop (< 0.1); "
                          "stopped before it could come to rest", (double)worst_stop);
    const int rests = lowest > -0.03 && lowest < 0.03 && torso_z < 0.5 && fastest < 0.3;
    return exu_report("ragdoll", rests && stops_ok,
                      "%d parts: lowest point %+.4f m (|z| < 0.03), torso at %.3f m (< 0.5), "
                      "fastest part %.3f m/s (< 0.3); hinges at most %.3f rad past a stop (< 0.1)",
                      part_count, (double)lowest, (double)torso_z, (double)fastest,
                      (double)worst_stop);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetAutoDisableFlag(world, 0);
    dWorldSetDamping(world, 0.002, 0.01);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactApprox1, .mu = 0.8 },
                               .max_per_pair = 4, .seen = contact_buffer,
                               .seen_capacity = 512 };
    build(0.2);
    dBodySetLinearVel(torso, 1.5, 0.3, 0);   // a push to fall forward

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
