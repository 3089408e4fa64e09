// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh.h -- what the native trimesh colliders share
// (collide_trimesh.c): the other geom posed in the mesh's frame, the walk
// over the triangles near it (the per-triangle and array callbacks), and the
// reduction of the triangles' contacts to a small manifold written in
// world coordinates (g1 the mesh, side1 the triangle).

#ifndef DX_COLLIDE_TRIMESH_H
#define DX_COLLIDE_TRIMESH_H

#include "../../libodecollide/trimesh_internal.h"
#include "collide_math.h"

// A hash grid of points for the reduction's neighbour searches
// (collide_trimesh_grid.c). A cell's list: its first entry `head`; entry e
// is the point link[2e], followed by entry link[2e + 1] (negative: none).
typedef struct dxTriCell {
    int key[3];
    int head;
} dxTriCell;
typedef struct dxTriGrid {
    dxTriCell *cell;
    int cell_cap, mask;
    int *link;
    int link_cap, links;
    double inv;     // 1 / the cells' side
    double reach;   // the search radius (widened for rounding)
} dxTriGrid;

// Empty the grid for up to `entries` points searched within `reach` of
// each other, every coordinate within `extent` of 0 (finite points only).
void dxTriGridStart(dxTriGrid *g, int entries, dReal reach, dReal extent);
// Add point number `point` at p.
void dxTriGridAdd(dxTriGrid *g, const dReal p[3], int point);
// The lists of the cells that may hold points within reach of p: pointers
// to their heads (so a walk may unlink entries); returns their count.
int dxTriGridNear(dxTriGrid *g, const dReal p[3], int *heads[27]);
void dxTriGridFree(dxTriGrid *g);

// The scratch memory of one collision (collide_trimesh_scratch.c): up to
// two triangle lists of each kind (candidates from the tree, triangles
// hit; [1] for the second mesh of a trimesh pair), the contacts before
// the reduction, and the reduction's grid and per-contact numbers.
typedef struct dxTriScratch {
    int *cand[2], *hits[2];
    int cand_cap[2], hits_cap[2];
    dxTriMeshRaw *raw;
    int raw_count, raw_cap;
    dxTriGrid grid;
    dReal *score;      // the reduction's numbers per contact
    int score_cap;
    // A triangle test's per-pair values (dxTriQuery.prepared): in double
    // whatever dReal is, for the room and the alignment of the pointers
    // among them.
    double pair[80];
    int *in_use;      // the owning thread's count of sets in use
    void *tc;         // the thread's temporal-coherence cache, once asked for
} dxTriScratch;

// A free set of the calling thread's (NULL, reported, if collisions nest
// too deep through callbacks), its contacts emptied; give it back with
// dxTriScratchRelease (NULL is ignored).
dxTriScratch *dxTriScratchAcquire(void);
void dxTriScratchRelease(dxTriScratch *s);
// Room for `extra` more contacts in s->raw.
void dxTriScratchAddRaw(dxTriScratch *s, int extra);
// The calling thread's temporal-coherence memory: `size` bytes at the start
// of a cache line, zeroed when first asked for (always asked for with the
// same size), freed when the thread exits.
void *dxTriScratchThreadTC(size_t size);

// A pair's entry in the temporal-coherence cache of a thread, which is
// always on (collide_trimesh_tc.c).
typedef struct dxTriLeafEntry dxTriLeafEntry;
// The entry of the pair (m, other) in the cache of s's thread, found (or
// taken over) ahead of the query: the lines of its leaves' nodes are asked
// for, and those of the entry found after it last time. NULL if m's tree is
// not cached (a heightfield's patch).
dxTriLeafEntry *dxTriMeshLeafEntry(dxTriScratch *s, const dxTriMesh *m, const void *other);
// The leaves (node * 4 + slot) that dxTriMeshQueryLeavesF lists for the
// float box lo_f, hi_f (dxFloatBox; the mesh's frame) of data d, the same in
// the same order, into leaf[] (at most max: -1 if more); through the pair's
// entry e (from dxTriMeshLeafEntry in this thread; NULL: the walk). Any
// entry gives the walk's list: one is used only with its own tree stamp and
// for a box inside its fat box, else made again.
int dxTriMeshQueryLeavesCached(const dxTriMeshData *d, dxTriLeafEntry *e, const float lo_f[4],
                               const float hi_f[4], int *leaf, int max);

// One pair's query, everything in the mesh frame.
typedef struct dxTriQuery {
    dxTriScratch *s;   // this collision's scratch memory
    dxTriMesh *mesh;
    const dxTriMeshData *data;   // the mesh's data (NULL: see dxTriClipToPrism)
    dxGeom *other;
    dReal pos[3];      // the other geom's position ...
    dReal R[12];       // ... and rotation (row-major 3x4; not for a sphere) in the mesh frame
    dReal scale;       // the other geom's size (tolerances)
    // Whether the triangle test has worked out what it needs once per pair
    // (into s->pair) on an earlier triangle: dxTriMeshGather clears it.
    int prepared;
} dxTriQuery;

