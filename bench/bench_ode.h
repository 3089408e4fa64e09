// SPDX-License-Identifier: BSD-3-Clause
//
// bench_ode.h -- what the ODE-API scenes share: the contact callback, the stepper choice,
// kinetic energy and joint separation. Written against the public ODE API only, so the same
// code builds against this project and against the reference ODE.

#ifndef BENCH_ODE_H
#define BENCH_ODE_H

#include <ode/ode.h>
#ifdef BENCH_HAVE_POSITION_ITERATIONS
#include <ode/position_correction.h>
#endif
#include <math.h>
#include <stdint.h>

#include "bench_common.h"

#ifndef BENCH_ENGINE
#define BENCH_ENGINE "ode"
#endif

#define BENCH_MAX_CONTACTS 4

// What the near callback needs, and what it measures.
typedef struct bench_contacts {
    dWorldID world;
    dJointGroupID group;
    dSurfaceParameters surface;
    int skip_connected;  // skip pairs of bodies joined by a non-contact joint
    int skip_same_data;  // skip pairs of geoms whose (non-null) data pointers are equal
    double max_depth;    // deepest contact seen so far
    long contacts;       // contact joints made so far
} bench_contacts;

// mu 0.8 with the friction pyramid approximation: the surface of every scene.
static inline void bench_contacts_init(bench_contacts *c, dWorldID world)
{
    memset(c, 0, sizeof *c);
    c->world = world;
    c->group = dJointGroupCreate(0);
    c->surface.mode = dContactApprox1;
    c->surface.mu = (dReal)0.8;
}

