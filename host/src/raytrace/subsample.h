/* Adaptive subsampling of a ray-traced frame (kernels/render/subsample.cl):
 * rays at the corners of squares of `size` pixels, squares whose corners
 * agree filled by interpolation, the others split level by level. */
#ifndef VCT_RENDER_SUBSAMPLE_H
#define VCT_RENDER_SUBSAMPLE_H

#include "frame/shaded_frame.h"

/* points_kernel traces listed pixels: its own arguments `own`, then points,
 * n, keys, traced and the frame (whitted_points). Writes the number of
 * pixels traced, the camera rays cast (a pixel may be traced twice: a
 * square's centre for the contrast test, then as a splitting point), and
 * with traced_mask (width x height) which pixels were traced. */
/* guard: per pixel, the projected size of the smallest object covering it
 * (render/small_objects.h), or NULL for the plain scheme. */
int vct_subsample(vct_shaded *sh, const char *points_kernel, const vct_kernel_arg *own,
                  int own_count, uint32_t size, const uint16_t *guard, float contrast,
                  uint64_t *traced, uint64_t *rays, uint8_t *traced_mask, vct_error *err);

#endif
