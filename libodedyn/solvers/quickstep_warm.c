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
// The cache belongs to the world: two arrays of entries (the last step's,
// read through a hash table on the body pair, and this step's, written
// while the rows are built and given their forces after the solve), swapped
// at the end of each quick step, and grown geometrically (dAlloc), so that a
// warm step allocates nothing; dWorldDestroy frees them. The last step's
// entries are used only right after the quick step that made them (another
// stepper in between, or none yet: a cold start).

#include "quickstep.h"
#include "snapshot_io.h"

#include <ode/memory.h>
#include <string.h>

struct qs_warm_entry {
    const struct dxBody *b0, *b1;   // stored order; b1 NULL for the static world
    uint32_t g0, g1;                // their generations
    int next;                       // the next entry of its bucket, -1 at the end
    int pos[3];                     // this step's lambda positions: normal, t1, t2 (-1: none)
    dReal p[3], n[3];               // point and normal in b0's frame
    dReal t1[3], t2[3];             // this step's friction directions (world frame)
    dReal ln, f[3];                 // normal force, friction force (b0's frame)
};

struct dxWarmCache {
    qs_warm_entry *old, *cur;
    int nold, ncur, cap_old, cap_cur;
    int *heads;                     // nheads (a power of 2): first entry of old per bucket
    int nheads;
    uint32_t stamp;                 // w->step_count of the step that made old
};

