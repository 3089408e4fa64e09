// SPDX-License-Identifier: BSD-3-Clause
//
// chain.c -- a chain of capsules hanging from a fixed point on ball joints,
// and a rope bridge of planks on hinges whose joints report their forces
// (joint feedback) and break under a heavy load dropped on it.
//
// Checks when the loop ends: the chain hangs below its anchor with every ball
// joint's two anchors within 1 cm; the unloaded bridge's end joints carry its
// weight (the vertical forces they apply sum to M g within 5 %); once loaded
// a joint broke (its force passed 3 times the largest unloaded one) and the
// load fell through.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define LINKS 12
#define PLANKS 12
#define HINGES (PLANKS + 1)
#define MAX_LOADS 8
#define MEASURE_FROM 60   // unloaded forces averaged over steps 60..89
#define LOAD_STEP 90
#define BREAK_RATIO 3
#define FALL_STEPS 150    // the load is on the ground 150 steps after it was dropped

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[1024];
static long steps;

static const dVector3 chain_anchor = { -2, 0, 4 };
static const dReal link_length = 0.3;
static dBodyID links[LINKS];
static dGeomID link_geoms[LINKS];
static dJointID link_joints[LINKS];

static const dReal plank_length = 0.35;
static const dReal plank_density = 600;
static dBodyID planks[PLANKS];
static dGeomID plank_geoms[PLANKS];
static dJointID hinges[HINGES];   // NULL once broken
static dJointFeedback feedback[HINGES];
static int broken;
static double support_sum;   // sum over the measured steps of the end joints' vertical force
static int support_samples;
static dReal unloaded_max;
static dReal bridge_weight;

static dBodyID loads[MAX_LOADS];
static dGeomID load_geoms[MAX_LOADS];
static int load_count;

static dReal norm3(const dReal *v)
{
    return (dReal)sqrt((double)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
}

static void build_chain(void)
{
    // Hanging 30 degrees from the vertical, in the x-z plane.
    const dReal tilt = 0.5236;
    const dReal dir[3] = { (dReal)sin(tilt), 0, -(dReal)cos(tilt) };
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, (dReal)M_PI - tilt);   // body z along dir
    for (int i = 0; i < LINKS; i++) {
        links[i] = dBodyCreate(world);
        dMass m;
        dMassSetCapsule(&m, 800, 3, 0.05, link_length);
        dBodySetMass(links[i], &m);
        const dReal s = (i + 0.5) * link_length;
        dBodySetPosition(links[i], chain_anchor[0] + dir[0] * s, chain_anchor[1],
                         chain_anchor[2] + dir[2] * s);
        dBodySetRotation(links[i], R);
        link_geoms[i] = dCreateCapsule(space, 0.05, link_length);
        dGeomSetBody(link_geoms[i], links[i]);
        link_joints[i] = dJointCreateBall(world, 0);
        dJointAttach(link_joints[i], links[i], i ? links[i - 1] : 0);
        const dReal a = i * link_length;
        dJointSetBallAnchor(link_joints[i], chain_anchor[0] + dir[0] * a, chain_anchor[1],
                            chain_anchor[2] + dir[2] * a);
    }
}

// Planks along x from (1, 0, 3), sagging: each plank turned a little more up
// than the one before, symmetric, so the far end is where the chain of planks
// ends and no joint starts stretched.
static void build_bridge(void)
{
    const dReal sag = 0.35;
    dVector3 p = { 1, 0, 3 };
    for (int i = 0; i < PLANKS; i++) {
        const dReal theta = -sag + 2 * sag * (i + 0.5) / PLANKS;
        const dVector3 next = { p[0] + plank_length * (dReal)cos(theta), 0,
                                p[2] + plank_length * (dReal)sin(theta) };
        planks[i] = dBodyCreate(world);
        dMass m;
        dMassSetBox(&m, plank_density, plank_length, 1.0, 0.05);
        dBodySetMass(planks[i], &m);
        bridge_weight += m.mass * 9.81;
        dBodySetPosition(planks[i], (p[0] + next[0]) / 2, 0, (p[2] + next[2]) / 2);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 1, 0, -theta);
        dBodySetRotation(planks[i], R);
        plank_geoms[i] = dCreateBox(space, plank_length, 1.0, 0.05);
        dGeomSetBody(plank_geoms[i], planks[i]);
        dCopyVector3(p, next);
    }
}

// A hinge at each plank end: hinge i joins plank i to plank i - 1, the two
// end hinges join the end planks to the world.
static void attach_hinges(void)
{
    for (int i = 0; i <= PLANKS; i++) {
        hinges[i] = dJointCreateHinge(world, 0);
        dBodyID a = i < PLANKS ? planks[i] : planks[PLANKS - 1];
        dBodyID b = i > 0 && i < PLANKS ? planks[i - 1] : 0;
        dJointAttach(hinges[i], a, b);
        const dReal *pos = dBodyGetPosition(a);
        const dReal *R = dBodyGetRotation(a);
        const dReal end = i < PLANKS ? -plank_length / 2 : plank_length / 2;
        dJointSetHingeAnchor(hinges[i], pos[0] + R[0] * end, pos[1] + R[4] * end,
                             pos[2] + R[8] * end);
        dJointSetHingeAxis(hinges[i], 0, 1, 0);
        dJointSetFeedback(hinges[i], &feedback[i]);
    }
}

