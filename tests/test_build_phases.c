// SPDX-License-Identifier: BSD-3-Clause
//
// test_build_phases.c -- QuickStep builds its islands in phases over a
// queue of them (quickstep_build.c: every queued island's joint rows, the
// run joints' blocks, two of the same size factored side by side, then
// every queued island's blocks and rows), which must give the same system,
// and so the same bits, as building island by island. A scene of many
// islands of every kind (hinge-2 cars under random parameters, chains of
// hinges and universal joints with motors that push against their stops,
// boxes on contacts of finite and of infinite friction, free bodies, a joint
// with feedback) is stepped island by island (dxQuickBuildJoints 0), with a
// queue smaller than some islands and with the default queue; the bodies'
// states and the feedback are compared after every step. The run joints'
// other rows are coupled to their blocks ahead too, two blocks' rows side by
// side: the hinge-2's limit and motor rows (none, one or two a joint, so
// pairs with a row on one side only), the contacts' normal rows; in some
// scenes a heavy box (a huge mass, a unit inertia) on contacts of infinite
// friction without CFM, whose normal rows depend on their friction rows
// (its linear part all but gone): their Schur complements fail the pivot
// test, the rows are made on their own, in a pair and alone.

#include "test.h"
#include "quickstep.h"
#include "random_joints.h"

#include <stdint.h>
#include <string.h>

enum { MAX_BODIES = 48, STEPS = 150, WAYS = 3 };

typedef struct scene {
    dWorldID w;
    dJointGroupID contacts;
    dBodyID b[MAX_BODIES];
    int nb;
    dBodyID box[12];   // the bodies held by contacts, their friction, heavy or not
    dReal mu[12];
    int heavy[12];
    int nbox;
    dJointFeedback fb;
} scene;

static dBodyID body_at(scene *s, uint32_t *r, dReal x, dReal y, dReal z)
{
    dBodyID b = random_body(s->w, r, x, y, z);
    s->b[s->nb++] = b;
    return b;
}

// A car: a chassis and four hinge-2 wheels, the first with feedback.
static void add_car(scene *s, uint32_t *r, dReal x)
{
    dBodyID chassis = body_at(s, r, x, 0, 1);
    for (int k = 0; k < 4; k++) {
        const dReal wx = x + (k < 2 ? REAL(0.4) : REAL(-0.4));
        const dReal wy = k % 2 ? REAL(-0.3) : REAL(0.3);
        dBodyID wheel = body_at(s, r, wx, wy, REAL(0.9));
        dJointID j = dJointCreateHinge2(s->w, 0);
        dJointAttach(j, chassis, wheel);
        dJointSetHinge2Anchor(j, wx, wy, REAL(0.9));
        const dReal up[3] = { uniform(r, -0.2, 0.2), uniform(r, -0.2, 0.2), 1 };
        const dReal across[3] = { uniform(r, -0.2, 0.2), 1, 0 };
        dJointSetHinge2Axes(j, up, across);
        dJointSetHinge2Param(j, dParamSuspensionERP, uniform(r, 0.1, 0.9));
        dJointSetHinge2Param(j, dParamSuspensionCFM, uniform(r, 0.001, 0.05));
        random_limot(r, j, 0, dJointSetHinge2Param);
        random_limot(r, j, 1, dJointSetHinge2Param);
        if (k == 0 && x == 0) dJointSetFeedback(j, &s->fb);
    }
}

// A chain of hinges and universal joints hanging from the world.
static void add_chain(scene *s, uint32_t *r, dReal x)
{
    dBodyID last = NULL;
    for (int k = 0; k < 4; k++) {
        const dReal z = (dReal)(3 - REAL(0.4) * k);
        dBodyID b = body_at(s, r, x, 2, z);
        if (k % 2 == 0) {
            dJointID j = dJointCreateHinge(s->w, 0);
            dJointAttach(j, b, last);
            dJointSetHingeAnchor(j, x, 2, z + REAL(0.2));
            dJointSetHingeAxis(j, uniform(r, -0.3, 0.3), 1, 0);
            random_limot(r, j, 0, dJointSetHingeParam);
        } else {
            dJointID j = dJointCreateUniversal(s->w, 0);
            dJointAttach(j, b, last);
            dJointSetUniversalAnchor(j, x, 2, z + REAL(0.2));
            dJointSetUniversalAxis1(j, 1, 0, 0);
            dJointSetUniversalAxis2(j, 0, 1, uniform(r, -0.3, 0.3));
            random_limot(r, j, 0, dJointSetUniversalParam);
            random_limot(r, j, 1, dJointSetUniversalParam);
        }
        last = b;
    }
}

// A box on the ground, its contacts' friction mu (heavy: heavy_contacts).
static void add_box(scene *s, dBodyID b, dReal mu, int heavy)
{
    s->box[s->nbox] = b;
    s->mu[s->nbox] = mu;
    s->heavy[s->nbox++] = heavy;
}

