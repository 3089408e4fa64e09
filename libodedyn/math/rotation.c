// SPDX-License-Identifier: BSD-3-Clause
//
// rotation.c -- rotation matrices and unit quaternions (guide 9.1): building
// them from axes and angles, converting one into the other, composing
// quaternions, and the time derivative of an orientation.

#include "dx_check.h"

#include <ode/odemath.h>
#include <ode/rotation.h>

// Fill R row by row; the unused fourth column is written as 0.
static void set_rows(dMatrix3 R, dReal r00, dReal r01, dReal r02, dReal r10, dReal r11,
                     dReal r12, dReal r20, dReal r21, dReal r22)
{
    R[0] = r00; R[1] = r01; R[2] = r02; R[3] = 0;
    R[4] = r10; R[5] = r11; R[6] = r12; R[7] = 0;
    R[8] = r20; R[9] = r21; R[10] = r22; R[11] = 0;
}

void dRSetIdentity(dMatrix3 R)
{
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    set_rows(R, 1, 0, 0, 0, 1, 0, 0, 0, 1);
}

void dQSetIdentity(dQuaternion q)
{
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    q[0] = 1;
    q[1] = q[2] = q[3] = 0;
}

// q = rotation by angle about the axis a of any nonzero length:
// (cos(angle/2), sin(angle/2) a/|a|). Returns 0 (q untouched) if a is zero.
static int q_from_axis_angle(dQuaternion q, dReal ax, dReal ay, dReal az, dReal angle)
{
    dVector3 a = {ax, ay, az, 0};
    if (!dSafeNormalize3(a)) return 0;
    dReal h = angle * REAL(0.5), s = dSin(h);
    q[0] = dCos(h);
    q[1] = a[0] * s;
    q[2] = a[1] * s;
    q[3] = a[2] * s;
    return 1;
}

// The quaternion of a rotation by angle about (ax, ay, az); identity if the axis is zero.
void dQFromAxisAndAngle(dQuaternion q, dReal ax, dReal ay, dReal az, dReal angle)
{
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az) && dxIsFinite(angle), return,
                 "the axis (%g, %g, %g) or the angle %g is not finite", (double)ax, (double)ay,
                 (double)az, (double)angle);
    DX_WARN_ARG(q_from_axis_angle(q, ax, ay, az, angle), dQSetIdentity(q); return,
                 "the axis (%g, %g, %g) is zero; using the identity", (double)ax, (double)ay,
                 (double)az);
}

// The same rotation as a matrix, by way of the quaternion.
void dRFromAxisAndAngle(dMatrix3 R, dReal ax, dReal ay, dReal az, dReal angle)
{
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az) && dxIsFinite(angle), return,
                 "the axis (%g, %g, %g) or the angle %g is not finite", (double)ax, (double)ay,
                 (double)az, (double)angle);
    dQuaternion q;
    DX_WARN_ARG(q_from_axis_angle(q, ax, ay, az, angle), dRSetIdentity(R); return,
                 "the axis (%g, %g, %g) is zero; using the identity", (double)ax, (double)ay,
                 (double)az);
    dRfromQ(R, q);
}

// ODE's Euler convention: R = (Rz(psi) Ry(theta) Rx(phi))^T
//                           = Rx(-phi) Ry(-theta) Rz(-psi).
void dRFromEulerAngles(dMatrix3 R, dReal phi, dReal theta, dReal psi)
{
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    DX_CHECK_ARG(dxIsFinite3(phi, theta, psi), return, "phi %g, theta %g or psi %g is not finite",
                 (double)phi, (double)theta, (double)psi);
    dReal sphi = dSin(phi), cphi = dCos(phi);
    dReal stheta = dSin(theta), ctheta = dCos(theta);
    dReal spsi = dSin(psi), cpsi = dCos(psi);
    set_rows(R,
             cpsi * ctheta, spsi * ctheta, -stheta,
             cpsi * stheta * sphi - spsi * cphi, spsi * stheta * sphi + cpsi * cphi,
             ctheta * sphi,
             cpsi * stheta * cphi + spsi * sphi, spsi * stheta * cphi - cpsi * sphi,
             ctheta * cphi);
}

