// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_clip.c -- the clip of a polygon to a triangle's prism
// (dxTriClipToPrism, whose clips are the box and face colliders' own)
// against the test's own clip, one side after the other, written out as
// the plain loop it is: a point is kept where its measure m . (x - v_k) +
// slack is at least 0, a point is made where an edge's ends are on
// different sides (a + s (b - a), s = fa / (fa - fb)), after the edge's
// first end. The corners, their count and their tags must be the same to
// the bit, for random convex polygons around random triangles, polygons
// wholly inside and wholly outside, points on the sides, and zigzags that
// cross a side more often than a convex polygon can (too many corners: 0).

#include "test.h"
#include "collide_trimesh.h"

#include <math.h>
#include <string.h>

#include "xorshift.h"

// The test's clip of a (n points, tags in made) to t's prism, with the
// library's side normals and slack; returns the new count (0 if more than
// DX_TRI_POLY_MAX).
static int reference_clip(const dxTri *t, dReal eps, dReal a[][3], int n, int *made)
{
    for (int k = 0; k < 3 && n > 0; k++) {
        dReal m[3];
        dxTriSideNormal(t, k, m);
        const dReal slack = eps * dSqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        dReal f[2 * DX_TRI_POLY_MAX];
        int all_in = 1;
        for (int i = 0; i < n; i++) {
            const dReal d[3] = { a[i][0] - t->v[k][0], a[i][1] - t->v[k][1],
                                 a[i][2] - t->v[k][2] };
            f[i] = m[0] * d[0] + m[1] * d[1] + m[2] * d[2] + slack;
            all_in &= f[i] >= 0;
        }
        if (all_in) continue;
        dReal out[2 * DX_TRI_POLY_MAX][3];
        int tags[2 * DX_TRI_POLY_MAX], count = 0;
        for (int i = 0; i < n; i++) {
            const int next = i + 1 < n ? i + 1 : 0;
            if (f[i] >= 0) {
                memcpy(out[count], a[i], sizeof out[count]);
                tags[count++] = made[i];
            }
            if ((f[i] >= 0) != (f[next] >= 0)) {
                const dReal s = f[i] / (f[i] - f[next]);
                for (int j = 0; j < 3; j++) out[count][j] = a[i][j] + s * (a[next][j] - a[i][j]);
                tags[count++] = DX_TRI_MADE_AT_EDGE;
            }
        }
        if (count > DX_TRI_POLY_MAX) return 0;
        n = count;
        memcpy(a, out, (size_t)n * sizeof out[0]);
        memcpy(made, tags, (size_t)n * sizeof tags[0]);
    }
    return n;
}

// A random triangle (normal up within 60 degrees) of size about `size`
// near the origin, into v and n.
static void random_triangle(dReal v[3][3], dReal n[3], double size)
{
    for (;;) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) v[i][j] = (dReal)rnd(-size, size) * (j == 2 ? 0.3 : 1);
        const dReal e1[3] = { v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2] };
        const dReal e2[3] = { v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2] };
        dReal c[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0] };
        const dReal len = dSqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (len < size * size * 0.05) continue;   // too thin
        if (c[2] < 0) {   // counter-clockwise seen from above
            for (int j = 0; j < 3; j++) {
                const dReal x = v[1][j];
                v[1][j] = v[2][j];
                v[2][j] = x;
                c[j] = -c[j];
            }
        }
        for (int j = 0; j < 3; j++) n[j] = c[j] / len;
        if (n[2] > 0.5) return;
    }
}

// Clip a with the library and the reference and compare; 0 if the same.
static int compare_clips(const dxTri *t, dReal scale, dReal a[][3], int n)
{
    dxTriQuery q;
    memset(&q, 0, sizeof q);
    q.scale = scale;   // (no data: no flat edges)
    dReal lib[2 * DX_TRI_POLY_MAX][3], ref[2 * DX_TRI_POLY_MAX][3];
    int lib_made[2 * DX_TRI_POLY_MAX], ref_made[2 * DX_TRI_POLY_MAX];
    memcpy(lib, a, (size_t)n * sizeof lib[0]);
    memcpy(ref, a, (size_t)n * sizeof ref[0]);
    for (int i = 0; i < n; i++) ref_made[i] = DX_TRI_MADE_NOT;
    const int nl = dxTriClipToPrism(&q, t, lib, n, lib_made);
    const int nr = reference_clip(t, DX_COLLIDE_EPS * scale, ref, n, ref_made);
    CHECK(nl == nr);
    for (int i = 0; i < nl; i++) {
        CHECK(memcmp(lib[i], ref[i], sizeof lib[i]) == 0);
        CHECK(lib_made[i] == ref_made[i]);
    }
    return 0;
}

