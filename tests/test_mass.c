// SPDX-License-Identifier: BSD-3-Clause
//
// test_mass.c -- mass parameters. The solids are checked against an
// independent numerical integration (thin discs summed with Simpson's rule),
// and the operations against the parallel axis theorem and composition:
// pieces translated into place and added make the whole.

#include "test.h"

// Relative rounding of a few operations: the inertia values are built from
// a handful of products, so a few ulps of dReal, with margin.
#define REL_TOL TOL(1e-13, 2e-6)

static dReal el(const dReal *M, int i, int j) { return M[4 * i + j]; }

// |a - b| <= tol * max(1, |b|) for a relative check of quantities of any size.
static int near_rel(double a, double b, double tol)
{
    return fabs(a - b) <= tol * fmax(1.0, fabs(b));
}

#define CHECK_REL(a, b, tol) \
    do { \
        if (!near_rel((a), (b), (tol))) { \
            test_fail(__FILE__, __LINE__, "CHECK_REL(%s, %s): %.17g vs %.17g", #a, #b, \
                      (double)(a), (double)(b)); \
            return 1; \
        } \
    } while (0)

// Two masses agree: mass, centre and all nine inertia entries, relatively.
static int masses_near(const dMass *a, const dMass *b, double tol)
{
    double scale = fmax(fmax(fabs(b->I[0]), fabs(b->I[5])), fabs(b->I[10]));
    CHECK_REL(a->mass, b->mass, tol);
    for (int i = 0; i < 3; i++) CHECK_NEAR(a->c[i], b->c[i], tol * fmax(1, fabs(b->c[i])));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(el(a->I, i, j), el(b->I, i, j), tol * scale);
    return 0;
}

// Nothing changed at all (bitwise): used after rejected calls.
static int unchanged(const dMass *a, const dMass *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

// ---------------------------------------------------------------- integration

// Squared radius of the slice at height s of a capsule (p[0] = r, p[1] = l),
// whose cylinder spans |s| <= l/2 and caps reach to l/2 + r.
static double capsule_r2(double s, const double *p)
{
    double r = p[0], u = fabs(s) - p[1] / 2;
    return u <= 0 ? r * r : r * r - u * u;
}

// Integrate unit-density mass properties of a solid of revolution about the
// z axis over s in [s0, s1] by composite Simpson's rule. The slice at height s
// is a disc of radius p (p^2 = r2(s)): mass pi p^2 ds, axial inertia
// pi p^4/2 ds, and about the x axis through the origin pi p^4/4 ds +
// pi p^2 s^2 ds (its own diameter plus the parallel axis term). The integrands
// are polynomials of degree <= 4 on each smooth piece, so with n = 1000 the
// error h^4 f''''/180 is below 1e-13 of the result.
static void integrate_slices(double (*r2)(double, const double *), const double *p, double s0,
                             double s1, double out[3])
{
    const int n = 1000;
    double h = (s1 - s0) / n;
    for (int k = 0; k <= n; k++) {
        double s = s0 + k * h, a = r2(s, p), w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        out[0] += w * h / 3 * M_PI * a;
        out[1] += w * h / 3 * M_PI * a * a / 2;
        out[2] += w * h / 3 * (M_PI * a * a / 4 + M_PI * a * s * s);
    }
}

// {mass, axial, transverse} of a unit-density capsule, piece by piece.
static void integrate_capsule(double r, double l, double out[3])
{
    double p[2] = {r, l};
    out[0] = out[1] = out[2] = 0;
    integrate_slices(capsule_r2, p, -l / 2 - r, -l / 2, out);
    if (l > 0) integrate_slices(capsule_r2, p, -l / 2, l / 2, out);
    integrate_slices(capsule_r2, p, l / 2, l / 2 + r, out);
}

// The diagonal index of axis `direction` (1..3) and of a transverse axis.
static int axial_index(int direction) { return 5 * (direction - 1); }
static int transverse_index(int direction) { return direction == 1 ? 5 : 0; }

// A solid of revolution centred at the origin: c = 0, I diagonal with the
// axial value on `direction`, transverse on the two others, pads 0.
static int check_revolution(const dMass *m, int direction, double mass, double axial,
                            double transverse, double tol)
{
    CHECK_REL(m->mass, mass, tol);
    for (int i = 0; i < 4; i++) CHECK(m->c[i] == 0);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            if (i != j) CHECK(el(m->I, i, j) == 0);
        }
        CHECK_REL(el(m->I, i, i), i == direction - 1 ? axial : transverse, tol);
    }
    return 0;
}

