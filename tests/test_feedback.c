// SPDX-License-Identifier: BSD-3-Clause
//
// test_feedback.c -- joint feedback reports the load a joint carries: a limit
// motor powering against its stop under both steppers (the stop's feedback
// balances the motor's push), stops set the wrong way round (ODE 0.16 holds
// the joint at the low stop), and a loaded bridge of hinged planks whose
// feedback forces are the forces that moved its bodies and whose supports
// carry exactly the weight of the bridge and its load.

#include "test.h"

#include <math.h>

typedef int (*stepper)(dWorldID, dReal);

// A slider body resting against its low stop while its motor (vel 0) pushes
// it into the stop with force fmax: the stop holds (the body does not move)
// and the joint's feedback is the stop's reaction, fmax along the axis.
static int powered_into_stop(stepper step)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBox(&m, 1, REAL(0.9), 4, REAL(0.1));
    dBodySetMass(b, &m);
    dJointID s = dJointCreateSlider(w, 0);
    dJointAttach(s, b, 0);
    dJointSetSliderAxis(s, 1, 0, 0);
    dJointSetSliderParam(s, dParamFMax, 4000);
    dJointSetSliderParam(s, dParamLoStop, 0);
    dJointSetSliderParam(s, dParamHiStop, REAL(0.2));
    dJointFeedback fb;
    dJointSetFeedback(s, &fb);
    for (int i = 0; i < 100; i++) {
        step(w, REAL(0.002));
        CHECK_NEAR(dJointGetSliderPosition(s), 0, TOL(1e-6, 1e-3));
        CHECK_NEAR(fb.f1[0], 4000, TOL(1e-3, 10));   // single: CFM 1e-5 softens the stop
    }
    dWorldDestroy(w);
    return 0;
}

// StepFast1 with 10 sub-steps; its rows are filled once per sub-step and
// joint, and the motor's push must still act once, not once per fill.
static int stepfast10(dWorldID w, dReal h)
{
    dWorldStepFast1(w, h, 10);
    return 1;
}

static int test_quickstep_stop_holds_powered_body(void) { return powered_into_stop(dWorldQuickStep); }
static int test_step_stop_holds_powered_body(void) { return powered_into_stop(dWorldStep); }
static int test_stepfast_stop_holds_powered_body(void) { return powered_into_stop(stepfast10); }

// Low stop above the high stop: as the guide says (dParamHiStop), both stops
// are ineffective, so the body moves freely both ways. (ODE 0.16 acts on
// them: docs/design.md.)
static int inverted_stops(stepper step)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphere(&m, 1, REAL(0.1));
    dMassAdjust(&m, 1);
    dBodySetMass(b, &m);
    dJointID s = dJointCreateSlider(w, 0);
    dJointAttach(s, b, 0);
    dJointSetSliderAxis(s, 1, 0, 0);
    dJointSetSliderParam(s, dParamLoStop, 0);
    dJointSetSliderParam(s, dParamHiStop, REAL(-0.2));
    for (int i = 0; i < 100; i++) {   // 1 N for 0.2 s: x = t^2 / 2
        dBodyAddForce(b, 1, 0, 0);
        step(w, REAL(0.002));
    }
    CHECK_NEAR(dJointGetSliderPosition(s), 0.02, 1e-3);
    for (int i = 0; i < 300; i++) {   // then -1 N for 0.6 s: x = 0.02 + 0.2 t - t^2 / 2
        dBodyAddForce(b, -1, 0, 0);
        step(w, REAL(0.002));
    }
    CHECK_NEAR(dJointGetSliderPosition(s), -0.04, 2e-3);
    dWorldDestroy(w);
    return 0;
}

static int test_quickstep_inverted_stops_are_ineffective(void) { return inverted_stops(dWorldQuickStep); }
static int test_step_inverted_stops_are_ineffective(void) { return inverted_stops(dWorldStep); }

// ---- a loaded bridge ------------------------------------------------------------

enum { PLANKS = 12, LOADS = 4, MAX_CONTACTS = 256 };

typedef struct bridge {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    dGeomID pier;
    dBodyID plank[PLANKS], load[LOADS];
    dJointID hinge[PLANKS];              // hinge 0 pins the first plank to the world
    dJointFeedback fb[PLANKS];
    dJointID contact[MAX_CONTACTS];      // this step's contacts, each with contact_fb[i]
    dBodyID contact_body[MAX_CONTACTS];  // the body a contact with the pier holds, or NULL
    dJointFeedback contact_fb[MAX_CONTACTS];
    int ncontacts;
    dReal weight;                        // of planks and loads, N
} bridge;

