// SPDX-License-Identifier: BSD-3-Clause
//
// example_util.c -- helpers shared by the drawstuff examples (example_util.h).

#include "example_util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int exu_headless(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "-headless") == 0) return 1;
    const char *env = getenv("DS_HEADLESS");
    return env != NULL && env[0] != '\0' && strcmp(env, "0") != 0;
}

static const dSurfaceParameters *surface_of(const exu_contacts *c, dGeomID g)
{
    const dSurfaceParameters *s = dGeomGetData(g);
    return s ? s : &c->surface;
}

// Bodies joined by any joint but a contact do not collide (a hinge's two links).
static int joined(dBodyID a, dBodyID b)
{
    return a && b && dAreConnectedExcluding(a, b, dJointTypeContact);
}

static void near_callback(void *data, dGeomID o1, dGeomID o2)
{
    exu_contacts *c = data;
    if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
        dSpaceCollide2(o1, o2, data, near_callback);
        return;
    }
    dBodyID b1 = dGeomGetBody(o1);
    dBodyID b2 = dGeomGetBody(o2);
    if (joined(b1, b2)) return;
    if ((!b1 || dBodyIsKinematic(b1)) && (!b2 || dBodyIsKinematic(b2))) return;

    enum { MAX_PAIR = 16 };
    dContact contact[MAX_PAIR];
    const int max = c->max_per_pair > 0 && c->max_per_pair < MAX_PAIR ? c->max_per_pair
                                                                       : MAX_PAIR;
    const int n = dCollide(o1, o2, max, &contact[0].geom, sizeof(dContact));
    const dSurfaceParameters *s1 = surface_of(c, o1);
    const dSurfaceParameters *s2 = surface_of(c, o2);
    for (int i = 0; i < n; i++) {
        contact[i].surface = *s1;
        contact[i].surface.mode |= s2->mode;
        contact[i].surface.mu = (s1->mu + s2->mu) / 2;
        if (s2->bounce > s1->bounce) {
            contact[i].surface.bounce = s2->bounce;
            contact[i].surface.bounce_vel = s2->bounce_vel;
        }
        dJointID j = dJointCreateContact(c->world, c->group, &contact[i]);
        dJointAttach(j, b1, b2);
        if (c->seen_count < c->seen_capacity) c->seen[c->seen_count++] = contact[i].geom;
    }
}

void exu_collide(exu_contacts *c, dSpaceID space)
{
    dJointGroupEmpty(c->group);
    c->seen_count = 0;
    dSpaceCollide(space, c, near_callback);
}

// A triangle mesh as one list of its triangles' world points, drawn in one
// call (a call per triangle costs the renderer a state change each).
static void draw_trimesh(dGeomID g)
{
    static dReal *v;   // 9 numbers a triangle, kept for the next mesh
    static int capacity;
    const int n = dGeomTriMeshGetTriangleCount(g);
    if (n > capacity) {
        dReal *grown = realloc(v, (size_t)n * 9 * sizeof *v);
        if (!grown) return;
        v = grown;
        capacity = n;
    }
    for (int i = 0; i < n; i++) {
        dVector3 p[3];
        dGeomTriMeshGetTriangle(g, i, &p[0], &p[1], &p[2]);
        for (int k = 0; k < 3; k++)
            for (int e = 0; e < 3; e++) v[9 * i + 3 * k + e] = p[k][e];
    }
    static const dReal origin[3] = { 0, 0, 0 };
    static const dReal identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    dsDrawTriangles(origin, identity, v, n, 1);   // v are world points
}

void exu_draw_geom(dGeomID g)
{
    const dReal *pos = dGeomGetPosition(g);
    const dReal *R = dGeomGetRotation(g);
    switch (dGeomGetClass(g)) {
    case dSphereClass:
        dsDrawSphere(pos, R, (float)dGeomSphereGetRadius(g));
        break;
    case dBoxClass: {
        dVector3 sides;
        dGeomBoxGetLengths(g, sides);
        dsDrawBox(pos, R, sides);
        break;
    }
    case dCapsuleClass: {
        dReal radius, length;
        dGeomCapsuleGetParams(g, &radius, &length);
        dsDrawCapsule(pos, R, (float)length, (float)radius);
        break;
    }
    case dCylinderClass: {
        dReal radius, length;
        dGeomCylinderGetParams(g, &radius, &length);
        dsDrawCylinder(pos, R, (float)length, (float)radius);
        break;
    }
    case dRayClass: {
        dVector3 start, dir;
        dGeomRayGet(g, start, dir);
        const dReal length = dGeomRayGetLength(g);
        const dReal end[3] = { start[0] + dir[0] * length, start[1] + dir[1] * length,
                               start[2] + dir[2] * length };
        dsDrawLine(start, end);
        break;
    }
    case dTriMeshClass:
        draw_trimesh(g);
        break;
    default:
        break;   // planes and heightfields are drawn by their examples
    }
}

void exu_draw_contacts(const exu_contacts *c, dReal normal_length)
{
    static const dReal identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    for (int i = 0; i < c->seen_count; i++) {
        const dContactGeom *g = &c->seen[i];
        const dReal tip[3] = { g->pos[0] + g->normal[0] * normal_length,
                               g->pos[1] + g->normal[1] * normal_length,
                               g->pos[2] + g->normal[2] * normal_length };
        dsDrawSphere(g->pos, identity, 0.03f);
        dsDrawLine(g->pos, tip);
    }
}

static int finite_n(const dReal *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite((double)v[i])) return 0;
    return 1;
}

int exu_body_finite(dBodyID b)
{
    return finite_n(dBodyGetPosition(b), 3) && finite_n(dBodyGetRotation(b), 12) &&
           finite_n(dBodyGetLinearVel(b), 3) && finite_n(dBodyGetAngularVel(b), 3);
}

dReal exu_geom_bottom(dGeomID g)
{
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    return aabb[4];
}

dReal exu_speed(dBodyID b)
{
    const dReal *v = dBodyGetLinearVel(b);
    return (dReal)sqrt((double)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
}

void exu_keys(const char *name, const char *help)
{
    printf("%s -- keys:\n%s", name, help);
    fflush(stdout);
}

int exu_report(const char *name, int ok, const char *what, ...)
{
    va_list ap;
    va_start(ap, what);
    printf("%s: %s: ", name, ok ? "ok" : "FAILED");
    vprintf(what, ap);
    printf("\n");
    va_end(ap);
    fflush(stdout);
    return ok ? 0 : 1;
}
