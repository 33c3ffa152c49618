/* Ray casting through the acceleration structure: images of direct light with hard
 * shadows, and closest hits for arbitrary rays. */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "accel/accel.h"
#include "frame/shaded_frame.h"
#include "raytrace/ray_packets.h"
#include "raytrace/whitted_as.h"

/* Hits of n rays by `kernel`, each work-item tracing `per_item` of them. */
static vct_status trace_rays_by(vct_context *ctx, const vct_accel *g, const char *kernel,
                                uint32_t per_item, const float *rays, uint32_t n, int any_hit,
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
    cl_kernel k = hb ? vct_kernel_create(ctx, p, kernel, err) : NULL;
    rc = k ? vct_accel_set_args(k, g, stage, err) : (int)err->status;
    cl_uint any = any_hit != 0;
    if (rc == VCT_OK)
        rc = vct_set_args(err, stage, k, 5, 4, VCT_ARG(rays, rb), VCT_ARG_OF(n),
                          VCT_ARG(any_hit, any), VCT_ARG(hits, hb));
    if (rc == VCT_OK) {
        vct_stage_begin(ctx, stage);
        rc = vct_launch(ctx, k, (n + per_item - 1) / per_item, 64, err);
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

vct_status vct_trace_rays(vct_context *ctx, const vct_accel *g, const float *rays, uint32_t n,
                          int any_hit, vct_hit *hits, vct_error *err) {
    return trace_rays_by(ctx, g, "trace_rays", 1, rays, n, any_hit, hits, err);
}

vct_status vct_trace_ray_packets(vct_context *ctx, const vct_accel *g, const float *rays,
                                 uint32_t n, int any_hit, vct_hit *hits, vct_error *err) {
    return trace_rays_by(ctx, g, "trace_ray_packets", VCT_PACKET_RAYS, rays, n, any_hit, hits, err);
}

vct_status vct_render_raycast(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                              const vct_render_options *opt, vct_image *image, vct_error *err) {
    if (opt->subsample) { /* Whitted's kernels at one hit with the ray caster's shading */
        const vct_whitted_options wo = {opt->width,
                                        opt->height,
                                        1,
                                        0.0f,
                                        opt->subsample,
                                        opt->subsample_unguarded,
                                        opt->subsample_contrast};
        return vct_whitted_render_as(ctx, s, g, &wo, 1, image, NULL, err);
    }
    return vct_shaded_frame(ctx, s, g, "render/raycast.cl", "render_direct", "ray cast", opt->width,
                            opt->height, NULL, 0, image, err);
}
