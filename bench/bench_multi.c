/* Frame time on one device and on several at once, per method, in one run:
 * efficiency = the group's throughput / the sum of its devices' own, and
 * the group's time against the fastest device alone. Shares settle over the
 * frames (row methods); the median of the last 5 frames is reported. Then
 * the group's voxels built on every device against built once and copied.
 *
 * Usage: bench_multi [LIST...] (default: "0" "1" "0,1"); the last list is
 * the group, the others its devices alone. The scene is the Cornell box
 * with its point light (or VCT_BENCH_HEAVY=1: the 102k-triangle scene). */
#include "bench_util.h"
#include "check.h"
#include "heavy_scene.h"

#define SIZE 384
#define FRAMES 10

typedef struct method_row {
    const char *name;
    vct_method method;
    uint32_t subsample;
} method_row;

static const method_row methods[] = {
    {"raycast", VCT_METHOD_RAYCAST, 0},
    {"whitted", VCT_METHOD_WHITTED, 0},
    {"whitted, subsample 8", VCT_METHOD_WHITTED, 8},
    {"vct", VCT_METHOD_VCT, 0},
    {"pt, 16 spp", VCT_METHOD_PATHTRACE, 0},
    {"pm, 4 passes", VCT_METHOD_PM, 0},
};

static vct_plan plan;

/* What every group builds: the BVH, and 64^3 voxels with bricks and one bounce. */
static vct_group_build build_options(void) {
    vct_group_build b;
    memset(&b, 0, sizeof b);
    b.accel.kind = VCT_ACCEL_BVH;
    b.plan = &plan;
    b.voxel.resolution = 64;
    b.bricks = (vct_brick_options){VCT_BRICKS_AUTO, 1, 0};
    b.bounces = 1;
    b.cones = vct_vct_options_default(512, 512).cones;
    return b;
}

