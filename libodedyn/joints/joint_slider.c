// SPDX-License-Identifier: BSD-3-Clause
//
// joint_slider.c -- the slider (prismatic) joint (guide 7.3.3): three rows
// lock the relative orientation, two keep body 0's origin on the line along
// the axis through its place at set time, and a limit/motor row acts along
// the axis.
//
// Attached as (0, b), b is stored as body 0 and the axis is kept as the user
// gave it; as in ODE 0.16 the position, its rate, the stops, the motor and
// dJointAddSliderForce then take the user's sense (body 1 against body 2:
// the world against b), the opposite of b's displacement along the axis.

#include "joint_fixed.h"
#include "joint_geometry.h"

typedef struct dxJointSlider {
    dxJoint base;
    dVector3 axis1;     // body 0 frame
    dVector3 offset;    // p0 - p1 at zero position, body 0 frame (world p0 without body 1)
    dQuaternion qrel;   // the relative orientation to keep
    dxLimot limot;
} dxJointSlider;

// The separation of the bodies minus its value at zero position (world):
// along the axis it is the position, across it the joint error.
static void separation_error(const dxJoint *j, const dxJointSlider *s, dVector3 d)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (b1) {
        dVector3 off;
        dMultiply0_331(off, b0->R, s->offset);
        dSubtractVectors3(d, b0->pos, b1->pos);
        dSubtractVectors3(d, d, off);
    } else {
        dSubtractVectors3(d, b0->pos, s->offset);
    }
}

// The sign turning a position, rate or force of the stored bodies (body 0
// against body 1) into the user's (body 1 against body 2 of dJointAttach).
static dReal stored_sign(const dxJoint *j)
{
    return (j->flags & DX_JOINT_REVERSE) ? -1 : 1;
}

// The position in the user's sense: body 0 along the axis relative to body 1,
// negated when attached as (0, b).
static dReal slider_position(const dxJoint *j, const dxJointSlider *s)
{
    dVector3 ax, d;
    dxJointGetAxis1(j, ax, s->axis1);
    separation_error(j, s, d);
    return stored_sign(j) * dCalcVectorDot3(ax, d);
}

static void slider_init(dxJoint *j)
{
    dxJointSlider *s = (dxJointSlider *)j;
    s->axis1[0] = 1;
    dQSetIdentity(s->qrel);
    dxLimotInit(&s->limot, j->world);
}

static void slider_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointSlider *s = (dxJointSlider *)j;
    count->m = 5;
    count->nub = 5;
    if (s->limot.lostop > -dInfinity || s->limot.histop < dInfinity)
        dxLimotTestLimit(&s->limot, slider_position(j, s));
    else
        s->limot.limit = 0;
    if (dxLimotActive(&s->limot)) count->m = 6;
}

// Rows 3 and 4: no motion across the axis. A pair of forces at the
// midpoint of the centres (angular terms (p1 - p0) / 2 x dir on both bodies)
// so they exert no net couple.
static void line_rows(const dxJoint *j, const dxJointSlider *s, dxJointRows *rows,
                      const dVector3 ax)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int rs = rows->rowskip;
    dVector3 dir[2], d, half = { 0, 0, 0, 0 };
    dPlaneSpace(ax, dir[0], dir[1]);
    separation_error(j, s, d);
    if (b1) {
        dSubtractVectors3(half, b1->pos, b0->pos);
        dScaleVector3(half, REAL(0.5));
    }
    const dReal k = rows->fps * rows->erp;
    for (int i = 0; i < 2; i++) {
        const int r = (3 + i) * rs;
        dCopyVector3(rows->J1l + r, dir[i]);
        if (b1) {
            dCopyNegatedVector3(rows->J2l + r, dir[i]);
            dCalcVectorCross3(rows->J1a + r, half, dir[i]);
            dCopyVector3(rows->J2a + r, rows->J1a + r);
        }
        rows->c[3 + i] = -k * dCalcVectorDot3(dir[i], d);
    }
}

static void slider_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointSlider *s = (dxJointSlider *)j;
    dVector3 ax;
    dxJointGetAxis1(j, ax, s->axis1);
    dxJointOrientationRows(j, rows, 0, s->qrel, rows->erp);
    line_rows(j, s, rows, ax);
    dScaleVector3(ax, stored_sign(j));   // the stops and motor act in the user's sense
    dxLimotAddRow(&s->limot, j, rows, 5, ax, 0);
}

