/* Types shared by host C and OpenCL C: the kernel interface's buffer
 * layouts (kernels/README.md). Every struct is made of 16-byte float4/uint4
 * members so that its layout is identical on both sides. */
#ifndef VCT_TYPES_H
#define VCT_TYPES_H

/* The kernel interface's version: bumped whenever an entry point's
 * arguments, a buffer layout or the meaning of a -D option changes. */
#define VCT_KERNEL_ABI_VERSION 28

#ifdef __OPENCL_VERSION__
typedef float4 vct_f4;
typedef uint4 vct_u4;
/* For helpers called once or twice inside a kernel's hot loop: PoCL leaves
 * large inline functions as calls, and inlining the cone marcher's measured
 * 5-10% faster there (bit-identical images). Not for helpers with large
 * private arrays: forced into the brick filters, they crashed PoCL's
 * kernels. GPU compilers inline them anyway. */
#if defined(__clang__) || defined(__GNUC__)
#define VCT_INLINE inline __attribute__((always_inline))
#else
#define VCT_INLINE inline
#endif
#else
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
typedef cl_float4 vct_f4;
typedef cl_uint4 vct_u4;
#endif

/* What every ray query knows of its acceleration structure: the scene's
 * extent and tolerance, the triangle count, and the grid's cells [0,res) per
 * axis from origin (BVH: res.x is the node count). */
typedef struct vct_accel_desc {
    vct_f4 origin;    /* xyz; w = scene extent (for relative epsilons) */
    vct_f4 cell_size; /* xyz; w = distance tolerance: extent and float spacing */
    vct_f4 inv_cell;  /* 1 / cell_size */
    vct_u4 res;       /* xyz; w = triangle count */
} vct_accel_desc;

typedef struct vct_camera_desc {
    vct_f4 position; /* w = tan(fov_y / 2) */
    vct_f4 forward;  /* w = aspect (width / height) */
    vct_f4 right;
    vct_f4 up;
    vct_u4 size; /* width, height */
} vct_camera_desc;

#define VCT_LIGHT_KIND_POINT 0u
#define VCT_LIGHT_KIND_SPOT 1u
#define VCT_LIGHT_KIND_DIRECTIONAL 2u

typedef struct vct_light_desc {
    vct_f4 position;  /* xyz; w = kind */
    vct_f4 direction; /* xyz normalised, direction of travel; w = cos(outer cone) */
    vct_f4 color;     /* intensity (W/sr) or irradiance; w = cos(inner cone) */
    vct_f4 shape;     /* x = radius (world units), or tan(angular radius) for a
                         directional light; 0 for a point */
} vct_light_desc;

/* A light's triangle bins (kernels/light_bins.h): a cube map of F x F
 * direction cells per face around a point or spot light. */
typedef struct vct_light_bins_desc {
    vct_f4 light; /* xyz: the light's position; w: distance quanta per unit */
    vct_u4 info;  /* x: its first cell, y: F, z: distance bits, w: 1 if it has bins */
} vct_light_bins_desc;

/* Below this roughness (alpha = roughness^2 under 0.02, a Phong exponent
 * over 5,000) a glossy lobe is an ideal mirror (a delta lobe), on both sides:
 * the BSDF (kernels/scene/bsdf.h) and the host's choices. */
#define VCT_MIRROR_ROUGHNESS 0.14f

typedef struct vct_material_desc {
    vct_f4 albedo;   /* rgb; w = metallic */
    vct_f4 emission; /* rgb; w = roughness */
    vct_f4 specular; /* rgb; w = transmission */
    vct_f4 extra;    /* x = ior, y = 1 + base-colour texture (0: none), z = its wrap, w = the
                        alpha mask's threshold on the texture's alpha (cutoff / alpha
                        factor; 0: no mask; an untextured surface's alpha is 1) */
} vct_material_desc;

/* Ray for vct_trace_rays: origin.w = tmin, direction.w = tmax. */
typedef struct vct_ray_desc {
    vct_f4 origin;
    vct_f4 direction;
} vct_ray_desc;

/* Hit: x = t (negative for a miss), y = triangle (as bits), z = u, w = v. */
typedef vct_f4 vct_hit_desc;

/* Voxel volume: a cube of R^3 voxels (R = 2^L) from origin. Vertices are
 * quantised to integers, 2^VCT_VOLUME_UNITS_LOG2 units per cube side, so that
 * triangle/voxel tests are exact integer arithmetic (Q = units per voxel). */
