// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_data.c -- dTriMeshDataID (guide 10.7.6): the builds over the
// user's strided arrays (checked, never copied), face normals, neighbours
// across edges and which edges and vertices are real features, the extra
// data (Set / Get / Preprocess) and Update.

#include <float.h>
#include <ode/memory.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SSE2__) && !defined(dSINGLE)
#include <emmintrin.h>
#endif

#include "trimesh_internal.h"

// Cosine above which two neighbouring faces count as coplanar.
#ifdef dSINGLE
#define FLAT_COS ((dReal)(1 - 1e-5))
#else
#define FLAT_COS ((dReal)(1 - 1e-8))
#endif

void dxTriMeshBuildTree(dxTriMeshData *d);   // trimesh_tree.c
// The tree's boxes and leaf-order copies made again for moved vertices
// (the faces' neighbours too unless the Update kept the topology).
void dxTriMeshRefitTree(dxTriMeshData *d, int neighbours_kept);
void dxTriMeshFreeTree(dxTriMeshData *d);

#define CHECK_DATA(d, on_fail) \
    DX_CHECK_ARG(dxTriMeshDataIsLive(d) && !(d)->destroy_pending, on_fail, \
                 "trimesh data is NULL or was destroyed")

void dxTriMeshIndices(const dxTriMeshData *d, int t, int idx[3])
{
    dTriIndex v[3];
    memcpy(v, (const char *)d->indices + (size_t)t * (size_t)d->tri_stride, sizeof v);
    for (int k = 0; k < 3; k++) idx[k] = (int)v[k];
}

void dxTriMeshTriangle(const dxTriMeshData *d, int t, dReal v[3][3])
{
    int idx[3];
    dxTriMeshIndices(d, t, idx);
    for (int k = 0; k < 3; k++) dxTriMeshVertex(d, idx[k], v[k]);
}

void dxTriMeshReserveInts(int **a, int *cap, int n)
{
    if (n <= *cap) return;
    int ncap = *cap ? *cap : 16;
    while (ncap < n) ncap *= 2;
    *a = (int *)dRealloc(*a, (size_t)*cap * sizeof(int), (size_t)ncap * sizeof(int));
    *cap = ncap;
}

// ---- derived data ----------------------------------------------------------

// Free what the weld decides (shared edges, vertex adjacency).
static void clear_adjacency(dxTriMeshData *d)
{
    if (d->edges) dFree(d->edges, (size_t)d->edge_count * sizeof *d->edges + sizeof *d->edges);
    d->edges = NULL;
    d->edge_count = 0;
    if (d->vertex_first) dFree(d->vertex_first, ((size_t)d->vertex_count + 1) * sizeof(int));
    if (d->vertex_adj)
        dFree(d->vertex_adj, (size_t)d->vertex_adj_count * sizeof(int) + sizeof(int));
    d->vertex_first = d->vertex_adj = NULL;
    d->vertex_adj_count = 0;
}

// Free what was derived from the arrays (the data keeps no triangles).
static void clear_derived(dxTriMeshData *d)
{
    size_t n = (size_t)d->tri_count;
    if (n > 0) {
        dFree(d->normal, 3 * n * sizeof(dReal));
        dFree(d->neighbour, 3 * n * sizeof(int));
        dFree(d->welded, 3 * n * sizeof(int));
        dFree(d->open_edges, n);
        dFree(d->features, n);
        dFree(d->order, n * sizeof(int));
        dxTriMeshFreeTree(d);
        if (d->built_flags) dFree(d->built_flags, n);
        dFree(d->weld, (size_t)d->vertex_count * sizeof(int));
        clear_adjacency(d);
    }
    d->normal = NULL;
    d->neighbour = NULL;
    d->welded = NULL;
    d->open_edges = NULL;
    d->features = NULL;
    d->order = NULL;
    d->leaf_vertices = NULL;
    d->leaf_faces = NULL;
    d->tree_stamp = 0;
    d->nodes = NULL;
    d->node_span = NULL;
    d->built_flags = NULL;
    d->weld = NULL;
    d->vertex_first = d->vertex_adj = NULL;
    d->vertex_adj_count = 0;
    d->node_count = 0;
    d->closed = 0;
    d->tri_count = 0;
    d->vertex_count = 0;
    d->vertices = d->indices = d->user_normals = NULL;
    d->user_flags = NULL;
}

