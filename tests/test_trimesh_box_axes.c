// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_box_axes.c -- a box against a mesh of one triangle, in
// random poses of both, judged by the test's own separating-axis sums in
// the world frame: a box apart from the triangle along one of the 13 axes
// (the normal, the box's three, the nine edge pairs) by more than rounding
// gets no contact; a box whose centre is in front of the triangle and whose
// lowest corner (below the triangle's plane) lies over the triangle gets
// contacts along the triangle's normal, the deepest as deep as that corner
// is below the plane, each a point of the box over the triangle. The collider takes the triangle into the
// box's frame for its axes and skips the box faces' clips against prism
// sides they are wholly within: these are the cases that must not move.

#include "test.h"

#include <math.h>
#include <stdlib.h>

static double urand(double lo, double hi)
{
    return lo + (hi - lo) * (rand() / (double)RAND_MAX);
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(double out[3], const double a[3], const double b[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// The largest gap between the box (centre c, unit axes ax[j] in world,
// half sides h) and the triangle v over the 13 axes, each made unit; a
// negative value: they overlap on every axis by at least its size.
static double largest_gap(const double c[3], double ax[3][3], const double h[3],
                          double v[3][3])
{
    double axes[13][3];
    int n = 0;
    double e[3][3], nrm[3];
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) e[k][i] = v[(k + 1) % 3][i] - v[k][i];
    cross3(nrm, e[0], e[1]);
    for (int i = 0; i < 3; i++) axes[n][i] = nrm[i];
    n++;
    for (int j = 0; j < 3; j++, n++)
        for (int i = 0; i < 3; i++) axes[n][i] = ax[j][i];
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++) cross3(axes[n++], e[k], ax[j]);
    double gap = -INFINITY;
    for (int a = 0; a < n; a++) {
        double len = sqrt(dot3(axes[a], axes[a]));
        if (len < 1e-6) continue;   // parallel edges: no axis
        double L[3] = { axes[a][0] / len, axes[a][1] / len, axes[a][2] / len };
        double lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < 3; k++) {
            double p = dot3(L, v[k]);
            lo = fmin(lo, p);
            hi = fmax(hi, p);
        }
        double bc = dot3(L, c), br = 0;
        for (int j = 0; j < 3; j++) br += h[j] * fabs(dot3(L, ax[j]));
        gap = fmax(gap, fmax(lo - (bc + br), (bc - br) - hi));
    }
    return gap;
}

// Whether p, projected on the triangle's plane, is inside it by margin.
static int over_triangle(double v[3][3], const double nrm[3], const double p[3], double margin)
{
    for (int k = 0; k < 3; k++) {
        double e[3], m[3], d[3];
        for (int i = 0; i < 3; i++) {
            e[i] = v[(k + 1) % 3][i] - v[k][i];
            d[i] = p[i] - v[k][i];
        }
        cross3(m, nrm, e);   // inward, in the plane
        if (dot3(m, d) < margin * sqrt(dot3(m, m))) return 0;
    }
    return 1;
}

