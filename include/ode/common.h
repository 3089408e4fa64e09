/* SPDX-License-Identifier: BSD-3-Clause */
/* common.h -- dReal and its maths macros, the vector and matrix types, the
 * opaque object IDs, error numbers, joint types and parameter names, and the
 * hooks through which the dynamics library tells the collision library that a
 * body moved (guide chapter 4 and 10.11.2). */
#ifndef ODE_COMMON_H
#define ODE_COMMON_H

#include <ode/odeconfig.h>
#include <ode/error.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifndef M_PI
#define M_PI REAL(3.1415926535897932384626433832795029)
#endif
#ifndef M_PI_2
#define M_PI_2 REAL(1.5707963267948966192313216916398)
#endif
#ifndef M_SQRT1_2
#define M_SQRT1_2 REAL(0.7071067811865475244008443621048490)
#endif

#if defined(dSINGLE)
typedef float dReal;
#elif defined(dDOUBLE)
typedef double dReal;
#else
#error "precision.h must define dSINGLE or dDOUBLE"
#endif

typedef duint32 dTriIndex;

/* Round a row length up to a multiple of 4 (rows of 1 stay 1): the row skip of
 * every matrix the matrix functions take. */
#define dPAD(a) (((a) > 1) ? (((a) + 3) & (int)(~3)) : (a))

/* Element indices, as ODE 0.16 names them. */
typedef enum { dSA__MIN, dSA_X = dSA__MIN, dSA_Y, dSA_Z, dSA__MAX } dSpaceAxis;
typedef enum { dMD__MIN, dMD_LINEAR = dMD__MIN, dMD_ANGULAR, dMD__MAX } dMotionDynamics;
typedef enum {
    dDA__MIN,
    dDA__L_MIN = dDA__MIN,
    dDA_LX = dDA__L_MIN, dDA_LY, dDA_LZ,
    dDA__L_MAX,
    dDA__A_MIN = dDA__L_MAX,
    dDA_AX = dDA__A_MIN, dDA_AY, dDA_AZ,
    dDA__A_MAX,
    dDA__MAX = dDA__A_MAX
} dDynamicsAxis;
typedef enum {
    dV3E__MIN,
    dV3E__AXES_MIN = dV3E__MIN,
    dV3E_X = dV3E__AXES_MIN, dV3E_Y, dV3E_Z,
    dV3E__AXES_MAX,
    dV3E_PAD = dV3E__AXES_MAX,
    dV3E__MAX,
    dV3E__AXES_COUNT = dV3E__AXES_MAX - dV3E__AXES_MIN
} dVec3Element;
typedef enum { dV4E__MIN, dV4E_X = dV4E__MIN, dV4E_Y, dV4E_Z, dV4E_O, dV4E__MAX } dVec4Element;
typedef enum {
    dM3E__MIN,
    dM3E__X_MIN = dM3E__MIN, dM3E__X_AXES_MIN = dM3E__X_MIN,
    dM3E_XX = dM3E__X_MIN, dM3E_XY, dM3E_XZ, dM3E__X_AXES_MAX, dM3E_XPAD = dM3E__X_AXES_MAX,
    dM3E__X_MAX,
    dM3E__Y_MIN = dM3E__X_MAX, dM3E__Y_AXES_MIN = dM3E__Y_MIN,
    dM3E_YX = dM3E__Y_MIN, dM3E_YY, dM3E_YZ, dM3E__Y_AXES_MAX, dM3E_YPAD = dM3E__Y_AXES_MAX,
    dM3E__Y_MAX,
    dM3E__Z_MIN = dM3E__Y_MAX, dM3E__Z_AXES_MIN = dM3E__Z_MIN,
    dM3E_ZX = dM3E__Z_MIN, dM3E_ZY, dM3E_ZZ, dM3E__Z_AXES_MAX, dM3E_ZPAD = dM3E__Z_AXES_MAX,
    dM3E__Z_MAX,
    dM3E__MAX = dM3E__Z_MAX
} dMat3Element;
typedef enum {
    dM4E__MIN,
    dM4E__X_MIN = dM4E__MIN, dM4E_XX = dM4E__X_MIN, dM4E_XY, dM4E_XZ, dM4E_XO, dM4E__X_MAX,
    dM4E__Y_MIN = dM4E__X_MAX, dM4E_YX = dM4E__Y_MIN, dM4E_YY, dM4E_YZ, dM4E_YO, dM4E__Y_MAX,
    dM4E__Z_MIN = dM4E__Y_MAX, dM4E_ZX = dM4E__Z_MIN, dM4E_ZY, dM4E_ZZ, dM4E_ZO, dM4E__Z_MAX,
    dM4E__O_MIN = dM4E__Z_MAX, dM4E_OX = dM4E__O_MIN, dM4E_OY, dM4E_OZ, dM4E_OO, dM4E__O_MAX,
    dM4E__MAX = dM4E__O_MAX
} dMat4Element;
typedef enum {
    dQUE__MIN,
    dQUE_R = dQUE__MIN,
    dQUE__AXIS_MIN,
    dQUE_I = dQUE__AXIS_MIN, dQUE_J, dQUE_K,
    dQUE__AXIS_MAX,
    dQUE__MAX = dQUE__AXIS_MAX
} dQuatElement;

