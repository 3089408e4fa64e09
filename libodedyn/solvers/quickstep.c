// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep.c -- dWorldQuickStep: the iterative stepper (guide 5.1). Per
// island it solves the same mixed LCP as dWorldStep,
//   A lambda = b + w,  A = J M^-1 J^T + cfm/h,  b = c/h - J (v/h + M^-1 f),
// but by projected successive over-relaxation (Gauss-Seidel with the factor
// sor_w = dWorldGetQuickStepW) instead of pivoting: O(m) memory and O(m N)
// time for m rows and N iterations. A is never formed: the vector
// fc = M^-1 J^T lambda (6 numbers per body) is kept up to date, so the
// residual of a row is b_i - cfm_i/h lambda_i - J_i fc, in O(1). Friction
// rows are bounded by +-mu times the current force of their normal row. The
// new velocities are v + h (M^-1 f + fc).
//
// With 20 iterations the answer is far from converged on a big stack, and
// the order of the updates decides where the error goes. A sweep updates
// the joints' equality blocks in the island's order (which carries forces
// along chains), each block followed by the limit and motor rows coupled to
// it, and every other row on its own: the blocks first in even sweeps, the
// rows first in odd ones, so that neither the joints nor the contacts always
// have the last word (always the contacts: ragdolls' joints come apart a
// third more than with ODE). The rows are shuffled before the first sweep
// and every REORDER_PERIOD sweeps, with one rule: a friction row comes after
// its normal row (not next to it), so that its bound is the normal force of
// the same sweep (bounded by the previous sweep's, as about half of them are
// in a plain shuffle, a tower of boxes sways twice as much). The generator
// is seeded from the island's state (positions and velocities): the order
// differs from step to step, yet a step is reproducible and independent of
// the other islands. Any fixed relation in the order leaves a bias that adds
// up over the steps:
//  - all normal rows before all friction rows (as this file once did) gives
//    the friction rows the last word in every step: their torques about the
//    boxes' centres undo part of the normal rows' work, contacts sink faster
//    than they are corrected, and a 20-layer pyramid of boxes collapses;
//  - a contact's normal and friction rows always next to each other make a
//    pyramid spread sideways (25 cm in 10 s at 20 layers);
//  - the same order in every step makes a stack creep.
//
// Islands share no body and no row, so their sweeps are interleaved row by
// row: each island sees exactly the updates it would see alone, and the
// processor gets independent rows to overlap (small islands, as ragdolls,
// are otherwise one long chain of dependent updates). They are interleaved
// in groups that fit the first-level cache (dxQuickGroupBytes): all the
// sweeps of one group, then the next, so that a group's rows and blocks are
// read from the cache in its 20 sweeps instead of streaming the whole
// system through it in every sweep. A long island of blocks alone (a chain
// of links, whose blocks each wait for the one before) is swept on its own,
// its sweeps overlapped (dxQuickSweepOverlapped): each body sees its updates
// in the same order, so the results are the same bits. (Its blocks in
// another order, red-black for a chain, made hanging chains come apart
// three times as far: docs/perf.md.)
//
// Warm start. Contacts do not start from lambda = 0 but from the forces of
// the same contact in the last step, when there is one: contact joints are
// made anew for every step, so quickstep_warm.c finds them again by body
// pair, point and normal in the first body's frame (a world-owned cache,
// reused from step to step), only right after a quick step of the same
// world. The starting forces are WARM_SCALE (0.8) times the old ones,
// projected on the rows' bounds, with fc = M^-1 J^T lambda to match
// (quickstep_build.c). The problem is the same, only the iteration starts
// elsewhere: with many iterations the answer is the cold start's, and
// feedback reports the final forces. With 20 iterations a tall stack gets
// the support it had instead of building it up again in every step (a
// 40-layer pyramid of boxes stands: 140 of 820 boxes fell from cold starts;
// 50 layers stand, and 40 layers with 10 iterations). Two limits, measured:
//  - all of the old force (a scale of 0.9 or more) carries last step's
//    penetration correction over again: tall pyramids gain energy and blow
//    apart;
//  - over-relaxing a warm normal row overshoots the support it already
//    nearly has, and the overshoot is carried to the next step: a column of
//    5 boxes rocked (2.4 cm of drift, 0.45 cm cold). A warm contact's
//    normal row is relaxed with factor 1 (plain Gauss-Seidel), its friction
//    rows and every cold row with sor_w (0.1 cm of drift).
// Only contacts start warm: other joints' forces carried over the same way
// made a swinging 100-link chain come apart further (joint_sep 1.69 m to
// 1.99 m against 1.52 m cold), and ragdolls gained nothing.

#include "quickstep.h"
#include "step_threads.h"

#include <string.h>

#define REORDER_PERIOD 8

