// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh.c -- the native trimesh colliders' shared walk and
// contact reduction (collide_trimesh.h), triangle geometry helpers (closest
// points, feature regions, clipping to a triangle's prism), and
// trimesh-plane (the vertices below the plane).

#include "collide_trimesh.h"

#include <ode/memory.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

// ---- the walk and the reduction --------------------------------------------

// The index of vertex k of triangle t.
static inline int tri_vertex(const dxTriMeshData *d, int t, int k)
{
    dTriIndex idx;
    memcpy(&idx, (const char *)d->indices + (size_t)t * (size_t)d->tri_stride + k * sizeof idx,
           sizeof idx);
    return (int)idx;
}

void dxTriLoad(const dxTriMeshData *d, int t, dxTriOwn *out)
{
    // The triangle's own vertices, as the leaf-order copy holds them (a
    // welded one is at the same position, but for the sign of a zero).
    for (int k = 0; k < 3; k++) {
        dxTriMeshVertex(d, tri_vertex(d, t, k), out->v[k]);
        out->n[k] = d->normal[3 * t + k];
    }
    out->t.index = t;
    out->t.v = (const dReal(*)[3])out->v;
    out->t.n = out->n;
    out->t.face = NULL;
}

static dReal dist2(const dReal a[3], const dReal b[3])
{
    dReal d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return dx_dot(d, d);
}

// The triangle index of a contact merged from those of triangles a and b
// of mesh g (its merge callback's, else -1).
static int merged_side(dxGeom *g, int a, int b)
{
    if (a == b) return a;
    dxTriMesh *m = g->ops->cls == dTriMeshClass ? (dxTriMesh *)g : NULL;
    return m && m->merge_callback ? m->merge_callback(g, a, b) : -1;
}

// Below this many contacts the reduction compares them pair by pair; from
// it on, it finds the candidates with the scratch's hash grid: the same
// results, about a constant per contact instead of a pass over the others.
enum { GRID_FROM = 96 };

static int finite3(const dReal p[3])
{
    return dxIsFinite(p[0]) && dxIsFinite(p[1]) && dxIsFinite(p[2]);
}

// Whether contact a merges into kept contact b: (nearly) the same point
// (within the square root of tol2), (nearly) the same normal.
static inline int same_contact(const dxTriMeshRaw *a, const dxTriMeshRaw *b, dReal tol2)
{
    return dist2(a->pos, b->pos) <= tol2 && dx_dot(a->n, b->n) > 1 - (dReal)1e-6;
}

// same_contact with the distance tol, tested along x first.
static int duplicates(const dxTriMeshRaw *a, const dxTriMeshRaw *b, dReal tol)
{
    // Most pairs are apart along x alone (the square of one term of the
    // distance's sum already over: the same answer, rounding included).
    dReal dx = a->pos[0] - b->pos[0];
    if (dx * dx > tol * tol) return 0;
    return same_contact(a, b, tol * tol);
}

// Whether points a and b are apart along x or along y by more than the
// square root of tol2 (the square of one term of the distance's sum
// already over tol2: not duplicates, rounding included). Both axes at once:
// on a grid mesh the contacts along one grid line share an x (or a y), and
// x alone left those pairs to a branch that went the other way.
static inline int apart_xy(const dReal *a, const dReal *b, dReal tol2)
{
#if defined(__SSE2__) && !defined(dSINGLE)
    __m128d d = _mm_sub_pd(_mm_loadu_pd(a), _mm_loadu_pd(b));
    d = _mm_mul_pd(d, d);
    return _mm_movemask_pd(_mm_cmpgt_pd(d, _mm_set1_pd(tol2))) != 0;
#else
    const dReal dx = a[0] - b[0], dy = a[1] - b[1];
    return (dx * dx > tol2) | (dy * dy > tol2);
#endif
}

// The lowest index among the n kept contacts that r[i] duplicates (n if
// none), pair by pair or through the grid of the kept ones' positions.
static int kept_duplicate(dxTriScratch *s, int n, int i, dReal tol, int grid)
{
    const dxTriMeshRaw *r = s->raw;
    if (!grid) {
        // duplicates' test along x and y first, the square of tol made
        // once (the same numbers and answers).
        const dReal tol2 = tol * tol;
        int j = 0;
        for (; j < n; j++)
            if (!apart_xy(r[i].pos, r[j].pos, tol2) && same_contact(&r[i], &r[j], tol2)) break;
        return j;
    }
    int best = n, *heads[27];
    if (!finite3(r[i].pos)) return n;   // a point that is not finite is near none
    int cells = dxTriGridNear(&s->grid, r[i].pos, heads);
    for (int c = 0; c < cells; c++)
        for (int e = *heads[c]; e >= 0; e = s->grid.link[2 * e + 1]) {
            int j = s->grid.link[2 * e];
            if (j < best && duplicates(&r[i], &r[j], tol)) best = j;
        }
    return best;
}

// Merge contacts at (nearly) the same point with (nearly) the same normal,
// each into the first kept one it duplicates, keeping the deeper; returns
// the new count. On the grid a kept contact that takes a deeper one's
// place is entered again at its new point (the old entry is then stale:
// harmless, as every candidate is tested at its current point).
static int merge_duplicates(dxTriScratch *s, dxTriMesh *m, dxGeom *other, dReal tol)
{
    dxTriMeshRaw *r = s->raw;
    int n = 0, grid = s->raw_count >= GRID_FROM;
    if (grid) {
        dReal extent = 0;
        for (int i = 0; i < s->raw_count; i++)
            if (finite3(r[i].pos))
                for (int k = 0; k < 3; k++) extent = dMax(extent, dFabs(r[i].pos[k]));
        dxTriGridStart(&s->grid, s->raw_count, tol, extent);
    }
    for (int i = 0; i < s->raw_count; i++) {
        int j = kept_duplicate(s, n, i, tol, grid);
        if (j == n) {
            if (n != i) r[n] = r[i];
            if (grid && finite3(r[n].pos)) dxTriGridAdd(&s->grid, r[n].pos, n);
            n++;
            continue;
        }
        int a = r[j].tri, b = r[i].tri, a2 = r[j].tri2, b2 = r[i].tri2;
        if (r[i].depth > r[j].depth) {
            r[j] = r[i];
            if (grid && finite3(r[j].pos)) dxTriGridAdd(&s->grid, r[j].pos, j);
        }
        r[j].tri = merged_side(&m->g, a, b);
        if (a2 >= 0 || b2 >= 0) r[j].tri2 = merged_side(other, a2, b2);
    }
    return n;
}

