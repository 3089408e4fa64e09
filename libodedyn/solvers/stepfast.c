// SPDX-License-Identifier: BSD-3-Clause
//
// stepfast.c -- dWorldStepFast1 (guide chapter 8): the step h is cut into
// maxiterations sub-steps s = h / maxiterations. In each sub-step every body
// receives its share s/h of the step's external forces, then every joint in
// turn solves its own rows as a small LCP in which only its two bodies move,
//   (J M^-1 J^T + cfm/s) lambda = c/s - J v/s + w,
// and applies the impulse s J^T lambda to their velocities at once, so the
// joints after it see the change (a Gauss-Seidel sweep over the joints). The
// bodies then move by s, and the next sub-step rebuilds the rows from the new
// poses. Memory and time are linear in the number of joints.
//
// Three choices the guide leaves open:
// - The joints fill their rows with fps = 1/h, not 1/s: c = erp * error / h
//   as under dWorldStep, so ERP and CFM keep their meaning for the step size
//   the user gave (a soft joint is the same spring, kp = ERP / (h CFM))
//   instead of becoming maxiterations times stiffer.
// - Warm start: each sub-step starts with every joint's force of the previous
//   sub-step acting; at its turn a joint takes its own force off and solves
//   for its new total force, so it can give back force it applied too much.
//   Without this each contact can only push, and a box resting on four
//   contacts gains upward and turning speed in every sweep and creeps away.
// - The first sub-step, which has no previous forces, sweeps twice: its first
//   sweep is the warm start of its second.
//
// Also here: the StepFast1 auto-disable of guide 8.4 (squared speeds under a
// per-body threshold for a number of steps) and its depth-limited waking.

#include "lcp.h"
#include "step_internal.h"

#include <ode/matrix.h>

// The rows of one joint and the local system built from them, in scratch that every joint
// solve of the step reuses (grown, rarely, for a joint with more rows than any before).
typedef struct joint_system {
    int cap;         // rows the scratch holds
    int m;
    int index[2];    // island index of each side, -1 if the side does not move here
    dReal *J;        // m x 12: [J1l J1a J2l J2a]
    dReal *c, *cfm, *lo, *hi;
    int *findex;     // relative to the joint's first row, as fill_rows writes it
    dReal *iMJ;      // m x 12: M^-1 J^T per row, zero for a side that does not move
    dReal *A;        // m x m, row skip dPAD(m): J M^-1 J^T + cfm/s
    dReal *rhs, *lambda, *w;
} joint_system;

// Most rows a joint of this library has; the scratch grows for more.
#define JOINT_ROWS 6

// Everything one step works on. `all` holds every enabled dynamic body (one
// island after another, in walk order) and every enabled joint touching them;
// a joint's other body may be kinematic (moves by its own velocity) or
// disabled (left asleep: it stays where it is, like static geometry).
typedef struct sf1_step {
    struct dxWorld *world;
    dxIsland all;
    dxIslandBodies bd;            // inverse masses; world inverse inertias, kept current
    dReal *force;                 // 12 per joint: J^T lambda of its latest solve
    dReal *external;              // 6 per body: force and torque of the step, as
                                  // prepared (accumulators, gravity)
    struct dxBody **kinematic;    // the enabled kinematic bodies
    int nk;
    dReal s, fps;                 // sub-step and its inverse
    dReal rows_fps;               // 1 / h, for the joints' rows
    int last;                     // the sub-step is the last one of the step
    int lcp_failures;
    int nonfinite_solves;          // joint solves whose rows were not finite ...
    const dxJoint *nonfinite;      // ... the first such joint
    joint_system js;              // scratch for one joint's solve
} sf1_step;

