/* The brick pool: where every octree node with geometry below it keeps its
 * 3x3x3 corner-centred samples, as half-float RGBA texels.
 *
 * A node at level l < L whose children exist owns brick (child[n] - 1) / 8,
 * the index of its child tile, so no brick pointers are stored and a level's
 * bricks are one contiguous range. Its samples sit at the node's corners,
 * edge and face midpoints and centre: texel (i, j, k) lies at
 * node_min + (i, j, k) * node_size / 2.
 *
 * Bricks are laid out like a 3D texture of pool.x * pool.y * ceil(n / (pool.x *
 * pool.y)) bricks; brick b sits at (b % pool.x, b / pool.x % pool.y,
 * b / (pool.x * pool.y)). A buffer pool uses pool = (1, 1), which makes each
 * brick's 27 texels contiguous; an image pool uses a wider layout that fits
 * the device's image limits and is filled from a buffer of the same layout.
 * Build with -DVCT_BRICK_IMAGE for an image3d pool (hardware trilinear
 * filtering), without it for a buffer (filtering in code). */
#ifndef VCT_BRICK_POOL_H
#define VCT_BRICK_POOL_H

#include "vct_types.h"

#define BRICK_NULL 0xffffffffu
#define BRICK_TEXELS 27u

#ifdef VCT_BRICK_IMAGE
#define BRICK_POOL __read_only image3d_t
#else
#define BRICK_POOL __global const half *
#endif

/* The brick of node `node` (at a level below the leaves), or BRICK_NULL. */
inline uint brick_of(__global const uint *child, uint node) {
    const uint first = child[node];
    return first == 0xffffffffu ? BRICK_NULL : (first - 1u) >> 3;
}

/* Texel coordinates of texel t = (i, j, k) of brick b in the pool. */
inline int4 brick_texel_coord(uint2 pool, uint b, uint3 t) {
    const uint slab = pool.x * pool.y;
    const uint3 base = (uint3)(b % pool.x, (b / pool.x) % pool.y, b / slab) * 3u;
    return (int4)(convert_int3(base + t), 0);
}

/* Linear index of brick b's texel (0, 0, 0) in a buffer pool of the same
 * layout; compute it once per brick (it divides). */
inline uint brick_base(uint2 pool, uint b) {
    if (pool.x == 1u && pool.y == 1u)
        return b * BRICK_TEXELS; /* a buffer pool: no division */
    const int4 c = brick_texel_coord(pool, b, (uint3)(0u));
    return ((uint)c.z * (3u * pool.y) + (uint)c.y) * (3u * pool.x) + (uint)c.x;
}

/* Offset of texel t from its brick's base. */
inline uint brick_offset(uint2 pool, uint3 t) {
    return (t.z * (3u * pool.y) + t.y) * (3u * pool.x) + t.x;
}

inline uint brick_texel_index(uint2 pool, uint b, uint3 t) {
    return brick_base(pool, b) + brick_offset(pool, t);
}

inline void brick_store_at(__global half *pool_buffer, uint2 pool, uint base, uint3 t, float4 v) {
    vstore_half4(v, base + brick_offset(pool, t), pool_buffer);
}

/* One texel, exactly as stored. */
inline float4 brick_load(BRICK_POOL p, uint2 pool, uint b, uint3 t) {
#ifdef VCT_BRICK_IMAGE
    const sampler_t nearest =
        CLK_NORMALIZED_COORDS_FALSE | CLK_ADDRESS_CLAMP_TO_EDGE | CLK_FILTER_NEAREST;
    return read_imagef(p, nearest, brick_texel_coord(pool, b, t));
#else
    return vload_half4(brick_texel_index(pool, b, t), p);
#endif
}

#ifndef VCT_BRICK_IMAGE
/* Where a trilinear sample at `at` ([0, 2]^3 texel units) in brick b of a
 * buffer pool reads: the first of its 2x2x2 texels, the strides to the
 * others, and the fractions between them. Computed once, it serves every
 * pool of the same layout. */
typedef struct brick_lerp {
    uint first, row, slice;
    float3 f;
} brick_lerp;

VCT_INLINE brick_lerp brick_lerp_at(uint2 pool, uint b, float3 at) {
    at = clamp(at, 0.0f, 2.0f);
    const uint3 lo = min(convert_uint3(at), (uint3)(1u));
    brick_lerp l;
    l.row = 3u * pool.x;
    l.slice = l.row * 3u * pool.y;
    l.first = brick_base(pool, b) + lo.z * l.slice + lo.y * l.row + lo.x;
    l.f = at - convert_float3(lo);
    return l;
}

VCT_INLINE float4 brick_lerp_read(__global const half *p, brick_lerp l) {
    const uint a = l.first, c = a + l.slice;
    const float4 y0 =
        mix(mix(vload_half4(a, p), vload_half4(a + 1u, p), l.f.x),
            mix(vload_half4(a + l.row, p), vload_half4(a + l.row + 1u, p), l.f.x), l.f.y);
    const float4 y1 =
        mix(mix(vload_half4(c, p), vload_half4(c + 1u, p), l.f.x),
            mix(vload_half4(c + l.row, p), vload_half4(c + l.row + 1u, p), l.f.x), l.f.y);
    return mix(y0, y1, l.f.z);
}
#endif

/* Trilinear sample at `at` in [0, 2]^3 texel units inside brick b. */
inline float4 brick_sample(BRICK_POOL p, uint2 pool, uint b, float3 at) {
#ifdef VCT_BRICK_IMAGE
    at = clamp(at, 0.0f, 2.0f);
    const sampler_t linear =
        CLK_NORMALIZED_COORDS_FALSE | CLK_ADDRESS_CLAMP_TO_EDGE | CLK_FILTER_LINEAR;
    const float4 base = convert_float4(brick_texel_coord(pool, b, (uint3)(0u)));
    return read_imagef(p, linear, base + (float4)(at + 0.5f, 0.0f));
#else
    return brick_lerp_read(p, brick_lerp_at(pool, b, at));
#endif
}

#endif
