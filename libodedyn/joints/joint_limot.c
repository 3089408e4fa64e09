// SPDX-License-Identifier: BSD-3-Clause
//
// joint_limot.c -- limits and motors of joint axes (see joint_limot.h).

#include "joint_limot.h"

void dxLimotInit(dxLimot *lm, const struct dxWorld *w)
{
    lm->vel = 0;
    lm->fmax = 0;
    lm->lostop = -dInfinity;
    lm->histop = dInfinity;
    lm->fudge_factor = 1;
    lm->normal_cfm = w->cfm;
    lm->stop_erp = w->erp;
    lm->stop_cfm = w->cfm;
    lm->bounce = 0;
    lm->limit = 0;
    lm->limit_err = 0;
}

int dxParamSplit(const char *function, int parameter, int max_groups, int *group, int *param)
{
    *group = parameter >> 8;
    *param = parameter & 0xff;
    if (parameter < 0 || *group >= max_groups || *param >= dParamsInGroup) {
        dxReportBadArgument(function, "parameter 0x%x is not a parameter of this joint",
                            (unsigned)parameter);
        return 0;
    }
    return 1;
}

int dxLimotSetParam(dxLimot *lm, int param, dReal value)
{
    switch (param) {
    case dParamLoStop: lm->lostop = value; return 1;
    case dParamHiStop: lm->histop = value; return 1;
    case dParamVel: lm->vel = value; return 1;
    case dParamFMax:
        DX_CHECK_ARG(value >= 0, return 1, "dParamFMax must be >= 0, got %g", (double)value);
        lm->fmax = value;
        return 1;
    case dParamFudgeFactor:
        DX_CHECK_ARG(value >= 0 && value <= 1, return 1,
                     "dParamFudgeFactor must be in 0..1, got %g", (double)value);
        lm->fudge_factor = value;
        return 1;
    case dParamBounce: lm->bounce = value; return 1;
    case dParamCFM: lm->normal_cfm = value; return 1;
    case dParamStopERP: lm->stop_erp = value; return 1;
    case dParamStopCFM: lm->stop_cfm = value; return 1;
    default: return 0;
    }
}

int dxLimotGetParam(const dxLimot *lm, int param, dReal *value)
{
    switch (param) {
    case dParamLoStop: *value = lm->lostop; return 1;
    case dParamHiStop: *value = lm->histop; return 1;
    case dParamVel: *value = lm->vel; return 1;
    case dParamFMax: *value = lm->fmax; return 1;
    case dParamFudgeFactor: *value = lm->fudge_factor; return 1;
    case dParamBounce: *value = lm->bounce; return 1;
    case dParamCFM: *value = lm->normal_cfm; return 1;
    case dParamStopERP: *value = lm->stop_erp; return 1;
    case dParamStopCFM: *value = lm->stop_cfm; return 1;
    default: return 0;
    }
}

int dxLimotTestLimit(dxLimot *lm, dReal position)
{
    if (lm->lostop > lm->histop) {   // inconsistent stops: none of them acts
        lm->limit = 0;
    } else if (position <= lm->lostop) {
        lm->limit = 1;
        lm->limit_err = position - lm->lostop;
    } else if (position >= lm->histop) {
        lm->limit = 2;
        lm->limit_err = position - lm->histop;
    } else {
        lm->limit = 0;
    }
    return lm->limit != 0;
}

// How far an angle must be from a stop (and from +-pi, where the wrap
// turns it over) for dxLimotAngleClear to decide without atan2: over
// three times the error of its estimate (ANGLE_ESTIMATE_ERROR), so that
// the exact angle, which differs from the estimate by less than that, is
// on the same side of every stop.
#define ANGLE_CLEAR_MARGIN ((dReal)0.01)

// atan(t) for |t| <= 1 within 0.0015 rad (a quadratic correction of
// pi/4 t, S. Rajan et al., "Efficient approximations for the arctangent
// function", 2006; tests/test_limot_angle.c checks the bound).
#define ANGLE_ESTIMATE_ERROR ((dReal)0.0015)
static dReal atan_estimate(dReal t)
{
    const dReal a = dFabs(t);
    return t * ((dReal)(M_PI / 4) - (a - 1) * ((dReal)0.2447 + (dReal)0.0663 * a));
}

// atan2(y, x) for x >= 0 within ANGLE_ESTIMATE_ERROR: atan(y / x), or
// sign(y) pi/2 - atan(x / y) where |y| > x (NaN for 0 / 0).
static dReal atan2_right_estimate(dReal y, dReal x)
{
    if (dFabs(y) <= x) return atan_estimate(y / x);
    const dReal right = y > 0 ? (dReal)(M_PI / 2) : (dReal)(-M_PI / 2);
    return right - atan_estimate(x / y);
}

// Is the estimate `angle` far enough from both stops and from +-pi?
static int estimate_clear(const dxLimot *lm, dReal angle)
{
    const dReal m = ANGLE_CLEAR_MARGIN;
    return dFabs(angle) < (dReal)M_PI - m && angle > lm->lostop + m && angle < lm->histop - m;
}

