// SPDX-License-Identifier: BSD-3-Clause
//
// selftest.c -- the two self-tests ODE 0.16 exports without declaring them
// in a public header (its demo declares them itself):
//
//   int dTestSolveLCP(void)        random mixed LCPs through the solver of
//                                  dWorldStep, each solution checked against
//                                  the LCP conditions; one line per problem.
//   void dTestDataStructures(void) random creation, attachment and
//                                  destruction of bodies and joints, the
//                                  world's lists checked after every change;
//                                  then the scratch arena's save/restore.
//
// A failed check is reported through the message handler (ODE uses the
// debug handler, which aborts by default; a self-test should say what failed
// and go on). dTestSolveLCP returns 1 if every problem passed, else 0.

#include "arena.h"
#include "lcp.h"
#include "objects_internal.h"

#include <ode/error.h>
#include <ode/matrix.h>
#include <ode/misc.h>
#include <ode/timer.h>
#include <stdio.h>
#include <string.h>

ODE_API int dTestSolveLCP(void);
ODE_API void dTestDataStructures(void);

// ---- dTestSolveLCP ------------------------------------------------------------

#define LCP_N 100
#define LCP_NUB 50
#define LCP_PROBLEMS 1000

#if defined(dSINGLE)
#define LCP_TOL 1e-4
#else
#define LCP_TOL 1e-9
#endif

// The conditions for row i of a solution, w = A x - b: at a bound, w points
// outward (or is zero); strictly inside, w is zero. The tolerance is relative
// to the row's scale, |b| + sum |A x|. Counts the rows at lo, at hi and
// inside (NL, NH, C, as ODE prints them); returns the number of violations.
static int lcp_check(const dReal *A, const dReal *x, const dReal *b, const dReal *lo,
                     const dReal *hi, int counts[3])
{
    const int skip = dPAD(LCP_N);
    int bad = 0;
    for (int i = 0; i < LCP_N; i++) {
        dReal w = -b[i], scale = dFabs(b[i]);
        for (int k = 0; k < LCP_N; k++) {
            w += A[i * skip + k] * x[k];
            scale += dFabs(A[i * skip + k] * x[k]);
        }
        const dReal tol = (dReal)LCP_TOL * (1 + scale);
        if (i >= LCP_NUB && x[i] == lo[i] && w >= -tol) {
            counts[0]++;
        } else if (i >= LCP_NUB && x[i] == hi[i] && w <= tol) {
            counts[1]++;
        } else if ((i < LCP_NUB || (x[i] >= lo[i] && x[i] <= hi[i])) && dFabs(w) <= tol) {
            counts[2]++;
        } else {
            dMessage(0, "dTestSolveLCP: FAILED: i=%d x=%.4e w=%.4e lo=%.4e hi=%.4e", i,
                     (double)x[i], (double)w, (double)lo[i], (double)hi[i]);
            bad++;
        }
    }
    return bad;
}

