// SPDX-License-Identifier: BSD-3-Clause
//
// backend.c -- the registry of narrow-phase backends (<ode/backend.h>): the
// native backend is always registered and selected first, then the adapters
// built in (FCL, Bullet); programs may register more. ODE_COLLISION_BACKEND
// is read when the registry is first used (before any collision): it selects
// the backend of that name as soon as one is registered; if none is by the
// first collision, that is reported once and native stays. An explicit dCollisionSetBackend wins over the variable.

#include "backend_internal.h"
#include "backend_support.h"

#include <ode/error.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_BACKENDS 8

static const dCollisionBackend *backends[MAX_BACKENDS];
static const char *names[MAX_BACKENDS + 1];
static int backend_count;
static const dCollisionBackend *selected;
static int strict;
static int fallback_reported;
static char requested[64];   // ODE_COLLISION_BACKEND while no backend of that name exists

static const dCollisionBackend *find(const char *name)
{
    for (int i = 0; i < backend_count; i++)
        if (strcmp(backends[i]->name, name) == 0) return backends[i];
    return NULL;
}

static void add_backend(const dCollisionBackend *b)
{
    backends[backend_count] = b;
    names[backend_count] = b->name;
    backend_count++;
}

// The first use registers native and the built-in adapters and reads
// ODE_COLLISION_BACKEND (a name too long for `requested` is cut and then
// matches nothing).
static void ensure_native(void)
{
    if (backend_count > 0) return;
    add_backend(dxNativeBackend());
#ifdef DX_HAVE_FCL
    add_backend(dxFclBackend());
#endif
#ifdef DX_HAVE_BULLET
    add_backend(dxBulletBackend());
#endif
    selected = backends[0];
    const char *env = getenv("ODE_COLLISION_BACKEND");
    if (!env) return;
    const dCollisionBackend *b = find(env);
    if (b) selected = b;
    else snprintf(requested, sizeof requested, "%s", env);
}

// A requested backend that never registered: say so once, at the first collision.
static void give_up_request(void)
{
    dMessage(d_ERR_UNKNOWN, "ODE_COLLISION_BACKEND: no backend named \"%s\"; using native",
             requested);
    requested[0] = 0;
}

int dCollisionRegisterBackend(const dCollisionBackend *b)
{
    DX_CHECK_ARG(b != NULL && b->name != NULL && b->collide != NULL && b->supports != NULL,
                 return 0, "backend is NULL or lacks a name, collide or supports");
    ensure_native();
    if (find(b->name)) return 0;
    DX_CHECK_ARG(backend_count < MAX_BACKENDS, return 0, "too many backends (at most %d)",
                 MAX_BACKENDS);
    add_backend(b);
    if (requested[0] && strcmp(requested, b->name) == 0) {
        selected = b;
        requested[0] = 0;
    }
    return 1;
}

int dCollisionSetBackend(const char *name)
{
    DX_CHECK_ARG(name != NULL, return 0, "name is NULL");
    ensure_native();
    const dCollisionBackend *b = find(name);
    DX_CHECK_ARG(b != NULL, return 0, "no collision backend named \"%s\"", name);
    selected = b;
    requested[0] = 0;
    fallback_reported = 0;
    return 1;
}

const char *dCollisionGetBackend(void)
{
    ensure_native();
    return selected->name;
}

const char *const *dCollisionListBackends(void)
{
    ensure_native();
    return names;
}

void dCollisionSetStrict(int on) { strict = on != 0; }

int dxBackendCollide(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip)
{
    ensure_native();
    if (requested[0]) give_up_request();
    const dCollisionBackend *b = selected;
    if (b != backends[0] && !b->supports(o1->ops->cls, o2->ops->cls)) {
        if (strict) {
            dxReportBadArgument("dCollide", "backend \"%s\" cannot collide a %s with a %s "
                                "(strict mode)", b->name, o1->ops->name, o2->ops->name);
            return 0;
        }
        if (!fallback_reported) {
            fallback_reported = 1;
            dMessage(d_ERR_UNKNOWN, "dCollide: backend \"%s\" cannot collide a %s with a %s; "
                     "using native for such pairs", b->name, o1->ops->name, o2->ops->name);
        }
        b = backends[0];
    }
    return b->collide(o1, o2, flags, contact, skip);
}

void dxBackendGeomChanged(dxGeom *g)
{
    for (int i = 0; i < backend_count; i++)
        if (backends[i]->geom_changed) backends[i]->geom_changed(g);
}

void dxBackendGeomDestroyed(dxGeom *g)
{
    for (int i = 0; i < backend_count; i++)
        if (backends[i]->geom_destroyed) backends[i]->geom_destroyed(g);
}
