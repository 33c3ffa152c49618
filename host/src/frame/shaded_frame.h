/* Kernels that shade with the ray caster's inputs: ACCEL_ARGS, the camera,
 * materials, textures, lights and emitters (arguments 0-17 of render_direct,
 * whitted and whitted_points), then their own arguments. */
#ifndef VCT_RENDER_SHADED_FRAME_H
#define VCT_RENDER_SHADED_FRAME_H

#include "runtime/runtime.h"
#include "light/emitters.h"
#include "scene/scene_device.h"

#define VCT_SHADED_FIRST_OWN_ARG 18

typedef struct vct_kernel_arg {
    const char *name; /* the kernel parameter's (checked with $VCT_CHECK_ARGS) */
    size_t size;
    const void *value;
} vct_kernel_arg;

/* The inputs on the device, and the frame they render into. */
typedef struct vct_shaded {
    vct_context *ctx;
    const vct_accel *accel;
    const char *stage;
    int width, height;
    vct_camera_desc cam;
    cl_program program;
    vct_scene_buffers sb;
    vct_emitters em;
    cl_mem frame;
} vct_shaded;

/* Begins the stage; on failure everything is released. */
int vct_shaded_begin(vct_context *ctx, const vct_scene *s, const vct_accel *accel, const char *file,
                     const char *stage, int width, int height, vct_shaded *sh, vct_error *err);
/* Kernel `name` with arguments 0-17 and then `extra` set (NULL on failure). */
cl_kernel vct_shaded_kernel(vct_shaded *sh, const char *name, const vct_kernel_arg *extra,
                            int extra_count, vct_error *err);
/* Delivers the frame into image when rc is VCT_OK, releases, ends the stage. */
int vct_shaded_end(vct_shaded *sh, int rc, vct_image *image, vct_error *err);

/* One 2D launch over the image: the shared inputs, `extra`, the frame. */
int vct_shaded_frame(vct_context *ctx, const vct_scene *s, const vct_accel *accel, const char *file,
                     const char *kernel, const char *stage, int width, int height,
                     const vct_kernel_arg *extra, int extra_count, vct_image *image,
                     vct_error *err);

#endif
