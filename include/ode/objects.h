/* SPDX-License-Identifier: BSD-3-Clause */
/* objects.h -- worlds, rigid bodies, joints and joint groups (guide chapters
 * 5 to 8), in the dynamics library.
 *
 * Every function checks its handles and numbers: a NULL or destroyed ID, a
 * non-finite value, an out-of-range parameter is reported through the debug
 * handler naming the function and the argument (error.h), and the call then
 * has no effect (getters return 0). Frames: "world" unless a name says Rel. */
#ifndef ODE_OBJECTS_H
#define ODE_OBJECTS_H

#include <ode/common.h>
#include <ode/mass.h>
#include <ode/contact.h>
#include <ode/threading.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- World (chapter 5) ------------------------------------------------ */

ODE_API dWorldID dWorldCreate(void);
/** Destroys the world, its bodies and its joints that are in no group; joints
 *  in groups are deactivated (destroyed when their group is emptied). */
ODE_API void dWorldDestroy(dWorldID world);
ODE_API void dWorldSetData(dWorldID world, void *data);
ODE_API void *dWorldGetData(dWorldID world);
/** m/s^2; default (0,0,0). */
ODE_API void dWorldSetGravity(dWorldID, dReal x, dReal y, dReal z);
ODE_API void dWorldGetGravity(dWorldID, dVector3 gravity);
/** Global error reduction parameter, 0..1; default 0.2. */
ODE_API void dWorldSetERP(dWorldID, dReal erp);
ODE_API dReal dWorldGetERP(dWorldID);
/** Global constraint force mixing, >= 0; default 1e-5 (single) or 1e-10 (double). */
ODE_API void dWorldSetCFM(dWorldID, dReal cfm);
ODE_API dReal dWorldGetCFM(dWorldID);

/* ---- Stepping threads and working memory (ODE 0.16) ------------------- */

#define dWORLDSTEP_THREADCOUNT_UNLIMITED dTHREADING_THREAD_COUNT_UNLIMITED

/** At most count threads step the world's islands at once (default
 *  dWORLDSTEP_THREADCOUNT_UNLIMITED: as many as the threading implementation
 *  has). Each thread gets its own working memory. */
ODE_API void dWorldSetStepIslandsProcessingMaxThreadCount(dWorldID w, unsigned count);
ODE_API unsigned dWorldGetStepIslandsProcessingMaxThreadCount(dWorldID w);
/** Step w with the working memory (arena, reservation policy, memory manager)
 *  of from_world; the two must then not be stepped at the same time. Only for
 *  a world without working memory yet (never stepped, no policy or manager
 *  set). from_world NULL: w leaves the sharing and returns to defaults.
 *  Returns 1, or 0 on failure. */
ODE_API int dWorldUseSharedWorkingMemory(dWorldID w, dWorldID from_world);
/** Free the working memory (of every world sharing it); the policy, the
 *  memory manager and the sharing stay. */
ODE_API void dWorldCleanupWorkingMemory(dWorldID w);

#define dWORLDSTEP_RESERVEFACTOR_DEFAULT 1.2f
#define dWORLDSTEP_RESERVESIZE_DEFAULT 65536U

/** Working memory grows to reserve_factor (>= 1) times what a step needed,
 *  and to at least reserve_minimum bytes. */
typedef struct {
    unsigned struct_size;
    float reserve_factor;
    unsigned reserve_minimum;
} dWorldStepReserveInfo;

/** NULL: the defaults above. Returns 1, or 0 on failure. */
ODE_API int dWorldSetStepMemoryReservationPolicy(dWorldID w,
                                                 const dWorldStepReserveInfo *policyinfo);

/** The functions that allocate and free the blocks of a world's working memory
 *  (shrink_block keeps a block's head; the working memory only grows, so it
 *  may be NULL). */
typedef struct {
    unsigned struct_size;
    void *(*alloc_block)(dsizeint block_size);
    void *(*shrink_block)(void *block_pointer, dsizeint block_current_size,
                          dsizeint block_smaller_size);
    void (*free_block)(void *block_pointer, dsizeint block_current_size);
} dWorldStepMemoryFunctionsInfo;

/** NULL: dAlloc and dFree. The working memory allocated so far is freed with
 *  the functions that allocated it. Returns 1, or 0 on failure. */
ODE_API int dWorldSetStepMemoryManager(dWorldID w, const dWorldStepMemoryFunctionsInfo *memfuncs);

