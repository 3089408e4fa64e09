/* SPDX-License-Identifier: BSD-3-Clause */
/* backend.h -- ours, not ODE's: choosing the narrow phase behind dCollide.
 *
 * A backend computes the contacts of two non-space geoms in ODE's convention
 * (contact.h: the normal points into o1, depth >= 0). "native" is always
 * available and is the default; others ("fcl", "bullet") are built when their
 * libraries are found, as modules loaded only when selected. The environment
 * variable ODE_COLLISION_BACKEND, read when the registry is first used,
 * selects one, so an unchanged program can switch (a name that is registered
 * later is selected when it registers).
 * A pair the selected backend does not support is handled by "native", with
 * one message through dMessage, unless strict mode makes that an error. */
#ifndef ODE_BACKEND_H
#define ODE_BACKEND_H

#include <ode/common.h>
#include <ode/contact.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dCollisionBackend {
    const char *name;
    /** 1 if it can collide geoms of these classes (either order). */
    int (*supports)(int class1, int class2);
    /** Contacts as dCollide defines them (flags, skip); o1 and o2 are not spaces. */
    int (*collide)(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip);
    /** The geom's shape or size changed: drop what was cached for it (may be 0). */
    void (*geom_changed)(dGeomID g);
    /** The geom is being destroyed (may be 0). */
    void (*geom_destroyed)(dGeomID g);
} dCollisionBackend;

/** Make a backend selectable by name; returns 1, or 0 if the name is taken. */
ODE_API int dCollisionRegisterBackend(const dCollisionBackend *backend);
/** Select by name; returns 1, or 0 (and reports) if no such backend exists. */
ODE_API int dCollisionSetBackend(const char *name);
/** The selected backend's name. */
ODE_API const char *dCollisionGetBackend(void);
/** The names of the available backends, NULL-terminated. */
ODE_API const char *const *dCollisionListBackends(void);
/** 1: an unsupported pair is an error instead of a native fallback. */
ODE_API void dCollisionSetStrict(int strict);

#ifdef __cplusplus
}
#endif

#endif
