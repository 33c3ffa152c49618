/* vct render on one device: a frame and its outputs, and sequences. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli_common.h"
#include "cli_denoise.h"
#include "cli_layers.h"
#include "cmd_render_frame.h"
#include "cmd_render_vct.h"

/* The path tracer's direct light: the image less its indirect part (before
 * any filter), the light of the first surface and the background seen. */
static int direct_part(const vct_image *image, const vct_image *indirect, vct_image *direct,
                       vct_error *err) {
    const size_t floats = 4 * (size_t)image->width * image->height;
    *direct = (vct_image){image->width, image->height, malloc(sizeof(float) * floats)};
    if (!direct->rgba) {
        snprintf(err->message, sizeof err->message,
                 "vct render: out of host memory for the direct light");
        err->status = VCT_ERR_MEMORY;
        return VCT_ERR_MEMORY;
    }
    for (size_t i = 0; i < floats; ++i)
        direct->rgba[i] = i % 4 == 3 ? 1.0f : image->rgba[i] - indirect->rgba[i];
    return VCT_OK;
}

int cli_frame_make(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                   const cli_options *opt, vct_method method, cli_frame *f, vct_error *err) {
    memset(f, 0, sizeof *f);
    vct_render_job job = cli_render_job(opt, method, s);
    vct_plan plan;
    if (method == VCT_METHOD_VCT) {
        cli_vct_plan(opt, s, &plan);
        job.plan = &plan;
        job.aovs = opt->aov ? &f->aovs : NULL;
    }
    if (opt->denoise && method == VCT_METHOD_PATHTRACE)
        job.pathtrace.variance = &f->variance;
    if ((opt->denoise || opt->aov) && method == VCT_METHOD_PATHTRACE)
        job.pathtrace.indirect = &f->aovs.indirect; /* filtered apart; an AOV layer */
    int rc = vct_device_scene_render(ds, &job, &f->image, &f->result, err);
    if (rc == VCT_OK && opt->aov && method == VCT_METHOD_PATHTRACE)
        rc = direct_part(&f->image, &f->aovs.indirect, &f->aovs.direct, err);
    if (rc == VCT_OK && method == VCT_METHOD_VCT)
        cli_print_voxels(opt, vct_device_scene_voxels(ds));
    if (rc == VCT_OK && method == VCT_METHOD_PM)
        cli_print_pm(&f->result.pm, stderr);
    if (rc == VCT_OK)
        cli_print_result(opt, &f->result);
    if (rc == VCT_OK && opt->aov && method == VCT_METHOD_VCT)
        cli_layers_add_aovs(&f->layers, &f->aovs);
    if (rc == VCT_OK && opt->aov && f->aovs.indirect.rgba && method == VCT_METHOD_PATHTRACE) {
        cli_layers_add(&f->layers, "direct", &f->aovs.direct, "RGB");
        cli_layers_add(&f->layers, "indirect", &f->aovs.indirect, "RGB");
    }
    if (rc == VCT_OK)
        rc = cli_denoise_outputs(ctx, s, vct_device_scene_accel(ds), opt, method, &f->image,
                                 f->variance.rgba ? &f->variance : NULL,
                                 f->aovs.indirect.rgba && method == VCT_METHOD_PATHTRACE ? &f->aovs
                                                                                         : NULL,
                                 &f->layers, err);
    if (rc != VCT_OK)
        cli_frame_release(f);
    return rc;
}

void cli_frame_release(cli_frame *f) {
    vct_image_release(&f->image);
    vct_image_release(&f->variance);
    cli_layers_free(&f->layers);
    vct_aovs_release(&f->aovs);
}

int cli_render_frame(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                     const cli_options *opt, vct_method method, const char *out, vct_error *err) {
    cli_frame f;
    int rc = cli_frame_make(ctx, ds, s, opt, method, &f, err);
    if (rc == VCT_OK)
        rc = cli_write_image(opt, &f.image, &f.layers, out, err);
    cli_frame_release(&f);
    return rc;
}

