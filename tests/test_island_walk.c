// SPDX-License-Identifier: BSD-3-Clause
//
// test_island_walk.c -- the island walk (solvers/island.c) marks the joints
// it meets with the world's walk number instead of clearing a mark on every
// joint first. When the number wraps past 2^32 - 1, every joint's mark is
// cleared, so that a joint last met at walk 1 (disabled since, say) is not
// taken as met by the new walk 1. Scenes stepped across the wrap must give
// the same bits as scenes stepped without it.

#include "test.h"
#include "objects_internal.h"
#include "replay_scenes.h"

#include <limits.h>
#include <string.h>

#define STEPS 40
static dReal plain[STEPS * SCENE_STATE_SIZE], wrapped[STEPS * SCENE_STATE_SIZE];

// Scene `kind` stepped STEPS times with the quick stepper, its states after
// each step into states; with `wrap`, the walk number is the last before
// the wrap and every joint marked as met by walk 1 before the first step.
static unsigned run_scene(int kind, int wrap, dReal *states)
{
    scene s;
    scene_build(&s, kind, STEP_QUICK, NULL, 0);
    if (wrap) {
        s.w->island_walk = UINT_MAX;
        for (dxJoint *j = s.w->joints; j; j = j->next) j->walk = 1;
    }
    for (int k = 0; k < STEPS; k++) {
        scene_step(&s);
        scene_state(&s, states + (size_t)k * SCENE_STATE_SIZE);
    }
    const unsigned walk = s.w->island_walk;
    scene_destroy(&s);
    return walk;
}

static int check_scene(int kind)
{
    run_scene(kind, 0, plain);
    CHECK(run_scene(kind, 1, wrapped) == STEPS);
    const int k = first_state_difference(plain, wrapped, STEPS, SCENE_STATE_SIZE);
    if (k >= 0) {
        test_fail(__FILE__, __LINE__, "%s across the walk number's wrap: states differ from "
                  "step %d", scene_names[kind], k);
        return 1;
    }
    return 0;
}

static int test_ragdolls_step_the_same_across_the_wrap(void) { return check_scene(SCENE_RAGDOLLS); }
static int test_chains_step_the_same_across_the_wrap(void) { return check_scene(SCENE_CHAIN); }

const test_case test_cases[] = {
    TEST_CASE(test_ragdolls_step_the_same_across_the_wrap),
    TEST_CASE(test_chains_step_the_same_across_the_wrap),
    TEST_END,
};
