// SPDX-License-Identifier: BSD-3-Clause
//
// convex_depth.h -- an independent estimate of how deep two convex geoms
// (box, capsule, cylinder) overlap, from their public parameters only, for
// the libccd pair tests and their differential twin (which builds against
// the reference ODE too, so: the ODE API only, everything static inline).

#ifndef TEST_CONVEX_DEPTH_H
#define TEST_CONVEX_DEPTH_H

#include <ode/ode.h>
#include <math.h>
#include <string.h>

// The point of g furthest along m (into out) and its support value m . x.
static inline double convex_support(dGeomID g, const double m[3], double out[3])
{
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    double l[3], w[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; k++) l[k] = m[0] * R[k] + m[1] * R[4 + k] + m[2] * R[8 + k];
    dReal r, len;
    switch (dGeomGetClass(g)) {
    case dBoxClass: {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        for (int k = 0; k < 3; k++) w[k] = (l[k] < 0 ? -1 : 1) * side[k] / 2;
        break;
    }
    case dCylinderClass: {
        dGeomCylinderGetParams(g, &r, &len);
        double q = sqrt(l[0] * l[0] + l[1] * l[1]);
        if (q > 0) {
            w[0] = r * l[0] / q;
            w[1] = r * l[1] / q;
        }
        w[2] = (l[2] < 0 ? -1 : 1) * len / 2;
        break;
    }
    default: {   // capsule
        dGeomCapsuleGetParams(g, &r, &len);
        double q = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        for (int k = 0; k < 3; k++) w[k] = r * l[k] / q;
        w[2] += (l[2] < 0 ? -1 : 1) * len / 2;
        break;
    }
    }
    double h = 0;
    for (int i = 0; i < 3; i++) {
        out[i] = c[i] + R[4 * i] * w[0] + R[4 * i + 1] * w[1] + R[4 * i + 2] * w[2];
        h += m[i] * out[i];
    }
    return h;
}

// The translation of a along the unit n that parts it from b.
static inline double convex_depth_along(dGeomID a, dGeomID b, const double n[3])
{
    double m[3] = { -n[0], -n[1], -n[2] }, p[3];
    return convex_support(b, n, p) + convex_support(a, m, p);
}

// The least convex_depth_along over 20000 directions spread on the sphere (a
// Fibonacci lattice), each then improved by random local steps: an estimate
// of the penetration depth from above (negative: apart by about that much).
static inline double convex_brute_force_depth(dGeomID a, dGeomID b)
{
    enum { N = 20000 };
    double best = INFINITY, bn[3] = { 0, 0, 1 };
    for (int i = 0; i < N; i++) {
        double z = 1 - 2 * (i + 0.5) / N, r = sqrt(1 - z * z), phi = i * 2.399963229728653;
        double n[3] = { r * cos(phi), r * sin(phi), z }, f = convex_depth_along(a, b, n);
        if (f < best) {
            best = f;
            memcpy(bn, n, sizeof bn);
        }
    }
    unsigned long long state = 99;
    double step = 0.03;
    for (int it = 0; it < 4000 && step > 1e-9; it++) {
        double m[3], l = 0;
        for (int k = 0; k < 3; k++) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            m[k] = bn[k] + step * ((double)(state >> 11) / 4503599627370496.0 - 1);
            l += m[k] * m[k];
        }
        for (int k = 0; k < 3; k++) m[k] /= sqrt(l);
        double f = convex_depth_along(a, b, m);
        if (f < best) {
            best = f;
            memcpy(bn, m, sizeof bn);
        } else if (it % 30 == 29) {
            step *= 0.6;
        }
    }
    return best;
}

#endif
