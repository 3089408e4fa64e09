// SPDX-License-Identifier: BSD-3-Clause
//
// body.c -- rigid bodies (guide chapter 6): creation, state, mass, forces,
// point and vector conversions, enabling, and the per-body parameters.
// Auto-disable and damping parameters are in body_params.c.

#include "collision_hooks.h"
#include "objects_internal.h"
#include "pool.h"

#include <ode/memory.h>
#include <ode/rotation.h>

#define CHECK_BODY(b, on_fail) \
    DX_CHECK_ARG(dxBodyIsLive(b), on_fail, "body is NULL or was destroyed")
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")

// R from q with dRfromQ's products in its order (the same numbers, without
// its call and argument check: once a body and step).
void dxBodyUpdateRotation(struct dxBody *b)
{
    const dReal w = b->q[0], x = b->q[1], y = b->q[2], z = b->q[3];
    const dReal xx = 2 * x * x, yy = 2 * y * y, zz = 2 * z * z;
    const dReal xy = 2 * x * y, xz = 2 * x * z, yz = 2 * y * z;
    const dReal wx = 2 * w * x, wy = 2 * w * y, wz = 2 * w * z;
    dReal *R = b->R;
    R[0] = 1 - yy - zz;
    R[1] = xy - wz;
    R[2] = xz + wy;
    R[3] = 0;
    R[4] = xy + wz;
    R[5] = 1 - xx - zz;
    R[6] = yz - wx;
    R[7] = 0;
    R[8] = xz - wy;
    R[9] = yz + wx;
    R[10] = 1 - xx - yy;
    R[11] = 0;
}

void dxBodyNotifyMoved(struct dxBody *b)
{
    for (dGeomID g = b->first_geom; g; g = dGeomGetBodyNext(g)) dGeomMoved(g);
}

dBodyID dBodyCreate(dWorldID w)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    struct dxBody *b = dxPoolTake(&dx_body_pool, sizeof *b);
    uint32_t generation = b->hdr.generation;
    memset(b, 0, sizeof *b);
    b->hdr.magic = DX_MAGIC_BODY;
    b->hdr.generation = generation + 1;
    b->world = w;
    dMassSetParameters(&b->mass, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0);
    b->inv_mass = 1;
    dRSetIdentity(b->inv_inertia);
    dQSetIdentity(b->q);
    dRSetIdentity(b->R);
    b->finite_rot_axis[0] = 0;
    dBodySetAutoDisableDefaults(b);
    dBodySetDampingDefaults(b);
    b->sf1_threshold = REAL(0.003);   // guide 8.4 defaults
    b->sf1_steps = 10;

    b->next = w->bodies;
    if (w->bodies) w->bodies->prev = b;
    w->bodies = b;
    w->num_bodies++;
    return b;
}

void dBodyDestroy(dBodyID b)
{
    CHECK_BODY(b, return);
    // Geoms first: the collision library unlinks each (read next before).
    for (dGeomID g = b->first_geom, next; g; g = next) {
        next = dGeomGetBodyNext(g);
        dGeomSetBody(g, 0);
    }
    b->first_geom = NULL;
    // Joints stay alive: detach them from this body (limbo if no body is left).
    while (b->joints) {
        dxJoint *j = b->joints->joint;
        struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
        int reversed = (j->flags & DX_JOINT_REVERSE) != 0;
        struct dxBody *first = reversed ? b1 : b0, *second = reversed ? b0 : b1;
        dJointAttach(j, first == b ? NULL : first, second == b ? NULL : second);
    }
    struct dxWorld *w = b->world;
    if (b->prev) b->prev->next = b->next;
    else w->bodies = b->next;
    if (b->next) b->next->prev = b->prev;
    w->num_bodies--;
    if (b->adis_lvel_samples) {
        dFree(b->adis_lvel_samples, b->adis_samples_size * sizeof(dReal));
        dFree(b->adis_avel_samples, b->adis_samples_size * sizeof(dReal));
    }
    b->hdr.magic = DX_MAGIC_DEAD;
    dxPoolGive(&dx_body_pool, b);
}

dWorldID dBodyGetWorld(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->world;
}

void dBodySetData(dBodyID b, void *data)
{
    CHECK_BODY(b, return);
    b->userdata = data;
}

void *dBodyGetData(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->userdata;
}

// ---- state ----------------------------------------------------------------

