/* Whitted ray tracing against analytic answers.
 *
 * Diffuse-only scenes: the image equals the ray caster's bit for bit (the
 * same shading, nothing to reflect). Mirror: a metal mirror facing a floor
 * under a point light; each pixel that sees the mirror holds the mirror's
 * reflectance times the floor's direct radiance at the reflected point, each
 * pixel that sees the floor that radiance (double-precision reference, 1e-4
 * relative). Glass: a slab in front of an emissive wall at normal and 45°
 * incidence: E (1 - F)^2 (1 + F^2 + F^4 ...), the terms the depth limit and
 * the throughput cut-off leave, with F from the Fresnel equations in double.
 * Total internal reflection: from inside a slab, below the critical angle
 * the ceiling's light comes through with 1 - F, beyond it none does. */
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "raytrace/whitted_as.h"
#include "vec3d.h"

#define L 50.0f
#define PI 3.14159265358979323846

static vct_context *ctx;

static vct_material matte(float a) {
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = a;
    return m;
}

static vct_material emitter(const float e[3]) {
    vct_material m = matte(0.0f);
    memcpy(m.emission, e, sizeof m.emission);
    return m;
}

static vct_material glass(void) {
    vct_material m = matte(1.0f);
    m.transmission = 1.0f;
    m.ior = 1.5f;
    m.roughness = 0.0f;
    return m;
}

/* Quads (4 corners each) with one material each. */
static vct_scene *quads_scene(const float *corners, uint32_t n, const vct_material *mats) {
    test_mesh m = mesh_quads(corners, n);
    uint32_t *tri_mat = malloc(4ull * m.nt);
    for (uint32_t t = 0; t < m.nt; ++t)
        tri_mat[t] = t / 2;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(m.pos, m.nv, m.tri, m.nt, tri_mat, mats, n, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(tri_mat);
    mesh_free(&m);
    return s;
}

static vct_image render(const vct_scene *s, vct_method method, int w, int h, uint32_t depth,
                        float cut) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_render_job job = vct_render_job_default(method, w, h);
    job.scene = s;
    job.accel = a;
    if (depth)
        job.whitted.max_depth = depth;
    if (cut >= 0.0f)
        job.whitted.min_throughput = cut;
    vct_image im;
    REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    vct_accel_release(a);
    return im;
}

static void check_same_as_raycast(vct_scene *s, const char *name) {
    vct_image w = render(s, VCT_METHOD_WHITTED, 40, 40, 0, -1.0f);
    vct_image r = render(s, VCT_METHOD_RAYCAST, 40, 40, 0, -1.0f);
    size_t differ = 0;
    double sum = 0.0;
    for (size_t i = 0; i < 40 * 40 * 4; ++i) {
        differ += memcmp(&w.rgba[i], &r.rgba[i], 4) != 0;
        sum += i % 4 == 3 ? 0.0 : r.rgba[i]; /* alpha is 1 everywhere */
    }
    CHECK(differ == 0 && sum > 0.0, "%s: %zu values differ from the ray caster's", name, differ);
    printf("%s: whitted equals the ray caster, %zu values differ\n", name, differ);
    vct_image_release(&w);
    vct_image_release(&r);
}

static const float radiant[3] = {2.0f, 3.0f, 4.0f};

