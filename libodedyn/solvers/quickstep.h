// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep.h -- the data of dWorldQuickStep's iteration (quickstep*.c only).
//
// The rows of all islands are solved in one system, in two kinds of
// updates, all for the same mixed LCP A lambda = b + w by projected SOR (see
// quickstep.c):
//  - blocks: a joint's unbounded (equality) rows, up to 6, solved together
//    with the exact inverse of their block of A, each followed by the
//    joint's limit and motor rows coupled to it;
//  - rows: every other row (contacts, limits, motors) on its own, in one
//    array of rows that all look alike: two bodies (a one-body row's second
//    body is a dummy whose numbers are never read: zeros, or for a direct
//    contact row not even written), bounds scaled by a lambda
//    (a friction row's normal force, or a constant 1), so that the update
//    has no branch that depends on the kind of row but one: a one-body row
//    (a contact with the ground, most of them in a heap) skips its second
//    body's zeros, which would add exact zeros.
// Each island has its own range of bodies in fc, of lambda positions, of
// blocks and of rows. lambda and fc start at zero, set while the rows are
// built (an island's fc, then each joint's lambdas), except for contacts
// that start warm (quickstep.c), whose lambdas and their M^-1 J^T are set
// there too.

#ifndef DX_QUICKSTEP_H
#define DX_QUICKSTEP_H

#include "step_internal.h"

#include <float.h>
#include <stdint.h>
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>   // (QS_FUSE's fused pairs)
#endif

typedef struct qs_scratch qs_scratch;

#define QS_MAX_BLOCK 6
#define QS_PAD(n) (((n) + 1) & ~1)   // n rounded up to pairs
// The block updates (quickstep_sweep.c, quickstep_block_batch.c) and the
// blocks' factorizations and couplings (quickstep_build.c) are inlined once
// per block size, so that their loops have constant bounds.
// Built with QS_ANY_SIZE (meson does so under the sanitizers, whose checks
// make that code several times larger and its build many minutes longer),
// one update takes every size, read at run time: the same operations in the
// same order.

#if defined(__GNUC__)
#define QS_INLINE static inline __attribute__((always_inline))
#else
#define QS_INLINE static inline
#endif

