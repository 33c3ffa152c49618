/* Reads bricks back through the same brick_load and brick_sample that cone
 * tracing uses, from either pool kind. */
#include "voxel/brick_pool.h"
#include "voxel/octree.h"
#include "vct_types.h"

/* out[(b - first) * 27 + (k * 9 + j * 3 + i)] */
__kernel void brick_gather(BRICK_POOL p, uint2 pool, uint first, uint count, __global float4 *out) {
    const uint i = get_global_id(0);
    if (i >= count * BRICK_TEXELS)
        return;
    const uint t = i % BRICK_TEXELS;
    out[i] = brick_load(p, pool, first + i / BRICK_TEXELS, (uint3)(t % 3u, t / 3u % 3u, t / 9u));
}

/* Trilinear samples of one level at world points, through brick_sample: the
 * read a cone makes. Points in a node without a brick read 0. */
__kernel void brick_probe(BRICK_POOL p, uint2 pool, __global const uint *child, vct_volume_desc vol,
                          uint level, __global const float4 *points, uint n, __global float4 *out) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const float cells = (float)(1u << level);
    const float3 at = (points[i].xyz - vol.origin.xyz) / vol.origin.w * cells;
    const uint3 cell = convert_uint3(clamp(floor(at), 0.0f, cells - 1.0f));
    const uint node = octree_node_at(child, cell, level);
    const uint b = node == OCT_NULL ? BRICK_NULL : brick_of(child, node);
    out[i] = b == BRICK_NULL ? (float4)(0.0f)
                             : brick_sample(p, pool, b, 2.0f * (at - convert_float3(cell)));
}
