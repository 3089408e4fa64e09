// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_tree.c -- the triangle tree (white box): its shape (every
// triangle in one leaf, leaves in order, each box holding what is below
// it), the box queries against a scan of every leaf, and rays against the
// same rays cast at each triangle alone (a mesh of one triangle is a tree
// of one leaf: the hits a walk must find, with the same arithmetic).

#include "test.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../libodecollide/trimesh_internal.h"

#define RNG_SEED 0x2545f4914f6cdd1dull
#include "xorshift.h"

// A mesh kept with its arrays: a wavy or flat (integer) grid, or a soup of
// random triangles; its vertices in dReal, or (vf set) in float; shift: a
// point of its frame that the tests place near the world's origin (a mesh
// far from its frame's origin).
typedef struct mesh {
    dReal *v;
    float *vf;
    dTriIndex *idx;
    int nv, nt;
    double shift[3];
    dTriMeshDataID data;
} mesh;

// Data on m's vertices and the n triangles from idx.
static dTriMeshDataID data_of(const mesh *m, const dTriIndex *idx, int n)
{
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    if (m->vf) {
        dGeomTriMeshDataBuildSingle(data, m->vf, 3 * sizeof(float), m->nv, idx, 3 * n,
                                    3 * sizeof(dTriIndex));
        return data;
    }
#ifdef dDOUBLE
    dGeomTriMeshDataBuildDouble(data, m->v, 3 * sizeof(dReal), m->nv, idx, 3 * n,
                                3 * sizeof(dTriIndex));
#else
    dGeomTriMeshDataBuildSingle(data, m->v, 3 * sizeof(dReal), m->nv, idx, 3 * n,
                                3 * sizeof(dTriIndex));
#endif
    return data;
}

static void mesh_build(mesh *m)
{
    m->data = data_of(m, m->idx, m->nt);
}

// An n x n grid of cells, around (off, off / 2, off / 3) in its frame
// (shift), its vertices in float if single.
static void make_grid(mesh *m, int n, double cell, int wavy, double off, int single)
{
    m->nv = (n + 1) * (n + 1);
    m->nt = 2 * n * n;
    m->v = malloc(sizeof(dReal) * 3 * (size_t)m->nv);
    m->vf = single ? malloc(sizeof(float) * 3 * (size_t)m->nv) : NULL;
    m->idx = malloc(sizeof(dTriIndex) * 3 * (size_t)m->nt);
    m->shift[0] = off;
    m->shift[1] = off / 2;
    m->shift[2] = off / 3;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            dReal *p = m->v + 3 * (i + j * (n + 1));
            p[0] = (i - n / 2) * cell;
            p[1] = (j - n / 2) * cell;
            // waves of a size in cells (the same numbers as 0.5 sin(0.6 x)
            // cos(0.5 y) for cells of 0.5)
            p[2] = wavy ? 2 * cell * 0.5 * sin(0.6 * p[0] / cell * 0.5) *
                              cos(0.5 * p[1] / cell * 0.5)
                        : 0;
            for (int k = 0; k < 3; k++) p[k] += m->shift[k];
            for (int k = 0; k < 3 && single; k++) {
                m->vf[3 * (i + j * (n + 1)) + k] = (float)p[k];
                p[k] = m->vf[3 * (i + j * (n + 1)) + k];
            }
        }
    int t = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = i + j * (n + 1), b = a + 1, c = a + n + 1, d = c + 1;
            dTriIndex q[6] = { a, b, d, a, d, c };
            memcpy(m->idx + 3 * t, q, sizeof q);
            t += 2;
        }
    mesh_build(m);
}

static void make_soup(mesh *m, int nt, double size)
{
    m->nt = nt;
    m->nv = 3 * nt;
    m->vf = NULL;
    m->shift[0] = m->shift[1] = m->shift[2] = 0;
    m->v = malloc(sizeof(dReal) * 3 * (size_t)m->nv);
    m->idx = malloc(sizeof(dTriIndex) * 3 * (size_t)m->nt);
    for (int i = 0; i < nt; i++) {
        double c[3] = { rnd(-size, size), rnd(-size, size), rnd(-size, size) };
        for (int k = 0; k < 3; k++) {
            for (int a = 0; a < 3; a++) m->v[3 * (3 * i + k) + a] = c[a] + rnd(-0.7, 0.7);
            m->idx[3 * i + k] = (dTriIndex)(3 * i + k);
        }
    }
    mesh_build(m);
}

static void mesh_destroy(mesh *m)
{
    dGeomTriMeshDataDestroy(m->data);
    free(m->v);
    free(m->vf);
    free(m->idx);
}