// Guide 8.4: enabled bodies wake the disabled bodies within `depth` joint hops
// of them (breadth first, so each body is reached by its shortest path). The
// walk crosses enabled joints only, and not kinematic bodies, like the island
// walk. b->tag: -1 unvisited, else the hop count from the nearest enabled body.
static void wake_within_depth(struct dxWorld *w)
{
    const int depth = w->sf1_auto_enable_depth;
    if (depth <= 0) return;
    struct dxBody **queue = DX_ARENA_ARRAY(w->arena, struct dxBody *, w->num_bodies + 1);
    int head = 0, tail = 0;
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        b->tag = -1;
        if (!(b->flags & (DX_BODY_DISABLED | DX_BODY_KINEMATIC))) {
            b->tag = 0;
            queue[tail++] = b;
        }
    }
    while (head < tail) {
        struct dxBody *b = queue[head++];
        if (b->tag >= depth) continue;
        for (dxJointNode *n = b->joints; n; n = n->next) {
            struct dxBody *o = n->other;
            if ((n->joint->flags & DX_JOINT_DISABLED) || !o || o->tag >= 0 ||
                (o->flags & DX_BODY_KINEMATIC))
                continue;
            dBodyEnable(o);   // unvisited and not kinematic: it was disabled
            o->tag = b->tag + 1;
            queue[tail++] = o;
        }
    }
}

// Depth-first walk from seed over enabled joints, appending bodies and joints
// to st->all; disabled and kinematic bodies end the walk (their joints are
// kept). Marks visited bodies and joints with tag 1.
static void walk_island(struct dxBody *seed, struct dxBody **stack, dxIsland *all)
{
    int top = 0;
    stack[top++] = seed;
    seed->tag = 1;
    while (top > 0) {
        struct dxBody *b = stack[--top];
        all->bodies[all->nb++] = b;
        for (dxJointNode *n = b->joints; n; n = n->next) {
            dxJoint *j = n->joint;
            if (j->tag || (j->flags & DX_JOINT_DISABLED)) continue;
            j->tag = 1;
            all->joints[all->nj++] = j;
            struct dxBody *o = n->other;
            if (!o || o->tag || (o->flags & (DX_BODY_DISABLED | DX_BODY_KINEMATIC))) continue;
            o->tag = 1;
            stack[top++] = o;
        }
    }
}

// Gather the bodies and joints of this step (arena scratch).
static void collect(struct dxWorld *w, sf1_step *st)
{
    dxArena *a = w->arena;
    st->all.bodies = DX_ARENA_ARRAY(a, struct dxBody *, w->num_bodies + 1);
    st->all.joints = DX_ARENA_ARRAY(a, dxJoint *, w->num_joints + 1);
    st->all.nb = st->all.nj = 0;
    st->force = DX_ARENA_ARRAY(a, dReal, 12 * (w->num_joints + 1));
    st->kinematic = DX_ARENA_ARRAY(a, struct dxBody *, w->num_bodies + 1);
    st->nk = 0;
    struct dxBody **stack = DX_ARENA_ARRAY(a, struct dxBody *, w->num_bodies + 1);
    for (struct dxBody *b = w->bodies; b; b = b->next) b->tag = 0;
    for (dxJoint *j = w->joints; j; j = j->next) j->tag = 0;
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        if (b->flags & DX_BODY_DISABLED) continue;
        if (b->flags & DX_BODY_KINEMATIC) st->kinematic[st->nk++] = b;
        else if (!b->tag) walk_island(b, stack, &st->all);
    }
}

// v += s M^-1 (f, t): this sub-step's share of the step's external forces
// (accumulators and gravity, added once by dxIslandPrepare), and the
// gyroscopic change of the sub-step, from the body's pose and rate now.
static void apply_external_forces(const sf1_step *st)
{
    for (int i = 0; i < st->all.nb; i++) {
        struct dxBody *b = st->all.bodies[i];
        dVector3 dw, t, torque;
        dCopyVector3(torque, b->torque);
        if (dxBodyGyroscopicTorque(b, st->s, t)) dAddVectors3(torque, torque, t);
        dAddVectorScaledVector3(b->lvel, b->lvel, b->force, st->s * st->bd.inv_mass[i]);
        dMultiply0_331(dw, st->bd.inv_inertia + 12 * i, torque);
        dAddVectorScaledVector3(b->avel, b->avel, dw, st->s);
    }
}

