// SPDX-License-Identifier: BSD-3-Clause
//
// test_block_batch.c -- QuickStep's joint blocks updated four at a time
// (quickstep_block_batch.c) must give the same bits as one by one. Each
// scene runs twice, with the batches on and off (dxQuickBlockBatches), and
// the bodies' states are compared after every step: the bench-like
// ragdolls and chains of the replay test, and islands of machines with
// every joint kind (one body and two, limits and motors whose rows are
// coupled to their blocks, contacts of infinite friction). The packing
// itself is checked on made-up blocks: full batches hold blocks of one kind
// on different bodies, and blocks that share a body keep their order.

#include "test.h"
#include "quickstep.h"
#include "replay_scenes.h"

#include <string.h>

// ---- the bench-like scenes ------------------------------------------------------

#define REPLAY_STEPS 150
static dReal state_a[REPLAY_STEPS * SCENE_STATE_SIZE], state_b[REPLAY_STEPS * SCENE_STATE_SIZE];

static void run_replay_scene(int kind, int batches, dReal *states)
{
    dxQuickBlockBatches = batches;
    scene_quick_states(kind, REPLAY_STEPS, states);
    dxQuickBlockBatches = 1;
}

static int check_replay_scene(int kind)
{
    run_replay_scene(kind, 1, state_a);
    run_replay_scene(kind, 0, state_b);
    const int k = first_state_difference(state_a, state_b, REPLAY_STEPS, SCENE_STATE_SIZE);
    if (k >= 0) test_fail(__FILE__, __LINE__, "%s: states differ from step %d", scene_names[kind], k);
    CHECK(k < 0);
    return 0;
}

static int test_ragdolls_step_the_same_either_way(void)
{
    return check_replay_scene(SCENE_RAGDOLLS);
}

static int test_chains_step_the_same_either_way(void)
{
    return check_replay_scene(SCENE_CHAIN);
}

// ---- machines with every joint kind ---------------------------------------------

enum { MACHINES = 7, PARTS = 12, MACHINE_STEPS = 300 };
#define MACHINE_STATE (13 * MACHINES * PARTS)

typedef struct machines {
    dWorldID w;
    dSpaceID space;
    dJointGroupID contacts;
    dGeomID plane, base_geom[MACHINES];
    dBodyID body[MACHINES][PARTS];
} machines;

static dBodyID machine_body(machines *m, int i, int k, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(m->w);
    dMass mass;
    dMassSetBox(&mass, 1, 0.2 + 0.05 * (k % 3), 0.3, 0.2 + 0.04 * (k % 4));
    dBodySetMass(b, &mass);
    dBodySetPosition(b, x, y, z);
    // Each machine starts moving a little differently, so that its limits
    // and contacts come and go at other steps than its neighbours'.
    dBodySetLinearVel(b, 0.3 * (k % 3 - 1) + 0.11 * i, 0.2 * (k % 2) - 0.07 * i, 0.1 * (i % 3));
    dBodySetAngularVel(b, 0.5 * (k % 5) - 0.2 * i, 0.4 * (i % 2), 0.3 * (k % 3));
    m->body[i][k] = b;
    return b;
}

