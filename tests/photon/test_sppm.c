/* Photon mapping (--method pm) against answers known in advance and the
 * path tracer:
 * - furnace: a closed box of albedo a whose walls all emit Le has radiance
 *   Le / (1 - a) everywhere;
 * - a plane under a point light, lit by photons alone (the seed's mode):
 *   the estimate converges to I cos(theta) / d^2 * albedo / pi, its error
 *   falling with passes about as SPPM predicts (n^(-1/3) for alpha 2/3);
 * - a mirror above a point light: the caustic map alone gives the light's
 *   image, I R cos / d'^2 * albedo / pi from the mirrored light;
 * - a glass sphere over a plane under a small area light: the caustic
 *   region against the path tracer;
 * - a plane under a uniform sky: a L, by escaping BSDF rays and by the
 *   environment's photons;
 * - corners of a closed box: with the normal filter no brighter than the
 *   path tracer's, without it brighter (the difference printed);
 * - a wall of zero thickness between a lit and a dark room: the dark room
 *   gets at most what the gather radius reaches across the wall's foot;
 * - the same seed and passes: the same image; resumed calls continue;
 * - bad input refused with a message. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"

static vct_scene *quads_scene(const float *quads, const uint32_t *quad_mat, uint32_t count,
                              const vct_material *mats, uint32_t mat_count) {
    test_mesh m = mesh_quads(quads, count);
    uint32_t *tm = malloc(4ull * m.nt);
    for (uint32_t t = 0; t < m.nt; ++t)
        tm[t] = quad_mat[t / 2];
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(m.pos, m.nv, m.tri, m.nt, tm, mats, mat_count, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(tm);
    mesh_free(&m);
    return s;
}

static vct_material grey(float a) {
    vct_material m;
    memset(&m, 0, sizeof m);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = a;
    m.roughness = 1.0f;
    return m;
}

static vct_image render(vct_context *ctx, const vct_scene *s, const vct_pm_options *o,
                        vct_pm_result *res) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_image im;
    REQUIRE_OK(vct_render_pm(ctx, s, a, o, &im, res, &err), err);
    vct_accel_release(a);
    return im;
}

static double channel_mean(const vct_image *im, int c) {
    double s = 0.0;
    const size_t n = (size_t)im->width * im->height;
    for (size_t i = 0; i < n; ++i)
        s += im->rgba[4 * i + c];
    return s / n;
}

/* The cube [-1, 1]^3, each face a quad facing inwards. */
static const float CUBE[6][12] = {
    {-1, -1, -1, 1, -1, -1, 1, -1, 1, -1, -1, 1}, {-1, 1, -1, -1, 1, 1, 1, 1, 1, 1, 1, -1},
    {-1, -1, -1, -1, 1, -1, 1, 1, -1, 1, -1, -1}, {-1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1},
    {-1, -1, -1, -1, -1, 1, -1, 1, 1, -1, 1, -1}, {1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1}};

