// SPDX-License-Identifier: BSD-3-Clause
//
// quickstep_contact.c -- a contact's solver rows (quickstep.h's qs_row)
// straight from the contact's numbers (dxJointContactRows: directions, lever
// arms, targets, bounds), without the generic joint rows in between: most of
// a heap's rows are contacts, and the generic way copies each row's 12
// numbers of J into the joint-row layout and out again, with the defaults,
// the block search and the bookkeeping of joints with blocks.
//
// The arithmetic is the generic build's (quickstep_build.c: row_full,
// fill_row, warm_apply), operation for operation, so the rows and the
// results are the same to the bit (tests/test_contact_direct.c runs scenes
// both ways). One shortcut: a one-body row (a contact with the static world)
// leaves out its second body's products, which are exact zeros.

#include "quickstep.h"

#include <string.h>

int dxQuickContactDirect = 1;

// A contact's bodies as the solver sees them: inverse mass and world inverse
// inertia, unconstrained rates (6 numbers as 3 pairs), offsets in fc (the
// island's dummy for a missing second body).
typedef struct qs_cbodies {
    int two;
    dReal im0, im1;
    const dReal *I0, *I1;
    const dReal *R0, *R1;
    int o0, o1;
} qs_cbodies;

QS_INLINE qs_v2 pair(dReal a, dReal b)
{
    qs_v2 v;
    qs_lane(v, 0) = a;
    qs_lane(v, 1) = b;
    return v;
}

