/* The rest of the bounces (vct_voxels_bounce_rest, kernels/voxel/bounce_rest.cl)
 * in a closed box lit by a point light inside:
 *  - against a plain-C reference on the light read back after injection and
 *    after each bounce: per colour channel, the ratio of the last two
 *    bounces' light summed over every voxel's two sides (at most the
 *    channel's brightest albedo), and each side's light plus its last
 *    bounce's times r / (1 - r);
 *  - physically: in a closed room of one albedo, each bounce carries on all
 *    the light the one before it sent times the albedo, channel by channel,
 *    so the measured ratios must be near the albedo's (the rays lose some
 *    and leave none: within 0.15), in a grey box (0.5) and in a coloured one
 *    (0.8, 0.5, 0.2), whose red light lasts longest;
 *  - with exact_bounces, or after one bounce only, nothing is added. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define RES 32
#define ALBEDO 0.5f
static const float coloured[3] = {0.8f, 0.5f, 0.2f};

static vct_context *ctx;

typedef struct voxel_light {
    float *radiance; /* 4 per voxel */
    float *sides;    /* 8 per voxel */
} voxel_light;

static voxel_light read_light(vct_voxels *v, uint32_t n) {
    voxel_light l = {malloc(16ull * n), malloc(32ull * n)};
    vct_error err = {0};
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, l.radiance, &err), err);
    REQUIRE_OK(vct_voxels_read_sides(ctx, v, l.sides, &err), err);
    return l;
}

static void light_free(voxel_light *l) {
    free(l->radiance);
    free(l->sides);
}

/* Voxel i's light on the side normal n points to and on the other. */
static void sides_of(const voxel_light *l, uint32_t i, const float n[3], double toward[3],
                     double away[3]) {
    const float *s = l->sides + 8 * i;
    const double facing = (double)s[4] * n[0] + (double)s[5] * n[1] + (double)s[6] * n[2];
    for (int k = 0; k < 3; ++k) {
        const double bright = l->radiance[4 * i + k], dark = bright - s[k];
        toward[k] = facing < 0.0 ? dark : bright;
        away[k] = facing < 0.0 ? bright : dark;
    }
}

/* What `after` added to `before` on voxel i's two sides (never below 0). */
static void added(const voxel_light *after, const voxel_light *before, const float n[3], uint32_t i,
                  double toward[3], double away[3]) {
    double t1[3], a1[3], t0[3], a0[3];
    sides_of(after, i, n, t1, a1);
    sides_of(before, i, n, t0, a0);
    for (int k = 0; k < 3; ++k) {
        toward[k] = fmax(t1[k] - t0[k], 0.0);
        away[k] = fmax(a1[k] - a0[k], 0.0);
    }
}

/* The light `after` added to `before` over every voxel's two sides, per
 * channel. */
static void bounce_light(const voxel_light *after, const voxel_light *before,
                         const voxel_light *direct, uint32_t n, double total[3]) {
    total[0] = total[1] = total[2] = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        double t[3], a[3];
        added(after, before, direct->sides + 8 * i + 4, i, t, a);
        for (int k = 0; k < 3; ++k)
            total[k] += t[k] + a[k];
    }
}

/* The closed box [2, 14]^3 facing in, a point light inside, and a plate
 * just under the light's height beside it: lit at a grazing angle from
 * above and, after the bounces, more from the floor below, so that its
 * voxels' brighter side turns from the direct light's. */
static vct_scene *closed_box(const float albedo[3]) {
    const float lo = 2.0f, hi = 14.0f;
    const float v[8][3] = {{lo, lo, lo}, {hi, lo, lo}, {hi, hi, lo}, {lo, hi, lo},
                           {lo, lo, hi}, {hi, lo, hi}, {hi, hi, hi}, {lo, hi, hi}};
    const uint32_t faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7},
                                  {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
    const float plate[4][3] = {{9, 10.6f, 4}, {13, 10.6f, 4}, {13, 10.6f, 10}, {9, 10.6f, 10}};
    float pos[28 * 3];
    uint32_t tri[42], mat[14] = {0};
    for (int f = 0; f < 7; ++f) {
        for (int c = 0; c < 4; ++c)
            memcpy(pos + 3 * (4 * f + c), f < 6 ? v[faces[f][c]] : plate[c], sizeof v[0]);
        const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; ++i)
            tri[6 * f + i] = 4u * (uint32_t)f + q[i];
    }
    vct_material m = vct_material_default();
    for (int c = 0; c < 3; ++c)
        m.albedo[c] = albedo[c];
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 28, tri, 14, mat, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const vct_light l = {VCT_LIGHT_POINT, {6.0f, 11.0f, 7.0f}, {0}, {60, 60, 60}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    return s;
}

