// SPDX-License-Identifier: BSD-3-Clause
//
// joint_contact.c -- the contact joint (guide 7.3.7, 3.11): a one-sided
// constraint along the contact normal, friction in the two tangent
// directions, and (ODE 0.16) rolling and spinning friction, with every
// surface mode: Mu2, FDir1, Bounce, SoftERP, SoftCFM, Motion1/2/N, Slip1/2,
// Rolling, and the friction pyramid (Approx1_1, _2, _N).
//
// Rows, in this order (row 0 is the findex of the pyramid rows):
//   0      normal: relative normal velocity >= target, force in 0..inf;
//   t1     if mu > 0            (force limit mu, or mu * normal force);
//   t2     if mu2 > 0           (mu2 with dContactMu2, else mu);
//   r1, r2, rn  with dContactRolling: rolling friction about t1, t2 and
//          spinning friction about n, limits rho, rho2, rhoN with
//          dContactAxisDep (= dContactMu2), else rho for all three; each if > 0.
// Rows whose coefficient is 0 are omitted, as in ODE: a frictionless
// contact cannot drag anything, so Motion1/2 and Slip1/2 have no effect on
// it. Directions are kept in the user's body order (the normal points into
// user body 1, friction motion is that of user body 1 relative to body 2)
// and negated when the joint is stored reversed.
//
// The depth follows the bodies: their poses are recorded at the contact's
// first step, and later rows (the sub-steps of dWorldStepFast1, or a contact
// kept over several steps) use the depth less the separation gained since,
// to first order, and the lever arms of that first step. For the usual
// contact, made from the current poses and used for one dWorldStep or
// dWorldQuickStep, this is the given depth and point, as in ODE; without it
// each StepFast1 sub-step would correct the whole initial depth again, and a
// rolling ball's lever arm would swing away from its contact point.
//
// dxJointContactWarmInfo gives dWorldQuickStep's warm start (quickstep_warm.c)
// the contact point and which friction rows follow the normal row, so that it
// can find the same contact in the last step's forces; dxJointContactRows
// gives it a plain contact's rows as numbers (directions, arms, targets,
// bounds), which it turns into its own rows directly (quickstep_contact.c).
// The joint's own rows (fill_rows) are made from the same numbers.
//
// Bad input at creation: a NULL world or contact or a destroyed group is
// reported and no joint is made (returns 0). A non-finite position, normal
// or depth, or a zero normal, is reported and the joint is made inert (no
// rows), so the caller's dJointAttach still works. Out-of-range surface
// numbers are reported and replaced by the nearest safe value (see
// sanitise_surface). A negative depth (the shapes do not touch yet) is
// accepted and gives no correction, like depth 0.

#include "joint_contact.h"
#include "joint_group.h"
#include "joint_kept.h"
#include "joint_geometry.h"
#include "step_internal.h"
#include "unit_vector.h"

// The rows a contact contributes, by kind (bit set = row present).
enum {
    ROW_T1 = 1 << 0,
    ROW_T2 = 1 << 1,
    ROW_R1 = 1 << 2,
    ROW_R2 = 1 << 3,
    ROW_RN = 1 << 4
};

static void contact_count_rows(dxJoint *j, dxJointRowCount *count)
{
    const dxJointContact *c = (const dxJointContact *)j;
    count->m = c->m;
    count->nub = 0;   // row 0 is bounded, so no row may be declared unbounded up front
}

// The contact writes every entry of its rows, so dxJointRowsFill skips
// setting the defaults first: the entries a row does not use get them here
// (J 0, c 0, cfm the world's, findex -1).

// An angular row about axis a (stored sense): J1a = a, J2a = -a (0 without
// a second body), no linear part, no velocity target.
static void angular_row(const dxJoint *j, dxJointRows *rows, int row, const dVector3 a)
{
    const int o = row * rows->rowskip;
    dZeroVector3(rows->J1l + o);
    dCopyVector3(rows->J1a + o, a);
    dZeroVector3(rows->J2l + o);
    if (dxJointBody(j, 1)) dCopyNegatedVector3(rows->J2a + o, a);
    else dZeroVector3(rows->J2a + o);
    rows->c[row] = 0;
    rows->cfm[row] = j->world->cfm;
}

