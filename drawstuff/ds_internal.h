// SPDX-License-Identifier: BSD-3-Clause
//
// ds_internal.h -- state and functions shared by drawstuff's files (never
// installed). One viewer per process, as ODE's: the state is a single global.

#ifndef DS_INTERNAL_H
#define DS_INTERNAL_H

#include <drawstuff/drawstuff.h>

#define DX_DS_PI 3.14159265358979323846

// Light direction (towards the light) in the xy plane, the light's z being 1;
// shadows are the shapes projected along it onto z = 0.
#define DX_DS_LIGHT_X 1.0f
#define DX_DS_LIGHT_Y 0.4f
// Ground colour without textures, and how much shadows darken the ground.
#define DX_DS_GROUND_R 0.5f
#define DX_DS_GROUND_G 0.5f
#define DX_DS_GROUND_B 0.3f
#define DX_DS_SHADOW_INTENSITY 0.65f
// Sky colour without textures.
#define DX_DS_SKY_R 0.0f
#define DX_DS_SKY_G 0.5f
#define DX_DS_SKY_B 1.0f
// Ground texture: one tile per metre, offset half a tile.
#define DX_DS_GROUND_SCALE 1.0f
#define DX_DS_GROUND_OFFSET 0.5f
// Projection: near and far planes, half-width of the view at distance 1.
#define DX_DS_NEAR 0.1f
#define DX_DS_FAR 100.0f
#define DX_DS_VIEW_SCALE 0.8f
// Frames per second of the window's real-time pacing.
#define DX_DS_FPS 60.0
// Frames a headless run draws when not told.
#define DX_DS_DEFAULT_FRAMES 300

// Where the loop is: dsSimulationLoop not running, running, or inside a
// frame (the step function may draw).
enum dxDsPhase { DX_DS_IDLE, DX_DS_RUNNING, DX_DS_DRAWING };

// What the command line and environment ask for.
typedef struct dxDsOptions {
    int textures;        // 0 for -notex
    int shadows;         // 0 for -noshadow(s)
    int pause;           // 1 for -pause
    int headless;        // 1 for -headless or DS_HEADLESS=1
    long frames;         // -frames / DS_FRAMES, or -1: not given
    const char *png;     // -png / DS_PNG: write the last frame there
    const char *record;  // -record / DS_RECORD: write every frame there
    const char *keys;    // -keys / DS_KEYS: typed, one per frame, from frame 1
    int width, height;   // -size WxH / DS_SIZE: the window or image size, or 0: the program's
} dxDsOptions;

typedef struct dxDsState {
    enum dxDsPhase phase;
    int textures, shadows;       // the Ctrl-T / Ctrl-S switches
    float color[4];              // current drawing colour and opacity
    int texture;                 // current DS_ texture
    int draw_mode;               // DS_POLYFILL or DS_WIREFRAME
    int sphere_quality, capsule_quality;
    float view_xyz[3], view_hpr[3];
    int run;                     // cleared by dsStop, Ctrl-X, window close
    int paused, single_step;     // Ctrl-P, Ctrl-O
    int write_frames;            // Ctrl-W
    float sky_offset;            // the sky's drift, a little each frame
} dxDsState;

extern dxDsState dxDs;

// report.c: a warning on stderr for a bad argument that is ignored.
void dxDsWarn(const char *msg, ...);

// options.c: reads argv and DS_* environment variables.
void dxDsOptionsParse(dxDsOptions *opt, int argc, char **argv);

// camera.c: the default viewpoint, mouse motion, and the GL view transform.
void dxDsCameraReset(void);
enum { DX_DS_DRAG_TURN = 1, DX_DS_DRAG_MOVE = 2, DX_DS_DRAG_LIFT = 3 };
void dxDsCameraDrag(int mode, double dx, double dy);
void dxDsCameraApply(void);

// keys.c: a key typed in the window (ctrl: Ctrl was held).
void dxDsKey(int key, int ctrl, dsFunctions *fn);

// textures.c: the procedural textures, in GL (needs a current context).
void dxDsTexturesCreate(void);
void dxDsTexturesDestroy(void);
void dxDsTextureBind(int texture);

// scene.c: one frame: projection, light, sky, ground, then the step function.
void dxDsFrameDraw(int width, int height, dsFunctions *fn, int pause);
void dxDsSceneInit(void);
// Shape drawing modes: lit in the current colour and texture, or as a shadow.
void dxDsShapeMode(void);
void dxDsShadowMode(void);
void dxDsShadowModeEnd(void);
void dxDsRequireDrawing(const char *function);

// frames.c: writing frames as PNG. dxDsPngWrite writes what GL's read
// buffer holds; dxDsReadPixels reads it into rgb (reallocated, bottom row
// first; NULL if out of memory) for dxDsPngWriteRgb to write later.
int dxDsPngWrite(const char *path, int width, int height);
unsigned char *dxDsReadPixels(unsigned char *rgb, int width, int height);
int dxDsPngWriteRgb(const char *path, const unsigned char *rgb, int width, int height);
int dxDsRecordFrame(const char *dir, long number, int width, int height);

// window.c, headless.c: the two loops. window returns 0 when no window could
// be opened (no display), before calling anything of the program's.
int dxDsWindowLoop(int width, int height, dsFunctions *fn, const dxDsOptions *opt);
void dxDsHeadlessLoop(int width, int height, dsFunctions *fn, const dxDsOptions *opt);

// loop.c: draws one frame and writes it where the options say; called by
// both loops. frame counts from 1.
void dxDsFrame(int width, int height, dsFunctions *fn, const dxDsOptions *opt, long frame);
// The banner ODE prints: keys and mouse.
void dxDsPrintHelp(void);

#endif
