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
// before reuses the answer) and compares only that pair's old contacts. A
// pair met in two runs has its runs chained, so every old contact of the
// pair is still a candidate. Each pair also gets its isolation, the smallest
// squared distance between two of its old contacts: an old contact that fits
// and lies within a third of that is the nearest beyond doubt, so a contact
// usually tries one or two old contacts (warm_match) instead of scanning
// all (dxQuickWarmFind); the same answer either way. The end pass goes run
// by run, and the changes of frame are made in fours (a rotation's rows times a vector's
// numbers: the same operations as one number at a time). The arrays grow
// geometrically (dAlloc) and are swapped, never freed, between steps, so that
// a warm step allocates nothing; dWorldDestroy frees them. The last step's entries are
// used only right after the quick step that made them (another stepper in
// between, or none yet: a cold start).

#include "quickstep_warm_match.h"
#include "snapshot_io.h"
#include "dx_clones.h"

// The match and the end pass are built for AVX2 too where the compiler can
// pick a version at load time (dx_clones.h): the changes of frame in wider
// operations, the same numbers (both are called from other files).
#define WARM_CLONES DX_AVX2_CLONES_EXTERN

#include <ode/memory.h>
#include <stddef.h>
#include <string.h>

// (The records, the changes of frame, the pair lookup and the match are in
// quickstep_warm_match.h.)

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


// The isolation of the old contacts of a pair: the smallest squared
// distance between two of them (dInfinity for a lone one), 0 where that is
// below WARM_ISO_MIN or not a number, so that the quick match (warm_match) never
// rests on distances near the underflow, nor on a point that is not a
// number (dxQuickWarmFind's scan lets such a contact win). iso after d2:
static inline dReal isolation_by(dReal iso, dReal d2)
{
    return d2 >= iso ? iso : d2 < iso ? d2 : 0;   // (not a number: 0)
}

#if defined(__GNUC__)
// The smaller of x and y in each lane.
QS_INLINE qs_v4 min4(qs_v4 x, qs_v4 y)
{
    const qs_m4 lt = x < y;
    return (qs_v4)(((qs_m4)x & lt) | ((qs_m4)y & ~lt));
}

// Of four contacts (a box face's): their points as x, y and z fours, each
// against the next and the one after that (all six pairs), a lane a pair.
QS_INLINE dReal isolation4(const warm_point *e)
{
    const qs_v4 a = v4_load(e[0].p), b = v4_load(e[1].p), c = v4_load(e[2].p), d = v4_load(e[3].p);
    const qs_v4 ab = __builtin_shufflevector(a, b, 0, 4, 1, 5);   // a0 b0 a1 b1
    const qs_v4 cd = __builtin_shufflevector(c, d, 0, 4, 1, 5);
    const qs_v4 X = __builtin_shufflevector(ab, cd, 0, 1, 4, 5);
    const qs_v4 Y = __builtin_shufflevector(ab, cd, 2, 3, 6, 7);
    const qs_v4 ab2 = __builtin_shufflevector(a, b, 2, 6, 2, 6);   // a2 b2 a2 b2
    const qs_v4 cd2 = __builtin_shufflevector(c, d, 2, 6, 2, 6);
    const qs_v4 Z = __builtin_shufflevector(ab2, cd2, 0, 1, 4, 5);
    const qs_v4 x1 = X - __builtin_shufflevector(X, X, 1, 2, 3, 0);
    const qs_v4 y1 = Y - __builtin_shufflevector(Y, Y, 1, 2, 3, 0);
    const qs_v4 z1 = Z - __builtin_shufflevector(Z, Z, 1, 2, 3, 0);
    const qs_v4 x2 = X - __builtin_shufflevector(X, X, 2, 3, 0, 1);
    const qs_v4 y2 = Y - __builtin_shufflevector(Y, Y, 2, 3, 0, 1);
    const qs_v4 z2 = Z - __builtin_shufflevector(Z, Z, 2, 3, 0, 1);
    const qs_v4 d1 = x1 * x1 + y1 * y1 + z1 * z1, d2 = x2 * x2 + y2 * y2 + z2 * z2;
    const qs_v4 sum = d1 + d2;   // not a number if one of them is not
    if (!(sum[0] + sum[1] + sum[2] + sum[3] >= 0)) return 0;
    const qs_v4 m = min4(d1, d2), m2 = min4(m, __builtin_shufflevector(m, m, 2, 3, 0, 1));
    return m2[0] < m2[1] ? m2[0] : m2[1];
}
#endif

// iso, or 0 below WARM_ISO_MIN (and not a number).
static inline dReal isolation_min(dReal iso)
{
    return iso >= WARM_ISO_MIN ? iso : 0;
}

// Of the n contacts e, each two of them.
QS_INLINE dReal isolation(const warm_point *e, int n)
{
    if (n < 2) return dInfinity;
#if defined(__GNUC__)
    if (n == 4) return isolation_min(isolation4(e));
#endif
    dReal iso = dInfinity;
    for (int i = 0; i + 1 < n; i++) {
        const dReal p[3] = { e[i].p[0], e[i].p[1], e[i].p[2] };
        for (const warm_point *o = e + i + 1; o < e + n; o++)
            iso = isolation_by(iso, dist2(o->p, p));
    }
    return isolation_min(iso);
}

// Of the contacts e[0..n) against o[0..no), down from iso.
static dReal isolation_across(const warm_point *e, int n, const warm_point *o, int no, dReal iso)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < no; j++) iso = isolation_by(iso, dist2(o[j].p, e[i].p));
    return iso;
}