static vct_voxels *lit_voxels(vct_scene *s, vct_accel *g, int exact) {
    vct_error err = {0};
    vct_voxel_options o = {0};
    o.resolution = RES;
    o.has_bounds = 1;
    o.bounds_size = 16.0;
    o.exact_bounces = exact;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, g, v, &err), err);
    const vct_brick_options bo = {VCT_BRICKS_AUTO, 1, 0};
    REQUIRE_OK(vct_bricks_build(ctx, v, &bo, &err), err);
    return v;
}

static void bounce(vct_scene *s, vct_accel *g, vct_voxels *v) {
    vct_error err = {0};
    const vct_cone_settings cs = vct_cone_settings_default();
    REQUIRE_OK(vct_voxels_inject_bounce(ctx, s, g, v, &cs, &err), err);
}

static void against_reference(const float albedo[3], const char *what) {
    vct_scene *s = closed_box(albedo);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxels *v = lit_voxels(s, g, 0);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    const uint32_t n = info.voxels;
    voxel_light direct = read_light(v, n);
    bounce(s, g, v);
    voxel_light one = read_light(v, n);
    REQUIRE_OK(vct_voxels_bounce_rest(ctx, v, &err), err);
    voxel_light still = read_light(v, n);
    CHECK(vct_voxels_bounce_ratio(v) == 0.0 && memcmp(still.radiance, one.radiance, 16ull * n) == 0,
          "%s: after one bounce the rest adds nothing (ratio %g)", what,
          vct_voxels_bounce_ratio(v));
    bounce(s, g, v);
    voxel_light two = read_light(v, n);
    REQUIRE_OK(vct_voxels_bounce_rest(ctx, v, &err), err);
    voxel_light rest = read_light(v, n);

    double e1[3], e2[3], measured[3], r[3], f[3], got_r[3];
    bounce_light(&one, &direct, &direct, n, e1);
    bounce_light(&two, &one, &direct, n, e2);
    vct_voxels_bounce_ratios(v, got_r);
    for (int k = 0; k < 3; ++k) {
        /* at most the channel's brightest albedo and VCT_BOUNCE_RATIO_MAX */
        measured[k] = e2[k] / e1[k];
        const double most = fmin(albedo[k], VCT_BOUNCE_RATIO_MAX);
        r[k] = measured[k] > most ? most : measured[k];
        f[k] = r[k] / (1.0 - r[k]);
        CHECK(fabs(got_r[k] - r[k]) < 1e-4 * r[k],
              "%s: channel %d's bounce ratio %.6f, the "
              "reference's %.6f",
              what, k, got_r[k], r[k]);
    }
    CHECK(vct_voxels_bounce_ratio(v) == fmax(got_r[0], fmax(got_r[1], got_r[2])),
          "%s: the bounce ratio is not the largest channel's", what);
    int bad = 0, turned = 0;
    double worst = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        const float *plane = direct.sides + 8 * i + 4;
        double t2[3], a2[3], dt[3], da[3], t[3], a[3];
        sides_of(&two, i, plane, t2, a2);
        added(&two, &one, plane, i, dt, da);
        sides_of(&rest, i, plane, t, a);
        for (int k = 0; k < 3; ++k) {
            const double want_t = t2[k] + f[k] * dt[k], want_a = a2[k] + f[k] * da[k];
            const double off = fmax(fabs(t[k] - want_t), fabs(a[k] - want_a));
            const double scale = fmax(fmax(want_t, want_a), 1e-3);
            worst = fmax(worst, off / scale);
            bad += off > 1e-4 * scale;
        }
        const float *up = rest.sides + 8 * i + 4;
        turned +=
            (double)up[0] * plane[0] + (double)up[1] * plane[1] + (double)up[2] * plane[2] < 0.0;
    }
    CHECK(bad == 0 && turned > 0,
          "%s: %d voxel sides off the reference's light plus the rest (worst %.2e); %d voxels "
          "whose brighter side is no longer the direct light's",
          what, bad, worst, turned);
    /* A closed room of one albedo: each channel's bounce ratio is its albedo. */
    for (int k = 0; k < 3; ++k)
        CHECK(fabs(measured[k] - albedo[k]) < 0.15,
              "%s: channel %d of albedo %.2f carries on %.3f of its light per bounce", what, k,
              albedo[k], measured[k]);
    printf("%s, albedo %.2f %.2f %.2f: bounce ratios %.4f %.4f %.4f (kernel %.4f %.4f %.4f), "
           "rest x %.3f %.3f %.3f of the last bounce, %u voxels (%d turned), worst side %.1e\n",
           what, albedo[0], albedo[1], albedo[2], r[0], r[1], r[2], got_r[0], got_r[1], got_r[2],
           f[0], f[1], f[2], n, turned, worst);
    light_free(&direct);
    light_free(&one);
    light_free(&still);
    light_free(&two);
    light_free(&rest);
    vct_voxels_release(v);

    /* exact_bounces: the same two bounces, nothing after them. */
    v = lit_voxels(s, g, 1);
    bounce(s, g, v);
    bounce(s, g, v);
    voxel_light exact = read_light(v, n);
    REQUIRE_OK(vct_voxels_bounce_rest(ctx, v, &err), err);
    voxel_light exact_after = read_light(v, n);
    CHECK(vct_voxels_bounce_ratio(v) == 0.0 &&
              memcmp(exact.radiance, exact_after.radiance, 16ull * n) == 0,
          "%s, exact_bounces: the rest adds nothing", what);
    light_free(&exact);
    light_free(&exact_after);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* Light entering a long stone hall by a slit in its one-voxel roof: each
 * bounce must carry on less light than the one before, no more than its
 * brightest stone's albedo (0.62) of it. When every bounce decided each
 * voxel's sides again, the planes turned between bounces and the third
 * bounce carried on 0.9 of the second's; the rest of the series then made the
 * hall 1.2 times as bright as the path tracer's. The kernel's ratio is the
 * last two bounces'. */
