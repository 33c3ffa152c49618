/* The denoiser (vct_denoise, kernels/denoise/atrous.cl) against the plain-C
 * reference (denoise_ref.h) on the same inputs, and against what a denoiser
 * must do: a noisy image of a known answer comes out closer to it; a checker
 * of albedo keeps its contrast; a lit wall beside a dark one does not bleed
 * into it; zero variance, black albedo, zero normals and pixels without a
 * surface give no NaN; the result is the same bit for bit on every run; bad
 * guides are refused. Then the path tracer at 4 spp, denoised, against its
 * own 1024-spp image. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "denoise_ref.h"

/* Device and reference agree to this, relative to the image's largest
 * value (exp, pow and sqrt round differently: a tap's weight moves a few
 * ulps, and a pixel on the firefly bound may fall either side of it). */
#define REF_TOL 5e-6

typedef struct inputs {
    int w, h;
    vct_image color, albedo, nd, variance, clean;
    int with_variance;
} inputs;

static uint32_t lcg(uint32_t *s) {
    *s = *s * 1664525u + 1013904223u;
    return *s;
}

/* Uniform in [-1, 1). */
static float noise(uint32_t *s) {
    return (float)(lcg(s) >> 8) / 8388608.0f - 1.0f;
}

static vct_image image_new(int w, int h) {
    vct_image im = {w, h, calloc((size_t)w * h, 16)};
    return im;
}

static void inputs_alloc(inputs *in, int w, int h) {
    memset(in, 0, sizeof *in);
    in->w = w;
    in->h = h;
    in->color = image_new(w, h);
    in->albedo = image_new(w, h);
    in->nd = image_new(w, h);
    in->variance = image_new(w, h);
    in->clean = image_new(w, h);
    in->with_variance = 1;
}

static void inputs_free(inputs *in) {
    vct_image_release(&in->color);
    vct_image_release(&in->albedo);
    vct_image_release(&in->nd);
    vct_image_release(&in->variance);
    vct_image_release(&in->clean);
}

static void set4(vct_image *im, int i, float a, float b, float c, float d) {
    float *p = &im->rgba[4 * i];
    p[0] = a, p[1] = b, p[2] = c, p[3] = d;
}

/* A pixel: albedo a (grey), irradiance e, relative noise amplitude k (so its
 * variance is (k e lum(a))^2 / 3 per sample, one sample), normal, depth. */
static void pixel(inputs *in, int i, float a, float e, float k, const float n[3], float z,
                  uint32_t *seed) {
    const float c = a * e;
    const float noisy = c * (1.0f + k * noise(seed));
    set4(&in->clean, i, c, c, c, 1.0f);
    set4(&in->color, i, noisy, noisy, noisy, 1.0f);
    set4(&in->albedo, i, a, a, a, 1.0f);
    set4(&in->nd, i, n[0], n[1], n[2], z);
    set4(&in->variance, i, k * k * c * c / 3.0f, 0.0f, 0.0f, 1.0f);
}

/* The normals' exponent of the next runs (0: the default, a whole number,
 * which the device raises to by squaring; others go through exp2 and log2). */
static float normal_exponent = 0.0f;

static vct_denoise_options test_options(void) {
    vct_denoise_options o = vct_denoise_options_default();
    if (normal_exponent > 0.0f)
        o.sigma_normal = normal_exponent;
    return o;
}

static int run(vct_context *ctx, const inputs *in, vct_image *out, vct_error *err) {
    const vct_denoise_guides g = {&in->albedo, &in->nd, in->with_variance ? &in->variance : NULL,
                                  NULL, 0};
    const vct_denoise_options o = test_options();
    return vct_denoise(ctx, &in->color, &g, &o, out, err);
}

