/* Bricks: 3x3x3 corner-centred samples per octree node (layout in
 * brick_pool.h), built bottom-up.
 *
 * Every channel holds (premultiplied value, opacity): albedo, normal and
 * outgoing radiance each times opacity, with opacity in w. Premultiplied
 * values filter linearly, so a plain weighted average of them is the
 * opacity-weighted average of the colours and empty space never darkens one.
 *
 *   brick_around     per brick, top-down: the 27 same-level nodes around
 *                    its node, from the parent's 27 (no links, no descent).
 *   brick_leaf       level L-1: a sample is the mean of the up to 8 voxels
 *                    around its corner (those with geometry; none gives 0).
 *   brick_filter     level l from level l+1: each sample is the 3x3x3
 *                    Gaussian (1/4, 1/2, 1/4 per axis; the inverse
 *                    multiplicity of corner-centred samples) of the child
 *                    lattice around it, 7^3 points per brick.
 *   brick_filter_dir the same lattice seen along one axis direction: the
 *                    three samples along the axis are composited front to
 *                    back (thicknesses 1/2, 1, 1/2 child samples), the nine
 *                    columns averaged with the same Gaussian weights.
 *
 * A sample depends only on its lattice point, never on the brick asking, and
 * sums run in a fixed world order: samples on faces shared by neighbouring
 * bricks agree bit for bit. Lattice points outside the volume are empty. */
#include "brick_pool.h"
#include "octree.h"

#define AROUND 27u /* nodes per neighbourhood, index (z+1)*9 + (y+1)*3 + x+1 */

/* Level-`level` bricks: their node's 27 neighbours (OCT_NULL where no node
 * exists). A neighbour is a child of one of the parent's 27 neighbours, and
 * the parent's brick is the tile the node belongs to. */
__kernel void brick_around(__global const uint *child, __global const uint *tile_parent, uint level,
                           uint first_brick, uint count, __global uint *around) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i, node = tile_parent[b];
    if (level == 0u) {
        for (uint k = 0; k < AROUND; ++k)
            around[AROUND * b + k] = k == 13u ? node : OCT_NULL;
        return;
    }
    const uint octant = (node - 1u) & 7u, parent_brick = (node - 1u) >> 3;
    const int3 bit = (int3)(octant & 1u, (octant >> 1) & 1u, (octant >> 2) & 1u);
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                const int3 s = bit + (int3)(x, y, z) + 2; /* 1..4: child cell + 2 */
                const int3 up = s / 2 - 1;                /* the parent's neighbour */
                const uint3 oct = convert_uint3(s & 1);
                const uint p = around[AROUND * parent_brick +
                                      (uint)((up.z + 1) * 9 + (up.y + 1) * 3 + up.x + 1)];
                const uint first = p == OCT_NULL ? OCT_NULL : child[p];
                around[AROUND * b + (uint)((z + 1) * 9 + (y + 1) * 3 + x + 1)] =
                    first == OCT_NULL ? OCT_NULL : first + (oct.x | (oct.y << 1) | (oct.z << 2));
            }
}

/* Child cell c (0..3 per axis: cells -1 .. 2 around brick b's node) as a
 * node, or OCT_NULL: cell c lies in neighbour (c + 1) / 2 - 1 at octant bit
 * (c + 1) & 1. */
inline uint child_cell(__global const uint *child, __global const uint *around, uint b, uint3 c) {
    const uint3 up = (c + 1u) / 2u, bit = (c + 1u) & 1u;
    const uint n = around[AROUND * b + up.z * 9u + up.y * 3u + up.x];
    const uint first = n == OCT_NULL ? OCT_NULL : child[n];
    return first == OCT_NULL ? OCT_NULL : first + (bit.x | (bit.y << 1) | (bit.z << 2));
}

/* One work-item per texel: global id = 27 * brick + (z * 9 + y * 3 + x). */
inline uint3 texel_of(uint i) {
    const uint t = i % BRICK_TEXELS;
    return (uint3)(t % 3u, (t / 3u) % 3u, t / 9u);
}

/* Level L-1: texel (x, y, z) sits at the corner shared by child cells x..x+1,
 * y..y+1, z..z+1: the mean of the voxels among them, premultiplied. */
