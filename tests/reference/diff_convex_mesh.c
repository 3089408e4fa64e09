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

#include <math.h>
#include <string.h>

enum { SCENES = 40 };

typedef struct hull {
    dReal planes[4 * 8], points[3 * 12];
    unsigned polygons[2 * 7 + 6 * 5];
    unsigned nplanes, npoints;
} hull;

static void make_box(hull *b, double lx, double ly, double lz)
{
    const double h[3] = { lx / 2, ly / 2, lz / 2 };
    static const unsigned faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 },
                                          { 2, 6, 7, 3 }, { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
    for (unsigned v = 0; v < 8; v++)
        for (int i = 0; i < 3; i++) b->points[3 * v + i] = (dReal)((v >> i & 1) ? h[i] : -h[i]);
    for (int f = 0; f < 6; f++) {
        for (int i = 0; i < 3; i++) b->planes[4 * f + i] = i == f / 2 ? (f & 1 ? 1 : -1) : 0;
        b->planes[4 * f + 3] = (dReal)h[f / 2];
        b->polygons[5 * f] = 4;
        for (int k = 0; k < 4; k++) b->polygons[5 * f + 1 + k] = faces[f][k];
    }
    b->nplanes = 6;
    b->npoints = 8;
}

// A hexagonal prism: corners at radius r about z, half height hh.
static void make_prism(hull *p, double r, double hh)
{
    for (int i = 0; i < 6; i++) {
        double a = M_PI / 3 * i, b = a + M_PI / 6;
        for (int top = 0; top < 2; top++) {
            dReal *q = p->points + 3 * (6 * top + i);
            q[0] = (dReal)(r * cos(a));
            q[1] = (dReal)(r * sin(a));
            q[2] = (dReal)(top ? hh : -hh);
        }
        dReal *pl = p->planes + 4 * (2 + i);
        pl[0] = (dReal)cos(b);
        pl[1] = (dReal)sin(b);
        pl[2] = 0;
        pl[3] = (dReal)(r * cos(M_PI / 6));
    }
    const dReal caps[8] = { 0, 0, 1, (dReal)hh, 0, 0, -1, (dReal)hh };
    memcpy(p->planes, caps, sizeof caps);
    unsigned *q = p->polygons;
    *q++ = 6;
    for (unsigned i = 0; i < 6; i++) *q++ = 6 + i;
    *q++ = 6;
    for (int i = 5; i >= 0; i--) *q++ = (unsigned)i;
    for (unsigned i = 0; i < 6; i++) {
        unsigned j = (i + 1) % 6;
        *q++ = 4;
        *q++ = i;
        *q++ = j;
        *q++ = 6 + j;
        *q++ = 6 + i;
    }
    p->nplanes = 8;
    p->npoints = 12;
}

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
static double lowest(dGeomID g, const hull *h)
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

static void hulls_on_flat_field(hull *shapes)
{
    static double flat[33 * 33];
    dHeightfieldDataID d = dGeomHeightfieldDataCreate();
    dGeomHeightfieldDataBuildDouble(d, flat, 0, 16, 16, 33, 33, 1, 0, 1, 0);
    dGeomID hf = dCreateHeightfield(0, d, 1);
    const dMatrix3 Rf = { 1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0 };   // Y up to Z
    dGeomSetRotation(hf, Rf);
    rng_state = 302;
    for (int s = 0; s < 2; s++) {
        hull *h = &shapes[s];
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
    static hull shapes[2];
    make_box(&shapes[0], 0.6, 0.4, 0.3);
    make_prism(&shapes[1], 0.3, 0.2);
    hulls_on_flat_field(shapes);
    dCloseODE();
    return 0;
}
