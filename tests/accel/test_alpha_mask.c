/* Alpha masks (kernels/accel/alpha_mask.h): a masked quad (a 2-texel
 * checker of alpha 0 and 1, cutoff 0.5) hangs over a floor under a point
 * light. Every pixel the camera finds, through the BVH and through the grid,
 * against a plain-C answer: the quad is seen only where its alpha reaches
 * the cutoff, the floor through its holes, and the floor's shadow ray passes
 * the quad where it is masked (a point light's and a sun's straight down,
 * through the acceleration structure). Light injection's shadow rays, through
 * the point light's triangle bins, pass it too: the floor's voxels against
 * the same answer. The quad's voxels are as opaque as the share of their
 * surface the mask keeps. A masked material without a texture masks by its
 * alpha factor alone. */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

#define TEX 6       /* texels per side: their edges fall inside voxels */
#define QUAD_Y 4.0f /* the masked quad's height over the floor */
#define CUTOFF 0.5f
/* fragment_albedo.h's FRAGMENT_ALBEDO_SIDE: the points per side a voxel's
 * albedo and mask coverage are read at */
#define POINTS 4

static vct_context *ctx;
static const float light[3] = {8.3f, 20.0f, 7.7f}, intensity = 400.0f;
static const float eye[3] = {8.0f, 14.0f, 8.01f};

/* The case under test: the quad's alpha factor, textured or not, and a sun
 * straight down (irradiance pi) instead of the point light. */
typedef struct mask_case {
    const char *name;
    vct_accel_kind kind;
    int textured, sun;
    float factor;
} mask_case;

static float texel_alpha(int x, int y) {
    return ((x / 2 + y / 2) & 1) ? 1.0f : 0.0f;
}

/* The plain-C bilinear alpha at uv (texel centres at (i + 1/2) / TEX,
 * repeated). */
static double ref_alpha(double u, double v) {
    const double x = u * TEX - 0.5, y = v * TEX - 0.5;
    const double fx = floor(x), fy = floor(y), ax = x - fx, ay = y - fy;
    double sum = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const int xi = (((int)fx + i) % TEX + TEX) % TEX,
                      yj = (((int)fy + j) % TEX + TEX) % TEX;
            sum += (i ? ax : 1 - ax) * (j ? ay : 1 - ay) * texel_alpha(xi, yj);
        }
    return sum;
}

/* The quad's alpha at uv: the factor times the texture's, if any. */
static double quad_alpha(const mask_case *mc, double u, double v) {
    return mc->factor * (mc->textured ? ref_alpha(u, v) : 1.0);
}

/* The quad spans [4, 12]^2 in x and z at QUAD_Y, uv (x - 4) / 8, (z - 4) / 8.
 * The alpha where the segment from a to b crosses its plane, or -1 where it
 * misses the quad. */
static double alpha_crossing(const mask_case *mc, const double a[3], const double b[3]) {
    if ((a[1] - QUAD_Y) * (b[1] - QUAD_Y) > 0.0)
        return -1.0;
    const double t = (QUAD_Y - a[1]) / (b[1] - a[1]);
    const double x = a[0] + t * (b[0] - a[0]), z = a[2] + t * (b[2] - a[2]);
    if (x < 4.0 || x > 12.0 || z < 4.0 || z > 12.0)
        return -1.0;
    return quad_alpha(mc, (x - 4.0) / 8.0, (z - 4.0) / 8.0);
}

/* Floor [0, 16]^2 at y = 0 (material 1) and the masked quad (material 0,
 * the checker's alpha, or no texture and alpha `factor` when untextured). */