static void hall_bounces_decay(void) {
    vct_error err = {0};
    vct_scene *s = check_scene_file("scenes/suite/long_hall.gltf");
    const float sky[3] = {0.35f, 0.45f, 0.6f};
    memcpy(s->ambient, sky, sizeof sky);
    vct_render_job job = vct_render_job_default(VCT_METHOD_VCT, 64, 64);
    vct_accel *a = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    vct_voxels *v = vct_voxelize(ctx, s, &job.voxel_options, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, a, v, &err), err);
    REQUIRE_OK(vct_bricks_build(ctx, v, &job.brick_options, &err), err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    const uint32_t n = info.voxels;
    voxel_light light[4];
    light[0] = read_light(v, n);
    double carried[3][3];
    for (int b = 1; b <= 3; ++b) {
        bounce(s, a, v);
        light[b] = read_light(v, n);
        bounce_light(&light[b], &light[b - 1], &light[0], n, carried[b - 1]);
    }
    REQUIRE_OK(vct_voxels_bounce_rest(ctx, v, &err), err);
    double got[3];
    vct_voxels_bounce_ratios(v, got);
    for (int k = 0; k < 3; ++k) {
        const double r2 = carried[1][k] / carried[0][k], r3 = carried[2][k] / carried[1][k];
        CHECK(r2 <= 0.62 && r3 <= 0.62 && r3 > 0.0,
              "long hall: channel %d's bounces carry on %.3f and %.3f of the light before them, "
              "more than the brightest albedo 0.62",
              k, r2, r3);
        CHECK(fabs(got[k] - r3) < 1e-3 * r3,
              "long hall: channel %d's bounce ratio %.4f, the last two bounces' %.4f", k, got[k],
              r3);
        printf("long hall, %u voxels, channel %d: the bounces carry on %.3f, then %.3f of the "
               "light before them\n",
               n, k, r2, r3);
    }
    for (int b = 0; b < 4; ++b)
        light_free(&light[b]);
    vct_voxels_release(v);
    vct_accel_release(a);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    const float grey[3] = {ALBEDO, ALBEDO, ALBEDO};
    against_reference(grey, "grey box");
    against_reference(coloured, "coloured box");
    hall_bounces_decay();
    vct_context_release(ctx);
    return check_exit("test_bounce_rest");
}