/** dWorldStep and dWorldQuickStep run on threading_impl's threads (NULL,
 *  NULL: on the caller's): with more than one thread, islands are stepped in
 *  parallel, with results identical to the bit to a step on one thread. */
ODE_API void dWorldSetStepThreadingImplementation(dWorldID w,
                                                  const dThreadingFunctionsInfo *functions_info,
                                                  dThreadingImplementationID threading_impl);

/** Step with the big-matrix LCP method (accurate, O(m^3)). Returns 1, or 0 if
 *  the step was refused (bad step size). */
ODE_API int dWorldStep(dWorldID w, dReal stepsize);
/** Step with the iterative SOR / projected Gauss-Seidel method (O(m N)). */
ODE_API int dWorldQuickStep(dWorldID w, dReal stepsize);
/** Step with the StepFast1 method of chapter 8 (per-joint iterations). */
ODE_API void dWorldStepFast1(dWorldID w, dReal stepsize, int maxiterations);
/** The force that applies impulse (ix,iy,iz) over one step of stepsize. */
ODE_API void dWorldImpulseToForce(dWorldID, dReal stepsize, dReal ix, dReal iy, dReal iz,
                                  dVector3 force);
/** QuickStep iterations, default 20. */
ODE_API void dWorldSetQuickStepNumIterations(dWorldID, int num);
ODE_API int dWorldGetQuickStepNumIterations(dWorldID);
/** QuickStep successive over-relaxation factor, default 1.3. */
ODE_API void dWorldSetQuickStepW(dWorldID, dReal over_relaxation);
ODE_API dReal dWorldGetQuickStepW(dWorldID);
/** Largest velocity contacts may use to correct penetration; default dInfinity. */
ODE_API void dWorldSetContactMaxCorrectingVel(dWorldID, dReal vel);
ODE_API dReal dWorldGetContactMaxCorrectingVel(dWorldID);
/** Penetration depth allowed before contacts push back; default 0. */
ODE_API void dWorldSetContactSurfaceLayer(dWorldID, dReal depth);
ODE_API dReal dWorldGetContactSurfaceLayer(dWorldID);

/* Auto-disable defaults for new bodies (guide 5.x): flag 0, linear and angular
 * thresholds 0.01, 10 steps, time 0, averaging over 1 sample. */
ODE_API dReal dWorldGetAutoDisableLinearThreshold(dWorldID);
ODE_API void dWorldSetAutoDisableLinearThreshold(dWorldID, dReal linear_threshold);
ODE_API dReal dWorldGetAutoDisableAngularThreshold(dWorldID);
ODE_API void dWorldSetAutoDisableAngularThreshold(dWorldID, dReal angular_threshold);
ODE_API int dWorldGetAutoDisableAverageSamplesCount(dWorldID);
ODE_API void dWorldSetAutoDisableAverageSamplesCount(dWorldID, unsigned int average_samples_count);
ODE_API int dWorldGetAutoDisableSteps(dWorldID);
ODE_API void dWorldSetAutoDisableSteps(dWorldID, int steps);
ODE_API dReal dWorldGetAutoDisableTime(dWorldID);
ODE_API void dWorldSetAutoDisableTime(dWorldID, dReal time);
ODE_API int dWorldGetAutoDisableFlag(dWorldID);
ODE_API void dWorldSetAutoDisableFlag(dWorldID, int do_auto_disable);

/* StepFast1 auto-disable (guide 8.5). */
ODE_API void dWorldSetAutoEnableDepthSF1(dWorldID, int autoEnableDepth);
ODE_API int dWorldGetAutoEnableDepthSF1(dWorldID);

/* Damping (ODE 0.16): velocities are scaled by (1 - scale) each step when
 * above the thresholds; defaults 0 (off) and thresholds 0.01. */
ODE_API dReal dWorldGetLinearDampingThreshold(dWorldID w);
ODE_API void dWorldSetLinearDampingThreshold(dWorldID w, dReal threshold);
ODE_API dReal dWorldGetAngularDampingThreshold(dWorldID w);
ODE_API void dWorldSetAngularDampingThreshold(dWorldID w, dReal threshold);
ODE_API dReal dWorldGetLinearDamping(dWorldID w);
ODE_API void dWorldSetLinearDamping(dWorldID w, dReal scale);
ODE_API dReal dWorldGetAngularDamping(dWorldID w);
ODE_API void dWorldSetAngularDamping(dWorldID w, dReal scale);
ODE_API void dWorldSetDamping(dWorldID w, dReal linear_scale, dReal angular_scale);
/** Clamp of a body's angular speed after each step; default dInfinity (off). */
ODE_API dReal dWorldGetMaxAngularSpeed(dWorldID w);
ODE_API void dWorldSetMaxAngularSpeed(dWorldID w, dReal max_speed);

