// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_convex.c -- a trimesh against a sphere, a capsule and a
// box, triangle by triangle in the mesh frame. Triangles are one-sided:
// a shape whose centre is behind a triangle's plane does not touch it.
//
// - Sphere: the closest point of the triangle; on the face the contact
//   takes the face normal and the depth below the face's plane; on a
//   convex edge or vertex, the direction from it (if within its region);
//   an edge or vertex that is not a real feature (flat or concave) leaves
//   the contact to the neighbouring face, so a ball rolling over a flat
//   area of many triangles meets one plane.
// - Capsule: the axis segment clipped to the triangle's prism gives a
//   contact at each end (face normal, depth below the plane); if it misses
//   the prism, the closest points of the segment and the triangle's edges
//   as for the sphere.
// - Box: rejected if a separating axis exists (the triangle's normal, the
//   box's axes, the edges' cross products); else each box face clipped to
//   the triangle's prism gives its corners on or behind the triangle's
//   plane, with the face normal and their depth below the plane (the
//   corners of the part of the box behind the triangle, but for those on
//   the plane itself).
// - Convex hull (dCreateConvex): as the box, with the hull's face normals
//   and edges for the box's axes and its polygons for the box's faces, so a
//   convex box has exactly a box's contacts.

#include <float.h>
#include <stddef.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "collide_trimesh.h"
#include "../../libodecollide/geom_convex.h"

// How far (relative to the other geom's size) a point may be off a
// triangle's border and still count as over it (rounding at shared edges).
#ifdef dSINGLE
#define OVER_BORDER ((dReal)1e-4)
#else
#define OVER_BORDER ((dReal)1e-7)
#endif

static void sub3(dReal out[3], const dReal a[3], const dReal b[3])
{
    for (int i = 0; i < 3; i++) out[i] = a[i] - b[i];
}