// Ask for the cache line holding p (a hint: nothing where the compiler has
// no prefetch).
QS_INLINE void qs_prefetch(const void *p)
{
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

// Pairs of numbers: rows and fc are stored and updated two numbers at a time
// (SSE2 with doubles); the 12 numbers of a row's J are 6 pairs.
#if defined(__GNUC__)
typedef dReal qs_v2 __attribute__((vector_size(2 * sizeof(dReal))));
#define qs_add(x, y) ((x) + (y))
#define qs_sub(x, y) ((x) - (y))
#define qs_mul(x, y) ((x) * (y))
#define qs_neg(x) (-(x))
#define qs_lane(v, i) ((v)[i])
QS_INLINE qs_v2 qs_splat(dReal a)
{
    qs_v2 v = { a, a };
    return v;
}
#else
typedef struct qs_v2 {
    dReal e[2];
} qs_v2;
static inline qs_v2 qs_add(qs_v2 x, qs_v2 y)
{
    qs_v2 v = { { x.e[0] + y.e[0], x.e[1] + y.e[1] } };
    return v;
}
static inline qs_v2 qs_sub(qs_v2 x, qs_v2 y)
{
    qs_v2 v = { { x.e[0] - y.e[0], x.e[1] - y.e[1] } };
    return v;
}
static inline qs_v2 qs_mul(qs_v2 x, qs_v2 y)
{
    qs_v2 v = { { x.e[0] * y.e[0], x.e[1] * y.e[1] } };
    return v;
}
static inline qs_v2 qs_neg(qs_v2 x)
{
    qs_v2 v = { { -x.e[0], -x.e[1] } };
    return v;
}
#define qs_lane(v, i) ((v).e[i])
static inline qs_v2 qs_splat(dReal a)
{
    qs_v2 v = { { a, a } };
    return v;
}
#endif

// Fused multiply-adds. Where QS_FUSE is 1 (GCC on x86-64, ELF and glibc, as
// for dx_clones.h's versions; not built with -Dfused_multiply_add=false:
// DX_NO_FMA), the
// sweeps (quickstep_sweep.c, quickstep_block_batch.c) have a second version
// for processors with AVX2 and FMA (QS_FUSED_VERSION), run while
// dxQuickFused is 1. It passes fu = 1 to qs_madd1, qs_madd and v4_madd
// (quickstep_v4.h): a * b + c rounded once. Every other version passes 0:
// the product rounded, then the sum. Each path of the sweeps (a row alone, a
// block's coupled row, four blocks side by side) uses them at the same
// places, so the paths give the same bits in either version.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) && \
    defined(__GLIBC__) && !defined(DX_NO_FMA)
#define QS_FUSE 1
#define QS_FUSED_VERSION __attribute__((target("avx2,fma")))
#else
#define QS_FUSE 0
#endif

#if QS_FUSE
#if defined(dSINGLE)
#define QS_FMA(a, b, c) __builtin_fmaf(a, b, c)
#else
#define QS_FMA(a, b, c) __builtin_fma(a, b, c)
#endif
#endif

// 1 where the processor has AVX2 and FMA (found when the library is
// loaded) and the sweeps have their fused version; tests set it to 0 to run
// the other (other bits: the two versions round differently).
extern int dxQuickFused;

// a * b + c, rounded once if fu (a constant after inlining).
QS_INLINE dReal qs_madd1(dReal a, dReal b, dReal c, int fu)
{
#if QS_FUSE
    if (fu) return QS_FMA(a, b, c);
#endif
    (void)fu;
    return a * b + c;
}

#if QS_FUSE
// a * b + c lane by lane for pairs, rounded once (one vfmadd for doubles;
// not always inlined, as quickstep_v4.h's v4_fused).
QS_FUSED_VERSION static inline qs_v2 qs_fused(qs_v2 a, qs_v2 b, qs_v2 c)
{
#if defined(dSINGLE)
    const qs_v2 v = { QS_FMA(a[0], b[0], c[0]), QS_FMA(a[1], b[1], c[1]) };
    return v;
#else
    return (qs_v2)_mm_fmadd_pd((__m128d)a, (__m128d)b, (__m128d)c);
#endif
}
#endif

// The same lane by lane for pairs.
QS_INLINE qs_v2 qs_madd(qs_v2 a, qs_v2 b, qs_v2 c, int fu)
{
#if QS_FUSE
    if (fu) return qs_fused(a, b, c);
#endif
    (void)fu;
    return qs_add(qs_mul(a, b), c);
}

// n rows of one joint solved together: with the residuals res (unscaled)
// delta = Ainv res (Ainv: the inverse of the block of A, times sor_w; its
// rows padded to pairs, so that two numbers of delta are made at a time),
// lambda += delta, fc += M^-1 J^T delta; then the joint's rows coupled to it
// (quickstep_sweep.c: the bodies' fc stays in registers meanwhile).
typedef struct qs_block {
    int n;
    int two;          // acts on two bodies (else on o0 only)
    int o0, o1;       // offsets of the bodies in fc
    int first;        // lambda position of its first row; the others follow
    qs_v2 *J, *M;     // n x 6 pairs: J and M^-1 J^T
    dReal *Ainv;      // n x QS_PAD(n) (symmetric, the padding zero): rows as pairs
    dReal *rhs, *cfm; // n: b and cfm/h
    int coupled, ncoupled;   // the joint's rows coupled to the block: rows[coupled...]
} qs_block;

// Up to QS_LANES blocks of the same size, number of bodies and form that
// share no body, updated side by side, one block a lane
// (quickstep_block_batch.c). A full batch has its blocks' numbers copied by
// lane (soa: each number as QS_LANES consecutive numbers, one a lane; then
// those of the coupled rows), without those the rows' structure makes known
// (its form); a batch of one block (soa NULL) is updated on its own as in
// bseq.
#define QS_LANES 4
typedef struct qs_batch {
    const qs_block *blk[QS_LANES];
    const dReal *soa;   // NULL: a single block, blk[0]
    int ncoupled;       // each lane's coupled rows, side by side too (their
                        // numbers after the blocks' in soa); -1: the lanes
                        // differ, each lane's are updated on their own
    int form;           // what soa leaves out (quickstep_block_batch.c)
    int n, two;         // (a full batch's) its blocks' size and bodies, and
    int o0[QS_LANES], o1[QS_LANES], first[QS_LANES];   // each lane's offsets, as
    const int *cpos;    // in blk; per coupled row side by side, each lane's
                        // lambda position, then its bound's (f)
} qs_batch;

// A row updated on its own. With D = sor_w / A_ii and s = |lambda[f]|:
//   lambda[pos] = keep lambda[pos] + rhs - J . fc, clamped to lo s .. hi s
//   (keep = 1 - D cfm_i / h: the update's lambda[pos] - D cfm_i / h
//   lambda[pos] in one product), fc += delta M for the change delta.
// A limit or motor row of a joint with a block is coupled to it: it moves
// the block along, its lambdas changing by g * delta so that the block's
// residuals stay as they were (M and D then include the block's response:
// A_ii becomes its Schur complement). Without this the row would fight a
// much stiffer block and converge very slowly (a stop on a pendulum with a
// light bob). Coupled rows are updated right after their block.
// The numbers of each body are together, the first body's right after the
// scalars: a one-body row (most contacts: with the ground) reads only those,
// never the second body's numbers (which would add exact zeros).
typedef struct qs_row {
    dReal rhs, keep;  // D * b_i, 1 - D * cfm_i / h
    dReal lo, hi;     // bounds, or friction coefficients (-mu, mu)
    int o0, o1;       // offsets of the bodies in fc (o1: the dummy for a one-body row)
    int pos;          // lambda position
    int f;            // lambda position of the normal row, or of the constant 1
    const dReal *g;   // gn numbers: the block's lambda change per unit of delta
    int gfirst;       // the lambda position of the block's first row
    short gn;
    short two;        // 1: acts on two bodies; 0: the second body's numbers are zero
    qs_v2 J[3], M[3];   // D * J_i and M^-1 J_i^T (world frame, plus the block's
    qs_v2 J1[3], M1[3]; // response) of the first body [lin ang], then of the second
} qs_row;

// A joint with a dJointFeedback: its rows' J and lambda positions, kept for
// the forces it applies.
typedef struct qs_feedback {
    dxJoint *joint;
    const dReal *J;        // m x DX_ROW_SKIP
    const int *pos;        // m
    int m;
} qs_feedback;

// An island's part of the system: islands share no body and no row, so
// their sweeps can be interleaved (quickstep.c).
typedef struct qs_island {
    int body0;             // its first body in fc; body0 + nb is its dummy
    int block0, nblocks;   // its blocks, in its joints' order
    int order0, norder;    // its part of order: its rows not coupled to a block
    uint32_t seed;         // of its shuffles
} qs_island;

// The warm start (quickstep.c, quickstep_warm.c): a contact is the same as
// one of the last step if its point moved by at most WARM_TOL times its lever
// arm in the first body's frame and its normal turned by at most
// acos(WARM_COS); it then starts from WARM_SCALE times that one's forces.
#define WARM_TOL ((dReal)0.03)
#define WARM_COS ((dReal)0.95)
#define WARM_SCALE ((dReal)0.8)
// Old contacts nearer to each other than sqrt(WARM_ISO_MIN) are matched by
// the full scan alone (quickstep_warm.c: far above the underflow in either
// precision).
#define WARM_ISO_MIN ((dReal)1e-20)

// A group of islands swept together (quickstep.c): all the step's sweeps of
// one group, then the next, so that a group's numbers stay in the
// first-level cache. Its blocks are a range of bseq, its batches a range of
// batches, its rows a range of seq.
typedef struct qs_group {
    int block0, nblocks;     // its blocks in bseq
    int batch0, nbatches;    // its entries in batches (dxQuickBatchBlocks)
    int islands;             // its islands with blocks
    int rows0, nrows;        // its islands with rows: a range of solve's list
    int seq0, nseq;          // its rows in seq
} qs_group;

// The budget of a group in bytes (quickstep.c): islands are added to a
// group while their rows, blocks, lambdas and fc fit; a bigger island is a
// group alone. Tests set it small, to sweep a scene in many groups.
extern int dxQuickGroupBytes;
// Islands with blocks join a group this many at a time (quickstep.c), past
// the budget if need be, so that their blocks fill batches. Tests set it to
// 1, so that the budget alone cuts a scene's block islands into groups.
extern int dxQuickGroupIslands;

typedef struct dxWarmCache dxWarmCache;
typedef struct qs_warm_entry qs_warm_entry;

typedef struct qs_system {
    int m, nblocks, nrows, norder, nfeedback, nbodies;
    qs_block *blocks;      // in each island's joint order
    qs_row *rows;          // the rows coupled to blocks, and the others
    int *order;            // each island's other rows, in the order of its sweeps
    const qs_block **bseq; // the blocks of all islands, interleaved group by group
    const qs_batch *batches; // bseq packed in batches (NULL: sweep bseq)
    int nbatches;
    const qs_row **seq;    // order of all islands, interleaved group by group, as the
                           // rows themselves (the sweep's loads need no row index
                           // scaled and added)
    unsigned *normal;      // per row in order: the row in order whose lambda bounds it
                           // (a contact's normal row, made before it), else QS_NO_ROW
    dReal *lambda;         // m + 1: the last holds the constant 1
    dReal *fc;             // 6 per body (and island dummy): M^-1 J^T lambda
    qs_feedback *feedback;
    dReal *rates;          // 6 per body: v/h + M^-1 f (build scratch)
    dReal *inv_mass;       // per body (and dummy, unset): the step's dxIslandBodies
    dReal *inv_inertia;    // 12 per body (and dummy, unset)
    int next;              // the next free lambda position (build)
    qs_scratch *scratch;   // per-joint build scratch
    dxWarmCache *warm;     // the world's contact cache (NULL: no contacts yet)
} qs_system;

// A row without a normal row in order (qs_system.normal).
#define QS_NO_ROW (~0u)

// What the build needs about an island (quickstep_build.c).
typedef struct qs_input {
    const dxIslandBodies *bd;
    const dReal *rates;    // v/h + M^-1 f per body, 6 each
    dReal fps, erp, sor_w;
    int body0, nb;         // the island's first body in fc, its number of bodies
    int warm;              // the joint is a contact that starts warm: its normal
                           // row is relaxed with factor 1 (quickstep.c)
} qs_input;

// The largest finite number: a friction coefficient standing in for an
// infinite one keeps 0 * coefficient at 0.
#ifdef dSINGLE
#define QS_BIG FLT_MAX
#else
#define QS_BIG DBL_MAX
#endif

// Count the rows of the islands' joints (count_rows, once per step) and
// allocate the system for all of them (world arena).
void dxQuickSetup(struct dxWorld *w, const dxIsland *islands, int count, qs_system *sys);

// Fill the rows of one island's joints (prepared: bd) and append its blocks
// and rows to the system; *part gets its ranges (seed left as it is). Call
// it for each of dxQuickSetup's islands in their order: part->body0 is set
// (and sys->nbodies moved past the island) at once, the rest may wait for
// later calls (the islands are built in phases over a queue of them,
// quickstep_build.c); the system is complete after the last island's call.
// is, bd and part must stay in place until then.
void dxQuickBuild(struct dxWorld *w, const dxIsland *is, const dxIslandBodies *bd, dReal h,
                  qs_system *sys, qs_island *part);

// The world's contact cache, with room for this step's ncontacts (the last
// step's entries dropped unless it was a quick step); NULL while the world
// has had no contact.
dxWarmCache *dxQuickWarmBegin(struct dxWorld *w, int ncontacts);
// Enter a contact of this step in the cache (stored bodies b0, b1; world
// point; normal and friction directions as in its rows, a missing friction
// direction zero). *found: 1 if it matches one of the last step, whose
// normal force goes to *ln and friction force (world frame) to f.
qs_warm_entry *dxQuickWarmContact(dxWarmCache *c, const struct dxBody *b0,
                                  const struct dxBody *b1, const dReal *point, const dReal *n,
                                  const dReal *t1, const dReal *t2, int *found, dReal *ln,
                                  dReal *f);
// The lambda positions of the entry's normal and friction rows (-1: none).
void dxQuickWarmPositions(qs_warm_entry *e, const int pos[3]);
// Both for a plain contact's numbers r (dxJointContactRows) whose rows take
// the lambda positions from `first` on in r's order: 1 if it matches one of
// the last step, whose friction force (world frame) goes to f[0..3) and
// normal force to f[3]. (dxQuickContact runs the same code inline:
// quickstep_warm_match.h.)
int dxQuickWarmContactRows(dxWarmCache *c, const struct dxBody *b0, const struct dxBody *b1,
                           const dxContactRows *r, int first, dReal f[4]);
// After the solve: this step's contacts get their forces and become the last
// step's.
void dxQuickWarmEnd(struct dxWorld *w, dxWarmCache *c, const dReal *lambda);

// Contacts whose rows go straight from the contact to the solver's rows
// (quickstep_contact.c): 1 (the default) or 0, every contact through the
// generic joint rows (for tests that compare the two: the same results).
extern int dxQuickContactDirect;
// Does joint j take the direct way: a plain contact (DX_JOINT_PLAIN_CONTACT,
// step_internal.h) without feedback between island bodies (no
// kinematic body, whose motion the generic rows fold in)? Inline: it is
// asked of every contact of every step.
static inline int dxQuickContactIsDirect(const dxJoint *j)
{
    if (!dxQuickContactDirect || !(j->flags & DX_JOINT_PLAIN_CONTACT) || j->feedback) return 0;
    const struct dxBody *b1 = dxJointBody(j, 1);
    return !(dxJointBody(j, 0)->flags & DX_BODY_KINEMATIC) &&
           !(b1 && (b1->flags & DX_BODY_KINEMATIC));
}
// Joints of at most QS_MAX_BLOCK rows without friction indices whose
// unbounded rows are one run of two or more (hinge-2, a hinge or universal
// joint at a stop or with a motor, a contact with two infinite friction
// rows) take their block and the rows coupled to it without the general
// search (quickstep_build.c's run_joint): 1 (the default) or 0, every joint
// the general way (for tests that compare the two: the same results).
extern int dxQuickRunJoints;
// Append the rows of such a contact to the system (lambda positions from
// sys->next on), enter it in the warm-start cache and start it from the
// last step's forces if it was there; the same rows, bit for bit, as the
// generic build makes from its joint rows.
void dxQuickContact(const qs_input *in, dxJoint *j, qs_system *sys);

// Pack sys->bseq in batches (sys->batches; NULL when there would be no full
// batch): each block in the first batch after every batch holding an earlier
// block on one of its bodies, so that blocks sharing a body keep their order
// and each is updated exactly as in bseq (the same bits). Once per step,
// each of the ngroups groups' blocks apart (their batches a range of
// batches: batch0, nbatches): one island's blocks (a chain) mostly share
// bodies, so those of a group of fewer than two islands are left as in bseq.
void dxQuickBatchBlocks(dxArena *a, qs_system *sys, qs_group *groups, int ngroups);
// 1 (the default): dxQuickBatchBlocks packs; 0: it leaves bseq alone (for
// tests that compare the two: the same results).
extern int dxQuickBlockBatches;
// A full batch's update: each lane's block and then its coupled rows.
void dxQuickBatchUpdate(const qs_batch *b, const qs_row *rows, dReal *lambda, dReal *fc);
// The coupled rows of one block (quickstep_sweep.c), its bodies' fc read
// from fc and stored back.
void dxQuickCoupledRows(const qs_block *blk, const qs_row *rows, dReal *lambda, dReal *fc);

// The room of dxQuickBuild's queue, in joints (the default 256); 0: each
// island is built right away, as in steps of contacts alone or of large
// islands (for tests that compare the two: the same results).
extern int dxQuickBuildJoints;

// One reshuffle of an island's n rows in order (quickstep.c), for tests that
// compare it with the plain form (a Fisher-Yates shuffle, then a pass
// upwards swapping each friction row found before its normal row with it):
// state: the island's generator; base: one the last reshuffle's places do
// not meet (the solver's: 0 and n in turn, quickstep.c's reshuffle_base);
// per row index, normal: its normal row in order or ~0u, at: scratch, ~0u
// for every row before the step's first reshuffle, and at[-1] scratch too.
void dxQuickReshuffle(int *order, int n, uint32_t *state, unsigned base, const unsigned *normal,
                      unsigned *at);
// 1 (the default): the shuffles' random places with AVX2 where the processor
// has it; 0: the baseline (for tests that compare the two: the same numbers).
extern int dxQuickShuffleAVX2;

// `iterations` sweeps, one after the other, over the n blocks blk (in
// order; each followed by its coupled rows) of an island without free rows,
// overlapped: sweep s's block k at time k + s lag, the blocks of one time by
// sweep. Blocks lag apart or more must share no body: then each body sees
// its updates in the order of the sweeps one after the other (the same
// bits), while consecutive updates are of different sweeps and share no
// body, which the processor overlaps (a chain, lag 2: link k of one sweep,
// link k - 2 of the next, ...), and the island's numbers are read once, a
// few blocks at a time, instead of once a sweep (quickstep.c).
void dxQuickSweepOverlapped(const qs_system *sys, const qs_block *blk, int n, int lag,
                            int iterations);
// 1 (the default): islands of blocks alone that pay are swept overlapped
// (quickstep.c); 0: one sweep after the other (for tests that compare the
// two: the same results).
extern int dxQuickOverlapSweeps;

// One sweep over all blocks in bseq (each followed by its coupled rows) and
// all rows in seq: the blocks first, or (rows_first) the rows.
void dxQuickSweep(const qs_system *sys, int rows_first);
// to[0, n) = the rows rows + from[0, n) (a sweep's seq from its order; with
// AVX2 four at a time).
void dxQuickRowsOf(const qs_row **to, const qs_row *rows, const int *from, int n);

#endif
