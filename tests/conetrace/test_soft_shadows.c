/* Soft shadows of lights with a radius. A floor under a plate, lit by a
 * point light with a disk radius or a sun with an angular radius: the
 * fraction of the light each floor point sees comes from an independent
 * reference (the disk facing the point, or the cone of directions, sampled
 * on a fine grid in double and tested against the plate here). The path
 * tracer must match it within its noise; voxel cone tracing, which reads the
 * fraction from one cone of filtered voxels, within stated tolerances: lit
 * floor stays lit, the umbra stays dark, the penumbra widens with the
 * radius. Also: the plan, the kernels it enqueues, bit-identical images when
 * soft shadows are forced on without a radius or off with one, and input
 * that cannot be taken. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "vct_case.h"
#include "vec3d.h"

#define W 64
#define H 64
#define PLATE_Y 2.53
#define PLATE_X0 -3.0
#define PLATE_X1 0.03
#define PLATE_Z 3.0
#define FLOOR 4.0
#define REF_GRID 64                 /* reference samples per axis of the light's extent */
#define VOXEL (2.0 * FLOOR / 128.0) /* the volume spans the floor at 128^3 */

static vct_context *ctx;
/* The camera looks straight down from below the plate: it sees the floor
 * only, never the plate. */
static const v3 eye = {0.0, 2.0, 0.0}, look = {0.0, 0.0, 0.0}, up = {0, 0, -1};
static const double fov = 90.0;

/* A floor of half-size FLOOR at y = 0, and, with `plate`, a plate over
 * x in [PLATE_X0, PLATE_X1], |z| < PLATE_Z at y = PLATE_Y. */
static vct_scene *floor_scene(int plate, vct_light light) {
    const float f = (float)FLOOR, py = (float)PLATE_Y, x0 = (float)PLATE_X0, x1 = (float)PLATE_X1,
                pz = (float)PLATE_Z;
    const float pos[24] = {-f, 0,  -f,  f,  0,  -f,  f,  0,  f,  -f, 0,  f,
                           x0, py, -pz, x1, py, -pz, x1, py, pz, x0, py, pz};
    const uint32_t tris[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    const uint32_t mats[4] = {0, 0, 0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 0.8f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 8, tris, plate ? 4 : 2, mats, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    s->camera = (vct_camera){{(float)eye.x, (float)eye.y, (float)eye.z},
                             {(float)look.x, (float)look.y, (float)look.z},
                             {(float)up.x, (float)up.y, (float)up.z},
                             (float)fov};
    return s;
}

/* The floor point pixel (x, y) sees, or 0 where it sees none. */
static int floor_point(int x, int y, v3 *p) {
    const v3 d = camera_ray(eye, look, up, fov, W, H, x, y);
    if (d.y >= 0)
        return 0;
    *p = add(eye, mul(d, -eye.y / d.y));
    return fabs(p->x) < FLOOR - 0.5 && fabs(p->z) < FLOOR - 0.5;
}

static v3 towards_light(const vct_light *l, v3 p, double *dist) {
    if (l->type == VCT_LIGHT_DIRECTIONAL) {
        *dist = INFINITY;
        return mul(norm(v3_of(l->direction)), -1.0);
    }
    const v3 to = sub(v3_of(l->position), p);
    *dist = sqrt(dot(to, to));
    return mul(to, 1.0 / *dist);
}

/* Unshadowed radiance of floor point p: albedo / pi * I cos / d^2 (or E cos). */
static double unshadowed(const vct_light *l, v3 p) {
    double dist;
    const v3 wi = towards_light(l, p, &dist);
    const double radiant = isinf(dist) ? l->color[1] : l->color[1] / (dist * dist);
    return wi.y > 0 ? 0.8 / CHECK_PI * radiant * wi.y : 0.0;
}

/* The fraction of the light's extent that p sees past the plate. */
static double visible_fraction(const vct_light *l, v3 p) {
    double dist;
    const v3 wi = towards_light(l, p, &dist);
    const v3 t = norm(fabs(wi.x) > 0.9 ? cross(wi, v(0, 1, 0)) : cross(wi, v(1, 0, 0)));
    const v3 b = cross(wi, t);
    int seen = 0;
    for (int i = 0; i < REF_GRID; ++i) {
        for (int j = 0; j < REF_GRID; ++j) {
            const double u1 = (i + 0.5) / REF_GRID, phi = 2.0 * CHECK_PI * (j + 0.5) / REF_GRID;
            const v3 around = add(mul(t, cos(phi)), mul(b, sin(phi)));
            v3 to; /* from p to the sample, scaled so that its length is its reach */
            if (isinf(dist)) {
                const double cos_max = cos((double)l->radius);
                const double c = 1.0 - u1 * (1.0 - cos_max), s = sqrt(1.0 - c * c);
                to = mul(add(mul(wi, c), mul(around, s)), 1e6);
            } else {
                to = add(mul(wi, dist), mul(around, l->radius * sqrt(u1)));
            }
            const double s = (PLATE_Y - p.y) / to.y;
            const v3 q = add(p, mul(to, s));
            const int blocked = to.y > 0 && s > 0 && s < 1 && q.x > PLATE_X0 && q.x < PLATE_X1 &&
                                fabs(q.z) < PLATE_Z;
            seen += !blocked && to.y > 0;
        }
    }
    return (double)seen / (REF_GRID * REF_GRID);
}

/* The floor's fraction of light in each pixel, read from image / unshadowed;
 * -1 where the pixel does not see the open floor. */
static void fractions(const vct_image *im, const vct_light *l, double *out) {
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            v3 p;
            const double u = floor_point(x, y, &p) ? unshadowed(l, p) : 0.0;
            out[y * W + x] = u > 0 ? im->rgba[4 * (y * W + x) + 1] / u : -1.0;
        }
}

static void reference(const vct_light *l, double *out) {
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            v3 p;
            out[y * W + x] =
                floor_point(x, y, &p) && unshadowed(l, p) > 0 ? visible_fraction(l, p) : -1.0;
        }
}