// Normals this close belong to one flat group; points this close to a line
// (sine of the angle) are on it.
#define SAME_NORMAL ((dReal)1 - 10 * DX_COLLIDE_EPS)
#define SAME_LINE (100 * DX_COLLIDE_EPS)

// The gift wrap's step in the plane of a flat group (uv: member i's
// coordinates there at 2i, 2i + 1; depth: member i's depth): from member
// cur, the member that all the others are not clockwise of; among those in
// line with it (within a relative sine of SAME_LINE) the farthest, and
// among those at one place (within the square root of near2) the deepest.
// Members at cur's place are not candidates: two contacts at one point of
// the plane but at different depths (a cap's rim and a side's corner, apart
// along the normal) are apart by rounding alone in uv, so the direction
// between them is noise; taken as a candidate it made the pick depend on
// the members' order (clockwise of next then no longer orders them) and
// the wrap close a loop that left hull corners out.
static int wrap_next(const dReal *uv, const dReal *depth, int count, int cur, dReal near2)
{
    int next = -1;
    dReal nu = 0, nv = 0;
    for (int q = 0; q < count; q++) {
        if (q == cur) continue;
        dReal qu = uv[2 * q] - uv[2 * cur], qv = uv[2 * q + 1] - uv[2 * cur + 1];
        dReal q2 = qu * qu + qv * qv;
        if (q2 <= near2) continue;
        if (next < 0) {
            next = q, nu = qu, nv = qv;
            continue;
        }
        // cross < 0: q is clockwise of next; collinear within a
        // relative sine of SAME_LINE.
        dReal cross = nu * qv - nv * qu, n2 = nu * nu + nv * nv;
        dReal tol = SAME_LINE * dSqrt(q2 * n2);
        dReal du = qu - nu, dv = qv - nv;
        int same_place = du * du + dv * dv <= near2;
        if (cross < -tol || (cross <= tol && (same_place ? depth[q] > depth[next] : q2 > n2)))
            next = q, nu = qu, nv = qv;
    }
    return next < 0 ? cur : next;   // every other member at cur's place
}

// Within a group of contacts with one normal (one flat patch), the corners
// of the patch's convex hull and its deepest point are what matters (with a
// flat solid on it, where depth varies linearly, the corners alone): mark
// them in keep[] (gift wrapping in the plane; points on a hull edge between
// two corners are left out; of members at one place, within depth_tol in
// the plane, the deepest). members lists the group; uv has room for
// 3 count numbers (the plane coordinates, then the depths).
static void mark_hull(const dxTriMeshRaw *r, const int *members, int count, dReal depth_tol,
                      int *keep, dReal *uv)
{
    if (count <= 2) {
        for (int i = 0; i < count; i++) keep[members[i]] = 1;
        return;
    }
    dReal e1[3], e2[3];
    const dReal *n = r[members[0]].n;
    dx_perpendicular(n, e1);
    e2[0] = n[1] * e1[2] - n[2] * e1[1];
    e2[1] = n[2] * e1[0] - n[0] * e1[2];
    e2[2] = n[0] * e1[1] - n[1] * e1[0];
    dReal *depth = uv + 2 * count, near2 = depth_tol * depth_tol;
    for (int i = 0; i < count; i++) {
        uv[2 * i] = dx_dot(r[members[i]].pos, e1);
        uv[2 * i + 1] = dx_dot(r[members[i]].pos, e2);
        depth[i] = r[members[i]].depth;
    }
    int start = 0;
    for (int i = 1; i < count; i++)
        if (uv[2 * i] < uv[2 * start] ||
            (uv[2 * i] == uv[2 * start] && uv[2 * i + 1] < uv[2 * start + 1]))
            start = i;
    // The deepest at the start's place (as the wrap takes at a place).
    for (int i = 0, s0 = start; i < count; i++) {
        dReal du = uv[2 * i] - uv[2 * s0], dv = uv[2 * i + 1] - uv[2 * s0 + 1];
        if (du * du + dv * dv <= near2 && depth[i] > depth[start]) start = i;
    }
    // Wrap until a member comes round again: the loop from it is the hull.
    // The start, lowest in e1, is a corner but for rounding: it can lie on
    // an edge between two corners, in line within SAME_LINE; then the wrap
    // enters the loop at the next corner without coming back to it, and
    // the members before the loop are unmarked.
    int cur = start;
    while (!keep[members[cur]]) {
        keep[members[cur]] = 1;
        cur = wrap_next(uv, depth, count, cur, near2);
    }
    for (int entry = cur, p = start; p != entry; p = wrap_next(uv, depth, count, p, near2))
        keep[members[p]] = 0;
    int deepest = 0;
    dReal corner_depth = -dInfinity;
    for (int i = 0; i < count; i++) {
        if (r[members[i]].depth > r[members[deepest]].depth) deepest = i;
        if (keep[members[i]]) corner_depth = dMax(corner_depth, r[members[i]].depth);
    }
    if (r[members[deepest]].depth > corner_depth + depth_tol) keep[members[deepest]] = 1;
}

