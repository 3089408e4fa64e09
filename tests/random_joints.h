// SPDX-License-Identifier: BSD-3-Clause
//
// random_joints.h -- the random draws of the tests that step scenes of
// joints under random parameters two ways and compare the bits
// (test_run_joint.c, test_build_phases.c): a linear congruential generator
// on a caller's state, bodies of random mass and velocities, and random
// limits and motors for a joint's axis.

#ifndef TEST_RANDOM_JOINTS_H
#define TEST_RANDOM_JOINTS_H

#include <ode/ode.h>
#include <stdint.h>

static inline uint32_t next_random(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s;
}

// A number in [lo, hi).
static inline dReal uniform(uint32_t *s, double lo, double hi)
{
    return (dReal)(lo + (hi - lo) * (double)(next_random(s) >> 8) / (double)(1u << 24));
}

// A box-shaped body of random mass at (x, y, z), moving and turning at
// random.
static inline dBodyID random_body(dWorldID w, uint32_t *r, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetBoxTotal(&m, uniform(r, 0.2, 2), (dReal)0.3, (dReal)0.2, (dReal)0.4);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    dBodySetAngularVel(b, uniform(r, -3, 3), uniform(r, -3, 3), uniform(r, -3, 3));
    dBodySetLinearVel(b, uniform(r, -1, 1), uniform(r, -1, 1), uniform(r, -1, 1));
    return b;
}

// Random stops (maybe close, maybe locked), motor and stop numbers for
// group g (dParamGroup * g) of j through set(j, parameter, value).
static inline void random_limot(uint32_t *r, dJointID j, int g,
                                void (*set)(dJointID, int, dReal))
{
    const int p = dParamGroup * g;
    const uint32_t kind = next_random(r) >> 28;
    if (kind < 4) {   // stops, maybe close
        set(j, p + dParamLoStop, uniform(r, -0.6, 0.05));
        set(j, p + dParamHiStop, uniform(r, -0.05, 0.6));
    } else if (kind < 7) {   // locked
        set(j, p + dParamLoStop, 0);
        set(j, p + dParamHiStop, 0);
    }
    if (next_random(r) >> 31) {
        set(j, p + dParamVel, uniform(r, -4, 4));
        set(j, p + dParamFMax, uniform(r, 0, 2));
    }
    set(j, p + dParamFudgeFactor, uniform(r, 0, 1));
    set(j, p + dParamStopERP, uniform(r, 0.1, 0.9));
    set(j, p + dParamStopCFM, uniform(r, 0, 0.01));
    set(j, p + dParamCFM, uniform(r, 0, 0.01));
    if (next_random(r) >> 30 == 0) set(j, p + dParamBounce, uniform(r, 0, 1));
}

#endif