static void bridge_near(void *data, dGeomID o1, dGeomID o2)
{
    bridge *br = data;
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    if (b1 && b2 && dAreConnected(b1, b2)) return;
    const int on_pier = o1 == br->pier || o2 == br->pier;
    dContact c[8];
    int n = dCollide(o1, o2, 8, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n && br->ncontacts < MAX_CONTACTS; i++) {
        c[i].surface.mode = dContactApprox1;
        c[i].surface.mu = on_pier ? 0 : 1;   // the pier is a frictionless roller
        dJointID j = dJointCreateContact(br->world, br->contacts, &c[i]);
        dJointAttach(j, b1, b2);
        dJointSetFeedback(j, &br->contact_fb[br->ncontacts]);
        br->contact_body[br->ncontacts] = on_pier ? (b1 ? b1 : b2) : NULL;
        br->contact[br->ncontacts++] = j;
    }
}

// A simply supported bridge: planks 1 m long along x at z = 2, hinged to each
// other about y with friction motors (vel 0, FMax) stiff enough to carry the
// bending moment, pinned to the world at x = 0 and resting on a frictionless
// pier at x = 12; boxes dropped onto it. Its supports' vertical forces are
// then determined by statics alone.
static void bridge_build(bridge *br)
{
    const dReal g = REAL(9.81);
    br->world = dWorldCreate();
    dWorldSetGravity(br->world, 0, 0, -g);
    br->space = dHashSpaceCreate(0);
    br->contacts = dJointGroupCreate(0);
    br->weight = 0;
    br->pier = dCreateBox(br->space, REAL(0.4), 2, 1);
    dGeomSetPosition(br->pier, PLANKS - REAL(0.2), 0, REAL(1.45));
    dMass m;
    for (int i = 0; i < PLANKS; i++) {
        dBodyID b = br->plank[i] = dBodyCreate(br->world);
        dMassSetBox(&m, 100, REAL(0.9), 2, REAL(0.1));
        dBodySetMass(b, &m);
        br->weight += m.mass * g;
        dBodySetPosition(b, i + REAL(0.5), 0, 2);
        dGeomSetBody(dCreateBox(br->space, REAL(0.9), 2, REAL(0.1)), b);
    }
    for (int i = 0; i < PLANKS; i++) {
        dJointID h = br->hinge[i] = dJointCreateHinge(br->world, 0);
        if (i == 0) dJointAttach(h, br->plank[0], 0);
        else dJointAttach(h, br->plank[i - 1], br->plank[i]);
        dJointSetHingeAnchor(h, i, 0, 2);
        dJointSetHingeAxis(h, 0, 1, 0);
        if (i > 0) dJointSetHingeParam(h, dParamFMax, 20000);
        dJointSetFeedback(h, &br->fb[i]);
    }
    for (int i = 0; i < LOADS; i++) {
        dBodyID b = br->load[i] = dBodyCreate(br->world);
        dMassSetBox(&m, 200, REAL(0.6), REAL(0.6), REAL(0.6));
        dBodySetMass(b, &m);
        br->weight += m.mass * g;
        dBodySetPosition(b, 2 + REAL(2.5) * i, 0, REAL(2.5));
        dGeomSetBody(dCreateBox(br->space, REAL(0.6), REAL(0.6), REAL(0.6)), b);
    }
}

// The force joint j applied to body b by its feedback, or NULL. As in ODE,
// f1 is the force on the first body the joint holds: for a joint attached
// as (0, b) that is b.
static const dReal *feedback_on(dJointID j, const dJointFeedback *fb, dBodyID b)
{
    dBodyID b0 = dJointGetBody(j, 0), b1 = dJointGetBody(j, 1);
    if (b0 == b) return fb->f1;
    if (b1 == b) return b0 ? fb->f2 : fb->f1;
    return NULL;
}

