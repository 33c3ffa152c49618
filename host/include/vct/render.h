/* vct: renderers, the effect plan and the frame they write.
 *
 * Every method is reached the same way: vct_render with one job (the
 * method, its inputs and its options struct) and one frame out. The
 * per-method calls below it remain for callers that want them. */
#ifndef VCT_API_RENDER_H
#define VCT_API_RENDER_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/accel.h"
#include "vct/device.h"
#include "vct/image.h"
#include "vct/scene.h"
#include "vct/voxels.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_render_options {
    int width, height;
    /* Adaptive subsampling as Whitted's (vct_whitted_options): 0 off. */
    uint32_t subsample, subsample_unguarded;
    float subsample_contrast;
} vct_render_options;

/* No subsampling. */
VCT_API vct_render_options vct_render_options_default(int width, int height);

/* Direct illumination with hard shadows by ray casting. */
VCT_API vct_status vct_render_raycast(vct_context *ctx, const vct_scene *scene,
                                      const vct_accel *accel, const vct_render_options *options,
                                      vct_image *image, vct_error *err);

typedef struct vct_pathtrace_options {
    int width, height;
    uint32_t spp;        /* samples per pixel; 0: run for time_limit_s */
    double time_limit_s; /* used when spp is 0 */
    uint32_t max_depth;  /* surface interactions per path; 1 = direct light only */
    uint32_t seed;       /* same seed and spp: same image, bit for bit */
    /* Samples per launch (0: 1; default 16): fewer launches, each pixel's
     * sums read and written once per launch, and on CPU devices a pixel's
     * camera rays traced 16 to a packet (the Cornell box at depth 8 on 2
     * PoCL cores: 16 about 6 % faster than 8, 8 about 6 % faster than 1; the
     * image the same bits). A time limit launches one sample at a time, to
     * stop on time. */
    uint32_t samples_per_pass;
    int progress; /* progress bar on a terminal's stderr */
    /* 1: add to the running sums of the previous call of this scene on this
     * context (same size), continuing its sample sequence: n calls of k
     * samples give the image of one call of n * k. Through a device scene a
     * commit that finds the scene or its camera changed starts over by
     * itself; without one, the caller vouches that nothing changed. 0: start
     * over. */
    int resume;
    /* Non-NULL: also filled with the variance of each pixel's mean luminance
     * (in r; the denoiser's guide), from the same sums as the image, and of
     * its direct and indirect parts' (in g and b); -1 where a pixel has
     * fewer than two samples (unknown). */
    vct_image *variance;
    /* Non-NULL: also filled with each pixel's indirect light: the image
     * less its direct part (what the first surface emits or receives from
     * the lights and emitters by next-event estimation, or the background a
     * camera ray meets). The denoiser filters the two parts apart. */
    vct_image *indirect;
    /* 1: the running sums hold each pixel's colour alone, not the moments
     * that variance and indirect must be resolved from (both must then be
     * NULL): on PoCL the Cornell box's path tracing takes about 5 % less
     * time. Sums kept this way are not resumed by a call without it, nor
     * sums with moments by one with it: such a call starts over. */
    int colour_only;
} vct_pathtrace_options;

/* 64 samples per pixel, depth 16, one sample per pass, seed 0. */
VCT_API vct_pathtrace_options vct_pathtrace_options_default(int width, int height);

typedef struct vct_pathtrace_result {
    uint32_t spp;       /* samples per pixel in the image (all resumed calls) */
    uint32_t discarded; /* samples dropped because they were not finite */
    double seconds;
} vct_pathtrace_result;

/* The denoiser's guides (vct/denoise.h) at width x height: the first hit's
 * albedo (textured; 1 where rays leave the scene; in w the share of the rays
 * whose first hit emits nothing) and, in normal_depth, its
 * normal facing the viewer (xyz, not normalised) and distance (w, 0 where
 * no ray hit), each the mean of rays_per_axis^2 rays across the pixel. */
VCT_API vct_status vct_render_guides(vct_context *ctx, const vct_scene *scene,
                                     const vct_accel *accel, int width, int height,
                                     uint32_t rays_per_axis, vct_image *albedo,
                                     vct_image *normal_depth, vct_error *err);

