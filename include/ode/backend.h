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
 * one message through dMessage, unless strict mode makes that an error.
 * "first,shadow" (e.g. "native,fcl") also turns shadow mode on (below). */
#ifndef ODE_BACKEND_H
#define ODE_BACKEND_H

#include <ode/common.h>
#include <ode/contact.h>
#include <stdio.h>

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
/** 1 if the backend of that name (loading its module) collides these two
 *  classes itself, without falling back to native; 0 otherwise (an unknown
 *  name is reported). */
ODE_API int dCollisionBackendSupports(const char *name, int class1, int class2);

/* Shadow mode: every dCollide that reaches the selected backend (not the
 * pairs a program's colliders or user classes answer) is also run on a
 * second, "shadow" backend, with the same geoms and flags (at most
 * dCOLLISION_SHADOW_MAX_CONTACTS contacts) into its own buffer; only the
 * selected backend's contacts reach the program. The two results are
 * compared with the collision contract's tolerances and each call that breaks
 * one is a disagreement of one or more kinds (dCOLLISION_SHADOW_*):
 *   CONTACT   one reports contact and the other none, deeper than the depth
 *             tolerance (5 mm + 5 % of the larger deepest depth);
 *   DEPTH     both report contact, deepest depths differ by more than it;
 *   NORMAL    the deepest contacts' normals differ by more than 10 degrees,
 *             where both are at least 0.1 mm deep;
 *   POINT     a contact point of either lies outside one of the two shapes
 *             by more than 1 cm + 10 % of its depth (checked for sphere, box,
 *             capsule, cylinder, plane and convex);
 *   MANIFOLD  one gives a single contact where the other, allowed several,
 *             gives points spread over more than 1 cm (a resting face).
 * Pairs the shadow does not support are counted as not answered. Counts are
 * kept per pair class (for every call), and the first
 * dCOLLISION_SHADOW_RECORDS disagreements per pair class are kept whole (both
 * poses and sizes, both results). At exit, if calls were recorded since the
 * last report or reset, the summary table is printed on stderr.
 * ODE_COLLISION_BACKEND=first,shadow (e.g. "native,fcl") turns it on from the
 * environment. While it is on, dCollide calls that reach a backend are
 * serialised by one lock (so threads may call dCollide); turn it on or off
 * while no other thread collides. When it is off it costs one test per call. */
#define dCOLLISION_SHADOW_MAX_CONTACTS 64
#define dCOLLISION_SHADOW_RECORDS 4
enum {
    dCOLLISION_SHADOW_CONTACT = 1,
    dCOLLISION_SHADOW_DEPTH = 2,
    dCOLLISION_SHADOW_NORMAL = 4,
    dCOLLISION_SHADOW_POINT = 8,
    dCOLLISION_SHADOW_MANIFOLD = 16,
    dCOLLISION_SHADOW_KINDS = 5
};

/** Turn shadow mode on with the backend of that name, or off with NULL;
 *  returns 1, or 0 (and reports) if no such backend exists. Counts and
 *  records are kept (dCollisionShadowReset clears them). */
ODE_API int dCollisionSetShadowBackend(const char *name);
/** The shadow backend's name, or NULL when shadow mode is off. */
ODE_API const char *dCollisionGetShadowBackend(void);

/** What shadow mode counted for one pair class (class1 <= class2). */
typedef struct dCollisionShadowStats {
    int class1, class2;
    unsigned long calls;          /* dCollide calls of this pair class */
    unsigned long not_answered;   /* ... that the shadow does not support */
    unsigned long disagreements;  /* ... with at least one kind */
    unsigned long kinds[dCOLLISION_SHADOW_KINDS];   /* per kind, CONTACT first */
    double worst_depth;           /* largest |deepest depth difference| */
    double worst_normal;          /* largest normal angle, degrees */
    double worst_point_first;     /* largest distance of a selected backend's */
    double worst_point_shadow;    /* ... or the shadow's point outside a shape */
} dCollisionShadowStats;

/** One disagreement: the pair as passed to the backends, both results. */
typedef struct dCollisionShadowRecord {
    int class1, class2;
    dReal params1[4], params2[4]; /* sizes: radius / sides / radius, length / plane */
    dReal pos1[3], R1[12], pos2[3], R2[12];
    int flags;                    /* as passed to the backends */
    int kinds;                    /* dCOLLISION_SHADOW_* bits */
    double depth_error, normal_error, point_error;
    int n_first, n_shadow;        /* contacts each returned */
    dContactGeom first[4], shadow[4];   /* the first ones (g1, g2 cleared) */
} dCollisionShadowRecord;

/** Copy up to max pair classes seen (calls > 0) into out, in class order;
 *  returns how many there are. */
ODE_API int dCollisionShadowGetStats(dCollisionShadowStats *out, int max);
/** Copy up to max kept disagreements of the pair class (either order) into
 *  out, oldest first; returns how many are kept. */
ODE_API int dCollisionShadowGetRecords(int class1, int class2, dCollisionShadowRecord *out,
                                       int max);
/** Print the summary table (and the first disagreement of each pair class)
 *  to f. */
ODE_API void dCollisionShadowReport(FILE *f);
/** Forget all counts and records. */
ODE_API void dCollisionShadowReset(void);

#ifdef __cplusplus
}
#endif

#endif
