// SPDX-License-Identifier: BSD-3-Clause
//
// mass.c -- mass parameters of a body (guide 9.2): the standard solids, and
// scaling, moving, rotating and combining masses. I is the inertia tensor
// about the body frame origin, c the centre of mass.

#include "dx_check.h"

#include <ode/mass.h>
#include <ode/odemath.h>

// Reject the call with a report naming the public function fn.
#define REQUIRE(cond, ...) \
    do { \
        if (!(cond)) { \
            dxReportBadArgument(fn, __VA_ARGS__); \
            return 0; \
        } \
    } while (0)

static int positive(dReal x) { return dxIsFinite(x) && x > 0; }
// Sizes may be zero (ODE accepts a sphere of radius 0): the solid is then a
// point, a rod or a plate, whose inertia dMassCheck reports as not definite.
static int size_ok(dReal x) { return dxIsFinite(x) && x >= 0; }

// 1 if the quadratic form of the 3x3 block A (row skip 4) is positive
// definite: Sylvester's criterion (leading minors > 0) on the symmetric part
// of A divided by its largest diagonal entry. A positive definite matrix has
// |A_ij| < sqrt(A_ii A_jj), so every scaled entry is at most 1 and the minors
// can neither overflow nor underflow; larger entries mean "not definite".
static int positive_definite3(const dReal *A)
{
    double s = fmax(fmax(fabs(A[0]), fabs(A[5])), fabs(A[10])), b[3][3];
    if (!(s > 0) || !isfinite(s)) return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            b[i][j] = 0.5 * ((double)A[4 * i + j] + (double)A[4 * j + i]) / s;
            if (!(fabs(b[i][j]) <= 1)) return 0;
        }
    double m2 = b[0][0] * b[1][1] - b[0][1] * b[1][0];
    double m3 = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    return b[0][0] > 0 && m2 > 0 && m3 > 0;
}

// 1 if m is physically possible, else 0 with a message saying why.
int dMassCheck(const dMass *m)
{
    DX_CHECK_ARG(m != NULL, return 0, "m is NULL");
    if (!positive(m->mass)) {
        dxReportMessage(__func__, "the mass %g must be positive", (double)m->mass);
        return 0;
    }
    if (!positive_definite3(m->I)) {
        dxReportMessage(__func__, "the inertia tensor must be positive definite");
        return 0;
    }
    // the inertia about c: I + mass [c]x^2 = I - mass (|c|^2 E - c c^T)
    dMatrix3 Ic;
    dReal c2 = dCalcVectorLengthSquare3(m->c);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Ic[4 * i + j] = m->I[4 * i + j] + m->mass * (m->c[i] * m->c[j] - (i == j ? c2 : 0));
    if (!positive_definite3(Ic)) {
        dxReportMessage(__func__, "the inertia about the centre of mass must be positive "
                                  "definite (the centre of mass does not fit the inertia)");
        return 0;
    }
    return 1;
}

void dMassSetZero(dMass *m)
{
    DX_CHECK_ARG(m != NULL, return, "m is NULL");
    m->mass = 0;
    for (int i = 0; i < 4; i++) m->c[i] = 0;
    for (int i = 0; i < 12; i++) m->I[i] = 0;
}

// Mass, centre and the symmetric inertia tensor given entry by entry.
void dMassSetParameters(dMass *m, dReal themass, dReal cgx, dReal cgy, dReal cgz, dReal I11,
                        dReal I22, dReal I33, dReal I12, dReal I13, dReal I23)
{
    DX_CHECK_ARG(m != NULL, return, "m is NULL");
    DX_CHECK_ARG(dxIsFinite(themass) && dxIsFinite3(cgx, cgy, cgz) &&
                     dxIsFinite3(I11, I22, I33) && dxIsFinite3(I12, I13, I23),
                 return, "a parameter is not finite");
    dMassSetZero(m);
    m->mass = themass;
    m->c[0] = cgx;
    m->c[1] = cgy;
    m->c[2] = cgz;
    m->I[0] = I11; m->I[1] = I12; m->I[2] = I13;
    m->I[4] = I12; m->I[5] = I22; m->I[6] = I23;
    m->I[8] = I13; m->I[9] = I23; m->I[10] = I33;
    dMassCheck(m);   // as ODE 0.16: an impossible mass is reported, and kept
}

// A solid centred at the origin with principal axes along the body axes.
static void set_diagonal(dMass *m, dReal mass, dReal ixx, dReal iyy, dReal izz)
{
    dMassSetZero(m);
    m->mass = mass;
    m->I[0] = ixx;
    m->I[5] = iyy;
    m->I[10] = izz;
}

// A solid of revolution about body axis `direction`: axial and transverse inertia.
static void set_axial(dMass *m, dReal mass, int direction, dReal axial, dReal transverse)
{
    set_diagonal(m, mass, transverse, transverse, transverse);
    m->I[5 * (direction - 1)] = axial;
}

