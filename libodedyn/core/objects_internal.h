// SPDX-License-Identifier: BSD-3-Clause
//
// objects_internal.h -- the private structures of the dynamics library:
// world, body, joint, joint group, and the interface through which each joint
// type contributes constraint rows to the steppers.

#ifndef DX_OBJECTS_INTERNAL_H
#define DX_OBJECTS_INTERNAL_H

#include <ode/objects.h>
#include <ode/odemath.h>
#include <stdint.h>

#include "arena.h"
#include "dx_check.h"

// ---- handles -----------------------------------------------------------

// Every object starts with a header so a handle can be checked: the magic
// names the kind while the object lives and is DX_MAGIC_DEAD after destroy.
// Destroyed bodies and worlds go to a free list, never back to the system,
// so reading a dead handle's header is always safe.
typedef struct dxObjectHeader {
    uint32_t magic;
    uint32_t generation;   // bumped each time the memory is reused
} dxObjectHeader;

enum {
    DX_MAGIC_WORLD = 0x576f726cu,   // "Worl"
    DX_MAGIC_BODY = 0x426f6479u,    // "Body"
    DX_MAGIC_JOINT = 0x4a6f696eu,   // "Join"
    DX_MAGIC_GROUP = 0x47727570u,   // "Grup"
    DX_MAGIC_DEAD = 0xdeadbeefu
};

// ---- bodies ------------------------------------------------------------

enum {
    DX_BODY_DISABLED = 1 << 0,
    DX_BODY_FINITE_ROTATION = 1 << 1,
    DX_BODY_FINITE_ROTATION_AXIS = 1 << 2,
    DX_BODY_NO_GRAVITY = 1 << 3,
    DX_BODY_AUTO_DISABLE = 1 << 4,
    DX_BODY_KINEMATIC = 1 << 5,
    DX_BODY_NO_GYROSCOPIC = 1 << 6,
    DX_BODY_LINEAR_DAMPING = 1 << 7,
    DX_BODY_ANGULAR_DAMPING = 1 << 8,
    DX_BODY_MAX_ANGULAR_SPEED = 1 << 9,
    DX_BODY_AUTO_DISABLE_SF1 = 1 << 10
};

// One end of a joint as seen from a body: each joint has two nodes; node k
// sits in the joint list of the joint's body k and points at the other body.
typedef struct dxJointNode {
    struct dxJoint *joint;
    struct dxBody *other;        // the body at the other end, or NULL (static world)
    struct dxJointNode *next;    // next node in this body's list
} dxJointNode;

typedef struct dxAutoDisable {
    dReal linear_threshold;      // average speed below which a body counts as idle
    dReal angular_threshold;
    unsigned average_samples;    // speeds averaged over this many steps (>= 1)
    int idle_steps;              // idle this many steps ...
    dReal idle_time;             // ... and this long before disabling
} dxAutoDisable;

typedef struct dxDamping {
    dReal linear_scale, angular_scale;
    dReal linear_threshold, angular_threshold;
    dReal max_angular_speed;
} dxDamping;

struct dxBody {
    dxObjectHeader hdr;
    // What the island walk, dJointAttach and the notification after the
    // move read, in the first 64 bytes; then what a step reads of every
    // body; the rest last.
    struct dxWorld *world;
    struct dxBody *next;          // the world's body list
    unsigned flags;               // DX_BODY_...
    int tag;                      // scratch for the island walk and steppers
    dxJointNode *joints;          // the nodes of the joints attached here
    int num_joints;
    dGeomID first_geom;           // kept for the collision library
    void (*moved_callback)(dBodyID);

    dMass mass;                   // centre of mass at the body origin
    dReal inv_mass;
    dMatrix3 inv_inertia;         // body frame
    dVector3 pos;
    dQuaternion q;
    dMatrix3 R;                   // always the rotation of q
    dVector3 lvel, avel;
    dVector3 force, torque;       // accumulators, zeroed after each step
    // The gyroscopic work ledger (solvers/rows.c): this step's gyroscopic
    // torque (world), its work over the first half of the step, and the work
    // it did in the last step, which the next step's torque gives back.
    dVector3 gyro_torque;
    dReal gyro_work, gyro_pending;
    dxDamping damping;

