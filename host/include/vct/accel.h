/* vct: acceleration structures and ray queries. Every ray of every method
 * goes through one vct_accel: a 4-wide BVH built on the device (the default,
 * with one level or two) or the uniform triangle grid.
 *
 * A structure belongs to the context it was built on: it is used only there
 * (vct_render refuses another's), its calls are serialised with the
 * context's, and it is released before the context. It keeps no pointer to
 * the scene it was built from. */
#ifndef VCT_API_ACCEL_H
#define VCT_API_ACCEL_H

#include "vct/export.h"

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
VCT_API vct_grid *vct_grid_build(vct_context *ctx, const vct_scene *scene, const uint32_t *res,
                                 vct_error *err);
VCT_API void vct_grid_info_get(const vct_grid *grid, vct_grid_info *info);
VCT_API void vct_grid_release(vct_grid *grid);

typedef enum vct_accel_kind { VCT_ACCEL_BVH = 0, VCT_ACCEL_GRID = 1 } vct_accel_kind;

typedef struct vct_accel vct_accel;

/* How the BVH's binary tree is made from the Morton-sorted triangles:
 * agglomerative clustering (PLOC, the default: lower SAH cost, faster rays)
 * or the linear hierarchy alone (Karras 2012: faster to build). */
typedef enum vct_bvh_builder { VCT_BVH_PLOC = 0, VCT_BVH_LINEAR = 1 } vct_bvh_builder;

/* One BVH over every triangle of the scene, or two levels: a BVH per mesh
 * (each mesh once, however many instances place it) under a BVH over the
 * instances. Rays meet the same triangles either way and report the same
 * hits; two levels hold shared meshes once and move an instance by
 * rebuilding the top level alone, one level refits its boxes when vertices
 * move. AUTO: two levels where some mesh is placed more than once. Two
 * levels need the flat positions to be the instances' (as loading and
 * vct_scene_set_instance_transform keep them); where a host edited the
 * positions alone, one level is built. */
typedef enum vct_bvh_levels {
    VCT_BVH_LEVELS_AUTO = 0,
    VCT_BVH_ONE_LEVEL = 1,
    VCT_BVH_TWO_LEVELS = 2
} vct_bvh_levels;

typedef struct vct_accel_options {
    vct_accel_kind kind;
    uint32_t grid_res[3]; /* the grid's cells per axis; 0: chosen from the scene */
    vct_bvh_builder bvh_builder;
    vct_bvh_levels bvh_levels; /* two levels need the scene's instances */
} vct_accel_options;

typedef struct vct_accel_info {
    vct_accel_kind kind;
    double build_ms; /* host wall time of the build, device work included */
    double bytes;    /* device memory it holds */
    uint32_t nodes;  /* BVH: wide nodes; grid: cells */
    uint32_t leaves; /* BVH: leaves; grid: occupied (cell, triangle) references */
    uint32_t depth;  /* BVH: levels */
    uint32_t passes; /* BVH: clustering passes (0 for the linear hierarchy) */
    vct_bvh_builder bvh_builder;
    double sah_cost; /* BVH: surface-area cost relative to the root, 1 per node and triangle
                        (one level only) */
    int two_levels;  /* BVH: a BVH per mesh under one over the instances */
    uint32_t instances, mesh_triangles; /* two levels: instances placed, triangles held */
    vct_grid_info grid;                 /* grid only */
} vct_accel_info;

/* A BVH, clustered (VCT_BVH_PLOC). */
VCT_API vct_accel_options vct_accel_options_default(void);
/* options NULL: the defaults. */
VCT_API vct_accel *vct_accel_build(vct_context *ctx, const vct_scene *scene,
                                   const vct_accel_options *options, vct_error *err);
/* The scene's vertices moved (same triangles): bounds recomputed without a
 * rebuild (the grid is rebuilt, having nothing to refit). Two levels: the
 * instances moved (vct_scene_set_instance_transform), the meshes kept their
 * shape: the top level is built again, the meshes' BVHs kept; the hits are
 * a new build's. */
VCT_API vct_status vct_accel_refit(vct_context *ctx, vct_accel *accel, const vct_scene *scene,
                                   vct_error *err);
/* With sah_cost, which reads the nodes back. */
VCT_API vct_status vct_accel_info_get(vct_context *ctx, const vct_accel *accel,
                                      vct_accel_info *info, vct_error *err);
VCT_API vct_accel_kind vct_accel_kind_of(const vct_accel *accel);
VCT_API const char *vct_accel_kind_name(vct_accel_kind kind);
/* "bvh" or "grid"; -1 for anything else. */
VCT_API int vct_accel_kind_from_name(const char *name);
VCT_API void vct_accel_release(vct_accel *accel);

typedef struct vct_hit {
    float t; /* < 0: miss */
    uint32_t triangle;
    float u, v;
} vct_hit;

/* Hits for n rays, 8 floats each (origin xyz, tmin; direction xyz, tmax):
 * the closest one, or with any_hit the first found (occlusion queries). */
VCT_API vct_status vct_trace_rays(vct_context *ctx, const vct_accel *accel, const float *rays,
                                  uint32_t n, int any_hit, vct_hit *hits, vct_error *err);

#ifdef __cplusplus
}
#endif
#endif
