/* --denoise and the denoiser's guides as layers, after a render. */
#ifndef VCT_APP_CLI_DENOISE_H
#define VCT_APP_CLI_DENOISE_H

#include <stdlib.h>

#include "cli_layers.h"

/* `image` denoised into `out`: whole; or, with aovs' indirect term and the
 * path tracer's variance (of the whole in r, of the direct and indirect
 * parts in g and b), its direct and indirect parts apart. */
int cli_denoise_image(vct_context *ctx, const vct_denoise_guides *g, const vct_image *image,
                      const vct_aovs *aovs, vct_image *out, vct_error *err);

/* With --aov (and a method other than cone tracing, whose own AOVs come
 * first): the guides as layers albedo, normal, depth and, for the path
 * tracer, variance. With --denoise: `image` replaced by its denoised self
 * (the noisy one a layer, with --aov); cone tracing's render filtered its
 * indirect light itself (vct_vct_options.indirect_passes). variance: the
 * path tracer's, or NULL; aovs: the path tracer's indirect light, or NULL
 * (cli_denoise_image). */
int cli_denoise_outputs(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                        const cli_options *opt, vct_method method, vct_image *image,
                        const vct_image *variance, const vct_aovs *aovs, cli_layers *layers,
                        vct_error *err);

#endif
