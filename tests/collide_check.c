// SPDX-License-Identifier: BSD-3-Clause
//
// collide_check.c -- see collide_check.h.

#include "collide_check.h"
#include "test.h"

#include <math.h>
#include <string.h>

void set_rot(dGeomID g, dReal ax, dReal ay, dReal az, dReal angle)
{
    dMatrix3 R;
    dRFromAxisAndAngle(R, ax, ay, az, angle);
    dGeomSetRotation(g, R);
}

// The cylinder's point depth: inside, the distance to the nearer of the caps
// and the side; outside, minus the distance to the solid.
static dReal cylinder_point_depth(dGeomID g, const dReal *p)
{
    dReal r, len;
    dGeomCylinderGetParams(g, &r, &len);
    const dReal *c = dGeomGetPosition(g), *R = dGeomGetRotation(g);
    dReal d[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] }, q[3];
    for (int i = 0; i < 3; i++) q[i] = R[i] * d[0] + R[4 + i] * d[1] + R[8 + i] * d[2];
    dReal axial = fabs(q[2]) - len / 2, radial = sqrt(q[0] * q[0] + q[1] * q[1]) - r;
    if (axial <= 0 && radial <= 0) return -(axial > radial ? axial : radial);
    dReal oa = axial > 0 ? axial : 0, orad = radial > 0 ? radial : 0;
    return -sqrt(oa * oa + orad * orad);
}

dReal point_depth(dGeomID g, const dReal *p)
{
    switch (dGeomGetClass(g)) {
    case dSphereClass: return dGeomSpherePointDepth(g, p[0], p[1], p[2]);
    case dBoxClass: return dGeomBoxPointDepth(g, p[0], p[1], p[2]);
    case dCapsuleClass: return dGeomCapsulePointDepth(g, p[0], p[1], p[2]);
    case dPlaneClass: return dGeomPlanePointDepth(g, p[0], p[1], p[2]);
    default: return cylinder_point_depth(g, p);
    }
}

int deepest(const dContactGeom *c, int n)
{
    int k = 0;
    for (int i = 1; i < n; i++)
        if (c[i].depth > c[k].depth) k = i;
    return k;
}

dReal depth_after_separation(dGeomID a, dGeomID b, const dContactGeom *k, dReal margin)
{
    int move_a = dGeomGetClass(a) != dPlaneClass;
    dGeomID g = move_a ? a : b;
    dReal s = (move_a ? 1 : -1) * (k->depth + margin);
    dVector3 p;
    dGeomCopyPosition(g, p);
    dGeomSetPosition(g, p[0] + s * k->normal[0], p[1] + s * k->normal[1], p[2] + s * k->normal[2]);
    dContactGeom c[64];
    int n = dCollide(a, b, 64, c, sizeof c[0]);
    dGeomSetPosition(g, p[0], p[1], p[2]);
    return n ? c[deepest(c, n)].depth : 0;
}

unsigned long long rng_state;

double rnd(double lo, double hi)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

int backend_built(const char *name)
{
    for (const char *const *b = dCollisionListBackends(); *b; b++)
        if (strcmp(*b, name) == 0) return 1;
    return 0;
}

int backend_answers(const char *backend, dGeomID a, dGeomID b)
{
    dContactGeom c[16];
    dCollisionSetBackend(backend);
    test_capture_reports();
    dCollisionSetStrict(1);
    dCollide(a, b, 16, c, sizeof c[0]);
    dCollisionSetStrict(0);
    int answered = !test_captured_contains("cannot collide");
    test_release_reports();
    return answered;
}
