// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_world.c -- a world built and stepped from the input: bodies with
// random masses, poses and velocities, joints of every type attached at
// random with random anchors, axes, parameters and limits, contact joints
// with random surfaces, and steps by dWorldStep, dWorldQuickStep and
// dWorldStepFast1 between operations that destroy, disable, push and make
// kinematic. Values are sane (bounded masses, velocities, ERP and CFM in
// [0, 1], ...) except where a "poke" hands a setter a special value
// (NaN, infinite, huge, zero), which the library must refuse or survive.
// Checked: no crash or sanitizer report; after each step, when no special
// value was accepted, every body's state is finite.

#include "fuzz_input.h"

#include <string.h>

#define MAX_BODIES 8
#define MAX_JOINTS 12

typedef struct scene {
    dWorldID world;
    dJointGroupID contacts;
    dBodyID bodies[MAX_BODIES];
    dJointID joints[MAX_JOINTS];
    fz_input *in;
} scene;

// A sane vector of components in [-s, s].
static void sane3(fz_input *in, dReal s, dReal *v)
{
    for (int i = 0; i < 3; i++) v[i] = fz_range(in, -s, s);
}

// A body of the scene or 0 (the static environment).
static dBodyID any_body(scene *sc)
{
    unsigned k = fz_pick(sc->in, MAX_BODIES + 1);
    return k < MAX_BODIES ? sc->bodies[k] : 0;
}

static void make_body(scene *sc, int k)
{
    fz_input *in = sc->in;
    dBodyID b = dBodyCreate(sc->world);
    dMass m;
    dReal total = fz_range(in, (dReal)0.05, 20);
    switch (fz_pick(in, 3)) {
    case 0: dMassSetSphereTotal(&m, total, fz_range(in, (dReal)0.05, 2)); break;
    case 1:
        dMassSetBoxTotal(&m, total, fz_range(in, (dReal)0.05, 2), fz_range(in, (dReal)0.05, 2),
                         fz_range(in, (dReal)0.05, 2));
        break;
    default:
        dMassSetCapsuleTotal(&m, total, 1 + (int)fz_pick(in, 3), fz_range(in, (dReal)0.05, 1),
                             fz_range(in, (dReal)0.05, 2));
        break;
    }
    dBodySetMass(b, &m);
    dVector3 v;
    sane3(in, 5, v);
    dBodySetPosition(b, v[0], v[1], v[2]);
    dQuaternion q = {fz_range(in, -1, 1), fz_range(in, -1, 1), fz_range(in, -1, 1),
                     fz_range(in, -1, 1)};
    if (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > (dReal)0.01) {
        dNormalize4(q);
        dBodySetQuaternion(b, q);
    }
    sane3(in, 5, v);
    dBodySetLinearVel(b, v[0], v[1], v[2]);
    sane3(in, 5, v);
    dBodySetAngularVel(b, v[0], v[1], v[2]);
    uint8_t f = fz_u8(in);
    if (f & 1) dBodySetGravityMode(b, 0);
    if (f & 2) dBodySetFiniteRotationMode(b, 1);
    if (f & 4) dBodySetAutoDisableFlag(b, 1);
    if (f & 8) dBodySetLinearDamping(b, fz_range(in, 0, 1));
    if (f & 16) dBodySetMaxAngularSpeed(b, fz_range(in, 0, 50));
    sc->bodies[k] = b;
}

// A sane value for joint parameter p (its group stripped).
static dReal param_value(fz_input *in, int p)
{
    switch (p % dParamGroup) {
    case dParamLoStop: case dParamHiStop: return fz_range(in, -4, 4);
    case dParamVel: case dParamLoVel: case dParamHiVel: return fz_range(in, -10, 10);
    case dParamFMax: return fz_range(in, 0, 50);
    case dParamFudgeFactor: case dParamBounce: return fz_range(in, 0, 1);
    case dParamCFM: case dParamStopCFM: case dParamSuspensionCFM: return fz_range(in, 0, 1);
    default: return fz_range(in, 0, 1);   // the ERPs
    }
}

