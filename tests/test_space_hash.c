// SPDX-License-Identifier: BSD-3-Clause
//
// test_space_hash.c -- the hash space keeps its cells from one collision to
// the next (space_hash.c): through long random sequences of moves, resizes,
// adds, removes, destroys, enables and disables, level changes, planes,
// nested spaces and geoms sharing a body, every dSpaceCollide reports the
// pairs of a brute-force AABB test, each once, and dSpaceCollide2 (a geom, a
// space) too; the order of the pairs depends only on the geoms and their
// boxes (a space built afresh with the same geoms in the same order calls
// back in the same order), which is what replays and snapshots rely on; and
// geoms changing cells every step allocate nothing once the space is warm;
// geoms drifting a little (keeping some of their cells) order as afresh; a
// coarse level of a few geoms passed over after box tests calls back as its
// cells would (dxHashFewGeoms at 1 for the cells always).

#include "space_pairs.h"
#include "test.h"

#include "geom_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "xorshift.h"

// ---- recorded pairs -------------------------------------------------------------

static void number(dGeomID g, int i) { dGeomSetData(g, (void *)(intptr_t)i); }

// The brute-force pairs among the geoms of s (nested spaces as geoms).
static void brute_pairs(dSpaceID s, pairs *out)
{
    const int n = dSpaceGetNumGeoms(s);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            dGeomID a = dSpaceGetGeom(s, i), b = dSpaceGetGeom(s, j);
            if (expect_touch(a, b)) pairs_add(out, idx(a), idx(b));
        }
}

// dSpaceCollide of s reports the brute-force pairs, each once.
static int check_collide(dSpaceID s)
{
    pairs want = { 0 }, got = { 0 };
    brute_pairs(s, &want);
    dSpaceCollide(s, &got, record);
    CHECK(pairs_same(&got, &want) && pairs_unique(&got));
    free(want.p);
    free(got.p);
    return 0;
}

// dSpaceCollide2(o, s) reports o against each geom of s it touches, o first.
static int check_collide2(dGeomID o, dSpaceID s)
{
    pairs want = { 0 }, got = { 0 };
    for (int i = 0; i < dSpaceGetNumGeoms(s); i++) {
        dGeomID g = dSpaceGetGeom(s, i);
        if (expect_touch(o, g)) pairs_add(&want, idx(o), idx(g));
    }
    dSpaceCollide2(o, (dGeomID)s, &got, record);
    CHECK(pairs_same(&got, &want) && pairs_unique(&got));
    for (int i = 0; i < got.n; i++) CHECK(got.p[i][0] == idx(o));
    free(want.p);
    free(got.p);
    return 0;
}

// ---- random edits ---------------------------------------------------------------

static int next_number = 1;

// A sphere, box or capsule of size 0.05 .. 6 (every 40th 60 long, a few
// levels up) somewhere in +-20.
static dGeomID random_geom(dSpaceID s)
{
    dGeomID g;
    const double k = rnd(0, 3);
    const double big = rnd(0, 40) < 1 ? 10 : 1;
    if (k < 1) {
        g = dCreateSphere(s, (dReal)(big * rnd(0.025, 3)));
    } else if (k < 2) {
        g = dCreateBox(s, (dReal)(big * rnd(0.05, 6)), (dReal)rnd(0.05, 6), (dReal)rnd(0.05, 6));
    } else {
        g = dCreateCapsule(s, (dReal)rnd(0.05, 1), (dReal)(big * rnd(0.1, 4)));
        dMatrix3 R;
        dRFromAxisAndAngle(R, (dReal)rnd(-1, 1), (dReal)rnd(-1, 1), 1, (dReal)rnd(0, 3));
        dGeomSetRotation(g, R);
    }
    dGeomSetPosition(g, (dReal)rnd(-20, 20), (dReal)rnd(-20, 20), (dReal)rnd(-20, 20));
    number(g, next_number++);
    return g;
}

// A placeable geom of s other than the first `keep` (planes, the nested space).
static dGeomID pick(dSpaceID s, int keep)
{
    const int n = dSpaceGetNumGeoms(s);
    if (n <= keep) return NULL;
    dGeomID g = dSpaceGetGeom(s, keep + (int)rnd(0, n - keep));
    return dGeomGetClass(g) == dPlaneClass || dGeomIsSpace(g) ? NULL : g;
}

