// SPDX-License-Identifier: BSD-3-Clause
//
// main.c -- odecontactdiff: every collision backend against the ground truth
// of contacts (tools/contact_truth.h) on given pairs, a scene file or random
// poses; a table, CSV or an SVG plot (see usage_text).

#include "odecontactdiff.h"

#include <math.h>
#include <ode/backend.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static const char usage_text[] =
"NAME\n"
"    odecontactdiff - hold every collision backend of ode-c11 to the contact contract\n"
"\n"
"SYNOPSIS\n"
"    odecontactdiff [--pair SHAPE SHAPE]... [--scene FILE] [--seed S] [--count N]\n"
"                   [--backends NAME,...] [--csv] [--plot FILE.svg]\n"
"\n"
"DESCRIPTION\n"
"    Collides pairs of geoms through every collision backend available (native,\n"
"    and fcl and bullet when their modules are installed), computes the ground\n"
"    truth of each pair from the shapes' support functions alone (the\n"
"    penetration depth is the least overlap of the two shapes over all\n"
"    directions), and prints, per backend and pair class: the poses, how many\n"
"    overlap, how many the backend answers itself (a pair it does not answer\n"
"    falls back to native in a program, and is not counted here), the number\n"
"    of poses failing each rule of the contract, the worst errors, and whether\n"
"    the backend passes. The 'truth' rows give the poses measured.\n"
"\n"
"    Without --pair or --scene, every pair of sphere, box, capsule, cylinder\n"
"    and plane (default sizes) is posed at random. Random poses closer to\n"
"    touching than 2 cm (or 5 % of the two bounding radii, if less) are drawn\n"
"    again: there a contact is a matter of tolerance. The output depends only\n"
"    on the arguments (and the backends built).\n"
"\n"
"THE CONTRACT\n"
"    For every pair a backend answers, with dCollide's convention (the normal\n"
"    points into g1; depth >= 0):\n"
"    contact   it reports a contact exactly when the shapes overlap (a pose\n"
"              within the depth tolerance of touching may go either way);\n"
"    depth     the deepest contact's depth is within 5 mm + 5 % of the true\n"
"              penetration depth;\n"
"    sep       moving g1 along that contact's normal by its depth parts the\n"
"              shapes, to the same tolerance (the overlap left is measured);\n"
"    point     every contact point lies within both shapes, to 1 cm + 10 % of\n"
"              its depth.\n"
"    The angle between the deepest normal and the true one is shown (worst-deg)\n"
"    but not judged: on symmetric poses the true normal is not unique.\n"
"    The contract's manifold rule (a face resting on a face gives several\n"
"    points) is not judged here, where poses do not rest; shadow mode\n"
"    (ODE_COLLISION_BACKEND=native,fcl) counts it in a running program and uses\n"
"    the same tolerances.\n"
"\n"
"OPTIONS\n"
"    --pair SHAPE SHAPE\n"
"           A pair to pose at random (repeatable). SHAPE is CLASS or\n"
"           CLASS:SIZES, sizes separated by commas: sphere:R, box:LX,LY,LZ,\n"
"           capsule:R,LENGTH, cylinder:R,LENGTH (lengths along local z, a\n"
"           capsule's without its caps), plane:A,B,C,D (the solid half-space\n"
"           A x + B y + C z <= D). Defaults: sphere:0.5, box:1,0.6,0.4,\n"
"           capsule:0.3,0.8, cylinder:0.4,0.8, plane:0,0,1,0.\n"
"    --scene FILE\n"
"           Measure every pair of the geoms of FILE as they are posed.\n"
"    --seed S\n"
"           Seed of the random poses (default 1).\n"
"    --count N\n"
"           Random poses per pair (default 200).\n"
"    --backends NAME,...\n"
"           Only these backends (default: every one available).\n"
"    --csv  Print CSV instead of the table: backend, pair, poses, overlapping,\n"
"           answered, contact_fail, depth_fail, separation_fail, point_fail,\n"
"           worst_depth_error, worst_separation, worst_normal_deg,\n"
"           worst_point_outside, contract (pass, FAIL, '-' if nothing answered,\n"
"           truth).\n"
"    --plot FILE.svg\n"
"           Also write an SVG scatter plot of each backend's depth error\n"
"           against the true depth, with the contract's tolerance dashed.\n"
"    --help Print this text.\n"
"\n"
"SCENE FILES\n"
"    One geom per line: CLASS, its sizes (as above, separated by spaces), then\n"
"    for all but a plane the position X Y Z and optionally the rotation as a\n"
"    quaternion W X Y Z (default: none). '#' starts a comment. Example:\n"
"        plane 0 0 1 0\n"
"        box 1 1 1      0 0 0.49\n"
"        sphere 0.5     0.2 0 1.2    0.924 0.383 0 0\n"
"\n"
"EXIT STATUS\n"
"    0 if every backend passes on every pair it answers, 1 if one fails,\n"
"    2 on a usage error.\n";

