/* vct render on one device: a frame and its outputs, and sequences. */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli_common.h"
#include "cli_denoise.h"
#include "cli_layers.h"
#include "cmd_render_frame.h"
#include "cmd_render_vct.h"

int cli_render_frame(vct_context *ctx, vct_device_scene *ds, const vct_scene *s,
                     const cli_options *opt, vct_method method, const char *out, vct_error *err) {
    vct_image image = {0};
    vct_render_job job = cli_render_job(opt, method, s);
    vct_render_result result = {0};
    vct_aovs aovs;
    memset(&aovs, 0, sizeof aovs);
    vct_plan plan;
    if (method == VCT_METHOD_VCT) {
        cli_vct_plan(opt, s, &plan);
        job.plan = &plan;
        job.aovs = opt->aov || opt->denoise ? &aovs : NULL; /* --denoise filters the indirect AOV */
    }
    vct_image variance = {0};
    if (opt->denoise && method == VCT_METHOD_PATHTRACE)
        job.pathtrace.variance = &variance;
    int rc = vct_device_scene_render(ds, &job, &image, &result, err);
    if (rc == VCT_OK && method == VCT_METHOD_VCT)
        cli_print_voxels(opt, vct_device_scene_voxels(ds));
    if (rc == VCT_OK && method == VCT_METHOD_PM)
        cli_print_pm(&result.pm, stderr);
    if (rc == VCT_OK)
        cli_print_result(opt, &result);
    cli_layers layers = {0};
    if (rc == VCT_OK && opt->aov && method == VCT_METHOD_VCT)
        cli_layers_add_aovs(&layers, &aovs);
    if (rc == VCT_OK)
        rc = cli_denoise_outputs(ctx, s, vct_device_scene_accel(ds), opt, method, &image,
                                 variance.rgba ? &variance : NULL,
                                 method == VCT_METHOD_VCT ? &aovs : NULL, &layers, err);
    if (rc == VCT_OK)
        rc = cli_write_image(opt, &image, &layers, out, err);
    vct_image_release(&image);
    vct_image_release(&variance);
    cli_layers_free(&layers);
    vct_aovs_release(&aovs);
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

int cli_render_frames(vct_context *ctx, vct_device_scene *ds, vct_scene *s, const cli_options *opt,
                      vct_method method, const char *pattern, vct_error *err) {
    char path[1024];
    int rc = cli_frame_path(pattern, opt->frames[0], path, sizeof path, err);
    if (rc == VCT_OK && s->animation_count == 0)
        rc = cli_fail_input(err, "vct render --frames: %s has no animation", s->source);
    for (int f = opt->frames[0]; rc == VCT_OK && f <= opt->frames[1]; ++f) {
        const double t0 = now_s();
        rc = vct_scene_pose(s, 0, (double)f / opt->fps, err);
        if (rc == VCT_OK)
            rc = cli_frame_path(pattern, f, path, sizeof path, err);
        if (rc == VCT_OK)
            rc = cli_render_frame(ctx, ds, s, opt, method, path, err);
        if (rc == VCT_OK)
            fprintf(stderr, "frame %d (%.3f s): %s in %.2f s\n", f, (double)f / opt->fps, path,
                    now_s() - t0);
    }
    return rc;
}
