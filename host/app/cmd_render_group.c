/* vct render on a device group: every device builds the scene's structures,
 * the frame is split between them, and --stats says what each held, built
 * and did. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_denoise.h"
#include "cli_layers.h"
#include "cmd_render_frame.h"
#include "cmd_render_group.h"

static void print_devices(const vct_group *g, FILE *out) {
    const vct_group_device *d;
    const int n = vct_group_devices(g, &d);
    fprintf(out, "%-4s %-40s %5s %9s %10s %9s %7s %9s %9s  %s\n", "dev", "name", "type", "build ms",
            "voxels ms", "MiB", "share", "last ms", "work", "state");
    for (int i = 0; i < n; ++i)
        fprintf(out, "%-4d %-40.40s %5s %9.1f %9.1f%s %9.2f %7.3f %9.1f %9.0f  %s\n",
                d[i].info.index, d[i].info.name, d[i].info.is_gpu ? "GPU" : "CPU", d[i].build_ms,
                d[i].voxels_ms, d[i].voxels_copied ? "c" : " ", d[i].build_mib, d[i].share,
                d[i].last_ms, d[i].last_work, d[i].active ? "active" : d[i].dropped);
    fprintf(out, "(voxels ms: c = copied from another device)\n");
}

int cli_devices_denoise(vct_group *g, const vct_scene *s, const cli_options *opt, vct_method method,
                        vct_image *image, const vct_image *variance, const vct_aovs *parts,
                        vct_error *err) {
    const vct_group_device *d;
    const int n = vct_group_devices(g, &d);
    int first = 0;
    while (first < n && !d[first].active)
        ++first;
    vct_context *ctx = vct_group_context(g, first);
    vct_accel *accel = vct_accel_build(ctx, s, &opt->accel, err);
    cli_layers layers = {0};
    int rc = accel ? cli_denoise_outputs(ctx, s, accel, opt, method, image,
                                         variance && variance->rgba ? variance : NULL,
                                         parts && parts->indirect.rgba ? parts : NULL, &layers, err)
                   : (int)err->status;
    cli_layers_free(&layers);
    vct_accel_release(accel);
    return rc;
}

vct_group *cli_devices_open(const cli_options *opt, vct_error *err) {
    vct_group *g = vct_group_create(opt->device, err);
    if (!g)
        return NULL;
    vct_group_set_log(g, cli_log, NULL);
    const vct_group_device *d;
    const int n = vct_group_devices(g, &d);
    for (int i = 0; i < n; ++i)
        fprintf(stderr, "device %d: %s (%s)\n", d[i].info.index, d[i].info.name,
                d[i].info.platform);
    return g;
}

void cli_devices_build(const cli_options *opt, vct_method method, const vct_plan *plan,
                       vct_group_build *build) {
    memset(build, 0, sizeof *build);
    build->accel = opt->accel;
    build->plan = method == VCT_METHOD_VCT ? plan : NULL;
    cli_voxel_options(opt, 128, &build->voxel);
    build->bricks = (vct_brick_options){opt->bricks, opt->anisotropic == 1, 0};
    build->bounces = (uint32_t)opt->bounces;
    build->cones = opt->cones;
    build->copy_voxels = opt->copy_voxels;
}

int cli_devices_frame(vct_group *g, const vct_scene *s, const cli_options *opt, vct_method method,
                      const vct_group_build *build, cli_frame *f, vct_error *err) {
    memset(f, 0, sizeof *f);
    vct_render_job job = cli_render_job(opt, method, s);
    job.plan = build->plan;
    if (opt->denoise && method == VCT_METHOD_PATHTRACE) {
        job.pathtrace.variance = &f->variance; /* from the summed samples */
        job.pathtrace.indirect = &f->aovs.indirect;
    }
    int rc = vct_group_prepare(g, s, build, err);
    if (rc == VCT_OK)
        rc = vct_group_render(g, &job, &f->image, &f->result, err);
    if (rc == VCT_OK)
        cli_print_result(opt, &f->result);
    if (rc == VCT_OK && opt->denoise && method != VCT_METHOD_VCT) /* vct's render filtered */
        rc = cli_devices_denoise(g, s, opt, method, &f->image, &f->variance, &f->aovs, err);
    if (rc != VCT_OK)
        cli_frame_release(f);
    return rc;
}

/* A sequence's frames on the group: each device's device scene rebuilds
 * what a frame moved when the group is prepared again. */
typedef struct group_frames {
    vct_group *group;
    const vct_scene *scene;
    const cli_options *opt;
    vct_method method;
    const vct_group_build *build;
} group_frames;

static int group_frame(void *user, cli_frame *frame, vct_error *err) {
    const group_frames *g = user;
    return cli_devices_frame(g->group, g->scene, g->opt, g->method, g->build, frame, err);
}

int cli_render_group(const cli_options *opt, vct_scene *s, vct_method method, const char *out) {
    vct_error err = {0};
    if (opt->aov) {
        fprintf(stderr, "vct render: --aov comes from one device: give --device one device\n");
        return 1;
    }
    vct_group *g = cli_devices_open(opt, &err);
    if (!g)
        return cli_fail(&err);
    const vct_group_device *d;
    const int n = vct_group_devices(g, &d);
    vct_plan plan;
    vct_plan_make(s, opt->force, &plan);
    plan.emitters_by_cones = opt->emitters_by_cones;
    if (method == VCT_METHOD_VCT && opt->print_plan)
        cli_print_plan(&plan, stdout);
    vct_group_build build;
    cli_devices_build(opt, method, &plan, &build);
    int rc = VCT_OK;
    if (opt->frames[1] >= 0) {
        group_frames frames = {g, s, opt, method, &build};
        const cli_frame_source source = {group_frame, &frames, NULL};
        rc = cli_render_frames(opt, s, out, &source, &err);
    } else {
        cli_frame f;
        rc = cli_devices_frame(g, s, opt, method, &build, &f, &err);
        if (rc == VCT_OK) {
            fprintf(stderr, "devices: %d of %d active, frame in %.1f ms\n",
                    vct_group_active_count(g), n, f.result.seconds * 1e3);
            rc = cli_write_image(opt, &f.image, NULL, out, &err);
            cli_frame_release(&f);
        }
    }
    if (rc == VCT_OK && opt->stats) {
        print_devices(g, stdout);
        for (int i = 0; i < n; ++i) {
            printf("device %d:\n", d[i].info.index);
            cli_print_stats(vct_group_context(g, i));
        }
    }
    vct_group_release(g);
    return rc == VCT_OK ? 0 : cli_fail(&err);
}