static inline void bench_near(void *data, dGeomID o1, dGeomID o2)
{
    bench_contacts *c = (bench_contacts *)data;
    dBodyID b1 = dGeomGetBody(o1);
    dBodyID b2 = dGeomGetBody(o2);
    if (!b1 && !b2) return;
    if (c->skip_connected && b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;
    if (c->skip_same_data && dGeomGetData(o1) && dGeomGetData(o1) == dGeomGetData(o2)) return;
    dContact contact[BENCH_MAX_CONTACTS];
    int n = dCollide(o1, o2, BENCH_MAX_CONTACTS, &contact[0].geom, sizeof(dContact));
    for (int i = 0; i < n; i++) {
        contact[i].surface = c->surface;
        if (contact[i].geom.depth > c->max_depth) c->max_depth = contact[i].geom.depth;
        dJointID j = dJointCreateContact(c->world, c->group, &contact[i]);
        dJointAttach(j, b1, b2);
    }
    c->contacts += n;
}

typedef enum bench_stepper { BENCH_QUICK, BENCH_WORLD, BENCH_FAST } bench_stepper;

// stepper=quick|world|fast (dWorldQuickStep, dWorldStep, dWorldStepFast1). ODE 0.16 dropped
// dWorldStepFast1: builds define BENCH_HAVE_STEPFAST where the engine has it; elsewhere
// stepper=fast exits with status 3 (not available).
static inline bench_stepper bench_arg_stepper(bench_args *a, const char *def)
{
    const char *s = bench_arg_str(a, "stepper", def);
    if (strcmp(s, "quick") == 0) return BENCH_QUICK;
    if (strcmp(s, "world") == 0) return BENCH_WORLD;
    if (strcmp(s, "fast") == 0) {
#ifdef BENCH_HAVE_STEPFAST
        return BENCH_FAST;
#else
        fprintf(stderr, "%s: this engine has no dWorldStepFast1\n", a->argv[0]);
        exit(3);
#endif
    }
    fprintf(stderr, "%s: stepper is quick, world or fast, not '%s'\n", a->argv[0], s);
    exit(2);
}

// position_iterations=N (not given: 0, ODE's own step): this project's opt-in position
// correction, N sweeps after each step (dWorldSetPositionIterations). Builds define
// BENCH_HAVE_POSITION_ITERATIONS where the engine has it; elsewhere asking for it exits with
// status 3 (not available).
static inline int bench_arg_position_iterations(bench_args *a)
{
    const int n = (int)bench_arg_int(a, "position_iterations", 0);
#ifndef BENCH_HAVE_POSITION_ITERATIONS
    if (n > 0) {
        fprintf(stderr, "%s: this engine has no dWorldSetPositionIterations\n", a->argv[0]);
        exit(3);
    }
#endif
    return n;
}

static inline void bench_set_position_iterations(dWorldID w, int n)
{
#ifdef BENCH_HAVE_POSITION_ITERATIONS
    dWorldSetPositionIterations(w, n);
#else
    (void)w;
    (void)n;
#endif
}

static inline const char *bench_stepper_name(bench_stepper s)
{
    return s == BENCH_QUICK ? "quick" : s == BENCH_WORLD ? "world" : "fast";
}

// threads=N (0: none, the default): the world steps on a multi-threaded implementation served
// by a pool of N threads (ODE 0.16's threading API; the stepping thread waits, so N threads
// work). The variant name gets "-Nt".
typedef struct bench_threads {
    int n;
    dThreadingImplementationID impl;
    dThreadingThreadPoolID pool;
    char variant[32];
} bench_threads;

static inline void bench_threads_start(bench_threads *t, bench_args *a, dWorldID w,
                                       const char *variant)
{
    memset(t, 0, sizeof *t);
    const char *s = bench_arg_str(a, "threads", "0");
    char *end;
    t->n = (int)strtol(s, &end, 10);
    if (*end || t->n < 0) {
        fprintf(stderr, "%s: threads wants a count, not '%s'\n", a->argv[0], s);
        exit(2);
    }
    snprintf(t->variant, sizeof t->variant, "%s", variant);
    if (t->n == 0) return;
    snprintf(t->variant, sizeof t->variant, "%s-%dt", variant, t->n);
    t->impl = dThreadingAllocateMultiThreadedImplementation();
    t->pool = dThreadingAllocateThreadPool((unsigned)t->n, 0, dAllocateFlagBasicData, NULL);
    if (!t->impl || !t->pool) {
        fprintf(stderr, "%s: this engine has no thread pools\n", a->argv[0]);
        exit(3);
    }
    dThreadingThreadPoolServeMultiThreadedImplementation(t->pool, t->impl);
    dWorldSetStepThreadingImplementation(w, dThreadingImplementationGetFunctions(t->impl),
                                         t->impl);
}

static inline void bench_threads_stop(bench_threads *t, dWorldID w)
{
    if (t->n == 0) return;
    dThreadingImplementationShutdownProcessing(t->impl);
    dThreadingFreeThreadPool(t->pool);
    dWorldSetStepThreadingImplementation(w, NULL, NULL);
    dThreadingFreeImplementation(t->impl);
}

// One step of the chosen stepper; iterations for QuickStep are set on the world.
static inline void bench_step(dWorldID w, bench_stepper s, dReal dt, int iterations)
{
    if (s == BENCH_QUICK)
        dWorldQuickStep(w, dt);
    else if (s == BENCH_WORLD)
        dWorldStep(w, dt);
#ifdef BENCH_HAVE_STEPFAST
    else
        dWorldStepFast1(w, dt, iterations);
#else
    (void)iterations;
#endif
}

// One timed step of a scene: collide the space through bench_near, step, empty the contact
// group; the seconds of each part are added to *coll_s and *step_s.
static inline void bench_timed_step(dSpaceID space, bench_contacts *con, bench_stepper s,
                                    dReal dt, int iterations, double *coll_s, double *step_s)
{
    bench_count_on();
    double t0 = bench_now();
    dSpaceCollide(space, con, bench_near);
    double t1 = bench_now();
    bench_step(con->world, s, dt, iterations);
    dJointGroupEmpty(con->group);
    double t2 = bench_now();
    bench_count_off();
    *coll_s += t1 - t0;
    *step_s += t2 - t1;
}

// Linear plus rotational kinetic energy of a body (its mass is centred at the body origin).
static inline double bench_body_ke(dBodyID b)
{
    dMass m;
    dBodyGetMass(b, &m);
    const dReal *v = dBodyGetLinearVel(b);
    const dReal *w = dBodyGetAngularVel(b);
    const dReal *R = dBodyGetRotation(b);
    double wl[3];  // angular velocity in the body frame: R^T w
    for (int i = 0; i < 3; i++) wl[i] = R[i] * w[0] + R[4 + i] * w[1] + R[8 + i] * w[2];
    double rot = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) rot += wl[i] * m.I[4 * i + j] * wl[j];
    double lin = (double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2];
    return 0.5 * m.mass * lin + 0.5 * rot;
}

