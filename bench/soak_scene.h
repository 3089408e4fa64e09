// SPDX-License-Identifier: BSD-3-Clause
//
// soak_scene.h -- the long-run scene of bench/soak.c and tests/test_soak.c:
// boxes, spheres and capsules falling on a plane in a hash space, with ball,
// hinge, slider and fixed joints between them, while bodies (with their
// geoms), joints and static boxes are destroyed and created again as it runs
// (a seeded generator decides what and when, so every run is the same).

#ifndef SOAK_SCENE_H
#define SOAK_SCENE_H

#include <ode/ode.h>

typedef struct soak_scene soak_scene;

// A scene of `bodies` (<= 64) moving bodies, seeded.
soak_scene *soak_create(int bodies, unsigned long long seed);
// One step: churn (maybe destroy/create a body, a joint, a static box),
// collide, step (dWorldQuickStep; dWorldStep one step in 16), empty contacts.
void soak_step(soak_scene *s);
// What exists now, and what was created and destroyed so far.
typedef struct soak_counts {
    int bodies, joints, static_boxes, space_geoms;
    long bodies_made, joints_made, geoms_made;
    long bodies_destroyed, joints_destroyed, geoms_destroyed;
} soak_counts;
soak_counts soak_count(const soak_scene *s);
// 1 if every body's position, orientation and velocities are finite.
int soak_all_finite(const soak_scene *s);
// Destroy everything (the world, the space, the joints and the geoms).
void soak_destroy(soak_scene *s);

#endif
