// SPDX-License-Identifier: BSD-3-Clause
//
// diff_export_dif.c -- dWorldExportDIF on one scene: a world with bodies of
// every flag, geoms of every class ODE writes, and every joint type of both
// libraries, each moved away from its rest pose along its own freedoms so
// that angles and positions are not zero, attached to two bodies, to one
// (b, 0) and as (0, b), and contact joints with several surface modes. The
// DIF text is turned into lines for compare.py: one per text line, named by
// the line with its numbers taken out (so the layout must match exactly),
// its numbers as the values.

#include "diff_print.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#define NUM_BODIES 36

// Turn a rotation about a world axis through a world point into a body move.
static void turn_body(dBodyID b, const dReal *point, const dReal *axis, dReal angle)
{
    dMatrix3 R, Rn;
    dRFromAxisAndAngle(R, axis[0], axis[1], axis[2], angle);
    dMultiply0(Rn, R, dBodyGetRotation(b), 3, 3, 3);
    for (int i = 0; i < 3; i++) Rn[i * 4 + 3] = 0;
    dVector3 d, nd;
    const dReal *p = dBodyGetPosition(b);
    for (int i = 0; i < 3; i++) d[i] = p[i] - point[i];
    dMultiply0_331(nd, R, d);
    dBodySetRotation(b, Rn);
    dBodySetPosition(b, point[0] + nd[0], point[1] + nd[1], point[2] + nd[2]);
}

static dBodyID make_body(dWorldID w, dReal x, dReal y, dReal z, dReal angle)
{
    dBodyID b = dBodyCreate(w);
    dBodySetPosition(b, x, y, z);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0.3 + x, 1, 0.2 * y, angle);
    dBodySetRotation(b, R);
    dMass m;
    dMassSetBox(&m, 1.5, 0.4 + 0.1 * x, 0.5, 0.7);
    dBodySetMass(b, &m);
    dBodySetLinearVel(b, 0.1 * x, -0.2, 0.3);
    dBodySetAngularVel(b, 0.5, 0.1 * y, -0.25);
    return b;
}

static void set_limot(dJointID j, void (*set)(dJointID, int, dReal), int group, dReal k)
{
    const int g = group * dParamGroup;
    set(j, g + dParamLoStop, -0.5 * k);
    set(j, g + dParamHiStop, 0.75 * k);
    set(j, g + dParamVel, 1.25 * k);
    set(j, g + dParamFMax, 3 * k);
    set(j, g + dParamFudgeFactor, 0.5);
    set(j, g + dParamBounce, 0.25 * k);
    set(j, g + dParamCFM, 1e-5 * k);
    set(j, g + dParamStopERP, 0.4);
    set(j, g + dParamStopCFM, 2e-5 * k);
}

// Move body b by d along world direction dir.
static void slide_body(dBodyID b, const dReal *dir, dReal d)
{
    const dReal *p = dBodyGetPosition(b);
    dBodySetPosition(b, p[0] + d * dir[0], p[1] + d * dir[1], p[2] + d * dir[2]);
}

