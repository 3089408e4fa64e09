/* SPDX-License-Identifier: BSD-3-Clause */
/* mass.h -- mass parameters of a body (guide 9.2).
 *
 * A dMass holds the total mass, the centre of mass c and the inertia tensor I,
 * both in the body frame; I is about the body frame's origin (the point of
 * reference), not about c. Sizes and densities must be positive and finite;
 * bad arguments are reported through dDebug and leave the dMass unchanged. */
#ifndef ODE_MASS_H
#define ODE_MASS_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dMass;
typedef struct dMass dMass;

/** 1 if m is physically valid (mass > 0, I and the inertia about c positive
 *  definite), else 0 with a message through dMessage. */
ODE_API int dMassCheck(const dMass *m);
ODE_API void dMassSetZero(dMass *m);
ODE_API void dMassSetParameters(dMass *m, dReal themass, dReal cgx, dReal cgy, dReal cgz,
                                dReal I11, dReal I22, dReal I33, dReal I12, dReal I13,
                                dReal I23);
ODE_API void dMassSetSphere(dMass *m, dReal density, dReal radius);
ODE_API void dMassSetSphereTotal(dMass *m, dReal total_mass, dReal radius);
/** A capsule along body axis direction (1=x, 2=y, 3=z); length excludes the caps. */
ODE_API void dMassSetCapsule(dMass *m, dReal density, int direction, dReal radius,
                             dReal length);
ODE_API void dMassSetCapsuleTotal(dMass *m, dReal total_mass, int direction, dReal radius,
                                  dReal length);
/** A flat-ended cylinder along body axis direction (1=x, 2=y, 3=z). */
ODE_API void dMassSetCylinder(dMass *m, dReal density, int direction, dReal radius,
                              dReal length);
ODE_API void dMassSetCylinderTotal(dMass *m, dReal total_mass, int direction, dReal radius,
                                   dReal length);
/** A box with side lengths lx, ly, lz along the body axes. */
ODE_API void dMassSetBox(dMass *m, dReal density, dReal lx, dReal ly, dReal lz);
ODE_API void dMassSetBoxTotal(dMass *m, dReal total_mass, dReal lx, dReal ly, dReal lz);
/** The solid inside a closed trimesh geom (outward winding), in world
 *  coordinates; as in ODE 0.16 the inertia about the origin is moved to the
 *  centre of mass with dMassTranslate (exact for a mesh centred on the
 *  origin). Defined in the collision library. */
ODE_API void dMassSetTrimesh(dMass *m, dReal density, dGeomID g);
ODE_API void dMassSetTrimeshTotal(dMass *m, dReal total_mass, dGeomID g);
/** Scale the mass (and the inertia with it) to newmass. */
ODE_API void dMassAdjust(dMass *m, dReal newmass);
/** The same object displaced by (x,y,z) in the body frame. */
ODE_API void dMassTranslate(dMass *m, dReal x, dReal y, dReal z);
/** The same object rotated by R about the body frame origin. */
ODE_API void dMassRotate(dMass *m, const dMatrix3 R);
/** a = the two objects a and b taken together. */
ODE_API void dMassAdd(dMass *a, const dMass *b);

/* ODE 0.5 names of the capsule functions. */
ODE_API_DEPRECATED ODE_API void dMassSetCappedCylinder(dMass *m, dReal density, int direction,
                                                       dReal radius, dReal length);
ODE_API_DEPRECATED ODE_API void dMassSetCappedCylinderTotal(dMass *m, dReal total_mass,
                                                            int direction, dReal radius,
                                                            dReal length);

struct dMass {
    dReal mass;
    dVector3 c;
    dMatrix3 I;
#ifdef __cplusplus
    dMass() { dMassSetZero(this); }
    void setZero() { dMassSetZero(this); }
    void setParameters(dReal themass, dReal cgx, dReal cgy, dReal cgz, dReal I11, dReal I22,
                       dReal I33, dReal I12, dReal I13, dReal I23)
    {
        dMassSetParameters(this, themass, cgx, cgy, cgz, I11, I22, I33, I12, I13, I23);
    }
    void setSphere(dReal density, dReal radius) { dMassSetSphere(this, density, radius); }
    void setSphereTotal(dReal total, dReal radius) { dMassSetSphereTotal(this, total, radius); }
    void setCapsule(dReal density, int direction, dReal radius, dReal length)
    {
        dMassSetCapsule(this, density, direction, radius, length);
    }
    void setCapsuleTotal(dReal total, int direction, dReal radius, dReal length)
    {
        dMassSetCapsuleTotal(this, total, direction, radius, length);
    }
    void setCylinder(dReal density, int direction, dReal radius, dReal length)
    {
        dMassSetCylinder(this, density, direction, radius, length);
    }
    void setCylinderTotal(dReal total, int direction, dReal radius, dReal length)
    {
        dMassSetCylinderTotal(this, total, direction, radius, length);
    }
    void setBox(dReal density, dReal lx, dReal ly, dReal lz)
    {
        dMassSetBox(this, density, lx, ly, lz);
    }
    void setBoxTotal(dReal total, dReal lx, dReal ly, dReal lz)
    {
        dMassSetBoxTotal(this, total, lx, ly, lz);
    }
    void adjust(dReal newmass) { dMassAdjust(this, newmass); }
    void translate(dReal x, dReal y, dReal z) { dMassTranslate(this, x, y, z); }
    void rotate(const dMatrix3 R) { dMassRotate(this, R); }
    void add(const dMass *b) { dMassAdd(this, b); }
#endif
};

#ifdef __cplusplus
}
#endif

#endif