// One triangle: its index, vertices and unit normal, where they are kept
// (the walk points into the tree's leaf-order copy and the data's normals:
// nothing is copied for a candidate). Its feature bits, neighbours and
// welded vertex indices, needed only at an edge or vertex, are read from
// the data there (dxTriFeatureNormal, dxTriPrismInit), but for what its
// leaf-order face holds.
typedef struct dxTri {
    int index;
    const dReal (*v)[3];   // its three vertices
    const dReal *n;
    dReal h;   // the height of the other geom's position above its plane (the walk's)
    // The data's face of the triangle (dxTriLeafFace: its coplanar bits and
    // its neighbours' faces) for the walk's triangles; NULL for others
    // (dxTriLoad's, the mesh pair's, a heightfield's): the data is asked.
    const dxTriLeafFace *face;
} dxTri;

// The height of p above triangle t's plane.
static inline dReal dxTriHeight(const dxTri *t, const dReal p[3])
{
    const dReal d[3] = { p[0] - t->v[0][0], p[1] - t->v[0][1], p[2] - t->v[0][2] };
    return dx_dot(t->n, d);
}

// A triangle with its own copy of its vertices and normal (dxTriLoad): for
// a triangle read outside the walk, or moved into another frame.
typedef struct dxTriOwn {
    dxTri t;   // points at v and n
    dReal v[3][3];
    dReal n[3];
} dxTriOwn;

// A triangle test: adds the triangle's contacts with dxTriAdd and returns 1
// if the triangle touches the other geom. The walk has worked out t->h and
// made the test's first rejection (a triangle whose plane the other's
// position is below, or above by more than the walk's `reach`) already.
typedef int dxTriTest(dxTriQuery *q, const dxTri *t);

// Add a contact with the other's triangle (the other geom being a
// trimesh; else -1): pos in the overlap, n the unit direction in which the
// other geom leaves the mesh, depth >= 0 (mesh frame). Inline: the box
// test adds a few a triangle.
static inline void dxTriAdd2(dxTriQuery *q, const dReal pos[3], const dReal n[3], dReal depth,
                             int tri, int tri2)
{
    dxTriScratch *s = q->s;
    if (s->raw_count >= s->raw_cap) dxTriScratchAddRaw(s, 1);
    dxTriMeshRaw *r = &s->raw[s->raw_count++];
    for (int k = 0; k < 3; k++) {
        r->pos[k] = pos[k];
        r->n[k] = n[k];
    }
    r->depth = depth;
    r->tri = tri;
    r->tri2 = tri2;
}

// The same with no other triangle.
static inline void dxTriAdd(dxTriQuery *q, const dReal pos[3], const dReal n[3], dReal depth,
                            int tri)
{
    dxTriAdd2(q, pos, n, depth, tri, -1);
}

// The collider body: every triangle whose box meets the other geom's box
// (mesh frame), that the per-triangle callback accepts and whose plane the
// other's position is on or above by at most reach (reach < 0: any height;
// dInfinity: on or above) goes through test; the array callback then sees
// those that touch; the contacts are
// reduced (near-duplicates merged, the triangles of a merged one given to
// the merge callback, at most flags & 0xffff kept: the deepest first, then
// each the farthest from those kept) and written.
int dxTriMeshCollide(dxGeom *mesh, dxGeom *other, int flags, dContactGeom *c, int skip,
                     dReal reach, dxTriTest *test);

// Reduce the contacts gathered in q->s->raw (near-duplicates merged, the
// triangles of a merged one given to the merge callbacks, flat groups kept
// to their hull corners, at most flags & 0xffff kept: the deepest first,
// then the spread) and write them in world coordinates; returns the count.
int dxTriMeshFinish(dxTriQuery *q, int flags, dContactGeom *c, int skip);

// The walk of dxTriMeshCollide alone: sets q up for the pair (every field
// but a sphere's R; q->s, an acquired scratch set, is kept), gathers the
// triangles' contacts into q->s->raw (callbacks honoured) and returns
// their count.
int dxTriMeshGather(dxTriQuery *q, dxGeom *mesh, dxGeom *other, dReal reach, dxTriTest *test);
// Keep at most flags & 0xffff of the first n gathered contacts (the deepest
// first, then the spread) at the front; returns the count kept.
int dxTriMeshSpread(dxTriQuery *q, int n, int flags);
// Write the first n gathered contacts in world coordinates as they are.
void dxTriMeshWrite(dxTriQuery *q, int n, dContactGeom *c, int skip);

// Load triangle t from the data into out (its copies, out->t pointing at them).
void dxTriLoad(const dxTriMeshData *d, int t, dxTriOwn *out);