static void reference(const inputs *in, ref_px *out) {
    const size_t n = (size_t)in->w * in->h;
    float *v = malloc(4 * n);
    for (size_t i = 0; i < n; ++i)
        v[i] = in->variance.rgba[4 * i];
    const vct_denoise_options o = test_options();
    const float sigma[4] = {o.sigma_luminance, o.sigma_normal, o.sigma_depth, o.firefly_sigma};
    ref_denoise((const ref_px *)in->color.rgba, (const ref_px *)in->albedo.rgba,
                (const ref_px *)in->nd.rgba, in->with_variance ? v : NULL, in->w, in->h,
                (int)o.iterations, sigma, out);
    free(v);
}

/* The device's image against the reference's: the largest difference over
 * the largest value. */
static void against_reference(vct_context *ctx, const char *name, const inputs *in) {
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, in, &out, &err), err);
    const size_t n = (size_t)in->w * in->h;
    ref_px *ref = malloc(n * sizeof *ref);
    reference(in, ref);
    double worst = 0, largest = 1e-30;
    int finite = 1;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const float r = (&ref[i].r)[c], d = out.rgba[4 * i + c];
            finite &= isfinite(d) && isfinite(r);
            worst = fmax(worst, fabs(d - r));
            largest = fmax(largest, fabs(r));
        }
    CHECK(finite, "%s: a value is not finite", name);
    CHECK(worst / largest < REF_TOL, "%s: device and reference differ by %.3g of the largest", name,
          worst / largest);
    printf("%s (%dx%d): device against reference %.2g of the largest value\n", name, in->w, in->h,
           worst / largest);
    free(ref);
    vct_image_release(&out);
}

static double nrmse(const vct_image *a, const vct_image *ref) {
    double se = 0, sum = 0;
    const size_t n = (size_t)a->width * a->height;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = a->rgba[4 * i + c] - ref->rgba[4 * i + c];
            se += d * d;
            sum += ref->rgba[4 * i + c];
        }
    return sqrt(se / (3.0 * n)) / (sum / (3.0 * n));
}

static const float facing[3] = {0, 0, 1}, sideways[3] = {1, 0, 0}, none[3] = {0, 0, 0};

/* A sloping, gently curved surface (its normal turns by 0.02 rad a pixel),
 * a checker of albedo (4-pixel cells, 0.8 and 0.2), smooth irradiance, 50 %
 * noise. */
static void checker_plane(inputs *in, int w, int h) {
    inputs_alloc(in, w, h);
    uint32_t seed = 7;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float a = ((x / 4 + y / 4) & 1) ? 0.8f : 0.2f;
            const float e = 1.0f + 0.5f * sinf(0.1f * (float)x) * cosf(0.07f * (float)y);
            const float n[3] = {sinf(0.02f * (float)x), 0.0f, cosf(0.02f * (float)x)};
            pixel(in, y * w + x, a, e, 0.5f, n, 2.0f + 0.01f * (float)x, &seed);
        }
}

static void test_checker(vct_context *ctx) {
    inputs in;
    checker_plane(&in, 48, 40);
    against_reference(ctx, "checker plane", &in);
    vct_error err = {0};
    vct_image out, again;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    const double before = nrmse(&in.color, &in.clean), after = nrmse(&out, &in.clean);
    printf("checker plane: NRMSE against the clean image %.4f noisy, %.4f denoised\n", before,
           after);
    CHECK(after < 0.3 * before, "denoised %.4f, noisy %.4f", after, before);
    /* Its light's slow waves come through: 0.0476 with a luminance weight
     * that falls off as a Gaussian of the difference in standard deviations,
     * 0.0564 where it fell off exponentially. */
    CHECK(after < 0.052, "denoised %.4f against the clean image", after);
    /* The checker's contrast: light cells over dark cells, 4 in the clean image. */
    double light = 0, dark = 0, truth_l = 0, truth_d = 0;
    for (int i = 0; i < in.w * in.h; ++i) {
        const int is_light = in.albedo.rgba[4 * i] > 0.5f;
        *(is_light ? &light : &dark) += out.rgba[4 * i];
        *(is_light ? &truth_l : &truth_d) += in.clean.rgba[4 * i];
    }
    const double contrast = (light / dark) / (truth_l / truth_d);
    printf("checker plane: contrast kept %.4f of the clean image's\n", contrast);
    CHECK(fabs(contrast - 1.0) < 0.02, "the checker's contrast is %.4f of the truth's", contrast);
    /* The same input twice, and on a fresh context: the same bits. */
    REQUIRE_OK(run(ctx, &in, &again, &err), err);
    CHECK(memcmp(out.rgba, again.rgba, 16ull * in.w * in.h) == 0, "two runs differ");
    vct_image_release(&again);
    vct_context *fresh = check_context();
    REQUIRE_OK(run(fresh, &in, &again, &err), err);
    CHECK(memcmp(out.rgba, again.rgba, 16ull * in.w * in.h) == 0, "a fresh context differs");
    vct_context_release(fresh);
    vct_image_release(&again);
    /* Without the estimator's variance: estimated, still against the reference. */
    in.with_variance = 0;
    against_reference(ctx, "checker plane, variance estimated", &in);
    vct_image_release(&out);
    inputs_free(&in);
}