/* Unbiased path tracing: next-event estimation with MIS, Lambert, glossy,
 * mirror and dielectric materials, Russian roulette. result may be NULL. */
VCT_API vct_status vct_render_pathtrace(vct_context *ctx, const vct_scene *scene,
                                        const vct_accel *accel,
                                        const vct_pathtrace_options *options, vct_image *image,
                                        vct_pathtrace_result *result, vct_error *err);

/* The voxels as the scene camera sees them, ray marched through the octree:
 * their injected radiance once light is injected, else albedo under a headlight. */
VCT_API vct_status vct_render_voxels(vct_context *ctx, const vct_scene *scene,
                                     const vct_voxels *voxels, int width, int height,
                                     vct_image *image, vct_error *err);
/* The same at octree level `level` (0 = root .. levels = voxels): below the
 * leaf level every node with geometry in it shows as a grey cube. */
VCT_API vct_status vct_render_voxels_level(vct_context *ctx, const vct_scene *scene,
                                           const vct_voxels *voxels, uint32_t level, int width,
                                           int height, vct_image *image, vct_error *err);

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
    VCT_EFFECT_CAUSTICS,     /* light through dielectrics onto diffuse surfaces, by photons */
    VCT_EFFECTS
} vct_effect;

typedef enum vct_effect_force { VCT_FORCE_AUTO, VCT_FORCE_ON, VCT_FORCE_OFF } vct_effect_force;

typedef struct vct_plan {
    int on[VCT_EFFECTS];
    int forced[VCT_EFFECTS]; /* 1 where a flag decided, not the scene */
    char why[VCT_EFFECTS][160];
    /* 1: emissive triangles light the scene through the voxels alone (their
     * emission stays in the voxels and cones gather it), not as lights
     * sampled with shadow rays at pixels and voxels (0, vct_plan_make's). */
    int emitters_by_cones;
} vct_plan;

VCT_API const char *vct_effect_name(vct_effect effect);
/* -1 for an unknown name. */
VCT_API int vct_effect_from_name(const char *name);
/* force: VCT_EFFECTS entries, or NULL to follow the scene. */
VCT_API void vct_plan_make(const vct_scene *scene, const vct_effect_force *force, vct_plan *plan);
/* Whether the plan reads the voxel hierarchy, and whether it needs its light. */
VCT_API int vct_plan_needs_voxels(const vct_plan *plan);
VCT_API int vct_plan_needs_voxel_light(const vct_plan *plan);

typedef struct vct_vct_options {
    int width, height;
    uint32_t diffuse_cones; /* 1 to 16: the diffuse gather's rays, 9 per cone */
    vct_cone_settings cones;
    /* 1 (vct_vct_options_default): trace the diffuse cones at every other
     * pixel per axis and give the others the mean of the traced neighbours
     * on the same surface (a pixel with none traces its own); 0: at every
     * pixel. Over the scene suite both give the same error, and the frame
     * takes 0.3 to 0.6 of its time with 1 (doc/results/suite.md). */
    int sparse_diffuse;
    /* Camera rays per axis at pixels on an edge (of a surface, a material or
     * a hard shadow), which then show their mean; twice as many where the
     * shading on its two sides is four times apart (a hard shadow's, a lit
     * wall's against a dark sky), four times on an emitting surface's
     * border: there the bright side's share of a pixel decides it. 1 traces
     * pixel centres only; 0 means VCT_EDGE_SAMPLES_DEFAULT. At most
     * VCT_EDGE_SAMPLES_MAX. */
    uint32_t edge_samples;
    int aovs; /* also fill the AOV images */
    /* The indirect diffuse light through this many of the denoiser's
     * passes (vct/denoise.h), guided by the first hit's albedo, normal and
     * depth and by each pixel's variance (vct_aovs.indirect_variance); the
     * direct light's part from emitter samples too (at most 3 passes, by
     * the spread of the samples' two halves; exact light from punctual
     * lights kept where the filter would move it more than that noise
     * explains); the specular cone is kept as it is. Over the scene suite 3
     * passes take the error as far down as 4 or 5 do. 0: not filtered. At
     * most VCT_INDIRECT_PASSES_MAX. */
    uint32_t indirect_passes;
} vct_vct_options;

