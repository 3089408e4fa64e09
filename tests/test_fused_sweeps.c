// SPDX-License-Identifier: BSD-3-Clause
//
// test_fused_sweeps.c -- QuickStep's sweeps in their version with fused
// multiply-adds (quickstep.h: dxQuickFused, on where the processor has
// FMA) against the version without: the same solution up to rounding. The
// bench-like scenes of the replay test stepped once both ways: the states
// differ in their last bits (the fused version ran), and by no more than
// rounding explains, 1000 epsilons of dReal (2.2e-13 in double) in any
// position, quaternion or velocity number.
// (Stepped on, the runs part as any two roundings of a pile do.) Each
// version's paths giving the same bits is tested by block_batch,
// overlap_sweeps and island_groups, both versions.

#include "test.h"
#include "quickstep.h"
#include "replay_scenes.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#if defined(dSINGLE)
#define REAL_EPSILON FLT_EPSILON
#else
#define REAL_EPSILON DBL_EPSILON
#endif

#define STEPS 1
static dReal fused_states[STEPS * SCENE_STATE_SIZE], plain_states[STEPS * SCENE_STATE_SIZE];

// The largest difference between the two runs' states.
static double largest_difference(void)
{
    double most = 0;
    for (int i = 0; i < SCENE_STATE_SIZE; i++)
        most = fmax(most, fabs((double)fused_states[i] - (double)plain_states[i]));
    return most;
}

static int check_scene(int kind)
{
    if (!dxQuickFused) return test_skip("no fused version here (no FMA, or built without it)");
    scene_quick_states(kind, STEPS, fused_states);
    dxQuickFused = 0;
    scene_quick_states(kind, STEPS, plain_states);
    dxQuickFused = 1;
    const int k = first_state_difference(fused_states, plain_states, STEPS, SCENE_STATE_SIZE);
    const double most = largest_difference();
    printf("# %s: the versions differ by %.3g after one step\n", scene_names[kind], most);
    CHECK(k == 0);
    CHECK(most <= 1000 * REAL_EPSILON);
    return 0;
}

static int test_pyramid_the_same_up_to_rounding(void) { return check_scene(SCENE_PYRAMID); }
static int test_spheres_the_same_up_to_rounding(void) { return check_scene(SCENE_SPHERES); }
static int test_ragdolls_the_same_up_to_rounding(void) { return check_scene(SCENE_RAGDOLLS); }
static int test_chain_the_same_up_to_rounding(void) { return check_scene(SCENE_CHAIN); }

const test_case test_cases[] = {
    TEST_CASE(test_pyramid_the_same_up_to_rounding),
    TEST_CASE(test_spheres_the_same_up_to_rounding),
    TEST_CASE(test_ragdolls_the_same_up_to_rounding),
    TEST_CASE(test_chain_the_same_up_to_rounding),
    TEST_END,
};