// One step of edits to s: moves (a little, far, onto the grid: boxes that
// touch cell boundaries), resizes, destroys, adds, a geom taken out and put
// back (last in space order), enables and disables, bits changed.
static void edit(dSpaceID s, int keep, int moves)
{
    for (int m = 0; m < moves; m++) {
        dGeomID g = pick(s, keep);
        if (!g || dGeomGetBody(g)) continue;
        const dReal *p = dGeomGetPosition(g);
        const double r = rnd(0, 1);
        if (r < 0.1) {
            dGeomSetPosition(g, (dReal)rnd(-20, 20), (dReal)rnd(-20, 20), (dReal)rnd(-20, 20));
        } else if (r < 0.2) {
            dGeomSetPosition(g, (dReal)floor(p[0]), (dReal)floor(p[1]), (dReal)floor(p[2]));
        } else if (r < 0.25 && dGeomGetClass(g) == dBoxClass) {
            dGeomBoxSetLengths(g, (dReal)rnd(0.05, 6), (dReal)rnd(0.05, 6), (dReal)rnd(0.05, 6));
        } else if (r < 0.3 && dGeomGetClass(g) == dSphereClass) {
            dGeomSphereSetRadius(g, (dReal)rnd(0.025, 3));
        } else {
            dGeomSetPosition(g, p[0] + (dReal)rnd(-0.3, 0.3), p[1] + (dReal)rnd(-0.3, 0.3),
                             p[2] + (dReal)rnd(-0.3, 0.3));
        }
    }
    const double r = rnd(0, 1);
    dGeomID g = pick(s, keep);
    if (!g) {
        random_geom(s);
    } else if (r < 0.15) {
        if (!dGeomGetBody(g)) dGeomDestroy(g);
    } else if (r < 0.4) {
        random_geom(s);
    } else if (r < 0.55) {
        dSpaceRemove(s, g);
        dSpaceAdd(s, g);
    } else if (r < 0.7) {
        if (dGeomIsEnabled(g)) dGeomDisable(g);
        else dGeomEnable(g);
    } else if (r < 0.75) {
        dGeomSetCategoryBits(g, (unsigned long)rnd(1, 4));
        dGeomSetCollideBits(g, (unsigned long)rnd(1, 4));
    }
}

static int test_random_edits_find_the_brute_force_pairs_every_step(void)
{
    // Two planes and a nested simple space first; three geoms on one body
    // (never reported together) moved with it; 600 steps at different
    // levels, the levels changed now and then.
    static const int levels[][2] = { { -3, 10 }, { -1, 1 }, { 0, 0 }, { -6, 4 }, { 3, 8 } };
    rng_state = 0x243F6A8885A308D3u;
    dWorldID w = dWorldCreate();
    dSpaceID s = dHashSpaceCreate(0), inner = dSimpleSpaceCreate(s);
    dGeomID probe = dCreateSphere(0, 2);
    dSpaceID outside = dSimpleSpaceCreate(0);
    number(probe, 100000);
    number((dGeomID)inner, next_number++);
    dGeomID plane = dCreatePlane(s, 0, 0, 1, -15);
    number(plane, next_number++);
    number(dCreatePlane(s, 1, 0, 0, 18), next_number++);
    const int keep = 3;
    dBodyID body = dBodyCreate(w);
    for (int i = 0; i < 3; i++) dGeomSetBody(random_geom(s), body);
    for (int i = 0; i < 200; i++) random_geom(s);
    for (int i = 0; i < 20; i++) random_geom(outside);
    int max_pairs = 0, level_changes = 0;

    for (int step = 0; step < 600; step++) {
        edit(s, keep, 1 + (int)rnd(0, 30));
        if (step % 50 == 49) {
            const int *lv = levels[(step / 50) % 5];
            dHashSpaceSetLevels(s, lv[0], lv[1]);
            level_changes++;
        }
        if (step % 9 == 0) {   // the nested space fills and empties
            if (dSpaceGetNumGeoms(inner) < 3) random_geom(inner);
            else dGeomDestroy(dSpaceGetGeom(inner, 0));
        }
        dBodySetPosition(body, (dReal)rnd(-15, 15), (dReal)rnd(-15, 15), (dReal)rnd(-15, 15));
        if (check_collide(s)) return 1;
        dGeomSetPosition(probe, (dReal)rnd(-20, 20), (dReal)rnd(-20, 20), (dReal)rnd(-20, 20));
        if (check_collide2(probe, s)) return 1;
        if (check_collide2(plane, s)) return 1;   // a member: (plane, plane) too
        if (step % 10 == 0) {   // space against space: the smaller one is walked
            pairs want = { 0 }, got = { 0 };
            for (int i = 0; i < dSpaceGetNumGeoms(outside); i++)
                for (int j = 0; j < dSpaceGetNumGeoms(s); j++) {
                    dGeomID a = dSpaceGetGeom(outside, i), b = dSpaceGetGeom(s, j);
                    if (expect_touch(a, b)) pairs_add(&want, idx(a), idx(b));
                }
            dSpaceCollide2((dGeomID)outside, (dGeomID)s, &got, record);
            CHECK(pairs_same(&got, &want) && pairs_unique(&got));
            free(want.p);
            free(got.p);
            edit(outside, 0, 10);
        }
        pairs all = { 0 };
        brute_pairs(s, &all);
        if (all.n > max_pairs) max_pairs = all.n;
        free(all.p);
    }
    // Not vacuous: the scene had many pairs and changed a lot.
    CHECK(max_pairs > 100);
    CHECK(dSpaceGetNumGeoms(s) > 100);
    CHECK(level_changes == 12);
    dGeomDestroy(probe);
    dSpaceDestroy(outside);
    dSpaceDestroy(s);
    dWorldDestroy(w);
    return 0;
}