/* Direct light only: indirect and AO forced off, so the image is the
 * direct term. */
static vct_image render_vct(const vct_scene *s, const vct_effect_force *extra, uint32_t res,
                            vct_plan *plan) {
    vct_effect_force force[VCT_EFFECTS] = {0};
    if (extra)
        memcpy(force, extra, sizeof force);
    force[VCT_EFFECT_INDIRECT] = force[VCT_EFFECT_AO] = VCT_FORCE_OFF;
    vct_plan_make(s, force, plan);
    return vct_case_render(ctx, s, plan, res, W, H, 1, NULL);
}

static vct_image render_pt(const vct_scene *s, uint32_t spp) {
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_pathtrace_options o = {W, H, spp, 0.0, 1, 7, 64, 0, 0, NULL, NULL, 1};
    vct_image im;
    REQUIRE_OK(vct_render_pathtrace(ctx, s, g, &o, &im, NULL, &err), err);
    vct_accel_release(g);
    return im;
}

typedef struct agreement {
    int compared, lit, lit_dark, umbra, umbra_bright;
    double mean_abs, mean_signed;
} agreement;

/* Compares measured fractions with the reference: lit means the reference
 * sees all of the light, umbra none of it. */
static agreement agree(const double *got, const double *want, double lit_min, double umbra_max) {
    agreement a;
    memset(&a, 0, sizeof a);
    for (int i = 0; i < W * H; ++i) {
        if (want[i] < 0 || got[i] < 0)
            continue;
        const double d = got[i] - want[i];
        a.mean_abs += fabs(d);
        a.mean_signed += d;
        ++a.compared;
        if (want[i] == 1.0) {
            ++a.lit;
            a.lit_dark += got[i] < lit_min;
        } else if (want[i] == 0.0) {
            ++a.umbra;
            a.umbra_bright += got[i] > umbra_max;
        }
    }
    if (a.compared) {
        a.mean_abs /= a.compared;
        a.mean_signed /= a.compared;
    }
    return a;
}