// Tolerance for comparing with the integration: its own 1e-13, or single rounding.
#define INTEGRATION_TOL TOL(1e-11, 2e-6)

// ---------------------------------------------------------------- basics

static int test_set_zero(void)
{
    dMass m;
    memset(&m, 0x55, sizeof m);
    dMassSetZero(&m);
    CHECK(m.mass == 0);
    for (int i = 0; i < 4; i++) CHECK(m.c[i] == 0);
    for (int i = 0; i < 12; i++) CHECK(m.I[i] == 0);
    return 0;
}

static int test_set_parameters_fills_a_symmetric_tensor(void)
{
    dMass m;
    memset(&m, 0x55, sizeof m);
    dMassSetParameters(&m, 2, 0.5f, -1, 3, 11, 22, 33, 12, 13, 23);
    CHECK(m.mass == 2);
    CHECK(m.c[0] == 0.5f && m.c[1] == -1 && m.c[2] == 3);
    const dReal want[12] = {11, 12, 13, 0, 12, 22, 23, 0, 13, 23, 33, 0};
    for (int i = 0; i < 12; i++) CHECK(m.I[i] == want[i]);
    return 0;
}

// ---------------------------------------------------------------- solids

static int test_sphere_matches_formula_and_integration(void)
{
    const dReal r = 0.7f, rho = 3;
    dMass m;
    dMassSetSphere(&m, rho, r);
    double mass = 4.0 / 3 * M_PI * r * r * r * rho;
    if (check_revolution(&m, 3, mass, 0.4 * mass * r * r, 0.4 * mass * r * r, REL_TOL)) return 1;

    // a sphere is a capsule of length 0: integrate it as such
    double in[3];
    integrate_capsule(r, 0, in);
    CHECK_REL(m.mass, rho * in[0], INTEGRATION_TOL);
    CHECK_REL(m.I[0], rho * in[2], INTEGRATION_TOL);
    CHECK_REL(m.I[10], rho * in[1], INTEGRATION_TOL);

    dMass t;
    dMassSetSphereTotal(&t, 5, r);
    return check_revolution(&t, 1, 5, 0.4 * 5 * r * r, 0.4 * 5 * r * r, REL_TOL);
}

static int test_capsule_matches_integration(void)
{
    const double shapes[][2] = {{0.5, 2}, {1, 0.3}, {0.2, 5}, {1.5, 1.5}};
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++)
        for (int dir = 1; dir <= 3; dir++) {
            dReal r = (dReal)shapes[k][0], l = (dReal)shapes[k][1], rho = 2.5f;
            double in[3];
            integrate_capsule(r, l, in);
            dMass m;
            dMassSetCapsule(&m, rho, dir, r, l);
            if (check_revolution(&m, dir, rho * in[0], rho * in[1], rho * in[2],
                                 INTEGRATION_TOL))
                return 1;
            // and the closed form of the brief: M1 = pi r^2 l rho, M2 = 4/3 pi r^3 rho
            double m1 = M_PI * r * r * l * rho, m2 = 4.0 / 3 * M_PI * r * r * r * rho;
            CHECK_REL(m.I[axial_index(dir)], (m1 / 2 + 0.4 * m2) * r * r, REL_TOL);
            CHECK_REL(m.I[transverse_index(dir)],
                      m1 * (r * r / 4 + l * l / 12) +
                          m2 * (0.4 * r * r + 0.375 * r * l + l * l / 4),
                      REL_TOL);
        }
    return 0;
}

