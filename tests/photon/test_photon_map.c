/* The photon stage against plain C on the same photons:
 * - energy: in a closed grey box around a point light every photon path
 *   deposits the light's power times albedo^k at its k-th bounce, so the
 *   stored flux per path is Phi * sum_k a^k (bounded by the paths' spread);
 * - the photon grid: every radius search (the estimates' 27 or more cells,
 *   dense and hashed grids, radii below and above the cell) finds exactly
 *   the photons a brute-force search over all stored photons finds, with
 *   the same summed power;
 * - kinds: no caustic photons without mirrors or glass, caustic ones under
 *   a glass sphere; the same photons on every run. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "mesh_gen.h"
#include "accel/accel.h"
#include "accel/tri_vertices.h"
#include "photon/photon_grid.h"
#include "runtime/runtime.h"

#define STAGE "test photon map"

/* Closed cube [-1, 1]^3 of grey albedo a (both windings mixed), with a
 * point light of intensity I at its centre; optionally a glass sphere. */
static vct_scene *box_scene(float a, float intensity, int glass) {
    const float c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const uint32_t t[12][3] = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}, {0, 4, 5}, {0, 5, 1},
                               {3, 2, 6}, {3, 6, 7}, {0, 3, 7}, {0, 7, 4}, {1, 6, 5}, {1, 2, 6}};
    const float centre[3] = {0.3f, -0.5f, 0.2f};
    test_mesh ball = mesh_icosphere(glass ? 2 : 0, 0.35f, centre);
    const uint32_t nv = 8 + (glass ? ball.nv : 0), nt = 12 + (glass ? ball.nt : 0);
    float *pos = malloc(12ull * nv);
    uint32_t *tri = malloc(12ull * nt), *mat = malloc(4ull * nt);
    memcpy(pos, c, sizeof c);
    memcpy(tri, t, sizeof t);
    for (uint32_t i = 0; i < nt; ++i)
        mat[i] = i < 12 ? 0 : 1;
    if (glass) {
        memcpy(pos + 24, ball.pos, 12ull * ball.nv);
        for (uint32_t i = 0; i < 3 * ball.nt; ++i)
            tri[36 + i] = ball.tri[i] + 8;
    }
    vct_material m[2];
    memset(m, 0, sizeof m);
    for (int k = 0; k < 3; ++k) {
        m[0].albedo[k] = a;
        m[1].albedo[k] = 1.0f;
    }
    m[1].roughness = 0.0f;
    m[1].transmission = 1.0f;
    m[1].ior = 1.5f;
    m[0].roughness = 1.0f;
    vct_error err = {0};
    vct_scene *s = vct_scene_from_arrays(pos, nv, tri, nt, mat, m, glass ? 2 : 1, &err);
    REQUIRE_OK(s ? VCT_OK : err.status, err);
    vct_light l = {0};
    l.type = VCT_LIGHT_POINT;
    l.position[1] = 0.5f;
    l.color[0] = l.color[1] = l.color[2] = intensity;
    REQUIRE_OK(vct_scene_add_light(s, &l, &err), err);
    free(pos);
    free(tri);
    free(mat);
    mesh_free(&ball);
    return s;
}

typedef struct traced {
    vct_scene_buffers sb;
    vct_photon_sources src;
    vct_photon_slots slots;
    vct_accel *accel;
    float *records;
    uint32_t *kinds;
} traced;

static void trace_pass(vct_context *ctx, const vct_scene *s, uint32_t paths, uint32_t depth,
                       uint32_t pass, traced *t) {
    vct_error err = {0};
    memset(t, 0, sizeof *t);
    t->accel = vct_accel_build(ctx, s, NULL, &err);
    REQUIRE_OK(t->accel ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_scene_buffers_make(ctx, s, STAGE, &t->sb, &err), err);
    REQUIRE_OK(vct_photon_sources_make(ctx, s, STAGE, &t->src, &err), err);
    REQUIRE_OK(vct_photon_slots_make(ctx, STAGE, paths, depth, &t->slots, &err), err);
    const vct_photon_trace_job job = {s, t->accel, &t->sb, &t->src, 7, pass, 7u};
    REQUIRE_OK(vct_photon_trace(ctx, STAGE, &job, &t->slots, &err), err);
    const size_t n = (size_t)paths * depth;
    t->records = malloc(48 * n);
    t->kinds = malloc(4 * n);
    REQUIRE_OK(vct_buffer_read(ctx, STAGE, t->slots.records, 0, 48 * n, t->records, &err), err);
    REQUIRE_OK(vct_buffer_read(ctx, STAGE, t->slots.kinds, 0, 4 * n, t->kinds, &err), err);
}

static void traced_free(vct_context *ctx, traced *t) {
    vct_photon_slots_release(ctx, &t->slots);
    vct_photon_sources_release(ctx, &t->src);
    vct_scene_buffers_release(ctx, &t->sb);
    vct_accel_release(t->accel);
    free(t->records);
    free(t->kinds);
}