void dBodySetPosition(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "position is not finite");
    dAssignVector3(b->pos, x, y, z);
    dxBodyNotifyMoved(b);
}

void dBodySetRotation(dBodyID b, const dMatrix3 R)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(R != NULL, return, "R is NULL");
    DX_CHECK_ARG(dxIsFiniteMatrix3(R), return, "R is not finite");
    dMatrix3 clean;
    dxCopyMatrix3(clean, R);   // without the padding, which may be uninitialised
    DX_CHECK_ARG(dOrthogonalizeR(clean), return, "R is not a rotation (degenerate rows)");
    dQfromR(b->q, clean);
    dNormalize4(b->q);
    dxBodyUpdateRotation(b);
    b->gyro_pending = 0;   // a new rotational state: an empty gyroscopic ledger
    dxBodyNotifyMoved(b);
}

void dBodySetQuaternion(dBodyID b, const dQuaternion q)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(q != NULL, return, "q is NULL");
    DX_CHECK_ARG(dxIsFinite3(q[1], q[2], q[3]) && dxIsFinite(q[0]), return, "q is not finite");
    dQuaternion n = { q[0], q[1], q[2], q[3] };
    DX_CHECK_ARG(dSafeNormalize4(n), return, "q has zero length");
    dCopyVector4(b->q, n);
    dxBodyUpdateRotation(b);
    b->gyro_pending = 0;
    dxBodyNotifyMoved(b);
}

void dBodySetLinearVel(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "velocity is not finite");
    dAssignVector3(b->lvel, x, y, z);
}

void dBodySetAngularVel(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "angular velocity is not finite");
    dAssignVector3(b->avel, x, y, z);
    b->gyro_pending = 0;
}

const dReal *dBodyGetPosition(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->pos;
}

void dBodyCopyPosition(dBodyID b, dVector3 pos)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(pos, return);
    dCopyVector3(pos, b->pos);
}

const dReal *dBodyGetRotation(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->R;
}

void dBodyCopyRotation(dBodyID b, dMatrix3 R)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(R, return);
    dCopyMatrix4x3(R, b->R);
}

const dReal *dBodyGetQuaternion(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->q;
}

void dBodyCopyQuaternion(dBodyID b, dQuaternion q)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(q, return);
    dCopyVector4(q, b->q);
}

const dReal *dBodyGetLinearVel(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->lvel;
}

const dReal *dBodyGetAngularVel(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->avel;
}

// ---- mass -------------------------------------------------------------------

void dBodySetMass(dBodyID b, const dMass *m)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(m != NULL, return, "mass is NULL");
    DX_CHECK_ARG(dMassCheck(m), return, "mass is not valid (see dMassCheck)");
    const dReal tol = 1e-4 * (1 + dFabs(m->c[0]) + dFabs(m->c[1]) + dFabs(m->c[2]));
    DX_CHECK_ARG(dFabs(m->c[0]) <= tol && dFabs(m->c[1]) <= tol && dFabs(m->c[2]) <= tol,
                 return, "mass has its centre of mass at (%g, %g, %g): it must be at the body "
                 "origin (translate the geoms instead)",
                 (double)m->c[0], (double)m->c[1], (double)m->c[2]);
    dMatrix3 inv = { 0 };   // (dInvertMatrix3 leaves the padding: zero in the snapshot)
    DX_CHECK_ARG(dInvertMatrix3(inv, m->I) != 0, return, "inertia is singular");
    b->mass = *m;
    // The centre at the origin, and the padding a dMass filled by hand may
    // leave unset zeroed, so that a snapshot's bytes depend on the state alone.
    b->mass.c[0] = b->mass.c[1] = b->mass.c[2] = b->mass.c[3] = 0;
    b->mass.I[3] = b->mass.I[7] = b->mass.I[11] = 0;
    b->inv_mass = dRecip(m->mass);
    dCopyMatrix4x3(b->inv_inertia, inv);
    b->gyro_pending = 0;
}

void dBodyGetMass(dBodyID b, dMass *m)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(m != NULL, return, "mass (the result) is NULL");
    *m = b->mass;
}

// ---- forces ----------------------------------------------------------------

#define CHECK_FORCE(x, y, z, on_fail) \
    DX_CHECK_ARG(dxIsFinite3(x, y, z), on_fail, "force or torque is not finite")