static int test_box_against_one_triangle(void)
{
    srand(11);
    const double margin = TOL(1e-6, 2e-3);
    int apart = 0, deep = 0, behind = 0;
    for (int round = 0; round < 6000; round++) {
        // The triangle in the mesh frame, the mesh turned and moved.
        double tv[3][3];
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) tv[k][i] = urand(-1, 1);
        float fv[9];
        for (int k = 0; k < 9; k++) fv[k] = (float)tv[k / 3][k % 3];
        static const dTriIndex idx[3] = { 0, 1, 2 };
        dTriMeshDataID data = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildSingle(data, fv, 3 * sizeof(float), 3, idx, 3, 3 * sizeof(dTriIndex));
        dGeomID mesh = dCreateTriMesh(0, data, 0, 0, 0);
        dMatrix3 Rm, Rb;
        dRFromAxisAndAngle(Rm, urand(-1, 1), urand(-1, 1), urand(-1, 1), urand(0, 3));
        dGeomSetRotation(mesh, Rm);
        dGeomSetPosition(mesh, urand(-1, 1), urand(-1, 1), urand(-1, 1));
        double v[3][3];
        for (int k = 0; k < 3; k++) {
            dVector3 w;
            dGeomGetRelPointPos(mesh, fv[3 * k], fv[3 * k + 1], fv[3 * k + 2], w);
            for (int i = 0; i < 3; i++) v[k][i] = w[i];
        }
        double e1[3], e2[3], nrm[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = v[1][i] - v[0][i];
            e2[i] = v[2][i] - v[0][i];
        }
        cross3(nrm, e1, e2);
        double nl = sqrt(dot3(nrm, nrm));
        if (nl < 0.05) {   // a sliver: its normal is rounding
            dGeomDestroy(mesh);
            dGeomTriMeshDataDestroy(data);
            continue;
        }
        for (int i = 0; i < 3; i++) nrm[i] /= nl;

        // The box near the triangle's centre.
        double h[3] = { urand(0.05, 0.6), urand(0.05, 0.6), urand(0.05, 0.6) };
        dGeomID box = dCreateBox(0, 2 * h[0], 2 * h[1], 2 * h[2]);
        double c[3];
        for (int i = 0; i < 3; i++)
            c[i] = (v[0][i] + v[1][i] + v[2][i]) / 3 + urand(-0.8, 0.8);
        dRFromAxisAndAngle(Rb, urand(-1, 1), urand(-1, 1), urand(-1, 1), urand(0, 3));
        dGeomSetRotation(box, Rb);
        dGeomSetPosition(box, c[0], c[1], c[2]);
        const dReal *R = dGeomGetRotation(box), *P = dGeomGetPosition(box);
        double ax[3][3];
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++) ax[j][i] = R[4 * i + j];
        for (int i = 0; i < 3; i++) c[i] = P[i];

        dContactGeom k[8];
        int n = dCollide(mesh, box, 8, k, sizeof k[0]);
        double gap = largest_gap(c, ax, h, v);
        double hc = dot3(nrm, c) - dot3(nrm, v[0]);
        // The lowest corner along the normal.
        double low[3] = { 0, 0, 0 }, low_h = INFINITY;   // and its height
        for (int corner = 0; corner < 8; corner++) {
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = c[i] + (corner & 1 ? h[0] : -h[0]) * ax[0][i] +
                       (corner & 2 ? h[1] : -h[1]) * ax[1][i] +
                       (corner & 4 ? h[2] : -h[2]) * ax[2][i];
            double ph = dot3(nrm, p) - dot3(nrm, v[0]);
            if (ph < low_h) {
                low_h = ph;
                for (int i = 0; i < 3; i++) low[i] = p[i];
            }
        }
        if (gap > margin) {
            CHECK(n == 0);
            apart++;
        } else if (hc < -margin) {
            CHECK(n == 0);   // one-sided: the centre behind the triangle
            behind++;
        } else if (hc > margin && gap < -margin && low_h < -margin &&
                   over_triangle(v, nrm, low, margin)) {
            CHECK(n >= 1);
            double deepest = 0;
            for (int j = 0; j < n; j++) deepest = fmax(deepest, k[j].depth);
            CHECK_NEAR(deepest, -low_h, TOL(1e-9, 1e-4));
            for (int j = 0; j < n; j++) {
                CHECK(k[j].g1 == mesh && k[j].g2 == box && k[j].side1 == 0);
                CHECK_VEC(k[j].normal, -nrm[0], -nrm[1], -nrm[2], TOL(1e-9, 1e-4));
                CHECK(k[j].depth >= 0);
                // Each contact a point of the box over the triangle, as
                // deep below the plane as it says.
                double p[3] = { k[j].pos[0], k[j].pos[1], k[j].pos[2] }, d[3];
                for (int i = 0; i < 3; i++) d[i] = p[i] - c[i];
                for (int a = 0; a < 3; a++) CHECK(fabs(dot3(d, ax[a])) <= h[a] + margin);
                CHECK(over_triangle(v, nrm, p, -margin));
                CHECK_NEAR(dot3(nrm, p) - dot3(nrm, v[0]), -k[j].depth, TOL(1e-8, 1e-4));
            }
            deep++;
        }
        dGeomDestroy(box);
        dGeomDestroy(mesh);
        dGeomTriMeshDataDestroy(data);
    }
    // Each kind judged often enough to mean something.
    CHECK(apart > 1000 && deep > 300 && behind > 300);
    return 0;
}

// A box of random half sides h (5 to 60 cm), turned and placed at random:
// its axes ax[j] and centre c as the geom holds them.
static dGeomID random_box(double h[3], double ax[3][3], double c[3])
{
    for (int j = 0; j < 3; j++) h[j] = urand(0.05, 0.6);
    dGeomID box = dCreateBox(0, 2 * h[0], 2 * h[1], 2 * h[2]);
    dMatrix3 Rb;
    dRFromAxisAndAngle(Rb, urand(-1, 1), urand(-1, 1), urand(-1, 1), urand(0, 3));
    dGeomSetRotation(box, Rb);
    dGeomSetPosition(box, urand(-1, 1), urand(-1, 1), urand(-1, 1));
    const dReal *R = dGeomGetRotation(box), *P = dGeomGetPosition(box);
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) ax[j][i] = R[4 * i + j];
    for (int i = 0; i < 3; i++) c[i] = P[i];
    return box;
}