// ---- shape ------------------------------------------------------------------------

// Every used slot's box holds what is below it (triangles or a node's
// slots), children come after their parent, unused slots last, and the
// leaves met depth first, slot by slot, cover order[] once, in order
// (counted into *leaves); the node's span is the leaf-order triangles met
// below it.
static int check_node(const dxTriMeshData *d, int i, int *next_first, int *leaves)
{
    const dxTriMeshNode *node = &d->nodes[i];
    const int span_first = *next_first;
    int used = 0;
    for (int s = 0; s < 4; s++) {
        if (node->count[s] < 0) continue;
        CHECK(s == used);
        used++;
        if (node->count[s] == 0) {
            int c = node->first[s];
            CHECK(c > i && c < d->node_count);
            const dxTriMeshNode *child = &d->nodes[c];
            for (int cs = 0; cs < 4 && child->count[cs] >= 0; cs++)
                for (int k = 0; k < 3; k++)
                    CHECK(node->lo[k][s] <= child->lo[k][cs] && child->hi[k][cs] <= node->hi[k][s]);
            if (check_node(d, c, next_first, leaves)) return 1;
            continue;
        }
        CHECK(node->count[s] <= 4 && node->first[s] == *next_first);
        ++*leaves;
        *next_first += node->count[s];
        for (int j = node->first[s]; j < node->first[s] + node->count[s]; j++) {
            dReal tv[3][3];
            dxTriMeshTriangle(d, d->order[j], tv);
            for (int p = 0; p < 3; p++)
                for (int k = 0; k < 3; k++) {
                    CHECK(node->lo[k][s] <= tv[p][k] && tv[p][k] <= node->hi[k][s]);
                    CHECK(d->leaf_vertices[9 * j + 3 * p + k] == tv[p][k]);
                }
            // the triangle's own float box: the nearest floats outside its
            // exact box, inside the leaf's
            for (int k = 0; k < 3; k++) {
                dReal lo = fmin(tv[0][k], fmin(tv[1][k], tv[2][k]));
                dReal hi = fmax(tv[0][k], fmax(tv[1][k], tv[2][k]));
                float flo = d->leaf_faces[j].box[k], fhi = d->leaf_faces[j].box[3 + k];
                CHECK(flo == dxFloatBelow(lo) && fhi == dxFloatAbove(hi));
                CHECK(flo <= lo && hi <= fhi);
                CHECK(node->lo[k][s] <= flo && fhi <= node->hi[k][s]);
            }
        }
    }
    CHECK(used > 0);
    CHECK(d->node_span[2 * i] == span_first && d->node_span[2 * i + 1] == *next_first - span_first);
    return 0;
}

static int check_shape(const dxTriMeshData *d)
{
    int next_first = 0, leaves = 0;
    // the nodes and the leaf-order vertices start at cache lines
    CHECK((uintptr_t)d->nodes % 64 == 0 && (uintptr_t)d->leaf_vertices % 64 == 0);
    // one block, in order, not overlapping: nodes, spans, vertices, faces
    CHECK((uintptr_t)d->node_span % 64 == 0 &&
          (const char *)d->node_span >= (const char *)(d->nodes + d->node_count));
    CHECK((const char *)d->leaf_vertices >= (const char *)(d->node_span + 2 * d->node_count));
    CHECK((uintptr_t)d->leaf_faces % 64 == 0 && sizeof *d->leaf_faces == 64 &&
          (const char *)d->leaf_faces >= (const char *)(d->leaf_vertices + 9 * d->tri_count));
    CHECK((const char *)(d->leaf_faces + d->tri_count) <=
          (const char *)d->tree_block.base + d->tree_block.size);
    if (check_node(d, 0, &next_first, &leaves)) return 1;
    CHECK(next_first == d->tri_count);
    // nodes mostly full: about a third as many as leaves
    CHECK(2 * d->node_count <= leaves + 2);
    int *seen = calloc((size_t)d->tri_count, sizeof(int));
    for (int j = 0; j < d->tri_count; j++) seen[d->order[j]]++;
    int once = 1;
    for (int t = 0; t < d->tri_count; t++) once &= seen[t] == 1;
    free(seen);
    CHECK(once);
    return 0;
}

// ---- box queries ------------------------------------------------------------------

