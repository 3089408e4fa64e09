// SPDX-License-Identifier: BSD-3-Clause
//
// geom_plane_ray.c -- the plane (guide 10.7.3: not placeable, a half-space
// below a x + b y + c z = d) and ray (10.7.5) classes.

#include "shapes.h"

#include <ode/rotation.h>

#include <string.h>

#include "../libodedyn/math/unit_vector.h"

#define CHECK_CLASS(g, c, label, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->ops->cls == (c), on_fail, "geom is a %s, not a " label, \
                     (g)->ops->name); \
    } while (0)

// ---- plane ----------------------------------------------------------------------

// A plane's box is infinite unless it is perpendicular to an axis, when the
// solid side is bounded along that axis.
static void plane_aabb(dxGeom *g)
{
    const dReal *p = ((dxPlane *)g)->p;
    dInfiniteAABB(g, g->aabb);
    for (int i = 0; i < 3; i++) {
        if (p[i] == 1 && p[(i + 1) % 3] == 0 && p[(i + 2) % 3] == 0) g->aabb[2 * i + 1] = p[3];
        if (p[i] == -1 && p[(i + 1) % 3] == 0 && p[(i + 2) % 3] == 0) g->aabb[2 * i] = -p[3];
    }
}

const dxGeomClassOps dx_plane_ops = { dPlaneClass, "plane", plane_aabb, NULL };

// Store the plane with a unit normal; 0 if (a, b, c) has no direction.
static int set_plane(dxPlane *pl, dReal a, dReal b, dReal c, dReal d)
{
    dReal len = dSqrt(a * a + b * b + c * c);
    if (!(len > 0) || !dxIsFinite(len) || !dxIsFinite(d)) return 0;
    pl->p[0] = a / len;
    pl->p[1] = b / len;
    pl->p[2] = c / len;
    pl->p[3] = d / len;
    return 1;
}

dGeomID dCreatePlane(dSpaceID space, dReal a, dReal b, dReal c, dReal d)
{
    dxPlane tmp;
    DX_CHECK_ARG(set_plane(&tmp, a, b, c, d), return NULL,
                 "the normal (%g, %g, %g) has no direction, or d is not finite", (double)a,
                 (double)b, (double)c);
    dxPlane *pl = (dxPlane *)dxGeomCreate(sizeof *pl, &dx_plane_ops, 0, space);
    memcpy(pl->p, tmp.p, sizeof pl->p);
    return &pl->g;
}

void dGeomPlaneSetParams(dGeomID g, dReal a, dReal b, dReal c, dReal d)
{
    CHECK_CLASS(g, dPlaneClass, "plane", return);
    dxPlane tmp;
    DX_CHECK_ARG(set_plane(&tmp, a, b, c, d), return,
                 "the normal (%g, %g, %g) has no direction, or d is not finite", (double)a,
                 (double)b, (double)c);
    memcpy(((dxPlane *)g)->p, tmp.p, sizeof tmp.p);
    dxGeomShapeChanged(g);
}

