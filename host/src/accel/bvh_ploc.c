/* PLOC passes on the device: nearest neighbours, mutual pairs merged,
 * compaction, until one cluster is left; then the depth-first layout. */
#include "accel/bvh_ploc.h"
#include "vct/parallel.h"

#define LEAF_BIT 0x80000000u

typedef struct ploc_buffers {
    cl_mem clusters, merged, nearest, offsets, keep, sizes, leaf_place, placed_ids, placed_parents;
    cl_mem packed; /* the clusters' boxes in place order */
} ploc_buffers;

static void release_all(vct_context *ctx, ploc_buffers *t) {
    cl_mem *m[] = {&t->clusters, &t->merged,     &t->nearest,    &t->offsets,        &t->keep,
                   &t->sizes,    &t->leaf_place, &t->placed_ids, &t->placed_parents, &t->packed};
    for (size_t i = 0; i < sizeof m / sizeof *m; ++i) {
        vct_buffer_release(ctx, *m[i]);
        *m[i] = NULL;
    }
}

static int allocate(vct_context *ctx, uint32_t n, const char *stage, ploc_buffers *t,
                    vct_error *err) {
    struct {
        cl_mem *mem;
        const char *what;
        size_t bytes;
    } list[] = {
        {&t->clusters, "ploc clusters", 4ull * n},
        {&t->merged, "ploc merged clusters", 4ull * n},
        {&t->nearest, "ploc nearest neighbours", 4ull * n},
        {&t->offsets, "ploc merge offsets", 4ull * n},
        {&t->keep, "ploc kept places", 4ull * n},
        {&t->sizes, "ploc subtree sizes", 4ull * (2ull * n - 1)},
        {&t->leaf_place, "ploc leaf places", 4ull * n},
        {&t->placed_ids, "ploc placed triangles", 4ull * n},
        {&t->placed_parents, "ploc placed parents", 4ull * (2ull * n - 1)},
        {&t->packed, "ploc cluster boxes", 32ull * n},
    };
    for (size_t i = 0; i < sizeof list / sizeof *list; ++i) {
        *list[i].mem = vct_buffer_create(ctx, stage, list[i].what, list[i].bytes, CL_MEM_READ_WRITE,
                                         NULL, err);
        if (!*list[i].mem)
            return (int)err->status;
    }
    return VCT_OK;
}

/* Merges until one cluster is left; nodes numbered from n-2 down. */
static int cluster(vct_context *ctx, vct_bvh *b, cl_program p, ploc_buffers *t, const char *stage,
                   uint32_t *passes, vct_error *err) {
    const uint32_t n = b->triangle_count;
    int rc = vct_run_kernel(ctx, p, "ploc_init", stage, n, err, 3, VCT_ARG_OF(n),
                            VCT_ARG_OF(t->clusters), VCT_ARG_OF(t->sizes));
    uint32_t m = n, top = n - 2;
    *passes = 0;
    while (rc == VCT_OK && m > 1) {
        const uint32_t radius = m > VCT_PLOC_WIDE_BELOW ? VCT_PLOC_RADIUS : VCT_PLOC_RADIUS_WIDE;
        rc = vct_run_kernel(ctx, p, "ploc_gather", stage, m, err, 5, VCT_ARG_OF(t->clusters),
                            VCT_ARG_OF(m), VCT_ARG_OF(b->boxes), VCT_ARG_OF(n),
                            VCT_ARG_OF(t->packed));
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "ploc_nearest", stage, m, err, 4, VCT_ARG_OF(t->packed),
                                VCT_ARG_OF(m), VCT_ARG_OF(radius), VCT_ARG_OF(t->nearest));
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "ploc_flags", stage, m, err, 3, VCT_ARG_OF(t->nearest),
                                VCT_ARG_OF(m), VCT_ARG(flags, t->offsets));
        uint64_t merges = 0;
        if (rc == VCT_OK)
            rc = vct_scan_u32(ctx, t->offsets, t->offsets, m, 0, &merges, err);
        if (rc == VCT_OK && merges == 0)
            rc = vct_fail(err, VCT_ERR_OPENCL,
                          "%s: a clustering pass merged nothing (a device fault): use --accel grid",
                          stage);
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "ploc_merge", stage, m, err, 12, VCT_ARG_OF(t->clusters),
                                VCT_ARG_OF(t->nearest), VCT_ARG_OF(m), VCT_ARG_OF(t->offsets),
                                VCT_ARG_OF(top), VCT_ARG_OF(n), VCT_ARG_OF(b->children),
                                VCT_ARG_OF(b->parents), VCT_ARG_OF(b->boxes), VCT_ARG_OF(t->sizes),
                                VCT_ARG_OF(t->merged), VCT_ARG_OF(t->keep));
        uint32_t left = 0;
        if (rc == VCT_OK)
            rc = vct_compact_u32(ctx, t->merged, t->keep, t->clusters, m, &left, err);
        top -= (uint32_t)merges;
        m = left;
        ++*passes;
    }
    return rc;
}

int vct_bvh_ploc(vct_context *ctx, vct_bvh *b, cl_mem ranges, const char *stage, uint32_t *passes,
                 vct_error *err) {
    const uint32_t n = b->triangle_count;
    *passes = 0;
    if (n < 2)
        return VCT_OK;
    cl_program p;
    ploc_buffers t = {0};
    int rc = vct_program_get(ctx, "accel/bvh/bvh_ploc.cl", "", &p, err);
    if (rc == VCT_OK)
        rc = allocate(ctx, n, stage, &t, err);
    if (rc == VCT_OK)
        rc = cluster(ctx, b, p, &t, stage, passes, err);
    const size_t slots = 2ull * n - 1;
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "ploc_layout", stage, slots, err, 6, VCT_ARG_OF(b->children),
                            VCT_ARG_OF(b->parents), VCT_ARG_OF(t.sizes), VCT_ARG_OF(n),
                            VCT_ARG_OF(ranges), VCT_ARG_OF(t.leaf_place));
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "ploc_relabel_nodes", stage, n - 1, err, 3,
                            VCT_ARG_OF(b->children), VCT_ARG_OF(n), VCT_ARG_OF(t.leaf_place));
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "ploc_relabel_leaves", stage, n, err, 6,
                            VCT_ARG(ids, b->tri_ids), VCT_ARG_OF(b->parents), VCT_ARG_OF(n),
                            VCT_ARG_OF(t.leaf_place), VCT_ARG_OF(t.placed_ids),
                            VCT_ARG_OF(t.placed_parents));
    if (rc == VCT_OK) { /* the placed order and parents replace the sorted ones */
        cl_mem ids = b->tri_ids, parents = b->parents;
        b->tri_ids = t.placed_ids;
        b->parents = t.placed_parents;
        t.placed_ids = ids;
        t.placed_parents = parents;
    }
    release_all(ctx, &t);
    return rc;
}
