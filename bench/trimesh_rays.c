// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_rays.c -- bench scene: rays cast onto a large triangle-mesh terrain.
//
// `trimesh_rays rays=10000 cells=224 rounds=10`: a 224 x 224-cell terrain (100 352
// triangles) over 40 m x 40 m, height 0.5 sin(0.6 x) cos(0.5 y) m; 10 000 rays of 10 m
// from random points 3 m above it (fixed seed), in random downward directions, each
// collided (dCollide, closest hit) `rounds` times. "steps" in the report are the rounds;
// coll_s is the rays' time (ms_per_step: a round of rays), build_ms the time it took to build
// the mesh data (once, before the rays); instructions (bench/run --instructions) are counted
// over the rays only, as coll_s. Quality: how many rays hit, and the mean distance to the hit.
//
// `measure=build builds=N`: no rays; the mesh data and its geom are built N times (created,
// built, the geom's box asked for, destroyed), and "steps" are the builds: step_s their time,
// ms_per_step one build's, instructions counted over the builds.

#include "bench_ode.h"

#define HALF 20.0

static double terrain_height(double x, double y)
{
    return 0.5 * sin(0.6 * x) * cos(0.5 * y);
}

// Build the terrain's mesh data and geom (the tree is built by the time the geom's box is
// known, in both engines); the build's time (s) into *build_s.
static dGeomID build_terrain(int cells, double (*v)[3], dTriIndex (*tri)[3],
                             dTriMeshDataID *data, double *build_s)
{
    double t0 = bench_now();
    dGeomID mesh = bench_terrain_geom(0, cells, v, tri, 0, data);
    dReal aabb[6];
    dGeomGetAABB(mesh, aabb);
    *build_s = bench_now() - t0;
    return mesh;
}

// measure=build: the terrain built `builds` times.
static int measure_builds(int cells, int builds, double (*v)[3], dTriIndex (*tri)[3])
{
    double total_s = 0;
    for (int k = 0; k < builds; k++) {
        dTriMeshDataID data;
        double build_s;
        bench_count_on();
        dGeomID mesh = build_terrain(cells, v, tri, &data, &build_s);
        bench_count_off();
        total_s += build_s;
        dGeomDestroy(mesh);
        dGeomTriMeshDataDestroy(data);
    }
    bench_report("trimesh_rays", BENCH_ENGINE, "build", cells, builds, 0.0, total_s,
                 "triangles=%d", 2 * cells * cells);
    return 0;
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int rays = (int)bench_arg_int(&args, "rays", 10000);
    const int cells = (int)bench_arg_int(&args, "cells", 224);
    const int rounds = (int)bench_arg_int(&args, "rounds", 10);
    const int builds = (int)bench_arg_int(&args, "builds", 1);
    const char *measure = bench_arg_str(&args, "measure", "rays");
    bench_args_check(&args, "[rays=N] [cells=N] [rounds=N] [measure=rays|build] [builds=N]");
    const int build_only = strcmp(measure, "build") == 0;
    if (!build_only && strcmp(measure, "rays") != 0) {
        fprintf(stderr, "measure must be rays or build\n");
        return 2;
    }

    dInitODE2(0);
    const int nt = 2 * cells * cells;
    double(*v)[3] = NULL;
    dTriIndex(*tri)[3] = NULL;
    const int terrain_ok = bench_grid_terrain(cells, HALF, terrain_height, &v, &tri);
    double(*ray)[6] = (double(*)[6])malloc(sizeof *ray * (size_t)rays);
    if (!terrain_ok || !ray) return 1;
    if (build_only) {
        int status = measure_builds(cells, builds, v, tri);
        dCloseODE();
        free(v);
        free(tri);
        free(ray);
        return status;
    }
    dTriMeshDataID data;
    double build_s;
    dGeomID mesh = build_terrain(cells, v, tri, &data, &build_s);

    bench_rng rng = bench_rng_init(13);
    for (int i = 0; i < rays; i++) {
        double *r = ray[i];
        r[0] = bench_rand(&rng, -HALF + 2, HALF - 2);
        r[1] = bench_rand(&rng, -HALF + 2, HALF - 2);
        r[2] = 3;
        r[3] = bench_rand(&rng, -0.5, 0.5);
        r[4] = bench_rand(&rng, -0.5, 0.5);
        r[5] = -1;
    }
    dGeomID g = dCreateRay(0, 10);
    dGeomRaySetClosestHit(g, 1);
    long hits = 0;
    double dist = 0, ray_s = 0;
    for (int k = 0; k < rounds; k++) {
        bench_count_on();
        double t1 = bench_now();
        for (int i = 0; i < rays; i++) {
            const double *r = ray[i];
            dGeomRaySet(g, (dReal)r[0], (dReal)r[1], (dReal)r[2], (dReal)r[3], (dReal)r[4],
                        (dReal)r[5]);
            dContactGeom c;
            if (dCollide(g, mesh, 1, &c, sizeof c) && k == 0) {
                hits++;
                dist += c.depth;
            }
        }
        ray_s += bench_now() - t1;
        bench_count_off();
    }
    bench_report("trimesh_rays", BENCH_ENGINE, "closest", rays, rounds, ray_s, 0.0,
                 "triangles=%d hits=%ld mean_dist=%.6f us_per_ray=%.3f build_ms=%.3f", nt, hits,
                 hits ? dist / hits : 0.0, 1e6 * ray_s / ((double)rays * rounds),
                 1000 * build_s);

    dGeomDestroy(g);
    dGeomDestroy(mesh);
    dGeomTriMeshDataDestroy(data);
    dCloseODE();
    free(v);
    free(tri);
    free(ray);
    return 0;
}
