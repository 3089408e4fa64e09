// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_tree.c -- the box tree of a mesh: built once per data object
// (top-down, each node's triangles split at the median of their centres
// along the longest side of the centres' box, leaves of at most LEAF
// triangles; siblings side by side, after their parent; then the boxes
// bottom-up), refitted bottom-up when the vertices move (same topology),
// and walked with a fixed stack to list the triangles near a box (or the
// leaves, for temporal coherence). Beside the tree, a copy of
// the triangles' vertices in leaf order, so that a ray reads contiguous
// memory (the user's arrays are indexed twice over: triangle, vertex).

#include <math.h>
#include <ode/memory.h>
#include <stdatomic.h>
#include <string.h>

#include "trimesh_internal.h"

// A median split halves the triangles, so the depth stays below
// log2(tri_count) + 2, far below STACK.
enum { LEAF = 4, STACK = 64 };

void dxTriMeshBuildTree(dxTriMeshData *d);
void dxTriMeshRefitTree(dxTriMeshData *d);

uint64_t dxTriMeshNewStamp(void)
{
    static _Atomic uint64_t next = 1;
    return atomic_fetch_add(&next, 1);
}

// (Re)write the leaf-order copy of the vertices from the user's arrays.
static void copy_leaf_vertices(dxTriMeshData *d)
{
    for (int j = 0; j < d->tri_count; j++)
        dxTriMeshTriangle(d, d->order[j], (dReal(*)[3])(d->leaf_vertices + 9 * j));
}

// The box of the triangle at leaf position j, from the copy.
static void leaf_triangle_box(const dxTriMeshData *d, int j, dReal lo[3], dReal hi[3])
{
    const dReal *v = d->leaf_vertices + 9 * j;
    for (int k = 0; k < 3; k++) {
        lo[k] = dMin(v[k], dMin(v[3 + k], v[6 + k]));
        hi[k] = dMax(v[k], dMax(v[3 + k], v[6 + k]));
    }
}

static void triangle_box(const dxTriMeshData *d, int t, dReal lo[3], dReal hi[3])
{
    dReal v[3][3];
    dxTriMeshTriangle(d, t, v);
    for (int k = 0; k < 3; k++) {
        lo[k] = dMin(v[0][k], dMin(v[1][k], v[2][k]));
        hi[k] = dMax(v[0][k], dMax(v[1][k], v[2][k]));
    }
}

// Rearrange order[lo, hi) so that the element at mid has the centre it
// would have sorted by centre[.][axis], no larger ones before it
// (quickselect).
static void select_median(int *order, const dReal *centre, int axis, int lo, int hi, int mid)
{
    while (hi - lo > 1) {
        dReal pivot = centre[3 * order[(lo + hi) / 2] + axis];
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (centre[3 * order[i] + axis] < pivot) i++;
            while (centre[3 * order[j] + axis] > pivot) j--;
            if (i <= j) {
                int t = order[i];
                order[i] = order[j];
                order[j] = t;
                i++;
                j--;
            }
        }
        if (mid <= j) hi = j + 1;
        else if (mid >= i) lo = i;
        else return;
    }
}

void dxTriMeshNodeSetBox(dxTriMeshNode *node, const dReal lo[3], const dReal hi[3])
{
    for (int k = 0; k < 3; k++) {
        float l = (float)lo[k], h = (float)hi[k];
        if (l > lo[k]) l = nextafterf(l, -INFINITY);
        if (h < hi[k]) h = nextafterf(h, INFINITY);
        node->lo[k] = l;
        node->hi[k] = h;
    }
}

static void grow(dReal lo[3], dReal hi[3], const dReal blo[3], const dReal bhi[3])
{
    for (int k = 0; k < 3; k++) {
        if (blo[k] < lo[k]) lo[k] = blo[k];
        if (bhi[k] > hi[k]) hi[k] = bhi[k];
    }
}

