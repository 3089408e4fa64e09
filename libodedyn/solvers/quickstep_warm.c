// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_warm.c -- the contact forces dWorldQuickStep carries from one
// step to the next (its warm start, quickstep.c).
//
// Contact joints are made anew for every step, so the last step's contacts
// are found by what they are: the same two bodies (pointers and handle
// generations, in the joint's stored order), a contact point that moved by
// at most WARM_TOL times the lever arm (the distance from the farther body's
// centre to the point) in the first body's frame, and a normal within
// WARM_COS of the old one in that frame. The normal force carries as a number;
// the friction force as a vector in the first body's frame, projected on the
// new contact's friction directions (the same ones when the normal is the
// same). Of several old contacts that fit, the nearest is taken (ties: the
// smaller normal force), so the match does not depend on the order in which
// the islands or joints were built.
//
// The cache belongs to the world. The contacts of a step are entered in
// build order, which gives a body pair's contacts one after the other (the
// joints of a pair sit together in its bodies' joint lists), so they are kept
// as runs: a pair record (bodies, generations, first contact, count) per run,
// and per contact only what the next step compares and carries (point,
// normal, forces: warm_point). After the solve the runs become the last
// step's, indexed by an open-addressing table on the body pair; a contact
// then looks its pair up once per run (a contact of the same pair as the one
// before reuses the answer) and compares only that pair's old contacts, in
// their order. A pair met in two runs has its runs chained, so every old
// contact of the pair is still a candidate. The arrays grow geometrically
// (dAlloc) and are swapped, never freed, between steps, so that a warm step
// allocates nothing; dWorldDestroy frees them. The last step's entries are
// used only right after the quick step that made them (another stepper in
// between, or none yet: a cold start).

#include "quickstep.h"
#include "snapshot_io.h"
#include "dx_clones.h"

// The match and the end pass are built for AVX2 too where the compiler can
// pick a version at load time (dx_clones.h): the changes of frame in wider
// operations, the same numbers (both are called from other files).
#define WARM_CLONES DX_AVX2_CLONES_EXTERN

#include <ode/memory.h>
#include <string.h>

// A contact as the next step compares and carries it (b0's frame).
typedef struct warm_point {
    dReal p[3], n[3];               // point (from b0's origin) and normal
    dReal ln, f[3];                 // normal force, friction force
} warm_point;

// What a contact of this step needs until its forces are known: the handle
// dxQuickWarmContact returns.
struct qs_warm_entry {
    const struct dxBody *b0;        // its first body
    int pos[3];                     // lambda positions: normal, t1, t2 (-1: none)
    dReal t1[3], t2[3];             // friction directions (world frame)
};

// A slot of the index: run `run` if stamp is the table's, else empty.
typedef struct warm_slot {
    uint32_t stamp;
    int run;
} warm_slot;

// A run of consecutive contacts of one body pair.
typedef struct warm_pair {
    const struct dxBody *b0, *b1;   // stored order; b1 NULL for the static world
    uint32_t g0, g1;                // their generations
    uint32_t hash;                  // of b0 and b1 (pair_hash)
    int first, count;               // its contacts
    int next;                       // (old runs) the pair's next run, -1 at the end
} warm_pair;

struct dxWarmCache {
    // This step's contacts and runs, and the last step's.
    warm_point *cur, *old;
    warm_pair *cur_pairs, *old_pairs;
    qs_warm_entry *pending;         // per contact of this step
    int ncur, nold, cap_cur, cap_old, cap_pending;
    int ncur_pairs, nold_pairs;
    warm_pair *run;                 // the current run (NULL before the first)
    const warm_pair *match;         // its pair's first old run, NULL: none
    // The index of the old runs by pair: nslots (a power of 2) slots, those
    // whose stamp is slot_stamp in use (so the table is never cleared).
    struct warm_slot *slots;
    int nslots;
    uint32_t slot_stamp;
    uint32_t stamp;                 // w->step_count of the step that made old
};