typedef void param_setter(dJointID, int, dReal);

// The joint's parameter setter (none for the ball, fixed-less types return 0).
static param_setter *setter_of(int type)
{
    switch (type) {
    case dJointTypeBall: return dJointSetBallParam;
    case dJointTypeHinge: return dJointSetHingeParam;
    case dJointTypeSlider: return dJointSetSliderParam;
    case dJointTypeUniversal: return dJointSetUniversalParam;
    case dJointTypeHinge2: return dJointSetHinge2Param;
    case dJointTypeFixed: return dJointSetFixedParam;
    case dJointTypeAMotor: return dJointSetAMotorParam;
    case dJointTypeLMotor: return dJointSetLMotorParam;
    case dJointTypePR: return dJointSetPRParam;
    case dJointTypePU: return dJointSetPUParam;
    case dJointTypePiston: return dJointSetPistonParam;
    case dJointTypeDBall: return dJointSetDBallParam;
    case dJointTypeDHinge: return dJointSetDHingeParam;
    case dJointTypeTransmission: return dJointSetTransmissionParam;
    case dJointTypePlane2D: return dJointSetPlane2DXParam;
    default: return 0;
    }
}

// Anchors and axes of joint j from the input (v: a vector for each setter).
static void shape_joint(fz_input *in, dJointID j, int type)
{
    dVector3 a, x, y;
    sane3(in, 5, a);
    sane3(in, 1, x);
    sane3(in, 1, y);
    switch (type) {
    case dJointTypeBall: dJointSetBallAnchor(j, a[0], a[1], a[2]); break;
    case dJointTypeHinge:
        dJointSetHingeAnchor(j, a[0], a[1], a[2]);
        dJointSetHingeAxis(j, x[0], x[1], x[2]);
        break;
    case dJointTypeSlider: dJointSetSliderAxis(j, x[0], x[1], x[2]); break;
    case dJointTypeUniversal:
        dJointSetUniversalAnchor(j, a[0], a[1], a[2]);
        dJointSetUniversalAxis1(j, x[0], x[1], x[2]);
        dJointSetUniversalAxis2(j, y[0], y[1], y[2]);
        break;
    case dJointTypeHinge2:
        dJointSetHinge2Anchor(j, a[0], a[1], a[2]);
        dJointSetHinge2Axes(j, x, y);
        break;
    case dJointTypeFixed: dJointSetFixed(j); break;
    case dJointTypeAMotor: {
        int n = (int)fz_pick(in, 4);
        dJointSetAMotorMode(j, fz_u8(in) & 1 ? dAMotorEuler : dAMotorUser);
        dJointSetAMotorNumAxes(j, n);
        dJointSetAMotorAxis(j, 0, (int)fz_pick(in, 3), x[0], x[1], x[2]);
        dJointSetAMotorAxis(j, 2, (int)fz_pick(in, 3), y[0], y[1], y[2]);
        dJointSetAMotorAngle(j, (int)fz_pick(in, 3), fz_range(in, -3, 3));
        break;
    }
    case dJointTypeLMotor:
        dJointSetLMotorNumAxes(j, (int)fz_pick(in, 4));
        dJointSetLMotorAxis(j, 0, (int)fz_pick(in, 3), x[0], x[1], x[2]);
        dJointSetLMotorAxis(j, 1, (int)fz_pick(in, 3), y[0], y[1], y[2]);
        break;
    case dJointTypePR:
        dJointSetPRAnchor(j, a[0], a[1], a[2]);
        dJointSetPRAxis1(j, x[0], x[1], x[2]);
        dJointSetPRAxis2(j, y[0], y[1], y[2]);
        break;
    case dJointTypePU:
        dJointSetPUAnchor(j, a[0], a[1], a[2]);
        dJointSetPUAxis1(j, x[0], x[1], x[2]);
        dJointSetPUAxis2(j, y[0], y[1], y[2]);
        dJointSetPUAxisP(j, y[1], y[2], y[0]);
        break;
    case dJointTypePiston:
        dJointSetPistonAnchor(j, a[0], a[1], a[2]);
        dJointSetPistonAxis(j, x[0], x[1], x[2]);
        break;
    case dJointTypeDBall:
        dJointSetDBallAnchor1(j, a[0], a[1], a[2]);
        dJointSetDBallAnchor2(j, y[0], y[1], y[2]);
        if (fz_u8(in) & 1) dJointSetDBallDistance(j, fz_range(in, 0, 3));
        break;
    case dJointTypeDHinge:
        dJointSetDHingeAxis(j, x[0], x[1], x[2]);
        dJointSetDHingeAnchor1(j, a[0], a[1], a[2]);
        dJointSetDHingeAnchor2(j, y[0], y[1], y[2]);
        break;
    case dJointTypeTransmission:
        dJointSetTransmissionMode(j, (int)fz_pick(in, 3));
        dJointSetTransmissionAxis1(j, x[0], x[1], x[2]);
        dJointSetTransmissionAxis2(j, y[0], y[1], y[2]);
        dJointSetTransmissionAnchor1(j, a[0], a[1], a[2]);
        dJointSetTransmissionAnchor2(j, y[2], a[1], x[0]);
        dJointSetTransmissionRatio(j, fz_range(in, (dReal)0.1, 4));
        dJointSetTransmissionRadius1(j, fz_range(in, (dReal)0.1, 2));
        dJointSetTransmissionRadius2(j, fz_range(in, (dReal)0.1, 2));
        dJointSetTransmissionBacklash(j, fz_range(in, 0, (dReal)0.2));
        break;
    default: break;
    }
}