/* A corner: a lit wall (irradiance 1) beside a dark one (0.1) at another
 * normal, 30 % noise. The columns beside the edge keep their own side. */
static void test_edge(vct_context *ctx) {
    inputs in;
    const int w = 40, h = 32;
    inputs_alloc(&in, w, h);
    uint32_t seed = 11;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            pixel(&in, y * w + x, 0.5f, x < w / 2 ? 1.0f : 0.1f, 0.3f,
                  x < w / 2 ? facing : sideways, 3.0f, &seed);
    against_reference(ctx, "corner", &in);
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    for (int side = 0; side < 2; ++side) {
        const int x = side ? w / 2 : w / 2 - 1;
        double mean = 0;
        for (int y = 0; y < h; ++y)
            mean += out.rgba[4 * (y * w + x)] / h;
        const double truth = in.clean.rgba[4 * x];
        printf("corner: column %d beside the edge %.4f, truth %.4f\n", x, mean, truth);
        CHECK(fabs(mean / truth - 1.0) < 0.05, "column %d: %.4f against %.4f", x, mean, truth);
    }
    vct_image_release(&out);
    inputs_free(&in);
}

/* A crease running across the image at a slant: a lit wall (albedo 0.5,
 * irradiance 1, facing) meets a dim one (albedo 0.8, irradiance 0.2,
 * sideways), 30 % noise. The pixels the crease crosses hold a share f of
 * the first wall, as a camera's rays would: f of its normal, albedo and
 * radiance. Their normals are like none of their neighbours', so the
 * passes leave them nearly as noisy as they came (30 % / sqrt 3: 17 %
 * RMS); their fit from both sides brings them within 6 %. */
static void test_crease(vct_context *ctx) {
    inputs in;
    const int w = 48, h = 40;
    inputs_alloc(&in, w, h);
    uint32_t seed = 13;
    int mixed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            /* the crease: x = 14 + 0.45 y; f, the share left of it, over 16 x 16 points */
            int left = 0;
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i)
                    left += x + (i + 0.5f) / 16.0f < 14.0f + 0.45f * (y + (j + 0.5f) / 16.0f);
            const float f = (float)left / 256.0f;
            const float a = 0.5f * f + 0.8f * (1.0f - f);
            const float c = 0.5f * f + 0.8f * 0.2f * (1.0f - f);
            const float n[3] = {(1.0f - f) * sideways[0], 0.0f, f * facing[2]};
            pixel(&in, y * w + x, 1.0f, c, 0.3f, n, 4.0f, &seed);
            set4(&in.albedo, y * w + x, a, a, a, 1.0f);
            mixed += f > 0.0f && f < 1.0f;
        }
    against_reference(ctx, "crease", &in);
    normal_exponent = 37.5f; /* mixed normals meet at cosines below 1 */
    against_reference(ctx, "crease, normals' exponent 37.5", &in);
    normal_exponent = 0.0f;
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    double se = 0.0, se_noisy = 0.0;
    for (int i = 0; i < w * h; ++i) {
        const float *n = &in.nd.rgba[4 * i];
        if (n[0] * n[0] + n[2] * n[2] > 0.999f)
            continue;
        const double truth = in.clean.rgba[4 * i];
        se += pow(out.rgba[4 * i] / truth - 1.0, 2);
        se_noisy += pow(in.color.rgba[4 * i] / truth - 1.0, 2);
    }
    const double rms = sqrt(se / mixed), rms_noisy = sqrt(se_noisy / mixed);
    printf("crease: %d mixed pixels, RMS error %.4f of their value (noisy %.4f)\n", mixed, rms,
           rms_noisy);
    CHECK(mixed > 40, "only %d pixels on the crease", mixed);
    CHECK(rms < 0.06, "the crease's pixels are off by %.4f RMS", rms);
    vct_image_release(&out);
    inputs_free(&in);
}

