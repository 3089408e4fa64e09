// SPDX-License-Identifier: BSD-3-Clause
//
// space_sap.c -- the sweep-and-prune space (ODE 0.16's
// dSweepAndPruneSpaceCreate), incremental.
//
// Each geom has a proxy holding the AABB last seen (in the space's axis
// order). The low and high ends of the proxies' boxes are kept sorted on all
// three axes, and the space keeps the set of pairs whose boxes overlap on all
// three (space_sap_pairs.c). When a geom's box changed, its ends are moved
// through their lists by insertion: an end that passes another proxy's end of
// the other kind starts or ends the pair's overlap along that axis, and if
// the boxes (as the lists place them) overlap on the other two axes, the pair
// joins or leaves the set. A box is moved one axis after the other, so the
// set stays exact after every swap. At equal values low ends sort before high
// ends, so boxes that just touch overlap (closed boxes). dSpaceCollide then
// walks the set: only geoms whose boxes changed cost work beyond one
// comparison of boxes each.
//
// When moving ends would cost more than sorting afresh (most of a dense pile
// moving; see sap_refresh), or many proxies are new (a first collision), the
// first list is sorted afresh and the set found by one sweep along it. New
// proxies are otherwise inserted at the top of the lists and moved down.
// Removed proxies leave the lists and the set in one pass at the next
// refresh. Proxies whose box holds a NaN or is empty (low above high, e.g. an
// empty nested space) stay out of the lists ("wild") and are tested against
// every geom of the space, as the AABB test decides for them.
//
// The structure is refreshed only when the space's bounding box was
// recomputed (something in it moved, came or went), never while a collision
// of the space walks it (a callback that moves geoms makes nested queries
// test geom by geom). Arrays grow geometrically: a steady state allocates
// nothing.

#include "geom_internal.h"
#include "space_pair.h"
#include "space_sap_pairs.h"

#include <ode/memory.h>
#include <string.h>

enum { PX_FREE, PX_NEW, PX_LISTED, PX_WILD, PX_DEAD };

typedef struct sap_proxy {
    dReal box[6];                 // the AABB last seen, in the space's axis order
    dxGeom *g;
    int at[3][2];                 // places of its low and high ends in the lists (LISTED)
    int state;                    // PX_...
    int next_free;                // the next free proxy (FREE)
} sap_proxy;

// A box open in a fresh sweep: its extent on the second and third axes.
typedef struct sap_open {
    dReal b[4];
    int p;
} sap_open;

// One end of a proxy's box along an axis.
typedef struct sap_end {
    dReal v;
    int e;                        // proxy * 2, + 1 for a high end
} sap_end;

typedef struct dxSapSpace {
    dxSpace s;
    int axis[3];                  // the axis order: sweep axis first
    int stale;                    // the proxies' boxes may be out of date
    int walking;                  // > 0 while a collision walks the structure
    sap_proxy *px;
    int npx, pxcap, free_px;      // proxies used (high water), allocated, first free
    int *proxy_of;                // the proxy of s->geoms[i]
    int proxy_of_cap;
    sap_end *end[3];              // the sorted ends on each axis (2 * pxcap allocated)
    int nend;                     // ends per list
    sap_end *tmp;                 // scratch for sorting a list (2 * pxcap allocated)
    int rest_unsorted;            // a fresh sort left the second and third lists unsorted
    int *wild, nwild;             // the WILD proxies (pxcap allocated)
    sap_open *open;               // a fresh sweep's open boxes (pxcap allocated) ...
    int *open_at;                 // ... and where each proxy's is
    int dead;                     // DEAD proxies still in the lists
    // Choosing between moving ends and sorting afresh: swaps of ends made so
    // far, the cost of the last fresh sort in swaps, and the swaps one
    // changed box cost in the last refresh that moved some.
    long swaps, afresh_cost;
    double swaps_per_move;
    dxSapPairSet pairs;
} dxSapSpace;

// ---- proxies ------------------------------------------------------------------

static void *grow(void *p, int old_n, int n, size_t size)
{
    return dRealloc(p, (size_t)old_n * size, (size_t)n * size);
}