static void joint_system_reserve(dxArena *a, joint_system *js, int m)
{
    if (m <= js->cap) return;
    js->cap = m;
    dReal *r = DX_ARENA_ARRAY(a, dReal, 36 * (size_t)m + (size_t)m * dPAD(m));
    js->J = r;
    js->iMJ = r + 12 * m;
    js->A = r + 24 * m;
    r += 24 * m + (size_t)m * dPAD(m);
    js->c = r;
    js->cfm = r + m;
    js->lo = r + 2 * m;
    js->hi = r + 3 * m;
    js->rhs = r + 4 * m;
    js->lambda = r + 5 * m;
    js->w = r + 6 * m;
    js->findex = DX_ARENA_ARRAY(a, int, m);
}

// Island index of a joint's body k, or -1 when it does not move in the solve:
// the static world, a kinematic body (moves by itself) or a disabled body.
static int moving_index(const dxJoint *j, int k)
{
    const struct dxBody *b = dxJointBody(j, k);
    return (b && !(b->flags & (DX_BODY_KINEMATIC | DX_BODY_DISABLED))) ? b->tag : -1;
}

// v += sign * s M^-1 f for the moving bodies of joint j; f = [force0 torque0
// force1 torque1] in stored body order.
static void add_joint_impulse(const sf1_step *st, const dxJoint *j, const dReal *f, dReal sign)
{
    for (int k = 0; k < 2; k++) {
        int i = moving_index(j, k);
        if (i < 0) continue;
        struct dxBody *b = st->all.bodies[i];
        dVector3 dw;
        dAddVectorScaledVector3(b->lvel, b->lvel, f + 6 * k, sign * st->s * st->bd.inv_mass[i]);
        dMultiply0_331(dw, st->bd.inv_inertia + 12 * i, f + 6 * k + 3);
        dAddVectorScaledVector3(b->avel, b->avel, dw, sign * st->s);
    }
}

// Ask the joint for its rows at the current poses (fps = 1/h), and move the
// known velocity of a kinematic body into c, as dxRowsBuild does. Rows that
// are not finite are cleared (no force) and counted.
static void fill_joint_rows(sf1_step *st, dxJoint *j, joint_system *js)
{
    const int m = js->m;
    dSetZero(js->J, 12 * m);
    dSetZero(js->c, m);
    dSetValue(js->cfm, m, st->world->cfm);
    dSetValue(js->lo, m, -dInfinity);
    dSetValue(js->hi, m, dInfinity);
    for (int i = 0; i < m; i++) js->findex[i] = -1;

    dxJointRows info = { .fps = st->rows_fps, .erp = st->world->erp, .rowskip = 12,
                         .J1l = js->J, .J1a = js->J + 3, .J2l = js->J + 6, .J2a = js->J + 9,
                         .c = js->c, .cfm = js->cfm, .lo = js->lo, .hi = js->hi,
                         .findex = js->findex };
    j->cls->fill_rows(j, &info);

    for (int k = 0; k < 2; k++) {
        const struct dxBody *b = dxJointBody(j, k);
        js->index[k] = moving_index(j, k);
        if (!b || (b->flags & (DX_BODY_KINEMATIC | DX_BODY_DISABLED)) != DX_BODY_KINEMATIC)
            continue;
        for (int i = 0; i < m; i++) {
            const dReal *Jk = js->J + 12 * i + 6 * k;
            js->c[i] -= dCalcVectorDot3(Jk, b->lvel) + dCalcVectorDot3(Jk + 3, b->avel);
        }
    }
    if (!dxJointRowsKeepFinite(j, m, js->J, 12, js->c, js->cfm, js->lo, js->hi, js->findex)) {
        if (st->nonfinite_solves++ == 0) st->nonfinite = j;
    }
}

