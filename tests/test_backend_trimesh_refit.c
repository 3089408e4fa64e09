// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_trimesh_refit.c -- the FCL and Bullet adapters refit their
// mesh model when dGeomTriMeshDataUpdate moved the vertices (issue 11), and
// rebuild it only when the triangles change.
//
// Under each backend that is built (the others skip): a terrain bump
// growing and a sheet lifted and curving, Update after each move, give the
// contacts of a freshly built data object with the moved vertices (the same
// points, normals, depths and triangles, as sets) and native's deepest
// contact (its depth within test_backend_trimesh.c's depth tolerance, its
// normal within 0.05 rad), both argument orders; the adapters' trace
// (ODE_BACKEND_TRACE_TRIMESH, set by meson) counts one build, then one refit
// per Update shared by two geoms on the data, nothing for an Update that
// moved nothing, a build when the triangles change, and the model kept for
// a geom freed with it; two threads colliding two geoms on one data right
// after each Update get the moved surface, with one refit per Update.

#include "collide_check.h"
#include "test.h"
#include "test_trimesh_meshes.h"

#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAXC = 64, ROUNDS = 6, PROBES = 9 };

#define RADIUS 0.3
#define SINK 0.06   // how deep each probe's lowest point is put under the surface

// ---- the adapters' trace, counted -------------------------------------------------

static atomic_int built, refit, other_reports;

static void count_report(int num, const char *msg, va_list ap)
{
    (void)num;
    char text[256];
    vsnprintf(text, sizeof text, msg, ap);
    if (strstr(text, "trimesh model built")) atomic_fetch_add(&built, 1);
    else if (strstr(text, "trimesh model refit")) atomic_fetch_add(&refit, 1);
    else atomic_fetch_add(&other_reports, 1);
}

static void start_counting(void)
{
    atomic_store(&built, 0);
    atomic_store(&refit, 0);
    atomic_store(&other_reports, 0);
    dSetMessageHandler(count_report);
}

static void stop_counting(void) { dSetMessageHandler(0); }

static int tracing(void) { return getenv("ODE_BACKEND_TRACE_TRIMESH") != NULL; }

// ---- the moving surfaces ------------------------------------------------------------

// Height of the surface in the mesh frame at round r: a bump growing, or a
// sheet lifted and curving (as cloth held at its middle).
static double surface(int kind, int r, double x, double y)
{
    if (kind == 0) return 0.12 * r * exp(-(x * x + y * y) / 0.8);
    return 0.05 * r * (1 - 0.15 * (x * x + y * y));
}

static void move_vertices(test_mesh *m, int kind, int r)
{
    for (int i = 0; i < m->nv; i++) m->v[i][2] = surface(kind, r, m->v[i][0], m->v[i][1]);
}

// Both meshes where the other trimesh tests put theirs: off the origin and
// turned, so that the adapters' transforms are exercised.
static void pose_mesh(dGeomID g)
{
    dGeomSetPosition(g, 0.3, -0.2, 0.1);
    set_rot(g, 0.2, -0.3, 1, (dReal)0.35);
}

// Probe p of a 3 x 3 grid, its lowest point SINK under the surface of
// round r (below its centre). (FCL 0.7 misses the triangles under a sphere
// whose centre lies right above their shared edge, refit or not.)
static void pose_probe(dGeomID sphere, dGeomID mesh, int kind, int r, int p)
{
    static const double xs[3] = { -1.1, 0.08, 1.2 }, ys[3] = { -1.05, 0.12, 1.15 };
    const double x = xs[p % 3], y = ys[p / 3];   // over no edge of the grid's triangles
    dVector3 w;
    dGeomGetRelPointPos(mesh, (dReal)x, (dReal)y,
                        (dReal)(surface(kind, r, x, y) + RADIUS - SINK), w);
    dGeomSetPosition(sphere, w[0], w[1], w[2]);
}

// A data object of its own with m's triangles and a copy of its vertices as
// they are now, and a geom on it posed as the meshes: a fresh build.
typedef struct fresh_mesh {
    double (*v)[3];
    dTriMeshDataID data;
    dGeomID geom;
} fresh_mesh;

