// SPDX-License-Identifier: BSD-3-Clause
//
// joint_transmission.c -- the transmission joint (ODE 0.16): two wheels,
// each turning about an axis through an anchor on its body, coupled at a
// contact point so that the contact point moves alike on both: gears with
// parallel axes (the contact point divides the line between the anchors in
// the ratio), gears with intersecting axes (bevel gears: the contact points
// are on the line where the wheel planes meet), or a chain (or belt) drive
// between sprockets of given radii (the contact points are where the chain
// leaves the sprockets). One row: the contact points' velocities along the
// tangent l agree, l0 . (v0 + w0 x r0) = l1 . (v1 + w1 x r1).
//
// Phases. When the geometry changes (an anchor or axis set; the first step)
// each wheel remembers, in its body frame, the direction from its anchor to
// its contact point; its phase is then the angle the contact direction has
// turned in that frame since, unwrapped from step to step (so it decreases
// as the wheel turns positively about its axis). The drive keeps the arc
// lengths equal: delta = r0 phase0 + r1 phase1 = 0 for gears, r0 phase0 -
// r1 phase1 = 0 for a chain (signs as the tangent sees the wheels turn, see
// arc_coefficient), corrected with the joint's ERP. With backlash
// b > 0 the row only acts once |delta| > b, and only pushes back towards the
// gap: the wheels turn freely through a play of b (arc length) either way.
// A chain pulls with one branch or the other by the sign of delta: the
// contact points and tangents are mirrored across the line between anchors.
//
// Where this differs from ODE 0.16 on purpose: the line of intersection of
// bevel gears is normalised (ODE leaves it scaled by the sine of the angle
// between the axes, which moves the contact points off the line for axes
// that are not perpendicular); a chain's contact points are placed in the
// sprockets' planes whatever their orientation (ODE's are right only when the
// sprockets' frame is aligned with the world's) and mirrored across the line
// between the anchors (ODE mirrors across a parallel plane through the
// origin); the phase estimate that picks the turn a wheel is in subtracts the
// turn of this step (ODE adds it, which is right only below a quarter turn
// per step); the sign of each wheel's arc in delta follows the tangent (ODE
// adds the arcs of both gears, which for bevel gears with some orientations
// of the axes contradicts the row: there its ERP term makes the teeth slide at
// a constant phase error). In the configurations ODE handles, the results are
// the same.

#include "joint_geometry.h"

#ifdef dSINGLE
#define MIN_LENGTH REAL(1e-6)
#else
#define MIN_LENGTH REAL(1e-12)
#endif

typedef struct dxJointTransmission {
    dxJoint base;
    int mode;                 // dTransmission...
    int update;               // the geometry changed: new reference frames
    dVector3 anchor[2];       // body i frame
    dVector3 axis[2];         // body i frame, unit
    dVector3 reference[2][3]; // body i frame: contact direction, axis x it, axis
    dVector3 contact[2];      // world, as of the last step
    dReal phase[2];
    dReal radius[2];
    dReal ratio, backlash;
    dReal erp, cfm;
} dxJointTransmission;

// The mesh in world coordinates.
typedef struct mesh {
    dVector3 a[2];            // anchors
    dVector3 n[2];            // axes
    dVector3 c[2];            // contact points
    dVector3 l[2];            // tangents (unit)
} mesh;

static dReal clamp1(dReal x) { return x < -1 ? -1 : (x > 1 ? 1 : x); }

// Anchors and axes in the world. A new geometry makes the axes point the same
// way (the same handedness for both wheels) by turning axis 0 round.
static void world_geometry(dxJointTransmission *t, mesh *g)
{
    for (int i = 0; i < 2; i++) {
        const struct dxBody *b = dxJointBody(&t->base, i);
        dMultiply0_331(g->a[i], b->R, t->anchor[i]);
        dAddVectors3(g->a[i], g->a[i], b->pos);
        dMultiply0_331(g->n[i], b->R, t->axis[i]);
    }
    if (t->update && dCalcVectorDot3(g->n[0], g->n[1]) < 0) {
        dNegateVector3(t->axis[0]);
        dNegateVector3(g->n[0]);
    }
}

