// SPDX-License-Identifier: BSD-3-Clause
//
// options.c -- the viewer's options: ODE's (-notex, -noshadow, -noshadows,
// -pause, -texturepath DIR) and ours for running without a display
// (-headless, -frames N, -png FILE, -record DIR, -keys KEYS, -size WxH), the
// latter also read from DS_HEADLESS, DS_FRAMES, DS_PNG, DS_RECORD, DS_KEYS, DS_SIZE so an
// unchanged program can be run headless and driven by its command keys.
// The command line wins over the environment.

#include "ds_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// A frame count from text: a whole number >= 0, else -1 (reported).
static long parse_frames(const char *text, const char *where)
{
    char *end = NULL;
    long n = text ? strtol(text, &end, 10) : -1;
    if (!text || end == text || *end != '\0' || n < 0) {
        dxDsWarn("%s: '%s' is not a frame count, ignored", where, text ? text : "");
        return -1;
    }
    return n;
}

// A window or image size "WxH" (each 1 to 8192) into opt, else reported and ignored.
static void parse_size(dxDsOptions *opt, const char *text, const char *where)
{
    int w = 0, h = 0;
    char extra;
    if (!text || sscanf(text, "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 8192 ||
        h > 8192) {
        dxDsWarn("%s: '%s' is not a size WxH, ignored", where, text ? text : "");
        return;
    }
    opt->width = w;
    opt->height = h;
}

static const char *nonempty(const char *s)
{
    return s && *s ? s : NULL;
}

void dxDsOptionsParse(dxDsOptions *opt, int argc, char **argv)
{
    opt->textures = 1;
    opt->shadows = 1;
    opt->pause = 0;
    const char *env = getenv("DS_HEADLESS");
    opt->headless = env && *env && strcmp(env, "0") != 0;
    env = nonempty(getenv("DS_FRAMES"));
    opt->frames = env ? parse_frames(env, "DS_FRAMES") : -1;
    opt->png = nonempty(getenv("DS_PNG"));
    opt->record = nonempty(getenv("DS_RECORD"));
    opt->keys = nonempty(getenv("DS_KEYS"));
    opt->width = opt->height = 0;
    env = nonempty(getenv("DS_SIZE"));
    if (env) parse_size(opt, env, "DS_SIZE");

    for (int i = 1; i < argc && argv; i++) {
        const char *a = argv[i];
        if (!a) continue;
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "-notex") == 0) opt->textures = 0;
        else if (strcmp(a, "-noshadow") == 0 || strcmp(a, "-noshadows") == 0) opt->shadows = 0;
        else if (strcmp(a, "-pause") == 0) opt->pause = 1;
        else if (strcmp(a, "-headless") == 0) opt->headless = 1;
        else if (strcmp(a, "-texturepath") == 0) i++;
        else if (strcmp(a, "-frames") == 0) {
            opt->frames = parse_frames(next, "-frames");
            i++;
        } else if (strcmp(a, "-png") == 0) {
            opt->png = nonempty(next);
            i++;
        } else if (strcmp(a, "-record") == 0) {
            opt->record = nonempty(next);
            i++;
        } else if (strcmp(a, "-keys") == 0) {
            opt->keys = nonempty(next);
            i++;
        } else if (strcmp(a, "-size") == 0) {
            parse_size(opt, next, "-size");
            i++;
        }
    }
}
