/* SPDX-License-Identifier: BSD-3-Clause */
/* snapshot.h -- ours, not ODE's: saving and restoring a world's state, and a
 * watchdog that explains (and can undo) a step that blew up.
 *
 * A snapshot holds everything a step reads of a world: the world's
 * parameters and step counter; each body's pose, velocities, force and
 * torque accumulators, flags, mass, damping and auto-disable state (speed
 * samples and idle counters); each joint's type-specific parameters (anchors,
 * axes, limits, motors, stored rest orientation, flags); dWorldQuickStep's
 * contact-force cache (its warm start); and the random generator's seed
 * (dRandGetSeed, global to the library). Stepping on from a restored snapshot
 * gives bit-identical states to stepping on from the moment it was taken.
 *
 * What it does not hold: user data pointers, moved callbacks, feedback
 * pointers and the feedback structures (user memory, written by every step;
 * they keep their current values), threading settings, and contact joints
 * (made anew from collision before every step; those alive at restore are
 * left as they are). Geoms follow their bodies: a restore moves every body's
 * geoms (dGeomMoved). The geoms themselves are in a space's snapshot
 * (dSpaceSnapshot, libodecollide): enabled or not, category and collide
 * bits, the pose of geoms not on a body, the sizes of spheres, boxes,
 * capsules, cylinders, planes and rays (and the rays' flags); not offsets,
 * the geom inside a geometry transform, nor the data of triangle meshes,
 * heightfields and convex hulls (user memory).
 *
 * A snapshot restores into the world it was taken from, whose bodies and
 * non-contact joints must still be the same objects in the same order (a
 * body or joint created or destroyed since makes dWorldRestore refuse).
 * Restoring into another world, or a fresh one, is not supported. The same
 * holds for a space and its geoms (nested spaces included, in order).
 *
 * Format: a 32-byte header (magic "ODESNAP\0", format version, sizeof(dReal),
 * payload size, FNV-1a 64 checksum of the payload) and the payload, in this
 * machine's byte order. dWorldRestore checks all of it, and the payload against
 * the world, before it changes anything: a bad buffer or file is reported
 * through the debug handler (d_ERR_UASSERT, naming the function and what is
 * wrong) and leaves the world untouched. */
#ifndef ODE_SNAPSHOT_H
#define ODE_SNAPSHOT_H

#include <stddef.h>
#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Write w's snapshot into buffer if capacity is enough, and return its size
 *  in bytes either way (as snprintf: buffer may be NULL to ask the size).
 *  Returns 0 for a bad world (reported). */
ODE_API size_t dWorldSnapshot(dWorldID w, void *buffer, size_t capacity);
/** Restore w from a snapshot of size bytes taken of w. Returns 1, or 0 (after
 *  reporting) with w untouched. */
ODE_API int dWorldRestore(dWorldID w, const void *buffer, size_t size);
/** The same through a file (written whole, or reported). Return 1 or 0. */
ODE_API int dWorldSnapshotToFile(dWorldID w, const char *path);
ODE_API int dWorldRestoreFromFile(dWorldID w, const char *path);

/** The same for the geoms of a space and the spaces in it (libodecollide). */
ODE_API size_t dSpaceSnapshot(dSpaceID space, void *buffer, size_t capacity);
ODE_API int dSpaceRestore(dSpaceID space, const void *buffer, size_t size);

/* ---- watchdog ---------------------------------------------------------- */

/** What a watchdog checks after each step. A zero limit is not checked. */
typedef struct dWatchdogLimits {
    dReal max_linear_speed;       /**< m/s, any body */
    dReal max_angular_speed;      /**< rad/s, any body */
    dReal max_joint_error;        /**< m between a joint's two anchors (ball, hinge,
                                       universal, hinge-2; double ball: off its distance) */
    dReal max_energy_growth;      /**< factor of the kinetic energy in one step */
    dReal min_energy;             /**< energy growth below this many J is ignored */
    /* Used to name the likely cause of what was detected: */
    dReal max_mass_ratio;         /**< of the two bodies of a joint (contacts too) */
    dReal max_contact_depth;      /**< m, a contact joint's depth */
    dReal max_rotation_per_step;  /**< rad, angular speed times the step size */
    int keep_last_good;           /**< 1: copy the state before each step, so that the
                                       callback can ask for a roll back */
} dWatchdogLimits;

/** What was detected (dWatchdogReport.detected). */
enum {
    dWatchdogNonFinite = 1 << 0,
    dWatchdogLinearSpeed = 1 << 1,
    dWatchdogAngularSpeed = 1 << 2,
    dWatchdogJointError = 1 << 3,
    dWatchdogEnergyGrowth = 1 << 4
};
/** The likely causes (dWatchdogReport.causes). */
enum {
    dWatchdogCauseMassRatio = 1 << 0,        /**< bodies of very different mass joined */
    dWatchdogCauseJointPulledApart = 1 << 1, /**< a joint's anchors far apart */
    dWatchdogCauseInterpenetration = 1 << 2, /**< a deep contact pushed bodies out */
    dWatchdogCauseLargeStep = 1 << 3         /**< a body turned too far in one step */
};

#define dWATCHDOG_MAX_NAMED 8

typedef struct dWatchdogReport {
    unsigned detected;            /**< dWatchdog... bits */
    unsigned causes;              /**< dWatchdogCause... bits */
    unsigned long step;           /**< the world's steps so far, this one included */
    dReal stepsize;
    dReal energy_before, energy_after;   /**< kinetic, J */
    int num_bodies;               /**< bodies named (at most dWATCHDOG_MAX_NAMED) */
    dBodyID bodies[dWATCHDOG_MAX_NAMED];
    int num_joints;
    dJointID joints[dWATCHDOG_MAX_NAMED];
    char text[1024];              /**< the same in words; "body #k", "joint #k": the
                                       k-th (from 0) in order of creation of the
                                       world's living bodies, joints (contacts too) */
} dWatchdogReport;

/** Called after a step that broke a limit. Return 1 to roll the world back to
 *  its state before the step (only with keep_last_good), 0 to keep it. */
typedef int dWatchdogCallback(void *user, dWorldID w, const dWatchdogReport *report);

/** Default limits: speeds 1e3 m/s and 1e3 rad/s, joint error 0.1 m, energy
 *  growth 10x above 1 J, mass ratio 100, contact depth 0.1 m, 0.5 rad per
 *  step, keep_last_good 1. */
ODE_API void dWatchdogLimitsSetDefaults(dWatchdogLimits *limits);
/** Watch w after each step (dWorldStep, dWorldQuickStep, dWorldStepFast1)
 *  with these limits (copied) and callback (may be NULL: the report goes to
 *  dMessage, d_ERR_UNKNOWN). limits NULL turns the watchdog off (the default:
 *  a step then costs one test more). A step rolled back returns 0. */
ODE_API void dWorldSetWatchdog(dWorldID w, const dWatchdogLimits *limits,
                               dWatchdogCallback *callback, void *user);

#ifdef __cplusplus
}
#endif

#endif
