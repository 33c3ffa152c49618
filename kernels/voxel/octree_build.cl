/* Sparse voxel octree, built level by level from the root (octree.h has
 * the layout). For each level l:
 *   oct_flag      each voxel steps to its node at level l and flags it;
 *   (host)        an inclusive scan of the flags numbers the flagged nodes;
 *   oct_allocate  flagged node j gets child tile number scan[j] - 1 of level
 *                 l + 1: compact, in node order, the same on every run;
 *   oct_init      clears the new nodes and links them to their neighbours.
 * oct_leaves finally points each leaf at its voxel. oct_level_histogram
 * counts the nodes of every level beforehand, so the pool is allocated once
 * at its exact size and the scans' totals can be checked against it. */
#include "voxel/octree.h"

#define OCT_SPAN 256u

/* hist[l] += number of voxels whose level-l ancestor differs from the
 * previous voxel's but whose level-(l-1) ancestor does not (keys sorted). */
__kernel void oct_level_histogram(__global const uint *keys, uint voxels, uint levels,
                                  __global uint *hist) {
    const uint begin = get_global_id(0) * OCT_SPAN;
    if (begin >= voxels)
        return;
    uint local_hist[11] = {0};
    const uint end = min(begin + OCT_SPAN, voxels);
    for (uint i = begin; i < end; ++i) {
        if (i == 0) {
            local_hist[1] += 1;
            continue;
        }
        const uint diff = keys[i] ^ keys[i - 1];
        const uint top = 31u - clz(diff); /* diff != 0: keys are unique */
        local_hist[levels - top / 3u] += 1;
    }
    for (uint l = 1; l <= levels; ++l)
        if (local_hist[l])
            atomic_add(&hist[l], local_hist[l]);
}

__kernel void oct_flag(__global const uint *keys, uint voxels, uint levels, uint level,
                       uint level_start, __global const uint *child, __global uint *current,
                       __global uint *flags) {
    const uint i = get_global_id(0);
    if (i >= voxels)
        return;
    const uint node = level == 0 ? 0u : child[current[i]] + octant_of_key(keys[i], levels, level);
    current[i] = node;
    flags[node - level_start] = 1u;
}

__kernel void oct_allocate(uint level_start, uint count, uint next_start,
                           __global const uint *scanned, __global uint *child,
                           __global uint *tile_parent) {
    const uint j = get_global_id(0);
    if (j >= count)
        return;
    const uint node = level_start + j;
    const uint before = j == 0 ? 0u : scanned[j - 1];
    if (scanned[j] == before) {
        child[node] = OCT_NULL;
        return;
    }
    const uint first = next_start + 8u * before;
    child[node] = first;
    tile_parent[(first - 1u) >> 3] = node;
}

/* New nodes of one level: no children yet; neighbours from the parent's. */
__kernel void oct_init(uint level_start, uint count, __global uint *child,
                       __global const uint *tile_parent, __global uint *neighbours) {
    const uint j = get_global_id(0);
    if (j >= count)
        return;
    const uint node = level_start + j;
    const uint octant = (node - 1u) & 7u, tile_first = node - octant;
    const uint parent = tile_parent[(node - 1u) >> 3];
    child[node] = OCT_NULL;
    for (uint dir = 0; dir < 6; ++dir) {
        const uint bit = 1u << (dir % 3u);
        const int towards_high = dir < 3u;
        uint link;
        if (towards_high != ((octant & bit) != 0u)) {
            link = tile_first + (octant ^ bit); /* sibling in the same tile */
        } else {
            const uint across = neighbours[6u * parent + dir];
            const uint first = across == OCT_NULL ? OCT_NULL : child[across];
            link = first == OCT_NULL ? OCT_NULL : first + (octant ^ bit);
        }
        neighbours[6u * node + dir] = link;
    }
}

/* current[i]: voxel i's node at level levels - 1. */
__kernel void oct_leaves(__global const uint *keys, uint voxels, uint levels,
                         __global const uint *current, __global uint *child) {
    const uint i = get_global_id(0);
    if (i < voxels)
        child[child[current[i]] + octant_of_key(keys[i], levels, levels)] = i;
}

/* Test access to the traversal functions: query = (x, y, z, level). */
__kernel void oct_lookup(__global const uint *child, __global const uint4 *queries, uint n,
                         __global uint *nodes) {
    const uint i = get_global_id(0);
    if (i < n)
        nodes[i] = octree_node_at(child, queries[i].xyz, queries[i].w);
}
