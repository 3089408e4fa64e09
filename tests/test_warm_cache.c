// SPDX-License-Identifier: BSD-3-Clause
//
// test_warm_cache.c -- the warm start's contact cache (quickstep_warm.c)
// driven directly, as dWorldQuickStep's build does: contacts entered one by
// one with their bodies, point, normal and friction directions, given lambda
// positions (every other one as a plain contact's numbers, the direct way),
// then the solve's forces. Its answers (found or not, the old
// normal force, the friction force in the world frame) are compared with a
// plain matcher written here from the rule alone: every old contact of the
// same body pair (pointers and generations) is a candidate; the point, in
// the first body's frame, within WARM_TOL times the longer lever arm; the
// normal within WARM_COS; the nearest wins, ties to the smaller normal force,
// then to the earlier contact. The cases: random scenes whose pairs come in
// runs, split runs and any order; a body reused under a new generation; a
// step of another stepper in between. The random scenes come in runs whose
// contacts lie apart (the quick match), close together, twice (ties), and
// in the next step in the same order or each pair's from another start.

#include "test.h"
#include "objects_internal.h"
#include "quickstep.h"

#include <math.h>
#include <string.h>

#define NB 6          // bodies (the last pair slot uses the static world)
#define MAXC 400      // contacts per step

// A contact as the test enters it, with what the cache should carry.
typedef struct tcontact {
    dBodyID b0, b1;
    dVector3 p, n, t1, t2;
    dReal ln, l1, l2;             // the forces the "solve" gives it
} tcontact;

// The test's own record of a step's contacts (world frame at that step's
// poses, which do not change within the step).
typedef struct tstep {
    tcontact c[MAXC];
    int n;
    uint32_t g0[MAXC], g1[MAXC];
    dReal pb[MAXC][3], nb[MAXC][3], fb[MAXC][3];   // b0's frame
} tstep;

static uint32_t rng = 12345;
static double urand(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (rng >> 8) * (1.0 / 16777216.0);
}

static void to_body(const dBodyID b, const dReal *v, dReal *x)
{
    const dReal *R = dBodyGetRotation(b);
    for (int i = 0; i < 3; i++) x[i] = R[i] * v[0] + R[4 + i] * v[1] + R[8 + i] * v[2];
}

static void random_unit(dReal *v)
{
    do {
        for (int i = 0; i < 3; i++) v[i] = 2 * urand() - 1;
    } while (dCalcVectorDot3(v, v) < 0.1 || dCalcVectorDot3(v, v) > 1);
    dNormalize3(v);
}

// Record what the cache keeps of c (b0's frame), as the rule says.
static void record(tstep *s, int k)
{
    const tcontact *c = &s->c[k];
    dVector3 arm, f;
    dSubtractVectors3(arm, c->p, dBodyGetPosition(c->b0));
    to_body(c->b0, arm, s->pb[k]);
    to_body(c->b0, c->n, s->nb[k]);
    for (int i = 0; i < 3; i++) f[i] = c->l1 * c->t1[i] + c->l2 * c->t2[i];
    to_body(c->b0, f, s->fb[k]);
    s->g0[k] = c->b0->hdr.generation;
    s->g1[k] = c->b1 ? c->b1->hdr.generation : 0;
}

// The plain matcher: the index of the old contact that c matches, or -1.
static int plain_match(const tstep *old, const tcontact *c)
{
    dVector3 arm, p, n;
    dSubtractVectors3(arm, c->p, dBodyGetPosition(c->b0));
    dReal reach2 = dCalcVectorDot3(arm, arm);
    if (c->b1) {
        dVector3 a1;
        dSubtractVectors3(a1, c->p, dBodyGetPosition(c->b1));
        if (dCalcVectorDot3(a1, a1) > reach2) reach2 = dCalcVectorDot3(a1, a1);
    }
    to_body(c->b0, arm, p);
    to_body(c->b0, c->n, n);
    const uint32_t g0 = c->b0->hdr.generation, g1 = c->b1 ? c->b1->hdr.generation : 0;
    int best = -1;
    dReal best_d2 = WARM_TOL * WARM_TOL * reach2;
    for (int k = 0; k < old->n; k++) {
        const tcontact *o = &old->c[k];
        if (o->b0 != c->b0 || o->b1 != c->b1 || old->g0[k] != g0 || old->g1[k] != g1) continue;
        dReal d2 = 0;
        for (int i = 0; i < 3; i++) d2 += (old->pb[k][i] - p[i]) * (old->pb[k][i] - p[i]);
        if (dCalcVectorDot3(old->nb[k], n) < WARM_COS) continue;
        // Within the tolerance (its bound included), nearer than the best so
        // far, or as near with a smaller normal force.
        const int better = best < 0 ? d2 <= best_d2
                                    : d2 < best_d2 || (d2 == best_d2 && o->ln < old->c[best].ln);
        if (better) {
            best = k;
            best_d2 = d2;
        }
    }
    return best;
}

