// SPDX-License-Identifier: BSD-3-Clause
//
// init.c -- dInitODE/dCloseODE and the build configuration string. The
// library needs no initialisation; these keep ODE 0.16 programs working and
// report misuse (closing more often than initialising, unknown flags).

#include "dx_check.h"
#include "pool.h"

#include <ode/odeinit.h>

static int init_count;

void dInitODE(void) { dInitODE2(0); }

int dInitODE2(unsigned int uiInitFlags)
{
    DX_CHECK_ARG((uiInitFlags & ~(unsigned)dInitFlagManualThreadCleanup) == 0, return 0,
                 "uiInitFlags has unknown bits 0x%x", uiInitFlags);
    init_count++;
    return 1;
}

int dAllocateODEDataForThread(unsigned int uiAllocateFlags)
{
    (void)uiAllocateFlags;   // nothing is kept per thread
    DX_CHECK_ARG(init_count > 0, return 0, "dInitODE2 has not been called");
    return 1;
}

void dCleanupODEAllDataForThread(void) {}

void dCloseODE(void)
{
    DX_CHECK_ARG(init_count > 0, return, "called more often than dInitODE2");
    if (--init_count == 0) {   // give pooled memory of destroyed objects back
        dxPoolDrain(&dx_world_pool);
        dxPoolDrain(&dx_body_pool);
        dxJointPoolsDrain();
        dxThreadingPoolsDrain();
    }
}

#ifdef dSINGLE
#define PRECISION_TOKEN "ODE_single_precision"
#else
#define PRECISION_TOKEN "ODE_double_precision"
#endif

const char *dGetConfiguration(void) { return "ODE " PRECISION_TOKEN; }

int dCheckConfiguration(const char *token)
{
    DX_CHECK_ARG(token != NULL, return 0, "token is NULL");
    const char *config = dGetConfiguration();
    size_t len = strlen(token);
    if (len == 0) return 0;
    for (const char *p = config; (p = strstr(p, token)) != NULL; p += len) {
        int starts = (p == config || p[-1] == ' ');
        int ends = (p[len] == '\0' || p[len] == ' ');
        if (starts && ends) return 1;
    }
    return 0;
}
