/* vct render --method vct: the effect plan, the voxel hierarchy it needs,
 * the cone-traced image and its AOVs. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cmd_render_vct.h"

int cli_render_vct(vct_context *ctx, vct_render_job *job, const cli_options *opt, vct_image *image,
                   vct_aovs *aovs, vct_error *err) {
    vct_plan plan;
    vct_plan_make(job->scene, opt->force, &plan);
    plan.emitters_by_cones = opt->emitters_by_cones;
    if (opt->print_plan)
        cli_print_plan(&plan, stdout);
    vct_voxel_options voxel;
    /* 128^3 by default (the scene suite's page shows what it costs). */
    cli_voxel_options(opt, 128, &voxel);
    const vct_brick_options bricks = {opt->bricks, opt->anisotropic == 1, 0};
    vct_voxels *v = NULL;
    int rc = vct_vct_prepare(ctx, job->scene, job->accel, &plan, &voxel, &bricks,
                             (uint32_t)opt->bounces, &opt->cones, &v, err);
    if (rc == VCT_OK && v) {
        vct_brick_info b;
        vct_bricks_info_get(v, &b);
        fprintf(stderr, "voxels: %u^3, %u bricks, %s\n", voxel.resolution, b.bricks,
                b.storage_reason);
        const double ratio = vct_voxels_bounce_ratio(v);
        if (ratio > 0.0)
            fprintf(stderr,
                    "voxel light: %d bounces, then the rest at the bounce ratio %.3f (x %.3f of "
                    "the last)\n",
                    opt->bounces, ratio, ratio / (1.0 - ratio));
    }
    job->voxels = v;
    job->plan = &plan;
    job->aovs = opt->aov || opt->denoise ? aovs : NULL; /* --denoise filters the indirect AOV */
    if (rc == VCT_OK)
        rc = vct_render(ctx, job, image, NULL, err);
    job->voxels = NULL;
    job->plan = NULL;
    job->aovs = NULL;
    vct_voxels_free(v);
    return rc;
}
