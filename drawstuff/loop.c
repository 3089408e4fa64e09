// SPDX-License-Identifier: BSD-3-Clause
//
// loop.c -- dsSimulationLoop: reads the options, then runs the program in a
// window or, with -headless / DS_HEADLESS or when there is no display,
// offscreen; both draw each frame with dxDsFrame. Also dsStop,
// dsElapsedTime and the console functions.

#define _POSIX_C_SOURCE 200809L   // clock_gettime

#include "ds_internal.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void dxDsPrintHelp(void)
{
    fprintf(stderr,
            "\nSimulation test environment v%d.%02d\n"
            "   Ctrl-P : pause / unpause (or say `-pause' on command line).\n"
            "   Ctrl-O : single step when paused.\n"
            "   Ctrl-T : toggle textures (or say `-notex' on command line).\n"
            "   Ctrl-S : toggle shadows (or say `-noshadow' on command line).\n"
            "   Ctrl-V : print current viewpoint coordinates (x,y,z,h,p,r).\n"
            "   Ctrl-W : write frames to PNG files: frame/frameNNNNN.png\n"
            "   Ctrl-X : exit.\n"
            "\n"
            "Change the camera position by clicking + dragging in the window.\n"
            "   Left button - pan and tilt.\n"
            "   Right button - forward and sideways.\n"
            "   Left + Right button (or middle button) - sideways and up.\n\n",
            DS_VERSION >> 8, DS_VERSION & 0xff);
}

void dxDsFrame(int width, int height, dsFunctions *fn, const dxDsOptions *opt, long frame)
{
    static long written;   // frames written by Ctrl-W so far
    if (opt->keys && frame <= (long)strlen(opt->keys))
        dxDsKey((unsigned char)opt->keys[frame - 1], 0, fn);
    dxDsFrameDraw(width, height, fn, dxDs.paused && !dxDs.single_step);
    dxDs.single_step = 0;
    if (opt->record) dxDsRecordFrame(opt->record, frame, width, height);
    if (dxDs.write_frames && !dxDs.paused) dxDsRecordFrame("frame", ++written, width, height);
}

// The last path component of argv[0], for a default file name.
static const char *program_name(int argc, char **argv)
{
    const char *name = argc > 0 && argv && argv[0] && *argv[0] ? argv[0] : "drawstuff";
    const char *slash = strrchr(name, '/');
    return slash && slash[1] ? slash + 1 : name;
}

void dsSimulationLoop(int argc, char **argv, int window_width, int window_height,
                      struct dsFunctions *fn)
{
    if (!fn) dsError("dsSimulationLoop(): fn is NULL");
    if (dxDs.phase != DX_DS_IDLE) dsError("dsSimulationLoop() called more than once");
    if (fn->version > DS_VERSION) dsDebug("bad version number in dsFunctions structure");
    if (window_width < 1 || window_height < 1)
        dsError("dsSimulationLoop(): bad window width or height (%d x %d)", window_width,
                window_height);

    dxDsOptions opt;
    dxDsOptionsParse(&opt, argc, argv);
    if (opt.width > 0) {
        window_width = opt.width;
        window_height = opt.height;
    }
    dxDs.textures = opt.textures;
    dxDs.shadows = opt.shadows;
    dxDs.paused = opt.pause;
    dxDs.single_step = 0;
    dxDs.write_frames = 0;
    dxDs.run = 1;
    dxDsCameraReset();
    dxDs.phase = DX_DS_RUNNING;

    char fallback_png[512];
    int headless = opt.headless;
    if (!headless) {
        const char *x = getenv("DISPLAY"), *wl = getenv("WAYLAND_DISPLAY");
        int display = (x && *x) || (wl && *wl);
        if (!display || !dxDsWindowLoop(window_width, window_height, fn, &opt)) {
            headless = 1;
            if (!opt.png) {
                snprintf(fallback_png, sizeof fallback_png, "%s.png",
                         program_name(argc, argv));
                opt.png = fallback_png;
            }
            fprintf(stderr, "drawstuff: %s; running headless (%ld frames)\n",
                    display ? "cannot open a window" : "no display",
                    opt.frames >= 0 ? opt.frames : (long)DX_DS_DEFAULT_FRAMES);
        }
    }
    if (headless) dxDsHeadlessLoop(window_width, window_height, fn, &opt);
    dxDs.phase = DX_DS_IDLE;
}

void dsStop(void)
{
    dxDs.run = 0;
}

double dsElapsedTime(void)
{
    static double previous;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    double now = (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
    double dt = previous > 0.0 ? now - previous : 0.0;
    previous = now;
    if (dt > 1.0) dt = 1.0;
    if (dt < DBL_EPSILON) dt = DBL_EPSILON;
    return dt;
}

void dsInitializeConsole(int argc, char **argv)
{
    (void)argc;
    (void)argv;
}

void dsFinalizeConsole(void)
{
}
