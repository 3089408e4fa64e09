// SPDX-License-Identifier: BSD-3-Clause
//
// test_compat.c -- what ODE programs rely on beyond the guide's letter:
// matrices whose padding (R[3], R[7], R[11]) is uninitialised, shapes and
// masses of size zero (created now, sized later), impossible masses reported
// through the message handler, and the guide index's names of the universal
// joint's rates.

#include "test.h"

#include <ode/backend.h>
#include <string.h>

#define EPS TOL(1e-12, 1e-5)

// Separate counts for the debug handler (errors) and the message handler.
static int debug_count, message_count;
static char last_message[256];

static void on_debug(int num, const char *msg, va_list ap)
{
    (void)num;
    (void)msg;
    (void)ap;
    debug_count++;
}

static void on_message(int num, const char *msg, va_list ap)
{
    (void)num;
    vsnprintf(last_message, sizeof last_message, msg, ap);
    message_count++;
}

static void count_reports(void)
{
    debug_count = message_count = 0;
    last_message[0] = 0;
    dSetDebugHandler(on_debug);
    dSetMessageHandler(on_message);
}

// A rotation with NaN in its padding, as an ODE program's stack may hold.
static void rotation_with_bad_padding(dMatrix3 R)
{
    dRFromAxisAndAngle(R, 0.3, -0.5, 0.8, 0.7);
    R[3] = R[7] = R[11] = NAN;
}

// ---- dMatrix3 padding -------------------------------------------------------

static int test_body_set_rotation_ignores_the_padding(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMatrix3 R;
    rotation_with_bad_padding(R);
    count_reports();

    dBodySetRotation(b, R);

    CHECK(debug_count == 0 && message_count == 0);
    const dReal *got = dBodyGetRotation(b);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_NEAR(got[4 * i + j], R[4 * i + j], EPS);
    dQuaternion q;
    dRtoQ(R, q);   // dRtoQ reads the 9 elements only
    const dReal *bq = dBodyGetQuaternion(b);
    for (int i = 0; i < 4; i++) CHECK_NEAR(fabs(bq[i]), fabs(q[i]), EPS);
    dWorldDestroy(w);
    return 0;
}

static int test_geom_set_rotation_ignores_the_padding(void)
{
    dGeomID g = dCreateBox(0, 1, 2, 3);
    dMatrix3 R;
    rotation_with_bad_padding(R);
    count_reports();

    dGeomSetRotation(g, R);

    CHECK(debug_count == 0 && message_count == 0);
    const dReal *got = dGeomGetRotation(g);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) CHECK_NEAR(got[4 * i + j], R[4 * i + j], EPS);
        CHECK(got[4 * i + 3] == 0);
    }
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    for (int i = 0; i < 6; i++) CHECK(isfinite(aabb[i]));
    dGeomDestroy(g);
    return 0;
}

// R I R^T by hand, against dMassRotate given a matrix with NaN padding.
static int test_mass_rotate_and_products_ignore_the_padding(void)
{
    dMatrix3 R;
    rotation_with_bad_padding(R);
    dMass m;
    dMassSetBoxTotal(&m, 2, 1, 2, 3);
    dReal want[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            want[i][j] = 0;
            for (int k = 0; k < 3; k++) want[i][j] += R[4 * i + k] * m.I[5 * k] * R[4 * j + k];
        }
    count_reports();

    dMassRotate(&m, R);
    dMatrix3 RR;
    dMultiply0_333(RR, R, R);

    CHECK(debug_count == 0 && message_count == 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            CHECK_NEAR(m.I[4 * i + j], want[i][j], TOL(1e-12, 1e-5));
            dReal rr = 0;
            for (int k = 0; k < 3; k++) rr += R[4 * i + k] * R[4 * k + j];
            CHECK_NEAR(RR[4 * i + j], rr, EPS);
        }
    return 0;
}

// ---- zero sizes ---------------------------------------------------------------

