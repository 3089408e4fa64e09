// SPDX-License-Identifier: BSD-3-Clause
//
// test_drawstuff.c -- drawstuff through its public API, rendered headless:
// pixels where the scene puts ground, sky, a box and its shadow (projected
// here independently of GL), the options and environment variables, frame
// counts and recording, and how bad input is reported.

#define _POSIX_C_SOURCE 200809L   // setenv, nanosleep

#include "../test.h"
#include "ds_run.h"

#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define W 200
#define H 150

// The scene of the current test: camera, and what step() draws.
static float cam_xyz[3], cam_hpr[3];
static int steps, starts, stops, stop_after, last_pause;
static float got_xyz[3], got_hpr[3];   // dsGetViewpoint in the first step
static char typed[16];   // keys the command function received, each with the steps before it
static int draw_box, box_double, wireframe;
static const float box_pos[3] = { 6.0f, 0.0f, 0.25f };
static const float box_sides[3] = { 0.5f, 0.5f, 0.5f };
static float box_R[12];

static void reset_scene(const float xyz[3], const float hpr[3])
{
    memcpy(cam_xyz, xyz, sizeof cam_xyz);
    memcpy(cam_hpr, hpr, sizeof cam_hpr);
    steps = starts = stops = stop_after = 0;
    typed[0] = '\0';
    draw_box = box_double = wireframe = 0;
    // 30 degrees about z, row-major 3x4 as ODE stores it.
    float c = cosf(0.5235988f), s = sinf(0.5235988f);
    const float R[12] = { c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0 };
    memcpy(box_R, R, sizeof box_R);
}

static void start(void)
{
    starts++;
    dsSetViewpoint(cam_xyz, cam_hpr);
}

static void step(int pause)
{
    if (steps++ == 0) dsGetViewpoint(got_xyz, got_hpr);
    last_pause = pause;
    if (stop_after && steps >= stop_after) dsStop();
    if (!draw_box) return;
    if (wireframe) dsSetDrawMode(DS_WIREFRAME);
    dsSetColor(1, 0, 0);
    if (box_double) {
        double p[3], R[12], s[3];
        for (int i = 0; i < 3; i++) p[i] = box_pos[i], s[i] = box_sides[i];
        for (int i = 0; i < 12; i++) R[i] = box_R[i];
        dsDrawBoxD(p, R, s);
    } else {
        dsDrawBox(box_pos, box_R, box_sides);
    }
    dsSetDrawMode(DS_POLYFILL);
}

static void stop(void)
{
    stops++;
}


static void command(int cmd)
{
    size_t n = strlen(typed);
    if (n + 2 < sizeof typed) {
        typed[n] = (char)cmd;
        typed[n + 1] = (char)('0' + steps);
    }
}

static dsFunctions functions = { DS_VERSION, start, step, command, stop, NULL };

static int is_red(const unsigned char *p)
{
    return p[0] >= 40 && p[1] * 3 <= p[0] && p[2] * 3 <= p[0];
}

static int near_color(const unsigned char *p, int r, int g, int b, int tol)
{
    return abs(p[0] - r) <= tol && abs(p[1] - g) <= tol && abs(p[2] - b) <= tol;
}

// Looking level along +y from 10 m out on y (the axis markers behind).
static const float level_xyz[3] = { 0.0f, -10.0f, 1.0f }, level_hpr[3] = { 90.0f, 0.0f, 0.0f };

static int test_empty_scene_ground_and_sky(void)
{
    reset_scene(level_xyz, level_hpr);
    ds_image img;
    CHECK(ds_render(&img, &functions, W, H, 2, NULL));
    CHECK(img.width == W && img.height == H);
    // Above the horizon sky (blue dominates), below ground (earth: red and
    // green above blue, no blue cast).
    for (int x = 10; x < W; x += 30) {
        const unsigned char *sky = ds_pixel(&img, x, H / 5), *ground = ds_pixel(&img, x, 4 * H / 5);
        CHECK(sky[2] > sky[0] + 40 && sky[2] > sky[1]);
        CHECK(ground[0] > ground[2] + 20 && ground[1] > ground[2] + 15);
    }
    ds_image_free(&img);
    return 0;
}

