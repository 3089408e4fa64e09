// SPDX-License-Identifier: BSD-3-Clause
//
// test_watchdog.c -- dWorldSetWatchdog: each kind of blow-up is provoked and
// its report checked (what was detected, the likely cause, the bodies and
// joints named, the words); a roll back restores the state before the step;
// a watched world that stays sane steps exactly as an unwatched one.

#include "test.h"

#include <ode/snapshot.h>
#include <string.h>

#ifdef dSINGLE
#define HUGE_SPEED REAL(1e37)
#else
#define HUGE_SPEED REAL(1e306)
#endif

typedef struct seen {
    int calls;
    dWatchdogReport last;
    int answer;   // what the callback returns (1: roll back)
} seen;

static int remember(void *user, dWorldID w, const dWatchdogReport *r)
{
    (void)w;
    seen *s = user;
    s->calls++;
    s->last = *r;
    return s->answer;
}

static int names_body(const dWatchdogReport *r, dBodyID b)
{
    for (int i = 0; i < r->num_bodies; i++)
        if (r->bodies[i] == b) return 1;
    return 0;
}

static int names_joint(const dWatchdogReport *r, dJointID j)
{
    for (int i = 0; i < r->num_joints; i++)
        if (r->joints[i] == j) return 1;
    return 0;
}

static dBodyID unit_body(dWorldID w, dReal x, dReal y, dReal z, dReal mass)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, mass, REAL(0.5));
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

static void watch(dWorldID w, seen *s)
{
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    dWorldSetWatchdog(w, &l, remember, s);
}

static int test_non_finite_state_is_detected(void)
{
    dWorldID w = dWorldCreate();
    unit_body(w, 0, 0, 0, 1);
    dBodyID b = unit_body(w, 5, 0, 0, 1);
    dBodySetLinearVel(b, HUGE_SPEED, 0, 0);
    seen s = { 0 };
    watch(w, &s);

    dWorldStep(w, 1000);   // the position overflows

    CHECK(s.calls == 1);
    CHECK(s.last.detected & dWatchdogNonFinite);
    CHECK(s.last.num_bodies == 1 && names_body(&s.last, b));
    CHECK(strstr(s.last.text, "body #1: state is not finite") != NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_fast_spin_is_blamed_on_the_step_size(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = unit_body(w, 0, 0, 0, 1);
    dBodySetAngularVel(b, 0, 0, 100);
    seen s = { 0 };
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    l.max_angular_speed = 50;
    dWorldSetWatchdog(w, &l, remember, &s);

    dWorldQuickStep(w, REAL(0.01));   // 1 rad per step

    CHECK(s.calls == 1);
    CHECK(s.last.detected == dWatchdogAngularSpeed);
    CHECK(s.last.causes == dWatchdogCauseLargeStep);
    CHECK(names_body(&s.last, b));
    CHECK(strstr(s.last.text, "angular speed 100 > 50") != NULL);
    CHECK(strstr(s.last.text, "step too large, body #0 turns 1 rad") != NULL);
    dWorldDestroy(w);
    return 0;
}

// Two bodies joined by a ball joint, pulled 1 m apart.
static int test_joint_pulled_apart_is_named(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = unit_body(w, 0, 0, 0, 1);
    dBodyID b = unit_body(w, 1, 0, 0, 1);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, a, b);
    dJointSetBallAnchor(j, REAL(0.5), 0, 0);
    dBodySetPosition(b, 2, 0, 0);
    seen s = { 0 };
    watch(w, &s);

    dWorldStep(w, REAL(0.01));

    CHECK(s.calls == 1);
    CHECK(s.last.detected & dWatchdogJointError);
    CHECK(s.last.causes == dWatchdogCauseJointPulledApart);   // equal masses
    CHECK(names_joint(&s.last, j));
    CHECK(strstr(s.last.text, "joint #0 (ball): pulled apart") != NULL);
    dWorldDestroy(w);
    return 0;
}

// A light body holding a very heavy one on a hinge: under QuickStep the
// joint cannot hold, and the mass ratio is named as the cause.
static int test_mass_ratio_is_named(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, REAL(-9.81));
    dWorldSetQuickStepNumIterations(w, 5);
    dBodyID light = unit_body(w, 0, 0, 0, REAL(0.01));
    dBodyID heavy = unit_body(w, 1, 0, 0, 1000);
    dJointID top = dJointCreateBall(w, 0);
    dJointAttach(top, light, 0);
    dJointSetBallAnchor(top, 0, 0, 0);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, light, heavy);
    dJointSetHingeAnchor(j, REAL(0.5), 0, 0);
    dJointSetHingeAxis(j, 0, 1, 0);
    seen s = { 0 };
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    l.max_joint_error = REAL(0.01);
    dWorldSetWatchdog(w, &l, remember, &s);

    for (int i = 0; i < 200 && s.calls == 0; i++) dWorldQuickStep(w, REAL(0.01));

    CHECK(s.calls >= 1);
    CHECK(s.last.detected & dWatchdogJointError);
    CHECK(s.last.causes & dWatchdogCauseMassRatio);
    CHECK(names_joint(&s.last, j));
    CHECK(strstr(s.last.text, "mass ratio 100000 > 100 across joint #1 (hinge)") != NULL);
    dWorldDestroy(w);
    return 0;
}

