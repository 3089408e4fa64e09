// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_mesh.c -- trimesh-trimesh, in the first mesh's frame.
// The second mesh's triangles near the first mesh's box are taken one by
// one, each against the first mesh's triangles near it (both trees). A pair
// of triangles that cross (an edge of one passes through the other) gives
// contacts along one of the two face normals: the points of either triangle
// within the other's prism and behind its plane, at their depths below it.
// Which face: never one behind which the other mesh has the centre of its
// box (as the convex pairs are one-sided: no contact if both are), else the
// one with the shallower penetration; where the two are nearly as deep and both geoms have a last transform
// (dGeomTriMeshSetLastTransform, guide 10.7.6), the one the other triangle
// moved into since then. Both meshes' per-triangle, array
// and merge callbacks apply; side1 and side2 are the two triangles.

#include "collide_trimesh.h"

#include <stdint.h>

// Depths within this fraction of each other are a tie that the motion
// since the last transforms decides.
#define NEAR_TIE ((dReal)0.1)
#include <stdlib.h>

// Whether the segment p -> q crosses triangle t (either side).
static int segment_crosses(const dReal p[3], const dReal q[3], const dxTri *t)
{
    dReal hp = 0, hq = 0;
    for (int i = 0; i < 3; i++) {
        hp += t->n[i] * (p[i] - t->v[0][i]);
        hq += t->n[i] * (q[i] - t->v[0][i]);
    }
    if ((hp > 0 && hq > 0) || (hp < 0 && hq < 0) || hp == hq) return 0;
    dReal s = hp / (hp - hq), x[3];
    for (int i = 0; i < 3; i++) x[i] = p[i] + s * (q[i] - p[i]);
    for (int k = 0; k < 3; k++) {
        dReal m[3], d[3];
        dxTriSideNormal(t, k, m);
        for (int i = 0; i < 3; i++) d[i] = x[i] - t->v[k][i];
        if (dx_dot(m, d) < 0) return 0;
    }
    return 1;
}

static int triangles_cross(const dxTri *a, const dxTri *b)
{
    for (int k = 0; k < 3; k++)
        if (segment_crosses(a->v[k], a->v[(k + 1) % 3], b) ||
            segment_crosses(b->v[k], b->v[(k + 1) % 3], a))
            return 1;
    return 0;
}

// The points of triangle `moving` within the prism of `face` and behind its
// plane, but not deeper than `reach` (the face's solid is no thicker there),
// into pts (depths into depth); returns how many, and the deepest depth in
// *most.
static int points_behind(const dxTriQuery *q, const dxTri *face, const dxTri *moving,
                         dReal reach, dReal pts[][3], dReal *depth, dReal *most)
{
    int made[DX_TRI_POLY_MAX];
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) pts[k][i] = moving->v[k][i];
    int n = dxTriClipToPrism(q, face, pts, 3, made), kept = 0;
    *most = 0;
    for (int j = 0; j < n; j++) {
        dReal d = 0;
        for (int i = 0; i < 3; i++) d -= face->n[i] * (pts[j][i] - face->v[0][i]);
        if (d <= 0 || d > reach) continue;
        for (int i = 0; i < 3; i++) pts[kept][i] = pts[j][i];
        depth[kept++] = d;
        if (d > *most) *most = d;
    }
    return kept;
}

// Where point p (first mesh's frame, on the second mesh) was at the last
// transforms, relative to the first mesh then; 0 if either geom has none.
static int last_position(const dxTriMesh *a, const dxTriMesh *b, const dReal p[3], dReal out[3])
{
    if (!a->last_set || !b->last_set) return 0;
    // p in b's frame now, then in the world at b's last transform, then in
    // a's frame at a's last transform (ODE's layout: the columns of R in
    // elements 0-2, 4-6, 8-10, the position in 12-14).
    const dxGeom *ga = &a->g, *gb = &b->g;
    dReal w[3], lb[3], d[3];
    dx_point_to_world(ga->R, ga->pos, p, w);
    for (int i = 0; i < 3; i++) d[i] = w[i] - gb->pos[i];
    dx_to_local(gb->R, d, lb);
    const dReal *T = b->last_transform, *S = a->last_transform;
    for (int i = 0; i < 3; i++) w[i] = T[i] * lb[0] + T[4 + i] * lb[1] + T[8 + i] * lb[2] + T[12 + i];
    for (int i = 0; i < 3; i++) d[i] = w[i] - S[12 + i];
    for (int i = 0; i < 3; i++) out[i] = S[4 * i] * d[0] + S[4 * i + 1] * d[1] + S[4 * i + 2] * d[2];
    return 1;
}

