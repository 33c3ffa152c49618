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
 *                    The build's leaf and filter passes turn them into each
 *                    brick's window (brick_window) and keep it: a light
 *                    update reads 64 words in a row per brick.
 *   brick_leaf       level L-1: a sample is the mean of the up to 8 voxels
 *                    around its corner (those with geometry; none gives 0),
 *                    for channels channel_from .. channel_to - 1 (0 albedo,
 *                    1 normal, 2 radiance, whose w is the voxel's opacity,
 *                    3 shade and 4 plane: the voxel's sides, voxel_side.h).
 *   brick_filter     level l from level l+1: each sample is the 3x3x3
 *                    Gaussian (1/4, 1/2, 1/4 per axis; the inverse
 *                    multiplicity of corner-centred samples) of the child
 *                    lattice around it, 7^3 points per brick.
 *   brick_filter_dir the same lattice seen along one axis direction: the
 *                    three samples along the axis are composited front to
 *                    back (thicknesses 1/2, 1, 1/2 child samples), the nine
 *                    columns averaged with the same Gaussian weights. With
 *                    one_source, all six read one pool (the leaves', which
 *                    have no directions), each value loaded once per axis;
 *                    and the same of the surfaces' darker sides (from the
 *                    leaves, radiance less shade): the directions of what
 *                    a cone sees from behind them (voxel_side.h).
 *
 * A sample depends only on its lattice point, never on the brick asking, and
 * sums run in a fixed world order: samples on faces shared by neighbouring
 * bricks agree bit for bit. Lattice points outside the volume are empty. */
#include "voxel/brick_pool.h"
#include "voxel/octree.h"

#define AROUND 27u /* nodes per neighbourhood, index (z+1)*9 + (y+1)*3 + x+1 */

/* Level-`level` bricks: the child tiles of their node's 27 neighbours, the
 * first child's index (OCT_NULL where no node or no child exists): what the
 * leaf and filter passes need, one load each. A neighbour is a child of one
 * of the parent's 27 neighbours, and the parent's brick is the tile the node
 * belongs to. */
__kernel void brick_around(__global const uint *child, __global const uint *tile_parent, uint level,
                           uint first_brick, uint count, __global uint *around) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i, node = tile_parent[b];
    if (level == 0u) {
        for (uint k = 0; k < AROUND; ++k)
            around[AROUND * b + k] = k == 13u ? child[node] : OCT_NULL;
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
                const uint tile = around[AROUND * parent_brick +
                                         (uint)((up.z + 1) * 9 + (up.y + 1) * 3 + up.x + 1)];
                around[AROUND * b + (uint)((z + 1) * 9 + (y + 1) * 3 + x + 1)] =
                    tile == OCT_NULL ? OCT_NULL
                                     : child[tile + (oct.x | (oct.y << 1) | (oct.z << 2))];
            }
}

/* The 4^3 child cells from -1 to 2 around brick b's node, through its 27
 * neighbours' child tiles: cell index c per axis lies in neighbour
 * (c + 1) / 2 - 1 at octant bit (c + 1) & 1. Each entry is the child node or
 * OCT_NULL. */
inline void gather_children(__global const uint *around, uint b, uint *cells) {
    uint first[AROUND];
    for (uint k = 0; k < AROUND; ++k)
        first[k] = around[AROUND * b + k];
    for (uint z = 0; z < 4u; ++z)
        for (uint y = 0; y < 4u; ++y)
            for (uint x = 0; x < 4u; ++x) {
                const uint f = first[((z + 1u) / 2u) * 9u + ((y + 1u) / 2u) * 3u + (x + 1u) / 2u];
                const uint octant =
                    ((x + 1u) & 1u) | (((y + 1u) & 1u) << 1) | (((z + 1u) & 1u) << 2);
                cells[z * 16u + y * 4u + x] = f == OCT_NULL ? OCT_NULL : f + octant;
            }
}

/* What brick b's 4^3 child cells hold: voxels for a leaf brick, child bricks
 * above (OCT_NULL = BRICK_NULL where nothing). Without window_ready, found
 * through the neighbourhoods and kept in `window` (64 words per brick);
 * with it, read back from there. */