    struct dxBody *prev;
    void *userdata;
    dVector3 finite_rot_axis;
    dxAutoDisable adis;
    int adis_idle_steps;          // consecutive idle steps so far
    dReal adis_idle_time;
    dReal *adis_lvel_samples;     // ring buffers of adis.average_samples speeds
    dReal *adis_avel_samples;
    unsigned adis_sample_next, adis_samples_taken, adis_samples_size;
    dReal sf1_threshold;          // StepFast1 auto-disable
    int sf1_steps, sf1_idle_steps;
};

// ---- joints ------------------------------------------------------------

enum {
    DX_JOINT_IN_GROUP = 1 << 0,
    DX_JOINT_REVERSE = 1 << 1,    // attached as (0, b): b is stored as body 0
    DX_JOINT_DISABLED = 1 << 2,
    DX_JOINT_DEAD_WORLD = 1 << 3, // the world was destroyed; only the group may free it
    DX_JOINT_PLAIN_CONTACT = 1 << 4 // a contact whose rows dxJointContactRows gives (set at creation)
};

// How many constraint rows a joint adds this step; the first `nub` are
// unbounded (equality) rows.
typedef struct dxJointRowCount {
    int m;
    int nub;
} dxJointRowCount;

// Where a joint writes its rows: row i of each array at + i * rowskip.
// J1l/J1a: linear and angular Jacobian of body 0 (3 each); J2l/J2a: body 1
// (absent when body 1 is the static world). c: right-hand side (velocity
// error correction, fps * erp * position error); cfm, lo, hi: per row
// (pre-filled with the world's cfm, -inf, +inf); findex: friction rows name
// their normal row (relative to the joint's first row), -1 otherwise.
typedef struct dxJointRows {
    dReal fps;        // 1 / step size
    dReal erp;        // the world's ERP
    int rowskip;
    dReal *J1l, *J1a, *J2l, *J2a;
    dReal *c, *cfm, *lo, *hi;
    int *findex;
} dxJointRows;

typedef struct dxJoint dxJoint;

typedef struct dxJointClass {
    dJointType type;
    const char *name;             // for messages: "hinge", "ball", ...
    size_t size;                  // of the whole joint structure
    void (*init)(dxJoint *j);     // defaults after creation
    void (*count_rows)(dxJoint *j, dxJointRowCount *count);
    void (*fill_rows)(dxJoint *j, dxJointRows *rows);
    // Called at the end of dJointAttach: recompute the body-relative anchors,
    // axes, offsets and rest orientation from the joint's world values (as its
    // getters report them with the new bodies) and the bodies' current poses,
    // as ODE 0.16 does, so a newly attached joint starts without error.
    // NULL for joints that keep nothing body-relative.
    void (*attached)(dxJoint *j);
} dxJointClass;

struct dxJoint {
    dxObjectHeader hdr;
    const dxJointClass *cls;
    struct dxWorld *world;
    struct dxJoint *next, *prev;  // the world's joint list
    struct dxJointGroup *group;
    struct dxJoint *group_prev;   // the group's next older joint (its list, newest first)
    void *userdata;
    unsigned flags;               // DX_JOINT_...
    unsigned walk;                // the world's island_walk when the island walk last met it
    dxJointNode node[2];          // node[k] is in the list of body k
    dJointFeedback *feedback;
    int tag;                      // scratch for the island walk and steppers
    dxJointRowCount rows;         // filled by the stepper each step
};

// The bodies of a joint as stored (body 0 is never NULL if one exists).
static inline struct dxBody *dxJointBody(const dxJoint *j, int k)
{
    return j->node[1 - k].other;
}

// ---- joint groups ------------------------------------------------------

typedef struct dxJointGroupChunk dxJointGroupChunk;

struct dxJointGroup {
    dxObjectHeader hdr;
    dxJointGroupChunk *chunks;    // joints are carved from these, freed on destroy
    dxJointGroupChunk *current;
    dxJoint *newest;              // the group's joints, newest first through group_prev
};

// ---- world -------------------------------------------------------------

// The unit normal and friction directions dJointCreateContact made last for
// a usual contact, and the normal as given that they were made from: a
// collider gives all of a pair's contacts one normal, so the next contact
// whose normal has the same bits copies them (joint_contact.c). `given` is
// not a number until the first.
typedef struct dxContactFrame {
    dReal given[3];
    dVector3 n, t1, t2;
} dxContactFrame;