static void drop_load(void)
{
    if (load_count == MAX_LOADS) return;
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetBoxTotal(&m, 300, 0.5, 0.5, 0.5);
    dBodySetMass(b, &m);
    dBodySetPosition(b, 1 + PLANKS * plank_length / 2 - 0.1 * load_count, 0, 4.2);
    load_geoms[load_count] = dCreateBox(space, 0.5, 0.5, 0.5);
    dGeomSetBody(load_geoms[load_count], b);
    loads[load_count++] = b;
}

static void start(void)
{
    static const float xyz[3] = { 0.5f, -6.5f, 3.3f };
    static const float hpr[3] = { 90.0f, -8.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("chain", "  d: drop another load on the bridge\n  p: push the chain's end\n");
}

static void command(int key)
{
    if (key == 'd') drop_load();
    if (key == 'p') dBodyAddForce(links[LINKS - 1], 300, 200, 0);
}

// Before the load: measure the support and the largest force; after: break
// the joints whose force passes the limit.
static void watch_joints(void)
{
    if (steps >= MEASURE_FROM && steps < LOAD_STEP) {
        support_sum += feedback[0].f1[2] + feedback[PLANKS].f1[2];
        support_samples++;
        for (int i = 0; i < HINGES; i++)
            if (norm3(feedback[i].f1) > unloaded_max) unloaded_max = norm3(feedback[i].f1);
    }
    if (steps < LOAD_STEP) return;
    // One joint per step, the most loaded: once it gives way the others unload.
    int worst = -1;
    for (int i = 0; i < HINGES; i++)
        if (hinges[i] && norm3(feedback[i].f1) > BREAK_RATIO * unloaded_max &&
            (worst < 0 || norm3(feedback[i].f1) > norm3(feedback[worst].f1)))
            worst = i;
    if (worst < 0) return;
    printf("chain: hinge %d broke at step %ld under %.0f N\n", worst, steps,
           (double)norm3(feedback[worst].f1));
    dJointDestroy(hinges[worst]);
    hinges[worst] = NULL;
    broken++;
}

static void step(int pause)
{
    if (!pause) {
        if (steps == LOAD_STEP) drop_load();
        exu_collide(&contacts, space);
        dWorldStep(world, EXU_DT);
        steps++;
        watch_joints();
    }
    dsSetTexture(DS_WOOD);
    dsSetColor(0.7f, 0.7f, 0.75f);
    for (int i = 0; i < LINKS; i++) exu_draw_geom(link_geoms[i]);
    for (int i = 0; i < PLANKS; i++) {
        // Redder as the plank's joints near their limit.
        dReal load = 0;
        for (int k = i; k <= i + 1; k++)
            if (hinges[k] && unloaded_max > 0)
                load = fmax(load, norm3(feedback[k].f1) / (BREAK_RATIO * unloaded_max));
        dsSetColor(0.6f + 0.4f * (float)load, 0.45f * (1 - (float)load), 0.2f);
        exu_draw_geom(plank_geoms[i]);
    }
    dsSetColor(0.3f, 0.3f, 0.8f);
    for (int i = 0; i < load_count; i++) exu_draw_geom(load_geoms[i]);
}

static int check(void)
{
    for (int i = 0; i < LINKS; i++)
        if (!exu_body_finite(links[i])) return exu_report("chain", 0, "chain state not finite");
    for (int i = 0; i < PLANKS; i++)
        if (!exu_body_finite(planks[i])) return exu_report("chain", 0, "bridge state not finite");
    dReal highest = -1e9;
    dReal joint_error = 0;
    for (int i = 0; i < LINKS; i++) {
        highest = fmax(highest, dBodyGetPosition(links[i])[2]);
        dVector3 a1, a2;
        dJointGetBallAnchor(link_joints[i], a1);
        dJointGetBallAnchor2(link_joints[i], a2);
        const dReal d[3] = { a1[0] - a2[0], a1[1] - a2[1], a1[2] - a2[2] };
        joint_error = fmax(joint_error, norm3(d));
    }
    const int chain_ok = highest < chain_anchor[2] && joint_error < 0.01;
    if (support_samples == 0)
        return exu_report("chain", chain_ok, "chain: highest link %.3f m (< anchor %.1f), "
                          "joint error %.2g m (< 0.01); stopped before the bridge was measured",
                          (double)highest, (double)chain_anchor[2], (double)joint_error);
    const double support = support_sum / support_samples;
    const int support_ok = fabs(support - bridge_weight) < 0.05 * bridge_weight;
    const int loaded = steps >= LOAD_STEP + FALL_STEPS;
    const dReal load_z = load_count ? dBodyGetPosition(loads[0])[2] : 0;
    const int breaks_ok = !loaded || (broken > 0 && load_z < 1.5);
    return exu_report("chain", chain_ok && support_ok && breaks_ok,
                      "chain: highest link %.3f m (< anchor %.1f), joint error %.2g m (< 0.01); "
                      "bridge ends carry %.1f N of its %.1f N weight (5 %%); %s%d joint(s) broke "
                      "(limit %.0f N), load at z %.2f (< 1.5)",
                      (double)highest, (double)chain_anchor[2], (double)joint_error, support,
                      (double)bridge_weight, loaded ? "" : "(not loaded long enough) ", broken,
                      (double)(BREAK_RATIO * unloaded_max), (double)load_z);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetAutoDisableFlag(world, 0);
    dWorldSetDamping(world, 0.001, 0.01);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactApprox1, .mu = 0.6 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 1024 };
    build_chain();
    build_bridge();
    attach_hinges();

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
