// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_internal.h -- triangle mesh data (the user's arrays, read in place,
// and what is derived from them: face normals, edge features, a tree of
// boxes) and the trimesh geom, for trimesh_*.c and the native colliders.
// Everything here is in the mesh's own frame.

#ifndef DX_TRIMESH_INTERNAL_H
#define DX_TRIMESH_INTERNAL_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include <ode/collision_trimesh.h>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "big_block.h"
#include "geom_internal.h"

enum {
    DX_MAGIC_TRIMESH_DATA = 0x54726944u,   // "TriD"
    DX_MAGIC_TRIMESH_DATA_DEAD = 0xdead7e1du
};

// Per-triangle feature bits (same values as dMESHDATAUSE_*): edge k joins
// vertices k and k+1 (mod 3). A set bit means the edge or vertex is a real
// feature of the surface: on the border or convex. Edges between coplanar
// faces and concave edges are not, nor vertices with no such edge: the
// colliders leave contacts there to the neighbouring faces (no internal-edge
// bumps).
enum { DX_TRI_EDGE_FEATURE = 0x01, DX_TRI_VERTEX_FEATURE = 0x08 };

// The most triangles a leaf of a built tree holds (a heightfield's patch,
// a tree of one leaf without the leaf copy, may hold more).
enum { DX_TRI_LEAF_MAX = 4 };

// A node of the box tree: up to four children ("slots") with their boxes
// side by side per axis, so that a query or a ray tests the four at once
// (128 bytes: two cache lines, the nodes starting at a line's start).
// Slot s is a leaf of count[s] > 0
// triangles order[first[s] ..], an inner node (count 0) at nodes[first[s]],
// after this one, or unused (count -1; unused slots come last). The boxes
// are in float, rounded outwards: each contains the exact one. The tree is
// a median-split binary tree with levels lifted into their parents (see
// trimesh_tree.c): its leaves, their order and their boxes are the binary
// tree's.
// A leaf is named by node * 4 + slot (temporal coherence). Aligned to 16
// bytes wherever it is placed (a heightfield's patch holds one after its
// data): the rays load a node's fours as aligned vectors.
typedef struct dxTriMeshNode {
    float lo[3][4], hi[3][4];
    int first[4], count[4];
} __attribute__((aligned(16))) dxTriMeshNode;

// The next float from f towards -infinity (down) or +infinity (up):
// nextafterf's answers, inline (query boxes are rounded per query); f is
// not NaN, nor the infinity it would step towards.
static inline float dxFloatStep(float f, int up)
{
    if (f == 0) return up ? FLT_TRUE_MIN : -FLT_TRUE_MIN;
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    bits += (f > 0) == (up != 0) ? 1 : (uint32_t)-1;   // away from 0, or towards it
    memcpy(&f, &bits, sizeof f);
    return f;
}

// The float nearest x on the side of -infinity (below) or +infinity
// (above): the tree's boxes are rounded outwards with these, the queries'
// inwards. Without branches: the step is one unit of the bits away from
// zero or towards it by the sign bit, and a zero needs no case of its own,
// (float)x keeping x's sign (a negative x that rounds up to a zero gives
// -0, whose next bits are -FLT_TRUE_MIN; a positive one +0, whose next are
// FLT_TRUE_MIN); -infinity from below -FLT_MAX steps to -FLT_MAX, +infinity
// to FLT_MAX; a NaN compares false and stays.
static inline float dxFloatBelow(dReal x)
{
    float f = (float)x;
    int32_t bits;
    memcpy(&bits, &f, sizeof bits);
    bits -= f > x ? ((bits >> 31) | 1) : 0;   // down: +1 if negative, else -1
    memcpy(&f, &bits, sizeof f);
    return f;
}
static inline float dxFloatAbove(dReal x)
{
    float f = (float)x;
    int32_t bits;
    memcpy(&bits, &f, sizeof bits);
    bits += f < x ? ((bits >> 31) | 1) : 0;   // up: -1 if negative, else +1
    memcpy(&f, &bits, sizeof f);
    return f;
}