// dxQuickGroupBytes' default: islands are swept in groups that fit the
// first-level cache (docs/perf.md measures it).
#define QS_GROUP_BYTES 32768

// dxQuickGroupIslands' default: islands with blocks join a group this many
// at a time, even past the budget, so that their blocks fill batches of four (dxQuickBatchBlocks):
// in fours, 16 cars' contact blocks (which differ from car to car) filled
// fewer batches and the vehicle bench took 3.9 % more instructions and 6 %
// more time; in sixteens it is one group as before, and the ragdolls and
// the rain keep most of their fewer misses (docs/perf.md).
#define QS_GROUP_ISLANDS (4 * QS_LANES)

// The generator is counter-based: the i-th number (i = 1, 2, ...) from a
// state s is a hash of s + i * RANDOM_STEP, so that the numbers do not wait
// for each other and a shuffle makes them RANDOM_BLOCK at a time (vectorized
// where the machine allows) before its swaps, which must go one by one.
#define RANDOM_STEP 0x9e3779b9u
#define RANDOM_BLOCK 256

// random_places has a version for AVX2 (x86-64, GCC or clang), taken when the
// processor has it (the same numbers either way): -DQS_SHUFFLE_AVX2=0 leaves
// the baseline alone, to compare the two.
#if !defined(QS_SHUFFLE_AVX2)
#if defined(__x86_64__) && defined(__GNUC__)
#define QS_SHUFFLE_AVX2 1
#else
#define QS_SHUFFLE_AVX2 0
#endif
#endif
#if QS_SHUFFLE_AVX2
#include <immintrin.h>
#endif

// The generator's number from state x (the state already advanced).
QS_INLINE uint32_t random_hash(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

#if QS_SHUFFLE_AVX2
// random_places eight at a time: the hash with vpmulld, the products of the
// even and the odd 32-bit lanes with vpmuludq, their high halves blended.
// The last eight may reach past count (j has room for RANDOM_BLOCK, a
// multiple of eight): those places are never read.
__attribute__((target("avx2"))) static unsigned random_places_avx2(uint32_t state, unsigned lo,
                                                                   unsigned count, unsigned *j)
{
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i step = _mm256_set1_epi32((int)RANDOM_STEP);
    const __m256i c1 = _mm256_set1_epi32(0x7feb352d), c2 = _mm256_set1_epi32((int)0x846ca68bu);
    __m256i x = _mm256_sub_epi32(_mm256_set1_epi32((int)(state + count * RANDOM_STEP)),
                                 _mm256_mullo_epi32(lane, step));
    __m256i m = _mm256_add_epi32(_mm256_set1_epi32((int)(lo + 1)), lane);
    const __m256i x8 = _mm256_set1_epi32((int)(8 * RANDOM_STEP)), m8 = _mm256_set1_epi32(8);
    unsigned i = 0;
    for (; i < count; i += 8) {
        __m256i h = _mm256_xor_si256(x, _mm256_srli_epi32(x, 16));
        h = _mm256_mullo_epi32(h, c1);
        h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 15));
        h = _mm256_mullo_epi32(h, c2);
        h = _mm256_xor_si256(h, _mm256_srli_epi32(h, 16));
        const __m256i even = _mm256_srli_epi64(_mm256_mul_epu32(h, m), 32);
        const __m256i odd =
            _mm256_mul_epu32(_mm256_srli_epi64(h, 32), _mm256_srli_epi64(m, 32));
        _mm256_storeu_si256((__m256i *)(j + i), _mm256_blend_epi32(even, odd, 0xaa));
        x = _mm256_sub_epi32(x, x8);
        m = _mm256_add_epi32(m, m8);
    }
    return i;
}
#endif

int dxQuickShuffleAVX2 = 1;

// The places j[i] in [0, lo + i] that a Fisher-Yates shuffle's steps
// k = lo + i (i = 0 .. count - 1) swap with, from the state's next count
// numbers, the first for the highest k: a uniform index in [0, k] by
// multiply-shift. avx2: the processor has it and dxQuickShuffleAVX2 asks
// for it (found once a step).
QS_INLINE void random_places(uint32_t state, unsigned lo, unsigned count, unsigned *j, int avx2)
{
    unsigned i = 0;
#if QS_SHUFFLE_AVX2
    if (avx2) i = random_places_avx2(state, lo, count, j);
#else
    (void)avx2;
#endif
    for (; i < count; i++) {
        const uint32_t x = random_hash(state + (count - i) * RANDOM_STEP);
        j[i] = (unsigned)(((uint64_t)x * (lo + i + 1)) >> 32);
    }
}