// ---- the order depends only on the geoms ---------------------------------------

// A geom like g (class, size, pose, enabled, bits, number) in s.
static dGeomID twin(dSpaceID s, dGeomID g)
{
    dGeomID t;
    switch (dGeomGetClass(g)) {
    case dSphereClass: t = dCreateSphere(s, dGeomSphereGetRadius(g)); break;
    case dBoxClass: {
        dVector3 l;
        dGeomBoxGetLengths(g, l);
        t = dCreateBox(s, l[0], l[1], l[2]);
        break;
    }
    case dCapsuleClass: {
        dReal r, len;
        dGeomCapsuleGetParams(g, &r, &len);
        t = dCreateCapsule(s, r, len);
        break;
    }
    default: {
        dVector4 p;
        dGeomPlaneGetParams(g, p);
        t = dCreatePlane(s, p[0], p[1], p[2], p[3]);
        break;
    }
    }
    if (dGeomGetClass(g) != dPlaneClass) {
        const dReal *p = dGeomGetPosition(g);
        dGeomSetPosition(t, p[0], p[1], p[2]);
        dGeomSetRotation(t, dGeomGetRotation(g));
    }
    if (!dGeomIsEnabled(g)) dGeomDisable(t);
    dGeomSetCategoryBits(t, dGeomGetCategoryBits(g));
    dGeomSetCollideBits(t, dGeomGetCollideBits(g));
    number(t, idx(g));
    return t;
}

// s calls back in the order of a hash space made afresh from its geoms.
static int check_order_is_fresh(dSpaceID s, int minlevel, int maxlevel)
{
    dSpaceID fresh = dHashSpaceCreate(0);
    dHashSpaceSetLevels(fresh, minlevel, maxlevel);
    for (int i = 0; i < dSpaceGetNumGeoms(s); i++) twin(fresh, dSpaceGetGeom(s, i));
    pairs a = { 0 }, b = { 0 };
    dSpaceCollide(s, &a, record);
    dSpaceCollide(fresh, &b, record);
    CHECK(a.n == b.n && a.n > 0);
    CHECK(memcmp(a.p, b.p, (size_t)a.n * sizeof *a.p) == 0);
    free(a.p);
    free(b.p);
    dSpaceDestroy(fresh);
    return 0;
}

static int test_pair_order_depends_only_on_the_geoms(void)
{
    // After every few steps of edits, the kept space and one made afresh
    // with the same geoms in the same order give the same sequence of
    // callbacks (the history of moves and edits leaves no trace).
    rng_state = 0x13198A2E03707344u;
    dSpaceID s = dHashSpaceCreate(0);
    number(dCreatePlane(s, 0, 0, 1, -15), next_number++);
    for (int i = 0; i < 300; i++) random_geom(s);
    int lo = -3, hi = 10;
    for (int step = 0; step < 200; step++) {
        edit(s, 1, 1 + (int)rnd(0, 60));
        if (step == 100) {
            lo = -2;
            hi = 5;
            dHashSpaceSetLevels(s, lo, hi);
        }
        pairs scratch = { 0 };
        dSpaceCollide(s, &scratch, record);   // the cells follow the edits
        free(scratch.p);
        if (step % 5 == 4 && check_order_is_fresh(s, lo, hi)) return 1;
    }
    dSpaceDestroy(s);
    return 0;
}

// ---- collisions nested in callbacks --------------------------------------------

// The pairs of one collision and of the collisions nested in its callbacks.
typedef struct nesting {
    dSpaceID s;
    pairs outer;        // the outer collision's callbacks, in order
    pairs inner[4];     // the first callbacks' nested dSpaceCollide of s
    int n_inner;
} nesting;

