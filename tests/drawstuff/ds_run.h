// SPDX-License-Identifier: BSD-3-Clause
//
// ds_run.h -- helpers of the drawstuff tests: run a program's callbacks
// headless into a PNG and read it back, run a body in a child process to
// see how it ends, project world points to pixels independently of GL.

#ifndef DS_RUN_H
#define DS_RUN_H

#include <drawstuff/drawstuff.h>
#include <stddef.h>

typedef struct ds_image {
    int width, height;
    unsigned char *rgb;   // top row first, 3 bytes per pixel
} ds_image;

// A fresh empty directory for a test's files (static storage).
const char *ds_temp_dir(void);
// Removes the DS_* variables so only the arguments given count.
void ds_clear_env(void);

// Runs fn headless at width x height for `frames` frames with the extra
// arguments (NULL-terminated, may be NULL), writes the last frame as a PNG
// and loads it into img. Returns 1 on success.
int ds_render(ds_image *img, dsFunctions *fn, int width, int height, int frames,
              const char *const *extra);
int ds_load_png(const char *path, ds_image *img);
void ds_image_free(ds_image *img);
const unsigned char *ds_pixel(const ds_image *img, int x, int y);

// Runs the program named by $DS_MISUSE with argument `what`, its stdout
// and stderr captured into out (n bytes, NUL-terminated). Returns its wait
// status, or -1 when it could not be run.
int ds_misuse(const char *what, char *out, size_t n);

// Pixel (x right, y down) where world point p appears for a camera at xyz
// looking with heading/pitch hpr (roll 0) into a width x height image, by
// drawstuff's documented projection: +-0.8 at distance 1 across the longer
// side. Returns 0 if p is behind the camera.
int ds_project(const float xyz[3], const float hpr[3], int width, int height, const float p[3],
               double *px, double *py);

#endif
