/* Cone tracing's indirect diffuse light through the denoiser (vct/denoise.h):
 * the gather's 81 rays per traced pixel leave a pixel-scale grain that a
 * few edge-avoiding passes, guided by the rays' own variance, remove. */
#ifndef VCT_VCT_INDIRECT_FILTER_H
#define VCT_VCT_INDIRECT_FILTER_H

#include "frame/frame.h"
#include "runtime/runtime.h"

/* Rows beyond a band's own that `passes` filter passes read (vct_band_shape):
 * the variance estimate's 2, the firefly clamp's 1, each pass's 2 step,
 * and the depth slope's 1 at the outermost taps. */
int vct_indirect_filter_reach(uint32_t passes);

/* Filters `indirect` (the frame's indirect light: ctx's frame, or the band
 * of it ctx renders) in place, guided by the albedo and normal-depth images
 * of the surfaces it was gathered at (vct/denoise.h) and by its variance
 * (NULL: estimated from the image), and puts what the filter changed into
 * the frame. Where `direct` is given (emitters are sampled), the direct
 * light too, at most 3 passes, by `direct_variance` (the emitter samples';
 * 0 where the light is exact, which each pixel keeps where the filter moved
 * it by more than the noise around explains: a point light's shadow edge
 * stays sharp). One read and one write of the frame for both. */
int vct_indirect_filter(vct_context *ctx, const vct_image *albedo, const vct_image *normal_depth,
                        const vct_image *variance, uint32_t passes, vct_image *indirect,
                        const vct_image *direct_variance, vct_image *direct, vct_error *err);

#endif