static void furnace(vct_context *ctx, int final_gather) {
    const float a = 0.5f, le = 1.0f;
    vct_material m = grey(a);
    m.emission[0] = m.emission[1] = m.emission[2] = le;
    const uint32_t mats[6] = {0};
    vct_scene *s = quads_scene(&CUBE[0][0], mats, 6, &m, 1);
    s->camera = (vct_camera){{0.1f, 0.2f, 0.3f}, {0.7f, -0.4f, 0.9f}, {0, 1, 0}, 70.0f};
    vct_pm_options o = vct_pm_options_default(32, 32);
    o.passes = 16;
    o.photons_per_pass = 1u << 15;
    o.normal_cos = -2.0f;          /* corners: photons of the next wall count (flat furnace) */
    o.final_gather = final_gather; /* rays from the visible points read the map where they land */
    vct_pm_result r;
    vct_image im = render(ctx, s, &o, &r);
    const double expect = le / (1.0 - a), mean = channel_mean(&im, 0);
    /* Depth 16 keeps all but a^16 of the light; the rest is density noise
     * and the disk that a corner cuts, both small at 16 passes. */
    CHECK(fabs(mean - expect) < 0.03 * expect,
          "furnace (final gathering %d): mean radiance %.4f, expected %.4f", final_gather, mean,
          expect);
    printf("furnace (final gathering %d): mean radiance %.4f, expected %.4f\n", final_gather, mean,
           expect);
    CHECK(r.global_map && !r.caustic_map, "furnace: maps global %d caustic %d (expected 1, 0)",
          r.global_map, r.caustic_map);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* A 4 x 4 plane at y = 0 of albedo a under a point light at height h. */
static vct_scene *plane_scene(float a, float h, float intensity) {
    const float q[12] = {-2, 0, -2, -2, 0, 2, 2, 0, 2, 2, 0, -2};
    const uint32_t mats[1] = {0};
    vct_material m = grey(a);
    vct_scene *s = quads_scene(q, mats, 1, &m, 1);
    vct_light l = {0};
    l.type = VCT_LIGHT_POINT;
    l.position[1] = h;
    l.color[0] = l.color[1] = l.color[2] = intensity;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    /* Looking straight down on the middle 2 x 2: pixel (x, y) sees one point. */
    s->camera = (vct_camera){{0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 36.8699f};
    return s;
}

/* RMS error of the image's red channel against the plane's exact radiance. */
static double plane_error(const vct_image *im, float a, float h, float intensity, double *mean) {
    const double half = tan(36.8699 * CHECK_PI / 360.0) * 3.0; /* 1: the view spans 2 x 2 */
    double e2 = 0.0, sum = 0.0;
    for (int y = 0; y < im->height; ++y)
        for (int x = 0; x < im->width; ++x) {
            const double px = (2.0 * (x + 0.5) / im->width - 1.0) * half;
            const double pz = (2.0 * (y + 0.5) / im->height - 1.0) * half;
            const double d2 = px * px + pz * pz + (double)h * h;
            const double exact = intensity * (h / sqrt(d2)) / d2 * a / CHECK_PI;
            const double v = im->rgba[4 * ((size_t)y * im->width + x)];
            e2 += (v - exact) * (v - exact);
            sum += exact;
        }
    const double n = (double)im->width * im->height;
    *mean = sum / n;
    return sqrt(e2 / n);
}

static void plane_convergence(vct_context *ctx) {
    const float a = 0.8f, h = 1.0f, intensity = 1.0f;
    vct_scene *s = plane_scene(a, h, intensity);
    vct_pm_options o = vct_pm_options_default(24, 24);
    o.direct_photons = 1;
    o.components = VCT_PM_GLOBAL;
    o.photons_per_pass = 1u << 14;
    o.radius = 0.1f;
    double err[3], mean = 0.0;
    const uint32_t passes[3] = {4, 32, 256};
    for (int i = 0; i < 3; ++i) {
        o.passes = passes[i];
        vct_image im = render(ctx, s, &o, NULL);
        err[i] = plane_error(&im, a, h, intensity, &mean);
        vct_image_release(&im);
    }
    printf("plane under a point light, photons only: relative RMS error %.4f, %.4f, %.4f at "
           "4, 32, 256 passes\n",
           err[0] / mean, err[1] / mean, err[2] / mean);
    /* n^(-1/3) per 8x passes is a factor 2; ask for 1.5 at least. */
    CHECK(err[1] < err[0] / 1.5 && err[2] < err[1] / 1.5,
          "the error does not fall with passes: %.4g, %.4g, %.4g", err[0], err[1], err[2]);
    CHECK(err[2] < 0.05 * mean, "256 passes: error %.3g of the mean %.3g", err[2] / mean, mean);
    vct_scene_release(s);
}

/* A mirror quad at y = 2 above a point light at y = 1 over a floor at y = 0:
 * the caustic on the floor is the light mirrored to y = 3, times R. */
static void mirror_caustic(vct_context *ctx) {
    const float quads[2][12] = {{-8, 0, -8, -8, 0, 8, 8, 0, 8, 8, 0, -8},
                                {-8, 2, -8, 8, 2, -8, 8, 2, 8, -8, 2, 8}};
    const uint32_t mats[2] = {0, 1};
    vct_material m[2] = {grey(0.5f), grey(0.9f)};
    m[1].metallic = 1.0f;
    m[1].roughness = 0.0f;
    vct_scene *s = quads_scene(&quads[0][0], mats, 2, m, 2);
    vct_light l = {0};
    l.type = VCT_LIGHT_POINT;
    l.position[1] = 1.0f;
    l.color[0] = l.color[1] = l.color[2] = 1.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    s->camera = (vct_camera){{0, 1.5f, 0}, {0, 0, 0}, {0, 0, -1}, 67.3801f}; /* 2 x 2 at y 0 */
    vct_pm_options o = vct_pm_options_default(24, 24);
    o.passes = 64;
    o.photons_per_pass = 1u << 16;
    o.components = VCT_PM_CAUSTIC;
    o.caustic_radius = 0.1f;
    o.max_depth = 2; /* light, mirror, floor: not the floor's light mirrored back */
    vct_pm_result r;
    vct_image im = render(ctx, s, &o, &r);
    /* The same as a plane under a light of intensity R at height 3 seen from 1.5. */
    const double half = 1.0;
    double e2 = 0.0, sum = 0.0, peak = 0.0, got_peak = 0.0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double px = (2.0 * (x + 0.5) / im.width - 1.0) * half;
            const double pz = (2.0 * (y + 0.5) / im.height - 1.0) * half;
            const double d2 = px * px + pz * pz + 9.0;
            const double exact = 0.9 * (3.0 / sqrt(d2)) / d2 * 0.5 / CHECK_PI;
            const double v = im.rgba[4 * ((size_t)y * im.width + x)];
            e2 += (v - exact) * (v - exact);
            sum += exact;
            if (exact > peak)
                peak = exact, got_peak = v;
        }
    const double n = (double)im.width * im.height, mean = sum / n;
    printf("mirror caustic: relative RMS error %.4f, mean %.5g of %.5g, peak %.5g of %.5g\n",
           sqrt(e2 / n) / mean, channel_mean(&im, 0), mean, got_peak, peak);
    CHECK(r.caustic_map, "a mirror makes no caustic map");
    CHECK(fabs(channel_mean(&im, 0) - mean) < 0.03 * mean, "caustic power %.5g, expected %.5g",
          channel_mean(&im, 0), mean);
    CHECK(sqrt(e2 / n) < 0.1 * mean, "caustic error %.3g of its mean", sqrt(e2 / n) / mean);
    vct_image_release(&im);
    vct_scene_release(s);
}

/* A glass ball over a floor under a small emissive quad: the bright spot
 * under the ball (the pixels the path tracer finds 1.5 times brighter than
 * the floor's median) against the path tracer at high spp. */
static void glass_caustic(vct_context *ctx) {
    const float cx = 0.0f, cy = 1.0f, cz = 0.0f;
    const float centre[3] = {cx, cy, cz};
    test_mesh ball = mesh_icosphere(3, 0.5f, centre);
    const float quads[2][12] = {
        {-3, 0, -3, -3, 0, 3, 3, 0, 3, 3, 0, -3},
        {-0.15f, 3, -0.15f, 0.15f, 3, -0.15f, 0.15f, 3, 0.15f, -0.15f, 3, 0.15f}};
    test_mesh q = mesh_quads(&quads[0][0], 2);
    const uint32_t nv = ball.nv + q.nv, nt = ball.nt + q.nt;
    float *pos = malloc(12ull * nv);
    uint32_t *tri = malloc(12ull * nt), *tm = malloc(4ull * nt);
    memcpy(pos, q.pos, 12ull * q.nv);
    memcpy(pos + 3 * q.nv, ball.pos, 12ull * ball.nv);
    memcpy(tri, q.tri, 12ull * q.nt);
    for (uint32_t i = 0; i < 3 * ball.nt; ++i)
        tri[3 * q.nt + i] = ball.tri[i] + q.nv;
    for (uint32_t t = 0; t < nt; ++t)
        tm[t] = t < 2 ? 0 : t < 4 ? 1 : 2;
    vct_material m[3] = {grey(0.7f), grey(0.0f), grey(1.0f)};
    m[1].emission[0] = m[1].emission[1] = m[1].emission[2] = 60.0f;
    m[2].transmission = 1.0f;
    m[2].roughness = 0.0f;
    m[2].ior = 1.5f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, tm, m, 3, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    s->camera = (vct_camera){{0, 2.2f, 2.4f}, {0, 0.1f, 0}, {0, 1, 0}, 50.0f};
    const int w = 40, h = 40;
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_pathtrace_options po = {w, h, 2048, 0.0, 8, 5, 64, 0, 0, NULL, NULL, 1};
    vct_image ref;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, a, &po, &ref, NULL, &err), err);
    vct_pm_options o = vct_pm_options_default(w, h);
    o.passes = 48;
    o.photons_per_pass = 1u << 16;
    o.max_depth = 8;
    vct_pm_result r;
    vct_image im;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &im, &r, &err), err);
    /* The floor's median radiance, from the reference's floor pixels. */
    float *floor_px = malloc(sizeof(float) * w * h);
    int nf = 0;
    for (int i = 0; i < w * h; ++i)
        if (ref.rgba[4 * i] > 0.0f && ref.rgba[4 * i] < 50.0f)
            floor_px[nf++] = ref.rgba[4 * i];
    float median = 0.0f;
    for (int i = 0; i < nf; ++i) { /* nth element by counting: nf is small */
        int below = 0;
        for (int j = 0; j < nf; ++j)
            below += floor_px[j] < floor_px[i];
        if (below == nf / 2)
            median = floor_px[i];
    }
    double pm = 0.0, pt = 0.0;
    int n = 0;
    for (int i = 0; i < w * h; ++i)
        if (ref.rgba[4 * i] > 1.5f * median && ref.rgba[4 * i] < 50.0f) {
            pm += im.rgba[4 * i];
            pt += ref.rgba[4 * i];
            ++n;
        }
    printf("glass caustic: %d pixels, photon mapping %.4g, path tracing %.4g (ratio %.3f)\n", n,
           pm / n, pt / n, pm / pt);
    CHECK(r.caustic_map, "a glass ball makes no caustic map");
    CHECK(n >= 10, "only %d caustic pixels: the scene does not test caustics", n);
    CHECK(fabs(pm / pt - 1.0) < 0.1, "caustic region: photon mapping %.4g, path tracer %.4g",
          pm / n, pt / n);
    free(floor_px);
    vct_image_release(&im);
    vct_image_release(&ref);
    vct_accel_release(a);
    vct_scene_release(s);
    free(pos);
    free(tri);
    free(tm);
    mesh_free(&ball);
    mesh_free(&q);
}