// Records the pair; the first four callbacks collide the whole space again,
// each into its own list.
static void nesting_callback(void *data, dGeomID a, dGeomID b)
{
    nesting *m = data;
    record(&m->outer, a, b);
    if (m->n_inner < 4) dSpaceCollide(m->s, &m->inner[m->n_inner++], record);
}

// 1 if the two lists hold the same pairs in the same order.
static int same_sequence(const pairs *x, const pairs *y)
{
    return x->n == y->n && (x->n == 0 || memcmp(x->p, y->p, sizeof *x->p * (size_t)x->n) == 0);
}

static int test_collisions_nested_in_callbacks_see_the_same_pairs(void)
{
    // A collision of the space nested in a callback of its own collision
    // (which lists a geom's partners before calling back) or of a
    // dSpaceCollide2 against it (made right after the geoms moved) reports
    // what a collision alone does, in the same order, and leaves the outer
    // one's sequence intact. Geoms crowded so that each has many partners.
    rng_state = 0x452821E638D01377u;
    dSpaceID s = dHashSpaceCreate(0);
    for (int i = 0; i < 200; i++) {
        dGeomID g = dCreateSphere(s, (dReal)rnd(0.2, 0.6));
        number(g, next_number++);
        dGeomSetPosition(g, (dReal)rnd(-3, 3), (dReal)rnd(-3, 3), (dReal)rnd(-3, 3));
    }
    dGeomID probe = dCreateSphere(0, 2);
    number(probe, next_number++);
    for (int round = 0; round < 3; round++) {
        for (int i = 0; i < dSpaceGetNumGeoms(s); i += 3) {   // moved: the cells are updated
            dGeomID g = dSpaceGetGeom(s, i);
            const dReal *p = dGeomGetPosition(g);
            dGeomSetPosition(g, p[0] + (dReal)rnd(-0.3, 0.3), p[1], p[2]);
        }
        nesting m = { s, { 0 }, { { 0 } }, 0 };
        if (round == 1) dSpaceCollide2(probe, (dGeomID)s, &m, nesting_callback);
        else dSpaceCollide(s, &m, nesting_callback);
        pairs alone = { 0 };
        if (round == 1) dSpaceCollide2(probe, (dGeomID)s, &alone, record);
        else dSpaceCollide(s, &alone, record);
        CHECK(alone.n > 4 && same_sequence(&m.outer, &alone));
        pairs whole = { 0 };
        dSpaceCollide(s, &whole, record);
        CHECK(m.n_inner == 4);
        for (int k = 0; k < m.n_inner; k++) {
            CHECK(same_sequence(&m.inner[k], &whole));
            pairs_free(&m.inner[k]);
        }
        if (check_collide(s)) return 1;
        pairs_free(&m.outer);
        pairs_free(&alone);
        pairs_free(&whole);
    }
    dGeomDestroy(probe);
    dSpaceDestroy(s);
    return 0;
}

// ---- no allocation once warm ----------------------------------------------------

static int test_geoms_changing_cells_allocate_nothing_once_warm(void)
{
    // 400 spheres that every step jump between two places a cell apart
    // (every geom changes cells every step), with collisions and queries.
    dSpaceID s = dHashSpaceCreate(0);
    dGeomID g[400];
    rng_state = 77;
    for (int i = 0; i < 400; i++) {
        g[i] = dCreateSphere(s, (dReal)rnd(0.05, 0.5));
        number(g[i], i + 1);
    }
    dGeomID probe = dCreateBox(0, 2, 2, 2);
    number(probe, 1000);
    pairs got = { 0 };
    int moved_pairs = 0;
    for (int step = 0; step < 8; step++) {
        if (step == 4) test_count_allocations();
        const dReal shift = (dReal)(step % 2);
        for (int i = 0; i < 400; i++)
            dGeomSetPosition(g[i], (dReal)(i % 20) * REAL(0.7) + shift,
                             (dReal)(i / 20) * REAL(0.7) + shift, shift);
        got.n = 0;
        dSpaceCollide(s, &got, record);
        moved_pairs += got.n;
        dSpaceCollide2(probe, (dGeomID)s, &got, record);
    }
    CHECK(test_allocations_counted() == 0);
    CHECK(moved_pairs > 0);
    free(got.p);
    dGeomDestroy(probe);
    dSpaceDestroy(s);
    return 0;
}

// ---- levels changed from the callback ---------------------------------------------

typedef struct relevel_call {
    dSpaceID s;
    pairs got;
} relevel_call;

