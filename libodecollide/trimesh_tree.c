// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_tree.c -- the box tree of a mesh: built once per data object
// (top-down as a binary tree, each node's triangles split at the median of
// their centres along the longest side of the centres' box, leaves of at
// most LEAF triangles; then levels lifted into their parents, so that a
// node holds up to four children, after it; then the boxes
// bottom-up), refitted bottom-up when the vertices move (same topology),
// and walked with a fixed stack to list the triangles near a box (or the
// leaves, for temporal coherence), a node's four boxes tested at once.
// Beside the tree, a copy of the triangles' vertices in leaf order, so that
// a ray reads contiguous memory (the user's arrays are indexed twice over:
// triangle, vertex), and of their normals with their indices (the
// colliders' walk reads them without going through order[]).

#include <math.h>
#include <ode/memory.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

#include "trimesh_internal.h"
#include "../libodedyn/core/dx_clones.h"

// The query's walk in two versions (see query_leaves); clang (14) builds
// the baseline alone, as for box-box (collide_box.c).
#if !defined(__clang__) && defined(DX_AVX2_CLONES)
#define QUERY_CLONES DX_AVX2_CLONES
#else
#define QUERY_CLONES
#endif


// Leaves of at most LEAF triangles (DX_TRI_LEAF_MAX). A median split
// halves the triangles, so the binary depth stays below log2(tri_count) + 2
// and the four-way depth below half that: a walk stacks at most one node a
// level, far below DX_TRI_WALK_STACK.
enum { LEAF = DX_TRI_LEAF_MAX };

void dxTriMeshBuildTree(dxTriMeshData *d);
void dxTriMeshRefitTree(dxTriMeshData *d, int neighbours_kept);

uint64_t dxTriMeshNewStamp(void)
{
    static _Atomic uint64_t next = 1;
    return atomic_fetch_add(&next, 1);
}

// Bit k set for each edge k of triangle t with a coplanar neighbour
// (dxTriLeafFace): the dot product summed as the colliders sum it.
static unsigned coplanar_edges(const dxTriMeshData *d, int t)
{
    const dReal *n = d->normal + 3 * t;
    unsigned bits = 0;
    for (int k = 0; k < 3; k++) {
        const int u = d->neighbour[3 * t + k];
        if (u < 0) continue;
        const dReal *m = d->normal + 3 * u;
        if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > DX_TRI_COPLANAR_COS) bits |= 1u << k;
    }
    return bits;
}

// (Re)write leaf position j's copies of triangle t: its vertices from the
// user's arrays, its face (normal, index, coplanar edges; found before)
// and the face's float box, rounded outwards; its exact box into lo, hi.
static void copy_leaf_triangle(dxTriMeshData *d, int j, int t, dReal lo[3], dReal hi[3])
{
    dReal(*v)[3] = (dReal(*)[3])(d->leaf_vertices + 9 * j);
    dxTriMeshTriangle(d, t, v);
    dxTriLeafFace *f = &d->leaf_faces[j];
    for (int k = 0; k < 3; k++) {
        lo[k] = dMin(v[0][k], dMin(v[1][k], v[2][k]));
        hi[k] = dMax(v[0][k], dMax(v[1][k], v[2][k]));
        f->box[k] = dxFloatBelow(lo[k]);
        f->box[3 + k] = dxFloatAbove(hi[k]);
        f->n[k] = d->normal[3 * t + k];
    }
    f->index = t;
    f->coplanar = coplanar_edges(d, t);
}

// Each face's near[] (dxTriLeafFace): the neighbours' leaf positions less
// its own, from the neighbours (found again by an Update: a weld may join
// or part them) and the leaf order.
static void set_near_faces(dxTriMeshData *d)
{
    int *position = (int *)dAlloc((size_t)d->tri_count * sizeof(int));
    for (int j = 0; j < d->tri_count; j++) position[d->order[j]] = j;
    for (int j = 0; j < d->tri_count; j++) {
        const int *u = d->neighbour + 3 * d->order[j];
        for (int k = 0; k < 3; k++) {
            const long away = u[k] < 0 ? DX_TRI_NEAR_NONE : (long)position[u[k]] - j;
            d->leaf_faces[j].near[k] =
                (int16_t)(away > INT16_MIN && away <= INT16_MAX ? away : DX_TRI_NEAR_NONE);
        }
    }
    dFree(position, (size_t)d->tri_count * sizeof(int));
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

// A triangle's centre with its index, moved as one while the tree is
// built: the splits read the centres in sequence, not through order[].
typedef struct centre_rec {
    dReal c[3];
    int t;
} centre_rec;

// Rearrange rec[lo, hi) so that the element at mid has the centre it
// would have sorted by c[axis], no larger ones before it (quickselect,
// Hoare's partition).
static void select_median(centre_rec *rec, int axis, int lo, int hi, int mid)
{
    while (hi - lo > 1) {
        dReal pivot = rec[(lo + hi) / 2].c[axis];
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (rec[i].c[axis] < pivot) i++;
            while (rec[j].c[axis] > pivot) j--;
            if (i <= j) {
                centre_rec t = rec[i];
                rec[i] = rec[j];
                rec[j] = t;
                i++;
                j--;
            }
        }
        if (mid <= j) hi = j + 1;
        else if (mid >= i) lo = i;
        else return;
    }
}

