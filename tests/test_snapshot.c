// SPDX-License-Identifier: BSD-3-Clause
//
// test_snapshot.c -- dWorldSnapshot / dWorldRestore: a world restored from a
// snapshot and stepped on equals, to the bit, the world stepped on from the
// moment of the snapshot (every bench-like scene, every stepper, 1000
// steps, 250 under the sanitizers); bad buffers and files are reported by
// name and leave the world untouched.

#define _POSIX_C_SOURCE 200809L   // mkstemp

#include "test.h"
#include "replay_scenes.h"

#include <ode/snapshot.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define WARMUP 60
// Under AddressSanitizer (the CI's sanitizer build runs this test several
// times slower) a quarter of the steps: the other builds hold the bits over
// all 1000, and what the sanitizers look for shows in the first steps.
#if defined(__SANITIZE_ADDRESS__)
#define CONTINUE 250
#else
#define CONTINUE 1000
#endif

static uint64_t hashes[CONTINUE];
static dReal state_a[SCENE_STATE_SIZE], state_b[SCENE_STATE_SIZE];

static unsigned char *take_snapshot(dWorldID w, size_t *size)
{
    *size = dWorldSnapshot(w, NULL, 0);
    unsigned char *buffer = malloc(*size);
    if (buffer && dWorldSnapshot(w, buffer, *size) != *size) {
        free(buffer);
        return NULL;
    }
    return buffer;
}

// Warm up, snapshot, run on recording each step's state; restore, run on
// again: each step must equal the first run's.
static int check_round_trip(int kind, int stepper, size_t *bytes_per_body)
{
    scene s;
    scene_build(&s, kind, stepper, NULL, 0);
    for (int i = 0; i < WARMUP; i++) scene_step(&s);
    size_t size;
    unsigned char *snap = take_snapshot(s.w, &size);
    CHECK(snap != NULL);
    for (int i = 0; i < CONTINUE; i++) {
        scene_step(&s);
        hashes[i] = scene_hash(&s);
    }
    scene_state(&s, state_a);

    CHECK(dWorldRestore(s.w, snap, size) == 1);
    int first_diff = -1;
    for (int i = 0; i < CONTINUE; i++) {
        scene_step(&s);
        if (first_diff < 0 && scene_hash(&s) != hashes[i]) first_diff = i;
    }
    scene_state(&s, state_b);

    if (first_diff >= 0)
        printf("# %s, %s: restored run differs at step %d\n", scene_names[kind],
               stepper_names[stepper], first_diff);
    CHECK(first_diff < 0);
    CHECK(memcmp(state_a, state_b, sizeof state_a) == 0);
    *bytes_per_body = size / (size_t)s.nbody;
    if (stepper == STEP_QUICK)
        printf("# %s: %zu bytes for %d bodies, %zu per body\n", scene_names[kind], size,
               s.nbody, *bytes_per_body);
    free(snap);
    scene_destroy(&s);
    return 0;
}

static int test_restored_world_continues_bit_identically(void)
{
    for (int kind = 0; kind < SCENE_KINDS; kind++)
        for (int stepper = 0; stepper < STEPPERS; stepper++) {
            size_t per_body;
            CHECK(check_round_trip(kind, stepper, &per_body) == 0);
            CHECK(per_body > 13 * sizeof(dReal) && per_body < 2000);
        }
    return 0;
}

