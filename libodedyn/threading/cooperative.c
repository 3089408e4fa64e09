// SPDX-License-Identifier: BSD-3-Clause
//
// cooperative.c -- Cooperative objects, resource requirements and resource
// containers (cooperative.h), and the run of a cooperative computation's
// pieces on the Cooperative's threads. A container holds what a computation
// needs besides its arguments: a call wait of the threading implementation
// and one number of scratch per row.

#include "cooperative_internal.h"
#include "parallel_run.h"
#include "threading_internal.h"

#include <ode/memory.h>

enum {
    DX_MAGIC_COOPERATIVE = 0x43636f70u,    // "Ccop"
    DX_MAGIC_REQUIREMENTS = 0x43726571u,   // "Creq"
    DX_MAGIC_CONTAINER = 0x43636e74u       // "Ccnt"
};

struct dxCooperative {
    uint32_t magic;
    const dThreadingFunctionsInfo *functions;   // NULL: no threads
    dThreadingImplementationID impl;
    int users;                                  // requirements and containers
};

struct dxResourceRequirements {
    uint32_t magic;
    struct dxCooperative *cooperative;
    unsigned threads, rows;   // the largest estimated
};

struct dxResourceContainer {
    uint32_t magic;
    struct dxCooperative *cooperative;
    unsigned threads, rows;
    dCallWaitID wait;         // of the Cooperative's implementation, or NULL
    dReal *scratch;           // rows numbers
};

static int cooperative_live(const struct dxCooperative *c)
{
    return c && c->magic == DX_MAGIC_COOPERATIVE;
}

static int requirements_live(const struct dxResourceRequirements *r)
{
    return r && r->magic == DX_MAGIC_REQUIREMENTS;
}

static int container_live(const struct dxResourceContainer *rc)
{
    return rc && rc->magic == DX_MAGIC_CONTAINER;
}

dCooperativeID dCooperativeCreate(const dThreadingFunctionsInfo *functionInfo,
                                  dThreadingImplementationID threadingImpl)
{
    if (functionInfo) {
        DX_CHECK_ARG(functionInfo->struct_size >= sizeof *functionInfo, return NULL,
                     "functionInfo->struct_size is %u, smaller than the structure",
                     functionInfo->struct_size);
        DX_CHECK_ARG(functionInfo != &dx_threading_functions || dxThreadingIsLive(threadingImpl),
                     return NULL, "threadingImpl is NULL or was freed");
    }
    struct dxCooperative *c = dAlloc(sizeof *c);
    c->magic = DX_MAGIC_COOPERATIVE;
    c->functions = functionInfo;
    c->impl = functionInfo ? threadingImpl : NULL;
    c->users = 0;
    return c;
}

void dCooperativeDestroy(dCooperativeID c)
{
    if (!c) return;
    DX_CHECK_ARG(cooperative_live(c), return, "cooperative was destroyed");
    DX_CHECK_ARG(c->users == 0, return, "%d requirements or containers still use it", c->users);
    c->magic = DX_MAGIC_THREADING_DEAD;
    dFree(c, sizeof *c);
}

static dResourceRequirementsID requirements_new(struct dxCooperative *c, unsigned threads,
                                                unsigned rows)
{
    struct dxResourceRequirements *r = dAlloc(sizeof *r);
    r->magic = DX_MAGIC_REQUIREMENTS;
    r->cooperative = c;
    r->threads = threads;
    r->rows = rows;
    c->users++;
    return r;
}

dResourceRequirementsID dResourceRequirementsCreate(dCooperativeID c)
{
    DX_CHECK_ARG(cooperative_live(c), return NULL, "cooperative is NULL or was destroyed");
    return requirements_new(c, 0, 0);
}

void dResourceRequirementsDestroy(dResourceRequirementsID r)
{
    if (!r) return;
    DX_CHECK_ARG(requirements_live(r), return, "requirements were destroyed");
    r->cooperative->users--;
    r->magic = DX_MAGIC_THREADING_DEAD;
    dFree(r, sizeof *r);
}

