/* SPDX-License-Identifier: BSD-3-Clause */
/* memory.h -- the allocation functions every part of the library allocates
 * through (guide 9.4). Handlers set to 0 restore the C library defaults. */
#ifndef ODE_MEMORY_H
#define ODE_MEMORY_H

#include <ode/odeconfig.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef void *dAllocFunction(dsizeint size);
typedef void *dReallocFunction(void *ptr, dsizeint oldsize, dsizeint newsize);
typedef void dFreeFunction(void *ptr, dsizeint size);

ODE_API void dSetAllocHandler(dAllocFunction *fn);
ODE_API void dSetReallocHandler(dReallocFunction *fn);
ODE_API void dSetFreeHandler(dFreeFunction *fn);
ODE_API dAllocFunction *dGetAllocHandler(void);
ODE_API dReallocFunction *dGetReallocHandler(void);
ODE_API dFreeFunction *dGetFreeHandler(void);

/** Allocate size bytes; reports through dError when memory is exhausted. */
ODE_API void *dAlloc(dsizeint size);
/** Resize a block from dAlloc; oldsize is the size it was allocated with. */
ODE_API void *dRealloc(void *ptr, dsizeint oldsize, dsizeint newsize);
/** Free a block from dAlloc; size is the size it was allocated with. */
ODE_API void dFree(void *ptr, dsizeint size);

#ifdef __cplusplus
}
#endif

#endif
