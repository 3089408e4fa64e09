// SPDX-License-Identifier: BSD-3-Clause
//
// ds_run.c -- helpers of the drawstuff tests (see ds_run.h).

#define _POSIX_C_SOURCE 200809L   // mkdtemp, setenv, fork, pipe, execl

#include "ds_run.h"

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

const char *ds_temp_dir(void)
{
    static char dir[64];
    snprintf(dir, sizeof dir, "/tmp/ds-test-XXXXXX");
    if (!mkdtemp(dir)) return "/tmp";
    return dir;
}

void ds_clear_env(void)
{
    unsetenv("DS_HEADLESS");
    unsetenv("DS_FRAMES");
    unsetenv("DS_PNG");
    unsetenv("DS_RECORD");
    unsetenv("DS_KEYS");
}

int ds_load_png(const char *path, ds_image *img)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path)) return 0;
    image.format = PNG_FORMAT_RGB;
    img->width = (int)image.width;
    img->height = (int)image.height;
    img->rgb = malloc(PNG_IMAGE_SIZE(image));
    if (!img->rgb || !png_image_finish_read(&image, NULL, img->rgb, 0, NULL)) {
        png_image_free(&image);
        free(img->rgb);
        img->rgb = NULL;
        return 0;
    }
    return 1;
}

void ds_image_free(ds_image *img)
{
    free(img->rgb);
    img->rgb = NULL;
}

const unsigned char *ds_pixel(const ds_image *img, int x, int y)
{
    if (x < 0) x = 0;
    if (y < 0) y = 0;
    if (x >= img->width) x = img->width - 1;
    if (y >= img->height) y = img->height - 1;
    return img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
}

int ds_render(ds_image *img, dsFunctions *fn, int width, int height, int frames,
              const char *const *extra)
{
    char dir[64], path[128], count[32];
    snprintf(dir, sizeof dir, "%s", ds_temp_dir());
    snprintf(path, sizeof path, "%s/frame.png", dir);
    snprintf(count, sizeof count, "%d", frames);
    char *argv[32];
    int argc = 0;
    argv[argc++] = (char *)"test";
    argv[argc++] = (char *)"-headless";
    argv[argc++] = (char *)"-frames";
    argv[argc++] = count;
    argv[argc++] = (char *)"-png";
    argv[argc++] = path;
    for (int i = 0; extra && extra[i] && argc < 31; i++) argv[argc++] = (char *)extra[i];
    argv[argc] = NULL;
    ds_clear_env();
    dsSimulationLoop(argc, argv, width, height, fn);
    int ok = ds_load_png(path, img);
    remove(path);
    rmdir(dir);
    return ok;
}

int ds_misuse(const char *what, char *out, size_t n)
{
    const char *program = getenv("DS_MISUSE");
    int fd[2];
    out[0] = '\0';
    if (!program || pipe(fd) != 0) return -1;
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        dup2(fd[1], 1);
        dup2(fd[1], 2);
        execl(program, program, what, (char *)NULL);
        _exit(127);
    }
    close(fd[1]);
    size_t got = 0;
    ssize_t r;
    while (got < n - 1 && (r = read(fd[0], out + got, n - 1 - got)) > 0) got += (size_t)r;
    out[got] = '\0';
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
}

int ds_project(const float xyz[3], const float hpr[3], int width, int height, const float p[3],
               double *px, double *py)
{
    const double deg = 3.14159265358979323846 / 180.0;
    double h = hpr[0] * deg, pitch = hpr[1] * deg;
    double f[3] = { cos(pitch) * cos(h), cos(pitch) * sin(h), sin(pitch) };
    double r[3] = { sin(h), -cos(h), 0.0 };
    double u[3] = { r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                    r[0] * f[1] - r[1] * f[0] };
    double d[3] = { p[0] - xyz[0], p[1] - xyz[1], p[2] - xyz[2] };
    double x = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
    double y = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    double z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
    if (z <= 0.0) return 0;
    double sx = 0.8, sy = 0.8;
    if (width >= height) sy *= (double)height / width;
    else sx *= (double)width / height;
    *px = (x / (z * sx) + 1.0) * 0.5 * width;
    *py = (1.0 - y / (z * sy)) * 0.5 * height;
    return 1;
}
