// SPDX-License-Identifier: BSD-3-Clause
//
// test_space.c -- spaces (guide 10.3, 10.5, 10.6): the simple, hash,
// quadtree and sweep-and-prune spaces report the same pairs as a brute-force
// AABB test, each once; the hash and quadtree spaces do near-linear work on
// spread-out scenes (counted with dx_aabb_tests, never timed); the
// sweep-and-prune space keeps its pairs exact through many moves, adds,
// removes, equal ends, and NaN, empty and infinite boxes; bits, disabled
// geoms, geoms of one body and nested spaces; the cases of dSpaceCollide2;
// locking during the callback; cleanup; geom order; hash levels; space
// bounding boxes; bad input. White-box: needs geom_internal.h for the counter.

#include "space_pairs.h"
#include "test.h"

#include "geom_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "xorshift.h"

enum { SIMPLE, HASH, QUADTREE, SAP, N_TYPES };

// A quadtree around the random scenes below (+-25 with a few larger geoms).
static dSpaceID make_space(int type, dSpaceID parent)
{
    static const dVector3 center = { 0, 0, 0, 0 }, extents = { 30, 30, 30, 0 };
    switch (type) {
    case SIMPLE: return dSimpleSpaceCreate(parent);
    case HASH: return dHashSpaceCreate(parent);
    case SAP: return dSweepAndPruneSpaceCreate(parent, dSAP_AXES_XZY);
    default: return dQuadTreeSpaceCreate(parent, center, extents, 5);
    }
}

// ---- recorded pairs ---------------------------------------------------------

static void brute_pairs(dGeomID *g, int n, pairs *out)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (expect_touch(g[i], g[j])) pairs_add(out, idx(g[i]), idx(g[j]));
}

// ---- scenes -------------------------------------------------------------------

static void number(dGeomID g, int i) { dGeomSetData(g, (void *)(intptr_t)(i + 1)); }

// n geoms in +-25: spheres and rotated boxes of sides 0.2 .. 4, every 150th
// a big one (sphere of radius 12, a 3000-long box beyond the hash space's top
// level 2^10, a flat 40 x 40 slab), and geom 0 a plane (z < -20 solid).
static void random_scene(dSpaceID s, dGeomID *g, int n, uint64_t seed)
{
    rng_state = seed;
    for (int i = 0; i < n; i++) {
        if (i == 0) {
            g[i] = dCreatePlane(s, 0, 0, 1, -20);
            number(g[i], i);
            continue;
        }
        int kind = (int)rnd(0, 2);
        if (i % 150 == 1) {
            int big = (i / 150) % 3;
            if (big == 0) g[i] = dCreateSphere(s, 12);
            else if (big == 1) g[i] = dCreateBox(s, 3000, 1, 1);
            else g[i] = dCreateBox(s, 40, 40, 0.5);
        } else if (kind == 0) {
            g[i] = dCreateSphere(s, rnd(0.1, 2));
        } else {
            g[i] = dCreateBox(s, rnd(0.2, 4), rnd(0.2, 4), rnd(0.2, 4));
            dMatrix3 R;
            dRFromAxisAndAngle(R, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) + 2, rnd(0, 3));
            dGeomSetRotation(g[i], R);
        }
        dGeomSetPosition(g[i], rnd(-25, 25), rnd(-25, 25), rnd(-25, 25));
        number(g[i], i);
    }
}

// Boxes whose AABBs touch exactly (closed boxes overlap): unit cubes on an
// integer grid, 2-cubes on the even grid beside them, and 0.5-cubes on the
// half grid, straddling and meeting cell and block boundaries of every level.
static int touching_scene(dSpaceID s, dGeomID *g)
{
    int n = 0;
    for (int x = -3; x < 3; x++)
        for (int y = -3; y < 3; y++)
            for (int z = -2; z < 2; z++) {
                g[n] = dCreateBox(s, 1, 1, 1);
                dGeomSetPosition(g[n], x + 0.5, y + 0.5, z + 0.5);
                number(g[n], n);
                n++;
            }
    for (int x = 3; x < 9; x += 2)
        for (int y = -4; y < 4; y += 2) {
            g[n] = dCreateBox(s, 2, 2, 2);
            dGeomSetPosition(g[n], x + 1, y + 1, 1);
            number(g[n], n);
            n++;
        }
    for (int x = -8; x < 8; x++) {
        g[n] = dCreateBox(s, 0.5, 0.5, 0.5);
        dGeomSetPosition(g[n], x * 0.5 + 0.25, 0.25 * (x % 3), 2.25);
        number(g[n], n);
        n++;
    }
    return n;
}

// ---- all three spaces agree with the brute force -------------------------------

#define SCENE_N 1000

static int check_space_finds(dSpaceID s, dGeomID *g, int n)
{
    pairs want = { 0 }, got = { 0 };
    brute_pairs(g, n, &want);

    dSpaceCollide(s, &got, record);

    CHECK(pairs_unique(&got));
    CHECK(pairs_same(&got, &want));
    pairs_free(&want);
    pairs_free(&got);
    return 0;
}

static int test_all_spaces_report_the_brute_force_pairs_of_a_random_scene(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        for (uint64_t seed = 1; seed <= 3; seed++) {
            dSpaceID s = make_space(t, 0);
            dGeomID g[SCENE_N];
            random_scene(s, g, SCENE_N, seed * 0x9E3779B97F4A7C15u);
            if (check_space_finds(s, g, SCENE_N)) return 1;
            dSpaceDestroy(s);
        }
    }
    return 0;
}

static int test_random_scene_has_work_for_the_spaces(void)
{
    // Guard against a vacuous comparison: the scene has many pairs, some of
    // them with the plane and the big geoms.
    dSpaceID s = dSimpleSpaceCreate(0);
    dGeomID g[SCENE_N];
    random_scene(s, g, SCENE_N, 0x9E3779B97F4A7C15u);
    pairs got = { 0 };

    dSpaceCollide(s, &got, record);

    int with_plane = 0, with_long_box = 0;
    for (int i = 0; i < got.n; i++) {
        with_plane += got.p[i][0] == 1 || got.p[i][1] == 1;
        with_long_box += got.p[i][0] == 152 || got.p[i][1] == 152;
    }
    CHECK(got.n > 500);
    CHECK(with_plane > 20);
    CHECK(with_long_box >= 3);
    pairs_free(&got);
    dSpaceDestroy(s);
    return 0;
}

