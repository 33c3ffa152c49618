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

/* Light carried over from the frame before, as engines do: with
 * inject_direct the lights' direct light again, then one bounce gathered
 * from the light the bricks hold (the frame before's, every bounce in it);
 * without, one more bounce of the same direct light. Repeated, the light
 * settles to every bounce of the new lights. */
int vct_vct_relight_carry(vct_context *ctx, const vct_scene *s, const vct_accel *g, vct_voxels *v,
                          const vct_cone_settings *cs, int inject_direct, vct_error *err);

#endif
