// SPDX-License-Identifier: BSD-3-Clause
//
// ds_misuse.c -- a program that misuses drawstuff in the way its argument
// names, for test_drawstuff to see how each misuse is reported (a fresh
// process each time: a forked copy of a process that has rendered would
// inherit a GL driver whose threads did not survive the fork).

#include <drawstuff/drawstuff.h>
#include <stdio.h>
#include <string.h>

static const float pos[3] = { 0, 0, 1 }, R[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
static const float sides[3] = { 1, 1, 1 };

static void step_null_pos(int pause)
{
    (void)pause;
    dsDrawSphere(NULL, R, 1.0f);
}

static void step_sphere(int pause)
{
    (void)pause;
    dsSetSphereQuality(-1);
    dsSetCapsuleQuality(-3);
    dsSetDrawMode(7);
    dsSetTexture(9);
    dsDrawSphere(pos, R, 0.5f);
    dsDrawCapsule(pos, R, 0.5f, 0.2f);
}

int main(int argc, char **argv)
{
    const char *what = argc > 1 ? argv[1] : "";
    char *args[] = { argv[0], (char *)"-headless", (char *)"-frames", (char *)"2", NULL };
    dsFunctions fn = { DS_VERSION, NULL, NULL, NULL, NULL, NULL };
    if (strcmp(what, "null-functions") == 0) {
        dsSimulationLoop(4, args, 32, 32, NULL);
    } else if (strcmp(what, "future-version") == 0) {
        fn.version = DS_VERSION + 1;
        dsSimulationLoop(4, args, 32, 32, &fn);
    } else if (strcmp(what, "bad-size") == 0) {
        dsSimulationLoop(4, args, 0, 32, &fn);
    } else if (strcmp(what, "draw-outside-loop") == 0) {
        dsDrawBox(pos, R, sides);
    } else if (strcmp(what, "viewpoint-before-loop") == 0) {
        dsSetViewpoint(pos, pos);
    } else if (strcmp(what, "null-pos") == 0) {
        fn.step = step_null_pos;
        dsSimulationLoop(4, args, 32, 32, &fn);
    } else if (strcmp(what, "bad-settings") == 0) {
        fn.step = step_sphere;
        dsSimulationLoop(4, args, 32, 32, &fn);
        printf("continued\n");
    } else {
        fprintf(stderr, "ds_misuse: unknown case '%s'\n", what);
        return 2;
    }
    return 0;
}
