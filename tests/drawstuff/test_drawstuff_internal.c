// SPDX-License-Identifier: BSD-3-Clause
//
// test_drawstuff_internal.c -- drawstuff's window-side logic without a
// window: option parsing (command line over environment), the Ctrl keys and
// command keys, and the mouse camera's motion.

#define _POSIX_C_SOURCE 200809L   // setenv

#include "../test.h"
#include "ds_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int test_options(void)
{
    dxDsOptions opt;
    unsetenv("DS_HEADLESS");
    unsetenv("DS_FRAMES");
    unsetenv("DS_PNG");
    unsetenv("DS_RECORD");
    unsetenv("DS_KEYS");
    char *plain[] = { (char *)"demo", NULL };
    dxDsOptionsParse(&opt, 1, plain);
    CHECK(opt.textures && opt.shadows && !opt.pause && !opt.headless);
    CHECK(opt.frames == -1 && !opt.png && !opt.record);

    char *all[] = { (char *)"demo", (char *)"-notex", (char *)"-noshadows", (char *)"-pause",
                    (char *)"-texturepath", (char *)"/x", (char *)"-headless",
                    (char *)"-frames", (char *)"12", (char *)"-png", (char *)"a.png",
                    (char *)"-record", (char *)"dir", (char *)"-keys", (char *)"ab", NULL };
    dxDsOptionsParse(&opt, 15, all);
    CHECK(strcmp(opt.keys, "ab") == 0);
    CHECK(!opt.textures && !opt.shadows && opt.pause && opt.headless);
    CHECK(opt.frames == 12 && strcmp(opt.png, "a.png") == 0 && strcmp(opt.record, "dir") == 0);
    char *one[] = { (char *)"demo", (char *)"-noshadow", NULL };
    dxDsOptionsParse(&opt, 2, one);
    CHECK(opt.textures && !opt.shadows);

    // The environment, and the command line over it.
    setenv("DS_HEADLESS", "1", 1);
    setenv("DS_FRAMES", "40", 1);
    setenv("DS_PNG", "env.png", 1);
    setenv("DS_RECORD", "envdir", 1);
    setenv("DS_KEYS", "xyz", 1);
    dxDsOptionsParse(&opt, 1, plain);
    CHECK(strcmp(opt.keys, "xyz") == 0);
    CHECK(opt.headless && opt.frames == 40);
    CHECK(strcmp(opt.png, "env.png") == 0 && strcmp(opt.record, "envdir") == 0);
    char *over[] = { (char *)"demo", (char *)"-frames", (char *)"3", (char *)"-png",
                     (char *)"cl.png", NULL };
    dxDsOptionsParse(&opt, 5, over);
    CHECK(opt.frames == 3 && strcmp(opt.png, "cl.png") == 0);
    setenv("DS_HEADLESS", "0", 1);
    setenv("DS_FRAMES", "many", 1);   // not a count: reported, ignored
    dxDsOptionsParse(&opt, 1, plain);
    CHECK(!opt.headless && opt.frames == -1);
    // An option missing its value at the end is ignored, not read past argv.
    char *cut[] = { (char *)"demo", (char *)"-frames", NULL };
    dxDsOptionsParse(&opt, 2, cut);
    CHECK(opt.frames == -1);

    // The size: WxH from the environment, the command line over it, nonsense ignored.
    CHECK(opt.width == 0 && opt.height == 0);
    setenv("DS_SIZE", "320x200", 1);
    dxDsOptionsParse(&opt, 1, plain);
    CHECK(opt.width == 320 && opt.height == 200);
    char *size[] = { (char *)"demo", (char *)"-size", (char *)"640x360", NULL };
    dxDsOptionsParse(&opt, 3, size);
    CHECK(opt.width == 640 && opt.height == 360);
    char *bad[] = { (char *)"demo", (char *)"-size", (char *)"640x0", NULL };
    unsetenv("DS_SIZE");
    dxDsOptionsParse(&opt, 3, bad);
    CHECK(opt.width == 0 && opt.height == 0);
    char *junk[] = { (char *)"demo", (char *)"-size", (char *)"64x36px", NULL };
    dxDsOptionsParse(&opt, 3, junk);
    CHECK(opt.width == 0 && opt.height == 0);
    unsetenv("DS_HEADLESS");
    unsetenv("DS_FRAMES");
    unsetenv("DS_PNG");
    unsetenv("DS_RECORD");
    unsetenv("DS_KEYS");
    return 0;
}