/* A closed grey cube around a point light, seen into a corner: the normal
 * filter keeps the next wall's photons out of the corner's estimate. */
static void corners(vct_context *ctx) {
    const uint32_t mats[6] = {0};
    vct_material m = grey(0.6f);
    vct_scene *s = quads_scene(&CUBE[0][0], mats, 6, &m, 1);
    vct_light l = {0};
    l.type = VCT_LIGHT_POINT;
    l.position[0] = -0.3f;
    l.color[0] = l.color[1] = l.color[2] = 1.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    s->camera = (vct_camera){{-0.2f, -0.2f, -0.2f}, {1, 1, 1}, {0, 1, 0}, 60.0f};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_pathtrace_options po = {32, 32, 1024, 0.0, 16, 3, 64, 0, 0, NULL, NULL, 1};
    vct_image ref, on, off;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, a, &po, &ref, NULL, &err), err);
    vct_pm_options o = vct_pm_options_default(32, 32);
    o.passes = 16;
    o.photons_per_pass = 1u << 15;
    o.radius = 0.15f;
    o.fixed_radius = 1;  /* a wide disk that stays wide: the corner effect at its largest */
    o.normal_cos = 0.7f; /* the seed's filter */
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &on, NULL, &err), err);
    o.normal_cos = -2.0f;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &off, NULL, &err), err);
    const double pt = channel_mean(&ref, 0), m_on = channel_mean(&on, 0),
                 m_off = channel_mean(&off, 0);
    printf("corners: mean radiance, path tracing %.5g, normal filter on %.5g (%+.2f %%), off "
           "%.5g (%+.2f %%)\n",
           pt, m_on, 100.0 * (m_on / pt - 1.0), m_off, 100.0 * (m_off / pt - 1.0));
    CHECK(m_on < 1.01 * pt, "with the normal filter the corners gain light: %.5g against %.5g",
          m_on, pt);
    CHECK(m_off > m_on, "without the filter the next wall's photons should add light");
    vct_image_release(&ref);
    vct_image_release(&on);
    vct_image_release(&off);
    vct_accel_release(a);
    vct_scene_release(s);
}