static void cross3(dReal out[3], const dReal a[3], const dReal b[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// A ball of radius r at p (a sphere's centre, or a point of a capsule's
// axis) against the closest point of t, p - d, on feature f (as
// dxTriClosestOffset): along the face normal on the face, or over a flat or
// concave edge or vertex when p is (within rounding) over the triangle's
// border; along the direction from a convex feature within its region;
// else none. Returns 1 if a contact was added.
static inline int ball_contact(dxTriQuery *q, const dxTri *t, const dReal p[3], dReal r,
                               const dReal d[3], int f)
{
    dReal dist2 = dx_dot(d, d);
    if (dist2 > r * r) return 0;
    dReal dist = dSqrt(dist2), h = dxTriHeight(t, p), dir[3] = { t->n[0], t->n[1], t->n[2] };
    int how = 0;
    if (f != 0 && dist > DX_COLLIDE_EPS * r) {
        for (int i = 0; i < 3; i++) dir[i] = d[i] / dist;
        how = dxTriFeatureNormal(q, t, f, dir);
        // Off the border of a non-feature: the neighbour's contact.
        dReal off2 = dist2 - h * h, tol = OVER_BORDER * q->scale;
        if (how == 0 && off2 > tol * tol) return 0;
    }
    if (how < 0) return 0;
    dReal depth, pos[3];
    if (how == 0) {
        depth = r - h;
        if (depth < 0) return 0;
        for (int i = 0; i < 3; i++) dir[i] = t->n[i];
    } else {
        depth = r - dist;
    }
    for (int i = 0; i < 3; i++) pos[i] = p[i] - r * dir[i];
    dxTriAdd(q, pos, dir, depth, t->index);
    return 1;
}

// ---- sphere ---------------------------------------------------------------------

// (The walk has left out a triangle whose plane the centre is below or
// more than r above: dxCollideTriMeshSphere's reach.)
static int sphere_test(dxTriQuery *q, const dxTri *t)
{
    dReal r = ((const dxSphere *)q->other)->radius;
    dReal d[3];
    int f = dxTriClosestOffset(t, q->pos, d);
    return ball_contact(q, t, q->pos, r, d, f);
}

// The mean of the n contacts' normals weighted by their depths, into N;
// 0 if it has no direction.
static int mean_normal(const dxTriMeshRaw *r, int n, dReal N[3])
{
    N[0] = N[1] = N[2] = 0;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) N[k] += r[i].depth * r[i].n[k];
    dReal len = dSqrt(dx_dot(N, N));
    if (!(len > 0)) return 0;
    for (int k = 0; k < 3; k++) N[k] /= len;
    return 1;
}

// The n contacts merged into r[0]: at their mean point, along N, as deep as
// the deepest of them needs along N (depth / cos, the cosine at least 1/2);
// its triangle as the merge callback names it. 0 (nothing changed) if a
// contact is at right angles to N or beyond.
static int merge_fully(dxTriMesh *m, dxTriMeshRaw *r, int n, const dReal N[3])
{
    dReal depth = 0, pos[3] = { 0, 0, 0 };
    for (int i = 0; i < n; i++) {
        dReal cosine = dx_dot(N, r[i].n);
        if (cosine < DX_COLLIDE_EPS) return 0;
        depth = dMax(depth, r[i].depth / dMax(cosine, (dReal)0.5));
        for (int k = 0; k < 3; k++) pos[k] += r[i].pos[k] / n;
    }
    int tri = r[0].tri;
    for (int i = 1; i < n; i++) tri = m->merge_callback ? m->merge_callback(&m->g, tri, r[i].tri) : -1;
    for (int k = 0; k < 3; k++) {
        r[0].pos[k] = pos[k];
        r[0].n[k] = N[k];
    }
    r[0].depth = depth;
    r[0].tri = tri;
    return 1;
}

// A sphere's contacts, one per triangle it touches, merged as the mesh's
// setting says (dGeomColliderMergeContactsValue_*, ODE's semantics): not at
// all (the default), the normals only (each takes the mean normal) or fully
// (one contact). CONTACTS_UNIMPORTANT skips the merging (fully: the first
// contact only). A heightfield's shadow mesh (setting 0) reduces them as
// any shape's.
int dxCollideTriMeshSphere(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    dxTriQuery q;
    q.s = dxTriScratchAcquire();
    if (!q.s) return 0;
    int n = dxTriMeshGather(&q, o1, o2, ((const dxSphere *)o2)->radius, sphere_test);
    dxTriMesh *m = q.mesh;
    dxTriMeshRaw *r = q.s->raw;
    int important = !(flags & CONTACTS_UNIMPORTANT);
    dReal N[3];
    if (n == 0) {
        // nothing touches
    } else if (m->sphere_merge == 0) {
        n = dxTriMeshFinish(&q, flags, c, skip);
    } else {
        if (m->sphere_merge == dGeomColliderMergeContactsValue_Full) {
            if (!important || (n > 1 && mean_normal(r, n, N) && merge_fully(m, r, n, N))) n = 1;
        } else if (m->sphere_merge == dGeomColliderMergeContactsValue_Normals && important &&
                   n > 1 && mean_normal(r, n, N)) {
            for (int i = 0; i < n; i++)
                for (int k = 0; k < 3; k++) r[i].n[k] = N[k];
        }
        n = dxTriMeshSpread(&q, n, flags);
        dxTriMeshWrite(&q, n, c, skip);
    }
    dxTriScratchRelease(q.s);
    return n;
}

// ---- capsule --------------------------------------------------------------------

// The parameter range [*lo, *hi] of p0 + s (p1 - p0) inside the prism of t
// (borders widened by rounding): 0 if empty.
static int clip_to_prism(const dxTri *t, const dReal p0[3], const dReal p1[3], dReal tol,
                         dReal *lo, dReal *hi)
{
    *lo = 0;
    *hi = 1;
    for (int k = 0; k < 3; k++) {
        dReal m[3], a[3], b[3];
        dxTriSideNormal(t, k, m);
        sub3(a, p0, t->v[k]);
        sub3(b, p1, t->v[k]);
        dReal slack = tol * dSqrt(dx_dot(m, m));
        dReal f0 = dx_dot(m, a) + slack, f1 = dx_dot(m, b) + slack;
        if (f0 < 0 && f1 < 0) return 0;
        if (f0 < 0) *lo = dMax(*lo, f0 / (f0 - f1));
        else if (f1 < 0) *hi = dMin(*hi, f0 / (f0 - f1));
    }
    return *lo <= *hi;
}

// (The walk has left out a triangle whose plane the centre is below.)
static int capsule_test(dxTriQuery *q, const dxTri *t)
{
    const dxCapsule *cap = (const dxCapsule *)q->other;
    dReal r = cap->radius, half = cap->length / 2, a[3], p0[3], p1[3];
    dx_axis(q->R, 2, a);
    for (int i = 0; i < 3; i++) {
        p0[i] = q->pos[i] - half * a[i];
        p1[i] = q->pos[i] + half * a[i];
    }
    if (dMin(dxTriHeight(t, p0), dxTriHeight(t, p1)) > r) return 0;
    dReal lo, hi;
    int added = 0;
    if (clip_to_prism(t, p0, p1, DX_COLLIDE_EPS * q->scale, &lo, &hi)) {
        dReal s[2] = { lo, hi };
        for (int j = 0; j < (hi - lo > DX_COLLIDE_EPS ? 2 : 1); j++) {
            dReal e[3], pos[3];
            for (int i = 0; i < 3; i++) e[i] = p0[i] + s[j] * (p1[i] - p0[i]);
            dReal depth = r - dxTriHeight(t, e);
            if (depth < 0) continue;
            for (int i = 0; i < 3; i++) pos[i] = e[i] - r * t->n[i];
            dxTriAdd(q, pos, t->n, depth, t->index);
            added = 1;
        }
        if (added) return 1;
    }
    // The closest points of the axis and the triangle's edges.
    dReal best = dInfinity, ps[3], pt[3];
    int feature = 0;
    for (int k = 0; k < 3; k++) {
        const dReal *va = t->v[k], *vb = t->v[(k + 1) % 3];
        dReal ec[3], eu[3];
        sub3(eu, vb, va);
        dReal elen = dSqrt(dx_dot(eu, eu));
        for (int i = 0; i < 3; i++) {
            ec[i] = (va[i] + vb[i]) / 2;
            eu[i] /= elen;
        }
        dReal s, u;
        dx_closest_segments(q->pos, a, half, ec, eu, elen / 2, &s, &u);
        dReal x[3], y[3], d[3];
        for (int i = 0; i < 3; i++) {
            x[i] = q->pos[i] + s * a[i];
            y[i] = ec[i] + u * eu[i];
        }
        sub3(d, x, y);
        dReal dd = dx_dot(d, d);
        if (dd < best) {
            best = dd;
            for (int i = 0; i < 3; i++) {
                ps[i] = x[i];
                pt[i] = y[i];
            }
            dReal end = elen / 2 * (1 - DX_COLLIDE_EPS);
            feature = u <= -end ? 4 + k : u >= end ? 4 + (k + 1) % 3 : 1 + k;
        }
    }
    if (best > r * r || dxTriHeight(t, ps) < 0) return 0;
    dReal d[3];
    sub3(d, ps, pt);
    return ball_contact(q, t, ps, r, d, feature);
}

int dxCollideTriMeshCapsule(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return dxTriMeshCollide(o1, o2, flags, c, skip, dInfinity, capsule_test);
}

// ---- box --------------------------------------------------------------------------

// The interval of triangle t's projection on the axis L.
static void triangle_interval(const dxTri *t, const dReal L[3], dReal *lo, dReal *hi)
{
    dReal t0 = dx_dot(L, t->v[0]), t1 = dx_dot(L, t->v[1]), t2 = dx_dot(L, t->v[2]);
    *lo = dMin(t0, dMin(t1, t2));
    *hi = dMax(t0, dMax(t1, t2));
}

// Whether the axis L separates the triangle from the cylinder (centre c,
// unit axis a, radius r, half length h): its projection reaches
// h |L.a| + r sqrt(|L|^2 - (L.a)^2) from the centre's.
static int separates_cylinder(const dxTri *t, const dReal L[3], const dReal c[3],
                              const dReal a[3], dReal r, dReal h)
{
    dReal len2 = dx_dot(L, L);
    if (len2 <= DX_COLLIDE_EPS * DX_COLLIDE_EPS) return 0;
    dReal la = dx_dot(L, a), lo, hi, bc = dx_dot(L, c);
    dReal across = len2 - la * la;
    dReal br = h * dFabs(la) + r * dSqrt(across > 0 ? across : 0);
    triangle_interval(t, L, &lo, &hi);
    return hi < bc - br || lo > bc + br;
}

// A cylinder's cap has CYL_SIDES corners (a polygon clipped to a prism
// gains at most three).
enum { CYL_SIDES = 32, POLY_MAX = DX_TRI_POLY_MAX };

// ---- clipping to a triangle's prism ------------------------------------------

// A side of the prism for clip_polygon's measures m . (x - o) + slack,
// in dx_dot's order ((x + y) + z); with SSE2 (double) x and y side by
// side, loaded once a clip: the same differences, products and sums.
typedef struct clip_side {
#if defined(__SSE2__) && !defined(dSINGLE)
    __m128d m01, o01;
    dReal m2, o2;
#else
    const dReal *m, *o;
#endif
    dReal slack;
} clip_side;

static inline __attribute__((always_inline)) clip_side
clip_side_set(const dReal m[3], const dReal o[3], dReal slack)
{
#if defined(__SSE2__) && !defined(dSINGLE)
    return (clip_side){ _mm_loadu_pd(m), _mm_loadu_pd(o), m[2], o[2], slack };
#else
    return (clip_side){ m, o, slack };
#endif
}

static inline __attribute__((always_inline)) dReal clip_measure(const dReal *x,
                                                                const clip_side *k)
{
#if defined(__SSE2__) && !defined(dSINGLE)
    const __m128d p = _mm_mul_pd(k->m01, _mm_sub_pd(_mm_loadu_pd(x), k->o01));
    return (_mm_cvtsd_f64(p) + _mm_cvtsd_f64(_mm_unpackhi_pd(p, p)) + k->m2 * (x[2] - k->o2)) +
           k->slack;
#else
    const dReal d[3] = { x[0] - k->o[0], x[1] - k->o[1], x[2] - k->o[2] };
    return dx_dot(k->m, d) + k->slack;
#endif
}

// Keep the part of the polygon pt (n points, tags tp) where
// m . (x - o) >= -slack, into npt and ntp: a point kept keeps its pointer
// and tag, a point made on this boundary (into c->room) gets the tag
// `made`. Returns the new count, or -1 (nothing written that the caller
// reads) if every point is kept as it is; 0 if the result has more than
// DX_TRI_POLY_MAX points (a polygon crossing the boundary more often than
// a convex one can; npt and ntp have room for twice n). Inline in its one
// caller: its lists and the result's pointers stay in registers.
static inline __attribute__((always_inline)) int
clip_polygon(const dReal *const *pt, const int *tp, int n, const dReal m[3], const dReal o[3],
             dReal slack, int made, dxTriClipped *c, const dReal **npt, int *ntp)
{
    dReal f[DX_TRI_POLY_MAX];
    // One pass over the points: each point's measure, then (the points'
    // sides follow the data, so without branching on them) the place of
    // the point made on the edge from the one before, which moves on only
    // if that edge crosses (the two on different sides; its room, taken in
    // order), then the point itself at the list's next place, which moves
    // on only if it is kept (k: the next place). The edge from
    // the last point to the first closes the list. from[j]: the first point
    // of the j-th crossing edge (edge i: from point i to the next), written
    // at every edge and counted if it crosses.
    const clip_side side = clip_side_set(m, o, slack);
    // (Indices as wide as pointers: no sign extension in the loop.)
    int from[DX_TRI_POLY_MAX];
    ptrdiff_t crossings = 0, k;
    f[0] = clip_measure(pt[0], &side);
    const unsigned first_in = f[0] >= 0;
    unsigned was_in = first_in;
    const dReal *room = c->room[c->made_count];
    npt[0] = pt[0];
    ntp[0] = tp[0];
    k = first_in;
    for (int i = 1; i < n; i++) {
        const dReal *x = pt[i];   // (read before the stores, which may alias)
        const int tag = tp[i];
        f[i] = clip_measure(x, &side);
        const unsigned in = f[i] >= 0, cross = in ^ was_in;
        from[crossings] = i - 1;
        crossings += cross;
        npt[k] = room;
        ntp[k] = made;
        k += cross;
        room += 3 * cross;
        npt[k] = x;
        ntp[k] = tag;
        k += in;
        was_in = in;
    }
    npt[k] = room;
    ntp[k] = made;
    from[crossings] = n - 1;
    crossings += was_in ^ first_in;
    k += was_in ^ first_in;
    if (!crossings && first_in) return -1;   // every point kept
    // The points made on the crossing edges, into their room in the same
    // order (two for a convex polygon).
    for (ptrdiff_t e = 0; e < crossings; e++) {
        // (The edge's end wraps to 0 after the last point: masked, not
        // branched on; which edge is the closing one follows the data.)
        const int i = from[e], next = (i + 1) & -(i + 1 < n);
        const dReal *a = pt[i], *b = pt[next], fa = f[i], fb = f[next];
        dReal s = fa / (fa - fb), *x = c->room[c->made_count++];
#if defined(__SSE2__) && !defined(dSINGLE)
        const __m128d a01 = _mm_loadu_pd(a);   // x and y side by side: the same sums
        _mm_storeu_pd(x, _mm_add_pd(a01, _mm_mul_pd(_mm_set1_pd(s),
                                                    _mm_sub_pd(_mm_loadu_pd(b), a01))));
        x[2] = a[2] + s * (b[2] - a[2]);
#else
        for (int j = 0; j < 3; j++) x[j] = a[j] + s * (b[j] - a[j]);
#endif
    }
    return k <= DX_TRI_POLY_MAX ? (int)k : 0;
}

// dxTriClipToPrismWith, inline in the box's and the faces' clips.
static inline __attribute__((always_inline)) int
clip_to_prism_with(const dxTriPrism *p, const dxTri *t, const dReal *const *corner,
                   const int *made, int n, unsigned inside, dxTriClipped *c)
{
    // From one list into the other working list (out), which then holds
    // the polygon, and the lists swap; unchanged clips leave it where it is.
    const dReal *const *pt = corner;
    const int *tp = made;
    const dReal **out = c->list[0], **spare = c->list[1];
    int *out_tag = c->tags[0], *spare_tag = c->tags[1];
    c->made_count = 0;
    for (unsigned sides = ~inside & 7; sides && n > 0; sides &= sides - 1) {
        const int k = __builtin_ctz(sides);
        const int m = clip_polygon(pt, tp, n, p->m[k], t->v[k], p->slack[k], p->made[k], c,
                                   out, out_tag);
        if (m < 0) continue;   // unchanged
        const dReal **full = out;
        int *full_tag = out_tag;
        out = spare;
        out_tag = spare_tag;
        spare = full;
        spare_tag = full_tag;
        n = m;
        pt = full;
        tp = full_tag;
    }
    c->pt = pt;
    c->made = tp;
    c->n = n;
    return n;
}

int dxTriClipToPrismWith(const dxTriPrism *p, const dxTri *t, const dReal *const *corner,
                         const int *made, int n, unsigned inside, dxTriClipped *c)
{
    return clip_to_prism_with(p, t, corner, made, n, inside, c);
}

// A clip tag's bits for clipped_face_contacts: a box corner's own bit
// (DX_TRI_MADE_CORNER + v: bit v, the `seen` bit), TAG_FLAT for a point
// made at a flat edge (never added), none for the rest.
enum { TAG_FLAT = 1u << 8 };
static const unsigned tag_bits[DX_TRI_MADE_CORNER + 8] = {
    [DX_TRI_MADE_AT_FLAT_EDGE] = TAG_FLAT,
    [DX_TRI_MADE_CORNER] = 1,        [DX_TRI_MADE_CORNER + 1] = 2,
    [DX_TRI_MADE_CORNER + 2] = 4,    [DX_TRI_MADE_CORNER + 3] = 8,
    [DX_TRI_MADE_CORNER + 4] = 16,   [DX_TRI_MADE_CORNER + 5] = 32,
    [DX_TRI_MADE_CORNER + 6] = 64,   [DX_TRI_MADE_CORNER + 7] = 128,
};

// One face (n corners, pointers to them in corner[], at least one of them
// on or behind the triangle's plane) of a convex solid against triangle t
// (prism p): clipped to the triangle's prism (widened by rounding), its
// points on or behind the triangle's plane are contacts with the face
// normal and their depth below the plane (where the face crosses the plane
// the depth is zero and adds nothing). Points made on the prism's side at
// a flat edge are left out: they are corners of the triangulation, not of
// the contact patch (the corners of the solid over the neighbour come from
// it). made[]: the corners' tags (dxTriClipToPrismWith; a corner's tag
// is one of a box's eight, DX_TRI_MADE_CORNER + v with v < 8); with
// `seen`, a corner tagged DX_TRI_MADE_CORNER + v that bit v of *seen says
// was added already (by another face of the solid, against the same
// triangle: the same point, depth and normal to the bit) is not added
// again, and a corner added sets its bit. Returns 1 if any was added. Inline in its
// callers: box_test's pointers, `seen` and the prism stay in registers.
static inline __attribute__((always_inline)) int
clipped_face_contacts(dxTriQuery *q, const dxTri *t, const dxTriPrism *p,
                      const dReal *const *corner, const int *made, int n, unsigned inside,
                      unsigned *seen)
{
    dReal eps = DX_COLLIDE_EPS * q->scale;
    dxTriClipped c;
    n = clip_to_prism_with(p, t, corner, made, n, inside, &c);
    // Which points are added follows the data: they are listed without
    // branches (each written at the list's next place, which moves on only
    // if it is added: not at a flat edge, not a corner seen already, not
    // above the plane by more than eps), then their contacts written; a
    // corner is in the clip's list once at most, so the seen bits are
    // updated after.
    const unsigned was = seen ? *seen : 0;
    int added[2 * DX_TRI_POLY_MAX];   // the points added, in order
    ptrdiff_t count = 0;
    dReal height[2 * DX_TRI_POLY_MAX];
#if defined(__SSE2__) && !defined(dSINGLE)
    const __m128d n01 = _mm_loadu_pd(t->n), v01 = _mm_loadu_pd(t->v[0]);
#endif
    for (int i = 0; i < n; i++) {
        const unsigned bits = tag_bits[c.made[i]];
        const dReal *x = c.pt[i];
#if defined(__SSE2__) && !defined(dSINGLE)
        // dxTriHeight with x and y side by side: the same sums.
        const __m128d d = _mm_mul_pd(n01, _mm_sub_pd(_mm_loadu_pd(x), v01));
        height[i] = _mm_cvtsd_f64(d) + _mm_cvtsd_f64(_mm_unpackhi_pd(d, d)) +
                    t->n[2] * (x[2] - t->v[0][2]);
#else
        height[i] = dxTriHeight(t, x);
#endif
        // (-height < -eps is height > eps, NaN included: negation is exact.)
        added[count] = i;
        count += !((was | TAG_FLAT) & bits) & !(height[i] > eps);
    }
    if (!count) return 0;
    // The contacts of the points added, with room made once, and their
    // corners' seen bits.
    dxTriScratch *s = q->s;
    if (s->raw_count + count > s->raw_cap) dxTriScratchAddRaw(s, (int)count);
    dxTriMeshRaw *r = s->raw + s->raw_count;
    s->raw_count += (int)count;
    unsigned now = was;
    for (ptrdiff_t e = 0; e < count; e++, r++) {
        const int i = added[e];
        now |= tag_bits[c.made[i]];
        for (int k = 0; k < 3; k++) {
            r->pos[k] = c.pt[i][k];
            r->n[k] = t->n[k];
        }
        r->depth = dMax(-height[i], 0);
        r->tri = t->index;
        r->tri2 = -1;
    }
    if (seen) *seen = now;
    return 1;
}

// The same for any face (polygon a): one wholly in front of the plane adds
// nothing (clipping keeps points within the polygon), so it is not clipped.
static int face_contacts(dxTriQuery *q, const dxTri *t, const dxTriPrism *p, dReal a[][3],
                         int n)
{
    dReal eps = DX_COLLIDE_EPS * q->scale;
    int behind = 0;
    for (int i = 0; i < n && !behind; i++) behind = dxTriHeight(t, a[i]) <= eps;
    if (!behind) return 0;
    const dReal *corner[POLY_MAX];
    int made[POLY_MAX];
    for (int i = 0; i < n; i++) {
        corner[i] = a[i];
        made[i] = DX_TRI_MADE_NOT;
    }
    return clipped_face_contacts(q, t, p, corner, made, n, 0, NULL);
}

// The eight sums x + (+-d0) + (+-d1) + (+-d2), bit j of the index picking
// the sign of d_j, into out: each summed left to right as written, the
// partial sums shared (the same numbers as the eight sums one by one).
// With SSE2 (double) two neighbouring corners at a time: the same sums.
static inline void corner_sums(dReal x, const dReal d[3], dReal out[8])
{
#if defined(__SSE2__) && !defined(dSINGLE)
    const __m128d a = _mm_add_pd(_mm_set1_pd(x), _mm_set_pd(d[0], -d[0]));
    const __m128d d1 = _mm_set1_pd(d[1]), d2 = _mm_set1_pd(d[2]);
    const __m128d b0 = _mm_sub_pd(a, d1), b1 = _mm_add_pd(a, d1);
    _mm_storeu_pd(out, _mm_sub_pd(b0, d2));
    _mm_storeu_pd(out + 2, _mm_sub_pd(b1, d2));
    _mm_storeu_pd(out + 4, _mm_add_pd(b0, d2));
    _mm_storeu_pd(out + 6, _mm_add_pd(b1, d2));
#else
    dReal a[2] = { x - d[0], x + d[0] }, b[4];
    for (int v = 0; v < 4; v++) b[v] = a[v & 1] + (v & 2 ? d[1] : -d[1]);
    for (int v = 0; v < 8; v++) out[v] = b[v & 3] + (v & 4 ? d[2] : -d[2]);
#endif
}

// A box's faces as corner numbers (in order round the face), as bit
// masks of those corners, and the clip's tags of their corners.
static const int box_faces[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 },
                                     { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
static const unsigned box_face_mask[6] = { 0x55, 0xaa, 0x33, 0xcc, 0x0f, 0xf0 };
#define BOX_MADE(a, b, c, d)                                                               \
    { DX_TRI_MADE_CORNER + (a), DX_TRI_MADE_CORNER + (b), DX_TRI_MADE_CORNER + (c),         \
      DX_TRI_MADE_CORNER + (d) }
static const int box_face_made[6][4] = { BOX_MADE(0, 2, 6, 4), BOX_MADE(1, 3, 7, 5),
                                         BOX_MADE(0, 1, 5, 4), BOX_MADE(2, 3, 7, 6),
                                         BOX_MADE(0, 1, 3, 2), BOX_MADE(4, 5, 7, 6) };
#undef BOX_MADE

// A box's values for a pair, worked out on its first triangle (in q->s->pair):
// unit axes, half sides and corners (bit j of the index picks the sign of
// axis j); inner[j]: h[j] less the margin within which a point counts as
// inside the box whatever the rounding (box_separated); through[j] the
// same with a wider margin, for a point of a triangle's edge whose ends are
// at most `reach` from the centre along each axis. ax01[k]: component k of
// axes 0 and 1 side by side. face_corner[f]: face f's corners (box_faces).
typedef struct box_pair {
    dReal ax[3][3], h[3], corner[8][3], inner[3], through[3], reach, ax01[3][2];
    const dReal *face_corner[6][4];
} box_pair;
_Static_assert(sizeof(box_pair) <= sizeof(((dxTriScratch *)0)->pair), "box_pair fits");

// box_pair's values into q->s->pair, once a pair (out of line: box_test,
// run for every triangle, keeps its registers and stack for the triangles).
static __attribute__((noinline)) void work_out_box(dxTriQuery *q)
{
    box_pair *b = (box_pair *)q->s->pair;
    const dReal *side = ((const dxBox *)q->other)->side, *c = q->pos;
    for (int j = 0; j < 3; j++) {
        b->h[j] = side[j] / 2;
        dx_axis(q->R, j, b->ax[j]);
    }
    for (int k = 0; k < 3; k++) {
        b->ax01[k][0] = b->ax[0][k];
        b->ax01[k][1] = b->ax[1][k];
    }
    const dReal *h = b->h;
    // The margin: 128 roundings of the largest number in the edge pairs
    // sums (a point inside the box is within |c| + h of 0).
    dReal eps = sizeof(dReal) == sizeof(double) ? (dReal)DBL_EPSILON : (dReal)FLT_EPSILON;
    dReal size = dMax(dFabs(c[0]), dMax(dFabs(c[1]), dFabs(c[2]))) + h[0] + h[1] + h[2];
    for (int j = 0; j < 3; j++) {
        b->inner[j] = h[j] - 128 * eps * size;
        b->through[j] = h[j] - 1024 * eps * size;
    }
    b->reach = 2 * (h[0] + h[1] + h[2]);
    // Corner v's coordinate i: c[i] + (+-h0) ax0[i] + (+-h1) ax1[i] +
    // (+-h2) ax2[i], summed left to right ((-h) a is -(h a): the same
    // numbers), the eight of a coordinate with their partial sums shared.
    for (int i = 0; i < 3; i++) {
        const dReal d[3] = { h[0] * b->ax[0][i], h[1] * b->ax[1][i], h[2] * b->ax[2][i] };
        dReal x[8];
        corner_sums(c[i], d, x);
        for (int v = 0; v < 8; v++) b->corner[v][i] = x[v];
    }
    for (int f = 0; f < 6; f++)
        for (int i = 0; i < 4; i++) b->face_corner[f][i] = b->corner[box_faces[f][i]];
    q->prepared = 1;
}

// The pair's box_pair, worked out on the first call.
static inline const box_pair *prepare_box(dxTriQuery *q)
{
    if (!q->prepared) work_out_box(q);
    return (const box_pair *)q->s->pair;
}

// Whether the axis L (mesh frame) separates the triangle from the box
// (centre c, unit axes ax[j], half sides h[j]).
static int separates_box(const dxTri *t, const dReal L[3], const dReal c[3],
                         const dReal ax[3][3], const dReal h[3])
{
    if (dx_dot(L, L) <= DX_COLLIDE_EPS * DX_COLLIDE_EPS) return 0;   // parallel edges
    dReal lo, hi, bc = dx_dot(L, c), br = 0;
    triangle_interval(t, L, &lo, &hi);
    for (int j = 0; j < 3; j++) br += h[j] * dFabs(dx_dot(L, ax[j]));
    return hi < bc - br || lo > bc + br;
}

#if defined(__SSE2__) && !defined(dSINGLE)
// separates_box for the axes e x ax[0] and e x ax[1] side by side (SSE2):
// whether either separates, from the same sums (dMin(x, y) is
// _mm_min_pd(x, y) and dMax(x, y) _mm_max_pd(y, x), NaN included).
static int separates_box01(const box_pair *b, const dxTri *t, const dReal e[3],
                           const dReal c[3])
{
    const __m128d a0 = _mm_loadu_pd(b->ax01[0]), a1 = _mm_loadu_pd(b->ax01[1]),
                  a2 = _mm_loadu_pd(b->ax01[2]);
    const __m128d e0 = _mm_set1_pd(e[0]), e1 = _mm_set1_pd(e[1]), e2 = _mm_set1_pd(e[2]);
    // L = e x ax_j, component by component as cross3.
    const __m128d l0 = _mm_sub_pd(_mm_mul_pd(e1, a2), _mm_mul_pd(e2, a1));
    const __m128d l1 = _mm_sub_pd(_mm_mul_pd(e2, a0), _mm_mul_pd(e0, a2));
    const __m128d l2 = _mm_sub_pd(_mm_mul_pd(e0, a1), _mm_mul_pd(e1, a0));
#define DOT_L(x)                                                                           \
    _mm_add_pd(_mm_add_pd(_mm_mul_pd(l0, _mm_set1_pd((x)[0])),                              \
                          _mm_mul_pd(l1, _mm_set1_pd((x)[1]))),                             \
               _mm_mul_pd(l2, _mm_set1_pd((x)[2])))
    const __m128d len2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(l0, l0), _mm_mul_pd(l1, l1)),
                                    _mm_mul_pd(l2, l2));
    const __m128d live = _mm_cmpgt_pd(len2, _mm_set1_pd(DX_COLLIDE_EPS * DX_COLLIDE_EPS));
    const __m128d bc = DOT_L(c), t0 = DOT_L(t->v[0]), t1 = DOT_L(t->v[1]), t2 = DOT_L(t->v[2]);
    const __m128d lo = _mm_min_pd(t0, _mm_min_pd(t1, t2));
    const __m128d hi = _mm_max_pd(_mm_max_pd(t2, t1), t0);
    const __m128d sign = _mm_set1_pd(-0.0);
    __m128d br = _mm_mul_pd(_mm_set1_pd(b->h[0]), _mm_andnot_pd(sign, DOT_L(b->ax[0])));
    br = _mm_add_pd(br, _mm_mul_pd(_mm_set1_pd(b->h[1]), _mm_andnot_pd(sign, DOT_L(b->ax[1]))));
    br = _mm_add_pd(br, _mm_mul_pd(_mm_set1_pd(b->h[2]), _mm_andnot_pd(sign, DOT_L(b->ax[2]))));
#undef DOT_L
    const __m128d apart = _mm_or_pd(_mm_cmplt_pd(hi, _mm_sub_pd(bc, br)),
                                    _mm_cmpgt_pd(lo, _mm_add_pd(bc, br)));
    return _mm_movemask_pd(_mm_and_pd(live, apart)) != 0;
}
#endif

