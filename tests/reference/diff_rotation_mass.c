// SPDX-License-Identifier: BSD-3-Clause
//
// diff_rotation_mass.c -- differential test of rotation.h, the non-inline
// functions of odemath.h and mass.h: the same deterministic inputs through
// this library and through the reference ODE. Only valid arguments are used
// (the two libraries report bad ones differently). Tolerances are 1e-12
// relative to the largest magnitude printed on the line.

#include "diff_print.h"

// Deterministic pseudo-random numbers in [-1, 1], computed by this program
// (not by the library) so both builds see the same bits.
static unsigned long long rng_state = 20240611;
static double rnd(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) / (double)(1ULL << 53) * 2 - 1;
}

// Print n values with tolerance 1e-12 * max(1, largest |value|).
static void print_scaled(const char *name, const dReal *v, int n)
{
    double big = 1;
    for (int i = 0; i < n; i++)
        if (fabs((double)v[i]) > big) big = fabs((double)v[i]);
    diff_values(name, 1e-12 * big, v, n);
}

static void print_matrix(const char *name, const dMatrix3 R)
{
    dReal v[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) v[i * 3 + j] = R[i * 4 + j];
    print_scaled(name, v, 9);
}

// q and -q are the same rotation, and Shepperd's branches may return either:
// print the one whose first clearly nonzero component is positive.
static void print_quaternion(const char *name, const dQuaternion q)
{
    dReal v[4] = {q[0], q[1], q[2], q[3]};
    for (int i = 0; i < 4; i++)
        if (fabs((double)v[i]) > 1e-9) {
            if (v[i] < 0)
                for (int k = 0; k < 4; k++) v[k] = -v[k];
            break;
        }
    print_scaled(name, v, 4);
}

static void print_mass(const char *name, const dMass *m)
{
    dReal v[13];
    v[0] = m->mass;
    for (int i = 0; i < 3; i++) v[1 + i] = m->c[i];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) v[4 + i * 3 + j] = m->I[i * 4 + j];
    print_scaled(name, v, 13);
}

// The rotation matrix of the quaternion (w, x, y, z) of any nonzero length,
// computed here so that dQfromR gets the same input bits in both builds. The
// homogeneous form (entries divided by |q|^2) needs no square root, which
// keeps this program free of libm calls (the reference build does not link
// libm explicitly).
static void matrix_of(dMatrix3 R, double w, double x, double y, double z)
{
    double n2 = w * w + x * x + y * y + z * z;
    double m[9] = {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z};
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) R[i * 4 + j] = (dReal)(m[i * 3 + j] / n2);
        R[i * 4 + 3] = 0;
    }
}

static void rotations(void)
{
    dMatrix3 R;
    dQuaternion q;
    dRSetIdentity(R);
    print_matrix("RSetIdentity", R);
    dQSetIdentity(q);
    print_quaternion("QSetIdentity", q);

    const double aa[][4] = {{0, 0, 1, M_PI / 2}, {1, 0, 0, 0.3}, {0, 2, 0, -1.2},
                            {1, 2, 3, 0.7}, {-3, 0.5, 0.1, M_PI}, {1e-3, -2e-3, 5e-4, 7},
                            {5, 5, 5, -20}};
    for (size_t k = 0; k < sizeof aa / sizeof aa[0]; k++) {
        dRFromAxisAndAngle(R, aa[k][0], aa[k][1], aa[k][2], aa[k][3]);
        print_matrix("RFromAxisAndAngle", R);
        dQFromAxisAndAngle(q, aa[k][0], aa[k][1], aa[k][2], aa[k][3]);
        print_quaternion("QFromAxisAndAngle", q);
    }

    const double eu[][3] = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5},
                            {0.3, -1.1, 2.5}, {-2, 1.5, -0.4}, {M_PI, M_PI / 2, 1}};
    for (size_t k = 0; k < sizeof eu / sizeof eu[0]; k++) {
        dRFromEulerAngles(R, eu[k][0], eu[k][1], eu[k][2]);
        print_matrix("RFromEulerAngles", R);
    }

    const double ab[][6] = {{1, 0, 0, 0, 1, 0}, {2, 0, 0, 3, 5, 0}, {1, 2, 3, -1, 0.5, 2},
                            {0, 0, -1, 1, 1, 1}, {1, 1, 0, 1, 1.01, 0}, {-4, 1, 2, 0, 0, 9}};
    for (size_t k = 0; k < sizeof ab / sizeof ab[0]; k++) {
        dRFrom2Axes(R, ab[k][0], ab[k][1], ab[k][2], ab[k][3], ab[k][4], ab[k][5]);
        print_matrix("RFrom2Axes", R);
    }

    const double za[][3] = {{0, 0, 1}, {0, 0, -2}, {1, 0, 0}, {0, 3, 0}, {1, 2, 3},
                            {0.7, 0, 0.72}, {0.72, 0, 0.7}, {-1, -1, 0.2}};
    for (size_t k = 0; k < sizeof za / sizeof za[0]; k++) {
        dRFromZAxis(R, za[k][0], za[k][1], za[k][2]);
        print_matrix("RFromZAxis", R);
    }
}

