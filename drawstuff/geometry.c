// SPDX-License-Identifier: BSD-3-Clause
//
// geometry.c -- the shapes' triangles, in the shape's own frame, faces
// counter-clockwise seen from outside, with normals for lighting.

#include "ds_internal.h"
#include "shapes.h"

#include <GL/gl.h>
#include <math.h>

#define CYLINDER_SEGMENTS 24

void dxDsBoxGeometry(const dxDsShape *s)
{
    float h[3] = { 0.5f * s->size[0], 0.5f * s->size[1], 0.5f * s->size[2] };
    // Per face: the axis of its normal and its sign; corners walk
    // counter-clockwise around that normal.
    glBegin(GL_QUADS);
    for (int axis = 0; axis < 3; axis++) {
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int sign = -1; sign <= 1; sign += 2) {
            static const float walk[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
            float n[3] = { 0, 0, 0 };
            n[axis] = (float)sign;
            glNormal3fv(n);
            for (int k = 0; k < 4; k++) {
                int kk = sign > 0 ? k : 3 - k;
                float p[3];
                p[axis] = (float)sign * h[axis];
                p[u] = walk[kk][0] * h[u];
                p[v] = walk[kk][1] * h[v];
                glVertex3fv(p);
            }
        }
    }
    glEnd();
}

static void normalize(float v[3])
{
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0f)
        for (int i = 0; i < 3; i++) v[i] /= len;
}

// One spherical triangle of unit vectors a, b, c: split `level` times into
// four, then drawn at radius r with the unit vectors as normals.
static void sphere_patch(const float *a, const float *b, const float *c, int level, float r)
{
    if (level > 0) {
        float ab[3], bc[3], ca[3];
        for (int i = 0; i < 3; i++) {
            ab[i] = a[i] + b[i];
            bc[i] = b[i] + c[i];
            ca[i] = c[i] + a[i];
        }
        normalize(ab);
        normalize(bc);
        normalize(ca);
        sphere_patch(a, ab, ca, level - 1, r);
        sphere_patch(ab, b, bc, level - 1, r);
        sphere_patch(ca, bc, c, level - 1, r);
        sphere_patch(ab, bc, ca, level - 1, r);
        return;
    }
    const float *p[3] = { a, b, c };
    for (int k = 0; k < 3; k++) {
        glNormal3fv(p[k]);
        glVertex3f(r * p[k][0], r * p[k][1], r * p[k][2]);
    }
}

// An icosahedron refined sphere_quality times.
void dxDsSphereGeometry(const dxDsShape *s)
{
    // Vertices (0, +-1, +-g) and their cyclic permutations, g the golden ratio.
    const float g = 1.6180340f, k = 1.0f / sqrtf(1.0f + g * g);
    const float a = k, b = g * k;
    const float vtx[12][3] = {
        { -a, b, 0 }, { a, b, 0 }, { -a, -b, 0 }, { a, -b, 0 },
        { 0, -a, b }, { 0, a, b }, { 0, -a, -b }, { 0, a, -b },
        { b, 0, -a }, { b, 0, a }, { -b, 0, -a }, { -b, 0, a },
    };
    static const unsigned char face[20][3] = {
        { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
        { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
        { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
        { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 },
    };
    int level = dxDs.sphere_quality;
    glBegin(GL_TRIANGLES);
    for (int f = 0; f < 20; f++)
        sphere_patch(vtx[face[f][0]], vtx[face[f][1]], vtx[face[f][2]], level, s->size[0]);
    glEnd();
}

// A point of a unit circle of latitude lat (radians) at longitude lon, as
// normal n, and the point r n + (0, 0, z).
static void ring_vertex(float lat, float lon, float r, float z)
{
    float n[3] = { cosf(lat) * cosf(lon), cosf(lat) * sinf(lon), sinf(lat) };
    glNormal3fv(n);
    glVertex3f(r * n[0], r * n[1], r * n[2] + z);
}

// The band between latitudes lo < hi around the z axis, in `segments`
// pieces, points at radius r about (0, 0, z).
static void band(float lo, float hi, int segments, float r, float z)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < segments; i++) {
        float l0 = 2.0f * (float)DX_DS_PI * (float)i / (float)segments;
        float l1 = 2.0f * (float)DX_DS_PI * (float)(i + 1) / (float)segments;
        ring_vertex(hi, l0, r, z);
        ring_vertex(lo, l0, r, z);
        ring_vertex(lo, l1, r, z);
        ring_vertex(hi, l0, r, z);
        ring_vertex(lo, l1, r, z);
        ring_vertex(hi, l1, r, z);
    }
    glEnd();
}

// Side of a cylinder of radius r from z = -h to z = h.
static void tube(float r, float h, int segments)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < segments; i++) {
        float l0 = 2.0f * (float)DX_DS_PI * (float)i / (float)segments;
        float l1 = 2.0f * (float)DX_DS_PI * (float)(i + 1) / (float)segments;
        float c0 = cosf(l0), s0 = sinf(l0), c1 = cosf(l1), s1 = sinf(l1);
        glNormal3f(c0, s0, 0);
        glVertex3f(r * c0, r * s0, h);
        glVertex3f(r * c0, r * s0, -h);
        glNormal3f(c1, s1, 0);
        glVertex3f(r * c1, r * s1, -h);
        glNormal3f(c0, s0, 0);
        glVertex3f(r * c0, r * s0, h);
        glNormal3f(c1, s1, 0);
        glVertex3f(r * c1, r * s1, -h);
        glVertex3f(r * c1, r * s1, h);
    }
    glEnd();
}