static int test_capsule_of_length_zero_is_a_sphere(void)
{
    dMass c, s;
    dMassSetCapsule(&c, 2, 2, 0.8f, 0);
    dMassSetSphere(&s, 2, 0.8f);
    return masses_near(&c, &s, REL_TOL);
}

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
static int test_capsule_total_and_old_names(void)
{
    dMass a, b, c, d;
    dMassSetCapsule(&a, 1, 3, 0.4f, 1.2f);
    dMassSetCapsuleTotal(&b, 7, 3, 0.4f, 1.2f);
    dMassAdjust(&a, 7);
    if (masses_near(&a, &b, REL_TOL)) return 1;
    CHECK(b.mass == 7);

    dMassSetCappedCylinder(&c, 1, 3, 0.4f, 1.2f);   // the ODE 0.5 names
    dMassSetCappedCylinderTotal(&d, 7, 3, 0.4f, 1.2f);
    dMassSetCapsule(&a, 1, 3, 0.4f, 1.2f);
    CHECK(memcmp(&a, &c, sizeof a) == 0);
    CHECK(memcmp(&b, &d, sizeof b) == 0);
    return 0;
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

static double cylinder_r2(double s, const double *p)
{
    (void)s;
    return p[0] * p[0];
}

static int test_cylinder_matches_integration(void)
{
    const double shapes[][2] = {{0.5, 2}, {1, 0.3}, {0.2, 5}};
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++)
        for (int dir = 1; dir <= 3; dir++) {
            dReal r = (dReal)shapes[k][0], l = (dReal)shapes[k][1], rho = 0.8f;
            double in[3] = {0, 0, 0}, p[1] = {r};
            integrate_slices(cylinder_r2, p, -l / 2, l / 2, in);
            dMass m;
            dMassSetCylinder(&m, rho, dir, r, l);
            if (check_revolution(&m, dir, rho * in[0], rho * in[1], rho * in[2],
                                 INTEGRATION_TOL))
                return 1;
            double mass = M_PI * r * r * l * rho;   // closed form
            CHECK_REL(m.I[axial_index(dir)], mass * r * r / 2, REL_TOL);
            CHECK_REL(m.I[transverse_index(dir)], mass * (r * r / 4 + l * l / 12), REL_TOL);
        }
    return 0;
}

static int test_cylinder_total_and_thin_disc(void)
{
    dMass a, b;
    dMassSetCylinder(&a, 1, 2, 0.4f, 1.2f);
    dMassSetCylinderTotal(&b, 3, 2, 0.4f, 1.2f);
    dMassAdjust(&a, 3);
    if (masses_near(&a, &b, REL_TOL)) return 1;

    // length 0 with a total mass: a flat disc, axial m r^2/2, diameters m r^2/4
    dMassSetCylinderTotal(&b, 2, 1, 0.5f, 0);
    if (check_revolution(&b, 1, 2, 0.25, 0.125, REL_TOL)) return 1;
    CHECK(dMassCheck(&b));
    return 0;
}

static int test_box_matches_formula(void)
{
    const dReal lx = 1, ly = 2, lz = 3, rho = 4;
    dMass m;
    dMassSetBox(&m, rho, lx, ly, lz);
    double mass = 24;
    CHECK(m.mass == mass);
    CHECK_REL(m.I[0], mass * (ly * ly + lz * lz) / 12, REL_TOL);
    CHECK_REL(m.I[5], mass * (lx * lx + lz * lz) / 12, REL_TOL);
    CHECK_REL(m.I[10], mass * (lx * lx + ly * ly) / 12, REL_TOL);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (i != j) CHECK(el(m.I, i, j) == 0);
    for (int i = 0; i < 4; i++) CHECK(m.c[i] == 0);

    // a cube of side a: every axis m a^2 / 6
    dMassSetBoxTotal(&m, 6, 2, 2, 2);
    CHECK(m.mass == 6);
    for (int i = 0; i < 3; i++) CHECK_REL(el(m.I, i, i), 6.0 * 4 / 6, REL_TOL);
    return 0;
}

// ---------------------------------------------------------------- composition

static int test_two_half_boxes_side_by_side_make_the_box(void)
{
    for (int axis = 0; axis < 3; axis++) {
        dReal L[3] = {1.2f, 0.7f, 2.1f}, half[3] = {L[0], L[1], L[2]}, t[3] = {0, 0, 0};
        half[axis] /= 2;
        t[axis] = L[axis] / 4;   // the half boxes' centres
        dMass whole, a, b;
        dMassSetBox(&whole, 3, L[0], L[1], L[2]);
        dMassSetBox(&a, 3, half[0], half[1], half[2]);
        b = a;
        dMassTranslate(&a, t[0], t[1], t[2]);
        dMassTranslate(&b, -t[0], -t[1], -t[2]);
        dMassAdd(&a, &b);
        if (masses_near(&a, &whole, REL_TOL)) return 1;
    }
    return 0;
}