/* Direct light that is exact but where a shadow's edge crosses: the crease
 * of test_crease, sunlit above row 20 (radiance 1) and in shadow below (0),
 * row 20 half lit (0.5, with the spread of 16 samples that met light or
 * not), no indirect light. Filtered as the path tracer's parts, every pixel
 * whose 3x3 pixels are exact keeps its value bit for bit, and none moves
 * from the truth by more than row 20's own noise: the crease's fit over
 * 5x5 pixels would blend the lit rows with the shadowed ones. */
static void test_exact_direct(vct_context *ctx) {
    const int w = 48, h = 40, edge_row = 20;
    const float spread = 0.5f / 4.0f; /* one standard deviation of 16 samples */
    vct_image color = image_new(w, h), albedo = image_new(w, h), nd = image_new(w, h),
              variance = image_new(w, h), indirect = image_new(w, h), out;
    uint32_t seed = 17;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float f = fminf(fmaxf(x - 14.0f - 0.45f * y + 0.5f, 0.0f), 1.0f);
            const float n[3] = {f * sideways[0], 0.0f, (1.0f - f) * facing[2]};
            const float truth = y < edge_row ? 1.0f : y == edge_row ? 0.5f : 0.0f;
            const float v = y == edge_row ? truth + spread * noise(&seed) : truth;
            const float var = y == edge_row ? spread * spread : 0.0f;
            const int i = y * w + x;
            set4(&color, i, v, v, v, 1.0f);
            set4(&albedo, i, 0.6f, 0.6f, 0.6f, 1.0f);
            set4(&nd, i, n[0], n[1], n[2], 4.0f);
            set4(&variance, i, var, var, 0.0f, 1.0f);
            set4(&indirect, i, 0.0f, 0.0f, 0.0f, 1.0f);
        }
    const vct_denoise_guides g = {&albedo, &nd, &variance, &indirect, 0};
    const vct_denoise_options o = vct_denoise_options_default();
    vct_error err = {0};
    REQUIRE_OK(vct_denoise(ctx, &color, &g, &o, &out, &err), err);
    int moved = 0;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x;
            const float truth = y < edge_row ? 1.0f : y == edge_row ? 0.5f : 0.0f;
            worst = fmax(worst, fabs(out.rgba[4 * i] - truth));
            if (abs(y - edge_row) > 1)
                moved += memcmp(&out.rgba[4 * i], &color.rgba[4 * i], 12) != 0;
        }
    printf("exact direct light: %d exact pixels moved, worst %.3f from the truth\n", moved, worst);
    CHECK(moved == 0, "%d exact pixels moved", moved);
    CHECK(worst < 3.0 * spread, "a pixel moved %.3f from the truth", worst);
    vct_image *all[] = {&color, &albedo, &nd, &variance, &indirect, &out};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
}

/* Cone tracing's image: the checker plane's noisy light as its indirect
 * part, beside a rest (direct light, a specular cone) of sharp bars that no
 * filter must touch. With indirect_alone the image is the rest plus the
 * indirect part as the reference filters it alone (its variance estimated
 * from it); filtered whole, the bars would be blurred. */