// A linear row along d (stored sense) through the contact point:
// J1l = d, J1a = arm0 x d, J2l = -d, J2a = -(arm1 x d) (dxContactRows). The
// arms are those of the first step, so the row stays the same over
// StepFast1's sub-steps (a rolling ball's contact point does not travel with
// its material).
static void linear_row(const dxContactRows *r, dxJointRows *rows, int row, const dReal *d)
{
    const int o = row * rows->rowskip;
    dCopyVector3(rows->J1l + o, d);
    dCalcVectorCross3(rows->J1a + o, r->arm[0], d);
    if (r->arm[1]) {
        dCopyNegatedVector3(rows->J2l + o, d);
        dCalcVectorCross3(rows->J2a + o, d, r->arm[1]);
    } else {
        dZeroVector3(rows->J2l + o);
        dZeroVector3(rows->J2a + o);
    }
}

// The current relative velocity along n (stored sense) at the contact: J v
// of the normal row (both bodies, kinematic included).
static dReal normal_velocity(const dxJointContact *c, const dVector3 n)
{
    const struct dxBody *b0 = dxJointBody(&c->base, 0), *b1 = dxJointBody(&c->base, 1);
    dVector3 a;
    dCalcVectorCross3(a, c->arm[0], n);
    dReal v = dCalcVectorDot3(n, b0->lvel) + dCalcVectorDot3(a, b0->avel);
    if (b1) {
        dVector3 l;
        dCopyNegatedVector3(l, n);
        dCalcVectorCross3(a, n, c->arm[1]);
        v += dCalcVectorDot3(l, b1->lvel) + dCalcVectorDot3(a, b1->avel);
    }
    return v;
}

// Bounds of a friction row with coefficient k: constant-force-limit model
// (lo = -k, hi = k), or with `pyramid` the limit k * normal force (findex =
// the normal row). An infinite coefficient never slips: an unbounded row
// (and no findex, whose bound would be inf * force).
static void friction_bounds(dxJointRows *rows, int row, dReal k, int pyramid)
{
    rows->lo[row] = -k;
    rows->hi[row] = k;
    rows->findex[row] = pyramid && k < dInfinity ? 0 : -1;
}

// How far the contact point moved with body k since it was anchored, to
// first order: translation plus (rotation vector) x arm. The second-order
// part is left out on purpose: a ball rolling over its contact point would
// otherwise seem to lift off it.
static void contact_point_motion(const dxJointContact *c, int k, dVector3 d)
{
    const struct dxBody *b = dxJointBody(&c->base, k);
    dQuaternion q;
    dQMultiply2(q, b->q, c->q0[k]);   // the rotation since: q0 -> q
    dVector3 v = { q[1], q[2], q[3], 0 }, rot;
    const dReal sin_half = dCalcVectorLength3(v), cos_half = dFabs(q[0]);
    dReal scale = 2;   // rotation vector = axis * angle = v * angle / sin(angle / 2)
    if (sin_half > 0) scale = 2 * dAtan2(sin_half, cos_half) / sin_half;
    if (q[0] < 0) scale = -scale;
    dScaleVector3(v, scale);
    dCalcVectorCross3(rot, v, c->arm[k]);
    dSubtractVectors3(d, b->pos, c->pos0[k]);
    dAddVectors3(d, d, rot);
}

// The penetration depth now of a contact anchored at an earlier step (the
// sub-steps of dWorldStepFast1, or a contact kept over several steps):
// collision found c->contact.geom.depth with the bodies where they were
// then, and the depth shrinks by how far the point carried by body 0 moved
// along n (stored sense, into body 0) relative to body 1's.
dReal dxJointContactMovedDepth(const dxJointContact *c, const dVector3 n)
{
    dVector3 d0, d1 = { 0, 0, 0, 0 };
    contact_point_motion(c, 0, d0);
    if (dxJointBody(&c->base, 1)) contact_point_motion(c, 1, d1);
    dSubtractVectors3(d0, d0, d1);
    return c->contact.geom.depth - dCalcVectorDot3(n, d0);
}

dReal dxJointContactBounce(const dxJointContact *c, const dVector3 n, dReal target, dReal motion)
{
    const dSurfaceParameters *s = &c->contact.surface;
    const dReal incoming = normal_velocity(c, n) - motion;   // < 0: approaching
    if (-incoming > s->bounce_vel) {
        const dReal outgoing = -s->bounce * incoming;
        if (outgoing > target) target = outgoing;
    }
    return target;
}

