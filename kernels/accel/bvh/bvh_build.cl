/* A 4-wide BVH built on the device (a linear BVH, Karras 2012, collapsed).
 *
 * bvh_morton: 30-bit Morton code of each triangle's box centre in the scene's
 * frame; the host radix-sorts (code, triangle) pairs. bvh_hierarchy: one
 * work-item per binary internal node finds the range of sorted leaves it
 * covers and where that range splits (the longest common prefix of the codes,
 * ties between equal codes broken by position), so the whole binary tree is
 * built in one launch. bvh_bounds: one work-item per leaf writes its padded
 * box, then climbs; the second child to arrive at a node (an atomic counter)
 * writes the node's box, so each box is written once, after both children.
 * bvh_collapse_count / bvh_collapse_write: level by level from the root, each
 * binary node becomes one 4-wide node by opening its largest-area children;
 * a scan of the internal children per node places the next level, so the
 * layout is the same on every run.
 *
 * Binary node refs: internal i < n-1 is i; leaf j (the j-th sorted triangle)
 * is BVH_LEAF | j. Boxes of both sit in one array: internal i at i, leaf j at
 * n-1+j. Wide node layout: see accel/bvh/bvh_node.h. */
#include "accel/bvh/bvh_node.h"
#include "vct_types.h"

/* Spreads the low 10 bits of x to every third bit. */
inline uint morton_spread(uint x) {
    x = (x | (x << 16)) & 0x030000FFu;
    x = (x | (x << 8)) & 0x0300F00Fu;
    x = (x | (x << 4)) & 0x030C30C3u;
    x = (x | (x << 2)) & 0x09249249u;
    return x;
}

__kernel void bvh_morton(__global const float4 *tri_vertices, uint n, float4 frame_lo,
                         float4 frame_scale, __global uint *codes, __global uint *ids) {
    const uint t = get_global_id(0);
    if (t >= n)
        return;
    const float3 a = tri_vertices[3 * t].xyz, b = tri_vertices[3 * t + 1].xyz,
                 c = tri_vertices[3 * t + 2].xyz;
    const float3 centre = 0.5f * (fmin(a, fmin(b, c)) + fmax(a, fmax(b, c)));
    const float3 q = clamp((centre - frame_lo.xyz) * frame_scale.xyz, 0.0f, 1023.0f);
    const uint3 qi = convert_uint3(q);
    codes[t] = (morton_spread(qi.x) << 2) | (morton_spread(qi.y) << 1) | morton_spread(qi.z);
    ids[t] = t;
}

/* Length of the common prefix of sorted keys i and j; -1 outside [0, n).
 * Equal codes compare by position, so every key is distinct. */
inline int prefix(__global const uint *codes, uint n, int i, int j) {
    if (j < 0 || j >= (int)n)
        return -1;
    const uint a = codes[i], b = codes[j];
    return a != b ? (int)clz(a ^ b) : 32 + (int)clz((uint)i ^ (uint)j);
}

inline uint leaf_or_internal(int index, int first, int last) {
    return first == last ? (BVH_LEAF | (uint)index) : (uint)index;
}

__kernel void bvh_hierarchy(__global const uint *codes, uint n, __global uint2 *children,
                            __global uint2 *ranges, __global uint *parents) {
    const int i = (int)get_global_id(0);
    if (i >= (int)n - 1)
        return;
    /* Direction of the range: towards the neighbour with the longer prefix. */
    const int d = prefix(codes, n, i, i + 1) - prefix(codes, n, i, i - 1) > 0 ? 1 : -1;
    const int min_prefix = prefix(codes, n, i, i - d);
    int span_max = 2;
    while (prefix(codes, n, i, i + span_max * d) > min_prefix)
        span_max <<= 1;
    int span = 0;
    for (int step = span_max >> 1; step > 0; step >>= 1)
        if (prefix(codes, n, i, i + (span + step) * d) > min_prefix)
            span += step;
    const int j = i + span * d;
    const int node_prefix = prefix(codes, n, i, j);
    /* Split: the last position sharing more than node_prefix bits with i. */
    int split = 0, step = span;
    do {
        step = (step + 1) >> 1;
        if (prefix(codes, n, i, i + (split + step) * d) > node_prefix)
            split += step;
    } while (step > 1);
    const int gamma = i + split * d + min(d, 0);
    const int first = min(i, j), last = max(i, j);
    const uint left = leaf_or_internal(gamma, first, gamma);
    const uint right = leaf_or_internal(gamma + 1, gamma + 1, last);
    children[i] = (uint2)(left, right);
    ranges[i] = (uint2)((uint)first, (uint)last);
    parents[bvh_box_slot(left, n)] = (uint)i;
    parents[bvh_box_slot(right, n)] = (uint)i;
}