__kernel void brick_leaf(__global const uint *child, __global const uint *around, uint first_brick,
                         uint count, __global const float4 *albedo, __global const float4 *normal,
                         __global const float4 *radiance, uint has_radiance, uint write_geometry,
                         uint2 pool, __global half *albedo_pool, __global half *normal_pool,
                         __global half *radiance_pool) {
    const uint i = get_global_id(0);
    if (i >= count * BRICK_TEXELS)
        return;
    const uint b = first_brick + i / BRICK_TEXELS;
    const uint3 t = texel_of(i);
    float4 a = (float4)(0.0f), n = (float4)(0.0f), r = (float4)(0.0f);
    uint found = 0;
    for (uint d = 0; d < 8u; ++d) { /* a fixed world order: shared samples agree */
        const uint leaf = child_cell(child, around, b, t + (uint3)(d & 1u, (d >> 1) & 1u, d >> 2));
        const uint v = leaf == OCT_NULL ? OCT_NULL : child[leaf];
        if (v == OCT_NULL)
            continue;
        const float alpha = albedo[v].w;
        ++found;
        a += (float4)(alpha * albedo[v].xyz, alpha);
        n += (float4)(alpha * normal[v].xyz, alpha);
        r += (float4)(has_radiance ? alpha * radiance[v].xyz : (float3)(0.0f), alpha);
    }
    const float inv = found ? 1.0f / (float)found : 0.0f;
    const uint base = brick_base(pool, b);
    if (write_geometry) {
        brick_store_at(albedo_pool, pool, base, t, a * inv);
        brick_store_at(normal_pool, pool, base, t, n * inv);
    }
    brick_store_at(radiance_pool, pool, base, t, r * inv);
}

/* The pool index of each of the 8 child cells i..i+1 per axis around
 * parent texel i (BRICK_NULL: no brick). Its 3^3 child lattice points e =
 * 2i .. 2i+2 (in 0..6 around the node) lie in them. */
inline void texel_cells(__global const uint *child, __global const uint *around, uint b, uint3 t,
                        uint2 pool, uint *cell_base) {
    for (uint d = 0; d < 8u; ++d) {
        const uint n = child_cell(child, around, b, t + (uint3)(d & 1u, (d >> 1) & 1u, d >> 2));
        const uint cb = n == OCT_NULL ? BRICK_NULL : brick_of(child, n);
        cell_base[d] = cb == BRICK_NULL ? BRICK_NULL : brick_base(pool, cb);
    }
}

/* Where child lattice point 2t + s (s in 0..2 per axis) is stored: s = 0 is
 * the middle of cell t, s = 2 the middle of cell t + 1, s = 1 their shared
 * face, held bit-identically by either. The pool index, or BRICK_NULL where
 * no child brick holds it (empty space). */
inline uint lattice_texel(const uint *cell_base, uint2 pool, uint3 s) {
    const uint3 face = (s == 1u) ? (uint3)(1u) : (uint3)(0u);
    const uint3 lo = s / 2u; /* the first candidate cell: 0 or 1 */
    for (uint cz = 0; cz <= face.z; ++cz)
        for (uint cy = 0; cy <= face.y; ++cy)
            for (uint cx = 0; cx <= face.x; ++cx) {
                const uint3 c = lo + (uint3)(cx, cy, cz);
                const uint base = cell_base[c.z * 4u + c.y * 2u + c.x];
                if (base == BRICK_NULL)
                    continue;
                /* texel 1 in the middle; 2 on the low cell's face, 0 on the high one's */
                return base + brick_offset(pool, 1u + face - 2u * face * (uint3)(cx, cy, cz));
            }
    return BRICK_NULL;
}

inline float4 texel_load(__global const half *src, uint texel) {
    return texel == BRICK_NULL ? (float4)(0.0f) : vload_half4(texel, src);
}

inline float gauss(uint s) {
    return s == 1u ? 0.5f : 0.25f;
}

/* Channels c0, c1, c2 (`channels` of them, 1..3) of the level's bricks: the
 * 27-point Gaussian of the child lattice around each texel. */
