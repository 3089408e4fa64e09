// SPDX-License-Identifier: BSD-3-Clause
//
// test_warmstart.c -- dWorldQuickStep's warm start (quickstep.c,
// quickstep_warm.c): contacts start from the forces of the same contact in
// the last step. It moves only the iteration's starting point: many
// iterations give the answer of a cold start; it lets a resting stack settle
// with less residual motion; a contact that moved far, or any contact after
// another stepper ran, starts cold; memory stops growing; the result does
// not depend on other islands.
//
// White-box: a cold start is forced by counting a step of another stepper
// (w->step_count), which the cache must not reach across.

#include "test.h"
#include "objects_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define G 9.81

static const double SIZE[3] = { 0.5, 0.5, 0.25 };

static dBodyID box_body(dWorldID w, double x, double y, double z)
{
    dBodyID b = dBodyCreate(w);
    dMass mass;
    dMassSetBoxTotal(&mass, 1, SIZE[0], SIZE[1], SIZE[2]);
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    return b;
}

static void contact(dWorldID w, dJointGroupID g, dBodyID top, dBodyID bottom, const dVector3 p,
                    const dReal *n, double depth)
{
    if (depth < 0) return;
    dContact c;
    memset(&c, 0, sizeof c);
    c.surface.mode = dContactApprox1;
    c.surface.mu = 0.5;
    dCopyVector3(c.geom.pos, p);
    dCopyVector3(c.geom.normal, n);
    c.geom.depth = depth;
    c.geom.side1 = c.geom.side2 = -1;
    dJointAttach(dJointCreateContact(w, g, &c), top, bottom);
}

// The four contacts of `top` resting on `bottom` (or the ground z = 0), as
// a box-box collider puts them for boxes stacked nearly flat: the corners of
// the top box's bottom face, seen from the lower box (normal its up axis,
// depth below its top face), each shifted along the face by `shift`.
static void face_contacts(dWorldID w, dJointGroupID g, dBodyID top, dBodyID bottom, double shift)
{
    const double hx = 0.5 * SIZE[0], hy = 0.5 * SIZE[1], hz = 0.5 * SIZE[2];
    for (int k = 0; k < 4; k++) {
        dVector3 p, q;
        dBodyGetRelPointPos(top, (k & 1 ? hx : -hx) + shift, (k & 2 ? hy : -hy), -hz, p);
        if (!bottom) {
            static const dReal up[3] = { 0, 0, 1 };
            contact(w, g, top, NULL, p, up, -p[2]);
            continue;
        }
        dVector3 n;
        dBodyVectorToWorld(bottom, 0, 0, 1, n);
        dBodyGetPosRelPoint(bottom, p[0], p[1], p[2], q);
        contact(w, g, top, bottom, p, n, hz - q[2]);
    }
}

typedef struct stack {
    dWorldID w;
    dJointGroupID g;
    int n;
    dBodyID box[8];
} stack;

// n boxes on the ground at (x, y), 20 iterations.
static void stack_make(stack *s, dWorldID w, int n, double x, double y)
{
    s->w = w;
    s->g = dJointGroupCreate(0);
    s->n = n;
    for (int k = 0; k < n; k++) s->box[k] = box_body(w, x, y, (k + 0.5) * SIZE[2]);
}

static void stack_contacts(stack *s, double shift)
{
    for (int k = 0; k < s->n; k++) face_contacts(s->w, s->g, s->box[k], k ? s->box[k - 1] : 0, shift);
}

// One step: contacts, QuickStep (cold: as if another stepper had run since
// the last quick step), contacts dropped.
static void stack_step(stack *s, double h, int cold, double shift)
{
    stack_contacts(s, shift);
    if (cold) s->w->step_count++;
    dWorldQuickStep(s->w, h);
    dJointGroupEmpty(s->g);
}