static int test_two_half_cylinders_end_to_end_make_the_cylinder(void)
{
    // checks the l^2/12 term: 2 (m/2)((l/2)^2 k + (l/4)^2) = m l^2 k only for k = 1/12
    dMass whole, a, b;
    dMassSetCylinder(&whole, 2, 3, 0.3f, 1.6f);
    dMassSetCylinder(&a, 2, 3, 0.3f, 0.8f);
    b = a;
    dMassTranslate(&a, 0, 0, 0.4f);
    dMassTranslate(&b, 0, 0, -0.4f);
    dMassAdd(&a, &b);
    return masses_near(&a, &whole, REL_TOL);
}

static int test_capsule_is_cylinder_plus_displaced_sphere_halves(void)
{
    // the caps of a capsule are two hemispheres; moved together they are a
    // sphere, so capsule - cylinder has the sphere's mass, and its
    // transverse inertia is that of the sphere plus, per the parallel axis
    // theorem for each hemisphere (centre 3r/8 from its face, at l/2 + 3r/8):
    // M2 ((l/2 + 3r/8)^2 - (3r/8)^2) = M2 (l^2/4 + 3 r l / 8)
    const dReal r = 0.6f, l = 1.4f;
    dMass cap, cyl, sph;
    dMassSetCapsule(&cap, 1, 3, r, l);
    dMassSetCylinder(&cyl, 1, 3, r, l);
    dMassSetSphere(&sph, 1, r);
    CHECK_REL(cap.mass, cyl.mass + sph.mass, REL_TOL);
    CHECK_REL(cap.I[10], cyl.I[10] + sph.I[10], REL_TOL);
    CHECK_REL(cap.I[0], cyl.I[0] + sph.I[0] + sph.mass * (l * l / 4 + 3 * r * l / 8), REL_TOL);
    return 0;
}

// ---------------------------------------------------------------- operations

static int test_adjust_scales_mass_and_inertia(void)
{
    dMass m, orig;
    dMassSetBox(&m, 1, 1, 2, 3);
    dMassTranslate(&m, 0.5f, -0.2f, 0.1f);
    orig = m;
    dMassAdjust(&m, 3 * orig.mass);
    CHECK(m.mass == 3 * orig.mass);
    for (int i = 0; i < 3; i++) CHECK(m.c[i] == orig.c[i]);   // same shape, same centre
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_REL(el(m.I, i, j), 3 * el(orig.I, i, j), REL_TOL);
    dMassAdjust(&m, orig.mass);
    return masses_near(&m, &orig, REL_TOL);
}

static int test_translate_obeys_parallel_axis_theorem(void)
{
    const dReal r = 0.5f, t[3] = {1, -2, 0.5f};
    dMass m, s;
    dMassSetSphereTotal(&m, 2, r);
    s = m;
    dMassTranslate(&m, t[0], t[1], t[2]);
    // about the origin: I = I_c + m (|t|^2 E - t t^T)
    double t2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    for (int i = 0; i < 3; i++) {
        CHECK(m.c[i] == t[i]);
        for (int j = 0; j < 3; j++)
            CHECK_NEAR(el(m.I, i, j), el(s.I, i, j) + 2 * ((i == j ? t2 : 0) - t[i] * t[j]),
                       REL_TOL * 20);
    }
    // translating back restores the original, and two moves add up
    dMass back = m;
    dMassTranslate(&back, -t[0], -t[1], -t[2]);
    if (masses_near(&back, &s, REL_TOL * 20)) return 1;
    dMass two = s;
    dMassTranslate(&two, 0.3f, 0, 0);
    dMassTranslate(&two, t[0] - 0.3f, t[1], t[2]);
    return masses_near(&two, &m, REL_TOL * 20);
}

// Inertia about the centre of mass: I + mass [c]x^2 = I - mass (|c|^2 E - c c^T).
static void inertia_about_centre(const dMass *m, double out[3][3])
{
    double c2 = m->c[0] * m->c[0] + m->c[1] * m->c[1] + m->c[2] * m->c[2];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = el(m->I, i, j) - m->mass * ((i == j ? c2 : 0) - m->c[i] * m->c[j]);
}

