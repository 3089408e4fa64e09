/* SPDX-License-Identifier: BSD-3-Clause */
/* export-dif.h -- write a world as text in the Dynamics Interchange Format
 * (DIF v0.1) that ODE writes: the world's parameters, its bodies with the
 * geoms attached to them, and its joints. */
#ifndef ODE_EXPORT_DIF_H
#define ODE_EXPORT_DIF_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Write world w to file as DIF text. world_name prefixes every top-level
 *  name ("" gives `world`, `body[i]`, `joint[i]`). Numbers have 15
 *  significant digits (7 with dSINGLE). Geoms are written when the collision
 *  library attached them. A NULL or destroyed world, or a NULL file or name,
 *  is reported through the debug handler and nothing is written. */
ODE_API void dWorldExportDIF(dWorldID w, FILE *file, const char *world_name);

#ifdef __cplusplus
}
#endif

#endif