// What the reshuffles of a step need, per row of the system (row index):
// normal: the row that bounds it if that one is in its island's order (a
// friction row's normal row: sys->normal, made with the rows), else
// QS_NO_ROW; at: where the current reshuffle put the row, plus that
// reshuffle's base (below), and at[-1] (QS_NO_ROW's place, as a signed
// index) a row that is never placed. Unsigned: row indices index without
// widening.
typedef struct qs_reorder {
    const unsigned *normal;
    unsigned *at;
    int avx2;   // random_places with AVX2
} qs_reorder;

// Whether random_places takes its AVX2 version.
static int shuffle_avx2(void)
{
#if QS_SHUFFLE_AVX2
    return dxQuickShuffleAVX2 && __builtin_cpu_supports("avx2");
#else
    return 0;
#endif
}

// The base of an island's g-th reshuffle of a step, for its n rows: at[r]
// minus it is below n exactly for the rows the reshuffle has placed (at[]
// holds the last or this reshuffle's places, or ~0 from the step's start;
// unsigned arithmetic wraps). Each reshuffle places every row of the
// island, so the bases need only differ from the last one's: 0 and n in
// turn. Then at[-1] = ~0u (reorder_begin) is never placed (~0u - base >= n
// for n < 2^31), set once for all islands: threads that sweep islands
// side by side share at[].
static unsigned reshuffle_base(int g, int n)
{
    return (unsigned)(g & 1) * (unsigned)n;
}

// Row r has just been put at place k by the shuffle (the places above k are
// final; those below are not yet). A friction row must come after its
// normal row: if r's normal row is already above, the normal row moves to k,
// r to the place where the shuffle put the normal row, and the friction row
// of the same contact that went there before (one above r) back to its own
// place. So the normal row ends up at the lowest place of its rows, and the
// friction row that had it at the normal row's: exactly what one pass
// upwards swapping each friction row found before its normal row with it
// gives (the two-pass form this replaced), as the contacts' rows are
// disjoint groups (only a contact's friction rows are bounded by a row, and
// a normal row by the constant 1). A row without a normal row looks up
// at[-1], never placed (reshuffle_base): one branch, not two, on whether the row
// moves, as both follow the random order (a mispredict in two or three rows).
QS_INLINE void place(unsigned *o, size_t k, unsigned r, unsigned base, unsigned n,
                     unsigned *at, const unsigned *normal)
{
    at[r] = base + (unsigned)k;
    const unsigned nr = normal[r];
    const unsigned a = at[(int)nr] - base;   // QS_NO_ROW: at[-1]
    if (a >= n) return;        // no normal row, or it comes below k
    const unsigned f = o[a];   // nr, or a friction row that took its place
    o[at[f] - base] = f;
    o[a] = r;
    o[k] = nr;
}

// Shuffle an island's n rows order[0, n) (Fisher-Yates, downwards) with its
// generator state, each friction row after its normal row (place); base:
// reshuffle_base.
QS_INLINE void reshuffle(int *order, int n, uint32_t *state, unsigned base, const qs_reorder *re)
{
    unsigned j[RANDOM_BLOCK];
    unsigned *o = (unsigned *)order, *at = re->at;
    const unsigned *normal = re->normal;
    uint32_t s = *state;
    for (size_t top = n > 1 ? (size_t)n - 1 : 0; top > 0;) {
        const size_t count = top < RANDOM_BLOCK ? top : RANDOM_BLOCK, lo = top - count + 1;
        random_places(s, (unsigned)lo, (unsigned)count, j, re->avx2);
        s += (uint32_t)count * RANDOM_STEP;
#if defined(__GNUC__)
#pragma GCC unroll 4
#endif
        for (size_t k = top; k >= lo; k--) {
            const unsigned r = o[j[k - lo]];
            o[j[k - lo]] = o[k];
            o[k] = r;
            place(o, k, r, base, (unsigned)n, at, normal);
        }
        top = lo - 1;
    }
    if (n > 0) place(o, 0, o[0], base, (unsigned)n, at, normal);
    *state = s;
}

void dxQuickReshuffle(int *order, int n, uint32_t *state, unsigned base, const unsigned *normal,
                      unsigned *at)
{
    at[-1] = base - 1;   // never placed, whatever the base (reshuffle_base)
    const qs_reorder re = { normal, at, shuffle_avx2() };
    reshuffle(order, n, state, base, &re);
}

// The step's passes over an island's bodies (island_seed, finish_island)
// ask for the lines of the body this many places ahead while they work on
// the current one: the bodies lie far apart, in an order the hardware
// prefetchers cannot follow, and their lines have left the first-level
// cache since collision and the island walk (docs/perf.md: about half of
// dWorldQuickStep's own time waited on them in ragdolls).
#define BODY_AHEAD 4

// Ask for the line holding p and the one holding p + bytes - 1.
QS_INLINE void prefetch_span(const void *p, size_t bytes)
{
    qs_prefetch(p);
    qs_prefetch((const char *)p + bytes - 1);
}

