// SPDX-License-Identifier: BSD-3-Clause
//
// export_dif.c -- dWorldExportDIF: a world as DIF v0.1 text, the format ODE
// 0.16 writes. Its layout (names, order, braces, which values are written
// only when nonzero) follows ODE's output line for line, including its
// quirks, so that the two libraries' files compare equal: a vector is
// "nonzero" only when all three components are, the fixed joint's qrel is
// written with three components, category and collide bits have no comma.
//
// Joints are read through their public getters where these say enough. ODE
// writes the values a joint keeps in its bodies' frames (anchors, axes, the
// rest orientations qrel, the slider and PR offsets); they are recovered here
// from the getters' world values, the bodies' poses and the current angle or
// position. That gives the kept values exactly while the joint holds; when it
// is violated (error the next step would correct), the values describe the
// nearest pose that holds. A joint attached as (0, b) keeps b as its first
// body, and ODE writes it in that order: its anchors, axes, angles and axis
// relativities are mapped from the getters' user order to that order. What
// no getter tells, the joint's own file gives through an internal accessor
// (joint_kept.h): the contact's dContact, the linear motor's axis
// relativities, and the rest orientations of the PR, PU and piston joints
// (a quaternion's sign does not follow from the angle).
//
// Each joint type has one printer in joint_printers; a type without one (the
// null joint, and the ODE 0.16 types ODE has no printer for) is written as
// ODE writes a type it does not know: its name, its bodies, and the line
// `unknown joint`.

#include "dif_print.h"
#include "joint_kept.h"
#include "objects_internal.h"

#include <ode/export-dif.h>
#include <ode/rotation.h>

#include "collision_hooks.h"

static dxDifGeomWriter *geom_writer;

void dxDifSetGeomWriter(dxDifGeomWriter *writer)
{
    geom_writer = writer;
}

// ---- joints -----------------------------------------------------------------

// A joint with its bodies in the order it keeps them: b0 is the first body
// that exists (for a joint attached as (0, b) that is b), b1 may be NULL.
typedef struct joint_view {
    dJointID j;
    dBodyID b0, b1;
    int reversed;
} joint_view;

typedef void joint_printer(const dxDifPrinter *p, const joint_view *v);
typedef void vector_getter(dJointID j, dVector3 result);
typedef dReal param_getter(dJointID j, int parameter);

// World point -> body frame (or unchanged for the static world).
static void body_point(dBodyID b, const dVector3 world, dVector3 out)
{
    if (!b) {
        dCopyVector3(out, world);
        return;
    }
    dVector3 d;
    dSubtractVectors3(d, world, dBodyGetPosition(b));
    dMultiply1_331(out, dBodyGetRotation(b), d);
}

// World direction -> body frame (or unchanged).
static void body_direction(dBodyID b, const dVector3 world, dVector3 out)
{
    if (b) dMultiply1_331(out, dBodyGetRotation(b), world);
    else dCopyVector3(out, world);
}

// The anchors as kept: anchor1 in b0's frame, anchor2 in b1's (or world).
// get1 gives the user's body-1 anchor, get2 the body-2 anchor.
static void kept_anchors(const joint_view *v, vector_getter *get1, vector_getter *get2,
                         dVector3 a1, dVector3 a2)
{
    dVector3 w1, w2;
    get1(v->j, v->reversed ? w2 : w1);
    get2(v->j, v->reversed ? w1 : w2);
    body_point(v->b0, w1, a1);
    body_point(v->b1, w2, a2);
}

// The bodies' relative orientation now: conj(q0) q1, or conj(q0) without b1.
static void relative_quaternion(const joint_view *v, dQuaternion q)
{
    static const dQuaternion identity = { 1, 0, 0, 0 };
    const dReal *q0 = v->b0 ? dBodyGetQuaternion(v->b0) : identity;
    const dReal *q1 = v->b1 ? dBodyGetQuaternion(v->b1) : identity;
    dQMultiply1(q, q0, q1);
}

