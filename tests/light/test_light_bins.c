/* Light-space triangle bins (kernels/light/light_bins.cl) against a plain-C
 * reference: every triangle that a ray from a binned light hits, found in
 * double precision over all triangles, must sit in the cell of the ray's
 * direction, with a distance quantum no farther than the hit. Then light
 * injection through the bins must give the grid's radiance bit for bit,
 * and a light inside a closed sphere must leave everything outside dark.
 * Scenes: a triangle soup with slivers and degenerate triangles, plus
 * triangles through the light, a hair from it, across cube faces and edge-on
 * to it, near the origin and a hundred thousand units away. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "runtime/runtime.h"
#include "light/light_bins_host.h"
#include "mesh_gen.h"
#include "vct_types.h"
#include "voxel/voxels.h"

static vct_context *ctx;

typedef struct mesh_builder {
    float *pos;
    uint32_t *tri;
    uint32_t nv, nt;
} mesh_builder;

static void add_triangle(mesh_builder *b, const float v[9]) {
    b->pos = realloc(b->pos, 12ull * (b->nv + 3));
    b->tri = realloc(b->tri, 12ull * (b->nt + 1));
    memcpy(b->pos + 3ull * b->nv, v, 36);
    for (int k = 0; k < 3; ++k)
        b->tri[3ull * b->nt + k] = b->nv + (uint32_t)k;
    b->nv += 3;
    b->nt += 1;
}

static void add_mesh(mesh_builder *b, const test_mesh *m) {
    for (uint32_t t = 0; t < m->nt; ++t) {
        float v[9];
        for (int c = 0; c < 3; ++c)
            memcpy(v + 3 * c, m->pos + 3ull * m->tri[3 * t + c], 12);
        add_triangle(b, v);
    }
}

/* The hard triangles around light position l (offset by o). */
static void add_hard_triangles(mesh_builder *b, const float l[3]) {
    const float rel[][9] = {
        {-0.2f, -0.1f, 0.0f, 0.3f, -0.1f, 0.0f, 0.0f, 0.2f, 0.0f},         /* through the light */
        {-0.2f, -0.1f, 1e-5f, 0.3f, -0.1f, 1e-5f, 0.0f, 0.2f, 1e-5f},      /* a hair above it */
        {0.3f, -0.4f, -0.4f, 0.3f, 0.4f, -0.4f, 0.3f, 0.0f, 0.5f},         /* across 3+ faces */
        {0.2f, 0.2f, 0.05f, 0.25f, 0.25f, -0.05f, 0.2f, 0.21f, 0.0f},      /* on a face edge */
        {0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f, 0.3f, 0.3f, 0.25f},           /* edge-on */
        {-0.45f, 0.45f, 0.45f, -0.45f, -0.45f, 0.45f, 0.45f, 0.0f, 0.45f}, /* big, overhead */
    };
    for (size_t t = 0; t < sizeof rel / sizeof rel[0]; ++t) {
        float v[9];
        for (int k = 0; k < 9; ++k)
            v[k] = rel[t][k] + l[k % 3];
        add_triangle(b, v);
    }
    /* Triangles whose corners project onto cell borders (multiples of 1/8
     * in face coordinates) and the faces' edges, on every face. */
    uint64_t seed = 3;
    for (int t = 0; t < 120; ++t) {
        const int axis = t % 3, sign = (t / 3) % 2 ? -1 : 1;
        const float r = 0.1f + 0.3f * check_randf(&seed);
        const float u0 = (float)(int)(check_randf(&seed) * 16.0f) / 8.0f - 1.0f;
        const float v0 = (float)(int)(check_randf(&seed) * 16.0f) / 8.0f - 1.0f;
        const float corner[3][2] = {{u0, v0}, {u0 + 0.125f, v0}, {u0, v0 + 0.125f}};
        float v[9];
        for (int c = 0; c < 3; ++c) {
            v[3 * c + axis] = l[axis] + sign * r;
            v[3 * c + (axis + 1) % 3] = l[(axis + 1) % 3] + r * corner[c][0];
            v[3 * c + (axis + 2) % 3] = l[(axis + 2) % 3] + r * corner[c][1];
        }
        add_triangle(b, v);
    }
}

