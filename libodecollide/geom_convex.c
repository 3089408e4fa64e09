// SPDX-License-Identifier: BSD-3-Clause
//
// geom_convex.c -- the convex hull class of ODE 0.16: creation and
// dGeomSetConvex with their checks, and the bounding box of the points as
// posed. The arrays belong to the caller (as in ODE): they are not copied.
// The geom owns only what it derives from them: the edge list (each edge
// with its two faces), which the colliders use to skip edge pairs, where
// each polygon starts, and room for the hull posed in the world.

#include "geom_convex.h"

#include <ode/memory.h>

#include <math.h>
#include <string.h>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

// 1 if the hull data is usable by the colliders; else reports what is
// wrong (naming the calling function) and returns 0.
static int convex_valid(const char *fn, const dReal *planes, unsigned planecount,
                        const dReal *points, unsigned pointcount, const unsigned *polygons)
{
#define CONVEX_CHECK(cond, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(fn, __VA_ARGS__); \
            return 0; \
        } \
    } while (0)
    CONVEX_CHECK(planecount > 0, "planecount is 0: a convex needs planes");
    CONVEX_CHECK(pointcount > 0, "pointcount is 0: a convex needs points");
    CONVEX_CHECK(planes != NULL, "planes is NULL with planecount %u", planecount);
    CONVEX_CHECK(points != NULL, "points is NULL with pointcount %u", pointcount);
    CONVEX_CHECK(polygons != NULL, "polygons is NULL with planecount %u", planecount);
    for (unsigned i = 0; i < 3 * pointcount; i++)
        CONVEX_CHECK(dxIsFinite(points[i]), "points[%u] is not finite", i);
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++) {
        const dReal *p = planes + 4 * f;
        for (int k = 0; k < 4; k++)
            CONVEX_CHECK(dxIsFinite(p[k]), "planes[%u] is not finite", 4 * f + (unsigned)k);
        CONVEX_CHECK(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 0,
                     "plane %u has a zero normal", f);
        unsigned count = *poly++;
        CONVEX_CHECK(count >= 3, "polygon %u has %u points (at least 3 needed)", f, count);
        for (unsigned k = 0; k < count; k++, poly++)
            CONVEX_CHECK(*poly < pointcount, "polygon %u uses point %u, past pointcount %u", f,
                         *poly, pointcount);
    }
    return 1;
#undef CONVEX_CHECK
}

void dxHullPosePointsPlanes(const double R[9], const double c[3], const dReal *pts, unsigned npts,
                            const dReal *planes, const double *len, unsigned nplanes,
                            double (*wp)[3], double *const p3[3], double (*wn)[3],
                            double *const n3[3], double *wd)
{
    for (unsigned v = 0; v < npts; v++) {
        const dReal *p = pts + 3 * v;
        for (int r = 0; r < 3; r++)
            p3[r][v] = wp[v][r] = c[r] + R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2];
    }
    for (unsigned f = 0; f < nplanes; f++) {
        const dReal *p = planes + 4 * f;
        double l = len ? len[f]
                       : sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
        for (int r = 0; r < 3; r++)
            n3[r][f] = wn[f][r] = (R[3 * r] * p[0] + R[3 * r + 1] * p[1] + R[3 * r + 2] * p[2]) / l;
        wd[f] = p[3] / l + (wn[f][0] * c[0] + wn[f][1] * c[1] + wn[f][2] * c[2]);
    }
}

// Whether the n numbers at a and b are the same bits (memcmp's answer,
// without its call: this runs for every pair a hull meets).
static int same_bits(const dReal *a, const dReal *b, int n)
{
#ifdef dSINGLE
    uint32_t diff = 0, x, y;
#else
    uint64_t diff = 0, x, y;
#endif
    for (int i = 0; i < n; i++) {
        memcpy(&x, a + i, sizeof x);
        memcpy(&y, b + i, sizeof y);
        diff |= x ^ y;
    }
    return diff == 0;
}

void dxConvexPose(dxConvex *c)
{
    const dxGeom *g = &c->g;
    dxHullPose *pose = &c->pose;
    if (pose->valid && same_bits(pose->pos, g->pos, 3) && same_bits(pose->R, g->R, 12)) return;
    dx_hull *h = &c->hull;
    for (int i = 0; i < 3; i++) {
        h->c[i] = g->pos[i];
        for (int k = 0; k < 3; k++) h->R[3 * i + k] = g->R[4 * i + k];
    }
    dxHullPosePointsPlanes(h->R, h->c, c->points, c->pointcount, c->planes, c->plane_len,
                           c->planecount, pose->pts, (double *const[3]){ pose->px, pose->py, pose->pz },
                           pose->normals, (double *const[3]){ pose->nx, pose->ny, pose->nz },
                           pose->offsets);
    double sum[3] = { 0, 0, 0 };
    for (unsigned v = 0; v < c->pointcount; v++)
        for (int i = 0; i < 3; i++) sum[i] += pose->pts[v][i];
    for (int i = 0; i < 3; i++) h->centre[i] = pose->centre[i] = sum[i] / c->pointcount;
    memcpy(pose->pos, g->pos, sizeof pose->pos);
    memcpy(pose->R, g->R, sizeof pose->R);
    pose->valid = 1;
    pose->edges_valid = 0;
}

