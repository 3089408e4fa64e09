// SPDX-License-Identifier: BSD-3-Clause
//
// test_hooks.c -- the dynamics library used alone, with the program bringing
// its own "collision library": this file defines the three hooks of guide
// 10.11.2 and checks that libodedyn calls them as documented.

#include "test.h"

// A stand-in geom: the hooks only need a list through the body.
struct dxGeom {
    dBodyID body;
    struct dxGeom *body_next;
    int moved;
};

static int set_body_calls;

void dGeomMoved(dGeomID g) { g->moved++; }

dGeomID dGeomGetBodyNext(dGeomID g) { return g->body_next; }

void dGeomSetBody(dGeomID g, dBodyID b)
{
    set_body_calls++;
    g->body = b;
    if (!b) g->body_next = NULL;
}

// Attach two stand-in geoms to a body the way a collision library would.
static void attach(dBodyID b, struct dxGeom *g1, struct dxGeom *g2)
{
    g1->body = g2->body = b;
    g1->body_next = g2;
    g2->body_next = NULL;
    dBodySetFirstGeom(b, g1);
}

static int test_step_tells_every_geom_of_a_moved_body(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = dBodyCreate(w);
    struct dxGeom g1 = { 0 }, g2 = { 0 };
    attach(b, &g1, &g2);

    dWorldStep(w, 0.01);
    dWorldQuickStep(w, 0.01);

    CHECK(g1.moved == 2 && g2.moved == 2);
    CHECK(dBodyGetFirstGeom(b) == &g1);
    CHECK(dBodyGetNextGeom(&g1) == &g2);
    dBodySetFirstGeom(b, NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_setting_the_pose_tells_the_geoms(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    struct dxGeom g1 = { 0 }, g2 = { 0 };
    attach(b, &g1, &g2);
    dQuaternion q = { 1, 0, 0, 0 };
    dMatrix3 R;
    dRSetIdentity(R);

    dBodySetPosition(b, 1, 2, 3);
    dBodySetQuaternion(b, q);
    dBodySetRotation(b, R);

    CHECK(g1.moved == 3 && g2.moved == 3);
    dBodySetFirstGeom(b, NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_disabled_body_geoms_are_not_told(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    struct dxGeom g1 = { 0 }, g2 = { 0 };
    attach(b, &g1, &g2);
    dBodyDisable(b);

    dWorldStep(w, 0.01);

    CHECK(g1.moved == 0);
    dBodySetFirstGeom(b, NULL);
    dWorldDestroy(w);
    return 0;
}

static int test_destroying_a_body_detaches_its_geoms(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    struct dxGeom g1 = { 0 }, g2 = { 0 };
    attach(b, &g1, &g2);
    set_body_calls = 0;

    dBodyDestroy(b);

    CHECK(set_body_calls == 2);   // every geom, read next before unlinking
    CHECK(g1.body == NULL && g2.body == NULL);
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_step_tells_every_geom_of_a_moved_body),
    TEST_CASE(test_setting_the_pose_tells_the_geoms),
    TEST_CASE(test_disabled_body_geoms_are_not_told),
    TEST_CASE(test_destroying_a_body_detaches_its_geoms),
    TEST_END
};
