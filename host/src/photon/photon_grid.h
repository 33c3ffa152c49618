/* The photon grid (kernels/photon/photon_grid.cl): the photons of chosen
 * kinds, sorted by cell, and each cell's range. Cells are the gather radius
 * across (seed 000); where the scene's box would need too many of them the
 * cells are hashed into a table twice the photon count. */
#ifndef VCT_PHOTON_GRID_H
#define VCT_PHOTON_GRID_H

#include "photon/photon_trace.h"

typedef struct vct_photon_grid {
    cl_mem photons;                    /* 3 float4 each, in key order */
    cl_mem ranges;                     /* uint2 per key */
    cl_mem keys, ids, counts, offsets; /* build scratch, kept for the next pass */
    size_t photon_capacity, key_capacity, table_capacity, slot_capacity;
    cl_float4 origin; /* w: cell edge */
    cl_uint4 dims;    /* w: hash mask, 0 when dense */
    uint32_t count;   /* photons in the grid */
    uint64_t table;   /* keys: cells, or hash buckets */
    double build_ms;
} vct_photon_grid;

/* (Re)builds g from the slots' photons of kinds in kind_mask, with cells of
 * edge `cell` over the box [lo, hi]. Buffers grow as needed and are reused. */
int vct_photon_grid_build(vct_context *ctx, const char *stage, const vct_photon_slots *slots,
                          uint32_t kind_mask, float cell, const float lo[3], const float hi[3],
                          vct_photon_grid *g, vct_error *err);
/* Sets the grid's four kernel arguments (PHOTON_GRID_ARGS(prefix)) from
 * `first`. */
int vct_photon_grid_args(cl_kernel k, int first, const char *prefix, const vct_photon_grid *g,
                         const char *stage, vct_error *err);
/* Device memory the grid holds (photons and ranges). */
uint64_t vct_photon_grid_bytes(const vct_photon_grid *g);
void vct_photon_grid_release(vct_context *ctx, vct_photon_grid *g);

#endif