void dGeomPlaneGetParams(dGeomID g, dVector4 result)
{
    CHECK_CLASS(g, dPlaneClass, "plane", return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    dCopyVector4(result, ((dxPlane *)g)->p);
}

dReal dGeomPlanePointDepth(dGeomID g, dReal x, dReal y, dReal z)
{
    CHECK_CLASS(g, dPlaneClass, "plane", return 0);
    const dReal *p = ((dxPlane *)g)->p;
    return p[3] - (p[0] * x + p[1] * y + p[2] * z);
}

// ---- ray ------------------------------------------------------------------------

static void ray_aabb(dxGeom *g)
{
    const dReal len = ((dxRay *)g)->length;
    for (int i = 0; i < 3; i++) {
        dReal end = g->pos[i] + g->R[4 * i + 2] * len;
        g->aabb[2 * i] = dMin(g->pos[i], end);
        g->aabb[2 * i + 1] = dMax(g->pos[i], end);
    }
}

const dxGeomClassOps dx_ray_ops = { dRayClass, "ray", ray_aabb, NULL };

dGeomID dCreateRay(dSpaceID space, dReal length)
{
    DX_CHECK_ARG(length >= 0 && dxIsFinite(length), return NULL,
                 "length must be >= 0 and finite, got %g", (double)length);
    dxRay *r = (dxRay *)dxGeomCreate(sizeof *r, &dx_ray_ops, DX_GEOM_PLACEABLE, space);
    r->length = length;
    return &r->g;
}

void dGeomRaySetLength(dGeomID g, dReal length)
{
    CHECK_CLASS(g, dRayClass, "ray", return);
    DX_CHECK_ARG(length >= 0 && dxIsFinite(length), return,
                 "length must be >= 0 and finite, got %g", (double)length);
    ((dxRay *)g)->length = length;
    dxGeomShapeChanged(g);
}

dReal dGeomRayGetLength(dGeomID g)
{
    CHECK_CLASS(g, dRayClass, "ray", return 0);
    return ((dxRay *)g)->length;
}

// A rotation whose z column is the unit vector n, bit for bit, and whose x
// and y columns complete it to a right-handed orthonormal frame (Duff et
// al., "Building an orthonormal basis, revisited", 2017): with s the sign of
// n_z, 1 / (s + n_z) never divides by less than 1 in size, and the frame
// costs one division, no square root and no branch. Its columns are
// orthonormal to within a few units in the last place for a unit n.
static void ray_frame(const dReal n[3], dReal *R)
{
    const dReal s = dCopySign((dReal)1, n[2]), a = -1 / (s + n[2]), b = n[0] * n[1] * a;
    R[0] = 1 + s * n[0] * n[0] * a;
    R[1] = b;
    R[2] = n[0];
    R[4] = s * b;
    R[5] = s + n[1] * n[1] * a;
    R[6] = n[1];
    R[8] = -s * n[0];
    R[9] = -n[1];
    R[10] = n[2];
    R[3] = R[7] = R[11] = 0;
}

// Place the ray at p pointing along d: the direction is d normalised as
// dSafeNormalize3 does (the z column of the rotation, as in ODE), the x and
// y columns ray_frame's. A ray on no body takes them directly, with one walk
// up the spaces; one on a body turns and moves the body (dGeomSetRotation,
// whose clean-up of the rotation may move its last bits, and
// dGeomSetPosition).
void dGeomRaySet(dGeomID g, dReal px, dReal py, dReal pz, dReal dx, dReal dy, dReal dz)
{
    CHECK_CLASS(g, dRayClass, "ray", return);
    DX_CHECK_ARG(dxIsFinite3(px, py, pz), return, "start point is not finite");
    dVector3 d = { dx, dy, dz, 0 };
    DX_CHECK_ARG(dxIsFinite3(dx, dy, dz) && dxUnitVector3(d), return,
                 "direction (%g, %g, %g) has no length", (double)dx, (double)dy, (double)dz);
    if (!g->body) {
        ray_frame(d, g->own_R);
        dAssignVector3(g->own_pos, px, py, pz);
        dxGeomMarkMoved(g);
        return;
    }
    dMatrix3 R;
    ray_frame(d, R);
    dGeomSetRotation(g, R);
    dGeomSetPosition(g, px, py, pz);
}

void dGeomRayGet(dGeomID g, dVector3 start, dVector3 dir)
{
    CHECK_CLASS(g, dRayClass, "ray", return);
    DX_CHECK_ARG(start != NULL && dir != NULL, return, "start or dir is NULL");
    dCopyVector3(start, g->pos);
    dGetMatrixColumn3(dir, g->R, 2);
}

#define RAY_FLAG(Name, field) \
    void dGeomRaySet##Name(dGeomID g, int value) \
    { \
        CHECK_CLASS(g, dRayClass, "ray", return); \
        ((dxRay *)g)->field = value != 0; \
    } \
    int dGeomRayGet##Name(dGeomID g) \
    { \
        CHECK_CLASS(g, dRayClass, "ray", return 0); \
        return ((dxRay *)g)->field; \
    }

RAY_FLAG(FirstContact, first_contact)
RAY_FLAG(BackfaceCull, backface_cull)
RAY_FLAG(ClosestHit, closest_hit)

// The ODE 0.5 pair of the first two flags (deprecated in ODE 0.16).
void dGeomRaySetParams(dGeomID g, int FirstContact, int BackfaceCull)
{
    CHECK_CLASS(g, dRayClass, "ray", return);
    ((dxRay *)g)->first_contact = FirstContact != 0;
    ((dxRay *)g)->backface_cull = BackfaceCull != 0;
}

void dGeomRayGetParams(dGeomID g, int *FirstContact, int *BackfaceCull)
{
    CHECK_CLASS(g, dRayClass, "ray", return);
    DX_CHECK_ARG(FirstContact != NULL && BackfaceCull != NULL, return,
                 "FirstContact or BackfaceCull is NULL");
    *FirstContact = ((dxRay *)g)->first_contact;
    *BackfaceCull = ((dxRay *)g)->backface_cull;
}
