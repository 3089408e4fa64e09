// SPDX-License-Identifier: BSD-3-Clause
//
// test_contact_direct.c -- dWorldQuickStep makes a plain contact's solver
// rows straight from the contact (quickstep_contact.c) instead of through
// the generic joint rows: the results must be the same to the bit. Each
// scene runs twice, once each way (dxQuickContactDirect), and the bodies'
// states are compared after every step: the bench-like scenes of the replay
// test (pyramids, spheres, ragdolls), and a scene of boxes, spheres and a
// capsule thrown onto a plane and a kinematic platform under every surface
// mode (contacts that go the generic way too: rolling friction, two
// unbounded friction rows, feedback, a kinematic body).

#include "test.h"
#include "quickstep.h"
#include "replay_scenes.h"

#include <stdint.h>
#include <string.h>

// ---- the bench-like scenes ------------------------------------------------------

// Steps of scene `kind` under QuickStep with the direct way on or off
// (replay_scenes.h).
static void run_replay_scene(int kind, int direct, int steps, dReal *states)
{
    dxQuickContactDirect = direct;
    scene_quick_states(kind, steps, states);
    dxQuickContactDirect = 1;
}

#define REPLAY_STEPS 150
static dReal state_a[REPLAY_STEPS * SCENE_STATE_SIZE], state_b[REPLAY_STEPS * SCENE_STATE_SIZE];

static int check_replay_scene(int kind)
{
    run_replay_scene(kind, 1, REPLAY_STEPS, state_a);
    run_replay_scene(kind, 0, REPLAY_STEPS, state_b);

    const int k = first_state_difference(state_a, state_b, REPLAY_STEPS, SCENE_STATE_SIZE);
    if (k >= 0) test_fail(__FILE__, __LINE__, "%s: states differ from step %d", scene_names[kind], k);
    CHECK(k < 0);
    return 0;
}

static int test_pyramids_step_the_same_either_way(void)
{
    return check_replay_scene(SCENE_PYRAMID);
}

static int test_spheres_step_the_same_either_way(void)
{
    return check_replay_scene(SCENE_SPHERES);
}

static int test_ragdolls_step_the_same_either_way(void)
{
    return check_replay_scene(SCENE_RAGDOLLS);
}

// ---- every surface mode ---------------------------------------------------------

enum { MODE_BOXES = 5, MODE_SPHERES = 4, MODE_BODIES = MODE_BOXES + MODE_SPHERES + 2 };
#define MODE_STATE (13 * MODE_BODIES)
#define MODE_STEPS 120

typedef struct mode_scene {
    dWorldID w;
    dSpaceID space;
    dJointGroupID contacts;
    dBodyID body[MODE_BODIES];   // the last: the kinematic platform
    int surface;                 // index into surfaces[]
    int contacts_made, direct;   // over the run
    dJointFeedback feedback[64];
    int nfeedback;
} mode_scene;

