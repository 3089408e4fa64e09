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
static void infinitesimal_rotation(dQuaternion q, const dReal *w, dReal h)
{
    dReal dq[4];
    dDQfromW(dq, w, q);
    for (int i = 0; i < 4; i++) q[i] += h * dq[i];
}

void dxBodyIntegrate(struct dxBody *b, dReal h)
{
    dAddVectorScaledVector3(b->pos, b->pos, b->lvel, h);

    if (b->flags & DX_BODY_FINITE_ROTATION) {
        // Finite rotation about the axis (or about w itself), and with an
        // axis the remaining part of w infinitesimally.
        dVector3 finite, rest;
        if (b->flags & DX_BODY_FINITE_ROTATION_AXIS) {
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
        if (b->flags & DX_BODY_FINITE_ROTATION_AXIS) infinitesimal_rotation(b->q, rest, h);
    } else {
        infinitesimal_rotation(b->q, b->avel, h);
    }
    dNormalize4(b->q);
    dxBodyUpdateRotation(b);
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

void dxIslandMove(const dxIsland *is, dReal h)
{
    for (int i = 0; i < is->nb; i++) {
        struct dxBody *b = is->bodies[i];
        dxBodyGyroscopicEnd(b, h);
        damp(b);
        dxBodyIntegrate(b, h);
    }
}

void dxIslandFinish(const dxIsland *is)
{
    for (int i = 0; i < is->nb; i++) finish_body(is->bodies[i]);
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