// Enter the step's contacts in the cache, compare each answer with the
// plain matcher's against `old`, then end the step with the contacts'
// forces. Returns the number of contacts found.
static int run_step(dWorldID w, tstep *s, const tstep *old, int *mismatches)
{
    static dReal lambda[3 * MAXC];
    dxWarmCache *cache = dxQuickWarmBegin(w, s->n);
    int found_count = 0;
    for (int k = 0; k < s->n; k++) {
        tcontact *c = &s->c[k];
        int found;
        dReal ln = -1, f[4] = { 0, 0, 0, 0 };
        if (k % 2) {   // as a plain contact's numbers (quickstep_contact.c)
            dxContactRows r;
            memset(&r, 0, sizeof r);
            r.friction = 3;   // both friction rows, after the normal row
            dCopyVector3(r.n, c->n);
            dCopyVector3(r.t1, c->t1);
            dCopyVector3(r.t2, c->t2);
            r.point = c->p;
            found = dxQuickWarmContactRows(cache, c->b0, c->b1, &r, 3 * k, f);
            if (found) ln = f[3];
        } else {   // as a contact through the generic rows (quickstep_build.c)
            qs_warm_entry *e = dxQuickWarmContact(cache, c->b0, c->b1, c->p, c->n, c->t1,
                                                  c->t2, &found, &ln, f);
            const int pos[3] = { 3 * k, 3 * k + 1, 3 * k + 2 };
            dxQuickWarmPositions(e, pos);
        }
        lambda[3 * k] = c->ln;
        lambda[3 * k + 1] = c->l1;
        lambda[3 * k + 2] = c->l2;
        const int want = old ? plain_match(old, c) : -1;
        if (found != (want >= 0)) {
            (*mismatches)++;
            continue;
        }
        if (!found) continue;
        found_count++;
        // The old contact's forces: its normal force, and its friction force
        // carried in b0's frame, back in the world frame now.
        dVector3 fw;
        const dReal *R = dBodyGetRotation(c->b0), *fb = old->fb[want];
        for (int i = 0; i < 3; i++) fw[i] = R[4 * i] * fb[0] + R[4 * i + 1] * fb[1] + R[4 * i + 2] * fb[2];
        const dReal tol = 1e-5 * (1 + dFabs(old->c[want].l1) + dFabs(old->c[want].l2));
        if (ln != old->c[want].ln || dFabs(f[0] - fw[0]) > tol || dFabs(f[1] - fw[1]) > tol ||
            dFabs(f[2] - fw[2]) > tol)
            (*mismatches)++;
    }
    for (int k = 0; k < s->n; k++) record(s, k);
    dxQuickWarmEnd(w, cache, lambda);
    w->step_count++;   // as the quick step does after its end
    return found_count;
}

// A contact of pair (a, b) near point p with normal n; the friction
// directions are n's plane space.
static void make_contact(tcontact *c, dBodyID a, dBodyID b, const dReal *p, const dReal *n)
{
    c->b0 = a;
    c->b1 = b;
    dCopyVector3(c->p, p);
    dCopyVector3(c->n, n);
    dPlaneSpace(n, c->t1, c->t2);
    c->ln = urand();
    c->l1 = urand() - 0.5;
    c->l2 = urand() - 0.5;
}