static int test_notex_flat_colors(void)
{
    reset_scene(level_xyz, level_hpr);
    const char *notex[] = { "-notex", NULL };
    ds_image flat, textured;
    CHECK(ds_render(&flat, &functions, W, H, 1, notex));
    CHECK(ds_render(&textured, &functions, W, H, 1, NULL));
    // Without textures: the documented flat colours (ground 0.5 0.5 0.3, sky
    // 0 0.5 1), the same in every pixel.
    int differ = 0;
    for (int x = 5; x < W; x += 10) {
        CHECK(near_color(ds_pixel(&flat, x, 4 * H / 5), 128, 128, 77, 2));
        CHECK(near_color(ds_pixel(&flat, x, H - 2), 128, 128, 77, 2));
        CHECK(near_color(ds_pixel(&flat, x, H / 5), 0, 128, 255, 2));
        const unsigned char *t = ds_pixel(&textured, x, 4 * H / 5);
        differ += !near_color(t, 128, 128, 77, 2);
    }
    // With textures the ground is not that flat colour.
    CHECK(differ > 10);
    ds_image_free(&flat);
    ds_image_free(&textured);
    return 0;
}

// A camera 4 m in front of the box (at x = 6, away from the red axis marker
// at x = 1), looking along +y and 10 degrees down.
static const float box_xyz[3] = { 6.0f, -4.0f, 1.5f }, box_hpr[3] = { 90.0f, -10.0f, 0.0f };

// The pixel box of the box's 8 projected corners, grown by a pixel.
static int box_bounds(double lo[2], double hi[2])
{
    lo[0] = lo[1] = 1e9;
    hi[0] = hi[1] = -1e9;
    for (int k = 0; k < 8; k++) {
        float local[3], world[3];
        for (int i = 0; i < 3; i++) local[i] = ((k >> i) & 1 ? 0.5f : -0.5f) * box_sides[i];
        for (int i = 0; i < 3; i++)
            world[i] = box_pos[i] + box_R[4 * i] * local[0] + box_R[4 * i + 1] * local[1] +
                       box_R[4 * i + 2] * local[2];
        double px, py;
        if (!ds_project(box_xyz, box_hpr, W, H, world, &px, &py)) return 0;
        lo[0] = fmin(lo[0], px - 1.5);
        lo[1] = fmin(lo[1], py - 1.5);
        hi[0] = fmax(hi[0], px + 1.5);
        hi[1] = fmax(hi[1], py + 1.5);
    }
    return 1;
}

// Counts red pixels, and red pixels outside [lo, hi].
static void count_red(const ds_image *img, const double lo[2], const double hi[2], int *red,
                      int *outside)
{
    *red = *outside = 0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            if (is_red(ds_pixel(img, x, y))) {
                (*red)++;
                *outside += x < lo[0] || x > hi[0] || y < lo[1] || y > hi[1];
            }
}

static int test_red_box_where_projected(void)
{
    reset_scene(box_xyz, box_hpr);
    draw_box = 1;
    ds_image img;
    CHECK(ds_render(&img, &functions, W, H, 1, NULL));
    double px, py, lo[2], hi[2];
    // Red at the centre of the top face and of the box.
    const float top[3] = { box_pos[0], box_pos[1], box_pos[2] + 0.5f * box_sides[2] };
    CHECK(ds_project(box_xyz, box_hpr, W, H, top, &px, &py));
    CHECK(is_red(ds_pixel(&img, (int)px, (int)py)));
    CHECK(ds_project(box_xyz, box_hpr, W, H, box_pos, &px, &py));
    CHECK(is_red(ds_pixel(&img, (int)px, (int)py)));
    // Not red where the box would be had it been drawn 1 m to the side.
    const float aside[3] = { box_pos[0] + 1.0f, box_pos[1], box_pos[2] };
    CHECK(ds_project(box_xyz, box_hpr, W, H, aside, &px, &py));
    CHECK(!is_red(ds_pixel(&img, (int)px, (int)py)));
    // Every red pixel within the projected corners, and enough of them.
    CHECK(box_bounds(lo, hi));
    int red, outside;
    count_red(&img, lo, hi, &red, &outside);
    CHECK(outside == 0);
    CHECK(red > 0.3 * (hi[0] - lo[0]) * (hi[1] - lo[1]));
    ds_image_free(&img);
    return 0;
}

static int test_double_variant_same_image(void)
{
    reset_scene(box_xyz, box_hpr);
    draw_box = 1;
    const char *still[] = { "-notex", NULL };   // the sky drifts between runs otherwise
    ds_image a, b;
    CHECK(ds_render(&a, &functions, W, H, 1, still));
    box_double = 1;
    CHECK(ds_render(&b, &functions, W, H, 1, still));
    CHECK(memcmp(a.rgb, b.rgb, (size_t)W * H * 3) == 0);
    ds_image_free(&a);
    ds_image_free(&b);
    return 0;
}

