// SPDX-License-Identifier: BSD-3-Clause
//
// test_collide_ray.c -- rays against spheres, boxes, capsules, cylinders and
// planes through dCollide (BACKENDS.md section 1, guide 10.7.5). Every
// collision is made both ways round: (ray, shape) gives the shape's surface
// normal facing the ray's side, (shape, ray) the same contact with the
// normal flipped and g1/g2 swapped. Hand-worked rays: hits from outside,
// starts inside (the exit point, normal inward), misses, rays too short or
// ending exactly on the surface, tangent rays, box faces and edges, capsule
// caps and sides, cylinder caps, sides and rims, planes from either side.
// Seeded random rays check the contact against the surface (point depth
// ~0), the ray (pos = start + depth dir, depth <= length) and a brute-force
// march along the ray for the first crossing. Also: ray against ray, a ray
// in a space, the ray's setters and a ray on a body.

#include "collide_check.h"
#include "test.h"

#include <float.h>
#include <math.h>
#include <string.h>

enum { MAXC = 4 };

// Rounding of a few dozen operations on sizes ~1..10: double 1e-9 is far
// above it, single 1e-4 covers float's 6e-8 times that.
#define EPS TOL(1e-9, 1e-4)

static const unsigned char SENTINEL = 0xA5;

// ---- helpers ----------------------------------------------------------------

static dGeomID make_ray(dReal length, dReal px, dReal py, dReal pz, dReal dx, dReal dy,
                        dReal dz)
{
    dGeomID r = dCreateRay(0, length);
    dGeomRaySet(r, px, py, pz, dx, dy, dz);
    return r;
}

static int untouched(const void *p, size_t size)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < size; i++)
        if (b[i] != SENTINEL) return 0;
    return 1;
}