/* ---- Bodies (chapter 6) ----------------------------------------------- */

ODE_API dBodyID dBodyCreate(dWorldID);
/** Joints attached to the body stay, detached from it ("limbo" if no body is
 *  left); attached geoms are told through dGeomSetBody(g, 0). */
ODE_API void dBodyDestroy(dBodyID);
ODE_API dWorldID dBodyGetWorld(dBodyID);
ODE_API void dBodySetData(dBodyID, void *data);
ODE_API void *dBodyGetData(dBodyID);

ODE_API void dBodySetPosition(dBodyID, dReal x, dReal y, dReal z);
/** R must be a rotation; it is re-orthonormalised and kept with the quaternion. */
ODE_API void dBodySetRotation(dBodyID, const dMatrix3 R);
/** q is normalised first. */
ODE_API void dBodySetQuaternion(dBodyID, const dQuaternion q);
ODE_API void dBodySetLinearVel(dBodyID, dReal x, dReal y, dReal z);
ODE_API void dBodySetAngularVel(dBodyID, dReal x, dReal y, dReal z);
/* The getters return pointers into the body, valid until it changes. */
ODE_API const dReal *dBodyGetPosition(dBodyID);
ODE_API void dBodyCopyPosition(dBodyID body, dVector3 pos);
ODE_API const dReal *dBodyGetRotation(dBodyID);
ODE_API void dBodyCopyRotation(dBodyID, dMatrix3 R);
ODE_API const dReal *dBodyGetQuaternion(dBodyID);
ODE_API void dBodyCopyQuaternion(dBodyID body, dQuaternion quat);
ODE_API const dReal *dBodyGetLinearVel(dBodyID);
ODE_API const dReal *dBodyGetAngularVel(dBodyID);

/** The mass must pass dMassCheck and have its centre of mass at the body
 *  origin (translate the body's geoms instead, as ODE requires). */
ODE_API void dBodySetMass(dBodyID, const dMass *mass);
ODE_API void dBodyGetMass(dBodyID, dMass *mass);

/* Forces and torques accumulate until the next step, which zeroes them. */
ODE_API void dBodyAddForce(dBodyID, dReal fx, dReal fy, dReal fz);
ODE_API void dBodyAddTorque(dBodyID, dReal fx, dReal fy, dReal fz);
ODE_API void dBodyAddRelForce(dBodyID, dReal fx, dReal fy, dReal fz);
ODE_API void dBodyAddRelTorque(dBodyID, dReal fx, dReal fy, dReal fz);
ODE_API void dBodyAddForceAtPos(dBodyID, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                                dReal pz);
ODE_API void dBodyAddForceAtRelPos(dBodyID, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                                   dReal pz);
ODE_API void dBodyAddRelForceAtPos(dBodyID, dReal fx, dReal fy, dReal fz, dReal px, dReal py,
                                   dReal pz);
ODE_API void dBodyAddRelForceAtRelPos(dBodyID, dReal fx, dReal fy, dReal fz, dReal px,
                                      dReal py, dReal pz);
ODE_API const dReal *dBodyGetForce(dBodyID);
ODE_API const dReal *dBodyGetTorque(dBodyID);
ODE_API void dBodySetForce(dBodyID b, dReal x, dReal y, dReal z);
ODE_API void dBodySetTorque(dBodyID b, dReal x, dReal y, dReal z);