/* The floor x coordinate at the centre of pixel column px (fractional): the
 * camera looks straight down from height 2 with a 90 degree square view. */
static double floor_x(double px) {
    return eye.y * (2.0 * (px + 0.5) / W - 1.0);
}

/* Where a row's fraction of light first reaches `level`, going from the
 * umbra (-x) to the open floor (+x), interpolated between pixels. */
static double crossing(const double *row, double level) {
    for (int x = 1; x < W; ++x)
        if (row[x - 1] >= 0 && row[x - 1] < level && row[x] >= level)
            return floor_x(x - 1 + (level - row[x - 1]) / (row[x] - row[x - 1]));
    return NAN;
}

/* The shadow edge (straight, along z): where half the light is seen, and
 * the penumbra's width from 10% to 90%, averaged over the rows. */
typedef struct edge {
    double middle, width;
} edge;

static edge edge_of(const double *fraction) {
    edge e = {0.0, 0.0};
    for (int y = 0; y < H; ++y) {
        const double *row = &fraction[y * W];
        e.middle += crossing(row, 0.5) / H;
        e.width += (crossing(row, 0.9) - crossing(row, 0.1)) / H;
    }
    return e;
}

static vct_light point_light(float radius) {
    vct_light l;
    memset(&l, 0, sizeof l);
    l.type = VCT_LIGHT_POINT;
    l.position[0] = 0.5f;
    l.position[1] = 5.0f;
    l.color[0] = l.color[1] = l.color[2] = 20.0f;
    l.radius = radius;
    return l;
}

static vct_light sun(float angle) {
    vct_light l;
    memset(&l, 0, sizeof l);
    l.type = VCT_LIGHT_DIRECTIONAL;
    l.direction[0] = -0.3f;
    l.direction[1] = -1.0f;
    l.color[0] = l.color[1] = l.color[2] = 2.0f;
    l.radius = angle;
    return l;
}

/* One light over the plate: the path tracer and the cones against the
 * reference. Returns the width of the cones' penumbra. */
