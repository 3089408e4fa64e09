// SPDX-License-Identifier: BSD-3-Clause
//
// test_contact_rows.c -- the contact joint writes every entry of its rows
// (dxJointRowsFill relies on it and sets no defaults for contacts): rows
// filled into arrays of garbage must equal, bit for bit, the rows the joint
// writes over the generic defaults (J 0, c 0, cfm the world's, lo -inf,
// hi inf, findex -1), for every surface mode and with one or two bodies.

#include "test.h"
#include "objects_internal.h"
#include "step_internal.h"

#include <math.h>
#include <string.h>

#define MAX_M 6

// The rows of joint j over the generic defaults, as the solvers set them.
static void rows_over_defaults(dWorldID w, dxJoint *j, dReal h, dReal *J, dReal *c, dReal *cfm,
                               dReal *lo, dReal *hi, int *findex)
{
    const int m = j->rows.m;
    for (int i = 0; i < m * DX_ROW_SKIP; i++) J[i] = 0;
    dxJointRowsDefaults(w, m, c, cfm, lo, hi, findex);
    dxJointRows info = { .fps = 1 / h, .erp = w->erp, .rowskip = DX_ROW_SKIP, .J1l = J,
                         .J1a = J + 3, .J2l = J + 6, .J2a = J + 9, .c = c, .cfm = cfm,
                         .lo = lo, .hi = hi, .findex = findex };
    j->cls->fill_rows(j, &info);
}

// A contact between b1 and b2 (b2 may be 0) with the given surface mode.
static dxJoint *make_contact(dWorldID w, dBodyID b1, dBodyID b2, int mode)
{
    dContact ct;
    memset(&ct, 0, sizeof ct);
    ct.geom.pos[0] = 0.1;
    ct.geom.pos[1] = -0.2;
    ct.geom.pos[2] = 0.05;
    ct.geom.normal[0] = 0.3;
    ct.geom.normal[2] = 1;
    ct.geom.depth = 0.02;
    ct.surface.mode = mode;
    ct.surface.mu = (mode & dContactApprox1_N) ? dInfinity : 0.7;
    ct.surface.mu2 = 0.4;
    ct.surface.rho = 0.01;
    ct.surface.rho2 = 0.02;
    ct.surface.rhoN = 0.03;
    ct.surface.bounce = 0.5;
    ct.surface.bounce_vel = 0.01;
    ct.surface.soft_erp = 0.4;
    ct.surface.soft_cfm = 1e-3;
    ct.surface.motion1 = 0.2;
    ct.surface.motion2 = -0.1;
    ct.surface.motionN = 0.05;
    ct.surface.slip1 = 1e-3;
    ct.surface.slip2 = 2e-3;
    dJointID j = dJointCreateContact(w, 0, &ct);
    dJointAttach(j, b1, b2);
    return (dxJoint *)j;
}