#define CHECK_POINT(x, y, z, on_fail) \
    DX_CHECK_ARG(dxIsFinite3(x, y, z), on_fail, "point is not finite")

// force f at world point p: adds f and (p - pos) x f.
static void add_force_at(struct dxBody *b, const dReal f[3], const dReal p[3])
{
    dVector3 r;
    dSubtractVectors3(r, p, b->pos);
    dAddVectors3(b->force, b->force, f);
    dAddVectorCross3(b->torque, r, f);
}

void dBodyAddForce(dBodyID b, dReal fx, dReal fy, dReal fz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    b->force[0] += fx; b->force[1] += fy; b->force[2] += fz;
}

void dBodyAddTorque(dBodyID b, dReal fx, dReal fy, dReal fz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    b->torque[0] += fx; b->torque[1] += fy; b->torque[2] += fz;
}

void dBodyAddRelForce(dBodyID b, dReal fx, dReal fy, dReal fz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    dVector3 f = { fx, fy, fz, 0 };
    dMultiplyAdd0_331(b->force, b->R, f);
}

void dBodyAddRelTorque(dBodyID b, dReal fx, dReal fy, dReal fz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    dVector3 t = { fx, fy, fz, 0 };
    dMultiplyAdd0_331(b->torque, b->R, t);
}

void dBodyAddForceAtPos(dBodyID b, dReal fx, dReal fy, dReal fz, dReal px, dReal py, dReal pz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    CHECK_POINT(px, py, pz, return);
    dVector3 f = { fx, fy, fz, 0 }, p = { px, py, pz, 0 };
    add_force_at(b, f, p);
}

void dBodyAddForceAtRelPos(dBodyID b, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                           dReal pz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    CHECK_POINT(px, py, pz, return);
    dVector3 f = { fx, fy, fz, 0 }, prel = { px, py, pz, 0 }, p;
    dMultiply0_331(p, b->R, prel);
    dAddVectors3(p, p, b->pos);
    add_force_at(b, f, p);
}

void dBodyAddRelForceAtPos(dBodyID b, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                           dReal pz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    CHECK_POINT(px, py, pz, return);
    dVector3 frel = { fx, fy, fz, 0 }, f, p = { px, py, pz, 0 };
    dMultiply0_331(f, b->R, frel);
    add_force_at(b, f, p);
}

void dBodyAddRelForceAtRelPos(dBodyID b, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                              dReal pz)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(fx, fy, fz, return);
    CHECK_POINT(px, py, pz, return);
    dVector3 frel = { fx, fy, fz, 0 }, prel = { px, py, pz, 0 }, f, p;
    dMultiply0_331(f, b->R, frel);
    dMultiply0_331(p, b->R, prel);
    dAddVectors3(p, p, b->pos);
    add_force_at(b, f, p);
}

const dReal *dBodyGetForce(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->force;
}

const dReal *dBodyGetTorque(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->torque;
}

void dBodySetForce(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(x, y, z, return);
    dAssignVector3(b->force, x, y, z);
}

void dBodySetTorque(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    CHECK_FORCE(x, y, z, return);
    dAssignVector3(b->torque, x, y, z);
}

// ---- conversions (guide 6.4) --------------------------------------------

void dBodyGetRelPointPos(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 prel = { px, py, pz, 0 };
    dMultiply0_331(result, b->R, prel);
    dAddVectors3(result, result, b->pos);
}

void dBodyGetRelPointVel(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 prel = { px, py, pz, 0 }, r;
    dMultiply0_331(r, b->R, prel);
    dCalcVectorCross3(result, b->avel, r);
    dAddVectors3(result, result, b->lvel);
}

void dBodyGetPointVel(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 r = { px - b->pos[0], py - b->pos[1], pz - b->pos[2], 0 };
    dCalcVectorCross3(result, b->avel, r);
    dAddVectors3(result, result, b->lvel);
}

void dBodyGetPosRelPoint(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 r = { px - b->pos[0], py - b->pos[1], pz - b->pos[2], 0 };
    dMultiply1_331(result, b->R, r);
}

void dBodyVectorToWorld(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 v = { px, py, pz, 0 };
    dMultiply0_331(result, b->R, v);
}

void dBodyVectorFromWorld(dBodyID b, dReal px, dReal py, dReal pz, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dVector3 v = { px, py, pz, 0 };
    dMultiply1_331(result, b->R, v);
}