// Ask for the lines island_seed reads of body b.
QS_INLINE void prefetch_seed(const struct dxBody *b)
{
    prefetch_span(b->pos, sizeof(dReal) * 3);
    prefetch_span(b->lvel, (size_t)((const char *)(b->avel + 3) - (const char *)b->lvel));
}

// Ask for the lines the set-up reads of body b (island_seed,
// dxIslandPrepareAt): from its mass to its gyroscopic fields, every other
// line (the second-level cache's prefetcher brings each one's pair).
QS_INLINE void prefetch_setup(const struct dxBody *b)
{
    const char *p = (const char *)&b->mass, *end = (const char *)(&b->gyro_pending + 1);
    for (; p < end; p += 128) qs_prefetch(p);
    qs_prefetch(end - 1);
}

// A seed from the bits of the island's positions and velocities (FNV-1a
// over their words, in three independent lanes): the same state gives the
// same seed.
static uint32_t island_seed(const dxIsland *is)
{
    uint64_t hash[3] = { 0xcbf29ce484222325u, 0x84222325cbf29ce4u, 0x9e3779b97f4a7c15u };
    for (int b = 0; b < is->nb; b++) {
        if (b + BODY_AHEAD < is->nb) prefetch_seed(is->bodies[b + BODY_AHEAD]);
        const struct dxBody *body = is->bodies[b];
        const dReal *v[3] = { body->pos, body->lvel, body->avel };
        for (int k = 0; k < 3; k++) {
            for (int e = 0; e < 3; e++) {
                uint64_t word = 0;
                memcpy(&word, &v[k][e], sizeof(dReal));
                hash[e] = (hash[e] ^ word) * 0x100000001b3u;
            }
        }
    }
    const uint64_t h = hash[0] ^ (hash[1] * 0x9e3779b97f4a7c15u) ^ (hash[2] >> 7);
    return (uint32_t)(h ^ (h >> 32));
}

// How many blocks (block = 1) or rows (block = 0) an island has.
static int island_length(const qs_island *p, int block)
{
    return block ? p->nblocks : p->norder;
}

// list[0, n) (islands) in tmp, longest first and the same length in list's
// order, by counting (O(n + longest); counters from arena a).
static void sort_by_counting(const qs_island *parts, int block, const int *list, int n,
                             int longest, int *tmp, dxArena *a)
{
    int *start = DX_ARENA_ARRAY(a, int, longest + 1);
    for (int len = 0; len <= longest; len++) start[len] = 0;
    for (int k = 0; k < n; k++) start[island_length(&parts[list[k]], block)]++;
    int before = 0;   // islands longer than len
    for (int len = longest; len > 0; len--) {
        const int c = start[len];
        start[len] = before;
        before += c;
    }
    for (int k = 0; k < n; k++) tmp[start[island_length(&parts[list[k]], block)]++] = list[k];
}

// The islands with blocks (block = 1) or rows (block = 0) into list, longest
// first and the same length in island order; returns how many. tmp: scratch
// for count. (A stable sort: by counting when the islands are many next to
// their lengths, as many small ones; else bottom-up merging, O(n log n).)
static int islands_by_length(const qs_island *parts, int count, int block, int *list, int *tmp,
                             dxArena *a)
{
    int n = 0, longest = 0;
    for (int i = 0; i < count; i++) {
        const int len = island_length(&parts[i], block);
        if (len > 0) list[n++] = i;
        if (len > longest) longest = len;
    }
    if (n > 1 && longest <= 8 * n) {
        sort_by_counting(parts, block, list, n, longest, tmp, a);
        memcpy(list, tmp, sizeof(int) * (size_t)n);
        return n;
    }
    int *from = list, *to = tmp;
    for (int width = 1; width < n; width *= 2) {
        for (int lo = 0; lo < n; lo += 2 * width) {
            const int mid = lo + width < n ? lo + width : n;
            const int hi = lo + 2 * width < n ? lo + 2 * width : n;
            int a = lo, b = mid, out = lo;
            while (a < mid || b < hi) {
                const int la = a < mid ? island_length(&parts[from[a]], block) : -1;
                const int lb = b < hi ? island_length(&parts[from[b]], block) : -1;
                to[out++] = la >= lb ? from[a++] : from[b++];
            }
        }
        int *t = from;
        from = to;
        to = t;
    }
    if (from != list) memcpy(list, from, sizeof(int) * (size_t)n);
    return n;
}