// Room for n numbers in s->score (the flat groups' plane coordinates, the
// spread's distances).
static void reserve_reals(dxTriScratch *s, int n)
{
    if (n <= s->score_cap) return;
    dFree(s->score, (size_t)s->score_cap * sizeof(dReal));
    s->score = (dReal *)dAlloc((size_t)n * sizeof(dReal));
    s->score_cap = n;
}

static int compare_ints(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

// Whether every one of the n contacts' normals is a unit vector within
// the flat groups' tolerance: then the normals of a group are within
// sqrt(40 eps) of each other and the grid finds them.
static int unit_normals(const dxTriMeshRaw *r, int n)
{
    for (int i = 0; i < n; i++) {
        dReal l2 = dx_dot(r[i].n, r[i].n);
        if (!(l2 > SAME_NORMAL && l2 < 2 - SAME_NORMAL)) return 0;
    }
    return 1;
}

// The flat group of contact i (those not yet in a group, from i on, whose
// normal is within SAME_NORMAL of i's) into members in increasing order,
// each marked done; returns its size. With the grid (of the normals, every
// one unit), entries of contacts already in a group are unlinked as met.
static int flat_group(dxTriScratch *s, int n, int i, int grid, int *members, int *done)
{
    const dxTriMeshRaw *r = s->raw;
    int count = 0;
    if (!grid) {
        for (int j = i; j < n; j++)
            if (!done[j] && dx_dot(r[i].n, r[j].n) > SAME_NORMAL) {
                members[count++] = j;
                done[j] = 1;
            }
        return count;
    }
    int *heads[27];
    int cells = dxTriGridNear(&s->grid, r[i].n, heads);
    for (int c = 0; c < cells; c++) {
        int *link = heads[c];
        while (*link >= 0) {
            int e = *link, j = s->grid.link[2 * e];
            if (!done[j] && dx_dot(r[i].n, r[j].n) > SAME_NORMAL) {
                members[count++] = j;
                done[j] = 1;
            }
            if (done[j]) *link = s->grid.link[2 * e + 1];
            else link = &s->grid.link[2 * e + 1];
        }
    }
    qsort(members, (size_t)count, sizeof *members, compare_ints);
    return count;
}

// Keep only the hull corners (and an inner point deeper than them by more
// than tol) of each flat group; returns the new count.
static int prune_flat_groups(dxTriScratch *s, int n, dReal tol)
{
    dxTriMeshReserveInts(&s->cand[0], &s->cand_cap[0], n);
    dxTriMeshReserveInts(&s->hits[0], &s->hits_cap[0], 2 * n);
    reserve_reals(s, 3 * n);
    int *members = s->cand[0], *keep = s->hits[0], *done = s->hits[0] + n;
    for (int i = 0; i < n; i++) keep[i] = done[i] = 0;
    int grid = n >= GRID_FROM && unit_normals(s->raw, n);
    if (grid) {
        dxTriGridStart(&s->grid, n, dSqrt(64 * DX_COLLIDE_EPS), 1);
        for (int i = 0; i < n; i++) dxTriGridAdd(&s->grid, s->raw[i].n, i);
    }
    for (int i = 0; i < n; i++) {
        if (done[i]) continue;
        int count = flat_group(s, n, i, grid, members, done);
        mark_hull(s->raw, members, count, tol, keep, s->score);
    }
    int k = 0;
    for (int i = 0; i < n; i++)
        if (keep[i]) {
            if (k != i) s->raw[k] = s->raw[i];
            k++;
        }
    return k;
}

static void swap_raw(dxTriMeshRaw *r, int a, int b)
{
    dxTriMeshRaw t = r[a];
    r[a] = r[b];
    r[b] = t;
}

// Twice the area by which the triangle with corners x[k] and edges
// e[k] = x[k + 1] - x[k] (normal direction N) grows if it takes in p.
static dReal hull_growth(const dReal *const x[3], const dReal e[3][3], const dReal N[3],
                         const dReal *p)
{
    dReal growth = 0;
    for (int k = 0; k < 3; k++) {
        const dReal *xk = x[k], *ek = e[k];
        dReal d[3] = { p[0] - xk[0], p[1] - xk[1], p[2] - xk[2] };
        dReal cr[3] = { ek[1] * d[2] - ek[2] * d[1], ek[2] * d[0] - ek[0] * d[2],
                        ek[0] * d[1] - ek[1] * d[0] };
        dReal s = dx_dot(cr, N);
        if (s < 0) growth -= s;
    }
    return growth;
}

// Move the `keep` contacts to keep to the front: the deepest, the farthest
// from it, the farthest from the line of those two, the one that widens
// their triangle most, then each the farthest from those kept. near[i]
// (room for n) carries contact i's squared distance to the nearest kept
// one from the first step that needs it on, so each step is one pass.
static void select_spread(dxTriMeshRaw *r, dReal *near, int n, int keep)
{
    int best = 0;
    for (int i = 1; i < n; i++)
        if (r[i].depth > r[best].depth) best = i;
    swap_raw(r, 0, best);
    dReal N[3] = { 0, 0, 0 }, e[3][3] = { { 0 } };   // e: the edges of the first three kept
    const dReal *x[3] = { r[0].pos, r[1].pos, r[2].pos };
    int have_near = 0;
    for (int k = 1; k < keep; k++) {
        int by_near = k >= 3 && !(k == 3 && dx_dot(N, N) > 0);
        if (by_near && !have_near) {
            for (int i = k; i < n; i++) {
                near[i] = dInfinity;
                for (int j = 0; j < k; j++) near[i] = dMin(near[i], dist2(r[i].pos, r[j].pos));
            }
            have_near = 1;
        }
        if (k == 2)
            for (int j = 0; j < 3; j++) e[0][j] = r[1].pos[j] - r[0].pos[j];
        if (k == 3 && !by_near)
            for (int j = 0; j < 3; j++) {
                e[1][j] = r[2].pos[j] - r[1].pos[j];
                e[2][j] = r[0].pos[j] - r[2].pos[j];
            }
        dReal score_best = -1;
        best = k;
        for (int i = k; i < n; i++) {
            dReal score;
            if (k == 1) {
                score = dist2(r[i].pos, r[0].pos);
            } else if (k == 2) {
                dReal d[3], cr[3];
                for (int j = 0; j < 3; j++) d[j] = r[i].pos[j] - r[0].pos[j];
                cr[0] = e[0][1] * d[2] - e[0][2] * d[1];
                cr[1] = e[0][2] * d[0] - e[0][0] * d[2];
                cr[2] = e[0][0] * d[1] - e[0][1] * d[0];
                score = dx_dot(cr, cr);
            } else if (!by_near) {
                score = hull_growth(x, e, N, r[i].pos);
            } else {
                score = near[i];
            }
            if (score > score_best) {
                score_best = score;
                best = i;
            }
        }
        swap_raw(r, k, best);
        if (have_near) {
            dReal t = near[k];
            near[k] = near[best];
            near[best] = t;
            for (int i = k + 1; i < n; i++) near[i] = dMin(near[i], dist2(r[i].pos, r[k].pos));
        }
        if (k == 2) {
            dReal d[3];
            for (int j = 0; j < 3; j++) d[j] = r[2].pos[j] - r[0].pos[j];
            N[0] = e[0][1] * d[2] - e[0][2] * d[1];
            N[1] = e[0][2] * d[0] - e[0][0] * d[2];
            N[2] = e[0][0] * d[1] - e[0][1] * d[0];
        }
    }
}

void dxTriMeshWrite(dxTriQuery *q, int n, dContactGeom *c, int skip)
{
    dxGeom *g = &q->mesh->g;
    for (int i = 0; i < n; i++) {
        const dxTriMeshRaw *r = &q->s->raw[i];
        dReal pos[3], nw[3];
        dx_point_to_world(g->R, g->pos, r->pos, pos);
        dx_to_world(g->R, r->n, nw);
        for (int k = 0; k < 3; k++) nw[k] = -nw[k];   // into the mesh (g1)
        dx_put_contact(c, i, skip, pos, nw, r->depth, g, q->other);
        dxContactAt(c, i, skip)->side1 = r->tri;
        dxContactAt(c, i, skip)->side2 = r->tri2;
    }
}

int dxTriMeshSpread(dxTriQuery *q, int n, int flags)
{
    int max = dx_max_contacts(flags);
    if (n <= max) return n;
    reserve_reals(q->s, n);
    select_spread(q->s->raw, q->s->score, n, max);
    return max;
}

int dxTriMeshFinish(dxTriQuery *q, int flags, dContactGeom *c, int skip)
{
    dReal tol = q->scale * (dReal)1e-5;
    int n = merge_duplicates(q->s, q->mesh, q->other, tol);
    n = prune_flat_groups(q->s, n, tol);
    n = dxTriMeshSpread(q, n, flags);
    dxTriMeshWrite(q, n, c, skip);
    return n;
}

// R^T v (R row-major 3x4): dxTriMeshDirToLocal's sums, inline.
static inline void turn_back(const dReal *R, const dReal v[3], dReal out[3])
{
    for (int i = 0; i < 3; i++) out[i] = R[i] * v[0] + R[4 + i] * v[1] + R[8 + i] * v[2];
}

// The other geom's pose in the mesh frame (a sphere's rotation, which no
// test reads, is left out), and its box there.
static void pose_other(dxTriQuery *q, dReal lo[3], dReal hi[3])
{
    dxGeom *mesh = &q->mesh->g, *o = q->other;
    const dReal *R = mesh->R, *mp = mesh->pos;
    int cls = o->ops->cls;
    if (o->flags & DX_GEOM_PLACEABLE) {
        dReal d[3] = { o->pos[0] - mp[0], o->pos[1] - mp[1], o->pos[2] - mp[2] };
        turn_back(R, d, q->pos);
        for (int j = 0; j < 3 && cls != dSphereClass; j++) {
            dReal col[3] = { o->R[j], o->R[4 + j], o->R[8 + j] }, lc[3];
            turn_back(R, col, lc);
            for (int i = 0; i < 3; i++) q->R[4 * i + j] = lc[i];
        }
        for (int i = 0; i < 3; i++) q->R[4 * i + 3] = 0;
    } else {
        q->pos[0] = q->pos[1] = q->pos[2] = 0;
    }
    dxGeomUpdateAABB(o);
    if (!(o->flags & DX_GEOM_PLACEABLE)) {   // a plane: the whole mesh
        dxTriMeshDataBounds(q->data, lo, hi);
        q->scale = 0;
        for (int k = 0; k < 3; k++) q->scale += hi[k] - lo[k];
        return;
    }
    dReal cw[3], hw[3], cl[3];
    for (int k = 0; k < 3; k++) {
        cw[k] = (o->aabb[2 * k] + o->aabb[2 * k + 1]) / 2;
        hw[k] = (o->aabb[2 * k + 1] - o->aabb[2 * k]) / 2;
    }
    dReal dc[3] = { cw[0] - mp[0], cw[1] - mp[1], cw[2] - mp[2] };
    turn_back(R, dc, cl);
    q->scale = 0;
    for (int i = 0; i < 3; i++) {
        dReal e = dFabs(R[i]) * hw[0] + dFabs(R[4 + i]) * hw[1] + dFabs(R[8 + i]) * hw[2];
        lo[i] = cl[i] - e;
        hi[i] = cl[i] + e;
        q->scale += hw[i];
    }
    // A sphere's or a box's own box in the mesh frame is tighter where the
    // mesh is turned (the world box turned with it holds it).
    if (cls == dSphereClass || cls == dBoxClass) {
        dReal e[3];
        for (int i = 0; i < 3; i++) {
            if (cls == dSphereClass) {
                e[i] = ((const dxSphere *)o)->radius;
            } else {
                const dReal *side = ((const dxBox *)o)->side;
                e[i] = (dFabs(q->R[4 * i]) * side[0] + dFabs(q->R[4 * i + 1]) * side[1] +
                        dFabs(q->R[4 * i + 2]) * side[2]) / 2;
            }
            lo[i] = dMax(lo[i], q->pos[i] - e[i]);
            hi[i] = dMin(hi[i], q->pos[i] + e[i]);
        }
    }
}

// The query box [lo, hi] as tri_off_box compares with it (loaded once for
// a walk).
typedef struct off_box {
#if defined(__SSE2__) && !defined(dSINGLE)
    __m128d lxy, hxy, lz, hz;   // x and y side by side, then z
#else
    dReal lo[3], hi[3];
#endif
} off_box;

static inline void off_box_set(off_box *b, const dReal lo[3], const dReal hi[3])
{
#if defined(__SSE2__) && !defined(dSINGLE)
    b->lxy = _mm_loadu_pd(lo);
    b->hxy = _mm_loadu_pd(hi);
    b->lz = _mm_load_sd(lo + 2);
    b->hz = _mm_load_sd(hi + 2);
#else
    for (int i = 0; i < 3; i++) {
        b->lo[i] = lo[i];
        b->hi[i] = hi[i];
    }
#endif
}

// Whether the triangle with vertices v (9 numbers) lies off the box b
// along one of the mesh's axes. The query box holds the other geom
// (widened by rounding), so such a triangle touches nothing. A mesh's
// vertices are finite (a data object with one that is not is emptied), so
// "all three below lo" is "their largest below lo"; a NaN in the box (the
// other geom's pose) is never off either way, the comparisons being false.
static inline int tri_off_box(const dReal *v, const off_box *b)
{
#if defined(__SSE2__) && !defined(dSINGLE)
    // x and y side by side, then z with a zero beside it (0 < 0 and 0 > 0
    // are false: the upper lane never counts), one movemask for both.
    const __m128d a = _mm_loadu_pd(v), bb = _mm_loadu_pd(v + 3), c = _mm_loadu_pd(v + 6);
    const __m128d az = _mm_load_sd(v + 2), bz = _mm_load_sd(v + 5), cz = _mm_load_sd(v + 8);
    const __m128d mx = _mm_max_pd(_mm_max_pd(a, bb), c), mn = _mm_min_pd(_mm_min_pd(a, bb), c);
    const __m128d mxz = _mm_max_pd(_mm_max_pd(az, bz), cz), mnz = _mm_min_pd(_mm_min_pd(az, bz), cz);
    const __m128d off = _mm_or_pd(_mm_or_pd(_mm_cmplt_pd(mx, b->lxy), _mm_cmpgt_pd(mn, b->hxy)),
                                  _mm_or_pd(_mm_cmplt_pd(mxz, b->lz), _mm_cmpgt_pd(mnz, b->hz)));
    return _mm_movemask_pd(off) != 0;
#else
    const dReal *lo = b->lo, *hi = b->hi;
    int off = 0;
    for (int i = 0; i < 3; i++) {
        off |= dMax(v[i], dMax(v[3 + i], v[6 + i])) < lo[i];
        off |= dMin(v[i], dMin(v[3 + i], v[6 + i])) > hi[i];
    }
    return off;
#endif
}

// Whether a height h above a triangle's plane is within the test's reach:
// not below the plane, nor above it by more than reach (reach < 0: any);
// without a branch on h, which the walk keeps or drops triangles by.
static inline int height_within(dReal h, dReal reach)
{
    return reach < 0 || !((h < 0) | (h > reach));
}

// Whether the walk passes triangle *t (its vertices and normal set) to
// the test: the height of the other geom's position above its plane into
// t->h, then the test's own first rejection made here, without the call:
// below the plane, or above it by more than `reach` (reach < 0: neither).
static inline int height_passes(const dxTriQuery *q, dxTri *t, dReal reach)
{
    t->h = dxTriHeight(t, q->pos);
    return height_within(t->h, reach);
}

// One candidate read through the triangle list or seen by the
// per-triangle callback: skipped if degenerate or refused by the callback;
// its vertices then read from v (9 numbers) if given, else from the user's
// arrays (dxTriLoad into own); tested if its own box meets b and its
// height passes. Returns whether it touches.
static int gather_listed(dxTriQuery *q, int t, const dReal *v, const off_box *b, dReal reach,
                         dxTriTest *test, dxTriOwn *own)
{
    dxTriMesh *m = q->mesh;
    // A degenerate triangle has a zero normal (dxTriMeshIsDegenerate).
    const dReal *n = q->data->normal + 3 * t;
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) return 0;
    if (m->callback && !m->callback(&m->g, q->other, t)) return 0;
    dxTri tri = { .index = t, .n = n };
    if (v) {
        tri.v = (const dReal(*)[3])v;
    } else {
        dxTriLoad(q->data, t, own);
        tri.v = own->t.v;
    }
    if (tri_off_box(&tri.v[0][0], b) || !height_passes(q, &tri, reach)) return 0;
    return test(q, &tri);
}

