// SPDX-License-Identifier: BSD-3-Clause
//
// diff_collide_override.c -- dSetColliderOverride and the ray's params
// against the reference: which geoms the collider gets in each order, how the
// contacts come back, a NULL override, and the flags dGeomRayGetParams reads.

#include "diff_print.h"

#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

static dGeomID seen1, seen2;

static int marker(dGeomID o1, dGeomID o2, int flags, dContactGeom *c, int skip)
{
    seen1 = o1;
    seen2 = o2;
    int n = flags & 0xffff;
    if (n > 2) n = 2;
    for (int i = 0; i < n; i++) {
        dContactGeom *k = (dContactGeom *)((char *)c + i * skip);
        k->pos[0] = 1 + i;
        k->pos[1] = 2;
        k->pos[2] = 3;
        k->normal[0] = 0.6;
        k->normal[1] = 0;
        k->normal[2] = 0.8;
        k->depth = 0.25 * (i + 1);
        k->g1 = o1;
        k->g2 = o2;
        k->side1 = 3 + i;
        k->side2 = 7;
    }
    return n;
}

static void print_contacts(const char *name, dGeomID a, dGeomID b)
{
    dContactGeom c[4];
    seen1 = seen2 = 0;
    int n = dCollide(a, b, 4, c, sizeof c[0]);
    char key[64];
    snprintf(key, sizeof key, "%s_count", name);
    diff_value(key, 0, n);
    snprintf(key, sizeof key, "%s_called_with_a_first", name);
    diff_value(key, 0, seen1 == a);
    for (int i = 0; i < n; i++) {
        dReal v[9] = { c[i].pos[0], c[i].pos[1], c[i].pos[2], c[i].normal[0], c[i].normal[1],
                       c[i].normal[2], c[i].depth, c[i].side1, c[i].side2 };
        snprintf(key, sizeof key, "%s_contact%d", name, i);
        diff_values(key, 1e-12, v, 9);
        snprintf(key, sizeof key, "%s_g1_is_a", name);
        diff_value(key, 0, c[i].g1 == a && c[i].g2 == b);
    }
}

int main(void)
{
    dInitODE2(0);
    dGeomID s = dCreateSphere(0, 0.5);
    dGeomID b = dCreateBox(0, 1, 1, 1);
    dGeomSetPosition(b, 10, 0, 0);
    dSetColliderOverride(dSphereClass, dBoxClass, marker);
    print_contacts("sphere_box", s, b);
    print_contacts("box_sphere", b, s);

    dGeomID c1 = dCreateCapsule(0, 0.5, 1);
    dGeomID c2 = dCreateCapsule(0, 0.5, 1);
    dContactGeom k[4];
    diff_value("capsules_before_count", 0, dCollide(c1, c2, 4, k, sizeof k[0]) > 0);
    dSetColliderOverride(dCapsuleClass, dCapsuleClass, NULL);
    print_contacts("capsules_null_override", c1, c2);

    dGeomID r = dCreateRay(0, 1);
    int fc = 7, bc = 7;
    dGeomRayGetParams(r, &fc, &bc);
    diff_value("ray_params_default", 0, fc * 10 + bc);
    dGeomRaySetParams(r, 5, 1);
    dGeomRayGetParams(r, &fc, &bc);
    diff_value("ray_params_5_1", 0, fc * 10 + bc);
    dGeomRaySetParams(r, 0, 3);
    dGeomRayGetParams(r, &fc, &bc);
    diff_value("ray_params_0_3", 0, fc * 10 + bc);
    diff_value("ray_first_contact", 0, dGeomRayGetFirstContact(r));

    dGeomDestroy(s);
    dGeomDestroy(b);
    dGeomDestroy(c1);
    dGeomDestroy(c2);
    dGeomDestroy(r);
    dCloseODE();
    return 0;
}