static int test_contact_rows_need_no_defaults(void)
{
    static const int modes[] = {
        0,
        dContactBounce | dContactSoftCFM | dContactSoftERP,
        dContactMu2 | dContactSlip1 | dContactSlip2 | dContactMotion1 | dContactMotion2,
        dContactRolling | dContactApprox1,
        dContactRolling | dContactAxisDep | dContactApprox1_1 | dContactMotionN,
        dContactApprox1_N | dContactRolling,   // infinite mu: unbounded friction rows
    };
    dWorldID w = dWorldCreate();
    dWorldSetCFM(w, 1e-6);
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w);
    dBodySetPosition(b, 0.3, 0, -0.5);
    dBodySetLinearVel(a, 0.1, 0.2, -0.4);
    dBodySetAngularVel(b, 0.5, -0.3, 0.2);
    const dReal h = 0.01;
    int checked = 0;
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++) {
        for (int two = 0; two < 2; two++) {
            for (int reversed = 0; reversed < 2; reversed++) {
                dxJoint *j = reversed ? make_contact(w, two ? b : 0, a, modes[k])
                                      : make_contact(w, a, two ? b : 0, modes[k]);
                j->cls->count_rows(j, &j->rows);
                const int m = j->rows.m;
                CHECK(m >= 1 && m <= MAX_M);
                dReal J[MAX_M * DX_ROW_SKIP], c[MAX_M], cfm[MAX_M], lo[MAX_M], hi[MAX_M];
                dReal J0[MAX_M * DX_ROW_SKIP], c0[MAX_M], cfm0[MAX_M], lo0[MAX_M], hi0[MAX_M];
                int f[MAX_M], f0[MAX_M], bi[2];
                // The first fill records the contact's anchor; both compared fills follow it.
                dxJointRowsFill(w, j, h, J, c, cfm, lo, hi, f, bi);
                rows_over_defaults(w, j, h, J0, c0, cfm0, lo0, hi0, f0);
                for (int i = 0; i < MAX_M * DX_ROW_SKIP; i++) J[i] = NAN;
                for (int i = 0; i < MAX_M; i++) {
                    c[i] = cfm[i] = lo[i] = hi[i] = NAN;
                    f[i] = 12345;
                }
                dxJointRowsFill(w, j, h, J, c, cfm, lo, hi, f, bi);
                CHECK(memcmp(J, J0, sizeof J[0] * DX_ROW_SKIP * (size_t)m) == 0);
                CHECK(memcmp(c, c0, sizeof c[0] * (size_t)m) == 0);
                CHECK(memcmp(cfm, cfm0, sizeof cfm[0] * (size_t)m) == 0);
                CHECK(memcmp(lo, lo0, sizeof lo[0] * (size_t)m) == 0);
                CHECK(memcmp(hi, hi0, sizeof hi[0] * (size_t)m) == 0);
                CHECK(memcmp(f, f0, sizeof f[0] * (size_t)m) == 0);
                checked += m;
                dJointDestroy((dJointID)j);
            }
        }
    }
    CHECK(checked > 4 * 6 * 2);   // the modes give more than two rows on average
    dWorldDestroy(w);
    return 0;
}

