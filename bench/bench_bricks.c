/* The whole voxel spine on a 100k+ triangle scene at 128^3, 256^3 and
 * 512^3, laid out like the VCT thesis's Table 5.1 (memory) and Table 5.2
 * (time), with its figures beside ours. Best-of-N device time per stage.
 * Light goes into the voxels first, so that the bricks build and filter
 * every channel, radiance included, in one pass; the light update is
 * re-injection plus radiance re-filtering after the light moves. The thesis measured Sponza on a
 * GPU with OpenGL; we measure whatever device runs this (PoCL on 2 CPU cores in our figures). */
#include <math.h>

#include "bench_util.h"
#include "heavy_scene.h"
#include "voxel/voxels.h"

#define RESOLUTIONS 3
#define UPDATE_PARTS 4

static const char *update_part_names[UPDATE_PARTS] = {
    "light bins and transfers", "shadow rays (inject_direct)", "leaf bricks (brick_leaf)",
    "filtering up (brick_filter*)"};

/* Which part of a light update kernel `name` belongs to. */
static int update_part(const char *name) {
    if (!strcmp(name, "inject_direct"))
        return 1;
    if (!strcmp(name, "brick_leaf"))
        return 2;
    return strncmp(name, "brick_filter", 12) ? 0 : 3;
}

typedef struct spine_run {
    vct_voxel_info voxels;
    vct_brick_info bricks;
    double voxelize, octree, create, filter, inject, update, peak;
    double update_parts[UPDATE_PARTS]; /* the update by kernel, from the same run */
} spine_run;

static void keep_best(spine_run *best, const spine_run *r) {
    best->voxelize = fmin(best->voxelize, r->voxelize);
    best->octree = fmin(best->octree, r->octree);
    best->create = fmin(best->create, r->create);
    best->filter = fmin(best->filter, r->filter);
    best->inject = fmin(best->inject, r->inject);
    if (r->update < best->update)
        memcpy(best->update_parts, r->update_parts, sizeof r->update_parts);
    best->update = fmin(best->update, r->update);
    best->peak = fmax(best->peak, r->peak);
    best->voxels = r->voxels;
    best->bricks = r->bricks;
}

static double stages_peak(const vct_context *ctx) {
    const vct_stage_stat *st;
    const int n = vct_stats(ctx, &st);
    double peak = 0.0;
    for (int i = 0; i < n; ++i)
        peak = fmax(peak, st[i].mib);
    return peak;
}

static spine_run run_once(vct_context *ctx, vct_scene *s, vct_accel *accel, uint32_t res,
                          int anisotropic) {
    vct_error err = {0};
    spine_run r = {0};
    vct_stats_reset(ctx);
    vct_voxel_options o = {0};
    o.resolution = res;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    /* Light first: the bricks then build and filter every channel in one pass. */
    const vct_brick_options bo = {VCT_BRICKS_AUTO, anisotropic, 0};
    if (!v || vct_octree_build(ctx, v, &err) != VCT_OK ||
        vct_voxels_inject_light(ctx, s, accel, v, &err) != VCT_OK ||
        vct_bricks_build(ctx, v, &bo, &err) != VCT_OK)
        bench_die(&err);
    r.voxelize = stage_device_ms(ctx, "voxelize");
    r.octree = stage_device_ms(ctx, "octree build");
    r.create = stage_device_ms(ctx, "brick creation");
    r.filter = stage_device_ms(ctx, "brick filtering");
    r.inject = stage_device_ms(ctx, "light injection");
    r.peak = stages_peak(ctx);
    vct_voxels_info_get(v, &r.voxels);
    vct_bricks_info_get(v, &r.bricks);
    s->lights[0].position[0] += 40.0f;
    vct_stats_reset(ctx);
    if (vct_voxels_inject_light(ctx, s, accel, v, &err) != VCT_OK)
        bench_die(&err);
    s->lights[0].position[0] -= 40.0f;
    r.update = stage_device_ms(ctx, "light injection") + stage_device_ms(ctx, "radiance filtering");
    const vct_kernel_stat *k;
    const int kernels = vct_kernel_stats(ctx, &k);
    for (int i = 0; i < kernels; ++i)
        r.update_parts[update_part(k[i].name)] += k[i].device_ms;
    vct_voxels_release(v);
    return r;
}

