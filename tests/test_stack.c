// SPDX-License-Identifier: BSD-3-Clause
//
// test_stack.c -- end to end: geoms on bodies in a hash space, dSpaceCollide
// with a near callback that turns dCollide's contacts into contact joints,
// and the steppers. A stack of boxes must stand still on a plane, and a ball
// dropped with restitution 1 must bounce back to its height. The measured
// drifts are printed as TAP comments.

#include "test.h"

#include <stdio.h>
#include <string.h>

#define MAX_BOXES 10
#define MAX_CONTACTS 8

typedef struct scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    dGeomID ground;
    int n;
    dBodyID body[MAX_BOXES];
    dGeomID geom[MAX_BOXES];
    dSurfaceParameters surface;
    dReal deepest;      // the deepest contact seen since the last reset
    int contact_count;  // contacts created in the last step
} scene;

// The guide's near callback (10.5): contacts of the pair become contact
// joints between the geoms' bodies (0 for the ground) in the scene's group.
static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *s = data;
    dContact c[MAX_CONTACTS];
    int n = dCollide(a, b, MAX_CONTACTS, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface = s->surface;
        if (c[i].geom.depth > s->deepest) s->deepest = c[i].geom.depth;
        dJointID j = dJointCreateContact(s->world, s->contacts, &c[i]);
        dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
    s->contact_count += n;
}

// World with gravity -9.81 z, a hash space holding the plane z = 0.
static void scene_init(scene *s)
{
    memset(s, 0, sizeof *s);
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, -9.81);
    s->space = dHashSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    s->ground = dCreatePlane(s->space, 0, 0, 1, 0);
}

// A body of mass m with geom g (already in the space) at (x, y, z).
static dBodyID scene_add(scene *s, dGeomID g, dReal m, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(s->world);
    dMass mass;
    if (dGeomGetClass(g) == dSphereClass) {
        dMassSetSphereTotal(&mass, m, dGeomSphereGetRadius(g));
    } else {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        dMassSetBoxTotal(&mass, m, side[0], side[1], side[2]);
    }
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    dGeomSetBody(g, b);
    s->body[s->n] = b;
    s->geom[s->n] = g;
    s->n++;
    return b;
}

// One step: collide, solve with `step`, drop the contacts.
static void scene_step(scene *s, int (*step)(dWorldID, dReal), dReal h)
{
    s->contact_count = 0;
    dSpaceCollide(s->space, s, near_callback);
    step(s->world, h);
    dJointGroupEmpty(s->contacts);
}

static void scene_free(scene *s)
{
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);
    dWorldDestroy(s->world);
}

// ---- the box stack ---------------------------------------------------------------

typedef struct stack_drift {
    double horizontal, vertical, tilt_deg, deepest;
} stack_drift;

// n unit cubes of mass 1 resting on each other on the plane (touching
// exactly at the start), run for `seconds` at 60 Hz. The worst drift of any
// box from its start, the top box's tilt and the deepest contact over the run.
static stack_drift run_stack(int n, int (*step)(dWorldID, dReal), double seconds)
{
    scene s;
    scene_init(&s);
    dWorldSetQuickStepNumIterations(s.world, 20);
    s.surface.mode = dContactApprox1 | dContactSoftCFM;
    s.surface.mu = 0.5;
    s.surface.soft_cfm = 1e-5;
    for (int i = 0; i < n; i++) scene_add(&s, dCreateBox(s.space, 1, 1, 1), 1, 0, 0, 0.5 + i);

    stack_drift d = { 0, 0, 0, 0 };
    const dReal h = REAL(1.0) / 60;
    for (int k = 0; k < (int)(seconds * 60 + 0.5); k++) {
        scene_step(&s, step, h);
        for (int i = 0; i < n; i++) {
            const dReal *p = dBodyGetPosition(s.body[i]);
            double horizontal = sqrt((double)p[0] * p[0] + (double)p[1] * p[1]);
            double vertical = fabs(p[2] - (0.5 + i));
            if (horizontal > d.horizontal) d.horizontal = horizontal;
            if (vertical > d.vertical) d.vertical = vertical;
        }
        // The angle between the top box's z axis and the world's.
        double cz = dBodyGetRotation(s.body[n - 1])[10];
        double tilt = acos(cz > 1 ? 1 : cz) * 180 / M_PI;
        if (tilt > d.tilt_deg) d.tilt_deg = tilt;
    }
    d.deepest = s.deepest;
    scene_free(&s);
    return d;
}