static void fail_usage(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "odecontactdiff: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n(odecontactdiff --help explains the options)\n");
    va_end(ap);
    exit(2);
}

// ODE's errors (a backend module that cannot load, ...) end the run.
static void ode_error(int num, const char *msg, va_list ap)
{
    (void)num;
    fprintf(stderr, "odecontactdiff: ");
    vfprintf(stderr, msg, ap);
    fprintf(stderr, "\n");
    exit(2);
}

typedef struct options {
    cd_shape pairs[64][2];
    int npairs;
    const char *scene, *plot, *backends;
    unsigned long seed;
    long count;
    int csv;
} options;

static void parse_options(int argc, char **argv, options *o)
{
    char err[256];
    memset(o, 0, sizeof *o);
    o->seed = 1;
    o->count = 200;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage_text, stdout);
            exit(0);
        } else if (strcmp(a, "--pair") == 0) {
            if (i + 2 >= argc) fail_usage("--pair takes two shapes");
            if (o->npairs == 64) fail_usage("at most 64 pairs");
            for (int k = 0; k < 2; k++)
                if (!cd_parse_shape(argv[i + 1 + k], &o->pairs[o->npairs][k], err, sizeof err))
                    fail_usage("--pair: %s", err);
            if (o->pairs[o->npairs][0].cls == dPlaneClass &&
                o->pairs[o->npairs][1].cls == dPlaneClass)
                fail_usage("--pair: two planes are not a pair");
            o->npairs++;
            i += 2;
        } else if (strcmp(a, "--scene") == 0 && more) {
            o->scene = argv[++i];
        } else if (strcmp(a, "--plot") == 0 && more) {
            o->plot = argv[++i];
        } else if (strcmp(a, "--backends") == 0 && more) {
            o->backends = argv[++i];
        } else if (strcmp(a, "--seed") == 0 && more) {
            char *end;
            o->seed = strtoul(argv[++i], &end, 10);
            if (*end || end == argv[i]) fail_usage("--seed takes a whole number");
        } else if (strcmp(a, "--count") == 0 && more) {
            char *end;
            o->count = strtol(argv[++i], &end, 10);
            if (*end || end == argv[i] || o->count < 1 || o->count > 1000000)
                fail_usage("--count takes a number from 1 to 1000000");
        } else if (strcmp(a, "--csv") == 0) {
            o->csv = 1;
        } else {
            fail_usage("unknown option or missing value: %s", a);
        }
    }
}

// The backends to measure: --backends (each checked) or every one.
static const char **choose_backends(const char *list)
{
    static const char *chosen[16];
    static char copy[256];
    const char *const *all = dCollisionListBackends();
    int n = 0;
    if (!list) {
        for (; all[n] && n < 15; n++) chosen[n] = all[n];
        return chosen;
    }
    snprintf(copy, sizeof copy, "%s", list);
    for (char *name = strtok(copy, ","); name && n < 15; name = strtok(NULL, ",")) {
        int found = 0;
        for (int k = 0; all[k]; k++) found |= strcmp(all[k], name) == 0;
        if (!found) fail_usage("--backends: no backend \"%s\" here", name);
        chosen[n++] = name;
    }
    if (n == 0) fail_usage("--backends: no name given");
    return chosen;
}

