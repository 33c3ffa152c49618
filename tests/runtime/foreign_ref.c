/* The C library's side of the foreign-host test (foreign_host.py): runs the
 * scan, the voxelization and a cone trace through the library and writes
 * their inputs and results, raw and little-endian, into DIR, so that a host
 * of another language can run the kernels on its own buffers and compare.
 * Usage: foreign_ref SCENE DIR */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "runtime/runtime.h"
#include "scene/scene_device.h"
#include "vct_types.h"
#include "voxel/cones.h"
#include "voxel/voxels.h"

static const char *dir;

static void put(const char *name, const void *data, size_t bytes) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || (bytes && fwrite(data, 1, bytes, f) != bytes) || fclose(f) != 0) {
        fprintf(stderr, "foreign_ref: cannot write %s\n", path);
        exit(1);
    }
}

static void *device_copy(vct_context *ctx, cl_mem mem, size_t bytes) {
    vct_error err = {0};
    void *host = malloc(bytes ? bytes : 1);
    REQUIRE_OK(vct_buffer_read(ctx, "foreign", mem, 0, bytes, host, &err), err);
    return host;
}

/* An exclusive scan of n pseudo-random counts, input and output. */
static void scan(vct_context *ctx) {
    vct_error err = {0};
    const uint32_t n = 100003;
    uint32_t *in = malloc(4ull * n), *out = malloc(4ull * n);
    uint32_t state = 12345u;
    for (uint32_t i = 0; i < n; ++i) {
        state = state * 1664525u + 1013904223u;
        in[i] = state >> 22; /* 0 .. 1023 */
    }
    cl_mem a = vct_buffer_create(ctx, "foreign", "scan", 4ull * n, CL_MEM_READ_WRITE, in, &err);
    REQUIRE_OK(a ? VCT_OK : err.status, err);
    uint64_t total = 0;
    REQUIRE_OK(vct_scan_u32(ctx, a, a, n, 0, &total, &err), err);
    REQUIRE_OK(vct_buffer_read(ctx, "foreign", a, 0, 4ull * n, out, &err), err);
    put("scan_in.u32", in, 4ull * n);
    put("scan_out.u32", out, 4ull * n);
    vct_buffer_release(ctx, a);
    free(in);
    free(out);
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: foreign_ref SCENE DIR\n");
        return 2;
    }
    dir = argv[2];
    vct_error err = {0};
    vct_context *ctx = check_context();
    scan(ctx);

    vct_scene *s = vct_scene_load(argv[1], &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    put("positions.f32", s->positions, 12ull * s->vertex_count);
    put("triangles.u32", s->triangles, 12ull * s->triangle_count);
    put("triangle_material.u32", s->triangle_material, 4ull * s->triangle_count);
    vct_material_desc *m = calloc(s->material_count, sizeof *m);
    for (uint32_t i = 0; i < s->material_count; ++i)
        vct_material_desc_make(&s->materials[i], &m[i]);
    put("materials.desc", m, sizeof *m * s->material_count);
    free(m);

    /* Voxels, octree, bricks (a buffer pool, one isotropic radiance value per
     * sample) and injected light: what the cone kernel reads. */
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    const vct_voxel_options vo = {64, 0, 0, {0, 0, 0}, 0, 0, 0};
    vct_voxels *v = vct_voxelize(ctx, s, &vo, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, v, &err), err);
    const vct_brick_options bo = {VCT_BRICKS_BUFFER, 0, 1};
    REQUIRE_OK(vct_bricks_build(ctx, v, &bo, &err), err);
    REQUIRE_OK(vct_voxels_inject_light(ctx, s, g, v, &err), err);

    vct_volume_desc vol;
    vct_voxels_volume_desc(v, &vol);
    put("volume.desc", &vol, sizeof vol);
    const uint32_t nv = v->info.voxels;
    uint32_t *keys = malloc(4ull * nv);
    float *albedo = malloc(16ull * nv), *normal = malloc(16ull * nv),
          *emission = malloc(16ull * nv);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, albedo, normal, emission, &err), err);
    put("voxel_keys.u32", keys, 4ull * nv);
    put("voxel_albedo.f32", albedo, 16ull * nv);
    put("voxel_normal.f32", normal, 16ull * nv);
    const uint32_t counts[2] = {v->info.fragments, nv};
    put("voxel_counts.u32", counts, sizeof counts);

    const vct_cone_settings cs = vct_cone_settings_default();
    vct_cone_desc cd;
    vct_cone_desc_make(v, &cs, NULL, &cd);
    put("cone.desc", &cd, sizeof cd);
    void *radiance =
        device_copy(ctx, v->brick_buffer[VCT_BRICK_RADIANCE], v->brick_info.channel_bytes);
    put("bricks_radiance.f16", radiance, v->brick_info.channel_bytes);
    void *shade = device_copy(ctx, v->brick_buffer[VCT_BRICK_SHADE], v->brick_info.channel_bytes);
    put("bricks_shade.f16", shade, v->brick_info.channel_bytes);
    void *plane = device_copy(ctx, v->brick_buffer[VCT_BRICK_PLANE], v->brick_info.channel_bytes);
    put("bricks_plane.f16", plane, v->brick_info.channel_bytes);
    void *child = device_copy(ctx, v->child, 4ull * v->info.nodes);
    put("octree_child.u32", child, 4ull * v->info.nodes);
    /* Cones from points inside the box towards every direction of a grid. */
    enum { CONES = 512 };
    float *cones = malloc(32ull * CONES), *result = malloc(32ull * CONES);
    for (int i = 0; i < CONES; ++i) {
        float *c = cones + 8 * i;
        const float u = (i % 32 + 0.5f) / 32.0f, w = (i / 32 + 0.5f) / 16.0f;
        for (int k = 0; k < 3; ++k)
            c[k] = s->bounds_min[k] + (0.2f + 0.6f * (k == 0   ? u
                                                      : k == 1 ? w
                                                               : 0.5f)) *
                                          (s->bounds_max[k] - s->bounds_min[k]);
        c[3] = 0.1f + 0.5f * w;
        const float phi = 6.2831853f * u, z = 2.0f * w - 1.0f, r = sqrtf(1.0f - z * z);
        c[4] = r * cosf(phi);
        c[5] = r * sinf(phi);
        c[6] = z;
        c[7] = 1e30f;
    }
    REQUIRE_OK(vct_cone_trace(ctx, v, &cs, NULL, cones, CONES, result, &err), err);
    put("cones.f32", cones, 32ull * CONES);
    put("cone_results.f32", result, 32ull * CONES);
    printf("foreign_ref: scan, %u voxels from %u fragments, %d cones written to %s\n", nv,
           v->info.fragments, CONES, dir);
    free(cones), free(result), free(radiance), free(shade), free(plane), free(child);
    free(keys), free(albedo), free(normal), free(emission);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
    vct_context_release(ctx);
    return 0;
}
