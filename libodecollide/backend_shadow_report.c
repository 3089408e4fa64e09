// SPDX-License-Identifier: BSD-3-Clause
//
// backend_shadow_report.c -- shadow mode's printed report: a table of the
// counts per pair class, then the first kept disagreement of each pair
// class (poses, sizes, both results' deepest contacts).

#include "backend_shadow.h"

static const char *class_name(int cls)
{
    static const char *const names[] = { "sphere", "box", "capsule", "cylinder", "plane",
                                         "ray", "convex", "transform", "trimesh",
                                         "heightfield" };
    if (cls >= 0 && cls < (int)(sizeof names / sizeof names[0])) return names[cls];
    return cls >= dFirstUserClass && cls <= dLastUserClass ? "user" : "other";
}

static const char *const kind_names[dCOLLISION_SHADOW_KINDS] = { "contact", "depth", "normal",
                                                                 "point", "manifold" };

static void print_geom(FILE *f, const char *label, int cls, const dReal *p, const dReal *pos,
                       const dReal *R)
{
    fprintf(f, "    %s %s (%.6g, %.6g, %.6g, %.6g) at (%.9g, %.9g, %.9g), R rows (%.9g %.9g %.9g) "
            "(%.9g %.9g %.9g) (%.9g %.9g %.9g)\n", label, class_name(cls), (double)p[0],
            (double)p[1], (double)p[2], (double)p[3], (double)pos[0], (double)pos[1],
            (double)pos[2], (double)R[0], (double)R[1], (double)R[2], (double)R[4],
            (double)R[5], (double)R[6], (double)R[8], (double)R[9], (double)R[10]);
}

static void print_result(FILE *f, const char *label, const dContactGeom *c, int n)
{
    fprintf(f, "    %s: %d contact%s", label, n, n == 1 ? "" : "s");
    int shown = n < 4 ? n : 4;
    for (int i = 0; i < shown; i++)
        fprintf(f, "%s pos (%.6g, %.6g, %.6g) normal (%.6f, %.6f, %.6f) depth %.6g",
                i ? ";" : ":", (double)c[i].pos[0], (double)c[i].pos[1], (double)c[i].pos[2],
                (double)c[i].normal[0], (double)c[i].normal[1], (double)c[i].normal[2],
                (double)c[i].depth);
    fprintf(f, "%s\n", n > shown ? "; ..." : "");
}

static void print_record(FILE *f, const dCollisionShadowRecord *r)
{
    fprintf(f, "  %s-%s, first disagreement:", class_name(r->class1), class_name(r->class2));
    for (int k = 0; k < dCOLLISION_SHADOW_KINDS; k++)
        if (r->kinds & (1 << k)) fprintf(f, " %s", kind_names[k]);
    fprintf(f, " (depth error %.6g, normal %.3g deg, point %.6g; max contacts %d)\n",
            r->depth_error, r->normal_error, r->point_error, r->flags & 0xffff);
    print_geom(f, "g1", r->class1, r->params1, r->pos1, r->R1);
    print_geom(f, "g2", r->class2, r->params2, r->pos2, r->R2);
    print_result(f, "first ", r->first, r->n_first);
    print_result(f, "shadow", r->shadow, r->n_shadow);
}

void dxShadowPrint(FILE *f)
{
    const char *shadow = dCollisionGetShadowBackend();
    fprintf(f, "ODE collision shadow mode: \"%s\" answers, \"%s\" shadows (tolerances: depth 5 mm "
            "+ 5 %%, normal 10 deg, point 1 cm + 10 %% of its depth)\n", dCollisionGetBackend(),
            shadow ? shadow : "(off now)");
    dCollisionShadowStats stats[dGeomNumClasses * (dGeomNumClasses + 1) / 2];
    int n = dCollisionShadowGetStats(stats, (int)(sizeof stats / sizeof stats[0]));
    fprintf(f, "%-22s %9s %9s %9s %8s %8s %8s %8s %8s %11s %9s %11s %11s\n", "pair", "calls",
            "unanswd", "disagree", "contact", "depth", "normal", "point", "manifold",
            "worst-depth", "worst-deg", "pt-first", "pt-shadow");
    for (int i = 0; i < n; i++) {
        const dCollisionShadowStats *s = &stats[i];
        char pair[40];
        snprintf(pair, sizeof pair, "%s-%s", class_name(s->class1), class_name(s->class2));
        fprintf(f, "%-22s %9lu %9lu %9lu", pair, s->calls, s->not_answered, s->disagreements);
        for (int k = 0; k < dCOLLISION_SHADOW_KINDS; k++) fprintf(f, " %8lu", s->kinds[k]);
        fprintf(f, " %11.6f %9.3f %11.6f %11.6f\n", s->worst_depth, s->worst_normal,
                s->worst_point_first, s->worst_point_shadow);
    }
    if (n == 0) fprintf(f, "(no collisions reached a backend)\n");
    for (int i = 0; i < n; i++) {
        dCollisionShadowRecord r;
        if (dCollisionShadowGetRecords(stats[i].class1, stats[i].class2, &r, 1) > 0)
            print_record(f, &r);
    }
}
