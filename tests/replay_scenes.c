// SPDX-License-Identifier: BSD-3-Clause
//
// replay_scenes.c -- the scenes of replay_scenes.h. Every group stands 20 m
// from the next along x, so groups never meet; what a group is depends only
// on its number (positions from a generator seeded by it), never on the
// order in which groups are created.

#include "replay_scenes.h"

#include <string.h>

const char *const scene_names[SCENE_KINDS] = { "pyramid", "spheres", "ragdolls", "chain" };
const char *const stepper_names[STEPPERS] = { "dWorldStep", "dWorldQuickStep",
                                              "dWorldStepFast1" };

static double group_random(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (double)(*state >> 8) / (double)(1u << 24);
}

static dBodyID add_body(scene *s, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(s->w);
    dBodySetPosition(b, x, y, z);
    s->body[s->nbody++] = b;
    return b;
}

static void add_box(scene *s, dBodyID b, dReal lx, dReal ly, dReal lz)
{
    dMass m;
    dMassSetBox(&m, 1, lx, ly, lz);
    dBodySetMass(b, &m);
    dGeomSetBody(dCreateBox(s->space, lx, ly, lz), b);
}

static void add_sphere(scene *s, dBodyID b, dReal r)
{
    dMass m;
    dMassSetSphere(&m, 1, r);
    dBodySetMass(b, &m);
    dGeomSetBody(dCreateSphere(s->space, r), b);
}

static void add_capsule(scene *s, dBodyID b, dReal r, dReal len)
{
    dMass m;
    dMassSetCapsule(&m, 1, 3, r, len);
    dBodySetMass(b, &m);
    dGeomSetBody(dCreateCapsule(s->space, r, len), b);
}

static void build_pyramid(scene *s, dReal x0)
{
    const int layers = 4;
    for (int layer = 0; layer < layers; layer++)
        for (int i = 0; i < layers - layer; i++) {
            dBodyID b = add_body(s, x0 + (dReal)i * REAL(1.02) + (dReal)layer * REAL(0.51), 0,
                                 REAL(0.5) + (dReal)layer);
            add_box(s, b, 1, 1, 1);
        }
}

static void build_spheres(scene *s, dReal x0, uint32_t seed)
{
    for (int i = 0; i < 18; i++) {
        dBodyID b = add_body(s, x0 + (dReal)(group_random(&seed) * 2),
                             (dReal)(group_random(&seed) * 2),
                             REAL(0.5) + (dReal)i * REAL(0.45));
        add_sphere(s, b, REAL(0.2) + (dReal)(group_random(&seed) * 0.1));
        dBodySetLinearVel(b, 0, 0, -(dReal)(group_random(&seed) * 2));
    }
}

// Torso, head, two arms, two legs: ball, hinge and universal joints.
static void build_ragdoll(scene *s, dReal x0, dReal z0, dReal spin)
{
    dBodyID torso = add_body(s, x0, 0, z0);
    add_box(s, torso, REAL(0.4), REAL(0.25), REAL(0.6));
    dBodySetAngularVel(torso, spin, REAL(0.5) * spin, 0);
    dBodyID head = add_body(s, x0, 0, z0 + REAL(0.45));
    add_sphere(s, head, REAL(0.14));
    dJointID neck = dJointCreateBall(s->w, 0);
    dJointAttach(neck, torso, head);
    dJointSetBallAnchor(neck, x0, 0, z0 + REAL(0.32));
    for (int side = -1; side <= 1; side += 2) {
        dBodyID arm = add_body(s, x0 + (dReal)side * REAL(0.4), 0, z0 + REAL(0.2));
        add_capsule(s, arm, REAL(0.06), REAL(0.35));
        dJointID shoulder = dJointCreateUniversal(s->w, 0);
        dJointAttach(shoulder, torso, arm);
        dJointSetUniversalAnchor(shoulder, x0 + (dReal)side * REAL(0.22), 0, z0 + REAL(0.25));
        dJointSetUniversalAxis1(shoulder, 0, 1, 0);
        dJointSetUniversalAxis2(shoulder, 1, 0, 0);
        dBodyID leg = add_body(s, x0 + (dReal)side * REAL(0.12), 0, z0 - REAL(0.6));
        add_capsule(s, leg, REAL(0.08), REAL(0.45));
        dJointID hip = dJointCreateHinge(s->w, 0);
        dJointAttach(hip, torso, leg);
        dJointSetHingeAnchor(hip, x0 + (dReal)side * REAL(0.12), 0, z0 - REAL(0.32));
        dJointSetHingeAxis(hip, 1, 0, 0);
        dJointSetHingeParam(hip, dParamLoStop, -1);
        dJointSetHingeParam(hip, dParamHiStop, 1);
    }
}

// Ten spheres hanging from the world by alternating ball and hinge joints,
// thrown sideways onto the ground.
static void build_chain(scene *s, dReal x0, uint32_t seed)
{
    dBodyID prev = 0;
    for (int i = 0; i < 10; i++) {
        dBodyID b = add_body(s, x0 + REAL(0.3) * (dReal)i, 0, 2);
        add_sphere(s, b, REAL(0.12));
        dBodySetLinearVel(b, 0, (dReal)(group_random(&seed) * 3), 0);
        dJointID j = (i % 2) ? dJointCreateHinge(s->w, 0) : dJointCreateBall(s->w, 0);
        dJointAttach(j, b, prev);
        const dReal ax = x0 + REAL(0.3) * (dReal)i - REAL(0.15);
        if (i % 2) {
            dJointSetHingeAnchor(j, ax, 0, 2);
            dJointSetHingeAxis(j, 0, 0, 1);
        } else {
            dJointSetBallAnchor(j, ax, 0, 2);
        }
        prev = b;
    }
}

