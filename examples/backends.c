// SPDX-License-Identifier: BSD-3-Clause
//
// backends.c -- one scene stepped three times side by side, each copy's
// contacts computed by another collision backend (native, FCL, Bullet;
// <ode/backend.h>), drawn as points with their normals. A backend whose
// module was not built is skipped with a message. Keys 1, 2, 3 show one copy,
// 0 all of them. Checks when the loop ends: under every backend each shape
// came to rest where it should (a box, a sphere, a lying capsule, a standing
// cylinder and a two-box stack, each centre within 3 cm of its resting height).

#include "example_util.h"

#include <ode/backend.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define COPIES 3
#define SHAPES 6
#define REST_STEPS 180

static const char *const names[COPIES] = { "native", "fcl", "bullet" };

static struct copy {
    int available;
    dWorldID world;
    dSpaceID space;
    exu_contacts contacts;
    dContactGeom seen[256];
    dBodyID bodies[SHAPES];
    dGeomID geoms[SHAPES];
} copies[COPIES];
static const dReal rest_z[SHAPES] = { 0.2, 0.25, 0.15, 0.2, 0.2, 0.6 };
static int shown = -1;   // the copy shown alone, or -1 for all
static long steps;

static void add_shape(struct copy *c, int k, dReal offset_y)
{
    static const dReal xs[SHAPES] = { -2.0, -1.0, 0.0, 1.0, 2.2, 2.2 };
    dMass m;
    dGeomID g;
    dMatrix3 R;
    dRSetIdentity(R);
    switch (k) {
    case 1:
        g = dCreateSphere(c->space, 0.25);
        dMassSetSphere(&m, 500, 0.25);
        break;
    case 2:   // lying along x
        g = dCreateCapsule(c->space, 0.15, 0.5);
        dMassSetCapsule(&m, 500, 3, 0.15, 0.5);
        dRFromAxisAndAngle(R, 0, 1, 0, (dReal)M_PI / 2);
        break;
    case 3:   // standing
        g = dCreateCylinder(c->space, 0.2, 0.4);
        dMassSetCylinder(&m, 500, 3, 0.2, 0.4);
        break;
    default:   // 0 alone, 4 and 5 a stack
        g = dCreateBox(c->space, 0.4, 0.4, 0.4);
        dMassSetBox(&m, 500, 0.4, 0.4, 0.4);
        break;
    }
    dBodyID b = dBodyCreate(c->world);
    dBodySetMass(b, &m);
    dBodySetPosition(b, xs[k], offset_y, rest_z[k] + 0.3 + 0.1 * k);
    dBodySetRotation(b, R);
    dGeomSetBody(g, b);
    c->bodies[k] = b;
    c->geoms[k] = g;
}

// Is the backend there? Its module may not have been built.
static int listed(const char *name)
{
    for (const char *const *n = dCollisionListBackends(); *n; n++)
        if (strcmp(*n, name) == 0) return 1;
    return 0;
}

static void build(void)
{
    for (int i = 0; i < COPIES; i++) {
        struct copy *c = &copies[i];
        c->available = listed(names[i]) && dCollisionSetBackend(names[i]);
        if (!c->available) {
            printf("backends: %s is not available (its module was not built); skipped\n",
                   names[i]);
            continue;
        }
        c->world = dWorldCreate();
        dWorldSetGravity(c->world, 0, 0, -9.81);
        dWorldSetQuickStepNumIterations(c->world, 30);
        dWorldSetAutoDisableFlag(c->world, 0);
        c->space = dHashSpaceCreate(0);
        dCreatePlane(c->space, 0, 0, 1, 0);
        c->contacts = (exu_contacts){ .world = c->world, .group = dJointGroupCreate(0),
                                      .surface = { .mode = dContactApprox1 | dContactSoftCFM,
                                                   .mu = 0.8, .soft_cfm = 1e-5 },
                                      .max_per_pair = 8, .seen = c->seen,
                                      .seen_capacity = 256 };
        for (int k = 0; k < SHAPES; k++) add_shape(c, k, (i - 1) * 2.5);
    }
    dCollisionSetBackend("native");
}

static void start(void)
{
    static const float xyz[3] = { 6.0f, -4.2f, 3.2f };
    static const float hpr[3] = { 147.0f, -25.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("backends", "  1 / 2 / 3: show the native / FCL / Bullet copy alone\n"
             "  0: show them side by side (native front, Bullet back)\n");
}

static void command(int key)
{
    if (key >= '1' && key <= '3' && copies[key - '1'].available) shown = key - '1';
    if (key == '0') shown = -1;
}

static void step(int pause)
{
    if (!pause) {
        for (int i = 0; i < COPIES; i++) {
            struct copy *c = &copies[i];
            if (!c->available) continue;
            dCollisionSetBackend(names[i]);
            exu_collide(&c->contacts, c->space);
            dWorldQuickStep(c->world, EXU_DT);
        }
        dCollisionSetBackend("native");
        steps++;
    }
    static const float tint[COPIES][3] = {
        { 0.9f, 0.6f, 0.2f }, { 0.3f, 0.6f, 0.9f }, { 0.5f, 0.8f, 0.3f }
    };
    for (int i = 0; i < COPIES; i++) {
        struct copy *c = &copies[i];
        if (!c->available || (shown >= 0 && shown != i)) continue;
        dsSetTexture(DS_WOOD);
        dsSetColor(tint[i][0], tint[i][1], tint[i][2]);
        for (int k = 0; k < SHAPES; k++) exu_draw_geom(c->geoms[k]);
        dsSetTexture(DS_NONE);
        dsSetColor(1, 0.1f, 0.1f);
        exu_draw_contacts(&c->contacts, 0.3);
    }
}

static int check(void)
{
    int ok = 1;
    int checked = 0;
    for (int i = 0; i < COPIES; i++) {
        struct copy *c = &copies[i];
        if (!c->available) continue;
        dReal worst = 0;
        for (int k = 0; k < SHAPES; k++) {
            if (!exu_body_finite(c->bodies[k]))
                return exu_report("backends", 0, "%s: state not finite", names[i]);
            worst = fmax(worst, fabs((double)(dBodyGetPosition(c->bodies[k])[2] - rest_z[k])));
        }
        if (steps < REST_STEPS) continue;
        printf("  %-7s %d contacts in the last step, worst resting height error %.4f m\n",
               names[i], c->contacts.seen_count, (double)worst);
        ok = ok && worst < 0.03;
        checked++;
    }
    if (steps < REST_STEPS)
        return exu_report("backends", 1, "state finite; stopped before the shapes could rest");
    return exu_report("backends", ok, "%d backends: every shape rests at its height "
                      "(within 0.03 m)", checked);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    build();

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    for (int i = 0; i < COPIES; i++) {
        struct copy *c = &copies[i];
        if (!c->available) continue;
        dJointGroupDestroy(c->contacts.group);
        dSpaceDestroy(c->space);
        dWorldDestroy(c->world);
    }
    dCloseODE();
    return rc;
}
