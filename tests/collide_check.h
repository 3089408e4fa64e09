// SPDX-License-Identifier: BSD-3-Clause
//
// collide_check.h -- helpers the collision tests share: posing a geom, the depth
// of a point inside any geom of the native classes, the deepest of a set of contacts,
// which backends are built and which pairs they answer.

#ifndef TEST_COLLIDE_CHECK_H
#define TEST_COLLIDE_CHECK_H

#include <ode/ode.h>

// Rotate g by `angle` about the axis (ax, ay, az).
void set_rot(dGeomID g, dReal ax, dReal ay, dReal az, dReal angle);
// Depth of point p in g: positive inside, minus the distance outside (for the
// cylinder, which has no public function, computed here; the other classes
// use their ...PointDepth function).
dReal point_depth(dGeomID g, const dReal *p);
// Index of the deepest of n contacts.
int deepest(const dContactGeom *c, int n);
// Move the pair apart by contact k's depth + margin along its normal (a along
// it if placeable, else b against it), collide again, move back. Returns the
// deepest remaining depth (0 if apart): the sign rule of the contact.
dReal depth_after_separation(dGeomID a, dGeomID b, const dContactGeom *k, dReal margin);

// Whether a collision backend of that name is built (and registered).
int backend_built(const char *name);
// Whether the backend answers the pair itself: in strict mode a pair it
// leaves to native is reported instead of collided. Leaves strict mode off;
// the backend selected stays `backend`.
int backend_answers(const char *backend, dGeomID a, dGeomID b);

// The random poses of the tests: a 64-bit LCG, seeded by setting rng_state.
extern unsigned long long rng_state;
// Uniform in [lo, hi).
double rnd(double lo, double hi);

#endif
