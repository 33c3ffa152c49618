/* Runtime guarantees: the same scene gives the same image bit for bit (twice
 * in one context, in a fresh context, and with the other kernel shapes); a
 * warm start loads programs from the disk cache instead of compiling; images
 * hold no NaN or infinity. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "runtime/runtime.h"

static vct_image render(vct_context *ctx, const vct_scene *s) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_image im;
    vct_render_options ro = {160, 120, 0, 0, 0.0f};
    REQUIRE_OK(vct_render_raycast(ctx, s, g, &ro, &im, &err), err);
    vct_accel_release(g);
    return im;
}

static int same(const vct_image *a, const vct_image *b) {
    return a->width == b->width && a->height == b->height &&
           memcmp(a->rgba, b->rgba, 16ull * a->width * a->height) == 0;
}

static void check_finite(const vct_image *im, const char *name) {
    size_t bad = 0, lit = 0;
    for (size_t i = 0; i < 4ull * im->width * im->height; ++i) {
        bad += !isfinite(im->rgba[i]);
        lit += im->rgba[i] > 0.0f;
    }
    CHECK(bad == 0, "%s: %zu non-finite values", name, bad);
    CHECK(lit > 0, "%s: the image is black", name);
}

/* Every status has its own name; values outside the enum say so. */
static void check_status_names(void) {
    const char *expect[] = {"VCT_OK",         "VCT_ERR_OPENCL", "VCT_ERR_INPUT",
                            "VCT_ERR_MEMORY", "VCT_ERR_IO",     "VCT_ERR_OVERFLOW"};
    for (int i = 0; i < 6; ++i)
        CHECK(strcmp(vct_status_string((vct_status)i), expect[i]) == 0, "status %d is named %s", i,
              vct_status_string((vct_status)i));
    CHECK(strcmp(vct_status_string((vct_status)99), "unknown status") == 0, "status 99 is named %s",
          vct_status_string((vct_status)99));
}

/* With $VCT_CHECK_ARGS=1 an argument bound under another name than the
 * kernel's parameter is refused, naming both; the right names pass. */
static void check_argument_names(void) {
    setenv("VCT_CHECK_ARGS", "1", 1);
    vct_context *ctx = check_context();
    vct_error err = {0};
    cl_program p;
    REQUIRE_OK(vct_program_get(ctx, "parallel/scan.cl", "-D WG=64 -D ITEM_SPAN=64", &p, &err), err);
    cl_kernel k = vct_kernel_create(ctx, p, "scan_group_offsets", &err);
    REQUIRE_OK(k ? VCT_OK : err.status, err);
    cl_mem sums = vct_buffer_create(ctx, "test", "sums", 64, CL_MEM_READ_WRITE, NULL, &err);
    cl_uint groups = 1, count = 1;
    CHECK(vct_set_args(&err, "test", k, 0, 2, VCT_ARG_OF(sums), VCT_ARG_OF(groups)) == VCT_OK,
          "the kernel's own names are refused: %s", err.message);
    CHECK(vct_set_args(&err, "test", k, 0, 2, VCT_ARG_OF(sums), VCT_ARG_OF(count)) ==
                  VCT_ERR_INPUT &&
              strstr(err.message, "\"groups\"") && strstr(err.message, "count at"),
          "an argument bound under another name: %s", err.message);
    CHECK(vct_set_args(&err, "test", k, 0, 2, VCT_ARG(sums, sums), VCT_ARG(groups, count)) ==
              VCT_OK,
          "a name given with VCT_ARG is refused: %s", err.message);
    clReleaseKernel(k);
    vct_buffer_release(ctx, sums);
    vct_context_release(ctx);
}

/* The 1-based line of text's first line holding `probe` (0: none). */
static int line_of(const char *text, const char *probe) {
    const char *at = strstr(text, probe);
    if (!at)
        return 0;
    int line = 1;
    for (const char *p = text; p < at; ++p)
        line += *p == '\n';
    return line;
}