struct dxWorld {
    dxObjectHeader hdr;
    struct dxBody *bodies;
    struct dxJoint *joints;
    int num_bodies, num_joints;
    void *userdata;

    dVector3 gravity;
    dReal erp, cfm;
    int qs_iterations;
    dReal qs_w;
    int position_iterations;      // sweeps of solvers/position_correction.c, 0: none
    dReal max_correcting_vel;
    dReal contact_surface_layer;
    dxAutoDisable adis;
    int adis_flag;
    int sf1_auto_enable_depth;
    dxDamping damping;

    dxArena *arena;               // the step's scratch: the main arena of `memory`
                                  // (NULL until the world has memory)
    struct dxStepMemory *memory;  // working memory, maybe shared (step_memory.c)
    // Threads for stepping (threading/world_threads.c): NULL, or a threading
    // implementation's functions; at most islands_max_threads (0: any number)
    // of its threads step islands.
    const dThreadingFunctionsInfo *threading;
    dThreadingImplementationID threading_impl;
    unsigned islands_max_threads;
    dCallWaitID step_wait;        // of threading_impl, allocated at the first threaded step
    uint32_t step_count;          // steps taken (any stepper), for the warm start
    unsigned island_walk;         // the island walks so far (never 0 during one): a joint
                                  // met by this step's walk has it as its walk
    struct dxWarmCache *qs_warm;  // dWorldQuickStep's contact forces of the last
                                  // step (quickstep_warm.c), NULL until one
    struct dxWatchdog *watchdog;  // dWorldSetWatchdog's (watchdog.c), NULL when off
    int watchdog_stepping;        // 1 while the watchdog runs the step it watches
    dxContactFrame contact_frame; // the last usual contact's (joint_contact.c)
};

// Free a world's warm-start cache (dWorldDestroy).
void dxWarmCacheFree(struct dxWorld *w);
// Free a world's watchdog (dWorldDestroy).
void dxWatchdogFree(struct dxWorld *w);
// Give back what the world holds of its threading implementation (dWorldDestroy).
void dxWorldThreadingRelease(struct dxWorld *w);

// ---- shared internal functions ------------------------------------------

// Checks for the API entry points.
static inline int dxWorldIsLive(const struct dxWorld *w)
{
    return w != NULL && w->hdr.magic == DX_MAGIC_WORLD;
}
static inline int dxBodyIsLive(const struct dxBody *b)
{
    return b != NULL && b->hdr.magic == DX_MAGIC_BODY;
}
static inline int dxJointIsLive(const struct dxJoint *j)
{
    return j != NULL && j->hdr.magic == DX_MAGIC_JOINT;
}

// The steppers a watchdog runs (watchdog.c).
typedef enum dxStepper { DX_STEP_WORLD, DX_STEP_QUICK, DX_STEP_FAST1 } dxStepper;
// 1 if w is watched and not already inside the watched step: the public
// steppers then hand the step to dxWatchdogStep.
static inline int dxWatchdogWants(const struct dxWorld *w)
{
    return dxWorldIsLive(w) && w->watchdog && !w->watchdog_stepping;
}
// Run the step (iterations: StepFast1's) and check it; returns the step's
// result, or 0 if it was rolled back.
int dxWatchdogStep(struct dxWorld *w, dReal h, dxStepper stepper, int iterations);

// Tell the collision library that a body moved (dGeomMoved for each geom).
void dxBodyNotifyMoved(struct dxBody *b);
// Recompute R from q (after q changed).
void dxBodyUpdateRotation(struct dxBody *b);

// Create a joint of class cls in world w (and group g, or NULL).
dxJoint *dxJointCreate(struct dxWorld *w, struct dxJointGroup *g, const dxJointClass *cls);
// The same with only the common part (struct dxJoint) written: the caller
// writes every field of the type's own part (cls->init is not called).
dxJoint *dxJointCreateBare(struct dxWorld *w, struct dxJointGroup *g, const dxJointClass *cls);
// Detach from both bodies (keeps the joint in its world).
void dxJointDetach(dxJoint *j);
// Unlink from the world, detach, and poison; frees unless it lives in a group.
void dxJointRemove(dxJoint *j);

#endif