// Index the old runs by pair (slots at least twice the runs, so probes are
// short); a pair's later runs are chained after its first. Then the old
// contacts' isolation, pair by pair.
QS_INLINE void index_old(dxWarmCache *c)
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
    int chained = 0;
    for (int r = 0; r < c->nold_pairs; r++) {
        warm_pair *q = &c->old_pairs[r];
        q->next = -1;
        unsigned s = q->hash & mask;
        while (c->slots[s].stamp == c->slot_stamp && !same_pair(&c->old_pairs[c->slots[s].run], q))
            s = (s + 1) & mask;
        q->head = c->slots[s].stamp != c->slot_stamp;
        q->iso = isolation(c->old + q->first, q->count);
        if (q->head) {
            c->slots[s].stamp = c->slot_stamp;
            c->slots[s].run = r;
            continue;
        }
        int last = c->slots[s].run;   // the same pair in an earlier run
        while (c->old_pairs[last].next >= 0) last = c->old_pairs[last].next;
        c->old_pairs[last].next = r;
        chained = 1;
    }
    // A pair met in several runs: the distances between the runs too.
    for (int r = 0; chained && r < c->nold_pairs; r++) {
        warm_pair *h = &c->old_pairs[r];
        if (!h->head || h->next < 0) continue;
        for (const warm_pair *x = h;; x = &c->old_pairs[x->next]) {
            h->iso = dMin(h->iso, x->iso);
            if (x->next < 0) break;
            for (const warm_pair *y = &c->old_pairs[x->next];; y = &c->old_pairs[y->next]) {
                h->iso = isolation_across(c->old + x->first, x->count, c->old + y->first,
                                          y->count, h->iso);
                if (y->next < 0) break;
            }
        }
        h->iso = isolation_min(h->iso);
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
    c->cols_of = NULL;
    c->expect = 0;
    if (c->stamp + 1 != w->step_count) c->nold = c->nold_pairs = 0;   // not the step just before
    return c;
}

const warm_point *dxQuickWarmFind(const dxWarmCache *c, const warm_pair *q, const dReal *p,
                                  const dReal *n, dReal tol2)
{
    const warm_point *best = NULL;
    dReal best_d2 = tol2;
    for (;; q = &c->old_pairs[q->next]) {
        const warm_point *e = c->old + q->first, *end = e + q->count;
        for (; e < end; e++) {
            // The point first: most of a pair's other contacts are too far,
            // and their normals the same.
            const dReal d2 = dist2(e->p, p);
            if (d2 > best_d2 || (best && d2 == best_d2 && !(e->ln < best->ln))) continue;
            if (e->n[0] * n[0] + e->n[1] * n[1] + e->n[2] * n[2] < WARM_COS) continue;
            best = e;
            best_d2 = d2;
        }
        if (q->next < 0) return best;
    }
}

WARM_CLONES qs_warm_entry *dxQuickWarmContact(dxWarmCache *c, const struct dxBody *b0,
                                              const struct dxBody *b1, const dReal *point,
                                              const dReal *n, const dReal *t1, const dReal *t2,
                                              int *found, dReal *ln, dReal *f)
{
    const int k = warm_enter(c, b0, b1);
    qs_warm_entry *pend = &c->pending[k];
    dCopyVector3(pend->t1, t1);
    dCopyVector3(pend->t2, t2);
    pend->t1[3] = pend->t2[3] = 0;
    const dVector3 p4 = { point[0], point[1], point[2], 0 }, n4 = { n[0], n[1], n[2], 0 };
    const warm_point *old = warm_match(c, k, b0, b1, p4, n4);
    *found = old != NULL;
    if (old) {
        *ln = old->ln;
        to_world(f, b0->R, old->f);   // back to the world frame
    }
    return pend;
}

WARM_CLONES int dxQuickWarmContactRows(dxWarmCache *c, const struct dxBody *b0,
                                       const struct dxBody *b1, const dxContactRows *r,
                                       int first, dReal f[4])
{
    return warm_contact_rows(c, b0, b1, r, first, f);
}

void dxQuickWarmPositions(qs_warm_entry *e, const int pos[3])
{
    memcpy(e->pos, pos, sizeof e->pos);
}

WARM_CLONES void dxQuickWarmEnd(struct dxWorld *w, dxWarmCache *c, const dReal *lambda)
{
    if (!c) return;
    // Each run's forces into its first body's frame (the bodies have not
    // moved yet).
    for (int p = 0; p < c->ncur_pairs; p++) {   // (cur_pairs is NULL before the first pair)
        const warm_pair *q = &c->cur_pairs[p];
        const dReal *R = q->b0->R;
        for (int k = q->first, kend = k + q->count; k < kend; k++) {
            const qs_warm_entry *pend = &c->pending[k];
            warm_point *e = &c->cur[k];
            const dReal l1 = pend->pos[1] >= 0 ? lambda[pend->pos[1]] : 0;
            const dReal l2 = pend->pos[2] >= 0 ? lambda[pend->pos[2]] : 0;
            e->ln = lambda[pend->pos[0]];
#if defined(__GNUC__)
            const qs_v4 L1 = { l1, l1, l1, l1 }, L2 = { l2, l2, l2, l2 };
            to_body4_v(e->f, R, L1 * v4_load(pend->t1) + L2 * v4_load(pend->t2));
#else
            dVector3 fw;
            for (int i = 0; i < 3; i++) fw[i] = l1 * pend->t1[i] + l2 * pend->t2[i];
            to_body4(e->f, R, fw);
#endif
        }
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
