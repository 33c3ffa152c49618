/* The photon grid, built as the triangle grid is (seed 000 §2.3): each
 * path's photons of the wanted kinds counted, scanned and written as (cell
 * key, slot) pairs, sorted by key, the photons copied in key order, and each key's
 * range found where the sorted keys change. */
#include "photon/photon.h"
#include "vct_types.h"

/* Photons of the wanted kinds per path (a path's photons fill its first slots). */
__kernel void photon_counts(__global const uint *kinds, uint paths, uint depth, uint kind_mask,
                            __global uint *counts) {
    const uint p = get_global_id(0);
    if (p >= paths)
        return;
    uint n = 0;
    for (uint k = 0; k < depth; ++k) {
        const uint kind = kinds[p * depth + k];
        if (kind == 0u)
            break;
        n += (kind & kind_mask) != 0u ? 1u : 0u;
    }
    counts[p] = n;
}

/* offsets: the exclusive scan of photon_counts. Each path writes its
 * photons' (key, slot) pairs in slot order. */
__kernel void photon_keys(__global const float4 *records, __global const uint *kinds, uint paths,
                          uint depth, uint kind_mask, __global const uint *offsets, float4 origin,
                          uint4 dims, __global uint *keys, __global uint *ids) {
    const uint p = get_global_id(0);
    if (p >= paths)
        return;
    /* A photon on the grid's far faces belongs to the last cell. */
    const int3 last = convert_int3((uint3)(dims.x, dims.y, dims.z)) - 1;
    uint o = offsets[p];
    for (uint k = 0; k < depth; ++k) {
        const uint i = p * depth + k, kind = kinds[i];
        if (kind == 0u)
            break;
        if (!(kind & kind_mask))
            continue;
        const int3 c = photon_cell_of(origin, records[3u * i].xyz);
        const int3 cell = dims.w != 0u ? c : clamp(c, (int3)(0), last);
        keys[o] = photon_cell_key(origin, dims, cell);
        ids[o++] = i;
    }
}

__kernel void photon_reorder(__global const float4 *records, __global const uint *ids, uint count,
                             __global float4 *sorted) {
    const uint j = get_global_id(0);
    if (j >= count)
        return;
    const uint i = ids[j];
    sorted[3u * j] = records[3u * i];
    sorted[3u * j + 1u] = records[3u * i + 1u];
    sorted[3u * j + 2u] = records[3u * i + 2u];
}

/* ranges (a key's [first, end) as two uints) zeroed before. A key's first
 * and end are written by different work-items, so each writes its own
 * uint: a store to one component of a uint2 may be compiled as a load and a
 * store of the whole pair (NVIDIA's OpenCL does), which loses the other's
 * write. */
__kernel void photon_ranges(__global const uint *keys, uint count, __global uint *ranges) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const uint key = keys[i];
    if (i == 0u || keys[i - 1u] != key)
        ranges[2u * key] = i;
    if (i == count - 1u || keys[i + 1u] != key)
        ranges[2u * key + 1u] = i + 1u;
}

/* For checks: the photons within radius of each query point, as the
 * estimates find them (power summed, no BSDF, no filter). */
__kernel void photon_query(PHOTON_GRID_ARGS(map), __global const float4 *points, uint count,
                           float radius, uint flags, __global float4 *sums) {
    const uint i = get_global_id(0);
    if (i >= count)
        return;
    const photon_grid g = PHOTON_GRID_VIEW(map);
    uint found;
    const float3 s =
        photon_estimate(&g, points[i].xyz, (float3)(0.0f, 0.0f, 1.0f), (float3)(0.0f, 0.0f, 1.0f),
                        radius, 0, flags | PHOTON_RAW, -2.0f, &found);
    sums[i] = (float4)(s, (float)found);
}