// Round robin over the islands in list (longest first): the t-th block of
// each island that has one, for t = 0, 1, ..., into to.
static void interleave_blocks(const qs_system *sys, const qs_island *parts, const int *list,
                              int n, const qs_block **to)
{
    int out = 0;
    for (int t = 0; n > 0; t++) {
        while (n > 0 && parts[list[n - 1]].nblocks <= t) n--;
        for (int k = 0; k < n; k++) to[out++] = &sys->blocks[parts[list[k]].block0 + t];
    }
}

// The reshuffles' data for the step (a: the world arena): each row's normal
// row (made with the rows), and at[] from ~0.
static qs_reorder reorder_begin(dxArena *a, qs_system *sys)
{
    unsigned *at = DX_ARENA_ARRAY(a, unsigned, sys->nrows + 2) + 1;   // and at[-1]
    const int *order = sys->order, n = sys->norder;
    at[-1] = ~0u;
    for (int k = 0; k < n; k++) at[order[k]] = ~0u;
    qs_reorder re = { sys->normal, at, shuffle_avx2() };
    return re;
}

// The step's g-th reshuffle of the n islands in list, each with its own
// generator (one call for all: most islands are a few rows).
static void reshuffle_islands(const qs_system *sys, qs_island *parts, const int *list, int n,
                              int g, const qs_reorder *re)
{
    for (int k = 0; k < n; k++) {
        qs_island *p = &parts[list[k]];
        reshuffle(sys->order + p->order0, p->norder, &p->seed, reshuffle_base(g, p->norder), re);
    }
}

// After every reshuffle: seq gets the t-th row of each island in list
// (longest first) that has one, for t = 0, 1, ...: in runs of c islands for
// the rows t0 to t1 of the c-th longest, island by island where the run is
// long, else row by row (many short islands); the longest one's rows beyond
// the second's (all of them if n is 1) in one pass (dxQuickRowsOf), the rows
// themselves (qs_system.seq). from: scratch for n pointers.
static void interleave_rows(const qs_system *sys, const qs_island *parts, const int *list, int n,
                            const int **from)
{
    const qs_row *rows = sys->rows;
    for (int k = 0; k < n; k++) from[k] = sys->order + parts[list[k]].order0;
    int out = 0, t0 = 0;
    for (int c = n; c > 1; c--) {
        const int t1 = parts[list[c - 1]].norder;
        if (t1 <= t0) continue;
        const qs_row **seq = sys->seq + out;
        if (t1 - t0 >= c) {
            for (int k = 0; k < c; k++) {
                const qs_row **to = seq + k;
                for (int t = t0; t < t1; t++, to += c) *to = rows + from[k][t];
            }
        } else {
            for (int t = t0; t < t1; t++)
                for (int k = 0; k < c; k++) *seq++ = rows + from[k][t];
        }
        out += (t1 - t0) * c;
        t0 = t1;
    }
    dxQuickRowsOf(sys->seq + out, rows, from[0] + t0, parts[list[0]].norder - t0);
}

int dxQuickGroupBytes = QS_GROUP_BYTES;
int dxQuickGroupIslands = QS_GROUP_ISLANDS;

// The bytes island p's sweeps go through: its rows (the free ones and those
// coupled to its blocks) and their places in seq, its blocks' numbers (or
// their copies in batches), its lambdas, and its bodies' fc (nb1: its
// bodies and dummy).
static size_t island_bytes(const qs_system *sys, const qs_island *p, int nb1)
{
    size_t rows = (size_t)p->norder, numbers = 6 * (size_t)nb1 + (size_t)p->norder;
    for (int k = p->block0; k < p->block0 + p->nblocks; k++) {
        const qs_block *blk = &sys->blocks[k];
        const size_t n = (size_t)blk->n;
        rows += (size_t)blk->ncoupled;
        numbers += n * (24 + QS_PAD(n) + 2) + n + (size_t)blk->ncoupled;
    }
    return rows * sizeof(qs_row) + (size_t)p->norder * sizeof(int) +
           (size_t)p->nblocks * sizeof(qs_block) + numbers * sizeof(dReal);
}

