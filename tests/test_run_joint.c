// SPDX-License-Identifier: BSD-3-Clause
//
// test_run_joint.c -- QuickStep takes a joint whose unbounded rows are one
// run (hinge-2 joints, hinges and universal joints at their stops or with
// motors, contacts with two infinite friction rows) into its block and the
// rows coupled to it without the general search (quickstep_build.c's
// run_joint). Both ways must give the same bits: each scene is stepped with
// dxQuickRunJoints on and off, and the bodies' states compared after every
// step. The scenes: hinge-2 joints under random parameters (stops, locked
// stops, motors on either axis, suspension ERP and CFM, FMax, fudge factor,
// stop ERP and CFM, bounce; between two bodies, or one body and the world
// either way round), hinges and universal joints swinging into their stops
// with motors, and boxes resting on the ground through contacts of infinite
// friction.

#include "test.h"
#include "quickstep.h"
#include "random_joints.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

enum { MAX_BODIES = 40, STEPS = 200 };

typedef struct scene {
    dWorldID w;
    dJointGroupID contacts;
    dBodyID b[MAX_BODIES];
    int nb;
} scene;

static dBodyID body_at(scene *s, uint32_t *r, dReal x, dReal y, dReal z)
{
    dBodyID b = random_body(s->w, r, x, y, z);
    s->b[s->nb++] = b;
    return b;
}

// Cars of a chassis and hinge-2 wheels, some wheels held by the world.
static void build_hinge2(scene *s, uint32_t seed)
{
    uint32_t r = seed;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    for (int c = 0; c < 6; c++) {
        const dReal x = (dReal)(2 * c);
        dBodyID chassis = body_at(s, &r, x, 0, 1);
        for (int k = 0; k < 4; k++) {
            const dReal wx = x + (k < 2 ? REAL(0.4) : REAL(-0.4));
            const dReal wy = k % 2 ? REAL(-0.3) : REAL(0.3);
            dBodyID wheel = body_at(s, &r, wx, wy, REAL(0.9));
            dJointID j = dJointCreateHinge2(s->w, 0);
            const uint32_t how = next_random(&r) >> 29;
            if (how == 0) dJointAttach(j, wheel, 0);
            else if (how == 1) dJointAttach(j, 0, wheel);
            else dJointAttach(j, chassis, wheel);
            dJointSetHinge2Anchor(j, wx, wy, REAL(0.9));
            const dReal up[3] = { uniform(&r, -0.2, 0.2), uniform(&r, -0.2, 0.2), 1 };
            const dReal across[3] = { uniform(&r, -0.2, 0.2), 1, 0 };
            dJointSetHinge2Axes(j, up, across);
            dJointSetHinge2Param(j, dParamSuspensionERP, uniform(&r, 0.1, 0.9));
            dJointSetHinge2Param(j, dParamSuspensionCFM, uniform(&r, 0.001, 0.05));
            random_limot(&r, j, 0, dJointSetHinge2Param);
            random_limot(&r, j, 1, dJointSetHinge2Param);
        }
    }
}

// Chains of hinges and universal joints with stops and motors, swinging.
static void build_hinges(scene *s, uint32_t seed)
{
    uint32_t r = seed;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    for (int c = 0; c < 4; c++) {
        dBodyID last = NULL;
        for (int k = 0; k < 5; k++) {
            const dReal x = (dReal)(2 * c), z = (dReal)(2 - REAL(0.4) * k);
            dBodyID b = body_at(s, &r, x, 0, z);
            if (k % 2 == 0) {
                dJointID j = dJointCreateHinge(s->w, 0);
                dJointAttach(j, b, last);
                dJointSetHingeAnchor(j, x, 0, z + REAL(0.2));
                dJointSetHingeAxis(j, uniform(&r, -0.3, 0.3), 1, 0);
                random_limot(&r, j, 0, dJointSetHingeParam);
            } else {
                dJointID j = dJointCreateUniversal(s->w, 0);
                dJointAttach(j, b, last);
                dJointSetUniversalAnchor(j, x, 0, z + REAL(0.2));
                dJointSetUniversalAxis1(j, 1, 0, 0);
                dJointSetUniversalAxis2(j, 0, 1, uniform(&r, -0.3, 0.3));
                random_limot(&r, j, 0, dJointSetUniversalParam);
                random_limot(&r, j, 1, dJointSetUniversalParam);
            }
            last = b;
        }
    }
}

// Boxes on the ground (z = 0), each held by four contacts of infinite
// friction made anew every step (contacts_now).
static void build_boxes(scene *s, uint32_t seed)
{
    uint32_t r = seed;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    for (int k = 0; k < 8; k++) body_at(s, &r, (dReal)k, 0, REAL(0.19));
}

// The contacts of the boxes' bottom corners below z = 0.
static void contacts_now(scene *s)
{
    dJointGroupEmpty(s->contacts);
    for (int k = 0; k < s->nb; k++) ground_contacts(s->w, s->contacts, s->b[k], dInfinity);
}

// Steps the scene built by build(seed) with run joints on and off; 0 if
// every step's state is the same bits.
static int same_either_way(void (*build)(scene *, uint32_t), uint32_t seed, int contacts)
{
    static dReal x[2][13 * MAX_BODIES];
    scene s[2];
    for (int k = 0; k < 2; k++) {
        memset(&s[k], 0, sizeof s[k]);
        build(&s[k], seed);
        s[k].contacts = dJointGroupCreate(0);
        dWorldSetQuickStepNumIterations(s[k].w, 20);
    }
    int differ = -1;
    for (int n = 0; n < STEPS && differ < 0; n++) {
        for (int k = 0; k < 2; k++) {
            if (contacts) contacts_now(&s[k]);
            dxQuickRunJoints = k == 0;
            dWorldQuickStep(s[k].w, REAL(0.01));
            dxQuickRunJoints = 1;
            body_states(s[k].b, s[k].nb, x[k]);
        }
        if (memcmp(x[0], x[1], (size_t)13 * s[0].nb * sizeof(dReal)) != 0) differ = n;
    }
    for (int k = 0; k < 2; k++) {
        dJointGroupDestroy(s[k].contacts);
        dWorldDestroy(s[k].w);
    }
    if (differ >= 0) test_fail(__FILE__, __LINE__, "seed %u: states differ from step %d",
                               (unsigned)seed, differ);
    return differ >= 0;
}

static int test_hinge2_joints_step_the_same_either_way(void)
{
    for (uint32_t seed = 1; seed <= 12; seed++) CHECK(same_either_way(build_hinge2, seed, 0) == 0);
    return 0;
}

static int test_hinges_at_stops_step_the_same_either_way(void)
{
    for (uint32_t seed = 1; seed <= 12; seed++) CHECK(same_either_way(build_hinges, seed, 0) == 0);
    return 0;
}

static int test_infinite_friction_contacts_step_the_same_either_way(void)
{
    for (uint32_t seed = 1; seed <= 4; seed++) CHECK(same_either_way(build_boxes, seed, 1) == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_hinge2_joints_step_the_same_either_way),
    TEST_CASE(test_hinges_at_stops_step_the_same_either_way),
    TEST_CASE(test_infinite_friction_contacts_step_the_same_either_way),
    TEST_END,
};
