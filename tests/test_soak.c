// SPDX-License-Identifier: BSD-3-Clause
//
// test_soak.c -- the soak scene (bench/soak_scene.c) bounded to 10^4 steps:
// bodies, joints and geoms are created and destroyed as it runs; the state
// stays finite, the space holds exactly the live geoms, and destroying the
// scene frees everything (under AddressSanitizer a leak fails the run).

#include "test.h"
#include "../bench/soak_scene.h"

static int test_soak_10k_steps(void)
{
    soak_scene *s = soak_create(32, 7);
    CHECK(s != NULL);
    for (int i = 1; i <= 10000; i++) {
        soak_step(s);
        if (i % 1000 == 0) {
            CHECK(soak_all_finite(s));
            soak_counts c = soak_count(s);
            // the ground, one geom per body, the static boxes
            CHECK(c.space_geoms == 1 + c.bodies + c.static_boxes);
            CHECK(c.bodies_made - c.bodies_destroyed == c.bodies);
            CHECK(c.geoms_made - c.geoms_destroyed == c.bodies + c.static_boxes);
            CHECK(c.joints_made - c.joints_destroyed == c.joints);
        }
    }
    soak_counts c = soak_count(s);
    // the churn really ran: hundreds of bodies and dozens of joints replaced
    CHECK(c.bodies_destroyed > 300);
    CHECK(c.joints_destroyed > 20);
    CHECK(c.geoms_made > c.bodies_made);
    soak_destroy(s);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_soak_10k_steps),
    TEST_END
};
