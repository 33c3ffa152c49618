/* Uniform triangle grid: resolution choice and the device build. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "accel/grid.h"
#include "vct/debug.h"
#include "accel/tri_vertices.h"
#include "parallel/parallel.h"
#include "vct_types.h"

#define STAGE "grid build"
#define MAX_AXIS_RES 1024u
#define MAX_CELLS (1u << 25)
#define CELLS_PER_TRIANGLE 2.0

static void choose_resolution(const vct_scene *s, const float lo[3], const float hi[3],
                              uint32_t res[3]) {
    double e[3], volume = 1.0;
    for (int k = 0; k < 3; ++k) {
        e[k] = (double)hi[k] - lo[k];
        volume *= e[k];
    }
    double cells = CELLS_PER_TRIANGLE * s->triangle_count;
    if (cells > MAX_CELLS)
        cells = MAX_CELLS;
    double per_unit = cbrt(cells / volume);
    for (int k = 0; k < 3; ++k) {
        double r = ceil(e[k] * per_unit);
        res[k] = (uint32_t)(r < 1 ? 1 : (r > MAX_AXIS_RES ? MAX_AXIS_RES : r));
    }
}

void vct_grid_kernel_args(const vct_grid *grid, void *out) {
    vct_accel_desc *d = out;
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k) {
        d->origin.s[k] = grid->origin[k];
        d->cell_size.s[k] = grid->cell_size[k];
        d->inv_cell.s[k] = 1.0f / grid->cell_size[k];
        d->res.s[k] = grid->res[k];
    }
    d->origin.s[3] = grid->scene_extent;
    d->cell_size.s[3] = grid->tolerance;
    d->res.s[3] = grid->triangle_count;
}

void vct_grid_release(vct_grid *g) {
    if (!g)
        return;
    vct_buffer_release(g->ctx, g->cell_ranges);
    vct_buffer_release(g->ctx, g->cell_bits);
    vct_buffer_release(g->ctx, g->tri_ids);
    vct_buffer_release(g->ctx, g->tri_vertices);
    free(g);
}

void vct_grid_info_get(const vct_grid *g, vct_grid_info *info) {
    memset(info, 0, sizeof *info);
    for (int k = 0; k < 3; ++k) {
        info->res[k] = g->res[k];
        info->cell_size[k] = g->cell_size[k];
    }
    info->references = g->references;
}

vct_grid *vct_grid_build(vct_context *ctx, const vct_scene *s, const uint32_t *res_in,
                         vct_error *err) {
    vct_grid *g = calloc(1, sizeof *g);
    if (!g) {
        vct_fail(err, VCT_ERR_MEMORY, "grid: out of host memory");
        return NULL;
    }
    g->ctx = ctx;
    g->triangle_count = s->triangle_count;
    vct_scene_frame frame;
    vct_scene_frame_of(s, &frame);
    const float *lo = frame.lo, *hi = frame.hi;
    g->scene_extent = frame.extent;
    g->tolerance = frame.tolerance;
    if (res_in && res_in[0] && res_in[1] && res_in[2]) {
        for (int k = 0; k < 3; ++k)
            g->res[k] = res_in[k];
    } else {
        choose_resolution(s, lo, hi, g->res);
    }
    uint64_t cells = (uint64_t)g->res[0] * g->res[1] * g->res[2];
    if (cells > (1ull << 30)) {
        vct_fail(err, VCT_ERR_INPUT, "grid: %ux%ux%u cells is more than 2^30: lower --grid-res",
                 g->res[0], g->res[1], g->res[2]);
        free(g);
        return NULL;
    }
    for (int k = 0; k < 3; ++k) {
        g->origin[k] = lo[k];
        g->cell_size[k] = (hi[k] - lo[k]) / (float)g->res[k];
    }
    vct_stage_begin(ctx, STAGE);
    cl_program p;
    int rc = vct_program_get(ctx, "accel/grid_build.cl", "", &p, err);
    if (rc == VCT_OK)
        rc = vct_tri_vertices_upload(ctx, s, STAGE, &g->tri_vertices, err);
    vct_accel_desc desc;
    vct_grid_kernel_args(g, &desc);
    float max_cell = fmaxf(g->cell_size[0], fmaxf(g->cell_size[1], g->cell_size[2]));
    float pad = max_cell * 1e-5f + g->tolerance;
    uint32_t n = s->triangle_count;
    cl_mem counts = NULL, keys = NULL;
    cl_kernel k_count = NULL, k_write = NULL, k_ranges = NULL;
    if (rc == VCT_OK) {
        counts =
            vct_buffer_create(ctx, STAGE, "cell counts", 4ull * n, CL_MEM_READ_WRITE, NULL, err);
        k_count = counts ? vct_kernel_create(ctx, p, "grid_count", err) : NULL;
        k_write = k_count ? vct_kernel_create(ctx, p, "grid_write", err) : NULL;
        k_ranges = k_write ? vct_kernel_create(ctx, p, "grid_ranges", err) : NULL;
        rc = k_ranges ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_count, 0, 5, VCT_ARG_OF(g->tri_vertices),
                          VCT_ARG(triangles, n), VCT_ARG(g, desc), VCT_ARG_OF(pad),
                          VCT_ARG_OF(counts));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_count, n, 0, err);
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, counts, counts, n, 0, &total, err);
    if (rc == VCT_ERR_OVERFLOW)
        rc = vct_fail(err, VCT_ERR_MEMORY,
                      "grid: %llu (cell, triangle) references do not fit 32-bit offsets: lower "
                      "--grid-res",
                      (unsigned long long)total);
    g->references = (uint32_t)total;
    if (rc == VCT_OK) {
        keys =
            vct_buffer_create(ctx, STAGE, "cell keys", 4ull * total, CL_MEM_READ_WRITE, NULL, err);
        g->tri_ids = keys ? vct_buffer_create(ctx, STAGE, "cell triangle lists", 4ull * total,
                                              CL_MEM_READ_WRITE, NULL, err)
                          : NULL;
        rc = g->tri_ids ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_write, 0, 7, VCT_ARG_OF(g->tri_vertices),
                          VCT_ARG(triangles, n), VCT_ARG(g, desc), VCT_ARG_OF(pad),
                          VCT_ARG(offsets, counts), VCT_ARG(cell_keys, keys),
                          VCT_ARG_OF(g->tri_ids));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_write, n, 0, err);
    if (rc == VCT_OK)
        rc = vct_sort_pairs_u32(ctx, keys, g->tri_ids, g->references, vct_key_bits_for(cells), err);
    if (rc == VCT_OK) {
        g->cell_ranges = vct_buffer_create(ctx, STAGE, "cell ranges", 8ull * cells,
                                           CL_MEM_READ_WRITE, NULL, err);
        g->cell_bits = g->cell_ranges ? vct_buffer_create(ctx, STAGE, "cell occupancy",
                                                          4ull * ((cells + 31) / 32),
                                                          CL_MEM_READ_WRITE, NULL, err)
                                      : NULL;
        rc = g->cell_bits ? VCT_OK : (int)err->status;
    }
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, g->cell_ranges, 0, 2 * cells, err);
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, STAGE, g->cell_bits, 0, (cells + 31) / 32, err);
    if (rc == VCT_OK)
        rc = vct_set_args(err, STAGE, k_ranges, 0, 4, VCT_ARG(cell_keys, keys),
                          VCT_ARG(n, g->references), VCT_ARG_OF(g->cell_ranges),
                          VCT_ARG_OF(g->cell_bits));
    if (rc == VCT_OK)
        rc = vct_launch(ctx, k_ranges, g->references, 0, err);
    if (rc == VCT_OK)
        rc = vct_finish(ctx, STAGE, err);
    if (k_count)
        clReleaseKernel(k_count);
    if (k_write)
        clReleaseKernel(k_write);
    if (k_ranges)
        clReleaseKernel(k_ranges);
    vct_buffer_release(ctx, counts);
    vct_buffer_release(ctx, keys);
    vct_stage_end(ctx);
    if (rc != VCT_OK) {
        vct_grid_release(g);
        return NULL;
    }
    return g;
}

vct_status vct_grid_read(vct_context *ctx, const vct_grid *g, uint32_t *cell_start,
                         uint32_t *cell_end, uint32_t *tri_ids, vct_error *err) {
    size_t cells = (size_t)g->res[0] * g->res[1] * g->res[2];
    uint32_t *ranges = malloc(8 * cells), *bits = malloc(4 * ((cells + 31) / 32));
    if (!ranges || !bits) {
        free(ranges);
        free(bits);
        return vct_fail(err, VCT_ERR_MEMORY, "grid read: out of host memory");
    }
    int rc = vct_buffer_read(ctx, "grid read", g->cell_ranges, 0, cells * 8, ranges, err);
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, "grid read", g->cell_bits, 0, 4 * ((cells + 31) / 32), bits, err);
    if (rc == VCT_OK)
        rc = vct_buffer_read(ctx, "grid read", g->tri_ids, 0, g->references * 4ull, tri_ids, err);
    /* A cell's range counts only where its occupancy bit is set, as in traversal. */
    for (size_t c = 0; rc == VCT_OK && c < cells; ++c) {
        int occupied = (bits[c >> 5] >> (c & 31)) & 1u;
        cell_start[c] = occupied ? ranges[2 * c] : 0;
        cell_end[c] = occupied ? ranges[2 * c + 1] : 0;
    }
    free(ranges);
    free(bits);
    return rc;
}

int vct_grid_set_args(cl_kernel k, const vct_grid *g, const char *stage, vct_error *err) {
    vct_accel_desc desc;
    vct_grid_kernel_args(g, &desc);
    return vct_set_args(err, stage, k, 0, 5, VCT_ARG(accel, desc), VCT_ARG_OF(g->cell_bits),
                        VCT_ARG_OF(g->cell_ranges), VCT_ARG_OF(g->tri_ids),
                        VCT_ARG_OF(g->tri_vertices));
}
