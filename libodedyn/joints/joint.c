// SPDX-License-Identifier: BSD-3-Clause
//
// joint.c -- what every joint shares (guide 7.1-7.2): creation and
// destruction, joint groups, attaching to bodies, enabling, user data,
// feedback, and the connectivity queries. Each joint type's geometry and
// constraint rows are in joint_<type>.c.

#include "objects_internal.h"
#include "joint_contact.h"
#include "joint_group.h"
#include "pool.h"

#include <stddef.h>

#include <ode/memory.h>

#define CHECK_JOINT(j, on_fail) \
    DX_CHECK_ARG(dxJointIsLive(j), on_fail, "joint is NULL or was destroyed")
#define CHECK_GROUP(g, on_fail) \
    DX_CHECK_ARG((g) != NULL && (g)->hdr.magic == DX_MAGIC_GROUP, on_fail, \
                 "joint group is NULL or was destroyed")

#define GROUP_CHUNK_BYTES (64 * 1024)

// Non-grouped joints come from a pool per joint type (sizes differ).
static dxPool joint_pools[dJointTypeTransmission + 1];
static dxPool group_pool;

static char *chunk_data(dxJointGroupChunk *c) { return (char *)(c + 1); }

void *dxJointGroupCarveSlow(struct dxJointGroup *g, size_t size)
{
    // The chunks kept from before the last dJointGroupEmpty first, in order.
    dxJointGroupChunk *c = g->current;
    while (c && c->size - c->used < size) {
        c = c->next;
        if (c) c->used = 0;
    }
    if (!c) {
        size_t bytes = size > GROUP_CHUNK_BYTES ? size : GROUP_CHUNK_BYTES;
        size_t alloc_size = sizeof(dxJointGroupChunk) + bytes;
        c = dAlloc(alloc_size);
        c->size = bytes;
        c->used = 0;
        c->alloc_size = alloc_size;
        c->next = NULL;
        if (g->current) {
            // append after the last chunk so emptied chunks are reused in order
            dxJointGroupChunk *last = g->current;
            while (last->next) last = last->next;
            last->next = c;
        } else {
            g->chunks = c;
        }
    }
    g->current = c;
    void *p = chunk_data(c) + c->used;
    c->used += size;
    return p;
}

dxJoint *dxJointPoolTake(dJointType type, size_t size, uint32_t *generation)
{
    dxJoint *j = dxPoolTake(&joint_pools[type], size);
    *generation = j->hdr.generation;
    return j;
}

dxJoint *dxJointCreateBare(struct dxWorld *w, struct dxJointGroup *g, const dxJointClass *cls)
{
    return dxJointCreateBareInline(w, g, cls);
}

dxJoint *dxJointCreate(struct dxWorld *w, struct dxJointGroup *g, const dxJointClass *cls)
{
    dxJoint *j = dxJointCreateBare(w, g, cls);
    memset(j + 1, 0, cls->size - sizeof *j);
    if (cls->init) cls->init(j);
    return j;
}

// Remove node n from the joint list of body b: O(1) when n is the newest
// there (a group emptied newest first).
static inline void unlink_node(struct dxBody *b, dxJointNode *n)
{
    dxJointNode **p = &b->joints;
    if (*p != n) {
        while (*p && *p != n) p = &(*p)->next;
        if (!*p) return;
    }
    *p = n->next;
    b->num_joints--;
}

// Unlink j from its bodies' lists.
static inline void unlink_bodies(dxJoint *j)
{
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (b0) unlink_node(b0, &j->node[0]);
    if (b1) unlink_node(b1, &j->node[1]);
}

// Unlink j from its bodies' lists and its world's, and poison its handle.
static inline void unlink_joint(dxJoint *j)
{
    unlink_bodies(j);
    struct dxWorld *w = j->world;
    if (w) {
        if (j->prev) j->prev->next = j->next;
        else w->joints = j->next;
        if (j->next) j->next->prev = j->prev;
        w->num_joints--;
    }
    j->hdr.magic = DX_MAGIC_DEAD;
}

void dxJointDetach(dxJoint *j)
{
    struct dxBody *b0 = dxJointBody(j, 0), *b1 = dxJointBody(j, 1);
    if (b0) unlink_node(b0, &j->node[0]);
    if (b1) unlink_node(b1, &j->node[1]);
    j->node[0].other = j->node[1].other = NULL;
    j->node[0].next = j->node[1].next = NULL;
    j->flags &= ~(unsigned)DX_JOINT_REVERSE;
}

void dxJointRemove(dxJoint *j)
{
    unlink_joint(j);
    j->node[0].other = j->node[1].other = NULL;
    j->node[0].next = j->node[1].next = NULL;
    if (!(j->flags & DX_JOINT_IN_GROUP)) dxPoolGive(&joint_pools[j->cls->type], j);
}