// What a query must list: every leaf whose box overlaps [lo, hi] (compared
// in dReal), in leaf order, found by scanning every slot.
static int scan_leaves(const dxTriMeshData *d, const dReal lo[3], const dReal hi[3], int *out)
{
    int n = 0;
    for (int first = 0; first < d->tri_count;) {
        int found = 0;
        for (int i = 0; i < d->node_count && !found; i++)
            for (int s = 0; s < 4 && !found; s++) {
                const dxTriMeshNode *node = &d->nodes[i];
                if (node->count[s] <= 0 || node->first[s] != first) continue;
                found = 1;
                int meets = 1;
                for (int k = 0; k < 3; k++)
                    meets &= node->lo[k][s] <= hi[k] && node->hi[k][s] >= lo[k];
                for (int j = 0; meets && j < node->count[s]; j++) out[n++] = d->order[first + j];
                first += node->count[s];
            }
        if (!found) return -1;
    }
    return n;
}

static int check_queries(const dxTriMeshData *d, double size, const double centre[3])
{
    int *expect = malloc(sizeof(int) * (size_t)d->tri_count);
    int *got = NULL, cap = 0;
    for (int q = 0; q < 400; q++) {
        dReal lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            double c = centre[k] + rnd(-size, size), h = q % 4 == 0 ? 0 : rnd(0, size / 8);
            lo[k] = c - h;
            hi[k] = c + h;
        }
        if (q % 50 == 1) lo[0] = -dInfinity, hi[1] = dInfinity;
        if (q % 50 == 2) lo[2] = NAN;
        if (q % 50 == 3) {   // a side on a leaf box's float side, or just off it
            const dxTriMeshNode *node = &d->nodes[d->node_count - 1];
            hi[0] = node->lo[0][0];
            lo[1] = nextafter((double)node->hi[1][0], INFINITY);
        }
        int n = scan_leaves(d, lo, hi, expect);
        CHECK(n >= 0);
        int m = dxTriMeshQueryBox(d, lo, hi, &got, &cap);
        CHECK(m == n);
        CHECK(n == 0 || memcmp(expect, got, sizeof(int) * (size_t)n) == 0);
    }
    free(expect);
    free(got);
    return 0;
}

// ---- rays -------------------------------------------------------------------------

typedef struct hit {
    dReal depth;
    int tri;
} hit;

static int hit_order(const void *a, const void *b)
{
    const hit *x = a, *y = b;
    if (x->depth != y->depth) return x->depth < y->depth ? -1 : 1;
    return (x->tri > y->tri) - (x->tri < y->tri);
}

