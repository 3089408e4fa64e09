// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_settle.c -- swapping the narrow phase must not change the
// physics (issue 14): a box dropped flat and tilted onto a plane, a capsule
// and a cylinder dropped on their sides, under every backend built and both
// big-matrix and iterative steppers, with typical contact parameters. Each
// must come to rest (every point of the body slower than 1 mm/s after 3 s)
// at the height native gives it (to 1 mm). The final heights and speeds are
// printed.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { MAX_CONTACTS = 8 };

#define STEP 0.01
#define SECONDS 3.0
#define REST_SPEED 1e-3    // m/s, at any point of the body
#define SAME_HEIGHT 1e-3   // m, against native

typedef struct drop {
    const char *name;
    int cls;
    dReal size[3];        // box sides, or radius and length
    dReal axis[3], angle; // the starting rotation
} drop;

static const drop drops[] = {
    { "box flat", dBoxClass, { 0.4, 0.3, 0.2 }, { 0, 0, 1 }, 0.3 },
    { "box tilted", dBoxClass, { 0.4, 0.3, 0.2 }, { 1, 0.5, 0.2 }, 0.5 },
    { "capsule on its side", dCapsuleClass, { 0.1, 0.4, 0 }, { 1, 0, 0 }, 1.5707963267948966 },
    { "cylinder on its side", dCylinderClass, { 0.1, 0.4, 0 }, { 1, 0, 0 }, 1.5707963267948966 },
};

typedef struct scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    dBodyID body;
    dGeomID geom, ground;
} scene;

// Contacts with typical parameters: friction 1 (pyramid scaled by the normal
// force), slightly soft.
static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *s = data;
    dContact c[MAX_CONTACTS];
    int n = dCollide(a, b, MAX_CONTACTS, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = dContactApprox1 | dContactSoftCFM | dContactSoftERP;
        c[i].surface.mu = 1;
        c[i].surface.soft_cfm = 1e-5;
        c[i].surface.soft_erp = 0.2;
        dJointAttach(dJointCreateContact(s->world, s->contacts, &c[i]), dGeomGetBody(a),
                     dGeomGetBody(b));
    }
}

static void scene_init(scene *s, const drop *d)
{
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, -9.81);
    dWorldSetERP(s->world, 0.2);
    dWorldSetCFM(s->world, 1e-5);
    dWorldSetQuickStepNumIterations(s->world, 20);
    s->space = dSimpleSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    s->ground = dCreatePlane(s->space, 0, 0, 1, 0);
    s->body = dBodyCreate(s->world);
    dMass m;
    if (d->cls == dBoxClass) {
        s->geom = dCreateBox(s->space, d->size[0], d->size[1], d->size[2]);
        dMassSetBox(&m, 500, d->size[0], d->size[1], d->size[2]);
    } else if (d->cls == dCapsuleClass) {
        s->geom = dCreateCapsule(s->space, d->size[0], d->size[1]);
        dMassSetCapsule(&m, 500, 3, d->size[0], d->size[1]);
    } else {
        s->geom = dCreateCylinder(s->space, d->size[0], d->size[1]);
        dMassSetCylinder(&m, 500, 3, d->size[0], d->size[1]);
    }
    dBodySetMass(s->body, &m);
    dGeomSetBody(s->geom, s->body);
    dMatrix3 R;
    dRFromAxisAndAngle(R, d->axis[0], d->axis[1], d->axis[2], d->angle);
    dBodySetRotation(s->body, R);
    dBodySetPosition(s->body, 0.05, -0.02, 0.5);
}

static void scene_end(scene *s)
{
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);
    dWorldDestroy(s->world);
}

// The fastest speed of a point of the body: |v| + |w| times the bounding radius.
static double top_speed(const scene *s, const drop *d)
{
    const dReal *v = dBodyGetLinearVel(s->body), *w = dBodyGetAngularVel(s->body);
    double radius = d->cls == dBoxClass
                        ? 0.5 * sqrt(d->size[0] * d->size[0] + d->size[1] * d->size[1] +
                                     d->size[2] * d->size[2])
                        : d->size[0] + d->size[1] / 2;
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
           radius * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

// Drops d under the backend and stepper; the final height and top speed.
static void run_drop(const char *backend, int quick, const drop *d, double *z, double *speed)
{
    dCollisionSetBackend(backend);
    scene s;
    scene_init(&s, d);
    for (int i = 0; i < (int)(SECONDS / STEP + 0.5); i++) {
        dSpaceCollide(s.space, &s, near_callback);
        if (quick)
            dWorldQuickStep(s.world, STEP);
        else
            dWorldStep(s.world, STEP);
        dJointGroupEmpty(s.contacts);
    }
    *z = dBodyGetPosition(s.body)[2];
    *speed = top_speed(&s, d);
    scene_end(&s);
    dCollisionSetBackend("native");
}

static int check_backend(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    int failed = 0;
    for (int quick = 0; quick < 2; quick++)
        for (size_t k = 0; k < sizeof drops / sizeof drops[0]; k++) {
            double z, speed, z_native, speed_native;
            run_drop("native", quick, &drops[k], &z_native, &speed_native);
            run_drop(backend, quick, &drops[k], &z, &speed);
            int ok = speed < REST_SPEED && fabs(z - z_native) <= SAME_HEIGHT;
            printf("# %s, %s, %s: rests at z = %.4f (native %.4f), top speed %.2g m/s%s\n",
                   backend, quick ? "dWorldQuickStep" : "dWorldStep", drops[k].name, z,
                   z_native, speed, ok ? "" : " -- FAIL");
            if (!ok) failed = 1;
        }
    return failed;
}

static int test_native_drops_come_to_rest(void)
{
    return check_backend("native");
}

static int test_fcl_drops_settle_as_native(void)
{
    return check_backend("fcl");
}

static int test_bullet_drops_settle_as_native(void)
{
    return check_backend("bullet");
}

const test_case test_cases[] = {
    TEST_CASE(test_native_drops_come_to_rest),
    TEST_CASE(test_fcl_drops_settle_as_native),
    TEST_CASE(test_bullet_drops_settle_as_native),
    TEST_END
};
