/* The level loop of adaptive subsampling: trace the lattice, then per level
 * fill or flag, compact, trace the splitting pixels, split. */
#include <stdlib.h>
#include <string.h>

#include "raytrace/subsample.h"
#include "vct/parallel.h"

typedef struct sub_buffers {
    cl_mem keys, traced, guard, points, squares, refining, flags;
    cl_mem wanted, listed, split_map; /* the pixels to trace, compacted; the squares split */
} sub_buffers;

static void release_all(vct_context *ctx, sub_buffers *b) {
    cl_mem *m[] = {&b->wanted, &b->listed, &b->split_map, &b->keys,     &b->traced,
                   &b->guard,  &b->points, &b->squares,   &b->refining, &b->flags};
    for (size_t i = 0; i < sizeof m / sizeof *m; ++i)
        vct_buffer_release(ctx, *m[i]);
}

static int allocate(vct_context *ctx, const char *stage, size_t pixels, size_t squares,
                    sub_buffers *b, vct_error *err) {
    struct {
        cl_mem *mem;
        const char *what;
        size_t bytes;
    } list[] = {
        {&b->keys, "subsample keys", 4 * pixels},
        {&b->traced, "subsample traced pixels", 4 * pixels},
        {&b->guard, "subsample small-object guard", 4 * ((pixels + 1) / 2)},
        {&b->points, "subsample points", 4 * 5 * squares},
        {&b->squares, "subsample squares", 4 * 4 * squares},
        {&b->refining, "subsample squares to split", 4 * 4 * squares},
        {&b->flags, "subsample split flags", 4 * 4 * squares},
        {&b->wanted, "subsample pixels wanted", 4 * 5 * squares},
        {&b->listed, "subsample pixels to trace", 4 * 5 * squares},
        {&b->split_map, "subsample split squares", 4 * squares},
    };
    for (size_t i = 0; i < sizeof list / sizeof *list; ++i) {
        *list[i].mem = vct_buffer_create(ctx, stage, list[i].what, list[i].bytes, CL_MEM_READ_WRITE,
                                         NULL, err);
        if (!*list[i].mem)
            return (int)err->status;
    }
    int rc = vct_buffer_fill_u32(ctx, stage, b->traced, 0, pixels, err);
    return rc == VCT_OK ? vct_buffer_fill_u32(ctx, stage, b->split_map, 0, squares, err) : rc;
}

/* The corners of every square of the first level, and the squares. */
static int first_level(vct_shaded *sh, uint32_t size, sub_buffers *b, uint32_t *points,
                       uint32_t *squares, vct_error *err) {
    const uint32_t w = (uint32_t)sh->width, h = (uint32_t)sh->height;
    const uint32_t cx = (w - 1 + size - 1) / size, cy = (h - 1 + size - 1) / size;
    uint32_t *list = malloc(4ull * (cx + 1) * (cy + 1)), *sq = malloc(4ull * (cx + 1) * (cy + 1));
    if (!list || !sq) {
        free(list);
        free(sq);
        return vct_fail(err, VCT_ERR_MEMORY, "subsample: out of host memory");
    }
    *points = *squares = 0;
    for (uint32_t j = 0; j <= cy; ++j)
        for (uint32_t i = 0; i <= cx; ++i) {
            const uint32_t x = i * size < w ? i * size : w - 1, y = j * size < h ? j * size : h - 1;
            list[(*points)++] = y * w + x;
            if (i < cx && j < cy)
                sq[(*squares)++] = (j * size) << 16 | (i * size);
        }
    int rc = vct_buffer_write(sh->ctx, sh->stage, b->points, 0, 4ull * *points, list, err);
    if (rc == VCT_OK && *squares)
        rc = vct_buffer_write(sh->ctx, sh->stage, b->squares, 0, 4ull * *squares, sq, err);
    free(list);
    free(sq);
    return rc;
}

/* Traces the n pixels listed in `list`. */
static int trace(vct_shaded *sh, cl_kernel k, int first_arg, sub_buffers *b, cl_mem list,
                 uint32_t n, uint64_t *rays, vct_error *err) {
    *rays += n;
    int rc = vct_set_args(err, sh->stage, k, first_arg, 5, VCT_ARG(points, list), VCT_ARG_OF(n),
                          VCT_ARG_OF(b->keys), VCT_ARG_OF(b->traced), VCT_ARG(image, sh->frame));
    return rc == VCT_OK ? vct_launch(sh->ctx, k, n, 64, err) : rc;
}

/* Traces the wanted ones of the n pixels in b->points (b->wanted: 0 or 1). */
static int trace_wanted(vct_shaded *sh, cl_kernel k, int first_arg, sub_buffers *b, uint32_t n,
                        uint64_t *rays, vct_error *err) {
    uint32_t count = 0;
    int rc = vct_compact_u32(sh->ctx, b->points, b->wanted, b->listed, n, &count, err);
    return rc == VCT_OK && count ? trace(sh, k, first_arg, b, b->listed, count, rays, err) : rc;
}

