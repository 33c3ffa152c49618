/* vct: OpenCL global illumination engine — public C API.
 *
 * Shape: an opaque context (one OpenCL device, queue, program cache and stage
 * statistics), a host scene of flat arrays, and stages that take both. Every
 * call reports failure through a vct_error the caller owns; there is no global
 * state. */
#ifndef VCT_VCT_H
#define VCT_VCT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum vct_status {
    VCT_OK = 0,
    VCT_ERR_OPENCL,   /* an OpenCL call failed */
    VCT_ERR_INPUT,    /* the scene or an option is invalid */
    VCT_ERR_MEMORY,   /* a buffer would not fit the device or host */
    VCT_ERR_IO,       /* a file could not be read or written */
    VCT_ERR_OVERFLOW, /* a count exceeded what the structure can index */
} vct_status;

typedef struct vct_error {
    vct_status status;
    char message[2048];
} vct_error;

/* ---- devices ------------------------------------------------------------ */

typedef struct vct_device_info {
    int index; /* global index over all platforms, as used by --device N */
    char platform[128];
    char name[256];
    char version[128];
    char driver[128];
    int is_gpu;
    unsigned compute_units;
    uint64_t global_mem;
    uint64_t max_alloc;
    size_t max_work_group;
    int image_support;
    int fp64;
    int gl_sharing;
    char extensions[4096];
} vct_device_info;

/* Lists every device of every platform. Returns the count (at most max). */
int vct_list_devices(vct_device_info *out, int max, vct_error *err);

typedef struct vct_context vct_context;

/* selector: NULL or "" = $VCT_DEVICE, else first GPU, else first CPU;
 * a number = global device index; otherwise a case-insensitive substring of
 * the device or platform name. */
vct_context *vct_context_create(const char *selector, vct_error *err);
void vct_context_destroy(vct_context *ctx);
const vct_device_info *vct_context_device(const vct_context *ctx);

/* ---- statistics ----------------------------------------------------------- */

typedef struct vct_stage_stat {
    char name[48];
    double device_ms; /* sum of kernel/copy event durations */
    double host_ms;   /* wall time the host spent in the stage */
    double mib;       /* peak device memory allocated through vct while the stage ran */
    int launches;
} vct_stage_stat;

int vct_stats(const vct_context *ctx, const vct_stage_stat **stages);
void vct_stats_reset(vct_context *ctx);
/* Kernels launched so far by name (for plan tests): count of launches. */
int vct_kernel_launches(const vct_context *ctx, const char *kernel_name);

typedef struct vct_kernel_stat {
    char name[64];
    int launches;
    double device_ms; /* summed over the launches made inside a stage */
} vct_kernel_stat;

/* Per-kernel launches and device time since the last reset. */
int vct_kernel_stats(const vct_context *ctx, const vct_kernel_stat **kernels);

/* ---- scene ------------------------------------------------------------------ */

typedef struct vct_material {
    char name[64];
    float albedo[3];   /* diffuse reflectance */
    float emission[3]; /* emitted radiance Le */
    float specular[3]; /* specular reflectance (or metallic tint) */
    float metallic;
    float roughness;    /* 0 = mirror, 1 = diffuse-like */
    float transmission; /* 0..1 */
    float ior;
} vct_material;

typedef enum vct_light_type {
    VCT_LIGHT_POINT = 0,
    VCT_LIGHT_SPOT = 1,
    VCT_LIGHT_DIRECTIONAL = 2,
} vct_light_type;

typedef struct vct_light {
    vct_light_type type;
    float position[3];
    float direction[3]; /* direction the light travels (spot, directional) */
    float color[3];     /* point/spot: radiant intensity W/sr; directional: irradiance */
    float inner_cone;   /* spot: radians, full intensity inside */
    float outer_cone;   /* spot: radians, zero outside */
    /* Size for soft shadows (0: a point, hard shadows): point and spot, the
     * radius of the disk facing the lit point, in world units; directional,
     * the angular radius in radians (below 1). The light is shaded as from
     * its centre, times the fraction of it that the point sees. */
    float radius;
} vct_light;