void dJointDestroy(dJointID j)
{
    CHECK_JOINT(j, return);
    if (j->flags & DX_JOINT_IN_GROUP) return;   // the group owns it (guide 7.1)
    dxJointRemove(j);
}

// ---- groups ---------------------------------------------------------------

dJointGroupID dJointGroupCreate(int max_size)
{
    (void)max_size;   // ODE 0.5 sized groups up front; ours grow
    struct dxJointGroup *g = dxPoolTake(&group_pool, sizeof *g);
    uint32_t generation = g->hdr.generation;
    memset(g, 0, sizeof *g);
    g->hdr.magic = DX_MAGIC_GROUP;
    g->hdr.generation = generation + 1;
    return g;
}

// dJointGroupEmpty asks for the joint this many places on in its walk while
// it unlinks the current one: the joints' lines have left the caches since
// collision made them, and each joint's address comes from the one before.
#define EMPTY_AHEAD 8

// Ask for the lines dJointGroupEmpty reads and writes of the joint
// EMPTY_AHEAD places after j in its newest-first walk, where that joint lies
// if it and those between are contacts, as nearly all of a group's are: a
// group's joints are carved one after another from its chunks. (Only a
// hint: elsewhere it asks for a line in vain, or, hitting no mapping,
// nothing at all.)
static inline void prefetch_older(const dxJoint *j)
{
#if defined(__GNUC__)
    const uintptr_t at = (uintptr_t)j - EMPTY_AHEAD * dxJointCarveSize(sizeof(dxJointContact));
    __builtin_prefetch((const void *)at);   // (the span's lines: three at most)
    __builtin_prefetch((const void *)(at + 64));
    __builtin_prefetch((const void *)(at + offsetof(dxJoint, node) + sizeof j->node - 1));
#else
    (void)j;
#endif
}

// Unlink j, met in dJointGroupEmpty's walk, from its bodies' lists and poison
// its handle.
static inline void empty_joint(dxJoint *j)
{
    prefetch_older(j);
    unlink_bodies(j);
    j->hdr.magic = DX_MAGIC_DEAD;
}

void dJointGroupEmpty(dJointGroupID g)
{
    CHECK_GROUP(g, return);
    // Newest first, so a body's joint list (newest at its head) unlinks in
    // O(1). Joints made one after another are neighbours in their world's
    // list too (each older than the one before): such a run is cut out of
    // the world's list as a whole. The group's memory is reused whole, so a
    // joint is only unlinked and poisoned.
    dxJoint *j = g->newest;
    while (j) {
        dxJoint *const newest = j;
        int run = 1;
        empty_joint(j);
        while (j->group_prev && j->next == j->group_prev) {
            j = j->next;
            empty_joint(j);
            run++;
        }
        struct dxWorld *w = j->world;
        if (w) {   // (NULL once the world is destroyed: the joint is in no list)
            dxJoint *before = newest->prev, *after = j->next;
            if (before) before->next = after;
            else w->joints = after;
            if (after) after->prev = before;
            w->num_joints -= run;
        }
        j = j->group_prev;
    }
    g->newest = NULL;
    g->current = g->chunks;
    if (g->current) g->current->used = 0;
}

void dJointGroupDestroy(dJointGroupID g)
{
    CHECK_GROUP(g, return);
    dJointGroupEmpty(g);
    for (dxJointGroupChunk *c = g->chunks, *next; c; c = next) {
        next = c->next;
        dFree(c, c->alloc_size);
    }
    g->hdr.magic = DX_MAGIC_DEAD;
    dxPoolGive(&group_pool, g);
}

// ---- attaching --------------------------------------------------------------

void dJointAttach(dJointID j, dBodyID body1, dBodyID body2)
{
    CHECK_JOINT(j, return);
    DX_CHECK_ARG(j->world != NULL, return, "the joint's world was destroyed");
    DX_CHECK_ARG(body1 == NULL || dxBodyIsLive(body1), return, "body1 was destroyed");
    DX_CHECK_ARG(body2 == NULL || dxBodyIsLive(body2), return, "body2 was destroyed");
    DX_CHECK_ARG(body1 == NULL || body1 != body2, return, "body1 and body2 are the same body");
    DX_CHECK_ARG((!body1 || body1->world == j->world) && (!body2 || body2->world == j->world),
                 return, "a body belongs to another world than the joint");

    if (j->node[0].other || j->node[1].other) dxJointDetach(j);   // (a new joint is not attached)
    else j->flags &= ~(unsigned)DX_JOINT_REVERSE;
    if (!body1 && body2) {   // keep body 0 non-NULL: store (body2, 0), reversed
        body1 = body2;
        body2 = NULL;
        j->flags |= DX_JOINT_REVERSE;
    }
    j->node[0].other = body2;
    j->node[1].other = body1;
    if (body1) {
        j->node[0].next = body1->joints;
        body1->joints = &j->node[0];
        body1->num_joints++;
    }
    if (body2) {
        j->node[1].next = body2->joints;
        body2->joints = &j->node[1];
        body2->num_joints++;
    }
    if (j->cls->attached) j->cls->attached(j);
}

