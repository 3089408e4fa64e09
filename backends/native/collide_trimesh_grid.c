// SPDX-License-Identifier: BSD-3-Clause
//
// collide_trimesh_grid.c -- a hash grid of points (contact positions or
// normals) for the neighbour searches of the trimesh colliders' contact
// reduction (collide_trimesh.h): with it, merging near-duplicates and
// grouping equal normals cost about a constant per contact instead of a
// pass over all the others. Cells are at least twice the search radius
// wide, so the points near a point are in at most 2 x 2 x 2 cells; their
// lists live in an open-addressing table keyed by the cell's integer
// coordinates (a slot's head: -2 never used, -1 an emptied list, else
// its first entry). Memory is the scratch set's, kept from one collision
// to the next.

#include "collide_trimesh.h"

#include <float.h>
#include <math.h>
#include <ode/memory.h>

// Cell coordinates stay below this in magnitude (ints, no overflow).
#define KEY_LIMIT ((double)(1 << 29))

void dxTriGridStart(dxTriGrid *g, int entries, dReal reach, dReal extent)
{
    int cap = 16;
    while (cap < 2 * entries) cap *= 2;
    if (cap > g->cell_cap) {
        dFree(g->cell, (size_t)g->cell_cap * sizeof *g->cell);
        g->cell = (dxTriCell *)dAlloc((size_t)cap * sizeof *g->cell);
        g->cell_cap = cap;
    }
    g->mask = cap - 1;
    for (int i = 0; i < cap; i++) g->cell[i].head = -2;
    dxTriMeshReserveInts(&g->link, &g->link_cap, 2 * entries);
    g->links = 0;
    // The search radius, widened by what rounding (of the callers'
    // differences, of the coordinates scaled to cells) can move a point.
    double eps = sizeof(dReal) == sizeof(double) ? DBL_EPSILON : FLT_EPSILON;
    g->reach = (double)reach * 1.001 + 8 * eps * (double)extent;
    double side = 2 * g->reach, coarsest = (extent + g->reach) / KEY_LIMIT;
    if (side < coarsest) side = coarsest;
    // An unbounded radius (or no size at all): one cell for everything.
    g->inv = !isfinite(side) ? 0 : side > 0 ? 1 / side : 1;
}

// The table slot of cell key (an unused one to fill if it has none).
static dxTriCell *slot(dxTriGrid *g, const int key[3])
{
    unsigned h = (unsigned)key[0] * 73856093u ^ (unsigned)key[1] * 19349663u ^
                 (unsigned)key[2] * 83492791u;
    for (unsigned i = h & (unsigned)g->mask;; i = (i + 1) & (unsigned)g->mask) {
        dxTriCell *c = &g->cell[i];
        if (c->head == -2 || (c->key[0] == key[0] && c->key[1] == key[1] && c->key[2] == key[2]))
            return c;
    }
}

void dxTriGridAdd(dxTriGrid *g, const dReal p[3], int point)
{
    int key[3];
    for (int k = 0; k < 3; k++) key[k] = g->inv > 0 ? (int)floor((double)p[k] * g->inv) : 0;
    dxTriCell *c = slot(g, key);
    if (c->head == -2) {
        for (int k = 0; k < 3; k++) c->key[k] = key[k];
        c->head = -1;
    }
    int e = g->links++;
    g->link[2 * e] = point;
    g->link[2 * e + 1] = c->head;
    c->head = e;
}

int dxTriGridNear(dxTriGrid *g, const dReal p[3], int *heads[27])
{
    int lo[3], hi[3], n = 0;
    for (int k = 0; k < 3; k++) {
        lo[k] = g->inv > 0 ? (int)floor(((double)p[k] - g->reach) * g->inv) : 0;
        hi[k] = g->inv > 0 ? (int)floor(((double)p[k] + g->reach) * g->inv) : 0;
    }
    int key[3];
    for (key[0] = lo[0]; key[0] <= hi[0]; key[0]++)
        for (key[1] = lo[1]; key[1] <= hi[1]; key[1]++)
            for (key[2] = lo[2]; key[2] <= hi[2]; key[2]++) {
                dxTriCell *c = slot(g, key);
                if (c->head >= 0) heads[n++] = &c->head;
            }
    return n;
}

void dxTriGridFree(dxTriGrid *g)
{
    dFree(g->cell, (size_t)g->cell_cap * sizeof *g->cell);
    dFree(g->link, (size_t)g->link_cap * sizeof(int));
}