/* A compiler that ignores #line (NVIDIA's) counts the lines of the expanded
 * source: "<kernel>:LINE:" in its log must come out as the kernel file and
 * its own line, for a line of the program's file and one of a header it
 * includes; "<built-in>:N:" and other text are left as they are. */
static void check_log_locations(void) {
    vct_error err = {0};
    char *expanded = vct_kernel_source_expand("render/raycast.cl", &err);
    REQUIRE_OK(expanded ? VCT_OK : err.status, err);
    const char *probes[][2] = {{"render/raycast.cl", "__kernel void trace_rays("},
                               {"accel/accel.h", "inline int surface_hit("}};
    for (int i = 0; i < 2; ++i) {
        char path[1024];
        snprintf(path, sizeof path, "%s/kernels/%s", getenv("VCT_SOURCE_DIR"), probes[i][0]);
        char *original = vct_read_file(path, NULL);
        const int at = line_of(expanded, probes[i][1]);
        const int want = original ? line_of(original, probes[i][1]) : 0;
        if (!(at > 0 && want > 0)) {
            CHECK(0, "%s: not found in %s or in the expanded source", probes[i][1], path);
            free(original);
            continue;
        }
        char log[256], expect[256];
        snprintf(log, sizeof log, "<kernel>:%d:7: error: x\n<a> <kernel>:y: <built-in>:3: z", at);
        snprintf(expect, sizeof expect, "%s:%d:7: error: x\n<a> <kernel>:y: <built-in>:3: z",
                 probes[i][0], want);
        char *located = vct_kernel_log_locate(log, expanded);
        CHECK(located && strcmp(located, expect) == 0,
              "log \"%s\" located as \"%s\", expected \"%s\"", log, located ? located : "(null)",
              expect);
        free(located);
        free(original);
    }
    free(expanded);
}

int main(void) {
    check_status_names();
    check_log_locations();
    char cache[] = "/tmp/vct-cache-test-XXXXXX";
    if (!mkdtemp(cache))
        return 1;
    setenv("VCT_CACHE_DIR", cache, 1);
    vct_scene *s = check_cornell_box();

    /* Cold start: every program compiled. */
    vct_context *ctx = check_context();
    double t0 = vct_now_ms();
    vct_image a = render(ctx, s);
    double cold = vct_now_ms() - t0;
    int cold_misses = ctx->cache_misses, cold_hits = ctx->cache_hits;
    vct_image b = render(ctx, s);
    CHECK(same(&a, &b), "two renders in one context differ");
    check_finite(&a, "cornell box");
    vct_context_release(ctx);

    /* Warm start: a new context finds every program in the cache. */
    ctx = check_context();
    t0 = vct_now_ms();
    vct_image c = render(ctx, s);
    double warm = vct_now_ms() - t0;
    CHECK(cold_misses > 0 && cold_hits == 0, "cold start: %d compiled, %d cached", cold_misses,
          cold_hits);
    CHECK(ctx->cache_misses == 0 && ctx->cache_hits == cold_misses,
          "warm start compiled %d programs and loaded %d (expected 0 and %d)", ctx->cache_misses,
          ctx->cache_hits, cold_misses);
    CHECK(same(&a, &c), "a render in a fresh context differs");
    printf("cold start %.0f ms (%d programs compiled), warm start %.0f ms (%d loaded)\n", cold,
           cold_misses, warm, ctx->cache_hits);
    vct_context_release(ctx);

    /* The other kernel shapes (wide work-groups, local splits) sort the grid
     * identically, so the image is identical too. */
    const char *other =
        getenv("VCT_TUNING") && strcmp(getenv("VCT_TUNING"), "gpu") == 0 ? "cpu" : "gpu";
    setenv("VCT_TUNING", other, 1);
    ctx = check_context();
    vct_image d = render(ctx, s);
    CHECK(same(&a, &d), "the %s-shaped kernels give a different image", other);
    vct_context_release(ctx);

    vct_image_release(&a);
    vct_image_release(&b);
    vct_image_release(&c);
    vct_image_release(&d);
    vct_scene_release(s);
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", cache);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", cache);
    check_argument_names(); /* after the cache tests, which set the cache directory first */
    return check_exit("test_runtime");
}