// The rest orientation of a hinge-like axis. ODE measures the angle from the
// relative orientation now and the rest one qrel as now conj(qrel) =
// rot(axis, -angle) (axis in b0's frame), hence qrel = rot(axis, angle) now.
// The sign of the kept qrel does not follow (q and -q give the same angle):
// this gives the one of the relative quaternion now.
static void rest_quaternion(const dQuaternion now, const dVector3 axis, dReal angle,
                            dQuaternion qrel)
{
    dQuaternion r;
    dQFromAxisAndAngle(r, axis[0], axis[1], axis[2], angle);
    dQMultiply0(qrel, r, now);
}

// A limit/motor group as ODE writes it: `limit = {...}` and `motor = {...}`,
// numbered when the joint has several axes (num >= 0).
static void print_limot(const dxDifPrinter *p, const joint_view *v, param_getter *get, int group,
                        int num)
{
    const int g = group * dParamGroup;
    dxDifPrinter q = *p;
    char line[32];
    if (num >= 0) snprintf(line, sizeof line, "limit%d = {", num);
    else snprintf(line, sizeof line, "limit = {");
    dxDifPrintLine(&q, line);
    q.indent++;
    dxDifPrintReal(&q, "low_stop", get(v->j, g + dParamLoStop));
    dxDifPrintReal(&q, "high_stop", get(v->j, g + dParamHiStop));
    dReal x = get(v->j, g + dParamBounce);
    if (x != 0) dxDifPrintReal(&q, "bounce", x);
    dxDifPrintLine(&q, "ODE = {");
    q.indent++;
    if ((x = get(v->j, g + dParamStopERP)) != 0) dxDifPrintReal(&q, "stop_erp", x);
    if ((x = get(v->j, g + dParamStopCFM)) != 0) dxDifPrintReal(&q, "stop_cfm", x);
    q.indent--;
    dxDifPrintLine(&q, "},");
    q.indent--;
    dxDifPrintLine(&q, "},");

    if (num >= 0) snprintf(line, sizeof line, "motor%d = {", num);
    else snprintf(line, sizeof line, "motor = {");
    dxDifPrintLine(&q, line);
    q.indent++;
    if ((x = get(v->j, g + dParamVel)) != 0) dxDifPrintReal(&q, "vel", x);
    if ((x = get(v->j, g + dParamFMax)) != 0) dxDifPrintReal(&q, "fmax", x);
    dxDifPrintLine(&q, "ODE = {");
    q.indent++;
    if ((x = get(v->j, g + dParamFudgeFactor)) != 0) dxDifPrintReal(&q, "fudge_factor", x);
    if ((x = get(v->j, g + dParamCFM)) != 0) dxDifPrintReal(&q, "normal_cfm", x);
    q.indent--;
    dxDifPrintLine(&q, "},");
    q.indent--;
    dxDifPrintLine(&q, "},");
}

static void print_ball(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 a1, a2;
    kept_anchors(v, dJointGetBallAnchor, dJointGetBallAnchor2, a1, a2);
    dxDifPrintReals(p, "anchor1", a1, 3);
    dxDifPrintReals(p, "anchor2", a2, 3);
}

// Anchors and the axis in both bodies' frames and the kept rest orientation,
// as ODE writes them for the hinge and the piston.
static void print_anchors_axis_rest(const dxDifPrinter *p, const joint_view *v,
                                    vector_getter *anchor1, vector_getter *anchor2,
                                    vector_getter *axis_getter,
                                    void (*rest)(const dxJoint *, dQuaternion))
{
    dVector3 a1, a2, axis, ax1, ax2;
    kept_anchors(v, anchor1, anchor2, a1, a2);
    axis_getter(v->j, axis);
    body_direction(v->b0, axis, ax1);
    body_direction(v->b1, axis, ax2);
    dQuaternion qrel;
    rest(v->j, qrel);
    dxDifPrintReals(p, "anchor1", a1, 3);
    dxDifPrintReals(p, "anchor2", a2, 3);
    dxDifPrintReals(p, "axis1", ax1, 3);
    dxDifPrintReals(p, "axis2", ax2, 3);
    dxDifPrintReals(p, "qrel", qrel, 4);
}

static void print_hinge(const dxDifPrinter *p, const joint_view *v)
{
    print_anchors_axis_rest(p, v, dJointGetHingeAnchor, dJointGetHingeAnchor2,
                            dJointGetHingeAxis, dxJointHingeRest);
    print_limot(p, v, dJointGetHingeParam, 0, -1);
}