// The problems are ODE's: A = M M^T for a random M (positive definite),
// b = A x0 + noise, the first LCP_NUB rows unbounded, the others boxed in
// [-(0.01..1.01), 0.01..1.01].
int dTestSolveLCP(void)
{
    const int n = LCP_N, skip = dPAD(LCP_N);
    dxArena arena;
    dxArenaInit(&arena);
    dReal *A = DX_ARENA_ARRAY(&arena, dReal, n * skip);
    dReal *M = DX_ARENA_ARRAY(&arena, dReal, n * skip);
    dReal *x = DX_ARENA_ARRAY(&arena, dReal, n);
    dReal *b = DX_ARENA_ARRAY(&arena, dReal, n);
    dReal *w = DX_ARENA_ARRAY(&arena, dReal, n);
    dReal *lo = DX_ARENA_ARRAY(&arena, dReal, n);
    dReal *hi = DX_ARENA_ARRAY(&arena, dReal, n);
    printf("dTestSolveLCP()\n");
    double total_time = 0;
    int failed = 0;
    for (int count = 0; count < LCP_PROBLEMS; count++) {
        dMakeRandomMatrix(M, n, n, 1.0);
        dMultiply2(A, M, M, n, n, n);
        dMakeRandomMatrix(x, n, 1, 1.0);
        dMultiply0(b, A, x, n, n, 1);
        for (int i = 0; i < n; i++) b[i] += dRandReal() * (dReal)0.2 - (dReal)0.1;
        for (int i = LCP_NUB; i < n; i++) lo[i] = -dRandReal() - (dReal)0.01;
        for (int i = LCP_NUB; i < n; i++) hi[i] = dRandReal() + (dReal)0.01;

        dStopwatch sw;
        dStopwatchReset(&sw);
        dStopwatchStart(&sw);
        const int solved = dxSolveLCP(&arena, n, A, x, b, w, LCP_NUB, lo, hi, NULL);
        dStopwatchStop(&sw);
        const double time = dStopwatchTime(&sw);
        total_time += time;

        int counts[3] = { 0, 0, 0 };
        const int bad = lcp_check(A, x, b, lo, hi, counts);
        if (bad || !solved) {
            if (!solved) dMessage(0, "dTestSolveLCP: the solver reported failure");
            failed++;
        }
        printf("%s: NL=%3d NH=%3d C=%3d   time=%10.3f ms  avg=%10.4f\n",
               bad || !solved ? "FAILED" : "passed", counts[0], counts[1], counts[2],
               time * 1000.0, total_time / (count + 1) * 1000.0);
    }
    dxArenaFree(&arena);
    return failed == 0;
}

// ---- dTestDataStructures ------------------------------------------------------------

#define DS_MAX 100
#define DS_OPERATIONS 20000

// Check what links a world's bodies and joints; report each broken rule.
// Returns the number of broken rules.
static int check_world(const struct dxWorld *w)
{
    int bad = 0, bodies = 0, joints = 0;
#define RULE(cond, what) \
    do { \
        if (!(cond)) { \
            dMessage(0, "dTestDataStructures: %s", what); \
            bad++; \
        } \
    } while (0)
    for (const struct dxBody *b = w->bodies; b; b = b->next) {
        bodies++;
        RULE(dxBodyIsLive(b), "a dead body in the world's list");
        RULE(b->world == w, "a body names another world");
        RULE(!b->next || b->next->prev == b, "the body list's back links are broken");
        int n = 0;
        for (const dxJointNode *node = b->joints; node; node = node->next) {
            n++;
            const dxJoint *j = node->joint;
            RULE(dxJointIsLive(j), "a body lists a dead joint");
            const int k = (int)(node - j->node);
            RULE(k == 0 || k == 1, "a joint node is not one of its joint's nodes");
            RULE(dxJointBody(j, k) == b, "a joint node sits in another body's list");
        }
        RULE(n == b->num_joints, "a body's joint count is wrong");
    }
    for (const struct dxJoint *j = w->joints; j; j = j->next) {
        joints++;
        RULE(dxJointIsLive(j), "a dead joint in the world's list");
        RULE(j->world == w, "a joint names another world");
        RULE(!j->next || j->next->prev == j, "the joint list's back links are broken");
        for (int k = 0; k < 2; k++) {
            const struct dxBody *b = dxJointBody(j, k);
            if (!b) continue;
            int found = 0;
            for (const dxJointNode *node = b->joints; node; node = node->next)
                found += node == &j->node[k];
            RULE(found == 1, "a joint is not listed once by its body");
        }
        RULE(dxJointBody(j, 0) || !dxJointBody(j, 1), "a joint has body 1 without body 0");
    }
    RULE(bodies == w->num_bodies, "the world's body count is wrong");
    RULE(joints == w->num_joints, "the world's joint count is wrong");
#undef RULE
    return bad;
}

