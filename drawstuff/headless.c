// SPDX-License-Identifier: BSD-3-Clause
//
// headless.c -- the loop without a display: an OpenGL context on an EGL
// pbuffer (Mesa's surfaceless platform, so no X or Wayland server; llvmpipe
// when there is no GPU), N frames as fast as they render, then the last
// frame as PNG if asked. The drawing is the window's (scene.c, shapes.c).
//
// EGL rather than OSMesa: libOSMesa defines its own gl* entry points, which
// would clash with libGL's in one library; through libglvnd, libGL's calls
// reach whichever EGL or GLX context is current, so the same drawing code
// serves the window and this pbuffer.

#include "ds_internal.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

// The EGL display stays initialized for the life of the process (a later
// loop reuses it): terminating it would unload Mesa's driver on every run.
static EGLDisplay display = EGL_NO_DISPLAY;

// A display that needs no window system: the surfaceless platform if the
// EGL library offers it, else the default display.
static EGLDisplay open_display(void)
{
    if (display != EGL_NO_DISPLAY) return display;
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay d = EGL_NO_DISPLAY;
    if (client && strstr(client, "EGL_MESA_platform_surfaceless") && get_platform_display)
        d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (d == EGL_NO_DISPLAY) d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major, minor;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) return EGL_NO_DISPLAY;
    display = d;
    return display;
}

// Makes a width x height pbuffer with a desktop OpenGL context current;
// dsError when impossible.
static void open_context(int width, int height, EGLSurface *surface, EGLContext *context)
{
    EGLDisplay d = open_display();
    if (d == EGL_NO_DISPLAY) dsError("drawstuff: no EGL display for offscreen rendering");
    if (!eglBindAPI(EGL_OPENGL_API)) dsError("drawstuff: EGL has no desktop OpenGL");
    static const EGLint wanted[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE,
    };
    EGLConfig config;
    EGLint count = 0;
    if (!eglChooseConfig(d, wanted, &config, 1, &count) || count < 1)
        dsError("drawstuff: no EGL configuration for an RGB pbuffer with depth");
    const EGLint size[] = { EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE };
    *surface = eglCreatePbufferSurface(d, config, size);
    if (*surface == EGL_NO_SURFACE)
        dsError("drawstuff: cannot make a %dx%d EGL pbuffer", width, height);
    *context = eglCreateContext(d, config, EGL_NO_CONTEXT, NULL);
    if (*context == EGL_NO_CONTEXT || !eglMakeCurrent(d, *surface, *surface, *context))
        dsError("drawstuff: cannot make an OpenGL context current on the pbuffer");
}

void dxDsHeadlessLoop(int width, int height, dsFunctions *fn, const dxDsOptions *opt)
{
    EGLSurface surface;
    EGLContext context;
    open_context(width, height, &surface, &context);
    dxDsSceneInit();

    long frames = opt->frames >= 0 ? opt->frames : DX_DS_DEFAULT_FRAMES;
    if (fn->start) fn->start();
    long frame = 0;
    while (frame < frames && dxDs.run) dxDsFrame(width, height, fn, opt, ++frame);
    if (fn->stop) fn->stop();

    glFinish();
    if (opt->png) {
        if (frame == 0) dxDsWarn("no frame drawn, %s not written", opt->png);
        else if (dxDsPngWrite(opt->png, width, height))
            fprintf(stderr, "drawstuff: wrote %s\n", opt->png);
    }
    dxDsTexturesDestroy();
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglDestroySurface(display, surface);
}