// The slider keeps its bodies' relative orientation (qrel) and the offset
// that makes the position 0: position = axis . (p0 - p1 - R1 offset), so
// offset = R1^T (p0 - p1 - position axis) (world: p0 - position axis).
static void print_slider(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 axis, ax1, d = { 0, 0, 0 }, offset;
    dJointGetSliderAxis(v->j, axis);
    body_direction(v->b0, axis, ax1);
    dReal pos = dJointGetSliderPosition(v->j);
    if (v->reversed) pos = -pos;
    if (v->b0) dCopyVector3(d, dBodyGetPosition(v->b0));
    dAddScaledVectors3(d, d, axis, 1, -pos);
    if (v->b1) {
        dSubtractVectors3(d, d, dBodyGetPosition(v->b1));
        dMultiply1_331(offset, dBodyGetRotation(v->b1), d);
    } else {
        dCopyVector3(offset, d);
    }
    dQuaternion qrel;
    relative_quaternion(v, qrel);
    dxDifPrintReals(p, "axis1", ax1, 3);
    dxDifPrintReals(p, "qrel", qrel, 4);
    dxDifPrintReals(p, "offset", offset, 3);
    print_limot(p, v, dJointGetSliderParam, 0, -1);
}

// What ODE writes for a joint type it has no printer for (the null joint,
// types it does not know).
static void print_unknown(const dxDifPrinter *p, const joint_view *v)
{
    (void)v;
    dxDifPrintLine(p, "unknown joint");
}

// The universal joint keeps, per axis, the rest orientation of the cross
// (the frame of the two axes) relative to the body of that axis: axis 1
// relative to b0, axis 2 relative to b1. Angle 1 is measured like a hinge
// angle of the cross against b0; angle 2 with the opposite sign.
static void print_universal(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 a1, a2, w1, w2, ax1, ax2;
    kept_anchors(v, dJointGetUniversalAnchor, dJointGetUniversalAnchor2, a1, a2);
    dJointGetUniversalAxis1(v->j, v->reversed ? w2 : w1);
    dJointGetUniversalAxis2(v->j, v->reversed ? w1 : w2);
    body_direction(v->b0, w1, ax1);
    body_direction(v->b1, w2, ax2);
    dReal angle1, angle2;
    dJointGetUniversalAngles(v->j, &angle1, &angle2);
    if (v->reversed) {   // b0 is user body 2: the kept axis 1 is the user's axis 2
        dReal t = angle1;
        angle1 = -angle2;
        angle2 = -t;
    }
    static const dQuaternion identity = { 1, 0, 0, 0 };
    const dReal *q0 = v->b0 ? dBodyGetQuaternion(v->b0) : identity;
    const dReal *q1 = v->b1 ? dBodyGetQuaternion(v->b1) : identity;
    dMatrix3 R;
    dQuaternion cross, now, qrel1, qrel2;
    dRFrom2Axes(R, w1[0], w1[1], w1[2], w2[0], w2[1], w2[2]);
    dRtoQ(R, cross);
    dQMultiply1(now, q0, cross);
    rest_quaternion(now, ax1, angle1, qrel1);
    dRFrom2Axes(R, w2[0], w2[1], w2[2], w1[0], w1[1], w1[2]);
    dRtoQ(R, cross);
    dQMultiply1(now, q1, cross);
    rest_quaternion(now, ax2, -angle2, qrel2);
    dxDifPrintReals(p, "anchor1", a1, 3);
    dxDifPrintReals(p, "anchor2", a2, 3);
    dxDifPrintReals(p, "axis1", ax1, 3);
    dxDifPrintReals(p, "axis2", ax2, 3);
    dxDifPrintReals(p, "qrel1", qrel1, 4);
    dxDifPrintReals(p, "qrel2", qrel2, 4);
    print_limot(p, v, dJointGetUniversalParam, 0, 1);
    print_limot(p, v, dJointGetUniversalParam, 1, 2);
}