#if defined(__SSE2__) && !defined(dSINGLE)
// dxFloatAbove (up) or dxFloatBelow of x[0], x[1], x[2] in lanes 0-2 (lane
// 3: of 0), four at once: the same conversion, comparison and step of the
// bits per lane.
static inline __m128 dxFloatStep3(const double x[3], int up)
{
    const __m128d x01 = _mm_loadu_pd(x), x2 = _mm_load_sd(x + 2);
    const __m128 f = _mm_movelh_ps(_mm_cvtpd_ps(x01), _mm_cvtpd_ps(x2));
    const __m128d g01 = _mm_cvtps_pd(f), g2 = _mm_cvtps_pd(_mm_movehl_ps(f, f));
    // The lanes whose float is on the wrong side of x, as 32-bit masks.
    const __m128d w01 = up ? _mm_cmplt_pd(g01, x01) : _mm_cmpgt_pd(g01, x01);
    const __m128d w2 = up ? _mm_cmplt_pd(g2, x2) : _mm_cmpgt_pd(g2, x2);
    const __m128i wrong = _mm_castps_si128(
        _mm_shuffle_ps(_mm_castpd_ps(w01), _mm_castpd_ps(w2), _MM_SHUFFLE(2, 0, 2, 0)));
    // Up: +1 for a positive float, -1 for a negative one (down: the opposite).
    const __m128i bits = _mm_castps_si128(f);
    const __m128i step = _mm_and_si128(wrong, _mm_or_si128(_mm_srai_epi32(bits, 31),
                                                           _mm_set1_epi32(1)));
    return _mm_castsi128_ps(up ? _mm_add_epi32(bits, step) : _mm_sub_epi32(bits, step));
}
#endif

// The box [lo, hi] in floats rounded inwards: lo_f[k] = dxFloatAbove(lo[k]),
// hi_f[k] = dxFloatBelow(hi[k]) (lane 3 unused).
static inline void dxFloatBox(const dReal lo[3], const dReal hi[3], float lo_f[4], float hi_f[4])
{
#if defined(__SSE2__) && !defined(dSINGLE)
    _mm_storeu_ps(lo_f, dxFloatStep3(lo, 1));
    _mm_storeu_ps(hi_f, dxFloatStep3(hi, 0));
#else
    for (int k = 0; k < 3; k++) {
        lo_f[k] = dxFloatAbove(lo[k]);
        hi_f[k] = dxFloatBelow(hi[k]);
    }
    lo_f[3] = hi_f[3] = 0;
#endif
}

// Two neighbouring triangles whose unit normals' dot product is over this
// are coplanar: the edge between them is one of the triangulation only
// (ten times the native colliders' relative tolerance, DX_COLLIDE_EPS).
#ifdef dSINGLE
#define DX_TRI_COPLANAR_COS (1 - 10 * (dReal)1e-5)
#else
#define DX_TRI_COPLANAR_COS (1 - 10 * (dReal)1e-9)
#endif

// What the colliders' walk reads of the triangle at leaf position j beside
// its vertices, in leaf order (leaf_faces[j]), so that none of it waits for
// order[j] first, and all of it in one cache line: its box in float rounded
// outwards (lo, then hi: the walk's first test, which also reads the index
// after it as a float and lets it count for nothing), its index
// order[j], as bit k of coplanar whether it has a neighbour across edge k
// whose normal is within DX_TRI_COPLANAR_COS of its own (the geometry's
// part of "a flat edge"; the feature bits, which the user may set, are read
// where needed), its normal (a copy of normal[3 order[j]]) and, in the
// line's room left, where its neighbours' faces are: near[k] the leaf
// position of the neighbour across edge k less j, or DX_TRI_NEAR_NONE (no
// neighbour, or one farther than an int16_t reaches: ask the data). A
// sphere's edge contact reads the neighbour's normal there, in a line the
// walk has just read (the neighbour meets the sphere's box too), instead
// of its index and then its normal in the user's order.
enum { DX_TRI_NEAR_NONE = INT16_MIN };
typedef struct dxTriLeafFace {
    float box[6];
    int index;
    unsigned coplanar;
    dReal n[3];
    int16_t near[3];
} __attribute__((aligned(64))) dxTriLeafFace;

