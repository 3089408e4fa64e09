// SPDX-License-Identifier: BSD-3-Clause
//
// step_internal.h -- what the three steppers share: islands, the per-island
// body data, the constraint rows, and integration.
//
// A step: dxStepBegin finds the islands of enabled bodies; for each island
// the stepper calls dxIslandPrepare (world-frame inverse inertia, gravity and
// gyroscopic torque into the accumulators) and dxRowsBuild (every joint's
// rows; or dxJointRowsFill joint by joint), solves for the constraint forces,
// updates velocities, and calls dxIslandIntegrate; dxStepEnd handles
// auto-disable and releases scratch.

#ifndef DX_STEP_INTERNAL_H
#define DX_STEP_INTERNAL_H

#include "objects_internal.h"
#include "step_memory.h"

typedef struct dxIsland {
    struct dxBody **bodies;   // b->tag is the body's index here while stepping
    int nb;
    dxJoint **joints;         // joints with rows this step
    int nj;
} dxIsland;

// World-frame mass data of the bodies of an island (index = b->tag).
typedef struct dxIslandBodies {
    dReal *inv_mass;          // nb
    dReal *inv_inertia;       // nb x 12 (dMatrix3, world frame)
} dxIslandBodies;

// The constraint rows of an island. Row i: J + i*DX_ROW_SKIP holds
// [J1l J1a J2l J2a] (3 each) for the bodies body0[i] and body1[i] (island
// indices; -1 = static world, or a kinematic body whose motion is already
// folded into c). findex is a global row index or -1.
#define DX_ROW_SKIP 12
typedef struct dxIslandRows {
    int m;
    dReal *J;
    dReal *c, *cfm, *lo, *hi;
    int *findex;
    int *body0, *body1;
    int *joint_row;           // nj + 1 offsets: the rows of joint k are joint_row[k]..[k+1]-1
} dxIslandRows;

// A stepper's solve: the constraint forces lambda[r->m] of one island, from
// its bodies bd and rows r (lambda is zeroed scratch; more scratch from
// arena). Reads and writes only the island's data: islands may be solved
// at once on several threads.
typedef void dxIslandSolver(struct dxWorld *w, dxArena *arena, const dxIsland *is,
                            const dxIslandBodies *bd, const dxIslandRows *r, dReal h,
                            dReal *lambda);
// A whole step with one solver (dWorldStep): islands; per island external
// forces, rows, solve, velocities, positions (on the threads of the world's
// threading implementation, if it has one); then on the caller's thread the
// moved bodies' geoms and callbacks, kinematic bodies, auto-disable.
// Returns 1, or 0 (reported) for a bad world or step.
// (dWorldQuickStep does the same steps its own way, quickstep.c.)
int dxStepWorld(struct dxWorld *w, dReal h, const char *function, dxIslandSolver *solve);

// Check the step size, reset the world's arena and find the islands (arena
// scratch). Returns 0 (after reporting) if the step must not run.
// Counts the step in w->step_count.
int dxStepBegin(struct dxWorld *w, dReal h, const char *function, dxIsland **islands,
                int *count);