/* Stored flux per path against Phi * sum_{k < depth} a^k, per kind. */
static void energy(vct_context *ctx) {
    const float a = 0.6f, intensity = 2.0f;
    const uint32_t paths = 1u << 16, depth = 12;
    vct_scene *s = box_scene(a, intensity, 0);
    traced t;
    trace_pass(ctx, s, paths, depth, 0, &t);
    const double phi = 4.0 * CHECK_PI * intensity;
    double sum[3] = {0, 0, 0}, sum2 = 0.0, direct = 0.0;
    uint32_t caustic = 0;
    for (uint32_t p = 0; p < paths; ++p) {
        double path = 0.0;
        for (uint32_t k = 0; k < depth; ++k) {
            const size_t i = (size_t)p * depth + k;
            if (!t.kinds[i])
                continue;
            const float *r = t.records + 12 * i;
            for (int c = 0; c < 3; ++c)
                sum[c] += r[8 + c];
            path += r[8];
            if (t.kinds[i] == VCT_PHOTON_DIRECT)
                direct += r[8];
            caustic += t.kinds[i] == VCT_PHOTON_CAUSTIC;
        }
        sum2 += path * path;
    }
    double expect = 0.0;
    for (uint32_t k = 0; k < depth; ++k)
        expect += phi * pow(a, k);
    const double mean = sum[0] / paths;
    const double se = sqrt(fmax(sum2 / paths - mean * mean, 0.0) / paths);
    CHECK(fabs(mean - expect) < 5.0 * se + 1e-4 * expect,
          "stored flux per path %.5g, expected %.5g (5 se = %.3g)", mean, expect, 5 * se);
    CHECK(fabs(direct / paths - phi) < 1e-3 * phi,
          "direct photons carry %.6g per path, the light sends %.6g", direct / paths, phi);
    CHECK(sum[1] == sum[0] && sum[2] == sum[0], "grey box: the channels differ");
    CHECK(caustic == 0, "%u caustic photons without a mirror or glass", caustic);
    traced_free(ctx, &t);
    vct_scene_release(s);
}

/* Every query's found photons and power against brute force: n points, half
 * beside stored photons, half anywhere in the box. */
static void grid_queries(vct_context *ctx, const vct_scene *s, const traced *t, uint32_t mask,
                         float cell, float radius, int expect_hashed, const char *what) {
    vct_error err = {0};
    vct_scene_frame f;
    vct_scene_frame_of(s, &f);
    vct_photon_grid g;
    memset(&g, 0, sizeof g);
    REQUIRE_OK(vct_photon_grid_build(ctx, STAGE, &t->slots, mask, cell, f.lo, f.hi, &g, &err), err);
    CHECK((g.dims.s[3] != 0) == expect_hashed, "%s: the grid is %s", what,
          g.dims.s[3] ? "hashed" : "dense");
    const size_t slots = (size_t)t->slots.paths * t->slots.depth;
    uint32_t *stored = malloc(4 * slots), count = 0;
    for (size_t i = 0; i < slots; ++i)
        if (t->kinds[i] & mask)
            stored[count++] = (uint32_t)i;
    CHECK(count == g.count, "%s: %u photons in the grid, %u stored", what, g.count, count);
    enum { N = 256 };
    float pts[4 * N];
    uint64_t rng = 99;
    for (int q = 0; q < N; ++q)
        for (int k = 0; k < 3; ++k) {
            const float *near =
                count ? t->records + 12 * (size_t)stored[check_rand(&rng) % count] : NULL;
            pts[4 * q + k] = q % 2 == 0 && near ? near[k] + (check_randf(&rng) - 0.5f) * radius
                                                : f.lo[k] + check_randf(&rng) * (f.hi[k] - f.lo[k]);
            pts[4 * q + 3] = 0.0f;
        }
    cl_program p;
    REQUIRE_OK(vct_program_get(ctx, "photon/photon_grid.cl", "", &p, &err), err);
    cl_mem points =
        vct_buffer_create(ctx, STAGE, "points", sizeof pts, CL_MEM_READ_ONLY, pts, &err);
    cl_mem sums = vct_buffer_create(ctx, STAGE, "sums", sizeof pts, CL_MEM_READ_WRITE, NULL, &err);
    REQUIRE_OK(points && sums ? VCT_OK : err.status, err);
    const cl_uint n = N, flags = 0;
    REQUIRE_OK(vct_run_kernel(ctx, p, "photon_query", STAGE, N, &err, 9,
                              VCT_ARG(map_photons, g.photons), VCT_ARG(map_ranges, g.ranges),
                              VCT_ARG(map_origin, g.origin), VCT_ARG(map_dims, g.dims),
                              VCT_ARG_OF(points), VCT_ARG(count, n), VCT_ARG_OF(radius),
                              VCT_ARG_OF(flags), VCT_ARG_OF(sums)),
               err);
    float got[4 * N];
    REQUIRE_OK(vct_buffer_read(ctx, STAGE, sums, 0, sizeof got, got, &err), err);
    int bad = 0, found_any = 0;
    const double r2 = (double)radius * radius;
    for (int q = 0; q < N && bad < 5; ++q) {
        uint32_t want = 0, borderline = 0;
        double power = 0.0;
        for (uint32_t j = 0; j < count; ++j) {
            const float *r = t->records + 12 * (size_t)stored[j];
            double d2 = 0.0;
            for (int k = 0; k < 3; ++k)
                d2 += ((double)r[k] - pts[4 * q + k]) * ((double)r[k] - pts[4 * q + k]);
            if (fabs(d2 - r2) < 1e-5 * r2)
                ++borderline; /* float rounding may decide either way */
            else if (d2 < r2) {
                ++want;
                power += r[8];
            }
        }
        const uint32_t have = (uint32_t)got[4 * q + 3];
        found_any |= want > 0;
        if (have < want || have > want + borderline ||
            (borderline == 0 && fabs(got[4 * q] - power) > 1e-4 * power + 1e-6)) {
            ++bad;
            CHECK(0,
                  "%s: query %d found %u photons of power %.6g; brute force %u (+%u on the "
                  "sphere) of %.6g",
                  what, q, have, got[4 * q], want, borderline, power);
        }
    }
    CHECK(bad == 0, "%s: queries differ from brute force", what);
    CHECK(found_any || count == 0, "%s: no query found a photon: the check checks nothing", what);
    vct_buffer_release(ctx, points);
    vct_buffer_release(ctx, sums);
    vct_photon_grid_release(ctx, &g);
    free(stored);
}