// Working memory of a build or an Update: every vertex in dReal (pos, 3 a
// vertex, read by index without the user's stride and type), an open
// hash table of vertex indices by position (slot, -1 free; a power of two
// at least twice the vertices) and a byte a vertex (mark).
typedef struct derive_scratch {
    dReal *pos;
    int *slot;
    unsigned char *mark;
    size_t slots;
} derive_scratch;

static void scratch_alloc(derive_scratch *s, int vertex_count)
{
    size_t n = (size_t)vertex_count;
    s->slots = 2;
    while (s->slots < 2 * n) s->slots *= 2;
    s->pos = (dReal *)dAlloc(3 * n * sizeof(dReal) + sizeof(dReal));
    s->slot = (int *)dAlloc(s->slots * sizeof(int));
    s->mark = (unsigned char *)dAlloc(n + 1);
}

static void scratch_free(derive_scratch *s, int vertex_count)
{
    size_t n = (size_t)vertex_count;
    dFree(s->pos, 3 * n * sizeof(dReal) + sizeof(dReal));
    dFree(s->slot, s->slots * sizeof(int));
    dFree(s->mark, n + 1);
}

// The vertices that the first `tris` triangles name into pos, the others
// zero: only those are read from the user's array, as ODE reads only what
// its triangles name (ODE's own demo_trimesh_collision passes a VertexCount
// three times its array's). Indices past the vertex count are skipped (the
// build rejects them first). used: scratch, a byte a vertex. 1 if every
// named vertex is finite, else 0 with the first bad index in *bad.
static int load_positions(const dxTriMeshData *d, int tris, dReal *pos, unsigned char *used,
                          int *bad)
{
    const int count = d->vertex_count;
    memset(used, 0, (size_t)count);
    for (int t = 0; t < tris; t++) {
        dTriIndex v[3];
        memcpy(v, (const char *)d->indices + (size_t)t * (size_t)d->tri_stride, sizeof v);
        for (int k = 0; k < 3; k++)
            if (v[k] < (dTriIndex)count) used[v[k]] = 1;
    }
    for (int i = 0; i < count; i++) {
        dReal *out = pos + 3 * i;
        if (!used[i]) {
            out[0] = out[1] = out[2] = 0;
            continue;
        }
        dxTriMeshVertex(d, i, out);
        if (!dxIsFinite3(out[0], out[1], out[2])) {
            *bad = i;
            return 0;
        }
    }
    return 1;
}

#ifdef dSINGLE
typedef uint32_t real_bits;
#else
typedef uint64_t real_bits;
#endif

// A hash of a position in which -0 and +0 agree (they weld: == holds).
static size_t position_hash(const dReal p[3])
{
    uint64_t h = 0;
    for (int k = 0; k < 3; k++) {
        dReal x = p[k] + (dReal)0;   // -0 + 0 is +0
        real_bits b;
        memcpy(&b, &x, sizeof b);
        h = (h ^ (uint64_t)b) * 0x9e3779b97f4a7c15ull;
    }
    return (size_t)(h ^ (h >> 29));
}

// weld[i]: the first vertex at exactly the position of vertex i (a hash
// of the positions, vertices entered in index order), so that meshes with
// repeated vertices (per face, for normals or texture coordinates) still
// know their neighbours. With check set, weld[] is compared instead of
// written: 0 at the first vertex whose first is not weld[i], else 1.
static int weld_positions(const dxTriMeshData *d, const derive_scratch *s, int *weld, int check)
{
    const size_t mask = s->slots - 1;
    memset(s->slot, 0xff, s->slots * sizeof(int));
    for (int i = 0; i < d->vertex_count; i++) {
        const dReal *p = s->pos + 3 * i;
        size_t h = position_hash(p) & mask;
        int first = i;
        for (; s->slot[h] >= 0; h = (h + 1) & mask) {
            const dReal *q = s->pos + 3 * s->slot[h];
            if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) {
                first = s->slot[h];
                break;
            }
        }
        if (first == i) s->slot[h] = i;
        if (!check) weld[i] = first;
        else if (weld[i] != first) return 0;
    }
    return 1;
}

// The welded vertex indices of every triangle (3 a triangle).
static void compute_welded(dxTriMeshData *d)
{
    for (int t = 0; t < d->tri_count; t++) {
        int *idx = d->welded + 3 * t;
        dxTriMeshIndices(d, t, idx);
        for (int k = 0; k < 3; k++) idx[k] = d->weld[idx[k]];
    }
}

typedef struct edge_key {
    int lo, hi, tri, k;
} edge_key;

static int compare_edges(const void *pa, const void *pb)
{
    const edge_key *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return a->tri < b->tri ? -1 : a->tri > b->tri;
}