// Contact points and tangents for the mode; 0 if the geometry has none
// (coinciding anchors, parallel bevel axes, a wheel of no radius).
static int mesh_points(const dxJointTransmission *t, mesh *g)
{
    dVector3 d;
    switch (t->mode) {
    case dTransmissionParallelAxes: {
        dSubtractVectors3(d, g->a[1], g->a[0]);
        dAddVectorScaledVector3(g->c[0], g->a[0], d, t->ratio / (1 + t->ratio));
        dCopyVector3(g->c[1], g->c[0]);
        if (!dSafeNormalize3(d)) return 0;
        for (int i = 0; i < 2; i++) {
            dCalcVectorCross3(g->l[i], d, g->n[i]);
            if (!dSafeNormalize3(g->l[i])) return 0;
        }
        break;
    }
    case dTransmissionIntersectingAxes: {
        // The planes n_i . x = n_i . a_i meet on the line O + s l, with O the
        // point of that line in the plane spanned by the normals. Axes closer
        // to parallel than MIN_LENGTH in sin^2 have no line within reach (den
        // below would round to 0, the points to NaN): no row, as for parallel.
        dCalcVectorCross3(g->l[0], g->n[0], g->n[1]);
        const dReal den = dCalcVectorLengthSquare3(g->l[0]);   // 1 - (n0 . n1)^2
        if (!(den >= MIN_LENGTH) || !dSafeNormalize3(g->l[0])) return 0;
        dCopyVector3(g->l[1], g->l[0]);
        const dReal nn = dCalcVectorDot3(g->n[0], g->n[1]);
        const dReal h0 = dCalcVectorDot3(g->n[0], g->a[0]);
        const dReal h1 = dCalcVectorDot3(g->n[1], g->a[1]);
        dVector3 O;
        dAddScaledVectors3(O, g->n[0], g->n[1], (h0 - h1 * nn) / den, (h1 - h0 * nn) / den);
        for (int i = 0; i < 2; i++) {
            dSubtractVectors3(d, g->a[i], O);
            dAddVectorScaledVector3(g->c[i], O, g->l[i], dCalcVectorDot3(d, g->l[i]));
        }
        break;
    }
    default: {   // chain drive
        // The chain leaves both sprockets where their radius e makes
        // e . d = (r1 - r0) / |a0 - a1| with d the unit baseline (a1 to a0).
        dSubtractVectors3(d, g->a[0], g->a[1]);
        const dReal len = dCalcVectorLength3(d);
        if (len < MIN_LENGTH) return 0;
        const dReal cosphi = clamp1((t->radius[1] - t->radius[0]) / len);
        const dReal sinphi = dSqrt(1 - cosphi * cosphi);
        dScaleVector3(d, 1 / len);
        for (int i = 0; i < 2; i++) {
            dVector3 side, v;
            dCalcVectorCross3(side, g->n[i], d);
            dAddScaledVectors3(v, d, side, t->radius[i] * cosphi, t->radius[i] * sinphi);
            dAddVectors3(g->c[i], g->a[i], v);
            dCalcVectorCross3(g->l[i], v, g->n[i]);
            if (!dSafeNormalize3(g->l[i])) return 0;
        }
        break;
    }
    }
    for (int i = 0; i < 2; i++)
        if (dCalcPointsDistance3(g->c[i], g->a[i]) < MIN_LENGTH) return 0;
    return 1;
}

// Remember each wheel's contact direction in its body frame (phase 0 now).
static void set_reference(dxJointTransmission *t, const mesh *g)
{
    for (int i = 0; i < 2; i++) {
        const struct dxBody *b = dxJointBody(&t->base, i);
        dVector3 r;
        dSubtractVectors3(r, g->c[i], g->a[i]);
        t->radius[i] = dCalcVectorLength3(r);
        dVector3 *ref = t->reference[i];
        dMultiply1_331(ref[0], b->R, r);
        dNormalize3(ref[0]);
        dCopyVector3(ref[2], t->axis[i]);
        dCalcVectorCross3(ref[1], ref[2], ref[0]);
        t->phase[i] = 0;
    }
    t->ratio = t->radius[0] / t->radius[1];
    t->update = 0;
}

// The new phase of wheel i: the angle of its contact direction in its
// reference frame, taken in the turn nearest to where its angular velocity
// over the step says it should be.
static void track_phase(dxJointTransmission *t, const mesh *g, int i, dReal fps)
{
    const struct dxBody *b = dxJointBody(&t->base, i);
    dVector3 r, s;
    dSubtractVectors3(r, g->c[i], g->a[i]);
    dMultiply1_331(s, b->R, r);
    const dVector3 *ref = t->reference[i];
    const dReal theta = dAtan2(dCalcVectorDot3(ref[1], s), dCalcVectorDot3(ref[0], s));
    const dReal expected = t->phase[i] - dCalcVectorDot3(b->avel, g->n[i]) / fps;
    const dReal turns = dFloor((expected - theta) / (2 * M_PI) + REAL(0.5));
    t->phase[i] = theta + turns * (dReal)(2 * M_PI);
}

