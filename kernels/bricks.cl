/* Bricks: 3x3x3 corner-centred samples per octree node (layout in
 * brick_pool.h), built bottom-up.
 *
 * Every channel holds (premultiplied value, opacity): albedo, normal and
 * outgoing radiance each times opacity, with opacity in w. Premultiplied
 * values filter linearly, so a plain weighted average of them is the
 * opacity-weighted average of the colours and empty space never darkens one.
 *
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

inline float4 pool_load(__global const half *pool_buffer, uint2 pool, uint b, uint3 t) {
    return vload_half4(brick_texel_index(pool, b, t), pool_buffer);
}

/* Cell of `node` at its level, from the octants on the way up. */
inline uint3 node_cell(__global const uint *tile_parent, uint node) {
    uint3 cell = (uint3)(0u);
    for (uint shift = 0; node != 0u; ++shift) {
        const uint octant = (node - 1u) & 7u;
        cell |= ((uint3)(octant, octant >> 1, octant >> 2) & 1u) << shift;
        node = tile_parent[(node - 1u) >> 3];
    }
    return cell;
}

/* The level-`level` node at `cell` + `offset`, or OCT_NULL where none
 * exists: neighbour links (x, then y, then z) where they lead there, else a
 * descent from the root (a diagonal can exist where its path does not). */
inline uint node_neighbour(__global const uint *child, __global const uint *links, uint node,
                           uint3 cell, uint level, int3 offset) {
    const int3 target = convert_int3(cell) + offset;
    const int side = 1 << level;
    if (any(target < 0) || any(target >= side))
        return OCT_NULL;
    uint at = node;
    const int o[3] = {offset.x, offset.y, offset.z};
    for (uint axis = 0; axis < 3u && at != OCT_NULL; ++axis)
        if (o[axis] != 0)
            at = links[6u * at + (o[axis] > 0 ? axis : axis + 3u)];
    return at != OCT_NULL ? at : octree_node_at(child, convert_uint3(target), level);
}

/* The 27 same-level nodes around `node` (index (z+1)*9 + (y+1)*3 + x+1). */
inline void gather_neighbours(__global const uint *child, __global const uint *links, uint node,
                              uint3 cell, uint level, uint *around) {
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                around[(z + 1) * 9 + (y + 1) * 3 + x + 1] =
                    x == 0 && y == 0 && z == 0
                        ? node
                        : node_neighbour(child, links, node, cell, level, (int3)(x, y, z));
}

/* The 4^3 child cells from -1 to 2 around a node, through its 27
 * neighbours: cell index c per axis lies in neighbour (c + 1) / 2 - 1 at
 * octant bit (c + 1) & 1. Each entry is the child node or OCT_NULL. */
inline void gather_children(__global const uint *child, const uint *around, uint *cells) {
    for (uint z = 0; z < 4u; ++z)
        for (uint y = 0; y < 4u; ++y)
            for (uint x = 0; x < 4u; ++x) {
                const uint n = around[((z + 1u) / 2u) * 9u + ((y + 1u) / 2u) * 3u + (x + 1u) / 2u];
                const uint first = n == OCT_NULL ? OCT_NULL : child[n];
                const uint octant =
                    ((x + 1u) & 1u) | (((y + 1u) & 1u) << 1) | (((z + 1u) & 1u) << 2);
                cells[z * 16u + y * 4u + x] = first == OCT_NULL ? OCT_NULL : first + octant;
            }
}

__kernel void brick_leaf(__global const uint *child, __global const uint *links,
                         __global const uint *tile_parent, uint level, uint first_brick, uint count,
                         __global const float4 *albedo, __global const float4 *normal,
                         __global const float4 *radiance, uint has_radiance, uint write_geometry,
                         uint2 pool, __global half *albedo_pool, __global half *normal_pool,
                         __global half *radiance_pool) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i, node = tile_parent[b];
    uint around[27], voxel[64];
    gather_neighbours(child, links, node, node_cell(tile_parent, node), level, around);
    gather_children(child, around, voxel);
    for (uint c = 0; c < 64u; ++c)
        voxel[c] = voxel[c] == OCT_NULL ? OCT_NULL : child[voxel[c]];

    for (uint z = 0; z < 3u; ++z)
        for (uint y = 0; y < 3u; ++y)
            for (uint x = 0; x < 3u; ++x) {
                float4 a = (float4)(0.0f), n = (float4)(0.0f), r = (float4)(0.0f);
                float found = 0.0f;
                for (uint dz = 0; dz < 2u; ++dz)
                    for (uint dy = 0; dy < 2u; ++dy)
                        for (uint dx = 0; dx < 2u; ++dx) {
                            const uint v = voxel[(z + dz) * 16u + (y + dy) * 4u + x + dx];
                            if (v == OCT_NULL)
                                continue;
                            const float alpha = albedo[v].w;
                            found += 1.0f;
                            a += (float4)(alpha * albedo[v].xyz, alpha);
                            n += (float4)(alpha * normal[v].xyz, alpha);
                            if (has_radiance)
                                r += (float4)(alpha * radiance[v].xyz, alpha);
                            else
                                r.w += alpha;
                        }
                const float inv = found > 0.0f ? 1.0f / found : 0.0f;
                const uint3 texel = (uint3)(x, y, z);
                if (write_geometry) {
                    brick_store(albedo_pool, pool, b, texel, a * inv);
                    brick_store(normal_pool, pool, b, texel, n * inv);
                }
                brick_store(radiance_pool, pool, b, texel, r * inv);
            }
}