// Sort the edges by (lo, hi, tri) as compare_edges orders them: counted
// into buckets by lo (in their order), then each bucket sorted by insertion
// (a vertex has a few edges) or, for a vertex shared by many, by qsort. e
// is the input (n edges), out the result.
static void sort_edges(const edge_key *e, size_t n, int vertex_count, edge_key *out)
{
    size_t *start = (size_t *)dAlloc(((size_t)vertex_count + 1) * sizeof(size_t));
    memset(start, 0, ((size_t)vertex_count + 1) * sizeof(size_t));
    for (size_t i = 0; i < n; i++) start[e[i].lo + 1]++;
    for (int v = 0; v < vertex_count; v++) start[v + 1] += start[v];
    for (size_t i = 0; i < n; i++) out[start[e[i].lo]++] = e[i];
    // start[v] is now the end of bucket v.
    for (int v = 0; v < vertex_count; v++) {
        size_t lo = v > 0 ? start[v - 1] : 0, count = start[v] - lo;
        edge_key *b = out + lo;
        if (count > 32) {
            qsort(b, count, sizeof *b, compare_edges);
            continue;
        }
        for (size_t i = 1; i < count; i++) {
            edge_key x = b[i];
            size_t j = i;
            while (j > 0 && compare_edges(&b[j - 1], &x) > 0) {
                b[j] = b[j - 1];
                j--;
            }
            b[j] = x;
        }
    }
    dFree(start, ((size_t)vertex_count + 1) * sizeof(size_t));
}

// The vertices joined to each (welded) vertex by an edge, from the edges
// sorted by their ends (CSR: vertex_adj[vertex_first[v] .. vertex_first[v + 1])).
static void compute_vertex_adjacency(dxTriMeshData *d, const edge_key *e, size_t n)
{
    int *first = (int *)dAlloc(((size_t)d->vertex_count + 1) * sizeof(int));
    memset(first, 0, ((size_t)d->vertex_count + 1) * sizeof(int));
    int unique = 0;
    for (size_t i = 0; i < n; i++) {
        if (i > 0 && e[i].lo == e[i - 1].lo && e[i].hi == e[i - 1].hi) continue;
        if (e[i].lo == e[i].hi) continue;
        first[e[i].lo + 1]++;
        first[e[i].hi + 1]++;
        unique++;
    }
    for (int v = 0; v < d->vertex_count; v++) first[v + 1] += first[v];
    int *adj = (int *)dAlloc((size_t)(2 * unique) * sizeof(int) + sizeof(int));
    int *fill = (int *)dAlloc((size_t)d->vertex_count * sizeof(int));
    memcpy(fill, first, (size_t)d->vertex_count * sizeof(int));
    for (size_t i = 0; i < n; i++) {
        if (i > 0 && e[i].lo == e[i - 1].lo && e[i].hi == e[i - 1].hi) continue;
        if (e[i].lo == e[i].hi) continue;
        adj[fill[e[i].lo]++] = e[i].hi;
        adj[fill[e[i].hi]++] = e[i].lo;
    }
    dFree(fill, (size_t)d->vertex_count * sizeof(int));
    d->vertex_first = first;
    d->vertex_adj = adj;
    d->vertex_adj_count = 2 * unique;
}

// The corner of triangle uidx (welded indices) across the edge a-b: the
// last one that is neither end, or corner 0 if none is.
static int far_corner(const int uidx[3], int a, int b)
{
    int far = 0;
    for (int m = 0; m < 3; m++)
        if (uidx[m] != a && uidx[m] != b) far = m;
    return far;
}

