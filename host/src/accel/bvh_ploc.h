/* The BVH's quality step: the binary tree by agglomerative clustering
 * (PLOC) instead of the linear hierarchy (kernels/accel/bvh/bvh_ploc.cl). */
#ifndef VCT_ACCEL_BVH_PLOC_H
#define VCT_ACCEL_BVH_PLOC_H

#include "accel/bvh.h"

/* Neighbours searched on each side in the sorted order: VCT_PLOC_RADIUS
 * while more than VCT_PLOC_WIDE_BELOW clusters are left, then
 * VCT_PLOC_RADIUS_WIDE. The first passes merge neighbours that the Morton
 * order already put side by side; the last ones shape the top of the tree,
 * which every ray walks, and cost little for the few clusters left. On the
 * 102k-triangle heavy scene the wide search made the path tracer 7 % faster
 * (1,541-1,563 against 1,648-1,676 ms); 128 throughout, 8 %, but the
 * build of the 105k-triangle dense hall took 194 ms. */
#define VCT_PLOC_RADIUS 16u
#define VCT_PLOC_RADIUS_WIDE 128u
#define VCT_PLOC_WIDE_BELOW 16384u

/* From Morton-sorted leaves (b->tri_ids, their boxes in b->boxes): children,
 * parents, boxes and ranges of the binary tree, its triangles placed depth
 * first (b->tri_ids reordered, leaf boxes rewritten by the caller). Writes
 * the number of passes. */
int vct_bvh_ploc(vct_context *ctx, vct_bvh *b, cl_mem ranges, const char *stage, uint32_t *passes,
                 vct_error *err);

#endif