// A world with every body setting changed from its default: auto-disable
// with averaging, damping, finite rotation, no gravity, a disabled joint, a
// kinematic body, accumulated forces.
static dWorldID odd_world(dBodyID body[3], dJointID *joint)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    for (int i = 0; i < 3; i++) {
        body[i] = dBodyCreate(w);
        dBodySetPosition(body[i], (dReal)i, 0, 1);
    }
    dBodySetAutoDisableFlag(body[0], 1);
    dBodySetAutoDisableAverageSamplesCount(body[0], 5);
    dBodySetLinearDamping(body[0], REAL(0.1));
    dBodySetFiniteRotationMode(body[0], 1);
    dBodySetFiniteRotationAxis(body[0], 0, 0, 1);
    dBodySetAngularVel(body[0], 0, 0, 3);
    dBodySetGravityMode(body[1], 0);
    dBodySetLinearVel(body[1], 1, 2, 3);
    dBodyAddForce(body[1], 5, 0, 0);
    dBodySetKinematic(body[2]);
    dBodySetLinearVel(body[2], 0, 1, 0);
    *joint = dJointCreateHinge(w, 0);
    dJointAttach(*joint, body[0], body[1]);
    dJointSetHingeAnchor(*joint, REAL(0.5), 0, 1);
    dJointSetHingeAxis(*joint, 0, 1, 0);
    dJointSetHingeParam(*joint, dParamVel, 2);
    dJointSetHingeParam(*joint, dParamFMax, 10);
    return w;
}

static int test_settings_and_joint_parameters_are_restored(void)
{
    dBodyID b[3];
    dJointID j;
    dWorldID w = odd_world(b, &j);
    for (int i = 0; i < 3; i++) dWorldStep(w, REAL(0.01));
    size_t size;
    unsigned char *snap = take_snapshot(w, &size);
    dReal before[13 * 3];
    for (int i = 0; i < 3; i++) {
        memcpy(before + 13 * i, dBodyGetPosition(b[i]), 3 * sizeof(dReal));
        memcpy(before + 13 * i + 3, dBodyGetQuaternion(b[i]), 4 * sizeof(dReal));
        memcpy(before + 13 * i + 7, dBodyGetLinearVel(b[i]), 3 * sizeof(dReal));
        memcpy(before + 13 * i + 10, dBodyGetAngularVel(b[i]), 3 * sizeof(dReal));
    }
    dVector3 axis_before;
    dJointGetHingeAxis(j, axis_before);
    dBodyAddForce(b[1], 5, 0, 0);
    const dReal force_before = dBodyGetForce(b[1])[0];

    // Change everything the snapshot holds.
    dWorldSetGravity(w, 1, 1, 1);
    dWorldSetERP(w, REAL(0.5));
    dBodySetAutoDisableAverageSamplesCount(b[0], 2);
    dBodySetLinearDamping(b[0], 0);
    dBodySetGravityMode(b[1], 1);
    dBodyAddForce(b[1], 100, 0, 0);
    dJointSetHingeParam(j, dParamVel, -7);
    dJointSetHingeAxis(j, 1, 0, 0);
    dJointDisable(j);
    dRandSetSeed(99);
    for (int i = 0; i < 10; i++) dWorldStep(w, REAL(0.01));
    CHECK(dWorldRestore(w, snap, size) == 1);

    dVector3 g, axis;
    dWorldGetGravity(w, g);
    CHECK(g[0] == 0 && g[2] == REAL(-9.81));
    CHECK(dWorldGetERP(w) == REAL(0.2));
    CHECK(dBodyGetAutoDisableAverageSamplesCount(b[0]) == 5);
    CHECK(dBodyGetLinearDamping(b[0]) == REAL(0.1));
    CHECK(dBodyGetGravityMode(b[1]) == 0);
    CHECK(dBodyGetForce(b[1])[0] == force_before - 5);   // the accumulator as it was
    CHECK(dJointGetHingeParam(j, dParamVel) == 2);
    dJointGetHingeAxis(j, axis);
    CHECK(memcmp(axis, axis_before, 3 * sizeof(dReal)) == 0);
    CHECK(dJointIsEnabled(j) == 1);
    CHECK(dBodyIsKinematic(b[2]) == 1);
    for (int i = 0; i < 3; i++) {
        CHECK(memcmp(before + 13 * i, dBodyGetPosition(b[i]), 3 * sizeof(dReal)) == 0);
        CHECK(memcmp(before + 13 * i + 7, dBodyGetLinearVel(b[i]), 3 * sizeof(dReal)) == 0);
    }
    free(snap);
    dWorldDestroy(w);
    return 0;
}