// A random point x of the box, each coordinate short of the face it is
// nearer by inset (0 to 1) times half to all of the box's half side.
static void point_in_box(const double c[3], const double ax[3][3], const double h[3],
                         double inset, double x[3])
{
    for (int i = 0; i < 3; i++) x[i] = c[i];
    for (int j = 0; j < 3; j++) {
        double u = (urand(-1, 1) < 0 ? -1 : 1) * (1 - inset * urand(0.5, 1)) * h[j];
        for (int i = 0; i < 3; i++) x[i] += u * ax[j][i];
    }
}

// Triangle v's unit normal, if it is no sliver and c lies in front of it
// by more than margin: 1; else 0.
static int front_normal(double v[3][3], const double c[3], double margin, double nrm[3])
{
    double e1[3], e2[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = v[1][i] - v[0][i];
        e2[i] = v[2][i] - v[0][i];
    }
    cross3(nrm, e1, e2);
    double nl = sqrt(dot3(nrm, nrm));
    if (nl < 0.05 || (dot3(nrm, c) - dot3(nrm, v[0])) / nl < margin) return 0;
    for (int i = 0; i < 3; i++) nrm[i] /= nl;
    return 1;
}

// The box (centre c, axes ax, half sides h) against a mesh of triangle v
// alone (unit normal nrm, c in front), both argument orders: contacts, the
// same each way, each along the triangle's normal, a point of the box over
// the triangle as deep below its plane as it says. 0, or 1 after a failed
// check.
static int judge_box_on_triangle(dGeomID box, double v[3][3], const double nrm[3],
                                 const double c[3], const double ax[3][3], const double h[3],
                                 double margin)
{
    dReal fv[9];
    for (int k = 0; k < 9; k++) fv[k] = (dReal)v[k / 3][k % 3];
    static const dTriIndex idx[3] = { 0, 1, 2 };
    dTriMeshDataID data = dGeomTriMeshDataCreate();
#ifdef dDOUBLE
    dGeomTriMeshDataBuildDouble(data, fv, 3 * sizeof(dReal), 3, idx, 3, 3 * sizeof(dTriIndex));
#else
    dGeomTriMeshDataBuildSingle(data, fv, 3 * sizeof(dReal), 3, idx, 3, 3 * sizeof(dTriIndex));
#endif
    dGeomID mesh = dCreateTriMesh(0, data, 0, 0, 0);

    dContactGeom k[8], kr[8];
    int n = dCollide(mesh, box, 8, k, sizeof k[0]);
    int nr = dCollide(box, mesh, 8, kr, sizeof kr[0]);
    CHECK(n >= 1 && nr == n);
    for (int j = 0; j < n; j++) {
        CHECK(k[j].g1 == mesh && k[j].g2 == box && k[j].side1 == 0);
        CHECK(kr[j].g1 == box && kr[j].g2 == mesh && kr[j].side2 == 0);
        CHECK_VEC(k[j].normal, -nrm[0], -nrm[1], -nrm[2], TOL(1e-9, 1e-4));
        CHECK_VEC(kr[j].normal, nrm[0], nrm[1], nrm[2], TOL(1e-9, 1e-4));
        CHECK(k[j].depth >= 0 && kr[j].depth == k[j].depth);
        double p[3] = { k[j].pos[0], k[j].pos[1], k[j].pos[2] }, d[3];
        for (int i = 0; i < 3; i++) d[i] = p[i] - c[i];
        for (int a = 0; a < 3; a++) CHECK(fabs(dot3(d, ax[a])) <= h[a] + margin);
        CHECK(over_triangle(v, nrm, p, -margin));
        CHECK_NEAR(dot3(nrm, p) - dot3(nrm, v[0]), -k[j].depth, TOL(1e-8, 1e-4));
    }
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(data);
    return 0;
}