// Nested saves and restores hand out aligned, disjoint memory and give back
// exactly what was taken after the mark.
static int check_arena(void)
{
    int bad = 0;
    dxArena arena;
    dxArenaInit(&arena);
    for (int round = 0; round < 3; round++) {
        dxArenaMark outer = dxArenaSave(&arena);
        char *a = dxArenaAlloc(&arena, 100);
        dxArenaMark inner = dxArenaSave(&arena);
        char *b = dxArenaAlloc(&arena, 1 << 16);   // may need a new block
        char *c = dxArenaAlloc(&arena, 10);
        memset(a, 1, 100);
        memset(b, 2, 1 << 16);
        memset(c, 3, 10);
        if ((uintptr_t)a % 64 || (uintptr_t)b % 64 || (uintptr_t)c % 64) bad++;
        if (a[99] != 1 || b[0] != 2 || c[9] != 3) bad++;   // no overlap
        dxArenaRestore(&arena, inner);
        if (arena.in_use != inner.in_use) bad++;
        dxArenaRestore(&arena, outer);
        if (arena.in_use != outer.in_use) bad++;
        dxArenaReset(&arena);
    }
    dxArenaFree(&arena);
    if (bad) dMessage(0, "dTestDataStructures: the scratch arena broke %d rules", bad);
    return bad;
}

// ODE's test, bounded: each round may create a body, create and attach a
// joint, reattach one, destroy a body, destroy a joint (each with chance
// 1/2, from dRandReal), and the world is checked after every change. A
// destroyed handle must read as dead.
void dTestDataStructures(void)
{
    printf("dTestDataStructures()\n");
    dBodyID body[DS_MAX];
    dJointID joint[DS_MAX];
    int nb = 0, nj = 0, bad = 0, operations = 0;
    dWorldID w = dWorldCreate();
    bad += check_world(w);
    while (operations < DS_OPERATIONS) {
        if (nb < DS_MAX && dRandReal() > 0.5) {
            body[nb++] = dBodyCreate(w);
            bad += check_world(w);
            operations++;
        }
        if (nj < DS_MAX && nb > 2 && dRandReal() > 0.5) {
            dBodyID b1 = body[dRand() % (unsigned long)nb];
            dBodyID b2 = body[dRand() % (unsigned long)nb];
            if (b1 != b2) {
                joint[nj] = dJointCreateBall(w, 0);
                bad += check_world(w);
                dJointAttach(joint[nj++], b1, dRandReal() > 0.8 ? NULL : b2);
                bad += check_world(w);
                operations++;
            }
        }
        if (nj > 0 && nb > 2 && dRandReal() > 0.5) {
            dBodyID b1 = body[dRand() % (unsigned long)nb];
            dBodyID b2 = body[dRand() % (unsigned long)nb];
            if (b1 != b2) {
                dJointAttach(joint[dRand() % (unsigned long)nj], dRandReal() > 0.8 ? NULL : b1,
                             b2);
                bad += check_world(w);
                operations++;
            }
        }
        if (nb > 0 && dRandReal() > 0.5) {
            const int k = (int)(dRand() % (unsigned long)nb);
            dBodyID dead = body[k];
            dBodyDestroy(dead);
            if (dxBodyIsLive(dead)) {
                dMessage(0, "dTestDataStructures: a destroyed body is live");
                bad++;
            }
            bad += check_world(w);
            body[k] = body[--nb];
            operations++;
        }
        if (nj > 0 && dRandReal() > 0.5) {
            const int k = (int)(dRand() % (unsigned long)nj);
            dJointID dead = joint[k];
            dJointDestroy(dead);
            if (dxJointIsLive(dead)) {
                dMessage(0, "dTestDataStructures: a destroyed joint is live");
                bad++;
            }
            bad += check_world(w);
            joint[k] = joint[--nj];
            operations++;
        }
    }
    dWorldDestroy(w);
    bad += check_arena();
    printf("%d operations on bodies and joints, %d broken rules: %s\n", operations, bad,
           bad ? "FAILED" : "passed");
}
