/* Cone tracing's pixels on an edge show the pixel's mean, as a converged
 * reference does, not the value at its centre.
 *
 * The reference is independent of the edge search: the ray caster at N^2
 * times the width and height, one ray through each of its pixel centres.
 * A coarse pixel's N x N rays go through N x N of those centres: ray (i, j)
 * through fine pixel (N i + j, N j + i) of its N^2 x N^2 block, each on a
 * column and a row of its own. A pixel that an edge crosses (those fine
 * pixels not all alike) must equal their mean; any other pixel its centre's
 * value, which lies within 1e-3 of that mean on a smooth surface. A pixel on
 * an edge of high contrast (the hard shadow's) takes (2 N)^2 rays: it must
 * equal the mean of its whole N^2 x N^2 block, within 3 % of the contrast
 * around. The scene holds every kind of edge: a floor's border against the
 * sky, a plate over the floor of the same material (found by geometry
 * alone), the plate's hard shadow (the lights seen) and two floor materials
 * meeting.
 *
 * Indirect light is weighted by the share of the pixel that found a surface:
 * a plate under a sky, whose indirect light is albedo * sky wherever it is
 * seen, has at its border the indirect light of its interior times the
 * share of the fine pixels that see it; a pixel across a wall's junction
 * with a floor, each surface's own light in its share. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "vct_case.h"

#define W 40
#define H 32
#define N 4

static vct_context *ctx;

static vct_scene *scene_of(const float *quads, int count, const uint32_t *quad_material,
                           const vct_material *materials, uint32_t material_count) {
    test_mesh t = mesh_quads(quads, (uint32_t)count);
    uint32_t *mat = malloc(4ull * t.nt);
    for (uint32_t i = 0; i < t.nt; ++i)
        mat[i] = quad_material[i / 2];
    vct_error err = {0};
    vct_scene *s =
        vct_scene_from_arrays(t.pos, t.nv, t.tri, t.nt, mat, materials, material_count, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(mat);
    mesh_free(&t);
    s->camera = (vct_camera){{0.05f, 3.0f, 0.02f}, {0, 0, 0}, {0, 0, -1}, 80.0f};
    return s;
}

static vct_image render_vct_with(const vct_scene *s, const vct_plan *plan, int w, int h,
                                 uint32_t edge_samples, int sparse, vct_aovs *aovs) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options vo = {0};
    vo.resolution = 32;
    vct_vct_options o = vct_vct_options_default(512, 512);
    o.width = w;
    o.height = h;
    o.edge_samples = edge_samples;
    o.aovs = aovs != NULL;
    o.indirect_passes = 0; /* the edges' own indirect light, unfiltered */
    o.sparse_diffuse = sparse;
    vct_voxels *v = NULL;
    REQUIRE_OK(vct_vct_prepare(ctx, s, g, plan, &vo, NULL, 1, &o.cones, &v, &err), err);
    vct_image im;
    vct_stats_reset(ctx);
    REQUIRE_OK(vct_render_vct(ctx, s, g, v, plan, &o, &im, aovs, &err), err);
    vct_voxels_release(v);
    vct_accel_release(g);
    return im;
}

static vct_image render_vct(const vct_scene *s, const vct_plan *plan, int w, int h,
                            uint32_t edge_samples, vct_aovs *aovs) {
    return render_vct_with(s, plan, w, h, edge_samples, 1, aovs);
}

/* The reference: the ray caster at N^2 times the width and height. */
static vct_image fine_reference(const vct_scene *s) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_render_options ro = {N * N * W, N * N * H, 0, 0, 0.0f};
    vct_image fine;
    REQUIRE_OK(vct_render_raycast(ctx, s, g, &ro, &fine, &err), err);
    vct_accel_release(g);
    return fine;
}

/* The fine pixels pixel (x, y)'s rays go through, channel k. */
static void block_stats(const vct_image *fine, int x, int y, int k, double *mean, double *spread) {
    double sum = 0.0, lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const size_t fx = (size_t)N * N * x + N * i + j, fy = (size_t)N * N * y + N * j + i;
            const double v = fine->rgba[4 * (fy * fine->width + fx) + k];
            sum += v;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
    *mean = sum / (N * N);
    *spread = hi - lo;
}

/* The mean of all N^2 x N^2 fine pixels of pixel (x, y), channel k, and
 * their spread over the 3 x 3 pixels around: the contrast of an edge
 * nearby, which may cross the pixel in a strip too thin for the fine
 * pixels' centres to meet. */
