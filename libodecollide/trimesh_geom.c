// SPDX-License-Identifier: BSD-3-Clause
//
// trimesh_geom.c -- the trimesh geom class (guide 10.7.6): creation on a
// data object, the callbacks, temporal-coherence settings (used by the
// native colliders' queries, collide_trimesh_tc.c), the last transform,
// triangles in world coordinates and the bounding box.

#include <ode/memory.h>
#include <string.h>

#include "shapes.h"
#include "trimesh_internal.h"

void dxTriMeshDataFree(dxTriMeshData *d);   // trimesh_data.c

#define CHECK_TRIMESH(g, on_fail) \
    do { \
        DX_CHECK_GEOM(g, on_fail); \
        DX_CHECK_ARG((g)->ops->cls == dTriMeshClass, on_fail, "geom is a %s, not a trimesh", \
                     (g)->ops->name); \
    } while (0)

// The box around the tree's root box, posed.
static void trimesh_aabb(dxGeom *g)
{
    dxTriMesh *m = (dxTriMesh *)g;
    dReal lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    if (m->data) dxTriMeshDataBounds(m->data, lo, hi);
    dReal c[3], h[3], centre[3];
    for (int k = 0; k < 3; k++) {
        c[k] = (lo[k] + hi[k]) / 2;
        h[k] = (hi[k] - lo[k]) / 2;
    }
    dMultiply0_331(centre, g->R, c);
    for (int k = 0; k < 3; k++) centre[k] += g->pos[k];
    dxAABBOfBox(g->aabb, centre, g->R, h);
}

// Let go of the data (freed if it was destroyed while in use).
static void detach_data(dxTriMesh *m)
{
    dxTriMeshData *d = m->data;
    if (!d) return;
    dxTriMesh **p = &d->first_user;
    while (*p && *p != m) p = &(*p)->next_user;
    if (*p) *p = m->next_user;
    m->next_user = NULL;
    m->data = NULL;
    if (--d->users == 0 && d->destroy_pending) dxTriMeshDataFree(d);
}

static void attach_data(dxTriMesh *m, dxTriMeshData *d)
{
    if (m->data == d) return;
    detach_data(m);
    m->data = d;
    if (!d) return;
    d->users++;
    m->next_user = d->first_user;
    d->first_user = m;
}

static void trimesh_destroy(dxGeom *g)
{
    dxTriMesh *m = (dxTriMesh *)g;
    detach_data(m);
}

const dxGeomClassOps dx_trimesh_ops = { dTriMeshClass, "trimesh", trimesh_aabb, trimesh_destroy };

void dxTriMeshDataChanged(dxTriMeshData *d)
{
    for (dxTriMesh *m = d->first_user; m; m = m->next_user) dxGeomShapeChanged(&m->g);
}

// The collider class's codes: how a sphere's contacts with several
// triangles are merged (ODE 0.16's default: not at all).
static int trimesh_control(dxGeom *g, int controlClass, int controlCode, void *dataValue,
                           int *dataSize)
{
    dxTriMesh *m = (dxTriMesh *)g;
    if (controlClass != dGeomColliderControlClass) {
        *dataSize = 0;
        DX_CHECK_ARG(0, return 0, "a trimesh has no codes in control class %d", controlClass);
    }
    if (controlCode == dGeomCommonAnyControlCode)
        return dxGeomControlSizeValid(dataValue, dataSize, 0);
    int set = controlCode == dGeomColliderSetMergeSphereContactsControlCode;
    if (!set && controlCode != dGeomColliderGetMergeSphereContactsControlCode) {
        *dataSize = 0;
        DX_CHECK_ARG(0, return 0, "a trimesh has no control code %d", controlCode);
    }
    if (!dxGeomControlSizeValid(dataValue, dataSize, (int)sizeof(int))) return 0;
    int *value = (int *)dataValue;
    if (!set) {
        *value = m->sphere_merge;
        return 1;
    }
    DX_CHECK_ARG(*value >= dGeomColliderMergeContactsValue__Default &&
                     *value <= dGeomColliderMergeContactsValue_Full,
                 return 0, "%d is not a dGeomColliderMergeContactsValue", *value);
    m->sphere_merge = *value == dGeomColliderMergeContactsValue__Default
                          ? dGeomColliderMergeContactsValue_None
                          : *value;
    return 1;
}

dGeomID dCreateTriMesh(dSpaceID space, dTriMeshDataID Data, dTriCallback *Callback,
                       dTriArrayCallback *ArrayCallback, dTriRayCallback *RayCallback)
{
    DX_CHECK_ARG(Data == NULL || (dxTriMeshDataIsLive(Data) && !Data->destroy_pending),
                 return NULL, "Data was destroyed");
    dxTriMesh *m = (dxTriMesh *)dxGeomCreate(sizeof *m, &dx_trimesh_ops, DX_GEOM_PLACEABLE,
                                             NULL);
    m->callback = Callback;
    m->array_callback = ArrayCallback;
    m->ray_callback = RayCallback;
    m->sphere_merge = dGeomColliderMergeContactsValue_None;
    m->tc_id = dxTriMeshNewStamp();
    dxGeomRegisterControl(dTriMeshClass, trimesh_control);
    for (int i = 0; i < 4; i++) m->last_transform[5 * i] = 1;
    attach_data(m, Data);
    if (space) dSpaceAdd(space, &m->g);
    return &m->g;
}

