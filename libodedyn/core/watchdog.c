// SPDX-License-Identifier: BSD-3-Clause
//
// watchdog.c -- dWorldSetWatchdog (ours, <ode/snapshot.h>): after each step
// of a watched world, look for state that has blown up, name the bodies and
// joints involved and the likely cause, and on the callback's request put
// the world back as it was before the step (a snapshot taken before it).
//
// What is detected: non-finite body state, speeds above the limits, joints
// whose two anchors separated (ball, hinge, universal, hinge-2; a double
// ball off its distance), kinetic energy multiplied beyond a factor in one
// step. The likely causes are read around what was detected: a joint
// between bodies of very different mass, a joint pulled apart, a deep
// contact (the contact joints of the step are still alive when the
// watchdog runs), a body that turned more than a bound in one step.
// An unwatched world pays one test per step (dxWatchdogWants).

#include "objects_internal.h"
#include "joint_kept.h"

#include <math.h>
#include <ode/memory.h>
#include <ode/snapshot.h>
#include <stdarg.h>
#include <stdio.h>

typedef struct dxWatchdog {
    dWatchdogLimits limits;
    dWatchdogCallback *callback;
    void *user;
    unsigned char *last_good;   // snapshot before the step (keep_last_good)
    size_t last_good_size, last_good_cap;
} dxWatchdog;

void dxWatchdogFree(struct dxWorld *w)
{
    dxWatchdog *d = w->watchdog;
    if (!d) return;
    if (d->last_good) dFree(d->last_good, d->last_good_cap);
    dFree(d, sizeof *d);
    w->watchdog = NULL;
}

void dWatchdogLimitsSetDefaults(dWatchdogLimits *limits)
{
    DX_CHECK_ARG(limits != NULL, return, "limits is NULL");
    memset(limits, 0, sizeof *limits);
    limits->max_linear_speed = 1000;
    limits->max_angular_speed = 1000;
    limits->max_joint_error = REAL(0.1);
    limits->max_energy_growth = 10;
    limits->min_energy = 1;
    limits->max_mass_ratio = 100;
    limits->max_contact_depth = REAL(0.1);
    limits->max_rotation_per_step = REAL(0.5);
    limits->keep_last_good = 1;
}

static int non_negative(const dWatchdogLimits *l)
{
    const dReal x[] = { l->max_linear_speed, l->max_angular_speed, l->max_joint_error,
                        l->max_energy_growth, l->min_energy, l->max_mass_ratio,
                        l->max_contact_depth, l->max_rotation_per_step };
    for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
        if (!(x[i] >= 0)) return 0;
    return 1;
}

void dWorldSetWatchdog(dWorldID w, const dWatchdogLimits *limits, dWatchdogCallback *callback,
                       void *user)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return, "world is NULL or was destroyed");
    DX_CHECK_ARG(!w->watchdog_stepping, return, "called during a watched step");
    if (!limits) {
        dxWatchdogFree(w);
        return;
    }
    DX_CHECK_ARG(non_negative(limits), return, "limits must be >= 0 (0: not checked)");
    if (!w->watchdog) {
        w->watchdog = dAlloc(sizeof(dxWatchdog));
        memset(w->watchdog, 0, sizeof(dxWatchdog));
    }
    w->watchdog->limits = *limits;
    w->watchdog->callback = callback;
    w->watchdog->user = user;
}

// ---- measures --------------------------------------------------------------

static int is_dynamic(const struct dxBody *b) { return !(b->flags & DX_BODY_KINEMATIC); }

static dReal kinetic_energy(const struct dxBody *b)
{
    dVector3 wb;   // angular velocity in the body frame
    for (int i = 0; i < 3; i++)
        wb[i] = b->R[i] * b->avel[0] + b->R[4 + i] * b->avel[1] + b->R[8 + i] * b->avel[2];
    dReal rot = 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) rot += wb[i] * b->mass.I[4 * i + k] * wb[k];
    return REAL(0.5) * (b->mass.mass * dCalcVectorDot3(b->lvel, b->lvel) + rot);
}