static void relevel_on_first(void *data, dGeomID a, dGeomID b)
{
    relevel_call *rc = data;
    if (rc->got.n == 0) dHashSpaceSetLevels(rc->s, 0, 0);
    pairs_add(&rc->got, idx(a), idx(b));
}

static int test_levels_changed_by_the_callback_take_effect_after_it(void)
{
    // The collision in progress finishes with the cells it started with
    // (every pair still found once); the next one uses the new levels.
    rng_state = 5;
    dSpaceID s = dHashSpaceCreate(0);
    for (int i = 0; i < 150; i++) random_geom(s);
    pairs want = { 0 };
    brute_pairs(s, &want);
    relevel_call rc = { s, { 0 } };
    dSpaceCollide(s, &rc, relevel_on_first);
    CHECK(pairs_same(&rc.got, &want) && pairs_unique(&rc.got));
    int lo, hi;
    dHashSpaceGetLevels(s, &lo, &hi);
    CHECK(lo == 0 && hi == 0);
    if (check_collide(s)) return 1;
    if (check_order_is_fresh(s, 0, 0)) return 1;
    free(want.p);
    free(rc.got.p);
    dSpaceDestroy(s);
    return 0;
}

static int test_geom_shrinking_after_minlevel_lowered_orders_as_fresh(void)
{
    // a sits at level -3, the old minlevel, with a side in (2^-4, 2^-3]: it
    // stays there when minlevel drops to -5. When it then shrinks to a side
    // of 0.02 within the same cell, it belongs at level -5, where it meets b
    // through b's coarser cell (a first), not in a shared cell (b first).
    dSpaceID s = dHashSpaceCreate(0);
    dGeomID a = dCreateSphere(s, REAL(0.05));
    dGeomID b = dCreateSphere(s, REAL(0.05));
    number(a, 1);
    number(b, 2);
    dGeomSetPosition(a, REAL(0.0625), REAL(0.0625), REAL(0.0625));
    dGeomSetPosition(b, REAL(0.07), REAL(0.06), REAL(0.0625));
    pairs got = { 0 };
    dSpaceCollide(s, &got, record);
    dHashSpaceSetLevels(s, -5, 10);
    dSpaceCollide(s, &got, record);
    dGeomSphereSetRadius(a, REAL(0.01));
    dSpaceCollide(s, &got, record);
    free(got.p);
    if (check_order_is_fresh(s, -5, 10)) return 1;
    dSpaceDestroy(s);
    return 0;
}

static int test_box_reaching_a_third_cell_goes_a_level_up(void)
{
    // A sphere of radius 1/2 + 2^-53 at (1/2, 1/2, 1/2) has the box
    // [-2^-53, 1] on every axis (1/2 + r rounds to 1) and a side that rounds
    // to 1 = 2^0; at level 0 it would touch cells -1, 0 and 1 on each axis,
    // 27 cells where a geom has room for 8 entries (the neighbours' entries
    // were overwritten, and the array overrun). It goes to level 1 and meets
    // its neighbours like any geom, in the order of a space made afresh.
    // (In single precision the radius rounds to 1/2: two cells, the same
    // checks.)
    rng_state = 11;
    dSpaceID s = dHashSpaceCreate(0);
    dHashSpaceSetLevels(s, -3, 10);
    dGeomID big = dCreateSphere(s, REAL(0.5) + (dReal)0x1p-53);   // first: slot 0
    number(big, 0);
    dGeomSetPosition(big, REAL(0.5), REAL(0.5), REAL(0.5));
    for (int i = 1; i <= 40; i++) {
        dGeomID g = dCreateSphere(s, REAL(0.1));
        number(g, i);
        dGeomSetPosition(g, (dReal)rnd(-0.2, 1.2), (dReal)rnd(-0.2, 1.2), (dReal)rnd(-0.2, 1.2));
    }
    for (int step = 1; step <= 3; step++) {
        if (check_collide(s)) return 1;
        if (check_order_is_fresh(s, -3, 10)) return 1;
        dGeomSetPosition(dSpaceGetGeom(s, step), REAL(0.5), REAL(0.5), REAL(0.1) * step);
    }
    dSpaceDestroy(s);
    return 0;
}

// ---- geoms drifting across cell boundaries -------------------------------------

