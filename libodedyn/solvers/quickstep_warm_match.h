// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_warm_match.h -- the warm-start cache's records and a contact's
// match against the last step's contacts (quickstep_warm.c has the rest and
// says how it works), inline: a plain contact's rows (quickstep_contact.c)
// enter the cache and look their contact up without a call.

#ifndef DX_QUICKSTEP_WARM_MATCH_H
#define DX_QUICKSTEP_WARM_MATCH_H

#include "quickstep.h"
#include "quickstep_v4.h"

#include <stddef.h>
#include <string.h>

// A contact as the next step compares and carries it (b0's frame), in fours
// (to_body4 writes four numbers; the fourth of p and f is unused).
typedef struct warm_point {
    dReal p[4];                     // point (from b0's origin)
    dReal n[3], ln;                 // normal, normal force
    dReal f[4];                     // friction force
} warm_point;

// What a contact of this step needs until its forces are known: the handle
// dxQuickWarmContact returns (its first body is its run's).
struct qs_warm_entry {
    int pos[3];                     // lambda positions: normal, t1, t2 (-1: none)
    dReal t1[4], t2[4];             // friction directions (world frame; 0 fourth)
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
    int head;                       // (old runs) the pair's first run
    dReal iso;                      // (old first runs) the pair's isolation (isolation)
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
    int expect;                     // the old run after the last one matched: a
                                    // step's runs come in the order of the step
                                    // before, so it is usually the next run's
    int shift;                      // where in match the run's last found contact
                                    // was, less where it is in the run (mod count)
    dReal cols[3][4];               // the columns of cols_of's b0->R
    const warm_pair *cols_of;       // the run whose they are (NULL: none)
    // The index of the old runs by pair: nslots (a power of 2) slots, those
    // whose stamp is slot_stamp in use (so the table is never cleared).
    struct warm_slot *slots;
    int nslots;
    uint32_t slot_stamp;
    uint32_t stamp;                 // w->step_count of the step that made old
};

// x = R v for a rotation R (dMatrix3: rows of 4).
QS_INLINE void to_world(dReal *x, const dReal *R, const dReal *v)
{
    const dReal a = v[0], b = v[1], c = v[2];
    const dReal x0 = R[0] * a + R[1] * b + R[2] * c, x1 = R[4] * a + R[5] * b + R[6] * c,
                x2 = R[8] * a + R[9] * b + R[10] * c;
    x[0] = x0;
    x[1] = x1;
    x[2] = x2;
}

// x = R^T v, x[i] = R[i] v[0] + R[4 + i] v[1] + R[8 + i] v[2] for i < 3; with
// GNU vectors the rows of R as fours times v's numbers (the same operations
// in the same order), x and v four numbers (the fourth of x whatever R's
// padding makes it).
#if defined(__GNUC__)
QS_INLINE void to_body4_v(dReal *x, const dReal *R, qs_v4 v)
{
    v4_store(v4_load(R) * v4_spread(v, 0) + v4_load(R + 4) * v4_spread(v, 1) +
                 v4_load(R + 8) * v4_spread(v, 2),
             x);
}

QS_INLINE void to_body4(dReal *x, const dReal *R, const dReal *v)
{
    to_body4_v(x, R, v4_load(v));
}
#else
static inline void to_body4(dReal *x, const dReal *R, const dReal *v)
{
    const dReal a = v[0], b = v[1], c = v[2];
    const dReal x0 = R[0] * a + R[4] * b + R[8] * c, x1 = R[1] * a + R[5] * b + R[9] * c,
                x2 = R[2] * a + R[6] * b + R[10] * c;
    x[0] = x0;
    x[1] = x1;
    x[2] = x2;
}
#endif

static inline uint32_t pair_hash(const struct dxBody *b0, const struct dxBody *b1)
{
    uint64_t x = (uint64_t)(uintptr_t)b0 * 0x9e3779b97f4a7c15u;
    x ^= (uint64_t)(uintptr_t)b1 * 0xc2b2ae3d27d4eb4fu;
    x ^= x >> 29;
    return (uint32_t)(x >> 17);
}