static vct_scene *make_scene(float offset, uint64_t seed, const float light[3]) {
    mesh_builder b = {0};
    test_mesh soup = mesh_soup(1500, offset, seed);
    add_mesh(&b, &soup);
    mesh_free(&soup);
    add_hard_triangles(&b, light);
    uint32_t *mat = calloc(b.nt, 4);
    vct_material m = vct_material_default();
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(b.pos, b.nv, b.tri, b.nt, mat, &m, 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    free(b.pos);
    free(b.tri);
    free(mat);
    return s;
}

/* The documented cell of unit direction w: face 2 * axis + (w[axis] < 0), u
 * and v the next two components over |w[axis]|, F cells over [-1, 1]. */
static uint32_t reference_cell(const float w[3], uint32_t face_res, uint32_t first) {
    const float a[3] = {fabsf(w[0]), fabsf(w[1]), fabsf(w[2])};
    const int axis = (a[0] >= a[1] && a[0] >= a[2]) ? 0 : (a[1] >= a[2] ? 1 : 2);
    const uint32_t face = 2u * (uint32_t)axis + (w[axis] < 0.0f);
    int c[2];
    for (int k = 0; k < 2; ++k) {
        const float u = w[(axis + 1 + k) % 3] / a[axis];
        c[k] = (int)floorf((u + 1.0f) * 0.5f * (float)face_res);
        c[k] = c[k] < 0 ? 0 : (c[k] >= (int)face_res ? (int)face_res - 1 : c[k]);
    }
    return first + (face * face_res + (uint32_t)c[1]) * face_res + (uint32_t)c[0];
}

/* Distance along the ray from l along w to triangle t, or -1 (closed
 * triangle, double precision Moller-Trumbore). */
static double reference_hit(const vct_scene *s, uint32_t t, const double l[3], const double w[3]) {
    double v[3][3];
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            v[c][k] = s->positions[3ull * s->triangles[3ull * t + c] + k];
    double e1[3], e2[3], p[3], q[3], tv[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = v[1][k] - v[0][k];
        e2[k] = v[2][k] - v[0][k];
        tv[k] = l[k] - v[0][k];
    }
    p[0] = w[1] * e2[2] - w[2] * e2[1];
    p[1] = w[2] * e2[0] - w[0] * e2[2];
    p[2] = w[0] * e2[1] - w[1] * e2[0];
    const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0)
        return -1.0;
    const double u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) / det;
    q[0] = tv[1] * e1[2] - tv[2] * e1[1];
    q[1] = tv[2] * e1[0] - tv[0] * e1[2];
    q[2] = tv[0] * e1[1] - tv[1] * e1[0];
    const double vv = (w[0] * q[0] + w[1] * q[1] + w[2] * q[2]) / det;
    const double d = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return (u >= 0.0 && vv >= 0.0 && u + vv <= 1.0 && d > 0.0) ? d : -1.0;
}

typedef struct bins_host {
    vct_light_bins_desc *desc;
    uint32_t *ranges, *keys, *tris;
    uint64_t cells;
} bins_host;

static bins_host bins_read(const vct_scene *s, const vct_light_bins *b) {
    vct_error err = {0};
    bins_host h = {0};
    h.desc = calloc(s->light_count + 1, sizeof *h.desc);
    h.cells = 6ull * b->face_res * b->face_res * b->lights;
    h.ranges = malloc(8ull * (h.cells ? h.cells : 1));
    h.keys = malloc(4ull * (b->entries ? b->entries : 1));
    h.tris = malloc(4ull * (b->entries ? b->entries : 1));
    REQUIRE_OK(
        vct_buffer_read(ctx, "test", b->desc, 0, sizeof *h.desc * s->light_count, h.desc, &err),
        err);
    REQUIRE_OK(vct_buffer_read(ctx, "test", b->ranges, 0, 8ull * h.cells, h.ranges, &err), err);
    REQUIRE_OK(vct_buffer_read(ctx, "test", b->keys, 0, 4ull * b->entries, h.keys, &err), err);
    REQUIRE_OK(vct_buffer_read(ctx, "test", b->tris, 0, 4ull * b->entries, h.tris, &err), err);
    return h;
}