static int test_all_spaces_report_touching_boxes_each_once(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID g[256];
        int n = touching_scene(s, g);
        if (check_space_finds(s, g, n)) return 1;
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_hash_space_agrees_at_other_levels(void)
{
    // Small top levels make most geoms "big"; a single level puts every geom
    // in one grid; a very fine bottom level spreads geoms over many cells.
    static const int levels[][2] = { { -1, 1 }, { 0, 0 }, { 2, 2 }, { -8, 3 }, { 5, 20 } };
    for (int i = 0; i < 5; i++) {
        dSpaceID s = dHashSpaceCreate(0);
        dHashSpaceSetLevels(s, levels[i][0], levels[i][1]);
        dGeomID g[SCENE_N];
        random_scene(s, g, 400, 77 + (uint64_t)i);
        if (check_space_finds(s, g, 400)) return 1;
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_hash_space_agrees_over_many_sizes(void)
{
    // Sizes from 1e-3 to 1e2 use many levels at once.
    dSpaceID s = dHashSpaceCreate(0);
    dGeomID g[600];
    rng_state = 12345;
    for (int i = 0; i < 600; i++) {
        g[i] = dCreateSphere(s, pow(10, rnd(-3, 2)));
        dGeomSetPosition(g[i], rnd(-60, 60), rnd(-60, 60), rnd(-60, 60));
        number(g[i], i);
    }
    int fail = check_space_finds(s, g, 600);
    dSpaceDestroy(s);
    return fail;
}

static int test_quadtree_agrees_whatever_its_axes_and_region(void)
{
    // Split axes chosen by the extents (z up, y up, x up), a region that
    // holds only part of the scene, and a zero extent (all geoms at the root).
    static const dReal ext[][3] = { { 30, 30, 5 }, { 30, 5, 30 }, { 5, 30, 30 }, { 10, 10, 10 },
                                    { 0, 30, 30 } };
    static const int depth[] = { 6, 4, 3, 8, 2 };
    for (int i = 0; i < 5; i++) {
        dVector3 c = { 3, -2, 1, 0 }, e = { ext[i][0], ext[i][1], ext[i][2], 0 };
        dSpaceID s = dQuadTreeSpaceCreate(0, c, e, depth[i]);
        dGeomID g[SCENE_N];
        random_scene(s, g, 500, 99 + (uint64_t)i);
        if (check_space_finds(s, g, 500)) return 1;
        dSpaceDestroy(s);
    }
    return 0;
}

// Every axis order of the sweep-and-prune space finds the brute-force pairs,
// in a fresh scene and after most geoms moved a little and a few far (the
// sort repaired in place, or redone).
static int test_sap_agrees_whatever_its_axis_order(void)
{
    static const int orders[6] = { dSAP_AXES_XYZ, dSAP_AXES_XZY, dSAP_AXES_YXZ,
                                   dSAP_AXES_YZX, dSAP_AXES_ZXY, dSAP_AXES_ZYX };
    for (int i = 0; i < 6; i++) {
        dSpaceID s = dSweepAndPruneSpaceCreate(0, orders[i]);
        CHECK(dGeomGetClass((dGeomID)s) == dSweepAndPruneSpaceClass);
        dGeomID g[SCENE_N];
        const int n = 500;
        random_scene(s, g, n, 7 + (uint64_t)i);
        if (check_space_finds(s, g, n)) return 1;
        uint64_t r = 12345 + (uint64_t)i;
        for (int k = 0; k < n; k++) {
            if (dGeomGetClass(g[k]) == dPlaneClass) continue;
            r = r * 6364136223846793005u + 1442695040888963407u;
            const dReal *p = dGeomGetPosition(g[k]);
            dReal step = (r >> 60) == 0 ? 20 : REAL(0.3);   // 1 in 16 moves far
            dGeomSetPosition(g[k], p[0] + step * (dReal)((r >> 33) % 3 - 1),
                             p[1] - step * (dReal)((r >> 40) % 3 - 1), p[2]);
        }
        if (check_space_finds(s, g, n)) return 1;
        dSpaceDestroy(s);
    }
    return 0;
}

// A bad axis order is reported and makes no space.
static int count_errors;
static void counting_handler(int num, const char *msg, va_list ap)
{
    (void)num;
    (void)msg;
    (void)ap;
    count_errors++;
}

static int test_sap_rejects_a_bad_axis_order(void)
{
    dSetDebugHandler(counting_handler);
    count_errors = 0;
    CHECK(dSweepAndPruneSpaceCreate(0, 0) == NULL);   // x, x, x
    CHECK(dSweepAndPruneSpaceCreate(0, 3 | 1 << 2 | 2 << 4) == NULL);
    CHECK(count_errors == 2);
    dSetDebugHandler(NULL);
    return 0;
}

// ---- the sweep-and-prune space's incremental paths ------------------------------

// g[i] moves: mostly a little, some far, some onto the integer grid (ends
// equal to other ends), boxes resized; never geom 0 (the plane).
static void stir(dGeomID *g, int n, int count)
{
    for (int k = 0; k < count; k++) {
        const int i = 1 + (int)rnd(0, n - 1);
        const dReal *p = dGeomGetPosition(g[i]);
        const double r = rnd(0, 1);
        if (r < 0.1) {
            dGeomSetPosition(g[i], rnd(-25, 25), rnd(-25, 25), rnd(-25, 25));
        } else if (r < 0.2 && dGeomGetClass(g[i]) == dBoxClass) {
            dGeomBoxSetLengths(g[i], rnd(0.2, 4), rnd(0.2, 4), rnd(0.2, 4));
        } else if (r < 0.3) {
            dGeomSetPosition(g[i], floor(p[0]), floor(p[1]), floor(p[2]));
        } else {
            dGeomSetPosition(g[i], p[0] + rnd(-0.5, 0.5), p[1] + rnd(-0.5, 0.5),
                             p[2] + rnd(-0.5, 0.5));
        }
    }
}

// As check_space_finds, and the space tested no other pair: its pair set
// holds no pair whose boxes stopped overlapping (every geom enabled, no
// bits or bodies in the way, no NaN or empty box).
static int check_sap_finds_exactly(dSpaceID s, dGeomID *g, int n)
{
    pairs want = { 0 }, got = { 0 };
    brute_pairs(g, n, &want);
    unsigned long before = dx_aabb_tests;

    dSpaceCollide(s, &got, record);

    CHECK(dx_aabb_tests - before == (unsigned long)got.n);
    CHECK(pairs_unique(&got));
    CHECK(pairs_same(&got, &want));
    pairs_free(&want);
    pairs_free(&got);
    return 0;
}

// The probe (not in s) against s by dSpaceCollide2 finds the brute-force
// pairs of probe with g[0 .. n-1], each once.
static int check_probe_finds(dSpaceID s, dGeomID probe, dGeomID *g, int n)
{
    pairs want = { 0 }, got = { 0 };
    for (int i = 0; i < n; i++)
        if (expect_touch(probe, g[i])) pairs_add(&want, idx(probe), idx(g[i]));

    dSpaceCollide2(probe, (dGeomID)s, &got, record);

    CHECK(pairs_unique(&got));
    CHECK(pairs_same(&got, &want));
    pairs_free(&want);
    pairs_free(&got);
    return 0;
}

static int test_sap_follows_many_random_moves(void)
{
    // Every step a tenth of the geoms move; the kept pair set must be the
    // brute-force one after each, in two axis orders.
    static const int orders[2] = { dSAP_AXES_XZY, dSAP_AXES_ZYX };
    for (int o = 0; o < 2; o++) {
        dSpaceID s = dSweepAndPruneSpaceCreate(0, orders[o]);
        dGeomID g[SCENE_N], probe = dCreateBox(0, 3, 3, 3);
        const int n = 400;
        random_scene(s, g, n, 31 + (uint64_t)o);
        number(probe, 999);
        for (int step = 0; step < 60; step++) {
            stir(g, n, n / 10);
            if (check_sap_finds_exactly(s, g, n)) return 1;
            dGeomSetPosition(probe, rnd(-20, 20), rnd(-20, 20), rnd(-20, 20));
            if (check_probe_finds(s, probe, g, n)) return 1;
        }
        dGeomDestroy(probe);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_sap_follows_a_pile_with_equal_ends(void)
{
    // Unit boxes on the integer grid: every box's ends equal its neighbours'
    // (touching boxes overlap). A few boxes move a little each step, and
    // some go back exactly home.
    dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_XZY);
    dGeomID g[216];
    for (int i = 0; i < 216; i++) {
        g[i] = dCreateBox(s, 1, 1, 1);
        dGeomSetPosition(g[i], i % 6, (i / 6) % 6, i / 36);
        number(g[i], i);
    }
    rng_state = 5;
    for (int step = 0; step < 100; step++) {
        for (int k = 0; k < 5; k++) {
            const int i = (int)rnd(0, 216);
            const dReal home[3] = { i % 6, (i / 6) % 6, i / 36 };
            const dReal d = rnd(0, 1) < 0.3 ? 0 : REAL(0.05);
            dGeomSetPosition(g[i], home[0] + d * rnd(-1, 1), home[1] + d * rnd(-1, 1),
                             home[2] + d * rnd(-1, 1));
        }
        if (check_sap_finds_exactly(s, g, 216)) return 1;
    }
    dSpaceDestroy(s);
    return 0;
}

static int test_sap_follows_the_pile_all_moving_then_few(void)
{
    // Every box moving (the lists sorted afresh each time) for some steps,
    // then a few (ends moved one by one again), and again, with a box added
    // and one destroyed in between: the pairs follow all the way.
    dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_ZXY);
    dGeomID g[217];
    int n = 216;
    for (int i = 0; i < n; i++) {
        g[i] = dCreateBox(s, 1, 1, 1);
        dGeomSetPosition(g[i], i % 6, (i / 6) % 6, i / 36);
        number(g[i], i);
    }
    rng_state = 9;
    for (int step = 0; step < 60; step++) {
        const int all = (step / 6) % 2 == 0;
        for (int k = 0; k < (all ? n : 3); k++) {
            const int i = all ? k : (int)rnd(0, n);
            const dReal home[3] = { i % 6, (i / 6) % 6, i / 36 };
            dGeomSetPosition(g[i], home[0] + rnd(-0.2, 0.2), home[1] + rnd(-0.2, 0.2),
                             home[2] + rnd(-0.2, 0.2));
        }
        if (step == 20) {
            g[n] = dCreateSphere(s, 1);
            dGeomSetPosition(g[n], 2.5, 2.5, 2.5);
            number(g[n], n);
            n++;
        }
        if (step == 40) {
            dGeomDestroy(g[100]);
            g[100] = g[--n];
        }
        if (check_sap_finds_exactly(s, g, n)) return 1;
    }
    dSpaceDestroy(s);
    return 0;
}

static int test_sap_allocates_nothing_moving_ends_or_sorting_afresh(void)
{
    // After a warm-up of both (every box moving: the lists sorted afresh;
    // a few: ends moved), neither allocates.
    dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_XZY);
    dGeomID g[216];
    for (int i = 0; i < 216; i++) {
        g[i] = dCreateBox(s, 1, 1, 1);
        number(g[i], i);
    }
    rng_state = 21;
    pairs got = { 0 };
    for (int step = 0; step < 40; step++) {
        if (step == 20) test_count_allocations();
        const int all = (step / 4) % 2 == 0;
        for (int k = 0; k < (all ? 216 : 3); k++) {
            const int i = all ? k : (int)rnd(0, 216);
            dGeomSetPosition(g[i], i % 6 + rnd(-0.2, 0.2), (i / 6) % 6 + rnd(-0.2, 0.2),
                             i / 36 + rnd(-0.2, 0.2));
        }
        got.n = 0;
        dSpaceCollide(s, &got, record);
        dSpaceCollide2(g[5], (dGeomID)s, &got, record);
    }
    CHECK(test_allocations_counted() == 0);
    pairs_free(&got);
    dSpaceDestroy(s);
    return 0;
}

static int test_sap_follows_adds_and_removes_between_collides(void)
{
    // Each step some geoms are destroyed, one is taken out and put back,
    // a few are added (inserted one by one) or, every tenth step, many (the
    // lists sorted afresh; the step after, only two are added), and some
    // move.
    enum { MAX = 1200 };
    dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_YXZ);
    dGeomID *g = malloc(MAX * sizeof *g);
    int n = 200, next = 200;
    random_scene(s, g, n, 88);
    if (check_sap_finds_exactly(s, g, n)) return 1;
    for (int step = 0; step < 40; step++) {
        if (step % 10 == 6) {   // after a fresh sort, only two new geoms
            for (int k = 0; k < 2; k++) {
                g[n] = dCreateSphere(s, rnd(0.1, 2));
                dGeomSetPosition(g[n], rnd(-25, 25), rnd(-25, 25), rnd(-25, 25));
                number(g[n++], next++);
            }
            if (check_sap_finds_exactly(s, g, n)) return 1;
            continue;
        }
        for (int k = 0; k < step % 4; k++) {
            const int i = 1 + (int)rnd(0, n - 1);
            dGeomDestroy(g[i]);
            g[i] = g[--n];
        }
        const int out = 1 + (int)rnd(0, n - 1);
        dSpaceRemove(s, g[out]);
        dGeomSetPosition(g[out], rnd(-25, 25), rnd(-25, 25), rnd(-25, 25));
        dSpaceAdd(s, g[out]);
        const int add = step % 10 == 5 ? 120 : 2;
        for (int k = 0; k < add && n < MAX; k++) {
            g[n] = rnd(0, 1) < 0.5 ? dCreateSphere(s, rnd(0.1, 2))
                                   : dCreateBox(s, rnd(0.2, 4), rnd(0.2, 4), rnd(0.2, 4));
            dGeomSetPosition(g[n], rnd(-25, 25), rnd(-25, 25), rnd(-25, 25));
            number(g[n++], next++);
        }
        stir(g, n, n / 20);
        if (check_sap_finds_exactly(s, g, n)) return 1;
    }
    CHECK(n > 600);
    free(g);
    dSpaceDestroy(s);
    return 0;
}

// A user class whose AABB is its class data: any six numbers, NaN included.
static dColliderFn *no_collider(int num)
{
    (void)num;
    return NULL;
}

static void data_aabb(dGeomID g, dReal aabb[6])
{
    memcpy(aabb, dGeomGetClassData(g), 6 * sizeof(dReal));
}

static dGeomID create_free_box(dSpaceID s)
{
    static int cls = -1;
    if (cls < 0) {
        dGeomClass c = { 6 * sizeof(dReal), no_collider, data_aabb, NULL, NULL };
        cls = dCreateGeomClass(&c);
    }
    dGeomID g = dCreateGeom(cls);
    if (s) dSpaceAdd(s, g);
    return g;
}

// Set the free box's AABB and tell its space.
static void set_free_box(dGeomID g, dReal x0, dReal x1, dReal y0, dReal y1, dReal z0, dReal z1)
{
    dReal *b = dGeomGetClassData(g);
    const dReal v[6] = { x0, x1, y0, y1, z0, z1 };
    memcpy(b, v, sizeof v);
    dGeomSetPosition(g, 0, 0, 0);
}

static int test_sap_handles_infinite_nan_and_empty_boxes(void)
{
    // Planes (infinite boxes), an empty nested space (low above high: it
    // meets the plane's box), and free boxes that change between finite,
    // NaN, empty and infinite boxes, compared with the brute force each step,
    // also from a probe and a NaN probe outside the space.
    dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_XYZ);
    dGeomID g[60];
    int n = 0;
    g[n++] = dCreatePlane(s, 0, 0, 1, -20);
    g[n++] = dCreatePlane(s, 1, 0, 0, 0);
    dSpaceID inner = dSimpleSpaceCreate(s);
    g[n++] = (dGeomID)inner;
    rng_state = 17;
    for (int i = 0; i < 40; i++) {
        g[n] = dCreateSphere(s, rnd(0.5, 3));
        dGeomSetPosition(g[n++], rnd(-10, 10), rnd(-10, 10), rnd(-10, 10));
    }
    const int first_free = n;
    for (int i = 0; i < 8; i++) {
        g[n] = create_free_box(s);
        set_free_box(g[n++], -1, 1, -1, 1, -1, 1);
    }
    for (int i = 0; i < n; i++) number(g[i], i);
    dGeomID probe = dCreateSphere(0, 4), nan_probe = create_free_box(0);
    number(probe, 100);
    number(nan_probe, 101);
    set_free_box(nan_probe, 0, 1, NAN, 1, 0, 1);
    dGeomID inner_ball = NULL;

    for (int step = 0; step < 50; step++) {
        for (int i = first_free; i < n; i++) {
            const double r = rnd(0, 1);
            const dReal c[3] = { rnd(-10, 10), rnd(-10, 10), rnd(-10, 10) };
            const int axis = (int)rnd(0, 3);
            dReal b[6] = { c[0] - 2, c[0] + 2, c[1] - 2, c[1] + 2, c[2] - 2, c[2] + 2 };
            if (r < 0.15) b[2 * axis + (int)rnd(0, 2)] = NAN;
            else if (r < 0.3) b[2 * axis] = c[axis] + 3;   // empty along one axis
            else if (r < 0.4) b[2 * axis] = -dInfinity;
            else if (r < 0.5) b[2 * axis] = -dInfinity, b[2 * axis + 1] = dInfinity;
            set_free_box(g[i], b[0], b[1], b[2], b[3], b[4], b[5]);
        }
        if (step % 7 == 3) {   // the nested space fills up and empties again
            if (inner_ball) {
                dGeomDestroy(inner_ball);
                inner_ball = NULL;
            } else {
                inner_ball = dCreateSphere(inner, 1);
            }
        }
        stir(g + 2, 41, 5);   // the spheres (g[2] is the space: stir skips its first)
        if (check_space_finds(s, g, n)) return 1;
        dGeomSetPosition(probe, rnd(-10, 10), rnd(-10, 10), rnd(-10, 10));
        if (check_probe_finds(s, probe, g, n)) return 1;
        if (check_probe_finds(s, nan_probe, g, n)) return 1;
    }
    dGeomDestroy(probe);
    dGeomDestroy(nan_probe);
    dSpaceDestroy(s);
    return 0;
}