#define VCT_VOLUME_UNITS_LOG2 18
#define VCT_VOXEL_MAX_LEVELS 10
/* float4s per voxel in the sides array (voxel/voxel_side.h) */
#define VCT_VOXEL_SIDE_FLOAT4S 2
/* leaf voxels per work-item of gather_pick_peak (render/vct_render.cl) */
#define VCT_PICK_SPAN 64
/* A voxel with no counterpart (kernels/voxel/voxel_carry.h). */
#define VCT_NO_VOXEL 0xffffffffu

typedef struct vct_volume_desc {
    vct_f4 origin; /* xyz: world position of the cube's minimum corner; w = side length */
    vct_u4 res;    /* x = R, y = L, z = Q, w = triangle count */
} vct_volume_desc;

/* Cone marching through the brick pool (kernels/cone_trace.h). */
typedef struct vct_cone_desc {
    vct_f4 volume;  /* xyz: the voxel cube's minimum corner; w: its side */
    vct_u4 res;     /* x = voxels per axis R, y = levels L, zw = brick pool layout */
    vct_f4 march;   /* x = step as a fraction of the diameter, y = start offset
                       along the normal in voxels, z = AO distance (world),
                       w = opacity at which a cone stops */
    vct_f4 ambient; /* rgb: radiance beyond the volume; w = 1 / side */
} vct_cone_desc;

/* One cone of a diffuse preset: direction in the surface frame (z = normal)
 * and its weight; tan of its half-angle. */
typedef struct vct_cone_dir {
    vct_f4 dir;      /* xyz; w = weight (the preset's weights sum to 1) */
    vct_f4 aperture; /* x = tan(half-angle); y = tan of its cell's (vct_cone_preset) */
} vct_cone_dir;

/* Every struct above with its size, and every field with its offset, in
 * bytes: checked at compile time on the host (runtime/abi.c) and against
 * the device's own layout by tests/runtime/test_abi.c. S(type, size),
 * F(type, field, offset). */
#define VCT_ABI_LAYOUT(S, F)                                                                       \
    S(vct_accel_desc, 64)                                                                          \
    F(vct_accel_desc, origin, 0)                                                                   \
    F(vct_accel_desc, cell_size, 16)                                                               \
    F(vct_accel_desc, inv_cell, 32)                                                                \
    F(vct_accel_desc, res, 48)                                                                     \
    S(vct_camera_desc, 80)                                                                         \
    F(vct_camera_desc, position, 0)                                                                \
    F(vct_camera_desc, forward, 16)                                                                \
    F(vct_camera_desc, right, 32)                                                                  \
    F(vct_camera_desc, up, 48)                                                                     \
    F(vct_camera_desc, size, 64)                                                                   \
    S(vct_light_desc, 64)                                                                          \
    F(vct_light_desc, position, 0)                                                                 \
    F(vct_light_desc, direction, 16)                                                               \
    F(vct_light_desc, color, 32)                                                                   \
    F(vct_light_desc, shape, 48)                                                                   \
    S(vct_light_bins_desc, 32)                                                                     \
    F(vct_light_bins_desc, light, 0)                                                               \
    F(vct_light_bins_desc, info, 16)                                                               \
    S(vct_material_desc, 64)                                                                       \
    F(vct_material_desc, albedo, 0)                                                                \
    F(vct_material_desc, emission, 16)                                                             \
    F(vct_material_desc, specular, 32)                                                             \
    F(vct_material_desc, extra, 48)                                                                \
    S(vct_ray_desc, 32)                                                                            \
    F(vct_ray_desc, origin, 0)                                                                     \
    F(vct_ray_desc, direction, 16)                                                                 \
    S(vct_volume_desc, 32)                                                                         \
    F(vct_volume_desc, origin, 0)                                                                  \
    F(vct_volume_desc, res, 16)                                                                    \
    S(vct_cone_desc, 64)                                                                           \
    F(vct_cone_desc, volume, 0)                                                                    \
    F(vct_cone_desc, res, 16)                                                                      \
    F(vct_cone_desc, march, 32)                                                                    \
    F(vct_cone_desc, ambient, 48)                                                                  \
    S(vct_cone_dir, 32)                                                                            \
    F(vct_cone_dir, dir, 0)                                                                        \
    F(vct_cone_dir, aperture, 16)

#endif
