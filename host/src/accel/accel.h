/* The one acceleration interface as the stages see it: kernels that trace
 * rays are built with vct_accel_program_options and take their first five
 * arguments from vct_accel_set_args (ACCEL_ARGS in kernels/accel/accel.h). */
#ifndef VCT_ACCEL_ACCEL_H
#define VCT_ACCEL_ACCEL_H

#include "accel/bvh.h"
#include "accel/bvh2.h"
#include "accel/grid.h"

struct vct_accel {
    vct_accel_kind kind;
    vct_accel_options options;
    vct_grid *grid; /* kind VCT_ACCEL_GRID */
    vct_bvh *bvh;   /* kind VCT_ACCEL_BVH, one level */
    vct_bvh2 *bvh2; /* kind VCT_ACCEL_BVH, two levels */
    double build_ms;
    vct_context *ctx;
};

/* The -D option that selects the traversal in accel/accel.h. */
const char *vct_accel_program_options(const vct_accel *a);
/* Joins a program's own options and the traversal's into out. */
const char *vct_accel_options_join(const vct_accel *a, const char *own, char *out, size_t size);
int vct_accel_set_args(cl_kernel k, const vct_accel *a, const char *stage, vct_error *err);
/* 3 float4 per triangle, in the scene's order. */
cl_mem vct_accel_tri_vertices(const vct_accel *a);

#endif