// Append triangle t to the list of those that touch (s->hits[0], *hits).
static inline void add_hit(dxTriScratch *s, int *hits, int t)
{
    if (*hits >= s->hits_cap[0]) dxTriMeshReserveInts(&s->hits[0], &s->hits_cap[0], *hits + 1);
    s->hits[0][(*hits)++] = t;
}

// The widened query box as the triangles' float boxes (leaf_faces) are
// compared with it: per axis the float at or above its lower side (a) and
// the one at or below its upper side (c), a lane 3 of NaN that no
// comparison counts. A triangle's float box [lo, hi] holds its exact one
// [tlo, thi], and hi is the float at or above thi (lo the one at or below
// tlo), so hi < a means thi < the lower side (off the box), hi > a means
// thi is at least the lower side (not off that way: were thi below it, a
// would be a float at or above thi under hi), and the same for lo and c;
// only hi == a or lo == c leaves the question to the exact test. A NaN
// side makes every comparison false: not off, as the exact test says.
typedef struct off_box_f {
#if defined(__SSE__)
    __m128 a, c;
#else
    float a[3], c[3];
#endif
} off_box_f;

static inline void off_box_f_set(off_box_f *f, const dReal lo[3], const dReal hi[3])
{
    float a[4], c[4];
    dxFloatBox(lo, hi, a, c);
#if defined(__SSE__)
    const __m128 nan3 = _mm_setr_ps(0, 0, 0, NAN);   // (or: lanes 0-2 kept, lane 3 a NaN)
    f->a = _mm_or_ps(_mm_loadu_ps(a), nan3);
    f->c = _mm_or_ps(_mm_loadu_ps(c), nan3);
#else
    for (int k = 0; k < 3; k++) {
        f->a[k] = a[k];
        f->c[k] = c[k];
    }
#endif
}