typedef struct vct_camera {
    float position[3];
    float look_at[3];
    float up[3];
    float fov_y_deg;
} vct_camera;

typedef struct vct_scene {
    char source[512];
    uint32_t vertex_count;
    uint32_t triangle_count;
    uint32_t material_count;
    uint32_t light_count;
    float *positions;    /* 3 * vertex_count */
    uint32_t *triangles; /* 3 * triangle_count */
    uint32_t *triangle_material;
    vct_material *materials;
    vct_light *lights;
    vct_camera camera;
    int has_camera;
    /* Radiance arriving from every direction where nothing is hit (a
     * constant environment, 0 by default): lights what is open to the sky. */
    float ambient[3];
    uint32_t degenerate_triangles; /* zero-area triangles, kept but never hit */
    float bounds_min[3], bounds_max[3];
} vct_scene;

/* Loads OBJ+MTL, glTF 2.0 or anything assimp reads; flattens the node tree. */
vct_scene *vct_scene_load(const char *path, vct_error *err);
/* Builds a scene from arrays (copied); validates like a loaded file. */
vct_scene *vct_scene_from_arrays(const float *positions, uint32_t vertex_count,
                                 const uint32_t *triangles, uint32_t triangle_count,
                                 const uint32_t *triangle_material, const vct_material *materials,
                                 uint32_t material_count, vct_error *err);
int vct_scene_add_light(vct_scene *scene, const vct_light *light, vct_error *err);
/* Checks indices, finite values, non-empty; counts degenerates; sets bounds. */
int vct_scene_validate(vct_scene *scene, vct_error *err);
/* A default camera framing the scene's bounds, looking down -z. */
void vct_scene_default_camera(const vct_scene *scene, vct_camera *camera);
void vct_scene_free(vct_scene *scene);
vct_material vct_material_default(void);

/* ---- parallel primitives (device buffers are cl_mem passed as void*) ----- */

/* out[i] = sum of in[0..i) (exclusive) or in[0..i] (inclusive); n may be 0.
 * total receives the sum of all n inputs; a total above UINT32_MAX fails with
 * VCT_ERR_OVERFLOW instead of wrapping. in and out may be the same buffer. */
int vct_scan_u32(vct_context *ctx, void *in_mem, void *out_mem, uint32_t n, int inclusive,
                 uint64_t *total, vct_error *err);
/* out receives in[i] for every i with flags[i] != 0, in order; count returned. */
int vct_compact_u32(vct_context *ctx, void *in_mem, void *flags_mem, void *out_mem, uint32_t n,
                    uint32_t *count, vct_error *err);
/* Stable LSD radix sort of (key, value) pairs on the low key_bits bits. */
int vct_sort_pairs_u32(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n, int key_bits,
                       vct_error *err);
int vct_sort_pairs_u64(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n, int key_bits,
                       vct_error *err);
/* keys sorted; sums float4 values of equal-key runs in input order.
 * Writes unique keys and their sums; returns the number of runs. */
int vct_segmented_sum_f4(vct_context *ctx, void *keys_mem, void *values_mem, uint32_t n,
                         void *out_keys_mem, void *out_sums_mem, uint32_t *runs, vct_error *err);

/* ---- triangle grid and ray casting ----------------------------------------- */

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

typedef struct vct_image {
    int width, height;
    float *rgba; /* linear radiance, width*height*4 */
} vct_image;

typedef struct vct_render_options {
    int width, height;
    uint32_t grid_res[3]; /* 0 = automatic */
} vct_render_options;

/* Direct illumination with hard shadows by ray casting. */
int vct_render_raycast(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                       const vct_render_options *options, vct_image *image, vct_error *err);
void vct_image_free(vct_image *image);