static void test_indirect_alone(vct_context *ctx) {
    inputs in;
    checker_plane(&in, 48, 40);
    const int n = in.w * in.h;
    vct_image rest = image_new(in.w, in.h), total = image_new(in.w, in.h), out;
    for (int i = 0; i < n; ++i) {
        const float bar = (i % in.w) % 6 < 2 ? 3.0f : 0.0f;
        set4(&rest, i, bar, 0.5f * bar, 0.25f * bar, 1.0f);
        for (int c = 0; c < 3; ++c)
            total.rgba[4 * i + c] = rest.rgba[4 * i + c] + in.color.rgba[4 * i + c];
        total.rgba[4 * i + 3] = 1.0f;
    }
    const vct_denoise_guides g = {&in.albedo, &in.nd, NULL, &in.color, 1};
    const vct_denoise_options o = test_options();
    vct_error err = {0};
    REQUIRE_OK(vct_denoise(ctx, &total, &g, &o, &out, &err), err);
    in.with_variance = 0;
    ref_px *ref = malloc((size_t)n * sizeof *ref);
    reference(&in, ref);
    double worst = 0.0, largest = 1e-30;
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const float r = (&ref[i].r)[c];
            const float expected = rest.rgba[4 * i + c] + r;
            worst = fmax(worst, fabs(out.rgba[4 * i + c] - expected));
            largest = fmax(largest, fabs(expected));
        }
    printf("indirect light alone: device against reference %.2g of the largest value\n",
           worst / largest);
    CHECK(worst / largest < REF_TOL, "indirect alone: %.3g of the largest value from the reference",
          worst / largest);
    free(ref);
    vct_image *all[] = {&rest, &total, &out};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    inputs_free(&in);
}

/* Zero variance, black albedo, normals that cancel, pixels without a surface. */
static void test_degenerate(vct_context *ctx) {
    inputs in;
    const int w = 24, h = 16;
    inputs_alloc(&in, w, h);
    uint32_t seed = 3;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x;
            const int region = (x / 6) % 4;
            pixel(&in, i, region == 1 ? 0.0f : 0.5f, 1.0f, 0.0f, region == 2 ? none : facing,
                  region == 3 ? 0.0f : 1.0f, &seed);
            if (region == 1) /* black albedo but light (an emitter): filtered as it is */
                set4(&in.color, i, 2.0f, 2.0f, 2.0f, 1.0f);
        }
    against_reference(ctx, "degenerate guides", &in);
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    double worst = 0, worst_fitted = 0;
    int finite = 1;
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < 3; ++c) {
            finite &= isfinite(out.rgba[4 * i + c]);
            const double moved = fabs(out.rgba[4 * i + c] - in.color.rgba[4 * i + c]);
            /* normals that cancel make an edge pixel, whose fit's ridge
             * shrinks its slopes a little */
            if ((i % w) / 6 % 4 == 2)
                worst_fitted = fmax(worst_fitted, moved / in.color.rgba[4 * i + c]);
            else
                worst = fmax(worst, moved);
        }
    CHECK(finite, "a NaN or infinity from degenerate guides");
    /* No noise at all: nothing to take away. */
    CHECK(worst < 1e-5, "a noiseless image moved by %.3g", worst);
    CHECK(worst_fitted < 1e-2, "noiseless edge pixels moved by %.3g of their value", worst_fitted);
    printf("degenerate guides: noiseless pixels kept to %.2g, edge pixels to %.2g of their value\n",
           worst, worst_fitted);
    vct_image_release(&out);
    inputs_free(&in);
}

/* One path a thousand times brighter than the rest on a flat wall: clamped
 * to its neighbourhood, it does not spread into a blotch. */