inline void brick_window(__global const uint *child, __global const uint *around,
                         __global uint *window, uint window_ready, uint b, int leaf, uint *cells) {
    __global uint *kept = window + 64u * b;
    if (window_ready) {
        for (uint c = 0; c < 64u; ++c)
            cells[c] = kept[c];
        return;
    }
    gather_children(around, b, cells);
    for (uint c = 0; c < 64u; ++c) {
        const uint node = cells[c];
        cells[c] = node == OCT_NULL ? OCT_NULL : leaf ? child[node] : brick_of(child, node);
        kept[c] = cells[c];
    }
}

/* Voxel v's value of `channel`, premultiplied by its opacity. Injected
 * radiance carries the opacity in w (so radiance alone reads one array);
 * before any injection the radiance channels are 0 with the opacity. */
inline float4 leaf_value(uint channel, uint v, float alpha, int has_radiance,
                         __global const float4 *albedo, __global const float4 *normal,
                         __global const float4 *radiance, __global const float4 *side) {
    if (v == OCT_NULL)
        return (float4)(0.0f);
    if (channel < 2u) {
        const float3 x = (channel == 0u ? albedo : normal)[v].xyz;
        return (float4)(alpha * x, alpha);
    }
    if (!has_radiance)
        return channel == 2u ? (float4)(0.0f, 0.0f, 0.0f, alpha) : (float4)(0.0f);
    const float a = radiance[v].w;
    if (channel == 2u)
        return (float4)(a * radiance[v].xyz, a);
    __global const float4 *sides = side + VCT_VOXEL_SIDE_FLOAT4S * v;
    if (channel == 3u)
        return a * sides[0];
    return (a * sides[0].w) * sides[1]; /* the plane */
}

__kernel void brick_leaf(__global const uint *child, __global const uint *around,
                         __global uint *window, uint window_ready, uint first_brick, uint count,
                         __global const float4 *albedo, __global const float4 *normal,
                         __global const float4 *radiance, __global const float4 *side,
                         uint has_radiance, uint channel_from, uint channel_to, uint2 pool,
                         __global half *albedo_pool, __global half *normal_pool,
                         __global half *radiance_pool, __global half *shade_pool,
                         __global half *plane_pool) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i;
    uint voxel[64];
    brick_window(child, around, window, window_ready, b, 1, voxel);

    /* each sample: the mean over the voxels present among its 8 */
    float inv_found[27];
    for (uint z = 0; z < 3u; ++z)
        for (uint y = 0; y < 3u; ++y)
            for (uint x = 0; x < 3u; ++x) {
                const uint *v = voxel + z * 16u + y * 4u + x;
                const uint found = (v[0] != OCT_NULL) + (v[1] != OCT_NULL) + (v[4] != OCT_NULL) +
                                   (v[5] != OCT_NULL) + (v[16] != OCT_NULL) + (v[17] != OCT_NULL) +
                                   (v[20] != OCT_NULL) + (v[21] != OCT_NULL);
                inv_found[(z * 3u + y) * 3u + x] = found ? 1.0f / (float)found : 0.0f;
            }
    const int lit = has_radiance != 0u;
    float alpha[64];
    for (uint c = 0; c < 64u; ++c)
        alpha[c] = voxel[c] == OCT_NULL || (channel_from >= 2u && lit) ? 0.0f : albedo[voxel[c]].w;
    __global half *pools[5] = {albedo_pool, normal_pool, radiance_pool, shade_pool, plane_pool};
    for (uint channel = channel_from; channel < channel_to; ++channel) {
        float4 premultiplied[64];
        for (uint c = 0; c < 64u; ++c)
            premultiplied[c] =
                leaf_value(channel, voxel[c], alpha[c], lit, albedo, normal, radiance, side);
        __global half *dst = pools[channel];
        const uint base = brick_base(pool, b);
        for (uint z = 0; z < 3u; ++z)
            for (uint y = 0; y < 3u; ++y)
                for (uint x = 0; x < 3u; ++x) {
                    /* a fixed world order: shared samples agree */
                    const float4 *p = premultiplied + z * 16u + y * 4u + x;
                    const float4 sum =
                        ((p[0] + p[1]) + (p[4] + p[5])) + ((p[16] + p[17]) + (p[20] + p[21]));
                    brick_store_at(dst, pool, base, (uint3)(x, y, z),
                                   sum * inv_found[(z * 3u + y) * 3u + x]);
                }
    }
}

