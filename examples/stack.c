// SPDX-License-Identifier: BSD-3-Clause
//
// stack.c -- a tower of boxes that must stand, and a brick wall knocked over
// by a heavy ball thrown at it after one second. When the loop ends it checks
// that the tower stood (every box within 5 cm of where it was built) and that
// the wall fell (at least a third of its bricks moved more than 30 cm).

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define TOWER 8
#define WALL_ROWS 6
#define WALL_COLS 7
#define BRICKS (WALL_ROWS * WALL_COLS)
#define MAX_BALLS 16
#define THROW_STEP 60    // the first ball, at 1 s
#define FALL_STEPS 200   // the wall has fallen 200 steps after the throw

static dWorldID world;
static dSpaceID space;
static exu_contacts contacts;
static dContactGeom contact_buffer[2048];
static long steps;

static const dReal cube = 0.4;
static const dVector3 brick = { 0.25, 0.5, 0.25 };
static dBodyID tower[TOWER];
static dGeomID tower_geoms[TOWER];
static dVector3 tower_start[TOWER];
static dBodyID bricks[BRICKS];
static dGeomID brick_geoms[BRICKS];
static dVector3 brick_start[BRICKS];
static dBodyID balls[MAX_BALLS];
static dGeomID ball_geoms[MAX_BALLS];
static int ball_count;

static dBodyID make_box(dGeomID *geom, const dReal *sides, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetBox(&m, 400, sides[0], sides[1], sides[2]);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    *geom = dCreateBox(space, sides[0], sides[1], sides[2]);
    dGeomSetBody(*geom, b);
    return b;
}

// A heavy ball from the left of the wall, aimed at its middle.
static void throw_ball(void)
{
    if (ball_count == MAX_BALLS) return;
    const dReal radius = 0.25;
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetSphere(&m, 3000, radius);
    dBodySetMass(b, &m);
    dBodySetPosition(b, -3, 1.5, 1.0);
    dBodySetLinearVel(b, 12, 0, 2);
    ball_geoms[ball_count] = dCreateSphere(space, radius);
    dGeomSetBody(ball_geoms[ball_count], b);
    balls[ball_count++] = b;
}

static void start(void)
{
    static const float xyz[3] = { -1.0f, -6.5f, 2.2f };
    static const float hpr[3] = { 80.0f, -12.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("stack", "  t: throw another ball at the wall\n");
}

static void command(int key)
{
    if (key == 't') throw_ball();
}

static void step(int pause)
{
    if (!pause) {
        if (steps == THROW_STEP) throw_ball();
        exu_collide(&contacts, space);
        dWorldQuickStep(world, EXU_DT);
        steps++;
    }
    dsSetTexture(DS_WOOD);
    dsSetColor(0.9f, 0.7f, 0.3f);
    for (int i = 0; i < TOWER; i++) exu_draw_geom(tower_geoms[i]);
    dsSetColor(0.8f, 0.35f, 0.25f);
    for (int i = 0; i < BRICKS; i++) exu_draw_geom(brick_geoms[i]);
    dsSetColor(0.3f, 0.3f, 0.35f);
    for (int i = 0; i < ball_count; i++) exu_draw_geom(ball_geoms[i]);
}

static dReal moved(dBodyID b, const dVector3 from)
{
    const dReal *p = dBodyGetPosition(b);
    return (dReal)sqrt((double)((p[0] - from[0]) * (p[0] - from[0]) +
                                (p[1] - from[1]) * (p[1] - from[1]) +
                                (p[2] - from[2]) * (p[2] - from[2])));
}

static int check(void)
{
    for (int i = 0; i < TOWER; i++)
        if (!exu_body_finite(tower[i])) return exu_report("stack", 0, "tower state not finite");
    for (int i = 0; i < BRICKS; i++)
        if (!exu_body_finite(bricks[i])) return exu_report("stack", 0, "wall state not finite");
    dReal tower_worst = 0;
    for (int i = 0; i < TOWER; i++) {
        const dReal d = moved(tower[i], tower_start[i]);
        if (d > tower_worst) tower_worst = d;
    }
    int fallen = 0;
    for (int i = 0; i < BRICKS; i++)
        if (moved(bricks[i], brick_start[i]) > 0.3) fallen++;
    const int stands = tower_worst < 0.05;
    if (steps < THROW_STEP + FALL_STEPS)
        return exu_report("stack", stands, "tower of %d moved at most %.4f m (< 0.05); "
                          "stopped before the wall could fall", TOWER, (double)tower_worst);
    return exu_report("stack", stands && 3 * fallen >= BRICKS,
                      "tower of %d moved at most %.4f m (< 0.05); %d of %d bricks moved "
                      "more than 0.3 m (>= a third)", TOWER, (double)tower_worst, fallen, BRICKS);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(world, 40);
    dWorldSetAutoDisableFlag(world, 0);
    space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contacts = (exu_contacts){ .world = world, .group = dJointGroupCreate(0),
                               .surface = { .mode = dContactApprox1, .mu = 0.7 },
                               .max_per_pair = 8, .seen = contact_buffer,
                               .seen_capacity = 2048 };

    const dReal sides[3] = { cube, cube, cube };
    for (int i = 0; i < TOWER; i++) {
        tower[i] = make_box(&tower_geoms[i], sides, -1.5, -2.5, cube * (i + 0.5));
        dCopyVector3(tower_start[i], dBodyGetPosition(tower[i]));
    }
    // Bricks laid in courses along y, every other course shifted by half a brick.
    for (int r = 0; r < WALL_ROWS; r++)
        for (int c = 0; c < WALL_COLS; c++) {
            const int i = r * WALL_COLS + c;
            const dReal y = 1.5 + (c - (WALL_COLS - 1) / 2.0) * brick[1] + (r % 2) * brick[1] / 2;
            bricks[i] = make_box(&brick_geoms[i], brick, 1.0, y, brick[2] * (r + 0.5));
            dCopyVector3(brick_start[i], dBodyGetPosition(bricks[i]));
        }

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    dJointGroupDestroy(contacts.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
