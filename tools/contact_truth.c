// SPDX-License-Identifier: BSD-3-Clause
//
// contact_truth.c -- penetration depth and point containment of convex geoms
// from their support functions (contact_truth.h). The overlap of the pair
// along a unit direction u is f(u) = h2(u) + h1(-u), the support function of
// the Minkowski difference g2 - g1: moving g1 by f(u) along u parts the pair,
// and the least f over the sphere is the penetration depth (apart, it is
// minus the distance). f has a local minimum per face of the difference,
// and kinks where a support point jumps: on the great circles perpendicular
// to a box's axes and to a capsule's or cylinder's axis, and at a cylinder's
// axis. So the least f is found among: a dense search on the sphere refined
// by pattern searches (minima inside smooth regions), a search along each
// kink circle (minima on one circle), and the crossings of two circles and
// the cylinder axes (minima where kinks meet, such as face normals).

#include "contact_truth.h"

#include <math.h>
#include <string.h>

static const double TWO_PI = 6.283185307179586;

enum {
    LATTICE = 3000,   // directions of the dense search (Fibonacci lattice)
    STARTS = 8,       // local minima refined
    PATTERN = 8,      // directions per pattern-search step
};

int contact_truth_supports(int cls)
{
    return cls == dSphereClass || cls == dBoxClass || cls == dCapsuleClass ||
           cls == dCylinderClass || cls == dPlaneClass;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize3(double v[3])
{
    double l = sqrt(dot3(v, v));
    for (int k = 0; k < 3; k++) v[k] /= l;
}

// World vector w into g's frame (R is row-major: local = R^T w).
static void to_local(dGeomID g, const double w[3], double l[3])
{
    const dReal *R = dGeomGetRotation(g);
    for (int k = 0; k < 3; k++) l[k] = w[0] * R[k] + w[1] * R[4 + k] + w[2] * R[8 + k];
}

double contact_truth_support(dGeomID g, const double dir[3], double point[3])
{
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    double l[3], w[3] = { 0, 0, 0 };
    to_local(g, dir, l);
    dReal r, len;
    switch (dGeomGetClass(g)) {
    case dSphereClass: {
        double q = sqrt(dot3(l, l));
        r = dGeomSphereGetRadius(g);
        if (q > 0)
            for (int k = 0; k < 3; k++) w[k] = r * l[k] / q;
        break;
    }
    case dBoxClass: {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        for (int k = 0; k < 3; k++) w[k] = (l[k] < 0 ? -0.5 : 0.5) * side[k];
        break;
    }
    case dCylinderClass: {
        dGeomCylinderGetParams(g, &r, &len);
        double q = sqrt(l[0] * l[0] + l[1] * l[1]);
        if (q > 0) {
            w[0] = r * l[0] / q;
            w[1] = r * l[1] / q;
        }
        w[2] = (l[2] < 0 ? -0.5 : 0.5) * len;
        break;
    }
    default: {   // capsule: a sphere swept along its z segment
        dGeomCapsuleGetParams(g, &r, &len);
        double q = sqrt(dot3(l, l));
        if (q > 0)
            for (int k = 0; k < 3; k++) w[k] = r * l[k] / q;
        w[2] += (l[2] < 0 ? -0.5 : 0.5) * len;
        break;
    }
    }
    for (int i = 0; i < 3; i++)
        point[i] = c[i] + R[4 * i] * w[0] + R[4 * i + 1] * w[1] + R[4 * i + 2] * w[2];
    return dot3(dir, point);
}

// f(u): the translation of g1 along unit u that parts it from g2.
static double overlap_along(dGeomID g1, dGeomID g2, const double u[3])
{
    double m[3] = { -u[0], -u[1], -u[2] }, p[3];
    return contact_truth_support(g2, u, p) + contact_truth_support(g1, m, p);
}

// Two unit vectors perpendicular to unit u and to each other.
static void tangents(const double u[3], double e1[3], double e2[3])
{
    double a[3] = { 1, 0, 0 };
    if (fabs(u[0]) > 0.6) a[0] = 0, a[1] = 1;
    double d = dot3(a, u);
    for (int k = 0; k < 3; k++) e1[k] = a[k] - d * u[k];
    normalize3(e1);
    e2[0] = u[1] * e1[2] - u[2] * e1[1];
    e2[1] = u[2] * e1[0] - u[0] * e1[2];
    e2[2] = u[0] * e1[1] - u[1] * e1[0];
}

// Pattern search from u (value *f) on the sphere: PATTERN tangent directions,
// turned by the golden angle at every step; a step that improves is taken
// (and grows), else the step shrinks, down to 1e-12 rad.
static void refine(dGeomID g1, dGeomID g2, double u[3], double *f)
{
    double step = 0.02, turn = 0;
    for (int it = 0; it < 4000 && step > 1e-12; it++) {
        double e1[3], e2[3], best_u[3], best = *f;
        tangents(u, e1, e2);
        for (int j = 0; j < PATTERN; j++) {
            double a = turn + j * (TWO_PI / PATTERN), v[3];
            for (int k = 0; k < 3; k++)
                v[k] = u[k] + step * (cos(a) * e1[k] + sin(a) * e2[k]);
            normalize3(v);
            double fv = overlap_along(g1, g2, v);
            if (fv < best) {
                best = fv;
                memcpy(best_u, v, sizeof best_u);
            }
        }
        turn += 2.399963229728653;
        if (best < *f) {
            *f = best;
            memcpy(u, best_u, sizeof best_u);
            step *= 1.5;
        } else {
            step *= 0.5;
        }
    }
}

// The directions of the kink circles of g (unit, world frame; the circle is
// perpendicular to each): a box's three axes, a capsule's or cylinder's axis.
static int kink_axes(dGeomID g, double axes[][3])
{
    const dReal *R = dGeomGetRotation(g);
    int cls = dGeomGetClass(g), n = cls == dBoxClass ? 3 : cls == dSphereClass ? 0 : 1;
    for (int m = 0; m < n; m++)
        for (int k = 0; k < 3; k++) axes[m][k] = R[4 * k + (cls == dBoxClass ? m : 2)];
    return n;
}

// Keeps u if it improves on the best so far.
static void consider(dGeomID g1, dGeomID g2, const double u[3], contact_truth *best)
{
    double f = overlap_along(g1, g2, u);
    if (f < best->depth) {
        best->depth = f;
        memcpy(best->normal, u, sizeof best->normal);
    }
}

// The least f along the great circle perpendicular to unit a: samples, then
// each local minimum refined by a one-dimensional pattern search (kinks on
// the circle need no care in one dimension).
static void circle_minimum(dGeomID g1, dGeomID g2, const double a[3], contact_truth *best)
{
    enum { SAMPLES = 96 };
    double e1[3], e2[3], f[SAMPLES];
    tangents(a, e1, e2);
    for (int i = 0; i < SAMPLES; i++) {
        double t = i * TWO_PI / SAMPLES, u[3];
        for (int k = 0; k < 3; k++) u[k] = cos(t) * e1[k] + sin(t) * e2[k];
        f[i] = overlap_along(g1, g2, u);
    }
    for (int i = 0; i < SAMPLES; i++) {
        if (f[i] > f[(i + 1) % SAMPLES] || f[i] > f[(i + SAMPLES - 1) % SAMPLES]) continue;
        double t = i * TWO_PI / SAMPLES, ft = f[i], step = TWO_PI / SAMPLES, u[3];
        while (step > 1e-14) {
            int moved = 0;
            for (int s = -1; s <= 1; s += 2) {
                double tt = t + s * step;
                for (int k = 0; k < 3; k++) u[k] = cos(tt) * e1[k] + sin(tt) * e2[k];
                double fv = overlap_along(g1, g2, u);
                if (fv < ft) {
                    ft = fv, t = tt, moved = 1;
                    break;
                }
            }
            if (!moved) step *= 0.5;
        }
        for (int k = 0; k < 3; k++) u[k] = cos(t) * e1[k] + sin(t) * e2[k];
        consider(g1, g2, u, best);
    }
}

// The least overlap over all directions, for two shapes with support functions.
static void convex_pair(dGeomID g1, dGeomID g2, contact_truth *out)
{
    double start[STARTS][3], start_f[STARTS];
    int n = 0;
    for (int i = 0; i < LATTICE; i++) {
        double z = 1 - 2 * (i + 0.5) / LATTICE, r = sqrt(1 - z * z);
        double phi = i * 2.399963229728653;
        double u[3] = { r * cos(phi), r * sin(phi), z }, f = overlap_along(g1, g2, u);
        // Keep the STARTS best directions at least 0.1 rad apart.
        int near = -1;
        for (int j = 0; j < n; j++)
            if (dot3(u, start[j]) > 0.995) near = j;
        if (near >= 0) {
            if (f < start_f[near]) {
                start_f[near] = f;
                memcpy(start[near], u, sizeof u);
            }
            continue;
        }
        int slot = n < STARTS ? n++ : -1;
        if (slot < 0) {
            int worst = 0;
            for (int j = 1; j < STARTS; j++)
                if (start_f[j] > start_f[worst]) worst = j;
            if (f >= start_f[worst]) continue;
            slot = worst;
        }
        start_f[slot] = f;
        memcpy(start[slot], u, sizeof u);
    }
    out->depth = INFINITY;
    for (int j = 0; j < n; j++) {
        refine(g1, g2, start[j], &start_f[j]);
        consider(g1, g2, start[j], out);
    }
    double axes[6][3];
    int na = kink_axes(g1, axes);
    na += kink_axes(g2, axes + na);
    for (int i = 0; i < na; i++) {
        circle_minimum(g1, g2, axes[i], out);
        for (int s = -1; s <= 1; s += 2) {   // a cylinder's axis, both ways
            double u[3] = { s * axes[i][0], s * axes[i][1], s * axes[i][2] };
            consider(g1, g2, u, out);
        }
        for (int j = 0; j < i; j++) {   // where two circles cross
            const double *a = axes[i], *b = axes[j];
            double u[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                            a[0] * b[1] - a[1] * b[0] };
            if (dot3(u, u) < 1e-24) continue;
            normalize3(u);
            consider(g1, g2, u, out);
            for (int k = 0; k < 3; k++) u[k] = -u[k];
            consider(g1, g2, u, out);
        }
    }
}

// A plane (unit n, offset d: solid where n.x < d) against a convex shape s:
// only the plane's normal can part them, by d - min over s of n.x. The
// normal points into g1: -n when the plane is g1.
static void plane_pair(dGeomID plane, dGeomID s, int plane_is_g1, contact_truth *out)
{
    dVector4 abcd;
    dGeomPlaneGetParams(plane, abcd);
    double m[3] = { -abcd[0], -abcd[1], -abcd[2] }, p[3];
    out->depth = abcd[3] + contact_truth_support(s, m, p);
    for (int k = 0; k < 3; k++) out->normal[k] = plane_is_g1 ? m[k] : -m[k];
}

int contact_truth_compute(dGeomID g1, dGeomID g2, contact_truth *out)
{
    int c1 = dGeomGetClass(g1), c2 = dGeomGetClass(g2);
    if (!contact_truth_supports(c1) || !contact_truth_supports(c2)) return 0;
    if (c1 == dPlaneClass && c2 == dPlaneClass) return 0;
    if (c1 == dPlaneClass)
        plane_pair(g1, g2, 1, out);
    else if (c2 == dPlaneClass)
        plane_pair(g2, g1, 0, out);
    else
        convex_pair(g1, g2, out);
    out->overlap = out->depth > 0;
    return 1;
}

// Signed depth of (y, z) in the rectangle |y| <= a, |z| <= b: the depth
// of a cylinder (radial and axial) or of one box axis pair.
static double rect_depth(double dy, double dz)
{
    if (dy >= 0 && dz >= 0) return dy < dz ? dy : dz;
    double oy = dy < 0 ? -dy : 0, oz = dz < 0 ? -dz : 0;
    return -sqrt(oy * oy + oz * oz);
}

double contact_truth_point_depth(dGeomID g, const double p[3])
{
    int cls = dGeomGetClass(g);
    if (cls == dPlaneClass) {
        dVector4 abcd;
        dGeomPlaneGetParams(g, abcd);
        return abcd[3] - (abcd[0] * p[0] + abcd[1] * p[1] + abcd[2] * p[2]);
    }
    const dReal *c = dGeomGetPosition(g);
    double w[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] }, l[3];
    to_local(g, w, l);
    dReal r, len;
    switch (cls) {
    case dSphereClass: return dGeomSphereGetRadius(g) - sqrt(dot3(l, l));
    case dBoxClass: {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        double in = INFINITY, out = 0;
        for (int k = 0; k < 3; k++) {
            double d = 0.5 * side[k] - fabs(l[k]);
            if (d < in) in = d;
            if (d < 0) out += d * d;
        }
        return out > 0 ? -sqrt(out) : in;
    }
    case dCylinderClass:
        dGeomCylinderGetParams(g, &r, &len);
        return rect_depth(r - sqrt(l[0] * l[0] + l[1] * l[1]), 0.5 * len - fabs(l[2]));
    case dCapsuleClass: {
        dGeomCapsuleGetParams(g, &r, &len);
        double z = fmax(-0.5 * len, fmin(0.5 * len, l[2]));
        return r - sqrt(l[0] * l[0] + l[1] * l[1] + (l[2] - z) * (l[2] - z));
    }
    default: return -INFINITY;
    }
}

int contact_truth_point_inside(dGeomID g, const double p[3], double tol)
{
    return contact_truth_point_depth(g, p) >= -tol;
}
