/* The uniform triangle grid as the renderers and light stages see it. */
#ifndef VCT_ACCEL_GRID_H
#define VCT_ACCEL_GRID_H

#include "runtime/runtime.h"

struct vct_grid {
    cl_mem cell_ranges, cell_bits, tri_ids;
    cl_mem tri_vertices; /* 3 float4 per triangle */
    uint32_t res[3];
    float origin[3], cell_size[3];
    float scene_extent;
    float tolerance; /* distance below which positions are not told apart */
    uint32_t references;
    uint32_t triangle_count;
    vct_context *ctx;
};

/* Grid description passed to kernels (vct_accel_desc in kernels/vct_types.h). */
void vct_grid_kernel_args(const vct_grid *grid, void *out_desc);
/* Arguments 0-4 of every kernel that traverses the grid (ACCEL_ARGS in the kernels). */
int vct_grid_set_args(cl_kernel k, const vct_grid *grid, const char *stage, vct_error *err);

#endif