static int proxy_alloc(dxSapSpace *ss)
{
    if (ss->free_px >= 0) {
        int p = ss->free_px;
        ss->free_px = ss->px[p].next_free;
        return p;
    }
    if (ss->npx == ss->pxcap) {
        int cap = ss->pxcap ? 2 * ss->pxcap : 64;
        ss->px = grow(ss->px, ss->pxcap, cap, sizeof *ss->px);
        for (int k = 0; k < 3; k++)
            ss->end[k] = grow(ss->end[k], 2 * ss->pxcap, 2 * cap, sizeof *ss->end[k]);
        ss->tmp = grow(ss->tmp, 2 * ss->pxcap, 2 * cap, sizeof *ss->tmp);
        ss->wild = grow(ss->wild, ss->pxcap, cap, sizeof *ss->wild);
        ss->open = grow(ss->open, ss->pxcap, cap, sizeof *ss->open);
        ss->open_at = grow(ss->open_at, ss->pxcap, cap, sizeof *ss->open_at);
        ss->pxcap = cap;
    }
    return ss->npx++;
}

static void proxy_free(dxSapSpace *ss, int p)
{
    ss->px[p].state = PX_FREE;
    ss->px[p].g = NULL;
    ss->px[p].next_free = ss->free_px;
    ss->free_px = p;
}

static void sap_added(dxSpace *s, dxGeom *g)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    if (s->count > ss->proxy_of_cap) {
        int cap = s->capacity;
        ss->proxy_of = grow(ss->proxy_of, ss->proxy_of_cap, cap, sizeof *ss->proxy_of);
        ss->proxy_of_cap = cap;
    }
    int p = proxy_alloc(ss);
    ss->px[p].g = g;
    ss->px[p].state = PX_NEW;
    ss->proxy_of[g->space_index] = p;
    ss->stale = 1;
}

// Called before space.c closes the gap in s->geoms: close it here too.
static void sap_removed(dxSpace *s, dxGeom *g)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    const int i = g->space_index, p = ss->proxy_of[i];
    memmove(ss->proxy_of + i, ss->proxy_of + i + 1,
            (size_t)(s->count - i - 1) * sizeof *ss->proxy_of);
    if (ss->px[p].state == PX_LISTED) {
        ss->px[p].state = PX_DEAD;
        ss->px[p].g = NULL;
        ss->dead++;
    } else {
        proxy_free(ss, p);
    }
    ss->stale = 1;
}

// g's AABB in the space's axis order; 1 if it is wild (a NaN, or empty).
static int read_box(const dxSapSpace *ss, const dxGeom *g, dReal box[6])
{
    int wild = 0;
    for (int k = 0; k < 3; k++) {
        box[2 * k] = g->aabb[2 * ss->axis[k]];
        box[2 * k + 1] = g->aabb[2 * ss->axis[k] + 1];
        wild |= !(box[2 * k] <= box[2 * k + 1]);
    }
    return wild;
}

static int boxes_overlap(const dReal *a, const dReal *b)
{
    return a[0] <= b[1] && b[0] <= a[1] && a[2] <= b[3] && b[2] <= a[3] && a[4] <= b[5] &&
           b[4] <= a[5];
}

// ---- keeping the lists sorted ----------------------------------------------------

// x sorts strictly before y: a smaller value, or the same with x a low end
// and y a high one.
static int before(const sap_end *x, const sap_end *y)
{
    return x->v < y->v || (x->v == y->v && (x->e & 1) < (y->e & 1));
}

// The boxes overlap on axes j1 and j2.
static inline int overlap_on(const dReal *a, const dReal *b, int j1, int j2)
{
    return (a[2 * j1] <= b[2 * j1 + 1]) & (b[2 * j1] <= a[2 * j1 + 1]) &
           (a[2 * j2] <= b[2 * j2 + 1]) & (b[2 * j2] <= a[2 * j2 + 1]);
}

// The pair p, q overlaps on two axes, and on the third an end of p passed one
// of q's of the other kind: their overlap there starts (start = 1) or ends.
static void crossed(dxSapSpace *ss, int p, int q, int start)
{
    if (!start) dxSapPairRemove(&ss->pairs, p, q);
    else if (ss->px[q].state == PX_LISTED)
        dxSapPairAdd(&ss->pairs, p, ss->px[p].g, q, ss->px[q].g);
}