/* The child lattice of brick b: points 0..6 per axis (point 2i + 1 is the
 * parent's texel i), kept in a table padded to 9^3 (points -1..7) so that
 * every child cell writes its 27 texels without clipping: cell c (0..3 per
 * axis, cells -1..2 around the node) holds points 2c - 1 .. 2c + 1, table
 * entries 2c .. 2c + 2. LATTICE(x, y, z) is point (x, y, z)'s entry.
 * Each entry is the pool texel, or BRICK_NULL where no child brick holds
 * the point (empty space). A point on a face between two cells is held
 * bit-identically by either, so each present cell simply writes the points
 * it holds. (Clipping each cell's writes to 7^3 cost as much as filtering
 * radiance.) */
#define LATTICE_SIDE 9u
#define LATTICE_ENTRIES (LATTICE_SIDE * LATTICE_SIDE * LATTICE_SIDE)
#define LATTICE_STRIDE_Y LATTICE_SIDE
#define LATTICE_STRIDE_Z (LATTICE_SIDE * LATTICE_SIDE)
#define LATTICE(x, y, z) (((z) + 1u) * LATTICE_STRIDE_Z + ((y) + 1u) * LATTICE_STRIDE_Y + (x) + 1u)

inline void lattice_texels(__global const uint *child, __global const uint *around,
                           __global uint *window, uint window_ready, uint b, uint2 pool,
                           uint *texel) {
    uint cell[64];
    brick_window(child, around, window, window_ready, b, 0, cell);
    for (uint e = 0; e < LATTICE_ENTRIES; ++e)
        texel[e] = BRICK_NULL;
    for (uint c = 0; c < 64u; ++c) {
        const uint cb = cell[c];
        if (cb == BRICK_NULL)
            continue;
        const uint base = brick_base(pool, cb);
        uint *first = texel + 2u * ((c >> 4) * LATTICE_STRIDE_Z +
                                    ((c >> 2) & 3u) * LATTICE_STRIDE_Y + (c & 3u));
        for (uint tz = 0; tz < 3u; ++tz)
            for (uint ty = 0; ty < 3u; ++ty)
                for (uint tx = 0; tx < 3u; ++tx)
                    first[tz * LATTICE_STRIDE_Z + ty * LATTICE_STRIDE_Y + tx] =
                        base + brick_offset(pool, (uint3)(tx, ty, tz));
    }
}

/* Empty space reads 0. Without a branch: which lattice points are empty
 * follows no pattern a CPU could predict, and texel 0 always exists. */
inline float4 texel_load(__global const half *src, uint texel) {
    const int present = texel != BRICK_NULL;
    const float4 v = vload_half4(present ? texel : 0u, src);
    return present ? v : (float4)(0.0f);
}

/* One channel of brick b from the child lattice: separable, z into a 7x7
 * plane, then y, then x. */
inline void filter_channel(const uint *texel, uint2 pool, uint b, __global half *channel) {
    const float w[3] = {0.25f, 0.5f, 0.25f};
    const uint base = brick_base(pool, b);
    float4 shared[49]; /* lattice plane 2k: the last plane of layer k - 1, loaded once */
    for (uint k = 0; k < 3u; ++k) {
        float4 plane[49];
        for (uint y = 0; y < 7u; ++y)
            for (uint x = 0; x < 7u; ++x) {
                const uint i = y * 7u + x;
                const float4 first = k ? shared[i] : texel_load(channel, texel[LATTICE(x, y, 0u)]);
                const float4 last = texel_load(channel, texel[LATTICE(x, y, 2u * k + 2u)]);
                float4 s = (float4)(0.0f);
                s += w[0] * first;
                s += w[1] * texel_load(channel, texel[LATTICE(x, y, 2u * k + 1u)]);
                s += w[2] * last;
                plane[i] = s;
                shared[i] = last;
            }
        for (uint j = 0; j < 3u; ++j) {
            float4 row[7];
            for (uint x = 0; x < 7u; ++x)
                row[x] = w[0] * plane[(2u * j) * 7u + x] + w[1] * plane[(2u * j + 1u) * 7u + x] +
                         w[2] * plane[(2u * j + 2u) * 7u + x];
            for (uint t = 0; t < 3u; ++t)
                brick_store_at(channel, pool, base, (uint3)(t, j, k),
                               w[0] * row[2u * t] + w[1] * row[2u * t + 1u] +
                                   w[2] * row[2u * t + 2u]);
        }
    }
}

