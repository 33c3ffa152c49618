/* vct: images: linear radiance on the host, files and error metrics. */
#ifndef VCT_API_IMAGE_H
#define VCT_API_IMAGE_H

#include "vct/export.h"

#include <stddef.h>

#include "vct/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_image {
    int width, height;
    float *rgba; /* linear radiance, width*height*4 */
} vct_image;

VCT_API void vct_image_release(vct_image *image);

/* How linear radiance becomes a displayed image (PNG files, the viewer):
 * times 2^stops, through a tone curve, sRGB encoded. */
typedef enum vct_tone_curve {
    VCT_TONE_CLIP = 0,  /* values above 1 clip to white */
    VCT_TONE_FILMIC = 1 /* an ACES fit: highlights roll off towards white */
} vct_tone_curve;

typedef struct vct_tone {
    /* 1: the exposure is taken from the image, its log-average luminance
     * (pixels that hold light) mapped to middle grey, 0.18, plus `exposure`;
     * 0: `exposure` alone. */
    int auto_exposure;
    float exposure; /* stops */
    vct_tone_curve curve;
} vct_tone;

/* Automatic exposure, filmic curve: what `vct render` writes by default. */
VCT_API vct_tone vct_tone_default(void);
/* The stops that map the log-average luminance of `pixels` rgba pixels to
 * 0.18 (0 when no pixel holds light). */
VCT_API double vct_image_auto_exposure(const float *rgba, size_t pixels);
/* The stops `tone` applies to an image. */
VCT_API float vct_tone_exposure(const vct_tone *tone, const float *rgba, size_t pixels);
/* The curve on one exposed linear value, into [0, 1] (before sRGB). */
VCT_API float vct_tone_curve_apply(vct_tone_curve curve, float x);
VCT_API const char *vct_tone_curve_name(vct_tone_curve curve);
/* PNG tone mapped as `tone` says; *applied (may be NULL) gets the stops. */
VCT_API vct_status vct_image_write_png_tone(const vct_image *image, const char *path,
                                            const vct_tone *tone, float *applied, vct_error *err);
/* .png through `tone`; .pfm raw; .exr raw, half floats. */
VCT_API vct_status vct_image_write_tone(const vct_image *image, const char *path,
                                        const vct_tone *tone, vct_error *err);

/* PFM: raw linear radiance. PNG: radiance * 2^exposure, clipped, sRGB encoded.
 * Written to a temporary file and renamed, so a failure leaves nothing. */
VCT_API vct_status vct_image_write_pfm(const vct_image *image, const char *path, vct_error *err);
VCT_API vct_status vct_image_write_png(const vct_image *image, const char *path, float exposure,
                                       vct_error *err);
VCT_API vct_status vct_image_write(const vct_image *image, const char *path, float exposure,
                                   vct_error *err);
VCT_API vct_status vct_image_read_pfm(const char *path, vct_image *image, vct_error *err);

/* OpenEXR: linear half or 32-bit float channels. */
typedef enum vct_exr_pixel { VCT_EXR_HALF = 0, VCT_EXR_FLOAT = 1 } vct_exr_pixel;
/* One layer of an EXR file: the image's first components as channels named
 * by `channels`, one letter each ("RGB", "RGBA", "XYZ", "Y"). An empty or
 * NULL name gives the image itself (R, G, B); a name gives "name.R", ... */
typedef struct vct_exr_layer {
    const char *name;
    const vct_image *image;
    const char *channels; /* NULL: "RGB" */
} vct_exr_layer;
/* Layers of one size into one file, written to a temporary name and
 * renamed, so a failure leaves nothing. */
VCT_API vct_status vct_image_write_exr(const vct_exr_layer *layers, int count, vct_exr_pixel pixel,
                                       const char *path, vct_error *err);
/* The R, G and B channels of a scanline EXR file (alpha set to 1). */
VCT_API vct_status vct_image_read_exr(const char *path, vct_image *image, vct_error *err);
/* .pfm or .exr, by the name's ending. */
VCT_API vct_status vct_image_read(const char *path, vct_image *image, vct_error *err);

typedef struct vct_image_metrics {
    double mse, rmse;
    /* NRMSE: the RMSE over all pixels and channels divided by the
     * reference's mean (the error every accuracy goal is stated in). */
    double nrmse;
    double reference_mean, test_mean; /* over all pixels and channels */
    double relative_rmse;             /* sqrt(sum (t - r)^2 / sum r^2) */
    double relative_mse;              /* mean of (t - r)^2 / (r^2 + 0.01) */
    double mae;                       /* mean absolute error */
    double psnr;                      /* dB, peak = the reference's largest value */
    size_t nonfinite;                 /* channel values that are NaN or infinite, left out */
} vct_image_metrics;

/* Errors of `test` against `ref` over the rgb channels of every pixel. */
VCT_API vct_status vct_image_compare(const vct_image *test, const vct_image *ref,
                                     vct_image_metrics *metrics, vct_error *err);
/* Per-pixel mean absolute error as false colour (blue = 0, red >= scale;
 * scale <= 0: the largest error). The result is a displayable linear image. */
VCT_API vct_status vct_image_error_map(const vct_image *test, const vct_image *ref, double scale,
                                       vct_image *out, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