// A copy of a's bodies' state in b (the same number of boxes), to the bit:
// dBodySetQuaternion normalises again, which can move the last bit, and the
// gyroscopic work ledger has no public setter (white-box).
static void stack_copy_state(stack *b, const stack *a)
{
    for (int k = 0; k < a->n; k++) {
        const dReal *p = dBodyGetPosition(a->box[k]), *q = dBodyGetQuaternion(a->box[k]);
        const dReal *v = dBodyGetLinearVel(a->box[k]), *o = dBodyGetAngularVel(a->box[k]);
        dBodySetPosition(b->box[k], p[0], p[1], p[2]);
        dBodySetQuaternion(b->box[k], q);
        dBodySetLinearVel(b->box[k], v[0], v[1], v[2]);
        dBodySetAngularVel(b->box[k], o[0], o[1], o[2]);
        memcpy(b->box[k]->q, a->box[k]->q, sizeof(dQuaternion));
        memcpy(b->box[k]->R, a->box[k]->R, sizeof(dMatrix3));
        b->box[k]->gyro_pending = a->box[k]->gyro_pending;
    }
}

// The largest difference of the boxes' velocities.
static double velocity_difference(const stack *a, const stack *b)
{
    double d = 0;
    for (int k = 0; k < a->n; k++) {
        const dReal *va = dBodyGetLinearVel(a->box[k]), *vb = dBodyGetLinearVel(b->box[k]);
        const dReal *wa = dBodyGetAngularVel(a->box[k]), *wb = dBodyGetAngularVel(b->box[k]);
        for (int e = 0; e < 3; e++) d = fmax(d, fmax(fabs(va[e] - vb[e]), fabs(wa[e] - wb[e])));
    }
    return d;
}

static int bits_equal(const stack *a, const stack *b)
{
    for (int k = 0; k < a->n; k++) {
        if (memcmp(dBodyGetPosition(a->box[k]), dBodyGetPosition(b->box[k]), 3 * sizeof(dReal)) ||
            memcmp(dBodyGetQuaternion(a->box[k]), dBodyGetQuaternion(b->box[k]),
                   4 * sizeof(dReal)) ||
            memcmp(dBodyGetLinearVel(a->box[k]), dBodyGetLinearVel(b->box[k]),
                   3 * sizeof(dReal)) ||
            memcmp(dBodyGetAngularVel(a->box[k]), dBodyGetAngularVel(b->box[k]),
                   3 * sizeof(dReal)))
            return 0;
    }
    return 1;
}

static dWorldID world(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -G);
    return w;
}

static void stack_destroy(stack *s)
{
    dJointGroupDestroy(s->g);
    dWorldDestroy(s->w);
}

// A warm start and a cold start of the same step, from the same state: with
// 20 iterations they differ (the warm start is in effect), with many they
// converge to the same velocities (the problem solved is the same).
static int test_converged_answer_is_the_cold_one(void)
{
    const double h = 0.01;
    stack a, b;
    stack_make(&a, world(), 3, 0, 0);
    stack_make(&b, world(), 3, 0, 0);
    for (int s = 0; s < 50; s++) stack_step(&a, h, 0, 0);
    double diff[2];
    const int iterations[2] = { 20, 2000 };
    for (int t = 0; t < 2; t++) {
        dWorldSetQuickStepNumIterations(a.w, iterations[t]);
        dWorldSetQuickStepNumIterations(b.w, iterations[t]);
        stack_copy_state(&b, &a);
        stack_step(&b, h, 1, 0);
        stack_step(&a, h, 0, 0);
        diff[t] = velocity_difference(&a, &b);
        stack_copy_state(&b, &a);   // the same state for the next comparison
    }
    printf("# warm vs cold start, largest velocity difference: %.3g (20 iterations), "
           "%.3g (2000)\n", diff[0], diff[1]);
    // (In single precision rounding leaves differences of some 1e-5 m/s.)
    CHECK(diff[0] > TOL(1e-6, 1e-4));
    CHECK(diff[1] < TOL(1e-7, 1e-4));
    CHECK(diff[1] < TOL(0.001, 0.05) * diff[0]);
    stack_destroy(&a);
    stack_destroy(&b);
    return 0;
}

// The motion left in a stack of 5 boxes that should rest, over the last
// two of 6 seconds: mean speed of the boxes' corners (linear plus angular
// times the half diagonal).
static double residual_motion(int cold)
{
    const double h = 1.0 / 60, arm = 0.5 * sqrt(SIZE[0] * SIZE[0] + SIZE[1] * SIZE[1] +
                                                SIZE[2] * SIZE[2]);
    stack s;
    stack_make(&s, world(), 5, 0, 0);
    double sum = 0;
    int count = 0;
    for (int t = 0; t < 360; t++) {
        stack_step(&s, h, cold, 0);
        if (t < 240) continue;
        for (int k = 0; k < s.n; k++) {
            sum += dCalcVectorLength3(dBodyGetLinearVel(s.box[k])) +
                   arm * dCalcVectorLength3(dBodyGetAngularVel(s.box[k]));
            count++;
        }
    }
    stack_destroy(&s);
    return sum / count;
}

