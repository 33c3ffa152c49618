/* The shared launch of the ray caster and Whitted ray tracing. */
#include <string.h>

#include "render/shaded_frame.h"
#include "accel/accel.h"
#include "light/emitters.h"
#include "render/frame.h"
#include "scene/scene_device.h"

#define FIRST_OWN_ARG 18

int vct_shaded_frame(vct_context *ctx, const vct_scene *s, const vct_accel *g, const char *file,
                     const char *kernel, const char *stage, int width, int height,
                     const vct_kernel_arg *extra, int extra_count, vct_image *image,
                     vct_error *err) {
    memset(image, 0, sizeof *image);
    vct_camera_desc cam;
    int rc = vct_camera_desc_make(&s->camera, width, height, &cam, err);
    if (rc)
        return rc;
    vct_stage_begin(ctx, stage);
    cl_program p;
    rc = vct_program_get(ctx, file, vct_accel_program_options(g), &p, err);
    vct_scene_buffers sb = {0};
    vct_emitters em = {0};
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, stage, &sb, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, stage, &em, err);
    cl_mem img = rc == VCT_OK ? vct_frame_get(ctx, stage, width, height, err) : NULL;
    cl_kernel k = img ? vct_kernel_create(ctx, p, kernel, err) : NULL;
    if (rc == VCT_OK)
        rc = k ? vct_accel_set_args(k, g, stage, err) : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 5, 3, VCT_ARG_OF(cam), VCT_ARG_OF(sb.materials),
                          VCT_ARG_OF(sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, &sb, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 11, 2, VCT_ARG_OF(sb.lights), VCT_ARG_OF(sb.light_count));
    if (rc == VCT_OK)
        rc = vct_emitters_set_args(k, 13, &em, VCT_EMITTER_SAMPLES, stage, err);
    for (int i = 0; rc == VCT_OK && i < extra_count; ++i)
        rc = vct_set_args(err, stage, k, FIRST_OWN_ARG + i, 1, extra[i].size, extra[i].value);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, FIRST_OWN_ARG + extra_count, 1, VCT_ARG_OF(img));
    const size_t global[2] = {(size_t)width, (size_t)height};
    const size_t local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(ctx, k, global, local, err);
    if (rc == VCT_OK)
        rc = vct_frame_deliver(ctx, stage, image, err);
    if (k)
        clReleaseKernel(k);
    vct_scene_buffers_release(ctx, &sb);
    vct_emitters_release(ctx, &em);
    vct_stage_end(ctx);
    if (rc != VCT_OK)
        vct_image_free(image);
    return rc;
}
