/* Reads bricks back through the same brick_load that cone tracing uses, from
 * either pool kind: out[(b - first) * 27 + (k * 9 + j * 3 + i)]. */
#include "brick_pool.h"

__kernel void brick_gather(BRICK_POOL p, uint2 pool, uint first, uint count, __global float4 *out) {
    const uint i = get_global_id(0);
    if (i >= count * BRICK_TEXELS)
        return;
    const uint t = i % BRICK_TEXELS;
    out[i] = brick_load(p, pool, first + i / BRICK_TEXELS, (uint3)(t % 3u, t / 3u % 3u, t / 9u));
}
