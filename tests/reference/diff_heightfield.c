// SPDX-License-Identifier: BSD-3-Clause
//
// diff_heightfield.c -- heightfields against the reference ODE 0.16.
//
// Bounding boxes of array fields (not placeable, and placed with no turn:
// see bounds()), and on
// faces, where the answer is unique, the deepest contact's depth and normal
// (counts differ and are not printed), tolerance 1e-9:
// - a sphere, a box (any yaw, flat) and a capsule (lying) sunk into a flat
//   field, well inside it, both argument orders, the field placed with a
//   rotation (its Y up to the world's Z);
// - a sphere sunk into a sloped planar field (every cell coplanar) at
//   random places, both orders, the field not placeable.
// - rays straight down onto the sloped field: hit, depth, position, normal.
//
// Not compared, because the libraries differ there on purpose (README):
// spheres on curved fields near edges and vertices (the reference takes the
// plane contacts of every triangle under the geom and adds edge-ray
// contacts, so a ball gets several contacts with tilted normals at an edge;
// here, as on a trimesh, an edge between coplanar or concave faces gives
// none); a geom wholly under the surface (the reference reports one contact
// of depth lowest-height minus the geom's top, here the depth that lifts the
// geom out along the normal of the triangle under its centre).

#include "diff_print.h"
#include "diff_random.h"

#include <math.h>

enum { SCENES = 40 };

static void print_deepest(const char *name, dGeomID a, dGeomID b)
{
    dContactGeom c[32];
    int n = dCollide(a, b, 32, c, sizeof c[0]);
    int k = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[k].depth) k = i;
    dReal v[4] = { 0, 0, 0, 0 };
    if (n > 0) {
        v[0] = c[k].depth;
        for (int i = 0; i < 3; i++) v[1 + i] = c[k].normal[i];
    }
    diff_values(name, 1e-9, v, 4);
}

static void bounds(void)
{
    static const double h[12] = { 0, 1, 2, -1, 3, 0.5, 2, 2, 1, 0, -2, 4 };
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, h, 1, 6, 4, 4, 3, 0.5, 0.25, 0.75, 0);
    dGeomID fixed = dCreateHeightfield(0, d, 0), placed = dCreateHeightfield(0, d, 1);
    // Translated only: turned, the reference's box is too small (it takes,
    // per world axis, the least of the three local axes' extents where the
    // box of a turned box adds them), ours is the box around the turned one.
    dGeomSetPosition(placed, 1, -2, 3);
    dReal aabb[6];
    dGeomGetAABB(fixed, aabb);
    diff_values("heightfield_aabb", 1e-9, aabb, 6);
    dGeomGetAABB(placed, aabb);
    diff_values("heightfield_aabb_placed", 1e-9, aabb, 6);
    dGeomDestroy(fixed);
    dGeomDestroy(placed);
    dGeomHeightfieldDataDestroy(d);
}

static void primitives_on_flat_field(void)
{
    static float flat[41 * 41];
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildSingle(d, flat, 0, 20, 20, 41, 41, 1, 0, 1, 0);
    dGeomID hf = dCreateHeightfield(0, d, 1);
    dMatrix3 Rf;
    dRFromAxisAndAngle(Rf, 1, 0, 0, M_PI / 2);   // Y up to Z
    dGeomSetRotation(hf, Rf);
    dGeomID s = dCreateSphere(0, 0.5), b = dCreateBox(0, 0.8, 0.6, 0.4);
    dGeomID cap = dCreateCapsule(0, 0.3, 1.0);
    rng_state = 201;
    for (int i = 0; i < SCENES; i++) {
        double x = rnd(-7, 7), y = rnd(-7, 7), sink = rnd(0.01, 0.2);
        dGeomSetPosition(s, x, y, 0.5 - sink);
        print_deepest("heightfield_sphere", hf, s);
        print_deepest("sphere_heightfield", s, hf);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 0, 0, 1, rnd(0, 3));
        dGeomSetRotation(b, R);
        dGeomSetPosition(b, x, y, 0.2 - sink);
        print_deepest("heightfield_box", hf, b);
        print_deepest("box_heightfield", b, hf);
        dMatrix3 R1, R2;
        dRFromAxisAndAngle(R1, 1, 0, 0, M_PI / 2);
        dMultiply0_333(R2, R, R1);
        dGeomSetRotation(cap, R2);
        dGeomSetPosition(cap, x, y, 0.3 - sink);
        print_deepest("heightfield_capsule", hf, cap);
        print_deepest("capsule_heightfield", cap, hf);
    }
    dGeomDestroy(s);
    dGeomDestroy(b);
    dGeomDestroy(cap);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
}

// Heights 0.2 x - 0.1 z + 1 over 10 x 10 (11 x 11 samples): one plane.
static dReal slope(void *user, int x, int z)
{
    (void)user;
    return (dReal)(0.2 * (x - 5) - 0.1 * (z - 5) + 1);
}

static void sloped_field(void)
{
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildCallback(d, NULL, slope, 10, 10, 11, 11, 1, 0, 0, 0);
    dGeomHeightfieldDataSetBounds(d, -2, 4);
    dGeomID hf = dCreateHeightfield(0, d, 0);
    dGeomID s = dCreateSphere(0, 0.4);
    dGeomID ray = dCreateRay(0, 10);
    rng_state = 202;
    for (int i = 0; i < SCENES; i++) {
        double x = rnd(-3.5, 3.5), z = rnd(-3.5, 3.5), sink = rnd(0.01, 0.2);
        // The surface y = 0.2 x - 0.1 z + 1; unit normal n = (-0.2, 1, 0.1) / |.|.
        double l = sqrt(0.04 + 1 + 0.01);
        double n[3] = { -0.2 / l, 1 / l, 0.1 / l }, y = 0.2 * x - 0.1 * z + 1;
        double r = 0.4 - sink;
        dGeomSetPosition(s, x + r * n[0], y + r * n[1], z + r * n[2]);
        print_deepest("heightfield_sphere_slope", hf, s);
        print_deepest("sphere_heightfield_slope", s, hf);
        dGeomRaySet(ray, x, 5, z, 0, -1, 0);
        dContactGeom c[4];
        int k = dCollide(ray, hf, 1, c, sizeof c[0]);
        dReal v[8] = { (dReal)k, 0, 0, 0, 0, 0, 0, 0 };
        if (k > 0) {
            v[1] = c[0].depth;
            for (int j = 0; j < 3; j++) {
                v[2 + j] = c[0].pos[j];
                v[5 + j] = c[0].normal[j];
            }
        }
        diff_values("ray_heightfield_slope", 1e-9, v, 8);
    }
    dGeomDestroy(ray);
    dGeomDestroy(s);
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
}

int main(void)
{
    dInitODE();
    bounds();
    primitives_on_flat_field();
    sloped_field();
    dCloseODE();
    return 0;
}