static void fresh_make(fresh_mesh *f, const test_mesh *m)
{
    f->v = malloc(sizeof *f->v * (size_t)m->nv);
    memcpy(f->v, m->v, sizeof *f->v * (size_t)m->nv);
    f->data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(f->data, f->v, 3 * sizeof(double), m->nv, m->tri, 3 * m->nt,
                                3 * sizeof(dTriIndex));
    f->geom = dCreateTriMesh(0, f->data, NULL, NULL, NULL);
    pose_mesh(f->geom);
}

static void fresh_free(fresh_mesh *f)
{
    dGeomDestroy(f->geom);
    dGeomTriMeshDataDestroy(f->data);
    free(f->v);
}

// Whether triangles s and t of m are the same or share a vertex (-1: no
// triangle on either).
static int same_or_adjacent(const test_mesh *m, int s, int t)
{
    if (s == t) return 1;
    if (s < 0 || t < 0) return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (m->tri[s][i] == m->tri[t][j]) return 1;
    return 0;
}

// Whether a and b hold the same contacts in any order: for each of a, one of
// b with pos, normal and depth within tol, on the same triangle or, where
// two triangles give the same contact at their shared edge or corner, its
// neighbour (which one is kept follows the engine's tree).
static int same_contact_sets(const test_mesh *m, const dContactGeom *a, int na,
                             const dContactGeom *b, int nb, double tol)
{
    if (na != nb) return 0;
    int used[MAXC] = { 0 };
    for (int i = 0; i < na; i++) {
        int found = 0;
        for (int j = 0; j < nb && !found; j++) {
            if (used[j] || !same_or_adjacent(m, a[i].side1, b[j].side1) ||
                !same_or_adjacent(m, a[i].side2, b[j].side2))
                continue;
            double err = fabs((double)(a[i].depth - b[j].depth));
            for (int k = 0; k < 3; k++) {
                err = fmax(err, fabs((double)(a[i].pos[k] - b[j].pos[k])));
                err = fmax(err, fabs((double)(a[i].normal[k] - b[j].normal[k])));
            }
            if (err <= tol) found = used[j] = 1;
        }
        if (!found) return 0;
    }
    return 1;
}

// ---- the refit gives a fresh build's contacts and native's ----------------------

static int check_matches_fresh(const char *backend, int kind)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    test_mesh m;
    mesh_grid(&m, 12, 2, NULL);
    dGeomID mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    pose_mesh(mesh);
    dGeomID sphere = dCreateSphere(0, (dReal)RADIUS);
    const double tol = TOL(1e-9, 1e-5);
    start_counting();
    for (int r = 0; r <= ROUNDS; r++) {
        move_vertices(&m, kind, r);
        dGeomTriMeshDataUpdate(m.data);
        fresh_mesh f;
        fresh_make(&f, &m);
        for (int p = 0; p < PROBES; p++) {
            pose_probe(sphere, mesh, kind, r, p);
            for (int order = 0; order < 2; order++) {
                dGeomID o1 = order ? sphere : mesh, o2 = order ? mesh : sphere;
                dGeomID f1 = order ? sphere : f.geom, f2 = order ? f.geom : sphere;
                dContactGeom c[MAXC], cf[MAXC], cn[MAXC];
                dCollisionSetBackend(backend);
                const int n = dCollide(o1, o2, MAXC, c, sizeof c[0]);
                const int nf = dCollide(f1, f2, MAXC, cf, sizeof cf[0]);
                dCollisionSetBackend("native");
                const int nn = dCollide(o1, o2, MAXC, cn, sizeof cn[0]);
                CHECK(n >= 1 && nn >= 1);
                // The fresh geom's contacts name it: compare everything else.
                CHECK(same_contact_sets(&m, c, n, cf, nf, tol));
                const dContactGeom *d = &c[deepest(c, n)], *dn = &cn[deepest(cn, nn)];
                CHECK_NEAR(d->depth, dn->depth, 0.005 + 0.05 * dn->depth);
                const double cosine = d->normal[0] * dn->normal[0] +
                                      d->normal[1] * dn->normal[1] + d->normal[2] * dn->normal[2];
                CHECK(cosine > cos(0.05));
            }
        }
        fresh_free(&f);
    }
    // One build of the mesh's model, one refit per moving Update, one
    // build per fresh data object.
    if (tracing()) {
        CHECK(atomic_load(&refit) == ROUNDS);
        CHECK(atomic_load(&built) == 1 + (ROUNDS + 1));
    }
    stop_counting();
    dGeomDestroy(sphere);
    dGeomDestroy(mesh);
    mesh_free(&m);
    return 0;
}