// Move the end at place i of list k down (then up) to its place. A low end
// moving down past a high end starts an overlap, a high end moving down past
// a low end ends one; moving up, the other way round. The pair is in the set
// exactly when it overlaps on the other two axes too (boxes as the lists
// place them). With events 0 the overlaps it starts or ends are not looked
// at.
static void settle(dxSapSpace *ss, int k, int i, int events)
{
    sap_end *const list = ss->end[k];
    sap_proxy *const px = ss->px;
    const int j1 = k == 0 ? 1 : 0, j2 = k == 2 ? 1 : 2;
    const sap_end x = list[i];
    const int p = x.e >> 1, high = x.e & 1;
    const dReal *box = px[p].box;
    long swaps = 0;
    while (i > 0 && before(&x, &list[i - 1])) {
        const sap_end y = list[i - 1];
        const int q = y.e >> 1;
        if (events && (y.e & 1) != high && q != p && overlap_on(box, px[q].box, j1, j2))
            crossed(ss, p, q, !high);
        list[i] = y;
        px[q].at[k][y.e & 1] = i--;
        swaps++;
    }
    while (i + 1 < ss->nend && before(&list[i + 1], &x)) {
        const sap_end y = list[i + 1];
        const int q = y.e >> 1;
        if (events && (y.e & 1) != high && q != p && overlap_on(box, px[q].box, j1, j2))
            crossed(ss, p, q, high);
        list[i] = y;
        px[q].at[k][y.e & 1] = i++;
        swaps++;
    }
    list[i] = x;
    px[p].at[k][high] = i;
    ss->swaps += swaps;
}

// The listed proxy p's box became nb, one axis after the other (so that its
// box says where the lists place it). The end moving up goes first when the
// high end rises, else the low end does, so that neither passes the other.
static void move_proxy(dxSapSpace *ss, int p, const dReal nb[6])
{
    sap_proxy *x = &ss->px[p];
    for (int k = 0; k < 3; k++) {
        const int first = nb[2 * k + 1] > x->box[2 * k + 1];
        x->box[2 * k] = nb[2 * k];
        x->box[2 * k + 1] = nb[2 * k + 1];
        for (int n = 0; n < 2; n++) {
            const int end = n == 0 ? first : !first;
            const int i = x->at[k][end];
            ss->end[k][i].v = nb[2 * k + end];
            settle(ss, k, i, 1);
        }
    }
}

// Put the new proxy p (its box current) into the lists: its ends start above
// every other end and move down, low end first. On the second and third axes
// they are just placed (those lists may still wait for their sort: see
// rebuild); on the first, every overlap they start is a pair's if the boxes
// overlap on the other two.
static void link_proxy(dxSapSpace *ss, int p)
{
    sap_proxy *x = &ss->px[p];
    x->state = PX_LISTED;
    const int n = ss->nend;
    ss->nend += 2;
    for (int k = 2; k >= 0; k--) {
        ss->end[k][n] = (sap_end){ x->box[2 * k], 2 * p };
        ss->end[k][n + 1] = (sap_end){ x->box[2 * k + 1], 2 * p + 1 };
        x->at[k][0] = n;
        x->at[k][1] = n + 1;
        settle(ss, k, n, k == 0);
        settle(ss, k, x->at[k][1], k == 0);
    }
}

static int both_listed(void *ctx, int a, int b)
{
    const sap_proxy *px = ctx;
    return px[a].state == PX_LISTED && px[b].state == PX_LISTED;
}

// Take the ends of proxies no longer listed (removed, or gone wild) out of the
// lists and their pairs out of the set; free the removed ones.
static void compact(dxSapSpace *ss)
{
    int n = 0;
    for (int k = 0; k < 3; k++) {
        sap_end *list = ss->end[k];
        n = 0;
        for (int i = 0; i < ss->nend; i++) {
            const int p = list[i].e >> 1;
            if (ss->px[p].state != PX_LISTED) continue;
            ss->px[p].at[k][list[i].e & 1] = n;
            list[n++] = list[i];
        }
    }
    ss->nend = n;
    dxSapPairFilter(&ss->pairs, both_listed, ss->px);
    for (int p = 0; p < ss->npx; p++)
        if (ss->px[p].state == PX_DEAD) proxy_free(ss, p);
    ss->dead = 0;
}

