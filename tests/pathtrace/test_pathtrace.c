/* The path tracer against answers known in advance: the furnace (a closed box
 * of albedo a and emission Le has radiance Le / (1 - a) everywhere), direct
 * light equal to the ray caster's at depth 1, no gain of energy in an open
 * scene, error falling as 1 / sqrt(spp), determinism, resumed calls that
 * continue one sample sequence, sums of the colour alone, and no NaN on adversarial geometry.
 * Bounds come from the measured spread of the samples. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lambert.h"
#include "mesh_gen.h"
#include "vec3d.h"

/* Closed cube [-1, 1]^3 (12 triangles) of one material, camera inside. */
static vct_scene *cube_scene(vct_material m) {
    const float p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const uint32_t t[12][3] = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}, {0, 4, 5}, {0, 5, 1},
                               {3, 2, 6}, {3, 6, 7}, {0, 3, 7}, {0, 7, 4}, {1, 5, 6}, {1, 6, 2}};
    uint32_t mats[12] = {0};
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(&p[0][0], 8, &t[0][0], 12, mats, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    s->camera = (vct_camera){{0.1f, 0.2f, 0.3f}, {0.7f, -0.4f, 0.9f}, {0, 1, 0}, 70.0f};
    return s;
}

static vct_image trace(vct_context *ctx, const vct_scene *s, int w, int h, uint32_t spp,
                       uint32_t depth, uint32_t seed, vct_pathtrace_result *res) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_pathtrace_options o = {w, h, spp, 0.0, depth, seed, spp, 0, 0, NULL, NULL, 0};
    vct_image im;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &im, res, &err), err);
    vct_accel_release(g);
    return im;
}

/* Mean of channel c over all pixels and its standard error (pixels are
 * independent estimates). */
static void image_mean(const vct_image *im, int c, double *mean, double *se) {
    const size_t n = (size_t)im->width * im->height;
    double s = 0.0, s2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double v = im->rgba[4 * i + c];
        s += v;
        s2 += v * v;
    }
    *mean = s / n;
    *se = sqrt(fmax(s2 / n - *mean * *mean, 0.0) / n);
}

static void furnace(vct_context *ctx, const char *name, vct_material m, double expect) {
    vct_scene *s = cube_scene(m);
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, 48, 48, 32, 200, 1, &r);
    for (int c = 0; c < 3; ++c) {
        double mean, se;
        image_mean(&im, c, &mean, &se);
        /* 5 standard errors: a false alarm about once in 3.5 million runs. */
        CHECK(fabs(mean - expect) <= 5.0 * se, "%s channel %d: %.5f, expected %.5f (+-%.5f)", name,
              c, mean, expect, 5.0 * se);
        if (c == 0)
            printf("%s: mean radiance %.5f, expected %.5f, 5 sigma = %.5f\n", name, mean, expect,
                   5.0 * se);
    }
    CHECK(r.discarded == 0, "%s: %u samples discarded", name, r.discarded);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* A plane with an optional point light; camera looking down at it. */
static vct_scene *plane_scene(float albedo, const vct_light *light) {
    const float p[] = {-50, 0, -50, 50, 0, -50, 50, 0, 50, -50, 0, 50};
    const uint32_t t[] = {0, 1, 2, 0, 2, 3}, mats[2] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = albedo;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(p, 4, t, 2, mats, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_scene_add_light(s, light, &err), err);
    s->camera = (vct_camera){{0.3f, 6.0f, 6.0f}, {0, 0, 0}, {0, 1, 0}, 40.0f};
    return s;
}

