// SPDX-License-Identifier: BSD-3-Clause
//
// test_limot_angle.c -- dxLimotAngleClear (joint_limot.c), the hinge's and
// the universal joint's limit test without atan2 (and dxLimotAtan2Clear,
// hinge-2's, for the angle atan2(y, x) itself): whenever it says an angle
// is clear of the stops, dxLimotTestLimit on the angle measured exactly
// (wrap(2 atan2(y, x)), as the joints measure it) finds no limit; and it
// says so for every angle farther from both stops and from +-pi than its
// margin plus twice the error of its arctangent estimate. Angles on a fine
// grid around the circle, the pair (y, x) scaled and of either sign, stops
// made up (finite, one infinite, crossed).

#include "test.h"
#include "joint_limot.h"

#include <math.h>
#include <stdint.h>

// The margin and the estimate's error bound of joint_limot.c.
#define MARGIN 0.01
#define ESTIMATE_ERROR 0.0015

static dReal exact_angle(dReal y, dReal x)
{
    dReal a = 2 * dAtan2(y, x);
    if (a > M_PI) a -= 2 * M_PI;
    if (a <= -M_PI) a += 2 * M_PI;
    return a;
}

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s;
}

static double uniform(uint32_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(lcg(s) >> 8) / (double)(1u << 24);
}

// Stops for round `stops`: lo in [-2 reach, reach), hi in [-reach, 2 reach)
// (crossed now and then), one of them infinite in two rounds of ten.
static void random_stops(dxLimot *lm, uint32_t *s, int stops, double reach)
{
    lm->lostop = (dReal)uniform(s, -2 * reach, reach);
    lm->histop = (dReal)uniform(s, -reach, 2 * reach);
    if (stops % 10 == 1) lm->lostop = -dInfinity;
    if (stops % 10 == 2) lm->histop = dInfinity;
}

// dxLimotTestLimit's verdict on the exact angle (-1, 0 or 1).
static int limit_at(const dxLimot *lm, dReal angle)
{
    dxLimot t = *lm;
    t.limit = -1;
    dxLimotTestLimit(&t, angle);
    return t.limit;
}

static int angle_clear_agrees(void)
{
    dxLimot lm = { 0 };
    uint32_t s = 12345;
    long cleared = 0, far = 0;
    for (int stops = 0; stops < 200; stops++) {
        random_stops(&lm, &s, stops, 2);
        for (int k = 0; k < 4000; k++) {
            const double half = -M_PI / 2 + M_PI * (k + 0.5) / 4000;   // the half angle
            const double r = uniform(&s, 0.05, 2) * (k % 2 ? -1 : 1);
            const dReal y = (dReal)(r * sin(half)), x = (dReal)(r * cos(half));
            const dReal angle = exact_angle(y, x);
            const int clear = dxLimotAngleClear(&lm, y, x);
            if (clear) CHECK(limit_at(&lm, angle) == 0);
            cleared += clear;
            const double need = MARGIN + 2 * ESTIMATE_ERROR + 1e-5;
            if (fabs(angle) < M_PI - need && angle > lm.lostop + need &&
                angle < lm.histop - need) {
                far++;
                CHECK(clear);
            }
        }
    }
    CHECK(far > 100000);   // the grid reaches the cases that matter
    CHECK(cleared >= far);
    return 0;
}

// Crossed stops act as none (limit 0) and no pair of zeros is clear.
static int angle_clear_edges(void)
{
    dxLimot lm = { 0 };
    lm.lostop = 1;
    lm.histop = -1;
    CHECK(!dxLimotAngleClear(&lm, 0, 1));
    lm.lostop = -1;
    lm.histop = 1;
    CHECK(dxLimotAngleClear(&lm, 0, 1));
    CHECK(!dxLimotAngleClear(&lm, 0, 0));
    CHECK(!dxLimotAngleClear(&lm, 1, 0));   // the angle is pi: past both stops
    return 0;
}

// dxLimotAtan2Clear against dxLimotTestLimit on atan2(y, x): never clear
// where the exact angle is at a stop; clear wherever the angle is in the
// right half plane and farther than the margin and the estimate's error from
// both stops (crossed and infinite stops among them); never in the left
// half plane.
static int atan2_clear_agrees(void)
{
    dxLimot lm = { 0 };
    uint32_t s = 54321;
    long cleared = 0, far = 0;
    for (int stops = 0; stops < 200; stops++) {
        random_stops(&lm, &s, stops, 1);
        for (int k = 0; k < 4000; k++) {
            const double a = -M_PI + 2 * M_PI * (k + 0.5) / 4000;
            const double r = uniform(&s, 0.05, 2);
            const dReal y = (dReal)(r * sin(a)), x = (dReal)(r * cos(a));
            const dReal angle = dAtan2(y, x);
            const int clear = dxLimotAtan2Clear(&lm, y, x);
            if (clear) CHECK(limit_at(&lm, angle) == 0);
            if (x < 0) CHECK(!clear);
            cleared += clear;
            const double need = MARGIN + ESTIMATE_ERROR + 1e-5;
            if (x >= 0 && angle > lm.lostop + need && angle < lm.histop - need) {
                far++;
                CHECK(clear);
            }
        }
    }
    CHECK(far > 100000);
    CHECK(cleared >= far);
    lm.lostop = -1;
    lm.histop = 1;
    CHECK(!dxLimotAtan2Clear(&lm, 0, 0));
    CHECK(dxLimotAtan2Clear(&lm, 0, 1));
    lm.lostop = 1;
    lm.histop = -1;   // crossed: none acts, but never clear
    CHECK(!dxLimotAtan2Clear(&lm, 0, 1));
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(angle_clear_agrees),
    TEST_CASE(angle_clear_edges),
    TEST_CASE(atan2_clear_agrees),
    TEST_END,
};