// Neighbours across edges: two triangles sharing the (welded) vertices of
// an edge (an edge of more than two triangles has none), each such edge
// listed once in edges[] (in the order of its ends), the others in
// open_edges[]; and the vertices' neighbours. These depend on the weld
// and the indices only: an Update whose weld is the build's keeps them.
static void compute_neighbours(dxTriMeshData *d)
{
    size_t n = 3 * (size_t)d->tri_count;
    dxBigBlock unsorted_block = { 0 }, sorted_block = { 0 };   // big_block.h: large, written once
    edge_key *unsorted = (edge_key *)dxBigBlockAlloc(&unsorted_block, n * sizeof *unsorted);
    for (int t = 0; t < d->tri_count; t++) {
        const int *idx = d->welded + 3 * t;
        for (int k = 0; k < 3; k++) {
            int a = idx[k], b = idx[(k + 1) % 3];
            unsorted[3 * t + k] = (edge_key){ a < b ? a : b, a < b ? b : a, t, k };
            d->neighbour[3 * t + k] = -1;
        }
    }
    edge_key *e = (edge_key *)dxBigBlockAlloc(&sorted_block, n * sizeof *e);
    sort_edges(unsorted, n, d->vertex_count, e);
    dxBigBlockFree(&unsorted_block);
    clear_adjacency(d);
    for (int pass = 0; pass < 2; pass++) {   // count the shared edges, then list them
        int count = 0;
        for (size_t i = 0; i < n;) {
            size_t j = i + 1;
            while (j < n && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
            if (j - i == 2 && e[i].tri != e[i + 1].tri) {
                const edge_key *x = &e[i], *y = &e[i + 1];
                if (pass == 1) {
                    d->neighbour[3 * x->tri + x->k] = y->tri;
                    d->neighbour[3 * y->tri + y->k] = x->tri;
                    d->edges[count] = (dxTriMeshEdge){
                        x->tri, y->tri, (unsigned char)x->k, (unsigned char)y->k,
                        (unsigned char)far_corner(d->welded + 3 * x->tri, x->lo, x->hi),
                        (unsigned char)far_corner(d->welded + 3 * y->tri, x->lo, x->hi) };
                }
                count++;
            }
            i = j;
        }
        if (pass == 0) {
            d->edge_count = count;
            d->edges = (dxTriMeshEdge *)dAlloc((size_t)count * sizeof *d->edges +
                                               sizeof *d->edges);
        }
    }
    compute_vertex_adjacency(d, e, n);
    dxBigBlockFree(&sorted_block);
    d->closed = 1;
    for (int t = 0; t < d->tri_count; t++) {
        const int *u = d->neighbour + 3 * t;
        d->open_edges[t] = (unsigned char)((u[0] < 0) * DX_TRI_EDGE_FEATURE |
                                           (u[1] < 0) * (DX_TRI_EDGE_FEATURE << 1) |
                                           (u[2] < 0) * (DX_TRI_EDGE_FEATURE << 2));
        if (d->open_edges[t]) d->closed = 0;
    }
}

// A bit of features[] while they are derived: the triangle has no area.
enum { DEGENERATE = 0x80 };

// Mark the ends of triangle t's feature edges (bits) in mark[].
static inline void mark_edge_ends(const dxTriMeshData *d, int t, unsigned bits,
                                  unsigned char *mark)
{
    const int *idx = d->welded + 3 * t;
    if (bits & DX_TRI_EDGE_FEATURE) mark[idx[0]] = mark[idx[1]] = 1;
    if (bits & DX_TRI_EDGE_FEATURE << 1) mark[idx[1]] = mark[idx[2]] = 1;
    if (bits & DX_TRI_EDGE_FEATURE << 2) mark[idx[2]] = mark[idx[0]] = 1;
}

// Triangle t's normal has been found (unit, or none: 0): its features[]
// started with the edges without a neighbour, or all three and DEGENERATE
// for a triangle without area; those edges' ends marked in mark[].
static inline void start_features(dxTriMeshData *d, int t, int has_area, unsigned char *mark)
{
    const unsigned bits = has_area ? d->open_edges[t] : 7 * DX_TRI_EDGE_FEATURE;
    d->features[t] = (unsigned char)(has_area ? bits : DEGENERATE | bits);
    if (bits) mark_edge_ends(d, t, bits, mark);
}

// Triangle t's unit normal (zero without area): the cross product of the
// sides from corner 0, n = a x b, over its length, if that is above
// |a| |b| 1e-12 and finite; from the welded vertices (the triangle's own:
// they are at the same positions).
static void triangle_normal(dxTriMeshData *d, const dReal *pos, int t, unsigned char *mark)
{
    const int *idx = d->welded + 3 * t;
    const dReal *v0 = pos + 3 * idx[0], *v1 = pos + 3 * idx[1], *v2 = pos + 3 * idx[2];
    dVector3 a, b, n;
    dSubtractVectors3(a, v1, v0);
    dSubtractVectors3(b, v2, v0);
    dCalcVectorCross3(n, a, b);
    dReal len = dCalcVectorLength3(n);
    dReal scale = dCalcVectorLength3(a) * dCalcVectorLength3(b);
    dReal *out = d->normal + 3 * t;
    const int has_area = len > 0 && len > scale * (dReal)1e-12 && dxIsFinite(len);
    for (int k = 0; k < 3; k++) out[k] = has_area ? n[k] / len : 0;
    start_features(d, t, has_area, mark);
}

#if defined(__SSE2__) && !defined(dSINGLE)
// Triangles t and t + 1 as triangle_normal, one in each lane: the same
// operations in the same order, so the same bits (a lane without area
// computes 0 / 0 and is cleared).
static void triangle_normals2(dxTriMeshData *d, const dReal *pos, int t, unsigned char *mark)
{
    const int *i0 = d->welded + 3 * t, *i1 = i0 + 3;
    __m128d v[3][3];   // corner, axis; lane 0 triangle t, lane 1 t + 1
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++)
            v[c][k] = _mm_loadh_pd(_mm_load_sd(pos + 3 * i0[c] + k), pos + 3 * i1[c] + k);
    __m128d a[3], b[3];
    for (int k = 0; k < 3; k++) {
        a[k] = _mm_sub_pd(v[1][k], v[0][k]);
        b[k] = _mm_sub_pd(v[2][k], v[0][k]);
    }
    __m128d n0 = _mm_sub_pd(_mm_mul_pd(a[1], b[2]), _mm_mul_pd(a[2], b[1]));
    __m128d n1 = _mm_sub_pd(_mm_mul_pd(a[2], b[0]), _mm_mul_pd(a[0], b[2]));
    __m128d n2 = _mm_sub_pd(_mm_mul_pd(a[0], b[1]), _mm_mul_pd(a[1], b[0]));
    __m128d len = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(n0, n0), _mm_mul_pd(n1, n1)),
                                         _mm_mul_pd(n2, n2)));
    __m128d la = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(a[0], a[0]), _mm_mul_pd(a[1], a[1])),
                                        _mm_mul_pd(a[2], a[2])));
    __m128d lb = _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(b[0], b[0]), _mm_mul_pd(b[1], b[1])),
                                        _mm_mul_pd(b[2], b[2])));
    __m128d scale = _mm_mul_pd(la, lb);
    // len > 0, len > scale 1e-12 and finite (len is not negative: finite
    // is at most DBL_MAX; NaN fails every comparison).
    __m128d area = _mm_and_pd(_mm_cmpgt_pd(len, _mm_setzero_pd()),
                              _mm_and_pd(_mm_cmpgt_pd(len, _mm_mul_pd(scale, _mm_set1_pd(1e-12))),
                                         _mm_cmple_pd(len, _mm_set1_pd(DBL_MAX))));
    n0 = _mm_and_pd(_mm_div_pd(n0, len), area);
    n1 = _mm_and_pd(_mm_div_pd(n1, len), area);
    n2 = _mm_and_pd(_mm_div_pd(n2, len), area);
    dReal *out = d->normal + 3 * t;   // x y z of t, then of t + 1
    _mm_storeu_pd(out, _mm_unpacklo_pd(n0, n1));
    _mm_storeu_pd(out + 2, _mm_shuffle_pd(n2, n0, 2));
    _mm_storeu_pd(out + 4, _mm_unpackhi_pd(n1, n2));
    const int lanes = _mm_movemask_pd(area);
    start_features(d, t, lanes & 1, mark);
    start_features(d, t + 1, lanes >> 1, mark);
}
#endif

