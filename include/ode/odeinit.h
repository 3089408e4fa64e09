/* SPDX-License-Identifier: BSD-3-Clause */
/* odeinit.h -- library initialisation and shutdown. The library works without
 * them, but programs written for ODE 0.16 call them and may rely on their
 * results; dCloseODE releases the library's global caches. */
#ifndef ODE_ODEINIT_H
#define ODE_ODEINIT_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

enum dInitODEFlags {
    dInitFlagManualThreadCleanup = 0x00000001
};

enum dAllocateODEDataFlags {
    dAllocateFlagBasicData = 0,
    dAllocateFlagCollisionData = 0x00000001,
    dAllocateMaskAll = ~0
};

ODE_API void dInitODE(void);
/** Returns 1 on success, 0 for unknown flags. Calls nest with dCloseODE. */
ODE_API int dInitODE2(unsigned int uiInitFlags);
/** Returns 1 on success, 0 if the library is not initialised. */
ODE_API int dAllocateODEDataForThread(unsigned int uiAllocateFlags);
ODE_API void dCleanupODEAllDataForThread(void);
ODE_API void dCloseODE(void);

#ifdef __cplusplus
}
#endif

#endif
