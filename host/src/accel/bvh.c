/* The 4-wide BVH's device build (Morton codes -> radix sort -> binary tree ->
 * bottom-up boxes -> collapse level by level), refit and read-back. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "accel/bvh_ploc.h"
#include "accel/tri_vertices.h"
#include "vct/parallel.h"

#define STAGE "bvh build"
#define REFIT_STAGE "bvh refit"
#define NODE_BYTES 128u
#define LEAF_BIT 0x80000000u
#define EMPTY_REF 0xFFFFFFFFu
#define MORTON_BITS 30
#define MAX_TRIANGLES (1u << 27) /* a leaf ref keeps 27 bits for its first triangle */

static size_t at_least_one(uint32_t n) {
    return n ? n : 1u;
}

void vct_bvh_free(vct_bvh *b) {
    if (!b)
        return;
    cl_mem *mems[] = {&b->nodes,    &b->leaf_vertices, &b->tri_ids, &b->tri_vertices,
                      &b->children, &b->parents,       &b->boxes,   &b->arrivals};
    for (size_t i = 0; i < sizeof mems / sizeof *mems; ++i)
        vct_buffer_release(b->ctx, *mems[i]);
    free(b);
}

/* A root with four empty children: what an empty scene traverses. */
static void empty_node(float node[32]) {
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 4; ++c) {
            node[8 * k + c] = INFINITY;
            node[8 * k + 4 + c] = -INFINITY;
        }
    uint32_t refs[8];
    for (int c = 0; c < 8; ++c)
        refs[c] = EMPTY_REF;
    memcpy(&node[24], refs, sizeof refs);
}

/* Sorted leaves' vertices and boxes, then the binary boxes bottom-up. */
static int binary_boxes(vct_context *ctx, vct_bvh *b, cl_program p, const char *stage,
                        vct_error *err) {
    const uint32_t n = b->triangle_count;
    int rc = vct_run_kernel(ctx, p, "bvh_leaves", stage, n, err, 6, VCT_ARG_OF(b->tri_vertices),
                            VCT_ARG(ids, b->tri_ids), VCT_ARG_OF(n), VCT_ARG(pad, b->tolerance),
                            VCT_ARG_OF(b->leaf_vertices), VCT_ARG_OF(b->boxes));
    if (rc == VCT_OK && n > 1)
        rc = vct_buffer_fill_u32(ctx, stage, b->arrivals, 0, n - 1, err);
    if (rc == VCT_OK && n > 1)
        rc = vct_run_kernel(ctx, p, "bvh_bounds", stage, n, err, 5, VCT_ARG_OF(b->children),
                            VCT_ARG_OF(b->parents), VCT_ARG_OF(n), VCT_ARG_OF(b->boxes),
                            VCT_ARG_OF(b->arrivals));
    return rc;
}

/* Morton codes of the triangles' box centres over the scene's frame, sorted
 * with the triangle indices (b->tri_ids). */
static int sorted_codes(vct_context *ctx, vct_bvh *b, const vct_scene_frame *f, cl_program p,
                        cl_mem codes, vct_error *err) {
    const uint32_t n = b->triangle_count;
    cl_float4 lo = {{f->lo[0], f->lo[1], f->lo[2], 0.0f}}, scale;
    for (int k = 0; k < 3; ++k)
        scale.s[k] = 1024.0f / (f->hi[k] - f->lo[k]);
    scale.s[3] = 0.0f;
    int rc = vct_run_kernel(ctx, p, "bvh_morton", STAGE, n, err, 6, VCT_ARG_OF(b->tri_vertices),
                            VCT_ARG_OF(n), VCT_ARG(frame_lo, lo), VCT_ARG(frame_scale, scale),
                            VCT_ARG_OF(codes), VCT_ARG(ids, b->tri_ids));
    if (rc == VCT_OK)
        rc = vct_sort_pairs_u32(ctx, codes, b->tri_ids, n, MORTON_BITS, err);
    return rc;
}

/* Wide nodes level by level from the root: each level's binary refs
 * (frontier) become nodes base..base+size-1 and name the next level's. */