// A zero direction, for the rows a contact does not have.
static const dVector3 no_direction = { 0, 0, 0, 0 };

void dxJointContactFlip(dxJointContact *c)
{
    dNegateVector3(c->kept.n);
    dNegateVector3(c->kept.t1);
    dNegateVector3(c->kept.t2);
    c->negated ^= 1;
}

// Friction row `row` of r with its own numbers: target tangential velocity
// `motion`, cfm `slip` (force-dependent slip: velocity = slip * force) if
// set, else the world's.
static void friction_row_own(const dxJointContact *c, dxContactRows *r, int row, dReal motion,
                             int has_slip, dReal slip)
{
    r->c[row] = motion;
    r->cfm[row] = has_slip ? slip : c->base.world->cfm;
}

void dxJointContactOwnNumbers(dxJointContact *c)
{
    dxContactRows *r = &c->kept;
    const dSurfaceParameters *s = &c->contact.surface;
    const int mode = s->mode;
    const unsigned friction = (unsigned)r->friction;
    if (mode & dContactSoftCFM) r->cfm[0] = s->soft_cfm;
    int row = 1;
    if (friction & ROW_T1)
        friction_row_own(c, r, row++, (mode & dContactMotion1) ? s->motion1 : 0,
                         mode & dContactSlip1, s->slip1);
    if (friction & ROW_T2)
        friction_row_own(c, r, row, (mode & dContactMotion2) ? s->motion2 : 0,
                         mode & dContactSlip2, s->slip2);
}

const dxContactRows *dxJointContactRows(dxJoint *j, dReal fps, dReal erp)
{
    const struct dxBody *const b[2] = { dxJointBody(j, 0), dxJointBody(j, 1) };
    dxJointContact *c = (dxJointContact *)j;
    dxJointContactCfm(c);
    return dxJointContactStep(c, b, fps, erp);
}

static void contact_fill_rows(dxJoint *j, dxJointRows *rows)
{
    dxJointContact *c = (dxJointContact *)j;
    if (c->inert) return;
    const dSurfaceParameters *s = &c->contact.surface;
    const int mode = s->mode;
    const dxContactRows *r = dxJointContactRows(j, rows->fps, rows->erp);
    for (int i = 0; i < r->m; i++) {
        linear_row(r, rows, i, r->d[i]);
        rows->c[i] = r->c[i];
        rows->cfm[i] = r->cfm[i];
        if (i > 0) {
            friction_bounds(rows, i, r->hi[i], r->pyramid[i] != 0);
            continue;
        }
        rows->lo[0] = r->lo[0];
        rows->hi[0] = r->hi[0];
        rows->findex[0] = -1;
    }
    int row = r->m;
    const unsigned present = c->rows_present;
    if (present & ROW_R1) {
        angular_row(j, rows, row, r->t1);
        friction_bounds(rows, row++, s->rho, mode & dContactApprox1_1);
    }
    if (present & ROW_R2) {
        angular_row(j, rows, row, r->t2);
        friction_bounds(rows, row++, c->rho2, mode & dContactApprox1_2);
    }
    if (present & ROW_RN) {
        angular_row(j, rows, row, r->n);
        friction_bounds(rows, row, c->rhoN, mode & dContactApprox1_N);
    }
}

int dxJointContactWarmInfo(const dxJoint *j, dVector3 point)
{
    const dxJointContact *c = (const dxJointContact *)j;
    if (j->cls->type != dJointTypeContact || c->inert) return -1;
    dCopyVector3(point, c->contact.geom.pos);
    return (int)(c->rows_present & (ROW_T1 | ROW_T2));
}

const dContact *dxJointContactGet(const dxJoint *j)
{
    if (j->cls->type != dJointTypeContact) return NULL;
    return &((const dxJointContact *)j)->contact;
}

static const dxJointClass contact_class = {
    dJointTypeContact, "contact", sizeof(dxJointContact), NULL, contact_count_rows,
    contact_fill_rows, NULL
};

// ---- creation and input checks --------------------------------------------

// A friction-like coefficient must be 0..dInfinity; anything else becomes 0.
static dReal check_coefficient(const char *what, dReal k)
{
    if (k >= 0) return k;   // false for NaN
    dxReportBadArgument("dJointCreateContact", "%s = %g must be in 0..dInfinity; using 0", what,
                        (double)k);
    return 0;
}