typedef struct vct_pathtrace_options {
    int width, height;
    uint32_t spp;              /* samples per pixel; 0: run for time_limit_s */
    double time_limit_s;       /* used when spp is 0 */
    uint32_t max_depth;        /* surface interactions per path; 1 = direct light only */
    uint32_t seed;             /* same seed and spp: same image, bit for bit */
    uint32_t samples_per_pass; /* samples per launch (0: 1) */
    int progress;              /* progress bar on a terminal's stderr */
    /* 1: add to the running sums of the previous call on this context (same
     * scene, camera and size), continuing its sample sequence: n calls of k
     * samples give the image of one call of n * k. 0: start over. */
    int resume;
} vct_pathtrace_options;

typedef struct vct_pathtrace_result {
    uint32_t spp;       /* samples per pixel in the image (all resumed calls) */
    uint32_t discarded; /* samples dropped because they were not finite */
    double seconds;
} vct_pathtrace_result;

/* Unbiased path tracing: next-event estimation with MIS, Lambert, glossy,
 * mirror and dielectric materials, Russian roulette. result may be NULL. */
int vct_render_pathtrace(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                         const vct_pathtrace_options *options, vct_image *image,
                         vct_pathtrace_result *result, vct_error *err);

/* ---- voxelization and the sparse voxel octree ---------------------------------- */

#define VCT_VOXEL_MAX_RES 1024u
#define VCT_NODE_NULL 0xffffffffu /* no node, no child, no neighbour */

typedef struct vct_voxel_options {
    uint32_t resolution; /* voxels per axis: a power of two from 2 to VCT_VOXEL_MAX_RES */
    int thin;            /* 0: conservative (26-separating); 1: thin (6-separating) */
    int has_bounds;      /* 0: a cube around the scene with a one-voxel margin */
    double bounds_min[3];
    double bounds_size; /* side of the cube when has_bounds */
} vct_voxel_options;

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
    uint64_t voxel_bytes;     /* per-voxel keys and attributes */
    uint64_t node_bytes;      /* child pointers and tile parents */
    uint64_t neighbour_bytes; /* 6 links per node */
    uint64_t fragment_bytes;  /* transient: fragments and their sort */
} vct_voxel_info;

/* Triangle-parallel voxelization. Voxels are sorted by Morton key (bit 3k =
 * x bit k); each holds the mean of its fragments. Zero-area triangles make no
 * voxels; geometry outside the bounds is cut off at the cube's faces. */
vct_voxels *vct_voxelize(vct_context *ctx, const vct_scene *scene, const vct_voxel_options *options,
                         vct_error *err);
/* Builds the sparse voxel octree over the voxels, with neighbour links. */
int vct_octree_build(vct_context *ctx, vct_voxels *voxels, vct_error *err);
void vct_voxels_info_get(const vct_voxels *voxels, vct_voxel_info *info);
/* Per voxel: Morton key; albedo rgb + opacity; unit normal + coherence (the
 * mean unit normal's length); emission rgb + fragment count. NULL skips one. */
int vct_voxels_read(vct_context *ctx, const vct_voxels *voxels, uint32_t *keys, float *albedo,
                    float *normal, float *emission, vct_error *err);
/* Per node: child (first node of the child tile, or at the leaf level the
 * voxel index; VCT_NODE_NULL when empty) and 6 neighbour links (+x, +y, +z,
 * -x, -y, -z). Either may be NULL. */
int vct_octree_read(vct_context *ctx, const vct_voxels *voxels, uint32_t *child,
                    uint32_t *neighbours, vct_error *err);
/* Runs the kernels' traversal: for each query (x, y, z, level), cell
 * coordinates at that level, the node covering it or VCT_NODE_NULL. */
int vct_octree_lookup(vct_context *ctx, const vct_voxels *voxels, const uint32_t *queries,
                      uint32_t n, uint32_t *nodes, vct_error *err);
/* Injects direct light into the voxels: per voxel, the outgoing radiance
 * albedo / pi * irradiance (every light of the scene, shadows through the
 * grid, or for point and spot lights without a radius through triangle bins
 * around the light: the same answer) + emission, at the voxel centre with
 * its mean normal. Call again after moving lights: nothing is re-voxelized. */