static int test_translate_keeps_inertia_about_the_centre(void)
{
    dMass m;
    dMatrix3 R;
    dMassSetBox(&m, 1, 0.4f, 1, 1.6f);
    dRFromAxisAndAngle(R, 1, 1, 0, 0.7f);
    dMassRotate(&m, R);
    dMassTranslate(&m, 0.2f, 0.3f, -0.1f);
    double before[3][3], after[3][3];
    inertia_about_centre(&m, before);
    dMassTranslate(&m, -1, 0.5f, 2);
    inertia_about_centre(&m, after);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(after[i][j], before[i][j], REL_TOL * 50);
    return 0;
}

static int test_rotate_turns_the_principal_axes(void)
{
    // a box long in x, turned a quarter about z, is long in y: Ixx <-> Iyy
    dMass m, turned;
    dMatrix3 R;
    dMassSetBox(&m, 1, 3, 1, 0.5f);
    turned = m;
    dRFromAxisAndAngle(R, 0, 0, 1, (dReal)(M_PI / 2));
    dMassRotate(&turned, R);
    CHECK_REL(turned.I[0], m.I[5], REL_TOL);
    CHECK_REL(turned.I[5], m.I[0], REL_TOL);
    CHECK_REL(turned.I[10], m.I[10], REL_TOL);
    CHECK_NEAR(turned.I[1], 0, REL_TOL * m.I[0]);

    // an off-centre sphere at +x, turned a quarter about z, sits at +y
    dMass a, b;
    dMassSetSphere(&a, 1, 0.3f);
    b = a;
    dMassTranslate(&a, 2, 0, 0);
    dMassTranslate(&b, 0, 2, 0);
    dMassRotate(&a, R);
    return masses_near(&a, &b, REL_TOL * 10);
}

static int test_rotate_preserves_invariants_and_inverts(void)
{
    dMass m, orig;
    dMassSetBox(&m, 1, 0.4f, 1, 1.6f);
    dMassTranslate(&m, 0.5f, -0.3f, 0.2f);
    orig = m;
    dMatrix3 R, RT;
    dRFromAxisAndAngle(R, 0.3f, -1, 0.6f, 2.1f);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) RT[4 * i + j] = j < 3 ? R[4 * j + i] : 0;

    dMassRotate(&m, R);
    // symmetric, same trace (sum of eigenvalues) and determinant, |c| kept
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK(el(m.I, i, j) == el(m.I, j, i));
    CHECK_REL(m.I[0] + m.I[5] + m.I[10], orig.I[0] + orig.I[5] + orig.I[10], REL_TOL);
    CHECK_REL(dCalcMatrix3Det(m.I), dCalcMatrix3Det(orig.I), REL_TOL * 10);
    CHECK_REL(dCalcVectorLength3(m.c), dCalcVectorLength3(orig.c), REL_TOL);
    dReal rc[3];
    dMultiply0_331(rc, R, orig.c);
    for (int i = 0; i < 3; i++) CHECK_NEAR(m.c[i], rc[i], REL_TOL);
    CHECK(m.mass == orig.mass);

    dMassRotate(&m, RT);   // and back
    return masses_near(&m, &orig, REL_TOL * 10);
}

static int test_add_weights_the_centres(void)
{
    dMass a, b;
    dMassSetSphereTotal(&a, 1, 0.2f);
    dMassSetSphereTotal(&b, 3, 0.4f);
    dMassTranslate(&a, 4, 0, 0);
    dMassTranslate(&b, 0, 4, 0);
    dMass sum = a;
    dMassAdd(&sum, &b);
    CHECK(sum.mass == 4);
    CHECK_NEAR(sum.c[0], 1, REL_TOL);   // (1*4 + 3*0) / 4
    CHECK_NEAR(sum.c[1], 3, REL_TOL);   // (1*0 + 3*4) / 4
    CHECK(sum.c[2] == 0);
    for (int i = 0; i < 12; i++) CHECK(sum.I[i] == a.I[i] + b.I[i]);   // same origin
    CHECK(dMassCheck(&sum));

    dMassAdd(&a, &a);   // itself: twice the mass, same centre
    CHECK(a.mass == 2 && a.c[0] == 4);
    return 0;
}

// ---------------------------------------------------------------- dMassCheck