static dJointID create_joint(dWorldID w, int type)
{
    switch (type) {
    case dJointTypeBall: return dJointCreateBall(w, 0);
    case dJointTypeHinge: return dJointCreateHinge(w, 0);
    case dJointTypeSlider: return dJointCreateSlider(w, 0);
    case dJointTypeUniversal: return dJointCreateUniversal(w, 0);
    case dJointTypeHinge2: return dJointCreateHinge2(w, 0);
    case dJointTypeFixed: return dJointCreateFixed(w, 0);
    case dJointTypeNull: return dJointCreateNull(w, 0);
    case dJointTypeAMotor: return dJointCreateAMotor(w, 0);
    case dJointTypeLMotor: return dJointCreateLMotor(w, 0);
    case dJointTypePlane2D: return dJointCreatePlane2D(w, 0);
    case dJointTypePR: return dJointCreatePR(w, 0);
    case dJointTypePU: return dJointCreatePU(w, 0);
    case dJointTypePiston: return dJointCreatePiston(w, 0);
    case dJointTypeDBall: return dJointCreateDBall(w, 0);
    case dJointTypeDHinge: return dJointCreateDHinge(w, 0);
    default: return dJointCreateTransmission(w, 0);
    }
}

static void make_joint(scene *sc, int k)
{
    fz_input *in = sc->in;
    static const int types[] = {
        dJointTypeBall, dJointTypeHinge, dJointTypeSlider, dJointTypeUniversal,
        dJointTypeHinge2, dJointTypeFixed, dJointTypeNull, dJointTypeAMotor,
        dJointTypeLMotor, dJointTypePlane2D, dJointTypePR, dJointTypePU,
        dJointTypePiston, dJointTypeDBall, dJointTypeDHinge, dJointTypeTransmission};
    int type = types[fz_pick(in, sizeof types / sizeof types[0])];
    dJointID j = create_joint(sc->world, type);
    if (!j) return;
    dBodyID b1 = any_body(sc), b2 = any_body(sc);
    dJointAttach(j, b1, b2);   // the same body twice must be refused
    shape_joint(in, j, type);
    param_setter *set = setter_of(type);
    for (int n = (int)fz_pick(in, 6); set && n > 0; n--) {
        int p = (int)fz_pick(in, dParamsInGroup) + dParamGroup * (int)fz_pick(in, 3);
        set(j, p, param_value(in, p));
    }
    sc->joints[k] = j;
}

