// SPDX-License-Identifier: BSD-3-Clause
//
// heightfield_scratch.c -- the patches of the heightfield colliders (the
// cells of one query as a triangle mesh, and the trimesh geom the colliders
// see it through), per thread: two threads may collide one heightfield with
// different geoms at once. Each thread has one patch per nesting level (a
// height callback or a trimesh callback may itself collide a heightfield);
// the arrays grow when needed and are reused, so a warm collision allocates
// nothing. A thread's patches are freed when it exits.

#include "heightfield_internal.h"

#include <ode/memory.h>
#include <pthread.h>
#include <string.h>

enum { NESTING = 4 };

typedef struct thread_patches {
    dxHeightfieldPatch level[NESTING];
    int depth;   // levels in use
} thread_patches;

static _Thread_local thread_patches *mine;
static pthread_key_t exit_key;
static pthread_once_t exit_key_once = PTHREAD_ONCE_INIT;

static void free_arrays(dxHeightfieldPatch *p)
{
    dxTriMeshData *d = &p->data;
    size_t nv = (size_t)p->vertex_cap, nt = (size_t)p->tri_cap;
    dFree((void *)d->vertices, 3 * nv * sizeof(dReal));
    dFree(d->weld, nv * sizeof(int));
    dFree(d->vertex_first, (nv + 1) * sizeof(int));
    dFree(d->vertex_adj, (size_t)p->adj_cap * sizeof(int));
    dFree((void *)d->indices, 3 * nt * sizeof(dTriIndex));
    dFree(d->normal, 3 * nt * sizeof(dReal));
    dFree(d->neighbour, 3 * nt * sizeof(int));
    dFree(d->features, nt);
    dFree(d->order, nt * sizeof(int));
}

static void free_thread_patches(void *arg)
{
    thread_patches *t = (thread_patches *)arg;
    for (int i = 0; i < NESTING; i++) free_arrays(&t->level[i]);
    dFree(t, sizeof *t);
}

static void make_exit_key(void)
{
    pthread_key_create(&exit_key, free_thread_patches);
}

// An empty patch: a placeable trimesh geom in no space, on its own data,
// whose arrays come with the first query.
static void init_patch(dxHeightfieldPatch *p)
{
    dxGeom *s = &p->mesh.g;
    s->magic = DX_MAGIC_GEOM;
    s->ops = &dx_trimesh_ops;
    s->flags = DX_GEOM_PLACEABLE | DX_GEOM_ENABLED;
    s->category_bits = s->collide_bits = ~0ul;
    s->space_index = -1;
    p->mesh.data = &p->data;
    p->data.magic = DX_MAGIC_TRIMESH_DATA;
    p->data.vertex_double = sizeof(dReal) == sizeof(double);
    p->data.vertex_stride = 3 * (int)sizeof(dReal);
    p->data.tri_stride = 3 * (int)sizeof(dTriIndex);
    p->data.nodes = &p->node;
}

dxHeightfieldPatch *dxHeightfieldPatchAcquire(void)
{
    if (!mine) {
        pthread_once(&exit_key_once, make_exit_key);
        mine = (thread_patches *)dAlloc(sizeof *mine);
        memset(mine, 0, sizeof *mine);
        for (int i = 0; i < NESTING; i++) init_patch(&mine->level[i]);
        pthread_setspecific(exit_key, mine);
    }
    if (mine->depth >= NESTING) {
        dxReportBadArgument("dCollide", "heightfield collisions nested more than %d deep "
                            "(dCollide called from a height or trimesh callback): no contacts",
                            NESTING);
        return NULL;
    }
    return &mine->level[mine->depth++];
}

void dxHeightfieldPatchRelease(dxHeightfieldPatch *p)
{
    if (p) mine->depth--;
}
