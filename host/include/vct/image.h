/* vct: images: linear radiance on the host, files and error metrics. */
#ifndef VCT_API_IMAGE_H
#define VCT_API_IMAGE_H

#include <stddef.h>

#include "vct/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_image {
    int width, height;
    float *rgba; /* linear radiance, width*height*4 */
} vct_image;

void vct_image_free(vct_image *image);

/* PFM: raw linear radiance. PNG: radiance * 2^exposure, clamped, sRGB encoded.
 * Written to a temporary file and renamed, so a failure leaves nothing. */
int vct_image_write_pfm(const vct_image *image, const char *path, vct_error *err);
int vct_image_write_png(const vct_image *image, const char *path, float exposure, vct_error *err);
int vct_image_write(const vct_image *image, const char *path, float exposure, vct_error *err);
int vct_image_read_pfm(const char *path, vct_image *image, vct_error *err);

typedef struct vct_image_metrics {
    double mse, rmse;
    double relative_rmse; /* sqrt(sum (t - r)^2 / sum r^2) */
    double relative_mse;  /* mean of (t - r)^2 / (r^2 + 0.01) */
    double mae;           /* mean absolute error */
    double psnr;          /* dB, peak = the reference's largest value */
    size_t nonfinite;     /* channel values that are NaN or infinite, left out */
} vct_image_metrics;

/* Errors of `test` against `ref` over the rgb channels of every pixel. */
int vct_image_compare(const vct_image *test, const vct_image *ref, vct_image_metrics *metrics,
                      vct_error *err);
/* Per-pixel mean absolute error as false colour (blue = 0, red >= scale;
 * scale <= 0: the largest error). The result is a displayable linear image. */
int vct_image_error_map(const vct_image *test, const vct_image *ref, double scale, vct_image *out,
                        vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
