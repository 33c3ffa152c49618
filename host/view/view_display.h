/* The window: GLFW, OpenGL 3.3 core through libepoxy, and the frame shown
 * as a float texture filled from a pixel buffer, either on the device by
 * CL-GL sharing or through a host mapping of that buffer. */
#ifndef VCT_VIEW_DISPLAY_H
#define VCT_VIEW_DISPLAY_H

#include <stddef.h>

#include "vct/vct.h"

typedef struct GLFWwindow GLFWwindow;

typedef enum display_mode {
    DISPLAY_AUTO,    /* interop where the device and GL share, else host */
    DISPLAY_INTEROP, /* CL-GL sharing or fail */
    DISPLAY_HOST     /* always through the host */
} display_mode;

typedef struct display {
    GLFWwindow *window;
    unsigned program, vao, texture, pbo;
    int texture_size[2];
    int interop;         /* 1: the frame reaches GL on the device */
    char path[200];      /* the path in use, and why */
    vct_tone tone;       /* as the PNG writer's: exposure (automatic or given), curve */
    float applied_stops; /* the exposure the last frame was shown at */
} display;

/* Opens the window and GL context. On failure (no display, no GL 3.3)
 * writes the reason and returns non-zero. */
int display_open(display *d, int width, int height, char *why, size_t why_size);
void display_close(display *d);
/* The OpenCL context for this window: sharing with its GL context where
 * `mode` allows and the device can, else a plain one; d->path says which. */
vct_context *display_context(display *d, display_mode mode, const char *device, vct_error *err);
/* Takes the frame (width x height) into the texture, and its exposure from
 * it when the tone is automatic: `image` when given (a device group's frame
 * on the host), else the context's frame. */
int display_upload(display *d, vct_context *ctx, const vct_image *image, int width, int height,
                   vct_error *err);
/* Draws the texture over the framebuffer (the caller swaps). */
int display_draw(display *d, vct_error *err);
/* What display_draw drew, before the swap, as 8-bit RGB with rows top to
 * bottom (width x height of the framebuffer). */
int display_read(display *d, unsigned char *rgb, int width, int height, vct_error *err);

#endif