static int test_resting_stack_settles_with_less_motion(void)
{
    const double warm = residual_motion(0), cold = residual_motion(1);
    printf("# stack of 5 boxes, mean corner speed over the last 2 s: %.3g m/s warm, "
           "%.3g m/s cold\n", warm, cold);
    CHECK(warm < 0.5 * cold);
    return 0;
}

// A contact that moved along the face by more than the tolerance (3 % of its
// lever arm, here 1.8 cm) is a new contact: the step is the cold step to the
// bit. One that moved by 1 mm is the same contact.
static int test_moved_contact_is_not_matched(void)
{
    const double h = 0.01;
    for (int t = 0; t < 2; t++) {
        const double shift = t ? 0.001 : 0.05;
        stack a, b;
        stack_make(&a, world(), 2, 0, 0);
        stack_make(&b, world(), 2, 0, 0);
        for (int s = 0; s < 20; s++) stack_step(&a, h, 0, 0);
        stack_copy_state(&b, &a);
        stack_step(&a, h, 0, shift);
        stack_step(&b, h, 1, shift);
        if (t == 0) CHECK(bits_equal(&a, &b));
        else CHECK(!bits_equal(&a, &b));
        stack_destroy(&a);
        stack_destroy(&b);
    }
    return 0;
}

// The same contacts after a dWorldStep start cold: its forces were not the
// cache's.
static int test_other_stepper_in_between_starts_cold(void)
{
    const double h = 0.01;
    stack a, b;
    stack_make(&a, world(), 2, 0, 0);
    stack_make(&b, world(), 2, 0, 0);
    for (int s = 0; s < 20; s++) stack_step(&a, h, 0, 0);
    stack_contacts(&a, 0);
    dWorldStep(a.w, h);
    dJointGroupEmpty(a.g);
    stack_copy_state(&b, &a);
    stack_step(&a, h, 0, 0);
    stack_step(&b, h, 1, 0);
    CHECK(bits_equal(&a, &b));
    stack_destroy(&a);
    stack_destroy(&b);
    return 0;
}

// A stack steps the same, to the bit, with another island (another stack,
// whose contacts were made first) in the world.
static int test_independent_of_other_islands(void)
{
    const double h = 1.0 / 60;
    stack a, b, other;
    stack_make(&a, world(), 4, 0, 0);
    dWorldID w2 = world();
    stack_make(&other, w2, 3, 5, 0);
    stack_make(&b, w2, 4, 0, 0);
    for (int s = 0; s < 200; s++) {
        stack_step(&a, h, 0, 0);
        stack_contacts(&other, 0);
        stack_step(&b, h, 0, 0);   // steps other too, its contacts built first
        dJointGroupEmpty(other.g);
    }
    CHECK(bits_equal(&a, &b));
    dJointGroupDestroy(other.g);
    stack_destroy(&a);
    stack_destroy(&b);
    return 0;
}

// Contacts are made anew every step, their cache is reused: after two
// warm-up steps a step allocates nothing.
static int test_cache_does_not_grow(void)
{
    stack s;
    stack_make(&s, world(), 6, 0, 0);
    stack_step(&s, 0.01, 0, 0);
    stack_step(&s, 0.01, 0, 0);
    // The joint group keeps its chunks: make the contacts once more before counting.
    stack_contacts(&s, 0);
    dJointGroupEmpty(s.g);
    test_count_allocations();
    for (int t = 0; t < 50; t++) stack_step(&s, 0.01, 0, 0);
    const int counted = test_allocations_counted();
    stack_destroy(&s);
    CHECK(counted == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_converged_answer_is_the_cold_one),
    TEST_CASE(test_resting_stack_settles_with_less_motion),
    TEST_CASE(test_moved_contact_is_not_matched),
    TEST_CASE(test_other_stepper_in_between_starts_cold),
    TEST_CASE(test_independent_of_other_islands),
    TEST_CASE(test_cache_does_not_grow),
    TEST_END
};
