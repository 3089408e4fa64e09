// SPDX-License-Identifier: BSD-3-Clause
//
// joint_contact.h -- the contact joint's record and its plain rows' numbers
// for a step (dxJointContactRows, step_internal.h), inline: dWorldQuickStep
// asks them of every contact of every step (quickstep_contact.c), where a
// call, its saved registers and the bodies' loads cost more than the usual
// contact's own work. What the usual contact never needs (a kept contact's
// moved depth, Bounce, the modes' own friction numbers, a reversal) stays
// out of line in joint_contact.c, which says what the contact joint is.

#ifndef DX_JOINT_CONTACT_H
#define DX_JOINT_CONTACT_H

#include "step_internal.h"

#include <ode/contact.h>
#include <string.h>

typedef struct dxJointContact {
    dxJoint base;
    dContact contact;      // as given, with the surface sanitised (see contact_init)
    // Its rows' numbers as dxJointContactRows gives them. What the contact
    // alone decides is set at creation: the unit normal and friction
    // directions (4th numbers 0; kept.n, .t1, .t2 in the user's body order,
    // negated while `negated`: they are turned to the stored sense
    // (DX_JOINT_REVERSE) when the rows are asked for, and stay so), the
    // sliding rows (kept.m) with their directions, bounds and pyramid flags,
    // targets 0 but the normal row's, the arm of body 0 and the point. Each
    // step sets the normal row's target, the cfm (the world's, read then,
    // or a mode's) and whether body 1 has an arm.
    dxContactRows kept;
    unsigned negated;
    dReal mu2, rho2, rhoN; // effective coefficients of direction 2 and spin
    unsigned rows_present; // which rows (joint_contact.c's ROW_...); set at creation
    int inert;             // bad geometry: no rows at all
    int m;                 // its number of rows (0 when inert)
    // A mode gives a sliding friction row its own target or cfm (Motion1/2,
    // Slip1/2, SoftCFM): without, every row's target is 0 but the normal
    // row's, and its cfm is the world's.
    int own_numbers;
    // The bodies' poses at the contact's first step, and the arms from
    // their origins to the contact point then (world frame).
    const struct dxBody *anchor_body[2];
    uint32_t anchor_generation[2];
    dVector3 pos0[2], arm[2];
    dQuaternion q0[2];
} dxJointContact;

// Out of line (joint_contact.c): the depth of a contact anchored at an
// earlier step, less the separation its bodies gained since along n; the
// normal target with Bounce (the least rebound of the incoming velocity
// relative to the surface's own `motion`, if over `target`); n, t1, t2
// turned to the other sense; the friction rows' own targets and cfm of
// Motion1/2, Slip1/2 and SoftCFM.
dReal dxJointContactMovedDepth(const dxJointContact *c, const dVector3 n);
dReal dxJointContactBounce(const dxJointContact *c, const dVector3 n, dReal target,
                           dReal motion);
void dxJointContactFlip(dxJointContact *c);
void dxJointContactOwnNumbers(dxJointContact *c);

// Does the anchor record belong to the bodies b[0], b[1] attached now?
static inline int dxJointContactAnchored(const dxJointContact *c, const struct dxBody *const b[2])
{
    for (int k = 0; k < 2; k++) {
        if (c->anchor_body[k] != b[k] || (b[k] && c->anchor_generation[k] != b[k]->hdr.generation))
            return 0;
    }
    return 1;
}

// Record the bodies' poses and the arms to the contact point.
static inline void dxJointContactAnchor(dxJointContact *c, const struct dxBody *const b[2])
{
    for (int k = 0; k < 2; k++) {
        c->anchor_body[k] = b[k];
        if (!b[k]) continue;
        c->anchor_generation[k] = b[k]->hdr.generation;
        memcpy(c->pos0[k], b[k]->pos, sizeof c->pos0[k]);   // (with its 4th number: whole fours)
        memcpy(c->q0[k], b[k]->q, sizeof c->q0[k]);
        dSubtractVectors3(c->arm[k], c->contact.geom.pos, b[k]->pos);
    }
}

// The normal row's target relative velocity: the penetration correction
// fps * erp * (depth - surface layer), capped at the world's max correcting
// velocity; with Bounce, at least -bounce times the incoming velocity
// (relative to the surface motion); with MotionN, plus the surface's own
// normal velocity. The bodies may separate but not approach. The depth is
// collision's at the contact's first step (which records the anchor), less
// the separation gained since at a later one.
static inline dReal dxJointContactNormalTarget(dxJointContact *c, const struct dxBody *const b[2],
                                               const dVector3 n, dReal fps, dReal world_erp)
{
    const dSurfaceParameters *s = &c->contact.surface;
    const struct dxWorld *w = c->base.world;
    dReal depth = c->contact.geom.depth;
    if (dxJointContactAnchored(c, b)) depth = dxJointContactMovedDepth(c, n);
    else dxJointContactAnchor(c, b);
    const int mode = s->mode;
    const dReal erp = (mode & dContactSoftERP) ? s->soft_erp : world_erp;
    const dReal excess = depth - w->contact_surface_layer;
    dReal target = 0;
    if (excess > 0) {
        target = fps * erp * excess;
        if (target > w->max_correcting_vel) target = w->max_correcting_vel;
    }
    const dReal motion = (mode & dContactMotionN) ? s->motionN : 0;
    if (mode & dContactBounce) target = dxJointContactBounce(c, n, target, motion);
    return target + motion;
}

// The per-step part of dxJointContactRows but the cfm, for the contact's
// bodies b[0], b[1] (stored order): the directions' sense, the normal row's
// target (with the anchor at the first step), body 1's arm.
static inline dxContactRows *dxJointContactStep(dxJointContact *c, const struct dxBody *const b[2],
                                                dReal fps, dReal erp)
{
    dxContactRows *r = &c->kept;
    // Stored sense: the user's directions, negated when the joint is stored
    // reversed (user body 2 as body 0).
    if (((c->base.flags & DX_JOINT_REVERSE) != 0) != c->negated) dxJointContactFlip(c);
    r->c[0] = dxJointContactNormalTarget(c, b, r->n, fps, erp);   // first: it may record the arms
    r->arm[1] = b[1] ? c->arm[1] : NULL;
    return r;
}

// The rows' cfm: the world's, read now, unless a mode gives a row its own.
static inline void dxJointContactCfm(dxJointContact *c)
{
    dxContactRows *r = &c->kept;
    const dReal world_cfm = c->base.world->cfm;
    const int m = r->m;
    r->cfm[0] = world_cfm;
    r->cfm[1] = m > 1 ? world_cfm : 0;
    r->cfm[2] = m > 2 ? world_cfm : 0;
    if (c->own_numbers) dxJointContactOwnNumbers(c);
}

#endif