// Slot s of node gets the float box containing [lo, hi].
static void set_slot_box(dxTriMeshNode *node, int s, const dReal lo[3], const dReal hi[3])
{
    for (int k = 0; k < 3; k++) {
        node->lo[k][s] = dxFloatBelow(lo[k]);
        node->hi[k][s] = dxFloatAbove(hi[k]);
    }
}

// Every slot unused (count -1, an empty box).
static void clear_node(dxTriMeshNode *node)
{
    for (int s = 0; s < 4; s++) {
        for (int k = 0; k < 3; k++) {
            node->lo[k][s] = INFINITY;
            node->hi[k][s] = -INFINITY;
        }
        node->first[s] = 0;
        node->count[s] = -1;
    }
}

void dxTriMeshNodeSetLeaf(dxTriMeshNode *node, const dReal lo[3], const dReal hi[3], int count)
{
    clear_node(node);
    set_slot_box(node, 0, lo, hi);
    node->first[0] = 0;
    node->count[0] = count;
}

static void grow(dReal lo[3], dReal hi[3], const dReal blo[3], const dReal bhi[3])
{
    for (int k = 0; k < 3; k++) {
        if (blo[k] < lo[k]) lo[k] = blo[k];
        if (bhi[k] > hi[k]) hi[k] = bhi[k];
    }
}

// A node of the binary tree while building: a leaf of count > 0 triangles
// order[first ..], or (count 0) an inner node with its children at first
// and first + 1; height: the longest way down to a leaf (a leaf's is 0).
typedef struct bin_node {
    int first, count, height;
} bin_node;