/* Floor (x <= 1) under a point light, a metal mirror at x = 1 facing it. */
static void check_mirror(void) {
    const float floor_mirror[24] = {-6, 0, -6, -6, 0, 6, 1, 0, 6, 1, 0, -6,
                                    1,  0, -6, 1,  0, 6, 1, 4, 6, 1, 4, -6};
    vct_material mats[2] = {matte(0.6f), matte(0.0f)};
    const float R[3] = {0.9f, 0.7f, 0.5f};
    memcpy(mats[1].albedo, R, sizeof R);
    mats[1].metallic = 1.0f;
    mats[1].roughness = 0.0f;
    vct_scene *s = quads_scene(floor_mirror, 2, mats);
    vct_light light = {0};
    light.type = VCT_LIGHT_POINT;
    light.position[0] = -1.0f, light.position[1] = 3.0f, light.position[2] = 0.5f;
    light.color[0] = light.color[1] = light.color[2] = 10.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    const v3 eye = v(-3.0, 1.5, 0.2), at = v(1.0, 0.8, 0.0), up = v(0, 1, 0);
    s->camera = (vct_camera){{-3.0f, 1.5f, 0.2f}, {1.0f, 0.8f, 0.0f}, {0, 1, 0}, 60.0f};
    const int W = 48, H = 48;
    vct_image im = render(s, VCT_METHOD_WHITTED, W, H, 0, -1.0f);
    const v3 lp = v3_of(light.position);
    const double margin = 1e-3;
    int mirrored = 0, direct = 0, worst_px = -1;
    double worst = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            v3 d = camera_ray(eye, at, up, 60.0, W, H, x, y), o = eye;
            double scale[3] = {1, 1, 1};
            const double tm = d.x > 0 ? (1.0 - o.x) / d.x : INFINITY;
            const double tf = d.y < 0 ? -o.y / d.y : INFINITY;
            if (isfinite(tm) && tm < tf) { /* the mirror, then on to the floor */
                const v3 m = add(o, mul(d, tm));
                if (m.y < margin || m.y > 4 - margin || fabs(m.z) > 6 - margin)
                    continue;
                o = m;
                d = v(-d.x, d.y, d.z);
                for (int k = 0; k < 3; ++k)
                    scale[k] = R[k];
            }
            double expect[3] = {0, 0, 0};
            if (d.y < 0) {
                const v3 q = add(o, mul(d, -o.y / d.y));
                if (q.x < -6 + margin || q.x > 1 - margin || fabs(q.z) > 6 - margin)
                    continue;
                const v3 to = sub(lp, q);
                const double dist2 = dot(to, to), cos_t = to.y / sqrt(dist2);
                for (int k = 0; k < 3; ++k)
                    expect[k] = scale[k] * 0.6 / PI * 10.0 * cos_t / dist2;
                mirrored += scale[0] != 1.0;
                direct += scale[0] == 1.0;
            }
            for (int k = 0; k < 3; ++k) {
                const double got = im.rgba[4 * (y * W + x) + k];
                const double e = expect[k] > 0 ? fabs(got - expect[k]) / expect[k] : fabs(got);
                if (e > worst)
                    worst = e, worst_px = y * W + x;
            }
        }
    CHECK(worst <= 1e-4, "mirror: error %.3g at pixel %d (1e-4 allowed)", worst, worst_px);
    CHECK(mirrored > 200 && direct > 200, "mirror: %d reflected and %d direct pixels: a weak test",
          mirrored, direct);
    printf("mirror: %d reflected and %d direct floor pixels, worst relative error %.2g\n", mirrored,
           direct, worst);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* One pixel through a glass slab (faces z = 1 and z = 0) at an emissive wall
 * (z = -2), the view `angle` from the slab's normal. */