// The islands in groups of at most dxQuickGroupBytes (island_bytes; a
// bigger island alone, and islands with blocks dxQuickGroupIslands at a time, which may pass
// it), in the order of blist (the nb islands with blocks, longest
// first: alike ones together, so that a group's blocks make full batches)
// and then of rlist's islands without blocks (the nr islands with rows,
// longest first); returns the number of groups. Each group gets its
// blocks in bseq, interleaved (interleave_blocks), and its islands with
// rows as a range of rlist, which is reordered group by group (stable:
// longest first within a group); its rows' range of seq. group_of, tmp:
// scratch for count islands.
static int make_groups(const qs_system *sys, const qs_island *parts, int count,
                       const int *blist, int nb, int *rlist, int nr, qs_group *groups,
                       int *group_of, int *tmp)
{
    const size_t budget = (size_t)dxQuickGroupBytes;
    int ng = 0;
    size_t bytes = 0;
    int total = nb;   // islands to group (one: no bytes to count)
    for (int k = 0; k < nr; k++) total += parts[rlist[k]].nblocks == 0;
    for (int i = 0; i < count; i++) group_of[i] = -1;
    for (int k = 0; k < nb + nr; k++) {
        const int i = k < nb ? blist[k] : rlist[k - nb];
        if (k >= nb && parts[i].nblocks > 0) continue;   // grouped by blist
        const int end = i + 1 < count ? parts[i + 1].body0 : sys->nbodies;
        // Islands with blocks join a group dxQuickGroupIslands at a time.
        const size_t b = total > 1 ? island_bytes(sys, &parts[i], end - parts[i].body0) : 0;
        const int fill = k < nb && ng > 0 && groups[ng - 1].islands % dxQuickGroupIslands;
        if (ng == 0 || (bytes + b > budget && !fill)) {
            qs_group *g = &groups[ng++];
            memset(g, 0, sizeof *g);
            g->block0 = ng > 1 ? groups[ng - 2].block0 + groups[ng - 2].nblocks : 0;
            bytes = 0;
        }
        bytes += b;
        qs_group *g = &groups[ng - 1];
        group_of[i] = ng - 1;
        if (parts[i].nblocks > 0) {
            g->nblocks += parts[i].nblocks;
            g->islands++;
        }
    }
    // Blocks: each group's islands are a range of blist, as they came.
    for (int k = 0, first = 0; k < ng; k++) {
        interleave_blocks(sys, parts, blist + first, groups[k].islands,
                          sys->bseq + groups[k].block0);
        first += groups[k].islands;
    }
    // Rows: rlist by group, counting.
    for (int k = 0; k < nr; k++) groups[group_of[rlist[k]]].nrows++;
    for (int g = 0, at = 0; g < ng; g++) {
        groups[g].rows0 = at;
        at += groups[g].nrows;
        groups[g].nrows = 0;
    }
    for (int k = 0; k < nr; k++) {
        qs_group *g = &groups[group_of[rlist[k]]];
        tmp[g->rows0 + g->nrows++] = rlist[k];
        g->nseq += parts[rlist[k]].norder;
    }
    for (int g = 1; g < ng; g++) groups[g].seq0 = groups[g - 1].seq0 + groups[g - 1].nseq;
    memcpy(rlist, tmp, sizeof(int) * (size_t)nr);
    return ng;
}

// The part of sys that group g sweeps: its blocks or batches, its rows in
// seq.
static qs_system group_system(const qs_system *sys, const qs_group *g)
{
    qs_system one = *sys;
    one.bseq = sys->bseq + g->block0;
    one.nblocks = g->nblocks;
    if (sys->batches) {
        one.batches = sys->batches + g->batch0;
        one.nbatches = g->nbatches;
    }
    one.norder = g->nseq;
    one.seq = sys->seq + g->seq0;
    return one;
}

// Islands of blocks alone (no free rows) with at least this many blocks,
// and this many times their lag (below) or more, have all their sweeps
// overlapped (dxQuickSweepOverlapped).
#define QS_OVERLAP_BLOCKS 16
#define QS_OVERLAP_SWEEPS 4

int dxQuickOverlapSweeps = 1;

// The sweeps' lag for island p (nb1: its bodies and dummy) if they are to
// be overlapped, else 0. An island of blocks alone sweeps its blocks in
// order, one sweep after the other; blocks lag apart or more in that order
// share no body (lag: one more than the most blocks apart two blocks on one
// body are), so all its sweeps can be overlapped, sweep s's block k at time
// k + s lag, and about n / lag sweeps of its n blocks go side by side. A
// chain of links (lag 2) pays: each of its blocks shares a body with the one
// before, so its sweep in order is one long chain of dependent updates.
// Others do not: small islands overlap with the other islands of their
// group instead, and a car's blocks on its chassis are far apart in its
// order. first: scratch for nb1 numbers.
static int overlap_lag(const qs_system *sys, const qs_island *p, int nb1, int *first)
{
    const int n = p->nblocks;
    if (!dxQuickOverlapSweeps || p->norder > 0 || n < QS_OVERLAP_BLOCKS) return 0;
    for (int b = 0; b < nb1; b++) first[b] = -1;   // per body: its first block, -1 none
    const qs_block *blk = sys->blocks + p->block0;
    int lag = 1;
    for (int k = 0; k < n && QS_OVERLAP_SWEEPS * lag <= n; k++) {
        const int b[2] = { blk[k].o0 / 6 - p->body0, blk[k].o1 / 6 - p->body0 };
        for (int e = 0; e < 1 + (blk[k].two != 0); e++) {
            if (first[b[e]] < 0) first[b[e]] = k;
            lag = k - first[b[e]] + 1 > lag ? k - first[b[e]] + 1 : lag;
        }
    }
    return QS_OVERLAP_SWEEPS * lag <= n ? lag : 0;
}

