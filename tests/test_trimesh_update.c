// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_update.c -- dGeomTriMeshDataUpdate derives exactly what a
// fresh build derives (white box): after random deformations of a shared
// grid, of a closed mesh made of separate triangles (welded by position)
// and of float vertices, every derived number of the updated data (face
// normals, feature bits, neighbours, shared edges, weld, vertex adjacency,
// the whole-mesh box) is bit for bit that of a data object built from the
// same arrays, the normals and feature bits also what their rule says
// (worked out by brute force); and the updated tree's boxes are the float
// boxes around exactly the triangles below them.
// The deformations include moves that keep coinciding vertices together,
// moves that part them, vertices brought onto others, triangles collapsed
// to a line, flat stretches (coplanar neighbours) and moves of a few
// vertices only.

#include "test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../libodecollide/trimesh_internal.h"

#define RNG_SEED 0x9e3779b97f4a7c15ull
#include "xorshift.h"

// A mesh's arrays: vertices in double or float (3 a vertex), indices.
typedef struct mesh {
    double *v;
    float *vf;   // the float copy, when the data reads floats
    dTriIndex *idx;
    int nv, nt, use_float;
} mesh;

static void build_on(dTriMeshDataID data, const mesh *m)
{
    if (m->use_float) {
        for (int i = 0; i < 3 * m->nv; i++) m->vf[i] = (float)m->v[i];
        dGeomTriMeshDataBuildSingle(data, m->vf, 3 * sizeof(float), m->nv, m->idx, 3 * m->nt,
                                    3 * sizeof(dTriIndex));
    } else {
        dGeomTriMeshDataBuildDouble(data, m->v, 3 * sizeof(double), m->nv, m->idx, 3 * m->nt,
                                    3 * sizeof(dTriIndex));
    }
}

// The arrays moved: the float copy follows the doubles.
static void sync(mesh *m)
{
    if (m->use_float)
        for (int i = 0; i < 3 * m->nv; i++) m->vf[i] = (float)m->v[i];
}

static void mesh_alloc(mesh *m, int nv, int nt, int use_float)
{
    m->nv = nv;
    m->nt = nt;
    m->use_float = use_float;
    m->v = calloc(3 * (size_t)nv, sizeof(double));
    m->vf = calloc(3 * (size_t)nv, sizeof(float));
    m->idx = calloc(3 * (size_t)nt, sizeof(dTriIndex));
}

static void mesh_free(mesh *m)
{
    free(m->v);
    free(m->vf);
    free(m->idx);
}

// An n x n-cell grid on integer coordinates (z = 0), vertices shared.
static void make_grid(mesh *m, int n, int use_float)
{
    mesh_alloc(m, (n + 1) * (n + 1), 2 * n * n, use_float);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double *p = m->v + 3 * (j * (n + 1) + i);
            p[0] = i;
            p[1] = j;
            p[2] = 0;
        }
    int t = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            dTriIndex a = (dTriIndex)(j * (n + 1) + i), b = a + 1, c = a + (dTriIndex)(n + 1),
                      d = c + 1;
            dTriIndex tris[2][3] = { { a, b, d }, { a, d, c } };
            for (int k = 0; k < 2; k++, t++) memcpy(m->idx + 3 * t, tris[k], sizeof tris[k]);
        }
}