// Hinge-2 keeps v1 (axis 2 made perpendicular to axis 1 at rest) and
// v2 = axis1 x v1 in b0's frame; angle 1 = -atan2(v2.a, v1.a) for axis 2's
// direction a there now, so v1 is a turned back by angle 1 about axis 1.
static void print_hinge2(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 a1, a2, w1, w2, ax1, ax2, a, c, v1, v2;
    kept_anchors(v, dJointGetHinge2Anchor, dJointGetHinge2Anchor2, a1, a2);
    dJointGetHinge2Axis1(v->j, w1);
    dJointGetHinge2Axis2(v->j, w2);
    body_direction(v->b0, w1, ax1);
    body_direction(v->b1, w2, ax2);
    body_direction(v->b0, w2, a);
    dAddScaledVectors3(a, a, ax1, 1, -dCalcVectorDot3(a, ax1));
    dSafeNormalize3(a);
    dCalcVectorCross3(c, ax1, a);
    const dReal angle = dJointGetHinge2Angle1(v->j);
    dAddScaledVectors3(v1, a, c, dCos(angle), dSin(angle));
    dCalcVectorCross3(v2, ax1, v1);
    dxDifPrintReals(p, "anchor1", a1, 3);
    dxDifPrintReals(p, "anchor2", a2, 3);
    dxDifPrintReals(p, "axis1", ax1, 3);
    dxDifPrintReals(p, "axis2", ax2, 3);
    dxDifPrintReals(p, "v1", v1, 3);
    dxDifPrintReals(p, "v2", v2, 3);
    dxDifPrintReal(p, "susp_erp", dJointGetHinge2Param(v->j, dParamSuspensionERP));
    dxDifPrintReal(p, "susp_cfm", dJointGetHinge2Param(v->j, dParamSuspensionCFM));
    print_limot(p, v, dJointGetHinge2Param, 0, 1);
    print_limot(p, v, dJointGetHinge2Param, 1, 2);
}

// The fixed joint keeps the relative orientation and b0's offset from b1 in
// b0's frame (b0's position without b1). ODE writes qrel's first three
// components only.
static void print_fixed(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 offset = { 0, 0, 0 };
    if (v->b0) {
        const dReal *p0 = dBodyGetPosition(v->b0);
        if (v->b1) {
            dVector3 d;
            dSubtractVectors3(d, p0, dBodyGetPosition(v->b1));
            dMultiply1_331(offset, dBodyGetRotation(v->b0), d);
        } else {
            dCopyVector3(offset, p0);
        }
    }
    dQuaternion qrel;
    relative_quaternion(v, qrel);
    dxDifPrintReals(p, "qrel", qrel, 3);
    dxDifPrintReals(p, "offset", offset, 3);
}