// One step; returns the largest violation, over the bridge's bodies, of
// m dv = h (m g + the sum of the feedback forces of the joints on the body):
// feedback must be the whole force each joint applied in the step.
static double bridge_step(bridge *br, stepper step)
{
    enum { NB = PLANKS + LOADS };
    const dReal h = REAL(0.002);
    dBodyID body[NB];
    dVector3 v0[NB];
    for (int i = 0; i < NB; i++) {
        body[i] = i < PLANKS ? br->plank[i] : br->load[i - PLANKS];
        dCopyVector3(v0[i], dBodyGetLinearVel(body[i]));
    }
    br->ncontacts = 0;
    dSpaceCollide(br->space, br, bridge_near);
    step(br->world, h);
    double worst = 0;
    for (int i = 0; i < NB; i++) {
        dMass m;
        dBodyGetMass(body[i], &m);
        dVector3 f = { 0, 0, -REAL(9.81) * m.mass };
        for (int k = 0; k < PLANKS + br->ncontacts; k++) {
            dJointID j = k < PLANKS ? br->hinge[k] : br->contact[k - PLANKS];
            const dJointFeedback *fb = k < PLANKS ? &br->fb[k] : &br->contact_fb[k - PLANKS];
            const dReal *on = feedback_on(j, fb, body[i]);
            if (on) dAddVectors3(f, f, on);
        }
        const dReal *v1 = dBodyGetLinearVel(body[i]);
        for (int e = 0; e < 3; e++) {
            double err = fabs(m.mass * (v1[e] - v0[i][e]) - h * f[e]) / (h * br->weight);
            if (err > worst) worst = err;
        }
    }
    dJointGroupEmpty(br->contacts);
    return worst;
}

static void bridge_destroy(bridge *br)
{
    dJointGroupDestroy(br->contacts);
    dSpaceDestroy(br->space);
    dWorldDestroy(br->world);
}

// Every step, each body's change of momentum is gravity plus the feedback of
// the joints on it (to 1e-9 of the bridge's weight): feedback reports the
// forces applied, nothing carried from an earlier step or left out.
static int bridge_feedback_is_applied_force(stepper step)
{
    bridge br;
    bridge_build(&br);
    double worst = 0;
    for (int i = 0; i < 1000; i++) {
        double e = bridge_step(&br, step);
        if (e > worst) worst = e;
    }
    printf("# momentum change vs gravity + feedback: worst %.3g of the weight\n", worst);
    CHECK(worst < TOL(1e-9, 1e-3));
    bridge_destroy(&br);
    return 0;
}

static int test_quickstep_bridge_feedback_is_applied_force(void)
{
    return bridge_feedback_is_applied_force(dWorldQuickStep);
}
static int test_step_bridge_feedback_is_applied_force(void)
{
    return bridge_feedback_is_applied_force(dWorldStep);
}

// With the exact solver the loaded bridge comes to rest: then the pin's and
// the pier's vertical forces carry the weight of the bridge and its loads
// within 2 %, and no hinge reports more than that weight. (Under QuickStep's
// 20 sweeps the friction motors of this 12-plank bridge give way, here as in
// ODE 0.16, so it does not come to rest.)
static int test_step_bridge_supports_carry_its_weight(void)
{
#ifdef dSINGLE
    return test_skip("in single precision this 12-plank bridge does not come to rest "
                     "under dWorldStep (supports off by 18 %): the statics need double");
#endif
    bridge br;
    bridge_build(&br);
    for (int i = 0; i < 1500; i++) bridge_step(&br, dWorldStep);
    double worst_balance = 0, worst_hinge = 0;
    for (int i = 0; i < 250; i++) {
        bridge_step(&br, dWorldStep);
        double up = br.fb[0].f1[2];
        for (int k = 0; k < br.ncontacts; k++)   // the pier's contacts hold one body
            if (br.contact_body[k]) up += br.contact_fb[k].f1[2];
        double balance = fabs(up - br.weight) / br.weight;
        if (balance > worst_balance) worst_balance = balance;
        for (int k = 0; k < PLANKS; k++) {
            double f = dCalcVectorLength3(br.fb[k].f1);
            if (f > worst_hinge) worst_hinge = f;
        }
    }
    printf("# supports carry the weight within %.3g %%, largest hinge force %.4g N (weight %.4g N)\n",
           100 * worst_balance, worst_hinge, (double)br.weight);
    CHECK(worst_balance < 0.02);
    CHECK(worst_hinge < br.weight);
    bridge_destroy(&br);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_quickstep_stop_holds_powered_body),
    TEST_CASE(test_step_stop_holds_powered_body),
    TEST_CASE(test_stepfast_stop_holds_powered_body),
    TEST_CASE(test_quickstep_inverted_stops_are_ineffective),
    TEST_CASE(test_step_inverted_stops_are_ineffective),
    TEST_CASE(test_quickstep_bridge_feedback_is_applied_force),
    TEST_CASE(test_step_bridge_feedback_is_applied_force),
    TEST_CASE(test_step_bridge_supports_carry_its_weight),
    TEST_END
};
