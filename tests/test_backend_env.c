// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_env.c -- ODE_COLLISION_BACKEND (backend.h), which meson sets
// to "envfake" for this program: the backend of that name is selected as
// soon as the program registers it, without any dCollisionSetBackend call.

#include "test.h"

#include <ode/backend.h>
#include <stdlib.h>
#include <string.h>

#define MARKER_DEPTH 4321.5

static int envfake_supports(int c1, int c2) { return c1 == dSphereClass && c2 == dSphereClass; }

// One contact with a marker depth, whatever the spheres' poses.
static int envfake_collide(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    (void)flags;
    (void)skip;
    memset(c, 0, sizeof *c);
    c->normal[2] = 1;
    c->depth = MARKER_DEPTH;
    c->g1 = o1;
    c->g2 = o2;
    c->side1 = c->side2 = -1;
    return 1;
}

static const dCollisionBackend envfake = { "envfake", envfake_supports, envfake_collide, 0, 0 };

static int test_environment_selects_the_backend_once_registered(void)
{
    const char *env = getenv("ODE_COLLISION_BACKEND");
    CHECK(env && strcmp(env, "envfake") == 0);   // set by tests/meson.build
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);   // not registered yet

    CHECK(dCollisionRegisterBackend(&envfake) == 1);

    CHECK(strcmp(dCollisionGetBackend(), "envfake") == 0);
    dGeomID a = dCreateSphere(0, 1), b = dCreateSphere(0, 1);
    dGeomSetPosition(b, 5, 0, 0);   // apart: only the fake reports a contact
    dContactGeom c[1];
    CHECK(dCollide(a, b, 1, c, sizeof c[0]) == 1 && c[0].depth == MARKER_DEPTH);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

static int test_explicit_selection_wins_over_the_environment(void)
{
    CHECK(dCollisionSetBackend("native") == 1);
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_environment_selects_the_backend_once_registered),
    TEST_CASE(test_explicit_selection_wins_over_the_environment),
    TEST_END
};
