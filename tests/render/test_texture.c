/* Base-colour textures: a PNG named by an OBJ's map_Kd is read and decoded
 * from sRGB; on a floor under a sun straight above, every pixel the camera
 * finds (cone tracing's primary pass, the ray caster's light) against a
 * plain-C bilinear sample of the checker at that point, with repeat and clamp
 * wrapping; the path tracer's mean against the ray caster's; and the voxels'
 * albedo against the checker's mean over each voxel, not one texel. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <stb/stb_image_write.h>

#include "check.h"
#include "vct_case.h"

#define TEX 8 /* texels per side */

static vct_context *ctx;

static float checker(int x, int y) {
    return ((x + y) & 1) ? 0.9f : 0.1f;
}

/* The plain-C bilinear sample of the checker at uv (texel centres at
 * (i + 1/2) / TEX), wrapped by repeat or clamp. */
static double ref_sample(double u, double v, int clamp_s, int clamp_t) {
    const double x = u * TEX - 0.5, y = v * TEX - 0.5;
    const double fx = floor(x), fy = floor(y), ax = x - fx, ay = y - fy;
    double sum = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            int xi = (int)fx + i, yj = (int)fy + j;
            xi = clamp_s ? (xi < 0 ? 0 : xi > TEX - 1 ? TEX - 1 : xi) : ((xi % TEX) + TEX) % TEX;
            yj = clamp_t ? (yj < 0 ? 0 : yj > TEX - 1 ? TEX - 1 : yj) : ((yj % TEX) + TEX) % TEX;
            sum += (i ? ax : 1 - ax) * (j ? ay : 1 - ay) * checker(xi, yj);
        }
    return sum;
}

/* A floor [0, 16]^2 at y = 0 whose uv runs over [0, reps]^2 + shift (u along x, v
 * along z), textured with the checker as material 0 with albedo factor 1. */
