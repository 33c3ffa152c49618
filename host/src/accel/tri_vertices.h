/* What every acceleration structure starts from: the scene's frame (its box
 * with a margin, its extent and the tolerance below which positions are not
 * told apart) and its triangles' vertices on the device. */
#ifndef VCT_ACCEL_TRI_VERTICES_H
#define VCT_ACCEL_TRI_VERTICES_H

#include "runtime/runtime.h"

typedef struct vct_scene_frame {
    float lo[3], hi[3]; /* flat axes get a slab a thousandth of the extent thick */
    float extent;
    float tolerance; /* covers both the extent and float spacing at the coordinates' size */
} vct_scene_frame;

void vct_scene_frame_of(const vct_scene *s, vct_scene_frame *f);

/* 3 float4 per triangle (xyz; w: 0, or a masked triangle's mask record),
 * in the scene's order, then the alpha masks' block when the scene has
 * masked materials (kernels/accel/alpha_mask.h). */
int vct_tri_vertices_upload(vct_context *ctx, const vct_scene *s, const char *stage, cl_mem *out,
                            vct_error *err);

#endif
