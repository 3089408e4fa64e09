// SPDX-License-Identifier: BSD-3-Clause
//
// diff_convex_mesh.c -- convex hulls (dCreateConvex) against a heightfield,
// against the reference ODE 0.16: a convex box and a hexagonal prism turned
// at random and sunk into a flat heightfield (the lowest vertex is the
// deepest point), both argument orders: the deepest contact's depth and
// normal and the contact count (the reference's heightfield collider and
// ours give the same points there), tolerance 1e-9.
//
// Convex against a triangle mesh is not compared: the reference does not
// answer it usefully. Its collider (libccd per triangle, with the face
// angles preprocessed) finds no contact for a hull lying 1 cm deep in a
// flat 16 x 16-cell grid anywhere but near the mesh's origin (150 of 160
// random places over [-3, 3]^2), and near the origin tilts the deepest
// normal away from the face's (43 of 80 scenes, by up to 79 degrees).
// tests/test_convex_mesh.c checks that pair against the box's contacts and
// signed distances instead.

#include "diff_print.h"
#include "diff_random.h"
#include "../convex_hulls.h"

#include <math.h>
#include <string.h>

enum { SCENES = 40 };

// The deepest contact's depth and normal, and the count.
static void print_deepest(const char *name, dGeomID a, dGeomID b)
{
    dContactGeom c[32];
    int n = dCollide(a, b, 32, c, sizeof c[0]);
    int k = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[k].depth) k = i;
    dReal v[5] = { 0, 0, 0, 0, (dReal)n };
    if (n > 0) {
        v[0] = c[k].depth;
        for (int i = 0; i < 3; i++) v[1 + i] = c[k].normal[i];
    }
    diff_values(name, 1e-9, v, 5);
}

// The lowest z of g's points (shape h) in the world.
static double lowest(dGeomID g, const test_hull *h)
{
    double low = INFINITY;
    for (unsigned v = 0; v < h->npoints; v++) {
        dVector3 w;
        const dReal *p = h->points + 3 * v;
        dGeomGetRelPointPos(g, p[0], p[1], p[2], w);
        if (w[2] < low) low = w[2];
    }
    return low;
}

static void hulls_on_flat_field(test_hull *shapes)
{
    static double flat[33 * 33];
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, flat, 0, 16, 16, 33, 33, 1, 0, 1, 0);
    dGeomID hf = dCreateHeightfield(0, d, 1);
    const dMatrix3 Rf = { 1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0 };   // Y up to Z
    dGeomSetRotation(hf, Rf);
    rng_state = 302;
    for (int s = 0; s < 2; s++) {
        test_hull *h = &shapes[s];
        dGeomID g = dCreateConvex(0, h->planes, h->nplanes, h->points, h->npoints, h->polygons);
        for (int i = 0; i < SCENES; i++) {
            dMatrix3 R;
            random_rotation(R);
            dGeomSetRotation(g, R);
            dGeomSetPosition(g, rnd(-6, 6), rnd(-6, 6), 0);
            double sink = rnd(0.005, 0.05), x = dGeomGetPosition(g)[0];
            dGeomSetPosition(g, x, dGeomGetPosition(g)[1], -lowest(g, h) - sink);
            print_deepest(s ? "prism_heightfield" : "convex_box_heightfield", g, hf);
            print_deepest(s ? "heightfield_prism" : "heightfield_convex_box", hf, g);
        }
        dGeomDestroy(g);
    }
    dGeomDestroy(hf);
    dGeomHeightfieldDataDestroy(d);
}

int main(void)
{
    dInitODE();
    static test_hull shapes[2];
    test_hull_box(&shapes[0], 0.6, 0.4, 0.3);
    test_hull_prism(&shapes[1], 0.3, 0.2);
    hulls_on_flat_field(shapes);
    dCloseODE();
    return 0;
}