// Room for n of each per-contact array of this step (cur, cur_pairs), never
// less than the last step's (the two are swapped every step).
static void grow_cur(dxWarmCache *c, int n)
{
    if (c->cap_cur >= n) return;
    int cap = n > 2 * c->cap_cur ? n : 2 * c->cap_cur;
    if (cap < c->cap_old) cap = c->cap_old;
    dFree(c->cur, sizeof(warm_point) * (size_t)c->cap_cur);
    dFree(c->cur_pairs, sizeof(warm_pair) * (size_t)c->cap_cur);
    c->cur = dAlloc(sizeof(warm_point) * (size_t)cap);
    c->cur_pairs = dAlloc(sizeof(warm_pair) * (size_t)cap);
    c->cap_cur = cap;
}

static dxWarmCache *cache_new(struct dxWorld *w)
{
    dxWarmCache *c = dAlloc(sizeof *c);
    memset(c, 0, sizeof *c);
    w->qs_warm = c;
    return c;
}

void dxWarmCacheFree(struct dxWorld *w)
{
    dxWarmCache *c = w->qs_warm;
    if (!c) return;
    dFree(c->cur, sizeof(warm_point) * (size_t)c->cap_cur);
    dFree(c->cur_pairs, sizeof(warm_pair) * (size_t)c->cap_cur);
    dFree(c->old, sizeof(warm_point) * (size_t)c->cap_old);
    dFree(c->old_pairs, sizeof(warm_pair) * (size_t)c->cap_old);
    dFree(c->pending, sizeof(qs_warm_entry) * (size_t)c->cap_pending);
    dFree(c->slots, sizeof(warm_slot) * (size_t)c->nslots);
    dFree(c, sizeof *c);
    w->qs_warm = NULL;
}

// x = R^T v and x = R v for a rotation R (dMatrix3: rows of 4).
static inline void to_body(dReal *x, const dReal *R, const dReal *v)
{
    const dReal a = v[0], b = v[1], c = v[2];
    const dReal x0 = R[0] * a + R[4] * b + R[8] * c, x1 = R[1] * a + R[5] * b + R[9] * c,
                x2 = R[2] * a + R[6] * b + R[10] * c;
    x[0] = x0;
    x[1] = x1;
    x[2] = x2;
}

static inline void to_world(dReal *x, const dReal *R, const dReal *v)
{
    const dReal a = v[0], b = v[1], c = v[2];
    const dReal x0 = R[0] * a + R[1] * b + R[2] * c, x1 = R[4] * a + R[5] * b + R[6] * c,
                x2 = R[8] * a + R[9] * b + R[10] * c;
    x[0] = x0;
    x[1] = x1;
    x[2] = x2;
}

static uint32_t pair_hash(const struct dxBody *b0, const struct dxBody *b1)
{
    uint64_t x = (uint64_t)(uintptr_t)b0 * 0x9e3779b97f4a7c15u;
    x ^= (uint64_t)(uintptr_t)b1 * 0xc2b2ae3d27d4eb4fu;
    x ^= x >> 29;
    return (uint32_t)(x >> 17);
}

// The same pair: bodies and generations (the hash first, the cheap reject).
static int same_pair(const warm_pair *a, const warm_pair *b)
{
    return a->hash == b->hash && a->b0 == b->b0 && a->b1 == b->b1 && a->g0 == b->g0 &&
           a->g1 == b->g1;
}

// The first old run of pair `key`, or NULL.
static const warm_pair *find_pair(const dxWarmCache *c, const warm_pair *key)
{
    if (c->nold_pairs == 0) return NULL;
    const unsigned mask = (unsigned)c->nslots - 1;
    for (unsigned s = key->hash & mask;; s = (s + 1) & mask) {
        const warm_slot *t = &c->slots[s];
        if (t->stamp != c->slot_stamp) return NULL;
        const warm_pair *q = &c->old_pairs[t->run];
        if (same_pair(q, key)) return q;
    }
}