static int test_geoms_drifting_across_cells_keep_the_fresh_order(void)
{
    // 150 boxes of 0.3 .. 0.95 (level 0, one or two cells per axis) packed
    // in a 4 m cube, a fifth of them nudged by up to 0.15 each step (the
    // update moves them one by one): a box keeps the cells it stays in,
    // leaves some, enters others, spreads from one cell to two on an axis or
    // back. Every step: the brute-force pairs, in the order of a space made
    // afresh, and a probe's pairs.
    rng_state = 0x452821E638D01377u;
    dSpaceID s = dHashSpaceCreate(0);
    dGeomID g[150];
    for (int i = 0; i < 150; i++) {
        g[i] = dCreateBox(s, (dReal)rnd(0.3, 0.95), (dReal)rnd(0.3, 0.95), (dReal)rnd(0.3, 0.95));
        number(g[i], next_number++);
        dGeomSetPosition(g[i], (dReal)rnd(-2, 2), (dReal)rnd(-2, 2), (dReal)rnd(-2, 2));
    }
    dGeomID probe = dCreateSphere(0, REAL(0.7));
    number(probe, 100000);
    for (int step = 0; step < 120; step++) {
        for (int m = 0; m < 30; m++) {
            dGeomID h = g[(int)rnd(0, 150)];
            const dReal *p = dGeomGetPosition(h);
            dGeomSetPosition(h, p[0] + (dReal)rnd(-0.15, 0.15), p[1] + (dReal)rnd(-0.15, 0.15),
                             p[2] + (dReal)rnd(-0.15, 0.15));
        }
        if (check_collide(s)) return 1;
        if (check_order_is_fresh(s, -3, 10)) return 1;
        dGeomSetPosition(probe, (dReal)rnd(-2, 2), (dReal)rnd(-2, 2), (dReal)rnd(-2, 2));
        if (check_collide2(probe, s)) return 1;
    }
    dGeomDestroy(probe);
    dSpaceDestroy(s);
    return 0;
}

// ---- a level of one geom ----------------------------------------------------------

static int test_a_level_of_one_geom_meets_the_geoms_its_box_touches(void)
{
    // A flat 30 x 30 x 1 box (alone at level 5, as a terrain) and 120 small
    // spheres above, across and below its faces and around its edges and
    // corners, moved every step; a second run with a twin of the terrain
    // (two geoms at level 5, through the cells again). Every step: the
    // brute-force pairs, each once, in the order of a space made afresh.
    for (int twins = 1; twins <= 2; twins++) {
        rng_state = 0xA4093822299F31D0u + (uint64_t)twins;
        dSpaceID s = dHashSpaceCreate(0);
        for (int t = 0; t < twins; t++) {
            dGeomID terrain = dCreateBox(s, 30, 30, 1);
            number(terrain, next_number++);
            dGeomSetPosition(terrain, (dReal)(3 * t), 0, 0);
        }
        for (int i = 0; i < 120; i++) {
            dGeomID g = dCreateSphere(s, (dReal)rnd(0.05, 0.4));
            number(g, next_number++);
        }
        int touching = 0;
        for (int step = 0; step < 40; step++) {
            for (int i = twins; i < dSpaceGetNumGeoms(s); i++)
                dGeomSetPosition(dSpaceGetGeom(s, i), (dReal)rnd(-16, 16), (dReal)rnd(-16, 16),
                                 (dReal)rnd(-1.5, 1.5));
            if (check_collide(s)) return 1;
            if (check_order_is_fresh(s, -3, 10)) return 1;
            pairs all = { 0 };
            brute_pairs(s, &all);
            touching += all.n;
            free(all.p);
        }
        CHECK(touching > 40 * 40);   // not vacuous: most steps have many pairs with it
        dSpaceDestroy(s);
    }
    return 0;
}

// ---- a few geoms on a coarse level -------------------------------------------------

// What the callbacks of the walls scene share: the pairs in order, the
// coarse geoms (walls and posts), and in the moving mode the space, for a
// nested collision and for moving geoms from the callback.
typedef struct walls_call {
    pairs *out;
    dSpaceID s;
    dGeomID *coarse;
    int n_coarse;
    int moving;      // the callbacks move geoms and collide the space again
    int calls;       // callbacks of this dSpaceCollide or dSpaceCollide2
    int moved;       // this collision's callbacks moved the geoms
} walls_call;

// Numbers below this are the coarse geoms'.
#define SMALL_NUMBERS 1000

