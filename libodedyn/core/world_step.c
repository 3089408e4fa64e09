// SPDX-License-Identifier: BSD-3-Clause
//
// world_step.c -- the step of a solver that works one island at a time on
// its rows (dWorldStep): every island goes through the same preparation,
// rows, velocity update and integration; only the solve for the constraint
// forces is the solver's. (dWorldQuickStep builds its rows straight into its
// own layout and solves all islands together: quickstep.c.)

#include "step_internal.h"

#include <ode/matrix.h>

static void step_island(struct dxWorld *w, const dxIsland *is, dReal h, dxIslandSolver *solve)
{
    dxArena *a = &w->arena;
    dxArenaMark mark = dxArenaSave(a);
    dxIslandBodies bd;
    dxIslandPrepare(w, is, h, &bd);
    dxIslandRows r;
    dxRowsBuild(w, is, h, &r);

    dReal *cforce = DX_ARENA_ARRAY(a, dReal, 6 * is->nb);
    dSetZero(cforce, 6 * is->nb);
    if (r.m > 0) {
        dReal *lambda = DX_ARENA_ARRAY(a, dReal, r.m);
        dSetZero(lambda, r.m);
        solve(w, is, &bd, &r, h, lambda);
        dxRowsApplyForces(is, &r, lambda, cforce);
    }
    dxIslandUpdateVelocities(is, &bd, cforce, h);
    dxIslandIntegrate(is, h);
    dxArenaRestore(a, mark);
}

int dxStepWorld(struct dxWorld *w, dReal h, const char *function, dxIslandSolver *solve)
{
    dxIsland *islands;
    int count;
    if (!dxStepBegin(w, h, function, &islands, &count)) return 0;
    for (int i = 0; i < count; i++) step_island(w, &islands[i], h, solve);
    dxStepKinematicBodies(w, h);
    dxStepEnd(islands, count, h);
    return 1;
}