static int test_random_seed_is_restored(void)
{
    dWorldID w = dWorldCreate();
    dRandSetSeed(12345);
    size_t size;
    unsigned char *snap = take_snapshot(w, &size);
    const unsigned long first = dRand();
    dRand();

    CHECK(dWorldRestore(w, snap, size) == 1);

    CHECK(dRandGetSeed() == 12345);
    CHECK(dRand() == first);
    free(snap);
    dWorldDestroy(w);
    return 0;
}

static int test_file_round_trip(void)
{
    scene s;
    scene_build(&s, SCENE_RAGDOLLS, STEP_QUICK, NULL, 0);
    for (int i = 0; i < 30; i++) scene_step(&s);
    char path[] = "/tmp/ode_snapshot_XXXXXX";
    const int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    CHECK(dWorldSnapshotToFile(s.w, path) == 1);
    for (int i = 0; i < 50; i++) scene_step(&s);
    const uint64_t after = scene_hash(&s);

    CHECK(dWorldRestoreFromFile(s.w, path) == 1);
    for (int i = 0; i < 50; i++) scene_step(&s);

    CHECK(scene_hash(&s) == after);
    remove(path);
    scene_destroy(&s);
    return 0;
}

// Restore from bad, then check that the world did not move and one named
// error was reported.
static int check_rejected(scene *s, const void *bad, size_t size, const char *why)
{
    scene_state(s, state_a);
    test_capture_reports();
    const int restored = dWorldRestore(s->w, bad, size);
    const int reports = test_captured_count();
    const int named = test_captured_contains(why) && test_captured_contains("dWorldRestore");
    if (!named && reports > 0) printf("# got: %s\n", test_captured_last());
    test_release_reports();
    scene_state(s, state_b);
    CHECK(restored == 0);
    CHECK(memcmp(state_a, state_b, sizeof state_a) == 0);
    CHECK(reports == 1);
    CHECK(named);
    return 0;
}

static int test_bad_snapshots_are_reported_and_change_nothing(void)
{
    scene s;
    scene_build(&s, SCENE_CHAIN, STEP_QUICK, NULL, 0);
    for (int i = 0; i < 20; i++) scene_step(&s);
    size_t size;
    unsigned char *snap = take_snapshot(s.w, &size);
    unsigned char *bad = malloc(size + 8);
    for (int i = 0; i < 20; i++) scene_step(&s);

    CHECK(check_rejected(&s, snap, size - 1, "truncated") == 0);
    CHECK(check_rejected(&s, snap, 20, "shorter than its header") == 0);
    CHECK(check_rejected(&s, snap, 0, "truncated") == 0);
    memcpy(bad, snap, size);
    memset(bad + size, 0, 8);
    CHECK(check_rejected(&s, bad, size + 8, "bytes after its end") == 0);
    bad[0] = 'X';
    CHECK(check_rejected(&s, bad, size, "bad magic") == 0);
    memcpy(bad, snap, size);
    bad[8] = 99;   // version
    CHECK(check_rejected(&s, bad, size, "version") == 0);
    memcpy(bad, snap, size);
    bad[12] = (unsigned char)(sizeof(dReal) == 8 ? 4 : 8);
    CHECK(check_rejected(&s, bad, size, "precision") == 0);
    // Every single flipped payload byte is caught by the checksum.
    for (size_t k = 32; k < size; k += 7) {
        memcpy(bad, snap, size);
        bad[k] ^= 0x10;
        CHECK(check_rejected(&s, bad, size, "checksum") == 0);
    }
    test_capture_reports();
    CHECK(dWorldRestore(s.w, NULL, size) == 0);
    CHECK(test_captured_contains("buffer is NULL"));
    CHECK(dWorldRestoreFromFile(s.w, "/nonexistent/dir/snap") == 0);
    CHECK(test_captured_contains("cannot open"));
    CHECK(dWorldSnapshot(NULL, NULL, 0) == 0);
    CHECK(test_captured_contains("world is NULL"));
    test_release_reports();

    // And the good one still works.
    CHECK(dWorldRestore(s.w, snap, size) == 1);
    free(bad);
    free(snap);
    scene_destroy(&s);
    return 0;
}