// Speed of a body's origin (m/s): the final "at rest" figure.
static inline double bench_body_speed(dBodyID b)
{
    const dReal *v = dBodyGetLinearVel(b);
    return sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
}

// Distance between a joint's two anchors (ball, hinge, universal), 0 for other joints.
static inline double bench_joint_separation(dJointID j)
{
    dVector3 a1, a2;
    switch (dJointGetType(j)) {
    case dJointTypeBall:
        dJointGetBallAnchor(j, a1);
        dJointGetBallAnchor2(j, a2);
        break;
    case dJointTypeHinge:
        dJointGetHingeAnchor(j, a1);
        dJointGetHingeAnchor2(j, a2);
        break;
    case dJointTypeUniversal:
        dJointGetUniversalAnchor(j, a1);
        dJointGetUniversalAnchor2(j, a2);
        break;
    default:
        return 0;
    }
    double dx = a1[0] - a2[0], dy = a1[1] - a2[1], dz = a1[2] - a2[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

// Body rotation R = Rf * Rl (row-major 3x4 matrices, as dMatrix3).
static inline void bench_rmul(dMatrix3 out, const dMatrix3 a, const dMatrix3 b)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            out[4 * i + j] = a[4 * i] * b[j] + a[4 * i + 1] * b[4 + j] + a[4 * i + 2] * b[8 + j];
        out[4 * i + 3] = 0;
    }
}

// out = R * v + t
static inline void bench_xform(dVector3 out, const dMatrix3 R, const dReal *t, double x,
                               double y, double z)
{
    for (int i = 0; i < 3; i++)
        out[i] = (dReal)(R[4 * i] * x + R[4 * i + 1] * y + R[4 * i + 2] * z + (t ? t[i] : 0));
}

// A square terrain of side 2 half centred on the origin, z = height(x, y):
// (cells + 1)^2 vertices in *v, 2 cells^2 upward-facing triangles in *tri
// (both malloc'ed; the caller frees them). Returns 0 when out of memory.
static inline int bench_grid_terrain(int cells, double half, double (*height)(double, double),
                                     double (**v)[3], dTriIndex (**tri)[3])
{
    const int nv = (cells + 1) * (cells + 1), nt = 2 * cells * cells;
    *v = (double(*)[3])malloc(sizeof **v * (size_t)nv);
    *tri = (dTriIndex(*)[3])malloc(sizeof **tri * (size_t)nt);
    if (!*v || !*tri) return 0;
    for (int j = 0; j <= cells; j++)
        for (int i = 0; i <= cells; i++) {
            double *p = (*v)[j * (cells + 1) + i];
            p[0] = -half + 2 * half * i / cells;
            p[1] = -half + 2 * half * j / cells;
            p[2] = height(p[0], p[1]);
        }
    int t = 0;
    for (int j = 0; j < cells; j++)
        for (int i = 0; i < cells; i++) {
            dTriIndex a = (dTriIndex)(j * (cells + 1) + i), b = a + 1;
            dTriIndex c = a + (dTriIndex)(cells + 1), d = c + 1;
            (*tri)[t][0] = a, (*tri)[t][1] = b, (*tri)[t][2] = d, t++;
            (*tri)[t][0] = a, (*tri)[t][1] = d, (*tri)[t][2] = c, t++;
        }
    return 1;
}

// The trimesh geom (in space) of a bench_grid_terrain of that many cells,
// its data in *data built from v and tri in place (keep them until the data
// is destroyed), temporal coherence set to tc for the classes that have it
// (off by default, as in ODE).
static inline dGeomID bench_terrain_geom(dSpaceID space, int cells, double (*v)[3],
                                         dTriIndex (*tri)[3], int tc, dTriMeshDataID *data)
{
    const int nv = (cells + 1) * (cells + 1), nt = 2 * cells * cells;
    *data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(*data, v, 3 * sizeof(double), nv, tri, 3 * nt,
                                3 * sizeof(dTriIndex));
    dGeomID terrain = dCreateTriMesh(space, *data, NULL, NULL, NULL);
    dGeomTriMeshEnableTC(terrain, dSphereClass, tc);
    dGeomTriMeshEnableTC(terrain, dBoxClass, tc);
    dGeomTriMeshEnableTC(terrain, dCapsuleClass, tc);
    return terrain;
}

#endif
