// SPDX-License-Identifier: BSD-3-Clause
//
// heightfield_patch.c -- the cells under a query as a small triangle mesh
// (heightfield_internal.h): vertices, triangles, normals, neighbours, the
// vertices' neighbours and the feature bits, everything the trimesh
// colliders read, written directly from the grid (no sorting). The arrays
// belong to the thread's patch (heightfield_scratch.c) and only grow, so a
// warm query allocates nothing.

#include <ode/memory.h>

#include "heightfield_internal.h"

// As trimesh_data.c: faces this close to parallel are coplanar.
#if defined(dSINGLE)
#define FLAT_COS ((dReal)(1 - 1e-5))
#else
#define FLAT_COS ((dReal)(1 - 1e-8))
#endif

// Make room for nv vertices and nt triangles (contents not kept).
static void reserve(dxHeightfieldPatch *pt, int nv, int nt)
{
    dxTriMeshData *p = &pt->data;
    if (nv > pt->vertex_cap) {
        size_t o = (size_t)pt->vertex_cap, n = (size_t)nv + (size_t)nv / 2;
        dFree((void *)p->vertices, 3 * o * sizeof(dReal));
        dFree(p->weld, o * sizeof(int));
        dFree(p->vertex_first, (o + 1) * sizeof(int));
        dFree(p->vertex_adj, (size_t)pt->adj_cap * sizeof(int));
        p->vertices = dAlloc(3 * n * sizeof(dReal));
        p->weld = (int *)dAlloc(n * sizeof(int));
        p->vertex_first = (int *)dAlloc((n + 1) * sizeof(int));
        pt->adj_cap = 6 * (int)n;
        p->vertex_adj = (int *)dAlloc((size_t)pt->adj_cap * sizeof(int));
        pt->vertex_cap = (int)n;
    }
    if (nt > pt->tri_cap) {
        size_t o = (size_t)pt->tri_cap, n = (size_t)nt + (size_t)nt / 2;
        dFree((void *)p->indices, 3 * o * sizeof(dTriIndex));
        dFree(p->normal, 3 * o * sizeof(dReal));
        dFree(p->neighbour, 3 * o * sizeof(int));
        dFree(p->features, o);
        dFree(p->order, o * sizeof(int));
        p->indices = dAlloc(3 * n * sizeof(dTriIndex));
        p->normal = (dReal *)dAlloc(3 * n * sizeof(dReal));
        p->neighbour = (int *)dAlloc(3 * n * sizeof(int));
        p->features = (unsigned char *)dAlloc(n);
        p->order = (int *)dAlloc(n * sizeof(int));
        pt->tri_cap = (int)n;
    }
}

// Cell (i, j) of a patch nvx vertices wide is triangles 2 c and 2 c + 1,
// c = i + j (nvx - 1): with A = (i, j), B = (i + 1, j), C = (i, j + 1),
// D = (i + 1, j + 1), triangle 0 is (A, C, B) and triangle 1 (D, B, C), both
// facing +Y. Edges: 0 (A-C west), 1 (C-B diagonal), 2 (B-A north); and
// 0 (D-B east), 1 (B-C diagonal), 2 (C-D south).
static void cell_triangles(dxTriMeshData *p, int nvx, int ncz)
{
    int ncx = nvx - 1;
    dTriIndex *idx = (dTriIndex *)p->indices;
    for (int j = 0; j < ncz; j++) {
        for (int i = 0; i < ncx; i++) {
            int c = i + j * ncx, t = 2 * c;
            dTriIndex a = (dTriIndex)(i + j * nvx), b = a + 1, cc = a + (dTriIndex)nvx,
                      d = cc + 1;
            dTriIndex *u = idx + 3 * t;
            u[0] = a, u[1] = cc, u[2] = b;
            u[3] = d, u[4] = b, u[5] = cc;
            int *n0 = p->neighbour + 3 * t, *n1 = n0 + 3;
            n0[0] = i > 0 ? 2 * (c - 1) + 1 : -1;
            n0[1] = t + 1;
            n0[2] = j > 0 ? 2 * (c - ncx) + 1 : -1;
            n1[0] = i + 1 < ncx ? 2 * (c + 1) : -1;
            n1[1] = t;
            n1[2] = j + 1 < ncz ? 2 * (c + ncx) : -1;
        }
    }
}

static void normals(dxTriMeshData *p)
{
    for (int t = 0; t < p->tri_count; t++) {
        dReal v[3][3], e1[3], e2[3], *n = p->normal + 3 * t;
        dxTriMeshTriangle(p, t, v);
        for (int k = 0; k < 3; k++) {
            e1[k] = v[1][k] - v[0][k];
            e2[k] = v[2][k] - v[0][k];
        }
        dCalcVectorCross3(n, e1, e2);
        dReal len = dCalcVectorLength3(n);
        for (int k = 0; k < 3; k++) n[k] /= len;   // len > 0: cells have area
    }
}