static vct_scene *masked_scene(const mask_case *mc) {
    const float pos[] = {0, 0,      0, 0, 0,      16, 16, 0,      16, 16, 0,      0,
                         4, QUAD_Y, 4, 4, QUAD_Y, 12, 12, QUAD_Y, 12, 12, QUAD_Y, 4};
    const uint32_t tri[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}, mat[] = {1, 1, 0, 0};
    vct_material m[2] = {vct_material_default(), vct_material_default()};
    m[0].albedo[0] = m[0].albedo[1] = m[0].albedo[2] = 0.5f;
    m[0].alpha = mc->factor;
    m[0].alpha_cutoff = CUTOFF;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 8, tri, 4, mat, m, 2, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const float uv[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0};
    s->uvs = malloc(sizeof uv);
    memcpy(s->uvs, uv, sizeof uv);
    if (mc->textured) {
        s->textures = calloc(1, sizeof *s->textures);
        s->texture_count = 1;
        vct_texture *t = &s->textures[0];
        snprintf(t->name, sizeof t->name, "alpha checker");
        t->width = t->height = TEX;
        t->rgba = malloc(16 * TEX * TEX);
        for (int y = 0; y < TEX; ++y)
            for (int x = 0; x < TEX; ++x)
                for (int c = 0; c < 4; ++c)
                    t->rgba[4 * (y * TEX + x) + c] = c == 3 ? texel_alpha(x, y) : 1.0f;
        s->materials[0].albedo_texture = 1;
    }
    REQUIRE_OK(vct_scene_validate(s, &err), err);
    vct_light l = {VCT_LIGHT_POINT, {0}, {0}, {intensity, intensity, intensity}, 0, 0, 0};
    memcpy(l.position, light, sizeof light);
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, -1, 0}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, mc->sun ? &sun : &l, &err), err);
    const vct_camera cam = {{eye[0], eye[1], eye[2]}, {8, 0, 8}, {0, 0, -1}, 70.0f};
    s->camera = cam;
    s->has_camera = 1;
    return s;
}

typedef struct tally {
    int checked, quad, through, lit_through, shadowed, bad;
} tally;

/* One pixel that found p: what the plain-C answer says it shows. Returns -1
 * where the answer sits within a margin of the cutoff (left out), -2 where
 * nothing should be seen (a masked point). */
static double expected(const mask_case *mc, const double p[3], tally *t) {
    const double margin = 0.02;
    const double from[3] = {eye[0], eye[1], eye[2]};
    double to[3] = {light[0], light[1], light[2]}, lit;
    if (mc->sun) {
        to[0] = p[0], to[1] = p[1] + 100.0, to[2] = p[2];
        lit = 1.0; /* pi / pi */
    } else {
        const double d[3] = {to[0] - p[0], to[1] - p[1], to[2] - p[2]};
        const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        lit = intensity / CHECK_PI * (d[1] / dist) / (dist * dist);
    }
    if (fabs(p[1] - QUAD_Y) < 1e-3) { /* on the quad: it must be opaque there */
        const double a = quad_alpha(mc, (p[0] - 4.0) / 8.0, (p[2] - 4.0) / 8.0);
        if (fabs(a - CUTOFF) < margin)
            return -1.0;
        ++t->quad;
        return a >= CUTOFF ? 0.5 * lit : -2.0;
    }
    /* on the floor: the camera ray passed the quad, and so must the shadow ray */
    const double seen = alpha_crossing(mc, from, p), shade = alpha_crossing(mc, p, to);
    if ((seen >= 0.0 && fabs(seen - CUTOFF) < margin) ||
        (shade >= 0.0 && fabs(shade - CUTOFF) < margin))
        return -1.0;
    if (seen >= CUTOFF)
        return -2.0;
    t->through += seen >= 0.0;
    if (shade >= CUTOFF) {
        ++t->shadowed;
        return 0.0;
    }
    t->lit_through += shade >= 0.0;
    return 0.8 * lit;
}

