/* The voxel list and its sparse voxel octree, shared by the host files
 * that build, read and render them. */
#ifndef VCT_VOXELS_H
#define VCT_VOXELS_H

#include "runtime/runtime.h"
#include "light/light_bins_host.h"

struct vct_voxels {
    vct_context *ctx;
    /* vct_plan.emitters_by_cones: light injection leaves emitters out as
     * lights, and the voxels keep their emission for the cones. */
    int emitters_by_cones;
    vct_voxel_info info;
    /* Per voxel, sorted by Morton key. */
    cl_mem keys, albedo, normal, emission;
    /* Per voxel, its first fragment; per fragment (sorted by voxel), its
     * triangle: light injection lights each surface in a voxel on its own. */
    cl_mem fragment_start, fragment_tri;
    /* Per triangle, kept for an update that voxelizes only what moved
     * (vct_voxelize_moved): its vertices in integer units with its material,
     * and its unit normal. */
    cl_mem tris, tri_normals;
    cl_mem radiance; /* outgoing radiance, after vct_voxels_inject_light */
    /* Per voxel, two float4 beside radiance (which holds the brighter side's):
     * (brighter - darker side's radiance, 0), then the brighter side's unit
     * normal and its plane's offset (kernels/voxel/voxel_side.h). */
    cl_mem side;
    /* The direct part of radiance, copied by the first bounce so that each
     * bounce adds to it, not to the bounces before. Valid while bounces > 0;
     * light injection sets bounces back to 0. */
    cl_mem direct_radiance, direct_side;
    uint32_t bounces;
    /* The rest of the bounces (bounce_rest.h), unless the voxel options
     * said exact_bounces: the light before the last bounce, the light the
     * last two bounces added (summed over the voxels' sides, per colour
     * channel), how many were measured since light injection, and the
     * ratios the rest used. */
    int bounce_rest;
    int dense_bounces; /* vct_voxel_options.dense_bounces */
    cl_mem before_radiance, before_side;
    double bounce_light[2][3];
    uint32_t bounces_measured;
    double bounce_ratio[3];
    /* Per colour channel, the brightest albedo of the scene's materials
     * (textures only darken it): no bounce can keep more of the light before
     * it, which bounds the measured ratio where a few bounces are not yet
     * its own. */
    double albedo_max[3];
    int radiance_stale; /* the bricks' radiance waits for the rest */
    /* Octree: built by vct_octree_build (child is NULL before). */
    cl_mem child, neighbours, tile_parent;
    /* Bricks: built by vct_bricks_build (has_bricks 0 before). Buffers are
     * the build storage; an image pool also has images, and keeps only the
     * radiance buffers for re-filtering. */
    int has_bricks;
    int radiance_ready; /* 0 while radiance_later waits for light injection */
    vct_brick_info brick_info;
    cl_mem brick_buffer[VCT_BRICK_CHANNELS], brick_image[VCT_BRICK_CHANNELS];
    /* Per brick, what the 4^3 child cells around its node (-1 .. 2 per axis,
     * x fastest) hold: child bricks above the leaves, voxels at the leaves,
     * OCT_NULL where nothing. Found once by the build, so that a light update
     * reads 64 words in a row instead of following the octree. */
    cl_mem brick_window;
};

/* Light carried from the voxels before into new ones after geometry moved
 * (kernels/voxel/voxel_carry.h): the world boxes that moved (before and
 * after), and how many renders the carried bounce is spread over. */
#define VCT_CARRY_BOXES 16
/* The carried bounce is gathered by a voxel in VCT_CARRY_EVERY at each
 * render (and by every voxel lit anew). */
#define VCT_CARRY_EVERY 4
typedef struct vct_voxel_carry {
    vct_voxels *before; /* its triangle buffers are taken by vct_voxelize_moved */
    /* the triangles that moved lie in moved_lo .. moved_hi - 1 (none known
     * where equal: everything is voxelized again) */
    uint32_t moved_lo, moved_hi;
    uint32_t box_count;
    cl_float4 boxes[2 * VCT_CARRY_BOXES]; /* lo, hi */
    uint32_t every, phase; /* a voxel gathers at the render where hash(key) % every == phase */
    cl_mem carried_from;   /* per new voxel, its voxel before or VCT_NO_VOXEL (made by injection) */
} vct_voxel_carry;

/* Direct light into new voxels, kept from carry->before where nothing
 * moved can reach (carry_direct), injected elsewhere. */
int vct_voxels_inject_light_carried(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                    vct_voxels *v, vct_voxel_carry *carry, vct_error *err);

/* The voxels of s where only triangles moved_lo .. moved_hi - 1 moved since
 * `before` was voxelized (same options): the fragments of the rest kept,
 * the moved ones voxelized again, merged in the order a full voxelization
 * gives, so that the voxels are the same bit for bit. Takes before's
 * triangle buffers. Where before cannot serve (another volume frame or
 * triangle count, no triangle buffers), voxelizes all of s. */
vct_voxels *vct_voxelize_moved(vct_context *ctx, const vct_scene *s, const vct_voxel_options *o,
                               vct_voxels *before, uint32_t moved_lo, uint32_t moved_hi,
                               vct_error *err);

/* 1 when a and b cover the same volume at the same resolution: a voxel
 * key means the same place in both. */
int vct_voxels_same_frame(const vct_voxels *a, const vct_voxels *b);

/* Volume description for kernels (vct_volume_desc in kernels/vct_types.h). */
void vct_voxels_volume_desc(const vct_voxels *voxels, void *out_desc);
/* The largest power-of-two resolution below `res` at which `bytes`, growing
 * with the square of the resolution like a surface does, stays within `limit`. */
uint32_t vct_voxel_res_that_fits(uint32_t res, double bytes, double limit);
/* Fails with a message naming the resolution that would fit when one
 * buffer of `bytes` exceeds the device's allocation limit. */
int vct_voxel_buffer_fits(vct_context *ctx, const vct_voxel_info *info, const char *stage,
                          const char *what, double bytes, vct_error *err);

/* vct_voxels_inject_light, with the shadow rays of hard point and spot
 * lights through light-space triangle bins as `bins_options` says (NULL:
 * the defaults), or through the grid: the same radiance. */
/* Direct light into the voxels, the bricks left holding the light they
 * held: the next bounce (vct_vct_relight_carry) gathers the light of the
 * frame before. */
int vct_voxels_inject_light_kept(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 vct_voxels *v, vct_error *err);
int vct_voxels_inject_light_with(vct_context *ctx, const vct_scene *s, const vct_accel *g,
                                 vct_voxels *v, const vct_light_bins_options *bins_options,
                                 vct_error *err);
/* Fails, naming the stage, while the radiance bricks wait for light
 * injection (vct_brick_options.radiance_later). */
int vct_bricks_radiance_check(const vct_voxels *voxels, const char *stage, vct_error *err);
/* Re-creates the radiance bricks from the voxels' radiance and filters
 * them up (after light injection); nothing when no bricks are built. */
int vct_bricks_refresh_radiance(vct_context *ctx, vct_voxels *voxels, vct_error *err);
/* The leaf level's radiance bricks alone, for readers of the finest level
 * (a bounce's rays); the coarser levels keep their light before until
 * vct_bricks_refresh_radiance. */
int vct_bricks_refresh_leaves(vct_context *ctx, vct_voxels *voxels, vct_error *err);
void vct_bricks_release(vct_voxels *voxels);

#endif
