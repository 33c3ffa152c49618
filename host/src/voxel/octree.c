/* Sparse voxel octree over the voxel list (kernels/voxel/octree_build.cl):
 * per-level node counts first, then flag -> scan -> allocate -> init from
 * the root down, then the leaves' voxel pointers. */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "vct_types.h"
#include "voxel/voxels.h"

#define STAGE "octree build"
#define SPAN 256u /* voxels per work-item in oct_level_histogram */

/* Nodes per level from the sorted keys: level l + 1 holds one tile of 8 for
 * every distinct level-l ancestor. */
static int count_levels(vct_context *ctx, vct_voxels *v, cl_program p, vct_error *err) {
    vct_voxel_info *info = &v->info;
    const uint32_t levels = info->levels, nv = info->voxels;
    uint32_t hist[VCT_VOXEL_MAX_LEVELS + 1] = {0};
    cl_mem h =
        vct_buffer_create(ctx, STAGE, "level histogram", sizeof hist, CL_MEM_READ_WRITE, hist, err);
    if (!h)
        return err->status;
    int rc = vct_run_kernel(ctx, p, "oct_level_histogram", STAGE, (nv + SPAN - 1) / SPAN, err, 4,
                            VCT_ARG_OF(v->keys), VCT_ARG(voxels, nv), VCT_ARG_OF(levels),
                            VCT_ARG(hist, h));
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, STAGE, h, 0, sizeof hist, hist, err);
    vct_buffer_release(ctx, h);
    /* distinct: level-(l-1) ancestors with geometry; hist[m]: voxels whose
     * ancestors first differ from the previous voxel's at level m. */
    uint64_t distinct = nv ? 1 : 0, seen = 0, total = 1;
    info->level_nodes[0] = 1;
    for (uint32_t l = 1; l <= levels; ++l) {
        const uint64_t count = 8 * distinct;
        info->level_start[l] = (uint32_t)total;
        info->level_nodes[l] = (uint32_t)count;
        total += count;
        seen += hist[l];
        distinct = seen;
    }
    info->nodes = (uint32_t)total;
    info->node_bytes = 4 * total + 4 * ((total - 1) / 8);
    info->neighbour_bytes = 24 * total;
    if (rc == VCT_OK)
        rc = vct_voxel_buffer_fits(ctx, info, "octree", "neighbour links",
                                   (double)info->neighbour_bytes, err);
    return rc;
}

static int build_levels(vct_context *ctx, vct_voxels *v, cl_program p, vct_error *err) {
    const vct_voxel_info *info = &v->info;
    const uint32_t levels = info->levels, nv = info->voxels;
    uint32_t widest = 1;
    for (uint32_t l = 0; l < levels; ++l)
        widest = info->level_nodes[l] > widest ? info->level_nodes[l] : widest;
    cl_mem current =
        vct_buffer_create(ctx, STAGE, "voxel ancestors", 4ull * nv, CL_MEM_READ_WRITE, NULL, err);
    cl_mem flags = current ? vct_buffer_create(ctx, STAGE, "node flags", 4ull * widest,
                                               CL_MEM_READ_WRITE, NULL, err)
                           : NULL;
    int rc = flags ? vct_buffer_fill_u32(ctx, STAGE, v->neighbours, VCT_NODE_NULL, 6, err)
                   : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, v->child, VCT_NODE_NULL, 1, err);
    for (uint32_t l = 0; l < levels && rc == VCT_OK && nv; ++l) {
        const uint32_t start = info->level_start[l], count = info->level_nodes[l];
        const uint32_t next = info->level_start[l + 1], next_count = info->level_nodes[l + 1];
        rc = vct_buffer_fill_u32(ctx, STAGE, flags, 0, count, err);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "oct_flag", STAGE, nv, err, 8, VCT_ARG_OF(v->keys),
                                VCT_ARG(voxels, nv), VCT_ARG_OF(levels), VCT_ARG(level, l),
                                VCT_ARG(level_start, start), VCT_ARG_OF(v->child),
                                VCT_ARG_OF(current), VCT_ARG_OF(flags));
        uint64_t flagged = 0;
        if (rc == VCT_OK)
            rc = vct_scan_u32(ctx, flags, flags, count, 1, &flagged, err);
        if (rc == VCT_OK && 8 * flagged != next_count)
            rc = vct_fail(err, VCT_ERR_OPENCL,
                          "octree: level %u flagged %llu nodes where the key count gave %u: the "
                          "device computed inconsistent results",
                          l, (unsigned long long)flagged, next_count / 8);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "oct_allocate", STAGE, count, err, 6,
                                VCT_ARG(level_start, start), VCT_ARG_OF(count),
                                VCT_ARG(next_start, next), VCT_ARG(scanned, flags),
                                VCT_ARG_OF(v->child), VCT_ARG_OF(v->tile_parent));
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "oct_init", STAGE, next_count, err, 5,
                                VCT_ARG(level_start, next), VCT_ARG(count, next_count),
                                VCT_ARG_OF(v->child), VCT_ARG_OF(v->tile_parent),
                                VCT_ARG_OF(v->neighbours));
    }
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "oct_leaves", STAGE, nv, err, 5, VCT_ARG_OF(v->keys),
                            VCT_ARG(voxels, nv), VCT_ARG_OF(levels), VCT_ARG_OF(current),
                            VCT_ARG_OF(v->child));
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    vct_buffer_release(ctx, flags);
    vct_buffer_release(ctx, current);
    return rc;
}