// `iterations` sweeps over all islands, group by group (make_groups), each
// island's rows reshuffled every REORDER_PERIOD with its own generator, the
// odd sweeps going through the rows before the blocks, the blocks in
// batches (a: the world arena). list, tmp: scratch for count islands.
static void solve(dxArena *a, qs_system *sys, qs_island *parts, int count, int iterations,
                  int *list, int *tmp)
{
    int with_blocks = islands_by_length(parts, count, 1, list, tmp, a);
    // Islands whose sweeps are overlapped are no group's.
    int kept = 0, *first = DX_ARENA_ARRAY(a, int, sys->nbodies);
    for (int k = 0; k < with_blocks; k++) {
        const int i = list[k];
        const int end = i + 1 < count ? parts[i + 1].body0 : sys->nbodies;
        const int lag = overlap_lag(sys, &parts[i], end - parts[i].body0, first);
        if (lag > 0)
            dxQuickSweepOverlapped(sys, sys->blocks + parts[i].block0, parts[i].nblocks, lag,
                                   iterations);
        else
            list[kept++] = i;
    }
    with_blocks = kept;
    int *rlist = DX_ARENA_ARRAY(a, int, count + 1);
    const int n = islands_by_length(parts, count, 0, rlist, tmp, a);
    qs_group *groups = DX_ARENA_ARRAY(a, qs_group, count + 1);
    int *group_of = DX_ARENA_ARRAY(a, int, count + 1);
    const int ng = make_groups(sys, parts, count, list, with_blocks, rlist, n, groups, group_of,
                               tmp);
    dxQuickBatchBlocks(a, sys, groups, ng);
    const qs_reorder re = reorder_begin(a, sys);
    const int **from = DX_ARENA_ARRAY(a, const int *, n + 1);
    for (int k = 0; k < ng; k++) {
        const qs_group *g = &groups[k];
        const int *glist = rlist + g->rows0;
        qs_system one = group_system(sys, g);
        for (int it = 0; it < iterations; it++) {
            if (it % REORDER_PERIOD == 0) {
                reshuffle_islands(sys, parts, glist, g->nrows, it / REORDER_PERIOD, &re);
                if (g->nrows > 0) interleave_rows(&one, parts, glist, g->nrows, from);
            }
            dxQuickSweep(&one, it & 1);
        }
    }
}

// With a threading implementation the islands are swept apart, each on
// whichever thread takes it: an island goes through exactly the updates, in
// exactly the order, that it gets interleaved with the others in solve()
// (its blocks in its joints' order, its rows in its shuffled order, the same
// shuffles, the same sweeps rows first), and no island reads another's
// numbers, so the results are the same to the bit.
typedef struct solve_islands {
    qs_system *sys;
    qs_island *parts;
    qs_reorder re;
    int iterations;
} solve_islands;

static void solve_island(void *context, int item, dxArena *arena)
{
    (void)arena;
    const solve_islands *s = context;
    qs_island *p = &s->parts[item];
    if (p->nblocks == 0 && p->norder == 0) return;
    qs_system one = *s->sys;   // this island's blocks and rows only
    one.nblocks = p->nblocks;
    one.bseq = s->sys->bseq + p->block0;
    one.batches = NULL;   // one island's blocks mostly share bodies
    one.nbatches = 0;
    for (int t = 0; t < p->nblocks; t++) one.bseq[t] = &s->sys->blocks[p->block0 + t];
    one.norder = p->norder;
    one.seq = s->sys->seq + p->order0;
    int *order = s->sys->order + p->order0;
    for (int it = 0; it < s->iterations; it++) {
        if (it % REORDER_PERIOD == 0) {
            reshuffle(order, p->norder, &p->seed, reshuffle_base(it / REORDER_PERIOD, p->norder),
                      &s->re);
            dxQuickRowsOf(one.seq, s->sys->rows, order, p->norder);
        }
        dxQuickSweep(&one, it & 1);
    }
}

// The forces a joint with feedback applies: J^T lambda of its rows, per body.
static void joint_feedback(const qs_feedback *q, const dReal *lambda)
{
    dReal f[12] = { 0 };   // [force0 torque0 force1 torque1]
    for (int i = 0; i < q->m; i++) {
        const dReal *J = q->J + i * DX_ROW_SKIP, l = lambda[q->pos[i]];
        for (int e = 0; e < 12; e++) f[e] += J[e] * l;
    }
    dJointFeedback *fb = q->joint->feedback;
    dCopyVector3(fb->f1, f);
    dCopyVector3(fb->t1, f + 3);
    dCopyVector3(fb->f2, f + 6);
    dCopyVector3(fb->t2, f + 9);
}