// A triangle with a vertex inside the box (the collider then skips the
// edge pairs' axes: no axis can part them) and the box's centre in front of
// it: the box reaches behind the triangle near that vertex, so there are
// contacts, judged by judge_box_on_triangle. Vertices from deep inside to a
// millionth of the box's size from its faces (a thousandth in single
// precision, where the box then reaches behind the triangle by less than
// rounding).
static int test_box_holding_a_vertex(void)
{
    srand(12);
    const double margin = TOL(1e-6, 2e-3);
    int judged = 0;
    for (int round = 0; round < 4000; round++) {
        double h[3], ax[3][3], c[3];
        dGeomID box = random_box(h, ax, c);
        // Vertex 0 in the box (a quarter of them within a millionth of a
        // face), the others around it.
        double inset = round % 4 == 0 ? TOL(1e-6, 1e-3) : urand(0.01, 1), v[3][3], nrm[3];
        point_in_box(c, ax, h, inset, v[0]);
        for (int k = 1; k < 3; k++)
            for (int i = 0; i < 3; i++) v[k][i] = v[0][i] + urand(-1, 1);
        if (front_normal(v, c, margin, nrm)) {
            if (judge_box_on_triangle(box, v, nrm, c, ax, h, margin)) return 1;
            judged++;
        }
        dGeomDestroy(box);
    }
    CHECK(judged > 1000);
    return 0;
}

// A triangle none of whose vertices is in the box but one of whose edges
// passes through it (the collider then also skips the edge pairs' axes),
// the box's centre in front of it: the box reaches behind the triangle
// where the edge runs through, so there are contacts, judged as above. The
// edge's point in the box from deep inside to a millionth of the box's size
// from a face (a thousandth in single precision), its ends from just
// outside the box to beyond its size.
static int test_box_crossed_by_an_edge(void)
{
    srand(13);
    const double margin = TOL(1e-6, 2e-3);
    int judged = 0;
    for (int round = 0; round < 4000; round++) {
        double h[3], ax[3][3], c[3];
        dGeomID box = random_box(h, ax, c);
        // x: the edge's point in the box; d: the edge's direction.
        double inset = round % 4 == 0 ? TOL(1e-6, 1e-3) : urand(0.01, 1), x[3], d[3];
        point_in_box(c, ax, h, inset, x);
        for (int i = 0; i < 3; i++) d[i] = urand(-1, 1);
        double dl = sqrt(dot3(d, d)), size = h[0] + h[1] + h[2];
        double v[3][3], back = urand(0.2, 1.2) * size / dl, on = urand(0.2, 1.2) * size / dl;
        for (int i = 0; i < 3; i++) {
            v[0][i] = x[i] - back * d[i];
            v[1][i] = x[i] + on * d[i];
            v[2][i] = x[i] + urand(-1, 1);
        }
        int inside = 0;   // a vertex in the box: the other test's case
        for (int k = 0; k < 3; k++) {
            double r[3];
            for (int i = 0; i < 3; i++) r[i] = v[k][i] - c[i];
            int in = 1;
            for (int j = 0; j < 3; j++) in &= fabs(dot3(r, ax[j])) <= h[j];
            inside |= in;
        }
        double nrm[3];
        if (!inside && front_normal(v, c, margin, nrm)) {
            if (judge_box_on_triangle(box, v, nrm, c, ax, h, margin)) return 1;
            judged++;
        }
        dGeomDestroy(box);
    }
    CHECK(judged > 1000);
    return 0;
}

// The distance of p's projection on the triangle's plane inside edge k's
// line (negative: beyond it).
static double inside_edge(double v[3][3], const double nrm[3], const double p[3], int k)
{
    double e[3], m[3], d[3];
    for (int i = 0; i < 3; i++) {
        e[i] = v[(k + 1) % 3][i] - v[k][i];
        d[i] = p[i] - v[k][i];
    }
    cross3(m, nrm, e);
    return dot3(m, d) / sqrt(dot3(m, m));
}