// Whether the triangle's edge from a to e (box frame) has a point inside
// the box by more than the margin b->through: then, as for a vertex inside
// (box_separated), no axis can part them. The point is the middle of the
// edge's part within the three slabs |x_j| <= through[j], checked where it
// is worked out. Only for an edge whose ends are within b->reach of the
// centre along each axis and not both beyond one side of a slab (the
// caller checks: then no point of the edge is within, as the slabs' test
// below would say after its divisions), so that its ends' coordinates
// (and the sums that test an axis) are rounded by far less than the
// margin: 1024 roundings of |c| + h, where the ends are within
// 3.5 (h0 + h1 + h2) of c.
static int edge_through(const box_pair *b, const dReal a[3], const dReal e[3])
{
    dReal d[3] = { e[0] - a[0], e[1] - a[1], e[2] - a[2] }, s0 = 0, s1 = 1;
    for (int j = 0; j < 3; j++) {
        dReal w = b->through[j];
        if (d[j] == 0) {
            if (!(dFabs(a[j]) <= w)) return 0;
            continue;
        }
        dReal inv = 1 / d[j], t0 = (-w - a[j]) * inv, t1 = (w - a[j]) * inv;
        s0 = dMax(s0, dMin(t0, t1));
        s1 = dMin(s1, dMax(t0, t1));
        if (!(s0 <= s1)) return 0;   // (the slabs met so far already miss)
    }
    dReal s = (s0 + s1) / 2;
    for (int j = 0; j < 3; j++)
        if (!(dFabs(a[j] + s * d[j]) <= b->through[j])) return 0;
    return 1;
}

