// SPDX-License-Identifier: BSD-3-Clause
//
// random_joints.h -- the random draws of the tests that step scenes of
// joints under random parameters two ways and compare the bits
// (test_run_joint.c, test_build_phases.c): a linear congruential generator
// on a caller's state, bodies of random mass and velocities, random limits
// and motors for a joint's axis, the ground contacts of a box's bottom
// corners, and the bodies' states to compare.

#ifndef TEST_RANDOM_JOINTS_H
#define TEST_RANDOM_JOINTS_H

#include <ode/ode.h>
#include <stdint.h>
#include <string.h>

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

// Contacts (friction mu, soft) of the bottom corners of random_body's box b
// that are below the ground z = 0, into group g.
static inline void ground_contacts(dWorldID w, dJointGroupID g, dBodyID b, dReal mu)
{
    for (int c = 0; c < 4; c++) {
        dVector3 p;
        dBodyGetRelPointPos(b, c & 1 ? (dReal)0.15 : (dReal)-0.15, c & 2 ? (dReal)0.1 : (dReal)-0.1,
                            (dReal)-0.2, p);
        if (p[2] >= 0) continue;
        dContact ct;
        memset(&ct, 0, sizeof ct);
        ct.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
        ct.surface.mu = mu;
        ct.surface.soft_erp = (dReal)0.5;
        ct.surface.soft_cfm = (dReal)0.001;
        ct.geom.pos[0] = p[0];
        ct.geom.pos[1] = p[1];
        ct.geom.normal[2] = 1;
        ct.geom.depth = -p[2];
        dJointAttach(dJointCreateContact(w, g, &ct), b, 0);
    }
}

// The positions, quaternions and velocities of bodies b[0 .. nb) into out
// (13 numbers a body); returns the end of what was written.
static inline dReal *body_states(const dBodyID *b, int nb, dReal *out)
{
    for (int k = 0; k < nb; k++) {
        memcpy(out, dBodyGetPosition(b[k]), 3 * sizeof(dReal));
        memcpy(out + 3, dBodyGetQuaternion(b[k]), 4 * sizeof(dReal));
        memcpy(out + 7, dBodyGetLinearVel(b[k]), 3 * sizeof(dReal));
        memcpy(out + 10, dBodyGetAngularVel(b[k]), 3 * sizeof(dReal));
        out += 13;
    }
    return out;
}

#endif
