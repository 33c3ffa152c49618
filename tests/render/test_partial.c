/* A render in parts (vct/partial.h), as a host spreading a frame over
 * processes would make it: bands cut where vct_band_shape says and put
 * together give the whole image, bit for bit, for the ray caster and
 * Whitted (subsampled), and cone tracing (edge samples, sparse diffuse);
 * ranges of the path tracer's samples rendered apart, added in any order
 * and resolved give the image of one render. Misuse is refused. */
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define WIDTH 40
#define HEIGHT 37 /* not a multiple of any band alignment */

static vct_context *ctx;
static vct_device_scene *ds;

static vct_render_job job_for(vct_method method) {
    vct_render_job job = vct_render_job_default(method, WIDTH, HEIGHT);
    job.voxel_options.resolution = 32;
    job.bounces = 1;
    job.pathtrace.spp = 7;
    job.pathtrace.seed = 3;
    return job;
}

static vct_image whole(const vct_render_job *job) {
    vct_error err = {0};
    vct_image im;
    REQUIRE_OK(vct_device_scene_render(ds, job, &im, NULL, &err), err);
    return im;
}

/* The image from `parts` bands, each starting on the alignment and
 * rendering its halos, its own rows copied into place. */
static vct_image from_bands(const vct_render_job *job, int parts) {
    vct_error err = {0};
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    vct_image out = {0};
    out.width = WIDTH;
    out.height = HEIGHT;
    out.rgba = calloc(4 * (size_t)WIDTH * HEIGHT, sizeof(float));
    if (!out.rgba)
        abort(); /* out of host memory */
    const int units = (HEIGHT + align - 1) / align;
    for (int p = 0; p < parts; ++p) {
        const int first = units * p / parts * align;
        int end = units * (p + 1) / parts * align;
        end = end < HEIGHT ? end : HEIGHT;
        if (end <= first)
            continue;
        const int from = first - above > 0 ? first - above : 0;
        const int to = end + below < HEIGHT ? end + below : HEIGHT;
        vct_render_job band = *job;
        band.height = to - from;
        band.band.first = from;
        band.band.height = HEIGHT;
        vct_image im;
        REQUIRE_OK(vct_device_scene_render(ds, &band, &im, NULL, &err), err);
        memcpy(out.rgba + 4 * (size_t)first * WIDTH, im.rgba + 4 * (size_t)(first - from) * WIDTH,
               4 * sizeof(float) * (size_t)(end - first) * WIDTH);
        vct_image_release(&im);
    }
    return out;
}

static void check_bands(const char *name, const vct_render_job *job) {
    vct_image one = whole(job);
    for (int parts = 2; parts <= 5; parts += 3) {
        vct_image put = from_bands(job, parts);
        const size_t n = check_differing(&one, &put);
        CHECK(n == 0, "%s in %d bands: %zu values differ from the whole image", name, parts, n);
        vct_image_release(&put);
    }
    int align, above, below;
    vct_band_shape(job, &align, &above, &below);
    printf("%s: 2 and 5 bands (align %d, halo %d above, %d below) equal the whole image\n", name,
           align, above, below);
    vct_image_release(&one);
}

static vct_sample_sums samples(const vct_render_job *job, uint32_t first, uint32_t count) {
    vct_error err = {0};
    vct_sample_sums s;
    REQUIRE_OK(vct_device_scene_render_samples(ds, job, first, count, &s, &err), err);
    return s;
}

static void check_samples(void) {
    vct_error err = {0};
    const vct_render_job job = job_for(VCT_METHOD_PATHTRACE);
    vct_image one = whole(&job);
    /* [0, 2) + [2, 3) + [3, 7), added last range first */
    vct_sample_sums total = samples(&job, 3, 4), a = samples(&job, 0, 2), b = samples(&job, 2, 1);
    REQUIRE_OK(vct_sample_sums_add(&total, &b, &err), err);
    REQUIRE_OK(vct_sample_sums_add(&total, &a, &err), err);
    CHECK(total.samples == 7, "the sums hold %u samples, expected 7", total.samples);
    vct_image put;
    REQUIRE_OK(vct_device_scene_resolve_samples(ds, &job, &total, &put, &err), err);
    const size_t n = check_differing(&one, &put);
    CHECK(n == 0, "samples in 3 ranges: %zu values differ from one render of 7", n);
    printf("path tracer: 7 samples in 3 ranges, added out of order, equal one render\n");
    vct_image_release(&put);

    /* refused: sums of another size, a job of another method, a PT band */
    vct_render_job small = job;
    small.width = WIDTH / 2;
    vct_sample_sums other = samples(&small, 0, 1);
    CHECK(vct_sample_sums_add(&total, &other, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "do not add"),
          "sums of two sizes added: %s", err.message);
    CHECK(vct_device_scene_resolve_samples(ds, &job, &other, &put, &err) == VCT_ERR_INPUT,
          "sums of another size resolved");
    vct_render_job raycast = job_for(VCT_METHOD_RAYCAST);
    CHECK(vct_device_scene_render_samples(ds, &raycast, 0, 1, &other, &err) == VCT_ERR_INPUT &&
              other.data == NULL,
          "samples of the ray caster: %s", err.message);
    vct_render_job band = job;
    band.band.height = 2 * HEIGHT;
    CHECK(vct_device_scene_render(ds, &band, &put, NULL, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "not bands"),
          "a band of the path tracer: %s", err.message);
    vct_render_job pm = job_for(VCT_METHOD_PM);
    pm.band.height = 2 * HEIGHT;
    CHECK(vct_device_scene_render(ds, &pm, &put, NULL, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "pass_sync"),
          "a band of photon mapping without pass_sync: %s", err.message);
    vct_sample_sums_release(&other);
    vct_sample_sums_release(&a);
    vct_sample_sums_release(&b);
    vct_sample_sums_release(&total);
    vct_image_release(&one);
}

int main(void) {
    ctx = check_context();
    vct_scene *s = check_cornell_box_point_light();
    vct_error err = {0};
    ds = vct_device_scene_create(ctx, s, &err);
    REQUIRE_OK(ds ? VCT_OK : err.status, err);

    vct_render_job job = job_for(VCT_METHOD_RAYCAST);
    job.raycast.subsample = 4;
    check_bands("ray caster, subsample 4", &job);
    job = job_for(VCT_METHOD_WHITTED);
    job.whitted.subsample = 8;
    check_bands("Whitted, subsample 8", &job);
    job = job_for(VCT_METHOD_VCT);
    check_bands("cone tracing", &job);
    job.vct.sparse_diffuse = 1;
    check_bands("cone tracing, sparse diffuse", &job);
    check_samples();

    vct_device_scene_release(ds);
    vct_scene_release(s);
    vct_context_release(ctx);
    return check_exit("test_partial");
}
