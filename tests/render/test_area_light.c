/* Emissive triangles are lights: a floor under an emissive square (no other
 * light) against the analytic irradiance of a uniform polygon (Lambert's
 * formula: E = Le / 2 * sum over edges of the edge's angle times the cosine
 * of its plane), at every pixel cone tracing's primary hit finds, and in the
 * voxels light injection fills; a blocker under the lamp casts its shadow;
 * and the plan says the triangles are sampled. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lambert.h"
#include "vct_case.h"
#include "voxel/voxels.h"

#define LE 5.0
#define ALBEDO 0.7

static vct_context *ctx;

/* E at p (normal +y) from the square lamp. */
static double lambert_polygon(const double p[3], const double lamp[4][3]) {
    static const double up[3] = {0.0, 1.0, 0.0};
    return lambert_irradiance(p, up, lamp, 4, LE);
}

/* Materials of quad_scene: the floor's, the lamp's (black, emitting Le)
 * and a glowing floor tile's (both). */
enum { FLOOR_MATERIAL, LAMP_MATERIAL, TILE_MATERIAL };

/* A scene of `count` quads (4 corners of 3 floats each), quad k of
 * material kind[k] and wound the other way where flip[k], seen by camera. */
static vct_scene *quad_scene(const float *corners, uint32_t count, const uint32_t *kind,
                             const int *flip, vct_camera camera) {
    uint32_t *tri = malloc(6 * sizeof(uint32_t) * count),
             *mat = malloc(2 * sizeof(uint32_t) * count);
    for (uint32_t k = 0; k < count; ++k) {
        const uint32_t up[6] = {0, 1, 2, 0, 2, 3}, down[6] = {0, 2, 1, 0, 3, 2};
        for (int i = 0; i < 6; ++i)
            tri[6 * k + i] = 4 * k + (flip[k] ? down[i] : up[i]);
        mat[2 * k] = mat[2 * k + 1] = kind[k];
    }
    vct_material m[3] = {vct_material_default(), vct_material_default(), vct_material_default()};
    for (int c = 0; c < 3; ++c) {
        m[FLOOR_MATERIAL].albedo[c] = m[TILE_MATERIAL].albedo[c] = (float)ALBEDO;
        m[LAMP_MATERIAL].albedo[c] = 0.0f;
        m[LAMP_MATERIAL].emission[c] = m[TILE_MATERIAL].emission[c] = (float)LE;
    }
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(corners, 4 * count, tri, 2 * count, mat, m, 3, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    s->camera = camera;
    s->has_camera = 1;
    free(tri);
    free(mat);
    return s;
}

/* A floor [0, 10]^2 at y = 0; a lamp square [4, 6]^2 at y = 3 (wound down
 * or up); a blocker square [3.5, 6.5]^2 at y = 1.5 when asked, seen from low
 * down so that the floor under it shows. */
static vct_scene *lamp_scene(int blocker, int lamp_up) {
    const float q[] = {
        0,    0,    0,    0,    0,    10,   10,   0,    10,   10,   0,    0, /* floor, up */
        4,    3,    4,    6,    3,    4,    6,    3,    6,    4,    3,    6, /* lamp, down */
        3.5f, 1.5f, 3.5f, 6.5f, 1.5f, 3.5f, 6.5f, 1.5f, 6.5f, 3.5f, 1.5f, 6.5f};
    const uint32_t kind[3] = {FLOOR_MATERIAL, LAMP_MATERIAL, FLOOR_MATERIAL};
    const int flip[3] = {0, lamp_up, 0};
    const vct_camera above = {{5, 9, 5.01f}, {5, 0, 5}, {0, 0, -1}, 70.0f};
    const vct_camera low = {{5, 0.8f, -3}, {5, 0, 5}, {0, 1, 0}, 50.0f};
    return quad_scene(q, blocker ? 3 : 2, kind, flip, blocker ? low : above);
}

static const double LAMP[4][3] = {{4, 3, 4}, {6, 3, 4}, {6, 3, 6}, {4, 3, 6}};

/* Direct light at every floor pixel against the analytic E * albedo / pi,
 * outside the blocker's penumbra when there is one. */
static void pixels_against_analytic(const char *name, int blocker, int lamp_up) {
    vct_scene *s = lamp_scene(blocker, lamp_up);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    CHECK(plan.on[VCT_EFFECT_DIRECT] && strstr(plan.why[VCT_EFFECT_DIRECT], "emissive"),
          "%s: direct light planned for the emitters (%s)", name, plan.why[VCT_EFFECT_DIRECT]);
    vct_aovs aovs;
    vct_image im = vct_case_render(ctx, s, &plan, 32, 96, 96, 1, &aovs);
    double sum_got = 0.0, sum_want = 0.0, sq = 0.0;
    int floor_pixels = 0, shadowed = 0, lit_in_umbra = 0;
    for (int i = 0; i < 96 * 96; ++i) {
        const float *pos = &aovs.position.rgba[4 * i];
        if (pos[3] == 0.0f || fabsf(pos[1]) > 1e-3f)
            continue; /* not the floor */
        const double p[3] = {pos[0], pos[1], pos[2]};
        const double got = aovs.direct.rgba[4 * i];
        if (blocker) {
            /* the blocker's umbra, where it hides the whole lamp: a ray to
             * lamp point x crosses the blocker's height halfway, so p is in
             * it while |p + x - 10| / 2 <= 1.5 for x in [4, 6] per axis */
            const double r = fmax(fabs(p[0] - 5.0), fabs(p[2] - 5.0));
            if (r < 2.0 - 0.05) {
                ++shadowed;
                lit_in_umbra += got > 0.0;
            }
            continue;
        }
        const double want = ALBEDO / CHECK_PI * lambert_polygon(p, LAMP);
        sum_got += got;
        sum_want += want;
        sq += (got - want) * (got - want);
        ++floor_pixels;
    }
    if (blocker) {
        CHECK(shadowed > 20 && lit_in_umbra == 0, "%s: %d of %d umbra pixels lit", name,
              lit_in_umbra, shadowed);
        printf("%-32s %d umbra pixels, %d lit\n", name, shadowed, lit_in_umbra);
    } else {
        const double ratio = sum_got / sum_want;
        const double nrmse = sqrt(sq / floor_pixels) / (sum_want / floor_pixels);
        /* 16 stratified samples per pixel: the mean agrees to 1%, pixels
         * to sampling noise */
        CHECK(floor_pixels > 5000 && fabs(ratio - 1.0) < 0.01 && nrmse < 0.07,
              "%s: %d floor pixels, mean ratio %.4f, NRMSE %.4f against Lambert's formula", name,
              floor_pixels, ratio, nrmse);
        printf("%-32s %d floor pixels: mean ratio %.4f, NRMSE %.4f\n", name, floor_pixels, ratio,
               nrmse);
    }
    vct_image_release(&im);
    vct_aovs_release(&aovs);
    vct_scene_release(s);
}

/* A lamp panel standing upright on the floor, 2 mm above it, seen from
 * above: the floor beside its foot is lit mostly by the panel's nearest
 * centimetres, where a point sample's Le cos cos / d^2 is heavy-tailed and
 * a pixel's 16 samples fall short. The panel is `tiles` x `tiles` quads:
 * one (2 triangles, each pixel's light summed exactly) or three (18, the
 * picked triangles' light). Every floor pixel against Lambert's formula,
 * computed here in double over the whole panel. */
static void near_panel_against_analytic(int tiles, double mean_tolerance, double nrmse_tolerance) {
    const float x = 5.0f, y0 = 0.002f, y1 = 1.0f, z0 = 4.0f, z1 = 6.0f;
    const uint32_t quads = 1 + (uint32_t)(tiles * tiles);
    float *v = malloc(12 * sizeof(float) * quads);
    uint32_t *kind = malloc(sizeof(uint32_t) * quads);
    int *flip = calloc(quads, sizeof(int));
    const float floor_quad[12] = {0, 0, 0, 0, 0, 10, 10, 0, 10, 10, 0, 0};
    memcpy(v, floor_quad, sizeof floor_quad);
    for (int i = 0; i < tiles; ++i)
        for (int j = 0; j < tiles; ++j) {
            const float ya = y0 + (y1 - y0) * (float)i / (float)tiles,
                        yb = y0 + (y1 - y0) * (float)(i + 1) / (float)tiles,
                        za = z0 + (z1 - z0) * (float)j / (float)tiles,
                        zb = z0 + (z1 - z0) * (float)(j + 1) / (float)tiles;
            const float q[12] = {x, ya, za, x, yb, za, x, yb, zb, x, ya, zb};
            memcpy(v + 12 * (1 + i * tiles + j), q, sizeof q);
        }
    for (uint32_t k = 0; k < quads; ++k)
        kind[k] = k == 0 ? FLOOR_MATERIAL : LAMP_MATERIAL;
    const vct_camera above = {{5.15f, 3, 5}, {5.15f, 0, 5}, {0, 0, -1}, 6.0f};
    vct_scene *s = quad_scene(v, quads, kind, flip, above);
    free(v);
    free(kind);
    free(flip);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    vct_aovs aovs;
    vct_image im = vct_case_render(ctx, s, &plan, 32, 96, 96, 1, &aovs);
    const double panel[4][3] = {{x, y0, z0}, {x, y1, z0}, {x, y1, z1}, {x, y0, z1}};
    double sum_got = 0.0, sum_want = 0.0, sq = 0.0, worst = 0.0;
    int floor_pixels = 0;
    for (int i = 0; i < 96 * 96; ++i) {
        const float *pos = &aovs.position.rgba[4 * i];
        if (pos[3] == 0.0f || fabsf(pos[1]) > 1e-3f)
            continue; /* the panel, not the floor */
        const double p[3] = {pos[0], pos[1], pos[2]};
        const double got = aovs.direct.rgba[4 * i];
        const double want = ALBEDO / CHECK_PI * lambert_polygon(p, panel);
        sum_got += got;
        sum_want += want;
        sq += (got - want) * (got - want);
        worst = fmax(worst, fabs(got - want) / want);
        ++floor_pixels;
    }
    const double ratio = sum_got / sum_want;
    const double nrmse = sqrt(sq / floor_pixels) / (sum_want / floor_pixels);
    CHECK(floor_pixels > 4000 && fabs(ratio - 1.0) < mean_tolerance && nrmse < nrmse_tolerance,
          "panel of %d triangles 2 mm above the floor: %d floor pixels, mean ratio %.4f, NRMSE "
          "%.4f against Lambert's formula",
          2 * tiles * tiles, floor_pixels, ratio, nrmse);
    printf("panel of %2d triangles, 2 mm up      %d floor pixels: mean ratio %.4f, NRMSE %.4f, "
           "worst pixel %.4f\n",
           2 * tiles * tiles, floor_pixels, ratio, nrmse, worst);
    vct_image_release(&im);
    vct_aovs_release(&aovs);
    vct_scene_release(s);
}

/* An emissive square inlaid in the floor under the lamp: the floor around
 * it and the square itself lie in its plane and get none of its light
 * (Lambert's formula would sum its angles there), only the lamp's; the
 * square shows its emission besides. Every pixel against Lambert's formula
 * for the lamp alone. */
static void inlaid_tile(void) {
    /* the floor [0, 10]^2 in four quads around the tile [4.5, 5.5]^2, then
     * the lamp (down) and the tile, all as x0 z0, x0 z1, x1 z1, x1 z0 */
    const float rect[6][5] = {{0, 0, 10, 4.5f, 0},      {0, 5.5f, 10, 10, 0},
                              {0, 4.5f, 4.5f, 5.5f, 0}, {5.5f, 4.5f, 10, 5.5f, 0},
                              {4, 4, 6, 6, 3},          {4.5f, 4.5f, 5.5f, 5.5f, 0}};
    float q[6 * 12];
    for (int k = 0; k < 6; ++k) {
        const float x0 = rect[k][0], z0 = rect[k][1], x1 = rect[k][2], z1 = rect[k][3],
                    y = rect[k][4];
        const float v[12] = {x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0};
        memcpy(q + 12 * k, v, sizeof v);
    }
    const uint32_t kind[6] = {FLOOR_MATERIAL, FLOOR_MATERIAL, FLOOR_MATERIAL,
                              FLOOR_MATERIAL, LAMP_MATERIAL,  TILE_MATERIAL};
    const int flip[6] = {0, 0, 0, 0, 1, 0};
    const vct_camera above = {{5, 2.5f, 5.01f}, {5, 0, 5}, {0, 0, -1}, 70.0f};
    vct_scene *s = quad_scene(q, 6, kind, flip, above);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    vct_aovs aovs;
    vct_image im = vct_case_render(ctx, s, &plan, 32, 96, 96, 1, &aovs);
    int pixels = 0, tile_pixels = 0, bad = 0;
    double worst = 0.0;
    for (int i = 0; i < 96 * 96; ++i) {
        const float *pos = &aovs.position.rgba[4 * i];
        if (pos[3] == 0.0f || fabsf(pos[1]) > 1e-3f)
            continue;
        const double p[3] = {pos[0], pos[1], pos[2]};
        const int on_tile = p[0] > 4.5 && p[0] < 5.5 && p[2] > 4.5 && p[2] < 5.5;
        const double want = (on_tile ? LE : 0.0) + ALBEDO / CHECK_PI * lambert_polygon(p, LAMP);
        const double off = fabs(im.rgba[4 * i] - want) / want; /* no indirect planned */
        worst = fmax(worst, off);
        bad += off > 1e-3;
        tile_pixels += on_tile;
        ++pixels;
    }
    CHECK(pixels > 4000 && tile_pixels > 100 && bad == 0,
          "tile inlaid in the floor: %d of %d pixels (%d on the tile) off Lambert's formula for "
          "the lamp alone (worst %.3g)",
          bad, pixels, tile_pixels, worst);
    printf("tile inlaid in the floor          %d pixels (%d on the tile), worst %.2e\n", pixels,
           tile_pixels, worst);
    vct_image_release(&im);
    vct_aovs_release(&aovs);
    vct_scene_release(s);
}

/* The floor's voxels: their radiance against albedo / pi * E at their
 * centres (8 samples per fragment: the mean over the voxels to 2%). */
static void voxels_against_analytic(void) {
    vct_scene *s = lamp_scene(0, 0);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options o = {0};
    o.resolution = 32;
    o.has_bounds = 1;
    o.bounds_min[0] = o.bounds_min[2] = 0.0f;
    o.bounds_min[1] = -5.0f + 10.0f / 64.0f; /* the floor through voxel centres */
    o.bounds_size = 10.0f;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, g, v, &err), err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    uint32_t *keys = malloc(4ull * info.voxels);
    float *radiance = malloc(16ull * info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, NULL, NULL, NULL, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, radiance, &err), err);
    const double voxel = 10.0 / 32.0;
    double sum_got = 0.0, sum_want = 0.0, lamp = 0.0;
    int floor_voxels = 0;
    for (uint32_t i = 0; i < info.voxels; ++i) {
        uint32_t cell[3] = {0, 0, 0};
        for (int b = 0; b < 10; ++b)
            for (int k = 0; k < 3; ++k)
                cell[k] |= ((keys[i] >> (3 * b + k)) & 1u) << b;
        const double p[3] = {(cell[0] + 0.5) * voxel, o.bounds_min[1] + (cell[1] + 0.5) * voxel,
                             (cell[2] + 0.5) * voxel};
        if (fabs(p[1]) > 1e-3) {
            lamp = fmax(lamp, radiance[4 * i]); /* the lamp's voxels: black, no emission */
            continue;
        }
        sum_got += radiance[4 * i];
        sum_want += ALBEDO / CHECK_PI * lambert_polygon(p, LAMP);
        ++floor_voxels;
    }
    const double ratio = sum_got / sum_want;
    CHECK(floor_voxels == 32 * 32 && fabs(ratio - 1.0) < 0.02,
          "voxels: %d floor voxels, mean ratio %.4f against Lambert's formula", floor_voxels,
          ratio);
    /* The emission stays out of the voxels: cones would count it twice. */
    CHECK(lamp == 0.0, "the lamp's voxels send out %g (they hold no emission)", lamp);
    printf("voxels: %d floor voxels, mean ratio %.4f\n", floor_voxels, ratio);
    free(keys);
    free(radiance);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* --emitters cones: the lamp is no light; its voxels keep its emission and
 * the floor's diffuse cones gather it. The lamp's voxels hold Le, no direct
 * light is sampled, and the floor is lit; how far the cones are from
 * Lambert's formula is printed (README: 3.7x too bright here, a lamp much
 * smaller than the cones that reach it), not asserted. */
