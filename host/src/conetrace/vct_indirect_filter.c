/* Cone tracing's indirect light filtered through the denoiser's host
 * interface: the frame read back, vct_denoise with the indirect light alone
 * and the guides of the surfaces it was gathered at, and the result written
 * into the frame again (a frame kept on the device, as the viewer's, shows
 * it too); and its direct light from emitter samples likewise, apart. */
#include "conetrace/vct_indirect_filter.h"
#include "denoise/denoise_parts.h"
#include "frame/frame.h"
#include "vct/denoise.h"

#define STAGE "vct indirect filter"

int vct_indirect_filter_reach(uint32_t passes) {
    return passes ? (2 << passes) + 1 : 0;
}

int vct_indirect_filter(vct_context *ctx, const vct_image *albedo, const vct_image *normal_depth,
                        const vct_image *variance, uint32_t passes, vct_image *indirect,
                        const vct_image *direct_variance, vct_image *direct, vct_error *err) {
    const int width = indirect->width, height = indirect->height;
    vct_image frame = {0}, filtered = {0}, direct_filtered = {0};
    int rc = vct_image_read_device(ctx, STAGE, ctx->frame, width, height, &frame, err);
    vct_denoise_options o = vct_denoise_options_default();
    o.iterations = passes;
    const vct_denoise_guides guides = {albedo, normal_depth, variance, indirect, 1};
    if (rc == VCT_OK)
        rc = vct_denoise(ctx, &frame, &guides, &o, &filtered, err);
    const vct_denoise_guides direct_guides = {albedo, normal_depth, direct_variance, NULL, 0};
    if (rc == VCT_OK && direct)
        rc = vct_denoise_direct(ctx, direct, &direct_guides, &o, &direct_filtered, err);
    const size_t values = 4 * (size_t)width * height;
    /* the indirect light filtered: the noisy one plus what the filter
     * changed; the direct light's change added to the frame */
    for (size_t i = 0; rc == VCT_OK && i < values; ++i)
        if (i % 4 != 3) {
            indirect->rgba[i] += filtered.rgba[i] - frame.rgba[i];
            if (direct) {
                filtered.rgba[i] += direct_filtered.rgba[i] - direct->rgba[i];
                direct->rgba[i] = direct_filtered.rgba[i];
            }
        }
    if (rc == VCT_OK)
        rc = vct_buffer_write(ctx, STAGE, ctx->frame, 0, 4 * values, filtered.rgba, err);
    vct_image *all[] = {&frame, &filtered, &direct_filtered};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    return rc;
}
