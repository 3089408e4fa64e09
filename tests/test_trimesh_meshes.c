// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_meshes.c -- see test_trimesh_meshes.h.

#include "test_trimesh_meshes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void mesh_alloc(test_mesh *m, int nv, int nt)
{
    m->v = calloc((size_t)nv, sizeof *m->v);
    m->tri = calloc((size_t)nt, sizeof *m->tri);
    m->nv = 0;
    m->nt = 0;
}

static int add_vertex(test_mesh *m, double x, double y, double z)
{
    m->v[m->nv][0] = x;
    m->v[m->nv][1] = y;
    m->v[m->nv][2] = z;
    return m->nv++;
}

static void add_tri(test_mesh *m, int a, int b, int c)
{
    m->tri[m->nt][0] = (dTriIndex)a;
    m->tri[m->nt][1] = (dTriIndex)b;
    m->tri[m->nt][2] = (dTriIndex)c;
    m->nt++;
}

static void build(test_mesh *m)
{
    m->data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(m->data, m->v, 3 * sizeof(double), m->nv, m->tri, 3 * m->nt,
                                3 * sizeof(dTriIndex));
}

void mesh_grid(test_mesh *m, int n, double half, double (*height)(double x, double y))
{
    mesh_alloc(m, (n + 1) * (n + 1), 2 * n * n);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = -half + 2 * half * i / n, y = -half + 2 * half * j / n;
            add_vertex(m, x, y, height ? height(x, y) : 0);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            // Alternate the diagonal so that edges run in both directions.
            if ((i + j) % 2) {
                add_tri(m, a, b, d);
                add_tri(m, a, d, c);
            } else {
                add_tri(m, a, b, c);
                add_tri(m, b, d, c);
            }
        }
    build(m);
}

// The midpoint of edge (a, b), pushed to radius r, shared through a table
// of the edges already split (linear search: the meshes are small).
static int midpoint(test_mesh *m, int a, int b, double r, int (*cache)[3], int *ncache)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    for (int i = 0; i < *ncache; i++)
        if (cache[i][0] == lo && cache[i][1] == hi) return cache[i][2];
    double p[3], len = 0;
    for (int k = 0; k < 3; k++) {
        p[k] = (m->v[a][k] + m->v[b][k]) / 2;
        len += p[k] * p[k];
    }
    len = sqrt(len);
    int v = add_vertex(m, p[0] * r / len, p[1] * r / len, p[2] * r / len);
    cache[*ncache][0] = lo;
    cache[*ncache][1] = hi;
    cache[*ncache][2] = v;
    (*ncache)++;
    return v;
}

void mesh_icosphere(test_mesh *m, double r, int levels)
{
    int nt = 20, nv = 12;
    for (int l = 0; l < levels; l++) {
        nv += 3 * nt / 2;
        nt *= 4;
    }
    mesh_alloc(m, nv, nt);
    double t = (1 + sqrt(5.0)) / 2, s = r / sqrt(1 + t * t);
    static const int base[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
                                     { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 },
                                     { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
                                     { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 },
                                     { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
    double pts[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
                          { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t },
                          { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
    for (int i = 0; i < 12; i++) add_vertex(m, pts[i][0] * s, pts[i][1] * s, pts[i][2] * s);
    dTriIndex(*cur)[3] = malloc((size_t)nt * sizeof *cur);
    int ncur = 20;
    for (int i = 0; i < 20; i++)
        for (int k = 0; k < 3; k++) cur[i][k] = (dTriIndex)base[i][k];
    int(*cache)[3] = malloc((size_t)nv * sizeof *cache);
    for (int l = 0; l < levels; l++) {
        dTriIndex(*next)[3] = malloc((size_t)nt * sizeof *next);
        int nn = 0, ncache = 0;
        for (int i = 0; i < ncur; i++) {
            int a = (int)cur[i][0], b = (int)cur[i][1], c = (int)cur[i][2];
            int ab = midpoint(m, a, b, r, cache, &ncache), bc = midpoint(m, b, c, r, cache, &ncache),
                ca = midpoint(m, c, a, r, cache, &ncache);
            int quad[4][3] = { { a, ab, ca }, { b, bc, ab }, { c, ca, bc }, { ab, bc, ca } };
            for (int q = 0; q < 4; q++, nn++)
                for (int k = 0; k < 3; k++) next[nn][k] = (dTriIndex)quad[q][k];
        }
        free(cur);
        cur = next;
        ncur = nn;
    }
    for (int i = 0; i < ncur; i++) add_tri(m, (int)cur[i][0], (int)cur[i][1], (int)cur[i][2]);
    free(cur);
    free(cache);
    build(m);
}

void mesh_box(test_mesh *m, double lx, double ly, double lz, int n)
{
    mesh_alloc(m, 6 * (n + 1) * (n + 1), 12 * n * n);
    double h[3] = { lx / 2, ly / 2, lz / 2 };
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2) {
            // Face coordinates (u, w) along the other two axes, ordered so
            // that u x w points outwards.
            int u = (axis + 1) % 3, w = (axis + 2) % 3;
            if (sign < 0) {
                int t = u;
                u = w;
                w = t;
            }
            int first = m->nv;
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++) {
                    double p[3];
                    p[axis] = sign * h[axis];
                    p[u] = -h[u] + 2 * h[u] * i / n;
                    p[w] = -h[w] + 2 * h[w] * j / n;
                    add_vertex(m, p[0], p[1], p[2]);
                }
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    int a = first + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                    add_tri(m, a, b, d);
                    add_tri(m, a, d, c);
                }
        }
    build(m);
}

void mesh_torus(test_mesh *m, double R, double r, int nu, int nv)
{
    mesh_alloc(m, nu * nv, 2 * nu * nv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
            add_vertex(m, (R + r * cos(b)) * cos(a), (R + r * cos(b)) * sin(a), r * sin(b));
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = i * nv + (j + 1) % nv,
                d = ((i + 1) % nu) * nv + (j + 1) % nv;
            add_tri(m, a, b, d);
            add_tri(m, a, d, c);
        }
    build(m);
}

void mesh_sheet(test_mesh *m, double half)
{
    mesh_alloc(m, 4, 2);
    add_vertex(m, -half, -half, 0);
    add_vertex(m, half, -half, 0);
    add_vertex(m, half, half, 0);
    add_vertex(m, -half, half, 0);
    add_tri(m, 0, 1, 2);
    add_tri(m, 0, 2, 3);
    build(m);
}

void mesh_free(test_mesh *m)
{
    if (m->data) dGeomTriMeshDataDestroy(m->data);
    free(m->v);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

double sdf_sphere(double r, const double p[3])
{
    return r - sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}

double sdf_box(double lx, double ly, double lz, const double p[3])
{
    double h[3] = { lx / 2, ly / 2, lz / 2 }, inside = 1e300, out2 = 0;
    for (int i = 0; i < 3; i++) {
        double d = h[i] - fabs(p[i]);
        if (d < inside) inside = d;
        if (d < 0) out2 += d * d;
    }
    return out2 > 0 ? -sqrt(out2) : inside;
}

double sdf_torus(double R, double r, const double p[3])
{
    double q = sqrt(p[0] * p[0] + p[1] * p[1]) - R;
    return r - sqrt(q * q + p[2] * p[2]);
}
