/* Image error metrics against a reference, and a false-colour error image. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"

/* Relative MSE uses (ref^2 + eps) so that black reference pixels do not
 * dominate; eps = 1e-2 as is customary for rendering comparisons. */
#define REL_MSE_EPS 1e-2

vct_status vct_image_compare(const vct_image *test, const vct_image *ref, vct_image_metrics *m,
                             vct_error *err) {
    memset(m, 0, sizeof *m);
    if (test->width != ref->width || test->height != ref->height)
        return vct_fail(err, VCT_ERR_INPUT, "compare: image sizes differ (%dx%d vs %dx%d)",
                        test->width, test->height, ref->width, ref->height);
    const size_t pixels = (size_t)ref->width * ref->height;
    double se = 0.0, rel = 0.0, ae = 0.0, peak = 0.0, ref_sq = 0.0, ref_sum = 0.0, test_sum = 0.0;
    size_t nonfinite = 0;
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            double t = test->rgba[4 * i + c], r = ref->rgba[4 * i + c];
            if (!isfinite(t) || !isfinite(r)) {
                ++nonfinite;
                continue;
            }
            double d = t - r;
            se += d * d;
            ae += fabs(d);
            rel += d * d / (r * r + REL_MSE_EPS);
            ref_sq += r * r;
            ref_sum += r;
            test_sum += t;
            peak = fmax(peak, r);
        }
    }
    const double n = fmax(3.0 * (double)pixels - (double)nonfinite, 1.0);
    m->mse = se / n;
    m->rmse = sqrt(m->mse);
    m->relative_rmse = ref_sq > 0.0 ? sqrt(se / ref_sq) : 0.0;
    m->reference_mean = ref_sum / n;
    m->test_mean = test_sum / n;
    m->nrmse = ref_sum > 0.0 ? m->rmse / m->reference_mean : 0.0;
    m->relative_mse = rel / n;
    m->mae = ae / n;
    m->psnr = m->mse > 0.0 && peak > 0.0 ? 10.0 * log10(peak * peak / m->mse) : INFINITY;
    m->nonfinite = nonfinite;
    return VCT_OK;
}

/* A blue -> cyan -> green -> yellow -> red ramp over [0, 1]. */
static void ramp(double x, float *rgb) {
    static const float stops[5][3] = {{0.0f, 0.0f, 0.5f},
                                      {0.0f, 0.8f, 1.0f},
                                      {0.1f, 0.9f, 0.2f},
                                      {1.0f, 0.9f, 0.0f},
                                      {0.9f, 0.0f, 0.0f}};
    x = fmin(fmax(x, 0.0), 1.0) * 4.0;
    int i = (int)fmin(floor(x), 3.0);
    float f = (float)(x - i);
    for (int c = 0; c < 3; ++c)
        rgb[c] = stops[i][c] + f * (stops[i + 1][c] - stops[i][c]);
}

vct_status vct_image_error_map(const vct_image *test, const vct_image *ref, double scale,
                               vct_image *out, vct_error *err) {
    memset(out, 0, sizeof *out);
    if (test->width != ref->width || test->height != ref->height)
        return vct_fail(err, VCT_ERR_INPUT, "compare: image sizes differ (%dx%d vs %dx%d)",
                        test->width, test->height, ref->width, ref->height);
    const size_t pixels = (size_t)ref->width * ref->height;
    double *e = malloc(sizeof *e * (pixels ? pixels : 1));
    out->rgba = malloc(16 * (pixels ? pixels : 1));
    if (!e || !out->rgba) {
        free(e);
        vct_image_release(out);
        return vct_fail(err, VCT_ERR_MEMORY, "compare: out of host memory");
    }
    out->width = ref->width;
    out->height = ref->height;
    double max_e = 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        double s = 0.0;
        for (int c = 0; c < 3; ++c) {
            double d = (double)test->rgba[4 * i + c] - ref->rgba[4 * i + c];
            s += isfinite(d) ? fabs(d) : INFINITY;
        }
        e[i] = s / 3.0;
        if (isfinite(e[i]))
            max_e = fmax(max_e, e[i]);
    }
    if (!(scale > 0.0))
        scale = max_e > 0.0 ? max_e : 1.0;
    for (size_t i = 0; i < pixels; ++i) {
        ramp(isfinite(e[i]) ? e[i] / scale : 1.0, &out->rgba[4 * i]);
        out->rgba[4 * i + 3] = 1.0f;
    }
    free(e);
    return VCT_OK;
}