// N random poses of the pair (a, b), each outside the grazing band.
static void measure_random(cd_results *res, const char **backends, const cd_shape *a,
                           const cd_shape *b, cd_rng *rng, long count)
{
    cd_geom ga = { *a, { 0, 0, 0 }, { 1, 0, 0, 0 } }, gb = { *b, { 0, 0, 0 }, { 1, 0, 0, 0 } };
    dGeomID g1 = cd_make_geom(&ga), g2 = cd_make_geom(&gb);
    double band = cd_grazing_band(a, b);
    long done = 0;
    for (long tries = 0; done < count && tries < 50 * count; tries++) {
        cd_random_pose(rng, g1, g2);
        contact_truth t;
        if (!contact_truth_compute(g1, g2, &t) || fabs(t.depth) < band) continue;
        cd_measure(res, backends, g1, g2, &t);
        done++;
    }
    dGeomDestroy(g1);
    dGeomDestroy(g2);
}

// Every pair of a scene's geoms, as posed.
static void measure_scene(cd_results *res, const char **backends, const char *path)
{
    char err[512];
    cd_geom *geoms;
    int n = cd_read_scene(path, &geoms, err, sizeof err);
    if (n < 0) fail_usage("--scene: %s", err);
    dGeomID *ids = malloc((size_t)(n > 0 ? n : 1) * sizeof *ids);
    if (!ids) fail_usage("out of memory");
    for (int i = 0; i < n; i++) ids[i] = cd_make_geom(&geoms[i]);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            contact_truth t;
            if (contact_truth_compute(ids[i], ids[j], &t))
                cd_measure(res, backends, ids[i], ids[j], &t);
        }
    for (int i = 0; i < n; i++) dGeomDestroy(ids[i]);
    free(ids);
    free(geoms);
}

int main(int argc, char **argv)
{
    options o;
    parse_options(argc, argv, &o);
    dInitODE2(0);
    dSetErrorHandler(ode_error);
    dSetDebugHandler(ode_error);
    const char **backends = choose_backends(o.backends);
    cd_results res = { 0, 0, NULL };
    cd_rng rng = { o.seed };
    if (o.scene) measure_scene(&res, backends, o.scene);
    for (int i = 0; i < o.npairs; i++)
        measure_random(&res, backends, &o.pairs[i][0], &o.pairs[i][1], &rng, o.count);
    if (!o.scene && o.npairs == 0) {
        static const char *const names[] = { "sphere", "box", "capsule", "cylinder", "plane" };
        char err[128];
        for (int i = 0; i < 5; i++)
            for (int j = i; j < 5; j++) {
                cd_shape a, b;
                if (j == 4 && i == 4) continue;
                cd_parse_shape(names[i], &a, err, sizeof err);
                cd_parse_shape(names[j], &b, err, sizeof err);
                measure_random(&res, backends, &a, &b, &rng, o.count);
            }
    }
    if (o.csv) cd_print_csv(stdout, &res);
    else {
        printf("odecontactdiff: ");
        if (o.scene) printf("scene %s%s", o.scene, o.npairs ? ", " : "");
        if (o.npairs || !o.scene) printf("seed %lu, %ld random poses per pair", o.seed, o.count);
        printf("; tolerances: depth and separation 5 mm + 5 %%, points 1 cm + 10 %%\n");
        cd_print_table(stdout, &res);
    }
    if (o.plot && !cd_write_svg(o.plot, &res)) fail_usage("--plot: cannot write %s", o.plot);
    int failed = 0;
    for (int i = 0; i < res.count; i++)
        if (strcmp(res.rows[i].backend, "truth") != 0 && res.rows[i].answered > 0 &&
            !cd_row_passes(&res.rows[i]))
            failed = 1;
    cd_free_results(&res);
    dCloseODE();
    return failed;
}
