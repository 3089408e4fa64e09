// SPDX-License-Identifier: BSD-3-Clause
//
// backend_shadow.c -- shadow mode (backend.h): each dCollide that reaches
// the selected backend also runs on the shadow backend into a buffer of its
// own; the two results are compared (backend_shadow_compare.c) and counted
// per pair class, and the first disagreements of each pair class are kept
// whole. One lock serialises the shadowed calls, the counts and their
// readers. The shadow keeps its shapes in the geom's second cache slot,
// swapped in around its calls, so two caching backends never rebuild each
// other's shapes.

#include "backend_shadow.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "backend_support.h"

typedef struct pair_entry {
    dCollisionShadowStats stats;
    dCollisionShadowRecord *records;   // dCOLLISION_SHADOW_RECORDS, from the first disagreement
    int kept;
} pair_entry;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pair_entry pairs[dGeomNumClasses][dGeomNumClasses];   // [smaller class][larger]
static dContactGeom buffer[dCOLLISION_SHADOW_MAX_CONTACTS];   // the shadow's contacts
static int unreported;   // calls counted since the last report or reset
static int exit_report_registered;

static void swap_cache_slot(dxGeom *g)
{
    void *cache = g->backend_cache;
    const void *owner = g->backend_cache_owner;
    g->backend_cache = g->shadow_cache;
    g->backend_cache_owner = g->shadow_cache_owner;
    g->shadow_cache = cache;
    g->shadow_cache_owner = owner;
}

// Keep one disagreement whole (the entry has room).
static void keep_record(pair_entry *e, dxGeom *o1, dxGeom *o2, int flags, const dContactGeom *a,
                        int na, int skip, int nb, const dxShadowVerdict *v)
{
    if (!e->records) {
        e->records = calloc(dCOLLISION_SHADOW_RECORDS, sizeof *e->records);
        if (!e->records) return;
    }
    dCollisionShadowRecord *r = &e->records[e->kept++];
    memset(r, 0, sizeof *r);
    dxShapeDesc d;
    dxGeomDescribe(o1, &d);
    memcpy(r->params1, d.p, sizeof r->params1);
    dxGeomDescribe(o2, &d);
    memcpy(r->params2, d.p, sizeof r->params2);
    r->class1 = o1->ops->cls;
    r->class2 = o2->ops->cls;
    dxGeomPose(o1, r->pos1, r->R1);
    dxGeomPose(o2, r->pos2, r->R2);
    r->flags = flags;
    r->kinds = v->kinds;
    r->depth_error = v->depth_error;
    r->normal_error = v->normal_error;
    r->point_error = v->point_first > v->point_shadow ? v->point_first : v->point_shadow;
    r->n_first = na;
    r->n_shadow = nb;
    for (int i = 0; i < na && i < 4; i++) {
        r->first[i] = *(const dContactGeom *)((const char *)a + (size_t)i * (size_t)skip);
        r->first[i].g1 = r->first[i].g2 = NULL;
    }
    for (int i = 0; i < nb && i < 4; i++) {
        r->shadow[i] = buffer[i];
        r->shadow[i].g1 = r->shadow[i].g2 = NULL;
    }
}

static double larger(double a, double b) { return b > a ? b : a; }

// Count one compared call in its pair class.
static void count(pair_entry *e, dxGeom *o1, dxGeom *o2, int flags, const dContactGeom *a, int na,
                  int skip, int nb, const dxShadowVerdict *v)
{
    dCollisionShadowStats *s = &e->stats;
    s->worst_depth = larger(s->worst_depth, v->depth_error);
    s->worst_normal = larger(s->worst_normal, v->normal_error);
    s->worst_point_first = larger(s->worst_point_first, v->point_first);
    s->worst_point_shadow = larger(s->worst_point_shadow, v->point_shadow);
    if (!v->kinds) return;
    s->disagreements++;
    for (int k = 0; k < dCOLLISION_SHADOW_KINDS; k++)
        if (v->kinds & (1 << k)) s->kinds[k]++;
    if (e->kept < dCOLLISION_SHADOW_RECORDS) keep_record(e, o1, o2, flags, a, na, skip, nb, v);
}