static void direct_matches_raycast(vct_context *ctx) {
    vct_light point = {VCT_LIGHT_POINT, {1.0f, 3.0f, -0.5f}, {0, 0, 0}, {10, 20, 30}, 0, 0, 0};
    vct_scene *s = plane_scene(0.6f, &point);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    /* The path tracer averages each pixel's footprint: compare with the ray
     * caster at 8x8 samples per pixel, box-filtered down. */
    vct_render_options ro = {64 * 8, 48 * 8, 0, 0, 0.0f};
    vct_image fine, ref = {64, 48, calloc(16, 64 * 48)};
    REQUIRE_OK(vct_render_raycast(ctx, s, g, &ro, &fine, &err), err);
    vct_accel_release(g);
    for (int y = 0; y < 48 * 8; ++y)
        for (int x = 0; x < 64 * 8; ++x)
            for (int c = 0; c < 4; ++c)
                ref.rgba[4 * ((y / 8) * 64 + x / 8) + c] += fine.rgba[4 * (y * 512 + x) + c] / 64;
    vct_image_release(&fine);
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, 64, 48, 256, 1, 3, &r);
    /* What remains is the random placement of the samples in each pixel
     * (measured: relative RMSE 2.4e-3 at 64 spp, 6.2e-4 at 1024, as
     * 1/sqrt(spp)); over the whole image it averages away. */
    vct_image_metrics m;
    REQUIRE_OK(vct_image_compare(&im, &ref, &m, &err), err);
    double worst = 0;
    for (int i = 0; i < 64 * 48; ++i)
        for (int c = 0; c < 3; ++c) {
            double a = im.rgba[4 * i + c], b = ref.rgba[4 * i + c];
            worst = fmax(worst, fabs(a - b) / fmax(b, 1e-6));
        }
    double mean_pt, mean_rc, se;
    image_mean(&im, 1, &mean_pt, &se);
    image_mean(&ref, 1, &mean_rc, &se);
    const double mean_diff = fabs(mean_pt - mean_rc) / mean_rc;
    CHECK(worst < 0.02, "depth 1 vs ray caster: worst pixel differs by %.4f relative", worst);
    CHECK(m.relative_rmse < 2.5e-3, "depth 1 vs ray caster: relative RMSE %.5f", m.relative_rmse);
    CHECK(mean_diff < 5e-4, "depth 1 vs ray caster: image means differ by %.2e", mean_diff);
    printf("depth 1 vs ray caster: relative RMSE %.2e, worst pixel %.2e, means %.2e apart\n",
           m.relative_rmse, worst, mean_diff);
    vct_image_release(&im);
    vct_image_release(&ref);
    vct_scene_release(s);
}

/* The light's direct and indirect parts, in a furnace (a closed cube whose
 * walls emit 1 and reflect a = 0.5): the direct part is the emission seen
 * and the light the first surface receives from the walls (next-event
 * estimation and the first bounce's BSDF sample, weighted against each
 * other), 1 + a; the indirect part the rest of the series, a^2 / (1 - a).
 * Paths of one surface have no indirect part, exactly. */
static void direct_and_indirect(vct_context *ctx) {
    vct_material m = vct_material_default();
    for (int c = 0; c < 3; ++c) {
        m.albedo[c] = 0.5f;
        m.emission[c] = 1.0f;
    }
    vct_scene *s = cube_scene(m);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const int w = 24, h = 16, n = w * h;
    vct_image full, one, indirect, indirect_one, var, var_one;
    vct_pathtrace_options o = {w, h, 16, 0.0, 32, 7, 16, 0, 0, &var, &indirect, 0};
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &full, NULL, &err), err);
    o.max_depth = 1;
    o.variance = &var_one;
    o.indirect = &indirect_one;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &one, NULL, &err), err);
    double direct_sum = 0, direct_sq = 0, indirect_sum = 0, indirect_sq = 0;
    int var_same = 1, one_zero = 1;
    for (int i = 0; i < n; ++i) {
        const double d = full.rgba[4 * i] - indirect.rgba[4 * i], r = indirect.rgba[4 * i];
        direct_sum += d;
        direct_sq += d * d;
        indirect_sum += r;
        indirect_sq += r * r;
        var_same &= var_one.rgba[4 * i + 1] == var_one.rgba[4 * i] && var.rgba[4 * i + 2] > 0.0f;
        one_zero &= indirect_one.rgba[4 * i] == 0.0f && var_one.rgba[4 * i + 2] == 0.0f;
    }
    const double dm = direct_sum / n, rm = indirect_sum / n;
    const double dse = sqrt(fmax(direct_sq / n - dm * dm, 0.0) / n),
                 rse = sqrt(fmax(indirect_sq / n - rm * rm, 0.0) / n);
    printf("furnace a=0.5: direct part %.4f (+-%.4f, expected 1.5), indirect %.4f (+-%.4f, "
           "expected 0.5)\n",
           dm, dse, rm, rse);
    CHECK(fabs(dm - 1.5) <= 5.0 * dse + 1e-4, "direct part %.4f, expected 1.5", dm);
    CHECK(fabs(rm - 0.5) <= 5.0 * rse + 1e-4, "indirect part %.4f, expected 0.5", rm);
    CHECK(var_same, "variances: one surface's direct part is not its whole, or no indirect");
    CHECK(one_zero, "paths of one surface have indirect light");
    vct_image *all[] = {&full, &one, &indirect, &indirect_one, &var, &var_one};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* An open plane of albedo 1 under a sun of irradiance E reflects exactly
 * E / pi: paths that leave it never return, so there is nothing to add. */