// A box of mass 1e20 and unit inertia at x on the ground, tilted so that
// three of its bottom corners touch it.
static void add_heavy_box(scene *s, dReal x)
{
    dBodyID b = dBodyCreate(s->w);
    dMass m;
    dMassSetParameters(&m, REAL(1e20), 0, 0, 0, 1, 1, 1, 0, 0, 0);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, -4, REAL(0.19));
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 1, 0, REAL(0.05));
    dBodySetRotation(b, R);
    s->b[s->nb++] = b;
    add_box(s, b, dInfinity, 1);
}

// Cars, chains, boxes on the ground (z = 0) of infinite and of finite
// friction and free bodies, interleaved so that the islands of each kind
// come between the others; heavy boxes too, and no CFM, if heavy.
static void build(scene *s, uint32_t seed, int heavy)
{
    uint32_t r = seed;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    if (heavy) dWorldSetCFM(s->w, 0);
    for (int c = 0; c < 4; c++) {
        add_car(s, &r, (dReal)(3 * c));
        if (c < 2) add_chain(s, &r, (dReal)(3 * c + 1));
        for (int k = 0; k < 2; k++)
            add_box(s, body_at(s, &r, (dReal)(3 * c + k), -2, REAL(0.19)), k ? REAL(0.6) : dInfinity, 0);
        if (heavy && c % 2 == 0) add_heavy_box(s, (dReal)(3 * c));
        body_at(s, &r, (dReal)(3 * c), 5, 10);
    }
}

// Contacts of infinite friction without CFM (the world's, 0 in a scene
// with heavy boxes) of heavy box b's bottom corners below z = 0.
static void heavy_contacts(scene *s, dBodyID b)
{
    for (int c = 0; c < 4; c++) {
        dVector3 p;
        dBodyGetRelPointPos(b, c & 1 ? REAL(0.15) : REAL(-0.15), c & 2 ? REAL(0.1) : REAL(-0.1),
                            REAL(-0.2), p);
        if (p[2] >= 0) continue;
        dContact ct;
        memset(&ct, 0, sizeof ct);
        ct.surface.mu = dInfinity;
        ct.geom.pos[0] = p[0];
        ct.geom.pos[1] = p[1];
        ct.geom.normal[2] = 1;
        ct.geom.depth = -p[2];
        dJointAttach(dJointCreateContact(s->w, s->contacts, &ct), b, 0);
    }
}

// The contacts of the boxes' bottom corners below z = 0.
static void contacts_now(scene *s)
{
    dJointGroupEmpty(s->contacts);
    for (int k = 0; k < s->nbox; k++) {
        if (s->heavy[k]) heavy_contacts(s, s->box[k]);
        else ground_contacts(s->w, s->contacts, s->box[k], s->mu[k]);
    }
}

// The bodies' positions, orientations and velocities, then the feedback.
static void state_of(const scene *s, dReal *out)
{
    out = body_states(s->b, s->nb, out);
    memcpy(out, s->fb.f1, 3 * sizeof(dReal));
    memcpy(out + 3, s->fb.t2, 3 * sizeof(dReal));
}

// Steps the scene of the seed (with heavy boxes if heavy) built island by
// island, with a queue of 5 joints and with the default queue; 0 if every
// step's state is the same bits every way.
static int same_every_way(uint32_t seed, int heavy)
{
    static dReal x[WAYS][13 * MAX_BODIES + 6];
    const int room[WAYS] = { 0, 5, dxQuickBuildJoints };
    const int saved = dxQuickBuildJoints;
    scene s[WAYS];
    for (int k = 0; k < WAYS; k++) {
        memset(&s[k], 0, sizeof s[k]);
        build(&s[k], seed, heavy);
        s[k].contacts = dJointGroupCreate(0);
        dWorldSetQuickStepNumIterations(s[k].w, 20);
    }
    const size_t n = (size_t)(13 * s[0].nb + 6) * sizeof(dReal);
    int differ = -1, way = 0;
    for (int t = 0; t < STEPS && differ < 0; t++) {
        for (int k = 0; k < WAYS; k++) {
            contacts_now(&s[k]);
            dxQuickBuildJoints = room[k];
            dWorldQuickStep(s[k].w, REAL(0.01));
            dxQuickBuildJoints = saved;
            state_of(&s[k], x[k]);
        }
        for (int k = 1; k < WAYS && differ < 0; k++) {
            if (memcmp(x[0], x[k], n) != 0) {
                differ = t;
                way = k;
            }
        }
    }
    for (int k = 0; k < WAYS; k++) {
        dJointGroupDestroy(s[k].contacts);
        dWorldDestroy(s[k].w);
    }
    if (differ >= 0) test_fail(__FILE__, __LINE__, "seed %u%s, queue of %d joints: states "
                               "differ from step %d", (unsigned)seed, heavy ? " (heavy)" : "",
                               room[way], differ);
    return differ >= 0;
}

static int test_islands_built_in_phases_step_as_one_by_one(void)
{
    for (uint32_t seed = 1; seed <= 6; seed++) CHECK(same_every_way(seed, 0) == 0);
    for (uint32_t seed = 1; seed <= 3; seed++) CHECK(same_every_way(seed, 1) == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_islands_built_in_phases_step_as_one_by_one),
    TEST_END,
};
