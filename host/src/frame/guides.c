/* The denoiser's guides (kernels/render/guides.cl): the first hit's albedo,
 * normal and distance at every pixel, averaged over n x n rays across it. */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "accel/accel.h"
#include "frame/frame.h"
#include "scene/scene_device.h"

#define STAGE "guides"

static int read_image(vct_context *ctx, cl_mem b, int width, int height, vct_image *out,
                      vct_error *err) {
    const size_t bytes = 16 * (size_t)width * height;
    out->width = width;
    out->height = height;
    out->rgba = malloc(bytes);
    if (!out->rgba)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    return vct_buffer_read(ctx, STAGE, b, 0, bytes, out->rgba, err);
}

vct_status vct_render_guides(vct_context *ctx, const vct_scene *s, const vct_accel *g, int width,
                             int height, uint32_t rays_per_axis, vct_image *albedo,
                             vct_image *normal_depth, vct_error *err) {
    memset(albedo, 0, sizeof *albedo);
    memset(normal_depth, 0, sizeof *normal_depth);
    if (rays_per_axis < 1 || rays_per_axis > 16)
        return vct_fail(err, VCT_ERR_INPUT, "%s: %u rays per axis: give 1 to 16", STAGE,
                        rays_per_axis);
    vct_camera_desc cam;
    int rc = vct_frame_camera(ctx, &s->camera, width, height, &cam, err);
    if (rc)
        return rc;
    vct_stage_begin(ctx, STAGE);
    cl_program p;
    vct_scene_buffers sb;
    memset(&sb, 0, sizeof sb);
    rc = vct_program_get(ctx, "render/guides.cl", vct_accel_program_options(g), &p, err);
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, STAGE, &sb, err);
    const size_t bytes = 16 * (size_t)width * height;
    cl_mem ab = rc == VCT_OK
                    ? vct_buffer_create(ctx, STAGE, "albedo", bytes, CL_MEM_WRITE_ONLY, NULL, err)
                    : NULL;
    cl_mem nb =
        ab ? vct_buffer_create(ctx, STAGE, "normal and depth", bytes, CL_MEM_WRITE_ONLY, NULL, err)
           : NULL;
    cl_kernel k = nb ? vct_kernel_create(ctx, p, "render_guides", err) : NULL;
    rc = k ? vct_accel_set_args(k, g, STAGE, err) : (int)err->status;
    const cl_uint n = rays_per_axis;
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 5, 3, VCT_ARG_OF(cam), VCT_ARG_OF(sb.materials),
                          VCT_ARG_OF(sb.tri_material));
    if (rc == VCT_OK)
        rc = vct_scene_texture_args(k, 8, &sb, STAGE, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k, 11, 3, VCT_ARG_OF(n), VCT_ARG(albedo, ab),
                          VCT_ARG(normal_depth, nb));
    const size_t global[2] = {(size_t)width, (size_t)height}, local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(ctx, k, global, local, err);
    if (rc == VCT_OK)
        rc = read_image(ctx, ab, width, height, albedo, err);
    if (rc == VCT_OK)
        rc = read_image(ctx, nb, width, height, normal_depth, err);
    if (k)
        clReleaseKernel(k);
    vct_buffer_release(ctx, ab);
    vct_buffer_release(ctx, nb);
    vct_scene_buffers_release(ctx, &sb);
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        vct_image_release(albedo);
        vct_image_release(normal_depth);
    }
    return rc;
}