/* Vectors are padded to 4 elements; a dMatrix3 is 3 rows of 4 (row-major, the
 * fourth column unused), so R[i*4+j] is row i, column j. A quaternion is
 * (w, x, y, z). */
typedef dReal dVector3[4];
typedef dReal dVector4[4];
typedef dReal dMatrix3[4 * 3];
typedef dReal dMatrix4[4 * 4];
typedef dReal dMatrix6[8 * 6];
typedef dReal dQuaternion[4];

#if defined(dSINGLE)
#define REAL(x) (x##f)
#define dRecip(x) ((1.0f / (x)))
#define dSqrt(x) (sqrtf(x))
#define dRecipSqrt(x) ((1.0f / sqrtf(x)))
#define dSin(x) (sinf(x))
#define dCos(x) (cosf(x))
#define dFabs(x) (fabsf(x))
#define dAtan2(y, x) (atan2f((y), (x)))
#define dAsin(x) (asinf(x))
#define dAcos(x) (acosf(x))
#define dFMod(a, b) (fmodf((a), (b)))
#define dFloor(x) (floorf(x))
#define dCeil(x) (ceilf(x))
#define dCopySign(a, b) (copysignf((a), (b)))
#define dNextAfter(x, y) (nextafterf((x), (y)))
#else
#define REAL(x) (x)
#define dRecip(x) (1.0 / (x))
#define dSqrt(x) (sqrt(x))
#define dRecipSqrt(x) (1.0 / sqrt(x))
#define dSin(x) (sin(x))
#define dCos(x) (cos(x))
#define dFabs(x) (fabs(x))
#define dAtan2(y, x) (atan2((y), (x)))
#define dAsin(x) (asin(x))
#define dAcos(x) (acos(x))
#define dFMod(a, b) (fmod((a), (b)))
#define dFloor(x) (floor(x))
#define dCeil(x) (ceil(x))
#define dCopySign(a, b) (copysign((a), (b)))
#define dNextAfter(x, y) (nextafter((x), (y)))
#endif
#define dIsNan(x) (isnan(x))

ODE_PURE_INLINE dReal dMin(dReal x, dReal y) { return x <= y ? x : y; }
ODE_PURE_INLINE dReal dMax(dReal x, dReal y) { return x <= y ? y : x; }

/* Object IDs are pointers to structures private to the library. */
struct dxWorld;
struct dxSpace;
struct dxBody;
struct dxGeom;
struct dxJoint;
struct dxJointGroup;

typedef struct dxWorld *dWorldID;
typedef struct dxSpace *dSpaceID;
typedef struct dxBody *dBodyID;
typedef struct dxGeom *dGeomID;
typedef struct dxJoint *dJointID;
typedef struct dxJointGroup *dJointGroupID;

