// SPDX-License-Identifier: BSD-3-Clause
//
// world.c -- world creation and destruction and the world's parameters
// (guide chapter 5). Stepping lives in step.c, quickstep.c and stepfast.c.

#include "objects_internal.h"
#include "pool.h"
#include "step_memory.h"

#include <ode/memory.h>
#include <math.h>

#define CHECK_WORLD(w, on_fail) \
    DX_CHECK_ARG(dxWorldIsLive(w), on_fail, "world is NULL or was destroyed")

dWorldID dWorldCreate(void)
{
    struct dxWorld *w = dxPoolTake(&dx_world_pool, sizeof *w);
    uint32_t generation = w->hdr.generation;
    memset(w, 0, sizeof *w);
    w->hdr.magic = DX_MAGIC_WORLD;
    w->hdr.generation = generation + 1;
#ifdef dSINGLE
    w->cfm = REAL(1e-5);
#else
    w->cfm = REAL(1e-10);
#endif
    w->erp = REAL(0.2);
    w->qs_iterations = 20;
    w->qs_w = REAL(1.3);
    w->max_correcting_vel = dInfinity;
    w->contact_surface_layer = 0;
    w->adis.linear_threshold = REAL(0.01);
    w->adis.angular_threshold = REAL(0.01);
    w->adis.average_samples = 1;
    w->adis.idle_steps = 10;
    w->adis.idle_time = 0;
    w->adis_flag = 0;
    w->sf1_auto_enable_depth = 1000;   // guide 8.4
    w->damping.linear_threshold = REAL(0.01);
    w->damping.angular_threshold = REAL(0.01);
    w->damping.max_angular_speed = dInfinity;
    for (int i = 0; i < 3; i++) w->contact_frame.given[i] = (dReal)NAN;   // (matches no normal)
    return w;
}

void dWorldDestroy(dWorldID w)
{
    CHECK_WORLD(w, return);
    // Joints first: grouped ones only lose their world (the group frees them).
    while (w->joints) {
        dxJoint *j = w->joints;
        if (j->flags & DX_JOINT_IN_GROUP) {
            dxJointDetach(j);
            w->joints = j->next;
            j->next = j->prev = NULL;
            j->world = NULL;
            j->flags |= DX_JOINT_DEAD_WORLD;
        } else {
            dJointDestroy(j);
        }
    }
    while (w->bodies) dBodyDestroy(w->bodies);
    dxStepMemoryRelease(w);
    dxWorldThreadingRelease(w);
    dxWarmCacheFree(w);
    dxWatchdogFree(w);
    w->hdr.magic = DX_MAGIC_DEAD;
    dxPoolGive(&dx_world_pool, w);
}

void dWorldSetData(dWorldID w, void *data)
{
    CHECK_WORLD(w, return);
    w->userdata = data;
}

void *dWorldGetData(dWorldID w)
{
    CHECK_WORLD(w, return NULL);
    return w->userdata;
}

void dWorldSetGravity(dWorldID w, dReal x, dReal y, dReal z)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "gravity is not finite");
    dAssignVector3(w->gravity, x, y, z);
}

void dWorldGetGravity(dWorldID w, dVector3 g)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(g != NULL, return, "gravity (the result) is NULL");
    dCopyVector3(g, w->gravity);
}

void dWorldSetERP(dWorldID w, dReal erp)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(erp >= 0 && erp <= 1, return, "erp must be in 0..1, got %g", (double)erp);
    w->erp = erp;
}

dReal dWorldGetERP(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->erp;
}

void dWorldSetCFM(dWorldID w, dReal cfm)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(cfm >= 0 && dxIsFinite(cfm), return, "cfm must be finite and >= 0, got %g",
                 (double)cfm);
    w->cfm = cfm;
}

dReal dWorldGetCFM(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->cfm;
}

void dWorldImpulseToForce(dWorldID w, dReal stepsize, dReal ix, dReal iy, dReal iz,
                          dVector3 force)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(stepsize > 0 && dxIsFinite(stepsize), return,
                 "stepsize must be positive, got %g", (double)stepsize);
    DX_CHECK_ARG(force != NULL, return, "force (the result) is NULL");
    dReal k = dRecip(stepsize);
    dAssignVector3(force, ix * k, iy * k, iz * k);
}

void dWorldSetQuickStepNumIterations(dWorldID w, int num)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(num > 0, return, "num must be positive, got %d", num);
    w->qs_iterations = num;
}

int dWorldGetQuickStepNumIterations(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->qs_iterations;
}

void dWorldSetQuickStepW(dWorldID w, dReal over_relaxation)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(over_relaxation > 0 && over_relaxation < 2, return,
                 "over_relaxation must be in (0, 2), got %g", (double)over_relaxation);
    w->qs_w = over_relaxation;
}