int vct_voxels_inject_light(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                            vct_voxels *voxels, vct_error *err);
/* Per voxel: injected radiance rgb and the voxel's opacity (as in its
 * albedo's w), in voxel order. */
int vct_voxels_read_radiance(vct_context *ctx, const vct_voxels *voxels, float *radiance,
                             vct_error *err);
/* The voxels as the scene camera sees them, ray marched through the octree:
 * their injected radiance once light is injected, else albedo under a headlight. */
int vct_render_voxels(vct_context *ctx, const vct_scene *scene, const vct_voxels *voxels, int width,
                      int height, vct_image *image, vct_error *err);
/* The same at octree level `level` (0 = root .. levels = voxels): below the
 * leaf level every node with geometry in it shows as a grey cube. */
int vct_render_voxels_level(vct_context *ctx, const vct_scene *scene, const vct_voxels *voxels,
                            uint32_t level, int width, int height, vct_image *image,
                            vct_error *err);
void vct_voxels_free(vct_voxels *voxels);

/* ---- bricks ---------------------------------------------------------------------- */

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
     * composited front to back along the axis, then averaged. */
    int anisotropic;
    /* 1: light injection follows (vct_voxels_inject_light), so the radiance
     * channels are left for it to build: the build fills albedo and normal
     * only, and cones and radiance reads refuse the bricks until then. 0:
     * radiance too (the voxels' radiance, or 0 with opacity before any
     * injection, which is all that occlusion needs). */
    int radiance_later;
} vct_brick_options;

typedef enum vct_brick_channel {
    VCT_BRICK_ALBEDO,       /* albedo * opacity, opacity */
    VCT_BRICK_NORMAL,       /* mean normal * opacity (its length is coherence), opacity */
    VCT_BRICK_RADIANCE,     /* injected outgoing radiance * opacity, opacity; with
                               anisotropic bricks at level L-1 only */
    VCT_BRICK_RADIANCE_DIR0 /* + direction 0..5, anisotropic only, levels 0 .. L-2 */
} vct_brick_channel;
#define VCT_BRICK_CHANNELS 9

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
int vct_bricks_build(vct_context *ctx, vct_voxels *voxels, const vct_brick_options *options,
                     vct_error *err);
/* 0 and no change when no bricks are built. */
int vct_bricks_info_get(const vct_voxels *voxels, vct_brick_info *info);
/* Bricks first .. first + count - 1 of one channel as float4 texels, 27 per
 * brick (index k * 9 + j * 3 + i), read through the kernels' own brick access. */
int vct_bricks_read(vct_context *ctx, const vct_voxels *voxels, int channel, uint32_t first,
                    uint32_t count, float *out, vct_error *err);
/* Trilinear samples of one channel at `level` (0 .. L-1; directions 0 .. L-2)
 * at n world points (xyz, 4 floats each, w unused), as float4: what a cone
 * reads. A point in a node without a brick reads 0. */
int vct_bricks_sample(vct_context *ctx, const vct_voxels *voxels, int channel, uint32_t level,
                      const float *points, uint32_t n, float *out, vct_error *err);

/* ---- voxel cone tracing ------------------------------------------------------------ */

/* How cones march (kernels/cone_trace.h). */
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
vct_cone_settings vct_cone_settings_default(void);

/* Diffuse cone preset of `count` cones (1, 5, 6, 9 or 16): directions in a
 * frame whose z axis is the normal (4 floats each: xyz and the weight) and
 * tan(half-angle) each. Each weight is the cosine-weighted share of the
 * hemisphere closest to its cone, so the weights sum to 1 and a constant
 * environment L is integrated exactly: sum w_i L = L. A cone's half-angle
 * matches its share's solid angle, at most 20 degrees. */
int vct_cone_preset(uint32_t count, float *dirs, float *tan_half, vct_error *err);