static int test_moved_geoms_are_found_at_their_new_place(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dWorldID w = dWorldCreate();
        dBodyID body = dBodyCreate(w);
        dGeomID g[SCENE_N];
        random_scene(s, g, 300, 5);
        dGeomSetBody(g[7], body);
        if (check_space_finds(s, g, 300)) return 1;

        // Move geoms onto one point, through the geom and through a body,
        // and shrink the 3000-long box (size changes count too).
        dGeomSetPosition(g[3], 1, 2, 3);
        dGeomSetPosition(g[4], 1, 2, 3);
        dBodySetPosition(body, 1, 2, 3);
        dGeomBoxSetLengths(g[151], 1, 1, 1);
        if (check_space_finds(s, g, 300)) return 1;

        // dSpaceCollide2 against the space sees the new places as well.
        pairs got = { 0 };
        dSpaceCollide2(g[3], (dGeomID)s, &got, record);
        CHECK(pairs_has(&got, 4, 4) && pairs_has(&got, 4, 5) && pairs_has(&got, 4, 8));
        dGeomSetPosition(g[4], 100, 100, 100);
        pairs_free(&got);
        dSpaceCollide2(g[3], (dGeomID)s, &got, record);
        CHECK(!pairs_has(&got, 4, 5));
        CHECK(pairs_has(&got, 4, 8));
        pairs_free(&got);
        dSpaceDestroy(s);
        dWorldDestroy(w);
    }
    return 0;
}