static void test_firefly(vct_context *ctx) {
    inputs in;
    const int w = 32, h = 32;
    inputs_alloc(&in, w, h);
    uint32_t seed = 5;
    for (int i = 0; i < w * h; ++i)
        pixel(&in, i, 0.5f, 1.0f, 0.2f, facing, 2.0f, &seed);
    const int hot = 16 * w + 16;
    set4(&in.color, hot, 500.0f, 500.0f, 500.0f, 1.0f);
    set4(&in.variance, hot, 500.0f * 500.0f / 4.0f, 0.0f, 0.0f, 1.0f);
    against_reference(ctx, "firefly", &in);
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    float largest = 0.0f;
    for (int i = 0; i < w * h; ++i)
        largest = fmaxf(largest, out.rgba[4 * i]);
    printf("firefly: the brightest pixel after the filter %.3f (the wall 0.5)\n", largest);
    CHECK(largest < 1.0f, "a firefly of 500 left %.3f", largest);
    vct_image_release(&out);
    inputs_free(&in);
}

/* Sizes below the kernel's reach and off the work-group's. */
static void test_sizes(vct_context *ctx) {
    const int sizes[][2] = {{1, 1}, {3, 2}, {13, 7}, {64, 1}};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        inputs in;
        checker_plane(&in, sizes[s][0], sizes[s][1]);
        in.with_variance = s & 1;
        char name[64];
        snprintf(name, sizeof name, "size %dx%d", sizes[s][0], sizes[s][1]);
        against_reference(ctx, name, &in);
        inputs_free(&in);
    }
}

/* Pixels of every kind at random: surfaces of random albedo (some black)
 * facing random ways (some normals cancelled), no surface, emitters, noise
 * and variance of every size. */
static void mixed_pixels(inputs *in, int w, int h, uint32_t seed) {
    inputs_alloc(in, w, h);
    for (int i = 0; i < w * h; ++i) {
        const uint32_t kind = lcg(&seed) % 8u;
        const float n[3] = {noise(&seed), noise(&seed), noise(&seed)};
        const float a = kind == 0 ? 0.0f : 0.5f + 0.5f * noise(&seed);
        pixel(in, i, a, 1.0f + noise(&seed), 0.8f, kind == 1 ? none : n,
              kind == 2 ? 0.0f : 3.0f + noise(&seed), &seed);
        if (kind == 3) /* an emitter seen */
            in->albedo.rgba[4 * i + 3] = 0.0f;
        if (kind == 4)
            in->variance.rgba[4 * i] = 0.0f;
    }
}

/* The pass in vector lanes (16 pixels of a row per work-item, CPU devices)
 * against the pass a pixel per work-item (the kernels built with
 * VCT_PACKETS=0, as for GPUs): the same image bit for bit, at widths that
 * leave a row's last lanes empty and taps 8 pixels out past its ends, with
 * and without the estimator's variance, the normals' exponent whole and not. */
static void test_lanes(vct_context *ctx) {
    const int sizes[][2] = {{37, 23}, {16, 5}, {3, 9}, {100, 40}};
    vct_context *plain = check_context();
    for (int e = 0; e < 2; ++e) {
        normal_exponent = e ? 127.5f : 0.0f;
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
            inputs in;
            mixed_pixels(&in, sizes[s][0], sizes[s][1], 7u + (uint32_t)s);
            in.with_variance = (s + e) & 1;
            vct_error err = {0};
            vct_image lanes, one;
            REQUIRE_OK(run(ctx, &in, &lanes, &err), err);
            setenv("VCT_PACKETS", "0", 1); /* read where the kernels are built */
            REQUIRE_OK(run(plain, &in, &one, &err), err);
            unsetenv("VCT_PACKETS");
            const size_t bytes = 16ull * in.w * in.h;
            CHECK(memcmp(lanes.rgba, one.rgba, bytes) == 0,
                  "%dx%d (exponent %g): the pass in lanes changes the image", in.w, in.h,
                  normal_exponent);
            vct_image_release(&lanes);
            vct_image_release(&one);
            inputs_free(&in);
        }
    }
    normal_exponent = 0.0f;
    vct_context_release(plain);
    printf("lanes: the same images with 16 pixels a work-item and one (4 sizes, 2 exponents)\n");
}

