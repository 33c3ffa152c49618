/* Light-space triangle bins for the hard point and spot lights of a scene
 * (kernels/light/light_bins.h): built for one set of light positions, read by the
 * shadow rays of light injection. */
#ifndef VCT_LIGHT_BINS_HOST_H
#define VCT_LIGHT_BINS_HOST_H

#include "runtime/runtime.h"

/* What to bin: enabled 1 bins, 0 leaves every light to the grid, -1
 * chooses by device: bins on CPU devices, where they made injection 3.1x
 * faster, the grid on GPUs, where building them cost more than they saved
 * (0.8 against 0.6 ms at 256^3 on an H100); face_res 0
 * chooses the cells per face side from the triangle count; max_entries 0
 * allows up to 2^24 (cell, triangle) entries (256 MiB with the sort) or a
 * quarter of the device's largest buffer. A scene that needs more keeps
 * its lights on the grid: the same answer, slower. */
typedef struct vct_light_bins_options {
    int enabled;
    uint32_t face_res;
    uint64_t max_entries;
} vct_light_bins_options;

typedef struct vct_light_bins {
    cl_mem desc;   /* vct_light_bins_desc per light */
    cl_mem ranges; /* (start, end) per cell */
    cl_mem keys, tris;
    uint32_t lights;   /* lights with bins */
    uint32_t face_res; /* cells per face side */
    uint32_t entries;  /* (cell, triangle) pairs */
} vct_light_bins;

/* Bins for every point and spot light of s without a radius (options may
 * be NULL: the defaults). Lights without bins keep to the grid. */
int vct_light_bins_build(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                         const vct_light_bins_options *options, const char *stage,
                         vct_light_bins *bins, vct_error *err);
/* Sets the four LIGHT_BINS_ARGS from argument `first`. */
int vct_light_bins_set_args(cl_kernel k, int first, const vct_light_bins *bins, const char *stage,
                            vct_error *err);
void vct_light_bins_release(vct_context *ctx, vct_light_bins *bins);

#endif