// A contact joint in the group between two bodies (or a body and the
// environment) with a random surface.
static void make_contact(scene *sc)
{
    fz_input *in = sc->in;
    dContact c;
    memset(&c, 0, sizeof c);
    c.surface.mode = (int)(fz_u16(in) & 0x77ff);
    c.surface.mu = fz_u8(in) < 32 ? dInfinity : fz_range(in, 0, 2);
    c.surface.mu2 = fz_range(in, 0, 2);
    c.surface.rho = fz_range(in, 0, (dReal)0.1);
    c.surface.rho2 = fz_range(in, 0, (dReal)0.1);
    c.surface.rhoN = fz_range(in, 0, (dReal)0.1);
    c.surface.bounce = fz_range(in, 0, 1);
    c.surface.bounce_vel = fz_range(in, 0, 1);
    c.surface.soft_erp = fz_range(in, 0, 1);
    c.surface.soft_cfm = fz_range(in, 0, 1);
    c.surface.motion1 = fz_range(in, -1, 1);
    c.surface.motion2 = fz_range(in, -1, 1);
    c.surface.motionN = fz_range(in, -1, 1);
    c.surface.slip1 = fz_range(in, 0, (dReal)0.1);
    c.surface.slip2 = fz_range(in, 0, (dReal)0.1);
    sane3(in, 5, c.geom.pos);
    sane3(in, 1, c.geom.normal);
    if (dCalcVectorLength3(c.geom.normal) < (dReal)0.1) c.geom.normal[2] = 1;
    dNormalize3(c.geom.normal);
    c.geom.depth = fz_range(in, 0, (dReal)0.5);
    sane3(in, 1, c.fdir1);
    if (dCalcVectorLength3(c.fdir1) < (dReal)0.1) c.fdir1[0] = 1;
    dNormalize3(c.fdir1);
    dJointID j = dJointCreateContact(sc->world, sc->contacts, &c);
    if (j) dJointAttach(j, any_body(sc), any_body(sc));
}

// Hand a setter a value of fz_real (specials included).
static void poke(scene *sc)
{
    fz_input *in = sc->in;
    dBodyID b = sc->bodies[fz_pick(in, MAX_BODIES)];
    dJointID j = sc->joints[fz_pick(in, MAX_JOINTS)];
    dReal v = fz_real(in, 10);
    switch (fz_pick(in, 8)) {
    case 0: if (b) dBodySetPosition(b, v, 0, 0); break;
    case 1: if (b) dBodySetLinearVel(b, 0, v, 0); break;
    case 2: if (b) dBodyAddForce(b, v, 0, 0); break;
    case 3: if (b) dBodyAddTorque(b, 0, 0, v); break;
    case 4: dWorldSetCFM(sc->world, v); break;
    case 5: dWorldSetERP(sc->world, v); break;
    case 6:
        if (j && setter_of(dJointGetType(j)))
            setter_of(dJointGetType(j))(j, (int)fz_pick(in, dParamsInGroup), v);
        break;
    default: {
        dMass m;
        dMassSetSphereTotal(&m, v, 1);
        if (b) dBodySetMass(b, &m);
        break;
    }
    }
}

static int body_finite(dBodyID b)
{
    const dReal *p = dBodyGetPosition(b), *q = dBodyGetQuaternion(b);
    const dReal *v = dBodyGetLinearVel(b), *w = dBodyGetAngularVel(b);
    for (int i = 0; i < 3; i++)
        if (!isfinite(p[i]) || !isfinite(v[i]) || !isfinite(w[i])) return 0;
    for (int i = 0; i < 4; i++)
        if (!isfinite(q[i])) return 0;
    return 1;
}