static double plate_case(const char *name, vct_light light) {
    vct_scene *s = floor_scene(1, light);
    static double want[W * H], got[W * H];
    reference(&light, want);

    vct_image pt = render_pt(s, 256);
    fractions(&pt, &light, got);
    const agreement ap = agree(got, want, 0.99, 0.02);
    /* 256 binary samples: a standard deviation of at most 0.031 per pixel. */
    CHECK(ap.compared > W * H / 3 && ap.lit > 100 && ap.umbra > 50,
          "%s: %d pixels, %d lit, %d umbra", name, ap.compared, ap.lit, ap.umbra);
    CHECK(ap.lit_dark == 0 && ap.umbra_bright == 0,
          "%s, path tracer: %d lit pixels darkened, %d umbra pixels lit", name, ap.lit_dark,
          ap.umbra_bright);
    CHECK(ap.mean_abs < 0.012 && fabs(ap.mean_signed) < 0.004,
          "%s, path tracer: mean |error| %.4f, mean error %.4f of the unshadowed light", name,
          ap.mean_abs, ap.mean_signed);

    vct_plan plan;
    vct_image cones = render_vct(s, NULL, 128, &plan);
    CHECK(vct_kernel_launches(ctx, "vct_soft_shadows") == 1, "%s: soft shadow kernel ran %d times",
          name, vct_kernel_launches(ctx, "vct_soft_shadows"));
    fractions(&cones, &light, got);
    const agreement ac = agree(got, want, 0.0, 1.0);
    const edge e_ref = edge_of(want), e_cone = edge_of(got);
    double umbra_max = 0.0, lit_min = 1.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double fx = floor_x(x), g = got[y * W + x];
            if (fx < e_ref.middle - e_ref.width - 0.5)
                umbra_max = fmax(umbra_max, g);
            if (fx > e_ref.middle + e_ref.width + 0.5)
                lit_min = fmin(lit_min, g);
        }
    CHECK(umbra_max <= 0.05 && lit_min >= 0.97,
          "%s, cones: deep umbra up to %.3f, open floor down to %.3f", name, umbra_max, lit_min);
    /* Voxels make the plate larger, never smaller: conservative voxels and
     * corner samples by up to 2 voxels, the filtered level the cone reads at
     * the plate by up to half its sample spacing (a quarter of the cone's
     * diameter there). The shadow's edge moves out by that, projected from
     * the light onto the floor. */
    const int sun_light = light.type == VCT_LIGHT_DIRECTIONAL;
    const double tan_half =
        sun_light ? tan((double)light.radius) : light.radius / light.position[1];
    const double project = sun_light ? 1.0 : light.position[1] / (light.position[1] - PLATE_Y);
    const double shift_max = project * (2.0 * VOXEL + 0.5 * tan_half * PLATE_Y);
    const double shift = e_cone.middle - e_ref.middle;
    CHECK(shift > -0.5 * VOXEL && shift < shift_max,
          "%s, cones: the half-light edge at x = %.3f, the reference's at %.3f (may move out by "
          "up to %.3f)",
          name, e_cone.middle, e_ref.middle, shift_max);
    CHECK(e_cone.width > 0.5 * e_ref.width && e_cone.width < 2.0 * e_ref.width + 0.25,
          "%s, cones: penumbra %.3f wide, the reference's %.3f", name, e_cone.width, e_ref.width);
    CHECK(ac.mean_abs < 0.1, "%s, cones: mean |error| %.4f of the unshadowed light", name,
          ac.mean_abs);
    printf("%s: path tracer mean |error| %.4f (bias %+.4f) over %d pixels; cones: mean |error| "
           "%.4f (bias %+.4f), half-light edge at %.3f (reference %.3f, bound %.3f), penumbra "
           "%.3f wide "
           "(reference %.3f), deep umbra up to %.3f, open floor down to %.3f\n",
           name, ap.mean_abs, ap.mean_signed, ap.compared, ac.mean_abs, ac.mean_signed,
           e_cone.middle, e_ref.middle, e_ref.middle + shift_max, e_cone.width, e_ref.width,
           umbra_max, lit_min);
    vct_image_release(&pt);
    vct_image_release(&cones);
    vct_scene_release(s);
    return e_cone.width;
}

/* With nothing in the way, a cone as wide as the light sees only the floor
 * it starts from: the image stays within 1% of hard-shadowed light. */
static void open_floor(void) {
    vct_light light = point_light(0.6f);
    vct_scene *s = floor_scene(0, light);
    vct_plan plan;
    vct_image cones = render_vct(s, NULL, 128, &plan);
    static double got[W * H];
    fractions(&cones, &light, got);
    double lowest = 1.0;
    int compared = 0;
    for (int i = 0; i < W * H; ++i)
        if (got[i] >= 0) {
            lowest = fmin(lowest, got[i]);
            ++compared;
        }
    CHECK(compared > W * H / 3 && lowest > 0.99 && lowest <= 1.0 + 1e-5,
          "open floor: %d pixels, lowest fraction of light %.4f", compared, lowest);
    printf("open floor: %d pixels, lowest fraction of light %.5f\n", compared, lowest);
    vct_image_release(&cones);
    vct_scene_release(s);
}

static int same_image(const vct_image *a, const vct_image *b) {
    return a->width == b->width && a->height == b->height &&
           memcmp(a->rgba, b->rgba, 16ull * a->width * a->height) == 0;
}

/* The plan turns soft shadows on only for a light with a radius; forcing
 * them off gives the hard image, forcing them on without a radius changes
 * no pixel. */