static void build_group(scene *s, int g)
{
    const dReal x0 = REAL(20.0) * (dReal)g;
    const uint32_t seed = 1234u + 977u * (uint32_t)g;
    switch (s->kind) {
    case SCENE_PYRAMID: build_pyramid(s, x0); break;
    case SCENE_SPHERES: build_spheres(s, x0, seed); break;
    case SCENE_RAGDOLLS:
        build_ragdoll(s, x0, REAL(1.2), REAL(1.0) + (dReal)g);
        build_ragdoll(s, x0 + REAL(0.2), REAL(2.6), -REAL(2.0));
        break;
    default: build_chain(s, x0, seed); break;
    }
}

void scene_build(scene *s, int kind, int stepper, const int *order, int threads)
{
    static const int identity[SCENE_GROUPS] = { 0, 1, 2, 3 };
    if (!order) order = identity;
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->stepper = stepper;
    s->w = dWorldCreate();
    dWorldSetGravity(s->w, 0, 0, REAL(-9.81));
    dWorldSetCFM(s->w, REAL(1e-5));
    dWorldSetQuickStepNumIterations(s->w, 20);
    s->space = dHashSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    dCreatePlane(s->space, 0, 0, 1, 0);
    // Build each group, then move its bodies to their logical places.
    dBodyID made[SCENE_GROUPS][SCENE_MAX_BODIES];
    int count[SCENE_GROUPS];
    for (int k = 0; k < SCENE_GROUPS; k++) {
        const int g = order[k];
        const int first = s->nbody;
        build_group(s, g);
        count[g] = s->nbody - first;
        memcpy(made[g], s->body + first, sizeof(dBodyID) * (size_t)count[g]);
    }
    s->nbody = 0;
    for (int g = 0; g < SCENE_GROUPS; g++) {
        s->group_first[g] = s->nbody;
        memcpy(s->body + s->nbody, made[g], sizeof(dBodyID) * (size_t)count[g]);
        s->nbody += count[g];
    }
    s->group_first[SCENE_GROUPS] = s->nbody;
    if (threads > 0) {
        dInitODE2(0);   // (the pool's threads need the library initialised)
        s->impl = dThreadingAllocateMultiThreadedImplementation();
        s->pool = dThreadingAllocateThreadPool((unsigned)threads, 0, dAllocateFlagBasicData, 0);
        dThreadingThreadPoolServeMultiThreadedImplementation(s->pool, s->impl);
        dWorldSetStepThreadingImplementation(s->w, dThreadingImplementationGetFunctions(s->impl),
                                             s->impl);
    }
}

static void near_callback(void *data, dGeomID o1, dGeomID o2)
{
    scene *s = data;
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;
    dContact c[4];
    const int n = dCollide(o1, o2, 4, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = dContactSoftCFM | dContactApprox1;
        c[i].surface.mu = REAL(0.6);
        c[i].surface.soft_cfm = REAL(1e-4);
        dJointAttach(dJointCreateContact(s->w, s->contacts, &c[i]), b1, b2);
    }
}

void scene_step(scene *s)
{
    dSpaceCollide(s->space, s, near_callback);
    const dReal h = REAL(0.01);
    switch (s->stepper) {
    case STEP_WORLD: dWorldStep(s->w, h); break;
    case STEP_QUICK: dWorldQuickStep(s->w, h); break;
    default: dWorldStepFast1(s->w, h, 10); break;
    }
    dJointGroupEmpty(s->contacts);
}

void scene_state(const scene *s, dReal *out)
{
    memset(out, 0, sizeof(dReal) * SCENE_STATE_SIZE);
    for (int i = 0; i < s->nbody; i++) {
        dReal *x = out + 13 * i;
        memcpy(x, dBodyGetPosition(s->body[i]), 3 * sizeof(dReal));
        memcpy(x + 3, dBodyGetQuaternion(s->body[i]), 4 * sizeof(dReal));
        memcpy(x + 7, dBodyGetLinearVel(s->body[i]), 3 * sizeof(dReal));
        memcpy(x + 10, dBodyGetAngularVel(s->body[i]), 3 * sizeof(dReal));
    }
}

uint64_t scene_hash(const scene *s)
{
    static dReal state[SCENE_STATE_SIZE];
    scene_state(s, state);
    const unsigned char *p = (const unsigned char *)state;
    uint64_t h = 0xcbf29ce484222325u;
    for (size_t i = 0; i < sizeof state; i++) {
        h ^= p[i];
        h *= 0x100000001b3u;
    }
    return h;
}

void scene_destroy(scene *s)
{
    if (s->impl) {
        dWorldSetStepThreadingImplementation(s->w, NULL, NULL);
        dThreadingImplementationShutdownProcessing(s->impl);
        dThreadingFreeThreadPool(s->pool);
        dThreadingFreeImplementation(s->impl);
    }
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);
    dWorldDestroy(s->w);
}

void scene_quick_states(int kind, int steps, dReal *states)
{
    scene s;
    scene_build(&s, kind, STEP_QUICK, NULL, 0);
    for (int k = 0; k < steps; k++) {
        scene_step(&s);
        scene_state(&s, states + (size_t)k * SCENE_STATE_SIZE);
    }
    scene_destroy(&s);
}

int first_state_difference(const dReal *a, const dReal *b, int steps, size_t size)
{
    for (int k = 0; k < steps; k++)
        if (memcmp(a + (size_t)k * size, b + (size_t)k * size, size * sizeof(dReal))) return k;
    return -1;
}