// A finite number, else 0.
static dReal check_finite(const char *what, dReal x)
{
    if (dxIsFinite(x)) return x;
    dxReportBadArgument("dJointCreateContact", "%s = %g is not finite; using 0", what,
                        (double)x);
    return 0;
}

// A slip coefficient (a cfm) must be finite and >= 0; anything else becomes 0.
static dReal check_slip(const char *what, dReal x)
{
    if (x >= 0 && dxIsFinite(x)) return x;
    dxReportBadArgument("dJointCreateContact", "%s = %g must be finite and >= 0; using 0", what,
                        (double)x);
    return 0;
}

// Clamp x to lo..hi (NaN to lo), reporting a value outside.
static dReal check_range(const char *what, dReal x, dReal lo, dReal hi)
{
    if (x >= lo && x <= hi) return x;
    dxReportBadArgument("dJointCreateContact", "%s = %g must be in %g..%g", what, (double)x,
                        (double)lo, (double)hi);
    return x > hi ? hi : lo;
}

// Replace out-of-range surface numbers (read only when their mode flag is
// set, as the guide specifies) by safe values, reporting each.
static void sanitise_surface(dSurfaceParameters *s)
{
    const int mode = s->mode;
    s->mu = check_coefficient("surface.mu", s->mu);
    enum {
        CHECKED = dContactMu2 | dContactRolling | dContactBounce | dContactSoftERP |
                  dContactSoftCFM | dContactMotion1 | dContactMotion2 | dContactMotionN |
                  dContactSlip1 | dContactSlip2
    };
    if (!(mode & CHECKED)) return;   // (the usual contact: mu only)
    if (mode & dContactMu2) s->mu2 = check_coefficient("surface.mu2", s->mu2);
    if (mode & dContactRolling) {
        s->rho = check_coefficient("surface.rho", s->rho);
        if (mode & dContactAxisDep) {
            s->rho2 = check_coefficient("surface.rho2", s->rho2);
            s->rhoN = check_coefficient("surface.rhoN", s->rhoN);
        }
    }
    if (mode & dContactBounce) {
        s->bounce = check_range("surface.bounce", s->bounce, 0, 1);
        s->bounce_vel = check_coefficient("surface.bounce_vel", s->bounce_vel);
    }
    if (mode & dContactSoftERP) s->soft_erp = check_range("surface.soft_erp", s->soft_erp, 0, 1);
    if ((mode & dContactSoftCFM) && !(s->soft_cfm >= 0 && dxIsFinite(s->soft_cfm))) {
        dxReportBadArgument("dJointCreateContact",
                            "surface.soft_cfm = %g must be finite and >= 0; using the world's",
                            (double)s->soft_cfm);
        s->mode &= ~dContactSoftCFM;
    }
    if (mode & dContactMotion1) s->motion1 = check_finite("surface.motion1", s->motion1);
    if (mode & dContactMotion2) s->motion2 = check_finite("surface.motion2", s->motion2);
    if (mode & dContactMotionN) s->motionN = check_finite("surface.motionN", s->motionN);
    if (mode & dContactSlip1) s->slip1 = check_slip("surface.slip1", s->slip1);
    if (mode & dContactSlip2) s->slip2 = check_slip("surface.slip2", s->slip2);
}

// Report a normal that is not finite or has no direction; 0.
static int bad_normal(const dContactGeom *g)
{
    dxReportBadArgument("dJointCreateContact", "contact normal (%g, %g, %g) has no direction;"
                        " the contact is ignored", (double)g->normal[0], (double)g->normal[1],
                        (double)g->normal[2]);
    return 0;
}

// The sum of a contact's seven numbers (point, depth, normal as given): finite
// only if each is (a NaN or an infinity makes it NaN or infinite); finite
// numbers whose sum overflows go on to the tests of each number
// (geometry_by_number).
static inline dReal geometry_sum(const dContactGeom *g)
{
    return g->pos[0] + g->pos[1] + g->pos[2] + g->depth + g->normal[0] + g->normal[1] +
           g->normal[2];
}

