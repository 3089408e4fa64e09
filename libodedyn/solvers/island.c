// SPDX-License-Identifier: BSD-3-Clause
//
// island.c -- splitting the world's enabled bodies into islands (bodies
// connected through enabled joints; the static world and kinematic bodies do
// not connect), waking disabled bodies joined to enabled ones, and the
// auto-disable bookkeeping after a step.

#include "step_internal.h"

// Ask for the line holding p (a hint).
static inline void prefetch_line(const void *p)
{
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

// Walk from `seed` over joints, appending to the island arrays; a joint
// met is marked with this walk's number. Each node lies in its own joint,
// a line that has mostly left the first-level cache since the last step:
// the next node is asked for as soon as it is known (and each body's first
// one in dxStepBegin's pass over the bodies), so that the misses overlap
// with the work before they are read (docs/perf.md: the walk waited on the
// nodes' lines, one after the other).
static void grow_island(struct dxBody *seed, struct dxBody **stack, dxIsland *is,
                        unsigned walk)
{
    int top = 0;
    stack[top++] = seed;
    seed->tag = 1;
    while (top > 0) {
        struct dxBody *b = stack[--top];
        is->bodies[is->nb++] = b;
        for (dxJointNode *n = b->joints; n; n = n->next) {
            prefetch_line(n->next);
            dxJoint *j = n->joint;
            if (j->walk == walk || (j->flags & DX_JOINT_DISABLED)) continue;
            j->walk = walk;
            is->joints[is->nj++] = j;
            struct dxBody *o = n->other;
            if (!o || o->tag || (o->flags & DX_BODY_KINEMATIC)) continue;
            o->tag = 1;
            if (o->flags & DX_BODY_DISABLED) dBodyEnable(o);   // woken by its neighbour
            stack[top++] = o;
        }
    }
}

int dxStepBegin(struct dxWorld *w, dReal h, const char *function, dxIsland **islands,
                int *count)
{
    if (!dxWorldIsLive(w)) {
        dxReportBadArgument(function, "world is NULL or was destroyed");
        return 0;
    }
    if (!(h > 0) || !dxIsFinite(h)) {
        dxReportBadArgument(function, "stepsize must be positive and finite, got %g", (double)h);
        return 0;
    }
    dxStepMemoryBegin(w);
    w->step_count++;
    dxArena *a = w->arena;
    struct dxBody **all_bodies = DX_ARENA_ARRAY(a, struct dxBody *, w->num_bodies + 1);
    dxJoint **all_joints = DX_ARENA_ARRAY(a, dxJoint *, w->num_joints + 1);
    struct dxBody **stack = DX_ARENA_ARRAY(a, struct dxBody *, w->num_bodies + 1);
    dxIsland *list = DX_ARENA_ARRAY(a, dxIsland, w->num_bodies + 1);

    // Joints are marked by the walk's number, so they need no clearing pass
    // (a new joint has 0); after 2^32 walks the numbers start again.
    if (++w->island_walk == 0) {
        for (dxJoint *j = w->joints; j; j = j->next) j->walk = 0;
        w->island_walk = 1;
    }
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        b->tag = 0;
        prefetch_line(b->joints);
    }

    int n = 0;
    struct dxBody **next_body = all_bodies;
    dxJoint **next_joint = all_joints;
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        if (b->tag || (b->flags & (DX_BODY_DISABLED | DX_BODY_KINEMATIC))) continue;
        dxIsland *is = &list[n++];
        is->bodies = next_body;
        is->joints = next_joint;
        is->nb = is->nj = 0;
        grow_island(b, stack, is, w->island_walk);
        next_body += is->nb;
        next_joint += is->nj;
    }
    *islands = list;
    *count = n;
    return 1;
}

// Mean of the n speeds in a ring buffer.
static dReal ring_average(const dReal *ring, unsigned n)
{
    dReal sum = 0;
    for (unsigned i = 0; i < n; i++) sum += ring[i];
    return sum / (dReal)n;
}

// Record this step's speeds of a body with auto-disable; once its average
// speeds (over the last average_samples steps) have stayed under the
// thresholds for idle_steps steps and idle_time seconds, disable it.
static void auto_disable(struct dxBody *b, dReal h)
{
    unsigned n = b->adis_samples_size;
    b->adis_lvel_samples[b->adis_sample_next] = dCalcVectorLength3(b->lvel);
    b->adis_avel_samples[b->adis_sample_next] = dCalcVectorLength3(b->avel);
    b->adis_sample_next = (b->adis_sample_next + 1) % n;
    if (b->adis_samples_taken < n) b->adis_samples_taken++;
    if (b->adis_samples_taken < n) return;   // not enough samples yet

    if (ring_average(b->adis_lvel_samples, n) > b->adis.linear_threshold ||
        ring_average(b->adis_avel_samples, n) > b->adis.angular_threshold) {
        b->adis_idle_steps = 0;
        b->adis_idle_time = 0;
        return;
    }
    b->adis_idle_steps++;
    b->adis_idle_time += h;
    if (b->adis_idle_steps >= b->adis.idle_steps && b->adis_idle_time >= b->adis.idle_time) {
        b->flags |= DX_BODY_DISABLED;
        dZeroVector3(b->lvel);
        dZeroVector3(b->avel);
        b->gyro_pending = 0;   // nothing left to give back to a body at rest
    }
}

void dxStepEnd(const dxIsland *islands, int count, dReal h)
{
    for (int i = 0; i < count; i++) {
        for (int k = 0; k < islands[i].nb; k++) {
            struct dxBody *b = islands[i].bodies[k];
            if (b->flags & DX_BODY_AUTO_DISABLE) auto_disable(b, h);
        }
    }
}
