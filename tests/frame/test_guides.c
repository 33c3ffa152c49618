/* The denoiser's guides (vct_render_guides, kernels/render/guides.cl) on a
 * plane seen from above and from below, against the plane computed here in
 * double: where all of a pixel's n x n rays hit it, the albedo is the
 * material's, the normal faces the viewer with length 1 and the depth is the
 * mean of the rays' distances; where none does, albedo 1, normal 0 and depth
 * 0. The albedo's w is the share of the rays that met no emitter: 1 on a
 * plane that emits nothing, 1 less the share that met it on one that
 * emits. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "vec3d.h"

#define W 40
#define H 30
#define N 4

/* The ray through (px, py) in pixels (row 0 at the top), as camera_ray but
 * anywhere in the pixel. */
static v3 ray_at(v3 eye, v3 at, v3 up, double fov_deg, double px, double py) {
    const v3 f = norm(sub(at, eye)), r = norm(cross(f, up)), u = cross(r, f);
    const double th = tan(fov_deg * CHECK_PI / 360.0), aspect = (double)W / H;
    const double sx = (2.0 * px / W - 1.0) * th * aspect, sy = (1.0 - 2.0 * py / H) * th;
    return norm(add(f, add(mul(r, sx), mul(u, sy))));
}

static void run_case(vct_context *ctx, const char *name, double eye_y, int emits) {
    float pos[] = {-50, 0, -50, 50, 0, -50, 50, 0, 50, -50, 0, 50};
    uint32_t tris[] = {0, 1, 2, 0, 2, 3}, mats[] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = 0.8f, m.albedo[1] = 0.5f, m.albedo[2] = 0.25f;
    m.emission[0] = m.emission[1] = m.emission[2] = emits ? 3.0f : 0.0f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 4, tris, 2, mats, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const v3 eye = v(0.4, eye_y, 7.0), at = v(0.0, 0.0, 0.0), up = v(0, 1, 0);
    const double fov = 70.0;
    s->camera =
        (vct_camera){{(float)eye.x, (float)eye.y, (float)eye.z}, {0, 0, 0}, {0, 1, 0}, (float)fov};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_image albedo, nd;
    REQUIRE_OK(vct_render_guides(ctx, s, g, W, H, N, &albedo, &nd, &err), err);
    int full = 0, empty = 0, bad = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double t_sum = 0;
            int hits = 0;
            for (int j = 0; j < N; ++j)
                for (int i = 0; i < N; ++i) {
                    const v3 d = ray_at(eye, at, up, fov, x + (i + 0.5) / N, y + (j + 0.5) / N);
                    const double t = -eye.y / d.y;
                    const v3 p = add(eye, mul(d, t));
                    /* rays within a hair of the plane's border are left out */
                    if (t > 0 && fabs(p.x) < 49.9 && fabs(p.z) < 49.9)
                        t_sum += t, ++hits;
                    else if (t > 0 && fabs(p.x) < 50.1 && fabs(p.z) < 50.1)
                        hits = -1000;
                }
            const float *a = &albedo.rgba[4 * (y * W + x)], *q = &nd.rgba[4 * (y * W + x)];
            const double clear = emits ? (double)(N * N - hits) / (N * N) : 1.0;
            if (hits >= 0 && fabs(a[3] - clear) > 1e-6 && bad++ < 4)
                fprintf(stderr,
                        "%s (%d,%d): %d of %d rays on the plane, share clear %g (want %g)\n", name,
                        x, y, hits, N * N, a[3], clear);
            if (hits == N * N) {
                ++full;
                const double depth = t_sum / hits, ny = eye_y > 0 ? 1.0 : -1.0;
                const int ok = fabs(a[0] - 0.8) < 1e-6 && fabs(a[1] - 0.5) < 1e-6 &&
                               fabs(a[2] - 0.25) < 1e-6 && fabs(q[0]) < 1e-6 &&
                               fabs(q[1] - ny) < 1e-6 && fabs(q[2]) < 1e-6 &&
                               fabs(q[3] - depth) < 1e-4 * depth;
                if (!ok && bad++ < 4)
                    fprintf(stderr,
                            "%s (%d,%d): albedo %g %g %g, normal %g %g %g, depth %g (want %g)\n",
                            name, x, y, a[0], a[1], a[2], q[0], q[1], q[2], q[3], depth);
            } else if (hits == 0) {
                ++empty;
                const int ok = a[0] == 1.0f && a[1] == 1.0f && a[2] == 1.0f && q[0] == 0.0f &&
                               q[1] == 0.0f && q[2] == 0.0f && q[3] == 0.0f;
                if (!ok && bad++ < 4)
                    fprintf(stderr, "%s (%d,%d): no surface, yet albedo %g, depth %g\n", name, x, y,
                            a[0], q[3]);
            }
        }
    printf("%s: %d pixels all on the plane, %d all off it, %d wrong\n", name, full, empty, bad);
    CHECK(bad == 0, "%s: %d pixels wrong", name, bad);
    CHECK(full > W * H / 4 && empty > W * H / 10, "%s: the view misses its mix (%d, %d)", name,
          full, empty);
    vct_image_release(&albedo);
    vct_image_release(&nd);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    vct_context *ctx = check_context();
    run_case(ctx, "from above", 2.0, 0);
    run_case(ctx, "from below", -2.0, 0);
    run_case(ctx, "an emitter from above", 2.0, 1);
    vct_error err = {0};
    vct_image a, b;
    vct_scene *s = NULL;
    CHECK(vct_render_guides(ctx, s, NULL, W, H, 0, &a, &b, &err) == VCT_ERR_INPUT,
          "0 rays per axis accepted");
    vct_context_release(ctx);
    return check_exit("test_guides");
}