// The columns of R are a/|a|, the part of b perpendicular to a normalised, and
// their cross product: Gram-Schmidt on the rows of R^T.
void dRFrom2Axes(dMatrix3 R, dReal ax, dReal ay, dReal az, dReal bx, dReal by, dReal bz)
{
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az) && dxIsFinite3(bx, by, bz), return,
                 "a (%g, %g, %g) or b (%g, %g, %g) is not finite", (double)ax, (double)ay,
                 (double)az, (double)bx, (double)by, (double)bz);
    DX_WARN_ARG(ax != 0 || ay != 0 || az != 0, return, "the axis a is zero; R unchanged");
    dMatrix3 T = {ax, ay, az, 0, bx, by, bz, 0, 0, 0, 0, 0};
    DX_WARN_ARG(dOrthogonalizeR(T), return,
                "b (%g, %g, %g) is zero or parallel to a (%g, %g, %g); R unchanged", (double)bx, (double)by,
                 (double)bz, (double)ax, (double)ay, (double)az);
    set_rows(R, T[0], T[4], T[8], T[1], T[5], T[9], T[2], T[6], T[10]);
}

// The columns of R are two unit vectors perpendicular to a (from dPlaneSpace)
// and a/|a|, so R maps the z axis onto a.
void dRFromZAxis(dMatrix3 R, dReal ax, dReal ay, dReal az)
{
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    DX_CHECK_ARG(dxIsFinite3(ax, ay, az), return, "the axis (%g, %g, %g) is not finite",
                 (double)ax, (double)ay, (double)az);
    dVector3 n = {ax, ay, az, 0}, p, q;
    DX_WARN_ARG(dSafeNormalize3(n), return, "the axis (%g, %g, %g) is zero; R unchanged",
                (double)ax, (double)ay, (double)az);
    dPlaneSpace(n, p, q);
    set_rows(R, p[0], q[0], n[0], p[1], q[1], n[1], p[2], q[2], n[2]);
}

// Hamilton product qa = b*c of b = (b0, sb*bv) and c = (c0, sc*cv): sb, sc are
// +1 or -1, so -1 multiplies by a conjugate (the inverse of a unit quaternion).
static void q_multiply(dQuaternion qa, const dQuaternion qb, const dQuaternion qc, dReal sb,
                       dReal sc)
{
    dReal b0 = qb[0], b1 = sb * qb[1], b2 = sb * qb[2], b3 = sb * qb[3];
    dReal c0 = qc[0], c1 = sc * qc[1], c2 = sc * qc[2], c3 = sc * qc[3];
    // (b0 c0 - bv.cv, b0 cv + c0 bv + bv x cv)
    qa[0] = b0 * c0 - b1 * c1 - b2 * c2 - b3 * c3;
    qa[1] = b0 * c1 + b1 * c0 + b2 * c3 - b3 * c2;
    qa[2] = b0 * c2 + b2 * c0 + b3 * c1 - b1 * c3;
    qa[3] = b0 * c3 + b3 * c0 + b1 * c2 - b2 * c1;
}

// qa = qb qc, qb^-1 qc, qb qc^-1 and qb^-1 qc^-1 for the four forms.
void dQMultiply0(dQuaternion qa, const dQuaternion qb, const dQuaternion qc)
{
    DX_CHECK_ARG(qa != NULL && qb != NULL && qc != NULL, return, "qa, qb or qc is NULL");
    q_multiply(qa, qb, qc, 1, 1);
}

void dQMultiply1(dQuaternion qa, const dQuaternion qb, const dQuaternion qc)
{
    DX_CHECK_ARG(qa != NULL && qb != NULL && qc != NULL, return, "qa, qb or qc is NULL");
    q_multiply(qa, qb, qc, -1, 1);
}

void dQMultiply2(dQuaternion qa, const dQuaternion qb, const dQuaternion qc)
{
    DX_CHECK_ARG(qa != NULL && qb != NULL && qc != NULL, return, "qa, qb or qc is NULL");
    q_multiply(qa, qb, qc, 1, -1);
}

