/* Cone tracing's indirect light filtered on the host's side of the
 * denoiser: the frame and its indirect slot read back, the guides traced
 * for the same rows, vct_denoise with the indirect light alone, and the
 * result written into the frame again (a frame kept on the device, as the
 * viewer's, shows it too). */
#include <stdlib.h>
#include <string.h>

#include "conetrace/vct_indirect_filter.h"
#include "frame/frame.h"
#include "vct/denoise.h"
#include "vct/render.h"

#define STAGE "vct indirect filter"

int vct_indirect_filter_reach(uint32_t passes) {
    return passes ? (2 << passes) + 1 : 0;
}

/* Slot `slot` of an AOV buffer read into an image. */
static int read_slot(vct_context *ctx, cl_mem aov, int slots, int slot, int width, int height,
                     vct_image *out, vct_error *err) {
    const size_t pixels = (size_t)width * height, bytes = 16 * (size_t)slots * pixels;
    float *raw = malloc(bytes);
    out->width = width;
    out->height = height;
    out->rgba = malloc(16 * pixels);
    int rc = raw && out->rgba ? vct_buffer_read(ctx, STAGE, aov, 0, bytes, raw, err)
                              : vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory", STAGE);
    for (size_t p = 0; rc == VCT_OK && p < pixels; ++p)
        memcpy(out->rgba + 4 * p, raw + 4 * ((size_t)slots * p + (size_t)slot), 16);
    free(raw);
    if (rc != VCT_OK)
        vct_image_release(out);
    return rc;
}

int vct_indirect_filter(vct_context *ctx, const vct_scene *s, const vct_accel *g, cl_mem aov,
                        int aov_slots, int width, int height, uint32_t passes, vct_image *indirect,
                        vct_error *err) {
    memset(indirect, 0, sizeof *indirect);
    vct_image frame = {0}, noisy = {0}, albedo = {0}, normal_depth = {0}, filtered = {0};
    int rc = vct_image_read_device(ctx, STAGE, ctx->frame, width, height, &frame, err);
    if (rc == VCT_OK)
        rc = read_slot(ctx, aov, aov_slots, 1, width, height, &noisy, err);
    if (rc == VCT_OK)
        rc = vct_render_guides(ctx, s, g, width, height, VCT_INDIRECT_GUIDE_RAYS, &albedo,
                               &normal_depth, err);
    vct_denoise_options o = vct_denoise_options_default();
    o.iterations = passes;
    const vct_denoise_guides guides = {&albedo, &normal_depth, NULL, &noisy, 1};
    if (rc == VCT_OK)
        rc = vct_denoise(ctx, &frame, &guides, &o, &filtered, err);
    const size_t values = 4 * (size_t)width * height;
    if (rc == VCT_OK)
        rc = vct_buffer_write(ctx, STAGE, ctx->frame, 0, 4 * values, filtered.rgba, err);
    /* the indirect light filtered: the noisy one plus what the filter changed */
    for (size_t i = 0; rc == VCT_OK && i < values; ++i)
        if (i % 4 != 3)
            noisy.rgba[i] += filtered.rgba[i] - frame.rgba[i];
    if (rc == VCT_OK) {
        *indirect = noisy;
        noisy.rgba = NULL;
    }
    vct_image *all[] = {&frame, &noisy, &albedo, &normal_depth, &filtered};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    return rc;
}