// Index the old runs by pair (slots at least twice the runs, so probes are
// short); a pair's later runs are chained after its first.
static void index_old(dxWarmCache *c)
{
    if (c->nslots < 2 * c->nold_pairs) {
        int n = c->nslots > 0 ? c->nslots : 64;
        while (n < 2 * c->nold_pairs) n *= 2;
        dFree(c->slots, sizeof(warm_slot) * (size_t)c->nslots);
        c->slots = dAlloc(sizeof(warm_slot) * (size_t)n);
        memset(c->slots, 0, sizeof(warm_slot) * (size_t)n);   // stamp 0: never in use
        c->nslots = n;
    }
    if (++c->slot_stamp == 0) {   // (after 2^32 tables: clear once)
        memset(c->slots, 0, sizeof(warm_slot) * (size_t)c->nslots);
        c->slot_stamp = 1;
    }
    const unsigned mask = (unsigned)c->nslots - 1;
    for (int r = 0; r < c->nold_pairs; r++) {
        warm_pair *q = &c->old_pairs[r];
        q->next = -1;
        unsigned s = q->hash & mask;
        while (c->slots[s].stamp == c->slot_stamp && !same_pair(&c->old_pairs[c->slots[s].run], q))
            s = (s + 1) & mask;
        if (c->slots[s].stamp != c->slot_stamp) {
            c->slots[s].stamp = c->slot_stamp;
            c->slots[s].run = r;
            continue;
        }
        int last = c->slots[s].run;   // the same pair in an earlier run
        while (c->old_pairs[last].next >= 0) last = c->old_pairs[last].next;
        c->old_pairs[last].next = r;
    }
}

dxWarmCache *dxQuickWarmBegin(struct dxWorld *w, int ncontacts)
{
    dxWarmCache *c = w->qs_warm;
    if (!c && ncontacts == 0) return NULL;   // (none made before the first contact)
    if (!c) {
        c = cache_new(w);
        c->stamp = w->step_count - 2;   // not the last step's
    }
    grow_cur(c, ncontacts);
    if (c->cap_pending < ncontacts) {
        const int cap = ncontacts > 2 * c->cap_pending ? ncontacts : 2 * c->cap_pending;
        dFree(c->pending, sizeof(qs_warm_entry) * (size_t)c->cap_pending);
        c->pending = dAlloc(sizeof(qs_warm_entry) * (size_t)cap);
        c->cap_pending = cap;
    }
    c->ncur = c->ncur_pairs = 0;
    c->run = NULL;
    if (c->stamp + 1 != w->step_count) c->nold = c->nold_pairs = 0;   // not the step just before
    return c;
}

// The old contact of run q and the runs chained after it that matches
// (point p within sqrt(tol2), normal n within WARM_COS), or NULL: the
// nearest, ties to the smaller normal force, the first of equals.
static const warm_point *find(const dxWarmCache *c, const warm_pair *q, const dReal *p,
                              const dReal *n, dReal tol2)
{
    const warm_point *best = NULL;
    dReal best_d2 = tol2;
    for (;; q = &c->old_pairs[q->next]) {
        const warm_point *e = c->old + q->first, *end = e + q->count;
        for (; e < end; e++) {
            // The point first: most of a pair's other contacts are too far,
            // and their normals the same.
            const dReal d[3] = { e->p[0] - p[0], e->p[1] - p[1], e->p[2] - p[2] };
            const dReal d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (d2 > best_d2 || (best && d2 == best_d2 && !(e->ln < best->ln))) continue;
            if (e->n[0] * n[0] + e->n[1] * n[1] + e->n[2] * n[2] < WARM_COS) continue;
            best = e;
            best_d2 = d2;
        }
        if (q->next < 0) return best;
    }
}