// Ask for the lines finish_island reads of body b.
QS_INLINE void prefetch_finish(const struct dxBody *b)
{
    prefetch_span(b->lvel, (size_t)((const char *)(b->torque + 3) - (const char *)b->lvel));
    qs_prefetch(b->force);
    qs_prefetch(&b->flags);   // dxBodyMoveAhead's first read (nearly all its time)
}

// v += h M^-1 (f + J^T lambda) for every body of the island, with fc the
// island's M^-1 J^T lambda (without constraints, fc zero, this is
// dxIslandUpdateVelocities to the bit); then the island's integration, each
// body moved right after its velocity update unless the world corrects
// positions (which needs every body of the island moved first); its
// quaternion normalised and its rotation matrix made in the pass that tells
// its geoms (dxBodyMoveAhead).
static void finish_island(const dxIsland *is, const dxIslandBodies *bd, const dReal *fc,
                          dReal h, int correct)
{
    for (int b = 0; b < is->nb; b++) {
        if (b + BODY_AHEAD < is->nb) prefetch_finish(is->bodies[b + BODY_AHEAD]);
        struct dxBody *body = is->bodies[b];
        const dReal *c = fc + 6 * b, *I = bd->inv_inertia + 12 * b, *t = body->torque;
        const dReal k = h * bd->inv_mass[b];
        dReal v[6];   // all read before any is written, so the compiler may pair them
        for (int e = 0; e < 3; e++) {
            const dReal dw = dCalcVectorDot3(I + 4 * e, t);   // (I^-1 torque)_e
            v[e] = body->lvel[e] + (body->force[e] * k + h * c[e]);
            v[3 + e] = body->avel[e] + (dw * h + h * c[3 + e]);
        }
        dCopyVector3(body->lvel, v);
        dCopyVector3(body->avel, v + 3);
        if (!correct) dxBodyMoveAhead(body, h);
    }
    if (correct) dxIslandIntegrate(is, h);
    else dxIslandRotateFinish(is);
}

int dWorldQuickStep(dWorldID w, dReal stepsize)
{
    if (dxWatchdogWants(w)) return dxWatchdogStep(w, stepsize, DX_STEP_QUICK, 0);
    dxIsland *islands;
    int count;
    if (!dxStepBegin(w, stepsize, __func__, &islands, &count)) return 0;
    dxArena *a = w->arena;
    const dReal h = stepsize;
    qs_system sys;
    dxQuickSetup(w, islands, count, &sys);
    dxIslandBodies *bd = DX_ARENA_ARRAY(a, dxIslandBodies, count + 1);
    qs_island *parts = DX_ARENA_ARRAY(a, qs_island, count + 1);
    int *list = DX_ARENA_ARRAY(a, int, count + 1);
    int *tmp = DX_ARENA_ARRAY(a, int, count + 1);
    for (int i = 0; i < count; i++) {
        // The next island's first body, which island_seed's and
        // dxIslandPrepareAt's look-ahead does not reach (most islands of a
        // rain or a heap are one or two bodies).
        if (i + 1 < count) prefetch_setup(islands[i + 1].bodies[0]);
        // (an island without joints has no rows to shuffle)
        parts[i].seed = islands[i].nj > 0 ? island_seed(&islands[i]) : 0;
        const int body0 = sys.nbodies;   // where dxQuickBuild puts the island's bodies
        dxIslandPrepareAt(w, &islands[i], h, sys.inv_mass + body0,
                          sys.inv_inertia + 12 * (size_t)body0, &bd[i]);
        dxQuickBuild(w, &islands[i], &bd[i], h, &sys, &parts[i]);
    }
    const int threads = dxStepThreadCount(w, count, __func__);
    if (threads > 1 && sys.m > 0) {
        solve_islands s = { &sys, parts, reorder_begin(a, &sys), w->qs_iterations };
        dxStepRunParallel(w, threads, count, solve_island, &s);
    } else if (sys.m > 0) {
        solve(a, &sys, parts, count, w->qs_iterations, list, tmp);
    }
    for (int k = 0; k < sys.nfeedback; k++) joint_feedback(&sys.feedback[k], sys.lambda);
    dxQuickWarmEnd(w, sys.warm, sys.lambda);   // before the bodies move
    const int correct = w->position_iterations > 0;
    for (int i = 0; i < count; i++) {
        if (i + 1 < count) prefetch_finish(islands[i + 1].bodies[0]);   // (as in the set-up)
        finish_island(&islands[i], &bd[i], sys.fc + 6 * parts[i].body0, h, correct);
    }
    dxStepKinematicBodies(w, h);
    dxStepEnd(islands, count, h);
    return 1;
}