// A box held half a metre inside the ground by a contact joint is thrown
// out: energy grows from rest, and the deep contact is the cause.
static int test_deep_contact_is_named(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetERP(w, REAL(0.8));
    dWorldSetCFM(w, 0);   // (a hard contact: the speed is exactly ERP depth / h)
    dBodyID b = unit_body(w, 0, 0, 0, 1);
    dContact c;
    memset(&c, 0, sizeof c);
    c.surface.mode = 0;
    c.geom.pos[2] = REAL(-0.5);
    c.geom.normal[2] = 1;
    c.geom.depth = REAL(0.5);
    dJointGroupID group = dJointGroupCreate(0);
    dJointID contact = dJointCreateContact(w, group, &c);
    dJointAttach(contact, b, 0);
    seen s = { 0 };
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    l.min_energy = REAL(1e-3);
    dWorldSetWatchdog(w, &l, remember, &s);

    dWorldStep(w, REAL(0.01));   // 0.8 * 0.5 / 0.01 = 40 m/s up

    CHECK(s.calls == 1);
    CHECK(s.last.detected == dWatchdogEnergyGrowth);
    CHECK(s.last.causes == dWatchdogCauseInterpenetration);
    CHECK(names_body(&s.last, b) && names_joint(&s.last, contact));
    CHECK_NEAR(s.last.energy_after, 800, TOL(1e-9, 1e-2));
    CHECK(strstr(s.last.text, "kinetic energy grew from 0 to 800") != NULL);
    CHECK(strstr(s.last.text, "interpenetration, contact joint #0 of body #0 is 0.5 m deep")
          != NULL);
    dJointGroupDestroy(group);
    dWorldDestroy(w);
    return 0;
}

static int test_roll_back_restores_the_state_before_the_step(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, REAL(-9.81));
    dBodyID b = unit_body(w, 0, 0, 0, 1);
    dBodyID other = unit_body(w, 3, 0, 0, 1);
    seen s = { 0, { 0 }, 1 };
    watch(w, &s);
    CHECK(dWorldStep(w, REAL(0.01)) == 1);
    CHECK(s.calls == 0);
    dBodySetLinearVel(b, HUGE_SPEED, 0, 0);
    dReal pos[3], vel[3], pos2[3];
    memcpy(pos, dBodyGetPosition(b), sizeof pos);
    memcpy(vel, dBodyGetLinearVel(b), sizeof vel);
    memcpy(pos2, dBodyGetPosition(other), sizeof pos2);

    const int result = dWorldStep(w, 1000);

    CHECK(result == 0);
    CHECK(s.calls == 1);
    CHECK(memcmp(pos, dBodyGetPosition(b), sizeof pos) == 0);
    CHECK(memcmp(vel, dBodyGetLinearVel(b), sizeof vel) == 0);
    CHECK(memcmp(pos2, dBodyGetPosition(other), sizeof pos2) == 0);
    dWorldDestroy(w);
    return 0;
}