static void open_scene_energy(vct_context *ctx) {
    vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0, 0, 0}, {0, -1, 0}, {1, 1, 1}, 0, 0, 0};
    vct_scene *s = plane_scene(1.0f, &sun);
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, 32, 24, 16, 32, 5, &r);
    double worst = 0;
    for (int i = 0; i < 32 * 24; ++i)
        worst = fmax(worst, fabs(im.rgba[4 * i] - 1.0 / CHECK_PI));
    CHECK(worst < 1e-5, "open plane: off E/pi by %.3g", worst);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* An open plane under a sky and no light: its light comes from the BSDF
 * rays that escape, each of them the sky times the albedo, so every pixel
 * is exactly that at depth 1 (the last surface's BSDF ray) and deeper. */
static void sky_only_plane(vct_context *ctx) {
    const float p[] = {-50, 0, -50, 50, 0, -50, 50, 0, 50, -50, 0, 50};
    const uint32_t t[] = {0, 1, 2, 0, 2, 3}, mats[2] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.5f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(p, 4, t, 2, mats, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    s->camera = (vct_camera){{0.3f, 6.0f, 6.0f}, {0, 0, 0}, {0, 1, 0}, 40.0f};
    const float sky[3] = {0.2f, 0.3f, 0.4f};
    memcpy(s->ambient, sky, sizeof sky);
    for (uint32_t depth = 1; depth <= 3; depth += 2) {
        vct_pathtrace_result r;
        vct_image im = trace(ctx, s, 16, 12, 4, depth, 3, &r);
        double worst = 0;
        for (int i = 0; i < 16 * 12; ++i)
            for (int c = 0; c < 3; ++c)
                worst = fmax(worst, fabs(im.rgba[4 * i + c] - 0.5 * sky[c]));
        CHECK(worst < 1e-6, "plane under a sky, depth %u: off albedo x sky by %.3g", depth, worst);
        printf("plane under a sky, depth %u: albedo x sky within %.2g\n", depth, worst);
        vct_image_release(&im);
    }
    vct_scene_release(s);
}

static void convergence_and_determinism(vct_context *ctx) {
    vct_scene *s = check_cornell_box();
    vct_pathtrace_result r;
    vct_image ref = trace(ctx, s, 32, 32, 1024, 16, 100, &r);
    double e[3];
    const uint32_t spp[3] = {4, 16, 64};
    vct_image first = {0};
    for (int i = 0; i < 3; ++i) {
        vct_image im = trace(ctx, s, 32, 32, spp[i], 16, 7, &r);
        vct_image_metrics m;
        vct_error err = {0};
        REQUIRE_OK(vct_image_compare(&im, &ref, &m, &err), err);
        e[i] = m.rmse;
        printf("cornell %3u spp: RMSE %.4f against 1024 spp\n", spp[i], m.rmse);
        if (i == 0)
            first = im;
        else
            vct_image_release(&im);
    }
    /* 1/sqrt(spp): each 4x more samples halves the error (the reference's own
     * noise pulls the last ratio slightly below 2). */
    CHECK(e[0] / e[1] > 1.5 && e[0] / e[1] < 2.6, "RMSE ratio 4->16 spp: %.2f", e[0] / e[1]);
    CHECK(e[1] / e[2] > 1.4 && e[1] / e[2] < 2.6, "RMSE ratio 16->64 spp: %.2f", e[1] / e[2]);
    vct_image again = trace(ctx, s, 32, 32, 4, 16, 7, &r);
    CHECK(memcmp(again.rgba, first.rgba, 16 * 32 * 32) == 0, "same seed and spp differ");
    vct_image other = trace(ctx, s, 32, 32, 4, 16, 8, &r);
    CHECK(memcmp(other.rgba, first.rgba, 16 * 32 * 32) != 0, "another seed gives the same image");
    vct_image_release(&again);
    vct_image_release(&other);
    vct_image_release(&first);
    vct_image_release(&ref);
    vct_scene_release(s);
}

/* A room open at the front under a sky, with one surface of every kind
 * the path tracer shades: a textured floor, diffuse walls, a glossy wall,
 * a mirror, a glass pane, a metal plate and an emitting panel, lit by a
 * point light with a radius, a spot and a sun. */
static vct_scene *mixed_room(void) {
    const float q[9][12] = {
        {0, 0, 0, 0, 0, 4, 4, 0, 4, 4, 0, 0},                         /* floor, textured */
        {0, 3, 0, 4, 3, 0, 4, 3, 4, 0, 3, 4},                         /* ceiling */
        {0, 0, 0, 4, 0, 0, 4, 3, 0, 0, 3, 0},                         /* back wall */
        {0, 0, 0, 0, 3, 0, 0, 3, 4, 0, 0, 4},                         /* left wall */
        {4, 0, 0, 4, 0, 4, 4, 3, 4, 4, 3, 0},                         /* right wall, glossy */
        {0.5f, 0, 1, 1.5f, 0, 0.5f, 1.5f, 2, 0.5f, 0.5f, 2, 1},       /* mirror */
        {2.5f, 0, 2, 3.5f, 0, 2, 3.5f, 1.5f, 2, 2.5f, 1.5f, 2},       /* glass */
        {1.5f, 2.9f, 1, 2.5f, 2.9f, 1, 2.5f, 2.9f, 2, 1.5f, 2.9f, 2}, /* emitter */
        {1.8f, 0.01f, 2.5f, 2.4f, 0.01f, 2.5f, 2.4f, 0.5f, 2.9f, 1.8f, 0.5f, 2.9f}}; /* metal */
    test_mesh mesh = mesh_quads(&q[0][0], 9);
    vct_material m[8];
    for (int i = 0; i < 8; ++i)
        m[i] = vct_material_default();
    m[2].albedo[0] = 0.7f, m[2].albedo[1] = 0.2f, m[2].albedo[2] = 0.1f;
    for (int c = 0; c < 3; ++c) {
        m[3].albedo[c] = 0.3f;
        m[3].specular[c] = 0.5f;
        m[4].albedo[c] = 0.0f;
        m[4].specular[c] = 0.9f;
        m[5].albedo[c] = 1.0f;
        m[6].emission[c] = 4.0f;
        m[7].albedo[c] = 0.8f;
    }
    m[3].roughness = 0.4f;
    m[4].roughness = 0.0f;
    m[5].transmission = 1.0f;
    m[5].ior = 1.5f;
    m[7].metallic = 1.0f;
    m[7].roughness = 0.3f;
    const uint32_t quad_material[9] = {0, 1, 1, 2, 3, 4, 5, 6, 7};
    uint32_t mats[18];
    for (int t = 0; t < 18; ++t)
        mats[t] = quad_material[t / 2];
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(mesh.pos, mesh.nv, mesh.tri, mesh.nt, mats, m, 8, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    s->uvs = calloc(2ull * mesh.nv, sizeof(float));
    for (uint32_t v = 0; v < 4; ++v) { /* the floor's checker: 2 squares a unit */
        s->uvs[2 * v] = mesh.pos[3 * v] / 2.0f;
        s->uvs[2 * v + 1] = mesh.pos[3 * v + 2] / 2.0f;
    }
    s->textures = calloc(1, sizeof *s->textures);
    s->texture_count = 1;
    vct_texture *tex = &s->textures[0];
    tex->width = tex->height = 4;
    tex->rgba = malloc(16 * 4 * 4);
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 4; ++c)
            tex->rgba[4 * i + c] = c == 3 ? 1.0f : (((i % 4) + i / 4) & 1) ? 0.9f : 0.1f;
    s->materials[0].albedo_texture = 1;
    REQUIRE_OK(vct_scene_validate(s, &err), err);
    const vct_light lights[3] = {
        {VCT_LIGHT_POINT, {2, 2.5f, 2}, {0, 0, 0}, {6, 6, 5}, 0, 0, 0.2f},
        {VCT_LIGHT_SPOT, {3, 2.8f, 1}, {0, -1, 0.2f}, {9, 7, 5}, 0.3f, 0.6f, 0},
        {VCT_LIGHT_DIRECTIONAL, {0, 0, 0}, {-0.2f, -0.6f, -1}, {1.5f, 1.4f, 1.2f}, 0, 0, 0}};
    for (int i = 0; i < 3; ++i)
        REQUIRE_OK(vct_scene_add_light(s, &lights[i], &err), err);
    s->ambient[0] = 0.3f, s->ambient[1] = 0.4f, s->ambient[2] = 0.5f;
    s->camera = (vct_camera){{2, 1.5f, 3.8f}, {2, 1, 0.5f}, {0, 1, 0}, 70.0f};
    mesh_free(&mesh);
    return s;
}

/* Paths in vector lanes and camera rays 16 to a packet (CPU devices)
 * against each path and ray by itself (the kernels built with
 * VCT_PACKETS=0, as for GPUs): the same image bit for bit, with a sample
 * count that leaves the last group partly empty, in the Cornell box (every
 * surface diffuse, the lanes alone) and in a room where the lanes' paths
 * meet every other kind of surface and light. */
static void packets_change_nothing(vct_context *ctx) {
    vct_scene *scenes[2] = {check_cornell_box(), mixed_room()};
    const char *names[2] = {"cornell", "mixed room"};
    vct_context *plain = check_context();
    for (int i = 0; i < 2; ++i) {
        vct_pathtrace_result r;
        vct_image packed = trace(ctx, scenes[i], 24, 20, 37, 6, 11, &r);
        setenv("VCT_PACKETS", "0", 1); /* read where the kernels are built */
        vct_image one = trace(plain, scenes[i], 24, 20, 37, 6, 11, &r);
        unsetenv("VCT_PACKETS");
        double sum = 0.0;
        for (int k = 0; k < 4 * 24 * 20; ++k)
            sum += packed.rgba[k];
        const int same = memcmp(packed.rgba, one.rgba, 16 * 24 * 20) == 0;
        CHECK(same && sum > 0.0, "%s: paths in lanes change the image (sum %g)", names[i], sum);
        if (same)
            printf("%s 37 spp: the same image with paths in lanes and one by one\n", names[i]);
        vct_image_release(&packed);
        vct_image_release(&one);
        vct_scene_release(scenes[i]);
    }
    vct_context_release(plain);
}

/* Slivers, zero-area triangles, albedo 1, emission and every material kind:
 * nothing may come out non-finite. */
static void adversarial(vct_context *ctx) {
    test_mesh soup = mesh_soup(600, 0.0f, 3);
    uint32_t *mats = malloc(4ull * soup.nt);
    vct_material m[4] = {vct_material_default(), vct_material_default(), vct_material_default(),
                         vct_material_default()};
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 1.0f;
    m[1].emission[0] = m[1].emission[1] = m[1].emission[2] = 2.0f;
    m[2].specular[0] = m[2].specular[1] = m[2].specular[2] = 1.0f;
    m[2].roughness = 0.0f;
    m[3].transmission = 1.0f;
    m[3].albedo[0] = m[3].albedo[1] = m[3].albedo[2] = 1.0f;
    for (uint32_t t = 0; t < soup.nt; ++t)
        mats[t] = t % 4;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(soup.pos, soup.nv, soup.tri, soup.nt, mats, m, 4, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    vct_light grazing = {VCT_LIGHT_DIRECTIONAL, {0, 0, 0}, {1, -1e-4f, 0}, {3, 3, 3}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, &grazing, &err), err);
    s->camera = (vct_camera){{0.5f, 0.5f, 2.5f}, {0.5f, 0.5f, 0.5f}, {0, 1, 0}, 50.0f};
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, 40, 40, 16, 32, 11, &r);
    size_t bad = 0;
    for (int i = 0; i < 4 * 40 * 40; ++i)
        bad += !isfinite(im.rgba[i]);
    CHECK(bad == 0, "adversarial scene: %zu non-finite values", bad);
    printf("adversarial scene: %u samples discarded (reported, never in the image)\n", r.discarded);
    vct_image_release(&im);
    vct_scene_release(s);
    free(mats);
    mesh_free(&soup);
}

/* A glass slab (IOR 1.5, two parallel faces at z = -1 and -1.2) in front of
 * an emitter of radiance 1: seen through it, radiance is (1 - F) / (1 + F)
 * with F the Fresnel reflectance at the viewing angle (all internal
 * reflections summed; reflected paths leave into the dark). */
static void glass_slab(vct_context *ctx, float angle_deg) {
    const float L = 60.0f;
    const float p[] = {-L, -L, -1.0f,  L, -L, -1.0f,  L, L, -1.0f,  -L, L, -1.0f,
                       -L, -L, -1.2f,  L, -L, -1.2f,  L, L, -1.2f,  -L, L, -1.2f,
                       -L, -L, -10.0f, L, -L, -10.0f, L, L, -10.0f, -L, L, -10.0f};
    /* Outward normals: +z on the front face, -z on the back face. */
    const uint32_t t[] = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 8, 9, 10, 8, 10, 11};
    const uint32_t mats[] = {0, 0, 0, 0, 1, 1};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    m[0].transmission = 1.0f;
    m[0].ior = 1.5f;
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 1.0f;
    m[1].albedo[0] = m[1].albedo[1] = m[1].albedo[2] = 0.0f;
    m[1].emission[0] = m[1].emission[1] = m[1].emission[2] = 1.0f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(p, 12, t, 6, mats, m, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const double a = angle_deg * CHECK_PI / 180.0;
    s->camera = (vct_camera){{0, 0, 0}, {0, (float)-sin(a), (float)-cos(a)}, {0, 1, 0}, 0.5f};
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, 8, 8, 512, 64, 13, &r);
    const double F = check_fresnel(cos(a), 1.0 / 1.5), expect = (1.0 - F) / (1.0 + F);
    double mean, se;
    image_mean(&im, 0, &mean, &se);
    /* Each sample is 0 or 1: its spread gives the bound. */
    const double sigma = sqrt(expect * (1.0 - expect) / (8.0 * 8.0 * 512.0));
    CHECK(fabs(mean - expect) <= 5.0 * sigma, "glass slab at %g degrees: %.5f, expected %.5f",
          angle_deg, mean, expect);
    printf("glass slab at %2.0f degrees: transmitted %.5f, expected %.5f (5 sigma %.5f)\n",
           angle_deg, mean, expect, 5.0 * sigma);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* Four resumed calls of one sample equal one call of four, bit for bit (the
 * viewer's progressive mode); a call without resume starts over. */
static void resume_continues(vct_context *ctx) {
    vct_material m = vct_material_default();
    for (int c = 0; c < 3; ++c)
        m.emission[c] = 0.5f;
    vct_scene *s = cube_scene(m);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_pathtrace_options whole = {24, 16, 4, 0.0, 8, 5, 1, 0, 0, NULL, NULL, 0};
    vct_pathtrace_result r;
    vct_image once, step = {0}, fresh;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &whole, &once, &r, &err), err);
    vct_pathtrace_options part = whole;
    part.spp = 1;
    for (int i = 0; i < 4; ++i) {
        part.resume = i > 0;
        vct_image_release(&step);
        REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &part, &step, &r, &err), err);
    }
    CHECK(r.spp == 4, "resumed calls report %u samples, expected 4", r.spp);
    CHECK(memcmp(once.rgba, step.rgba, 16ull * 24 * 16) == 0,
          "four resumed samples differ from one call of four");
    part.resume = 0;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &part, &fresh, &r, &err), err);
    CHECK(r.spp == 1 && memcmp(once.rgba, fresh.rgba, 16ull * 24 * 16) != 0,
          "a call without resume should start over (%u samples)", r.spp);
    vct_image_release(&once);
    vct_image_release(&step);
    vct_image_release(&fresh);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* A ceiling beside an emissive panel a centimetre under it, seen from below
 * at depth 1: each ceiling pixel against Lambert's formula (in double,
 * averaged over 8 x 8 points of the pixel), in bands of distance from the
 * panel's edge. Beyond a few centimetres the ceiling sees the panel edge-on;
 * a shadow ray parallel to the sample's direction but lifted off the ceiling
 * met the panel's own plane short of its end there, and the light was lost. */
