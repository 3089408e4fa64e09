// SPDX-License-Identifier: BSD-3-Clause
//
// replay_scenes.h -- small versions of the bench scenes (pyramids of boxes,
// spheres, ragdolls, chains) for the replay and snapshot tests: each made of
// independent groups (islands that never touch one another) that can be
// created in any order, colliding through a hash space with a ground plane,
// stepped by any of the three steppers, on any number of threads.

#ifndef REPLAY_SCENES_H
#define REPLAY_SCENES_H

#include <ode/ode.h>
#include <stddef.h>
#include <stdint.h>

enum { SCENE_PYRAMID, SCENE_SPHERES, SCENE_RAGDOLLS, SCENE_CHAIN, SCENE_KINDS };
enum { STEP_WORLD, STEP_QUICK, STEP_FAST1, STEPPERS };

#define SCENE_GROUPS 4
#define SCENE_MAX_BODIES 160

typedef struct scene {
    int kind, stepper;
    dWorldID w;
    dSpaceID space;
    dJointGroupID contacts;
    dBodyID body[SCENE_MAX_BODIES];   // by logical index: group g's bodies together
    int nbody;
    int group_first[SCENE_GROUPS + 1];   // bodies of group g: [first[g], first[g+1])
    dThreadingImplementationID impl;
    dThreadingThreadPoolID pool;
} scene;

extern const char *const scene_names[SCENE_KINDS];
extern const char *const stepper_names[STEPPERS];

// Build a scene; its groups are created in the order `order` (a permutation of
// 0..SCENE_GROUPS-1, or NULL for 0, 1, 2, 3). threads > 0 steps it on a pool
// of that many threads.
void scene_build(scene *s, int kind, int stepper, const int *order, int threads);
// Collide, step (0.01 s), empty the contact group.
void scene_step(scene *s);
// Bodies' pos, q, lvel, avel (13 reals each) by logical index.
void scene_state(const scene *s, dReal *out);
#define SCENE_STATE_SIZE (13 * SCENE_MAX_BODIES)
uint64_t scene_hash(const scene *s);
void scene_destroy(scene *s);

// Scene `kind` built alone and stepped `steps` times under QuickStep, the
// state after each step into states (steps x SCENE_STATE_SIZE): for tests
// that run a scene two ways (an internal switch) and compare.
void scene_quick_states(int kind, int steps, dReal *states);
// The first step at which two runs' states a and b (steps states of size
// numbers each) differ, or -1.
int first_state_difference(const dReal *a, const dReal *b, int steps, size_t size);

#endif
