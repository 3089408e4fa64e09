// SPDX-License-Identifier: BSD-3-Clause
//
// backend.c -- the registry of narrow-phase backends (<ode/backend.h>): the
// native backend is always registered and selected first; the adapters meson
// built (FCL, Bullet) are loadable modules, listed when their file is found
// and loaded (dlopen) only when selected; programs may register more.
// ODE_COLLISION_BACKEND is read when the registry is first used (before any
// collision): it selects the backend of that name, loading its module, or
// else as soon as a backend of that name is registered; if none is by the
// first collision, that is reported once and native stays. An explicit
// dCollisionSetBackend wins over the variable. "first,shadow" also turns
// shadow mode on (backend_shadow.c) with the second name, found the same way.
//
// Modules are looked for in the directory of the libodecollide.so that holds
// this code (dladdr): in its subdirectory DX_BACKEND_MODULE_SUBDIR (the
// installed layout), then beside it (the build tree). A statically linked
// libodecollide loads none: the module would bring a second libodecollide.

#define _GNU_SOURCE   // dladdr

#include "backend_internal.h"
#include "backend_shadow.h"
#include "backend_support.h"

#include <dlfcn.h>
#include <ode/error.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_BACKENDS 8

// A backend: registered (table set), or a module found but not loaded yet
// (table NULL, path set).
typedef struct entry {
    const char *name;
    const dCollisionBackend *table;
    const char *path;
} entry;

static entry backends[MAX_BACKENDS];
static const char *names[MAX_BACKENDS + 1];
static int backend_count;
static const dCollisionBackend *selected;
static int strict;
static int fallback_reported;
static char requested[64];   // ODE_COLLISION_BACKEND while no backend of that name exists
static const dCollisionBackend *shadow;   // shadow mode's backend, or NULL when off
static char requested_shadow[64];   // its name from ODE_COLLISION_BACKEND, likewise

// The modules meson built, and where they were found.
static const char *const module_names[] = { DX_BACKEND_MODULES NULL };
static char module_paths[sizeof module_names / sizeof module_names[0]][4096];
static char module_dir[4096];   // directory of libodecollide.so, "" if linked statically

static entry *find(const char *name)
{
    for (int i = 0; i < backend_count; i++)
        if (strcmp(backends[i].name, name) == 0) return &backends[i];
    return NULL;
}

static void add_entry(const char *name, const dCollisionBackend *table, const char *path)
{
    backends[backend_count].name = name;
    backends[backend_count].table = table;
    backends[backend_count].path = path;
    names[backend_count] = name;
    backend_count++;
}

// Where is libodecollide.so? Sets module_dir, or leaves it empty when this
// code is linked into something else (a static libodecollide).
static void locate_library(void)
{
    Dl_info info;
    if (!dladdr(&backend_count, &info) || !info.dli_fname) return;
    const char *slash = strrchr(info.dli_fname, '/');
    const char *base = slash ? slash + 1 : info.dli_fname;
    if (strncmp(base, "libodecollide.so", strlen("libodecollide.so")) != 0) return;
    if (!slash) {
        snprintf(module_dir, sizeof module_dir, ".");
        return;
    }
    int len = (int)(slash - info.dli_fname);
    if (len == 0) len = 1;   // "/libodecollide.so"
    snprintf(module_dir, sizeof module_dir, "%.*s", len, info.dli_fname);
}

// List each module whose file is found (without loading it).
static void find_modules(void)
{
    if (!module_names[0]) return;
    locate_library();
    if (!module_dir[0]) return;
    for (int i = 0; module_names[i] && backend_count < MAX_BACKENDS; i++) {
        char *path = module_paths[i];
        int n = snprintf(path, sizeof module_paths[i], "%s/%s/libodecollide-%s.so", module_dir,
                         DX_BACKEND_MODULE_SUBDIR, module_names[i]);
        if (n < 0 || (size_t)n >= sizeof module_paths[i] || access(path, R_OK) != 0)
            n = snprintf(path, sizeof module_paths[i], "%s/libodecollide-%s.so", module_dir,
                         module_names[i]);
        if (n < 0 || (size_t)n >= sizeof module_paths[i] || access(path, R_OK) != 0) continue;
        add_entry(module_names[i], NULL, path);
    }
}

// The table of e, loading its module the first time. On failure returns
// NULL with the reason in `why`.
static const dCollisionBackend *load(entry *e, char *why, size_t size)
{
    if (e->table) return e->table;
    void *lib = dlopen(e->path, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        const char *err = dlerror();
        snprintf(why, size, "%s", err ? err : e->path);
        return NULL;
    }
    typedef const dCollisionBackend *module_entry(const char *abi);
    module_entry *fn = (module_entry *)dlsym(lib, DX_BACKEND_MODULE_ENTRY);
    const dCollisionBackend *table = fn ? fn(DX_BACKEND_ABI) : NULL;
    if (!table || !table->name || strcmp(table->name, e->name) != 0 || !table->collide ||
        !table->supports) {
        snprintf(why, size, "%.300s is not a backend module of this libodecollide (%s)",
                 e->path, DX_BACKEND_ABI);
        dlclose(lib);
        return NULL;
    }
    e->table = table;   // never unloaded: geoms may keep its cached shapes
    return table;
}

