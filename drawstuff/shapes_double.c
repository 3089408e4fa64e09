// SPDX-License-Identifier: BSD-3-Clause
//
// shapes_double.c -- the dsDraw*D functions: the same shapes with positions,
// rotations and vertices given as doubles (what dReal is in double builds).

#include "ds_internal.h"
#include "shapes.h"

// Checks a shape's pose arguments; returns its matrix in m.
static void pose(float m[16], const char *function, const double pos[3], const double R[12])
{
    dxDsRequireDrawing(function);
    dxDsRequireArg(pos, function, "pos");
    dxDsRequireArg(R, function, "R");
    dxDsPoseDouble(m, pos, R);
}

void dsDrawBoxD(const double pos[3], const double R[12], const double sides[3])
{
    float m[16];
    pose(m, "dsDrawBoxD", pos, R);
    dxDsRequireArg(sides, "dsDrawBoxD", "sides");
    dxDsShape s = { .size = { (float)sides[0], (float)sides[1], (float)sides[2] } };
    dxDsDrawShape(m, dxDsBoxGeometry, &s, 0);
}

void dsDrawSphereD(const double pos[3], const double R[12], const float radius)
{
    float m[16];
    pose(m, "dsDrawSphereD", pos, R);
    dxDsShape s = { .size = { radius } };
    dxDsDrawShape(m, dxDsSphereGeometry, &s, 1);
}

void dsDrawCylinderD(const double pos[3], const double R[12], float length, float radius)
{
    float m[16];
    pose(m, "dsDrawCylinderD", pos, R);
    dxDsShape s = { .size = { radius, length } };
    dxDsDrawShape(m, dxDsCylinderGeometry, &s, 1);
}

void dsDrawCapsuleD(const double pos[3], const double R[12], float length, float radius)
{
    float m[16];
    pose(m, "dsDrawCapsuleD", pos, R);
    dxDsShape s = { .size = { radius, length } };
    dxDsDrawShape(m, dxDsCapsuleGeometry, &s, 1);
}

void dsDrawTriangleD(const double pos[3], const double R[12], const double *v0,
                     const double *v1, const double *v2, int solid)
{
    float m[16];
    pose(m, "dsDrawTriangleD", pos, R);
    dxDsRequireArg(v0, "dsDrawTriangleD", "v0");
    dxDsRequireArg(v1, "dsDrawTriangleD", "v1");
    dxDsRequireArg(v2, "dsDrawTriangleD", "v2");
    double v[9];
    for (int i = 0; i < 3; i++) {
        v[i] = v0[i];
        v[3 + i] = v1[i];
        v[6 + i] = v2[i];
    }
    dxDsShape s = { .v = v, .n = 1, .solid = solid, .is_double = 1 };
    dxDsDrawShape(m, dxDsTrianglesGeometry, &s, 0);
}

void dsDrawTrianglesD(const double pos[3], const double R[12], const double *v, const int n,
                      int solid)
{
    float m[16];
    pose(m, "dsDrawTrianglesD", pos, R);
    if (n <= 0) return;
    dxDsRequireArg(v, "dsDrawTrianglesD", "v");
    dxDsShape s = { .v = v, .n = n, .solid = solid, .is_double = 1 };
    dxDsDrawShape(m, dxDsTrianglesGeometry, &s, 0);
}

void dsDrawConvexD(const double pos[3], const double R[12], const double *_planes,
                   unsigned int _planecount, const double *_points, unsigned int _pointcount,
                   const unsigned int *_polygons)
{
    float m[16];
    pose(m, "dsDrawConvexD", pos, R);
    if (_planecount == 0) return;
    dxDsRequireArg(_planes, "dsDrawConvexD", "_planes");
    dxDsRequireArg(_points, "dsDrawConvexD", "_points");
    dxDsRequireArg(_polygons, "dsDrawConvexD", "_polygons");
    dxDsShape s = { .planes = _planes, .planecount = _planecount, .points = _points,
                    .pointcount = _pointcount, .polygons = _polygons, .is_double = 1 };
    dxDsCheckConvex(&s, "dsDrawConvexD");
    dxDsDrawShape(m, dxDsConvexGeometry, &s, 0);
}

void dsDrawLineD(const double pos1[3], const double pos2[3])
{
    dxDsRequireDrawing("dsDrawLineD");
    dxDsRequireArg(pos1, "dsDrawLineD", "pos1");
    dxDsRequireArg(pos2, "dsDrawLineD", "pos2");
    float a[3] = { (float)pos1[0], (float)pos1[1], (float)pos1[2] };
    float b[3] = { (float)pos2[0], (float)pos2[1], (float)pos2[2] };
    dxDsDrawSegment(a, b);
}
