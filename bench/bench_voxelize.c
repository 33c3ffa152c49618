/* Voxelization, octree build and direct light injection (first, and again
 * after the light moves) on a 100k+ triangle scene at 256^3 and 512^3:
 * best-of-N device time per stage, peak and final device memory,
 * and OpenVDB's mesh-to-volume on the same mesh and voxel size, timed in
 * the same run (bench/openvdb_voxelize.py, Debian's python3-openvdb). */
#include <math.h>
#include <unistd.h>

#include "bench_util.h"
#include "heavy_scene.h"

static int write_mesh(const vct_scene *s, const char *path) {
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    const uint32_t counts[2] = {s->vertex_count, s->triangle_count};
    int ok = fwrite(counts, 4, 2, f) == 2 &&
             fwrite(s->positions, 12, s->vertex_count, f) == s->vertex_count &&
             fwrite(s->triangles, 12, s->triangle_count, f) == s->triangle_count;
    return fclose(f) == 0 && ok;
}

/* Seconds and active voxels of OpenVDB, or a negative time when unavailable. */
static double openvdb_seconds(const char *script, const char *mesh, double voxel_size, int runs,
                              unsigned long long *active) {
    const char *python = access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "%s %s %s %.9g %d 2>/dev/null", python, script, mesh, voxel_size,
             runs);
    FILE *p = popen(cmd, "r");
    double seconds = -1.0;
    if (p) {
        if (fscanf(p, "seconds %lf active_voxels %llu", &seconds, active) != 2)
            seconds = -1.0;
        pclose(p);
    }
    return seconds;
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
    const int runs = bench_repeats();
    char script[1024], mesh[] = "/tmp/vct_bench_mesh.bin";
    snprintf(script, sizeof script, "%s/bench/openvdb_voxelize.py", src);
    const int have_mesh = write_mesh(s, mesh);
    printf("%u triangles, %s, best of %d\n\n", s->triangle_count, vct_context_device(ctx)->name,
           runs);
    vct_accel *accel = vct_accel_build(ctx, s, NULL, &err);
    if (!accel)
        bench_die(&err);
    printf("| resolution | voxels | nodes | voxelize | octree | light injection | light update | "
           "peak MiB | final MiB | peak / final | OpenVDB mesh-to-volume | OpenVDB / vct voxelize "
           "|\n");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    const uint32_t resolutions[] = {256, 512};
    for (int r = 0; r < 2; ++r) {
        double best_vox = INFINITY, best_oct = INFINITY, best_inject = INFINITY,
               best_update = INFINITY, peak = 0.0;
        vct_voxel_info info = {0};
        for (int i = 0; i < runs; ++i) {
            vct_stats_reset(ctx);
            vct_voxel_options o = {0};
            o.resolution = resolutions[r];
            vct_voxels *v = vct_voxelize(ctx, s, &o, &err);
            if (!v || vct_octree_build(ctx, v, &err) != VCT_OK)
                bench_die(&err);
            vct_voxels_info_get(v, &info);
            best_vox = fmin(best_vox, stage_device_ms(ctx, "voxelize"));
            best_oct = fmin(best_oct, stage_device_ms(ctx, "octree build"));
            peak = fmax(peak,
                        fmax(stage_peak_mib(ctx, "voxelize"), stage_peak_mib(ctx, "octree build")));
            /* Inject, then move the light and inject again: the update. */
            if (vct_voxels_inject_light(ctx, s, accel, v, &err) != VCT_OK)
                bench_die(&err);
            best_inject = fmin(best_inject, stage_device_ms(ctx, "light injection"));
            s->lights[0].position[0] += 40.0f;
            vct_stats_reset(ctx);
            if (vct_voxels_inject_light(ctx, s, accel, v, &err) != VCT_OK)
                bench_die(&err);
            s->lights[0].position[0] -= 40.0f;
            best_update = fmin(best_update, stage_device_ms(ctx, "light injection"));
            vct_voxels_release(v);
        }
        const double final_mib =
            (info.voxel_bytes + info.node_bytes + info.neighbour_bytes) / 1048576.0;
        unsigned long long active = 0;
        const double vdb =
            have_mesh ? openvdb_seconds(script, mesh, info.side / info.resolution, runs, &active)
                      : -1.0;
        char vdb_cell[96] = "not available", ratio[32] = "–";
        if (vdb >= 0.0) {
            snprintf(vdb_cell, sizeof vdb_cell, "%.0f ms (%llu voxels)", vdb * 1e3, active);
            snprintf(ratio, sizeof ratio, "%.1f×", vdb * 1e3 / best_vox);
        }
        printf("| %u^3 | %u | %u | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f | %.0f | %.2f | %s "
               "| %s |\n",
               info.resolution, info.voxels, info.nodes, best_vox, best_oct, best_inject,
               best_update, peak, final_mib, peak / final_mib, vdb_cell, ratio);
        fflush(stdout);
    }
    /* Where the time of the last 512^3 run went. */
    const vct_kernel_stat *k;
    const int nk = vct_kernel_stats(ctx, &k);
    printf("\nlast 512^3 run, per kernel:\n");
    for (int i = 0; i < nk; ++i)
        printf("  %-24s %8.2f ms %4d launches\n", k[i].name, k[i].device_ms, k[i].launches);
    remove(mesh);
    vct_accel_release(accel);
    vct_context_release(ctx);
    vct_scene_release(s);
    return 0;
}