static int test_a_changed_world_is_refused(void)
{
    scene s;
    scene_build(&s, SCENE_RAGDOLLS, STEP_WORLD, NULL, 0);
    size_t size;
    unsigned char *snap = take_snapshot(s.w, &size);

    dBodyID extra = dBodyCreate(s.w);
    CHECK(check_rejected(&s, snap, size, "bodies are not those") == 0);
    dBodyDestroy(extra);
    CHECK(dWorldRestore(s.w, snap, size) == 1);   // the same bodies again

    dJointID j = dJointCreateBall(s.w, 0);
    CHECK(check_rejected(&s, snap, size, "joints are not those") == 0);
    dJointDestroy(j);

    dJointID neck = dBodyGetJoint(s.body[0], 0);
    dJointAttach(neck, s.body[0], 0);
    CHECK(check_rejected(&s, snap, size, "attached to other bodies") == 0);

    dWorldID other = dWorldCreate();
    test_capture_reports();
    CHECK(dWorldRestore(other, snap, size) == 0);
    CHECK(test_captured_contains("bodies are not those"));
    test_release_reports();
    dWorldDestroy(other);
    free(snap);
    scene_destroy(&s);
    return 0;
}

static int test_snapshot_size_query(void)
{
    dBodyID b[3];
    dJointID j;
    dWorldID w = odd_world(b, &j);
    const size_t size = dWorldSnapshot(w, NULL, 0);
    unsigned char small[16];
    memset(small, 0xab, sizeof small);

    CHECK(size > 32);
    CHECK(dWorldSnapshot(w, small, sizeof small) == size);   // too small: nothing written
    CHECK(small[0] == 0xab && small[15] == 0xab);
    dWorldDestroy(w);
    return 0;
}

// The stack below the caller filled with v (volatile: the stores stay).
static void scribble_stack(unsigned char v)
{
    volatile unsigned char junk[4096];
    for (size_t i = 0; i < sizeof junk; i++) junk[i] = v;
}

static void set_box_mass(dBodyID b, unsigned char stack_fill)
{
    dMass m;
    memset(&m, stack_fill, sizeof m);   // a dMass's padding as a caller may leave it
    dMassSetBoxTotal(&m, 2, REAL(0.3), REAL(0.4), REAL(0.5));
    scribble_stack(stack_fill);   // dBodySetMass's frame lands on the filled bytes
    dBodySetMass(b, &m);
}

// A snapshot's bytes are the state's alone: the same mass set over different
// stack contents and dMass padding gives the same bytes.
static int test_snapshot_bytes_depend_on_the_state_alone(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    set_box_mass(b, 0x5a);
    size_t size_a, size_b;
    unsigned char *a = take_snapshot(w, &size_a);
    set_box_mass(b, 0xc3);
    unsigned char *s = take_snapshot(w, &size_b);

    CHECK(a != NULL && s != NULL && size_a == size_b);
    CHECK(memcmp(a, s, size_a) == 0);
    free(a);
    free(s);
    dWorldDestroy(w);
    return 0;
}