static void cones_against_analytic(void) {
    vct_scene *s = lamp_scene(0, 0);
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    plan.emitters_by_cones = 1;
    vct_aovs aovs;
    vct_image im = vct_case_render(ctx, s, &plan, 32, 96, 96, 1, &aovs);
    double sum_got = 0.0, sum_want = 0.0, sq = 0.0, direct = 0.0;
    int floor_pixels = 0;
    for (int i = 0; i < 96 * 96; ++i) {
        const float *pos = &aovs.position.rgba[4 * i];
        if (pos[3] == 0.0f || fabsf(pos[1]) > 1e-3f)
            continue;
        const double p[3] = {pos[0], pos[1], pos[2]};
        const double got = im.rgba[4 * i], want = ALBEDO / CHECK_PI * lambert_polygon(p, LAMP);
        sum_got += got;
        sum_want += want;
        sq += (got - want) * (got - want);
        direct = fmax(direct, aovs.direct.rgba[4 * i]);
        ++floor_pixels;
    }
    const double ratio = sum_got / sum_want;
    const double nrmse = sqrt(sq / floor_pixels) / (sum_want / floor_pixels);
    CHECK(floor_pixels > 5000 && ratio > 0.1 && direct == 0.0,
          "emitters by cones: mean ratio %.4f against Lambert's formula, direct light %g (the "
          "lamp is no light)",
          ratio, direct);
    printf("%-32s %d floor pixels: mean ratio %.4f, NRMSE %.4f\n", "emitters by cones",
           floor_pixels, ratio, nrmse);
    vct_image_release(&im);
    vct_aovs_release(&aovs);

    /* The lamp's voxels keep its emission. */
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options o = {0};
    o.resolution = 32;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    v->emitters_by_cones = 1;
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, g, v, &err), err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    float *radiance = malloc(16ull * info.voxels), *emission = malloc(16ull * info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, v, NULL, NULL, NULL, emission, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, radiance, &err), err);
    double lamp = 0.0;
    for (uint32_t i = 0; i < info.voxels; ++i)
        if (emission[4 * i] > 0.0f)
            lamp = fmax(lamp, radiance[4 * i]);
    CHECK(fabs(lamp - LE) < 1e-3 * LE, "the lamp's voxels send out %g, its emission is %g", lamp,
          (double)LE);
    free(radiance);
    free(emission);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    cones_against_analytic();
    pixels_against_analytic("lamp wound down", 0, 0);
    pixels_against_analytic("lamp wound up", 0, 1);
    pixels_against_analytic("blocker under the lamp", 1, 0);
    /* Summed exactly: to float rounding. Picked: each pixel's 16 picks
     * among 18 triangles are still noisy (NRMSE 0.39 measured), the mean
     * is not; point samples alone gave NRMSE 3.3 and 1.9, pixels 100x off. */
    near_panel_against_analytic(1, 1e-3, 1e-3);
    near_panel_against_analytic(3, 0.02, 0.6);
    inlaid_tile();
    voxels_against_analytic();
    vct_context_release(ctx);
    return check_exit("test_area_light");
}
