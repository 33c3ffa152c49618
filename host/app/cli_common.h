/* Helpers shared by the commands of vct and vct-view. */
#ifndef VCT_APP_CLI_COMMON_H
#define VCT_APP_CLI_COMMON_H

#include <stdio.h>

#include "options.h"

int cli_fail(const vct_error *err); /* prints the message; returns 1 */
int cli_fail_input(vct_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
vct_scene *cli_load_scene(const cli_options *opt, vct_error *err);
void cli_print_scene(const vct_scene *s, FILE *out);
void cli_print_stats(const vct_context *ctx);
/* The library's messages (kernel compilation), on stderr. */
void cli_log(void *user, const char *message);
/* The context for --device (or the default), its name printed on stderr. */
vct_context *cli_open_context(const cli_options *opt, vct_error *err);
int cli_make_parent_dir(const char *path, vct_error *err);
void cli_voxel_options(const cli_options *opt, uint32_t default_res, vct_voxel_options *options);
void cli_print_plan(const vct_plan *plan, FILE *out);
/* The --accel structure for the scene, and one line on what it is. */
vct_accel *cli_accel_build(vct_context *ctx, const vct_scene *s, const cli_options *opt,
                           vct_error *err);
/* --method pm: the options from the command line, and the report. */
void cli_pm_options(const cli_options *opt, vct_pm_options *pm);
void cli_print_pm(const vct_pm_result *r, FILE *out);
int cli_print_accel(vct_context *ctx, const vct_accel *accel, FILE *out, vct_error *err);
/* The render job the options describe (no structures yet). */
vct_render_job cli_render_job(const cli_options *opt, vct_method method, const vct_scene *s);
/* What a render did (traced pixels, samples), on stderr. */
void cli_print_result(const cli_options *opt, const vct_render_result *result);
/* 0 when `out` ends in .exr, .pfm or .png; else 1 after a message. */
int cli_check_output(const char *who, const char *out);

/* 1 when --device (or $VCT_DEVICE) names several devices: "0,2", all, gpu, cpu. */
int cli_device_list(const cli_options *opt);

#endif