// Make node a tree of one leaf: the count triangles order[0 ..], in the box
// [lo, hi] (a heightfield's patch).
void dxTriMeshNodeSetLeaf(dxTriMeshNode *node, const dReal lo[3], const dReal hi[3], int count);

struct dxTriMesh;

// An edge shared by triangles t and u (neighbours): its index in each (kt,
// ku: edge k joins corners k and k + 1) and each one's corner off the edge
// (ct, cu). What an Update needs to judge the edge from both sides
// without looking the neighbours up again.
typedef struct dxTriMeshEdge {
    int t, u;
    unsigned char kt, ku, ct, cu;
} dxTriMeshEdge;

struct dxTriMeshData {
    uint32_t magic;
    // The user's arrays (not copied).
    const void *vertices;
    int vertex_stride, vertex_count, vertex_double;   // double or float coordinates
    const void *indices;
    int tri_stride, tri_count;
    const void *user_normals;             // dTRIMESHDATA_FACE_NORMALS
    unsigned char *user_flags;            // dTRIMESHDATA_USE_FLAGS set by the user
    // Derived (owned).
    dReal *normal;                        // 3 per triangle: unit, or 0 if degenerate
    int *weld;                            // per vertex: the first one at its position
    int *vertex_first, *vertex_adj;       // per welded vertex: the vertices joined to it
    int vertex_adj_count;
    int *neighbour;                       // 3 per triangle: across edge k, or -1
    int *welded;                          // 3 per triangle: its vertices welded
    unsigned char *open_edges;            // per triangle: the edges k without a
                                          // neighbour (DX_TRI_EDGE_FEATURE << k)
    struct dxTriMeshEdge *edges;          // the edges with two triangles, once
    int edge_count;
    int closed;                           // every edge has a neighbour
    unsigned char *features;              // DX_TRI_*_FEATURE bits per triangle
    dxTriMeshNode *nodes;                 // the box tree, root first
    int node_count;
    int *node_span;                       // 2 per node: its subtree's triangles
                                          // are order[first .. first + count)
                                          // (rays ask for a small one's early)
    dReal lo[3], hi[3];                   // the exact box of the triangles (with nodes)
    int *order;                           // triangles in leaf order
    dReal *leaf_vertices;                 // 9 per triangle in leaf order: the
                                          // vertices of order[j] at 9 j (rays)
    dxTriLeafFace *leaf_faces;            // 1 per triangle in leaf order
    dxBigBlock tree_block;                // one block holding nodes,
                                          // node_span, leaf_vertices and
                                          // leaf_faces, each at a cache line
                                          // (big_block.h, trimesh_tree.c)
    uint64_t tree_stamp;                  // unique per build and refit; 0: no
                                          // temporal coherence (a heightfield patch)
    unsigned char *built_flags;           // Preprocess: use flags
    void *face_angles;                    // Preprocess: angles per edge
    size_t face_angles_size;
    int users;                            // trimesh geoms using the data ...
    struct dxTriMesh *first_user;         // ... listed through next_user
    int destroy_pending;                  // destroyed while still used
};
typedef struct dxTriMeshData dxTriMeshData;

// A contact of a triangle before the reduction (mesh frame).
typedef struct dxTriMeshRaw {
    dReal pos[3], n[3], depth;   // n: the direction the other geom leaves along
    int tri, tri2;               // the triangle, and the other's (a trimesh) or -1
} dxTriMeshRaw;

typedef struct dxTriMesh {
    dxGeom g;
    dxTriMeshData *data;
    struct dxTriMesh *next_user;          // the next geom on the same data
    dTriCallback *callback;
    dTriArrayCallback *array_callback;
    dTriRayCallback *ray_callback;
    dTriTriMergeCallback *merge_callback;
    // How a sphere's contacts merge: dGeomColliderMergeContactsValue_None,
    // _Normals or _Full; 0 (a heightfield's shadow mesh) as other shapes'.
    int sphere_merge;
    unsigned tc_classes;                  // bit per class: temporal coherence on
    uint64_t tc_id;                       // names the geom's temporal-coherence
                                          // entries (new on ClearTCCache)
    dMatrix4 last_transform;
    int last_set;                         // SetLastTransform was called
} dxTriMesh;