static void check_slab(double angle_deg, uint32_t depth, float cut, int terms) {
    const float slab_wall[36] = {-L,    -L,     1,  L,     -L,    1,  L,      L,      1,
                                 -L,    L,      1,  -L,    L,     0,  L,      L,      0,
                                 L,     -L,     0,  -L,    -L,    0,  -4 * L, -4 * L, -2,
                                 4 * L, -4 * L, -2, 4 * L, 4 * L, -2, -4 * L, 4 * L,  -2};
    const vct_material mats[3] = {glass(), glass(), emitter(radiant)};
    vct_scene *s = quads_scene(slab_wall, 3, mats);
    const double a = angle_deg * PI / 180.0;
    s->camera = (vct_camera){
        {0, 0, 5}, {(float)(5.0 * sin(a)), 0, (float)(5.0 - 5.0 * cos(a))}, {0, 1, 0}, 30.0f};
    vct_image im = render(s, VCT_METHOD_WHITTED, 1, 1, depth, cut);
    const double F = check_fresnel(cos(a), 1.0 / 1.5), T = (1 - F) * (1 - F);
    double sum = 0.0, f2k = 1.0;
    for (int k = 0; k < terms; ++k, f2k *= F * F)
        sum += T * f2k;
    double worst = 0.0;
    for (int k = 0; k < 3; ++k)
        worst = fmax(worst, fabs(im.rgba[k] - radiant[k] * sum) / (radiant[k] * sum));
    CHECK(worst < 1e-5, "slab at %g°, depth %u, cut %g: %.7g, expected E x %.7g (error %.2g)",
          angle_deg, depth, cut, im.rgba[0] / radiant[0], sum, worst);
    printf("slab at %g°, depth %u, throughput cut %g: E x %.7f (%d terms of (1-F)^2 F^2k, F = "
           "%.5f), error %.1g\n",
           angle_deg, depth, cut, im.rgba[0] / radiant[0], terms, F, worst);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* From inside a slab (faces y = 0 and y = 1) towards its top face at `angle`
 * from the normal, under an emissive ceiling (y = 2), depth 2 (the top
 * face, then whatever the refracted ray meets). */
static void check_total_reflection(double angle_deg, uint32_t depth) {
    const float slab_ceiling[36] = {-L,    1, -L,     -L,    1, L,     L,      1, L,
                                    L,     1, -L,     L,     0, -L,    L,      0, L,
                                    -L,    0, L,      -L,    0, -L,    -4 * L, 2, -4 * L,
                                    4 * L, 2, -4 * L, 4 * L, 2, 4 * L, -4 * L, 2, 4 * L};
    const vct_material mats[3] = {glass(), glass(), emitter(radiant)};
    vct_scene *s = quads_scene(slab_ceiling, 3, mats);
    const double a = angle_deg * PI / 180.0;
    s->camera =
        (vct_camera){{0, 0.5f, 0}, {(float)sin(a), (float)(0.5 + cos(a)), 0}, {0, 0, 1}, 30.0f};
    vct_image im = render(s, VCT_METHOD_WHITTED, 1, 1, depth, 0.0f);
    const double F = check_fresnel(cos(a), 1.5), expect = 1.0 - F;
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double e = radiant[k] * expect;
        worst = fmax(worst, e > 0 ? fabs(im.rgba[k] - e) / e : fabs(im.rgba[k]));
    }
    CHECK(worst < 1e-5, "inside glass at %g°, depth %u: E x %.7g, expected E x %.7g", angle_deg,
          depth, im.rgba[0] / radiant[0], expect);
    printf("inside glass at %g° (critical %.2f°), depth %u: E x %.7f, expected %.7f\n", angle_deg,
           asin(1.0 / 1.5) * 180.0 / PI, depth, im.rgba[0] / radiant[0], expect);
    vct_image_release(&im);
    vct_scene_release(s);
}

static vct_image render_sub(const vct_scene *s, int w, int h, uint32_t n, float contrast,
                            uint8_t *mask, uint64_t *traced) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_whitted_options o = {w, h, 8, 1e-3f, n, 0, contrast};
    vct_whitted_result r = {0, 0, mask, 0};
    vct_image im;
    REQUIRE_OK(vct_render_whitted(ctx, s, a, &o, &im, &r, &err), err);
    *traced = r.traced_pixels;
    vct_accel_release(a);
    return im;
}

/* A point light just in front of a plane, on the view axis: its bright spot
 * lies at the centre of the one 8-pixel square of a 9x9 image, whose four
 * corners are alike by symmetry. Keys alone interpolate the spot away; the
 * contrast test traces the centre, finds it far from the corners' bilinear
 * value, and refines the square, so the spot is traced. */
