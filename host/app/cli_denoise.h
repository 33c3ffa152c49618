/* --denoise and the denoiser's guides as layers, after a render. */
#ifndef VCT_APP_CLI_DENOISE_H
#define VCT_APP_CLI_DENOISE_H

#include <stdlib.h>

#include "cli_layers.h"

/* With --aov (and a method other than cone tracing, whose own AOVs come
 * first): the guides as layers albedo, normal, depth and, for the path
 * tracer, variance. With --denoise: `image` replaced by its denoised self
 * (the noisy one a layer, with --aov). variance: the path tracer's, or NULL. */
int cli_denoise_outputs(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                        const cli_options *opt, vct_method method, vct_image *image,
                        const vct_image *variance, cli_layers *layers, vct_error *err);

#endif
