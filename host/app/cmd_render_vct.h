/* vct render --method vct: the plan the options ask for, and what the
 * voxels it built hold. */
#ifndef VCT_APP_CMD_RENDER_VCT_H
#define VCT_APP_CMD_RENDER_VCT_H

#include "options.h"

/* The scene's plan with the options' forced effects and emitters (printed
 * with --print-plan). */
void cli_vct_plan(const cli_options *opt, const vct_scene *s, vct_plan *plan);
/* The voxels' size, bricks and bounce ratio, on stderr (nothing for NULL). */
void cli_print_voxels(const cli_options *opt, const vct_voxels *v);

#endif