// The numbers of a plain contact's rows (dxJointContactRows) from the rule
// alone: the unit normal and dPlaneSpace's directions in the stored sense
// (negated when the joint is stored reversed, also after it is attached the
// other way round between two steps), the friction rows present in order t1,
// t2 with bounds -k..k, the pyramid mask (all bits) for a finite k under
// Approx1_1/_2 (else 0, as for the normal row and the fourth),
// Motion1/2's targets, Slip1/2's and SoftCFM's cfm or else the world's, and
// zeros after the last row. The usual surface (no mode but the pyramid's) is
// made on a path of its own at creation: both paths are covered.
static int test_contact_numbers_follow_the_rule(void)
{
    static const int modes[] = {
        0,
        dContactApprox1_1,
        dContactApprox1_2,
        dContactApprox1,
        dContactApprox1 | dContactSoftCFM,
        dContactApprox1_1 | dContactMu2 | dContactMotion1 | dContactSlip2,
        dContactMu2 | dContactApprox1_2 | dContactSlip1 | dContactMotion2,
    };
    static const dReal mus[] = { 0, 0.7, dInfinity };
    static const dReal normals[][3] = { { 0.3, 0, 1 }, { 0, 0, -2 }, { 1, -0.5, 0.2 } };
    dWorldID w = dWorldCreate();
    dWorldSetCFM(w, 3e-6);
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w);
    dBodySetPosition(b, 0.3, 0, -0.5);
    const dVector3 zero = { 0, 0, 0, 0 };
    int checked = 0;
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++)
    for (size_t u = 0; u < sizeof mus / sizeof mus[0]; u++)
    for (size_t q = 0; q < sizeof normals / sizeof normals[0]; q++)
    for (int two = 0; two < 2; two++)
    for (int reversed = 0; reversed < 2; reversed++) {
        const int mode = modes[k];
        dContact ct;
        memset(&ct, 0, sizeof ct);
        ct.geom.pos[0] = 0.1;
        ct.geom.pos[1] = -0.2;
        ct.geom.pos[2] = 0.05;
        for (int i = 0; i < 3; i++) ct.geom.normal[i] = normals[q][i];
        ct.geom.depth = 0.02;
        ct.surface.mode = mode;
        ct.surface.mu = mus[u];
        ct.surface.mu2 = 0.4;
        ct.surface.soft_cfm = 1e-3;
        ct.surface.motion1 = 0.2;
        ct.surface.motion2 = -0.1;
        ct.surface.slip1 = 1e-4;
        ct.surface.slip2 = 2e-4;
        dxJoint *j = (dxJoint *)dJointCreateContact(w, 0, &ct);
        dBodyID other = two ? b : 0;
        if (reversed) dJointAttach((dJointID)j, other, a);
        else dJointAttach((dJointID)j, a, other);

        const dReal mu = mus[u], mu2 = (mode & dContactMu2) ? ct.surface.mu2 : mu;
        const int plain = !(mu == dInfinity && mu2 == dInfinity);
        CHECK(((j->flags & DX_JOINT_PLAIN_CONTACT) != 0) == plain);
        if (!plain) {
            dJointDestroy((dJointID)j);
            continue;
        }
        dVector3 n = { normals[q][0], normals[q][1], normals[q][2], 0 }, t1, t2;
        dSafeNormalize3(n);
        dPlaneSpace(n, t1, t2);
        for (int flip = 0; flip < 2; flip++) {
            // The second time attached the other way round; stored reversed
            // (negated directions) is (0, a) alone.
            const int swapped = reversed ^ flip, rev = !two && swapped;
            if (flip) {
                if (swapped) dJointAttach((dJointID)j, other, a);
                else dJointAttach((dJointID)j, a, other);
            }
            const dxContactRows r = *dxJointContactRows(j, 100, 0.2);
            const dReal sign = rev ? -1 : 1;
            const dReal *dir[3] = { n, t1, t2 };
            for (int d = 0; d < 3; d++) {
                dVector3 e;
                for (int i = 0; i < 3; i++) e[i] = sign * dir[d][i];
                const dReal *got = d == 0 ? r.n : d == 1 ? r.t1 : r.t2;
                CHECK(memcmp(got, e, 3 * sizeof(dReal)) == 0);
            }
            const dReal ks[2] = { mu, mu2 };
            const int present[2] = { mu > 0, mu2 > 0 };
            const int motion[2] = { dContactMotion1, dContactMotion2 };
            const int slip[2] = { dContactSlip1, dContactSlip2 };
            const int approx[2] = { dContactApprox1_1, dContactApprox1_2 };
            const dReal motions[2] = { ct.surface.motion1, ct.surface.motion2 };
            const dReal slips[2] = { ct.surface.slip1, ct.surface.slip2 };
            const dReal *dirs[2] = { r.t1, r.t2 };
            dReal c[4] = { r.c[0], 0, 0, 0 }, cfm[4] = { 0, 0, 0, 0 };
            dReal lo[4] = { 0, 0, 0, 0 }, hi[4] = { dInfinity, 0, 0, 0 };
            int pyramid[4] = { 0, 0, 0, 0 };
            const dReal *d[3] = { r.n, zero, zero };
            cfm[0] = (mode & dContactSoftCFM) ? ct.surface.soft_cfm : dWorldGetCFM(w);
            int m = 1;
            for (int f = 0; f < 2; f++) {
                if (!present[f]) continue;
                c[m] = (mode & motion[f]) ? motions[f] : 0;
                cfm[m] = (mode & slip[f]) ? slips[f] : dWorldGetCFM(w);
                lo[m] = -ks[f];
                hi[m] = ks[f];
                pyramid[m] = (mode & approx[f]) && ks[f] < dInfinity;
                d[m] = dirs[f];
                m++;
            }
            CHECK(r.m == m);
            CHECK(r.friction == (present[0] | present[1] << 1));
            CHECK(memcmp(r.c, c, sizeof c) == 0);
            CHECK(memcmp(r.cfm, cfm, sizeof cfm) == 0);
            CHECK(memcmp(r.lo, lo, sizeof lo) == 0);
            CHECK(memcmp(r.hi, hi, sizeof hi) == 0);
            for (int i = 0; i < 4; i++) CHECK(r.pyramid[i] == -(dxRealMask)pyramid[i]);
            for (int i = 0; i < 3; i++) CHECK(memcmp(r.d[i], d[i], 3 * sizeof(dReal)) == 0);
            CHECK(memcmp(r.point, ct.geom.pos, 3 * sizeof(dReal)) == 0);
            CHECK((r.arm[1] != NULL) == two);
            checked++;
        }
        dJointDestroy((dJointID)j);
    }
    CHECK(checked > 100);
    dWorldDestroy(w);
    return 0;
}

