// SPDX-License-Identifier: BSD-3-Clause
//
// body_params.c -- a body's auto-disable (guide 6.x and 8.5) and damping
// parameters.

#include "objects_internal.h"

#include <ode/memory.h>
#include <string.h>

#define CHECK_BODY(b, on_fail) \
    DX_CHECK_ARG(dxBodyIsLive(b), on_fail, "body is NULL or was destroyed")

// Size the speed-sample ring buffers for adis.average_samples.
static void resize_samples(struct dxBody *b)
{
    unsigned n = b->adis.average_samples;
    if (n == b->adis_samples_size) return;
    if (b->adis_lvel_samples) {
        dFree(b->adis_lvel_samples, b->adis_samples_size * sizeof(dReal));
        dFree(b->adis_avel_samples, b->adis_samples_size * sizeof(dReal));
    }
    // Zeroed: the slots not yet sampled are never averaged, but a snapshot
    // writes them, and its bytes (and checksum) should depend on the state
    // alone.
    b->adis_lvel_samples = dAlloc(n * sizeof(dReal));
    b->adis_avel_samples = dAlloc(n * sizeof(dReal));
    if (n) {
        memset(b->adis_lvel_samples, 0, n * sizeof(dReal));
        memset(b->adis_avel_samples, 0, n * sizeof(dReal));
    }
    b->adis_samples_size = n;
    b->adis_sample_next = 0;
    b->adis_samples_taken = 0;
}

dReal dBodyGetAutoDisableLinearThreshold(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->adis.linear_threshold;
}

void dBodySetAutoDisableLinearThreshold(dBodyID b, dReal threshold)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    b->adis.linear_threshold = threshold;
}

dReal dBodyGetAutoDisableAngularThreshold(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->adis.angular_threshold;
}

void dBodySetAutoDisableAngularThreshold(dBodyID b, dReal threshold)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    b->adis.angular_threshold = threshold;
}

int dBodyGetAutoDisableAverageSamplesCount(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (int)b->adis.average_samples;
}

void dBodySetAutoDisableAverageSamplesCount(dBodyID b, unsigned int count)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(count >= 1 && count <= 10000, return,
                 "average_samples_count must be in 1..10000, got %u", count);
    b->adis.average_samples = count;
    resize_samples(b);
}

int dBodyGetAutoDisableSteps(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->adis.idle_steps;
}

void dBodySetAutoDisableSteps(dBodyID b, int steps)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(steps >= 0, return, "steps must be >= 0, got %d", steps);
    b->adis.idle_steps = steps;
}

dReal dBodyGetAutoDisableTime(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->adis.idle_time;
}

void dBodySetAutoDisableTime(dBodyID b, dReal time)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(time >= 0, return, "time must be >= 0");
    b->adis.idle_time = time;
}

int dBodyGetAutoDisableFlag(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_AUTO_DISABLE) != 0;
}

void dBodySetAutoDisableFlag(dBodyID b, int do_auto_disable)
{
    CHECK_BODY(b, return);
    if (do_auto_disable) b->flags |= DX_BODY_AUTO_DISABLE;
    else b->flags &= ~(unsigned)DX_BODY_AUTO_DISABLE;
    b->adis_idle_steps = 0;
    b->adis_idle_time = 0;
    b->adis_samples_taken = 0;
}

void dBodySetAutoDisableDefaults(dBodyID b)
{
    CHECK_BODY(b, return);
    b->adis = b->world->adis;
    resize_samples(b);
    dBodySetAutoDisableFlag(b, b->world->adis_flag);
}

void dBodySetAutoDisableThresholdSF1(dBodyID b, dReal threshold)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(threshold >= 0, return, "autoDisableThreshold must be >= 0");
    b->sf1_threshold = threshold;
}

dReal dBodyGetAutoDisableThresholdSF1(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->sf1_threshold;
}

void dBodySetAutoDisableStepsSF1(dBodyID b, int steps)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(steps >= 0, return, "AutoDisableSteps must be >= 0, got %d", steps);
    b->sf1_steps = steps;
}

int dBodyGetAutoDisableStepsSF1(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->sf1_steps;
}

void dBodySetAutoDisableSF1(dBodyID b, int do_auto_disable)
{
    CHECK_BODY(b, return);
    if (do_auto_disable) b->flags |= DX_BODY_AUTO_DISABLE_SF1;
    else b->flags &= ~(unsigned)DX_BODY_AUTO_DISABLE_SF1;
    b->sf1_idle_steps = 0;
}

int dBodyGetAutoDisableSF1(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_AUTO_DISABLE_SF1) != 0;
}

// ---- damping ------------------------------------------------------------

#define CHECK_SCALE(s, on_fail) \
    DX_CHECK_ARG((s) >= 0 && (s) <= 1, on_fail, "scale must be in 0..1, got %g", (double)(s))

// Keep the flags that let the integrator skip damping in sync with the values.
static void update_damping_flags(struct dxBody *b)
{
    b->flags &= ~(unsigned)(DX_BODY_LINEAR_DAMPING | DX_BODY_ANGULAR_DAMPING |
                            DX_BODY_MAX_ANGULAR_SPEED);
    if (b->damping.linear_scale > 0) b->flags |= DX_BODY_LINEAR_DAMPING;
    if (b->damping.angular_scale > 0) b->flags |= DX_BODY_ANGULAR_DAMPING;
    if (b->damping.max_angular_speed < dInfinity) b->flags |= DX_BODY_MAX_ANGULAR_SPEED;
}

void dBodySetDampingDefaults(dBodyID b)
{
    CHECK_BODY(b, return);
    b->damping = b->world->damping;
    update_damping_flags(b);
}

dReal dBodyGetLinearDamping(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->damping.linear_scale;
}

void dBodySetLinearDamping(dBodyID b, dReal scale)
{
    CHECK_BODY(b, return);
    CHECK_SCALE(scale, return);
    b->damping.linear_scale = scale;
    update_damping_flags(b);
}

dReal dBodyGetAngularDamping(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->damping.angular_scale;
}

void dBodySetAngularDamping(dBodyID b, dReal scale)
{
    CHECK_BODY(b, return);
    CHECK_SCALE(scale, return);
    b->damping.angular_scale = scale;
    update_damping_flags(b);
}

void dBodySetDamping(dBodyID b, dReal linear_scale, dReal angular_scale)
{
    CHECK_BODY(b, return);
    CHECK_SCALE(linear_scale, return);
    CHECK_SCALE(angular_scale, return);
    b->damping.linear_scale = linear_scale;
    b->damping.angular_scale = angular_scale;
    update_damping_flags(b);
}

dReal dBodyGetLinearDampingThreshold(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->damping.linear_threshold;
}

void dBodySetLinearDampingThreshold(dBodyID b, dReal threshold)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    b->damping.linear_threshold = threshold;
}

dReal dBodyGetAngularDampingThreshold(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->damping.angular_threshold;
}

void dBodySetAngularDampingThreshold(dBodyID b, dReal threshold)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    b->damping.angular_threshold = threshold;
}

dReal dBodyGetMaxAngularSpeed(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->damping.max_angular_speed;
}

void dBodySetMaxAngularSpeed(dBodyID b, dReal max_speed)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(max_speed >= 0, return, "max_speed must be >= 0");
    b->damping.max_angular_speed = max_speed;
    update_damping_flags(b);
}