static void bins_free(bins_host *h) {
    free(h->desc);
    free(h->ranges);
    free(h->keys);
    free(h->tris);
}

/* One ray from light i along w: every triangle hit must be listed in its
 * cell no farther than the hit. Returns the hits checked. */
static int check_ray(const char *name, const vct_scene *s, const bins_host *h, uint32_t i,
                     const float wf[3], int *missing) {
    const vct_light_bins_desc d = h->desc[i];
    const double l[3] = {d.light.s[0], d.light.s[1], d.light.s[2]};
    const double w[3] = {wf[0], wf[1], wf[2]};
    const uint32_t cell = reference_cell(wf, d.info.s[1], d.info.s[0]);
    const uint32_t bits = d.info.s[2], low = (1u << bits) - 1u;
    const uint32_t start = h->ranges[2 * cell], end = h->ranges[2 * cell + 1];
    int hits = 0;
    for (uint32_t t = 0; t < s->triangle_count; ++t) {
        const double at = reference_hit(s, t, l, w);
        if (at < 0.0)
            continue;
        ++hits;
        const double quantum = floor(at * d.light.s[3]);
        int found = 0;
        for (uint32_t k = start; k < end && !found; ++k)
            found = h->tris[k] == t && (double)(h->keys[k] & low) <= quantum;
        if (!found && (*missing)++ < 5)
            CHECK(0, "%s: light %u, direction (%g %g %g): triangle %u hit at %g is not in cell %u",
                  name, i, w[0], w[1], w[2], t, at, cell);
    }
    return hits;
}