static void block_all(const vct_image *fine, int x, int y, int k, double *mean, double *spread) {
    double sum = 0.0, lo = INFINITY, hi = -INFINITY;
    const int s = N * N;
    for (int fy = s * (y - 1); fy < s * (y + 2); ++fy)
        for (int fx = s * (x - 1); fx < s * (x + 2); ++fx) {
            if (fx < 0 || fy < 0 || fx >= (int)fine->width || fy >= (int)fine->height)
                continue;
            const double v = fine->rgba[4 * ((size_t)fy * fine->width + fx) + k];
            if (fx / s == x && fy / s == y)
                sum += v;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
    *mean = sum / (s * s);
    *spread = hi - lo;
}

/* A floor of two materials (x < 0.7 and beyond), 2.2 wide each way, and a
 * plate of the first material over it; with `emitter`, a small emitting
 * quad above the floor too. */
static vct_scene *floor_and_plate(int emitter) {
    const float quads[] = {-2.2f, 0,    -2.2f, 0.7f,  0,     -2.2f, 0.7f,  0,     2.2f, -2.2f,
                           0,     2.2f, 0.7f,  0,     -2.2f, 2.2f,  0,     -2.2f, 2.2f, 0,
                           2.2f,  0.7f, 0,     2.2f,  -1.9f, 1.1f,  -1.3f, -0.2f, 1.1f, -1.3f,
                           -0.2f, 1.1f, 0.9f,  -1.9f, 1.1f,  0.9f,  0.9f,  0.4f,  0.3f, 1.3f,
                           0.4f,  0.3f, 1.3f,  0.4f,  0.6f,  0.9f,  0.4f,  0.6f};
    const uint32_t quad_material[4] = {0, 1, 0, 2};
    vct_material m[3] = {vct_material_default(), vct_material_default(), vct_material_default()};
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.8f;
    m[1].albedo[0] = 0.3f, m[1].albedo[1] = 0.6f, m[1].albedo[2] = 0.2f;
    m[2].albedo[0] = m[2].albedo[1] = m[2].albedo[2] = 0.5f;
    m[2].emission[0] = m[2].emission[1] = m[2].emission[2] = 4.0f;
    return scene_of(quads, emitter ? 4 : 3, quad_material, m, emitter ? 3 : 2);
}

static void direct_edges(void) {
    /* the floor and the plate; a point light above */
    vct_scene *s = floor_and_plate(0);
    vct_light light = {0};
    light.type = VCT_LIGHT_POINT;
    light.position[0] = -1.5f, light.position[1] = 3.4f, light.position[2] = -0.35f;
    light.color[0] = light.color[1] = light.color[2] = 9.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);

    vct_image fine = fine_reference(s);

    for (uint32_t n = 1; n <= N; n += N - 1) {
        vct_image im = render_vct(s, &plan, W, H, n, NULL);
        CHECK(vct_kernel_launches(ctx, "vct_primary_refine") == (n > 1),
              "%u rays per axis: the refining pass ran %llu times", n,
              (unsigned long long)vct_kernel_launches(ctx, "vct_primary_refine"));
        int edges = 0, flat = 0, off = 0, centred = 0, sharp = 0;
        double worst = 0.0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int edge = 0, whole = 1;
                double err_px = 0.0;
                for (int k = 0; k < 3; ++k) {
                    double mean, spread, all_mean, all_spread;
                    block_stats(&fine, x, y, k, &mean, &spread);
                    block_all(&fine, x, y, k, &all_mean, &all_spread);
                    const double got = im.rgba[4 * (y * W + x) + k];
                    edge |= spread > 0.25 * (mean + 1e-2);
                    err_px = fmax(err_px, fabs(got - mean) / (mean + 1e-2));
                    whole &= fabs(got - all_mean) <= 0.03 * all_spread + 1e-3 * (all_mean + 1e-2);
                }
                edges += edge;
                flat += !edge;
                centred += edge && err_px > 1e-2;
                if (n == N && err_px > 1e-3) {
                    sharp += whole;
                    off += !whole;
                    worst = fmax(worst, err_px);
                }
            }
        if (n == N)
            CHECK(off <= 2 && sharp > 20 && edges > 100 && flat > 400,
                  "%u rays per axis: %d pixels (of %d on an edge and %d not) differ from the "
                  "fine ray caster's mean over their rays by more than 1e-3 (worst %.3g) and "
                  "from its mean over the whole pixel by more than 3 %% of its spread; %d "
                  "pixels on the shadow's sharp edge took the whole pixel's mean",
                  n, off, edges, flat, worst, sharp);
        else
            CHECK(centred > edges / 2,
                  "one ray per pixel: only %d of %d edge pixels differ from their mean (the "
                  "test sees no edges)",
                  centred, edges);
        vct_image_release(&im);
    }
    vct_image_release(&fine);
    vct_scene_release(s);
}

/* The denoiser's guides among the AOVs (vct_aovs.albedo, .normal_depth)
 * come from the pixel's own camera samples: with one ray per pixel they are
 * render_guides' with one ray; with N x N they are, at every pixel an edge
 * crosses, the mean of render_guides' at the N x N fine pixels its rays go
 * through (the albedo, the share on no emitter, the normal, the distance
 * of the rays that found a surface), and elsewhere the centre's, within
 * what a flat surface varies across a pixel. The scene: the floor of two
 * materials, the plate over it, the sky beyond, and a small emitter. */