// The checks shared by every solid: `amount` is a density or a total mass.
static int solid_args_ok(const char *fn, const dMass *m, dReal amount, int by_total)
{
    REQUIRE(m != NULL, "m is NULL");
    REQUIRE(positive(amount), "%s %g must be positive and finite",
            by_total ? "the total mass" : "the density", (double)amount);
    return 1;
}

// The checks of the capsule and the cylinder.
static int round_args_ok(const char *fn, const dMass *m, dReal amount, int by_total,
                         int direction, dReal radius, dReal length)
{
    if (!solid_args_ok(fn, m, amount, by_total)) return 0;
    REQUIRE(direction >= 1 && direction <= 3, "direction %d must be 1 (x), 2 (y) or 3 (z)",
            direction);
    REQUIRE(size_ok(radius), "the radius %g must be >= 0 and finite", (double)radius);
    REQUIRE(dxIsFinite(length) && length >= 0, "the length %g must be >= 0 and finite",
            (double)length);
    return 1;
}

// A sphere of the given mass: I = 2/5 m r^2.
static void set_sphere(dMass *m, dReal mass, dReal r)
{
    dReal i = REAL(0.4) * mass * r * r;
    set_diagonal(m, mass, i, i, i);
    dMassCheck(m);
}

// The solids below: by density, or (the Total forms) by total mass.
void dMassSetSphere(dMass *m, dReal density, dReal radius)
{
    if (!solid_args_ok(__func__, m, density, 0)) return;
    DX_CHECK_ARG(size_ok(radius), return, "the radius %g must be >= 0 and finite",
                 (double)radius);
    set_sphere(m, REAL(4.0) / 3 * (dReal)M_PI * radius * radius * radius * density, radius);
}

void dMassSetSphereTotal(dMass *m, dReal total_mass, dReal radius)
{
    if (!solid_args_ok(__func__, m, total_mass, 1)) return;
    DX_CHECK_ARG(size_ok(radius), return, "the radius %g must be >= 0 and finite",
                 (double)radius);
    set_sphere(m, total_mass, radius);
}

// A capsule of the given mass: a cylinder (mass M1, length l) and two
// hemispherical caps (together a sphere of mass M2) in the ratio of their
// volumes, M1 : M2 = pi r^2 l : 4/3 pi r^3 = 3l : 4r. Each cap has its centre
// of mass 3r/8 beyond the cylinder's end, which by the parallel axis theorem
// gives the transverse term M2 (2/5 r^2 + 3/8 r l + l^2/4).
static void set_capsule(dMass *m, dReal mass, int direction, dReal r, dReal l)
{
    const dReal parts = 3 * l + 4 * r;   // 0 for a point: no part has mass then
    dReal m1 = parts > 0 ? mass * (3 * l) / parts : 0;
    dReal m2 = parts > 0 ? mass * (4 * r) / parts : 0;
    dReal axial = (REAL(0.5) * m1 + REAL(0.4) * m2) * r * r;
    dReal transverse = m1 * (REAL(0.25) * r * r + l * l / 12) +
                       m2 * (REAL(0.4) * r * r + REAL(0.375) * r * l + REAL(0.25) * l * l);
    set_axial(m, mass, direction, axial, transverse);
    dMassCheck(m);
}

// Volume of a capsule: cylinder plus sphere, pi r^2 (l + 4/3 r).
static dReal capsule_volume(dReal r, dReal l)
{
    return (dReal)M_PI * r * r * (l + REAL(4.0) / 3 * r);
}

void dMassSetCapsule(dMass *m, dReal density, int direction, dReal radius, dReal length)
{
    if (!round_args_ok(__func__, m, density, 0, direction, radius, length)) return;
    set_capsule(m, density * capsule_volume(radius, length), direction, radius, length);
}

void dMassSetCapsuleTotal(dMass *m, dReal total_mass, int direction, dReal radius, dReal length)
{
    if (!round_args_ok(__func__, m, total_mass, 1, direction, radius, length)) return;
    set_capsule(m, total_mass, direction, radius, length);
}

// The ODE 0.5 names of the capsule functions.
void dMassSetCappedCylinder(dMass *m, dReal density, int direction, dReal radius, dReal length)
{
    if (!round_args_ok(__func__, m, density, 0, direction, radius, length)) return;
    set_capsule(m, density * capsule_volume(radius, length), direction, radius, length);
}

void dMassSetCappedCylinderTotal(dMass *m, dReal total_mass, int direction, dReal radius,
                                 dReal length)
{
    if (!round_args_ok(__func__, m, total_mass, 1, direction, radius, length)) return;
    set_capsule(m, total_mass, direction, radius, length);
}

// A solid cylinder of the given mass: axial m r^2/2, transverse m (r^2/4 + l^2/12).
static void set_cylinder(dMass *m, dReal mass, int direction, dReal r, dReal l)
{
    set_axial(m, mass, direction, REAL(0.5) * mass * r * r,
              mass * (REAL(0.25) * r * r + l * l / 12));
    dMassCheck(m);
}