/* Channels c0 .. c3 (`channels` of them, 1..4) of the level's bricks. */
__kernel void brick_filter(__global const uint *child, __global const uint *around,
                           __global uint *window, uint window_ready, uint first_brick, uint count,
                           uint2 pool, uint channels, __global half *c0, __global half *c1,
                           __global half *c2, __global half *c3) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i;
    uint texel[LATTICE_ENTRIES];
    lattice_texels(child, around, window, window_ready, b, pool, texel);
    filter_channel(texel, pool, b, c0);
    if (channels > 1u)
        filter_channel(texel, pool, b, c1);
    if (channels > 2u)
        filter_channel(texel, pool, b, c2);
    if (channels > 3u)
        filter_channel(texel, pool, b, c3);
}

/* Each half's opacity (w) across its half: the directional filter carries
 * the up and the down direction side by side in one 8-wide value, which
 * halves its arithmetic on 8-wide CPUs. */
inline float8 opacity8(float8 v) {
    return (float8)((float4)(v.s3), (float4)(v.s7));
}

/* Opacity of each half's sample over half its thickness, colour kept. */
inline float8 half_thickness(float8 v) {
    /* 1 - (1 - a)^(1/2) = a / (1 + sqrt(1 - a)), stable near a = 0 */
    return v / (1.0f + sqrt(fmax(1.0f - opacity8(v), 0.0f)));
}

/* Front-to-back composites of three samples met in this order, each half
 * on its own, nested from the back: a + (1 - a.w) (b + (1 - b.w) c) is two
 * dependent steps. */
inline float8 composite3(float8 a, float8 b, float8 c) {
    return a + (1.0f - opacity8(a)) * (b + (1.0f - opacity8(b)) * c);
}

/* Output layer g along `axis` from its 7x7 composited columns ([q][p],
 * lattice p and q across the axis; up in the low half, down in the high),
 * averaged separably. */
inline void store_layer(const float8 column[7][7], uint2 pool, uint base, uint axis, uint g,
                        __global half *up, __global half *down) {
    const float w[3] = {0.25f, 0.5f, 0.25f};
    float8 row[7][3]; /* [q][i]: averaged across p */
    for (uint q = 0; q < 7u; ++q)
        for (uint i = 0; i < 3u; ++i)
            row[q][i] = w[0] * column[q][2u * i] + w[1] * column[q][2u * i + 1u] +
                        w[2] * column[q][2u * i + 2u];
    for (uint m = 0; m < 3u; ++m)
        for (uint i = 0; i < 3u; ++i) {
            uint t[3];
            t[axis] = g;
            t[(axis + 1u) % 3u] = i;
            t[(axis + 2u) % 3u] = m;
            const float8 v =
                w[0] * row[2u * m][i] + w[1] * row[2u * m + 1u][i] + w[2] * row[2u * m + 2u][i];
            const uint3 at = (uint3)(t[0], t[1], t[2]);
            brick_store_at(up, pool, base, at, v.lo);
            brick_store_at(down, pool, base, at, v.hi);
        }
}

/* A leaf texel's darker side: its radiance less its shade. */
inline float4 dark_load(__global const half *radiance, __global const half *shade, uint texel) {
    const float4 r = texel_load(radiance, texel), s = texel_load(shade, texel);
    return (float4)(r.xyz - s.xyz, r.w);
}

/* Both directions along `axis` (0..2) of brick b: `up` travels +axis and
 * reads its child values from src_up, `down` travels -axis from src_down.
 * Lattice points 2g, 2g + 1, 2g + 2 along the axis composite into output g,
 * the end points over half their thickness; with one_source both read
 * src_up, and each point is loaded once for the two (less `shade` when
 * `dark`). */