// ---- work done: counted AABB tests ------------------------------------------------

// n spheres (radius 0.5 .. 1.2) on a jittered grid of spacing 3: the density
// stays the same whatever n. flat: a 2-D grid (z in 0 .. 2), else 3-D.
static void spread_scene(dSpaceID s, int n, int flat, uint64_t seed)
{
    rng_state = seed;
    int m = flat ? (int)ceil(sqrt(n)) : (int)ceil(cbrt(n));
    for (int i = 0; i < n; i++) {
        int x = i % m, y = (i / m) % m, z = flat ? 0 : i / (m * m);
        dGeomID g = dCreateSphere(s, rnd(0.5, 1.2));
        dGeomSetPosition(g, 3 * x + rnd(-0.5, 0.5), 3 * y + rnd(-0.5, 0.5),
                         flat ? rnd(0, 2) : 3 * z + rnd(-0.5, 0.5));
        number(g, i);
    }
}

static void count_pair(void *data, dGeomID a, dGeomID b)
{
    (void)a;
    (void)b;
    (*(int *)data)++;
}

static unsigned long tests_of_collide(dSpaceID s)
{
    int found = 0;
    unsigned long before = dx_aabb_tests;
    dSpaceCollide(s, &found, count_pair);
    return dx_aabb_tests - before;
}

static int test_hash_space_work_grows_near_linearly(void)
{
    unsigned long tests[2];
    const int n[2] = { 1000, 8000 };
    for (int i = 0; i < 2; i++) {
        dSpaceID s = dHashSpaceCreate(0);
        spread_scene(s, n[i], 0, 42);
        tests[i] = tests_of_collide(s);
        dSpaceDestroy(s);
    }

    // 8x the geoms at the same density: ideally 8x the tests; < 10x allows
    // for the boundary of the scene. n^2/2 would be 32e6.
    CHECK(tests[1] < 10 * tests[0]);
    CHECK(tests[1] < 8000ul * 8000ul / 2 / 500);
    return 0;
}