static int test_fcl_bump_growing(void) { return check_matches_fresh("fcl", 0); }
static int test_fcl_sheet_lifted(void) { return check_matches_fresh("fcl", 1); }
static int test_bullet_bump_growing(void) { return check_matches_fresh("bullet", 0); }
static int test_bullet_sheet_lifted(void) { return check_matches_fresh("bullet", 1); }

// ---- refit, not rebuilt: the trace counted ---------------------------------------

// Collides each geom with a sphere resting SINK into the flat grid lifted
// to height h (mesh frame = world): depth SINK on each.
static int probe_flat(dGeomID g, dGeomID sphere, double h)
{
    dContactGeom c[MAXC];
    dGeomSetPosition(sphere, 0.1, -0.7, (dReal)(h + RADIUS - SINK));   // over the first half
    const int n = dCollide(g, sphere, MAXC, c, sizeof c[0]);
    return n >= 1 && fabs(c[deepest(c, n)].depth - SINK) <= TOL(1e-9, 1e-5);
}

static void lift(test_mesh *m, double h)
{
    for (int i = 0; i < m->nv; i++) m->v[i][2] = h;
}

static int check_counts(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    if (!tracing()) return test_skip("ODE_BACKEND_TRACE_TRIMESH not set");
    test_mesh m;
    mesh_grid(&m, 8, 2, NULL);
    dGeomID g1 = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID g2 = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    dGeomID sphere = dCreateSphere(0, (dReal)RADIUS);
    dCollisionSetBackend(backend);
    start_counting();
    // The first collisions build one model for both geoms.
    CHECK(probe_flat(g1, sphere, 0) && probe_flat(g2, sphere, 0));
    CHECK(atomic_load(&built) == 1 && atomic_load(&refit) == 0);
    // Each Update that moved the vertices: one refit, whichever geom
    // collides first, none rebuilt.
    for (int r = 1; r <= 5; r++) {
        lift(&m, 0.1 * r);
        dGeomTriMeshDataUpdate(m.data);
        CHECK(probe_flat(r % 2 ? g1 : g2, sphere, 0.1 * r));
        CHECK(probe_flat(r % 2 ? g2 : g1, sphere, 0.1 * r));
    }
    CHECK(atomic_load(&built) == 1 && atomic_load(&refit) == 5);
    // An Update that moved nothing: neither.
    dGeomTriMeshDataUpdate(m.data);
    CHECK(probe_flat(g1, sphere, 0.5) && probe_flat(g2, sphere, 0.5));
    CHECK(atomic_load(&built) == 1 && atomic_load(&refit) == 5);
    // A build with other triangles (the first half only): a new model.
    dGeomTriMeshDataBuildDouble(m.data, m.v, 3 * sizeof(double), m.nv, m.tri, 3 * (m.nt / 2),
                                3 * sizeof(dTriIndex));
    CHECK(probe_flat(g1, sphere, 0.5) && probe_flat(g2, sphere, 0.5));
    CHECK(atomic_load(&built) == 2 && atomic_load(&refit) == 5);
    // A build with the same triangles and moved vertices is refit.
    lift(&m, 0.6);
    dGeomTriMeshDataBuildDouble(m.data, m.v, 3 * sizeof(double), m.nv, m.tri, 3 * (m.nt / 2),
                                3 * sizeof(dTriIndex));
    CHECK(probe_flat(g1, sphere, 0.6) && probe_flat(g2, sphere, 0.6));
    CHECK(atomic_load(&built) == 2 && atomic_load(&refit) == 6);
    // g2 destroyed after an Update: g1's model is still refit.
    lift(&m, 0.7);
    dGeomTriMeshDataUpdate(m.data);
    dGeomDestroy(g2);
    CHECK(probe_flat(g1, sphere, 0.7));
    CHECK(atomic_load(&built) == 2 && atomic_load(&refit) == 7);
    // g1 destroyed after an Update without colliding: the model it kept goes
    // with it, and a new geom on the data builds one.
    lift(&m, 0.8);
    dGeomTriMeshDataUpdate(m.data);
    dGeomDestroy(g1);
    dGeomID g3 = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
    CHECK(probe_flat(g3, sphere, 0.8));
    CHECK(atomic_load(&built) == 3 && atomic_load(&refit) == 7);
    // g3 moved to other data and back: the first data's model went with it.
    test_mesh other;
    mesh_grid(&other, 4, 2, NULL);
    dGeomTriMeshSetData(g3, other.data);
    CHECK(probe_flat(g3, sphere, 0));
    dGeomTriMeshSetData(g3, m.data);
    CHECK(probe_flat(g3, sphere, 0.8));
    CHECK(atomic_load(&built) == 5 && atomic_load(&refit) == 7);
    CHECK(atomic_load(&other_reports) == 0);
    stop_counting();
    dCollisionSetBackend("native");
    dGeomDestroy(g3);
    dGeomDestroy(sphere);
    mesh_free(&other);
    mesh_free(&m);
    return 0;
}