// A contact's frame: the unit normal n, the friction directions t1 (unit,
// perpendicular to n) and t2 = n x t1, as numbers (kept in registers, not
// in memory that is loaded again before its stores are done).
typedef struct contact_frame_t {
    dReal nx, ny, nz, t1x, t1y, t1z, t2x, t2y, t2z;
} contact_frame_t;

// The frame of a normal (g0, g1, g2) as given, finite: dSafeNormalize3's
// normal and dPlaneSpace's directions (their arithmetic, so their bits); 0
// if it has no direction.
static inline int contact_frame(dReal g0, dReal g1, dReal g2, contact_frame_t *f)
{
    dReal n[3] = { g0, g1, g2 }, t1[3], t2[3];
    if (!dxUnitVector3(n)) return 0;
    dxPlaneSpaceUnit(n, t1, t2);
    *f = (contact_frame_t){ n[0], n[1], n[2], t1[0], t1[1], t1[2], t2[0], t2[1], t2[2] };
    return 1;
}

// Store a frame as three dVector3s (4th numbers 0).
static inline void store_frame(const contact_frame_t *f, dReal *n, dReal *t1, dReal *t2)
{
    n[0] = f->nx;
    n[1] = f->ny;
    n[2] = f->nz;
    n[3] = 0;
    t1[0] = f->t1x;
    t1[1] = f->t1y;
    t1[2] = f->t1z;
    t1[3] = 0;
    t2[0] = f->t2x;
    t2[1] = f->t2y;
    t2[2] = f->t2z;
    t2[3] = 0;
}

// The frame (contact_frame) into kept.n, .t1, .t2 from the normal as given,
// its numbers finite; 0 (after a report) if it has no direction.
static inline int unit_normal(dxJointContact *c)
{
    const dReal *g = c->contact.geom.normal;
    contact_frame_t f;
    if (!contact_frame(g[0], g[1], g[2], &f)) return bad_normal(&c->contact.geom);
    store_frame(&f, c->kept.n, c->kept.t1, c->kept.t2);
    return 1;
}

// check_geometry where the sum of the numbers is not finite: each tested.
static int geometry_by_number(dxJointContact *c)
{
    const dContactGeom *g = &c->contact.geom;
    if (!dxIsFinite3(g->pos[0], g->pos[1], g->pos[2]) || !dxIsFinite(g->depth)) {
        dxReportBadArgument("dJointCreateContact",
                            "contact position or depth is not finite; the contact is ignored");
        return 0;
    }
    if (!dxIsFinite3(g->normal[0], g->normal[1], g->normal[2])) return bad_normal(g);
    return unit_normal(c);
}

// Store the frame; 0 (after a report) if the geometry is unusable.
static int check_geometry(dxJointContact *c)
{
    if (dxIsFinite(geometry_sum(&c->contact.geom))) return unit_normal(c);
    return geometry_by_number(c);
}

// The usual contact's frame (contact_frame; see usual_surface) from the
// caller's contact g, or, when its normal as given has the bits of the last
// usual contact's in the world (a collider's contacts of one pair share
// their normal), the one made from that: the same numbers without the
// square roots and divisions. Read from g, not from the joint's copy just
// stored, and stored from registers: loads of lines just written in smaller
// parts wait for the stores. 0 (after a report) if the geometry is unusable.
static int usual_frame(dxJointContact *c, const dContactGeom *g)
{
    dxContactFrame *last = &c->base.world->contact_frame;
    if (dxIsFinite(geometry_sum(g))) {
        if (memcmp(last->given, g->normal, sizeof last->given) == 0) {
            memcpy(c->kept.n, last->n, sizeof last->n);
            memcpy(c->kept.t1, last->t1, sizeof last->t1);
            memcpy(c->kept.t2, last->t2, sizeof last->t2);
            return 1;
        }
        const dReal g0 = g->normal[0], g1 = g->normal[1], g2 = g->normal[2];
        contact_frame_t f;
        if (!contact_frame(g0, g1, g2, &f)) return bad_normal(g);
        store_frame(&f, c->kept.n, c->kept.t1, c->kept.t2);
        last->given[0] = g0;
        last->given[1] = g1;
        last->given[2] = g2;
        store_frame(&f, last->n, last->t1, last->t2);
        return 1;
    }
    return geometry_by_number(c);
}

