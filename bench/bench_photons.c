/* Photon mapping's costs, beside seed 000's GT 640 figures (Table 6.4:
 * photon tracing; Tables 6.5-6.6: photon grid build):
 *   1. photons traced per second, photon-grid build and gather time per
 *      frame at 250k, 1M and 6M photons (passes of 2^18 photons) on the
 *      Cornell box with two boxes and on the glass-and-mirror box, 512 x 512;
 *   2. on the glass-and-mirror box, the time progressive photon mapping and
 *      the path tracer take to reach an error in the caustic region (the
 *      pixels where the caustic map brings most of the light), against a
 *      path-traced reference (whose own noise sets a floor under both).
 *
 * usage: bench_photons [--reference REF.pfm] [--reference-spp N] [--size W H]
 * (run from the source tree, or with VCT_SOURCE_DIR set, after
 * python3 scenes/suite/make_suite.py has written the suite's scenes). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "check.h"

#define PASS_PHOTONS (1u << 18)

static vct_scene *load(const char *relative) {
    const char *src = getenv("VCT_SOURCE_DIR") ? getenv("VCT_SOURCE_DIR") : ".";
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", src, relative);
    vct_error err = {0};
    vct_scene *s = vct_scene_load(path, &err);
    if (!s) {
        fprintf(stderr,
                "bench_photons: %s (the suite's scenes are written by "
                "python3 scenes/suite/make_suite.py)\n",
                err.message);
        exit(1);
    }
    return s;
}

static void throughput(vct_context *ctx, const char *name, const vct_scene *s) {
    static const uint32_t totals[] = {250000, 1000000, 6000000};
    static const double gt640_ms[2][3] = {{61.40, 242.81, 1444.95}, {223.71, 879.41, 5246.84}};
    const int row = strstr(name, "glass") != NULL; /* beside the seed's 2 spheres scene */
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    if (!a)
        bench_die(&err);
    printf("\n%s, 512 x 512, passes of %u photons, fixed radii:\n", name, PASS_PHOTONS);
    printf("| photons | passes | traced M/s | stored per photon | trace ms | grid ms / pass | "
           "gather ms / pass | GT 640 trace ms (seed, %s) |\n|---|---|---|---|---|---|---|---|\n",
           row ? "2 spheres" : "2 boxes");
    for (int i = 0; i < 3; ++i) {
        vct_pm_options o = vct_pm_options_default(512, 512);
        o.photons_per_pass = PASS_PHOTONS;
        o.passes = (totals[i] + PASS_PHOTONS - 1) / PASS_PHOTONS;
        o.fixed_radius = 1;
        vct_pm_result r;
        vct_image im;
        vct_stats_reset(ctx); /* a long event record slows every launch */
        if (vct_render_pm(ctx, s, a, &o, &im, &r, &err))
            bench_die(&err);
        const double stored = (double)(r.photons_stored[0] + r.photons_stored[1]);
        printf("| %llu | %u | %.2f | %.2f | %.1f | %.1f | %.1f | %.2f |\n",
               (unsigned long long)r.photons_emitted, r.passes,
               r.photons_emitted / (r.trace_ms * 1e3), stored / r.photons_emitted, r.trace_ms,
               r.grid_ms / r.passes, r.gather_ms / r.passes, gt640_ms[row][i]);
        vct_image_release(&im);
    }
    vct_accel_release(a);
}

/* RMS error over the masked pixels' channels, relative to their mean in ref. */
static double region_error(const vct_image *im, const vct_image *ref, const unsigned char *mask) {
    double e2 = 0.0, sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)ref->width * ref->height; ++i)
        if (mask[i])
            for (int c = 0; c < 3; ++c) {
                const double d = im->rgba[4 * i + c] - ref->rgba[4 * i + c];
                e2 += d * d;
                sum += ref->rgba[4 * i + c];
                ++n;
            }
    return n ? sqrt(e2 / n) / (sum / n) : 0.0;
}

/* Time (ms) at which the log-log line through the (time, error) points
 * reaches `target` (0 when it never does). */
static double time_to(const double *t, const double *e, int n, double target) {
    for (int i = 0; i < n; ++i) {
        if (e[i] > target)
            continue;
        if (i == 0)
            return t[0];
        const double f = log(e[i - 1] / target) / log(e[i - 1] / e[i]);
        return exp(log(t[i - 1]) + f * log(t[i] / t[i - 1]));
    }
    return 0.0;
}

