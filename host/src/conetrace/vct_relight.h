/* Light in voxels that are kept: what a committed scene runs when only its
 * lights changed. */
#ifndef VCT_RENDER_VCT_RELIGHT_H
#define VCT_RENDER_VCT_RELIGHT_H

#include "runtime/runtime.h"

/* Injects the scene's direct light into v again and gathers `bounces` - 1
 * bounces, as vct_vct_prepare does for new voxels: the same radiance, bit
 * for bit. */
int vct_vct_relight(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                    uint32_t bounces, const vct_cone_settings *cs, vct_error *err);

#endif