// The space keeps the pairs whose boxes overlap on all three axes and tests
// only those: every pair it tests is a pair of overlapping boxes, whatever
// the number of geoms.
static int test_sap_tests_only_overlapping_boxes(void)
{
    const int n[2] = { 1000, 8000 };
    for (int i = 0; i < 2; i++) {
        dSpaceID s = dSweepAndPruneSpaceCreate(0, dSAP_AXES_XYZ);
        spread_scene(s, n[i], i, 42);
        int found = 0;
        unsigned long before = dx_aabb_tests;
        dSpaceCollide(s, &found, count_pair);
        CHECK(found > 0);
        CHECK(dx_aabb_tests - before == (unsigned long)found);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_quadtree_work_is_far_below_quadratic(void)
{
    // A landscape; the tree is as deep as gives about one geom per smallest
    // block. Geoms that straddle a block's middle lines stay in that block,
    // and the geoms of a block meet those straddlers of the child blocks
    // they touch: about n tests per level of blocks, and the tree is
    // deeper for more geoms (7 levels against 5): expect a little over
    // 8 * 7 / 5 = 11x; measured 16.6x; allow 20x.
    unsigned long tests[2];
    const int n[2] = { 1000, 8000 }, depth[2] = { 5, 7 };
    for (int i = 0; i < 2; i++) {
        double half = 1.5 * ceil(sqrt(n[i])) + 1;
        dVector3 c = { half - 2, half - 2, 1, 0 }, e = { half, half, 2, 0 };
        dSpaceID s = dQuadTreeSpaceCreate(0, c, e, depth[i]);
        spread_scene(s, n[i], 1, 43);
        tests[i] = tests_of_collide(s);
        dSpaceDestroy(s);
    }

    CHECK(tests[1] < 20 * tests[0]);
    CHECK(tests[1] < 8000ul * 8000ul / 2 / 100);
    return 0;
}

static int test_one_geom_against_a_big_space_costs_few_tests(void)
{
    // 8000 spheres on a flat grid (about 268 x 268, z in 0 .. 2), a probe in
    // the middle of one grid square.
    dVector3 c = { 133, 133, 1, 0 }, e = { 136, 136, 2, 0 };
    dSpaceID spaces[2] = { dHashSpaceCreate(0), dQuadTreeSpaceCreate(0, c, e, 7) };
    unsigned long tests[2];
    for (int i = 0; i < 2; i++) {
        spread_scene(spaces[i], 8000, 1, 44);
        dGeomID probe = dCreateSphere(0, 1);
        dGeomSetPosition(probe, 100.5, 80.5, 1);
        number(probe, 9999);
        int found = 0;
        dSpaceCollide2(probe, (dGeomID)spaces[i], &found, count_pair);   // builds the structure

        unsigned long before = dx_aabb_tests;
        dSpaceCollide2(probe, (dGeomID)spaces[i], &found, count_pair);
        tests[i] = dx_aabb_tests - before;
        dGeomDestroy(probe);
        dSpaceDestroy(spaces[i]);
    }

    // The hash space: the few geoms in the probe's cells. The quadtree also
    // meets the geoms that straddle the middle lines of the probe's
    // ancestors (a few times sqrt(n)), still far from 8000.
    CHECK(tests[0] < 20);
    CHECK(tests[1] < 400);
    return 0;
}

static int test_collide_allocates_nothing_in_steady_state(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID g[SCENE_N];
        random_scene(s, g, 500, 8);
        pairs got = { 0 };
        dSpaceCollide(s, &got, record);   // grows the scratch
        dSpaceCollide2(g[5], (dGeomID)s, &got, record);
        test_count_allocations();

        for (int step = 0; step < 3; step++) {
            for (int i = 1; i < 500; i += 7) {
                const dReal *p = dGeomGetPosition(g[i]);
                dGeomSetPosition(g[i], p[0] + 0.3, p[1], p[2] - 0.2);
            }
            got.n = 0;
            dSpaceCollide(s, &got, record);
            dSpaceCollide2(g[5], (dGeomID)s, &got, record);
        }

        CHECK(test_allocations_counted() == 0);
        pairs_free(&got);
        dSpaceDestroy(s);
    }
    return 0;
}

// ---- what is never reported ------------------------------------------------------------

// Two unit spheres at the origin in a space of the type.
static dSpaceID two_spheres(int t, dGeomID *a, dGeomID *b)
{
    dSpaceID s = make_space(t, 0);
    *a = dCreateSphere(s, 1);
    *b = dCreateSphere(s, 1);
    dGeomSetPosition(*b, 0.5, 0, 0);
    number(*a, 0);
    number(*b, 1);
    return s;
}

static int test_pairs_without_matching_bits_are_not_reported(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        pairs got = { 0 };

        dGeomSetCategoryBits(a, 1);
        dGeomSetCollideBits(a, 1);
        dGeomSetCategoryBits(b, 2);
        dGeomSetCollideBits(b, 2);
        dSpaceCollide(s, &got, record);
        dSpaceCollide2(a, (dGeomID)s, &got, record);
        dSpaceCollide2(a, b, &got, record);
        CHECK(got.n == 1 && pairs_has(&got, 1, 1));   // only (a, a) (guide 10.5.2)

        // One direction suffices: b's category is in a's collide bits.
        dGeomSetCollideBits(a, 2);
        dGeomSetCollideBits(b, 0);
        got.n = 0;
        dSpaceCollide(s, &got, record);
        CHECK(got.n == 1);
        pairs_free(&got);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_disabled_geoms_are_skipped(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        dGeomID c = dCreateSphere(0, 1);
        number(c, 2);
        pairs got = { 0 };

        dGeomDisable(b);
        dSpaceCollide(s, &got, record);
        dSpaceCollide2(b, (dGeomID)s, &got, record);
        dSpaceCollide2((dGeomID)s, b, &got, record);
        dSpaceCollide2(b, c, &got, record);
        CHECK(got.n == 0);
        dSpaceCollide2(c, (dGeomID)s, &got, record);
        CHECK(got.n == 1 && pairs_has(&got, 3, 1));

        dGeomEnable(b);
        got.n = 0;
        dSpaceCollide(s, &got, record);
        CHECK(got.n == 1);
        pairs_free(&got);
        dGeomDestroy(c);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_geoms_of_one_body_are_skipped(void)
{
    dWorldID w = dWorldCreate();
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        dBodyID body = dBodyCreate(w);
        dGeomSetBody(a, body);
        dGeomSetBody(b, body);
        pairs got = { 0 };

        dSpaceCollide(s, &got, record);
        dSpaceCollide2(a, b, &got, record);

        CHECK(got.n == 0);
        pairs_free(&got);
        dSpaceDestroy(s);
    }
    dWorldDestroy(w);
    return 0;
}

static int test_nested_spaces_are_passed_as_geoms_not_recursed(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        for (int u = 0; u < N_TYPES; u++) {
            dSpaceID top = make_space(t, 0);
            dGeomID a, b;
            dSpaceID sub = two_spheres(u, &a, &b);
            dSpaceAdd(top, (dGeomID)sub);
            number((dGeomID)sub, 10);
            dGeomID c = dCreateSphere(top, 1);   // overlaps the subspace's box
            dGeomSetPosition(c, 2, 0, 0);
            number(c, 2);
            dGeomID far = dCreateSphere(top, 1);
            dGeomSetPosition(far, 20, 0, 0);
            number(far, 3);
            pairs got = { 0 };

            dSpaceCollide(top, &got, record);

            CHECK(got.n == 1);
            CHECK(pairs_has(&got, 11, 3) || pairs_has(&got, 3, 11));
            pairs_free(&got);
            dSpaceDestroy(top);
        }
    }
    return 0;
}

// ---- dSpaceCollide2 ------------------------------------------------------------------

static int test_collide2_of_two_geoms_calls_back_once_in_order(void)
{
    dGeomID a = dCreateSphere(0, 1), b = dCreateBox(0, 1, 1, 1), far = dCreateSphere(0, 1);
    number(a, 0);
    number(b, 1);
    number(far, 2);
    dGeomSetPosition(far, 5, 0, 0);
    pairs got = { 0 };

    dSpaceCollide2(b, a, &got, record);
    dSpaceCollide2(a, far, &got, record);

    CHECK(got.n == 1 && pairs_has(&got, 2, 1));
    pairs_free(&got);
    dGeomDestroy(a);
    dGeomDestroy(b);
    dGeomDestroy(far);
    return 0;
}

static int test_collide2_of_geom_and_space_puts_o1s_geom_first(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID g[SCENE_N];
        random_scene(s, g, 300, 11);
        dGeomID probe = dCreateSphere(0, 6);
        number(probe, 999);
        pairs want = { 0 }, got = { 0 }, back = { 0 };
        for (int i = 0; i < 300; i++)
            if (expect_touch(probe, g[i])) pairs_add(&want, 1000, idx(g[i]));

        dSpaceCollide2(probe, (dGeomID)s, &got, record);
        dSpaceCollide2((dGeomID)s, probe, &back, record);

        CHECK(want.n > 3);
        CHECK(pairs_same(&got, &want) && pairs_unique(&got));
        CHECK(pairs_same(&back, &want) && pairs_unique(&back));
        for (int i = 0; i < got.n; i++) CHECK(got.p[i][0] == 1000);
        for (int i = 0; i < back.n; i++) CHECK(back.p[i][1] == 1000);
        pairs_free(&want);
        pairs_free(&got);
        pairs_free(&back);
        dGeomDestroy(probe);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_collide2_of_two_spaces_pairs_one_geom_of_each(void)
{
    // Every combination of types, with the smaller space first and second.
    for (int t = 0; t < N_TYPES; t++) {
        for (int u = 0; u < N_TYPES; u++) {
            dSpaceID s1 = make_space(t, 0), s2 = make_space(u, 0);
            dGeomID g1[SCENE_N], g2[SCENE_N];
            random_scene(s1, g1, 150, 21);
            random_scene(s2, g2, 450, 22);
            for (int i = 0; i < 450; i++) number(g2[i], 1000 + i);
            pairs want = { 0 }, got = { 0 }, back = { 0 };
            for (int i = 0; i < 150; i++)
                for (int j = 0; j < 450; j++)
                    if (expect_touch(g1[i], g2[j])) pairs_add(&want, idx(g1[i]), idx(g2[j]));

            dSpaceCollide2((dGeomID)s1, (dGeomID)s2, &got, record);
            dSpaceCollide2((dGeomID)s2, (dGeomID)s1, &back, record);

            CHECK(want.n > 50);
            CHECK(pairs_same(&got, &want) && pairs_unique(&got));
            CHECK(pairs_same(&back, &want) && pairs_unique(&back));
            for (int i = 0; i < got.n; i++) CHECK(got.p[i][0] <= 150 && got.p[i][1] > 1000);
            for (int i = 0; i < back.n; i++) CHECK(back.p[i][0] > 1000 && back.p[i][1] <= 150);
            pairs_free(&want);
            pairs_free(&got);
            pairs_free(&back);
            dSpaceDestroy(s1);
            dSpaceDestroy(s2);
        }
    }
    return 0;
}

static int test_collide2_of_a_space_with_itself_is_dSpaceCollide(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID g[SCENE_N];
        random_scene(s, g, 300, 31);
        pairs one = { 0 }, two = { 0 };

        dSpaceCollide(s, &one, record);
        dSpaceCollide2((dGeomID)s, (dGeomID)s, &two, record);

        CHECK(one.n > 0 && pairs_same(&one, &two));
        pairs_free(&one);
        pairs_free(&two);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_collide2_of_a_space_and_its_own_geom_reports_x_x(void)
{
    // Guide 10.5.2: "the callback will always be called with the pair (X,X)".
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        dGeomID far = dCreateSphere(s, 1);
        dGeomSetPosition(far, 9, 9, 9);
        number(far, 2);
        pairs got = { 0 };

        dSpaceCollide2((dGeomID)s, a, &got, record);

        CHECK(got.n == 2 && pairs_has(&got, 1, 1) && pairs_has(&got, 2, 1));
        pairs_free(&got);
        dSpaceDestroy(s);
    }
    return 0;
}

// The guide's callback (10.5): spaces are collided further with
// dSpaceCollide2, geoms recorded.
static void recurse(void *data, dGeomID a, dGeomID b)
{
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
        dSpaceCollide2(a, b, data, recurse);
        if (dGeomIsSpace(a)) dSpaceCollide((dSpaceID)a, data, recurse);
        if (dGeomIsSpace(b)) dSpaceCollide((dSpaceID)b, data, recurse);
    } else {
        record(data, a, b);
    }
}

static int test_callback_may_recurse_into_passed_spaces(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID top = make_space(t, 0);
        dSpaceID car1 = make_space((t + 1) % N_TYPES, top);
        dSpaceID car2 = make_space((t + 2) % N_TYPES, top);
        dGeomID g[SCENE_N];
        random_scene(car1, g, 40, 51);
        random_scene(car2, g + 40, 40, 52);
        dGeomDestroy(g[40]);   // one plane is enough
        g[40] = dCreateSphere(car2, 0.1);
        for (int i = 40; i < 80; i++) number(g[i], i);
        pairs want = { 0 }, got = { 0 };
        brute_pairs(g, 80, &want);

        dSpaceCollide(top, &got, recurse);

        CHECK(want.n > 10);
        CHECK(pairs_same(&got, &want) && pairs_unique(&got));
        pairs_free(&want);
        pairs_free(&got);
        dSpaceDestroy(top);
    }
    return 0;
}