static void test_refusals(vct_context *ctx) {
    inputs in;
    checker_plane(&in, 16, 8);
    vct_error err = {0};
    vct_image out, small = image_new(8, 8);
    vct_denoise_guides g = {&in.albedo, &small, NULL, NULL, 0};
    vct_denoise_options o = vct_denoise_options_default();
    CHECK(vct_denoise(ctx, &in.color, &g, &o, &out, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "normal and depth guide is 8x8"),
          "a guide of another size: %s", err.message);
    g.normal_depth = &in.nd;
    o.iterations = 0;
    CHECK(vct_denoise(ctx, &in.color, &g, &o, &out, &err) == VCT_ERR_INPUT, "0 passes accepted");
    vct_image_release(&small);
    inputs_free(&in);
}

/* What filtering the light's parts apart must gain on the Cornell box at
 * 4 spp, against filtering it whole (measured: see test_pathtrace). */
#define PARTS_GAIN 0.9

/* The path tracer at 4 spp with its variance and the guides, denoised,
 * against 1024 spp of the same scene: whole, and its direct and indirect
 * parts apart (the point light's direct light is sharp and nearly
 * noiseless, the indirect light smooth and noisy: apart, each is filtered
 * as far as its own variance allows); then at 1 spp, whose variance is
 * unknown. */
