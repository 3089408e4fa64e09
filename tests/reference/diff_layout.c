// SPDX-License-Identifier: BSD-3-Clause
//
// diff_layout.c -- the binary interface a compiled ODE program bakes in:
// the size and field offsets of every public struct, the sizes of the public
// types and the values of the public constants. Built against this library and
// against the reference ODE, the two must print exactly the same numbers, so a
// program compiled against the reference runs unchanged on libode.so.8.
// (The reference's structs of APIs not provided here are left out: the world
// step memory descriptors dWorldStepReserveInfo and
// dWorldStepMemoryFunctionsInfo, dStopwatch, the threading descriptors.)
#include <ode/ode.h>
#include <stddef.h>
#include <stdio.h>

// One line per struct: its size, then the offset of each field named.
#define BEGIN(T) printf("%s 0 %zu", #T, sizeof(T))
#define FIELD(T, f) printf(" %zu", offsetof(T, f))
#define END() printf("\n")
#define SIZE(T) printf("sizeof_%s 0 %zu\n", #T, sizeof(T))
#define CONST(name) printf("%s 0 %ld\n", #name, (long)(name))

static void structs(void)
{
    BEGIN(dMass); FIELD(dMass, mass); FIELD(dMass, c); FIELD(dMass, I); END();

    BEGIN(dSurfaceParameters);
    FIELD(dSurfaceParameters, mode); FIELD(dSurfaceParameters, mu);
    FIELD(dSurfaceParameters, mu2); FIELD(dSurfaceParameters, rho);
    FIELD(dSurfaceParameters, rho2); FIELD(dSurfaceParameters, rhoN);
    FIELD(dSurfaceParameters, bounce); FIELD(dSurfaceParameters, bounce_vel);
    FIELD(dSurfaceParameters, soft_erp); FIELD(dSurfaceParameters, soft_cfm);
    FIELD(dSurfaceParameters, motion1); FIELD(dSurfaceParameters, motion2);
    FIELD(dSurfaceParameters, motionN); FIELD(dSurfaceParameters, slip1);
    FIELD(dSurfaceParameters, slip2);
    END();

    BEGIN(dContactGeom);
    FIELD(dContactGeom, pos); FIELD(dContactGeom, normal); FIELD(dContactGeom, depth);
    FIELD(dContactGeom, g1); FIELD(dContactGeom, g2); FIELD(dContactGeom, side1);
    FIELD(dContactGeom, side2);
    END();

    BEGIN(dContact);
    FIELD(dContact, surface); FIELD(dContact, geom); FIELD(dContact, fdir1);
    END();

    BEGIN(dJointFeedback);
    FIELD(dJointFeedback, f1); FIELD(dJointFeedback, t1);
    FIELD(dJointFeedback, f2); FIELD(dJointFeedback, t2);
    END();

    BEGIN(dGeomClass);
    FIELD(dGeomClass, bytes); FIELD(dGeomClass, collider); FIELD(dGeomClass, aabb);
    FIELD(dGeomClass, aabb_test); FIELD(dGeomClass, dtor);
    END();
}

static void types(void)
{
    SIZE(dReal); SIZE(dVector3); SIZE(dVector4); SIZE(dMatrix3); SIZE(dMatrix4);
    SIZE(dMatrix6); SIZE(dQuaternion); SIZE(dWorldID); SIZE(dBodyID); SIZE(dJointID);
    SIZE(dJointGroupID); SIZE(dGeomID); SIZE(dSpaceID);
    SIZE(dJointType);
    printf("sizeof_dNearCallback_pointer 0 %zu\n", sizeof(dNearCallback *));
}

static void constants(void)
{
    CONST(dContactMu2); CONST(dContactAxisDep); CONST(dContactFDir1); CONST(dContactBounce);
    CONST(dContactSoftERP); CONST(dContactSoftCFM); CONST(dContactMotion1);
    CONST(dContactMotion2); CONST(dContactMotionN); CONST(dContactSlip1);
    CONST(dContactSlip2); CONST(dContactRolling); CONST(dContactApprox0);
    CONST(dContactApprox1_1); CONST(dContactApprox1_2); CONST(dContactApprox1_N);
    CONST(dContactApprox1);

    CONST(dJointTypeNone); CONST(dJointTypeBall); CONST(dJointTypeHinge);
    CONST(dJointTypeSlider); CONST(dJointTypeContact); CONST(dJointTypeUniversal);
    CONST(dJointTypeHinge2); CONST(dJointTypeFixed); CONST(dJointTypeNull);
    CONST(dJointTypeAMotor); CONST(dJointTypeLMotor); CONST(dJointTypePlane2D);
    CONST(dJointTypePR); CONST(dJointTypePU); CONST(dJointTypePiston);
    CONST(dJointTypeDBall); CONST(dJointTypeDHinge); CONST(dJointTypeTransmission);

    CONST(dParamLoStop); CONST(dParamHiStop); CONST(dParamVel); CONST(dParamLoVel);
    CONST(dParamHiVel); CONST(dParamFMax); CONST(dParamFudgeFactor); CONST(dParamBounce);
    CONST(dParamCFM); CONST(dParamStopERP); CONST(dParamStopCFM);
    CONST(dParamSuspensionERP); CONST(dParamSuspensionCFM); CONST(dParamERP);
    CONST(dParamsInGroup); CONST(dParamGroup); CONST(dParamGroup1); CONST(dParamGroup2);
    CONST(dParamGroup3); CONST(dParamLoStop2); CONST(dParamERP2); CONST(dParamLoStop3);
    CONST(dParamERP3);

    CONST(dSphereClass); CONST(dBoxClass); CONST(dCapsuleClass); CONST(dCCylinderClass);
    CONST(dCylinderClass); CONST(dPlaneClass); CONST(dRayClass); CONST(dConvexClass);
    CONST(dGeomTransformClass); CONST(dTriMeshClass); CONST(dHeightfieldClass);
    CONST(dFirstSpaceClass); CONST(dSimpleSpaceClass); CONST(dHashSpaceClass);
    CONST(dSweepAndPruneSpaceClass); CONST(dQuadTreeSpaceClass); CONST(dLastSpaceClass);
    CONST(dFirstUserClass); CONST(dLastUserClass); CONST(dGeomNumClasses);
    CONST(dMaxUserClasses); CONST(CONTACTS_UNIMPORTANT);

    CONST(dAMotorUser); CONST(dAMotorEuler);
    CONST(dTransmissionParallelAxes); CONST(dTransmissionIntersectingAxes);
    CONST(dTransmissionChainDrive);
    CONST(d_ERR_UNKNOWN); CONST(d_ERR_IASSERT); CONST(d_ERR_UASSERT); CONST(d_ERR_LCP);
    CONST(dInitFlagManualThreadCleanup); CONST(dAllocateFlagBasicData);
    CONST(dAllocateFlagCollisionData); CONST(dAllocateMaskAll);
}

int main(void)
{
    structs();
    types();
    constants();
    return 0;
}