// The bounding box of the points as posed (the pose is kept for the
// colliders: a hull that meets others this step is posed once).
static void convex_aabb(dxGeom *g)
{
    dxConvex *c = (dxConvex *)g;
    dxConvexPose(c);
    const double *p3[3] = { c->pose.px, c->pose.py, c->pose.pz };
    unsigned n = c->pointcount;
    for (int i = 0; i < 3; i++) {
        const double *x = p3[i];
        double lo = x[0], hi = x[0];
        unsigned v = 1;
#ifdef __SSE2__
        __m128d vlo = _mm_set1_pd(lo), vhi = vlo;
        for (; v + 2 <= n; v += 2) {
            __m128d e = _mm_loadu_pd(x + v);
            vlo = _mm_min_pd(e, vlo);
            vhi = _mm_max_pd(e, vhi);
        }
        double l2[2], h2[2];
        _mm_storeu_pd(l2, vlo);
        _mm_storeu_pd(h2, vhi);
        lo = l2[0] < l2[1] ? l2[0] : l2[1];
        hi = h2[0] > h2[1] ? h2[0] : h2[1];
#endif
        for (; v < n; v++) {
            lo = x[v] < lo ? x[v] : lo;
            hi = x[v] > hi ? x[v] : hi;
        }
        g->aabb[2 * i] = (dReal)lo;
        g->aabb[2 * i + 1] = (dReal)hi;
    }
}

// The edges of the polygons, each once, with the faces on either side,
// into e (room for one per polygon side); returns their count.
static unsigned convex_edges(const unsigned *polygons, unsigned planecount, dxHullEdge *e)
{
    unsigned n = 0;
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++, poly += 1 + *poly) {
        for (unsigned k = 0; k < poly[0]; k++) {
            unsigned i = poly[1 + k], j = poly[1 + (k + 1) % poly[0]];
            unsigned a = i < j ? i : j, b = i < j ? j : i, m = 0;
            while (m < n && !(e[m].a == a && e[m].b == b)) m++;
            if (m < n) {   // the same edge from its other face
                if (e[m].f2 == e[m].f1 && e[m].f1 != f) e[m].f2 = f;
                continue;
            }
            e[n++] = (dxHullEdge){ a, b, f, f };
        }
    }
    return n;
}

// The sets of edges by face and of neighbouring faces (dxConvex's by_f1,
// by_f2, lone, nbr) into masks (room for three per plane), for hulls that
// fit 64-bit sets.
static void convex_edge_sets(dxConvex *c, uint64_t *masks)
{
    c->lone = 0;
    if (c->edgecount > 64 || c->planecount > 64) {
        c->by_f1 = c->by_f2 = c->nbr = NULL;
        return;
    }
    c->by_f1 = masks;
    c->by_f2 = masks + c->planecount;
    c->nbr = masks + 2 * (size_t)c->planecount;
    for (unsigned f = 0; f < c->planecount; f++) {
        c->by_f1[f] = c->by_f2[f] = 0;
        c->nbr[f] = (uint64_t)1 << f;
    }
    for (unsigned k = 0; k < c->edgecount; k++) {
        const dxHullEdge *e = &c->edges[k];
        uint64_t bit = (uint64_t)1 << k;
        c->by_f1[e->f1] |= bit;
        c->by_f2[e->f2] |= bit;
        c->nbr[e->f1] |= (uint64_t)1 << e->f2;
        c->nbr[e->f2] |= (uint64_t)1 << e->f1;
        if (e->f1 == e->f2) c->lone |= bit;
    }
}

// The parts of c->hull that stay from one pose to the next.
static void convex_view(dxConvex *c)
{
    dx_hull *h = &c->hull;
    dxHullPose *pose = &c->pose;
    h->pts = c->points;
    h->planes = c->planes;
    h->polys = c->polygons;
    h->poly_start = c->poly_start;
    h->edges = c->edges;
    h->npts = c->pointcount;
    h->nplanes = c->planecount;
    h->nedges = c->edgecount;
    h->wp = (const double (*)[3])pose->pts;
    h->wn = (const double (*)[3])pose->normals;
    h->wd = pose->offsets;
    h->we = pose->edges;
    h->face_low = pose->face_low;
    h->plane_dev = c->plane_dev;
    h->edges_posed = &pose->edges_valid;
    h->by_f1 = c->by_f1;
    h->by_f2 = c->by_f2;
    h->lone = c->lone;
    h->nbr = c->nbr;
    h->px = pose->px;
    h->py = pose->py;
    h->pz = pose->pz;
    h->nx = pose->nx;
    h->ny = pose->ny;
    h->nz = pose->nz;
    h->ex = pose->ex;
    h->ey = pose->ey;
    h->ez = pose->ez;
    h->convex = c;
}

