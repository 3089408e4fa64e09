// SPDX-License-Identifier: BSD-3-Clause
//
// test_position_correction.c -- dWorldSetPositionIterations
// (<ode/position_correction.h>): a 100-link chain released horizontal holds
// together under dWorldStep with a few sweeps; 0 sweeps (the default) is the
// step as before, to the bit; bad input is reported.

#include "test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define LINKS 100
#define LINK 0.1

typedef struct chain {
    dWorldID w;
    dBodyID body[LINKS];
    dJointID joint[LINKS];
} chain;

// The chain of bench/chain.c without its collisions: capsules 10 cm long
// (radius 2.5 cm, 0.1 kg) on ball joints along +x from a world anchor at the
// origin, released horizontal under gravity.
static void chain_make(chain *c)
{
    c->w = dWorldCreate();
    dWorldSetGravity(c->w, 0, 0, -9.81);
    dMass m;
    dMassSetCapsuleTotal(&m, 0.1, 3, 0.025, LINK - 0.05);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);
    for (int i = 0; i < LINKS; i++) {
        c->body[i] = dBodyCreate(c->w);
        dBodySetMass(c->body[i], &m);
        dBodySetPosition(c->body[i], (i + 0.5) * LINK, 0, 0);
        dBodySetRotation(c->body[i], R);
        c->joint[i] = dJointCreateBall(c->w, 0);
        dJointAttach(c->joint[i], c->body[i], i > 0 ? c->body[i - 1] : 0);
        dJointSetBallAnchor(c->joint[i], i * LINK, 0, 0);
    }
}

// The distance between the two anchors of each joint: their sum, and the
// largest in *largest.
static double chain_separation(const chain *c, double *largest)
{
    double sum = 0;
    *largest = 0;
    for (int i = 0; i < LINKS; i++) {
        dVector3 a1, a2;
        dJointGetBallAnchor(c->joint[i], a1);
        dJointGetBallAnchor2(c->joint[i], a2);
        const double d = dCalcPointsDistance3(a1, a2);
        sum += d;
        *largest = fmax(*largest, d);
    }
    return sum;
}

typedef struct chain_result {
    double largest;   // the largest separation of one joint over the run (bench/chain's joint_sep)
    double sum;       // the largest sum over the joints over the run
} chain_result;

// The chain stepped for `steps` steps at 1/100 with n position sweeps.
static chain_result chain_run(int n, int stepper, int steps)
{
    chain c;
    chain_make(&c);
    dWorldSetPositionIterations(c.w, n);
    chain_result r = { 0, 0 };
    for (int s = 0; s < steps; s++) {
        if (stepper == 0) dWorldStep(c.w, 0.01);
        else if (stepper == 1) dWorldQuickStep(c.w, 0.01);
        else dWorldStepFast1(c.w, 0.01, 5);
        double largest;
        r.sum = fmax(r.sum, chain_separation(&c, &largest));
        r.largest = fmax(r.largest, largest);
    }
    dWorldDestroy(c.w);
    return r;
}

// Without sweeps the chain whips apart (bench/chain.c, which also collides
// the links, reports 1.62 m for one joint over 3 s); with 8 sweeps no joint
// opens by 1 cm over 10 s. The sum over the 100 joints converges more
// slowly (Gauss-Seidel carries a correction along a chain a few links a
// sweep), and is reported. Fewer sweeps can be worse than none: 2 are, and
// 4 are on the edge (under 1 cm in double precision, apart in single).
static int test_chain_holds_together_with_a_few_sweeps(void)
{
    static const int sweeps[] = { 0, 2, 4, 8, 16 };
    chain_result r[5];
    for (int k = 0; k < 5; k++) {
        r[k] = chain_run(sweeps[k], 0, 1000);
        printf("# 100-link chain, 10 s of dWorldStep at 1/100, %2d sweeps: largest joint "
               "separation %.4f m, largest sum over the joints %.4f m\n", sweeps[k],
               r[k].largest, r[k].sum);
    }
    CHECK(r[0].largest > 1);      // without them it comes apart
    CHECK(r[3].largest < 0.01);   // 8 sweeps hold every joint within 1 cm
    CHECK(r[4].sum < r[3].sum && r[3].sum < r[0].sum / 10);
    return 0;
}