// Every triangle's normal (triangle_normal) and the start of its
// features (start_features); two at a time with SSE2 in double.
static void compute_normals(dxTriMeshData *d, const dReal *pos, unsigned char *mark)
{
    memset(mark, 0, (size_t)d->vertex_count);
    int t = 0;
#if defined(__SSE2__) && !defined(dSINGLE)
    for (; t + 2 <= d->tri_count; t += 2) triangle_normals2(d, pos, t, mark);
#endif
    for (; t < d->tri_count; t++) triangle_normal(d, pos, t, mark);
}

// Which edges and vertices are features (trimesh_internal.h): an edge is one
// if it has no neighbour (or either face has no area) or the neighbour's far
// vertex lies behind this face's plane (convex) with the faces not
// coplanar; a vertex is one if any edge of any triangle around it is
// (marked per welded vertex in mark[], begun by compute_normals). After
// compute_normals; one pass over the shared edges (each judged from both
// sides), one over the triangles: only the numbers are new.
static void compute_features(dxTriMeshData *d, const dReal *pos, unsigned char *mark)
{
    unsigned char *f = d->features;
    for (int i = 0; i < d->edge_count; i++) {
        const dxTriMeshEdge *e = &d->edges[i];
        const int t = e->t, u = e->u;
        if ((f[t] | f[u]) & DEGENERATE) {   // the ends are marked already
            f[t] |= (unsigned char)(DX_TRI_EDGE_FEATURE << e->kt);
            f[u] |= (unsigned char)(DX_TRI_EDGE_FEATURE << e->ku);
            continue;
        }
        const dReal *nt = d->normal + 3 * t, *nu = d->normal + 3 * u;
        if (dCalcVectorDot3(nt, nu) > FLAT_COS) continue;   // coplanar
        const int *it = d->welded + 3 * t, *iu = d->welded + 3 * u;
        dVector3 aw;
        dSubtractVectors3(aw, pos + 3 * iu[e->cu], pos + 3 * it[e->kt]);
        if (dCalcVectorDot3(nt, aw) < 0) {
            f[t] |= (unsigned char)(DX_TRI_EDGE_FEATURE << e->kt);
            mark[it[e->kt]] = mark[it[e->kt == 2 ? 0 : e->kt + 1]] = 1;
        }
        dSubtractVectors3(aw, pos + 3 * it[e->ct], pos + 3 * iu[e->ku]);
        if (dCalcVectorDot3(nu, aw) < 0) {
            f[u] |= (unsigned char)(DX_TRI_EDGE_FEATURE << e->ku);
            mark[iu[e->ku]] = mark[iu[e->ku == 2 ? 0 : e->ku + 1]] = 1;
        }
    }
    for (int t = 0; t < d->tri_count; t++) {
        const int *idx = d->welded + 3 * t;
        unsigned bits = f[t] & 7u * DX_TRI_EDGE_FEATURE;
        for (int k = 0; k < 3; k++) bits |= (unsigned)mark[idx[k]] * (DX_TRI_VERTEX_FEATURE << k);
        f[t] = (unsigned char)bits;
    }
}