static int test_wireframe_differs(void)
{
    reset_scene(box_xyz, box_hpr);
    draw_box = 1;
    ds_image fill, wire;
    CHECK(ds_render(&fill, &functions, W, H, 1, NULL));
    wireframe = 1;
    CHECK(ds_render(&wire, &functions, W, H, 1, NULL));
    double lo[2], hi[2];
    CHECK(box_bounds(lo, hi));
    int red_fill, red_wire, outside;
    count_red(&fill, lo, hi, &red_fill, &outside);
    count_red(&wire, lo, hi, &red_wire, &outside);
    // Edges only: some red, inside the box's outline, far fewer pixels.
    CHECK(outside == 0);
    CHECK(red_wire > 0);
    CHECK(red_wire < red_fill / 2);
    ds_image_free(&fill);
    ds_image_free(&wire);
    return 0;
}

static int test_shadow_on_ground(void)
{
    reset_scene(box_xyz, box_hpr);
    draw_box = 1;
    // The top face (z = 0.5) falls along the light (1, 0.4, 1) onto the
    // ground 0.5 towards -x and 0.2 towards -y: its centre is in the shadow
    // and, 0.54 from the box's axis (its corners reach 0.35), off the box.
    const float in_shadow[3] = { box_pos[0] - 0.5f, box_pos[1] - 0.2f, 0.0f };
    double px, py;
    CHECK(ds_project(box_xyz, box_hpr, W, H, in_shadow, &px, &py));
    const char *notex[] = { "-notex", NULL }, *noshadow[] = { "-notex", "-noshadow", NULL };
    ds_image lit, dark;
    CHECK(ds_render(&dark, &functions, W, H, 1, notex));
    CHECK(ds_render(&lit, &functions, W, H, 1, noshadow));
    // Shadow: the ground colour times 0.65; without shadows the ground.
    CHECK(near_color(ds_pixel(&dark, (int)px, (int)py), 83, 83, 50, 3));
    CHECK(near_color(ds_pixel(&lit, (int)px, (int)py), 128, 128, 77, 2));
    ds_image_free(&lit);
    ds_image_free(&dark);
    return 0;
}

static int test_frames_counted(void)
{
    reset_scene(level_xyz, level_hpr);
    ds_image img;
    CHECK(ds_render(&img, &functions, 64, 48, 7, NULL));
    ds_image_free(&img);
    CHECK(steps == 7 && starts == 1 && stops == 1);
    CHECK(last_pause == 0);

    // The environment alone runs an unchanged program headless.
    reset_scene(level_xyz, level_hpr);
    ds_clear_env();
    setenv("DS_HEADLESS", "1", 1);
    setenv("DS_FRAMES", "5", 1);
    char *argv[] = { (char *)"test", NULL };
    dsSimulationLoop(1, argv, 64, 48, &functions);
    CHECK(steps == 5);
    // The command line wins over the environment; -pause passes pause = 1.
    reset_scene(level_xyz, level_hpr);
    char *argv2[] = { (char *)"test", (char *)"-frames", (char *)"3", (char *)"-pause", NULL };
    dsSimulationLoop(4, argv2, 64, 48, &functions);
    CHECK(steps == 3 && last_pause == 1);
    // -keys: one key before each of the first frames' steps.
    reset_scene(level_xyz, level_hpr);
    char *argv3[] = { (char *)"test", (char *)"-frames", (char *)"4", (char *)"-keys",
                      (char *)"ab", NULL };
    dsSimulationLoop(5, argv3, 64, 48, &functions);
    CHECK(steps == 4 && strcmp(typed, "a0b1") == 0);
    // dsStop ends the loop after the current frame.
    reset_scene(level_xyz, level_hpr);
    stop_after = 4;
    dsSimulationLoop(1, argv, 64, 48, &functions);
    CHECK(steps == 4 && stops == 1);
    // No -frames and no DS_FRAMES: the default, 300.
    reset_scene(level_xyz, level_hpr);
    unsetenv("DS_FRAMES");
    dsSimulationLoop(1, argv, 16, 16, &functions);
    CHECK(steps == 300);
    ds_clear_env();
    return 0;
}

// -size WxH overrides the size the program asks for (smaller screenshots).
static int test_size_option_sets_the_image_size(void)
{
    reset_scene(level_xyz, level_hpr);
    const char *size[] = { "-size", "40x30", NULL };
    ds_image img;
    CHECK(ds_render(&img, &functions, 64, 48, 2, size));
    CHECK(img.width == 40 && img.height == 30);
    ds_image_free(&img);
    return 0;
}