static void test_pathtrace(vct_context *ctx) {
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/scenes/cornell_box.gltf", src ? src : ".");
    vct_scene *s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const int size = 48;
    vct_render_job job = vct_render_job_default(VCT_METHOD_PATHTRACE, size, size);
    job.scene = s;
    job.accel = g;
    vct_image reference, noisy, variance, albedo, nd, denoised, indirect, parts;
    job.pathtrace.spp = 1024;
    REQUIRE_OK(vct_render(ctx, &job, &reference, NULL, &err), err);
    job.pathtrace.spp = 4;
    job.pathtrace.seed = 1;
    job.pathtrace.variance = &variance;
    job.pathtrace.indirect = &indirect;
    REQUIRE_OK(vct_render(ctx, &job, &noisy, NULL, &err), err);
    REQUIRE_OK(vct_render_guides(ctx, s, g, size, size, 4, &albedo, &nd, &err), err);
    const vct_denoise_guides guides = {&albedo, &nd, &variance, NULL, 0},
                             apart = {&albedo, &nd, &variance, &indirect, 0};
    const vct_denoise_options o = vct_denoise_options_default();
    REQUIRE_OK(vct_denoise(ctx, &noisy, &guides, &o, &denoised, &err), err);
    REQUIRE_OK(vct_denoise(ctx, &noisy, &apart, &o, &parts, &err), err);
    const double before = nrmse(&noisy, &reference), after = nrmse(&denoised, &reference),
                 after_parts = nrmse(&parts, &reference);
    printf("Cornell box %d^2, 4 spp: direct and indirect light denoised apart %.4f, whole %.4f\n",
           size, after_parts, after);
    CHECK(after_parts < PARTS_GAIN * after, "apart %.4f, whole %.4f", after_parts, after);
    vct_image_release(&parts);
    vct_image_release(&indirect);
    double mean_d = 0, mean_r = 0, var_mean = 0;
    for (int i = 0; i < size * size; ++i) {
        mean_d += denoised.rgba[4 * i];
        mean_r += reference.rgba[4 * i];
        var_mean += variance.rgba[4 * i] / (size * size);
    }
    printf("Cornell box %d^2: NRMSE against 1024 spp: 4 spp %.4f, denoised %.4f; mean %.4f of "
           "the reference's\n",
           size, before, after, mean_d / mean_r);
    CHECK(var_mean > 0.0, "the path tracer's variance is all 0");
    CHECK(after < 0.5 * before, "denoised %.4f, noisy %.4f", after, before);
    CHECK(fabs(mean_d / mean_r - 1.0) < 0.03, "the mean moved to %.4f", mean_d / mean_r);
    /* One sample: the path tracer cannot know its spread (-1), so the
     * filter estimates it from the image instead of taking the image for
     * exact. */
    vct_image_release(&noisy);
    vct_image_release(&variance);
    vct_image_release(&denoised);
    job.pathtrace.spp = 1;
    REQUIRE_OK(vct_render(ctx, &job, &noisy, NULL, &err), err);
    CHECK(variance.rgba[0] == -1.0f, "one sample's variance is %g, not -1 (unknown)",
          variance.rgba[0]);
    REQUIRE_OK(vct_denoise(ctx, &noisy, &guides, &o, &denoised, &err), err);
    const double before1 = nrmse(&noisy, &reference), after1 = nrmse(&denoised, &reference);
    printf("Cornell box %d^2: 1 spp %.4f, denoised %.4f\n", size, before1, after1);
    CHECK(after1 < 0.4 * before1, "1 spp denoised %.4f, noisy %.4f", after1, before1);
    vct_image *all[] = {&reference, &noisy, &variance, &albedo, &nd, &denoised};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* A ceiling (albedo 0.5, irradiance 1, 30 % noise) with a small black
 * panel in it, seen directly: its 3x3 pixels emit 400 (the albedo guide's w
 * 0), the ring around them half covered (200, albedo 0.25, w 0.5, and the
 * variance of 4 rays that met the panel or not), as a 4 spp path tracer's
 * pixels show a lamp. The panel's pixels keep their colour, bit for bit,
 * and lend no light to the ceiling: every ceiling pixel within 40 % of its
 * clean value (spread, the panel lit the ceiling around it at 30 to 90
 * times its light). */
static void test_emitter(vct_context *ctx) {
    inputs in;
    const int w = 32, h = 24, cx = 15, cy = 11;
    inputs_alloc(&in, w, h);
    uint32_t seed = 5;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x, ring = abs(x - cx) > abs(y - cy) ? abs(x - cx) : abs(y - cy);
            pixel(&in, i, 0.5f, 1.0f, 0.3f, facing, 3.0f, &seed);
            if (ring <= 1) { /* the panel: black but for its light */
                set4(&in.color, i, 400.0f, 400.0f, 400.0f, 1.0f);
                set4(&in.albedo, i, 0.0f, 0.0f, 0.0f, 0.0f);
                set4(&in.variance, i, 0.0f, 0.0f, 0.0f, 1.0f);
            } else if (ring == 2) { /* half of it, as 4 rays saw it: 400^2 / 16 */
                set4(&in.color, i, 200.0f, 200.0f, 200.0f, 1.0f);
                set4(&in.albedo, i, 0.25f, 0.25f, 0.25f, 0.5f);
                set4(&in.variance, i, 1e4f, 0.0f, 0.0f, 1.0f);
            }
        }
    against_reference(ctx, "ceiling panel", &in);
    vct_error err = {0};
    vct_image out;
    REQUIRE_OK(run(ctx, &in, &out, &err), err);
    int kept = 1;
    double worst = 0.0;
    for (int i = 0; i < w * h; ++i) {
        if (in.albedo.rgba[4 * i + 3] < 1.0f) {
            kept &= memcmp(&out.rgba[4 * i], &in.color.rgba[4 * i], 12) == 0;
            continue;
        }
        worst = fmax(worst, fabs(out.rgba[4 * i] / in.clean.rgba[4 * i] - 1.0));
    }
    CHECK(kept, "the panel's pixels changed");
    CHECK(worst < 0.4, "a ceiling pixel is off its clean value by %.3f of it", worst);
    printf("ceiling panel: its pixels kept; the ceiling within %.3f of its clean value\n", worst);
    vct_image_release(&out);
    inputs_free(&in);
}

int main(void) {
    vct_context *ctx = check_context();
    test_checker(ctx);
    test_edge(ctx);
    test_crease(ctx);
    test_exact_direct(ctx);
    test_indirect_alone(ctx);
    test_emitter(ctx);
    test_degenerate(ctx);
    test_firefly(ctx);
    test_sizes(ctx);
    test_lanes(ctx);
    test_refusals(ctx);
    test_pathtrace(ctx);
    vct_context_release(ctx);
    return check_exit("test_denoise");
}