static void plan_and_forcing(void) {
    vct_scene *hard = floor_scene(1, point_light(0.0f));
    vct_scene *soft = floor_scene(1, point_light(0.5f));
    vct_plan p;
    vct_plan_make(hard, NULL, &p);
    CHECK(!p.on[VCT_EFFECT_SOFT_SHADOWS] && strstr(p.why[VCT_EFFECT_SOFT_SHADOWS], "radius"),
          "no radius: soft shadows %d (%s)", p.on[VCT_EFFECT_SOFT_SHADOWS],
          p.why[VCT_EFFECT_SOFT_SHADOWS]);
    vct_plan_make(soft, NULL, &p);
    CHECK(p.on[VCT_EFFECT_SOFT_SHADOWS] && vct_plan_needs_voxels(&p),
          "radius: soft shadows %d (%s)", p.on[VCT_EFFECT_SOFT_SHADOWS],
          p.why[VCT_EFFECT_SOFT_SHADOWS]);
    vct_effect_force force[VCT_EFFECTS] = {0};
    force[VCT_EFFECT_SHADOWS] = VCT_FORCE_OFF;
    vct_plan_make(soft, force, &p);
    CHECK(!p.on[VCT_EFFECT_SOFT_SHADOWS] && strstr(p.why[VCT_EFFECT_SOFT_SHADOWS], "shadows"),
          "shadows off: soft shadows %d (%s)", p.on[VCT_EFFECT_SOFT_SHADOWS],
          p.why[VCT_EFFECT_SOFT_SHADOWS]);

    vct_plan plan;
    vct_image base = render_vct(hard, NULL, 64, &plan);
    CHECK(vct_kernel_launches(ctx, "vct_soft_shadows") == 0, "hard light: soft kernel enqueued");
    memset(force, 0, sizeof force);
    force[VCT_EFFECT_SOFT_SHADOWS] = VCT_FORCE_ON;
    vct_image forced_on = render_vct(hard, force, 64, &plan);
    CHECK(vct_kernel_launches(ctx, "vct_soft_shadows") == 1 && same_image(&base, &forced_on),
          "soft shadows forced on without a radius: %d launches, image %s",
          vct_kernel_launches(ctx, "vct_soft_shadows"),
          same_image(&base, &forced_on) ? "identical" : "changed");
    force[VCT_EFFECT_SOFT_SHADOWS] = VCT_FORCE_OFF;
    vct_image forced_off = render_vct(soft, force, 64, &plan);
    CHECK(vct_kernel_launches(ctx, "vct_soft_shadows") == 0 && same_image(&base, &forced_off),
          "soft shadows forced off: the hard image, bit for bit");
    vct_image again = render_vct(soft, NULL, 64, &plan), twice = render_vct(soft, NULL, 64, &plan);
    CHECK(same_image(&again, &twice) && !same_image(&again, &base),
          "soft image deterministic and unlike the hard one");
    vct_image *all[5] = {&base, &forced_on, &forced_off, &again, &twice};
    for (int i = 0; i < 5; ++i)
        vct_image_release(all[i]);
    vct_scene_release(hard);
    vct_scene_release(soft);
}

static void bad_radius(void) {
    vct_scene *s = floor_scene(0, point_light(0.0f));
    const vct_light bad[3] = {point_light(-0.1f), point_light(NAN), sun(1.2f)};
    const char *why[3] = {"negative", "NaN", "over 1 radian"};
    for (int i = 0; i < 3; ++i) {
        vct_error err = {0};
        const int rc = vct_scene_add_light(s, &bad[i], &err);
        CHECK(rc == VCT_ERR_INPUT && s->light_count == 1 &&
                  (strstr(err.message, "radius") || strstr(err.message, "non-finite")),
              "%s radius: status %d, \"%s\"", why[i], rc, err.message);
    }
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    bad_radius();
    plan_and_forcing();
    open_floor();
    const double narrow = plate_case("point, radius 0.25", point_light(0.25f));
    const double wide = plate_case("point, radius 0.75", point_light(0.75f));
    CHECK(wide > 2.0 * narrow, "penumbra widens with the radius: %.3f, then %.3f", narrow, wide);
    plate_case("sun, 0.1 rad", sun(0.1f));
    vct_context_release(ctx);
    return check_exit("test_soft_shadows");
}
