// SPDX-License-Identifier: BSD-3-Clause
//
// joint_dball.c -- the double ball joint (ODE 0.16): one anchor on each body,
// kept at a fixed distance (a massless rod with ball joints at both ends).
// The distance is the anchors' distance when an anchor is set or the joint is
// attached, or what dJointSetDBallDistance says. The row has its own ERP and
// CFM (dParamERP, dParamCFM; the world's by default). The double ball
// functions also accept a double hinge joint, which is one (as in ODE).

#include "joint_dball.h"

void dxDBallInit(dxJoint *j)
{
    dxJointDBall *d = (dxJointDBall *)j;
    d->erp = j->world->erp;
    d->cfm = j->world->cfm;
}

// World position of point p stored in the frame of stored body k (or world).
static void to_world(const dxJoint *j, int k, dVector3 out, const dVector3 p)
{
    const struct dxBody *b = dxJointBody(j, k);
    if (b) {
        dMultiply0_331(out, b->R, p);
        dAddVectors3(out, out, b->pos);
    } else {
        dCopyVector3(out, p);
    }
    out[3] = 0;
}

// World point (x,y,z) in the frame of stored body k (or world).
static void from_world(const dxJoint *j, int k, dVector3 out, dReal x, dReal y, dReal z)
{
    const struct dxBody *b = dxJointBody(j, k);
    dVector3 p = { x, y, z, 0 };
    if (b) {
        dVector3 r;
        dSubtractVectors3(r, p, b->pos);
        dMultiply1_331(out, b->R, r);
    } else {
        dCopyVector3(out, p);
    }
    out[3] = 0;
}

void dxDBallWorldAnchors(const dxJoint *j, dVector3 p1, dVector3 p2)
{
    const dxJointDBall *d = (const dxJointDBall *)j;
    to_world(j, 0, p1, d->anchor1);
    to_world(j, 1, p2, d->anchor2);
}

void dxDBallUpdateDistance(dxJoint *j)
{
    if (!dxJointBody(j, 0)) return;   // detached (dJointAttach(j, 0, 0)): keep it
    dVector3 p1, p2;
    dxDBallWorldAnchors(j, p1, p2);
    ((dxJointDBall *)j)->distance = dCalcPointsDistance3(p1, p2);
}

// The row acts along the unit direction q from anchor 2 to anchor 1:
// q . (v0 + w0 x r1 - v1 - w1 x r2) = fps erp (distance - |p1 - p2|), with
// r1, r2 the anchors relative to the centres. Coinciding anchors have no
// direction: the relative velocity of the anchors gives one, else x.
void dxDBallDistanceRow(const dxJoint *j, dxJointRows *rows)
{
    const dxJointDBall *d = (const dxJointDBall *)j;
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
#ifdef dSINGLE
    const dReal min_length = REAL(1e-7);
#else
    const dReal min_length = REAL(1e-12);
#endif
    dVector3 p1, p2, r1, r2 = { 0, 0, 0, 0 }, q;
    dxDBallWorldAnchors(j, p1, p2);
    dSubtractVectors3(r1, p1, b0->pos);
    if (b1) dSubtractVectors3(r2, p2, b1->pos);
    dSubtractVectors3(q, p1, p2);
    if (dCalcVectorLength3(q) < min_length) {
        dVector3 v1, v2 = { 0, 0, 0, 0 };
        dCalcVectorCross3(v1, b0->avel, r1);
        dAddVectors3(v1, v1, b0->lvel);
        if (b1) {
            dCalcVectorCross3(v2, b1->avel, r2);
            dAddVectors3(v2, v2, b1->lvel);
        }
        dSubtractVectors3(q, v1, v2);
        if (dCalcVectorLength3(q) < min_length) dAssignVector3(q, 1, 0, 0);
    }
    dNormalize3(q);
    dCopyVector3(rows->J1l, q);
    dCalcVectorCross3(rows->J1a, r1, q);
    if (b1) {
        dCopyNegatedVector3(rows->J2l, q);
        dCalcVectorCross3(rows->J2a, q, r2);
    }
    rows->c[0] = rows->fps * d->erp * (d->distance - dCalcPointsDistance3(p1, p2));
    rows->cfm[0] = d->cfm;
}

static void dball_count_rows(dxJoint *j, dxJointRowCount *count)
{
    count->m = count->nub = dxJointBody(j, 0) ? 1 : 0;
}

static void dball_fill_rows(dxJoint *j, dxJointRows *rows) { dxDBallDistanceRow(j, rows); }

static const dxJointClass dball_class = {
    dJointTypeDBall, "double ball", sizeof(dxJointDBall), dxDBallInit, dball_count_rows,
    dball_fill_rows, dxDBallUpdateDistance
};

dJointID dJointCreateDBall(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &dball_class);
}

#define DBALL(j, on_fail) \
    DX_CHECK_ARG(dxJointIsDBall(j), on_fail, \
                 "joint is NULL, destroyed or not a double ball or double hinge joint")

// Set the anchor on user body k (0: body 1, 1: body 2); the distance becomes
// the anchors' distance.
static void set_anchor(dxJoint *j, int k, dReal x, dReal y, dReal z)
{
    dxJointDBall *d = (dxJointDBall *)j;
    if (j->flags & DX_JOINT_REVERSE) k = 1 - k;
    from_world(j, k, k == 0 ? d->anchor1 : d->anchor2, x, y, z);
    dxDBallUpdateDistance(j);
}

static void get_anchor(const dxJoint *j, int k, dVector3 result)
{
    const dxJointDBall *d = (const dxJointDBall *)j;
    if (j->flags & DX_JOINT_REVERSE) k = 1 - k;
    to_world(j, k, result, k == 0 ? d->anchor1 : d->anchor2);
}

void dJointSetDBallAnchor1(dJointID j, dReal x, dReal y, dReal z)
{
    DBALL(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    set_anchor(j, 0, x, y, z);
}

void dJointSetDBallAnchor2(dJointID j, dReal x, dReal y, dReal z)
{
    DBALL(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    set_anchor(j, 1, x, y, z);
}

void dJointGetDBallAnchor1(dJointID j, dVector3 result)
{
    DBALL(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    get_anchor(j, 0, result);
}

void dJointGetDBallAnchor2(dJointID j, dVector3 result)
{
    DBALL(j, return);
    DX_CHECK_ARG(result != NULL, return, "result is NULL");
    get_anchor(j, 1, result);
}

dReal dJointGetDBallDistance(dJointID j)
{
    DBALL(j, return 0);
    return ((dxJointDBall *)j)->distance;
}

void dJointSetDBallDistance(dJointID j, dReal dist)
{
    DBALL(j, return);
    DX_CHECK_ARG(dxIsFinite(dist) && dist >= 0, return,
                 "distance must be finite and >= 0, got %g", (double)dist);
    ((dxJointDBall *)j)->distance = dist;
}

void dJointSetDBallParam(dJointID j, int parameter, dReal value)
{
    DBALL(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    dxJointDBall *d = (dxJointDBall *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    if (param == dParamERP) d->erp = value;
    else if (param == dParamCFM) d->cfm = value;
}

dReal dJointGetDBallParam(dJointID j, int parameter)
{
    DBALL(j, return 0);
    const dxJointDBall *d = (const dxJointDBall *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    if (param == dParamERP) return d->erp;
    if (param == dParamCFM) return d->cfm;
    return 0;
}
