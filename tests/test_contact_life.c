// SPDX-License-Identifier: BSD-3-Clause
//
// test_contact_life.c -- a contact joint's life (joint.c, joint_contact.c):
// made in a group, attached, listed by its bodies, stepped, and dropped with
// the group, mixed with joints outside the group and with bodies destroyed on
// the way. A contact is made without zeroing its memory first, and a group
// reuses its memory after dJointGroupEmpty: a contact made where another one
// lived must not inherit anything of it (its recorded body poses above all),
// so it steps to the bit like one made in fresh memory.

#include "test.h"

#include <ode/ode.h>
#include <math.h>
#include <string.h>

static dContact contact_at(double x, double y, double z, double depth)
{
    dContact c;
    memset(&c, 0, sizeof c);
    c.surface.mode = dContactApprox1;
    c.surface.mu = 0.5;
    c.geom.pos[0] = x;
    c.geom.pos[1] = y;
    c.geom.pos[2] = z;
    c.geom.normal[2] = 1;
    c.geom.depth = depth;
    c.geom.side1 = c.geom.side2 = -1;
    return c;
}

static dBodyID box(dWorldID w, double z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, 1, 0.5, 0.5, 0.2);
    dBodySetMass(b, &m);
    dBodySetPosition(b, 0, 0, z);
    return b;
}

// Contacts are listed by their bodies (newest first), report their bodies in
// the order given (also when attached as (0, b)), survive dJointDestroy
// while in the group, and leave every list when the group is emptied.
static int test_contacts_listed_and_dropped(void)
{
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = box(w, 0.1), b = box(w, 0.3);
    dContact c = contact_at(0, 0, 0.2, 0.001);
    dJointID c1 = dJointCreateContact(w, g, &c);
    dJointAttach(c1, b, a);
    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, a, b);
    dJointID c2 = dJointCreateContact(w, g, &c);
    dJointAttach(c2, 0, a);

    CHECK(dJointGetType(c1) == dJointTypeContact);
    CHECK(dJointGetBody(c1, 0) == b && dJointGetBody(c1, 1) == a);
    CHECK(dJointGetBody(c2, 0) == NULL && dJointGetBody(c2, 1) == a);
    CHECK(dJointGetNumBodies(c2) == 1);
    CHECK(dBodyGetNumJoints(a) == 3 && dBodyGetNumJoints(b) == 2);
    CHECK(dBodyGetJoint(a, 0) == c2 && dBodyGetJoint(a, 1) == ball && dBodyGetJoint(a, 2) == c1);
    CHECK(dAreConnected(a, b) && dAreConnectedExcluding(a, b, dJointTypeBall));
    dJointID list[4];
    CHECK(dConnectingJointList(a, b, list) == 2);

    dJointDestroy(c1);   // the group owns it: no effect
    CHECK(dBodyGetNumJoints(a) == 3);
    dJointDestroy(ball);   // from the middle of a's list
    CHECK(dBodyGetNumJoints(a) == 2 && dBodyGetJoint(a, 0) == c2 && dBodyGetJoint(a, 1) == c1);

    // Attached again elsewhere: the lists follow.
    dJointAttach(c1, a, 0);
    CHECK(dBodyGetNumJoints(b) == 0 && dBodyGetNumJoints(a) == 2);
    CHECK(dJointGetBody(c1, 0) == a && dJointGetBody(c1, 1) == NULL);

    dJointID kept = dJointCreateHinge(w, 0);
    dJointAttach(kept, a, b);
    dJointGroupEmpty(g);
    CHECK(dBodyGetNumJoints(a) == 1 && dBodyGetJoint(a, 0) == kept);
    CHECK(dBodyGetNumJoints(b) == 1);
    test_capture_reports();
    CHECK(dJointGetBody(c1, 0) == NULL);   // a dead handle is reported, not followed
    CHECK(test_captured_contains("dJointGetBody"));
    test_release_reports();

    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// A body destroyed while its contacts are in the group: they let go of it,
