/* SPDX-License-Identifier: BSD-3-Clause */
/* cooperative.h -- cooperative computations (ODE 0.16): a Cooperative object
 * ties a threading implementation (threading.h) to computations that split
 * their work among its threads (matrix_coop.h). Resource requirements are
 * estimated per computation, merged, and then acquired as a resource
 * container (scratch memory and what the threads need), which the
 * computations are given.
 *
 * Lifetimes: requirements may be destroyed at any time; containers and
 * requirements must go before their Cooperative. A NULL or destroyed handle
 * is reported through the debug handler naming the function (Destroy
 * functions accept NULL). */
#ifndef ODE_COOPERATIVE_H
#define ODE_COOPERATIVE_H

#include <ode/common.h>
#include <ode/threading.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dxCooperative;
struct dxResourceRequirements;
struct dxResourceContainer;

typedef struct dxCooperative *dCooperativeID;
typedef struct dxResourceRequirements *dResourceRequirementsID;
typedef struct dxResourceContainer *dResourceContainerID;

/** A Cooperative using threadingImpl through functionInfo; both NULL: the
 *  computations run on the caller's thread. NULL on failure. */
ODE_API dCooperativeID dCooperativeCreate(const dThreadingFunctionsInfo *functionInfo,
                                          dThreadingImplementationID threadingImpl);
ODE_API void dCooperativeDestroy(dCooperativeID cooperative);

/** Empty requirements of computations with cooperative. NULL on failure. */
ODE_API dResourceRequirementsID dResourceRequirementsCreate(dCooperativeID cooperative);
ODE_API void dResourceRequirementsDestroy(dResourceRequirementsID requirements);
/** A copy of requirements. NULL on failure. */
ODE_API dResourceRequirementsID dResourceRequirementsClone(dResourceRequirementsID requirements);
/** summaryRequirements grows to suffice for extraRequirements' computations too. */
ODE_API void dResourceRequirementsMergeIn(dResourceRequirementsID summaryRequirements,
                                          dResourceRequirementsID extraRequirements);

/** The resources requirements describe. NULL on failure. */
ODE_API dResourceContainerID dResourceContainerAcquire(dResourceRequirementsID requirements);
ODE_API void dResourceContainerDestroy(dResourceContainerID resources);

#ifdef __cplusplus
}
#endif

#endif