// The trimesh rule (trimesh_internal.h): an edge is a feature if it has
// no neighbour or it is convex and not flat; a vertex if an edge at it is.
static void features(dxTriMeshData *p, unsigned char *vertex_feature)
{
    for (int v = 0; v < p->vertex_count; v++) vertex_feature[v] = 0;
    for (int t = 0; t < p->tri_count; t++) {
        int idx[3];
        dxTriMeshIndices(p, t, idx);
        unsigned char f = 0;
        for (int k = 0; k < 3; k++) {
            int u = p->neighbour[3 * t + k], is_feature = 1;
            if (u >= 0) {
                int uidx[3], far = 0;
                dxTriMeshIndices(p, u, uidx);
                for (int m = 0; m < 3; m++)
                    if (uidx[m] != idx[k] && uidx[m] != idx[(k + 1) % 3]) far = uidx[m];
                dReal a[3], w[3], aw[3];
                dxTriMeshVertex(p, idx[k], a);
                dxTriMeshVertex(p, far, w);
                dSubtractVectors3(aw, w, a);
                const dReal *n = p->normal + 3 * t;
                int flat = dCalcVectorDot3(n, p->normal + 3 * u) > FLAT_COS;
                is_feature = !flat && dCalcVectorDot3(n, aw) < 0;
            }
            if (is_feature) {
                f |= (unsigned char)(DX_TRI_EDGE_FEATURE << k);
                vertex_feature[idx[k]] = vertex_feature[idx[(k + 1) % 3]] = 1;
            }
        }
        p->features[t] = f;
    }
    for (int t = 0; t < p->tri_count; t++) {
        int idx[3];
        dxTriMeshIndices(p, t, idx);
        for (int k = 0; k < 3; k++)
            if (vertex_feature[idx[k]])
                p->features[t] |= (unsigned char)(DX_TRI_VERTEX_FEATURE << k);
    }
}

// Each vertex's neighbours along grid lines and the cells' diagonals.
static void adjacency(dxTriMeshData *p, int nvx, int nvz)
{
    static const int step[6][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 1, -1 }, { -1, 1 } };
    int n = 0;
    for (int j = 0; j < nvz; j++) {
        for (int i = 0; i < nvx; i++) {
            p->vertex_first[i + j * nvx] = n;
            for (int s = 0; s < 6; s++) {
                int a = i + step[s][0], b = j + step[s][1];
                if (a >= 0 && a < nvx && b >= 0 && b < nvz) p->vertex_adj[n++] = a + b * nvx;
            }
        }
    }
    p->vertex_first[nvx * nvz] = n;
    p->vertex_adj_count = n;
}

int dxHeightfieldBuildPatch(const dxHeightfieldData *d, dxHeightfieldPatch *pt, int x0, int x1,
                            int z0, int z1)
{
    int vx0 = x0 - 1, vx1 = x1 + 1, vz0 = z0 - 1, vz1 = z1 + 1;
    if (!d->wrap) {
        vx0 = vx0 < 0 ? 0 : vx0;
        vz0 = vz0 < 0 ? 0 : vz0;
        vx1 = vx1 > d->width_samples - 1 ? d->width_samples - 1 : vx1;
        vz1 = vz1 > d->depth_samples - 1 ? d->depth_samples - 1 : vz1;
    }
    int nvx = vx1 - vx0 + 1, nvz = vz1 - vz0 + 1;
    int nv = nvx * nvz, nt = 2 * (nvx - 1) * (nvz - 1);
    reserve(pt, nv, nt);
    dxTriMeshData *p = &pt->data;
    p->vertex_count = nv;
    p->tri_count = nt;
    dReal sw = dxHeightfieldCellWidth(d), sd = dxHeightfieldCellDepth(d);
    dReal *v = (dReal *)p->vertices;
    for (int j = 0; j < nvz; j++) {
        for (int i = 0; i < nvx; i++) {
            dReal *w = v + 3 * (i + j * nvx);
            int x = vx0 + i, z = vz0 + j;
            w[0] = (dReal)x * sw - d->width / 2;
            w[1] = dxHeightfieldSample(d, x, z);
            w[2] = (dReal)z * sd - d->depth / 2;
            if (!dxIsFinite(w[1])) {
                dxReportBadArgument("dCollide", "heightfield height at sample (%d, %d) is not finite",
                                    x, z);
                return 0;
            }
            p->weld[i + j * nvx] = i + j * nvx;
        }
    }
    cell_triangles(p, nvx, nvz - 1);
    normals(p);
    // vertex_first is free until adjacency(): the per-vertex marks go there.
    features(p, (unsigned char *)p->vertex_first);
    adjacency(p, nvx, nvz);
    // One leaf: the asked cells' triangles, in the box of their vertices.
    dxTriMeshNode *node = p->nodes;
    for (int k = 0; k < 3; k++) {
        p->lo[k] = dInfinity;
        p->hi[k] = -dInfinity;
    }
    int count = 0, ncx = nvx - 1;
    for (int j = z0 - vz0; j < z1 - vz0; j++)
        for (int i = x0 - vx0; i < x1 - vx0; i++) {
            p->order[count++] = 2 * (i + j * ncx);
            p->order[count++] = 2 * (i + j * ncx) + 1;
            for (int c = 0; c < 4; c++) {
                const dReal *w = v + 3 * (i + (c & 1) + (j + (c >> 1)) * nvx);
                for (int k = 0; k < 3; k++) {
                    p->lo[k] = dMin(p->lo[k], w[k]);
                    p->hi[k] = dMax(p->hi[k], w[k]);
                }
            }
        }
    dxTriMeshNodeSetLeaf(node, p->lo, p->hi, count);
    p->node_count = count > 0;
    return 1;
}