// ---- modes ------------------------------------------------------------------

void dBodySetFiniteRotationMode(dBodyID b, int mode)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(mode == 0 || mode == 1, return, "mode must be 0 or 1, got %d", mode);
    b->flags &= ~(unsigned)(DX_BODY_FINITE_ROTATION | DX_BODY_FINITE_ROTATION_AXIS);
    if (mode) {
        b->flags |= DX_BODY_FINITE_ROTATION;
        if (dCalcVectorLengthSquare3(b->finite_rot_axis) > 0)
            b->flags |= DX_BODY_FINITE_ROTATION_AXIS;
    }
}

void dBodySetFiniteRotationAxis(dBodyID b, dReal x, dReal y, dReal z)
{
    CHECK_BODY(b, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "axis is not finite");
    dAssignVector3(b->finite_rot_axis, x, y, z);
    if (dCalcVectorLengthSquare3(b->finite_rot_axis) > 0) {
        dNormalize3(b->finite_rot_axis);
        b->flags |= DX_BODY_FINITE_ROTATION_AXIS;
    } else {
        b->flags &= ~(unsigned)DX_BODY_FINITE_ROTATION_AXIS;
    }
}

int dBodyGetFiniteRotationMode(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_FINITE_ROTATION) != 0;
}

void dBodyGetFiniteRotationAxis(dBodyID b, dVector3 result)
{
    CHECK_BODY(b, return);
    CHECK_RESULT(result, return);
    dCopyVector3(result, b->finite_rot_axis);
}

int dBodyGetNumJoints(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return b->num_joints;
}

dJointID dBodyGetJoint(dBodyID b, int index)
{
    CHECK_BODY(b, return NULL);
    DX_CHECK_ARG(index >= 0 && index < b->num_joints, return NULL,
                 "index %d is out of range (the body has %d joints)", index, b->num_joints);
    dxJointNode *n = b->joints;
    for (int i = 0; i < index; i++) n = n->next;
    return n->joint;
}

void dBodySetDynamic(dBodyID b)
{
    CHECK_BODY(b, return);
    b->flags &= ~(unsigned)DX_BODY_KINEMATIC;
}

void dBodySetKinematic(dBodyID b)
{
    CHECK_BODY(b, return);
    b->flags |= DX_BODY_KINEMATIC;
}

int dBodyIsKinematic(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_KINEMATIC) != 0;
}

void dBodyEnable(dBodyID b)
{
    CHECK_BODY(b, return);
    b->flags &= ~(unsigned)DX_BODY_DISABLED;
    b->adis_idle_steps = 0;
    b->adis_idle_time = 0;
    b->adis_samples_taken = 0;
    b->sf1_idle_steps = 0;
}

void dBodyDisable(dBodyID b)
{
    CHECK_BODY(b, return);
    b->flags |= DX_BODY_DISABLED;
}

int dBodyIsEnabled(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_DISABLED) == 0;
}

void dBodySetGravityMode(dBodyID b, int mode)
{
    CHECK_BODY(b, return);
    if (mode) b->flags &= ~(unsigned)DX_BODY_NO_GRAVITY;
    else b->flags |= DX_BODY_NO_GRAVITY;
}

int dBodyGetGravityMode(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_NO_GRAVITY) == 0;
}

void dBodySetMovedCallback(dBodyID b, void (*callback)(dBodyID))
{
    CHECK_BODY(b, return);
    b->moved_callback = callback;
}

dGeomID dBodyGetFirstGeom(dBodyID b)
{
    CHECK_BODY(b, return NULL);
    return b->first_geom;
}

dGeomID dBodyGetNextGeom(dGeomID g) { return dGeomGetBodyNext(g); }

void dBodySetFirstGeom(dBodyID b, dGeomID geom)
{
    CHECK_BODY(b, return);
    b->first_geom = geom;
}

int dBodyGetGyroscopicMode(dBodyID b)
{
    CHECK_BODY(b, return 0);
    return (b->flags & DX_BODY_NO_GYROSCOPIC) == 0;
}

void dBodySetGyroscopicMode(dBodyID b, int enabled)
{
    CHECK_BODY(b, return);
    if (enabled) b->flags &= ~(unsigned)DX_BODY_NO_GYROSCOPIC;
    else b->flags |= DX_BODY_NO_GYROSCOPIC;
}