inline void filter_axis(const uint *texel, uint2 pool, uint b, uint axis,
                        __global const half *src_up, __global const half *src_down, uint one_source,
                        __global const half *shade, uint dark, __global half *up,
                        __global half *down) {
    const uint stride[3] = {1u, LATTICE_STRIDE_Y, LATTICE_STRIDE_Z};
    const uint step = stride[axis], u_step = stride[(axis + 1u) % 3u];
    const uint v_step = stride[(axis + 2u) % 3u];
    const uint base = brick_base(pool, b);
    for (uint g = 0; g < 3u; ++g) {
        float8 column[7][7];
        for (uint q = 0; q < 7u; ++q)
            for (uint p = 0; p < 7u; ++p) {
                const uint at = LATTICE(0u, 0u, 0u) + 2u * g * step + p * u_step + q * v_step;
                const uint t0 = texel[at], t1 = texel[at + step], t2 = texel[at + 2u * step];
                /* All three empty (a present texel has a zero bit): both
                 * composites are 0. Most columns of a surface's lattice are
                 * empty, so this branch, unlike one per texel, pays. */
                if ((t0 & t1 & t2) == BRICK_NULL) {
                    column[q][p] = (float8)(0.0f);
                    continue;
                }
                /* (up's sample, down's sample) at each point */
                float8 v0, v1, v2;
                if (one_source) {
                    const float4 a0 = dark ? dark_load(src_up, shade, t0) : texel_load(src_up, t0);
                    const float4 a1 = dark ? dark_load(src_up, shade, t1) : texel_load(src_up, t1);
                    const float4 a2 = dark ? dark_load(src_up, shade, t2) : texel_load(src_up, t2);
                    v0 = (float8)(a0, a0);
                    v1 = (float8)(a1, a1);
                    v2 = (float8)(a2, a2);
                } else {
                    v0 = (float8)(texel_load(src_up, t0), texel_load(src_down, t0));
                    v1 = (float8)(texel_load(src_up, t1), texel_load(src_down, t1));
                    v2 = (float8)(texel_load(src_up, t2), texel_load(src_down, t2));
                }
                const float8 h0 = half_thickness(v0), h2 = half_thickness(v2);
                /* up meets 0, 1, 2; down meets 2, 1, 0 */
                column[q][p] = composite3((float8)(h0.lo, h2.hi), v1, (float8)(h2.lo, h0.hi));
            }
        store_layer(column, pool, base, axis, g, up, down);
    }
}

/* All six directions of the level's bricks: the three samples along the
 * axis composited front to back (the end ones half as thick), the nine
 * columns averaged with the Gaussian weights. */
__kernel void
brick_filter_dir(__global const uint *child, __global const uint *around, __global uint *window,
                 uint window_ready, uint first_brick, uint count, uint2 pool,
                 __global const half *s0, __global const half *s1, __global const half *s2,
                 __global const half *s3, __global const half *s4, __global const half *s5,
                 __global half *d0, __global half *d1, __global half *d2, __global half *d3,
                 __global half *d4, __global half *d5, uint one_source, __global const half *shade,
                 __global const half *e0, __global const half *e1, __global const half *e2,
                 __global const half *e3, __global const half *e4, __global const half *e5,
                 __global half *f0, __global half *f1, __global half *f2, __global half *f3,
                 __global half *f4, __global half *f5) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint b = first_brick + i;
    uint texel[LATTICE_ENTRIES];
    lattice_texels(child, around, window, window_ready, b, pool, texel);
    /* the brighter sides from s into d, the darker from e into f (or, from
     * the leaves, from radiance less shade) */
    filter_axis(texel, pool, b, 0u, s0, s3, one_source, shade, 0u, d0, d3);
    filter_axis(texel, pool, b, 1u, s1, s4, one_source, shade, 0u, d1, d4);
    filter_axis(texel, pool, b, 2u, s2, s5, one_source, shade, 0u, d2, d5);
    filter_axis(texel, pool, b, 0u, one_source ? s0 : e0, e3, one_source, shade, 1u, f0, f3);
    filter_axis(texel, pool, b, 1u, one_source ? s1 : e1, e4, one_source, shade, 1u, f1, f4);
    filter_axis(texel, pool, b, 2u, one_source ? s2 : e2, e5, one_source, shade, 1u, f2, f5);
}
