/* The voxel list and its sparse voxel octree, shared by the host files
 * that build, read and render them. */
#ifndef VCT_VOXELS_H
#define VCT_VOXELS_H

#include "internal.h"

struct vct_voxels {
    vct_context *ctx;
    vct_voxel_info info;
    /* Per voxel, sorted by Morton key. */
    cl_mem keys, albedo, normal, emission;
    cl_mem radiance; /* outgoing radiance, after vct_voxels_inject_light */
    /* Octree: built by vct_octree_build (child is NULL before). */
    cl_mem child, neighbours, tile_parent;
};

/* Volume description for kernels (vct_volume_desc in kernels/vct_types.h). */
void vct_voxels_volume_desc(const vct_voxels *voxels, void *out_desc);
/* The largest power-of-two resolution below `res` at which `bytes`, growing
 * with the square of the resolution like a surface does, stays within `limit`. */
uint32_t vct_voxel_res_that_fits(uint32_t res, double bytes, double limit);
/* Fails with a message naming the resolution that would fit when one
 * buffer of `bytes` exceeds the device's allocation limit. */
int vct_voxel_buffer_fits(vct_context *ctx, const vct_voxel_info *info, const char *stage,
                          const char *what, double bytes, vct_error *err);

#endif
