/* One acceleration structure behind every ray query: the BVH or the grid. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "scene/instances.h"
#include "vct_types.h"

const char *vct_accel_kind_name(vct_accel_kind kind) {
    return kind == VCT_ACCEL_GRID ? "grid" : "bvh";
}

int vct_accel_kind_from_name(const char *name) {
    if (!strcmp(name, "bvh"))
        return VCT_ACCEL_BVH;
    if (!strcmp(name, "grid"))
        return VCT_ACCEL_GRID;
    return -1;
}

vct_accel_kind vct_accel_kind_of(const vct_accel *a) {
    return a->kind;
}

vct_accel *vct_accel_build(vct_context *ctx, const vct_scene *s, const vct_accel_options *options,
                           vct_error *err) {
    vct_accel *a = calloc(1, sizeof *a);
    if (!a) {
        vct_fail(err, VCT_ERR_MEMORY, "accel: out of host memory");
        return NULL;
    }
    if (options)
        a->options = *options;
    a->kind = a->options.kind;
    a->ctx = ctx;
    const double start = vct_now_ms();
    const vct_bvh_levels levels = a->options.bvh_levels;
    const int two = s->instance_count > 0 &&
                    (levels == VCT_BVH_TWO_LEVELS ||
                     (levels == VCT_BVH_LEVELS_AUTO && vct_instances_shared(s))) &&
                    vct_instances_consistent(s);
    if (a->kind == VCT_ACCEL_GRID)
        a->grid = vct_grid_build(ctx, s, a->options.grid_res, err);
    else if (two)
        a->bvh2 = vct_bvh2_build(ctx, s, a->options.bvh_builder, err);
    else
        a->bvh = vct_bvh_build(ctx, s, a->options.bvh_builder, err);
    a->build_ms = vct_now_ms() - start;
    if (!a->grid && !a->bvh && !a->bvh2) {
        free(a);
        return NULL;
    }
    return a;
}

vct_status vct_accel_refit(vct_context *ctx, vct_accel *a, const vct_scene *s, vct_error *err) {
    const double start = vct_now_ms();
    int rc;
    if (a->bvh2) { /* the meshes keep their shape: the top level and vertices again */
        rc = vct_bvh2_move(ctx, a->bvh2, s, err);
    } else if (a->kind == VCT_ACCEL_BVH) {
        rc = vct_bvh_refit(ctx, a->bvh, s, err);
    } else {
        vct_grid *g = vct_grid_build(ctx, s, a->options.grid_res, err);
        rc = g ? VCT_OK : (int)err->status;
        if (g) {
            vct_grid_release(a->grid);
            a->grid = g;
        }
    }
    a->build_ms = vct_now_ms() - start;
    return rc;
}

static double mem_bytes(cl_mem m) {
    size_t bytes = 0;
    if (m && clGetMemObjectInfo(m, CL_MEM_SIZE, sizeof bytes, &bytes, NULL) != CL_SUCCESS)
        bytes = 0;
    return (double)bytes;
}

vct_status vct_accel_info_get(vct_context *ctx, const vct_accel *a, vct_accel_info *info,
                              vct_error *err) {
    memset(info, 0, sizeof *info);
    info->kind = a->kind;
    info->build_ms = a->build_ms;
    if (a->kind == VCT_ACCEL_GRID) {
        const vct_grid *g = a->grid;
        vct_grid_info_get(g, &info->grid);
        info->nodes = g->res[0] * g->res[1] * g->res[2];
        info->leaves = g->references;
        info->bytes = mem_bytes(g->cell_ranges) + mem_bytes(g->cell_bits) + mem_bytes(g->tri_ids) +
                      mem_bytes(g->tri_vertices);
        return VCT_OK;
    }
    if (a->bvh2) {
        const vct_bvh2 *b = a->bvh2;
        info->two_levels = 1;
        info->nodes = b->top_nodes + b->mesh_nodes;
        info->depth = b->depth;
        info->instances = b->instance_count;
        info->mesh_triangles = b->mesh_triangles;
        info->bvh_builder = a->options.bvh_builder;
        info->bytes = mem_bytes(b->nodes) + mem_bytes(b->instances) + mem_bytes(b->tri_ids) +
                      mem_bytes(b->tri_vertices);
        return VCT_OK;
    }
    const vct_bvh *b = a->bvh;
    info->nodes = b->node_count;
    info->depth = b->depth;
    info->passes = b->passes;
    info->bvh_builder = a->options.bvh_builder;
    cl_mem mems[] = {b->nodes,    b->leaf_vertices, b->tri_ids, b->tri_vertices,
                     b->children, b->parents,       b->boxes,   b->arrivals};
    for (size_t i = 0; i < sizeof mems / sizeof *mems; ++i)
        info->bytes += mem_bytes(mems[i]);
    return vct_bvh_cost(ctx, b, &info->sah_cost, NULL, &info->leaves, err);
}

void vct_accel_release(vct_accel *a) {
    if (!a)
        return;
    vct_grid_release(a->grid);
    vct_bvh_free(a->bvh);
    vct_bvh2_free(a->bvh2);
    free(a);
}

const char *vct_accel_program_options(const vct_accel *a) {
    return a->bvh2 ? "-DVCT_ACCEL_BVH2" : a->kind == VCT_ACCEL_BVH ? "-DVCT_ACCEL_BVH" : "";
}

const char *vct_accel_options_join(const vct_accel *a, const char *own, char *out, size_t size) {
    snprintf(out, size, "%s %s", own ? own : "", vct_accel_program_options(a));
    return out;
}

cl_mem vct_accel_tri_vertices(const vct_accel *a) {
    return a->bvh2                    ? a->bvh2->tri_vertices
           : a->kind == VCT_ACCEL_BVH ? a->bvh->tri_vertices
                                      : a->grid->tri_vertices;
}

int vct_accel_set_args(cl_kernel k, const vct_accel *a, const char *stage, vct_error *err) {
    if (a->kind == VCT_ACCEL_GRID)
        return vct_grid_set_args(k, a->grid, stage, err);
    vct_accel_desc desc;
    memset(&desc, 0, sizeof desc);
    if (a->bvh2) {
        const vct_bvh2 *b = a->bvh2;
        desc.origin.s[3] = b->scene_extent;
        desc.cell_size.s[3] = b->tolerance;
        desc.res.s[0] = b->instance_count ? b->top_nodes : 0;
        desc.res.s[3] = b->triangle_count;
        return vct_set_args(err, stage, k, 0, 5, VCT_ARG(accel, desc), VCT_ARG(bvh_nodes, b->nodes),
                            VCT_ARG(bvh_leaf_vertices, b->instances), VCT_ARG_OF(b->tri_ids),
                            VCT_ARG_OF(b->tri_vertices));
    }
    const vct_bvh *b = a->bvh;
    desc.origin.s[3] = b->scene_extent;
    desc.cell_size.s[3] = b->tolerance;
    desc.res.s[0] = b->node_count;
    desc.res.s[3] = b->triangle_count;
    return vct_set_args(err, stage, k, 0, 5, VCT_ARG(accel, desc), VCT_ARG(bvh_nodes, b->nodes),
                        VCT_ARG(bvh_leaf_vertices, b->leaf_vertices), VCT_ARG_OF(b->tri_ids),
                        VCT_ARG_OF(b->tri_vertices));
}

vct_accel_options vct_accel_options_default(void) {
    vct_accel_options o;
    memset(&o, 0, sizeof o);
    o.kind = VCT_ACCEL_BVH;
    o.bvh_builder = VCT_BVH_PLOC;
    return o;
}