/* The same seed and passes give the same image; 2 resumed calls of 3
 * passes give the image of one call of 6; another seed another image. */
static void determinism(vct_context *ctx) {
    vct_scene *s = check_cornell_box();
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_pm_options o = vct_pm_options_default(24, 24);
    o.passes = 6;
    o.photons_per_pass = 1u << 13;
    vct_image x, y, z, w;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &x, NULL, &err), err);
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &y, NULL, &err), err);
    o.passes = 3;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &z, NULL, &err), err);
    o.resume = 1;
    vct_pm_result r;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &z, &r, &err), err);
    o.resume = 0;
    o.passes = 6;
    o.seed = 9;
    REQUIRE_OK(vct_render_pm(ctx, s, a, &o, &w, NULL, &err), err);
    const size_t bytes = 16ull * 24 * 24;
    CHECK(memcmp(x.rgba, y.rgba, bytes) == 0, "the same seed and passes gave two images");
    CHECK(r.passes == 6 && memcmp(x.rgba, z.rgba, bytes) == 0,
          "3 + 3 resumed passes (%u) differ from 6", r.passes);
    CHECK(memcmp(x.rgba, w.rgba, bytes) != 0, "another seed gave the same image");
    vct_image_release(&x);
    vct_image_release(&y);
    vct_image_release(&z);
    vct_image_release(&w);
    vct_accel_release(a);
    vct_scene_release(s);
}

