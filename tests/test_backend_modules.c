// SPDX-License-Identifier: BSD-3-Clause
//
// test_backend_modules.c -- the FCL and Bullet adapters are loadable modules
// (libodecollide/meson.build): a program that collides only through native
// never maps them, their libraries or the C++ runtime; selecting one loads it
// and it collides; every module meson built is listed (BUILT_MODULES, set by
// tests/meson.build). Built a second time against the static libodecollide
// (STATIC_ODECOLLIDE), where no module can be loaded: the list is native
// alone and selecting a module backend is reported, without a crash.

#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ode/backend.h>

#ifndef BUILT_MODULES
#define BUILT_MODULES ""
#endif

enum { MAXC = 8 };

// 1 if a line of /proc/self/maps contains `text`.
static int mapped(const char *text)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f) return -1;
    char line[4096];
    int found = 0;
    while (!found && fgets(line, sizeof line, f)) found = strstr(line, text) != NULL;
    fclose(f);
    return found;
}

// 1 if `name` is in the comma-separated BUILT_MODULES.
static int built(const char *name)
{
    const char *p = BUILT_MODULES;
    size_t len = strlen(name);
    while (*p) {
        size_t n = strcspn(p, ",");
        if (n == len && strncmp(p, name, len) == 0) return 1;
        p += n + (p[n] == ',');
    }
    return 0;
}

typedef struct scene {
    dWorldID world;
    dJointGroupID group;
} scene;

static void near_callback(void *data, dGeomID a, dGeomID b)
{
    scene *sc = data;
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (!ba && !bb) return;
    dContact c[MAXC];
    int n = dCollide(a, b, MAXC, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = 0;
        c[i].surface.mu = 1;
        dJointAttach(dJointCreateContact(sc->world, sc->group, &c[i]), ba, bb);
    }
}

// A world, a body with a sphere, a box and a plane in a space; one step
// with contacts, and a dCollide: everything a native-only program does.
static int simulate_natively(void)
{
    scene sc = { dWorldCreate(), dJointGroupCreate(0) };
    dWorldSetGravity(sc.world, 0, 0, -9.81);
    dSpaceID space = dHashSpaceCreate(0);
    dBodyID body = dBodyCreate(sc.world);
    dMass m;
    dMassSetSphere(&m, 1, 0.5);
    dBodySetMass(body, &m);
    dBodySetPosition(body, 0, 0, 0.45);
    dGeomID sphere = dCreateSphere(space, 0.5), box = dCreateBox(space, 1, 1, 1);
    dGeomID plane = dCreatePlane(space, 0, 0, 1, 0);
    dGeomSetBody(sphere, body);
    dGeomSetPosition(box, 3, 0, 0.49);
    dSpaceCollide(space, &sc, near_callback);
    CHECK(dBodyGetNumJoints(body) == 1);   // the sphere on the plane
    dWorldStep(sc.world, 0.01);
    dJointGroupEmpty(sc.group);
    dContactGeom c[MAXC];
    CHECK(dCollide(box, plane, MAXC, c, sizeof c[0]) == 4);
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    dJointGroupDestroy(sc.group);
    dSpaceDestroy(space);   // destroys its geoms
    dWorldDestroy(sc.world);
    return 0;
}

// No adapter, adapter library or C++ runtime is mapped (a sanitizer runtime
// may bring the C++ runtime itself).
static int check_no_adapter_mapped(void)
{
    static const char *const adapters[] = { "libodecollide-", "libfcl", "liboctomap",
                                            "libBullet", "libLinearMath" };
    for (size_t i = 0; i < sizeof adapters / sizeof adapters[0]; i++) {
        if (mapped(adapters[i]) != 0) printf("# %s is mapped\n", adapters[i]);
        CHECK(mapped(adapters[i]) == 0);
    }
    if (!mapped("libasan") && !mapped("libubsan") && !mapped("libtsan"))
        CHECK(mapped("libstdc++") == 0);
    return 0;
}

static int test_native_program_loads_no_adapter(void)
{
    if (getenv("ODE_COLLISION_BACKEND"))
        return test_skip("ODE_COLLISION_BACKEND is set: it may load an adapter");
    CHECK(simulate_natively() == 0);
    CHECK(dCollisionListBackends()[0] != NULL);   // listing loads nothing either
    CHECK(check_no_adapter_mapped() == 0);
    return 0;
}

#ifndef STATIC_ODECOLLIDE