static void guides_from_samples(void) {
    vct_scene *s = floor_and_plate(1);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_image centre_a, centre_nd, fine_a, fine_nd;
    REQUIRE_OK(vct_render_guides(ctx, s, g, W, H, 1, &centre_a, &centre_nd, &err), err);
    REQUIRE_OK(vct_render_guides(ctx, s, g, N * N * W, N * N * H, 1, &fine_a, &fine_nd, &err), err);
    vct_accel_release(g);
    for (uint32_t n = 1; n <= N; n += N - 1) {
        vct_aovs a;
        vct_image im = render_vct(s, &plan, W, H, n, &a);
        int edges = 0, off = 0, glowing = 0;
        double worst = 0.0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const size_t p = (size_t)y * W + x;
                const float *ga = a.albedo.rgba + 4 * p, *gn = a.normal_depth.rgba + 4 * p;
                double want[8] = {0}, hits = 0.0;
                int edge = 0;
                if (n == 1) {
                    for (int k = 0; k < 4; ++k) {
                        want[k] = centre_a.rgba[4 * p + k];
                        want[4 + k] = centre_nd.rgba[4 * p + k];
                    }
                } else {
                    const float *first = NULL, *first_n = NULL;
                    for (int j = 0; j < N; ++j)
                        for (int i = 0; i < N; ++i) {
                            const size_t fx = (size_t)N * N * x + N * i + j,
                                         fy = (size_t)N * N * y + N * j + i;
                            const size_t f = fy * fine_a.width + fx;
                            const float *fa = fine_a.rgba + 4 * f, *fn = fine_nd.rgba + 4 * f;
                            for (int k = 0; k < 4; ++k)
                                want[k] += fa[k] / (N * N);
                            for (int k = 0; k < 3; ++k)
                                want[4 + k] += fn[k] / (N * N);
                            want[7] += fn[3];
                            hits += fn[3] > 0.0f;
                            edge |= first &&
                                    (memcmp(first, fa, 16) != 0 || memcmp(first_n, fn, 12) != 0);
                            first_n = first ? first_n : fn;
                            first = first ? first : fa;
                        }
                    want[7] = hits > 0.0 ? want[7] / hits : 0.0;
                }
                double e = 0.0;
                for (int k = 0; k < 7; ++k)
                    e = fmax(e, fabs((k < 4 ? ga[k] : gn[k - 4]) - want[k]));
                /* the distance: relative, and across a flat pixel's rays */
                e = fmax(e, fabs(gn[3] - want[7]) / (want[7] + 1.0) * (n == 1 ? 10.0 : 1.0));
                edges += edge;
                glowing += ga[3] < 1.0f;
                worst = fmax(worst, e);
                if (!(e <= (n == 1 ? 1e-5 : 2e-3)) && off++ < 3)
                    fprintf(stderr,
                            "guides, %u rays per axis: pixel (%d, %d) off by %g: albedo %g %g "
                            "%g %g, normal and distance %g %g %g %g; want %g %g %g %g, %g %g %g "
                            "%g\n",
                            n, x, y, e, ga[0], ga[1], ga[2], ga[3], gn[0], gn[1], gn[2], gn[3],
                            want[0], want[1], want[2], want[3], want[4], want[5], want[6], want[7]);
            }
        if (n == 1)
            CHECK(off == 0 && glowing > 0,
                  "one ray per pixel: %d pixels' guides differ from render_guides' (worst %g), "
                  "%d on the emitter",
                  off, worst, glowing);
        else
            CHECK(off <= 2 && edges > 50,
                  "%u rays per axis: %d pixels' guides (%d on an edge) differ from the mean of "
                  "the fine pixels their rays go through (worst %g)",
                  n, off, edges, worst);
        printf("guides from the camera samples, %u rays per axis: %d on an edge, %d off, worst "
               "%.3g\n",
               n, edges, off, worst);
        vct_image_release(&im);
        vct_aovs_release(&a);
    }
    vct_image *all[] = {&centre_a, &centre_nd, &fine_a, &fine_nd};
    for (int i = 0; i < 4; ++i)
        vct_image_release(all[i]);
    vct_scene_release(s);
}