// A = J M^-1 J^T + cfm/s (row skip dPAD(m)) and rhs = c/s - J v/s, with only
// the joint's moving bodies; fills js->iMJ.
static void form_local_system(const sf1_step *st, joint_system *js)
{
    const int m = js->m, skip = dPAD(m);
    for (int i = 0; i < m; i++) {
        const dReal *J = js->J + 12 * i;
        dReal *o = js->iMJ + 12 * i, v_dot = 0;
        for (int k = 0; k < 2; k++) {
            int b = js->index[k];
            if (b < 0) {
                dSetZero(o + 6 * k, 6);
                continue;
            }
            const struct dxBody *body = st->all.bodies[b];
            dCopyScaledVector3(o + 6 * k, J + 6 * k, st->bd.inv_mass[b]);
            dMultiply0_331(o + 6 * k + 3, st->bd.inv_inertia + 12 * b, J + 6 * k + 3);
            v_dot += dCalcVectorDot3(J + 6 * k, body->lvel) +
                     dCalcVectorDot3(J + 6 * k + 3, body->avel);
        }
        js->rhs[i] = (js->c[i] - v_dot) * st->fps;
    }
    for (int i = 0; i < m; i++) {   // symmetric: the lower triangle, mirrored
        const dReal *J = js->J + 12 * i;
        for (int r = 0; r <= i; r++) {
            const dReal *M = js->iMJ + 12 * r;
            dReal sum = 0;
            for (int e = 0; e < 12; e++) sum += J[e] * M[e];
            js->A[i * skip + r] = js->A[r * skip + i] = sum;
        }
        js->A[i * skip + i] += js->cfm[i] * st->fps;
    }
}

// Solve one joint alone (the velocities must not include its own force) and
// apply its impulse s J^T lambda to its moving bodies' velocities now. f
// receives J^T lambda.
static void solve_joint(sf1_step *st, dxJoint *j, dReal f[12])
{
    joint_system *js = &st->js;
    joint_system_reserve(st->world->arena, js, j->rows.m);
    js->m = j->rows.m;
    fill_joint_rows(st, j, js);
    form_local_system(st, js);
    if (!dxSolveLCP(st->world->arena, js->m, js->A, js->lambda, js->rhs, js->w, 0, js->lo,
                    js->hi, js->findex))
        st->lcp_failures++;
    for (int i = 0; i < js->m; i++)
        for (int e = 0; e < 12; e++) f[e] += js->J[12 * i + e] * js->lambda[i];
    add_joint_impulse(st, j, f, 1);
}

// Every joint's force of the previous sub-step acts again (zero at first).
static void apply_warm_start(const sf1_step *st)
{
    for (int k = 0; k < st->all.nj; k++)
        add_joint_impulse(st, st->all.joints[k], st->force + 12 * k, 1);
}

// The bodies' accumulators back to the step's external forces. Filling a
// joint's rows adds the push of a limit motor powering against its stop
// (joint_limot.c); a sweep's pushes act in the next sub-step, each once.
static void restore_external_forces(const sf1_step *st)
{
    for (int i = 0; i < st->all.nb; i++) {
        struct dxBody *b = st->all.bodies[i];
        dCopyVector3(b->force, st->external + 6 * i);
        dCopyVector3(b->torque, st->external + 6 * i + 3);
    }
}

// One sweep over the joints, each replacing its previous force by a new
// solve; the last sub-step's forces go to the feedback.
static void solve_joints(sf1_step *st)
{
    restore_external_forces(st);
    for (int k = 0; k < st->all.nj; k++) {
        dxJoint *j = st->all.joints[k];
        dReal *f = st->force + 12 * k;
        add_joint_impulse(st, j, f, -1);
        dSetZero(f, 12);
        j->cls->count_rows(j, &j->rows);
        if (j->rows.m > 0) solve_joint(st, j, f);
        dJointFeedback *fb = j->feedback;
        if (st->last && fb) {
            dCopyVector3(fb->f1, f);
            dCopyVector3(fb->t1, f + 3);
            dCopyVector3(fb->f2, f + 6);
            dCopyVector3(fb->t2, f + 9);
        }
    }
}