static void normalize3(float w[3]) {
    const float n = sqrtf(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (int k = 0; k < 3; ++k)
        w[k] /= n;
}

static void check_bins(const char *name, float offset, uint32_t face_res) {
    const float light[3] = {offset + 0.5f, offset + 0.45f, offset + 0.55f};
    vct_scene *s = make_scene(offset, 7, light);
    vct_error err = {0};
    const vct_light point = {
        VCT_LIGHT_POINT, {light[0], light[1], light[2]}, {0}, {1, 1, 1}, 0, 0, 0};
    const vct_light spot = {VCT_LIGHT_SPOT,
                            {offset + 1.3f, offset + 1.2f, offset - 0.2f},
                            {-0.6f, -0.6f, 0.53f},
                            {1, 1, 1},
                            0.3f,
                            0.6f,
                            0};
    const vct_light sun = {VCT_LIGHT_DIRECTIONAL, {0}, {0, 0, -1}, {1, 1, 1}, 0, 0, 0};
    const vct_light soft = {
        VCT_LIGHT_POINT, {light[0], light[1], light[2]}, {0}, {1, 1, 1}, 0, 0, 0.1f};
    REQUIRE_OK(vct_scene_add_light(s, &sun, &err), err);
    REQUIRE_OK(vct_scene_add_light(s, &point, &err), err);
    REQUIRE_OK(vct_scene_add_light(s, &soft, &err), err);
    REQUIRE_OK(vct_scene_add_light(s, &spot, &err), err);
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_light_bins b;
    const vct_light_bins_options bo = {1, face_res, 0};
    REQUIRE_OK(vct_light_bins_build(ctx, s, g, &bo, "test", &b, &err), err);
    bins_host h = bins_read(s, &b);

    CHECK(b.lights == 2, "%s: %u lights binned, expected the point and the spot", name, b.lights);
    const uint32_t per = 6u * b.face_res * b.face_res;
    CHECK(!h.desc[0].info.s[3] && !h.desc[2].info.s[3] && h.desc[1].info.s[3] &&
              h.desc[3].info.s[3] && h.desc[1].info.s[0] == 0 && h.desc[3].info.s[0] == per,
          "%s: the directional and the soft light keep to the grid; the others' cells follow "
          "one another",
          name);
    int order = 1, placed = 1;
    const uint32_t bits = h.desc[1].info.s[2];
    for (uint32_t k = 0; k < b.entries; ++k) {
        const uint32_t cell = h.keys[k] >> bits;
        order &= k == 0 || h.keys[k - 1] <= h.keys[k];
        placed &= cell < h.cells && h.ranges[2 * cell] <= k && k < h.ranges[2 * cell + 1];
    }
    CHECK(order && placed, "%s: keys sorted (%d) and inside their cells' ranges (%d)", name, order,
          placed);

    int hits = 0, missing = 0, rays = 0;
    uint64_t seed = 99;
    for (uint32_t i = 1; i < 4; i += 2) {
        const float *l = h.desc[i].light.s;
        /* Random directions, then every triangle's vertices, edge
         * midpoints and centroid: rays that graze or hit for certain. */
        for (int r = 0; r < 3000; ++r, ++rays) {
            float w[3] = {2 * check_randf(&seed) - 1, 2 * check_randf(&seed) - 1,
                          2 * check_randf(&seed) - 1};
            if (w[0] == 0 && w[1] == 0 && w[2] == 0)
                continue;
            normalize3(w);
            hits += check_ray(name, s, &h, i, w, &missing);
        }
        for (uint32_t t = 0; t < s->triangle_count; t += 3) {
            const float *v[3];
            for (int c = 0; c < 3; ++c)
                v[c] = s->positions + 3ull * s->triangles[3ull * t + c];
            const float weights[7][3] = {{1, 0, 0},
                                         {0, 1, 0},
                                         {0, 0, 1},
                                         {0.5f, 0.5f, 0},
                                         {0, 0.5f, 0.5f},
                                         {0.5f, 0, 0.5f},
                                         {1 / 3.0f, 1 / 3.0f, 1 / 3.0f}};
            for (int p = 0; p < 7; ++p, ++rays) {
                float w[3];
                for (int k = 0; k < 3; ++k)
                    w[k] = weights[p][0] * v[0][k] + weights[p][1] * v[1][k] +
                           weights[p][2] * v[2][k] - l[k];
                if (w[0] == 0 && w[1] == 0 && w[2] == 0)
                    continue;
                normalize3(w);
                hits += check_ray(name, s, &h, i, w, &missing);
            }
        }
    }
    CHECK(missing == 0 && hits > 1000, "%s: %d hits of %d rays, %d not in their cell", name, hits,
          rays, missing);
    printf("%-36s F %3u, %6u entries: %d rays, %d hits, all listed: %s\n", name, b.face_res,
           b.entries, rays, hits, missing ? "no" : "yes");
    bins_free(&h);
    vct_light_bins_release(ctx, &b);
    vct_accel_release(g);
    vct_scene_release(s);
}

static float *inject_with(const vct_scene *s, const vct_accel *g, vct_voxels *v,
                          const vct_light_bins_options *bins, uint32_t n) {
    vct_error err = {0};
    float *r = malloc(16ull * n);
    REQUIRE_OK(vct_voxels_inject_light_with(ctx, s, g, v, bins, &err), err);
    REQUIRE_OK(vct_voxels_read_radiance(ctx, v, r, &err), err);
    return r;
}

/* Injection through the bins against the grid: the same bits. With
 * `sphere`, the light sits inside a closed icosphere around the soup's
 * centre and every voxel outside it must stay dark. */
static void check_injection(const char *name, float offset, int sphere) {
    const float light[3] = {offset + 0.5f, offset + 0.45f, offset + 0.55f};
    vct_scene *s = make_scene(offset, 11, light);
    if (sphere) {
        vct_scene_release(s);
        mesh_builder b = {0};
        const float centre[3] = {light[0], light[1], light[2]};
        test_mesh ball = mesh_icosphere(3, 0.3f, centre), soup = mesh_soup(800, offset, 5);
        add_mesh(&b, &ball);
        add_mesh(&b, &soup);
        mesh_free(&ball);
        mesh_free(&soup);
        uint32_t *mat = calloc(b.nt, 4);
        vct_material m = vct_material_default();
        vct_error e = {0};
        s = vct_scene_from_arrays(b.pos, b.nv, b.tri, b.nt, mat, &m, 1, &e);
        REQUIRE_OK(s ? VCT_OK : e.status, e);
        free(b.pos);
        free(b.tri);
        free(mat);
    }
    vct_error err = {0};
    const vct_light point = {
        VCT_LIGHT_POINT, {light[0], light[1], light[2]}, {0}, {1, 1, 1}, 0, 0, 0};
    const vct_light spot = {VCT_LIGHT_SPOT,
                            {offset + 0.1f, offset + 0.9f, offset + 0.95f},
                            {0.5f, -0.5f, -0.7f},
                            {2, 2, 2},
                            0.5f,
                            0.9f,
                            0};
    REQUIRE_OK(vct_scene_add_light(s, &point, &err), err);
    if (!sphere)
        REQUIRE_OK(vct_scene_add_light(s, &spot, &err), err);
    vct_accel *g = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(g ? VCT_OK : err.status, err);
    vct_voxel_options o = {0};
    o.resolution = 32;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    REQUIRE_OK(v ? VCT_OK : err.status, err);
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    const uint32_t n = info.voxels;
    /* bins, the grid, and bins over a budget of 10 entries (the grid again) */
    const vct_light_bins_options binned = {1, 8, 0}, grid_only = {0, 0, 0}, over = {1, 8, 10};
    float *with_bins = inject_with(s, g, v, &binned, n),
          *with_grid = inject_with(s, g, v, &grid_only, n),
          *fallback = inject_with(s, g, v, &over, n);
    CHECK(memcmp(with_grid, fallback, 16ull * n) == 0,
          "%s: bins over their budget fall back to the grid's radiance", name);
    vct_light_bins b;
    vct_error berr = {0};
    REQUIRE_OK(vct_light_bins_build(ctx, s, g, &over, "test", &b, &berr), berr);
    CHECK(b.lights == 0 && b.entries == 0, "%s: over budget, no light binned (%u)", name, b.lights);
    vct_light_bins_release(ctx, &b);
    uint32_t differ = 0, lit = 0, leaks = 0;
    uint32_t *keys = malloc(4ull * n);
    REQUIRE_OK(vct_voxels_read(ctx, v, keys, NULL, NULL, NULL, &err), err);
    const double *origin = info.origin, size = info.side;
    for (uint32_t i = 0; i < n; ++i) {
        differ += memcmp(with_bins + 4ull * i, with_grid + 4ull * i, 16) != 0;
        lit += with_bins[4ull * i] > 0.0f;
        if (sphere) {
            uint32_t c[3] = {0, 0, 0};
            for (int bit = 0; bit < 10; ++bit)
                for (int k = 0; k < 3; ++k)
                    c[k] |= ((keys[i] >> (3 * bit + k)) & 1u) << bit;
            double r2 = 0.0;
            for (int k = 0; k < 3; ++k) {
                const double x = origin[k] + (c[k] + 0.5) * size / o.resolution - light[k];
                r2 += x * x;
            }
            /* beyond the sphere by more than two voxel diagonals */
            const double outside = 0.3 + 2.0 * 1.7321 * size / o.resolution;
            leaks += r2 > outside * outside && with_bins[4ull * i] > 0.0f;
        }
    }
    CHECK(differ == 0, "%s: %u of %u voxels differ between bins and grid", name, differ, n);
    CHECK(lit > 20, "%s: %u voxels lit", name, lit);
    if (sphere)
        CHECK(leaks == 0, "%s: %u voxels outside the closed sphere are lit", name, leaks);
    printf("%-36s %u voxels, %u lit, %u differ, %u outside lit\n", name, n, lit, differ, leaks);
    free(keys);
    free(with_bins);
    free(with_grid);
    free(fallback);
    vct_voxels_release(v);
    vct_accel_release(g);
    vct_scene_release(s);
}

int main(void) {
    ctx = check_context();
    check_bins("bins, near the origin, F 16", 0.0f, 16);
    check_bins("bins, near the origin, F 64", 0.0f, 64);
    check_bins("bins, 1e5 units away, F 16", 1e5f, 16);
    check_injection("injection, soup", 0.0f, 0);
    check_injection("injection, soup 1e5 units away", 1e5f, 0);
    check_injection("injection, light in a closed sphere", 0.0f, 1);
    vct_context_release(ctx);
    return check_exit("test_light_bins");
}
