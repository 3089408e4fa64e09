// SPDX-License-Identifier: BSD-3-Clause
//
// joints.c -- every joint type side by side, with motors and stops: ball,
// hinge, slider, universal, hinge-2, fixed, angular motor, linear motor, PR,
// PU, piston, plane-2D, double ball, double hinge and a gear transmission.
// The motors reverse every 3 s (and on key m). Before each reversal and when
// the loop ends each rig checks what its joint promises: a motor driving
// against a stop holds the joint at that stop, a motor without one reaches
// its speed, a distance or a relative pose is kept.

#include "example_util.h"

#include <math.h>
#include <stdio.h>

#define MAX_RIGS 16
#define FLIP_STEPS 180     // the motors reverse every 3 s
#define SETTLE_STEPS 100   // a motor has reached its stop or speed 100 steps after a flip

typedef struct rig {
    const char *name;
    dBodyID body[2];
    dGeomID geom[2];
    dJointID joint, extra;   // extra: a second joint (the hinges of gears, fixed's arm hinge)
    dReal value, target, tolerance;   // measured by check_rig
    dVector3 kept;                    // a quantity the joint keeps, recorded at build time
} rig;

static dWorldID world;
static rig rigs[MAX_RIGS];
static int rig_count;
static long steps;
static long flipped_at;
static dReal sign = 1;   // direction of every motor
static int period_checked, period_failed;   // the checks made before each reversal

static const dReal speed = 0.8;   // rad/s or m/s of every motor
static const dReal fmax_ = 60;

static dReal P[MAX_RIGS][3];   // each rig's base point

static dBodyID box_body(rig *r, int k, dReal lx, dReal ly, dReal lz, const dReal *at)
{
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetBox(&m, 500, lx, ly, lz);
    dBodySetMass(b, &m);
    dBodySetPosition(b, at[0], at[1], at[2]);
    r->body[k] = b;
    r->geom[k] = dCreateBox(0, lx, ly, lz);
    dGeomSetBody(r->geom[k], b);
    return b;
}

static dBodyID gear_body(rig *r, int k, dReal radius, const dReal *at)
{
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetCylinder(&m, 500, 2, radius, 0.1);   // axis along body y
    dBodySetMass(b, &m);
    dBodySetPosition(b, at[0], at[1], at[2]);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, (dReal)M_PI / 2);   // cylinder z to world y
    dBodySetRotation(b, R);
    r->body[k] = b;
    r->geom[k] = dCreateCylinder(0, radius, 0.1);
    dGeomSetBody(r->geom[k], b);
    return b;
}

static rig *new_rig(const char *name)
{
    rig *r = &rigs[rig_count++];
    r->name = name;
    return r;
}

static const dReal *at(const dReal *p, dReal dx, dReal dy, dReal dz)
{
    static dReal q[3];
    q[0] = p[0] + dx;
    q[1] = p[1] + dy;
    q[2] = p[2] + dz;
    return q;
}

