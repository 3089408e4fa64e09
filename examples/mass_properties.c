// SPDX-License-Identifier: BSD-3-Clause
//
// mass_properties.c -- builds the mass of a dumbbell (two spheres on a
// capsule bar) from ODE's mass functions, turns it, and prints what a rigid
// body would be given: total mass, centre of mass and inertia tensor.

#include <ode/ode.h>

static void print_mass(const char *title, const dMass *m)
{
    printf("%s\n  mass %.4f kg, centre of mass (%.4f, %.4f, %.4f) m\n", title,
           (double)m->mass, (double)m->c[0], (double)m->c[1], (double)m->c[2]);
    for (int i = 0; i < 3; i++)
        printf("  | %9.5f %9.5f %9.5f |\n", (double)m->I[i * 4], (double)m->I[i * 4 + 1],
               (double)m->I[i * 4 + 2]);
}

int main(void)
{
    dInitODE2(0);

    const dReal steel = 7850, radius = 0.05, bar_length = 0.4;
    dMass bar, bell, dumbbell;

    dMassSetCapsule(&bar, steel, 1, 0.01, bar_length);   // along body x
    dumbbell = bar;
    for (int side = -1; side <= 1; side += 2) {
        dMassSetSphere(&bell, steel, radius);
        dMassTranslate(&bell, side * (bar_length / 2 + radius), 0, 0);
        dMassAdd(&dumbbell, &bell);
    }
    print_mass("dumbbell along x:", &dumbbell);

    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, M_PI / 2);   // turn it to lie along y
    dMassRotate(&dumbbell, R);
    print_mass("turned 90 degrees about z (now along y):", &dumbbell);

    printf("dMassCheck: %s\n", dMassCheck(&dumbbell) ? "valid" : "invalid");
    dCloseODE();
    return dMassCheck(&dumbbell) ? 0 : 1;
}