/* The sorted triangles' vertices (3 float4 each; the first's w holds the
 * original triangle index) and their boxes, widened by pad. */
__kernel void bvh_leaves(__global const float4 *tri_vertices, __global const uint *ids, uint n,
                         float pad, __global float4 *leaf_vertices, __global float4 *boxes) {
    const uint j = get_global_id(0);
    if (j >= n)
        return;
    const uint t = ids[j];
    const float4 a = tri_vertices[3 * t], b = tri_vertices[3 * t + 1], c = tri_vertices[3 * t + 2];
    leaf_vertices[3 * j] = (float4)(a.xyz, as_float(t));
    leaf_vertices[3 * j + 1] = (float4)(b.xyz, a.w); /* the alpha-mask slot, alpha_mask.h */
    leaf_vertices[3 * j + 2] = (float4)(c.xyz, 0.0f);
    const uint slot = bvh_box_slot(BVH_LEAF | j, n);
    boxes[2 * slot] = (float4)(fmin(a.xyz, fmin(b.xyz, c.xyz)) - pad, 0.0f);
    boxes[2 * slot + 1] = (float4)(fmax(a.xyz, fmax(b.xyz, c.xyz)) + pad, 0.0f);
}

/* Bottom-up boxes: arrivals counts the children done per internal node
 * (zeroed by the host). The box loads are volatile so that a device with
 * non-coherent caches reads what the other child's work-item wrote. */
__kernel void bvh_bounds(__global const uint2 *children, __global const uint *parents, uint n,
                         volatile __global float4 *boxes, __global uint *arrivals) {
    const uint j = get_global_id(0);
    if (j >= n || n < 2)
        return;
    uint node = parents[bvh_box_slot(BVH_LEAF | j, n)];
    for (;;) {
        mem_fence(CLK_GLOBAL_MEM_FENCE);
        if (atomic_inc(&arrivals[node]) == 0u)
            return; /* the sibling's work-item finishes this node */
        mem_fence(CLK_GLOBAL_MEM_FENCE);
        const uint2 ch = children[node];
        const uint l = bvh_box_slot(ch.x, n), r = bvh_box_slot(ch.y, n);
        boxes[2 * node] = fmin(boxes[2 * l], boxes[2 * r]);
        boxes[2 * node + 1] = fmax(boxes[2 * l + 1], boxes[2 * r + 1]);
        if (node == 0u)
            return;
        node = parents[node];
    }
}

