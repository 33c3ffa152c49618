/* The rest of the bounces after the last one the voxels gathered, as a
 * geometric series of the scene's own bounce ratio
 * (kernels/voxel/bounce_rest.cl): each bounce keeps the light before it and
 * measures what it added; vct_voxels_bounce_rest (voxels.h) adds the rest. */
#ifndef VCT_BOUNCE_REST_H
#define VCT_BOUNCE_REST_H

#include "voxel/voxels.h"

/* Before a bounce: keeps the voxels' light as it is (when they add a rest). */
int vct_bounce_rest_keep(vct_context *ctx, vct_voxels *v, vct_error *err);

/* After a bounce: the light it added, summed over the voxels' sides. */
int vct_bounce_rest_measure(vct_context *ctx, vct_voxels *v, vct_error *err);

#endif