vct_status vct_octree_build(vct_context *ctx, vct_voxels *v, vct_error *err) {
    if (v->child)
        return VCT_OK;
    vct_stage_begin(ctx, STAGE);
    cl_program p;
    int rc = vct_program_get(ctx, "voxel/octree_build.cl", "", &p, err);
    if (rc == VCT_OK)
        rc = count_levels(ctx, v, p, err);
    const uint64_t nodes = v->info.nodes;
    if (rc == VCT_OK) {
        v->child =
            vct_buffer_create(ctx, STAGE, "node children", 4 * nodes, CL_MEM_READ_WRITE, NULL, err);
        v->tile_parent = v->child
                             ? vct_buffer_create(ctx, STAGE, "tile parents", 4 * ((nodes - 1) / 8),
                                                 CL_MEM_READ_WRITE, NULL, err)
                             : NULL;
        v->neighbours = v->tile_parent ? vct_buffer_create(ctx, STAGE, "neighbour links",
                                                           24 * nodes, CL_MEM_READ_WRITE, NULL, err)
                                       : NULL;
        rc = v->neighbours ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = build_levels(ctx, v, p, err);
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        cl_mem *mems[] = {&v->child, &v->tile_parent, &v->neighbours};
        for (int i = 0; i < 3; ++i) {
            vct_buffer_release(ctx, *mems[i]);
            *mems[i] = NULL;
        }
    }
    return rc;
}

static int require_octree(const vct_voxels *v, const char *what, vct_error *err) {
    return v->child ? VCT_OK
                    : vct_fail(err, VCT_ERR_INPUT, "%s: build the octree first (vct_octree_build)",
                               what);
}

vct_status vct_octree_read(vct_context *ctx, const vct_voxels *v, uint32_t *child,
                           uint32_t *neighbours, vct_error *err) {
    int rc = require_octree(v, "octree read", err);
    if (rc == VCT_OK && child)
        rc = vct_buffer_read(ctx, "octree read", v->child, 0, 4ull * v->info.nodes, child, err);
    if (rc == VCT_OK && neighbours)
        rc = vct_buffer_read(ctx, "octree read", v->neighbours, 0, 24ull * v->info.nodes,
                             neighbours, err);
    return rc;
}

vct_status vct_octree_lookup(vct_context *ctx, const vct_voxels *v, const uint32_t *queries,
                             uint32_t n, uint32_t *nodes, vct_error *err) {
    const char *stage = "octree lookup";
    int rc = require_octree(v, stage, err);
    cl_program p = NULL;
    if (rc == VCT_OK && n)
        rc = vct_program_get(ctx, "voxel/octree_build.cl", "", &p, err);
    if (rc || n == 0)
        return rc;
    cl_mem q =
        vct_buffer_create(ctx, stage, "queries", 16ull * n, CL_MEM_READ_ONLY, (void *)queries, err);
    cl_mem out =
        q ? vct_buffer_create(ctx, stage, "nodes", 4ull * n, CL_MEM_WRITE_ONLY, NULL, err) : NULL;
    rc = out ? vct_run_kernel(ctx, p, "oct_lookup", stage, n, err, 4, VCT_ARG_OF(v->child),
                              VCT_ARG(queries, q), VCT_ARG_OF(n), VCT_ARG(nodes, out))
             : (int)err->status;
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, out, 0, 4ull * n, nodes, err);
    vct_buffer_release(ctx, out);
    vct_buffer_release(ctx, q);
    return rc;
}