static int collapse(vct_context *ctx, vct_bvh *b, cl_program p, cl_mem ranges, vct_error *err) {
    const uint32_t n = b->triangle_count, cap = (uint32_t)at_least_one(n - 1),
                   leaf_max = VCT_BVH_LEAF_MAX;
    cl_mem frontier[2] = {NULL, NULL}, counts = NULL;
    frontier[0] =
        vct_buffer_create(ctx, STAGE, "bvh frontier", 4ull * cap, CL_MEM_READ_WRITE, NULL, err);
    frontier[1] = frontier[0] ? vct_buffer_create(ctx, STAGE, "bvh next frontier", 4ull * cap,
                                                  CL_MEM_READ_WRITE, NULL, err)
                              : NULL;
    counts = frontier[1] ? vct_buffer_create(ctx, STAGE, "bvh child counts", 4ull * cap,
                                             CL_MEM_READ_WRITE, NULL, err)
                         : NULL;
    int rc = counts ? VCT_OK : (int)err->status;
    const uint32_t root = n == 1 ? LEAF_BIT : 0u;
    if (rc == VCT_OK)
        rc = vct_buffer_write(ctx, STAGE, frontier[0], 0, 4, &root, err);
    uint32_t base = 0, size = 1, depth = 0;
    int cur = 0;
    while (rc == VCT_OK && size > 0) {
        rc = vct_run_kernel(ctx, p, "bvh_collapse_count", STAGE, size, err, 8,
                            VCT_ARG_OF(b->children), VCT_ARG_OF(ranges), VCT_ARG_OF(b->boxes),
                            VCT_ARG_OF(n), VCT_ARG_OF(leaf_max), VCT_ARG(frontier, frontier[cur]),
                            VCT_ARG(frontier_size, size), VCT_ARG_OF(counts));
        uint64_t next = 0;
        if (rc == VCT_OK)
            rc = vct_scan_u32(ctx, counts, counts, size, 0, &next, err);
        const uint32_t next_base = base + size;
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "bvh_collapse_write", STAGE, size, err, 12,
                                VCT_ARG_OF(b->children), VCT_ARG_OF(ranges), VCT_ARG_OF(b->boxes),
                                VCT_ARG_OF(n), VCT_ARG_OF(leaf_max),
                                VCT_ARG(frontier, frontier[cur]), VCT_ARG(frontier_size, size),
                                VCT_ARG(offsets, counts), VCT_ARG_OF(base), VCT_ARG_OF(next_base),
                                VCT_ARG(next_frontier, frontier[!cur]), VCT_ARG_OF(b->nodes));
        base = next_base;
        size = (uint32_t)next;
        cur = !cur;
        ++depth;
        if (rc == VCT_OK && size > 0 && depth >= VCT_BVH_MAX_DEPTH)
            rc = vct_fail(err, VCT_ERR_INPUT,
                          "bvh build: the tree is deeper than %d levels, more than traversal's "
                          "stack holds: use --accel grid for this scene",
                          VCT_BVH_MAX_DEPTH);
    }
    b->node_count = base;
    b->depth = depth;
    vct_buffer_release(ctx, frontier[0]);
    vct_buffer_release(ctx, frontier[1]);
    vct_buffer_release(ctx, counts);
    return rc;
}

static int allocate(vct_context *ctx, vct_bvh *b, cl_mem *codes, cl_mem *ranges, vct_error *err) {
    const uint32_t n = b->triangle_count;
    const size_t inner = at_least_one(n - 1), all = 2ull * n - 1;
    struct {
        cl_mem *mem;
        const char *what;
        size_t bytes;
    } list[] = {
        {&b->nodes, "bvh nodes", NODE_BYTES * inner},
        {&b->leaf_vertices, "bvh leaf vertices", 48ull * n},
        {&b->tri_ids, "bvh triangle order", 4ull * n},
        {codes, "bvh morton codes", 4ull * n},
        {&b->children, "bvh binary children", 8ull * inner},
        {ranges, "bvh binary ranges", 8ull * inner},
        {&b->parents, "bvh binary parents", 4ull * all},
        {&b->boxes, "bvh binary boxes", 32ull * all},
        {&b->arrivals, "bvh arrivals", 4ull * inner},
    };
    for (size_t i = 0; i < sizeof list / sizeof *list; ++i) {
        *list[i].mem = vct_buffer_create(ctx, STAGE, list[i].what, list[i].bytes, CL_MEM_READ_WRITE,
                                         NULL, err);
        if (!*list[i].mem)
            return (int)err->status;
    }
    return VCT_OK;
}

