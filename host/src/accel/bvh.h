/* The 4-wide BVH as the renderers and its tests see it (layout:
 * kernels/accel/bvh/bvh_node.h). */
#ifndef VCT_ACCEL_BVH_H
#define VCT_ACCEL_BVH_H

#include "runtime/runtime.h"

/* Traversal's stack holds 3 nodes per level: deeper trees are refused
 * (BVH_MAX_DEPTH in kernels/accel/bvh/bvh_traverse.h). */
#define VCT_BVH_MAX_DEPTH 40
/* A leaf holds up to this many consecutive triangles. */
#define VCT_BVH_LEAF_MAX 4

typedef struct vct_bvh {
    cl_mem nodes;         /* 8 float4 per wide node */
    cl_mem leaf_vertices; /* 3 float4 per sorted triangle */
    cl_mem tri_ids;       /* sorted position -> triangle */
    cl_mem tri_vertices;  /* 3 float4 per triangle, scene order */
    /* The binary tree it was collapsed from, kept for refit. */
    cl_mem children, parents, boxes, arrivals;
    uint32_t node_count, depth, triangle_count, passes;
    float scene_extent, tolerance;
    vct_context *ctx;
} vct_bvh;

vct_bvh *vct_bvh_build(vct_context *ctx, const vct_scene *s, vct_bvh_builder builder,
                       vct_error *err);
/* New positions for the same triangles: boxes recomputed, tree kept. */
int vct_bvh_refit(vct_context *ctx, vct_bvh *b, const vct_scene *s, vct_error *err);
/* The wide nodes (8 float4 each) and the sorted triangle order, read back. */
int vct_bvh_read(vct_context *ctx, const vct_bvh *b, float *nodes, uint32_t *tri_ids,
                 vct_error *err);
/* Surface-area cost: (sum over nodes of area + sum over leaves of area x
 * triangles) / root area, both costs 1; *area (where not NULL) that sum
 * before the division; also the leaf count. */
int vct_bvh_cost(vct_context *ctx, const vct_bvh *b, double *sah, double *area, uint32_t *leaves,
                 vct_error *err);
void vct_bvh_free(vct_bvh *b);

#endif
