/* Test scaffolding shared by the brick and cone tests: a voxelized, lit,
 * bricked scene read back into plain arrays, and the octree lookup and
 * trilinear interpolation of the plain-C reference. */
#ifndef VCT_TEST_BRICK_CASE_H
#define VCT_TEST_BRICK_CASE_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "brick_ref.h"
#include "check.h"
#include "mesh_gen.h"

static vct_context *ctx;

typedef struct brick_case {
    const char *name;
    vct_scene *scene;
    vct_accel *accel;
    vct_voxels *voxels;
    vct_voxel_info info;
    vct_brick_info bricks;
    uint32_t *child, *cell; /* per node: child pointer, cell (x | y << 10 | z << 20) */
    int32_t *voxel_of;      /* dense res^3 -> voxel */
    float *albedo, *normal, *radiance;
    float *sides; /* 8 per voxel: vct_voxels_read_sides (0 before light injection) */
} brick_case;

static void case_free(brick_case *c) {
    vct_voxels_release(c->voxels);
    vct_accel_release(c->accel);
    vct_scene_release(c->scene);
    free(c->child);
    free(c->cell);
    free(c->voxel_of);
    free(c->albedo);
    free(c->normal);
    free(c->radiance);
    free(c->sides);
}

static void decode(uint32_t key, uint32_t cell[3]) {
    cell[0] = cell[1] = cell[2] = 0;
    for (int b = 0; b < 10; ++b)
        for (int k = 0; k < 3; ++k)
            cell[k] |= ((key >> (3 * b + k)) & 1u) << b;
}

/* Builds everything for `scene` in [0, side]^3 and reads back what the
 * reference needs. */
static brick_case make_case(const char *name, vct_scene *scene, uint32_t res, float side,
                            const vct_brick_options *opt) {
    vct_error err = {0};
    brick_case c = {0};
    c.name = name;
    c.scene = scene;
    vct_voxel_options o = {0};
    o.resolution = res;
    o.has_bounds = 1;
    o.bounds_size = side;
    /* every voxel gathers its bounces, as test_cone's reference does
     * (test_bounce_fill checks the sparse fill) */
    o.dense_bounces = 1;
    c.voxels = vct_voxelize(ctx, scene, &o, &err);
    REQUIRE_OK(c.voxels ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_octree_build(ctx, c.voxels, &err), err);
    REQUIRE_OK(vct_bricks_build(ctx, c.voxels, opt, &err), err);
    if (scene->light_count) {
        c.accel = vct_accel_build(ctx, scene, NULL, &err);
        REQUIRE_OK(c.accel ? VCT_OK : err.status, err);
        REQUIRE_OK(vct_voxels_inject_light(ctx, scene, c.accel, c.voxels, &err), err);
    }
    vct_voxels_info_get(c.voxels, &c.info);
    CHECK(vct_bricks_info_get(c.voxels, &c.bricks), "%s: brick info", name);
    const uint32_t nv = c.info.voxels, nodes = c.info.nodes;
    uint32_t *keys = malloc(4ull * nv + 4);
    c.albedo = malloc(16ull * nv + 16);
    c.normal = malloc(16ull * nv + 16);
    c.radiance = calloc(4ull * nv + 4, sizeof(float));
    c.sides = calloc(8ull * nv + 8, sizeof(float));
    REQUIRE_OK(vct_voxels_read(ctx, c.voxels, keys, c.albedo, c.normal, NULL, &err), err);
    if (scene->light_count) {
        REQUIRE_OK(vct_voxels_read_radiance(ctx, c.voxels, c.radiance, &err), err);
        REQUIRE_OK(vct_voxels_read_sides(ctx, c.voxels, c.sides, &err), err);
    }
    c.voxel_of = malloc(4ull * res * res * res);
    memset(c.voxel_of, 0xff, 4ull * res * res * res);
    for (uint32_t v = 0; v < nv; ++v) {
        uint32_t p[3];
        decode(keys[v], p);
        c.voxel_of[((size_t)p[2] * res + p[1]) * res + p[0]] = (int32_t)v;
    }
    free(keys);
    c.child = malloc(4ull * nodes);
    c.cell = calloc(nodes, 4);
    REQUIRE_OK(vct_octree_read(ctx, c.voxels, c.child, NULL, &err), err);
    for (uint32_t n = 0; n < nodes && nv; ++n) { /* parents come before children */
        if (n >= c.info.level_start[c.info.levels] || c.child[n] == VCT_NODE_NULL)
            continue;
        for (uint32_t o = 0; o < 8; ++o) {
            const uint32_t p = c.cell[n];
            const uint32_t x = 2 * (p & 1023) + (o & 1), y = 2 * ((p >> 10) & 1023) + (o >> 1 & 1);
            const uint32_t z = 2 * (p >> 20) + (o >> 2);
            c.cell[c.child[n] + o] = x | y << 10 | z << 20;
        }
    }
    return c;
}

