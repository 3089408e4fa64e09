/* SPDX-License-Identifier: BSD-3-Clause */
/* matrix_coop.h -- matrix.h's factorisation and solves, computed
 * cooperatively by the threads of a resource container's Cooperative
 * (cooperative.h), ODE 0.16. Each dEstimate... function makes requirements
 * suffice for calls with up to maximalAllowedThreadCount threads and
 * maximalRowCount rows (it never lowers them); the call then uses at most
 * allowedThreadCount threads of the container, and gives the same result for
 * any thread count. Matrices are stored by rows, row i at i * rowSkip
 * (rowSkip >= rowCount). Calls beyond the container's estimates, and bad
 * handles, are reported through the debug handler and do nothing. */
#ifndef ODE_MATRIX_COOP_H
#define ODE_MATRIX_COOP_H

#include <ode/common.h>
#include <ode/cooperative.h>
#include <ode/threading.h>

#ifdef __cplusplus
extern "C" {
#endif

ODE_API void dEstimateCooperativelyFactorLDLTResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount);
/** A = L D L^T for symmetric positive definite A (its lower triangle is read):
 *  L, unit lower triangular, into the strict lower triangle of A; the
 *  reciprocals of D into d. */
ODE_API void dCooperativelyFactorLDLT(dResourceContainerID resources, unsigned allowedThreadCount,
                                      dReal *A, dReal *d, unsigned rowCount, unsigned rowSkip);

ODE_API void dEstimateCooperativelySolveLDLTResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount);
/** Solve L D L^T x = b (d: the reciprocals of D, as the factorisation gives);
 *  x overwrites b. */
ODE_API void dCooperativelySolveLDLT(dResourceContainerID resources, unsigned allowedThreadCount,
                                     const dReal *L, const dReal *d, dReal *b, unsigned rowCount,
                                     unsigned rowSkip);

ODE_API void dEstimateCooperativelySolveL1StraightResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount);
/** Solve L x = b for unit lower triangular L (its strict lower triangle is
 *  read); x overwrites b. */
ODE_API void dCooperativelySolveL1Straight(dResourceContainerID resources,
                                           unsigned allowedThreadCount, const dReal *L, dReal *b,
                                           unsigned rowCount, unsigned rowSkip);

ODE_API void dEstimateCooperativelySolveL1TransposedResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalRowCount);
/** Solve L^T x = b for unit lower triangular L; x overwrites b. */
ODE_API void dCooperativelySolveL1Transposed(dResourceContainerID resources,
                                             unsigned allowedThreadCount, const dReal *L,
                                             dReal *b, unsigned rowCount, unsigned rowSkip);

ODE_API void dEstimateCooperativelyScaleVectorResourceRequirements(
    dResourceRequirementsID requirements, unsigned maximalAllowedThreadCount,
    unsigned maximalElementCount);
/** dataVector[i] *= scaleVector[i] for i < elementCount. */
ODE_API void dCooperativelyScaleVector(dResourceContainerID resources,
                                       unsigned allowedThreadCount, dReal *dataVector,
                                       const dReal *scaleVector, unsigned elementCount);

#ifdef __cplusplus
}
#endif

#endif