__kernel void brick_filter(__global const uint *child, __global const uint *around,
                           uint first_brick, uint count, uint2 pool, uint channels,
                           __global half *c0, __global half *c1, __global half *c2) {
    const uint i = get_global_id(0);
    if (i >= count * BRICK_TEXELS)
        return;
    const uint b = first_brick + i / BRICK_TEXELS;
    const uint3 t = texel_of(i);
    uint cell_base[8];
    texel_cells(child, around, b, t, pool, cell_base);
    float4 s0 = (float4)(0.0f), s1 = (float4)(0.0f), s2 = (float4)(0.0f);
    for (uint k = 0; k < 27u; ++k) {
        const uint3 s = (uint3)(k % 3u, (k / 3u) % 3u, k / 9u);
        const uint at = lattice_texel(cell_base, pool, s);
        const float w = gauss(s.x) * gauss(s.y) * gauss(s.z);
        s0 += w * texel_load(c0, at);
        if (channels > 1u)
            s1 += w * texel_load(c1, at);
        if (channels > 2u)
            s2 += w * texel_load(c2, at);
    }
    const uint base = brick_base(pool, b);
    brick_store_at(c0, pool, base, t, s0);
    if (channels > 1u)
        brick_store_at(c1, pool, base, t, s1);
    if (channels > 2u)
        brick_store_at(c2, pool, base, t, s2);
}

/* Opacity of a sample over half its thickness, colour kept. */
inline float4 half_thickness(float4 v) {
    /* 1 - (1 - a)^(1/2) = a / (1 + sqrt(1 - a)), stable near a = 0 */
    return v / (1.0f + sqrt(fmax(1.0f - v.w, 0.0f)));
}

/* Direction dir (0..5: +x, +y, +z, -x, -y, -z; the way a cone travels) of
 * one texel from `src`, the child level's values for that direction: the
 * three samples along the axis composited front to back (the end ones half
 * as thick), the nine columns averaged with the Gaussian weights. */
inline float4 filter_direction(const uint *cell_base, uint2 pool, uint dir,
                               __global const half *src) {
    const uint axis = dir % 3u, backwards = dir >= 3u;
    float4 sum = (float4)(0.0f);
    for (uint v = 0; v < 3u; ++v)
        for (uint u = 0; u < 3u; ++u) {
            float4 acc = (float4)(0.0f);
            for (uint step = 0; step < 3u; ++step) {
                const uint along = backwards ? 2u - step : step;
                uint s[3];
                s[axis] = along;
                s[(axis + 1u) % 3u] = u;
                s[(axis + 2u) % 3u] = v;
                float4 x =
                    texel_load(src, lattice_texel(cell_base, pool, (uint3)(s[0], s[1], s[2])));
                if (along != 1u)
                    x = half_thickness(x);
                acc += (1.0f - acc.w) * x;
            }
            sum += (gauss(u) * gauss(v)) * acc;
        }
    return sum;
}

/* All six directions of the level's bricks. */
__kernel void brick_filter_dir(__global const uint *child, __global const uint *around,
                               uint first_brick, uint count, uint2 pool, __global const half *s0,
                               __global const half *s1, __global const half *s2,
                               __global const half *s3, __global const half *s4,
                               __global const half *s5, __global half *d0, __global half *d1,
                               __global half *d2, __global half *d3, __global half *d4,
                               __global half *d5) {
    const uint i = get_global_id(0);
    if (i >= count * BRICK_TEXELS)
        return;
    const uint b = first_brick + i / BRICK_TEXELS;
    const uint3 t = texel_of(i);
    uint cell_base[8];
    texel_cells(child, around, b, t, pool, cell_base);
    const uint base = brick_base(pool, b);
    brick_store_at(d0, pool, base, t, filter_direction(cell_base, pool, 0u, s0));
    brick_store_at(d1, pool, base, t, filter_direction(cell_base, pool, 1u, s1));
    brick_store_at(d2, pool, base, t, filter_direction(cell_base, pool, 2u, s2));
    brick_store_at(d3, pool, base, t, filter_direction(cell_base, pool, 3u, s3));
    brick_store_at(d4, pool, base, t, filter_direction(cell_base, pool, 4u, s4));
    brick_store_at(d5, pool, base, t, filter_direction(cell_base, pool, 5u, s5));
}