// The contacts of triangles t (first mesh) and u (second, in the first's
// frame) if they cross; returns 1 then.
// How thick the solid of a mesh can be across the unit direction n (its
// frame): its box's width if it is closed, else unbounded (a sheet or
// terrain stands for everything behind it).
static dReal reach_along(const dxTriMeshData *d, const dReal h[3], const dReal n[3])
{
    if (!d->closed) return dInfinity;
    return 2 * (h[0] * dFabs(n[0]) + h[1] * dFabs(n[1]) + h[2] * dFabs(n[2]));
}

// reach_u: how thick the second mesh is across u (reach_along).
static int pair_contacts(dxTriQuery *q, const dxTri *t, const dxTri *u, const dReal centre_a[3],
                         const dReal half_a[3], const dReal centre_b[3], dReal reach_u)
{
    if (!triangles_cross(t, u)) return 0;
    dReal pu[DX_TRI_POLY_MAX][3], du[DX_TRI_POLY_MAX], mu_;
    dReal pt[DX_TRI_POLY_MAX][3], dt[DX_TRI_POLY_MAX], mt_;
    // u's data is not in this frame: its flat edges are not looked up.
    dxTriQuery qu = *q;
    qu.data = NULL;
    dReal reach_t = reach_along(q->data, half_a, t->n);
    int nu = points_behind(q, t, u, reach_t, pu, du, &mu_);   // u's behind t: leaves along n_t
    int nt = points_behind(&qu, u, t, reach_u, pt, dt, &mt_);  // t's behind u: along -n_u
    // A direction is out of the question if the mesh it moves has its centre
    // behind the face it would leave (as for the one-sided convex pairs): a
    // floor's vertex inside a resting box must not throw it sideways.
    dReal d[3];
    for (int i = 0; i < 3; i++) d[i] = centre_b[i] - t->v[0][i];
    if (dx_dot(d, t->n) < 0) nu = 0;
    for (int i = 0; i < 3; i++) d[i] = centre_a[i] - u->v[0][i];
    if (dx_dot(d, u->n) < 0) nt = 0;
    if (nu == 0 && nt == 0) return 0;
    int use_t = nt == 0 || (nu > 0 && mu_ <= mt_);
    dReal c[3], before[3];
    for (int i = 0; i < 3; i++) c[i] = (u->v[0][i] + u->v[1][i] + u->v[2][i]) / 3;
    int close = nu > 0 && nt > 0 && dFabs(mu_ - mt_) <= NEAR_TIE * dMax(mu_, mt_);
    if (close && last_position(q->mesh, (dxTriMesh *)q->other, c, before)) {
        dReal moved[3] = { c[0] - before[0], c[1] - before[1], c[2] - before[2] };
        dReal into_t = -dx_dot(moved, t->n), into_u = dx_dot(moved, u->n);
        if (dx_dot(moved, moved) > DX_COLLIDE_EPS * q->scale * q->scale && into_t != into_u)
            use_t = into_t > into_u;
    }
    if (use_t) {
        for (int j = 0; j < nu; j++) dxTriAdd2(q, pu[j], t->n, du[j], t->index, u->index);
    } else {
        dReal leave[3] = { -u->n[0], -u->n[1], -u->n[2] };
        for (int j = 0; j < nt; j++) dxTriAdd2(q, pt[j], leave, dt[j], t->index, u->index);
    }
    return 1;
}

static int compare_ints(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return x < y ? -1 : x > y;
}

// Sort and deduplicate a[0..n); returns the new count.
static int unique_ints(int *a, int n)
{
    qsort(a, (size_t)n, sizeof *a, compare_ints);
    int k = 0;
    for (int i = 0; i < n; i++)
        if (k == 0 || a[k - 1] != a[i]) a[k++] = a[i];
    return k;
}

