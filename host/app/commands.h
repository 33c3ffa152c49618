/* The vct subcommands. Each returns a process exit code. */
#ifndef VCT_APP_COMMANDS_H
#define VCT_APP_COMMANDS_H

#include <stdio.h>

#include "options.h"

int cmd_devices(const cli_options *opt);
int cmd_info(const cli_options *opt);
int cmd_render(const cli_options *opt);
int cmd_compare(const cli_options *opt);
int cmd_voxelize(const cli_options *opt);

/* Helpers shared by the commands. */
int cli_fail(const vct_error *err); /* prints the message; returns 1 */
int cli_fail_input(vct_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
vct_scene *cli_load_scene(const cli_options *opt, vct_error *err);
void cli_print_scene(const vct_scene *s, FILE *out);
void cli_print_stats(const vct_context *ctx);
/* The context for --device (or the default), its name printed on stderr. */
vct_context *cli_open_context(const cli_options *opt, vct_error *err);
int cli_make_parent_dir(const char *path, vct_error *err);
void cli_voxel_options(const cli_options *opt, uint32_t default_res, vct_voxel_options *options);
void cli_print_plan(const vct_plan *plan, FILE *out);
/* Plans, builds what the plan needs and renders by voxel cone tracing. */
int cli_render_vct(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                   const cli_options *opt, vct_image *image, vct_error *err);

#endif