dReal dWorldGetQuickStepW(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->qs_w;
}

void dWorldSetContactMaxCorrectingVel(dWorldID w, dReal vel)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(vel >= 0, return, "vel must be >= 0, got %g", (double)vel);
    w->max_correcting_vel = vel;
}

dReal dWorldGetContactMaxCorrectingVel(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->max_correcting_vel;
}

void dWorldSetContactSurfaceLayer(dWorldID w, dReal depth)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(depth >= 0 && dxIsFinite(depth), return, "depth must be finite and >= 0");
    w->contact_surface_layer = depth;
}

dReal dWorldGetContactSurfaceLayer(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->contact_surface_layer;
}

// ---- auto-disable defaults --------------------------------------------

dReal dWorldGetAutoDisableLinearThreshold(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->adis.linear_threshold;
}

void dWorldSetAutoDisableLinearThreshold(dWorldID w, dReal threshold)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    w->adis.linear_threshold = threshold;
}

dReal dWorldGetAutoDisableAngularThreshold(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->adis.angular_threshold;
}

void dWorldSetAutoDisableAngularThreshold(dWorldID w, dReal threshold)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    w->adis.angular_threshold = threshold;
}

int dWorldGetAutoDisableAverageSamplesCount(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return (int)w->adis.average_samples;
}

void dWorldSetAutoDisableAverageSamplesCount(dWorldID w, unsigned int count)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(count >= 1 && count <= 10000, return,
                 "average_samples_count must be in 1..10000, got %u", count);
    w->adis.average_samples = count;
}

int dWorldGetAutoDisableSteps(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->adis.idle_steps;
}

void dWorldSetAutoDisableSteps(dWorldID w, int steps)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(steps >= 0, return, "steps must be >= 0, got %d", steps);
    w->adis.idle_steps = steps;
}

dReal dWorldGetAutoDisableTime(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->adis.idle_time;
}

void dWorldSetAutoDisableTime(dWorldID w, dReal time)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(time >= 0, return, "time must be >= 0");
    w->adis.idle_time = time;
}

int dWorldGetAutoDisableFlag(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->adis_flag;
}

void dWorldSetAutoDisableFlag(dWorldID w, int do_auto_disable)
{
    CHECK_WORLD(w, return);
    w->adis_flag = do_auto_disable != 0;
}

void dWorldSetAutoEnableDepthSF1(dWorldID w, int depth)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(depth >= 0, return, "autoEnableDepth must be >= 0, got %d", depth);
    w->sf1_auto_enable_depth = depth;
}

int dWorldGetAutoEnableDepthSF1(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->sf1_auto_enable_depth;
}

// ---- damping ------------------------------------------------------------

#define CHECK_SCALE(s, on_fail) \
    DX_CHECK_ARG((s) >= 0 && (s) <= 1, on_fail, "scale must be in 0..1, got %g", (double)(s))

dReal dWorldGetLinearDampingThreshold(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->damping.linear_threshold;
}

void dWorldSetLinearDampingThreshold(dWorldID w, dReal threshold)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    w->damping.linear_threshold = threshold;
}

dReal dWorldGetAngularDampingThreshold(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->damping.angular_threshold;
}

void dWorldSetAngularDampingThreshold(dWorldID w, dReal threshold)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(threshold >= 0, return, "threshold must be >= 0");
    w->damping.angular_threshold = threshold;
}

dReal dWorldGetLinearDamping(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->damping.linear_scale;
}

void dWorldSetLinearDamping(dWorldID w, dReal scale)
{
    CHECK_WORLD(w, return);
    CHECK_SCALE(scale, return);
    w->damping.linear_scale = scale;
}

dReal dWorldGetAngularDamping(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->damping.angular_scale;
}

void dWorldSetAngularDamping(dWorldID w, dReal scale)
{
    CHECK_WORLD(w, return);
    CHECK_SCALE(scale, return);
    w->damping.angular_scale = scale;
}

void dWorldSetDamping(dWorldID w, dReal linear_scale, dReal angular_scale)
{
    CHECK_WORLD(w, return);
    CHECK_SCALE(linear_scale, return);
    CHECK_SCALE(angular_scale, return);
    w->damping.linear_scale = linear_scale;
    w->damping.angular_scale = angular_scale;
}

dReal dWorldGetMaxAngularSpeed(dWorldID w)
{
    CHECK_WORLD(w, return 0);
    return w->damping.max_angular_speed;
}

void dWorldSetMaxAngularSpeed(dWorldID w, dReal max_speed)
{
    CHECK_WORLD(w, return);
    DX_CHECK_ARG(max_speed >= 0, return, "max_speed must be >= 0");
    w->damping.max_angular_speed = max_speed;
}
