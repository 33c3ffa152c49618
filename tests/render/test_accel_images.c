/* Every method renders the same image, bit for bit, whether its rays go
 * through the BVH or the triangle grid: both report the same closest hit
 * (the same watertight test on the same triangle), and any hit only answers
 * "blocked or not". Scenes: the Cornell box with a point light, and the
 * glTF Cornell box, lit by its emissive ceiling. */
#include <string.h>

#include "check.h"

#define SIZE 48

static vct_context *ctx;

static vct_image render(const vct_scene *s, vct_method method, vct_accel_kind kind) {
    vct_error err = {0};
    const vct_accel_options o = {kind, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};
    vct_accel *a = vct_accel_build(ctx, s, &o, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_image im;
    if (method == VCT_METHOD_VCT) {
        vct_plan plan;
        vct_plan_make(s, NULL, &plan);
        vct_voxel_options vo = {0};
        vo.resolution = 32;
        const vct_brick_options bo = {VCT_BRICKS_AUTO, 1, 0};
        vct_vct_options vopt = vct_vct_options_default(512, 512);
        vopt.width = vopt.height = SIZE;
        vct_voxels *v = NULL;
        REQUIRE_OK(vct_vct_prepare(ctx, s, a, &plan, &vo, &bo, 1, &vopt.cones, &v, &err), err);
        REQUIRE_OK(vct_render_vct(ctx, s, a, v, &plan, &vopt, &im, NULL, &err), err);
        vct_voxels_release(v);
    } else {
        vct_render_job job = vct_render_job_default(method, SIZE, SIZE);
        job.scene = s;
        job.accel = a;
        job.pathtrace.spp = 8;
        job.pathtrace.seed = 3;
        REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    }
    vct_accel_release(a);
    return im;
}

static void check_scene(const char *name, const vct_scene *s) {
    const vct_method methods[] = {VCT_METHOD_RAYCAST, VCT_METHOD_VCT, VCT_METHOD_PATHTRACE,
                                  VCT_METHOD_WHITTED};
    for (size_t m = 0; m < sizeof methods / sizeof *methods; ++m) {
        vct_image bvh = render(s, methods[m], VCT_ACCEL_BVH);
        vct_image grid = render(s, methods[m], VCT_ACCEL_GRID);
        const size_t n = (size_t)SIZE * SIZE * 4;
        size_t differ = 0;
        double sum = 0.0;
        for (size_t i = 0; i < n; ++i) {
            differ += memcmp(&bvh.rgba[i], &grid.rgba[i], sizeof(float)) != 0;
            sum += i % 4 == 3 ? 0.0 : bvh.rgba[i]; /* alpha is 1 everywhere */
        }
        const char *method = vct_method_name(methods[m]);
        CHECK(differ == 0, "%s, %s: %zu of %zu values differ between bvh and grid", name, method,
              differ, n);
        CHECK(sum > 0.0, "%s, %s: a black image proves nothing", name, method);
        printf("%s, %s: bvh and grid images %s (%zu values differ)\n", name, method,
               differ ? "differ" : "identical", differ);
        vct_image_release(&bvh);
        vct_image_release(&grid);
    }
}

int main(void) {
    ctx = check_context();
    vct_scene *box = check_cornell_box_point_light();
    check_scene("cornell box", box);
    vct_scene_release(box);
    vct_scene *lit = check_cornell_box();
    check_scene("emissive cornell box", lit);
    vct_scene_release(lit);
    vct_context_release(ctx);
    return check_exit("test_accel_images");
}