// The weight e_i of wheel i's phase in delta = e0 phase0 + e1 phase1, chosen
// so that d(delta)/dt is the row's velocity: turning by w about n_i moves
// the contact point at w n_i x r_i (r_i from anchor to contact point), which
// the row sees along +l0 (wheel 0) or -l1 (wheel 1), while the phase changes
// by -w. That is +r0, +r1 for gears with parallel axes and +r0, -r1 for a
// chain, as in ODE; for bevel gears it depends on how the axes point.
static dReal arc_coefficient(const mesh *g, int i)
{
    dVector3 r, v;
    dSubtractVectors3(r, g->c[i], g->a[i]);
    dCalcVectorCross3(v, g->n[i], r);
    const dReal e = dCalcVectorDot3(g->l[i], v);
    return i == 0 ? -e : e;
}

static void transmission_init(dxJoint *j)
{
    dxJointTransmission *t = (dxJointTransmission *)j;
    t->mode = dTransmissionParallelAxes;
    t->update = 1;
    t->axis[0][0] = t->axis[1][0] = 1;
    t->ratio = 1;
    t->erp = j->world->erp;
    t->cfm = j->world->cfm;
}

static int has_two_bodies(const dxJoint *j) { return dxJointBody(j, 1) != NULL; }

static void transmission_count_rows(dxJoint *j, dxJointRowCount *count)
{
    dxJointTransmission *t = (dxJointTransmission *)j;
    count->m = 0;
    count->nub = 0;
    if (!has_two_bodies(j)) return;
    mesh g;
    world_geometry(t, &g);
    if (!mesh_points(t, &g)) return;
    count->m = 1;
    count->nub = t->backlash > 0 ? 0 : 1;   // with backlash it only pushes one way
}

static void transmission_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointTransmission *t = (dxJointTransmission *)j;
    mesh g;
    world_geometry(t, &g);
    mesh_points(t, &g);   // count_rows saw it is not degenerate
    if (t->update) set_reference(t, &g);
    for (int i = 0; i < 2; i++) track_phase(t, &g, i, rows->fps);

    const dReal delta = arc_coefficient(&g, 0) * t->phase[0] + arc_coefficient(&g, 1) * t->phase[1];
    const int chain = t->mode == dTransmissionChainDrive;
    if (chain && delta < 0) {
        // The other branch of the chain pulls: mirror the contact points and
        // tangents across the plane of the baseline and the axis.
        dVector3 base;
        dSubtractVectors3(base, g.a[0], g.a[1]);
        for (int i = 0; i < 2; i++) {
            dVector3 nrm, rel;
            dCalcVectorCross3(nrm, g.n[i], base);
            const dReal nn = dCalcVectorDot3(nrm, nrm);
            dSubtractVectors3(rel, g.c[i], g.a[i]);
            dAddVectorScaledVector3(g.c[i], g.c[i], nrm, -2 * dCalcVectorDot3(rel, nrm) / nn);
            dAddScaledVectors3(g.l[i], g.l[i], nrm, -1, 2 * dCalcVectorDot3(g.l[i], nrm) / nn);
        }
    }
    dCopyVector3(t->contact[0], g.c[0]);
    dCopyVector3(t->contact[1], g.c[1]);
    rows->cfm[0] = t->cfm;

    if (t->backlash > 0 && dFabs(delta) <= t->backlash) {
        rows->lo[0] = rows->hi[0] = 0;   // in the gap: no force
        return;
    }
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    dVector3 rc0, rc1;
    dSubtractVectors3(rc0, g.c[0], b0->pos);
    dSubtractVectors3(rc1, g.c[1], b1->pos);
    dCopyVector3(rows->J1l, g.l[0]);
    dCalcVectorCross3(rows->J1a, rc0, g.l[0]);
    dCopyNegatedVector3(rows->J2l, g.l[1]);
    dCalcVectorCross3(rows->J2a, g.l[1], rc1);
    // The row's velocity is d(delta)/dt: drive delta back to the edge of the gap.
    const dReal k = rows->fps * t->erp;
    if (delta > 0) {
        rows->c[0] = -k * (delta - t->backlash);
        if (t->backlash > 0) rows->hi[0] = 0;   // lo stays -inf
    } else {
        rows->c[0] = -k * (delta + t->backlash);
        if (t->backlash > 0) rows->lo[0] = 0;   // hi stays +inf
    }
}

// A transmission needs two bodies (ODE refuses to attach it to one).
static void transmission_attached(dxJoint *j)
{
    if (dxJointBody(j, 0) && !has_two_bodies(j))
        dxReportBadArgument("dJointAttach", "a transmission joint needs two bodies; it will "
                                            "not act until attached to two");
}