/* Marches n cones through the radiance bricks: 8 floats in each (origin xyz,
 * tan(half-angle); unit direction xyz, reach), 8 floats out each (radiance
 * rgb and opacity; opacity within the AO distance, sum of levels sampled,
 * samples, 1 if it left the volume). `ambient`: radiance beyond the volume
 * (NULL: none). The bricks must be built (and lit, when built with
 * radiance_later). */
int vct_cone_trace(vct_context *ctx, const vct_voxels *voxels, const vct_cone_settings *settings,
                   const float *ambient, const float *cones, uint32_t n, float *out,
                   vct_error *err);

/* The effect plan: which effects a scene calls for, and why. The renderer
 * enqueues no work for an effect that is off. */
typedef enum vct_effect {
    VCT_EFFECT_DIRECT,       /* light from the scene's lights */
    VCT_EFFECT_SHADOWS,      /* hard shadows by shadow rays */
    VCT_EFFECT_INDIRECT,     /* indirect diffuse light by cones */
    VCT_EFFECT_SPECULAR,     /* glossy highlights and a specular cone */
    VCT_EFFECT_REFRACTION,   /* rays followed through transmissive materials */
    VCT_EFFECT_EMISSION,     /* emissive surfaces */
    VCT_EFFECT_AO,           /* ambient occlusion of the ambient light */
    VCT_EFFECT_SOFT_SHADOWS, /* shadows of lights with a radius, by cones */
    VCT_EFFECTS
} vct_effect;

typedef enum vct_effect_force { VCT_FORCE_AUTO, VCT_FORCE_ON, VCT_FORCE_OFF } vct_effect_force;

typedef struct vct_plan {
    int on[VCT_EFFECTS];
    int forced[VCT_EFFECTS]; /* 1 where a flag decided, not the scene */
    char why[VCT_EFFECTS][160];
} vct_plan;

const char *vct_effect_name(vct_effect effect);
/* -1 for an unknown name. */
int vct_effect_from_name(const char *name);
/* force: VCT_EFFECTS entries, or NULL to follow the scene. */
void vct_plan_make(const vct_scene *scene, const vct_effect_force *force, vct_plan *plan);
/* Whether the plan reads the voxel hierarchy, and whether it needs its light. */
int vct_plan_needs_voxels(const vct_plan *plan);
int vct_plan_needs_voxel_light(const vct_plan *plan);

typedef struct vct_vct_options {
    int width, height;
    uint32_t diffuse_cones; /* preset: 1, 5, 6, 9 or 16 */
    vct_cone_settings cones;
    /* 1: trace the diffuse cones at every other pixel per axis and give the
     * others the mean of the traced neighbours on the same surface (a pixel
     * with none traces its own); 0: at every pixel */
    int sparse_diffuse;
    int aovs; /* also fill the AOV images */
} vct_vct_options;

/* 512 x 512, 6 diffuse cones, default cone settings, no AOVs. */
vct_vct_options vct_vct_options_default(void);

typedef struct vct_aovs {
    vct_image direct;   /* direct light and emission */
    vct_image indirect; /* indirect diffuse (or ambient light times AO) */
    vct_image specular; /* the specular cone */
    vct_image ao;       /* fraction of the hemisphere open within the AO distance */
    vct_image level;    /* mean octree level the diffuse cones sampled */
    vct_image position; /* the surface the camera ray found, w 1 (all 0 where none) */
    vct_image normal;   /* its shading normal, facing the viewer, w 1 (all 0 where none) */
} vct_aovs;
void vct_aovs_free(vct_aovs *aovs);

/* Builds what the plan's cones read: voxels, octree and bricks, then light
 * (when indirect diffuse or specular is on) with `bounces` - 1 extra
 * diffuse bounces gathered at the voxels by the 6-cone preset. *voxels is
 * NULL when the plan needs none. */
int vct_vct_prepare(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                    const vct_plan *plan, const vct_voxel_options *voxel_options,
                    const vct_brick_options *brick_options, uint32_t bounces,
                    const vct_cone_settings *cones, vct_voxels **voxels, vct_error *err);

