// SPDX-License-Identifier: BSD-3-Clause
//
// test_overlap_sweeps.c -- QuickStep's sweeps of an island of blocks alone
// overlapped (dxQuickSweepOverlapped: sweep s's block k at time k + s lag)
// must give the same bits as the sweeps one after the other. Each scene
// runs twice, overlapping on and off (dxQuickOverlapSweeps), and every
// body's state is compared after every step: chains of ball and hinge
// joints (limits and motors, whose rows are coupled to their blocks), hung
// from the world at one end or both, a ring, chains too short to be
// overlapped and a chain whose joints were made out of order.

#include "test.h"
#include "quickstep.h"

#include <string.h>

enum { STEPS = 300, MAX_BODIES = 160 };
#define STATE (13 * MAX_BODIES)

typedef struct links {
    dWorldID w;
    dBodyID body[MAX_BODIES];
    int nb;
} links;

static dBodyID add_link(links *s, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(s->w);
    dMass m;
    dMassSetBoxTotal(&m, 0.1, 0.1, 0.02, 0.02);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    s->body[s->nb++] = b;
    return b;
}

// A joint between a and b (b may be 0: the world) at (x, y, z): a ball, or
// a hinge about y with stops and a motor.
static void add_joint(links *s, int hinge, dBodyID a, dBodyID b, dReal x, dReal y, dReal z)
{
    dJointID j;
    if (hinge) {
        j = dJointCreateHinge(s->w, 0);
        dJointAttach(j, a, b);
        dJointSetHingeAnchor(j, x, y, z);
        dJointSetHingeAxis(j, 0, 1, 0);
        dJointSetHingeParam(j, dParamLoStop, -0.4);
        dJointSetHingeParam(j, dParamHiStop, 0.3);
        dJointSetHingeParam(j, dParamVel, 0.5);
        dJointSetHingeParam(j, dParamFMax, 0.05);
    } else {
        j = dJointCreateBall(s->w, 0);
        dJointAttach(j, a, b);
        dJointSetBallAnchor(j, x, y, z);
    }
}

// n links along x from (x0, y, 2), the first hung from the world; ends: the
// last hung from the world too; kinds: every other joint a hinge.
static void add_chain(links *s, int n, dReal x0, dReal y, int ends, int kinds)
{
    dBodyID prev = 0;
    for (int i = 0; i < n; i++) {
        dBodyID b = add_link(s, x0 + 0.1 * (i + 0.5), y, 2);
        add_joint(s, kinds && i % 2, b, prev, x0 + 0.1 * i, y, 2);
        prev = b;
    }
    if (ends) add_joint(s, 0, prev, 0, x0 + 0.1 * n, y, 2);
}

// A ring of n links about (x0, y, 2) in the x-z plane, each joined to the
// next, the last to the first.
static void add_ring(links *s, int n, dReal x0, dReal y)
{
    const int first = s->nb;
    const dReal r = 0.1 * n / (2 * M_PI);
    for (int i = 0; i < n; i++) {
        const dReal a = 2 * M_PI * (i + 0.5) / n;
        add_link(s, x0 + r * cos(a), y, 2 + r * sin(a));
    }
    for (int i = 0; i < n; i++) {
        const dReal a = 2 * M_PI * (i + 1) / n;
        add_joint(s, 0, s->body[first + i], s->body[first + (i + 1) % n], x0 + r * cos(a), y,
                  2 + r * sin(a));
    }
    dBodySetLinearVel(s->body[first], 0, 0, 3);
}

// n ball-joined links whose joints are made in a scattered order.
static void add_scattered_chain(links *s, int n, dReal x0, dReal y)
{
    const int first = s->nb;
    for (int i = 0; i < n; i++) add_link(s, x0 + 0.1 * (i + 0.5), y, 2);
    for (int k = 0; k < n; k++) {
        const int i = (k * 7) % n;   // n not a multiple of 7
        add_joint(s, 0, s->body[first + i], i > 0 ? s->body[first + i - 1] : 0, x0 + 0.1 * i, y,
                  2);
    }
}

static void build(links *s)
{
    memset(s, 0, sizeof *s);
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, -9.81);
    add_chain(s, 40, 0, 0, 0, 1);
    add_chain(s, 24, 0, 1, 1, 0);
    add_ring(s, 20, 0, 2);
    add_chain(s, 10, 0, 3, 0, 1);   // too short to be overlapped
    add_scattered_chain(s, 32, 0, 4);
    add_chain(s, 16, 0, 5, 0, 0);   // just long enough
}

static void state(const links *s, dReal *out)
{
    for (int i = 0; i < s->nb; i++, out += 13) {
        memcpy(out, dBodyGetPosition(s->body[i]), 3 * sizeof(dReal));
        memcpy(out + 3, dBodyGetQuaternion(s->body[i]), 4 * sizeof(dReal));
        memcpy(out + 7, dBodyGetLinearVel(s->body[i]), 3 * sizeof(dReal));
        memcpy(out + 10, dBodyGetAngularVel(s->body[i]), 3 * sizeof(dReal));
    }
}

static dReal states[2][STEPS][STATE];

static void run(int overlap, dReal (*out)[STATE])
{
    links s;
    build(&s);
    dxQuickOverlapSweeps = overlap;
    for (int k = 0; k < STEPS; k++) {
        dWorldQuickStep(s.w, 0.01);
        state(&s, out[k]);
    }
    dxQuickOverlapSweeps = 1;
    dWorldDestroy(s.w);
}

static int test_overlapped_sweeps_give_the_same_bits(void)
{
    run(1, states[0]);
    run(0, states[1]);
    int differ = -1;
    for (int k = 0; k < STEPS && differ < 0; k++)
        if (memcmp(states[0][k], states[1][k], sizeof states[0][k])) differ = k;
    if (differ >= 0) test_fail(__FILE__, __LINE__, "states differ from step %d", differ);
    CHECK(differ < 0);
    // The chains moved (and stayed finite): the comparison compared something.
    CHECK(states[0][STEPS - 1][13 * 39 + 2] < 1.5);
    CHECK(states[0][STEPS - 1][13 * 39 + 2] == states[0][STEPS - 1][13 * 39 + 2]);
    return 0;
}

// The same with the sweeps' version without fused multiply-adds
// (quickstep.h: dxQuickFused), the one processors without FMA run.
static int test_unfused_overlapped_sweeps_give_the_same_bits(void)
{
    const int fused = dxQuickFused;
    dxQuickFused = 0;
    const int failed = test_overlapped_sweeps_give_the_same_bits();
    dxQuickFused = fused;
    CHECK(!failed);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_overlapped_sweeps_give_the_same_bits),
    TEST_CASE(test_unfused_overlapped_sweeps_give_the_same_bits),
    TEST_END,
};
