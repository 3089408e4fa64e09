// SPDX-License-Identifier: BSD-3-Clause
//
// soak_scene.c -- the churning scene of soak_scene.h.

#include "soak_scene.h"

#include <math.h>
#include <stdlib.h>

#define MAX_BODIES 64
#define MAX_JOINTS 16
#define MAX_STATIC 8
#define MAX_CONTACTS 4

struct soak_scene {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    dGeomID ground;
    int nbodies;
    dBodyID bodies[MAX_BODIES];
    dGeomID geoms[MAX_BODIES];
    dJointID joints[MAX_JOINTS];
    int joint_ends[MAX_JOINTS][2];   // body slots the joint connects
    dGeomID statics[MAX_STATIC];
    unsigned long long rng;
    long steps;
    soak_counts made;                // the *_made and *_destroyed counters
};

// xorshift64*, uniform in [0, 1).
static double uniform(soak_scene *s)
{
    s->rng ^= s->rng >> 12;
    s->rng ^= s->rng << 25;
    s->rng ^= s->rng >> 27;
    return (double)((s->rng * 0x2545F4914F6CDD1DULL) >> 11) * (1.0 / 9007199254740992.0);
}

static double between(soak_scene *s, double lo, double hi) { return lo + (hi - lo) * uniform(s); }

// A new body in slot k: a box, a sphere or a capsule dropped from above.
static void spawn_body(soak_scene *s, int k)
{
    dBodyID b = dBodyCreate(s->world);
    dMass m;
    dGeomID g;
    switch ((int)(uniform(s) * 3)) {
    case 0: {
        dReal x = (dReal)between(s, 0.2, 0.8), y = (dReal)between(s, 0.2, 0.8),
              z = (dReal)between(s, 0.2, 0.8);
        dMassSetBox(&m, 500, x, y, z);
        g = dCreateBox(s->space, x, y, z);
        break;
    }
    case 1: {
        dReal r = (dReal)between(s, 0.1, 0.4);
        dMassSetSphere(&m, 500, r);
        g = dCreateSphere(s->space, r);
        break;
    }
    default: {
        dReal r = (dReal)between(s, 0.1, 0.3), l = (dReal)between(s, 0.2, 0.8);
        dMassSetCapsule(&m, 500, 3, r, l);
        g = dCreateCapsule(s->space, r, l);
        break;
    }
    }
    dBodySetMass(b, &m);
    dBodySetPosition(b, (dReal)between(s, -4, 4), (dReal)between(s, -4, 4),
                     (dReal)between(s, 1, 6));
    dMatrix3 R;
    dRFromAxisAndAngle(R, (dReal)between(s, -1, 1), (dReal)between(s, -1, 1), 1,
                       (dReal)between(s, 0, 6.28));
    dBodySetRotation(b, R);
    dGeomSetBody(g, b);
    s->bodies[k] = b;
    s->geoms[k] = g;
    s->made.bodies_made++;
    s->made.geoms_made++;
}

static void destroy_joint(soak_scene *s, int j)
{
    dJointDestroy(s->joints[j]);
    s->joints[j] = 0;
    s->made.joints_destroyed++;
}

// Destroy the body in slot k, its geom and the joints on it.
static void kill_body(soak_scene *s, int k)
{
    for (int j = 0; j < MAX_JOINTS; j++)
        if (s->joints[j] && (s->joint_ends[j][0] == k || s->joint_ends[j][1] == k))
            destroy_joint(s, j);
    dGeomDestroy(s->geoms[k]);
    dBodyDestroy(s->bodies[k]);
    s->made.bodies_destroyed++;
    s->made.geoms_destroyed++;
}

