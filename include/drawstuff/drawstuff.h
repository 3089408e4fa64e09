/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * drawstuff.h -- a small viewer for ODE programs, with the API of ODE's own
 * drawstuff library: dsSimulationLoop opens a window (or renders offscreen,
 * see README.md), calls the program's step function once per frame, and the
 * dsDraw* functions draw simple shapes from inside that step function.
 *
 * The world is z-up and the ground is the plane z = 0. Rotation matrices are
 * ODE's: 3 rows of 4 floats (the 4th of each row unused). Mouse: left drag
 * turns the camera (heading, pitch), right drag moves it forward and
 * sideways, middle (or left + right) drag moves it sideways and up.
 */
#ifndef DRAWSTUFF_H
#define DRAWSTUFF_H

#if !defined(DS_API)
#define DS_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

#include <drawstuff/version.h>

/* Textures for dsSetTexture. DS_NONE draws in the current colour alone. */
enum DS_TEXTURE_NUMBER {
    DS_NONE = 0,
    DS_WOOD,
    DS_CHECKERED,
    DS_GROUND,
    DS_SKY
};

/* Drawing modes for dsSetDrawMode. */
#define DS_POLYFILL 0
#define DS_WIREFRAME 1

/* The program's callbacks. */
typedef struct dsFunctions {
    int version;                   /* DS_VERSION */
    /* version 1 */
    void (*start)(void);           /* once, before the first frame */
    void (*step)(int pause);       /* every frame: advance (unless pause) and draw */
    void (*command)(int cmd);      /* a key pressed without Ctrl */
    void (*stop)(void);            /* once, after the last frame */
    /* version 2 */
    const char *path_to_textures;  /* accepted; textures are generated, not loaded */
} dsFunctions;

/* Console set-up and tear-down for programs that do not call
 * dsSimulationLoop (nothing to do on this platform). */
DS_API void dsInitializeConsole(int argc, char **argv);
DS_API void dsFinalizeConsole(void);

#define DS_SIMULATION_DEFAULT_WIDTH 1280
#define DS_SIMULATION_DEFAULT_HEIGHT 720

/* Runs the simulation until the window is closed, Ctrl-X, dsStop() or the
 * frame count is reached. Options in argv: -notex, -noshadow(s), -pause,
 * -texturepath DIR, and ours: -headless, -frames N, -png FILE, -record DIR,
 * -keys KEYS (see README.md). */
DS_API void dsSimulationLoop(int argc, char **argv, int window_width, int window_height,
                             struct dsFunctions *fn);

/* Messages, printf-style, no trailing newline needed. dsError prints
 * "Error: ..." and exits with status 1; dsDebug prints "INTERNAL ERROR: ..."
 * and aborts; dsPrint prints to standard output. */
DS_API void dsError(const char *msg, ...);
DS_API void dsDebug(const char *msg, ...);
DS_API void dsPrint(const char *msg, ...);

/* The camera: position and heading, pitch, roll in degrees (heading 0 looks
 * along +x, pitch 0 at the horizon). Either pointer may be NULL. */
DS_API void dsSetViewpoint(const float xyz[3], const float hpr[3]);
DS_API void dsGetViewpoint(float xyz[3], float hpr[3]);

/* Ends dsSimulationLoop after the current frame. */
DS_API void dsStop(void);

/* Wall-clock seconds since the previous call, within [tiny, 1]. */
DS_API double dsElapsedTime(void);

/* Drawing state, reset to white and DS_NONE at the start of every frame. */
DS_API void dsSetTexture(int texture_number);
DS_API void dsSetColor(float red, float green, float blue);
DS_API void dsSetColorAlpha(float red, float green, float blue, float alpha);

/* Shapes, at pos with rotation R. */
DS_API void dsDrawBox(const float pos[3], const float R[12], const float sides[3]);
DS_API void dsDrawSphere(const float pos[3], const float R[12], float radius);
DS_API void dsDrawTriangle(const float pos[3], const float R[12], const float *v0,
                           const float *v1, const float *v2, int solid);
/* n triangles, v holds 9 floats per triangle. */
DS_API void dsDrawTriangles(const float pos[3], const float R[12], const float *v, const int n,
                            int solid);
/* Along the body's z axis, centred on pos. */
DS_API void dsDrawCylinder(const float pos[3], const float R[12], float length, float radius);
DS_API void dsDrawCapsule(const float pos[3], const float R[12], float length, float radius);
DS_API void dsDrawLine(const float pos1[3], const float pos2[3]);
/* Faces as dGeomSetConvex takes them: planes (a, b, c, d) and, per face,
 * a vertex count followed by that many indices into points. */
DS_API void dsDrawConvex(const float pos[3], const float R[12], const float *_planes,
                         unsigned int _planecount, const float *_points,
                         unsigned int _pointcount, const unsigned int *_polygons);

/* The same with double arrays (the sizes stay float where ODE's are). */
DS_API void dsDrawBoxD(const double pos[3], const double R[12], const double sides[3]);
DS_API void dsDrawSphereD(const double pos[3], const double R[12], const float radius);
DS_API void dsDrawTriangleD(const double pos[3], const double R[12], const double *v0,
                            const double *v1, const double *v2, int solid);
DS_API void dsDrawTrianglesD(const double pos[3], const double R[12], const double *v,
                             const int n, int solid);
DS_API void dsDrawCylinderD(const double pos[3], const double R[12], float length,
                            float radius);
DS_API void dsDrawCapsuleD(const double pos[3], const double R[12], float length, float radius);
DS_API void dsDrawLineD(const double pos1[3], const double pos2[3]);
DS_API void dsDrawConvexD(const double pos[3], const double R[12], const double *_planes,
                          unsigned int _planecount, const double *_points,
                          unsigned int _pointcount, const unsigned int *_polygons);

/* Tessellation of spheres (default 1) and capsules (default 3). */
DS_API void dsSetSphereQuality(int n);
DS_API void dsSetCapsuleQuality(int n);

/* DS_POLYFILL or DS_WIREFRAME, for the shapes drawn after it. */
DS_API void dsSetDrawMode(int mode);

/* Shadows and textures on (1) or off (0); Ctrl-S and Ctrl-T toggle them. */
DS_API int dsGetShadows(void);
DS_API void dsSetShadows(int a);
DS_API int dsGetTextures(void);
DS_API void dsSetTextures(int a);

/* Older names. */
#define dsDrawCappedCylinder dsDrawCapsule
#define dsDrawCappedCylinderD dsDrawCapsuleD
#define dsSetCappedCylinderQuality dsSetCapsuleQuality

#ifdef __cplusplus
}
#endif

#endif