static void refused(vct_context *ctx, const vct_scene *s, const vct_pm_options *o,
                    const char *expect, const char *what) {
    vct_error err = {0};
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_image im = {0};
    const int rc = vct_render_pm(ctx, s, a, o, &im, NULL, &err);
    CHECK(rc != VCT_OK && strstr(err.message, expect) && !im.rgba,
          "%s: rc %d, message \"%s\" (expected one with \"%s\")", what, rc, err.message, expect);
    vct_accel_release(a);
}

static void bad_input(vct_context *ctx) {
    const uint32_t mats[6] = {0};
    vct_material m = grey(0.5f);
    vct_scene *dark = quads_scene(&CUBE[0][0], mats, 6, &m, 1);
    vct_pm_options o = vct_pm_options_default(8, 8);
    o.passes = 1;
    refused(ctx, dark, &o, "no lights, nothing emits", "a scene without light");
    vct_scene *s = check_cornell_box();
    o.radius = 1e6f;
    refused(ctx, s, &o, "larger than the scene", "a radius larger than the scene");
    o.radius = 0.0f;
    o.photons_per_pass = 1u << 30;
    refused(ctx, s, &o, "--photons", "more photons than the device holds");
    o.photons_per_pass = 1024;
    o.passes = 0;
    refused(ctx, s, &o, "--spp", "no passes and no time");
    vct_scene_release(dark);
    vct_scene_release(s);
}

/* A plane under a uniform sky of radiance L: radiance a L, from the BSDF
 * rays that escape (default) and from the environment's photons alone (the
 * seed's mode, where every photon is a direct one). */
static void sky(vct_context *ctx) {
    const float a = 0.6f, L = 0.5f;
    vct_scene *s = plane_scene(a, 1.0f, 0.0f);
    s->light_count = 0; /* the sky alone */
    s->ambient[0] = s->ambient[1] = s->ambient[2] = L;
    const double expect = a * L;
    vct_pm_options o = vct_pm_options_default(16, 16);
    o.passes = 32;
    o.photons_per_pass = 1u << 15;
    vct_image im = render(ctx, s, &o, NULL);
    const double by_rays = channel_mean(&im, 0);
    vct_image_release(&im);
    o.direct_photons = 1;
    o.radius = 0.1f;
    im = render(ctx, s, &o, NULL);
    const double by_photons = channel_mean(&im, 0);
    vct_image_release(&im);
    printf("plane under a sky: %.5f by BSDF rays, %.5f by photons, exact %.5f\n", by_rays,
           by_photons, expect);
    CHECK(fabs(by_rays - expect) < 0.02 * expect, "sky by rays: %.5f, expected %.5f", by_rays,
          expect);
    CHECK(fabs(by_photons - expect) < 0.03 * expect, "sky by photons: %.5f, expected %.5f",
          by_photons, expect);
    vct_scene_release(s);
}