// Why a backend named `name` is not available, when it is a module meson
// built; NULL otherwise.
static const char *module_missing(const char *name, char *why, size_t size)
{
    for (int i = 0; module_names[i]; i++) {
        if (strcmp(module_names[i], name) != 0) continue;
        if (!module_dir[0])
            snprintf(why, size, "its module cannot be loaded by a statically linked "
                     "libodecollide");
        else
            snprintf(why, size, "its module libodecollide-%.64s.so is neither in %.180s/%s "
                     "nor in %.180s", name, module_dir, DX_BACKEND_MODULE_SUBDIR, module_dir);
        return why;
    }
    return NULL;
}

// The backend named in ODE_COLLISION_BACKEND for a role ("" for the
// selected one, "shadow " for the shadow), loaded; or NULL, after saving the
// name in `request` (not registered yet) or reporting why it cannot load.
static const dCollisionBackend *from_environment(const char *name, const char *role,
                                                 char *request, size_t size)
{
    entry *e = find(name);
    if (!e) {
        snprintf(request, size, "%s", name);
        return NULL;
    }
    char why[512];
    const dCollisionBackend *b = load(e, why, sizeof why);
    if (!b)
        dMessage(d_ERR_UNKNOWN, "ODE_COLLISION_BACKEND: cannot load the %s\"%s\" backend: %s; "
                 "%s", role, name, why, role[0] ? "no shadow mode" : "using native");
    return b;
}

const dxRoute *dx_routes[DX_ROUTE_CLASSES][DX_ROUTE_CLASSES];

void dxBackendRoutesUpdate(void)
{
    const int plain = backend_count > 0 && selected == backends[0].table && !shadow &&
                      !requested[0] && !requested_shadow[0];
    for (int a = 0; a < DX_ROUTE_CLASSES; a++)
        for (int b = 0; b < DX_ROUTE_CLASSES; b++)
            dx_routes[a][b] = plain && !dxCollideOverrideIsSet(a, b) ? dxNativeRoute(a, b) : NULL;
}

static void start_shadow(const dCollisionBackend *b)
{
    shadow = b;
    dxShadowReportAtExit();
}

// The first use registers native, lists the modules found and reads
// ODE_COLLISION_BACKEND, "name" or "name,shadow" (a name too long for
// `requested` is cut and then matches nothing).
static void read_environment(void)
{
    const char *env = getenv("ODE_COLLISION_BACKEND");
    if (!env) return;
    char first[64];
    const char *comma = strchr(env, ',');
    snprintf(first, sizeof first, "%.*s", comma ? (int)(comma - env) : (int)strlen(env), env);
    const dCollisionBackend *b = from_environment(first, "", requested, sizeof requested);
    if (b) selected = b;
    if (comma && (b = from_environment(comma + 1, "shadow ", requested_shadow,
                                       sizeof requested_shadow)))
        start_shadow(b);
}

static void ensure_native(void)
{
    if (backend_count > 0) return;
    add_entry(dxNativeBackend()->name, dxNativeBackend(), NULL);
    selected = backends[0].table;
    find_modules();
    read_environment();
    dxBackendRoutesUpdate();
}

// A requested backend that never registered: say so once, at the first collision.
static void give_up_request(char *request, const char *role, const char *fallback)
{
    char why[512];
    const char *missing = module_missing(request, why, sizeof why);
    dMessage(d_ERR_UNKNOWN, "ODE_COLLISION_BACKEND: no %sbackend named \"%s\"%s%s; %s", role,
             request, missing ? ": " : "", missing ? missing : "", fallback);
    request[0] = 0;
    dxBackendRoutesUpdate();
}

int dCollisionRegisterBackend(const dCollisionBackend *b)
{
    DX_CHECK_ARG(b != NULL && b->name != NULL && b->collide != NULL && b->supports != NULL,
                 return 0, "backend is NULL or lacks a name, collide or supports");
    ensure_native();
    if (find(b->name)) return 0;
    DX_CHECK_ARG(backend_count < MAX_BACKENDS, return 0, "too many backends (at most %d)",
                 MAX_BACKENDS);
    add_entry(b->name, b, NULL);
    if (requested[0] && strcmp(requested, b->name) == 0) {
        selected = b;
        requested[0] = 0;
    }
    if (requested_shadow[0] && strcmp(requested_shadow, b->name) == 0) {
        start_shadow(b);
        requested_shadow[0] = 0;
    }
    dxBackendRoutesUpdate();
    return 1;
}

