/* vct: voxelization, the sparse voxel octree, bricks, light in the
 * voxels and cones through them.
 *
 * Voxels belong to the context they were built on (vct_voxels_copy makes a
 * copy on another): their calls are serialised with the context's, and they
 * are released before it. */
#ifndef VCT_API_VOXELS_H
#define VCT_API_VOXELS_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/accel.h"
#include "vct/device.h"
#include "vct/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define VCT_VOXEL_MAX_RES 1024u
#define VCT_NODE_NULL 0xffffffffu /* no node, no child, no neighbour */

typedef struct vct_voxel_options {
    uint32_t resolution; /* voxels per axis: a power of two from 2 to VCT_VOXEL_MAX_RES */
    int thin;            /* 0: conservative (26-separating); 1: thin (6-separating) */
    int has_bounds;      /* 0: a cube around the scene with a one-voxel margin */
    double bounds_min[3];
    double bounds_size; /* side of the cube when has_bounds */
    /* 0: after two bounces or more, the voxels add the rest of the series
     * (vct_voxels_bounce_rest); 1: only the bounces asked for */
    int exact_bounces;
    /* 0: each bounce is gathered by a quarter of the voxels (those whose
     * x + y + z is a multiple of 4) and the others take the mean of what the
     * gathering voxels one and two steps away along the axes, on the same
     * surface, received (they gather themselves where there is none): over
     * the scene suite the error of every voxel gathering, the whole voxel
     * build in 0.4 to 0.6 of its time; 1: every voxel gathers */
    int dense_bounces;
} vct_voxel_options;

/* 128^3 conservative voxels in a cube around the scene, the rest of the
 * bounces added. */
VCT_API vct_voxel_options vct_voxel_options_default(void);

/* The largest bounce ratio the rest of the bounces assumes. */
#define VCT_BOUNCE_RATIO_MAX 0.9

typedef struct vct_voxels vct_voxels;

typedef struct vct_voxel_info {
    uint32_t resolution, levels; /* resolution = 2^levels */
    /* Vertex quantisation: q = round((p - origin) * units / side) in double, to
     * nearest with ties to even;
     * a voxel spans units / resolution integers per axis. */
    uint32_t units;
    double origin[3], side;
    uint32_t triangles, fragments, voxels;
    /* Octree (after vct_octree_build): nodes per level, level 0 = root. */
    uint32_t nodes, level_nodes[11], level_start[11];
    uint64_t voxel_bytes;     /* per-voxel keys and attributes, and their fragment lists */
    uint64_t node_bytes;      /* child pointers and tile parents */
    uint64_t neighbour_bytes; /* 6 links per node */
    uint64_t fragment_bytes;  /* transient: fragments and their sort */
} vct_voxel_info;

/* A copy on `ctx` of voxels built on another device (octree, bricks and
 * light as they are): instead of building them there again. */
VCT_API vct_voxels *vct_voxels_copy(vct_context *ctx, const vct_voxels *voxels, vct_error *err);

/* Triangle-parallel voxelization. Voxels are sorted by Morton key (bit 3k =
 * x bit k); each holds the mean of its fragments. Zero-area triangles make no
 * voxels; geometry outside the bounds is cut off at the cube's faces. */
VCT_API vct_voxels *vct_voxelize(vct_context *ctx, const vct_scene *scene,
                                 const vct_voxel_options *options, vct_error *err);
/* Builds the sparse voxel octree over the voxels, with neighbour links. */
VCT_API vct_status vct_octree_build(vct_context *ctx, vct_voxels *voxels, vct_error *err);
VCT_API void vct_voxels_info_get(const vct_voxels *voxels, vct_voxel_info *info);
/* Per voxel: Morton key; albedo rgb + opacity; unit normal + coherence (the
 * mean unit normal's length); emission rgb + fragment count. NULL skips one. */
VCT_API vct_status vct_voxels_read(vct_context *ctx, const vct_voxels *voxels, uint32_t *keys,
                                   float *albedo, float *normal, float *emission, vct_error *err);
/* Per node: child (first node of the child tile, or at the leaf level the
 * voxel index; VCT_NODE_NULL when empty) and 6 neighbour links (+x, +y, +z,
 * -x, -y, -z). Either may be NULL. */
VCT_API vct_status vct_octree_read(vct_context *ctx, const vct_voxels *voxels, uint32_t *child,
                                   uint32_t *neighbours, vct_error *err);
/* Runs the kernels' traversal: for each query (x, y, z, level), cell
 * coordinates at that level, the node covering it or VCT_NODE_NULL. */
VCT_API vct_status vct_octree_lookup(vct_context *ctx, const vct_voxels *voxels,
                                     const uint32_t *queries, uint32_t n, uint32_t *nodes,
                                     vct_error *err);
/* Injects direct light into the voxels: per voxel and per side of its
 * surfaces, the outgoing radiance albedo / pi * irradiance (every light of
 * the scene, shadows through the acceleration structure, or for point and
 * spot lights without a radius through triangle bins around the light: the
 * same answer) + emission, at the voxel centre. A wall lit on one face keeps
 * its other face dark (vct_voxels_read_sides). Call again after moving
 * lights: nothing is re-voxelized. */
