/* vct_denoise: an image through the passes whole (denoise.c), or the path
 * tracer's as two parts: its direct light (the image less its indirect
 * light) and its indirect light, each through the passes with its own
 * variance (the variance image's g and b) and options, then added; or cone
 * tracing's indirect light alone, added to the rest of its image. */
#include <stdlib.h>
#include <string.h>

#include "denoise/denoise_parts.h"
#include "runtime/runtime.h"

#define STAGE "denoise"

/* Passes for the direct part at most: it is far less noisy than the
 * indirect part, and over the scene suite 3 passes do as well as 5. */
#define DIRECT_PASSES 3u
/* The indirect part's luminance and firefly bounds, as multiples of the
 * options': it has no sharp shadows to keep, so wider luminance differences
 * may be averaged; and its noise has long tails (paths that meet a small
 * lamp after a bounce), so clamping at the image's bound took 9 % of a lamp
 * room's indirect light at 4 spp. Over the scene suite at 128 and 256
 * pixels square these cut the error at 4 spp by up to a tenth. */
#define INDIRECT_SIGMA_SCALE 1.5f
#define INDIRECT_FIREFLY_SCALE (10.0f / 6.0f)
/* The direct part keeps its own value where the filter moved it by more than
 * this many standard deviations of the noise around (the mean variance of
 * the 3x3 pixels): no noise explains such a change, so it is the filter's
 * bias. Direct light from a sun or a point light is exact but for the
 * pixels a shadow's edge crosses, and the passes spread those pixels'
 * spread over their exact neighbours: at 16 spp a sunlit hall's error grew
 * by 40 % where it should have shrunk. */
#define DIRECT_TRUST_SIGMAS 4.0f

static float luminance(const float *c) {
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

/* filtered takes noisy's value where they differ by more than
 * DIRECT_TRUST_SIGMAS standard deviations of the 3x3 pixels' variance (r of
 * variance; a negative one, unknown, trusts the filter). */
static void keep_unexplained(const vct_image *noisy, const vct_image *variance,
                             vct_image *filtered) {
    const int w = noisy->width, h = noisy->height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float sum = 0.0f;
            int count = 0, unknown = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h)
                        continue;
                    const float v = variance->rgba[4 * ((size_t)qy * w + qx)];
                    unknown |= v < 0.0f;
                    sum += v;
                    ++count;
                }
            const size_t i = 4 * ((size_t)y * w + x);
            const float d = luminance(filtered->rgba + i) - luminance(noisy->rgba + i);
            if (!unknown &&
                d * d > DIRECT_TRUST_SIGMAS * DIRECT_TRUST_SIGMAS * (sum / (float)count))
                memcpy(filtered->rgba + i, noisy->rgba + i, 3 * sizeof(float));
        }
}

/* A copy of the variance with channel c of each pixel in r, where the
 * passes read it (NULL stays NULL: estimated from the image). */
static int variance_channel(const vct_image *v, int c, vct_image *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    if (!v)
        return VCT_OK;
    const size_t pixels = (size_t)v->width * v->height;
    out->rgba = malloc(16 * pixels);
    if (!out->rgba)
        return vct_fail(err, VCT_ERR_MEMORY, "%s: out of host memory for a variance", STAGE);
    out->width = v->width;
    out->height = v->height;
    for (size_t i = 0; i < pixels; ++i) {
        out->rgba[4 * i] = v->rgba[4 * i + c];
        out->rgba[4 * i + 1] = out->rgba[4 * i + 2] = 0.0f;
        out->rgba[4 * i + 3] = 1.0f;
    }
    return VCT_OK;
}

int vct_denoise_direct(vct_context *ctx, const vct_image *direct, const vct_denoise_guides *g,
                       const vct_denoise_options *o, vct_image *out, vct_error *err) {
    vct_denoise_options direct_options = *o;
    if (direct_options.iterations > DIRECT_PASSES)
        direct_options.iterations = DIRECT_PASSES;
    const int rc = vct_denoise_whole(ctx, direct, g, &direct_options, out, err);
    if (rc == VCT_OK && g->variance)
        keep_unexplained(direct, g->variance, out);
    return rc;
}

/* The direct part (color less g->indirect) and the indirect part filtered
 * apart, each with its own variance (g and b), and added again. */
int vct_denoise_parts(vct_context *ctx, const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_image *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    const size_t values = 4 * (size_t)color->width * color->height;
    vct_image direct = {color->width, color->height, malloc(4 * values)}, var_direct, var_indirect,
              filtered = {0};
    int rc = direct.rgba ? VCT_OK
                         : vct_fail(err, VCT_ERR_MEMORY,
                                    "%s: out of host memory for the direct "
                                    "light",
                                    STAGE);
    if (rc == VCT_OK)
        rc = variance_channel(g->variance, 1, &var_direct, err);
    if (rc == VCT_OK)
        rc = variance_channel(g->variance, 2, &var_indirect, err);
    for (size_t i = 0; rc == VCT_OK && i < values; ++i)
        direct.rgba[i] = i % 4 == 3 ? 1.0f : color->rgba[i] - g->indirect->rgba[i];
    vct_denoise_guides part = *g;
    part.variance = g->variance ? &var_direct : NULL;
    if (rc == VCT_OK)
        rc = vct_denoise_direct(ctx, &direct, &part, o, out, err);
    part.variance = g->variance ? &var_indirect : NULL;
    vct_denoise_options indirect_options = *o;
    indirect_options.sigma_luminance *= INDIRECT_SIGMA_SCALE;
    indirect_options.firefly_sigma *= INDIRECT_FIREFLY_SCALE;
    if (rc == VCT_OK)
        rc = vct_denoise_whole(ctx, g->indirect, &part, &indirect_options, &filtered, err);
    for (size_t i = 0; rc == VCT_OK && i < values; ++i)
        if (i % 4 != 3)
            out->rgba[i] += filtered.rgba[i];
    if (rc != VCT_OK)
        vct_image_release(out);
    vct_image *all[] = {&filtered, &direct, &var_direct, &var_indirect};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    return rc;
}

/* g->indirect alone through the passes; the rest of the image kept. */
static int denoise_indirect_alone(vct_context *ctx, const vct_image *color,
                                  const vct_denoise_guides *g, const vct_denoise_options *o,
                                  vct_image *out, vct_error *err) {
    const int rc = vct_denoise_whole(ctx, g->indirect, g, o, out, err);
    const size_t values = 4 * (size_t)color->width * color->height;
    for (size_t i = 0; rc == VCT_OK && i < values; ++i)
        out->rgba[i] =
            i % 4 == 3 ? color->rgba[i] : color->rgba[i] + (out->rgba[i] - g->indirect->rgba[i]);
    return rc;
}

vct_status vct_denoise(vct_context *ctx, const vct_image *color, const vct_denoise_guides *g,
                       const vct_denoise_options *o, vct_image *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    int rc = vct_denoise_check(color, g, o, err);
    if (rc)
        return rc;
    if (g->indirect && g->indirect_alone)
        return denoise_indirect_alone(ctx, color, g, o, out, err);
    return g->indirect ? vct_denoise_parts(ctx, color, g, o, out, err)
                       : vct_denoise_whole(ctx, color, g, o, out, err);
}