#define REQUIRE(cond) \
    do { \
        if (!(cond)) { \
            test_fail(__FILE__, __LINE__, "REQUIRE(%s)", #cond); \
            return -1; \
        } \
    } while (0)

// dCollide(a, b) asking for MAXC contacts: at most one, the rest of the
// array untouched, g1 = a, g2 = b, sides -1. Returns the count or -1.
static int collide_one(dGeomID a, dGeomID b, dContactGeom *c)
{
    memset(c, SENTINEL, MAXC * sizeof *c);
    int n = dCollide(a, b, MAXC, c, sizeof *c);
    REQUIRE(n == 0 || n == 1);
    REQUIRE(untouched(c + n, (MAXC - n) * sizeof *c));
    if (n) REQUIRE(c->g1 == a && c->g2 == b && c->side1 == -1 && c->side2 == -1);
    return n;
}

// The ray against g both ways round: the same count; with a contact, the
// same pos and depth and opposite normals. c gets (ray, g)'s contact.
// Returns the count or -1.
static int ray_both_ways(dGeomID ray, dGeomID g, dContactGeom *c)
{
    dContactGeom r[MAXC];
    int n = collide_one(ray, g, c), m = collide_one(g, ray, r);
    REQUIRE(n >= 0 && m == n);
    if (n == 0) return 0;
    for (int i = 0; i < 3; i++) {
        REQUIRE(r->pos[i] == c->pos[i]);
        REQUIRE(r->normal[i] == -c->normal[i]);
    }
    REQUIRE(r->depth == c->depth);
    return n;
}

// Check a contact of (ray, g) against hand-worked values.
#define CHECK_HIT(ray, g, depth_, px, py, pz, nx, ny, nz) \
    do { \
        dContactGeom c_[MAXC]; \
        CHECK(ray_both_ways(ray, g, c_) == 1); \
        CHECK_NEAR(c_[0].depth, depth_, EPS); \
        CHECK_VEC(c_[0].pos, px, py, pz, EPS); \
        CHECK_VEC(c_[0].normal, nx, ny, nz, EPS); \
    } while (0)

#define CHECK_MISS(ray, g) \
    do { \
        dContactGeom c_[MAXC]; \
        CHECK(ray_both_ways(ray, g, c_) == 0); \
    } while (0)

// ---- sphere -----------------------------------------------------------------

static int test_ray_sphere(void)
{
    dGeomID s = dCreateSphere(0, 1);
    dGeomSetPosition(s, 1, 2, 3);
    dGeomID r = make_ray(10, 1, 2, -2, 0, 0, 1);   // up the z axis of the sphere
    CHECK_HIT(r, s, 4, 1, 2, 2, 0, 0, -1);
    dGeomRaySet(r, 1.6, 2, 8, 0, 0, -1);   // down, off centre by 0.6: z = 3 + 0.8
    CHECK_HIT(r, s, 4.2, 1.6, 2, 3.8, 0.6, 0, 0.8);
    dGeomRaySet(r, 1, 2, 3.5, 0, 0, 1);   // from inside: the exit, normal inward
    CHECK_HIT(r, s, 0.5, 1, 2, 4, 0, 0, -1);
    dGeomRaySet(r, 1, 2, 3, 1, 0, 0);   // from the centre
    CHECK_HIT(r, s, 1, 2, 2, 3, -1, 0, 0);
    dGeomRaySet(r, 1, 2, -2, 0, 0, -1);   // pointing away
    CHECK_MISS(r, s);
    dGeomRaySet(r, 2.5, 2, -2, 0, 0, 1);   // passing by
    CHECK_MISS(r, s);
    dGeomRaySet(r, 2, 2, -2, 0, 0, 1);   // tangent: touches at (2, 2, 3)
    CHECK_HIT(r, s, 5, 2, 2, 3, 1, 0, 0);
    dGeomRaySet(r, 1, 2, -2, 0, 0, 1);
    dGeomRaySetLength(r, 4);   // ends exactly on the surface: hits
    CHECK_HIT(r, s, 4, 1, 2, 2, 0, 0, -1);
    dGeomRaySetLength(r, 3.999);   // too short
    CHECK_MISS(r, s);
    dGeomRaySetLength(r, 0);   // zero length, inside: the exit is too far
    dGeomRaySet(r, 1, 2, 3, 0, 0, 1);
    CHECK_MISS(r, s);
    dGeomDestroy(r);
    dGeomDestroy(s);
    return 0;
}

// ---- box --------------------------------------------------------------------

static int test_ray_box(void)
{
    dGeomID b = dCreateBox(0, 2, 4, 6);   // half sides 1, 2, 3
    dGeomID r = make_ray(10, -5, 0.5, 0.5, 1, 0, 0);
    CHECK_HIT(r, b, 4, -1, 0.5, 0.5, -1, 0, 0);
    dGeomRaySet(r, 0.5, -0.5, 10, 0, 0, -1);   // onto the top face
    CHECK_HIT(r, b, 7, 0.5, -0.5, 3, 0, 0, 1);
    dGeomRaySet(r, 0.2, 0.3, 0.1, 0, 1, 0);   // from inside: out through y = 2
    CHECK_HIT(r, b, 1.7, 0.2, 2, 0.1, 0, -1, 0);
    dGeomRaySet(r, 0.2, 0.3, 0.1, 1, 1, 1);   // diagonally: x = 1 first, after 0.8 / cos
    CHECK_HIT(r, b, 0.8 * sqrt(3.0), 1, 1.1, 0.9, -1, 0, 0);
    dGeomRaySet(r, -5, 2, 0, 1, 0, 0);   // along the face y = 2: in its plane, hits x = -1
    CHECK_HIT(r, b, 4, -1, 2, 0, -1, 0, 0);
    dGeomRaySet(r, -5, 2.001, 0, 1, 0, 0);   // just beside it
    CHECK_MISS(r, b);
    // Onto the edge x = -1, y = -2 at 45 degrees: both faces are met at the
    // same distance; the lower-numbered axis (x) gives the normal, as ODE.
    dGeomRaySet(r, -3, -4, 0, 1, 1, 0);
    CHECK_HIT(r, b, 2 * sqrt(2.0), -1, -2, 0, -1, 0, 0);
    dGeomRaySet(r, -3, -4.5, 0, 1, 1, 0);   // beside the edge: x = -1 is passed at
    CHECK_HIT(r, b, 2.5 * sqrt(2.0), -0.5, -2, 0, 0, -1, 0);   // y = -2.5, y = -2 met next
    dGeomRaySet(r, -2.9, -4, 0, 1, 1, 0);   // into the face y = -2 at x = -0.9
    CHECK_HIT(r, b, 2 * sqrt(2.0), -0.9, -2, 0, 0, -1, 0);
    dGeomRaySet(r, -2, -5.1, 0, 1, 1, 0);   // 0.07 beside the edge x = 1, y = -2
    CHECK_MISS(r, b);
    // Turned 90 degrees about z and moved: the 4-long side now along x.
    set_rot(b, 0, 0, 1, M_PI / 2);
    dGeomSetPosition(b, 1, 1, 1);
    dGeomRaySet(r, -5, 1, 1, 1, 0, 0);
    CHECK_HIT(r, b, 4, -1, 1, 1, -1, 0, 0);
    dGeomRaySetLength(r, 3.9);
    CHECK_MISS(r, b);
    dGeomDestroy(r);
    dGeomDestroy(b);
    return 0;
}

// ---- capsule ----------------------------------------------------------------

// The exit distance of a ray (start s, unit direction u) from the ball
// (centre c, radius 1): the larger root of |s + t u - c|^2 = 1.
static double ball_exit(const double *s, const double *u, const double *c)
{
    double q[3] = { s[0] - c[0], s[1] - c[1], s[2] - c[2] };
    double b = q[0] * u[0] + q[1] * u[1] + q[2] * u[2];
    double cc = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - 1;
    return -b + sqrt(b * b - cc);
}

static int test_ray_capsule(void)
{
    dGeomID cap = dCreateCapsule(0, 1, 2);   // caps centred at z = +-1
    dGeomID r = make_ray(10, -5, 0, 0.5, 1, 0, 0);   // the side
    CHECK_HIT(r, cap, 4, -1, 0, 0.5, -1, 0, 0);
    dGeomRaySet(r, 0, 0, 5, 0, 0, -1);   // the top cap's pole
    CHECK_HIT(r, cap, 3, 0, 0, 2, 0, 0, 1);
    dGeomRaySet(r, 0.6, 0, 5, 0, 0, -1);   // the cap off the axis: z = 1 + 0.8
    CHECK_HIT(r, cap, 3.2, 0.6, 0, 1.8, 0.6, 0, 0.8);
    dGeomRaySet(r, 0.6, 0, -0.5, 0, 0, 1);   // from inside, up: out through the cap
    CHECK_HIT(r, cap, 2.3, 0.6, 0, 1.8, -0.6, 0, -0.8);
    dGeomRaySet(r, 0, 0, 0, 1, 0, 0);   // from the centre, sideways
    CHECK_HIT(r, cap, 1, 1, 0, 0, -1, 0, 0);
    dGeomRaySet(r, 1, -5, 0, 0, 1, 0);   // tangent to the side at (1, 0, 0)
    CHECK_HIT(r, cap, 5, 1, 0, 0, 1, 0, 0);
    dGeomRaySet(r, -5, 0, 2, 1, 0, 0);   // tangent to the top cap at its pole
    CHECK_HIT(r, cap, 5, 0, 0, 2, 0, 0, 1);
    dGeomRaySet(r, -5, 0, 2.01, 1, 0, 0);
    CHECK_MISS(r, cap);
    dGeomRaySet(r, -5, 0, 0, 1, 0, 0);
    dGeomRaySetLength(r, 3.99);
    CHECK_MISS(r, cap);
    // From inside the cylindrical part, slanting down out through the lower
    // cap; the ray ends (length 3) before its line would leave the infinite
    // tube of radius 1 (at x = -1, t = 3.35): ODE 0.16 misses this exit.
    const double s[3] = { 0.5, 0, 0.5 }, k = 1 / sqrt(1.25);
    const double u[3] = { -0.5 * k, 0, -k }, low[3] = { 0, 0, -1 };
    dGeomRaySet(r, s[0], s[1], s[2], u[0], u[1], u[2]);
    dGeomRaySetLength(r, 3);
    double t = ball_exit(s, u, low), p[3] = { s[0] + t * u[0], s[1] + t * u[1], s[2] + t * u[2] };
    CHECK(p[2] < -1);   // below the lower cap's centre: on the cap
    CHECK_HIT(r, cap, t, p[0], p[1], p[2], -p[0], -p[1], -(p[2] + 1));
    // Turned to lie along x and moved: the side seen from above.
    set_rot(cap, 0, 1, 0, M_PI / 2);
    dGeomSetPosition(cap, 2, 0, 0);
    dGeomRaySet(r, 2.5, 0, 4, 0, 0, -1);
    dGeomRaySetLength(r, 10);
    CHECK_HIT(r, cap, 3, 2.5, 0, 1, 0, 0, 1);
    dGeomRaySet(r, 3.6, 0, 4, 0, 0, -1);   // over the cap centred at x = 3
    CHECK_HIT(r, cap, 3.2, 3.6, 0, 0.8, 0.6, 0, 0.8);
    dGeomDestroy(r);
    dGeomDestroy(cap);
    return 0;
}

// ---- cylinder ---------------------------------------------------------------

static int test_ray_cylinder(void)
{
    dGeomID cyl = dCreateCylinder(0, 1, 2);   // flat caps at z = +-1
    dGeomID r = make_ray(10, -5, 0, 0.5, 1, 0, 0);
    CHECK_HIT(r, cyl, 4, -1, 0, 0.5, -1, 0, 0);
    dGeomRaySet(r, 0.5, 0, 5, 0, 0, -1);   // onto the top cap
    CHECK_HIT(r, cyl, 4, 0.5, 0, 1, 0, 0, 1);
    dGeomRaySet(r, 3, 0, 2.5, -1, 0, -1);   // slanting onto the side at z = 0.5
    CHECK_HIT(r, cyl, 2 * sqrt(2.0), 1, 0, 0.5, 1, 0, 0);
    dGeomRaySet(r, 3, 0, 3.5, -1, 0, -1);   // slanting onto the cap at x = 0.5
    CHECK_HIT(r, cyl, 2.5 * sqrt(2.0), 0.5, 0, 1, 0, 0, 1);
    dGeomRaySet(r, 0.5, 0, 0.2, 0, 0, 1);   // from inside: out through the cap
    CHECK_HIT(r, cyl, 0.8, 0.5, 0, 1, 0, 0, -1);
    dGeomRaySet(r, 0.5, 0, 0.2, 1, 0, 1);   // from inside: out through the side
    CHECK_HIT(r, cyl, 0.5 * sqrt(2.0), 1, 0, 0.7, -1, 0, 0);
    dGeomRaySet(r, -5, 0, 1.5, 1, 0, 0);   // over the top
    CHECK_MISS(r, cyl);
    dGeomRaySet(r, -5, 1, 0, 1, 0, 0);   // tangent to the side at (0, 1, 0)
    CHECK_HIT(r, cyl, 5, 0, 1, 0, 0, 1, 0);
    dGeomRaySet(r, -5, 0, 1, 1, 0, 0);   // in the top cap's plane: meets the rim
    CHECK_HIT(r, cyl, 4, -1, 0, 1, -1, 0, 0);   // where the side starts
    // Through the rim at (1, 0, 1): both the cap and the side are met there
    // (up to rounding); the normal is one of them (ODE: the cap).
    dGeomRaySet(r, 3, 0, 3, -1, 0, -1);
    dContactGeom c[MAXC];
    CHECK(ray_both_ways(r, cyl, c) == 1);
    CHECK_NEAR(c[0].depth, 2 * sqrt(2.0), EPS);
    CHECK_VEC(c[0].pos, 1, 0, 1, EPS);
    CHECK(fabs(c[0].normal[0] - 1) <= EPS || fabs(c[0].normal[2] - 1) <= EPS);
    // Turned to lie along y and moved up: the round side seen from above.
    set_rot(cyl, 1, 0, 0, M_PI / 2);
    dGeomSetPosition(cyl, 0, 0, 2);
    dGeomRaySet(r, 0.6, 0.3, 5, 0, 0, -1);   // z = 2 + 0.8
    CHECK_HIT(r, cyl, 2.2, 0.6, 0.3, 2.8, 0.6, 0, 0.8);
    dGeomRaySet(r, 0.6, 1.3, 5, 0, 0, -1);   // beyond its end (y = 1)
    CHECK_MISS(r, cyl);
    dGeomDestroy(r);
    dGeomDestroy(cyl);
    return 0;
}

// ---- plane ------------------------------------------------------------------

static int test_ray_plane(void)
{
    dGeomID pl = dCreatePlane(0, 0, 0, 1, 0);   // solid below z = 0
    dGeomID r = make_ray(10, 1, 2, 5, 0, 0, -1);
    CHECK_HIT(r, pl, 5, 1, 2, 0, 0, 0, 1);   // from above
    dGeomRaySet(r, 1, 2, -5, 0, 0, 1);   // from the solid side: the way out,
    CHECK_HIT(r, pl, 5, 1, 2, 0, 0, 0, -1);   // normal facing down (the ray's side)
    dGeomRaySet(r, 1, 2, 5, 0, 0, 1);   // above, going up
    CHECK_MISS(r, pl);
    dGeomRaySet(r, 1, 2, -5, 0, 0, -1);   // below, going down
    CHECK_MISS(r, pl);
    dGeomRaySet(r, 0, 0, -1, 1, 0, 0);   // parallel, inside: nothing (as ODE)
    CHECK_MISS(r, pl);
    dGeomRaySet(r, 0, 0, 3, 3, 0, -4);   // slanting: 3 down in 5 along
    CHECK_HIT(r, pl, 3.75, 2.25, 0, 0, 0, 0, 1);
    dGeomRaySetLength(r, 3.7);
    CHECK_MISS(r, pl);
    // Tilted: x + y = 4 (stored with the unit normal (1, 1, 0) / sqrt 2),
    // hit along x from the origin (inside, on the solid side) at x = 4.
    dGeomPlaneSetParams(pl, 1, 1, 0, 4);
    dGeomRaySet(r, 0, 0, 0, 1, 0, 0);
    dGeomRaySetLength(r, 10);
    const double h = sqrt(0.5);
    CHECK_HIT(r, pl, 4, 4, 0, 0, -h, -h, 0);
    dGeomDestroy(r);
    dGeomDestroy(pl);
    return 0;
}

// Two rays never collide (no collider for the pair); the array is untouched.
static int test_ray_ray(void)
{
    dGeomID a = make_ray(10, 0, 0, 0, 1, 0, 0), b = make_ray(10, 5, -5, 0, 0, 1, 0);
    dContactGeom c[MAXC];
    CHECK(collide_one(a, b, c) == 0);
    CHECK(collide_one(b, a, c) == 0);
    dGeomDestroy(a);
    dGeomDestroy(b);
    return 0;
}

// flags 0 means one contact (guide); the contact goes to the first slot of a
// strided array.
static int test_ray_flags_and_skip(void)
{
    dGeomID s = dCreateSphere(0, 1), r = make_ray(10, 0, 0, -5, 0, 0, 1);
    struct {
        dContactGeom c;
        double pad[3];
    } out[2];
    memset(out, SENTINEL, sizeof out);
    CHECK(dCollide(r, s, 0, &out[0].c, sizeof out[0]) == 1);
    CHECK_NEAR(out[0].c.depth, 4, EPS);
    CHECK(untouched(out[0].pad, sizeof out[0].pad) && untouched(&out[1], sizeof out[1]));
    CHECK(dCollide(s, r, 2, &out[0].c, sizeof out[0]) == 1);
    CHECK(out[0].c.g1 == s && out[0].c.g2 == r);
    dGeomDestroy(r);
    dGeomDestroy(s);
    return 0;
}

// ---- space, setters, bodies -------------------------------------------------

typedef struct hits {
    dGeomID ray;
    int n;
    dGeomID geom[8];
    dReal depth[8];
} hits;

static void collect(void *data, dGeomID a, dGeomID b)
{
    hits *h = data;
    dContactGeom c[MAXC];
    if (a != h->ray && b != h->ray) return;
    int n = dCollide(a, b, MAXC, c, sizeof c[0]);
    if (n == 1 && h->n < 8) {
        h->geom[h->n] = a == h->ray ? b : a;
        h->depth[h->n] = c[0].depth;
        h->n++;
    }
}

static dReal depth_of(const hits *h, dGeomID g)
{
    for (int i = 0; i < h->n; i++)
        if (h->geom[i] == g) return h->depth[i];
    return -1;
}

// A ray along x through a space of shapes, some on its way, some beside it:
// dSpaceCollide hands the ray's pairs to the callback, and each shape on its
// way gives one contact at its entry.
static int test_ray_in_space(void)
{
    dSpaceID space = dSimpleSpaceCreate(0);
    dGeomID r = dCreateRay(space, 20);
    dGeomRaySet(r, 0, 0, 0, 1, 0, 0);
    dGeomID s = dCreateSphere(space, 0.5), b = dCreateBox(space, 1, 1, 1);
    dGeomID cap = dCreateCapsule(space, 0.5, 1), cyl = dCreateCylinder(space, 0.5, 1);
    dGeomID off = dCreateSphere(space, 0.5), pl = dCreatePlane(space, -1, 0, 0, -15);
    dGeomSetPosition(s, 3, 0, 0);     // entry x = 2.5
    dGeomSetPosition(b, 6, 0, 0);     // 5.5
    dGeomSetPosition(cap, 9, 0, 0);   // axis along z: the side, 8.5
    dGeomSetPosition(cyl, 12, 0, 0);  // 11.5
    dGeomSetPosition(off, 5, 3, 0);   // beside the ray
    hits h = { r, 0, { 0 }, { 0 } };
    dSpaceCollide(space, &h, collect);
    CHECK(h.n == 5);
    CHECK_NEAR(depth_of(&h, s), 2.5, EPS);
    CHECK_NEAR(depth_of(&h, b), 5.5, EPS);
    CHECK_NEAR(depth_of(&h, cap), 8.5, EPS);
    CHECK_NEAR(depth_of(&h, cyl), 11.5, EPS);
    CHECK_NEAR(depth_of(&h, pl), 15, EPS);   // solid where x > 15: entered at x = 15
    CHECK(depth_of(&h, off) < 0);
    dGeomRaySetLength(r, 7);   // now reaches the sphere and the box only
    h.n = 0;
    dSpaceCollide(space, &h, collect);
    CHECK(h.n == 2 && depth_of(&h, s) > 0 && depth_of(&h, b) > 0);
    dSpaceDestroy(space);
    return 0;
}

// dGeomRaySet normalises the direction; dGeomRayGet returns it with the start;
// the length and the start change what the ray hits; its AABB spans it.
static int test_ray_setters(void)
{
    dGeomID s = dCreateSphere(0, 1), r = dCreateRay(0, 2);
    dGeomSetPosition(s, 0, 0, 5);
    dGeomRaySet(r, 0, 0, 0, 0, 0, 7);
    dVector3 start, dir;
    dGeomRayGet(r, start, dir);
    CHECK_VEC(start, 0, 0, 0, 0);
    CHECK_VEC(dir, 0, 0, 1, EPS);
    CHECK_NEAR(dGeomRayGetLength(r), 2, 0);
    CHECK_MISS(r, s);
    dGeomRaySetLength(r, 4);
    CHECK_NEAR(dGeomRayGetLength(r), 4, 0);
    CHECK_HIT(r, s, 4, 0, 0, 4, 0, 0, -1);
    dReal aabb[6];
    dGeomGetAABB(r, aabb);
    CHECK(aabb[4] <= 0 && aabb[5] >= 4 && aabb[0] <= 0 && aabb[1] >= 0);
    dGeomSetPosition(r, 0, 0, 1);   // moving the start keeps the direction
    CHECK_HIT(r, s, 3, 0, 0, 4, 0, 0, -1);
    dGeomRaySet(r, 0, -3, 5, 0, 2, 0);   // new start and direction: along y
    dGeomRayGet(r, start, dir);
    CHECK_VEC(start, 0, -3, 5, 0);
    CHECK_VEC(dir, 0, 1, 0, EPS);
    CHECK_HIT(r, s, 2, 0, -1, 5, 0, -1, 0);
    // Flags of 0.16 for triangle meshes do not change hits on primitives.
    dGeomRaySetClosestHit(r, 1);
    dGeomRaySetBackfaceCull(r, 1);
    CHECK(dGeomRayGetClosestHit(r) == 1 && dGeomRayGetBackfaceCull(r) == 1);
    CHECK_HIT(r, s, 2, 0, -1, 5, 0, -1, 0);
    dGeomDestroy(r);
    dGeomDestroy(s);
    return 0;
}

// dGeomRaySet's rotation: its z column is the direction normalised as
// dSafeNormalize3 does, bit for bit, and its columns are a right-handed
// orthonormal frame to within a few units in the last place; the position
// is the start's bits. Random directions of every size and sign, the axes
// and directions just off them (n_z = -0 included), read back through
// dGeomGetRotation and dGeomGetPosition. A ray on a body gets the same
// frame to within rounding (through dGeomSetRotation).
static int test_ray_set_frame(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body = dBodyCreate(w);
    dGeomID free_ray = dCreateRay(0, 3), body_ray = dCreateRay(0, 3);
    dGeomSetBody(body_ray, body);
    const dReal fixed[][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 },
                               { 1e-9, 0, -1 }, { 1, 1e-12, 0 }, { 1, 1, 1 },
                               { -0.7071, 0.7072, 0 }, { 3e-30, 1e-30, -2e-30 },
                               { 1e30, -3e30, 2e30 }, { 1, 2, -0.0 }, { 0, 0, -1e-300 } };
    const int nfixed = (int)(sizeof fixed / sizeof fixed[0]);
#ifdef dSINGLE
    const dReal tol = 8 * FLT_EPSILON;
#else
    const dReal tol = 8 * DBL_EPSILON;
#endif
    for (int i = 0; i < nfixed + 2000; i++) {
        dReal d[3], p[3] = { rnd(-50, 50), rnd(-50, 50), rnd(-50, 50) };
        for (int k = 0; k < 3; k++) {
            d[k] = i < nfixed ? fixed[i][k] : rnd(-1, 1);
            if (i >= nfixed && i % 3 == 0) d[k] *= rnd(1e-6, 1e6);
        }
        if (!(d[0] != 0 || d[1] != 0 || d[2] != 0)) continue;   // a single-precision underflow
        dGeomRaySet(free_ray, p[0], p[1], p[2], d[0], d[1], d[2]);
        dVector3 n = { d[0], d[1], d[2], 0 };
        CHECK(dSafeNormalize3(n));
        const dReal *R = dGeomGetRotation(free_ray);
        for (int k = 0; k < 3; k++) CHECK(memcmp(&R[4 * k + 2], &n[k], sizeof(dReal)) == 0);
        CHECK(memcmp(dGeomGetPosition(free_ray), p, 3 * sizeof(dReal)) == 0);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                const dReal dot = R[a] * R[b] + R[4 + a] * R[4 + b] + R[8 + a] * R[8 + b];
                CHECK(dFabs(dot - (a == b)) <= tol);
            }
        // x column cross y column is the z column: right-handed.
        CHECK(dFabs(R[4] * R[9] - R[8] * R[5] - R[2]) <= tol);
        CHECK(dFabs(R[8] * R[1] - R[0] * R[9] - R[6]) <= tol);
        CHECK(dFabs(R[0] * R[5] - R[4] * R[1] - R[10]) <= tol);
        dGeomRaySet(body_ray, p[0], p[1], p[2], d[0], d[1], d[2]);
        const dReal *Rb = dGeomGetRotation(body_ray), *pb = dGeomGetPosition(body_ray);
        for (int k = 0; k < 12; k++)
            if (k % 4 != 3) CHECK(dFabs(Rb[k] - R[k]) <= tol);
        for (int k = 0; k < 3; k++) CHECK(pb[k] == p[k]);
    }
    dGeomDestroy(free_ray);
    dGeomDestroy(body_ray);
    dBodyDestroy(body);
    dWorldDestroy(w);
    return 0;
}