// Records the pair. In the moving mode the first callback of a collision
// collides the space again (into the same list), and the first from the
// seventh on between a small geom a and a coarse one b moves every coarse
// geom but b onto a, and a a little, reading their boxes (the cells then no
// longer describe them).
static void walls_callback(void *data, dGeomID a, dGeomID b)
{
    walls_call *wc = data;
    pairs_add(wc->out, idx(a), idx(b));
    if (!wc->moving) return;
    if (wc->calls++ == 0) {
        walls_call inner = { wc->out, wc->s, wc->coarse, wc->n_coarse, 0, 0, 0 };
        dSpaceCollide(wc->s, &inner, walls_callback);
    }
    if (wc->calls < 7 || wc->moved || idx(a) < SMALL_NUMBERS || idx(b) >= SMALL_NUMBERS) return;
    wc->moved = 1;
    const dReal *p = dGeomGetPosition(a);
    const dReal at[3] = { p[0], p[1], p[2] };
    dReal box[6];
    for (int i = 0; i < wc->n_coarse; i++) {
        if (wc->coarse[i] == b) continue;
        dGeomSetPosition(wc->coarse[i], at[0], at[1], at[2]);
        dGeomGetAABB(wc->coarse[i], box);
    }
    if (!dGeomGetBody(a)) {
        dGeomSetPosition(a, at[0] + REAL(0.25), at[1], at[2]);
        dGeomGetAABB(a, box);
    }
}

// A small sphere at a random place in +-16, numbered from SMALL_NUMBERS.
static dGeomID small_sphere(dSpaceID s, int *next)
{
    dGeomID g = dCreateSphere(s, (dReal)rnd(0.05, 0.45));
    dGeomSetPosition(g, (dReal)rnd(-16, 16), (dReal)rnd(-16, 16), (dReal)rnd(-16, 16));
    number(g, (*next)++);
    return g;
}

// A random small geom of s (a sphere numbered from SMALL_NUMBERS).
static dGeomID pick_small(dSpaceID s)
{
    for (;;) {
        dGeomID g = dSpaceGetGeom(s, (int)rnd(0, dSpaceGetNumGeoms(s)));
        if (idx(g) >= SMALL_NUMBERS) return g;
    }
}

// One collision of the walls scene: dSpaceCollide or dSpaceCollide2 of o1
// and o2, its callbacks after a (0, step) mark.
static void walls_collide(walls_call *wc, dGeomID o1, dGeomID o2, int step)
{
    pairs_add(wc->out, 0, step);
    wc->calls = wc->moved = 0;
    if (o1 == o2) dSpaceCollide((dSpaceID)o1, wc, walls_callback);
    else dSpaceCollide2(o1, o2, wc, walls_callback);
}

// The walls scene with dxHashFewGeoms = few: n_walls boxes 17 to 30 long
// (level 5, across the borders of its cells at 0 and +-32) and K + 3 -
// n_walls posts 4.1 to 7.9 wide (level 3), among 300 spheres of radius 0.05
// to 0.45 (every seventh disabled) that move every step, some across the
// coarse cells' borders. Every step one wall moves, a sphere is destroyed
// and another made, one is disabled or enabled, and every third step a wall
// and a post leave the space and come back (last in space order). The
// callbacks of every collision in order into out: of the space, of a probe
// against it, of a small simple space against it, of a wall against it.
static void walls_run(int few, int n_walls, int moving, pairs *out)
{
    const int K = dxHashFewGeoms;
    dxHashFewGeoms = few;
    rng_state = 0x082EFA98EC4E6C89u + (uint64_t)n_walls;
    dSpaceID s = dHashSpaceCreate(0), group = dSimpleSpaceCreate(0);
    dGeomID coarse[64];
    const int n_coarse = K + 3;
    for (int i = 0; i < n_coarse; i++) {
        const int wall = i < n_walls;
        const double side = wall ? rnd(0.5, 4) : rnd(4.1, 7.9);
        const double len = wall ? rnd(17, 30) : side;
        coarse[i] = i % 3 == 0 ? dCreateBox(s, (dReal)len, (dReal)side, (dReal)side)
                  : i % 3 == 1 ? dCreateBox(s, (dReal)side, (dReal)len, (dReal)side)
                               : dCreateBox(s, (dReal)side, (dReal)side, (dReal)len);
        dGeomSetPosition(coarse[i], (dReal)rnd(-20, 20), (dReal)rnd(-20, 20), (dReal)rnd(-20, 20));
        number(coarse[i], i + 1);
    }
    int next = SMALL_NUMBERS;
    for (int i = 0; i < 300; i++) {
        dGeomID g = small_sphere(s, &next);
        if (i % 7 == 0) dGeomDisable(g);
    }
    for (int i = 0; i < 5; i++) small_sphere(group, &next);
    dGeomID probe = dCreateSphere(0, REAL(0.3));
    number(probe, next++);
    walls_call wc = { out, s, coarse, n_coarse, moving, 0, 0 };
    for (int step = 1; step <= 25; step++) {
        for (int i = 0; i < dSpaceGetNumGeoms(s); i++) {
            dGeomID g = dSpaceGetGeom(s, i);
            if (idx(g) < SMALL_NUMBERS) continue;
            const dReal *p = dGeomGetPosition(g);
            dGeomSetPosition(g, p[0] + (dReal)rnd(-0.5, 0.5), p[1] + (dReal)rnd(-0.5, 0.5),
                             p[2] + (dReal)rnd(-0.5, 0.5));
        }
        dGeomID w = coarse[step % n_walls];
        const dReal *p = dGeomGetPosition(w);
        dGeomSetPosition(w, p[0] + (dReal)rnd(-1, 1), p[1] + (dReal)rnd(-1, 1), p[2]);
        dGeomDestroy(pick_small(s));
        small_sphere(s, &next);
        dGeomID t = pick_small(s);
        if (dGeomIsEnabled(t)) dGeomDisable(t);
        else dGeomEnable(t);
        if (step % 3 == 0) {
            dGeomID post = coarse[n_walls + step % (n_coarse - n_walls)];
            dSpaceRemove(s, w);
            dSpaceAdd(s, w);
            dSpaceRemove(s, post);
            dSpaceAdd(s, post);
        }
        if (step % 4 == 0) {
            if (dGeomIsEnabled(coarse[0])) dGeomDisable(coarse[0]);
            else dGeomEnable(coarse[0]);
        }
        walls_collide(&wc, (dGeomID)s, (dGeomID)s, step);
        dGeomSetPosition(probe, (dReal)rnd(-20, 20), (dReal)rnd(-20, 20), (dReal)rnd(-20, 20));
        walls_collide(&wc, probe, (dGeomID)s, step);
        walls_collide(&wc, (dGeomID)group, (dGeomID)s, step);
        walls_collide(&wc, w, (dGeomID)s, step);
    }
    dGeomDestroy(probe);
    dSpaceDestroy(group);
    dSpaceDestroy(s);
    dxHashFewGeoms = K;
}

