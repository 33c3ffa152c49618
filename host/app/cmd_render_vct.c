/* vct render --method vct: the effect plan and what the voxels hold. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cmd_render_vct.h"

void cli_vct_plan(const cli_options *opt, const vct_scene *s, vct_plan *plan) {
    vct_plan_make(s, opt->force, plan);
    plan->emitters_by_cones = opt->emitters_by_cones;
    if (opt->print_plan)
        cli_print_plan(plan, stdout);
}

void cli_print_voxels(const cli_options *opt, const vct_voxels *v) {
    if (!v)
        return;
    vct_voxel_info info;
    vct_voxels_info_get(v, &info);
    vct_brick_info b;
    vct_bricks_info_get(v, &b);
    fprintf(stderr, "voxels: %u^3, %u bricks, %s\n", info.resolution, b.bricks, b.storage_reason);
    double r[3];
    vct_voxels_bounce_ratios(v, r);
    if (r[0] > 0.0 || r[1] > 0.0 || r[2] > 0.0)
        fprintf(stderr,
                "voxel light: %d bounces, then the rest at the bounce ratios %.3f %.3f %.3f "
                "(red, green, blue: x %.3f %.3f %.3f of the last)\n",
                opt->bounces, r[0], r[1], r[2], r[0] / (1.0 - r[0]), r[1] / (1.0 - r[1]),
                r[2] / (1.0 - r[2]));
}