// A flat disc of radius r at height z facing +z (up = 1) or -z (up = 0).
static void disc(float r, float z, int up, int segments)
{
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0, up ? 1.0f : -1.0f);
    glVertex3f(0, 0, z);
    for (int i = 0; i <= segments; i++) {
        float l = 2.0f * (float)DX_DS_PI * (float)(up ? i : segments - i) / (float)segments;
        glVertex3f(r * cosf(l), r * sinf(l), z);
    }
    glEnd();
}

// size[0] radius, size[1] length.
void dxDsCylinderGeometry(const dxDsShape *s)
{
    float r = s->size[0], h = 0.5f * s->size[1];
    tube(r, h, CYLINDER_SEGMENTS);
    disc(r, h, 1, CYLINDER_SEGMENTS);
    disc(r, -h, 0, CYLINDER_SEGMENTS);
}

// size[0] radius, size[1] length of the cylinder between the two caps.
void dxDsCapsuleGeometry(const dxDsShape *s)
{
    int segments = 4 * dxDs.capsule_quality, rings = dxDs.capsule_quality;
    float r = s->size[0], h = 0.5f * s->size[1];
    const float quarter = 0.5f * (float)DX_DS_PI;
    tube(r, h, segments);
    for (int j = 0; j < rings; j++) {
        float lo = quarter * (float)j / (float)rings, hi = quarter * (float)(j + 1) / (float)rings;
        band(lo, hi, segments, r, h);
        band(-hi, -lo, segments, r, -h);
    }
}

// Reads number i of an array of floats or doubles.
static float number(const void *array, int is_double, unsigned long i)
{
    return is_double ? (float)((const double *)array)[i] : ((const float *)array)[i];
}

void dxDsTrianglesGeometry(const dxDsShape *s)
{
    for (int t = 0; t < s->n; t++) {
        float p[3][3];
        for (int k = 0; k < 9; k++) p[k / 3][k % 3] = number(s->v, s->is_double, 9ul * t + k);
        float e1[3], e2[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = p[1][i] - p[0][i];
            e2[i] = p[2][i] - p[0][i];
        }
        float n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0] };
        normalize(n);
        glBegin(s->solid ? GL_TRIANGLES : GL_LINE_LOOP);
        glNormal3fv(n);
        for (int k = 0; k < 3; k++) glVertex3fv(p[k]);
        glEnd();
    }
}

void dxDsConvexGeometry(const dxDsShape *s)
{
    unsigned at = 0;
    for (unsigned f = 0; f < s->planecount; f++) {
        unsigned count = s->polygons[at++];
        glBegin(GL_POLYGON);
        glNormal3f(number(s->planes, s->is_double, 4ul * f),
                   number(s->planes, s->is_double, 4ul * f + 1),
                   number(s->planes, s->is_double, 4ul * f + 2));
        for (unsigned k = 0; k < count; k++) {
            unsigned long idx = s->polygons[at++];
            glVertex3f(number(s->points, s->is_double, 3 * idx),
                       number(s->points, s->is_double, 3 * idx + 1),
                       number(s->points, s->is_double, 3 * idx + 2));
        }
        glEnd();
    }
}

void dxDsCheckConvex(const dxDsShape *s, const char *function)
{
    unsigned at = 0;
    for (unsigned f = 0; f < s->planecount; f++) {
        unsigned count = s->polygons[at++];
        for (unsigned k = 0; k < count; k++, at++)
            if (s->polygons[at] >= s->pointcount)
                dsError("%s(): face %u names point %u of %u", function, f, s->polygons[at],
                        s->pointcount);
    }
}
