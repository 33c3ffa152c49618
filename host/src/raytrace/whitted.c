/* Whitted ray tracing: ray trees on the device (kernels/render/whitted.cl),
 * every pixel or adaptively subsampled (render/subsample.c). */
#include <stdlib.h>
#include <string.h>

#include "raytrace/small_objects.h"
#include "raytrace/subsample.h"
#include "raytrace/whitted_as.h"

#define KERNEL_FILE "render/whitted.cl"
#define STAGE "whitted"

static int check_options(const vct_context *ctx, const vct_whitted_options *o, vct_error *err) {
    if (o->max_depth < 1 || o->max_depth > VCT_WHITTED_MAX_DEPTH)
        return vct_fail(err, VCT_ERR_INPUT, "whitted: a depth of %u is outside 1..%d", o->max_depth,
                        VCT_WHITTED_MAX_DEPTH);
    if (!(o->subsample_contrast >= 0.0f))
        return vct_fail(err, VCT_ERR_INPUT, "whitted: the subsampling contrast must be 0 or more");
    if (!(o->min_throughput >= 0.0f))
        return vct_fail(err, VCT_ERR_INPUT, "whitted: the throughput cut-off must be 0 or more");
    /* A band of a taller image may be shorter than a square: the whole
     * image's bottom squares are cut short the same way. */
    const int height = ctx->band_height ? ctx->band_height : o->height;
    const uint32_t n = o->subsample, side = (uint32_t)(o->width < height ? o->width : height);
    if (n && (n < 2 || (n & (n - 1)) || n > side))
        return vct_fail(err, VCT_ERR_INPUT,
                        "whitted: --subsample %u must be 0 or a power of two from 2 to the "
                        "image's smaller side (%u)",
                        n, side);
    return VCT_OK;
}

int vct_whitted_render_as(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                          const vct_whitted_options *opt, int plain, vct_image *image,
                          vct_whitted_result *result, vct_error *err) {
    memset(image, 0, sizeof *image);
    int rc = check_options(ctx, opt, err);
    if (rc)
        return rc;
    const float a = plain ? 0.0f : 1.0f;
    const cl_float4 ambient = {{a * s->ambient[0], a * s->ambient[1], a * s->ambient[2], 0.0f}};
    const cl_uint depth = opt->max_depth, plain_arg = (cl_uint)plain;
    const cl_float cut = opt->min_throughput;
    const vct_kernel_arg own[4] = {{"ambient", sizeof ambient, &ambient},
                                   {"max_depth", sizeof depth, &depth},
                                   {"min_throughput", sizeof cut, &cut},
                                   {"plain", sizeof plain_arg, &plain_arg}};
    uint64_t traced = (uint64_t)opt->width * (uint64_t)opt->height, rays = traced;
    if (!opt->subsample) {
        rc = vct_shaded_frame(ctx, s, g, KERNEL_FILE, "whitted", STAGE, opt->width, opt->height,
                              own, 4, image, err);
        if (rc == VCT_OK && result && result->traced_mask)
            memset(result->traced_mask, 1, (size_t)traced);
    } else {
        vct_shaded sh;
        rc = vct_shaded_begin(ctx, s, g, KERNEL_FILE, STAGE, opt->width, opt->height, &sh, err);
        if (rc)
            return rc;
        uint16_t *guard = NULL;
        if (!opt->subsample_unguarded) {
            guard = malloc(2ull * opt->width * opt->height);
            const int64_t small =
                guard ? vct_small_object_map(s, &sh.cam, opt->subsample, guard) : -1;
            if (small < 0)
                rc = vct_fail(err, VCT_ERR_MEMORY, "whitted: out of host memory");
            else if (result)
                result->small_objects = (uint64_t)small;
        }
        if (rc == VCT_OK)
            rc = vct_subsample(&sh, "whitted_points", own, 4, opt->subsample, guard,
                               opt->subsample_contrast, &traced, &rays,
                               result ? result->traced_mask : NULL, err);
        free(guard);
        rc = vct_shaded_end(&sh, rc, image, err);
    }
    if (rc == VCT_OK && result) {
        result->traced_pixels = traced;
        result->camera_rays = rays;
    }
    return rc;
}

vct_status vct_render_whitted(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                              const vct_whitted_options *opt, vct_image *image,
                              vct_whitted_result *result, vct_error *err) {
    return vct_whitted_render_as(ctx, s, g, opt, 0, image, result, err);
}