/* Light injection at 256^3 through the lights' triangle bins against the
 * triangle grid alone, alternated in one run, best of `runs` each. */
static void bins_against_grid(vct_context *ctx, vct_scene *s, vct_accel *accel, int runs) {
    vct_error err = {0};
    vct_voxel_options o = {0};
    o.resolution = 256;
    vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
    if (!v)
        bench_die(&err);
    const vct_light_bins_options with_bins = {1, 0, 0}, grid_only = {0, 0, 0};
    double best[2] = {INFINITY, INFINITY};
    for (int i = 0; i < 2 * runs; ++i) {
        vct_stats_reset(ctx);
        if (vct_voxels_inject_light_with(ctx, s, accel, v, i & 1 ? &grid_only : &with_bins, &err))
            bench_die(&err);
        best[i & 1] = fmin(best[i & 1], stage_device_ms(ctx, "light injection"));
    }
    printf("light injection at 256^3, shadow rays through the light's triangle bins: %.1f ms; "
           "through the triangle grid: %.1f ms (%.2fx)\n",
           best[0], best[1], best[1] / best[0]);
    vct_voxels_release(v);
}

static double mib(uint64_t bytes) {
    return bytes / 1048576.0;
}

int main(void) {
    const char *src = getenv("VCT_SOURCE_DIR") ? getenv("VCT_SOURCE_DIR") : ".";
    vct_error err = {0};
    vct_scene *s = heavy_scene_load(src, &err);
    if (!s)
        bench_die(&err);
    vct_context *ctx = vct_context_create(NULL, &err);
    if (!ctx)
        bench_die(&err);
    vct_accel *accel = vct_accel_build(ctx, s, NULL, &err);
    if (!accel)
        bench_die(&err);
    const int runs = bench_repeats();
    const uint32_t res[RESOLUTIONS] = {128, 256, 512};
    spine_run best[RESOLUTIONS], aniso = {0};
    for (int r = 0; r < RESOLUTIONS; ++r) {
        for (int i = 0; i < runs; ++i) {
            const spine_run one = run_once(ctx, s, accel, res[r], 0);
            if (i == 0)
                best[r] = one;
            keep_best(&best[r], &one);
        }
        fprintf(stderr, "%u^3 done\n", res[r]);
    }
    for (int i = 0; i < runs; ++i) {
        const spine_run one = run_once(ctx, s, accel, 256, 1);
        if (i == 0)
            aniso = one;
        keep_best(&aniso, &one);
    }
    printf("%u triangles, %s, best of %d; thesis: Sponza (~280k triangles), GPU, OpenGL\n\n",
           s->triangle_count, vct_context_device(ctx)->name, runs);

    printf("Memory (Table 5.1), MiB; thesis kB / 1024 in brackets\n\n");
    printf("| structure | 128^3 | 256^3 | 512^3 |\n|---|---:|---:|---:|\n");
    const double thesis_mem[6][3] = {{8192, 65536, 524288}, {15354, 24719, 51035},
                                     {224, 1066, 4576},     {1345, 6398, 27460},
                                     {8192, 65536, 65536},  {9362, 74898, 599186}};
    const char *mem_rows[6] = {"dense RGBA8 3D texture (comparison)",
                               "voxel fragments (transient)",
                               "sparse voxel octree (child pointers, tile parents)",
                               "neighbour links",
                               "brick pool (isotropic: albedo, normal, radiance, shade, plane)",
                               "full voxel octree (thesis only; not built here)"};
    for (int row = 0; row < 6; ++row) {
        printf("| %s |", mem_rows[row]);
        for (int r = 0; r < RESOLUTIONS; ++r) {
            const vct_voxel_info *v = &best[r].voxels;
            const vct_brick_info *b = &best[r].bricks;
            const uint64_t ours[6] = {b->dense_rgba8_bytes, v->fragment_bytes, v->node_bytes,
                                      v->neighbour_bytes,   b->pool_bytes,     0};
            if (row == 5)
                printf(" – [%.1f] |", thesis_mem[row][r] / 1024.0);
            else
                printf(" %.1f [%.1f] |", mib(ours[row]), thesis_mem[row][r] / 1024.0);
        }
        printf("\n");
    }
    printf("| voxel attributes (keys, albedo, normal, emission, radiance) |");
    for (int r = 0; r < RESOLUTIONS; ++r)
        printf(" %.1f [–] |", mib(best[r].voxels.voxel_bytes + 16ull * best[r].voxels.voxels));
    printf("\n| bricks / voxels |");
    for (int r = 0; r < RESOLUTIONS; ++r)
        printf(" %u / %u |", best[r].bricks.bricks, best[r].voxels.voxels);
    printf("\n| brick windows (4^3 child cells), kept for light updates |");
    for (int r = 0; r < RESOLUTIONS; ++r)
        printf(" %.1f [–] |", mib(best[r].bricks.window_bytes));
    printf("\n| peak device memory, all stages |");
    for (int r = 0; r < RESOLUTIONS; ++r)
        printf(" %.1f |", best[r].peak);

    printf("\n\nTime (Table 5.2), device ms; thesis in brackets\n\n");
    printf("| stage | 128^3 | 256^3 | 512^3 |\n|---|---:|---:|---:|\n");
    const char *rows[7] = {
        "voxelization [thesis]",
        "octree with neighbour links [1st + 2nd SVO build + neighbours]",
        "brick creation, radiance included [brick creation]",
        "brick filtering (albedo, normal, radiance, shade, plane) [brick MIP mapping]",
        "light injection into the voxels [shadow map + photon storage "
        "+ distribution + photon MIP mapping]",
        "bricks + filtering + injection (goal at 256^3: < 500)",
        "light update: re-inject + re-filter (goal at 256^3: < 200)"};
    const double thesis[7][3] = {
        {30, 30, 110},
        {478 + 454 + 2, 207 + 169 + 10, 1944 + 111 + 76},
        {114, 2012, 7092},
        {18, 132, 1038},
        {8 + 10718 + 1 + 16, 253 + 9833 + 6 + 123, 233 + 10855 + 31 + 982},
        {114 + 18 + 8 + 10718 + 1 + 16, 2012 + 132 + 253 + 9833 + 6 + 123,
         7092 + 1038 + 233 + 10855 + 31 + 982},
        {8 + 10718 + 1 + 16, 253 + 9833 + 6 + 123, 233 + 10855 + 31 + 982}};
    for (int row = 0; row < 7; ++row) {
        printf("| %s |", rows[row]);
        for (int r = 0; r < RESOLUTIONS; ++r) {
            const spine_run *b = &best[r];
            const double ours[7] = {b->voxelize, b->octree, b->create,
                                    b->filter,   b->inject, b->create + b->filter + b->inject,
                                    b->update};
            printf(" %.0f [%.0f] |", ours[row], thesis[row][r]);
        }
        printf("\n");
    }
    printf("\nAnisotropic (6 directional radiance values of each side at levels 0..L-2), 256^3: "
           "brick "
           "creation %.0f ms, filtering %.0f ms, injection %.0f ms, light update "
           "%.0f ms; bricks %.1f MiB (isotropic %.1f MiB)\n",
           aniso.create, aniso.filter, aniso.inject, aniso.update, mib(aniso.bricks.pool_bytes),
           mib(best[1].bricks.pool_bytes));
    const spine_run *by_kernel[2] = {&best[1], &aniso};
    for (int a = 0; a < 2; ++a) {
        printf("light update at 256^3, %s, by kernel (the fastest update):",
               a ? "anisotropic" : "isotropic");
        for (int p = 0; p < UPDATE_PARTS; ++p)
            printf("%s %s %.0f ms", p ? "," : "", update_part_names[p],
                   by_kernel[a]->update_parts[p]);
        printf("\n");
    }
    printf("brick pool kind: %s\n", best[1].bricks.storage_reason);
    bins_against_grid(ctx, s, accel, runs);
    vct_accel_release(accel);
    vct_context_release(ctx);
    vct_scene_release(s);
    return 0;
}