static int cmp_double(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Median frame time (ms) of the last frames; *image: the last frame. */
static double frames(vct_group *g, const vct_scene *s, const method_row *m, vct_image *image,
                     double *share_last, int *alone) {
    double ms[FRAMES];
    for (int f = 0; f < FRAMES; ++f) {
        vct_render_job job = vct_render_job_default(m->method, SIZE, SIZE);
        job.scene = s;
        job.plan = &plan;
        job.pathtrace.spp = 16;
        job.pathtrace.max_depth = 8;
        job.whitted.subsample = m->subsample;
        job.pm.passes = 4;
        vct_error err = {0};
        vct_image_release(image);
        const double t0 = vct_now_ms();
        if (vct_group_render(g, &job, image, NULL, &err))
            bench_die(&err);
        ms[f] = vct_now_ms() - t0;
        const vct_group_device *d;
        const int n = vct_group_devices(g, &d);
        if (getenv("VCT_BENCH_VERBOSE")) {
            fprintf(stderr, "%s, frame %d: %.1f ms;", m->name, f, ms[f]);
            for (int k = 0; k < n; ++k)
                fprintf(stderr, " [%d] %.0f in %.1f ms, share %.2f", d[k].info.index,
                        d[k].last_work, d[k].last_ms, d[k].share);
            fprintf(stderr, "\n");
        }
    }
    const vct_group_device *d;
    vct_group_devices(g, &d);
    *share_last = d[vct_group_size(g) - 1].share;
    *alone = vct_group_alone(g);
    qsort(ms + FRAMES - 5, 5, sizeof(double), cmp_double);
    return ms[FRAMES - 3];
}

int main(int argc, char **argv) {
    const char *defaults[] = {"0", "1", "0,1"};
    const char **lists = argc > 1 ? (const char **)argv + 1 : defaults;
    const int count = argc > 1 ? argc - 1 : 3;
    vct_error err = {0};
    const char *src = getenv("VCT_SOURCE_DIR");
    const char *heavy_env = getenv("VCT_BENCH_HEAVY");
    vct_scene *s = heavy_env && atoi(heavy_env) ? heavy_scene_load(src ? src : ".", &err)
                                                : check_cornell_box_point_light();
    if (!s)
        bench_die(&err);
    vct_plan_make(s, NULL, &plan);
    vct_group *groups[8];
    for (int i = 0; i < count && i < 8; ++i) {
        groups[i] = vct_group_create(lists[i], &err);
        const vct_group_build b = build_options();
        if (!groups[i] || vct_group_prepare(groups[i], s, &b, &err))
            bench_die(&err);
        const vct_group_device *d;
        const int n = vct_group_devices(groups[i], &d);
        printf("\"%s\":", lists[i]);
        for (int k = 0; k < n; ++k)
            printf(" [%d] %s (%s, %.0f ms to build)", d[k].info.index, d[k].info.name,
                   d[k].info.platform, d[k].build_ms);
        printf("\n");
    }
    printf("\n%dx%d, %s, median of the last 5 of %d frames\n\n", SIZE, SIZE,
           heavy_env && atoi(heavy_env) ? "heavy scene" : "Cornell box", FRAMES);
    printf("| method |");
    for (int i = 0; i < count; ++i)
        printf(" \"%s\" (ms) |", lists[i]);
    printf(" efficiency | fastest alone / group | last device's share | group's choice | same "
           "image |\n|---|");
    for (int i = 0; i < count + 5; ++i)
        printf("---:|");
    printf("\n");
    for (size_t m = 0; m < sizeof methods / sizeof *methods; ++m) {
        double ms[8], share = 0.0, throughput_sum = 0.0, fastest = 1e30;
        int alone = -1;
        vct_image images[8] = {{0}};
        for (int i = 0; i < count; ++i) {
            ms[i] = frames(groups[i], s, &methods[m], &images[i], &share, &alone);
            if (i < count - 1) {
                throughput_sum += 1.0 / ms[i];
                fastest = ms[i] < fastest ? ms[i] : fastest;
            }
        }
        int same = 1;
        const size_t floats = 4 * (size_t)SIZE * SIZE;
        for (int i = 1; i < count; ++i)
            same &= memcmp(images[0].rgba, images[i].rgba, floats * sizeof(float)) == 0;
        printf("| %s |", methods[m].name);
        for (int i = 0; i < count; ++i)
            printf(" %.1f |", ms[i]);
        char choice[32] = "together";
        if (methods[m].method == VCT_METHOD_PATHTRACE)
            snprintf(choice, sizeof choice, "chunks of samples"); /* no bands to give up */
        else if (alone >= 0)
            snprintf(choice, sizeof choice, "device %d alone", alone);
        printf(" %.2f | %.2f | %.2f | %s | %s |\n", (1.0 / ms[count - 1]) / throughput_sum,
               fastest / ms[count - 1], share, choice, same ? "yes" : "NO");
        for (int i = 0; i < count; ++i)
            vct_image_release(&images[i]);
    }
    /* The voxels: every device builds its own, or the first builds and the
     * others receive a copy. */
    vct_group *g = groups[count - 1];
    const vct_group_device *d;
    const int n = vct_group_devices(g, &d);
    printf("\nvoxels of \"%s\" (64^3, bricks, 1 bounce), ms per device:\n\n", lists[count - 1]);
    printf("| device | each builds its own | first builds, others copy |\n|---|---:|---:|\n");
    vct_group_build b = build_options();
    /* again, warm (the first prepare compiled the kernels) */
    if (vct_group_prepare(g, s, &b, &err))
        bench_die(&err);
    double own[16];
    for (int k = 0; k < n && k < 16; ++k)
        own[k] = d[k].voxels_ms;
    b.copy_voxels = 1;
    if (vct_group_prepare(g, s, &b, &err))
        bench_die(&err);
    for (int k = 0; k < n && k < 16; ++k)
        printf("| [%d] %s | %.1f | %.1f %s |\n", d[k].info.index, d[k].info.name, own[k],
               d[k].voxels_ms, d[k].voxels_copied ? "(copy)" : "(build)");
    for (int i = 0; i < count; ++i)
        vct_group_release(groups[i]);
    vct_scene_release(s);
    return 0;
}