static const dxJointClass transmission_class = {
    dJointTypeTransmission, "transmission", sizeof(dxJointTransmission), transmission_init,
    transmission_count_rows, transmission_fill_rows, transmission_attached
};

dJointID dJointCreateTransmission(dWorldID w, dJointGroupID g)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    return dxJointCreate(w, g, &transmission_class);
}

#define TRANSMISSION(j, on_fail) DX_CHECK_JOINT_TYPE(j, dJointTypeTransmission, on_fail)
#define CHECK_RESULT(r, on_fail) DX_CHECK_ARG((r) != NULL, on_fail, "result is NULL")
#define CHECK_MODE(t, cond, on_fail, what) \
    DX_CHECK_ARG(cond, on_fail, "%s in mode %d", what, (t)->mode)

// Store world direction a as axis i of body i (if attached).
static void store_axis(dxJointTransmission *t, int i, const dVector3 a)
{
    const struct dxBody *b = dxJointBody(&t->base, i);
    if (!b) return;
    dMultiply1_331(t->axis[i], b->R, a);
    t->axis[i][3] = 0;
    t->update = 1;
}

static void world_axis(const dxJointTransmission *t, int i, dVector3 result)
{
    const struct dxBody *b = dxJointBody(&t->base, i);
    if (b) dMultiply0_331(result, b->R, t->axis[i]);
    else dCopyVector3(result, t->axis[i]);
}

#define UNIT_AXIS(a, x, y, z, on_fail) \
    dVector3 a = { x, y, z, 0 }; \
    DX_CHECK_ARG(dxIsFinite3(x, y, z) && dSafeNormalize3(a), on_fail, \
                 "axis (%g, %g, %g) has no direction", (double)(x), (double)(y), (double)(z))

void dJointSetTransmissionAxis(dJointID j, dReal x, dReal y, dReal z)
{
    TRANSMISSION(j, return);
    dxJointTransmission *t = (dxJointTransmission *)j;
    CHECK_MODE(t, t->mode != dTransmissionIntersectingAxes, return,
               "intersecting axes are set one by one (dJointSetTransmissionAxis1, 2)");
    UNIT_AXIS(a, x, y, z, return);
    store_axis(t, 0, a);
    store_axis(t, 1, a);
}

void dJointSetTransmissionAxis1(dJointID j, dReal x, dReal y, dReal z)
{
    TRANSMISSION(j, return);
    dxJointTransmission *t = (dxJointTransmission *)j;
    CHECK_MODE(t, t->mode == dTransmissionIntersectingAxes, return,
               "only intersecting axes are set one by one");
    UNIT_AXIS(a, x, y, z, return);
    store_axis(t, 0, a);
}

void dJointSetTransmissionAxis2(dJointID j, dReal x, dReal y, dReal z)
{
    TRANSMISSION(j, return);
    dxJointTransmission *t = (dxJointTransmission *)j;
    CHECK_MODE(t, t->mode == dTransmissionIntersectingAxes, return,
               "only intersecting axes are set one by one");
    UNIT_AXIS(a, x, y, z, return);
    store_axis(t, 1, a);
}

void dJointGetTransmissionAxis(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    dxJointTransmission *t = (dxJointTransmission *)j;
    CHECK_MODE(t, t->mode == dTransmissionParallelAxes, return,
               "the axes are queried one by one (dJointGetTransmissionAxis1, 2)");
    world_axis(t, 0, result);
}

void dJointGetTransmissionAxis1(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    world_axis((dxJointTransmission *)j, 0, result);
}

void dJointGetTransmissionAxis2(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    world_axis((dxJointTransmission *)j, 1, result);
}

static void set_anchor(dxJointTransmission *t, int i, dReal x, dReal y, dReal z)
{
    const struct dxBody *b = dxJointBody(&t->base, i);
    if (!b) return;
    dVector3 r = { x - b->pos[0], y - b->pos[1], z - b->pos[2], 0 };
    dMultiply1_331(t->anchor[i], b->R, r);
    t->anchor[i][3] = 0;
    t->update = 1;
}

static void get_anchor(const dxJointTransmission *t, int i, dVector3 result)
{
    const struct dxBody *b = dxJointBody(&t->base, i);
    if (!b) {
        dZeroVector3(result);
        return;
    }
    dMultiply0_331(result, b->R, t->anchor[i]);
    dAddVectors3(result, result, b->pos);
}