/* Adds one diffuse bounce to the voxels' light: cones from every voxel
 * gather the filtered radiance, the voxel's radiance becomes its injected
 * direct radiance plus albedo times that, and the radiance bricks are
 * filtered again. After k calls the voxels hold paths of up to k + 1
 * bounces, each counted once; vct_voxels_inject_light starts over. */
int vct_voxels_inject_bounce(vct_context *ctx, const vct_scene *scene, vct_voxels *voxels,
                             const vct_cone_settings *cones, uint32_t diffuse_cones,
                             vct_error *err);

/* Renders by voxel cone tracing: stages "vct primary", "vct diffuse cones"
 * and "vct specular cone", each only when the plan calls for it. voxels may
 * be NULL when the plan needs none. aovs may be NULL. */
int vct_render_vct(vct_context *ctx, const vct_scene *scene, const vct_grid *grid,
                   const vct_voxels *voxels, const vct_plan *plan, const vct_vct_options *options,
                   vct_image *image, vct_aovs *aovs, vct_error *err);

/* ---- the frame and OpenGL display ----------------------------------------------- */

/* Every renderer writes its image into the context's frame, a device buffer
 * of width * height float4 (linear radiance, rows top to bottom) kept between
 * calls, and copies it into the vct_image it returns. With host copies off
 * the returned image carries its size and rgba NULL: for displays that take
 * the frame on the device. On by default. */
void vct_frame_host_copy(vct_context *ctx, int on);
/* The last frame's size (0 x 0 before any), and a copy of it into `rgba`,
 * which holds `floats` floats (at least width * height * 4). */
void vct_frame_size(const vct_context *ctx, int *width, int *height);
int vct_frame_read(vct_context *ctx, float *rgba, size_t floats, vct_error *err);

/* A context that shares objects with an OpenGL context (cl_khr_gl_sharing on
 * GLX): glx_context is the GLXContext, x_display the X Display it belongs to.
 * Fails with the reason when the device has no such sharing or cannot share
 * with that context; plain contexts then display through the host. */
vct_context *vct_context_create_gl(const char *selector, void *glx_context, void *x_display,
                                   vct_error *err);
int vct_context_shares_gl(const vct_context *ctx);
/* Copies the frame into an OpenGL buffer object of at least width * height
 * * 16 bytes, on the device: acquire, copy, release, finish. Call glFinish()
 * first so that GL is done with the buffer; it is complete on return. */
int vct_frame_to_gl_buffer(vct_context *ctx, unsigned gl_buffer, vct_error *err);

/* ---- images --------------------------------------------------------------------- */

/* PFM: raw linear radiance. PNG: radiance * 2^exposure, clamped, sRGB encoded.
 * Written to a temporary file and renamed, so a failure leaves nothing. */
int vct_image_write_pfm(const vct_image *image, const char *path, vct_error *err);
int vct_image_write_png(const vct_image *image, const char *path, float exposure, vct_error *err);
int vct_image_write(const vct_image *image, const char *path, float exposure, vct_error *err);
int vct_image_read_pfm(const char *path, vct_image *image, vct_error *err);

typedef struct vct_image_metrics {
    double mse, rmse;
    double relative_rmse; /* sqrt(sum (t - r)^2 / sum r^2) */
    double relative_mse;  /* mean of (t - r)^2 / (r^2 + 0.01) */
    double mae;           /* mean absolute error */
    double psnr;          /* dB, peak = the reference's largest value */
    size_t nonfinite;     /* channel values that are NaN or infinite, left out */
} vct_image_metrics;

/* Errors of `test` against `ref` over the rgb channels of every pixel. */
int vct_image_compare(const vct_image *test, const vct_image *ref, vct_image_metrics *metrics,
                      vct_error *err);
/* Per-pixel mean absolute error as false colour (blue = 0, red >= scale;
 * scale <= 0: the largest error). The result is a displayable linear image. */
int vct_image_error_map(const vct_image *test, const vct_image *ref, double scale, vct_image *out,
                        vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
