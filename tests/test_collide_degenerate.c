// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_degenerate.c -- every class pair of the native colliders on
// sizes and offsets drawn from a few extreme values (0, 1e-30, 1e-6, 0.5, 1,
// 1e6): points, needles, sheets and giants against each other, posed square,
// a quarter turn or at random. Each dCollide must return (a pair still
// running after ALARM_SECONDS is reported by name and fails the run), with at
// most the contacts asked for, each with a finite position, a unit normal, a
// finite depth >= 0 and g1/g2 the pair in call order. Refused input (a
// non-positive size, a zero plane normal) is reported through the handlers
// and skipped.
//
// The fuzz targets draw such values one field at a time and rarely all at
// once; this draw found in seconds what 1.5 million fuzz units missed:
// libccd's MPR looping without end on a hull 1e-6 thick against a
// zero-radius cylinder 1e6 long (backends/native/mpr_bounded.h); a
// zero-radius capsule 1e6 long touching a flat hull's edge getting a contact
// 250 km out with a depth of -4e-12 (collide_convex.c); and, in single
// precision, spheres 1e-30 off a box or a cylinder whose offsets' squares
// underflow getting a negative depth or a NaN normal (collide_sphere.c).

#define _POSIX_C_SOURCE 200809L
#define RNG_SEED 0x2026112901ull
#include "convex_hulls.h"
#include "test.h"
#include "xorshift.h"

#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

enum { PAIRS = 20000, MAXC = 8, ALARM_SECONDS = 20 };
enum { BOX, CAPSULE, CYLINDER, SPHERE, CONVEX, RAY, PLANE, TRIMESH, HEIGHTFIELD, CLASSES };
static const char *const class_names[CLASSES] = { "box",  "capsule", "cylinder",
                                                  "sphere", "convex", "ray",
                                                  "plane", "trimesh", "heightfield" };

static char pair_text[512];   // the pair being collided, for the alarm

static void on_alarm(int sig)
{
    (void)sig;
    static const char head[] = "# a dCollide did not return: ";
    (void)!write(STDOUT_FILENO, head, sizeof head - 1);
    (void)!write(STDOUT_FILENO, pair_text, strlen(pair_text));
    (void)!write(STDOUT_FILENO, "\n", 1);
    _exit(1);
}

static void quiet(int num, const char *msg, va_list ap)
{
    (void)num;
    (void)msg;
    (void)ap;
}

// An extreme value: one of six magnitudes, negative one time in four.
static double extreme(void)
{
    static const double magnitudes[] = { 0, 1e-30, 1e-6, 0.5, 1, 1e6 };
    const double m = magnitudes[(int)rnd(0, 6)];
    return rnd(0, 1) < 0.25 ? -m : m;
}

// The data a geom reads from its user's arrays, kept while it lives.
typedef struct shape_data {
    test_hull hull;
    float vertices[12 * 3];
    dTriIndex indices[16 * 3];
    double heights[49];
    dTriMeshDataID mesh;
    dHeightfieldDataID field;
} shape_data;

// A geom of class k with sizes from h (absolute extremes); text: what it is.
static dGeomID make_geom(int k, shape_data *d, char *text, size_t room)
{
    double h[3];
    for (int i = 0; i < 3; i++) h[i] = fabs(extreme());
    snprintf(text, room, "%s %g %g %g", class_names[k], h[0], h[1], h[2]);
    switch (k) {
    case BOX: return dCreateBox(0, (dReal)h[0], (dReal)h[1], (dReal)h[2]);
    case CAPSULE: return dCreateCapsule(0, (dReal)h[0], (dReal)h[1]);
    case CYLINDER: return dCreateCylinder(0, (dReal)h[0], (dReal)h[1]);
    case SPHERE: return dCreateSphere(0, (dReal)h[0]);
    case CONVEX:
        test_hull_box(&d->hull, 2 * h[0], 2 * h[1], 2 * h[2]);
        return dCreateConvex(0, d->hull.planes, 6, d->hull.points, 8, d->hull.polygons);
    case RAY: {
        dGeomID r = dCreateRay(0, (dReal)h[0]);
        if (r) {
            dGeomRaySetFirstContact(r, rnd(0, 1) < 0.5);
            dGeomRaySetBackfaceCull(r, rnd(0, 1) < 0.5);
            dGeomRaySetClosestHit(r, rnd(0, 1) < 0.5);
        }
        return r;
    }
    case PLANE:
        return dCreatePlane(0, (dReal)(h[0] + (rnd(0, 1) < 0.5)), (dReal)h[1],
                            (dReal)(h[2] + (rnd(0, 1) < 0.3)), (dReal)extreme());
    case TRIMESH:
        // 12 points: extremes, or a size times a fraction; 16 triangles of them
        for (int i = 0; i < 36; i++)
            d->vertices[i] = (float)(rnd(0, 1) < 0.3 ? extreme() : h[i % 3] * rnd(-1, 1));
        for (int i = 0; i < 48; i++) d->indices[i] = (dTriIndex)rnd(0, 12);
        d->mesh = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildSingle(d->mesh, d->vertices, 3 * sizeof(float), 12, d->indices, 48,
                                    3 * sizeof(dTriIndex));
        if (rnd(0, 1) < 0.5)
            dGeomTriMeshDataPreprocess2(d->mesh, 1u << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, NULL);
        return dCreateTriMesh(0, d->mesh, NULL, NULL, NULL);
    default:
        // 7 x 7 samples over at least 1 m a side (cells of 1/6 m or more: a
        // small field under a huge geom is capped at 2^16 cells a query, which
        // takes seconds under the sanitizers, a bound tested elsewhere)
        for (int i = 0; i < 49; i++) d->heights[i] = rnd(0, 1) < 0.5 ? extreme() : 0;
        d->field = dGeomHeightfieldDataCreate();
        dGeomHeightfieldDataBuildDouble(d->field, d->heights, 0, (dReal)(h[0] + 1),
                                        (dReal)(h[1] + 1), 7, 7, 1, 0, (dReal)h[2],
                                        rnd(0, 1) < 0.5);
        return dCreateHeightfield(0, d->field, 1);
    }
}