static dReal world_energy(const struct dxWorld *w)
{
    dReal e = 0;
    for (const struct dxBody *b = w->bodies; b; b = b->next)
        if (is_dynamic(b) && !(b->flags & DX_BODY_DISABLED)) e += kinetic_energy(b);
    return e;
}

static int body_finite(const struct dxBody *b)
{
    for (int i = 0; i < 3; i++)
        if (!dxIsFinite(b->pos[i]) || !dxIsFinite(b->lvel[i]) || !dxIsFinite(b->avel[i]))
            return 0;
    for (int i = 0; i < 4; i++)
        if (!dxIsFinite(b->q[i])) return 0;
    return 1;
}

// How far a joint's anchors are apart (m), or -1 if its class has no such
// measure.
static dReal joint_error(dxJoint *j)
{
    dVector3 a, b;
    switch (j->cls->type) {
    case dJointTypeBall:
        dJointGetBallAnchor(j, a);
        dJointGetBallAnchor2(j, b);
        break;
    case dJointTypeHinge:
        dJointGetHingeAnchor(j, a);
        dJointGetHingeAnchor2(j, b);
        break;
    case dJointTypeUniversal:
        dJointGetUniversalAnchor(j, a);
        dJointGetUniversalAnchor2(j, b);
        break;
    case dJointTypeHinge2:
        dJointGetHinge2Anchor(j, a);
        dJointGetHinge2Anchor2(j, b);
        break;
    case dJointTypeDBall: {
        dJointGetDBallAnchor1(j, a);
        dJointGetDBallAnchor2(j, b);
        return dFabs(dCalcPointsDistance3(a, b) - dJointGetDBallDistance(j));
    }
    default:
        return -1;
    }
    return dCalcPointsDistance3(a, b);
}

// The larger of the two masses over the smaller (1 for a joint to the world).
static dReal mass_ratio(const dxJoint *j)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0 || !b1 || !is_dynamic(b0) || !is_dynamic(b1)) return 1;
    const dReal m0 = b0->mass.mass, m1 = b1->mass.mass;
    if (!(m0 > 0 && m1 > 0)) return 1;
    return m0 > m1 ? m0 / m1 : m1 / m0;
}

// ---- the report ------------------------------------------------------------

typedef struct report_ctx {
    dWatchdogReport *r;
    size_t len;
} report_ctx;

static void say(report_ctx *c, const char *fmt, ...) DX_PRINTF(2, 3);
static void say(report_ctx *c, const char *fmt, ...)
{
    const size_t cap = sizeof c->r->text;
    if (c->len >= cap - 1) return;
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(c->r->text + c->len, cap - c->len, fmt, ap);
    va_end(ap);
    if (n > 0) c->len = c->len + (size_t)n < cap ? c->len + (size_t)n : cap - 1;
}

// Bodies and joints are named by their rank in creation order among the
// world's living ones (the lists hold the newest first).
static int index_of_body(const struct dxWorld *w, const struct dxBody *b)
{
    int k = 0;
    for (const struct dxBody *x = w->bodies; x; x = x->next, k++)
        if (x == b) return w->num_bodies - 1 - k;
    return -1;
}

static int index_of_joint(const struct dxWorld *w, const dxJoint *j)
{
    int k = 0;
    for (const dxJoint *x = w->joints; x; x = x->next, k++)
        if (x == j) return w->num_joints - 1 - k;
    return -1;
}

// Name b in the report (once); returns 1 if it is (now) named.
static int name_body(dWatchdogReport *r, struct dxBody *b)
{
    for (int i = 0; i < r->num_bodies; i++)
        if (r->bodies[i] == b) return 1;
    if (r->num_bodies == dWATCHDOG_MAX_NAMED) return 0;
    r->bodies[r->num_bodies++] = b;
    return 1;
}

static int name_joint(dWatchdogReport *r, dxJoint *j)
{
    for (int i = 0; i < r->num_joints; i++)
        if (r->joints[i] == j) return 0;
    if (r->num_joints == dWATCHDOG_MAX_NAMED) return 0;
    r->joints[r->num_joints++] = j;
    return 1;
}