// Where each vertex of a triangle lies against the box b (p[i][j]:
// vertex i's coordinate along axis j), as bits of where[i]: bit j (j < 3)
// beyond the side +through[j] of slab j, bit 3 + j beyond -through[j],
// bit 6 within b->reach of the centre along each axis. Returns whether a
// vertex is inside the box by more than the margin (|p[i][j]| <= inner[j]
// for each j). With SSE2 (double) the comparisons of axes 0 and 1 side by
// side: the same comparisons (NaN makes each false, as one by one).
static inline int vertex_classes(const box_pair *b, const dReal p[3][3], unsigned where[3])
{
    const dReal *in = b->inner, *w = b->through, reach = b->reach;
    int inner = 0;
#if defined(__SSE2__) && !defined(dSINGLE)
    const __m128d sign = _mm_set1_pd(-0.0), w01 = _mm_loadu_pd(w), in01 = _mm_loadu_pd(in);
    const __m128d mw01 = _mm_xor_pd(w01, sign), reach01 = _mm_set1_pd(reach);
    for (int i = 0; i < 3; i++) {
        const __m128d x = _mm_loadu_pd(p[i]), ax = _mm_andnot_pd(sign, x);
        const dReal z = p[i][2], az = dFabs(z);
        const unsigned beyond = (unsigned)_mm_movemask_pd(_mm_cmpgt_pd(x, w01)) |
                                (unsigned)(z > w[2]) << 2 |
                                (unsigned)_mm_movemask_pd(_mm_cmplt_pd(x, mw01)) << 3 |
                                (unsigned)(z < -w[2]) << 5;
        const unsigned near = (unsigned)_mm_movemask_pd(_mm_cmple_pd(ax, reach01)) |
                              (unsigned)(az <= reach) << 2;
        inner |= (_mm_movemask_pd(_mm_cmple_pd(ax, in01)) == 3) & (az <= in[2]);
        where[i] = beyond | (unsigned)(near == 7) << 6;
    }
#else
    for (int i = 0; i < 3; i++) {
        unsigned beyond = 0, near = 1, in_all = 1;
        for (int j = 0; j < 3; j++) {
            const dReal x = p[i][j], ax = dFabs(x);
            beyond |= (unsigned)(x > w[j]) << j | (unsigned)(x < -w[j]) << (3 + j);
            near &= ax <= reach;
            in_all &= ax <= in[j];
        }
        inner |= (int)in_all;
        where[i] = beyond | near << 6;
    }
#endif
    return inner;
}