// The contact point (world frame) of a contact joint, and which of its
// friction rows exist (bit 0: direction 1, bit 1: direction 2; they follow
// the normal row 0 in that order); -1 for any other joint or an inert
// contact (joint_contact.c).
int dxJointContactWarmInfo(const dxJoint *j, dVector3 point);
// An integer as wide as a dReal: a lane's mask in fours of dReal.
#ifdef dSINGLE
typedef int32_t dxRealMask;
#else
typedef int64_t dxRealMask;
#endif
// A contact's normal and sliding friction rows, in the order of its joint
// rows (the normal, then t1 and t2 as present), as numbers: row i is linear
// along d[i] through the contact point, J = [d, arm0 x d, -d, d x arm1]
// (the second body's half zero without one), target velocity c[i], cfm[i];
// a friction row's bounds are -k..k, or k times the normal force with
// `pyramid` (and k finite). (joint_contact.c; d[] points into the struct.)
typedef struct dxContactRows {
    int m;                    // 1..3
    int friction;             // as dxJointContactWarmInfo returns it
    dVector3 n, t1, t2;       // stored sense (t1, t2 even where their rows are absent)
    const dReal *d[3];        // row i's direction (from row m on: a zero dVector3)
    const dReal *arm[2];      // the lever arms (world frame); arm[1] NULL: no body 1
    const dReal *point;       // the contact point (world frame)
    // Per row (fours, so that the rows can be made together; 0 from row m
    // on): target velocity, cfm, bounds (the normal row 0..inf, a friction
    // row -k..k for its coefficient k, times the normal force if pyramid).
    dReal c[4], cfm[4], lo[4], hi[4];
    // Per row: all bits set if bounded by the normal force (a friction row,
    // k finite), else 0 (rows 0 and 3 always): a mask of the fours' lanes.
    dxRealMask pyramid[4];
} dxContactRows;
// A live contact whose rows are all in dxContactRows (no rolling friction,
// and not both friction rows unbounded: the generic path solves those two as
// a block) has DX_JOINT_PLAIN_CONTACT in its flags, set at creation.
// The rows of a plain contact for a step with 1/h = fps and the world's
// erp (as its fill_rows makes them: the same numbers; it may record the
// contact's anchor on its first step), kept in the contact (valid until it
// is asked again or destroyed). Kinematic bodies are not folded in.
const dxContactRows *dxJointContactRows(dxJoint *j, dReal fps, dReal erp);
void dxStepEnd(const dxIsland *islands, int count, dReal h);

// The island's body data (from arena), with gravity and, if gyro_h > 0, the
// gyroscopic torque of a step gyro_h added to the accumulators (StepFast1
// passes 0 and adds the gyroscopic change per sub-step).
void dxIslandPrepare(struct dxWorld *w, dxArena *arena, const dxIsland *is, dReal gyro_h,
                     dxIslandBodies *out);
// The same into the caller's arrays: inv_mass (nb) and inv_inertia (12 nb).
void dxIslandPrepareAt(struct dxWorld *w, const dxIsland *is, dReal gyro_h, dReal *inv_mass,
                       dReal *inv_inertia, dxIslandBodies *out);
// The gyroscopic torque t (world) of body b for a step h (rows.c): the one
// that takes its angular velocity to the torque-free implicit midpoint
// solution of Euler's equation, which keeps the rotational energy and |L|,
// plus the return of the work the gyroscopic torque did in the body's last
// step (nonzero only where joints or contacts took part of the change).
// Returns 0 (t untouched) for a body with the term off or isotropic inertia.
// Opens the step's ledger entry: call dxBodyGyroscopicEnd after the
// velocity update, before the body moves.
int dxBodyGyroscopicTorque(struct dxBody *b, dReal h, dReal *t);
// Close the ledger entry: the work h t . (w_start + w_end) / 2 the
// gyroscopic torque did over the step (w_end = the body's rate now).
void dxBodyGyroscopicEnd(struct dxBody *b, dReal h);
// The unconstrained rates v/h + M^-1 (f, t) of the island's bodies
// (fps = 1/h), 6 per body, into rates.
void dxIslandBodyRates(const dxIsland *is, const dxIslandBodies *bd, dReal fps, dReal *rates);
void dxRowsBuild(struct dxWorld *w, dxArena *arena, const dxIsland *is, dReal h,
                 dxIslandRows *rows);
// The rows of one joint (j->rows.m of them, counted this step) at J, c, cfm,
// lo, hi, findex (row i at index i, J with DX_ROW_SKIP): J zeroed and filled,
// cfm, lo, hi defaulted and filled (a contact joint writes every entry itself,
// so its defaults are skipped), findex joint-local or -1, kinematic
// bodies' motion folded into c. Island indices of its bodies in b[2] (-1:
// static world or kinematic). What dxRowsBuild does for every joint. Rows
// that are not finite are cleared and reported (dxJointRowsKeepFinite).
void dxJointRowsFill(struct dxWorld *w, dxJoint *j, dReal h, dReal *J, dReal *c, dReal *cfm,
                     dReal *lo, dReal *hi, int *findex, int *b);
