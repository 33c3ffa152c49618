/* Light in voxels that are kept: what a committed scene runs when only its
 * lights changed. */
#ifndef VCT_RENDER_VCT_RELIGHT_H
#define VCT_RENDER_VCT_RELIGHT_H

#include "runtime/runtime.h"
#include "voxel/voxels.h"

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
 * from carry->before (the voxels of the frame before): each voxel's direct
 * light kept where nothing inside carry's moved boxes can reach it, and
 * injected anew elsewhere; then one bounce gathered through before's
 * bricks (where the light of every bounce of the frame before is), by the
 * voxels whose turn it is (one in carry->every, carry->phase) and those
 * lit anew, the others keeping all their light before. Repeated renders
 * settle it with vct_vct_relight_carry. Where before's volume frame
 * differs (the scene's bounds grew), every bounce is gathered as
 * vct_vct_prepare does, and *carried says 0. */
vct_status vct_vct_prepare_carry(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 const vct_plan *plan, const vct_voxel_options *vo,
                                 const vct_brick_options *bo, uint32_t bounces,
                                 const vct_cone_settings *cs, vct_voxel_carry *carry,
                                 vct_voxels **out, int *carried, vct_error *err);

#endif
