/* For hosts inside the library that hold a device scene per device (a
 * group): its structures built ahead of the renders, and voxels copied from
 * another device's taken as its own. */
#ifndef VCT_DEVICE_SCENE_PREPARE_H
#define VCT_DEVICE_SCENE_PREPARE_H

#include "vct/device_scene.h"

/* Commits, then builds what `job` would read (as vct_device_scene_render
 * does), without rendering. */
int vct_device_scene_prepare(vct_device_scene *ds, const vct_render_job *job, vct_error *err);
/* The context and the scene ds was made with. */
vct_context *vct_device_scene_context(const vct_device_scene *ds);
const vct_scene *vct_device_scene_scene(const vct_device_scene *ds);
/* voxels (a copy of from's, made on ds's context) become ds's, with the
 * settings from built them with; ds's own are released. */
void vct_device_scene_adopt_voxels(vct_device_scene *ds, vct_voxels *voxels,
                                   const vct_device_scene *from);

#endif