WARM_CLONES qs_warm_entry *dxQuickWarmContact(dxWarmCache *c, const struct dxBody *b0,
                                  const struct dxBody *b1, const dReal *point, const dReal *n,
                                  const dReal *t1, const dReal *t2, int *found, dReal *ln,
                                  dReal *f)
{
    const int k = c->ncur++;
    warm_pair *run = c->run;
    if (!run || run->b0 != b0 || run->b1 != b1) {
        // A new run (within a step a body pointer names one body: no
        // generation can change while the system is built).
        run = &c->cur_pairs[c->ncur_pairs++];
        run->b0 = b0;
        run->b1 = b1;
        run->g0 = b0->hdr.generation;
        run->g1 = b1 ? b1->hdr.generation : 0;
        run->hash = pair_hash(b0, b1);
        run->first = k;
        run->count = 1;
        c->match = find_pair(c, run);
        c->run = run;
    } else {
        run->count++;
    }
    warm_point *e = &c->cur[k];
    qs_warm_entry *pend = &c->pending[k];
    pend->b0 = b0;
    dCopyVector3(pend->t1, t1);
    dCopyVector3(pend->t2, t2);
    dVector3 arm;
    dSubtractVectors3(arm, point, b0->pos);
    to_body(e->p, b0->R, arm);
    to_body(e->n, b0->R, n);
    *found = 0;
    if (!c->match) return pend;
    dReal reach2 = dCalcVectorDot3(arm, arm);   // the longer lever arm, squared
    if (b1) {
        dVector3 arm1;
        dSubtractVectors3(arm1, point, b1->pos);
        const dReal r2 = dCalcVectorDot3(arm1, arm1);
        if (r2 > reach2) reach2 = r2;
    }
    const warm_point *old = find(c, c->match, e->p, e->n, WARM_TOL * WARM_TOL * reach2);
    if (!old) return pend;
    *found = 1;
    *ln = old->ln;
    to_world(f, b0->R, old->f);   // back to the world frame
    return pend;
}

void dxQuickWarmPositions(qs_warm_entry *e, const int pos[3])
{
    memcpy(e->pos, pos, sizeof e->pos);
}

WARM_CLONES void dxQuickWarmEnd(struct dxWorld *w, dxWarmCache *c, const dReal *lambda)
{
    if (!c) return;
    for (int k = 0; k < c->ncur; k++) {
        const qs_warm_entry *pend = &c->pending[k];
        warm_point *e = &c->cur[k];
        const dReal l1 = pend->pos[1] >= 0 ? lambda[pend->pos[1]] : 0;
        const dReal l2 = pend->pos[2] >= 0 ? lambda[pend->pos[2]] : 0;
        e->ln = lambda[pend->pos[0]];
        dVector3 fw;   // into b0's frame (the bodies have not moved yet)
        for (int i = 0; i < 3; i++) fw[i] = l1 * pend->t1[i] + l2 * pend->t2[i];
        to_body(e->f, pend->b0->R, fw);
    }
    // Swap, and index the new old runs by body pair.
    warm_point *t = c->old;
    c->old = c->cur;
    c->cur = t;
    warm_pair *tp = c->old_pairs;
    c->old_pairs = c->cur_pairs;
    c->cur_pairs = tp;
    const int cap = c->cap_old;
    c->cap_old = c->cap_cur;
    c->cap_cur = cap;
    c->nold = c->ncur;
    c->nold_pairs = c->ncur_pairs;
    c->ncur = c->ncur_pairs = 0;
    c->run = NULL;
    c->stamp = w->step_count;
    index_old(c);
}

// ---- snapshots (io/snapshot.c) --------------------------------------------