// A joint of a random type between two different bodies, anchored between them.
static void make_joint(soak_scene *s, int j)
{
    int a = (int)(uniform(s) * s->nbodies), b = (int)(uniform(s) * s->nbodies);
    if (a == b) return;
    dJointID jt;
    const dReal *pa = dBodyGetPosition(s->bodies[a]), *pb = dBodyGetPosition(s->bodies[b]);
    dReal mid[3] = {(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2};
    switch ((int)(uniform(s) * 4)) {
    case 0:
        jt = dJointCreateBall(s->world, 0);
        dJointAttach(jt, s->bodies[a], s->bodies[b]);
        dJointSetBallAnchor(jt, mid[0], mid[1], mid[2]);
        break;
    case 1:
        jt = dJointCreateHinge(s->world, 0);
        dJointAttach(jt, s->bodies[a], s->bodies[b]);
        dJointSetHingeAnchor(jt, mid[0], mid[1], mid[2]);
        dJointSetHingeAxis(jt, 0, 0, 1);
        dJointSetHingeParam(jt, dParamLoStop, -1);
        dJointSetHingeParam(jt, dParamHiStop, 1);
        break;
    case 2:
        jt = dJointCreateSlider(s->world, 0);
        dJointAttach(jt, s->bodies[a], s->bodies[b]);
        dJointSetSliderAxis(jt, pb[0] - pa[0] + (dReal)1e-3, pb[1] - pa[1], pb[2] - pa[2]);
        dJointSetSliderParam(jt, dParamLoStop, -(dReal)0.5);
        dJointSetSliderParam(jt, dParamHiStop, (dReal)0.5);
        break;
    default:
        jt = dJointCreateFixed(s->world, 0);
        dJointAttach(jt, s->bodies[a], s->bodies[b]);
        dJointSetFixed(jt);
        break;
    }
    s->joints[j] = jt;
    s->joint_ends[j][0] = a;
    s->joint_ends[j][1] = b;
    s->made.joints_made++;
}

static void near_callback(void *data, dGeomID o1, dGeomID o2)
{
    soak_scene *s = data;
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;
    dContact c[MAX_CONTACTS];
    int n = dCollide(o1, o2, MAX_CONTACTS, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = dContactApprox1 | dContactSoftCFM;
        c[i].surface.mu = (dReal)0.6;
        c[i].surface.soft_cfm = (dReal)1e-4;
        dJointAttach(dJointCreateContact(s->world, s->contacts, &c[i]), b1, b2);
    }
}

soak_scene *soak_create(int bodies, unsigned long long seed)
{
    soak_scene *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->rng = seed * 0x9E3779B97F4A7C15ULL + 1;
    s->nbodies = bodies < 2 ? 2 : bodies > MAX_BODIES ? MAX_BODIES : bodies;
    s->world = dWorldCreate();
    dWorldSetGravity(s->world, 0, 0, (dReal)-9.81);
    dWorldSetCFM(s->world, (dReal)1e-5);
    dWorldSetQuickStepNumIterations(s->world, 20);
    dWorldSetAutoDisableFlag(s->world, 1);
    s->space = dHashSpaceCreate(0);
    s->contacts = dJointGroupCreate(0);
    s->ground = dCreatePlane(s->space, 0, 0, 1, 0);
    for (int k = 0; k < s->nbodies; k++) spawn_body(s, k);
    return s;
}

void soak_step(soak_scene *s)
{
    // churn: about one body in 20 steps, a joint made or broken in 50,
    // a static box in 200
    if (uniform(s) < 0.05) {
        int k = (int)(uniform(s) * s->nbodies);
        kill_body(s, k);
        spawn_body(s, k);
    }
    if (uniform(s) < 0.02) {
        int j = (int)(uniform(s) * MAX_JOINTS);
        if (s->joints[j]) destroy_joint(s, j);
        else make_joint(s, j);
    }
    if (uniform(s) < 0.005) {
        int k = (int)(uniform(s) * MAX_STATIC);
        if (s->statics[k]) {
            dGeomDestroy(s->statics[k]);
            s->statics[k] = 0;
            s->made.geoms_destroyed++;
        } else {
            s->statics[k] = dCreateBox(s->space, 1, 1, (dReal)0.3);
            dGeomSetPosition(s->statics[k], (dReal)between(s, -4, 4), (dReal)between(s, -4, 4),
                             (dReal)0.15);
            s->made.geoms_made++;
        }
    }
    // a body that left the scene comes back from above
    for (int k = 0; k < s->nbodies; k++) {
        const dReal *p = dBodyGetPosition(s->bodies[k]);
        if (fabs((double)p[0]) > 20 || fabs((double)p[1]) > 20 || p[2] < -5) {
            kill_body(s, k);
            spawn_body(s, k);
        }
    }
    dSpaceCollide(s->space, s, near_callback);
    if (s->steps % 16 == 15) dWorldStep(s->world, (dReal)0.01);
    else dWorldQuickStep(s->world, (dReal)0.01);
    dJointGroupEmpty(s->contacts);
    s->steps++;
}

soak_counts soak_count(const soak_scene *s)
{
    soak_counts c = s->made;
    c.bodies = s->nbodies;
    c.joints = 0;
    c.static_boxes = 0;
    for (int j = 0; j < MAX_JOINTS; j++) c.joints += s->joints[j] != 0;
    for (int k = 0; k < MAX_STATIC; k++) c.static_boxes += s->statics[k] != 0;
    c.space_geoms = dSpaceGetNumGeoms(s->space);
    return c;
}

int soak_all_finite(const soak_scene *s)
{
    for (int k = 0; k < s->nbodies; k++) {
        const dReal *p = dBodyGetPosition(s->bodies[k]), *q = dBodyGetQuaternion(s->bodies[k]);
        const dReal *v = dBodyGetLinearVel(s->bodies[k]), *w = dBodyGetAngularVel(s->bodies[k]);
        for (int i = 0; i < 3; i++)
            if (!isfinite(p[i]) || !isfinite(v[i]) || !isfinite(w[i])) return 0;
        for (int i = 0; i < 4; i++)
            if (!isfinite(q[i])) return 0;
    }
    return 1;
}

void soak_destroy(soak_scene *s)
{
    dJointGroupDestroy(s->contacts);
    dSpaceDestroy(s->space);   // cleanup on: its geoms go with it
    dWorldDestroy(s->world);   // the bodies and the joints outside groups
    free(s);
}