static void caustic_race(vct_context *ctx, const vct_scene *s, const char *ref_path, int w, int h,
                         uint32_t ref_spp) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    if (!a)
        bench_die(&err);
    vct_image ref;
    if (ref_path) {
        if (vct_image_read_pfm(ref_path, &ref, &err))
            bench_die(&err);
        w = ref.width;
        h = ref.height;
    } else {
        fprintf(stderr, "reference: path tracing, %u spp at %dx%d...\n", ref_spp, w, h);
        vct_pathtrace_options po = {w, h, ref_spp, 0.0, 16, 0x5eed, 16, 0, 0, NULL, NULL, 1};
        if (vct_render_pathtrace(ctx, s, a, &po, &ref, NULL, &err))
            bench_die(&err);
        vct_image_write_pfm(&ref, "bench_photons_reference.pfm", &err);
    }
    /* The caustic region: where the caustic map gives over half the light. */
    vct_pm_options o = vct_pm_options_default(w, h);
    o.passes = 32;
    vct_image all, caustic;
    if (vct_render_pm(ctx, s, a, &o, &all, NULL, &err))
        bench_die(&err);
    o.components = VCT_PM_CAUSTIC;
    if (vct_render_pm(ctx, s, a, &o, &caustic, NULL, &err))
        bench_die(&err);
    unsigned char *mask = calloc((size_t)w * h, 1);
    size_t region = 0;
    for (size_t i = 0; i < (size_t)w * h; ++i)
        if (caustic.rgba[4 * i] > 0.5f * all.rgba[4 * i] && all.rgba[4 * i] > 0.0f)
            mask[i] = 1, ++region;
    printf("\ncaustic region of the glass-and-mirror box: %zu of %d pixels\n", region, w * h);
    printf("| method | setting | ms | caustic-region error | whole-image NRMSE |\n"
           "|---|---|---|---|---|\n");
    double tp[8], ep[8], tt[8], et[8];
    int np = 0, nt = 0;
    o.components = 0;
    for (uint32_t passes = 2; passes <= 128 && np < 8; passes *= 2, ++np) {
        o.passes = passes;
        vct_stats_reset(ctx);
        vct_image im;
        if (vct_render_pm(ctx, s, a, &o, &im, NULL, &err))
            bench_die(&err);
        vct_image_metrics m;
        vct_image_compare(&im, &ref, &m, &err);
        tp[np] = stage_device_ms(ctx, "photon mapping");
        ep[np] = region_error(&im, &ref, mask);
        printf("| progressive photon mapping | %u passes | %.1f | %.4f | %.4f |\n", passes, tp[np],
               ep[np], m.nrmse);
        vct_image_release(&im);
    }
    for (uint32_t spp = 4; spp <= 4096 && nt < 8; spp *= 4, ++nt) {
        vct_pathtrace_options po = {w, h, spp, 0.0, 16, 1, 16, 0, 0, NULL, NULL, 1};
        vct_stats_reset(ctx);
        vct_image im;
        if (vct_render_pathtrace(ctx, s, a, &po, &im, NULL, &err))
            bench_die(&err);
        vct_image_metrics m;
        vct_image_compare(&im, &ref, &m, &err);
        tt[nt] = stage_device_ms(ctx, "path trace");
        et[nt] = region_error(&im, &ref, mask);
        printf("| path tracing | %u spp | %.1f | %.4f | %.4f |\n", spp, tt[nt], et[nt], m.nrmse);
        vct_image_release(&im);
    }
    static const double targets[] = {0.4, 0.3, 0.25, 0.2, 0.15};
    for (size_t i = 0; i < sizeof targets / sizeof targets[0]; ++i) {
        const double target = targets[i];
        const double a_ms = time_to(tp, ep, np, target), b_ms = time_to(tt, et, nt, target);
        printf("caustic-region error %.2f: photon mapping %.0f ms, path tracing %.0f ms%s", target,
               a_ms, b_ms, a_ms > 0 && b_ms > 0 ? "" : " (not reached in the runs)\n");
        if (a_ms > 0 && b_ms > 0)
            printf(" (%.1fx sooner)\n", b_ms / a_ms);
    }
    free(mask);
    vct_image_release(&all);
    vct_image_release(&caustic);
    vct_image_release(&ref);
    vct_accel_release(a);
}

int main(int argc, char **argv) {
    const char *ref = NULL;
    int w = 128, h = 128;
    uint32_t ref_spp = 8192;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--reference") == 0 && i + 1 < argc)
            ref = argv[++i];
        else if (strcmp(argv[i], "--reference-spp") == 0 && i + 1 < argc)
            ref_spp = (uint32_t)atoi(argv[++i]);
        else if (strcmp(argv[i], "--size") == 0 && i + 2 < argc) {
            w = atoi(argv[++i]);
            h = atoi(argv[++i]);
        } else {
            fprintf(stderr, "usage: bench_photons [--reference REF.pfm] [--reference-spp N] "
                            "[--size W H]\n");
            return 2;
        }
    }
    vct_error err = {0};
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    printf("device: %s\n", ctx->info.name);
    vct_scene *cornell = load("scenes/cornell_box.gltf");
    vct_scene *glass = load("scenes/suite/glass_mirror_box.gltf");
    throughput(ctx, "Cornell box with two boxes", cornell);
    throughput(ctx, "glass-and-mirror box", glass);
    caustic_race(ctx, glass, ref, w, h, ref_spp);
    vct_scene_release(cornell);
    vct_scene_release(glass);
    vct_context_release(ctx);
    return 0;
}
