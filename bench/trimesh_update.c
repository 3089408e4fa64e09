// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_update.c -- bench scene: a deforming terrain, its vertices moved and
// dGeomTriMeshDataUpdate called every round, then probed by spheres.
//
// `trimesh_update cells=100 updates=100 spheres=64`: a 100 x 100-cell terrain (20 000
// triangles) over 20 m x 20 m whose height 0.5 sin(0.6 x + 0.05 r) cos(0.5 y) m moves with
// the round r; each round rewrites every vertex's height in place, calls Update, and collides
// an 8 x 8 grid of spheres (radius 0.3 m, each 5 cm into the surface at its centre) with the
// terrain through dCollide, 8 contacts asked. Only what a deforming mesh costs is timed and
// counted (bench_count_on/off): the vertex writes, Update and the collisions, where a
// backend brings its model up to date (the FCL and Bullet adapters refit theirs there).
// The backend is ODE_COLLISION_BACKEND's (this project; the reference refits OPCODE's tree
// in Update). Figures: contacts per round and the deepest depth (the same under a refit and
// a rebuild).

#include "bench_ode.h"

#define HALF 10.0
#define RADIUS 0.3
#define SINK 0.05

static double height_at(double x, double y, int round)
{
    return 0.5 * sin(0.6 * x + 0.05 * round) * cos(0.5 * y);
}

static double flat(double x, double y)
{
    (void)x, (void)y;
    return 0;
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int cells = (int)bench_arg_int(&args, "cells", 100);
    const int updates = (int)bench_arg_int(&args, "updates", 100);
    const int spheres = (int)bench_arg_int(&args, "spheres", 64);
    const int side = (int)ceil(sqrt((double)spheres));
    bench_args_check(&args, "[cells=N] [updates=N] [spheres=N (a square grid)]");

    dInitODE2(0);
    double(*v)[3] = NULL;
    dTriIndex(*tri)[3] = NULL;
    if (!bench_grid_terrain(cells, HALF, flat, &v, &tri)) return 1;
    const int nv = (cells + 1) * (cells + 1), nt = 2 * cells * cells;
    dTriMeshDataID data;
    dGeomID terrain = bench_terrain_geom(0, cells, v, tri, 0, &data);
    const int count = side * side;
    dGeomID *sphere = (dGeomID *)malloc(sizeof(dGeomID) * (size_t)count);
    if (!sphere) return 1;
    for (int i = 0; i < count; i++) sphere[i] = dCreateSphere(0, (dReal)RADIUS);

    dContactGeom c[8];
    long contacts = 0;
    double deepest = 0, secs = 0;
    for (int r = 0; r < updates; r++) {
        const double t0 = bench_now();
        bench_count_on();
        for (int i = 0; i < nv; i++) v[i][2] = height_at(v[i][0], v[i][1], r);
        dGeomTriMeshDataUpdate(data);
        for (int i = 0; i < count; i++) {
            const double x = -0.8 * HALF + 1.6 * HALF * (i % side + 0.5) / side;
            const double y = -0.8 * HALF + 1.6 * HALF * (i / side + 0.5) / side;
            dGeomSetPosition(sphere[i], (dReal)x, (dReal)y,
                             (dReal)(height_at(x, y, r) + RADIUS - SINK));
            const int n = dCollide(terrain, sphere[i], 8, c, sizeof c[0]);
            contacts += n;
            for (int k = 0; k < n; k++)
                if (c[k].depth > deepest) deepest = c[k].depth;
        }
        bench_count_off();
        secs += bench_now() - t0;
    }
    bench_report("trimesh_update", BENCH_ENGINE, "update", count, updates, secs, 0,
                 "triangles=%d contacts_per_round=%.2f max_depth=%.6f", nt,
                 (double)contacts / updates, deepest);

    for (int i = 0; i < count; i++) dGeomDestroy(sphere[i]);
    dGeomDestroy(terrain);
    dGeomTriMeshDataDestroy(data);
    dCloseODE();
    free(sphere);
    free(v);
    free(tri);
    return 0;
}