#define VCT_EDGE_SAMPLES_DEFAULT 4u
#define VCT_EDGE_SAMPLES_MAX 8u
#define VCT_INDIRECT_PASSES_DEFAULT 3u
#define VCT_INDIRECT_PASSES_MAX 5u

/* 9 diffuse cones, default cone settings, 4 x 4 rays at edges, the indirect
 * light through 3 filter passes, no AOVs. */
VCT_API vct_vct_options vct_vct_options_default(int width, int height);

typedef struct vct_aovs {
    vct_image direct;   /* direct light and emission (filtered as indirect_passes says) */
    vct_image indirect; /* indirect diffuse (or ambient light times AO) */
    vct_image specular; /* the specular cone */
    vct_image ao;       /* fraction of the hemisphere open within the AO distance */
    vct_image position; /* the surface the camera ray found, w 1 (all 0 where none) */
    vct_image normal;   /* its shading normal, facing the viewer, w 1 (all 0 where none) */
    /* The denoiser's guides (vct_denoise_guides) from the pixel's camera
     * samples, its centre's or, on an edge, the n x n of the edge samples:
     * their mean albedo, 1 where one found nothing, w the share on no
     * emitter; their mean normal facing the viewer (shorter at an edge), w
     * the mean distance of those that found a surface (0 where none did). */
    vct_image albedo;
    vct_image normal_depth;
    /* The variance of each pixel's indirect light (its luminance, as grey):
     * the spread of its gather rays' light over their count, the indirect
     * filter's guide; 0 where no rays were traced. */
    vct_image indirect_variance;
} vct_aovs;
VCT_API void vct_aovs_release(vct_aovs *aovs);

/* Light bounces in the voxels by default (direct light counts as the first),
 * after which the rest of the series is added at the scene's bounce ratio. */
#define VCT_DEFAULT_BOUNCES 4u

/* Builds what the plan's cones read: voxels, octree and bricks, then light
 * (when indirect diffuse or specular is on) with `bounces` - 1 extra
 * diffuse bounces gathered at the voxels by the 6-cone preset. *voxels is
 * NULL when the plan needs none. */
VCT_API vct_status vct_vct_prepare(vct_context *ctx, const vct_scene *scene, const vct_accel *accel,
                                   const vct_plan *plan, const vct_voxel_options *voxel_options,
                                   const vct_brick_options *brick_options, uint32_t bounces,
                                   const vct_cone_settings *cones, vct_voxels **voxels,
                                   vct_error *err);

/* Renders by voxel cone tracing: stages "vct primary", "vct diffuse cones"
 * and "vct specular cone", each only when the plan calls for it. voxels may
 * be NULL when the plan needs none. aovs may be NULL. */
VCT_API vct_status vct_render_vct(vct_context *ctx, const vct_scene *scene, const vct_accel *accel,
                                  const vct_voxels *voxels, const vct_plan *plan,
                                  const vct_vct_options *options, vct_image *image, vct_aovs *aovs,
                                  vct_error *err);

/* ---- one way to every method -------------------------------------------------- */

typedef enum vct_method {
    VCT_METHOD_VCT,       /* voxel cone tracing (needs voxels when the plan reads them) */
    VCT_METHOD_RAYCAST,   /* direct light with hard or soft shadows */
    VCT_METHOD_PATHTRACE, /* unbiased path tracing */
    VCT_METHOD_VOXELS,    /* the voxels themselves, ray marched (needs voxels) */
    VCT_METHOD_WHITTED,   /* Whitted ray trees: mirrors, Fresnel refraction, hard shadows */
    VCT_METHOD_PM,        /* photon mapping, progressive (SPPM) or with a fixed radius */
    VCT_METHODS
} vct_method;

/* Whitted ray tracing: max_depth surface interactions per ray tree (1 to
 * VCT_WHITTED_MAX_DEPTH; 1 is the ray caster with the glossy highlight and
 * the ambient term), branches whose throughput falls below min_throughput
 * end. The scene's ambient is the environment and an ambient term. */
