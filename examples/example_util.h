// SPDX-License-Identifier: BSD-3-Clause
//
// example_util.h -- what the drawstuff examples share: the dReal drawing
// names (as ODE's demos map them), drawing any geom, a contact callback with
// one surface per geom, and the checks each example runs when its loop ends.

#ifndef EXAMPLE_UTIL_H
#define EXAMPLE_UTIL_H

#include <ode/ode.h>
#include <drawstuff/drawstuff.h>

// Draw from dReal arrays in either precision, as ODE's demos do.
#ifdef dDOUBLE
#define dsDrawBox dsDrawBoxD
#define dsDrawSphere dsDrawSphereD
#define dsDrawCylinder dsDrawCylinderD
#define dsDrawCapsule dsDrawCapsuleD
#define dsDrawLine dsDrawLineD
#define dsDrawTriangle dsDrawTriangleD
#define dsDrawTriangles dsDrawTrianglesD
#define dsDrawConvex dsDrawConvexD
#endif

// Frames per simulated second: every example steps dt = 1 / EXU_RATE per frame.
#define EXU_RATE 60
#define EXU_DT ((dReal)1.0 / EXU_RATE)

// 1 when the program was started with -headless (or DS_HEADLESS=1), the way
// drawstuff runs it without a window.
int exu_headless(int argc, char **argv);

// The contact surface of a geom (its data pointer if set, else the default)
// and the contact joints made by exu_collide.
typedef struct exu_contacts {
    dWorldID world;
    dJointGroupID group;
    dSurfaceParameters surface;   // used for geoms without their own
    int max_per_pair;
    // Filled for drawing: the last exu_collide's contacts.
    dContactGeom *seen;
    int seen_count;
    int seen_capacity;
} exu_contacts;

// Empty the group, collide the space and attach a contact joint per contact.
// A geom's data, if set, is a dSurfaceParameters* used for its contacts (the
// modes of both, the mean mu, the bounce of the bouncier). Bodies already joined by
// a non-contact joint do not collide.
void exu_collide(exu_contacts *c, dSpaceID space);

// Draw a geom where it is (sphere, box, capsule, cylinder, plane-less classes,
// ray as a line, transform's child; triangle meshes triangle by triangle).
void exu_draw_geom(dGeomID g);

// Draw each seen contact as a small sphere and a line along its normal.
void exu_draw_contacts(const exu_contacts *c, dReal normal_length);

// 1 when a body's position, rotation and velocities are all finite.
int exu_body_finite(dBodyID b);

// The lowest z of a geom's bounding box.
dReal exu_geom_bottom(dGeomID g);

// The speed of a body (linear, m/s).
dReal exu_speed(dBodyID b);

// Print the key help at start.
void exu_keys(const char *name, const char *help);

// Print the one line of what was checked; returns 0 if ok, 1 if not.
int exu_report(const char *name, int ok, const char *what, ...);

#endif
