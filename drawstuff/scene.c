// SPDX-License-Identifier: BSD-3-Clause
//
// scene.c -- one frame of the scene shared by the window and the offscreen
// renderer: projection, light, sky, ground and its markers, then the
// program's step function; and the drawing state the step function sets
// (colour, texture, draw mode, shadows, textures).

#include "ds_internal.h"

#include <GL/gl.h>

dxDsState dxDs = {
    .phase = DX_DS_IDLE,
    .textures = 1,
    .shadows = 1,
    .color = { 1.0f, 1.0f, 1.0f, 1.0f },
    .sphere_quality = 1,
    .capsule_quality = 3,
};

// GL state that stays for the whole run.
void dxDsSceneInit(void)
{
    static const GLfloat ambient[4] = { 0.5f, 0.5f, 0.5f, 1.0f };
    static const GLfloat diffuse[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    static const GLfloat specular[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
    glEnable(GL_LIGHT0);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
    dxDsTexturesCreate();
}

// A perspective view VIEW_SCALE wide (each side, at distance 1) along the
// longer side of the image.
static void set_projection(int width, int height)
{
    float kx = DX_DS_NEAR * DX_DS_VIEW_SCALE, ky = kx;
    if (width >= height) ky *= (float)height / (float)width;
    else kx *= (float)width / (float)height;
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-kx, kx, -ky, ky, DX_DS_NEAR, DX_DS_FAR);
    glMatrixMode(GL_MODELVIEW);
}

// Lighting, texturing and depth test as the background wants them.
static void background_mode(int texture, float r, float g, float b)
{
    glDisable(GL_LIGHTING);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    if (dxDs.textures) {
        glEnable(GL_TEXTURE_2D);
        dxDsTextureBind(texture);
        glColor3f(1.0f, 1.0f, 1.0f);
    } else {
        glDisable(GL_TEXTURE_2D);
        glColor3f(r, g, b);
    }
}

// The sky: a plane a metre above the eye, facing down, drawn at the far
// depth so everything else is in front of it; its texture drifts.
static void draw_sky(void)
{
    const float half = 1000.0f, tiles = half / 4.0f, off = dxDs.sky_offset;
    const float *eye = dxDs.view_xyz;
    float z = eye[2] + 1.0f;
    background_mode(DS_SKY, DX_DS_SKY_R, DX_DS_SKY_G, DX_DS_SKY_B);
    glDepthFunc(GL_LEQUAL);
    glDepthRange(1.0, 1.0);
    glBegin(GL_QUADS);
    glTexCoord2f(off - tiles, off - tiles);
    glVertex3f(eye[0] - half, eye[1] - half, z);
    glTexCoord2f(off - tiles, off + tiles);
    glVertex3f(eye[0] - half, eye[1] + half, z);
    glTexCoord2f(off + tiles, off + tiles);
    glVertex3f(eye[0] + half, eye[1] + half, z);
    glTexCoord2f(off + tiles, off - tiles);
    glVertex3f(eye[0] + half, eye[1] - half, z);
    glEnd();
    glDepthRange(0.0, 1.0);
    glDepthFunc(GL_LESS);
    dxDs.sky_offset += 0.002f;
    if (dxDs.sky_offset > 1.0f) dxDs.sky_offset -= 1.0f;
}

// The ground: the plane z = 0, 200 m square, one texture tile per metre.
static void draw_ground(void)
{
    const float half = 100.0f, s = DX_DS_GROUND_SCALE, o = DX_DS_GROUND_OFFSET;
    static const float corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    background_mode(DS_GROUND, DX_DS_GROUND_R, DX_DS_GROUND_G, DX_DS_GROUND_B);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++) {
        float x = corners[i][0] * half, y = corners[i][1] * half;
        glTexCoord2f(x * s + o, y * s + o);
        glVertex3f(x, y, 0.0f);
    }
    glEnd();
}

// Sets the lit material for colour (r, g, b, a).
static void set_material(const float *c)
{
    GLfloat ambient[4], diffuse[4], specular[4];
    for (int i = 0; i < 3; i++) {
        ambient[i] = 0.3f * c[i];
        diffuse[i] = 0.7f * c[i];
        specular[i] = 0.2f * c[i];
    }
    ambient[3] = diffuse[3] = specular[3] = c[3];
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 5.0f);
}

// Small pyramids on the ground at the integer points around the origin:
// red on +x, blue on +y, yellow elsewhere, to show where the axes are.
static void draw_markers(void)
{
    static const float red[4] = { 1, 0, 0, 1 }, blue[4] = { 0, 0, 1, 1 },
                       yellow[4] = { 1, 1, 0, 1 };
    const float k = 0.03f;
    glEnable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            set_material(i == 1 && j == 0 ? red : i == 0 && j == 1 ? blue : yellow);
            float x = (float)i, y = (float)j;
            static const float base[5][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 },
                                              { -1, -1 } };
            glBegin(GL_TRIANGLES);
            for (int e = 0; e < 4; e++) {
                float nx = base[e][0] + base[e + 1][0], ny = base[e][1] + base[e + 1][1];
                glNormal3f(0.5f * nx, 0.5f * ny, 1.0f);
                glVertex3f(x + k * base[e][0], y + k * base[e][1], 0.0f);
                glVertex3f(x + k * base[e + 1][0], y + k * base[e + 1][1], 0.0f);
                glVertex3f(x, y, k);
            }
            glEnd();
        }
    }
}