#define VCT_WHITTED_MAX_DEPTH 16
typedef struct vct_whitted_options {
    int width, height;
    uint32_t max_depth;   /* default 8 */
    float min_throughput; /* default 1e-3 */
    /* Adaptive subsampling: 0 traces every pixel; N (a power of
     * two, 2 to the image's smaller side) traces the corners of N x N
     * squares, fills a square whose corners met the same materials and saw
     * the same lights by bilinear interpolation, and splits the others. */
    uint32_t subsample;
    /* 1: the corners alone decide; 0 (default): squares that a piece of
     * the mesh smaller than the square touches on screen are split whatever
     * their corners say, so small objects are not lost between corners. */
    uint32_t subsample_unguarded;
    /* > 0: corners whose radiance spreads by more than this share of their
     * mean disagree too (soft shadows, falloff); 0: the keys alone.
     * VCT_SUBSAMPLE_CONTRAST_DEFAULT in vct_render_job_default. */
    float subsample_contrast;
} vct_whitted_options;

/* The contrast subsampling splits at by default: with keys alone, the
 * brightest spots between equal corners are interpolated away
 * (doc/results/subsample.md measures both). */
#define VCT_SUBSAMPLE_CONTRAST_DEFAULT 0.05f

/* Depth 8, throughput 1e-3, no subsampling (contrast
 * VCT_SUBSAMPLE_CONTRAST_DEFAULT once subsample is set). */
VCT_API vct_whitted_options vct_whitted_options_default(int width, int height);

typedef struct vct_whitted_result {
    uint64_t traced_pixels; /* pixels whose ray tree was traced (all without subsampling) */
    uint64_t small_objects; /* pieces of the mesh smaller than a square on screen (guarded) */
    uint8_t *traced_mask;   /* in: NULL, or width x height bytes to receive 1 where traced */
    uint64_t camera_rays;   /* ray trees started: pixels traced, some twice (contrast centres) */
} vct_whitted_result;

/* result may be NULL. */
VCT_API vct_status vct_render_whitted(vct_context *ctx, const vct_scene *scene,
                                      const vct_accel *accel, const vct_whitted_options *options,
                                      vct_image *image, vct_whitted_result *result, vct_error *err);

/* Photon mapping, progressive. Each pass traces the camera
 * rays through mirrors and glass to their first diffuse or glossy hit,
 * shoots photons_per_pass photons from the lights (by power), grids them
 * (cell = radius) and gathers them at every such hit. Direct light comes
 * from shadow rays, light with a specular bounce since its last diffuse one
 * from the caustic map, the rest from the global map: by a density estimate
 * at the hit or, with final_gather, at the hits of a few rays from it. */
typedef enum vct_pm_kernel { VCT_PM_KERNEL_BOX, VCT_PM_KERNEL_EPANECHNIKOV } vct_pm_kernel;
#define VCT_PM_DIRECT 1u  /* component: emission and direct light */
#define VCT_PM_GLOBAL 2u  /* component: the global map (or final gathering) */
#define VCT_PM_CAUSTIC 4u /* component: the caustic map */
#define VCT_PM_ALL 7u
typedef struct vct_pm_options {
    int width, height;
    uint32_t passes;           /* 0: run for time_limit_s */
    double time_limit_s;       /* used when passes is 0 */
    uint32_t photons_per_pass; /* photon paths per pass (default 131072) */
    uint32_t max_depth;        /* camera and photon bounces (default 16) */
    /* Gather radii in world units, initial (progressive) or fixed; 0: from
     * the scene's size: 1.5 % of its largest side, the caustic radius the
     * same when progressive and half that when fixed. */
    float radius, caustic_radius;
    /* 0: progressive, each pixel's radius shrinking by alpha (Hachisuka and
     * Jensen; default 2/3, as pbrt-v4); 1: fixed radii. */
    int fixed_radius;
    float alpha;
    int final_gather;     /* 1: the global map read by final gathering */
    uint32_t gather_rays; /* final-gathering rays per pixel and pass (default 8) */
    int direct_photons;   /* 1: direct light from the photons too, not shadow rays */
    vct_pm_kernel kernel; /* default VCT_PM_KERNEL_EPANECHNIKOV */
    /* Photons whose surface normal's cosine with the point's is below this
     * are not counted: default 0, those on surfaces facing away; a stricter
     * 0.7 darkens detailed scenes (the gather disk keeps its area); -2 counts
     * all. */
    float normal_cos;
    uint32_t components; /* VCT_PM_* bits to show; 0: all */
    uint32_t seed;       /* same seed and passes: same image, bit for bit */
    int progress;        /* progress bar on a terminal's stderr */
    /* 1: go on from the previous call's statistics of this scene on this
     * context (same size and settings; a device scene's commit that finds a
     * change starts over, as for the path tracer); 0: start over. */
    int resume;
} vct_pm_options;
/* Defaults as above, at width x height, 64 passes. Every options struct
 * has such a function; a zeroed struct is not a default. */