static void indirect_share(void) {
    const float plate[] = {-1.2f, 0.5f, -0.9f, 1.1f,  0.5f, -0.9f,
                           1.1f,  0.5f, 1.0f,  -1.2f, 0.5f, 1.0f};
    const uint32_t quad_material[1] = {0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.6f;
    vct_scene *s = scene_of(plate, 1, quad_material, &m, 1);
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.5f;
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    CHECK(plan.on[VCT_EFFECT_INDIRECT] || plan.on[VCT_EFFECT_AO], "a sky-lit plate plans cones");
    /* Which fine pixels see the plate: their positions, no cones needed. */
    vct_plan visible;
    vct_case_plan_forcing(s, VCT_EFFECT_DIRECT, VCT_FORCE_OFF, VCT_FORCE_OFF, &visible);
    vct_aovs aovs, fine_aovs;
    vct_image im = render_vct(s, &plan, W, H, N, &aovs);
    vct_image fine = render_vct(s, &visible, N * N * W, N * N * H, 1, &fine_aovs);
    /* The interior's indirect light, and each border pixel's share. */
    double interior = 0.0;
    int inside = 0;
    double share[W * H];
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int hits = 0;
            for (int j = 0; j < N; ++j)
                for (int i = 0; i < N; ++i) {
                    const size_t fx = (size_t)N * N * x + N * i + j,
                                 fy = (size_t)N * N * y + N * j + i;
                    hits += fine_aovs.position.rgba[4 * (fy * N * N * W + fx) + 3] != 0.0f;
                }
            share[y * W + x] = (double)hits / (N * N);
            if (hits == N * N) {
                interior += aovs.indirect.rgba[4 * (y * W + x) + 1];
                ++inside;
            }
        }
    interior /= inside > 0 ? inside : 1;
    int border = 0, off = 0;
    double worst = 0.0;
    for (int p = 0; p < W * H; ++p) {
        if (share[p] == 0.0 || share[p] == 1.0)
            continue;
        ++border;
        const double got = aovs.indirect.rgba[4 * p + 1] / interior;
        worst = fmax(worst, fabs(got - share[p]));
        off += fabs(got - share[p]) > 0.08;
    }
    CHECK(inside > 150 && border > 40 && off == 0 && interior > 0.2,
          "indirect light at the border in proportion to the share that sees the plate: %d of "
          "%d border pixels off by more than 0.08 (worst %.3f; interior %.4f over %d pixels)",
          off, border, worst, interior, inside);
    vct_image_release(&im);
    vct_image_release(&fine);
    vct_aovs_release(&aovs);
    vct_aovs_release(&fine_aovs);
    vct_scene_release(s);
}

/* A wall standing on a floor, the floor lit by the sun and the wall not
 * (the sun travels along the wall's plane):
 * the wall's foot sees the bright floor close by, the floor beside it the
 * dark wall, and their indirect light differs by a factor of several. A
 * pixel across the junction must show each surface's own light in the
 * share of the pixel it covers, as the reference does: cone tracing at N
 * times the width and height, one ray through each pixel centre, its
 * indirect light averaged over each coarse pixel's N x N block. The
 * junction's pixels (blocks on both surfaces) must lie within 30 % of the
 * light's contrast there (the wall's light just above against the
 * floor's just below, ten to one); shading a pixel by one of its surfaces
 * alone was off by up to half of it (measured: worst 0.55 dense, 0.50
 * sparse; with the second surface 0.21 and 0.16). */
static void junction(void) {
    const float quads[] = {0, 0, -2, 0, 0,    2,  2.5f, 0,    2, 2.5f, 0, -2,
                           0, 0, -2, 0, 1.5f, -2, 0,    1.5f, 2, 0,    0, 2};
    const uint32_t quad_material[2] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.7f;
    vct_scene *s = scene_of(quads, 2, quad_material, &m, 1);
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0, 0, 0}, {0.0f, -1.0f, 0.6f}, {3, 3, 3}, 0, 0, 0};
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    s->camera = (vct_camera){{1.6f, 0.5f, 0.05f}, {0.0f, 0.12f, 0.0f}, {0, 1, 0}, 50.0f};
    s->has_camera = 1;
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    for (int sparse = 0; sparse < 2; ++sparse) {
        vct_aovs aovs, fine_aovs;
        vct_image im = render_vct_with(s, &plan, W, H, N, sparse, &aovs);
        vct_image fine = render_vct_with(s, &plan, N * W, N * H, 1, sparse, &fine_aovs);
        /* each coarse pixel's block: the mean of its indirect light, and
         * what it covers (1 wall, 2 floor, 3 both) */
        double want[W * H];
        int covers[W * H];
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int wall = 0, ground = 0;
                double sum = 0.0;
                for (int j = 0; j < N; ++j)
                    for (int i = 0; i < N; ++i) {
                        const size_t f = (size_t)(N * y + j) * N * W + N * x + i;
                        const float *n = &fine_aovs.normal.rgba[4 * f];
                        wall += n[3] != 0.0f && n[0] > 0.9f;
                        ground += n[3] != 0.0f && n[1] > 0.9f;
                        sum += fine_aovs.indirect.rgba[4 * f + 1];
                    }
                want[y * W + x] = sum / (N * N);
                covers[y * W + x] = wall + ground < N * N ? 0 : (wall > 0) + 2 * (ground > 0);
            }
        /* the contrast: the wall's light just above the junction against
         * the floor's just below it */
        double wall_light = 0.0, floor_light = 0.0;
        int walls = 0, floors = 0;
        for (int y = 1; y + 1 < H; ++y)
            for (int x = 0; x < W; ++x)
                if (covers[y * W + x] == 3) {
                    if (covers[(y - 1) * W + x] == 1)
                        wall_light += want[(y - 1) * W + x], ++walls;
                    if (covers[(y + 1) * W + x] == 2)
                        floor_light += want[(y + 1) * W + x], ++floors;
                }
        wall_light /= walls > 0 ? walls : 1;
        floor_light /= floors > 0 ? floors : 1;
        const double contrast = wall_light - floor_light;
        int crossed = 0, off = 0;
        double worst = 0.0;
        for (int p = 0; p < W * H; ++p) {
            if (covers[p] != 3)
                continue;
            ++crossed;
            const double e = fabs(aovs.indirect.rgba[4 * p + 1] - want[p]) / contrast;
            worst = fmax(worst, e);
            off += e > 0.3;
        }
        CHECK(crossed >= W && off == 0 && wall_light > 2.0 * floor_light,
              "junction, %s gather: %d of %d pixels across it off by more than 30 %% of the "
              "light's contrast (worst %.3f; the wall's light %.4f, the floor's %.4f)",
              sparse ? "sparse" : "dense", off, crossed, worst, wall_light, floor_light);
        printf("junction, %s gather: %d pixels across it, worst off by %.3f of the contrast "
               "(the wall's light %.4f, the floor's %.4f)\n",
               sparse ? "sparse" : "dense", crossed, worst, wall_light, floor_light);
        vct_image_release(&im);
        vct_image_release(&fine);
        vct_aovs_release(&aovs);
        vct_aovs_release(&fine_aovs);
    }
    vct_scene_release(s);
}