static int collide_ordered(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip,
                           dxTriScratch *s)
{
    dxTriMesh *a = (dxTriMesh *)o1, *b = (dxTriMesh *)o2;
    const dxTriMeshData *da = a->data, *db = b->data;
    if (!da || !db || da->tri_count == 0 || db->tri_count == 0) return 0;
    dxTriQuery q = { .s = s, .mesh = a, .data = da, .other = o2 };
    // b's pose in a's frame.
    dxTriMeshToLocal(o1, o2->pos, q.pos);
    for (int j = 0; j < 3; j++) {
        dReal col[3] = { o2->R[j], o2->R[4 + j], o2->R[8 + j] }, lc[3];
        dxTriMeshDirToLocal(o1, col, lc);
        for (int i = 0; i < 3; i++) q.R[4 * i + j] = lc[i];
    }
    // a's box in b's frame: b's triangles near a.
    dReal lo[3], hi[3], ca[3], ha[3], cw[3], cb[3];
    dxTriMeshDataBounds(da, lo, hi);
    q.scale = 0;
    for (int k = 0; k < 3; k++) {
        ca[k] = (lo[k] + hi[k]) / 2;
        ha[k] = (hi[k] - lo[k]) / 2;
    }
    dx_point_to_world(o1->R, o1->pos, ca, cw);
    dxTriMeshToLocal(o2, cw, cb);
    for (int i = 0; i < 3; i++) {
        dReal e = 0;
        for (int k = 0; k < 3; k++) e += dFabs(q.R[4 * k + i]) * ha[k];   // (R_b^T R_a) h
        lo[i] = cb[i] - e;
        hi[i] = cb[i] + e;
    }
    int nb = dxTriMeshQueryBox(db, lo, hi, &s->cand[1], &s->cand_cap[1]);
    dReal centre_b[3], half_b[3];   // b's box: centre in a's frame, half sides in b's
    {
        dReal blo[3], bhi[3], cbl[3];
        dxTriMeshDataBounds(db, blo, bhi);
        for (int k = 0; k < 3; k++) {
            half_b[k] = (bhi[k] - blo[k]) / 2;
            q.scale += half_b[k];
            cbl[k] = (blo[k] + bhi[k]) / 2;
        }
        dx_point_to_world(q.R, q.pos, cbl, centre_b);
    }
    int hits_a = 0, hits_b = 0;
    for (int i = 0; i < nb; i++) {
        int ub = s->cand[1][i];
        if (dxTriMeshIsDegenerate(db, ub)) continue;
        if (b->callback && !b->callback(o2, o1, ub)) continue;
        dxTriOwn u;
        dxTriLoad(db, ub, &u);
        dReal reach_u = reach_along(db, half_b, u.n);   // u.n still in b's frame
        // u in a's frame, and its box there.
        dReal n[3];
        for (int k = 0; k < 3; k++) {
            dReal w[3];
            dx_point_to_world(q.R, q.pos, u.v[k], w);
            for (int j = 0; j < 3; j++) u.v[k][j] = w[j];
        }
        dx_to_world(q.R, u.n, n);
        for (int j = 0; j < 3; j++) {
            u.n[j] = n[j];
            lo[j] = dMin(u.v[0][j], dMin(u.v[1][j], u.v[2][j]));
            hi[j] = dMax(u.v[0][j], dMax(u.v[1][j], u.v[2][j]));
        }
        int na = dxTriMeshQueryBox(da, lo, hi, &s->cand[0], &s->cand_cap[0]);
        int touched_b = 0;
        for (int j = 0; j < na; j++) {
            int ta = s->cand[0][j];
            if (dxTriMeshIsDegenerate(da, ta)) continue;
            if (a->callback && !a->callback(o1, o2, ta)) continue;
            dxTriOwn t;
            dxTriLoad(da, ta, &t);
            if (!pair_contacts(&q, &t.t, &u.t, ca, ha, centre_b, reach_u)) continue;
            touched_b = 1;
            dxTriMeshReserveInts(&s->hits[0], &s->hits_cap[0], hits_a + 1);
            s->hits[0][hits_a++] = ta;
        }
        if (touched_b) {
            dxTriMeshReserveInts(&s->hits[1], &s->hits_cap[1], hits_b + 1);
            s->hits[1][hits_b++] = ub;
        }
    }
    if (hits_a > 0 && a->array_callback) {
        hits_a = unique_ints(s->hits[0], hits_a);
        a->array_callback(o1, o2, s->hits[0], hits_a);
    }
    if (hits_b > 0 && b->array_callback) b->array_callback(o2, o1, s->hits[1], hits_b);
    return s->raw_count ? dxTriMeshFinish(&q, flags, c, skip) : 0;
}

// The pair in one order whichever way it is asked (the lower address first),
// so that dCollide(b, a) mirrors dCollide(a, b).
int dxCollideTriMeshTriMesh(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    dxTriScratch *s = dxTriScratchAcquire();
    if (!s) return 0;
    int n;
    if ((uintptr_t)o1 < (uintptr_t)o2) {
        n = collide_ordered(o1, o2, flags, c, skip, s);
    } else {
        n = collide_ordered(o2, o1, flags, c, skip, s);
        dxFlipContacts(c, n, skip);
    }
    dxTriScratchRelease(s);
    return n;
}

int dxCollideTriMeshTriMeshInOrder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    dxTriScratch *s = dxTriScratchAcquire();
    if (!s) return 0;
    int n = collide_ordered(o1, o2, flags, c, skip, s);
    dxTriScratchRelease(s);
    return n;
}
