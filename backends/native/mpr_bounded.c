// SPDX-License-Identifier: BSD-3-Clause
//
// mpr_bounded.c -- libccd's MPR with a bound on its support calls
// (mpr_bounded.h).

#include "mpr_bounded.h"

#include <ccd/ccd.h>
#include <setjmp.h>
#include <string.h>

_Static_assert(sizeof(ccd_real_t) == sizeof(double), "libccd must be built in double precision");

// A query: its count of support calls, and the way out of MPR.
typedef struct mpr_query {
    int supports;
    jmp_buf out;
} mpr_query;

// A shape of the query.
typedef struct counted_shape {
    const dx_mpr_shape *s;
    mpr_query *q;
} counted_shape;

// The shape's support point; past the bound, back to dx_mpr_penetration.
// (MPR allocates nothing and keeps its state on its stack: leaving it from
// here loses nothing.)
static void counted_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const counted_shape *c = obj;
    if (++c->q->supports > DX_MPR_MAX_SUPPORTS) longjmp(c->q->out, 1);
    c->s->support(c->s->shape, dir->v, out->v);
}

static void counted_centre(const void *obj, ccd_vec3_t *out)
{
    const counted_shape *c = obj;
    memcpy(out->v, c->s->centre, sizeof out->v);
}

dx_mpr_verdict dx_mpr_penetration(const dx_mpr_shape *a, const dx_mpr_shape *b, double tolerance,
                                  double dir[3])
{
    mpr_query q = { .supports = 0 };
    const counted_shape ca = { a, &q }, cb = { b, &q };
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = counted_support;
    ccd.center1 = ccd.center2 = counted_centre;
    ccd.max_iterations = 100;
    ccd.mpr_tolerance = tolerance;
    ccd_real_t depth;
    ccd_vec3_t d, pos;
    if (setjmp(q.out)) return DX_MPR_UNDECIDED;
    if (ccdMPRPenetration(&ca, &cb, &ccd, &depth, &d, &pos) != 0) return DX_MPR_APART;
    memcpy(dir, d.v, sizeof d.v);
    return DX_MPR_OVERLAP;
}