// ---- the space may not change during its own collision ----------------------------------

typedef struct meddle {
    dSpaceID s;
    dGeomID extra;   // not in the space
    int calls;
} meddle;

static void meddling_callback(void *data, dGeomID a, dGeomID b)
{
    (void)b;
    meddle *m = data;
    m->calls++;
    dSpaceAdd(m->s, m->extra);
    dSpaceRemove(m->s, a);
    dGeomDestroy(a);
    dSpaceDestroy(m->s);
    // Reading is fine: the space's pairs with a, through its structure.
    int found = 0;
    dSpaceCollide2(a, (dGeomID)m->s, &found, count_pair);
    if (found < 1) m->calls = -1000;
}

static int test_changing_a_space_from_its_callback_is_reported(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        meddle m = { s, dCreateSphere(0, 1), 0 };
        test_capture_reports();

        dSpaceCollide(s, &m, meddling_callback);
        dSpaceCollide2(a, (dGeomID)s, &m, meddling_callback);

        CHECK(m.calls == 3);   // (a, b), (a, a), (a, b)
        CHECK(test_captured_count() == 12);
        CHECK(test_captured_contains("dSpaceAdd"));
        CHECK(test_captured_contains("dSpaceRemove"));
        CHECK(test_captured_contains("dGeomDestroy"));
        CHECK(test_captured_contains("dSpaceDestroy"));
        test_release_reports();
        CHECK(dSpaceGetNumGeoms(s) == 2);
        CHECK(dSpaceGetGeom(s, 0) == a && dSpaceGetGeom(s, 1) == b);
        CHECK(dGeomGetSpace(m.extra) == 0);
        dGeomDestroy(m.extra);
        dSpaceDestroy(s);
    }
    return 0;
}

typedef struct mover {
    dSpaceID s;
    dGeomID c;
    pairs nested;
} mover;

static void moving_callback(void *data, dGeomID a, dGeomID b)
{
    (void)a;
    (void)b;
    mover *m = data;
    if (m->nested.n > 0) return;
    dGeomSetPosition(m->c, 0, 0, 0);
    dSpaceCollide2(m->c, (dGeomID)m->s, &m->nested, record);
}

static int test_geom_moved_by_the_callback_is_seen_by_nested_queries(void)
{
    // The guide forbids moving geoms of a space being collided, but nothing
    // can stop a callback from doing it: the walk in progress must stay
    // intact and a nested query must see the new place.
    for (int t = 0; t < N_TYPES; t++) {
        dGeomID a, b;
        dSpaceID s = two_spheres(t, &a, &b);
        mover m = { s, dCreateSphere(s, 1), { 0 } };
        number(m.c, 2);
        dGeomSetPosition(m.c, 10, 0, 0);
        pairs after = { 0 };

        dSpaceCollide(s, &m, moving_callback);
        dSpaceCollide(s, &after, record);

        CHECK(m.nested.n == 3);
        CHECK(pairs_has(&m.nested, 3, 1) && pairs_has(&m.nested, 3, 2) &&
              pairs_has(&m.nested, 3, 3));
        CHECK(after.n == 3 && pairs_unique(&after));
        pairs_free(&m.nested);
        pairs_free(&after);
        dSpaceDestroy(s);
    }
    return 0;
}