VCT_API vct_pm_options vct_pm_options_default(int width, int height);
typedef struct vct_pm_result {
    uint32_t passes;
    uint64_t photons_emitted;                     /* photon paths, all passes */
    uint64_t photons_stored[2];                   /* global, caustic: all passes */
    int global_map, caustic_map;                  /* which maps the scene called for */
    int hashed[2];                                /* the last pass's grids: 1 where hashed */
    uint64_t grid_bytes[2];                       /* their device memory */
    float cell[2];                                /* their cell edge */
    double seconds, trace_ms, grid_ms, gather_ms; /* wall time; per-part device time */
} vct_pm_result;
/* result may be NULL. */
VCT_API vct_status vct_render_pm(vct_context *ctx, const vct_scene *scene, const vct_accel *accel,
                                 const vct_pm_options *options, vct_image *image,
                                 vct_pm_result *result, vct_error *err);

/* The ray caster's options (vct_render_raycast's). */
typedef vct_render_options vct_raycast_options;

typedef struct vct_voxel_view_options {
    int width, height;
    /* octree level to show (0 = root); VCT_VOXEL_VIEW_LEAVES shows the voxels */
    uint32_t level;
} vct_voxel_view_options;
#define VCT_VOXEL_VIEW_LEAVES 0xffffffffu
/* The voxels themselves (VCT_VOXEL_VIEW_LEAVES). */
VCT_API vct_voxel_view_options vct_voxel_view_options_default(int width, int height);

/* A band of a taller image: rows [first, first + the job's height) of an
 * image `height` rows tall, rendered as an image of their own with the
 * whole image's rays and random streams, so that its pixels equal the whole
 * image's. height 0: the job is the whole image. vct/partial.h tells how to
 * split an image into bands. */
typedef struct vct_band {
    int first, height;
    /* Photon mapping only, and required there: called once per pass with
     * the band's largest gather radii (float bits: global map, caustic
     * map); it must replace them with the largest over all the image's
     * bands of that pass and return 0, or return non-zero to stop the
     * render. */
    int (*pass_sync)(void *user, uint32_t pass, uint32_t radius_bits[2]);
    void *pass_sync_user;
} vct_band;

/* One render: the method, the image size, what it reads and its options.
 * Only the options of `method` are read; their width and height are set
 * from the job's. */