static vct_scene *floor_scene(float reps, uint32_t wrap, float shift) {
    const float pos[] = {0, 0, 0, 0, 0, 16, 16, 0, 16, 16, 0, 0};
    const uint32_t tri[] = {0, 1, 2, 0, 2, 3}, mat[] = {0, 0};
    vct_material m = vct_material_default();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.texture_wrap = wrap;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, 4, tri, 2, mat, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const float uv[] = {shift,        shift,        shift,        reps + shift,
                        reps + shift, reps + shift, reps + shift, shift};
    s->uvs = malloc(sizeof uv);
    memcpy(s->uvs, uv, sizeof uv);
    s->textures = calloc(1, sizeof *s->textures);
    s->texture_count = 1;
    vct_texture *t = &s->textures[0];
    snprintf(t->name, sizeof t->name, "checker");
    t->width = t->height = TEX;
    t->rgba = malloc(16 * TEX * TEX);
    for (int y = 0; y < TEX; ++y)
        for (int x = 0; x < TEX; ++x)
            for (int c = 0; c < 4; ++c)
                t->rgba[4 * (y * TEX + x) + c] = c == 3 ? 1.0f : checker(x, y);
    s->materials[0].albedo_texture = 1;
    REQUIRE_OK(vct_scene_validate(s, &err), err);
    /* a sun straight down, irradiance pi: radiance = albedo */
    const vct_light sun = {
        VCT_LIGHT_DIRECTIONAL, {0}, {0, -1, 0}, {3.14159265f, 3.14159265f, 3.14159265f}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    const vct_camera cam = {{8, 14, 8.01f}, {8, 0, 8}, {0, 0, -1}, 50.0f};
    s->camera = cam;
    s->has_camera = 1;
    return s;
}

static void pixels_against_reference(const char *name, float reps, uint32_t wrap) {
    vct_scene *s = floor_scene(reps, wrap, 0.0f);
    vct_plan plan;
    vct_case_direct_plan(s, &plan);
    vct_aovs aovs;
    vct_image im = vct_case_render(ctx, s, &plan, 16, 80, 80, 1, &aovs);
    int checked = 0, bad = 0;
    double worst = 0.0;
    for (int i = 0; i < 80 * 80; ++i) {
        const float *p = &aovs.position.rgba[4 * i];
        if (p[3] == 0.0f)
            continue;
        const double u = p[0] / 16.0 * reps, v = p[2] / 16.0 * reps;
        const double want = ref_sample(u, v, wrap & VCT_WRAP_CLAMP_S, wrap & VCT_WRAP_CLAMP_T);
        const double got = aovs.direct.rgba[4 * i + 1];
        const double e = fabs(got - want);
        worst = fmax(worst, e);
        if (!(e < 2e-3) && bad++ < 3)
            CHECK(0, "%s: pixel %d at uv (%.4f %.4f): %.5f, expected %.5f", name, i, u, v, got,
                  want);
        ++checked;
    }
    CHECK(checked > 5000 && bad == 0, "%s: %d of %d pixels off", name, bad, checked);
    printf("%-34s %d pixels, worst difference %.2g\n", name, checked, worst);
    vct_image_release(&im);
    vct_aovs_release(&aovs);
    vct_scene_release(s);
}

static double image_mean(const vct_image *im) {
    double sum = 0.0;
    for (int i = 0; i < im->width * im->height; ++i)
        sum += im->rgba[4 * i] + im->rgba[4 * i + 1] + im->rgba[4 * i + 2];
    return sum / (3.0 * im->width * im->height);
}

/* The path tracer reads the same texture: its direct light (depth 1) has
 * the ray caster's mean. */
static void path_tracer_agrees(void) {
    vct_scene *s = floor_scene(3.0f, 0, 0.0f);
    vct_error err = {0};
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_render_job job = vct_render_job_default(VCT_METHOD_RAYCAST, 64, 64);
    job.scene = s;
    job.accel = g;
    vct_image rc, pt;
    REQUIRE_OK(vct_render(ctx, &job, &rc, NULL, &err), err);
    job.method = VCT_METHOD_PATHTRACE;
    job.pathtrace.spp = 64;
    job.pathtrace.max_depth = 1;
    REQUIRE_OK(vct_render(ctx, &job, &pt, NULL, &err), err);
    const double ratio = image_mean(&pt) / image_mean(&rc);
    CHECK(fabs(ratio - 1.0) < 0.01, "path tracer mean %.4f of the ray caster's", ratio);
    printf("path tracer, direct only: mean %.4f of the ray caster's\n", ratio);
    vct_image_release(&rc);
    vct_image_release(&pt);
    vct_accel_release(g);
    vct_scene_release(s);
}

/* The floor through voxel centres at 16^3 with 4 checker texels per voxel
 * side: each voxel's albedo is the bilinear checker's mean over the voxel
 * (0.5), where one texel would give 0.1 or 0.9. */
static void voxel_albedo_is_a_mean(void) {
    /* 8 repeats of 8 texels over 16 voxels, shifted off the texel corners
     * (where one bilinear sample would happen to be the mean) */
    const float shift = 0.37f / TEX;
    vct_scene *s = floor_scene(8.0f, 0, shift);
    vct_error err = {0};
    vct_voxel_options o = {0};
    o.resolution = 16;
    o.has_bounds = 1;
    o.bounds_min[1] = -8.5f; /* the floor through the centres of voxel layer 8 */
    o.bounds_size = 16.0f;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    uint32_t *keys = malloc(4ull * info.voxels);
    float *albedo = malloc(16ull * info.voxels);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, albedo, NULL, NULL, &err), err);
    int checked = 0, bad = 0;
    double worst = 0.0;
    for (uint32_t i = 0; i < info.voxels; ++i) {
        uint32_t cell[3] = {0, 0, 0};
        for (int b = 0; b < 10; ++b)
            for (int k = 0; k < 3; ++k)
                cell[k] |= ((keys[i] >> (3 * b + k)) & 1u) << b;
        /* the reference: 32 x 32 points of the voxel's square on the floor */
        double want = 0.0;
        for (int j = 0; j < 32; ++j)
            for (int k = 0; k < 32; ++k) {
                const double x = cell[0] + (k + 0.5) / 32, z = cell[2] + (j + 0.5) / 32;
                want += ref_sample(x / 16 * 8 + shift, z / 16 * 8 + shift, 0, 0) / 1024.0;
            }
        const double e = fabs(albedo[4 * i] - want);
        worst = fmax(worst, e);
        bad += !(e < 0.02);
        ++checked;
    }
    CHECK(checked == 256 && bad == 0, "voxel albedo: %d of %d voxels off the mean, worst %.3f", bad,
          checked, worst);
    printf("voxel albedo: %d voxels, worst difference from the mean %.4f\n", checked, worst);
    free(keys);
    free(albedo);
    vct_voxels_release(v);
    vct_scene_release(s);
}