static void check_pixels(const mask_case *mc) {
    const char *name = mc->name;
    vct_scene *s = masked_scene(mc);
    vct_error err = {0};
    vct_accel_options ao = {mc->kind, {0, 0, 0}, VCT_BVH_PLOC, VCT_BVH_LEVELS_AUTO};
    vct_accel *g = vct_accel_build(ctx, s, &ao, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_effect_force force[VCT_EFFECTS];
    for (int e = 0; e < VCT_EFFECTS; ++e)
        force[e] = VCT_FORCE_AUTO;
    force[VCT_EFFECT_INDIRECT] = VCT_FORCE_OFF;
    vct_plan plan;
    vct_plan_make(s, force, &plan);
    vct_vct_options o = vct_vct_options_default(512, 512);
    o.width = o.height = 72;
    o.aovs = 1;
    o.edge_samples = 1; /* the reference follows each pixel's centre */
    vct_image im;
    vct_aovs aovs;
    REQUIRE_OK(vct_render_vct(ctx, s, g, NULL, &plan, &o, &im, &aovs, &err), err);
    tally t = {0};
    double worst = 0.0;
    for (int i = 0; i < 72 * 72; ++i) {
        const float *pos = &aovs.position.rgba[4 * i];
        if (pos[3] == 0.0f)
            continue;
        const double p[3] = {pos[0], pos[1], pos[2]};
        const double want = expected(mc, p, &t);
        if (want == -1.0)
            continue;
        ++t.checked;
        const double got = aovs.direct.rgba[4 * i + 1];
        const double e = want < 0.0 ? INFINITY : fabs(got - want) / fmax(want, 1e-3);
        worst = fmax(worst, e);
        if (!(e < 1e-3) && t.bad++ < 3)
            CHECK(0, "%s: pixel %d at (%.3f %.3f %.3f): %.5f, expected %s %.5f", name, i, p[0],
                  p[1], p[2], got, want == -2.0 ? "nothing here (masked)," : "", want);
    }
    /* what each case must meet: both sides of the mask, or all of one */
    const int open = mc->factor < CUTOFF;
    const int met = mc->textured
                        ? t.quad > 50 && t.through > 50 && t.lit_through > 20 && t.shadowed > 20
                        : (open ? t.quad == 0 && t.through > 500 : t.through == 0 && t.quad > 500);
    CHECK(t.bad == 0 && t.checked > 3000 && met,
          "%s: %d of %d pixels off (%d on the quad, %d on the floor through it, %d of those lit "
          "through it, %d in its shadow)",
          name, t.bad, t.checked, t.quad, t.through, t.lit_through, t.shadowed);
    printf("%-40s %d pixels: %d on the quad, %d through its holes, %d lit through them, %d "
           "shadowed; worst relative error %.2g\n",
           name, t.checked, t.quad, t.through, t.lit_through, t.shadowed, worst);
    vct_image_release(&im);
    vct_aovs_release(&aovs);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* The floor's voxels (16^3 over [0, 16]^3): each lit by the point light
 * where the segment from its floor point to the light passes the mask
 * (injection's shadow rays go through the light's triangle bins). */
static void voxels_see_through(void) {
    const mask_case mc = {"voxels", VCT_ACCEL_BVH, 1, 0, 1.0f};
    vct_scene *s = masked_scene(&mc);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options o = {0};
    o.resolution = 16;
    o.has_bounds = 1;
    o.bounds_size = 16.0f;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, g, v, &err), err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    uint32_t *keys = malloc(4ull * info.voxels);
    float *radiance = malloc(16ull * info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, NULL, NULL, NULL, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, radiance, &err), err);
    int checked = 0, lit_through = 0, shadowed = 0, bad = 0;
    for (uint32_t i = 0; i < info.voxels; ++i) {
        uint32_t cell[3] = {0, 0, 0};
        for (int b = 0; b < 10; ++b)
            for (int k = 0; k < 3; ++k)
                cell[k] |= ((keys[i] >> (3 * b + k)) & 1u) << b;
        /* the quad's own voxels, and the floor's along its diagonal, which
         * hold both its triangles, each lit from its own nearest point */
        if (cell[1] != 0 || abs((int)cell[0] - (int)cell[2]) <= 1)
            continue;
        const double p[3] = {cell[0] + 0.5, 0.5, cell[2] + 0.5}, q[3] = {p[0], 0.0, p[2]};
        const double to[3] = {light[0], light[1], light[2]};
        const double a = alpha_crossing(&mc, q, to);
        if (a >= 0.0 && fabs(a - CUTOFF) < 0.05)
            continue;
        const double d[3] = {to[0] - p[0], to[1] - p[1], to[2] - p[2]};
        const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double want =
            a >= CUTOFF ? 0.0 : 0.8 / CHECK_PI * intensity * (d[1] / dist) / (dist * dist);
        lit_through += a >= 0.0 && a < CUTOFF;
        shadowed += a >= CUTOFF;
        ++checked;
        const double got = radiance[4 * i + 1];
        if (!(fabs(got - want) <= 1e-4 * want + 1e-7) && bad++ < 3)
            CHECK(0, "floor voxel (%u %u): radiance %g, expected %g (alpha %g on the way)", cell[0],
                  cell[2], got, want, a);
    }
    CHECK(bad == 0 && lit_through > 10 && shadowed > 10,
          "floor voxels: %d of %d off (%d lit through the mask, %d in its shadow)", bad, checked,
          lit_through, shadowed);
    printf("%-40s %d floor voxels: %d lit through the mask, %d in its shadow\n",
           "voxels under the mask", checked, lit_through, shadowed);
    /* The quad's voxels (the layers on both sides of y = 4): opacity is the
     * share of fragment_albedo.h's POINTS x POINTS points over the voxel that the mask
     * keeps (the quad's diagonal, where both triangles meet, left out). */
    float *albedo = malloc(16ull * info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, albedo, NULL, NULL, &err), err);
    int quad_voxels = 0, partial = 0, off = 0;
    for (uint32_t i = 0; i < info.voxels; ++i) {
        uint32_t cell[3] = {0, 0, 0};
        for (int b = 0; b < 10; ++b)
            for (int k = 0; k < 3; ++k)
                cell[k] |= ((keys[i] >> (3 * b + k)) & 1u) << b;
        if ((cell[1] != 3 && cell[1] != 4) || abs((int)cell[0] - (int)cell[2]) <= 1 ||
            cell[0] < 4 || cell[0] > 11 || cell[2] < 4 || cell[2] > 11)
            continue;
        int kept = 0;
        for (int j = 0; j < POINTS; ++j)
            for (int k = 0; k < POINTS; ++k) {
                const double x = cell[0] + (k + 0.5) / POINTS, z = cell[2] + (j + 0.5) / POINTS;
                kept += quad_alpha(&mc, (x - 4.0) / 8.0, (z - 4.0) / 8.0) >= CUTOFF;
            }
        const double want = kept / (double)(POINTS * POINTS), got = albedo[4 * i + 3];
        ++quad_voxels;
        partial += kept > 0 && kept < POINTS * POINTS;
        if (!(fabs(got - want) < 1e-5) && off++ < 3)
            CHECK(0, "quad voxel (%u %u %u): opacity %g, expected %g", cell[0], cell[1], cell[2],
                  got, want);
    }
    CHECK(off == 0 && quad_voxels > 50 && partial > 20,
          "quad voxels: %d of %d off (%d partly kept)", off, quad_voxels, partial);
    printf("%-40s %d quad voxels, %d partly kept, opacity = the share kept\n", "voxel opacity",
           quad_voxels, partial);
    free(albedo);
    free(keys);
    free(radiance);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    const mask_case cases[] = {
        {"alpha checker, BVH, point light", VCT_ACCEL_BVH, 1, 0, 1.0f},
        {"alpha checker, grid, point light", VCT_ACCEL_GRID, 1, 0, 1.0f},
        {"alpha checker, BVH, sun", VCT_ACCEL_BVH, 1, 1, 1.0f},
        {"alpha checker, grid, sun", VCT_ACCEL_GRID, 1, 1, 1.0f},
        /* no texture: the factor alone, below the cutoff (all passes) or not */
        {"alpha factor 0.3, no texture", VCT_ACCEL_BVH, 0, 0, 0.3f},
        {"alpha factor 0.7, no texture", VCT_ACCEL_BVH, 0, 0, 0.7f},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        check_pixels(&cases[i]);
    voxels_see_through();
    vct_context_release(ctx);
    return check_exit("test_alpha_mask");
}