// Merge the sorted runs src[lo, mid) and src[mid, hi) into dst (stable).
static void merge(const sap_end *src, sap_end *dst, int lo, int mid, int hi)
{
    int i = lo, j = mid, o = lo;
    while (i < mid && j < hi) dst[o++] = before(&src[j], &src[i]) ? src[j++] : src[i++];
    while (i < mid) dst[o++] = src[i++];
    while (j < hi) dst[o++] = src[j++];
}

// Sort list k (stable merge sort through the scratch list, runs of 16 by
// insertion first) and note where each end went.
static void sort_list(dxSapSpace *ss, int k)
{
    sap_end *src = ss->end[k], *dst = ss->tmp;
    const int n = ss->nend;
    for (int lo = 0; lo < n; lo += 16) {
        const int hi = lo + 16 < n ? lo + 16 : n;
        for (int i = lo + 1; i < hi; i++) {
            const sap_end x = src[i];
            int j = i;
            for (; j > lo && before(&x, &src[j - 1]); j--) src[j] = src[j - 1];
            src[j] = x;
        }
    }
    for (int w = 16; w < n; w *= 2) {
        for (int lo = 0; lo < n; lo += 2 * w) {
            const int mid = lo + w < n ? lo + w : n, hi = lo + 2 * w < n ? lo + 2 * w : n;
            merge(src, dst, lo, mid, hi);
        }
        sap_end *t = src;
        src = dst;
        dst = t;
    }
    if (src != ss->end[k]) memcpy(ss->end[k], src, (size_t)n * sizeof *src);
    for (int i = 0; i < n; i++) ss->px[ss->end[k][i].e >> 1].at[k][ss->end[k][i].e & 1] = i;
}

// Before ends are moved one by one, all three lists must be sorted.
static void sort_rest(dxSapSpace *ss)
{
    if (!ss->rest_unsorted) return;
    sort_list(ss, 1);
    sort_list(ss, 2);
    ss->rest_unsorted = 0;
}

// Fill the lists afresh with every listed and new proxy (freeing the removed
// ones), sort the first, and find the set by one sweep along it: each low end
// meets the boxes open there (kept side by side for the scan) and keeps those
// that overlap on the other two axes. Its cost, in swaps of ends, is kept.
static void rebuild(dxSapSpace *ss)
{
    dxSpace *s = &ss->s;
    for (int p = 0; p < ss->npx; p++)
        if (ss->px[p].state == PX_DEAD) proxy_free(ss, p);
    ss->dead = 0;
    ss->nend = 0;
    for (int i = 0; i < s->count; i++) {
        const int p = ss->proxy_of[i];
        sap_proxy *x = &ss->px[p];
        if (x->state != PX_NEW && x->state != PX_LISTED) continue;
        x->state = PX_LISTED;
        for (int k = 0; k < 3; k++) {
            ss->end[k][ss->nend] = (sap_end){ x->box[2 * k], 2 * p };
            ss->end[k][ss->nend + 1] = (sap_end){ x->box[2 * k + 1], 2 * p + 1 };
        }
        ss->nend += 2;
    }
    // The first list now, the other two only when ends are moved next (a
    // scene sorted afresh at every refresh never needs them).
    sort_list(ss, 0);
    ss->rest_unsorted = 1;

    dxSapPairClear(&ss->pairs);
    long visits = 0;
    int open = 0;
    for (int i = 0; i < ss->nend; i++) {
        const int p = ss->end[0][i].e >> 1;
        if (ss->end[0][i].e & 1) {   // close p: the last open box takes its place
            const int j = ss->open_at[p];
            ss->open[j] = ss->open[--open];
            ss->open_at[ss->open[j].p] = j;
            continue;
        }
        const dReal *a = ss->px[p].box;
        for (int j = 0; j < open; j++) {
            const dReal *b = ss->open[j].b;
            if ((a[2] <= b[1]) & (b[0] <= a[3]) & (a[4] <= b[3]) & (b[2] <= a[5])) {
                const int q = ss->open[j].p;
                dxSapPairAppend(&ss->pairs, p, ss->px[p].g, q, ss->px[q].g);
            }
        }
        visits += open;
        ss->open[open] = (sap_open){ { a[2], a[3], a[4], a[5] }, p };
        ss->open_at[p] = open++;
    }
    // Room for the set to grow by half without allocating.
    dxSapPairReserve(&ss->pairs, ss->pairs.count + ss->pairs.count / 2 + 64);
    // Measured on a pile of boxes: a visit of the sweep costs about a quarter
    // of a swap of ends (which looks at the other proxy), sorting the three
    // lists about two swaps an end.
    ss->afresh_cost = visits / 4 + 2L * 3 * ss->nend;
}

