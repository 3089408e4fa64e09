// SPDX-License-Identifier: BSD-3-Clause
//
// test_contact_truth.c -- the ground truth of tools/contact_truth.c against
// closed forms: sphere-sphere, sphere-capsule, sphere-box (centre outside
// and inside), box-plane, box-box (face-aligned, under a common rotation),
// the distance of separated pairs, and the point depth of every class.
// The largest errors are printed (tools/README.md quotes them).

#include "collide_check.h"
#include "contact_truth.h"
#include "test.h"

#include <math.h>
#include <stdio.h>

enum { SAMPLES = 300 };

// Truth tolerance: the search refines to 1e-12 rad; in single precision the
// closed forms read the same stored floats, so only rounding of the closed
// forms' float inputs differs.
#define TRUTH_TOL TOL(1e-8, 1e-5)

static double vdist(const dReal *a, const dReal *b)
{
    double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static void random_rotation(dGeomID g)
{
    set_rot(g, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) + 0.01, rnd(0, 6.3));
}

// Angle between the truth's normal and n.
static double normal_error(const contact_truth *t, const double n[3])
{
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double c = (t->normal[0] * n[0] + t->normal[1] * n[1] + t->normal[2] * n[2]) / l;
    return acos(fmin(1, fmax(-1, c)));
}