int vct_subsample(vct_shaded *sh, const char *points_kernel, const vct_kernel_arg *own,
                  int own_count, uint32_t size, const uint16_t *guard, float contrast_in,
                  uint64_t *traced, uint64_t *rays, uint8_t *traced_mask, vct_error *err) {
    *rays = 0;
    vct_context *ctx = sh->ctx;
    const char *stage = sh->stage;
    const uint32_t w = (uint32_t)sh->width, h = (uint32_t)sh->height;
    const cl_float contrast = contrast_in;
    const size_t pixels = (size_t)w * h;
    /* Squares of any level: at most one per 2x2 block, plus the edges. */
    const size_t max_squares = ((size_t)w / 2 + 2) * ((size_t)h / 2 + 2);
    sub_buffers b = {0};
    cl_program p;
    int rc = vct_program_get(ctx, "render/subsample.cl", "", &p, err);
    if (rc == VCT_OK)
        rc = allocate(ctx, stage, pixels, max_squares, &b, err);
    if (rc == VCT_OK)
        rc = guard ? vct_buffer_write(ctx, stage, b.guard, 0, 2 * pixels, guard, err)
                   : vct_buffer_fill_u32(ctx, stage, b.guard, 0xFFFFFFFFu, (pixels + 1) / 2, err);
    cl_kernel k = rc == VCT_OK ? vct_shaded_kernel(sh, points_kernel, own, own_count, err) : NULL;
    if (rc == VCT_OK && !k)
        rc = (int)err->status;
    const int first_arg = VCT_SHADED_FIRST_OWN_ARG + own_count;
    uint32_t n_points = 0, m = 0;
    if (rc == VCT_OK)
        rc = first_level(sh, size, &b, &n_points, &m, err);
    if (rc == VCT_OK)
        rc = trace(sh, k, first_arg, &b, b.points, n_points, rays, err);
    const cl_uint cw = w, ch = h;
    for (cl_uint s = size; rc == VCT_OK && m > 0 && s >= 2; s /= 2) {
        /* the contrast test also reads each square's centre (sub_fill) */
        if (contrast > 0.0f && s > 2) {
            rc = vct_run_kernel(ctx, p, "sub_centres", stage, m, err, 8, VCT_ARG_OF(b.squares),
                                VCT_ARG(n, m), VCT_ARG(size, s), VCT_ARG(width, cw),
                                VCT_ARG(height, ch), VCT_ARG_OF(b.traced), VCT_ARG_OF(b.points),
                                VCT_ARG_OF(b.wanted));
            if (rc == VCT_OK)
                rc = trace_wanted(sh, k, first_arg, &b, m, rays, err);
        }
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "sub_fill", stage, m, err, 10, VCT_ARG_OF(b.squares),
                                VCT_ARG(n, m), VCT_ARG(size, s), VCT_ARG(width, cw),
                                VCT_ARG(height, ch), VCT_ARG_OF(b.keys), VCT_ARG_OF(b.guard),
                                VCT_ARG_OF(contrast), VCT_ARG(image, sh->frame),
                                VCT_ARG(refine, b.flags));
        uint32_t r = 0;
        if (rc == VCT_OK)
            rc = vct_compact_u32(ctx, b.squares, b.flags, b.refining, m, &r, err);
        if (rc != VCT_OK || r == 0)
            break;
        rc = vct_run_kernel(ctx, p, "sub_mark", stage, r, err, 5, VCT_ARG(squares, b.refining),
                            VCT_ARG(n, r), VCT_ARG(size, s), VCT_ARG(width, cw),
                            VCT_ARG(map, b.split_map));
        if (rc == VCT_OK)
            rc = vct_run_kernel(ctx, p, "sub_points", stage, r, err, 9,
                                VCT_ARG(squares, b.refining), VCT_ARG(n, r), VCT_ARG(size, s),
                                VCT_ARG(width, cw), VCT_ARG(height, ch), VCT_ARG(map, b.split_map),
                                VCT_ARG_OF(b.traced), VCT_ARG_OF(b.points), VCT_ARG_OF(b.wanted));
        if (rc == VCT_OK)
            rc = trace_wanted(sh, k, first_arg, &b, 5 * r, rays, err);
        if (rc == VCT_OK && s > 2)
            rc = vct_run_kernel(ctx, p, "sub_split", stage, r, err, 4, VCT_ARG(squares, b.refining),
                                VCT_ARG(n, r), VCT_ARG(size, s), VCT_ARG(children, b.squares));
        m = 4 * r;
    }
    uint32_t *mask = rc == VCT_OK ? malloc(4 * pixels) : NULL;
    if (rc == VCT_OK && !mask)
        rc = vct_fail(err, VCT_ERR_MEMORY, "subsample: out of host memory");
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, stage, b.traced, 0, 4 * pixels, mask, err);
    *traced = 0;
    for (size_t i = 0; rc == VCT_OK && i < pixels; ++i) {
        *traced += mask[i] != 0;
        if (traced_mask)
            traced_mask[i] = (uint8_t)(mask[i] != 0);
    }
    free(mask);
    if (k)
        clReleaseKernel(k);
    release_all(ctx, &b);
    return rc;
}