typedef struct vct_render_job {
    vct_method method;
    int width, height; /* the image (or, with a band, the band's rows) */
    const vct_scene *scene;
    const vct_accel *accel;   /* every method but VCT_METHOD_VOXELS */
    const vct_voxels *voxels; /* VCT_METHOD_VCT (may be NULL when the plan reads none), VOXELS */
    const vct_plan *plan;     /* VCT_METHOD_VCT; NULL: the scene's own plan */
    vct_aovs *aovs;           /* VCT_METHOD_VCT; NULL: none */
    vct_raycast_options raycast;
    vct_whitted_options whitted;
    vct_pathtrace_options pathtrace;
    vct_pm_options pm;
    vct_vct_options vct;
    vct_voxel_view_options voxel_view;
    vct_band band; /* every method but path tracing */
    /* How vct_device_scene_render builds what the job reads (vct_render
     * takes them built, in scene, accel and voxels above): the acceleration
     * structure; for cone tracing and the voxel view the voxels, their
     * bricks and light bounces (1 to 4, VCT_DEFAULT_BOUNCES). */
    vct_accel_options accel_options;
    vct_voxel_options voxel_options;
    vct_brick_options brick_options;
    uint32_t bounces;
    /* Cone tracing through a device scene, when lights or geometry
     * changed: 1 carries the voxels' light over from the frame before, as
     * engines do. Lights moved: the new direct light plus one bounce
     * gathered from the light the voxels held. Geometry moved: the moved
     * triangles voxelized alone, direct light kept wherever nothing that
     * moved can reach it, and one bounce gathered from the light before by
     * the voxels lit anew and a quarter of the others in turn (the rest
     * keep their light before). Then one bounce more at each render until
     * the light before has faded (bench/dynamic.sh measures how it
     * settles). 0 (the default): every bounce again, the image of a fresh
     * build, bit for bit. */
    int light_carry;
} vct_render_job;

typedef struct vct_render_result {
    vct_method method;
    int width, height;
    double seconds;       /* host wall time of the call */
    uint32_t spp;         /* path tracing: samples per pixel; photon mapping: passes */
    uint32_t discarded;   /* path tracing: non-finite samples dropped */
    uint64_t traced;      /* Whitted: pixels traced (the rest interpolated) */
    uint64_t camera_rays; /* Whitted: ray trees started (pixels traced, some twice) */
    uint64_t photons;     /* photon mapping: photon paths emitted */
    vct_pm_result pm;     /* photon mapping: the whole account */
} vct_render_result;

/* A job with every method's defaults (vct_vct_options_default, 64 spp,
 * depth 16; a BVH, 128^3 voxels with isotropic bricks, VCT_DEFAULT_BOUNCES)
 * at width x height, for `method`. */
VCT_API vct_render_job vct_render_job_default(vct_method method, int width, int height);
VCT_API const char *vct_method_name(vct_method method);
/* -1 for an unknown name ("vct", "raycast", "pt", "voxels"). */
VCT_API int vct_method_from_name(const char *name);
/* Renders `job` into the context's frame and returns it in `image` (as every
 * renderer does; see vct_frame_host_copy). result may be NULL. */
VCT_API vct_status vct_render(vct_context *ctx, const vct_render_job *job, vct_image *image,
                              vct_render_result *result, vct_error *err);

/* ---- the frame and OpenGL display ----------------------------------------------- */

/* Every renderer writes its image into the context's frame, a device buffer
 * of width * height float4 (linear radiance, rows top to bottom) kept between
 * calls, and copies it into the vct_image it returns. With host copies off
 * the returned image carries its size and rgba NULL: for displays that take
 * the frame on the device. On by default. */
VCT_API void vct_frame_host_copy(vct_context *ctx, int on);
/* The last frame's size (0 x 0 before any), and a copy of it into `rgba`,
 * which holds `floats` floats (at least width * height * 4). */
VCT_API void vct_frame_size(const vct_context *ctx, int *width, int *height);
VCT_API vct_status vct_frame_read(vct_context *ctx, float *rgba, size_t floats, vct_error *err);

/* A context that shares objects with an OpenGL context (cl_khr_gl_sharing on
 * GLX): glx_context is the GLXContext, x_display the X Display it belongs to.
 * Fails with the reason when the device has no such sharing or cannot share
 * with that context; plain contexts then display through the host. */
VCT_API vct_context *vct_context_create_gl(const char *selector, void *glx_context, void *x_display,
                                           vct_error *err);
VCT_API int vct_context_shares_gl(const vct_context *ctx);
/* Copies the frame into an OpenGL buffer object of at least width * height
 * * 16 bytes, on the device: acquire, copy, release, finish. Call glFinish()
 * first so that GL is done with the buffer; it is complete on return. */
VCT_API vct_status vct_frame_to_gl_buffer(vct_context *ctx, unsigned gl_buffer, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