static int test_zero_sizes_are_valid_and_negative_ones_are_not(void)
{
    count_reports();

    dGeomID s = dCreateSphere(0, 0), b = dCreateBox(0, 0, 1, 0), c = dCreateCapsule(0, 0, 0);
    dGeomID y = dCreateCylinder(0, 0, 0), r = dCreateRay(0, 0);

    CHECK(debug_count == 0);
    CHECK(s && b && c && y && r);
    CHECK(dGeomSphereGetRadius(s) == 0);
    dGeomSphereSetRadius(s, 2);
    dGeomSphereSetRadius(s, 0);
    dGeomBoxSetLengths(b, 0, 0, 0);
    dGeomCapsuleSetParams(c, 0, 1);
    dGeomCylinderSetParams(y, 1, 0);
    CHECK(debug_count == 0);
    CHECK(dGeomSphereGetRadius(s) == 0);
    dReal radius, length;
    dGeomCylinderGetParams(y, &radius, &length);
    CHECK(radius == 1 && length == 0);

    dGeomSphereSetRadius(s, -1);
    dGeomBoxSetLengths(b, 0, -1, 0);
    dGeomCapsuleSetParams(c, NAN, 1);
    CHECK(dCreateCylinder(0, -1, 0) == 0);
    CHECK(debug_count == 4);
    CHECK(dGeomSphereGetRadius(s) == 0);
    dGeomDestroy(s);
    dGeomDestroy(b);
    dGeomDestroy(c);
    dGeomDestroy(y);
    dGeomDestroy(r);
    return 0;
}

enum { SHAPES = 6 };

// Shape k of each class (sphere, box, capsule, cylinder, plane, ray); size 0
// makes every size zero, size 1 gives ordinary sizes, size 2 mixes zero and
// non-zero sizes.
static dGeomID make_shape(int k, int size)
{
    const dReal a = size == 1 ? REAL(0.5) : 0, b = size == 0 ? 0 : REAL(0.8);
    switch (k) {
    case 0: return dCreateSphere(0, a);
    case 1: return dCreateBox(0, a, b, size == 2 ? 0 : b);
    case 2: return dCreateCapsule(0, a, b);
    case 3: return dCreateCylinder(0, b, a);
    case 4: return dCreatePlane(0, 0, 0, 1, 0);
    default: {
        dGeomID r = dCreateRay(0, a + b);
        dGeomRaySet(r, 0, 0, -0.3, 0, 0.6, 0.8);
        return r;
    }
    }
}

static int contacts_are_finite(const dContactGeom *c, int n)
{
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            if (!isfinite(c[i].pos[k]) || !isfinite(c[i].normal[k])) return 0;
        if (!isfinite(c[i].depth) || c[i].depth < 0) return 0;
        if (n && fabs(dCalcVectorLength3(c[i].normal) - 1) > 1e-3) return 0;
    }
    return 1;
}

// Every class against every class, one of them (or both) of size zero, in
// poses where they touch, overlap exactly, or are apart: no NaN, no crash;
// in every backend built.
static int test_zero_sized_shapes_collide_with_every_class_without_nan(void)
{
    static const dReal offsets[][3] = {
        { 0, 0, 0 }, { 0.1, 0.05, -0.2 }, { 0.3, 0, 0 }, { 0, 0, 0.4 }, { 3, 3, 3 }
    };
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 1, 0, 0.4);
    count_reports();
    int collisions = 0, touching = 0, backends = 0;

    for (const char *const *be = dCollisionListBackends(); *be; be++, backends++)
    for (int size = 0; size <= 2; size += 2)
        for (int i = 0; i < SHAPES; i++)
            for (int j = 0; j < SHAPES; j++)
                for (int other = 0; other <= 1; other++)
                    for (size_t o = 0; o < sizeof offsets / sizeof offsets[0]; o++) {
                        dGeomID g1 = make_shape(i, size), g2 = make_shape(j, other ? size : 1);
                        if (dGeomGetClass(g2) != dPlaneClass) {
                            dGeomSetPosition(g2, offsets[o][0], offsets[o][1], offsets[o][2]);
                            if (o & 1) dGeomSetRotation(g2, R);
                        }
                        CHECK(dCollisionSetBackend(*be));
                        dContactGeom c[16];
                        int n = dCollide(g1, g2, 16, c, sizeof c[0]);
                        collisions++;
                        touching += n > 0;
                        if (!(n >= 0 && n <= 16 && contacts_are_finite(c, n))) {
                            printf("# %s: classes %d and %d, size %d/%d, offset %zu: %d contacts\n",
                                   *be, i, j, size, other, o, n);
                            for (int k = 0; k < n; k++)
                                printf("#  pos %g %g %g normal %g %g %g depth %g\n",
                                       (double)c[k].pos[0], (double)c[k].pos[1],
                                       (double)c[k].pos[2], (double)c[k].normal[0],
                                       (double)c[k].normal[1], (double)c[k].normal[2],
                                       (double)c[k].depth);
                            CHECK(0);
                        }
                        dGeomDestroy(g1);
                        dGeomDestroy(g2);
                    }
    dCollisionSetBackend("native");
    printf("# %d backends, %d of %d collisions touching\n", backends, touching, collisions);
    CHECK(debug_count == 0);
    CHECK(collisions == backends * 2 * SHAPES * SHAPES * 2 * 5);
    CHECK(touching > 0);
    return 0;
}