// Prints the drifts and checks them against the limits given.
static int check_stack(const char *what, stack_drift d, stack_drift limit)
{
    printf("# %s: max horizontal drift %.3g m, max height drift %.3g m, top tilt %.3g deg, "
           "deepest contact %.3g m\n",
           what, d.horizontal, d.vertical, d.tilt_deg, d.deepest);
    CHECK(d.horizontal <= limit.horizontal);
    CHECK(d.vertical <= limit.vertical);
    CHECK(d.tilt_deg <= limit.tilt_deg);
    CHECK(d.deepest <= limit.deepest);
    return 0;
}

// Projected Gauss-Seidel with 20 iterations does not converge for a stack
// ten high, and its randomly reordered rows make the upper boxes wander a
// little (the heights sag by the stack's compliance, about 2 cm). ODE 0.16
// in this very scene wanders 6 to 16 cm horizontally for 4 or 8 contacts,
// soft CFM 1e-5..1e-3 and mu 0.5..1 (we measure 7 to 13 cm): 15 cm is the
// limit here; 5 cm of sag, 3 degrees of tilt, 2 cm of penetration.
static int test_ten_box_stack_stands_for_10_s_with_quickstep(void)
{
    stack_drift limit = { 0.15, 0.05, 3, 0.02 };
    return check_stack("10 boxes, dWorldQuickStep 20 it, 10 s",
                       run_stack(10, dWorldQuickStep, 10), limit);
}

// The direct solver solves each step's LCP exactly: a symmetric stack has no
// reason to move sideways or tilt, and only settles by the contacts' CFM
// (about 0.1 mm in either precision).
static int test_ten_box_stack_stands_still_for_2_s_with_dWorldStep(void)
{
    stack_drift limit = { 1e-3, 1e-3, 0.1, 1e-3 };
    return check_stack("10 boxes, dWorldStep, 2 s", run_stack(10, dWorldStep, 2), limit);
}

// ---- a bouncing ball ---------------------------------------------------------------

// A ball of radius 0.5 dropped with its bottom 1.5 m above the plane, with
// restitution 1 and no threshold: the contact reverses the impact speed, so
// the ball climbs back to its height (less the little the step loses).
static int test_ball_bounces_back_to_its_height(void)
{
    scene s;
    scene_init(&s);
    s.surface.mode = dContactBounce;
    s.surface.mu = 0;
    s.surface.bounce = 1;
    s.surface.bounce_vel = 0;
    const dReal r = 0.5, drop = 1.5;
    dBodyID ball = scene_add(&s, dCreateSphere(s.space, r), 1, 0, 0, r + drop);

    // The first fall takes sqrt(2 drop / g) = 0.55 s; the apex follows at 1.1 s.
    double apex = 0, lowest = drop;
    int bounced = 0;
    for (int k = 0; k < 1500; k++) {   // 1.5 s at 1 ms
        scene_step(&s, dWorldStep, 0.001);
        double gap = dBodyGetPosition(ball)[2] - r;
        if (gap < lowest) lowest = gap;
        if (s.contact_count > 0) bounced = 1;
        if (bounced && gap > apex) apex = gap;
    }

    printf("# ball: dropped from %.3g m, back to %.4g m (%.2f %%), deepest %.3g m\n",
           (double)drop, apex, 100 * apex / drop, (double)s.deepest);
    CHECK(bounced);
    CHECK(apex >= 0.95 * drop);
    CHECK(apex <= 1.02 * drop);   // no energy gained
    CHECK(lowest > -0.02);
    scene_free(&s);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_ten_box_stack_stands_for_10_s_with_quickstep),
    TEST_CASE(test_ten_box_stack_stands_still_for_2_s_with_dWorldStep),
    TEST_CASE(test_ball_bounces_back_to_its_height),
    TEST_END
};
