// SPDX-License-Identifier: BSD-3-Clause
//
// camera.c -- the viewpoint: position and heading/pitch/roll in degrees,
// set by the program or dragged with the mouse, and the GL view transform.

#include "ds_internal.h"

#include <GL/gl.h>
#include <math.h>

// Keeps each angle in (-180, 180].
static void wrap_angles(void)
{
    for (int i = 0; i < 3; i++) {
        float a = fmodf(dxDs.view_hpr[i], 360.0f);
        if (a > 180.0f) a -= 360.0f;
        if (a <= -180.0f) a += 360.0f;
        dxDs.view_hpr[i] = a;
    }
}

// The viewpoint at the start of every loop: 2 m along x, 1 m up, looking
// back at the origin.
void dxDsCameraReset(void)
{
    dxDs.view_xyz[0] = 2.0f;
    dxDs.view_xyz[1] = 0.0f;
    dxDs.view_xyz[2] = 1.0f;
    dxDs.view_hpr[0] = 180.0f;
    dxDs.view_hpr[1] = 0.0f;
    dxDs.view_hpr[2] = 0.0f;
}

void dsSetViewpoint(const float xyz[3], const float hpr[3])
{
    if (dxDs.phase == DX_DS_IDLE) dsError("dsSetViewpoint() called before simulation started");
    for (int i = 0; i < 3; i++) {
        if (xyz) dxDs.view_xyz[i] = xyz[i];
        if (hpr) dxDs.view_hpr[i] = hpr[i];
    }
    wrap_angles();
}

void dsGetViewpoint(float xyz[3], float hpr[3])
{
    if (dxDs.phase == DX_DS_IDLE) dsError("dsGetViewpoint() called before simulation started");
    for (int i = 0; i < 3; i++) {
        if (xyz) xyz[i] = dxDs.view_xyz[i];
        if (hpr) hpr[i] = dxDs.view_hpr[i];
    }
}

// A mouse drag of (dx, dy) pixels (y down): TURN changes heading and pitch by
// half a degree per pixel; MOVE goes sideways and forward, LIFT sideways and
// up, a centimetre per pixel, sideways and forward relative to the heading.
void dxDsCameraDrag(int mode, double dx, double dy)
{
    if (mode == DX_DS_DRAG_TURN) {
        dxDs.view_hpr[0] += (float)(0.5 * dx);
        dxDs.view_hpr[1] += (float)(0.5 * dy);
    } else {
        double h = dxDs.view_hpr[0] * (DX_DS_PI / 180.0);
        double side = 0.01 * dx, forward = mode == DX_DS_DRAG_MOVE ? 0.01 * dy : 0.0;
        dxDs.view_xyz[0] += (float)(-sin(h) * side + cos(h) * forward);
        dxDs.view_xyz[1] += (float)(cos(h) * side + sin(h) * forward);
        if (mode == DX_DS_DRAG_LIFT) dxDs.view_xyz[2] += (float)(0.01 * dy);
    }
    wrap_angles();
}

// Loads the view transform into GL's modelview matrix. GL's eye looks down
// its -z with y up; ours looks along +x (heading 0) with z up: the first two
// rotations map one onto the other, then roll, pitch and heading are undone
// and the eye moved to the origin.
void dxDsCameraApply(void)
{
    const float *p = dxDs.view_xyz, *a = dxDs.view_hpr;
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    glRotatef(90.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(a[2], 1.0f, 0.0f, 0.0f);
    glRotatef(a[1], 0.0f, 1.0f, 0.0f);
    glRotatef(-a[0], 0.0f, 0.0f, 1.0f);
    glTranslatef(-p[0], -p[1], -p[2]);
}
