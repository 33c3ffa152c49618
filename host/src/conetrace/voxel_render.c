/* Voxel view: the octree ray marched from the scene camera (kernels/render/voxel_render.cl). */
#include <stdlib.h>
#include <string.h>

#include "runtime/runtime.h"
#include "frame/frame.h"
#include "scene/scene_device.h"
#include "vct_types.h"
#include "voxel/voxels.h"

vct_status vct_render_voxels(vct_context *ctx, const vct_scene *s, const vct_voxels *v, int width,
                             int height, vct_image *image, vct_error *err) {
    return vct_render_voxels_level(ctx, s, v, v->info.levels, width, height, image, err);
}

vct_status vct_render_voxels_level(vct_context *ctx, const vct_scene *s, const vct_voxels *v,
                                   uint32_t level, int width, int height, vct_image *image,
                                   vct_error *err) {
    const char *stage = "voxel render";
    memset(image, 0, sizeof *image);
    if (!v->child)
        return vct_fail(err, VCT_ERR_INPUT, "%s: build the octree first (vct_octree_build)", stage);
    if (level > v->info.levels)
        return vct_fail(err, VCT_ERR_INPUT, "%s: level %u does not exist (levels 0 to %u)", stage,
                        level, v->info.levels);
    vct_camera_desc cam;
    int rc = vct_frame_camera(ctx, &s->camera, width, height, &cam, err);
    if (rc)
        return rc;
    vct_volume_desc vol;
    vct_voxels_volume_desc(v, &vol);
    vct_stage_begin(ctx, stage);
    cl_program p;
    rc = vct_program_get(ctx, "render/voxel_render.cl", "", &p, err);
    cl_mem img = rc == VCT_OK ? vct_frame_get(ctx, stage, width, height, err) : NULL;
    cl_kernel k = img ? vct_kernel_create(ctx, p, "voxel_render", err) : NULL;
    const cl_uint has_radiance = v->radiance != NULL && v->side != NULL;
    cl_mem radiance = has_radiance ? v->radiance : v->emission;
    cl_mem side = has_radiance ? v->side : v->emission; /* unread without radiance */
    const cl_uint show_level = level;
    rc = k ? vct_set_args(err, stage, k, 0, 11, VCT_ARG_OF(cam), VCT_ARG_OF(vol),
                          VCT_ARG_OF(v->child), VCT_ARG(voxel_albedo, v->albedo),
                          VCT_ARG(voxel_normal, v->normal), VCT_ARG(voxel_emission, v->emission),
                          VCT_ARG(voxel_radiance, radiance), VCT_ARG(voxel_side, side),
                          VCT_ARG_OF(has_radiance), VCT_ARG_OF(show_level), VCT_ARG(image, img))
           : (int)err->status;
    const size_t global[2] = {(size_t)width, (size_t)height}, local[2] = {8, 8};
    if (rc == VCT_OK)
        rc = vct_launch_2d(ctx, k, global, local, err);
    if (rc == VCT_OK)
        rc = vct_frame_deliver(ctx, stage, image, err);
    if (k)
        clReleaseKernel(k);
    vct_stage_end(ctx);
    if (rc != VCT_OK)
        vct_image_release(image);
    return rc;
}
