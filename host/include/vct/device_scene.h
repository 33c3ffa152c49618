/* vct: a scene committed to a context: uploaded once, rendered many times.
 *
 *   vct_scene *scene = vct_scene_load("scenes/cornell_box.obj", &err);
 *   vct_context *ctx = vct_context_create(NULL, &err);
 *   vct_device_scene *ds = vct_device_scene_create(ctx, scene, &err);
 *   vct_render_job job = vct_render_job_default(VCT_METHOD_VCT, 512, 512);
 *   vct_device_scene_render(ds, &job, &image, NULL, &err);
 *
 * The device scene owns what the methods build from the scene: its
 * materials, lights and textures on the device, the emitter tables, the
 * acceleration structure and the voxels with their light. Each is built
 * when a render first needs it and kept while the scene and the job's
 * settings for it stay the same, so a second render of an unchanged scene
 * uploads no scene data and rebuilds nothing.
 *
 * Change the host scene (a light, a material, the camera, the geometry),
 * then commit: only what depends on the change is rebuilt, at the next
 * render that needs it. A moved light re-injects the voxels' light and
 * keeps the acceleration structure and the voxels; a changed material keeps
 * the acceleration structure (unless its alpha mask changed); a moved
 * instance (vct_scene_set_instance_transform) rebuilds a two-level
 * structure's top level alone, and the voxels; new geometry rebuilds
 * everything. A render commits first, so a change is never missed.
 *
 * Lifetime: the scene and the context must outlive the device scene; release
 * it before destroying either. Calls on one device scene, like calls on its
 * context, must be serialised by the caller. */
#ifndef VCT_API_DEVICE_SCENE_H
#define VCT_API_DEVICE_SCENE_H

#include "vct/export.h"

#include <stdint.h>

#include "vct/render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct vct_device_scene vct_device_scene;

/* Commits `scene` to `ctx` (nothing is uploaded before a render needs it).
 * One device scene per scene and context. */
VCT_API vct_device_scene *vct_device_scene_create(vct_context *ctx, const vct_scene *scene,
                                                  vct_error *err);
/* Compares the scene with the last commit and lets go of what its changes
 * invalidate (rewriting lights and materials on the device in place). */
VCT_API vct_status vct_device_scene_commit(vct_device_scene *ds, vct_error *err);
/* Commits, builds what the job needs (job->scene, accel and voxels are
 * ignored: the device scene's are used, made with job->accel_options,
 * voxel_options, brick_options, bounces and vct.cones), and renders. */
VCT_API vct_status vct_device_scene_render(vct_device_scene *ds, const vct_render_job *job,
                                           vct_image *image, vct_render_result *result,
                                           vct_error *err);
VCT_API void vct_device_scene_release(vct_device_scene *ds);

/* What the device scene has done since it was created: for hosts that
 * check that an unchanged frame costs nothing. */
typedef struct vct_device_scene_stats {
    uint32_t commits;      /* commits, those of renders included */
    uint32_t changes;      /* commits that found the scene changed */
    uint32_t accel_builds; /* acceleration structures built */
    uint32_t accel_moves;  /* placed again: two levels' top level built again (the meshes'
                              BVHs kept), or one level's boxes refit to moved vertices */
    uint32_t voxel_builds; /* voxelization, octree and bricks */
    uint32_t light_builds; /* direct light and bounces into the voxels (new or kept) */
    uint64_t scene_bytes;  /* scene data uploaded: geometry, materials, lights, textures */
} vct_device_scene_stats;
VCT_API void vct_device_scene_stats_get(const vct_device_scene *ds, vct_device_scene_stats *stats);
/* The structures it holds now (NULL where none is built): for the
 * per-method calls of vct/render.h and vct/voxels.h. */
VCT_API const vct_accel *vct_device_scene_accel(const vct_device_scene *ds);
VCT_API const vct_voxels *vct_device_scene_voxels(const vct_device_scene *ds);

#ifdef __cplusplus
}
#endif
#endif