// A closed octahedron cut into 4^level triangles per face, each triangle
// with its own three vertices (the mesh is closed only once welded).
static void make_split_octahedron(mesh *m, int level)
{
    int per_face = 1 << (2 * level), nt = 8 * per_face;
    mesh_alloc(m, 3 * nt, nt, 0);
    static const double corner[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 },
                                         { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    static const int face[8][3] = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
                                    { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
    int n = 1 << level, t = 0;
    for (int f = 0; f < 8; f++) {
        const double *A = corner[face[f][0]], *B = corner[face[f][1]], *C = corner[face[f][2]];
        // Barycentric lattice point (i, j) of the face: A + i/n (B - A) + j/n (C - A).
        for (int i = 0; i < n; i++)
            for (int j = 0; i + j < n; j++) {
                int tri[2][3][2] = { { { i, j }, { i + 1, j }, { i, j + 1 } },
                                     { { i + 1, j }, { i + 1, j + 1 }, { i, j + 1 } } };
                for (int h = 0; h < (i + j + 1 < n ? 2 : 1); h++, t++)
                    for (int k = 0; k < 3; k++) {
                        double *p = m->v + 3 * (3 * t + k);
                        for (int c = 0; c < 3; c++)
                            p[c] = A[c] + (B[c] - A[c]) * tri[h][k][0] / n +
                                   (C[c] - A[c]) * tri[h][k][1] / n;
                        m->idx[3 * t + k] = (dTriIndex)(3 * t + k);
                    }
            }
    }
}

// ---- the comparison -----------------------------------------------------------

static int same_ints(const int *a, const int *b, int n)
{
    return n == 0 || memcmp(a, b, (size_t)n * sizeof(int)) == 0;
}

// Every derived number of a (updated) equals b's (fresh).
static int check_same_derived(const dxTriMeshData *a, const dxTriMeshData *b)
{
    CHECK(a->tri_count == b->tri_count && a->vertex_count == b->vertex_count);
    int n = a->tri_count;
    CHECK(memcmp(a->normal, b->normal, 3 * (size_t)n * sizeof(dReal)) == 0);
    CHECK(memcmp(a->features, b->features, (size_t)n) == 0);
    CHECK(same_ints(a->neighbour, b->neighbour, 3 * n));
    CHECK(same_ints(a->welded, b->welded, 3 * n));
    CHECK(memcmp(a->open_edges, b->open_edges, (size_t)n) == 0);
    CHECK(same_ints(a->weld, b->weld, a->vertex_count));
    CHECK(a->closed == b->closed);
    CHECK(a->edge_count == b->edge_count);
    for (int i = 0; i < a->edge_count; i++) {
        const dxTriMeshEdge *x = &a->edges[i], *y = &b->edges[i];
        CHECK(x->t == y->t && x->u == y->u && x->kt == y->kt && x->ku == y->ku &&
              x->ct == y->ct && x->cu == y->cu);
    }
    CHECK(same_ints(a->vertex_first, b->vertex_first, a->vertex_count + 1));
    CHECK(a->vertex_adj_count == b->vertex_adj_count);
    CHECK(same_ints(a->vertex_adj, b->vertex_adj, a->vertex_adj_count));
    for (int k = 0; k < 3; k++) CHECK(a->lo[k] == b->lo[k] && a->hi[k] == b->hi[k]);
    return 0;
}

// The exact box of tree node i's triangles into lo, hi; 1 if every slot's
// float box, and every triangle's (leaf_faces' box), is the one around the exact
// box (rounded outwards).
static int node_boxes_exact(const dxTriMeshData *d, int i, dReal lo[3], dReal hi[3])
{
    const dxTriMeshNode *node = &d->nodes[i];
    for (int k = 0; k < 3; k++) {
        lo[k] = dInfinity;
        hi[k] = -dInfinity;
    }
    for (int s = 0; s < 4 && node->count[s] >= 0; s++) {
        dReal slo[3] = { dInfinity, dInfinity, dInfinity };
        dReal shi[3] = { -dInfinity, -dInfinity, -dInfinity };
        if (node->count[s] > 0) {
            for (int j = node->first[s]; j < node->first[s] + node->count[s]; j++) {
                dReal v[3][3], tlo[3], thi[3];
                dxTriMeshTriangle(d, d->order[j], v);
                for (int k = 0; k < 3; k++) {
                    tlo[k] = fmin(v[0][k], fmin(v[1][k], v[2][k]));
                    thi[k] = fmax(v[0][k], fmax(v[1][k], v[2][k]));
                    slo[k] = fmin(slo[k], tlo[k]);
                    shi[k] = fmax(shi[k], thi[k]);
                    // the triangle's own float box (the walk's first test)
                    if (d->leaf_faces[j].box[k] != dxFloatBelow(tlo[k]) ||
                        d->leaf_faces[j].box[3 + k] != dxFloatAbove(thi[k]))
                        return 0;
                }
            }
        } else if (!node_boxes_exact(d, node->first[s], slo, shi)) {
            return 0;
        }
        for (int k = 0; k < 3; k++) {
            if (node->lo[k][s] != dxFloatBelow(slo[k]) || node->hi[k][s] != dxFloatAbove(shi[k]))
                return 0;
            lo[k] = fmin(lo[k], slo[k]);
            hi[k] = fmax(hi[k], shi[k]);
        }
    }
    return 1;
}

// The tree of d fits the current vertices exactly (its nodes' boxes; how
// the leaves' own copy of the vertices is laid out is the tree's affair,
// and test_trimesh_tree.c's).
static int check_tree_fits(const dxTriMeshData *d)
{
    dReal lo[3], hi[3];
    CHECK(node_boxes_exact(d, 0, lo, hi));
    for (int k = 0; k < 3; k++) CHECK(lo[k] == d->lo[k] && hi[k] == d->hi[k]);
    return 0;
}

// The walk's leaf-order faces of d are the current ones: at leaf position
// j the index order[j], that triangle's normal bit for bit, bit k of
// coplanar set exactly when it has a neighbour across edge k whose normal's
// dot product with its own is over DX_TRI_COPLANAR_COS, and near[k] that
// neighbour's face (its leaf position less j; none without a neighbour).
// *near_faces counts the neighbours found through near[].
static int check_leaf_faces(const dxTriMeshData *d, int *near_faces)
{
    for (int j = 0; j < d->tri_count; j++) {
        const dxTriLeafFace *f = &d->leaf_faces[j];
        const int t = d->order[j];
        CHECK(f->index == t);
        CHECK(memcmp(f->n, d->normal + 3 * t, sizeof f->n) == 0);
        unsigned bits = 0;
        for (int k = 0; k < 3; k++) {
            const int u = d->neighbour[3 * t + k];
            const dReal *a = d->normal + 3 * t, *b = u >= 0 ? d->normal + 3 * u : NULL;
            if (b && a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > DX_TRI_COPLANAR_COS)
                bits |= 1u << k;
            if (f->near[k] == DX_TRI_NEAR_NONE) continue;
            CHECK(u >= 0 && j + f->near[k] >= 0 && j + f->near[k] < d->tri_count);
            CHECK(f[f->near[k]].index == u);
            ++*near_faces;
        }
        CHECK(f->coplanar == bits);
    }
    return 0;
}

// Cosine above which neighbouring faces are coplanar (trimesh_data.c's).
#ifdef dSINGLE
#define FLAT_COS ((dReal)(1 - 1e-5))
#else
#define FLAT_COS ((dReal)(1 - 1e-8))
#endif

// The normals and feature bits of d against the rule, worked out by brute
// force (every pair of vertices compared for the weld, every triangle
// searched for the neighbour): a normal is the cross product of the sides
// from corner 0 over its length, to the bit (or 0 if that length is not
// above 1e-12 times the sides' lengths' product); an edge is a feature
// unless exactly one other triangle has it, both have area and the
// other's far corner lies on or over this face's plane or the faces are
// coplanar; a vertex is one if an edge of a triangle at it is.
static int check_features_by_rule(const dxTriMeshData *d)
{
    int nv = d->vertex_count, nt = d->tri_count;
    int *w = malloc((size_t)nv * sizeof(int)), *tw = malloc(3 * (size_t)nt * sizeof(int));
    unsigned char *vf = calloc((size_t)nv, 1), *ef = calloc((size_t)nt, 1);
    for (int i = 0; i < nv; i++) {
        dReal p[3], q[3];
        dxTriMeshVertex(d, i, p);
        w[i] = i;
        for (int j = 0; j < i && w[i] == i; j++) {
            dxTriMeshVertex(d, j, q);
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) w[i] = j;
        }
    }
    int fail = 0;
    for (int t = 0; t < nt && !fail; t++) {
        int idx[3];
        dxTriMeshIndices(d, t, idx);
        for (int k = 0; k < 3; k++) tw[3 * t + k] = w[idx[k]];
        dReal v[3][3], a[3], b[3], n[3];
        dxTriMeshTriangle(d, t, v);
        for (int k = 0; k < 3; k++) {
            a[k] = v[1][k] - v[0][k];
            b[k] = v[2][k] - v[0][k];
        }
        dCalcVectorCross3(n, a, b);
        dReal len = dCalcVectorLength3(n);
        dReal scale = dCalcVectorLength3(a) * dCalcVectorLength3(b);
        int has_area = len > 0 && len > scale * (dReal)1e-12 && isfinite(len);
        const dReal *dn = d->normal + 3 * t;
        fail |= dxTriMeshIsDegenerate(d, t) == has_area;
        for (int k = 0; k < 3 && has_area; k++) fail |= dn[k] != n[k] / len;   // the same bits
    }
    for (int t = 0; t < nt && !fail; t++)
        for (int k = 0; k < 3; k++) {
            int ea = tw[3 * t + k], eb = tw[3 * t + (k + 1) % 3], uses = 0, u = -1;
            for (int x = 0; x < nt; x++)
                for (int m = 0; m < 3; m++) {
                    int xa = tw[3 * x + m], xb = tw[3 * x + (m + 1) % 3];
                    if ((xa == ea && xb == eb) || (xa == eb && xb == ea)) {
                        uses++;
                        if (x != t) u = x;
                    }
                }
            int feature = 1;
            if (uses == 2 && u >= 0 && !dxTriMeshIsDegenerate(d, t) &&
                !dxTriMeshIsDegenerate(d, u)) {
                int far = tw[3 * u];
                for (int m = 0; m < 3; m++)
                    if (tw[3 * u + m] != ea && tw[3 * u + m] != eb) far = tw[3 * u + m];
                dReal pa[3], pf[3], aw[3];
                dxTriMeshVertex(d, ea, pa);
                dxTriMeshVertex(d, far, pf);
                for (int c = 0; c < 3; c++) aw[c] = pf[c] - pa[c];
                const dReal *nt_ = d->normal + 3 * t, *nu = d->normal + 3 * u;
                feature = !(dCalcVectorDot3(nt_, nu) > FLAT_COS) && dCalcVectorDot3(nt_, aw) < 0;
            }
            if (feature) {
                ef[t] |= (unsigned char)(DX_TRI_EDGE_FEATURE << k);
                vf[ea] = vf[eb] = 1;
            }
        }
    for (int t = 0; t < nt && !fail; t++) {
        unsigned f = ef[t];
        for (int k = 0; k < 3; k++)
            if (vf[tw[3 * t + k]]) f |= DX_TRI_VERTEX_FEATURE << k;
        fail |= d->features[t] != f;
    }
    free(w);
    free(tw);
    free(vf);
    free(ef);
    CHECK(!fail);
    return 0;
}

// Update data (on m) and compare it with a fresh build of m.
static int check_update(dTriMeshDataID data, mesh *m)
{
    sync(m);
    dGeomTriMeshDataUpdate(data);
    dTriMeshDataID fresh = dGeomTriMeshDataCreate();
    build_on(fresh, m);
    int near_faces = 0;
    int fail = check_same_derived(data, fresh) || check_tree_fits(data) ||
               check_leaf_faces(data, &near_faces) || check_features_by_rule(data);
    dGeomTriMeshDataDestroy(fresh);
    if (fail) return fail;
    // An int16_t reaches every leaf position of these meshes: every
    // neighbour is found through near[].
    int neighbours = 0;
    for (int i = 0; i < 3 * data->tri_count; i++) neighbours += data->neighbour[i] >= 0;
    CHECK(data->tri_count <= INT16_MAX && near_faces == neighbours);
    return 0;
}

// Feature bits of every kind occur in data (the comparisons are not
// between empty sets): flat and convex edges, feature and plain vertices.
static int check_features_varied(const dxTriMeshData *d)
{
    int edge = 0, plain_edge = 0, vertex = 0, plain_vertex = 0;
    for (int t = 0; t < d->tri_count; t++)
        for (int k = 0; k < 3; k++) {
            if (d->features[t] & (DX_TRI_EDGE_FEATURE << k)) edge++;
            else plain_edge++;
            if (d->features[t] & (DX_TRI_VERTEX_FEATURE << k)) vertex++;
            else plain_vertex++;
        }
    CHECK(edge > 0 && plain_edge > 0 && vertex > 0 && plain_vertex > 0);
    return 0;
}

// ---- the cases -------------------------------------------------------------------

// A shared grid: every vertex jittered, then flat stretches, a few moved,
// and the whole surface a wave; in double and float vertices.
static int test_update_grid_matches_fresh_build(void)
{
    for (int use_float = 0; use_float < 2; use_float++) {
        mesh m;
        make_grid(&m, 14, use_float);
        dTriMeshDataID data = dGeomTriMeshDataCreate();
        build_on(data, &m);
        for (int round = 0; round < 24; round++) {
            switch (round % 4) {
            case 0:   // every vertex jittered
                for (int i = 0; i < m.nv; i++)
                    for (int k = 0; k < 3; k++) m.v[3 * i + k] += rnd(-0.2, 0.2);
                break;
            case 1:   // back on the integer grid, half of it flat, half a ridge
                for (int i = 0; i < m.nv; i++) {
                    double *p = m.v + 3 * i;
                    p[0] = i % 15;
                    p[1] = i / 15;
                    p[2] = p[0] < 7 ? 0 : (p[0] - 7) * (round % 8 == 1 ? 1 : -1);
                }
                break;
            case 2:   // a few vertices moved
                for (int n = 0; n < 5; n++) m.v[3 * (int)rnd(0, m.nv) + 2] += rnd(-1, 1);
                break;
            default:   // a wave
                for (int i = 0; i < m.nv; i++) {
                    double *p = m.v + 3 * i;
                    p[2] = 0.8 * sin(0.7 * p[0] + round) * cos(0.4 * p[1]);
                }
            }
            CHECK(check_update(data, &m) == 0);
            if (round % 4 == 3) CHECK(check_features_varied(data) == 0);
        }
        dGeomTriMeshDataDestroy(data);
        mesh_free(&m);
    }
    return 0;
}

static int accept_all(dGeomID mesh, dGeomID other, int tri)
{
    (void)mesh;
    (void)other;
    (void)tri;
    return 1;
}

// A sphere just over edge k of the triangle at leaf position j (off the
// triangle across it, so that its closest point there is on the edge)
// collided with mesh through the walk and through the per-triangle
// callback's path (whose triangles carry no face: the data is asked): the
// same contacts, bit for bit. *touched counts the collisions with contacts.
static int edge_contacts_agree(const dxTriMeshData *d, dGeomID mesh, dGeomID ball, int j, int k,
                               int *touched)
{
    const dReal *v = d->leaf_vertices + 9 * j, *n = d->leaf_faces[j].n;
    const dReal *a = v + 3 * k, *b = v + 3 * ((k + 1) % 3), *c = v + 3 * ((k + 2) % 3);
    dReal e[3], out[3], len = 0;
    for (int i = 0; i < 3; i++) e[i] = b[i] - a[i];
    dCalcVectorCross3(out, e, n);   // in the plane, across the edge
    if (dCalcVectorDot3(out, c) > dCalcVectorDot3(out, a)) dScaleVector3(out, -1);
    len = dCalcVectorLength3(out);
    dVector3 p;
    for (int i = 0; i < 3; i++) p[i] = (a[i] + b[i]) / 2 + 0.05 * out[i] / len + 0.3 * n[i];
    dGeomSetPosition(ball, p[0], p[1], p[2]);
    dContactGeom c0[8], c1[8];
    memset(c0, 0, sizeof c0);
    memset(c1, 0, sizeof c1);
    dGeomTriMeshSetCallback(mesh, NULL);
    const int n0 = dCollide(mesh, ball, 8, c0, sizeof c0[0]);
    dGeomTriMeshSetCallback(mesh, accept_all);
    const int n1 = dCollide(mesh, ball, 8, c1, sizeof c1[0]);
    CHECK(n0 == n1 && memcmp(c0, c1, (size_t)n0 * sizeof c0[0]) == 0);
    *touched += n0 > 0;
    return 0;
}

// A grid of more triangles than an int16_t counts: the faces' near[] hold
// the neighbours within its reach and leave the farther ones (in leaf
// order) to the data, and an Update keeps them; a sphere over an edge
// whose neighbour is far has the contacts of the data's path.
static int test_far_neighbours_left_to_the_data(void)
{
    mesh m;
    make_grid(&m, 260, 0);
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    build_on(data, &m);
    const dxTriMeshData *d = (const dxTriMeshData *)data;
    CHECK(d->tri_count > 32768);
    int near_faces = 0, far = 0;
    CHECK(check_leaf_faces(d, &near_faces) == 0);
    for (int j = 0; j < d->tri_count; j++)
        for (int k = 0; k < 3; k++)
            far += d->leaf_faces[j].near[k] == DX_TRI_NEAR_NONE &&
                   d->neighbour[3 * d->order[j] + k] >= 0;
    CHECK(near_faces > 0 && far > 0);
    for (int i = 0; i < m.nv; i++) m.v[3 * i + 2] = 0.3 * sin(0.5 * m.v[3 * i]);
    dGeomTriMeshDataUpdate(data);
    int near_after = 0;
    CHECK(check_leaf_faces(d, &near_after) == 0 && near_after == near_faces);
    dGeomID mesh = dCreateTriMesh(0, data, NULL, NULL, NULL);
    dGeomID ball = dCreateSphere(0, 0.4);
    int touched = 0;
    for (int j = 0; j < d->tri_count; j++)
        for (int k = 0; k < 3; k++)
            if (d->leaf_faces[j].near[k] == DX_TRI_NEAR_NONE &&
                d->neighbour[3 * d->order[j] + k] >= 0)
                CHECK(edge_contacts_agree(d, mesh, ball, j, k, &touched) == 0);
    CHECK(touched > 0);
    dGeomDestroy(ball);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(data);
    mesh_free(&m);
    return 0;
}

// A closed mesh of separate triangles: moves by position (the coinciding
// vertices stay together: the build's neighbours hold), moves per vertex
// (they part: the mesh falls apart into single triangles), and back
// together.
static int test_update_welded_mesh_matches_fresh_build(void)
{
    mesh m;
    make_split_octahedron(&m, 2);
    double *rest = malloc(3 * (size_t)m.nv * sizeof(double));
    memcpy(rest, m.v, 3 * (size_t)m.nv * sizeof(double));
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    build_on(data, &m);
    CHECK(data->closed);
    for (int round = 0; round < 12; round++) {
        if (round % 3 == 1) {   // every copy of a vertex on its own
            for (int i = 0; i < 3 * m.nv; i++) m.v[i] = rest[i] + rnd(-0.05, 0.05);
        } else {   // a bumpy sphere: the radius a function of the position
            double a = rnd(0.5, 3), b = rnd(0, 6);
            for (int i = 0; i < m.nv; i++) {
                const double *p = rest + 3 * i;
                double r = 1 + 0.15 * sin(a * p[0] + b) * cos(a * p[1] - p[2]);
                for (int k = 0; k < 3; k++) m.v[3 * i + k] = r * p[k];
            }
        }
        CHECK(check_update(data, &m) == 0);
        CHECK(data->closed == (round % 3 != 1));
    }
    dGeomTriMeshDataDestroy(data);
    free(rest);
    mesh_free(&m);
    return 0;
}

// Vertices brought onto others (a weld the build did not have) and
// triangles collapsed to a line or a point: the updated data is the fresh
// build's, degenerate triangles and all.
static int test_update_collapses_match_fresh_build(void)
{
    mesh m;
    make_grid(&m, 6, 0);
    dTriMeshDataID data = dGeomTriMeshDataCreate();
    build_on(data, &m);
    for (int round = 0; round < 10; round++) {
        // Heights in sixteenths: a midpoint is exact, in float too, so the
        // collapsed triangle's area is exactly 0.
        for (int i = 0; i < m.nv; i++) m.v[3 * i + 2] = floor(rnd(-5, 5)) / 16;
        int a = (int)rnd(0, m.nv), b = (int)rnd(0, m.nv), t = (int)rnd(0, m.nt);
        if (round % 2 == 0) {   // vertex a onto vertex b
            memcpy(m.v + 3 * a, m.v + 3 * b, 3 * sizeof(double));
        } else {   // triangle t's first corner midway along its opposite side
            const dTriIndex *idx = m.idx + 3 * t;
            for (int k = 0; k < 3; k++)
                m.v[3 * idx[0] + k] = 0.5 * (m.v[3 * idx[1] + k] + m.v[3 * idx[2] + k]);
        }
        CHECK(check_update(data, &m) == 0);
        if (round % 2 == 1) CHECK(dxTriMeshIsDegenerate(data, t));
    }
    dGeomTriMeshDataDestroy(data);
    mesh_free(&m);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_update_grid_matches_fresh_build),
    TEST_CASE(test_update_welded_mesh_matches_fresh_build),
    TEST_CASE(test_update_collapses_match_fresh_build),
    TEST_CASE(test_far_neighbours_left_to_the_data),
    TEST_END,
};