// Watched and unwatched worlds step to the same bits while nothing is wrong.
static int test_a_sane_watched_world_steps_as_an_unwatched_one(void)
{
    dWorldID w[2];
    dBodyID b[2][2];
    seen s = { 0 };
    for (int k = 0; k < 2; k++) {
        w[k] = dWorldCreate();
        dWorldSetGravity(w[k], 0, 0, REAL(-9.81));
        b[k][0] = unit_body(w[k], 0, 0, 0, 1);
        b[k][1] = unit_body(w[k], 1, 0, 0, 2);
        dJointID j = dJointCreateHinge(w[k], 0);
        dJointAttach(j, b[k][0], b[k][1]);
        dJointSetHingeAnchor(j, REAL(0.5), 0, 0);
        dJointSetHingeAxis(j, 0, 1, 0);
        dJointID top = dJointCreateBall(w[k], 0);
        dJointAttach(top, b[k][0], 0);
        dJointSetBallAnchor(top, 0, 0, 0);
    }
    watch(w[1], &s);

    for (int i = 0; i < 300; i++) {
        const int k = i % 3;
        for (int n = 0; n < 2; n++) {
            if (k == 0) dWorldStep(w[n], REAL(0.01));
            else if (k == 1) dWorldQuickStep(w[n], REAL(0.01));
            else dWorldStepFast1(w[n], REAL(0.01), 5);
        }
    }

    CHECK(s.calls == 0);
    for (int i = 0; i < 2; i++) {
        CHECK(memcmp(dBodyGetPosition(b[0][i]), dBodyGetPosition(b[1][i]),
                     3 * sizeof(dReal)) == 0);
        CHECK(memcmp(dBodyGetAngularVel(b[0][i]), dBodyGetAngularVel(b[1][i]),
                     3 * sizeof(dReal)) == 0);
    }
    dWorldSetWatchdog(w[1], NULL, NULL, NULL);   // off again
    dWorldDestroy(w[0]);
    dWorldDestroy(w[1]);
    return 0;
}

static int test_without_callback_the_report_is_a_message(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = unit_body(w, 0, 0, 0, 1);
    dBodySetLinearVel(b, 5000, 0, 0);
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    dWorldSetWatchdog(w, &l, NULL, NULL);
    test_capture_reports();

    CHECK(dWorldStep(w, REAL(0.01)) == 1);

    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("watchdog: step 1"));
    CHECK(test_captured_contains("body #0: linear speed 5000 > 1000 m/s"));
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

static int test_bad_arguments_are_reported(void)
{
    dWorldID w = dWorldCreate();
    dWatchdogLimits l;
    dWatchdogLimitsSetDefaults(&l);
    test_capture_reports();

    dWorldSetWatchdog(NULL, &l, NULL, NULL);
    CHECK(test_captured_count() == 1 && test_captured_contains("dWorldSetWatchdog: world"));
    l.max_linear_speed = -1;
    dWorldSetWatchdog(w, &l, NULL, NULL);
    CHECK(test_captured_count() == 2 && test_captured_contains("limits must be >= 0"));
    dWatchdogLimitsSetDefaults(NULL);
    CHECK(test_captured_count() == 3 && test_captured_contains("limits is NULL"));
    test_release_reports();
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_non_finite_state_is_detected),
    TEST_CASE(test_fast_spin_is_blamed_on_the_step_size),
    TEST_CASE(test_joint_pulled_apart_is_named),
    TEST_CASE(test_mass_ratio_is_named),
    TEST_CASE(test_deep_contact_is_named),
    TEST_CASE(test_roll_back_restores_the_state_before_the_step),
    TEST_CASE(test_a_sane_watched_world_steps_as_an_unwatched_one),
    TEST_CASE(test_without_callback_the_report_is_a_message),
    TEST_CASE(test_bad_arguments_are_reported),
    TEST_END
};