/* Child lattice point e (0..6 per axis; point 2i + 1 is the parent's texel
 * i) from the child bricks around: an even e is the middle of child cell
 * e / 2, an odd e the shared face of cells (e - 1) / 2 and (e + 1) / 2, held
 * equally by either. Empty where no child brick holds it. */
inline float4 lattice_load(__global const half *src, uint2 pool, __global const uint *child,
                           const uint *cells, uint3 e) {
    const uint3 odd = e & 1u;
    const uint3 lo = (e - odd) / 2u; /* first candidate cell per axis */
    for (uint cz = 0; cz <= odd.z; ++cz)
        for (uint cy = 0; cy <= odd.y; ++cy)
            for (uint cx = 0; cx <= odd.x; ++cx) {
                const uint3 c = lo + (uint3)(cx, cy, cz);
                const uint n = cells[c.z * 16u + c.y * 4u + c.x];
                const uint b = n == OCT_NULL ? BRICK_NULL : brick_of(child, n);
                if (b == BRICK_NULL)
                    continue;
                /* local texel: 1 in the middle; 2 or 0 on the low or high cell's face */
                const uint3 l = 1u + odd - 2u * odd * (uint3)(cx, cy, cz);
                return pool_load(src, pool, b, l);
            }
    return (float4)(0.0f);
}

inline void filter_brick_cells(__global const uint *child, __global const uint *links,
                               __global const uint *tile_parent, uint level, uint b, uint *cells) {
    const uint node = tile_parent[b];
    uint around[27];
    gather_neighbours(child, links, node, node_cell(tile_parent, node), level, around);
    gather_children(child, around, cells);
}

__kernel void brick_filter(__global const uint *child, __global const uint *links,
                           __global const uint *tile_parent, uint level, uint first_brick,
                           uint count, uint2 pool, __global half *channel) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i;
    uint cells[64];
    filter_brick_cells(child, links, tile_parent, level, b, cells);
    const float w[3] = {0.25f, 0.5f, 0.25f};
    /* separable: z into a 7x7 plane, then y, then x */
    for (uint k = 0; k < 3u; ++k) {
        float4 plane[49];
        for (uint y = 0; y < 7u; ++y)
            for (uint x = 0; x < 7u; ++x) {
                float4 s = (float4)(0.0f);
                for (uint d = 0; d < 3u; ++d)
                    s +=
                        w[d] * lattice_load(channel, pool, child, cells, (uint3)(x, y, 2u * k + d));
                plane[y * 7u + x] = s;
            }
        for (uint j = 0; j < 3u; ++j) {
            float4 row[7];
            for (uint x = 0; x < 7u; ++x)
                row[x] = w[0] * plane[(2u * j) * 7u + x] + w[1] * plane[(2u * j + 1u) * 7u + x] +
                         w[2] * plane[(2u * j + 2u) * 7u + x];
            for (uint t = 0; t < 3u; ++t)
                brick_store(channel, pool, b, (uint3)(t, j, k),
                            w[0] * row[2u * t] + w[1] * row[2u * t + 1u] + w[2] * row[2u * t + 2u]);
        }
    }
}

/* Opacity of a sample over `thickness` child samples, colour kept. */
inline float4 over_thickness(float4 v, uint half_thick) {
    if (!half_thick)
        return v;
    /* 1 - (1 - a)^(1/2) = a / (1 + sqrt(1 - a)), stable near a = 0 */
    return v / (1.0f + sqrt(fmax(1.0f - v.w, 0.0f)));
}

/* Direction dir (0..5: +x, +y, +z, -x, -y, -z; the way a cone travels)
 * from `src` (the child level's values for that direction) into `dst`. */
__kernel void brick_filter_dir(__global const uint *child, __global const uint *links,
                               __global const uint *tile_parent, uint level, uint first_brick,
                               uint count, uint2 pool, uint dir, __global const half *src,
                               __global half *dst) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i;
    uint cells[64];
    filter_brick_cells(child, links, tile_parent, level, b, cells);
    const float w[3] = {0.25f, 0.5f, 0.25f};
    const uint axis = dir % 3u, backwards = dir >= 3u;
    for (uint k = 0; k < 3u; ++k)
        for (uint j = 0; j < 3u; ++j)
            for (uint t = 0; t < 3u; ++t) {
                const uint centre[3] = {2u * t + 1u, 2u * j + 1u, 2u * k + 1u};
                float4 sum = (float4)(0.0f);
                for (uint v = 0; v < 3u; ++v)
                    for (uint u = 0; u < 3u; ++u) {
                        float4 acc = (float4)(0.0f);
                        for (uint s = 0; s < 3u; ++s) {
                            const uint along = backwards ? 2u - s : s;
                            uint p[3];
                            p[axis] = centre[axis] + along - 1u;
                            p[(axis + 1u) % 3u] = centre[(axis + 1u) % 3u] + u - 1u;
                            p[(axis + 2u) % 3u] = centre[(axis + 2u) % 3u] + v - 1u;
                            const float4 x = over_thickness(
                                lattice_load(src, pool, child, cells, (uint3)(p[0], p[1], p[2])),
                                along != 1u);
                            acc += (1.0f - acc.w) * x;
                        }
                        sum += (w[u] * w[v]) * acc;
                    }
                brick_store(dst, pool, b, (uint3)(t, j, k), sum);
            }
}
