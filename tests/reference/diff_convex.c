// SPDX-License-Identifier: BSD-3-Clause
//
// diff_convex.c -- the convex hull (dCreateConvex) against the reference ODE
// 0.16: a convex cube of random sides with a sphere, a plane and a box, in
// seeded random poses (BACKENDS.md section 7): whether the pair touches,
// the deepest depth and its normal. The same
// scenes with a real box (box-sphere, box-plane, box-box) print the answers
// the convex should reproduce, so the two builds also show how the
// reference's convex departs from its own box.
//
// Measured over the 120 scenes: the box lines agree with the reference
// within 1e-9 (they are the same closed forms), and ours prints the same
// values for the convex as for the box in every scene (test_convex.c checks
// that on many more poses). The reference's convex departs from its own
// box by more than 1e-9: convex-sphere in 35 scenes (e.g. depth 0.399
// with another normal where the box gives 0.375), convex-plane in 10 (no
// contact where the box is 1.6 deep), convex-box in 36 (e.g. 1.130 where
// box-box gives 0.943, another normal). So the convex lines have tolerances that show
// these differences without failing on them (touch 1, depth and normal 4);
// the box lines keep 1e-9.

#include "diff_print.h"
#include "diff_random.h"
#include "../convex_hulls.h"

#include <math.h>
#include <stdio.h>

enum { SCENES = 120, MAXC = 16 };

// Prints the pair's touching flag, deepest depth and its normal.
static void print_pair(const char *tag, int s, dGeomID a, dGeomID b, double tol_touch,
                       double tol_depth, double tol_normal)
{
    dContactGeom c[MAXC];
    int n = dCollide(a, b, MAXC, c, sizeof c[0]), k = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[k].depth) k = i;
    char name[64];
    snprintf(name, sizeof name, "%s_touch_%d", tag, s);
    diff_value(name, tol_touch, n > 0);
    snprintf(name, sizeof name, "%s_depth_%d", tag, s);
    diff_value(name, tol_depth, n ? c[k].depth : 0);
    snprintf(name, sizeof name, "%s_normal_%d", tag, s);
    dReal zero[3] = { 0, 0, 0 };
    diff_values(name, tol_normal, n ? c[k].normal : zero, 3);
}

int main(void)
{
    dInitODE();
    rng_state = 5;
    for (int s = 0; s < SCENES; s++) {
        dReal side[3] = { rnd(0.3, 2), rnd(0.3, 2), rnd(0.3, 2) };
        test_hull bh;
        test_hull_box(&bh, side[0], side[1], side[2]);
        dGeomID hull = dCreateConvex(0, bh.planes, 6, bh.points, 8, bh.polygons);
        dGeomID box = dCreateBox(0, side[0], side[1], side[2]);
        dMatrix3 R;
        random_rotation(R);
        dReal p[3] = { rnd(-0.5, 0.5), rnd(-0.5, 0.5), rnd(-0.5, 0.5) };
        dGeomSetPosition(hull, p[0], p[1], p[2]);
        dGeomSetRotation(hull, R);
        dGeomSetPosition(box, p[0], p[1], p[2]);
        dGeomSetRotation(box, R);

        dGeomID sphere = dCreateSphere(0, rnd(0.1, 0.8));
        dGeomSetPosition(sphere, rnd(-1.5, 1.5), rnd(-1.5, 1.5), rnd(-1.5, 1.5));
        print_pair("convex_sphere", s, hull, sphere, 1, 4, 4);
        print_pair("box_sphere", s, box, sphere, 0, 1e-9, 1e-9);

        dReal a = rnd(-1, 1), b = rnd(-1, 1), c = rnd(-1, 1), l = sqrt(a * a + b * b + c * c);
        dGeomID plane = dCreatePlane(0, a / l, b / l, c / l, rnd(-0.8, 0.8));
        print_pair("convex_plane", s, hull, plane, 1, 4, 4);
        print_pair("box_plane", s, box, plane, 0, 1e-9, 1e-9);

        dReal o[3] = { rnd(0.3, 2), rnd(0.3, 2), rnd(0.3, 2) };
        dGeomID other = dCreateBox(0, o[0], o[1], o[2]);
        random_geom_rotation(other);
        dGeomSetPosition(other, rnd(-1.2, 1.2), rnd(-1.2, 1.2), rnd(-1.2, 1.2));
        print_pair("convex_box", s, hull, other, 1, 4, 4);
        print_pair("box_box", s, box, other, 0, 1e-9, 1e-9);

        dGeomDestroy(hull);
        dGeomDestroy(box);
        dGeomDestroy(sphere);
        dGeomDestroy(plane);
        dGeomDestroy(other);
    }
    dCloseODE();
    return 0;
}