// A space with a nested space: static geoms moved, resized, disabled and
// re-categorised after the snapshot come back; a body's geom follows its body.
static int test_space_round_trip(void)
{
    dWorldID w = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(0);
    dSpaceID inner = dSimpleSpaceCreate(space);
    dGeomID box = dCreateBox(space, 1, 2, 3);
    dGeomSetPosition(box, 1, 2, 3);
    dGeomID ray = dCreateRay(inner, 5);
    dGeomRaySetClosestHit(ray, 1);
    dGeomID plane = dCreatePlane(space, 0, 0, 1, 0);
    dGeomID ball = dCreateSphere(inner, REAL(0.5));
    dBodyID body = dBodyCreate(w);
    dGeomSetBody(ball, body);
    dBodySetPosition(body, 0, 0, 4);
    dGeomSetCategoryBits(box, 6);
    const size_t size = dSpaceSnapshot(space, NULL, 0);
    unsigned char *snap = malloc(size);
    CHECK(dSpaceSnapshot(space, snap, size) == size);
    const size_t wsize = dWorldSnapshot(w, NULL, 0);
    unsigned char *wsnap = malloc(wsize);
    dWorldSnapshot(w, wsnap, wsize);

    dGeomSetPosition(box, 9, 9, 9);
    dGeomBoxSetLengths(box, 4, 4, 4);
    dGeomSetCategoryBits(box, 1);
    dGeomDisable(ray);
    dGeomRaySetLength(ray, 1);
    dGeomRaySetClosestHit(ray, 0);
    dGeomPlaneSetParams(plane, 1, 0, 0, 2);
    dGeomSphereSetRadius(ball, 2);
    dBodySetPosition(body, 7, 7, 7);
    CHECK(dSpaceRestore(space, snap, size) == 1);
    CHECK(dWorldRestore(w, wsnap, wsize) == 1);

    dVector3 l;
    dVector4 p;
    dGeomBoxGetLengths(box, l);
    dGeomPlaneGetParams(plane, p);
    CHECK(dGeomGetPosition(box)[0] == 1 && dGeomGetPosition(box)[2] == 3);
    CHECK(l[0] == 1 && l[1] == 2 && l[2] == 3);
    CHECK(dGeomGetCategoryBits(box) == 6);
    CHECK(dGeomIsEnabled(ray) == 1);
    CHECK(dGeomRayGetLength(ray) == 5 && dGeomRayGetClosestHit(ray) == 1);
    CHECK(p[0] == 0 && p[2] == 1 && p[3] == 0);
    CHECK(dGeomSphereGetRadius(ball) == REAL(0.5));
    CHECK(dGeomGetPosition(ball)[2] == 4);   // with its body
    dReal aabb[6];
    dGeomGetAABB(box, aabb);
    CHECK_NEAR(aabb[0], 0.5, 1e-6);   // the AABB follows the restored pose

    // Bad input: named, nothing changed.
    dGeomSetPosition(box, 9, 9, 9);
    test_capture_reports();
    CHECK(dSpaceRestore(space, snap, size - 3) == 0);
    CHECK(test_captured_contains("dSpaceRestore: bad snapshot: it is truncated"));
    CHECK(dSpaceRestore(space, wsnap, wsize) == 0);
    CHECK(test_captured_contains("bad magic"));
    CHECK(dSpaceRestore(inner, snap, size) == 0);
    CHECK(test_captured_contains("geoms are not those"));
    CHECK(dSpaceSnapshot((dSpaceID)box, NULL, 0) == 0);
    CHECK(test_captured_contains("not a space"));
    snap[size - 1] ^= 1;
    CHECK(dSpaceRestore(space, snap, size) == 0);
    CHECK(test_captured_contains("checksum"));
    CHECK(test_captured_count() == 5);
    test_release_reports();
    CHECK(dGeomGetPosition(box)[0] == 9);
    free(snap);
    free(wsnap);
    dSpaceDestroy(space);
    dWorldDestroy(w);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_restored_world_continues_bit_identically),
    TEST_CASE(test_settings_and_joint_parameters_are_restored),
    TEST_CASE(test_random_seed_is_restored),
    TEST_CASE(test_file_round_trip),
    TEST_CASE(test_bad_snapshots_are_reported_and_change_nothing),
    TEST_CASE(test_a_changed_world_is_refused),
    TEST_CASE(test_snapshot_size_query),
    TEST_CASE(test_snapshot_bytes_depend_on_the_state_alone),
    TEST_CASE(test_space_round_trip),
    TEST_END
};
