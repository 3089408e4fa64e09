/* SPDX-License-Identifier: BSD-3-Clause */
/* contact.h -- contact points and contact surface parameters (guide 7.3.7,
 * 10.1). Shared by the collision library, which fills dContactGeom, and the
 * dynamics library, whose contact joints take a dContact. */
#ifndef ODE_CONTACT_H
#define ODE_CONTACT_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/* dSurfaceParameters.mode flags. */
enum {
    dContactMu2 = 0x001,     /* mu for friction direction 1, mu2 for direction 2 */
    dContactAxisDep = 0x001, /* the same as dContactMu2 */
    dContactFDir1 = 0x002,   /* dContact.fdir1 is friction direction 1 */
    dContactBounce = 0x004,  /* restitution: bounce, above bounce_vel */
    dContactSoftERP = 0x008, /* soft_erp replaces the world ERP for the normal */
    dContactSoftCFM = 0x010, /* soft_cfm replaces the world CFM for the normal */
    dContactMotion1 = 0x020, /* surface velocity motion1 along friction direction 1 */
    dContactMotion2 = 0x040,
    dContactMotionN = 0x080, /* surface velocity motionN along the normal */
    dContactSlip1 = 0x100,   /* force-dependent slip slip1 in friction direction 1 */
    dContactSlip2 = 0x200,
    dContactRolling = 0x400, /* rolling friction (ODE 0.16; rho, rho2, rhoN) */

    dContactApprox0 = 0x0000,   /* friction limits are constant forces (mu in N) */
    dContactApprox1_1 = 0x1000, /* friction pyramid: limit mu * normal force, direction 1 */
    dContactApprox1_2 = 0x2000, /* ... direction 2 */
    dContactApprox1_N = 0x4000, /* ... spinning (rolling friction) */
    dContactApprox1 = 0x7000
};

typedef struct dSurfaceParameters {
    int mode;       /* always set */
    dReal mu;       /* always set: Coulomb friction, 0..dInfinity */
    dReal mu2;      /* with dContactMu2 */
    dReal rho;      /* with dContactRolling: rolling friction */
    dReal rho2;
    dReal rhoN;     /* spinning friction */
    dReal bounce;   /* with dContactBounce: restitution 0..1 */
    dReal bounce_vel; /* minimum incoming speed for a bounce */
    dReal soft_erp;
    dReal soft_cfm;
    dReal motion1, motion2, motionN;
    dReal slip1, slip2;
} dSurfaceParameters;

/** A contact point. Moving g1 along normal by depth separates the geoms: the
 *  normal points into g1. side1/side2 are triangle indices for trimeshes, -1
 *  otherwise. */
typedef struct dContactGeom {
    dVector3 pos;
    dVector3 normal;
    dReal depth;
    dGeomID g1, g2;
    int side1, side2;
} dContactGeom;

/** What dJointCreateContact takes: the surface, the contact point and, with
 *  dContactFDir1, the first friction direction (unit, perpendicular to the
 *  normal). */
typedef struct dContact {
    dSurfaceParameters surface;
    dContactGeom geom;
    dVector3 fdir1;
} dContact;

#ifdef __cplusplus
}
#endif

#endif