// The surfaces: every mode flag, alone and together, with pyramid and box
// friction, one and two directions, infinite coefficients.
static void set_surface(int which, int index, dContact *c)
{
    dSurfaceParameters *s = &c->surface;
    memset(s, 0, sizeof *s);
    memset(c->fdir1, 0, sizeof c->fdir1);
    s->mu = REAL(0.7);
    s->mu2 = REAL(0.3);
    s->bounce = REAL(0.6);
    s->bounce_vel = REAL(0.05);
    s->soft_erp = REAL(0.5);
    s->soft_cfm = REAL(1e-3);
    s->motion1 = REAL(0.3);
    s->motion2 = REAL(-0.2);
    s->motionN = REAL(0.01);
    s->slip1 = REAL(0.02);
    s->slip2 = REAL(0.05);
    s->rho = REAL(0.01);
    s->rho2 = REAL(0.02);
    s->rhoN = REAL(0.005);
    switch (which) {
    case 0: s->mode = 0; break;
    case 1: s->mode = dContactApprox1; break;
    case 2: s->mode = dContactMu2 | dContactApprox1_1; break;
    case 3: s->mode = dContactBounce | dContactApprox1; break;
    case 4: s->mode = dContactSoftERP | dContactSoftCFM; break;
    case 5: s->mode = dContactMotion1 | dContactMotion2 | dContactMotionN | dContactApprox1; break;
    case 6: s->mode = dContactSlip1 | dContactSlip2 | dContactMu2; break;
    case 7:
        s->mode = dContactFDir1 | dContactMu2 | dContactApprox1_2;
        c->fdir1[0] = REAL(0.31);
        c->fdir1[1] = REAL(0.67);
        c->fdir1[2] = REAL(0.11);
        break;
    case 8: s->mode = dContactMu2, s->mu = 0; break;                 // one friction row
    case 9: s->mode = 0, s->mu = 0; break;                            // frictionless
    case 10: s->mode = dContactApprox1, s->mu = dInfinity; break;     // two unbounded rows
    case 11: s->mode = dContactMu2 | dContactApprox1, s->mu = dInfinity; break;   // one
    case 12: s->mode = dContactRolling | dContactApprox1; break;
    case 13:   // a mixture, contact by contact
        set_surface(index % 13, index, c);
        break;
    default:   // everything at once
        s->mode = dContactMu2 | dContactFDir1 | dContactBounce | dContactSoftERP |
                  dContactSoftCFM | dContactMotion1 | dContactMotion2 | dContactMotionN |
                  dContactSlip1 | dContactSlip2 | dContactApprox1_1;
        c->fdir1[0] = REAL(-0.52);
        c->fdir1[1] = REAL(0.23);
        c->fdir1[2] = REAL(0.19);
        break;
    }
}
#define SURFACES 15

static void mode_near(void *data, dGeomID o1, dGeomID o2)
{
    mode_scene *s = data;
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    dContact c[4];
    const int n = dCollide(o1, o2, 4, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        set_surface(s->surface, s->contacts_made, &c[i]);
        dJointID j = dJointCreateContact(s->w, s->contacts, &c[i]);
        dJointAttach(j, b1, b2);   // in the geoms' order: with the plane first, reversed
        if (s->contacts_made % 7 == 3 && s->nfeedback < 64)
            dJointSetFeedback(j, &s->feedback[s->nfeedback++]);
        s->direct += dxQuickContactIsDirect(j);
        s->contacts_made++;
    }
}

static void mode_build(mode_scene *s, int surface)
{
    memset(s, 0, sizeof *s);
    s->surface = surface;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    dWorldSetQuickStepNumIterations(s->w, 20);
    dWorldSetContactSurfaceLayer(s->w, REAL(0.001));
    s->space = dHashSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    dCreatePlane(s->space, 0, 0, 1, 0);
    dMass m;
    for (int i = 0; i < MODE_BODIES; i++) {
        dBodyID b = s->body[i] = dBodyCreate(s->w);
        dGeomID g;
        if (i < MODE_BOXES) {   // a tower of 3 and two boxes thrown across
            const int tower = i < 3;
            dBodySetPosition(b, tower ? 0 : REAL(0.3) * i, tower ? 0 : REAL(-0.5),
                             tower ? REAL(0.26) + REAL(0.52) * i : REAL(0.4));
            if (!tower) dBodySetLinearVel(b, 1, REAL(0.5), REAL(-0.5));
            dMassSetBox(&m, 1, REAL(0.5), REAL(0.4), REAL(0.5));
            g = dCreateBox(s->space, REAL(0.5), REAL(0.4), REAL(0.5));
        } else if (i < MODE_BOXES + MODE_SPHERES) {   // spheres rolling and falling
            const int k = i - MODE_BOXES;
            dBodySetPosition(b, -1 + REAL(0.25) * k, REAL(0.8), REAL(0.2) + REAL(0.3) * k);
            dBodySetLinearVel(b, REAL(0.8), REAL(-0.4) * k, -1);
            dBodySetAngularVel(b, 3, 0, 2 * (dReal)k);
            dMassSetSphere(&m, 1, REAL(0.15));
            g = dCreateSphere(s->space, REAL(0.15));
        } else if (i == MODE_BODIES - 2) {   // a capsule lying across, spinning
            dBodySetPosition(b, 1, 1, REAL(0.3));
            dBodySetAngularVel(b, 0, 1, 4);
            dMassSetCapsule(&m, 1, 1, REAL(0.1), REAL(0.6));
            g = dCreateCapsule(s->space, REAL(0.1), REAL(0.6));
            dQuaternion q;
            dQFromAxisAndAngle(q, 1, 0, 0, REAL(1.4));
            dBodySetQuaternion(b, q);
        } else {   // a kinematic platform sliding under a box
            dBodySetPosition(b, REAL(1.2), REAL(-0.5), REAL(0.05));
            dBodySetLinearVel(b, REAL(-0.2), 0, 0);
            dMassSetBox(&m, 1, 1, 1, REAL(0.1));
            g = dCreateBox(s->space, 1, 1, REAL(0.1));
        }
        dBodySetMass(b, &m);
        dGeomSetBody(g, b);
        if (i == MODE_BODIES - 1) dBodySetKinematic(b);
    }
}

