/* The BVH's quality step: agglomerative clustering of the Morton-sorted
 * triangles, PLOC (Meister and Bittner 2018), in place of the linear
 * hierarchy. Each pass, every cluster finds its nearest neighbour within
 * `radius` places in the sorted order, by the surface area of their union
 * (ties to the lower place, so that the order over pairs is strict and the
 * closest pair of a pass is always mutual); mutual pairs merge into a new node,
 * at the lower place; a scan numbers the new nodes and compaction drops the
 * merged-away places. Passes repeat until one cluster, the root, is left. New
 * nodes are numbered from n-2 down, so the root is node 0.
 *
 * The tree is then laid out depth first (ploc_layout): a subtree's triangles
 * become consecutive, so the binary nodes carry ranges as the linear
 * hierarchy's do and the collapse to 4-wide nodes is shared. Binary refs,
 * box slots and sizes follow bvh_build.cl. */
#include "accel/bvh/bvh_node.h"

inline float union_area(float4 alo, float4 ahi, float4 blo, float4 bhi) {
    const float3 e = fmax(ahi.xyz, bhi.xyz) - fmin(alo.xyz, blo.xyz);
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

__kernel void ploc_init(uint n, __global uint *clusters, __global uint *sizes) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    clusters[i] = BVH_LEAF | i;
    sizes[n - 1u + i] = 1u;
}

/* The clusters' boxes in place order (lo, hi), so that the neighbour search
 * reads them in a row instead of through the clusters' box slots. */
__kernel void ploc_gather(__global const uint *clusters, uint m, __global const float4 *boxes,
                          uint n, __global float4 *packed) {
    const uint i = get_global_id(0);
    if (i >= m)
        return;
    const uint si = bvh_box_slot(clusters[i], n);
    packed[2 * i] = boxes[2 * si];
    packed[2 * i + 1] = boxes[2 * si + 1];
}

__kernel void ploc_nearest(__global const float4 *packed, uint m, uint radius,
                           __global uint *nearest) {
    const uint i = get_global_id(0);
    if (i >= m)
        return;
    const float4 lo = packed[2 * i], hi = packed[2 * i + 1];
    const uint first = i > radius ? i - radius : 0u, last = min(m - 1u, i + radius);
    float best = INFINITY;
    uint best_j = i;
    for (uint j = first; j <= last; ++j) {
        if (j == i)
            continue;
        const float a = union_area(lo, hi, packed[2 * j], packed[2 * j + 1]);
        if (a < best) { /* strictly: the lower place keeps a tie */
            best = a;
            best_j = j;
        }
    }
    nearest[i] = best_j;
}

/* 1 where place i opens a merge: i and its neighbour choose each other, and
 * i is the lower place. */
__kernel void ploc_flags(__global const uint *nearest, uint m, __global uint *flags) {
    const uint i = get_global_id(0);
    if (i >= m)
        return;
    const uint j = nearest[i];
    flags[i] = (uint)(j != i && nearest[j] == i && i < j);
}

/* offsets: the exclusive scan of the flags; top: the number of the first
 * node this pass makes (counting down). keep: whether place i survives. */
__kernel void ploc_merge(__global const uint *clusters, __global const uint *nearest, uint m,
                         __global const uint *offsets, uint top, uint n, __global uint2 *children,
                         __global uint *parents, __global float4 *boxes, __global uint *sizes,
                         __global uint *merged, __global uint *keep) {
    const uint i = get_global_id(0);
    if (i >= m)
        return;
    const uint j = nearest[i];
    const int mutual = j != i && nearest[j] == i;
    if (mutual && i > j) {
        keep[i] = 0u;
        return;
    }
    keep[i] = 1u;
    if (!mutual) {
        merged[i] = clusters[i];
        return;
    }
    const uint node = top - offsets[i];
    const uint a = clusters[i], b = clusters[j];
    const uint sa = bvh_box_slot(a, n), sb = bvh_box_slot(b, n);
    children[node] = (uint2)(a, b);
    parents[sa] = node;
    parents[sb] = node;
    boxes[2 * node] = fmin(boxes[2 * sa], boxes[2 * sb]);
    boxes[2 * node + 1] = fmax(boxes[2 * sa + 1], boxes[2 * sb + 1]);
    sizes[node] = sizes[sa] + sizes[sb];
    merged[i] = node;
}

/* Depth-first place of every node: the triangles left of it are those under
 * the left siblings of the nodes on its path to the root. Internal nodes get
 * their range of places; leaf j (sorted place j) gets its new place. */
__kernel void ploc_layout(__global const uint2 *children, __global const uint *parents,
                          __global const uint *sizes, uint n, __global uint2 *ranges,
                          __global uint *leaf_place) {
    const uint s = get_global_id(0);
    if (s >= 2u * n - 1u)
        return;
    uint offset = 0u, slot = s;
    while (slot != 0u) {
        const uint p = parents[slot];
        const uint2 ch = children[p];
        if (bvh_box_slot(ch.y, n) == slot)
            offset += sizes[bvh_box_slot(ch.x, n)];
        slot = p;
    }
    if (s < n - 1u)
        ranges[s] = (uint2)(offset, offset + sizes[s] - 1u);
    else
        leaf_place[s - (n - 1u)] = offset;
}

/* Leaf refs, the triangle order and the leaves' parents renamed by place. */
__kernel void ploc_relabel_nodes(__global uint2 *children, uint n,
                                 __global const uint *leaf_place) {
    const uint i = get_global_id(0);
    if (i >= n - 1u)
        return;
    uint2 ch = children[i];
    if (ch.x & BVH_LEAF)
        ch.x = BVH_LEAF | leaf_place[ch.x & ~BVH_LEAF];
    if (ch.y & BVH_LEAF)
        ch.y = BVH_LEAF | leaf_place[ch.y & ~BVH_LEAF];
    children[i] = ch;
}

__kernel void ploc_relabel_leaves(__global const uint *ids, __global const uint *parents, uint n,
                                  __global const uint *leaf_place, __global uint *placed_ids,
                                  __global uint *placed_parents) {
    const uint j = get_global_id(0);
    if (j >= n)
        return;
    const uint to = leaf_place[j];
    placed_ids[to] = ids[j];
    placed_parents[n - 1u + to] = parents[n - 1u + j];
    if (j < n - 1u) /* internal nodes keep their parents */
        placed_parents[j] = parents[j];
}