/* A floor wider than the view, textured with a TEX x TEX checker (0.1 and
 * 0.9) repeated `reps` times each way: a texel about 1.5 pixels wide, so
 * that a pixel's texture varies within it. A sun straight down of
 * irradiance pi makes the ray caster's radiance the albedo itself. */
#define TEX 8
static vct_scene *textured_floor(float reps) {
    const float floor[] = {-4, 0, -4, 4, 0, -4, 4, 0, 4, -4, 0, 4};
    const uint32_t quad_material[1] = {0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    vct_scene *s = scene_of(floor, 1, quad_material, &m, 1);
    free(s->uvs);
    s->uvs = malloc(sizeof(float) * 2 * s->vertex_count);
    for (uint32_t i = 0; i < s->vertex_count; ++i) {
        s->uvs[2 * i] = (s->positions[3 * i] + 4.0f) / 8.0f * reps;
        s->uvs[2 * i + 1] = (s->positions[3 * i + 2] + 4.0f) / 8.0f * reps;
    }
    s->textures = calloc(1, sizeof *s->textures);
    s->texture_count = 1;
    vct_texture *t = &s->textures[0];
    snprintf(t->name, sizeof t->name, "checker");
    t->width = t->height = TEX;
    t->rgba = malloc(sizeof(float) * 4 * TEX * TEX);
    for (int y = 0; y < TEX; ++y)
        for (int x = 0; x < TEX; ++x)
            for (int c = 0; c < 4; ++c)
                t->rgba[4 * (y * TEX + x) + c] = c == 3 ? 1.0f : (((x + y) & 1) ? 0.9f : 0.1f);
    s->materials[0].albedo_texture = 1;
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, -1, 0}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    vct_error err = {0};
    REQUIRE_OK(vct_scene_validate(s, &err), err);
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    return s;
}

/* A texture's detail within a pixel is an edge too: the pixel shows the
 * mean of its texture, in its direct light (against the ray caster's fine
 * pixels) and in its indirect light, which is the sky's times the albedo,
 * so that indirect / mean albedo is one value over the whole floor. With
 * one ray per pixel neither holds. */
static void texture_detail(void) {
    vct_scene *s = textured_floor(4.0f);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_render_options ro = {N * N * W, N * N * H, 0, 0, 0.0f};
    vct_image fine; /* the albedo at each fine pixel */
    REQUIRE_OK(vct_render_raycast(ctx, s, g, &ro, &fine, &err), err);
    vct_accel_release(g);
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.5f;
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    CHECK(plan.on[VCT_EFFECT_INDIRECT], "a sky-lit floor plans indirect light");
    for (uint32_t n = 1; n <= N; n += N - 1) {
        vct_aovs aovs;
        vct_image im = render_vct(s, &plan, W, H, n, &aovs);
        int varied = 0, off = 0;
        double worst = 0.0, lo = INFINITY, hi = -INFINITY;
        for (int y = 1; y < H - 1; ++y)
            for (int x = 1; x < W - 1; ++x) {
                const int p = y * W + x;
                double mean, spread;
                block_stats(&fine, x, y, 1, &mean, &spread);
                const double direct = aovs.direct.rgba[4 * p + 1];
                const double e = fabs(direct - mean) / mean;
                const double shade = aovs.indirect.rgba[4 * p + 1] / mean;
                lo = fmin(lo, shade);
                hi = fmax(hi, shade);
                if (spread > 0.25 * mean) {
                    ++varied;
                    off += e > 1e-2;
                    worst = fmax(worst, e);
                }
            }
        const double indirect_spread = (hi - lo) / hi;
        if (n == N)
            CHECK(varied > 200 && off == 0 && indirect_spread < 0.1,
                  "%u rays per axis: %d of %d pixels whose texture varies differ from its mean "
                  "by more than 1 %% (worst %.3g); indirect light over the mean albedo spreads "
                  "by %.3f",
                  n, off, varied, worst, indirect_spread);
        else
            CHECK(off > varied / 2 && indirect_spread > 0.3,
                  "one ray per pixel: only %d of %d textured pixels differ from their mean, "
                  "indirect over albedo spreads by %.3f (the test sees no texture)",
                  off, varied, indirect_spread);
        printf("texture detail, %u rays per axis: %d of %d varied pixels off their mean (worst "
               "%.3g), indirect / albedo spread %.3f\n",
               n, off, varied, worst, indirect_spread);
        vct_image_release(&im);
        vct_aovs_release(&aovs);
    }
    vct_image_release(&fine);
    vct_scene_release(s);
}