int dCollisionSetBackend(const char *name)
{
    DX_CHECK_ARG(name != NULL, return 0, "name is NULL");
    ensure_native();
    entry *e = find(name);
    char why[512];
    const char *missing = e ? NULL : module_missing(name, why, sizeof why);
    DX_CHECK_ARG(e != NULL, return 0, "no collision backend named \"%s\"%s%s", name,
                 missing ? ": " : "", missing ? missing : "");
    const dCollisionBackend *b = load(e, why, sizeof why);
    DX_CHECK_ARG(b != NULL, return 0, "cannot load the \"%s\" backend: %s", name, why);
    selected = b;
    requested[0] = 0;
    fallback_reported = 0;
    dxBackendRoutesUpdate();
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

int dCollisionBackendSupports(const char *name, int class1, int class2)
{
    DX_CHECK_ARG(name != NULL, return 0, "name is NULL");
    ensure_native();
    entry *e = find(name);
    DX_CHECK_ARG(e != NULL, return 0, "no collision backend named \"%s\"", name);
    char why[512];
    const dCollisionBackend *b = load(e, why, sizeof why);
    DX_CHECK_ARG(b != NULL, return 0, "cannot load the \"%s\" backend: %s", name, why);
    return b->supports(class1, class2) != 0;
}

int dCollisionSetShadowBackend(const char *name)
{
    ensure_native();
    requested_shadow[0] = 0;
    if (!name) {
        shadow = NULL;
        dxBackendRoutesUpdate();
        return 1;
    }
    entry *e = find(name);
    char why[512];
    const char *missing = e ? NULL : module_missing(name, why, sizeof why);
    DX_CHECK_ARG(e != NULL, return 0, "no collision backend named \"%s\"%s%s", name,
                 missing ? ": " : "", missing ? missing : "");
    const dCollisionBackend *b = load(e, why, sizeof why);
    DX_CHECK_ARG(b != NULL, return 0, "cannot load the \"%s\" backend: %s", name, why);
    start_shadow(b);
    dxBackendRoutesUpdate();
    return 1;
}

const char *dCollisionGetShadowBackend(void)
{
    ensure_native();
    return shadow ? shadow->name : NULL;
}

int dxBackendCollide(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *contact, int skip)
{
    ensure_native();
    if (requested[0]) give_up_request(requested, "", "using native");
    if (requested_shadow[0]) give_up_request(requested_shadow, "shadow ", "no shadow mode");
    const dCollisionBackend *b = selected;
    if (b != backends[0].table && !b->supports(o1->ops->cls, o2->ops->cls)) {
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
        b = backends[0].table;
    }
    if (shadow) return dxShadowCollide(b, shadow, o1, o2, flags, contact, skip);
    return b->collide(o1, o2, flags, contact, skip);
}

// The reasons already said by dxBackendNativeFallback (backend, why).
static struct {
    const char *backend, *why;
} fallbacks_said[16];
static int fallbacks_said_count;

static int fallback_said(const char *backend, const char *why)
{
    for (int i = 0; i < fallbacks_said_count; i++)
        if (strcmp(fallbacks_said[i].backend, backend) == 0 &&
            strcmp(fallbacks_said[i].why, why) == 0)
            return 1;
    if (fallbacks_said_count < (int)(sizeof fallbacks_said / sizeof fallbacks_said[0])) {
        fallbacks_said[fallbacks_said_count].backend = backend;
        fallbacks_said[fallbacks_said_count++].why = why;
    }
    return 0;
}

int dxBackendNativeFallback(const char *backend, dGeomID o1, dGeomID o2, int flags,
                            dContactGeom *out, int skip, const char *why)
{
    if (strict) {
        dxReportBadArgument("dCollide", "backend \"%s\" cannot collide a %s with a %s: %s "
                            "(strict mode)", backend, o1->ops->name, o2->ops->name, why);
        return 0;
    }
    if (!fallback_said(backend, why))
        dMessage(d_ERR_UNKNOWN, "dCollide: backend \"%s\" cannot honour %s; using native "
                 "for such geoms", backend, why);
    return backends[0].table->collide(o1, o2, flags, out, skip);
}

static void notify_changed(dxGeom *g)
{
    for (int i = 0; i < backend_count; i++)
        if (backends[i].table && backends[i].table->geom_changed)
            backends[i].table->geom_changed(g);
}

static void notify_destroyed(dxGeom *g)
{
    for (int i = 0; i < backend_count; i++)
        if (backends[i].table && backends[i].table->geom_destroyed)
            backends[i].table->geom_destroyed(g);
}

void dxBackendGeomChanged(dxGeom *g)
{
    notify_changed(g);
    dxShadowNotify(g, notify_changed);
}

void dxBackendGeomDestroyed(dxGeom *g)
{
    notify_destroyed(g);
    dxShadowNotify(g, notify_destroyed);
}
