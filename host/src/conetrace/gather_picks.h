/* The diffuse gather's picks (kernels/render/gather_picks.h): which leaf
 * voxels its extra rays aim at, by their direct light, where a scene has a
 * small patch far brighter than the rest. */
#ifndef VCT_CONETRACE_GATHER_PICKS_H
#define VCT_CONETRACE_GATHER_PICKS_H

#include "runtime/runtime.h"
#include "voxel/voxels.h"

/* Per leaf voxel, the running sum of its pick weight (inclusive), with how
 * many voxels and the sum; count 0 (and cdf NULL): no picks. */
typedef struct vct_gather_picks {
    cl_mem cdf;
    cl_uint count, total;
} vct_gather_picks;

/* The picks of voxels v's direct light by `program`'s gather_pick_*
 * kernels (render/vct_render.cl, built with indirect light), or none
 * where no small patch is far brighter than the rest. */
int vct_gather_picks_build(vct_context *ctx, cl_program program, const vct_voxels *v,
                           const char *stage, vct_gather_picks *picks, vct_error *err);

#endif