// A PR joint attached as (b1, b2): body 1 slid along the slide axis, and the
// body turning about the rotation axis at the anchor (the one attached
// second, or b1 alone) turned.
static void add_pr(dWorldID w, dBodyID b1, dBodyID b2, dReal x, dReal k)
{
    dJointID j = dJointCreatePR(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetPRAnchor(j, x, 0.4, 3.1);
    dJointSetPRAxis1(j, 0, 0.6, 0.8);
    dJointSetPRAxis2(j, 1, 0, 0);
    set_limot(j, dJointSetPRParam, 0, fabs(k));
    set_limot(j, dJointSetPRParam, 1, 2 * fabs(k));
    dVector3 a, axp, axr;
    dJointGetPRAnchor(j, a);
    dJointGetPRAxis1(j, axp);
    dJointGetPRAxis2(j, axr);
    dBodyID slider = b1 ? b1 : b2;
    slide_body(slider, axp, 0.2 * k);
    turn_body(b1 && b2 ? b2 : slider, a, axr, 0.3 * k);
}

// A PU joint attached as (b1, b2), turned about both axes at the anchor, then
// slid along axis P (taken before the turns: attached as (0, b), the two
// libraries report axis P differently once b turned).
static void add_pu(dWorldID w, dBodyID b1, dBodyID b2, dReal x, dReal k)
{
    dJointID j = dJointCreatePU(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetPUAnchor(j, x, 0.2, 2.9);
    dJointSetPUAxis1(j, 1, 0, 0);
    dJointSetPUAxis2(j, 0, 0.6, 0.8);
    dJointSetPUAxisP(j, 0.8, 0, 0.6);
    set_limot(j, dJointSetPUParam, 0, fabs(k));
    set_limot(j, dJointSetPUParam, 1, 2 * fabs(k));
    set_limot(j, dJointSetPUParam, 2, 3 * fabs(k));
    dVector3 a, ax1, ax2, axp;
    dJointGetPUAnchor(j, a);
    dJointGetPUAxis1(j, ax1);
    dJointGetPUAxis2(j, ax2);
    dJointGetPUAxisP(j, axp);
    // Axis 1 is fixed to body 1, axis 2 to body 2: turn each body about its own.
    if (b2) turn_body(b2, a, ax2, -0.25 * k);
    else turn_body(b1, a, ax2, -0.25 * k);
    if (b1) {
        dJointGetPUAxis1(j, ax1);
        turn_body(b1, a, ax1, 0.15 * k);
        dJointGetPUAxisP(j, axp);
        slide_body(b1, axp, 0.35 * k);
    } else {
        dJointGetPUAxis1(j, ax1);
        turn_body(b2, a, ax1, 0.15 * k);
        slide_body(b2, axp, -0.35 * k);
    }
}

// A piston attached as (b1, b2): each body moved along and about the axis.
static void add_piston(dWorldID w, dBodyID b1, dBodyID b2, dReal x, dReal k)
{
    dJointID j = dJointCreatePiston(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetPistonAnchor(j, x, 0.1, 2.6);
    dJointSetPistonAxis(j, 0.48, 0.6, 0.64);
    set_limot(j, dJointSetPistonParam, 0, fabs(k));
    set_limot(j, dJointSetPistonParam, 1, 2 * fabs(k));
    dVector3 a, ax;
    dJointGetPistonAnchor(j, a);
    dJointGetPistonAxis(j, ax);
    if (b1) {
        turn_body(b1, a, ax, 0.4 * k);
        slide_body(b1, ax, 0.3 * k);
    }
    if (b2) {
        turn_body(b2, a, ax, -0.2 * k);
        slide_body(b2, ax, -0.1 * k);
    }
}

// A linear motor attached as (b1, b2) with its three axes in the frames rel
// names (set after the bodies' last moves: ODE and this library fix a rel 1
// axis of a (0, b) motor, and a rel 2 axis of a (b, 0) one, to different
// frames, which agree until b turns).
static void add_lmotor(dWorldID w, dBodyID b1, dBodyID b2, int rel0, int rel1, int rel2, dReal k)
{
    dJointID j = dJointCreateLMotor(w, 0);
    dJointAttach(j, b1, b2);
    dJointSetLMotorNumAxes(j, rel2 ? 3 : 2);
    dJointSetLMotorAxis(j, 0, rel0, 1, 0.5, 0);
    dJointSetLMotorAxis(j, 1, rel1, 0, 1, 2);
    dJointSetLMotorAxis(j, 2, rel2, 0.3, -0.4, 0.5);
    for (int i = 0; i < 3; i++) set_limot(j, dJointSetLMotorParam, i, k + i);
}

// A contact between b1 and b2 with surface mode `mode`, every coefficient set.
static void add_contact(dWorldID w, dBodyID b1, dBodyID b2, int mode, dReal k)
{
    dContact c;
    memset(&c, 0, sizeof c);
    c.geom.pos[0] = k;
    c.geom.pos[1] = -0.5;
    c.geom.pos[2] = 0.25 * k;
    c.geom.normal[0] = 0.6;
    c.geom.normal[2] = 0.8;
    c.geom.depth = 0.01 * k;
    c.surface.mode = mode;
    c.surface.mu = k == 4 ? dInfinity : 0.5 * k;
    c.surface.mu2 = 0.25 * k;
    c.surface.rho = 0.01;
    c.surface.rho2 = 0.02;
    c.surface.rhoN = 0.03;
    c.surface.bounce = 0.1 * k;
    c.surface.bounce_vel = 0.05;
    c.surface.soft_erp = 0.3;
    c.surface.soft_cfm = 1e-4 * k;
    c.surface.motion1 = 0.5;
    c.surface.motion2 = -0.5 * k;
    c.surface.motionN = 0.125;
    c.surface.slip1 = 0.001 * k;
    c.surface.slip2 = 0.002;
    c.fdir1[0] = 0;
    c.fdir1[1] = 1;
    c.fdir1[2] = 0;
    dJointAttach(dJointCreateContact(w, 0, &c), b1, b2);
}

static void build_scene(dWorldID w, dSpaceID space)
{
    dWorldSetGravity(w, 0, 0, -9.81);
    dWorldSetERP(w, 0.3);
    dWorldSetCFM(w, 1e-6);
    dWorldSetAutoDisableLinearThreshold(w, 0.02);
    dWorldSetAutoDisableAngularThreshold(w, 0.03);
    dWorldSetAutoDisableSteps(w, 12);
    dWorldSetAutoDisableTime(w, 0.5);
    dWorldSetAutoDisableAverageSamplesCount(w, 3);

    dBodyID b[NUM_BODIES];
    for (int i = 0; i < NUM_BODIES; i++)
        b[i] = make_body(w, 0.5 * i, 0.25 * (i % 3), 1 + 0.1 * i, 0.2 * i);
    dBodySetFiniteRotationMode(b[1], 1);
    dBodySetFiniteRotationAxis(b[1], 0.6, 0.8, 0.5);
    dBodyDisable(b[2]);
    dBodySetGravityMode(b[3], 0);
    dBodySetAutoDisableFlag(b[4], 1);
    dBodyAddForce(b[5], 1, 2, 3);
    dBodyAddTorque(b[5], -1, 0.5, 4);

    dGeomID s = dCreateSphere(space, 0.5);
    dGeomSetBody(s, b[0]);
    dGeomID bx = dCreateBox(space, 1, 2, 3);
    dGeomSetBody(bx, b[0]);
    dGeomSetCategoryBits(bx, 6);
    dGeomSetCollideBits(bx, 5);
    dGeomID c = dCreateCapsule(space, 0.25, 1.5);
    dGeomSetBody(c, b[1]);
    dGeomDisable(c);
    dGeomID cy = dCreateCylinder(space, 0.3, 0.9);
    dGeomSetBody(cy, b[2]);
    dGeomID r = dCreateRay(space, 2.5);
    dGeomSetBody(r, b[3]);

    const dReal x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 }, z[3] = { 0, 0, 1 };
    dVector3 a;

    dJointID ball = dJointCreateBall(w, 0);
    dJointAttach(ball, b[0], b[1]);
    dJointSetBallAnchor(ball, 0.2, 0.3, 1.1);

    dJointID ball_rev = dJointCreateBall(w, 0);
    dJointAttach(ball_rev, 0, b[12]);
    dJointSetBallAnchor(ball_rev, 3.1, 0.2, 1.7);

    dJointID hinge = dJointCreateHinge(w, 0);
    dJointAttach(hinge, b[1], b[2]);
    dJointSetHingeAnchor(hinge, 0.7, 0.2, 1.2);
    dJointSetHingeAxis(hinge, 0.3, 0.4, 0.8);
    set_limot(hinge, dJointSetHingeParam, 0, 1);
    dJointGetHingeAnchor(hinge, a);
    dVector3 ax;
    dJointGetHingeAxis(hinge, ax);
    turn_body(b[2], a, ax, 0.35);

    dJointID slider = dJointCreateSlider(w, 0);
    dJointAttach(slider, b[3], b[4]);
    dJointSetSliderAxis(slider, 0.2, -0.5, 0.9);
    set_limot(slider, dJointSetSliderParam, 0, 2);
    dJointGetSliderAxis(slider, ax);
    const dReal *p4 = dBodyGetPosition(b[4]);
    dBodySetPosition(b[4], p4[0] - 0.3 * ax[0], p4[1] - 0.3 * ax[1], p4[2] - 0.3 * ax[2]);

    dJointID slider1 = dJointCreateSlider(w, 0);
    dJointAttach(slider1, b[7], 0);
    dJointSetSliderAxis(slider1, 0, 0.6, 0.8);

    dJointID uni = dJointCreateUniversal(w, 0);
    dJointAttach(uni, b[13], b[14]);
    dJointSetUniversalAnchor(uni, 2.2, 0.3, 1.5);
    dJointSetUniversalAxis1(uni, x[0], x[1], x[2]);
    dJointSetUniversalAxis2(uni, y[0], y[1], y[2]);
    set_limot(uni, dJointSetUniversalParam, 0, 1);
    set_limot(uni, dJointSetUniversalParam, 1, 3);
    dJointGetUniversalAnchor(uni, a);
    dVector3 ax1, ax2;
    dJointGetUniversalAxis1(uni, ax1);
    dJointGetUniversalAxis2(uni, ax2);
    turn_body(b[13], a, ax1, 0.2);
    turn_body(b[14], a, ax2, -0.3);

    dJointID h2 = dJointCreateHinge2(w, 0);
    dJointAttach(h2, b[6], b[15]);
    dJointSetHinge2Anchor(h2, 3.3, 0.1, 1.6);
    dJointSetHinge2Axes(h2, z, y);
    dJointSetHinge2Param(h2, dParamSuspensionERP, 0.35);
    dJointSetHinge2Param(h2, dParamSuspensionCFM, 0.002);
    set_limot(h2, dJointSetHinge2Param, 0, 1);
    set_limot(h2, dJointSetHinge2Param, 1, 2);
    dJointGetHinge2Anchor(h2, a);
    dJointGetHinge2Axis1(h2, ax1);
    turn_body(b[15], a, ax1, 0.25);

    dJointID fixed = dJointCreateFixed(w, 0);
    dJointAttach(fixed, b[8], b[9]);
    dJointSetFixed(fixed);
    dJointID fixed1 = dJointCreateFixed(w, 0);
    dJointAttach(fixed1, b[10], 0);
    dJointSetFixed(fixed1);

    dJointID null = dJointCreateNull(w, 0);
    dJointAttach(null, b[8], b[10]);

    dJointID am = dJointCreateAMotor(w, 0);
    dJointAttach(am, b[9], b[11]);
    dJointSetAMotorNumAxes(am, 3);
    dJointSetAMotorAxis(am, 0, 0, 1, 0, 0);
    dJointSetAMotorAxis(am, 1, 1, 0, 0.6, 0.8);
    dJointSetAMotorAxis(am, 2, 2, 0, 0, 1);
    dJointSetAMotorAngle(am, 0, 0.1);
    dJointSetAMotorAngle(am, 1, -0.2);
    dJointSetAMotorAngle(am, 2, 0.3);
    for (int i = 0; i < 3; i++) set_limot(am, dJointSetAMotorParam, i, 1 + i);

    dJointID am2 = dJointCreateAMotor(w, 0);
    dJointAttach(am2, b[11], 0);
    dJointSetAMotorNumAxes(am2, 1);
    dJointSetAMotorAxis(am2, 0, 1, 0, 0, 1);

    // Attached as (0, b): kept as (b, 0), the getters keep the user's sense.
    dJointID hinge_rev = dJointCreateHinge(w, 0);
    dJointAttach(hinge_rev, 0, b[16]);
    dJointSetHingeAnchor(hinge_rev, 8.1, 0.3, 2.5);
    dJointSetHingeAxis(hinge_rev, 0.6, 0, 0.8);
    dJointGetHingeAxis(hinge_rev, ax);
    dJointGetHingeAnchor(hinge_rev, a);
    turn_body(b[16], a, ax, -0.4);

    dJointID slider_rev = dJointCreateSlider(w, 0);
    dJointAttach(slider_rev, 0, b[17]);
    dJointSetSliderAxis(slider_rev, 0.6, 0.8, 0);
    const dReal *p17 = dBodyGetPosition(b[17]);
    dBodySetPosition(b[17], p17[0] + 0.12, p17[1] + 0.16, p17[2]);

    dJointID uni_rev = dJointCreateUniversal(w, 0);
    dJointAttach(uni_rev, 0, b[18]);
    dJointSetUniversalAnchor(uni_rev, 9, 0.5, 2.7);
    dJointSetUniversalAxis1(uni_rev, 0, 0.6, 0.8);
    dJointSetUniversalAxis2(uni_rev, 1, 0, 0);
    dJointGetUniversalAnchor(uni_rev, a);
    dJointGetUniversalAxis2(uni_rev, ax2);
    turn_body(b[18], a, ax2, 0.3);
    dJointGetUniversalAxis1(uni_rev, ax1);
    turn_body(b[18], a, ax1, 0.2);

    dJointID fixed_rev = dJointCreateFixed(w, 0);
    dJointAttach(fixed_rev, 0, b[19]);
    dJointSetFixed(fixed_rev);

    dJointID am_rev = dJointCreateAMotor(w, 0);
    dJointAttach(am_rev, 0, b[19]);
    dJointSetAMotorNumAxes(am_rev, 2);
    dJointSetAMotorAxis(am_rev, 0, 2, 0, 0.6, 0.8);
    dJointSetAMotorAxis(am_rev, 1, 0, 1, 0, 0);

    // ODE 0.16's PR, PU, piston and linear motor: attached to two bodies, to
    // one, and as (0, b).
    add_pr(w, b[20], b[21], 10.2, 1);
    add_pr(w, b[22], 0, 11.1, -1.5);
    add_pr(w, 0, b[23], 11.6, 0.5);
    add_pu(w, b[24], b[25], 12.1, 1);
    add_pu(w, b[26], 0, 13.1, -0.5);
    add_pu(w, 0, b[27], 13.7, 1.5);
    add_piston(w, b[28], b[29], 14.2, 1);
    add_piston(w, b[30], 0, 15.3, 0.5);
    add_piston(w, 0, b[31], 15.8, -1);
    add_lmotor(w, b[20], b[21], 0, 1, 2, 1);
    add_lmotor(w, b[22], 0, 2, 1, 0, 2);
    add_lmotor(w, 0, b[23], 1, 2, 0, 3);
    add_lmotor(w, b[32], b[33], 2, 0, 0, 4);   // two axes

    // Contacts: no mode, then every coefficient ODE writes, on two bodies,
    // one body and as (0, b).
    add_contact(w, b[34], b[35], 0, 1);
    add_contact(w, b[34], b[35],
                dContactMu2 | dContactBounce | dContactSoftERP | dContactSoftCFM | dContactApprox1,
                2);
    add_contact(w, b[34], 0,
                dContactMotion1 | dContactMotion2 | dContactSlip1 | dContactSlip2 |
                    dContactFDir1 | dContactApprox1_2,
                3);
    add_contact(w, 0, b[35], dContactApprox1_1 | dContactRolling | dContactMotionN | dContactFDir1,
                4);

    dJointCreateBall(w, 0);   // attached to nothing
}

// Print one DIF text line as "L<n>:<line without numbers> tol numbers".
static void emit_line(int n, const char *line)
{
    char shape[512];
    double vals[64];
    int ns = 0, nv = 0;
    const char *s = line;
    while (*s && ns < (int)sizeof shape - 2) {
        const int starts_number =
            (isdigit((unsigned char)*s) || ((*s == '-' || *s == '.') && s[1] &&
                                            (isdigit((unsigned char)s[1]) || s[1] == 'i')) ||
             strncmp(s, "inf", 3) == 0) &&
            (s == line || !(isalnum((unsigned char)s[-1]) || s[-1] == '_'));
        if (starts_number && nv < 64) {
            char *end;
            vals[nv++] = strtod(s, &end);
            shape[ns++] = '#';
            s = end;
        } else {
            shape[ns++] = (*s == ' ' || *s == '\t') ? '_' : *s;
            s++;
        }
    }
    shape[ns] = 0;
    printf("L%d:%s 1e-12", n, shape);
    for (int i = 0; i < nv; i++) printf(" %.17g", vals[i]);
    printf("\n");
}

int main(void)
{
    dInitODE();
    dWorldID w = dWorldCreate();
    dSpaceID space = dSimpleSpaceCreate(0);   // holds the geoms, destroys them
    build_scene(w, space);
    FILE *f = tmpfile();
    dWorldExportDIF(w, f, "sim_");
    rewind(f);
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = 0;
        emit_line(++n, line);
    }
    fclose(f);
    dWorldDestroy(w);
    dSpaceDestroy(space);
    dCloseODE();
    return 0;
}