// ---- membership -------------------------------------------------------------------

static int test_adding_a_geom_already_in_a_space_is_reported(void)
{
    dSpaceID s1 = dHashSpaceCreate(0), s2 = dSimpleSpaceCreate(0);
    dGeomID g = dCreateSphere(s1, 1);
    test_capture_reports();

    dSpaceAdd(s2, g);
    dSpaceAdd(s1, g);

    CHECK(test_captured_count() == 2);
    CHECK(test_captured_contains("another space"));
    CHECK(test_captured_contains("already in this space"));
    CHECK(dGeomGetSpace(g) == s1 && dSpaceGetNumGeoms(s1) == 1 && dSpaceGetNumGeoms(s2) == 0);
    CHECK(dSpaceQuery(s1, g) && !dSpaceQuery(s2, g));
    dSpaceDestroy(s1);
    dSpaceDestroy(s2);
    return 0;
}

static int test_space_cannot_be_added_into_itself(void)
{
    dSpaceID a = dSimpleSpaceCreate(0), b = dHashSpaceCreate(a);
    test_capture_reports();

    dSpaceAdd(b, (dGeomID)a);
    dSpaceAdd(a, (dGeomID)a);

    CHECK(test_captured_count() == 2);
    CHECK(dGeomGetSpace((dGeomID)a) == 0);
    dSpaceDestroy(a);
    return 0;
}

static int test_cleanup_one_destroys_the_geoms_zero_leaves_them(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID parent = dSimpleSpaceCreate(0);
        int found = 0;

        // Cleanup 1 (the default): the space, its geoms and a subspace's go;
        // their handles then read as destroyed (geoms are pooled, not freed).
        dSpaceID s = make_space(t, parent);
        CHECK(dSpaceGetCleanup(s) == 1);
        dSpaceID sub = dSimpleSpaceCreate(s);
        dGeomID inner = dCreateSphere(sub, 1);
        dGeomID box = dCreateBox(s, 1, 1, 1);
        dCreateSphere(s, 1);
        dSpaceCollide(s, &found, count_pair);
        CHECK(found == 3 && dSpaceGetNumGeoms(parent) == 1);
        dSpaceDestroy(s);
        CHECK(dSpaceGetNumGeoms(parent) == 0);
        test_capture_reports();
        CHECK(dGeomGetClass(inner) == -1 && dGeomGetClass(box) == -1);
        CHECK(test_captured_count() == 2 && test_captured_contains("destroyed"));
        test_release_reports();

        // Cleanup 0: the geoms stay, outside any space.
        s = make_space(t, parent);
        dSpaceSetCleanup(s, 0);
        dGeomID a = dCreateSphere(s, 1), b = dCreateBox(s, 1, 1, 1);
        dSpaceDestroy(s);
        CHECK(dGeomGetSpace(a) == 0 && dGeomGetSpace(b) == 0);
        CHECK(dGeomGetClass(a) == dSphereClass && dGeomGetClass(b) == dBoxClass);
        dSpaceAdd(parent, a);
        CHECK(dSpaceGetNumGeoms(parent) == 1);
        dGeomDestroy(a);
        dGeomDestroy(b);
        dSpaceDestroy(parent);
    }
    return 0;
}

static int test_get_geom_follows_insertion_order_after_removals(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID g[8];
        for (int i = 0; i < 8; i++) g[i] = dCreateSphere(s, 1);

        dSpaceRemove(s, g[2]);
        dGeomDestroy(g[5]);
        dSpaceRemove(s, g[0]);
        dSpaceAdd(s, g[2]);

        static const int order[] = { 1, 3, 4, 6, 7, 2 };
        CHECK(dSpaceGetNumGeoms(s) == 6);
        for (int i = 0; i < 6; i++) CHECK(dSpaceGetGeom(s, i) == g[order[i]]);
        CHECK(!dSpaceQuery(s, g[0]) && dSpaceQuery(s, g[2]));
        dGeomDestroy(g[0]);
        dSpaceDestroy(s);
    }
    return 0;
}

// ---- levels, classes, boxes -------------------------------------------------------------

static int test_hash_levels_round_trip_and_are_checked(void)
{
    dSpaceID h = dHashSpaceCreate(0), simple = dSimpleSpaceCreate(0);
    int lo = 0, hi = 0;
    dHashSpaceGetLevels(h, &lo, &hi);
    CHECK(lo == -3 && hi == 10);   // guide defaults

    dHashSpaceSetLevels(h, -5, 7);
    dHashSpaceGetLevels(h, &lo, NULL);
    dHashSpaceGetLevels(h, NULL, &hi);
    CHECK(lo == -5 && hi == 7);
    dHashSpaceSetLevels(h, 4, 4);
    dHashSpaceGetLevels(h, &lo, &hi);
    CHECK(lo == 4 && hi == 4);

    test_capture_reports();
    dHashSpaceSetLevels(h, 3, 2);
    CHECK(test_captured_count() == 1 && test_captured_contains("minlevel"));
    dHashSpaceSetLevels(simple, 0, 1);
    dHashSpaceGetLevels(simple, &lo, &hi);
    CHECK(test_captured_count() == 3 && test_captured_contains("not a hash space"));
    test_release_reports();
    dHashSpaceGetLevels(h, &lo, &hi);
    CHECK(lo == 4 && hi == 4);
    dSpaceDestroy(h);
    dSpaceDestroy(simple);
    return 0;
}

static int test_space_classes_and_defaults(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        static const int cls[] = { dSimpleSpaceClass, dHashSpaceClass, dQuadTreeSpaceClass,
                                   dSweepAndPruneSpaceClass };
        dSpaceID s = make_space(t, 0);
        CHECK(dSpaceGetClass(s) == cls[t] && dGeomGetClass((dGeomID)s) == cls[t]);
        CHECK(dGeomIsSpace((dGeomID)s) && dSpaceGetNumGeoms(s) == 0);
        dSpaceSetSublevel(s, 3);
        CHECK(dSpaceGetSublevel(s) == 3);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_space_aabb_is_the_union_of_its_geoms(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID s = make_space(t, 0);
        dGeomID a = dCreateSphere(s, 1), b = dCreateBox(s, 2, 4, 6);
        dGeomSetPosition(a, -3, 0, 1);
        dGeomSetPosition(b, 5, 1, 0);
        dReal box[6];

        dGeomGetAABB((dGeomID)s, box);
        // exact: sums of small binary fractions
        static const dReal want[6] = { -4, 6, -1, 3, -3, 3 };
        for (int k = 0; k < 6; k++) CHECK(box[k] == want[k]);

        dGeomSetPosition(a, 0, 0, 10);   // the box follows a move
        dGeomGetAABB((dGeomID)s, box);
        CHECK(box[0] == -1 && box[5] == 11 && box[4] == -3);
        dSpaceDestroy(s);
    }
    return 0;
}