static int test_check_accepts_valid_masses(void)
{
    test_capture_reports();
    dMass m;
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 2, 3, 0.9f);

    dMassSetSphere(&m, 1, 1);
    CHECK(dMassCheck(&m));
    dMassSetCapsule(&m, 1, 2, 0.1f, 4);
    CHECK(dMassCheck(&m));
    dMassSetCylinder(&m, 1, 1, 0.1f, 4);
    CHECK(dMassCheck(&m));
    dMassSetBox(&m, 1, 0.01f, 1, 10);   // a thin plate
    CHECK(dMassCheck(&m));
    dMassTranslate(&m, 100, -50, 20);   // far from the origin: I is dominated by m d^2
    CHECK(dMassCheck(&m));
    dMassRotate(&m, R);
    CHECK(dMassCheck(&m));

    // scale does not matter: very small and very large bodies
    dMassSetBoxTotal(&m, TOL(1e-30, 1e-12f), TOL(1e-40, 1e-12f), TOL(2e-40, 2e-12f),
                     TOL(3e-40, 3e-12f));
    CHECK(dMassCheck(&m));
    dMassSetBoxTotal(&m, TOL(1e60, 1e12f), TOL(1e40, 1e10f), TOL(2e40, 2e10f),
                     TOL(3e40, 3e10f));
    CHECK(dMassCheck(&m));
    CHECK(test_captured_count() == 0);
    return 0;
}

static int test_check_rejects_invalid_masses(void)
{
    test_capture_reports();
    dMass m;

    dMassSetZero(&m);
    CHECK(!dMassCheck(&m));
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dMassCheck"));
    CHECK(test_captured_contains("mass"));

    // dMassSetParameters checks (and reports) as dMassCheck does, as in ODE 0.16
    dMassSetParameters(&m, -1, 0, 0, 0, 1, 1, 1, 0, 0, 0);   // negative mass
    CHECK(!dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, -1, 1, 0, 0, 0);   // negative moment
    CHECK(!dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 1, 0, 0);    // singular: I12 = sqrt(I11 I22)
    CHECK(!dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 0.6f, 0.6f, -0.6f);   // minors ok, det < 0
    CHECK(!dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 5, 0, 0);    // off-diagonal too large
    CHECK(!dMassCheck(&m));
    CHECK(test_captured_count() == 11);
    CHECK(test_captured_contains("positive definite"));
    CHECK(m.I[1] == 5);   // reported, and kept as given

    // a valid sphere's inertia about the origin, but a centre far away: the
    // inertia about the centre would be negative
    dMassSetSphere(&m, 1, 1);
    m.c[0] = 10;
    CHECK(!dMassCheck(&m));
    CHECK(test_captured_count() == 12);
    CHECK(test_captured_contains("centre of mass"));
    m.c[0] = NAN;
    CHECK(!dMassCheck(&m));
    CHECK(test_captured_count() == 13);
    CHECK(!dMassCheck(NULL));
    CHECK(test_captured_count() == 14);
    return 0;
}