/* More rays per axis than VCT_EDGE_SAMPLES_MAX: a clear error, no image. */
static void too_many_rays(void) {
    const float quad[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const uint32_t quad_material[1] = {0};
    const vct_material m = vct_material_default();
    vct_scene *s = scene_of(quad, 1, quad_material, &m, 1);
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 1.0f;
    vct_plan plan;
    vct_case_plan_forcing(s, VCT_EFFECT_DIRECT, VCT_FORCE_OFF, VCT_FORCE_OFF, &plan);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_vct_options o = vct_vct_options_default(512, 512);
    o.width = o.height = 8;
    o.edge_samples = VCT_EDGE_SAMPLES_MAX + 1;
    vct_image im;
    const int rc = vct_render_vct(ctx, s, g, NULL, &plan, &o, &im, NULL, &err);
    CHECK(rc == VCT_ERR_INPUT && strstr(err.message, "rays per axis") && im.rgba == NULL,
          "%u rays per axis: rc %d, '%s'", o.edge_samples, rc, err.message);
    o.edge_samples = VCT_EDGE_SAMPLES_DEFAULT;
    o.indirect_passes = VCT_INDIRECT_PASSES_MAX + 1;
    const int passes_rc = vct_render_vct(ctx, s, g, NULL, &plan, &o, &im, NULL, &err);
    CHECK(passes_rc == VCT_ERR_INPUT && strstr(err.message, "filter passes") && im.rgba == NULL,
          "%u filter passes: rc %d, '%s'", o.indirect_passes, passes_rc, err.message);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* An emitting quad facing the camera, on black: its border pixels show
 * its emission times the share of each pixel it covers, worked out from
 * the camera's projection (a plane facing a pinhole camera maps to the
 * image affinely). Its edges cross their pixels at 0.53 of them, where the
 * N x N rays of other edges see 8 of 16 (off by 3 % of the emission, far
 * more than the rest of the image's light where an emitter is small);
 * emitters' borders take (4 N)^2 rays and must be within 1 %. */
static void emitter_border(void) {
    const float d = 4.0f, t = tanf(0.5f * 40.0f * 3.14159265f / 180.0f), a = (float)W / (float)H;
    const float px0 = 10.47f, px1 = 29.53f, py0 = 8.47f, py1 = 23.53f; /* pixel units */
    const float x0 = (2.0f * px0 / W - 1.0f) * d * t * a, x1 = (2.0f * px1 / W - 1.0f) * d * t * a;
    const float y0 = (1.0f - 2.0f * py1 / H) * d * t, y1 = (1.0f - 2.0f * py0 / H) * d * t;
    const float quad[] = {x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0};
    const uint32_t quad_material[1] = {0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.0f;
    m.emission[0] = m.emission[1] = m.emission[2] = 100.0f;
    vct_scene *s = scene_of(quad, 1, quad_material, &m, 1);
    s->camera = (vct_camera){{0, 0, d}, {0, 0, 0}, {0, 1, 0}, 40.0f};
    vct_plan plan;
    vct_plan_make(s, NULL, &plan);
    vct_image im = render_vct(s, &plan, W, H, N, NULL);
    double worst = 0.0;
    int border = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double cx = fmax(0.0, fmin(x + 1.0, px1) - fmax((double)x, px0));
            const double cy = fmax(0.0, fmin(y + 1.0, py1) - fmax((double)y, py0));
            const double want = 100.0 * cx * cy;
            border += want > 0.0 && want < 100.0;
            for (int k = 0; k < 3; ++k)
                worst = fmax(worst, fabs(im.rgba[4 * (y * W + x) + k] - want) / 100.0);
        }
    CHECK(border > 0 && worst < 0.01,
          "emitter's border: a pixel off by %.4f of the emission (%d border pixels)", worst,
          border);
    printf("emitter's border: %d pixels covered in part, worst off by %.4f of the emission\n",
           border, worst);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* A hard shadow's edge, oblique to the pixel grid: a floor (albedo 0.8)
 * seen straight down, under a sun straight down of irradiance pi and a
 * plate above the camera whose edge is the line x = 0.3 + 0.16 z. Lit
 * floor shows 0.8, shadowed floor 0, and a pixel the edge crosses 0.8
 * times its lit share, integrated here on a 256 x 256 grid (a plane facing
 * a pinhole camera maps to the image affinely). Light against shadow is
 * the sharpest contrast a surface shows, and the N x N rays of other edges
 * meet it in N^2 steps: their error reaches 1/N^2 of it (3.4 % on average
 * here, 9.3 % at worst). Such pixels take (2 N)^2 rays: their mean error
 * must stay within 1.5 % of the contrast and the worst within 4.5 %. */
static double lit_share(int x, int y, float t, float a) {
    const int k = 256;
    int lit = 0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            const double px = x + (i + 0.5) / k, py = y + (j + 0.5) / k;
            const double wx = (2.0 * px / W - 1.0) * 3.0 * t * a,
                         wz = (2.0 * py / H - 1.0) * 3.0 * t;
            lit += wx > 0.3 + 0.16 * wz;
        }
    return (double)lit / ((double)k * k);
}

static void shadow_edge(void) {
    const float quads[] = {-6,    0,    -6, 6,      0,    -6, 6,     0,    6, -6,    0,    6,
                           -9.0f, 3.5f, -9, -1.14f, 3.5f, -9, 1.74f, 3.5f, 9, -9.0f, 3.5f, 9};
    const uint32_t quad_material[2] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.8f;
    vct_scene *s = scene_of(quads, 2, quad_material, &m, 1);
    s->camera = (vct_camera){{0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 80.0f};
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, -1, 0}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    const float t = tanf(0.5f * 80.0f * 3.14159265f / 180.0f), a = (float)W / (float)H;
    vct_image im = render_vct(s, &plan, W, H, N, NULL);
    double sum = 0.0, worst = 0.0;
    int edge = 0, flat_off = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double want = 0.8 * lit_share(x, y, t, a);
            double e = 0.0;
            for (int k = 0; k < 3; ++k)
                e = fmax(e, fabs(im.rgba[4 * (y * W + x) + k] - want) / 0.8);
            if (want > 0.0 && want < 0.8) {
                ++edge;
                sum += e;
                worst = fmax(worst, e);
            } else
                flat_off += e > 1e-3;
        }
    const double mean = edge ? sum / edge : 0.0;
    CHECK(edge > 20 && flat_off == 0 && mean < 0.015 && worst < 0.045,
          "hard shadow's edge: %d pixels crossed, off their lit share by %.4f of the contrast on "
          "average and %.4f at worst; %d pixels off it are off",
          edge, mean, worst, flat_off);
    printf("hard shadow's edge: %d pixels crossed, off by %.4f of the contrast on average, %.4f "
           "at worst\n",
           edge, mean, worst);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* A faceted ball (an icosphere, each face flat and lit at its own angle)
 * on a floor: one surface as the edge search sees it (neighbouring faces
 * turn by less than it counts as an edge), one material, one light. Where
 * the faces' shading steps across a pixel, the pixel must show the mean of
 * the fine ray caster's pixels it covers (within 1 % of the light), as on
 * any other edge, not its centre's face: all but a quarter do (the smallest
 * steps are left to the centre; measured 37 of 204 off, 100 when only
 * geometric edges were refined); at one ray per pixel most are off. */
static void facets(void) {
    const float centre[3] = {0.0f, 0.6f, 0.0f};
    test_mesh t = mesh_icosphere(2, 0.6f, centre);
    uint32_t *mat = calloc(t.nt, 4);
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.8f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(t.pos, t.nv, t.tri, t.nt, mat, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(mat);
    mesh_free(&t);
    s->camera = (vct_camera){{0.0f, 0.7f, 1.9f}, {0.0f, 0.6f, 0.0f}, {0, 1, 0}, 50.0f};
    const vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0}, {-0.6f, -0.5f, -0.62f}, {3, 3, 3}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    vct_image fine = fine_reference(s);
    double light = 0.0;
    for (size_t i = 0; i < (size_t)fine.width * fine.height; ++i)
        light = fmax(light, fine.rgba[4 * i]);
    int stepped = 0, off[2] = {0, 0};
    for (uint32_t n = 1; n <= N; n += N - 1) {
        vct_image im = render_vct(s, &plan, W, H, n, NULL);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                double mean, spread, all_mean, all_spread;
                block_stats(&fine, x, y, 0, &mean, &spread);
                block_all(&fine, x, y, 0, &all_mean, &all_spread);
                if (spread < 0.05 * light || mean <= 0.0)
                    continue; /* no step within the pixel */
                stepped += n == N;
                off[n == N] += fabs(im.rgba[4 * (y * W + x)] - all_mean) > 0.01 * light;
            }
        vct_image_release(&im);
    }
    printf("faceted ball: %d pixels a step between faces crosses; %d off their mean (%d "
           "with one ray per pixel)\n",
           stepped, off[1], off[0]);
    CHECK(stepped > 30 && off[1] <= stepped / 4 && off[0] > stepped / 2,
          "faceted ball: %d pixels a step between faces crosses; %d off their mean (%d "
          "with one ray per pixel)",
          stepped, off[1], off[0]);
    vct_image_release(&fine);
    vct_scene_release(s);
}

