// SPDX-License-Identifier: BSD-3-Clause
//
// shapes.h -- between the float and double entry points and the geometry:
// a shape's parameters and the function that draws it (never installed).

#ifndef DS_SHAPES_H
#define DS_SHAPES_H

typedef struct dxDsShape dxDsShape;
typedef void dxDsGeometry(const dxDsShape *s);

struct dxDsShape {
    float size[3];               // box sides; radius, length for round shapes
    const void *v;               // triangles: 9 numbers per triangle
    int n;                       // triangle count
    int solid;                   // triangles: filled (1) or outlined (0)
    const void *planes;          // convex: 4 numbers per face
    unsigned planecount;
    const void *points;          // convex: 3 numbers per point
    unsigned pointcount;
    const unsigned *polygons;    // convex: count, then indices, per face
    int is_double;               // v, planes, points hold doubles, else floats
};

dxDsGeometry dxDsBoxGeometry, dxDsSphereGeometry, dxDsCylinderGeometry, dxDsCapsuleGeometry,
    dxDsTrianglesGeometry, dxDsConvexGeometry;

// Draws a shape at the pose m (a column-major GL matrix), then its shadow.
void dxDsDrawShape(const float m[16], dxDsGeometry *geometry, const dxDsShape *s, int smooth);
// A line between two points and its shadow.
void dxDsDrawSegment(const float a[3], const float b[3]);

// Pose matrices from ODE's position and 3x4 row-major rotation.
void dxDsPoseFloat(float m[16], const float pos[3], const float R[12]);
void dxDsPoseDouble(float m[16], const double pos[3], const double R[12]);

// Checks a pointer argument of a drawing function (dsError if NULL).
void dxDsRequireArg(const void *p, const char *function, const char *arg);
// Checks that a convex's face list stays inside its points (dsError if not).
void dxDsCheckConvex(const dxDsShape *s, const char *function);

#endif