void dMassSetCylinder(dMass *m, dReal density, int direction, dReal radius, dReal length)
{
    if (!round_args_ok(__func__, m, density, 0, direction, radius, length)) return;
    set_cylinder(m, density * (dReal)M_PI * radius * radius * length, direction, radius, length);
}

void dMassSetCylinderTotal(dMass *m, dReal total_mass, int direction, dReal radius,
                           dReal length)
{
    if (!round_args_ok(__func__, m, total_mass, 1, direction, radius, length)) return;
    set_cylinder(m, total_mass, direction, radius, length);
}

// The checks of the box: every side >= 0.
static int box_args_ok(const char *fn, const dMass *m, dReal amount, int by_total, dReal lx,
                       dReal ly, dReal lz)
{
    if (!solid_args_ok(fn, m, amount, by_total)) return 0;
    REQUIRE(size_ok(lx) && size_ok(ly) && size_ok(lz),
            "the sides (%g, %g, %g) must be >= 0 and finite", (double)lx, (double)ly,
            (double)lz);
    return 1;
}

// A box of the given mass: Ixx = m (ly^2 + lz^2) / 12 and so on.
static void set_box(dMass *m, dReal mass, dReal lx, dReal ly, dReal lz)
{
    dReal k = mass / 12;
    set_diagonal(m, mass, k * (ly * ly + lz * lz), k * (lx * lx + lz * lz),
                 k * (lx * lx + ly * ly));
    dMassCheck(m);
}

void dMassSetBox(dMass *m, dReal density, dReal lx, dReal ly, dReal lz)
{
    if (!box_args_ok(__func__, m, density, 0, lx, ly, lz)) return;
    set_box(m, density * lx * ly * lz, lx, ly, lz);
}

void dMassSetBoxTotal(dMass *m, dReal total_mass, dReal lx, dReal ly, dReal lz)
{
    if (!box_args_ok(__func__, m, total_mass, 1, lx, ly, lz)) return;
    set_box(m, total_mass, lx, ly, lz);
}

// The same shape with another mass: inertia scales with the mass.
void dMassAdjust(dMass *m, dReal newmass)
{
    DX_CHECK_ARG(m != NULL, return, "m is NULL");
    DX_CHECK_ARG(positive(newmass), return, "the new mass %g must be positive and finite",
                 (double)newmass);
    DX_CHECK_ARG(positive(m->mass), return, "the mass %g cannot be scaled to %g",
                 (double)m->mass, (double)newmass);
    dReal scale = newmass / m->mass;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) m->I[4 * i + j] *= scale;
    m->mass = newmass;
}

// Parallel axis theorem about the origin: moving the centre of mass from c to
// d = c + t changes I by mass ([c]x^2 - [d]x^2), where
// [v]x^2 = v v^T - |v|^2 E.
void dMassTranslate(dMass *m, dReal x, dReal y, dReal z)
{
    DX_CHECK_ARG(m != NULL, return, "m is NULL");
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "(%g, %g, %g) is not finite", (double)x,
                 (double)y, (double)z);
    const dReal *c = m->c;
    dReal d[3] = {c[0] + x, c[1] + y, c[2] + z};
    dReal diag = dCalcVectorLengthSquare3(c) - (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m->I[4 * i + j] += m->mass * ((c[i] * c[j] - d[i] * d[j]) - (i == j ? diag : 0));
    for (int i = 0; i < 3; i++) m->c[i] = d[i];
}

// Rotating the object by R about the origin: I -> R I R^T, c -> R c.
void dMassRotate(dMass *m, const dMatrix3 R)
{
    DX_CHECK_ARG(m != NULL && R != NULL, return, "m or R is NULL");
    for (int i = 0; i < 3; i++)
        DX_CHECK_ARG(dxIsFinite3(R[4 * i], R[4 * i + 1], R[4 * i + 2]), return,
                     "R is not finite");
    dMatrix3 RI, I2;
    dMultiply0_333(RI, R, m->I);
    dMultiply2_333(I2, RI, R);
    // R I R^T is symmetric; average away the rounding that says otherwise
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m->I[4 * i + j] = REAL(0.5) * (I2[4 * i + j] + I2[4 * j + i]);
    dMultiply0_331(m->c, R, m->c);
}

// Two objects taken together: masses and inertias (both about the same
// origin) add, and the centre of mass is the mass-weighted mean.
void dMassAdd(dMass *a, const dMass *b)
{
    DX_CHECK_ARG(a != NULL && b != NULL, return, "a or b is NULL");
    dReal total = a->mass + b->mass;
    DX_CHECK_ARG(dxIsFinite(total) && total != 0, return,
                 "the total mass (%g + %g) must be nonzero and finite", (double)a->mass,
                 (double)b->mass);
    for (int i = 0; i < 3; i++) a->c[i] = (a->mass * a->c[i] + b->mass * b->c[i]) / total;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) a->I[4 * i + j] += b->I[4 * i + j];
    a->mass = total;
}
