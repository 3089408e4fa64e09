/* SPDX-License-Identifier: BSD-3-Clause */
/* collision_trimesh.h -- triangle meshes (guide 10.7.6, with ODE 0.16's
 * additions), included by collision.h as in ODE.
 *
 * A dTriMeshDataID holds pointers to the user's vertex and index arrays (never
 * copied: they must outlive the data) and what is built from them: face
 * normals, edge convexity and a bounding-volume tree. Triangles are one-sided:
 * their front is where (v1 - v0) x (v2 - v0) points; solids behind the
 * triangle of their centre are not pushed out. Zero-area triangles are kept
 * in the numbering but never collide. Bad arguments (an index past the vertex
 * count, a non-finite vertex, a stride smaller than a vertex, an index count
 * that is not a multiple of 3) are reported through the debug handler and
 * leave the data empty. */
#ifndef ODE_COLLISION_TRIMESH_H
#define ODE_COLLISION_TRIMESH_H

#include <ode/common.h>

#ifdef __cplusplus
extern "C" {
#endif

struct dxTriMeshData;
typedef struct dxTriMeshData *dTriMeshDataID;

typedef enum {
    dMTV__MIN,
    dMTV_FIRST = dMTV__MIN,
    dMTV_SECOND,
    dMTV_THIRD,
    dMTV__MAX
} dMeshTriangleVertex;

ODE_API dTriMeshDataID dGeomTriMeshDataCreate(void);
/** Frees the data; if trimesh geoms still use it, when the last of them lets
 *  it go. */
ODE_API void dGeomTriMeshDataDestroy(dTriMeshDataID g);

/* data_id values of dGeomTriMeshDataSet / Get / Get2. */
enum {
    dTRIMESHDATA__MIN,
    dTRIMESHDATA_FACE_NORMALS = dTRIMESHDATA__MIN,
    dTRIMESHDATA_USE_FLAGS,
    dTRIMESHDATA__MAX
#ifndef TRIMESH_FACE_NORMALS
    , TRIMESH_FACE_NORMALS = dTRIMESHDATA_FACE_NORMALS
#endif
};

/* Bits of the dTRIMESHDATA_USE_FLAGS bytes (one per triangle): the edge
 * (v0v1, v1v2, v2v0) or vertex is a real feature of the surface (convex or on
 * the border), not inside a flat or concave region. */
enum {
    dMESHDATAUSE_EDGE1 = 0x01,
    dMESHDATAUSE_EDGE2 = 0x02,
    dMESHDATAUSE_EDGE3 = 0x04,
    dMESHDATAUSE_VERTEX1 = 0x08,
    dMESHDATAUSE_VERTEX2 = 0x10,
    dMESHDATAUSE_VERTEX3 = 0x20
};

/** Attach extra data (not copied): face normals (dReal[3] per triangle, for
 *  the user only) or the use-flags bytes (one per triangle). */
ODE_API void dGeomTriMeshDataSet(dTriMeshDataID g, int data_id, void *in_data);
ODE_API void *dGeomTriMeshDataGet(dTriMeshDataID g, int data_id);
/** As Get; *pout_size (if not NULL) receives the size in bytes (0 if unknown). */
ODE_API void *dGeomTriMeshDataGet2(dTriMeshDataID g, int data_id, dsizeint *pout_size);

/** The transform of the geom at the last step (per geom), for the user. */
ODE_API void dGeomTriMeshSetLastTransform(dGeomID g, const dMatrix4 last_trans);
ODE_API const dReal *dGeomTriMeshGetLastTransform(dGeomID g);

/* Builds from single (float) or double vertices: VertexStride bytes between
 * vertices, IndexCount indices (3 per triangle, dTriIndex), TriStride bytes
 * between triangles. The *1 forms take an optional array of face normals
 * (float or double, 3 per triangle; kept for dTRIMESHDATA_FACE_NORMALS). */
ODE_API void dGeomTriMeshDataBuildSingle(dTriMeshDataID g, const void *Vertices,
                                         int VertexStride, int VertexCount,
                                         const void *Indices, int IndexCount, int TriStride);
ODE_API void dGeomTriMeshDataBuildSingle1(dTriMeshDataID g, const void *Vertices,
                                          int VertexStride, int VertexCount,
                                          const void *Indices, int IndexCount, int TriStride,
                                          const void *Normals);
ODE_API void dGeomTriMeshDataBuildDouble(dTriMeshDataID g, const void *Vertices,
                                         int VertexStride, int VertexCount,
                                         const void *Indices, int IndexCount, int TriStride);
ODE_API void dGeomTriMeshDataBuildDouble1(dTriMeshDataID g, const void *Vertices,
                                          int VertexStride, int VertexCount,
                                          const void *Indices, int IndexCount, int TriStride,
                                          const void *Normals);
/* dReal vertices with the stride of a dVector3 (4 dReal), packed triangles. */
ODE_API void dGeomTriMeshDataBuildSimple(dTriMeshDataID g, const dReal *Vertices,
                                         int VertexCount, const dTriIndex *Indices,
                                         int IndexCount);
ODE_API void dGeomTriMeshDataBuildSimple1(dTriMeshDataID g, const dReal *Vertices,
                                          int VertexCount, const dTriIndex *Indices,
                                          int IndexCount, const int *Normals);

/* Preprocess requests: bit (1U << value) of buildRequestFlags. */
enum {
    dTRIDATAPREPROCESS_BUILD__MIN,
    dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES = dTRIDATAPREPROCESS_BUILD__MIN,
    dTRIDATAPREPROCESS_BUILD_FACE_ANGLES,
    dTRIDATAPREPROCESS_BUILD__MAX
};

/* Storage of the face angles (extra data of dTRIDATAPREPROCESS_BUILD_FACE_ANGLES). */
enum {
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__MIN,
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_BYTE_POSITIVE =
        dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__MIN,
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_BYTE_ALL,
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_WORD_ALL,
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__MAX,
    dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA__DEFAULT =
        dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_BYTE_POSITIVE
};

/** Fill the use-flags (CONCAVE_EDGES) and/or the per-edge face angles
 *  (FACE_ANGLES) from the built data. The colliders do not need it: they use
 *  the edge data built with the mesh. Returns 1 (0 only if out of memory or
 *  given bad flags). */
ODE_API int dGeomTriMeshDataPreprocess2(dTriMeshDataID g, unsigned int buildRequestFlags,
                                        const dintptr *requestExtraData);
/** dGeomTriMeshDataPreprocess2(g, 1U << dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES, NULL). */
ODE_API int dGeomTriMeshDataPreprocess(dTriMeshDataID g);
/* The use-flags buffer (deprecated forms of Get2 / Set with USE_FLAGS). */
ODE_API_DEPRECATED ODE_API void dGeomTriMeshDataGetBuffer(dTriMeshDataID g, unsigned char **buf,
                                                          int *bufLen);
ODE_API_DEPRECATED ODE_API void dGeomTriMeshDataSetBuffer(dTriMeshDataID g, unsigned char *buf);

/** Per-triangle callback, asked for each triangle near the other geom before it
 *  is tested (for rays, for each hit after the ray callback): return 0 to
 *  ignore the triangle for this pair. */
typedef int dTriCallback(dGeomID TriMesh, dGeomID RefObject, int TriangleIndex);
ODE_API void dGeomTriMeshSetCallback(dGeomID g, dTriCallback *Callback);
ODE_API dTriCallback *dGeomTriMeshGetCallback(dGeomID g);

/** Called once per collision with every triangle that touches the other geom (of
 *  those the per-triangle callback let through); not for rays. */
typedef void dTriArrayCallback(dGeomID TriMesh, dGeomID RefObject, const int *TriIndices,
                               int TriCount);
ODE_API void dGeomTriMeshSetArrayCallback(dGeomID g, dTriArrayCallback *ArrayCallback);
ODE_API dTriArrayCallback *dGeomTriMeshGetArrayCallback(dGeomID g);

/** Ray callback: the hit is (1 - u - v) v0 + u v1 + v v2; return 0 to ignore it. */
typedef int dTriRayCallback(dGeomID TriMesh, dGeomID Ray, int TriangleIndex, dReal u,
                            dReal v);
ODE_API void dGeomTriMeshSetRayCallback(dGeomID g, dTriRayCallback *Callback);
ODE_API dTriRayCallback *dGeomTriMeshGetRayCallback(dGeomID g);

/** Gives the triangle index (side) of a contact merged from contacts of two
 *  triangles; without it such a contact has side -1. */
typedef int dTriTriMergeCallback(dGeomID TriMesh, int FirstTriangleIndex,
                                 int SecondTriangleIndex);
ODE_API void dGeomTriMeshSetTriMergeCallback(dGeomID g, dTriTriMergeCallback *Callback);
ODE_API dTriTriMergeCallback *dGeomTriMeshGetTriMergeCallback(dGeomID g);

/** A trimesh geom on Data (may be NULL: set it later); callbacks are optional. */
ODE_API dGeomID dCreateTriMesh(dSpaceID space, dTriMeshDataID Data, dTriCallback *Callback,
                               dTriArrayCallback *ArrayCallback, dTriRayCallback *RayCallback);
ODE_API void dGeomTriMeshSetData(dGeomID g, dTriMeshDataID Data);
ODE_API dTriMeshDataID dGeomTriMeshGetData(dGeomID g);

/* Temporal coherence: the settings are kept; contacts never depend on them. */
ODE_API void dGeomTriMeshEnableTC(dGeomID g, int geomClass, int enable);
ODE_API int dGeomTriMeshIsTCEnabled(dGeomID g, int geomClass);
ODE_API void dGeomTriMeshClearTCCache(dGeomID g);

ODE_API dTriMeshDataID dGeomTriMeshGetTriMeshDataID(dGeomID g);

/** The vertices of triangle Index in world coordinates (any of v0, v1, v2 may be NULL). */
ODE_API void dGeomTriMeshGetTriangle(dGeomID g, int Index, dVector3 *v0, dVector3 *v1,
                                     dVector3 *v2);
/** (1 - u - v) v0 + u v1 + v v2 of triangle Index, in world coordinates. */
ODE_API void dGeomTriMeshGetPoint(dGeomID g, int Index, dReal u, dReal v, dVector3 Out);
ODE_API int dGeomTriMeshGetTriangleCount(dGeomID g);

/** The vertices moved (same counts and indices): normals, edges and the tree
 *  are recomputed from them. */
ODE_API void dGeomTriMeshDataUpdate(dTriMeshDataID g);

#ifdef __cplusplus
}
#endif

#endif