// The same pair: bodies and generations (the hash first, the cheap reject).
static inline int same_pair(const warm_pair *a, const warm_pair *b)
{
    return a->hash == b->hash && a->b0 == b->b0 && a->b1 == b->b1 && a->g0 == b->g0 &&
           a->g1 == b->g1;
}

// The first old run of pair `key`, or NULL.
static inline const warm_pair *find_pair(const dxWarmCache *c, const warm_pair *key)
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

// The squared distance of two points, as the match measures it.
QS_INLINE dReal dist2(const dReal *a, const dReal *b)
{
    const dReal d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

// The old contact of run q and the runs chained after it that matches
// (point p within sqrt(tol2), normal n within WARM_COS), or NULL: the
// nearest, ties to the smaller normal force, the first of equals
// (quickstep_warm.c: the scan, where the quick match does not decide).
const warm_point *dxQuickWarmFind(const dxWarmCache *c, const warm_pair *q, const dReal *p,
                                  const dReal *n, dReal tol2);

// The first old run of the pair of run `key`: the expected one if it is
// that (the same pair, the first of its runs), else through the index. The
// expected one is the next in an array read in order where the index's
// slot is a line anywhere: the same answer without that wait.
static inline const warm_pair *match_pair(dxWarmCache *c, const warm_pair *key)
{
    const warm_pair *x = c->expect < c->nold_pairs ? &c->old_pairs[c->expect] : NULL;
    const warm_pair *q = x && same_pair(x, key) && x->head ? x : find_pair(c, key);
    if (q) c->expect = (int)(q - c->old_pairs) + 1;
    return q;
}

// Contact k of this step, of bodies b0, b1 (stored order), in its run: the
// run goes on, or a new one starts and looks its pair up in the last step's.
QS_INLINE int warm_enter(dxWarmCache *c, const struct dxBody *b0, const struct dxBody *b1)
{
    const int k = c->ncur++;
    warm_pair *run = c->run;
    if (run && run->b0 == b0 && run->b1 == b1) {
        run->count++;
        return k;
    }
    // A new run (within a step a body pointer names one body: no generation
    // can change while the system is built).
    run = &c->cur_pairs[c->ncur_pairs++];
    run->b0 = b0;
    run->b1 = b1;
    // The generations in one store: the pair's compare (same_pair) reads
    // them in one load, which waits for the cache if it spans two stores.
    // (Made in a register: the compiler turns the copies into shifts.)
    const uint32_t g2[2] = { b0->hdr.generation, b1 ? b1->hdr.generation : 0 };
    uint64_t g;
    memcpy(&g, g2, sizeof g);
    _Static_assert(offsetof(warm_pair, g1) == offsetof(warm_pair, g0) + 4, "g0, g1 together");
    memcpy(&run->g0, &g, sizeof g);
    run->hash = pair_hash(b0, b1);
    run->first = k;
    run->count = 1;
    c->match = match_pair(c, run);
    c->shift = 0;
    c->run = run;
    return k;
}

// Contact k (entered) at world point `point` with normal n (dVector3s):
// kept in b0's frame for the next step, and matched against the last step's:
// the old contact, or NULL.
//
// The quick match: an old contact of the pair that fits and lies closer
// than a third of the pair's isolation (9 d2 < iso) is the one the scan (dxQuickWarmFind)
// would take: every other old contact of the pair is at least twice as far
// (the triangle inequality), whatever the rounding of the squared distances
// (a few units in the last place against a factor of 4). It is looked for
// in the pair's first old run from a guess on: a collider reports a pair's
// contacts in a steady order, though not always from the same start (box-box
// starts from another corner now and then), so the guess is the old contact
// at the run's place, shifted as the run's last found contact was. Where
// none is that near (contacts close together, a new one, a chained run),
// dxQuickWarmFind scans them all.
QS_INLINE const warm_point *warm_match(dxWarmCache *c, int k, const struct dxBody *b0,
                                  const struct dxBody *b1, const dReal *point, const dReal *n)
{
    warm_point *e = &c->cur[k];
    dReal reach2, r2 = 0;   // the lever arms, squared
#if defined(__GNUC__)
    const qs_v4 a = v4_load(point) - v4_load(b0->pos);   // (the fourth: whatever)
    to_body4_v(e->p, b0->R, a);
    const qs_v4 aa = a * a;
    reach2 = aa[0] + aa[1] + aa[2];
    if (b1) {
        const qs_v4 a1 = v4_load(point) - v4_load(b1->pos), bb = a1 * a1;
        r2 = bb[0] + bb[1] + bb[2];
    }
#else
    dVector3 arm;
    dSubtractVectors3(arm, point, b0->pos);
    to_body4(e->p, b0->R, arm);
    reach2 = dCalcVectorDot3(arm, arm);
    if (b1) {
        dVector3 arm1;
        dSubtractVectors3(arm1, point, b1->pos);
        r2 = dCalcVectorDot3(arm1, arm1);
    }
#endif
    // The normal's four numbers over n and ln (ln is set at the end).
    to_body4((dReal *)((char *)e + offsetof(warm_point, n)), b0->R, n);
    const warm_pair *q = c->match;
    if (!q) return NULL;
    if (r2 > reach2) reach2 = r2;
    const dReal tol2 = WARM_TOL * WARM_TOL * reach2;
    // The quick match: from the guess on through the pair's first old run.
    const int i = k - c->run->first, count = q->count;
    const warm_point *first = c->old + q->first;
    int j = i + c->shift;   // (the shift is 0 at a run's start)
    if (j >= count) j -= count;
    for (int left = j < count ? count : 0; left > 0; left--) {
        const warm_point *o = first + j;
        const dReal d2 = dist2(o->p, e->p);
        if (d2 <= tol2 && 9 * d2 < q->iso &&
            !(o->n[0] * e->n[0] + o->n[1] * e->n[1] + o->n[2] * e->n[2] < WARM_COS)) {
            c->shift = j >= i ? j - i : j - i + count;
            return o;
        }
        if (++j == count) j = 0;
    }
    return dxQuickWarmFind(c, q, e->p, e->n, tol2);
}

// dxQuickWarmContactRows (quickstep.h), inline: dxQuickContact's way.
QS_INLINE int warm_contact_rows(dxWarmCache *c, const struct dxBody *b0, const struct dxBody *b1,
                                const dxContactRows *r, int first, dReal f[4])
{
    static const dReal zero[4] = { 0, 0, 0, 0 };
    const int k = warm_enter(c, b0, b1);
    qs_warm_entry *pend = &c->pending[k];
    // The friction rows follow the normal row, t1's first (r->friction).
    const int t1 = r->friction & 1, t2 = r->friction & 2;
    pend->pos[0] = first;
    pend->pos[1] = t1 ? first + 1 : -1;
    pend->pos[2] = t2 ? first + 1 + t1 : -1;
    memcpy(pend->t1, t1 ? r->t1 : zero, sizeof pend->t1);   // (r's fourths are 0)
    memcpy(pend->t2, t2 ? r->t2 : zero, sizeof pend->t2);
    const warm_point *old = warm_match(c, k, b0, b1, r->point, r->n);
    if (!old) return 0;
    // Back to the world frame: R's columns times f's numbers, the same
    // operations as to_world.
#if defined(__GNUC__)
    if (c->cols_of != c->run) {   // R's columns, once a run
        const dReal *R = b0->R;
        for (int i = 0; i < 3; i++) {
            c->cols[i][0] = R[i];
            c->cols[i][1] = R[4 + i];
            c->cols[i][2] = R[8 + i];
            c->cols[i][3] = 0;
        }
        c->cols_of = c->run;
    }
    const qs_v4 F = v4_load(old->f);
    const qs_v4 x = v4_load(c->cols[0]) * __builtin_shufflevector(F, F, 0, 0, 0, 0) +
                      v4_load(c->cols[1]) * __builtin_shufflevector(F, F, 1, 1, 1, 1) +
                      v4_load(c->cols[2]) * __builtin_shufflevector(F, F, 2, 2, 2, 2);
    memcpy(f, &x, sizeof x);
#else
    to_world(f, b0->R, old->f);
#endif
    f[3] = old->ln;
    return 1;
}

#endif