static void ceiling_beside_panel(vct_context *ctx) {
    enum { W = 40, H = 40, SUB = 8, BANDS = 3 };
    const double le = 5.0, albedo = 0.7, ceiling = 3.0, panel_y = 2.99;
    const float corners[] = {0,    3,     0,    10, 3,     0,    10, 3,     10,   0, 3,     10,
                             4.0f, 2.99f, 4.0f, 6,  2.99f, 4.0f, 6,  2.99f, 6.0f, 4, 2.99f, 6.0f};
    const uint32_t tris[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7}, mats[4] = {0, 0, 1, 1};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    for (int c = 0; c < 3; ++c) {
        m[0].albedo[c] = (float)albedo;
        m[1].albedo[c] = 0.0f;
        m[1].emission[c] = (float)le;
    }
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(corners, 8, tris, 4, mats, m, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const v3 eye = v(5.0, 1.0, 2.0), at = v(5.0, 3.0, 3.8), up = v(0.0, 1.0, 0.0);
    const double fov = 16.0;
    s->camera = (vct_camera){{5.0f, 1.0f, 2.0f}, {5.0f, 3.0f, 3.8f}, {0, 1, 0}, (float)fov};
    s->has_camera = 1;
    vct_pathtrace_result r;
    vct_image im = trace(ctx, s, W, H, 512, 1, 11, &r);
    static const double panel[4][3] = {{4, 2.99, 4}, {6, 2.99, 4}, {6, 2.99, 6}, {4, 2.99, 6}};
    static const double down[3] = {0.0, -1.0, 0.0};
    double got[BANDS] = {0}, want[BANDS] = {0};
    int count[BANDS] = {0};
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double sum = 0.0, nearest = 1e30;
            int on_ceiling = 1;
            for (int k = 0; k < SUB * SUB && on_ceiling; ++k) {
                /* the point of the pixel's k-th sub-square, as a finer image's pixel centre */
                const v3 d = camera_ray(eye, at, up, fov, W * SUB, H * SUB, x * SUB + k % SUB,
                                        y * SUB + k / SUB);
                const v3 on_panel = add(eye, mul(d, (panel_y - eye.y) / d.y));
                const v3 q = add(eye, mul(d, (ceiling - eye.y) / d.y));
                on_ceiling =
                    !(on_panel.x >= 4 && on_panel.x <= 6 && on_panel.z >= 4 && on_panel.z <= 6) &&
                    q.z < 4.0;
                const double p[3] = {q.x, q.y, q.z};
                sum += albedo / CHECK_PI * lambert_irradiance(p, down, panel, 4, le);
                nearest = fmin(nearest, 4.0 - q.z);
            }
            if (!on_ceiling)
                continue;
            const int band = nearest < 0.05 ? 0 : nearest < 0.15 ? 1 : 2;
            got[band] += im.rgba[4 * (y * W + x)];
            want[band] += sum / (SUB * SUB);
            ++count[band];
        }
    static const char *names[BANDS] = {"within 5 cm", "5 to 15 cm", "farther"};
    for (int b = 0; b < BANDS; ++b) {
        const double ratio = got[b] / want[b];
        CHECK(count[b] > 20 && fabs(ratio - 1.0) < 0.03,
              "ceiling %s of a panel 1 cm under it: %d pixels at %.4f of Lambert's formula",
              names[b], count[b], ratio);
        printf("ceiling %-12s of a panel 1 cm under it: %4d pixels, %.4f of Lambert's formula\n",
               names[b], count[b], ratio);
    }
    vct_image_release(&im);
    vct_scene_release(s);
}