static int test_nested_space_box_follows_its_geoms_in_collisions(void)
{
    for (int t = 0; t < N_TYPES; t++) {
        dSpaceID top = make_space(t, 0), sub = dSimpleSpaceCreate(top);
        number((dGeomID)sub, 0);
        dGeomID a = dCreateSphere(sub, 1), b = dCreateSphere(top, 1);
        number(a, 1);
        number(b, 2);
        dGeomSetPosition(b, 10, 0, 0);
        pairs got = { 0 };
        dSpaceCollide(top, &got, record);
        CHECK(got.n == 0);

        dGeomSetPosition(a, 9, 0, 0);   // the subspace's box moves onto b
        dSpaceCollide(top, &got, record);

        CHECK(got.n == 1 && (pairs_has(&got, 1, 3) || pairs_has(&got, 3, 1)));
        pairs_free(&got);
        dSpaceDestroy(top);
    }
    return 0;
}

// ---- bad input -------------------------------------------------------------------------

static int test_bad_handles_and_arguments_are_reported(void)
{
    dSpaceID s = dHashSpaceCreate(0);
    dGeomID g = dCreateSphere(s, 1), loose = dCreateSphere(0, 1);
    test_capture_reports();

    dSpaceAdd(NULL, loose);
    dSpaceAdd(s, NULL);
    dSpaceAdd((dSpaceID)loose, g);
    dSpaceRemove(s, loose);
    dSpaceDestroy((dSpaceID)loose);
    dSpaceCollide(s, 0, NULL);
    dSpaceCollide(NULL, 0, count_pair);
    dSpaceCollide2(NULL, g, 0, count_pair);
    dSpaceCollide2(g, (dGeomID)s, 0, NULL);
    CHECK(dSpaceGetGeom(s, 1) == NULL);
    CHECK(dSpaceGetGeom(s, -1) == NULL);
    CHECK(dSpaceGetNumGeoms(NULL) == 0);
    CHECK(dSpaceQuery(s, NULL) == 0);
    CHECK(dHashSpaceCreate((dSpaceID)loose) == NULL);

    CHECK(test_captured_count() == 14);
    CHECK(test_captured_contains("dSpaceGetGeom: i = 1 is out of range"));
    CHECK(test_captured_contains("not a space"));
    CHECK(test_captured_contains("callback is NULL"));
    test_release_reports();
    CHECK(dSpaceGetNumGeoms(s) == 1 && dGeomGetSpace(loose) == 0);
    dGeomDestroy(loose);
    dSpaceDestroy(s);
    return 0;
}

static int test_bad_quadtree_arguments_are_reported(void)
{
    dVector3 c = { 0, 0, 0, 0 }, e = { 10, 10, 10, 0 };
    dVector3 inf = { 10, INFINITY, 10, 0 }, neg = { 10, -1, 10, 0 }, nan = { NAN, 0, 0, 0 };
    test_capture_reports();

    CHECK(dQuadTreeSpaceCreate(0, c, e, 0) == NULL);
    CHECK(dQuadTreeSpaceCreate(0, c, inf, 3) == NULL);
    CHECK(dQuadTreeSpaceCreate(0, c, neg, 3) == NULL);
    CHECK(dQuadTreeSpaceCreate(0, nan, e, 3) == NULL);
    CHECK(dQuadTreeSpaceCreate(0, NULL, e, 3) == NULL);

    CHECK(test_captured_count() == 5);
    CHECK(test_captured_contains("Depth (0) is less than 1"));
    CHECK(test_captured_contains("Extents"));
    CHECK(test_captured_contains("Center"));
    test_release_reports();
    return 0;
}

static int test_very_deep_quadtree_is_capped_and_works(void)
{
    dVector3 c = { 0, 0, 0, 0 }, e = { 30, 30, 30, 0 };
    test_capture_reports();

    dSpaceID s = dQuadTreeSpaceCreate(0, c, e, 40);

    CHECK(s != NULL && test_captured_count() == 1 && test_captured_contains("31"));
    test_release_reports();
    dGeomID g[SCENE_N];
    random_scene(s, g, 300, 61);
    int fail = check_space_finds(s, g, 300);
    dSpaceDestroy(s);
    return fail;
}

const test_case test_cases[] = {
    TEST_CASE(test_all_spaces_report_the_brute_force_pairs_of_a_random_scene),
    TEST_CASE(test_random_scene_has_work_for_the_spaces),
    TEST_CASE(test_all_spaces_report_touching_boxes_each_once),
    TEST_CASE(test_hash_space_agrees_at_other_levels),
    TEST_CASE(test_hash_space_agrees_over_many_sizes),
    TEST_CASE(test_quadtree_agrees_whatever_its_axes_and_region),
    TEST_CASE(test_sap_agrees_whatever_its_axis_order),
    TEST_CASE(test_sap_rejects_a_bad_axis_order),
    TEST_CASE(test_sap_follows_many_random_moves),
    TEST_CASE(test_sap_follows_a_pile_with_equal_ends),
    TEST_CASE(test_sap_follows_the_pile_all_moving_then_few),
    TEST_CASE(test_sap_allocates_nothing_moving_ends_or_sorting_afresh),
    TEST_CASE(test_sap_follows_adds_and_removes_between_collides),
    TEST_CASE(test_sap_handles_infinite_nan_and_empty_boxes),
    TEST_CASE(test_moved_geoms_are_found_at_their_new_place),
    TEST_CASE(test_hash_space_work_grows_near_linearly),
    TEST_CASE(test_sap_tests_only_overlapping_boxes),
    TEST_CASE(test_quadtree_work_is_far_below_quadratic),
    TEST_CASE(test_one_geom_against_a_big_space_costs_few_tests),
    TEST_CASE(test_collide_allocates_nothing_in_steady_state),
    TEST_CASE(test_pairs_without_matching_bits_are_not_reported),
    TEST_CASE(test_disabled_geoms_are_skipped),
    TEST_CASE(test_geoms_of_one_body_are_skipped),
    TEST_CASE(test_nested_spaces_are_passed_as_geoms_not_recursed),
    TEST_CASE(test_collide2_of_two_geoms_calls_back_once_in_order),
    TEST_CASE(test_collide2_of_geom_and_space_puts_o1s_geom_first),
    TEST_CASE(test_collide2_of_two_spaces_pairs_one_geom_of_each),
    TEST_CASE(test_collide2_of_a_space_with_itself_is_dSpaceCollide),
    TEST_CASE(test_collide2_of_a_space_and_its_own_geom_reports_x_x),
    TEST_CASE(test_callback_may_recurse_into_passed_spaces),
    TEST_CASE(test_changing_a_space_from_its_callback_is_reported),
    TEST_CASE(test_geom_moved_by_the_callback_is_seen_by_nested_queries),
    TEST_CASE(test_adding_a_geom_already_in_a_space_is_reported),
    TEST_CASE(test_space_cannot_be_added_into_itself),
    TEST_CASE(test_cleanup_one_destroys_the_geoms_zero_leaves_them),
    TEST_CASE(test_get_geom_follows_insertion_order_after_removals),
    TEST_CASE(test_hash_levels_round_trip_and_are_checked),
    TEST_CASE(test_space_classes_and_defaults),
    TEST_CASE(test_space_aabb_is_the_union_of_its_geoms),
    TEST_CASE(test_nested_space_box_follows_its_geoms_in_collisions),
    TEST_CASE(test_bad_handles_and_arguments_are_reported),
    TEST_CASE(test_bad_quadtree_arguments_are_reported),
    TEST_CASE(test_very_deep_quadtree_is_capped_and_works),
    TEST_END
};