static void step(scene *sc)
{
    fz_input *in = sc->in;
    dReal h = fz_u8(in) < 8 ? fz_real(in, (dReal)0.05) : fz_range(in, (dReal)1e-4, (dReal)0.05);
    const char *how;
    switch (fz_pick(in, 3)) {
    case 0: dWorldStep(sc->world, h); how = "dWorldStep"; break;
    case 1:
        dWorldSetQuickStepNumIterations(sc->world, 1 + (int)fz_pick(in, 40));
        dWorldQuickStep(sc->world, h);
        how = "dWorldQuickStep";
        break;
    default: dWorldStepFast1(sc->world, h, 1 + (int)fz_pick(in, 20)); how = "dWorldStepFast1"; break;
    }
    if (fz_u8(in) & 1) dJointGroupEmpty(sc->contacts);
    if (in->specials) return;
    for (int k = 0; k < MAX_BODIES; k++)
        if (sc->bodies[k] && !body_finite(sc->bodies[k]))
            fz_fail("%s (h = %g) left body %d not finite", how, (double)h, k);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        dInitODE2(0);
        fz_install_handlers();
        ready = 1;
    }
    fz_input in = {data, size, 0};
    scene sc;
    memset(&sc, 0, sizeof sc);
    sc.in = &in;
    sc.world = dWorldCreate();
    sc.contacts = dJointGroupCreate(0);
    dWorldSetGravity(sc.world, fz_range(&in, -10, 10), fz_range(&in, -10, 10),
                     fz_range(&in, -20, 0));
    dWorldSetERP(sc.world, fz_range(&in, 0, 1));
    dWorldSetCFM(sc.world, fz_range(&in, (dReal)1e-9, (dReal)1e-2));
    if (fz_u8(&in) & 1) dWorldSetAutoDisableFlag(sc.world, 1);
    for (int op = 0; op < 200 && in.left > 0; op++) {
        unsigned kb = fz_pick(&in, MAX_BODIES), kj = fz_pick(&in, MAX_JOINTS);
        switch (fz_pick(&in, 12)) {
        case 0: case 1:
            if (!sc.bodies[kb]) make_body(&sc, (int)kb);
            break;
        case 2: case 3:
            if (!sc.joints[kj]) make_joint(&sc, (int)kj);
            break;
        case 4: make_contact(&sc); break;
        case 5: case 6: step(&sc); break;
        case 7:
            if (sc.bodies[kb]) {
                dBodyDestroy(sc.bodies[kb]);   // its joints stay, detached from it
                sc.bodies[kb] = 0;
            }
            break;
        case 8:
            if (sc.joints[kj]) {
                dJointDestroy(sc.joints[kj]);
                sc.joints[kj] = 0;
            }
            break;
        case 9:
            if (sc.bodies[kb]) {
                uint8_t f = fz_u8(&in);
                if (f & 1) dBodyDisable(sc.bodies[kb]);
                else dBodyEnable(sc.bodies[kb]);
                if (f & 2) dBodySetKinematic(sc.bodies[kb]);
                else if (f & 4) dBodySetDynamic(sc.bodies[kb]);
            }
            break;
        case 10:
            if (sc.bodies[kb]) {
                dVector3 f;
                sane3(&in, 50, f);
                dBodyAddForce(sc.bodies[kb], f[0], f[1], f[2]);
                sane3(&in, 5, f);
                dBodyAddRelTorque(sc.bodies[kb], f[0], f[1], f[2]);
            }
            break;
        default: poke(&sc); break;
        }
    }
    step(&sc);
    dJointGroupDestroy(sc.contacts);
    dWorldDestroy(sc.world);
    return 0;
}
