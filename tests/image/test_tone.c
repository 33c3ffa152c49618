/* Tone mapping of PNG files (and so of the viewer, which shares it): the
 * automatic exposure against a log-average worked out by hand, the filmic
 * curve against its formula written out here, PNG files read back byte for
 * byte against a plain-C encoder. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <stb/stb_image.h>

#include "check.h"

static unsigned char reference_srgb8(double display) {
    if (!(display > 0.0))
        return 0;
    if (display >= 1.0)
        return 255;
    const double s = display <= 0.0031308 ? 12.92 * display : 1.055 * pow(display, 1 / 2.4) - 0.055;
    return (unsigned char)lrint(s * 255.0);
}

static double reference_filmic(double x) {
    const double y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    return y < 1.0 ? y : 1.0;
}

static void auto_exposure(void) {
    /* Grey pixels of luminance 0.5 and 2 (half each) and black ones that
     * nothing lit: the log-average is 1, so the exposure is log2(0.18). */
    float rgba[4 * 6] = {0};
    const float grey[6] = {0.5f, 2.0f, 0.0f, 0.5f, 2.0f, 0.0f};
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c)
            rgba[4 * i + c] = grey[i];
    const double stops = vct_image_auto_exposure(rgba, 6);
    CHECK(fabs(stops - log2(0.18)) < 1e-6, "auto exposure %.6f stops, expected %.6f", stops,
          log2(0.18));
    /* Luminance weighs green most: pure green of 1 is luminance 0.7152. */
    float green[4] = {0.0f, 1.0f, 0.0f, 1.0f};
    const double g = vct_image_auto_exposure(green, 1);
    CHECK(fabs(g - log2(0.18 / 0.7152)) < 1e-6, "green: %.6f stops", g);
    const float black[8] = {0};
    CHECK(vct_image_auto_exposure(black, 2) == 0.0, "a black image keeps exposure 0");
    vct_tone t = vct_tone_default();
    CHECK(t.auto_exposure && t.curve == VCT_TONE_FILMIC, "the default tone: automatic, filmic");
    t.exposure = 1.5f;
    CHECK(fabs(vct_tone_exposure(&t, rgba, 6) - (log2(0.18) + 1.5)) < 1e-5,
          "a given exposure adds to the automatic one");
    t.auto_exposure = 0;
    CHECK(vct_tone_exposure(&t, rgba, 6) == 1.5f, "without auto, the given exposure alone");
}

static void curves(void) {
    int bad = 0;
    float previous = 0.0f;
    for (int i = 0; i <= 4000; ++i) {
        const float x = 0.005f * (float)i;
        const float got = vct_tone_curve_apply(VCT_TONE_FILMIC, x);
        bad += fabs(got - reference_filmic(x)) > 1e-6 || got < previous;
        bad += vct_tone_curve_apply(VCT_TONE_CLIP, x) != (x < 1.0f ? x : 1.0f);
        previous = got;
    }
    CHECK(bad == 0, "%d curve values wrong or not rising", bad);
    CHECK(vct_tone_curve_apply(VCT_TONE_FILMIC, 0.0f) == 0.0f &&
              vct_tone_curve_apply(VCT_TONE_FILMIC, NAN) == 0.0f &&
              vct_tone_curve_apply(VCT_TONE_FILMIC, 1.0f) < 0.81f,
          "filmic: black stays black, NaN is black, 1 rolls off below white");
}

/* A ramp of radiance written through each tone and read back. */
static void png_round_trip(void) {
    const int w = 64, h = 2;
    vct_image im = {w, h, malloc(16ull * w * h)};
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < 4; ++c)
            im.rgba[4 * i + c] = c == 3 ? 1.0f : 0.002f * powf(1.15f, (float)(i % w)) * (1 + c);
    char path[64];
    snprintf(path, sizeof path, "test_tone_%d.png", (int)getpid());
    const vct_tone tones[3] = {
        {0, 0.75f, VCT_TONE_CLIP}, {0, -0.5f, VCT_TONE_FILMIC}, {1, 0.0f, VCT_TONE_FILMIC}};
    for (int t = 0; t < 3; ++t) {
        vct_error err = {0};
        float applied = 0.0f;
        REQUIRE_OK(vct_image_write_png_tone(&im, path, &tones[t], &applied, &err), err);
        int rw, rh, n;
        unsigned char *px = stbi_load(path, &rw, &rh, &n, 3);
        CHECK(px && rw == w && rh == h, "PNG %d read back", t);
        const double stops = tones[t].auto_exposure
                                 ? vct_image_auto_exposure(im.rgba, (size_t)w * h)
                                 : tones[t].exposure;
        int wrong = 0;
        for (int i = 0; px && i < w * h; ++i)
            for (int c = 0; c < 3; ++c) {
                const double x = im.rgba[4 * i + c] * exp2(stops);
                const double d =
                    tones[t].curve == VCT_TONE_FILMIC ? reference_filmic(x) : fmin(x, 1);
                wrong += abs((int)px[3 * i + c] - (int)reference_srgb8(d)) > 0;
            }
        CHECK(fabs(applied - stops) < 1e-5 && wrong == 0,
              "tone %d: %d of %d values differ from the plain-C encoder (applied %.4f, %.4f)", t,
              wrong, 3 * w * h, applied, stops);
        stbi_image_free(px);
    }
    remove(path);
    vct_image_release(&im);
}

int main(void) {
    auto_exposure();
    curves();
    png_round_trip();
    return check_exit("test_tone");
}
