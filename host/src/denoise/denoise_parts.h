/* The denoiser's two ways through an image: whole, or as the path tracer's
 * direct and indirect parts (vct_denoise_guides.indirect), each filtered
 * whole with its own variance and options. */
#ifndef VCT_DENOISE_PARTS_H
#define VCT_DENOISE_PARTS_H

#include "vct/denoise.h"

/* Refuses missing or mis-sized inputs and options out of range. */
int vct_denoise_check(const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_error *err);
/* The image through the passes, with g's variance (in r); g->indirect
 * unread. Inputs checked by the caller. */
int vct_denoise_whole(vct_context *ctx, const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_image *out, vct_error *err);
/* Direct light through at most 3 passes with g's variance (in r), each
 * pixel keeping its own value where the filter moved it by more than the
 * noise around explains (a shadow's edge); g->indirect unread. */
int vct_denoise_direct(vct_context *ctx, const vct_image *direct, const vct_denoise_guides *g,
                       const vct_denoise_options *o, vct_image *out, vct_error *err);
/* The direct part (color less g->indirect) and the indirect part filtered
 * apart and added again. */
int vct_denoise_parts(vct_context *ctx, const vct_image *color, const vct_denoise_guides *g,
                      const vct_denoise_options *o, vct_image *out, vct_error *err);

#endif
