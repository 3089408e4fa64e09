// SPDX-License-Identifier: BSD-3-Clause
//
// test_replay.c -- same inputs, same bits: two runs of a scene are identical
// to the bit at every step, whatever the number of threads and whatever the
// order in which the scene's independent islands were created (which is the
// order of the world's body and joint lists, of the islands found in a step,
// of the geoms in the space, and of the addresses the handles get).
// Within an island, the order of creation is part of the input (it orders
// the island's rows) and is kept.

#include "test.h"
#include "replay_scenes.h"

#include <stdio.h>
#include <string.h>

// Under AddressSanitizer (the CI's sanitizer build runs this test about four
// times slower) half the steps: the other builds hold the bits over all 150.
#if defined(__SANITIZE_ADDRESS__)
#define STEPS 75
#else
#define STEPS 150
#endif

static dReal state_a[SCENE_STATE_SIZE], state_b[SCENE_STATE_SIZE];

// Step a and b together; returns the first step at which they differ, or -1.
static int first_difference(scene *a, scene *b, int steps)
{
    for (int i = 0; i < steps; i++) {
        scene_step(a);
        scene_step(b);
        scene_state(a, state_a);
        scene_state(b, state_b);
        if (memcmp(state_a, state_b, sizeof state_a) != 0) return i;
    }
    return -1;
}

// The scene moved: a replay test on a still scene would prove nothing.
static int scene_moved(const scene *s)
{
    dReal speed = 0;
    for (int i = 0; i < s->nbody; i++) {
        const dReal *v = dBodyGetLinearVel(s->body[i]);
        speed += dFabs(v[0]) + dFabs(v[1]) + dFabs(v[2]);
    }
    return speed > 0 && s->nbody > 20;
}

static int test_two_runs_are_bit_identical(void)
{
    for (int kind = 0; kind < SCENE_KINDS; kind++)
        for (int stepper = 0; stepper < STEPPERS; stepper++) {
            scene a, b;
            scene_build(&a, kind, stepper, NULL, 0);
            scene_build(&b, kind, stepper, NULL, 0);

            const int diff = first_difference(&a, &b, STEPS);

            if (diff >= 0)
                printf("# %s, %s: runs differ at step %d\n", scene_names[kind],
                       stepper_names[stepper], diff);
            CHECK(diff < 0);
            CHECK(scene_moved(&a));
            scene_destroy(&a);
            scene_destroy(&b);
        }
    return 0;
}

static int test_any_thread_count_gives_the_same_bits(void)
{
    const int steppers[2] = { STEP_WORLD, STEP_QUICK };   // (StepFast1 has no threads)
    for (int kind = 0; kind < SCENE_KINDS; kind++)
        for (int k = 0; k < 2; k++)
            for (int threads = 1; threads <= 4; threads++) {
                scene a, b;
                scene_build(&a, kind, steppers[k], NULL, 0);
                scene_build(&b, kind, steppers[k], NULL, threads);

                const int diff = first_difference(&a, &b, STEPS);

                if (diff >= 0)
                    printf("# %s, %s, %d threads: differs at step %d\n", scene_names[kind],
                           stepper_names[steppers[k]], threads, diff);
                CHECK(diff < 0);
                scene_destroy(&a);
                scene_destroy(&b);
            }
    return 0;
}

static int test_island_creation_order_does_not_matter(void)
{
    static const int orders[3][SCENE_GROUPS] = { { 3, 1, 0, 2 }, { 2, 3, 1, 0 },
                                                 { 1, 0, 3, 2 } };
    for (int kind = 0; kind < SCENE_KINDS; kind++)
        for (int stepper = 0; stepper < STEPPERS; stepper++)
            for (int o = 0; o < 3; o++) {
                scene a, b;
                scene_build(&a, kind, stepper, NULL, 0);
                scene_build(&b, kind, stepper, orders[o], o == 2 ? 3 : 0);

                const int diff = first_difference(&a, &b, STEPS);

                if (diff >= 0)
                    printf("# %s, %s, order %d: differs at step %d\n", scene_names[kind],
                           stepper_names[stepper], o, diff);
                CHECK(diff < 0);
                scene_destroy(&a);
                scene_destroy(&b);
            }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_two_runs_are_bit_identical),
    TEST_CASE(test_any_thread_count_gives_the_same_bits),
    TEST_CASE(test_island_creation_order_does_not_matter),
    TEST_END
};