// The last step's runs (body handles, generations, contacts) and contacts as
// they are: a restore into the same world finds them as the step after the
// snapshot did (the index is rebuilt from the runs). Field by field (no
// padding).
void dxWarmCacheSave(const struct dxWorld *w, dxSnapWriter *out)
{
    const dxWarmCache *c = w->qs_warm;
    dxSnapPutU32(out, c ? 1 : 0);
    if (!c) return;
    dxSnapPutU32(out, c->stamp);
    dxSnapPutU32(out, (uint32_t)c->nold);
    dxSnapPutU32(out, (uint32_t)c->nold_pairs);
    for (int r = 0; r < c->nold_pairs; r++) {
        const warm_pair *q = &c->old_pairs[r];
        dxSnapPutU64(out, (uint64_t)(uintptr_t)q->b0);
        dxSnapPutU64(out, (uint64_t)(uintptr_t)q->b1);
        dxSnapPutU32(out, q->g0);
        dxSnapPutU32(out, q->g1);
        dxSnapPutU32(out, (uint32_t)q->first);
        dxSnapPutU32(out, (uint32_t)q->count);
    }
    for (int k = 0; k < c->nold; k++) {
        const warm_point *e = &c->old[k];
        dxSnapPutReals(out, e->p, 3);
        dxSnapPutReals(out, e->n, 3);
        dxSnapPutReals(out, &e->ln, 1);
        dxSnapPutReals(out, e->f, 3);
    }
}

int dxWarmCacheLoad(struct dxWorld *w, dxSnapReader *in, int apply)
{
    if (!dxSnapGetU32(in)) {   // none saved: none to use after the restore
        if (apply && w->qs_warm) w->qs_warm->nold = w->qs_warm->nold_pairs = 0;
        return !in->bad;
    }
    const uint32_t stamp = dxSnapGetU32(in);
    const uint32_t nold = dxSnapGetU32(in), npairs = dxSnapGetU32(in);
    if (in->bad || nold > (1u << 28) || npairs > nold) return 0;
    dxWarmCache *c = w->qs_warm;
    if (apply) {
        if (!c) c = cache_new(w);
        if ((uint32_t)c->cap_old < nold) {
            dFree(c->old, sizeof(warm_point) * (size_t)c->cap_old);
            dFree(c->old_pairs, sizeof(warm_pair) * (size_t)c->cap_old);
            c->old = dAlloc(sizeof(warm_point) * (size_t)nold);
            c->old_pairs = dAlloc(sizeof(warm_pair) * (size_t)nold);
            c->cap_old = (int)nold;
        }
        c->stamp = stamp;
        c->nold = c->nold_pairs = 0;   // until all of it is read
        c->ncur = c->ncur_pairs = 0;
    }
    // The runs cover the contacts in order, each at least one.
    uint32_t next_first = 0;
    for (uint32_t r = 0; r < npairs; r++) {
        warm_pair q;
        q.b0 = (const struct dxBody *)(uintptr_t)dxSnapGetU64(in);
        q.b1 = (const struct dxBody *)(uintptr_t)dxSnapGetU64(in);
        q.g0 = dxSnapGetU32(in);
        q.g1 = dxSnapGetU32(in);
        const uint32_t first = dxSnapGetU32(in), count = dxSnapGetU32(in);
        if (in->bad || first != next_first || count == 0 || count > nold - first) return 0;
        next_first = first + count;
        q.hash = pair_hash(q.b0, q.b1);
        q.first = (int)first;
        q.count = (int)count;
        q.next = -1;
        if (apply) c->old_pairs[r] = q;
    }
    if (next_first != nold) return 0;
    for (uint32_t k = 0; k < nold; k++) {
        warm_point e;
        dxSnapGetReals(in, e.p, 3);
        dxSnapGetReals(in, e.n, 3);
        dxSnapGetReals(in, &e.ln, 1);
        dxSnapGetReals(in, e.f, 3);
        if (apply) c->old[k] = e;
    }
    if (in->bad) return 0;
    if (apply) {
        c->nold = (int)nold;
        c->nold_pairs = (int)npairs;
        index_old(c);
    }
    return 1;
}
