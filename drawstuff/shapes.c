// SPDX-License-Identifier: BSD-3-Clause
//
// shapes.c -- the dsDraw* functions taking floats, the tessellation
// settings, and what every shape shares: pose, lit pass and shadow pass.

#include "ds_internal.h"
#include "shapes.h"

#include <GL/gl.h>

// Sphere quality q draws 20 * 4^q triangles, capsule quality q 4q segments.
#define MAX_SPHERE_QUALITY 5
#define MAX_CAPSULE_QUALITY 16

void dxDsPoseFloat(float m[16], const float pos[3], const float R[12])
{
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++) m[4 * col + row] = R[4 * row + col];
        m[12 + row] = pos[row];
        m[4 * row + 3] = 0.0f;
    }
    m[15] = 1.0f;
}

void dxDsPoseDouble(float m[16], const double pos[3], const double R[12])
{
    float p[3], r[12];
    for (int i = 0; i < 3; i++) p[i] = (float)pos[i];
    for (int i = 0; i < 12; i++) r[i] = (float)R[i];
    dxDsPoseFloat(m, p, r);
}

void dxDsRequireArg(const void *p, const char *function, const char *arg)
{
    if (!p) dsError("%s(): %s is NULL", function, arg);
}

void dxDsDrawShape(const float m[16], dxDsGeometry *geometry, const dxDsShape *s, int smooth)
{
    dxDsShapeMode();
    glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);
    glPushMatrix();
    glMultMatrixf(m);
    geometry(s);
    glPopMatrix();
    if (!dxDs.shadows) return;
    dxDsShadowMode();
    glMultMatrixf(m);
    geometry(s);
    dxDsShadowModeEnd();
}

void dxDsDrawSegment(const float a[3], const float b[3])
{
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glLineWidth(2.0f);
    glShadeModel(GL_FLAT);
    glColor4fv(dxDs.color);
    glBegin(GL_LINES);
    glVertex3fv(a);
    glVertex3fv(b);
    glEnd();
    if (dxDs.shadows) {
        dxDsShadowMode();
        glBegin(GL_LINES);
        glVertex3fv(a);
        glVertex3fv(b);
        glEnd();
        dxDsShadowModeEnd();
    }
    glLineWidth(1.0f);
}

// Checks a shape's pose arguments; returns its matrix in m.
static void pose(float m[16], const char *function, const float pos[3], const float R[12])
{
    dxDsRequireDrawing(function);
    dxDsRequireArg(pos, function, "pos");
    dxDsRequireArg(R, function, "R");
    dxDsPoseFloat(m, pos, R);
}

void dsDrawBox(const float pos[3], const float R[12], const float sides[3])
{
    float m[16];
    pose(m, "dsDrawBox", pos, R);
    dxDsRequireArg(sides, "dsDrawBox", "sides");
    dxDsShape s = { .size = { sides[0], sides[1], sides[2] } };
    dxDsDrawShape(m, dxDsBoxGeometry, &s, 0);
}

void dsDrawSphere(const float pos[3], const float R[12], float radius)
{
    float m[16];
    pose(m, "dsDrawSphere", pos, R);
    dxDsShape s = { .size = { radius } };
    dxDsDrawShape(m, dxDsSphereGeometry, &s, 1);
}

void dsDrawCylinder(const float pos[3], const float R[12], float length, float radius)
{
    float m[16];
    pose(m, "dsDrawCylinder", pos, R);
    dxDsShape s = { .size = { radius, length } };
    dxDsDrawShape(m, dxDsCylinderGeometry, &s, 1);
}

void dsDrawCapsule(const float pos[3], const float R[12], float length, float radius)
{
    float m[16];
    pose(m, "dsDrawCapsule", pos, R);
    dxDsShape s = { .size = { radius, length } };
    dxDsDrawShape(m, dxDsCapsuleGeometry, &s, 1);
}

void dsDrawTriangle(const float pos[3], const float R[12], const float *v0, const float *v1,
                    const float *v2, int solid)
{
    float m[16];
    pose(m, "dsDrawTriangle", pos, R);
    dxDsRequireArg(v0, "dsDrawTriangle", "v0");
    dxDsRequireArg(v1, "dsDrawTriangle", "v1");
    dxDsRequireArg(v2, "dsDrawTriangle", "v2");
    float v[9];
    for (int i = 0; i < 3; i++) {
        v[i] = v0[i];
        v[3 + i] = v1[i];
        v[6 + i] = v2[i];
    }
    dxDsShape s = { .v = v, .n = 1, .solid = solid };
    dxDsDrawShape(m, dxDsTrianglesGeometry, &s, 0);
}

void dsDrawTriangles(const float pos[3], const float R[12], const float *v, const int n,
                     int solid)
{
    float m[16];
    pose(m, "dsDrawTriangles", pos, R);
    if (n <= 0) return;
    dxDsRequireArg(v, "dsDrawTriangles", "v");
    dxDsShape s = { .v = v, .n = n, .solid = solid };
    dxDsDrawShape(m, dxDsTrianglesGeometry, &s, 0);
}

void dsDrawConvex(const float pos[3], const float R[12], const float *_planes,
                  unsigned int _planecount, const float *_points, unsigned int _pointcount,
                  const unsigned int *_polygons)
{
    float m[16];
    pose(m, "dsDrawConvex", pos, R);
    if (_planecount == 0) return;
    dxDsRequireArg(_planes, "dsDrawConvex", "_planes");
    dxDsRequireArg(_points, "dsDrawConvex", "_points");
    dxDsRequireArg(_polygons, "dsDrawConvex", "_polygons");
    dxDsShape s = { .planes = _planes, .planecount = _planecount, .points = _points,
                    .pointcount = _pointcount, .polygons = _polygons };
    dxDsCheckConvex(&s, "dsDrawConvex");
    dxDsDrawShape(m, dxDsConvexGeometry, &s, 0);
}

void dsDrawLine(const float pos1[3], const float pos2[3])
{
    dxDsRequireDrawing("dsDrawLine");
    dxDsRequireArg(pos1, "dsDrawLine", "pos1");
    dxDsRequireArg(pos2, "dsDrawLine", "pos2");
    dxDsDrawSegment(pos1, pos2);
}

// A tessellation level from lo to hi; anything else is reported and the
// previous level kept.
static void set_quality(int *quality, int n, int lo, int hi, const char *function)
{
    if (n < lo || n > hi) {
        dxDsWarn("%s: quality %d is outside %d..%d, kept %d", function, n, lo, hi, *quality);
        return;
    }
    *quality = n;
}

void dsSetSphereQuality(int n)
{
    set_quality(&dxDs.sphere_quality, n, 0, MAX_SPHERE_QUALITY, "dsSetSphereQuality");
}

void dsSetCapsuleQuality(int n)
{
    set_quality(&dxDs.capsule_quality, n, 1, MAX_CAPSULE_QUALITY, "dsSetCapsuleQuality");
}