// Default and n = 0: the step is the one without this feature, to the bit
// (the same world stepped with and without setting 0 explicitly, and a world
// whose sweeps were set and then set back to 0).
static int test_zero_sweeps_is_the_step_unchanged(void)
{
    chain a, b;
    chain_make(&a);
    chain_make(&b);
    CHECK(dWorldGetPositionIterations(a.w) == 0);
    dWorldSetPositionIterations(b.w, 3);
    CHECK(dWorldGetPositionIterations(b.w) == 3);
    dWorldSetPositionIterations(b.w, 0);

    for (int s = 0; s < 200; s++) {
        dWorldStep(a.w, 0.01);
        dWorldStep(b.w, 0.01);
    }

    for (int i = 0; i < LINKS; i++) {
        CHECK(!memcmp(dBodyGetPosition(a.body[i]), dBodyGetPosition(b.body[i]),
                      3 * sizeof(dReal)));
        CHECK(!memcmp(dBodyGetQuaternion(a.body[i]), dBodyGetQuaternion(b.body[i]),
                      4 * sizeof(dReal)));
    }
    dWorldDestroy(a.w);
    dWorldDestroy(b.w);
    return 0;
}

// The sweeps move positions only: a joint already without error is not
// touched, and the velocities the step computed are kept.
static int test_sweeps_leave_velocities_alone(void)
{
    chain a, b;
    chain_make(&a);
    chain_make(&b);
    dWorldSetPositionIterations(b.w, 4);

    dWorldStep(a.w, 0.01);
    dWorldStep(b.w, 0.01);

    for (int i = 0; i < LINKS; i++) {
        CHECK(!memcmp(dBodyGetLinearVel(a.body[i]), dBodyGetLinearVel(b.body[i]),
                      3 * sizeof(dReal)));
        CHECK(!memcmp(dBodyGetAngularVel(a.body[i]), dBodyGetAngularVel(b.body[i]),
                      3 * sizeof(dReal)));
    }
    dWorldDestroy(a.w);
    dWorldDestroy(b.w);
    return 0;
}

static int test_quickstep_holds_the_chain_too(void)
{
    const chain_result off = chain_run(0, 1, 300), on = chain_run(8, 1, 300);
    printf("# QuickStep, 3 s: largest joint separation %.4f m without sweeps, %.4f m with 8\n",
           off.largest, on.largest);
    // (QuickStep's 20 iterations leave joint error in the velocities that
    // dWorldStep removes, so more drift is left for the sweeps.)
    CHECK(on.largest < off.largest / 20);
    return 0;
}

// StepFast1 takes no sweeps: its sub-steps relax the joints one by one
// already (sweeps after its last sub-step left this chain at 0.13 m instead
// of 0.06 m). The setting changes nothing there, to the bit.
static int test_stepfast1_ignores_the_setting(void)
{
    chain a, b;
    chain_make(&a);
    chain_make(&b);
    dWorldSetPositionIterations(b.w, 8);

    for (int s = 0; s < 50; s++) {
        dWorldStepFast1(a.w, 0.01, 5);
        dWorldStepFast1(b.w, 0.01, 5);
    }

    for (int i = 0; i < LINKS; i++)
        CHECK(!memcmp(dBodyGetPosition(a.body[i]), dBodyGetPosition(b.body[i]),
                      3 * sizeof(dReal)));
    dWorldDestroy(a.w);
    dWorldDestroy(b.w);
    return 0;
}

static int test_negative_count_is_reported(void)
{
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dWorldSetPositionIterations(w, 2);

    dWorldSetPositionIterations(w, -1);
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dWorldSetPositionIterations"));
    CHECK(test_captured_contains("n must be >= 0"));
    CHECK(dWorldGetPositionIterations(w) == 2);
    dWorldSetPositionIterations(NULL, 1);
    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("world is NULL"));
    dWorldDestroy(w);
    test_release_reports();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_chain_holds_together_with_a_few_sweeps),
    TEST_CASE(test_zero_sweeps_is_the_step_unchanged),
    TEST_CASE(test_sweeps_leave_velocities_alone),
    TEST_CASE(test_quickstep_holds_the_chain_too),
    TEST_CASE(test_stepfast1_ignores_the_setting),
    TEST_CASE(test_negative_count_is_reported),
    TEST_END
};
