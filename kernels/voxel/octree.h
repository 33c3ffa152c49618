/* Sparse voxel octree layout and traversal, shared by every kernel that
 * reads the octree.
 *
 * Nodes live in one pool. Node 0 is the root; every other node belongs to a
 * tile of 8 siblings, so node n >= 1 is octant (n - 1) & 7 of tile (n - 1) >> 3.
 * child[n] is the first node of n's child tile, or at the leaf level the
 * index of n's voxel; OCT_NULL marks a node with no geometry below it.
 * Octant bits: 1 = +x, 2 = +y, 4 = +z. Voxel keys are Morton codes with the
 * same bit order (bit 3k = x bit k), so a key's top bits name its ancestors.
 * Neighbour links: 6 per node, order +x, +y, +z, -x, -y, -z. */
#ifndef VCT_OCTREE_H
#define VCT_OCTREE_H

#define OCT_NULL 0xffffffffu

inline uint morton_spread(uint v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    return (v | (v << 2)) & 0x09249249u;
}

inline uint morton_encode(uint3 c) {
    return morton_spread(c.x) | (morton_spread(c.y) << 1) | (morton_spread(c.z) << 2);
}

inline uint morton_compact(uint v) {
    v &= 0x09249249u;
    v = (v | (v >> 2)) & 0x030c30c3u;
    v = (v | (v >> 4)) & 0x0300f00fu;
    v = (v | (v >> 8)) & 0x030000ffu;
    return (v | (v >> 16)) & 0x3ffu;
}

inline uint3 morton_decode(uint key) {
    return (uint3)(morton_compact(key), morton_compact(key >> 1), morton_compact(key >> 2));
}

/* Octant, within its parent, of the level-`level` ancestor of leaf key `key`. */
inline uint octant_of_key(uint key, uint levels, uint level) {
    return (key >> (3u * (levels - level))) & 7u;
}

/* Octant of the cell that is `shift` levels above `cell`, within its parent. */
inline uint octant_of_cell(uint3 cell, uint shift) {
    return ((cell.x >> shift) & 1u) | (((cell.y >> shift) & 1u) << 1) |
           (((cell.z >> shift) & 1u) << 2);
}

/* The node covering `cell` (coordinates in cells of `level`), or OCT_NULL
 * where an ancestor has no children. The node found may itself be empty. */
inline uint octree_node_at(__global const uint *child, uint3 cell, uint level) {
    uint node = 0;
    for (uint l = 1; l <= level; ++l) {
        const uint first = child[node];
        if (first == OCT_NULL)
            return OCT_NULL;
        node = first + octant_of_cell(cell, level - l);
    }
    return node;
}

/* The node of `level` at `cell` if geometry lies in it, else OCT_NULL. */
inline uint octree_find(__global const uint *child, uint3 cell, uint level) {
    const uint node = octree_node_at(child, cell, level);
    return node != OCT_NULL && child[node] != OCT_NULL ? node : OCT_NULL;
}

/* Descends towards leaf cell `cell` while nodes have geometry, no deeper
 * than `max_level`; returns the deepest such node and its level. At
 * *level == levels, child[node] is the voxel. */
inline uint octree_descend_to(__global const uint *child, uint3 cell, uint levels, uint max_level,
                              uint *level) {
    uint node = 0, l = 0;
    while (l < max_level) {
        const uint first = child[node];
        if (first == OCT_NULL)
            break;
        ++l;
        node = first + octant_of_cell(cell, levels - l);
    }
    *level = l;
    return node;
}

inline uint octree_descend(__global const uint *child, uint3 cell, uint levels, uint *level) {
    return octree_descend_to(child, cell, levels, levels, level);
}

/* The voxel at leaf cell `cell`, or OCT_NULL where it holds no geometry. */
inline uint octree_leaf_voxel(__global const uint *child, uint3 cell, uint levels) {
    uint level;
    const uint node = octree_descend(child, cell, levels, &level);
    return level == levels ? child[node] : OCT_NULL;
}

#endif
