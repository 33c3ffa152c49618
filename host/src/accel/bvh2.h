/* The two-level BVH (kernels/accel/bvh/bvh2_traverse.h): a 4-wide BVH per mesh,
 * built on the device in the mesh's space, under a 4-wide BVH over the
 * instances, built on the host at every build (instances are few): moving
 * an instance rebuilds only the top level and the instance's vertices. */
#ifndef VCT_ACCEL_BVH2_H
#define VCT_ACCEL_BVH2_H

#include "accel/bvh.h"

/* A mesh's BVH: its nodes and sorted triangles while being joined, then
 * its root box and its places in the joined buffers. */
typedef struct vct_mesh_tree {
    float *nodes;
    uint32_t *tri_ids;
    uint32_t node_count, depth;
    float lo[3], hi[3];
    uint32_t root, first_id;
} vct_mesh_tree;

typedef struct vct_bvh2 {
    cl_mem nodes;         /* top_cap slots for the top level's nodes, then every mesh's */
    cl_mem instances;     /* BVH2_INSTANCE_FLOAT4S (5) float4 per placed instance */
    cl_mem tri_ids;       /* every mesh's sorted triangles, as indices in the mesh */
    cl_mem tri_vertices;  /* 3 float4 per triangle of the scene, world space */
    vct_mesh_tree *trees; /* per mesh of the scene (node_count 0: not placed) */
    uint32_t top_cap, top_nodes, mesh_nodes, depth, triangle_count, instance_count, mesh_count;
    uint32_t mesh_triangles; /* triangles the meshes' BVHs hold (each mesh once) */
    float scene_extent, tolerance;
    vct_context *ctx;
} vct_bvh2;

/* For a scene with instances (vct_scene.instances). */
vct_bvh2 *vct_bvh2_build(vct_context *ctx, const vct_scene *s, vct_bvh_builder builder,
                         vct_error *err);
/* The instances moved (same meshes, instances and triangles; new
 * transforms and positions): the top level and the vertices again, the
 * meshes' BVHs kept. */
int vct_bvh2_move(vct_context *ctx, vct_bvh2 *b, const vct_scene *s, vct_error *err);
void vct_bvh2_free(vct_bvh2 *b);

#endif