// For the triangle with the float box fb (lo, then hi; the number after it
// is read as a float, and counts for nothing): whether it may meet f (not
// off it), and in *unsure whether only the exact test can say (a side of
// its box at a side of the query's in float). Without branches: the walk
// keeps or drops a triangle by the result, which a predictor cannot guess.
static inline int tri_meets_box_f(const float *fb, const off_box_f *f, int *unsure)
{
#if defined(__SSE__)
    const __m128 lo = _mm_loadu_ps(fb), hi = _mm_loadu_ps(fb + 3);
    const int off = _mm_movemask_ps(_mm_or_ps(_mm_cmplt_ps(hi, f->a), _mm_cmpgt_ps(lo, f->c)));
    *unsure = _mm_movemask_ps(_mm_or_ps(_mm_cmpeq_ps(hi, f->a), _mm_cmpeq_ps(lo, f->c))) != 0;
    return off == 0;
#else
    int off = 0, eq = 0;
    for (int k = 0; k < 3; k++) {
        off |= (fb[3 + k] < f->a[k]) | (fb[k] > f->c[k]);
        eq |= (fb[3 + k] == f->a[k]) | (fb[k] == f->c[k]);
    }
    *unsure = eq;
    return !off;
#endif
}

// The walk's candidates: at most DX_TRI_LEAF_MAX triangles a leaf; a
// candidate's leaf position with this bit where only the exact box test
// can say whether it meets the query.
enum { WALK_TRIS_MAX = DX_TRI_LEAF_MAX * 256, WALK_UNSURE = 1 << 30 };

