// SPDX-License-Identifier: BSD-3-Clause
//
// pile.c -- the broad phase alone: a pile of boxes (a block of unit boxes whose bounding
// boxes touch their neighbours', 20 wide, 25 deep and 20 high for 10 000), of which 1 % move
// by up to 5 cm from their place each step (`moving=100`: every box); dSpaceCollide counts
// the pairs the space reports. For comparing spaces on scenes that mostly stand still:
// `space=hash`, `space=sap` (sweep and prune, axes x z y) or `space=quadtree`.
//
//   pile [boxes=10000] [steps=200] [space=hash|sap|quadtree] [moving=PERCENT]

#include "bench_common.h"

#include <ode/ode.h>

static void count_pair(void *data, dGeomID a, dGeomID b)
{
    (void)a;
    (void)b;
    (*(long *)data)++;
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int boxes = (int)bench_arg_int(&args, "boxes", 10000);
    const int steps = (int)bench_arg_int(&args, "steps", 200);
    const char *kind = bench_arg_str(&args, "space", "hash");
    const long percent = bench_arg_int(&args, "moving", 1);
    bench_args_check(&args, "[boxes=N] [steps=N] [space=hash|sap|quadtree] [moving=1..100]");

    dInitODE2(0);
    const int wide = 20, deep = 25;
    const int high = (boxes + wide * deep - 1) / (wide * deep);
    dSpaceID space;
    if (strcmp(kind, "sap") == 0) {
        space = dSweepAndPruneSpaceCreate(0, dSAP_AXES_XZY);
    } else if (strcmp(kind, "quadtree") == 0) {
        dVector3 c = { wide / 2.0, high / 2.0, deep / 2.0, 0 };
        dVector3 e = { wide / 2.0 + 1, high / 2.0 + 1, deep / 2.0 + 1, 0 };
        space = dQuadTreeSpaceCreate(0, c, e, 6);
    } else if (strcmp(kind, "hash") == 0) {
        space = dHashSpaceCreate(0);
    } else {
        fprintf(stderr, "pile: space must be hash, sap or quadtree, not '%s'\n", kind);
        return 2;
    }
    dGeomID *g = malloc(sizeof *g * (size_t)boxes);
    dReal (*home)[3] = malloc(sizeof *home * (size_t)boxes);
    for (int i = 0; i < boxes; i++) {
        g[i] = dCreateBox(space, 1, 1, 1);
        home[i][0] = i % wide + 0.5;
        home[i][1] = i / (wide * deep) + 0.5;   // y up: layers of wide x deep
        home[i][2] = (i / wide) % deep + 0.5;
        dGeomSetPosition(g[i], home[i][0], home[i][1], home[i][2]);
    }
    bench_rng rng = bench_rng_init(7);
    int moving = (int)(boxes * percent / 100);   // 100: every box, each once
    if (moving < 1) moving = 1;
    if (moving > boxes) moving = boxes;
    long pairs = 0;
    double coll = 0;
    for (int s = 0; s < steps; s++) {
        for (int k = 0; k < moving; k++) {
            int i = moving == boxes ? k : (int)bench_rand(&rng, 0, boxes);
            // One draw a statement (C leaves the order of a call's arguments open, and gcc
            // and clang differ): z, y, then x, the order gcc drew them in.
            const double dz = bench_rand(&rng, -0.05, 0.05);
            const double dy = bench_rand(&rng, -0.05, 0.05);
            const double dx = bench_rand(&rng, -0.05, 0.05);
            dGeomSetPosition(g[i], home[i][0] + dx, home[i][1] + dy, home[i][2] + dz);
        }
        bench_count_on();
        double t0 = bench_now();
        dSpaceCollide(space, &pairs, count_pair);
        coll += bench_now() - t0;
        bench_count_off();
    }
    bench_report("pile", BENCH_ENGINE, kind, boxes, steps, coll, 0,
                 "moving_pct=%ld pairs_per_step=%.1f", percent, (double)pairs / steps);
    dSpaceDestroy(space);
    free(g);
    free(home);
    dCloseODE();
    return 0;
}