// Bring the structure up to date with the geoms' AABBs (current: the caller
// updated them). Returns 0 if it is stale while a collision of this space
// walks it: the caller then tests geoms one by one.
//
// Moving the changed boxes' ends costs swaps in proportion to the ends they
// pass; sorting afresh costs about the same whatever moved. The changed boxes
// are counted first: if, at the last refresh's swaps per box, moving them
// would cost more than the last fresh sort, the lists are sorted afresh;
// moving also gives up for a fresh sort once its swaps pass that cost. So a
// refresh costs at most about twice the cheaper of the two. The swaps per box
// decay while sorting afresh, so that moving is tried again after a while.
static int sap_refresh(dxSapSpace *ss)
{
    if (!ss->stale) return 1;
    if (ss->walking > 0) return 0;
    dxSpace *s = &ss->s;
    int changed = 0;
    for (int i = 0; i < s->count; i++) {
        const sap_proxy *x = &ss->px[ss->proxy_of[i]];
        dReal nb[6];
        read_box(ss, s->geoms[i], nb);
        changed += x->state == PX_LISTED && memcmp(nb, x->box, sizeof nb) != 0;
    }
    int afresh = changed * ss->swaps_per_move > (double)ss->afresh_cost;
    if (afresh) ss->swaps_per_move *= 0.98;   // so that moving is tried again now and then
    const long swaps0 = ss->swaps;
    int fresh = 0, leaving = 0, moved = 0;
    ss->nwild = 0;
    for (int i = 0; i < s->count; i++) {
        const int p = ss->proxy_of[i];
        sap_proxy *x = &ss->px[p];
        dReal nb[6];
        const int wild = read_box(ss, s->geoms[i], nb);
        if (x->state == PX_LISTED) {
            if (memcmp(nb, x->box, sizeof nb) == 0) continue;
            if (!wild && afresh) {
                memcpy(x->box, nb, sizeof nb);
                continue;
            }
            if (!wild) {
                sort_rest(ss);
                move_proxy(ss, p, nb);
                moved++;
                afresh = ss->swaps - swaps0 > ss->afresh_cost;
                continue;
            }
            leaving++;
        }
        memcpy(x->box, nb, sizeof nb);
        x->state = wild ? PX_WILD : PX_NEW;
        if (wild) ss->wild[ss->nwild++] = p;
        else fresh++;
    }
    if (moved > 0) ss->swaps_per_move = (double)(ss->swaps - swaps0) / moved;
    if (afresh || 8 * fresh > ss->nend / 2) {
        rebuild(ss);
    } else {
        if (ss->dead > 0 || leaving > 0) compact(ss);
        for (int i = 0; i < s->count && fresh > 0; i++)
            if (ss->px[ss->proxy_of[i]].state == PX_NEW) link_proxy(ss, ss->proxy_of[i]);
    }
    ss->stale = 0;
    return 1;
}

// ---- the space's operations --------------------------------------------------------

static void sap_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    if (!sap_refresh(ss)) {
        for (int i = 0; i < s->count; i++)
            for (int j = i + 1; j < s->count; j++)
                dxSpaceTestPair(s->geoms[i], s->geoms[j], data, cb);
        return;
    }
    ss->walking++;
    const dxSapPair *pair = ss->pairs.pair;
    for (int i = 0; i < ss->pairs.count; i++)
        dxSpaceTestPairInline(pair[i].ga, pair[i].gb, data, cb);
    // Each wild proxy against every other geom (wild pairs once).
    for (int w = 0; w < ss->nwild; w++) {
        const int p = ss->wild[w];
        for (int i = 0; i < s->count; i++) {
            const int q = ss->proxy_of[i];
            if (q == p || (ss->px[q].state == PX_WILD && q < p)) continue;
            dxSpaceTestPair(ss->px[p].g, s->geoms[i], data, cb);
        }
    }
    ss->walking--;
}