// Node i over order[lo, hi) (its slot taken): split at the median of the
// triangles' centres (3 numbers per triangle) along the longest side of
// their box. Its children take the next two free slots. The nodes' boxes
// are set afterwards (fit_boxes).
static void build_node(dxTriMeshData *d, int i, const dReal *centre, int lo, int hi)
{
    dxTriMeshNode *node = &d->nodes[i];
    if (hi - lo <= LEAF) {
        node->first = lo;
        node->count = hi - lo;
        return;
    }
    dReal clo[3] = { dInfinity, dInfinity, dInfinity };
    dReal chi[3] = { -dInfinity, -dInfinity, -dInfinity };
    for (int j = lo; j < hi; j++) {
        const dReal *c = centre + 3 * d->order[j];
        grow(clo, chi, c, c);
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    int mid = (lo + hi) / 2;
    select_median(d->order, centre, axis, lo, hi, mid);
    node->count = 0;
    node->first = d->node_count;
    d->node_count += 2;
    build_node(d, node->first, centre, lo, mid);
    build_node(d, d->nodes[i].first + 1, centre, mid, hi);
}

// Every node's box from the leaf-order copy of the vertices, bottom-up
// (children come after their parent: going backwards meets them first),
// the exact boxes kept beside the nodes' rounded ones while walking; the
// root's exact box into the data.
static void fit_boxes(dxTriMeshData *d)
{
    size_t size = (size_t)d->node_count * 6 * sizeof(dReal);
    dReal *exact = (dReal *)dAlloc(size);
    for (int i = d->node_count - 1; i >= 0; i--) {
        dxTriMeshNode *node = &d->nodes[i];
        dReal *lo = exact + 6 * i, *hi = lo + 3;
        for (int k = 0; k < 3; k++) {
            lo[k] = dInfinity;
            hi[k] = -dInfinity;
        }
        if (node->count > 0) {
            for (int j = node->first; j < node->first + node->count; j++) {
                dReal tlo[3], thi[3];
                leaf_triangle_box(d, j, tlo, thi);
                grow(lo, hi, tlo, thi);
            }
        } else {
            for (int c = node->first; c <= node->first + 1; c++)
                grow(lo, hi, exact + 6 * c, exact + 6 * c + 3);
        }
        dxTriMeshNodeSetBox(node, lo, hi);
    }
    for (int k = 0; k < 3; k++) {
        d->lo[k] = exact[k];
        d->hi[k] = exact[3 + k];
    }
    dFree(exact, size);
}

void dxTriMeshBuildTree(dxTriMeshData *d)
{
    size_t n = (size_t)d->tri_count;
    d->order = (int *)dAlloc(n * sizeof(int));
    d->nodes = (dxTriMeshNode *)dAlloc(2 * n * sizeof(dxTriMeshNode));
    d->node_count = 1;
    dReal *centre = (dReal *)dAlloc(3 * n * sizeof(dReal));
    for (int t = 0; t < d->tri_count; t++) {
        d->order[t] = t;
        dReal lo[3], hi[3];
        triangle_box(d, t, lo, hi);
        for (int k = 0; k < 3; k++) centre[3 * t + k] = (lo[k] + hi[k]) / 2;
    }
    build_node(d, 0, centre, 0, d->tri_count);
    dFree(centre, 3 * n * sizeof(dReal));
    // Fewer nodes than the 2 n reserved are used (about n / 2): give the rest back.
    d->nodes = (dxTriMeshNode *)dRealloc(d->nodes, 2 * n * sizeof(dxTriMeshNode),
                                         (size_t)d->node_count * sizeof(dxTriMeshNode));
    d->leaf_vertices = (dReal *)dAlloc(9 * n * sizeof(dReal));
    copy_leaf_vertices(d);
    fit_boxes(d);
    d->tree_stamp = dxTriMeshNewStamp();
}

void dxTriMeshRefitTree(dxTriMeshData *d)
{
    if (d->node_count == 0) return;
    copy_leaf_vertices(d);
    fit_boxes(d);
    d->tree_stamp = dxTriMeshNewStamp();
}

static int overlaps(const dxTriMeshNode *node, const dReal lo[3], const dReal hi[3])
{
    return node->lo[0] <= hi[0] && node->hi[0] >= lo[0] && node->lo[1] <= hi[1] &&
           node->hi[1] >= lo[1] && node->lo[2] <= hi[2] && node->hi[2] >= lo[2];
}

int dxTriMeshQueryBox(const dxTriMeshData *d, const dReal lo[3], const dReal hi[3], int **out,
                      int *cap)
{
    if (d->node_count == 0) return 0;
    int stack[STACK], top = 0, n = 0;
    stack[top++] = 0;
    while (top > 0) {
        int i = stack[--top];
        const dxTriMeshNode *node = &d->nodes[i];
        if (!overlaps(node, lo, hi)) continue;
        if (node->count > 0) {
            if (n + node->count > *cap) dxTriMeshReserveInts(out, cap, n + node->count);
            for (int j = 0; j < node->count; j++) (*out)[n++] = d->order[node->first + j];
        } else {   // the first child is walked first
            stack[top++] = node->first + 1;
            stack[top++] = node->first;
        }
    }
    return n;
}

int dxTriMeshQueryLeaves(const dxTriMeshData *d, const dReal lo[3], const dReal hi[3], int *leaf,
                         int max)
{
    if (d->node_count == 0) return 0;
    int stack[STACK], top = 0, n = 0;
    stack[top++] = 0;
    while (top > 0) {
        int i = stack[--top];
        const dxTriMeshNode *node = &d->nodes[i];
        if (!overlaps(node, lo, hi)) continue;
        if (node->count > 0) {
            if (n == max) return -1;
            leaf[n++] = i;
        } else {   // the first child is walked first, as in dxTriMeshQueryBox
            stack[top++] = node->first + 1;
            stack[top++] = node->first;
        }
    }
    return n;
}

int dxTriMeshFilterLeaves(const dxTriMeshData *d, const int *leaf, int n, const dReal lo[3],
                          const dReal hi[3], int **out, int *cap)
{
    int count = 0;
    for (int i = 0; i < n; i++) {
        const dxTriMeshNode *node = &d->nodes[leaf[i]];
        if (!overlaps(node, lo, hi)) continue;
        if (count + node->count > *cap) dxTriMeshReserveInts(out, cap, count + node->count);
        for (int j = 0; j < node->count; j++) (*out)[count++] = d->order[node->first + j];
    }
    return count;
}

void dxTriMeshDataBounds(const dxTriMeshData *d, dReal lo[3], dReal hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = d->node_count ? d->lo[k] : 0;
        hi[k] = d->node_count ? d->hi[k] : 0;
    }
}
