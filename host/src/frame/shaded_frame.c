/* The shared inputs and launch of the ray caster and Whitted ray tracing. */
#include <string.h>

#include "frame/shaded_frame.h"
#include "accel/accel.h"
#include "frame/frame.h"

static void release(vct_shaded *sh) {
    vct_scene_buffers_release(sh->ctx, &sh->sb);
    vct_emitters_release(sh->ctx, &sh->em);
    vct_stage_end(sh->ctx);
}

int vct_shaded_begin(vct_context *ctx, const vct_scene *s, const vct_accel *g, const char *file,
                     const char *stage, int width, int height, vct_shaded *sh, vct_error *err) {
    memset(sh, 0, sizeof *sh);
    sh->ctx = ctx;
    sh->accel = g;
    sh->stage = stage;
    sh->width = width;
    sh->height = height;
    int rc = vct_frame_camera(ctx, &s->camera, width, height, &sh->cam, err);
    if (rc)
        return rc;
    vct_stage_begin(ctx, stage);
    rc = vct_program_get(ctx, file, vct_accel_program_options(g), &sh->program, err);
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, stage, &sh->sb, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, stage, &sh->em, err);
    sh->frame = rc == VCT_OK ? vct_frame_get(ctx, stage, width, height, err) : NULL;
    if (!sh->frame) {
        release(sh);
        return rc == VCT_OK ? (int)err->status : rc;
    }
    return VCT_OK;
}

cl_kernel vct_shaded_kernel(vct_shaded *sh, const char *name, const vct_kernel_arg *extra,
                            int extra_count, vct_error *err) {
    const char *stage = sh->stage;
    cl_kernel k = vct_kernel_create(sh->ctx, sh->program, name, err);
    int rc = k ? vct_accel_set_args(k, sh->accel, stage, err) : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 5, 3, VCT_ARG_OF(sh->cam), VCT_ARG_OF(sh->sb.materials),
                          VCT_ARG_OF(sh->sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, &sh->sb, stage, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 11, 2, VCT_ARG_OF(sh->sb.lights),
                          VCT_ARG_OF(sh->sb.light_count));
    if (rc == VCT_OK)
        rc = vct_emitters_set_args(k, 13, &sh->em, VCT_EMITTER_SAMPLES, stage, err);
    for (int i = 0; rc == VCT_OK && i < extra_count; ++i)
        rc = vct_set_args(err, stage, k, VCT_SHADED_FIRST_OWN_ARG + i, 1, extra[i].size,
                          extra[i].value, extra[i].name);
    if (rc != VCT_OK && k) {
        clReleaseKernel(k);
        k = NULL;
    }
    return k;
}

int vct_shaded_end(vct_shaded *sh, int rc, vct_image *image, vct_error *err) {
    if (rc == VCT_OK)
        rc = vct_frame_deliver(sh->ctx, sh->stage, image, err);
    release(sh);
    if (rc != VCT_OK)
        vct_image_release(image);
    return rc;
}

int vct_shaded_frame(vct_context *ctx, const vct_scene *s, const vct_accel *g, const char *file,
                     const char *kernel, const char *stage, int width, int height,
                     const vct_kernel_arg *extra, int extra_count, vct_image *image,
                     vct_error *err) {
    memset(image, 0, sizeof *image);
    vct_shaded sh;
    int rc = vct_shaded_begin(ctx, s, g, file, stage, width, height, &sh, err);
    if (rc)
        return rc;
    cl_kernel k = vct_shaded_kernel(&sh, kernel, extra, extra_count, err);
    rc = k ? vct_set_args(err, stage, k, VCT_SHADED_FIRST_OWN_ARG + extra_count, 1,
                          VCT_ARG(image, sh.frame))
           : (int)err->status;
    const size_t global[2] = {(size_t)width, (size_t)height};
    const size_t local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(ctx, k, global, local, err);
    if (k)
        clReleaseKernel(k);
    return vct_shaded_end(&sh, rc, image, err);
}