// Everything derived from the arrays but the tree, from the positions in
// s: the weld and what follows from it (welded indices, neighbours, vertex
// adjacency) unless keep_topology (an Update whose weld is the build's),
// then the normals and features.
static void derive(dxTriMeshData *d, derive_scratch *s, int keep_topology)
{
    if (!keep_topology) {
        weld_positions(d, s, d->weld, 0);
        compute_welded(d);
        compute_neighbours(d);
    }
    compute_normals(d, s->pos, s->mark);
    compute_features(d, s->pos, s->mark);
}

// The builds' shared body: check everything, then derive (on bad input
// the data is left empty).
static void build_checked(const char *fn, dxTriMeshData *d, const void *vertices, int vertex_stride,
                  int vertex_count, int vertex_double, const void *indices, int index_count,
                  int tri_stride, const void *normals)
{
    clear_derived(d);
    size_t vsize = 3 * (vertex_double ? sizeof(double) : sizeof(float));
    derive_scratch s = { 0 };
#define BUILD_CHECK(cond, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(fn, __VA_ARGS__); \
            if (s.pos) scratch_free(&s, vertex_count); \
            clear_derived(d); \
            return; \
        } \
    } while (0)
    BUILD_CHECK(vertex_count >= 0 && index_count >= 0, "VertexCount (%d) or IndexCount (%d) < 0",
                vertex_count, index_count);
    BUILD_CHECK(index_count % 3 == 0, "IndexCount (%d) is not a multiple of 3", index_count);
    BUILD_CHECK(vertex_count == 0 || vertices != NULL, "Vertices is NULL");
    BUILD_CHECK(index_count == 0 || indices != NULL, "Indices is NULL");
    BUILD_CHECK(vertex_stride >= (int)vsize, "VertexStride (%d) is smaller than a vertex (%d)",
                vertex_stride, (int)vsize);
    BUILD_CHECK(tri_stride >= (int)(3 * sizeof(dTriIndex)),
                "TriStride (%d) is smaller than a triangle's 3 indices (%d)", tri_stride,
                (int)(3 * sizeof(dTriIndex)));
    d->vertices = vertices;
    d->vertex_stride = vertex_stride;
    d->vertex_count = vertex_count;
    d->vertex_double = vertex_double;
    d->indices = indices;
    d->tri_stride = tri_stride;
    int tris = index_count / 3;
    for (int t = 0; t < tris; t++) {
        dTriIndex v[3];
        memcpy(v, (const char *)indices + (size_t)t * (size_t)tri_stride, sizeof v);
        for (int k = 0; k < 3; k++)
            BUILD_CHECK(v[k] < (dTriIndex)vertex_count,
                        "index %d of triangle %d (%lu) is past the vertex count (%d)", k, t,
                        (unsigned long)v[k], vertex_count);
    }
    scratch_alloc(&s, vertex_count);
    int bad;
    BUILD_CHECK(load_positions(d, tris, s.pos, s.mark, &bad), "vertex %d is not finite", bad);