void dxDsFrameDraw(int width, int height, dsFunctions *fn, int pause)
{
    set_projection(width, height);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    dxDsCameraApply();
    // A directional light (w = 0), placed in world coordinates.
    static const GLfloat light[4] = { DX_DS_LIGHT_X, DX_DS_LIGHT_Y, 1.0f, 0.0f };
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    // Shadows take the ground's texture coordinates from world x and y: eye
    // planes given under the view transform are world planes.
    const GLfloat s_plane[4] = { DX_DS_GROUND_SCALE, 0, 0, DX_DS_GROUND_OFFSET };
    const GLfloat t_plane[4] = { 0, DX_DS_GROUND_SCALE, 0, DX_DS_GROUND_OFFSET };
    glTexGenfv(GL_S, GL_EYE_PLANE, s_plane);
    glTexGenfv(GL_T, GL_EYE_PLANE, t_plane);

    draw_sky();
    draw_ground();
    draw_markers();

    dxDs.color[0] = dxDs.color[1] = dxDs.color[2] = dxDs.color[3] = 1.0f;
    dxDs.texture = DS_NONE;
    dxDs.phase = DX_DS_DRAWING;
    if (fn->step) fn->step(pause);
    dxDs.phase = DX_DS_RUNNING;
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

void dxDsRequireDrawing(const char *function)
{
    if (dxDs.phase != DX_DS_DRAWING)
        dsError("%s() called outside the simulation loop's step function", function);
}

// Before a shape: lit in the current colour, textured if asked, blended
// when not opaque, filled or wireframe.
void dxDsShapeMode(void)
{
    glEnable(GL_LIGHTING);
    if (dxDs.texture != DS_NONE && dxDs.textures) {
        // Object-linear coordinates: the texture is fixed to the shape.
        static const GLfloat s_plane[4] = { 1.0f, 0.7f, 0.0f, 0.0f };
        static const GLfloat t_plane[4] = { 0.0f, 0.6f, 0.9f, 0.0f };
        glEnable(GL_TEXTURE_2D);
        dxDsTextureBind(dxDs.texture);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glTexGenfv(GL_S, GL_OBJECT_PLANE, s_plane);
        glTexGenfv(GL_T, GL_OBJECT_PLANE, t_plane);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
    } else {
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
    }
    set_material(dxDs.color);
    if (dxDs.color[3] < 1.0f) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else {
        glDisable(GL_BLEND);
    }
    glPolygonMode(GL_FRONT_AND_BACK, dxDs.draw_mode == DS_WIREFRAME ? GL_LINE : GL_FILL);
}

// Before a shadow: the shape is flattened onto z = 0 along the light, drawn
// as darkened ground (the ground's texture at the same place), a little in
// front of the ground in depth. Pushes a matrix; dxDsShadowModeEnd pops it.
void dxDsShadowMode(void)
{
    const float shade = DX_DS_SHADOW_INTENSITY;
    glDisable(GL_LIGHTING);
    glDisable(GL_BLEND);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    if (dxDs.textures) {
        glEnable(GL_TEXTURE_2D);
        dxDsTextureBind(DS_GROUND);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glColor3f(shade, shade, shade);
    } else {
        glDisable(GL_TEXTURE_2D);
        glColor3f(DX_DS_GROUND_R * shade, DX_DS_GROUND_G * shade, DX_DS_GROUND_B * shade);
    }
    glDepthRange(0.0, 0.9999);
    // (x, y, z) -> (x - Lx z, y - Ly z, 0), column-major.
    const GLfloat flatten[16] = { 1, 0, 0, 0, 0, 1, 0, 0,
                                  -DX_DS_LIGHT_X, -DX_DS_LIGHT_Y, 0, 0, 0, 0, 0, 1 };
    glPushMatrix();
    glMultMatrixf(flatten);
}

void dxDsShadowModeEnd(void)
{
    glPopMatrix();
    glDepthRange(0.0, 1.0);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
}

// Stores the drawing colour for the shapes that follow.
static void set_color(const char *function, float r, float g, float b, float a)
{
    dxDsRequireDrawing(function);
    dxDs.color[0] = r;
    dxDs.color[1] = g;
    dxDs.color[2] = b;
    dxDs.color[3] = a;
}

void dsSetColor(float red, float green, float blue)
{
    set_color("dsSetColor", red, green, blue, 1.0f);
}

void dsSetColorAlpha(float red, float green, float blue, float alpha)
{
    set_color("dsSetColorAlpha", red, green, blue, alpha);
}

void dsSetTexture(int texture_number)
{
    dxDsRequireDrawing("dsSetTexture");
    if (texture_number < DS_NONE || texture_number > DS_SKY) {
        dxDsWarn("dsSetTexture: no texture %d (DS_NONE..DS_SKY), ignored", texture_number);
        return;
    }
    dxDs.texture = texture_number;
}

void dsSetDrawMode(int mode)
{
    if (mode != DS_POLYFILL && mode != DS_WIREFRAME) {
        dxDsWarn("dsSetDrawMode: mode %d is neither DS_POLYFILL nor DS_WIREFRAME, ignored",
                 mode);
        return;
    }
    dxDs.draw_mode = mode;
}

int dsGetShadows(void)
{
    return dxDs.shadows;
}

void dsSetShadows(int a)
{
    dxDs.shadows = a != 0;
}

int dsGetTextures(void)
{
    return dxDs.textures;
}

void dsSetTextures(int a)
{
    dxDs.textures = a != 0;
}