static int test_sphere_sphere_depth_and_distance(void)
{
    rng_state = 11;
    double worst = 0, worst_angle = 0;
    for (int i = 0; i < SAMPLES; i++) {
        dGeomID a = dCreateSphere(0, rnd(0.1, 1)), b = dCreateSphere(0, rnd(0.1, 1));
        dGeomSetPosition(a, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        dGeomSetPosition(b, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        const dReal *pa = dGeomGetPosition(a), *pb = dGeomGetPosition(b);
        double d = vdist(pa, pb);
        double want = dGeomSphereGetRadius(a) + dGeomSphereGetRadius(b) - d;
        double n[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
        contact_truth t;

        CHECK(contact_truth_compute(a, b, &t));

        worst = fmax(worst, fabs(t.depth - want));
        if (d > 1e-3) worst_angle = fmax(worst_angle, normal_error(&t, n));
        CHECK(t.overlap == (t.depth > 0));
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    printf("# sphere-sphere: depth error %.2g, normal error %.2g rad\n", worst, worst_angle);
    CHECK(worst < TRUTH_TOL);
    CHECK(worst_angle < TOL(1e-5, 1e-2));
    return 0;
}

static int test_sphere_capsule_depth(void)
{
    rng_state = 12;
    double worst = 0;
    for (int i = 0; i < SAMPLES; i++) {
        dGeomID a = dCreateCapsule(0, rnd(0.1, 0.5), rnd(0, 1.5));
        dGeomID b = dCreateSphere(0, rnd(0.1, 1));
        dGeomSetPosition(a, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        random_rotation(a);
        dGeomSetPosition(b, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        dReal r, len;
        dGeomCapsuleGetParams(a, &r, &len);
        const dReal *pb = dGeomGetPosition(b);
        double p[3] = { pb[0], pb[1], pb[2] };
        // Capsule point depth is r - distance to the axis segment (closed form).
        double want = dGeomSphereGetRadius(b) + contact_truth_point_depth(a, p);
        contact_truth t;

        CHECK(contact_truth_compute(a, b, &t));

        worst = fmax(worst, fabs(t.depth - want));
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    printf("# sphere-capsule: depth error %.2g\n", worst);
    CHECK(worst < TRUTH_TOL);
    return 0;
}

// A sphere against a box: r minus the distance from the centre to the box
// when the centre is outside, r plus the centre's depth inside.
static int test_sphere_box_depth(void)
{
    rng_state = 13;
    double worst = 0;
    for (int i = 0; i < SAMPLES; i++) {
        dGeomID a = dCreateBox(0, rnd(0.1, 1.5), rnd(0.1, 1.5), rnd(0.1, 1.5));
        dGeomID b = dCreateSphere(0, rnd(0.1, 1));
        dGeomSetPosition(a, rnd(-0.3, 0.3), rnd(-0.3, 0.3), rnd(-0.3, 0.3));
        random_rotation(a);
        dGeomSetPosition(b, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        const dReal *pb = dGeomGetPosition(b);
        double want = dGeomSphereGetRadius(b) + dGeomBoxPointDepth(a, pb[0], pb[1], pb[2]);
        double p[3] = { pb[0], pb[1], pb[2] }, pd = contact_truth_point_depth(a, p);
        if (pd < 0) want = dGeomSphereGetRadius(b) + pd;   // ODE's box point depth is only signed
        contact_truth t;

        CHECK(contact_truth_compute(b, a, &t));

        worst = fmax(worst, fabs(t.depth - want));
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    printf("# sphere-box: depth error %.2g\n", worst);
    CHECK(worst < TRUTH_TOL);
    return 0;
}

// A box against a plane: the plane offset minus the lowest corner, along
// the plane's normal, both argument orders.
static int test_box_plane_depth(void)
{
    rng_state = 14;
    double worst = 0;
    for (int i = 0; i < SAMPLES; i++) {
        dGeomID box = dCreateBox(0, rnd(0.1, 1.5), rnd(0.1, 1.5), rnd(0.1, 1.5));
        dGeomID plane = dCreatePlane(0, rnd(-1, 1), rnd(-1, 1), 1, rnd(-0.5, 0.5));
        dGeomSetPosition(box, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        random_rotation(box);
        dVector4 abcd;
        dGeomPlaneGetParams(plane, abcd);
        dVector3 side;
        dGeomBoxGetLengths(box, side);
        const dReal *c = dGeomGetPosition(box), *R = dGeomGetRotation(box);
        double low = INFINITY;
        for (int k = 0; k < 8; k++) {
            double h = 0;
            for (int j = 0; j < 3; j++) {
                double x = c[j];
                for (int m = 0; m < 3; m++)
                    x += R[4 * j + m] * ((k >> m & 1) ? 0.5 : -0.5) * side[m];
                h += abcd[j] * x;
            }
            low = fmin(low, h);
        }
        contact_truth t1, t2;

        CHECK(contact_truth_compute(box, plane, &t1));
        CHECK(contact_truth_compute(plane, box, &t2));

        worst = fmax(worst, fabs(t1.depth - (abcd[3] - low)));
        worst = fmax(worst, fabs(t2.depth - (abcd[3] - low)));
        CHECK_NEAR(t1.normal[2], abcd[2], 1e-12);
        CHECK_NEAR(t2.normal[2], -abcd[2], 1e-12);
        dGeomDestroy(box);
        dGeomDestroy(plane);
    }
    printf("# box-plane: depth error %.2g\n", worst);
    CHECK(worst < TRUTH_TOL);
    return 0;
}

// Two boxes with the same rotation: their Minkowski difference is a box of
// the summed sides, so the depth is the least overlap over its three axes.
static int test_aligned_box_box_depth(void)
{
    rng_state = 15;
    double worst = 0, worst_angle = 0;
    for (int i = 0; i < SAMPLES; i++) {
        dGeomID a = dCreateBox(0, rnd(0.1, 1.5), rnd(0.1, 1.5), rnd(0.1, 1.5));
        dGeomID b = dCreateBox(0, rnd(0.1, 1.5), rnd(0.1, 1.5), rnd(0.1, 1.5));
        dGeomSetPosition(a, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        dGeomSetPosition(b, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        random_rotation(a);
        dGeomSetRotation(b, dGeomGetRotation(a));
        dVector3 sa, sb;
        dGeomBoxGetLengths(a, sa);
        dGeomBoxGetLengths(b, sb);
        const dReal *pa = dGeomGetPosition(a), *pb = dGeomGetPosition(b), *R = dGeomGetRotation(a);
        double want = INFINITY, axis[3] = { 0, 0, 0 };
        for (int m = 0; m < 3; m++) {   // along box axis m (column m of R)
            double s = 0;
            for (int j = 0; j < 3; j++) s += R[4 * j + m] * (pa[j] - pb[j]);
            double o = 0.5 * (sa[m] + sb[m]) - fabs(s);
            if (o < want) {
                want = o;
                for (int j = 0; j < 3; j++) axis[j] = (s < 0 ? -1 : 1) * R[4 * j + m];
            }
        }
        contact_truth t;

        CHECK(contact_truth_compute(a, b, &t));

        if (want > 0) {   // apart, the distance is not the least axis gap
            worst = fmax(worst, fabs(t.depth - want));
            worst_angle = fmax(worst_angle, normal_error(&t, axis));
        }
        CHECK(t.overlap == (want > 0));
        dGeomDestroy(a);
        dGeomDestroy(b);
    }
    printf("# box-box (aligned): depth error %.2g, normal error %.2g rad\n", worst, worst_angle);
    CHECK(worst < TRUTH_TOL);
    return 0;
}

// The point depth of each class against ODE's own point-depth functions
// (boxes: inside only, where ODE's is the distance to the surface), and
// against collide_check.h's cylinder depth.
static int test_point_depth_matches_ode(void)
{
    rng_state = 16;
    dGeomID g[5] = { dCreateSphere(0, 0.4), dCreateBox(0, 0.3, 0.6, 0.9),
                     dCreateCapsule(0, 0.3, 0.8), dCreateCylinder(0, 0.35, 0.7),
                     dCreatePlane(0, 0.2, -0.3, 1, 0.1) };
    for (int k = 0; k < 4; k++) {
        dGeomSetPosition(g[k], 0.1, -0.2, 0.3);
        random_rotation(g[k]);
    }
    for (int i = 0; i < SAMPLES; i++) {
        double p[3] = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
        dReal q[3] = { p[0], p[1], p[2] };
        CHECK_NEAR(contact_truth_point_depth(g[0], p),
                   dGeomSpherePointDepth(g[0], q[0], q[1], q[2]), TRUTH_TOL);
        double bd = contact_truth_point_depth(g[1], p);
        if (bd >= 0) CHECK_NEAR(bd, dGeomBoxPointDepth(g[1], q[0], q[1], q[2]), TRUTH_TOL);
        CHECK_NEAR(contact_truth_point_depth(g[2], p),
                   dGeomCapsulePointDepth(g[2], q[0], q[1], q[2]), TRUTH_TOL);
        CHECK_NEAR(contact_truth_point_depth(g[3], p), point_depth(g[3], q), TRUTH_TOL);
        CHECK_NEAR(contact_truth_point_depth(g[4], p), dGeomPlanePointDepth(g[4], q[0], q[1], q[2]),
                   TRUTH_TOL);
        CHECK(contact_truth_point_inside(g[1], p, 0.01) == (bd >= -0.01));
    }
    for (int k = 0; k < 5; k++) dGeomDestroy(g[k]);
    return 0;
}

// Rays and two planes are not pairs of the truth: it says so and writes nothing.
static int test_unsupported_pairs_are_refused(void)
{
    dGeomID ray = dCreateRay(0, 1), p1 = dCreatePlane(0, 0, 0, 1, 0);
    dGeomID p2 = dCreatePlane(0, 1, 0, 0, 0);
    contact_truth t = { 7, 7, { 7, 7, 7 } };

    CHECK(!contact_truth_compute(ray, p1, &t));
    CHECK(!contact_truth_compute(p1, p2, &t));
    CHECK(t.overlap == 7 && t.depth == 7);
    CHECK(!contact_truth_supports(dRayClass));
    dGeomDestroy(ray);
    dGeomDestroy(p1);
    dGeomDestroy(p2);
    return 0;
}

static int setup(void)
{
    dInitODE();
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(setup),
    TEST_CASE(test_sphere_sphere_depth_and_distance),
    TEST_CASE(test_sphere_capsule_depth),
    TEST_CASE(test_sphere_box_depth),
    TEST_CASE(test_box_plane_depth),
    TEST_CASE(test_aligned_box_box_depth),
    TEST_CASE(test_point_depth_matches_ode),
    TEST_CASE(test_unsupported_pairs_are_refused),
    TEST_END
};
