/* Whitted's ray trees, or with `plain` the ray caster's shading through the
 * same kernels (one hit, Lambertian, no ambient): how the ray caster is
 * subsampled. */
#ifndef VCT_RENDER_WHITTED_AS_H
#define VCT_RENDER_WHITTED_AS_H

#include "vct/vct.h"

int vct_whitted_render_as(vct_context *ctx, const vct_scene *s, const vct_accel *accel,
                          const vct_whitted_options *opt, int plain, vct_image *image,
                          vct_whitted_result *result, vct_error *err);

#endif
