/* The 4-wide BVH's node layout, shared by its build and its traversal.
 *
 * A node is 8 float4 (128 bytes, two cache lines): its children's boxes as
 * structure of arrays, lo.x hi.x lo.y hi.y lo.z hi.z (one float4 each, one
 * lane per child), so that one ray meets four boxes in a few vector
 * operations; then the children's refs (uint4) and, for refit only, the
 * binary nodes they were made of. An unused child has an empty box
 * (lo = +inf, hi = -inf) that no ray enters, and ref BVH_EMPTY.
 *
 * A child ref is a node index, or BVH_LEAF | (count - 1) << 27 | first: a
 * leaf of count (1 to 16) consecutive triangles in the sorted order. */
#ifndef VCT_BVH_NODE_H
#define VCT_BVH_NODE_H

#define BVH_WIDTH 4
#define BVH_NODE_FLOAT4S 8
#define BVH_NODE_REFS 6
#define BVH_NODE_SOURCES 7
#define BVH_LEAF 0x80000000u
#define BVH_EMPTY 0xFFFFFFFFu
#define BVH_LEAF_COUNT_SHIFT 27
#define BVH_LEAF_FIRST_MASK 0x07FFFFFFu

inline uint bvh_leaf_ref(uint first, uint count) {
    return BVH_LEAF | ((count - 1u) << BVH_LEAF_COUNT_SHIFT) | first;
}

/* Where a binary node's box is: internal nodes first, then the leaves. */
inline uint bvh_box_slot(uint ref, uint n) {
    return (ref & BVH_LEAF) ? n - 1u + (ref & ~BVH_LEAF) : ref;
}

#endif