/* Bars 0.3 rows thick against the empty sky, like a blind's slats in a
 * window, lit head-on, in groups of `per` pixel rows, bar k % per of a
 * group (k < per) with its top `top[k % per]` rows below the group's first
 * row; and a first bar below them. Each pixel a bar crosses must show the bars'
 * light times the share of it they cover, within a tenth of the light (the
 * rays of an edge of high contrast step by 1/8 of a row); with one ray per
 * pixel, more than half of them must not (the test would not see a
 * broken edge search). */
static void bars_against_sky(const char *what, const float *top, int per) {
    enum { GROUPS = 6 };
    const int bars = GROUPS * per + 1;
    const float pixel = 2.0f * 5.0f * tanf(20.0f * 3.14159265f / 180.0f) / H;
    float *quads = malloc(sizeof(float) * 12 * (size_t)bars);
    uint32_t *quad_material = calloc((size_t)bars, sizeof(uint32_t));
    for (int k = 0; k < bars; ++k) {
        const float row = 1.0f + (float)(per * (k / per)) + top[k % per]; /* from the top */
        const float y1 = (0.5f * H - row) * pixel, y0 = y1 - 0.3f * pixel;
        const float q[12] = {-3, y0, 0, 3, y0, 0, 3, y1, 0, -3, y1, 0};
        memcpy(quads + 12 * k, q, sizeof q);
    }
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.8f;
    vct_scene *s = scene_of(quads, bars, quad_material, &m, 1);
    s->camera = (vct_camera){{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f};
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, 0, -1}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    int crossed[2] = {0, 0}, off[2] = {0, 0};
    double worst[2] = {0.0, 0.0};
    for (uint32_t n = 1; n <= N; n += N - 1) {
        vct_image im = render_vct(s, &plan, W, H, n, NULL);
        const int i = n == N;
        for (int y = 0; y < H; ++y) {
            /* the share of row y the bars cover (a plane facing a pinhole
             * camera maps to the image affinely) */
            double share = 0.0;
            for (int k = 0; k < bars; ++k) {
                const double r0 = 1.0 + per * (k / per) + top[k % per];
                share += fmax(0.0, fmin(y + 1.0, r0 + 0.3) - fmax((double)y, r0));
            }
            if (share <= 0.0)
                continue;
            for (int x = 0; x < W; ++x) {
                const double e = fabs(im.rgba[4 * (y * W + x) + 1] - 0.8 * share) / 0.8;
                ++crossed[i];
                off[i] += e > 0.1;
                worst[i] = fmax(worst[i], e);
            }
        }
        vct_image_release(&im);
    }
    CHECK(crossed[1] > 0 && off[1] == 0 && off[0] > crossed[0] / 2,
          "%s: %d of %d pixels a bar crosses off its share of the light by more than a tenth "
          "of it (worst %.3f); with one ray per pixel %d of %d",
          what, off[1], crossed[1], worst[1], off[0], crossed[0]);
    printf("%s: %d pixels crossed, worst off by %.4f of the light (one ray per pixel: %d off, "
           "worst %.4f)\n",
           what, crossed[1], worst[1], off[0], worst[0]);
    free(quads);
    free(quad_material);
    vct_scene_release(s);
}

/* In every group of five rows a bar covers the first row's centre, and
 * four more cross the other rows between their centres: rows two away from
 * the one whose centres meet a bar have no centre on a bar within the 3 x 3
 * pixels around, and were shown as pure sky (off by 0.3 of the bars'
 * light): a surface against a miss within two pixels is an edge. Then a
 * bar in every row, each below its row's centre: no centre meets one, and
 * the window showed clear sky (the sky pixels' probes find them). */
static void thin_bars(void) {
    const float near_centres[5] = {0.35f, 1.05f, 2.6f, 3.1f, 4.6f};
    bars_against_sky("thin bars against the sky", near_centres, 5);
    const float between_centres[2] = {0.55f, 1.6f};
    bars_against_sky("bars between every centre", between_centres, 2);
}

int main(void) {
    ctx = check_context();
    too_many_rays();
    direct_edges();
    guides_from_samples();
    indirect_share();
    texture_detail();
    emitter_border();
    shadow_edge();
    facets();
    thin_bars();
    junction();
    vct_context_release(ctx);
    return check_exit("test_edge_samples");
}
