// SPDX-License-Identifier: BSD-3-Clause
//
// measure.c -- odecontactdiff's judge: one posed pair through each backend,
// held to the contract against the ground truth (tools/contact_truth.h).
// A backend's result passes when: it reports a contact exactly when the
// shapes overlap (unless the truth is within the depth tolerance of
// touching); its deepest depth is within 5 mm + 5 % of the true depth;
// moving g1 along the deepest normal by that depth leaves them overlapping
// by no more than that tolerance; each contact point is within both shapes
// to 1 cm + 10 % of its depth. The angle to the true normal is measured,
// not judged (the true normal is not unique on symmetric poses).

#include "odecontactdiff.h"

#include <math.h>
#include <ode/backend.h>
#include <stdlib.h>
#include <string.h>

static double larger(double a, double b) { return b > a ? b : a; }

double cd_grazing_band(const cd_shape *a, const cd_shape *b)
{
    double rel = CD_BAND_REL * (cd_bounding_radius(a) + cd_bounding_radius(b));
    return rel < CD_BAND ? rel : CD_BAND;
}

// The row of (backend, pair), added (zeroed) if new; NULL if out of memory.
static cd_row *row_for(cd_results *res, const char *backend, const char *pair)
{
    for (int i = 0; i < res->count; i++)
        if (strcmp(res->rows[i].backend, backend) == 0 && strcmp(res->rows[i].pair, pair) == 0)
            return &res->rows[i];
    if (res->count == res->capacity) {
        int cap = res->capacity ? 2 * res->capacity : 32;
        cd_row *grown = realloc(res->rows, (size_t)cap * sizeof *grown);
        if (!grown) return NULL;
        res->rows = grown;
        res->capacity = cap;
    }
    cd_row *r = &res->rows[res->count++];
    memset(r, 0, sizeof *r);
    snprintf(r->backend, sizeof r->backend, "%s", backend);
    snprintf(r->pair, sizeof r->pair, "%s", pair);
    return r;
}

static void add_sample(cd_row *r, double true_depth, double error)
{
    if (r->nsamples == r->capacity) {
        int cap = r->capacity ? 2 * r->capacity : 64;
        double *grown = realloc(r->samples, (size_t)cap * 2 * sizeof *grown);
        if (!grown) return;
        r->samples = grown;
        r->capacity = cap;
    }
    r->samples[2 * r->nsamples] = true_depth;
    r->samples[2 * r->nsamples + 1] = error;
    r->nsamples++;
}

// How much (g1, g2) still overlap after moving them apart by depth along n
// (g1 along n, or g2 against it when g1 is a plane): the truth's depth at
// the moved pose. The pose is put back.
static double overlap_after_separation(dGeomID g1, dGeomID g2, const dReal n[3], double depth)
{
    dGeomID moved = dGeomGetClass(g1) == dPlaneClass ? g2 : g1;
    double sign = moved == g1 ? 1 : -1;
    const dReal *p = dGeomGetPosition(moved);
    double old[3] = { p[0], p[1], p[2] };
    dGeomSetPosition(moved, old[0] + sign * depth * n[0], old[1] + sign * depth * n[1],
                     old[2] + sign * depth * n[2]);
    contact_truth t;
    double left = contact_truth_compute(g1, g2, &t) ? t.depth : 0;
    dGeomSetPosition(moved, old[0], old[1], old[2]);
    return left;
}

// One backend's contacts for the pair, judged against the truth t.
static void judge(cd_row *r, dGeomID g1, dGeomID g2, const contact_truth *t,
                  const dContactGeom *c, int n)
{
    double tol = CD_DEPTH_ABS + CD_DEPTH_REL * larger(t->depth, 0);
    const dContactGeom *deep = NULL;
    for (int i = 0; i < n; i++)
        if (!deep || c[i].depth > deep->depth) deep = &c[i];
    if ((n > 0) != t->overlap && fabs(t->depth) > tol) r->contact_fail++;
    if (!deep) {
        if (t->overlap) add_sample(r, t->depth, -t->depth);
        return;
    }
    if (t->overlap) {
        double err = deep->depth - t->depth;
        add_sample(r, t->depth, err);
        r->worst_depth = larger(r->worst_depth, fabs(err));
        if (fabs(err) > tol) r->depth_fail++;
        double cosine = deep->normal[0] * t->normal[0] + deep->normal[1] * t->normal[1] +
                        deep->normal[2] * t->normal[2];
        cosine = cosine > 1 ? 1 : cosine < -1 ? -1 : cosine;
        r->worst_normal = larger(r->worst_normal, acos(cosine) * 180 / M_PI);
    }
    double left = overlap_after_separation(g1, g2, deep->normal, deep->depth);
    r->worst_sep = larger(r->worst_sep, left);
    if (left > tol) r->sep_fail++;
    for (int i = 0; i < n; i++) {
        double p[3] = { c[i].pos[0], c[i].pos[1], c[i].pos[2] };
        double out = larger(-contact_truth_point_depth(g1, p), -contact_truth_point_depth(g2, p));
        r->worst_point = larger(r->worst_point, out);
        if (out > CD_POINT_ABS + CD_POINT_REL * fabs(c[i].depth)) r->point_fail++;
    }
}

void cd_measure(cd_results *res, const char *const *backends, dGeomID g1, dGeomID g2,
                const contact_truth *t)
{
    int c1 = dGeomGetClass(g1), c2 = dGeomGetClass(g2);
    char pair[40];
    snprintf(pair, sizeof pair, "%s-%s", cd_class_name(c1), cd_class_name(c2));
    cd_row *truth = row_for(res, "truth", pair);
    if (!truth) return;
    truth->poses++;
    truth->answered++;
    truth->overlapping += t->overlap;
    for (int b = 0; backends[b]; b++) {
        cd_row *r = row_for(res, backends[b], pair);
        if (!r) return;
        r->poses++;
        r->overlapping += t->overlap;
        if (!dCollisionBackendSupports(backends[b], c1, c2)) continue;
        r->answered++;
        dCollisionSetBackend(backends[b]);
        dContactGeom c[CD_MAX_CONTACTS];
        int n = dCollide(g1, g2, CD_MAX_CONTACTS, c, sizeof c[0]);
        judge(r, g1, g2, t, c, n);
    }
}

int cd_row_passes(const cd_row *r)
{
    return r->answered > 0 && r->contact_fail == 0 && r->depth_fail == 0 && r->sep_fail == 0 &&
           r->point_fail == 0;
}

void cd_free_results(cd_results *res)
{
    for (int i = 0; i < res->count; i++) free(res->rows[i].samples);
    free(res->rows);
    memset(res, 0, sizeof *res);
}
