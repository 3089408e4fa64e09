// SPDX-License-Identifier: BSD-3-Clause
//
// convex_hulls.h -- convex hulls as ODE's dCreateConvex arrays, for the convex
// tests and their differential twins (which build against the reference ODE
// too, so: the ODE API only, everything static inline).

#ifndef TEST_CONVEX_HULLS_H
#define TEST_CONVEX_HULLS_H

#include <ode/ode.h>
#include <math.h>
#include <string.h>

// Room for the largest hull here, the hexagonal prism: 8 planes, 12 points,
// 2 hexagons and 6 quads.
typedef struct test_hull {
    dReal planes[4 * 8], points[3 * 12];
    unsigned polygons[2 * 7 + 6 * 5];
    unsigned nplanes, npoints;
} test_hull;

// A box of sides lx, ly, lz about the origin: corner v at (+-, +-, +-) by the
// bits (x, y, z) of v, faces -x +x -y +y -z +z whose corners faces[f] lists.
static inline void test_hull_box_faces(test_hull *b, double lx, double ly, double lz,
                                       const unsigned faces[6][4])
{
    const double h[3] = { lx / 2, ly / 2, lz / 2 };
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

// The same box, each face wound counterclockwise seen from outside.
static inline void test_hull_box(test_hull *b, double lx, double ly, double lz)
{
    static const unsigned ccw[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 },
                                        { 2, 6, 7, 3 }, { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
    test_hull_box_faces(b, lx, ly, lz, ccw);
}

// A hexagonal prism about z: corners at radius r, half height hh.
static inline void test_hull_prism(test_hull *p, double r, double hh)
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

#endif