// The leaf positions of the triangles of the n leaves (node * 4 + slot)
// whose float boxes (the data's leaf_faces) may meet fb, in leaf order,
// into cand (a position + WALK_UNSURE where only the exact test can say);
// returns their count. Each leaf's DX_TRI_LEAF_MAX slots are looked at
// (past its last triangle, that one again, counted for nothing): no
// branch on a leaf's count or a triangle's box.
static int boxes_meeting(const dxTriMeshData *d, const int *leaf, int n, const off_box_f *fb,
                         int *cand)
{
    const dxTriLeafFace *faces = d->leaf_faces;
    ptrdiff_t m = 0; // pointer-wide, as are the positions: no widening per slot
    for (int i = 0; i < n; i++) {
        const dxTriMeshNode *node = &d->nodes[leaf[i] >> 2];
        const ptrdiff_t first = node->first[leaf[i] & 3];
        const ptrdiff_t last = first + node->count[leaf[i] & 3] - 1;
        for (ptrdiff_t j = first; j < first + DX_TRI_LEAF_MAX; j++) {
            const ptrdiff_t at = j < last ? j : last;
            int unsure;
            const int meets = tri_meets_box_f(faces[at].box, fb, &unsure);
            cand[m] = (int)at + (unsure ? WALK_UNSURE : 0);
            m += meets & (j <= last);
        }
    }
    return (int)m;
}

// Of the m candidates (boxes_meeting's), in place, those whose exact box
// meets b where the float one could not say, whose height passes (their
// heights into h) and that are not degenerate; returns their count. The
// keep or drop is again without a branch.
static int heights_passing(const dxTriQuery *q, int *cand, int m, const off_box *b, dReal reach,
                           dReal *h)
{
    const dxTriMeshData *d = q->data;
    // The candidates' vertices asked for at once: the tests below would
    // otherwise wait for them one after another.
    for (int i = 0; i < m; i++)
        __builtin_prefetch(d->leaf_vertices + 9 * (cand[i] & (WALK_UNSURE - 1)));
    int kept = 0;
    for (int i = 0; i < m; i++) {
        const int j = cand[i] & (WALK_UNSURE - 1);
        const dReal *v = d->leaf_vertices + 9 * j;
        if ((cand[i] & WALK_UNSURE) && tri_off_box(v, b)) continue;
        const dReal *n = d->leaf_faces[j].n;
        const dxTri tri = { .v = (const dReal(*)[3])v, .n = n };
        const dReal ht = dxTriHeight(&tri, q->pos);
        int pass = height_within(ht, reach);
        // A degenerate triangle's height is 0 (or NaN): only then is its
        // normal looked at.
        if (!(ht != 0) && n[0] == 0 && n[1] == 0 && n[2] == 0) pass = 0;
        cand[kept] = j;
        h[kept] = ht;
        kept += pass;
    }
    return kept;
}

