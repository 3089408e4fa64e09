// SPDX-License-Identifier: BSD-3-Clause
//
// space_simple.c -- the simple space (guide 10.6): every pair of its geoms is
// tested, O(n^2); best for few geoms.

#include "geom_internal.h"
#include "space_pair.h"

static void simple_collide(dxSpace *s, void *data, dNearCallback *cb)
{
    for (int i = 0; i < s->count; i++)
        for (int j = i + 1; j < s->count; j++)
            dxSpaceTestPairInline(s->geoms[i], s->geoms[j], data, cb);
}

static void simple_collide_geom(dxSpace *s, dxGeom *g, void *data, dNearCallback *cb)
{
    for (int i = 0; i < s->count; i++) dxSpaceTestPairInline(g, s->geoms[i], data, cb);
}

static const dxSpaceOps simple_ops = { NULL, NULL, simple_collide, simple_collide_geom, NULL };

dSpaceID dSimpleSpaceCreate(dSpaceID parent)
{
    return dxSpaceCreate(sizeof(dxSpace), dSimpleSpaceClass, &simple_ops, parent);
}
