// SPDX-License-Identifier: BSD-3-Clause
//
// xorshift.h -- the random numbers of tests that draw poses and meshes:
// Marsaglia's xorshift64 (shifts 13, 7, 17). rng_state starts at RNG_SEED
// (defined before the include, or 0: then the test seeds it before drawing).

#ifndef TEST_XORSHIFT_H
#define TEST_XORSHIFT_H

#include <stdint.h>

#ifndef RNG_SEED
#define RNG_SEED 0
#endif

static uint64_t rng_state = RNG_SEED;

// Uniform in [lo, hi): the state's top 53 bits as a fraction.
static double rnd(double lo, double hi)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return lo + (hi - lo) * (double)(rng_state >> 11) * 0x1p-53;
}

#endif