#undef BUILD_CHECK
    d->user_normals = normals;
    if (tris == 0) scratch_free(&s, vertex_count);
    DX_WARN_ARG(tris > 0, return, "the mesh has no triangles: it collides with nothing");
    d->tri_count = tris;
    size_t n = (size_t)tris;
    d->normal = (dReal *)dAlloc(3 * n * sizeof(dReal));
    d->neighbour = (int *)dAlloc(3 * n * sizeof(int));
    d->welded = (int *)dAlloc(3 * n * sizeof(int));
    d->open_edges = (unsigned char *)dAlloc(n);
    d->features = (unsigned char *)dAlloc(n);
    d->weld = (int *)dAlloc((size_t)vertex_count * sizeof(int));
    derive(d, &s, 0);
    scratch_free(&s, vertex_count);
    dxTriMeshBuildTree(d);
}

static void build(const char *fn, dxTriMeshData *d, const void *vertices, int vertex_stride,
                  int vertex_count, int vertex_double, const void *indices, int index_count,
                  int tri_stride, const void *normals)
{
    build_checked(fn, d, vertices, vertex_stride, vertex_count, vertex_double, indices,
                  index_count, tri_stride, normals);
    dxTriMeshDataChanged(d);
}

// ---- public API ----------------------------------------------------------------

dTriMeshDataID dGeomTriMeshDataCreate(void)
{
    dxTriMeshData *d = (dxTriMeshData *)dAlloc(sizeof *d);
    memset(d, 0, sizeof *d);
    d->magic = DX_MAGIC_TRIMESH_DATA;
    return d;
}

// Free the data now (no geom uses it any more).
void dxTriMeshDataFree(dxTriMeshData *d)
{
    clear_derived(d);
    d->magic = DX_MAGIC_TRIMESH_DATA_DEAD;
    dFree(d, sizeof *d);
}

void dGeomTriMeshDataDestroy(dTriMeshDataID g)
{
    CHECK_DATA(g, return);
    if (g->users > 0) g->destroy_pending = 1;
    else dxTriMeshDataFree(g);
}

void dGeomTriMeshDataBuildSingle1(dTriMeshDataID g, const void *Vertices, int VertexStride,
                                  int VertexCount, const void *Indices, int IndexCount,
                                  int TriStride, const void *Normals)
{
    CHECK_DATA(g, return);
    build(__func__, g, Vertices, VertexStride, VertexCount, 0, Indices, IndexCount, TriStride,
          Normals);
}

void dGeomTriMeshDataBuildSingle(dTriMeshDataID g, const void *Vertices, int VertexStride,
                                 int VertexCount, const void *Indices, int IndexCount,
                                 int TriStride)
{
    CHECK_DATA(g, return);
    build(__func__, g, Vertices, VertexStride, VertexCount, 0, Indices, IndexCount, TriStride,
          NULL);
}

void dGeomTriMeshDataBuildDouble1(dTriMeshDataID g, const void *Vertices, int VertexStride,
                                  int VertexCount, const void *Indices, int IndexCount,
                                  int TriStride, const void *Normals)
{
    CHECK_DATA(g, return);
    build(__func__, g, Vertices, VertexStride, VertexCount, 1, Indices, IndexCount, TriStride,
          Normals);
}

void dGeomTriMeshDataBuildDouble(dTriMeshDataID g, const void *Vertices, int VertexStride,
                                 int VertexCount, const void *Indices, int IndexCount,
                                 int TriStride)
{
    CHECK_DATA(g, return);
    build(__func__, g, Vertices, VertexStride, VertexCount, 1, Indices, IndexCount, TriStride,
          NULL);
}

void dGeomTriMeshDataBuildSimple1(dTriMeshDataID g, const dReal *Vertices, int VertexCount,
                                  const dTriIndex *Indices, int IndexCount, const int *Normals)
{
    CHECK_DATA(g, return);
#ifdef dSINGLE
    const int is_double = 0;
#else
    const int is_double = 1;
#endif
    build(__func__, g, Vertices, 4 * (int)sizeof(dReal), VertexCount, is_double, Indices,
          IndexCount, 3 * (int)sizeof(dTriIndex), Normals);
}

void dGeomTriMeshDataBuildSimple(dTriMeshDataID g, const dReal *Vertices, int VertexCount,
                                 const dTriIndex *Indices, int IndexCount)
{
    CHECK_DATA(g, return);
    dGeomTriMeshDataBuildSimple1(g, Vertices, VertexCount, Indices, IndexCount, NULL);
}