static int test_fcl_refit_not_rebuilt(void) { return check_counts("fcl"); }
static int test_bullet_refit_not_rebuilt(void) { return check_counts("bullet"); }

// ---- two threads right after each Update ----------------------------------------

typedef struct worker {
    dGeomID mesh, sphere;
    double h;
    int ok;
} worker;

static void *collide_lifted(void *arg)
{
    worker *w = (worker *)arg;
    dAllocateODEDataForThread(dAllocateMaskAll);
    w->ok = probe_flat(w->mesh, w->sphere, w->h);
    dCleanupODEAllDataForThread();
    return NULL;
}

static int check_threads(const char *backend)
{
    if (!backend_built(backend)) return test_skip("backend not built");
    dInitODE2(0);
    test_mesh m;
    mesh_grid(&m, 16, 2, NULL);
    worker w[2];
    for (int i = 0; i < 2; i++) {
        w[i].mesh = dCreateTriMesh(0, m.data, NULL, NULL, NULL);
        w[i].sphere = dCreateSphere(0, (dReal)RADIUS);
    }
    dCollisionSetBackend(backend);
    start_counting();
    for (int r = 0; r < 20; r++) {
        lift(&m, 0.05 * r);
        dGeomTriMeshDataUpdate(m.data);
        pthread_t t[2];
        for (int i = 0; i < 2; i++) {
            w[i].h = 0.05 * r;
            w[i].ok = 0;
            CHECK(pthread_create(&t[i], NULL, collide_lifted, &w[i]) == 0);
        }
        for (int i = 0; i < 2; i++) pthread_join(t[i], NULL);
        CHECK(w[0].ok && w[1].ok);
    }
    if (tracing()) CHECK(atomic_load(&built) == 1 && atomic_load(&refit) == 19);
    stop_counting();
    dCollisionSetBackend("native");
    for (int i = 0; i < 2; i++) {
        dGeomDestroy(w[i].mesh);
        dGeomDestroy(w[i].sphere);
    }
    mesh_free(&m);
    dCloseODE();
    return 0;
}

static int test_fcl_threads(void) { return check_threads("fcl"); }
static int test_bullet_threads(void) { return check_threads("bullet"); }

const test_case test_cases[] = {
    TEST_CASE(test_fcl_bump_growing),
    TEST_CASE(test_fcl_sheet_lifted),
    TEST_CASE(test_bullet_bump_growing),
    TEST_CASE(test_bullet_sheet_lifted),
    TEST_CASE(test_fcl_refit_not_rebuilt),
    TEST_CASE(test_bullet_refit_not_rebuilt),
    TEST_CASE(test_fcl_threads),
    TEST_CASE(test_bullet_threads),
    TEST_END
};