static int commands[8], command_count;

static void command(int cmd)
{
    if (command_count < 8) commands[command_count] = cmd;
    command_count++;
}

static int test_keys(void)
{
    dsFunctions fn = { DS_VERSION, NULL, NULL, command, NULL, NULL };
    dxDs.textures = dxDs.shadows = 1;
    dxDs.run = 1;
    dxDs.paused = dxDs.single_step = 0;
    command_count = 0;

    dxDsKey('t', 1, &fn);
    CHECK(dsGetTextures() == 0);
    dxDsKey('T', 1, &fn);
    CHECK(dsGetTextures() == 1);
    dxDsKey('s', 1, &fn);
    CHECK(dsGetShadows() == 0);
    // Single step only while paused.
    dxDsKey('o', 1, &fn);
    CHECK(dxDs.single_step == 0);
    dxDsKey('p', 1, &fn);
    CHECK(dxDs.paused == 1);
    dxDsKey('o', 1, &fn);
    CHECK(dxDs.single_step == 1);
    dxDsKey('p', 1, &fn);
    CHECK(dxDs.paused == 0 && dxDs.single_step == 0);
    CHECK(command_count == 0);
    // Without Ctrl, printable characters go to the program.
    dxDsKey('a', 0, &fn);
    dxDsKey('T', 0, &fn);
    dxDsKey('\t', 0, &fn);
    CHECK(command_count == 2 && commands[0] == 'a' && commands[1] == 'T');
    CHECK(dsGetTextures() == 1);
    dxDsKey('x', 1, &fn);
    CHECK(dxDs.run == 0);
    dsFunctions quiet = { DS_VERSION, NULL, NULL, NULL, NULL, NULL };
    dxDsKey('a', 0, &quiet);   // no command function: nothing happens
    dxDs.shadows = 1;
    return 0;
}

static int test_mouse_camera(void)
{
    dxDsCameraReset();
    CHECK_VEC(dxDs.view_xyz, 2.0, 0.0, 1.0, 0.0);
    CHECK_VEC(dxDs.view_hpr, 180.0, 0.0, 0.0, 0.0);
    // Left drag: half a degree per pixel; heading wraps to (-180, 180].
    dxDsCameraDrag(DX_DS_DRAG_TURN, 20.0, -10.0);
    CHECK_NEAR(dxDs.view_hpr[0], -170.0, 1e-4);
    CHECK_NEAR(dxDs.view_hpr[1], -5.0, 1e-5);
    // Right drag: forward (y) along the heading, sideways (x) across it.
    dxDs.view_hpr[0] = 90.0f;
    dxDsCameraDrag(DX_DS_DRAG_MOVE, 0.0, 100.0);
    CHECK_VEC(dxDs.view_xyz, 2.0, 1.0, 1.0, 1e-5);
    dxDsCameraDrag(DX_DS_DRAG_MOVE, 50.0, 0.0);
    CHECK_VEC(dxDs.view_xyz, 1.5, 1.0, 1.0, 1e-5);
    // Middle drag: sideways and up.
    dxDsCameraDrag(DX_DS_DRAG_LIFT, 0.0, 30.0);
    CHECK_VEC(dxDs.view_xyz, 1.5, 1.0, 1.3, 1e-5);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_options),
    TEST_CASE(test_keys),
    TEST_CASE(test_mouse_camera),
    TEST_END,
};