// Whether edge_through is to look at the edge between vertices classed
// wa and wb: both ends near, not both beyond one side of a slab.
static inline int edge_may_pass(unsigned wa, unsigned wb)
{
    return (wa & wb) == 1u << 6;
}

// Whether a separating axis parts the box b (centre c) from triangle t,
// whose plane the centre is hc above (hc >= 0): in the order of what they
// reject in a rain of boxes on terrain (of the triangles left after the
// bounding boxes: most by the triangle's normal, then the box's axes, few
// by the edge pairs). The normal and the box's axes are tested with the
// triangle in the box's frame, where the box is [-h, h]; the edge pairs in
// the mesh frame, from the edges as they are there (worked out in the
// box's frame from the vertices there, they judged a box sliding over a
// grid mesh otherwise in single precision and let it bump:
// tests/test_trimesh_motion.c). nb: the normal in the box's frame.
static int box_separated(const box_pair *b, const dxTri *t, const dReal c[3], dReal hc,
                         dReal nb[3])
{
    const dReal *h = b->h;
    dReal p[3][3];   // vertex i's coordinate j
#if defined(__SSE2__) && !defined(dSINGLE)
    // Axes 0 and 1 side by side, axis 2 alone: the same sums. dMax(x, y)
    // is _mm_max_pd(y, x) and dMin(x, y) _mm_min_pd(x, y), NaN included
    // (they differ only in the sign of a zero, which no comparison sees).
    const __m128d a0 = _mm_loadu_pd(b->ax01[0]), a1 = _mm_loadu_pd(b->ax01[1]),
                  a2 = _mm_loadu_pd(b->ax01[2]);
    const __m128d n01 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(t->n[0]), a0),
                                              _mm_mul_pd(_mm_set1_pd(t->n[1]), a1)),
                                   _mm_mul_pd(_mm_set1_pd(t->n[2]), a2));
    _mm_storeu_pd(nb, n01);
    nb[2] = dx_dot(t->n, b->ax[2]);
    if (hc > h[0] * dFabs(nb[0]) + h[1] * dFabs(nb[1]) + h[2] * dFabs(nb[2])) return 1;
    __m128d p01[3];
    for (int i = 0; i < 3; i++) {
        dReal d[3];
        sub3(d, t->v[i], c);
        p01[i] = _mm_add_pd(_mm_add_pd(_mm_mul_pd(a0, _mm_set1_pd(d[0])),
                                       _mm_mul_pd(a1, _mm_set1_pd(d[1]))),
                            _mm_mul_pd(a2, _mm_set1_pd(d[2])));
        _mm_storeu_pd(p[i], p01[i]);
        p[i][2] = dx_dot(b->ax[2], d);
    }
    const __m128d hi01 = _mm_loadu_pd(h), lo01 = _mm_sub_pd(_mm_setzero_pd(), hi01);
    const __m128d mx = _mm_max_pd(_mm_max_pd(p01[2], p01[1]), p01[0]);
    const __m128d mn = _mm_min_pd(p01[0], _mm_min_pd(p01[1], p01[2]));
    if (_mm_movemask_pd(_mm_or_pd(_mm_cmplt_pd(mx, lo01), _mm_cmpgt_pd(mn, hi01))) ||
        dMax(p[0][2], dMax(p[1][2], p[2][2])) < -h[2] ||
        dMin(p[0][2], dMin(p[1][2], p[2][2])) > h[2])
        return 1;
