/* Ray casting through the triangle grid: images of direct light with hard
 * shadows, and closest hits for arbitrary rays. */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "accel/accel.h"
#include "light/emitters.h"
#include "render/frame.h"
#include "scene/scene_device.h"

int vct_trace_rays(vct_context *ctx, const vct_accel *g, const float *rays, uint32_t n, int any_hit,
                   vct_hit *hits, vct_error *err) {
    const char *stage = any_hit ? "trace rays (any hit)" : "trace rays";
    if (n == 0)
        return VCT_OK;
    cl_program p;
    int rc = vct_program_get(ctx, "render/raycast.cl", vct_accel_program_options(g), &p, err);
    if (rc)
        return rc;
    cl_mem rb = vct_buffer_create(ctx, stage, "rays", 32ull * n, CL_MEM_READ_ONLY, rays, err);
    cl_mem hb =
        rb ? vct_buffer_create(ctx, stage, "hits", 16ull * n, CL_MEM_WRITE_ONLY, NULL, err) : NULL;
    cl_kernel k = hb ? vct_kernel_create(ctx, p, "trace_rays", err) : NULL;
    rc = k ? vct_accel_set_args(k, g, stage, err) : (int)err->status;
    cl_uint any = any_hit != 0;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 5, 4, VCT_ARG_OF(rb), VCT_ARG_OF(n), VCT_ARG_OF(any),
                          VCT_ARG_OF(hb));
    if (rc == VCT_OK) {
        vct_stage_begin(ctx, stage);
        rc = vct_launch(ctx, k, n, 64, err);
        vct_stage_end(ctx);
    }
    float *raw = rc == VCT_OK ? malloc(16ull * n) : NULL;
    if (rc == VCT_OK && !raw)
        rc = vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", stage);
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, hb, 0, 16ull * n, raw, err);
    if (rc == VCT_OK) {
        for (uint32_t i = 0; i < n; ++i) {
            hits[i].t = raw[4 * i];
            memcpy(&hits[i].triangle, &raw[4 * i + 1], 4);
            hits[i].u = raw[4 * i + 2];
            hits[i].v = raw[4 * i + 3];
        }
    }
    free(raw);
    if (k)
        clReleaseKernel(k);
    vct_buffer_release(ctx, hb);
    vct_buffer_release(ctx, rb);
    return rc;
}

int vct_render_raycast(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                       const vct_render_options *opt, vct_image *image, vct_error *err) {
    const char *stage = "ray cast";
    memset(image, 0, sizeof *image);
    vct_camera_desc cam;
    int rc = vct_camera_desc_make(&s->camera, opt->width, opt->height, &cam, err);
    if (rc)
        return rc;
    vct_stage_begin(ctx, stage);
    cl_program p;
    rc = vct_program_get(ctx, "render/raycast.cl", vct_accel_program_options(g), &p, err);
    vct_scene_buffers sb = {0};
    vct_emitters em = {0};
    if (rc == VCT_OK)
        rc = vct_scene_buffers_make(ctx, s, stage, &sb, err);
    if (rc == VCT_OK)
        rc = vct_emitters_build(ctx, s, VCT_EMITTERS_BY_POWER, stage, &em, err);
    cl_mem img = rc == VCT_OK ? vct_frame_get(ctx, stage, opt->width, opt->height, err) : NULL;
    cl_kernel k = img ? vct_kernel_create(ctx, p, "render_direct", err) : NULL;
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
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 18, 1, VCT_ARG_OF(img));
    const size_t global[2] = {(size_t)opt->width, (size_t)opt->height};
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
