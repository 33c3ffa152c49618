/* Renders a scene by voxel cone tracing for tests: the triangle grid, what
 * the plan needs of the voxel hierarchy, then the image, with the context's
 * statistics reset first so that kernel launches count this frame alone. */
#ifndef VCT_TEST_VCT_CASE_H
#define VCT_TEST_VCT_CASE_H

#include "check.h"

/* w x h at res^3 voxels and `bounces` light bounces, pixel centres only,
 * directional bricks or isotropic ones (the default); AOVs too when aovs
 * is not NULL. */
static inline vct_image vct_case_render_bricks(vct_context *ctx, const vct_scene *s,
                                               const vct_plan *plan, uint32_t res, int w, int h,
                                               uint32_t bounces, int directional, vct_aovs *aovs) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options vo = {0};
    vo.resolution = res;
    const vct_brick_options bo = {VCT_BRICKS_AUTO, directional, 0};
    vct_vct_options o = vct_vct_options_default(512, 512);
    o.width = w;
    o.height = h;
    o.aovs = aovs != NULL;
    /* One ray through each pixel's centre and every pixel's own diffuse
     * cones, where the tests' references (the ray caster, light at a point)
     * look; test_edge_samples tests edges, test_vct sparse diffuse. */
    o.edge_samples = 1;
    o.sparse_diffuse = 0;
    o.indirect_passes = 0; /* each pixel's own cones, unfiltered */
    vct_voxels *v = NULL;
    REQUIRE_OK(vct_vct_prepare(ctx, s, g, plan, &vo, &bo, bounces, &o.cones, &v, &err), err);
    vct_image image;
    vct_stats_reset(ctx);
    REQUIRE_OK(vct_render_vct(ctx, s, g, v, plan, &o, &image, aovs, &err), err);
    vct_voxels_release(v);
    vct_accel_release(g);
    return image;
}

/* Cone tracing as `vct render` does it by default (bounces, edge samples,
 * sparse diffuse cones, isotropic bricks, the indirect light filtered) at
 * `res` voxels: what the accuracy goals are stated for; with
 * indirect_passes filter passes, and AOVs when aovs is not NULL. */
static inline vct_image vct_case_render_filtered(vct_context *ctx, const vct_scene *s,
                                                 const vct_plan *plan, uint32_t res, int w, int h,
                                                 uint32_t indirect_passes, vct_aovs *aovs) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options vo = {0};
    vo.resolution = res;
    const vct_brick_options bo = {VCT_BRICKS_AUTO, 0, 0};
    vct_vct_options o = vct_vct_options_default(w, h);
    o.indirect_passes = indirect_passes;
    vct_voxels *v = NULL;
    REQUIRE_OK(vct_vct_prepare(ctx, s, g, plan, &vo, &bo, VCT_DEFAULT_BOUNCES, &o.cones, &v, &err),
               err);
    vct_image image;
    REQUIRE_OK(vct_render_vct(ctx, s, g, v, plan, &o, &image, aovs, &err), err);
    vct_voxels_release(v);
    vct_accel_release(g);
    return image;
}

static inline vct_image vct_case_render_default(vct_context *ctx, const vct_scene *s,
                                                const vct_plan *plan, uint32_t res, int w, int h) {
    return vct_case_render_filtered(ctx, s, plan, res, w, h, VCT_INDIRECT_PASSES_DEFAULT, NULL);
}

/* The same with directional bricks. */
static inline vct_image vct_case_render(vct_context *ctx, const vct_scene *s, const vct_plan *plan,
                                        uint32_t res, int w, int h, uint32_t bounces,
                                        vct_aovs *aovs) {
    return vct_case_render_bricks(ctx, s, plan, res, w, h, bounces, 1, aovs);
}

/* The plan with every effect forced to `rest`, but `effect` to `forced`
 * (VCT_FORCE_AUTO: the scene decides). */
static inline void vct_case_plan_forcing(const vct_scene *s, vct_effect effect,
                                         vct_effect_force forced, vct_effect_force rest,
                                         vct_plan *plan) {
    vct_effect_force force[VCT_EFFECTS];
    for (int e = 0; e < VCT_EFFECTS; ++e)
        force[e] = rest;
    force[effect] = forced;
    vct_plan_make(s, force, plan);
}

/* The scene's own plan with indirect light forced off: direct light alone. */
static inline void vct_case_direct_plan(const vct_scene *s, vct_plan *plan) {
    vct_case_plan_forcing(s, VCT_EFFECT_INDIRECT, VCT_FORCE_OFF, VCT_FORCE_AUTO, plan);
}

#endif
