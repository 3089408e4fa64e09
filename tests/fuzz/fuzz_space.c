// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_space.c -- a space of each kind (simple, hash, quadtree, sweep and
// prune), nested spaces, and a sequence of operations from the input: geoms
// inserted, moved, destroyed, moved between spaces, enabled and disabled,
// category and collide bits set, dSpaceCollide and dSpaceCollide2 on any
// pair. Checked: every pair the callback gets is enabled, allowed by the bits
// and AABB-overlapping; dSpaceCollide on a space holding only geoms reports
// each such pair exactly once; the contacts pass fz_check_contacts.

#include "fuzz_shapes.h"

#include <string.h>

#define MAX_GEOMS 32
#define MAX_SPACES 4

typedef struct world_state {
    dSpaceID spaces[MAX_SPACES];
    int nspaces;
    dGeomID geoms[MAX_GEOMS];       // NULL: free slot
    unsigned char seen[MAX_GEOMS][MAX_GEOMS];
    int record;                     // 1 while a flat dSpaceCollide is checked
    int depth;
    fz_input *in;
    const fz_shapes *store;
} world_state;

static int index_of(dGeomID g) { return (int)(intptr_t)dGeomGetData(g) - 1; }

static int bits_allow(dGeomID a, dGeomID b)
{
    return (dGeomGetCategoryBits(a) & dGeomGetCollideBits(b)) ||
           (dGeomGetCategoryBits(b) & dGeomGetCollideBits(a));
}

static int aabbs_overlap(dGeomID a, dGeomID b)
{
    dReal x[6], y[6];
    dGeomGetAABB(a, x);
    dGeomGetAABB(b, y);
    for (int i = 0; i < 3; i++)
        if (x[2 * i] > y[2 * i + 1] || y[2 * i] > x[2 * i + 1]) return 0;
    return 1;
}

static void near_callback(void *data, dGeomID o1, dGeomID o2)
{
    world_state *w = data;
    if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
        if (w->depth < 4) {
            w->depth++;
            dSpaceCollide2(o1, o2, w, near_callback);
            w->depth--;
        }
        return;
    }
    if (!dGeomIsEnabled(o1) || !dGeomIsEnabled(o2)) fz_fail("a disabled geom was reported");
    if (!bits_allow(o1, o2)) fz_fail("a pair the category/collide bits exclude was reported");
    if (!aabbs_overlap(o1, o2)) fz_fail("a pair with disjoint AABBs was reported");
    if (w->record) {
        int i = index_of(o1), j = index_of(o2);
        if (i < 0 || j < 0 || i == j) fz_fail("dSpaceCollide reported a geom with itself");
        if (w->seen[i][j]++ || w->seen[j][i]++) fz_fail("dSpaceCollide reported a pair twice");
    }
    if (!fz_pair_cheap(w->store, o1, o2)) return;
    dContactGeom c[8];
    int flags = 1 + (int)fz_pick(w->in, 8);
    int n = dCollide(o1, o2, flags, c, sizeof c[0]);
    fz_check_contacts(o1, o2, flags, c, sizeof c[0], n);
}

static dSpaceID make_space(fz_input *in, dSpaceID parent)
{
    switch (fz_pick(in, 4)) {
    case 0: return dSimpleSpaceCreate(parent);
    case 1: {
        dSpaceID s = dHashSpaceCreate(parent);
        int lo = (int)fz_pick(in, 16) - 8, hi = (int)fz_pick(in, 16) - 8;
        dHashSpaceSetLevels(s, lo, hi);
        return s;
    }
    case 2: {
        dVector3 c, e;
        fz_vec3(in, 4, c);
        for (int i = 0; i < 3; i++) e[i] = fz_size(in, 16);
        return dQuadTreeSpaceCreate(parent, c, e, (int)fz_pick(in, 8));
    }
    default: return dSweepAndPruneSpaceCreate(parent, (int)fz_pick(in, 8));
    }
}