// Axes are kept in the frame they are relative to: world (rel 0), b0 (1),
// b1 (2); rel names the bodies in the order kept, the user's order swapped
// for a joint attached as (0, b).
static void print_amotor(const dxDifPrinter *p, const joint_view *v)
{
    const int num = dJointGetAMotorNumAxes(v->j);
    int rel[3] = { 0, 0, 0 };
    dVector3 axis[3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
    for (int i = 0; i < num; i++) {
        dVector3 w;
        rel[i] = dJointGetAMotorAxisRel(v->j, i);
        if (v->reversed && rel[i] != 0) rel[i] = 3 - rel[i];   // kept in body order
        dJointGetAMotorAxis(v->j, i, w);
        body_direction(rel[i] == 1 ? v->b0 : rel[i] == 2 ? v->b1 : NULL, w, axis[i]);
    }
    dxDifPrintInt(p, "num", num);
    dxDifPrintInt(p, "mode", dJointGetAMotorMode(v->j));
    dxDifIndent(p);
    fprintf(p->file, "rel = {%d,%d,%d},\n", rel[0], rel[1], rel[2]);
    dxDifPrintReals(p, "axis1", axis[0], 3);
    dxDifPrintReals(p, "axis2", axis[1], 3);
    dxDifPrintReals(p, "axis3", axis[2], 3);
    for (int i = 0; i < 3; i++) print_limot(p, v, dJointGetAMotorParam, i, i + 1);
    dxDifPrintReal(p, "angle1", num > 0 ? dJointGetAMotorAngle(v->j, 0) : 0);
    dxDifPrintReal(p, "angle2", num > 1 ? dJointGetAMotorAngle(v->j, 1) : 0);
    dxDifPrintReal(p, "angle3", num > 2 ? dJointGetAMotorAngle(v->j, 2) : 0);
}

// The PR joint keeps the anchor in b1's frame (anchor2), the rotation axis
// in both bodies' frames, the slide axis in b0's, the rest orientation qrel
// and the offset: the anchor in b0's frame at position 0. The position is
// axis . (p0 + R0 offset - anchor), so offset = R0^T (anchor - p0 +
// position axis).
static void print_pr(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 anchor, axp, axr, a2, axr1, axr2, axp1, d, offset;
    dJointGetPRAnchor(v->j, anchor);
    dJointGetPRAxis1(v->j, axp);
    dJointGetPRAxis2(v->j, axr);
    body_point(v->b1, anchor, a2);
    body_direction(v->b0, axr, axr1);
    body_direction(v->b1, axr, axr2);
    body_direction(v->b0, axp, axp1);
    // Attached as (0, b), the position is reported with the opposite sign.
    dReal pos = dJointGetPRPosition(v->j);
    if (v->reversed) pos = -pos;
    dAddScaledVectors3(d, anchor, axp, 1, pos);
    body_point(v->b0, d, offset);
    dQuaternion qrel;
    dxJointPRRest(v->j, qrel);
    dxDifPrintReals(p, "anchor2", a2, 3);
    dxDifPrintReals(p, "axisR1", axr1, 3);
    dxDifPrintReals(p, "axisR2", axr2, 3);
    dxDifPrintReals(p, "axisP1", axp1, 3);
    dxDifPrintReals(p, "qrel", qrel, 4);
    dxDifPrintReals(p, "offset", offset, 3);
    print_limot(p, v, dJointGetPRParam, 0, 1);
    print_limot(p, v, dJointGetPRParam, 1, 2);
}

// ODE keeps a PU joint's axis P in b0's frame also when the joint was
// attached as (0, b), at b's orientation when the axis was set; this library
// keeps that axis in the world (axp). b's orientation q0 then is recovered
// from the kept rest orientations, taken as set with the axis: qrel2 is
// the cross (axis 2, axis 1) in the world then, its second column axis 1
// then, which with axis 2 (w2, fixed in the world) gives the cross (axis 1,
// axis 2), and qrel1 = conj(q0) cross.
static void pu_reversed_axis_p(const dVector3 w2, const dQuaternion qrel1,
                               const dQuaternion qrel2, const dVector3 axp, dVector3 out)
{
    dMatrix3 R;
    dQtoR(qrel2, R);
    const dVector3 ax1 = { R[1], R[5], R[9], 0 };
    dRFrom2Axes(R, ax1[0], ax1[1], ax1[2], w2[0], w2[1], w2[2]);
    dQuaternion cross, q0;
    dRtoQ(R, cross);
    dQMultiply2(q0, cross, qrel1);
    dQtoR(q0, R);
    dMultiply1_331(out, R, axp);
}

// The PU joint keeps what the universal joint keeps, with anchor1 (b0's) off
// anchor2 along axis P by the position, and axis P in b0's frame.
static void print_pu(const dxDifPrinter *p, const joint_view *v)
{
    dVector3 an1, an2, axp, a1, a2, w1, w2, ax1, ax2, axp1;
    dJointGetPUAnchor(v->j, an2);
    dJointGetPUAxisP(v->j, axp);
    dReal pos = dJointGetPUPosition(v->j);
    if (v->reversed) pos = -pos;
    dAddScaledVectors3(an1, an2, axp, 1, pos);
    body_point(v->b0, an1, a1);
    body_point(v->b1, an2, a2);
    // Attached as (0, b), the getters swap the axes into the user's order.
    dJointGetPUAxis1(v->j, v->reversed ? w2 : w1);
    dJointGetPUAxis2(v->j, v->reversed ? w1 : w2);
    body_direction(v->b0, w1, ax1);
    body_direction(v->b1, w2, ax2);
    dQuaternion qrel1, qrel2;
    dxJointPURest(v->j, qrel1, qrel2);
    if (v->reversed) pu_reversed_axis_p(w2, qrel1, qrel2, axp, axp1);
    else body_direction(v->b0, axp, axp1);
    dxDifPrintReals(p, "anchor1", a1, 3);
    dxDifPrintReals(p, "anchor2", a2, 3);
    dxDifPrintReals(p, "axis1", ax1, 3);
    dxDifPrintReals(p, "axis2", ax2, 3);
    dxDifPrintReals(p, "axisP", axp1, 3);
    dxDifPrintReals(p, "qrel1", qrel1, 4);
    dxDifPrintReals(p, "qrel2", qrel2, 4);
    print_limot(p, v, dJointGetPUParam, 0, 1);
    print_limot(p, v, dJointGetPUParam, 1, 2);
    print_limot(p, v, dJointGetPUParam, 2, 3);
}

// The piston keeps an anchor and the axis in each body's frame, and the rest
// orientation.
static void print_piston(const dxDifPrinter *p, const joint_view *v)
{
    print_anchors_axis_rest(p, v, dJointGetPistonAnchor, dJointGetPistonAnchor2,
                            dJointGetPistonAxis, dxJointPistonRest);
    print_limot(p, v, dJointGetPistonParam, 0, 1);
    print_limot(p, v, dJointGetPistonParam, 1, 2);
}

// The linear motor's rel has no getter (dxJointLMotorAxisRel). ODE keeps rel
// as given, body 1 and 2 being the kept b0 and b1 (it ignores a (0, b)
// attachment), and a body-2 axis without b1 as a body-1 one; the axis is
// kept in that frame. Where this library fixes the axis elsewhere (rel 1
// attached as (0, b), rel 2 attached as (b, 0): in the world), it is
// written in b's frame now: ODE's value until b turns after the axis is set.
static void print_lmotor(const dxDifPrinter *p, const joint_view *v)
{
    int rel[3];
    dVector3 axis[3];
    for (int i = 0; i < 3; i++) {
        dVector3 w;
        rel[i] = dxJointLMotorAxisRel(v->j, i);
        if (rel[i] == 2 && !v->b1) rel[i] = 1;
        dJointGetLMotorAxis(v->j, i, w);
        body_direction(rel[i] == 1 ? v->b0 : rel[i] == 2 ? v->b1 : NULL, w, axis[i]);
    }
    dxDifPrintInt(p, "num", dJointGetLMotorNumAxes(v->j));
    dxDifIndent(p);
    fprintf(p->file, "rel = {%d,%d,%d},\n", rel[0], rel[1], rel[2]);
    dxDifPrintReals(p, "axis1", axis[0], 3);
    dxDifPrintReals(p, "axis2", axis[1], 3);
    dxDifPrintReals(p, "axis3", axis[2], 3);
    for (int i = 0; i < 3; i++) print_limot(p, v, dJointGetLMotorParam, i, i + 1);
}

// The contact joint writes the dContact it was made from: its point, the
// surface's coefficients its mode uses, the friction pyramid bits as one
// number (1: direction 1, 2: direction 2) and fdir1.
static void print_contact(const dxDifPrinter *p, const joint_view *v)
{
    const dContact *c = dxJointContactGet(v->j);
    const dSurfaceParameters *s = &c->surface;
    const int mode = s->mode;
    dxDifPrintReals(p, "pos", c->geom.pos, 3);
    dxDifPrintReals(p, "normal", c->geom.normal, 3);
    dxDifPrintReal(p, "depth", c->geom.depth);
    dxDifPrintReal(p, "mu", s->mu);
    if (mode & dContactMu2) dxDifPrintReal(p, "mu2", s->mu2);
    if (mode & dContactBounce) {
        dxDifPrintReal(p, "bounce", s->bounce);
        dxDifPrintReal(p, "bounce_vel", s->bounce_vel);
    }
    if (mode & dContactSoftERP) dxDifPrintReal(p, "soft_ERP", s->soft_erp);
    if (mode & dContactSoftCFM) dxDifPrintReal(p, "soft_CFM", s->soft_cfm);
    if (mode & dContactMotion1) dxDifPrintReal(p, "motion1", s->motion1);
    if (mode & dContactMotion2) dxDifPrintReal(p, "motion2", s->motion2);
    if (mode & dContactSlip1) dxDifPrintReal(p, "slip1", s->slip1);
    if (mode & dContactSlip2) dxDifPrintReal(p, "slip2", s->slip2);
    const int approx = ((mode & dContactApprox1_1) ? 1 : 0) | ((mode & dContactApprox1_2) ? 2 : 0);
    if (approx) dxDifPrintInt(p, "friction_approximation", approx);
    if (mode & dContactFDir1) dxDifPrintReals(p, "fdir1", c->fdir1, 3);
}

// DIF names (as ODE writes them) and printers, by dJointType. To add a
// type: write its printer from its getters and put it here.
static const struct {
    const char *name;
    joint_printer *print;
} joint_printers[] = {
    [dJointTypeBall] = { "ball", print_ball },
    [dJointTypeHinge] = { "hinge", print_hinge },
    [dJointTypeSlider] = { "slider", print_slider },
    [dJointTypeContact] = { "contact", print_contact },
    [dJointTypeUniversal] = { "universal", print_universal },
    [dJointTypeHinge2] = { "ODE_hinge2", print_hinge2 },
    [dJointTypeFixed] = { "fixed", print_fixed },
    [dJointTypeNull] = { "null", print_unknown },   // as ODE writes it
    [dJointTypeAMotor] = { "ODE_angular_motor", print_amotor },
    [dJointTypeLMotor] = { "ODE_linear_motor", print_lmotor },
    [dJointTypePR] = { "PR", print_pr },
    [dJointTypePU] = { "PU", print_pu },
    [dJointTypePiston] = { "piston", print_piston },
    // ODE 0.16 has no printer and no name for plane-2D, DBall, DHinge and
    // transmission: it writes them as "unknown" types.
};

static void print_joint(const dxDifPrinter *file_printer, const char *prefix, int num,
                        struct dxJoint *jt)
{
    joint_view v = { jt, dJointGetBody(jt, 0), dJointGetBody(jt, 1), 0 };
    if (!v.b0 && v.b1) {
        v.b0 = v.b1;
        v.b1 = NULL;
        v.reversed = 1;
    }
    const int type = (int)dJointGetType(jt);
    const int known = type >= 0 && type < (int)(sizeof joint_printers / sizeof joint_printers[0])
                      && joint_printers[type].name;
    FILE *f = file_printer->file;
    fprintf(f, "%sjoint[%d] = dynamics.%s_joint {\n\tworld = %sworld,\n\tbody = {", prefix, num,
            known ? joint_printers[type].name : "unknown", prefix);
    if (v.b0) fprintf(f, "%sbody[%d]", prefix, v.b0->tag);
    if (v.b1) fprintf(f, ",%sbody[%d]", prefix, v.b1->tag);
    fputs("}\n", f);
    dxDifPrinter p = *file_printer;
    p.indent = 1;
    if (known) joint_printers[type].print(&p, &v);
    else print_unknown(&p, &v);
    p.indent = 0;
    dxDifPrintLine(&p, "}");
}

// ---- bodies and the world ---------------------------------------------------

// ODE keeps (and writes) the squares of the speed thresholds.
static void print_auto_disable(const dxDifPrinter *p, const dxAutoDisable *a)
{
    dxDifPrintReal(p, "linear_threshold", a->linear_threshold * a->linear_threshold);
    dxDifPrintReal(p, "angular_threshold", a->angular_threshold * a->angular_threshold);
    dxDifPrintInt(p, "average_samples", (int)a->average_samples);
    dxDifPrintReal(p, "idle_time", a->idle_time);
    dxDifPrintInt(p, "idle_steps", a->idle_steps);
}

static int all_nonzero(const dReal *v)
{
    return v[0] != 0 && v[1] != 0 && v[2] != 0;
}

static void print_geoms(const dxDifPrinter *p, struct dxBody *b)
{
    dxDifPrinter q = *p;
    dxDifPrintLine(&q, "geometry = {");
    q.indent++;
    for (dGeomID g = b->first_geom; g; g = dGeomGetBodyNext(g)) {
        dxDifPrintLine(&q, "{");
        q.indent++;
        geom_writer(&q, g);
        q.indent--;
        dxDifPrintLine(&q, "},");
    }
    q.indent--;
    dxDifPrintLine(&q, "},");
}

static void print_body(const dxDifPrinter *file_printer, const char *prefix, int num,
                       struct dxBody *b)
{
    FILE *f = file_printer->file;
    dxDifPrinter p = *file_printer;
    p.indent = 1;
    fprintf(f, "%sbody[%d] = dynamics.body {\n\tworld = %sworld,\n", prefix, num, prefix);
    dxDifPrintReals(&p, "pos", b->pos, 3);
    dxDifPrintReals(&p, "q", b->q, 4);
    dxDifPrintReals(&p, "lvel", b->lvel, 3);
    dxDifPrintReals(&p, "avel", b->avel, 3);
    dxDifPrintReal(&p, "mass", b->mass.mass);
    fputs("\tI = {{", f);
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++) {
            dxDifReal(&p, b->mass.I[i * 4 + k]);
            if (k < 2) fputc(',', f);
        }
        if (i < 2) fputs("},{", f);
    }
    fputs("}},\n", f);
    if (all_nonzero(b->mass.c)) dxDifPrintReals(&p, "com", b->mass.c, 3);
    dxDifPrintLine(&p, "ODE = {");
    p.indent++;
    if (b->flags & DX_BODY_FINITE_ROTATION) dxDifPrintInt(&p, "finite_rotation", 1);
    if (b->flags & DX_BODY_DISABLED) dxDifPrintInt(&p, "disabled", 1);
    if (b->flags & DX_BODY_NO_GRAVITY) dxDifPrintInt(&p, "no_gravity", 1);
    if (b->flags & DX_BODY_AUTO_DISABLE) {
        dxDifPrintLine(&p, "auto_disable = {");
        p.indent++;
        print_auto_disable(&p, &b->adis);
        // ODE counts down what this library counts up.
        dxDifPrintReal(&p, "time_left", b->adis.idle_time - b->adis_idle_time);
        dxDifPrintInt(&p, "steps_left", b->adis.idle_steps - b->adis_idle_steps);
        p.indent--;
        dxDifPrintLine(&p, "},");
    }
    if (all_nonzero(b->force)) dxDifPrintReals(&p, "facc", b->force, 3);
    if (all_nonzero(b->torque)) dxDifPrintReals(&p, "tacc", b->torque, 3);
    if (b->flags & DX_BODY_FINITE_ROTATION_AXIS)
        dxDifPrintReals(&p, "finite_rotation_axis", b->finite_rot_axis, 3);
    p.indent--;
    dxDifPrintLine(&p, "},");
    if (b->first_geom && geom_writer) print_geoms(&p, b);
    p.indent = 0;
    dxDifPrintLine(&p, "}");
}

