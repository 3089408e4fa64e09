// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_data.c -- dTriMeshDataID (guide 10.7.6): the builds over the
// user's strided arrays (checked, never copied), face normals, neighbours
// across edges and which edges and vertices are real features, the extra
// data (Set / Get / Preprocess) and Update.

#include <ode/memory.h>
#include <stdlib.h>
#include <string.h>

#include "trimesh_internal.h"

// Cosine above which two neighbouring faces count as coplanar.
#ifdef dSINGLE
#define FLAT_COS ((dReal)(1 - 1e-5))
#else
#define FLAT_COS ((dReal)(1 - 1e-8))
#endif

void dxTriMeshBuildTree(dxTriMeshData *d);   // trimesh_tree.c
void dxTriMeshRefitTree(dxTriMeshData *d);
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

// Free what was derived from the arrays (the data keeps no triangles).
static void clear_derived(dxTriMeshData *d)
{
    size_t n = (size_t)d->tri_count;
    if (n > 0) {
        dFree(d->normal, 3 * n * sizeof(dReal));
        dFree(d->neighbour, 3 * n * sizeof(int));
        dFree(d->features, n);
        dFree(d->order, n * sizeof(int));
        dxTriMeshFreeTree(d);
        if (d->built_flags) dFree(d->built_flags, n);
        dFree(d->weld, (size_t)d->vertex_count * sizeof(int));
        dFree(d->vertex_first, ((size_t)d->vertex_count + 1) * sizeof(int));
        dFree(d->vertex_adj, (size_t)d->vertex_adj_count * sizeof(int) + sizeof(int));
    }
    d->normal = NULL;
    d->neighbour = NULL;
    d->features = NULL;
    d->order = NULL;
    d->leaf_vertices = NULL;
    d->tree_stamp = 0;
    d->nodes = NULL;
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

// Unit face normals (zero for triangles without area).
static void compute_normals(dxTriMeshData *d)
{
    for (int t = 0; t < d->tri_count; t++) {
        dReal v[3][3];
        dxTriMeshTriangle(d, t, v);
        dVector3 a, b, n;
        dSubtractVectors3(a, v[1], v[0]);
        dSubtractVectors3(b, v[2], v[0]);
        dCalcVectorCross3(n, a, b);
        dReal len = dCalcVectorLength3(n);
        dReal scale = dCalcVectorLength3(a) * dCalcVectorLength3(b);
        dReal *out = d->normal + 3 * t;
        if (len > 0 && len > scale * (dReal)1e-12 && dxIsFinite(len)) {
            for (int k = 0; k < 3; k++) out[k] = n[k] / len;
        } else {
            out[0] = out[1] = out[2] = 0;
        }
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

typedef struct vertex_key {
    dReal p[3];
    int i;
} vertex_key;

static int compare_vertices(const void *pa, const void *pb)
{
    const vertex_key *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a->p[k] != b->p[k]) return a->p[k] < b->p[k] ? -1 : 1;
    return a->i < b->i ? -1 : a->i > b->i;
}

// weld[i]: the first vertex at exactly the position of vertex i, so that
// meshes with repeated vertices (per face, for normals or texture
// coordinates) still know their neighbours.
static void compute_weld(dxTriMeshData *d)
{
    size_t n = (size_t)d->vertex_count;
    vertex_key *v = (vertex_key *)dAlloc(n * sizeof *v);
    for (int i = 0; i < d->vertex_count; i++) {
        dxTriMeshVertex(d, i, v[i].p);
        v[i].i = i;
    }
    qsort(v, n, sizeof *v, compare_vertices);
    for (size_t i = 0; i < n; i++) {
        int same = i > 0 && v[i].p[0] == v[i - 1].p[0] && v[i].p[1] == v[i - 1].p[1] &&
                   v[i].p[2] == v[i - 1].p[2];
        d->weld[v[i].i] = same ? d->weld[v[i - 1].i] : v[i].i;
    }
    dFree(v, n * sizeof *v);
}

// The welded vertex indices of triangle t.
static void welded_indices(const dxTriMeshData *d, int t, int idx[3])
{
    dxTriMeshIndices(d, t, idx);
    for (int k = 0; k < 3; k++) idx[k] = d->weld[idx[k]];
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

// Neighbours across edges: two triangles sharing the (welded) vertices of
// an edge (an edge of more than two triangles has none); and the vertices'
// neighbours.
static void compute_neighbours(dxTriMeshData *d)
{
    size_t n = 3 * (size_t)d->tri_count;
    edge_key *unsorted = (edge_key *)dAlloc(n * sizeof *unsorted);
    for (int t = 0; t < d->tri_count; t++) {
        int idx[3];
        welded_indices(d, t, idx);
        for (int k = 0; k < 3; k++) {
            int a = idx[k], b = idx[(k + 1) % 3];
            unsorted[3 * t + k] = (edge_key){ a < b ? a : b, a < b ? b : a, t, k };
            d->neighbour[3 * t + k] = -1;
        }
    }
    edge_key *e = (edge_key *)dAlloc(n * sizeof *e);
    sort_edges(unsorted, n, d->vertex_count, e);
    dFree(unsorted, n * sizeof *unsorted);
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        if (j - i == 2 && e[i].tri != e[i + 1].tri) {
            d->neighbour[3 * e[i].tri + e[i].k] = e[i + 1].tri;
            d->neighbour[3 * e[i + 1].tri + e[i + 1].k] = e[i].tri;
        }
        i = j;
    }
    compute_vertex_adjacency(d, e, n);
    dFree(e, n * sizeof *e);
    d->closed = 1;
    for (size_t i = 0; i < n; i++)
        if (d->neighbour[i] < 0) d->closed = 0;
}

// Which edges and vertices are features (trimesh_internal.h): an edge is one
// if it has no neighbour (or either face has no area) or the neighbour's far
// vertex lies behind this face's plane (convex) with the faces not
// coplanar; a vertex is one if any edge of any triangle around it is.
static void compute_features(dxTriMeshData *d)
{
    unsigned char *vertex_feature = (unsigned char *)dAlloc((size_t)d->vertex_count + 1);
    memset(vertex_feature, 0, (size_t)d->vertex_count + 1);
    for (int t = 0; t < d->tri_count; t++) {
        int idx[3];
        welded_indices(d, t, idx);
        const dReal *n = d->normal + 3 * t;
        unsigned char f = 0;
        for (int k = 0; k < 3; k++) {
            int u = d->neighbour[3 * t + k], is_feature = 1;
            if (u >= 0 && !dxTriMeshIsDegenerate(d, t) && !dxTriMeshIsDegenerate(d, u)) {
                const dReal *nu = d->normal + 3 * u;
                int uidx[3];
                welded_indices(d, u, uidx);
                int far = uidx[0];
                for (int m = 0; m < 3; m++)
                    if (uidx[m] != idx[k] && uidx[m] != idx[(k + 1) % 3]) far = uidx[m];
                dReal a[3], w[3];
                dxTriMeshVertex(d, idx[k], a);
                dxTriMeshVertex(d, far, w);
                dVector3 aw;
                dSubtractVectors3(aw, w, a);
                int flat = dCalcVectorDot3(n, nu) > FLAT_COS;
                is_feature = !flat && dCalcVectorDot3(n, aw) < 0;
            }
            if (is_feature) {
                f |= (unsigned char)(DX_TRI_EDGE_FEATURE << k);
                vertex_feature[idx[k]] = vertex_feature[idx[(k + 1) % 3]] = 1;
            }
        }
        d->features[t] = f;
    }
    for (int t = 0; t < d->tri_count; t++) {
        int idx[3];
        welded_indices(d, t, idx);
        for (int k = 0; k < 3; k++)
            if (vertex_feature[idx[k]]) d->features[t] |= (unsigned char)(DX_TRI_VERTEX_FEATURE << k);
    }
    dFree(vertex_feature, (size_t)d->vertex_count + 1);
}

// Every vertex finite: 1, else 0 with the first bad index in *bad.
static int vertices_finite(const dxTriMeshData *d, int *bad)
{
    for (int i = 0; i < d->vertex_count; i++) {
        dReal v[3];
        dxTriMeshVertex(d, i, v);
        if (!dxIsFinite3(v[0], v[1], v[2])) {
            *bad = i;
            return 0;
        }
    }
    return 1;
}

// The builds' shared body: check everything, then derive (on bad input
// the data is left empty).
static void build_checked(const char *fn, dxTriMeshData *d, const void *vertices, int vertex_stride,
                  int vertex_count, int vertex_double, const void *indices, int index_count,
                  int tri_stride, const void *normals)
{
    clear_derived(d);
    size_t vsize = 3 * (vertex_double ? sizeof(double) : sizeof(float));
#define BUILD_CHECK(cond, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(fn, __VA_ARGS__); \
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
    int bad;
    BUILD_CHECK(vertices_finite(d, &bad), "vertex %d is not finite", bad);
    int tris = index_count / 3;
    for (int t = 0; t < tris; t++) {
        dTriIndex v[3];
        memcpy(v, (const char *)indices + (size_t)t * (size_t)tri_stride, sizeof v);
        for (int k = 0; k < 3; k++)
            BUILD_CHECK(v[k] < (dTriIndex)vertex_count,
                        "index %d of triangle %d (%lu) is past the vertex count (%d)", k, t,
                        (unsigned long)v[k], vertex_count);
    }
#undef BUILD_CHECK
    d->user_normals = normals;
    DX_WARN_ARG(tris > 0, return, "the mesh has no triangles: it collides with nothing");
    d->tri_count = tris;
    size_t n = (size_t)tris;
    d->normal = (dReal *)dAlloc(3 * n * sizeof(dReal));
    d->neighbour = (int *)dAlloc(3 * n * sizeof(int));
    d->features = (unsigned char *)dAlloc(n);
    d->weld = (int *)dAlloc((size_t)vertex_count * sizeof(int));
    compute_normals(d);
    compute_weld(d);
    compute_neighbours(d);
    compute_features(d);
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
    int bad;
    if (!vertices_finite(g, &bad)) {
        dxReportBadArgument(__func__, "vertex %d is not finite: the mesh is emptied", bad);
        clear_derived(g);
        dxTriMeshDataChanged(g);
        return;
    }
    if (g->tri_count == 0) return;
    compute_normals(g);
    compute_features(g);
    dxTriMeshRefitTree(g);
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
