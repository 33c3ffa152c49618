/* Whitted ray tracing: ray trees on the device (kernels/render/whitted.cl). */
#include "render/shaded_frame.h"

int vct_render_whitted(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                       const vct_whitted_options *opt, vct_image *image, vct_error *err) {
    if (opt->max_depth < 1 || opt->max_depth > VCT_WHITTED_MAX_DEPTH)
        return vct_fail(err, VCT_ERR_INPUT, "whitted: a depth of %u is outside 1..%d",
                        opt->max_depth, VCT_WHITTED_MAX_DEPTH);
    if (!(opt->min_throughput >= 0.0f))
        return vct_fail(err, VCT_ERR_INPUT, "whitted: the throughput cut-off must be 0 or more");
    const cl_float4 ambient = {{s->ambient[0], s->ambient[1], s->ambient[2], 0.0f}};
    const cl_uint depth = opt->max_depth;
    const cl_float cut = opt->min_throughput;
    const vct_kernel_arg own[3] = {
        {sizeof ambient, &ambient}, {sizeof depth, &depth}, {sizeof cut, &cut}};
    return vct_shaded_frame(ctx, s, g, "render/whitted.cl", "whitted", "whitted", opt->width,
                            opt->height, own, 3, image, err);
}
