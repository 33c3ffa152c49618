/* vct: the denoiser, an edge-avoiding à-trous wavelet filter guided by the
 * first hit's albedo, normal and depth and by each pixel's variance (SVGF's
 * spatial filter, on one frame). The image is divided by the albedo before
 * filtering and multiplied by it after, so texture detail is not blurred;
 * edges stop the filter where normals, depths or luminance (against the
 * local standard deviation) differ. Pixels on a geometric edge, whose rays
 * met surfaces facing different ways, are fitted instead: their colour as a
 * linear function of the normal and depth over the 5x5 pixels around.
 * Deterministic: the same input gives the same output, bit for bit, on a
 * device. */
#ifndef VCT_API_DENOISE_H
#define VCT_API_DENOISE_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/device.h"
#include "vct/image.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_denoise_options {
    uint32_t iterations; /* passes, taps 1, 2, 4, ... pixels apart (1 to 10) */
    /* luminance differences allowed, in standard deviations, in the first
     * pass; each later one allows 0.8 of the one before */
    float sigma_luminance;
    float sigma_normal; /* the exponent on the normals' cosine */
    float sigma_depth;  /* depth differences allowed, in the local slope */
    /* Before the passes, a pixel brighter than its 3x3 neighbours' mean by
     * more than this many of their standard deviations is clamped to that
     * (a firefly; 0: none is). Biased: rare bright paths lose energy. */
    float firefly_sigma;
} vct_denoise_options;

/* 5 passes, 4 standard deviations, cosine^128, one slope, fireflies above
 * 6 standard deviations. */
VCT_API vct_denoise_options vct_denoise_options_default(void);

/* What guides the filter: vct_render_guides' images, and the variance of
 * each pixel's mean luminance in r (vct_pathtrace_options.variance); NULL
 * variance, or one with a negative value (a path tracer's single sample
 * says nothing of its spread): estimated from the image's luminance over
 * 5x5 pixels. Where the
 * albedo's w is below 1 an emitter is seen: its light is no noise, so those
 * pixels keep their colour and lend nothing to their neighbours (w 1
 * everywhere: no pixel is kept). */
typedef struct vct_denoise_guides {
    const vct_image *albedo;
    const vct_image *normal_depth;
    const vct_image *variance;
    /* Non-NULL: the image's indirect light (vct_pathtrace_options.indirect).
     * Its direct part (the image less this) and this are filtered apart,
     * each with its own variance (the variance's g and b), and added: direct
     * light from small lights has sharp shadows and little noise, indirect
     * light is smooth and noisy, and one filter for both blurs the one or
     * leaves the other blotchy. The direct part takes at most 3 passes; the
     * indirect part allows 1.5 times the luminance difference and clamps
     * fireflies at 10/6 times the bound (smooth light, long-tailed noise).
     * NULL: the image is filtered whole. */
    const vct_image *indirect;
    /* 1, with `indirect`: only the indirect light is filtered, and the rest
     * of the image is kept as it is (cone tracing's direct light is exact
     * and its specular cone no noise). */
    int indirect_alone;
} vct_denoise_guides;

/* Filters `color` into `out` (allocated here; free with vct_image_release).
 * Every guide must have the image's size. */
VCT_API vct_status vct_denoise(vct_context *ctx, const vct_image *color,
                               const vct_denoise_guides *guides, const vct_denoise_options *options,
                               vct_image *out, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
