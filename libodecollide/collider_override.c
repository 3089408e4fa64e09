// SPDX-License-Identifier: BSD-3-Clause
//
// collider_override.c -- dSetColliderOverride: a program's own collider for
// a pair of classes, which dCollide calls before anything else (backend,
// transform, user class). As in ODE, setting (i, j) sets (j, i) too, called
// with the geoms swapped and the contacts mirrored back.

#include "backend_internal.h"

typedef struct override_entry {
    dColliderFn *fn;
    unsigned char set;       // an override exists (fn may be NULL: no contacts)
    unsigned char reverse;   // call fn(o2, o1) and mirror the contacts
} override_entry;

static override_entry overrides[dGeomNumClasses][dGeomNumClasses];

void dSetColliderOverride(int i, int j, dColliderFn *fn)
{
    DX_CHECK_ARG(i >= 0 && i < dGeomNumClasses, return, "class i (%d) is not a class number", i);
    DX_CHECK_ARG(j >= 0 && j < dGeomNumClasses, return, "class j (%d) is not a class number", j);
    overrides[i][j] = (override_entry){ fn, 1, 0 };
    overrides[j][i] = (override_entry){ fn, 1, 1 };
    dxBackendRoutesUpdate();
}

int dxCollideOverrideIsSet(int c1, int c2) { return overrides[c1][c2].set; }

int dxCollideOverride(dxGeom *o1, dxGeom *o2, int flags, dContactGeom *c, int skip, int *handled)
{
    const override_entry *e = &overrides[o1->ops->cls][o2->ops->cls];
    *handled = e->set;
    if (!e->set || !e->fn) return 0;
    if (!e->reverse) return e->fn(o1, o2, flags, c, skip);
    const int n = e->fn(o2, o1, flags, c, skip);
    dxFlipContacts(c, n, skip);
    return n;
}