// The current configuration becomes position 0 and the orientation to keep;
// delta (world) displaces the zero of a body attached to the world, as in
// ODE 0.16's dJointSetSliderAxisDelta.
static void set_zero(dxJoint *j, const dVector3 delta)
{
    dxJointSlider *s = (dxJointSlider *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;
    if (b1) {
        dVector3 c;
        dSubtractVectors3(c, b0->pos, b1->pos);
        dMultiply1_331(s->offset, b0->R, c);
    } else {
        dAddVectors3(s->offset, b0->pos, delta);
    }
    s->offset[3] = 0;
    dxJointRelativeQuaternion(j, s->qrel);
}

// After dJointAttach: the axis stays fixed in the first body, and the current
// configuration becomes position 0 (ODE 0.16).
static void slider_attached(dxJoint *j)
{
    const dVector3 none = { 0, 0, 0, 0 };
    set_zero(j, none);
}

static const dxJointClass slider_class = {
    dJointTypeSlider, "slider", sizeof(dxJointSlider), slider_init, slider_count_rows,
    slider_fill_rows, slider_attached
};

dJointID dJointCreateSlider(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &slider_class);
}

#define SLIDER(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeSlider, on_fail)

// Set the axis and make the current configuration the zero position. As in
// ODE 0.16, delta (world) only applies to a body attached to the world: its
// zero is where it would be displaced by delta.
static void set_axis(dxJoint *j, const char *function, dReal x, dReal y, dReal z,
                     const dVector3 delta)
{
    dxJointSlider *s = (dxJointSlider *)j;
    if (dxJointSetAxes(j, function, x, y, z, s->axis1, NULL)) set_zero(j, delta);
}

void dJointSetSliderAxis(dJointID j, dReal x, dReal y, dReal z)
{
    SLIDER(j, return);
    const dVector3 none = { 0, 0, 0, 0 };
    set_axis(j, __func__, x, y, z, none);
}

void dJointSetSliderAxisDelta(dJointID j, dReal x, dReal y, dReal z, dReal ax, dReal ay,
                              dReal az)
{
    SLIDER(j, return);
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az), return, "delta is not finite");
    const dVector3 delta = { ax, ay, az, 0 };
    set_axis(j, __func__, x, y, z, delta);
}

void dJointGetSliderAxis(dJointID j, dVector3 result)
{
    SLIDER(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dxJointSlider *s = (dxJointSlider *)j;
    dxJointGetAxis1(j, result, s->axis1);
}

dReal dJointGetSliderPosition(dJointID j)
{
    SLIDER(j, return 0);
    if (!dxJointBody(j, 0)) return 0;
    return slider_position(j, (dxJointSlider *)j);
}

// The time derivative of the position: ax . d with ax turning with body 0 and
// d = (p0 - p1) - R0 offset, where R0 offset . ax is constant; so
// ax . (v0 - v1) + (w0 x ax) . (p0 - p1), with p1 = offset without body 1.
dReal dJointGetSliderPositionRate(dJointID j)
{
    SLIDER(j, return 0);
    dxJointSlider *s = (dxJointSlider *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return 0;
    dVector3 ax, wxa, sep;
    dxJointGetAxis1(j, ax, s->axis1);
    dCalcVectorCross3(wxa, b0->avel, ax);
    dSubtractVectors3(sep, b0->pos, b1 ? b1->pos : s->offset);
    dReal rate = dCalcVectorDot3(ax, b0->lvel) + dCalcVectorDot3(wxa, sep);
    if (b1) rate -= dCalcVectorDot3(ax, b1->lvel);
    return stored_sign(j) * rate;
}

void dJointSetSliderParam(dJointID j, int parameter, dReal value)
{
    SLIDER(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    dxLimotSetParam(&((dxJointSlider *)j)->limot, param, value);
}

dReal dJointGetSliderParam(dJointID j, int parameter)
{
    SLIDER(j, return 0);
    int group, param;
    dReal value = 0;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    dxLimotGetParam(&((dxJointSlider *)j)->limot, param, &value);
    return value;
}

// A force along the axis on body 1 and its opposite on body 2 (user order),
// plus the couple that makes the pair act at the midpoint of the centres, as
// the motor row does.
void dJointAddSliderForce(dJointID j, dReal force)
{
    SLIDER(j, return);
    DX_CHECK_ARG(dxIsFinite(force), return, "force is not finite");
    dxJointSlider *s = (dxJointSlider *)j;
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (!b0) return;
    dVector3 f;
    dxJointGetAxis1(j, f, s->axis1);
    dScaleVector3(f, stored_sign(j) * force);
    dAddVectors3(b0->force, b0->force, f);
    if (b1) {
        dVector3 half, ltd;
        dSubtractVectors3(b1->force, b1->force, f);
        dSubtractVectors3(half, b1->pos, b0->pos);
        dScaleVector3(half, REAL(0.5));
        dCalcVectorCross3(ltd, half, f);
        dAddVectors3(b0->torque, b0->torque, ltd);
        dAddVectors3(b1->torque, b1->torque, ltd);
    }
}