// Random convex polygons (a circle's points at sorted random angles, in a
// tilted plane) of every size around random triangles.
static int test_clip_convex(void)
{
    rng_state = 0x5eed1234abcdULL;
    for (int trial = 0; trial < 20000; trial++) {
        dReal v[3][3], n[3];
        random_triangle(v, n, 1.0);
        const dxTri t = { .index = 0, .v = (const dReal(*)[3])v, .n = n, .h = 0, .face = NULL };
        const int count = 3 + trial % 20;
        double angle[32];
        for (int i = 0; i < count; i++) angle[i] = rnd(0, 6.283185307179586);
        for (int i = 1; i < count; i++)   // sorted: a convex polygon
            for (int j = i; j > 0 && angle[j] < angle[j - 1]; j--) {
                const double x = angle[j];
                angle[j] = angle[j - 1];
                angle[j - 1] = x;
            }
        const double r = rnd(0.05, 2.0), cx = rnd(-1, 1), cy = rnd(-1, 1), cz = rnd(-0.3, 0.3);
        const double tx = rnd(-0.5, 0.5), ty = rnd(-0.5, 0.5);
        dReal a[DX_TRI_POLY_MAX][3];
        for (int i = 0; i < count; i++) {
            const double x = r * cos(angle[i]), y = r * sin(angle[i]);
            a[i][0] = (dReal)(cx + x);
            a[i][1] = (dReal)(cy + y);
            a[i][2] = (dReal)(cz + tx * x + ty * y);
        }
        if (compare_clips(&t, (dReal)rnd(0.01, 10), a, count)) return 1;
    }
    return 0;
}

// Polygons wholly inside (unchanged), wholly outside (nothing), with
// corners on the triangle's vertices and edges (measure 0 less slack),
// and zigzags that cross the sides many times (more corners than
// DX_TRI_POLY_MAX: 0).
static int test_clip_special(void)
{
    rng_state = 0x0badc0ffee42ULL;
    for (int trial = 0; trial < 5000; trial++) {
        dReal v[3][3], n[3];
        random_triangle(v, n, 1.0);
        const dxTri t = { .index = 0, .v = (const dReal(*)[3])v, .n = n, .h = 0, .face = NULL };
        const dReal g[3] = { (v[0][0] + v[1][0] + v[2][0]) / 3, (v[0][1] + v[1][1] + v[2][1]) / 3,
                             (v[0][2] + v[1][2] + v[2][2]) / 3 };
        dReal a[DX_TRI_POLY_MAX][3];
        // Inside: the triangle shrunk towards its centroid; on it: the
        // vertices and edge midpoints themselves.
        const dReal shrink = trial % 2 ? (dReal)0.5 : 1;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                a[2 * i][j] = g[j] + shrink * (v[i][j] - g[j]);
                a[2 * i + 1][j] = g[j] + shrink * ((v[i][j] + v[(i + 1) % 3][j]) / 2 - g[j]);
            }
        if (compare_clips(&t, 1, a, 6)) return 1;
        // Outside: a square far off.
        for (int i = 0; i < 4; i++) {
            a[i][0] = (dReal)(5 + (i == 1 || i == 2));
            a[i][1] = (dReal)(5 + (i >= 2));
            a[i][2] = 0;
        }
        if (compare_clips(&t, 1, a, 4)) return 1;
        // A zigzag of up to DX_TRI_POLY_MAX - 3 points through the triangle.
        const int count = 4 + trial % (DX_TRI_POLY_MAX - 6);
        for (int i = 0; i < count; i++) {
            const dReal s = (dReal)i / (dReal)count, w = i % 2 ? (dReal)1.5 : (dReal)-1.5;
            for (int j = 0; j < 3; j++)
                a[i][j] = g[j] + (v[0][j] - g[j]) * 2 * (s - (dReal)0.5) +
                          (v[1][j] - v[2][j]) * w * (j < 2);
        }
        if (compare_clips(&t, (dReal)rnd(0.01, 10), a, count)) return 1;
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_clip_convex),
    TEST_CASE(test_clip_special),
    TEST_END,
};
