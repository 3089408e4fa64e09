// SPDX-License-Identifier: BSD-3-Clause
//
// test_equality_block.c -- QuickStep writes the rows of a joint whose rows
// are all equalities (ball, fixed, hinge or universal off their stops)
// straight into its block; any other joint goes the generic way over a row
// buffer. Both ways must give the same bits. Each scene is stepped twice:
// once as built, once with every joint given a copy of its class that
// counts one row fewer as unbounded (nub), which only the straight way
// looks at: the rows and their numbers stay the same, the generic way takes
// them. A joint whose block is singular (a universal joint with parallel
// axes at world CFM 0: its fourth row is zero) must fall back to the
// generic way and behave as it does there.

#include "test.h"
#include "objects_internal.h"

#include <math.h>
#include <string.h>

enum { MAX_JOINTS = 8, MAX_BODIES = 8 };
static dxJointClass generic_class[MAX_JOINTS];
static void (*count_rows_of[MAX_JOINTS])(dxJoint *, dxJointRowCount *);
static dxJoint *joint_at[MAX_JOINTS];
static int njoints;

// The joint's own count, with one row fewer counted unbounded.
static void generic_count_rows(dxJoint *j, dxJointRowCount *count)
{
    for (int k = 0; k < njoints; k++)
        if (joint_at[k] == j) count_rows_of[k](j, count);
    if (count->nub > 0) count->nub--;
}

static void make_generic(dJointID jid)
{
    dxJoint *j = (dxJoint *)jid;
    const int k = njoints++;
    generic_class[k] = *j->cls;
    count_rows_of[k] = j->cls->count_rows;
    generic_class[k].count_rows = generic_count_rows;
    joint_at[k] = j;
    j->cls = &generic_class[k];
}

typedef struct scene {
    dWorldID w;
    dBodyID b[MAX_BODIES];
    int nb;
} scene;

static dBodyID body_at(scene *s, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(s->w);
    dMass m;
    dMassSetBoxTotal(&m, 1, REAL(0.2), REAL(0.3), REAL(0.4));
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    dBodySetAngularVel(b, REAL(0.3) * s->nb, REAL(-0.2), REAL(0.1));
    s->b[s->nb++] = b;
    return b;
}

// A hanging chain of ball, hinge, universal and fixed joints, released
// spinning; `generic`: every joint forced the generic way.
static void build_chain(scene *s, int generic)
{
    njoints = 0;
    s->nb = 0;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    dBodyID a = body_at(s, 0, 0, 2), b = body_at(s, REAL(0.5), 0, 2);
    dBodyID c = body_at(s, 1, 0, 2), d = body_at(s, REAL(1.5), 0, 2);
    dBodyID e = body_at(s, 2, 0, 2);
    dJointID j[5];
    j[0] = dJointCreateBall(s->w, 0);
    dJointAttach(j[0], a, 0);
    dJointSetBallAnchor(j[0], REAL(-0.25), 0, 2);
    j[1] = dJointCreateHinge(s->w, 0);
    dJointAttach(j[1], a, b);
    dJointSetHingeAnchor(j[1], REAL(0.25), 0, 2);
    dJointSetHingeAxis(j[1], 0, 1, 0);
    j[2] = dJointCreateUniversal(s->w, 0);
    dJointAttach(j[2], b, c);
    dJointSetUniversalAnchor(j[2], REAL(0.75), 0, 2);
    dJointSetUniversalAxis1(j[2], 0, 1, 0);
    dJointSetUniversalAxis2(j[2], 0, 0, 1);
    j[3] = dJointCreateFixed(s->w, 0);
    dJointAttach(j[3], c, d);
    dJointSetFixed(j[3]);
    j[4] = dJointCreateBall(s->w, 0);
    dJointAttach(j[4], d, e);
    dJointSetBallAnchor(j[4], REAL(1.75), 0, 2);
    if (generic)
        for (int k = 0; k < 5; k++) make_generic(j[k]);
}

// A box hanging from the world by a universal joint whose axes are parallel
// (its fourth row is zero), at world CFM 0: the joint's block is singular.
static void build_singular(scene *s, int generic)
{
    njoints = 0;
    s->nb = 0;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    dWorldSetCFM(s->w, 0);
    dBodyID a = body_at(s, REAL(0.5), 0, 1);
    dBodySetAngularVel(a, 0, REAL(-0.2), 0);   // (about the axes: the row stays exactly zero)
    dJointID j = dJointCreateUniversal(s->w, 0);
    dJointAttach(j, a, 0);
    dJointSetUniversalAnchor(j, 0, 0, 1);
    dJointSetUniversalAxis1(j, 0, 1, 0);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    if (generic) make_generic(j);
}