#else
    for (int j = 0; j < 3; j++) nb[j] = dx_dot(t->n, b->ax[j]);
    if (hc > h[0] * dFabs(nb[0]) + h[1] * dFabs(nb[1]) + h[2] * dFabs(nb[2])) return 1;
    for (int i = 0; i < 3; i++) {
        dReal d[3];
        sub3(d, t->v[i], c);
        for (int j = 0; j < 3; j++) p[i][j] = dx_dot(b->ax[j], d);
    }
    for (int j = 0; j < 3; j++)
        if (dMax(p[0][j], dMax(p[1][j], p[2][j])) < -h[j] ||
            dMin(p[0][j], dMin(p[1][j], p[2][j])) > h[j])
            return 1;
#endif
    // A vertex inside the box by more than the margin lies, on every axis
    // L, within the box's interval by at least the margin times |L| (the
    // box's |L . a_j| sum to at least |L|), far beyond the rounding of the
    // sums below: no edge pair can separate, and they are not worked out.
    // Else an edge may pass through the box (edge_through).
    unsigned where[3];
    if (vertex_classes(b, p, where)) return 0;
    for (int k = 0; k < 3; k++) {
        const int k1 = k < 2 ? k + 1 : 0;
        if (edge_may_pass(where[k], where[k1]) && edge_through(b, p[k], p[k1])) return 0;
    }
    for (int k = 0; k < 3; k++) {
        dReal e[3], L[3];
        sub3(e, t->v[(k + 1) % 3], t->v[k]);
#if defined(__SSE2__) && !defined(dSINGLE)
        if (separates_box01(b, t, e, c)) return 1;
        cross3(L, e, b->ax[2]);
        if (separates_box(t, L, c, b->ax, h)) return 1;
#else
        for (int j = 0; j < 3; j++) {
            cross3(L, e, b->ax[j]);
            if (separates_box(t, L, c, b->ax, h)) return 1;
        }
#endif
    }
    return 0;
}

// Bit v set where x[v] < lim (of eight numbers), where x[v] >= lim, where
// x[v] <= lim (false for NaN, as the comparisons one by one). With SSE2 the
// low halves of four comparisons' 64-bit masks are gathered as four 32-bit
// ones (a shuffle), so that one movemask gives four bits.
#if defined(__SSE2__) && !defined(dSINGLE)
static inline unsigned four_bits(__m128d m01, __m128d m23)
{
    return (unsigned)_mm_movemask_ps(
        _mm_shuffle_ps(_mm_castpd_ps(m01), _mm_castpd_ps(m23), _MM_SHUFFLE(2, 0, 2, 0)));
}
#define EIGHT_BITS(x, lim, cmp)                                                            \
    (four_bits(cmp(_mm_loadu_pd(x), lim), cmp(_mm_loadu_pd((x) + 2), lim)) |               \
     four_bits(cmp(_mm_loadu_pd((x) + 4), lim), cmp(_mm_loadu_pd((x) + 6), lim)) << 4)
static inline unsigned bits_below(const dReal x[8], dReal lim)
{
    return EIGHT_BITS(x, _mm_set1_pd(lim), _mm_cmplt_pd);
}
static inline unsigned bits_at_least(const dReal x[8], dReal lim)
{
    return EIGHT_BITS(x, _mm_set1_pd(lim), _mm_cmpge_pd);
}
static inline unsigned bits_at_most(const dReal x[8], dReal lim)
{
    return EIGHT_BITS(x, _mm_set1_pd(lim), _mm_cmple_pd);
}
#undef EIGHT_BITS
#else
static inline unsigned bits_below(const dReal x[8], dReal lim)
{
    unsigned bits = 0;
    for (int v = 0; v < 8; v++)
        if (x[v] < lim) bits |= 1u << v;
    return bits;
}
static inline unsigned bits_at_least(const dReal x[8], dReal lim)
{
    unsigned bits = 0;
    for (int v = 0; v < 8; v++)
        if (x[v] >= lim) bits |= 1u << v;
    return bits;
}
static inline unsigned bits_at_most(const dReal x[8], dReal lim)
{
    unsigned bits = 0;
    for (int v = 0; v < 8; v++)
        if (x[v] <= lim) bits |= 1u << v;
    return bits;
}
#endif


// The faces whose four corners are all in the corner set m (bit v: corner
// v), face f as bit 3 f: three sets of faces, one for each prism side k,
// fit side by side (bit 3 f + k) and a face's three read as one number.
// A face has a corner in m when not all of its corners are in the rest.
#define FACES_ALL_OF(m)                                                                    \
    ((((m) & 0x55) == 0x55) | (((m) & 0xaa) == 0xaa) << 3 | (((m) & 0x33) == 0x33) << 6 |   \
     (((m) & 0xcc) == 0xcc) << 9 | (((m) & 0x0f) == 0x0f) << 12 | (((m) & 0xf0) == 0xf0) << 15)
#define FACES_4(m) FACES_ALL_OF(m), FACES_ALL_OF((m) + 1), FACES_ALL_OF((m) + 2), FACES_ALL_OF((m) + 3)
#define FACES_16(m) FACES_4(m), FACES_4((m) + 4), FACES_4((m) + 8), FACES_4((m) + 12)
#define FACES_64(m) FACES_16(m), FACES_16((m) + 16), FACES_16((m) + 32), FACES_16((m) + 48)
static const uint32_t faces_all_of[256] = { FACES_64(0), FACES_64(64), FACES_64(128),
                                            FACES_64(192) };
#undef FACES_64
#undef FACES_16
#undef FACES_4
#undef FACES_ALL_OF
enum { EVERY_FACE = 0x9249 };   // bit 3 f for each of the six faces

// The three sets of faces all of whose corners in `low` are in m[k] (or,
// what is the same, none of whose low corners is outside m[k]), side k's
// at bit 3 f + k.
static inline uint32_t faces_low_in(unsigned low, const unsigned m[3])
{
    return faces_all_of[(~low | m[0]) & 0xff] | faces_all_of[(~low | m[1]) & 0xff] << 1 |
           faces_all_of[(~low | m[2]) & 0xff] << 2;
}

// face_crossings[f][m]: the edges of box face f whose ends differ in the
// corner set m (bit v: corner v), bit i for the edge from its corner i
// (box_faces) to the next.
#define CROSSES(m, u, x) (((m) >> (u) ^ (m) >> (x)) & 1)
#define FACE_CROSSINGS(m, a, b, c, d)                                                      \
    (CROSSES(m, a, b) | CROSSES(m, b, c) << 1 | CROSSES(m, c, d) << 2 | CROSSES(m, d, a) << 3)
#define CROSS_4(m, ...)                                                                    \
    FACE_CROSSINGS(m, __VA_ARGS__), FACE_CROSSINGS((m) + 1, __VA_ARGS__),                    \
        FACE_CROSSINGS((m) + 2, __VA_ARGS__), FACE_CROSSINGS((m) + 3, __VA_ARGS__)
#define CROSS_16(m, ...)                                                                   \
    CROSS_4(m, __VA_ARGS__), CROSS_4((m) + 4, __VA_ARGS__), CROSS_4((m) + 8, __VA_ARGS__),    \
        CROSS_4((m) + 12, __VA_ARGS__)
#define CROSS_64(m, ...)                                                                   \
    CROSS_16(m, __VA_ARGS__), CROSS_16((m) + 16, __VA_ARGS__),                               \
        CROSS_16((m) + 32, __VA_ARGS__), CROSS_16((m) + 48, __VA_ARGS__)
#define CROSS_256(...)                                                                     \
    { CROSS_64(0, __VA_ARGS__), CROSS_64(64, __VA_ARGS__), CROSS_64(128, __VA_ARGS__),        \
      CROSS_64(192, __VA_ARGS__) }
static const uint8_t face_crossings[6][256] = { CROSS_256(0, 2, 6, 4), CROSS_256(1, 3, 7, 5),
                                                CROSS_256(0, 1, 5, 4), CROSS_256(2, 3, 7, 6),
                                                CROSS_256(0, 1, 3, 2), CROSS_256(4, 5, 7, 6) };