// What is wrong with the bodies after the step.
static void check_bodies(const struct dxWorld *w, const dWatchdogLimits *l, report_ctx *c)
{
    dWatchdogReport *r = c->r;
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        if (!is_dynamic(b)) continue;
        const int k = index_of_body(w, b);
        if (!body_finite(b)) {
            r->detected |= dWatchdogNonFinite;
            if (name_body(r, b)) say(c, "body #%d: state is not finite; ", k);
            continue;
        }
        const dReal v = dSqrt(dCalcVectorDot3(b->lvel, b->lvel));
        const dReal av = dSqrt(dCalcVectorDot3(b->avel, b->avel));
        if (l->max_linear_speed > 0 && v > l->max_linear_speed) {
            r->detected |= dWatchdogLinearSpeed;
            if (name_body(r, b))
                say(c, "body #%d: linear speed %g > %g m/s; ", k, (double)v,
                    (double)l->max_linear_speed);
        }
        if (l->max_angular_speed > 0 && av > l->max_angular_speed) {
            r->detected |= dWatchdogAngularSpeed;
            if (name_body(r, b))
                say(c, "body #%d: angular speed %g > %g rad/s; ", k, (double)av,
                    (double)l->max_angular_speed);
        }
    }
}

static void check_joints(const struct dxWorld *w, const dWatchdogLimits *l, report_ctx *c)
{
    if (!(l->max_joint_error > 0)) return;
    for (dxJoint *j = w->joints; j; j = j->next) {
        if (j->flags & DX_JOINT_DISABLED) continue;
        const dReal e = joint_error(j);
        if (e > l->max_joint_error || isnan(e)) {
            c->r->detected |= dWatchdogJointError;
            c->r->causes |= dWatchdogCauseJointPulledApart;
            if (name_joint(c->r, j))
                say(c, "joint #%d (%s): pulled apart, anchors %g m apart > %g; ",
                    index_of_joint(w, j), j->cls->name, (double)e, (double)l->max_joint_error);
        }
    }
}

// The bodies with the most kinetic energy, named when the energy grew and
// nothing else named a body.
static void name_most_energetic(const struct dxWorld *w, report_ctx *c)
{
    for (int n = 0; n < 3; n++) {
        struct dxBody *best = NULL;
        dReal best_e = -1;
        for (struct dxBody *b = w->bodies; b; b = b->next) {
            int named = 0;
            for (int i = 0; i < c->r->num_bodies; i++) named |= c->r->bodies[i] == b;
            const dReal e = is_dynamic(b) ? kinetic_energy(b) : -1;
            if (!named && e > best_e) {
                best = b;
                best_e = e;
            }
        }
        if (!best || !(best_e > 0)) return;
        name_body(c->r, best);
        say(c, "body #%d: kinetic energy %g J; ", index_of_body(w, best), (double)best_e);
    }
}

// The likely causes, around the named bodies and joints.
static void find_causes(const struct dxWorld *w, const dWatchdogLimits *l, dReal h,
                        report_ctx *c)
{
    dWatchdogReport *r = c->r;
    const int nbodies = r->num_bodies;
    for (int i = 0; i < nbodies; i++) {
        struct dxBody *b = r->bodies[i];
        const int k = index_of_body(w, b);
        const dReal turn = dSqrt(dCalcVectorDot3(b->avel, b->avel)) * h;
        if (l->max_rotation_per_step > 0 && turn > l->max_rotation_per_step) {
            r->causes |= dWatchdogCauseLargeStep;
            say(c, "cause: step too large, body #%d turns %g rad per step > %g; ", k,
                (double)turn, (double)l->max_rotation_per_step);
        }
        for (const dxJointNode *n = b->joints; n; n = n->next) {
            dxJoint *j = n->joint;
            const dContact *contact = dxJointContactGet(j);
            if (contact && l->max_contact_depth > 0 &&
                contact->geom.depth > l->max_contact_depth) {
                r->causes |= dWatchdogCauseInterpenetration;
                if (name_joint(r, j))
                    say(c, "cause: interpenetration, contact joint #%d of body #%d is %g m "
                        "deep > %g; ", index_of_joint(w, j), k, (double)contact->geom.depth,
                        (double)l->max_contact_depth);
            }
        }
    }
    // Mass ratios across the named joints and the joints of the named bodies.
    for (dxJoint *j = w->joints; j && l->max_mass_ratio > 0; j = j->next) {
        int near = 0;
        for (int i = 0; i < r->num_joints; i++) near |= r->joints[i] == j;
        for (int i = 0; i < nbodies; i++)
            near |= r->bodies[i] == dxJointBody(j, 0) || r->bodies[i] == dxJointBody(j, 1);
        const dReal ratio = near ? mass_ratio(j) : 1;
        if (ratio > l->max_mass_ratio) {
            r->causes |= dWatchdogCauseMassRatio;
            name_joint(r, j);
            say(c, "cause: mass ratio %g > %g across joint #%d (%s); ", (double)ratio,
                (double)l->max_mass_ratio, index_of_joint(w, j), j->cls->name);
        }
    }
    if (!r->causes) say(c, "cause: unknown; ");
}