// dSpaceCollide on s; when s holds only geoms, compare the pairs reported with
// every enabled, bit-allowed, overlapping pair of its geoms.
static void collide_space(world_state *w, dSpaceID s)
{
    int n = dSpaceGetNumGeoms(s), flat = 1;
    for (int i = 0; i < n; i++)
        if (dGeomIsSpace(dSpaceGetGeom(s, i))) flat = 0;
    memset(w->seen, 0, sizeof w->seen);
    w->record = flat;
    dSpaceCollide(s, w, near_callback);
    w->record = 0;
    if (!flat) return;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            dGeomID a = dSpaceGetGeom(s, i), b = dSpaceGetGeom(s, j);
            int want = dGeomIsEnabled(a) && dGeomIsEnabled(b) && bits_allow(a, b) &&
                       aabbs_overlap(a, b);
            int got = w->seen[index_of(a)][index_of(b)] || w->seen[index_of(b)][index_of(a)];
            if (want != got)
                fz_fail("space class %d: pair of classes %d, %d %s", dSpaceGetClass(s),
                        dGeomGetClass(a), dGeomGetClass(b),
                        want ? "overlaps but was not reported" : "reported unexpectedly");
        }
}

// Any geom or space of the state, or NULL.
static dGeomID any_object(world_state *w, fz_input *in)
{
    unsigned k = fz_pick(in, MAX_GEOMS + MAX_SPACES);
    if (k < MAX_GEOMS) return w->geoms[k];
    k -= MAX_GEOMS;
    return (int)k < w->nspaces ? (dGeomID)w->spaces[k] : NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        dInitODE2(0);
        fz_install_handlers();
        ready = 1;
    }
    fz_input in = {data, size, 0};
    world_state w;
    memset(&w, 0, sizeof w);
    w.in = &in;
    fz_shapes store = {0};
    w.store = &store;
    // a refused space (a bad axis order, reported) leaves a simple one
    w.spaces[0] = make_space(&in, 0);
    if (!w.spaces[0]) w.spaces[0] = dSimpleSpaceCreate(0);
    w.nspaces = 1;
    for (int op = 0; op < 256 && in.left > 0; op++) {
        dSpaceID s = w.spaces[fz_pick(&in, (unsigned)w.nspaces)];
        unsigned k = fz_pick(&in, MAX_GEOMS);
        dGeomID g = w.geoms[k];
        switch (fz_pick(&in, 10)) {
        case 0:
        case 1:
            if (!g && (w.geoms[k] = fz_make_geom(&in, s, &store)))
                dGeomSetData(w.geoms[k], (void *)(intptr_t)(k + 1));
            break;
        case 2:
            if (g) fz_pose_geom(&in, g);
            break;
        case 3:
            if (g) {
                dGeomDestroy(g);
                w.geoms[k] = NULL;
            }
            break;
        case 4:
            if (g && dGeomGetSpace(g) != s) {
                if (dGeomGetSpace(g)) dSpaceRemove(dGeomGetSpace(g), g);
                dSpaceAdd(s, g);
            }
            break;
        case 5:
            if (g) {
                dGeomSetCategoryBits(g, fz_u8(&in) & 7);
                dGeomSetCollideBits(g, fz_u8(&in) & 7);
            }
            break;
        case 6:
            if (g) {
                if (dGeomIsEnabled(g)) dGeomDisable(g);
                else dGeomEnable(g);
            }
            break;
        case 7: collide_space(&w, s); break;
        case 8: {
            dGeomID a = any_object(&w, &in), b = any_object(&w, &in);
            if (a && b) dSpaceCollide2(a, b, &w, near_callback);
            break;
        }
        default:
            if (w.nspaces < MAX_SPACES) {
                dSpaceID sub = make_space(&in, s);
                if (sub) {
                    dSpaceSetCleanup(sub, 1);
                    w.spaces[w.nspaces++] = sub;
                }
            }
            break;
        }
    }
    collide_space(&w, w.spaces[0]);
    // a geom left out of every space (a refused dSpaceAdd) is not cleaned up
    for (int k = 0; k < MAX_GEOMS; k++)
        if (w.geoms[k] && !dGeomGetSpace(w.geoms[k])) dGeomDestroy(w.geoms[k]);
    dSpaceSetCleanup(w.spaces[0], 1);
    dSpaceDestroy(w.spaces[0]);
    fz_shapes_free(&store);
    return 0;
}
