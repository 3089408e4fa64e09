// SPDX-License-Identifier: BSD-3-Clause
//
// test_nonfinite_rows.c -- a joint whose rows come out not finite (a pose or
// parameters with no answer) acts with no force for the step, and every
// stepper says so, instead of spreading NaN to its bodies (nor do the
// position sweeps move them). A ball joint is given a class whose rows carry
// a NaN or an infinity. Rows of huge finite numbers are kept.

#include "test.h"
#include "objects_internal.h"
#include "step_internal.h"

#include <math.h>

static const dxJointClass *ball_class;
static dxJointClass broken_class;
static int broken_entry;   // which entry of row 0 the broken joint spoils

static void broken_fill_rows(dxJoint *j, dxJointRows *rows)
{
    ball_class->fill_rows(j, rows);
    switch (broken_entry) {
    case 0: rows->c[0] = NAN; break;
    case 1: rows->J1a[1] = NAN; break;
    case 2: rows->J2l[2] = INFINITY; break;
    default: rows->lo[0] = NAN; break;
    }
}

static int step_with_a_broken_joint(int stepper, int entry, int position_iterations)
{
    const dReal h = REAL(0.01);
    test_capture_reports();
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, REAL(-9.81));
    dWorldSetPositionIterations(w, position_iterations);
    dBodyID a = dBodyCreate(w), b = dBodyCreate(w);
    dBodySetPosition(b, 0, 0, 1);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, a, b);
    dJointSetBallAnchor(j, 0, 0, REAL(0.5));
    ball_class = ((dxJoint *)j)->cls;
    broken_class = *ball_class;
    broken_class.name = "broken";
    broken_class.fill_rows = broken_fill_rows;
    ((dxJoint *)j)->cls = &broken_class;
    broken_entry = entry;

    const int steps = 5;
    for (int i = 0; i < steps; i++) {
        if (stepper == 0) dWorldStep(w, h);
        else if (stepper == 1) dWorldQuickStep(w, h);
        else dWorldStepFast1(w, h, 4);
    }

    // Both bodies fell freely: the joint gave no force (nor correction).
    for (int k = 0; k < 2; k++) {
        const dReal *v = dBodyGetLinearVel(k ? b : a), *w_ = dBodyGetAngularVel(k ? b : a);
        const dReal *p = dBodyGetPosition(k ? b : a);
        CHECK_VEC(v, 0, 0, -9.81 * h * steps, TOL(1e-12, 1e-5));
        CHECK_VEC(w_, 0, 0, 0, 1e-12);
        CHECK_NEAR(p[0], 0, 1e-12);
        CHECK_NEAR(p[1], 0, 1e-12);
        CHECK(isfinite(p[2]) && p[2] < k);
    }
    CHECK(test_captured_count() == steps);   // once per step
    CHECK(test_captured_contains(stepper == 2 ? "dWorldStepFast1: a broken joint's rows were "
                                                "not finite"
                                              : "step: a broken joint's rows are not finite"));
    test_release_reports();
    ((dxJoint *)j)->cls = ball_class;
    dWorldDestroy(w);
    return 0;
}

static int test_dWorldStep_leaves_out_a_joint_whose_rows_are_not_finite(void)
{
    for (int entry = 0; entry < 4; entry++)
        if (step_with_a_broken_joint(0, entry, 0) || step_with_a_broken_joint(0, entry, 3))
            return 1;
    return 0;
}

static int test_dWorldQuickStep_leaves_out_a_joint_whose_rows_are_not_finite(void)
{
    for (int entry = 0; entry < 4; entry++)
        if (step_with_a_broken_joint(1, entry, 0)) return 1;
    return 0;
}

static int test_dWorldStepFast1_leaves_out_a_joint_whose_rows_are_not_finite(void)
{
    for (int entry = 0; entry < 4; entry++)
        if (step_with_a_broken_joint(2, entry, 0)) return 1;
    return 0;
}

// Rows of huge but finite numbers, whose plain sum overflows, are kept as
// they are (the check's first, cheap pass only settles finite sums); one
// infinity among them still clears them.
static int test_huge_finite_rows_are_kept(void)
{
    dWorldID w = dWorldCreate();
    dBodyID a = dBodyCreate(w);
    dJointID jid = dJointCreateBall(w, 0);
    dJointAttach(jid, a, 0);
    const dxJoint *j = (const dxJoint *)jid;
    enum { M = 3, SKIP = 12 };
#ifdef dSINGLE
    const dReal big = REAL(3e38);
#else
    const dReal big = REAL(1.5e308);
#endif
    for (int spoil = 0; spoil < 2; spoil++) {
        dReal J[M * SKIP], c[M], cfm[M], lo[M], hi[M];
        int findex[M];
        for (int i = 0; i < M; i++) {
            for (int e = 0; e < SKIP; e++) J[i * SKIP + e] = big;
            c[i] = cfm[i] = big;
            lo[i] = -dInfinity;
            hi[i] = dInfinity;
            findex[i] = -1;
        }
        if (spoil) J[SKIP + 5] = dInfinity;
        const int kept = dxJointRowsKeepFinite(j, M, J, SKIP, c, cfm, lo, hi, findex);
        CHECK(kept == !spoil);
        CHECK(J[0] == (spoil ? 0 : big) && c[M - 1] == (spoil ? 0 : big));
        CHECK(hi[0] == (spoil ? 0 : dInfinity));
    }
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_dWorldStep_leaves_out_a_joint_whose_rows_are_not_finite),
    TEST_CASE(test_dWorldQuickStep_leaves_out_a_joint_whose_rows_are_not_finite),
    TEST_CASE(test_dWorldStepFast1_leaves_out_a_joint_whose_rows_are_not_finite),
    TEST_CASE(test_huge_finite_rows_are_kept),
    TEST_END,
};