/* Error numbers passed to the handlers of error.h. */
enum {
    d_ERR_UNKNOWN = 0, /* unknown error */
    d_ERR_IASSERT,     /* internal assertion failed */
    d_ERR_UASSERT,     /* user assertion failed: bad arguments */
    d_ERR_LCP          /* the LCP solver failed */
};

/* Joint type numbers, as dJointGetType returns them. */
typedef enum {
    dJointTypeNone = 0,
    dJointTypeBall,
    dJointTypeHinge,
    dJointTypeSlider,
    dJointTypeContact,
    dJointTypeUniversal,
    dJointTypeHinge2,
    dJointTypeFixed,
    dJointTypeNull,
    dJointTypeAMotor,
    dJointTypeLMotor,
    dJointTypePlane2D,
    dJointTypePR,
    dJointTypePU,
    dJointTypePiston,
    dJointTypeDBall,
    dJointTypeDHinge,
    dJointTypeTransmission
} dJointType;

/* Joint parameter names (guide 7.5). A parameter of the second or third axis
 * is the first axis' name plus dParamGroup or 2*dParamGroup, so
 * dParamGroup2 | dParamFMax == dParamFMax2. */
#define ODE_PARAM_NAMES_(start, x) \
    dParamLoStop##x = (start), \
    dParamHiStop##x, \
    dParamVel##x, \
    dParamLoVel##x, \
    dParamHiVel##x, \
    dParamFMax##x, \
    dParamFudgeFactor##x, \
    dParamBounce##x, \
    dParamCFM##x, \
    dParamStopERP##x, \
    dParamStopCFM##x, \
    dParamSuspensionERP##x, \
    dParamSuspensionCFM##x, \
    dParamERP##x,

enum {
    /* The first axis' names, spelled out (an empty macro argument is not
     * C89/C++98). */
    dParamLoStop = 0, dParamHiStop, dParamVel, dParamLoVel, dParamHiVel, dParamFMax,
    dParamFudgeFactor, dParamBounce, dParamCFM, dParamStopERP, dParamStopCFM,
    dParamSuspensionERP, dParamSuspensionCFM, dParamERP,
    dParamsInGroup,
    dParamGroup1 = 0x000,
    ODE_PARAM_NAMES_(0x000, 1)
    dParamGroup2 = 0x100,
    ODE_PARAM_NAMES_(0x100, 2)
    dParamGroup3 = 0x200,
    ODE_PARAM_NAMES_(0x200, 3)
    dParamGroup = 0x100
};

/* Angular motor modes. */
enum { dAMotorUser = 0, dAMotorEuler = 1 };

/* Transmission joint modes (dJointSetTransmissionMode). */
enum {
    dTransmissionParallelAxes = 0,
    dTransmissionIntersectingAxes = 1,
    dTransmissionChainDrive = 2
};

/** Forces and torques a joint applied in the last step, filled when set with
 *  dJointSetFeedback (world frame). */
typedef struct dJointFeedback {
    dVector3 f1; /* force on body 1 */
    dVector3 t1; /* torque on body 1 */
    dVector3 f2; /* force on body 2 */
    dVector3 t2; /* torque on body 2 */
} dJointFeedback;

/* The hooks of guide 10.11.2, defined by the collision library (or by a
 * program that uses another one) and called by the dynamics library:
 * dGeomMoved tells that a geom's body moved; dGeomGetBodyNext walks the list
 * of geoms attached to one body. */
ODE_API void dGeomMoved(dGeomID geom);
ODE_API dGeomID dGeomGetBodyNext(dGeomID geom);

/** The build configuration as space-separated tokens ("ODE ODE_double_precision ..."). */
ODE_API const char *dGetConfiguration(void);
/** 1 if token is one of dGetConfiguration's tokens exactly (case-sensitive), else 0. */
ODE_API int dCheckConfiguration(const char *token);

#ifdef __cplusplus
}
#endif

#endif