// A point mass (radius 0): the mass is kept, the inertia is zero, and
// dMassCheck says through the message handler that it is not definite.
static int test_zero_sized_masses_are_kept_and_reported_as_messages(void)
{
    dMass m;
    count_reports();

    dMassSetSphereTotal(&m, 2, 0);

    CHECK(debug_count == 0 && message_count == 1);
    CHECK(strstr(last_message, "positive definite") != NULL);
    CHECK(m.mass == 2 && m.I[0] == 0 && m.I[5] == 0 && m.I[10] == 0);

    dMassSetBoxTotal(&m, 3, 0, 1, 2);   // a plate: still definite
    CHECK(debug_count == 0 && message_count == 1);
    CHECK_NEAR(m.I[0], 3 * (1 + 4) / 12.0, EPS);
    CHECK_NEAR(m.I[5], 3 * 4 / 12.0, EPS);
    CHECK(dMassCheck(&m));

    dMassSetCapsuleTotal(&m, 1, 3, 0, 0);   // a point: no division by zero
    dMassSetCylinder(&m, 1, 3, 0, 2);        // no volume: mass 0
    CHECK(debug_count == 0 && message_count == 3);
    CHECK(m.mass == 0 && !dIsNan(m.I[0]));
    return 0;
}

// ---- impossible masses --------------------------------------------------------

static int test_mass_set_parameters_reports_an_indefinite_inertia_as_a_message(void)
{
    dMass m;
    count_reports();

    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0);
    CHECK(message_count == 0 && dMassCheck(&m));
    dMassSetParameters(&m, 1, 0, 0, 0, 1, 1, 1, 2, 0, 0);   // I12 > sqrt(I11 I22)

    CHECK(debug_count == 0 && message_count == 1);
    CHECK(strstr(last_message, "dMassCheck") && strstr(last_message, "positive definite"));
    CHECK(m.mass == 1 && m.I[1] == 2 && m.I[4] == 2);   // kept as given, as in ODE
    CHECK(!dMassCheck(&m));
    CHECK(message_count == 2);
    return 0;
}

// ---- names --------------------------------------------------------------------

static int test_universal_rate_names_of_the_guide_index_are_the_same(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w);
    dBodySetPosition(b, 1, 0, 0);
    dJointID j = dJointCreateUniversal(w, 0);
    dJointAttach(j, a, b);
    dJointSetUniversalAxis1(j, 0, 0, 1);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    dBodySetAngularVel(a, 0.5, 0.25, 2);
    dBodySetAngularVel(b, -1, 3, 0.5);

    CHECK_NEAR(dJointGetUniversalAngleRate1(j), 2 - 0.5, EPS);
    CHECK_NEAR(dJointGetUniversalAngleRate2(j), 0.25 - 3, EPS);
    CHECK(dJointGetUniversalAngleRate1(j) == dJointGetUniversalAngle1Rate(j));
    CHECK(dJointGetUniversalAngleRate2(j) == dJointGetUniversalAngle2Rate(j));
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_body_set_rotation_ignores_the_padding),
    TEST_CASE(test_geom_set_rotation_ignores_the_padding),
    TEST_CASE(test_mass_rotate_and_products_ignore_the_padding),
    TEST_CASE(test_zero_sizes_are_valid_and_negative_ones_are_not),
    TEST_CASE(test_zero_sized_shapes_collide_with_every_class_without_nan),
    TEST_CASE(test_zero_sized_masses_are_kept_and_reported_as_messages),
    TEST_CASE(test_mass_set_parameters_reports_an_indefinite_inertia_as_a_message),
    TEST_CASE(test_universal_rate_names_of_the_guide_index_are_the_same),
    TEST_END
};