/* Two closed rooms sharing one wall of zero thickness, a light in the first,
 * the camera in the second, looking at the wall and the floor under it: the
 * second room is black for the path tracer. Photon mapping may only let in
 * what a disk of the gather radius reaches across the wall's foot, and less
 * as the radius shrinks. */
static double dark_room_mean(vct_context *ctx, const vct_scene *s, uint32_t passes,
                             float normal_cos) {
    vct_pm_options o = vct_pm_options_default(24, 24);
    o.passes = passes;
    o.photons_per_pass = 1u << 15;
    o.normal_cos = normal_cos;
    vct_image im = render(ctx, s, &o, NULL);
    const double m = channel_mean(&im, 0);
    vct_image_release(&im);
    return m;
}

static void thin_wall(vct_context *ctx) {
    /* x in [-2, 0] and [0, 2], y in [0, 2], z in [-1, 1]; the wall x = 0. */
    const float q[11][12] = {
        {-2, 0, -1, -2, 0, 1, 0, 0, 1, 0, 0, -1},   {0, 0, -1, 0, 0, 1, 2, 0, 1, 2, 0, -1},
        {-2, 2, -1, 0, 2, -1, 0, 2, 1, -2, 2, 1},   {0, 2, -1, 2, 2, -1, 2, 2, 1, 0, 2, 1},
        {-2, 0, -1, 0, 0, -1, 0, 2, -1, -2, 2, -1}, {0, 0, -1, 2, 0, -1, 2, 2, -1, 0, 2, -1},
        {-2, 0, 1, -2, 2, 1, 0, 2, 1, 0, 0, 1},     {0, 0, 1, 0, 2, 1, 2, 2, 1, 2, 0, 1},
        {-2, 0, -1, -2, 2, -1, -2, 2, 1, -2, 0, 1}, {2, 0, -1, 2, 0, 1, 2, 2, 1, 2, 2, -1},
        {0, 0, -1, 0, 2, -1, 0, 2, 1, 0, 0, 1}};
    const uint32_t mats[11] = {0};
    vct_material m = grey(0.7f);
    vct_scene *s = quads_scene(&q[0][0], mats, 11, &m, 1);
    vct_light l = {0};
    l.type = VCT_LIGHT_POINT;
    l.position[0] = -1.0f, l.position[1] = 1.0f;
    l.color[0] = l.color[1] = l.color[2] = 2.0f;
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    s->camera = (vct_camera){{1.6f, 1.2f, 0.0f}, {0.0f, 0.2f, 0.0f}, {0, 1, 0}, 60.0f};
    const double early = dark_room_mean(ctx, s, 4, 0.0f), late = dark_room_mean(ctx, s, 64, 0.0f);
    const double strict = dark_room_mean(ctx, s, 64, 0.7f);
    const double unfiltered = dark_room_mean(ctx, s, 64, -2.0f);
    s->camera = (vct_camera){{-1.6f, 1.2f, 0.0f}, {0.0f, 0.2f, 0.0f}, {0, 1, 0}, 60.0f};
    const double lit = dark_room_mean(ctx, s, 4, 0.0f);
    printf("thin wall: the dark room's mean radiance is %.3g %% of the lit room's after 4 passes, "
           "%.3g %% after 64 (normal filter 0.7: %.3g %%, none: %.3g %%)\n",
           100.0 * early / lit, 100.0 * late / lit, 100.0 * strict / lit, 100.0 * unfiltered / lit);
    CHECK(late < 0.005 * lit, "light through the wall: %.4g against %.4g in the lit room", late,
          lit);
    CHECK(late < early || early == 0.0, "the leak does not shrink with the radius: %.4g, %.4g",
          early, late);
    vct_scene_release(s);
}

int main(void) {
    vct_context *ctx = check_context();
    furnace(ctx, 0);
    furnace(ctx, 1);
    sky(ctx);
    plane_convergence(ctx);
    mirror_caustic(ctx);
    glass_caustic(ctx);
    corners(ctx);
    thin_wall(ctx);
    determinism(ctx);
    bad_input(ctx);
    vct_context_release(ctx);
    return check_exit("test_sppm");
}