VCT_API vct_status vct_voxels_inject_light(vct_context *ctx, const vct_scene *scene,
                                           const vct_accel *accel, vct_voxels *voxels,
                                           vct_error *err);
/* Per voxel: injected radiance rgb (its brighter side's) and the voxel's
 * opacity (as in its albedo's w), in voxel order. */
VCT_API vct_status vct_voxels_read_radiance(vct_context *ctx, const vct_voxels *voxels,
                                            float *radiance, vct_error *err);
/* Per voxel, 8 floats (kernels/voxel/voxel_side.h): the brighter side's
 * radiance less the darker side's, and that difference's luminance; the
 * brighter side's unit normal (0 without one) and its plane's offset
 * (normal . (p - 0.5), p in volume units [0, 1)^3). */
VCT_API vct_status vct_voxels_read_sides(vct_context *ctx, const vct_voxels *voxels, float *sides,
                                         vct_error *err);
VCT_API void vct_voxels_release(vct_voxels *voxels);

/* Every octree node with geometry below it (levels 0 .. L-1) owns a brick of
 * 3x3x3 corner-centred samples: texel (i, j, k) at node_min + (i, j, k) *
 * node_size / 2. Each channel holds (value * opacity, opacity) as half
 * floats, so that plain averages of it are opacity-weighted colours. Level
 * L-1 samples are the mean of the up to 8 voxels around the corner that hold
 * geometry; each coarser level is the 3x3x3 Gaussian (1/4, 1/2, 1/4 per axis)
 * of the finer lattice. Samples shared by neighbouring bricks are equal. */
typedef enum vct_brick_storage {
    VCT_BRICKS_AUTO,   /* an image3d on GPUs that can hold the pool, else a buffer */
    VCT_BRICKS_BUFFER, /* a buffer, filtered in code */
    VCT_BRICKS_IMAGE   /* an image3d (hardware trilinear); fails where the device has none */
} vct_brick_storage;

typedef struct vct_brick_options {
    vct_brick_storage storage;
    /* Also 6 directional radiance values per sample (+x, +y, +z, -x, -y, -z,
     * the way a cone travels) at levels 0 .. L-2: the child lattice
     * composited front to back along the axis, then averaged; and the same
     * six of the surfaces' darker sides, seen by cones from behind them. */
    int anisotropic;
    /* 1: light injection follows (vct_voxels_inject_light), so the radiance
     * channels are left for it to build: the build fills albedo and normal
     * only, and cones and radiance reads refuse the bricks until then. 0:
     * radiance too (the voxels' radiance, or 0 with opacity before any
     * injection, which is all that occlusion needs). */
    int radiance_later;
} vct_brick_options;

/* Isotropic bricks, the pool kind chosen for the device, radiance built
 * with the rest. */
VCT_API vct_brick_options vct_brick_options_default(void);

typedef enum vct_brick_channel {
    VCT_BRICK_ALBEDO,        /* albedo * opacity, opacity */
    VCT_BRICK_NORMAL,        /* mean normal * opacity (its length is coherence), opacity */
    VCT_BRICK_RADIANCE,      /* injected outgoing radiance * opacity, opacity; with
                                anisotropic bricks at level L-1 only. A surface lit on
                                one side sends out its brighter side's radiance here */
    VCT_BRICK_SHADE,         /* (brighter side - darker side) * opacity, opacity * k, k the
                                difference's luminance (kernels/voxel/voxel_side.h) */
    VCT_BRICK_PLANE,         /* the brighter side's unit normal, and the plane's offset
                                (normal . (p - 0.5), p in volume units), * opacity * k */
    VCT_BRICK_RADIANCE_DIR0, /* + direction 0..5, anisotropic only, levels 0 .. L-2 */
    VCT_BRICK_DARK_DIR0 = VCT_BRICK_RADIANCE_DIR0 + 6 /* + direction 0..5: the same, of the
                                                          surfaces' darker sides */
} vct_brick_channel;
#define VCT_BRICK_CHANNELS 17

typedef struct vct_brick_info {
    uint32_t bricks;                            /* one per node with children */
    uint32_t level_bricks[11], level_first[11]; /* level l's bricks: a contiguous range */
    uint32_t directional_bricks; /* bricks with directional values (levels 0 .. L-2) */
    uint32_t pool[3];            /* pool size in bricks; texels are 3x that */
    int image;                   /* 1: image3d pool, 0: buffer pool */
    int anisotropic;
    char storage_reason[160];   /* why this pool kind was chosen */
    uint64_t channel_bytes;     /* one channel of all bricks */
    uint64_t pool_bytes;        /* every channel, as allocated */
    uint64_t staging_bytes;     /* image pools: buffers kept for re-filtering */
    uint64_t window_bytes;      /* each brick's 4^3 child cells, kept for re-filtering */
    uint64_t dense_rgba8_bytes; /* a dense RGBA8 3D texture at the voxel resolution */
} vct_brick_info;

/* Builds the bricks of every channel (radiance from the injected light, or 0
 * before injection; left out with radiance_later). vct_voxels_inject_light
 * (re-)builds and re-filters radiance. */
