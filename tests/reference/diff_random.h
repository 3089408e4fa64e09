// SPDX-License-Identifier: BSD-3-Clause
//
// diff_random.h -- the random scenes of the differential collision tests: a
// generator of their own (a 64-bit LCG, seeded through rng_state) and
// rotations built here from random unit quaternions, so that this library
// and the reference ODE get the very same numbers and matrices.

#ifndef DIFF_RANDOM_H
#define DIFF_RANDOM_H

#include <ode/ode.h>
#include <math.h>

static unsigned long long rng_state;

// Uniform in [lo, hi).
static inline double rnd(double lo, double hi)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

// R: the rotation of a random unit quaternion.
static inline void random_rotation(dMatrix3 R)
{
    double q[4], l = 0;
    for (int i = 0; i < 4; i++) {
        q[i] = rnd(-1, 1);
        l += q[i] * q[i];
    }
    l = sqrt(l) + 1e-12;
    double w = q[0] / l, x = q[1] / l, y = q[2] / l, z = q[3] / l;
    dMatrix3 M = { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 0,
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 0,
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), 0 };
    for (int i = 0; i < 12; i++) R[i] = (dReal)M[i];
}

// Turn g by a random rotation.
static inline void random_geom_rotation(dGeomID g)
{
    dMatrix3 R;
    random_rotation(R);
    dGeomSetRotation(g, R);
}

#endif