/* An OBJ whose MTL names a PNG by map_Kd: read, decoded from sRGB. */
static void obj_map_kd(void) {
    char dir[] = "/tmp/vct-texture-XXXXXX", path[96];
    if (!mkdtemp(dir))
        exit(1);
    const unsigned char px[4 * 3] = {255, 128, 0, 255, 0, 64, 255, 255, 10, 10, 10, 255};
    snprintf(path, sizeof path, "%s/t.png", dir);
    CHECK(stbi_write_png(path, 3, 1, 4, px, 12) != 0, "writing %s", path);
    snprintf(path, sizeof path, "%s/t.mtl", dir);
    FILE *f = fopen(path, "w");
    fputs("newmtl tex\nKd 1 1 1\nmap_Kd t.png\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/t.obj", dir);
    f = fopen(path, "w");
    fputs("mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl tex\n"
          "f 1/1 2/2 3/3\n",
          f);
    fclose(f);
    vct_error err = {0};
    vct_scene *s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const vct_material *tex = NULL;
    for (uint32_t m = 0; m < s->material_count; ++m)
        tex = strcmp(s->materials[m].name, "tex") == 0 ? &s->materials[m] : tex;
    CHECK(s->texture_count == 1 && tex && tex->albedo_texture == 1 && s->uvs,
          "map_Kd: %u textures, material texture %u", s->texture_count,
          tex ? tex->albedo_texture : 0);
    if (s->texture_count == 1) {
        const float *t = s->textures[0].rgba;
        /* sRGB 128 is linear 0.2158605; 10 is 0.0030353 */
        CHECK(s->textures[0].width == 3 && t[0] == 1.0f && fabsf(t[1] - 0.2158605f) < 1e-6f &&
                  t[2] == 0.0f && fabsf(t[8] - 0.0030353f) < 1e-6f && t[3] == 1.0f,
              "decoded texels (%g %g %g %g), (%g)", t[0], t[1], t[2], t[3], t[8]);
    }
    vct_scene_release(s);
    /* the same without texture coordinates: every point reads uv (0, 0), the
     * same colour everywhere, and nothing past the buffers */
    snprintf(path, sizeof path, "%s/t.obj", dir);
    f = fopen(path, "w");
    fputs("mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\nusemtl tex\nf 1 2 3\n", f);
    fclose(f);
    s = vct_scene_load(path, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    const vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0}, {0, -1, 0}, {1, 1, 1}, 0, 0, 0};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    const vct_camera above = {{0.3f, 2, 0.3f}, {0.3f, 0, 0.3f}, {0, 0, -1}, 20.0f};
    s->camera = above;
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_render_job job = vct_render_job_default(VCT_METHOD_RAYCAST, 16, 16);
    job.scene = s;
    job.accel = g;
    vct_image im;
    REQUIRE_OK(vct_render(ctx, &job, &im, NULL, &err), err);
    int lit = 0, differ = 0;
    float first = -1.0f;
    for (int i = 0; i < 16 * 16; ++i) {
        const float r = im.rgba[4 * i];
        if (!(r > 0.0f))
            continue;
        first = first < 0.0f ? r : first;
        differ += r != first;
        ++lit;
    }
    CHECK(lit > 20 && differ == 0, "no coordinates: %d pixels lit, %d of another colour", lit,
          differ);
    vct_image_release(&im);
    vct_accel_release(g);
    vct_scene_release(s);
    /* a missing image is refused, naming it */
    snprintf(path, sizeof path, "%s/t.png", dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/t.obj", dir);
    s = vct_scene_load(path, &err);
    CHECK(!s && strstr(err.message, "t.png"), "missing texture: %s", s ? "loaded" : err.message);
    vct_scene_release(s);
    snprintf(path, sizeof path, "%s/t.mtl", dir);
    unlink(path);
    snprintf(path, sizeof path, "%s/t.obj", dir);
    unlink(path);
    rmdir(dir);
}

int main(void) {
    ctx = check_context();
    obj_map_kd();
    pixels_against_reference("checker, repeated 3 times", 3.0f, 0);
    pixels_against_reference("checker, clamped beyond [0, 1]", 1.6f,
                             VCT_WRAP_CLAMP_S | VCT_WRAP_CLAMP_T);
    path_tracer_agrees();
    voxel_albedo_is_a_mean();
    vct_context_release(ctx);
    return check_exit("test_texture");
}
