// SPDX-License-Identifier: BSD-3-Clause
//
// integrate.c -- moving bodies by their velocities at the end of a step:
// position, orientation (infinitesimal or finite rotation, guide 6.x),
// damping and the angular speed limit, notification of the collision library
// and the moved callback, and zeroing the force accumulators.

#include "step_internal.h"

#include <ode/rotation.h>

// sin(x)/x, accurate near 0.
static dReal sinc(dReal x)
{
    if (dFabs(x) < REAL(1.0e-4)) return REAL(1.0) - x * x / REAL(6.0);
    return dSin(x) / x;
}

// The unit quaternion of a rotation by vector v * h (angle |v| h about v).
static void rotation_quaternion(dQuaternion q, const dReal *v, dReal h)
{
    dReal half = REAL(0.5) * h;
    dReal theta = dCalcVectorLength3(v) * half;
    dReal s = sinc(theta) * half;
    q[0] = dCos(theta);
    q[1] = v[0] * s;
    q[2] = v[1] * s;
    q[3] = v[2] * s;
}

// q += h * dq/dt for angular velocity w (first order; normalised later).
// dq/dt = (-w.qv, q0 w + w x qv) / 2 with dDQfromW's products in its order
// (the same numbers, without its call and argument check: once a body and
// step).
static inline void infinitesimal_rotation(dQuaternion q, const dReal *w, dReal h)
{
    const dReal w0 = REAL(0.5) * w[0], w1 = REAL(0.5) * w[1], w2 = REAL(0.5) * w[2];
    const dReal q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
    q[0] = q0 + h * (-w0 * q1 - w1 * q2 - w2 * q3);
    q[1] = q1 + h * (w0 * q0 + w1 * q3 - w2 * q2);
    q[2] = q2 + h * (w1 * q0 + w2 * q1 - w0 * q3);
    q[3] = q3 + h * (w2 * q0 + w0 * q2 - w1 * q1);
}

// dNormalize4(q) for a body's quaternion: scaled by its largest component,
// then divided by its length, dNormalize4's operations in its order (the
// same numbers, inline); a zero or non-finite q (or a sum of components
// that overflows) goes to dNormalize4 itself, which reports it.
static inline void normalize_quaternion(dQuaternion q)
{
    const dReal sum = q[0] + q[1] + q[2] + q[3];
    dReal m = 0;
    for (int i = 0; i < 4; i++)
        if (dFabs(q[i]) > m) m = dFabs(q[i]);
    if (!(m > 0) || sum - sum != 0) {   // x - x is 0 for a finite x only
        dNormalize4(q);
        return;
    }
    const dReal s0 = q[0] / m, s1 = q[1] / m, s2 = q[2] / m, s3 = q[3] / m;
    const dReal len = dSqrt(s0 * s0 + s1 * s1 + s2 * s2 + s3 * s3);
    q[0] = s0 / len;
    q[1] = s1 / len;
    q[2] = s2 / len;
    q[3] = s3 / len;
}

// A body's position and quaternion moved by its velocities (the quaternion
// not yet normalised, the rotation matrix not yet made: orient).
static inline void advance(struct dxBody *b, dReal h)
{
    dAddVectorScaledVector3(b->pos, b->pos, b->lvel, h);

    if (b->flags & DX_BODY_FINITE_ROTATION) {
        // Finite rotation about the axis (or about w itself), and with an
        // axis the remaining part of w infinitesimally.
        const int axis = (b->flags & DX_BODY_FINITE_ROTATION_AXIS) != 0;
        dVector3 finite, rest = { 0, 0, 0 };
        if (axis) {
            dReal k = dCalcVectorDot3(b->finite_rot_axis, b->avel);
            dCopyScaledVector3(finite, b->finite_rot_axis, k);
            dSubtractVectors3(rest, b->avel, finite);
        } else {
            dCopyVector3(finite, b->avel);
        }
        dQuaternion r, q;
        rotation_quaternion(r, finite, h);
        dQMultiply0(q, r, b->q);
        dCopyVector4(b->q, q);
        if (axis) infinitesimal_rotation(b->q, rest, h);
    } else {
        infinitesimal_rotation(b->q, b->avel, h);
    }
}

// A moved body's quaternion normalised and its rotation matrix made from it.
static inline void orient(struct dxBody *b)
{
    normalize_quaternion(b->q);
    dxBodyUpdateRotation(b);
}

void dxBodyIntegrate(struct dxBody *b, dReal h)
{
    advance(b, h);
    orient(b);
}

// Damping (ODE 0.16): scale a velocity above its threshold by (1 - scale).
static void damp(struct dxBody *b)
{
    const dxDamping *d = &b->damping;
    if ((b->flags & DX_BODY_LINEAR_DAMPING) &&
        dCalcVectorLengthSquare3(b->lvel) > d->linear_threshold * d->linear_threshold)
        dScaleVector3(b->lvel, 1 - d->linear_scale);
    if ((b->flags & DX_BODY_ANGULAR_DAMPING) &&
        dCalcVectorLengthSquare3(b->avel) > d->angular_threshold * d->angular_threshold)
        dScaleVector3(b->avel, 1 - d->angular_scale);
    if (b->flags & DX_BODY_MAX_ANGULAR_SPEED) {
        dReal speed2 = dCalcVectorLengthSquare3(b->avel);
        if (speed2 > d->max_angular_speed * d->max_angular_speed)
            dScaleVector3(b->avel, d->max_angular_speed / dSqrt(speed2));
    }
}

// After a body moved: tell its geoms and its callback; clear the accumulators.
static void finish_body(struct dxBody *b)
{
    dxBodyNotifyMoved(b);
    if (b->moved_callback) b->moved_callback(b);
    dZeroVector3(b->force);
    dZeroVector3(b->torque);
}

void dxBodyMove(struct dxBody *b, dReal h)
{
    dxBodyGyroscopicEnd(b, h);
    damp(b);
    dxBodyIntegrate(b, h);
}

void dxBodyMoveAhead(struct dxBody *b, dReal h)
{
    dxBodyGyroscopicEnd(b, h);
    damp(b);
    advance(b, h);
}

void dxIslandMove(const dxIsland *is, dReal h)
{
    for (int i = 0; i < is->nb; i++) dxBodyMove(is->bodies[i], h);
}

void dxIslandFinish(const dxIsland *is)
{
    for (int i = 0; i < is->nb; i++) finish_body(is->bodies[i]);
}

void dxIslandRotateFinish(const dxIsland *is)
{
    for (int i = 0; i < is->nb; i++) {
        orient(is->bodies[i]);
        finish_body(is->bodies[i]);
    }
}

void dxIslandIntegrate(const dxIsland *is, dReal h)
{
    dxIslandMove(is, h);
    dxIslandCorrectPositions(is, h);
    dxIslandFinish(is);
}

void dxStepKinematicBodies(struct dxWorld *w, dReal h)
{
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        if ((b->flags & (DX_BODY_KINEMATIC | DX_BODY_DISABLED)) != DX_BODY_KINEMATIC) continue;
        dxBodyIntegrate(b, h);
        finish_body(b);
    }
}