void dQMultiply3(dQuaternion qa, const dQuaternion qb, const dQuaternion qc)
{
    DX_CHECK_ARG(qa != NULL && qb != NULL && qc != NULL, return, "qa, qb or qc is NULL");
    q_multiply(qa, qb, qc, -1, -1);
}

// The rotation matrix of the unit quaternion (w, x, y, z).
void dRfromQ(dMatrix3 R, const dQuaternion q)
{
    DX_CHECK_ARG(R != NULL && q != NULL, return, "R or q is NULL");
    dReal w = q[0], x = q[1], y = q[2], z = q[3];
    dReal xx = 2 * x * x, yy = 2 * y * y, zz = 2 * z * z;
    dReal xy = 2 * x * y, xz = 2 * x * z, yz = 2 * y * z;
    dReal wx = 2 * w * x, wy = 2 * w * y, wz = 2 * w * z;
    set_rows(R,
             1 - yy - zz, xy - wz, xz + wy,
             xy + wz, 1 - xx - zz, yz - wx,
             xz - wy, yz + wx, 1 - xx - yy);
}

// Shepperd's method: 4w^2 = 1 + trace, 4x^2 = 1 + R00 - R11 - R22 (and the
// like for y, z). Take the component whose square is large (w when
// trace >= 0, else the one of the largest diagonal entry; either way it is
// at least 1/2) from its square root, and the other three from the
// off-diagonal sums and differences (4xy = R01 + R10, 4wx = R21 - R12, ...)
// divided by it, so nothing is divided by a small number.
void dQfromR(dQuaternion q, const dMatrix3 R)
{
    DX_CHECK_ARG(q != NULL && R != NULL, return, "q or R is NULL");
    dReal r00 = R[0], r01 = R[1], r02 = R[2];
    dReal r10 = R[4], r11 = R[5], r12 = R[6];
    dReal r20 = R[8], r21 = R[9], r22 = R[10];
    dReal tr = r00 + r11 + r22, s;
    if (tr >= 0) {
        s = dSqrt(tr + 1);
        q[0] = REAL(0.5) * s;
        s = REAL(0.5) / s;
        q[1] = (r21 - r12) * s;
        q[2] = (r02 - r20) * s;
        q[3] = (r10 - r01) * s;
        return;
    }
    // which of x, y, z has the largest magnitude: the largest diagonal entry
    int k = 0;
    if (r11 > r00) k = (r22 > r11) ? 2 : 1;
    else if (r22 > r00) k = 2;
    if (k == 0) {
        s = dSqrt((r00 - (r11 + r22)) + 1);
        q[1] = REAL(0.5) * s;
        s = REAL(0.5) / s;
        q[2] = (r01 + r10) * s;
        q[3] = (r20 + r02) * s;
        q[0] = (r21 - r12) * s;
    } else if (k == 1) {
        s = dSqrt((r11 - (r22 + r00)) + 1);
        q[2] = REAL(0.5) * s;
        s = REAL(0.5) / s;
        q[3] = (r12 + r21) * s;
        q[1] = (r01 + r10) * s;
        q[0] = (r02 - r20) * s;
    } else {
        s = dSqrt((r22 - (r00 + r11)) + 1);
        q[3] = REAL(0.5) * s;
        s = REAL(0.5) / s;
        q[1] = (r20 + r02) * s;
        q[2] = (r12 + r21) * s;
        q[0] = (r10 - r01) * s;
    }
}

// dq/dt = (1/2) (0, w) q for an angular velocity w in the world frame.
void dDQfromW(dReal dq[4], const dVector3 w, const dQuaternion q)
{
    DX_CHECK_ARG(dq != NULL && w != NULL && q != NULL, return, "dq, w or q is NULL");
    dReal w0 = REAL(0.5) * w[0], w1 = REAL(0.5) * w[1], w2 = REAL(0.5) * w[2];
    dReal q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
    // (-w.qv, q0 w + w x qv)
    dq[0] = -w0 * q1 - w1 * q2 - w2 * q3;
    dq[1] = w0 * q0 + w1 * q3 - w2 * q2;
    dq[2] = w1 * q0 + w2 * q1 - w0 * q3;
    dq[3] = w2 * q0 + w0 * q2 - w1 * q1;
}