void dJointSetTransmissionAnchor1(dJointID j, dReal x, dReal y, dReal z)
{
    TRANSMISSION(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    set_anchor((dxJointTransmission *)j, 0, x, y, z);
}

void dJointSetTransmissionAnchor2(dJointID j, dReal x, dReal y, dReal z)
{
    TRANSMISSION(j, return);
    DX_CHECK_ARG(dxIsFinite3(x, y, z), return, "anchor is not finite");
    set_anchor((dxJointTransmission *)j, 1, x, y, z);
}

void dJointGetTransmissionAnchor1(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    get_anchor((dxJointTransmission *)j, 0, result);
}

void dJointGetTransmissionAnchor2(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    get_anchor((dxJointTransmission *)j, 1, result);
}

// The contact points as of the last step (world; zero before the first).
void dJointGetTransmissionContactPoint1(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    dCopyVector3(result, ((dxJointTransmission *)j)->contact[0]);
}

void dJointGetTransmissionContactPoint2(dJointID j, dVector3 result)
{
    TRANSMISSION(j, return);
    CHECK_RESULT(result, return);
    dCopyVector3(result, ((dxJointTransmission *)j)->contact[1]);
}

void dJointSetTransmissionParam(dJointID j, int parameter, dReal value)
{
    TRANSMISSION(j, return);
    DX_CHECK_ARG(!isnan(value), return, "value is NaN");
    dxJointTransmission *t = (dxJointTransmission *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return;
    if (param == dParamERP) t->erp = value;
    else if (param == dParamCFM) t->cfm = value;
}

dReal dJointGetTransmissionParam(dJointID j, int parameter)
{
    TRANSMISSION(j, return 0);
    const dxJointTransmission *t = (const dxJointTransmission *)j;
    int group, param;
    if (!dxParamSplit(__func__, parameter, 1, &group, &param)) return 0;
    if (param == dParamERP) return t->erp;
    if (param == dParamCFM) return t->cfm;
    return 0;
}

void dJointSetTransmissionMode(dJointID j, int mode)
{
    TRANSMISSION(j, return);
    DX_CHECK_ARG(mode == dTransmissionParallelAxes || mode == dTransmissionIntersectingAxes ||
                     mode == dTransmissionChainDrive,
                 return, "mode must be dTransmissionParallelAxes (0), "
                         "dTransmissionIntersectingAxes (1) or dTransmissionChainDrive (2), "
                         "got %d", mode);
    ((dxJointTransmission *)j)->mode = mode;
}

int dJointGetTransmissionMode(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->mode;
}

void dJointSetTransmissionRatio(dJointID j, dReal ratio)
{
    TRANSMISSION(j, return);
    dxJointTransmission *t = (dxJointTransmission *)j;
    CHECK_MODE(t, t->mode == dTransmissionParallelAxes, return,
               "the ratio follows from the geometry");
    DX_CHECK_ARG(dxIsFinite(ratio) && ratio > 0, return, "ratio must be > 0, got %g",
                 (double)ratio);
    t->ratio = ratio;
}

dReal dJointGetTransmissionRatio(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->ratio;
}

dReal dJointGetTransmissionAngle1(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->phase[0];
}

dReal dJointGetTransmissionAngle2(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->phase[1];
}

dReal dJointGetTransmissionRadius1(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->radius[0];
}

dReal dJointGetTransmissionRadius2(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->radius[1];
}

static void set_radius(dxJointTransmission *t, int i, dReal radius, const char *function)
{
    if (t->mode != dTransmissionChainDrive) {
        dxReportBadArgument(function, "the radii follow from the geometry in mode %d", t->mode);
        return;
    }
    if (!dxIsFinite(radius) || radius <= 0) {
        dxReportBadArgument(function, "radius must be > 0, got %g", (double)radius);
        return;
    }
    t->radius[i] = radius;
}

void dJointSetTransmissionRadius1(dJointID j, dReal radius)
{
    TRANSMISSION(j, return);
    set_radius((dxJointTransmission *)j, 0, radius, __func__);
}

void dJointSetTransmissionRadius2(dJointID j, dReal radius)
{
    TRANSMISSION(j, return);
    set_radius((dxJointTransmission *)j, 1, radius, __func__);
}

dReal dJointGetTransmissionBacklash(dJointID j)
{
    TRANSMISSION(j, return 0);
    return ((dxJointTransmission *)j)->backlash;
}

void dJointSetTransmissionBacklash(dJointID j, dReal backlash)
{
    TRANSMISSION(j, return);
    DX_CHECK_ARG(dxIsFinite(backlash) && backlash >= 0, return,
                 "backlash must be finite and >= 0, got %g", (double)backlash);
    ((dxJointTransmission *)j)->backlash = backlash;
}
