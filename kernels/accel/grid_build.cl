/* Uniform grid over triangles (count -> scan -> write -> sort -> ranges).
 *
 * grid_count: one work-item per triangle counts the cells its box touches
 * that the exact triangle/box test accepts; the host scans the counts into
 * write offsets; grid_write emits (cell, triangle) pairs in triangle order; a
 * stable radix sort by cell then keeps triangles ascending within a cell;
 * grid_ranges records each cell's [start, end) and an occupancy bit. Cell boxes are widened by a
 * small fraction of a cell so that a triangle on a cell face is kept by both
 * cells: the grid is conservative, never missing a triangle. */
#include "accel/tri_box.h"
#include "vct_types.h"

inline int grid_cell_range(vct_accel_desc g, float4 a, float4 b, float4 c, float pad, int3 *lo,
                           int3 *hi) {
    const float3 mn = fmin(a.xyz, fmin(b.xyz, c.xyz)) - pad;
    const float3 mx = fmax(a.xyz, fmax(b.xyz, c.xyz)) + pad;
    const int3 last = convert_int3(g.res.xyz) - 1;
    *lo = clamp(convert_int3_rtn((mn - g.origin.xyz) * g.inv_cell.xyz), (int3)(0), last);
    *hi = clamp(convert_int3_rtn((mx - g.origin.xyz) * g.inv_cell.xyz), (int3)(0), last);
    return 1;
}

inline int cell_accepts(vct_accel_desc g, int3 cell, float4 a, float4 b, float4 c, float pad) {
    float v0[3] = {a.x, a.y, a.z}, v1[3] = {b.x, b.y, b.z}, v2[3] = {c.x, c.y, c.z};
    const float3 centre = g.origin.xyz + (convert_float3(cell) + 0.5f) * g.cell_size.xyz;
    const float3 hs = 0.5f * g.cell_size.xyz + pad;
    float ce[3] = {centre.x, centre.y, centre.z}, h[3] = {hs.x, hs.y, hs.z};
    return tri_box_overlap(v0, v1, v2, ce, h);
}

/* Walks the cells triangle t overlaps, in x-fastest order; with `write`
 * stores (cell, t) pairs from keys[out] and ids[out]. Returns the count, so
 * the counting and writing passes cannot disagree. */
inline uint grid_visit(__global const float4 *tri_vertices, uint t, vct_accel_desc g, float pad,
                       int write, __global uint *keys, __global uint *ids, uint out) {
    const float4 a = tri_vertices[3 * t], b = tri_vertices[3 * t + 1], c = tri_vertices[3 * t + 2];
    int3 lo, hi;
    grid_cell_range(g, a, b, c, pad, &lo, &hi);
    uint n = 0;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x)
                if (cell_accepts(g, (int3)(x, y, z), a, b, c, pad)) {
                    if (write) {
                        keys[out + n] = (uint)x + g.res.x * ((uint)y + g.res.y * (uint)z);
                        ids[out + n] = t;
                    }
                    ++n;
                }
    return n;
}

/* pad: how far each cell box is widened (relative to the cell, set by host). */
__kernel void grid_count(__global const float4 *tri_vertices, uint triangles, vct_accel_desc g,
                         float pad, __global uint *counts) {
    const uint t = get_global_id(0);
    if (t < triangles)
        counts[t] = grid_visit(tri_vertices, t, g, pad, 0, counts, counts, 0);
}

__kernel void grid_write(__global const float4 *tri_vertices, uint triangles, vct_accel_desc g,
                         float pad, __global const uint *offsets, __global uint *cell_keys,
                         __global uint *tri_ids) {
    const uint t = get_global_id(0);
    if (t < triangles)
        grid_visit(tri_vertices, t, g, pad, 1, cell_keys, tri_ids, offsets[t]);
}

__kernel void grid_ranges(__global const uint *cell_keys, uint n, __global uint *cell_ranges,
                          __global uint *cell_bits) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint key = cell_keys[i];
    if (i == 0 || cell_keys[i - 1] != key) {
        cell_ranges[2 * key] = i;
        atomic_or(&cell_bits[key >> 5], 1u << (key & 31u));
    }
    if (i == n - 1 || cell_keys[i + 1] != key)
        cell_ranges[2 * key + 1] = i + 1;
}