extern const dxGeomClassOps dx_trimesh_ops;

static inline int dxTriMeshDataIsLive(const dxTriMeshData *d)
{
    return d != NULL && d->magic == DX_MAGIC_TRIMESH_DATA;
}

// The geometry of the data changed: every geom on it learns it (bounding
// box, backend caches).
void dxTriMeshDataChanged(dxTriMeshData *d);

// The feature bits the colliders use for triangle t: the user's
// dTRIMESHDATA_USE_FLAGS if set, else those computed with the data.
static inline unsigned dxTriMeshFeatures(const dxTriMeshData *d, int t)
{
    return d->user_flags ? d->user_flags[t] : d->features[t];
}

// Vertex i (0 <= i < vertex_count) in dReal (inline: loading triangles is
// the colliders' hot path).
static inline void dxTriMeshVertex(const dxTriMeshData *d, int i, dReal out[3])
{
    const char *p = (const char *)d->vertices + (size_t)i * (size_t)d->vertex_stride;
    if (d->vertex_double) {
        double v[3];
        memcpy(v, p, sizeof v);
        for (int k = 0; k < 3; k++) out[k] = (dReal)v[k];
    } else {
        float v[3];
        memcpy(v, p, sizeof v);
        for (int k = 0; k < 3; k++) out[k] = (dReal)v[k];
    }
}
// The three vertex indices of triangle t.
void dxTriMeshIndices(const dxTriMeshData *d, int t, int idx[3]);
// The three vertices of triangle t.
void dxTriMeshTriangle(const dxTriMeshData *d, int t, dReal v[3][3]);
// A triangle with a zero normal has no area and never collides.
static inline int dxTriMeshIsDegenerate(const dxTriMeshData *d, int t)
{
    const dReal *n = d->normal + 3 * t;
    return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

// ---- the tree's walk for a box (inline: the colliders walk in place) ----

typedef float dxTriF4 __attribute__((vector_size(16)));
typedef int dxTriI4 __attribute__((vector_size(16)));

// Bit s set for each used slot of node whose box overlaps the box
// [lo, hi] (floats, rounded inwards: see dxTriTreeWalk), the return value;
// bit s of *leaves for each leaf slot. The four slots at once.
static inline unsigned dxTriNodeOverlaps(const dxTriMeshNode *node, const float lo[3],
                                         const float hi[3], unsigned *leaves)
{
    dxTriI4 count;
    memcpy(&count, node->count, sizeof count);
    dxTriI4 m = count >= (dxTriI4){ 0, 0, 0, 0 };
    dxTriI4 leaf = count > (dxTriI4){ 0, 0, 0, 0 };
    for (int k = 0; k < 3; k++) {
        dxTriF4 qlo = { lo[k], lo[k], lo[k], lo[k] }, qhi = { hi[k], hi[k], hi[k], hi[k] };
        dxTriF4 slo, shi;
        memcpy(&slo, node->lo[k], sizeof slo);
        memcpy(&shi, node->hi[k], sizeof shi);
        m &= (slo <= qhi) & (shi >= qlo);
    }
#if defined(__SSE__)
    *leaves = (unsigned)_mm_movemask_ps((__m128)leaf);
    return (unsigned)_mm_movemask_ps((__m128)m);
#else
    *leaves = (unsigned)((leaf[0] & 1) | (leaf[1] & 2) | (leaf[2] & 4) | (leaf[3] & 8));
    return (unsigned)((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
}

// A walk of the tree for the leaves whose boxes overlap a query box. The
// box is kept as floats rounded inwards: a float box side x meets the
// exact one as it meets these (x <= hi exactly when x <= the float at or
// below hi), so the four slots are compared in float with the same
// outcome. Then the node being read with its overlapping slots not yet
// taken (m) and which of its slots are leaves; below it, the nodes left
// part way (their slots still to take in mask[]: bits 0-3 the slots, 4-7
// the leaves), the last left first out. A node is stacked once at most,
// when the walk goes down from it with slots left, so the stack holds
// at most the four-way depth (below 17 for 2^31 triangles).
enum { DX_TRI_WALK_STACK = 64 };
typedef struct dxTriTreeWalk {
    float lo[4], hi[4];   // (lane 3 unused)
    int node;
    unsigned m, leaves;
    int top;
    int stack[DX_TRI_WALK_STACK];
    unsigned char mask[DX_TRI_WALK_STACK];
} dxTriTreeWalk;

// Start a walk for the box whose floats (dxFloatBox) are lo_f, hi_f at
// the root (the tree must have nodes).
static inline void dxTriTreeWalkStartF(const dxTriMeshData *d, const float lo_f[3],
                                       const float hi_f[3], dxTriTreeWalk *w)
{
    for (int k = 0; k < 3; k++) {
        w->lo[k] = lo_f[k];
        w->hi[k] = hi_f[k];
    }
    w->top = 0;
    w->node = 0;
    w->m = dxTriNodeOverlaps(&d->nodes[0], w->lo, w->hi, &w->leaves);
}

// The next leaf (node * 4 + slot) whose box overlaps the query, in leaf
// order (a node's slots in order, each inner slot's subtree before the
// next slot), or -1 at the end.
static inline int dxTriTreeWalkNext(const dxTriMeshData *d, dxTriTreeWalk *w)
{
    for (;;) {
        while (w->m) {
            const int s = __builtin_ctz(w->m);
            w->m &= w->m - 1;
            if (w->leaves >> s & 1) return 4 * w->node + s;
            if (w->m) {
                w->stack[w->top] = w->node;
                w->mask[w->top++] = (unsigned char)(w->m | w->leaves << 4);
                // The node of the next inner slot left, where the walk
                // comes back to, asked for now: its lines arrive while the
                // walk goes down the first subtree.
                const unsigned inner = w->m & ~w->leaves;
                if (inner) {
                    const char *next =
                        (const char *)&d->nodes[d->nodes[w->node].first[__builtin_ctz(inner)]];
                    __builtin_prefetch(next);
                    __builtin_prefetch(next + 64);
                }
            }
            w->node = d->nodes[w->node].first[s];
            w->m = dxTriNodeOverlaps(&d->nodes[w->node], w->lo, w->hi, &w->leaves);
        }
        if (w->top == 0) return -1;
        w->top--;
        w->node = w->stack[w->top];
        w->m = w->mask[w->top] & 15u;
        w->leaves = (unsigned)w->mask[w->top] >> 4;
    }
}

// Every triangle whose box overlaps [lo, hi] (mesh frame) into *out (grown
// as needed, capacity *cap); returns the count.
int dxTriMeshQueryBox(const dxTriMeshData *d, const dReal lo[3], const dReal hi[3], int **out,
                      int *cap);
// The leaves (node * 4 + slot) whose box overlaps the box whose floats
// (dxFloatBox) are lo_f, hi_f, in the order dxTriMeshQueryBox lists their
// triangles, into leaf[]; returns the count, or -1 (stopping) if there are
// more than max.
int dxTriMeshQueryLeavesF(const dxTriMeshData *d, const float lo_f[3], const float hi_f[3],
                          int *leaf, int max);
// A number unique in the process, never 0 (tree stamps, tc_id).
uint64_t dxTriMeshNewStamp(void);
// Grow an int array to hold n.
void dxTriMeshReserveInts(int **a, int *cap, int n);

// The bounding box of the whole mesh in its frame (empty data: a point).
void dxTriMeshDataBounds(const dxTriMeshData *d, dReal lo[3], dReal hi[3]);

// A geom's world pose as the mesh frame of its collisions: p_mesh = R^T (p - pos)
// (inline: a ray's collision is short enough for the calls to count).
static inline void dxTriMeshDirToLocal(const dxGeom *mesh, const dReal v[3], dReal out[3])
{
    const dReal *R = mesh->R;
    for (int i = 0; i < 3; i++) out[i] = R[i] * v[0] + R[4 + i] * v[1] + R[8 + i] * v[2];
}
static inline void dxTriMeshToLocal(const dxGeom *mesh, const dReal p[3], dReal out[3])
{
    dReal d[3] = { p[0] - mesh->pos[0], p[1] - mesh->pos[1], p[2] - mesh->pos[2] };
    dxTriMeshDirToLocal(mesh, d, out);
}

#endif
