// SPDX-License-Identifier: BSD-3-Clause
//
// frames.c -- the rendered image as a PNG file (libpng): the last frame
// (-png), every frame (-record DIR) or the frames Ctrl-W asks for.

#define _POSIX_C_SOURCE 200809L   // mkdir

#include "ds_internal.h"

#include <GL/gl.h>
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

// Encodes rows of 8-bit RGB, bottom row first (GL's order), top row first in
// the file. Returns 1 on success.
static int encode(FILE *f, const unsigned char *rgb, int width, int height)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytepp rows = malloc((size_t)height * sizeof *rows);
    if (!png || !info || !rows) {
        png_destroy_write_struct(&png, &info);
        free(rows);
        return 0;
    }
    for (int y = 0; y < height; y++)
        rows[y] = (png_bytep)(rgb + (size_t)(height - 1 - y) * (size_t)width * 3);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(rows);
        return 0;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(rows);
    return 1;
}

int dxDsPngWriteRgb(const char *path, const unsigned char *rgb, int width, int height)
{
    FILE *f = fopen(path, "wb");
    int ok = f && encode(f, rgb, width, height);
    if (f && fclose(f) != 0) ok = 0;
    if (!ok) dxDsWarn("cannot write %s: %s", path, f ? "PNG encoding failed" : strerror(errno));
    return ok;
}

unsigned char *dxDsReadPixels(unsigned char *rgb, int width, int height)
{
    rgb = realloc(rgb, (size_t)width * (size_t)height * 3);
    if (!rgb) {
        dxDsWarn("no memory for a %dx%d frame", width, height);
        return NULL;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    return rgb;
}

int dxDsPngWrite(const char *path, int width, int height)
{
    unsigned char *rgb = dxDsReadPixels(NULL, width, height);
    int ok = rgb && dxDsPngWriteRgb(path, rgb, width, height);
    free(rgb);
    return ok;
}

// Writes frame `number` as dir/frameNNNNN.png, making dir if needed.
int dxDsRecordFrame(const char *dir, long number, int width, int height)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        dxDsWarn("cannot make directory %s: %s", dir, strerror(errno));
        return 0;
    }
    size_t len = strlen(dir) + 32;
    char *path = malloc(len);
    if (!path) return 0;
    snprintf(path, len, "%s/frame%05ld.png", dir, number);
    int ok = dxDsPngWrite(path, width, height);
    free(path);
    return ok;
}