void dGeomTriMeshSetData(dGeomID g, dTriMeshDataID Data)
{
    CHECK_TRIMESH(g, return);
    DX_CHECK_ARG(Data == NULL || (dxTriMeshDataIsLive(Data) && !Data->destroy_pending), return,
                 "Data was destroyed");
    attach_data((dxTriMesh *)g, Data);
    dxGeomShapeChanged(g);
}

dTriMeshDataID dGeomTriMeshGetData(dGeomID g)
{
    CHECK_TRIMESH(g, return NULL);
    return ((dxTriMesh *)g)->data;
}

dTriMeshDataID dGeomTriMeshGetTriMeshDataID(dGeomID g)
{
    return dGeomTriMeshGetData(g);
}

#define CALLBACK_ACCESSORS(Name, Type, field) \
    void dGeomTriMeshSet##Name(dGeomID g, Type *cb) \
    { \
        CHECK_TRIMESH(g, return); \
        ((dxTriMesh *)g)->field = cb; \
    } \
    Type *dGeomTriMeshGet##Name(dGeomID g) \
    { \
        CHECK_TRIMESH(g, return NULL); \
        return ((dxTriMesh *)g)->field; \
    }

CALLBACK_ACCESSORS(Callback, dTriCallback, callback)
CALLBACK_ACCESSORS(ArrayCallback, dTriArrayCallback, array_callback)
CALLBACK_ACCESSORS(RayCallback, dTriRayCallback, ray_callback)
CALLBACK_ACCESSORS(TriMergeCallback, dTriTriMergeCallback, merge_callback)

#define CHECK_TC_CLASS(c, on_fail) \
    DX_CHECK_ARG((c) >= 0 && (c) < 32, on_fail, "geomClass %d is not a geometry class", (c))

// Only spheres, boxes and capsules have a flag (cylinders follow the box's),
// as in ODE 0.16: other classes are accepted and left off.
static int has_tc_flag(int geomClass)
{
    return geomClass == dSphereClass || geomClass == dBoxClass || geomClass == dCapsuleClass;
}

void dGeomTriMeshEnableTC(dGeomID g, int geomClass, int enable)
{
    CHECK_TRIMESH(g, return);
    CHECK_TC_CLASS(geomClass, return);
    dxTriMesh *m = (dxTriMesh *)g;
    if (!has_tc_flag(geomClass)) return;
    if (enable) m->tc_classes |= 1u << geomClass;
    else m->tc_classes &= ~(1u << geomClass);
}

int dGeomTriMeshIsTCEnabled(dGeomID g, int geomClass)
{
    CHECK_TRIMESH(g, return 0);
    CHECK_TC_CLASS(geomClass, return 0);
    return (((dxTriMesh *)g)->tc_classes >> geomClass) & 1;
}

// The geom's entries in every thread's cache (collide_trimesh_tc.c) are
// left behind: they carry the old tc_id and are never found again.
void dGeomTriMeshClearTCCache(dGeomID g)
{
    CHECK_TRIMESH(g, return);
    ((dxTriMesh *)g)->tc_id = dxTriMeshNewStamp();
}

void dGeomTriMeshSetLastTransform(dGeomID g, const dMatrix4 last_trans)
{
    CHECK_TRIMESH(g, return);
    DX_CHECK_ARG(last_trans != NULL, return, "last_trans is NULL");
    memcpy(((dxTriMesh *)g)->last_transform, last_trans, sizeof(dMatrix4));
    ((dxTriMesh *)g)->last_set = 1;
}

const dReal *dGeomTriMeshGetLastTransform(dGeomID g)
{
    CHECK_TRIMESH(g, return NULL);
    return ((dxTriMesh *)g)->last_transform;
}

int dGeomTriMeshGetTriangleCount(dGeomID g)
{
    CHECK_TRIMESH(g, return 0);
    const dxTriMeshData *d = ((dxTriMesh *)g)->data;
    return d ? d->tri_count : 0;
}

#define CHECK_INDEX(g, i, on_fail) \
    DX_CHECK_ARG(((dxTriMesh *)g)->data && (i) >= 0 && (i) < ((dxTriMesh *)g)->data->tri_count, \
                 on_fail, "Index %d is not a triangle of the mesh (%d)", (i), \
                 dGeomTriMeshGetTriangleCount(g))

// Triangle t of the geom in world coordinates.
static void world_triangle(dxGeom *g, int t, dReal v[3][3])
{
    dReal local[3][3];
    dxTriMeshTriangle(((dxTriMesh *)g)->data, t, local);
    for (int k = 0; k < 3; k++) {
        dMultiply0_331(v[k], g->R, local[k]);
        for (int i = 0; i < 3; i++) v[k][i] += g->pos[i];
    }
}

void dGeomTriMeshGetTriangle(dGeomID g, int Index, dVector3 *v0, dVector3 *v1, dVector3 *v2)
{
    CHECK_TRIMESH(g, return);
    CHECK_INDEX(g, Index, return);
    dReal v[3][3];
    world_triangle(g, Index, v);
    dVector3 *out[3] = { v0, v1, v2 };
    for (int k = 0; k < 3; k++)
        if (out[k]) dAssignVector3(*out[k], v[k][0], v[k][1], v[k][2]);
}

void dGeomTriMeshGetPoint(dGeomID g, int Index, dReal u, dReal v, dVector3 Out)
{
    CHECK_TRIMESH(g, return);
    CHECK_INDEX(g, Index, return);
    DX_CHECK_ARG(Out != NULL, return, "Out is NULL");
    dReal w[3][3];
    world_triangle(g, Index, w);
    for (int i = 0; i < 3; i++) Out[i] = (1 - u - v) * w[0][i] + u * w[1][i] + v * w[2][i];
}