int cli_frame_path(const char *pattern, int frame, char *out, size_t size, vct_error *err) {
    const char *pct = strchr(pattern, '%');
    const char *p = pct ? pct + 1 : NULL;
    if (p && *p == '0')
        ++p;
    if (p && isdigit((unsigned char)*p))
        ++p;
    if (!pct || *p != 'd' || strchr(p, '%'))
        return cli_fail_input(err,
                              "vct render --frames: -o %s needs one frame number in its name, as "
                              "%%d or %%04d (out/shot_%%04d.png)",
                              pattern);
    char format[1024];
    snprintf(format, sizeof format, "%s", pattern); /* checked above: one integer conversion */
    if (snprintf(out, size, format, frame) >= (int)size)
        return cli_fail_input(err, "vct render --frames: -o %s is too long", pattern);
    return VCT_OK;
}

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cli_frames_left(const cli_options *opt, const vct_scene *s, const char *pattern, int *frames,
                    int *count, vct_error *err) {
    char path[1024];
    *count = 0;
    int rc = cli_frame_path(pattern, opt->frames[0], path, sizeof path, err);
    if (rc == VCT_OK && s->animation_count == 0)
        rc = cli_fail_input(err, "vct render --frames: %s has no animation", s->source);
    for (int f = opt->frames[0]; rc == VCT_OK && f <= opt->frames[1]; ++f) {
        rc = cli_frame_path(pattern, f, path, sizeof path, err);
        if (rc == VCT_OK && !(opt->resume_frames && access(path, F_OK) == 0))
            frames[(*count)++] = f;
    }
    return rc;
}

/* What a frame of a sequence cost and rebuilt, for --stats' table. */
typedef struct frame_row {
    int frame;
    double seconds;
    vct_device_scene_stats built; /* the device scene's counts during the frame */
} frame_row;

static void print_frame_table(const frame_row *rows, int count, int counted) {
    fprintf(stderr, "%-7s %9s %6s %10s %7s %6s %12s\n", "frame", "seconds", "BVH", "BVH moved",
            "voxels", "light", "scene bytes");
    for (int k = 0; k < count; ++k) {
        const vct_device_scene_stats *b = &rows[k].built;
        if (counted)
            fprintf(stderr, "%-7d %9.3f %6u %10u %7u %6u %12llu\n", rows[k].frame, rows[k].seconds,
                    b->accel_builds, b->accel_moves, b->voxel_builds, b->light_builds,
                    (unsigned long long)b->scene_bytes);
        else
            fprintf(stderr, "%-7d %9.3f %6s %10s %7s %6s %12s\n", rows[k].frame, rows[k].seconds,
                    "-", "-", "-", "-", "-");
    }
    fprintf(stderr, "(built during each frame: BVHs, BVHs moved (two levels' top level placed "
                    "again, or one level's boxes refit), voxels, their light; scene data "
                    "uploaded)\n");
}

static vct_device_scene_stats stats_since(const vct_device_scene_stats *a,
                                          const vct_device_scene_stats *b) {
    vct_device_scene_stats d = {
        b->commits - a->commits,           b->changes - a->changes,
        b->accel_builds - a->accel_builds, b->accel_moves - a->accel_moves,
        b->voxel_builds - a->voxel_builds, b->light_builds - a->light_builds,
        b->scene_bytes - a->scene_bytes};
    return d;
}

int cli_render_frames(const cli_options *opt, vct_scene *s, const char *pattern,
                      const cli_frame_source *source, vct_error *err) {
    const int total = opt->frames[1] - opt->frames[0] + 1;
    int *frames = malloc(sizeof(int) * (size_t)total), count = 0;
    frame_row *rows = calloc((size_t)total, sizeof *rows);
    if (!frames || !rows) {
        free(frames);
        free(rows);
        return cli_fail_input(err, "vct render --frames: out of host memory");
    }
    int rc = cli_frames_left(opt, s, pattern, frames, &count, err);
    if (rc == VCT_OK && count < total)
        fprintf(stderr, "vct render --resume: %d of %d frames are there; rendering %d\n",
                total - count, total, count);
    char path[1024];
    const double start = now_s();
    for (int k = 0; rc == VCT_OK && k < count; ++k) {
        const int f = frames[k];
        const double t0 = now_s();
        vct_device_scene_stats before = {0}, after = {0};
        if (source->ds)
            vct_device_scene_stats_get(source->ds, &before);
        cli_frame frame;
        rc = vct_scene_pose(s, 0, (double)f / opt->fps, err);
        if (rc == VCT_OK)
            rc = cli_frame_path(pattern, f, path, sizeof path, err);
        if (rc == VCT_OK)
            rc = source->make(source->user, &frame, err);
        if (rc == VCT_OK) {
            rc = cli_write_image(opt, &frame.image, &frame.layers, path, err);
            cli_frame_release(&frame);
        }
        if (source->ds)
            vct_device_scene_stats_get(source->ds, &after);
        rows[k] = (frame_row){f, now_s() - t0, stats_since(&before, &after)};
        if (rc == VCT_OK) {
            const double spent = now_s() - start, left = spent / (k + 1) * (count - k - 1);
            fprintf(stderr, "frame %d (%.3f s): %s in %.2f s [%d/%d, %.0f s left]\n", f,
                    (double)f / opt->fps, path, rows[k].seconds, k + 1, count, left);
        }
    }
    if (rc == VCT_OK && opt->stats)
        print_frame_table(rows, count, source->ds != NULL);
    free(frames);
    free(rows);
    return rc;
}