// The number of different files mapped whose name contains `text`.
static int mapped_files(const char *text)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f) return -1;
    char line[4096], seen[8][4096];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        char *path = strchr(line, '/');
        if (!path || !strstr(path, text)) continue;
        path[strcspn(path, "\n")] = 0;
        int known = 0;
        for (int i = 0; i < n; i++) known |= strcmp(seen[i], path) == 0;
        if (!known && n < 8) snprintf(seen[n++], sizeof seen[0], "%s", path);
    }
    fclose(f);
    return n;
}

static int listed(const char *name)
{
    for (const char *const *n = dCollisionListBackends(); *n; n++)
        if (strcmp(*n, name) == 0) return 1;
    return 0;
}

// Every module meson built is listed (found beside libodecollide.so).
static int test_built_modules_are_listed(void)
{
    CHECK(listed("native"));
    CHECK(listed("fcl") == built("fcl"));
    CHECK(listed("bullet") == built("bullet"));
    return 0;
}

// A box 0.01 deep in a plane: each module backend, loaded when selected,
// finds it; the module and its library are mapped then, with one
// libodecollide.so (the module links it, it does not carry a copy).
static int test_modules_load_when_selected(void)
{
    static const char *const modules[][2] = { { "fcl", "libfcl" },
                                              { "bullet", "libBulletCollision" } };
    int tried = 0;
    for (int i = 0; i < 2; i++) {
        const char *name = modules[i][0];
        if (!listed(name)) continue;
        tried++;
        CHECK(dCollisionSetBackend(name) == 1);
        CHECK(strcmp(dCollisionGetBackend(), name) == 0);
        dGeomID plane = dCreatePlane(0, 0, 0, 1, 0), box = dCreateBox(0, 1, 1, 1);
        dGeomSetPosition(box, 0, 0, 0.49);
        dContactGeom c[MAXC];
        int n = dCollide(box, plane, MAXC, c, sizeof c[0]);
        CHECK(n >= 1);
        for (int k = 0; k < n; k++) CHECK_NEAR(c[k].depth, 0.01, TOL(1e-6, 1e-4));
        dGeomDestroy(plane);
        dGeomDestroy(box);
        char file[64];
        snprintf(file, sizeof file, "libodecollide-%s.so", name);
        CHECK(mapped(file) == 1);
        CHECK(mapped(modules[i][1]) == 1);
        CHECK(mapped_files("libodecollide.so") == 1);
        CHECK(dCollisionSetBackend("native") == 1);
    }
    if (!tried) return test_skip("no backend module is built");
    return 0;
}

// An unknown name is reported with the function and the name.
static int test_unknown_backend_is_reported(void)
{
    test_capture_reports();
    int ok = dCollisionSetBackend("nosuch");
    int named = test_captured_contains("dCollisionSetBackend") &&
                test_captured_contains("\"nosuch\"");
    test_release_reports();
    CHECK(ok == 0 && named);
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_native_program_loads_no_adapter),   // first: nothing selected yet
    TEST_CASE(test_built_modules_are_listed),
    TEST_CASE(test_modules_load_when_selected),
    TEST_CASE(test_unknown_backend_is_reported),
    TEST_END
};

#else

// A static libodecollide lists native alone; selecting a module backend is
// an error that says why, and native stays selected.
static int test_static_library_loads_no_module(void)
{
    const char *const *names = dCollisionListBackends();
    CHECK(strcmp(names[0], "native") == 0 && names[1] == NULL);
    const char *name = built("fcl") ? "fcl" : built("bullet") ? "bullet" : "fcl";
    test_capture_reports();
    int ok = dCollisionSetBackend(name);
    int named = test_captured_contains("dCollisionSetBackend") && test_captured_contains(name);
    int why = test_captured_contains("statically linked");
    test_release_reports();
    CHECK(ok == 0 && named);
    if (built(name)) CHECK(why);
    CHECK(strcmp(dCollisionGetBackend(), "native") == 0);
    dGeomID a = dCreateSphere(0, 1), b = dCreateSphere(0, 1);
    dGeomSetPosition(b, 1.5, 0, 0);
    dContactGeom c[1];
    CHECK(dCollide(a, b, 1, c, sizeof c[0]) == 1);
    dGeomDestroy(a);
    dGeomDestroy(b);
    CHECK(check_no_adapter_mapped() == 0);
    CHECK(mapped("libodecollide.so") == 0);   // one libodecollide: the static one
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_native_program_loads_no_adapter),
    TEST_CASE(test_static_library_loads_no_module),
    TEST_END
};

#endif
