/* The path tracer's time for the same samples through the triangle grid
 * and through the BVH (its images are the same: test_accel_images), on the
 * Cornell box and on the 102k-triangle heavy scene, in one run: the ratio
 * is what the BVH saves a whole method, shading and sampling included. */
#include "bench_util.h"
#include "check.h"
#include "heavy_scene.h"

#define SIZE 256
#define SPP 32

static double render_best(vct_context *ctx, const vct_scene *s, vct_accel_kind kind) {
    vct_error err = {0};
    const vct_accel_options o = {kind, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};
    vct_accel *a = vct_accel_build(ctx, s, &o, &err);
    if (!a)
        bench_die(&err);
    const vct_pathtrace_options po = {SIZE, SIZE, SPP, 0.0, 8, 1, 4, 0, 0, NULL, NULL, 1};
    double best = 1e30;
    for (int i = 0; i < bench_repeats(); ++i) {
        vct_image im;
        const double t0 = vct_now_ms();
        if (vct_render_pathtrace(ctx, s, a, &po, &im, NULL, &err))
            bench_die(&err);
        const double ms = vct_now_ms() - t0;
        best = ms < best ? ms : best;
        vct_image_release(&im);
    }
    vct_accel_release(a);
    return best;
}

int main(void) {
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR");
    /* the glTF box: lit by its ceiling, seen through its open side */
    vct_scene *box = check_cornell_box();
    vct_scene *heavy = heavy_scene_load(src ? src : ".", &err);
    vct_context *ctx = heavy ? vct_context_create(NULL, &err) : NULL;
    if (!ctx)
        bench_die(&err);
    printf("device: %s; path tracing %dx%d, %d spp, depth 8\n\n", ctx->info.name, SIZE, SIZE, SPP);
    printf("| scene | grid (ms) | bvh (ms) | grid / bvh time |\n|---|---:|---:|---:|\n");
    const vct_scene *scenes[2] = {box, heavy};
    const char *names[2] = {"Cornell box (30 triangles)", "heavy scene (102,430 triangles)"};
    for (int i = 0; i < 2; ++i) {
        const double grid = render_best(ctx, scenes[i], VCT_ACCEL_GRID);
        const double bvh = render_best(ctx, scenes[i], VCT_ACCEL_BVH);
        printf("| %s | %.0f | %.0f | %.2f |\n", names[i], grid, bvh, grid / bvh);
    }
    vct_context_release(ctx);
    vct_scene_release(box);
    vct_scene_release(heavy);
    return 0;
}
