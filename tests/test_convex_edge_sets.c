// SPDX-License-Identifier: BSD-3-Clause
//
// test_convex_edge_sets.c -- the hulls' edges by face as bytes (dx_hull's
// edge_faces), which the separating axis test's AVX2 path looks up to turn
// sets of faces into sets of edges, and with which it screens the edge
// pairs four at a time. White-box: each hull's bytes say what its by_f1
// and by_f2 sets say, and a hull pair collided with the bytes gives the
// same contacts, bit for bit, as with the bytes taken away (the plain
// loop over the faces, each pair screened alone), over many random poses,
// both orders.

#include "test.h"
#include "collide_convex.h"
#include "convex_hulls.h"

#include <stdint.h>
#include <string.h>

enum { MAXC = 4, POSES = 3000 };

#define RNG_SEED 88172645463325252ULL
#include "xorshift.h"

// Whether h's bytes name, for each face, the edges of its by_f1 and by_f2
// and nothing past its edges.
static int bytes_as_sets(const dx_hull *h)
{
    if (!h->edge_faces) return 0;
    for (unsigned k = h->nedges; k < 32; k++)
        if (h->edge_faces[0][k] != 0x80 || h->edge_faces[1][k] != 0x80) return 0;
    for (unsigned f = 0; f < h->nplanes; f++) {
        uint64_t first = 0, second = 0;
        for (unsigned k = 0; k < h->nedges; k++) {
            first |= (uint64_t)(h->edge_faces[0][k] == f) << k;
            second |= (uint64_t)(h->edge_faces[1][k] == f) << k;
        }
        if (first != h->by_f1[f] || second != h->by_f2[f]) return 0;
    }
    return 1;
}

static void random_pose(dGeomID g, double spread)
{
    dMatrix3 R;
    dRFromAxisAndAngle(R, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) + 1e-3, rnd(0, 6.3));
    dGeomSetPosition(g, rnd(-spread, spread), rnd(-spread, spread), rnd(-spread, spread));
    dGeomSetRotation(g, R);
}

// a against b through dx_hull_hull, into c (the count returned), with the
// bytes of both hulls (plain 0) or without them (plain 1).
static int collide(dGeomID a, dGeomID b, int plain, dContactGeom *c)
{
    dx_hull ha = *dx_hull_posed(a);
    dx_hull hb = *dx_hull_posed(b);
    if (plain) ha.edge_faces = hb.edge_faces = NULL;
    memset(c, 0, MAXC * sizeof *c);
    return dx_hull_hull(&ha, &hb, a, b, MAXC, c, sizeof *c);
}

static int test_bytes_name_the_edge_sets(void)
{
    test_hull prism, cube;
    test_hull_prism(&prism, 0.15, 0.1);
    test_hull_box(&cube, 0.3, 0.2, 0.25);
    dGeomID p = dCreateConvex(0, prism.planes, prism.nplanes, prism.points, prism.npoints,
                              prism.polygons);
    dGeomID c = dCreateConvex(0, cube.planes, cube.nplanes, cube.points, cube.npoints,
                              cube.polygons);
    dGeomID box = dCreateBox(0, 0.3, 0.2, 0.25);
    CHECK(bytes_as_sets(dx_hull_posed(p)));
    CHECK(bytes_as_sets(dx_hull_posed(c)));
    CHECK(bytes_as_sets(dx_hull_posed(box)));
    dGeomDestroy(p);
    dGeomDestroy(c);
    dGeomDestroy(box);
    return 0;
}

// Prisms, a cube hull and a box, pairs in both orders at random poses
// close enough that most touch (by faces and by edges) or nearly do.
static int test_edge_sets_as_plain_loop(void)
{
    test_hull prism, cube;
    test_hull_prism(&prism, 0.15, 0.1);
    test_hull_box(&cube, 0.3, 0.2, 0.25);
    dGeomID g[4];
    g[0] = dCreateConvex(0, prism.planes, prism.nplanes, prism.points, prism.npoints,
                         prism.polygons);
    g[1] = dCreateConvex(0, prism.planes, prism.nplanes, prism.points, prism.npoints,
                         prism.polygons);
    g[2] = dCreateConvex(0, cube.planes, cube.nplanes, cube.points, cube.npoints, cube.polygons);
    g[3] = dCreateBox(0, 0.3, 0.2, 0.25);
    int touching = 0, edges = 0;
    for (int k = 0; k < POSES; k++) {
        for (int i = 0; i < 4; i++) random_pose(g[i], 0.12);
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                if (i == j || (i == 3 && j == 3)) continue;
                if (dGeomGetClass(g[i]) == dBoxClass && dGeomGetClass(g[j]) == dBoxClass) continue;
                dContactGeom fast[MAXC], plain[MAXC];
                int n = collide(g[i], g[j], 0, fast), m = collide(g[i], g[j], 1, plain);
                CHECK(n == m);
                CHECK(memcmp(fast, plain, sizeof fast) == 0);
                touching += n > 0;
                edges += n == 1;
            }
        }
    }
    CHECK(touching > POSES);   // most pairs touch
    CHECK(edges > 0);
    for (int i = 0; i < 4; i++) dGeomDestroy(g[i]);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_bytes_name_the_edge_sets),
    TEST_CASE(test_edge_sets_as_plain_loop),
    TEST_END,
};
