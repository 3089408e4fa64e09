/* SPDX-License-Identifier: BSD-3-Clause */
/* position_correction.h -- ours, not ODE's: an opt-in position correction
 * after each step.
 *
 * ODE corrects a joint's position error through its velocity (ERP): a part of
 * the error each step, so a long chain that the step pulls apart faster than
 * that stays apart. With n position iterations, each step ends with n
 * Gauss-Seidel sweeps over the island's joints that move the bodies (not
 * their velocities) to remove the joints' position error: each joint's
 * equality rows, evaluated at the current poses, are solved for the smallest
 * move in the bodies' mass metric (Box2D's position relaxation, Bullet's split
 * impulse). Ball, hinge, slider, universal and fixed joints take part; the
 * rows of limits, motors, contacts and other joint types do not. The default,
 * 0, is ODE's step unchanged. dWorldStep and dWorldQuickStep do it;
 * dWorldStepFast1, which already relaxes the joints one by one in its
 * sub-steps, does not. Fewer sweeps than a long chain needs can leave it
 * worse than none (a 100-link chain under dWorldStep: take 8). */
#ifndef ODE_POSITION_CORRECTION_H
#define ODE_POSITION_CORRECTION_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Set the number of position sweeps at the end of each step (0: none, the
 *  default). A negative n is reported through the debug handler and ignored. */
ODE_API void dWorldSetPositionIterations(dWorldID w, int n);
/** The number of position sweeps set for the world. */
ODE_API int dWorldGetPositionIterations(dWorldID w);

#ifdef __cplusplus
}
#endif
#endif