/* Point and vector conversions (guide 6.4). */
ODE_API void dBodyGetRelPointPos(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dBodyGetRelPointVel(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dBodyGetPointVel(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dBodyGetPosRelPoint(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dBodyVectorToWorld(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);
ODE_API void dBodyVectorFromWorld(dBodyID, dReal px, dReal py, dReal pz, dVector3 result);

/** 0: infinitesimal orientation update (default); 1: finite rotation, about
 *  the finite rotation axis if one is set (0,0,0 = none). */
ODE_API void dBodySetFiniteRotationMode(dBodyID, int mode);
ODE_API void dBodySetFiniteRotationAxis(dBodyID, dReal x, dReal y, dReal z);
ODE_API int dBodyGetFiniteRotationMode(dBodyID);
ODE_API void dBodyGetFiniteRotationAxis(dBodyID, dVector3 result);

ODE_API int dBodyGetNumJoints(dBodyID b);
ODE_API dJointID dBodyGetJoint(dBodyID, int index);

/** Kinematic bodies (ODE 0.16) move with their velocity and ignore forces and joints' pull. */
ODE_API void dBodySetDynamic(dBodyID);
ODE_API void dBodySetKinematic(dBodyID);
ODE_API int dBodyIsKinematic(dBodyID);

/** A disabled body is not stepped; it is re-enabled when a joint connects it
 *  to an enabled body at the next step. */
ODE_API void dBodyEnable(dBodyID);
ODE_API void dBodyDisable(dBodyID);
ODE_API int dBodyIsEnabled(dBodyID);
/** 1 (default): the world's gravity acts on the body; 0: it does not. */
ODE_API void dBodySetGravityMode(dBodyID b, int mode);
ODE_API int dBodyGetGravityMode(dBodyID b);
/** Called after each step in which the body moved. */
ODE_API void dBodySetMovedCallback(dBodyID b, void (*callback)(dBodyID));

/** The first geom attached to the body, for the collision library; walk the
 *  rest with dGeomGetBodyNext (or dBodyGetNextGeom). */
ODE_API dGeomID dBodyGetFirstGeom(dBodyID b);
ODE_API dGeomID dBodyGetNextGeom(dGeomID g);
/** The one setter the collision library uses to keep the head of a body's
 *  geom list (this library never looks inside a geom). Not for programs. */
ODE_API void dBodySetFirstGeom(dBodyID b, dGeomID geom);

ODE_API dReal dBodyGetAutoDisableLinearThreshold(dBodyID);
ODE_API void dBodySetAutoDisableLinearThreshold(dBodyID, dReal linear_threshold);
ODE_API dReal dBodyGetAutoDisableAngularThreshold(dBodyID);
ODE_API void dBodySetAutoDisableAngularThreshold(dBodyID, dReal angular_threshold);
ODE_API int dBodyGetAutoDisableAverageSamplesCount(dBodyID);
ODE_API void dBodySetAutoDisableAverageSamplesCount(dBodyID, unsigned int average_samples_count);
ODE_API int dBodyGetAutoDisableSteps(dBodyID);
ODE_API void dBodySetAutoDisableSteps(dBodyID, int steps);
ODE_API dReal dBodyGetAutoDisableTime(dBodyID);
ODE_API void dBodySetAutoDisableTime(dBodyID, dReal time);
ODE_API int dBodyGetAutoDisableFlag(dBodyID);
ODE_API void dBodySetAutoDisableFlag(dBodyID, int do_auto_disable);
/** Copy the world's auto-disable settings into the body. */
ODE_API void dBodySetAutoDisableDefaults(dBodyID);

/* StepFast1 auto-disable (guide 8.5). */
ODE_API void dBodySetAutoDisableThresholdSF1(dBodyID, dReal autoDisableThreshold);
ODE_API dReal dBodyGetAutoDisableThresholdSF1(dBodyID);
ODE_API void dBodySetAutoDisableStepsSF1(dBodyID, int AutoDisableSteps);
ODE_API int dBodyGetAutoDisableStepsSF1(dBodyID);
ODE_API void dBodySetAutoDisableSF1(dBodyID, int doAutoDisable);
ODE_API int dBodyGetAutoDisableSF1(dBodyID);

ODE_API void dBodySetDampingDefaults(dBodyID b);
ODE_API dReal dBodyGetLinearDamping(dBodyID b);
ODE_API void dBodySetLinearDamping(dBodyID b, dReal scale);
ODE_API dReal dBodyGetAngularDamping(dBodyID b);
ODE_API void dBodySetAngularDamping(dBodyID b, dReal scale);
ODE_API void dBodySetDamping(dBodyID b, dReal linear_scale, dReal angular_scale);
ODE_API dReal dBodyGetLinearDampingThreshold(dBodyID b);
ODE_API void dBodySetLinearDampingThreshold(dBodyID b, dReal threshold);
ODE_API dReal dBodyGetAngularDampingThreshold(dBodyID b);
ODE_API void dBodySetAngularDampingThreshold(dBodyID b, dReal threshold);
ODE_API dReal dBodyGetMaxAngularSpeed(dBodyID b);
ODE_API void dBodySetMaxAngularSpeed(dBodyID b, dReal max_speed);
/** 1 (default): the gyroscopic term is integrated; 0: it is left out. */
ODE_API int dBodyGetGyroscopicMode(dBodyID b);
ODE_API void dBodySetGyroscopicMode(dBodyID b, int enabled);

/* ---- Joints (chapter 7) ----------------------------------------------- */

/* Create a joint in the world; with a group, the group owns it (dJointGroupEmpty). */
ODE_API dJointID dJointCreateBall(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateHinge(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateSlider(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateContact(dWorldID, dJointGroupID, const dContact *);
ODE_API dJointID dJointCreateHinge2(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateUniversal(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateFixed(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateNull(dWorldID, dJointGroupID);
ODE_API dJointID dJointCreateAMotor(dWorldID, dJointGroupID);
ODE_API void dJointDestroy(dJointID);

/** max_size is ignored (kept for ODE 0.5 programs): groups grow as needed. */
ODE_API dJointGroupID dJointGroupCreate(int max_size);
ODE_API void dJointGroupDestroy(dJointGroupID);
/** Destroy every joint in the group; cheap for thousands of contacts. */
ODE_API void dJointGroupEmpty(dJointGroupID);

/** body1 or body2 may be 0 (the static environment); both 0 = limbo. */
ODE_API void dJointAttach(dJointID, dBodyID body1, dBodyID body2);
ODE_API int dJointGetNumBodies(dJointID);
ODE_API void dJointEnable(dJointID);
ODE_API void dJointDisable(dJointID);
ODE_API int dJointIsEnabled(dJointID);
ODE_API void dJointSetData(dJointID, void *data);
ODE_API void *dJointGetData(dJointID);
ODE_API dJointType dJointGetType(dJointID);
/** index 0: body1 of dJointAttach, 1: body2. */
ODE_API dBodyID dJointGetBody(dJointID, int index);
ODE_API void dJointSetFeedback(dJointID, dJointFeedback *);
ODE_API dJointFeedback *dJointGetFeedback(dJointID);

/* Geometry setters take world coordinates and should be called after the
 * joint is attached and the bodies are placed; the current relative position
 * becomes the zero angle or position. Axes are normalised. */
ODE_API void dJointSetBallAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetBallAnchor2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetBallParam(dJointID, int parameter, dReal value);
ODE_API void dJointSetHingeAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetHingeAnchorDelta(dJointID, dReal x, dReal y, dReal z, dReal ax, dReal ay,
                                       dReal az);
ODE_API void dJointSetHingeAxis(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetHingeAxisOffset(dJointID j, dReal x, dReal y, dReal z, dReal angle);
ODE_API void dJointSetHingeParam(dJointID, int parameter, dReal value);
ODE_API void dJointAddHingeTorque(dJointID joint, dReal torque);
ODE_API void dJointSetSliderAxis(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetSliderAxisDelta(dJointID, dReal x, dReal y, dReal z, dReal ax, dReal ay,
                                      dReal az);
ODE_API void dJointSetSliderParam(dJointID, int parameter, dReal value);
ODE_API void dJointAddSliderForce(dJointID joint, dReal force);
ODE_API void dJointSetHinge2Anchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetHinge2Axes(dJointID j, const dReal *axis1, const dReal *axis2);
ODE_API void dJointSetHinge2Axis1(dJointID j, dReal x, dReal y, dReal z);
ODE_API void dJointSetHinge2Axis2(dJointID j, dReal x, dReal y, dReal z);
ODE_API void dJointSetHinge2Param(dJointID, int parameter, dReal value);
ODE_API void dJointAddHinge2Torques(dJointID joint, dReal torque1, dReal torque2);
ODE_API void dJointSetUniversalAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetUniversalAxis1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetUniversalAxis1Offset(dJointID, dReal x, dReal y, dReal z, dReal offset1,
                                           dReal offset2);
ODE_API void dJointSetUniversalAxis2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetUniversalAxis2Offset(dJointID, dReal x, dReal y, dReal z, dReal offset1,
                                           dReal offset2);
ODE_API void dJointSetUniversalParam(dJointID, int parameter, dReal value);
ODE_API void dJointAddUniversalTorques(dJointID joint, dReal torque1, dReal torque2);
/** Remember the current relative position and orientation as the fixed one. */
ODE_API void dJointSetFixed(dJointID);
ODE_API void dJointSetFixedParam(dJointID, int parameter, dReal value);
ODE_API void dJointSetAMotorNumAxes(dJointID, int num);
/** rel: 0 global axis, 1 fixed to body 1, 2 fixed to body 2; (x,y,z) is in
 *  world coordinates in every mode. */
ODE_API void dJointSetAMotorAxis(dJointID, int anum, int rel, dReal x, dReal y, dReal z);
ODE_API void dJointSetAMotorAngle(dJointID, int anum, dReal angle);
ODE_API void dJointSetAMotorParam(dJointID, int parameter, dReal value);
ODE_API void dJointSetAMotorMode(dJointID, int mode);
ODE_API void dJointAddAMotorTorques(dJointID, dReal torque1, dReal torque2, dReal torque3);

ODE_API void dJointGetBallAnchor(dJointID, dVector3 result);
ODE_API void dJointGetBallAnchor2(dJointID, dVector3 result);
ODE_API dReal dJointGetBallParam(dJointID, int parameter);
ODE_API void dJointGetHingeAnchor(dJointID, dVector3 result);
ODE_API void dJointGetHingeAnchor2(dJointID, dVector3 result);
ODE_API void dJointGetHingeAxis(dJointID, dVector3 result);
ODE_API dReal dJointGetHingeParam(dJointID, int parameter);
/** -pi..pi */
ODE_API dReal dJointGetHingeAngle(dJointID);
ODE_API dReal dJointGetHingeAngleRate(dJointID);
ODE_API dReal dJointGetSliderPosition(dJointID);
ODE_API dReal dJointGetSliderPositionRate(dJointID);
ODE_API void dJointGetSliderAxis(dJointID, dVector3 result);
ODE_API dReal dJointGetSliderParam(dJointID, int parameter);
ODE_API void dJointGetHinge2Anchor(dJointID, dVector3 result);
ODE_API void dJointGetHinge2Anchor2(dJointID, dVector3 result);
ODE_API void dJointGetHinge2Axis1(dJointID, dVector3 result);
ODE_API void dJointGetHinge2Axis2(dJointID, dVector3 result);
ODE_API dReal dJointGetHinge2Param(dJointID, int parameter);
ODE_API dReal dJointGetHinge2Angle1(dJointID);
ODE_API dReal dJointGetHinge2Angle2(dJointID);
ODE_API dReal dJointGetHinge2Angle1Rate(dJointID);
ODE_API dReal dJointGetHinge2Angle2Rate(dJointID);
ODE_API void dJointGetUniversalAnchor(dJointID, dVector3 result);
ODE_API void dJointGetUniversalAnchor2(dJointID, dVector3 result);
ODE_API void dJointGetUniversalAxis1(dJointID, dVector3 result);
ODE_API void dJointGetUniversalAxis2(dJointID, dVector3 result);
ODE_API dReal dJointGetUniversalParam(dJointID, int parameter);
ODE_API void dJointGetUniversalAngles(dJointID, dReal *angle1, dReal *angle2);
ODE_API dReal dJointGetUniversalAngle1(dJointID);
ODE_API dReal dJointGetUniversalAngle2(dJointID);
ODE_API dReal dJointGetUniversalAngle1Rate(dJointID);
ODE_API dReal dJointGetUniversalAngle2Rate(dJointID);
/** The same as dJointGetUniversalAngle1Rate / dJointGetUniversalAngle2Rate, under the
 *  names the ODE 0.5 guide's index spells. */
ODE_API dReal dJointGetUniversalAngleRate1(dJointID);
ODE_API dReal dJointGetUniversalAngleRate2(dJointID);
ODE_API dReal dJointGetFixedParam(dJointID, int parameter);
ODE_API int dJointGetAMotorNumAxes(dJointID);
ODE_API void dJointGetAMotorAxis(dJointID, int anum, dVector3 result);
ODE_API int dJointGetAMotorAxisRel(dJointID, int anum);
ODE_API dReal dJointGetAMotorAngle(dJointID, int anum);
ODE_API dReal dJointGetAMotorAngleRate(dJointID, int anum);
ODE_API dReal dJointGetAMotorParam(dJointID, int parameter);
ODE_API int dJointGetAMotorMode(dJointID);

/* ---- The joints ODE 0.16 added ------------------------------------------ */

/* Prismatic-rotoide (PR): a slider along axis 1, then a hinge about axis 2 at the anchor. */
ODE_API dJointID dJointCreatePR(dWorldID, dJointGroupID);
ODE_API void dJointSetPRAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPRAxis1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPRAxis2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPRParam(dJointID, int parameter, dReal value);
ODE_API void dJointAddPRTorque(dJointID j, dReal torque);
ODE_API void dJointGetPRAnchor(dJointID, dVector3 result);
ODE_API dReal dJointGetPRPosition(dJointID);
ODE_API dReal dJointGetPRPositionRate(dJointID);
ODE_API dReal dJointGetPRAngle(dJointID);
ODE_API dReal dJointGetPRAngleRate(dJointID);
ODE_API void dJointGetPRAxis1(dJointID, dVector3 result);
ODE_API void dJointGetPRAxis2(dJointID, dVector3 result);
ODE_API dReal dJointGetPRParam(dJointID, int parameter);

/* Prismatic-universal (PU): a slider along axis P, then a universal joint (axes 1 and 2) at the anchor. */
ODE_API dJointID dJointCreatePU(dWorldID, dJointGroupID);
ODE_API void dJointSetPUAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API_DEPRECATED ODE_API void dJointSetPUAnchorDelta(dJointID, dReal x, dReal y, dReal z,
        dReal dx, dReal dy, dReal dz);
ODE_API void dJointSetPUAnchorOffset(dJointID, dReal x, dReal y, dReal z, dReal dx, dReal dy,
        dReal dz);
ODE_API void dJointSetPUAxis1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPUAxis2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPUAxis3(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPUAxisP(dJointID id, dReal x, dReal y, dReal z);
ODE_API void dJointSetPUParam(dJointID, int parameter, dReal value);
ODE_API void dJointGetPUAnchor(dJointID, dVector3 result);
ODE_API dReal dJointGetPUPosition(dJointID);
ODE_API dReal dJointGetPUPositionRate(dJointID);
ODE_API void dJointGetPUAxis1(dJointID, dVector3 result);
ODE_API void dJointGetPUAxis2(dJointID, dVector3 result);
ODE_API void dJointGetPUAxis3(dJointID, dVector3 result);
ODE_API void dJointGetPUAxisP(dJointID id, dVector3 result);
ODE_API void dJointGetPUAngles(dJointID, dReal *angle1, dReal *angle2);
ODE_API dReal dJointGetPUAngle1(dJointID);
ODE_API dReal dJointGetPUAngle1Rate(dJointID);
ODE_API dReal dJointGetPUAngle2(dJointID);
ODE_API dReal dJointGetPUAngle2Rate(dJointID);
ODE_API dReal dJointGetPUParam(dJointID, int parameter);

/* Piston: slides along, and turns about, one axis through the anchor. */
ODE_API dJointID dJointCreatePiston(dWorldID, dJointGroupID);
ODE_API void dJointSetPistonAnchor(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetPistonAnchorOffset(dJointID j, dReal x, dReal y, dReal z, dReal dx,
        dReal dy, dReal dz);
ODE_API void dJointSetPistonAxis(dJointID, dReal x, dReal y, dReal z);
ODE_API_DEPRECATED ODE_API void dJointSetPistonAxisDelta(dJointID j, dReal x, dReal y, dReal z,
        dReal ax, dReal ay, dReal az);
ODE_API void dJointSetPistonParam(dJointID, int parameter, dReal value);
ODE_API void dJointAddPistonForce(dJointID joint, dReal force);
ODE_API dReal dJointGetPistonPosition(dJointID);
ODE_API dReal dJointGetPistonPositionRate(dJointID);
ODE_API dReal dJointGetPistonAngle(dJointID);
ODE_API dReal dJointGetPistonAngleRate(dJointID);
ODE_API void dJointGetPistonAnchor(dJointID, dVector3 result);
ODE_API void dJointGetPistonAnchor2(dJointID, dVector3 result);
ODE_API void dJointGetPistonAxis(dJointID, dVector3 result);
ODE_API dReal dJointGetPistonParam(dJointID, int parameter);

/* Plane-2D: keeps a body in the z = 0 plane, turning about z only. */
ODE_API dJointID dJointCreatePlane2D(dWorldID, dJointGroupID);
ODE_API void dJointSetPlane2DXParam(dJointID, int parameter, dReal value);
ODE_API void dJointSetPlane2DYParam(dJointID, int parameter, dReal value);
ODE_API void dJointSetPlane2DAngleParam(dJointID, int parameter, dReal value);

/* Linear motor: up to three axes, each fixed in the world, body 1 or body 2. */
ODE_API dJointID dJointCreateLMotor(dWorldID, dJointGroupID);
ODE_API void dJointSetLMotorNumAxes(dJointID, int num);
ODE_API void dJointSetLMotorAxis(dJointID, int anum, int rel, dReal x, dReal y, dReal z);
ODE_API void dJointSetLMotorParam(dJointID, int parameter, dReal value);
ODE_API int dJointGetLMotorNumAxes(dJointID);
ODE_API void dJointGetLMotorAxis(dJointID, int anum, dVector3 result);
ODE_API dReal dJointGetLMotorParam(dJointID, int parameter);

/* Double ball: keeps the distance between an anchor on each body. */
ODE_API dJointID dJointCreateDBall(dWorldID, dJointGroupID);
ODE_API void dJointSetDBallAnchor1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetDBallAnchor2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetDBallAnchor1(dJointID, dVector3 result);
ODE_API void dJointGetDBallAnchor2(dJointID, dVector3 result);
ODE_API dReal dJointGetDBallDistance(dJointID);
ODE_API void dJointSetDBallDistance(dJointID, dReal dist);
ODE_API void dJointSetDBallParam(dJointID, int parameter, dReal value);
ODE_API dReal dJointGetDBallParam(dJointID, int parameter);

/* Double hinge: two anchors at a fixed distance along an axis both bodies share. */
ODE_API dJointID dJointCreateDHinge(dWorldID, dJointGroupID);
ODE_API void dJointSetDHingeAxis(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetDHingeAxis(dJointID, dVector3 result);
ODE_API void dJointSetDHingeAnchor1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointSetDHingeAnchor2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetDHingeAnchor1(dJointID, dVector3 result);
ODE_API void dJointGetDHingeAnchor2(dJointID, dVector3 result);
ODE_API dReal dJointGetDHingeDistance(dJointID);
ODE_API void dJointSetDHingeParam(dJointID, int parameter, dReal value);
ODE_API dReal dJointGetDHingeParam(dJointID, int parameter);

/* Transmission: gears (parallel or intersecting axes) and chain drives, with a ratio and backlash. */
ODE_API dJointID dJointCreateTransmission(dWorldID, dJointGroupID);
ODE_API void dJointGetTransmissionContactPoint1(dJointID, dVector3 result);
ODE_API void dJointGetTransmissionContactPoint2(dJointID, dVector3 result);
ODE_API void dJointSetTransmissionAxis1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetTransmissionAxis1(dJointID, dVector3 result);
ODE_API void dJointSetTransmissionAxis2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetTransmissionAxis2(dJointID, dVector3 result);
ODE_API void dJointSetTransmissionAnchor1(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetTransmissionAnchor1(dJointID, dVector3 result);
ODE_API void dJointSetTransmissionAnchor2(dJointID, dReal x, dReal y, dReal z);
ODE_API void dJointGetTransmissionAnchor2(dJointID, dVector3 result);
ODE_API void dJointSetTransmissionParam(dJointID, int parameter, dReal value);
ODE_API dReal dJointGetTransmissionParam(dJointID, int parameter);
ODE_API void dJointSetTransmissionMode(dJointID j, int mode);
ODE_API int dJointGetTransmissionMode(dJointID j);
ODE_API void dJointSetTransmissionRatio(dJointID j, dReal ratio);
ODE_API dReal dJointGetTransmissionRatio(dJointID j);
ODE_API void dJointSetTransmissionAxis(dJointID j, dReal x, dReal y, dReal z);
ODE_API void dJointGetTransmissionAxis(dJointID j, dVector3 result);
ODE_API dReal dJointGetTransmissionAngle1(dJointID j);
ODE_API dReal dJointGetTransmissionAngle2(dJointID j);
ODE_API dReal dJointGetTransmissionRadius1(dJointID j);
ODE_API dReal dJointGetTransmissionRadius2(dJointID j);
ODE_API void dJointSetTransmissionRadius1(dJointID j, dReal radius);
ODE_API void dJointSetTransmissionRadius2(dJointID j, dReal radius);
ODE_API dReal dJointGetTransmissionBacklash(dJointID j);
ODE_API void dJointSetTransmissionBacklash(dJointID j, dReal backlash);
/* ---- Connectivity ------------------------------------------------------ */

/** A joint connecting the two bodies (either may be 0), or 0. */
ODE_API dJointID dConnectingJoint(dBodyID, dBodyID);
/** Fill joints (room for dBodyGetNumJoints of either) with every connecting joint; returns the count. */
ODE_API int dConnectingJointList(dBodyID, dBodyID, dJointID *);
/** 1 if a joint connects the two bodies. */
ODE_API int dAreConnected(dBodyID, dBodyID);
/** 1 if a joint of a type other than joint_type connects the two bodies. */
ODE_API int dAreConnectedExcluding(dBodyID body1, dBodyID body2, int joint_type);

#ifdef __cplusplus
}
#endif

#endif