static void build(void)
{
    for (int i = 0; i < MAX_RIGS; i++) {
        P[i][0] = (i % 8) * 1.4 - 4.9;
        P[i][1] = (i / 8) * 2.0;
        P[i][2] = 1.6;
    }
    const dReal *p;
    rig *r;
    dJointID j;

    r = new_rig("ball");   // a pendulum started sideways
    p = P[rig_count - 1];
    box_body(r, 0, 0.2, 0.2, 0.2, at(p, 0.3, 0.2, -0.4));
    j = r->joint = dJointCreateBall(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetBallAnchor(j, p[0], p[1], p[2]);

    r = new_rig("hinge");   // an arm with a motor between stops
    p = P[rig_count - 1];
    box_body(r, 0, 0.5, 0.1, 0.1, at(p, 0.25, 0, 0));
    j = r->joint = dJointCreateHinge(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetHingeAnchor(j, p[0], p[1], p[2]);
    dJointSetHingeAxis(j, 0, 1, 0);
    dJointSetHingeParam(j, dParamLoStop, -0.7);
    dJointSetHingeParam(j, dParamHiStop, 0.7);

    r = new_rig("slider");
    p = P[rig_count - 1];
    box_body(r, 0, 0.3, 0.2, 0.2, p);
    j = r->joint = dJointCreateSlider(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetSliderAxis(j, 1, 0, 0);
    dJointSetSliderParam(j, dParamLoStop, -0.3);
    dJointSetSliderParam(j, dParamHiStop, 0.3);

    r = new_rig("universal");
    p = P[rig_count - 1];
    box_body(r, 0, 0.1, 0.1, 0.5, at(p, 0, 0, -0.25));
    j = r->joint = dJointCreateUniversal(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetUniversalAnchor(j, p[0], p[1], p[2]);
    dJointSetUniversalAxis1(j, 0, 1, 0);
    dJointSetUniversalAxis2(j, 1, 0, 0);
    dJointSetUniversalParam(j, dParamLoStop, -0.6);
    dJointSetUniversalParam(j, dParamHiStop, 0.6);
    dJointSetUniversalParam(j, dParamLoStop2, -0.6);
    dJointSetUniversalParam(j, dParamHiStop2, 0.6);

    r = new_rig("hinge-2");   // a wheel on a steering fork held by a kinematic body
    p = P[rig_count - 1];
    box_body(r, 0, 0.1, 0.1, 0.3, at(p, 0, 0, 0.3));
    dBodySetKinematic(r->body[0]);
    gear_body(r, 1, 0.25, p);
    j = r->joint = dJointCreateHinge2(world, 0);
    dJointAttach(j, r->body[0], r->body[1]);
    dJointSetHinge2Anchor(j, p[0], p[1], p[2]);
    {
        const dReal steer_axis[3] = { 0, 0, 1 }, spin_axis[3] = { 0, 1, 0 };
        dJointSetHinge2Axes(j, steer_axis, spin_axis);
    }
    dJointSetHinge2Param(j, dParamLoStop, -0.4);
    dJointSetHinge2Param(j, dParamHiStop, 0.4);
    dJointSetHinge2Param(j, dParamSuspensionERP, 0.8);
    dJointSetHinge2Param(j, dParamSuspensionCFM, 1e-4);

    r = new_rig("fixed");   // a box fixed to the end of a turning arm
    p = P[rig_count - 1];
    box_body(r, 0, 0.5, 0.1, 0.1, at(p, 0.25, 0, 0));
    box_body(r, 1, 0.2, 0.2, 0.2, at(p, 0.55, 0, 0));
    j = r->extra = dJointCreateHinge(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetHingeAnchor(j, p[0], p[1], p[2]);
    dJointSetHingeAxis(j, 0, 1, 0);
    j = r->joint = dJointCreateFixed(world, 0);
    dJointAttach(j, r->body[1], r->body[0]);
    dJointSetFixed(j);
    dBodyGetPosRelPoint(r->body[0], p[0] + 0.55, p[1], p[2], r->kept);

    r = new_rig("angular motor");   // spins a box on a ball joint about z
    p = P[rig_count - 1];
    box_body(r, 0, 0.3, 0.3, 0.1, p);
    j = r->extra = dJointCreateBall(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetBallAnchor(j, p[0], p[1], p[2]);
    j = r->joint = dJointCreateAMotor(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetAMotorMode(j, dAMotorUser);
    dJointSetAMotorNumAxes(j, 1);
    dJointSetAMotorAxis(j, 0, 0, 0, 0, 1);

    r = new_rig("linear motor");   // a free box moved up and down, held in x and y
    p = P[rig_count - 1];
    box_body(r, 0, 0.2, 0.2, 0.2, p);
    j = r->joint = dJointCreateLMotor(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetLMotorNumAxes(j, 3);
    dJointSetLMotorAxis(j, 0, 0, 1, 0, 0);
    dJointSetLMotorAxis(j, 1, 0, 0, 1, 0);
    dJointSetLMotorAxis(j, 2, 0, 0, 0, 1);
    for (int k = 0; k < 3; k++)
        dJointSetLMotorParam(j, dParamFMax + k * dParamGroup, fmax_);

    r = new_rig("PR");   // slides vertically between stops, turns about x
    p = P[rig_count - 1];
    box_body(r, 0, 0.2, 0.3, 0.2, p);
    j = r->joint = dJointCreatePR(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetPRAnchor(j, p[0], p[1], p[2]);
    dJointSetPRAxis1(j, 0, 0, 1);
    dJointSetPRAxis2(j, 1, 0, 0);
    dJointSetPRParam(j, dParamLoStop, -0.25);
    dJointSetPRParam(j, dParamHiStop, 0.25);

    r = new_rig("PU");   // a universal that also slides along z
    p = P[rig_count - 1];
    box_body(r, 0, 0.1, 0.1, 0.4, at(p, 0, 0, -0.2));
    j = r->joint = dJointCreatePU(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetPUAnchor(j, p[0], p[1], p[2]);
    dJointSetPUAxis1(j, 0, 1, 0);
    dJointSetPUAxis2(j, 1, 0, 0);
    dJointSetPUAxisP(j, 0, 0, 1);
    dJointSetPUParam(j, dParamLoStop3, -0.25);
    dJointSetPUParam(j, dParamHiStop3, 0.25);

    r = new_rig("piston");   // slides and turns about x
    p = P[rig_count - 1];
    box_body(r, 0, 0.4, 0.15, 0.15, p);
    j = r->joint = dJointCreatePiston(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetPistonAnchor(j, p[0], p[1], p[2]);
    dJointSetPistonAxis(j, 1, 0, 0);
    dJointSetPistonParam(j, dParamLoStop, -0.25);
    dJointSetPistonParam(j, dParamHiStop, 0.25);

    r = new_rig("plane-2D");   // kept in the plane z = 0, driven along x, turning about z
    p = P[rig_count - 1];
    box_body(r, 0, 0.3, 0.2, 0.1, at(p, 0, 0, -p[2]));
    j = r->joint = dJointCreatePlane2D(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetPlane2DXParam(j, dParamFMax, fmax_);
    dJointSetPlane2DYParam(j, dParamFMax, fmax_);
    dJointSetPlane2DAngleParam(j, dParamFMax, fmax_);

    r = new_rig("double ball");   // a pendulum on a rod of 0.5 m
    p = P[rig_count - 1];
    box_body(r, 0, 0.2, 0.2, 0.2, at(p, 0.3, 0.1, -0.39));
    j = r->joint = dJointCreateDBall(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetDBallAnchor1(j, p[0] + 0.3, p[1] + 0.1, p[2] - 0.39);
    dJointSetDBallAnchor2(j, p[0], p[1], p[2]);
    r->kept[0] = dJointGetDBallDistance(j);

    r = new_rig("double hinge");   // swings about y on two anchors 0.4 m apart
    p = P[rig_count - 1];
    box_body(r, 0, 0.2, 0.2, 0.2, at(p, 0.3, 0, -0.3));
    j = r->joint = dJointCreateDHinge(world, 0);
    dJointAttach(j, r->body[0], 0);
    dJointSetDHingeAxis(j, 0, 1, 0);
    dJointSetDHingeAnchor1(j, p[0] + 0.3, p[1], p[2] - 0.3);
    dJointSetDHingeAnchor2(j, p[0], p[1], p[2]);
    r->kept[0] = dJointGetDHingeDistance(j);

    r = new_rig("transmission");   // gear 1 (motor) drives gear 2, twice its radius
    p = P[rig_count - 1];
    gear_body(r, 0, 0.15, at(p, -0.3, 0, 0));
    gear_body(r, 1, 0.30, at(p, 0.15, 0, 0));
    for (int k = 0; k < 2; k++) {
        j = dJointCreateHinge(world, 0);
        dJointAttach(j, r->body[k], 0);
        const dReal *c = dBodyGetPosition(r->body[k]);
        dJointSetHingeAnchor(j, c[0], c[1], c[2]);
        dJointSetHingeAxis(j, 0, 1, 0);
        if (k == 0) r->extra = j;
    }
    j = r->joint = dJointCreateTransmission(world, 0);
    dJointAttach(j, r->body[0], r->body[1]);
    dJointSetTransmissionMode(j, dTransmissionParallelAxes);
    dJointSetTransmissionAxis(j, 0, 1, 0);
    dJointSetTransmissionAnchor1(j, p[0] - 0.3, p[1], p[2]);
    dJointSetTransmissionAnchor2(j, p[0] + 0.15, p[1], p[2]);
    dJointSetTransmissionRatio(j, 0.5);   // radius 1 over radius 2
}

// Set every motor to turn or slide at sign * speed.
static void drive(void)
{
    const dReal v = sign * speed;
    for (int i = 0; i < rig_count; i++) {
        rig *r = &rigs[i];
        dJointID j = r->joint;
        switch (dJointGetType(j)) {
        case dJointTypeHinge:
            dJointSetHingeParam(j, dParamVel, v);
            dJointSetHingeParam(j, dParamFMax, fmax_);
            break;
        case dJointTypeSlider:
            dJointSetSliderParam(j, dParamVel, v);
            dJointSetSliderParam(j, dParamFMax, fmax_);
            break;
        case dJointTypeUniversal:
            dJointSetUniversalParam(j, dParamVel, v);
            dJointSetUniversalParam(j, dParamFMax, fmax_);
            break;
        case dJointTypeHinge2:
            dJointSetHinge2Param(j, dParamVel, v);
            dJointSetHinge2Param(j, dParamFMax, fmax_);
            dJointSetHinge2Param(j, dParamVel2, 4 * v);
            dJointSetHinge2Param(j, dParamFMax2, fmax_);
            break;
        case dJointTypeFixed:
        case dJointTypeTransmission:   // their arm or first gear turns
            dJointSetHingeParam(r->extra, dParamVel, v);
            dJointSetHingeParam(r->extra, dParamFMax, fmax_);
            break;
        case dJointTypeAMotor:
            dJointSetAMotorParam(j, dParamVel, v);
            dJointSetAMotorParam(j, dParamFMax, fmax_);
            break;
        case dJointTypeLMotor:
            dJointSetLMotorParam(j, dParamVel3, v / 4);
            break;
        case dJointTypePR:
            dJointSetPRParam(j, dParamVel, v / 2);
            dJointSetPRParam(j, dParamFMax, fmax_);
            dJointSetPRParam(j, dParamVel2, v);
            dJointSetPRParam(j, dParamFMax2, fmax_);
            break;
        case dJointTypePU:
            dJointSetPUParam(j, dParamVel3, v / 2);
            dJointSetPUParam(j, dParamFMax3, fmax_);
            break;
        case dJointTypePiston:
            dJointSetPistonParam(j, dParamVel, v / 2);
            dJointSetPistonParam(j, dParamFMax, fmax_);
            dJointSetPistonParam(j, dParamVel2, v);
            dJointSetPistonParam(j, dParamFMax2, fmax_);
            break;
        case dJointTypePlane2D:
            dJointSetPlane2DXParam(j, dParamVel, v / 4);
            dJointSetPlane2DAngleParam(j, dParamVel, v);
            break;
        default:
            break;
        }
    }
}

static void flip(void)
{
    sign = -sign;
    flipped_at = steps;
}

static void start(void)
{
    static const float xyz[3] = { 0.0f, -8.0f, 3.6f };
    static const float hpr[3] = { 90.0f, -14.0f, 0.0f };
    dsSetViewpoint(xyz, hpr);
    exu_keys("joints", "  m: reverse the motors (they also reverse every 3 s)\n");
    printf("  rigs, left to right, front row then back row:");
    for (int i = 0; i < rig_count; i++) printf("%s %s", i ? "," : "", rigs[i].name);
    printf("\n");
}

static void command(int key)
{
    if (key == 'm') flip();
}

static int check_rigs(int verbose, int *checked);

static void step(int pause)
{
    if (!pause) {
        if (steps > 0 && steps % FLIP_STEPS == 0) {
            period_failed += check_rigs(0, &period_checked);
            flip();
        }
        drive();
        dWorldStep(world, EXU_DT);
        steps++;
    }
    dsSetTexture(DS_WOOD);
    for (int i = 0; i < rig_count; i++) {
        static const dReal identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
        dsSetColor(0.4f, 0.4f, 0.45f);
        dsDrawSphere(P[i], identity, 0.04f);   // the rig's base point
        dsSetColor(0.2f + 0.05f * (float)(i % 8), 0.5f, 0.9f - 0.05f * (float)(i % 8));
        for (int k = 0; k < 2; k++)
            if (rigs[i].geom[k]) exu_draw_geom(rigs[i].geom[k]);
    }
}

static dReal distance(const dReal *a, const dReal *b)
{
    const dReal d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    return (dReal)sqrt((double)(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
}

// Fill value, target and tolerance with the joint's promise. Returns 0 when
// the motors reversed too recently for a motor's promise to be checked.
static int measure(rig *r, int settled)
{
    dJointID j = r->joint;
    const dReal hi_or_lo = sign > 0 ? 1 : -1;
    dVector3 a, b;
    r->tolerance = 0.02;
    switch (dJointGetType(j)) {
    case dJointTypeBall:
        dJointGetBallAnchor(j, a);
        dJointGetBallAnchor2(j, b);
        r->value = distance(a, b);
        r->target = 0;
        r->tolerance = 0.01;
        return 1;
    case dJointTypeHinge:   // the motor holds the arm at the stop it drives to
        r->value = dJointGetHingeAngle(j);
        r->target = hi_or_lo * 0.7;
        return settled;
    case dJointTypeSlider:
        r->value = dJointGetSliderPosition(j);
        r->target = hi_or_lo * 0.3;
        return settled;
    case dJointTypeUniversal:
        r->value = dJointGetUniversalAngle1(j);
        r->target = hi_or_lo * 0.6;
        return settled;
    case dJointTypeHinge2:   // the wheel spins at its motor's rate
        r->value = dJointGetHinge2Angle2Rate(j);
        r->target = 4 * sign * speed;
        r->tolerance = 0.05;
        return settled;
    case dJointTypeFixed:   // the box stays where it was on the arm
        dBodyGetPosRelPoint(r->body[0], dBodyGetPosition(r->body[1])[0],
                            dBodyGetPosition(r->body[1])[1], dBodyGetPosition(r->body[1])[2], a);
        r->value = distance(a, r->kept);
        r->target = 0;
        r->tolerance = 0.005;
        return 1;
    case dJointTypeAMotor:
        r->value = dBodyGetAngularVel(r->body[0])[2];
        r->target = sign * speed;
        return settled;
    case dJointTypeLMotor:
        r->value = dBodyGetLinearVel(r->body[0])[2];
        r->target = sign * speed / 4;
        return settled;
    case dJointTypePR:
        r->value = dJointGetPRPosition(j);
        r->target = hi_or_lo * 0.25;
        return settled;
    case dJointTypePU:
        r->value = dJointGetPUPosition(j);
        r->target = hi_or_lo * 0.25;
        return settled;
    case dJointTypePiston:
        r->value = dJointGetPistonPosition(j);
        r->target = hi_or_lo * 0.25;
        return settled;
    case dJointTypePlane2D:   // kept in its plane while driven along x
        r->value = dBodyGetPosition(r->body[0])[2];
        r->target = 0;
        r->tolerance = 0.005;
        return 1;
    case dJointTypeDBall:
        dJointGetDBallAnchor1(j, a);
        dJointGetDBallAnchor2(j, b);
        r->value = distance(a, b);
        r->target = r->kept[0];
        r->tolerance = 0.01;
        return 1;
    case dJointTypeDHinge:
        dJointGetDHingeAnchor1(j, a);
        dJointGetDHingeAnchor2(j, b);
        r->value = distance(a, b);
        r->target = r->kept[0];
        r->tolerance = 0.01;
        return 1;
    case dJointTypeTransmission: {   // gear 2 turns half as fast, the other way
        const dReal w1 = dBodyGetAngularVel(r->body[0])[1];
        const dReal w2 = dBodyGetAngularVel(r->body[1])[1];
        r->value = w2;
        r->target = -w1 / 2;
        r->tolerance = 0.02;
        return settled;
    }
    default:
        return 0;
    }
}

// Check every rig whose promise can be checked now; print each when verbose.
// Returns the number that failed, and adds to *checked the number checked.
static int check_rigs(int verbose, int *checked)
{
    const int settled = steps - flipped_at >= SETTLE_STEPS;
    int failed = 0;
    for (int i = 0; i < rig_count; i++) {
        rig *r = &rigs[i];
        if (!measure(r, settled)) continue;
        const int ok = fabs((double)(r->value - r->target)) <= (double)r->tolerance;
        if (verbose || !ok)
            printf("  %-14s %s: %+.4f, expected %+.4f +- %.3f (step %ld)\n", r->name,
                   ok ? "ok" : "FAILED", (double)r->value, (double)r->target,
                   (double)r->tolerance, steps);
        (*checked)++;
        failed += !ok;
    }
    return failed;
}

static int check(void)
{
    for (int i = 0; i < rig_count; i++)
        for (int k = 0; k < 2; k++)
            if (rigs[i].body[k] && !exu_body_finite(rigs[i].body[k]))
                return exu_report("joints", 0, "%s: state not finite", rigs[i].name);
    int checked = 0;
    const int failed = check_rigs(1, &checked);
    return exu_report("joints", failed + period_failed == 0,
                      "%d rig checks now and %d before each reversal of the motors (stops "
                      "held, motor speeds reached, distances and poses kept), %d failed",
                      checked, period_checked, failed + period_failed);
}

int main(int argc, char **argv)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetAutoDisableFlag(world, 0);
    build();

    dsFunctions fn = { DS_VERSION, start, step, command, NULL, NULL };
    dsSimulationLoop(argc, argv, DS_SIMULATION_DEFAULT_WIDTH, DS_SIMULATION_DEFAULT_HEIGHT, &fn);

    const int rc = check();
    for (int i = 0; i < rig_count; i++)
        for (int k = 0; k < 2; k++)
            if (rigs[i].geom[k]) dGeomDestroy(rigs[i].geom[k]);
    dWorldDestroy(world);
    dCloseODE();
    return rc;
}
