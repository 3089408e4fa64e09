// SPDX-License-Identifier: BSD-3-Clause
//
// keys.c -- keys typed in the window: with Ctrl, the viewer's own commands
// (as ODE's viewer: T textures, S shadows, X exit, P pause, O single step,
// V print viewpoint, W write frames); without, printable characters go to
// the program's command function.

#include "ds_internal.h"

#include <stdio.h>

void dxDsKey(int key, int ctrl, dsFunctions *fn)
{
    if (!ctrl) {
        if (key >= ' ' && key <= 126 && fn->command) fn->command(key);
        return;
    }
    switch (key) {
    case 't': case 'T':
        dsSetTextures(!dsGetTextures());
        break;
    case 's': case 'S':
        dsSetShadows(!dsGetShadows());
        break;
    case 'x': case 'X':
        dxDs.run = 0;
        break;
    case 'p': case 'P':
        dxDs.paused = !dxDs.paused;
        dxDs.single_step = 0;
        break;
    case 'o': case 'O':
        if (dxDs.paused) dxDs.single_step = 1;
        break;
    case 'v': case 'V':
        printf("Viewpoint = (%.4f,%.4f,%.4f,%.4f,%.4f,%.4f)\n", dxDs.view_xyz[0],
               dxDs.view_xyz[1], dxDs.view_xyz[2], dxDs.view_hpr[0], dxDs.view_hpr[1],
               dxDs.view_hpr[2]);
        fflush(stdout);
        break;
    case 'w': case 'W':
        dxDs.write_frames = !dxDs.write_frames;
        if (dxDs.write_frames) printf("Now writing frames to PNG files: frame/frameNNNNN.png\n");
        break;
    default:
        break;
    }
}
