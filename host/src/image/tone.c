/* Tone mapping for displayed images (PNG files and the viewer): an exposure
 * in stops, either given or taken from the image itself, then a tone curve,
 * then sRGB encoding. PFM files stay raw linear radiance. */
#include <math.h>
#include <stddef.h>

#include "vct/image.h"

/* Middle grey: what the image's log-average luminance is exposed to. */
#define MIDDLE_GREY 0.18

vct_tone vct_tone_default(void) {
    const vct_tone t = {1, 0.0f, VCT_TONE_FILMIC};
    return t;
}

double vct_image_auto_exposure(const float *rgba, size_t pixels) {
    /* exp(mean log L) over the pixels that hold light: pixels where nothing
     * was hit (exact 0) would pull it towards black, and are left out. */
    double sum = 0.0;
    size_t lit = 0;
    for (size_t i = 0; i < pixels; ++i) {
        const double l = 0.2126 * rgba[4 * i] + 0.7152 * rgba[4 * i + 1] + 0.0722 * rgba[4 * i + 2];
        if (l > 0.0 && isfinite(l)) {
            sum += log(l);
            ++lit;
        }
    }
    return lit ? log2(MIDDLE_GREY) - sum / (double)lit / log(2.0) : 0.0;
}

float vct_tone_exposure(const vct_tone *tone, const float *rgba, size_t pixels) {
    return tone->auto_exposure ? (float)vct_image_auto_exposure(rgba, pixels) + tone->exposure
                               : tone->exposure;
}

float vct_tone_curve_apply(vct_tone_curve curve, float x) {
    if (!(x > 0.0f))
        return 0.0f;
    if (curve == VCT_TONE_FILMIC) {
        /* Narkowicz's rational fit of the ACES reference rendering
         * transform: a toe, a straight middle and a shoulder that reaches 1
         * only at infinity, so highlights roll off instead of clipping. */
        x = x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
    }
    return x < 1.0f ? x : 1.0f;
}

const char *vct_tone_curve_name(vct_tone_curve curve) {
    return curve == VCT_TONE_FILMIC ? "filmic" : "clip";
}