// The triangles of the n leaves without a per-triangle callback, in three
// passes: those whose float box (leaf_faces) may meet fb (boxes_meeting),
// of those the ones that pass the exact box b where needed, the height and
// the degenerate test (heights_passing), then the test of each, with its
// vertices, index and normal from the leaf-order copies (leaf_vertices,
// leaf_faces: nothing through order[]), in leaf order: the triangles the
// tests see and their order are those of one pass with a branch for each
// test, without the mispredicted branches. Those that touch are listed
// (add_hit) if hits is not NULL.
static void walk_leaves(dxTriQuery *q, const int *leaf, int n, const off_box *b,
                        const off_box_f *fb, dReal reach, dxTriTest *test, int *hits)
{
    const dxTriMeshData *d = q->data;
    const dReal *lv = d->leaf_vertices;
    const dxTriLeafFace *faces = d->leaf_faces;
    // Every listed leaf's first and last face (a line each: box, index,
    // normal) and its first vertices asked for before the walk: they are
    // the pair's first touch of its part of the mesh, and the walk would
    // otherwise wait for them one leaf after another.
    for (int i = 0; i < n; i++) {
        const dxTriMeshNode *node = &d->nodes[leaf[i] >> 2];
        const int first = node->first[leaf[i] & 3], last = first + node->count[leaf[i] & 3] - 1;
        __builtin_prefetch(&faces[first]);
        __builtin_prefetch(&faces[last]);
        __builtin_prefetch(lv + 9 * first);
    }
    int cand[WALK_TRIS_MAX];
    dReal h[WALK_TRIS_MAX];
    const int m = heights_passing(q, cand, boxes_meeting(d, leaf, n, fb, cand), b, reach, h);
    for (int i = 0; i < m; i++) {
        const int j = cand[i];
        const dxTriLeafFace *f = &faces[j];
        dxTri tri = { .index = f->index, .v = (const dReal(*)[3])(lv + 9 * j), .n = f->n,
                      .h = h[i], .face = f };
        if (test(q, &tri) && hits) add_hit(q->s, hits, tri.index);
    }
}

// At most this many leaves are walked from the vertices' leaf-order copy;
// a query meeting more goes through the triangle list.
enum { LEAF_WALK_MAX = WALK_TRIS_MAX / DX_TRI_LEAF_MAX };

int dxTriMeshGather(dxTriQuery *q, dxGeom *mesh, dxGeom *other, dReal reach, dxTriTest *test)
{
    dxTriMesh *m = (dxTriMesh *)mesh;
    dxTriScratch *s = q->s;
    q->mesh = m;
    q->data = m->data;
    q->other = other;
    q->scale = 0;
    q->prepared = 0;
    s->raw_count = 0;
    const dxTriMeshData *d = m->data;
    if (!d || d->tri_count == 0) return 0;
    // The pair's cached leaves are asked for first: they arrive while the
    // pose is worked out.
    dxTriLeafEntry *cached = d->leaf_vertices ? dxTriMeshLeafEntry(s, m, other) : NULL;
    dReal lo[3], hi[3], wlo[3], whi[3];
    pose_other(q, lo, hi);
    dReal eps = DX_COLLIDE_EPS * q->scale;
    for (int i = 0; i < 3; i++) {
        wlo[i] = lo[i] - eps;
        whi[i] = hi[i] + eps;
    }
    off_box b;
    off_box_set(&b, wlo, whi);
    int hits = 0;
    // The tree's leaves are walked in place: the same triangles in the same
    // order as dxTriMeshQueryBox lists them, their vertices read from the
    // leaf-order copy; the leaves from the pair's temporal-coherence cache.
    int leaf[LEAF_WALK_MAX], leaves = -1;
    if (d->leaf_vertices) {
        float lo_f[4], hi_f[4];
        dxFloatBox(lo, hi, lo_f, hi_f);
        leaves = dxTriMeshQueryLeavesCached(d, cached, lo_f, hi_f, leaf, LEAF_WALK_MAX);
    }
    if (leaves >= 0 && !m->callback) {
        off_box_f fb;
        off_box_f_set(&fb, wlo, whi);
        walk_leaves(q, leaf, leaves, &b, &fb, reach, test, m->array_callback ? &hits : NULL);
    } else if (leaves >= 0) {
        // The per-triangle callback sees every listed triangle that is not
        // degenerate, before the box test.
        for (int i = 0; i < leaves; i++) {
            const dxTriMeshNode *node = &d->nodes[leaf[i] >> 2];   // node * 4 + slot
            const int first = node->first[leaf[i] & 3], end = first + node->count[leaf[i] & 3];
            for (int j = first; j < end; j++) {
                int t = d->order[j];
                if (gather_listed(q, t, d->leaf_vertices + 9 * j, &b, reach, test, NULL))
                    add_hit(s, &hits, t);
            }
        }
    } else {
        int count = dxTriMeshQueryBox(d, lo, hi, &s->cand[0], &s->cand_cap[0]);
        dxTriOwn own;
        for (int i = 0; i < count; i++) {
            int t = s->cand[0][i];
            if (gather_listed(q, t, NULL, &b, reach, test, &own)) add_hit(s, &hits, t);
        }
    }
    if (hits > 0 && m->array_callback) m->array_callback(mesh, other, s->hits[0], hits);
    return s->raw_count;
}

int dxTriMeshCollide(dxGeom *mesh, dxGeom *other, int flags, dContactGeom *c, int skip,
                     dReal reach, dxTriTest *test)
{
    dxTriQuery q;
    q.s = dxTriScratchAcquire();
    if (!q.s) return 0;
    int n = dxTriMeshGather(&q, mesh, other, reach, test) ? dxTriMeshFinish(&q, flags, c, skip) : 0;
    dxTriScratchRelease(q.s);
    return n;
}

// ---- triangle geometry --------------------------------------------------------