static void grids(vct_context *ctx) {
    vct_scene *s = box_scene(0.6f, 1.0f, 1);
    traced t;
    trace_pass(ctx, s, 1u << 14, 8, 3, &t);
    uint32_t caustic = 0, through_glass = 0, dir = 0;
    for (size_t i = 0; i < (size_t)t.slots.paths * t.slots.depth; ++i) {
        caustic += (t.kinds[i] & VCT_PHOTON_CAUSTIC) != 0;
        through_glass += t.kinds[i] == (VCT_PHOTON_CAUSTIC | VCT_PHOTON_DIELECTRIC);
        dir += t.kinds[i] == VCT_PHOTON_DIRECT;
    }
    CHECK(caustic > 100, "only %u caustic photons under a glass sphere", caustic);
    /* The box's only specular surface is the glass: every caustic passed it. */
    CHECK(through_glass == caustic, "%u of %u caustic photons marked as through a dielectric",
          through_glass, caustic);
    const uint32_t all = VCT_PHOTON_DIRECT | VCT_PHOTON_INDIRECT;
    grid_queries(ctx, s, &t, all, 0.1f, 0.1f, 0, "dense, radius = cell");
    grid_queries(ctx, s, &t, all, 0.1f, 0.04f, 0, "dense, radius < cell");
    grid_queries(ctx, s, &t, all, 0.05f, 0.13f, 0, "dense, radius 2.6 cells");
    grid_queries(ctx, s, &t, VCT_PHOTON_CAUSTIC, 0.1f, 0.1f, 0, "dense caustic map");
    grid_queries(ctx, s, &t, all, 0.004f, 0.01f, 1, "hashed, radius 2.5 cells");
    grid_queries(ctx, s, &t, all, 0.008f, 0.008f, 1, "hashed, radius = cell");
    /* Many cells per search: some share a bucket, whose photons count once. */
    grid_queries(ctx, s, &t, all, 0.002f, 0.012f, 1, "hashed, radius 6 cells");
    /* The same pass again: the same photons, bit for bit. */
    traced again;
    trace_pass(ctx, s, 1u << 14, 8, 3, &again);
    const size_t n = (size_t)t.slots.paths * t.slots.depth;
    int same = memcmp(t.kinds, again.kinds, 4 * n) == 0;
    for (size_t i = 0; same && i < n; ++i)
        same = !t.kinds[i] || memcmp(t.records + 12 * i, again.records + 12 * i, 48) == 0;
    CHECK(same, "the same pass traced twice stored different photons");
    traced_free(ctx, &again);
    traced_free(ctx, &t);
    vct_scene_release(s);
    /* Nothing of the kinds asked for: an empty grid whose searches find nothing. */
    vct_scene *plain = box_scene(0.6f, 1.0f, 0);
    trace_pass(ctx, plain, 1u << 12, 4, 0, &t);
    grid_queries(ctx, plain, &t, VCT_PHOTON_CAUSTIC, 0.1f, 0.1f, 0, "empty caustic map");
    traced_free(ctx, &t);
    vct_scene_release(plain);
}

int main(void) {
    vct_context *ctx = check_context();
    energy(ctx);
    grids(ctx);
    vct_context_release(ctx);
    return check_exit("test_photon_map");
}