static void mode_state(const mode_scene *s, dReal *out)
{
    for (int i = 0; i < MODE_BODIES; i++) {
        dReal *x = out + 13 * i;
        memcpy(x, dBodyGetPosition(s->body[i]), 3 * sizeof(dReal));
        memcpy(x + 3, dBodyGetQuaternion(s->body[i]), 4 * sizeof(dReal));
        memcpy(x + 7, dBodyGetLinearVel(s->body[i]), 3 * sizeof(dReal));
        memcpy(x + 10, dBodyGetAngularVel(s->body[i]), 3 * sizeof(dReal));
    }
}

// Run surface `surface` with the direct way on or off: states after each
// step, the feedback forces of the last step, and how many contacts were
// made and could go the direct way.
static void run_mode(int surface, int direct, dReal *states, dReal *feedback, int *made,
                     int *direct_ok)
{
    mode_scene s;
    mode_build(&s, surface);
    dxQuickContactDirect = direct;
    for (int k = 0; k < MODE_STEPS; k++) {
        s.nfeedback = 0;
        dSpaceCollide(s.space, &s, mode_near);
        dWorldQuickStep(s.w, REAL(0.01));
        dJointGroupEmpty(s.contacts);
        mode_state(&s, states + (size_t)k * MODE_STATE);
    }
    dxQuickContactDirect = 1;
    memset(feedback, 0, sizeof(dReal) * 64 * 12);
    for (int i = 0; i < s.nfeedback; i++) {
        memcpy(feedback + 12 * i, s.feedback[i].f1, 3 * sizeof(dReal));
        memcpy(feedback + 12 * i + 3, s.feedback[i].t1, 3 * sizeof(dReal));
        memcpy(feedback + 12 * i + 6, s.feedback[i].f2, 3 * sizeof(dReal));
        memcpy(feedback + 12 * i + 9, s.feedback[i].t2, 3 * sizeof(dReal));
    }
    *made = s.contacts_made;
    *direct_ok = s.direct;
    dJointGroupDestroy(s.contacts);
    dSpaceDestroy(s.space);
    dWorldDestroy(s.w);
}

static dReal mode_a[MODE_STEPS * MODE_STATE], mode_b[MODE_STEPS * MODE_STATE];

static int test_every_surface_mode_steps_the_same_either_way(void)
{
    for (int surface = 0; surface < SURFACES; surface++) {
        dReal fa[64 * 12], fb[64 * 12];
        int made_a, made_b, direct_a, direct_b;
        run_mode(surface, 1, mode_a, fa, &made_a, &direct_a);
        run_mode(surface, 0, mode_b, fb, &made_b, &direct_b);

        const int k = first_state_difference(mode_a, mode_b, MODE_STEPS, MODE_STATE);
        if (k >= 0) test_fail(__FILE__, __LINE__, "surface %d: states differ from step %d",
                              surface, k);
        CHECK(k < 0);
        CHECK(memcmp(fa, fb, sizeof fa) == 0);
        CHECK(made_a == made_b && made_a > 500);
        // Some of the contacts went the direct way (feedback and the kinematic
        // platform's never do), except where the surface has none that can.
        const int none = surface == 10 || surface == 12;
        CHECK(none ? direct_a == 0 : direct_a > made_a / 2);
        CHECK(direct_a < made_a);
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_pyramids_step_the_same_either_way),
    TEST_CASE(test_spheres_step_the_same_either_way),
    TEST_CASE(test_ragdolls_step_the_same_either_way),
    TEST_CASE(test_every_surface_mode_steps_the_same_either_way),
    TEST_END
};
