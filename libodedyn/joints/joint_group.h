// SPDX-License-Identifier: BSD-3-Clause
//
// joint_group.h -- a joint's creation, inline: its memory carved from its
// group's chunks (or taken from its type's pool) and the common part written.
// dJointCreateContact, made thousands of times a step, builds it in place of
// a call; the other joint types go through dxJointCreateBare (joint.c), the
// same code.

#ifndef DX_JOINT_GROUP_H
#define DX_JOINT_GROUP_H

#include "objects_internal.h"

// A block of a group's memory; joints are carved from it one after another.
struct dxJointGroupChunk {
    dxJointGroupChunk *next;
    size_t size, used;
    size_t alloc_size;
};

#define DX_JOINT_ALIGN 16

// A joint's bytes in its group's chunk.
static inline size_t dxJointCarveSize(size_t size)
{
    return (size + DX_JOINT_ALIGN - 1) / DX_JOINT_ALIGN * DX_JOINT_ALIGN;
}

// Carve `size` (a dxJointCarveSize) bytes when the current chunk is full:
// the next kept chunk, else a new one (joint.c).
void *dxJointGroupCarveSlow(struct dxJointGroup *g, size_t size);
// A joint of type `type` (`size` bytes) from its type's pool (joint.c).
dxJoint *dxJointPoolTake(dJointType type, size_t size, uint32_t *generation);

// Create a joint of class cls in world w (and group g, or NULL), writing
// only its common part (see dxJointCreateBare).
static inline dxJoint *dxJointCreateBareInline(struct dxWorld *w, struct dxJointGroup *g,
                                               const dxJointClass *cls)
{
    dxJoint *j;
    uint32_t generation = 0;
    if (g) {
        const size_t size = dxJointCarveSize(cls->size);
        dxJointGroupChunk *c = g->current;
        if (c && c->size - c->used >= size) {
            j = (dxJoint *)((char *)(c + 1) + c->used);
            c->used += size;
        } else {
            j = dxJointGroupCarveSlow(g, size);
        }
        j->group_prev = g->newest;   // the group's list, newest first
        g->newest = j;
    } else {
        j = dxJointPoolTake(cls->type, cls->size, &generation);
        j->group_prev = NULL;
    }
    // Every field of the common part, written once (no zeroing first).
    j->hdr.magic = DX_MAGIC_JOINT;
    j->hdr.generation = generation + 1;
    j->cls = cls;
    j->world = w;
    j->next = w->joints;
    j->prev = NULL;
    j->group = g;
    j->userdata = NULL;
    j->flags = g ? DX_JOINT_IN_GROUP : 0;
    j->walk = 0;
    for (int k = 0; k < 2; k++) {
        j->node[k].joint = j;
        j->node[k].other = NULL;
        j->node[k].next = NULL;
    }
    j->feedback = NULL;
    j->tag = 0;
    j->rows.m = j->rows.nub = 0;
    if (w->joints) w->joints->prev = j;
    w->joints = j;
    w->num_joints++;
    return j;
}

#endif