// A box whose part behind the triangle's plane (its corners there and the
// points where its edges cross the plane, every corner off the plane by
// more than a margin) lies over the triangle: its contacts are corners
// behind the plane, each at most once, as deep as they are below it; with
// up to three such corners (their shadows a triangle at most: corners of
// the patch) every one of them. A box whose part behind the plane lies
// beyond one of the triangle's edges has none. (The collider leaves out
// the clips that can only make points above the plane, and every clip of
// such a box's faces: these are the cases it must still get right.) Both
// argument orders.
static int test_box_low_part(void)
{
    srand(14);
    const double margin = TOL(1e-6, 2e-3);
    int over = 0, beyond = 0;
    for (int round = 0; round < 12000; round++) {
        double h[3], ax[3][3], c[3], v[3][3], nrm[3];
        dGeomID box = random_box(h, ax, c);
        // A large triangle under the box: its plane through a point of
        // the box, so that some corners are behind it.
        double x[3];
        point_in_box(c, ax, h, urand(0.01, 1), x);
        double size = h[0] + h[1] + h[2], spread = urand(0.5, 6) * size;
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) v[k][i] = x[i] + urand(-spread, spread);
        if (!front_normal(v, c, margin, nrm)) {
            dGeomDestroy(box);
            continue;
        }
        // The corners, their heights; the part behind the plane.
        double corner[8][3], ch[8], part[8 + 12][3];
        int low = 0, parts = 0, on_plane = 0;
        for (int a = 0; a < 8; a++) {
            for (int i = 0; i < 3; i++)
                corner[a][i] = c[i] + (a & 1 ? h[0] : -h[0]) * ax[0][i] +
                               (a & 2 ? h[1] : -h[1]) * ax[1][i] +
                               (a & 4 ? h[2] : -h[2]) * ax[2][i];
            ch[a] = dot3(nrm, corner[a]) - dot3(nrm, v[0]);
            on_plane |= fabs(ch[a]) <= margin;
            if (ch[a] < 0) {
                low++;
                for (int i = 0; i < 3; i++) part[parts][i] = corner[a][i];
                parts++;
            }
        }
        for (int a = 0; a < 8; a++)
            for (int j = 0; j < 3; j++) {
                int b = a | 1 << j;   // the edge from a along axis j
                if (b == a || (ch[a] < 0) == (ch[b] < 0)) continue;
                double s = ch[a] / (ch[a] - ch[b]);
                for (int i = 0; i < 3; i++)
                    part[parts][i] = corner[a][i] + s * (corner[b][i] - corner[a][i]);
                parts++;
            }
        if (on_plane || low == 0) {
            dGeomDestroy(box);
            continue;
        }
        int all_over = 1, away = 0;
        for (int p = 0; p < parts; p++) all_over &= over_triangle(v, nrm, part[p], margin);
        for (int k = 0; k < 3; k++) {
            int all_beyond = 1;
            for (int p = 0; p < parts; p++) all_beyond &= inside_edge(v, nrm, part[p], k) < -margin;
            away |= all_beyond;
        }
        if (all_over || away) {
            dReal fv[9];
            for (int k = 0; k < 9; k++) fv[k] = (dReal)v[k / 3][k % 3];
            static const dTriIndex idx[3] = { 0, 1, 2 };
            dTriMeshDataID data = dGeomTriMeshDataCreate();
#ifdef dDOUBLE
            dGeomTriMeshDataBuildDouble(data, fv, 3 * sizeof(dReal), 3, idx, 3,
                                        3 * sizeof(dTriIndex));
#else
            dGeomTriMeshDataBuildSingle(data, fv, 3 * sizeof(dReal), 3, idx, 3,
                                        3 * sizeof(dTriIndex));
#endif
            dGeomID mesh = dCreateTriMesh(0, data, 0, 0, 0);
            dContactGeom k[16], kr[16];
            int n = dCollide(mesh, box, 16, k, sizeof k[0]);
            int nr = dCollide(box, mesh, 16, kr, sizeof kr[0]);
            CHECK(nr == n);
            if (away) {
                CHECK(n == 0);
                beyond++;
            } else {
                CHECK(n >= 1 && n <= low);
                if (low <= 3) CHECK(n == low);
                unsigned met = 0;
                for (int j = 0; j < n; j++) {
                    int at = -1;   // the corner behind the plane at this contact
                    for (int a = 0; a < 8; a++) {
                        double d[3];
                        for (int i = 0; i < 3; i++) d[i] = k[j].pos[i] - corner[a][i];
                        if (ch[a] < 0 && sqrt(dot3(d, d)) <= TOL(1e-9, 1e-4)) at = a;
                    }
                    CHECK(at >= 0 && !(met >> at & 1));
                    met |= 1u << at;
                    CHECK_NEAR(k[j].depth, -ch[at], TOL(1e-9, 1e-4));
                    CHECK_VEC(k[j].normal, -nrm[0], -nrm[1], -nrm[2], TOL(1e-9, 1e-4));
                    CHECK(kr[j].depth == k[j].depth);
                    CHECK_VEC(kr[j].pos, k[j].pos[0], k[j].pos[1], k[j].pos[2], 0);
                }
                over++;
            }
            dGeomDestroy(mesh);
            dGeomTriMeshDataDestroy(data);
        }
        dGeomDestroy(box);
    }
    CHECK(over > 300 && beyond > 300);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_box_against_one_triangle),
    TEST_CASE(test_box_holding_a_vertex),
    TEST_CASE(test_box_crossed_by_an_edge),
    TEST_CASE(test_box_low_part),
    TEST_END,
};