int dJointGetNumBodies(dJointID j)
{
    CHECK_JOINT(j, return 0);
    return (dxJointBody(j, 0) != NULL) + (dxJointBody(j, 1) != NULL);
}

void dJointEnable(dJointID j)
{
    CHECK_JOINT(j, return);
    j->flags &= ~(unsigned)DX_JOINT_DISABLED;
}

void dJointDisable(dJointID j)
{
    CHECK_JOINT(j, return);
    j->flags |= DX_JOINT_DISABLED;
}

int dJointIsEnabled(dJointID j)
{
    CHECK_JOINT(j, return 0);
    return (j->flags & DX_JOINT_DISABLED) == 0;
}

void dJointSetData(dJointID j, void *data)
{
    CHECK_JOINT(j, return);
    j->userdata = data;
}

void *dJointGetData(dJointID j)
{
    CHECK_JOINT(j, return NULL);
    return j->userdata;
}

dJointType dJointGetType(dJointID j)
{
    CHECK_JOINT(j, return dJointTypeNone);
    return j->cls->type;
}

dBodyID dJointGetBody(dJointID j, int index)
{
    CHECK_JOINT(j, return NULL);
    DX_CHECK_ARG(index == 0 || index == 1, return NULL, "index must be 0 or 1, got %d", index);
    if (j->flags & DX_JOINT_REVERSE) index = 1 - index;
    return dxJointBody(j, index);
}

void dJointSetFeedback(dJointID j, dJointFeedback *f)
{
    CHECK_JOINT(j, return);
    j->feedback = f;
}

dJointFeedback *dJointGetFeedback(dJointID j)
{
    CHECK_JOINT(j, return NULL);
    return j->feedback;
}

// ---- connectivity ------------------------------------------------------------

// Order the pair so the first is a live body; 0 if neither is.
static int connection_pair(dBodyID *b1, dBodyID *b2)
{
    if (!*b1) {
        *b1 = *b2;
        *b2 = NULL;
    }
    return *b1 != NULL;
}

dJointID dConnectingJoint(dBodyID b1, dBodyID b2)
{
    DX_CHECK_ARG(!b1 || dxBodyIsLive(b1), return NULL, "body1 was destroyed");
    DX_CHECK_ARG(!b2 || dxBodyIsLive(b2), return NULL, "body2 was destroyed");
    DX_CHECK_ARG(connection_pair(&b1, &b2), return NULL, "both bodies are NULL");
    for (dxJointNode *n = b1->joints; n; n = n->next)
        if (n->other == b2) return n->joint;
    return NULL;
}

int dConnectingJointList(dBodyID b1, dBodyID b2, dJointID *out)
{
    DX_CHECK_ARG(!b1 || dxBodyIsLive(b1), return 0, "body1 was destroyed");
    DX_CHECK_ARG(!b2 || dxBodyIsLive(b2), return 0, "body2 was destroyed");
    DX_CHECK_ARG(out != NULL, return 0, "the joint list is NULL");
    DX_CHECK_ARG(connection_pair(&b1, &b2), return 0, "both bodies are NULL");
    int n = 0;
    for (dxJointNode *node = b1->joints; node; node = node->next)
        if (node->other == b2) out[n++] = node->joint;
    return n;
}

int dAreConnected(dBodyID b1, dBodyID b2)
{
    DX_CHECK_ARG(dxBodyIsLive(b1), return 0, "body1 is NULL or was destroyed");
    DX_CHECK_ARG(dxBodyIsLive(b2), return 0, "body2 is NULL or was destroyed");
    for (dxJointNode *n = b1->joints; n; n = n->next)
        if (n->other == b2) return 1;
    return 0;
}

int dAreConnectedExcluding(dBodyID b1, dBodyID b2, int joint_type)
{
    DX_CHECK_ARG(dxBodyIsLive(b1), return 0, "body1 is NULL or was destroyed");
    DX_CHECK_ARG(dxBodyIsLive(b2), return 0, "body2 is NULL or was destroyed");
    for (dxJointNode *n = b1->joints; n; n = n->next)
        if (n->other == b2 && (int)n->joint->cls->type != joint_type) return 1;
    return 0;
}

void dxJointPoolsDrain(void)
{
    for (size_t i = 0; i < sizeof joint_pools / sizeof joint_pools[0]; i++)
        dxPoolDrain(&joint_pools[i]);
    dxPoolDrain(&group_pool);
}
