// SPDX-License-Identifier: BSD-3-Clause
//
// collide_threads.c -- two threads colliding one geom (collide_threads.h).

#include "collide_threads.h"

#include <pthread.h>
#include <string.h>

int ct_same_contacts(const dContactGeom *a, const dContactGeom *b, int n)
{
    for (int i = 0; i < n; i++)
        if (memcmp(a[i].pos, b[i].pos, 3 * sizeof(dReal)) ||
            memcmp(a[i].normal, b[i].normal, 3 * sizeof(dReal)) ||
            memcmp(&a[i].depth, &b[i].depth, sizeof(dReal)) || a[i].g1 != b[i].g1 ||
            a[i].g2 != b[i].g2 || a[i].side1 != b[i].side1 || a[i].side2 != b[i].side2)
            return 0;
    return 1;
}

static void place(ct_worker *w, int p)
{
    for (int k = 0; k < w->kinds; k++)
        dGeomSetPosition(w->geom[k], w->pose[p][0], w->pose[p][1], w->pose[p][2]);
}

void ct_record(ct_worker *w, int touching[CT_KINDS])
{
    for (int k = 0; k < CT_KINDS; k++) touching[k] = 0;
    for (int p = 0; p < w->poses; p++) {
        place(w, p);
        for (int k = 0; k < w->kinds; k++) {
            w->expected_n[p][k] = dCollide(w->target, w->geom[k], CT_MAXC, w->expected[p][k],
                                           sizeof(dContactGeom));
            touching[k] += w->expected_n[p][k] > 0;
        }
    }
}

static void *work(void *arg)
{
    ct_worker *w = (ct_worker *)arg;
    dAllocateODEDataForThread(dAllocateMaskAll);
    for (int r = 0; r < w->rounds; r++)
        for (int p = 0; p < w->poses; p++) {
            place(w, p);
            for (int k = 0; k < w->kinds; k++) {
                dContactGeom c[CT_MAXC];
                int n = dCollide(w->target, w->geom[k], CT_MAXC, c, sizeof c[0]);
                if (n != w->expected_n[p][k] || !ct_same_contacts(c, w->expected[p][k], n))
                    w->mismatches++;
            }
        }
    dCleanupODEAllDataForThread();
    return NULL;
}

int ct_run_pair(ct_worker *a, ct_worker *b)
{
    ct_worker *w[2] = { a, b };
    pthread_t t[2];
    int started[2];
    a->mismatches = b->mismatches = 0;
    for (int i = 0; i < 2; i++) started[i] = pthread_create(&t[i], NULL, work, w[i]) == 0;
    for (int i = 0; i < 2; i++)
        if (started[i]) pthread_join(t[i], NULL);
    if (!started[0] || !started[1]) return -1;
    return a->mismatches + b->mismatches;
}