static void quaternions(void)
{
    for (int k = 0; k < 10; k++) {
        dQuaternion qb, qc, qa;
        for (int i = 0; i < 4; i++) qb[i] = rnd(), qc[i] = rnd();
        dQMultiply0(qa, qb, qc);
        print_scaled("QMultiply0", qa, 4);
        dQMultiply1(qa, qb, qc);
        print_scaled("QMultiply1", qa, 4);
        dQMultiply2(qa, qb, qc);
        print_scaled("QMultiply2", qa, 4);
        dQMultiply3(qa, qb, qc);
        print_scaled("QMultiply3", qa, 4);

        dQuaternion u;
        for (int i = 0; i < 4; i++) u[i] = qb[i];
        dSafeNormalize4(u);
        dMatrix3 R;
        dRfromQ(R, u);
        print_matrix("RfromQ", R);

        dVector3 w = {3 * rnd(), 3 * rnd(), 3 * rnd(), 0};
        dReal dq[4];
        dDQfromW(dq, w, u);
        print_scaled("DQfromW", dq, 4);
    }

    // dQfromR through every branch of Shepperd's method: w large, and half
    // turns (or nearly) about axes near x, y and z, diagonal ties included
    const double qs[][4] = {{1, 0, 0, 0}, {0.9, 0.1, -0.3, 0.2}, {0, 1, 0, 0}, {0, 0, 1, 0},
                            {0, 0, 0, 1}, {0.05, 1, 0.2, -0.1}, {-0.02, 0.1, -1, 0.3},
                            {0.01, 0.2, 0.1, 1}, {0, 1, 1, 0}, {0, 0, 1, 1}, {0, 1, 0, 1},
                            {0, 1, 1, 1}, {0.3, -0.4, 0.5, -0.6}};
    for (size_t k = 0; k < sizeof qs / sizeof qs[0]; k++) {
        dMatrix3 R;
        dQuaternion q;
        matrix_of(R, qs[k][0], qs[k][1], qs[k][2], qs[k][3]);
        dQfromR(q, R);
        print_quaternion("QfromR", q);
    }
    for (int k = 0; k < 20; k++) {
        dMatrix3 R;
        dQuaternion q;
        matrix_of(R, rnd(), rnd(), rnd(), rnd());
        dQfromR(q, R);
        print_quaternion("QfromR_random", q);
    }
}

