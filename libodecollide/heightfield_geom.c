// SPDX-License-Identifier: BSD-3-Clause
//
// heightfield_geom.c -- the heightfield geom class: creation on a data
// object (placeable or not), changing its data, and the bounding box.

#include "heightfield_internal.h"

void dxHeightfieldDataFree(dxHeightfieldData *d);   // heightfield_data.c

#define CHECK_HEIGHTFIELD(g, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->ops->cls == dHeightfieldClass, on_fail, \
                     "geom is a %s, not a heightfield", (g)->ops->name); \
    } while (0)

// The box of the field's extent (X, Z) and height bounds (Y), posed; a
// wrapping field is infinite along X and Z (and, placed, everywhere).
static void heightfield_aabb(dxGeom *g)
{
    const dxHeightfieldData *d = ((dxHeightfield *)g)->data;
    if (!d || d->source == DX_HF_NONE) {   // nothing to touch: an empty box at the origin
        for (int k = 0; k < 3; k++) g->aabb[2 * k] = g->aabb[2 * k + 1] = g->pos[k];
        return;
    }
    dReal lo[3] = { -d->width / 2, d->min_height, -d->depth / 2 };
    dReal hi[3] = { d->width / 2, d->max_height, d->depth / 2 };
    if (d->wrap) {
        lo[0] = lo[2] = -dInfinity;
        hi[0] = hi[2] = dInfinity;
    }
    const dReal *R = g->R;
    for (int i = 0; i < 3; i++) {
        dReal a = g->pos[i], b = g->pos[i];
        for (int j = 0; j < 3; j++) {
            dReal r = R[4 * i + j];
            if (r == 0) continue;   // 0 * infinity would be NaN
            dReal u = r * lo[j], v = r * hi[j];
            a += dMin(u, v);
            b += dMax(u, v);
        }
        g->aabb[2 * i] = a;
        g->aabb[2 * i + 1] = b;
    }
}

static void detach_data(dxHeightfield *h)
{
    dxHeightfieldData *d = h->data;
    h->data = NULL;
    if (d && --d->users == 0 && d->destroy_pending) dxHeightfieldDataFree(d);
}

static void heightfield_destroy(dxGeom *g)
{
    detach_data((dxHeightfield *)g);
}

const dxGeomClassOps dx_heightfield_ops = { dHeightfieldClass, "heightfield", heightfield_aabb,
                                            heightfield_destroy };

static void attach_data(dxHeightfield *h, dxHeightfieldData *d)
{
    if (h->data == d) return;
    detach_data(h);
    h->data = d;
    if (d) d->users++;
}

dGeomID dCreateHeightfield(dSpaceID space, dHeightfieldDataID data, int bPlaceable)
{
    DX_CHECK_ARG(data == NULL || (dxHeightfieldDataIsLive(data) && !data->destroy_pending),
                 return NULL, "data was destroyed");
    dxHeightfield *h = (dxHeightfield *)dxGeomCreate(
        sizeof *h, &dx_heightfield_ops, bPlaceable ? DX_GEOM_PLACEABLE : 0, NULL);
    attach_data(h, data);
    if (space) dSpaceAdd(space, &h->g);
    return &h->g;
}

void dGeomHeightfieldSetHeightfieldData(dGeomID g, dHeightfieldDataID d)
{
    CHECK_HEIGHTFIELD(g, return);
    DX_CHECK_ARG(d == NULL || (dxHeightfieldDataIsLive(d) && !d->destroy_pending), return,
                 "data was destroyed");
    attach_data((dxHeightfield *)g, d);
    dxGeomShapeChanged(g);
}

dHeightfieldDataID dGeomHeightfieldGetHeightfieldData(dGeomID g)
{
    CHECK_HEIGHTFIELD(g, return NULL);
    return ((dxHeightfield *)g)->data;
}
