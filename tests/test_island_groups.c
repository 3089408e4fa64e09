// SPDX-License-Identifier: BSD-3-Clause
//
// test_island_groups.c -- dWorldQuickStep sweeps its islands in groups that
// fit the first-level cache (quickstep.c: make_groups), all iterations of
// one group before the next. Each island still gets exactly its own updates
// in its own order, so the result must be the same bits however the
// islands are grouped: the bench-like scenes (pyramids, spheres, ragdolls
// and chains; islands of different sizes and kinds) are stepped with every
// island in one group, with groups forced small (so that a scene spans many
// groups) and with the default budget, and on threads (each island solved
// alone), and their states compared after every step.

#include "test.h"
#include "quickstep.h"
#include "replay_scenes.h"

#include <limits.h>
#include <string.h>

#define STEPS 120
static dReal one_group[STEPS * SCENE_STATE_SIZE], other[STEPS * SCENE_STATE_SIZE];

// Scene `kind` stepped STEPS times with group budget `bytes`, islands with
// blocks joining a group `islands` at a time, on `threads` threads (0:
// none), its states after each step into states.
static void run_scene(int kind, int bytes, int islands, int threads, dReal *states)
{
    const int saved = dxQuickGroupBytes, saved_islands = dxQuickGroupIslands;
    dxQuickGroupBytes = bytes;
    dxQuickGroupIslands = islands;
    scene s;
    scene_build(&s, kind, STEP_QUICK, NULL, threads);
    for (int k = 0; k < STEPS; k++) {
        scene_step(&s);
        scene_state(&s, states + (size_t)k * SCENE_STATE_SIZE);
    }
    scene_destroy(&s);
    dxQuickGroupBytes = saved;
    dxQuickGroupIslands = saved_islands;
}

static int check_scene(int kind)
{
    run_scene(kind, INT_MAX, dxQuickGroupIslands, 0, one_group);
    const int budgets[] = { 1, 3000, dxQuickGroupBytes };
    const int islands[] = { 1, 4, dxQuickGroupIslands };
    for (size_t b = 0; b < sizeof budgets / sizeof budgets[0]; b++)
        for (size_t i = 0; i < sizeof islands / sizeof islands[0]; i++) {
            run_scene(kind, budgets[b], islands[i], 0, other);
            const int k = first_state_difference(one_group, other, STEPS, SCENE_STATE_SIZE);
            if (k >= 0) {
                test_fail(__FILE__, __LINE__,
                          "%s in groups of %d bytes, %d islands with blocks at a time: states "
                          "differ from step %d",
                          scene_names[kind], budgets[b], islands[i], k);
                return 1;
            }
        }
    run_scene(kind, 1, 1, 2, other);
    const int k = first_state_difference(one_group, other, STEPS, SCENE_STATE_SIZE);
    if (k >= 0) {
        test_fail(__FILE__, __LINE__, "%s on threads: states differ from step %d",
                  scene_names[kind], k);
        return 1;
    }
    // The scene moved: the last state is not the first.
    CHECK(memcmp(one_group, one_group + (size_t)(STEPS - 1) * SCENE_STATE_SIZE,
                 SCENE_STATE_SIZE * sizeof(dReal)) != 0);
    return 0;
}

static int test_pyramids_step_the_same_in_any_groups(void) { return check_scene(SCENE_PYRAMID); }
static int test_spheres_step_the_same_in_any_groups(void) { return check_scene(SCENE_SPHERES); }
static int test_ragdolls_step_the_same_in_any_groups(void) { return check_scene(SCENE_RAGDOLLS); }
static int test_chains_step_the_same_in_any_groups(void) { return check_scene(SCENE_CHAIN); }

// Ragdolls (blocks in batches) again with the sweeps' version without
// fused multiply-adds (quickstep.h: dxQuickFused), the one processors
// without FMA run.
static int test_unfused_ragdolls_step_the_same_in_any_groups(void)
{
    const int fused = dxQuickFused;
    dxQuickFused = 0;
    const int failed = check_scene(SCENE_RAGDOLLS);
    dxQuickFused = fused;
    CHECK(!failed);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_pyramids_step_the_same_in_any_groups),
    TEST_CASE(test_spheres_step_the_same_in_any_groups),
    TEST_CASE(test_ragdolls_step_the_same_in_any_groups),
    TEST_CASE(test_chains_step_the_same_in_any_groups),
    TEST_CASE(test_unfused_ragdolls_step_the_same_in_any_groups),
    TEST_END,
};