/* Sums of the colour alone (colour_only) give the image of sums with their
 * moments, bit for bit; asking for the variance of them is refused; a
 * resumed call whose sums differ in kind from the running ones starts over,
 * and then gives a fresh call's image. */
static void colour_only_sums(vct_context *ctx) {
    vct_material m = vct_material_default();
    for (int c = 0; c < 3; ++c) { /* a colour, so that the channels' sums differ */
        m.albedo[c] = 0.6f - 0.1f * (float)c;
        m.emission[c] = 0.5f - 0.1f * (float)c;
    }
    vct_scene *s = cube_scene(m);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const size_t bytes = 16ull * 24 * 16;
    vct_image with_moments, variance, colour, resumed, again = {0};
    vct_pathtrace_options o = {24, 16, 4, 0.0, 8, 3, 2, 0, 0, &variance, NULL, 0};
    vct_pathtrace_result r;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &with_moments, &r, &err), err);
    vct_pathtrace_options plain = o;
    plain.variance = NULL;
    plain.colour_only = 1;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &plain, &colour, &r, &err), err);
    CHECK(memcmp(with_moments.rgba, colour.rgba, bytes) == 0,
          "the colour alone differs from the colour summed with its moments");
    plain.variance = &again;
    const vct_status refused = vct_render_pathtrace(ctx, s, g, &plain, &again, &r, &err);
    CHECK(refused == VCT_ERR_INPUT && strstr(err.message, "colour_only"),
          "the variance of colour-only sums: status %d (%s), expected an input error naming "
          "colour_only",
          (int)refused, err.message);
    plain.variance = NULL;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &plain, &colour, &r, &err), err);
    vct_image_release(&variance);
    o.resume = 1; /* the running sums hold no moments: this call starts over */
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &resumed, &r, &err), err);
    CHECK(r.spp == 4 && memcmp(resumed.rgba, with_moments.rgba, bytes) == 0,
          "a call with moments resumed colour-only sums (%u samples, expected a fresh 4)", r.spp);
    int known = 1;
    for (int i = 0; i < 24 * 16; ++i)
        known &= variance.rgba[4 * i] >= 0.0f;
    CHECK(known, "the variance after starting over is unknown somewhere");
    vct_image *all[] = {&with_moments, &variance, &colour, &resumed, &again};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        vct_image_release(all[i]);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    vct_context *ctx = check_context();
    resume_continues(ctx);
    colour_only_sums(ctx);
    ceiling_beside_panel(ctx);
    vct_material m = vct_material_default();
    for (int c = 0; c < 3; ++c) {
        m.albedo[c] = 0.5f;
        m.emission[c] = 1.0f;
    }
    furnace(ctx, "furnace a=0.5", m, 2.0);
    for (int c = 0; c < 3; ++c)
        m.albedo[c] = 0.8f;
    furnace(ctx, "furnace a=0.8", m, 5.0);
    vct_material mirror = vct_material_default();
    for (int c = 0; c < 3; ++c) {
        mirror.albedo[c] = 0.0f;
        mirror.specular[c] = 0.6f;
        mirror.emission[c] = 1.0f;
    }
    mirror.roughness = 0.0f;
    furnace(ctx, "mirror furnace a=0.6", mirror, 2.5);
    glass_slab(ctx, 0.0f);
    glass_slab(ctx, 45.0f);
    direct_matches_raycast(ctx);
    direct_and_indirect(ctx);
    open_scene_energy(ctx);
    sky_only_plane(ctx);
    convergence_and_determinism(ctx);
    packets_change_nothing(ctx);
    adversarial(ctx);
    vct_context_release(ctx);
    return check_exit("test_pathtrace");
}
