/* vct: acceleration structures: the uniform triangle grid and ray queries. */
#ifndef VCT_API_ACCEL_H
#define VCT_API_ACCEL_H

#include <stdint.h>

#include "vct/device.h"
#include "vct/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_grid vct_grid;

typedef struct vct_grid_info {
    uint32_t res[3];
    uint32_t references; /* (cell, triangle) pairs */
    float cell_size[3];
} vct_grid_info;

/* res NULL or {0,0,0}: chosen from triangle count and extent. */
vct_grid *vct_grid_build(vct_context *ctx, const vct_scene *scene, const uint32_t *res,
                         vct_error *err);
void vct_grid_info_get(const vct_grid *grid, vct_grid_info *info);
/* Reads back the cell ranges and the sorted triangle list (for tests). */
int vct_grid_read(vct_context *ctx, const vct_grid *grid, uint32_t *cell_start, uint32_t *cell_end,
                  uint32_t *tri_ids, vct_error *err);
void vct_grid_free(vct_grid *grid);

typedef struct vct_hit {
    float t; /* < 0: miss */
    uint32_t triangle;
    float u, v;
} vct_hit;

/* Hits for n rays, 8 floats each (origin xyz, tmin; direction xyz, tmax):
 * the closest one, or with any_hit the first found (occlusion queries). */
int vct_trace_rays(vct_context *ctx, const vct_grid *grid, const float *rays, uint32_t n,
                   int any_hit, vct_hit *hits, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
