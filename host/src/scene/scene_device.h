/* Conversions from the public scene structs to the kernels' layouts. */
#ifndef VCT_SCENE_DEVICE_H
#define VCT_SCENE_DEVICE_H

#include "runtime/runtime.h"
#include "vct_types.h"

int vct_camera_desc_make(const vct_camera *cam, int width, int height, vct_camera_desc *d,
                         vct_error *err);
void vct_light_desc_make(const vct_light *l, vct_light_desc *d);
void vct_material_desc_make(const vct_material *m, vct_material_desc *d);

/* Materials, per-triangle material ids and lights on the device. */
typedef struct vct_scene_buffers {
    cl_mem materials, tri_material, lights;
    cl_uint light_count;
} vct_scene_buffers;

int vct_scene_buffers_make(vct_context *ctx, const vct_scene *s, const char *stage,
                           vct_scene_buffers *b, vct_error *err);
void vct_scene_buffers_release(vct_context *ctx, vct_scene_buffers *b);

#endif