dResourceRequirementsID dResourceRequirementsClone(dResourceRequirementsID r)
{
    DX_CHECK_ARG(requirements_live(r), return NULL, "requirements are NULL or were destroyed");
    return requirements_new(r->cooperative, r->threads, r->rows);
}

void dResourceRequirementsMergeIn(dResourceRequirementsID summary, dResourceRequirementsID extra)
{
    DX_CHECK_ARG(requirements_live(summary), return,
                 "summaryRequirements are NULL or were destroyed");
    DX_CHECK_ARG(requirements_live(extra), return, "extraRequirements are NULL or were destroyed");
    if (extra->threads > summary->threads) summary->threads = extra->threads;
    if (extra->rows > summary->rows) summary->rows = extra->rows;
}

void dxCoopRequire(const char *function, dResourceRequirementsID r, unsigned threads,
                   unsigned rows)
{
    if (!requirements_live(r)) {
        dxReportBadArgument(function, "requirements are NULL or were destroyed");
        return;
    }
    if (threads > r->threads) r->threads = threads;
    if (rows > r->rows) r->rows = rows;
}

dResourceContainerID dResourceContainerAcquire(dResourceRequirementsID r)
{
    DX_CHECK_ARG(requirements_live(r), return NULL, "requirements are NULL or were destroyed");
    struct dxCooperative *c = r->cooperative;
    DX_CHECK_ARG(c->functions != &dx_threading_functions || dxThreadingIsLive(c->impl),
                 return NULL, "the Cooperative's threading implementation was freed");
    struct dxResourceContainer *rc = dAlloc(sizeof *rc);
    rc->magic = DX_MAGIC_CONTAINER;
    rc->cooperative = c;
    rc->threads = r->threads;
    rc->rows = r->rows;
    rc->wait = c->functions && r->threads > 1 ? c->functions->alloc_call_wait(c->impl) : NULL;
    rc->scratch = dAlloc(sizeof(dReal) * (rc->rows + 1));
    c->users++;
    return rc;
}

void dResourceContainerDestroy(dResourceContainerID rc)
{
    if (!rc) return;
    DX_CHECK_ARG(container_live(rc), return, "resources were destroyed");
    struct dxCooperative *c = rc->cooperative;
    if (rc->wait) c->functions->free_call_wait(c->impl, rc->wait);
    dFree(rc->scratch, sizeof(dReal) * (rc->rows + 1));
    c->users--;
    rc->magic = DX_MAGIC_THREADING_DEAD;
    dFree(rc, sizeof *rc);
}

int dxCoopContainerCovers(const char *function, dResourceContainerID rc, unsigned rows)
{
    if (!container_live(rc)) {
        dxReportBadArgument(function, "resources are NULL or were destroyed");
        return 0;
    }
    if (rows > rc->rows) {
        dxReportBadArgument(function, "%u rows, but the resources were estimated for %u", rows,
                            rc->rows);
        return 0;
    }
    return 1;
}

dReal *dxCoopScratch(dResourceContainerID rc) { return rc->scratch; }

// A piece as parallel_run.h calls it.
typedef struct coop_run {
    dxCoopPieceFunction *piece;
    void *context;
} coop_run;

static void coop_piece(void *context, int item, int thread)
{
    (void)thread;
    const coop_run *run = context;
    run->piece(run->context, item);
}

void dxCoopRun(dResourceContainerID rc, unsigned threads, int count, dxCoopPieceFunction *piece,
               void *context)
{
    const struct dxCooperative *c = rc->cooperative;
    unsigned n = 0;
    if (rc->wait && threads > 1 && count > 1) {
        n = c->functions->retrieve_thread_count(c->impl);
        if (n > threads) n = threads;
        if (n > rc->threads) n = rc->threads;
        if (n > (unsigned)count) n = (unsigned)count;
    }
    coop_run run = { piece, context };
    if (n > 1 && dxRunPieces(c->functions, c->impl, rc->wait, (int)n, count, coop_piece, &run))
        return;
    for (int k = 0; k < count; k++) piece(context, k);
}