// The defaults of m rows before a joint's fill_rows sets what it uses: no
// target (c 0), the world's cfm, no bounds, no friction index (findex -1).
static inline void dxJointRowsDefaults(const struct dxWorld *w, int m, dReal *c, dReal *cfm,
                                       dReal *lo, dReal *hi, int *findex)
{
    for (int i = 0; i < m; i++) {
        c[i] = 0;
        cfm[i] = w->cfm;
        lo[i] = -dInfinity;
        hi[i] = dInfinity;
        findex[i] = -1;
    }
}
// Whether the m rows of joint j just filled (J with row skip `skip`, c,
// cfm, lo, hi) are numbers a solver can take: J, c and cfm finite, no bound
// NaN. If not (a joint whose pose or parameters have no answer, such as
// bevel gears turned parallel) they become rows with no force, J and c 0,
// bounds 0, the world's cfm, no friction index, so the step goes on without
// the joint instead of spreading NaN to its bodies; returns 0 then (the
// caller reports it).
int dxJointRowsKeepFinite(const dxJoint *j, int m, dReal *J, int skip, dReal *c, dReal *cfm,
                          dReal *lo, dReal *hi, int *findex);
// out[6*nb] += J^T lambda per body (force, torque); fills joint feedback.
void dxRowsApplyForces(const dxIsland *is, const dxIslandRows *rows, const dReal *lambda,
                       dReal *body_forces);
// v += h * M^-1 * (accumulated + constraint forces) for every island body.
void dxIslandUpdateVelocities(const dxIsland *is, const dxIslandBodies *bd,
                              const dReal *constraint_forces, dReal h);
// Positions and orientations from the velocities, damping, geom notification,
// and zeroed accumulators: dxIslandMove, dxIslandCorrectPositions, then
// dxIslandFinish.
void dxIslandIntegrate(const dxIsland *is, dReal h);
// Damping, then positions and orientations from the velocities (touches only
// the island's bodies): dxBodyMove for each.
void dxIslandMove(const dxIsland *is, dReal h);
// One body's part of dxIslandMove: its gyroscopic ledger entry closed,
// damping, position and orientation.
void dxBodyMove(struct dxBody *b, dReal h);
// dxBodyMove without the quaternion's normalisation and the rotation matrix,
// which dxIslandRotateFinish does later: there the normalisations (two
// divisions and a square root in a chain, each) of several bodies overlap,
// with little other work between them (docs/perf.md, h-step17).
void dxBodyMoveAhead(struct dxBody *b, dReal h);
// After the move, if the world asks for position iterations: that many
// Gauss-Seidel sweeps over the island's joints moving its bodies to remove
// the joints' position error (position_correction.c). Touches only the
// island's bodies (and the accumulators, which dxIslandFinish clears).
void dxIslandCorrectPositions(const dxIsland *is, dReal h);
// After the move: the geoms' and the moved callbacks' notification (which may
// reach shared collision data: one thread), and zeroed accumulators.
void dxIslandFinish(const dxIsland *is);
// After dxBodyMoveAhead of every island body: each one's quaternion
// normalised and its rotation matrix made from it, then dxIslandFinish's part.
void dxIslandRotateFinish(const dxIsland *is);
// Move the enabled kinematic bodies by their velocities.
void dxStepKinematicBodies(struct dxWorld *w, dReal h);

// A body's inverse inertia in the world frame: R * I^-1 * R^T (a dMatrix3).
void dxBodyWorldInverseInertia(const struct dxBody *b, dReal *out);
// One body's position and orientation update (infinitesimal or finite rotation).
void dxBodyIntegrate(struct dxBody *b, dReal h);

#endif