inline float box_area(__global const float4 *boxes, uint slot) {
    const float3 e = fmax(boxes[2 * slot + 1].xyz - boxes[2 * slot].xyz, 0.0f);
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

inline uint binary_count(__global const uint2 *ranges, uint ref) {
    if (ref & BVH_LEAF)
        return 1u;
    const uint2 r = ranges[ref];
    return r.y - r.x + 1u;
}

/* The binary nodes that become one wide node's children: start from the
 * node's two children and open the largest-area child with more than
 * leaf_max triangles until there are BVH_WIDTH. Returns the child count. */
inline uint wide_children(__global const uint2 *children, __global const uint2 *ranges,
                          __global const float4 *boxes, uint n, uint leaf_max, uint ref,
                          uint slots[BVH_WIDTH]) {
    if (ref == BVH_EMPTY)
        return 0u;
    if ((ref & BVH_LEAF) || binary_count(ranges, ref) <= leaf_max) {
        slots[0] = ref;
        return 1u;
    }
    slots[0] = children[ref].x;
    slots[1] = children[ref].y;
    uint count = 2u;
    while (count < BVH_WIDTH) {
        int best = -1;
        float best_area = -1.0f;
        for (uint s = 0; s < count; ++s)
            if (binary_count(ranges, slots[s]) > leaf_max) {
                const float a = box_area(boxes, bvh_box_slot(slots[s], n));
                if (a > best_area) {
                    best_area = a;
                    best = (int)s;
                }
            }
        if (best < 0)
            break;
        const uint2 ch = children[slots[best]];
        slots[best] = ch.x;
        slots[count++] = ch.y;
    }
    return count;
}

inline uint opens(__global const uint2 *ranges, uint leaf_max, uint ref) {
    return binary_count(ranges, ref) > leaf_max;
}

__kernel void bvh_collapse_count(__global const uint2 *children, __global const uint2 *ranges,
                                 __global const float4 *boxes, uint n, uint leaf_max,
                                 __global const uint *frontier, uint frontier_size,
                                 __global uint *counts) {
    const uint f = get_global_id(0);
    if (f >= frontier_size)
        return;
    uint slots[BVH_WIDTH];
    const uint c = wide_children(children, ranges, boxes, n, leaf_max, frontier[f], slots);
    uint inner = 0;
    for (uint s = 0; s < c; ++s)
        inner += opens(ranges, leaf_max, slots[s]);
    counts[f] = inner;
}

/* Writes wide node base + f for frontier entry f and the binary refs of the
 * next level at next_frontier[offsets[f]...]; the wide index of those is
 * next_base + their position. */
__kernel void bvh_collapse_write(__global const uint2 *children, __global const uint2 *ranges,
                                 __global const float4 *boxes, uint n, uint leaf_max,
                                 __global const uint *frontier, uint frontier_size,
                                 __global const uint *offsets, uint base, uint next_base,
                                 __global uint *next_frontier, __global float4 *nodes) {
    const uint f = get_global_id(0);
    if (f >= frontier_size)
        return;
    uint slots[BVH_WIDTH];
    const uint c = wide_children(children, ranges, boxes, n, leaf_max, frontier[f], slots);
    float lo[3][BVH_WIDTH], hi[3][BVH_WIDTH];
    uint refs[BVH_WIDTH], sources[BVH_WIDTH];
    uint next = offsets[f];
    for (uint s = 0; s < BVH_WIDTH; ++s) {
        if (s >= c) {
            for (int k = 0; k < 3; ++k) {
                lo[k][s] = INFINITY;
                hi[k][s] = -INFINITY;
            }
            refs[s] = sources[s] = BVH_EMPTY;
            continue;
        }
        const uint ref = slots[s], slot = bvh_box_slot(ref, n);
        const float4 blo = boxes[2 * slot], bhi = boxes[2 * slot + 1];
        lo[0][s] = blo.x, lo[1][s] = blo.y, lo[2][s] = blo.z;
        hi[0][s] = bhi.x, hi[1][s] = bhi.y, hi[2][s] = bhi.z;
        sources[s] = ref;
        if (opens(ranges, leaf_max, ref)) {
            next_frontier[next] = ref;
            refs[s] = next_base + next++;
        } else {
            const uint first = (ref & BVH_LEAF) ? (ref & ~BVH_LEAF) : ranges[ref].x;
            refs[s] = bvh_leaf_ref(first, binary_count(ranges, ref));
        }
    }
    __global float4 *node = nodes + BVH_NODE_FLOAT4S * (base + f);
    for (int k = 0; k < 3; ++k) {
        node[2 * k] = vload4(0, lo[k]);
        node[2 * k + 1] = vload4(0, hi[k]);
    }
    node[BVH_NODE_REFS] = as_float4(vload4(0, refs));
    node[BVH_NODE_SOURCES] = as_float4(vload4(0, sources));
}

/* Refit: every wide node's child boxes again from the binary boxes it was
 * made of (its sources), after bvh_leaves and bvh_bounds on new positions. */
__kernel void bvh_refit(__global const float4 *boxes, uint n, uint node_count,
                        __global float4 *nodes) {
    const uint w = get_global_id(0);
    if (w >= node_count)
        return;
    __global float4 *node = nodes + BVH_NODE_FLOAT4S * w;
    const uint4 src = as_uint4(node[BVH_NODE_SOURCES]);
    const uint sources[BVH_WIDTH] = {src.x, src.y, src.z, src.w};
    float lo[3][BVH_WIDTH], hi[3][BVH_WIDTH];
    for (uint s = 0; s < BVH_WIDTH; ++s) {
        float4 blo = (float4)(INFINITY), bhi = (float4)(-INFINITY);
        if (sources[s] != BVH_EMPTY) {
            const uint slot = bvh_box_slot(sources[s], n);
            blo = boxes[2 * slot];
            bhi = boxes[2 * slot + 1];
        }
        lo[0][s] = blo.x, lo[1][s] = blo.y, lo[2][s] = blo.z;
        hi[0][s] = bhi.x, hi[1][s] = bhi.y, hi[2][s] = bhi.z;
    }
    for (int k = 0; k < 3; ++k) {
        node[2 * k] = vload4(0, lo[k]);
        node[2 * k + 1] = vload4(0, hi[k]);
    }
}
