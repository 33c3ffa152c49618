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

/* New voxels for a scene whose geometry moved, their light carried over
 * from `before` (the voxels of the frame before): direct light injected
 * anew, then one bounce gathered through before's bricks, where the light
 * of every bounce of the frame before is. Repeated renders then settle it
 * with vct_vct_relight_carry. Where before's volume frame or bricks differ
 * (the scene's bounds grew, other settings), every bounce is gathered as
 * vct_vct_prepare does, and *carried says 0. */
vct_status vct_vct_prepare_carry(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 const vct_plan *plan, const vct_voxel_options *vo,
                                 const vct_brick_options *bo, uint32_t bounces,
                                 const vct_cone_settings *cs, const vct_voxels *before,
                                 vct_voxels **out, int *carried, vct_error *err);

#endif