// A usual contact's unit normal and friction directions are made from its
// own normal as given, whatever contacts came before it in the world
// (dJointCreateContact copies them from the world's last usual contact whose
// normal has the same bits): normals equal as numbers but not as bits (-0
// against 0, which gives t1 a zero of the other sign), the same direction
// scaled, the same numbers after an unusable normal and after another
// world's contacts, all equal bit for bit to dSafeNormalize3 and dPlaneSpace
// of the contact's normal; an unusable normal after a usable one with the
// same bits in its other numbers makes no directions.
static int test_contact_directions_are_their_normals(void)
{
    test_capture_reports();
    static const dReal normals[][3] = {
        { 0, 0, 1 }, { 0, 0, 1 }, { 0, -0.0, 1 }, { 0, -0.0, 1 }, { 0, 0, 1 }, { 0, 0, 2 },
        { 0, 0, 0 }, { 0, 0, 2 }, { -0.0, 1, 0 }, { 0, 1, 0 }, { 0.3, 0, 1 }, { 0.3, 0, 1 },
        { NAN, 0, 1 }, { 0.3, 0, 1 }, { 1, -0.5, 0.2 }, { 1, -0.5, 0.2 },
    };
    dWorldID w[2] = { dWorldCreate(), dWorldCreate() };
    dBodyID a[2] = { dBodyCreate(w[0]), dBodyCreate(w[1]) };
    const int count = (int)(sizeof normals / sizeof normals[0]);
    int checked = 0;
    for (int k = 0; k < 2 * count; k++) {
        const int q = k % count, in = k < count ? 0 : (k & 1);   // then the worlds by turns
        dContact ct;
        memset(&ct, 0, sizeof ct);
        ct.geom.pos[0] = 0.1;
        ct.geom.depth = 0.02;
        ct.surface.mode = (k & 2) ? dContactApprox1 : 0;
        ct.surface.mu = 0.7;
        for (int i = 0; i < 3; i++) ct.geom.normal[i] = normals[q][i];
        dxJoint *j = (dxJoint *)dJointCreateContact(w[in], 0, &ct);
        dJointAttach((dJointID)j, a[in], 0);
        const int usable = !isnan(normals[q][0]) && normals[q][2] + normals[q][1] != 0;
        CHECK(j->rows.m == (usable ? 3 : 0));
        if (usable) {
            dVector3 n = { normals[q][0], normals[q][1], normals[q][2], 0 }, t1, t2;
            dSafeNormalize3(n);
            dPlaneSpace(n, t1, t2);
            const dxContactRows r = *dxJointContactRows(j, 100, 0.2);
            CHECK(memcmp(r.n, n, 3 * sizeof(dReal)) == 0);
            CHECK(memcmp(r.t1, t1, 3 * sizeof(dReal)) == 0);
            CHECK(memcmp(r.t2, t2, 3 * sizeof(dReal)) == 0);
            CHECK(r.n[3] == 0 && r.t1[3] == 0 && r.t2[3] == 0);
            checked++;
        }
        dJointDestroy((dJointID)j);
    }
    CHECK(checked == 2 * (count - 2));
    CHECK(test_captured_count() == 4);   // the zero and the NaN normal, each twice
    // The zeros' signs do reach t1: the case above is not vacuous.
    dVector3 p = { 0, 0, 1, 0 }, m = { 0, -0.0, 1, 0 }, t1p, t2p, t1m, t2m;
    dPlaneSpace(p, t1p, t2p);
    dPlaneSpace(m, t1m, t2m);
    CHECK(memcmp(t1p, t1m, 3 * sizeof(dReal)) != 0);
    dWorldDestroy(w[0]);
    dWorldDestroy(w[1]);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_contact_rows_need_no_defaults),
    TEST_CASE(test_contact_numbers_follow_the_rule),
    TEST_CASE(test_contact_directions_are_their_normals),
    TEST_END
};
