/* SPDX-License-Identifier: BSD-3-Clause */
/* rotation.h -- rotation matrices and quaternions (guide 9.1).
 * A quaternion is (w, x, y, z); a matrix is a dMatrix3 (3x4 row-major). */
#ifndef ODE_ROTATION_H
#define ODE_ROTATION_H

#include <ode/common.h>
#include <ode/compatibility.h>

#ifdef __cplusplus
extern "C" {
#endif

ODE_API void dRSetIdentity(dMatrix3 R);
/** Rotation by angle (radians, right-handed) about the axis (ax,ay,az), which
 *  need not be unit length. A zero axis is reported and gives the identity. */
ODE_API void dRFromAxisAndAngle(dMatrix3 R, dReal ax, dReal ay, dReal az, dReal angle);
/** Rotation from the Euler angles phi, theta, psi (ODE's convention). */
ODE_API void dRFromEulerAngles(dMatrix3 R, dReal phi, dReal theta, dReal psi);
/** Rotation whose x axis is a and whose y axis is b made perpendicular to a;
 *  z = x cross y. Parallel or zero vectors are reported, R is then unchanged. */
ODE_API void dRFrom2Axes(dMatrix3 R, dReal ax, dReal ay, dReal az, dReal bx, dReal by,
                         dReal bz);
/** A rotation whose z axis is a (x and y chosen by dPlaneSpace). */
ODE_API void dRFromZAxis(dMatrix3 R, dReal ax, dReal ay, dReal az);

ODE_API void dQSetIdentity(dQuaternion q);
ODE_API void dQFromAxisAndAngle(dQuaternion q, dReal ax, dReal ay, dReal az, dReal angle);
/** qa = qb*qc (rotation qc, then qb); 1 inverts qb, 2 inverts qc, 3 both.
 *  qa must not alias qb or qc. */
ODE_API void dQMultiply0(dQuaternion qa, const dQuaternion qb, const dQuaternion qc);
ODE_API void dQMultiply1(dQuaternion qa, const dQuaternion qb, const dQuaternion qc);
ODE_API void dQMultiply2(dQuaternion qa, const dQuaternion qb, const dQuaternion qc);
ODE_API void dQMultiply3(dQuaternion qa, const dQuaternion qb, const dQuaternion qc);
/** The matrix of a unit quaternion, and a quaternion of a rotation matrix
 *  (q and -q are the same rotation). */
ODE_API void dRfromQ(dMatrix3 R, const dQuaternion q);
ODE_API void dQfromR(dQuaternion q, const dMatrix3 R);
/** dq/dt of orientation q turning with angular velocity w (world frame). */
ODE_API void dDQfromW(dReal dq[4], const dVector3 w, const dQuaternion q);

#ifdef __cplusplus
}
#endif

#endif