// Rays cast at the whole mesh and at each triangle alone (a mesh of one
// triangle on the same pose): the closest hit, and the nearest 8 of all,
// are the least of the lone triangles' hits by distance then triangle, to
// the bit; with BackfaceCull too. On the grid (not turned, so that
// directions along its axes stay exact in its frame) the rays go through
// vertices and edges, along the axes and nearly along the grid; on the
// other meshes a third of them are aimed at a triangle's vertex or a point
// of its edge (the hits a filter of the leaves' triangles must not drop).
static int check_rays(mesh *m, double size, int grid, int soup)
{
    dMatrix3 R;
    if (grid) dRSetIdentity(R);
    else dRFromEulerAngles(R, 0.3, -0.2, 0.1);
    // the mesh's shift point at (0.25, -0.5, 0.125)
    double at[3] = { 0.25, -0.5, 0.125 };
    for (int i = 0; i < 3; i++)
        at[i] -= R[4 * i] * m->shift[0] + R[4 * i + 1] * m->shift[1] + R[4 * i + 2] * m->shift[2];
    dGeomID whole = dCreateTriMesh(0, m->data, NULL, NULL, NULL);
    dGeomSetRotation(whole, R);
    dGeomSetPosition(whole, at[0], at[1], at[2]);
    dTriMeshDataID *one = malloc(sizeof *one * (size_t)m->nt);
    dGeomID *lone = malloc(sizeof *lone * (size_t)m->nt);
    for (int t = 0; t < m->nt; t++) {
        one[t] = data_of(m, m->idx + 3 * t, 1);
        lone[t] = dCreateTriMesh(0, one[t], NULL, NULL, NULL);
        dGeomSetRotation(lone[t], R);
        dGeomSetPosition(lone[t], at[0], at[1], at[2]);
    }
    dGeomID ray = dCreateRay(0, 1);
    hit *all = malloc(sizeof *all * (size_t)m->nt);
    int failed = 0, hits = 0;
    for (int r = 0; r < 300 && !failed; r++) {
        // from a point in the mesh's box (grown) towards another in it
        double p[3], dir[3], len2 = 0;
        for (int k = 0; k < 3; k++) {
            p[k] = rnd(-1.2, 1.2) * (k == 2 && !soup ? 2 : size);
            dir[k] = rnd(-1, 1) * (k == 2 && !soup ? 0.5 : size) - p[k];
            len2 += dir[k] * dir[k];
        }
        double len = sqrt(len2) * rnd(0.3, 2);
        if (!grid && r % 3 == 2) {   // at a vertex (every other one) or an edge
            const dTriIndex *tri = m->idx + 3 * (int)rnd(0, m->nt);
            const dReal *a = m->v + 3 * tri[0], *b = m->v + 3 * tri[1];
            double w = r % 6 == 2 ? 0 : rnd(0, 1), q[3], aim[3];
            for (int k = 0; k < 3; k++) q[k] = a[k] + w * (b[k] - a[k]);
            len2 = 0;
            for (int i = 0; i < 3; i++) {
                aim[i] = at[i] + R[4 * i] * q[0] + R[4 * i + 1] * q[1] + R[4 * i + 2] * q[2];
                dir[i] = aim[i] - p[i];
                len2 += dir[i] * dir[i];
            }
            len = sqrt(len2) * rnd(1.01, 2);
        }
        if (grid) {
            static const double offset[3] = { 0, 0.25, 0.5 };
            p[0] = floor(p[0]) + offset[r % 3] - 0.25;
            p[1] = floor(p[1]) + offset[r / 3 % 3] + 0.5;
            p[2] = r % 7 == 0 ? 1e-3 : fabs(p[2]) + 0.5;
            dir[0] = r % 5 < 2 ? 0 : rnd(-0.5, 0.5);
            dir[1] = r % 5 == 0 || r % 5 == 2 ? 0 : rnd(-0.5, 0.5);
            dir[2] = r % 7 == 0 ? -1e-35 : -1;
        }
        dGeomRaySet(ray, p[0], p[1], p[2], dir[0], dir[1], dir[2]);
        dGeomRaySetLength(ray, grid ? 4 : len);
        int cull = r % 4 == 1;
        dGeomRaySetBackfaceCull(ray, cull);
        int n = 0;
        for (int t = 0; t < m->nt; t++) {
            dContactGeom c;
            if (dCollide(lone[t], ray, 1, &c, sizeof c)) all[n++] = (hit){ c.depth, t };
        }
        qsort(all, (size_t)n, sizeof *all, hit_order);
        hits += n > 0;
        dContactGeom c[8];
        dGeomRaySetClosestHit(ray, 1);
        int got = dCollide(whole, ray, 8, c, sizeof c[0]);
        failed |= got != (n > 0);
        failed |= n > 0 && (c[0].depth != all[0].depth || c[0].side1 != all[0].tri);
        dGeomRaySetClosestHit(ray, 0);
        got = dCollide(whole, ray, 8, c, sizeof c[0]);
        failed |= got != (n < 8 ? n : 8);
        for (int i = 0; i < got; i++)
            failed |= c[i].depth != all[i].depth || c[i].side1 != all[i].tri;
    }
    free(all);
    dGeomDestroy(ray);
    for (int t = 0; t < m->nt; t++) {
        dGeomDestroy(lone[t]);
        dGeomTriMeshDataDestroy(one[t]);
    }
    free(one);
    free(lone);
    dGeomDestroy(whole);
    CHECK(!failed);
    CHECK(m->nt < 100 || hits >= 100);   // the rays meet the mesh
    return 0;
}

static int check_mesh(mesh *m, double size, int grid, int soup)
{
    const dxTriMeshData *d = (const dxTriMeshData *)m->data;
    int bad = check_shape(d) || check_queries(d, size, m->shift) || check_rays(m, size, grid, soup);
    mesh_destroy(m);
    return bad;
}

static int test_tree_wavy_grid(void)
{
    mesh m;
    make_grid(&m, 24, 0.5, 1, 0, 0);
    return check_mesh(&m, 7, 0, 0);
}

// Far from its frame's origin (3000 m, cells of 5 cm: the vertices' floats
// are 2.4e-4 m apart), and with float vertex arrays.
static int test_tree_far_grid(void)
{
    mesh m;
    make_grid(&m, 24, 0.05, 1, 3000.3, 0);
    return check_mesh(&m, 0.7, 0, 0);
}

static int test_tree_float_vertices(void)
{
    mesh m;
    make_grid(&m, 20, 0.5, 1, 0.3, 1);
    return check_mesh(&m, 6, 0, 0);
}

static int test_tree_flat_integer_grid(void)
{
    mesh m;
    make_grid(&m, 20, 1, 0, 0, 0);
    return check_mesh(&m, 11, 1, 0);
}

