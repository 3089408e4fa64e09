// SPDX-License-Identifier: BSD-3-Clause
//
// world_step.c -- the step of a solver that works one island at a time on
// its rows (dWorldStep): every island goes through the same preparation,
// rows, velocity update and integration; only the solve for the constraint
// forces is the solver's. (dWorldQuickStep builds its rows straight into its
// own layout and solves all islands together: quickstep.c.)
//
// Islands share no body and no row, so with a threading implementation they
// are stepped on its threads, each in its own arena: an island's numbers are
// the same whichever thread steps it. What may reach data outside the
// island (the geoms of moved bodies, the moved callbacks) follows on the
// stepping thread, in island order, whatever the number of threads.

#include "step_internal.h"
#include "step_threads.h"

#include <ode/matrix.h>

typedef struct step_islands {
    struct dxWorld *w;
    const dxIsland *islands;
    dReal h;
    dxIslandSolver *solve;
} step_islands;

static void step_island(void *context, int item, dxArena *a)
{
    const step_islands *s = context;
    const dxIsland *is = &s->islands[item];
    const dReal h = s->h;
    dxArenaMark mark = dxArenaSave(a);
    dxIslandBodies bd;
    dxIslandPrepare(s->w, a, is, h, &bd);
    dxIslandRows r;
    dxRowsBuild(s->w, a, is, h, &r);

    dReal *cforce = DX_ARENA_ARRAY(a, dReal, 6 * is->nb);
    dSetZero(cforce, 6 * is->nb);
    if (r.m > 0) {
        dReal *lambda = DX_ARENA_ARRAY(a, dReal, r.m);
        dSetZero(lambda, r.m);
        s->solve(s->w, a, is, &bd, &r, h, lambda);
        dxRowsApplyForces(is, &r, lambda, cforce);
    }
    dxIslandUpdateVelocities(is, &bd, cforce, h);
    dxIslandMove(is, h);
    dxIslandCorrectPositions(is, h);
    dxArenaRestore(a, mark);
}

int dxStepWorld(struct dxWorld *w, dReal h, const char *function, dxIslandSolver *solve)
{
    dxIsland *islands;
    int count;
    if (!dxStepBegin(w, h, function, &islands, &count)) return 0;
    step_islands s = { w, islands, h, solve };
    const int threads = dxStepThreadCount(w, count, function);
    if (threads > 1) {
        dxStepRunParallel(w, threads, count, step_island, &s);
    } else {
        for (int i = 0; i < count; i++) step_island(&s, i, w->arena);
    }
    for (int i = 0; i < count; i++) dxIslandFinish(&islands[i]);
    dxStepKinematicBodies(w, h);
    dxStepEnd(islands, count, h);
    return 1;
}