VCT_API vct_status vct_bricks_build(vct_context *ctx, vct_voxels *voxels,
                                    const vct_brick_options *options, vct_error *err);
/* 0 and no change when no bricks are built. */
VCT_API int vct_bricks_info_get(const vct_voxels *voxels, vct_brick_info *info);
/* Bricks first .. first + count - 1 of one channel as float4 texels, 27 per
 * brick (index k * 9 + j * 3 + i), read through the kernels' own brick access. */
VCT_API vct_status vct_bricks_read(vct_context *ctx, const vct_voxels *voxels, int channel,
                                   uint32_t first, uint32_t count, float *out, vct_error *err);
/* Trilinear samples of one channel at `level` (0 .. L-1; directions 0 .. L-2)
 * at n world points (xyz, 4 floats each, w unused), as float4: what a cone
 * reads. A point in a node without a brick reads 0. */
VCT_API vct_status vct_bricks_sample(vct_context *ctx, const vct_voxels *voxels, int channel,
                                     uint32_t level, const float *points, uint32_t n, float *out,
                                     vct_error *err);

/* How cones march (kernels/conetrace/cone_trace.h). */
typedef struct vct_cone_settings {
    float step;        /* step as a fraction of the cone's diameter there */
    float offset;      /* start offset along the surface normal, in voxels */
    float ao_distance; /* ambient-occlusion range, as a fraction of the volume's side */
    float stop_alpha;  /* a cone stops once its opacity reaches this */
    /* 0: a sample blends the two levels around its diameter; 1: it reads
     * the nearest level alone (kernels built with -DVCT_CONE_NEAREST_LEVEL) */
    int nearest_level;
} vct_cone_settings;

/* step 1, offset 4 voxels, AO over 1/8 of the volume, stop at 0.99, levels
 * blended. */
VCT_API vct_cone_settings vct_cone_settings_default(void);

/* Diffuse cone preset of `count` cones (1, 5, 6, 9 or 16): directions in a
 * frame whose z axis is the normal (4 floats each: xyz and the weight) and
 * tan(half-angle) each. Each weight is the cosine-weighted share of the
 * hemisphere closest to its cone (its cell), so the weights sum to 1 and a
 * constant environment L is integrated exactly: sum w_i L = L. A cone's
 * half-angle matches its cell's solid angle, at most 20 degrees; cell_tan
 * (NULL: not wanted) gets tan of that half-angle up to 45 degrees, over
 * which the rays that look past the cone spread. */
VCT_API vct_status vct_cone_preset(uint32_t count, float *dirs, float *tan_half, float *cell_tan,
                                   vct_error *err);

/* Marches n cones through the radiance bricks: 8 floats in each (origin xyz,
 * tan(half-angle); unit direction xyz, reach), 8 floats out each (radiance
 * rgb and opacity; opacity within the AO distance, sum of levels sampled,
 * samples, 1 if it left the volume). `ambient`: radiance beyond the volume
 * (NULL: none). The bricks must be built (and lit, when built with
 * radiance_later). */
VCT_API vct_status vct_cone_trace(vct_context *ctx, const vct_voxels *voxels,
                                  const vct_cone_settings *settings, const float *ambient,
                                  const float *cones, uint32_t n, float *out, vct_error *err);

/* Adds one diffuse bounce to the voxels' light: cosine-distributed rays
 * from every voxel through `accel` read the radiance where they meet the
 * scene (the finest bricks; the scene's ambient light where they meet
 * nothing), the voxel's radiance becomes its injected direct radiance plus
 * albedo times that, and the radiance bricks are filtered again. After k
 * calls the voxels hold paths of up to k + 1 bounces, each counted once;
 * vct_voxels_inject_light starts over. The first call after it decides
 * which of each voxel's two sides faces where; later calls keep that and
 * only add light (vct_voxels_bounce_rest, where it adds the rest of the
 * series, decides again). */
VCT_API vct_status vct_voxels_inject_bounce(vct_context *ctx, const vct_scene *scene,
                                            const vct_accel *accel, vct_voxels *voxels,
                                            const vct_cone_settings *settings, vct_error *err);

/* After the last bounce: adds the bounces still to come, as each bounce
 * adds what the one before it added times a ratio r, to each voxel its
 * last bounce's light times r / (1 - r), per colour channel. r is the
 * scene's own: the light the last bounce added, summed over the voxels,
 * over what the one before it added, in that channel (at most the
 * channel's brightest albedo and VCT_BOUNCE_RATIO_MAX). Nothing with fewer
 * than two bounces since light injection, or with exact_bounces. */
VCT_API vct_status vct_voxels_bounce_rest(vct_context *ctx, vct_voxels *voxels, vct_error *err);

/* The ratios (red, green, blue) the last vct_voxels_bounce_rest used (0:
 * none). */
VCT_API void vct_voxels_bounce_ratios(const vct_voxels *voxels, double ratio[3]);

/* The largest of those: the channel whose light dies out slowest (0: none). */
VCT_API double vct_voxels_bounce_ratio(const vct_voxels *voxels);

#ifdef __cplusplus
}
#endif
#endif