void dWorldExportDIF(dWorldID w, FILE *file, const char *world_name)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return, "world is NULL or was destroyed");
    DX_CHECK_ARG(file != NULL, return, "file is NULL");
    DX_CHECK_ARG(world_name != NULL, return, "world_name is NULL");
#if defined(dSINGLE)
    dxDifPrinter p = { file, 7, 1 };
#else
    dxDifPrinter p = { file, 15, 1 };
#endif
    const char *prefix = world_name;
    fprintf(file, "-- Dynamics Interchange Format v0.1\n\n%sworld = dynamics.world {\n", prefix);
    dxDifPrintReals(&p, "gravity", w->gravity, 3);
    dxDifPrintLine(&p, "ODE = {");
    p.indent++;
    dxDifPrintReal(&p, "ERP", w->erp);
    dxDifPrintReal(&p, "CFM", w->cfm);
    dxDifPrintLine(&p, "auto_disable = {");
    p.indent++;
    print_auto_disable(&p, &w->adis);
    fputs("\t\t},\n\t},\n}\n", file);

    // Bodies and joints in list order (newest first, as in ODE); each
    // body's index goes into its tag for the joints' body lists.
    fprintf(file, "%sbody = {}\n", prefix);
    int num = 0;
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        b->tag = num;
        print_body(&p, prefix, num++, b);
    }
    fprintf(file, "%sjoint = {}\n", prefix);
    num = 0;
    for (struct dxJoint *j = w->joints; j; j = j->next) print_joint(&p, prefix, num++, j);
}