// Random scenes: bodies at random poses, pairs with 1-6 contacts each (a
// few with points close together, so that several old ones fit, some
// twice with other forces: ties), entered in
// pair runs, in split runs, or shuffled; the next step moves every body a
// little and every point by a random amount around the tolerance, drops some
// contacts and adds others.
static int test_matches_the_plain_rule(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body[NB];
    for (int i = 0; i < NB; i++) body[i] = dBodyCreate(w);
    static tstep a, b;
    int total_found = 0, total = 0, mismatches = 0;
    for (int scene = 0; scene < 200; scene++) {
        for (int i = 0; i < NB; i++) {
            dBodySetPosition(body[i], 4 * urand(), 4 * urand(), 4 * urand());
            dQuaternion q = { urand() + 0.1, urand() - 0.5, urand() - 0.5, urand() - 0.5 };
            dBodySetQuaternion(body[i], q);
        }
        // Step 1.
        a.n = 0;
        for (int pair = 0; pair < 12; pair++) {
            dBodyID x = body[(int)(urand() * NB)], y = body[(int)(urand() * NB)];
            if (y == x || urand() < 0.2) y = NULL;   // the static world
            const int count = 1 + (int)(urand() * 6);
            dVector3 base, n;
            for (int i = 0; i < 3; i++) base[i] = 4 * urand();
            random_unit(n);
            const double spread = urand() < 0.3 ? 0.01 : 0.5;
            for (int k = 0; k < count && a.n < MAXC; k++) {
                dVector3 p;
                for (int i = 0; i < 3; i++) p[i] = base[i] + spread * (urand() - 0.5);
                make_contact(&a.c[a.n++], x, y, p, n);
                if (urand() < 0.1 && a.n < MAXC) {   // the same contact twice: a tie
                    a.c[a.n] = a.c[a.n - 1];
                    a.c[a.n++].ln = urand();
                }
            }
        }
        const int order = scene % 3;   // 0: runs; 1: split runs; 2: shuffled
        if (order == 1)
            for (int k = 0; k + 3 < a.n; k += 4) {
                tcontact t = a.c[k + 1];
                a.c[k + 1] = a.c[k + 3];
                a.c[k + 3] = t;
            }
        if (order == 2)
            for (int k = a.n - 1; k > 0; k--) {
                const int j = (int)(urand() * (k + 1));
                tcontact t = a.c[k];
                a.c[k] = a.c[j];
                a.c[j] = t;
            }
        w->step_count += 5;   // a cold start
        run_step(w, &a, NULL, &mismatches);
        // Step 2: the bodies move a little, the points by about the tolerance.
        for (int i = 0; i < NB; i++) {
            const dReal *p = dBodyGetPosition(body[i]);
            dBodySetPosition(body[i], p[0] + 0.01 * urand(), p[1], p[2] - 0.01 * urand());
            dQuaternion q;
            dCopyVector4(q, dBodyGetQuaternion(body[i]));
            q[1] += 0.01 * (urand() - 0.5);
            dBodySetQuaternion(body[i], q);
        }
        b.n = 0;
        for (int k = 0; k < a.n; k++) {
            if (urand() < 0.1) continue;   // gone
            tcontact *c = &b.c[b.n++];
            dVector3 p, n;
            const double move = urand() < 0.5 ? 0.001 : 0.1;
            for (int i = 0; i < 3; i++) p[i] = a.c[k].p[i] + move * (urand() - 0.5);
            dCopyVector3(n, a.c[k].n);
            if (urand() < 0.1) random_unit(n);   // turned
            make_contact(c, a.c[k].b0, a.c[k].b1, p, n);
            if (urand() < 0.05 && b.n < MAXC) b.c[b.n++] = *c;   // a duplicate
        }
        // Each pair's run started elsewhere, as box-box does now and then
        // (the quick match's guess then moves along).
        if (scene % 4 == 3)
            for (int k = 0; k < b.n;) {
                int n = 1;
                while (k + n < b.n && b.c[k + n].b0 == b.c[k].b0 && b.c[k + n].b1 == b.c[k].b1)
                    n++;
                static tcontact t[MAXC];
                const int shift = (int)(urand() * n);
                for (int i = 0; i < n; i++) t[i] = b.c[k + (i + shift) % n];
                memcpy(&b.c[k], t, sizeof(tcontact) * (size_t)n);
                k += n;
            }
        total += b.n;
        total_found += run_step(w, &b, &a, &mismatches);
    }
    CHECK(mismatches == 0);
    // Both outcomes were exercised.
    CHECK(total_found > total / 5 && total_found < total);
    dWorldDestroy(w);
    return 0;
}

// A body whose handle was reused (a new generation) is another body: none
// of the old contacts of its pairs match; the other pairs still do.
static int test_new_generation_starts_cold(void)
{
    dWorldID w = dWorldCreate();
    dBodyID x = dBodyCreate(w), y = dBodyCreate(w), z = dBodyCreate(w);
    dBodySetPosition(y, 0, 0, 1);
    dBodySetPosition(z, 3, 0, 0);
    static tstep a, b;
    static const dReal up[3] = { 0, 0, 1 };
    const dReal p0[3] = { 0.1, 0, 0.5 }, p1[3] = { -0.1, 0, 0.5 }, p2[3] = { 3, 0, -0.5 };
    a.n = 0;
    make_contact(&a.c[a.n++], x, y, p0, up);
    make_contact(&a.c[a.n++], x, y, p1, up);
    make_contact(&a.c[a.n++], z, NULL, p2, up);
    int mismatches = 0;
    run_step(w, &a, NULL, &mismatches);
    b = a;
    CHECK(run_step(w, &b, &a, &mismatches) == 3);
    y->hdr.generation++;   // as if y were destroyed and its memory made a new body
    a = b;
    CHECK(run_step(w, &a, &b, &mismatches) == 1);   // only z's contact
    CHECK(mismatches == 0);
    y->hdr.generation--;
    dWorldDestroy(w);
    return 0;
}

// The last step's contacts are only for the quick step right after it.
static int test_other_step_in_between_starts_cold(void)
{
    dWorldID w = dWorldCreate();
    dBodyID x = dBodyCreate(w);
    static tstep a, b;
    static const dReal up[3] = { 0, 0, 1 };
    const dReal p0[3] = { 0.1, 0, -0.5 };
    a.n = 0;
    make_contact(&a.c[a.n++], x, NULL, p0, up);
    int mismatches = 0;
    run_step(w, &a, NULL, &mismatches);
    b = a;
    w->step_count++;   // another stepper's step
    CHECK(run_step(w, &b, NULL, &mismatches) == 0);
    CHECK(mismatches == 0);
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_matches_the_plain_rule),
    TEST_CASE(test_new_generation_starts_cold),
    TEST_CASE(test_other_step_in_between_starts_cold),
    TEST_END
};
