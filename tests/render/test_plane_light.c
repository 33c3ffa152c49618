/* A plane under a point, a spot and a directional light: every pixel of the
 * ray caster's image must equal the analytic radiance I cos / d^2 * albedo / pi
 * (or E cos * albedo / pi) to 1e-4 relative. The reference camera, plane hit
 * and shading are computed here in double, independently of the kernels. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "vec3d.h"

#define W 96
#define H 72
#define TOL 1e-4

/* Plane y = height, quad of half-size 50 around the origin, plus an optional
 * small occluding square above it. */
static vct_scene *plane_scene(double height, int occluder) {
    float pos[8 * 3] = {-50,   0,    -50,   50,   0,    -50,   50,   0,    50,   -50,   0,    50,
                        -0.5f, 1.5f, -0.5f, 0.5f, 1.5f, -0.5f, 0.5f, 1.5f, 0.5f, -0.5f, 1.5f, 0.5f};
    for (int i = 0; i < 4; ++i)
        pos[3 * i + 1] = (float)height;
    for (int i = 4; i < 8; ++i)
        pos[3 * i + 1] += (float)height;
    uint32_t tris[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    uint32_t mats[] = {0, 0, 1, 1};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    m[0].albedo[0] = 0.8f;
    m[0].albedo[1] = 0.5f;
    m[0].albedo[2] = 0.25f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 8, tris, occluder ? 4 : 2, mats, m, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    return s;
}

/* Radiance of the plane point p lit by light l (no occlusion). With
 * spot_scale, the spot factor is left out: the scale errors are judged on. */
static v3 analytic(const vct_light *l, v3 p, v3 albedo, int spot_scale) {
    v3 wi, radiant;
    double cos_theta;
    if (l->type == VCT_LIGHT_DIRECTIONAL) {
        wi = mul(norm(v(l->direction[0], l->direction[1], l->direction[2])), -1.0);
        radiant = v(l->color[0], l->color[1], l->color[2]);
    } else {
        v3 to = sub(v(l->position[0], l->position[1], l->position[2]), p);
        double d2 = dot(to, to);
        wi = mul(to, 1.0 / sqrt(d2));
        radiant = mul(v(l->color[0], l->color[1], l->color[2]), 1.0 / d2);
        if (l->type == VCT_LIGHT_SPOT && !spot_scale) {
            double cd = -dot(wi, norm(v(l->direction[0], l->direction[1], l->direction[2])));
            double co = cos(l->outer_cone), ci = cos(l->inner_cone);
            double x = (cd - co) / (ci - co);
            x = x < 0 ? 0 : (x > 1 ? 1 : x);
            radiant = mul(radiant, x * x);
        }
    }
    cos_theta = wi.y; /* plane normal +y */
    if (cos_theta <= 0)
        return v(0, 0, 0);
    return v(albedo.x / CHECK_PI * radiant.x * cos_theta,
             albedo.y / CHECK_PI * radiant.y * cos_theta,
             albedo.z / CHECK_PI * radiant.z * cos_theta);
}

/* 1 if the segment p -> light crosses the occluder square (|x|,|z| < 0.5 at
 * y = height + 1.5); *margin is its distance to the square's border. */
static int occluded(const vct_light *l, v3 p, double height, double *margin) {
    v3 to = l->type == VCT_LIGHT_DIRECTIONAL
                ? mul(v(l->direction[0], l->direction[1], l->direction[2]), -1e6)
                : sub(v(l->position[0], l->position[1], l->position[2]), p);
    double t = (height + 1.5 - p.y) / to.y;
    if (!(t > 0 && t < 1)) {
        *margin = 1e9;
        return 0;
    }
    v3 q = add(p, mul(to, t));
    *margin = fabs(fmax(fabs(q.x), fabs(q.z)) - 0.5);
    return fabs(q.x) < 0.5 && fabs(q.z) < 0.5;
}

static void run_case(vct_context *ctx, const char *name, vct_light light, double height,
                     int occluder) {
    vct_scene *s = plane_scene(height, occluder);
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &light, &err), err);
    const v3 eye = v(0.3, height + 6.0, 6.0), at = v(0.0, height, 0.0), up = v(0, 1, 0);
    const double fov = 40.0;
    s->camera = (vct_camera){{(float)eye.x, (float)eye.y, (float)eye.z},
                             {(float)at.x, (float)at.y, (float)at.z},
                             {0, 1, 0},
                             (float)fov};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_image im;
    vct_render_options ro = {W, H, 0, 0, 0.0f};
    REQUIRE_OK(vct_render_raycast(ctx, s, g, &ro, &im, &err), err);

    const v3 albedo = v(0.8, 0.5, 0.25);
    int bad = 0, compared = 0, shadowed = 0;
    double worst = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const v3 d = camera_ray(eye, at, up, fov, W, H, x, y);
            if (d.y >= 0)
                continue;
            double t = (height - eye.y) / d.y;
            v3 p = add(eye, mul(d, t));
            if (fabs(p.x) > 49 || fabs(p.z) > 49)
                continue;
            if (occluder) {
                /* Pixels that see the occluder itself are not plane pixels. */
                double to = (height + 1.5 - eye.y) / d.y;
                v3 q = add(eye, mul(d, to));
                if (fabs(q.x) < 0.51 && fabs(q.z) < 0.51)
                    continue;
            }
            double margin = 0;
            v3 ref = analytic(&light, p, albedo, 0);
            /* Errors relative to the unshadowed, un-attenuated value: the spot
             * falloff is a smooth float evaluation that is ill-conditioned
             * near its edge, and shadowed pixels have no scale of their own. */
            v3 scale = analytic(&light, p, albedo, 1);
            if (occluder && occluded(&light, p, height, &margin))
                ref = v(0, 0, 0), ++shadowed;
            /* Shadow rays start lifted off the surface by a small multiple of
             * the scene extent and of the coordinates' float spacing, which
             * may move a shadow edge by this much: either answer is right. */
            const double edge_band = 1e-4 * 100.0 + 1e-5 * fabs(height);
            if (occluder && margin < edge_band)
                continue;
            const float *px = &im.rgba[4 * (y * W + x)];
            double want[3] = {ref.x, ref.y, ref.z}, unit[3] = {scale.x, scale.y, scale.z};
            for (int c = 0; c < 3; ++c) {
                double e = fabs(px[c] - want[c]) / fmax(unit[c], 1e-30);
                if (e > worst)
                    worst = e;
                if (e > TOL && bad++ < 5)
                    fprintf(stderr, "%s: pixel (%d,%d) channel %d: %.8g, expected %.8g\n", name, x,
                            y, c, px[c], want[c]);
            }
            ++compared;
        }
    }
    CHECK(compared > W * H / 2, "%s: only %d pixels compared", name, compared);
    CHECK(bad == 0, "%s: %d values off by more than %g (worst %.3g)", name, bad, TOL, worst);
    if (occluder)
        CHECK(shadowed > 20, "%s: the occluder shadows only %d pixels", name, shadowed);
    printf("%s: %d pixels, worst relative error %.3g\n", name, compared, worst);
    vct_image_release(&im);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    vct_context *ctx = check_context();
    vct_light point = {VCT_LIGHT_POINT, {1.0f, 3.0f, -0.5f}, {0, 0, 0}, {10, 20, 30}, 0, 0, 0};
    vct_light spot = {
        VCT_LIGHT_SPOT, {0.5f, 4.0f, 0.0f}, {0.2f, -1.0f, 0.1f}, {40, 40, 40}, 0.3f, 0.6f, 0};
    vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0, 0, 0}, {0.3f, -1.0f, -0.4f}, {2.0f, 1.5f, 1.0f}, 0, 0, 0};
    run_case(ctx, "point", point, 0.0, 0);
    run_case(ctx, "spot", spot, 0.0, 0);
    run_case(ctx, "directional", sun, 0.0, 0);
    run_case(ctx, "point+occluder", point, 0.0, 1);
    run_case(ctx, "directional+occluder", sun, 0.0, 1);
    /* The same far from the origin: epsilons must scale with the coordinates. */
    vct_light far_point = point;
    far_point.position[1] += 1000.0f;
    run_case(ctx, "point at height 1000", far_point, 1000.0, 1);
    vct_context_release(ctx);
    return check_exit("test_plane_light");
}