static int test_tree_soup(void)
{
    mesh m;
    make_soup(&m, 700, 5);
    return check_mesh(&m, 6, 0, 1);
}

// 1 to 9 triangles: a root that is a leaf, roots of two to four slots.
static int test_tree_small(void)
{
    for (int nt = 1; nt <= 9; nt++) {
        mesh m;
        make_soup(&m, nt, 2);
        const dxTriMeshData *d = (const dxTriMeshData *)m.data;
        CHECK(d->node_count >= 1);
        if (check_mesh(&m, 3, 0, 1)) return 1;
    }
    return 0;
}

// The inline steps that round the tree's and the queries' boxes outwards
// give nextafterf's answers: zeros of both signs, subnormals, the largest
// float and infinity, and random numbers over the whole range.
static int test_float_steps_match_nextafterf(void)
{
    const float special[] = { 0.0f, -0.0f, FLT_TRUE_MIN, -FLT_TRUE_MIN, FLT_MIN, -FLT_MIN,
                              FLT_MAX, -FLT_MAX, INFINITY, -INFINITY, 1.0f, -1.0f };
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) {
        float f = special[i];
        if (f != INFINITY)   // (no step beyond infinity is ever asked for)
            CHECK(memcmp(&(float){ dxFloatStep(f, 1) }, &(float){ nextafterf(f, INFINITY) },
                         sizeof f) == 0);
        if (f != -INFINITY)
            CHECK(memcmp(&(float){ dxFloatStep(f, 0) }, &(float){ nextafterf(f, -INFINITY) },
                         sizeof f) == 0);
    }
    for (int i = 0; i < 100000; i++) {
        // x = m 2^e over every exponent a float has, and beyond.
        dReal x = (dReal)ldexp(rnd(-1, 1), (int)rnd(-160, 140));
        float below = dxFloatBelow(x), above = dxFloatAbove(x), f = (float)x;
        float want_below = f > x ? nextafterf(f, -INFINITY) : f;
        float want_above = f < x ? nextafterf(f, INFINITY) : f;
        CHECK(below == want_below && above == want_above);
        CHECK(below <= x && above >= x);
    }
    return 0;
}

// A box's floats three at a time (dxFloatBox, SSE2 in double) are
// dxFloatAbove's and dxFloatBelow's one by one, to the bit: special values
// (zeros, the float range's ends, infinities, a NaN, numbers a float
// cannot hold next to ones it can) in every lane and random ones over
// every exponent.
static int test_float_box_matches_steps(void)
{
    const dReal special[] = { 0.0, -0.0, 1.0, -1.0, (dReal)FLT_TRUE_MIN / 3, -(dReal)FLT_TRUE_MIN / 3,
                              FLT_MAX, -(dReal)FLT_MAX, (dReal)FLT_MAX * 2, -(dReal)FLT_MAX * 2,
                              INFINITY, -INFINITY, NAN, (dReal)0.1, -(dReal)0.1, (dReal)1e-40 };
    const int ns = (int)(sizeof special / sizeof special[0]);
    for (int i = 0; i < 20000 + ns * ns * ns; i++) {
        dReal lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            if (i >= 20000) {
                // Lane k takes special number (i - 20000) / ns^k mod ns.
                int j = i - 20000;
                for (int s = 0; s < k; s++) j /= ns;
                lo[k] = special[j % ns];
                hi[k] = special[(j + 1) % ns];
            } else {
                lo[k] = (dReal)ldexp(rnd(-1, 1), (int)rnd(-160, 140));
                hi[k] = (dReal)ldexp(rnd(-1, 1), (int)rnd(-160, 140));
            }
        }
        float lo_f[4], hi_f[4];
        dxFloatBox(lo, hi, lo_f, hi_f);
        for (int k = 0; k < 3; k++) {
            float above = dxFloatAbove(lo[k]), below = dxFloatBelow(hi[k]);
            CHECK(memcmp(&lo_f[k], &above, sizeof above) == 0);
            CHECK(memcmp(&hi_f[k], &below, sizeof below) == 0);
        }
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_float_steps_match_nextafterf),
    TEST_CASE(test_float_box_matches_steps),
    TEST_CASE(test_tree_wavy_grid),
    TEST_CASE(test_tree_flat_integer_grid),
    TEST_CASE(test_tree_far_grid),
    TEST_CASE(test_tree_float_vertices),
    TEST_CASE(test_tree_soup),
    TEST_CASE(test_tree_small),
    TEST_END,
};