static void free_derived(dxConvex *c)
{
    if (c->derived) dFree(c->derived, c->derived_size);
    c->derived = NULL;
    c->edges = NULL;
    c->poly_start = NULL;
    c->by_f1 = c->by_f2 = c->nbr = NULL;
    c->plane_len = c->plane_dev = NULL;
}

static void convex_destroy(dxGeom *g)
{
    free_derived((dxConvex *)g);
}

const dxGeomClassOps dx_convex_ops = { dConvexClass, "convex", convex_aabb, convex_destroy };

// Takes the caller's arrays and derives, in one block made once per
// dGeomSetConvex: the edge list, where each polygon starts, the size, and
// room for the hull posed in the world (filled by the colliders).
static void convex_set(dxConvex *c, const dReal *planes, unsigned planecount,
                       const dReal *points, unsigned pointcount, const unsigned *polygons)
{
    free_derived(c);
    c->planes = planes;
    c->planecount = planecount;
    c->points = points;
    c->pointcount = pointcount;
    c->polygons = polygons;
    size_t sides = 0;
    const unsigned *poly = polygons;
    for (unsigned f = 0; f < planecount; f++) {
        sides += *poly;
        poly += 1 + *poly;
    }
    size_t doubles = 6 * (size_t)pointcount + 10 * (size_t)planecount + 3 * sides;
    c->derived_size = sizeof(uint64_t) * 3 * (size_t)planecount + sizeof(double) * doubles +
                      sizeof(dxHullPosedEdge) * sides + sizeof(dxHullEdge) * sides +
                      sizeof(unsigned) * planecount;
    char *block = dAlloc(c->derived_size);
    c->derived = block;
    dxHullPose *pose = &c->pose;
    uint64_t *masks = (uint64_t *)block;
    pose->pts = (double (*)[3])(masks + 3 * (size_t)planecount);
    pose->normals = pose->pts + pointcount;
    pose->offsets = (double *)(pose->normals + planecount);
    pose->px = pose->offsets + planecount;
    pose->py = pose->px + pointcount;
    pose->pz = pose->py + pointcount;
    pose->nx = pose->pz + pointcount;
    pose->ny = pose->nx + planecount;
    pose->nz = pose->ny + planecount;
    pose->ex = pose->nz + planecount;
    pose->ey = pose->ex + sides;
    pose->ez = pose->ey + sides;
    pose->face_low = pose->ez + sides;
    c->plane_len = pose->face_low + planecount;
    c->plane_dev = c->plane_len + planecount;
    pose->edges = (dxHullPosedEdge *)(c->plane_dev + planecount);
    pose->valid = pose->edges_valid = 0;
    c->edges = (dxHullEdge *)(pose->edges + sides);
    c->poly_start = (unsigned *)(c->edges + sides);
    c->edgecount = convex_edges(polygons, planecount, c->edges);
    convex_edge_sets(c, masks);
    unsigned at = 0;
    for (unsigned f = 0; f < planecount; f++) {
        c->poly_start[f] = at;
        at += 1 + polygons[at];
    }
    for (unsigned f = 0; f < planecount; f++) {
        const dReal *p = planes + 4 * f;
        c->plane_len[f] = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
        // (d - n . x) / |n| at the polygon's points: the most is how far
        // under the plane the polygon reaches (0 for a flat one).
        const unsigned *idx = polygons + c->poly_start[f];
        double dev = 0;
        for (unsigned k = 1; k <= idx[0]; k++) {
            const dReal *q = points + 3 * idx[k];
            double under = ((double)p[3] - ((double)p[0] * q[0] + (double)p[1] * q[1] +
                                            (double)p[2] * q[2])) / c->plane_len[f];
            dev = under > dev ? under : dev;
        }
        c->plane_dev[f] = dev;
    }
    convex_view(c);
    double r2 = 0;
    for (unsigned v = 0; v < pointcount; v++) {
        const dReal *p = points + 3 * v;
        double d2 = (double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2];
        if (d2 > r2) r2 = d2;
    }
    c->size = c->hull.size = sqrt(r2);
}

dGeomID dCreateConvex(dSpaceID space, const dReal *planes, unsigned int planecount,
                      const dReal *points, unsigned int pointcount, const unsigned int *polygons)
{
    if (!convex_valid(__func__, planes, planecount, points, pointcount, polygons)) return NULL;
    dxConvex *c = (dxConvex *)dxGeomCreate(sizeof *c, &dx_convex_ops, DX_GEOM_PLACEABLE, space);
    convex_set(c, planes, planecount, points, pointcount, polygons);
    return &c->g;
}

void dGeomSetConvex(dGeomID g, const dReal *planes, unsigned int planecount,
                    const dReal *points, unsigned int pointcount, const unsigned int *polygons)
{
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(g->ops->cls == dConvexClass, return, "geom is a %s, not a convex",
                 g->ops->name);
    if (!convex_valid(__func__, planes, planecount, points, pointcount, polygons)) return;
    convex_set((dxConvex *)g, planes, planecount, points, pointcount, polygons);
    dxGeomShapeChanged(g);
}
