// SPDX-License-Identifier: BSD-3-Clause
//
// diff_boxbox.c -- ODE 0.16's public dBoxBox against the reference on boxes
// whose contact is a clear face contact (a box resting flat or tilted on a
// bigger box, a box pushed into another's side): contact count, axis code,
// normal, depth and the contacts' depths (tolerance 1e-9).
// Edge-edge poses are compared through dCollide in diff_collide_analytic.c.

#include "diff_print.h"

#include <stdio.h>

static void vec(dVector3 v, double x, double y, double z)
{
    v[0] = x;
    v[1] = y;
    v[2] = z;
    v[3] = 0;
}

static void scene(const char *name, const dVector3 p1, const dMatrix3 R1, const dVector3 s1,
                  const dVector3 p2, const dMatrix3 R2, const dVector3 s2)
{
    dContactGeom c[8];
    dVector3 normal;
    dReal depth;
    int code;
    char what[96];
    int n = dBoxBox(p1, R1, s1, p2, R2, s2, normal, &depth, &code, 8, c, sizeof c[0]);
    snprintf(what, sizeof what, "%s_count", name);
    diff_value(what, 0, n);
    if (n == 0) return;   // ODE 0.16 leaves the outputs unset then
    snprintf(what, sizeof what, "%s_code", name);
    diff_value(what, 0, code);
    snprintf(what, sizeof what, "%s_normal", name);
    diff_values(what, 1e-9, normal, 3);
    snprintf(what, sizeof what, "%s_depth", name);
    diff_value(what, 1e-9, depth);
    // The contacts' depths, deepest first. (Their positions are not compared:
    // ours lie midway through the overlap, ODE's on the reference face.)
    dReal depths[8];
    for (int i = 0; i < n; i++) depths[i] = c[i].depth;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (depths[j] > depths[i]) {
                dReal t = depths[i];
                depths[i] = depths[j];
                depths[j] = t;
            }
    snprintf(what, sizeof what, "%s_contact_depths", name);
    diff_values(what, 1e-9, depths, n);
}

int main(void)
{
    dInitODE2(0);
    dVector3 p1, p2, s1, s2;
    dMatrix3 I, R;
    dRSetIdentity(I);
    vec(s1, 1, 1, 1);
    vec(s2, 4, 4, 1);
    vec(p2, 0, 0, -0.5);
    vec(p1, 0, 0, 0.49);
    scene("resting", p1, I, s1, p2, I, s2);
    dRFromAxisAndAngle(R, 0, 0, 1, 0.3);
    vec(p1, 0.2, -0.1, 0.48);
    scene("resting_turned", p1, R, s1, p2, I, s2);
    dRFromAxisAndAngle(R, 1, 0, 0, 0.1);
    vec(p1, 0, 0, 0.5);
    scene("tilted", p1, R, s1, p2, I, s2);
    vec(s1, 0.5, 2, 0.7);
    vec(p1, 2.2, 0, 0);
    vec(p2, 0, 0, 0);
    vec(s2, 4, 4, 4);
    scene("side", p1, I, s1, p2, I, s2);
    vec(p1, 0, 0, 3);
    scene("apart", p1, I, s1, p2, I, s2);
    dCloseODE();
    return 0;
}