// Friction directions with dContactFDir1: t1 = fdir1's part perpendicular to
// n, unit, and t2 = n x t1; without it, or if that part is too short, the
// frame's (contact_frame) as check_geometry stored them.
static void friction_directions(dxJointContact *c)
{
    if (c->contact.surface.mode & dContactFDir1) {
        const dReal *f = c->contact.fdir1;
        dVector3 t1;
        dAddScaledVectors3(t1, f, c->kept.n, 1, -dCalcVectorDot3(f, c->kept.n));
        if (dxIsFinite3(t1[0], t1[1], t1[2]) &&
            dCalcVectorLength3(t1) > (dReal)1e-3 * dCalcVectorLength3(f) && dSafeNormalize3(t1)) {
            dCopyVector3(c->kept.t1, t1);
            dCalcVectorCross3(c->kept.t2, c->kept.n, c->kept.t1);
            return;
        }
        dxReportBadArgument("dJointCreateContact", "fdir1 (%g, %g, %g) is not a direction "
                            "across the normal; using an arbitrary one", (double)f[0],
                            (double)f[1], (double)f[2]);
    }
}

// The bounds -k..k of friction row `row` (1, 2) with coefficient k, times
// the normal force with `pyramid` (Approx1_1/2; an infinite k: never, whose
// bound would be inf * force).
static void friction_bounds_of(dxJointContact *c, int row, dReal k, int pyramid)
{
    c->kept.lo[row] = -k;
    c->kept.hi[row] = k;
    c->kept.pyramid[row] = -(dxRealMask)(pyramid && k < dInfinity);
}

// The sliding friction rows' own numbers (see dxJointContact).
static void sliding_rows(dxJointContact *c)
{
    const dSurfaceParameters *s = &c->contact.surface;
    const int mode = s->mode;
    c->own_numbers = (mode & (dContactSoftCFM | dContactMotion1 | dContactMotion2 |
                              dContactSlip1 | dContactSlip2)) != 0;
    c->kept.lo[1] = c->kept.lo[2] = c->kept.hi[1] = c->kept.hi[2] = 0;
    c->kept.pyramid[1] = c->kept.pyramid[2] = 0;
    int row = 1;
    if (c->rows_present & ROW_T1) friction_bounds_of(c, row++, s->mu, mode & dContactApprox1_1);
    if (c->rows_present & ROW_T2) friction_bounds_of(c, row, c->mu2, mode & dContactApprox1_2);
}

// Which rows exist, and the effective coefficients of direction 2 and spin.
static void choose_rows(dxJointContact *c)
{
    const dSurfaceParameters *s = &c->contact.surface;
    const int axis_dep = s->mode & dContactMu2;
    c->mu2 = axis_dep ? s->mu2 : s->mu;
    c->rho2 = axis_dep ? s->rho2 : s->rho;
    c->rhoN = axis_dep ? s->rhoN : s->rho;
    const int t1 = s->mu > 0, t2 = c->mu2 > 0;
    unsigned p = (t1 ? ROW_T1 : 0) | (t2 ? ROW_T2 : 0);
    int m = 1 + t1 + t2;
    if (s->mode & dContactRolling) {
        if (s->rho > 0) p |= ROW_R1, m++;
        if (c->rho2 > 0) p |= ROW_R2, m++;
        if (c->rhoN > 0) p |= ROW_RN, m++;
    }
    c->rows_present = p;
    c->m = m;
    c->kept.m = 1 + t1 + t2;
    sliding_rows(c);
    // Plain: no rolling rows, and not two unbounded friction rows (those
    // would be solved as a block, quickstep_build.c).
    if (m == 1 + t1 + t2 && !(s->mu == dInfinity && c->mu2 == dInfinity))
        c->base.flags |= DX_JOINT_PLAIN_CONTACT;
}