void dxWarmCacheFree(struct dxWorld *w)
{
    dxWarmCache *c = w->qs_warm;
    if (!c) return;
    dFree(c->old, sizeof(qs_warm_entry) * (size_t)c->cap_old);
    dFree(c->cur, sizeof(qs_warm_entry) * (size_t)c->cap_cur);
    dFree(c->heads, sizeof(int) * (size_t)c->nheads);
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

static unsigned bucket_of(const dxWarmCache *c, const struct dxBody *b0,
                          const struct dxBody *b1)
{
    uint64_t x = (uint64_t)(uintptr_t)b0 * 0x9e3779b97f4a7c15u;
    x ^= (uint64_t)(uintptr_t)b1 * 0xc2b2ae3d27d4eb4fu;
    x ^= x >> 29;
    return (unsigned)(x >> 17) & (unsigned)(c->nheads - 1);
}

dxWarmCache *dxQuickWarmBegin(struct dxWorld *w, int ncontacts)
{
    dxWarmCache *c = w->qs_warm;
    if (!c && ncontacts == 0) return NULL;   // (none made before the first contact)
    if (!c) {
        c = dAlloc(sizeof *c);
        memset(c, 0, sizeof *c);
        c->stamp = w->step_count - 2;   // not the last step's
        w->qs_warm = c;
    }
    if (c->cap_cur < ncontacts) {
        // Geometric growth, and never below the other array: the two are
        // swapped every step.
        int cap = ncontacts > 2 * c->cap_cur ? ncontacts : 2 * c->cap_cur;
        if (cap < c->cap_old) cap = c->cap_old;
        dFree(c->cur, sizeof(qs_warm_entry) * (size_t)c->cap_cur);
        c->cur = dAlloc(sizeof(qs_warm_entry) * (size_t)cap);
        c->cap_cur = cap;
    }
    c->ncur = 0;
    if (c->stamp + 1 != w->step_count) c->nold = 0;   // not the step just before
    return c;
}

// The matching entry of the last step (point within sqrt(tol2) of p), or
// NULL.
static const qs_warm_entry *find(const dxWarmCache *c, const struct dxBody *b0,
                                 const struct dxBody *b1, const dReal *p, const dReal *n,
                                 dReal tol2)
{
    if (c->nold == 0) return NULL;
    const uint32_t g0 = b0->hdr.generation, g1 = b1 ? b1->hdr.generation : 0;
    const qs_warm_entry *best = NULL;
    dReal best_d2 = tol2;
    for (int k = c->heads[bucket_of(c, b0, b1)]; k >= 0; k = c->old[k].next) {
        const qs_warm_entry *e = &c->old[k];
        if (e->b0 != b0 || e->b1 != b1 || e->g0 != g0 || e->g1 != g1) continue;
        // The point first: most of a pair's other contacts are too far, and
        // their normals the same.
        const dReal d[3] = { e->p[0] - p[0], e->p[1] - p[1], e->p[2] - p[2] };
        const dReal d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (d2 > best_d2 || (best && d2 == best_d2 && !(e->ln < best->ln))) continue;
        if (e->n[0] * n[0] + e->n[1] * n[1] + e->n[2] * n[2] < WARM_COS) continue;
        best = e;
        best_d2 = d2;
    }
    return best;
}

qs_warm_entry *dxQuickWarmContact(dxWarmCache *c, const struct dxBody *b0,
                                  const struct dxBody *b1, const dReal *point, const dReal *n,
                                  const dReal *t1, const dReal *t2, int *found, dReal *ln,
                                  dReal *f)
{
    qs_warm_entry *e = &c->cur[c->ncur++];
    e->b0 = b0;
    e->b1 = b1;
    e->g0 = b0->hdr.generation;
    e->g1 = b1 ? b1->hdr.generation : 0;
    e->next = -1;
    e->pos[0] = e->pos[1] = e->pos[2] = -1;
    dVector3 arm;
    dSubtractVectors3(arm, point, b0->pos);
    dReal reach2 = dCalcVectorDot3(arm, arm);   // the longer lever arm, squared
    if (b1) {
        dVector3 arm1;
        dSubtractVectors3(arm1, point, b1->pos);
        const dReal r2 = dCalcVectorDot3(arm1, arm1);
        if (r2 > reach2) reach2 = r2;
    }
    to_body(e->p, b0->R, arm);
    to_body(e->n, b0->R, n);
    dCopyVector3(e->t1, t1);
    dCopyVector3(e->t2, t2);
    const qs_warm_entry *old = find(c, b0, b1, e->p, e->n, WARM_TOL * WARM_TOL * reach2);
    *found = old != NULL;
    if (old) {
        *ln = old->ln;
        to_world(f, b0->R, old->f);   // back to the world frame
    }
    return e;
}

void dxQuickWarmPositions(qs_warm_entry *e, const int pos[3])
{
    memcpy(e->pos, pos, sizeof e->pos);
}

void dxQuickWarmEnd(struct dxWorld *w, dxWarmCache *c, const dReal *lambda)
{
    if (!c) return;
    for (int k = 0; k < c->ncur; k++) {
        qs_warm_entry *e = &c->cur[k];
        const dReal l1 = e->pos[1] >= 0 ? lambda[e->pos[1]] : 0;
        const dReal l2 = e->pos[2] >= 0 ? lambda[e->pos[2]] : 0;
        e->ln = lambda[e->pos[0]];
        dVector3 f;   // into b0's frame (the bodies have not moved yet)
        for (int i = 0; i < 3; i++) f[i] = l1 * e->t1[i] + l2 * e->t2[i];
        to_body(e->f, e->b0->R, f);
    }
    // Swap, and index the new old entries by body pair.
    qs_warm_entry *t = c->old;
    c->old = c->cur;
    c->cur = t;
    const int cap = c->cap_old;
    c->cap_old = c->cap_cur;
    c->cap_cur = cap;
    c->nold = c->ncur;
    c->ncur = 0;
    c->stamp = w->step_count;
    if (c->nheads < 2 * c->nold) {
        int n = c->nheads > 0 ? c->nheads : 64;
        while (n < 2 * c->nold) n *= 2;
        dFree(c->heads, sizeof(int) * (size_t)c->nheads);
        c->heads = dAlloc(sizeof(int) * (size_t)n);
        c->nheads = n;
    }
    if (c->nold == 0) return;
    for (int b = 0; b < c->nheads; b++) c->heads[b] = -1;
    for (int k = c->nold - 1; k >= 0; k--) {   // chains in entry order
        qs_warm_entry *e = &c->old[k];
        const unsigned b = bucket_of(c, e->b0, e->b1);
        e->next = c->heads[b];
        c->heads[b] = k;
    }
}

// ---- snapshots (io/snapshot.c) --------------------------------------------

// The last step's entries as they are (body handles, generations, bucket
// chains and heads): a restore into the same world finds them as the step
// after the snapshot did. The entries are written field by field (no padding).
void dxWarmCacheSave(const struct dxWorld *w, dxSnapWriter *out)
{
    const dxWarmCache *c = w->qs_warm;
    dxSnapPutU32(out, c ? 1 : 0);
    if (!c) return;
    dxSnapPutU32(out, c->stamp);
    dxSnapPutU32(out, (uint32_t)c->nold);
    dxSnapPutU32(out, (uint32_t)(c->nold ? c->nheads : 0));
    if (c->nold) dxSnapPut(out, c->heads, sizeof(int) * (size_t)c->nheads);
    for (int k = 0; k < c->nold; k++) {
        const qs_warm_entry *e = &c->old[k];
        dxSnapPutU64(out, (uint64_t)(uintptr_t)e->b0);
        dxSnapPutU64(out, (uint64_t)(uintptr_t)e->b1);
        dxSnapPutU32(out, e->g0);
        dxSnapPutU32(out, e->g1);
        dxSnapPut(out, &e->next, sizeof e->next);
        dxSnapPut(out, e->pos, sizeof e->pos);
        dxSnapPutReals(out, e->p, 3);
        dxSnapPutReals(out, e->n, 3);
        dxSnapPutReals(out, e->t1, 3);
        dxSnapPutReals(out, e->t2, 3);
        dxSnapPutReals(out, &e->ln, 1);
        dxSnapPutReals(out, e->f, 3);
    }
}

int dxWarmCacheLoad(struct dxWorld *w, dxSnapReader *in, int apply)
{
    if (!dxSnapGetU32(in)) {   // none saved: none to use after the restore
        if (apply && w->qs_warm) w->qs_warm->nold = 0;
        return !in->bad;
    }
    const uint32_t stamp = dxSnapGetU32(in);
    const uint32_t nold = dxSnapGetU32(in), nheads = dxSnapGetU32(in);
    if (in->bad || nold > (1u << 28) || nheads > (1u << 29)) return 0;
    if (nold && (nheads < 2 * nold || (nheads & (nheads - 1)))) return 0;
    dxWarmCache *c = w->qs_warm;
    if (apply) {
        if (!c) {
            c = dAlloc(sizeof *c);
            memset(c, 0, sizeof *c);
            w->qs_warm = c;
        }
        if ((uint32_t)c->cap_old < nold) {
            dFree(c->old, sizeof(qs_warm_entry) * (size_t)c->cap_old);
            c->old = dAlloc(sizeof(qs_warm_entry) * (size_t)nold);
            c->cap_old = (int)nold;
        }
        if (nold && (uint32_t)c->nheads != nheads) {
            dFree(c->heads, sizeof(int) * (size_t)c->nheads);
            c->heads = dAlloc(sizeof(int) * (size_t)nheads);
            c->nheads = (int)nheads;
        }
        c->stamp = stamp;
        c->nold = (int)nold;
        c->ncur = 0;
        if (nold) dxSnapGet(in, c->heads, sizeof(int) * (size_t)nheads);
    } else {
        for (uint32_t b = 0; b < nheads; b++) {
            int head;
            dxSnapGet(in, &head, sizeof head);
            if (head < -1 || head >= (int)nold) return 0;
        }
    }
    for (uint32_t k = 0; k < nold; k++) {
        qs_warm_entry e;
        e.b0 = (const struct dxBody *)(uintptr_t)dxSnapGetU64(in);
        e.b1 = (const struct dxBody *)(uintptr_t)dxSnapGetU64(in);
        e.g0 = dxSnapGetU32(in);
        e.g1 = dxSnapGetU32(in);
        dxSnapGet(in, &e.next, sizeof e.next);
        dxSnapGet(in, e.pos, sizeof e.pos);
        dxSnapGetReals(in, e.p, 3);
        dxSnapGetReals(in, e.n, 3);
        dxSnapGetReals(in, e.t1, 3);
        dxSnapGetReals(in, e.t2, 3);
        dxSnapGetReals(in, &e.ln, 1);
        dxSnapGetReals(in, e.f, 3);
        if (e.next < -1 || e.next >= (int)nold) return 0;
        if (apply) c->old[k] = e;
    }
    return !in->bad;
}