// A ray on a body points along the body's z axis from its position.
static int test_ray_on_body(void)
{
    dWorldID w = dWorldCreate();
    dBodyID body = dBodyCreate(w);
    dGeomID r = dCreateRay(0, 10), box = dCreateBox(0, 2, 2, 2);
    dGeomSetBody(r, body);
    dBodySetPosition(body, -5, 0, 0);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);   // body z turned onto world x
    dBodySetRotation(body, R);
    CHECK_HIT(r, box, 4, -1, 0, 0, -1, 0, 0);
    dBodySetPosition(body, -5, 3, 0);
    CHECK_MISS(r, box);
    dGeomDestroy(r);
    dGeomDestroy(box);
    dBodyDestroy(body);
    dWorldDestroy(w);
    return 0;
}

// ---- random rays ------------------------------------------------------------

static void random_rotation(dGeomID g)
{
    dQuaternion q = { rnd(-1, 1), rnd(-1, 1), rnd(-1, 1), rnd(-1, 1) };
    dNormalize4(q);
    dGeomSetQuaternion(g, q);
}

static dReal depth_along(dGeomID g, const dReal *s, const dReal *u, double t)
{
    dReal p[3] = { s[0] + t * u[0], s[1] + t * u[1], s[2] + t * u[2] };
    return point_depth(g, p);
}

