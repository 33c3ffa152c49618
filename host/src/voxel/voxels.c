/* The vct_voxels object: its volume's description for kernels, its memory
 * limits, and the release of everything it holds (voxels, octree, bricks). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vct_types.h"
#include "voxel/voxels.h"

void vct_voxels_volume_desc(const vct_voxels *v, void *out) {
    vct_volume_desc *d = out;
    memset(d, 0, sizeof *d);
    for (int k = 0; k < 3; ++k)
        d->origin.s[k] = (float)v->info.origin[k];
    d->origin.s[3] = (float)v->info.side;
    d->res.s[0] = v->info.resolution;
    d->res.s[1] = v->info.levels;
    d->res.s[2] = (1u << VCT_VOLUME_UNITS_LOG2) / v->info.resolution;
    d->res.s[3] = v->info.triangles;
}

uint32_t vct_voxel_res_that_fits(uint32_t res, double bytes, double limit) {
    while (res > 2 && bytes > limit) {
        res /= 2;
        bytes /= 4.0;
    }
    return res;
}

void vct_voxels_release(vct_voxels *v) {
    if (!v)
        return;
    cl_mem *mems[] = {
        &v->keys,         &v->albedo,      &v->normal,      &v->emission,        &v->child,
        &v->neighbours,   &v->tile_parent, &v->radiance,    &v->direct_radiance, &v->fragment_start,
        &v->fragment_tri, &v->side,        &v->direct_side, &v->before_radiance, &v->before_side,
        &v->tris,         &v->tri_normals};
    for (size_t i = 0; i < sizeof mems / sizeof mems[0]; ++i)
        vct_buffer_release(v->ctx, *mems[i]);
    vct_bricks_release(v);
    free(v);
}

int vct_voxels_same_frame(const vct_voxels *a, const vct_voxels *b) {
    return a->info.resolution == b->info.resolution && a->info.side == b->info.side &&
           memcmp(a->info.origin, b->info.origin, sizeof a->info.origin) == 0;
}

void vct_voxels_info_get(const vct_voxels *v, vct_voxel_info *info) {
    *info = v->info;
}

int vct_voxel_buffer_fits(vct_context *ctx, const vct_voxel_info *info, const char *stage,
                          const char *what, double bytes, vct_error *err) {
    const double limit = (double)ctx->info.max_alloc;
    if (bytes <= limit)
        return VCT_OK;
    return vct_fail(err, VCT_ERR_MEMORY,
                    "%s: %s at %u^3 need %.1f MiB, beyond what %s allows per buffer (%.1f MiB): "
                    "--voxel-res %u would fit",
                    stage, what, info->resolution, bytes / 1048576.0, ctx->info.name,
                    limit / 1048576.0, vct_voxel_res_that_fits(info->resolution, bytes, limit));
}

void vct_bricks_release(vct_voxels *v) {
    for (int c = 0; c < VCT_BRICK_CHANNELS; ++c) {
        vct_buffer_release(v->ctx, v->brick_buffer[c]);
        vct_buffer_release(v->ctx, v->brick_image[c]);
        v->brick_buffer[c] = v->brick_image[c] = NULL;
    }
    vct_buffer_release(v->ctx, v->brick_window);
    v->brick_window = NULL;
    v->has_bricks = 0;
}