// The rows of the usual contact: a surface with mu >= 0 (0 to dInfinity:
// nothing to sanitise) and no mode but the pyramid's (dContactApprox1_1/_2/_N):
// the numbers choose_rows and sliding_rows give it, made straight (its
// directions are usual_frame's, friction_directions' without FDir1).
static void usual_surface(dxJointContact *c)
{
    const dSurfaceParameters *s = &c->contact.surface;
    const dReal mu = s->mu;
    c->mu2 = mu;
    c->rho2 = c->rhoN = 0;   // (rolling friction's: no rolling rows)
    c->own_numbers = 0;
    if (mu > 0) {
        c->rows_present = ROW_T1 | ROW_T2;
        c->m = c->kept.m = 3;
        c->kept.lo[1] = c->kept.lo[2] = -mu;
        c->kept.hi[1] = c->kept.hi[2] = mu;
        const int finite = mu < dInfinity;   // (two infinite rows: not plain, a block)
        c->kept.pyramid[1] = -(dxRealMask)(finite && (s->mode & dContactApprox1_1));
        c->kept.pyramid[2] = -(dxRealMask)(finite && (s->mode & dContactApprox1_2));
        if (finite) c->base.flags |= DX_JOINT_PLAIN_CONTACT;
    } else {
        c->rows_present = 0;
        c->m = c->kept.m = 1;
        c->kept.lo[1] = c->kept.lo[2] = c->kept.hi[1] = c->kept.hi[2] = 0;
        c->kept.pyramid[1] = c->kept.pyramid[2] = 0;
        c->base.flags |= DX_JOINT_PLAIN_CONTACT;
    }
}

// The rest of the kept rows' numbers (see dxJointContact), once the rows
// and their bounds are chosen.
static void keep_rows(dxJointContact *c)
{
    dxContactRows *r = &c->kept;
    const unsigned friction = c->rows_present & (ROW_T1 | ROW_T2);
    r->friction = (int)friction;
    r->d[0] = r->n;
    r->d[1] = (friction & ROW_T1) ? r->t1 : (friction & ROW_T2) ? r->t2 : no_direction;
    r->d[2] = friction == (ROW_T1 | ROW_T2) ? r->t2 : no_direction;
    r->lo[0] = 0;
    r->hi[0] = dInfinity;
    r->c[1] = r->c[2] = 0;
    r->lo[3] = r->hi[3] = r->c[3] = r->cfm[3] = 0;
    r->pyramid[0] = r->pyramid[3] = 0;
    r->arm[0] = c->arm[0];
    r->point = c->contact.geom.pos;
}

// Every field of the contact's part (no zeroing first): the pose record
// only says "none yet"; dxJointContactAnchor fills it at the first step. Of the usual
// contact's dContact (see usual_surface) only what is ever read is kept:
// the surface's mode and mu, and the point, normal and depth.
static void contact_init(dxJointContact *c, const dContact *contact)
{
    const int usual = (contact->surface.mode & ~dContactApprox1) == 0 && contact->surface.mu >= 0;
    if (usual) {
        c->contact.surface.mode = contact->surface.mode;
        c->contact.surface.mu = contact->surface.mu;
        memcpy(c->contact.geom.pos, contact->geom.pos, sizeof contact->geom.pos);
        memcpy(c->contact.geom.normal, contact->geom.normal, sizeof contact->geom.normal);
        c->contact.geom.depth = contact->geom.depth;
    } else {
        c->contact = *contact;
    }
    c->anchor_body[0] = c->anchor_body[1] = NULL;
    c->negated = 0;
    if (!(usual ? usual_frame(c, &contact->geom) : check_geometry(c))) {
        dZeroVector3(c->kept.n);
        dZeroVector3(c->kept.t1);
        dZeroVector3(c->kept.t2);
        c->mu2 = c->rho2 = c->rhoN = 0;
        c->rows_present = 0;
        c->m = 0;
        c->inert = 1;
        return;
    }
    c->inert = 0;
    if (usual) {
        usual_surface(c);
    } else {
        sanitise_surface(&c->contact.surface);
        friction_directions(c);
        choose_rows(c);
    }
    keep_rows(c);
    // count_rows' answer, which never changes, kept where the steppers
    // read it (dWorldQuickStep's set-up does not ask again).
    c->base.rows.m = c->m;
    c->base.rows.nub = 0;
}

dJointID dJointCreateContact(dWorldID w, dJointGroupID g, const dContact *contact)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return NULL, "world is NULL or was destroyed");
    DX_CHECK_ARG(g == NULL || g->hdr.magic == DX_MAGIC_GROUP, return NULL,
                 "joint group was destroyed");
    DX_CHECK_ARG(contact != NULL, return NULL, "contact is NULL");
    dxJoint *j = dxJointCreateBareInline(w, g, &contact_class);
    contact_init((dxJointContact *)j, contact);
    return j;
}