static int test_record_writes_every_frame(void)
{
    reset_scene(level_xyz, level_hpr);
    char dir[96];
    snprintf(dir, sizeof dir, "%s/rec", ds_temp_dir());
    const char *record[] = { "-record", dir, NULL };
    ds_image img;
    CHECK(ds_render(&img, &functions, 64, 48, 4, record));
    ds_image_free(&img);
    for (int i = 1; i <= 5; i++) {
        char path[160];
        snprintf(path, sizeof path, "%s/frame%05d.png", dir, i);
        ds_image f;
        int exists = ds_load_png(path, &f);
        CHECK(exists == (i <= 4));
        if (exists) {
            CHECK(f.width == 64 && f.height == 48);
            ds_image_free(&f);
            remove(path);
        }
    }
    rmdir(dir);
    *strrchr(dir, '/') = '\0';
    rmdir(dir);
    return 0;
}

static int test_viewpoint_round_trip(void)
{
    // Set in start(), read back in step(): angles wrap into (-180, 180].
    reset_scene((const float[3]){ 1.0f, 2.0f, 3.0f }, (const float[3]){ 190.0f, -20.0f, 370.0f });
    ds_image img;
    CHECK(ds_render(&img, &functions, 32, 32, 1, NULL));
    ds_image_free(&img);
    CHECK_VEC(got_xyz, 1.0, 2.0, 3.0, 0.0);
    CHECK_VEC(got_hpr, -170.0, -20.0, 10.0, 1e-4);
    return 0;
}

static int test_elapsed_time(void)
{
    double first = dsElapsedTime();
    CHECK(first > 0.0 && first <= 1.0);
    struct timespec nap = { 0, 20 * 1000 * 1000 };
    nanosleep(&nap, NULL);
    double dt = dsElapsedTime();
    // At least the time slept (a monotonic clock), never more than 1 s.
    CHECK(dt >= 0.019 && dt <= 1.0);
    return 0;
}

static int exited_with(int status, int code)
{
    return WIFEXITED(status) && WEXITSTATUS(status) == code;
}

static int test_bad_input_reported(void)
{
    ds_clear_env();
    char out[4096];
    // dsError: "Error: ..." and exit status 1; dsDebug: "INTERNAL ERROR:
    // ..." and abort (a version newer than the library's, as ODE).
    CHECK(exited_with(ds_misuse("null-functions", out, sizeof out), 1));
    CHECK(strstr(out, "Error: dsSimulationLoop(): fn is NULL"));
    int status = ds_misuse("future-version", out, sizeof out);
    CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT);
    CHECK(strstr(out, "INTERNAL ERROR: bad version number in dsFunctions structure"));
    CHECK(exited_with(ds_misuse("bad-size", out, sizeof out), 1));
    CHECK(strstr(out, "bad window width or height"));
    CHECK(exited_with(ds_misuse("draw-outside-loop", out, sizeof out), 1));
    CHECK(strstr(out, "Error: dsDrawBox() called outside the simulation loop"));
    CHECK(exited_with(ds_misuse("viewpoint-before-loop", out, sizeof out), 1));
    CHECK(strstr(out, "Error: dsSetViewpoint() called before simulation started"));
    CHECK(exited_with(ds_misuse("null-pos", out, sizeof out), 1));
    CHECK(strstr(out, "Error: dsDrawSphere(): pos is NULL"));
    return 0;
}

static int test_bad_settings_ignored(void)
{
    ds_clear_env();
    char out[4096];
    // Reported, the previous value kept, and the program goes on to the end.
    CHECK(exited_with(ds_misuse("bad-settings", out, sizeof out), 0));
    CHECK(strstr(out, "dsSetSphereQuality: quality -1 is outside 0..5, kept 1"));
    CHECK(strstr(out, "dsSetCapsuleQuality: quality -3 is outside 1..16, kept 3"));
    CHECK(strstr(out, "dsSetDrawMode: mode 7"));
    CHECK(strstr(out, "dsSetTexture: no texture 9"));
    CHECK(strstr(out, "continued"));
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_empty_scene_ground_and_sky),
    TEST_CASE(test_notex_flat_colors),
    TEST_CASE(test_red_box_where_projected),
    TEST_CASE(test_double_variant_same_image),
    TEST_CASE(test_wireframe_differs),
    TEST_CASE(test_shadow_on_ground),
    TEST_CASE(test_frames_counted),
    TEST_CASE(test_size_option_sets_the_image_size),
    TEST_CASE(test_record_writes_every_frame),
    TEST_CASE(test_viewpoint_round_trip),
    TEST_CASE(test_elapsed_time),
    TEST_CASE(test_bad_input_reported),
    TEST_CASE(test_bad_settings_ignored),
    TEST_END,
};
