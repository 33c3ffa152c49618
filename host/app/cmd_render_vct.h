/* vct render --method vct: plan, voxel hierarchy, cone-traced image, AOVs. */
#ifndef VCT_APP_CMD_RENDER_VCT_H
#define VCT_APP_CMD_RENDER_VCT_H

#include "options.h"

/* Plans, builds what the plan needs and renders `job` (its scene, grid
 * and size set) by voxel cone tracing with the options' settings; with
 * --aov, fills aovs (the caller frees them). */
int cli_render_vct(vct_context *ctx, vct_render_job *job, const cli_options *opt, vct_image *image,
                   vct_aovs *aovs, vct_error *err);

#endif