// Binary node i over rec[lo, hi) (its slot taken): split at the median of
// the triangles' centres along the longest side of their box. Its children
// take the next two free slots of bin[] (*used).
static void build_node(bin_node *bin, int *used, int i, centre_rec *rec, int lo, int hi)
{
    if (hi - lo <= LEAF) {
        bin[i] = (bin_node){ lo, hi - lo, 0 };
        return;
    }
    dReal clo[3] = { dInfinity, dInfinity, dInfinity };
    dReal chi[3] = { -dInfinity, -dInfinity, -dInfinity };
    for (int j = lo; j < hi; j++) {   // the centres' box, without branches
        const dReal *c = rec[j].c;
        for (int k = 0; k < 3; k++) {
            clo[k] = c[k] < clo[k] ? c[k] : clo[k];
            chi[k] = c[k] > chi[k] ? c[k] : chi[k];
        }
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    int mid = (lo + hi) / 2;
    select_median(rec, axis, lo, hi, mid);
    int first = *used;
    *used += 2;
    build_node(bin, used, first, rec, lo, mid);
    build_node(bin, used, first + 1, rec, mid, hi);
    int h = bin[first].height > bin[first + 1].height ? bin[first].height : bin[first + 1].height;
    bin[i] = (bin_node){ first, 0, h + 1 };
}

// The slots of the four-way node made from binary inner node b (or a
// leaf, as the root of a small mesh) into slot[]; returns their count:
// b's children in order, and while there is room, the first inner slot of
// odd height gives way to its two children. So the slots below are of
// even height, whose grandchildren fill a node's four slots: about a third
// as many nodes as leaves, where lifting every second level from the root
// would make half-empty nodes over the leaves when the tree's height is
// odd.
static int lift_slots(const bin_node *bin, int b, int slot[4])
{
    int n = 0;
    if (bin[b].count > 0) {
        slot[n++] = b;
    } else {
        slot[n++] = bin[b].first;
        slot[n++] = bin[b].first + 1;
    }
    while (n < 4) {
        int e = 0;
        while (e < n && !(bin[slot[e]].count == 0 && bin[slot[e]].height % 2 == 1)) e++;
        if (e == n) break;
        int first = bin[slot[e]].first;
        for (int k = n; k > e + 1; k--) slot[k] = slot[k - 1];
        slot[e] = first;
        slot[e + 1] = first + 1;
        n++;
    }
    return n;
}

// How many four-way nodes lifting makes from binary node b down (the tree
// is placed once, at its size).
static int count_lifted(const bin_node *bin, int b)
{
    int slot[4], n = lift_slots(bin, b, slot), nodes = 1;
    for (int s = 0; s < n; s++)
        if (bin[slot[s]].count == 0) nodes += count_lifted(bin, slot[s]);
    return nodes;
}

// The four-way node w from binary node b (lift_slots). Inner slots take
// the next free nodes (*used) and are made at once (depth first: a node's
// children come after it).
static void lift_node(dxTriMeshData *d, const bin_node *bin, int b, int w, int *used)
{
    int slot[4], n = lift_slots(bin, b, slot);
    clear_node(&d->nodes[w]);
    for (int s = 0; s < n; s++) {
        const bin_node *e = &bin[slot[s]];
        if (e->count > 0) {
            d->nodes[w].first[s] = e->first;
            d->nodes[w].count[s] = e->count;
        } else {
            int child = (*used)++;
            d->nodes[w].first[s] = child;
            d->nodes[w].count[s] = 0;
            lift_node(d, bin, slot[s], child, used);
        }
    }
}

// Node i's slots' boxes and, for its leaves, the leaf-order copies
// (copy_leaf_triangle), depth first, children before their parent's box
// (post-order: leaf positions are met in increasing order, so the copies
// are written and the user's arrays read in sequence); node i's exact box
// into lo, hi.
static void fit_node(dxTriMeshData *d, int i, dReal lo[3], dReal hi[3])
{
    dxTriMeshNode *node = &d->nodes[i];
    for (int k = 0; k < 3; k++) {
        lo[k] = dInfinity;
        hi[k] = -dInfinity;
    }
    for (int s = 0; s < 4 && node->count[s] >= 0; s++) {
        dReal slo[3] = { dInfinity, dInfinity, dInfinity };
        dReal shi[3] = { -dInfinity, -dInfinity, -dInfinity };
        if (node->count[s] > 0) {
            for (int j = node->first[s]; j < node->first[s] + node->count[s]; j++) {
                dReal tlo[3], thi[3];
                copy_leaf_triangle(d, j, d->order[j], tlo, thi);
                grow(slo, shi, tlo, thi);
            }
        } else {
            fit_node(d, node->first[s], slo, shi);
        }
        set_slot_box(node, s, slo, shi);
        grow(lo, hi, slo, shi);
    }
}

// The leaf-order copies and every slot's box (fit_node); the root's exact
// box into the data.
static void fit_boxes(dxTriMeshData *d)
{
    fit_node(d, 0, d->lo, d->hi);
}

// Every node's span (node_span): the leaf-order triangles of its subtree,
// from its first slot's to its last used slot's (a subtree's leaves are
// consecutive in leaf order). Children come after their parent: going
// backwards meets them first.
static void set_spans(dxTriMeshData *d)
{
    for (int i = d->node_count - 1; i >= 0; i--) {
        const dxTriMeshNode *node = &d->nodes[i];
        int first = 0, end = 0;
        for (int s = 0; s < 4 && node->count[s] >= 0; s++) {
            const int *child = d->node_span + 2 * node->first[s];
            int lo = node->count[s] > 0 ? node->first[s] : child[0];
            int hi = node->count[s] > 0 ? node->first[s] + node->count[s] : child[0] + child[1];
            if (s == 0) first = lo;
            end = hi;
        }
        d->node_span[2 * i] = first;
        d->node_span[2 * i + 1] = end - first;
    }
}

// One block for the nodes (node_count of them), the nodes' spans, the
// leaf-order vertices and the triangles' faces, each at the start of a
// cache line: a node is read as two lines, not three, a leaf's vertices
// touch the fewest lines, and a face is one line. On huge pages where it
// is that large (big_block.h): a ray reads a few lines of nodes and leaves
// all over the block (a 100 000-triangle mesh's is 15 MB, 3 700 small
// pages), so nearly every line it waits for would also miss the TLB. The
// nodes and spans, which every ray reads, come first.
static void place_tree(dxTriMeshData *d)
{
    size_t node_room = ((size_t)d->node_count * sizeof(dxTriMeshNode) + 63) / 64 * 64;
    size_t vertex_room = (9 * (size_t)d->tri_count * sizeof(dReal) + 63) / 64 * 64;
    size_t face_room = ((size_t)d->tri_count * sizeof(dxTriLeafFace) + 63) / 64 * 64;
    size_t span_room = (2 * (size_t)d->node_count * sizeof(int) + 63) / 64 * 64;
    char *p = (char *)dxBigBlockAlloc(&d->tree_block,
                                      node_room + vertex_room + face_room + span_room);
    d->nodes = (dxTriMeshNode *)p;
    d->node_span = (int *)(p + node_room);
    d->leaf_vertices = (dReal *)(p + node_room + span_room);
    d->leaf_faces = (dxTriLeafFace *)(p + node_room + span_room + vertex_room);
}

void dxTriMeshFreeTree(dxTriMeshData *d)
{
    dxBigBlockFree(&d->tree_block);
    d->nodes = NULL;
    d->node_span = NULL;
    d->leaf_vertices = NULL;
    d->leaf_faces = NULL;
}

void dxTriMeshBuildTree(dxTriMeshData *d)
{
    size_t n = (size_t)d->tri_count;
    d->order = (int *)dAlloc(n * sizeof(int));
    centre_rec *rec = (centre_rec *)dAlloc(n * sizeof *rec);
    for (int t = 0; t < d->tri_count; t++) {
        dReal lo[3], hi[3];
        triangle_box(d, t, lo, hi);
        for (int k = 0; k < 3; k++) rec[t].c[k] = (lo[k] + hi[k]) / 2;
        rec[t].t = t;
    }
    // At most 2 n - 1 binary nodes.
    size_t bin_size = 2 * n * sizeof(bin_node);
    bin_node *bin = (bin_node *)dAlloc(bin_size);
    int used = 1;
    build_node(bin, &used, 0, rec, 0, d->tri_count);
    for (int j = 0; j < d->tri_count; j++) d->order[j] = rec[j].t;
    dFree(rec, n * sizeof *rec);
    d->node_count = count_lifted(bin, 0);
    place_tree(d);
    used = 1;
    lift_node(d, bin, 0, 0, &used);
    dFree(bin, bin_size);
    set_spans(d);
    fit_boxes(d);
    set_near_faces(d);
    d->tree_stamp = dxTriMeshNewStamp();
}

void dxTriMeshRefitTree(dxTriMeshData *d, int neighbours_kept)
{
    if (d->node_count == 0) return;
    fit_boxes(d);
    if (!neighbours_kept) set_near_faces(d);
    d->tree_stamp = dxTriMeshNewStamp();
}

int dxTriMeshQueryBox(const dxTriMeshData *d, const dReal lo[3], const dReal hi[3], int **out,
                      int *cap)
{
    if (d->node_count == 0) return 0;
    float lo_f[4], hi_f[4];
    dxFloatBox(lo, hi, lo_f, hi_f);
    dxTriTreeWalk w;
    dxTriTreeWalkStartF(d, lo_f, hi_f, &w);
    int n = 0;
    for (int id; (id = dxTriTreeWalkNext(d, &w)) >= 0;) {
        const dxTriMeshNode *leaf = &d->nodes[id >> 2];
        int first = leaf->first[id & 3], count = leaf->count[id & 3];
        if (n + count > *cap) dxTriMeshReserveInts(out, cap, n + count);
        for (int j = 0; j < count; j++) (*out)[n++] = d->order[first + j];
    }
    return n;
}

// dxTriMeshQueryLeavesF's walk, built twice where the library can pick a
// version when loaded (dx_clones.h): with AVX2 (the same comparisons, in
// three-operand form) and for the baseline. Static, called through the
// plain function below (GCC 12 exports a clone whatever the visibility).
QUERY_CLONES static int query_leaves(const dxTriMeshData *d, const float lo_f[3],
                                     const float hi_f[3], int *leaf, int max)
{
    dxTriTreeWalk w;
    dxTriTreeWalkStartF(d, lo_f, hi_f, &w);
    int n = 0;
    for (int id; (id = dxTriTreeWalkNext(d, &w)) >= 0;) {
        if (n == max) return -1;
        leaf[n++] = id;
    }
    return n;
}

int dxTriMeshQueryLeavesF(const dxTriMeshData *d, const float lo_f[3], const float hi_f[3],
                          int *leaf, int max)
{
    return d->node_count == 0 ? 0 : query_leaves(d, lo_f, hi_f, leaf, max);
}

void dxTriMeshDataBounds(const dxTriMeshData *d, dReal lo[3], dReal hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = d->node_count ? d->lo[k] : 0;
        hi[k] = d->node_count ? d->hi[k] : 0;
    }
}