// the other body keeps them until the group is emptied.
static int test_group_emptied_after_a_body_is_destroyed(void)
{
    dWorldID w = dWorldCreate();
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = box(w, 0.1), b = box(w, 0.3);
    dContact c = contact_at(0, 0, 0.2, 0.001);
    dJointID j[4];
    for (int k = 0; k < 4; k++) {
        j[k] = dJointCreateContact(w, g, &c);
        dJointAttach(j[k], b, a);
    }
    dBodyDestroy(b);
    CHECK(dBodyGetNumJoints(a) == 4);
    CHECK(dJointGetBody(j[2], 0) == NULL && dJointGetBody(j[2], 1) == a);
    dWorldStep(w, 0.01);   // contacts with one body left still step
    dJointGroupEmpty(g);
    CHECK(dBodyGetNumJoints(a) == 0);
    dBodyDestroy(a);
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Feedback on a contact is filled by the step, as on any joint.
static int test_contact_feedback(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = box(w, 0.1);
    dJointFeedback fb;
    memset(&fb, 0, sizeof fb);
    dContact c = contact_at(0, 0, 0, 0);
    dJointID j = dJointCreateContact(w, g, &c);
    CHECK(dJointGetFeedback(j) == NULL);
    dJointAttach(j, a, 0);
    dJointSetFeedback(j, &fb);
    CHECK(dJointGetFeedback(j) == &fb);
    dWorldQuickStep(w, 0.01);
    CHECK_NEAR(fb.f1[2], 9.81, TOL(1e-3, 0.05));   // the box's weight, at rest on it
    dJointGroupEmpty(g);
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// Two resting boxes' contacts for one step, then the lower box lifted by
// 5 mm and new contacts made: in the group's reused memory (where the first
// step's contacts recorded the boxes' poses) and in a new group's. Both
// steps give the same bits: a contact made in reused memory starts afresh.
typedef struct scene {
    dWorldID w;
    dBodyID a, b;
} scene;

static void scene_make(scene *s)
{
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, -9.81);
    s->a = box(s->w, 0.099);
    s->b = box(s->w, 0.298);
}

static dJointID scene_contacts(scene *s, dJointGroupID g, double lift)
{
    dJointID first = NULL;
    for (int k = 0; k < 4; k++) {
        const double x = k & 1 ? 0.25 : -0.25, y = k & 2 ? 0.25 : -0.25;
        dContact c = contact_at(x, y, 0, 0.001);
        dJointID j = dJointCreateContact(s->w, g, &c);
        if (!first) first = j;
        dJointAttach(j, s->a, 0);
        c = contact_at(x, y, 0.198 + lift, 0.002);
        dJointAttach(dJointCreateContact(s->w, g, &c), s->b, s->a);
    }
    return first;
}

static int test_reused_memory_starts_afresh(void)
{
    for (int stepper = 0; stepper < 3; stepper++) {
        scene s[2];
        dJointGroupID g[2] = { dJointGroupCreate(0), dJointGroupCreate(0) };
        dJointGroupID fresh = dJointGroupCreate(0);
        dJointID old = NULL, reused = NULL;
        for (int k = 0; k < 2; k++) {
            scene_make(&s[k]);
            dJointID j = scene_contacts(&s[k], g[k], 0);
            if (k == 0) old = j;
            dWorldStep(s[k].w, 0.01);
            dJointGroupEmpty(g[k]);
            const dReal *p = dBodyGetPosition(s[k].a);
            dBodySetPosition(s[k].a, p[0], p[1], p[2] + 0.005);
            dJointID n = scene_contacts(&s[k], k == 0 ? g[k] : fresh, 0.005);
            if (k == 0) reused = n;
            if (stepper == 0) dWorldStep(s[k].w, 0.01);
            else if (stepper == 1) dWorldQuickStep(s[k].w, 0.01);
            else dWorldStepFast1(s[k].w, 0.01, 5);
        }
        CHECK(reused == old);   // the same memory
        for (int k = 0; k < 2; k++) {
            const dBodyID x = k ? s[0].b : s[0].a, y = k ? s[1].b : s[1].a;
            CHECK(memcmp(dBodyGetPosition(x), dBodyGetPosition(y), 3 * sizeof(dReal)) == 0);
            CHECK(memcmp(dBodyGetLinearVel(x), dBodyGetLinearVel(y), 3 * sizeof(dReal)) == 0);
            CHECK(memcmp(dBodyGetAngularVel(x), dBodyGetAngularVel(y), 3 * sizeof(dReal)) == 0);
        }
        for (int k = 0; k < 2; k++) {
            dJointGroupDestroy(g[k]);
            dWorldDestroy(s[k].w);
        }
        dJointGroupDestroy(fresh);
    }
    return 0;
}

// A contact with an unusable normal, made where a good one lived: reported,
// no rows (the box falls as if it were not there), still attachable and
// listed.
static int test_inert_contact_in_reused_memory(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dJointGroupID g = dJointGroupCreate(0);
    dBodyID a = box(w, 0.1);
    dContact c = contact_at(0, 0, 0, 0.01);
    dJointAttach(dJointCreateContact(w, g, &c), a, 0);
    dWorldStep(w, 0.01);
    dJointGroupEmpty(g);
    dBodySetLinearVel(a, 0, 0, 0);
    dBodySetAngularVel(a, 0, 0, 0);
    c.geom.normal[2] = 0;
    test_capture_reports();
    dJointID j = dJointCreateContact(w, g, &c);
    CHECK(test_captured_contains("has no direction"));
    test_release_reports();
    dJointAttach(j, a, 0);
    CHECK(dBodyGetNumJoints(a) == 1);
    dWorldQuickStep(w, 0.01);
    CHECK_NEAR(dBodyGetLinearVel(a)[2], -9.81 * 0.01, TOL(1e-12, 1e-6));
    dJointGroupEmpty(g);
    dJointGroupDestroy(g);
    dWorldDestroy(w);
    return 0;
}

// A group's contacts made among joints of another group, of no group and of
// another world (one group may hold joints of two worlds): emptying it cuts
// its runs out of each world's list and leaves every other joint listed, by
// its bodies and by its world (which steps them and destroys the ungrouped
// ones at dWorldDestroy without a report); contacts whose world was destroyed
// first are dropped too.
static int test_group_emptied_among_other_joints(void)
{
    dWorldID w[2] = { dWorldCreate(), dWorldCreate() };
    dJointGroupID g = dJointGroupCreate(0), h = dJointGroupCreate(0);
    dBodyID a[2], b[2];
    for (int k = 0; k < 2; k++) {
        dWorldSetGravity(w[k], 0, 0, -9.81);
        a[k] = box(w[k], 0.1);
        b[k] = box(w[k], 0.3);
    }
    dContact c = contact_at(0, 0, 0.2, 0.001);
    // The order of making: g's contacts in runs of 1, 2 and 3, broken by a
    // contact of h, an ungrouped ball joint, and a contact in the other world.
    const char plan[] = "ghgg0ggg1gh0g";
    int in_g[2] = { 0, 0 }, others[2] = { 0, 0 };
    for (const char *p = plan; *p; p++) {
        const int k = *p == '1';
        dJointID j = *p == '0' ? dJointCreateBall(w[0], 0)
                   : dJointCreateContact(w[k], *p == 'h' ? h : g, &c);
        dJointAttach(j, b[k], a[k]);
        if (*p == 'g' || *p == '1') in_g[k]++;
        else others[k]++;
    }
    CHECK(dBodyGetNumJoints(a[0]) == in_g[0] + others[0]);
    test_capture_reports();
    dJointGroupEmpty(g);
    CHECK(dBodyGetNumJoints(a[0]) == others[0] && dBodyGetNumJoints(b[0]) == others[0]);
    CHECK(dBodyGetNumJoints(a[1]) == others[1] && dBodyGetNumJoints(b[1]) == others[1]);
    for (int i = 0; i < dBodyGetNumJoints(a[0]); i++) {
        const dJointType t = dJointGetType(dBodyGetJoint(a[0], i));
        CHECK(t == dJointTypeBall || t == dJointTypeContact);
    }
    dWorldQuickStep(w[0], 0.01);
    dWorldStep(w[1], 0.01);
    // Made again in the emptied group, and emptied with h.
    dJointAttach(dJointCreateContact(w[0], g, &c), a[0], 0);
    dJointGroupEmpty(h);
    CHECK(dBodyGetNumJoints(a[0]) == 1 + 2 && dBodyGetNumJoints(b[0]) == 2);
    dJointGroupEmpty(g);
    CHECK(dBodyGetNumJoints(a[0]) == 2);
    dWorldQuickStep(w[0], 0.01);
    dWorldDestroy(w[0]);   // the two ball joints with it
    // Contacts whose world is destroyed before their group is emptied.
    for (int k = 0; k < 3; k++) dJointAttach(dJointCreateContact(w[1], g, &c), a[1], b[1]);
    dWorldDestroy(w[1]);
    dJointGroupEmpty(g);
    CHECK(test_captured_count() == 0);
    test_release_reports();
    dJointGroupDestroy(g);
    dJointGroupDestroy(h);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_contacts_listed_and_dropped),
    TEST_CASE(test_group_emptied_after_a_body_is_destroyed),
    TEST_CASE(test_contact_feedback),
    TEST_CASE(test_reused_memory_starts_afresh),
    TEST_CASE(test_inert_contact_in_reused_memory),
    TEST_CASE(test_group_emptied_among_other_joints),
    TEST_END
};