// ---------------------------------------------------------------- bad arguments

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
static int test_bad_solid_arguments_are_reported_and_ignored(void)
{
    test_capture_reports();
    dMass m, keep;
    dMassSetBox(&m, 1, 1, 2, 3);
    keep = m;
    int n = 0;

#define REJECTED(call, text) \
    do { \
        call; \
        CHECK(test_captured_count() == ++n); \
        CHECK(test_captured_contains(text)); \
        CHECK(unchanged(&m, &keep)); \
    } while (0)

    REJECTED(dMassSetSphere(&m, 0, 1), "density");
    REJECTED(dMassSetSphere(&m, -1, 1), "density");
    REJECTED(dMassSetSphere(&m, NAN, 1), "density");
    REJECTED(dMassSetSphere(&m, 1, -1), "radius");
    REJECTED(dMassSetSphere(&m, 1, INFINITY), "radius");
    REJECTED(dMassSetSphereTotal(&m, 0, 1), "total mass");
    REJECTED(dMassSetSphereTotal(&m, 1, -1), "radius");
    REJECTED(dMassSetCapsule(&m, 1, 0, 1, 1), "direction");
    REJECTED(dMassSetCapsule(&m, 1, 4, 1, 1), "direction");
    REJECTED(dMassSetCapsule(&m, 1, 1, -1, 1), "radius");
    REJECTED(dMassSetCapsule(&m, 1, 1, 1, -1), "length");
    REJECTED(dMassSetCapsule(&m, 1, 1, 1, NAN), "length");
    REJECTED(dMassSetCapsuleTotal(&m, -2, 1, 1, 1), "total mass");
    REJECTED(dMassSetCappedCylinder(&m, 1, 5, 1, 1), "dMassSetCappedCylinder");
    REJECTED(dMassSetCappedCylinderTotal(&m, 0, 1, 1, 1), "dMassSetCappedCylinderTotal");
    REJECTED(dMassSetCylinder(&m, 1, 2, -1, 1), "radius");
    REJECTED(dMassSetCylinder(&m, 1, 2, 1, -0.5f), "length");
    REJECTED(dMassSetCylinderTotal(&m, 1, -1, 1, 1), "direction");
    REJECTED(dMassSetBox(&m, 1, -0.5f, 1, 1), "sides");
    REJECTED(dMassSetBox(&m, 1, 1, -1, 1), "sides");
    REJECTED(dMassSetBox(&m, 0, 1, 1, 1), "density");
    REJECTED(dMassSetBoxTotal(&m, 1, 1, 1, INFINITY), "sides");
    REJECTED(dMassSetParameters(&m, NAN, 0, 0, 0, 1, 1, 1, 0, 0, 0), "finite");
    REJECTED(dMassSetZero(NULL), "NULL");
    REJECTED(dMassSetSphere(NULL, 1, 1), "NULL");
    REJECTED(dMassSetBoxTotal(NULL, 1, 1, 1, 1), "NULL");
    return 0;
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

static int test_bad_operation_arguments_are_reported_and_ignored(void)
{
    test_capture_reports();
    dMass m, keep, zero;
    dMassSetSphere(&m, 1, 1);
    dMassTranslate(&m, 1, 0, 0);
    keep = m;
    dMassSetZero(&zero);
    int n = 0;
    dMatrix3 R;
    dRSetIdentity(R);

    REJECTED(dMassAdjust(&m, 0), "new mass");
    REJECTED(dMassAdjust(&m, -3), "new mass");
    REJECTED(dMassAdjust(&m, NAN), "new mass");
    REJECTED(dMassTranslate(&m, 0, NAN, 0), "finite");
    R[5] = NAN;
    REJECTED(dMassRotate(&m, R), "finite");
    REJECTED(dMassRotate(&m, NULL), "NULL");
    REJECTED(dMassAdd(&m, NULL), "NULL");
    REJECTED(dMassAdd(NULL, &m), "NULL");

    // operations on a zero mass
    dMass z = zero;
    dMassAdjust(&z, 2);
    CHECK(test_captured_count() == ++n);
    CHECK(z.mass == 0);
    dMassAdd(&z, &zero);
    CHECK(test_captured_count() == ++n);
    CHECK(test_captured_contains("total mass"));
    for (int i = 0; i < 3; i++) CHECK(!dIsNan(z.c[i]));
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_set_zero),
    TEST_CASE(test_set_parameters_fills_a_symmetric_tensor),
    TEST_CASE(test_sphere_matches_formula_and_integration),
    TEST_CASE(test_capsule_matches_integration),
    TEST_CASE(test_capsule_of_length_zero_is_a_sphere),
    TEST_CASE(test_capsule_total_and_old_names),
    TEST_CASE(test_cylinder_matches_integration),
    TEST_CASE(test_cylinder_total_and_thin_disc),
    TEST_CASE(test_box_matches_formula),
    TEST_CASE(test_two_half_boxes_side_by_side_make_the_box),
    TEST_CASE(test_two_half_cylinders_end_to_end_make_the_cylinder),
    TEST_CASE(test_capsule_is_cylinder_plus_displaced_sphere_halves),
    TEST_CASE(test_adjust_scales_mass_and_inertia),
    TEST_CASE(test_translate_obeys_parallel_axis_theorem),
    TEST_CASE(test_translate_keeps_inertia_about_the_centre),
    TEST_CASE(test_rotate_turns_the_principal_axes),
    TEST_CASE(test_rotate_preserves_invariants_and_inverts),
    TEST_CASE(test_add_weights_the_centres),
    TEST_CASE(test_check_accepts_valid_masses),
    TEST_CASE(test_check_rejects_invalid_masses),
    TEST_CASE(test_bad_solid_arguments_are_reported_and_ignored),
    TEST_CASE(test_bad_operation_arguments_are_reported_and_ignored),
    TEST_END
};