int dxShadowCollide(const dCollisionBackend *first, const dCollisionBackend *shadow,
                    dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip)
{
    pthread_mutex_lock(&lock);
    int n = first->collide(o1, o2, flags, contact, skip);
    int c1 = o1->ops->cls, c2 = o2->ops->cls;
    if (c1 < 0 || c2 < 0 || c1 >= dGeomNumClasses || c2 >= dGeomNumClasses) {
        pthread_mutex_unlock(&lock);
        return n;
    }
    pair_entry *e = c1 <= c2 ? &pairs[c1][c2] : &pairs[c2][c1];
    e->stats.class1 = c1 <= c2 ? c1 : c2;
    e->stats.class2 = c1 <= c2 ? c2 : c1;
    e->stats.calls++;
    unreported = 1;
    if (!shadow->supports(c1, c2)) {
        e->stats.not_answered++;
        pthread_mutex_unlock(&lock);
        return n;
    }
    int max = flags & 0xffff;
    if (max > dCOLLISION_SHADOW_MAX_CONTACTS) max = dCOLLISION_SHADOW_MAX_CONTACTS;
    int shadow_flags = (flags & ~0xffff) | max;
    swap_cache_slot(o1);
    swap_cache_slot(o2);
    int m = shadow->collide(o1, o2, shadow_flags, buffer, sizeof buffer[0]);
    swap_cache_slot(o1);
    swap_cache_slot(o2);
    if (m < 0) m = 0;
    if (m > max) m = max;
    dxShadowVerdict v;
    dxShadowCompare(o1, o2, max, contact, n, skip, buffer, m, &v);
    count(e, o1, o2, shadow_flags, contact, n, skip, m, &v);
    pthread_mutex_unlock(&lock);
    return n;
}

void dxShadowNotify(dxGeom *g, void (*notify)(dxGeom *g))
{
    if (!g->shadow_cache) return;
    swap_cache_slot(g);
    notify(g);
    swap_cache_slot(g);
}

int dCollisionShadowGetStats(dCollisionShadowStats *out, int max)
{
    DX_CHECK_ARG(max >= 0, return 0, "max (%d) is negative", max);
    DX_CHECK_ARG(out != NULL || max == 0, return 0, "out is NULL");
    pthread_mutex_lock(&lock);
    int n = 0;
    for (int i = 0; i < dGeomNumClasses; i++)
        for (int j = i; j < dGeomNumClasses; j++) {
            if (!pairs[i][j].stats.calls) continue;
            if (n < max) out[n] = pairs[i][j].stats;
            n++;
        }
    pthread_mutex_unlock(&lock);
    return n;
}

int dCollisionShadowGetRecords(int class1, int class2, dCollisionShadowRecord *out, int max)
{
    DX_CHECK_ARG(class1 >= 0 && class1 < dGeomNumClasses, return 0,
                 "class1 (%d) is not a geom class", class1);
    DX_CHECK_ARG(class2 >= 0 && class2 < dGeomNumClasses, return 0,
                 "class2 (%d) is not a geom class", class2);
    DX_CHECK_ARG(max >= 0, return 0, "max (%d) is negative", max);
    DX_CHECK_ARG(out != NULL || max == 0, return 0, "out is NULL");
    pthread_mutex_lock(&lock);
    const pair_entry *e = class1 <= class2 ? &pairs[class1][class2] : &pairs[class2][class1];
    for (int i = 0; i < e->kept && i < max; i++) out[i] = e->records[i];
    int n = e->kept;
    pthread_mutex_unlock(&lock);
    return n;
}

void dCollisionShadowReset(void)
{
    pthread_mutex_lock(&lock);
    for (int i = 0; i < dGeomNumClasses; i++)
        for (int j = 0; j < dGeomNumClasses; j++) {
            memset(&pairs[i][j].stats, 0, sizeof pairs[i][j].stats);
            pairs[i][j].kept = 0;
        }
    unreported = 0;
    pthread_mutex_unlock(&lock);
}

void dCollisionShadowReport(FILE *f)
{
    DX_CHECK_ARG(f != NULL, return, "f is NULL");
    dxShadowPrint(f);
    pthread_mutex_lock(&lock);
    unreported = 0;
    pthread_mutex_unlock(&lock);
}

static void report_at_exit(void)
{
    if (unreported) dCollisionShadowReport(stderr);
}

void dxShadowReportAtExit(void)
{
    pthread_mutex_lock(&lock);
    if (!exit_report_registered) exit_report_registered = atexit(report_at_exit) == 0;
    pthread_mutex_unlock(&lock);
}