#undef CROSS_256
#undef CROSS_64
#undef CROSS_16
#undef CROSS_4
#undef FACE_CROSSINGS
#undef CROSSES

// From the sides k (bits) a face needs no clip against or its low part is
// within, those from the last on: the sides whose clips are left out.
static inline unsigned sides_from_last(unsigned sides)
{
    return 0x76440000u >> (4 * sides) & 7;
}

// Which sides of the prism box face f's part at or below the level H
// (corner heights hv, bit v of `low` set for a corner at or below it) lies
// beyond (bit k of *away: fk[k], the side's measure, below zero at every
// point of it) and within (bit k of *within: fk[k] at least lim[k]). The
// part is a convex polygon, fk affine: its low corners and the points where
// the face's edges cross the level decide. *away and *within come in with
// the sides its low corners allow (the sides left out are not looked at).
static void low_part_sides(int f, const dReal hv[8], unsigned low, dReal H,
                           const dReal fk[3][8], const dReal lim[3], unsigned *away,
                           unsigned *within)
{
    const int *fv = box_faces[f];
    unsigned a = *away, w = *within;
    // The edges that cross the level (bit i: from corner fv[i] to the
    // next), looked up; at each, the three sides' bits cleared by masks (a
    // bit already clear stays clear), so that only the loop over the
    // crossings (two but for rounding) branches.
    for (unsigned cross = face_crossings[f][low]; cross; cross &= cross - 1) {
        const int i = __builtin_ctz(cross), u = fv[i], x = fv[(i + 1) & 3];
        dReal s = (H - hv[u]) / (hv[x] - hv[u]);
#if defined(__SSE2__) && !defined(dSINGLE)
        // Sides 0 and 1 side by side (the same sums), side 2 alone.
        const __m128d fu = _mm_set_pd(fk[1][u], fk[0][u]), fx = _mm_set_pd(fk[1][x], fk[0][x]);
        const __m128d fc = _mm_add_pd(fu, _mm_mul_pd(_mm_set1_pd(s), _mm_sub_pd(fx, fu)));
        const dReal fc2 = fk[2][u] + s * (fk[2][x] - fk[2][u]);
        a &= (unsigned)_mm_movemask_pd(_mm_cmplt_pd(fc, _mm_setzero_pd())) | (unsigned)(fc2 < 0) << 2;
        w &= (unsigned)_mm_movemask_pd(_mm_cmpge_pd(fc, _mm_loadu_pd(lim))) |
             (unsigned)(fc2 >= lim[2]) << 2;
#else
        for (int k = 0; k < 3; k++) {
            dReal fc = fk[k][u] + s * (fk[k][x] - fk[k][u]);
            a &= ~((unsigned)!(fc < 0) << k);
            w &= ~((unsigned)!(fc >= lim[k]) << k);
        }
#endif
    }
    *away = a;
    *within = w;
}

// (The walk has left out a triangle whose plane the centre is below.)
static int box_test(dxTriQuery *q, const dxTri *t)
{
    const dReal *c = q->pos, hc = t->h;
    // (A triangle off the box's own bounding box in the mesh frame never
    // comes here: dxTriMeshGather leaves it out.)
    const box_pair *b = prepare_box(q);
    dReal nb[3];
    if (box_separated(b, t, c, hc, nb)) return 0;
    // A face is clipped if one of its corners is on or behind the plane.
    // Bit v: corner v is on or behind the plane (height <= eps), from the
    // centre's height and the axes; one eps more covers that sum's
    // rounding (a face clipped needlessly adds nothing: its points are all
    // above the plane).
    dReal eps = DX_COLLIDE_EPS * q->scale, up[3], hv[8];
    for (int j = 0; j < 3; j++) up[j] = b->h[j] * nb[j];
    corner_sums(hc, up, hv);
    const unsigned behind = bits_at_most(hv, 2 * eps);
    dxTriPrism p;
    dxTriPrismInit(q, t, &p);
    // Bit v of outside[k]: corner v is beyond side k of the prism by more
    // than rounding (the clip's measure m . (x - v_k) + slack below zero by
    // one slack more, a margin for working it out from the centre and the
    // axes instead: fk[k][v] < 0). A face with its four corners beyond one
    // side clips to nothing.
    // Bit v of inside[k]: corner v is within side k by more than rounding
    // (the measure at least one slack: with the clip's own slack, two), so
    // a face with its four corners within needs no clip against side k.
    // Bit v of low_in[k]: fk[k][v] >= lim[k] = 2 slack, the clip's measure
    // one slack over its crossing (the face's low part, see below).
    unsigned outside[3] = { 0, 0, 0 }, inside[3] = { 0, 0, 0 }, low_in[3];
    dReal fk[3][8], lim[3];
    for (int k = 0; k < 3; k++) {
        dReal d[3], off[3];
        sub3(d, c, t->v[k]);
        dReal f0 = dx_dot(p.m[k], d) + 2 * p.slack[k];
        for (int j = 0; j < 3; j++) off[j] = b->h[j] * dx_dot(p.m[k], b->ax[j]);
        corner_sums(f0, off, fk[k]);
        outside[k] = bits_below(fk[k], 0);
        inside[k] = bits_at_least(fk[k], 3 * p.slack[k]);
        lim[k] = 2 * p.slack[k];
        low_in[k] = bits_at_least(fk[k], lim[k]);
    }
    // The faces to clip: those with a corner on or behind the plane, none
    // with all four corners beyond one side (bit 3 f). Per face and side k
    // (bit 3 f + k): its corners all within side k (no clip needed), its
    // low corners all within lim[k] of it (low_in), all beyond it (away).
    const uint32_t faces = ~faces_all_of[~behind & 0xff] & EVERY_FACE &
                           ~(faces_all_of[outside[0]] | faces_all_of[outside[1]] |
                             faces_all_of[outside[2]]);
    const uint32_t all_low = faces_all_of[behind];
    const uint32_t within_of = faces_all_of[inside[0]] | faces_all_of[inside[1]] << 1 |
                               faces_all_of[inside[2]] << 2;
    const uint32_t low_in_of = faces_low_in(behind, low_in);
    const uint32_t away_of = faces_low_in(behind, outside);
    // seen: the corners added already (each is in three faces).
    int added = 0;
    unsigned seen = 0;
    for (uint32_t left = faces; left; left &= left - 1) {
        const int f3 = __builtin_ctz(left), f = f3 / 3;
        // Every point a face can add lies in its low part (at or below
        // 2 eps). If that part is beyond a side, the face adds nothing. If
        // it is within the last side to clip against by one slack more
        // than the clip's crossings, that clip keeps the low points as
        // they are (their bits and order) and makes and drops only higher
        // ones, which add nothing: it is left out (and then the one before
        // it, the same way). A face left with no clip adds its low corners
        // (in its order, as the clip keeps them).
        const unsigned low = behind & box_face_mask[f];
        unsigned within = within_of >> f3 & 7;
        // low_within: the sides, from the last on, that the low part's
        // corners are within (or that need no clip), less those that need
        // no clip.
        unsigned low_within = sides_from_last(within | (low_in_of >> f3 & 7)) & ~within;
        if (!(all_low >> f3 & 1)) {
            unsigned away = away_of >> f3 & 7;
            if (away || low_within)
                low_part_sides(f, hv, behind, 2 * eps, fk, lim, &away, &low_within);
            if (away) continue;
        }
        within |= sides_from_last(within | low_within);
        const int *fv = box_faces[f];
        if (within == 7) {
            for (int i = 0; i < 4; i++) {
                const int v = fv[i];
                if (!(low >> v & 1) || (seen >> v & 1)) continue;
                dReal depth = -dxTriHeight(t, b->corner[v]);
                if (depth < -eps) continue;
                seen |= 1u << v;
                dxTriAdd(q, b->corner[v], t->n, dMax(depth, 0), t->index);
                added = 1;
            }
            continue;
        }
        added |= clipped_face_contacts(q, t, &p, b->face_corner[f], box_face_made[f], 4, within,
                                       &seen);
    }
    return added;
}

int dxCollideTriMeshBox(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return dxTriMeshCollide(o1, o2, flags, c, skip, dInfinity, box_test);
}

// ---- cylinder ---------------------------------------------------------------------