static void free_data(shape_data *d)
{
    if (d->mesh) dGeomTriMeshDataDestroy(d->mesh);
    if (d->field) dGeomHeightfieldDataDestroy(d->field);
    d->mesh = NULL;
    d->field = NULL;
}

// The contacts of one call, as the guide's convention wants them.
static int contacts_sane(dGeomID o1, dGeomID o2, int flags, const dContactGeom *c, int n)
{
    CHECK(n >= 0 && n <= (flags & 0xffff));
    for (int i = 0; i < n; i++) {
        CHECK(isfinite(c[i].pos[0]) && isfinite(c[i].pos[1]) && isfinite(c[i].pos[2]));
        CHECK_NEAR(dCalcVectorLength3(c[i].normal), 1, TOL(1e-6, 1e-3));
        CHECK(isfinite(c[i].depth) && c[i].depth >= 0);
        CHECK(c[i].g1 == o1 && c[i].g2 == o2);
    }
    return 0;
}

static int test_extreme_pairs_return_sane_contacts(void)
{
    dSetErrorHandler(quiet);
    dSetDebugHandler(quiet);
    dSetMessageHandler(quiet);
    signal(SIGALRM, on_alarm);
    int failed = 0, collided = 0;
    for (int p = 0; p < PAIRS && !failed; p++) {
        shape_data da = { .mesh = NULL }, db = { .mesh = NULL };
        char ta[128], tb[128];
        const int ka = (int)rnd(0, CLASSES), kb = (int)rnd(0, CLASSES);
        dGeomID a = make_geom(ka, &da, ta, sizeof ta), b = make_geom(kb, &db, tb, sizeof tb);
        if (a && b) {
            double pos[3], axis[3] = { rnd(0, 1) < 0.3, rnd(0, 1) < 0.3, 1 };
            for (int i = 0; i < 3; i++) pos[i] = rnd(0, 1) < 0.5 ? extreme() : 0;
            const double turn = rnd(0, 3), angle = turn < 1 ? 0 : turn < 2 ? M_PI / 2 : rnd(0, 6.3);
            if (kb != PLANE) {
                dMatrix3 R;
                dRFromAxisAndAngle(R, (dReal)axis[0], (dReal)axis[1], (dReal)axis[2], (dReal)angle);
                dGeomSetPosition(b, (dReal)pos[0], (dReal)pos[1], (dReal)pos[2]);
                dGeomSetRotation(b, R);
            }
            snprintf(pair_text, sizeof pair_text,
                     "pair %d: %s | %s at %g %g %g turned %.17g about %g %g 1", p, ta, tb, pos[0],
                     pos[1], pos[2], angle, axis[0], axis[1]);
            for (int order = 0; order < 2 && !failed; order++) {
                dContactGeom c[MAXC];
                const int flags = 1 + (int)rnd(0, MAXC);
                dGeomID o1 = order ? b : a, o2 = order ? a : b;
                alarm(ALARM_SECONDS);
                const int n = dCollide(o1, o2, flags, c, sizeof c[0]);
                alarm(0);
                if (contacts_sane(o1, o2, flags, c, n)) {
                    printf("# %s (order %d)\n", pair_text, order);
                    failed = 1;
                }
                collided += n > 0;
            }
        }
        if (a) dGeomDestroy(a);
        if (b) dGeomDestroy(b);
        free_data(&da);
        free_data(&db);
    }
    signal(SIGALRM, SIG_DFL);
    dSetErrorHandler(0);
    dSetDebugHandler(0);
    dSetMessageHandler(0);
    CHECK(!failed);
    // The draw is not all misses: a good share of the calls make contacts.
    CHECK(collided > PAIRS / 10);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_extreme_pairs_return_sane_contacts),
    TEST_END
};