static vct_bvh *build_empty(vct_context *ctx, vct_bvh *b, vct_error *err) {
    float node[32];
    empty_node(node);
    b->nodes = vct_buffer_create(ctx, STAGE, "bvh nodes", NODE_BYTES, CL_MEM_READ_ONLY, node, err);
    b->leaf_vertices = b->nodes ? vct_buffer_create(ctx, STAGE, "bvh leaf vertices", 48,
                                                    CL_MEM_READ_ONLY, NULL, err)
                                : NULL;
    b->tri_ids = b->leaf_vertices ? vct_buffer_create(ctx, STAGE, "bvh triangle order", 4,
                                                      CL_MEM_READ_ONLY, NULL, err)
                                  : NULL;
    if (!b->tri_ids) {
        vct_bvh_free(b);
        return NULL;
    }
    b->node_count = 1;
    b->depth = 1;
    return b;
}

vct_bvh *vct_bvh_build(vct_context *ctx, const vct_scene *s, vct_bvh_builder builder,
                       vct_error *err) {
    vct_bvh *b = calloc(1, sizeof *b);
    if (!b) {
        vct_fail(err, VCT_ERR_MEMORY, "bvh build: out of host memory");
        return NULL;
    }
    b->ctx = ctx;
    const uint32_t n = s->triangle_count;
    if (n >= MAX_TRIANGLES) {
        vct_fail(err, VCT_ERR_INPUT,
                 "bvh build: %u triangles is more than the BVH holds (2^27): use --accel grid", n);
        free(b);
        return NULL;
    }
    b->triangle_count = n;
    vct_scene_frame f;
    vct_scene_frame_of(s, &f);
    b->scene_extent = f.extent;
    b->tolerance = f.tolerance;
    vct_stage_begin(ctx, STAGE);
    int rc = vct_tri_vertices_upload(ctx, s, STAGE, &b->tri_vertices, err);
    if (rc == VCT_OK && n == 0) {
        vct_stage_end(ctx);
        return build_empty(ctx, b, err);
    }
    cl_program p;
    cl_mem codes = NULL, ranges = NULL;
    if (rc == VCT_OK)
        rc = vct_program_get(ctx, "accel/bvh/bvh_build.cl", "", &p, err);
    if (rc == VCT_OK)
        rc = allocate(ctx, b, &codes, &ranges, err);
    if (rc == VCT_OK)
        rc = sorted_codes(ctx, b, &f, p, codes, err);
    if (rc == VCT_OK && builder == VCT_BVH_PLOC) {
        /* Clustering starts from the sorted leaves' boxes. */
        rc = vct_run_kernel(ctx, p, "bvh_leaves", STAGE, n, err, 6, VCT_ARG_OF(b->tri_vertices),
                            VCT_ARG(ids, b->tri_ids), VCT_ARG_OF(n), VCT_ARG(pad, b->tolerance),
                            VCT_ARG_OF(b->leaf_vertices), VCT_ARG_OF(b->boxes));
        if (rc == VCT_OK)
            rc = vct_bvh_ploc(ctx, b, ranges, STAGE, &b->passes, err);
    } else if (rc == VCT_OK && n > 1) {
        rc = vct_run_kernel(ctx, p, "bvh_hierarchy", STAGE, n - 1, err, 5, VCT_ARG_OF(codes),
                            VCT_ARG_OF(n), VCT_ARG_OF(b->children), VCT_ARG_OF(ranges),
                            VCT_ARG_OF(b->parents));
    }
    if (rc == VCT_OK)
        rc = binary_boxes(ctx, b, p, STAGE, err);
    if (rc == VCT_OK)
        rc = collapse(ctx, b, p, ranges, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    vct_buffer_release(ctx, codes);
    vct_buffer_release(ctx, ranges);
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        vct_bvh_free(b);
        return NULL;
    }
    return b;
}

