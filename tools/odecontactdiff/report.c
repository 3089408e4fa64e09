// SPDX-License-Identifier: BSD-3-Clause
//
// report.c -- odecontactdiff's output: the table, its CSV form, and an SVG
// scatter plot of depth error against true depth, one colour per backend.

#include "odecontactdiff.h"

#include <math.h>
#include <string.h>

static const char *verdict(const cd_row *r)
{
    if (strcmp(r->backend, "truth") == 0) return "truth";
    if (r->answered == 0) return "-";
    return cd_row_passes(r) ? "pass" : "FAIL";
}

void cd_print_table(FILE *f, const cd_results *res)
{
    fprintf(f, "%-8s %-18s %6s %6s %6s %7s %6s %6s %6s %10s %10s %9s %10s  %s\n", "backend",
            "pair", "poses", "overl", "answd", "contact", "depth", "sep", "point", "worst-dep",
            "worst-sep", "worst-deg", "worst-pt", "contract");
    for (int i = 0; i < res->count; i++) {
        const cd_row *r = &res->rows[i];
        fprintf(f, "%-8s %-18s %6d %6d %6d %7d %6d %6d %6d %10.6f %10.6f %9.3f %10.6f  %s\n",
                r->backend, r->pair, r->poses, r->overlapping, r->answered, r->contact_fail,
                r->depth_fail, r->sep_fail, r->point_fail, r->worst_depth, r->worst_sep,
                r->worst_normal, r->worst_point, verdict(r));
    }
}

void cd_print_csv(FILE *f, const cd_results *res)
{
    fprintf(f, "backend,pair,poses,overlapping,answered,contact_fail,depth_fail,separation_fail,"
            "point_fail,worst_depth_error,worst_separation,worst_normal_deg,worst_point_outside,"
            "contract\n");
    for (int i = 0; i < res->count; i++) {
        const cd_row *r = &res->rows[i];
        fprintf(f, "%s,%s,%d,%d,%d,%d,%d,%d,%d,%.9g,%.9g,%.6g,%.9g,%s\n", r->backend, r->pair,
                r->poses, r->overlapping, r->answered, r->contact_fail, r->depth_fail,
                r->sep_fail, r->point_fail, r->worst_depth, r->worst_sep, r->worst_normal,
                r->worst_point, verdict(r));
    }
}

// ---- SVG ----------------------------------------------------------------------

enum { W = 760, H = 500, LEFT = 80, RIGHT = 170, TOP = 40, BOTTOM = 60 };
static const char *const colours[] = { "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                       "#8c564b", "#e377c2", "#17becf" };

typedef struct frame {
    double x0, x1, y0, y1;
} frame;

// Plot coordinates of a data point.
static double px(const frame *fr, double x)
{
    return LEFT + (x - fr->x0) / (fr->x1 - fr->x0) * (W - LEFT - RIGHT);
}

static double py(const frame *fr, double y)
{
    return H - BOTTOM - (y - fr->y0) / (fr->y1 - fr->y0) * (H - TOP - BOTTOM);
}

// The backends (not the truth) in first-seen order; returns their count.
static int backend_names(const cd_results *res, const char *names[8])
{
    int n = 0;
    for (int i = 0; i < res->count; i++) {
        const char *b = res->rows[i].backend;
        if (strcmp(b, "truth") == 0) continue;
        int seen = 0;
        for (int k = 0; k < n; k++) seen |= strcmp(names[k], b) == 0;
        if (!seen && n < 8) names[n++] = b;
    }
    return n;
}

// The plotted ranges: every sample and the tolerance band, with a margin.
static frame plot_frame(const cd_results *res)
{
    frame fr = { 0, 0, 0, 0 };
    for (int i = 0; i < res->count; i++)
        for (int s = 0; s < res->rows[i].nsamples; s++) {
            double x = res->rows[i].samples[2 * s], y = res->rows[i].samples[2 * s + 1];
            if (x > fr.x1) fr.x1 = x;
            if (y < fr.y0) fr.y0 = y;
            if (y > fr.y1) fr.y1 = y;
        }
    if (fr.x1 <= 0) fr.x1 = 0.1;
    double tol = CD_DEPTH_ABS + CD_DEPTH_REL * fr.x1;
    if (fr.y1 < 1.5 * tol) fr.y1 = 1.5 * tol;
    if (fr.y0 > -1.5 * tol) fr.y0 = -1.5 * tol;
    fr.x1 *= 1.05;
    return fr;
}

static void axes(FILE *f, const frame *fr)
{
    fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
            "stroke=\"#444\"/>\n", LEFT, TOP, W - LEFT - RIGHT, H - TOP - BOTTOM);
    for (int i = 0; i <= 5; i++) {
        double x = fr->x0 + (fr->x1 - fr->x0) * i / 5, y = fr->y0 + (fr->y1 - fr->y0) * i / 5;
        fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#444\"/>"
                "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%.3g</text>\n", px(fr, x),
                H - BOTTOM, px(fr, x), H - BOTTOM + 5, px(fr, x), H - BOTTOM + 20, x);
        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#444\"/>"
                "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.3g</text>\n", LEFT - 5,
                py(fr, y), LEFT, py(fr, y), LEFT - 8, py(fr, y) + 4, y);
    }
    fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#999\"/>\n", LEFT,
            py(fr, 0), W - RIGHT, py(fr, 0));
    // The contract's band: |error| <= 5 mm + 5 % of the true depth.
    for (int sign = -1; sign <= 1; sign += 2)
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#999\" "
                "stroke-dasharray=\"6,4\"/>\n", px(fr, 0), py(fr, sign * CD_DEPTH_ABS),
                px(fr, fr->x1), py(fr, sign * (CD_DEPTH_ABS + CD_DEPTH_REL * fr->x1)));
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">true penetration depth</text>\n",
            (LEFT + W - RIGHT) / 2, H - 15);
    fprintf(f, "<text transform=\"translate(20,%d) rotate(-90)\" text-anchor=\"middle\">depth "
            "error (backend - truth)</text>\n", (TOP + H - BOTTOM) / 2);
}

int cd_write_svg(const char *path, const cd_results *res)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    frame fr = plot_frame(res);
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "font-family=\"sans-serif\" font-size=\"12\">\n"
            "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
            "<text x=\"%d\" y=\"24\" font-size=\"15\">Deepest depth error against the true "
            "depth (dashed: the contract's tolerance)</text>\n", W, H, LEFT);
    axes(f, &fr);
    const char *names[8];
    int nb = backend_names(res, names);
    for (int b = 0; b < nb; b++) {
        const char *colour = colours[b];
        fprintf(f, "<g fill=\"%s\" fill-opacity=\"0.6\">\n", colour);
        for (int i = 0; i < res->count; i++) {
            const cd_row *r = &res->rows[i];
            if (strcmp(r->backend, names[b]) != 0) continue;
            for (int s = 0; s < r->nsamples; s++)
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.5\"/>\n",
                        px(&fr, r->samples[2 * s]), py(&fr, r->samples[2 * s + 1]));
        }
        fprintf(f, "</g>\n<circle cx=\"%d\" cy=\"%d\" r=\"5\" fill=\"%s\"/><text x=\"%d\" "
                "y=\"%d\">%s</text>\n", W - RIGHT + 20, TOP + 15 + 20 * b, colour, W - RIGHT + 32,
                TOP + 19 + 20 * b, names[b]);
    }
    fprintf(f, "</svg>\n");
    return fclose(f) == 0;
}