// A chain in the xz plane, turning about y only: a ball joint to the world,
// a universal joint with parallel axes (singular at world CFM 0, as in
// build_singular), a hinge and a ball joint. The equality joints' blocks are
// made in passes over the island (quickstep_build.c): the singular block
// must fall back to the generic way in its own place among the others.
static void build_singular_in_chain(scene *s, int generic)
{
    njoints = 0;
    s->nb = 0;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    dWorldSetCFM(s->w, 0);
    dBodyID b[4];
    for (int k = 0; k < 4; k++) {
        b[k] = body_at(s, REAL(0.5) * (k + 1), 0, 1);
        dBodySetAngularVel(b[k], 0, REAL(-0.2) * (k + 1), 0);
    }
    dJointID j[4];
    j[0] = dJointCreateBall(s->w, 0);
    dJointAttach(j[0], b[0], 0);
    dJointSetBallAnchor(j[0], REAL(0.25), 0, 1);
    j[1] = dJointCreateUniversal(s->w, 0);
    dJointAttach(j[1], b[0], b[1]);
    dJointSetUniversalAnchor(j[1], REAL(0.75), 0, 1);
    dJointSetUniversalAxis1(j[1], 0, 1, 0);
    dJointSetUniversalAxis2(j[1], 0, 1, 0);
    j[2] = dJointCreateHinge(s->w, 0);
    dJointAttach(j[2], b[1], b[2]);
    dJointSetHingeAnchor(j[2], REAL(1.25), 0, 1);
    dJointSetHingeAxis(j[2], 0, 1, 0);
    j[3] = dJointCreateBall(s->w, 0);
    dJointAttach(j[3], b[2], b[3]);
    dJointSetBallAnchor(j[3], REAL(1.75), 0, 1);
    if (generic)
        for (int k = 0; k < 4; k++) make_generic(j[k]);
}

// Every body's position, quaternion and velocities.
static void state_of(const scene *s, dReal *out)
{
    for (int i = 0; i < s->nb; i++) {
        memcpy(out, dBodyGetPosition(s->b[i]), 3 * sizeof(dReal));
        memcpy(out + 3, dBodyGetQuaternion(s->b[i]), 4 * sizeof(dReal));
        memcpy(out + 7, dBodyGetLinearVel(s->b[i]), 3 * sizeof(dReal));
        memcpy(out + 10, dBodyGetAngularVel(s->b[i]), 3 * sizeof(dReal));
        out += 13;
    }
}

// Steps the scene both ways; 0 if every step's state is the same bits.
static int same_either_way(void (*build)(scene *, int), int steps, dReal *last)
{
    scene s[2];
    build(&s[0], 0);
    build(&s[1], 1);
    for (int n = 0; n < steps; n++) {
        dReal x[2][13 * MAX_BODIES];
        for (int k = 0; k < 2; k++) {
            dWorldQuickStep(s[k].w, REAL(0.01));
            state_of(&s[k], x[k]);
        }
        if (memcmp(x[0], x[1], (size_t)13 * s[0].nb * sizeof(dReal)) != 0) {
            test_fail(__FILE__, __LINE__, "states differ from step %d", n);
            return 1;
        }
        if (last) memcpy(last, x[0], (size_t)13 * s[0].nb * sizeof(dReal));
    }
    dWorldDestroy(s[0].w);
    dWorldDestroy(s[1].w);
    return 0;
}

static int test_equality_joints_step_the_same_either_way(void)
{
    CHECK(same_either_way(build_chain, 300, NULL) == 0);
    return 0;
}

static int test_singular_block_falls_back_to_the_generic_way(void)
{
    dReal last[13];
    CHECK(same_either_way(build_singular, 300, last) == 0);
    // Everything finite, and the anchor held: the box's centre stays 0.5 m
    // from it (within 5 cm after 3 s of swinging: without a
    // block, the rows are solved one at a time and hold less tightly).
    for (int k = 0; k < 13; k++) CHECK(isfinite(last[k]));
    const dReal dx = last[0], dy = last[1], dz = last[2] - 1;
    CHECK_NEAR(sqrt(dx * dx + dy * dy + dz * dz), 0.5, 0.05);
    return 0;
}

static int test_singular_block_among_others_keeps_its_place(void)
{
    dReal last[13 * 4];
    CHECK(same_either_way(build_singular_in_chain, 300, last) == 0);
    for (int k = 0; k < 13 * 4; k++) CHECK(isfinite(last[k]));
    // The chain still hangs from its anchor: the first box's centre stays
    // 0.25 m from it (within 5 cm).
    const dReal dx = last[0] - REAL(0.25), dy = last[1], dz = last[2] - 1;
    CHECK_NEAR(sqrt(dx * dx + dy * dy + dz * dz), 0.25, 0.05);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_equality_joints_step_the_same_either_way),
    TEST_CASE(test_singular_block_falls_back_to_the_generic_way),
    TEST_CASE(test_singular_block_among_others_keeps_its_place),
    TEST_END,
};