int dxLimotAngleClear(const dxLimot *lm, dReal y, dReal x)
{
    // (x, y) and (-x, -y) give the same wrapped angle: take x >= 0.
    if (x < 0) {
        x = -x;
        y = -y;
    }
    return estimate_clear(lm, 2 * atan2_right_estimate(y, x));
}

int dxLimotAtan2Clear(const dxLimot *lm, dReal y, dReal x)
{
    // Only the right half plane, where atan2 is atan2_right_estimate's (the
    // left one is left to atan2: rare for the joints that ask).
    return x >= 0 && estimate_clear(lm, atan2_right_estimate(y, x));
}

int dxLimotActive(const dxLimot *lm) { return lm->fmax > 0 || lm->limit != 0; }

// The relative velocity of body 0 against body 1 along axis.
static dReal axis_velocity(const dxJoint *j, const dReal axis[3], int rotational)
{
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    dReal v = dCalcVectorDot3(rotational ? b0->avel : b0->lvel, axis);
    if (b1) v -= dCalcVectorDot3(rotational ? b1->avel : b1->lvel, axis);
    return v;
}

// A motor powering against its stop: the stop row holds the joint, and the
// motor's force is applied directly along the row's Jacobian (a fraction of
// it, the fudge factor, when it powers away from the stop, where it would
// otherwise need a second row).
static void push_against_stop(const dxLimot *lm, dxJoint *j, const dxJointRows *rows, int row)
{
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int s = row * rows->rowskip;
    dReal fm = lm->fmax;
    if (lm->vel > 0 || (lm->vel == 0 && lm->limit == 2)) fm = -fm;
    if ((lm->limit == 1 && lm->vel > 0) || (lm->limit == 2 && lm->vel < 0)) fm *= lm->fudge_factor;
    dAddVectorScaledVector3(b0->force, b0->force, rows->J1l + s, -fm);
    dAddVectorScaledVector3(b0->torque, b0->torque, rows->J1a + s, -fm);
    if (b1) {
        dAddVectorScaledVector3(b1->force, b1->force, rows->J2l + s, -fm);
        dAddVectorScaledVector3(b1->torque, b1->torque, rows->J2a + s, -fm);
    }
}

void dxLimotSetRow(dxLimot *lm, dxJoint *j, dxJointRows *rows, int row, dReal velocity)
{
    int powered = lm->fmax > 0 && !(lm->limit && lm->lostop == lm->histop);
    if (powered) {
        rows->cfm[row] = lm->normal_cfm;
        if (!lm->limit) {
            rows->c[row] = lm->vel;
            rows->lo[row] = -lm->fmax;
            rows->hi[row] = lm->fmax;
        } else {
            push_against_stop(lm, j, rows, row);
        }
    }
    if (!lm->limit) return;

    rows->c[row] = -rows->fps * lm->stop_erp * lm->limit_err;
    rows->cfm[row] = lm->stop_cfm;
    if (lm->lostop == lm->histop) {   // locked: a two-sided row
        rows->lo[row] = -dInfinity;
        rows->hi[row] = dInfinity;
        return;
    }
    rows->lo[row] = lm->limit == 1 ? 0 : -dInfinity;
    rows->hi[row] = lm->limit == 1 ? dInfinity : 0;
    if (lm->bounce > 0) {
        // Restitution: an incoming velocity v leaves as -bounce * v, if that
        // asks more than the position correction does.
        dReal bounced = -lm->bounce * velocity;
        if (lm->limit == 1 && velocity < 0 && bounced > rows->c[row]) rows->c[row] = bounced;
        if (lm->limit == 2 && velocity > 0 && bounced < rows->c[row]) rows->c[row] = bounced;
    }
}

int dxLimotAddRow(dxLimot *lm, dxJoint *j, dxJointRows *rows, int row, const dReal axis[3],
                  int rotational)
{
    if (!dxLimotActive(lm)) return 0;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const int s = row * rows->rowskip;
    dReal *J1 = (rotational ? rows->J1a : rows->J1l) + s;
    dReal *J2 = (rotational ? rows->J2a : rows->J2l) + s;
    dCopyVector3(J1, axis);
    if (b1) dCopyNegatedVector3(J2, axis);

    // A linear row between two bodies acts at the midpoint of their centres,
    // so the pair of forces creates no couple (no spurious angular momentum).
    if (!rotational && b1) {
        dVector3 half;
        dSubtractVectors3(half, b1->pos, b0->pos);
        dScaleVector3(half, REAL(0.5));
        dCalcVectorCross3(rows->J1a + s, half, axis);
        dCopyVector3(rows->J2a + s, rows->J1a + s);
    }

    dxLimotSetRow(lm, j, rows, row,
                  lm->limit && lm->bounce > 0 ? axis_velocity(j, axis, rotational) : 0);
    return 1;
}