// Fill r from the world after the step; returns 1 if a limit was broken.
static int check(const struct dxWorld *w, const dWatchdogLimits *l, dReal h, dReal e0,
                 dWatchdogReport *r)
{
    memset(r, 0, sizeof *r);
    report_ctx c = { r, 0 };
    say(&c, "step %lu (h %g): ", (unsigned long)w->step_count, (double)h);
    check_bodies(w, l, &c);
    check_joints(w, l, &c);
    const dReal e1 = world_energy(w);
    r->energy_before = e0;
    r->energy_after = e1;
    if (l->max_energy_growth > 0 && e1 > l->max_energy_growth * dMax(e0, l->min_energy)) {
        r->detected |= dWatchdogEnergyGrowth;
        say(&c, "kinetic energy grew from %g to %g J (> %g times); ", (double)e0, (double)e1,
            (double)l->max_energy_growth);
        if (r->num_bodies == 0) name_most_energetic(w, &c);
    }
    if (!r->detected) return 0;
    r->step = w->step_count;
    r->stepsize = h;
    find_causes(w, l, h, &c);
    if (c.len >= 2) r->text[c.len - 2] = 0;   // drop the last "; "
    return 1;
}

// ---- the watched step ------------------------------------------------------

static int run_step(struct dxWorld *w, dReal h, dxStepper stepper, int iterations)
{
    switch (stepper) {
    case DX_STEP_WORLD:
        return dWorldStep(w, h);
    case DX_STEP_QUICK:
        return dWorldQuickStep(w, h);
    case DX_STEP_FAST1:
        dWorldStepFast1(w, h, iterations);
        return 1;
    }
    return 0;
}

// Keep the world's state before the step (the buffer only grows).
static void keep_last_good(struct dxWorld *w, dxWatchdog *d)
{
    const size_t size = dWorldSnapshot(w, NULL, 0);
    if (size > d->last_good_cap) {
        if (d->last_good) dFree(d->last_good, d->last_good_cap);
        d->last_good_cap = size + size / 2;
        d->last_good = dAlloc(d->last_good_cap);
    }
    d->last_good_size = dWorldSnapshot(w, d->last_good, d->last_good_cap);
}

int dxWatchdogStep(struct dxWorld *w, dReal h, dxStepper stepper, int iterations)
{
    dxWatchdog *d = w->watchdog;
    const int keep = d->limits.keep_last_good;
    if (keep) keep_last_good(w, d);
    const dReal e0 = world_energy(w);
    w->watchdog_stepping = 1;
    const int ok = run_step(w, h, stepper, iterations);
    w->watchdog_stepping = 0;
    dWatchdogReport r;
    if (!ok || !check(w, &d->limits, h, e0, &r)) return ok;
    int back;
    if (d->callback) {
        back = d->callback(d->user, w, &r);
    } else {
        dMessage(d_ERR_UNKNOWN, "watchdog: %s", r.text);
        back = 0;
    }
    d = w->watchdog;   // (the callback may have changed it)
    if (!back || !keep || !d || !d->last_good) return 1;
    return dWorldRestore(w, d->last_good, d->last_good_size) ? 0 : 1;
}