// g (not in the space) against the listed proxies whose low end along the
// sweep axis is not above g's high end (the list's prefix up to there, found
// by bisection) and whose boxes overlap g's, then against the wild ones.
// g first in each pair.
static void sap_collide_geom(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    dReal gb[6];
    if (!sap_refresh(ss) || read_box(ss, g, gb)) {
        for (int i = 0; i < s->count; i++) dxSpaceTestPair(g, s->geoms[i], data, cb);
        return;
    }
    ss->walking++;
    const sap_end *list = ss->end[0];
    int lo = 0, hi = ss->nend;
    while (lo < hi) {   // the first end above gb[1]
        int mid = lo + (hi - lo) / 2;
        if (list[mid].v <= gb[1]) lo = mid + 1;
        else hi = mid;
    }
    for (int i = 0; i < lo; i++) {
        if (list[i].e & 1) continue;
        const sap_proxy *x = &ss->px[list[i].e >> 1];
        if (boxes_overlap(gb, x->box)) dxSpaceTestPair(g, x->g, data, cb);
    }
    for (int w = 0; w < ss->nwild; w++) dxSpaceTestPair(g, ss->px[ss->wild[w]].g, data, cb);
    ss->walking--;
}

static void sap_destroy(dxSpace *s)
{
    dxSapSpace *ss = (dxSapSpace *)s;
    dFree(ss->px, (size_t)ss->pxcap * sizeof *ss->px);
    for (int k = 0; k < 3; k++) dFree(ss->end[k], 2 * (size_t)ss->pxcap * sizeof *ss->end[k]);
    dFree(ss->tmp, 2 * (size_t)ss->pxcap * sizeof *ss->tmp);
    dFree(ss->wild, (size_t)ss->pxcap * sizeof *ss->wild);
    dFree(ss->open, (size_t)ss->pxcap * sizeof *ss->open);
    dFree(ss->open_at, (size_t)ss->pxcap * sizeof *ss->open_at);
    dFree(ss->proxy_of, (size_t)ss->proxy_of_cap * sizeof *ss->proxy_of);
    dxSapPairFree(&ss->pairs);
}

static const dxSpaceOps sap_ops = { sap_added, sap_removed, sap_collide, sap_collide_geom,
                                    sap_destroy };

// The class operations of all spaces, with compute_aabb wrapped: the space's
// box is recomputed exactly when something in it changed, which makes the
// proxies stale.
static dxGeomClassOps sap_class_ops;
static void (*union_aabb)(dxGeom *g);

static void sap_aabb(dxGeom *g)
{
    union_aabb(g);
    ((dxSapSpace *)g)->stale = 1;
}

dSpaceID dSweepAndPruneSpaceCreate(dSpaceID parent, int axisorder)
{
    const int a0 = axisorder & 3, a1 = (axisorder >> 2) & 3, a2 = (axisorder >> 4) & 3;
    DX_CHECK_ARG(a0 < 3 && a1 < 3 && a2 < 3 && a0 != a1 && a1 != a2 && a0 != a2 &&
                     (axisorder & ~63) == 0,
                 return NULL, "axisorder %d is not one of the dSAP_AXES_* orders", axisorder);
    dxSpace *s = dxSpaceCreate(sizeof(dxSapSpace), dSweepAndPruneSpaceClass, &sap_ops, parent);
    if (!s) return NULL;
    if (!union_aabb) {
        sap_class_ops = *s->geom.ops;
        union_aabb = sap_class_ops.compute_aabb;
        sap_class_ops.compute_aabb = sap_aabb;
    }
    s->geom.ops = &sap_class_ops;
    dxSapSpace *ss = (dxSapSpace *)s;
    ss->axis[0] = a0;
    ss->axis[1] = a1;
    ss->axis[2] = a2;
    ss->free_px = -1;
    ss->stale = 1;
    return s;
}