// The outward normal at p by central differences of the point depth (step
// 1e-6, single 1e-3), or 0 if p is within 1e-4 (single 3e-3) of an edge or
// rim, where it is not defined.
#define EDGE TOL(1e-4, 3e-3)
static int outward_normal(dGeomID g, const dReal *p, dReal n[3])
{
    const double h = TOL(1e-6, 1e-3);
    double len = 0;
    for (int i = 0; i < 3; i++) {
        dReal a[3] = { p[0], p[1], p[2] }, b[3] = { p[0], p[1], p[2] };
        a[i] += h;
        b[i] -= h;
        n[i] = -(point_depth(g, a) - point_depth(g, b)) / (2 * h);
        len += n[i] * n[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++) n[i] /= len;
    int cls = dGeomGetClass(g);
    if (cls != dBoxClass && cls != dCylinderClass) return 1;
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    dReal d[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] }, q[3];
    for (int i = 0; i < 3; i++) q[i] = R[i] * d[0] + R[4 + i] * d[1] + R[8 + i] * d[2];
    if (cls == dBoxClass) {
        dVector3 side;
        dGeomBoxGetLengths(g, side);
        int faces = 0;
        for (int i = 0; i < 3; i++) faces += fabs(fabs(q[i]) - side[i] / 2) < EDGE;
        return faces < 2;
    }
    dReal r, l;
    dGeomCylinderGetParams(g, &r, &l);
    return !(fabs(sqrt(q[0] * q[0] + q[1] * q[1]) - r) < EDGE && fabs(fabs(q[2]) - l / 2) < EDGE);
}

