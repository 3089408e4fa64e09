// SPDX-License-Identifier: BSD-3-Clause
//
// window.c -- the loop with a window (GLFW, a legacy OpenGL context): mouse
// camera, keys, and frames paced in real time at DX_DS_FPS whatever the
// machine's speed (a fast machine waits, a slow one drops the lost time
// instead of catching up in a burst).

#include "ds_internal.h"

#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <stdio.h>
#include <stdlib.h>

// What the event callbacks need.
typedef struct window_state {
    dsFunctions *fn;
    int buttons;             // bit 0 left, 1 right, 2 middle
    double last_x, last_y;   // cursor at the previous event
} window_state;

static int ctrl_held(GLFWwindow *w)
{
    return glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
           glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
}

// Ctrl + letter: the viewer's commands (characters typed with Ctrl do not
// reach the character callback).
static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)scancode;
    window_state *st = glfwGetWindowUserPointer(w);
    if (action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A &&
        key <= GLFW_KEY_Z)
        dxDsKey('a' + (key - GLFW_KEY_A), 1, st->fn);
}

// Typed characters, as the keyboard layout makes them: the program's keys.
static void on_char(GLFWwindow *w, unsigned int codepoint)
{
    window_state *st = glfwGetWindowUserPointer(w);
    if (codepoint < 128 && !ctrl_held(w)) dxDsKey((int)codepoint, 0, st->fn);
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    (void)mods;
    window_state *st = glfwGetWindowUserPointer(w);
    int bit = button == GLFW_MOUSE_BUTTON_LEFT    ? 1
              : button == GLFW_MOUSE_BUTTON_RIGHT ? 2
              : button == GLFW_MOUSE_BUTTON_MIDDLE ? 4
                                                  : 0;
    if (action == GLFW_PRESS) st->buttons |= bit;
    else st->buttons &= ~bit;
    glfwGetCursorPos(w, &st->last_x, &st->last_y);
}

// A drag: left turns, right moves, middle or left + right lifts.
static void on_cursor(GLFWwindow *w, double x, double y)
{
    window_state *st = glfwGetWindowUserPointer(w);
    double dx = x - st->last_x, dy = y - st->last_y;
    st->last_x = x;
    st->last_y = y;
    int b = st->buttons;
    if ((b & 4) || (b & 3) == 3) dxDsCameraDrag(DX_DS_DRAG_LIFT, dx, dy);
    else if (b & 1) dxDsCameraDrag(DX_DS_DRAG_TURN, dx, dy);
    else if (b & 2) dxDsCameraDrag(DX_DS_DRAG_MOVE, dx, dy);
}

int dxDsWindowLoop(int width, int height, dsFunctions *fn, const dxDsOptions *opt)
{
    if (!glfwInit()) return 0;
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    GLFWwindow *w = glfwCreateWindow(width, height, "Simulation", NULL, NULL);
    if (!w) {
        glfwTerminate();
        return 0;
    }
    window_state st = { .fn = fn };
    glfwSetWindowUserPointer(w, &st);
    glfwSetKeyCallback(w, on_key);
    glfwSetCharCallback(w, on_char);
    glfwSetMouseButtonCallback(w, on_button);
    glfwSetCursorPosCallback(w, on_cursor);
    glfwMakeContextCurrent(w);
    glfwSwapInterval(0);   // the pacing below sets the frame rate
    dxDsSceneInit();
    dxDsPrintHelp();

    if (fn->start) fn->start();
    const double period = 1.0 / DX_DS_FPS;
    double next = glfwGetTime();
    long frame = 0;
    int fw = 0, fh = 0, last_w = 0, last_h = 0;
    unsigned char *last = NULL;   // the last frame, when -png asks for it
    while (dxDs.run && !glfwWindowShouldClose(w) && (opt->frames < 0 || frame < opt->frames)) {
        double now = glfwGetTime();
        if (now < next) {
            glfwWaitEventsTimeout(next - now);
            continue;
        }
        next += period;
        if (now - next > period) next = now + period;
        glfwPollEvents();
        glfwGetFramebufferSize(w, &fw, &fh);
        if (fw < 1 || fh < 1) continue;   // minimised
        dxDsFrame(fw, fh, fn, opt, ++frame);
        // The front buffer cannot be read back reliably after the swap: keep
        // each frame until the last is known.
        if (opt->png) last = dxDsReadPixels(last, last_w = fw, last_h = fh);
        glfwSwapBuffers(w);
    }
    if (fn->stop) fn->stop();
    if (last && dxDsPngWriteRgb(opt->png, last, last_w, last_h))
        fprintf(stderr, "drawstuff: wrote %s\n", opt->png);
    free(last);
    dxDsTexturesDestroy();
    glfwDestroyWindow(w);
    glfwTerminate();
    return 1;
}
