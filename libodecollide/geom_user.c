// SPDX-License-Identifier: BSD-3-Clause
//
// geom_user.c -- user-defined geometry classes (guide 10.8): a program
// registers a class with its AABB, collider, optional box test and destructor;
// its geoms carry `bytes` of class data.

#include "user_class.h"

#include <stdio.h>
#include <string.h>

static dxUserClass classes[dMaxUserClasses];
static dxGeomClassOps class_ops[dMaxUserClasses];
static int class_count;

const dxUserClass *dxUserClassOf(const dxGeom *g)
{
    int i = g->ops->cls - dFirstUserClass;
    return (i >= 0 && i < class_count) ? &classes[i] : NULL;
}

static void user_aabb(dxGeom *g) { dxUserClassOf(g)->info.aabb(g, g->aabb); }

static void user_destroy(dxGeom *g)
{
    const dxUserClass *c = dxUserClassOf(g);
    if (c->info.dtor) c->info.dtor(g);
}

// The guide (10.8) lets the class's collider lookup be called rarely: each
// answer is asked once, on first use, and kept.
dColliderFn *dxUserColliderFor(const dxGeom *g, int other_class)
{
    dxUserClass *c = &classes[g->ops->cls - dFirstUserClass];
    if (!c->asked[other_class]) {
        c->collider[other_class] = c->info.collider(other_class);
        c->asked[other_class] = 1;
    }
    return c->collider[other_class];
}

// The class's optional box test (guide 10.8), both ways round: 0 when a user
// geom proves it does not reach the other geom's (current) AABB.
int dxUserAABBTest(dxGeom *a, dxGeom *b)
{
    const dxUserClass *ua = dxUserClassOf(a), *ub = dxUserClassOf(b);
    if (ua && ua->info.aabb_test && !ua->info.aabb_test(a, b, b->aabb)) return 0;
    if (ub && ub->info.aabb_test && !ub->info.aabb_test(b, a, a->aabb)) return 0;
    return 1;
}

int dCreateGeomClass(const dGeomClass *c)
{
    DX_CHECK_ARG(c != NULL, return -1, "classptr is NULL");
    DX_CHECK_ARG(c->bytes >= 0, return -1, "bytes must be >= 0, got %d", c->bytes);
    DX_CHECK_ARG(c->collider != NULL && c->aabb != NULL, return -1,
                 "the class needs a collider and an aabb function");
    DX_CHECK_ARG(class_count < dMaxUserClasses, return -1,
                 "too many user classes (at most %d)", dMaxUserClasses);
    int i = class_count++;
    memset(&classes[i], 0, sizeof classes[i]);
    classes[i].info = *c;
    snprintf(classes[i].name, sizeof classes[i].name, "user class %d", dFirstUserClass + i);
    class_ops[i].cls = dFirstUserClass + i;
    class_ops[i].name = classes[i].name;
    class_ops[i].compute_aabb = user_aabb;
    class_ops[i].destroy = user_destroy;
    return dFirstUserClass + i;
}

// Class data follows the geom, aligned for any type.
static size_t data_offset(void)
{
    const size_t a = sizeof(long double) > sizeof(void *) ? sizeof(long double) : sizeof(void *);
    return (sizeof(dxGeom) + a - 1) / a * a;
}

void *dGeomGetClassData(dGeomID g)
{
    DX_CHECK_GEOM(g, return NULL);
    DX_CHECK_ARG(dxUserClassOf(g) != NULL, return NULL, "geom is a %s, not of a user class",
                 g->ops->name);
    return (char *)g + data_offset();
}

dGeomID dCreateGeom(int classnum)
{
    int i = classnum - dFirstUserClass;
    DX_CHECK_ARG(i >= 0 && i < class_count, return NULL,
                 "class %d is not a user class registered with dCreateGeomClass", classnum);
    dxGeom *g = dxGeomCreate(data_offset() + (size_t)classes[i].info.bytes, &class_ops[i],
                             DX_GEOM_PLACEABLE, NULL);
    return g;
}