QS_INLINE qs_v2 load_pair(const dReal *p)
{
    qs_v2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

// M^-1 J^T of a body's half of a linear row: im l (l the linear part) and
// I a (a the angular part), as pairs.
QS_INLINE void half_response(dReal im, const dReal *I, const dReal *l, const dReal *a, qs_v2 *M)
{
    M[0] = pair(im * l[0], im * l[1]);
    M[1] = pair(im * l[2], I[0] * a[0] + I[1] * a[1] + I[2] * a[2]);
    M[2] = pair(I[4] * a[0] + I[5] * a[1] + I[6] * a[2], I[8] * a[0] + I[9] * a[1] + I[10] * a[2]);
}

// Row q from the contact row along d (target velocity c, cfm, factor sor_w),
// its lambda position pos: D J and M^-1 J^T, the scaled rhs and cfm, as
// fill_row makes them (bounds and f are the caller's).
QS_INLINE void contact_row(const qs_input *in, const qs_cbodies *cb, const dxContactRows *r,
                           const dReal *d, dReal c, dReal cfm_row, dReal sor_w, int pos,
                           qs_row *q)
{
    dVector3 a;
    dCalcVectorCross3(a, r->arm[0], d);
    const qs_v2 J[3] = { pair(d[0], d[1]), pair(d[2], a[0]), pair(a[1], a[2]) };
    qs_v2 M[3];
    half_response(cb->im0, cb->I0, d, a, M);
    const dReal *R = cb->R0;
    // pair_dot's sums: (p0 + p1) + ((p2 + p3) + (p4 + p5)), p3..p5 of body 1.
    const qs_v2 r01 = qs_add(qs_mul(J[0], load_pair(R)), qs_mul(J[1], load_pair(R + 2)));
    const qs_v2 m01 = qs_add(qs_mul(J[0], M[0]), qs_mul(J[1], M[1]));
    qs_v2 r2 = qs_mul(J[2], load_pair(R + 4)), m2 = qs_mul(J[2], M[2]);
    qs_v2 J1[3], M1[3];
    if (cb->two) {
        dVector3 l, a1;
        dCopyNegatedVector3(l, d);
        dCalcVectorCross3(a1, d, r->arm[1]);
        J1[0] = pair(l[0], l[1]);
        J1[1] = pair(l[2], a1[0]);
        J1[2] = pair(a1[1], a1[2]);
        half_response(cb->im1, cb->I1, l, a1, M1);
        const dReal *R1 = cb->R1;
        r2 = qs_add(qs_add(r2, qs_mul(J1[0], load_pair(R1))),
                    qs_add(qs_mul(J1[1], load_pair(R1 + 2)), qs_mul(J1[2], load_pair(R1 + 4))));
        m2 = qs_add(qs_add(m2, qs_mul(J1[0], M1[0])),
                    qs_add(qs_mul(J1[1], M1[1]), qs_mul(J1[2], M1[2])));
    } else {
        J1[0] = J1[1] = J1[2] = M1[0] = M1[1] = M1[2] = qs_splat(0);
    }
    const qs_v2 rs = qs_add(r01, r2), ms = qs_add(m01, m2);
    const dReal rate = qs_lane(rs, 0) + qs_lane(rs, 1), cfm = cfm_row * in->fps;
    const double diag = (double)(qs_lane(ms, 0) + qs_lane(ms, 1)) + cfm;
    // A zero diagonal (an empty row without cfm) leaves the row's force at 0.
    const dReal D = diag > 0 ? (dReal)(sor_w / diag) : 0;
    const qs_v2 dd = qs_splat(D);
    for (int e = 0; e < 3; e++) {
        q->J[e] = qs_mul(dd, J[e]);
        q->M[e] = M[e];
        q->J1[e] = qs_mul(dd, J1[e]);
        q->M1[e] = M1[e];
    }
    q->g = NULL;
    q->gn = 0;
    q->gfirst = 0;
    q->two = (short)cb->two;
    q->rhs = (c * in->fps - rate) * D;
    q->cfm = cfm * D;
    q->pos = pos;
    q->o0 = cb->o0;
    q->o1 = cb->o1;
}

// lambda[q->pos] = l and fc += M^-1 J^T l (warm_apply's start_row).
QS_INLINE void start_row(const qs_row *q, dReal l, qs_system *sys)
{
    if (l == 0) return;
    sys->lambda[q->pos] = l;
    const qs_v2 k = qs_splat(l);
    dReal *f0 = sys->fc + q->o0, *f1 = sys->fc + q->o1;
    for (int e = 0; e < 3; e++) {
        const qs_v2 x = qs_add(load_pair(f0 + 2 * e), qs_mul(k, q->M[e]));
        const qs_v2 y = qs_add(load_pair(f1 + 2 * e), qs_mul(k, q->M1[e]));
        memcpy(f0 + 2 * e, &x, sizeof x);
        memcpy(f1 + 2 * e, &y, sizeof y);
    }
}

int dxQuickContactIsDirect(const dxJoint *j)
{
    if (!dxQuickContactDirect || j->feedback || !dxJointContactIsPlain(j)) return 0;
    const struct dxBody *b1 = dxJointBody(j, 1);
    return !(dxJointBody(j, 0)->flags & DX_BODY_KINEMATIC) &&
           !(b1 && (b1->flags & DX_BODY_KINEMATIC));
}

void dxQuickContact(const qs_input *in, dxJoint *j, qs_system *sys)
{
    dxContactRows r;
    dxJointContactRows(j, in->fps, in->erp, &r);
    const struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    const dxIslandBodies *bd = in->bd;
    qs_cbodies cb;
    cb.two = b1 != NULL;
    cb.im0 = bd->inv_mass[b0->tag];
    cb.I0 = bd->inv_inertia + 12 * b0->tag;
    cb.R0 = in->rates + 6 * b0->tag;
    cb.o0 = 6 * (in->body0 + b0->tag);
    cb.im1 = b1 ? bd->inv_mass[b1->tag] : 0;
    cb.I1 = b1 ? bd->inv_inertia + 12 * b1->tag : NULL;
    cb.R1 = b1 ? in->rates + 6 * b1->tag : NULL;
    cb.o1 = 6 * (in->body0 + (b1 ? b1->tag : in->nb));

    // The warm start's lookup first: a warm normal row is relaxed with 1.
    static const dReal zero[3] = { 0, 0, 0 };
    const int t1 = r.friction & 1 ? 1 : -1, t2 = r.friction & 2 ? 1 + (r.friction & 1) : -1;
    int found;
    dReal ln, f[3];
    qs_warm_entry *entry =
        dxQuickWarmContact(sys->warm, b0, b1, r.point, r.n, t1 > 0 ? r.d[t1] : zero,
                           t2 > 0 ? r.d[t2] : zero, &found, &ln, f);

    const int first = sys->next;
    qs_row *rows = sys->rows + sys->nrows;
    for (int i = 0; i < r.m; i++) {
        qs_row *q = &rows[i];
        const dReal sor_w = found && i == 0 ? 1 : in->sor_w;
        contact_row(in, &cb, &r, r.d[i], r.c[i], r.cfm[i], sor_w, first + i, q);
        if (i > 0 && r.pyramid[i] && r.k[i] < dInfinity) {
            // Friction: -+k times the normal force.
            q->hi = r.k[i];
            q->lo = -q->hi;
            q->f = first;
        } else {
            q->lo = i > 0 ? -r.k[i] : 0;
            q->hi = i > 0 ? r.k[i] : dInfinity;
            q->f = sys->m;
        }
        sys->row_pos[sys->nrows + i] = q->pos;
        sys->row_f[sys->nrows + i] = q->f;
        sys->order[sys->norder++] = sys->nrows + i;
    }
    sys->nrows += r.m;
    sys->next += r.m;

    const int p[3] = { first, t1 > 0 ? first + t1 : -1, t2 > 0 ? first + t2 : -1 };
    dxQuickWarmPositions(entry, p);
    if (!found) return;
    // The last step's forces, scaled and projected on this step's bounds.
    const dReal lnw = WARM_SCALE * (ln > 0 ? ln : 0);
    start_row(&rows[0], lnw, sys);
    for (int i = 1; i < r.m; i++) {
        const dReal *t = r.d[i];
        dReal lo = rows[i].lo, hi = rows[i].hi;
        if (rows[i].f == first) {
            hi = r.k[i] * lnw;
            lo = -hi;
        }
        dReal l = WARM_SCALE * dCalcVectorDot3(f, t);
        l = l > hi ? hi : l < lo ? lo : l;
        start_row(&rows[i], l, sys);
    }
}