// The first crossing of the surface along the ray by marching in steps of
// STEP from the start (from inside: the first sample outside; from outside:
// the first sample inside or on the surface), or -1. The point depths are
// signed distances (1-Lipschitz), so the surface can lie between two samples
// on the same side only if their distances from it add up to at most the
// step: *grazing is set then (a touch or a short chord the march may skip),
// and when the start or the end lies within ON_SURFACE of the surface.
#define STEP 1e-3
#define ON_SURFACE TOL(1e-9, 1e-4)
static double march(dGeomID g, const dReal *s, const dReal *u, double length, int *grazing)
{
    double d = depth_along(g, s, u, 0);
    int inside = d > 0;
    *grazing = fabs(d) < ON_SURFACE;
    for (int i = 1;; i++) {
        double t = i * STEP < length ? i * STEP : length, prev = d;
        d = depth_along(g, s, u, t);
        if (inside ? d < 0 : d >= 0) return t;
        if (fabs(prev) + fabs(d) <= STEP) *grazing = 1;
        if (t == length) break;
    }
    *grazing |= fabs(d) < ON_SURFACE;
    return -1;
}

// Random rays against random shapes of class cls: the contact is on the
// surface (point depth within 1e-9, single 1e-4), on the ray at distance
// depth from the start, depth within [0, length], the normal a unit vector
// facing the ray's side and the shape's outward normal there (outside start)
// or its opposite (inside start), within 1e-4 (single 1e-3: the difference
// quotient); half the rays start within 0.3 of the shape's centre;
// the hit, and its distance within one marching step, is where a march
// along the ray first crosses the surface. Counts hits from outside and
// inside so that both kinds are seen.
static int random_rays(int cls)
{
    rng_state = 4242;
    dGeomID r = dCreateRay(0, 1);
    int outside_hits = 0, inside_hits = 0, misses = 0;
    for (int k = 0; k < 400; k++) {
        dGeomID g;
        switch (cls) {
        case dSphereClass: g = dCreateSphere(0, rnd(0.2, 1)); break;
        case dBoxClass: g = dCreateBox(0, rnd(0.2, 2), rnd(0.2, 2), rnd(0.2, 2)); break;
        case dCapsuleClass: g = dCreateCapsule(0, rnd(0.1, 0.6), rnd(0.1, 2)); break;
        case dCylinderClass: g = dCreateCylinder(0, rnd(0.2, 1), rnd(0.2, 2)); break;
        default: g = dCreatePlane(0, rnd(-1, 1), rnd(-1, 1), rnd(-1, 1), rnd(-0.5, 0.5));
        }
        if (cls != dPlaneClass) {
            dGeomSetPosition(g, rnd(-0.5, 0.5), rnd(-0.5, 0.5), rnd(-0.5, 0.5));
            random_rotation(g);
        }
        dReal s[3] = { rnd(-1.5, 1.5), rnd(-1.5, 1.5), rnd(-1.5, 1.5) };
        if (k % 2 && cls != dPlaneClass) {   // near the centre: often inside
            const dReal *c = dGeomGetPosition(g);
            for (int i = 0; i < 3; i++) s[i] = c[i] + rnd(-0.3, 0.3);
        }
        dReal aim[3] = { rnd(-0.7, 0.7) - s[0], rnd(-0.7, 0.7) - s[1], rnd(-0.7, 0.7) - s[2] };
        double length = rnd(0.2, 4);
        dGeomRaySetLength(r, length);
        dGeomRaySet(r, s[0], s[1], s[2], aim[0], aim[1], aim[2]);
        dVector3 start, u;
        dGeomRayGet(r, start, u);
        dContactGeom c[MAXC];
        int n = ray_both_ways(r, g, c), grazing;
        CHECK(n >= 0);
        double t = march(g, s, u, length, &grazing);
        if (!grazing) CHECK((n == 1) == (t >= 0));
        if (n == 0) {
            misses++;
            dGeomDestroy(g);
            continue;
        }
        const dContactGeom *k1 = &c[0];
        CHECK(isfinite(k1->depth) && k1->depth >= 0 && k1->depth <= length);
        if (!grazing) CHECK(k1->depth > t - STEP - EPS && k1->depth <= t + EPS);
        CHECK(fabs(point_depth(g, k1->pos)) <= EPS);
        for (int i = 0; i < 3; i++) CHECK_NEAR(k1->pos[i], s[i] + k1->depth * u[i], EPS);
        CHECK_NEAR(dCalcVectorLength3(k1->normal), 1, EPS);
        CHECK(dCalcVectorDot3(k1->normal, u) <= EPS);
        int inside = depth_along(g, s, u, 0) > 0;
        dReal out[3];
        if (outward_normal(g, k1->pos, out)) {
            dReal sign = inside ? -1 : 1;
            for (int i = 0; i < 3; i++)
                CHECK_NEAR(k1->normal[i], sign * out[i], TOL(1e-4, 1e-3));
        }
        if (!grazing) {
            outside_hits += !inside;
            inside_hits += inside;
        }
        dGeomDestroy(g);
    }
    dGeomDestroy(r);
    if (!(outside_hits >= 40 && inside_hits >= 40 && misses >= 40)) {
        test_fail(__FILE__, __LINE__, "too few of a kind: %d hits from outside, %d from inside, "
                  "%d misses", outside_hits, inside_hits, misses);
        return 1;
    }
    return 0;
}

static int test_random_ray_sphere(void) { return random_rays(dSphereClass); }
static int test_random_ray_box(void) { return random_rays(dBoxClass); }
static int test_random_ray_capsule(void) { return random_rays(dCapsuleClass); }
static int test_random_ray_cylinder(void) { return random_rays(dCylinderClass); }
static int test_random_ray_plane(void) { return random_rays(dPlaneClass); }

const test_case test_cases[] = {
    TEST_CASE(test_ray_sphere),
    TEST_CASE(test_ray_box),
    TEST_CASE(test_ray_capsule),
    TEST_CASE(test_ray_cylinder),
    TEST_CASE(test_ray_plane),
    TEST_CASE(test_ray_ray),
    TEST_CASE(test_ray_flags_and_skip),
    TEST_CASE(test_ray_in_space),
    TEST_CASE(test_ray_setters),
    TEST_CASE(test_ray_set_frame),
    TEST_CASE(test_ray_on_body),
    TEST_CASE(test_random_ray_sphere),
    TEST_CASE(test_random_ray_box),
    TEST_CASE(test_random_ray_capsule),
    TEST_CASE(test_random_ray_cylinder),
    TEST_CASE(test_random_ray_plane),
    TEST_END,
};