// Machine i at x = 3 i: a base box resting on the ground (contacts of
// infinite friction: a block of two friction rows and its coupled normal
// row), an arm on a hinge, a ball joint with an angular motor, a universal,
// a hinge-2 wheel, a slider, a piston, a fixed joint, a PR, a PU, and
// one-body joints to the world (ball, slider with limits, fixed).
static void machine_build(machines *m, int i)
{
    const dReal x = 3 * (dReal)i;
    dBodyID b[PARTS];
    for (int k = 0; k < PARTS; k++)
        b[k] = machine_body(m, i, k, x + 0.3 * (k % 4), 0.25 * (k / 4), 0.15 + 0.35 * k);
    dBodySetLinearVel(b[0], 0, 0, 0);
    dBodySetAngularVel(b[0], 0, 0, 0);
    m->base_geom[i] = dCreateBox(m->space, 0.6, 0.6, 0.3);
    dGeomSetBody(m->base_geom[i], b[0]);
    dWorldID w = m->w;

    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b[0], b[1]);
    dJointSetHingeAnchor(j, x, 0, 0.4);
    dJointSetHingeAxis(j, 0, 1, 0);
    dJointSetHingeParam(j, dParamLoStop, -0.3);
    dJointSetHingeParam(j, dParamHiStop, 0.2);
    dJointSetHingeParam(j, dParamVel, 1.5);
    dJointSetHingeParam(j, dParamFMax, 2);

    j = dJointCreateBall(w, 0);
    dJointAttach(j, b[1], b[2]);
    dJointSetBallAnchor(j, x + 0.2, 0, 0.7);
    dJointID am = dJointCreateAMotor(w, 0);
    dJointAttach(am, b[1], b[2]);
    dJointSetAMotorMode(am, dAMotorEuler);
    dJointSetAMotorAxis(am, 0, 1, 0, 0, 1);
    dJointSetAMotorAxis(am, 2, 2, 1, 0, 0);
    dJointSetAMotorParam(am, dParamLoStop, -0.2);
    dJointSetAMotorParam(am, dParamHiStop, 0.2);
    dJointSetAMotorParam(am, dParamVel3, 0.5);
    dJointSetAMotorParam(am, dParamFMax3, 1);

    j = dJointCreateUniversal(w, 0);
    dJointAttach(j, b[2], b[3]);
    dJointSetUniversalAnchor(j, x + 0.3, 0.1, 1.1);
    dJointSetUniversalAxis1(j, 1, 0, 0);
    dJointSetUniversalAxis2(j, 0, 1, 0);
    dJointSetUniversalParam(j, dParamLoStop, -0.25);
    dJointSetUniversalParam(j, dParamHiStop, 0.25);
    dJointSetUniversalParam(j, dParamVel2, -1);
    dJointSetUniversalParam(j, dParamFMax2, 3);

    j = dJointCreateHinge2(w, 0);
    dJointAttach(j, b[0], b[4]);
    dJointSetHinge2Anchor(j, x + 0.3, 0.3, 1.5);
    const dReal up[3] = { 0, 0, 1 }, side[3] = { 0, 1, 0 };
    dJointSetHinge2Axes(j, up, side);
    dJointSetHinge2Param(j, dParamSuspensionERP, 0.4);
    dJointSetHinge2Param(j, dParamSuspensionCFM, 0.01);
    dJointSetHinge2Param(j, dParamLoStop, (i % 2) ? 0 : -0.3);
    dJointSetHinge2Param(j, dParamHiStop, (i % 2) ? 0 : 0.3);
    dJointSetHinge2Param(j, dParamVel2, 4);
    dJointSetHinge2Param(j, dParamFMax2, 2);

    j = dJointCreateSlider(w, 0);
    dJointAttach(j, b[0], b[5]);
    dJointSetSliderAxis(j, 0, 0, 1);
    dJointSetSliderParam(j, dParamLoStop, -0.1);
    dJointSetSliderParam(j, dParamHiStop, 0.1);
    dJointSetSliderParam(j, dParamVel, 0.3);
    dJointSetSliderParam(j, dParamFMax, 5);

    j = dJointCreatePiston(w, 0);
    dJointAttach(j, b[3], b[6]);
    dJointSetPistonAnchor(j, x + 0.6, 0.5, 2.2);
    dJointSetPistonAxis(j, 1, 0, 0);
    dJointSetPistonParam(j, dParamLoStop, -0.05);
    dJointSetPistonParam(j, dParamHiStop, 0.05);

    j = dJointCreateFixed(w, 0);
    dJointAttach(j, b[6], b[7]);
    dJointSetFixed(j);

    j = dJointCreatePR(w, 0);
    dJointAttach(j, b[7], b[8]);
    dJointSetPRAnchor(j, x + 0.8, 0.5, 2.9);
    dJointSetPRAxis1(j, 0, 0, 1);
    dJointSetPRAxis2(j, 1, 0, 0);
    dJointSetPRParam(j, dParamLoStop, -0.1);
    dJointSetPRParam(j, dParamHiStop, 0.1);

    j = dJointCreatePU(w, 0);
    dJointAttach(j, b[8], b[9]);
    dJointSetPUAnchor(j, x + 0.9, 0.6, 3.2);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 1, 0);
    dJointSetPUAxis3(j, 0, 0, 1);

    // One-body joints: body 9 hangs from a ball joint to the world, body 10
    // slides along a world axis between stops, body 11 is fixed to the world.
    j = dJointCreateBall(w, 0);
    dJointAttach(j, b[9], 0);
    dJointSetBallAnchor(j, x + 1.2, 0.75, 3.6);
    j = dJointCreateSlider(w, 0);
    dJointAttach(j, b[10], 0);
    dJointSetSliderAxis(j, 1, 0, 0);
    dJointSetSliderParam(j, dParamLoStop, -0.02);
    dJointSetSliderParam(j, dParamHiStop, 0.02);
    dJointSetSliderParam(j, dParamVel, 0.5);
    dJointSetSliderParam(j, dParamFMax, 1);
    j = dJointCreateFixed(w, 0);
    dJointAttach(j, b[11], 0);
    dJointSetFixed(j);
    // body 10 on a hinge to body 11: a two-body block next to one-body ones
    j = dJointCreateHinge(w, 0);
    dJointAttach(j, b[10], b[11]);
    dJointSetHingeAnchor(j, x + 0.9, 0.5, 3.9);
    dJointSetHingeAxis(j, 1, 0, 0);
}