static void check_centre_peak(void) {
    /* far wider than the view: not a small object the guard would split */
    const float plane[12] = {-4 * L, -4 * L, 0.0f, 4 * L,  -4 * L, 0.0f,
                             4 * L,  4 * L,  0.0f, -4 * L, 4 * L,  0.0f};
    const vct_material m = matte(0.8f);
    vct_scene *s = quads_scene(plane, 1, &m);
    const vct_camera camera = {{0.0f, 0.0f, 100.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
    s->camera = camera;
    vct_light light = {0};
    light.type = VCT_LIGHT_POINT;
    light.position[2] = 3.0f;
    light.color[0] = light.color[1] = light.color[2] = 100.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    uint8_t mask[81];
    uint64_t traced = 0;
    vct_image full = render_sub(s, 9, 9, 0, 0.0f, mask, &traced);
    vct_image keys = render_sub(s, 9, 9, 8, 0.0f, mask, &traced);
    const size_t centre = 4 * (4 * 9 + 4);
    const float by_keys = keys.rgba[centre];
    CHECK(!mask[4 * 9 + 4] && by_keys < 0.5f * full.rgba[centre],
          "keys alone should miss the spot: centre %g against %g", by_keys, full.rgba[centre]);
    vct_image_release(&keys);
    vct_image contrast = render_sub(s, 9, 9, 8, 0.05f, mask, &traced);
    CHECK(mask[4 * 9 + 4] && contrast.rgba[centre] == full.rgba[centre],
          "the contrast test traces the spot: centre %g against %g", contrast.rgba[centre],
          full.rgba[centre]);
    printf("a spot between symmetric corners: keys alone give %g at its centre, the contrast "
           "test traces it (%g)\n",
           by_keys, contrast.rgba[centre]);
    vct_image_release(&contrast);
    vct_image_release(&full);
    vct_scene_release(s);
}

/* Subsampling: every traced pixel equals the full render bit for bit; on a
 * plane where every corner agrees, every other pixel is the bilinear
 * interpolation of its square's corners. */
static void check_subsampling(void) {
    const int W = 64, H = 48;
    vct_error err = {0};
    vct_scene *box = check_cornell_box();
    uint8_t *mask = malloc((size_t)W * H);
    uint64_t traced = 0, all = 0;
    vct_image full = render_sub(box, W, H, 0, 0.0f, mask, &all);
    vct_image sub = render_sub(box, W, H, 8, 0.0f, mask, &traced);
    size_t differ = 0, marked = 0;
    for (size_t i = 0; i < (size_t)W * H; ++i)
        if (mask[i]) {
            ++marked;
            differ += memcmp(&sub.rgba[4 * i], &full.rgba[4 * i], 12) != 0;
        }
    CHECK(differ == 0 && marked == traced && all == (uint64_t)W * H,
          "subsampling: %zu of %zu traced pixels differ from the full render", differ, marked);
    CHECK(traced > 81 && traced < all, "subsampling at 8: %llu of %llu pixels traced",
          (unsigned long long)traced, (unsigned long long)all);
    printf("subsampling at 8 on the Cornell box: %llu of %llu pixels traced, each as the full "
           "render's\n",
           (unsigned long long)traced, (unsigned long long)all);
    /* With a contrast threshold, squares whose corners' light spreads split
     * too: more pixels traced, each still the full render's. */
    uint64_t traced_contrast = 0;
    vct_image_release(&sub);
    sub = render_sub(box, W, H, 8, 0.05f, mask, &traced_contrast);
    differ = 0;
    for (size_t i = 0; i < (size_t)W * H; ++i)
        differ += mask[i] && memcmp(&sub.rgba[4 * i], &full.rgba[4 * i], 12) != 0;
    CHECK(differ == 0 && traced_contrast > traced,
          "contrast 0.05: %llu pixels traced (%llu without), %zu differ",
          (unsigned long long)traced_contrast, (unsigned long long)traced, differ);
    printf("subsampling at 8 with contrast 0.05: %llu pixels traced (%llu without)\n",
           (unsigned long long)traced_contrast, (unsigned long long)traced);
    vct_image_release(&full);
    vct_image_release(&sub);

    /* The ray caster subsampled: its traced pixels are the ray caster's. */
    vct_accel *acc = vct_accel_build(ctx, box, NULL, &err);
    REQUIRE_OK(acc ? VCT_OK : err.status, err);
    const vct_render_options ro = {W, H, 0, 0, 0.0f};
    REQUIRE_OK(vct_render_raycast(ctx, box, acc, &ro, &full, &err), err);
    const vct_whitted_options wo = {W, H, 1, 0.0f, 8, 0, 0.0f};
    vct_whitted_result wr = {0, 0, mask, 0};
    REQUIRE_OK(vct_whitted_render_as(ctx, box, acc, &wo, 1, &sub, &wr, &err), err);
    differ = marked = 0;
    for (size_t i = 0; i < (size_t)W * H; ++i)
        if (mask[i]) {
            ++marked;
            differ += memcmp(&sub.rgba[4 * i], &full.rgba[4 * i], 12) != 0;
        }
    CHECK(differ == 0 && marked > 81 && marked < (size_t)W * H,
          "ray caster subsampled: %zu of %zu traced pixels differ from its full render", differ,
          marked);
    printf("the ray caster at 8: %zu of %d pixels traced, each as its full render's\n", marked,
           W * H);
    vct_image_release(&full);
    vct_image_release(&sub);
    vct_accel_release(acc);
    vct_scene_release(box);

    /* A plane filling the view under a lamp: one material, one light seen
     * everywhere, so every square of the first level agrees. */
    const float plane[12] = {-50, 0, -50, -50, 0, 50, 50, 0, 50, 50, 0, -50};
    const vct_material m = matte(0.5f);
    vct_scene *s = quads_scene(plane, 1, &m);
    vct_light lamp = {0}; /* close over the plane: its light varies across every square */
    lamp.type = VCT_LIGHT_POINT;
    lamp.position[0] = 0.4f, lamp.position[1] = 1.0f, lamp.position[2] = -0.3f;
    lamp.color[0] = lamp.color[1] = lamp.color[2] = 3.0f;
    REQUIRE_OK(vct_scene_add_light(s, &lamp, &err), err);
    s->camera = (vct_camera){{0, 4, 2}, {0, 0, 0}, {0, 1, 0}, 50.0f};
    full = render_sub(s, W, H, 0, 0.0f, mask, &all);
    sub = render_sub(s, W, H, 16, 0.0f, mask, &traced);
    const int N = 16;
    double worst = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int x0 = x / N * N, y0 = y / N * N;
            const int x1 = x0 + N < W ? x0 + N : W - 1, y1 = y0 + N < H ? y0 + N : H - 1;
            const float fx = x1 > x0 ? (float)(x - x0) / (float)(x1 - x0) : 0.0f;
            const float fy = y1 > y0 ? (float)(y - y0) / (float)(y1 - y0) : 0.0f;
            for (int k = 0; k < 3; ++k) {
                const float c00 = full.rgba[4 * (y0 * W + x0) + k],
                            c10 = full.rgba[4 * (y0 * W + x1) + k],
                            c01 = full.rgba[4 * (y1 * W + x0) + k],
                            c11 = full.rgba[4 * (y1 * W + x1) + k];
                const float top = c00 + (c10 - c00) * fx, bottom = c01 + (c11 - c01) * fx;
                const double e = fabs(sub.rgba[4 * (y * W + x) + k] - (top + (bottom - top) * fy));
                worst = fmax(worst, e / fmax(fabs(top), 1e-6));
            }
        }
    const uint64_t lattice = (uint64_t)((W - 1 + N - 1) / N + 1) * ((H - 1 + N - 1) / N + 1);
    /* 1e-5: a few float roundings, which devices that fuse a * b + c (and
     * NVIDIA's does) place differently; a wrong corner or weight is off by
     * the light's change across a square: up to 5 times its value here. */
    CHECK(worst < 1e-5 && traced == lattice,
          "subsampled plane: %.3g from the bilinear interpolation, %llu pixels traced (%llu "
          "corners)",
          worst, (unsigned long long)traced, (unsigned long long)lattice);
    printf("subsampling at 16 on a plane: the corners traced (%llu), every other pixel bilinear "
           "(within %.1g)\n",
           (unsigned long long)traced, worst);
    vct_image_release(&full);
    vct_image_release(&sub);
    /* Sizes that are not powers of two, or exceed the image, are refused. */
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    const uint32_t bad[2] = {12, 64};
    for (int i = 0; i < 2; ++i) {
        vct_whitted_options o = {W, H, 8, 1e-3f, bad[i], 0, 0.0f};
        vct_image im;
        CHECK(vct_render_whitted(ctx, s, a, &o, &im, NULL, &err) == VCT_ERR_INPUT &&
                  strstr(err.message, "power of two"),
              "--subsample %u is not refused (%s)", bad[i], err.message);
    }
    vct_accel_release(a);
    vct_scene_release(s);
    free(mask);
}

/* 200 spheres about 2 pixels wide, 5 apart, in front of a wall, at
 * N = 16: a sphere is found when the pixel at its centre holds the full
 * render's value. The seed's plain scheme loses some between corners; the
 * guard loses none. */
static void check_small_objects(void) {
    enum { NX = 20, NY = 10, W = 160, H = 120 };
    const int per = 80; /* an icosphere of one subdivision */
    float *pos = NULL;
    uint32_t *tri = NULL, *mat = NULL, nv = 0, nt = 0;
    double centre[NX * NY][3];
    for (int i = 0; i < NX * NY; ++i) {
        const float c[3] = {-3.2f + 6.4f * (float)(i % NX) / (NX - 1),
                            -2.4f + 4.8f * (float)(i / NX) / (NY - 1), 0.0f};
        for (int k = 0; k < 3; ++k)
            centre[i][k] = c[k];
        test_mesh m = mesh_icosphere(1, 0.06f, c);
        pos = realloc(pos, 12ull * (nv + m.nv));
        tri = realloc(tri, 12ull * (nt + m.nt));
        mat = realloc(mat, 4ull * (nt + m.nt));
        memcpy(pos + 3 * nv, m.pos, 12ull * m.nv);
        for (uint32_t t = 0; t < m.nt; ++t) {
            for (int k = 0; k < 3; ++k)
                tri[3 * (nt + t) + k] = m.tri[3 * t + k] + nv;
            mat[nt + t] = 1;
        }
        nv += m.nv, nt += m.nt;
        mesh_free(&m);
    }
    CHECK(nt == (uint32_t)(per * NX * NY), "spheres: %u triangles", nt);
    const float wall[12] = {-20, -20, -1, 20, -20, -1, 20, 20, -1, -20, 20, -1};
    pos = realloc(pos, 12ull * (nv + 4));
    tri = realloc(tri, 12ull * (nt + 2));
    mat = realloc(mat, 4ull * (nt + 2));
    memcpy(pos + 3 * nv, wall, sizeof wall);
    const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int k = 0; k < 6; ++k)
        tri[3 * nt + k] = quad[k] + nv;
    mat[nt] = mat[nt + 1] = 0;
    nv += 4, nt += 2;
    vct_material mats[2] = {matte(0.5f), matte(0.8f)};
    mats[1].albedo[1] = mats[1].albedo[2] = 0.1f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, mat, mats, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(pos), free(tri), free(mat);
    vct_light lamp = {0};
    lamp.type = VCT_LIGHT_POINT;
    lamp.position[2] = 8.0f;
    lamp.color[0] = lamp.color[1] = lamp.color[2] = 50.0f;
    REQUIRE_OK(vct_scene_add_light(s, &lamp, &err), err);
    s->camera = (vct_camera){{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 40.0f};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    /* full; N = 16 plain; N = 16 guarded; N = 2 guarded, where the spheres'
     * boxes span 2 to 2.6 pixels: not smaller than the first squares, but
     * smaller than the twice their size below which sub_fill splits */
    vct_image im[4];
    uint64_t traced[4], small[4] = {0};
    for (int i = 0; i < 4; ++i) {
        vct_whitted_options o = {W, H, 8, 1e-3f, i == 3 ? 2u : i ? 16u : 0u, i == 1, 0.0f};
        vct_whitted_result r = {0, 0, NULL, 0};
        REQUIRE_OK(vct_render_whitted(ctx, s, a, &o, &im[i], &r, &err), err);
        traced[i] = r.traced_pixels;
        small[i] = r.small_objects;
    }
    /* The pixel at each sphere's centre, by the pinhole camera in double. */
    const v3 eye = v(0, 0, 10), f = v(0, 0, -1), rt = norm(cross(f, v(0, 1, 0))), up = cross(rt, f);
    const double th = tan(20.0 * PI / 180.0), aspect = (double)W / H;
    int lost[3] = {0, 0, 0}, seen = 0;
    for (int i = 0; i < NX * NY; ++i) {
        const v3 d = sub(v(centre[i][0], centre[i][1], centre[i][2]), eye);
        const double z = dot(d, f);
        const int x = (int)floor((dot(d, rt) / (z * th * aspect) + 1.0) * 0.5 * W);
        const int y = (int)floor((1.0 - dot(d, up) / (z * th)) * 0.5 * H);
        if (x < 0 || y < 0 || x >= W || y >= H)
            continue;
        const float *full = &im[0].rgba[4 * (y * W + x)];
        seen += full[1] < full[0] * 0.5f; /* red: the sphere, not the grey wall */
        for (int k = 0; k < 3; ++k)
            lost[k] += memcmp(full, &im[1 + k].rgba[4 * (y * W + x)], 12) != 0;
    }
    CHECK(seen == NX * NY, "small objects: %d of %d sphere centres show the sphere", seen, NX * NY);
    CHECK(lost[0] > 0, "small objects: the plain scheme lost none: a weak test");
    CHECK(lost[1] == 0 && small[2] == (uint64_t)NX * NY,
          "small objects: the guard lost %d of %d spheres (%llu small objects found)", lost[1],
          NX * NY, (unsigned long long)small[2]);
    CHECK(lost[2] == 0 && small[3] == (uint64_t)NX * NY,
          "small objects at N = 2: the guard lost %d of %d spheres (%llu small objects found)",
          lost[2], NX * NY, (unsigned long long)small[3]);
    printf("small objects at N = 16: the plain scheme loses %d of %d spheres (%llu of %d pixels "
           "traced), the guard none (%llu traced)\n",
           lost[0], NX * NY, (unsigned long long)traced[1], W * H, (unsigned long long)traced[2]);
    for (int i = 0; i < 4; ++i)
        vct_image_release(&im[i]);
    vct_accel_release(a);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    vct_scene *box = check_cornell_box_point_light();
    check_same_as_raycast(box, "cornell box");
    vct_scene_release(box);
    vct_error err = {0};
    vct_scene *lit = check_cornell_box();
    check_same_as_raycast(lit, "emissive cornell box");
    vct_scene_release(lit);

    check_mirror();
    check_subsampling();
    check_centre_peak();
    check_small_objects();

    /* Depth counts surface interactions: the wall is the third of the
     * straight path, the fifth and seventh after one and two round trips
     * inside the slab. */
    check_slab(0.0, 8, 0.0f, 3);
    check_slab(0.0, 5, 0.0f, 2);
    check_slab(0.0, 3, 0.0f, 1);
    check_slab(0.0, 2, 0.0f, 0);
    /* The default cut-off (1e-3) ends the branch of the second round trip. */
    check_slab(0.0, 8, -1.0f, 2);
    check_slab(45.0, 8, 0.0f, 3);

    check_total_reflection(30.0, 2);
    check_total_reflection(60.0, 2);
    check_total_reflection(60.0, 16);

    /* Depths outside 1..16 are refused. */
    vct_scene *one = check_cornell_box();
    vct_accel *a = vct_accel_build(ctx, one, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_whitted_options o = {8, 8, 17, 1e-3f, 0, 0, 0.0f};
    vct_image im;
    CHECK(vct_render_whitted(ctx, one, a, &o, &im, NULL, &err) == VCT_ERR_INPUT &&
              strstr(err.message, "outside 1..16"),
          "a depth of 17 is not refused (%s)", err.message);
    vct_accel_release(a);
    vct_scene_release(one);

    vct_context_release(ctx);
    return check_exit("test_whitted");
}