// The cylinder as a prism of CYL_SIDES sides inscribed in it, turned about
// its axis so that one side line lies where the cylinder reaches deepest
// below the triangle: that depth is exact, and so is a cylinder lying on
// its side (its lowest line is an edge of the prism). Elsewhere the prism
// is inside the cylinder by at most r (1 - cos(pi / CYL_SIDES)), 0.5% of r.
//
// (The walk has left out a triangle whose plane the centre is below.)
static int cylinder_test(dxTriQuery *q, const dxTri *t)
{
    const dxCylinder *cyl = (const dxCylinder *)q->other;
    const dReal *c = q->pos, r = cyl->radius, h = cyl->length / 2;
    dReal a[3], x[3], y[3];
    dx_axis(q->R, 2, a);
    if (separates_cylinder(t, t->n, c, a, r, h) || separates_cylinder(t, a, c, a, r, h))
        return 0;
    for (int k = 0; k < 3; k++) {
        dReal e[3], L[3];
        sub3(e, t->v[(k + 1) % 3], t->v[k]);
        cross3(L, e, a);
        if (separates_cylinder(t, L, c, a, r, h)) return 0;
    }
    // x: the direction across the axis closest to -n (any if the axis is
    // along n); y completes the frame.
    dReal down = -dx_dot(t->n, a);
    for (int i = 0; i < 3; i++) x[i] = -t->n[i] - down * a[i];
    dReal xl = dSqrt(dx_dot(x, x));
    if (xl > DX_COLLIDE_EPS) {
        for (int i = 0; i < 3; i++) x[i] /= xl;
    } else {
        dx_axis(q->R, 0, x);
    }
    cross3(y, a, x);
    // The corners, turning by 2 pi / CYL_SIDES (its cosine and sine).
    const dReal step_c = (dReal)0.98078528040323044913, step_s = (dReal)0.19509032201612826785;
    dReal rim[2][CYL_SIDES][3], cs = r, sn = 0;
    for (int s = 0; s < CYL_SIDES; s++) {
        for (int i = 0; i < 3; i++) {
            dReal p = c[i] + cs * x[i] + sn * y[i];
            rim[0][s][i] = p - h * a[i];
            rim[1][s][i] = p + h * a[i];
        }
        dReal nc = cs * step_c - sn * step_s;
        sn = sn * step_c + cs * step_s;
        cs = nc;
    }
    int added = 0;
    dReal poly[POLY_MAX][3];
    dxTriPrism p;
    dxTriPrismInit(q, t, &p);
    for (int cap = 0; cap < 2; cap++) {
        for (int s = 0; s < CYL_SIDES; s++)
            for (int i = 0; i < 3; i++) poly[s][i] = rim[cap][s][i];
        added |= face_contacts(q, t, &p, poly, CYL_SIDES);
    }
    for (int s = 0; s < CYL_SIDES; s++) {
        int u = (s + 1) % CYL_SIDES;
        for (int i = 0; i < 3; i++) {
            poly[0][i] = rim[0][s][i];
            poly[1][i] = rim[0][u][i];
            poly[2][i] = rim[1][u][i];
            poly[3][i] = rim[1][s][i];
        }
        added |= face_contacts(q, t, &p, poly, 4);
    }
    return added;
}

int dxCollideTriMeshCylinder(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return dxTriMeshCollide(o1, o2, flags, c, skip, dInfinity, cylinder_test);
}

// ---- convex hull ------------------------------------------------------------------

// The interval of the hull h (its points at q->pos + q->R p) on the axis L.
static void hull_interval(const dxTriQuery *q, const dxConvex *h, const dReal L[3], dReal *lo,
                          dReal *hi)
{
    dReal l[3];   // L in the hull's frame
    for (int k = 0; k < 3; k++) l[k] = q->R[k] * L[0] + q->R[4 + k] * L[1] + q->R[8 + k] * L[2];
    dReal mn = dInfinity, mx = -dInfinity;
    for (unsigned v = 0; v < h->pointcount; v++) {
        const dReal *p = h->points + 3 * v;
        dReal e = l[0] * p[0] + l[1] * p[1] + l[2] * p[2];
        mn = dMin(mn, e);
        mx = dMax(mx, e);
    }
    dReal c = dx_dot(L, q->pos);
    *lo = c + mn;
    *hi = c + mx;
}

// Whether the axis L (any length; len2 its squared length's scale, below
// which L is the cross product of parallel edges) separates the triangle
// from the hull.
static int separates_hull(const dxTriQuery *q, const dxConvex *h, const dxTri *t,
                          const dReal L[3], dReal len2)
{
    if (dx_dot(L, L) <= DX_COLLIDE_EPS * DX_COLLIDE_EPS * len2) return 0;
    dReal lo, hi, tlo, thi;
    hull_interval(q, h, L, &lo, &hi);
    triangle_interval(t, L, &tlo, &thi);
    return thi < lo || tlo > hi;
}

// Point i of the hull in the mesh frame.
static void hull_point(const dxTriQuery *q, const dxConvex *h, unsigned i, dReal out[3])
{
    const dReal *p = h->points + 3 * i;
    for (int r = 0; r < 3; r++)
        out[r] = q->pos[r] + q->R[4 * r] * p[0] + q->R[4 * r + 1] * p[1] + q->R[4 * r + 2] * p[2];
}

// The hull's polygons clipped by face_contacts; a polygon with more
// corners than a clip can take goes as a fan of pieces sharing its first
// corner (each piece convex; their shared diagonals add no corners of the
// hull's own, only prism crossings that lie in the face).
enum { HULL_PIECE = POLY_MAX - 3 };

static int convex_test(dxTriQuery *q, const dxTri *t)
{
    const dxConvex *h = (const dxConvex *)q->other;
    if (h->pointcount == 0 || h->planecount == 0) return 0;
    // The hull's centre: its points' mean (its origin need not be inside).
    dReal centre[3] = { 0, 0, 0 }, local[3] = { 0, 0, 0 };
    for (unsigned v = 0; v < h->pointcount; v++)
        for (int k = 0; k < 3; k++) local[k] += h->points[3 * v + k] / (dReal)h->pointcount;
    for (int r = 0; r < 3; r++)
        centre[r] = q->pos[r] + q->R[4 * r] * local[0] + q->R[4 * r + 1] * local[1] +
                    q->R[4 * r + 2] * local[2];
    if (dxTriHeight(t, centre) < 0) return 0;
    if (separates_hull(q, h, t, t->n, 1)) return 0;
    for (unsigned f = 0; f < h->planecount; f++) {
        const dReal *pl = h->planes + 4 * f;
        dReal n[3];
        for (int r = 0; r < 3; r++)
            n[r] = q->R[4 * r] * pl[0] + q->R[4 * r + 1] * pl[1] + q->R[4 * r + 2] * pl[2];
        if (separates_hull(q, h, t, n, 0)) return 0;
    }
    for (unsigned k = 0; k < h->edgecount; k++) {
        dReal a[3], b[3], u[3];
        hull_point(q, h, h->edges[k].a, a);
        hull_point(q, h, h->edges[k].b, b);
        sub3(u, b, a);
        for (int j = 0; j < 3; j++) {
            dReal e[3], L[3];
            sub3(e, t->v[(j + 1) % 3], t->v[j]);
            cross3(L, e, u);
            if (separates_hull(q, h, t, L, dx_dot(e, e) * dx_dot(u, u))) return 0;
        }
    }
    int added = 0;
    dxTriPrism p;
    dxTriPrismInit(q, t, &p);
    const unsigned *poly = h->polygons;
    for (unsigned f = 0; f < h->planecount; f++) {
        unsigned count = *poly++;
        // Piece: corner 0 and corners start .. start + HULL_PIECE - 2.
        for (unsigned start = 1; count >= 3; start += HULL_PIECE - 2) {
            dReal a[POLY_MAX][3];
            int n = 0;
            hull_point(q, h, poly[0], a[n++]);
            for (unsigned i = start; i < count && n < HULL_PIECE; i++)
                hull_point(q, h, poly[i], a[n++]);
            added |= face_contacts(q, t, &p, a, n);
            if (start + (HULL_PIECE - 1) >= count) break;
        }
        poly += count;
    }
    return added;
}

int dxCollideTriMeshConvex(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip)
{
    return dxTriMeshCollide(o1, o2, flags, c, skip, -1, convex_test);
}