int vct_bvh_refit(vct_context *ctx, vct_bvh *b, const vct_scene *s, vct_error *err) {
    if (s->triangle_count != b->triangle_count)
        return vct_fail(err, VCT_ERR_INPUT,
                        "bvh refit: the scene has %u triangles, the BVH %u: rebuild instead",
                        s->triangle_count, b->triangle_count);
    if (b->triangle_count == 0)
        return VCT_OK;
    vct_stage_begin(ctx, REFIT_STAGE);
    cl_mem fresh = NULL;
    cl_program p;
    int rc = vct_tri_vertices_upload(ctx, s, REFIT_STAGE, &fresh, err);
    if (rc == VCT_OK) {
        vct_buffer_release(ctx, b->tri_vertices);
        b->tri_vertices = fresh;
        rc = vct_program_get(ctx, "accel/bvh/bvh_build.cl", "", &p, err);
    }
    if (rc == VCT_OK)
        rc = binary_boxes(ctx, b, p, REFIT_STAGE, err);
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "bvh_refit", REFIT_STAGE, b->node_count, err, 4,
                            VCT_ARG_OF(b->boxes), VCT_ARG(n, b->triangle_count),
                            VCT_ARG_OF(b->node_count), VCT_ARG_OF(b->nodes));
    if (rc == VCT_OK)
        rc = vct_finish(ctx, REFIT_STAGE, err);
    vct_stage_end(ctx);
    return rc;
}

int vct_bvh_read(vct_context *ctx, const vct_bvh *b, float *nodes, uint32_t *tri_ids,
                 vct_error *err) {
    int rc = vct_buffer_read(ctx, "bvh read", b->nodes, 0, (size_t)NODE_BYTES * b->node_count,
                             nodes, err);
    if (rc == VCT_OK && tri_ids && b->triangle_count)
        rc =
            vct_buffer_read(ctx, "bvh read", b->tri_ids, 0, 4ull * b->triangle_count, tri_ids, err);
    return rc;
}

static double box_area(const float lo[3], const float hi[3]) {
    double e[3];
    for (int k = 0; k < 3; ++k)
        e[k] = hi[k] > lo[k] ? (double)hi[k] - lo[k] : 0.0;
    return 2.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
}

int vct_bvh_cost(vct_context *ctx, const vct_bvh *b, double *sah, double *area, uint32_t *leaves,
                 vct_error *err) {
    float *nodes = malloc((size_t)NODE_BYTES * b->node_count);
    if (!nodes)
        return vct_fail(err, VCT_ERR_MEMORY, "bvh cost: out of host memory");
    int rc = vct_bvh_read(ctx, b, nodes, NULL, err);
    double total = 0.0, root = 0.0;
    *leaves = 0;
    for (uint32_t w = 0; rc == VCT_OK && w < b->node_count; ++w) {
        const float *nd = &nodes[32 * w];
        uint32_t refs[4];
        memcpy(refs, &nd[24], sizeof refs);
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int c = 0; c < 4; ++c) {
            if (refs[c] == EMPTY_REF)
                continue;
            float clo[3], chi[3];
            for (int k = 0; k < 3; ++k) {
                clo[k] = nd[8 * k + c];
                chi[k] = nd[8 * k + 4 + c];
                lo[k] = fminf(lo[k], clo[k]);
                hi[k] = fmaxf(hi[k], chi[k]);
            }
            if (refs[c] & LEAF_BIT) {
                total += box_area(clo, chi) * (double)(((refs[c] >> 27) & 15u) + 1u);
                ++*leaves;
            }
        }
        const double a = box_area(lo, hi);
        total += a;
        if (w == 0)
            root = a;
    }
    *sah = root > 0.0 ? total / root : 0.0;
    if (area)
        *area = total;
    free(nodes);
    return rc;
}
