/* The BVH's quality step: the binary tree by agglomerative clustering
 * (PLOC) instead of the linear hierarchy (kernels/accel/bvh_ploc.cl). */
#ifndef VCT_ACCEL_BVH_PLOC_H
#define VCT_ACCEL_BVH_PLOC_H

#include "accel/bvh.h"

/* Neighbours searched on each side in the sorted order. */
#define VCT_PLOC_RADIUS 16u

/* From Morton-sorted leaves (b->tri_ids, their boxes in b->boxes): children,
 * parents, boxes and ranges of the binary tree, its triangles placed depth
 * first (b->tri_ids reordered, leaf boxes rewritten by the caller). Writes
 * the number of passes. */
int vct_bvh_ploc(vct_context *ctx, vct_bvh *b, cl_mem ranges, const char *stage, uint32_t *passes,
                 vct_error *err);

#endif