static void odemath(void)
{
    // dSafeNormalize4 of the reference does not rescale, so its tiny and huge
    // vectors lose accuracy or overflow: those go through the 3-vector forms only
    const double vs[][4] = {{3, 4, 0, 0}, {1, -2, 2, 5}, {1e-3, 2e-3, -2e-3, 1e-3},
                            {0, 0, 7, 0}, {-0.1, 0.2, 0.3, -0.4}, {1e150, -2e150, 2e150, 0},
                            {1e-160, 1e-160, -1e-160, 0}, {1e-300, 0, 3e-300, 0}};
    for (size_t k = 0; k < sizeof vs / sizeof vs[0]; k++) {
        int scaled = k >= 5;
        dVector4 a = {vs[k][0], vs[k][1], vs[k][2], vs[k][3]}, b;
        for (int i = 0; i < 4; i++) b[i] = a[i];
        dReal r = dSafeNormalize3(a);
        print_scaled("SafeNormalize3", a, 3);
        diff_value("SafeNormalize3_result", 0, r);
        for (int i = 0; i < 4; i++) a[i] = vs[k][i];
        dNormalize3(a);
        print_scaled("Normalize3", a, 3);
        if (scaled) continue;
        r = dSafeNormalize4(b);
        print_scaled("SafeNormalize4", b, 4);
        diff_value("SafeNormalize4_result", 0, r);
        for (int i = 0; i < 4; i++) b[i] = vs[k][i];
        dNormalize4(b);
        print_scaled("Normalize4", b, 4);
    }
    // a zero vector: both return 0 (the reference leaves the vector zero,
    // this library sets it to (1,0,0[,0]) as its header documents)
    dVector4 z = {0, 0, 0, 0};
    diff_value("SafeNormalize3_zero_result", 0, dSafeNormalize3(z));
    dVector4 z4 = {0, 0, 0, 0};
    diff_value("SafeNormalize4_zero_result", 0, dSafeNormalize4(z4));

    // dPlaneSpace on both sides of the |n_z| = sqrt(1/2) switch and around
    const double ns[][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0.6, 0, 0.8},
                            {0.8, 0, 0.6}, {0, -0.6, -0.8}, {0.48, 0.6, 0.64}};
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
        dVector3 n = {ns[k][0], ns[k][1], ns[k][2], 0}, p, q;
        dPlaneSpace(n, p, q);
        print_scaled("PlaneSpace_p", p, 3);
        print_scaled("PlaneSpace_q", q, 3);
    }
    for (int k = 0; k < 20; k++) {
        dVector3 n = {rnd(), rnd(), rnd(), 0}, p, q;
        dSafeNormalize3(n);
        dPlaneSpace(n, p, q);
        print_scaled("PlaneSpace_random_p", p, 3);
        print_scaled("PlaneSpace_random_q", q, 3);
    }

    // dOrthogonalizeR of disturbed rotations. Rows 0 and 2 only: the
    // reference 0.16 normalises row 0 and sets row 2 = normalised row 0 x
    // row 1, but leaves row 1 as it was (not perpendicular to row 0); this
    // library makes row 1 perpendicular, which gives the same rows 0 and 2.
    for (int k = 0; k < 10; k++) {
        dMatrix3 R;
        matrix_of(R, rnd(), rnd(), rnd(), rnd());
        for (int i = 0; i < 12; i++)
            if (i % 4 != 3) R[i] += 0.01 * rnd();
        int ok = dOrthogonalizeR(R);
        dReal rows02[6] = {R[0], R[1], R[2], R[8], R[9], R[10]};
        print_scaled("OrthogonalizeR_rows_0_2", rows02, 6);
        diff_value("OrthogonalizeR_result", 0, ok);
    }
    dMatrix3 P = {1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0};   // parallel rows: refused
    int ok = dOrthogonalizeR(P);
    print_matrix("OrthogonalizeR_parallel", P);
    diff_value("OrthogonalizeR_parallel_result", 0, ok);
}

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
static void masses(void)
{
    dMass m, b;
    dMassSetZero(&m);
    print_mass("MassSetZero", &m);
    dMassSetParameters(&m, 2, 0.1, -0.2, 0.3, 1, 2, 3, 0.1, -0.2, 0.3);
    print_mass("MassSetParameters", &m);
    diff_value("MassCheck_parameters", 0, dMassCheck(&m));

    dMassSetSphere(&m, 3, 0.7);
    print_mass("MassSetSphere", &m);
    dMassSetSphereTotal(&m, 5, 0.4);
    print_mass("MassSetSphereTotal", &m);
    for (int dir = 1; dir <= 3; dir++) {
        dMassSetCapsule(&m, 2.5, dir, 0.5, 2);
        print_mass("MassSetCapsule", &m);
        dMassSetCapsuleTotal(&m, 4, dir, 0.3, 0.9);
        print_mass("MassSetCapsuleTotal", &m);
        dMassSetCappedCylinder(&m, 1.5, dir, 0.2, 1.1);
        print_mass("MassSetCappedCylinder", &m);
        dMassSetCappedCylinderTotal(&m, 7, dir, 1.2, 0.1);
        print_mass("MassSetCappedCylinderTotal", &m);
        dMassSetCylinder(&m, 0.8, dir, 0.5, 2);
        print_mass("MassSetCylinder", &m);
        dMassSetCylinderTotal(&m, 3, dir, 0.25, 4);
        print_mass("MassSetCylinderTotal", &m);
    }
    dMassSetCapsule(&m, 1, 2, 0.8, 0);   // length 0: a sphere
    print_mass("MassSetCapsule_length0", &m);
    dMassSetBox(&m, 4, 1, 2, 3);
    print_mass("MassSetBox", &m);
    dMassSetBoxTotal(&m, 6, 0.1, 5, 0.7);
    print_mass("MassSetBoxTotal", &m);

    // adjust, translate, rotate and add on an off-centre, turned box
    dMassSetBox(&m, 1, 0.4, 1, 1.6);
    dMassAdjust(&m, 2.5);
    print_mass("MassAdjust", &m);
    dMassTranslate(&m, 0.5, -0.3, 0.2);
    print_mass("MassTranslate", &m);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0.3, -1, 0.6, 2.1);
    dMassRotate(&m, R);
    print_mass("MassRotate", &m);
    dMassTranslate(&m, -1, 2, 0.5);
    print_mass("MassTranslate_again", &m);
    dMassAdjust(&m, 0.3);
    print_mass("MassAdjust_offcentre", &m);
    diff_value("MassCheck_valid", 0, dMassCheck(&m));

    dMassSetCapsuleTotal(&b, 1.5, 2, 0.2, 0.6);
    dMassTranslate(&b, 0, 1, -1);
    dMassAdd(&m, &b);
    print_mass("MassAdd", &m);
    diff_value("MassCheck_sum", 0, dMassCheck(&m));

    // dMassCheck rejections (messages go to stderr, only the results compare)
    dMassSetZero(&m);
    diff_value("MassCheck_zero", 0, dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 0.6, 0.6, -0.6);
    diff_value("MassCheck_indefinite", 0, dMassCheck(&m));
    dMassSetSphere(&m, 1, 1);
    m.c[0] = 10;
    diff_value("MassCheck_centre", 0, dMassCheck(&m));
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

int main(void)
{
    dInitODE2(0);
    rotations();
    quaternions();
    odemath();
    masses();
    dCloseODE();
    return 0;
}
