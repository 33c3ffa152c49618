/* Photon grid build: counts per path, scan, keys, sort, reorder, ranges. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "parallel/parallel.h"
#include "photon/photon_grid.h"

/* A dense grid may have this many cells per stored photon (or 2^20 cells,
 * whichever is more) before the cells are hashed. */
#define DENSE_CELLS_PER_PHOTON 4u
#define DENSE_CELLS_MIN (1u << 20)

/* Replaces *mem by a buffer of at least `need` elements of `size` bytes
 * when the one it has (capacity *cap) is smaller. */
static int ensure(vct_context *ctx, const char *stage, const char *what, cl_mem *mem, size_t *cap,
                  size_t need, size_t size, vct_error *err) {
    if (*mem && *cap >= need)
        return VCT_OK;
    vct_buffer_release(ctx, *mem);
    *cap = need + need / 4 + 64;
    *mem = vct_buffer_create(ctx, stage, what, *cap * size, CL_MEM_READ_WRITE, NULL, err);
    if (!*mem)
        *cap = 0;
    return *mem ? VCT_OK : (int)err->status;
}

static uint64_t next_pow2(uint64_t v) {
    uint64_t p = 1;
    while (p < v)
        p <<= 1;
    return p;
}

/* Dense cells over the box, or a hash table, for `photons` photons. */
static void layout(vct_photon_grid *g, float cell, const float lo[3], const float hi[3],
                   uint64_t photons) {
    uint64_t cells = 1;
    for (int k = 0; k < 3; ++k) {
        double n = ceil(((double)hi[k] - lo[k]) / cell);
        n = n < 1.0 ? 1.0 : n;
        g->dims.s[k] = n > 4e9 ? 0xffffffffu : (cl_uint)n;
        cells = n > 1e12 || cells > (1ull << 40) ? (1ull << 41) : cells * (uint64_t)n;
        g->origin.s[k] = lo[k];
    }
    g->origin.s[3] = cell;
    uint64_t dense_max = photons * DENSE_CELLS_PER_PHOTON;
    if (dense_max < DENSE_CELLS_MIN)
        dense_max = DENSE_CELLS_MIN;
    if (cells <= dense_max && cells < (1ull << 31)) {
        g->dims.s[3] = 0;
        g->table = cells;
    } else {
        g->table = next_pow2(photons < 512 ? 1024 : 2 * photons);
        g->dims.s[3] = (cl_uint)(g->table - 1);
    }
}

int vct_photon_grid_build(vct_context *ctx, const char *stage, const vct_photon_slots *slots,
                          uint32_t kind_mask, float cell, const float lo[3], const float hi[3],
                          vct_photon_grid *g, vct_error *err) {
    const double t0 = vct_now_ms();
    cl_program p;
    int rc = vct_program_get(ctx, "photon/photon_grid.cl", "", &p, err);
    const cl_uint paths = slots->paths, depth = slots->depth;
    if (rc == VCT_OK)
        rc = ensure(ctx, stage, "photon counts", &g->counts, &g->slot_capacity, paths, 4, err);
    if (rc == VCT_OK) {
        size_t cap = g->slot_capacity;
        rc = ensure(ctx, stage, "photon offsets", &g->offsets, &cap, paths, 4, err);
    }
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "photon_counts", stage, paths, err, 5, VCT_ARG_OF(slots->kinds),
                            VCT_ARG_OF(paths), VCT_ARG_OF(depth), VCT_ARG_OF(kind_mask),
                            VCT_ARG_OF(g->counts));
    uint64_t total = 0;
    if (rc == VCT_OK)
        rc = vct_scan_u32(ctx, g->counts, g->offsets, paths, 0, &total, err);
    g->count = (uint32_t)total;
    layout(g, cell, lo, hi, total);
    if (rc == VCT_OK)
        rc = ensure(ctx, stage, "photon keys", &g->keys, &g->key_capacity, total + 1, 4, err);
    if (rc == VCT_OK) {
        size_t cap = g->key_capacity;
        rc = ensure(ctx, stage, "photon ids", &g->ids, &cap, total + 1, 4, err);
    }
    if (rc == VCT_OK)
        rc = ensure(ctx, stage, "photon map", &g->photons, &g->photon_capacity, total + 1,
                    VCT_PHOTON_BYTES, err);
    if (rc == VCT_OK)
        rc = ensure(ctx, stage, "photon grid ranges", &g->ranges, &g->table_capacity, g->table, 8,
                    err);
    if (rc == VCT_OK)
        rc =
            vct_run_kernel(ctx, p, "photon_keys", stage, paths, err, 10, VCT_ARG_OF(slots->records),
                           VCT_ARG_OF(slots->kinds), VCT_ARG_OF(paths), VCT_ARG_OF(depth),
                           VCT_ARG_OF(kind_mask), VCT_ARG_OF(g->offsets), VCT_ARG_OF(g->origin),
                           VCT_ARG_OF(g->dims), VCT_ARG_OF(g->keys), VCT_ARG_OF(g->ids));
    const cl_uint count = g->count;
    if (rc == VCT_OK && count > 1)
        rc = vct_sort_pairs_u32(ctx, g->keys, g->ids, count, vct_key_bits_for(g->table), err);
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "photon_reorder", stage, count, err, 4,
                            VCT_ARG_OF(slots->records), VCT_ARG_OF(g->ids), VCT_ARG_OF(count),
                            VCT_ARG(sorted, g->photons));
    if (rc == VCT_OK)
        rc = vct_buffer_fill_u32(ctx, stage, g->ranges, 0, 2 * g->table, err);
    if (rc == VCT_OK)
        rc = vct_run_kernel(ctx, p, "photon_ranges", stage, count, err, 3, VCT_ARG_OF(g->keys),
                            VCT_ARG_OF(count), VCT_ARG_OF(g->ranges));
    g->build_ms = vct_now_ms() - t0;
    return rc;
}

int vct_photon_grid_args(cl_kernel k, int first, const char *prefix, const vct_photon_grid *g,
                         const char *stage, vct_error *err) {
    /* PHOTON_GRID_ARGS(prefix) names them prefix_photons, prefix_ranges, ... */
    char names[4][64];
    static const char *const fields[4] = {"photons", "ranges", "origin", "dims"};
    for (int i = 0; i < 4; ++i)
        snprintf(names[i], sizeof names[i], "%s_%s", prefix, fields[i]);
    return vct_set_args(err, stage, k, first, 4, sizeof g->photons, (const void *)&g->photons,
                        names[0], sizeof g->ranges, (const void *)&g->ranges, names[1],
                        sizeof g->origin, (const void *)&g->origin, names[2], sizeof g->dims,
                        (const void *)&g->dims, names[3]);
}

uint64_t vct_photon_grid_bytes(const vct_photon_grid *g) {
    return (uint64_t)g->count * VCT_PHOTON_BYTES + g->table * 8u;
}

void vct_photon_grid_release(vct_context *ctx, vct_photon_grid *g) {
    cl_mem *mems[] = {&g->photons, &g->ranges, &g->keys, &g->ids, &g->counts, &g->offsets};
    for (size_t i = 0; i < sizeof mems / sizeof *mems; ++i) {
        vct_buffer_release(ctx, *mems[i]);
        *mems[i] = NULL;
    }
    memset(g, 0, sizeof *g);
}
