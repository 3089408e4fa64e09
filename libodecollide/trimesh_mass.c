// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_mass.c -- dMassSetTrimesh / dMassSetTrimeshTotal (declared in
// mass.h as in ODE, defined here since they read the geom): the exact
// volume integrals of a closed, outward-wound mesh in world coordinates,
// summed over the tetrahedra (origin, v0, v1, v2) with signed volumes.

#include <ode/mass.h>

#include "trimesh_internal.h"

// Volume, first moments and second moments (sum of x_i x_j dV) of the
// mesh's solid, in world coordinates.
static void volume_integrals(dxGeom *g, dReal *volume, dReal first[3], dReal second[3][3])
{
    const dxTriMeshData *d = ((dxTriMesh *)g)->data;
    *volume = 0;
    for (int i = 0; i < 3; i++) {
        first[i] = 0;
        for (int j = 0; j < 3; j++) second[i][j] = 0;
    }
    for (int t = 0; d && t < d->tri_count; t++) {
        dVector3 v[3];
        dGeomTriMeshGetTriangle(g, t, &v[0], &v[1], &v[2]);
        dVector3 bc;
        dCalcVectorCross3(bc, v[1], v[2]);
        dReal vol = dCalcVectorDot3(v[0], bc) / 6;   // det[v0 v1 v2] / 6
        dReal s[3];
        for (int i = 0; i < 3; i++) s[i] = v[0][i] + v[1][i] + v[2][i];
        *volume += vol;
        for (int i = 0; i < 3; i++) {
            first[i] += vol * s[i] / 4;
            // A tetrahedron with one vertex at the origin: the integral of
            // x_i x_j is vol / 20 (sum_k v_k,i v_k,j + s_i s_j).
            for (int j = 0; j < 3; j++) {
                dReal vv = v[0][i] * v[0][j] + v[1][i] * v[1][j] + v[2][i] * v[2][j];
                second[i][j] += vol / 20 * (vv + s[i] * s[j]);
            }
        }
    }
}

// As ODE 0.16: the inertia about the world origin, then dMassTranslate to
// the centre of mass (which adds the parallel-axis term, so only a mesh
// centred on the origin gives the inertia about its centre).
void dMassSetTrimesh(dMass *m, dReal density, dGeomID g)
{
    DX_CHECK_ARG(m != NULL, return, "m is NULL");
    DX_CHECK_ARG(density > 0 && dxIsFinite(density), return,
                 "density must be positive and finite, got %g", (double)density);
    DX_CHECK_GEOM(g, return);
    DX_CHECK_ARG(g->ops->cls == dTriMeshClass, return, "geom is a %s, not a trimesh",
                 g->ops->name);
    dReal volume, first[3], second[3][3];
    volume_integrals(g, &volume, first, second);
    DX_CHECK_ARG(volume > 0 && dxIsFinite(volume), return,
                 "the mesh encloses no volume (%g): it must be closed and wound outwards",
                 (double)volume);
    dReal trace = second[0][0] + second[1][1] + second[2][2];
    dReal I[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) I[i][j] = density * ((i == j ? trace : 0) - second[i][j]);
    dMassSetParameters(m, density * volume, 0, 0, 0, I[0][0], I[1][1], I[2][2], I[0][1],
                       I[0][2], I[1][2]);
    dMassTranslate(m, first[0] / volume, first[1] / volume, first[2] / volume);
}

void dMassSetTrimeshTotal(dMass *m, dReal total_mass, dGeomID g)
{
    DX_CHECK_ARG(total_mass > 0 && dxIsFinite(total_mass), return,
                 "total_mass must be positive and finite, got %g", (double)total_mass);
    dMass tmp;
    dMassSetZero(&tmp);
    dMassSetTrimesh(&tmp, 1, g);
    if (tmp.mass <= 0) return;   // reported
    dMassAdjust(&tmp, total_mass);
    *m = tmp;
}
