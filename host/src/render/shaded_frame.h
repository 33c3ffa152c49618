/* A frame from one 2D kernel that shades with the ray caster's inputs:
 * ACCEL_ARGS, the camera, materials, textures, lights and emitters (the
 * arguments 0-17 of render_direct and whitted), then the kernel's own
 * arguments, then the image. */
#ifndef VCT_RENDER_SHADED_FRAME_H
#define VCT_RENDER_SHADED_FRAME_H

#include "runtime/runtime.h"

typedef struct vct_kernel_arg {
    size_t size;
    const void *value;
} vct_kernel_arg;

int vct_shaded_frame(vct_context *ctx, const vct_scene *s, const vct_accel *accel, const char *file,
                     const char *kernel, const char *stage, int width, int height,
                     const vct_kernel_arg *extra, int extra_count, vct_image *image,
                     vct_error *err);

#endif