// Move every body by the sub-step. Between sub-steps only the poses change
// (and the world inverse inertias follow); after the last one the usual end
// of step runs once: damping, geom notification, moved callbacks, cleared
// accumulators.
static void move_bodies(sf1_step *st)
{
    if (st->last) {
        // (No position sweeps: the sub-steps already relax joint by joint, and
        // sweeps after the last one left a released chain further apart.)
        dxIslandMove(&st->all, st->s);
        dxIslandFinish(&st->all);
        dxStepKinematicBodies(st->world, st->s);
        return;
    }
    for (int i = 0; i < st->all.nb; i++) {
        struct dxBody *b = st->all.bodies[i];
        dxBodyGyroscopicEnd(b, st->s);
        dxBodyIntegrate(b, st->s);
        dxBodyWorldInverseInertia(b, st->bd.inv_inertia + 12 * i);
    }
    for (int i = 0; i < st->nk; i++) dxBodyIntegrate(st->kinematic[i], st->s);
}

// Guide 8.4: a body whose squared linear and angular speeds both stay at or
// under its threshold for sf1_steps consecutive steps is disabled (and its
// velocity zeroed, as the other auto-disable does).
static void sf1_auto_disable(const dxIsland *all)
{
    for (int i = 0; i < all->nb; i++) {
        struct dxBody *b = all->bodies[i];
        if (!(b->flags & DX_BODY_AUTO_DISABLE_SF1)) continue;
        if (dCalcVectorLengthSquare3(b->lvel) > b->sf1_threshold ||
            dCalcVectorLengthSquare3(b->avel) > b->sf1_threshold) {
            b->sf1_idle_steps = 0;
            continue;
        }
        if (++b->sf1_idle_steps >= b->sf1_steps) {
            b->flags |= DX_BODY_DISABLED;
            dZeroVector3(b->lvel);
            dZeroVector3(b->avel);
            b->gyro_pending = 0;
        }
    }
}

void dWorldStepFast1(dWorldID w, dReal stepsize, int maxiterations)
{
    if (dxWatchdogWants(w)) {
        dxWatchdogStep(w, stepsize, DX_STEP_FAST1, maxiterations);
        return;
    }
    DX_CHECK_ARG(dxWorldIsLive(w), return, "world is NULL or was destroyed");
    DX_CHECK_ARG(stepsize > 0 && dxIsFinite(stepsize), return,
                 "stepsize must be positive and finite, got %g", (double)stepsize);
    DX_CHECK_ARG(maxiterations >= 1, return, "maxiterations must be >= 1, got %d",
                 maxiterations);
    dxStepMemoryBegin(w);
    w->step_count++;   // (no QuickStep warm start across it)
    wake_within_depth(w);

    sf1_step st;
    st.world = w;
    st.s = stepsize / (dReal)maxiterations;
    st.fps = dRecip(st.s);
    st.rows_fps = dRecip(stepsize);
    st.lcp_failures = 0;
    st.nonfinite_solves = 0;
    st.nonfinite = NULL;
    st.js.cap = 0;
    joint_system_reserve(w->arena, &st.js, JOINT_ROWS);
    collect(w, &st);
    dSetZero(st.force, 12 * st.all.nj);
    dxIslandPrepare(w, w->arena, &st.all, 0, &st.bd);
    st.external = DX_ARENA_ARRAY(w->arena, dReal, 6 * (size_t)st.all.nb + 1);
    for (int i = 0; i < st.all.nb; i++) {
        dCopyVector3(st.external + 6 * i, st.all.bodies[i]->force);
        dCopyVector3(st.external + 6 * i + 3, st.all.bodies[i]->torque);
    }

    for (int it = 0; it < maxiterations; it++) {
        st.last = it == maxiterations - 1;
        apply_external_forces(&st);
        apply_warm_start(&st);
        solve_joints(&st);
        if (it == 0) solve_joints(&st);
        move_bodies(&st);
    }
    if (st.lcp_failures > 0)
        dMessage(d_ERR_LCP, "dWorldStepFast1: the LCP solver did not converge for %d joint "
                 "solves; using its best approximation", st.lcp_failures);
    if (st.nonfinite_solves > 0)
        dxReportMessage(__func__, "a %s joint's rows were not finite (its pose or parameters "
                        "have no answer) in %d joint solves: no force there",
                        st.nonfinite->cls->name, st.nonfinite_solves);
    sf1_auto_disable(&st.all);
    dxStepEnd(&st.all, 1, stepsize);
}