static int test_levels_of_few_geoms_call_back_as_through_the_cells(void)
{
    // The walls scene with levels of 1 .. K + 2 geoms, K = dxHashFewGeoms:
    // with a level of at most K passed over when none of its boxes meets a
    // geom's (the default) and through the cells always (1), the same
    // callbacks in the same order, through dSpaceCollide and dSpaceCollide2,
    // with callbacks that only record and with callbacks that collide the
    // space again and move geoms mid-walk.
    const int K = dxHashFewGeoms;
    CHECK(K >= 2 && K + 3 <= 64);
    for (int moving = 0; moving <= 1; moving++) {
        for (int n_walls = 1; n_walls <= K + 2; n_walls++) {
            pairs cells = { 0 }, few = { 0 };
            const unsigned long t0 = dx_aabb_tests;
            walls_run(1, n_walls, moving, &cells);
            const unsigned long t1 = dx_aabb_tests;
            walls_run(K, n_walls, moving, &few);
            const unsigned long t2 = dx_aabb_tests;
            CHECK(same_sequence(&cells, &few));
            // Not vacuous: many pairs of a small geom with a coarse one (as
            // query_levels reports them), and a level of 2 .. K geoms tested
            // box by box (another count of box tests).
            int coarse_pairs = 0;
            for (int i = 0; i < cells.n; i++)
                coarse_pairs += cells.p[i][0] >= SMALL_NUMBERS && cells.p[i][1] > 0 &&
                                cells.p[i][1] < SMALL_NUMBERS;
            CHECK(coarse_pairs > 50);
            if (n_walls >= 2 && n_walls <= K + 1) CHECK(t1 - t0 != t2 - t1);
            pairs_free(&cells);
            pairs_free(&few);
        }
    }
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_random_edits_find_the_brute_force_pairs_every_step),
    TEST_CASE(test_pair_order_depends_only_on_the_geoms),
    TEST_CASE(test_collisions_nested_in_callbacks_see_the_same_pairs),
    TEST_CASE(test_geoms_changing_cells_allocate_nothing_once_warm),
    TEST_CASE(test_levels_changed_by_the_callback_take_effect_after_it),
    TEST_CASE(test_geom_shrinking_after_minlevel_lowered_orders_as_fresh),
    TEST_CASE(test_box_reaching_a_third_cell_goes_a_level_up),
    TEST_CASE(test_geoms_drifting_across_cells_keep_the_fresh_order),
    TEST_CASE(test_a_level_of_one_geom_meets_the_geoms_its_box_touches),
    TEST_CASE(test_levels_of_few_geoms_call_back_as_through_the_cells),
    TEST_END
};