static float *opacities(const brick_case *c) {
    float *a = malloc(4ull * c->info.voxels + 4);
    for (uint32_t v = 0; v < c->info.voxels; ++v)
        a[v] = c->albedo[4 * v + 3];
    return a;
}

static uint32_t node_at(const brick_case *c, const uint32_t cell[3], uint32_t level) {
    uint32_t node = 0;
    for (uint32_t l = 1; l <= level; ++l) {
        if (c->child[node] == VCT_NODE_NULL)
            return VCT_NODE_NULL;
        const uint32_t s = level - l;
        node = c->child[node] +
               (((cell[0] >> s) & 1) | ((cell[1] >> s) & 1) << 1 | ((cell[2] >> s) & 1) << 2);
    }
    return node;
}

/* Trilinear interpolation of lattice `lat` at lattice coordinates p; the
 * spread (max - min) of the 8 values it mixes goes to `spread` if given. */
static void ref_trilinear_spread(const ref_lattice *lat, const double p[3], double out[4],
                                 double spread[4]) {
    int64_t lo[3];
    double f[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = (int64_t)fmin(floor(p[k]), lat->n - 2.0);
        f[k] = p[k] - (double)lo[k];
    }
    double lo_v[4] = {INFINITY, INFINITY, INFINITY, INFINITY},
           hi_v[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < 4; ++k)
        out[k] = 0.0;
    for (int d = 0; d < 8; ++d) {
        const int dx = d & 1, dy = d >> 1 & 1, dz = d >> 2;
        const double w = (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
        const float *v = ref_at(lat, lo[0] + dx, lo[1] + dy, lo[2] + dz);
        for (int k = 0; k < 4; ++k) {
            out[k] += w * v[k];
            lo_v[k] = fmin(lo_v[k], v[k]);
            hi_v[k] = fmax(hi_v[k], v[k]);
        }
    }
    for (int k = 0; spread && k < 4; ++k)
        spread[k] = hi_v[k] - lo_v[k];
}

static inline void ref_trilinear(const ref_lattice *lat, const double p[3], double out[4]) {
    ref_trilinear_spread(lat, p, out, NULL);
}

static vct_scene *scene_of(const test_mesh *m, const vct_material *mats, uint32_t nmat) {
    uint32_t *mat = malloc(4ull * m->nt);
    for (uint32_t t = 0; t < m->nt; ++t)
        mat[t] = t % nmat;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(m->pos, m->nv, m->tri, m->nt, mat, mats, nmat, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(mat);
    return s;
}

static vct_scene *quads_scene(const float *quads, uint32_t count) {
    test_mesh m = mesh_quads(quads, count);
    vct_material white = vct_material_default();
    vct_scene *s = scene_of(&m, &white, 1);
    mesh_free(&m);
    return s;
}

static void add_point_light(vct_scene *s, float x, float y, float z, float power) {
    vct_light l = {VCT_LIGHT_POINT, {x, y, z}, {0}, {power, power, power}, 0, 0, 0};
    vct_error err = {0};
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
}

static vct_material soup_material(int i) {
    vct_material m = vct_material_default();
    m.albedo[0] = 0.2f + 0.15f * (float)(i % 5);
    m.albedo[1] = 0.9f - 0.2f * (float)(i % 4);
    m.albedo[2] = 0.1f * (float)(i + 1);
    m.transmission = i == 2 ? 0.6f : 0.0f; /* one half-transparent material */
    return m;
}

#endif