void dGeomTriMeshDataUpdate(dTriMeshDataID g)
{
    CHECK_DATA(g, return);
    derive_scratch s;
    scratch_alloc(&s, g->vertex_count);
    int bad;
    if (!load_positions(g, g->tri_count, s.pos, s.mark, &bad)) {
        scratch_free(&s, g->vertex_count);
        dxReportBadArgument(__func__, "vertex %d is not finite: the mesh is emptied", bad);
        clear_derived(g);
        dxTriMeshDataChanged(g);
        return;
    }
    const int kept = g->tri_count > 0 && weld_positions(g, &s, g->weld, 1);
    if (g->tri_count > 0) derive(g, &s, kept);
    scratch_free(&s, g->vertex_count);
    if (g->tri_count == 0) return;
    dxTriMeshRefitTree(g, kept);
    dxTriMeshDataChanged(g);
}

void dGeomTriMeshDataSet(dTriMeshDataID g, int data_id, void *in_data)
{
    CHECK_DATA(g, return);
    DX_CHECK_ARG(data_id >= dTRIMESHDATA__MIN && data_id < dTRIMESHDATA__MAX, return,
                 "data_id %d is not a dTRIMESHDATA_ value", data_id);
    if (data_id == dTRIMESHDATA_FACE_NORMALS) g->user_normals = in_data;
    else g->user_flags = (unsigned char *)in_data;
}

void *dGeomTriMeshDataGet2(dTriMeshDataID g, int data_id, dsizeint *pout_size)
{
    if (pout_size) *pout_size = 0;
    CHECK_DATA(g, return NULL);
    DX_CHECK_ARG(data_id >= dTRIMESHDATA__MIN && data_id < dTRIMESHDATA__MAX, return NULL,
                 "data_id %d is not a dTRIMESHDATA_ value", data_id);
    if (data_id == dTRIMESHDATA_FACE_NORMALS) return (void *)g->user_normals;
    unsigned char *flags = g->user_flags ? g->user_flags : g->built_flags;
    if (pout_size && flags) *pout_size = (dsizeint)g->tri_count;
    return flags;
}

void *dGeomTriMeshDataGet(dTriMeshDataID g, int data_id)
{
    return dGeomTriMeshDataGet2(g, data_id, NULL);
}

int dGeomTriMeshDataPreprocess2(dTriMeshDataID g, unsigned int buildRequestFlags,
                                const dintptr *requestExtraData)
{
    CHECK_DATA(g, return 0);
    DX_CHECK_ARG(buildRequestFlags < (1u << dTRIDATAPREPROCESS_BUILD__MAX), return 0,
                 "buildRequestFlags 0x%x has bits past dTRIDATAPREPROCESS_BUILD__MAX",
                 buildRequestFlags);
    if (requestExtraData && (buildRequestFlags & (1u << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES))) {
        dintptr e = requestExtraData[dTRIDATAPREPROCESS_BUILD_FACE_ANGLES];
        DX_CHECK_ARG(e >= dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__MIN &&
                         e < dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__MAX,
                     return 0, "face angle storage %ld is not a dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_ value",
                     (long)e);
    }
    // The face angles' information (which edges are convex, flat or
    // concave) is already in the features the colliders use.
    if ((buildRequestFlags & (1u << dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES)) && g->tri_count > 0) {
        if (!g->built_flags) g->built_flags = (unsigned char *)dAlloc((size_t)g->tri_count);
        memcpy(g->built_flags, g->features, (size_t)g->tri_count);
    }
    return 1;
}

int dGeomTriMeshDataPreprocess(dTriMeshDataID g)
{
    return dGeomTriMeshDataPreprocess2(g, 1u << dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES, NULL);
}

void dGeomTriMeshDataGetBuffer(dTriMeshDataID g, unsigned char **buf, int *bufLen)
{
    DX_CHECK_ARG(buf != NULL && bufLen != NULL, return, "buf or bufLen is NULL");
    dsizeint size = 0;
    *buf = (unsigned char *)dGeomTriMeshDataGet2(g, dTRIMESHDATA_USE_FLAGS, &size);
    *bufLen = (int)size;
}

void dGeomTriMeshDataSetBuffer(dTriMeshDataID g, unsigned char *buf)
{
    dGeomTriMeshDataSet(g, dTRIMESHDATA_USE_FLAGS, buf);
}