// p less the closest point of triangle t to p: into d; returns the feature
// the point is on: 0 the face, 1 + k edge k (v_k to v_k+1), 4 + k vertex k.
// Inline, and the offset rather than the point: at a vertex it is p less
// the vertex, made anyway, and the sphere's test reads it at once from
// registers (a point copied out with 8-byte stores and read back with a
// 16-byte load waited until the stores reached the cache).
static inline int dxTriClosestOffset(const dxTri *t, const dReal p[3], dReal d[3])
{
    // Regions of the triangle's plane, tested in turn with the
    // barycentric signs (vertex, edge, then face regions).
    const dReal *a = t->v[0], *b = t->v[1], *c = t->v[2];
    dReal ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int i = 0; i < 3; i++) {
        ab[i] = b[i] - a[i];
        ac[i] = c[i] - a[i];
        ap[i] = p[i] - a[i];
        bp[i] = p[i] - b[i];
        cp[i] = p[i] - c[i];
    }
    dReal d1 = dx_dot(ab, ap), d2 = dx_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        for (int i = 0; i < 3; i++) d[i] = ap[i];
        return 4;
    }
    dReal d3 = dx_dot(ab, bp), d4 = dx_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        for (int i = 0; i < 3; i++) d[i] = bp[i];
        return 5;
    }
    dReal vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        dReal s = d1 / (d1 - d3);
        for (int i = 0; i < 3; i++) d[i] = p[i] - (a[i] + s * ab[i]);
        return 1;
    }
    dReal d5 = dx_dot(ab, cp), d6 = dx_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        for (int i = 0; i < 3; i++) d[i] = cp[i];
        return 6;
    }
    dReal vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        dReal s = d2 / (d2 - d6);
        for (int i = 0; i < 3; i++) d[i] = p[i] - (a[i] + s * ac[i]);
        return 3;   // edge 2: v2 to v0
    }
    dReal va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        dReal s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        for (int i = 0; i < 3; i++) d[i] = p[i] - (b[i] + s * (c[i] - b[i]));
        return 2;
    }
    dReal denom = 1 / (va + vb + vc), v = vb * denom, w = vc * denom;
    for (int i = 0; i < 3; i++) d[i] = p[i] - (a[i] + v * ab[i] + w * ac[i]);
    return 0;
}

// How a contact at `feature` (as dxTriClosestOffset) leaving along the unit
// direction dir is made: 1 along dir (a convex or border edge or vertex,
// dir within its region); 0 not a feature (the face; a flat or concave edge
// or vertex, where a neighbour face gives the contact unless the point is
// over this triangle's border: then the face normal, with no internal-edge
// bumps); -1 not at all (dir is outside the feature's region: a neighbour
// face or edge is nearer and gives the contact).
int dxTriFeatureNormal(const dxTriQuery *q, const dxTri *t, int feature, const dReal dir[3]);

// The inward normal (not unit) of the side of t's prism through edge k.
void dxTriSideNormal(const dxTri *t, int k, dReal m[3]);

// Clip the polygon a (n corners, at most DX_TRI_POLY_MAX - 3) to the prism
// of t (its sides widened by rounding): returns the new corner count, and
// for each corner in made[] whether it was made on a side of the prism, at
// an edge between coplanar faces (then a corner of the triangulation only,
// not of a contact patch; never if q->data is NULL) or another edge.
enum { DX_TRI_POLY_MAX = 36 };
enum { DX_TRI_MADE_NOT, DX_TRI_MADE_AT_EDGE, DX_TRI_MADE_AT_FLAT_EDGE, DX_TRI_MADE_CORNER };
int dxTriClipToPrism(const dxTriQuery *q, const dxTri *t, dReal a[][3], int n, int *made);

// The prism of a triangle made once for many clips: each side's inward
// normal m (not unit), the rounding slack it is widened by (in units of
// m) and the tag of the points made on it.
typedef struct dxTriPrism {
    dReal m[3][3];
    dReal slack[3];
    int made[3];
} dxTriPrism;
void dxTriPrismInit(const dxTriQuery *q, const dxTri *t, dxTriPrism *p);

// A clip's result: its n corners as pointers (to the polygon's own
// corners, which keep their bits, or to the points the clip made, in
// room) with their tags (as dxTriClipToPrism's made[], or the tag a corner
// was given), in pt and made: the caller's own lists if no clip changed
// the polygon, else one of the two working lists (each with room for a
// clip's output), in which the clips take turns.
typedef struct dxTriClipped {
    int n, made_count;
    const dReal *const *pt;
    const int *made;
    const dReal *list[2][2 * DX_TRI_POLY_MAX];
    int tags[2][2 * DX_TRI_POLY_MAX];
    dReal room[3 * DX_TRI_POLY_MAX][3];   // at most n points made by each of three clips
} dxTriClipped;
// dxTriClipToPrism with the prism made by dxTriPrismInit(q, t, p), the n
// corners given as pointers with their tags (DX_TRI_MADE_NOT, or
// DX_TRI_MADE_CORNER + i to follow corner i: a corner kept keeps its tag
// and its bits), the result into c (nothing copied but the points made:
// c->pt and c->made may be corner and made themselves);
// the sides k with bit k of `inside` set are known to keep every point (a
// polygon within them by more than rounding) and are not clipped against.
// Returns c->n. (In collide_trimesh_convex.c, whose clips inline it.)
int dxTriClipToPrismWith(const dxTriPrism *p, const dxTri *t, const dReal *const *corner,
                         const int *made, int n, unsigned inside, dxTriClipped *c);

#endif