int dxTriFeatureNormal(const dxTriQuery *q, const dxTri *t, int feature, const dReal dir[3])
{
    if (feature == 0) return 0;
    if (feature >= 4) {
        // A vertex's region: no edge from it may lean towards dir (exact
        // for a convex vertex).
        int k = feature - 4;
        const dxTriMeshData *d = q->data;
        if (!(dxTriMeshFeatures(d, t->index) & (DX_TRI_VERTEX_FEATURE << k))) return 0;
        int welded = d->weld[tri_vertex(d, t->index, k)];
        for (int j = d->vertex_first[welded]; j < d->vertex_first[welded + 1]; j++) {
            dReal w[3], e[3];
            dxTriMeshVertex(d, d->vertex_adj[j], w);
            for (int i = 0; i < 3; i++) e[i] = w[i] - t->v[k][i];
            if (dx_dot(e, dir) > DX_COLLIDE_EPS * dSqrt(dx_dot(e, e))) return -1;
        }
        return 1;
    }
    int k = feature - 1;
    if (!(dxTriMeshFeatures(q->data, t->index) & (DX_TRI_EDGE_FEATURE << k))) return 0;
    const dReal *nu;
    if (t->face && t->face->near[k] != DX_TRI_NEAR_NONE) {
        nu = t->face[t->face->near[k]].n;   // the same numbers, in leaf order
    } else {
        int u = q->data->neighbour[3 * t->index + k];
        if (u < 0) return 1;
        nu = q->data->normal + 3 * u;
    }
    // The neighbour's in-plane direction away from itself across the edge
    // (towards this triangle's side): dir must not point back over it.
    const dReal *a = t->v[k], *b = t->v[(k + 1) % 3], *far = t->v[(k + 2) % 3];
    dReal e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, m[3], af[3];
    dReal cr[3] = { nu[1] * e[2] - nu[2] * e[1], nu[2] * e[0] - nu[0] * e[2],
                    nu[0] * e[1] - nu[1] * e[0] };
    for (int i = 0; i < 3; i++) af[i] = far[i] - a[i];
    dReal s = dx_dot(cr, af) < 0 ? -1 : 1;
    for (int i = 0; i < 3; i++) m[i] = s * cr[i];
    return dx_dot(m, dir) >= 0 ? 1 : -1;
}

void dxTriSideNormal(const dxTri *t, int k, dReal m[3])
{
    dReal e[3] = { t->v[(k + 1) % 3][0] - t->v[k][0], t->v[(k + 1) % 3][1] - t->v[k][1],
                   t->v[(k + 1) % 3][2] - t->v[k][2] };
    m[0] = t->n[1] * e[2] - t->n[2] * e[1];
    m[1] = t->n[2] * e[0] - t->n[0] * e[2];
    m[2] = t->n[0] * e[1] - t->n[1] * e[0];
}

// Bit k: t's edge k joins two coplanar faces (an edge only of the
// triangulation, not of the surface). A walk's triangle carries the
// answer of the neighbours' normals (the same sum on the same numbers,
// made with the data), so that its prism does not wait on the neighbours'
// indices and then their normals, both in the user's order.
static unsigned flat_edges(const dxTriQuery *q, const dxTri *t)
{
    if (!q->data) return 0;
    const unsigned real = dxTriMeshFeatures(q->data, t->index) / DX_TRI_EDGE_FEATURE & 7;
    if (t->face) return t->face->coplanar & 7 & ~real;
    unsigned flat = 0;
    for (int k = 0; k < 3; k++) {
        const int u = q->data->neighbour[3 * t->index + k];
        flat |= (unsigned)(!(real >> k & 1) && u >= 0 &&
                           dx_dot(t->n, q->data->normal + 3 * u) > DX_TRI_COPLANAR_COS)
                << k;
    }
    return flat;
}

void dxTriPrismInit(const dxTriQuery *q, const dxTri *t, dxTriPrism *p)
{
    const dReal eps = DX_COLLIDE_EPS * q->scale;
    const unsigned flat = flat_edges(q, t);
    _Static_assert(DX_TRI_MADE_AT_FLAT_EDGE == DX_TRI_MADE_AT_EDGE + 1,
                   "a flat edge's tag follows");
    for (int k = 0; k < 3; k++) {
        dxTriSideNormal(t, k, p->m[k]);
        p->slack[k] = eps * dSqrt(dx_dot(p->m[k], p->m[k]));
        p->made[k] = DX_TRI_MADE_AT_EDGE + (int)(flat >> k & 1);
    }
}

int dxTriClipToPrism(const dxTriQuery *q, const dxTri *t, dReal a[][3], int n, int *made)
{
    dxTriPrism p;
    dxTriPrismInit(q, t, &p);
    const dReal *corner[DX_TRI_POLY_MAX];
    int tags[DX_TRI_POLY_MAX];
    for (int i = 0; i < n; i++) {
        corner[i] = a[i];
        tags[i] = DX_TRI_MADE_NOT;
    }
    dxTriClipped c;
    n = dxTriClipToPrismWith(&p, t, corner, tags, n, 0, &c);
    // The kept corners point into a: gathered first, then written back.
    dReal out[DX_TRI_POLY_MAX][3];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 3; j++) out[i][j] = c.pt[i][j];
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < 3; j++) a[i][j] = out[i][j];
        made[i] = c.made[i];
    }
    return n;
}

// ---- trimesh-plane ----------------------------------------------------------------

// The triangle's vertices below the plane, each a contact at the vertex.
static int plane_test(dxTriQuery *q, const dxTri *t)
{
    const dxPlane *p = (const dxPlane *)q->other;
    dReal nl[3];
    dxTriMeshDirToLocal(&q->mesh->g, p->p, nl);
    dReal d = p->p[3] - dx_dot(p->p, q->mesh->g.pos);
    dReal leave[3] = { -nl[0], -nl[1], -nl[2] };   // the plane leaves downwards
    int touched = 0;
    for (int k = 0; k < 3; k++) {
        dReal depth = d - dx_dot(nl, t->v[k]);
        if (depth < 0) continue;
        dxTriAdd(q, t->v[k], leave, depth, t->index);
        touched = 1;
    }
    return touched;
}

int dxCollideTriMeshPlane(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return dxTriMeshCollide(o1, o2, flags, c, skip, -1, plane_test);
}
