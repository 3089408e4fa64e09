// SPDX-License-Identifier: BSD-3-Clause
//
// rays.c -- a rotating laser scanner: a fan of rays from the centre of a
// walled room, turning a little every step, drawn to where each hits (a wall,
// a pillar, a ball circling the room). Keys + and - change the turning speed.
// Checks every step that each ray's hit is at the distance the room's
// geometry gives (the nearest of the wall planes and the circles the pillar
// and the ball cut in the scan plane), within 1 mm, and reports the worst.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define RAYS 90
#define WALLS 4

static dWorldID world;
static dSpaceID room;
static long steps;

static const dReal half_room = 4;     // inner half-width of the room
static const dReal scan_z = 0.5;      // height of the scanner and its scan plane
static const dReal ray_length = 10;
static const dReal pillar_at[2] = { 2, 1 }, pillar_radius = 0.3;
static const dReal ball_radius = 0.4;
static dGeomID walls[WALLS];
static dGeomID pillar;
static dBodyID ball;
static dGeomID ball_geom;
static dGeomID rays[RAYS];
static dReal hits[RAYS];   // distance, or -1 when nothing was hit
static dReal turn;          // the fan's angle
static dReal turn_rate = 0.6;   // rad/s
static dReal worst_error;
static long rays_checked;

static dReal ray_angle(int i)
{
    return turn + 2 * (dReal)M_PI * i / RAYS;
}

// The distance at which a ray from the scanner at angle a meets the room.
static dReal expected_hit(dReal a)
{
    const double dx = cos(a), dy = sin(a);
    double t = 1e30;
    if (fabs(dx) > 1e-12) t = fmin(t, half_room / fabs(dx));
    if (fabs(dy) > 1e-12) t = fmin(t, half_room / fabs(dy));
    const dReal *b = dBodyGetPosition(ball);
    const double circles[2][3] = { { pillar_at[0], pillar_at[1], pillar_radius },
                                   { b[0], b[1], ball_radius } };
    for (int k = 0; k < 2; k++) {   // |t d - c| = r, nearest root in front
        const double cx = circles[k][0], cy = circles[k][1], r = circles[k][2];
        const double half_b = -(dx * cx + dy * cy);
        const double disc = half_b * half_b - (cx * cx + cy * cy - r * r);
        if (disc < 0) continue;
        const double root = -half_b - sqrt(disc);
        if (root > 0) t = fmin(t, root);
    }
    return (dReal)t;
}

static void scan(void)
{
    dContactGeom contact;
    for (int i = 0; i < RAYS; i++) {
        const dReal a = ray_angle(i);
        dGeomRaySet(rays[i], 0, 0, scan_z, (dReal)cos(a), (dReal)sin(a), 0);
        hits[i] = -1;
        const int n = dSpaceGetNumGeoms(room);
        for (int k = 0; k < n; k++) {
            dGeomID g = dSpaceGetGeom(room, k);
            if (dCollide(rays[i], g, 1, &contact, sizeof contact) == 1 &&
                (hits[i] < 0 || contact.depth < hits[i]))
                hits[i] = contact.depth;
        }
        const dReal expected = expected_hit(a);
        const dReal error = hits[i] < 0 ? expected : (dReal)fabs((double)(hits[i] - expected));
        if (error > worst_error) worst_error = error;
        rays_checked++;
    }
}

static void build(void)
{
    room = dSimpleSpaceCreate(0);
    for (int k = 0; k < WALLS; k++) {
        const int along_x = k < 2;
        const dReal side = k % 2 ? 1 : -1;
        walls[k] = dCreateBox(room, along_x ? 0.2 : 2 * half_room + 0.4,
                              along_x ? 2 * half_room + 0.4 : 0.2, 1.2);
        dGeomSetPosition(walls[k], along_x ? side * (half_room + 0.1) : 0,
                         along_x ? 0 : side * (half_room + 0.1), 0.6);
    }
    pillar = dCreateCylinder(room, pillar_radius, 1.2);   // standing: its axis is z
    dGeomSetPosition(pillar, pillar_at[0], pillar_at[1], 0.6);
    ball = dBodyCreate(world);
    dBodySetKinematic(ball);
    dBodySetPosition(ball, -1.5 + 1.2, -1.5, scan_z);
    ball_geom = dCreateSphere(room, ball_radius);
    dGeomSetBody(ball_geom, ball);
    for (int i = 0; i < RAYS; i++) rays[i] = dCreateRay(0, ray_length);
}

static void start(void)
{
    static const float xyz[3] = { -6.8f, -5.5f, 5.5f };
    static const float hpr[3] = { 38.0f, -38.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("rays", "  + / -: turn the scanner faster / slower\n");
}

static void command(int key)
{
    if (key == '+' || key == '=') turn_rate += 0.2;
    if (key == '-') turn_rate -= 0.2;
}

static void step(int pause)
{
    if (!pause) {
        // The ball circles (-1.5, -1.5) at radius 1.2, one turn in 8 s.
        const dReal *p = dBodyGetPosition(ball);
        const dReal w = 2 * (dReal)M_PI / 8;
        dBodySetLinearVel(ball, -w * (p[1] + 1.5), w * (p[0] + 1.5), 0);
        dWorldStep(world, EXU_DT);
        turn += turn_rate * EXU_DT;
        steps++;
        scan();
    }
    static const dReal identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    dsSetTexture(DS_WOOD);
    dsSetColor(0.75f, 0.75f, 0.7f);
    for (int k = 0; k < WALLS; k++) exu_draw_geom(walls[k]);
    dsSetColor(0.4f, 0.5f, 0.8f);
    exu_draw_geom(pillar);
    dsSetColor(0.3f, 0.8f, 0.4f);
    exu_draw_geom(ball_geom);
    dsSetColor(0.2f, 0.2f, 0.2f);
    const dReal scanner[3] = { 0, 0, scan_z / 2 };
    dsDrawCylinder(scanner, identity, (float)scan_z, 0.12f);
    dsSetColor(1.0f, 0.1f, 0.1f);
    for (int i = 0; i < RAYS; i++) {
        if (hits[i] < 0) continue;
        const dReal a = ray_angle(i);
        const dReal from[3] = { 0, 0, scan_z };
        const dReal to[3] = { hits[i] * (dReal)cos(a), hits[i] * (dReal)sin(a), scan_z };
        dsDrawLine(from, to);
        dsDrawSphere(to, identity, 0.03f);
    }
}

static int check(void)
{
    if (!exu_body_finite(ball)) return exu_report("rays", 0, "state not finite");
    return exu_report("rays", rays_checked > 0 && worst_error < 1e-3,
                      "%ld ray casts over %ld steps hit at the room's distances: worst error "
                      "%.2g m (< 1e-3)", rays_checked, steps, (double)worst_error);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    build();

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    for (int i = 0; i < RAYS; i++) dGeomDestroy(rays[i]);
    dSpaceDestroy(room);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