static void machines_build(machines *m)
{
    m->w = dWorldCreate();
    dWorldSetGravity(m->w, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(m->w, 20);
    m->space = dHashSpaceCreate(0);
    m->contacts = dJointGroupCreate(0);
    m->plane = dCreatePlane(m->space, 0, 0, 1, 0);
    for (int i = 0; i < MACHINES; i++) machine_build(m, i);
}

// Contacts of the bases with the ground (infinite friction), a quick step.
static void machines_step(machines *m)
{
    for (int i = 0; i < MACHINES; i++) {
        dContactGeom g[8];
        const int n = dCollide(m->base_geom[i], m->plane, 8, g, sizeof g[0]);
        for (int k = 0; k < n; k++) {
            dContact c;
            memset(&c, 0, sizeof c);
            c.surface.mu = dInfinity;
            c.geom = g[k];
            dJointID j = dJointCreateContact(m->w, m->contacts, &c);
            dJointAttach(j, dGeomGetBody(g[k].g1), dGeomGetBody(g[k].g2));
        }
    }
    dWorldQuickStep(m->w, 0.01);
    dJointGroupEmpty(m->contacts);
}

static void machines_state(const machines *m, dReal *out)
{
    for (int i = 0; i < MACHINES; i++) {
        for (int k = 0; k < PARTS; k++) {
            dBodyID b = m->body[i][k];
            memcpy(out, dBodyGetPosition(b), 3 * sizeof(dReal));
            memcpy(out + 3, dBodyGetQuaternion(b), 4 * sizeof(dReal));
            memcpy(out + 7, dBodyGetLinearVel(b), 3 * sizeof(dReal));
            memcpy(out + 10, dBodyGetAngularVel(b), 3 * sizeof(dReal));
            out += 13;
        }
    }
}

static void machines_destroy(machines *m)
{
    dJointGroupDestroy(m->contacts);
    dSpaceDestroy(m->space);
    dWorldDestroy(m->w);
}

static dReal machine_a[MACHINE_STEPS * MACHINE_STATE], machine_b[MACHINE_STEPS * MACHINE_STATE];

static void run_machines(int batches, dReal *states)
{
    dxQuickBlockBatches = batches;
    machines m;
    machines_build(&m);
    for (int k = 0; k < MACHINE_STEPS; k++) {
        machines_step(&m);
        machines_state(&m, states + (size_t)k * MACHINE_STATE);
    }
    machines_destroy(&m);
    dxQuickBlockBatches = 1;
}

static int test_machines_step_the_same_either_way(void)
{
    dInitODE2(0);
    run_machines(1, machine_a);
    run_machines(0, machine_b);
    dCloseODE();
    const int k = first_state_difference(machine_a, machine_b, MACHINE_STEPS, MACHINE_STATE);
    if (k >= 0) test_fail(__FILE__, __LINE__, "machines: states differ from step %d", k);
    CHECK(k < 0);
    // The scene is alive: the machines moved and stayed finite.
    const dReal *end = machine_a + (size_t)(MACHINE_STEPS - 1) * MACHINE_STATE;
    for (int e = 0; e < MACHINE_STATE; e++) CHECK(end[e] == end[e] && dFabs(end[e]) < 1e6);
    CHECK(dFabs(end[13 * 1 + 2] - machine_a[13 * 1 + 2]) > 1e-3);
    return 0;
}

// ---- the packing ----------------------------------------------------------------

enum { PACK_BLOCKS = 64, PACK_BODIES = 24 };

// Made-up blocks (sizes 2 and 5, one body or two, bodies drawn from
// nbodies) packed; returns the number of full batches, or -1 if the packing
// breaks a rule.
static int check_packing(unsigned seed, int nbodies)
{
    static qs_block blocks[PACK_BLOCKS];
    static const qs_block *bseq[PACK_BLOCKS];
    unsigned r = seed;
    for (int k = 0; k < PACK_BLOCKS; k++) {
        r = r * 1103515245u + 12345u;
        qs_block *b = &blocks[k];
        memset(b, 0, sizeof *b);
        b->n = 2 + (int)((r >> 8) % 2) * 3;   // 2 or 5: few kinds, many batches
        b->two = (int)((r >> 12) % 3) != 0;
        b->o0 = 6 * (int)((r >> 16) % (unsigned)nbodies);
        b->o1 = 6 * (int)(((r >> 16) + 1 + (r >> 24) % (unsigned)(nbodies - 1)) % (unsigned)nbodies);
        bseq[k] = b;
    }
    // Numbers for the copies: every block's J, M, Ainv, rhs and cfm.
    static dReal numbers[PACK_BLOCKS][12 * 6 * 2 + 36 + 12];
    for (int k = 0; k < PACK_BLOCKS; k++) {
        dReal *p = numbers[k];
        for (size_t e = 0; e < sizeof numbers[k] / sizeof(dReal); e++) p[e] = (dReal)(k * 1000 + (int)e);
        blocks[k].J = (qs_v2 *)p;
        blocks[k].M = (qs_v2 *)(p + 72);
        blocks[k].Ainv = p + 144;
        blocks[k].rhs = p + 180;
        blocks[k].cfm = p + 186;
    }
    qs_system sys;
    memset(&sys, 0, sizeof sys);
    sys.nblocks = PACK_BLOCKS;
    sys.nbodies = nbodies;
    sys.bseq = bseq;
    dxArena arena;
    dxArenaInit(&arena);
    qs_group group = { 0, PACK_BLOCKS, 0, 0, 2, 0, 0, 0, 0 };
    dxQuickBatchBlocks(&arena, &sys, &group, 1);
    if (!sys.batches) {   // no full batch: nothing packed
        dxArenaFree(&arena);
        return sys.nbatches == 0 ? 0 : -1;
    }
    int ok = 1, seen = 0, full = 0;
    int place[PACK_BLOCKS];   // each block's entry in the sweep
    for (int t = 0; ok && t < sys.nbatches; t++) {
        const qs_batch *b = &sys.batches[t];
        const int lanes = b->soa ? QS_LANES : 1;
        full += b->soa != NULL;
        for (int i = 0; i < lanes; i++) {
            const qs_block *blk = b->blk[i];
            ok = ok && blk && blk->n == b->blk[0]->n && blk->two == b->blk[0]->two;
            if (!ok) break;
            place[blk - blocks] = t;
            seen++;
            for (int j = 0; j < i; j++) {   // lanes share no body
                const qs_block *o = b->blk[j];
                ok = ok && blk->o0 != o->o0 && !(o->two && blk->o0 == o->o1) &&
                     !(blk->two && (blk->o1 == o->o0 || (o->two && blk->o1 == o->o1)));
            }
            if (b->soa) {   // the lane's copy of its block's numbers
                const int n = blk->n, ne = blk->two ? 12 : 6;
                const dReal *J = (const dReal *)blk->J, *A = b->soa + 2 * QS_LANES * n * ne;
                ok = ok && b->soa[QS_LANES * (ne + 1) + i] == J[13] &&
                     A[QS_LANES * 1 + i] == blk->Ainv[QS_PAD(n)];   // (1, 0): lower triangle
            }
        }
    }
    ok = ok && seen == PACK_BLOCKS && full > 0;
    // Blocks that share a body are swept in bseq's order.
    for (int k = 0; ok && k < PACK_BLOCKS; k++) {
        for (int j = 0; j < k; j++) {
            const qs_block *p = bseq[j], *q = bseq[k];
            const int share = p->o0 == q->o0 || (q->two && p->o0 == q->o1) ||
                              (p->two && (p->o1 == q->o0 || (q->two && p->o1 == q->o1)));
            if (share && place[j] >= place[k]) ok = 0;
        }
    }
    dxArenaFree(&arena);
    return ok ? full : -1;
}

static int test_packing_keeps_the_order_of_blocks_on_a_body(void)
{
    int full = 0;
    for (unsigned seed = 1; seed <= 40; seed++) {
        const int f = check_packing(seed, 12 + (int)(seed % 3) * 10);
        if (f < 0) {
            test_fail(__FILE__, __LINE__, "packing broken for seed %u", seed);
            return 1;
        }
        full += f;
    }
    CHECK(full >= 40);   // most draws make full batches
    return 0;
}

static int test_packing_off_leaves_bseq(void)
{
    qs_system sys;
    memset(&sys, 0, sizeof sys);
    sys.nblocks = 0;
    dxArena arena;
    dxArenaInit(&arena);
    dxQuickBlockBatches = 0;
    sys.batches = (const qs_batch *)&sys;   // anything: must become NULL
    sys.nbatches = 5;
    qs_group group = { 0, 0, 0, 0, 2, 0, 0, 0, 0 };
    dxQuickBatchBlocks(&arena, &sys, &group, 1);
    dxQuickBlockBatches = 1;
    dxArenaFree(&arena);
    CHECK(sys.batches == NULL && sys.nbatches == 0);
    return 0;
}

// ---- the ball form on random numbers --------------------------------------------

enum { FORM_BLOCKS = 20, FORM_BODIES = 48 };

// Random blocks of the ball form (rows 0-2 with J_lin e_a, the others with
// J_lin zero, the second body's -J_lin, M^-1 J^T's linear part im J_lin;
// some angular numbers exactly zero, as a ball row's), four of each kind
// (sizes 3 and 5, one body and two) on different bodies, and four of the
// general form (J_lin random); swept in batches and one by one from the same fc and
// lambdas (some +0): every number must come out the same.
static int check_forms(unsigned seed)
{
    static qs_block blocks[FORM_BLOCKS];
    static const qs_block *bseq[FORM_BLOCKS];
    static dReal numbers[FORM_BLOCKS][12 * 6 * 2 + 36 + 12];
    static qs_row rows[1];   // none coupled
    static dReal inv_mass[FORM_BODIES], fc[2][6 * FORM_BODIES], lambda[2][FORM_BLOCKS * 6 + 1];
    unsigned r = seed;
#define RND() (r = r * 1103515245u + 12345u, (dReal)((int)((r >> 8) % 2001) - 1000) / 250)
    for (int b = 0; b < FORM_BODIES; b++) {
        inv_mass[b] = 1 / (1 + dFabs(RND()));
        for (int e = 0; e < 6; e++) fc[0][6 * b + e] = (b + e) % 5 ? RND() : 0;
    }
    int first = 0;
    for (int k = 0; k < FORM_BLOCKS; k++) {
        qs_block *blk = &blocks[k];
        memset(blk, 0, sizeof *blk);
        const int kind = k % 4, general = k >= 16;
        blk->n = general ? 4 : (kind & 1) ? 5 : 3;
        blk->two = general || kind >= 2;
        blk->o0 = 6 * (2 * k);
        blk->o1 = blk->two ? 6 * (2 * k + 1) : 6 * (FORM_BODIES - 1);
        blk->first = first;
        first += blk->n;
        dReal *p = numbers[k];
        dReal *J = p, *M = p + 72;
        const dReal im0 = inv_mass[blk->o0 / 6], im1 = inv_mass[blk->o1 / 6];
        for (int a = 0; a < blk->n; a++) {
            for (int e = 0; e < 12; e++) J[12 * a + e] = (a + e) % 4 ? RND() : 0;
            for (int e = 0; e < 3; e++) {
                if (!general) J[12 * a + e] = a == e ? 1 : 0;
                J[12 * a + 6 + e] = blk->two ? -J[12 * a + e] : 0;
                M[12 * a + e] = im0 * J[12 * a + e];
                M[12 * a + 6 + e] = blk->two ? im1 * J[12 * a + 6 + e] : 0;
                M[12 * a + 3 + e] = RND();
                M[12 * a + 9 + e] = blk->two ? RND() : 0;
                if (!blk->two) J[12 * a + 9 + e] = 0;
            }
        }
        dReal *A = p + 144;
        const int w = QS_PAD(blk->n);
        for (int c = 0; c < blk->n; c++)
            for (int a = 0; a <= c; a++) A[c * w + a] = A[a * w + c] = RND() / 8;
        blk->J = (qs_v2 *)J;
        blk->M = (qs_v2 *)M;
        blk->Ainv = A;
        blk->rhs = p + 180;
        blk->cfm = p + 186;
        for (int a = 0; a < blk->n; a++) {
            blk->rhs[a] = RND();
            blk->cfm[a] = dFabs(RND()) / 100;
            lambda[0][blk->first + a] = a == 1 ? 0 : RND();
        }
        bseq[k] = blk;
    }
#undef RND
    memcpy(fc[1], fc[0], sizeof fc[0]);
    memcpy(lambda[1], lambda[0], sizeof lambda[0]);
    int full = 0;
    for (int run = 0; run < 2; run++) {
        qs_system sys;
        memset(&sys, 0, sizeof sys);
        sys.nblocks = FORM_BLOCKS;
        sys.nbodies = FORM_BODIES;
        sys.bseq = bseq;
        sys.inv_mass = inv_mass;
        sys.rows = rows;
        sys.fc = fc[run];
        sys.lambda = lambda[run];
        dxArena arena;
        dxArenaInit(&arena);
        qs_group group = { 0, FORM_BLOCKS, 0, 0, 2, 0, 0, 0, 0 };
        dxQuickBlockBatches = run == 0;
        dxQuickBatchBlocks(&arena, &sys, &group, 1);
        dxQuickBlockBatches = 1;
        for (int t = 0; t < sys.nbatches; t++) full += sys.batches[t].soa != NULL;
        for (int sweep = 0; sweep < 5; sweep++) dxQuickSweep(&sys, 0);
        dxArenaFree(&arena);
    }
    CHECK(full == FORM_BLOCKS / QS_LANES);   // every block in a full batch
    CHECK(memcmp(fc[0], fc[1], sizeof fc[0]) == 0);
    CHECK(memcmp(lambda[0], lambda[1], sizeof lambda[0]) == 0);
    CHECK(fc[0][0] != 0 && lambda[0][0] != 0);
    return 0;
}

static int test_ball_form_gives_the_same_bits(void)
{
    for (unsigned seed = 1; seed <= 20; seed++)
        if (check_forms(seed)) return 1;
    return 0;
}

// The cases above again with the sweeps' version without fused
// multiply-adds (quickstep.h: dxQuickFused), the one processors without FMA
// run (where this one has none, the cases above ran it already).
static int test_unfused_version_steps_the_same_either_way(void)
{
    const int fused = dxQuickFused;
    dxQuickFused = 0;
    const int failed = test_ragdolls_step_the_same_either_way() ||
                       test_chains_step_the_same_either_way() ||
                       test_machines_step_the_same_either_way() ||
                       test_ball_form_gives_the_same_bits();
    dxQuickFused = fused;
    CHECK(!failed);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_ragdolls_step_the_same_either_way),
    TEST_CASE(test_chains_step_the_same_either_way),
    TEST_CASE(test_machines_step_the_same_either_way),
    TEST_CASE(test_packing_keeps_the_order_of_blocks_on_a_body),
    TEST_CASE(test_packing_off_leaves_bseq),
    TEST_CASE(test_ball_form_gives_the_same_bits),
    TEST_CASE(test_unfused_version_steps_the_same_either_way),
    TEST_END,
};
